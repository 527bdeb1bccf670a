// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_RATIONAL_EIGENVALUES_H
#define CGAL_SUBDIV_ANALYSIS_RATIONAL_EIGENVALUES_H

/// \file rational_eigenvalues.h
/// Eigenvalues of an exact local subdivision matrix that are small rationals
/// (1/2, 1/4, 1/8 ...): guessed from Eigen's double spectrum by continued
/// fractions, then confirmed exactly by the rank of S - lambda I, so that the
/// reports and doc tables state them exactly.

#include <CGAL/Subdiv/analysis/curve_analysis.h>     // sort_eigenvalues, snap_eigenvalues
#include <CGAL/Subdiv/analysis/curve_local_matrix.h> // algebraic_multiplicity

#include <CGAL/Fraction_traits.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <complex>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

// the rational p/q (q <= max_q) nearest to x by continued fractions, if within tol
inline bool nearby_rational(double x, long max_q, double tol, long& p, long& q)
{
  if(!std::isfinite(x) || std::abs(x) > 1e6)
    return false;
  long h0 = 1, h1 = 0, k0 = 0, k1 = 1; // convergents h/k
  double r = x;
  for(int iteration = 0; iteration < 40; ++iteration) {
    const double a_double = std::floor(r);
    const long a = static_cast<long>(a_double);
    const long h2 = a * h0 + h1, k2 = a * k0 + k1;
    if(k2 > max_q)
      break;
    h1 = h0;
    k1 = k0;
    h0 = h2;
    k0 = k2;
    if(std::abs(x - static_cast<double>(h0) / static_cast<double>(k0)) < tol) {
      p = h0;
      q = k0;
      return true;
    }
    const double fraction = r - a_double;
    if(fraction < 1e-15)
      break;
    r = 1 / fraction;
  }
  return false;
}

template <class FT>
bool has_small_denominator(const FT& x)
{
  if constexpr(std::is_floating_point<FT>::value) {
    return false;
  } else {
    using Traits = CGAL::Fraction_traits<FT>;
    if constexpr(!std::is_same<typename Traits::Is_fraction, CGAL::Tag_true>::value) {
      return false;
    } else {
      typename Traits::Numerator_type num;
      typename Traits::Denominator_type den;
      typename Traits::Decompose()(x, num, den);
      typename Traits::Denominator_type bound(1);
      for(int i = 0; i < 40; ++i)
        bound = bound * typename Traits::Denominator_type(2);
      return CGAL::abs(den) < bound;
    }
  }
}

// snaps computed real eigenvalues to rationals confirmed exactly
template <class FT>
void confirm_rational_eigenvalues(const Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic>& S,
                                  std::vector<std::complex<double>>& values, std::vector<std::pair<FT, int>>& confirmed)
{
  if constexpr(std::is_floating_point<FT>::value) {
    return;
  } else {
    if(S.rows() > 64)
      return;
    std::vector<std::pair<long, long>> tried;
    for(const auto& value : std::vector<std::complex<double>>(values)) {
      long p = 0, q = 1;
      if(std::abs(value.imag()) > 1e-7 || !nearby_rational(value.real(), 4096, 1e-9, p, q))
        continue;
      if(std::find(tried.begin(), tried.end(), std::make_pair(p, q)) != tried.end())
        continue;
      tried.emplace_back(p, q);
      const FT lambda = FT(p) / FT(q);
      const int multiplicity = algebraic_multiplicity(S, lambda);
      if(multiplicity == 0)
        continue;
      confirmed.emplace_back(lambda, multiplicity);
      snap_eigenvalues(values, static_cast<double>(p) / static_cast<double>(q), multiplicity, 1e-4);
    }
    sort_eigenvalues(values);
  }
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_RATIONAL_EIGENVALUES_H
