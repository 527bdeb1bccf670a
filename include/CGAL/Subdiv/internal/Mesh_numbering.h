// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_MESH_NUMBERING_H
#define CGAL_SUBDIV_INTERNAL_MESH_NUMBERING_H

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * Dense ordinals 0..n-1 of the vertices, edges and faces of a mesh, in its
 * iteration order: what the hosts number new vertices and faces by.
 * Halfedges are numbered by their edge: 2e for the halfedge that edge e's
 * iteration gives (`halfedge(e)`), 2e+1 for its opposite; so `h ^ 1` is the
 * opposite, `h >> 1` the edge, and `h & 1` tells the direction. Any FaceGraph goes through dynamic property maps; Surface_mesh (whose
 * garbage `subdivide()` collects first) uses its indices directly.
 */
template <class Mesh>
class Mesh_numbering
{
  using GT = boost::graph_traits<Mesh>;

public:
  /// whether ordinal i is the mesh's own index i (Surface_mesh): loops can
  /// then run on index ranges, in parallel chunks
  static constexpr bool dense = false;

  explicit Mesh_numbering(const Mesh& mesh)
    : m_vertex(get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh)),
      m_edge(get(CGAL::dynamic_edge_property_t<std::size_t>(), mesh)),
      m_halfedge(get(CGAL::dynamic_halfedge_property_t<std::size_t>(), mesh)),
      m_face(get(CGAL::dynamic_face_property_t<std::size_t>(), mesh))
  {
    std::size_t i = 0;
    for(auto v : vertices(mesh))
      put(m_vertex, v, i++);
    i = 0;
    for(auto e : edges(mesh))
      put(m_edge, e, i++);
    i = 0;
    for(auto e : edges(mesh)) {
      put(m_halfedge, halfedge(e, mesh), 2 * i);
      put(m_halfedge, opposite(halfedge(e, mesh), mesh), 2 * i + 1);
      ++i;
    }
    i = 0;
    for(auto f : faces(mesh))
      put(m_face, f, i++);
  }

  std::size_t operator()(typename GT::vertex_descriptor v) const { return get(m_vertex, v); }
  std::size_t operator()(typename GT::edge_descriptor e) const { return get(m_edge, e); }
  std::size_t operator()(typename GT::halfedge_descriptor h) const { return get(m_halfedge, h); }
  std::size_t operator()(typename GT::face_descriptor f) const { return get(m_face, f); }

private:
  typename boost::property_map<Mesh, CGAL::dynamic_vertex_property_t<std::size_t>>::const_type m_vertex;
  typename boost::property_map<Mesh, CGAL::dynamic_edge_property_t<std::size_t>>::const_type m_edge;
  typename boost::property_map<Mesh, CGAL::dynamic_halfedge_property_t<std::size_t>>::const_type m_halfedge;
  typename boost::property_map<Mesh, CGAL::dynamic_face_property_t<std::size_t>>::const_type m_face;
};

template <class Point>
class Mesh_numbering<CGAL::Surface_mesh<Point>>
{
  using SM = CGAL::Surface_mesh<Point>;

public:
  static constexpr bool dense = true;

  explicit Mesh_numbering(const SM&) {}
  std::size_t operator()(typename SM::Vertex_index v) const { return v.idx(); }
  std::size_t operator()(typename SM::Edge_index e) const { return e.idx(); }
  std::size_t operator()(typename SM::Halfedge_index h) const { return h.idx(); }
  std::size_t operator()(typename SM::Face_index f) const { return f.idx(); }
};

/*
 * Calls f(d) for every element d of `range` (the vertices, edges or faces of
 * a mesh, `count` of them): with a dense numbering on index ranges, split into
 * chunks by `loop` (so f must only write what belongs to d), otherwise in
 * iteration order in this thread.
 */
template <class Numbering, class Range, class Loop, class F>
void for_each_element(const Numbering&, const Range& range, std::size_t count, const Loop& loop, const F& f)
{
  if constexpr(Numbering::dense) {
    using Descriptor = std::decay_t<decltype(*range.begin())>;
    using Size = decltype(std::declval<Descriptor>().idx());
    loop.for_range(count, 2048, [&](std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i)
        f(Descriptor(static_cast<Size>(i)));
    });
  } else {
    (void)count;
    (void)loop;
    for(const auto& d : range)
      f(d);
  }
}

/*
 * The same, the range made by `make_range()` only when the numbering is not
 * dense: on a Surface_mesh the loop then reads nothing of the mesh but the
 * elements it visits (not the element counts), so it may run while the
 * mesh's arrays grow within their capacity.
 */
template <class Numbering, class MakeRange, class Loop, class F>
void for_each_element_of(const Numbering& number, const MakeRange& make_range, std::size_t count, const Loop& loop,
                         const F& f)
{
  if constexpr(Numbering::dense) {
    using Range = decltype(make_range());
    using Descriptor = std::decay_t<decltype(*std::declval<const Range&>().begin())>;
    using Size = decltype(std::declval<Descriptor>().idx());
    (void)number;
    loop.for_range(count, 2048, [&](std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i)
        f(Descriptor(static_cast<Size>(i)));
    });
  } else {
    for_each_element(number, make_range(), count, loop, f);
  }
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_MESH_NUMBERING_H
