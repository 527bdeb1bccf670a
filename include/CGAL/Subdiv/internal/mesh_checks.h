// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_MESH_CHECKS_H
#define CGAL_SUBDIV_INTERNAL_MESH_CHECKS_H

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/memory.h>
#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

// Surface_mesh keeps removed elements until collect_garbage(). The hosts
// number elements densely, and collecting the garbage here would make every
// program that refines a Surface_mesh compile CGAL's collect_garbage (about a
// tenth of a plain program's compile time), so a mesh with garbage is refused.
template <class Mesh>
bool has_garbage(const Mesh&)
{
  return false;
}

template <class Point>
bool has_garbage(const CGAL::Surface_mesh<Point>& mesh)
{
  return mesh.has_garbage();
}

/*
 * Everything a surface scheme needs of its input, checked before anything is
 * changed, so that a refused call leaves the caller's mesh as it was. Elements
 * are named by their position in the mesh's iteration order (for a
 * Surface_mesh without garbage, that is their index).
 */
template <class Mesh, class VertexPointMap>
bool passes_mesh_checks(const Mesh&, const VertexPointMap&, int, bool)
{
  return false;
}

// the halfedges of the face cycle of `h` (in range), 0 if next does not
// come back to h within all the halfedges
template <class P>
std::size_t face_cycle_length(const CGAL::Surface_mesh<P>& mesh, typename CGAL::Surface_mesh<P>::Halfedge_index h)
{
  std::size_t size = 0;
  auto g = h;
  do {
    ++size;
    g = mesh.next(g);
  } while(g != h && size <= mesh.number_of_halfedges());
  return g == h ? size : 0;
}

/*
 * Surface_mesh without garbage: one pass over the halfedge, vertex and face
 * arrays that is enough for everything `check_mesh` checks below (including
 * CGAL::is_valid_polygon_mesh). Returns false if anything may be wrong; the
 * full check then runs and names the problem, so the errors are the same.
 * - next is a bijection (prev(next(h)) = h = next(prev(h))), so
 *   h -> opposite(next(h)) is one too, and its cycles, along which the target
 *   stays the same (target(opposite(next(h))) = target(h)), split the
 *   halfedges; the cycles of the vertices' halfedges add up to all halfedges
 *   exactly when each vertex's cycle holds all its incoming halfedges (its
 *   faces form one fan);
 * - the face cycles along next, plus the border halfedges, add up to all
 *   halfedges; face(next(h)) = face(h) != face(opposite(h)); and the rest of
 *   is_valid_polygon_mesh's local conditions, halfedge by halfedge.
 */
