// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_DUAL_SPLIT_H
#define CGAL_SUBDIV_HOSTS_DUAL_SPLIT_H

#include <CGAL/Subdiv/hosts/Dual_crease_topology.h>
#include <CGAL/Subdiv/hosts/Host_for.h>
#include <CGAL/Subdiv/hosts/Vertex_origin.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/refinement/Child_faces.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivHosts
 * The dual quad split (DQQ) of Doo-Sabin subdivision, on any polygon mesh:
 * every face corner (a halfedge with a face, standing for the corner of
 * `face(h)` at `target(h)`) becomes a new vertex, and the new faces are
 * - one n-gon per old n-gon, through its corners (the "face face");
 * - one quad per interior edge, through the four corners at its two ends;
 * - one n-gon per interior vertex of valence n >= 3, through its corners (at
 *   an interior vertex of valence 2 the two edge quads share one edge);
 * - one k-gon per border vertex with k >= 3 faces, through its corners.
 *
 * Border: a border edge gets no face (the face face beside it already has an
 * edge along it), and a border vertex with k faces, which has k - 1 interior
 * edges, gets a face only when k >= 3: its k corners are then joined by the
 * k-gon, whose closing edge lies on the new border. So the new border
 * polygon runs, for every border edge (a, b), from the corner at a to the
 * corner at b of the face beside it, and straight on to the next border
 * edge's face; with the border corner rule of `Doo_sabin_mask` it is Chaikin's
 * refinement of the old border polygon. (CGAL's `DooSabin_subdivision` makes
 * no face at border vertices, so its border is a zigzag through all k corners
 * of every border vertex; its interior faces are the same as here.)
 *
 * Numbering of the new vertices: one per face corner, in face order, around
 * each face starting at the corner of `halfedge(f)`. Numbering of the new
 * faces: the face faces in face order, then the edge quads in edge order,
 * then the vertex faces in vertex order. Each face's parent is the old face
 * of its first corner.
 *
 * Counts: V' = C (the number of corners), E' = C + 2I - V_2 + K,
 * F' = F + I + V_i + K, with I interior edges, V_i interior vertices of
 * valence at least 3, V_2 interior vertices of valence 2 and K border vertices
 * with at least 3 faces; the Euler characteristic is kept.
 *
 * <b>Creases.</b> Made with a mask that carries the sharpness tags of its
 * level (`subdivide()` makes it so) and with an interior sharp edge or a
 * corner vertex, the split refines every sharp edge as a border on both of
 * its sides. The corners next to a sharp edge (u, v) at a crease vertex v
 * (two sharp edges) are one new vertex on both sides (Chaikin's point, by
 * the mask), so the edge quad of a sharp edge collapses to an edge, the new
 * crease edge, and gets no face. The vertex face of a crease vertex is split
 * into one face per sector (the faces between its two sharp edges) with at
 * least 3 faces; a sector of 2 faces gets an edge only (the side of the
 * edge quad between them). A corner vertex (a vertex sharpness of 10 and
 * above, three sharp edges or more, or a face whose two edges at the vertex
 * are both sharp) keeps one new vertex for all of its corners (at the
 * vertex, by the mask) and no vertex face; darts are refined smooth. The new
 * vertices are numbered by their first corner in the order above, the faces
 * in the order above with the empty ones left out; the new crease edges are
 * children of their old edges (`edge_parents()`) and the new vertex of a
 * corner vertex is its child (`vertex_parents()`), so the refined tags keep
 * the creases and the corners. Without an interior sharp edge or a corner
 * the split is the one above (the border rules are the crease rules).
 *
 * Mask used: `corner_node(Corner_view, acc)`.
 */
template <class Mesh>
class Dual_split
{
public:
  using Polygon_mesh = Mesh;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;

  static constexpr int required_face_size = 0;
  /// for the analysis: the faces of the regular meshes, a neighbourhood
  /// centred at a face, one host step per analysed step, rings doubled
  static constexpr int regular_face_size = 4;
  static constexpr bool face_centred = true;
  static constexpr int analysis_steps = 1;
  static constexpr int ring_growth = 2;
  /// F' = F + E + V: four times F on a quad mesh, which every mesh becomes
  /// after one level, up to its extraordinary faces
  static double face_growth() { return 4; }
  /// the peak memory of a refinement per output face, measured: the maximum
  /// resident size of `cgal-subdiv surface` over its output faces was
  /// 173 B (Doo-Sabin, fandisk, 5 levels, 9.9 M faces); rounded up (doc/memory.md)
  static double peak_bytes_per_face() { return 180; }
  /// the counts after one level: not known in advance (false)
  static bool next_counts(internal::Mesh_counts&) { return false; }

