// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_VERTEX_ORIGIN_H
#define CGAL_SUBDIV_HOSTS_VERTEX_ORIGIN_H

#include <cstddef>

namespace CGAL {
namespace Subdiv {

/// what a new vertex of a refinement level came from
enum class Origin_kind {
  vertex, ///< an old vertex (its vertex point)
  edge,   ///< an old edge (its edge point)
  face,   ///< an old face (its face point)
  corner  ///< a corner of an old face, i.e. a halfedge with a face (dual schemes)
};

/// the element a new vertex came from: its kind, and its ordinal among the
/// old elements of that kind in the mesh's iteration order
struct Vertex_origin
{
  Origin_kind kind;
  std::size_t index;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_HOSTS_VERTEX_ORIGIN_H
