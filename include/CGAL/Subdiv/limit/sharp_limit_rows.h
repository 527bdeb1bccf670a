// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_SHARP_LIMIT_ROWS_H
#define CGAL_SUBDIV_LIMIT_SHARP_LIMIT_ROWS_H

/// \file sharp_limit_rows.h
/// The limit rows of the corners and creases of a tagged mesh, as OpenSubdiv's
/// `PrimvarRefiner::Limit` takes them: the crease limit and tangent weights
/// from the curve rule along the crease (read off its local matrix by the
/// curve analysis), and the tangent across a crease. The other vertices get
/// the analysis' rows (`limit_rows.h`).

#include <CGAL/Subdiv/analysis/Limit_masks.h>
#include <CGAL/Subdiv/analysis/curve_local_matrix.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/limit/limit_rows.h>
#include <CGAL/Subdiv/masks/Border_curve_rule.h>
#include <CGAL/Subdiv/stencils/Stencil.h>
#include <CGAL/Subdiv/views/Sharp_level.h>
#include <CGAL/Subdiv/views/Vertex_view.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

// the curve rule of the creases as a curve scheme (its two masks), for the curve analysis
template <class FT>
struct Crease_curve_scheme
{
  using Number_type = FT;
  const Border_curve_rule<FT>& rule;
  std::string name() const { return "the crease rule"; }
  template <class Accumulator>
  void even_mask(Accumulator& acc) const
  {
    for(const auto& term : rule.even())
      acc.add(term.first, term.second);
  }
  template <class Accumulator>
  void odd_mask(Accumulator& acc) const
  {
    for(const auto& term : rule.odd())
      acc.add(term.first, term.second);
  }
};

/*
 * The limit of a crease vertex under a binary curve rule along its two
 * sharp edges (Loop, Catmull-Clark, the butterflies), over (one crease
 * neighbour, the vertex, the other): the left fixed vector of the curve's
 * local matrix (the cubic B-spline's 1/6, 2/3, 1/6); an interpolating rule
 * (the four-point) keeps the vertex: 0, 1, 0.
 */
template <class FT>
std::vector<FT> crease_limit_weights(const Border_curve_rule<FT>& curve)
{
  if(curve.even().size() == 1 && curve.even()[0].first == 0 && curve.even()[0].second == FT(1))
    return {FT(0), FT(1), FT(0)};
  const Crease_curve_scheme<FT> scheme{curve};
  const std::pair<int, int> window = invariant_window(scheme);
  std::vector<FT> crease = normalised_left_fixed_vector(local_subdivision_matrix(scheme));
  CGAL_assertion(window.first == -1 && window.second == 1 && crease.size() == 3); // a primal scheme's crease
  (void)window;
  return crease;
}

/*
 * The tangent along a crease under a binary curve rule along its two sharp
 * edges (Loop, Catmull-Clark), over (one crease neighbour, the vertex, the
 * other): the left eigenvector for 1/2 of the curve's local matrix,
 * normalised to pair to 1 with the offsets (-1, 0, 1), i.e. the derivative
 * in the curve's own parameter (the cubic B-spline's -1/2, 0, 1/2: half the
 * difference of the two neighbours). Empty for an interpolating rule (the
 * four-point, whose window is wider than the two neighbours) and where 1/2 is
 * not a simple eigenvalue: then the crease has no tangent rows.
 */
template <class FT>
std::vector<FT> crease_tangent_weights(const Border_curve_rule<FT>& curve)
{
  const Crease_curve_scheme<FT> scheme{curve};
  const std::pair<int, int> window = invariant_window(scheme);
  if(window.first != -1 || window.second != 1)
    return {};
  return normalised_left_eigenvector<FT>(local_subdivision_matrix(scheme), FT(1) / FT(2),
                                         std::vector<FT>{FT(-1), FT(0), FT(1)});
}

/*
 * The limit of a crease vertex of the sqrt3 schemes, whose crease rule is
 * their border rule (a ternary rule applied on every second step): the
 * limit mask of the border analysis (`border`, over a resting and a
 * refining step), which reads the border polyline alone (Kobbelt's ternary
 * cubic B-spline: 1/6, 2/3, 1/6 over the two border neighbours and the
 * vertex; the interpolating four-point rule: the vertex), so that a crease
 * vertex's limit is, by construction, the border limit of the same
 * polyline. The limit is a fixed vector of the curve rule, so it is the
 * same on a resting and a refining step (the phase does not matter).
 * \throws Bad_input if the mask reads more than the vertex and two
 * neighbours of equal weight (a symmetric curve rule on the border)
 */
