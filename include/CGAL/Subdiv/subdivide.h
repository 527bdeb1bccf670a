// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_SUBDIVIDE_H
#define CGAL_SUBDIV_SUBDIVIDE_H

#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/hosts/Host_for.h>
#include <CGAL/Subdiv/internal/Carried_data_fwd.h>
#include <CGAL/Subdiv/internal/isolated_vertices.h>
#include <CGAL/Subdiv/internal/mesh_checks.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/refinement/Inherited_face_map.h>
#include <CGAL/Subdiv/refinement/refine_level.h>
#include <CGAL/Subdiv/views/Sharpness_tags.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Subdiv {

namespace internal {

/*
 * Under `Boundary_interpolation::none` the faces at the border have no limit
 * surface, as in OpenSubdiv: true in `holes` for every face at a border
 * vertex that the tags of `np` do not make a crease or a corner (fewer than
 * two tagged sharp edges, no vertex sharpness), so that tagging the border
 * keeps its faces. (This is what OpenSubdiv 3.5 does on its two shapes with
 * this mode, catmark_edgenone and loop_triangle_edgenone, which the tests
 * compare face by face.)
 */
template <class PolygonMesh, class FaceHoleMap, class NamedParameters>
void make_border_faces_holes(const PolygonMesh& mesh, const FaceHoleMap& holes, const NamedParameters& np)
{
  for(auto v : vertices(mesh)) {
    if(!CGAL::is_border(v, mesh) || tagged_sharpness<vertex_sharpness_map_t>(np, v) > 0)
      continue;
    int tagged_sharp = 0;
    for(auto h : CGAL::halfedges_around_target(v, mesh))
      tagged_sharp += tagged_sharpness<edge_sharpness_map_t>(np, edge(h, mesh)) > 0 ? 1 : 0;
    if(tagged_sharp >= 2)
      continue;
    for(auto f : CGAL::faces_around_target(halfedge(v, mesh), mesh))
      if(f != boost::graph_traits<PolygonMesh>::null_face())
        put(holes, f, true);
  }
}

} // namespace internal

/*!
 * \ingroup PkgSubdivFunctions
 * refines `mesh` in place `number_of_iterations` times with the rules of
 * `mask` on the topological split of `mask` (`Mask::split`, performed by
 * `Host_of<Mask>`).
 *
 * \tparam PolygonMesh a model of `MutableFaceGraph`
 * \tparam Mask a model of `SurfaceSubdivisionMask` (`Loop_mask`, ...) over
 *         `PolygonMesh`, whose `Number_type` is the number type of the points
 *         of the vertex point map used
 * \param mesh the mesh to refine, in place
 * \param mask the rules of the scheme, with their options (a tension, a
 *        `Border_corners` value, ...)
 * \param np named parameters (`CGAL::Subdiv::parameters`, or CGAL's own):
 *   - `number_of_iterations` (default 1): how many levels;
 *   - `vertex_point_map` (default the mesh's internal point map): where the
 *     points are read and written;
 *   - `carried_data` (a `Carried_data`): other vertex data interpolated with
 *     the same stencils, face data inherited by child faces, origins;
 *   - `max_memory` (default this machine's memory, in bytes): a level count
 *     whose output would take more is refused before any work;
 *   - `isolated_vertices` (an `Isolated_vertices`, default `refuse`): what
 *     happens to vertices that belong to no face: refused, dropped, or kept
 *     unrefined after the refined vertices (not with `carried_data`);
 *   - `edge_sharpness_map`, `vertex_sharpness_map` (read-write property
 *     maps, by default none): sharpness tags as OpenSubdiv defines them (0
 *     smooth, fractional semi-sharp, 10 and above infinitely sharp; border
 *     edges are always sharp), refined with their decay and blends, with
 *     `crease_method` (`Crease_method`, default uniform); after each level
 *     the maps hold the sharpness of the children (Loop and Catmull-Clark);
 *   - `face_hole_map` (a read-write property map of bool, by default none):
 *     the faces that are holes, as OpenSubdiv's hole tags: a hole is refined
 *     like any face (its vertices take part in the rules of their
 *     neighbours) but has no limit surface, and after each level the map
 *     holds true for every child of a hole, so that the holes can be left out
 *     of what is drawn or written (`cgal-subdiv` does);
 *   - `boundary_interpolation` (`Boundary_interpolation`, default edges
 *     only): OpenSubdiv's boundary modes. It must agree with the mask's
 *     `Border_corners` (edges and corners: sharp); `none` refines as edges
 *     only and, with a `face_hole_map`, makes the faces at the border holes
 *     first;
 *   - `triangle_subdivision` (`Triangle_subdivision`): must agree with the
 *     mask's (Catmull-Clark; `catmull_clark_subdivision()` makes its mask
 *     with it);
 *   - `threads` (default 1; 0: TBB's choice): how many threads refine a
 *     `Surface_mesh` (points with double coordinates; with TBB only); the
 *     result is the same bit for bit with any number.
 *
 * \throws Bad_input when the mesh does not suit the scheme (empty, isolated
 * vertices unless `isolated_vertices` accepts them, non-manifold vertices, non-finite coordinates, a face of the wrong size, a
 * `Surface_mesh` that still holds removed elements: call `collect_garbage()`
 * first) or when the output would not fit in memory. The mesh is then unchanged.
 */
