// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_DUAL_CREASE_TOPOLOGY_H
#define CGAL_SUBDIV_HOSTS_DUAL_CREASE_TOPOLOGY_H

#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
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
namespace internal {

// the number of faces around v; on the border, *first becomes the incoming
// halfedge of its first face (the one after the border, in the order
// h <- prev(opposite(h)))
template <class Mesh>
int dual_faces_around(const Mesh& mesh, typename boost::graph_traits<Mesh>::vertex_descriptor v,
                      typename boost::graph_traits<Mesh>::halfedge_descriptor* first, bool* border)
{
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  int k = 0;
  halfedge_descriptor border_in = boost::graph_traits<Mesh>::null_halfedge();
  for(halfedge_descriptor h : CGAL::halfedges_around_target(v, mesh)) {
    if(CGAL::is_border(h, mesh))
      border_in = h;
    else
      ++k;
  }
  if(border)
    *border = border_in != boost::graph_traits<Mesh>::null_halfedge();
  if(first && border_in != boost::graph_traits<Mesh>::null_halfedge())
    *first = prev(opposite(border_in, mesh), mesh);
  return k;
}

/*
 * The child topology of `Dual_split` with creases (see "Creases" there): the
 * new vertices, some of them welded from several corners, the new faces as
 * runs of new vertices, and the new edges with their parents. Read once per
 * level, and only where the level has creases, so that the split without
 * them stays as it is.
 */
template <class Mesh>
class Dual_crease_topology
{
public:
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;
  using Numbering = Mesh_numbering<Mesh>;
  using Index = std::uint32_t;
  static constexpr Index none = (std::numeric_limits<Index>::max)();
  // what the mask is told of a corner with creases (`Corner_view::set_sharp`)
  static constexpr unsigned char before = 1, after = 2, kept = 4;

  std::size_t number_of_new_vertices() const { return m_vertex_corner.size(); }
  std::size_t number_of_new_faces() const { return m_face_parents.size(); }
  std::size_t number_of_new_edges() const { return m_sharp_edge_count; }
  /// the first corner (ordinal) of new vertex j, and what it is (before, after, kept, or 0)
  std::size_t first_corner(std::size_t j) const { return m_vertex_corner[j]; }
  unsigned char kind(std::size_t j) const { return m_vertex_kind[j]; }
  /// see `Dual_split::edge_parents()` and `Dual_split::vertex_parents()`
  const std::vector<std::size_t>& edge_parents() const { return m_edge_parents; }
  const std::vector<std::size_t>& vertex_parents() const { return m_vertex_parents; }

