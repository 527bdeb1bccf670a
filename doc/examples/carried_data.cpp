// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Carried data: two levels of Loop on the bundled torus, carrying a scalar, a
// colour and a UV per vertex, and a label per face. The scalar is combined
// with the weights of the points, so a linear function of the control points
// (here x + 2y - 3z) stays that function of the refined points; the colour
// (CGAL::IO::Color) too, each channel rounded back to a byte; the UV (a
// Point_2) linearly, with the weights of the linear scheme, as OpenSubdiv's
// varying data: an edge's new vertex gets the mean of its ends' UVs, so the
// UVs stay inside the box of the old ones. Every new face inherits the label of
// the old face it lies in, so each of the 64 labels covers 4 x 4 = 16 faces.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using UV = Kernel::Point_2;
using Mesh = CGAL::Surface_mesh<Point>;
using Vertex = Mesh::Vertex_index;
using Face = Mesh::Face_index;

double linear(const Point& p)
{
  return p.x() + 2 * p.y() - 3 * p.z();
}

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : SUBDIV_EXAMPLE_DATA_DIR "/torus.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "cannot read a triangle mesh from " << filename << "\n";
    return 1;
  }

  auto value = mesh.add_property_map<Vertex, double>("v:value", 0).first;
  auto colour = mesh.add_property_map<Vertex, CGAL::IO::Color>("v:colour").first;
  auto uv = mesh.add_property_map<Vertex, UV>("v:uv").first;
  auto label = mesh.add_property_map<Face, int>("f:label", -1).first;
  for(Vertex v : vertices(mesh)) {
    const Point& p = mesh.point(v);
    value[v] = linear(p);
    colour[v] = p.z() > 0 ? CGAL::IO::Color(230, 60, 20) : CGAL::IO::Color(20, 90, 230);
    uv[v] = UV(std::atan2(p.y(), p.x()), p.z());
  }
  CGAL::Bbox_2 uv_box;
  for(Vertex v : vertices(mesh))
    uv_box += uv[v].bbox();
  int next_label = 0;
  for(Face f : faces(mesh))
    label[f] = next_label++;

  CGAL::Subdiv::Carried_data<Mesh> data;
  data.vertex_map(value).vertex_map(colour).vertex_map(uv, CGAL::Subdiv::Interpolation::linear).face_map(label);
  CGAL::Subdiv::loop_subdivision(mesh, CGAL::Subdiv::parameters::number_of_iterations(2).carried_data(data));

  double worst = 0;
  bool uvs_inside = true;
  std::map<int, int> reds; // how many vertices have each red value
  for(Vertex v : vertices(mesh)) {
    worst = (std::max)(worst, std::abs(value[v] - linear(mesh.point(v))));
    uvs_inside = uvs_inside && CGAL::do_overlap(uv[v].bbox(), uv_box);
    ++reds[colour[v].red()];
  }
  std::map<int, int> faces_per_label;
  for(Face f : faces(mesh))
    ++faces_per_label[label[f]];
  const bool labels_ok =
    static_cast<int>(faces_per_label.size()) == next_label &&
    std::all_of(faces_per_label.begin(), faces_per_label.end(), [](const auto& entry) { return entry.second == 16; });

  std::cout << "Loop, 2 levels: " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces\n"
            << "carried value vs x + 2y - 3z of the refined points: largest difference " << worst << "\n"
            << reds.size() << " shades of red between " << reds.begin()->first << " and " << reds.rbegin()->first
            << "\n"
            << "UVs inside the box of the old ones: " << (uvs_inside ? "yes" : "no") << "\n"
            << faces_per_label.size() << " face labels, 16 faces each: " << (labels_ok ? "yes" : "no") << "\n";
  return worst < 1e-12 && uvs_inside && labels_ok ? 0 : 1;
}
