// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "surface_from_soup.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Subdiv/split_non_manifold.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <utility>

namespace cgal_subdiv {
namespace {

using Point = Double_kernel::Point_3;
using Polygon = std::vector<std::size_t>;

std::string point_text(const Point& p)
{
  std::ostringstream out;
  out.precision(10);
  out << '(' << p.x() << ' ' << p.y() << ' ' << p.z() << ')';
  return out.str();
}

using Polygon = std::vector<std::size_t>;

// "vertex 7 (0 1 0)": the number the file gives it, if known, and its point
std::string vertex_name(std::size_t v, const std::vector<Point>& points, const std::vector<std::size_t>& file_numbers)
{
  return "vertex " + (v < file_numbers.size() ? std::to_string(file_numbers[v]) + " " : std::string()) +
         point_text(points[v]);
}

// the first face that passes twice through a vertex (a zero-length edge,
// which no halfedge mesh holds), named; empty if there is none
std::string repeated_vertex_problem(const std::vector<Point>& points, const std::vector<Polygon>& polygons,
                                    const std::vector<std::size_t>& file_numbers)
{
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    Polygon sorted = polygons[f]; // its size and indices checked by the reader
    std::sort(sorted.begin(), sorted.end());
    const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    if(twice != sorted.end())
      return "face " + std::to_string(f) + " passes twice through " + vertex_name(*twice, points, file_numbers);
  }
  return "";
}

/*
 * Why a polygon soup is not a manifold polygon mesh, naming the first face,
 * edge or vertex at fault: vertex v by its number in the file
 * (`file_numbers[v]`, if there is one) and its coordinates.
 * Empty if nothing was found.
 */
std::string soup_problem(const std::vector<Point>& points, const std::vector<Polygon>& polygons,
                         const std::vector<std::size_t>& file_numbers)
{
  const auto name = [&](std::size_t v) { return vertex_name(v, points, file_numbers); };
  const std::string repeated = repeated_vertex_problem(points, polygons, file_numbers);
  if(!repeated.empty())
    return repeated;
  // edges: how many faces use each, and in which direction
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> directed;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> undirected;
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    const Polygon& poly = polygons[f];
    for(std::size_t k = 0; k < poly.size(); ++k) {
      const std::size_t a = poly[k], b = poly[(k + 1) % poly.size()];
      directed[{a, b}].push_back(f);
      ++undirected[{std::min(a, b), std::max(a, b)}];
    }
  }
  for(const auto& [edge, count] : undirected)
    if(count > 2)
      return "the edge from " + name(edge.first) + " to " + name(edge.second) + " belongs to " + std::to_string(count) +
             " faces";
  for(const auto& [edge, faces] : directed)
    if(faces.size() > 1)
      return "faces " + std::to_string(faces[0]) + " and " + std::to_string(faces[1]) +
             " are not consistently oriented (both run from " + name(edge.first) + " to " + name(edge.second) + ")";
  // vertices: the corners around a vertex must form one fan (corners that
  // share an edge at the vertex are joined)
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> corners(points.size()); // (prev, next)
  for(const Polygon& poly : polygons)
    for(std::size_t k = 0; k < poly.size(); ++k)
      corners[poly[k]].push_back({poly[(k + poly.size() - 1) % poly.size()], poly[(k + 1) % poly.size()]});
  for(std::size_t v = 0; v < points.size(); ++v) {
    const auto& around = corners[v];
    if(around.empty())
      continue;
    std::vector<std::size_t> parent(around.size());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    const auto root = [&](std::size_t i) {
      while(parent[i] != i)
        i = parent[i] = parent[parent[i]];
      return i;
    };
    std::map<std::size_t, std::size_t> by_neighbour;
    for(std::size_t c = 0; c < around.size(); ++c)
      for(std::size_t w : {around[c].first, around[c].second}) {
        const auto found = by_neighbour.find(w);
        if(found == by_neighbour.end())
          by_neighbour[w] = c;
        else
          parent[root(c)] = root(found->second);
      }
    std::set<std::size_t> fans;
    for(std::size_t c = 0; c < around.size(); ++c)
      fans.insert(root(c));
    if(fans.size() > 1)
      return name(v) + " is non-manifold (its faces form " + std::to_string(fans.size()) + " separate fans)";
  }
  return "";
}

