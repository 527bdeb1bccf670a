// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_SQRT3_SPLIT_H
#define CGAL_SUBDIV_HOSTS_SQRT3_SPLIT_H

#include <CGAL/Subdiv/hosts/Vertex_origin.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/refinement/Child_faces.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * Whether the border of `mesh` is due to be refined by the next sqrt3 step,
 * i.e. whether the mesh is the output of a sqrt3 step that left its border
 * alone (a "resting" step). Such a step puts its V_old old vertices first and
 * its face points last, and the three new faces of old face k at positions
 * 3k, 3k+1, 3k+2, each with face point V_old + k among its corners. So, with
 * V and F the numbers of vertices and faces now, F is a multiple of 3, the
 * vertices from V_old = V - F/3 on are the face points, and
 *   - face i has the face point V_old + i/3 (rounded down) among its corners,
 *     and at least one old vertex;
 *   - every border vertex is old;
 *   - no interior edge joins two old vertices (every old interior edge was
 *     flipped);
 *   - every face point has exactly three old neighbours (the corners of its
 *     old face).
 * The test reads the connectivity and the order of the elements, nothing
 * else, in one pass over the edges and one over the faces. The order part
 * keeps meshes that merely have the connectivity of a resting step's output
 * (CGAL's hedra_open.off, an octahedron without two faces, is one: two
 * triangles after a resting step) from being taken for one.
 */
template <class Mesh, class Numbering>
bool sqrt3_border_is_pending(const Mesh& mesh, const Numbering& number)
{
  const std::size_t vertex_count = num_vertices(mesh), face_count = num_faces(mesh);
  if(face_count % 3 != 0 || vertex_count < face_count / 3)
    return false;
  const std::size_t first_face_point = vertex_count - face_count / 3;
  std::vector<unsigned char> old_neighbours(face_count / 3, 0);
  for(auto e : edges(mesh)) {
    const auto h = halfedge(e, mesh);
    const std::size_t a = number(source(h, mesh)), b = number(target(h, mesh));
    const bool a_old = a < first_face_point, b_old = b < first_face_point;
    if(is_border_edge(h, mesh)) {
      if(!a_old || !b_old)
        return false; // a face point on the border
    } else if(a_old && b_old) {
      return false; // an unflipped old interior edge
    } else if(a_old != b_old) {
      unsigned char& count = old_neighbours[(a_old ? b : a) - first_face_point];
      if(++count > 3)
        return false;
    }
  }
  for(unsigned char count : old_neighbours)
    if(count != 3)
      return false;
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    const std::size_t corner[3] = {number(source(h, mesh)), number(target(h, mesh)),
                                   number(target(next(h, mesh), mesh))};
    const std::size_t expected = first_face_point + number(f) / 3;
    if(corner[0] != expected && corner[1] != expected && corner[2] != expected)
      return false;
    if(corner[0] >= first_face_point && corner[1] >= first_face_point && corner[2] >= first_face_point)
      return false;
  }
  return true;
}

} // namespace internal

