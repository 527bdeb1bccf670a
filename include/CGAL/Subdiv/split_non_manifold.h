// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_SPLIT_NON_MANIFOLD_H
#define CGAL_SUBDIV_SPLIT_NON_MANIFOLD_H

/// \file split_non_manifold.h
/// Non-manifold polygon soups as OpenSubdiv refines them: split into a
/// manifold mesh (CGAL's `orient_polygon_soup`), with the split edges and
/// vertices made as sharp as OpenSubdiv makes them, so that the refined
/// points are OpenSubdiv's (each point of a split vertex's copies, once per
/// copy).

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivFunctions
 * What `split_non_manifold()` made: the vertices of the mesh and the point of
 * the soup each one copies.
 */
template <class PolygonMesh>
struct Non_manifold_split
{
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  /// the vertices of the mesh, in the order they were added: the points of
  /// the soup first (vertex i is point i), then the copies
  std::vector<vertex_descriptor> vertices;
  /// the point of the soup of each of `vertices` (i for i < the number of
  /// points)
  std::vector<std::size_t> origin;
  /// the edges of the soup with more than two faces, with two faces that run
  /// along it in the same direction, or of zero length (a face that passes
  /// twice in a row through a point): OpenSubdiv's non-manifold edges
  std::size_t non_manifold_edges = 0;
  /// the points of the soup that are OpenSubdiv's non-manifold vertices
  /// (on a non-manifold edge, or whose faces do not make one fan), and how
  /// many of them were made corners (the others lie on a non-manifold crease)
  std::size_t non_manifold_vertices = 0, corners = 0;
};

/*!
 * \ingroup PkgSubdivErrors
 * Thrown by `split_non_manifold()` for a polygon that passes twice through a
 * point where no halfedge mesh can hold it: its two passes are one vertex
 * (glued by the edges other faces share with them), so the edge between them
 * would go from that vertex to itself.
 */
class Unsplittable_polygon : public Bad_input
{
public:
  Unsplittable_polygon(std::size_t polygon, std::size_t point)
    : Bad_input("split_non_manifold: polygon " + std::to_string(polygon) + " passes through point " +
                std::to_string(point) + " twice on one side of it (no halfedge mesh holds that face)"),
      polygon(polygon), point(point)
  {}
  std::size_t polygon; ///< the index of the polygon in the soup
  std::size_t point;   ///< the index of the point in the soup
};

namespace internal {

// the edges of a soup (unordered vertex pairs) with how many faces run along
// them in each direction
class Soup_edges
{
public:
  template <class PolygonRange>
  explicit Soup_edges(const PolygonRange& polygons)
  {
    for(const auto& polygon : polygons) {
      const std::size_t n = polygon.size();
      for(std::size_t k = 0; k < n; ++k) {
        const std::size_t a = polygon[k], b = polygon[(k + 1) % n];
        if(a == b) { // a zero-length edge (each is an edge of its own for OpenSubdiv)
          m_degenerate.insert(a);
          ++m_degenerate_edges;
          continue;
        }
        Count& count = m_counts[key(a, b)];
        (a < b ? count.forward : count.backward) += 1;
      }
    }
  }

