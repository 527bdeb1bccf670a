// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_REBUILD_MESH_H
#define CGAL_SUBDIV_INTERNAL_REBUILD_MESH_H

#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Subdiv/errors.h>

#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/internal/Raw_array.h>
#include <CGAL/Subdiv/internal/parallel.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/// element counts of a mesh; `corners` is the number of face corners, i.e.
/// of halfedges with a face
struct Mesh_counts
{
  std::size_t vertices;
  std::size_t edges;
  std::size_t faces;
  std::size_t corners;
};

/*
 * The new connectivity of one level, as the host knows it: every face is a
 * run of corners, and corner k of a face holds the new vertex it starts at
 * and the id of the new halfedge from corner k to corner k+1. Halfedge ids
 * come in pairs: id 2e and 2e+1 are the two halves of new edge e, so id ^ 1
 * is the opposite. Knowing the edges lets `rebuild_mesh` wire the halfedge
 * structure directly, with no search for opposite halfedges.
 * Each new face also records the ordinal of the old face it lies in (unless
 * the host was asked not to: the fast path without carried data).
 *
 * A host fills it either face by face (`corner`, `close_face`), or, when all
 * new faces have the same size, by position (`resize_uniform`, then
 * `set_corner` and `set_parent`, from any thread, each position once).
 */
class Face_soup
{
public:
  // Indices are stored in 32 bits, like Surface_mesh's own: half the memory
  // traffic of size_t on the hot path.
  using Index = std::uint32_t;
  struct Corner
  {
    Index vertex;
    Index halfedge;
  };

  Face_soup(std::size_t vertices, std::size_t edges) : m_vertex_count(vertices), m_edge_count(edges)
  {
    check_counts(vertices, edges);
  }

  /// throws `Bad_input` if new vertices or halfedges do not fit in an Index
  static void check_counts(std::size_t vertices, std::size_t edges)
  {
    require(2 * edges < (std::size_t(1) << 32) && vertices < (std::size_t(1) << 32),
            "the refined mesh would have more than 2^31 edges");
  }

  void reserve(std::size_t faces, std::size_t corners)
  {
    m_ends.reserve(faces);
    m_parents.reserve(faces);
    m_corners.reserve(corners);
  }

  /// adds corner (vertex, halfedge id to the next corner) to the open face
  void corner(std::size_t vertex, std::size_t halfedge)
  {
    m_corners.push_back(Corner{static_cast<Index>(vertex), static_cast<Index>(halfedge)});
  }

  /// closes the open face
  void close_face(std::size_t parent)
  {
    m_ends.push_back(m_corners.size());
    m_parents.push_back(static_cast<Index>(parent));
    ++m_face_count;
  }

  /// makes room for `faces` faces of `face_size` corners each, to be written
  /// by position; with `parents`, the parent of every face too
  void resize_uniform(std::size_t faces, int face_size, bool parents)
  {
    m_uniform_size = static_cast<std::size_t>(face_size);
    m_face_count = faces;
    m_corners.resize_for_overwrite(faces * m_uniform_size);
    if(parents)
      m_parents.resize_for_overwrite(faces);
  }
  void set_corner(std::size_t corner, std::size_t vertex, std::size_t halfedge)
  {
    m_corners[corner] = Corner{static_cast<Index>(vertex), static_cast<Index>(halfedge)};
  }
  void set_parent(std::size_t face, std::size_t parent)
  {
    if(m_parents.size() != 0)
      m_parents[face] = static_cast<Index>(parent);
  }

