// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_REFINEMENT_SEAM_FREE_CORNERS_H
#define CGAL_SUBDIV_REFINEMENT_SEAM_FREE_CORNERS_H

/// \file Seam_free_corners.h
/// Corner maps carried by the schemes that make new faces across the old
/// edges (Doo-Sabin's edge faces, sqrt3's flipped edges): such a face would
/// straddle a seam, so these schemes carry a corner map only when it has
/// none. A corner map without seams is a vertex map, and is carried as one:
/// with the scheme's mask (the smooth modes) or with the linear rules of the
/// split (`Face_varying_interpolation::all`) below. doc/provenance.md,
/// "Face-varying data".

#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/masks/Linear_quad_mask.h>
#include <CGAL/Subdiv/masks/Sharp_rules.h>
#include <CGAL/Subdiv/refinement/Face_varying.h>
#include <CGAL/Subdiv/refinement/refine_level.h>
#include <CGAL/Subdiv/views/Split.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/// two corners at one vertex, in two faces across an edge, that hold
/// different values (by ordinal in the mesh's iteration order)
struct Corner_seam
{
  std::size_t vertex;
  std::size_t face;
  std::size_t other_face;
  /// the other end of the edge between the two faces
  std::size_t across;
};

/// the first seam of the corner values that `same(h, g)` compares (h and g
/// halfedges with a face, into their vertex), vertex after vertex; none if
/// every vertex has one value
template <class Mesh, class Same>
std::optional<Corner_seam> first_seam(const Mesh& mesh, const Same& same)
{
  using GT = boost::graph_traits<Mesh>;
  const Mesh_numbering<Mesh> number(mesh);
  for(const auto v : vertices(mesh)) {
    if(halfedge(v, mesh) == GT::null_halfedge())
      continue;
    // the corners around v are joined by its edges: one value if the two
    // corners across every edge agree
    for(const auto h : CGAL::halfedges_around_target(v, mesh)) {
      const auto o = opposite(h, mesh);
      if(!CGAL::is_border(h, mesh) && !CGAL::is_border(o, mesh) && !same(h, prev(o, mesh)))
        return Corner_seam{number(v), number(face(h, mesh)), number(face(o, mesh)), number(source(h, mesh))};
    }
  }
  return std::nullopt;
}

/// "vertex 12 has different values in faces 3 and 5 (across its edge to vertex 7)"
inline std::string describe(const Corner_seam& seam)
{
  return (Message() << "vertex " << seam.vertex << " has different values in faces " << seam.face << " and "
                    << seam.other_face << " (across its edge to vertex " << seam.across << ")")
    .str();
}

/// throws `Bad_input`, naming `scheme` and the first seam, if the corner
/// values that `same` compares have one
template <class Mesh, class Same>
void refuse_seams(const Mesh& mesh, const Same& same, const std::string& scheme)
{
  if(const std::optional<Corner_seam> seam = first_seam(mesh, same))
    refuse(Message() << "Carried_data: " << scheme
                     << " carries corner maps without seams only (it makes new faces across the old edges, which "
                        "would straddle a seam): "
                     << describe(*seam) << "; Loop, Catmull-Clark, linear and the butterflies carry seams");
}

/*
 * The linear rules of the dual split (Doo-Sabin), for corner maps in
 * `Face_varying_interpolation::all` and vertex maps with
 * `Interpolation::linear`: the new vertex of a corner takes the centre of the
 * corner's quad in the linear quad split of its face, the mean of the four
 * points of that split around it (`Linear_quad_mask`'s: the corner, the
 * midpoints of its two edges, the face point). On a quad these are Doo-Sabin's
 * own weights 9/16, 3/16, 3/16, 1/16 (the bilinear interpolation at (1/4,
 * 1/4) from the corner). Corners that the creases of a tagged level make one
 * new vertex are given one value: a corner vertex keeps its own, the corners
 * beside a crease edge take the centre of their quads' side along it.
 */
template <class Mesh, class FT>
class Linear_dual_rules
{
public:
  template <class Accumulator>
  void corner_node(const Corner_view<Mesh>& corner, Accumulator& acc) const
  {
    const Mesh& mesh = corner.mesh();
    const auto h = corner.halfedge();
    const bool kept_vertex = corner.kept() && !(corner.border_before() && corner.border_after());
    const bool crease_before = corner.sharp_before() && !corner.border_before();
    const bool crease_after = corner.sharp_after() && !corner.border_after();
    if(kept_vertex)
      return m_linear.vertex_node(Vertex_view<Mesh>(mesh, target(h, mesh)), acc);
    Scaled_accumulator<Accumulator, FT> half(acc, FT(1) / FT(2));
    if(crease_before || crease_after) {
      m_linear.vertex_node(Vertex_view<Mesh>(mesh, target(h, mesh)), half);
      m_linear.edge_node(Edge_view<Mesh>(mesh, crease_before ? h : next(h, mesh)), half);
      return;
    }
    Scaled_accumulator<Accumulator, FT> quarter(acc, FT(1) / FT(4));
    m_linear.vertex_node(Vertex_view<Mesh>(mesh, target(h, mesh)), quarter);
    m_linear.edge_node(Edge_view<Mesh>(mesh, h), quarter);
    m_linear.edge_node(Edge_view<Mesh>(mesh, next(h, mesh)), quarter);
    m_linear.face_node(Face_view<Mesh>(mesh, face(h, mesh)), quarter);
  }

private:
  Linear_quad_mask<Mesh, FT> m_linear;
};

