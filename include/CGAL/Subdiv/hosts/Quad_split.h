// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_QUAD_SPLIT_H
#define CGAL_SUBDIV_HOSTS_QUAD_SPLIT_H

#include <CGAL/Subdiv/hosts/Vertex_origin.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/internal/rebuild_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivHosts
 * The primal quad split (PQQ) of Catmull-Clark and linear quad subdivision,
 * on any polygon mesh: every edge gets an edge point, every face a face
 * point, and an n-gon (v_0, ..., v_{n-1}) becomes the n quads
 * (v_i, e_{i+1}, f, e_i), where e_i is the edge point of edge (v_{i-1}, v_i)
 * and f the face point.
 *
 * Numbering of the new vertices: the old vertices first, in the mesh's
 * iteration order, then one vertex per edge, in edge order, then one vertex
 * per face, in face order. Numbering of the new faces: n quads per old
 * n-gon, in face order; within a face, the quad at the target of
 * `halfedge(f)` first, then around the face.
 *
 * Counts: V' = V + E + F, E' = 2E + C, F' = C, where C is the number of face
 * corners (the sum of the face sizes), so the Euler characteristic is kept.
 *
 * Masks used: `vertex_node(mesh, v, acc)`, `edge_node(mesh, h, acc)` and
 * `face_node(mesh, f, acc)`.
 */
template <class Mesh>
class Quad_split
{
public:
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;

  static constexpr int required_face_size = 0;
  /// every face becomes as many quads as it has corners: 4 once all faces are quads
  static double face_growth() { return 4; }
  /// the counts after one level
  static bool next_counts(internal::Mesh_counts& c)
  {
    c = internal::Mesh_counts{c.vertices + c.edges + c.faces, 2 * c.edges + c.corners, c.corners, 4 * c.corners};
    return true;
  }

  explicit Quad_split(const Mesh& mesh)
    : m_mesh(mesh),
      m_number(mesh),
      m_vertex_count(num_vertices(mesh)),
      m_edge_count(num_edges(mesh)),
      m_face_count(num_faces(mesh)),
      m_corner_count(0)
  {
    for(halfedge_descriptor h : halfedges(mesh))
      if(!CGAL::is_border(h, mesh))
        ++m_corner_count;
  }

  std::size_t number_of_new_vertices() const { return m_vertex_count + m_edge_count + m_face_count; }
  std::size_t number_of_new_faces() const { return m_corner_count; }

  Vertex_origin origin(std::size_t j) const
  {
    if(j < m_vertex_count)
      return {Origin_kind::vertex, j};
    if(j < m_vertex_count + m_edge_count)
      return {Origin_kind::edge, j - m_vertex_count};
    return {Origin_kind::face, j - m_vertex_count - m_edge_count};
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
    internal::for_each_element(m_number, CGAL::faces(m_mesh), m_face_count, loop, [&](face_descriptor f) {
      visit(m_vertex_count + m_edge_count + m_number(f), [&](auto& acc) { mask.face_node(m_mesh, f, acc); });
    });
  }

  /*
   * New edges: 2e and 2e+1 are the halves of old edge e (as in
   * `Triangle_quadrisection`), then one inner edge per face corner, from the
   * edge point of the corner's incoming halfedge to the face point; corners
   * are counted in face order, around each face from `halfedge(f)`.
   */
  internal::Face_soup faces() const { return faces(internal::Parallel_loop(1), true); }

  /// the new faces, written in parallel chunks by `loop` (Surface_mesh), with
  /// their parents or not
  template <class Loop>
  internal::Face_soup faces(const Loop& loop, bool parents) const
  {
    internal::Face_soup soup(number_of_new_vertices(), 2 * m_edge_count + m_corner_count);
    soup.resize_uniform(m_corner_count, 4, parents);
    // corner ordinal of halfedge(f) for every face: a running sum of face sizes
    std::vector<internal::Face_soup::Index> first_corner;
    if(loop.is_parallel() && internal::Mesh_numbering<Mesh>::dense) {
      first_corner.resize(m_face_count);
      internal::for_each_element(m_number, CGAL::faces(m_mesh), m_face_count, loop, [&](face_descriptor f) {
        first_corner[m_number(f)] =
          static_cast<internal::Face_soup::Index>(CGAL::halfedges_around_face(halfedge(f, m_mesh), m_mesh).size());
      });
      std::size_t sum = 0;
      for(auto& c : first_corner) {
        const std::size_t size = c;
        c = static_cast<internal::Face_soup::Index>(sum);
        sum += size;
      }
    }
    const std::size_t first_inner = 2 * m_edge_count;
    std::size_t running = 0; // corner ordinal of halfedge(f), sequentially
    internal::for_each_element(m_number, CGAL::faces(m_mesh), m_face_count, loop, [&](face_descriptor f) {
      const std::size_t parent = m_number(f);
      const std::size_t face_point = m_vertex_count + m_edge_count + parent;
      const std::size_t corner = first_corner.empty() ? running : first_corner[parent];
      const halfedge_descriptor first = halfedge(f, m_mesh);
      halfedge_descriptor h = first; // h = h_i, running from v_{i-1} to v_i
      std::size_t c = corner;
      do {
        const halfedge_descriptor n = next(h, m_mesh);
        const std::size_t c_next = (n == first) ? corner : c + 1;
        soup.set_corner(4 * c, edge_point(h), second_half(h));
        soup.set_corner(4 * c + 1, m_number(target(h, m_mesh)), first_half(n));
        soup.set_corner(4 * c + 2, edge_point(n), 2 * (first_inner + c_next));
        soup.set_corner(4 * c + 3, face_point, 2 * (first_inner + c) + 1);
        soup.set_parent(c, parent);
        h = n;
        ++c;
      } while(h != first);
      if(first_corner.empty())
        running = c;
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
  std::size_t m_face_count;
  std::size_t m_corner_count;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_HOSTS_QUAD_SPLIT_H
