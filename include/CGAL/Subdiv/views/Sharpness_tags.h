// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_VIEWS_SHARPNESS_TAGS_H
#define CGAL_SUBDIV_VIEWS_SHARPNESS_TAGS_H

/// \file Sharpness_tags.h
/// The options of a call that the mask must agree with, and where the
/// sharpness tags of a call come from, as one object that every
/// entry point asks for the mask of a level: `subdivide()` (the caller's
/// maps, written back), `make_stencil_table()` (maps of the copy it refines,
/// so the caller's are only read) and the limit layer. Without tags
/// (`No_sharpness_tags`) the mask is used as it is and nothing of the sharp
/// path is compiled.

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/views/Sharp_level.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/// the sharpness that `map` gives `key`; 0 where there is no map (CGAL's `Param_not_found`)
template <class Map, class Key>
auto sharpness_in(const Map& map, Key key)
{
  if constexpr(std::is_same<Map, CGAL::internal_np::Param_not_found>::value) {
    (void)map, (void)key;
    return 0;
  } else
    return get(map, key);
}

/// the sharpness that the map of `np` under `MapTag` (`edge_sharpness_map_t`,
/// `vertex_sharpness_map_t`) gives `key` (0 without such a map)
template <class MapTag, class NamedParameters, class Key>
auto tagged_sharpness(const NamedParameters& np, Key key)
{
  return sharpness_in(parameters::get_parameter(np, MapTag()), key);
}

/*
 * The named parameters `boundary_interpolation` and `triangle_subdivision`
 * name options of the mask (`loop_subdivision()` and the like make the mask
 * from them): a call to `subdivide()` whose mask has other options is refused.
 */
template <class Mask, class NamedParameters>
void check_mask_options(const Mask& mask, const NamedParameters& np)
{
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  if constexpr(!is_default_parameter<NamedParameters, boundary_interpolation_t>::value) {
    const Boundary_interpolation boundary = get_parameter(np, boundary_interpolation_t());
    require(border_corners_for(boundary) == border_corners_of(mask),
            mask.name() +
              ": boundary_interpolation(edges_and_corners) needs the mask's Border_corners::sharp, and "
              "the other modes Border_corners::smooth (the argument of the constructors of Loop_mask "
              "and Catmull_clark_mask; the other schemes have smooth corners only)");
  }
  if constexpr(!is_default_parameter<NamedParameters, triangle_subdivision_t>::value)
    require(get_parameter(np, triangle_subdivision_t()) == triangle_subdivision_of(mask),
            mask.name() +
              ": triangle_subdivision(smooth) is an option of Catmull_clark_mask, which was made "
              "with another (pass it to the constructor, or call catmull_clark_subdivision())");
}

/// whether `np` has an edge or a vertex sharpness map
template <class NamedParameters>
constexpr bool has_sharpness_tags()
{
  return !parameters::is_default_parameter<NamedParameters, edge_sharpness_map_t>::value ||
         !parameters::is_default_parameter<NamedParameters, vertex_sharpness_map_t>::value;
}

/// no sharpness tags: every level with the mask as it is
struct No_sharpness_tags
{
  template <class Mesh, class Mask>
  void check(const Mesh&, const Mask&, const std::string&) const
  {}
  /// `use(mask)`
  template <class Mesh, class Mask, class Use>
  decltype(auto) on_level(const Mesh&, const Mask& mask, const Use& use) const
  {
    return use(mask);
  }
  /// `refine_one(mask)`
  template <class Mesh, class Mask, class RefineOne>
  void refine(Mesh&, const Mask& mask, const RefineOne& refine_one) const
  {
    refine_one(mask);
  }
};

/*
 * Sharpness tags in an edge and a vertex property map (either may be CGAL's
 * `Param_not_found`: no tags of that kind), decaying by `method`.
 */
