// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The body of compute_curve(), included by curve_double.cpp and curve_exact.cpp
// (one kernel each, so that the two compile in parallel).
#ifndef CGAL_SUBDIV_CLI_CURVE_IMPL_H
#define CGAL_SUBDIV_CLI_CURVE_IMPL_H

#include "analysis_config.h"
#include "curve.h"
#include "numbers.h"
#include "schemes.h"

#include <CGAL/Subdiv/curves/refine_polyline.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

namespace cgal_subdiv {
namespace curve_impl {

namespace S = CGAL::Subdiv;

template <class Point>
using Point_FT = typename CGAL::Kernel_traits<Point>::Kernel::FT;

template <class Point>
constexpr int dimension_of()
{
  return CGAL::Ambient_dimension<Point>::value;
}

template <class Point>
std::vector<Point> make_points(const Input_polyline& input)
{
  using FT = Point_FT<Point>;
  std::vector<Point> points;
  points.reserve(input.points.size());
  for(const auto& c : input.points) {
    try {
      if constexpr(dimension_of<Point>() == 2)
        points.emplace_back(to_ft<FT>(c[0]), to_ft<FT>(c[1]));
      else
        points.emplace_back(to_ft<FT>(c[0]), to_ft<FT>(c[1]), to_ft<FT>(c[2]));
    } catch(const Input_error& e) {
      throw Input_error("input point " + std::to_string(points.size() + 1) + ": " + e.what());
    }
  }
  return points;
}

template <class Point>
auto to_double_points(const std::vector<Point>& points)
{
  using Double_point = std::conditional_t<dimension_of<Point>() == 2, Double_kernel::Point_2, Double_kernel::Point_3>;
  std::vector<Double_point> result;
  result.reserve(points.size());
  for(const Point& p : points) {
    if constexpr(dimension_of<Point>() == 2)
      result.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    else
      result.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  return result;
}

// the figure shows the projection onto the xy plane
template <class Point>
void add_level(Figure* figure, const std::vector<Point>& points)
{
  if(!figure)
    return;
  std::vector<std::array<double, 2>> level;
  level.reserve(points.size());
  for(const Point& p : points)
    level.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y())});
  figure->levels.push_back(std::move(level));
}

template <class Point, class Scheme>
std::vector<Point> refine_once(const std::vector<Point>& points, const Scheme& scheme, const Refine_spec& refine)
{
  if constexpr(Is_bezier<Scheme>::value)
    return S::bezier_subdivision(points, scheme.degree(), S::parameters::number_of_iterations(1).closed(refine.closed));
  else
    return S::refine_polyline(points, scheme,
                              S::parameters::number_of_iterations(1).closed(refine.closed).end_rule(refine.end_rule));
}

// Bezier "enough subdivisions": split until every segment is flat
template <class Point, class Scheme>
std::vector<Point> refine_to_tolerance(const std::vector<Point>& control, const Scheme& scheme,
                                       const Refine_spec& refine)
{
  if constexpr(Is_bezier<Scheme>::value)
    return S::bezier_subdivision(
      control, scheme.degree(),
      S::parameters::flatness_tolerance(to_ft<Point_FT<Point>>(refine.tolerance)).closed(refine.closed));
  else
    throw Usage_error("--tolerance applies to bezier only");
}

// all levels, one at a time, so that the figure can show each of them
template <class Point, class Scheme>
std::vector<Point> refine(const std::vector<Point>& control, const Scheme& scheme, const Refine_spec& refine,
                          Figure* figure)
{
  add_level(figure, control);
  if(refine.use_tolerance) {
    std::vector<Point> result = refine_to_tolerance(control, scheme, refine);
    add_level(figure, result);
    return result;
  }
  // refuse a too large output before computing anything
  S::internal::check_output_size(control.size(), refine.levels, S::default_max_output_points);
  // the first level is made even for --levels 0: it checks that the scheme applies
  std::vector<Point> current = refine_once(control, scheme, refine);
  if(refine.levels == 0)
    return control;
  add_level(figure, current);
  for(int level = 2; level <= refine.levels; ++level) {
    try {
      current = refine_once(current, scheme, refine);
    } catch(const S::Bad_input& e) { // e.g. shrinking ends: the polyline got too short
      throw S::Bad_input("level " + std::to_string(level) + " of " + std::to_string(refine.levels) + ": " + e.what());
    }
    add_level(figure, current);
  }
  return current;
}

