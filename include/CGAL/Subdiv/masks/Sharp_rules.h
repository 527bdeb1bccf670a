// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_SHARP_RULES_H
#define CGAL_SUBDIV_MASKS_SHARP_RULES_H

#include <CGAL/Subdiv/masks/Border_curve_rule.h>
#include <CGAL/Subdiv/views/Vertex_view.h>

#include <CGAL/assertions.h>

#include <utility>

namespace CGAL {
namespace Subdiv {
namespace internal {

// defined in views/Sharp_level.h, which only the tagged refinement includes
// (subdivide.h): a plain program does not compile the tags
template <class Mesh, class FT>
class Sharp_level;

/// an accumulator that scales every weight by `scale` before passing it on
/// (the two rules of a blend)
template <class Accumulator, class FT>
class Scaled_accumulator
{
public:
  Scaled_accumulator(Accumulator& acc, const FT& scale) : m_acc(acc), m_scale(scale) {}

  template <class VertexDescriptor, class Weight>
  void add(VertexDescriptor v, const Weight& weight)
  {
    m_acc.add(v, m_scale * weight);
  }

private:
  Accumulator& m_acc;
  FT m_scale;
};

/*
 * The vertex of the polyline of sharp edges beyond `v`, an end of the sharp
 * edge of `h`, under the tags of `level`: the other end of v's other sharp
 * edge where v has the crease rule (two sharp edges), and `null_vertex()`
 * where the polyline ends at v (a corner, or the end of a dart's edge).
 */
template <class Level, class Mesh>
typename boost::graph_traits<Mesh>::vertex_descriptor crease_beyond(
  const Level& level, const Mesh& mesh, typename boost::graph_traits<Mesh>::vertex_descriptor v,
  typename boost::graph_traits<Mesh>::halfedge_descriptor h)
{
  const Vertex_view<Mesh> view = level.vertex_view(v);
  if(view.rule() != Vertex_rule::crease)
    return boost::graph_traits<Mesh>::null_vertex();
  const auto out = edge(view.crease_out(0), mesh) == edge(h, mesh) ? view.crease_out(1) : view.crease_out(0);
  return target(out, mesh);
}

/*
 * The polyline around the border or sharp edge of `e` that the ternary
 * border rules of the sqrt3 schemes read (`Border_curve_rule::
 * add_polyline_vertex`), seen from the end that new vertex k (k = 1, 2, at
 * k/3 of the way along `e.halfedge()`, a face halfedge) is nearer to: `a` is
 * source(e.halfedge()) for k = 1 and its target for k = 2, `b` the other end,
 * `before` the polyline's vertex beyond a and `after` the one beyond b. The
 * polyline is the border loop for a mask without tags, the polyline of sharp
 * edges for a tagged one (`crease_beyond`; `none` where it ends).
 */
template <class Mesh>
struct Curve_edge
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;

  vertex_descriptor before, a, b, after;
  vertex_descriptor none = boost::graph_traits<Mesh>::null_vertex();

  template <class Mask>
  Curve_edge(const Mask& mask, const Edge_view<Mesh>& e, int k)
  {
    const Mesh& mesh = e.mesh();
    const auto h = e.halfedge();
    a = source(h, mesh);
    b = target(h, mesh);
    if constexpr(Refines_with_tags<Mask>::value) {
      before = crease_beyond(*mask.sharp_level(), mesh, a, h);
      after = crease_beyond(*mask.sharp_level(), mesh, b, h);
    } else {
      (void)mask;
      const auto g = opposite(h, mesh); // the border halfedge, from b to a
      before = target(next(g, mesh), mesh);
      after = source(prev(g, mesh), mesh);
    }
    if(k == 2) { // mirror
      std::swap(a, b);
      std::swap(before, after);
    }
  }
};

} // namespace internal

/*!
 * \ingroup PkgSubdivMasks
 * The base of a mask that refines with the sharpness tags of a level and
 * whose crease rules are its own (the sqrt3 schemes, whose border rules are
 * ternary): it gives the members through which `subdivide()` hands the mask
 * the tags of each level (`with_sharp_level()`, `sharp_level()`), as
 * `With_sharp_rules` does for the masks built on `Sharp_rules`.
 *
 * \tparam Mask the mask (CRTP), with `rebind<Mesh, FT, true>()`
 * \tparam Tagged whether the mask refines with the tags of a level
 */
template <class Mask, class Mesh, class FT, bool Tagged>
class With_sharp_level
{
public:
  /// whether the views of the mask come from the sharpness tags of a level
  static constexpr bool refines_with_tags = Tagged;

