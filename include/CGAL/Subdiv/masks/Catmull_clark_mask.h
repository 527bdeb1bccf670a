// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_CATMULL_CLARK_MASK_H
#define CGAL_SUBDIV_MASKS_CATMULL_CLARK_MASK_H

#include <CGAL/Subdiv/curves/Uniform_bspline_scheme.h>
#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/masks/Sharp_rules.h>
#include <CGAL/Subdiv/views/Split.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivMasks
 * Catmull-Clark subdivision [Catmull and Clark 1978] on any polygon mesh;
 * split: the quad split (`Quad_split`), so one level makes an all-quad mesh.
 *
 * - face point: the average of the face's vertices;
 * - interior edge: \f$ \frac14 (v_0 + v_1 + f_0 + f_1) \f$, the average of its
 *   two ends and the face points of its two faces;
 * - interior vertex of valence n: \f$ \frac1n (F + 2R + (n-3) v) \f$, where F
 *   is the average of the face points of its n faces and R the average of
 *   the midpoints of its n edges;
 * - border edge: its midpoint; border vertex: 1/8, 6/8, 1/8 with its two
 *   border neighbours: the rules of the cubic B-spline (`Uniform_bspline_scheme`
 *   of degree 3, through `Border_curve_rule`), so the border converges to the
 *   cubic B-spline curve of the border polygon.
 *
 * The border rules are those of CGAL's `CatmullClark_mask_3` and of
 * OpenSubdiv with `VTX_BOUNDARY_EDGE_ONLY` (RenderMan "interpolateboundary
 * 2"), at every border vertex, including a corner of valence 2 (a vertex with
 * a single face): it gets 1/8, 6/8, 1/8 too, and so is not interpolated
 * (`Border_corners::smooth`, the default). With `Border_corners::sharp` such
 * a corner stays where it is (weight 1 on itself), as with OpenSubdiv's
 * `VTX_BOUNDARY_EDGE_AND_CORNER` (RenderMan "interpolateboundary 1");
 * everything else is the same (the tests check both against OpenSubdiv's
 * reference results). `Triangle_subdivision::smooth` changes the edge rule
 * next to triangles as OpenSubdiv's `TRI_SUB_SMOOTH` does.
 *
 * The mask reports weights over old vertices only: a face point's weights are
 * expanded into its vertices (1/|f| each), and the edge and vertex rules add
 * the face points of their faces scaled by their own factor. All weights are
 * rational, so an exact kernel refines exactly; on a regular quad grid the
 * rules are those of the bicubic uniform B-spline.
 *
 * \tparam Mesh a model of `FaceGraph`
 * \tparam FT the number type of the weights (by default the mesh's)
 * \tparam Tagged whether the mask refines with the sharpness tags of a level
 * (`With_sharp_rules`): `subdivide()` makes such copies, users leave it false
 * \cgalModels `SurfaceSubdivisionMask`
 */
template <class Mesh, class FT = internal::Mesh_FT<Mesh>, bool Tagged = false>
class Catmull_clark_mask : public With_sharp_rules<Catmull_clark_mask<Mesh, FT, Tagged>, Mesh, FT, Tagged>
{
public:
  using Polygon_mesh = Mesh;
  using Number_type = FT;
  static constexpr Split split = Split::quad;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;

  explicit Catmull_clark_mask(Border_corners corners = Border_corners::smooth,
                              Triangle_subdivision triangles = Triangle_subdivision::catmark)
    : With_sharp_rules<Catmull_clark_mask, Mesh, FT, Tagged>(Uniform_bspline_scheme<FT>(3)), m_corners(corners),
      m_triangles(triangles)
  {}

  /// the same rules, with the same options, for another mesh type and number
  /// type (without the tags of a level)
  template <class OtherMesh, class OtherFT, bool OtherTagged = false>
  Catmull_clark_mask<OtherMesh, OtherFT, OtherTagged> rebind() const
  {
    return Catmull_clark_mask<OtherMesh, OtherFT, OtherTagged>(m_corners, m_triangles);
  }

  std::string name() const { return "Catmull-Clark"; }
  Border_corners border_corners() const { return m_corners; }
  /// the same rules with border corners `corners` (the face-varying limit
  /// cuts the mesh and keeps its corners by the face-varying mode)
  Catmull_clark_mask with_border_corners(Border_corners corners) const
  {
    Catmull_clark_mask copy(*this);
    copy.m_corners = corners;
    return copy;
  }
  Triangle_subdivision triangle_subdivision() const { return m_triangles; }
  bool is_interpolating() const { return false; }

  template <class Accumulator>
  void face_node(const Face_view<Mesh>& f, Accumulator& acc) const
  {
    add_face_point(f.mesh(), f.halfedge(), FT(1), acc);
  }

  template <class Accumulator>
  void edge_node(const Edge_view<Mesh>& e, Accumulator& acc) const
  {
    this->m_sharp.edge_node(e, acc, [&](auto& a) { smooth_edge_point(e, a); });
  }

  template <class Accumulator>
  void vertex_node(const Vertex_view<Mesh>& view, Accumulator& acc) const
  {
    this->m_sharp.vertex_node(view, acc, [&](auto& a) { smooth_vertex_point(view, a); });
  }

private:
  template <class Accumulator>
  void smooth_edge_point(const Edge_view<Mesh>& e, Accumulator& acc) const
  {
    const Mesh& mesh = e.mesh();
    const halfedge_descriptor h = e.halfedge();
    // Catmark: every weight is 1/4; the smooth triangle rule moves weight from the ends to a triangle's face point
    FT face_weight = FT(1) / FT(4);
    FT end_weight = face_weight;
    if(m_triangles == Triangle_subdivision::smooth && touches_triangle(mesh, h)) {
      face_weight = (triangle_face_weight(mesh, h) + triangle_face_weight(mesh, opposite(h, mesh))) / FT(2);
      end_weight = (FT(1) - FT(2) * face_weight) / FT(2);
    }
    acc.add(source(h, mesh), end_weight);
    acc.add(target(h, mesh), end_weight);
    add_face_point(mesh, h, face_weight, acc);
    add_face_point(mesh, opposite(h, mesh), face_weight, acc);
  }

  static bool is_triangle(const Mesh& mesh, halfedge_descriptor h)
  {
    return next(next(next(h, mesh), mesh), mesh) == h;
  }
  static bool touches_triangle(const Mesh& mesh, halfedge_descriptor h)
  {
    return is_triangle(mesh, h) || is_triangle(mesh, opposite(h, mesh));
  }
  // the weight of the face point of face(h) in the edge rule of `Triangle_subdivision::smooth`
  static FT triangle_face_weight(const Mesh& mesh, halfedge_descriptor h)
  {
    return is_triangle(mesh, h) ? FT(47) / FT(100) : FT(1) / FT(4);
  }

  template <class Accumulator>
  static void smooth_vertex_point(const Vertex_view<Mesh>& view, Accumulator& acc)
  {
    const Mesh& mesh = view.mesh();
    const vertex_descriptor v = view.vertex();
    const int n = view.valence();
    // (F + 2R + (n-3) v) / n with F = (1/n) sum of face points and
    // 2R = (1/n) sum (v + u) over the neighbours u
    // v gets (n-3)/n from itself and n * 1/n^2 from its edge midpoints
    const FT per_face = FT(1) / FT(n * n);
    acc.add(v, FT(n - 2) / FT(n));
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, mesh)) {
      acc.add(source(h, mesh), per_face);
      add_face_point(mesh, h, per_face, acc);
    }
  }

  // adds s times the face point of face(h): s/|f| for each vertex of the face
  // (one walk around faces of up to 8 corners, which are kept on the way)
  template <class Accumulator>
  static void add_face_point(const Mesh& mesh, halfedge_descriptor h, const FT& s, Accumulator& acc)
  {
    constexpr int kept = 8;
    vertex_descriptor corners[kept];
    int size = 0;
    halfedge_descriptor g = h;
    do {
      if(size < kept)
        corners[size] = target(g, mesh);
      ++size;
      g = next(g, mesh);
    } while(g != h);
    const FT weight = s / FT(size);
    if(size <= kept) {
      for(int i = 0; i < size; ++i)
        acc.add(corners[i], weight);
      return;
    }
    for(halfedge_descriptor around : CGAL::halfedges_around_face(h, mesh))
      acc.add(target(around, mesh), weight);
  }

  Border_corners m_corners;
  Triangle_subdivision m_triangles;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_CATMULL_CLARK_MASK_H