/*!
 * \ingroup PkgSubdivHosts
 * One step of the sqrt3 split [Kobbelt 2000] of triangle meshes: a new vertex
 * (face point) in every triangle, joined to its three corners, and every old
 * interior edge flipped, so that it joins the face points of its two faces.
 * On a closed mesh the step makes V + F vertices and 3F triangles (two per
 * old edge); two steps split every triangle 1-to-9.
 *
 * <b>Border.</b> As in Kobbelt's paper, the border is refined only on every
 * second step, by a 1-to-3 split of every border edge, so that two steps
 * also split the border 1-to-3:
 *   - on a <em>resting</em> step, a triangle with a border edge keeps it: the
 *     face point is joined to the edge's ends without flip; border vertices
 *     use the mask's `resting_border_vertex_node`;
 *   - on a <em>refining</em> step, a triangle (t, s, c) with border edge
 *     (t, s) gets no face point: the edge gets two new vertices p1, p2
 *     (`border_edge_node(mesh, h, 1 or 2, acc)`, at one and two thirds of the
 *     way from t), the triangle is split into (t, p1, c), (p1, p2, c),
 *     (p2, s, c), and its edges (s, c), (c, t) are flipped as any old
 *     interior edge; border vertices use `border_vertex_node`.
 *
 * <b>Which step refines the border</b> is decided from the mesh itself, so
 * that it does not depend on how the levels are split across calls: a step
 * refines the border exactly when the mesh is the output of a resting step
 * (see `internal::sqrt3_border_is_pending` for the test, which reads the
 * connectivity and the order of the elements, as a resting step leaves them,
 * and nothing else). A mesh read from a file is thus rested first, as CGAL's
 * `Sqrt3_subdivision` does on the first level of every call; after that the
 * steps alternate, and one call with two iterations gives the same mesh as
 * two calls with one, also across a save and load that keep the order of the
 * elements. (CGAL's `Sqrt3_subdivision` restarts with a resting step at
 * every call, so one-level calls never refine the border.) If the elements
 * of a resting step's output are reordered, the border simply rests once
 * more. A mesh that has the connectivity and the element order of a resting
 * step's output (e.g. three triangles around a valence-3 vertex that comes
 * last) is taken as one, and its border is refined on the first step. Closed
 * meshes have no phase and need nothing.
 *
 * Numbering of the new vertices: the old vertices first, in the mesh's
 * iteration order; then one face point per face, in face order (on a
 * refining step, only for the faces without border edge); then, on a
 * refining step, two vertices per border edge, p1 then p2, in the order of
 * their faces. Numbering of the new faces: for every old face in face order,
 * for each of its halfedges h (from `halfedge(f)` on), the triangle
 * (target(h), face point of f, face point across h), or for a border
 * halfedge the kept border triangle (resting step) or the middle triangle
 * (p1, p2, c) (refining step).
 *
 * Masks used: `vertex_node(Vertex_view, acc)` (interior vertices),
 * `face_node(Face_view, acc)`, `resting_border_vertex_node(Vertex_view, acc)`,
 * `border_vertex_node(Vertex_view, acc)` and `border_edge_node(Edge_view, k,
 * acc)` (the view of the face halfedge of the border edge, k = 1, 2).
 */
template <class Mesh>
class Sqrt3_split
{
public:
  using Polygon_mesh = Mesh;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;
  using Index = internal::Child_index;

  static constexpr int required_face_size = 3;
  /// for the analysis: the faces of the regular meshes, a neighbourhood
  /// centred at a vertex, and two host steps per analysed step (one sqrt3
  /// step rotates the neighbourhood by half a sector; two steps are the
  /// 1-to-9 split, which maps every ring onto itself), rings tripled. The
  /// matrix, its eigenvalues and the characteristic map are those of the
  /// double step S = S_2 S_1: the eigenvalues are the squares of the moduli
  /// of the single-step ones. At a border vertex the border is refined on
  /// every second step only: the double step is a resting step (the patch,
  /// built fresh, rests first, as a mesh read from a file) then a refining
  /// step; over the pair the border is split 1-to-3 and the neighbourhood is
  /// invariant.
  static constexpr int regular_face_size = 3;
  static constexpr bool face_centred = false;
  static constexpr int analysis_steps = 2;
  static constexpr int ring_growth = 3;
  static double face_growth() { return 3; }
  /// the peak memory of a refinement per output face, measured: the maximum
  /// resident size of `cgal-subdiv surface` over its output faces was
  /// 121 B (sqrt3, fandisk, 6 levels, 9.4 M faces); rounded up (doc/memory.md)
  static double peak_bytes_per_face() { return 125; }
  /// the counts after one level: not known in advance (false)
  static bool next_counts(internal::Mesh_counts&) { return false; }

  explicit Sqrt3_split(const Mesh& mesh)
    : m_mesh(mesh), m_number(mesh), m_vertex_count(num_vertices(mesh)), m_edge_count(num_edges(mesh)),
      m_face_count(num_faces(mesh))
  {
    // slots of the spokes (new edges from a face point to a corner): one per
    // face halfedge, and on a refining step one per border halfedge
    const std::size_t halfedge_count = 2 * m_edge_count;
    m_border_edges = halfedge_count - 3 * m_face_count; // each triangle has 3 halfedges
    if(m_border_edges == 0)
      return;
    m_refine_border = internal::sqrt3_border_is_pending(mesh, m_number);
    m_slot.assign(halfedge_count, 0);
    Index face_slot = 0, border_slot = static_cast<Index>(3 * m_face_count);
    for(halfedge_descriptor h : halfedges(mesh)) {
      if(is_border(h, mesh)) {
        m_slot[m_number(h)] = border_slot++;
      } else {
        m_slot[m_number(h)] = face_slot++;
      }
    }
    if(!m_refine_border)
      return;
    // refining: face points only for faces without border edge, then p1, p2
    m_face_vertex.resize(m_face_count);
    std::size_t point = m_vertex_count, border_point = m_vertex_count + m_face_count - m_border_edges;
    for(face_descriptor f : CGAL::faces(mesh)) {
      bool on_border = false;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
        if(is_border(opposite(h, mesh), mesh)) {
          on_border = true;
          m_edge_of_border_face.push_back(static_cast<Index>(m_number(edge(h, mesh))));
          m_border_halfedge_of_border_face.push_back(h);
        }
      if(on_border) {
        m_face_vertex[m_number(f)] = static_cast<Index>(border_point);
        border_point += 2;
      } else {
        m_face_of_point.push_back(static_cast<Index>(m_number(f)));
        m_face_vertex[m_number(f)] = static_cast<Index>(point++);
      }
    }
  }