  /// OpenSubdiv's non-manifold edge: more than two faces, two that run along
  /// it the same way, or zero length
  bool is_non_manifold(std::size_t a, std::size_t b) const
  {
    if(a == b)
      return true;
    const auto it = m_counts.find(key(a, b));
    if(it == m_counts.end())
      return false;
    const Count& c = it->second;
    return c.forward + c.backward > 2 || c.forward == 2 || c.backward == 2;
  }
  std::size_t faces(std::size_t a, std::size_t b) const
  {
    const auto it = m_counts.find(key(a, b));
    return it == m_counts.end() ? 0 : it->second.forward + it->second.backward;
  }
  /// whether a face passes twice in a row through point `a`
  bool has_degenerate_edge(std::size_t a) const { return m_degenerate.count(a) != 0; }
  /// how many times a face passes twice in a row through a point
  std::size_t degenerate_edges() const { return m_degenerate_edges; }
  template <class Visit>
  void for_each(const Visit& visit) const
  {
    for(const auto& entry : m_counts)
      visit(entry.first.first, entry.first.second);
  }

private:
  struct Count
  {
    std::size_t forward = 0, backward = 0;
  };
  static std::pair<std::size_t, std::size_t> key(std::size_t a, std::size_t b)
  {
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
  }
  std::map<std::pair<std::size_t, std::size_t>, Count> m_counts;
  std::set<std::size_t> m_degenerate;
  std::size_t m_degenerate_edges = 0;
};

/*
 * A face that passes twice through a point (OpenSubdiv's zero-length,
 * non-manifold edge) cannot be a face of a halfedge mesh: each of its passes
 * becomes its own corner (a new point, `origin` saying which it copies), and
 * the corners of a point are glued back where two faces share an edge of
 * nonzero length at them. What remains apart are the fans of the point; the
 * zero-length edges become edges between two of its copies.
 */
inline void separate_repeated_points(std::vector<std::vector<std::size_t>>& faces, std::vector<std::size_t>& origin)
{
  const std::size_t points = origin.size();
  for(std::vector<std::size_t>& face : faces) {
    const std::vector<std::size_t> original = face;
    for(std::size_t k = 0; k < face.size(); ++k)
      if(std::count(original.begin(), original.end(), original[k]) > 1) {
        face[k] = origin.size();
        origin.push_back(original[k]);
      }
  }
  if(origin.size() == points)
    return;
  std::vector<std::size_t> parent(origin.size());
  for(std::size_t i = 0; i < parent.size(); ++i)
    parent[i] = i;
  const auto root = [&](std::size_t i) {
    while(parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  const auto glue = [&](std::size_t a, std::size_t b) { // the smaller root stays: a point of the soup if there is one
    a = root(a), b = root(b);
    parent[(std::max)(a, b)] = (std::min)(a, b);
  };
  // the corners at the two ends of every edge of nonzero length, by its points
  std::map<std::pair<std::size_t, std::size_t>, std::pair<std::size_t, std::size_t>> first_ends;
  for(const std::vector<std::size_t>& face : faces)
    for(std::size_t k = 0; k < face.size(); ++k) {
      std::size_t a = face[k], b = face[(k + 1) % face.size()];
      if(origin[a] == origin[b])
        continue;
      if(origin[a] > origin[b])
        std::swap(a, b);
      const auto inserted = first_ends.emplace(std::make_pair(origin[a], origin[b]), std::make_pair(a, b));
      if(!inserted.second) {
        glue(inserted.first->second.first, a);
        glue(inserted.first->second.second, b);
      }
    }
  // a point every pass of which was separated takes the first of its copies'
  // numbers; the other copies are numbered after the points
  std::vector<bool> used(points, false);
  for(const std::vector<std::size_t>& face : faces)
    for(std::size_t corner : face)
      if(root(corner) < points)
        used[root(corner)] = true;
  std::vector<std::size_t> number(origin.size(), 0), kept_origin(origin.begin(), origin.begin() + points);
  for(std::size_t i = 0; i < origin.size(); ++i) {
    if(root(i) != i)
      continue;
    if(i < points) {
      number[i] = i;
    } else if(!used[origin[i]]) {
      number[i] = origin[i];
      used[origin[i]] = true;
    } else {
      number[i] = kept_origin.size();
      kept_origin.push_back(origin[i]);
    }
  }
  for(std::vector<std::size_t>& face : faces)
    for(std::size_t& corner : face)
      corner = number[root(corner)];
  origin = std::move(kept_origin);
}

// records the copies `orient_polygon_soup` makes of the non-manifold points
struct Copy_recorder : CGAL::Polygon_mesh_processing::Default_orientation_visitor
{
  std::vector<std::size_t>* origin = nullptr;
  void duplicated_vertex(std::size_t point, std::size_t copy)
  {
    if(origin->size() <= copy)
      origin->resize(copy + 1);
    (*origin)[copy] = (*origin)[point];
  }
};

} // namespace internal

/*!
 * \ingroup PkgSubdivFunctions
 * builds in `mesh` (empty) the polygon soup `points`, `polygons`, which may be
 * non-manifold (an edge with more than two faces, faces that meet at a vertex
 * only, faces that run along an edge in the same direction), split into a
 * manifold mesh as `CGAL::Polygon_mesh_processing::orient_polygon_soup` splits
 * it: it may reverse faces, and copies the points where the split separates
 * faces. OpenSubdiv refines such a soup as it is, with its non-manifold
 * edges infinitely sharp and its non-manifold vertices corners, except a
 * vertex on exactly two non-manifold edges around which the faces make fans
 * from one to the other (a non-manifold crease). The split gives these rules:
 * the split edges are borders (infinitely sharp), a non-manifold edge that
 * stays an interior edge gets sharpness 10 in `edge_sharpness_map`, and every
 * copy of a non-manifold vertex that is not on such a crease gets 10 in
 * `vertex_sharpness_map` (each copy of a crease vertex is a border vertex
 * between its two crease edges: the crease rule). The refined points are
 * then OpenSubdiv's, with as many copies of a point as the vertex has.
 *
 * A polygon that passes twice through a point in a row (a zero-length edge,
 * which OpenSubdiv takes as a non-manifold edge) is kept: each pass is a
 * copy of the point, as if the edge had a length, and each copy is a corner.
 *
 * \tparam PointRange a random-access range of points (`std::vector<Point_3>`),
 *         convertible to the points of `mesh`
 * \tparam PolygonRange a random-access range of polygons, each a range of
 *         indices into `points`
 * \tparam PolygonMesh a model of `MutableFaceGraph`
 * \param points the points of the soup
 * \param polygons its faces, as indices into `points`
 * \param mesh the output, empty
 * \param np `edge_sharpness_map` and `vertex_sharpness_map`: property maps of
 *        `mesh` (valid for the elements added to it, as `Surface_mesh`'s
 *        are), where the sharpness above is written (the larger of it and
 *        the value there); without them only the split is done
 * \returns the vertices made, the point each copies, and the counts
 * \throws Bad_input naming the polygon when one has fewer than three
 *         corners, names a point out of range, or passes twice through a
 *         point along edges that other faces glue into one vertex (no
 *         halfedge mesh holds it: `Unsplittable_polygon`, which names both),
 *         and when `mesh` is not empty
 */
template <class PointRange, class PolygonRange, class PolygonMesh,
          class NamedParameters = parameters::Default_named_parameters>
Non_manifold_split<PolygonMesh> split_non_manifold(const PointRange& points, const PolygonRange& polygons,
                                                   PolygonMesh& mesh,
                                                   const NamedParameters& np = parameters::default_values())
{
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  internal::require(CGAL::is_empty(mesh), "split_non_manifold: the output mesh must be empty");
  std::vector<std::vector<std::size_t>> faces;
  faces.reserve(polygons.size());
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    std::vector<std::size_t> face(polygons[f].begin(), polygons[f].end());
    const std::string which = "split_non_manifold: polygon " + std::to_string(f);
    internal::require(face.size() >= 3, which + " has fewer than three corners");
    for(std::size_t k = 0; k < face.size(); ++k)
      internal::require(face[k] < points.size(), which + " names point " + std::to_string(face[k]) +
                                                   ", out of range (" + std::to_string(points.size()) + " points)");
    faces.push_back(std::move(face));
  }
  const internal::Soup_edges soup_edges(faces);

  Non_manifold_split<PolygonMesh> split;
  for(std::size_t i = 0; i < points.size(); ++i)
    split.origin.push_back(i);
  internal::separate_repeated_points(faces, split.origin);
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(std::size_t corner : faces[f])
      if(std::count(faces[f].begin(), faces[f].end(), corner) != 1)
        throw Unsplittable_polygon(f, split.origin[corner]);
  std::vector<typename PointRange::value_type> split_points(points.begin(), points.end());
  for(std::size_t i = points.size(); i < split.origin.size(); ++i)
    split_points.push_back(points[split.origin[i]]);
  internal::Copy_recorder recorder;
  recorder.origin = &split.origin;
  CGAL::Polygon_mesh_processing::orient_polygon_soup(split_points, faces, CGAL::parameters::visitor(recorder));
  split.origin.resize(split_points.size());
  internal::require(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(faces),
                    "split_non_manifold: the soup is still not a polygon mesh once split");

  // the mesh: vertex i is split point i
  const auto vpm = get(CGAL::vertex_point, mesh);
  for(const auto& p : split_points) {
    split.vertices.push_back(add_vertex(mesh));
    put(vpm, split.vertices.back(), p);
  }
  for(const std::vector<std::size_t>& face : faces) {
    std::vector<vertex_descriptor> corners;
    for(std::size_t i : face)
      corners.push_back(split.vertices[i]);
    CGAL::Euler::add_face(corners, mesh);
  }

  // OpenSubdiv's non-manifold vertices: on a non-manifold edge, or copied
  std::vector<std::vector<std::size_t>> non_manifold_edges_at(points.size()), copies(points.size());
  split.non_manifold_edges = soup_edges.degenerate_edges();
  soup_edges.for_each([&](std::size_t a, std::size_t b) {
    if(soup_edges.is_non_manifold(a, b)) {
      ++split.non_manifold_edges;
      non_manifold_edges_at[a].push_back(b);
      non_manifold_edges_at[b].push_back(a);
    }
  });
  for(std::size_t i = 0; i < split.vertices.size(); ++i)
    copies[split.origin[i]].push_back(i);
  const auto origin_map = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  for(std::size_t i = 0; i < split.vertices.size(); ++i)
    put(origin_map, split.vertices[i], split.origin[i]);
  const auto origin_of = [&](vertex_descriptor v) { return get(origin_map, v); };
  const auto is_split_edge = [&](typename GT::halfedge_descriptor h) {
    return CGAL::is_border(edge(h, mesh), mesh) ||
           soup_edges.is_non_manifold(origin_of(source(h, mesh)), origin_of(target(h, mesh)));
  };
  // a non-manifold crease at point p: two non-manifold edges with as many
  // faces, its other edges with two faces, and every copy of p between the
  // two (its only split edges)
  const auto on_crease = [&](std::size_t p) {
    const std::vector<std::size_t>& crease = non_manifold_edges_at[p];
    if(crease.size() != 2 || soup_edges.has_degenerate_edge(p) ||
       soup_edges.faces(p, crease[0]) != soup_edges.faces(p, crease[1]))
      return false;
    for(std::size_t copy : copies[p]) {
      std::vector<std::size_t> ends;
      for(auto h : CGAL::halfedges_around_target(split.vertices[copy], mesh)) {
        const std::size_t other = origin_of(source(h, mesh));
        if(is_split_edge(h))
          ends.push_back(other);
        else if(soup_edges.faces(p, other) != 2)
          return false;
      }
      std::sort(ends.begin(), ends.end());
      if(ends != std::vector<std::size_t>{std::min(crease[0], crease[1]), std::max(crease[0], crease[1])})
        return false;
    }
    return true;
  };

  constexpr bool has_edge_map =
    !parameters::is_default_parameter<NamedParameters, internal::edge_sharpness_map_t>::value;
  constexpr bool has_vertex_map =
    !parameters::is_default_parameter<NamedParameters, internal::vertex_sharpness_map_t>::value;
  for(std::size_t p = 0; p < points.size(); ++p) {
    if(non_manifold_edges_at[p].empty() && copies[p].size() == 1 && !soup_edges.has_degenerate_edge(p))
      continue;
    ++split.non_manifold_vertices;
    if(on_crease(p))
      continue;
    ++split.corners;
    if constexpr(has_vertex_map) {
      const auto vertices = parameters::get_parameter(np, internal::vertex_sharpness_map_t());
      using S = typename boost::property_traits<std::remove_const_t<decltype(vertices)>>::value_type;
      for(std::size_t copy : copies[p])
        put(vertices, split.vertices[copy], (std::max)(S(get(vertices, split.vertices[copy])), S(10)));
    }
  }
  if constexpr(has_edge_map) {
    const auto edges_map = parameters::get_parameter(np, internal::edge_sharpness_map_t());
    using S = typename boost::property_traits<std::remove_const_t<decltype(edges_map)>>::value_type;
    for(auto e : edges(mesh)) {
      const auto h = halfedge(e, mesh);
      if(!CGAL::is_border(e, mesh) &&
         soup_edges.is_non_manifold(origin_of(source(h, mesh)), origin_of(target(h, mesh))))
        put(edges_map, e, (std::max)(S(get(edges_map, e)), S(10)));
    }
  }
  return split;
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_SPLIT_NON_MANIFOLD_H
