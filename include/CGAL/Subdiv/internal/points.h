// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_POINTS_H
#define CGAL_SUBDIV_INTERNAL_POINTS_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/Origin.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

template <class Point>
using Point_FT = typename CGAL::Kernel_traits<Point>::Kernel::FT;

template <class Point>
using Point_vector = decltype(std::declval<Point>() - CGAL::ORIGIN);

// whether T has `T - ORIGIN` (a point of a CGAL kernel)
template <class T, class = void>
struct Is_point : std::false_type
{};
template <class T>
struct Is_point<T, std::void_t<decltype(std::declval<const T&>() - CGAL::ORIGIN)>> : std::true_type
{};

// whether T is a 3D point with double coordinates (Simple_cartesian<double>,
// Epick): the fast paths sum its coordinates in three doubles
template <class T, class = void>
struct Is_double_point_3 : std::false_type
{};
template <class T>
struct Is_double_point_3<T, std::void_t<typename CGAL::Kernel_traits<T>::Kernel::Point_3>>
  : std::bool_constant<std::is_same<typename CGAL::Kernel_traits<T>::Kernel::Point_3, T>::value &&
                       std::is_same<typename CGAL::Kernel_traits<T>::Kernel::FT, double>::value>
{};

// Coordinates of floating-point kernels can be NaN or infinite; exact ones cannot.
template <class FT>
bool is_finite_number(const FT& x)
{
  if constexpr(std::is_floating_point<FT>::value)
    return std::isfinite(x);
  else
    return true;
}

template <class Point>
bool is_finite_point(const Point& p)
{
  for(int d = 0; d < p.dimension(); ++d)
    if(!is_finite_number(p.cartesian(d)))
      return false;
  return true;
}

/*
 * The point accumulator: sums weight * (point - ORIGIN) over the contributions
 * a stencil reports, then makes one point. Affine combination, so any kernel
 * (exact or not, 2D or 3D) works.
 */
template <class Point>
class Point_sum
{
public:
  using FT = Point_FT<Point>;
  using Vector = Point_vector<Point>;

  explicit Point_sum(const std::vector<Point>& points) : m_points(points), m_sum(CGAL::NULL_VECTOR) {}

  void add(std::size_t index, const FT& weight) { m_sum = m_sum + (m_points[index] - CGAL::ORIGIN) * weight; }

  Point point() const { return CGAL::ORIGIN + m_sum; }

private:
  const std::vector<Point>& m_points;
  Vector m_sum;
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_POINTS_H
