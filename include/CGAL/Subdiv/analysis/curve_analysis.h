// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_CURVE_ANALYSIS_H
#define CGAL_SUBDIV_ANALYSIS_CURVE_ANALYSIS_H

/// \file curve_analysis.h
/// Convergence and smoothness of binary curve schemes: local subdivision
/// matrix and its spectrum, limit mask, difference-scheme smoothness proof,
/// and measurements on real polylines that check the predictions.

#include <CGAL/Subdiv/analysis/Analysis_status.h>
#include <CGAL/Subdiv/analysis/curve_local_matrix.h>
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
                             std::vector<std::complex<double>>& values)
{
  if(S.rows() > 32)
    return;
  FT lambda(1);
  for(int j = 0; j <= 3; ++j, lambda = lambda / FT(2)) {
    const double target = std::ldexp(1.0, -j);
    bool near = false;
    for(const auto& value : values)
      near = near || std::abs(value - target) < 1e-4 * target;
    if(!near)
      continue;
    int multiplicity = algebraic_multiplicity(S, lambda);
    // replace the `multiplicity` computed values nearest to the exact one
    std::vector<bool> used(values.size(), false);
    for(; multiplicity > 0; --multiplicity) {
      std::size_t best = values.size();
      for(std::size_t i = 0; i < values.size(); ++i)
        if(!used[i] && (best == values.size() || std::abs(values[i] - target) < std::abs(values[best] - target)))
          best = i;
      if(best == values.size() || std::abs(values[best] - target) > 1e-4 * target)
        break;
      values[best] = std::complex<double>(target, 0.0);
      used[best] = true;
    }
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

/*!
 * \ingroup PkgSubdivAnalysis
 * One line of `measure_levels()`.
 */
struct Level_measurement
{
  int level = 0;            ///< the level k (1 for the first refinement)
  std::size_t points = 0;   ///< number of points of level k
  double distance = 0;      ///< sup distance between the curves of levels k-1 and k
  double ratio = 0;         ///< distance / distance of the previous level (NaN for the first)
  double max_curvature = 0; ///< largest `discrete_curvature()` of level k
};

namespace internal {

using Double_point = std::array<double, 3>;

template <class Point>
std::vector<Double_point> to_double_points(const std::vector<Point>& points)
{
  std::vector<Double_point> result;
  result.reserve(points.size());
  for(const Point& p : points) {
    Double_point q = {0, 0, 0};
    for(int d = 0; d < p.dimension() && d < 3; ++d)
      q[static_cast<std::size_t>(d)] = CGAL::to_double(p.cartesian(d));
    result.push_back(q);
  }
  return result;
}

inline double distance(const Double_point& p, const Double_point& q)
{
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

// The piecewise-linear curve through points[first..last] (or all points,
// periodically) where point i sits at index position i; evaluated at a real
// index position u. Returns false outside the curve.
struct Index_polyline
{
  const std::vector<Double_point>& points;
  bool closed;
  long first, last;

  bool at(double u, Double_point& result) const
  {
    const double n = static_cast<double>(points.size());
    if(closed)
      u -= n * std::floor(u / n);
    else if(u < static_cast<double>(first) - 1e-9 || u > static_cast<double>(last) + 1e-9)
      return false;
    long i = static_cast<long>(std::floor(u));
    if(!closed)
      i = (std::max)(first, (std::min)(i, last - 1));
    double s = u - static_cast<double>(i);
    if(!closed && first == last) {
      result = points[static_cast<std::size_t>(first)];
      return true;
    }
    const Double_point& p = points[static_cast<std::size_t>(i) % points.size()];
    const Double_point& q = points[static_cast<std::size_t>(i + 1) % points.size()];
    for(std::size_t d = 0; d < 3; ++d)
      result[d] = (1 - s) * p[d] + s * q[d];
    return true;
  }
};

// sup distance between the piecewise-linear curves of two successive levels,
// in the scheme's parametrisation: old point i at parameter i + sigma, new
// point j (position q = j + first_position) at (q + sigma) / 2. Both curves are
// linear between their points, so the sup is reached at a point of either.
inline double level_distance(const std::vector<Double_point>& old_points, const std::vector<Double_point>& new_points,
                             bool closed, long first_position, long skip_ends, double sigma)
{
  const Index_polyline old_curve{old_points, closed, 0, static_cast<long>(old_points.size()) - 1};
  const Index_polyline new_curve{new_points, closed, skip_ends, static_cast<long>(new_points.size()) - 1 - skip_ends};
  double result = 0;
  Double_point p;
  // at the old points: t = i + sigma, new index position 2t - sigma - first
  for(std::size_t i = 0; i < old_points.size(); ++i) {
    const double t = static_cast<double>(i) + sigma;
    if(new_curve.at(2 * t - sigma - static_cast<double>(first_position), p))
      result = (std::max)(result, distance(p, old_points[i]));
  }
  // at the new points: t = (q + sigma) / 2, old index position t - sigma
  for(long j = new_curve.first; j <= new_curve.last; ++j) {
    const double t = (static_cast<double>(j + first_position) + sigma) / 2;
    if(old_curve.at(t - sigma, p))
      result = (std::max)(result, distance(p, new_points[static_cast<std::size_t>(j)]));
  }
  return result;
}

} // namespace internal

/*!
 * \ingroup PkgSubdivAnalysis
 * Menger curvature \f$ \kappa = 4 A / (a b c) \f$ of every point with two
 * neighbours, where A is the area of the triangle formed with its two
 * neighbours and a, b, c its side lengths (the inverse radius of the circle
 * through the three points). Open polylines get 0 at their two end points;
 * coincident neighbours give 0. Computed in double.
 * \tparam PointRange a range of `Point_2` or `Point_3` of any kernel
 * \param points the polyline
 * \param np optional named parameters: `closed` (default false).
 * \throws Bad_input for a closed polyline of fewer than 3 points
 */
template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
std::vector<double> discrete_curvature(const PointRange& points,
                                       const NamedParameters& np = parameters::default_values())
{
  const bool closed = internal::read_curve_parameters(np).closed;
  const std::vector<internal::Double_point> p = internal::to_double_points(internal::to_point_vector(points));
  internal::require(!closed || p.size() >= 3,
                    "a closed polyline needs at least 3 points, got " + std::to_string(p.size()));
  const std::size_t n = p.size();
  std::vector<double> curvature(n, 0.0);
  if(n < 3)
    return curvature;
  for(std::size_t i = 0; i < n; ++i) {
    if(!closed && (i == 0 || i + 1 == n))
      continue;
    const internal::Double_point& a = p[(i + n - 1) % n];
    const internal::Double_point& b = p[i];
    const internal::Double_point& c = p[(i + 1) % n];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - b[0], c[1] - b[1], c[2] - b[2]};
    const double cross[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double twice_area = std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
    const double lengths = internal::distance(a, b) * internal::distance(b, c) * internal::distance(a, c);
    curvature[i] = lengths > 0 ? 2 * twice_area / lengths : 0.0;
  }
  return curvature;
}

/*!
 * \ingroup PkgSubdivAnalysis
 * refines `points` level by level with `refine_polyline()` (one call per
 * level, `number_of_iterations` levels) and measures, for every level
 * k = 1, 2, ..., how far it moved from level k-1.
 *
 * The distance is the sup distance \f$ \| f_k - f_{k-1} \|_\infty \f$ between
 * the piecewise-linear curves of the two levels in the scheme's own
 * parametrisation: point i of level k-1 sits at parameter
 * \f$ (i + \sigma) 2^{-(k-1)} \f$ and point j of level k at
 * \f$ (j + \sigma) 2^{-k} \f$, with \f$ \sigma \f$ = `parametric_shift(scheme)`
 * (open polylines: j counted from `Polyline_level::first_position()`; end
 * points copied by `End_rule::keep_ends` and parameters outside either curve
 * are left out). Since both curves are linear between their points, the sup
 * is reached at a point of one of them. Comparing only the new points with
 * the old curve would not do: Chaikin's new points lie on the old polygon.
 *
 * For a smooth limit, `ratio` tends to `Curve_analysis::predicted_rate`
 * (1/4 for the cubic B-spline, Chaikin and the four-point scheme). The linear
 * B-spline (degree 1) and w = 0 four-point do not move the curve: distance 0,
 * ratio NaN.
 *
 * \tparam PointRange a range of `Point_2` or `Point_3` of any kernel whose
 *         `FT` is the scheme's `Number_type`
 * \param points the control polygon of level 0, left unchanged
 * \param scheme the rules of the scheme, with their options
 * \param np optional named parameters: `number_of_iterations`, `closed`,
 *   `end_rule` and `max_output_points`, with the defaults of `refine_polyline()`.
 * \throws Bad_input as `refine_polyline()` does.
 */
template <class PointRange, class Scheme, class NamedParameters = parameters::Default_named_parameters>
std::vector<Level_measurement> measure_levels(const PointRange& points, const Scheme& scheme,
                                              const NamedParameters& np = parameters::default_values())
{
  using Point = internal::Range_point<PointRange>;
  const internal::Curve_parameters p = internal::read_curve_parameters(np);
  std::vector<Point> current = internal::to_point_vector(points);
  internal::check_polyline(current, p.closed);
  internal::check_output_size(current.size(), p.levels, p.max_output_points);
  const double sigma = CGAL::to_double(parametric_shift(scheme));
  const bool copies_ends = !p.closed && p.end_rule == End_rule::keep_ends && !is_vertex_centred(scheme);
  const auto one_level = parameters::number_of_iterations(1).closed(p.closed).end_rule(p.end_rule);

  std::vector<Level_measurement> result;
  std::vector<internal::Double_point> current_d = internal::to_double_points(current);
  for(int level = 1; level <= p.levels; ++level) {
    const internal::Polyline_level<Scheme> plan(scheme, current.size(), p.closed, p.end_rule);
    std::vector<Point> next = refine_polyline(current, scheme, one_level);
    std::vector<internal::Double_point> next_d = internal::to_double_points(next);
    Level_measurement m;
    m.level = level;
    m.points = next.size();
    m.distance =
      internal::level_distance(current_d, next_d, p.closed, plan.first_position(), copies_ends ? 1 : 0, sigma);
    m.ratio = result.empty() ? std::numeric_limits<double>::quiet_NaN() : m.distance / result.back().distance;
    const std::vector<double> curvature = discrete_curvature(next, parameters::closed(p.closed));
    m.max_curvature = curvature.empty() ? 0.0 : *std::max_element(curvature.begin(), curvature.end());
    result.push_back(m);
    current.swap(next);
    current_d.swap(next_d);
  }
  return result;
}

/*!
 * \ingroup PkgSubdivAnalysis
 * follows, with the real host, the point that old point `index` of a closed
 * polygon becomes: its even child 2 index, then that point's even child, for
 * `levels` levels, and returns where it is. It checks a limit mask against
 * refinement rather than against the matrix: the result tends to
 * \f$ \sum_k \ell_k p_{index+k} \f$ (`Curve_analysis::limit_mask`), with an
 * error of order \f$ |\lambda_1|^{levels} \f$.
 *
 * To keep the cost constant, every level keeps only the old points at offsets
 * L..R (`invariant_window()`) around the tracked point, refines them as an
 * open polyline with `End_rule::shrink` by `refine_polyline()`, and finds the
 * tracked point and its new window by `Polyline_level::first_position()`.
 *
 * \tparam PointRange a range of `Point_2` or `Point_3` of any kernel whose
 *         `FT` is the scheme's `Number_type`
 * \throws Bad_input for fewer than 3 points, a non-finite point,
 *         `index` out of range or negative `levels`.
 */
template <class PointRange, class Scheme>
internal::Range_point<PointRange> track_limit_point(const PointRange& polygon, const Scheme& scheme, std::size_t index,
                                                    int levels)
{
  using Point = internal::Range_point<PointRange>;
  const std::vector<Point> closed_polygon = internal::to_point_vector(polygon);
  internal::check_polyline(closed_polygon, true);
  internal::require(index < closed_polygon.size(), "index " + std::to_string(index) + " is out of range for " +
                                                     std::to_string(closed_polygon.size()) + " points");
  internal::require(levels >= 0, "the number of levels must not be negative, got " + std::to_string(levels));
  const std::pair<int, int> window = invariant_window(scheme);
  const long L = window.first, R = window.second;
  const long n = static_cast<long>(closed_polygon.size());
  std::vector<Point> crop; // crop[k] = point at offset L + k from the tracked one
  for(long k = L; k <= R; ++k)
    crop.push_back(closed_polygon[static_cast<std::size_t>((((static_cast<long>(index) + k) % n) + n) % n)]);
  const auto one_level = parameters::number_of_iterations(1).closed(false).end_rule(End_rule::shrink);
  for(int level = 0; level < levels; ++level) {
    const internal::Polyline_level<Scheme> plan(scheme, crop.size(), false, End_rule::shrink);
    const std::vector<Point> next = refine_polyline(crop, scheme, one_level);
    // crop index c is offset L + c, so the tracked child (relative position 0)
    // has position -2L in the numbering of `plan`; relative position q is
    // output index q - 2L - first_position
    std::vector<Point> next_crop;
    for(long q = L; q <= R; ++q) {
      const long j = q - 2 * L - plan.first_position();
      CGAL_assertion(j >= 0 && j < static_cast<long>(next.size()));
      next_crop.push_back(next[static_cast<std::size_t>(j)]);
    }
    crop.swap(next_crop);
  }
  return crop[static_cast<std::size_t>(-L)];
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_CURVE_ANALYSIS_H
