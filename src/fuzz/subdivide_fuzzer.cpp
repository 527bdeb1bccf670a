// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// libFuzzer target: the surface schemes of the library on whatever mesh the
// checked reader of the command-line tool (src/cli/mesh_soup.h) accepts. The
// first byte picks the format (its value modulo 4: OFF, OBJ, PLY, STL), the
// second the scheme (modulo 9, in the order of `schemes` below), the third the
// level count (modulo 3: 0, 1 or 2) and, divided by 3, what is done with a
// soup that is not a manifold mesh (modulo 3: refused, --repair,
// --split-non-manifold); the rest is the file. The soup is turned into a
// Surface_mesh by `surface_from_soup`, as the tool does; soups it refuses,
// and those of more than 2000 faces (to keep runs fast), are skipped. A refusal (Input_error of
// the reader, Bad_input of the library) is a fine answer; a result with a
// non-finite point (unless the input had a coordinate beyond 1e300: overflow
// of huge inputs is a known open issue) or that is not a valid polygon mesh
// traps; any other exception (a CGAL assertion among them) escapes, which
// libFuzzer reports. Built and run by src/scripts/fuzz.sh.
#include "mesh_soup.h"
#include "surface_from_soup.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/surface_subdivision.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using cgal_subdiv::Mesh_soup;
using Point = CGAL::Simple_cartesian<double>::Point_3;
using Mesh = cgal_subdiv::Surface;

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

bool has_huge_coordinate(const Mesh& mesh)
{
  for(auto v : mesh.vertices())
    for(int i = 0; i < 3; ++i)
      if(std::abs(mesh.point(v)[i]) > 1e300)
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
  // what is done with a soup that is not a manifold mesh: refused, --repair, --split-non-manifold
  const auto fix = static_cast<cgal_subdiv::Soup_fix>((data[2] / 3) % 3);
  Mesh_soup soup;
  try {
    soup = cgal_subdiv::parse_mesh_soup(reinterpret_cast<const char*>(data + 3), size - 3, format, "fuzz");
  } catch(const cgal_subdiv::Input_error&) {
    return 0;
  }
  if(soup.number_of_faces() > max_faces)
    return 0;
  // the one way the tool builds a mesh from a file
  Mesh mesh;
  std::vector<std::string> notes;
  try {
    mesh = cgal_subdiv::surface_from_soup(soup, "fuzz", format, fix, notes);
  } catch(const cgal_subdiv::Input_error&) {
    return 0;
  }
  const bool huge = has_huge_coordinate(mesh);
  try {
    subdivide(mesh, scheme, levels);
  } catch(const CGAL::Subdiv::Bad_input&) {
    return 0;
  }
  if(!all_finite(mesh) && !huge)
    __builtin_trap();
  if(!CGAL::is_valid_polygon_mesh(mesh))
    __builtin_trap();
  return 0;
}