template <class Mesh, class FT, class EdgeMap, class VertexMap>
class Sharpness_tags
{
  using GT = boost::graph_traits<Mesh>;

public:
  Sharpness_tags(const EdgeMap& edges, const VertexMap& vertices, Crease_method method)
    : m_edges(edges), m_vertices(vertices), m_method(method)
  {}

  /// refuses a negative or NaN sharpness, and a semi-sharp one where `mask`
  /// takes infinitely sharp tags only (`Takes_semi_sharp_tags`,
  /// `Sharp_level::check_tags`; `who` names the caller in the message):
  /// called before the mesh or a map is changed
  template <class Mask>
  void check(const Mesh& mesh, const Mask&, const std::string& who) const
  {
    Sharp_level<Mesh, FT>::check_tags(mesh, edge_reader(), vertex_reader(), who, !Takes_semi_sharp_tags<Mask>::value);
  }

  /// the tags of `mesh`'s level, for a mask with border corners `corners`
  Sharp_level<Mesh, FT> level(const Mesh& mesh, Border_corners corners) const
  {
    return Sharp_level<Mesh, FT>(mesh, edge_reader(), vertex_reader(), m_method, corners);
  }

  /// `use(level mask)`: the mask with the tags of `mesh`'s level
  template <class Mask, class Use>
  decltype(auto) on_level(const Mesh& mesh, const Mask& mask, const Use& use) const
  {
    static_assert(Takes_sharpness_tags<Mask>::value,
                  "this scheme does not take sharpness tags (edge_sharpness_map, vertex_sharpness_map) yet");
    const Sharp_level<Mesh, FT> tags = level(mesh, border_corners_of(mask));
    return use(mask.with_sharp_level(&tags));
  }

  /// `refine_one(level mask, writer)`: one level with the tags of `mesh`'s
  /// level; the writer (a sink of `refine_level`) puts the children's
  /// sharpness into the maps
  template <class Mask, class RefineOne>
  void refine(Mesh& mesh, const Mask& mask, const RefineOne& refine_one) const
  {
    static_assert(Takes_sharpness_tags<Mask>::value,
                  "this scheme does not take sharpness tags (edge_sharpness_map, vertex_sharpness_map) yet");
    const Sharp_level<Mesh, FT> tags = level(mesh, border_corners_of(mask));
    Sharpness_writer<Mesh, FT, EdgeMap, VertexMap> writer(mesh, tags, &m_edges, &m_vertices);
    refine_one(mask.with_sharp_level(&tags), writer);
  }

  /// how the sharpness decays from a level to the next
  Crease_method method() const { return m_method; }

  /// the reader of the sharpness of an edge (0 without an edge map)
  auto edge_reader() const
  {
    return [this](typename GT::edge_descriptor e) { return sharpness_in(m_edges, e); };
  }
  /// the reader of the sharpness of a vertex (0 without a vertex map)
  auto vertex_reader() const
  {
    return [this](typename GT::vertex_descriptor v) { return sharpness_in(m_vertices, v); };
  }

private:
  EdgeMap m_edges;
  VertexMap m_vertices;
  Crease_method m_method;
};

/// the tags of `np` (`edge_sharpness_map`, `vertex_sharpness_map`,
/// `crease_method`): `No_sharpness_tags` without a sharpness map
template <class Mesh, class FT, class NamedParameters>
auto sharpness_tags_of(const NamedParameters& np)
{
  if constexpr(has_sharpness_tags<NamedParameters>()) {
    using parameters::get_parameter;
    const auto edges = get_parameter(np, edge_sharpness_map_t());
    const auto vertices = get_parameter(np, vertex_sharpness_map_t());
    const Crease_method method =
      parameters::choose_parameter(get_parameter(np, crease_method_t()), Crease_method::uniform);
    return Sharpness_tags<Mesh, FT, std::remove_const_t<decltype(edges)>, std::remove_const_t<decltype(vertices)>>(
      edges, vertices, method);
  } else {
    (void)np;
    return No_sharpness_tags();
  }
}

/// the sharpness of every edge and vertex of a mesh, by ordinal (`Mesh_numbering`)
template <class FT>
struct Sharpness_by_ordinal
{
  std::vector<Sharpness_number<FT>> edges, vertices;
};

