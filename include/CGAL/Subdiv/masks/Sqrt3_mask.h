// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_SQRT3_MASK_H
#define CGAL_SUBDIV_MASKS_SQRT3_MASK_H

#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/masks/Sharp_rules.h>
#include <CGAL/Subdiv/masks/cosines.h>
#include <CGAL/Subdiv/views/Split.h>
#include <CGAL/Subdiv/views/Vertex_view.h>

#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivMasks
 * Kobbelt's sqrt3 subdivision [Kobbelt 2000, "sqrt(3)-Subdivision",
 * SIGGRAPH 2000] on triangle meshes; split: `Sqrt3_split`.
 *
 * - face point: the centroid, 1/3 for each corner;
 * - interior vertex of valence n: \f$ (1 - \alpha_n) v + \frac{\alpha_n}{n} \sum_i v_i \f$
 *   with \f$ \alpha_n = \frac{4 - 2\cos(2\pi/n)}{9} \f$. The weight is
 *   rational at n = 3, 4, 6 (\f$\alpha\f$ = 5/9, 4/9, 1/3) and exact there in
 *   an exact kernel; at other valences \f$\alpha_n\f$ is evaluated in double
 *   precision (cos(2 pi / n) is the double nearest to it) and converted to
 *   `FT`, so that an exact kernel gets weights that are exact rationals
 *   within an ulp of the true ones, and that still sum to exactly 1.
 * - border (Kobbelt's univariate rules, the ternary cubic B-spline, applied
 *   on every second step only, see `Sqrt3_split`): on a refining step the
 *   border edge (t, s), whose border neighbours beyond t and s are t' and s',
 *   gets (16 t + 10 s + t') / 27 at one third from t and (10 t + 16 s + s') / 27
 *   at two thirds; border vertex v with border neighbours u, w becomes
 *   (4 u + 19 v + 4 w) / 27. On a resting step border vertices stay where
 *   they are. These are the rules of CGAL's `Sqrt3_mask_3`.
 *
 * Creases (`edge_sharpness_map`, `vertex_sharpness_map` of `subdivide()`):
 * infinitely sharp values only (0, or 10 and above; a semi-sharp value is
 * refused, naming the edge or the vertex). A sharp edge is refined as a
 * border edge on both of its sides (`Sqrt3_split`: not flipped, trisected on
 * the steps that refine the border, with the border rules above along the
 * polyline of sharp edges), and a crease vertex (two sharp edges) moves by
 * the border vertex rule along it on those steps. The polyline ends at a
 * corner (a sharp vertex, or three sharp edges or more), which stays where
 * it is, and at the end of a dart's edge; beyond an end it is continued by
 * point reflection (`Border_curve_rule::add_polyline_vertex`), so the third
 * next to an end is at (2 t + s) / 3. A dart follows the interior rule.
 *
 * \tparam Mesh a model of `FaceGraph` whose faces are triangles
 * \tparam FT the number type of the weights (by default the mesh's)
 * \tparam Tagged whether the mask refines with the sharpness tags of a level
 * (made by `subdivide()`)
 * \cgalModels `SurfaceSubdivisionMask`
 */
template <class Mesh, class FT = internal::Mesh_FT<Mesh>, bool Tagged = false>
class Sqrt3_mask : public With_sharp_level<Sqrt3_mask<Mesh, FT, Tagged>, Mesh, FT, Tagged>
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
  Sqrt3_mask<OtherMesh, OtherFT, OtherTagged> rebind() const
  {
    return Sqrt3_mask<OtherMesh, OtherFT, OtherTagged>();
  }

  /// the sharpness tags it takes are infinitely sharp ones
  static constexpr bool takes_semi_sharp_tags = false;

  std::string name() const { return "sqrt3 (Kobbelt)"; }
  bool is_interpolating() const { return false; }

  /// \f$\alpha_n = (4 - 2\cos(2\pi/n)) / 9\f$
  static FT alpha(int n) { return (FT(4) - FT(2) * internal::cos_two_pi_over<FT>(n)) / FT(9); }
  /// whether `alpha(n)` is exact (n = 3, 4, 6)
  static bool is_exact(int n)
  {
    bool exact = false;
    internal::cos_two_pi_over<double>(n, &exact);
    return exact;
  }

  /// interior vertex
  template <class Accumulator>
  void vertex_node(const Vertex_view<Mesh>& view, Accumulator& acc) const
  {
    const int n = view.valence();
    const FT a = alpha(n);
    const FT each = a / FT(n);
    acc.add(view.vertex(), FT(1) - a);
    for(vertex_descriptor u : CGAL::vertices_around_target(view.vertex(), view.mesh()))
      acc.add(u, each);
  }

  template <class Accumulator>
  void face_node(const Face_view<Mesh>& f, Accumulator& acc) const
  {
    const FT third = FT(1) / FT(3);
    for(vertex_descriptor u : CGAL::vertices_around_face(f.halfedge(), f.mesh()))
      acc.add(u, third);
  }

  /// border vertex (with tags: crease or corner vertex) on a step that
  /// leaves the border alone: kept
  template <class Accumulator>
  void resting_border_vertex_node(const Vertex_view<Mesh>& view, Accumulator& acc) const
  {
    acc.add(view.vertex(), FT(1));
  }

  /// border vertex on a refining step (with tags: crease vertex, along its
  /// two sharp edges; a corner stays)
  template <class Accumulator>
  void border_vertex_node(const Vertex_view<Mesh>& view, Accumulator& acc) const
  {
    const Mesh& mesh = view.mesh();
    if(view.rule() == Vertex_rule::corner) {
      acc.add(view.vertex(), FT(1));
      return;
    }
    // the crease's two sharp edges; on the border, its border edges, in the order of the border loop
    const bool border = view.on_border();
    const vertex_descriptor u = border ? source(view.border_in(), mesh) : target(view.crease_out(0), mesh);
    const vertex_descriptor w = border ? target(view.border_out(), mesh) : target(view.crease_out(1), mesh);
    acc.add(u, FT(4) / FT(27));
    acc.add(view.vertex(), FT(19) / FT(27));
    acc.add(w, FT(4) / FT(27));
  }

  /// the new vertex at k/3 (k = 1, 2) of the way along the face halfedge
  /// `e.halfedge()` of a border edge (with tags: of a sharp edge, along its
  /// polyline of sharp edges), on a refining step
  template <class Accumulator>
  void border_edge_node(const Edge_view<Mesh>& e, int k, Accumulator& acc) const
  {
    const internal::Curve_edge<Mesh> c(*this, e, k);
    Border_curve_rule<FT>::add_polyline_vertex(0, FT(16) / FT(27), c.before, c.a, c.b, c.after, c.none, acc);
    Border_curve_rule<FT>::add_polyline_vertex(1, FT(10) / FT(27), c.before, c.a, c.b, c.after, c.none, acc);
    Border_curve_rule<FT>::add_polyline_vertex(-1, FT(1) / FT(27), c.before, c.a, c.b, c.after, c.none, acc);
  }
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_SQRT3_MASK_H