template <class FT>
std::vector<FT> crease_limit_weights(const Limit_masks& border)
{
  std::vector<FT> crease{FT(0), convert_weight<FT>(border.limit[0]), FT(0)};
  std::vector<std::size_t> others;
  for(std::size_t i = 1; i < border.limit.size(); ++i)
    if(border.limit[i] != 0)
      others.push_back(i);
  if(!others.empty()) {
    if(others.size() != 2 || border.limit[others[0]] != border.limit[others[1]])
      throw Bad_input("the border limit mask of " + border.scheme +
                      " is not a symmetric mask over the vertex and its two border neighbours");
    crease[0] = crease[2] = convert_weight<FT>(border.limit[others[0]]);
  }
  return crease;
}

/// which tangent rows the corners and creases get (`sharp_limit_rows`)
enum class Sharp_tangents {
  none,         ///< none: their normals are the faces' (the butterflies)
  loop,         ///< Loop's crease tangents (`crease_cross_tangent`)
  catmull_clark ///< Catmull-Clark's crease tangents
};

/*
 * The halfedges out of the vertex of `v` in the order of OpenSubdiv Far's
 * vertex edges (Vtr's ordering of the faces and edges of a vertex): from the
 * leading edge (the halfedge out of the vertex) of Far's first face at the
 * vertex, counter-clockwise, each next one opposite(prev(h)), the edge that
 * face shares with the next. Far's first face: at a border vertex, the face
 * after the border (that of opposite(border_in())), the list ending with
 * border_out(); inside, the face of the vertex with the smallest ordinal (Far
 * lists the faces of a vertex in the order of the mesh's faces and starts
 * from the first). Empty for a vertex in no face.
 */
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor> far_edge_order(const Vertex_view<Mesh>& v,
                                                                                    const Mesh_numbering<Mesh>& number)
{
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  const Mesh& mesh = v.mesh();
  std::vector<halfedge_descriptor> out;
  if(halfedge(v.vertex(), mesh) == boost::graph_traits<Mesh>::null_halfedge())
    return out;
  halfedge_descriptor first = boost::graph_traits<Mesh>::null_halfedge();
  if(v.on_border())
    first = opposite(v.border_in(), mesh);
  else
    for(halfedge_descriptor h : CGAL::halfedges_around_source(v.vertex(), mesh))
      if(!CGAL::is_border(h, mesh) &&
         (first == boost::graph_traits<Mesh>::null_halfedge() || number(face(h, mesh)) < number(face(first, mesh))))
        first = h;
  if(first == boost::graph_traits<Mesh>::null_halfedge() || CGAL::is_border(first, mesh))
    return out;
  halfedge_descriptor h = first;
  do {
    out.push_back(h);
    if(CGAL::is_border(h, mesh))
      break; // border_out(): the last edge
    h = opposite(prev(h, mesh), mesh);
  } while(h != first);
  return out;
}

/*
 * The tangent across a crease at a vertex v, into the faces between two of
 * its halfedges out, out[e0] and out[e1] (e0 < e1, `out` in Far's order:
 * `far_edge_order`, so these are the faces counter-clockwise from the first
 * to the second), as a row over ordinals summing to 0: OpenSubdiv Sdc's
 * crease limit tangent masks (`assignCreaseLimitTangentMasks` in
 * sdc/loopScheme.h and sdc/catmarkScheme.h), each case up to a positive
 * factor (the normal does not depend on it). With k = e1 - e0 faces in the
 * span, c0 and c1 the other ends of out[e0] and out[e1], m_i that of
 * out[e0 + i] (0 < i < k), d_i the corner two after v in the face of
 * out[e0 + i] (0 <= i < k; the diagonal of a quad):
 * - Loop: k = 1: (c0 + c1)/2 - v; k = 2: m_1 - v; k = 3: m_1 + m_2 - v -
 *   (c0 + c1)/2 (Far's divided by 6, 3, sqrt 3); k >= 4, theta = pi/k:
 *   2 (1 - cos theta) sum_i sin(i theta) m_i - sin(theta) (c0 + c1) (Far's
 *   divided by 3).
 * - Catmull-Clark: k = 1: (c0 + c1)/2 - v (Far's divided by 6); k = 2, the
 *   cubic B-spline's cross derivative: (4 m_1 + d_0 + d_1 - c0 - c1 - 4 v)/6;
 *   k >= 3 (Biermann et al., as Far), theta = pi/k, R = (1 + cos theta) /
 *   sin theta: [sum_i 4 sin(i theta) m_i + sum_i (sin(i theta) + sin((i + 1)
 *   theta)) d_i - R (1 + 2 cos theta) (c0 + c1) + 4 R (cos theta - 1) v] /
 *   (k (3 + cos theta)).
 * Transcendental weights are computed in double and converted to FT; the
 * weight of v is minus the sum of the others, so that the row sums to 0.
 * Far takes the faces as quads: on other faces d_i is still the corner two
 * after v (not the limit tangent there; refine once first).
 */
