// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MAKE_STENCIL_TABLE_H
#define CGAL_SUBDIV_MAKE_STENCIL_TABLE_H

#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/stencils/Stencil.h>
#include <CGAL/Subdiv/stencils/Stencil_table.h>
#include <CGAL/Subdiv/subdivide.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

// records a mask's weights by ordinal of the old vertex
template <class Mesh, class FT>
struct Ordinal_stencil
{
  const Mesh_numbering<Mesh>& number;
  Stencil<std::size_t, FT> stencil;

  void add(typename boost::graph_traits<Mesh>::vertex_descriptor v, const FT& w) { stencil.add(number(v), w); }
};

// One level on `mesh`: returns the level's stencil table (new vertex -> old
// vertices, by ordinal) and replaces `mesh` by the refined topology. Points of
// the refined mesh are left at the origin: the caller computes them.
template <class Mask, class Mesh, class VertexPointMap>
Stencil_table<typename Mask::Number_type> refine_topology_once(Mesh& mesh, const Mask& mask, const VertexPointMap& vpm)
{
  using FT = typename Mask::Number_type;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  const typename Mask::Host host(mesh);
  const Mesh_numbering<Mesh> number(mesh);
  std::vector<Stencil<std::size_t, FT>> rows(host.number_of_new_vertices());
  host.for_each_new_vertex(mask, [&](std::size_t j, const auto& report) {
    Ordinal_stencil<Mesh, FT> acc{number, {}};
    report(acc);
    rows[j] = std::move(acc.stencil);
  });
  Stencil_table<FT> table(num_vertices(mesh));
  for(const auto& row : rows)
    table.add_stencil(row.terms());
  const Face_soup soup = host.faces();
  rebuild_mesh(mesh, vpm, std::vector<Point>(rows.size(), Point(CGAL::ORIGIN)), soup);
  return table;
}

} // namespace internal

/*!
 * \ingroup PkgSubdivStencils
 * composes `levels` levels of the scheme of `mask` on the topology of `mesh`
 * into one table: stencil i gives vertex i of the refined mesh (in the order
 * `subdivide()` creates them) from the vertices of `mesh` (in its iteration
 * order). Then `table.apply(coarse_points, refined_points)` re-evaluates the
 * refined points for moved control points in one pass, and the same table
 * carries any other per-vertex data.
 *
 * If `refined_mesh` is given, it receives the refined mesh, with the points
 * that the table gives for the current points of `mesh`.
 *
 * The stencils come from the same masks as `subdivide()`, so applying the
 * table to the points of `mesh` gives exactly the points of `subdivide()`
 * (exactly, in an exact kernel).
 * \throws Bad_input as `subdivide()` does.
 */
template <class PolygonMesh, class Mask, class NamedParameters = parameters::Default_named_parameters>
Stencil_table<typename Mask::Number_type> make_stencil_table(const PolygonMesh& mesh, const Mask& mask, int levels,
                                                             PolygonMesh* refined_mesh = nullptr,
                                                             const NamedParameters& np = parameters::default_values())
{
  using FT = typename Mask::Number_type;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  internal::check_mesh(mesh, vpm, mask.name(), Mask::Host::required_face_size);
  internal::check_output_faces(mask.name(), static_cast<double>(num_faces(mesh)), Mask::Host::face_growth(), levels);

  internal::require(!internal::has_garbage(mesh), "make_stencil_table: call collect_garbage() on the mesh first");
  PolygonMesh work = mesh;
  const auto work_vpm = get(CGAL::vertex_point, work);
  Stencil_table<FT> table = Stencil_table<FT>::identity(num_vertices(mesh));
  for(int level = 0; level < levels; ++level)
    table = table.then(internal::refine_topology_once(work, mask, work_vpm));

  if(refined_mesh != nullptr) {
    using Point = typename boost::property_traits<decltype(work_vpm)>::value_type;
    std::vector<Point> coarse, fine;
    for(auto v : vertices(mesh))
      coarse.push_back(get(vpm, v));
    table.apply(coarse, fine);
    std::size_t i = 0;
    for(auto v : vertices(work))
      put(work_vpm, v, fine[i++]);
    *refined_mesh = std::move(work);
  }
  return table;
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MAKE_STENCIL_TABLE_H
