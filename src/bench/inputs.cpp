// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: the inputs (see inputs.h and src/bench/README.md).
#include "inputs.h"
#include "../cli/mesh_soup.h"

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Subdiv/mark_sharp_edges.h>
#include <CGAL/Subdiv/surface_subdivision.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <random>

namespace subdiv_bench {
namespace {

using vertex_descriptor = Mesh::Vertex_index;
const double pi = 3.14159265358979323846;

Point torus_point(double u, double v, double R, double r)
{
  return Point((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
}

// an nu x nv torus grid of quads, or of triangles along random diagonals
// (the vertices of a triangle grid are jittered)
Mesh torus(int nu, int nv, bool triangles, std::mt19937& random)
{
  Mesh mesh;
  std::vector<vertex_descriptor> v(static_cast<std::size_t>(nu * nv));
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j) {
      const double du = triangles ? jitter(random) : 0, dv = triangles ? jitter(random) : 0;
      v[static_cast<std::size_t>(i * nv + j)] =
        mesh.add_vertex(torus_point(2 * pi * (i + du) / nu, 2 * pi * (j + dv) / nv, 1.0, 0.4));
    }
  const auto at = [&](int i, int j) { return v[static_cast<std::size_t>((i % nu) * nv + (j % nv))]; };
  std::bernoulli_distribution coin(0.5);
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j) {
      const vertex_descriptor a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if(!triangles) {
        mesh.add_face(a, b, c, d);
      } else if(coin(random)) {
        mesh.add_face(a, b, c);
        mesh.add_face(a, c, d);
      } else {
        mesh.add_face(a, b, d);
        mesh.add_face(b, c, d);
      }
    }
  return mesh;
}

// a closed torus of triangles, quads, pentagons and hexagons: the cells of an
// nu x nv grid (nu even) are taken in pairs along u, and each pair becomes two
// quads, a hexagon, a pentagon and a triangle, or four triangles
Mesh mixed_torus(int nu, int nv, std::mt19937& random)
{
  Mesh mesh;
  std::vector<vertex_descriptor> v(static_cast<std::size_t>(nu * nv));
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
      v[static_cast<std::size_t>(i * nv + j)] =
        mesh.add_vertex(torus_point(2 * pi * i / nu, 2 * pi * j / nv, 1.0, 0.4));
  const auto at = [&](int i, int j) { return v[static_cast<std::size_t>((i % nu) * nv + (j % nv))]; };
  std::uniform_int_distribution<int> pick(0, 3);
  for(int i = 0; i < nu; i += 2)
    for(int j = 0; j < nv; ++j) {
      const vertex_descriptor a = at(i, j), b = at(i + 1, j), e = at(i + 2, j);
      const vertex_descriptor d = at(i, j + 1), c = at(i + 1, j + 1), f = at(i + 2, j + 1);
      switch(pick(random)) {
        case 0:
          mesh.add_face(a, b, c, d);
          mesh.add_face(b, e, f, c);
          break;
        case 1:
          mesh.add_face(std::vector<vertex_descriptor>{a, b, e, f, c, d});
          break;
        case 2:
          mesh.add_face(std::vector<vertex_descriptor>{a, b, e, f, c});
          mesh.add_face(a, c, d);
          break;
        default:
          mesh.add_face(a, b, c);
          mesh.add_face(a, c, d);
          mesh.add_face(b, e, c);
          mesh.add_face(e, f, c);
      }
    }
  return mesh;
}

// an open n x n patch of a wavy surface, triangles along random diagonals
Mesh border_patch(int n, std::mt19937& random)
{
  Mesh mesh;
  std::vector<vertex_descriptor> v(static_cast<std::size_t>((n + 1) * (n + 1)));
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for(int i = 0; i <= n; ++i)
    for(int j = 0; j <= n; ++j) {
      const bool inside = i > 0 && i < n && j > 0 && j < n;
      const double x = (i + (inside ? jitter(random) : 0)) / n, y = (j + (inside ? jitter(random) : 0)) / n;
      v[static_cast<std::size_t>(i * (n + 1) + j)] =
        mesh.add_vertex(Point(x, y, 0.1 * std::sin(6 * x) * std::cos(5 * y)));
    }
  const auto at = [&](int i, int j) { return v[static_cast<std::size_t>(i * (n + 1) + j)]; };
  std::bernoulli_distribution coin(0.5);
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j) {
      const vertex_descriptor a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if(coin(random)) {
        mesh.add_face(a, b, c);
        mesh.add_face(a, c, d);
      } else {
        mesh.add_face(a, b, d);
        mesh.add_face(b, c, d);
      }
    }
  return mesh;
}

// random flips of interior edges that keep every valence within 3..9
void flip_randomly(Mesh& mesh, double probability, std::mt19937& random)
{
  std::vector<Mesh::Edge_index> edges(mesh.edges().begin(), mesh.edges().end());
  std::shuffle(edges.begin(), edges.end(), random);
  std::bernoulli_distribution flip(probability);
  for(const Mesh::Edge_index e : edges) {
    if(!flip(random) || mesh.is_border(e))
      continue;
    const Mesh::Halfedge_index h = mesh.halfedge(e), o = mesh.opposite(h);
    const vertex_descriptor a = mesh.source(h), b = mesh.target(h);
    const vertex_descriptor c = mesh.target(mesh.next(h)), d = mesh.target(mesh.next(o));
    if(c == d || CGAL::halfedge(c, d, mesh).second)
      continue;
    if(mesh.degree(a) <= 3 || mesh.degree(b) <= 3 || mesh.degree(c) >= 9 || mesh.degree(d) >= 9)
      continue;
    CGAL::Euler::flip_edge(h, mesh);
  }
}

std::string thousands(std::size_t n)
{
  if(n >= 10000)
    return std::to_string((n + 500) / 1000) + "k";
  return std::to_string(n);
}

struct File_input
{
  const char* id;
  const char* path; // under the mesh directory
};

const File_input files[] = {
  {"fandisk", "cgal/fandisk.off"},
  {"mushroom", "cgal/mushroom.off"},
  {"spot", "odedstein/spot_control_mesh.obj"},
};

using Crease_map = Mesh::Property_map<Mesh::Edge_index, double>;

// fandisk with creases where its faces bend by more than 30 degrees: a CAD
// part's feature lines, infinitely sharp
bool fandisk_with_sharp_angle(const std::string& mesh_dir, Mesh& mesh, std::string& why)
{
  const std::string path = mesh_dir + "/cgal/fandisk.off";
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || mesh.is_empty()) {
    why = "cannot read " + path;
    return false;
  }
  const Crease_map creases = mesh.add_property_map<Mesh::Edge_index, double>(crease_map_name, 0).first;
  CGAL::Subdiv::mark_sharp_edges(mesh, 30, creases);
  return true;
}

