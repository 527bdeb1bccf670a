// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_MODIFIED_BUTTERFLY_MASK_H
#define CGAL_SUBDIV_MASKS_MODIFIED_BUTTERFLY_MASK_H

#include <CGAL/Subdiv/curves/Four_point_scheme.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/masks/Border_curve_rule.h>
#include <CGAL/Subdiv/masks/Sharp_rules.h>
#include <CGAL/Subdiv/masks/butterfly_weights.h>
#include <CGAL/Subdiv/views/Split.h>
#include <CGAL/Subdiv/views/Vertex_view.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivMasks
 * The modified butterfly scheme of Zorin, Schroeder and Sweldens [1996] on
 * triangle meshes; split: 1-to-4 triangle split. Interpolating: old vertices
 * keep their positions. Names of the stencil vertices as in
 * `butterfly_weights.h` (ends a, b; wings c, d; outer e1..e4).
 *
 * Interior edge (a, b), both ends interior vertices:
 * - both of valence 6: the ten-point stencil of the paper,
 *   1/2 - w for a, b; 1/8 + 2w for c, d; -1/16 - w for e1..e4; w for the two
 *   far vertices (the neighbour of a opposite b in a's ring, and the
 *   neighbour of b opposite a). w = 0, the default, is the eight-point
 *   butterfly 1/2, 1/8, -1/16, i.e. `Butterfly_mask` with tension 1/16;
 * - one end of valence k != 6: the stencil around that end only,
 *   `Modified_butterfly_weights` (k = 3: 5/12, -1/12, -1/12; k = 4: 3/8, 0,
 *   -1/8, 0; k >= 5: cosine formula; 3/4 for the end itself);
 * - both ends of valence != 6: the average of the two stencils.
 *
 * Border rules. The paper's rules are for interior edges between interior
 * vertices; Zorin's thesis adds special boundary stencils, which this mask
 * does not reproduce. It chooses, and documents:
 * - border edge: the four-point rule -1/16, 9/16, 9/16, -1/16 over the
 *   border polygon (`Four_point_scheme`, through `Border_curve_rule`), so a
 *   border loop refines as the four-point curve scheme;
 * - interior edge with one end on the border and the other (interior) end
 *   of valence k != 6: the stencil around the interior end, which needs only
 *   that end's ring (complete, since the end is interior);
 * - any other interior edge touching the border (the interior end has valence
 *   6, or both ends are on the border): the eight-point butterfly 1/2, 1/8,
 *   -1/16, a missing outer vertex replaced by the reflection of its face's
 *   third vertex through the border edge (e1 := b + c - a), as in
 *   `Butterfly_mask`. An interior vertex of valence < 3 (a degenerate mesh)
 *   counts as a border vertex here.
 * These are the rules OpenMesh's `ModifiedButterFlyT` applies, so results on
 * meshes with borders agree with it as well.
 *
 * Creases (`edge_sharpness_map`, `vertex_sharpness_map` of `subdivide()`),
 * infinitely sharp values only, as `Butterfly_mask` takes them: a sharp edge
 * gets the four-point rule (1/16) along its polyline of sharp edges,
 * continued by point reflection where it ends, and an end with a sharp edge
 * (a crease, dart or corner vertex) counts as a border end in the rules
 * above, so that no stencil reaches across a crease.
 *
 * Exactness: the weights are rational, and so exact in an exact kernel, at
 * valences 3, 4 and 6; other valences use the nearest double of each cosine
 * (see `Modified_butterfly_weights`), with the end's own weight taken as
 * 1 - sum of the ring weights, so that every stencil sums to exactly 1.
 *
 * \tparam Mesh a model of `FaceGraph`
 * \tparam FT the number type of the weights (by default the mesh's)
 * \tparam Tagged whether the mask refines with the sharpness tags of a level
 * (made by `subdivide()`)
 * \cgalModels `SurfaceSubdivisionMask`
 */
template <class Mesh, class FT = internal::Mesh_FT<Mesh>, bool Tagged = false>
class Modified_butterfly_mask : public With_sharp_rules<Modified_butterfly_mask<Mesh, FT, Tagged>, Mesh, FT, Tagged>
{
public:
  using Polygon_mesh = Mesh;
  using Number_type = FT;
  static constexpr Split split = Split::triangle_quadrisection;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using Weights = Modified_butterfly_weights<FT>;

  /// \param w the parameter of the regular ten-point stencil.
  /// \throws Bad_input unless -1/16 <= w <= 1/16, the range this library
  /// accepts (in it the wing weight 1/8 + 2w is >= 0 and the outer weight
  /// -1/16 - w is <= 0, as in the butterfly); it is not a smoothness bound.
  explicit Modified_butterfly_mask(const FT& w = FT(0))
    : With_sharp_rules<Modified_butterfly_mask, Mesh, FT, Tagged>(Four_point_scheme<FT>(FT(1) / FT(16))), m_w(w),
      m_half(FT(1) / FT(2)), m_end(FT(1) / FT(2) - w), m_wing(FT(1) / FT(8) + FT(2) * w), m_outer(FT(-1) / FT(16) - w),
      m_plain_wing(FT(1) / FT(8)), m_plain_outer(FT(-1) / FT(16))
  {
    internal::require(FT(-1) / FT(16) <= w && w <= FT(1) / FT(16),
                      "modified butterfly parameter w must satisfy -1/16 <= w <= 1/16");
    for(int k = 0; k <= max_cached_valence; ++k) {
      m_cache.emplace_back(k >= 3 ? k : 0);
      m_half_cache.push_back(halved(m_cache.back()));
    }
  }

  /// the same rules, with the same parameter, for another mesh type and number type
  template <class OtherMesh, class OtherFT, bool OtherTagged = false>
  Modified_butterfly_mask<OtherMesh, OtherFT, OtherTagged> rebind() const
  {
    return Modified_butterfly_mask<OtherMesh, OtherFT, OtherTagged>(internal::convert_weight<OtherFT>(m_w));
  }

  /// the sharpness tags it takes are infinitely sharp ones
  static constexpr bool takes_semi_sharp_tags = false;

  std::string name() const { return "modified butterfly"; }
  bool is_interpolating() const { return true; }
  const FT& w() const { return m_w; }

  /// the weights around an end of valence k (k >= 3)
  static Weights weights(int k) { return Weights(k); }

  template <class Accumulator>
  void vertex_node(const Vertex_view<Mesh>& v, Accumulator& acc) const
  {
    acc.add(v.vertex(), FT(1));
  }

  template <class Accumulator>
  void edge_node(const Edge_view<Mesh>& e, Accumulator& acc) const
  {
    const Mesh& mesh = e.mesh();
    if constexpr(Tagged) { // creases: sharp edges as borders, to both sides
      const internal::Sharp_level<Mesh, FT>& level = *this->sharp_level();
      if(e.sharp()) {
        internal::crease_edge_point(level, this->crease_curve(), e, acc);
        return;
      }
      const Vertex_view<Mesh> a = level.vertex_view(source(e.halfedge(), mesh)),
                              b = level.vertex_view(target(e.halfedge(), mesh));
      // an end with a sharp edge counts as a border end
      interior_edge_point(mesh, e.halfedge(), a, a.rule() == Vertex_rule::smooth && usable(a), b,
                          b.rule() == Vertex_rule::smooth && usable(b),
                          internal::Sharp_cuts<internal::Sharp_level<Mesh, FT>>{&level}, acc);
    } else {
      if(e.on_border()) { // border edge: four-point rule, along the border loop
        this->crease_curve().edge_point(mesh, e.border_halfedge(), acc);
        return;
      }
      const Vertex_view<Mesh> a = e.end(0), b = e.end(1);
      interior_edge_point(mesh, e.halfedge(), a, usable(a), b, usable(b), internal::Border_cuts(), acc);
    }
  }

private:
  static constexpr int max_cached_valence = 32;

  // whether the stencils around an end can use its ring: an interior vertex
  // of valence 3 or more (a degenerate one counts as a border vertex)
  static bool usable(const Vertex_view<Mesh>& v) { return !v.on_border() && v.valence() >= 3; }

  // the new vertex on the interior edge of h from a = source(h) to b =
  // target(h), whose ring stencils are usable or not; the eight-point
  // stencil does not reach across the edges where `cut` says so
  template <class Cut, class Accumulator>
  void interior_edge_point(const Mesh& mesh, halfedge_descriptor h, const Vertex_view<Mesh>& a, bool a_usable,
                           const Vertex_view<Mesh>& b, bool b_usable, const Cut& cut, Accumulator& acc) const
  {
    const halfedge_descriptor g = opposite(h, mesh);
    if(a_usable && b_usable) {
      if(a.valence() == 6 && b.valence() == 6) { // regular: ten-point stencil
        internal::butterfly_stencil(mesh, h, m_end, m_wing, m_outer, acc);
        if(m_w != FT(0)) {
          acc.add(target(rotate(mesh, h, 3), mesh), m_w);
          acc.add(target(rotate(mesh, g, 3), mesh), m_w);
        }
      } else if(a.valence() != 6 && b.valence() != 6) { // two extraordinary ends: average
        ring_stencil(mesh, h, a.valence(), true, acc);
        ring_stencil(mesh, g, b.valence(), true, acc);
      } else if(a.valence() != 6) { // one extraordinary end
        ring_stencil(mesh, h, a.valence(), false, acc);
      } else {
        ring_stencil(mesh, g, b.valence(), false, acc);
      }
    } else if(a_usable && a.valence() != 6) { // b on the border: the stencil around a
      ring_stencil(mesh, h, a.valence(), false, acc);
    } else if(b_usable && b.valence() != 6) {
      ring_stencil(mesh, g, b.valence(), false, acc);
    } else { // a regular end next to the border, or both on it: eight-point butterfly, reflected
      internal::butterfly_stencil(mesh, h, m_half, m_plain_wing, m_plain_outer, acc, cut);
    }
  }

  // the next halfedge leaving source(x), `steps` times
  static halfedge_descriptor rotate(const Mesh& mesh, halfedge_descriptor x, int steps)
  {
    for(int i = 0; i < steps; ++i)
      x = opposite(prev(x, mesh), mesh);
    return x;
  }

  static Weights halved(const Weights& weights)
  {
    Weights half(0);
    half.centre = weights.centre / FT(2);
    for(const FT& s : weights.ring)
      half.ring.push_back(s / FT(2));
    return half;
  }

  // the stencil around v = source(h), of valence k, from e_0 = target(h);
  // halved when it is one of two averaged stencils
  template <class Accumulator>
  void ring_stencil(const Mesh& mesh, halfedge_descriptor h, int k, bool half, Accumulator& acc) const
  {
    if(k <= max_cached_valence)
      return add_ring(mesh, h, half ? m_half_cache[k] : m_cache[k], acc);
    const Weights weights(k);
    add_ring(mesh, h, half ? halved(weights) : weights, acc);
  }

  template <class Accumulator>
  static void add_ring(const Mesh& mesh, halfedge_descriptor h, const Weights& weights, Accumulator& acc)
  {
    acc.add(source(h, mesh), weights.centre);
    halfedge_descriptor x = h;
    for(const FT& s : weights.ring) {
      if(s != FT(0))
        acc.add(target(x, mesh), s);
      x = opposite(prev(x, mesh), mesh);
    }
  }

  FT m_w;
  FT m_half;
  FT m_end;
  FT m_wing;
  FT m_outer;
  FT m_plain_wing;
  FT m_plain_outer;
  std::vector<Weights> m_cache;      // by valence, 0..max_cached_valence
  std::vector<Weights> m_half_cache; // the same, halved
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_MODIFIED_BUTTERFLY_MASK_H
