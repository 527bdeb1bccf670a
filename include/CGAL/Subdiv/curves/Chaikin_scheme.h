// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_CHAIKIN_SCHEME_H
#define CGAL_SUBDIV_CHAIKIN_SCHEME_H

#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivCurveSchemes
 * Chaikin's corner cutting [Chaikin 1974]: every edge (P_i, P_i+1) is
 * replaced by the two points
 * \f$ Q_i = \frac34 P_i + \frac14 P_{i+1} \f$ and
 * \f$ R_i = \frac14 P_i + \frac34 P_{i+1} \f$.
 * The limit is the uniform quadratic B-spline of the control polygon (C1).
 *
 * \cgalModels `CurveSubdivisionScheme`
 */
template <class FT>
class Chaikin_scheme
{
public:
  using Number_type = FT;

  std::string name() const { return "Chaikin"; }
  bool is_interpolating() const { return false; }

  /// new point 2i: Q_i
  template <class Accumulator>
  void even_mask(Accumulator& acc) const
  {
    acc.add(0, FT(3) / FT(4));
    acc.add(1, FT(1) / FT(4));
  }

  /// new point 2i+1: R_i
  template <class Accumulator>
  void odd_mask(Accumulator& acc) const
  {
    acc.add(0, FT(1) / FT(4));
    acc.add(1, FT(3) / FT(4));
  }
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_CHAIKIN_SCHEME_H
