// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_BEZIER_SCHEME_H
#define CGAL_SUBDIV_BEZIER_SCHEME_H

#include <CGAL/Dimension.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Subdiv/curves/curve_parameters.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/stencils/Stencil.h>
#include <CGAL/squared_distance_2.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

// de Casteljau's algorithm: the control polygons of the two pieces of a Bezier
// curve split at the parameter that `lerp` uses. Rows of the triangle are
// formed in place; the left piece takes the first entry of every row, the
// right piece the last. The one place where the algorithm is written.
template <class T, class Lerp>
std::pair<std::vector<T>, std::vector<T>> de_casteljau(std::vector<T> row, const Lerp& lerp)
{
  const std::size_t d = row.size() - 1;
  std::vector<T> left(row.size(), row.front()), right(row.size(), row.back());
  for(std::size_t r = 1; r <= d; ++r) {
    for(std::size_t i = 0; i + r <= d; ++i)
      row[i] = lerp(row[i], row[i + 1]);
    left[r] = row[0];
    right[d - r] = row[d - r];
  }
  return {left, right};
}

} // namespace internal

/*!
 * \ingroup PkgSubdivCurveSchemes
 * Subdivision of a Bezier curve of degree d by de Casteljau's midpoint split:
 * the d+1 control points become the 2d+1 control points of the two halves
 * (t in [0, 1/2] and [1/2, 1]), which share their middle point. For the cubic:
 * P0, P01, P012, P0123, P123, P23, P3.
 *
 * `split_mask(j, acc)` reports the weights of new control point j
 * (0 <= j <= 2d) over the old ones; they are derived by running de Casteljau's
 * algorithm on unit impulses.
 */
template <class FT>
class Bezier_scheme
{
public:
  using Number_type = FT;
  static constexpr int max_degree = 64;

  /// \throws Bad_input unless 1 <= degree <= max_degree
  explicit Bezier_scheme(int degree = 3) : m_degree(degree)
  {
    internal::require(
      degree >= 1 && degree <= max_degree,
      "Bezier degree must be between 1 and " + std::to_string(max_degree) + ", got " + std::to_string(degree));
    derive_masks();
  }

  std::string name() const { return "Bezier of degree " + std::to_string(m_degree); }
  int degree() const { return m_degree; }

  template <class Accumulator>
  void split_mask(int j, Accumulator& acc) const
  {
    for(const auto& term : m_masks[static_cast<std::size_t>(j)].terms())
      acc.add(term.first, term.second);
  }

private:
  void derive_masks()
  {
    const std::size_t d = static_cast<std::size_t>(m_degree);
    m_masks.assign(2 * d + 1, Stencil<int, FT>());
    const auto half = [](const FT& x, const FT& y) -> FT { return (x + y) / FT(2); };
    for(std::size_t source = 0; source <= d; ++source) {
      std::vector<FT> impulse(d + 1, FT(0));
      impulse[source] = FT(1);
      const auto halves = internal::de_casteljau(impulse, half);
      for(std::size_t j = 0; j <= 2 * d; ++j) {
        const FT& w = j <= d ? halves.first[j] : halves.second[j - d];
        if(w != FT(0))
          m_masks[j].add(static_cast<int>(source), w);
      }
    }
  }

  int m_degree;
  std::vector<Stencil<int, FT>> m_masks;
};

/*!
 * \ingroup PkgSubdivCurves
 * splits the Bezier curve with control points `control` (any range of points)
 * at parameter `t` and returns the control points of the pieces over [0, t]
 * and [t, 1].
 */
template <class PointRange>
std::pair<std::vector<internal::Range_point<PointRange>>, std::vector<internal::Range_point<PointRange>>>
de_casteljau_split(const PointRange& control, const internal::Point_FT<internal::Range_point<PointRange>>& t)
{
  using Point = internal::Range_point<PointRange>;
  std::vector<Point> row = internal::to_point_vector(control);
  internal::require(!row.empty(), "a Bezier curve needs at least one control point");
  const auto lerp = [&t](const Point& p, const Point& q) { return p + (q - p) * t; };
  return internal::de_casteljau(std::move(row), lerp);
}

