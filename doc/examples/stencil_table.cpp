// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Stencil re-evaluation: the three Loop levels of the bundled torus composed
// once into a table from its 32 control points to the 2048 refined points.
// After the control points move (an animation frame, a parameter sweep), one
// `apply` gives the refined points again, without refining: the example checks
// that they are those of subdividing the moved mesh (up to rounding: the table
// sums composed weights, refinement sums level after level).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

int main(int argc, char* argv[])
{
  namespace SD = CGAL::Subdiv;
  const std::string filename = argc > 1 ? argv[1] : SUBDIV_EXAMPLE_DATA_DIR "/torus.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "cannot read a triangle mesh from " << filename << "\n";
    return 1;
  }

  const SD::Stencil_table<double> table =
    SD::make_stencil_table(mesh, SD::Loop_mask<Mesh>(), SD::parameters::number_of_iterations(3));
  std::cout << "table: " << table.number_of_stencils() << " stencils over " << table.number_of_sources()
            << " control points, " << table.number_of_terms() << " terms\n";

  // move the control points: a twist about the z axis and a lift
  std::vector<Point> moved;
  for(Mesh::Vertex_index v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    const double angle = 0.3 * p.z();
    moved.emplace_back(std::cos(angle) * p.x() - std::sin(angle) * p.y(),
                       std::sin(angle) * p.x() + std::cos(angle) * p.y(), p.z() + 0.1 * p.x());
  }
  std::vector<Point> refined;
  table.apply(moved, refined);

  // the reference: subdivide the moved mesh
  std::size_t i = 0;
  for(Mesh::Vertex_index v : vertices(mesh))
    mesh.point(v) = moved[i++];
  SD::loop_subdivision(mesh, SD::parameters::number_of_iterations(3));
  double worst = 0;
  i = 0;
  for(Mesh::Vertex_index v : vertices(mesh))
    worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(mesh.point(v), refined[i++])));

  std::cout << "re-evaluated " << refined.size() << " points; subdividing the moved mesh gives " << num_vertices(mesh)
            << "; largest distance " << worst << "\n";
  return refined.size() == num_vertices(mesh) && worst < 1e-12 ? 0 : 1;
}