  std::size_t number_of_vertices() const { return m_vertex_count; }
  std::size_t number_of_edges() const { return m_edge_count; }
  std::size_t number_of_faces() const { return m_face_count; }
  std::size_t number_of_corners() const { return m_corners.size(); }
  std::size_t face_begin(std::size_t f) const
  {
    return m_uniform_size != 0 ? f * m_uniform_size : (f == 0 ? 0 : m_ends[f - 1]);
  }
  std::size_t face_end(std::size_t f) const { return m_uniform_size != 0 ? (f + 1) * m_uniform_size : m_ends[f]; }
  std::size_t vertex(std::size_t corner) const { return m_corners[corner].vertex; }
  std::size_t halfedge(std::size_t corner) const { return m_corners[corner].halfedge; }
  const Corner* corners() const { return m_corners.data(); }
  bool has_parents() const { return m_parents.size() == m_face_count; }
  std::size_t parent(std::size_t f) const
  {
    CGAL_precondition(has_parents());
    return m_parents[f];
  }

private:
  std::size_t m_vertex_count;
  std::size_t m_edge_count;
  std::size_t m_face_count = 0;
  std::size_t m_uniform_size = 0; // 0: faces of any size, ended by m_ends
  Raw_array<Corner> m_corners;
  Raw_array<std::size_t> m_ends; // one past the last corner of each face
  Raw_array<Index> m_parents;
};

/*
 * The halves of old edge e in the edge splits (`Triangle_quadrisection`,
 * `Quad_split`): new edges 2e (from the source of halfedge(e) to the edge
 * point) and 2e+1 (from the edge point to its target); as halfedge ids, 4e
 * and 4e+2 along halfedge(e), 4e+3 and 4e+1 against it. `id` is the old
 * halfedge's ordinal (2e along halfedge(e), 2e+1 against it).
 */
inline std::size_t first_half(std::size_t id)
{
  return (id & 1) == 0 ? 2 * id : 2 * id + 1;
}
inline std::size_t second_half(std::size_t id)
{
  return (id & 1) == 0 ? 2 * id + 2 : 2 * id - 1;
}

/*
 * What an edge split needs of the old mesh to make the new faces, instead of
 * a `Face_soup` of them (8 bytes per new corner): every old face corner, in
 * face order and around each face from halfedge(f), as the ordinal of its
 * halfedge and of that halfedge's target (8 bytes per old corner, a quarter
 * of the soup of a triangle or quad split), and, when the new mesh is wired
 * from it, the old border halfedges. The host expands it into the new faces
 * (`for_each_new_face`), into a soup or straight into a Surface_mesh
 * (`wire_split`); it is taken before the old connectivity is overwritten.
 */
struct Split_snapshot
{
  using Index = std::uint32_t;
  struct Corner
  {
    Index halfedge;
    Index target;
  };
  struct Border
  {
    Index halfedge;
    Index target;
    Index next;
  };

  std::size_t face_count = 0;
  std::size_t face_size = 0;     // every face has `face_size` corners, or 0: see `first_corner`
  Raw_array<Corner> corners;     // old corners in face order
  Raw_array<Index> first_corner; // face_size 0: face f's corners are [first_corner[f], first_corner[f+1])
  std::vector<Border> border;    // old border halfedges, in ordinal order (if asked for)

  std::size_t begin(std::size_t f) const { return face_size != 0 ? f * face_size : first_corner[f]; }
  std::size_t end(std::size_t f) const { return face_size != 0 ? (f + 1) * face_size : first_corner[f + 1]; }
};

/// adds the border halfedges of `mesh` (`halfedge_count` of them in all) to
/// the snapshot, in one thread (cheap: called only for meshes with a border)
template <class Mesh, class Numbering>
void snapshot_border(const Mesh& mesh, const Numbering& number, std::size_t halfedge_count, Split_snapshot& snapshot)
{
  using Index = Split_snapshot::Index;
  for_each_element_of(
    number, [&] { return halfedges(mesh); }, halfedge_count, Parallel_loop(1),
    [&](auto h) {
      if(is_border(h, mesh))
        snapshot.border.push_back(Split_snapshot::Border{static_cast<Index>(number(h)),
                                                         static_cast<Index>(number(target(h, mesh))),
                                                         static_cast<Index>(number(next(h, mesh)))});
    });
}