  /// the sharpness tags of the level being refined (tagged masks only)
  const internal::Sharp_level<Mesh, FT>* sharp_level() const { return m_level; }

  /// the same rules with the sharpness tags of a level (a tagged mask)
  auto with_sharp_level(const internal::Sharp_level<Mesh, FT>* level) const
  {
    auto mask = static_cast<const Mask&>(*this).template rebind<Mesh, FT, true>();
    using Tagged_mask = decltype(mask);
    static_cast<With_sharp_level<Tagged_mask, Mesh, FT, true>&>(mask).m_level = level;
    return mask;
  }

private:
  const internal::Sharp_level<Mesh, FT>* m_level = nullptr;

  template <class, class, class, bool>
  friend class With_sharp_level;
};

/*!
 * \ingroup PkgSubdivMasks
 * The sharp rules of a primal approximating scheme (Loop, Catmull-Clark), as
 * OpenSubdiv applies them: a corner stays where it is, a crease vertex and a
 * sharp edge follow the curve rule (`Border_curve_rule`, the cubic B-spline:
 * 1/8, 6/8, 1/8 with the two crease neighbours, and the midpoint), the
 * border being a crease; a dart follows the smooth rule. Where a vertex's
 * rule changes between levels, or a semi-sharp edge becomes smooth, the two
 * rules are blended with the weights of the level's sharpness tags
 * (`internal::Sharp_level`). Without tags, the rules are the border rules.
 *
 * The masks keep their smooth rules, and ask these first.
 *
 * \tparam Mesh a model of `FaceGraph`
 * \tparam FT the number type of the weights
 * \tparam Tagged whether the views come from sharpness tags. Without them a
 * vertex is sharp only on the border and its rule never changes between
 * levels, so neither the interior creases nor the blends are compiled.
 */
template <class Mesh, class FT, bool Tagged = false>
class Sharp_rules
{
public:
  using Level = internal::Sharp_level<Mesh, FT>;

  template <class CurveScheme>
  explicit Sharp_rules(const CurveScheme& scheme) : m_curve(scheme)
  {}

  const Border_curve_rule<FT>& curve() const { return m_curve; }
  /// the sharpness tags of the level being refined (null without tags)
  const Level* level() const { return m_level; }
  void set_level(const Level* level) { m_level = level; }

  /// adds the vertex point of `v`: the rule it has on this level, blended
  /// with the rule of the next where the two differ; `smooth(acc)` adds the
  /// mask's smooth rule (smooth vertices and darts)
  template <class Accumulator, class Smooth>
  void vertex_node(const Vertex_view<Mesh>& v, Accumulator& acc, const Smooth& smooth) const
  {
    const Vertex_rule rule = v.rule();
    if(is_smooth(rule)) { // a sharpness never grows, so its child is smooth too
      smooth(acc);
      return;
    }
    if constexpr(Tagged)
      if(v.child_rule() != rule) {
        blend(v, rule, v.child_rule(), acc, smooth);
        return;
      }
    rule_point(v, rule, false, acc);
  }

  /// adds the edge point of `e`: the curve rule if it is sharp, blended with
  /// `smooth(acc)` (the mask's smooth rule) where it is smooth on the next
  /// level, and else the smooth rule alone
  template <class Accumulator, class Smooth>
  void edge_node(const Edge_view<Mesh>& e, Accumulator& acc, const Smooth& smooth) const
  {
    if(!e.sharp()) {
      smooth(acc);
      return;
    }
    if constexpr(Tagged)
      if(!e.child_crease()) { // semi-sharp, smooth on the next level
        CGAL_assertion(m_level != nullptr);
        const FT weight = m_level->edge_weight(e.ordinal());
        internal::Scaled_accumulator<Accumulator, FT> sharp(acc, weight), next(acc, FT(1) - weight);
        m_curve.edge_point(e.mesh(), e.halfedge(), sharp);
        smooth(next);
        return;
      }
    m_curve.edge_point(e.mesh(), e.halfedge(), acc);
  }

private:
  static bool is_smooth(Vertex_rule rule) { return rule == Vertex_rule::smooth || rule == Vertex_rule::dart; }

