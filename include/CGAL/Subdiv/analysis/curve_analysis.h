// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_CURVE_ANALYSIS_H
#define CGAL_SUBDIV_ANALYSIS_CURVE_ANALYSIS_H

/// \file curve_analysis.h
/// Convergence and smoothness of binary curve schemes: local subdivision
/// matrix and its spectrum, limit mask, difference-scheme smoothness proof;
/// with the measurements on real polylines that check the predictions
/// (curve_measurements.h).

#include <CGAL/Subdiv/analysis/Analysis_status.h>
#include <CGAL/Subdiv/analysis/curve_local_matrix.h>
#include <CGAL/Subdiv/analysis/curve_measurements.h>
#include <CGAL/Subdiv/analysis/curve_symbol.h>
#include <CGAL/Subdiv/curves/Bezier_scheme.h>
#include <CGAL/Subdiv/curves/curve_mask.h>
#include <CGAL/Subdiv/curves/curve_parameters.h>
#include <CGAL/Subdiv/curves/refine_polyline.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * The smoothness reported for schemes whose limit is C^infinity (Bezier
 * subdivision: every piece is a polynomial). `Curve_analysis::smoothness`
 * holds this value and `holder_exponent` holds +infinity.
 */
constexpr int infinite_smoothness = (std::numeric_limits<int>::max)();

/*!
 * \ingroup PkgSubdivAnalysis
 * The analysis of a binary curve scheme, see `analyse_curve_scheme()`.
 */
template <class FT>
struct Curve_analysis
{
  /// `scheme.name()`
  std::string scheme;
  /// how the analysis ended; the spectrum and the verdicts mean something only
  /// with `Analysis_status::success`. `not_affine_invariant` (a row of `matrix`
  /// does not sum to 1) is checked first and kept; `no_convergence` says that
  /// Eigen's eigen-solver failed, and `eigenvalues` is then empty.
  Analysis_status status = Analysis_status::success;
  /// offsets of the invariant window of old points (`invariant_window()`)
  int window_first = 0, window_last = 0;
  /// local subdivision matrix over the window, exact in FT (`local_subdivision_matrix()`)
  Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic> matrix;
  /// eigenvalues of `matrix` (Eigen's solver, in double), sorted by modulus, largest
  /// first; ties by real part, then imaginary part, largest first. 1, 1/2, 1/4
  /// and 1/8 are confirmed exactly with their algebraic multiplicity (ranks of
  /// (S - lambda I)^k in FT) and reported exactly (for matrices up to 32 x 32).
  /// Empty if Eigen failed.
  std::vector<std::complex<double>> eigenvalues;
  /// lambda0 = 1 is simple and every other |lambda| < 1 (tolerance 1e-8)
  bool one_is_simple_and_dominant = false;
  /// also lambda1 = 1/2 is real and simple and |lambda2| < 1/2: necessary for C1
  bool c1_necessary = false;
  /// left eigenvector of 1, normalised to sum 1, over the window offsets
  /// window_first..window_last; solved exactly in FT. Empty if 1 is not simple.
  std::vector<FT> limit_mask;
  /// C0 proven by the difference-scheme method (smoothness >= 0)
  bool converges = false;
  /// largest k with C^k proven; -1 if convergence is not proven;
  /// `infinite_smoothness` for C^infinity
  int smoothness = -1;
  /// lower bound on the Holder regularity: smoothness + Holder exponent of the
  /// last proven derivative (cubic B-spline: 3)
  double holder_exponent = 0;
  /// asymptotic ratio of the distances between successive levels (see `measure_levels()`)
  double predicted_rate = 0;
};

