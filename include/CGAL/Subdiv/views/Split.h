// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_VIEWS_SPLIT_H
#define CGAL_SUBDIV_VIEWS_SPLIT_H

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivMasks
 * The topological split of a surface scheme: a trait of its mask
 * (`static constexpr Split split`), like OpenSubdiv's
 * `Sdc::SchemeTypeTraits::GetTopologicalSplitType()`. The refinement host
 * that performs a split is `Host_for<split, Mesh>`, defined by the host's header: the
 * masks know nothing of hosts.
 */
enum class Split {
  /// 1-to-4 triangle split (Loop, butterflies, linear): `Triangle_quadrisection`
  triangle_quadrisection,
  /// primal quad split of any polygon mesh (Catmull-Clark, bilinear): `Quad_split`
  quad,
  /// dual quad split of any polygon mesh (Doo-Sabin): `Dual_split`
  dual,
  /// Kobbelt's sqrt3 split of triangle meshes: `Sqrt3_split`
  sqrt3
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_VIEWS_SPLIT_H