// OpenSubdiv's rook (777 faces, 280 creases of sharpness 7.9), read with the
// command line's checked OBJ reader, scaled up by `levels` levels of
// Catmull-Clark with its creases: semi-sharp creases of sharpness 7.9 - levels
bool rook_scaled_up(const std::string& mesh_dir, int levels, Mesh& mesh, std::string& why)
{
  const std::string path = mesh_dir + "/opensubdiv/catmark_rook.obj";
  cgal_subdiv::Mesh_soup soup;
  try {
    soup = cgal_subdiv::read_mesh_soup(path, cgal_subdiv::Mesh_format::obj);
  } catch(const std::exception& e) {
    why = e.what();
    return false;
  }
  std::vector<Mesh::Vertex_index> vertices;
  for(const auto& p : soup.points)
    vertices.push_back(mesh.add_vertex(Point(p[0], p[1], p[2])));
  for(std::size_t f = 0; f < soup.number_of_faces(); ++f) {
    std::vector<Mesh::Vertex_index> face;
    for(std::size_t k = soup.face_starts[f]; k < soup.face_starts[f + 1]; ++k)
      face.push_back(vertices[soup.indices[k]]);
    if(mesh.add_face(face) == Mesh::null_face()) {
      why = path + ": face " + std::to_string(f) + " does not fit a Surface_mesh";
      return false;
    }
  }
  const Crease_map creases = mesh.add_property_map<Mesh::Edge_index, double>(crease_map_name, 0).first;
  for(const cgal_subdiv::Obj_tag& tag : soup.tags)
    if(tag.name == "crease" && tag.floats.size() == 1)
      for(std::size_t k = 0; k + 1 < tag.ints.size(); k += 2) {
        const auto a = static_cast<std::size_t>(tag.ints[k]), b = static_cast<std::size_t>(tag.ints[k + 1]);
        const auto h =
          a < vertices.size() && b < vertices.size() ? mesh.halfedge(vertices[a], vertices[b]) : Mesh::null_halfedge();
        if(h == Mesh::null_halfedge()) {
          why = path + " line " + std::to_string(tag.line) + ": a crease that is not an edge";
          return false;
        }
        creases[mesh.edge(h)] = tag.floats[0];
      }
  CGAL::Subdiv::catmull_clark_subdivision(
    mesh, CGAL::Subdiv::parameters::number_of_iterations(levels).edge_sharpness_map(creases));
  return true;
}

