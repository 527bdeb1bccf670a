// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_VIEWS_SHARP_LEVEL_H
#define CGAL_SUBDIV_VIEWS_SHARP_LEVEL_H

/// \file Sharp_level.h
/// The sharpness tags of one level, read once before the level is refined:
/// the effective sharpness of every edge and vertex (border edges are
/// infinitely sharp, as in OpenSubdiv), the rules they select at every vertex
/// on this level and the next, the blend weights, and the sharpness of the
/// children. The hosts' views read it (`vertex_view(mask, ...)`), so every
/// consumer of the masks sees the same rules; `Sharpness_writer` stores the
/// children's values in the caller's maps after the level.

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/views/Sharpness.h>
#include <CGAL/Subdiv/views/Vertex_view.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/// whether v is a border vertex with one face under `Border_corners::sharp`
/// (OpenSubdiv's boundary interpolation "edges and corners"): infinitely sharp
template <class Mesh>
bool is_pinned_border_corner(const Mesh& mesh, typename boost::graph_traits<Mesh>::vertex_descriptor v,
                             Border_corners corners)
{
  if(corners != Border_corners::sharp)
    return false;
  int edges = 0;
  bool border = false;
  for(const auto h : CGAL::halfedges_around_target(v, mesh)) {
    ++edges;
    border = border || CGAL::is_border(h, mesh);
  }
  return border && edges == 2;
}

/*
 * One level's sharpness, over the ordinals of `Mesh_numbering` (the hosts'
 * numbering, so new edge 2e + i of an edge split is the half of old edge e
 * at source(halfedge(e)) for i = 0, at its target for i = 1).
 */
template <class Mesh, class FT>
class Sharp_level
{
public:
  using Field = FT;
  using S = Sharpness_number<FT>;
  using Rules = Crease_rules<S>;
  using GT = boost::graph_traits<Mesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;

  /// throws `Bad_input` naming the first edge or vertex (by its ordinal)
  /// whose `edge_sharpness(e)` or `vertex_sharpness(v)` (callables) is
  /// negative or NaN, or semi-sharp (above 0, below 10) with
  /// `infinitely_sharp_only` (`scheme` names the caller in the message): a
  /// user's tags are checked by this before anything is changed
  template <class EdgeSharpness, class VertexSharpness>
  static void check_tags(const Mesh& mesh, const EdgeSharpness& edge_sharpness, const VertexSharpness& vertex_sharpness,
                         const std::string& scheme, bool infinitely_sharp_only = false)
  {
    const Mesh_numbering<Mesh> number(mesh);
    // the message is built only for the element refused: this runs on every edge
    const auto check = [&](const S& s, const char* element, std::size_t index) {
      if(!(s >= S(0)))
        refuse(Message() << scheme << ": the sharpness of " << element << " " << index << " is negative or NaN");
      if(infinitely_sharp_only && Rules::is_semi_sharp(s))
        refuse(Message() << scheme << ": " << element << " " << index
                         << " is semi-sharp (above 0, below 10): this scheme takes infinitely sharp creases and "
                            "corners only (0, or 10 and above); semi-sharp values are for Loop, Catmull-Clark and "
                            "bilinear");
    };
    for(std::size_t e = 0; e < num_edges(mesh); ++e)
      check(S(edge_sharpness(number.edge(e))), "edge", e);
    for(std::size_t i = 0; i < num_vertices(mesh); ++i)
      check(S(vertex_sharpness(number.vertex(i))), "vertex", i);
  }

  /// reads `edge_sharpness(e)` and `vertex_sharpness(v)` (callables, whose
  /// values `check_tags` accepts) for every edge and vertex of `mesh`
  template <class EdgeSharpness, class VertexSharpness>
  Sharp_level(const Mesh& mesh, const EdgeSharpness& edge_sharpness, const VertexSharpness& vertex_sharpness,
              Crease_method method, Border_corners corners)
    : m_mesh(&mesh), m_number(mesh), m_method(method), m_corners(corners)
  {
    const std::size_t edge_count = num_edges(mesh), vertex_count = num_vertices(mesh);
    m_edge.reserve(edge_count);
    for(std::size_t e = 0; e < edge_count; ++e) {
      const edge_descriptor ed = m_number.edge(e);
      m_edge.push_back(CGAL::is_border(ed, mesh) ? Rules::infinite() : S(edge_sharpness(ed)));
    }
    m_vertex.reserve(vertex_count);
    for(std::size_t i = 0; i < vertex_count; ++i) {
      const vertex_descriptor v = m_number.vertex(i);
      m_vertex.push_back(is_pinned_border_corner(mesh, v, corners) ? Rules::infinite() : S(vertex_sharpness(v)));
    }
    m_child_half.assign(2 * edge_count, S(0));
    m_records.resize(vertex_count);
    m_vertex_weight.assign(vertex_count, FT(0));
    for(std::size_t i = 0; i < vertex_count; ++i)
      read_vertex(i);
  }