namespace internal {

// by modulus, then real part, then imaginary part, largest first
inline void sort_eigenvalues(std::vector<std::complex<double>>& values)
{
  std::sort(values.begin(), values.end(), [](const std::complex<double>& x, const std::complex<double>& y) {
    const double ax = std::abs(x), ay = std::abs(y);
    if(std::abs(ax - ay) > 1e-12)
      return ax > ay;
    if(std::abs(x.real() - y.real()) > 1e-12)
      return x.real() > y.real();
    return x.imag() > y.imag();
  });
}

// the eigenvalues of S, sorted; empty, with `info` telling why, if Eigen's
// solver failed (the caller decides what a failure means for its analysis)
inline std::vector<std::complex<double>> sorted_eigenvalues(const Eigen::MatrixXd& S, Eigen::ComputationInfo& info)
{
  std::vector<std::complex<double>> values;
  info = Eigen::Success;
  if(S.rows() == 0)
    return values;
  Eigen::EigenSolver<Eigen::MatrixXd> solver(S, false);
  info = solver.info();
  if(info != Eigen::Success)
    return values;
  for(Eigen::Index i = 0; i < S.rows(); ++i)
    values.push_back(solver.eigenvalues()[i]);
  sort_eigenvalues(values);
  return values;
}

// the same, for callers that read a failure from the empty result
inline std::vector<std::complex<double>> sorted_eigenvalues(const Eigen::MatrixXd& S)
{
  Eigen::ComputationInfo info;
  return sorted_eigenvalues(S, info);
}

// affine invariance: every row of the local matrix sums to 1 (exactly for
// exact FT, to a relative 1e-12 for floating point), so that moving all old
// points moves the new ones alike
template <class FT>
bool rows_sum_to_one(const Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic>& S)
{
  const FT one(1);
  for(Eigen::Index r = 0; r < S.rows(); ++r) {
    FT sum(0);
    for(Eigen::Index c = 0; c < S.cols(); ++c)
      sum += S(r, c);
    if(!is_negligible(FT(sum - one), one))
      return false;
  }
  return true;
}

template <class FT>
Eigen::MatrixXd to_double_matrix(const Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic>& S)
{
  Eigen::MatrixXd D(S.rows(), S.cols());
  for(Eigen::Index r = 0; r < S.rows(); ++r)
    for(Eigen::Index c = 0; c < S.cols(); ++c)
      D(r, c) = CGAL::to_double(S(r, c));
  return D;
}

constexpr double eigenvalue_tolerance = 1e-8;

// replaces the `multiplicity` computed values nearest to the exact eigenvalue
// `target` (each within `tolerance` of it) by `target`
inline void snap_eigenvalues(std::vector<std::complex<double>>& values, double target, int multiplicity,
                             double tolerance)
{
  std::vector<bool> used(values.size(), false);
  for(; multiplicity > 0; --multiplicity) {
    std::size_t best = values.size();
    for(std::size_t i = 0; i < values.size(); ++i)
      if(!used[i] && (best == values.size() || std::abs(values[i] - target) < std::abs(values[best] - target)))
        best = i;
    if(best == values.size() || std::abs(values[best] - target) > tolerance)
      break;
    values[best] = std::complex<double>(target, 0.0);
    used[best] = true;
  }
}

// the spectral part of the analysis, shared by curve schemes and Bezier
// The eigenvalues 1, 1/2, 1/4 and 1/8 (those the verdicts and the predicted
// rate depend on) are confirmed exactly, with their algebraic multiplicity, by
// ranks of (S - lambda I)^k in FT, and then reported exactly: a defective
// eigenvalue (a Jordan block, as 1/4 of the four-point scheme) is otherwise
// only found to about sqrt(machine epsilon) by a double solver. Smaller powers
// of 1/2, and all eigenvalues of matrices larger than 32 x 32 (B-splines of
// degree > 32), are left as computed: exact ranks cost O(n^3) operations on
// growing rationals.
template <class FT>
void snap_dyadic_eigenvalues(const Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic>& S,
                             std::vector<std::complex<double>>& values, Eigen::Index max_rows = 32)
{
  if(S.rows() > max_rows)
    return;
  FT lambda(1);
  for(int j = 0; j <= 3; ++j, lambda = lambda / FT(2)) {
    const double target = std::ldexp(1.0, -j);
    bool near = false;
    for(const auto& value : values)
      near = near || std::abs(value - target) < 1e-4 * target;
    if(!near)
      continue;
    snap_eigenvalues(values, target, algebraic_multiplicity(S, lambda), 1e-4 * target);
  }
  sort_eigenvalues(values);
}

template <class FT>
void analyse_spectrum(Curve_analysis<FT>& result, bool linear_reproduction)
{
  if(!rows_sum_to_one(result.matrix))
    result.status = Analysis_status::not_affine_invariant;
  Eigen::ComputationInfo info;
  result.eigenvalues = sorted_eigenvalues(to_double_matrix(result.matrix), info);
  if(info != Eigen::Success && result.status == Analysis_status::success)
    result.status = Analysis_status::no_convergence;
  snap_dyadic_eigenvalues(result.matrix, result.eigenvalues);
  result.limit_mask = normalised_left_fixed_vector(result.matrix);
  const auto& ev = result.eigenvalues;
  const double tol = eigenvalue_tolerance;
  if(ev.empty())
    return;
  std::size_t ones = 0;
  bool others_inside = true;
  for(std::size_t i = 0; i < ev.size(); ++i) {
    if(std::abs(ev[i] - 1.0) < tol)
      ++ones;
    else if(std::abs(ev[i]) >= 1 - tol)
      others_inside = false;
  }
  result.one_is_simple_and_dominant = (ones == 1 && others_inside && std::abs(ev[0] - 1.0) < tol);
  result.c1_necessary = result.one_is_simple_and_dominant && ev.size() >= 2 && std::abs(ev[1] - 0.5) < tol &&
                        (ev.size() < 3 || std::abs(ev[2]) < 0.5 - tol);

  // predicted rate: drop one eigenvalue 1 and, for linear reproduction, one 1/2
  std::vector<std::complex<double>> rest = ev;
  const auto drop = [&rest](double value) {
    for(std::size_t i = 0; i < rest.size(); ++i)
      if(std::abs(rest[i] - value) < eigenvalue_tolerance) {
        rest.erase(rest.begin() + static_cast<long>(i));
        return;
      }
  };
  drop(1.0);
  if(linear_reproduction)
    drop(0.5);
  result.predicted_rate = 0;
  for(const auto& lambda : rest)
    result.predicted_rate = (std::max)(result.predicted_rate, std::abs(lambda));
}

} // namespace internal