/// a readable map of the values of `Sharpness_by_ordinal` (edges or vertices)
template <class Mesh, class S>
struct Ordinal_sharpness_map
{
  const Mesh_numbering<Mesh>* number;
  const std::vector<S>* values;

  template <class Key>
  friend S get(const Ordinal_sharpness_map& map, Key key)
  {
    return (*map.values)[(*map.number)(key)];
  }
};

/// the tags of `sharpness`, the ordinals being those of `number`: they are
/// read, never refined, and a level's rules do not depend on how sharpness
/// decays, so the crease method is immaterial
template <class Mesh, class FT>
Sharpness_tags<Mesh, FT, Ordinal_sharpness_map<Mesh, Sharpness_number<FT>>,
               Ordinal_sharpness_map<Mesh, Sharpness_number<FT>>>
tags_by_ordinal(const Mesh_numbering<Mesh>& number, const Sharpness_by_ordinal<FT>& sharpness)
{
  using Map = Ordinal_sharpness_map<Mesh, Sharpness_number<FT>>;
  return {Map{&number, &sharpness.edges}, Map{&number, &sharpness.vertices}, Crease_method::uniform};
}

/*
 * The tags of a copy of a mesh (`make_stencil_table()` refines one): the
 * caller's tags (`tags`) read into maps of the copy, by
 * ordinal, which the levels of the copy then refine: the caller's maps are
 * only read. The maps are properties of the copy while this object lives.
 */
template <class Mesh, class FT>
class Copied_sharpness
{
  using S = Sharpness_number<FT>;
  using Edge_map = typename boost::property_map<Mesh, CGAL::dynamic_edge_property_t<S>>::type;
  using Vertex_map = typename boost::property_map<Mesh, CGAL::dynamic_vertex_property_t<S>>::type;

public:
  template <class EdgeMap, class VertexMap>
  Copied_sharpness(const Mesh& mesh, Mesh& copy, const Sharpness_tags<Mesh, FT, EdgeMap, VertexMap>& tags)
    : m_copy(&copy), m_edges(get(CGAL::dynamic_edge_property_t<S>(), copy)),
      m_vertices(get(CGAL::dynamic_vertex_property_t<S>(), copy)), m_method(tags.method())
  {
    const Mesh_numbering<Mesh> from(mesh), to(copy);
    const auto edge_sharpness = tags.edge_reader();
    const auto vertex_sharpness = tags.vertex_reader();
    for(std::size_t e = 0; e < num_edges(mesh); ++e)
      put(m_edges, to.edge(e), S(edge_sharpness(from.edge(e))));
    for(std::size_t i = 0; i < num_vertices(mesh); ++i)
      put(m_vertices, to.vertex(i), S(vertex_sharpness(from.vertex(i))));
  }

  /// the tags of the copy's current level
  Sharpness_tags<Mesh, FT, Edge_map, Vertex_map> tags() const { return {m_edges, m_vertices, m_method}; }

  /// the maps of the copy's tags, for `subdivide()` to refine
  const Edge_map& edge_map() const { return m_edges; }
  const Vertex_map& vertex_map() const { return m_vertices; }

  /// the copy's current tags, by ordinal
  Sharpness_by_ordinal<FT> by_ordinal() const
  {
    const Mesh_numbering<Mesh> number(*m_copy);
    Sharpness_by_ordinal<FT> result;
    for(std::size_t e = 0; e < num_edges(*m_copy); ++e)
      result.edges.push_back(get(m_edges, number.edge(e)));
    for(std::size_t i = 0; i < num_vertices(*m_copy); ++i)
      result.vertices.push_back(get(m_vertices, number.vertex(i)));
    return result;
  }

private:
  const Mesh* m_copy;
  Edge_map m_edges;
  Vertex_map m_vertices;
  Crease_method m_method;
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_VIEWS_SHARPNESS_TAGS_H
