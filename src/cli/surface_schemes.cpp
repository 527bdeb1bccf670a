// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The one table of surface schemes of cgal-subdiv: a scheme is one line here.
#include "surface.h"

#include <CGAL/Subdiv/surface_subdivision.h>
#include <CGAL/boost/graph/helpers.h>

namespace cgal_subdiv {
namespace {

namespace SD = CGAL::Subdiv;

template <class Wrapper>
std::function<void(Surface&, int)> call(Wrapper wrapper)
{
  return [wrapper](Surface& mesh, int levels) { wrapper(mesh, CGAL::parameters::number_of_iterations(levels)); };
}

#define SUBDIV_CLI_WRAP(function) call([](Surface& m, const auto& np) { SD::function(m, np); })

// linear: a triangle mesh stays one (1-to-4 split), anything else becomes quads
const auto linear = call([](Surface& m, const auto& np) {
  if(CGAL::is_triangle_mesh(m))
    SD::linear_triangle_subdivision(m, np);
  else
    SD::linear_quad_subdivision(m, np);
});

} // namespace

const std::vector<std::string>& surface_scheme_keywords()
{
  static const std::vector<std::string> keywords = {"loop",  "loop-warren", "catmull-clark",      "doo-sabin",
                                                    "sqrt3", "butterfly",   "modified-butterfly", "interpolating-sqrt3",
                                                    "linear"};
  return keywords;
}

const std::vector<Surface_scheme>& surface_schemes()
{
  // name, description, run, triangles only, level by level, face growth per level
  static const std::vector<Surface_scheme> schemes = {
    {"loop", "Loop, Loop's 1987 beta (as CGAL and OpenSubdiv)", SUBDIV_CLI_WRAP(loop_subdivision), true, true, 4},
    {"loop-warren", "Loop with Warren's rational beta", SUBDIV_CLI_WRAP(loop_warren_subdivision), true, true, 4},
    {"catmull-clark", "Catmull-Clark (quads out)", SUBDIV_CLI_WRAP(catmull_clark_subdivision), false, true, 4},
    {"doo-sabin", "Doo-Sabin (the dual scheme)", SUBDIV_CLI_WRAP(doo_sabin_subdivision), false, true, 4},
    {"sqrt3", "Kobbelt's sqrt3", SUBDIV_CLI_WRAP(sqrt3_subdivision), true, true, 3},
    {"butterfly", "butterfly (Dyn, Levin, Gregory), interpolating", SUBDIV_CLI_WRAP(butterfly_subdivision), true, true,
     4},
    {"modified-butterfly", "modified butterfly (Zorin, Schroeder, Sweldens), interpolating",
     SUBDIV_CLI_WRAP(modified_butterfly_subdivision), true, true, 4},
    {"interpolating-sqrt3", "Labsik and Greiner's interpolating sqrt3",
     SUBDIV_CLI_WRAP(interpolating_sqrt3_subdivision), true, true, 3},
    {"linear", "midpoints: the 1-to-4 split of a triangle mesh, the quad split of any other", linear, false, true, 4},
  };
  return schemes;
}

} // namespace cgal_subdiv