  Vertex_view<Mesh> vertex_view(vertex_descriptor v) const
  {
    Vertex_view<Mesh> view(*m_mesh, v, m_corners);
    const std::size_t i = m_number(v);
    view.set_sharp(&m_records[i], i);
    return view;
  }

  Edge_view<Mesh> edge_view(halfedge_descriptor h) const
  {
    Edge_view<Mesh> view(*m_mesh, h, m_corners);
    const std::size_t e = m_number(h) >> 1;
    view.set_sharp(Rules::is_sharp(m_edge[e]),
                   Rules::is_sharp(m_child_half[2 * e]) && Rules::is_sharp(m_child_half[2 * e + 1]), e);
    return view;
  }

  /// the rules of vertex i (ordinal) on this level and the next
  const Sharp_vertex<Mesh>& record(std::size_t i) const { return m_records[i]; }
  /// the weight of the rule of this level in the blend of a vertex whose
  /// rule changes (`Vertex_view::ordinal()`)
  const FT& vertex_weight(std::size_t i) const { return m_vertex_weight[i]; }
  /// the weight of the crease rule in the blend of a sharp edge whose halves
  /// are not both sharp on the next level: its sharpness, as in OpenSubdiv
  FT edge_weight(std::size_t e) const { return FT(m_edge[e]); }

  /// the sharpness of edge e (ordinal) on this level (infinite on a border)
  const S& edge_sharpness(std::size_t e) const { return m_edge[e]; }
  /// the sharpness of vertex i (ordinal) on this level (infinite at a pinned corner)
  const S& vertex_sharpness(std::size_t i) const { return m_vertex[i]; }
  /// how the sharpness decays from this level to the next
  Crease_method method() const { return m_method; }

  /// whether edge e (ordinal) is sharp on this level (a border edge, or a tag above 0)
  bool is_sharp_edge(std::size_t e) const { return Rules::is_sharp(m_edge[e]); }

  /// the sharpness of new edge k of an edge split (k < 2 num_edges: a half of
  /// an old edge; the other new edges are smooth)
  S child_edge(std::size_t k) const { return k < m_child_half.size() ? m_child_half[k] : S(0); }
  /// the sharpness of a child of edge e of a split that does not halve it (the
  /// sqrt3 split keeps it or cuts it in three): e's, one level down, for the
  /// infinitely sharp values that those schemes take
  S child_of_edge(std::size_t e) const { return Rules::decrement(m_edge[e]); }
  /// the sharpness of new vertex j (j < num_vertices: the child of an old
  /// vertex; the other new vertices are smooth)
  S child_vertex(std::size_t j) const { return j < m_vertex.size() ? Rules::decrement(m_vertex[j]) : S(0); }

private:
  // the half of the edge of h (into v) at v
  std::size_t half_at_target(halfedge_descriptor h) const
  {
    const std::size_t id = m_number(h); // 2e along halfedge(e), which ends at target(halfedge(e))
    return (id & 1) == 0 ? id + 1 : id - 1;
  }

  void read_vertex(std::size_t i)
  {
    const vertex_descriptor v = m_number.vertex(i);
    int valence = 0, sharp = 0, semi = 0;
    S semi_sum(0);
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, *m_mesh)) {
      const S& s = m_edge[m_number(h) >> 1];
      ++valence;
      sharp += Rules::is_sharp(s) ? 1 : 0;
      if(Rules::is_semi_sharp(s)) {
        semi_sum = semi_sum + s;
        ++semi;
      }
    }
    Sharp_vertex<Mesh>& record = m_records[i];
    if(sharp == 0 && !Rules::is_sharp(m_vertex[i]))
      return; // smooth, with smooth children: the record's defaults, the halves' 0
    int child_sharp = 0, found = 0, child_found = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, *m_mesh)) {
      const S& s = m_edge[m_number(h) >> 1];
      const S child = Rules::child_at_end(m_method, s, semi_sum, semi, valence);
      m_child_half[half_at_target(h)] = child;
      const halfedge_descriptor out = opposite(h, *m_mesh);
      if(Rules::is_sharp(s)) // the first and the last sharp edge: the pair of a crease
        record.crease[found++ == 0 ? 0 : 1] = out;
      if(Rules::is_sharp(child)) {
        record.child_crease[child_found++ == 0 ? 0 : 1] = out;
        ++child_sharp;
      }
    }
    const S child_sharpness = Rules::decrement(m_vertex[i]);
    record.rule = Rules::rule(m_vertex[i], sharp);
    record.child_rule = Rules::rule(child_sharpness, child_sharp);
    if(record.rule == record.child_rule || record.rule == Vertex_rule::smooth || record.rule == Vertex_rule::dart)
      return; // no blend: the rule of this level alone
    m_vertex_weight[i] = FT(Rules::transition_weight([&](const auto& add) {
      add(m_vertex[i], child_sharpness);
      for(halfedge_descriptor h : CGAL::halfedges_around_target(v, *m_mesh))
        add(m_edge[m_number(h) >> 1], m_child_half[half_at_target(h)]);
    }));
  }

  const Mesh* m_mesh;
  Mesh_numbering<Mesh> m_number;
  Crease_method m_method;
  Border_corners m_corners;
  std::vector<S> m_edge;       // by edge ordinal
  std::vector<S> m_vertex;     // by vertex ordinal
  std::vector<S> m_child_half; // by new edge id of an edge split: 2e at source(halfedge(e)), 2e + 1 at its target
  std::vector<Sharp_vertex<Mesh>> m_records;
  std::vector<FT> m_vertex_weight;
};