  /// reads the creases of `level` (a `Sharp_level`) on `mesh`, whose corners
  /// are numbered by `corner_of` (by halfedge number) and `halfedge_of_corner`;
  /// false, and nothing read, where the level has no sharp edge inside the
  /// mesh and no corner vertex
  template <class Level>
  bool read(const Mesh& mesh, const Numbering& number, const std::vector<Index>& corner_of,
            const std::vector<halfedge_descriptor>& halfedge_of_corner, const Level& level)
  {
    const auto corner = [&](halfedge_descriptor h) -> std::size_t { return corner_of[number(h)]; };
    const std::size_t corner_count = halfedge_of_corner.size();
    const std::size_t edge_count = num_edges(mesh), vertex_count = num_vertices(mesh);
    std::vector<unsigned char> sharp(edge_count, 0);
    bool creases = false;
    for(std::size_t e = 0; e < edge_count; ++e) {
      sharp[e] = level.is_sharp_edge(e) ? 1 : 0;
      creases = creases || (sharp[e] != 0 && !CGAL::is_border(number.edge(e), mesh));
    }
    // by vertex ordinal: 0 smooth or dart (its corners apart), 1 crease, 2 corner (one new vertex)
    std::vector<unsigned char> kind(vertex_count, 0);
    for(std::size_t i = 0; i < vertex_count; ++i) {
      const vertex_descriptor v = number.vertex(i);
      const Vertex_rule rule = level.vertex_view(v).rule();
      if(rule == Vertex_rule::corner) {
        kind[i] = 2;
        creases = true;
      } else if(rule == Vertex_rule::crease) {
        kind[i] = 1;
        for(halfedge_descriptor h : CGAL::halfedges_around_target(v, mesh))
          if(!CGAL::is_border(h, mesh) && sharp[number(h) >> 1] && sharp[number(next(h, mesh)) >> 1])
            kind[i] = 2; // a sector of one face: a corner of the curve, kept (as on the border)
      }
    }
    if(!creases)
      return false; // the border alone: the split without tags
    const auto is_sharp = [&](halfedge_descriptor h) { return sharp[number(h) >> 1] != 0; };

    // new vertices: by corner, the first corner of each new vertex naming it
    std::vector<Index> by_vertex(vertex_count, none), by_halfedge(2 * edge_count, none);
    std::vector<Index> vertex_of_corner(corner_count);
    for(std::size_t c = 0; c < corner_count; ++c) {
      const halfedge_descriptor h = halfedge_of_corner[c];
      const std::size_t v = number(target(h, mesh));
      Index* slot = nullptr;
      unsigned char what = 0;
      if(kind[v] == 2) {
        slot = &by_vertex[v];
        what = kept;
      } else if(kind[v] == 1 && is_sharp(h)) {
        slot = &by_halfedge[number(opposite(h, mesh))]; // Chaikin's point on the edge from v
        what = before;
      } else if(kind[v] == 1 && is_sharp(next(h, mesh))) {
        slot = &by_halfedge[number(next(h, mesh))];
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
    for(face_descriptor f : CGAL::faces(mesh)) { // face faces
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
        run.push_back(id(h));
      add_face(number(f));
    }
    for(auto e : edges(mesh)) { // edge quads
      if(CGAL::is_border(e, mesh))
        continue;
      const halfedge_descriptor h = halfedge(e, mesh), o = opposite(h, mesh);
      run = {id(h), id(prev(h, mesh)), id(o), id(prev(o, mesh))};
      add_face(number(face(h, mesh)));
    }
    std::vector<halfedge_descriptor> around;
    for(vertex_descriptor v : vertices(mesh)) { // vertex faces, one per sector of a crease vertex
      const unsigned char what = kind[number(v)];
      if(what == 2)
        continue;
      halfedge_descriptor first = halfedge(v, mesh);
      bool border = false;
      const int k = dual_faces_around(mesh, v, &first, &border);
      if(k < 3)
        continue;
      around.clear();
      halfedge_descriptor h = first;
      for(int i = 0; i < k; ++i, h = prev(opposite(h, mesh), mesh))
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
          add_face(number(face(sector, mesh)));
      }
      if(!run.empty())
        add_face(number(face(sector, mesh)));
    }
    // the new crease edges: along a sharp edge between two welded or kept
    // ends (one that ends at a dart does not go on), and across a crease
    // vertex between its two Chaikin points (the cut corner of the curve)
    std::vector<unsigned char> along(edge_count, 0);
    for(std::size_t e = 0; e < edge_count; ++e) {
      const halfedge_descriptor h = halfedge(number.edge(e), mesh);
      along[e] = sharp[e] != 0 && kind[number(source(h, mesh))] != 0 && kind[number(target(h, mesh))] != 0;
    }
    std::vector<Cut> cuts;
    for(std::size_t i = 0; i < vertex_count; ++i) {
      if(kind[i] != 1)
        continue;
      Cut cut{none, none, 0};
      for(halfedge_descriptor h : CGAL::halfedges_around_source(number.vertex(i), mesh)) {
        const Index w = by_halfedge[number(h)];
        if(w == none)
          continue;
        (cut.a == none ? cut.a : cut.b) = w;
        cut.edge = number(h) >> 1;
      }
      if(cut.b != none)
        cuts.push_back(cut);
    }
    number_sharp_edges(num_faces(mesh), number, halfedge_of_corner, along, cuts);
    return true;
  }

  /// the new faces
  Face_soup faces() const
  {
    Face_soup soup(m_vertex_corner.size(), m_sharp_edge_count);
    soup.reserve(m_face_parents.size(), m_face_vertices.size());
    for(std::size_t f = 0, begin = 0; f < m_face_ends.size(); begin = m_face_ends[f++]) {
      for(std::size_t k = begin; k < m_face_ends[f]; ++k)
        soup.corner(m_face_vertices[k], m_face_halfedges[k]);
      soup.close_face(m_face_parents[f]);
    }
    return soup;
  }

private:
  // two new vertices whose edge is a child of old edge `edge`
  struct Cut
  {
    Index a, b;
    std::size_t edge;
  };

  // the new edges of the faces with creases: one per pair of new vertices,
  // halfedge 2e from the lower to the higher; the edges of the face faces
  // along the old edges of `along` and the edges of `cuts` are children
  void number_sharp_edges(std::size_t old_face_count, const Numbering& number,
                          const std::vector<halfedge_descriptor>& halfedge_of_corner,
                          const std::vector<unsigned char>& along, const std::vector<Cut>& cuts)
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
        require(used[halfedge_id] == 0,
                "Doo-Sabin with creases: the refined faces would meet along an edge the same way (a "
                "configuration of sharp edges that the dual split cannot refine)");
        used[halfedge_id] = 1;
        m_face_halfedges[k] = static_cast<Index>(halfedge_id);
      }
      if(f < old_face_count) { // a face face: its edge from corner k - 1 to corner k runs along that old edge
        for(std::size_t k = begin; k < end; ++k, ++face_face_corner) {
          const halfedge_descriptor h = halfedge_of_corner[face_face_corner];
          const std::size_t old_edge = number(h) >> 1;
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

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_HOSTS_DUAL_CREASE_TOPOLOGY_H
