// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_CURVE_SYMBOL_H
#define CGAL_SUBDIV_ANALYSIS_CURVE_SYMBOL_H

/// \file curve_symbol.h
/// The symbol (Laurent polynomial) of a binary curve scheme and the
/// difference-scheme test of convergence and smoothness [Dyn, Levin 2002].

#include <CGAL/Subdiv/curves/curve_mask.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * A Laurent polynomial \f$ p(z) = \sum_{e} p_e z^e \f$ with coefficients in
 * `FT`: `coefficients[i]` is the coefficient of \f$ z^{lowest + i} \f$.
 * Equality is coefficient-wise after trimming zeros at both ends, so it is
 * exact for exact number types.
 */
template <class FT>
struct Laurent_polynomial
{
  int lowest = 0;
  std::vector<FT> coefficients;

  /// exponent of the last stored coefficient (lowest - 1 for the zero polynomial)
  int highest() const { return lowest + static_cast<int>(coefficients.size()) - 1; }

  /// coefficient of z^e, zero outside the stored range
  FT coefficient(int e) const
  {
    if(e < lowest || e > highest())
      return FT(0);
    return coefficients[static_cast<std::size_t>(e - lowest)];
  }

  /// adds w z^e
  void add(int e, const FT& w)
  {
    if(coefficients.empty()) {
      lowest = e;
      coefficients.push_back(w);
      return;
    }
    if(e < lowest) {
      coefficients.insert(coefficients.begin(), static_cast<std::size_t>(lowest - e), FT(0));
      lowest = e;
    }
    if(e > highest())
      coefficients.resize(static_cast<std::size_t>(e - lowest + 1), FT(0));
    coefficients[static_cast<std::size_t>(e - lowest)] += w;
  }

  /// removes zero coefficients at both ends
  void trim()
  {
    std::size_t first = 0;
    while(first < coefficients.size() && coefficients[first] == FT(0))
      ++first;
    std::size_t end = coefficients.size();
    while(end > first && coefficients[end - 1] == FT(0))
      --end;
    coefficients =
      std::vector<FT>(coefficients.begin() + static_cast<long>(first), coefficients.begin() + static_cast<long>(end));
    lowest = coefficients.empty() ? 0 : lowest + static_cast<int>(first);
  }

  /// p(x)
  FT evaluate(const FT& x) const
  {
    // Horner on the polynomial part, then the factor x^lowest
    FT value(0);
    for(std::size_t i = coefficients.size(); i-- > 0;)
      value = value * x + coefficients[i];
    FT power(1);
    for(int e = 0; e < (lowest < 0 ? -lowest : lowest); ++e)
      power = power * x;
    return lowest < 0 ? FT(value / power) : FT(value * power);
  }

  friend bool operator==(const Laurent_polynomial& p, const Laurent_polynomial& q)
  {
    Laurent_polynomial a = p, b = q;
    a.trim();
    b.trim();
    return a.lowest == b.lowest && a.coefficients == b.coefficients;
  }
  friend bool operator!=(const Laurent_polynomial& p, const Laurent_polynomial& q) { return !(p == q); }
};

/*!
 * \ingroup PkgSubdivAnalysis
 * The symbol \f$ a(z) = \sum_j a_j z^j \f$ of a binary curve scheme, where
 * \f$ p'_j = \sum_i a_{j-2i} p_i \f$. It is read from the masks through the
 * accumulator interface: an even-rule term (k, w) (new point 2i gets w p_{i+k})
 * adds w to \f$ a_{-2k} \f$, an odd-rule term adds w to \f$ a_{1-2k} \f$.
 * For the cubic B-spline \f$ a(z) = (1+z)^4 / (8 z^2) \f$.
 */
template <class Scheme>
Laurent_polynomial<typename Scheme::Number_type> subdivision_symbol(const Scheme& scheme)
{
  using FT = typename Scheme::Number_type;
  struct Symbol_acc
  {
    Laurent_polynomial<FT>& symbol;
    int parity;
    void add(int k, const FT& w) { symbol.add(parity - 2 * k, w); }
  };
  Laurent_polynomial<FT> symbol;
  Symbol_acc even{symbol, 0};
  scheme.even_mask(even);
  Symbol_acc odd{symbol, 1};
  scheme.odd_mask(odd);
  symbol.trim();
  return symbol;
}

