// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_MESH_CHECKS_H
#define CGAL_SUBDIV_INTERNAL_MESH_CHECKS_H

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <string>
#include <unistd.h>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * Everything a surface scheme needs of its input, checked before anything is
 * changed, so that a refused call leaves the caller's mesh as it was. Elements
 * are named by their position in the mesh's iteration order (for a
 * Surface_mesh without garbage, that is their index).
 */
template <class Mesh, class VertexPointMap>
void check_mesh(const Mesh& mesh, const VertexPointMap& vpm, const std::string& scheme, int required_face_size)
{
  require(!faces(mesh).empty(), scheme + ": the mesh is empty (it has no faces)");
  // A vertex is manifold when the halfedges around it (one fan) are all of its
  // incoming halfedges and at most one of them is a border halfedge (a
  // halfedge structure can chain two fans through their border halfedges).
  auto incoming = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  auto incoming_border = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  for(auto v : vertices(mesh)) {
    put(incoming, v, 0);
    put(incoming_border, v, 0);
  }
  for(auto h : halfedges(mesh)) {
    put(incoming, target(h, mesh), get(incoming, target(h, mesh)) + 1);
    if(CGAL::is_border(h, mesh))
      put(incoming_border, target(h, mesh), get(incoming_border, target(h, mesh)) + 1);
  }
  // messages are built only on failure: this runs on every call
  std::size_t i = 0;
  for(auto v : vertices(mesh)) {
    if(halfedge(v, mesh) == boost::graph_traits<Mesh>::null_halfedge())
      throw Bad_input(scheme + ": vertex " + std::to_string(i) + " is isolated (it belongs to no face)");
    if(!is_finite_point(get(vpm, v)))
      throw Bad_input(scheme + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
    if(CGAL::halfedges_around_target(v, mesh).size() != get(incoming, v) || get(incoming_border, v) > 1)
      throw Bad_input(scheme + ": vertex " + std::to_string(i) + " is non-manifold (its faces do not form one fan)");
    ++i;
  }
  i = 0;
  for(auto f : faces(mesh)) {
    const std::size_t size = CGAL::halfedges_around_face(halfedge(f, mesh), mesh).size();
    if(size < 3)
      throw Bad_input(scheme + ": face " + std::to_string(i) + " has only " + std::to_string(size) + " vertices");
    if(required_face_size != 0 && size != static_cast<std::size_t>(required_face_size))
      throw Bad_input(scheme + " needs a mesh whose faces all have " + std::to_string(required_face_size) +
                      " vertices; face " + std::to_string(i) + " has " + std::to_string(size));
    ++i;
  }
  require(CGAL::is_valid_polygon_mesh(mesh), scheme + ": the mesh is not a valid polygon mesh");
}

inline double physical_memory_bytes()
{
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  if(pages <= 0 || page_size <= 0)
    return 16.0 * (1u << 30);
  return static_cast<double>(pages) * static_cast<double>(page_size);
}

// A mesh costs about this many bytes per face (vertices, halfedges, edges,
// faces and the points, with the polygon soup built on the way).
constexpr double bytes_per_output_face = 256;

// Refuse, before allocating, a level count whose output would not fit in memory.
inline void check_output_faces(const std::string& scheme, double faces_in, double growth_per_level, int levels)
{
  require(levels >= 0, scheme + ": the number of iterations must not be negative, got " + std::to_string(levels));
  const double limit = physical_memory_bytes() / bytes_per_output_face;
  double faces_out = faces_in;
  for(int l = 0; l < levels && faces_out <= limit; ++l)
    faces_out *= growth_per_level;
  require(faces_out <= limit, scheme + ": " + std::to_string(levels) + " iterations on " +
                                std::to_string(static_cast<long long>(faces_in)) +
                                " faces would make more faces than fit in this machine's memory (about " +
                                std::to_string(static_cast<long long>(limit)) + ")");
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_MESH_CHECKS_H
