// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// UVs with seams, material ids and colours: two levels of Catmull-Clark on a
// cube whose six faces each have their own island of the texture atlas (a
// 3 x 2 grid of unit cells), so that every edge of the cube is a seam, each
// face its own material, and each vertex a colour.
//
// The UVs are per corner (a halfedge map: the value of face(h) at target(h))
// with the index of each value (as OBJ's `vt` references give it), carried in
// OpenSubdiv's corners-plus1 mode, USD's default: each island is refined as a
// mesh of its own whose border is the seam, and its corners stay where they
// are. So every UV of a refined face stays inside its material's cell, the 4
// corners of every cell are still there, and each island ends with 5 x 5
// values. The material ids are inherited by the faces a face is split into;
// the colours are combined with the weights of the points.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <iostream>
#include <map>
#include <set>
#include <utility>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using UV = Kernel::Point_2;
using Mesh = CGAL::Surface_mesh<Point>;
using Vertex = Mesh::Vertex_index;
using Face = Mesh::Face_index;
using Halfedge = Mesh::Halfedge_index;

// the lower left corner of the atlas cell of material `m`
UV cell_of(int m)
{
  return UV(m % 3, m / 3);
}

int main()
{
  Mesh cube;
  std::vector<Vertex> v;
  for(int i = 0; i < 8; ++i)
    v.push_back(cube.add_vertex(Point(i & 1, (i >> 1) & 1, (i >> 2) & 1)));
  const std::array<std::array<int, 4>, 6> quads = {
    {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {1, 3, 7, 5}, {3, 2, 6, 7}, {2, 0, 4, 6}}};
  for(const auto& q : quads)
    cube.add_face(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);

  auto uv = cube.add_property_map<Halfedge, UV>("h:uv").first;
  auto uv_index = cube.add_property_map<Halfedge, std::size_t>("h:uv_index").first;
  auto material = cube.add_property_map<Face, int>("f:material", -1).first;
  auto colour = cube.add_property_map<Vertex, CGAL::IO::Color>("v:colour").first;
  const std::array<std::pair<int, int>, 4> cell_corners = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  std::size_t next_index = 0;
  int next_material = 0;
  for(Face f : faces(cube)) {
    material[f] = next_material++;
    const UV origin = cell_of(material[f]);
    int corner = 0;
    for(Halfedge h : halfedges_around_face(halfedge(f, cube), cube)) {
      const auto [du, dv] = cell_corners[corner++];
      uv[h] = UV(origin.x() + du, origin.y() + dv);
      uv_index[h] = next_index++; // every corner its own value: every edge is a seam
    }
  }
  for(Vertex w : vertices(cube))
    colour[w] = cube.point(w).z() > 0 ? CGAL::IO::Color(255, 255, 255) : CGAL::IO::Color(0, 0, 0);

  CGAL::Subdiv::Carried_data<Mesh> data;
  data.corner_map(uv, CGAL::Subdiv::Face_varying_interpolation::corners_plus1, uv_index)
    .face_map(material)
    .vertex_map(colour);
  CGAL::Subdiv::catmull_clark_subdivision(cube, CGAL::Subdiv::parameters::number_of_iterations(2).carried_data(data));

  bool inside_cells = true;
  std::map<int, int> faces_per_material;
  std::map<int, std::set<std::pair<double, double>>> uvs_of_material;
  std::set<std::size_t> values;
  for(Face f : faces(cube)) {
    ++faces_per_material[material[f]];
    const UV origin = cell_of(material[f]);
    for(Halfedge h : halfedges_around_face(halfedge(f, cube), cube)) {
      const double du = uv[h].x() - origin.x(), dv = uv[h].y() - origin.y();
      inside_cells = inside_cells && du >= 0 && du <= 1 && dv >= 0 && dv <= 1;
      uvs_of_material[material[f]].insert({uv[h].x(), uv[h].y()});
      values.insert(uv_index[h]);
    }
  }
  bool corners_kept = true;
  for(int m = 0; m < 6; ++m)
    for(const auto& [du, dv] : cell_corners)
      corners_kept = corners_kept && uvs_of_material[m].count({cell_of(m).x() + du, cell_of(m).y() + dv}) == 1;
  bool sixteen_each = faces_per_material.size() == 6;
  for(const auto& entry : faces_per_material)
    sixteen_each = sixteen_each && entry.second == 16;
  std::set<int> greys;
  for(Vertex w : vertices(cube))
    greys.insert(colour[w].red());

  std::cout << "Catmull-Clark, 2 levels: " << num_vertices(cube) << " vertices, " << num_faces(cube) << " faces\n"
            << values.size() << " UV values (6 islands of 5 x 5: " << (values.size() == 150 ? "yes" : "no") << ")\n"
            << "every UV inside its material's atlas cell: " << (inside_cells ? "yes" : "no") << "\n"
            << "the 4 corners of every cell kept: " << (corners_kept ? "yes" : "no") << "\n"
            << "6 materials of 16 faces each: " << (sixteen_each ? "yes" : "no") << "\n"
            << greys.size() << " shades of grey between black and white\n";
  return values.size() == 150 && inside_cells && corners_kept && sixteen_each && greys.size() > 2 ? 0 : 1;
}
