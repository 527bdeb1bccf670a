// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_CURVE_MEASUREMENTS_H
#define CGAL_SUBDIV_ANALYSIS_CURVE_MEASUREMENTS_H

/// \file curve_measurements.h
/// Measurements on real polylines that check what the analysis of a curve
/// scheme predicts (curve_analysis.h): the distance between levels and its
/// ratio, the discrete curvature, and a limit point followed level by level.

#include <CGAL/Subdiv/curves/curve_mask.h>
#include <CGAL/Subdiv/curves/curve_parameters.h>
#include <CGAL/Subdiv/curves/refine_polyline.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/Subdiv/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

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
    // the sides scaled by their largest coordinate, so that neither the
    // products below overflow (coordinates near 1e200) nor underflow; the
    // curvature scales back by 1 / scale
    double scale = 0;
    for(std::size_t k = 0; k < 3; ++k)
      scale = (std::max)({scale, std::abs(b[k] - a[k]), std::abs(c[k] - b[k])});
    if(!(scale > 0) || !std::isfinite(scale))
      continue; // repeated points (no circle through them), or infinite ones
    const internal::Double_point u = {(b[0] - a[0]) / scale, (b[1] - a[1]) / scale, (b[2] - a[2]) / scale};
    const internal::Double_point v = {(c[0] - b[0]) / scale, (c[1] - b[1]) / scale, (c[2] - b[2]) / scale};
    const internal::Double_point w = {u[0] + v[0], u[1] + v[1], u[2] + v[2]};
    const double cross[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double twice_area = std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
    const internal::Double_point origin = {0, 0, 0};
    const double lengths =
      internal::distance(origin, u) * internal::distance(origin, v) * internal::distance(origin, w);
    curvature[i] = lengths > 0 ? 2 * twice_area / lengths / scale : 0.0;
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

#endif // CGAL_SUBDIV_ANALYSIS_CURVE_MEASUREMENTS_H
