// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_LINEAR_QUAD_MASK_H
#define CGAL_SUBDIV_MASKS_LINEAR_QUAD_MASK_H

#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/views/Split.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/boost/graph/iterator.h>

#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivMasks
 * Linear (bilinear) subdivision on the quad split (`Quad_split`): the surface
 * does not move. Old vertices stay where they are, an edge point is the
 * edge's midpoint and a face point the average of the face's vertices (the
 * rules of OpenSubdiv's bilinear scheme and of CGAL's `Linear_mask_3`).
 * Interpolating, with rational weights: exact in an exact kernel.
 *
 * \tparam Mesh a model of `FaceGraph`
 * \tparam FT the number type of the weights (by default the mesh's)
 * \cgalModels `SurfaceSubdivisionMask`
 */
template <class Mesh, class FT = internal::Mesh_FT<Mesh>>
class Linear_quad_mask
{
public:
  using Polygon_mesh = Mesh;
  using Number_type = FT;
  static constexpr Split split = Split::quad;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;

  /// the same rules for another mesh type and number type
  template <class OtherMesh, class OtherFT>
  Linear_quad_mask<OtherMesh, OtherFT> rebind() const
  {
    return Linear_quad_mask<OtherMesh, OtherFT>();
  }

  std::string name() const { return "linear (quad split)"; }
  bool is_interpolating() const { return true; }

  /// sharpness tags move no point of a linear scheme: the mask of a tagged
  /// level is this one, and `subdivide()` only carries the children's
  /// sharpness (and the holes) from level to level, as OpenSubdiv's bilinear
  /// scheme does
  const Linear_quad_mask& with_sharp_level(const void* /* level */) const { return *this; }

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
    acc.add(source(h, mesh), FT(1) / FT(2));
    acc.add(target(h, mesh), FT(1) / FT(2));
  }

  template <class Accumulator>
  void face_node(const Face_view<Mesh>& view, Accumulator& acc) const
  {
    const Mesh& mesh = view.mesh();
    const face_descriptor f = view.face();
    int size = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      (void)h;
      ++size;
    }
    const FT weight = FT(1) / FT(size);
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      acc.add(target(h, mesh), weight);
  }
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_LINEAR_QUAD_MASK_H
