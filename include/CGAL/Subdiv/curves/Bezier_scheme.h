// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_BEZIER_SCHEME_H
#define CGAL_SUBDIV_BEZIER_SCHEME_H

#include <CGAL/Dimension.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/Subdiv/stencils/Stencil.h>
#include <CGAL/squared_distance_2.h>
#include <CGAL/squared_distance_3.h>

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
 * splits the Bezier curve with control points `control` at parameter `t` and
 * returns the control points of the pieces over [0, t] and [t, 1].
 */
template <class Point>
std::pair<std::vector<Point>, std::vector<Point>> de_casteljau_split(const std::vector<Point>& control,
                                                                     const internal::Point_FT<Point>& t)
{
  internal::require(!control.empty(), "a Bezier curve needs at least one control point");
  const auto lerp = [&t](const Point& p, const Point& q) { return p + (q - p) * t; };
  return internal::de_casteljau(control, lerp);
}

/// the point at parameter `t` of the Bezier curve with control points `control`
template <class Point>
Point bezier_point(const std::vector<Point>& control, const internal::Point_FT<Point>& t)
{
  return de_casteljau_split(control, t).first.back();
}

/*!
 * \ingroup PkgSubdivCurves
 * Options of `bezier_subdivision()`.
 */
class Bezier_options
{
public:
  Bezier_options& number_of_iterations(int levels)
  {
    m_levels = levels;
    return *this;
  }
  Bezier_options& closed(bool closed)
  {
    m_closed = closed;
    return *this;
  }
  Bezier_options& max_output_points(std::size_t n)
  {
    m_max_output_points = n;
    return *this;
  }
  int number_of_iterations() const { return m_levels; }
  bool closed() const { return m_closed; }
  std::size_t max_output_points() const { return m_max_output_points; }

private:
  int m_levels = 1;
  bool m_closed = false;
  std::size_t m_max_output_points = std::size_t(1) << 27;
};

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

/*!
 * \ingroup PkgSubdivCurves
 * subdivides a chain of Bezier segments of degree `degree` uniformly:
 * every level splits every segment at t = 1/2. Returns the control points of
 * the refined chain (open: 2^L m d + 1 points, closed: 2^L m d).
 * \throws Bad_input for a point count that is not a chain of degree `degree`,
 *         a negative level count, or too large an output.
 */
template <class Point>
std::vector<Point> bezier_subdivision(const std::vector<Point>& points, int degree,
                                      const Bezier_options& options = Bezier_options())
{
  using FT = internal::Point_FT<Point>;
  const Bezier_scheme<FT> scheme(degree);
  const std::size_t d = static_cast<std::size_t>(degree);
  std::size_t segments = internal::bezier_segment_count(points, degree, options.closed());
  internal::check_output_size(points.size(), options.number_of_iterations(), options.max_output_points());

  std::vector<Point> current = points;
  for(int level = 0; level < options.number_of_iterations(); ++level) {
    std::vector<Point> next;
    next.reserve(2 * segments * d + 1);
    for(std::size_t s = 0; s < segments; ++s) {
      const auto halves = internal::split_segment(internal::bezier_segment(current, s, d), scheme);
      next.insert(next.end(), halves.begin(), halves.end() - 1); // the last is the next segment's first
    }
    if(!options.closed())
      next.push_back(current.back());
    current.swap(next);
    segments *= 2;
  }
  return current;
}

/*!
 * \ingroup PkgSubdivCurves
 * subdivides a chain of Bezier segments adaptively, "enough subdivisions":
 * a segment is split at t = 1/2 until every control point is within
 * `tolerance` of the chord from its first to its last control point.
 * Returns the control points of the refined chain.
 * \throws Bad_input for a non-positive tolerance, a point count that is not a
 *         chain, or when more than `max_output_points` points would be needed.
 */
template <class Point>
std::vector<Point> bezier_subdivision_to_tolerance(const std::vector<Point>& points, int degree,
                                                   const internal::Point_FT<Point>& tolerance, bool closed = false,
                                                   std::size_t max_output_points = std::size_t(1) << 27)
{
  using FT = internal::Point_FT<Point>;
  internal::require(tolerance > FT(0), "the flatness tolerance must be positive");
  const Bezier_scheme<FT> scheme(degree);
  const std::size_t d = static_cast<std::size_t>(degree);
  const std::size_t segments = internal::bezier_segment_count(points, degree, closed);
  const FT squared_tolerance = tolerance * tolerance;

  std::vector<Point> result;
  for(std::size_t s = 0; s < segments; ++s) {
    // depth-first, left half first, so that the output stays in curve order
    std::vector<std::vector<Point>> stack{internal::bezier_segment(points, s, d)};
    while(!stack.empty()) {
      std::vector<Point> segment = std::move(stack.back());
      stack.pop_back();
      if(internal::is_flat(segment, squared_tolerance)) {
        result.insert(result.end(), segment.begin(), segment.end() - 1);
        internal::require(result.size() <= max_output_points, "the flatness tolerance needs more than " +
                                                                std::to_string(max_output_points) +
                                                                " points (the max_output_points limit)");
        continue;
      }
      const auto halves = internal::split_segment(segment, scheme);
      stack.emplace_back(halves.begin() + static_cast<long>(d), halves.end());
      stack.emplace_back(halves.begin(), halves.begin() + static_cast<long>(d) + 1);
    }
  }
  if(!closed)
    result.push_back(points.back());
  return result;
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_BEZIER_SCHEME_H
