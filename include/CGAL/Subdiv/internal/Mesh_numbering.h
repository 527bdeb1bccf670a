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
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

// halfedge(e) of any FaceGraph, for classes whose member `halfedge()` hides the free function
template <class Mesh>
typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_of_edge(
  typename boost::graph_traits<Mesh>::edge_descriptor e, const Mesh& mesh)
{
  return halfedge(e, mesh);
}

/*
 * Dense ordinals 0..n-1 of the vertices, edges and faces of a mesh, in its
 * iteration order: what the hosts number new vertices and faces by.
 * Halfedges are numbered by their edge: 2e for the halfedge that edge e's
 * iteration gives (`halfedge(e)`), 2e+1 for its opposite; so `h ^ 1` is the
 * opposite, `h >> 1` the edge, and `h & 1` tells the direction. Any
 * FaceGraph goes through dynamic property maps; Surface_mesh (without
 * garbage: `check_mesh` refuses it) uses its indices directly.
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
    : m_mesh(&mesh), m_vertex(get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh)),
      m_edge(get(CGAL::dynamic_edge_property_t<std::size_t>(), mesh)),
      m_halfedge(get(CGAL::dynamic_halfedge_property_t<std::size_t>(), mesh)),
      m_face(get(CGAL::dynamic_face_property_t<std::size_t>(), mesh))
  {
    for(auto v : vertices(mesh)) {
      put(m_vertex, v, m_vertices.size());
      m_vertices.push_back(v);
    }
    for(auto e : edges(mesh)) {
      const std::size_t i = m_edges.size();
      put(m_edge, e, i);
      put(m_halfedge, halfedge_of_edge(e, mesh), 2 * i);
      put(m_halfedge, opposite(halfedge_of_edge(e, mesh), mesh), 2 * i + 1);
      m_edges.push_back(e);
    }
    for(auto f : faces(mesh)) {
      put(m_face, f, m_faces.size());
      m_faces.push_back(f);
    }
  }

  std::size_t operator()(typename GT::vertex_descriptor v) const { return get(m_vertex, v); }
  std::size_t operator()(typename GT::edge_descriptor e) const { return get(m_edge, e); }
  std::size_t operator()(typename GT::halfedge_descriptor h) const { return get(m_halfedge, h); }
  std::size_t operator()(typename GT::face_descriptor f) const { return get(m_face, f); }

  /// the element of ordinal i
  typename GT::vertex_descriptor vertex(std::size_t i) const { return m_vertices[i]; }
  typename GT::edge_descriptor edge(std::size_t i) const { return m_edges[i]; }
  typename GT::halfedge_descriptor halfedge(std::size_t i) const
  {
    const auto h = halfedge_of_edge(m_edges[i >> 1], *m_mesh);
    return (i & 1) == 0 ? h : opposite(h, *m_mesh);
  }
  typename GT::face_descriptor face(std::size_t i) const { return m_faces[i]; }

private:
  const Mesh* m_mesh;
  std::vector<typename GT::vertex_descriptor> m_vertices;
  std::vector<typename GT::edge_descriptor> m_edges;
  std::vector<typename GT::face_descriptor> m_faces;
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

  using size_type = typename SM::size_type;

  explicit Mesh_numbering(const SM&) {}
  std::size_t operator()(typename SM::Vertex_index v) const { return v.idx(); }
  std::size_t operator()(typename SM::Edge_index e) const { return e.idx(); }
  std::size_t operator()(typename SM::Halfedge_index h) const { return h.idx(); }
  std::size_t operator()(typename SM::Face_index f) const { return f.idx(); }

  typename SM::Vertex_index vertex(std::size_t i) const { return typename SM::Vertex_index(static_cast<size_type>(i)); }
  typename SM::Edge_index edge(std::size_t i) const { return typename SM::Edge_index(static_cast<size_type>(i)); }
  typename SM::Halfedge_index halfedge(std::size_t i) const
  {
    return typename SM::Halfedge_index(static_cast<size_type>(i));
  }
  typename SM::Face_index face(std::size_t i) const { return typename SM::Face_index(static_cast<size_type>(i)); }
};

/*
 * Calls f(i) for every ordinal i in [0, count): with a dense numbering (a
 * Surface_mesh) in parallel chunks by `loop`, so f must only write what
 * belongs to i; otherwise in order, in this thread.
 */
template <class Numbering, class Loop, class F>
void for_each_ordinal(const Numbering&, std::size_t count, const Loop& loop, const F& f)
{
  const auto run = [&](std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i)
      f(i);
  };
  if constexpr(Numbering::dense)
    loop.for_range(count, 2048, run);
  else
    run(0, count);
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_MESH_NUMBERING_H
