// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Surface subdivision: two levels of Catmull-Clark on the bundled house (40
// quads and 4 triangles), read with CGAL's IO. Every level makes one vertex
// per old vertex, edge and face, and one quad per old face corner, so the
// counts of each level follow from those of the level before; the example
// checks them, and that the result is an all-quad mesh. It includes the
// scheme's own header, which compiles faster than <CGAL/Subdiv.h> (every
// scheme, the curves and the stencil tables).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdiv/catmull_clark_subdivision.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstddef>
#include <iostream>
#include <string>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : SUBDIV_EXAMPLE_DATA_DIR "/house.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh)) {
    std::cerr << "cannot read " << filename << "\n";
    return 1;
  }

  // the counts two levels of the quad split give: V' = V + E + F, E' = 2E + C,
  // F' = C, with C the number of face corners (every face becomes |f| quads)
  std::size_t v = num_vertices(mesh), e = num_edges(mesh), f = num_faces(mesh), corners = 2 * e; // closed mesh
  for(int level = 0; level < 2; ++level) {
    const std::size_t next_v = v + e + f, next_e = 2 * e + corners, next_f = corners;
    v = next_v, e = next_e, f = next_f, corners = 4 * next_f;
  }

  std::cout << filename << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces\n";
  CGAL::Subdiv::catmull_clark_subdivision(mesh, CGAL::Subdiv::parameters::number_of_iterations(2));
  std::cout << "Catmull-Clark, 2 levels: " << num_vertices(mesh) << " vertices, " << num_edges(mesh) << " edges, "
            << num_faces(mesh) << " faces, all quads: " << (CGAL::is_quad_mesh(mesh) ? "yes" : "no") << "\n";

  const bool ok = num_vertices(mesh) == v && num_edges(mesh) == e && num_faces(mesh) == f && CGAL::is_quad_mesh(mesh);
  std::cout << (ok ? "the counts are those of the quad split\n" : "FAILED: expected other counts\n");
  return ok ? 0 : 1;
}
