// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_VIEWS_VERTEX_VIEW_H
#define CGAL_SUBDIV_VIEWS_VERTEX_VIEW_H

/// \file Vertex_view.h
/// What a mask sees of the element whose new vertex it weighs: the views that
/// the refinement hosts build once per element and hand to the masks, in the
/// role of OpenSubdiv's Sdc neighbourhood interfaces. Every question "what
/// kind of vertex is this" (valence, faces, border, rule) is answered here and
/// nowhere else; crease and corner tags will enter here too.

#include <CGAL/Subdiv/views/Split.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace Subdiv {
namespace internal {

// halfedge(f) of any FaceGraph, for classes whose member `halfedge()` hides the free function
template <class Mesh>
typename boost::graph_traits<Mesh>::halfedge_descriptor first_halfedge(
  typename boost::graph_traits<Mesh>::face_descriptor f, const Mesh& mesh)
{
  return halfedge(f, mesh);
}

} // namespace internal

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

/*!
 * \ingroup PkgSubdivMasks
 * OpenSubdiv's boundary interpolation (`Sdc::Options::VtxBoundaryInterpolation`;
 * RenderMan's and USD's "interpolateBoundary"): the named parameter
 * `boundary_interpolation` of `loop_subdivision()`,
 * `catmull_clark_subdivision()` and `subdivide()`. Border edges are
 * infinitely sharp in all three.
 */
enum class Boundary_interpolation {
  /// the points of `edges_only`, but the faces at the border have no limit
  /// surface: with a `face_hole_map`, `subdivide()` makes them holes
  none,
  /// border vertices follow the border curve (`Border_corners::smooth`, the default)
  edges_only,
  /// and a border vertex with a single face stays where it is (`Border_corners::sharp`)
  edges_and_corners
};

/*!
 * \ingroup PkgSubdivMasks
 * The edge rule of Catmull-Clark next to a triangle of the input (after one
 * level every face is a quad, so it matters on the first level only).
 */
enum class Triangle_subdivision {
  /// the Catmull-Clark edge rule everywhere (OpenSubdiv's `TRI_SUB_CATMARK`,
  /// USD's "catmullClark", CGAL's rule; the default)
  catmark,
  /// OpenSubdiv's `TRI_SUB_SMOOTH` (USD's "smooth"): on an interior edge with a
  /// triangle on either side, each triangle's face point weighs 47/100
  /// instead of 1/4; the edge point is \f$ w_v (v_0 + v_1) + w_f (f_0 + f_1)
  /// \f$ with \f$ w_f \f$ the mean of the two faces' weights and \f$ w_v =
  /// (1 - 2 w_f) / 2 \f$. The constant is OpenSubdiv's, chosen by experiment
  /// to round the limit surface over triangles.
  smooth
};

namespace internal {

/// the `Border_corners` of the masks under a boundary interpolation
inline Border_corners border_corners_for(Boundary_interpolation boundary)
{
  return boundary == Boundary_interpolation::edges_and_corners ? Border_corners::sharp : Border_corners::smooth;
}

} // namespace internal

/*!
 * \ingroup PkgSubdivMasks
 * The rule a vertex is refined with, as OpenSubdiv's `Sdc::Crease` names
 * them, from the number of sharp edges at the vertex (border edges are
 * sharp) and its own sharpness: `smooth` with none, `dart` with one (refined
 * with the smooth rule), `crease` with two, `corner` with more or where the
 * vertex itself is sharp (with `Border_corners::sharp`, a border vertex with
 * a single face). Without sharpness tags a vertex is smooth inside the mesh
 * and a crease or a corner on its border.
 */
enum class Vertex_rule { smooth, dart, crease, corner };

/*!
 * \ingroup PkgSubdivMasks
 * What the sharpness tags of a level say about a vertex (made by
 * `internal::Sharp_level`, read through `Vertex_view`): its rule on this
 * level and on the next (they differ where a sharpness decays to zero in
 * this step; the mask then blends the two rules), and the two sharp edges of
 * each crease rule, as halfedges out of the vertex.
 */
template <class Mesh>
struct Sharp_vertex
{
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;

  Vertex_rule rule = Vertex_rule::smooth;
  Vertex_rule child_rule = Vertex_rule::smooth;
  halfedge_descriptor crease[2];
  halfedge_descriptor child_crease[2];
};

/*!
 * \ingroup PkgSubdivMasks
 * A vertex of a `FaceGraph` as a mask sees it: its valence (incident edges),
 * its faces, whether it is on the border and, there, its two border halfedges
 * (the border neighbours are their other ends), and its rule. Built by the
 * refinement hosts with one walk around the vertex.
 */
