// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "surface.h"
#include "files.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/mesh_checks.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <utility>

namespace cgal_subdiv {
namespace {

namespace fs = std::filesystem;
using Point = Double_kernel::Point_3;

const char* format_name(Mesh_format format)
{
  switch(format) {
    case Mesh_format::off:
      return "OFF";
    case Mesh_format::obj:
      return "OBJ";
    case Mesh_format::ply:
      return "PLY";
    case Mesh_format::stl:
      return "STL";
  }
  return "?";
}

// CGAL's readers may talk on std::cerr; keep it off the one-line error rule,
// and keep what they said for the message.
class Captured_cerr
{
public:
  Captured_cerr() : m_old(std::cerr.rdbuf(m_buffer.rdbuf())) {}
  ~Captured_cerr() { std::cerr.rdbuf(m_old); }
  Captured_cerr(const Captured_cerr&) = delete;
  Captured_cerr& operator=(const Captured_cerr&) = delete;
  // the first line CGAL wrote, if any
  std::string first_line() const
  {
    std::istringstream in(m_buffer.str());
    for(std::string line; std::getline(in, line);)
      if(line.find_first_not_of(" \t\r") != std::string::npos)
        return line;
    return "";
  }

private:
  std::ostringstream m_buffer;
  std::streambuf* m_old;
};

std::string point_text(const Point& p)
{
  std::ostringstream out;
  out.precision(10);
  out << '(' << p.x() << ' ' << p.y() << ' ' << p.z() << ')';
  return out.str();
}

using Polygon = std::vector<std::size_t>;

/*
 * Why a polygon soup is not a manifold polygon mesh, naming the first face,
 * edge or vertex at fault by its coordinates (which every format shares).
 * Empty if nothing was found.
 */
std::string soup_problem(const std::vector<Point>& points, const std::vector<Polygon>& polygons)
{
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    const Polygon& poly = polygons[f];
    if(poly.size() < 3)
      return "face " + std::to_string(f) + " has only " + std::to_string(poly.size()) + " vertices";
    for(std::size_t i : poly)
      if(i >= points.size())
        return "face " + std::to_string(f) + " uses vertex " + std::to_string(i) + ", but there are only " +
               std::to_string(points.size());
    Polygon sorted = poly;
    std::sort(sorted.begin(), sorted.end());
    const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    if(twice != sorted.end())
      return "face " + std::to_string(f) + " passes twice through vertex " + point_text(points[*twice]);
  }
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
      return "the edge from " + point_text(points[edge.first]) + " to " + point_text(points[edge.second]) +
             " belongs to " + std::to_string(count) + " faces";
  for(const auto& [edge, faces] : directed)
    if(faces.size() > 1)
      return "faces " + std::to_string(faces[0]) + " and " + std::to_string(faces[1]) +
             " are not consistently oriented (both run from " + point_text(points[edge.first]) + " to " +
             point_text(points[edge.second]) + ")";
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
      return "vertex " + point_text(points[v]) + " is non-manifold (its faces form " + std::to_string(fans.size()) +
             " separate fans)";
  }
  return "";
}

// Surface_mesh readers keep what a file holds besides the points (PLY
// properties, OFF colours and normals); the schemes do not carry them, so the
// mesh is copied without them.
bool has_extra_properties(const Surface& mesh)
{
  const std::set<std::string> internal = {"v:connectivity", "v:point",        "v:removed", "h:connectivity",
                                          "e:removed",      "f:connectivity", "f:removed"};
  std::vector<std::string> names = mesh.properties<Surface::Vertex_index>();
  for(const auto& more : {mesh.properties<Surface::Halfedge_index>(), mesh.properties<Surface::Edge_index>(),
                          mesh.properties<Surface::Face_index>()})
    names.insert(names.end(), more.begin(), more.end());
  for(const std::string& name : names)
    if(!internal.count(name))
      return true;
  return false;
}

void check_readable(const std::string& path)
{
  std::error_code ec;
  if(fs::is_directory(path, ec))
    throw Input_error("cannot read '" + path + "': it is a directory");
  std::ifstream probe(path, std::ios::binary);
  if(!probe)
    throw Input_error("cannot read '" + path + "': " + std::strerror(errno));
}