template <class PolygonMesh, class Mask, class NamedParameters = parameters::Default_named_parameters>
void subdivide(PolygonMesh& mesh, const Mask& mask, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Host = Host_of<Mask>;

  const auto vpm =
    choose_parameter(get_parameter(np, internal_np::vertex_point), get_property_map(CGAL::vertex_point, mesh));
  using VPM = std::remove_const_t<decltype(vpm)>;
  static_assert(std::is_same<typename Mask::Number_type, internal::Point_FT<internal::Point_of_map<VPM>>>::value,
                "the mask's Number_type must be the number type of the points of the vertex point map");
  const int levels = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 1);

  // setting isolated vertices aside is compiled only where the parameter is
  // passed (collect_garbage() alone costs a plain program 0.3 s to compile)
  constexpr bool may_set_aside =
    !parameters::is_default_parameter<NamedParameters, internal::isolated_vertices_t>::value;
  const Isolated_vertices isolated =
    choose_parameter(get_parameter(np, internal::isolated_vertices_t()), Isolated_vertices::refuse);
  const internal::Isolated_check isolated_check = isolated == Isolated_vertices::refuse
                                                    ? internal::Isolated_check::refuse_naming_parameter
                                                    : internal::Isolated_check::allow;
  internal::check_mask_options(mask, np);
  internal::check_mesh(mesh, vpm, mask.name(), Host::required_face_size, isolated_check);
  const auto tags = internal::sharpness_tags_of<PolygonMesh, typename Mask::Number_type>(np);
  tags.check(mesh, mask, mask.name());
  internal::check_output_faces(mask.name(), static_cast<double>(num_faces(mesh)), Host::face_growth(),
                               Host::peak_bytes_per_face(), levels, internal::max_memory_of(np));
  const internal::Parallel_loop loop = internal::parallel_loop(np);

  // (`Carried_data` is only declared here: its header is included by whoever makes one)
  const Carried_data<PolygonMesh, typename Mask::Number_type>* data = nullptr;
  bool carried = false;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal::carried_data_t>::value) {
    data = get_parameter(np, internal::carried_data_t());
    carried = data != nullptr && !data->empty();
    if(carried)
      data->prepare(mesh, mask);
  }
  // set aside before the refinement, put back after it (kept: unrefined)
  internal::Isolated_points<VPM> set_aside;
  if constexpr(may_set_aside)
    if(isolated != Isolated_vertices::refuse)
      set_aside = internal::remove_isolated_vertices(mesh, vpm, mask.name(), carried);

  internal::reserve_levels<Host>(mesh, levels);
  // one level with `level_mask` (the mask, with the sharpness tags of the
  // level if there are some) and `sinks`; the carried path (rows recorded per
  // level) is compiled only where carried_data is passed: a plain program
  // does not pay for it
  const auto refine_one = [&](const auto& level_mask, auto&... sinks) {
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal::carried_data_t>::value) {
      using Data = Carried_data<PolygonMesh, typename Mask::Number_type>;
      if(carried) {
        typename Data::Level carried_level(*data, mesh);
        if(data->records_vertex_stencils()) { // the points from the recorded stencils, as the vertex data
          const internal::Row_points<VPM, typename Data::Vertex_stencils> points{vpm, &carried_level.stencils()};
          internal::refine_level(mesh, level_mask, points, internal::Parallel_loop(1), carried_level, sinks...);
        } else // corner and face data only: the points of the plain path
          internal::refine_level(mesh, level_mask, internal::Mask_points<VPM>{vpm}, loop, carried_level, sinks...);
        return;
      }
    }
    internal::refine_level(mesh, level_mask, internal::Mask_points<VPM>{vpm}, loop, sinks...);
  };
  // the children of a hole are holes: the hole map is inherited level by level
  constexpr bool has_holes = !parameters::is_default_parameter<NamedParameters, internal::face_hole_map_t>::value;
  const auto refine_one_with_holes = [&](const auto& level_mask, auto&... sinks) {
    if constexpr(has_holes) {
      using Holes = std::remove_const_t<decltype(get_parameter(np, internal::face_hole_map_t()))>;
      internal::Inherited_face_map<PolygonMesh, Holes> holes(mesh, get_parameter(np, internal::face_hole_map_t()));
      refine_one(level_mask, holes, sinks...);
    } else
      refine_one(level_mask, sinks...);
  };
  if constexpr(has_holes)
    if(levels > 0 && choose_parameter(get_parameter(np, internal::boundary_interpolation_t()),
                                      Boundary_interpolation::edges_only) == Boundary_interpolation::none)
      internal::make_border_faces_holes(mesh, get_parameter(np, internal::face_hole_map_t()), np);
  for(int level = 0; level < levels; ++level)
    tags.refine(mesh, mask, refine_one_with_holes);
  if constexpr(may_set_aside)
    if(isolated == Isolated_vertices::keep)
      internal::add_isolated_vertices(mesh, vpm, set_aside);
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_SUBDIVIDE_H