template <class Mesh>
class Vertex_view
{
public:
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;

  Vertex_view(const Mesh& mesh, vertex_descriptor v, Border_corners corners = Border_corners::smooth)
    : m_mesh(&mesh), m_vertex(v), m_border_in(boost::graph_traits<Mesh>::null_halfedge())
  {
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, mesh)) {
      ++m_valence;
      if(CGAL::is_border(h, mesh))
        m_border_in = h;
    }
    if(!on_border())
      m_rule = Vertex_rule::smooth;
    else if(m_valence == 2 && corners == Border_corners::sharp)
      m_rule = Vertex_rule::corner;
    else
      m_rule = Vertex_rule::crease;
  }

  const Mesh& mesh() const { return *m_mesh; }
  vertex_descriptor vertex() const { return m_vertex; }
  /// the number of edges at the vertex (a border vertex counts its two border edges)
  int valence() const { return m_valence; }
  /// the number of faces at the vertex
  int number_of_faces() const { return on_border() ? m_valence - 1 : m_valence; }
  bool on_border() const { return m_border_in != boost::graph_traits<Mesh>::null_halfedge(); }
  /// the border halfedge that ends at the vertex (null inside the mesh)
  halfedge_descriptor border_in() const { return m_border_in; }
  /// the border halfedge that starts at the vertex (null inside the mesh)
  halfedge_descriptor border_out() const
  {
    return on_border() ? next(m_border_in, *m_mesh) : boost::graph_traits<Mesh>::null_halfedge();
  }
  /// the rule of the vertex on this level
  Vertex_rule rule() const { return m_sharp != nullptr ? m_sharp->rule : m_rule; }
  /// the rule of its child on the next level (different from `rule()` only
  /// where a sharpness decays to zero in this step)
  Vertex_rule child_rule() const { return m_sharp != nullptr ? m_sharp->child_rule : m_rule; }
  /// the two sharp edges of the crease rule of this level (`rule()` is
  /// `crease`), as halfedges out of the vertex; on the border, the border edges
  halfedge_descriptor crease_out(int i) const
  {
    if(m_sharp != nullptr)
      return m_sharp->crease[i];
    return i == 0 ? border_out() : opposite(m_border_in, *m_mesh);
  }
  /// the same for the crease rule of the next level (`child_rule()` is `crease`)
  halfedge_descriptor child_crease_out(int i) const
  {
    return m_sharp != nullptr ? m_sharp->child_crease[i] : crease_out(i);
  }
  /// the ordinal of the vertex in the numbering of its level (tagged views only)
  std::size_t ordinal() const { return m_ordinal; }
  void set_sharp(const Sharp_vertex<Mesh>* sharp, std::size_t ordinal)
  {
    m_sharp = sharp;
    m_ordinal = ordinal;
  }

private:
  const Mesh* m_mesh;
  vertex_descriptor m_vertex;
  halfedge_descriptor m_border_in;
  int m_valence = 0;
  Vertex_rule m_rule = Vertex_rule::smooth;
  const Sharp_vertex<Mesh>* m_sharp = nullptr;
  std::size_t m_ordinal = 0;
};

/*!
 * \ingroup PkgSubdivMasks
 * An edge as a mask sees it, through one of its halfedges (the hosts give
 * `halfedge(e)`): whether it is on the border, and the views of its two ends
 * (made when asked for).
 */
template <class Mesh>
class Edge_view
{
public:
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;

  Edge_view(const Mesh& mesh, halfedge_descriptor h, Border_corners corners = Border_corners::smooth)
    : m_mesh(&mesh), m_halfedge(h), m_corners(corners), m_border(CGAL::is_border_edge(h, mesh))
  {}

