// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_LIMIT_VALUES_H
#define CGAL_SUBDIV_LIMIT_LIMIT_VALUES_H

/// \file limit_values.h
/// Limit rows applied to values: points, carried heights, tangent vectors
/// in double, and what the evaluation finds at one vertex
/// (`Limit_evaluator` applies the rows of `limit_rows.h` with them).

#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/Subdiv/stencils/Stencil.h>

#include <CGAL/Origin.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Subdiv {
namespace internal {

inline std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline double norm(const std::array<double, 3>& a)
{
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

template <class Point>
std::array<double, 3> to_double3(const Point& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

// a row applied to points: sum w (p - ORIGIN), in the points' number type
template <class Point, class FT, class PointOf>
Point apply_row(const Stencil<std::uint32_t, FT>& row, const PointOf& point_of)
{
  Point_vector<Point> sum = CGAL::NULL_VECTOR;
  for(const auto& term : row)
    sum = sum + (point_of(term.first) - CGAL::ORIGIN) * term.second;
  return CGAL::ORIGIN + sum;
}

// a row applied to numbers (carried heights): sum w x
template <class FT, class ValueOf>
FT apply_value_row(const Stencil<std::uint32_t, FT>& row, const ValueOf& value_of)
{
  FT sum(0);
  for(const auto& term : row)
    sum = sum + value_of(term.first) * term.second;
  return sum;
}

// a row summing to 0 applied to points, relative to `centre`: sum w (p - centre), in double
template <class FT, class PointOf>
std::array<double, 3> apply_difference_row(const Stencil<std::uint32_t, FT>& row, const PointOf& point_of,
                                           const std::array<double, 3>& centre)
{
  std::array<double, 3> t{0, 0, 0};
  for(const auto& term : row) {
    const std::array<double, 3> p = to_double3(point_of(term.first));
    const double w = CGAL::to_double(term.second);
    for(int d = 0; d < 3; ++d)
      t[d] += w * (p[d] - centre[d]);
  }
  return t;
}

/// no height channel
struct No_heights
{};

/// whether the mask has sharp rules with a crease curve (Loop, Catmull-Clark)
template <class Mask, class = void>
struct Has_crease_curve : std::false_type
{};
template <class Mask>
struct Has_crease_curve<Mask, std::void_t<decltype(std::declval<const Mask&>().crease_curve())>> : std::true_type
{};

// what the evaluation finds at one vertex
template <class Point>
struct Vertex_limit
{
  Point limit;
  Point_FT<Point> height = Point_FT<Point>(0); // limit of the carried heights, if any
  std::array<std::array<double, 3>, 2> tangent{};
  bool tangents = false; // whether the tangent vectors give the tangent plane
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_LIMIT_VALUES_H
