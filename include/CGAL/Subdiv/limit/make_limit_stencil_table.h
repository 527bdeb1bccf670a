// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_MAKE_LIMIT_STENCIL_TABLE_H
#define CGAL_SUBDIV_LIMIT_MAKE_LIMIT_STENCIL_TABLE_H

#include <CGAL/Subdiv/hosts/hosts.h>
#include <CGAL/Subdiv/limit/Limit_evaluator.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/stencils/Stencil_table.h>
#include <CGAL/Subdiv/stencils/make_stencil_table.h>

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivStencils
 * Limit stencils after some levels (see `make_limit_stencil_tables()`):
 * row i of each table belongs to vertex i of the refined mesh, its sources
 * are the vertices of the coarse mesh.
 */
struct Limit_stencil_tables
{
  /// the limit position of every refined vertex
  Stencil_table<double> position;
  /// the two tangent vectors of the analysis' tangent masks
  /// (`Limit_masks::tangent`: t0 x t1 points to the side from which the faces
  /// are counter-clockwise), rows of weights summing to 0
  Stencil_table<double> tangent[2];
  /// per refined vertex: whether its tangent masks give the tangent plane
  /// (`Limit_masks::tangents`); elsewhere `limit_normals()` falls back to face
  /// normals, and so should the user of these tables
  std::vector<char> has_tangents;
};

/*!
 * \ingroup PkgSubdivStencils
 * Limit stencils: the limit positions and tangent vectors of the vertices of
 * `mesh` refined `number_of_iterations` times by the scheme of `evaluator`,
 * as tables over the coarse control points. So
 * `tables.position.apply(control_points, limit_points)` is `subdivide()`
 * followed by `project_to_limit()`, in one pass (equal up to rounding: the
 * sums are associated differently).
 *
 * The rows are the limit rows of the refined mesh (`Limit_evaluator::rows()`)
 * composed with the stencils of `make_stencil_table()`. For a mesh with
 * double coordinates. np as `make_stencil_table()`: `number_of_iterations`,
 * `refined_mesh` (with the refined, not the limit, points), `threads`, the
 * sharpness tags (`edge_sharpness_map`, `vertex_sharpness_map`,
 * `crease_method`): the limit rows of the refined mesh then take the tags of
 * its level, as `project_to_limit()` does (a corner stays, a crease goes to
 * the limit of its curve rule; Loop's and Catmull-Clark's have tangent rows
 * as OpenSubdiv Far's, see `internal::sharp_limit_rows`; the other schemes'
 * have none: their `has_tangents` is false).
 * \throws Bad_input as `subdivide()` and `project_to_limit()` do.
 */
template <class Mask, class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
Limit_stencil_tables make_limit_stencil_tables(const PolygonMesh& mesh, const Limit_evaluator<Mask>& evaluator,
                                               const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  static_assert(std::is_same<internal::Mesh_FT<PolygonMesh>, double>::value,
                "limit stencil tables: a mesh with double coordinates");
  const int levels = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 1);
  PolygonMesh* refined_mesh = choose_parameter<PolygonMesh*>(get_parameter(np, internal::refined_mesh_t()), nullptr);
  PolygonMesh refined;
  const auto vpm = get_const_property_map(CGAL::vertex_point, mesh);
  internal::Sharpness_by_ordinal<double> refined_sharpness;
  const Stencil_table<double> table =
    internal::stencil_table_of(mesh, evaluator.template mask<PolygonMesh, double>(), vpm, levels, &refined,
                               internal::parallel_loop(np), internal::max_memory_of(np), np, &refined_sharpness);
  const auto limit_rows = [&](const auto& tags) {
    return evaluator.template rows<double>(refined, get_const_property_map(CGAL::vertex_point, refined),
                                           "make_limit_stencil_tables", tags);
  };
  const internal::Limit_rows<double> rows = [&] {
    if constexpr(internal::has_sharpness_tags<NamedParameters>()) {
      const internal::Mesh_numbering<PolygonMesh> refined_number(refined);
      return limit_rows(internal::tags_by_ordinal(refined_number, refined_sharpness));
    } else
      return limit_rows(internal::No_sharpness_tags());
  }();
  const auto to_table = [&](const internal::Rows<double>& r) {
    Stencil_table<double> limit(num_vertices(refined));
    for(const auto& row : r)
      limit.add_stencil(row);
    return table.then(limit);
  };
  Limit_stencil_tables result;
  result.position = to_table(rows.position);
  result.tangent[0] = to_table(rows.tangent[0]);
  result.tangent[1] = to_table(rows.tangent[1]);
  result.has_tangents = rows.has_tangents;
  if(refined_mesh != nullptr)
    *refined_mesh = std::move(refined);
  return result;
}

/// the same with a new evaluator of `mask`
template <class PolygonMesh, class Mask, class NamedParameters = parameters::Default_named_parameters>
Limit_stencil_tables make_limit_stencil_tables(const PolygonMesh& mesh, const Mask& mask,
                                               const NamedParameters& np = parameters::default_values())
{
  return make_limit_stencil_tables(mesh, Limit_evaluator<Mask>(mask), np);
}

/*!
 * \ingroup PkgSubdivStencils
 * the limit positions after `number_of_iterations` levels of the scheme of
 * `mask` as one table over the coarse control points:
 * `make_limit_stencil_table(mesh, Loop_mask<Mesh>(), parameters::number_of_iterations(2))`.
 * See `make_limit_stencil_tables()`.
 */
template <class PolygonMesh, class Mask, class NamedParameters = parameters::Default_named_parameters>
Stencil_table<double> make_limit_stencil_table(const PolygonMesh& mesh, const Mask& mask,
                                               const NamedParameters& np = parameters::default_values())
{
  return make_limit_stencil_tables(mesh, Limit_evaluator<Mask>(mask), np).position;
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_MAKE_LIMIT_STENCIL_TABLE_H
