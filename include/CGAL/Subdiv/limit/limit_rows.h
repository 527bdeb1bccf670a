// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_LIMIT_ROWS_H
#define CGAL_SUBDIV_LIMIT_LIMIT_ROWS_H

/// \file limit_rows.h
/// The limit as rows: the limit position and the two tangent vectors of a
/// vertex as combinations of the control points, from the masks of the
/// analysis. This is the one place where the limit is evaluated; the
/// projection, the normals, the displacement and the limit stencil tables
/// apply these rows.
///
/// The masks of the analysis at a configuration (interior valence n, or a
/// border vertex with k faces) apply at a vertex whose neighbourhood of
/// `rings + 1` rings has exactly the connectivity of the analysed one: the
/// one walk (`Neighbourhood_walk`) reads the same transcript. A vertex whose
/// neighbourhood does not match (next to another extraordinary vertex or to
/// the border, a non-quad face for Catmull-Clark, ...) is evaluated at its
/// descendant one level further (the same limit point and tangent plane),
/// whose rows are composed with that level's stencils.

#include <CGAL/Subdiv/analysis/Limit_masks.h>
#include <CGAL/Subdiv/analysis/Neighbourhood_walk.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/hosts/hosts.h>
#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/refinement/refine_level.h>
#include <CGAL/Subdiv/stencils/Row_builder.h>
#include <CGAL/Subdiv/stencils/Stencil.h>
#include <CGAL/Subdiv/stencils/make_stencil_table.h>
#include <CGAL/Subdiv/views/Vertex_view.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/// rows over the vertex ordinals of a mesh: one per target vertex
template <class FT>
using Rows = std::vector<Stencil<std::uint32_t, FT>>;

/// the limit rows of some vertices of a mesh, over the vertex ordinals of the mesh
template <class FT>
struct Limit_rows
{
  Rows<FT> position;   ///< the limit position
  Rows<FT> tangent[2]; ///< the two tangent vectors (rows summing to 0)
  std::vector<char> has_tangents;

  explicit Limit_rows(std::size_t n = 0) : position(n), has_tangents(n, 0)
  {
    tangent[0].resize(n);
    tangent[1].resize(n);
  }
};

/// row = row composed with `level` (its sources are rows of `level`)
template <class FT>
void compose_with(Stencil<std::uint32_t, FT>& row, const Stencil_table<FT>& level, Row_builder<FT>& builder)
{
  builder.start(level.number_of_sources(), level.terms_under(row));
  level.compose_into(builder, row);
  Stencil<std::uint32_t, FT> composed;
  for(std::size_t k = 0; k < builder.size(); ++k)
    composed.add(builder.source(k), builder.weight(k));
  row = std::move(composed);
}

/*
 * Where the walk around v starts: interior, any halfedge leaving v; border,
 * the halfedge leaving v along the border edge whose face is on its left.
 */
template <class Mesh>
typename boost::graph_traits<Mesh>::halfedge_descriptor walk_start(const Vertex_view<Mesh>& v)
{
  return v.on_border() ? opposite(v.border_in(), v.mesh()) : opposite(halfedge(v.vertex(), v.mesh()), v.mesh());
}

// whether the next step of a sqrt3 host refines the border (false for other hosts)
template <class Host>
bool border_is_pending(const Host& host)
{
  if constexpr(Host::analysis_steps == 2)
    return host.refines_border();
  else {
    (void)host;
    return false;
  }
}

/*
 * The limit rows of the vertices `targets` (ordinals) of `mesh` under
 * `mask` (over `mesh`, in its number type); `masks(n, border)` gives the
 * analysis' masks of a configuration. Vertices not matched yet are
 * evaluated one level further, up to `max_extra_levels` levels.
 * \throws Bad_input naming `caller` and the vertex (by `ids`)
 */
