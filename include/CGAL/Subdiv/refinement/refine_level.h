// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_REFINEMENT_REFINE_LEVEL_H
#define CGAL_SUBDIV_REFINEMENT_REFINE_LEVEL_H

/// \file refine_level.h
/// The one level pipeline. `refine_level(mesh, mask, points, loop, sinks...)`:
///   1. the host of the mask's split is built on the old mesh;
///   2. every sink reads what it needs of the old level (`sink.read(host,
///      mask, loop)`: rows composed for a stencil table, stencils recorded,
///      old values of carried data, ...), usually by running the mask through
///      `for_each_new_vertex`;
///   3. the new points and the new topology are written by the writer of the
///      mesh: any MutableFaceGraph is rebuilt, a Surface_mesh is wired in
///      place (with threads, its resize runs beside the masks); the points come
///      from the point source: the mask itself, recorded rows, or none;
///   4. every sink writes what it needs of the new level (`sink.write(level)`).
/// Subdivision, carried data, stencil tables, the analysis and the limit all
/// refine through it.

#include <CGAL/Subdiv/hosts/Host_for.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/Subdiv/refinement/Child_faces.h>
#include <CGAL/Subdiv/refinement/point_sums.h>
#include <CGAL/Subdiv/refinement/write_faces.h>
#include <CGAL/Subdiv/stencils/Stencil.h>

#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * The one traversal of the new vertices: calls visit(j, report) for every
 * new vertex j of `host`, where report(acc) makes `mask` report j's weights to
 * `acc`. With a parallel `loop` (a Surface_mesh host), in chunks of
 * consecutive new vertices from several threads: visit must write only what
 * belongs to j. The host reads only the old elements.
 */
template <class Host, class Mask, class Visit>
void for_each_new_vertex(const Host& host, const Mask& mask, const Visit& visit,
                         const Parallel_loop& loop = Parallel_loop())
{
  loop.for_range(host.number_of_new_vertices(), 2048, [&](std::size_t first, std::size_t last) {
    for(std::size_t j = first; j < last; ++j)
      visit(j, [&](auto& acc) { host.report(j, mask, acc); });
  });
}

/// point source: the mask's report of every new vertex, summed over the points of `vpm`
template <class VertexPointMap>
struct Mask_points
{
  VertexPointMap vpm;
};

/// point source: the recorded row of every new vertex (`rows[j]`, a range of
/// (vertex, weight)), summed over the points of `vpm`, the weights converted
/// to the points' number type
template <class VertexPointMap, class Rows>
struct Row_points
{
  VertexPointMap vpm;
  const Rows* rows;
};

/// point source: none, the new level's topology only (new vertices get the
/// origin, or on a Surface_mesh what its resize gives them)
template <class VertexPointMap>
struct No_points
{
  VertexPointMap vpm;
};

template <class VertexPointMap>
using Point_of_map = typename boost::property_traits<VertexPointMap>::value_type;

// the new points of a point source, computed from the old level (in this thread)
template <class Host, class Mask, class VPM>
std::vector<Point_of_map<VPM>> new_points(const Host& host, const Mask& mask, const Mask_points<VPM>& source)
{
  std::vector<Point_of_map<VPM>> points(host.number_of_new_vertices());
  for_each_new_vertex(host, mask, [&](std::size_t j, const auto& report) {
    Mesh_point_sum<VPM> sum(source.vpm);
    report(sum);
    points[j] = sum.point();
  });
  return points;
}

template <class Host, class Mask, class VPM, class Rows>
std::vector<Point_of_map<VPM>> new_points(const Host&, const Mask&, const Row_points<VPM, Rows>& source)
{
  using FT = Point_FT<Point_of_map<VPM>>;
  std::vector<Point_of_map<VPM>> points;
  points.reserve(source.rows->size());
  for(const auto& row : *source.rows) {
    Mesh_point_sum<VPM> sum(source.vpm);
    for(const auto& term : row)
      sum.add(term.first, convert_weight<FT>(term.second));
    points.push_back(sum.point());
  }
  return points;
}

template <class Host, class Mask, class VPM>
std::vector<Point_of_map<VPM>> new_points(const Host& host, const Mask&, const No_points<VPM>&)
{
  return std::vector<Point_of_map<VPM>>(host.number_of_new_vertices(), Point_of_map<VPM>(CGAL::ORIGIN));
}

/*
 * What a level wrote, for the sinks: its child faces (with their parents),
 * and the descriptors of the new elements (made on demand on a
 * Surface_mesh wired in place, whose new element i is its index i).
 */
template <class Mesh, class Faces>
class New_level
{
public:
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;