// the soup in CGAL's form, without the vertices that no face uses (with a
// note: OpenSubdiv accepts them, and they play no part in any scheme)
void to_cgal_soup(const Mesh_soup& soup, const std::string& path, std::size_t first_number, std::vector<Point>& points,
                  std::vector<Polygon>& polygons, std::vector<std::size_t>& file_numbers,
                  std::vector<std::string>& notes)
{
  constexpr std::size_t unused = static_cast<std::size_t>(-1);
  std::vector<std::size_t> new_index(soup.points.size(), unused);
  for(std::size_t i : soup.indices)
    new_index[i] = 0;
  std::size_t kept = 0;
  for(std::size_t v = 0; v < soup.points.size(); ++v)
    if(new_index[v] != unused) {
      new_index[v] = kept++;
      file_numbers.push_back(first_number + v);
      const auto& p = soup.points[v];
      points.emplace_back(p[0], p[1], p[2]);
    }
  if(kept < soup.points.size())
    notes.push_back("dropped the " + std::to_string(soup.points.size() - kept) + " vertices of '" + path +
                    "' that no face uses (of " + std::to_string(soup.points.size()) + ")");
  polygons.resize(soup.number_of_faces());
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t k = soup.face_starts[f]; k < soup.face_starts[f + 1]; ++k)
      polygons[f].push_back(new_index[soup.indices[k]]);
}

// the soup split by CGAL::Subdiv::split_non_manifold, with OpenSubdiv's
// sharpness of its non-manifold edges and vertices in the tag maps
// (`origin`: the point of every vertex of the mesh)
Surface split_soup(const std::vector<Point>& points, const std::vector<Polygon>& polygons, const std::string& path,
                   std::vector<std::string>& notes, const std::vector<std::size_t>& file_numbers,
                   std::vector<std::size_t>* file_numbers_out, std::vector<std::size_t>& origin)
{
  Surface mesh;
  const auto edges = mesh.add_property_map<Surface::Edge_index, double>(edge_sharpness_name, 0).first;
  const auto vertices = mesh.add_property_map<Surface::Vertex_index, double>(vertex_sharpness_name, 0).first;
  CGAL::Subdiv::Non_manifold_split<Surface> split;
  try {
    split = CGAL::Subdiv::split_non_manifold(
      points, polygons, mesh, CGAL::Subdiv::parameters::edge_sharpness_map(edges).vertex_sharpness_map(vertices));
  } catch(const CGAL::Subdiv::Unsplittable_polygon& e) { // the reader checked everything else
    throw Input_error("'" + path + "' cannot be split into a manifold mesh (--split-non-manifold): face " +
                      std::to_string(e.polygon) + " passes twice through " +
                      vertex_name(e.point, points, file_numbers) +
                      ", and its other faces join the two passes into one vertex: the edge between them would "
                      "go from that vertex to itself, which no halfedge mesh holds");
  }
  const auto count = [](std::size_t n, const std::string& one, const std::string& several) {
    return std::to_string(n) + " " + (n == 1 ? one : several);
  };
  notes.push_back("split the non-manifold soup of '" + path +
                  "': " + count(split.non_manifold_edges, "non-manifold edge", "non-manifold edges") + ", " +
                  count(split.non_manifold_vertices, "non-manifold vertex", "non-manifold vertices") + " (" +
                  std::to_string(split.corners) + " made corners), " +
                  count(split.vertices.size() - points.size(), "vertex", "vertices") + " copied");
  origin = split.origin;
  if(file_numbers_out) {
    file_numbers_out->clear();
    for(std::size_t origin : split.origin)
      file_numbers_out->push_back(file_numbers[origin]);
  }
  return mesh;
}

// the texture coordinates of the soup's corners in the maps of the mesh,
// whose face f is polygon f, and whose vertex v is point origin[v]
void add_texture_points(Surface& mesh, const Mesh_soup& soup, const std::vector<Polygon>& polygons,
                        const std::vector<std::size_t>& origin)
{
  if(soup.texture_indices.empty())
    return;
  Texture_point_map values = mesh.add_property_map<Surface::Halfedge_index, Texture_point>(texture_point_name).first;
  Texture_index_map indices = mesh.add_property_map<Surface::Halfedge_index, std::size_t>(texture_index_name).first;
  for(const Surface::Face_index f : mesh.faces()) {
    const Polygon& polygon = polygons[f.idx()];
    for(const Surface::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      // the corner of the polygon at the halfedge's target (a face passes once through a point)
      const std::size_t k =
        static_cast<std::size_t>(std::find(polygon.begin(), polygon.end(), origin[mesh.target(h)]) - polygon.begin());
      if(k == polygon.size()) // face f is made of polygon f, whose points it keeps
        throw Input_error("face " + std::to_string(f.idx()) +
                          " of the mesh lost a point of its polygon (an internal error: please report it)");
      const std::size_t t = soup.texture_indices[soup.face_starts[f.idx()] + k];
      values[h] = Texture_point(soup.texture_points[t][0], soup.texture_points[t][1]);
      indices[h] = t;
    }
  }
}