  const Mesh& mesh() const { return *m_mesh; }
  halfedge_descriptor halfedge() const { return m_halfedge; }
  bool on_border() const { return m_border; }
  /// whether the edge is sharp on this level (a border edge, or a tagged
  /// sharpness above 0): its edge point then follows the curve rule, blended
  /// with the smooth rule unless `child_crease()`
  bool sharp() const { return m_tagged ? m_sharp : m_border; }
  /// whether both halves of the edge are sharp on the next level
  bool child_crease() const { return m_tagged ? m_child_crease : m_border; }
  /// the ordinal of the edge in the numbering of its level (tagged views only)
  std::size_t ordinal() const { return m_ordinal; }
  void set_sharp(bool sharp, bool child_crease, std::size_t ordinal)
  {
    m_tagged = true;
    m_sharp = sharp;
    m_child_crease = child_crease;
    m_ordinal = ordinal;
  }
  /// the border halfedge of a border edge
  halfedge_descriptor border_halfedge() const
  {
    return CGAL::is_border(m_halfedge, *m_mesh) ? m_halfedge : opposite(m_halfedge, *m_mesh);
  }
  /// the view of source(halfedge()) (i = 0) or target(halfedge()) (i = 1)
  Vertex_view<Mesh> end(int i) const
  {
    return Vertex_view<Mesh>(*m_mesh, i == 0 ? source(m_halfedge, *m_mesh) : target(m_halfedge, *m_mesh), m_corners);
  }

private:
  const Mesh* m_mesh;
  halfedge_descriptor m_halfedge;
  Border_corners m_corners;
  bool m_border;
  bool m_tagged = false;
  bool m_sharp = false;
  bool m_child_crease = false;
  std::size_t m_ordinal = 0;
};

/*!
 * \ingroup PkgSubdivMasks
 * A face as a mask sees it, through `halfedge(f)`; the views of its corners
 * are made when asked for.
 */
template <class Mesh>
class Face_view
{
public:
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;

  Face_view(const Mesh& mesh, face_descriptor f, Border_corners corners = Border_corners::smooth)
    : m_mesh(&mesh), m_face(f), m_corners(corners)
  {}

  const Mesh& mesh() const { return *m_mesh; }
  face_descriptor face() const { return m_face; }
  halfedge_descriptor halfedge() const { return internal::first_halfedge(m_face, *m_mesh); }
  /// the view of the corner target(h), h a halfedge of the face
  Vertex_view<Mesh> corner(halfedge_descriptor h) const
  {
    return Vertex_view<Mesh>(*m_mesh, target(h, *m_mesh), m_corners);
  }

private:
  const Mesh* m_mesh;
  face_descriptor m_face;
  Border_corners m_corners;
};

/*!
 * \ingroup PkgSubdivMasks
 * A face corner as a dual mask sees it: the corner of `face(h)` at
 * `target(h)`, whether the face's edges before and after the corner are on
 * the border, and the size of the face. With sharpness tags the host says
 * which of the two edges are sharp (a crease, or the border) and whether the
 * corner is kept at its vertex (`set_sharp`); without, the border edges are
 * the sharp ones and a corner with both of them is kept.
 */
template <class Mesh>
class Corner_view
{
public:
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;

  Corner_view(const Mesh& mesh, halfedge_descriptor h)
    : m_mesh(&mesh), m_halfedge(h), m_border_before(CGAL::is_border(opposite(h, mesh), mesh)),
      m_border_after(CGAL::is_border(opposite(next(h, mesh), mesh), mesh)), m_sharp_before(m_border_before),
      m_sharp_after(m_border_after), m_kept(m_border_before && m_border_after)
  {}

  const Mesh& mesh() const { return *m_mesh; }
  /// the halfedge of the face that ends at the corner
  halfedge_descriptor halfedge() const { return m_halfedge; }
  vertex_descriptor vertex() const { return target(m_halfedge, *m_mesh); }
  /// whether the edge of `halfedge()` is on the border
  bool border_before() const { return m_border_before; }
  /// whether the edge of `next(halfedge())` is on the border
  bool border_after() const { return m_border_after; }
  /// whether the edge of `halfedge()` is sharp (on the border, or a crease
  /// with tags): the corner then follows the curve rule along it
  bool sharp_before() const { return m_sharp_before; }
  /// whether the edge of `next(halfedge())` is sharp
  bool sharp_after() const { return m_sharp_after; }
  /// whether the corner stays at its vertex (a corner of the curve rule: a
  /// face whose two edges at the vertex are both sharp, or with tags a
  /// corner vertex)
  bool kept() const { return m_kept; }
  /// the sharp edges and the kept corner, as the host reads them from the tags of the level
  void set_sharp(bool before, bool after, bool kept)
  {
    m_sharp_before = before;
    m_sharp_after = after;
    m_kept = kept;
  }
  int face_size() const
  {
    int size = 0;
    halfedge_descriptor g = m_halfedge;
    do {
      ++size;
      g = next(g, *m_mesh);
    } while(g != m_halfedge);
    return size;
  }

private:
  const Mesh* m_mesh;
  halfedge_descriptor m_halfedge;
  bool m_border_before;
  bool m_border_after;
  bool m_sharp_before;
  bool m_sharp_after;
  bool m_kept;
};