/*
 * The linear rules of the sqrt3 split (both sqrt3 schemes), as
 * `Linear_dual_rules` are Doo-Sabin's: an old vertex keeps its value, a face
 * point takes the mean of the face's corners (`Linear_quad_mask`'s rules), and
 * on the steps that trisect the border and the creases, the new vertex at
 * k/3 along an edge takes the linear interpolation there: a third of the
 * nearer end and two thirds of the midpoint (the one rule that the linear
 * masks have no counterpart of, the primal splits halving edges).
 */
template <class Mesh, class FT>
class Linear_sqrt3_rules : private Linear_quad_mask<Mesh, FT>
{
  using Linear = Linear_quad_mask<Mesh, FT>;

public:
  using Linear::face_node;
  using Linear::vertex_node;
  // a border vertex keeps its value too, on both kinds of steps
  template <class Accumulator>
  void border_vertex_node(const Vertex_view<Mesh>& v, Accumulator& acc) const
  {
    vertex_node(v, acc);
  }
  template <class Accumulator>
  void resting_border_vertex_node(const Vertex_view<Mesh>& v, Accumulator& acc) const
  {
    vertex_node(v, acc);
  }
  /// the new vertex at k/3 (k = 1, 2) of the way along `e.halfedge()`
  template <class Accumulator>
  void border_edge_node(const Edge_view<Mesh>& e, int k, Accumulator& acc) const
  {
    const Mesh& mesh = e.mesh();
    const auto h = e.halfedge();
    Scaled_accumulator<Accumulator, FT> third(acc, FT(1) / FT(3)), two_thirds(acc, FT(2) / FT(3));
    vertex_node(Vertex_view<Mesh>(mesh, k == 1 ? source(h, mesh) : target(h, mesh)), third);
    Linear::edge_node(Edge_view<Mesh>(mesh, h), two_thirds);
  }
};

/// the linear rules of the split of `Mask`, a scheme that makes new faces
/// across the old edges
template <class Mesh, class FT, class Mask>
auto linear_rules_across_edges(const Mask&)
{
  static_assert(Mask::split == Split::dual || Mask::split == Split::sqrt3, "a split that makes faces across edges");
  if constexpr(Mask::split == Split::dual)
    return Linear_dual_rules<Mesh, FT>();
  else
    return Linear_sqrt3_rules<Mesh, FT>();
}

/*
 * One level of a channel of corner maps without seams (checked before the
 * first level, `refuse_seams`) carried by a scheme that makes new faces across
 * the old edges: each map is a vertex map, and the new value of a vertex is
 * the combination of the old values that the mask gives its point (the
 * smooth modes, as `Carried_data::vertex_map` carries one), or that the
 * linear rules of the split give it (`all`). Every corner of a new face takes
 * the value of its vertex, so the new maps have no seam either. The rows go
 * to the maps over the cut vertices of the level's topology (one a vertex,
 * there being no seam), row j being new vertex j's: an index map gets the
 * new vertex as the index of its value.
 */
template <class Mesh, class FT>
class Seam_free_corners
{
public:
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  /// puts the value of each corner (a halfedge into its vertex) given its row
  using Corner_writer = std::function<void(const std::vector<halfedge_descriptor>&, const std::vector<std::size_t>&)>;

  /// a map of the channel: `add_row` takes the rows in order (none for an
  /// index map), `write` writes the new corners
  void add_map(Face_varying_row_visitor<FT> add_row, Corner_writer write)
  {
    if(add_row)
      m_add_rows.push_back(std::move(add_row));
    m_writers.push_back(std::move(write));
  }

  /// the rows of the level of `host` (made by `mask`) in `mode`
  template <class Host, class Mask>
  void read(const Face_varying_topology<Mesh>& topology, const Host& host, const Mask& mask,
            Face_varying_interpolation mode)
  {
    Stencil_recorder<Mesh, FT> stencils;
    if(mode == Face_varying_interpolation::all)
      stencils.read(host, linear_rules_across_edges<Mesh, FT>(mask), Parallel_loop(1));
    else
      stencils.read(host, mask, Parallel_loop(1));
    const std::vector<typename Face_varying_cut_mesh::Vertex_index> value_of = value_of_vertex(topology);
    const Mesh_numbering<Mesh>& number = topology.numbering();
    Face_varying_row<FT> row;
    for(const auto& stencil : stencils.rows) {
      row.clear();
      for(const auto& [v, weight] : stencil)
        row.add(value_of[number(v)], weight);
      for(const auto& add_row : m_add_rows)
        add_row(row);
    }
  }

  /// every corner of every new face of `level` takes the row of its vertex
  template <class New_level>
  void write(const New_level& level) const
  {
    std::vector<halfedge_descriptor> halfedges;
    std::vector<std::size_t> rows;
    const auto& record = level.faces();
    for(std::size_t b = 0; b < record.number_of_blocks(); ++b)
      record.for_each_face_in_block(b, [&](std::size_t, const auto* corners, std::size_t size, std::size_t) {
        // corner i of a new face is the target of the halfedge from corner i - 1
        for(std::size_t i = 0; i < size; ++i) {
          halfedges.push_back(level.halfedge(corners[(i + size - 1) % size].halfedge));
          rows.push_back(corners[i].vertex);
        }
      });
    for(const Corner_writer& write : m_writers)
      write(halfedges, rows);
  }

private:
  // the one value (cut vertex) of every vertex of the mesh, by ordinal
  static std::vector<typename Face_varying_cut_mesh::Vertex_index> value_of_vertex(
    const Face_varying_topology<Mesh>& topology)
  {
    std::vector<typename Face_varying_cut_mesh::Vertex_index> result(num_vertices(topology.mesh()));
    for(const auto v : topology.cut().vertices())
      result[topology.vertex_of(v)] = v;
    return result;
  }

  std::vector<Face_varying_row_visitor<FT>> m_add_rows;
  std::vector<Corner_writer> m_writers;
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_REFINEMENT_SEAM_FREE_CORNERS_H
