// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_SQRT3_SPLIT_H
#define CGAL_SUBDIV_HOSTS_SQRT3_SPLIT_H

#include <CGAL/Subdiv/hosts/Host_for.h>
#include <CGAL/Subdiv/hosts/Vertex_origin.h>
#include <CGAL/Subdiv/hosts/sqrt3_border_phase.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/refinement/Child_faces.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

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
 * meshes without creases have no phase and need nothing.
 *
 * <b>Creases.</b> Made with a mask that carries the sharpness tags of its
 * level (`subdivide()` makes it so), the step refines every sharp edge as a
 * border edge on both of its sides: it is not flipped; on a resting step
 * each of its two triangles keeps it; on a refining step its two new
 * vertices p1, p2 (`border_edge_node`, along the halfedge of the face met
 * first) are shared by both sides, each triangle is split as a border
 * triangle, and its three thirds are its children (`edge_parents()`). A
 * vertex whose rule is crease or corner takes the border vertex rules, a
 * dart the interior one. The counts are those above: a crease edge adds two
 * vertices where its two faces lose their face points.
 *
 * Numbering of the new vertices: the old vertices first, in the mesh's
 * iteration order; then one face point per face, in face order (on a
 * refining step, only for the faces without border or sharp edge); then, on
 * a refining step, two vertices per border or sharp edge, p1 then p2, in the
 * order of their (first) faces. Numbering of the new faces: for every old face in face order,
 * for each of its halfedges h (from `halfedge(f)` on), the triangle
 * (target(h), face point of f, face point across h), or for a border
 * halfedge the kept border triangle (resting step) or the middle triangle
 * (p1, p2, c) (refining step).
 *
 * Masks used (with the views of `vertex_view()` and `edge_view()`, which
 * carry the tags of a tagged mask): `vertex_node(Vertex_view, acc)` (interior vertices),
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

  explicit Sqrt3_split(const Mesh& mesh) : Sqrt3_split(mesh, std::vector<unsigned char>()) {}

  /// the step with the sharpness tags of `mask`'s level, if it is a tagged
  /// copy: a sharp edge is refined as a border edge on both of its sides
  template <class Mask>
  Sqrt3_split(const Mesh& mesh, const Mask& mask) : Sqrt3_split(mesh, sharp_edges(mesh, mask))
  {}

private:
  // the sharp edges (by ordinal, border edges included) of a tagged mask's level; none otherwise
  template <class Mask>
  static std::vector<unsigned char> sharp_edges(const Mesh& mesh, const Mask& mask)
  {
    std::vector<unsigned char> sharp;
    if constexpr(internal::Refines_with_tags<Mask>::value) {
      sharp.resize(num_edges(mesh));
      for(std::size_t e = 0; e < sharp.size(); ++e)
        sharp[e] = mask.sharp_level()->is_sharp_edge(e) ? 1 : 0;
    } else
      (void)mesh, (void)mask;
    return sharp;
  }

  Sqrt3_split(const Mesh& mesh, std::vector<unsigned char> sharp)
    : m_mesh(mesh), m_number(mesh), m_vertex_count(num_vertices(mesh)), m_edge_count(num_edges(mesh)),
      m_face_count(num_faces(mesh)), m_sharp(std::move(sharp))
  {
    // slots of the spokes (new edges from a face point to a corner): one per
    // face halfedge, and on a refining step one per border halfedge
    const std::size_t halfedge_count = 2 * m_edge_count;
    m_border_edges = halfedge_count - 3 * m_face_count; // each triangle has 3 halfedges
    std::size_t crease_edges = 0;
    for(std::size_t e = 0; e < m_sharp.size(); ++e)
      crease_edges += m_sharp[e] != 0 ? 1 : 0;
    crease_edges -= m_sharp.empty() ? 0 : m_border_edges; // the border edges are sharp
    if(crease_edges == 0)
      m_sharp.clear(); // the border alone: as without tags
    if(m_border_edges == 0 && crease_edges == 0)
      return;
    m_refine_border = internal::sqrt3_border_is_pending(
      mesh, m_number,
      [&](typename boost::graph_traits<Mesh>::edge_descriptor e) { return cut_edge(halfedge(e, mesh)); });
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
    // refining: face points only for the faces without a cut edge (a border
    // or sharp edge; they have one at most, see sqrt3_border_is_pending),
    // then p1, p2 for every cut edge, in the order of its first face; the two
    // faces of a crease share them
    const std::size_t cut_faces = m_border_edges + 2 * crease_edges;
    m_face_vertex.resize(m_face_count);
    m_second_vertex.resize(m_face_count);
    std::vector<Index> pair_of_edge(crease_edges == 0 ? 0 : m_edge_count, 0);
    std::size_t point = m_vertex_count, pair_point = m_vertex_count + m_face_count - cut_faces;
    for(face_descriptor f : CGAL::faces(mesh)) {
      const std::size_t k = m_number(f);
      halfedge_descriptor cut = boost::graph_traits<Mesh>::null_halfedge();
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
        if(cut_edge(h))
          cut = h;
      if(cut == boost::graph_traits<Mesh>::null_halfedge()) {
        m_face_of_point.push_back(static_cast<Index>(k));
        m_face_vertex[k] = static_cast<Index>(point++);
        continue;
      }
      const std::size_t e = m_number(cut) >> 1;
      if(!pair_of_edge.empty() && pair_of_edge[e] != 0) { // the second face of a crease: p1 and p2 swap
        m_face_vertex[k] = pair_of_edge[e] + 1;
        m_second_vertex[k] = pair_of_edge[e];
        continue;
      }
      if(!pair_of_edge.empty())
        pair_of_edge[e] = static_cast<Index>(pair_point);
      m_edge_of_pair.push_back(static_cast<Index>(e));
      m_halfedge_of_pair.push_back(cut);
      m_face_vertex[k] = static_cast<Index>(pair_point);
      m_second_vertex[k] = static_cast<Index>(pair_point + 1);
      pair_point += 2;
    }
  }