namespace internal {

template <class Mask, class = void>
struct Has_border_corners : std::false_type
{};
template <class Mask>
struct Has_border_corners<Mask, std::void_t<decltype(std::declval<const Mask&>().border_corners())>> : std::true_type
{};

/// the `Border_corners` option of a mask (smooth for masks without one)
template <class Mask>
Border_corners border_corners_of(const Mask& mask)
{
  if constexpr(Has_border_corners<Mask>::value)
    return mask.border_corners();
  else {
    (void)mask;
    return Border_corners::smooth;
  }
}

template <class Mask, class = void>
struct Has_triangle_subdivision : std::false_type
{};
template <class Mask>
struct Has_triangle_subdivision<Mask, std::void_t<decltype(std::declval<const Mask&>().triangle_subdivision())>>
  : std::true_type
{};

/// the `Triangle_subdivision` option of a mask (catmark for masks without one)
template <class Mask>
Triangle_subdivision triangle_subdivision_of(const Mask& mask)
{
  if constexpr(Has_triangle_subdivision<Mask>::value)
    return mask.triangle_subdivision();
  else {
    (void)mask;
    return Triangle_subdivision::catmark;
  }
}

} // namespace internal

namespace internal {

/// whether `subdivide()` takes sharpness tags for the mask (it has
/// `with_sharp_level()`)
template <class Mask, class = void>
struct Takes_sharpness_tags : std::false_type
{};
template <class Mask>
struct Takes_sharpness_tags<Mask, std::void_t<decltype(std::declval<const Mask&>().with_sharp_level(nullptr))>>
  : std::true_type
{};

/// whether the mask takes semi-sharp tags (Loop, Catmull-Clark, the linear
/// masks), or infinitely sharp ones only (its `takes_semi_sharp_tags` is
/// false: the butterflies and the sqrt3 schemes)
template <class Mask, class = void>
struct Takes_semi_sharp_tags : std::true_type
{};
template <class Mask>
struct Takes_semi_sharp_tags<Mask, std::enable_if_t<!Mask::takes_semi_sharp_tags>> : std::false_type
{};

/// whether the limit layer takes sharpness tags for the mask: every mask
/// that `subdivide()` refines with tags but Doo-Sabin's (the dual split),
/// whose crease limit is not derived
template <class Mask, class = void>
struct Limit_takes_sharpness_tags : std::false_type
{};
template <class Mask>
struct Limit_takes_sharpness_tags<Mask, std::enable_if_t<Takes_sharpness_tags<Mask>::value>>
  : std::integral_constant<bool, Mask::split != Split::dual>
{};

/// whether the mask is a tagged copy (`With_sharp_rules`, `With_sharp_level`): its views come
/// from the tags of its level
template <class Mask, class = void>
struct Refines_with_tags : std::false_type
{};
template <class Mask>
struct Refines_with_tags<Mask, std::enable_if_t<Mask::refines_with_tags>> : std::true_type
{};

} // namespace internal

/// the view of vertex `v` with the options of `mask` (as the hosts make it):
/// with the rules its sharpness tags select, if it is a tagged copy
template <class Mask, class Mesh>
Vertex_view<Mesh> vertex_view(const Mask& mask, const Mesh& mesh,
                              typename boost::graph_traits<Mesh>::vertex_descriptor v)
{
  if constexpr(internal::Refines_with_tags<Mask>::value) {
    (void)mesh;
    return mask.sharp_level()->vertex_view(v);
  } else
    return Vertex_view<Mesh>(mesh, v, internal::border_corners_of(mask));
}

/// the view of the edge of `h` with the options of `mask` (as the hosts make
/// it): with the rules its sharpness tags select, if it is a tagged copy
template <class Mask, class Mesh>
Edge_view<Mesh> edge_view(const Mask& mask, const Mesh& mesh, typename boost::graph_traits<Mesh>::halfedge_descriptor h)
{
  if constexpr(internal::Refines_with_tags<Mask>::value) {
    (void)mesh;
    return mask.sharp_level()->edge_view(h);
  } else
    return Edge_view<Mesh>(mesh, h, internal::border_corners_of(mask));
}

/// the view of face `f` with the options of `mask` (as the hosts make it)
template <class Mask, class Mesh>
Face_view<Mesh> face_view(const Mask& mask, const Mesh& mesh, typename boost::graph_traits<Mesh>::face_descriptor f)
{
  return Face_view<Mesh>(mesh, f, internal::border_corners_of(mask));
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_VIEWS_VERTEX_VIEW_H