  /// whether this step refines the border (always false on a closed mesh)
  bool refines_border() const { return m_refine_border; }

  std::size_t number_of_new_vertices() const
  {
    return m_vertex_count + m_face_count + (m_refine_border ? m_border_edges : 0);
  }
  std::size_t number_of_new_faces() const { return 3 * m_face_count; }
  std::size_t number_of_new_edges() const
  {
    return m_edge_count + 3 * m_face_count + (m_refine_border ? m_border_edges : 0);
  }

  /// face points have `Origin_kind::face`; on a refining step, both new
  /// vertices of a border edge have `Origin_kind::edge` and the edge's ordinal
  /// the ordinals of the old elements that the new ones are numbered by
  const internal::Mesh_numbering<Mesh>& numbering() const { return m_number; }

  Vertex_origin origin(std::size_t j) const
  {
    if(j < m_vertex_count)
      return {Origin_kind::vertex, j};
    if(!m_refine_border)
      return {Origin_kind::face, j - m_vertex_count};
    const std::size_t k = j - m_vertex_count;
    if(k < m_face_of_point.size())
      return {Origin_kind::face, m_face_of_point[k]};
    return {Origin_kind::edge, m_edge_of_border_face[(k - m_face_of_point.size()) / 2]};
  }

  /// the mask's weights of new vertex j (j < number_of_new_vertices()) to
  /// `acc`; reads only the old elements
  template <class Mask, class Accumulator>
  void report(std::size_t j, const Mask& mask, Accumulator& acc) const
  {
    if(j < m_vertex_count) {
      const Vertex_view<Mesh> view(m_mesh, m_number.vertex(j));
      if(!view.on_border())
        mask.vertex_node(view, acc);
      else if(m_refine_border)
        mask.border_vertex_node(view, acc);
      else
        mask.resting_border_vertex_node(view, acc);
      return;
    }
    const std::size_t k = j - m_vertex_count;
    if(!m_refine_border)
      return mask.face_node(Face_view<Mesh>(m_mesh, m_number.face(k)), acc);
    if(k < m_face_of_point.size())
      return mask.face_node(Face_view<Mesh>(m_mesh, m_number.face(m_face_of_point[k])), acc);
    // on a refining step, the two new vertices of a border edge: p1, then p2
    const std::size_t b = k - m_face_of_point.size();
    mask.border_edge_node(Edge_view<Mesh>(m_mesh, m_border_halfedge_of_border_face[b / 2]), 1 + int(b % 2), acc);
  }

  /// the new faces (made in this thread, whatever `loop`)
  internal::Face_soup child_faces(const internal::Parallel_loop&) const
  {
    internal::Face_soup soup(number_of_new_vertices(), number_of_new_edges());
    soup.reserve(3 * m_face_count, 9 * m_face_count);
    if(m_border_edges == 0)
      add_closed_faces(soup);
    else
      add_faces_with_border(soup);
    return soup;
  }

private:
  // Halfedge ids of the new mesh. New edge e (< E) replaces old edge e: the
  // flipped edge between the face points of its two faces, or the kept
  // border edge (on a refining step, the middle third of it); its halfedge
  // 2e or 2e+1 runs from the face point of the face of old halfedge 2e or
  // 2e+1 (so along the old halfedge for a kept border edge). Spoke s (one
  // per face halfedge h: from target(h) to the face point of face(h)) is new
  // edge E + s, halfedge 2(E+s) from the corner, 2(E+s)+1 to it.
  std::size_t spoke_out(std::size_t slot) const { return 2 * (m_edge_count + slot); }
  std::size_t spoke_in(std::size_t slot) const { return 2 * (m_edge_count + slot) + 1; }

