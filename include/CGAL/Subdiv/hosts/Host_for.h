// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_HOST_FOR_H
#define CGAL_SUBDIV_HOSTS_HOST_FOR_H

/// \file Host_for.h
/// How a mask's `split` trait selects the topology code: each host header
/// (`Triangle_quadrisection.h`, `Quad_split.h`, `Dual_split.h`,
/// `Sqrt3_split.h`) specialises `Host_for` for its split, and `hosts.h`
/// includes them all. A program that refines with one scheme includes only
/// that scheme's host (through `loop_subdivision.h`, say): compile time is
/// part of the API (doc/compile_time.md).

#include <CGAL/Subdiv/views/Split.h>

#include <type_traits>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivHosts
 * `Host_for<split, Mesh>::type`: the refinement host of `split` over `Mesh`,
 * defined by the host's header.
 */
template <Split split, class Mesh>
struct Host_for
{
  static_assert(split != split,
                "the host of this mask's split is not included: include "
                "<CGAL/Subdiv/hosts/hosts.h> (every host), the scheme's header "
                "(<CGAL/Subdiv/loop_subdivision.h>, ...) or <CGAL/Subdiv/surface_subdivision.h>");
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