namespace internal {

template <class FT>
FT absolute(const FT& x)
{
  return x < FT(0) ? FT(-x) : x;
}

// zero test: exact for exact types, relative to `scale` for floating point ones
template <class FT>
bool is_negligible(const FT& x, const FT& scale)
{
  if constexpr(std::is_floating_point<FT>::value)
    return std::abs(x) <= 1e-12 * (scale > FT(1) ? scale : FT(1));
  else
    return x == FT(0);
}

} // namespace internal

/*!
 * \ingroup PkgSubdivAnalysis
 * divides `p` by \f$ (1+z) \f$ (synthetic division). Returns false, and leaves
 * `quotient` unspecified, if the remainder \f$ p(-1) \f$ is not zero: exactly
 * zero for exact `FT`, within a relative tolerance of 1e-12 for floating-point `FT`.
 */
template <class FT>
bool divide_by_one_plus_z(const Laurent_polynomial<FT>& p, Laurent_polynomial<FT>& quotient)
{
  Laurent_polynomial<FT> a = p;
  a.trim();
  if(a.coefficients.empty()) { // the zero polynomial
    quotient = a;
    return true;
  }
  if(a.coefficients.size() == 1) // c z^e with c != 0
    return false;
  const std::size_t n = a.coefficients.size() - 1; // degree of the polynomial part
  std::vector<FT> q(n, FT(0));
  FT scale(0);
  for(const FT& c : a.coefficients)
    scale += internal::absolute(c);
  // a_0 + a_1 z + ... + a_n z^n = (1 + z)(q_0 + ... + q_{n-1} z^{n-1}) + r
  q[n - 1] = a.coefficients[n];
  for(std::size_t k = n - 1; k >= 1; --k)
    q[k - 1] = a.coefficients[k] - q[k];
  const FT remainder = a.coefficients[0] - q[0];
  if(!internal::is_negligible(remainder, scale))
    return false;
  quotient.lowest = a.lowest;
  quotient.coefficients = q;
  quotient.trim();
  return true;
}

/*!
 * \ingroup PkgSubdivAnalysis
 * \f$ \| S_c^L \|_\infty \f$: the infinity norm of L steps of the scheme with
 * symbol `c`, computed in double. The L-step symbol is
 * \f$ c^{[L]}(z) = c(z) c(z^2) \cdots c(z^{2^{L-1}}) \f$ and
 * \f$ \| S_c^L \|_\infty = \max_{r} \sum_j | c^{[L]}_{r + 2^L j} | \f$, the
 * maximum over the residues r modulo \f$ 2^L \f$ [Dyn, Levin 2002, sec. 4].
 * \throws Bad_input unless 1 <= L <= 24
 */
template <class FT>
double iterated_scheme_norm(const Laurent_polynomial<FT>& c, int L)
{
  internal::require(L >= 1 && L <= 24, "the number of steps L must be between 1 and 24, got " + std::to_string(L));
  std::vector<double> base;
  for(const FT& x : c.coefficients)
    base.push_back(CGAL::to_double(x));
  if(base.empty())
    return 0;
  std::vector<double> product = base, next;
  std::size_t stride = 1;
  for(int l = 1; l < L; ++l) {
    stride *= 2;
    next.assign((product.size() - 1) + (base.size() - 1) * stride + 1, 0.0);
    for(std::size_t k = 0; k < base.size(); ++k) // k outside: sequential memory access
      if(base[k] != 0.0)
        for(std::size_t i = 0; i < product.size(); ++i)
          next[i + k * stride] += product[i] * base[k];
    product.swap(next);
  }
  const std::size_t period = stride * 2; // 2^L
  std::vector<double> sums(period, 0.0);
  for(std::size_t i = 0; i < product.size(); ++i)
    sums[i % period] += std::abs(product[i]);
  return *std::max_element(sums.begin(), sums.end());
}