/// the soup of an edge split, expanded from the snapshot by the host's
/// `for_each_new_face` (in parallel chunks by old face), with the parents or not
template <class Host, class Loop>
Face_soup split_soup(const Host& host, const Split_snapshot& snapshot, const Loop& loop, bool parents)
{
  constexpr int N = Host::new_face_size;
  Face_soup soup(host.number_of_new_vertices(), host.number_of_new_edges());
  soup.resize_uniform(host.number_of_new_faces(), N, parents);
  loop.for_range(snapshot.face_count, 1024, [&](std::size_t first, std::size_t last) {
    for(std::size_t f = first; f < last; ++f)
      host.for_each_new_face(snapshot, f, [&](std::size_t face, const Face_soup::Corner* c) {
        for(int k = 0; k < N; ++k)
          soup.set_corner(N * face + static_cast<std::size_t>(k), c[k].vertex, c[k].halfedge);
        soup.set_parent(face, f);
      });
  });
  return soup;
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

/*
 * Replaces the mesh by the new level through the low-level functions of
 * `MutableFaceGraph`: vertices, edges and faces are created in the order of
 * the soup (new vertex i gets points[i]), then every halfedge is wired.
 * Returns the new vertex and face descriptors in soup order if asked.
 */
template <class Mesh, class VertexPointMap, class Point>
void rebuild_mesh(Mesh& mesh, const VertexPointMap& vpm, const std::vector<Point>& points, const Face_soup& soup,
                  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>* new_vertices = nullptr,
                  std::vector<typename boost::graph_traits<Mesh>::face_descriptor>* new_faces = nullptr)
{
  using GT = boost::graph_traits<Mesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;

  clear_keeping_properties(mesh);
  CGAL::reserve(mesh, static_cast<typename GT::vertices_size_type>(soup.number_of_vertices()),
                static_cast<typename GT::edges_size_type>(soup.number_of_edges()),
                static_cast<typename GT::faces_size_type>(soup.number_of_faces()));

  std::vector<vertex_descriptor> vertex_of(soup.number_of_vertices());
  for(std::size_t i = 0; i < vertex_of.size(); ++i) {
    vertex_of[i] = add_vertex(mesh);
    put(vpm, vertex_of[i], points[i]);
  }
  std::vector<halfedge_descriptor> halfedge_of(2 * soup.number_of_edges());
  for(std::size_t e = 0; e < soup.number_of_edges(); ++e) {
    const halfedge_descriptor h = halfedge(add_edge(mesh), mesh);
    halfedge_of[2 * e] = h;
    halfedge_of[2 * e + 1] = opposite(h, mesh);
  }
  // halfedges of faces; a halfedge also names the target of its opposite
  std::vector<char> has_face(halfedge_of.size(), 0);
  std::vector<face_descriptor> face_of(soup.number_of_faces());
  for(std::size_t f = 0; f < soup.number_of_faces(); ++f) {
    const face_descriptor face = add_face(mesh);
    face_of[f] = face;
    const std::size_t begin = soup.face_begin(f), end = soup.face_end(f);
    for(std::size_t k = begin; k < end; ++k) {
      const std::size_t next_corner = (k + 1 == end) ? begin : k + 1;
      const std::size_t id = soup.halfedge(k);
      const halfedge_descriptor h = halfedge_of[id];
      const vertex_descriptor to = vertex_of[soup.vertex(next_corner)];
      set_target(h, to, mesh);
      set_target(halfedge_of[id ^ 1], vertex_of[soup.vertex(k)], mesh);
      set_next(h, halfedge_of[soup.halfedge(next_corner)], mesh);
      set_face(h, face, mesh);
      set_halfedge(to, h, mesh);
      has_face[id] = 1;
    }
    set_halfedge(face, halfedge_of[soup.halfedge(begin)], mesh);
  }
  // border halfedges: no face; the next one starts where this one ends
  for(std::size_t id = 0; id < halfedge_of.size(); ++id)
    if(!has_face[id])
      set_face(halfedge_of[id], GT::null_face(), mesh);
  for(std::size_t id = 0; id < halfedge_of.size(); ++id) {
    if(has_face[id])
      continue;
    const halfedge_descriptor border = halfedge_of[id];
    // rotate around target(border), from the face halfedge leaving it, to the border halfedge leaving it
    halfedge_descriptor around = halfedge_of[id ^ 1];
    while(!is_border(around, mesh))
      around = opposite(prev(around, mesh), mesh);
    set_next(border, around, mesh);
    set_halfedge(target(border, mesh), border, mesh); // border vertices keep a border halfedge
  }

  if(new_vertices)
    new_vertices->swap(vertex_of);
  if(new_faces)
    new_faces->swap(face_of);
}

template <class P>
void set_descriptors(const CGAL::Surface_mesh<P>&, const Face_soup& soup,
                     std::vector<typename CGAL::Surface_mesh<P>::Vertex_index>* new_vertices,
                     std::vector<typename CGAL::Surface_mesh<P>::Face_index>* new_faces)
{
  using SM = CGAL::Surface_mesh<P>;
  if(new_vertices) {
    new_vertices->clear();
    for(std::size_t i = 0; i < soup.number_of_vertices(); ++i)
      new_vertices->push_back(typename SM::Vertex_index(static_cast<typename SM::size_type>(i)));
  }
  if(new_faces) {
    new_faces->clear();
    for(std::size_t f = 0; f < soup.number_of_faces(); ++f)
      new_faces->push_back(typename SM::Face_index(static_cast<typename SM::size_type>(f)));
  }
}

/*
 * Surface_mesh: the halfedges, faces and vertices of a mesh already resized
 * to the soup's counts are wired in place: vertex i, halfedge id and face f of
 * the soup are the mesh's indices i, id and f, so nothing is looked up and no
 * element is pushed one by one.
 *
 * Every halfedge belongs to one face, so the faces are wired in parallel
 * chunks by `loop`. The halfedge of a vertex is what the sequential loop
 * leaves there: the incoming halfedge of the last face (in soup order) around
 * the vertex, or its incoming border halfedge; it is written in a pass of its
 * own, in soup order.
 */
template <class P>
void wire_surface_mesh(CGAL::Surface_mesh<P>& mesh, const Face_soup& soup, const Parallel_loop& loop)
{
  using SM = CGAL::Surface_mesh<P>;
  using size_type = typename SM::size_type;
  using V = typename SM::Vertex_index;
  using H = typename SM::Halfedge_index;
  using F = typename SM::Face_index;

  const std::size_t face_count = soup.number_of_faces();
  const std::size_t halfedge_count = 2 * soup.number_of_edges();
  CGAL_precondition(mesh.number_of_halfedges() == halfedge_count && mesh.number_of_faces() == face_count);
  const bool closed = soup.number_of_corners() == halfedge_count; // every halfedge has a face
  std::vector<char> has_face(closed ? 0 : halfedge_count, 0);
  const Face_soup::Corner* corners = soup.corners();

  loop.for_range(face_count, 1024, [&](std::size_t first, std::size_t last) {
    for(std::size_t f = first; f < last; ++f) {
      const F face(static_cast<size_type>(f));
      const std::size_t begin = soup.face_begin(f), end = soup.face_end(f);
      for(std::size_t k = begin; k < end; ++k) {
        const std::size_t next_corner = (k + 1 == end) ? begin : k + 1;
        const H h(static_cast<size_type>(corners[k].halfedge));
        mesh.set_target(h, V(static_cast<size_type>(corners[next_corner].vertex)));
        mesh.set_next(h, H(static_cast<size_type>(corners[next_corner].halfedge)));
        mesh.set_face(h, face);
        if(!closed)
          has_face[corners[k].halfedge] = 1;
      }
      mesh.set_halfedge(face, H(static_cast<size_type>(corners[begin].halfedge)));
    }
  });
  for(std::size_t f = 0; f < face_count; ++f) {
    const std::size_t begin = soup.face_begin(f), end = soup.face_end(f);
    for(std::size_t k = begin; k < end; ++k) {
      const std::size_t next_corner = (k + 1 == end) ? begin : k + 1;
      mesh.set_halfedge(V(static_cast<size_type>(corners[next_corner].vertex)),
                        H(static_cast<size_type>(corners[k].halfedge)));
    }
  }
  if(closed)
    return;
  // border halfedges: no face; they end where their opposite starts, and the
  // next one starts where this one ends
  for(std::size_t id = 0; id < halfedge_count; ++id)
    if(!has_face[id]) {
      const H border(static_cast<size_type>(id));
      mesh.set_face(border, SM::null_face());
      mesh.set_target(border, mesh.target(mesh.prev(H(static_cast<size_type>(id ^ 1)))));
    }
  for(std::size_t id = 0; id < halfedge_count; ++id) {
    if(has_face[id])
      continue;
    const H border(static_cast<size_type>(id));
    // rotate around target(border), from the face halfedge leaving it, to the border halfedge leaving it
    H around(static_cast<size_type>(id ^ 1));
    while(!mesh.is_border(around))
      around = mesh.opposite(mesh.prev(around));
    mesh.set_next(border, around);
    mesh.set_halfedge(mesh.target(border), border);
  }
}

/*
 * Surface_mesh, an edge split: the mesh already resized to the new counts is
 * wired straight from the snapshot of the old faces, the new faces made by
 * the host's `for_each_new_face`, with the result `wire_surface_mesh` gets
 * from the soup of the same faces (every link the same): faces in parallel
 * chunks by old face, each writing its own halfedges whole (face, target,
 * next, prev); the halfedge of each vertex in a pass of its own, in new face
 * order (the incoming halfedge of the last face around it), then the halves
 * of the old border halfedges (border vertices keep their incoming border
 * halfedge). In one thread the vertices are wired with the faces, in one
 * pass; with a parallel `loop` their pass runs beside the faces.
 */
template <class P, class Host, class Also>
void wire_split(CGAL::Surface_mesh<P>& mesh, const Host& host, const Split_snapshot& snapshot,
                std::size_t old_vertex_count, const Parallel_loop& loop, const Also& also)
{
  using SM = CGAL::Surface_mesh<P>;
  using size_type = typename SM::size_type;
  using V = typename SM::Vertex_index;
  using H = typename SM::Halfedge_index;
  using F = typename SM::Face_index;
  using Corner = Face_soup::Corner;
  constexpr int N = Host::new_face_size;
  CGAL_precondition(mesh.number_of_halfedges() == 2 * host.number_of_new_edges() &&
                    mesh.number_of_faces() == host.number_of_new_faces());

  // the halfedges of the new faces and the faces; with `vertices` (in one
  // thread, in new face order) the halfedges of the vertices too
  const auto wire_faces = [&](const Parallel_loop& faces_loop, auto vertices) {
    faces_loop.for_range(snapshot.face_count, 512, [&](std::size_t first, std::size_t last) {
      for(std::size_t f = first; f < last; ++f)
        host.for_each_new_face(snapshot, f, [&](std::size_t new_face, const Corner* c) {
          const F face(static_cast<size_type>(new_face));
          for(int k = 0; k < N; ++k) {
            const int n = (k + 1 == N) ? 0 : k + 1, p = (k == 0) ? N - 1 : k - 1;
            const H h(static_cast<size_type>(c[k].halfedge));
            mesh.set_face(h, face);
            mesh.set_target(h, V(static_cast<size_type>(c[n].vertex)));
            mesh.set_next_only(h, H(static_cast<size_type>(c[n].halfedge)));
            mesh.set_prev_only(h, H(static_cast<size_type>(c[p].halfedge)));
            if constexpr(decltype(vertices)::value)
              mesh.set_halfedge(V(static_cast<size_type>(c[n].vertex)), h);
          }
          mesh.set_halfedge(face, H(static_cast<size_type>(c[0].halfedge)));
        });
    });
  };
  const auto wire_vertices = [&] {
    for(std::size_t f = 0; f < snapshot.face_count; ++f)
      host.for_each_new_face(snapshot, f, [&](std::size_t, const Corner* c) {
        for(int k = 0; k < N; ++k)
          mesh.set_halfedge(V(static_cast<size_type>(c[(k + 1 == N) ? 0 : k + 1].vertex)),
                            H(static_cast<size_type>(c[k].halfedge)));
      });
  };
  const auto wire_border = [&] {
    // the halves of an old border halfedge b: the first from source(b) to
    // the edge point, the second from there to target(b), then on to the
    // first half of the next border halfedge
    for(const Split_snapshot::Border& b : snapshot.border) {
      const H first(static_cast<size_type>(first_half(b.halfedge)));
      const H second(static_cast<size_type>(second_half(b.halfedge)));
      const V edge_point(static_cast<size_type>(old_vertex_count + (b.halfedge >> 1)));
      mesh.set_face(first, SM::null_face());
      mesh.set_face(second, SM::null_face());
      mesh.set_target(first, edge_point);
      mesh.set_target(second, V(static_cast<size_type>(b.target)));
      mesh.set_next(first, second);
      mesh.set_next(second, H(static_cast<size_type>(first_half(b.next))));
      mesh.set_halfedge(edge_point, first);
      mesh.set_halfedge(V(static_cast<size_type>(b.target)), second);
    }
  };
  if(!loop.is_parallel()) {
    wire_faces(loop, std::true_type());
    wire_border();
    also(loop);
    return;
  }
  // the vertex pass writes only vertices and border halfedges, the faces
  // only halfedges with a face and faces: they run side by side
  const Parallel_loop inner = loop.in_arena();
  loop.invoke(
    [&] {
      wire_faces(inner, std::false_type());
      also(inner);
    },
    [&] {
      wire_vertices();
      wire_border();
    });
}

/// the same; `also(loop)`, which must write nothing the wiring writes, runs
/// in the loop of the faces, after them
template <class P, class Host>
void wire_split(CGAL::Surface_mesh<P>& mesh, const Host& host, const Split_snapshot& snapshot,
                std::size_t old_vertex_count, const Parallel_loop& loop)
{
  wire_split(mesh, host, snapshot, old_vertex_count, loop, [](const Parallel_loop&) {});
}

// Surface_mesh: the mesh is resized to the new counts and wired in place (see
// `wire_surface_mesh`). The mesh is not cleared (that would free and
// reallocate every array): old vertices keep their indices, and so the values
// of other vertex property maps; values of other edge, halfedge and face
// property maps are stale and must be carried explicitly (see `Vertex_data`
// and face inheritance).
template <class P, class VertexPointMap, class Point>
void rebuild_mesh(CGAL::Surface_mesh<P>& mesh, const VertexPointMap& vpm, const std::vector<Point>& points,
                  const Face_soup& soup,
                  std::vector<typename CGAL::Surface_mesh<P>::Vertex_index>* new_vertices = nullptr,
                  std::vector<typename CGAL::Surface_mesh<P>::Face_index>* new_faces = nullptr)
{
  using SM = CGAL::Surface_mesh<P>;
  using V = typename SM::Vertex_index;

  CGAL_precondition(!mesh.has_garbage());
  mesh.resize(static_cast<typename SM::size_type>(soup.number_of_vertices()),
              static_cast<typename SM::size_type>(soup.number_of_edges()),
              static_cast<typename SM::size_type>(soup.number_of_faces()));
  for(std::size_t i = 0; i < soup.number_of_vertices(); ++i)
    put(vpm, V(static_cast<typename SM::size_type>(i)), points[i]);
  wire_surface_mesh(mesh, soup, Parallel_loop(1));
  set_descriptors(mesh, soup, new_vertices, new_faces);
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_REBUILD_MESH_H
