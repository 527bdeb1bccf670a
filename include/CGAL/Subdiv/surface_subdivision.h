// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_SURFACE_SUBDIVISION_H
#define CGAL_SUBDIV_SURFACE_SUBDIVISION_H

/// \file surface_subdivision.h
/// One-line wrappers of `subdivide()`, one per scheme, with the names users
/// of CGAL expect, and every mask and host. A program that uses one scheme
/// compiles faster with that scheme's header alone: `loop_subdivision.h`,
/// `catmull_clark_subdivision.h` (doc/compile_time.md).

#include <CGAL/Subdiv/catmull_clark_subdivision.h>
#include <CGAL/Subdiv/hosts/hosts.h>
#include <CGAL/Subdiv/internal/call_parameters.h>
#include <CGAL/Subdiv/loop_subdivision.h>
#include <CGAL/Subdiv/masks/Butterfly_mask.h>
#include <CGAL/Subdiv/masks/Doo_sabin_mask.h>
#include <CGAL/Subdiv/masks/Interpolating_sqrt3_mask.h>
#include <CGAL/Subdiv/masks/Linear_quad_mask.h>
#include <CGAL/Subdiv/masks/Linear_triangle_mask.h>
#include <CGAL/Subdiv/masks/Modified_butterfly_mask.h>
#include <CGAL/Subdiv/masks/Sqrt3_mask.h>
#include <CGAL/Subdiv/subdivide.h>

namespace CGAL {
namespace Subdiv {

/// Butterfly subdivision (Dyn, Levin, Gregory 1990, tension 1/16). \sa `subdivide()`, `Butterfly_mask`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
void butterfly_subdivision(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  subdivide(mesh, Butterfly_mask<PolygonMesh, internal::Call_FT<PolygonMesh, NamedParameters>>(), np);
}

/// Modified butterfly subdivision (Zorin, Schroeder, Sweldens 1996). \sa `subdivide()`, `Modified_butterfly_mask`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
void modified_butterfly_subdivision(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  subdivide(mesh, Modified_butterfly_mask<PolygonMesh, internal::Call_FT<PolygonMesh, NamedParameters>>(), np);
}

/// Linear 1-to-4 split of a triangle mesh (edge midpoints). \sa `subdivide()`, `Linear_triangle_mask`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
void linear_triangle_subdivision(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  subdivide(mesh, Linear_triangle_mask<PolygonMesh, internal::Call_FT<PolygonMesh, NamedParameters>>(), np);
}

/// Doo-Sabin subdivision of any polygon mesh. \sa `subdivide()`, `Doo_sabin_mask`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
void doo_sabin_subdivision(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  subdivide(mesh, Doo_sabin_mask<PolygonMesh, internal::Call_FT<PolygonMesh, NamedParameters>>(), np);
}

/// Linear quad split of any polygon mesh (edge midpoints, face centroids). \sa `subdivide()`, `Linear_quad_mask`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
void linear_quad_subdivision(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  subdivide(mesh, Linear_quad_mask<PolygonMesh, internal::Call_FT<PolygonMesh, NamedParameters>>(), np);
}

/// Kobbelt's sqrt3 subdivision of a triangle mesh. The border is refined on
/// every second step; which step is read from the mesh, so that the levels
/// may be split across calls (see `Sqrt3_split`). \sa `subdivide()`, `Sqrt3_mask`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
void sqrt3_subdivision(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  subdivide(mesh, Sqrt3_mask<PolygonMesh, internal::Call_FT<PolygonMesh, NamedParameters>>(), np);
}

/// Labsik and Greiner's interpolating sqrt3 subdivision of a triangle mesh,
/// with the border phase of `Sqrt3_split`. \sa `subdivide()`, `Interpolating_sqrt3_mask`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
void interpolating_sqrt3_subdivision(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  subdivide(mesh, Interpolating_sqrt3_mask<PolygonMesh, internal::Call_FT<PolygonMesh, NamedParameters>>(), np);
}

/// Linear refinement: positions unchanged, the 1-to-4 split on a triangle
/// mesh and the quad split otherwise. \sa `linear_triangle_subdivision()`, `linear_quad_subdivision()`
template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
void linear_subdivision(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  if(!faces(mesh).empty() && CGAL::is_triangle_mesh(mesh))
    linear_triangle_subdivision(mesh, np);
  else
    linear_quad_subdivision(mesh, np);
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_SURFACE_SUBDIVISION_H