  explicit Dual_split(const Mesh& mesh)
    : m_mesh(mesh), m_number(mesh), m_corner(2 * num_edges(mesh), none), m_vertex_edge(2 * num_edges(mesh), none),
      m_corner_count(0), m_interior_count(0), m_edge_count(0), m_vertex_face_count(0), m_closing_count(0)
  {
    for(face_descriptor f : CGAL::faces(mesh))
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
        m_corner[m_number(h)] = static_cast<Index>(m_corner_count++);
        m_halfedge_of_corner.push_back(h);
      }
    m_edge_count = m_corner_count;
    for(auto e : edges(mesh)) {
      if(CGAL::is_border(e, mesh))
        continue;
      ++m_interior_count;
      for(halfedge_descriptor h : {halfedge(e, mesh), opposite(halfedge(e, mesh), mesh)}) {
        // at an interior vertex of valence 2, the vertex edges of its two
        // incoming halfedges are one edge, in opposite directions
        const halfedge_descriptor other = prev(opposite(h, mesh), mesh);
        const Index other_edge = m_vertex_edge[m_number(other)];
        if(prev(opposite(other, mesh), mesh) == h && other_edge != none)
          m_vertex_edge[m_number(h)] = other_edge ^ 1;
        else
          m_vertex_edge[m_number(h)] = static_cast<Index>(2 * m_edge_count++);
      }
    }
    for(vertex_descriptor v : vertices(mesh)) {
      bool border = false;
      if(faces_around(v, nullptr, &border) >= 3) {
        ++m_vertex_face_count;
        m_closing_count += border ? 1 : 0;
      }
    }
  }

  /// the split with the sharpness tags of `mask`'s level, if it is a tagged
  /// copy: see "Creases" above
  template <class Mask>
  Dual_split(const Mesh& mesh, const Mask& mask) : Dual_split(mesh)
  {
    if constexpr(internal::Refines_with_tags<Mask>::value)
      m_sharp = m_creases.read(m_mesh, m_number, m_corner, m_halfedge_of_corner, *mask.sharp_level());
    else
      (void)mask;
  }

  std::size_t number_of_new_vertices() const { return m_sharp ? m_creases.number_of_new_vertices() : m_corner_count; }
  std::size_t number_of_new_faces() const
  {
    return m_sharp ? m_creases.number_of_new_faces() : num_faces(m_mesh) + m_interior_count + m_vertex_face_count;
  }
  std::size_t number_of_new_edges() const
  {
    return m_sharp ? m_creases.number_of_new_edges() : m_edge_count + m_closing_count;
  }

  /// the ordinals of the old elements that the new ones are numbered by
  const internal::Mesh_numbering<Mesh>& numbering() const { return m_number; }

  Vertex_origin origin(std::size_t j) const
  {
    return {Origin_kind::corner, m_sharp ? corner(m_halfedge_of_corner[m_creases.first_corner(j)]) : j};
  }

  /// the mask's weights of new vertex j (the corner of ordinal j) to `acc`;
  /// reads only the old elements
  template <class Mask, class Accumulator>
  void report(std::size_t j, const Mask& mask, Accumulator& acc) const
  {
    if(!m_sharp) {
      mask.corner_node(Corner_view<Mesh>(m_mesh, m_halfedge_of_corner[j]), acc);
      return;
    }
    using Creases = internal::Dual_crease_topology<Mesh>;
    Corner_view<Mesh> view(m_mesh, m_halfedge_of_corner[m_creases.first_corner(j)]);
    const unsigned char kind = m_creases.kind(j);
    view.set_sharp((kind & Creases::before) != 0, (kind & Creases::after) != 0, (kind & Creases::kept) != 0);
    mask.corner_node(view, acc);
  }

  /// the old edge that each new edge is a child of, by new edge: e + 1 for
  /// old edge e, 0 for none (what `internal::Sharpness_writer` reads): the
  /// edges of the face faces along the border and the sharp edges
  std::vector<std::size_t> edge_parents() const
  {
    if(m_sharp)
      return m_creases.edge_parents();
    std::vector<std::size_t> parents(number_of_new_edges(), 0);
    for(std::size_t c = 0; c < m_corner_count; ++c) {
      const halfedge_descriptor h = m_halfedge_of_corner[c];
      if(CGAL::is_border(opposite(h, m_mesh), m_mesh))
        parents[c] = (m_number(h) >> 1) + 1;
    }
    return parents;
  }

  /// the old vertex that each new vertex is the child of, by new vertex: i + 1
  /// for old vertex i (the one new vertex of a corner vertex), 0 for none
  std::vector<std::size_t> vertex_parents() const
  {
    return m_sharp ? m_creases.vertex_parents() : std::vector<std::size_t>(number_of_new_vertices(), 0);
  }

  /// the new faces (made in this thread, whatever `loop`)
  internal::Face_soup child_faces(const internal::Parallel_loop&) const { return faces(); }

  /*
   * New edges: first one per corner, the edge of the face face along the
   * corner's halfedge h (from the corner at source(h) to the corner at
   * target(h)); then two per interior edge e, in edge order, one in the
   * vertex face at each end (first at the target of halfedge(e), then at its
   * source), running from the corner of the face of the incoming halfedge to
   * the corner of the face on the other side (just one at an interior vertex
   * of valence 2); then the closing edges of the border vertex faces, in
   * vertex order.
   */
  internal::Face_soup faces() const
  {
    if(m_sharp)
      return m_creases.faces();
    internal::Face_soup soup(m_corner_count, m_edge_count + m_closing_count);
    soup.reserve(number_of_new_faces(), 2 * m_corner_count + 4 * m_interior_count);

    // face faces
    for(face_descriptor f : CGAL::faces(m_mesh)) {
      const std::size_t parent = m_number(f);
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, m_mesh), m_mesh))
        soup.corner(corner(h), 2 * corner(next(h, m_mesh)));
      soup.close_face(parent);
    }
    // edge quads: h runs from a to b, h' = opposite(h) back
    for(auto e : edges(m_mesh)) {
      if(CGAL::is_border(e, m_mesh))
        continue;
      const halfedge_descriptor h = halfedge(e, m_mesh), o = opposite(h, m_mesh);
      soup.corner(corner(h), 2 * corner(h) + 1);
      soup.corner(corner(prev(h, m_mesh)), vertex_edge(o) ^ 1);
      soup.corner(corner(o), 2 * corner(o) + 1);
      soup.corner(corner(prev(o, m_mesh)), vertex_edge(h) ^ 1);
      soup.close_face(m_number(face(h, m_mesh)));
    }
    // vertex faces: corners of the incoming halfedges h, h <- prev(opposite(h))
    std::size_t closing = m_edge_count;
    for(vertex_descriptor v : vertices(m_mesh)) {
      halfedge_descriptor first = halfedge(v, m_mesh);
      bool border = false;
      const int k = faces_around(v, &first, &border);
      if(k < 3)
        continue;
      halfedge_descriptor h = first;
      for(int i = 0; i < k; ++i) {
        if(border && i == k - 1) // last corner of a border vertex face
          soup.corner(corner(h), 2 * closing++);
        else
          soup.corner(corner(h), vertex_edge(h));
        h = prev(opposite(h, m_mesh), m_mesh);
      }
      soup.close_face(m_number(face(first, m_mesh)));
    }
    return soup;
  }

