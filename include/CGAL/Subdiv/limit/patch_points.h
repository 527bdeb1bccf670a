// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_PATCH_POINTS_H
#define CGAL_SUBDIV_LIMIT_PATCH_POINTS_H

/// \file patch_points.h
/// The control points of a face's patch, read from any FaceGraph around
/// one halfedge (the one into the face's corner 0): whether the patch is
/// regular or has one extraordinary corner, the 16 (12) points of a
/// regular quad (triangle) as `patch_basis.h` numbers them, and the
/// vertices of the 1-ring in an order fixed by the topology alone, which
/// the eigenbasis of `Stam_eigenbasis.h` is expressed in.

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/// the patches of Catmull-Clark (`Quads`) or of Loop around a halfedge `h0` of `Mesh`
template <class Mesh, bool Quads>
class Patch_points
{
  using GT = boost::graph_traits<Mesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using Vpm = typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type;

public:
  using Point = typename boost::property_traits<Vpm>::value_type;
  // the valence of a regular vertex, and the corners of a regular face
  static constexpr std::size_t regular_valence = Quads ? 4 : 6;
  static constexpr std::size_t face_corners = Quads ? 4 : 3;

  Patch_points(const Mesh& mesh, halfedge_descriptor h0) : m(mesh), h0(h0), vpm(get(CGAL::vertex_point, mesh)) {}

  // the sides of the quad on the border: bit i for the edge from corner i to corner i+1
  int border_sides() const
  {
    int sides = 0;
    halfedge_descriptor h = next(h0, m);
    for(int i = 0; i < 4; ++i, h = next(h, m))
      if(CGAL::is_border(opposite(h, m), m))
        sides |= 1 << i;
    return sides;
  }

  /*
   * Whether the face and the faces around its corners are all quads
   * (triangles) and its corners inner vertices of valence 4 (6); under
   * Catmull-Clark, also a quad with one side on the border, whose two ends
   * have two faces, the other corners being inner of valence 4, and with
   * `sharp_corners` (Border_corners::sharp) a quad with two adjacent sides
   * on the border, whose common corner is a corner of one face (kept by the
   * mask: the B-spline interpolates it), their other ends having two faces
   * and the fourth corner being inner of valence 4. Under Loop, also a
   * triangle with one corner, or one side (its two ends), on the border,
   * each such corner having three faces, the others being inner of valence
   * 6 (the regular border of a triangle grid).
   */
  bool is_regular(bool sharp_corners = false) const
  {
    if constexpr(!Quads)
      return is_regular_triangle();
    const int sides = border_sides();
    if((sides & 5) == 5 || (sides & 10) == 10 || (sides != 0 && (sides & (sides - 1)) != 0 && !sharp_corners))
      return false; // opposite sides on the border, or a corner that is not kept
    int i = 0;
    for(const halfedge_descriptor h : CGAL::halfedges_around_face(h0, m)) {
      // corner i ends side i - 1 (from corner i - 1) and starts side i
      const int on_border = ((sides >> i) & 1) + ((sides >> ((i + 3) % 4)) & 1);
      ++i;
      const Corner_shape c = corner_shape(h);
      if(on_border > 0 ? c.valence != std::size_t(4 - on_border) || !c.border
                       : c.valence != regular_valence || c.border)
        return false;
      if(!c.faces_regular)
        return false;
    }
    return true;
  }

  /// the one extraordinary corner of a patch: its index from corner 0, its valence and the 1-ring
  struct Extraordinary_corner
  {
    int index = 0;
    std::size_t valence = 0;             // 0: the patch has none
    halfedge_descriptor into;            // the halfedge of the face into it
    std::vector<vertex_descriptor> ring; // ring_vertices(into)
  };

  /*
   * The patch's one extraordinary corner: the face and every face around
   * its corners have `face_corners` corners, every corner is an inner
   * vertex, one has another valence than the regular one and the others
   * have the regular one, and the 1-ring has as many vertices as that shape
   * has (2 n + 8 for a quad, n + 6 for a triangle: none is met twice); a
   * valence of 0 if there is none.
   */
  Extraordinary_corner extraordinary_corner() const
  {
    Extraordinary_corner found;
    int i = 0;
    for(const halfedge_descriptor h : CGAL::halfedges_around_face(h0, m)) {
      const Corner_shape c = corner_shape(h);
      if(c.border || !c.faces_regular)
        return {};
      if(const std::size_t k = c.valence; k != regular_valence) {
        if(found.valence > 0)
          return {};
        found.index = i;
        found.valence = k;
        found.into = h;
      }
      ++i;
    }
    if(found.valence == 0)
      return {};
    found.ring = ring_vertices(found.into);
    if(found.ring.size() != (Quads ? 2 * found.valence + 8 : found.valence + 6))
      return {};
    return found;
  }