/*!
 * \ingroup PkgSubdivAnalysis
 * analyses a binary curve scheme as in the convergence lectures and in
 * [Dyn, Levin, "Subdivision schemes in geometric modelling", Acta Numerica 2002]:
 *
 * - the local subdivision matrix S over the invariant window [L, R] of
 *   offsets around an old point (`local_subdivision_matrix()`), exact in FT,
 *   and its eigenvalues (Eigen, in double). Cubic B-spline:
 *   \f$ S = \frac18 [[4,4,0],[1,6,1],[0,4,4]] \f$, eigenvalues 1, 1/2, 1/4;
 * - the limit mask: the left eigenvector of 1 normalised to sum 1, solved
 *   exactly in FT: the limit of the point that old point i becomes is
 *   \f$ \sum_k \ell_k p_{i+k} \f$, k = L..R (cubic B-spline: (1, 4, 1)/6);
 * - smoothness by the difference-scheme method on the symbol a(z)
 *   (`difference_scheme_bounds()`): \f$ C^m \f$ is proven when
 *   \f$ (1+z)^{m+1} \f$ divides \f$ 2^m a(z) \f$ and
 *   \f$ \|S^L_{c_m}\|_\infty = \eta < 1 \f$ for some L <= `max_steps`, with
 *   Holder regularity at least \f$ m + \min(1, -\log_2(\eta)/L) \f$. The
 *   necessary conditions a(1) = 2 and a(-1) = 0 are checked first. A scheme
 *   whose contraction needs more than `max_steps` steps is reported with the
 *   smoothness that was proven (the method is inconclusive there, not negative);
 * - `predicted_rate`: the largest |lambda| once one eigenvalue 1 and, if the
 *   scheme reproduces linear functions in its own parametrisation
 *   (`reproduces_linear()`), one eigenvalue 1/2 are removed. It is the rate
 *   that `measure_levels()` observes for B-splines, Chaikin, corner cutting
 *   with b = a + 1/2 or b - a >= 1/2, four-point with w <= 1/16 (1/4 for the
 *   cubic B-spline, Chaikin and four-point w = 1/16, there approached slowly,
 *   like (k+1)/(4k), because 1/4 is a double eigenvalue with one eigenvector).
 *   The local matrix only sees the neighbourhood of the dyadic points; where
 *   the regularity is decided elsewhere (four-point with w > 1/16, whose
 *   subdominant pair is complex; corner cutting with a + 1/2 > b and b - a < 1/2)
 *   the observed rate is larger, between `predicted_rate` and about
 *   \f$ 2^{-holder\_exponent} \f$;
 * - `status`: `Analysis_status::not_affine_invariant` if a row of S does not
 *   sum to 1 (a custom scheme; every scheme of the package is affine
 *   invariant), `Analysis_status::no_convergence` if Eigen's solver failed
 *   (`eigenvalues` is then empty). The other fields are computed as always.
 *
 * With a floating-point `FT`, divisibility by (1+z) is decided with a tolerance
 * and fails for very high orders (B-splines of degree > 40): analyse with an
 * exact `FT` (`CGAL::Exact_rational`) to get exact masks and verdicts.
 *
 * \tparam Scheme a model of `CurveSubdivisionScheme`
 * \throws Bad_input unless 1 <= max_steps <= 24
 */
