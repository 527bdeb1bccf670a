// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_REFINEMENT_WRITE_FACES_H
#define CGAL_SUBDIV_REFINEMENT_WRITE_FACES_H

/// \file write_faces.h
/// The writers of a level's new topology (`Child_faces`): one for any
/// `MutableFaceGraph`, one that wires a `Surface_mesh` in place; and the one
/// border wiring both use.

#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/refinement/Child_faces.h>

#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * The border halfedges of a new level, once the halfedges of the faces are
 * wired (each with its next, prev and target): they get no face, end where
 * their opposite starts, and lead to the border halfedge that leaves their
 * target (found by turning around that vertex); border vertices keep their
 * incoming border halfedge. `halfedge_of(id)` is the new halfedge of an id.
 */
template <class Mesh, class HalfedgeOf>
void wire_border(Mesh& mesh, const std::vector<Child_index>& border, const HalfedgeOf& halfedge_of)
{
  using GT = boost::graph_traits<Mesh>;
  for(const Child_index id : border)
    set_face(halfedge_of(id), GT::null_face(), mesh);
  for(const Child_index id : border) {
    const typename GT::halfedge_descriptor b = halfedge_of(id);
    set_target(b, target(prev(opposite(b, mesh), mesh), mesh), mesh);
  }
  for(const Child_index id : border) {
    const typename GT::halfedge_descriptor b = halfedge_of(id);
    // turn around target(b), from the face halfedge leaving it, to the border halfedge leaving it
    typename GT::halfedge_descriptor around = opposite(b, mesh);
    while(!is_border(around, mesh))
      around = opposite(prev(around, mesh), mesh);
    set_next(b, around, mesh);
    set_halfedge(target(b, mesh), b, mesh);
  }
}

// Empty the mesh but keep its property maps, so that a vertex point map (or
// any other map) the caller holds stays valid and grows with the new elements.
template <class Mesh>
void clear_keeping_properties(Mesh& mesh)
{
  CGAL::clear(mesh);
}

template <class Point>
void clear_keeping_properties(CGAL::Surface_mesh<Point>& mesh)
{
  mesh.clear_without_removing_property_maps();
}

/// the new halfedges by id (2k and 2k + 1 on new edge k), where the mesh is
/// rebuilt element by element; a Surface_mesh, wired in place, numbers its new
/// edges itself (`New_level::edge`), so a program that refines one does not
/// compile the vector
template <class Mesh>
struct New_halfedges
{
  std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor> halfedges;
};
template <class P>
struct New_halfedges<CGAL::Surface_mesh<P>>
{};

/// the descriptors of the new vertices, faces (and halfedges), by new index
template <class Mesh>
struct New_elements : New_halfedges<Mesh>
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> vertices;
  std::vector<typename boost::graph_traits<Mesh>::face_descriptor> faces;
};

/*
 * Any MutableFaceGraph: the mesh is replaced by the new level through its
 * low-level functions. Vertices, edges and faces are created in the order of
 * the record (new vertex i gets points[i]), every halfedge of a face is wired
 * with its face, then the border. Returns the new descriptors.
 */
template <class Mesh, class VertexPointMap, class Point, class Faces>
New_elements<Mesh> rebuild_mesh(Mesh& mesh, const VertexPointMap& vpm, const std::vector<Point>& points,
                                const Faces& faces)
{
  using GT = boost::graph_traits<Mesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;

  clear_keeping_properties(mesh);
  CGAL::reserve(mesh, static_cast<typename GT::vertices_size_type>(faces.number_of_vertices()),
                static_cast<typename GT::edges_size_type>(faces.number_of_edges()),
                static_cast<typename GT::faces_size_type>(faces.number_of_faces()));
  New_elements<Mesh> result;
  result.vertices.reserve(faces.number_of_vertices());
  for(std::size_t i = 0; i < faces.number_of_vertices(); ++i) {
    result.vertices.push_back(add_vertex(mesh));
    put(vpm, result.vertices.back(), points[i]);
  }
  std::vector<halfedge_descriptor> halfedge_of(2 * faces.number_of_edges());
  for(std::size_t e = 0; e < faces.number_of_edges(); ++e) {
    const halfedge_descriptor h = halfedge(add_edge(mesh), mesh);
    halfedge_of[2 * e] = h;
    halfedge_of[2 * e + 1] = opposite(h, mesh);
  }
  result.faces.reserve(faces.number_of_faces());
  for(std::size_t b = 0; b < faces.number_of_blocks(); ++b)
    faces.for_each_face_in_block(b, [&](std::size_t, const Face_corner* c, std::size_t size, std::size_t) {
      const auto face = add_face(mesh);
      result.faces.push_back(face);
      for(std::size_t k = 0; k < size; ++k) {
        const Face_corner& n = c[k + 1 == size ? 0 : k + 1];
        const halfedge_descriptor h = halfedge_of[c[k].halfedge];
        set_target(h, result.vertices[n.vertex], mesh);
        set_next(h, halfedge_of[n.halfedge], mesh);
        set_face(h, face, mesh);
        set_halfedge(result.vertices[n.vertex], h, mesh);
      }
      set_halfedge(face, halfedge_of[c[0].halfedge], mesh);
    });
  wire_border(mesh, faces.border_halfedges(), [&](Child_index id) { return halfedge_of[id]; });
  result.halfedges = std::move(halfedge_of);
  return result;
}

