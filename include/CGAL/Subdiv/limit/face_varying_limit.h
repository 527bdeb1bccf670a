// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_FACE_VARYING_LIMIT_H
#define CGAL_SUBDIV_LIMIT_FACE_VARYING_LIMIT_H

/// \file face_varying_limit.h
/// The limit of face-varying data (`face_varying_limit()`): OpenSubdiv's
/// `PrimvarRefiner::LimitFaceVarying`, from the cut mesh that refinement
/// uses and the limit of its points.

#include <CGAL/Subdiv/limit/project_to_limit.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/refinement/Face_varying.h>
#include <CGAL/Subdiv/views/Sharpness_tags.h>
#include <CGAL/Subdiv/views/Vertex_view.h>

#include <CGAL/Dimension.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/// a value of a corner map (a 2D or 3D point or vector) as a point of the cut mesh
template <class Value>
Face_varying_cut_mesh::Point value_as_cut_point(const Value& value)
{
  if constexpr(Value::Ambient_dimension::value == 2)
    return Face_varying_cut_mesh::Point(CGAL::to_double(value.x()), CGAL::to_double(value.y()), 0);
  else
    return Face_varying_cut_mesh::Point(CGAL::to_double(value.x()), CGAL::to_double(value.y()),
                                        CGAL::to_double(value.z()));
}

/// a point of the cut mesh as a value of a corner map
template <class Value>
Value cut_point_as_value(const Face_varying_cut_mesh::Point& p)
{
  if constexpr(Value::Ambient_dimension::value == 2)
    return Value(p.x(), p.y());
  else
    return Value(p.x(), p.y(), p.z());
}

/// `mask` with smooth border corners: the cut mesh's corners are kept by the
/// face-varying mode, not by the mesh's boundary interpolation (as in
/// `smooth_face_varying_rows`)
template <class Mask>
auto with_smooth_border_corners(const Mask& mask)
{
  if constexpr(Has_border_corners<Mask>::value)
    return mask.with_border_corners(Border_corners::smooth);
  else
    return mask;
}

} // namespace internal

/*!
 * \ingroup PkgSubdivAnalysis
 * writes into `limit` the limit of every corner value of the corner map
 * `values` of `mesh` (face-varying data, such as UVs with seams) under the
 * scheme of `mask` in `mode`, as OpenSubdiv's
 * `PrimvarRefiner::LimitFaceVarying` does on a refined level: `limit` and
 * `values` are halfedge property maps (the value of `face(h)` at
 * `target(h)`), `indices` a halfedge map of value indices that gives the
 * face-varying topology (as in `Carried_data::corner_map(map, mode,
 * index_map)`). The mesh is cut along the seams as refinement cuts it (one
 * vertex per value, a seam a border), the values are the points of the cut
 * mesh, and each moves to its limit position (`project_to_limit()`) with the
 * sharpness tags of the mesh's level (np: `edge_sharpness_map`,
 * `vertex_sharpness_map`) and the vertices that `mode` keeps infinitely
 * sharp; with `Face_varying_interpolation::all`, and with the linear masks
 * in every mode, every value is its own limit (linear in every face). Values
 * are 2D or 3D points or vectors of any kernel, computed in double. For
 * Loop, Catmull-Clark and the linear masks. With np `non_manifold_copies`
 * (the map given to `Carried_data::non_manifold_copies`, which keeps it
 * through the levels), the copies of one non-manifold vertex whose corners
 * do not all hold one value keep their values, as OpenSubdiv's limit keeps
 * them. \throws Bad_input where `project_to_limit()` does (a vertex the
 * analysis does not cover, such as an interior triangle vertex of valence 2).
 */
template <class PolygonMesh, class Mask, class CornerMap, class IndexMap, class LimitMap,
          class NamedParameters = parameters::Default_named_parameters>
void face_varying_limit(const PolygonMesh& mesh, const Mask& mask, CornerMap values, Face_varying_interpolation mode,
                        IndexMap indices, LimitMap limit, const NamedParameters& np = parameters::default_values())
{
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  using Cut = internal::Face_varying_cut_mesh;
  using Value = typename boost::property_traits<CornerMap>::value_type;
  if(mode == Face_varying_interpolation::all) { // linear in every face: every value is its limit
    for(const auto f : faces(mesh))
      for(const halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
        put(limit, h, internal::cut_point_as_value<Value>(internal::value_as_cut_point(get(values, h))));
    return;
  }
  const auto same = [&](halfedge_descriptor a, halfedge_descriptor b) { return get(indices, a) == get(indices, b); };
  // the copies of a non-manifold vertex whose corners disagree keep their values
  std::vector<bool> pinned;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal::non_manifold_copies_t>::value) {
    const auto point_of = parameters::get_parameter(np, internal::non_manifold_copies_t());
    pinned = internal::non_manifold_corners(
      mesh, [&](auto v) { return static_cast<std::size_t>(get(point_of, v)); }, same);
  }
  const internal::Face_varying_topology<PolygonMesh> topology(mesh, same, false, std::move(pinned));

  // the sharpness of the mesh's level, and so of the cut mesh
  const auto tags = internal::sharpness_tags_of<PolygonMesh, double>(np);
  const auto mesh_mask = mask.template rebind<PolygonMesh, double>();
  const internal::Sharpness_by_ordinal<double> sharpness = [&]() {
    if constexpr(!std::is_same<std::decay_t<decltype(tags)>, internal::No_sharpness_tags>::value) {
      tags.check(mesh, mesh_mask, "face_varying_limit (" + mesh_mask.name() + ")");
      return internal::cut_sharpness(topology, tags.level(mesh, internal::border_corners_of(mesh_mask)), mode);
    } else {
      return internal::cut_sharpness(
        topology, internal::Untagged_level<PolygonMesh, double>(mesh, internal::border_corners_of(mesh_mask)), mode);
    }
  }();

  // the values as the points of the cut mesh, moved to their limit
  Cut cut = topology.cut();
  for(const typename Cut::Vertex_index v : cut.vertices())
    cut.point(v) = internal::value_as_cut_point(get(values, topology.corner_of(v)));
  const auto edge_sharpness = cut.add_property_map<typename Cut::Edge_index, double>("e:cgal_subdiv_fvar").first;
  for(const typename Cut::Edge_index e : cut.edges())
    edge_sharpness[e] = static_cast<double>(sharpness.edges[e.idx()]);
  const auto vertex_sharpness = cut.add_property_map<typename Cut::Vertex_index, double>("v:cgal_subdiv_fvar").first;
  for(const typename Cut::Vertex_index v : cut.vertices())
    vertex_sharpness[v] = static_cast<double>(sharpness.vertices[v.idx()]);
  project_to_limit(cut, internal::with_smooth_border_corners(mask.template rebind<Cut, double>()),
                   parameters::edge_sharpness_map(edge_sharpness).vertex_sharpness_map(vertex_sharpness));

  for(const auto f : faces(mesh))
    for(const halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      put(limit, h, internal::cut_point_as_value<Value>(cut.point(topology.value_at(h))));
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_FACE_VARYING_LIMIT_H