template <class Scheme>
Curve_analysis<typename Scheme::Number_type> analyse_curve_scheme(const Scheme& scheme, int max_steps = 16)
{
  using FT = typename Scheme::Number_type;
  internal::require(max_steps >= 1 && max_steps <= 24,
                    "max_steps must be between 1 and 24, got " + std::to_string(max_steps));
  Curve_analysis<FT> result;
  result.scheme = scheme.name();
  const std::pair<int, int> window = invariant_window(scheme);
  result.window_first = window.first;
  result.window_last = window.second;
  result.matrix = local_subdivision_matrix(scheme);
  internal::analyse_spectrum(result, reproduces_linear(scheme));

  // smoothness: necessary conditions, then the difference schemes
  const Laurent_polynomial<FT> a = subdivision_symbol(scheme);
  const FT one(1);
  const bool necessary =
    internal::is_negligible(FT(a.evaluate(one) - FT(2)), one) && internal::is_negligible(a.evaluate(FT(-1)), one);
  if(!necessary)
    return result;
  for(const auto& bound : difference_scheme_bounds(a, max_steps))
    if(bound.contractive) {
      result.smoothness = bound.order;
      result.holder_exponent = bound.holder;
    }
  result.converges = result.smoothness >= 0;
  return result;
}

/*!
 * \ingroup PkgSubdivAnalysis
 * analyses Bezier subdivision of degree d (de Casteljau's midpoint split)
 * at the start point of the curve: the matrix is the left-half split matrix,
 * row j = `split_mask(j)` for j = 0..d (window 0..d), lower triangular with
 * eigenvalues 1, 1/2, ..., 1/2^d; the limit mask is (1, 0, ..., 0) (the curve
 * starts at its first control point). The limit is a polynomial, C^infinity:
 * `smoothness` is `infinite_smoothness` and `holder_exponent` is +infinity.
 * `predicted_rate` (control polygon to curve) is 1/4 for d >= 2 and 0 for d = 1.
 */
template <class FT>
Curve_analysis<FT> analyse_bezier(const Bezier_scheme<FT>& scheme)
{
  const int d = scheme.degree();
  Curve_analysis<FT> result;
  result.scheme = scheme.name();
  result.window_first = 0;
  result.window_last = d;
  result.matrix.resize(d + 1, d + 1);
  for(int r = 0; r <= d; ++r)
    for(int c = 0; c <= d; ++c)
      result.matrix(r, c) = FT(0);
  struct Row_acc
  {
    Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic>& S;
    int row;
    void add(int source, const FT& w) { S(row, source) += w; }
  };
  for(int j = 0; j <= d; ++j) {
    Row_acc acc{result.matrix, j};
    scheme.split_mask(j, acc);
  }
  internal::analyse_spectrum(result, true);
  result.converges = true;
  result.smoothness = infinite_smoothness;
  result.holder_exponent = std::numeric_limits<double>::infinity();
  return result;
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_CURVE_ANALYSIS_H