// the sharp edges of the map, as OpenSubdiv's creases (vertex pairs in the soup's numbering)
void add_creases(const Mesh& mesh, Soup& soup)
{
  const Crease_map creases = mesh.property_map<Mesh::Edge_index, double>(crease_map_name).first;
  for(const Mesh::Edge_index e : mesh.edges())
    if(creases[e] > 0) {
      soup.crease_pairs.push_back(static_cast<int>(mesh.source(mesh.halfedge(e)).idx()));
      soup.crease_pairs.push_back(static_cast<int>(mesh.target(mesh.halfedge(e)).idx()));
      soup.crease_sharpness.push_back(static_cast<float>(creases[e]));
    }
}

// box-projected texture coordinates with seams, the layout of many scanned
// and CAD meshes: every face goes to the chart of the dominant axis of its
// normal (and its sign), its corners at their other two coordinates; a
// vertex has one value per chart around it, so an edge between two charts
// is a seam
void add_box_uvs(Mesh& mesh, Soup& soup)
{
  const auto uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>(uv_map_name).first;
  const auto uv_index = mesh.add_property_map<Mesh::Halfedge_index, std::size_t>(uv_index_map_name).first;
  std::vector<std::array<int, 6>> value_of(mesh.number_of_vertices(), {-1, -1, -1, -1, -1, -1});
  for(const Mesh::Face_index f : mesh.faces()) {
    double normal[3] = {0, 0, 0}; // Newell's
    for(const Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const Point &a = mesh.point(mesh.source(h)), &b = mesh.point(mesh.target(h));
      for(int i = 0; i < 3; ++i)
        normal[i] += (a[(i + 1) % 3] - b[(i + 1) % 3]) * (a[(i + 2) % 3] + b[(i + 2) % 3]);
    }
    int axis = 0;
    for(int i = 1; i < 3; ++i)
      if(std::abs(normal[i]) > std::abs(normal[axis]))
        axis = i;
    const int chart = 2 * axis + (normal[axis] < 0 ? 1 : 0);
    for(const Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const Mesh::Vertex_index v = mesh.target(h);
      int& value = value_of[v.idx()][static_cast<std::size_t>(chart)];
      const Point& p = mesh.point(v);
      if(value < 0) {
        value = static_cast<int>(soup.uvs.size());
        soup.uvs.push_back({p[(axis + 1) % 3], p[(axis + 2) % 3]});
      }
      uv[h] = Kernel::Point_2(p[(axis + 1) % 3], p[(axis + 2) % 3]);
      uv_index[h] = static_cast<std::size_t>(value);
    }
  }
  // the corners in the soup's order (soup_of: the targets around each face)
  for(const Mesh::Face_index f : mesh.faces())
    for(const Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
      soup.uv_indices.push_back(static_cast<int>(uv_index[h]));
}

const std::string textured_suffix = "-uv";

} // namespace

std::vector<std::string> input_ids()
{
  std::vector<std::string> ids = {"tri20k", "tri200k", "quad200k", "mixed", "border"};
  for(const File_input& file : files)
    ids.push_back(file.id);
  ids.push_back("fandisk-creased");
  ids.push_back("rook-creased");
  ids.push_back("tri200k-uv");
  ids.push_back("quad200k-uv");
  return ids;
}

std::string valence_range(const Mesh& mesh)
{
  unsigned low = 1000, high = 0;
  for(const vertex_descriptor v : mesh.vertices()) {
    low = std::min(low, mesh.degree(v));
    high = std::max(high, mesh.degree(v));
  }
  return std::to_string(low) + ".." + std::to_string(high);
}

