// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_LOOP_WEIGHTS_H
#define CGAL_SUBDIV_MASKS_LOOP_WEIGHTS_H

#include <CGAL/Subdiv/masks/cosines.h>

#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivMasks
 * Loop's 1987 vertex weight
 * \f$ \beta_n = \frac1n \left( \frac58 - \left( \frac38 + \frac14 \cos\frac{2\pi}{n} \right)^2 \right) \f$,
 * what CGAL, OpenSubdiv and OpenMesh compute. Rational at n = 3, 4, 6 (3/16,
 * 31/256, 1/16); at other valences the weight is the double nearest to it, so
 * an exact kernel gets a correctly rounded weight there (the generated tables
 * say so).
 */
struct Loop_beta
{
  static std::string name() { return "Loop 1987"; }
  static bool is_exact(int n)
  {
    bool exact = false;
    internal::cos_two_pi_over<double>(n, &exact);
    return exact;
  }
  template <class FT>
  static FT beta(int n)
  {
    const FT inner = FT(3) / FT(8) + internal::cos_two_pi_over<FT>(n) / FT(4);
    return (FT(5) / FT(8) - inner * inner) / FT(n);
  }
};

/*!
 * \ingroup PkgSubdivMasks
 * Warren's rational vertex weight: \f$ \beta_n = \frac{3}{8n} \f$ for n > 3 and
 * \f$ \beta_3 = \frac{3}{16} \f$; exact at every valence. At valence 8 the
 * centre weight is 1 - 8 * 3/64 = 5/8 and each neighbour gets 3/64.
 */
struct Warren_beta
{
  static std::string name() { return "Warren"; }
  static bool is_exact(int) { return true; }
  template <class FT>
  static FT beta(int n)
  {
    return n == 3 ? FT(3) / FT(16) : FT(3) / FT(8 * n);
  }
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_LOOP_WEIGHTS_H
