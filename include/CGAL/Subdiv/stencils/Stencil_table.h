// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_STENCIL_TABLE_H
#define CGAL_SUBDIV_STENCIL_TABLE_H

#include <CGAL/Origin.h>
#include <CGAL/Subdiv/errors.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

template <class T, class = void>
struct Is_point : std::false_type
{
};
template <class T>
struct Is_point<T, std::void_t<decltype(std::declval<const T&>() - CGAL::ORIGIN)>> : std::true_type
{
};

} // namespace internal

/*!
 * \ingroup PkgSubdivStencils
 * A stencil table: one stencil (a sparse row of (source, weight)) per output
 * value, stored in compressed rows. `apply` evaluates all of them for a new set
 * of source values in one pass over memory; `compose` chains two tables, so
 * that several levels of refinement become one table from the coarse control
 * points to the points of the finest level.
 *
 * \tparam FT the number type of the weights
 */
template <class FT>
class Stencil_table
{
public:
  using Index = std::uint32_t;

  explicit Stencil_table(std::size_t number_of_sources = 0) : m_sources(number_of_sources), m_ends() {}

  /// the table that copies every source
  static Stencil_table identity(std::size_t n)
  {
    Stencil_table table(n);
    table.reserve(n, n);
    for(std::size_t i = 0; i < n; ++i) {
      table.m_indices.push_back(static_cast<Index>(i));
      table.m_weights.push_back(FT(1));
      table.m_ends.push_back(table.m_indices.size());
    }
    return table;
  }

  void reserve(std::size_t stencils, std::size_t terms)
  {
    m_ends.reserve(stencils);
    m_indices.reserve(terms);
    m_weights.reserve(terms);
  }

  /// appends a stencil; `terms` is a range of (source index, weight)
  template <class Terms>
  void add_stencil(const Terms& terms)
  {
    for(const auto& term : terms) {
      internal::require(static_cast<std::size_t>(term.first) < m_sources,
                        "stencil source " + std::to_string(term.first) + " out of range");
      m_indices.push_back(static_cast<Index>(term.first));
      m_weights.push_back(term.second);
    }
    m_ends.push_back(m_indices.size());
  }

  std::size_t number_of_stencils() const { return m_ends.size(); }
  std::size_t number_of_sources() const { return m_sources; }
  std::size_t number_of_terms() const { return m_indices.size(); }
  std::size_t stencil_begin(std::size_t i) const { return i == 0 ? 0 : m_ends[i - 1]; }
  std::size_t stencil_end(std::size_t i) const { return m_ends[i]; }
  Index source(std::size_t term) const { return m_indices[term]; }
  const FT& weight(std::size_t term) const { return m_weights[term]; }

  /// the table of `finer` applied after this one: row i of the result is
  /// sum_k finer(i, k) * row k of this table
  Stencil_table then(const Stencil_table& finer) const
  {
    internal::require(finer.number_of_sources() == number_of_stencils(),
                      "stencil tables do not chain: " + std::to_string(finer.number_of_sources()) +
                        " sources after " + std::to_string(number_of_stencils()) + " stencils");
    Stencil_table result(m_sources);
    result.reserve(finer.number_of_stencils(), finer.number_of_terms() * 4);
    std::vector<FT> sum(m_sources, FT(0));
    std::vector<char> touched(m_sources, 0);
    std::vector<Index> order;
    for(std::size_t i = 0; i < finer.number_of_stencils(); ++i) {
      order.clear();
      for(std::size_t t = finer.stencil_begin(i); t < finer.stencil_end(i); ++t) {
        const FT& w = finer.weight(t);
        const std::size_t k = finer.source(t);
        for(std::size_t u = stencil_begin(k); u < stencil_end(k); ++u) {
          const Index s = m_indices[u];
          if(!touched[s]) {
            touched[s] = 1;
            order.push_back(s);
            sum[s] = w * m_weights[u];
          } else {
            sum[s] += w * m_weights[u];
          }
        }
      }
      for(Index s : order) {
        result.m_indices.push_back(s);
        result.m_weights.push_back(sum[s]);
        touched[s] = 0;
      }
      result.m_ends.push_back(result.m_indices.size());
    }
    return result;
  }

  /*!
   * evaluates every stencil on `in` (one value per source) into `out` (one
   * value per stencil). Points (`Point_2`, `Point_3`) are combined affinely;
   * other values need `value * weight` and `value + value`, with the weight
   * converted to `double` unless the value type is `FT`.
   */
  template <class Value>
  void apply(const std::vector<Value>& in, std::vector<Value>& out) const
  {
    internal::require(in.size() == m_sources, "the stencil table needs " + std::to_string(m_sources) +
                                                " source values, got " + std::to_string(in.size()));
    out.resize(number_of_stencils());
    apply_range(in, out, 0, number_of_stencils());
  }

  /// evaluates stencils [first, last) only (e.g. one chunk per thread)
  template <class Value>
  void apply_range(const std::vector<Value>& in, std::vector<Value>& out, std::size_t first, std::size_t last) const
  {
    for(std::size_t i = first; i < last; ++i)
      out[i] = evaluate(in, i);
  }

  template <class Value>
  Value evaluate(const std::vector<Value>& in, std::size_t i) const
  {
    const std::size_t begin = stencil_begin(i), end = stencil_end(i);
    if constexpr(internal::Is_point<Value>::value) {
      auto sum = (in[m_indices[begin]] - CGAL::ORIGIN) * m_weights[begin];
      for(std::size_t t = begin + 1; t < end; ++t)
        sum = sum + (in[m_indices[t]] - CGAL::ORIGIN) * m_weights[t];
      return CGAL::ORIGIN + sum;
    } else if constexpr(std::is_same<Value, FT>::value) {
      Value sum = in[m_indices[begin]] * m_weights[begin];
      for(std::size_t t = begin + 1; t < end; ++t)
        sum = sum + in[m_indices[t]] * m_weights[t];
      return sum;
    } else {
      Value sum = in[m_indices[begin]] * CGAL::to_double(m_weights[begin]);
      for(std::size_t t = begin + 1; t < end; ++t)
        sum = sum + in[m_indices[t]] * CGAL::to_double(m_weights[t]);
      return sum;
    }
  }

private:
  std::size_t m_sources;
  std::vector<std::size_t> m_ends; // one past the last term of each stencil
  std::vector<Index> m_indices;
  std::vector<FT> m_weights;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_STENCIL_TABLE_H