Soup soup_of(const Mesh& mesh)
{
  Soup soup;
  soup.points.reserve(mesh.number_of_vertices());
  for(const vertex_descriptor v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    soup.points.push_back({p.x(), p.y(), p.z()});
  }
  soup.face_sizes.reserve(mesh.number_of_faces());
  soup.indices.reserve(mesh.number_of_halfedges());
  for(const Mesh::Face_index f : mesh.faces()) {
    int size = 0;
    for(const vertex_descriptor v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      soup.indices.push_back(static_cast<int>(v.idx()));
      ++size;
    }
    soup.face_sizes.push_back(size);
  }
  return soup;
}

bool make_input(const std::string& id, bool quick, const std::string& mesh_dir, Input& input, std::string& why)
{
  const std::size_t suffix_at = id.size() > textured_suffix.size() ? id.size() - textured_suffix.size() : 0;
  if(suffix_at > 0 && id.compare(suffix_at, std::string::npos, textured_suffix) == 0) {
    if(!make_input(id.substr(0, suffix_at), quick, mesh_dir, input, why))
      return false;
    input.id = id;
    add_box_uvs(input.mesh, input.soup);
    input.textured = true;
    input.name += ", " + thousands(input.soup.uvs.size()) + " box-projected UVs";
    return true;
  }
  input.id = id;
  Mesh& mesh = input.mesh;
  std::string kind;
  if(id == "tri20k" || id == "tri200k") {
    std::mt19937 random(id == "tri20k" ? 20261122u : 20261123u);
    const int n = id == "tri20k" ? (quick ? 32 : 100) : (quick ? 100 : 320);
    mesh = torus(n, n, true, random);
    flip_randomly(mesh, 0.3, random);
    kind = "tri torus";
  } else if(id == "quad200k") {
    std::mt19937 random(20261124u);
    mesh = quick ? torus(100, 200, false, random) : torus(500, 400, false, random);
    kind = "quad torus";
  } else if(id == "mixed") {
    std::mt19937 random(20261125u);
    mesh = quick ? mixed_torus(80, 60, random) : mixed_torus(300, 200, random);
    kind = "mixed 3- to 6-gon torus";
  } else if(id == "border") {
    std::mt19937 random(20261126u);
    mesh = border_patch(quick ? 50 : 160, random);
    flip_randomly(mesh, 0.3, random);
    kind = "tri patch with border";
  } else if(id == "fandisk-creased") {
    if(!fandisk_with_sharp_angle(mesh_dir, mesh, why))
      return false;
    kind = "fandisk, creases over 30 degrees,";
  } else if(id == "rook-creased") {
    const int levels = quick ? 1 : 2;
    if(!rook_scaled_up(mesh_dir, levels, mesh, why))
      return false;
    kind = "OSD rook, semi-sharp creases, x" + std::to_string(1 << (2 * levels)) + ",";
  } else {
    const File_input* file = nullptr;
    for(const File_input& f : files)
      if(id == f.id)
        file = &f;
    if(file == nullptr) {
      why = "unknown input '" + id + "'";
      return false;
    }
    const std::string path = mesh_dir + "/" + file->path;
    if(!std::ifstream(path).good()) {
      why = path + " not found";
      return false;
    }
    if(!CGAL::IO::read_polygon_mesh(path, mesh) || mesh.is_empty()) {
      why = "cannot read " + path;
      return false;
    }
    kind = file->path;
  }
  if(mesh.has_garbage())
    mesh.collect_garbage();
  if(!CGAL::is_valid_polygon_mesh(mesh)) {
    why = "the input " + id + " is not a valid polygon mesh";
    return false;
  }
  input.triangles = CGAL::is_triangle_mesh(mesh);
  input.border = !CGAL::is_closed(mesh);
  input.name = kind + " " + thousands(mesh.number_of_faces()) + " F";
  if(input.triangles)
    input.name += " (valence " + valence_range(mesh) + ")";
  input.soup = soup_of(mesh);
  input.creased = mesh.property_map<Mesh::Edge_index, double>(crease_map_name).second;
  if(input.creased)
    add_creases(mesh, input.soup);
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  input.diagonal = std::sqrt((box.xmax() - box.xmin()) * (box.xmax() - box.xmin()) +
                             (box.ymax() - box.ymin()) * (box.ymax() - box.ymin()) +
                             (box.zmax() - box.zmin()) * (box.zmax() - box.zmin()));
  return true;
}

} // namespace subdiv_bench