  // the rule of this level blended with the one of the next (tagged views):
  // the vertex weight of the level for the first, the rest for the second
  template <class Accumulator, class Smooth>
  void blend(const Vertex_view<Mesh>& v, Vertex_rule rule, Vertex_rule child, Accumulator& acc,
             const Smooth& smooth) const
  {
    CGAL_assertion(m_level != nullptr);
    const FT& weight = m_level->vertex_weight(v.ordinal());
    internal::Scaled_accumulator<Accumulator, FT> sharp(acc, weight), next(acc, FT(1) - weight);
    rule_point(v, rule, false, sharp);
    if(is_smooth(child))
      smooth(next);
    else
      rule_point(v, child, true, next);
  }

  // the crease or corner rule of v, with the crease of this level or of the next
  template <class Accumulator>
  void rule_point(const Vertex_view<Mesh>& v, Vertex_rule rule, bool next_level, Accumulator& acc) const
  {
    if(rule == Vertex_rule::corner) {
      acc.add(v.vertex(), FT(1));
      return;
    }
    if constexpr(Tagged) // without tags, a crease is on the border
      if(!v.on_border()) {
        crease_point(v, next_level, acc);
        return;
      }
    (void)next_level;
    m_curve.vertex_point(v, acc); // a crease on the border is the border itself
  }

  // the curve rule along the two sharp edges of a crease inside the mesh
  template <class Accumulator>
  void crease_point(const Vertex_view<Mesh>& v, bool next_level, Accumulator& acc) const
  {
    const auto out0 = next_level ? v.child_crease_out(0) : v.crease_out(0);
    const auto out1 = next_level ? v.child_crease_out(1) : v.crease_out(1);
    // as on the border: the vertex first, then the others by increasing offset
    for(const auto& term : m_curve.even())
      if(term.first == 0)
        acc.add(v.vertex(), term.second);
    for(const auto& term : m_curve.even()) {
      // the curve rules of the primal schemes reach the crease neighbours only
      CGAL_assertion(term.first >= -1 && term.first <= 1);
      if(term.first != 0)
        acc.add(target(term.first < 0 ? out0 : out1, v.mesh()), term.second);
    }
  }

  Border_curve_rule<FT> m_curve;
  const Level* m_level = nullptr;
};

/*!
 * \ingroup PkgSubdivMasks
 * The base of a mask that refines with sharpness tags (`Loop_mask`,
 * `Catmull_clark_mask`): it holds the mask's `Sharp_rules`, and gives the
 * members through which `subdivide()` hands the mask the tags of each level
 * (`with_sharp_level()`, `sharp_level()`).
 *
 * The tagged copy is a mask of its own type (`Tagged` true, made by the
 * mask's `rebind<Mesh, FT, true>()`), so that a program that passes no tags
 * compiles only the border rules.
 *
 * \tparam Mask the mask (CRTP)
 * \tparam Tagged whether the mask refines with the tags of a level
 */
template <class Mask, class Mesh, class FT, bool Tagged>
class With_sharp_rules
{
public:
  /// whether the views of the mask come from the sharpness tags of a level
  static constexpr bool refines_with_tags = Tagged;

  /// the sharpness tags of the level being refined (tagged masks only)
  const internal::Sharp_level<Mesh, FT>* sharp_level() const { return m_sharp.level(); }
  /// the curve rule of the creases (and of the border)
  const Border_curve_rule<FT>& crease_curve() const { return m_sharp.curve(); }

  /// the same rules with the sharpness tags of a level (a tagged mask)
  auto with_sharp_level(const internal::Sharp_level<Mesh, FT>* level) const
  {
    auto mask = static_cast<const Mask&>(*this).template rebind<Mesh, FT, true>();
    using Tagged_mask = decltype(mask);
    static_cast<With_sharp_rules<Tagged_mask, Mesh, FT, true>&>(mask).m_sharp.set_level(level);
    return mask;
  }

protected:
  /// the sharp rules along the curve scheme `scheme` (its even and odd rules)
  template <class CurveScheme>
  explicit With_sharp_rules(const CurveScheme& scheme) : m_sharp(scheme)
  {}

  Sharp_rules<Mesh, FT, Tagged> m_sharp;

private:
  template <class, class, class, bool>
  friend class With_sharp_rules;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_SHARP_RULES_H