  New_level(Faces faces, New_elements<Mesh> elements) : m_faces(std::move(faces)), m_elements(std::move(elements)) {}

  const Faces& faces() const { return m_faces; }

  /// the new vertices and faces, by new index
  const New_elements<Mesh>& elements() const
  {
    if constexpr(Mesh_numbering<Mesh>::dense) { // a Surface_mesh: new element i is index i
      using size_type = typename Mesh::size_type;
      if(m_elements.vertices.size() != m_faces.number_of_vertices() ||
         m_elements.faces.size() != m_faces.number_of_faces()) {
        m_elements.vertices.clear();
        m_elements.faces.clear();
        for(std::size_t i = 0; i < m_faces.number_of_vertices(); ++i)
          m_elements.vertices.push_back(vertex_descriptor(static_cast<size_type>(i)));
        for(std::size_t f = 0; f < m_faces.number_of_faces(); ++f)
          m_elements.faces.push_back(face_descriptor(static_cast<size_type>(f)));
      }
    }
    return m_elements;
  }

  /// the new halfedge of id `id` (`Face_corner::halfedge`)
  typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge(std::size_t id) const
  {
    if constexpr(Mesh_numbering<Mesh>::dense) // a Surface_mesh: new halfedge id is index id
      return typename Mesh::Halfedge_index(static_cast<typename Mesh::size_type>(id));
    else
      return m_elements.halfedges[id];
  }

  /// new edge k: the edge of new halfedge ids 2k and 2k + 1
  typename boost::graph_traits<Mesh>::edge_descriptor edge(std::size_t k, const Mesh& mesh) const
  {
    if constexpr(Mesh_numbering<Mesh>::dense) { // a Surface_mesh: new edge k is index k
      (void)mesh;
      return typename Mesh::Edge_index(static_cast<typename Mesh::size_type>(k));
    } else
      return CGAL::edge(m_elements.halfedges[2 * k], mesh);
  }

  /// the parent (old face ordinal) of every new face, by new index
  std::vector<std::size_t> parents() const
  {
    std::vector<std::size_t> result(m_faces.number_of_faces());
    for(std::size_t b = 0; b < m_faces.number_of_blocks(); ++b)
      m_faces.for_each_face_in_block(
        b, [&](std::size_t f, const Face_corner*, std::size_t, std::size_t parent) { result[f] = parent; });
    return result;
  }

private:
  Faces m_faces;
  mutable New_elements<Mesh> m_elements;
};

template <class Faces>
struct Is_split_faces : std::false_type
{};
template <class Host>
struct Is_split_faces<Split_faces<Host>> : std::true_type
{};

// The resize of a Surface_mesh may run beside the loops that read the old
// mesh only when its accessors do not read the arrays' sizes (which the
// resize changes): not with CGAL's or the standard library's assertions.
#if defined(CGAL_NO_ASSERTIONS) && !defined(_GLIBCXX_ASSERTIONS) && !defined(_GLIBCXX_DEBUG) && \
  !defined(CGAL_SUBDIV_NO_CONCURRENT_RESIZE)
constexpr bool resize_beside_reads = true;
#else
constexpr bool resize_beside_reads = false;
#endif

// the Surface_mesh's own point map, of 3D points with double coordinates
template <class P, class VertexPointMap>
constexpr bool is_own_double_point_map()
{
  using SM = CGAL::Surface_mesh<P>;
  using Point = Point_of_map<VertexPointMap>;
  return std::is_same<VertexPointMap, typename SM::template Property_map<typename SM::Vertex_index, Point>>::value &&
         Is_double_point_3<Point>::value;
}

/*
 * Any MutableFaceGraph: the points are computed from the old level, the
 * record of the new faces made, and the mesh rebuilt from them.
 */
template <class Mesh, class Host, class Mask, class Points>
auto write_level(Mesh& mesh, const Host& host, const Mask& mask, const Points& points, const Parallel_loop&)
{
  const auto new_point = new_points(host, mask, points);
  auto faces = host.child_faces(Parallel_loop(1));
  New_elements<Mesh> elements = rebuild_mesh(mesh, points.vpm, new_point, faces);
  return New_level<Mesh, decltype(faces)>(std::move(faces), std::move(elements));
}

/*
 * The points of a Surface_mesh already resized to the new counts, whose old
 * elements are still there below the new ones: the mask runs for every new
 * vertex; with the mesh's own point map, points of new vertices go straight
 * into it (in parallel chunks by `loop` for double coordinates), those of
 * old vertices wait in `kept` until the old points are no longer read; other
 * maps get all points once they are computed.
 */