/// the point at parameter `t` of the Bezier curve with control points `control` (any range of points)
template <class PointRange>
internal::Range_point<PointRange> bezier_point(const PointRange& control,
                                               const internal::Point_FT<internal::Range_point<PointRange>>& t)
{
  return de_casteljau_split(control, t).first.back();
}

namespace internal {

// A chain of Bezier segments of degree d: open, m d + 1 points; closed, m d
// points (the last segment ends at the first point).
template <class Point>
std::size_t bezier_segment_count(const std::vector<Point>& points, int degree, bool closed)
{
  const std::size_t d = static_cast<std::size_t>(degree);
  const std::size_t n = points.size();
  const bool fits = closed ? (n >= d && n % d == 0 && n / d >= 1 && n >= 2) : (n >= d + 1 && (n - 1) % d == 0);
  require(fits, std::string("a ") + (closed ? "closed" : "open") + " chain of Bezier segments of degree " +
                  std::to_string(degree) + " needs " + (closed ? "a multiple of d" : "m d + 1") +
                  " control points, got " + std::to_string(n));
  for(std::size_t i = 0; i < n; ++i)
    require(is_finite_point(points[i]), "point " + std::to_string(i) + " has a non-finite coordinate");
  return closed ? n / d : (n - 1) / d;
}

template <class Point>
std::vector<Point> bezier_segment(const std::vector<Point>& points, std::size_t s, std::size_t d)
{
  std::vector<Point> segment;
  segment.reserve(d + 1);
  for(std::size_t i = 0; i <= d; ++i)
    segment.push_back(points[(s * d + i) % points.size()]);
  return segment;
}

// control points of the two halves of `segment`, from the scheme's masks
template <class Point, class FT>
std::vector<Point> split_segment(const std::vector<Point>& segment, const Bezier_scheme<FT>& scheme)
{
  std::vector<Point> halves;
  halves.reserve(2 * segment.size() - 1);
  for(int j = 0; j <= 2 * scheme.degree(); ++j) {
    Point_sum<Point> sum(segment);
    struct Index_acc
    {
      Point_sum<Point>& sum;
      void add(int i, const FT& w) { sum.add(static_cast<std::size_t>(i), w); }
    } acc{sum};
    scheme.split_mask(j, acc);
    halves.push_back(sum.point());
  }
  return halves;
}

template <class Point>
auto squared_distance_to_chord(const Point& p, const Point& a, const Point& b)
{
  using K = typename CGAL::Kernel_traits<Point>::Kernel;
  if(a == b)
    return CGAL::squared_distance(p, a);
  if constexpr(CGAL::Ambient_dimension<Point>::value == 2)
    return CGAL::squared_distance(p, typename K::Segment_2(a, b));
  else
    return CGAL::squared_distance(p, typename K::Segment_3(a, b));
}

template <class Point>
bool is_flat(const std::vector<Point>& segment, const Point_FT<Point>& squared_tolerance)
{
  for(std::size_t i = 1; i + 1 < segment.size(); ++i)
    if(squared_distance_to_chord(segment[i], segment.front(), segment.back()) > squared_tolerance)
      return false;
  return true;
}

} // namespace internal