/*
 * Surface_mesh, resized to the new counts: the record is wired in place,
 * vertex i, halfedge id and face f of the record being the mesh's indices i,
 * id and f, so nothing is looked up and nothing is pushed one by one. Every
 * halfedge of a face is written whole (face, target, next, prev) with its
 * face, the faces in parallel chunks of blocks by `loop`. The halfedge of a
 * vertex is what a sequential pass leaves there: the incoming halfedge of the
 * last face around it in new face order (in one thread written with the
 * faces; in parallel in a pass of its own, beside them), or, on the border,
 * its incoming border halfedge. `also(loop)`, which must write nothing the
 * wiring writes, runs in the loop of the faces, after them.
 */
template <class P, class Faces, class Also>
void wire_surface_mesh(CGAL::Surface_mesh<P>& mesh, const Faces& faces, const Parallel_loop& loop, const Also& also)
{
  using SM = CGAL::Surface_mesh<P>;
  using size_type = typename SM::size_type;
  using V = typename SM::Vertex_index;
  using H = typename SM::Halfedge_index;
  using F = typename SM::Face_index;
  CGAL_precondition(mesh.number_of_halfedges() == 2 * faces.number_of_edges() &&
                    mesh.number_of_faces() == faces.number_of_faces());
  const auto halfedge = [](std::size_t id) { return H(static_cast<size_type>(id)); };
  const auto vertex = [](std::size_t i) { return V(static_cast<size_type>(i)); };

  // the faces and their halfedges; with `vertices` (one thread, in new face
  // order) the halfedges of the vertices too
  const auto wire_faces = [&](const Parallel_loop& faces_loop, auto vertices) {
    faces_loop.for_range(faces.number_of_blocks(), 512, [&](std::size_t first, std::size_t last) {
      for(std::size_t b = first; b < last; ++b)
        faces.for_each_face_in_block(b, [&](std::size_t f, const Face_corner* c, std::size_t size, std::size_t) {
          const F face(static_cast<size_type>(f));
          for(std::size_t k = 0; k < size; ++k) {
            const std::size_t n = k + 1 == size ? 0 : k + 1, p = k == 0 ? size - 1 : k - 1;
            const H h = halfedge(c[k].halfedge);
            mesh.set_face(h, face);
            mesh.set_target(h, vertex(c[n].vertex));
            mesh.set_next_only(h, halfedge(c[n].halfedge));
            mesh.set_prev_only(h, halfedge(c[p].halfedge));
            if constexpr(decltype(vertices)::value)
              mesh.set_halfedge(vertex(c[n].vertex), h);
          }
          mesh.set_halfedge(face, halfedge(c[0].halfedge));
        });
    });
  };
  const auto wire_vertices = [&] {
    for(std::size_t b = 0; b < faces.number_of_blocks(); ++b)
      faces.for_each_face_in_block(b, [&](std::size_t, const Face_corner* c, std::size_t size, std::size_t) {
        for(std::size_t k = 0; k < size; ++k)
          mesh.set_halfedge(vertex(c[k + 1 == size ? 0 : k + 1].vertex), halfedge(c[k].halfedge));
      });
  };
  if(!loop.is_parallel()) {
    wire_faces(loop, std::true_type());
    also(loop);
  } else { // the vertex pass writes only vertices, the faces only halfedges with a face and faces
    const Parallel_loop inner = loop.in_arena();
    loop.invoke(
      [&] {
        wire_faces(inner, std::false_type());
        also(inner);
      },
      wire_vertices);
  }
  wire_border(mesh, faces.border_halfedges(), halfedge);
}

template <class P, class Faces>
void wire_surface_mesh(CGAL::Surface_mesh<P>& mesh, const Faces& faces, const Parallel_loop& loop)
{
  wire_surface_mesh(mesh, faces, loop, [](const Parallel_loop&) {});
}

/*
 * Surface_mesh: the mesh is resized to the new counts and wired in place (see
 * `wire_surface_mesh`); the new points are written after. The mesh is not
 * cleared (that would free and reallocate every array): old vertices keep
 * their indices, and so the values of other vertex property maps; values of
 * other edge, halfedge and face property maps are stale and must be carried
 * explicitly.
 */
template <class P, class VertexPointMap, class Point, class Faces>
New_elements<CGAL::Surface_mesh<P>> rebuild_mesh(CGAL::Surface_mesh<P>& mesh, const VertexPointMap& vpm,
                                                 const std::vector<Point>& points, const Faces& faces)
{
  using SM = CGAL::Surface_mesh<P>;
  using size_type = typename SM::size_type;
  CGAL_precondition(!mesh.has_garbage());
  mesh.resize(static_cast<size_type>(faces.number_of_vertices()), static_cast<size_type>(faces.number_of_edges()),
              static_cast<size_type>(faces.number_of_faces()));
  New_elements<SM> result;
  for(std::size_t i = 0; i < faces.number_of_vertices(); ++i) {
    result.vertices.push_back(typename SM::Vertex_index(static_cast<size_type>(i)));
    put(vpm, result.vertices.back(), points[i]);
  }
  for(std::size_t f = 0; f < faces.number_of_faces(); ++f)
    result.faces.push_back(typename SM::Face_index(static_cast<size_type>(f)));
  wire_surface_mesh(mesh, faces, Parallel_loop(1));
  return result;
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_REFINEMENT_WRITE_FACES_H