/// whether a host names the old edge of every new edge (`edge_parents()`):
/// the hosts whose new edges are not an edge split's halves and new edges
template <class Host, class = void>
struct Has_edge_parents : std::false_type
{};
template <class Host>
struct Has_edge_parents<Host, std::void_t<decltype(std::declval<const Host&>().edge_parents())>> : std::true_type
{};

/// whether a host names the old vertex of every new vertex (`vertex_parents()`):
/// the hosts whose new vertices are not the old ones first (the dual split)
template <class Host, class = void>
struct Has_vertex_parents : std::false_type
{};
template <class Host>
struct Has_vertex_parents<Host, std::void_t<decltype(std::declval<const Host&>().vertex_parents())>> : std::true_type
{};

/*
 * A sink of `refine_level` (refinement/refine_level.h): after the level, puts
 * the sharpness of every new edge in `edges` and of every new vertex in
 * `vertices` (each unless its type is CGAL's `Param_not_found`), from the tags of the old level: by
 * the edge splits' numbering, or through the old edge and the old vertex that
 * the host names (`edge_parents()`, `vertex_parents()`: the sqrt3 and the
 * dual splits). The value written is the effective one: a border edge gets the
 * infinite sharpness 10, so that refining one level and then another gives
 * what two levels give, bit for bit.
 */
template <class Mesh, class FT, class EdgeMap, class VertexMap>
class Sharpness_writer
{
public:
  Sharpness_writer(const Mesh& mesh, const Sharp_level<Mesh, FT>& level, const EdgeMap* edges,
                   const VertexMap* vertices)
    : m_mesh(&mesh), m_level(&level), m_edges(edges), m_vertices(vertices)
  {}

  template <class Host, class Mask, class Loop>
  void read(const Host& host, const Mask&, const Loop&)
  {
    m_new_edges = host.number_of_new_edges();
    m_new_vertices = host.number_of_new_vertices();
    if constexpr(Has_edge_parents<Host>::value)
      m_parents = host.edge_parents();
    if constexpr(Has_vertex_parents<Host>::value) {
      m_vertex_parents = host.vertex_parents();
      m_has_vertex_parents = true;
    }
  }

  template <class Level>
  void write(const Level& level) const
  {
    if constexpr(!std::is_same<EdgeMap, CGAL::internal_np::Param_not_found>::value)
      for(std::size_t k = 0; k < m_new_edges; ++k)
        put(*m_edges, level.edge(k, *m_mesh), value<EdgeMap>(child_edge(k)));
    if constexpr(!std::is_same<VertexMap, CGAL::internal_np::Param_not_found>::value) {
      const auto& vertices = level.elements().vertices;
      for(std::size_t j = 0; j < m_new_vertices; ++j)
        put(*m_vertices, vertices[j], value<VertexMap>(child_vertex(j)));
    }
  }

private:
  // the sharpness of new edge k: of an edge split's half, or of the child of
  // the old edge the host names (`edge_parents()`: 0 for none, e + 1 for e)
  auto child_edge(std::size_t k) const
  {
    if(m_parents.empty())
      return m_level->child_edge(k);
    using S = decltype(m_level->child_edge(k));
    return m_parents[k] == 0 ? S(0) : m_level->child_of_edge(m_parents[k] - 1);
  }

  // the sharpness of new vertex j: of the child of an old vertex, which is new
  // vertex j of the edge splits and the one the host names otherwise
  // (`vertex_parents()`: 0 for none, i + 1 for old vertex i)
  auto child_vertex(std::size_t j) const
  {
    if(!m_has_vertex_parents)
      return m_level->child_vertex(j);
    using S = decltype(m_level->child_vertex(j));
    return m_vertex_parents[j] == 0 ? S(0) : m_level->child_vertex(m_vertex_parents[j] - 1);
  }

  template <class Map, class S>
  static typename boost::property_traits<Map>::value_type value(const S& s)
  {
    using Value = typename boost::property_traits<Map>::value_type;
    if constexpr(std::is_constructible<Value, const S&>::value)
      return Value(s);
    else
      return Value(CGAL::to_double(s));
  }

  const Mesh* m_mesh;
  const Sharp_level<Mesh, FT>* m_level;
  const EdgeMap* m_edges;
  const VertexMap* m_vertices;
  std::size_t m_new_edges = 0;
  std::size_t m_new_vertices = 0;
  std::vector<std::size_t> m_parents;        // hosts with `edge_parents()` only
  std::vector<std::size_t> m_vertex_parents; // hosts with `vertex_parents()` only
  bool m_has_vertex_parents = false;
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_VIEWS_SHARP_LEVEL_H
