// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_CALL_PARAMETERS_H
#define CGAL_SUBDIV_INTERNAL_CALL_PARAMETERS_H

// What the one-line wrappers of `subdivide()` (loop_subdivision() and the
// like) read from their named parameters to make their mask.

#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Subdiv {

namespace internal {

/// the number type of the masks of a call: that of the kernel of its
/// `geom_traits`, by default the kernel of the points of its `vertex_point_map`
template <class PolygonMesh, class NamedParameters>
using Call_FT = typename GetGeomTraits<PolygonMesh, NamedParameters>::type::FT;

/// the `Border_corners` of the masks of a call (its `boundary_interpolation`)
template <class NamedParameters>
Border_corners call_border_corners(const NamedParameters& np)
{
  return border_corners_for(parameters::choose_parameter(parameters::get_parameter(np, boundary_interpolation_t()),
                                                         Boundary_interpolation::edges_only));
}

} // namespace internal

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_CALL_PARAMETERS_H
