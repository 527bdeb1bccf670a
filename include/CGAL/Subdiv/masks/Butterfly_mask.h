// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_BUTTERFLY_MASK_H
#define CGAL_SUBDIV_MASKS_BUTTERFLY_MASK_H

#include <CGAL/Subdiv/curves/Four_point_scheme.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/masks/Border_curve_rule.h>
#include <CGAL/Subdiv/masks/Sharp_rules.h>
#include <CGAL/Subdiv/masks/butterfly_weights.h>
#include <CGAL/Subdiv/views/Split.h>
#include <CGAL/Subdiv/views/Vertex_view.h>

#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivMasks
 * The butterfly scheme of Dyn, Levin and Gregory [1990] on triangle meshes;
 * split: 1-to-4 triangle split. Interpolating: old vertices keep their
 * positions.
 *
 * - interior edge (a, b) with wings c, d (the third vertices of its two
 *   faces) and outer vertices e1..e4 (the third vertices of the faces across
 *   the four other edges of those two faces, see `butterfly_weights.h`):
 *   \f$ \frac12 (a + b) + 2w (c + d) - w (e_1 + e_2 + e_3 + e_4) \f$;
 *   w = 1/16 gives 1/2, 1/2, 1/8, 1/8, -1/16 x 4 and reproduces cubic
 *   polynomials on a regular (valence 6) mesh. The same eight-point stencil
 *   is used at every valence: that is the 1990 scheme (the modified butterfly,
 *   `Modified_butterfly_mask`, is the variant with rules for valence != 6).
 * - old vertex: itself, weight 1.
 *
 * Border rules. The 1990 paper states no rule for a mesh with a border; this
 * mask chooses:
 * - border edge: the four-point rule with the same tension,
 *   -w, 1/2 + w, 1/2 + w, -w over the border polygon (-1/16, 9/16, 9/16,
 *   -1/16 at w = 1/16): `Four_point_scheme` through `Border_curve_rule`. A
 *   border edge point depends on border vertices only, so every border loop
 *   of the refined mesh is exactly one step of the four-point curve scheme
 *   applied to the old loop;
 * - interior edge whose stencil reaches over the border (an outer vertex
 *   e_i is missing because the edge across which it lies is a border edge):
 *   the missing vertex is replaced by the reflection of the face's third
 *   vertex through that border edge's midpoint, e.g. e1 := b + c - a, the
 *   vertex a regular grid would have there. The weights still sum to 1, so
 *   the rule is affine invariant and reproduces planes; it does not
 *   reproduce cubics.
 *
 * Creases (`edge_sharpness_map`, `vertex_sharpness_map` of `subdivide()`):
 * infinitely sharp values only (0, or 10 and above; a semi-sharp value is
 * refused, naming the edge or the vertex). An infinitely sharp edge is
 * refined as a border edge on both of its sides: its edge point is the
 * four-point rule along the polyline of sharp edges, which goes on through a
 * vertex with two sharp edges and ends at a corner (three or more, or a
 * sharp vertex) or at the end of a dart's edge, where it is continued by
 * point reflection as `End_rule::keep_ends` continues an open curve; the
 * stencil of an interior edge does not reach across a sharp edge (the
 * missing vertices are reflected, as at the border). The border is a crease
 * that ends at the corners. Old vertices keep their positions, tags or not.
 *
 * \tparam Mesh a model of `FaceGraph`
 * \tparam FT the number type of the weights (by default the mesh's)
 * \tparam Tagged whether the mask refines with the sharpness tags of a level
 * (made by `subdivide()`)
 * \cgalModels `SurfaceSubdivisionMask`
 */
template <class Mesh, class FT = internal::Mesh_FT<Mesh>, bool Tagged = false>
class Butterfly_mask : public With_sharp_rules<Butterfly_mask<Mesh, FT, Tagged>, Mesh, FT, Tagged>
{
public:
  using Polygon_mesh = Mesh;
  using Number_type = FT;
  static constexpr Split split = Split::triangle_quadrisection;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;

  /// \throws Bad_input unless 0 <= w < 1/4: the range in which the four-point
  /// rule of the border converges. w = 0 is piecewise-linear interpolation
  /// (edge midpoints); w = 1/16 is the value of the paper.
  explicit Butterfly_mask(const FT& w = FT(1) / FT(16))
    : With_sharp_rules<Butterfly_mask, Mesh, FT, Tagged>(Four_point_scheme<FT>(checked(w))), m_w(w),
      m_half(FT(1) / FT(2)), m_wing(FT(2) * w), m_outer(-w)
  {}

  /// the same rules, with the same tension, for another mesh type and number type
  template <class OtherMesh, class OtherFT, bool OtherTagged = false>
  Butterfly_mask<OtherMesh, OtherFT, OtherTagged> rebind() const
  {
    return Butterfly_mask<OtherMesh, OtherFT, OtherTagged>(internal::convert_weight<OtherFT>(m_w));
  }

  /// the sharpness tags it takes are infinitely sharp ones
  static constexpr bool takes_semi_sharp_tags = false;

  std::string name() const { return "butterfly"; }
  bool is_interpolating() const { return true; }
  const FT& w() const { return m_w; }

  template <class Accumulator>
  void vertex_node(const Vertex_view<Mesh>& v, Accumulator& acc) const
  {
    acc.add(v.vertex(), FT(1));
  }

  template <class Accumulator>
  void edge_node(const Edge_view<Mesh>& e, Accumulator& acc) const
  {
    if constexpr(Tagged) { // creases: sharp edges as borders, to both sides
      if(e.sharp()) {
        internal::crease_edge_point(*this->sharp_level(), this->crease_curve(), e, acc);
        return;
      }
      const internal::Sharp_cuts<internal::Sharp_level<Mesh, FT>> cuts{this->sharp_level()};
      internal::butterfly_stencil(e.mesh(), e.halfedge(), m_half, m_wing, m_outer, acc, cuts);
      return;
    }
    if(e.on_border()) { // border edge: four-point rule, along the border loop
      this->crease_curve().edge_point(e.mesh(), e.border_halfedge(), acc);
      return;
    }
    // interior edge: eight-point stencil, missing outer vertices reflected
    internal::butterfly_stencil(e.mesh(), e.halfedge(), m_half, m_wing, m_outer, acc);
  }

private:
  static const FT& checked(const FT& w)
  {
    internal::require(FT(0) <= w && w < FT(1) / FT(4), "butterfly tension w must satisfy 0 <= w < 1/4");
    return w;
  }

  FT m_w;
  FT m_half;
  FT m_wing;
  FT m_outer;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_BUTTERFLY_MASK_H
