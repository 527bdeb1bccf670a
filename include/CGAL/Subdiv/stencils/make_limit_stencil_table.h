// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MAKE_LIMIT_STENCIL_TABLE_H
#define CGAL_SUBDIV_MAKE_LIMIT_STENCIL_TABLE_H

#include <CGAL/Subdiv/analysis/limit.h>
#include <CGAL/Subdiv/hosts/Quad_split.h>
#include <CGAL/Subdiv/hosts/Triangle_quadrisection.h>
#include <CGAL/Subdiv/stencils/make_stencil_table.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivStencils
 * Limit stencils after `levels` levels (see `make_limit_stencil_tables()`):
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

namespace internal {

template <class T>
struct Non_deduced
{
  using type = T;
};

using Sparse_row = std::vector<std::pair<std::uint32_t, double>>;

// adds w * row to `sum` (merging repeated sources, first-appearance order)
inline void add_scaled(Sparse_row& sum, const Sparse_row& row, double w)
{
  for(const auto& term : row) {
    bool found = false;
    for(auto& s : sum)
      if(s.first == term.first) {
        s.second += w * term.second;
        found = true;
        break;
      }
    if(!found)
      sum.emplace_back(term.first, w * term.second);
  }
}

/*
 * The limit rows (position, two tangents, over the vertex ordinals of `mesh`)
 * of the vertices `targets` of `mesh`, from the masks of the analysis at each
 * vertex's configuration, read on the mesh with the evaluator's own walk.
 * A vertex whose neighbourhood is not the analysed one yet is evaluated at
 * its descendant one level further (as `Limit_evaluator` does), and its rows
 * composed with that level's stencils.
 */
template <class Evaluator, class Mesh>
void limit_rows(const Evaluator& evaluator, const Mesh& mesh, const std::vector<std::uint32_t>& targets,
                std::vector<Sparse_row> (&rows)[3], std::vector<char>& has_tangents, int depth)
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  const Mesh_numbering<Mesh> number(mesh);
  std::vector<vertex_descriptor> by_ordinal(num_vertices(mesh));
  for(vertex_descriptor v : vertices(mesh))
    by_ordinal[number(v)] = v;
  Neighbourhood_reader<Mesh> reader(mesh);
  std::vector<std::size_t> pending;
  for(std::size_t k = 0; k < targets.size(); ++k) {
    const vertex_descriptor v = by_ordinal[targets[k]];
    const Vertex_configuration<Mesh> c = vertex_configuration(v, mesh);
    const Limit_masks& lm = evaluator.masks(c.valence, c.border);
    if(!reader.read(c.start, lm.rings + 1, lm.neighbourhood_size) || reader.transcript != lm.connectivity) {
      pending.push_back(k);
      continue;
    }
    Sparse_row position, tangent[2];
    for(std::size_t i = 0; i < lm.limit.size(); ++i)
      if(lm.limit[i] != 0)
        position.emplace_back(static_cast<std::uint32_t>(number(reader.vertices_by_label[i])),
                              exact_weight_as<double>(lm.limit[i]));
    for(int a = 0; a < 2; ++a) {
      double centre = 0;
      tangent[a].emplace_back(static_cast<std::uint32_t>(number(reader.vertices_by_label[0])), 0.0);
      for(std::size_t i = 1; i < lm.tangent[a].size(); ++i) {
        if(lm.tangent[a][i] == 0)
          continue;
        tangent[a].emplace_back(static_cast<std::uint32_t>(number(reader.vertices_by_label[i])), lm.tangent[a][i]);
        centre -= lm.tangent[a][i];
      }
      tangent[a][0].second = centre;
    }
    rows[0][k] = std::move(position);
    rows[1][k] = std::move(tangent[0]);
    rows[2][k] = std::move(tangent[1]);
    has_tangents[k] = lm.tangents ? 1 : 0;
  }
  if(pending.empty())
    return;
  require(depth < evaluator.max_extra_levels,
          "make_limit_stencil_tables: the neighbourhood of refined vertex " + std::to_string(targets[pending.front()]) +
            " does not become the analysed one after " + std::to_string(depth) + " more levels");
  // one more level: the stencils of its vertices over this level's, and its
  // topology; a primal host numbers the old vertices first, so the
  // descendant of vertex j is vertex j
  Mesh finer = mesh;
  const auto mask = evaluator.template mask<Mesh, double>();
  Composed_level<double> composed{nullptr, num_vertices(finer)};
  const auto finer_points = get(CGAL::vertex_point, finer);
  refine_level(finer, mask, No_points<decltype(finer_points)>{finer_points}, Parallel_loop(1), composed);
  const Stencil_table<double>& level = composed.table;
  std::vector<std::uint32_t> descendants;
  for(const std::size_t k : pending)
    descendants.push_back(targets[k]);
  std::vector<Sparse_row> finer_rows[3];
  for(auto& r : finer_rows)
    r.resize(descendants.size());
  std::vector<char> finer_tangents(descendants.size(), 0);
  limit_rows(evaluator, finer, descendants, finer_rows, finer_tangents, depth + 1);
  for(std::size_t p = 0; p < pending.size(); ++p) {
    for(int r = 0; r < 3; ++r) {
      Sparse_row composed;
      for(const auto& term : finer_rows[r][p]) {
        Sparse_row stencil;
        for(std::size_t t = level.stencil_begin(term.first); t < level.stencil_end(term.first); ++t)
          stencil.emplace_back(level.source(t), level.weight(t));
        add_scaled(composed, stencil, term.second);
      }
      rows[r][pending[p]] = std::move(composed);
    }
    has_tangents[pending[p]] = finer_tangents[p];
  }
}

} // namespace internal

