// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The limit surface of Loop subdivision on the bundled torus (R = 1 about the
// z axis), after one level: `project_to_limit` moves every vertex to its limit
// point and `limit_normals` gives the unit normals there, both from the limit
// and tangent masks of the analysis. Checked: at a regular vertex (valence 6)
// the limit point is 1/2 of the vertex plus 1/12 of each neighbour, Loop's
// regular limit mask; every normal has length 1 and points away from the core
// circle of the torus.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Subdiv/limit.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Vertex = Mesh::Vertex_index;

int main(int argc, char* argv[])
{
  namespace SD = CGAL::Subdiv;
  const std::string filename = argc > 1 ? argv[1] : SUBDIV_EXAMPLE_DATA_DIR "/torus.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "cannot read a triangle mesh from " << filename << "\n";
    return 1;
  }
  SD::loop_subdivision(mesh); // one level: every edge point has valence 6

  Mesh limit = mesh;
  auto normal = limit.add_property_map<Vertex, Vector>("v:normal", CGAL::NULL_VECTOR).first;
  SD::limit_normals(limit, SD::Loop_mask<Mesh>(), normal);
  SD::project_to_limit(limit, SD::Loop_mask<Mesh>());

  double mask_error = 0, length_error = 0, worst_outward = 1;
  int regular = 0;
  for(Vertex v : vertices(mesh)) {
    if(degree(v, mesh) == 6) { // 1/2 v + 1/12 of each neighbour
      ++regular;
      Vector sum = (mesh.point(v) - CGAL::ORIGIN) / 2;
      for(Vertex u : CGAL::vertices_around_target(v, mesh))
        sum = sum + (mesh.point(u) - CGAL::ORIGIN) / 12;
      mask_error = (std::max)(mask_error, std::sqrt(CGAL::squared_distance(CGAL::ORIGIN + sum, limit.point(v))));
    }
    const Point& p = limit.point(v);
    const double ring = std::sqrt(p.x() * p.x() + p.y() * p.y());
    const Vector away = p - Point(p.x() / ring, p.y() / ring, 0); // from the core circle to p
    length_error = (std::max)(length_error, std::abs(std::sqrt(normal[v].squared_length()) - 1));
    worst_outward = (std::min)(worst_outward, normal[v] * away / std::sqrt(away.squared_length()));
  }

  std::cout << num_vertices(limit) << " vertices at their limit points; " << regular
            << " of valence 6, largest distance to 1/2 v + 1/12 sum of neighbours: " << mask_error << "\n"
            << "normals: largest | |n| - 1 | " << length_error
            << ", smallest cosine with the direction away from the core circle " << worst_outward << "\n";
  return regular > 0 && mask_error < 1e-12 && length_error < 1e-12 && worst_outward > 0.5 ? 0 : 1;
}
