// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_BOUNDARY_RULES_H
#define CGAL_SUBDIV_MASKS_BOUNDARY_RULES_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

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

namespace internal {

// What one walk around a vertex tells: its valence (incoming halfedges, so a
// border vertex counts its border halfedge too) and, on the border, the border
// halfedge that ends at it.
template <class Mesh>
struct Vertex_walk
{
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  int valence = 0;
  halfedge_descriptor border_in = boost::graph_traits<Mesh>::null_halfedge();

  Vertex_walk(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& mesh)
  {
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, mesh)) {
      ++valence;
      if(CGAL::is_border(h, mesh))
        border_in = h;
    }
  }
  bool on_border() const { return border_in != boost::graph_traits<Mesh>::null_halfedge(); }
};

/*
 * The border vertex rule of the approximating primal schemes (Loop,
 * Catmull-Clark): the cubic B-spline vertex rule 1/8, 6/8, 1/8 along the
 * border, or the vertex kept in place at a sharp corner (one face).
 */
template <class FT, class Mesh, class Accumulator>
void border_vertex_rule(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Vertex_walk<Mesh>& walk,
                        Border_corners corners, const Mesh& mesh, Accumulator& acc)
{
  if(walk.valence == 2 && corners == Border_corners::sharp) { // corner
    acc.add(v, FT(1));
    return;
  }
  acc.add(v, FT(6) / FT(8));
  acc.add(source(walk.border_in, mesh), FT(1) / FT(8));
  acc.add(target(next(walk.border_in, mesh), mesh), FT(1) / FT(8));
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_BOUNDARY_RULES_H
