// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_CURVE_PARAMETERS_H
#define CGAL_SUBDIV_CURVE_PARAMETERS_H

/// \file curve_parameters.h
/// What the curve functions read from their named parameters, and their
/// defaults, in one place: `refine_polyline()`, `bezier_subdivision()`,
/// `lane_riesenfeld_refine()` and `measure_levels()` all read them here.

#include <CGAL/Subdiv/parameters.h>

#include <boost/range/begin.hpp>
#include <boost/range/end.hpp>
#include <boost/range/value_type.hpp>

#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivCurves
 * What happens at the two ends of an open polyline (named parameter `end_rule`).
 */
enum class End_rule {
  /// Only the new points whose whole stencil lies on the polyline are made, as
  /// in the lecture notes: the polyline loses points at both ends on every
  /// level. The cubic B-spline limit starts near the second point (at
  /// (p0 + 4 p1 + p2) / 6); the four-point limit runs from the third point to the
  /// third from last.
  shrink,
  /// The end points are kept and the limit runs from the first to the last
  /// point. Primal symmetric schemes (odd-degree B-splines, four-point) see the
  /// polyline continued by point reflection, p_-j = 2 p_0 - p_j (this gives the
  /// cubic B-spline end rule p'_0 = p_0, the "natural" end); other schemes
  /// (Chaikin, corner cutting, even-degree B-splines) make the points of
  /// `shrink` and add the two end points unchanged.
  keep_ends
};

/*!
 * \ingroup PkgSubdivCurves
 * The default of the named parameter `max_output_points` of the curve
 * functions (2^27 points): a call that would make more is refused before it
 * allocates anything.
 */
constexpr std::size_t default_max_output_points = std::size_t(1) << 27;

namespace internal {

/// the point type of a range of points (a `std::vector`, a `std::list`, a boost range, ...)
template <class PointRange>
using Range_point = std::remove_cv_t<typename boost::range_value<PointRange>::type>;

/// a copy of a range of points, in the one container the curve code indexes
template <class PointRange>
std::vector<Range_point<PointRange>> to_point_vector(const PointRange& points)
{
  return std::vector<Range_point<PointRange>>(boost::begin(points), boost::end(points));
}

/// the named parameters that the curve functions share, with their defaults
struct Curve_parameters
{
  int levels = 1;
  bool closed = false;
  End_rule end_rule = End_rule::shrink;
  std::size_t max_output_points = default_max_output_points;
};

/// reads `number_of_iterations`, `closed`, `end_rule` and `max_output_points`
/// from a chain of CGAL's or CGAL Subdiv's named parameters
template <class NamedParameters>
Curve_parameters read_curve_parameters(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const Curve_parameters defaults;
  Curve_parameters p;
  // the casts accept any integer type, as CGAL's own functions do
  p.levels = static_cast<int>(choose_parameter(get_parameter(np, internal_np::number_of_iterations), defaults.levels));
  p.closed = static_cast<bool>(choose_parameter(get_parameter(np, internal::closed_t()), defaults.closed));
  p.end_rule = choose_parameter(get_parameter(np, internal::end_rule_t()), defaults.end_rule);
  p.max_output_points = static_cast<std::size_t>(
    choose_parameter(get_parameter(np, internal::max_output_points_t()), defaults.max_output_points));
  return p;
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_CURVE_PARAMETERS_H
