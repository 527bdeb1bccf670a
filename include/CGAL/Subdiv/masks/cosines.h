// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MASKS_COSINES_H
#define CGAL_SUBDIV_MASKS_COSINES_H

/// \file cosines.h
/// The cosines of the masks' transcendental weights, with whether they are
/// exact (rational): the only place where pi enters a weight.

#include <CGAL/number_type_config.h> // CGAL_PI

#include <cmath>
#include <numeric>

namespace CGAL {
namespace Subdiv {
namespace internal {

// cos(2 pi / n): rational (and so exact in any FT) for n = 1, 2, 3, 4, 6;
// otherwise the double nearest to std::cos(2 * CGAL_PI / n), as CGAL,
// OpenSubdiv and OpenMesh compute it, converted to FT (Loop's and Kobbelt's
// sqrt3 weights, so that the results agree with theirs bit for bit).
template <class FT>
FT cos_two_pi_over(int n, bool* exact = nullptr)
{
  bool rational = true;
  FT value;
  switch(n) {
    case 1:
      value = FT(1);
      break;
    case 2:
      value = FT(-1);
      break;
    case 3:
      value = FT(-1) / FT(2);
      break;
    case 4:
      value = FT(0);
      break;
    case 6:
      value = FT(1) / FT(2);
      break;
    default:
      rational = false;
      value = FT(std::cos(2 * CGAL_PI / n));
  }
  if(exact)
    *exact = rational;
  return value;
}

// cos(2 pi m / n), n > 0. With d = n / gcd(m, n), the value is rational
// exactly when d is 1, 2, 3, 4 or 6 (then m / gcd is +-1 modulo d and the
// value is cos(2 pi / d)); otherwise it is the double nearest to it, computed
// in long double (the weights of Doo-Sabin and the modified butterfly). m is
// first reduced to 0 <= m <= n / 2, so that cos(2 pi m / n) and
// cos(2 pi (n - m) / n) are the same number.
template <class FT>
FT cos_two_pi_fraction(int m, int n, bool* exact = nullptr)
{
  m %= n;
  if(m < 0)
    m += n;
  if(2 * m > n)
    m = n - m;
  const int d = n / std::gcd(m, n); // gcd(0, n) = n
  const bool rational = d == 1 || d == 2 || d == 3 || d == 4 || d == 6;
  if(exact)
    *exact = rational;
  if(rational)
    return cos_two_pi_over<FT>(d);
  const long double pi = 3.141592653589793238462643383279502884L;
  return FT(static_cast<double>(std::cos(2 * pi * static_cast<long double>(m) / static_cast<long double>(n))));
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MASKS_COSINES_H
