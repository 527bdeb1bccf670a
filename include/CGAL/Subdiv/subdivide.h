// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_SUBDIVIDE_H
#define CGAL_SUBDIV_SUBDIVIDE_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Subdiv/Carried_data.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/hosts/Host_for.h>
#include <CGAL/Subdiv/internal/mesh_checks.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/internal/rebuild_mesh.h>
#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * The point accumulator of surface masks: sums weight * (point - ORIGIN)
 * over the vertices a mask reports, then makes one point.
 */
template <class VertexPointMap>
class Mesh_point_sum
{
public:
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using FT = Point_FT<Point>;

  explicit Mesh_point_sum(const VertexPointMap& vpm) : m_vpm(vpm), m_sum(CGAL::NULL_VECTOR) {}

  template <class VertexDescriptor>
  void add(VertexDescriptor v, const FT& weight)
  {
    m_sum = m_sum + (get(m_vpm, v) - CGAL::ORIGIN) * weight;
  }

  Point point() const { return CGAL::ORIGIN + m_sum; }

private:
  const VertexPointMap& m_vpm;
  Point_vector<Point> m_sum;
};

// Surface_mesh keeps removed elements until collect_garbage(); the hosts
// number elements densely, so garbage is collected first (the mesh is the
// same mesh afterwards).
template <class Mesh>
void make_indices_dense(Mesh&)
{}

