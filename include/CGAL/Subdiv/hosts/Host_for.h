// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_HOST_FOR_H
#define CGAL_SUBDIV_HOSTS_HOST_FOR_H

/// \file Host_for.h
/// The refinement host of each split: the one place that maps a mask's
/// `split` trait to the topology code. Adding a host means adding it here.

#include <CGAL/Subdiv/hosts/Dual_split.h>
#include <CGAL/Subdiv/hosts/Quad_split.h>
#include <CGAL/Subdiv/hosts/Sqrt3_split.h>
#include <CGAL/Subdiv/hosts/Triangle_quadrisection.h>
#include <CGAL/Subdiv/views/Split.h>

#include <type_traits>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivHosts
 * `Host_for<split, Mesh>::type`: the refinement host of `split` over `Mesh`.
 */
template <Split split, class Mesh>
struct Host_for;

template <class Mesh>
struct Host_for<Split::triangle_quadrisection, Mesh>
{
  using type = Triangle_quadrisection<Mesh>;
};

template <class Mesh>
struct Host_for<Split::quad, Mesh>
{
  using type = Quad_split<Mesh>;
};

template <class Mesh>
struct Host_for<Split::dual, Mesh>
{
  using type = Dual_split<Mesh>;
};

template <class Mesh>
struct Host_for<Split::sqrt3, Mesh>
{
  using type = Sqrt3_split<Mesh>;
};

/// the host that refines with `Mask` (its `split` over its `Polygon_mesh`)
template <class Mask>
using Host_of = typename Host_for<Mask::split, typename Mask::Polygon_mesh>::type;

namespace internal {

/// the host of `mask` on `mesh`: made with the mask where the topology of
/// the split depends on its sharpness tags (`Sqrt3_split` keeps sharp edges)
template <class Mask, class Mesh>
Host_of<Mask> make_host(const Mesh& mesh, const Mask& mask)
{
  if constexpr(std::is_constructible<Host_of<Mask>, const Mesh&, const Mask&>::value)
    return Host_of<Mask>(mesh, mask);
  else {
    (void)mask;
    return Host_of<Mask>(mesh);
  }
}

} // namespace internal

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_HOSTS_HOST_FOR_H
