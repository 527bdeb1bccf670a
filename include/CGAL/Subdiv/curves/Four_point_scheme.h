// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_FOUR_POINT_SCHEME_H
#define CGAL_SUBDIV_FOUR_POINT_SCHEME_H

#include <CGAL/Subdiv/errors.h>

#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivCurveSchemes
 * The interpolating four-point scheme with tension w [Dyn, Levin, Gregory 1987]:
 * old points are kept, \f$ p_{2i} = p_i \f$, and every edge gets
 * \f$ p_{2i+1} = (w + \frac12)(p_i + p_{i+1}) - w (p_{i-1} + p_{i+2}) \f$.
 * w = 1/16 gives the weights -1/16, 9/16, 9/16, -1/16 (cubic precision);
 * w = 0 is linear interpolation.
 *
 * \cgalModels `CurveSubdivisionScheme`
 */
template <class FT>
class Four_point_scheme
{
public:
  using Number_type = FT;

  /// \throws Bad_input unless 0 <= w < 1/4 (the range of the convergence theorem)
  explicit Four_point_scheme(const FT& w = FT(1) / FT(16)) : m_w(w)
  {
    internal::require(FT(0) <= w && w < FT(1) / FT(4), "four-point tension w must satisfy 0 <= w < 1/4");
  }

  std::string name() const { return "four-point"; }
  bool is_interpolating() const { return true; }
  const FT& w() const { return m_w; }

  template <class Accumulator>
  void even_mask(Accumulator& acc) const
  {
    acc.add(0, FT(1));
  }

  template <class Accumulator>
  void odd_mask(Accumulator& acc) const
  {
    const FT inner = m_w + FT(1) / FT(2);
    acc.add(-1, -m_w);
    acc.add(0, inner);
    acc.add(1, inner);
    acc.add(2, -m_w);
  }

private:
  FT m_w;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_FOUR_POINT_SCHEME_H
