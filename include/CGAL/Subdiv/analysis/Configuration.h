// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_CONFIGURATION_H
#define CGAL_SUBDIV_ANALYSIS_CONFIGURATION_H

#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * Where an analysis is centred: inside the mesh, or on its border.
 */
enum class Vertex_kind { interior, border };

/*!
 * \ingroup PkgSubdivAnalysis
 * The configuration an analysis is made at: an interior vertex of valence
 * `valence`, or a border vertex with `valence` faces; for a dual scheme
 * (Doo-Sabin), an interior face with `valence` corners, or the border face
 * made from a border vertex with `valence` faces. All other vertices of the
 * neighbourhood are regular.
 */
struct Configuration
{
  int valence = 0;
  Vertex_kind kind = Vertex_kind::interior;

  Configuration() = default;
  Configuration(int n, Vertex_kind k = Vertex_kind::interior) : valence(n), kind(k) {}
  bool on_border() const { return kind == Vertex_kind::border; }
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_CONFIGURATION_H
