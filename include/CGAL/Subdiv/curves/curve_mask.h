// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_CURVE_MASK_H
#define CGAL_SUBDIV_CURVE_MASK_H

#include <CGAL/Subdiv/stencils/Stencil.h>

#include <algorithm>
#include <utility>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivCurveSchemes
 * The rules of a binary curve scheme, read from its masks through the
 * stencil recorder: `rule(scheme, 0)` is the even rule (new point 2i),
 * `rule(scheme, 1)` the odd rule (new point 2i+1); a term `(k, w)` means
 * that old point i+k contributes with weight w.
 */
template <class Scheme>
Stencil<int, typename Scheme::Number_type> rule(const Scheme& scheme, int parity)
{
  Stencil<int, typename Scheme::Number_type> stencil;
  if(parity == 0)
    scheme.even_mask(stencil);
  else
    scheme.odd_mask(stencil);
  return stencil;
}

/// smallest and largest offset that the rule of `parity` reads
template <class Scheme>
std::pair<int, int> rule_support(const Scheme& scheme, int parity)
{
  const auto stencil = rule(scheme, parity);
  std::pair<int, int> range(0, 0);
  bool first = true;
  for(const auto& term : stencil.terms()) {
    range.first = first ? term.first : (std::min)(range.first, term.first);
    range.second = first ? term.first : (std::max)(range.second, term.first);
    first = false;
  }
  return range;
}

/*!
 * true if the scheme is primal and symmetric: the even rule is symmetric
 * about the old point (w_k = w_-k) and the odd rule about the edge midpoint
 * (w_k = w_1-k). Such schemes keep an end point fixed when the polyline is
 * continued by point reflection, which is how `End_rule::keep_ends` treats them.
 */
template <class Scheme>
bool is_vertex_centred(const Scheme& scheme)
{
  const auto even = rule(scheme, 0);
  const auto odd = rule(scheme, 1);
  for(const auto& term : even.terms())
    if(even.weight(-term.first) != term.second)
      return false;
  for(const auto& term : odd.terms())
    if(odd.weight(1 - term.first) != term.second)
      return false;
  return true;
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_CURVE_MASK_H
