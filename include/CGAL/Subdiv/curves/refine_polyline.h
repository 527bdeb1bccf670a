// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_REFINE_POLYLINE_H
#define CGAL_SUBDIV_REFINE_POLYLINE_H

#include <CGAL/Subdiv/curves/curve_mask.h>
#include <CGAL/Subdiv/curves/curve_parameters.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/stencils/Stencil.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Subdiv {

namespace internal {

/*
 * One level of refinement of a polyline of n points: which new points there
 * are, and the stencil of each over the old points. Refinement (points),
 * stencil tables and the analysis all go through `stencil()`, which reads the
 * scheme's masks and maps offsets to old indices (periodic for closed
 * polylines, reflected at the ends for keep_ends).
 */
template <class Scheme>
class Polyline_level
{
public:
  using FT = typename Scheme::Number_type;

  Polyline_level(const Scheme& scheme, std::size_t n, bool closed, End_rule end_rule)
    : m_even(rule(scheme, 0)), m_odd(rule(scheme, 1)), m_n(static_cast<long>(n)), m_closed(closed), m_reflect(false),
      m_add_ends(false), m_first(0), m_count(0)
  {
    if(closed) {
      m_count = 2 * m_n;
      return;
    }
    if(end_rule == End_rule::keep_ends && is_vertex_centred(scheme)) {
      m_reflect = true;
      m_count = 2 * m_n - 1;
      for(long q = 0; q < m_count; ++q)
        require(reflection_fits(q),
                "a polyline of " + std::to_string(n) + " points is too short for " + scheme.name() + " with kept ends");
      return;
    }
    // the longest run of positions whose whole stencil lies on the polyline
    // (an interpolating scheme also "fits" at its end points, cut off by a gap)
    long first = 0, count = 0;
    for(long q = 0, run_start = 0; q <= 2 * m_n; ++q) {
      if(q < 2 * m_n && fits(q))
        continue;
      if(q - run_start > count) {
        first = run_start;
        count = q - run_start;
      }
      run_start = q + 1;
    }
    m_first = first;
    m_count = count;
    m_add_ends = (end_rule == End_rule::keep_ends);
    const long needed = m_add_ends ? 1 : 2;
    require(m_count >= needed, "a polyline of " + std::to_string(n) + " points is too short for " + scheme.name() +
                                 ": no new point has its whole stencil on it");
  }

  /// number of points of the new level
  std::size_t size() const { return static_cast<std::size_t>(m_count + (m_add_ends ? 2 : 0)); }

  /// position of new point 0 in the numbering 2i + parity of the new level
  long first_position() const { return m_add_ends ? m_first - 1 : m_first; }

  /// reports the stencil of new point `j` (0 <= j < size()) as acc.add(old index, weight)
  template <class Accumulator>
  void stencil(std::size_t j, Accumulator& acc) const
  {
    long q = static_cast<long>(j);
    if(m_add_ends) {
      if(j == 0) {
        acc.add(std::size_t(0), FT(1));
        return;
      }
      if(j + 1 == size()) {
        acc.add(static_cast<std::size_t>(m_n - 1), FT(1));
        return;
      }
      q -= 1;
    }
    q += m_first;
    const long i = q >> 1;
    const Stencil<int, FT>& r = (q & 1) ? m_odd : m_even;
    for(const auto& term : r.terms())
      add_old_point(i + term.first, term.second, acc);
  }

private:
  bool fits(long q) const
  {
    const long i = q >> 1;
    for(const auto& term : ((q & 1) ? m_odd : m_even).terms())
      if(i + term.first < 0 || i + term.first >= m_n)
        return false;
    return true;
  }

  bool reflection_fits(long q) const
  {
    const long i = q >> 1;
    for(const auto& term : ((q & 1) ? m_odd : m_even).terms()) {
      const long k = i + term.first;
      if(k < -(m_n - 1) || k > 2 * (m_n - 1))
        return false;
    }
    return true;
  }