  /*
   * The vertices of every face that shares a vertex with the face, each
   * once, in an order fixed by the topology around h0: corner by corner
   * from corner 0, the faces around the corner from the face on (turning
   * from the halfedge into the corner g to opposite(next(g))), and in each
   * face its vertices from that corner on. Empty if a corner is on the
   * border. (From the corner at the target of `start`, if given, instead.)
   */
  std::vector<vertex_descriptor> ring_vertices() const { return ring_vertices(h0); }
  std::vector<vertex_descriptor> ring_vertices(halfedge_descriptor start) const
  {
    std::vector<vertex_descriptor> ring;
    halfedge_descriptor into = start;
    do {
      halfedge_descriptor g = into;
      do {
        if(CGAL::is_border(g, m))
          return {};
        for(const vertex_descriptor w : CGAL::vertices_around_face(g, m))
          if(std::find(ring.begin(), ring.end(), w) == ring.end())
            ring.push_back(w);
        g = opposite(next(g, m), m);
      } while(g != into);
      into = next(into, m);
    } while(into != start);
    return ring;
  }

  /*
   * The 16 control points of a regular quad, numbered as
   * `bspline_patch_weights()` takes them (point 4 r + c in row r along v,
   * column c along u; corner i of the face at 5, 6, 10, 9). Across the edge
   * from corner i to corner i+1 lie the neighbours of both, and the diagonal
   * neighbour of corner i is the far corner of the face beyond. A side on
   * the border has nothing beyond: its row (column) is extrapolated, p =
   * 2 b - q from the border point b and the inner one q behind it, so that
   * the B-spline refines as Catmull-Clark's border rules do (a border
   * vertex 3/4, 1/8, 1/8; a border edge its midpoint; a sharp corner stays)
   * and its side is the cubic B-spline of the border points. With two sides
   * on the border, the second extrapolation also makes the point beyond
   * their common corner (the first one's there, read from points not made
   * yet, is overwritten).
   */
  std::array<Point, 16> quad_control_points() const
  {
    std::array<halfedge_descriptor, 4> h;
    h[0] = h0;
    for(int i = 1; i < 4; ++i)
      h[i] = next(h[i - 1], m);
    const int sides = border_sides();
    // by corner i: its point, the neighbours across the edge to corner i+1
    // (next to corner i, then to corner i+1), and its diagonal neighbour
    static const int corner_point[4] = {5, 6, 10, 9};
    static const int across[4][2] = {{1, 2}, {7, 11}, {14, 13}, {8, 4}};
    static const int diagonal[4] = {0, 3, 15, 12};
    std::array<Point, 16> points;
    points.fill(Point(CGAL::ORIGIN));
    for(int i = 0; i < 4; ++i) {
      points[corner_point[i]] = get(vpm, target(h[i], m));
      if((sides >> i) & 1) // nothing beyond
        continue;
      const halfedge_descriptor beyond = opposite(h[(i + 1) % 4], m); // across the edge from corner i to corner i+1
      points[across[i][0]] = get(vpm, target(next(beyond, m), m));
      points[across[i][1]] = get(vpm, target(next(next(beyond, m), m), m));
      if(!((sides >> ((i + 3) % 4)) & 1)) // corner i's diagonal face is not beyond the border
        points[diagonal[i]] = get(vpm, source(prev(opposite(next(beyond, m), m), m), m));
    }
    for(int side = 0; side < 4; ++side)
      if((sides >> side) & 1)
        extrapolate_beyond(side, points);
    return points;
  }

  /*
   * The 12 control points of a regular triangle, numbered as
   * `box_spline_patch_weights()` takes them (corner 0 at 4, 1 at 5, 2 at 8):
   * around corner 0 its neighbours from corner 1 on, away from the face, are
   * 5, 1, 0, 3, 7, 8; around corner 1 8, 9, 6, 2, 1, 4; around corner 2 4,
   * 7, 10, 11, 9, 5 (`around_corner`, which extrapolates those beyond the
   * border).
   */
  std::array<Point, 12> triangle_control_points() const
  {
    static const int corner_point[3] = {4, 5, 8};
    static const int ring[3][4] = {{1, 0, 3, 7}, {9, 6, 2, 1}, {7, 10, 11, 9}};
    std::array<Point, 12> points;
    halfedge_descriptor into = h0;
    for(int i = 0; i < 3; ++i, into = next(into, m)) {
      points[corner_point[i]] = get(vpm, target(into, m));
      const std::array<Point, 6> around = around_corner(into);
      for(int k = 0; k < 4; ++k)
        points[ring[i][k]] = around[k + 1];
    }
    return points;
  }

