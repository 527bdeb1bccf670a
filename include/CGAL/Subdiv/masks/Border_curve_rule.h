// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_BORDER_CURVE_RULE_H
#define CGAL_SUBDIV_MASKS_BORDER_CURVE_RULE_H

#include <CGAL/Subdiv/views/Vertex_view.h>

#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivMasks
 * The rules of a binary curve scheme (`Uniform_bspline_scheme`,
 * `Chaikin_scheme`, `Four_point_scheme`, ...) applied along the border
 * polygon of a surface mesh: how the surface masks refine their borders, so
 * that every border loop of the refined mesh is one step of the curve scheme
 * on the old loop and the curve weights are written once, in `curves/`.
 *
 * The curve masks are read once, at construction; offset k of a mask is the
 * border vertex k steps along the border from the point the rule is centred
 * at. Terms are reported in this order: for a vertex point the vertex itself
 * first, then the others by increasing offset; for the points on an edge, by
 * increasing offset along the halfedge given.
 *
 * \tparam FT the number type of the weights
 */
template <class FT>
class Border_curve_rule
{
public:
  /// reads the even and odd masks of `scheme` (a model of `CurveSubdivisionScheme`)
  template <class CurveScheme>
  explicit Border_curve_rule(const CurveScheme& scheme)
  {
    Sorted_terms even, odd;
    scheme.even_mask(even);
    scheme.odd_mask(odd);
    m_even = std::move(even.terms);
    m_odd = std::move(odd.terms);
  }

  /// the new position of the border vertex `v` (a primal scheme's even rule
  /// centred at it)
  template <class Mesh, class Accumulator>
  void vertex_point(const Vertex_view<Mesh>& v, Accumulator& acc) const
  {
    const auto along = v.border_out(); // from v to its next border neighbour
    for(const auto& term : m_even)
      if(term.first == 0)
        acc.add(v.vertex(), term.second);
    for(const auto& term : m_even)
      if(term.first != 0)
        acc.add(border_vertex(v.mesh(), along, term.first), term.second);
  }

  /// the new vertex on the border edge of `g` (a primal scheme's odd rule,
  /// offset 0 at source(g), 1 at target(g)); `g` is either halfedge of the edge
  template <class Mesh, class Accumulator>
  void edge_point(const Mesh& mesh, typename boost::graph_traits<Mesh>::halfedge_descriptor g, Accumulator& acc) const
  {
    add_along(m_odd, mesh, g, acc);
  }

  /// the new vertex of a dual scheme on the border edge of `g` next to
  /// source(g) (the even rule, offset 0 at source(g), 1 at target(g)); also
  /// on a crease edge (Doo-Sabin's creases), whose even rule (Chaikin's)
  /// reaches its two ends only
  template <class Mesh, class Accumulator>
  void dual_point(const Mesh& mesh, typename boost::graph_traits<Mesh>::halfedge_descriptor g, Accumulator& acc) const
  {
    add_along(m_even, mesh, g, acc);
  }

  /// the new vertex on the edge (a, b) of a polyline of the mesh that is not
  /// its border (a crease): the odd rule, offset 0 at a and 1 at b; `before`
  /// is the polyline's vertex before a and `after` the one after b, or
  /// `none` where the polyline ends at a or b: it is then continued by point
  /// reflection (2a - b before a, 2b - a after b), as `End_rule::keep_ends`
  /// continues an open curve. The rule must reach no further than one
  /// vertex beyond each end (offsets -1 to 2: the four-point rule).
  template <class Vertex, class Accumulator>
  void polyline_edge_point(Vertex before, Vertex a, Vertex b, Vertex after, Vertex none, Accumulator& acc) const
  {
    for(const auto& term : m_odd)
      add_polyline_vertex(term.first, term.second, before, a, b, after, none, acc);
  }

  /// adds `w` times the vertex at `offset` (-1 to 2) along the polyline
  /// (`before`, a, b, `after`) of `polyline_edge_point`, continued by point
  /// reflection where `before` or `after` is `none`: the one place of that
  /// end rule (the sqrt3 schemes' ternary border rules use it too)
  template <class Vertex, class Accumulator>
  static void add_polyline_vertex(int offset, const FT& w, Vertex before, Vertex a, Vertex b, Vertex after, Vertex none,
                                  Accumulator& acc)
  {
    CGAL_precondition(offset >= -1 && offset <= 2);
    if(offset == 0 || offset == 1) {
      acc.add(offset == 0 ? a : b, w);
      return;
    }
    const Vertex beyond = offset < 0 ? before : after;
    if(beyond != none) {
      acc.add(beyond, w);
      return;
    }
    const Vertex end = offset < 0 ? a : b, other = offset < 0 ? b : a;
    acc.add(end, FT(2) * w); // 2 end - other
    acc.add(other, -w);
  }

  /// the even and odd masks, by increasing offset
  const std::vector<std::pair<int, FT>>& even() const { return m_even; }
  const std::vector<std::pair<int, FT>>& odd() const { return m_odd; }

  /*
   * The border vertex k steps along the border from source(g) (k = 1:
   * target(g)); `g` is a halfedge of a border edge, either the border
   * halfedge (walking with the border loop) or its opposite (walking against it).
   */
  template <class Mesh>
  static typename boost::graph_traits<Mesh>::vertex_descriptor border_vertex(
    const Mesh& mesh, typename boost::graph_traits<Mesh>::halfedge_descriptor g, int k)
  {
    if(CGAL::is_border(g, mesh)) { // with the border loop
      for(; k > 1; --k)
        g = next(g, mesh);
      for(; k < 0; ++k)
        g = prev(g, mesh);
      return k == 1 ? target(g, mesh) : source(g, mesh);
    }
    auto b = opposite(g, mesh); // against the border loop: b runs from target(g) to source(g)
    for(; k > 1; --k)
      b = prev(b, mesh);
    for(; k < 0; ++k)
      b = next(b, mesh);
    return k == 1 ? source(b, mesh) : target(b, mesh);
  }

private:
  // the accumulator the curve masks are read with: their terms by increasing
  // offset, the weights of an offset added up. A plain insertion: a mask has
  // a handful of terms, and this costs every program that refines a border
  // less to compile than a Stencil sorted afterwards
  struct Sorted_terms
  {
    std::vector<std::pair<int, FT>> terms;

    void add(int offset, const FT& weight)
    {
      auto at = terms.begin();
      while(at != terms.end() && at->first < offset)
        ++at;
      if(at != terms.end() && at->first == offset)
        at->second += weight;
      else
        terms.emplace(at, offset, weight);
    }
  };

  template <class Mesh, class Accumulator>
  static void add_along(const std::vector<std::pair<int, FT>>& mask, const Mesh& mesh,
                        typename boost::graph_traits<Mesh>::halfedge_descriptor g, Accumulator& acc)
  {
    for(const auto& term : mask)
      acc.add(border_vertex(mesh, g, term.first), term.second);
  }

  std::vector<std::pair<int, FT>> m_even;
  std::vector<std::pair<int, FT>> m_odd;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_BORDER_CURVE_RULE_H