/*!
 * \ingroup PkgSubdivStencils
 * Limit stencils: the limit positions and tangent vectors of the vertices of
 * `mesh` refined `levels` times by the scheme of `evaluator`
 * (`make_limit_evaluator<Loop_mask>()`, ...), as tables over the coarse
 * control points. So `tables.position.apply(control_points, limit_points)`
 * is `subdivide()` `levels` times followed by `project_to_limit()`, in one
 * pass (equal up to rounding: the sums are associated differently).
 *
 * The rows are the limit and tangent masks of the analysis
 * (`Limit_evaluator::masks()`, read on the refined mesh with the evaluator's
 * own walk; a vertex whose neighbourhood is not the analysed one yet is
 * evaluated at its descendant further down, as `project_to_limit()` does)
 * composed with the stencils of `make_stencil_table()`.
 *
 * For the schemes of the primal triangle and quad splits (Loop,
 * Catmull-Clark, the butterflies, the linear schemes), on a mesh with double
 * coordinates. `refined_mesh`, if given, receives the refined mesh (with the
 * refined, not the limit, points). Named parameters as `make_stencil_table()`.
 * \throws Bad_input as `subdivide()` and `project_to_limit()` do.
 */
template <template <class, class> class MaskTemplate, class... Args, class PolygonMesh,
          class NamedParameters = parameters::Default_named_parameters>
Limit_stencil_tables make_limit_stencil_tables(
  const PolygonMesh& mesh, int levels, const Limit_evaluator<MaskTemplate, Args...>& evaluator,
  typename internal::Non_deduced<PolygonMesh>::type* refined_mesh = nullptr,
  const NamedParameters& np = parameters::default_values())
{
  using Mask = MaskTemplate<PolygonMesh, double>;
  using Host = Host_of<Mask>;
  static_assert(std::is_same<Host, Triangle_quadrisection<PolygonMesh>>::value ||
                  std::is_same<Host, Quad_split<PolygonMesh>>::value,
                "limit stencil tables: schemes of the primal triangle and quad splits");
  static_assert(std::is_same<internal::Mesh_FT<PolygonMesh>, double>::value,
                "limit stencil tables: a mesh with double coordinates");
  PolygonMesh refined;
  const Stencil_table<double> table = internal::stencil_table_of(mesh, evaluator.template mask<PolygonMesh, double>(),
                                                                 get_const_property_map(CGAL::vertex_point, mesh),
                                                                 levels, &refined, internal::parallel_loop(np));
  // the analysis' masks need a mesh the scheme applies to, as project_to_limit() checks
  internal::check_mesh(refined, get(CGAL::vertex_point, refined), evaluator.template mask<PolygonMesh, double>().name(),
                       Host::required_face_size);

  const std::size_t n = num_vertices(refined);
  std::vector<std::uint32_t> targets(n);
  for(std::size_t i = 0; i < n; ++i)
    targets[i] = static_cast<std::uint32_t>(i);
  std::vector<internal::Sparse_row> rows[3];
  for(auto& r : rows)
    r.resize(n);
  Limit_stencil_tables result;
  result.has_tangents.assign(n, 0);
  internal::limit_rows(evaluator, refined, targets, rows, result.has_tangents, 0);
  Stencil_table<double>* out[3] = {&result.position, &result.tangent[0], &result.tangent[1]};
  for(int r = 0; r < 3; ++r) {
    Stencil_table<double> limit(n);
    for(const auto& row : rows[r])
      limit.add_stencil(row);
    *out[r] = table.then(limit);
  }
  if(refined_mesh != nullptr)
    *refined_mesh = std::move(refined);
  return result;
}

/*!
 * \ingroup PkgSubdivStencils
 * the limit positions after `levels` levels of `MaskTemplate` (default mask
 * arguments) as one table over the coarse control points:
 * `make_limit_stencil_table<Loop_mask>(mesh, 2)`. See
 * `make_limit_stencil_tables()`.
 */
template <template <class, class> class MaskTemplate, class PolygonMesh,
          class NamedParameters = parameters::Default_named_parameters>
Stencil_table<double> make_limit_stencil_table(const PolygonMesh& mesh, int levels,
                                               const NamedParameters& np = parameters::default_values())
{
  return make_limit_stencil_tables(mesh, levels, make_limit_evaluator<MaskTemplate>(),
                                   static_cast<PolygonMesh*>(nullptr), np)
    .position;
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MAKE_LIMIT_STENCIL_TABLE_H
