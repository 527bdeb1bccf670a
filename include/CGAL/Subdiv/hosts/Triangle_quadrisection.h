// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_TRIANGLE_QUADRISECTION_H
#define CGAL_SUBDIV_HOSTS_TRIANGLE_QUADRISECTION_H

#include <CGAL/Subdiv/hosts/Host_for.h>
#include <CGAL/Subdiv/hosts/Vertex_origin.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/refinement/Child_faces.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstddef>
#include <utility>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivHosts
 * The 1-to-4 triangle split (primal triangle quadrisection, PTQ) of Loop,
 * butterfly and linear subdivision: every edge gets a new vertex, every
 * triangle (a, b, c) becomes (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca).
 *
 * Numbering of the new vertices: the old vertices first, in the mesh's
 * iteration order, then one vertex per edge, in edge order. Numbering of the
 * new faces: four per old face, in face order, the corner triangles at a, b, c
 * first and the middle triangle last.
 *
 * Masks used: `vertex_node(Vertex_view, acc)` and `edge_node(Edge_view, acc)`
 * (the view of `halfedge(e)`).
 */
template <class Mesh>
class Triangle_quadrisection
{
public:
  using Polygon_mesh = Mesh;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;

  static constexpr int required_face_size = 3;
  /// for the analysis: the faces of the regular meshes, a neighbourhood
  /// centred at a vertex, one host step per analysed step, rings doubled
  static constexpr int regular_face_size = 3;
  static constexpr bool face_centred = false;
  static constexpr int analysis_steps = 1;
  static constexpr int ring_growth = 2;
  static double face_growth() { return 4; }
  /// the peak memory of a refinement per output face, measured: the maximum
  /// resident size of `cgal-subdiv surface` over its output faces was
  /// 84 B (Loop, fandisk, 5 levels, 13.3 M faces); rounded up (doc/memory.md)
  static double peak_bytes_per_face() { return 90; }
  /// the counts after one level
  static bool next_counts(internal::Mesh_counts& c)
  {
    c = internal::Mesh_counts{c.vertices + c.edges, 2 * c.edges + 3 * c.faces, 4 * c.faces, 12 * c.faces};
    return true;
  }

  /// the new faces are triangles
  static constexpr int new_face_size = 3;

  explicit Triangle_quadrisection(const Mesh& mesh)
    : m_mesh(mesh), m_number(mesh), m_vertex_count(num_vertices(mesh)), m_edge_count(num_edges(mesh)),
      m_face_count(num_faces(mesh))
  {}

  std::size_t number_of_new_vertices() const { return m_vertex_count + m_edge_count; }
  std::size_t number_of_new_edges() const { return 2 * m_edge_count + 3 * m_face_count; }
  std::size_t number_of_new_faces() const { return 4 * m_face_count; }

  /// the ordinals of the old elements that the new ones are numbered by
  const internal::Mesh_numbering<Mesh>& numbering() const { return m_number; }

  Vertex_origin origin(std::size_t j) const
  {
    return j < m_vertex_count ? Vertex_origin{Origin_kind::vertex, j}
                              : Vertex_origin{Origin_kind::edge, j - m_vertex_count};
  }

  /// the mask's weights of new vertex j (j < number_of_new_vertices()) to
  /// `acc`; reads only the old elements (and the counts taken at construction)
  template <class Mask, class Accumulator>
  void report(std::size_t j, const Mask& mask, Accumulator& acc) const
  {
    if(j < m_vertex_count)
      mask.vertex_node(vertex_view(mask, m_mesh, m_number.vertex(j)), acc);
    else
      mask.edge_node(edge_view(mask, m_mesh, m_number.halfedge(2 * (j - m_vertex_count))), acc);
  }

  /// the new faces, made from a snapshot of the old mesh's faces (in parallel
  /// chunks by `loop` on a Surface_mesh); reads only the old elements
  internal::Split_faces<Triangle_quadrisection> child_faces(const internal::Parallel_loop& loop) const
  {
    using Index = internal::Child_index;
    internal::check_child_counts(number_of_new_vertices(), number_of_new_edges());
    internal::Split_snapshot s;
    s.face_count = m_face_count;
    s.face_size = 3;
    s.corners.resize_for_overwrite(3 * m_face_count);
    internal::for_each_ordinal(m_number, m_face_count, loop, [&](std::size_t f) {
      halfedge_descriptor h = halfedge(m_number.face(f), m_mesh);
      for(std::size_t k = 0; k < 3; ++k, h = next(h, m_mesh))
        s.corners[3 * f + k] = {static_cast<Index>(m_number(h)), static_cast<Index>(m_number(target(h, m_mesh)))};
    });
    if(3 * m_face_count != 2 * m_edge_count)
      internal::snapshot_border(m_mesh, m_number, 2 * m_edge_count, s);
    return internal::Split_faces<Triangle_quadrisection>(*this, std::move(s));
  }

  /*
   * calls emit(new face, corners) for the four new faces of old face
   * `parent` (3 corners each: new vertex, new halfedge id to the next
   * corner), from the snapshot. With halfedges h_k of the old face (h_0 =
   * halfedge(f), h_k running from corner k-1 to corner k), edge points m_k
   * on them and inner edges from m_k to m_k+1 (new edges 2E + 3 parent + k):
   * the corner triangles (m_k, c_k, m_k+1), then the middle one.
   */
  template <class Emit>
  void for_each_new_face(const internal::Split_snapshot& s, std::size_t parent, const Emit& emit) const
  {
    using Index = internal::Child_index;
    using Corner = internal::Face_corner;
    const internal::Split_snapshot::Corner* h = &s.corners[3 * parent];
    Index corner[3], middle[3], inner[3], first[3], second[3];
    for(std::size_t k = 0; k < 3; ++k) {
      corner[k] = h[k].target;
      middle[k] = static_cast<Index>(m_vertex_count + (h[k].halfedge >> 1));
      inner[k] = static_cast<Index>(2 * (2 * m_edge_count + 3 * parent + k));
      first[k] = static_cast<Index>(internal::first_half(h[k].halfedge));
      second[k] = static_cast<Index>(internal::second_half(h[k].halfedge));
    }
    for(std::size_t k = 0; k < 3; ++k) { // corner triangle at corner[k]
      const std::size_t j = (k + 1) % 3;
      const Corner c[3] = {{middle[k], second[k]}, {corner[k], first[j]}, {middle[j], inner[k] ^ 1}};
      emit(4 * parent + k, c);
    }
    const Corner c[3] = {{middle[0], inner[0]}, {middle[1], inner[1]}, {middle[2], inner[2]}}; // middle triangle
    emit(4 * parent + 3, c);
  }

private:
  const Mesh& m_mesh;
  internal::Mesh_numbering<Mesh> m_number;
  std::size_t m_vertex_count;
  std::size_t m_edge_count;
  std::size_t m_face_count;
};

/// `Split::triangle_quadrisection` is refined by `Triangle_quadrisection`
template <class Mesh>
struct Host_for<Split::triangle_quadrisection, Mesh>
{
  using type = Triangle_quadrisection<Mesh>;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_HOSTS_TRIANGLE_QUADRISECTION_H