template <class P, class VertexPointMap>
bool passes_mesh_checks(const CGAL::Surface_mesh<P>& mesh, const VertexPointMap& vpm, int required_face_size,
                        bool allow_isolated)
{
  using SM = CGAL::Surface_mesh<P>;
  using size_type = typename SM::size_type;
  using V = typename SM::Vertex_index;
  using H = typename SM::Halfedge_index;
  using F = typename SM::Face_index;
  if(mesh.has_garbage() || mesh.number_of_faces() == 0)
    return false;
  const std::size_t nv = mesh.number_of_vertices(), nh = mesh.number_of_halfedges(), nf = mesh.number_of_faces();
  std::size_t border_halfedges = 0;
  for(std::size_t i = 0; i < nh; ++i) {
    const H h(static_cast<size_type>(i));
    const H n = mesh.next(h), p = mesh.prev(h);
    if(std::size_t(n) >= nh || std::size_t(p) >= nh || n == h || mesh.prev(n) != h || mesh.next(p) != h)
      return false;
    const V t = mesh.target(h);
    if(std::size_t(t) >= nv || mesh.target(mesh.opposite(n)) != t || mesh.target(mesh.opposite(h)) == t)
      return false;
    const F f = mesh.face(h);
    if(f != SM::null_face() && std::size_t(f) >= nf)
      return false;
    if(mesh.face(n) != f || mesh.face(mesh.opposite(h)) == f)
      return false;
    const H nn = mesh.next(n);
    if(nn == h || mesh.target(n) == t || mesh.target(nn) == t)
      return false;
    if(f == SM::null_face())
      ++border_halfedges;
  }
  std::size_t around_vertices = 0;
  for(std::size_t i = 0; i < nv; ++i) {
    const V v(static_cast<size_type>(i));
    const H h = mesh.halfedge(v);
    if(h == SM::null_halfedge() && allow_isolated && is_finite_point(get(vpm, v)))
      continue;
    if(std::size_t(h) >= nh || mesh.target(h) != v || !is_finite_point(get(vpm, v)))
      return false;
    std::size_t count = 0, border = 0;
    H g = h;
    do {
      ++count;
      if(mesh.face(g) == SM::null_face())
        ++border;
      g = mesh.opposite(mesh.next(g));
    } while(g != h && count <= nh);
    if(g != h || border > 1)
      return false;
    around_vertices += count;
  }
  if(around_vertices != nh)
    return false;
  std::size_t around_faces = 0;
  for(std::size_t i = 0; i < nf; ++i) {
    const F f(static_cast<size_type>(i));
    const H h = mesh.halfedge(f);
    if(std::size_t(h) >= nh || mesh.face(h) != f)
      return false;
    const std::size_t size = face_cycle_length(mesh, h);
    if(size < 3 || (required_face_size != 0 && size != static_cast<std::size_t>(required_face_size)))
      return false;
    around_faces += size;
  }
  return around_faces + border_halfedges == nh;
}

// the refusal of element `index` ("vertex 3 is isolated ..."), out of the
// templates: each check below is one call
[[noreturn]] inline void refuse_element(const std::string& scheme, const char* element, std::size_t index,
                                        const std::string& what)
{
  refuse(Message() << scheme << ": " << element << " " << index << " " << what);
}

// the refusals of the whole mesh, out of the templates
[[noreturn]] inline void refuse_mesh(const std::string& scheme, const char* what)
{
  refuse(Message() << scheme << ": " << what);
}

// check_mesh's requirements of every mesh, before the elements are checked
inline void require_faces_and_no_garbage(const std::string& scheme, bool has_faces, bool garbage)
{
  if(!has_faces)
    refuse_mesh(scheme, "the mesh is empty (it has no faces)");
  if(garbage)
    refuse_mesh(scheme, "the mesh still holds removed elements (garbage); call collect_garbage() on it first");
}

[[noreturn]] inline void refuse_invalid_mesh(const std::string& scheme)
{
  refuse_mesh(scheme, "the mesh is not a valid polygon mesh");
}

/*
 * What check_mesh does with a vertex in no face: refuse it, refuse it naming
 * the parameter that accepts it (where the caller has that parameter,
 * `subdivide()`), or let it pass (the caller sets it aside).
 */
enum class Isolated_check { refuse, refuse_naming_parameter, allow };

[[noreturn]] inline void refuse_isolated(const std::string& scheme, std::size_t index, Isolated_check isolated)
{
  refuse_element(scheme, "vertex", index,
                 isolated == Isolated_check::refuse_naming_parameter
                   ? "is isolated (it belongs to no face); the named parameter "
                     "isolated_vertices(Isolated_vertices::keep) or (Isolated_vertices::drop) accepts it"
                   : "is isolated (it belongs to no face)");
}

inline void check_face_size(const std::string& scheme, std::size_t index, std::size_t size, int required_face_size)
{
  if(size < 3)
    refuse(Message() << scheme << ": face " << index << " has only " << size << " vertices");
  if(required_face_size != 0 && size != static_cast<std::size_t>(required_face_size))
    refuse(Message() << scheme << " needs a mesh whose faces all have " << required_face_size << " vertices; face "
                     << index << " has " << size);
}

