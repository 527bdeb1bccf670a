// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: the inputs (see inputs.h and src/bench/README.md).
#include "inputs.h"

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
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

} // namespace

std::vector<std::string> input_ids()
{
  std::vector<std::string> ids = {"tri20k", "tri200k", "quad200k", "mixed", "border"};
  for(const File_input& file : files)
    ids.push_back(file.id);
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
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  input.diagonal = std::sqrt((box.xmax() - box.xmin()) * (box.xmax() - box.xmin()) +
                             (box.ymax() - box.ymin()) * (box.ymax() - box.ymin()) +
                             (box.zmax() - box.zmin()) * (box.zmax() - box.zmin()));
  return true;
}

} // namespace subdiv_bench
