// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_QUAD_SPLIT_H
#define CGAL_SUBDIV_HOSTS_QUAD_SPLIT_H

#include <CGAL/Subdiv/hosts/Host_for.h>
#include <CGAL/Subdiv/hosts/Vertex_origin.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/refinement/Child_faces.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <utility>
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
 * Masks used: `vertex_node(Vertex_view, acc)`, `edge_node(Edge_view, acc)`
 * (the view of `halfedge(e)`) and `face_node(Face_view, acc)`.
 */
template <class Mesh>
class Quad_split
{
public:
  using Polygon_mesh = Mesh;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;

  static constexpr int required_face_size = 0;
  /// for the analysis: the faces of the regular meshes, a neighbourhood
  /// centred at a vertex, one host step per analysed step, rings doubled
  static constexpr int regular_face_size = 4;
  static constexpr bool face_centred = false;
  static constexpr int analysis_steps = 1;
  static constexpr int ring_growth = 2;
  /// every face becomes as many quads as it has corners: 4 once all faces are quads
  static double face_growth() { return 4; }
  /// the peak memory of a refinement per output face, measured: the maximum
  /// resident size of `cgal-subdiv surface` over its output faces was
  /// 121 B (Catmull-Clark, fandisk, 5 levels, 9.9 M faces); rounded up (doc/memory.md)
  static double peak_bytes_per_face() { return 125; }
  /// the counts after one level
  static bool next_counts(internal::Mesh_counts& c)
  {
    c = internal::Mesh_counts{c.vertices + c.edges + c.faces, 2 * c.edges + c.corners, c.corners, 4 * c.corners};
    return true;
  }

  explicit Quad_split(const Mesh& mesh)
    : m_mesh(mesh), m_number(mesh), m_vertex_count(num_vertices(mesh)), m_edge_count(num_edges(mesh)),
      m_face_count(num_faces(mesh)), m_corner_count(0)
  {
    for(halfedge_descriptor h : halfedges(mesh))
      if(!CGAL::is_border(h, mesh))
        ++m_corner_count;
  }

  /// the new faces are quads
  static constexpr int new_face_size = 4;

  std::size_t number_of_new_vertices() const { return m_vertex_count + m_edge_count + m_face_count; }
  std::size_t number_of_new_edges() const { return 2 * m_edge_count + m_corner_count; }
  std::size_t number_of_new_faces() const { return m_corner_count; }

  /// the ordinals of the old elements that the new ones are numbered by
  const internal::Mesh_numbering<Mesh>& numbering() const { return m_number; }

  Vertex_origin origin(std::size_t j) const
  {
    if(j < m_vertex_count)
      return {Origin_kind::vertex, j};
    if(j < m_vertex_count + m_edge_count)
      return {Origin_kind::edge, j - m_vertex_count};
    return {Origin_kind::face, j - m_vertex_count - m_edge_count};
  }

  /// the mask's weights of new vertex j (j < number_of_new_vertices()) to
  /// `acc`; reads only the old elements (and the counts taken at construction)
  template <class Mask, class Accumulator>
  void report(std::size_t j, const Mask& mask, Accumulator& acc) const
  {
    if(j < m_vertex_count)
      mask.vertex_node(vertex_view(mask, m_mesh, m_number.vertex(j)), acc);
    else if(j < m_vertex_count + m_edge_count)
      mask.edge_node(edge_view(mask, m_mesh, m_number.halfedge(2 * (j - m_vertex_count))), acc);
    else
      mask.face_node(face_view(mask, m_mesh, m_number.face(j - m_vertex_count - m_edge_count)), acc);
  }

