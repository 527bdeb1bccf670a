// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_TRIANGLE_QUADRISECTION_H
#define CGAL_SUBDIV_HOSTS_TRIANGLE_QUADRISECTION_H

#include <CGAL/Subdiv/hosts/Vertex_origin.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/internal/rebuild_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstddef>

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
 * Masks used: `vertex_node(mesh, v, acc)` and `edge_node(mesh, h, acc)`.
 */
template <class Mesh>
class Triangle_quadrisection
{
public:
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;

  static constexpr int required_face_size = 3;
  static double face_growth() { return 4; }
  /// the counts after one level
  static bool next_counts(internal::Mesh_counts& c)
  {
    c = internal::Mesh_counts{c.vertices + c.edges, 2 * c.edges + 3 * c.faces, 4 * c.faces, 12 * c.faces};
    return true;
  }

  explicit Triangle_quadrisection(const Mesh& mesh)
    : m_mesh(mesh), m_number(mesh), m_vertex_count(num_vertices(mesh)), m_edge_count(num_edges(mesh))
  {
  }

  std::size_t number_of_new_vertices() const { return m_vertex_count + m_edge_count; }
  std::size_t number_of_new_faces() const { return 4 * num_faces(m_mesh); }

  Vertex_origin origin(std::size_t j) const
  {
    return j < m_vertex_count ? Vertex_origin{Origin_kind::vertex, j}
                              : Vertex_origin{Origin_kind::edge, j - m_vertex_count};
  }

  /// calls visit(new index, report) for every new vertex; report(acc) makes the
  /// mask report that vertex's weights to `acc`. With a parallel `loop` (and a
  /// Surface_mesh), visit is called from several threads, once per vertex.
  template <class Mask, class Visitor, class Loop = internal::Parallel_loop>
  void for_each_new_vertex(const Mask& mask, Visitor&& visit, const Loop& loop = Loop()) const
  {
    internal::for_each_element(m_number, vertices(m_mesh), m_vertex_count, loop, [&](vertex_descriptor v) {
      visit(m_number(v), [&](auto& acc) { mask.vertex_node(m_mesh, v, acc); });
    });
    internal::for_each_element(m_number, edges(m_mesh), m_edge_count, loop, [&](auto e) {
      visit(m_vertex_count + m_number(e), [&](auto& acc) { mask.edge_node(m_mesh, halfedge(e, m_mesh), acc); });
    });
  }

  /// the new faces, with their parents
  internal::Face_soup faces() const { return faces(internal::Parallel_loop(1), true); }

  /// the new faces, written in parallel chunks by `loop` (Surface_mesh), with
  /// their parents or not
  template <class Loop>
  internal::Face_soup faces(const Loop& loop, bool parents) const
  {
    const std::size_t face_count = num_faces(m_mesh);
    internal::Face_soup soup(number_of_new_vertices(), 2 * m_edge_count + 3 * face_count);
    soup.resize_uniform(4 * face_count, 3, parents);
    internal::for_each_element(m_number, CGAL::faces(m_mesh), face_count, loop, [&](auto f) {
      const std::size_t parent = m_number(f);
      const halfedge_descriptor h[3] = {halfedge(f, m_mesh), next(halfedge(f, m_mesh), m_mesh),
                                        prev(halfedge(f, m_mesh), m_mesh)};
      std::size_t corner[3], middle[3], inner[3];
      for(int k = 0; k < 3; ++k) {
        corner[k] = m_number(target(h[k], m_mesh)); // h[k] runs from corner[k-1] to corner[k]
        middle[k] = edge_point(h[k]);
        // new edge from middle[k] to middle[k+1], inside the face
        inner[k] = 2 * (2 * m_edge_count + 3 * parent + static_cast<std::size_t>(k));
      }
      std::size_t c = 12 * parent;
      for(int k = 0; k < 3; ++k) { // corner triangle at corner[k]
        const int j = (k + 1) % 3;
        soup.set_corner(c++, middle[k], second_half(h[k]));
        soup.set_corner(c++, corner[k], first_half(h[j]));
        soup.set_corner(c++, middle[j], inner[k] ^ 1);
        soup.set_parent(4 * parent + static_cast<std::size_t>(k), parent);
      }
      for(int k = 0; k < 3; ++k) // middle triangle
        soup.set_corner(c++, middle[k], inner[k]);
      soup.set_parent(4 * parent + 3, parent);
    });
    return soup;
  }

private:
  std::size_t edge_point(halfedge_descriptor h) const { return m_vertex_count + m_number(edge(h, m_mesh)); }

  // The halves of old edge e are new edges 2e (from its halfedge's source to
  // the edge point) and 2e+1 (from the edge point to the target); as
  // halfedge ids, 4e and 4e+2 along halfedge(e), 4e+3 and 4e+1 against it.
  std::size_t first_half(halfedge_descriptor h) const
  {
    const std::size_t id = m_number(h); // 2e, or 2e+1 against halfedge(e)
    return (id & 1) == 0 ? 2 * id : 2 * id + 1;
  }
  std::size_t second_half(halfedge_descriptor h) const
  {
    const std::size_t id = m_number(h);
    return (id & 1) == 0 ? 2 * id + 2 : 2 * id - 1;
  }

  const Mesh& m_mesh;
  internal::Mesh_numbering<Mesh> m_number;
  std::size_t m_vertex_count;
  std::size_t m_edge_count;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_HOSTS_TRIANGLE_QUADRISECTION_H