public:
  /// whether this step refines the border (and the creases; always false on
  /// a closed mesh without creases)
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
    return {Origin_kind::edge, m_edge_of_pair[(k - m_face_of_point.size()) / 2]};
  }

  /// the old edge that each new edge is a child of, by new edge: e + 1 for
  /// old edge e, 0 for none (what `internal::Sharpness_writer` reads). The
  /// kept border or sharp edge e (on a refining step, its middle third) is
  /// new edge e; on a refining step the third at t of the face halfedge
  /// (t, s) of a cut edge is the spoke of the slot of its prev (one per
  /// side), and the third at s of a border edge the spoke of its own slot.
  std::vector<std::size_t> edge_parents() const
  {
    std::vector<std::size_t> parents(number_of_new_edges(), 0);
    if(m_slot.empty())
      return parents;
    for(halfedge_descriptor h : halfedges(m_mesh)) {
      if(is_border(h, m_mesh) || !cut_edge(h))
        continue;
      const std::size_t e = m_number(h) >> 1;
      parents[e] = e + 1;
      if(!m_refine_border)
        continue;
      parents[m_edge_count + m_slot[m_number(prev(h, m_mesh))]] = e + 1;
      if(is_border(opposite(h, m_mesh), m_mesh))
        parents[m_edge_count + m_slot[m_number(h)]] = e + 1;
    }
    return parents;
  }

  /// the mask's weights of new vertex j (j < number_of_new_vertices()) to
  /// `acc`; reads only the old elements
  template <class Mask, class Accumulator>
  void report(std::size_t j, const Mask& mask, Accumulator& acc) const
  {
    if(j < m_vertex_count) {
      // the view of the mask's level: with tags, crease and corner vertices
      // take the border rules (along the crease), darts the smooth one
      const Vertex_view<Mesh> view = vertex_view(mask, m_mesh, m_number.vertex(j));
      if(view.rule() == Vertex_rule::smooth || view.rule() == Vertex_rule::dart)
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
    // on a refining step, the two new vertices of a border or sharp edge: p1, then p2
    const std::size_t b = k - m_face_of_point.size();
    mask.border_edge_node(edge_view(mask, m_mesh, m_halfedge_of_pair[b / 2]), 1 + int(b % 2), acc);
  }

  /// the new faces (made in this thread, whatever `loop`)
  internal::Face_soup child_faces(const internal::Parallel_loop&) const
  {
    internal::Face_soup soup(number_of_new_vertices(), number_of_new_edges());
    soup.reserve(3 * m_face_count, 9 * m_face_count);
    if(m_slot.empty()) // no border, no crease
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
        if(!cut_edge(h)) {
          soup.corner(m_number(target(h, m_mesh)), spoke_out(m_slot[id]));
          soup.corner(centre(h), id);
          soup.corner(centre(o), spoke_in(in_slot(o)));
          soup.close_face(parent);
        } else if(!m_refine_border) { // kept border triangle (source, target, centre)
          soup.corner(m_number(source(h, m_mesh)), id);
          soup.corner(m_number(target(h, m_mesh)), spoke_out(m_slot[id]));
          soup.corner(centre(h), spoke_in(m_slot[m_number(prev(h, m_mesh))]));
          soup.close_face(parent);
        } else { // middle triangle (p1, p2, c) of a split border or sharp edge h = (t, s)
          soup.corner(m_face_vertex[parent], id);
          soup.corner(m_second_vertex[parent], spoke_in(m_slot[m_number(next(h, m_mesh))]));
          soup.corner(m_number(target(next(h, m_mesh), m_mesh)), spoke_out(slot_to_p1(h)));
          soup.close_face(parent);
        }
      }
    }
  }

  // whether the edge of h is refined as a border edge: a border edge, or a
  // sharp one (with tags)
  bool cut_edge(halfedge_descriptor h) const
  {
    return m_sharp.empty() ? CGAL::is_border_edge(h, m_mesh) : m_sharp[m_number(h) >> 1] != 0;
  }
  // whether the edge of h is sharp and not on the border (a crease)
  bool crease(halfedge_descriptor h) const { return cut_edge(h) && !CGAL::is_border_edge(h, m_mesh); }

  // the new vertex that plays the face point of face(h) for the flip of h's
  // edge: the face point, or on a refining step in a face with cut edge
  // (t, s), p1 for the edge (c, t) and p2 for the edge (s, c)
  std::size_t centre(halfedge_descriptor h) const
  {
    if(!m_refine_border)
      return m_vertex_count + m_number(face(h, m_mesh));
    const std::size_t k = m_number(face(h, m_mesh)), j = m_face_vertex[k];
    if(j < m_vertex_count + m_face_of_point.size())
      return j;
    return cut_edge(prev(h, m_mesh)) ? m_second_vertex[k] : j;
  }

  // slot of the spoke (c, p1) of the face halfedge h = (t, s) of a cut edge,
  // on a refining step: the slot of the border halfedge, or for a crease
  // (which has none) the slot of h, whose own spoke (s, p2) is the other
  // side's third at s
  std::size_t slot_to_p1(halfedge_descriptor h) const
  {
    const halfedge_descriptor o = opposite(h, m_mesh);
    return m_slot[m_number(is_border(o, m_mesh) ? o : h)];
  }

  // slot of the spoke from centre(h) to source(h): the spoke of prev(h), or
  // on a refining step, when next(h) is the cut edge (t, s) and so h is
  // (c, t), the spoke (c, p1); when prev(h) is a crease (t, s) and so h is
  // (s, c), the third (p2, s) of the crease, which is the spoke (t', p1') of
  // the other side's prev: each third of a crease is one edge of both sides
  std::size_t in_slot(halfedge_descriptor h) const
  {
    if(m_refine_border) {
      const halfedge_descriptor n = next(h, m_mesh), p = prev(h, m_mesh);
      if(cut_edge(n))
        return slot_to_p1(n);
      if(!m_sharp.empty() && crease(p))
        return m_slot[m_number(prev(opposite(p, m_mesh), m_mesh))];
    }
    return m_slot[m_number(prev(h, m_mesh))];
  }

  const Mesh& m_mesh;
  internal::Mesh_numbering<Mesh> m_number;
  std::size_t m_vertex_count;
  std::size_t m_edge_count;
  std::size_t m_face_count;
  std::vector<unsigned char> m_sharp; // with tags and creases: whether each edge (ordinal) is sharp
  std::size_t m_border_edges = 0;
  bool m_refine_border = false;
  std::vector<Index> m_slot;          // spoke slot of each halfedge (mesh with border or creases)
  std::vector<Index> m_face_vertex;   // refining step: face point, or p1 of a face with a cut edge
  std::vector<Index> m_second_vertex; // refining step: p2 of a face with a cut edge
  std::vector<Index> m_face_of_point; // refining step: the face of each face point
  std::vector<Index> m_edge_of_pair;  // refining step: the cut edge of each pair p1, p2
  std::vector<halfedge_descriptor>
    m_halfedge_of_pair; // refining step: that edge, as the halfedge of its first face, from p1 to p2
};

/// `Split::sqrt3` is refined by `Sqrt3_split`
template <class Mesh>
struct Host_for<Split::sqrt3, Mesh>
{
  using type = Sqrt3_split<Mesh>;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_HOSTS_SQRT3_SPLIT_H