// CGAL's validity, which refuses a vertex in no face: on a copy without them
// if there are any (this is the error path: the fast checks failed)
template <class Mesh>
bool valid_without_isolated_vertices(const Mesh& mesh)
{
  for(auto v : vertices(mesh))
    if(halfedge(v, mesh) == boost::graph_traits<Mesh>::null_halfedge()) {
      Mesh faces_only(mesh);
      for(auto w : std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>(vertices(faces_only).begin(),
                                                                                      vertices(faces_only).end()))
        if(halfedge(w, faces_only) == boost::graph_traits<Mesh>::null_halfedge())
          CGAL::remove_vertex(w, faces_only);
      return CGAL::is_valid_polygon_mesh(faces_only);
    }
  return CGAL::is_valid_polygon_mesh(mesh);
}

// `isolated`: what a vertex in no face meets
template <class Mesh, class VertexPointMap>
void check_mesh(const Mesh& mesh, const VertexPointMap& vpm, const std::string& scheme, int required_face_size,
                Isolated_check isolated = Isolated_check::refuse)
{
  const bool isolated_pass = isolated == Isolated_check::allow;
  if(passes_mesh_checks(mesh, vpm, required_face_size, isolated_pass))
    return;
  require_faces_and_no_garbage(scheme, !faces(mesh).empty(), has_garbage(mesh));
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
    if(!is_finite_point(get(vpm, v)))
      refuse_element(scheme, "vertex", i, "has a non-finite coordinate");
    if(halfedge(v, mesh) == boost::graph_traits<Mesh>::null_halfedge()) {
      if(!isolated_pass)
        refuse_isolated(scheme, i, isolated);
      ++i;
      continue;
    }
    if(CGAL::halfedges_around_target(v, mesh).size() != get(incoming, v) || get(incoming_border, v) > 1)
      refuse_element(scheme, "vertex", i, "is non-manifold (its faces do not form one fan)");
    ++i;
  }
  i = 0;
  for(auto f : faces(mesh)) {
    check_face_size(scheme, i, CGAL::halfedges_around_face(halfedge(f, mesh), mesh).size(), required_face_size);
    ++i;
  }
  if(!(isolated_pass ? valid_without_isolated_vertices(mesh) : CGAL::is_valid_polygon_mesh(mesh)))
    refuse_invalid_mesh(scheme);
}

/*
 * A Surface_mesh: the same refusals as above, from plain loops over its
 * arrays. The fast check (passes_mesh_checks) is CGAL's validity and more,
 * so a mesh it refuses whose elements all pass is not a valid polygon mesh;
 * neither dynamic maps nor CGAL::is_valid_polygon_mesh are compiled into
 * every program for this error path (about a quarter of the library's part
 * of a plain program's compile time).
 */