template <class FT, class Mesh>
Stencil<std::uint32_t, FT> crease_cross_tangent(
  Sharp_tangents rule, const std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor>& out, int e0, int e1,
  const Mesh& mesh, const Mesh_numbering<Mesh>& number)
{
  CGAL_precondition(rule != Sharp_tangents::none && 0 <= e0 && e0 < e1 && e1 < static_cast<int>(out.size()));
  const int k = e1 - e0;
  const auto end_of = [&](int i) { return static_cast<std::uint32_t>(number(target(out[e0 + i], mesh))); };
  const auto diagonal_of = [&](int i) {
    return static_cast<std::uint32_t>(number(target(next(out[e0 + i], mesh), mesh)));
  };
  std::vector<std::pair<std::uint32_t, FT>> terms; // all but v
  const auto ends = [&](const FT& w) {
    terms.emplace_back(end_of(0), w);
    terms.emplace_back(end_of(k), w);
  };
  const double pi = 3.14159265358979323846;
  const double theta = pi / k;
  if(rule == Sharp_tangents::loop) {
    if(k == 1)
      ends(FT(1) / FT(2));
    else if(k == 2)
      terms.emplace_back(end_of(1), FT(1));
    else if(k == 3) {
      ends(FT(-1) / FT(2));
      terms.emplace_back(end_of(1), FT(1));
      terms.emplace_back(end_of(2), FT(1));
    } else {
      ends(convert_weight<FT>(-std::sin(theta)));
      for(int i = 1; i < k; ++i)
        terms.emplace_back(end_of(i), convert_weight<FT>(2 * (1 - std::cos(theta)) * std::sin(i * theta)));
    }
  } else if(k == 1)
    ends(FT(1) / FT(2));
  else if(k == 2) {
    ends(FT(-1) / FT(6));
    terms.emplace_back(end_of(1), FT(4) / FT(6));
    terms.emplace_back(diagonal_of(0), FT(1) / FT(6));
    terms.emplace_back(diagonal_of(1), FT(1) / FT(6));
  } else {
    const double c = std::cos(theta), s = std::sin(theta);
    const double denominator = k * (3 + c), R = (1 + c) / s;
    ends(convert_weight<FT>(-R * (1 + 2 * c) / denominator));
    for(int i = 1; i < k; ++i)
      terms.emplace_back(end_of(i), convert_weight<FT>(4 * std::sin(i * theta) / denominator));
    for(int i = 0; i < k; ++i)
      terms.emplace_back(diagonal_of(i),
                         convert_weight<FT>((std::sin(i * theta) + std::sin((i + 1) * theta)) / denominator));
  }
  Stencil<std::uint32_t, FT> row;
  FT centre(0);
  for(const auto& term : terms) {
    row.add(term.first, term.second);
    centre -= term.second;
  }
  row.add(static_cast<std::uint32_t>(number(target(opposite(out[e0], mesh), mesh))), centre);
  return row;
}

/*
 * The tangent rows (row `k` of `rows`) of a corner, the vertex of ordinal
 * `self` whose edges in Far's order are `out` (`far_edge_order`): along the
 * two edges of Far's first face, the ends of out[0] and out[1] minus the
 * vertex (Far's corner tangent masks, up to a factor), so t0 x t1 is on the
 * side from which the faces are counter-clockwise. None for a vertex with
 * fewer than two edges.
 */
template <class FT, class Mesh>
void corner_tangent_rows(Limit_rows<FT>& rows, std::size_t k, std::uint32_t self,
                         const std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor>& out,
                         const Mesh& mesh, const Mesh_numbering<Mesh>& number)
{
  if(out.size() < 2)
    return;
  for(int a = 0; a < 2; ++a) {
    rows.tangent[a][k].add(static_cast<std::uint32_t>(number(target(out[a], mesh))), FT(1));
    rows.tangent[a][k].add(self, FT(-1));
  }
  rows.has_tangents[k] = 1;
}

