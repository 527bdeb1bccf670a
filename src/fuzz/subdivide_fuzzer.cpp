// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// libFuzzer target: the surface schemes of the library on whatever mesh the
// checked reader of the command-line tool (src/cli/mesh_soup.h) accepts. The
// first byte picks the format (its value modulo 4: OFF, OBJ, PLY, STL), the
// second the scheme (modulo 9, in the order of `schemes` below), the third the
// level count (modulo 3: 0, 1 or 2); the rest is the file. The soup is turned
// into a Surface_mesh as `read_surface` of src/cli/surface.cpp does (without
// --repair); soups that are not a manifold polygon mesh, and meshes of more
// than 2000 faces (to keep runs fast), are skipped. A refusal (Input_error of
// the reader, Bad_input of the library) is a fine answer; a result with a
// non-finite point (unless the input had a coordinate beyond 1e300: overflow
// of huge inputs is a known open issue) or that is not a valid polygon mesh
// traps; any other exception (a CGAL assertion among them) escapes, which
// libFuzzer reports. Built and run by src/scripts/fuzz.sh.
#include "mesh_soup.h"

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/surface_subdivision.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace {

using cgal_subdiv::Mesh_soup;
using Point = CGAL::Simple_cartesian<double>::Point_3;
using Polygon = std::vector<std::size_t>;
using Mesh = CGAL::Surface_mesh<Point>;

constexpr std::size_t max_faces = 2000;

enum class Scheme {
  loop,
  loop_warren,
  catmull_clark,
  doo_sabin,
  sqrt3,
  butterfly,
  modified_butterfly,
  interpolating_sqrt3,
  linear
};
constexpr int number_of_schemes = 9;

void subdivide(Mesh& mesh, Scheme scheme, int levels)
{
  namespace S = CGAL::Subdiv;
  const auto np = S::parameters::number_of_iterations(levels);
  switch(scheme) {
    case Scheme::loop:
      S::loop_subdivision(mesh, np);
      break;
    case Scheme::loop_warren:
      S::loop_warren_subdivision(mesh, np);
      break;
    case Scheme::catmull_clark:
      S::catmull_clark_subdivision(mesh, np);
      break;
    case Scheme::doo_sabin:
      S::doo_sabin_subdivision(mesh, np);
      break;
    case Scheme::sqrt3:
      S::sqrt3_subdivision(mesh, np);
      break;
    case Scheme::butterfly:
      S::butterfly_subdivision(mesh, np);
      break;
    case Scheme::modified_butterfly:
      S::modified_butterfly_subdivision(mesh, np);
      break;
    case Scheme::interpolating_sqrt3:
      S::interpolating_sqrt3_subdivision(mesh, np);
      break;
    case Scheme::linear:
      S::linear_subdivision(mesh, np);
      break;
  }
}

/// the soup as `to_cgal_soup` of src/cli/surface.cpp makes it: without the
/// vertices that no face uses
void to_cgal_soup(const Mesh_soup& soup, std::vector<Point>& points, std::vector<Polygon>& polygons)
{
  constexpr std::size_t unused = static_cast<std::size_t>(-1);
  std::vector<std::size_t> new_index(soup.points.size(), unused);
  for(std::size_t i : soup.indices)
    new_index[i] = 0;
  std::size_t kept = 0;
  for(std::size_t v = 0; v < soup.points.size(); ++v)
    if(new_index[v] != unused) {
      new_index[v] = kept++;
      const auto& p = soup.points[v];
      points.emplace_back(p[0], p[1], p[2]);
    }
  polygons.resize(soup.number_of_faces());
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t k = soup.face_starts[f]; k < soup.face_starts[f + 1]; ++k)
      polygons[f].push_back(new_index[soup.indices[k]]);
}

bool has_huge_coordinate(const std::vector<Point>& points)
{
  for(const Point& p : points)
    for(int i = 0; i < 3; ++i)
      if(std::abs(p[i]) > 1e300)
        return true;
  return false;
}

bool all_finite(const Mesh& mesh)
{
  for(auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return false;
  }
  return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 3)
    return 0;
  const auto format = static_cast<cgal_subdiv::Mesh_format>(data[0] % 4);
  const auto scheme = static_cast<Scheme>(data[1] % number_of_schemes);
  const int levels = data[2] % 3;
  Mesh_soup soup;
  try {
    soup = cgal_subdiv::parse_mesh_soup(reinterpret_cast<const char*>(data + 3), size - 3, format, "fuzz");
  } catch(const cgal_subdiv::Input_error&) {
    return 0;
  }
  if(soup.number_of_faces() == 0 || soup.number_of_faces() > max_faces)
    return 0;
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  to_cgal_soup(soup, points, polygons);
  namespace PMP = CGAL::Polygon_mesh_processing;
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    return 0;
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(mesh.number_of_faces() > max_faces)
    return 0;
  try {
    subdivide(mesh, scheme, levels);
  } catch(const CGAL::Subdiv::Bad_input&) {
    return 0;
  }
  if(!all_finite(mesh) && !has_huge_coordinate(points))
    __builtin_trap();
  if(!CGAL::is_valid_polygon_mesh(mesh))
    __builtin_trap();
  return 0;
}
