// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_CATMULL_CLARK_SUBDIVISION_H
#define CGAL_SUBDIV_CATMULL_CLARK_SUBDIVISION_H

/// \file catmull_clark_subdivision.h
/// `catmull_clark_subdivision()`, with only what it needs: the Catmull-Clark
/// mask and the quad split (compile time is part of the API;
/// `surface_subdivision.h` has every scheme).

#include <CGAL/Subdiv/hosts/Quad_split.h>
#include <CGAL/Subdiv/internal/call_parameters.h>
#include <CGAL/Subdiv/masks/Catmull_clark_mask.h>
#include <CGAL/Subdiv/subdivide.h>

namespace CGAL {
namespace Subdiv {

/// Catmull-Clark subdivision of any polygon mesh. \sa `subdivide()`, `Catmull_clark_mask`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
void catmull_clark_subdivision(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  const Triangle_subdivision triangles = parameters::choose_parameter(
    parameters::get_parameter(np, internal::triangle_subdivision_t()), Triangle_subdivision::catmark);
  subdivide(mesh,
            Catmull_clark_mask<PolygonMesh, internal::Call_FT<PolygonMesh, NamedParameters>>(
              internal::call_border_corners(np), triangles),
            np);
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_CATMULL_CLARK_SUBDIVISION_H
