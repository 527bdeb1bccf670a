// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_DOO_SABIN_MASK_H
#define CGAL_SUBDIV_MASKS_DOO_SABIN_MASK_H

#include <CGAL/Subdiv/curves/Chaikin_scheme.h>
#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/masks/Border_curve_rule.h>
#include <CGAL/Subdiv/masks/Sharp_rules.h>
#include <CGAL/Subdiv/masks/cosines.h>
#include <CGAL/Subdiv/views/Split.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/boost/graph/helpers.h>

#include <string>

namespace CGAL {
namespace Subdiv {
/*!
 * \ingroup PkgSubdivMasks
 * Doo-Sabin subdivision [Doo and Sabin 1978] on any polygon mesh; split: the
 * dual quad split (`Dual_split`).
 *
 * The new vertex of corner i of an n-gon (v_0, ..., v_{n-1}) is
 * \f$ \sum_j w_{ij} v_j \f$ with
 * \f$ w_{ij} = \frac{3 + 2\cos(2\pi(i-j)/n)}{4n} \f$ for j != i and
 * \f$ w_{ii} = \frac{n+5}{4n} \f$ (for a quad: 9/16, 3/16, 1/16, 3/16), the
 * weights of Doo and Sabin and of CGAL's `DooSabin_mask_3`. The cosine is
 * rational for n = 3, 4, 6 only (faces of those sizes are refined exactly by
 * an exact kernel); for other n the weight uses the double nearest to the
 * cosine (`internal::cos_two_pi_fraction`), converted to FT, and \f$ w_{ii} \f$ is computed as 1 minus the other
 * weights, so the weights of every corner sum to exactly 1 in any FT (the
 * scheme stays affine invariant; for n = 3, 4, 6 this is (n+5)/(4n) exactly).
 *
 * Border (a choice, with the border topology of `Dual_split`): the corner of a
 * face at a border vertex v whose face has a border edge (u, v) at v becomes
 * 3/4 v + 1/4 u, Chaikin's point on that edge; a corner whose face has both
 * border edges at v (a vertex with a single face, e.g. a valence-2 corner)
 * stays at v. So the new border polygon is Chaikin's refinement of the old
 * one, with such corners kept, and the border converges to the quadratic
 * B-spline of the border polygon: the same degree as the surface, which does
 * not shrink away from its border. Every other corner uses the face rule
 * above. CGAL's `DooSabin_subdivision` uses the face rule for every corner
 * and makes no faces at border vertices, so its surface pulls back from the
 * border by about a quarter of the border faces at each level; its interior
 * points are those of this mask (see the tests).
 *
 * Creases (`edge_sharpness_map`, `vertex_sharpness_map` of `subdivide()`):
 * infinitely sharp values only (0, or 10 and above; a semi-sharp value is
 * refused, naming the edge or the vertex). A sharp edge is refined as a
 * border on both of its sides: the corner at v of a face beside the sharp
 * edge (u, v) goes to Chaikin's point 3/4 v + 1/4 u (the same border rule),
 * and the two corners across the edge are one new vertex (`Dual_split`), so
 * the crease polyline is refined by Chaikin's rule. A corner (a vertex
 * sharpness of 10 and above, three sharp edges or more, or a face whose two
 * edges at the vertex are sharp) keeps one new vertex at the vertex itself;
 * a dart (one sharp edge) is refined smooth. The limit layer does not take
 * the tags for this scheme (`internal::Limit_takes_sharpness_tags`).
 *
 * \tparam Mesh a model of `FaceGraph`
 * \tparam FT the number type of the weights (by default the mesh's)
 * \tparam Tagged whether the mask refines with the sharpness tags of a level
 * (made by `subdivide()`)
 * \cgalModels `SurfaceSubdivisionMask`
 */
template <class Mesh, class FT = internal::Mesh_FT<Mesh>, bool Tagged = false>
class Doo_sabin_mask : public With_sharp_level<Doo_sabin_mask<Mesh, FT, Tagged>, Mesh, FT, Tagged>
{
public:
  using Polygon_mesh = Mesh;
  using Number_type = FT;
  static constexpr Split split = Split::dual;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;

  Doo_sabin_mask() : m_border(Chaikin_scheme<FT>()) {}

  /// the same rules for another mesh type and number type
  template <class OtherMesh, class OtherFT, bool OtherTagged = false>
  Doo_sabin_mask<OtherMesh, OtherFT, OtherTagged> rebind() const
  {
    return Doo_sabin_mask<OtherMesh, OtherFT, OtherTagged>();
  }

  /// the sharpness tags it takes are infinitely sharp ones
  static constexpr bool takes_semi_sharp_tags = false;

  std::string name() const { return "Doo-Sabin"; }
  bool is_interpolating() const { return false; }

  /// the new vertex of the corner of face(h) at target(h)
  template <class Accumulator>
  void corner_node(const Corner_view<Mesh>& corner, Accumulator& acc) const
  {
    const Mesh& mesh = corner.mesh();
    const halfedge_descriptor h = corner.halfedge();
    const halfedge_descriptor n = next(h, mesh);
    if(corner.kept()) { // a corner with a single face (or a corner vertex): kept
      acc.add(target(h, mesh), FT(1));
      return;
    }
    if(corner.sharp_before() || corner.sharp_after()) { // Chaikin on the border or sharp edge, from the corner
      m_border.dual_point(mesh, corner.sharp_before() ? opposite(h, mesh) : n, acc);
      return;
    }
    const int size = corner.face_size();
    const FT denominator = FT(4 * size);
    FT others(0);
    int k = 1;
    for(halfedge_descriptor g = n; g != h; g = next(g, mesh), ++k) {
      const FT weight = (FT(3) + FT(2) * internal::cos_two_pi_fraction<FT>(k, size)) / denominator;
      others += weight;
      acc.add(target(g, mesh), weight);
    }
    acc.add(target(h, mesh), FT(1) - others);
  }

private:
  Border_curve_rule<FT> m_border;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_DOO_SABIN_MASK_H
