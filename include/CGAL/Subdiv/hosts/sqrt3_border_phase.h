// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_SQRT3_BORDER_PHASE_H
#define CGAL_SUBDIV_HOSTS_SQRT3_BORDER_PHASE_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * Whether the border of `mesh` is due to be refined by the next sqrt3 step,
 * i.e. whether the mesh is the output of a sqrt3 step that left its border
 * alone (a "resting" step). Such a step puts its V_old old vertices first and
 * its face points last, and the three new faces of old face k at positions
 * 3k, 3k+1, 3k+2, each with face point V_old + k among its corners. So, with
 * V and F the numbers of vertices and faces now, F is a multiple of 3, the
 * vertices from V_old = V - F/3 on are the face points, and
 *   - face i has the face point V_old + i/3 (rounded down) among its corners,
 *     and at least one old vertex;
 *   - every border vertex is old;
 *   - no interior edge joins two old vertices (every old interior edge was
 *     flipped);
 *   - every face point has exactly three old neighbours (the corners of its
 *     old face).
 * `cut(e)` says which edges count as border edges here: the border edges,
 * and with sharpness tags the sharp edges too. A resting step keeps a sharp
 * edge as it keeps a border edge, and the children of a sharp edge are
 * sharp, so the phase is read from the same structure with or without
 * creases (a closed mesh with creases has a phase as well). The phase is
 * read, not passed, so that one call of two levels and two calls of one
 * agree with creases as they do without.
 * The test reads the connectivity and the order of the elements, nothing
 * else, in one pass over the edges and one over the faces. The order part
 * keeps meshes that merely have the connectivity of a resting step's output
 * (CGAL's hedra_open.off, an octahedron without two faces, is one: two
 * triangles after a resting step) from being taken for one.
 */
template <class Mesh, class Numbering, class Cut>
bool sqrt3_border_is_pending(const Mesh& mesh, const Numbering& number, const Cut& cut)
{
  const std::size_t vertex_count = num_vertices(mesh), face_count = num_faces(mesh);
  if(face_count % 3 != 0 || vertex_count < face_count / 3)
    return false;
  const std::size_t first_face_point = vertex_count - face_count / 3;
  std::vector<unsigned char> old_neighbours(face_count / 3, 0);
  for(auto e : edges(mesh)) {
    const auto h = halfedge(e, mesh);
    const std::size_t a = number(source(h, mesh)), b = number(target(h, mesh));
    const bool a_old = a < first_face_point, b_old = b < first_face_point;
    if(cut(e)) {
      if(!a_old || !b_old)
        return false; // a face point on the border or on a crease
    } else if(a_old && b_old) {
      return false; // an unflipped old interior edge
    } else if(a_old != b_old) {
      unsigned char& count = old_neighbours[(a_old ? b : a) - first_face_point];
      if(++count > 3)
        return false;
    }
  }
  for(unsigned char count : old_neighbours)
    if(count != 3)
      return false;
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    const std::size_t corner[3] = {number(source(h, mesh)), number(target(h, mesh)),
                                   number(target(next(h, mesh), mesh))};
    const std::size_t expected = first_face_point + number(f) / 3;
    if(corner[0] != expected && corner[1] != expected && corner[2] != expected)
      return false;
    if(corner[0] >= first_face_point && corner[1] >= first_face_point && corner[2] >= first_face_point)
      return false;
  }
  return true;
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_HOSTS_SQRT3_BORDER_PHASE_H
