// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_BUTTERFLY_WEIGHTS_H
#define CGAL_SUBDIV_MASKS_BUTTERFLY_WEIGHTS_H

#include <CGAL/Subdiv/masks/Border_curve_rule.h>
#include <CGAL/Subdiv/masks/Sharp_rules.h>
#include <CGAL/Subdiv/masks/cosines.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * Stencil pieces shared by the butterfly and the modified butterfly masks.
 * Names for an interior edge, seen from halfedge h = (a -> b) in face
 * (a, b, c), its opposite in face (b, a, d):
 *
 *        e2 ------ c ------ e1
 *          \     /   \     /
 *           \   /     \   /
 *             a ------- b
 *           /   \     /   \
 *          /     \   /     \
 *        e3 ------ d ------ e4
 *
 * a, b are the ends, c, d the wings, e1..e4 the outer vertices: e1 lies
 * across edge (b, c) from a, e2 across (c, a) from b, e3 across (a, d) from
 * b, e4 across (d, b) from a.
 */

// whether the edge of halfedge x (of a face) is on the border: the stencils
// do not reach across it
struct Border_cuts
{
  template <class Mesh>
  bool operator()(const Mesh& mesh, typename boost::graph_traits<Mesh>::halfedge_descriptor x) const
  {
    return CGAL::is_border(opposite(x, mesh), mesh);
  }
};

// The outer vertex across the edge of halfedge x from the face of x, with
// `weight`. Where the stencil does not reach across that edge (`cut(mesh,
// x)`: it is on the border, or an infinitely sharp crease) the outer vertex
// is replaced by the reflection of the face's third vertex r through the
// midpoint of x's edge, source(x) + target(x) - r: the vertex a regular
// triangle grid would have there. The weights still sum to `weight`, so the
// stencil stays affine invariant.
template <class Mesh, class FT, class Accumulator, class Cut = Border_cuts>
void add_outer_vertex(const Mesh& mesh, typename boost::graph_traits<Mesh>::halfedge_descriptor x, const FT& weight,
                      Accumulator& acc, const Cut& cut = Cut())
{
  const auto across = opposite(x, mesh);
  if(!cut(mesh, x)) {
    acc.add(target(next(across, mesh), mesh), weight);
    return;
  }
  const FT minus_weight = -weight;
  acc.add(source(x, mesh), weight);
  acc.add(target(x, mesh), weight);
  acc.add(target(next(x, mesh), mesh), minus_weight);
}

// The butterfly stencil of the interior edge of h: `end` for a and b,
// `wing` for c and d, `outer` for e1..e4 (reflected where `cut` says the
// stencil does not reach across).
template <class Mesh, class FT, class Accumulator, class Cut = Border_cuts>
void butterfly_stencil(const Mesh& mesh, typename boost::graph_traits<Mesh>::halfedge_descriptor h, const FT& end,
                       const FT& wing, const FT& outer, Accumulator& acc, const Cut& cut = Cut())
{
  for(const auto g : {h, opposite(h, mesh)}) {
    acc.add(target(g, mesh), end);
    acc.add(target(next(g, mesh), mesh), wing);
    add_outer_vertex(mesh, next(g, mesh), outer, acc, cut);
    add_outer_vertex(mesh, prev(g, mesh), outer, acc, cut);
  }
}

// whether the edge of halfedge x (of a face) is on the border or sharp on
// `level` (the sharpness tags of a level): the stencils of the butterflies
// do not reach across an infinitely sharp crease, as across a border
template <class Level>
struct Sharp_cuts
{
  const Level* level;
  template <class Mesh>
  bool operator()(const Mesh&, typename boost::graph_traits<Mesh>::halfedge_descriptor x) const
  {
    return level->edge_view(x).sharp();
  }
};

// The new vertex on the sharp edge `e` under the tags of `level`: the curve
// rule `curve` along the polyline of sharp edges (a crease, or the border,
// walked with its loop as without tags), which goes on through a vertex with
// the crease rule (two sharp edges) and ends at any other (a corner, or the
// end of a dart's edge), where it is continued by point reflection
// (`Border_curve_rule::polyline_edge_point`).
template <class Level, class Mesh, class FT, class Accumulator>
void crease_edge_point(const Level& level, const Border_curve_rule<FT>& curve, const Edge_view<Mesh>& e,
                       Accumulator& acc)
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  const Mesh& mesh = e.mesh();
  const auto h = e.on_border() ? e.border_halfedge() : e.halfedge();
  const vertex_descriptor a = source(h, mesh), b = target(h, mesh);
  curve.polyline_edge_point(crease_beyond(level, mesh, a, h), a, b, crease_beyond(level, mesh, b, h),
                            boost::graph_traits<Mesh>::null_vertex(), acc);
}

} // namespace internal

/*!
 * \ingroup PkgSubdivMasks
 * The weights of the modified butterfly rule [Zorin, Schroeder, Sweldens
 * 1996] for an edge from a vertex v of valence k, k >= 3, whose neighbours
 * e_0, ..., e_{k-1} are numbered around v from the edge's other end e_0:
 *
 * - k = 3: s_0 = 5/12, s_1 = s_2 = -1/12;
 * - k = 4: s_0 = 3/8, s_1 = 0, s_2 = -1/8, s_3 = 0;
 * - k >= 5: \f$ s_j = \frac1k \left( \frac14 + \cos\frac{2\pi j}{k} + \frac12 \cos\frac{4\pi j}{k} \right) \f$;
 * - v itself: `centre` = 1 - sum_j s_j, which is 3/4.
 *
 * Exact (rational) at k = 3, 4 and 6; at other valences some cosines are
 * irrational and the double nearest to each is used. The centre weight is
 * computed as 1 - sum_j s_j rather than written as 3/4, so that the weights
 * sum to exactly 1 in every number type: an exact kernel then keeps the
 * scheme's affine invariance exactly, and the centre weight differs from 3/4
 * by the rounding of the cosines only.
 */
template <class FT>
struct Modified_butterfly_weights
{
  FT centre;
  std::vector<FT> ring; ///< s_0, ..., s_{k-1}

  /// \pre k >= 3
  explicit Modified_butterfly_weights(int k) : centre(0), ring(k > 0 ? k : 0, FT(0))
  {
    if(k == 3) {
      ring[0] = FT(5) / FT(12);
      ring[1] = ring[2] = FT(-1) / FT(12);
    } else if(k == 4) {
      ring[0] = FT(3) / FT(8);
      ring[2] = FT(-1) / FT(8);
    } else {
      for(int j = 0; j < k; ++j) {
        const FT sum =
          FT(1) / FT(4) + internal::cos_two_pi_fraction<FT>(j, k) + internal::cos_two_pi_fraction<FT>(2 * j, k) / FT(2);
        ring[j] = sum / FT(k);
      }
    }
    FT ring_sum(0);
    for(const FT& s : ring)
      ring_sum += s;
    centre = FT(1) - ring_sum;
  }

  /// whether every weight at valence k is the exact (rational) value
  static bool is_exact(int k)
  {
    if(k == 3 || k == 4)
      return true;
    for(int j = 0; j < k; ++j) {
      bool first = false, second = false;
      internal::cos_two_pi_fraction<double>(j, k, &first);
      internal::cos_two_pi_fraction<double>(2 * j, k, &second);
      if(!first || !second)
        return false;
    }
    return true;
  }
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_BUTTERFLY_WEIGHTS_H