// the map `name` of the mesh, whose vertex v is the point of the file
// numbered file_numbers[origin[v]], holding `convert` of that point's value
// in `of_point` (nothing if it is empty)
template <class Value, class Source, class Convert>
void add_vertex_map(Surface& mesh, const char* name, const std::vector<Source>& of_point,
                    const std::vector<std::size_t>& file_numbers, std::size_t first_number,
                    const std::vector<std::size_t>& origin, Convert convert)
{
  if(of_point.empty())
    return;
  auto map = mesh.add_property_map<Surface::Vertex_index, Value>(name).first;
  for(const Surface::Vertex_index v : mesh.vertices())
    map[v] = convert(of_point[file_numbers[origin[v]] - first_number]);
}

// the normal of every point of the soup that a face uses: the normalised
// mean of the unit normals its corners reference (empty if the soup keeps
// none). A mean rather than one corner's pick: split normals (a hard edge, a
// flat-shaded export) have no single value at a vertex, and the surface
// refined is smooth there anyway. A note counts the points that had them.
std::vector<Normal> point_normals(const Mesh_soup& soup, const std::string& path, std::vector<std::string>& notes)
{
  if(soup.normal_indices.empty())
    return {};
  std::vector<Normal> sum(soup.points.size(), CGAL::NULL_VECTOR);
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> first(soup.points.size(), none); // the first normal referenced at the point
  std::vector<bool> split(soup.points.size(), false);
  const auto unit = [&soup](std::size_t index) {
    const auto& n = soup.normals[index];
    return unit_or_zero(Normal(n[0], n[1], n[2]));
  };
  for(std::size_t k = 0; k < soup.indices.size(); ++k) {
    const std::size_t point = soup.indices[k], index = soup.normal_indices[k];
    sum[point] = sum[point] + unit(index);
    if(first[point] == none)
      first[point] = index;
    else if(unit(index) != unit(first[point]))
      split[point] = true;
  }
  for(Normal& n : sum)
    n = unit_or_zero(n);
  const std::size_t splits = static_cast<std::size_t>(std::count(split.begin(), split.end(), true));
  if(splits > 0)
    notes.push_back("averaged the normals (vn) of '" + path + "' at " + std::to_string(splits) +
                    (splits == 1 ? " vertex whose corners reference" : " vertices whose corners reference") +
                    " different ones (split normals): the normals are vertex data, as the refined surface is smooth");
  return sum;
}

// the colours and the normals of the soup's points in the maps of the mesh,
// whose vertex v is the point of the file numbered file_numbers[origin[v]]
void add_vertex_data(Surface& mesh, const Mesh_soup& soup, const std::string& path,
                     const std::vector<std::size_t>& file_numbers, std::size_t first_number,
                     const std::vector<std::size_t>& origin, std::vector<std::string>& notes)
{
  add_vertex_map<CGAL::IO::Color>(mesh, colour_name, soup.colours, file_numbers, first_number, origin,
                                  [](const auto& c) { return CGAL::IO::Color(c[0], c[1], c[2], c[3]); });
  add_vertex_map<Normal>(mesh, normal_name, point_normals(soup, path, notes), file_numbers, first_number, origin,
                         [](const Normal& n) { return n; });
}

template <class Value>
std::optional<Surface::Property_map<Surface::Vertex_index, Value>> vertex_map_of(const Surface& mesh, const char* name)
{
  const auto map = mesh.property_map<Surface::Vertex_index, Value>(name);
  return map.second ? std::optional(map.first) : std::nullopt;
}

} // namespace

std::optional<Colour_map> colours_of(const Surface& mesh)
{
  return vertex_map_of<CGAL::IO::Color>(mesh, colour_name);
}

std::optional<Normal_map> normals_of(const Surface& mesh)
{
  return vertex_map_of<Normal>(mesh, normal_name);
}

void remove_normals(Surface& mesh)
{
  if(std::optional<Normal_map> normals = normals_of(mesh))
    mesh.remove_property_map(*normals);
}

Normal unit_or_zero(const Normal& v)
{
  const double scale = std::max({std::abs(v.x()), std::abs(v.y()), std::abs(v.z())});
  if(!(scale > 0))
    return CGAL::NULL_VECTOR;
  const Normal scaled = v / scale;
  return scaled / std::sqrt(scaled.squared_length());
}

void remove_colours(Surface& mesh)
{
  if(std::optional<Colour_map> colours = colours_of(mesh))
    mesh.remove_property_map(*colours);
}

