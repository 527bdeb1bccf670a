// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MARK_SHARP_EDGES_H
#define CGAL_SUBDIV_MARK_SHARP_EDGES_H

/// \file mark_sharp_edges.h
/// Creases from the geometry: the edges where the surface bends by more than
/// an angle become infinitely sharp, for the `edge_sharpness_map` of the
/// subdivision functions (something OpenSubdiv leaves to its users).

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivFunctions
 * makes infinitely sharp (sharpness 10, OpenSubdiv's `SHARPNESS_INFINITE`)
 * every edge of `mesh` whose two faces' normals make an angle of more than
 * `angle_in_degrees` (`CGAL::Polygon_mesh_processing::detect_sharp_edges`,
 * whose test this is: 0 marks every edge, 180 none). Border edges are not
 * marked: they are infinitely sharp anyway.
 * The other edges keep their value in `edge_sharpness`, so that tags read
 * from a file and creases from the angle add up.
 *
 * \tparam PolygonMesh a model of `FaceListGraph`
 * \tparam EdgeSharpnessMap a model of `ReadWritePropertyMap` from
 *         `boost::graph_traits<PolygonMesh>::%edge_descriptor` to a number
 *         type (the `edge_sharpness_map` of `subdivide()`)
 * \param mesh the mesh, with its points
 * \param angle_in_degrees the angle between two faces' normals above which
 *        their edge is sharp
 * \param edge_sharpness the map the sharpness 10 is written to
 * \param np `vertex_point_map` and `geom_traits`, passed to
 *        `detect_sharp_edges`
 * \returns the number of edges marked
 * \throws Bad_input when `angle_in_degrees` is not in [0, 180]
 */
template <class PolygonMesh, class EdgeSharpnessMap, class NamedParameters = parameters::Default_named_parameters>
std::size_t mark_sharp_edges(const PolygonMesh& mesh, double angle_in_degrees, EdgeSharpnessMap edge_sharpness,
                             const NamedParameters& np = parameters::default_values())
{
  internal::require(
    angle_in_degrees >= 0 && angle_in_degrees <= 180,
    "mark_sharp_edges: the angle is in degrees, from 0 to 180, not " + std::to_string(angle_in_degrees));
  const auto is_sharp = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
  CGAL::Polygon_mesh_processing::detect_sharp_edges(mesh, angle_in_degrees, is_sharp, np);
  using Sharpness = typename boost::property_traits<EdgeSharpnessMap>::value_type;
  std::size_t marked = 0;
  for(const auto e : edges(mesh))
    if(get(is_sharp, e) && !CGAL::is_border(e, mesh)) { // detect_sharp_edges marks the border too
      put(edge_sharpness, e, Sharpness(10));
      ++marked;
    }
  return marked;
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MARK_SHARP_EDGES_H
