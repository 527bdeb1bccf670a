// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_RANGES_H
#define CGAL_SUBDIV_INTERNAL_RANGES_H

// What the functions that take "any range" need to know of it.

#include <CGAL/Subdiv/errors.h>

#include <cstddef>
#include <iterator>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Subdiv {
namespace internal {

template <class T, class = void>
struct Is_range : std::false_type
{};
template <class T>
struct Is_range<
  T, std::void_t<decltype(std::begin(std::declval<const T&>())), decltype(std::end(std::declval<const T&>()))>>
  : std::true_type
{};

template <class T, class = void>
struct Is_random_access_range : std::false_type
{};
template <class T>
struct Is_random_access_range<T, std::enable_if_t<Is_range<T>::value>>
  : std::is_base_of<std::random_access_iterator_tag,
                    typename std::iterator_traits<decltype(std::begin(std::declval<const T&>()))>::iterator_category>
{};

template <class T, class = void>
struct Is_resizable : std::false_type
{};
template <class T>
struct Is_resizable<T, std::void_t<decltype(std::declval<T&>().resize(std::size_t()))>> : std::true_type
{};

/// the first element of a range, or the iterator itself
template <class T>
auto begin_of(const T& range_or_iterator)
{
  if constexpr(Is_range<T>::value)
    return std::begin(range_or_iterator);
  else
    return range_or_iterator;
}

/// makes `out` hold `n` values: resized if it can be, else it must have n
template <class Output>
void resize_output(Output& out, std::size_t n, const std::string& what)
{
  if constexpr(Is_resizable<Output>::value) {
    out.resize(n);
  } else {
    const auto size = static_cast<std::size_t>(std::distance(std::begin(out), std::end(out)));
    require(size == n, what + " needs room for " + std::to_string(n) + " values, got " + std::to_string(size));
  }
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_RANGES_H