private:
  using Index = typename internal::Dual_crease_topology<Mesh>::Index;
  static constexpr Index none = internal::Dual_crease_topology<Mesh>::none;

  std::size_t corner(halfedge_descriptor h) const { return m_corner[m_number(h)]; }

  // the new halfedge id of the vertex-face edge at target(h) across the
  // interior edge of h, from the corner of h to the corner of prev(opposite(h))
  std::size_t vertex_edge(halfedge_descriptor h) const { return m_vertex_edge[m_number(h)]; }

  // the number of faces around v; on the border, *first becomes the incoming
  // halfedge of its first face (the one after the border, in the order
  // h <- prev(opposite(h)))
  int faces_around(vertex_descriptor v, halfedge_descriptor* first = nullptr, bool* border = nullptr) const
  {
    return internal::dual_faces_around(m_mesh, v, first, border);
  }

  const Mesh& m_mesh;
  internal::Mesh_numbering<Mesh> m_number;
  std::vector<Index> m_corner;                           // by halfedge number: corner ordinal, or none on the border
  std::vector<halfedge_descriptor> m_halfedge_of_corner; // by corner ordinal
  std::vector<Index> m_vertex_edge;                      // by halfedge number: see vertex_edge(), or none
  std::size_t m_corner_count;
  std::size_t m_interior_count;
  std::size_t m_edge_count;        // new edges but the closing ones
  std::size_t m_vertex_face_count; // vertices with 3 or more faces
  std::size_t m_closing_count;     // border vertices with 3 or more faces
  // with creases: the child topology of the creases, if any (`m_sharp`)
  bool m_sharp = false;
  internal::Dual_crease_topology<Mesh> m_creases;
};

/// `Split::dual` is refined by `Dual_split`
template <class Mesh>
struct Host_for<Split::dual, Mesh>
{
  using type = Dual_split<Mesh>;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_HOSTS_DUAL_SPLIT_H
