// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// cgal-subdiv surface --limit and --displace.
#include "surface_limit.h"

#include "numbers.h"

#include <CGAL/Subdiv/limit.h>
#include <CGAL/Subdiv/masks/Butterfly_mask.h>
#include <CGAL/Subdiv/masks/Catmull_clark_mask.h>
#include <CGAL/Subdiv/masks/Doo_sabin_mask.h>
#include <CGAL/Subdiv/masks/Interpolating_sqrt3_mask.h>
#include <CGAL/Subdiv/masks/Linear_quad_mask.h>
#include <CGAL/Subdiv/masks/Linear_triangle_mask.h>
#include <CGAL/Subdiv/masks/Loop_mask.h>
#include <CGAL/Subdiv/masks/Modified_butterfly_mask.h>
#include <CGAL/Subdiv/masks/Sqrt3_mask.h>
#include <CGAL/boost/graph/helpers.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace cgal_subdiv {
namespace {

namespace SD = CGAL::Subdiv;

using Vertex = Surface::Vertex_index;

// calls `f(mask)` with the mask of the scheme, made with `options`
template <class F>
void with_mask(const Surface_scheme& scheme, const Surface& mesh, const Sharp_options& options, const F& f)
{
  const std::string& name = scheme.name;
  if(name == "loop")
    f(mask_with_options<SD::Loop_mask<Surface>>(options));
  else if(name == "loop-warren")
    f(mask_with_options<SD::Loop_warren_mask<Surface>>(options));
  else if(name == "catmull-clark")
    f(mask_with_options<SD::Catmull_clark_mask<Surface>>(options));
  else if(name == "doo-sabin") // dual: the limit of each vertex's vertex face (doc/limit.md)
    f(SD::Doo_sabin_mask<Surface>());
  else if(name == "sqrt3")
    f(SD::Sqrt3_mask<Surface>());
  else if(name == "butterfly")
    f(SD::Butterfly_mask<Surface>());
  else if(name == "modified-butterfly")
    f(SD::Modified_butterfly_mask<Surface>());
  else if(name == "interpolating-sqrt3")
    f(SD::Interpolating_sqrt3_mask<Surface>());
  else if(name == "linear" && CGAL::is_triangle_mesh(mesh))
    f(SD::Linear_triangle_mask<Surface>());
  else if(name == "linear")
    f(SD::Linear_quad_mask<Surface>());
  else
    throw std::logic_error("no limit masks for scheme '" + name + "'"); // every scheme has them
}

// with `tags`, the sharpness maps of the mesh (as the levels left them)
// give each vertex its rule
struct Project
{
  Surface& mesh;
  const Sharp_options* tags;
  template <class Mask>
  void operator()(const Mask& mask) const
  {
    if constexpr(SD::internal::Limit_takes_sharpness_tags<Mask>::value)
      if(tags != nullptr) {
        SD::project_to_limit(mesh, mask, tag_parameters<Mask>(mesh, *tags));
        return;
      }
    SD::project_to_limit(mesh, mask);
  }
};

// with `tags`, the levels refine the sharpness maps of the mesh and the
// limit takes them
struct Displace
{
  Surface& mesh;
  int levels;
  double max_memory;
  Surface::Property_map<Vertex, double> heights;
  const Sharp_options* tags;
  template <class Mask>
  void operator()(const Mask& mask) const
  {
    if constexpr(SD::internal::Limit_takes_sharpness_tags<Mask>::value)
      if(tags != nullptr) {
        SD::displace(mesh, mask, heights,
                     tag_parameters<Mask>(mesh, *tags).number_of_iterations(levels).max_memory(max_memory));
        return;
      }
    SD::displace(mesh, mask, heights, SD::parameters::number_of_iterations(levels).max_memory(max_memory));
  }
};

} // namespace

std::vector<double> read_heights(const std::string& path, std::size_t vertices)
{
  std::ifstream in(path);
  if(!in)
    throw Input_error("cannot read HEIGHTS '" + path + "'");
  std::vector<double> heights;
  std::string line;
  for(std::size_t number = 1; std::getline(in, line); ++number) {
    const std::size_t first = line.find_first_not_of(" \t\r");
    if(first == std::string::npos || line[first] == '#')
      continue;
    const std::size_t last = line.find_last_not_of(" \t\r");
    const std::string text = line.substr(first, last - first + 1);
    double height = 0;
    try {
      height = nearest_double(parse_number(text));
    } catch(const std::exception&) {
      throw Input_error("HEIGHTS '" + path + "' line " + std::to_string(number) + ": cannot read '" + text +
                        "' as a number");
    }
    if(!std::isfinite(height))
      throw Input_error("HEIGHTS '" + path + "' line " + std::to_string(number) + ": '" + text +
                        "' is too large for a double");
    heights.push_back(height);
  }
  if(heights.size() != vertices)
    throw Input_error("HEIGHTS '" + path + "' has " + std::to_string(heights.size()) + " heights, INPUT has " +
                      std::to_string(vertices) + " vertices (one height per vertex, in INPUT's order)");
  return heights;
}

void project_surface_to_limit(Surface& mesh, const Surface_scheme& scheme, const Sharp_options* tags)
{
  // subdivide_surface() and the command refuse the others first
  CGAL_precondition(tags == nullptr || (scheme.run_sharp && scheme.limit_sharp));
  with_mask(scheme, mesh, tags != nullptr ? *tags : Sharp_options(), Project{mesh, tags});
}

Surface_result displace_surface(Surface& mesh, const Surface_scheme& scheme, int levels, double max_memory,
                                const std::vector<double>& heights, const Sharp_options* tags)
{
  refuse_tags_unless_taken(scheme, tags);
  Surface_result result;
  result.in = counts(mesh);
  check_output_size(scheme, mesh, levels, max_memory);
  const auto start = std::chrono::steady_clock::now();
  auto map = mesh.add_property_map<Vertex, double>("v:cgal_subdiv_height", 0.0).first;
  std::size_t k = 0;
  for(Vertex v : mesh.vertices())
    map[v] = heights.at(k++);
  // linear: the mask follows the mesh before refinement, as `linear` does
  with_mask(scheme, mesh, tags != nullptr ? *tags : Sharp_options(), Displace{mesh, levels, max_memory, map, tags});
  mesh.remove_property_map(map);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.out = counts(mesh);
  return result;
}

} // namespace cgal_subdiv
