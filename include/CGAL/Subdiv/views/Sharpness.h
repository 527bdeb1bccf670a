// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_VIEWS_SHARPNESS_H
#define CGAL_SUBDIV_VIEWS_SHARPNESS_H

/// \file Sharpness.h
/// Semi-sharp creases as OpenSubdiv defines them (`Sdc::Crease`, after DeRose,
/// Kass and Truong 1998): the sharpness values, how they decay from a level
/// to the next, which vertex rule they select and how two rules are blended
/// when a vertex's rule changes between levels. Written once; the views
/// (`Sharp_level`) apply it, the masks only read the rules it selects.

#include <CGAL/Subdiv/views/Vertex_view.h>

#include <type_traits>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivMasks
 * How the sharpness of a semi-sharp edge decays from a level to the next
 * (OpenSubdiv's `Sdc::Options::CreasingMethod`).
 */
enum class Crease_method {
  /// every edge loses 1 per level (DeRose, Kass and Truong 1998; OpenSubdiv's
  /// `CREASE_UNIFORM`, the default)
  uniform,
  /// each half of an edge takes 3/4 of its sharpness and 1/4 of the mean of
  /// the other semi-sharp edges at its end, then loses 1, so that sharpness
  /// varies smoothly along a crease (OpenSubdiv's `CREASE_CHAIKIN`)
  chaikin
};

namespace internal {

/*
 * The number type sharpness values are computed in: `float` with an inexact
 * kernel, as OpenSubdiv stores and decays them (a sharpness such as 0.7 is
 * not a float exactly, and rounding it otherwise moves the refined points by
 * about 1e-10), the kernel's own number type with an exact one (rational
 * sharpness values then refine exactly).
 */
template <class FT>
using Sharpness_number = std::conditional_t<std::is_floating_point<FT>::value, float, FT>;

/// the creasing rules over sharpness values of type `S` (`Sharpness_number`)
template <class S>
struct Crease_rules
{
  /// sharpness 10 and above is infinitely sharp (OpenSubdiv's SHARPNESS_INFINITE)
  static S infinite() { return S(10); }
  static bool is_sharp(const S& s) { return s > S(0); }
  static bool is_infinite(const S& s) { return !(s < infinite()); }
  static bool is_semi_sharp(const S& s) { return is_sharp(s) && s < infinite(); }

  /// the sharpness of a vertex, or of an edge under the uniform method, one level down
  static S decrement(const S& s)
  {
    if(!is_sharp(s))
      return S(0);
    if(is_infinite(s))
      return infinite();
    return s > S(1) ? S(s - S(1)) : S(0);
  }

  /*
   * The sharpness of the half of an edge of sharpness `s` at one of its
   * ends, one level down; `semi_sum` and `semi_count` are the sum and the
   * number of the semi-sharp edges at that end (the edge included), and
   * `valence` its number of edges.
   */
  static S child_at_end(Crease_method method, const S& s, const S& semi_sum, int semi_count, int valence)
  {
    if(method == Crease_method::uniform || valence < 2)
      return decrement(s);
    if(!is_sharp(s))
      return S(0);
    if(is_infinite(s))
      return infinite();
    S value = s;
    if(semi_count > 1) {
      const S others = (semi_sum - s) / S(semi_count - 1);
      value = S(3) / S(4) * s + S(1) / S(4) * others;
    }
    value = value - S(1);
    return is_sharp(value) ? value : S(0);
  }

  /// the rule of a vertex of sharpness `vertex` with `sharp_edges` sharp edges
  static Vertex_rule rule(const S& vertex, int sharp_edges)
  {
    if(is_sharp(vertex) || sharp_edges > 2)
      return Vertex_rule::corner;
    return sharp_edges == 2 ? Vertex_rule::crease : sharp_edges == 1 ? Vertex_rule::dart : Vertex_rule::smooth;
  }

  /*
   * The weight of the parent's rule when a vertex's rule changes between
   * levels: the mean of the sharpness values (of the vertex and of its edges)
   * that decay to zero in this step, at most 1. `add(parent, child)` is
   * called for the vertex and for each edge by `for_each_pair`.
   */
  template <class ForEachPair>
  static S transition_weight(const ForEachPair& for_each_pair)
  {
    S sum(0);
    int count = 0;
    for_each_pair([&](const S& parent, const S& child) {
      if(is_sharp(parent) && !is_sharp(child)) {
        sum = sum + parent;
        ++count;
      }
    });
    if(count == 0)
      return S(0);
    const S mean = sum / S(count);
    return mean > S(1) ? S(1) : mean;
  }
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_VIEWS_SHARPNESS_H
