// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_CONFIGURATION_H
#define CGAL_SUBDIV_ANALYSIS_CONFIGURATION_H

#include <string>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * Where an analysis is centred: inside the mesh, or on its border; or, for
 * the schemes that take OpenSubdiv's sharpness tags (Loop, Catmull-Clark),
 * at an interior vertex made sharp by infinitely sharp tags (10): a crease
 * vertex (two sharp edges), a dart (one) or a corner (vertex sharpness 10).
 */
enum class Vertex_kind {
  interior, ///< a smooth interior vertex
  border,   ///< a border vertex
  crease,   ///< an interior vertex on a crease: two infinitely sharp rays of edges through it
  dart,     ///< an interior vertex where a crease ends: one infinitely sharp ray of edges from it
  corner    ///< an interior vertex of vertex sharpness 10, its edges smooth
};

/*!
 * \ingroup PkgSubdivAnalysis
 * The configuration an analysis is made at: an interior vertex of valence
 * `valence`, or a border vertex with `valence` faces; for a dual scheme
 * (Doo-Sabin), an interior face with `valence` corners, or the border face
 * made from a border vertex with `valence` faces. All other vertices of the
 * neighbourhood are regular.
 *
 * The sharp kinds (`crease()`, `dart()`, `corner()`) are interior vertices of
 * valence `valence` with infinitely sharp tags; a sharp edge is sharp along
 * its whole ray of edges (the straight line of edges through the regular
 * vertices beyond it), so that the configuration is the same on every level.
 * Semi-sharp values have no such configuration: their sharpness decays with
 * the level, so no stationary local matrix exists.
 */
struct Configuration
{
  int valence = 0;
  Vertex_kind kind = Vertex_kind::interior;
  /// crease: the faces on the first side (between sharp rays 0 and
  /// `first_side`, counter-clockwise); the other side has `valence - first_side`
  int first_side = 0;

  Configuration() = default;
  Configuration(int n, Vertex_kind k = Vertex_kind::interior) : valence(n), kind(k) {}

  /// a crease vertex with `k1` faces on one side and `k2` on the other
  static Configuration crease(int k1, int k2)
  {
    Configuration result(k1 + k2, Vertex_kind::crease);
    result.first_side = k1;
    return result;
  }
  /// a dart of valence `n`: one ray of sharp edges ends at the vertex
  static Configuration dart(int n) { return Configuration(n, Vertex_kind::dart); }
  /// a corner of valence `n`: vertex sharpness 10, smooth edges
  static Configuration corner(int n) { return Configuration(n, Vertex_kind::corner); }

  bool on_border() const { return kind == Vertex_kind::border; }
  /// a crease, dart or corner: the analysis refines with sharpness tags
  bool sharp() const { return kind == Vertex_kind::crease || kind == Vertex_kind::dart || kind == Vertex_kind::corner; }
  /// crease: the faces on the second side
  int second_side() const { return valence - first_side; }
  /// the sector boundaries (0 .. valence - 1, counter-clockwise from the
  /// first edge) whose rays of edges are infinitely sharp
  std::vector<int> sharp_rays() const
  {
    if(kind == Vertex_kind::crease)
      return {0, first_side};
    if(kind == Vertex_kind::dart)
      return {0};
    return {};
  }
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_CONFIGURATION_H