/*
 * The limit rows under the sharpness tags of the mesh's level (`level`), as
 * OpenSubdiv's `PrimvarRefiner::Limit` takes them, by the rule of each
 * vertex on this level: a corner's limit is the vertex itself; a crease's is
 * the limit of the curve rule along its two sharp edges, `crease` over (the
 * target of crease_out(0), the vertex, the target of crease_out(1))
 * (`crease_limit_weights`). Tangent rows (with `tangents` not `none`), in
 * the order of Far's vertex edges out[0], out[1], ... (`far_edge_order`):
 * - a crease, with e0 < e1 the indices of its two sharp edges in `out`: the
 *   first tangent is along the crease towards out[e0], `along` over (the end
 *   of out[e1], the vertex, the end of out[e0]) (`crease_tangent_weights`:
 *   half their difference); the second is across it, into the faces from
 *   out[e0] to out[e1] (`crease_cross_tangent`). Inside the mesh a crease
 *   has a tangent plane per side: this is Far's choice, the side of the
 *   sector starting at the first sharp edge counter-clockwise from the
 *   leading edge of Far's first face (that face's side if its leading edge
 *   is sharp, the other side otherwise). On the border, the faces' side.
 * - a corner: along the two edges of Far's first face, the ends of out[0]
 *   and out[1] minus the vertex (Far's corner tangent masks, up to a factor).
 * Both give t0 x t1 on the side from which the faces are counter-clockwise.
 * A crease with an interpolating rule (no `along`) and a vertex in no face
 * have no tangent rows (the normal there is the faces'). Fills those rows
 * of `rows` and returns the other vertices (ordinals), whose rows are the
 * analysis': the children of a smooth vertex's ring follow smooth rules
 * only, whatever the tags around it; a dart gets the smooth masks, as in
 * OpenSubdiv.
 */
template <class FT, class Mesh>
std::vector<std::size_t> sharp_limit_rows(Limit_rows<FT>& rows, const Mesh& mesh, const Sharp_level<Mesh, FT>& level,
                                          const std::vector<FT>& crease, const std::vector<FT>& along,
                                          Sharp_tangents tangents)
{
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  const bool interpolating = crease[0] == FT(0) && crease[2] == FT(0);
  const Mesh_numbering<Mesh> number(mesh);
  std::vector<std::size_t> smooth;
  for(std::size_t k = 0; k < rows.position.size(); ++k) {
    const Vertex_view<Mesh> v = level.vertex_view(number.vertex(k));
    if(v.rule() != Vertex_rule::corner && v.rule() != Vertex_rule::crease) {
      smooth.push_back(k);
      continue;
    }
    const auto self = static_cast<std::uint32_t>(k);
    if(v.rule() == Vertex_rule::corner || interpolating) {
      rows.position[k].add(self, FT(1));
    } else {
      rows.position[k].add(static_cast<std::uint32_t>(number(target(v.crease_out(0), mesh))), crease[0]);
      rows.position[k].add(self, crease[1]);
      rows.position[k].add(static_cast<std::uint32_t>(number(target(v.crease_out(1), mesh))), crease[2]);
    }
    if(tangents == Sharp_tangents::none)
      continue;
    const std::vector<halfedge_descriptor> out = far_edge_order(v, number);
    const auto end_of = [&](halfedge_descriptor h) { return static_cast<std::uint32_t>(number(target(h, mesh))); };
    if(v.rule() == Vertex_rule::corner) {
      corner_tangent_rows(rows, k, self, out, mesh, number);
      continue;
    }
    if(along.size() != 3)
      continue;
    int e[2] = {-1, -1};
    for(int i = 0; i < static_cast<int>(out.size()); ++i)
      for(int c = 0; c < 2; ++c)
        if(out[i] == v.crease_out(c))
          e[c] = i;
    if(e[0] < 0 || e[1] < 0 || e[0] == e[1])
      continue;
    if(e[0] > e[1])
      std::swap(e[0], e[1]);
    const std::uint32_t sources[3] = {end_of(out[e[1]]), self, end_of(out[e[0]])};
    for(int i = 0; i < 3; ++i)
      if(along[i] != FT(0))
        rows.tangent[0][k].add(sources[i], along[i]);
    rows.tangent[1][k] = crease_cross_tangent<FT>(tangents, out, e[0], e[1], mesh, number);
    rows.has_tangents[k] = 1;
  }
  return smooth;
}

/*
 * Without tags, a border vertex of one face that the mask keeps
 * (`Border_corners::sharp`) is a corner all the same (OpenSubdiv's "edges
 * and corners"), but the analysis finds no tangent plane there: such a
 * vertex among `vertices` (ordinals; row p of `rows` is vertices[p]'s)
 * without tangent rows gets a corner's (`corner_tangent_rows`), so that its
 * normal is the limit of the normals around it, not the faces' average.
 */
template <class FT, class Mesh>
void kept_corner_tangent_rows(Limit_rows<FT>& rows, const std::vector<std::size_t>& vertices, const Mesh& mesh)
{
  const Mesh_numbering<Mesh> number(mesh);
  for(std::size_t p = 0; p < vertices.size(); ++p) {
    if(rows.has_tangents[p])
      continue;
    const Vertex_view<Mesh> v(mesh, number.vertex(vertices[p]), Border_corners::sharp);
    if(v.rule() == Vertex_rule::corner)
      corner_tangent_rows(rows, p, static_cast<std::uint32_t>(vertices[p]), far_edge_order(v, number), mesh, number);
  }
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_SHARP_LIMIT_ROWS_H
