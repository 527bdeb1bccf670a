// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_LINEAR_QUAD_MASK_H
#define CGAL_SUBDIV_MASKS_LINEAR_QUAD_MASK_H

#include <CGAL/Subdiv/hosts/Quad_split.h>
#include <CGAL/Subdiv/internal/mesh_traits.h>
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
  using Number_type = FT;
  using Host = Quad_split<Mesh>;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;

  std::string name() const { return "linear (quad split)"; }
  bool is_interpolating() const { return true; }

  template <class Accumulator>
  void vertex_node(const Mesh&, vertex_descriptor v, Accumulator& acc) const
  {
    acc.add(v, FT(1));
  }

  template <class Accumulator>
  void edge_node(const Mesh& mesh, halfedge_descriptor h, Accumulator& acc) const
  {
    acc.add(source(h, mesh), FT(1) / FT(2));
    acc.add(target(h, mesh), FT(1) / FT(2));
  }

  template <class Accumulator>
  void face_node(const Mesh& mesh, face_descriptor f, Accumulator& acc) const
  {
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