  /// the control points of a regular patch, as the scheme's basis numbers them
  auto control_points() const
  {
    if constexpr(Quads)
      return quad_control_points();
    else
      return triangle_control_points();
  }

private:
  /*
   * Whether the triangle is a regular patch (`is_regular`): every corner
   * inner of valence 6, or on the border with three faces; at most two on
   * the border, and two only as the ends of a side on the border (two
   * borders within the ring are not the border of a triangle grid).
   */
  bool is_regular_triangle() const
  {
    int border_corners = 0;
    bool has_border_side = false;
    for(const halfedge_descriptor h : CGAL::halfedges_around_face(h0, m)) {
      const Corner_shape c = corner_shape(h);
      if(!c.faces_regular || c.valence != (c.border ? 4u : regular_valence))
        return false;
      border_corners += c.border ? 1 : 0;
      if(CGAL::is_border(opposite(h, m), m)) // the side from the previous corner to this one
        has_border_side = true;
    }
    return border_corners <= 1 || (border_corners == 2 && has_border_side);
  }

  /*
   * The six neighbours of the target c of `into` (a halfedge of the face,
   * into its corner c) in turning order: the face's next corner, the four
   * vertices away from the face, its previous corner. At a border vertex
   * with three faces two of them lie beyond the border; each is
   * extrapolated across its border edge (c, b) from the third corner q of
   * the face on that edge, p = c + b - q (symmetric in c and b, so both
   * ends of a border side make the same point). The box spline of the grid
   * so extended refines as Loop's border rules do (a border vertex 3/4, 1/8,
   * 1/8; a border edge its midpoint; an inner edge at the border its 3/8,
   * 3/8, 1/8, 1/8), and the extrapolated points of the refined grid are
   * those of the refined border: the side on the border is the cubic
   * B-spline of the border points.
   */
  std::array<Point, 6> around_corner(halfedge_descriptor into) const
  {
    std::array<Point, 6> around;
    const vertex_descriptor c = target(into, m);
    // forward from the next corner, while the face crossed is not beyond the border
    halfedge_descriptor g = opposite(next(into, m), m);
    int forward = 0;
    around[forward++] = get(vpm, source(g, m));
    while(forward < 6 && !CGAL::is_border(g, m)) {
      g = opposite(next(g, m), m);
      around[forward++] = get(vpm, source(g, m));
    }
    if(forward == 6)
      return around; // an inner vertex: g came back to `into`
    // backward from the previous corner
    int backward = 5;
    halfedge_descriptor h = into;
    around[backward] = get(vpm, source(h, m));
    while(backward > forward && !CGAL::is_border(opposite(h, m), m)) {
      h = prev(opposite(h, m), m);
      around[--backward] = get(vpm, source(h, m));
    }
    // around[forward .. backward - 1] lie beyond the border (two of them at a regular border vertex)
    const Point& centre = get(vpm, c);
    const auto beyond = [&centre](const Point& b, const Point& q) {
      return CGAL::ORIGIN + (((centre - CGAL::ORIGIN) + (b - CGAL::ORIGIN)) - (q - CGAL::ORIGIN));
    };
    around[forward] = beyond(around[forward - 1], around[(forward + 4) % 6]);
    around[backward - 1] = beyond(around[backward], around[(backward + 1) % 6]);
    return around;
  }

  /*
   * The target of h in one walk around it (the patch tests run on every
   * evaluation): its valence, whether it is on the border, and whether
   * every face around it has `face_corners` corners.
   */
  struct Corner_shape
  {
    std::size_t valence = 0;
    bool border = false;
    bool faces_regular = true;
  };
  Corner_shape corner_shape(halfedge_descriptor h) const
  {
    Corner_shape c;
    for(const halfedge_descriptor g : CGAL::halfedges_around_target(h, m)) {
      ++c.valence;
      if(CGAL::is_border(g, m))
        c.border = true;
      else if(c.faces_regular && !has_corners(g, face_corners))
        c.faces_regular = false;
    }
    return c;
  }
  // whether the face of g has n corners (walking n + 1 halfedges at most)
  bool has_corners(halfedge_descriptor g, std::size_t n) const
  {
    halfedge_descriptor h = g;
    for(std::size_t k = 1; k <= n; ++k) {
      h = next(h, m);
      if(h == g)
        return k == n;
    }
    return false;
  }

  // the points beyond border side `side` of the grid: p = 2 b - q
  static void extrapolate_beyond(int side, std::array<Point, 16>& points)
  {
    // point (r, c) of the grid seen from the side: row 0 beyond the border,
    // row 1 on it, row 2 inside
    const auto at = [side](int r, int c) {
      switch(side) {
        case 0:
          return 4 * r + c; // bottom
        case 1:
          return 4 * c + (3 - r); // right
        case 2:
          return 4 * (3 - r) + (3 - c); // top
        default:
          return 4 * (3 - c) + r; // left
      }
    };
    for(int c = 0; c < 4; ++c)
      points[at(0, c)] = points[at(1, c)] + (points[at(1, c)] - points[at(2, c)]);
  }

  const Mesh& m;
  halfedge_descriptor h0;
  Vpm vpm;
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_PATCH_POINTS_H