namespace internal {

// every level splits every segment at t = 1/2
template <class Point>
std::vector<Point> bezier_uniform(std::vector<Point> current, int degree, const Curve_parameters& p)
{
  using FT = Point_FT<Point>;
  const Bezier_scheme<FT> scheme(degree);
  const std::size_t d = static_cast<std::size_t>(degree);
  std::size_t segments = bezier_segment_count(current, degree, p.closed);
  check_output_size(current.size(), p.levels, p.max_output_points);

  for(int level = 0; level < p.levels; ++level) {
    std::vector<Point> next;
    next.reserve(2 * segments * d + 1);
    for(std::size_t s = 0; s < segments; ++s) {
      const auto halves = split_segment(bezier_segment(current, s, d), scheme);
      next.insert(next.end(), halves.begin(), halves.end() - 1); // the last is the next segment's first
    }
    if(!p.closed)
      next.push_back(current.back());
    current.swap(next);
    segments *= 2;
  }
  return current;
}

/*
 * An upper bound, known before any work, on the points that the adaptive
 * subdivision to `tolerance` makes: a control polygon whose second
 * differences are at most M lies within i (d - i) M / 2 <= d^2 M / 8 of the
 * point i/d of its chord, and each halving divides the second differences by
 * 4, so a segment is flat after at most k = ceil(log4(d^2 M / (8 tolerance)))
 * halvings: at most d 2^k points. In doubles (a bound, not a result).
 */
template <class Point>
double bezier_points_bound(const std::vector<Point>& points, std::size_t segments, std::size_t d, double tolerance)
{
  double bound = 1;
  for(std::size_t s = 0; s < segments; ++s) {
    const std::vector<Point> segment = bezier_segment(points, s, d);
    double most = 0; // the largest second difference, squared
    for(std::size_t i = 0; i + 2 <= d; ++i) {
      double squared = 0;
      for(int c = 0; c < segment[i].dimension(); ++c) {
        const double second = CGAL::to_double(segment[i + 2].cartesian(c)) -
                              2 * CGAL::to_double(segment[i + 1].cartesian(c)) +
                              CGAL::to_double(segment[i].cartesian(c));
        squared += second * second;
      }
      most = (std::max)(most, squared);
    }
    const double deviation = static_cast<double>(d * d) * std::sqrt(most) / 8;
    const double halvings = deviation > tolerance ? std::ceil(std::log(deviation / tolerance) / std::log(4.0)) : 0;
    bound += static_cast<double>(d) * std::pow(2.0, halvings);
  }
  return bound;
}

// a segment is split at t = 1/2 until it is flat
template <class Point>
std::vector<Point> bezier_adaptive(const std::vector<Point>& points, int degree, const Point_FT<Point>& tolerance,
                                   const Curve_parameters& p)
{
  using FT = Point_FT<Point>;
  require(tolerance > FT(0), "the flatness tolerance must be positive");
  const Bezier_scheme<FT> scheme(degree);
  const std::size_t d = static_cast<std::size_t>(degree);
  const std::size_t segments = bezier_segment_count(points, degree, p.closed);
  const FT squared_tolerance = tolerance * tolerance;
  // refuse before any work a tolerance that may need too many points
  const double bound = bezier_points_bound(points, segments, d, CGAL::to_double(tolerance));
  require(bound <= static_cast<double>(p.max_output_points),
          "the flatness tolerance may need up to " + std::to_string(std::llround((std::min)(bound, 1e18))) +
            " points, more than the max_output_points limit (" + std::to_string(p.max_output_points) +
            "): a bound from the control points, known before any work; take a larger tolerance");

  std::vector<Point> result;
  for(std::size_t s = 0; s < segments; ++s) {
    // depth-first, left half first, so that the output stays in curve order
    std::vector<std::vector<Point>> stack{bezier_segment(points, s, d)};
    while(!stack.empty()) {
      std::vector<Point> segment = std::move(stack.back());
      stack.pop_back();
      if(is_flat(segment, squared_tolerance)) {
        result.insert(result.end(), segment.begin(), segment.end() - 1);
        require(result.size() <= p.max_output_points, "the flatness tolerance needs more than " +
                                                        std::to_string(p.max_output_points) +
                                                        " points (the max_output_points limit)");
        continue;
      }
      const auto halves = split_segment(segment, scheme);
      stack.emplace_back(halves.begin() + static_cast<long>(d), halves.end());
      stack.emplace_back(halves.begin(), halves.begin() + static_cast<long>(d) + 1);
    }
  }
  if(!p.closed)
    result.push_back(points.back());
  return result;
}

} // namespace internal