template <class P, class Host, class Mask, class VPM>
void write_points(CGAL::Surface_mesh<P>& mesh, const Host& host, const Mask& mask, const Mask_points<VPM>& source,
                  std::size_t old_vertices, const Parallel_loop& loop)
{
  using SM = CGAL::Surface_mesh<P>;
  using V = typename SM::Vertex_index;
  using Point = Point_of_map<VPM>;
  constexpr bool own_map = std::is_same<VPM, typename SM::template Property_map<V, Point>>::value;
  if constexpr(own_map) {
    Point* out = &source.vpm[V(0)];
    std::vector<Point> kept(old_vertices);
    const auto store = [&](std::size_t j, const Point& p) { (j < old_vertices ? kept[j] : out[j]) = p; };
    if constexpr(Is_double_point_3<Point>::value) {
      for_each_new_vertex(
        host, mask,
        [&](std::size_t j, const auto& report) {
          Flat_point_sum<Point> sum(out);
          report(sum);
          store(j, sum.point());
        },
        loop);
      loop.for_range(old_vertices, 16384, [&](std::size_t begin, std::size_t end) {
        std::copy(kept.begin() + static_cast<std::ptrdiff_t>(begin), kept.begin() + static_cast<std::ptrdiff_t>(end),
                  out + begin);
      });
    } else {
      for_each_new_vertex(host, mask, [&](std::size_t j, const auto& report) {
        Mesh_point_sum<VPM> sum(source.vpm);
        report(sum);
        store(j, sum.point());
      });
      std::copy(kept.begin(), kept.end(), out);
    }
  } else {
    (void)mesh, (void)old_vertices, (void)loop;
    const std::vector<Point> points = new_points(host, mask, source);
    for(std::size_t i = 0; i < points.size(); ++i)
      put(source.vpm, V(static_cast<typename SM::size_type>(i)), points[i]);
  }
}

template <class P, class Host, class Mask, class VPM, class Rows>
void write_points(CGAL::Surface_mesh<P>&, const Host& host, const Mask& mask, const Row_points<VPM, Rows>& source,
                  std::size_t, const Parallel_loop&)
{
  using SM = CGAL::Surface_mesh<P>;
  const auto points = new_points(host, mask, source);
  for(std::size_t i = 0; i < points.size(); ++i)
    put(source.vpm, typename SM::Vertex_index(static_cast<typename SM::size_type>(i)), points[i]);
}

template <class P, class Host, class Mask, class VPM>
void write_points(CGAL::Surface_mesh<P>&, const Host&, const Mask&, const No_points<VPM>&, std::size_t,
                  const Parallel_loop&)
{}

/*
 * An edge split of a Surface_mesh with threads, double points in the mesh's
 * own map: the resize of the arrays (which the standard library fills in one
 * thread) runs beside the loops that only read the old mesh, the snapshot of
 * its faces and the masks (every new point into a buffer of its own, copied
 * into the point map afterwards). Room is reserved first, so the resize does
 * not move the arrays and the old elements stay where the readers look;
 * nothing the readers call looks at the arrays' sizes.
 */
template <class P, class Host, class Mask, class VPM>
auto write_beside_resize(CGAL::Surface_mesh<P>& mesh, const Host& host, const Mask& mask,
                         const Mask_points<VPM>& source, const Parallel_loop& loop)
{
  using SM = CGAL::Surface_mesh<P>;
  using V = typename SM::Vertex_index;
  using size_type = typename SM::size_type;
  using Point = Point_of_map<VPM>;
  using Faces = decltype(host.child_faces(loop));
  const auto nv = static_cast<size_type>(host.number_of_new_vertices());
  const auto ne = static_cast<size_type>(host.number_of_new_edges());
  const auto nf = static_cast<size_type>(host.number_of_new_faces());
  check_child_counts(nv, ne);
  mesh.reserve(nv, ne, nf);                    // no-op when the room is there (`reserve_levels`)
  const Point* old_points = &source.vpm[V(0)]; // stays valid: the resize below is within capacity
  std::vector<Point> points(nv);
  std::optional<Faces> faces;
  const Parallel_loop inner = loop.in_arena();
  loop.invoke(
    [&] {
      faces.emplace(host.child_faces(inner));
      for_each_new_vertex(
        host, mask,
        [&](std::size_t j, const auto& report) {
          Flat_point_sum<Point> sum(old_points);
          report(sum);
          points[j] = sum.point();
        },
        inner);
    },
    [&] { mesh.resize(nv, ne, nf); });
  CGAL_assertion(&source.vpm[V(0)] == old_points);
  Point* out = &source.vpm[V(0)];
  wire_surface_mesh(mesh, *faces, loop, [&](const Parallel_loop& copy_loop) {
    copy_loop.for_range(nv, 16384, [&](std::size_t begin, std::size_t end) {
      std::copy(points.begin() + static_cast<std::ptrdiff_t>(begin), points.begin() + static_cast<std::ptrdiff_t>(end),
                out + begin);
    });
  });
  return New_level<SM, Faces>(std::move(*faces), New_elements<SM>());
}

