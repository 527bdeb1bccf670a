// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_LOCAL_PATCH_H
#define CGAL_SUBDIV_LIMIT_LOCAL_PATCH_H

/// \file local_patch.h
/// The neighbourhood of one face copied out of any FaceGraph into a small
/// Surface_mesh (the face and every face sharing a vertex with it), which
/// the limit evaluator refines locally.

#include <CGAL/Subdiv/errors.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/// a face of a small mesh, with the halfedge whose target is its corner 0
template <class Point>
struct Local_patch
{
  using Mesh = CGAL::Surface_mesh<Point>;
  Mesh mesh;
  typename Mesh::Halfedge_index h0;
};

/*
 * The fan of every (vertex, face) of faces given by their vertices: two
 * faces at a vertex are in one fan if a chain of faces at it joins them,
 * each sharing an edge at the vertex with the next. A vertex of a face's
 * 1-ring that two corners reach through faces that share no edge there
 * (a pinch) is in two fans, and the patch gets a copy of it for each, so
 * that the patch is a disk: the refinement of the face's neighbourhood
 * reads no connectivity at such a vertex, only its point.
 */
template <class Vertex>
std::map<std::pair<Vertex, std::size_t>, std::size_t> fans_of(const std::vector<std::vector<Vertex>>& face_vertices)
{
  struct Use
  {
    std::size_t face;
    Vertex previous, next;
  };
  std::map<Vertex, std::vector<Use>> uses;
  for(std::size_t a = 0; a < face_vertices.size(); ++a) {
    const auto& vs = face_vertices[a];
    for(std::size_t k = 0; k < vs.size(); ++k)
      uses[vs[k]].push_back({a, vs[(k + vs.size() - 1) % vs.size()], vs[(k + 1) % vs.size()]});
  }
  std::map<std::pair<Vertex, std::size_t>, std::size_t> fans;
  for(const auto& [w, at_w] : uses) {
    std::vector<std::size_t> fan(at_w.size());
    for(std::size_t i = 0; i < fan.size(); ++i)
      fan[i] = i;
    // joins fans until no two faces that share an edge at w are in different ones
    for(bool joined = true; joined;) {
      joined = false;
      for(std::size_t i = 0; i < at_w.size(); ++i)
        for(std::size_t j = 0; j < at_w.size(); ++j)
          if(fan[i] != fan[j] && (at_w[i].next == at_w[j].previous || at_w[i].previous == at_w[j].next)) {
            const std::size_t from = std::max(fan[i], fan[j]), to = std::min(fan[i], fan[j]);
            for(std::size_t& k : fan)
              if(k == from)
                k = to;
            joined = true;
          }
    }
    for(std::size_t i = 0; i < at_w.size(); ++i)
      fans[{w, at_w[i].face}] = fan[i];
  }
  return fans;
}

/*
 * The patch of face f of `source` (a copy of f and of every face that
 * shares a vertex with it, f first), its corner 0 at the target of
 * halfedge(f, source). Outside f's corners the patch has a border of its
 * own: the elements that a refinement makes there are never read.
 */
template <class Point, class Source>
Local_patch<Point> local_patch(const Source& mesh, typename boost::graph_traits<Source>::halfedge_descriptor h0,
                               std::vector<typename boost::graph_traits<Source>::vertex_descriptor>* sources = nullptr)
{
  using Patch_mesh = typename Local_patch<Point>::Mesh;
  using Source_face = typename boost::graph_traits<Source>::face_descriptor;
  using Source_vertex = typename boost::graph_traits<Source>::vertex_descriptor;
  const auto vpm = get(CGAL::vertex_point, mesh);
  const Source_face f = face(h0, mesh);
  std::vector<Source_face> ring{f};
  for(const auto corner : CGAL::vertices_around_face(h0, mesh))
    for(const Source_face g : CGAL::faces_around_target(halfedge(corner, mesh), mesh))
      if(g != boost::graph_traits<Source>::null_face() && std::find(ring.begin(), ring.end(), g) == ring.end())
        ring.push_back(g);
  // each ring face's vertices, and at each vertex its fan: the ring faces
  // around it joined through the edges at it that they share
  std::vector<std::vector<Source_vertex>> face_vertices;
  for(const Source_face g : ring) {
    face_vertices.emplace_back();
    for(const Source_vertex w : CGAL::vertices_around_face(halfedge(g, mesh), mesh))
      face_vertices.back().push_back(w);
  }
  const auto fans = fans_of(face_vertices);
  Local_patch<Point> patch;
  std::map<std::pair<Source_vertex, std::size_t>, typename Patch_mesh::Vertex_index> copy;
  std::vector<typename Patch_mesh::Vertex_index> corners;
  for(std::size_t a = 0; a < ring.size(); ++a) {
    corners.clear();
    for(const Source_vertex w : face_vertices[a]) {
      auto [it, fresh] = copy.emplace(std::make_pair(w, fans.at({w, a})), typename Patch_mesh::Vertex_index());
      if(fresh) {
        it->second = patch.mesh.add_vertex(get(vpm, w));
        if(sources != nullptr)
          sources->push_back(w);
      }
      corners.push_back(it->second);
    }
    if(patch.mesh.add_face(corners) == Patch_mesh::null_face())
      internal::refuse(internal::Message()
                       << "Limit_surface: the faces around a face do not make a disk (a non-manifold neighbourhood)");
  }
  const auto copy_of = [&](Source_vertex w) { return copy.at({w, fans.at({w, 0})}); };
  [[maybe_unused]] const auto [h, found] =
    CGAL::halfedge(copy_of(source(h0, mesh)), copy_of(target(h0, mesh)), patch.mesh);
  CGAL_assertion(found && patch.mesh.face(h) == typename Patch_mesh::Face_index(0));
  patch.h0 = h;
  // the domain of the face's children (Face_origin) starts at the target of its halfedge
  patch.mesh.set_halfedge(patch.mesh.face(h), h);
  return patch;
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_LOCAL_PATCH_H
