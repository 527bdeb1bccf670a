// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_MESH_TRAITS_H
#define CGAL_SUBDIV_INTERNAL_MESH_TRAITS_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

namespace CGAL {
namespace Subdiv {
namespace internal {

template <class Mesh>
using Mesh_point =
  typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type;

/// the number type of the points of a mesh (the default FT of its masks)
template <class Mesh>
using Mesh_FT = typename CGAL::Kernel_traits<Mesh_point<Mesh>>::Kernel::FT;

// Around a border vertex: the border halfedge that ends at v and the one that
// starts at v (their other ends are v's two neighbours along the border).
template <class Mesh>
std::pair<typename boost::graph_traits<Mesh>::halfedge_descriptor,
          typename boost::graph_traits<Mesh>::halfedge_descriptor>
border_halfedges_at(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& mesh)
{
  for(auto h : CGAL::halfedges_around_target(v, mesh))
    if(CGAL::is_border(h, mesh))
      return {h, next(h, mesh)};
  return {boost::graph_traits<Mesh>::null_halfedge(), boost::graph_traits<Mesh>::null_halfedge()};
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_MESH_TRAITS_H