  // closed mesh: every halfedge h has a face, and its slot is its own number
  void add_closed_faces(internal::Face_soup& soup) const
  {
    for(face_descriptor f : CGAL::faces(m_mesh)) {
      const std::size_t parent = m_number(f);
      const std::size_t centre = m_vertex_count + parent;
      halfedge_descriptor h = halfedge(f, m_mesh);
      for(int k = 0; k < 3; ++k, h = next(h, m_mesh)) {
        // (target(h), centre, centre across h): the flip of old edge h
        const halfedge_descriptor o = opposite(h, m_mesh);
        const std::size_t id = m_number(h);
        soup.corner(m_number(target(h, m_mesh)), spoke_out(id));
        soup.corner(centre, id);
        soup.corner(m_vertex_count + m_number(face(o, m_mesh)), spoke_in(m_number(prev(o, m_mesh))));
        soup.close_face(parent);
      }
    }
  }

  void add_faces_with_border(internal::Face_soup& soup) const
  {
    for(face_descriptor f : CGAL::faces(m_mesh)) {
      const std::size_t parent = m_number(f);
      halfedge_descriptor h = halfedge(f, m_mesh);
      for(int k = 0; k < 3; ++k, h = next(h, m_mesh)) {
        const halfedge_descriptor o = opposite(h, m_mesh);
        const std::size_t id = m_number(h);
        if(!is_border(o, m_mesh)) {
          soup.corner(m_number(target(h, m_mesh)), spoke_out(m_slot[id]));
          soup.corner(centre(h), id);
          soup.corner(centre(o), spoke_in(in_slot(o)));
          soup.close_face(parent);
        } else if(!m_refine_border) { // kept border triangle (source, target, centre)
          soup.corner(m_number(source(h, m_mesh)), id);
          soup.corner(m_number(target(h, m_mesh)), spoke_out(m_slot[id]));
          soup.corner(centre(h), spoke_in(m_slot[m_number(prev(h, m_mesh))]));
          soup.close_face(parent);
        } else { // middle triangle (p1, p2, c) of a split border edge h = (t, s)
          const std::size_t p1 = m_face_vertex[parent];
          soup.corner(p1, id);
          soup.corner(p1 + 1, spoke_in(m_slot[m_number(next(h, m_mesh))]));
          soup.corner(m_number(target(next(h, m_mesh), m_mesh)), spoke_out(m_slot[m_number(o)]));
          soup.close_face(parent);
        }
      }
    }
  }

  // the new vertex that plays the face point of face(h) for the flip of h's
  // edge: the face point, or on a refining step in a face with border edge
  // b = (t, s), p1 for the edge (c, t) and p2 for the edge (s, c)
  std::size_t centre(halfedge_descriptor h) const
  {
    if(!m_refine_border)
      return m_vertex_count + m_number(face(h, m_mesh));
    const std::size_t j = m_face_vertex[m_number(face(h, m_mesh))];
    if(j < m_vertex_count + m_face_of_point.size())
      return j;
    return is_border(opposite(prev(h, m_mesh), m_mesh), m_mesh) ? j + 1 : j;
  }

  // slot of the spoke from centre(h) to source(h): the spoke of prev(h), or
  // on a refining step, when next(h) is the border edge (t, s) and so h is
  // (c, t), the spoke (c, p1), which takes the slot of the border halfedge
  std::size_t in_slot(halfedge_descriptor h) const
  {
    if(m_refine_border) {
      const halfedge_descriptor b = opposite(next(h, m_mesh), m_mesh);
      if(is_border(b, m_mesh))
        return m_slot[m_number(b)];
    }
    return m_slot[m_number(prev(h, m_mesh))];
  }

  const Mesh& m_mesh;
  internal::Mesh_numbering<Mesh> m_number;
  std::size_t m_vertex_count;
  std::size_t m_edge_count;
  std::size_t m_face_count;
  std::size_t m_border_edges = 0;
  bool m_refine_border = false;
  std::vector<Index> m_slot;                // spoke slot of each halfedge (mesh with border)
  std::vector<Index> m_face_vertex;         // refining step: face point, or p1 of a border face
  std::vector<Index> m_face_of_point;       // refining step: the face of each face point
  std::vector<Index> m_edge_of_border_face; // refining step: the border edge of each border face
  std::vector<halfedge_descriptor>
    m_border_halfedge_of_border_face; // refining step: its border edge, as a face halfedge
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_HOSTS_SQRT3_SPLIT_H