std::string lower(std::string s)
{
  for(char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

} // namespace

std::string list_surface_schemes()
{
  const std::vector<std::string>& names = surface_scheme_keywords();
  std::string list;
  for(std::size_t i = 0; i < names.size(); ++i)
    list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return list;
}

const Surface_scheme& find_surface_scheme(const std::string& name)
{
  for(const Surface_scheme& scheme : surface_schemes())
    if(scheme.name == name)
      return scheme;
  const std::vector<std::string>& known = surface_scheme_keywords();
  if(std::find(known.begin(), known.end(), name) != known.end())
    throw Input_error("the scheme '" + name + "' is not yet available in this build of cgal-subdiv");
  throw Usage_error("unknown scheme '" + name + "' (expected " + list_surface_schemes() + ")");
}

Mesh_format mesh_format(const std::string& path, const std::string& role)
{
  const std::string extension = lower(fs::path(path).extension().string());
  if(extension == ".off")
    return Mesh_format::off;
  if(extension == ".obj")
    return Mesh_format::obj;
  if(extension == ".ply")
    return Mesh_format::ply;
  if(extension == ".stl")
    return Mesh_format::stl;
  throw Usage_error(role + " '" + path + "': unknown format " +
                    (extension.empty() ? std::string("(no extension)") : "'" + extension + "'") +
                    " (expected .off, .obj, .ply or .stl)");
}

Mesh_counts counts(const Surface& mesh)
{
  return Mesh_counts{mesh.number_of_vertices(), mesh.number_of_edges(), mesh.number_of_faces()};
}

std::string describe(const Mesh_counts& c)
{
  return std::to_string(c.vertices) + " V, " + std::to_string(c.edges) + " E, " + std::to_string(c.faces) + " F";
}

Surface read_surface(const std::string& path, bool repair, std::vector<std::string>& notes)
{
  const Mesh_format format = mesh_format(path, "INPUT");
  check_readable(path);
  Surface mesh;
  bool ok = false;
  std::string said;
  {
    Captured_cerr quiet;
    if(repair)
      ok = CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(path, mesh, CGAL::parameters::verbose(true));
    else
      ok = CGAL::IO::read_polygon_mesh(path, mesh, CGAL::parameters::verbose(true));
    said = quiet.first_line();
  }
  if(!ok) {
    // find out why: a file that does not parse, or a soup that is no manifold mesh
    std::vector<Point> points;
    std::vector<Polygon> polygons;
    bool soup = false;
    {
      Captured_cerr quiet;
      soup = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(true));
      if(said.empty())
        said = quiet.first_line();
    }
    if(!soup || (points.empty() && polygons.empty()))
      throw Input_error(
        "cannot read '" + path + "' as " + format_name(format) + ": " +
        (said.empty() ? "CGAL's reader rejects it (malformed or truncated)" : "CGAL's reader says \"" + said + "\""));
    const std::string problem = soup_problem(points, polygons);
    throw Input_error("'" + path + "' is not a manifold polygon mesh" + (problem.empty() ? "" : ": " + problem) +
                      (repair ? "" : " (--repair makes one of it)"));
  }
  if(mesh.number_of_faces() == 0)
    throw Input_error("'" + path + "' holds no faces");
  if(repair)
    notes.push_back("read '" + path + "' as a repaired, oriented polygon soup: " + describe(counts(mesh)));
  if(has_extra_properties(mesh)) {
    Surface plain;
    CGAL::copy_face_graph(mesh, plain);
    notes.push_back("ignored the properties of '" + path + "' other than the points (colours, normals, ...)");
    return plain;
  }
  return mesh;
}

void write_surface(const Surface& mesh, const std::string& path)
{
  const Mesh_format format = mesh_format(path, "OUTPUT");
  Atomic_file file(path);
  std::ostream& out = file.stream();
  const auto np = CGAL::parameters::stream_precision(17);
  bool ok = false;
  {
    Captured_cerr quiet;
    switch(format) {
      case Mesh_format::off:
        ok = CGAL::IO::write_OFF(out, mesh, np);
        break;
      case Mesh_format::obj:
        ok = CGAL::IO::write_OBJ(out, mesh, np);
        break;
      case Mesh_format::ply:
        ok = CGAL::IO::write_PLY(out, mesh, np);
        break;
      case Mesh_format::stl:
        // STL holds triangles only: split the faces of a copy
        if(CGAL::is_triangle_mesh(mesh)) {
          ok = CGAL::IO::write_STL(out, mesh, np);
        } else {
          Surface triangles = mesh;
          CGAL::Polygon_mesh_processing::triangulate_faces(triangles);
          ok = CGAL::IO::write_STL(out, triangles, np);
        }
        break;
    }
  }
  if(!ok)
    throw Input_error("cannot write '" + path + "' as " + format_name(format));
  file.commit();
}

Surface_result subdivide_surface(Surface& mesh, const Surface_scheme& scheme, int levels,
                                 const Level_callback& on_level)
{
  Surface_result result;
  result.in = counts(mesh);
  // refuse before any work (the library would refuse too, level by level)
  CGAL::Subdiv::internal::check_output_faces(scheme.name, static_cast<double>(result.in.faces), scheme.face_growth,
                                             levels);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto seconds = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  if(on_level && scheme.level_by_level && levels > 1) {
    for(int level = 1; level <= levels; ++level) {
      scheme.run(mesh, 1);
      on_level(level, counts(mesh), seconds());
    }
  } else {
    scheme.run(mesh, levels);
    if(on_level && levels > 0)
      on_level(levels, counts(mesh), seconds());
  }
  result.seconds = seconds();
  result.out = counts(mesh);
  return result;
}

} // namespace cgal_subdiv
