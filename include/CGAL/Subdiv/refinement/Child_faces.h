// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_REFINEMENT_CHILD_FACES_H
#define CGAL_SUBDIV_REFINEMENT_CHILD_FACES_H

/// \file Child_faces.h
/// The record of one level's new topology that every refinement host makes,
/// and that every writer reads: the new faces as runs of corners, each with
/// its parent face; the new border halfedges. (The origin of every new vertex
/// is the host's `origin(j)`.)

#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/Raw_array.h>

#include <cstddef>
#include <cstdint>
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

// Indices are stored in 32 bits, like Surface_mesh's own: half the memory
// traffic of size_t on the hot paths.
using Child_index = std::uint32_t;

/*
 * A corner of a new face: the new vertex it is at and the id of the new
 * halfedge from it to the next corner. Halfedge ids come in pairs: 2e and
 * 2e+1 are the two halves of new edge e, so id ^ 1 is the opposite. Knowing
 * the edges lets the writers wire the halfedge structure directly, with no
 * search for opposite halfedges.
 */
struct Face_corner
{
  Child_index vertex;
  Child_index halfedge;
};

/// throws `Bad_input` if the new vertices or halfedges do not fit in a `Child_index`
inline void check_child_counts(std::size_t vertices, std::size_t edges)
{
  require(2 * edges < (std::size_t(1) << 32) && vertices < (std::size_t(1) << 32),
          "the refined mesh would have more than 2^31 edges");
}

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
 * Child faces: the concept of the record (two models below). The faces come
 * in blocks, in new face order:
 *   number_of_vertices(), number_of_edges(), number_of_faces()
 *   number_of_blocks()
 *   for_each_face_in_block(b, emit): emit(new face, const Face_corner* corners,
 *     std::size_t size, std::size_t parent) for the faces of block b, in order;
 *     blocks may be read from several threads
 *   border_halfedges(): the ids of the new halfedges without a face
 */

/*
 * Child faces listed one by one (the dual and sqrt3 splits): a block is a
 * face. A host adds the corners of a face (`corner`), then closes it with its
 * parent (`close_face`).
 */
class Face_soup
{
public:
  Face_soup(std::size_t vertices, std::size_t edges) : m_vertex_count(vertices), m_edge_count(edges)
  {
    check_child_counts(vertices, edges);
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
    m_corners.push_back(Face_corner{static_cast<Child_index>(vertex), static_cast<Child_index>(halfedge)});
  }

  /// closes the open face
  void close_face(std::size_t parent)
  {
    m_ends.push_back(m_corners.size());
    m_parents.push_back(static_cast<Child_index>(parent));
  }

  std::size_t number_of_vertices() const { return m_vertex_count; }
  std::size_t number_of_edges() const { return m_edge_count; }
  std::size_t number_of_faces() const { return m_ends.size(); }
  std::size_t number_of_blocks() const { return m_ends.size(); }

  template <class Emit>
  void for_each_face_in_block(std::size_t f, const Emit& emit) const
  {
    const std::size_t begin = f == 0 ? 0 : m_ends[f - 1];
    emit(f, m_corners.data() + begin, m_ends[f] - begin, static_cast<std::size_t>(m_parents[f]));
  }

  std::vector<Child_index> border_halfedges() const
  {
    std::vector<Child_index> border;
    if(m_corners.size() == 2 * m_edge_count) // every halfedge has a face
      return border;
    std::vector<char> has_face(2 * m_edge_count, 0);
    for(const Face_corner& c : m_corners)
      has_face[c.halfedge] = 1;
    for(std::size_t id = 0; id < has_face.size(); ++id)
      if(!has_face[id])
        border.push_back(static_cast<Child_index>(id));
    return border;
  }

private:
  std::size_t m_vertex_count;
  std::size_t m_edge_count;
  Raw_array<Face_corner> m_corners;
  Raw_array<std::size_t> m_ends; // one past the last corner of each face
  Raw_array<Child_index> m_parents;
};

/*
 * What an edge split needs of the old mesh to make its new faces (8 bytes
 * per old corner, a quarter of the corners of the new faces): every old face
 * corner, in face order and around each face from halfedge(f), as the
 * ordinal of its halfedge and of that halfedge's target; and the old border
 * halfedges. Taken before the old connectivity is overwritten.
 */
struct Split_snapshot
{
  struct Corner
  {
    Child_index halfedge;
    Child_index target;
  };

  std::size_t face_count = 0;
  std::size_t face_size = 0;           // every face has `face_size` corners, or 0: see `first_corner`
  Raw_array<Corner> corners;           // old corners in face order
  Raw_array<Child_index> first_corner; // face_size 0: face f's corners are [first_corner[f], first_corner[f+1])
  std::vector<Child_index> border;     // old border halfedges, by ordinal

  std::size_t begin(std::size_t f) const { return face_size != 0 ? f * face_size : first_corner[f]; }
  std::size_t end(std::size_t f) const { return face_size != 0 ? (f + 1) * face_size : first_corner[f + 1]; }
};

/// adds the border halfedges of `mesh` (`halfedge_count` of them in all) to
/// the snapshot, in one thread (cheap: called only for meshes with a border)
template <class Mesh, class Numbering>
void snapshot_border(const Mesh& mesh, const Numbering& number, std::size_t halfedge_count, Split_snapshot& snapshot)
{
  for(std::size_t i = 0; i < halfedge_count; ++i) {
    const auto h = number.halfedge(i);
    if(is_border(h, mesh))
      snapshot.border.push_back(static_cast<Child_index>(i));
  }
}

/*
 * Child faces of an edge split, made on the fly from the snapshot by the
 * host's `for_each_new_face(snapshot, old face, emit)`: a block is an old
 * face, and its new faces have it as their parent. The new border halfedges
 * are the halves of the old ones.
 */
template <class Host>
class Split_faces
{
public:
  Split_faces(const Host& host, Split_snapshot snapshot) : m_host(&host), m_snapshot(std::move(snapshot)) {}

  std::size_t number_of_vertices() const { return m_host->number_of_new_vertices(); }
  std::size_t number_of_edges() const { return m_host->number_of_new_edges(); }
  std::size_t number_of_faces() const { return m_host->number_of_new_faces(); }
  std::size_t number_of_blocks() const { return m_snapshot.face_count; }

  template <class Emit>
  void for_each_face_in_block(std::size_t parent, const Emit& emit) const
  {
    m_host->for_each_new_face(m_snapshot, parent, [&](std::size_t face, const Face_corner* corners) {
      emit(face, corners, static_cast<std::size_t>(Host::new_face_size), parent);
    });
  }

  std::vector<Child_index> border_halfedges() const
  {
    std::vector<Child_index> border;
    border.reserve(2 * m_snapshot.border.size());
    for(const Child_index b : m_snapshot.border) {
      border.push_back(static_cast<Child_index>(first_half(b)));
      border.push_back(static_cast<Child_index>(second_half(b)));
    }
    return border;
  }

private:
  const Host* m_host;
  Split_snapshot m_snapshot;
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_REFINEMENT_CHILD_FACES_H
