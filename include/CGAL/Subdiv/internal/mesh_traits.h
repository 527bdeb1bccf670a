// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_MESH_TRAITS_H
#define CGAL_SUBDIV_INTERNAL_MESH_TRAITS_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <type_traits>

namespace CGAL {
namespace Subdiv {
namespace internal {

template <class Mesh>
using Mesh_point =
  typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type;

/// the number type of the points of a mesh (the default FT of its masks)
template <class Mesh>
using Mesh_FT = typename CGAL::Kernel_traits<Mesh_point<Mesh>>::Kernel::FT;

/// a weight (or parameter) of one number type in another: itself when the
/// types agree, converted exactly when `To` can hold it, otherwise the
/// nearest double
template <class To, class From>
To convert_weight(const From& w)
{
  if constexpr(std::is_same<To, From>::value)
    return w;
  else if constexpr(std::is_floating_point<To>::value)
    return To(CGAL::to_double(w));
  else if constexpr(std::is_constructible<To, From>::value)
    return To(w);
  else
    return To(CGAL::to_double(w));
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_MESH_TRAITS_H