template <class P, class VertexPointMap>
void check_mesh(const CGAL::Surface_mesh<P>& mesh, const VertexPointMap& vpm, const std::string& scheme,
                int required_face_size, Isolated_check isolated = Isolated_check::refuse)
{
  using SM = CGAL::Surface_mesh<P>;
  using size_type = typename SM::size_type;
  using H = typename SM::Halfedge_index;
  const bool isolated_pass = isolated == Isolated_check::allow;
  if(passes_mesh_checks(mesh, vpm, required_face_size, isolated_pass))
    return;
  require_faces_and_no_garbage(scheme, mesh.number_of_faces() != 0, mesh.has_garbage());
  const std::size_t nv = mesh.number_of_vertices(), nh = mesh.number_of_halfedges(), nf = mesh.number_of_faces();
  const auto in_range = [nh](H h) { return std::size_t(h) < nh; };
  std::vector<std::size_t> incoming(nv, 0), incoming_border(nv, 0);
  for(std::size_t i = 0; i < nh; ++i) {
    const H h(static_cast<size_type>(i));
    const std::size_t t = std::size_t(mesh.target(h));
    if(!(t < nv && in_range(mesh.next(h)) && in_range(mesh.opposite(h))))
      refuse_invalid_mesh(scheme);
    ++incoming[t];
    if(mesh.face(h) == SM::null_face())
      ++incoming_border[t];
  }
  for(std::size_t i = 0; i < nv; ++i) {
    const typename SM::Vertex_index v(static_cast<size_type>(i));
    if(!is_finite_point(get(vpm, v)))
      refuse_element(scheme, "vertex", i, "has a non-finite coordinate");
    const H h = mesh.halfedge(v);
    if(h == SM::null_halfedge()) {
      if(!isolated_pass)
        refuse_isolated(scheme, i, isolated);
      continue;
    }
    if(!(in_range(h) && mesh.target(h) == v))
      refuse_invalid_mesh(scheme);
    std::size_t fan = 0; // the halfedges around the target, as CGAL's circulator walks them
    H g = h;
    do {
      ++fan;
      g = mesh.opposite(mesh.next(g));
    } while(g != h && fan <= nh);
    if(g != h)
      refuse_invalid_mesh(scheme);
    if(fan != incoming[i] || incoming_border[i] > 1)
      refuse_element(scheme, "vertex", i, "is non-manifold (its faces do not form one fan)");
  }
  for(std::size_t i = 0; i < nf; ++i) {
    const H h = mesh.halfedge(typename SM::Face_index(static_cast<size_type>(i)));
    if(!in_range(h))
      refuse_invalid_mesh(scheme);
    const std::size_t size = face_cycle_length(mesh, h);
    if(size == 0)
      refuse_invalid_mesh(scheme);
    check_face_size(scheme, i, size, required_face_size);
  }
  refuse_invalid_mesh(scheme);
}

/// "17.0 GB", "512 MB", "3 kB": a size for a message
inline std::string memory_text(double bytes)
{
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int unit = 0;
  while(bytes >= 1000 && unit < 6) {
    bytes /= 1000;
    ++unit;
  }
  char text[64];
  std::snprintf(text, sizeof text, unit >= 3 ? "%.1f %s" : "%.0f %s", bytes, units[unit]);
  return text;
}

/*
 * Refuses, before allocating, a level count whose output would not fit in
 * `max_bytes` (0: this machine's memory), in constant time whatever the
 * level count: `faces_in` faces grow by `growth_per_level` per level, and
 * each output face costs `bytes_per_face` at the peak (the host's measured
 * `peak_bytes_per_face()`). `raise_hint` says how the caller raises the limit.
 */
inline void check_output_faces(const std::string& scheme, double faces_in, double growth_per_level,
                               double bytes_per_face, int levels, double max_bytes = 0,
                               const std::string& raise_hint = "the named parameter max_memory raises it")
{
  if(levels < 0)
    refuse(Message() << scheme << ": the number of levels must not be negative, got " << levels);
  if(max_bytes < 0)
    refuse(Message() << scheme << ": the memory limit must be positive");
  const double limit = max_bytes > 0 ? max_bytes : physical_memory_bytes();
  // in logarithms: a billion levels must not take a billion steps
  const double log10_faces = std::log10((std::max)(faces_in, 1.0)) + levels * std::log10(growth_per_level);
  const double log10_bytes = log10_faces + std::log10(bytes_per_face);
  if(log10_bytes <= std::log10(limit))
    return;
  Message message;
  message << scheme << ": " << levels << (levels == 1 ? " level" : " levels") << " on " << std::llround(faces_in)
          << " faces would make ";
  if(log10_faces < 15)
    message << std::llround(std::pow(10.0, log10_faces));
  else
    message << "about 10^" << static_cast<long long>(std::floor(log10_faces));
  message << " faces, about ";
  if(log10_bytes < 18)
    message << memory_text(std::pow(10.0, log10_bytes));
  else
    message << "10^" << static_cast<long long>(std::floor(log10_bytes)) << " bytes";
  message << " at " << std::llround(bytes_per_face) << " bytes per face, more than the memory limit of "
          << memory_text(limit) << (max_bytes > 0 ? "" : " (this machine's memory)") << "; " << raise_hint;
  refuse(message);
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_MESH_CHECKS_H
