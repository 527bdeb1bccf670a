// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_SURFACE_SUBDIVISION_H
#define CGAL_SUBDIV_SURFACE_SUBDIVISION_H

/// \file surface_subdivision.h
/// One-line wrappers of `subdivide()`, one per scheme, with the names users
/// of CGAL expect.

#include <CGAL/Subdiv/masks/Loop_mask.h>
#include <CGAL/Subdiv/subdivide.h>

namespace CGAL {
namespace Subdiv {

/// Loop subdivision with Loop's 1987 weights. \sa `subdivide()`, `Loop_mask`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
void loop_subdivision(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  subdivide(mesh, Loop_mask<PolygonMesh>(), np);
}

/// Loop subdivision with Warren's rational weights. \sa `subdivide()`, `Loop_mask`, `Warren_beta`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
void loop_warren_subdivision(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  subdivide(mesh, Loop_mask<PolygonMesh, internal::Mesh_FT<PolygonMesh>, Warren_beta>(), np);
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_SURFACE_SUBDIVISION_H
