// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_LINEAR_TRIANGLE_MASK_H
#define CGAL_SUBDIV_MASKS_LINEAR_TRIANGLE_MASK_H

#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/views/Split.h>
#include <CGAL/Subdiv/views/Vertex_view.h>

#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivMasks
 * Linear subdivision of a triangle mesh: the 1-to-4 triangle split with no
 * smoothing. Old vertices keep their positions and every edge gets its
 * midpoint, so the refined mesh lies exactly on the old one (the same
 * surface, with four times as many triangles). Border edges are no different.
 *
 * \tparam Mesh a model of `FaceGraph`
 * \tparam FT the number type of the weights (by default the mesh's)
 * \cgalModels `SurfaceSubdivisionMask`
 */
template <class Mesh, class FT = internal::Mesh_FT<Mesh>>
class Linear_triangle_mask
{
public:
  using Polygon_mesh = Mesh;
  using Number_type = FT;
  static constexpr Split split = Split::triangle_quadrisection;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;

  Linear_triangle_mask() : m_half(FT(1) / FT(2)) {}

  /// the same rules for another mesh type and number type
  template <class OtherMesh, class OtherFT>
  Linear_triangle_mask<OtherMesh, OtherFT> rebind() const
  {
    return Linear_triangle_mask<OtherMesh, OtherFT>();
  }

  std::string name() const { return "linear triangle"; }
  bool is_interpolating() const { return true; }

  /// sharpness tags move no point of a linear scheme: the mask of a tagged
  /// level is this one, and `subdivide()` only carries the children's
  /// sharpness (and the holes) from level to level, as OpenSubdiv's bilinear
  /// scheme does
  const Linear_triangle_mask& with_sharp_level(const void* /* level */) const { return *this; }

  template <class Accumulator>
  void vertex_node(const Vertex_view<Mesh>& v, Accumulator& acc) const
  {
    acc.add(v.vertex(), FT(1));
  }

  template <class Accumulator>
  void edge_node(const Edge_view<Mesh>& e, Accumulator& acc) const
  {
    const Mesh& mesh = e.mesh();
    const halfedge_descriptor h = e.halfedge();
    acc.add(source(h, mesh), m_half);
    acc.add(target(h, mesh), m_half);
  }

private:
  FT m_half;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_LINEAR_TRIANGLE_MASK_H