  template <class Accumulator>
  void add_old_point(long k, const FT& w, Accumulator& acc) const
  {
    if(m_closed) {
      k %= m_n;
      if(k < 0)
        k += m_n;
    } else if(m_reflect && k < 0) { // p_k = 2 p_0 - p_-k
      acc.add(std::size_t(0), FT(2) * w);
      acc.add(static_cast<std::size_t>(-k), -w);
      return;
    } else if(m_reflect && k >= m_n) { // p_k = 2 p_n-1 - p_2(n-1)-k
      acc.add(static_cast<std::size_t>(m_n - 1), FT(2) * w);
      acc.add(static_cast<std::size_t>(2 * (m_n - 1) - k), -w);
      return;
    }
    acc.add(static_cast<std::size_t>(k), w);
  }

  Stencil<int, FT> m_even;
  Stencil<int, FT> m_odd;
  long m_n;
  bool m_closed;
  bool m_reflect;
  bool m_add_ends;
  long m_first;
  long m_count;
};

template <class Points>
void check_polyline(const Points& points, bool closed)
{
  require(!points.empty(), "the polyline is empty");
  require(points.size() >= (closed ? 3u : 2u),
          std::string("a ") +
            (closed ? "closed polyline needs at least 3 points" : "polyline needs at least 2 points") + ", got " +
            std::to_string(points.size()));
  for(std::size_t i = 0; i < points.size(); ++i)
    require(is_finite_point(points[i]), "point " + std::to_string(i) + " has a non-finite coordinate");
}

} // namespace internal

namespace internal {

// one level of `scheme` on `points`, by the plan of `Polyline_level`
template <class Point, class Scheme>
std::vector<Point> refine_polyline_once(const std::vector<Point>& points, const Scheme& scheme, bool closed,
                                        End_rule end_rule)
{
  const Polyline_level<Scheme> plan(scheme, points.size(), closed, end_rule);
  std::vector<Point> next;
  next.reserve(plan.size());
  for(std::size_t j = 0; j < plan.size(); ++j) {
    Point_sum<Point> sum(points);
    plan.stencil(j, sum);
    next.push_back(sum.point());
  }
  return next;
}

} // namespace internal

/*!
 * \ingroup PkgSubdivCurves
 * refines a polyline `number_of_iterations` times with the rules of `scheme`
 * and returns the new points. The input is left unchanged.
 *
 * \tparam PointRange a range of `Point_2` or `Point_3` of any CGAL kernel
 *         whose `FT` is the scheme's `Number_type` (`std::vector`, `std::list`,
 *         a boost range, ...); with an exact kernel the result is exact.
 * \tparam Scheme a model of `CurveSubdivisionScheme`
 * \param points the control polygon, left unchanged
 * \param scheme the rules of the scheme, with their options
 * \param np optional named parameters, from `CGAL::Subdiv::parameters` (or
 *   CGAL's own `CGAL::parameters::number_of_iterations()`), in any order:
 *   - `number_of_iterations` (default 1): how many levels;
 *   - `closed` (default false): whether the last point joins the first;
 *   - `end_rule` (default `End_rule::shrink`): the ends of an open polyline;
 *   - `max_output_points` (default `default_max_output_points`): a call
 *     whose output would have more points is refused before it allocates.
 *
 * `refine_polyline(points, scheme, CGAL::Subdiv::parameters::number_of_iterations(3).closed(true))`
 *
 * \throws Bad_input for an empty, too short or non-finite polyline, a negative
 *         level count, or an output larger than `max_output_points`.
 */
template <class PointRange, class Scheme, class NamedParameters = parameters::Default_named_parameters>
std::vector<internal::Range_point<PointRange>> refine_polyline(const PointRange& points, const Scheme& scheme,
                                                               const NamedParameters& np = parameters::default_values())
{
  const internal::Curve_parameters p = internal::read_curve_parameters(np);
  std::vector<internal::Range_point<PointRange>> current = internal::to_point_vector(points);
  internal::check_polyline(current, p.closed);
  internal::check_output_size(current.size(), p.levels, p.max_output_points);
  for(int level = 0; level < p.levels; ++level)
    current = internal::refine_polyline_once(current, scheme, p.closed, p.end_rule);
  return current;
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_REFINE_POLYLINE_H