template <class Point>
void make_indices_dense(CGAL::Surface_mesh<Point>& mesh)
{
  if(mesh.has_garbage())
    mesh.collect_garbage();
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
 * The point accumulator of the fast path, for 3D points with double
 * coordinates (Simple_cartesian<double>, Epick) stored in one array (a
 * Surface_mesh point map): sums weight * coordinate in three doubles, in the
 * order and with the operations of `Mesh_point_sum`, so the points are the
 * same bit for bit.
 */
template <class Point>
class Flat_point_sum
{
public:
  explicit Flat_point_sum(const Point* points) : m_points(points) {}

  template <class VertexIndex>
  void add(VertexIndex v, double weight)
  {
    const Point& p = m_points[v.idx()];
    m_x = m_x + p.x() * weight;
    m_y = m_y + p.y() * weight;
    m_z = m_z + p.z() * weight;
  }

  Point point() const { return Point(m_x, m_y, m_z); }

private:
  const Point* m_points;
  double m_x = 0, m_y = 0, m_z = 0;
};

template <class Point>
constexpr bool is_double_point_3()
{
  using K = typename CGAL::Kernel_traits<Point>::Kernel;
  return std::is_same<typename K::FT, double>::value && std::is_same<typename K::Point_3, Point>::value;
}

/// one level: the host numbers the new vertices and makes the new faces, the
/// mask gives every new vertex its weights
template <class Mask, class Mesh, class VertexPointMap>
void refine_once(Mesh& mesh, const Mask& mask, const VertexPointMap& vpm, const Parallel_loop& = Parallel_loop())
{
  using Host = Host_of<Mask>;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  const Host host(mesh);
  std::vector<Point> points(host.number_of_new_vertices());
  host.for_each_new_vertex(mask, [&](std::size_t j, const auto& report) {
    Mesh_point_sum<VertexPointMap> sum(vpm);
    report(sum);
    points[j] = sum.point();
  });
  const Face_soup soup = host.faces();
  rebuild_mesh(mesh, vpm, points, soup);
}

// whether the host makes its new faces from a `Split_snapshot` of the old
// mesh (the edge splits), which `wire_split` wires straight into a
// Surface_mesh, with no soup
template <class Host, class = void>
struct Wires_from_snapshot : std::false_type
{};
template <class Host>
struct Wires_from_snapshot<Host, std::void_t<decltype(Host::new_face_size)>> : std::true_type
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

/*
 * The new points of a Surface_mesh, the mesh already resized: the mask runs
 * for every new vertex (in parallel chunks by `loop` for double points and
 * the mesh's own point map); points of new vertices go straight into the
 * point map, those of old vertices wait in `kept` until the old points are no
 * longer read.
 */
template <class Host, class Mask, class P, class VertexPointMap>
void compute_points(CGAL::Surface_mesh<P>& mesh, const Host& host, const Mask& mask, const VertexPointMap& vpm,
                    std::size_t old_vertices, const Parallel_loop& loop)
{
  using SM = CGAL::Surface_mesh<P>;
  using V = typename SM::Vertex_index;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  constexpr bool own_map = std::is_same<VertexPointMap, typename SM::template Property_map<V, Point>>::value;
  if constexpr(own_map) {
    Point* out = &vpm[V(0)];
    std::vector<Point> kept(old_vertices);
    const auto store = [&](std::size_t j, const Point& p) { (j < old_vertices ? kept[j] : out[j]) = p; };
    if constexpr(is_double_point_3<Point>()) {
      host.for_each_new_vertex(
        mask,
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
      host.for_each_new_vertex(mask, [&](std::size_t j, const auto& report) {
        Mesh_point_sum<VertexPointMap> sum(vpm);
        report(sum);
        store(j, sum.point());
      });
      std::copy(kept.begin(), kept.end(), out);
    }
  } else {
    std::vector<Point> points(host.number_of_new_vertices());
    host.for_each_new_vertex(mask, [&](std::size_t j, const auto& report) {
      Mesh_point_sum<VertexPointMap> sum(vpm);
      report(sum);
      points[j] = sum.point();
    });
    for(std::size_t i = 0; i < points.size(); ++i)
      put(vpm, V(static_cast<typename SM::size_type>(i)), points[i]);
  }
}

/*
 * An edge split of a Surface_mesh with threads, double points in the mesh's
 * own map: the resize of the arrays (which the standard library fills in one
 * thread) runs beside the loops that only read the old mesh, the snapshot of
 * its faces and the masks (every new point into a buffer of its own, copied
 * into the point map afterwards). Room is reserved first, so the resize does
 * not move the arrays and the old elements stay where the readers look;
 * nothing the readers call looks at the arrays' sizes. Returns false (and
 * does nothing) when not applicable.
 */
template <class Host, class Mask, class P, class VertexPointMap>
bool refine_beside_resize(CGAL::Surface_mesh<P>& mesh, const Host& host, const Mask& mask, const VertexPointMap& vpm,
                          const Parallel_loop& loop)
{
  using SM = CGAL::Surface_mesh<P>;
  using V = typename SM::Vertex_index;
  using size_type = typename SM::size_type;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  constexpr bool own_map = std::is_same<VertexPointMap, typename SM::template Property_map<V, Point>>::value;
  if constexpr(resize_beside_reads && own_map && is_double_point_3<Point>()) {
    if(!loop.is_parallel())
      return false;
    const std::size_t old_vertices = num_vertices(mesh);
    const auto nv = static_cast<size_type>(host.number_of_new_vertices());
    const auto ne = static_cast<size_type>(host.number_of_new_edges());
    const auto nf = static_cast<size_type>(host.number_of_new_faces());
    Face_soup::check_counts(nv, ne);
    mesh.reserve(nv, ne, nf);             // no-op when the room is there (`reserve_levels`)
    const Point* old_points = &vpm[V(0)]; // stays valid: the resize below is within capacity
    std::vector<Point> points(nv);
    Split_snapshot snapshot;
    const Parallel_loop inner = loop.in_arena();
    loop.invoke(
      [&] {
        snapshot = host.snapshot(inner, true);
        host.for_each_new_vertex(
          mask,
          [&](std::size_t j, const auto& report) {
            Flat_point_sum<Point> sum(old_points);
            report(sum);
            points[j] = sum.point();
          },
          inner);
      },
      [&] { mesh.resize(nv, ne, nf); });
    CGAL_assertion(&vpm[V(0)] == old_points);
    Point* out = &vpm[V(0)];
    wire_split(mesh, host, snapshot, old_vertices, loop, [&](const Parallel_loop& copy_loop) {
      copy_loop.for_range(nv, 16384, [&](std::size_t begin, std::size_t end) {
        std::copy(points.begin() + static_cast<std::ptrdiff_t>(begin),
                  points.begin() + static_cast<std::ptrdiff_t>(end), out + begin);
      });
    });
    return true;
  } else {
    (void)mesh, (void)host, (void)mask, (void)vpm, (void)loop;
    return false;
  }
}

/*
 * One level of a Surface_mesh, in place: the host makes the new faces from
 * the old mesh (for the edge splits, a snapshot of the old faces, a quarter
 * of a soup of the new ones), the mesh is resized (old elements keep their
 * index, so the old mesh is still there, below the new elements), the new
 * points are computed from it, points of new vertices straight into the
 * point map, then the connectivity is wired over the old one. With a
 * parallel `loop`, the faces, the points (double coordinates and a point map
 * of the mesh) and the wiring run in parallel chunks, and for the edge splits
 * the resize beside the snapshot and the points; the result is the same.
 */
template <class Mask, class P, class VertexPointMap>
void refine_once(CGAL::Surface_mesh<P>& mesh, const Mask& mask, const VertexPointMap& vpm,
                 const Parallel_loop& loop = Parallel_loop())
{
  using SM = CGAL::Surface_mesh<P>;
  using size_type = typename SM::size_type;
  using Host = Host_of<Mask>;
  const Host host(mesh);
  const std::size_t old_vertices = num_vertices(mesh);
  if constexpr(Wires_from_snapshot<Host>::value) {
    if(refine_beside_resize(mesh, host, mask, vpm, loop))
      return;
    const Split_snapshot snapshot = host.snapshot(loop, true);
    mesh.resize(static_cast<size_type>(host.number_of_new_vertices()),
                static_cast<size_type>(host.number_of_new_edges()), static_cast<size_type>(host.number_of_new_faces()));
    compute_points(mesh, host, mask, vpm, old_vertices, loop);
    wire_split(mesh, host, snapshot, old_vertices, loop);
  } else {
    const Face_soup soup = host.faces(loop, false);
    mesh.resize(static_cast<size_type>(soup.number_of_vertices()), static_cast<size_type>(soup.number_of_edges()),
                static_cast<size_type>(soup.number_of_faces()));
    compute_points(mesh, host, mask, vpm, old_vertices, loop);
    wire_surface_mesh(mesh, soup, loop);
  }
}

/// one level that also carries other vertex and face data: the stencils are
/// recorded once and applied to the points and to every vertex map
template <class Mask, class Mesh, class VertexPointMap, class FT>
void refine_once(Mesh& mesh, const Mask& mask, const VertexPointMap& vpm, const Carried_data<Mesh, FT>& data)
{
  using Host = Host_of<Mask>;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  const Host host(mesh);
  typename Carried_data<Mesh, FT>::Vertex_stencils stencils(host.number_of_new_vertices());
  host.for_each_new_vertex(mask, [&](std::size_t j, const auto& report) { report(stencils[j]); });
  std::vector<Point> points;
  points.reserve(stencils.size());
  for(const auto& stencil : stencils) {
    Mesh_point_sum<VertexPointMap> sum(vpm);
    for(const auto& term : stencil.terms())
      sum.add(term.first, term.second);
    points.push_back(sum.point());
  }
  data.record_origins(host);
  const auto vertex_writers = data.read_vertices(stencils);
  const auto face_writers = data.read_faces(mesh);
  const Face_soup soup = host.faces();
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> new_vertices;
  std::vector<typename boost::graph_traits<Mesh>::face_descriptor> new_faces;
  rebuild_mesh(mesh, vpm, points, soup, &new_vertices, &new_faces);
  for(const auto& write : vertex_writers)
    write(new_vertices);
  for(const auto& write : face_writers)
    write(new_faces, soup);
}

} // namespace internal

/*!
 * \ingroup PkgSubdivFunctions
 * refines `mesh` in place `number_of_iterations` times with the rules of
 * `mask` on the topological split of `Host_of<Mask>`.
 *
 * \tparam PolygonMesh a model of `MutableFaceGraph`
 * \tparam Mask a model of `SurfaceSubdivisionMask` (`Loop_mask`, ...)
 * \param np optional named parameters:
 *   - `number_of_iterations` (default 1): how many levels;
 *   - `vertex_point_map` (default the mesh's internal point map): where the
 *     points are read and written; its value type's kernel FT must be the
 *     mask's `Number_type`;
 *   - `carried_data` (`CGAL::Subdiv::carried_data(data, np)`):
 *     other vertex data interpolated with the same stencils, face data
 *     inherited by child faces (see `Carried_data`);
 *   - `threads` (`CGAL::Subdiv::threads(n, np)`, default 1; 0: TBB's choice):
 *     how many threads refine a `Surface_mesh` (points with double
 *     coordinates; with TBB only); the result is the same bit for bit with
 *     any number.
 *
 * \throws Bad_input when the mesh does not suit the scheme (empty, isolated or
 * non-manifold vertices, non-finite coordinates, a face of the wrong size) or
 * when the output would not fit in memory. The mesh is then unchanged.
 */
template <class PolygonMesh, class Mask, class NamedParameters = parameters::Default_named_parameters>
void subdivide(PolygonMesh& mesh, const Mask& mask, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Host = Host_of<Mask>;

  const auto vpm =
    choose_parameter(get_parameter(np, internal_np::vertex_point), get_property_map(CGAL::vertex_point, mesh));
  const int levels = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 1);

  internal::check_mesh(mesh, vpm, mask.name(), Host::required_face_size);
  internal::check_output_faces(mask.name(), static_cast<double>(num_faces(mesh)), Host::face_growth(), levels);
  using Data = Carried_data<PolygonMesh, typename Mask::Number_type>;
  const Data* data = choose_parameter<const Data*>(get_parameter(np, internal::carried_data_t()), nullptr);

  const internal::Parallel_loop loop = internal::parallel_loop(np);

  internal::make_indices_dense(mesh);
  internal::reserve_levels<Host>(mesh, levels);
  for(int level = 0; level < levels; ++level) {
    if(data != nullptr && !data->empty())
      internal::refine_once(mesh, mask, vpm, *data);
    else
      internal::refine_once(mesh, mask, vpm, loop);
  }
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_SUBDIVIDE_H
