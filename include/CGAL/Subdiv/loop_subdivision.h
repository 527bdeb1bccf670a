// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LOOP_SUBDIVISION_H
#define CGAL_SUBDIV_LOOP_SUBDIVISION_H

/// \file loop_subdivision.h
/// `loop_subdivision()` and `loop_warren_subdivision()`, with only what they
/// need: the Loop mask and the triangle quadrisection (compile time is part of
/// the API; `surface_subdivision.h` has every scheme).

#include <CGAL/Subdiv/hosts/Triangle_quadrisection.h>
#include <CGAL/Subdiv/internal/call_parameters.h>
#include <CGAL/Subdiv/masks/Loop_mask.h>
#include <CGAL/Subdiv/subdivide.h>

namespace CGAL {
namespace Subdiv {

/// Loop subdivision with Loop's 1987 weights. \sa `subdivide()`, `Loop_mask`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
void loop_subdivision(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  subdivide(mesh,
            Loop_mask<PolygonMesh, internal::Call_FT<PolygonMesh, NamedParameters>>(internal::call_border_corners(np)),
            np);
}

/// Loop subdivision with Warren's rational weights. \sa `subdivide()`, `Loop_mask`, `Warren_beta`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
void loop_warren_subdivision(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  subdivide(mesh,
            Loop_mask<PolygonMesh, internal::Call_FT<PolygonMesh, NamedParameters>, Warren_beta>(
              internal::call_border_corners(np)),
            np);
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LOOP_SUBDIVISION_H
