// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_NEIGHBOURHOOD_WALK_H
#define CGAL_SUBDIV_ANALYSIS_NEIGHBOURHOOD_WALK_H

/// \file Neighbourhood_walk.h
/// The canonical numbering ("labels") of the vertices around a centre, on
/// any FaceGraph: the analysis writes its matrices and masks over these
/// labels, and the limit reads a vertex's neighbourhood in a mesh with the
/// same walk, so the two cannot disagree.

#include <CGAL/Subdiv/internal/Mesh_numbering.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * The labels of the vertices within `rings` rings of a centre, the same for
 * every neighbourhood with the same connectivity:
 * - ring 0: the centre, source(start) (vertex centre), or the corners of
 *   face(start) from source(start) along the face (face centre);
 * - then breadth first: a vertex v is read by walking counter-clockwise
 *   around it, from the halfedge by which it was reached, over its faces,
 *   each face's vertices listed in face order after v; every vertex not yet
 *   labelled gets the next label and ring(v) + 1.
 * For a vertex centre label 1 is target(start): for Loop ring 1 is v_0, v_1,
 * ..., v_{n-1} counter-clockwise; for Catmull-Clark e_0, f_0, e_1, f_1, ...
 *
 * The walk also keeps a transcript of what it saw: per walked vertex and per
 * halfedge around it, -1 for a border halfedge, or -(10 + face size)
 * followed by the labels of the face's other vertices, and -2 at the end of
 * the vertex. Two neighbourhoods with the same transcript have the same
 * labelled connectivity (faces around every vertex of ring < `rings`, which
 * of those vertices are on the border).
 */
template <class Mesh>
class Neighbourhood_walk
{
public:
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;

  explicit Neighbourhood_walk(const Mesh& mesh) : m_mesh(mesh), m_number(mesh), m_label(num_vertices(mesh), -1) {}

  /// reads the neighbourhood; false (and a partial result) once more than
  /// `max_labels` vertices are labelled
  bool read(halfedge_descriptor start, bool face_centred, int rings,
            std::size_t max_labels = (std::numeric_limits<std::size_t>::max)())
  {
    clear();
    std::vector<halfedge_descriptor> entry; // by label: the halfedge leaving the vertex the walk starts at
    const auto add = [&](vertex_descriptor v, int ring, halfedge_descriptor out) {
      m_label[m_number(v)] = static_cast<int>(vertices.size());
      vertices.push_back(v);
      ring_of_label.push_back(ring);
      entry.push_back(out);
    };
    if(face_centred) {
      halfedge_descriptor h = start;
      do {
        add(source(h, m_mesh), 0, h);
        h = next(h, m_mesh);
      } while(h != start);
    } else {
      add(source(start, m_mesh), 0, start);
    }
    for(std::size_t i = 0; i < vertices.size(); ++i) {
      if(ring_of_label[i] >= rings)
        continue;
      const halfedge_descriptor first = entry[i];
      halfedge_descriptor h = first;
      do {
        if(CGAL::is_border(h, m_mesh)) {
          transcript.push_back(-1);
        } else {
          transcript.push_back(-(10 + face_size(h)));
          // the vertices of face(h) after source(h), in face order
          for(halfedge_descriptor g = h; target(g, m_mesh) != source(h, m_mesh); g = next(g, m_mesh)) {
            const vertex_descriptor u = target(g, m_mesh);
            if(label(u) < 0) {
              if(vertices.size() >= max_labels)
                return false;
              add(u, ring_of_label[i] + 1, next(g, m_mesh));
            }
            transcript.push_back(label(u));
          }
        }
        h = opposite(prev(h, m_mesh), m_mesh); // counter-clockwise around the vertex
      } while(h != first);
      transcript.push_back(-2);
    }
    return true;
  }

  /// the label of v in the last read, -1 if it has none
  int label(vertex_descriptor v) const { return m_label[m_number(v)]; }
  std::size_t size() const { return vertices.size(); }
  /// the ordinals of the mesh's vertices (iteration order)
  const Mesh_numbering<Mesh>& numbering() const { return m_number; }

  std::vector<vertex_descriptor> vertices; ///< by label
  std::vector<int> ring_of_label;          ///< by label
  std::vector<int> transcript;

private:
  int face_size(halfedge_descriptor h) const
  {
    int size = 0;
    halfedge_descriptor g = h;
    do {
      ++size;
      g = next(g, m_mesh);
    } while(g != h);
    return size;
  }

  // forgets the labels of the last read (a walk is reused vertex after vertex)
  void clear()
  {
    for(vertex_descriptor v : vertices)
      m_label[m_number(v)] = -1;
    vertices.clear();
    ring_of_label.clear();
    transcript.clear();
  }

  const Mesh& m_mesh;
  Mesh_numbering<Mesh> m_number;
  std::vector<int> m_label; // by vertex ordinal
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_NEIGHBOURHOOD_WALK_H
