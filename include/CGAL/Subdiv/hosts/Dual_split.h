// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_DUAL_SPLIT_H
#define CGAL_SUBDIV_HOSTS_DUAL_SPLIT_H

#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/hosts/Host_for.h>
#include <CGAL/Subdiv/hosts/Vertex_origin.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/refinement/Child_faces.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <unordered_map>
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
      read_creases(*mask.sharp_level());
    else
      (void)mask;
  }

  std::size_t number_of_new_vertices() const { return m_sharp ? m_vertex_corner.size() : m_corner_count; }
  std::size_t number_of_new_faces() const
  {
    return m_sharp ? m_face_parents.size() : num_faces(m_mesh) + m_interior_count + m_vertex_face_count;
  }
  std::size_t number_of_new_edges() const { return m_sharp ? m_sharp_edge_count : m_edge_count + m_closing_count; }

  /// the ordinals of the old elements that the new ones are numbered by
  const internal::Mesh_numbering<Mesh>& numbering() const { return m_number; }

  Vertex_origin origin(std::size_t j) const
  {
    return {Origin_kind::corner, m_sharp ? corner(m_halfedge_of_corner[m_vertex_corner[j]]) : j};
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
    Corner_view<Mesh> view(m_mesh, m_halfedge_of_corner[m_vertex_corner[j]]);
    const unsigned char kind = m_vertex_kind[j];
    view.set_sharp((kind & before) != 0, (kind & after) != 0, (kind & kept) != 0);
    mask.corner_node(view, acc);
  }

  /// the old edge that each new edge is a child of, by new edge: e + 1 for
  /// old edge e, 0 for none (what `internal::Sharpness_writer` reads): the
  /// edges of the face faces along the border and the sharp edges
  std::vector<std::size_t> edge_parents() const
  {
    if(m_sharp)
      return m_edge_parents;
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
    return m_sharp ? m_vertex_parents : std::vector<std::size_t>(number_of_new_vertices(), 0);
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
      return sharp_faces();
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
  using Index = std::uint32_t;
  static constexpr Index none = (std::numeric_limits<Index>::max)();
  // what the mask is told of a corner with creases (`Corner_view::set_sharp`)
  static constexpr unsigned char before = 1, after = 2, kept = 4;

  /*
   * The topology with the creases of `level` (a `internal::Sharp_level`):
   * see "Creases" above. Leaves `m_sharp` false where the level has no
   * sharp edge inside the mesh and no corner vertex.
   */
  template <class Level>
  void read_creases(const Level& level)
  {
    const std::size_t edge_count = num_edges(m_mesh), vertex_count = num_vertices(m_mesh);
    std::vector<unsigned char> sharp(edge_count, 0);
    bool creases = false;
    for(std::size_t e = 0; e < edge_count; ++e) {
      sharp[e] = level.is_sharp_edge(e) ? 1 : 0;
      creases = creases || (sharp[e] != 0 && !CGAL::is_border(m_number.edge(e), m_mesh));
    }
    // by vertex ordinal: 0 smooth or dart (its corners apart), 1 crease, 2 corner (one new vertex)
    std::vector<unsigned char> kind(vertex_count, 0);
    for(std::size_t i = 0; i < vertex_count; ++i) {
      const vertex_descriptor v = m_number.vertex(i);
      const Vertex_rule rule = level.vertex_view(v).rule();
      if(rule == Vertex_rule::corner) {
        kind[i] = 2;
        creases = true;
      } else if(rule == Vertex_rule::crease) {
        kind[i] = 1;
        for(halfedge_descriptor h : CGAL::halfedges_around_target(v, m_mesh))
          if(!CGAL::is_border(h, m_mesh) && sharp[m_number(h) >> 1] && sharp[m_number(next(h, m_mesh)) >> 1])
            kind[i] = 2; // a sector of one face: a corner of the curve, kept (as on the border)
      }
    }
    if(!creases)
      return; // the border alone: the split without tags
    m_sharp = true;
    const auto is_sharp = [&](halfedge_descriptor h) { return sharp[m_number(h) >> 1] != 0; };

    // new vertices: by corner, the first corner of each new vertex naming it
    std::vector<Index> by_vertex(vertex_count, none), by_halfedge(2 * edge_count, none);
    std::vector<Index> vertex_of_corner(m_corner_count);
    for(std::size_t c = 0; c < m_corner_count; ++c) {
      const halfedge_descriptor h = m_halfedge_of_corner[c];
      const std::size_t v = m_number(target(h, m_mesh));
      Index* slot = nullptr;
      unsigned char what = 0;
      if(kind[v] == 2) {
        slot = &by_vertex[v];
        what = kept;
      } else if(kind[v] == 1 && is_sharp(h)) {
        slot = &by_halfedge[m_number(opposite(h, m_mesh))]; // Chaikin's point on the edge from v
        what = before;
      } else if(kind[v] == 1 && is_sharp(next(h, m_mesh))) {
        slot = &by_halfedge[m_number(next(h, m_mesh))];
        what = after;
      }
      if(slot != nullptr && *slot != none) {
        vertex_of_corner[c] = *slot;
        continue;
      }
      const Index j = static_cast<Index>(m_vertex_corner.size());
      m_vertex_corner.push_back(static_cast<Index>(c));
      m_vertex_kind.push_back(what);
      m_vertex_parents.push_back(what == kept ? v + 1 : 0);
      vertex_of_corner[c] = j;
      if(slot != nullptr)
        *slot = j;
    }
    const auto id = [&](halfedge_descriptor h) { return vertex_of_corner[corner(h)]; };

    // new faces, as runs of new vertices; a run of fewer than 3 distinct vertices is no face
    std::vector<Index> run;
    const auto add_face = [&](std::size_t parent) {
      std::size_t size = 0;
      for(std::size_t k = 0; k < run.size(); ++k)
        if(size == 0 || run[k] != run[size - 1])
          run[size++] = run[k];
      while(size > 1 && run[size - 1] == run[0])
        --size;
      if(size >= 3) {
        m_face_vertices.insert(m_face_vertices.end(), run.begin(), run.begin() + static_cast<std::ptrdiff_t>(size));
        m_face_ends.push_back(m_face_vertices.size());
        m_face_parents.push_back(static_cast<Index>(parent));
      }
      run.clear();
    };
    for(face_descriptor f : CGAL::faces(m_mesh)) { // face faces
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, m_mesh), m_mesh))
        run.push_back(id(h));
      add_face(m_number(f));
    }
    for(auto e : edges(m_mesh)) { // edge quads
      if(CGAL::is_border(e, m_mesh))
        continue;
      const halfedge_descriptor h = halfedge(e, m_mesh), o = opposite(h, m_mesh);
      run = {id(h), id(prev(h, m_mesh)), id(o), id(prev(o, m_mesh))};
      add_face(m_number(face(h, m_mesh)));
    }
    std::vector<halfedge_descriptor> around;
    for(vertex_descriptor v : vertices(m_mesh)) { // vertex faces, one per sector of a crease vertex
      const unsigned char what = kind[m_number(v)];
      if(what == 2)
        continue;
      halfedge_descriptor first = halfedge(v, m_mesh);
      bool border = false;
      const int k = faces_around(v, &first, &border);
      if(k < 3)
        continue;
      around.clear();
      halfedge_descriptor h = first;
      for(int i = 0; i < k; ++i, h = prev(opposite(h, m_mesh), m_mesh))
        around.push_back(h); // the edge of around[i] lies between around[i] and around[i + 1]
      // a sector starts after a sharp edge (on the border, at the first corner)
      std::size_t start = 0;
      if(what == 1 && !border)
        while(!is_sharp(around[(start + around.size() - 1) % around.size()]))
          ++start;
      halfedge_descriptor sector = around[start]; // the first corner of the sector
      for(std::size_t i = 0; i < around.size(); ++i) {
        const halfedge_descriptor c = around[(start + i) % around.size()];
        if(run.empty())
          sector = c;
        run.push_back(id(c));
        if(what == 1 && is_sharp(c)) // the end of a sector
          add_face(m_number(face(sector, m_mesh)));
      }
      if(!run.empty())
        add_face(m_number(face(sector, m_mesh)));
    }
    // the new crease edges: along a sharp edge between two welded or kept
    // ends (one that ends at a dart does not go on), and across a crease
    // vertex between its two Chaikin points (the cut corner of the curve)
    std::vector<unsigned char> along(edge_count, 0);
    for(std::size_t e = 0; e < edge_count; ++e) {
      const halfedge_descriptor h = halfedge(m_number.edge(e), m_mesh);
      along[e] = sharp[e] != 0 && kind[m_number(source(h, m_mesh))] != 0 && kind[m_number(target(h, m_mesh))] != 0;
    }
    std::vector<Cut> cuts;
    for(std::size_t i = 0; i < vertex_count; ++i) {
      if(kind[i] != 1)
        continue;
      Cut cut{none, none, 0};
      for(halfedge_descriptor h : CGAL::halfedges_around_source(m_number.vertex(i), m_mesh)) {
        const Index w = by_halfedge[m_number(h)];
        if(w == none)
          continue;
        (cut.a == none ? cut.a : cut.b) = w;
        cut.edge = m_number(h) >> 1;
      }
      if(cut.b != none)
        cuts.push_back(cut);
    }
    number_sharp_edges(along, cuts);
  }

  // two new vertices whose edge is a child of old edge `edge`
  struct Cut
  {
    Index a, b;
    std::size_t edge;
  };

  // the new edges of the faces with creases: one per pair of new vertices,
  // halfedge 2e from the lower to the higher; the edges of the face faces
  // along the old edges of `along` and the edges of `cuts` are children
  void number_sharp_edges(const std::vector<unsigned char>& along, const std::vector<Cut>& cuts)
  {
    std::unordered_map<std::uint64_t, Index> edge_of;
    edge_of.reserve(2 * m_face_vertices.size());
    m_face_halfedges.resize(m_face_vertices.size());
    std::vector<unsigned char> used;
    std::size_t face_face_corner = 0; // the face faces come first, corner by corner
    for(std::size_t f = 0, begin = 0; f < m_face_ends.size(); begin = m_face_ends[f++]) {
      const std::size_t end = m_face_ends[f];
      for(std::size_t k = begin; k < end; ++k) {
        const Index a = m_face_vertices[k], b = m_face_vertices[k + 1 < end ? k + 1 : begin];
        const std::uint64_t key = (std::uint64_t(a < b ? a : b) << 32) | (a < b ? b : a);
        auto found = edge_of.emplace(key, static_cast<Index>(m_sharp_edge_count));
        if(found.second) {
          ++m_sharp_edge_count;
          m_edge_parents.push_back(0);
          used.push_back(0);
          used.push_back(0);
        }
        const std::size_t e = found.first->second, halfedge_id = 2 * e + (a < b ? 0 : 1);
        internal::require(used[halfedge_id] == 0,
                          "Doo-Sabin with creases: the refined faces would meet along an edge the same way (a "
                          "configuration of sharp edges that the dual split cannot refine)");
        used[halfedge_id] = 1;
        m_face_halfedges[k] = static_cast<Index>(halfedge_id);
      }
      if(f < num_faces(m_mesh)) { // a face face: its edge from corner k - 1 to corner k runs along that old edge
        for(std::size_t k = begin; k < end; ++k, ++face_face_corner) {
          const halfedge_descriptor h = m_halfedge_of_corner[face_face_corner];
          const std::size_t old_edge = m_number(h) >> 1;
          if(along[old_edge] != 0) {
            const std::size_t previous = k == begin ? end - 1 : k - 1;
            m_edge_parents[m_face_halfedges[previous] >> 1] = old_edge + 1;
          }
        }
      }
    }
    for(const Cut& cut : cuts) {
      const auto found =
        edge_of.find((std::uint64_t(cut.a < cut.b ? cut.a : cut.b) << 32) | (cut.a < cut.b ? cut.b : cut.a));
      if(found != edge_of.end())
        m_edge_parents[found->second] = cut.edge + 1;
    }
  }

  internal::Face_soup sharp_faces() const
  {
    internal::Face_soup soup(m_vertex_corner.size(), m_sharp_edge_count);
    soup.reserve(m_face_parents.size(), m_face_vertices.size());
    for(std::size_t f = 0, begin = 0; f < m_face_ends.size(); begin = m_face_ends[f++]) {
      for(std::size_t k = begin; k < m_face_ends[f]; ++k)
        soup.corner(m_face_vertices[k], m_face_halfedges[k]);
      soup.close_face(m_face_parents[f]);
    }
    return soup;
  }

  std::size_t corner(halfedge_descriptor h) const { return m_corner[m_number(h)]; }

  // the new halfedge id of the vertex-face edge at target(h) across the
  // interior edge of h, from the corner of h to the corner of prev(opposite(h))
  std::size_t vertex_edge(halfedge_descriptor h) const { return m_vertex_edge[m_number(h)]; }

  // the number of faces around v; on the border, *first becomes the incoming
  // halfedge of its first face (the one after the border, in the order
  // h <- prev(opposite(h)))
  int faces_around(vertex_descriptor v, halfedge_descriptor* first = nullptr, bool* border = nullptr) const
  {
    int k = 0;
    halfedge_descriptor border_in = boost::graph_traits<Mesh>::null_halfedge();
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, m_mesh)) {
      if(CGAL::is_border(h, m_mesh))
        border_in = h;
      else
        ++k;
    }
    if(border)
      *border = border_in != boost::graph_traits<Mesh>::null_halfedge();
    if(first && border_in != boost::graph_traits<Mesh>::null_halfedge())
      *first = prev(opposite(border_in, m_mesh), m_mesh);
    return k;
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
  // with creases (`read_creases`)
  bool m_sharp = false;
  std::vector<Index> m_vertex_corner;        // by new vertex: its first corner (ordinal)
  std::vector<unsigned char> m_vertex_kind;  // by new vertex: before, after, kept
  std::vector<std::size_t> m_vertex_parents; // by new vertex: see vertex_parents()
  std::vector<Index> m_face_vertices;        // the new faces' vertices, face after face
  std::vector<std::size_t> m_face_ends;      // one past the last vertex of each new face
  std::vector<Index> m_face_parents;         // by new face
  std::vector<Index> m_face_halfedges;       // by face vertex: the halfedge id to the next
  std::vector<std::size_t> m_edge_parents;   // by new edge: see edge_parents()
  std::size_t m_sharp_edge_count = 0;
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
