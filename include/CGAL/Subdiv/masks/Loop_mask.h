// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_LOOP_MASK_H
#define CGAL_SUBDIV_MASKS_LOOP_MASK_H

#include <CGAL/Subdiv/hosts/Triangle_quadrisection.h>
#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/masks/boundary_rules.h>
#include <CGAL/Subdiv/masks/loop_weights.h>

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
 * - border edge: its midpoint; border vertex: 1/8, 6/8, 1/8 with its two
 *   border neighbours (the cubic B-spline rules, so the border is a cubic
 *   B-spline curve of the border polygon); a border vertex with a single
 *   face keeps that rule or, with `Border_corners::sharp`, stays in place.
 *
 * \tparam Mesh a model of `FaceGraph`
 * \tparam FT the number type of the weights (by default the mesh's)
 * \tparam Beta `Loop_beta` or `Warren_beta`
 * \cgalModels `SurfaceSubdivisionMask`
 */
template <class Mesh, class FT = internal::Mesh_FT<Mesh>, class Beta = Loop_beta>
class Loop_mask
{
public:
  using Number_type = FT;
  using Host = Triangle_quadrisection<Mesh>;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;

  explicit Loop_mask(Border_corners corners = Border_corners::smooth) : m_corners(corners) {}

  std::string name() const { return "Loop (" + Beta::name() + " beta)"; }
  Border_corners border_corners() const { return m_corners; }
  bool is_interpolating() const { return false; }

  template <class Accumulator>
  void vertex_node(const Mesh& mesh, vertex_descriptor v, Accumulator& acc) const
  {
    const internal::Vertex_walk<Mesh> walk(v, mesh);
    if(walk.on_border()) {
      internal::border_vertex_rule<FT>(v, walk, m_corners, mesh, acc);
      return;
    }
    const int n = walk.valence;
    const FT beta = Beta::template beta<FT>(n);
    acc.add(v, FT(1) - FT(n) * beta);
    for(vertex_descriptor u : CGAL::vertices_around_target(v, mesh))
      acc.add(u, beta);
  }

  template <class Accumulator>
  void edge_node(const Mesh& mesh, halfedge_descriptor h, Accumulator& acc) const
  {
    if(CGAL::is_border_edge(h, mesh)) { // border edge
      acc.add(source(h, mesh), FT(1) / FT(2));
      acc.add(target(h, mesh), FT(1) / FT(2));
      return;
    }
    acc.add(source(h, mesh), FT(3) / FT(8));
    acc.add(target(h, mesh), FT(3) / FT(8));
    acc.add(target(next(h, mesh), mesh), FT(1) / FT(8));
    acc.add(target(next(opposite(h, mesh), mesh), mesh), FT(1) / FT(8));
  }

private:
  Border_corners m_corners;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_LOOP_MASK_H
