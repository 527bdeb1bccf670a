// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_BOUNDARY_RULES_H
#define CGAL_SUBDIV_MASKS_BOUNDARY_RULES_H

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivMasks
 * What the approximating schemes do at a border vertex with a single incident
 * face (a "corner", border valence 2).
 */
enum class Border_corners {
  /// the border rule of every other border vertex (1/8, 6/8, 1/8): what CGAL's
  /// Subdivision_method_3 does, and OpenSubdiv with boundary interpolation
  /// "edges only"
  smooth,
  /// the vertex stays where it is, so the limit surface keeps the corner:
  /// OpenSubdiv's boundary interpolation "edges and corners"
  sharp
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_BOUNDARY_RULES_H
