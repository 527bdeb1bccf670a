// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_INTERPOLATING_SQRT3_MASK_H
#define CGAL_SUBDIV_MASKS_INTERPOLATING_SQRT3_MASK_H

#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/masks/Sharp_rules.h>
#include <CGAL/Subdiv/views/Split.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/number_type_config.h> // CGAL_PI

#include <cmath>
#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivMasks
 * Interpolating sqrt3 subdivision after Labsik and Greiner [U. Labsik,
 * G. Greiner, "Interpolatory sqrt(3)-Subdivision", Computer Graphics Forum
 * 19(3), Eurographics 2000] on triangle meshes; split: `Sqrt3_split` (the
 * same topology as Kobbelt's sqrt3, border refined every second step).
 *
 * Old vertices are kept (border vertices too). The new point of a face
 * (a, b, c) is:
 *
 * - <b>regular face</b> (a, b, c interior, each of valence 6): the 12-point
 *   stencil of the paper, 32/81 for each corner, -1/81 for each of the three
 *   vertices opposite to the face across its edges, -2/81 for each of the six
 *   further neighbours of the corners. These weights are the unique
 *   symmetric ones on this support that reproduce cubic polynomials on a
 *   regular planar grid (checked in the tests), which is what the paper
 *   derives them from;
 * - <b>face with irregular corners</b> (one or more interior corners of
 *   valence n != 6): the average, over those corners, of the one-ring rule of
 *   the corner v with ring v_0 .. v_{n-1}, where the face lies between
 *   v_{n-1} and v_0: \f$ q = (1 - \sum_j w_j) v + \sum_j w_j v_j \f$,
 *   \f$ w_j = \frac1n \left( \frac13 + \frac{2}{\sqrt3} \cos\theta_j + \frac23 \cos 2\theta_j \right) \f$,
 *   \f$ \theta_j = 2\pi (j + \frac12) / n \f$, and without the last term for
 *   n = 3 (where it would alias onto the first harmonic). This is the
 *   Fourier construction of the paper's irregular rule (as for Zorin's
 *   modified butterfly): the ring's first harmonics are scaled by
 *   \f$ 1/\sqrt3 \f$ and turned by \f$ \pi/n \f$, the second harmonics and the
 *   mean by 1/3, the others are dropped, so that the rule reproduces
 *   quadratics of the characteristic map and the local subdivision matrix
 *   has the subdominant eigenvalues \f$ 1/\sqrt3 \f$ (twice, rotating), then 1/3.
 *   <em>Unsure:</em> this is a reconstruction; the paper's printed irregular
 *   weights may differ in the coefficient of the mean (1/3 here) and in the
 *   valence-3 case. At n = 6 it gives the rational weights
 *   (5, -1, -1, -1, -1, 5)/18 and 2/3 for v; at other valences the weights
 *   are evaluated in double precision and converted to `FT` (the centre
 *   weight is 1 minus their sum, so weights sum to exactly 1 in an exact FT).
 * - <b>other faces at the border</b> (no irregular interior corner, at least
 *   one border corner): the 6-point rule 4/9 for each corner, -1/9 for each
 *   opposite vertex, where the opposite vertex across a border edge (a, b)
 *   of the face (a, b, c) is replaced by its reflection a + b - c. It
 *   reproduces quadratics on a regular grid. <em>Our choice</em>: we do not
 *   recall the paper's rule for these faces.
 * - <b>border</b> (on a refining step, see `Sqrt3_split`): the border curve is
 *   refined by the interpolating ternary 4-point rule (cubic Lagrange
 *   interpolation at 1/3 and 2/3): the border edge (t, s) with border
 *   neighbours t' (beyond t) and s' (beyond s) gets
 *   (-5 t' + 60 t + 30 s - 4 s') / 81 at one third from t and the mirror
 *   image at two thirds. <em>Our choice</em> as well (the border curve then
 *   depends on the border polygon only and reproduces cubics).
 *
 * All rules are rational, so exact in an exact kernel, except the one-ring
 * rule at valences other than 6.
 *
 * Creases (`edge_sharpness_map`, `vertex_sharpness_map` of `subdivide()`),
 * infinitely sharp values only, as `Sqrt3_mask` takes them: a sharp edge is
 * refined as a border edge on both of its sides, with the border's ternary
 * 4-point rule along the polyline of sharp edges, continued by point
 * reflection where it ends (at a corner or at the end of a dart's edge). In
 * the face rules a corner with a sharp edge (a dart, crease or corner
 * vertex) counts as a border corner, and the opposite vertex across a sharp
 * edge is reflected as across a border edge, so that no stencil reaches
 * across a crease. Old vertices stay where they are, tags or not.
 *
 * \tparam Mesh a model of `FaceGraph` whose faces are triangles
 * \tparam FT the number type of the weights (by default the mesh's)
 * \tparam Tagged whether the mask refines with the sharpness tags of a level
 * (made by `subdivide()`)
 * \cgalModels `SurfaceSubdivisionMask`
 */
template <class Mesh, class FT = internal::Mesh_FT<Mesh>, bool Tagged = false>
class Interpolating_sqrt3_mask : public With_sharp_level<Interpolating_sqrt3_mask<Mesh, FT, Tagged>, Mesh, FT, Tagged>
{
public:
  using Polygon_mesh = Mesh;
  using Number_type = FT;
  static constexpr Split split = Split::sqrt3;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;

  /// the same rules for another mesh type and number type
  template <class OtherMesh, class OtherFT, bool OtherTagged = false>
  Interpolating_sqrt3_mask<OtherMesh, OtherFT, OtherTagged> rebind() const
  {
    return Interpolating_sqrt3_mask<OtherMesh, OtherFT, OtherTagged>();
  }

  /// the sharpness tags it takes are infinitely sharp ones
  static constexpr bool takes_semi_sharp_tags = false;

  std::string name() const { return "interpolating sqrt3 (Labsik-Greiner)"; }
  bool is_interpolating() const { return true; }

  /// weight of ring vertex j (0 <= j < n) in the one-ring rule of a vertex of
  /// valence n, the face lying between ring vertices n-1 and 0
  static FT ring_weight(int n, int j)
  {
    if(n == 6) {
      const int numerator[6] = {5, -1, -1, -1, -1, 5};
      return FT(numerator[j]) / FT(18);
    }
    const double theta = 2 * CGAL_PI * (j + 0.5) / n;
    double w = 1.0 / 3 + 2 / std::sqrt(3.0) * std::cos(theta);
    if(n != 3)
      w += 2.0 / 3 * std::cos(2 * theta);
    return FT(w / n);
  }
  /// whether `ring_weight(n, j)` is exact (n = 6)
  static bool is_exact(int n) { return n == 6; }

  template <class Accumulator>
  void vertex_node(const Vertex_view<Mesh>& v, Accumulator& acc) const
  {
    acc.add(v.vertex(), FT(1));
  }

  template <class Accumulator>
  void resting_border_vertex_node(const Vertex_view<Mesh>& v, Accumulator& acc) const
  {
    acc.add(v.vertex(), FT(1));
  }

  template <class Accumulator>
  void border_vertex_node(const Vertex_view<Mesh>& v, Accumulator& acc) const
  {
    acc.add(v.vertex(), FT(1));
  }

  template <class Accumulator>
  void face_node(const Face_view<Mesh>& f, Accumulator& acc) const
  {
    const Mesh& mesh = f.mesh();
    halfedge_descriptor h[3];
    h[0] = f.halfedge();
    h[1] = next(h[0], mesh);
    h[2] = next(h[1], mesh);
    int valence[3];
    bool border[3];
    bool all_regular = true;
    int irregular = 0;
    for(int k = 0; k < 3; ++k) {
      // the view of the mask's level: without tags a corner has a rule other
      // than smooth on the border only; with them, where it has a sharp edge
      const Vertex_view<Mesh> corner = vertex_view(*this, mesh, target(h[k], mesh));
      valence[k] = corner.valence();
      border[k] = corner.rule() != Vertex_rule::smooth;
      all_regular = all_regular && !border[k] && valence[k] == 6;
      irregular += !border[k] && valence[k] != 6;
    }
    if(all_regular)
      return regular_rule(mesh, h, acc);
    if(irregular > 0) {
      const FT share = FT(1) / FT(irregular);
      for(int k = 0; k < 3; ++k)
        if(!border[k] && valence[k] != 6)
          one_ring_rule(mesh, h[k], valence[k], share, acc);
      return;
    }
    // border rule: corners 4/9, opposite vertices (or their reflection across
    // a border or sharp edge) -1/9
    for(int k = 0; k < 3; ++k) {
      acc.add(target(h[k], mesh), FT(4) / FT(9));
      const halfedge_descriptor o = opposite(h[k], mesh);
      if(!edge_view(*this, mesh, h[k]).sharp()) {
        acc.add(target(next(o, mesh), mesh), -FT(1) / FT(9));
      } else { // reflection source + target - apex
        acc.add(source(h[k], mesh), -FT(1) / FT(9));
        acc.add(target(h[k], mesh), -FT(1) / FT(9));
        acc.add(target(next(h[k], mesh), mesh), FT(1) / FT(9));
      }
    }
  }

  /// the new vertex at k/3 (k = 1, 2) of the way along the face halfedge
  /// `e.halfedge()` of a border edge (with tags: of a sharp edge, along its
  /// polyline of sharp edges), on a refining step
  template <class Accumulator>
  void border_edge_node(const Edge_view<Mesh>& e, int k, Accumulator& acc) const
  {
    const internal::Curve_edge<Mesh> c(*this, e, k);
    Border_curve_rule<FT>::add_polyline_vertex(-1, -FT(5) / FT(81), c.before, c.a, c.b, c.after, c.none, acc);
    Border_curve_rule<FT>::add_polyline_vertex(0, FT(60) / FT(81), c.before, c.a, c.b, c.after, c.none, acc);
    Border_curve_rule<FT>::add_polyline_vertex(1, FT(30) / FT(81), c.before, c.a, c.b, c.after, c.none, acc);
    Border_curve_rule<FT>::add_polyline_vertex(2, -FT(4) / FT(81), c.before, c.a, c.b, c.after, c.none, acc);
  }

private:
  template <class Accumulator>
  void regular_rule(const Mesh& mesh, const halfedge_descriptor (&h)[3], Accumulator& acc) const
  {
    for(int k = 0; k < 3; ++k) {
      // around corner c = target(h[k]), away from the face: the ring from
      // next(h[k]) on is b, o (opposite across (c, b)), y1, y2, o', a
      acc.add(target(h[k], mesh), FT(32) / FT(81));
      halfedge_descriptor g = next(opposite(next(h[k], mesh), mesh), mesh);
      acc.add(target(g, mesh), -FT(1) / FT(81));
      g = next(opposite(g, mesh), mesh);
      acc.add(target(g, mesh), -FT(2) / FT(81));
      g = next(opposite(g, mesh), mesh);
      acc.add(target(g, mesh), -FT(2) / FT(81));
    }
  }

  // the one-ring rule of v = target(h) for face(h), scaled by `share`
  template <class Accumulator>
  void one_ring_rule(const Mesh& mesh, halfedge_descriptor h, int n, const FT& share, Accumulator& acc) const
  {
    FT sum(0);
    halfedge_descriptor g = next(h, mesh); // from v to ring vertex 0
    for(int j = 0; j < n; ++j, g = next(opposite(g, mesh), mesh)) {
      const FT w = ring_weight(n, j);
      sum += w;
      acc.add(target(g, mesh), share * w);
    }
    acc.add(target(h, mesh), share * (FT(1) - sum));
  }
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_INTERPOLATING_SQRT3_MASK_H
