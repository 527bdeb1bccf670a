// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_ISOLATED_VERTICES_H
#define CGAL_SUBDIV_INTERNAL_ISOLATED_VERTICES_H

/// \file isolated_vertices.h
/// Vertices in no face (`Isolated_vertices`): set aside before a refinement,
/// put back after it. The hosts refine faces and the vertices around them;
/// a vertex in no face has no rule, and its limit is itself.

#include <CGAL/Subdiv/errors.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <boost/property_map/property_map.hpp>

#include <string>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

template <class VertexPointMap>
using Isolated_points = std::vector<typename boost::property_traits<VertexPointMap>::value_type>;

template <class Mesh>
void collect_removed(Mesh&)
{}

template <class Point>
void collect_removed(CGAL::Surface_mesh<Point>& mesh)
{
  mesh.collect_garbage();
}

/*
 * Removes the vertices of `mesh` that belong to no face and returns their
 * points. Data carried through the levels would be renumbered under it (a
 * `Surface_mesh` renumbers when it collects the removed vertices), so
 * `carried` and an isolated vertex are refused, before anything changes.
 */
template <class Mesh, class VertexPointMap>
Isolated_points<VertexPointMap> remove_isolated_vertices(Mesh& mesh, const VertexPointMap& vpm,
                                                         const std::string& scheme, bool carried)
{
  using GT = boost::graph_traits<Mesh>;
  std::vector<typename GT::vertex_descriptor> isolated;
  for(auto v : vertices(mesh))
    if(halfedge(v, mesh) == GT::null_halfedge())
      isolated.push_back(v);
  Isolated_points<VertexPointMap> points;
  if(isolated.empty())
    return points;
  require(!carried, scheme + ": the mesh has " + std::to_string(isolated.size()) +
                      " isolated vertices, and isolated_vertices(keep or drop) cannot be combined with "
                      "carried_data yet; remove them first");
  for(auto v : isolated) {
    points.push_back(get(vpm, v));
    CGAL::remove_vertex(v, mesh);
  }
  collect_removed(mesh);
  return points;
}

// appends one vertex per point, in no face
template <class Mesh, class VertexPointMap>
void add_isolated_vertices(Mesh& mesh, const VertexPointMap& vpm, const Isolated_points<VertexPointMap>& points)
{
  for(const auto& p : points)
    put(vpm, add_vertex(mesh), p);
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_ISOLATED_VERTICES_H