template <class Point>
void write_points(const std::vector<Point>& points, std::ostream& out)
{
  for(const Point& p : points) {
    for(int d = 0; d < dimension_of<Point>(); ++d)
      out << (d ? " " : "") << format_number(p.cartesian(d));
    out << '\n';
  }
}

// |p - q| without squaring the coordinates (which overflows beyond 1e154)
template <class Point>
double distance(const Point& p, const Point& q)
{
  const auto d = p - q;
  return dimension_of<Point>() == 2
           ? std::hypot(d.cartesian(0), d.cartesian(1))
           : std::hypot(d.cartesian(0), d.cartesian(1), d.cartesian(dimension_of<Point>() - 1));
}

template <class Point>
void add_curvature(Figure* figure, const std::vector<Point>& points, bool closed)
{
#if SUBDIV_CLI_WITH_ANALYSIS
  if(!figure || points.size() < 3)
    return;
  const auto p = to_double_points(points);
  figure->curvature = S::discrete_curvature(p, S::parameters::closed(closed));
  figure->arc_length.assign(1, 0.0);
  for(std::size_t i = 1; i < p.size(); ++i)
    figure->arc_length.push_back(figure->arc_length.back() + distance(p[i - 1], p[i]));
  figure->has_curvature = true;
#else
  (void)figure, (void)points, (void)closed;
#endif
}

// refuses a result in doubles with a non-finite coordinate: every scheme's
// weights are bounded, so the likely cause is the largest input coordinate
template <class Point>
void check_finite_result(const std::vector<Point>& result, const std::vector<Point>& control)
{
  if constexpr(std::is_floating_point<Point_FT<Point>>::value) {
    const auto finite = [](const Point& p) {
      for(int d = 0; d < dimension_of<Point>(); ++d)
        if(!std::isfinite(p.cartesian(d)))
          return false;
      return true;
    };
    const auto bad = std::find_if(result.begin(), result.end(), [&](const Point& p) { return !finite(p); });
    if(bad == result.end())
      return;
    std::size_t at = 0;
    double largest = 0;
    for(std::size_t i = 0; i < control.size(); ++i)
      for(int d = 0; d < dimension_of<Point>(); ++d)
        if(std::abs(control[i].cartesian(d)) > std::abs(largest)) {
          largest = control[i].cartesian(d);
          at = i;
        }
    std::ostringstream largest_text;
    largest_text.precision(6);
    largest_text << largest;
    throw Input_error("output point " + std::to_string(bad - result.begin() + 1) +
                      " has a non-finite coordinate: the input coordinates are too large for the scheme's "
                      "weights in doubles (the largest, " +
                      largest_text.str() + ", is at input point " + std::to_string(at + 1) +
                      "); scale the points down, or use --exact. Nothing was written");
  } else {
    (void)result, (void)control;
  }
}

template <class Point>
std::size_t compute(const Curve_job& job, const Input_polyline& input, std::ostream& out, Figure* figure)
{
  const std::vector<Point> control = make_points<Point>(input);
  const std::vector<Point> result = with_scheme<Point_FT<Point>>(
    job.scheme, [&](const auto& scheme) { return refine(control, scheme, job.refine, figure); });
  check_finite_result(result, control);
  write_points(result, out);
  add_curvature(figure, result, job.refine.closed);
  return result.size();
}

} // namespace curve_impl

template <class Kernel>
std::size_t compute_curve(const Curve_job& job, const Input_polyline& input, std::ostream& points_out, Figure* figure)
{
  if(input.dimension == 3)
    return curve_impl::compute<typename Kernel::Point_3>(job, input, points_out, figure);
  return curve_impl::compute<typename Kernel::Point_2>(job, input, points_out, figure);
}

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_CURVE_IMPL_H
