// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_REFINEMENT_CARRIED_VALUES_H
#define CGAL_SUBDIV_REFINEMENT_CARRIED_VALUES_H

/// \file carried_values.h
/// How the values of a carried map are combined with the weights of a row
/// (`Carried_data`): `internal::combine_values<Value>(get_value, terms)`,
/// where `terms` is a range of (element, weight) and `get_value(element)`
/// the element's value.
///   - a vector-like value (a scalar, `Vector_2`, `Vector_3`, an Eigen vector):
///     `value * weight` summed; the weight is the row's number type when the
///     value is made of it (the number type itself, or a kernel object of a
///     kernel with that FT), so that exact values stay exact, and a `double`
///     otherwise;
///   - `Point_2`, `Point_3`: their vectors from the origin, combined as above;
///   - `CGAL::IO::Color`: each channel (alpha too) in double, then rounded to
///     the nearest integer and clamped to [0, 255].

#include <CGAL/IO/Color.h>
#include <CGAL/Origin.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

namespace CGAL {
template <class K>
class Point_2;
template <class K>
class Point_3;

namespace Subdiv {
namespace internal {

template <class T, class = void>
struct Has_kernel : std::false_type
{};
template <class T>
struct Has_kernel<T, std::void_t<typename T::R::FT>> : std::true_type
{};

/// whether values of type Value are made of the number type FT
template <class Value, class FT>
constexpr bool is_made_of()
{
  if constexpr(std::is_same<Value, FT>::value)
    return true;
  else if constexpr(Has_kernel<Value>::value)
    return std::is_same<typename Value::R::FT, FT>::value;
  else
    return false;
}

/// `w` as the weight that multiplies values of type Value
template <class Value, class FT>
auto weight_for(const FT& w)
{
  if constexpr(is_made_of<Value, FT>())
    return w;
  else
    return CGAL::to_double(w);
}

template <class Value, class GetValue, class Terms>
Value combine_vectors(const GetValue& get_value, const Terms& terms)
{
  auto term = terms.begin();
  Value sum = get_value(term->first) * weight_for<Value>(term->second);
  for(++term; term != terms.end(); ++term)
    sum = sum + get_value(term->first) * weight_for<Value>(term->second);
  return sum;
}

template <class Value>
struct Carried_value
{
  template <class GetValue, class Terms>
  static Value combine(const GetValue& get_value, const Terms& terms)
  {
    return combine_vectors<Value>(get_value, terms);
  }
};

struct Carried_point
{
  template <class Point, class GetValue, class Terms>
  static Point combine(const GetValue& get_value, const Terms& terms)
  {
    using Vector = decltype(std::declval<Point>() - CGAL::ORIGIN);
    const auto vector_of = [&](const auto& element) { return get_value(element) - CGAL::ORIGIN; };
    return CGAL::ORIGIN + combine_vectors<Vector>(vector_of, terms);
  }
};

template <class K>
struct Carried_value<CGAL::Point_2<K>>
{
  template <class GetValue, class Terms>
  static CGAL::Point_2<K> combine(const GetValue& get_value, const Terms& terms)
  {
    return Carried_point::combine<CGAL::Point_2<K>>(get_value, terms);
  }
};

template <class K>
struct Carried_value<CGAL::Point_3<K>>
{
  template <class GetValue, class Terms>
  static CGAL::Point_3<K> combine(const GetValue& get_value, const Terms& terms)
  {
    return Carried_point::combine<CGAL::Point_3<K>>(get_value, terms);
  }
};

template <>
struct Carried_value<CGAL::IO::Color>
{
  template <class GetValue, class Terms>
  static CGAL::IO::Color combine(const GetValue& get_value, const Terms& terms)
  {
    std::array<double, 4> sum = {0, 0, 0, 0};
    for(const auto& term : terms) {
      const CGAL::IO::Color c = get_value(term.first);
      const double w = CGAL::to_double(term.second);
      sum[0] += c.red() * w;
      sum[1] += c.green() * w;
      sum[2] += c.blue() * w;
      sum[3] += c.alpha() * w;
    }
    const auto channel = [&](int k) { return static_cast<unsigned char>(std::clamp(std::round(sum[k]), 0.0, 255.0)); };
    return CGAL::IO::Color(channel(0), channel(1), channel(2), channel(3));
  }
};

/// the combination of the values of `terms` (a non-empty range of (element, weight))
template <class Value, class GetValue, class Terms>
Value combine_values(const GetValue& get_value, const Terms& terms)
{
  return Carried_value<Value>::combine(get_value, terms);
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_REFINEMENT_CARRIED_VALUES_H