template <class Masks, class Mask, class Mesh>
Limit_rows<typename Mask::Number_type> limit_rows(const Masks& masks, const Mask& mask, const Mesh& mesh,
                                                  const std::vector<std::size_t>& targets,
                                                  const std::vector<std::size_t>& ids, int max_extra_levels, int depth,
                                                  const std::string& caller)
{
  using FT = typename Mask::Number_type;
  using Host = Host_of<Mask>;
  Limit_rows<FT> rows(targets.size());
  Neighbourhood_walk<Mesh> walk(mesh);
  const Mesh_numbering<Mesh>& number = walk.numbering();
  const auto ordinal = [&](std::size_t label) { return static_cast<std::uint32_t>(number(walk.vertices[label])); };
  // sqrt3 hosts: the border masks are those of a resting step followed by a
  // refining one; on a mesh whose next step refines the border, border
  // vertices are evaluated one step later
  const bool border_phase_differs = border_is_pending(Host(mesh));
  std::vector<std::size_t> pending;
  for(std::size_t k = 0; k < targets.size(); ++k) {
    const Vertex_view<Mesh> v(mesh, number.vertex(targets[k]));
    if(v.on_border() && border_phase_differs) {
      pending.push_back(k);
      continue;
    }
    const int n = v.on_border() ? v.number_of_faces() : v.valence();
    const Limit_masks* found = nullptr;
    try {
      found = &masks(n, v.on_border());
    } catch(const Bad_input& e) {
      throw Bad_input(caller + ": vertex " + std::to_string(ids[k]) + ": " + e.what());
    }
    const Limit_masks& lm = *found;
    if(!walk.read(walk_start(v), false, lm.rings + 1, lm.neighbourhood_size) || walk.transcript != lm.connectivity) {
      pending.push_back(k);
      continue;
    }
    for(std::size_t i = 0; i < lm.limit.size(); ++i)
      if(lm.limit[i] != 0)
        rows.position[k].add(ordinal(i), convert_weight<FT>(lm.limit[i]));
    for(int a = 0; a < 2; ++a) { // sum w_i (p_i - p_0): the centre gets minus the sum of the others
      FT centre(0);
      for(std::size_t i = 1; i < lm.tangent[a].size(); ++i)
        centre -= convert_weight<FT>(lm.tangent[a][i]);
      rows.tangent[a][k].add(ordinal(0), centre);
      for(std::size_t i = 1; i < lm.tangent[a].size(); ++i)
        if(lm.tangent[a][i] != 0)
          rows.tangent[a][k].add(ordinal(i), convert_weight<FT>(lm.tangent[a][i]));
    }
    rows.has_tangents[k] = lm.tangents ? 1 : 0;
  }
  if(pending.empty())
    return rows;
  if(depth >= max_extra_levels + (Host::analysis_steps == 2 ? 1 : 0))
    throw Bad_input(caller + ": vertex " + std::to_string(ids[pending.front()]) +
                    ": its neighbourhood does not become the analysed one after " + std::to_string(depth) +
                    " more levels");

  // one more level, on a copy that keeps the order of the elements (the
  // sqrt3 hosts read the border phase from it): its stencils over this
  // level's vertices; a primal host numbers the old vertices first, so the
  // descendant of vertex j is vertex j
  Mesh finer = mesh;
  Composed_level<FT> level{nullptr, num_vertices(mesh)};
  const auto finer_points = get(CGAL::vertex_point, finer);
  refine_level(finer, mask, No_points<decltype(finer_points)>{finer_points}, Parallel_loop(1), level);
  std::vector<std::size_t> descendants, descendant_ids;
  for(const std::size_t k : pending) {
    descendants.push_back(targets[k]);
    descendant_ids.push_back(ids[k]);
  }
  Limit_rows<FT> finer_rows =
    limit_rows(masks, mask, finer, descendants, descendant_ids, max_extra_levels, depth + 1, caller);
  Row_builder<FT> builder;
  for(std::size_t p = 0; p < pending.size(); ++p) {
    compose_with(finer_rows.position[p], level.table, builder);
    rows.position[pending[p]] = std::move(finer_rows.position[p]);
    for(int a = 0; a < 2; ++a) {
      compose_with(finer_rows.tangent[a][p], level.table, builder);
      rows.tangent[a][pending[p]] = std::move(finer_rows.tangent[a][p]);
    }
    rows.has_tangents[pending[p]] = finer_rows.has_tangents[p];
  }
  return rows;
}

/*
 * Dual schemes (Doo-Sabin): the limit point of a vertex v is the limit of
 * the face that the next step makes of the corners at v (the vertex face).
 * Interior v of valence n: that face is an n-gon, and its limit is the
 * centroid of its corners (the limit mask of the analysis centred at an
 * n-gon, checked to be exactly that): (1/n) sum of the corner_node stencils
 * of the corners at v. Border v: the border corners of the new faces at v
 * (the corners of the first and last face around v, on the new border,
 * joined by a border edge) are Chaikin points of the two border edges at v;
 * the vertex face (k >= 3 faces) or the edge quad (k = 2) has that border
 * edge, whose two ends are refined by Chaikin's rule on it alone and
 * converge to its midpoint: the limit is the midpoint of the two border
 * corners, 3/4 v + 1/8 (u + w) for the border neighbours u, w (the quadratic
 * B-spline of the border polygon at v); a corner with a single face is kept
 * (the limit is v). That is the limit mask of the analysis at the border face
 * made from v, checked to be exactly that. Tangent rows: none (face normals;
 * the analysis' tangent masks are over the corners of the next level).
 */
template <class Masks, class Mask, class Mesh>
Limit_rows<typename Mask::Number_type> dual_limit_rows(const Masks& masks, const Mask& mask, const Mesh& mesh,
                                                       const std::string& caller)
{
  using FT = typename Mask::Number_type;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  const Mesh_numbering<Mesh> number(mesh);
  Limit_rows<FT> rows(num_vertices(mesh));
  for(std::size_t k = 0; k < num_vertices(mesh); ++k) {
    std::vector<halfedge_descriptor> corners, border_corners;
    bool border = false;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(number.vertex(k), mesh)) {
      if(CGAL::is_border(h, mesh)) {
        border = true;
        continue;
      }
      corners.push_back(h);
      if(CGAL::is_border(opposite(h, mesh), mesh) || CGAL::is_border(opposite(next(h, mesh), mesh), mesh))
        border_corners.push_back(h);
    }
    const int n = static_cast<int>(corners.size());
    if(border && (border_corners.size() > 2 || border_corners.empty()))
      throw Bad_input(caller + ": vertex " + std::to_string(k) + " has " + std::to_string(border_corners.size()) +
                      " faces with a border edge at it");
    try {
      masks(n, border); // checks that the analysis' limit is the centroid, or the border midpoint
    } catch(const Bad_input& e) {
      throw Bad_input(caller + ": vertex " + std::to_string(k) + ": " + e.what());
    }
    const std::vector<halfedge_descriptor>& used = border ? border_corners : corners;
    const FT share = FT(1) / FT(static_cast<int>(used.size()));
    for(halfedge_descriptor h : used) { // the mean of the corners' rows
      Stencil<std::uint32_t, FT> corner;
      Numbered_report<Mesh_numbering<Mesh>, Stencil<std::uint32_t, FT>> acc{number, corner};
      mask.corner_node(Corner_view<Mesh>(mesh, h), acc);
      for(const auto& term : corner)
        rows.position[k].add(term.first, share * term.second);
    }
  }
  return rows;
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_LIMIT_ROWS_H