/*!
 * \ingroup PkgSubdivCurves
 * subdivides a chain of Bezier segments of degree `degree` (open: m d + 1
 * control points, closed: m d) and returns the control points of the refined
 * chain.
 *
 * Uniformly by default: every level splits every segment at t = 1/2 (open:
 * 2^L m d + 1 points, closed: 2^L m d). With `flatness_tolerance`, "enough
 * subdivisions" instead: a segment is split at t = 1/2 until every control
 * point is within the tolerance of the chord from its first to its last
 * control point.
 *
 * \tparam PointRange a range of `Point_2` or `Point_3` of any CGAL kernel
 *         (`std::vector`, `std::list`, a boost range, ...)
 * \param points the control points of the chain, left unchanged
 * \param degree the degree d of every segment
 * \param np optional named parameters, from `CGAL::Subdiv::parameters` (or
 *   CGAL's own `CGAL::parameters::number_of_iterations()`), in any order:
 *   - `number_of_iterations` (default 1): how many uniform levels;
 *   - `flatness_tolerance` (a number convertible to the kernel's `FT`; no
 *     default): refine adaptively to this tolerance instead of by levels;
 *   - `closed` (default false): whether the last segment ends at the first point;
 *   - `max_output_points` (default `default_max_output_points`): refuse a call
 *     whose output would have more points.
 *
 * `bezier_subdivision(points, 3, CGAL::Subdiv::parameters::number_of_iterations(4).closed(true))`
 *
 * \throws Bad_input for a point count that is not a chain of degree `degree`,
 *         a negative level count, both `number_of_iterations` and
 *         `flatness_tolerance`, a non-positive tolerance, or too large an output.
 */
template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
std::vector<internal::Range_point<PointRange>> bezier_subdivision(
  const PointRange& points, int degree, const NamedParameters& np = parameters::default_values())
{
  using FT = internal::Point_FT<internal::Range_point<PointRange>>;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  const internal::Curve_parameters p = internal::read_curve_parameters(np);
  if constexpr(is_default_parameter<NamedParameters, internal::flatness_tolerance_t>::value) {
    return internal::bezier_uniform(internal::to_point_vector(points), degree, p);
  } else {
    // a fixed depth and a tolerance contradict each other: say so rather than pick one
    internal::require(is_default_parameter<NamedParameters, internal_np::number_of_iterations_t>::value,
                      "bezier_subdivision takes number_of_iterations or flatness_tolerance, not both");
    const FT tolerance(get_parameter(np, internal::flatness_tolerance_t()));
    return internal::bezier_adaptive(internal::to_point_vector(points), degree, tolerance, p);
  }
}

/*!
 * \ingroup PkgSubdivCurves
 * subdivides a chain of Bezier segments adaptively to `tolerance`: the same
 * as `bezier_subdivision(points, degree, np.flatness_tolerance(tolerance))`,
 * for a tolerance that the call always has.
 *
 * \param points the control points of the chain, left unchanged
 * \param degree the degree d of every segment
 * \param tolerance the flatness tolerance (see `flatness_tolerance` of
 *        `bezier_subdivision()`)
 * \param np optional named parameters: `closed` and `max_output_points`, as
 *   for `bezier_subdivision()`.
 * \throws Bad_input for a non-positive tolerance, a point count that is not a
 *         chain, or when more than `max_output_points` points would be needed.
 */
template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
std::vector<internal::Range_point<PointRange>> bezier_subdivision_to_tolerance(
  const PointRange& points, int degree, const internal::Point_FT<internal::Range_point<PointRange>>& tolerance,
  const NamedParameters& np = parameters::default_values())
{
  return internal::bezier_adaptive(internal::to_point_vector(points), degree, tolerance,
                                   internal::read_curve_parameters(np));
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_BEZIER_SCHEME_H