  /*
   * The new faces, made from a snapshot of the corners of the old faces,
   * counted in face order, around each face from `halfedge(f)` (the running
   * sum of the face sizes: made in two passes when parallel); in parallel
   * chunks by `loop` (Surface_mesh). Reads only the old elements.
   */
  internal::Split_faces<Quad_split> child_faces(const internal::Parallel_loop& loop) const
  {
    using Index = internal::Child_index;
    internal::check_child_counts(number_of_new_vertices(), number_of_new_edges());
    internal::Split_snapshot s;
    s.face_count = m_face_count;
    s.face_size = 0;
    s.corners.resize_for_overwrite(m_corner_count);
    s.first_corner.resize_for_overwrite(m_face_count + 1);
    // writes the corners of face f from s.first_corner[f]; returns how many
    const auto write_corners = [&](std::size_t f) {
      const halfedge_descriptor first = halfedge(m_number.face(f), m_mesh);
      halfedge_descriptor h = first;
      std::size_t c = s.first_corner[f];
      do {
        s.corners[c++] = {static_cast<Index>(m_number(h)), static_cast<Index>(m_number(target(h, m_mesh)))};
        h = next(h, m_mesh);
      } while(h != first);
      return c - s.first_corner[f];
    };
    if(loop.is_parallel() && internal::Mesh_numbering<Mesh>::dense) {
      internal::for_each_ordinal(m_number, m_face_count, loop, [&](std::size_t f) {
        std::size_t size = 0;
        const halfedge_descriptor first = halfedge(m_number.face(f), m_mesh);
        halfedge_descriptor h = first;
        do {
          ++size;
          h = next(h, m_mesh);
        } while(h != first);
        s.first_corner[f] = static_cast<Index>(size);
      });
      std::size_t sum = 0;
      for(std::size_t f = 0; f < m_face_count; ++f) {
        const std::size_t size = s.first_corner[f];
        s.first_corner[f] = static_cast<Index>(sum);
        sum += size;
      }
      internal::for_each_ordinal(m_number, m_face_count, loop, write_corners);
    } else { // in face order, in this thread
      std::size_t running = 0;
      for(std::size_t f = 0; f < m_face_count; ++f) {
        s.first_corner[f] = static_cast<Index>(running);
        running += write_corners(f);
      }
    }
    s.first_corner[m_face_count] = static_cast<Index>(m_corner_count);
    if(m_corner_count != 2 * m_edge_count)
      internal::snapshot_border(m_mesh, m_number, 2 * m_edge_count, s);
    return internal::Split_faces<Quad_split>(*this, std::move(s));
  }

  /*
   * calls emit(new face, corners) for the quads of old face `parent` (4
   * corners each: new vertex, new halfedge id to the next corner), from the
   * snapshot: quad c (the old corner ordinal) is (e_c, v_c, e_n, f) for the
   * old halfedge h_c into old vertex v_c, the next corner n, edge points e
   * and the face point f. New edges: 2e and 2e+1 are the halves of old edge
   * e (as in `Triangle_quadrisection`), then one inner edge per old corner,
   * from the edge point of the corner's incoming halfedge to the face point.
   */
  template <class Emit>
  void for_each_new_face(const internal::Split_snapshot& s, std::size_t parent, const Emit& emit) const
  {
    using Index = internal::Child_index;
    using Corner = internal::Face_corner;
    const std::size_t begin = s.begin(parent), end = s.end(parent);
    const Index face_point = static_cast<Index>(m_vertex_count + m_edge_count + parent);
    const std::size_t first_inner = 2 * m_edge_count;
    for(std::size_t c = begin; c < end; ++c) {
      const std::size_t n = (c + 1 == end) ? begin : c + 1;
      const internal::Split_snapshot::Corner h = s.corners[c], h_next = s.corners[n];
      const Corner quad[4] = {
        {static_cast<Index>(m_vertex_count + (h.halfedge >> 1)), static_cast<Index>(internal::second_half(h.halfedge))},
        {h.target, static_cast<Index>(internal::first_half(h_next.halfedge))},
        {static_cast<Index>(m_vertex_count + (h_next.halfedge >> 1)), static_cast<Index>(2 * (first_inner + n))},
        {face_point, static_cast<Index>(2 * (first_inner + c) + 1)}};
      emit(c, quad);
    }
  }

private:
  const Mesh& m_mesh;
  internal::Mesh_numbering<Mesh> m_number;
  std::size_t m_vertex_count;
  std::size_t m_edge_count;
  std::size_t m_face_count;
  std::size_t m_corner_count;
};

/// `Split::quad` is refined by `Quad_split`
template <class Mesh>
struct Host_for<Split::quad, Mesh>
{
  using type = Quad_split<Mesh>;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_HOSTS_QUAD_SPLIT_H