/*
 * A Surface_mesh, in place: the host makes the record of the new faces from
 * the old mesh (in parallel chunks by `loop`), the mesh is resized (old
 * elements keep their index, so the old mesh is still there, below the new
 * elements), the new points are computed from it, then the connectivity is
 * wired over the old one. For the edge splits with threads and double points
 * in the mesh's own map, the resize runs beside the record and the masks
 * (`write_beside_resize`); the result is the same.
 */
template <class P, class Host, class Mask, class Points>
auto write_level(CGAL::Surface_mesh<P>& mesh, const Host& host, const Mask& mask, const Points& points,
                 const Parallel_loop& loop)
{
  using SM = CGAL::Surface_mesh<P>;
  using size_type = typename SM::size_type;
  using Faces = decltype(host.child_faces(loop));
  if constexpr(resize_beside_reads && Is_split_faces<Faces>::value &&
               std::is_same<Points, Mask_points<decltype(points.vpm)>>::value &&
               is_own_double_point_map<P, decltype(points.vpm)>()) {
    if(loop.is_parallel())
      return write_beside_resize(mesh, host, mask, points, loop);
  }
  Faces faces = host.child_faces(loop);
  const std::size_t old_vertices = num_vertices(mesh);
  mesh.resize(static_cast<size_type>(faces.number_of_vertices()), static_cast<size_type>(faces.number_of_edges()),
              static_cast<size_type>(faces.number_of_faces()));
  write_points(mesh, host, mask, points, old_vertices, loop);
  wire_surface_mesh(mesh, faces, loop);
  return New_level<SM, Faces>(std::move(faces), New_elements<SM>());
}

/// a sink of `refine_level`: the stencil of every new vertex over the old
/// vertices, merged (`Stencil::add`), by new index
template <class Mesh, class FT>
struct Stencil_recorder
{
  std::vector<Stencil<typename boost::graph_traits<Mesh>::vertex_descriptor, FT>> rows;

  template <class Host, class Mask>
  void read(const Host& host, const Mask& mask, const Parallel_loop&)
  {
    rows.assign(host.number_of_new_vertices(), typename decltype(rows)::value_type());
    // room for the terms of a regular vertex of the quad split (9), so that
    // most rows allocate once rather than doubling from one term
    constexpr std::size_t usual_terms = 9;
    for_each_new_vertex(host, mask, [&](std::size_t j, const auto& report) {
      rows[j].reserve(usual_terms);
      report(rows[j]);
    });
  }
  template <class Level>
  void write(const Level&)
  {}
};

/// refines `mesh` one level with `mask`: see the file comment
template <class Mesh, class Mask, class Points, class... Sinks>
void refine_level(Mesh& mesh, const Mask& mask, const Points& points, const Parallel_loop& loop, Sinks&... sinks)
{
  static_assert(std::is_same<typename Mask::Polygon_mesh, Mesh>::value, "the mask is for another mesh type");
  const Host_of<Mask> host = make_host(mesh, mask);
  (sinks.read(host, mask, loop), ...);
  const auto level = write_level(mesh, host, mask, points, loop);
  (sinks.write(level), ...);
}

// Surface_mesh, several levels of a host that knows its counts: room for the
// last level is made at once, so the arrays are not moved at every level
// (an estimate above the truth costs address space only: untouched pages
// are never mapped)
template <class Host, class Mesh>
void reserve_levels(Mesh&, int)
{}

template <class Host, class Point>
void reserve_levels(CGAL::Surface_mesh<Point>& mesh, int levels)
{
  if(levels < 2)
    return;
  Mesh_counts counts{mesh.number_of_vertices(), mesh.number_of_edges(), mesh.number_of_faces(),
                     mesh.number_of_halfedges()};
  std::size_t border = 0;
  for(auto h : mesh.halfedges())
    if(mesh.is_border(h))
      ++border;
  counts.corners -= border;
  for(int level = 0; level < levels; ++level)
    if(!Host::next_counts(counts))
      return;
  mesh.reserve(static_cast<typename CGAL::Surface_mesh<Point>::size_type>(counts.vertices),
               static_cast<typename CGAL::Surface_mesh<Point>::size_type>(counts.edges),
               static_cast<typename CGAL::Surface_mesh<Point>::size_type>(counts.faces));
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_REFINEMENT_REFINE_LEVEL_H
