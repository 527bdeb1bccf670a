// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_CORNER_CUTTING_SCHEME_H
#define CGAL_SUBDIV_CORNER_CUTTING_SCHEME_H

#include <CGAL/Subdiv/errors.h>

#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivCurveSchemes
 * General corner cutting with two parameters 0 < a < b < 1 [de Rham 1956]:
 * every edge (x_i, x_i+1) is replaced by
 * \f$ x_{2i} = (1-a) x_i + a x_{i+1} \f$ and
 * \f$ x_{2i+1} = (1-b) x_i + b x_{i+1} \f$.
 * a = 1/4, b = 3/4 is Chaikin's scheme. The limit is C1 exactly when
 * b = a + 1/2 (see the generated smoothness table), C0 otherwise.
 *
 * \cgalModels `CurveSubdivisionScheme`
 */
template <class FT>
class Corner_cutting_scheme
{
public:
  using Number_type = FT;

  /// \throws Bad_input unless 0 < a < b < 1
  Corner_cutting_scheme(const FT& a, const FT& b) : m_a(a), m_b(b)
  {
    internal::require(FT(0) < a && a < b && b < FT(1), "corner cutting needs 0 < a < b < 1");
  }

  std::string name() const { return "corner cutting"; }
  bool is_interpolating() const { return false; }
  const FT& a() const { return m_a; }
  const FT& b() const { return m_b; }

  template <class Accumulator>
  void even_mask(Accumulator& acc) const
  {
    acc.add(0, FT(1) - m_a);
    acc.add(1, m_a);
  }

  template <class Accumulator>
  void odd_mask(Accumulator& acc) const
  {
    acc.add(0, FT(1) - m_b);
    acc.add(1, m_b);
  }

private:
  FT m_a;
  FT m_b;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_CORNER_CUTTING_SCHEME_H