/*!
 * \ingroup PkgSubdivAnalysis
 * One line of the difference-scheme analysis: for the order m, the symbol
 * \f$ c_m(z) = 2^m a(z) / (1+z)^{m+1} \f$ and the best contraction found,
 * \f$ \eta = \| S_{c_m}^L \|_\infty \f$.
 */
template <class FT>
struct Difference_scheme_bound
{
  int order = 0;                 ///< m
  Laurent_polynomial<FT> symbol; ///< c_m, exact in FT
  int steps = 0;                 ///< the L giving the best Holder bound (0 if none contracts)
  double norm = 0;               ///< eta at that L (or the smallest eta found, if none is < 1)
  bool contractive = false;      ///< eta < 1 for some L <= Lmax: C^m is proven
  double holder = 0;             ///< m + min(1, -log2(eta) / L) if contractive
};

/*!
 * \ingroup PkgSubdivAnalysis
 * The difference-scheme method of Dyn and Levin ["Subdivision schemes in
 * geometric modelling", Acta Numerica 2002, theorems 4.6 and 4.11]: the scheme
 * with symbol a is \f$ C^m \f$ if \f$ (1+z)^{m+1} \f$ divides \f$ 2^m a(z) \f$
 * and \f$ \| S_{c_m}^L \|_\infty < 1 \f$ for some L, where
 * \f$ c_m = 2^m a / (1+z)^{m+1} \f$; then the m-th derivative is Holder
 * continuous with exponent \f$ \min(1, -\log_2(\eta) / L) \f$.
 *
 * Returns one line per m = 0, 1, ... for which the division is exact, up to
 * `max_order` (the loop stops at the first m where \f$ (1+z)^{m+1} \f$ does not
 * divide). Norms are tried for L = 1..`max_steps`, as long as the L-step
 * symbol has at most 2^23 coefficients; a C^m that needs more steps is
 * reported as not proven (the method is then inconclusive, not negative).
 * \throws Bad_input unless 1 <= max_steps <= 24 and max_order >= 0
 */
template <class FT>
std::vector<Difference_scheme_bound<FT>> difference_scheme_bounds(const Laurent_polynomial<FT>& symbol,
                                                                  int max_steps = 16, int max_order = 64)
{
  internal::require(max_steps >= 1 && max_steps <= 24,
                    "max_steps must be between 1 and 24, got " + std::to_string(max_steps));
  internal::require(max_order >= 0, "max_order must not be negative");
  std::vector<Difference_scheme_bound<FT>> bounds;
  Laurent_polynomial<FT> scaled = symbol; // 2^m a / (1+z)^m
  for(int m = 0; m <= max_order; ++m) {
    Difference_scheme_bound<FT> bound;
    bound.order = m;
    if(!divide_by_one_plus_z(scaled, bound.symbol))
      break;
    bound.norm = std::numeric_limits<double>::infinity();
    double best_exponent = -1;
    for(int L = 1; L <= max_steps; ++L) {
      // the L-step symbol has (length - 1)(2^L - 1) + 1 coefficients: at most 2^23
      if(static_cast<double>(bound.symbol.coefficients.size() - 1) * (std::ldexp(1.0, L) - 1) + 1 > std::ldexp(1.0, 23))
        break;
      const double eta = iterated_scheme_norm(bound.symbol, L);
      if(eta < 1) {
        const double exponent = eta > 0 ? (std::min)(1.0, -std::log2(eta) / L) : 1.0;
        if(exponent > best_exponent) {
          best_exponent = exponent;
          bound.steps = L;
          bound.norm = eta;
        }
      } else if(!(best_exponent >= 0) && eta < bound.norm)
        bound.norm = eta;
      if(best_exponent >= 1 - 1e-12)
        break; // cannot do better than a Lipschitz bound (up to rounding of the norm)
    }
    bound.contractive = best_exponent >= 0;
    bound.holder = bound.contractive ? m + best_exponent : 0;
    bounds.push_back(bound);
    // next order: 2 c_m (1+z)^0 = 2^(m+1) a / (1+z)^(m+1)
    scaled = bound.symbol;
    for(FT& x : scaled.coefficients)
      x = FT(2) * x;
  }
  return bounds;
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_CURVE_SYMBOL_H
