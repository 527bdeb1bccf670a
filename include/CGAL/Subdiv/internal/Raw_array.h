// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_RAW_ARRAY_H
#define CGAL_SUBDIV_INTERNAL_RAW_ARRAY_H

#include <cstddef>
#include <cstring>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * A growable array of a trivially copyable type whose elements are not
 * initialised when it grows by `resize_for_overwrite`: the fast paths write
 * every element themselves (in parallel chunks), so the memory is touched
 * once, by the threads that fill it.
 */
template <class T>
class Raw_array
{
  static_assert(std::is_trivially_copyable<T>::value, "Raw_array holds trivially copyable values");

public:
  Raw_array() = default;
  Raw_array(Raw_array&&) noexcept = default;
  Raw_array& operator=(Raw_array&&) noexcept = default;
  Raw_array(const Raw_array& other) { *this = other; }
  Raw_array& operator=(const Raw_array& other)
  {
    if(this != &other) {
      Raw_array copy;
      copy.resize_for_overwrite(other.m_size);
      if(other.m_size != 0)
        std::memcpy(copy.m_data.get(), other.m_data.get(), other.m_size * sizeof(T));
      *this = std::move(copy);
    }
    return *this;
  }

  std::size_t size() const { return m_size; }
  T* data() { return m_data.get(); }
  const T* data() const { return m_data.get(); }
  T& operator[](std::size_t i) { return m_data[i]; }
  const T& operator[](std::size_t i) const { return m_data[i]; }

  void reserve(std::size_t n)
  {
    if(n <= m_capacity)
      return;
    std::unique_ptr<T[]> data(new T[n]);
    if(m_size != 0)
      std::memcpy(data.get(), m_data.get(), m_size * sizeof(T));
    m_data = std::move(data);
    m_capacity = n;
  }
  void resize_for_overwrite(std::size_t n)
  {
    reserve(n);
    m_size = n;
  }
  void clear() { m_size = 0; }
  T* begin() { return data(); }
  T* end() { return data() + m_size; }
  const T* begin() const { return data(); }
  const T* end() const { return data() + m_size; }
  void push_back(const T& value)
  {
    if(m_size == m_capacity)
      reserve(m_capacity < 8 ? 16 : 2 * m_capacity);
    m_data[m_size++] = value;
  }

private:
  std::unique_ptr<T[]> m_data;
  std::size_t m_size = 0;
  std::size_t m_capacity = 0;
};

/// Raw_array for trivially copyable values (double weights), std::vector otherwise (exact numbers)
template <class T>
using Value_array = std::conditional_t<std::is_trivially_copyable<T>::value, Raw_array<T>, std::vector<T>>;

template <class T>
void resize_for_overwrite(Raw_array<T>& a, std::size_t n)
{
  a.resize_for_overwrite(n);
}

template <class T>
void resize_for_overwrite(std::vector<T>& a, std::size_t n)
{
  a.resize(n);
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_RAW_ARRAY_H
