// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_LOOP_MASK_H
#define CGAL_SUBDIV_MASKS_LOOP_MASK_H

#include <CGAL/Subdiv/curves/Uniform_bspline_scheme.h>
#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/masks/Sharp_rules.h>
#include <CGAL/Subdiv/masks/loop_weights.h>
#include <CGAL/Subdiv/views/Split.h>
#include <CGAL/Subdiv/views/Vertex_view.h>

#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivMasks
 * Loop subdivision [Loop 1987] on triangle meshes; split: 1-to-4 triangle split.
 *
 * - interior edge: 3/8 for its two ends, 1/8 for the two opposite vertices;
 * - interior vertex of valence n: \f$ (1 - n\beta_n) v + \beta_n \sum_i v_i \f$,
 *   with \f$\beta_n\f$ from `Beta` (`Loop_beta` by default, `Warren_beta`);
 * - border: the rules of the cubic B-spline (`Uniform_bspline_scheme` of
 *   degree 3, through `Border_curve_rule`) along the border polygon, so the
 *   border is a cubic B-spline curve of the border polygon: border edge, its
 *   midpoint; border vertex, 1/8, 6/8, 1/8 with its two border neighbours; a
 *   border vertex with a single face keeps that rule or, with
 *   `Border_corners::sharp`, stays in place.
 *
 * \tparam Mesh a model of `FaceGraph`
 * \tparam FT the number type of the weights (by default the mesh's)
 * \tparam Beta `Loop_beta` or `Warren_beta`
 * \tparam Tagged whether the mask refines with the sharpness tags of a level
 * (`With_sharp_rules`): `subdivide()` makes such copies, users leave it false
 * \cgalModels `SurfaceSubdivisionMask`
 */
template <class Mesh, class FT = internal::Mesh_FT<Mesh>, class Beta = Loop_beta, bool Tagged = false>
class Loop_mask : public With_sharp_rules<Loop_mask<Mesh, FT, Beta, Tagged>, Mesh, FT, Tagged>
{
public:
  using Polygon_mesh = Mesh;
  using Number_type = FT;
  static constexpr Split split = Split::triangle_quadrisection;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  explicit Loop_mask(Border_corners corners = Border_corners::smooth)
    : With_sharp_rules<Loop_mask, Mesh, FT, Tagged>(Uniform_bspline_scheme<FT>(3)), m_corners(corners)
  {}

  /// the same rules, with the same options, for another mesh type and number
  /// type (without the tags of a level)
  template <class OtherMesh, class OtherFT, bool OtherTagged = false>
  Loop_mask<OtherMesh, OtherFT, Beta, OtherTagged> rebind() const
  {
    return Loop_mask<OtherMesh, OtherFT, Beta, OtherTagged>(m_corners);
  }

  std::string name() const { return "Loop (" + Beta::name() + " beta)"; }
  Border_corners border_corners() const { return m_corners; }
  /// the same rules with border corners `corners` (the face-varying limit
  /// cuts the mesh and keeps its corners by the face-varying mode)
  Loop_mask with_border_corners(Border_corners corners) const
  {
    Loop_mask copy(*this);
    copy.m_corners = corners;
    return copy;
  }
  bool is_interpolating() const { return false; }

  template <class Accumulator>
  void vertex_node(const Vertex_view<Mesh>& v, Accumulator& acc) const
  {
    this->m_sharp.vertex_node(v, acc, [&](auto& a) { smooth_vertex_point(v, a); });
  }

  template <class Accumulator>
  void edge_node(const Edge_view<Mesh>& e, Accumulator& acc) const
  {
    this->m_sharp.edge_node(e, acc, [&](auto& a) { smooth_edge_point(e, a); });
  }

private:
  template <class Accumulator>
  static void smooth_vertex_point(const Vertex_view<Mesh>& v, Accumulator& acc)
  {
    const int n = v.valence();
    const FT beta = Beta::template beta<FT>(n);
    acc.add(v.vertex(), FT(1) - FT(n) * beta);
    for(vertex_descriptor u : CGAL::vertices_around_target(v.vertex(), v.mesh()))
      acc.add(u, beta);
  }

  template <class Accumulator>
  static void smooth_edge_point(const Edge_view<Mesh>& e, Accumulator& acc)
  {
    const Mesh& mesh = e.mesh();
    const halfedge_descriptor h = e.halfedge();
    acc.add(source(h, mesh), FT(3) / FT(8));
    acc.add(target(h, mesh), FT(3) / FT(8));
    acc.add(target(next(h, mesh), mesh), FT(1) / FT(8));
    acc.add(target(next(opposite(h, mesh), mesh), mesh), FT(1) / FT(8));
  }

  Border_corners m_corners;
};

/*!
 * \ingroup PkgSubdivMasks
 * Loop subdivision with Warren's rational weights (`Warren_beta`).
 */
template <class Mesh, class FT = internal::Mesh_FT<Mesh>>
using Loop_warren_mask = Loop_mask<Mesh, FT, Warren_beta>;

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_LOOP_MASK_H