bool has_texture_points(const Surface& mesh)
{
  return mesh.property_map<Surface::Halfedge_index, Texture_point>(texture_point_name).second &&
         mesh.property_map<Surface::Halfedge_index, std::size_t>(texture_index_name).second;
}

void remove_texture_points(Surface& mesh)
{
  if(auto points = mesh.property_map<Surface::Vertex_index, std::size_t>(soup_point_name); points.second)
    mesh.remove_property_map(points.first);
  if(auto values = mesh.property_map<Surface::Halfedge_index, Texture_point>(texture_point_name); values.second)
    mesh.remove_property_map(values.first);
  if(auto indices = mesh.property_map<Surface::Halfedge_index, std::size_t>(texture_index_name); indices.second)
    mesh.remove_property_map(indices.first);
}

Surface surface_from_soup(const Mesh_soup& soup, const std::string& path, Mesh_format format, Soup_fix fix,
                          std::vector<std::string>& notes, std::vector<std::size_t>* file_numbers_out)
{
  const bool repair = fix == Soup_fix::repair;
  notes.insert(notes.end(), soup.notes.begin(), soup.notes.end());
  if(!soup.tags.empty())
    notes.push_back("ignored " + std::to_string(soup.tags.size()) +
                    (soup.tags.size() == 1 ? " tag line" : " tag lines") + " (t) of '" + path +
                    "': creases, corners and holes are not supported yet, the surface is refined smooth");
  if(!soup.texture_indices.empty() && repair)
    notes.push_back("ignored the " + std::to_string(soup.texture_points.size()) + " texture coordinates (vt) of '" +
                    path + "': --repair reorders the faces they belong to");
  if(!soup.colours.empty() && repair)
    notes.push_back("ignored the vertex colours of '" + path + "': --repair merges and splits vertices");
  if(!soup.normal_indices.empty() && repair)
    notes.push_back("ignored the normals (vn) of '" + path + "': --repair merges and splits vertices");
  if(soup.number_of_faces() == 0)
    throw Input_error("'" + path + "' holds no faces");
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  std::vector<std::size_t> file_numbers; // of the vertices kept (OBJ counts from 1)
  const std::size_t first_number = format == Mesh_format::obj ? 1 : 0;
  to_cgal_soup(soup, path, first_number, points, polygons, file_numbers, notes);
  namespace PMP = CGAL::Polygon_mesh_processing;
  if(repair) {
    PMP::repair_polygon_soup(points, polygons);
    PMP::orient_polygon_soup(points, polygons);
    file_numbers.clear(); // the repair merges and splits vertices
    if(polygons.empty())
      throw Input_error("'" + path + "' holds no faces once repaired (every face was degenerate)");
  }
  const bool manifold = PMP::is_polygon_soup_a_polygon_mesh(polygons);
  if(!manifold && fix == Soup_fix::split_non_manifold) {
    std::vector<std::size_t> origin; // the point of every vertex of the mesh
    Surface mesh = split_soup(points, polygons, path, notes, file_numbers, file_numbers_out, origin);
    add_texture_points(mesh, soup, polygons, origin);
    if(has_texture_points(mesh)) {
      auto point_of = mesh.add_property_map<Surface::Vertex_index, std::size_t>(soup_point_name).first;
      for(const Surface::Vertex_index v : mesh.vertices())
        point_of[v] = origin[v];
    }
    add_vertex_data(mesh, soup, path, file_numbers, first_number, origin, notes);
    return mesh;
  }
  if(!manifold) {
    const std::string problem = soup_problem(points, polygons, file_numbers);
    throw Input_error("'" + path + "' is not a manifold polygon mesh" + (problem.empty() ? "" : ": " + problem) +
                      (repair ? ""
                              : " (--split-non-manifold refines it as OpenSubdiv does, --repair makes a manifold "
                                "mesh of it)"));
  }
  Surface mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(repair)
    notes.push_back("read '" + path +
                    "' as a repaired, oriented polygon soup: " + std::to_string(mesh.number_of_vertices()) + " V, " +
                    std::to_string(mesh.number_of_edges()) + " E, " + std::to_string(mesh.number_of_faces()) + " F");
  if(!repair) { // polygon_soup_to_polygon_mesh makes vertex i of point i
    std::vector<std::size_t> origin(points.size());
    std::iota(origin.begin(), origin.end(), std::size_t(0));
    add_texture_points(mesh, soup, polygons, origin);
    add_vertex_data(mesh, soup, path, file_numbers, first_number, origin, notes);
  }
  if(file_numbers_out)
    *file_numbers_out = std::move(file_numbers);
  return mesh;
}

} // namespace cgal_subdiv
