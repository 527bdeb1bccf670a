// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_STENCIL_TABLE_H
#define CGAL_SUBDIV_STENCIL_TABLE_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/Origin.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/Raw_array.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/Subdiv/internal/ranges.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/stencils/Row_builder.h>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

struct Stencil_table_access;

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
      if(static_cast<std::size_t>(term.first) >= m_sources) // the message is made only on failure
        throw Bad_input("stencil source " + std::to_string(term.first) + " out of range");
      m_indices.push_back(static_cast<Index>(term.first));
      m_weights.push_back(term.second);
    }
    m_ends.push_back(m_indices.size());
  }

  std::size_t number_of_stencils() const { return m_ends.size(); }
  /// throws `Bad_input` unless `n` is the number of sources
  void check_sources(std::size_t n) const
  {
    internal::require(n == m_sources, "the stencil table needs " + std::to_string(m_sources) + " source values, got " +
                                        std::to_string(n));
  }
  std::size_t number_of_sources() const { return m_sources; }
  std::size_t number_of_terms() const { return m_indices.size(); }
  std::size_t stencil_begin(std::size_t i) const { return i == 0 ? 0 : m_ends[i - 1]; }
  std::size_t stencil_end(std::size_t i) const { return m_ends[i]; }
  Index source(std::size_t term) const { return m_indices[term]; }
  const FT& weight(std::size_t term) const { return m_weights[term]; }

  /// the bytes of the table's arrays (row ends, source indices, weights)
  std::size_t memory_bytes() const
  {
    return m_ends.size() * sizeof(std::size_t) + m_indices.size() * sizeof(Index) + m_weights.size() * sizeof(FT);
  }

  /// the raw rows: the terms of stencil i are [stencil_begin(i), stencil_end(i))
  /// of these arrays
  const Index* source_data() const { return m_indices.data(); }
  const FT* weight_data() const { return m_weights.data(); }

  /// the number of terms in the rows that `row` (a range of (stencil, weight))
  /// combines: room enough for their composition
  template <class Terms>
  std::size_t terms_under(const Terms& row) const
  {
    std::size_t most = 0;
    for(const auto& term : row)
      most += stencil_end(term.first) - stencil_begin(term.first);
    return most;
  }

  /// adds to `builder` the composition of `row` (a range of (stencil, weight))
  /// with this table: sum_k w_k * stencil k
  template <class Terms>
  void compose_into(internal::Row_builder<FT>& builder, const Terms& row) const
  {
    for(const auto& term : row) {
      const std::size_t k = static_cast<std::size_t>(term.first);
      builder.add_row(m_indices.data(), m_weights.data(), stencil_begin(k), stencil_end(k), term.second);
    }
  }

  /// the table of `finer` applied after this one: row i of the result is
  /// sum_k finer(i, k) * row k of this table
  Stencil_table then(const Stencil_table& finer) const
  {
    internal::require(finer.number_of_sources() == number_of_stencils(),
                      "stencil tables do not chain: " + std::to_string(finer.number_of_sources()) + " sources after " +
                        std::to_string(number_of_stencils()) + " stencils");
    Stencil_table result(m_sources);
    result.reserve(finer.number_of_stencils(), finer.number_of_terms() * 4);
    internal::Row_builder<FT> builder;
    std::vector<std::pair<Index, FT>> row;
    for(std::size_t i = 0; i < finer.number_of_stencils(); ++i) {
      row.clear();
      for(std::size_t t = finer.stencil_begin(i); t < finer.stencil_end(i); ++t)
        row.emplace_back(finer.source(t), finer.weight(t));
      builder.start(m_sources, terms_under(row));
      compose_into(builder, row);
      for(std::size_t k = 0; k < builder.size(); ++k) {
        result.m_indices.push_back(builder.source(k));
        result.m_weights.push_back(builder.weight(k));
      }
      result.m_ends.push_back(result.m_indices.size());
    }
    return result;
  }

  /*!
   * evaluates every stencil on `in` (one value per source, any range) into
   * `out` (one value per stencil: a container that is resized, or a
   * random-access range of that size). Points (`Point_2`, `Point_3`) are
   * combined affinely; other values need `value * weight` and
   * `value + value`, with the weight converted to `double` unless the value
   * type is `FT`.
   *
   * Named parameters: `threads(n)`: 1 (the default) in this thread, 0 TBB's
   * choice, n at most n threads (with TBB); the values are the same bit for
   * bit. Tables of exact weights are applied in one thread.
   */
  template <class InputRange, class OutputRange, class NamedParameters = parameters::Default_named_parameters,
            class = std::enable_if_t<internal::Is_range<InputRange>::value>>
  void apply(const InputRange& in, OutputRange&& out, const NamedParameters& np = parameters::default_values()) const
  {
    if constexpr(internal::Is_random_access_range<InputRange>::value) {
      check_sources(static_cast<std::size_t>(std::distance(std::begin(in), std::end(in))));
      internal::resize_output(out, number_of_stencils(), "the stencil table's output");
      const auto source = std::begin(in);
      auto target = std::begin(out);
      loop_for(np).for_range(number_of_stencils(), 4096, [&](std::size_t first, std::size_t last) {
        for(std::size_t i = first; i < last; ++i)
          target[i] = evaluate(source, i);
      });
    } else {
      using Value = typename std::iterator_traits<decltype(std::begin(in))>::value_type;
      apply(std::vector<Value>(std::begin(in), std::end(in)), out, np);
    }
  }

  /*!
   * the same through property maps: the sources are `get(input_map, k)` for
   * the keys `k` of `input_keys` in order, and `put(output_map, k, value)`
   * stores stencil i's value for the i-th key of `output_keys`. A table of
   * `make_stencil_table(coarse, mask, parameters::refined_mesh(fine))` takes
   * `vertices(coarse)` and gives `vertices(fine)`, each in iteration order.
   */
  template <class InputKeys, class InputMap, class OutputKeys, class OutputMap,
            class NamedParameters = parameters::Default_named_parameters,
            class = std::enable_if_t<internal::Is_range<InputKeys>::value && internal::Is_range<OutputKeys>::value>>
  void apply(const InputKeys& input_keys, const InputMap& input_map, const OutputKeys& output_keys,
             const OutputMap& output_map, const NamedParameters& np = parameters::default_values()) const
  {
    using Value = typename boost::property_traits<InputMap>::value_type;
    std::vector<Value> in;
    in.reserve(m_sources);
    for(const auto& k : input_keys)
      in.push_back(get(input_map, k));
    const std::size_t outputs = static_cast<std::size_t>(std::distance(std::begin(output_keys), std::end(output_keys)));
    internal::require(outputs == number_of_stencils(), "the stencil table has " + std::to_string(number_of_stencils()) +
                                                         " stencils, but " + std::to_string(outputs) +
                                                         " output keys were given");
    std::vector<Value> out;
    apply(in, out, np);
    std::size_t i = 0;
    for(const auto& k : output_keys)
      put(output_map, k, out[i++]);
  }

  /*!
   * the same on arrays of doubles (positions, normals, colours, UVs, any
   * vector-valued vertex data), for a table of double weights: `in` holds
   * `dimension` doubles per source, `out` receives `dimension` doubles per
   * stencil; the result is the same bit for bit as `apply` on points with
   * double coordinates. Named parameters: `threads(n)`.
   */
  template <class NamedParameters = parameters::Default_named_parameters>
  void apply(const double* in, double* out, std::size_t dimension,
             const NamedParameters& np = parameters::default_values()) const
  {
    apply_flat(
      dimension, [in, dimension](Index s) { return in + std::size_t(s) * dimension; },
      [out, dimension](std::size_t i) { return out + i * dimension; }, loop_for(np));
  }

  /// the same on `std::array<double, N>` values
  template <std::size_t N, class NamedParameters = parameters::Default_named_parameters>
  void apply(const std::vector<std::array<double, N>>& in, std::vector<std::array<double, N>>& out,
             const NamedParameters& np = parameters::default_values()) const
  {
    check_sources(in.size());
    out.resize(number_of_stencils());
    const std::array<double, N>* source = in.data();
    std::array<double, N>* target = out.data();
    apply_flat(
      N, [source](Index s) { return source[s].data(); }, [target](std::size_t i) { return target[i].data(); },
      loop_for(np));
  }

  /// evaluates stencils [first, last) only (e.g. one chunk per thread of
  /// one's own); `in` and `out` are random-access ranges of full size
  template <class InputRange, class OutputRange>
  void apply_range(const InputRange& in, OutputRange& out, std::size_t first, std::size_t last) const
  {
    const auto source = std::begin(in);
    auto target = std::begin(out);
    for(std::size_t i = first; i < last; ++i)
      target[i] = evaluate(source, i);
  }

  /// the value of stencil i on the sources `in[0], in[1], ...` (a random-access
  /// iterator or range)
  template <class Sources>
  auto evaluate(const Sources& sources, std::size_t i) const
  {
    const auto in = internal::begin_of(sources);
    using Value = std::decay_t<decltype(in[0])>;
    const std::size_t begin = stencil_begin(i), end = stencil_end(i);
    if(begin == end) // a row of no terms: zero, as in apply()
      return zero_of<Value>();
    if constexpr(internal::Is_point<Value>::value && internal::Is_double_point_3<Value>::value &&
                 std::is_same<FT, double>::value) {
      // three doubles: the operations of the vector sum below, without the kernel's objects
      const Value& p = in[m_indices[begin]];
      const double w0 = m_weights[begin];
      double x = p.x() * w0, y = p.y() * w0, z = p.z() * w0;
      for(std::size_t t = begin + 1; t < end; ++t) {
        const Value& q = in[m_indices[t]];
        const double w = m_weights[t];
        x = x + q.x() * w;
        y = y + q.y() * w;
        z = z + q.z() * w;
      }
      return Value(x, y, z);
    } else if constexpr(internal::Is_point<Value>::value) {
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
  friend struct internal::Stencil_table_access;

  // the value of a stencil without terms: the origin, the null vector or zero
  template <class Value>
  static Value zero_of()
  {
    if constexpr(internal::Is_point<Value>::value)
      return Value(CGAL::ORIGIN);
    else if constexpr(std::is_constructible<Value, CGAL::Null_vector>::value)
      return Value(CGAL::NULL_VECTOR);
    else if constexpr(std::is_arithmetic<Value>::value || std::is_same<Value, FT>::value)
      return Value(0);
    else
      return Value{};
  }

  // evaluates stencils [first, last) on values of `dimension` doubles, from
  // in(s) (a pointer to source s's values) to out(i)
  template <int D, class In, class Out>
  void apply_rows(std::size_t first, std::size_t last, std::size_t dimension, const In& in, const Out& out) const
  {
    const std::size_t* ends = m_ends.data();
    const Index* indices = m_indices.data();
    const FT* weights = m_weights.data();
    const std::size_t n = D > 0 ? std::size_t(D) : dimension;
    for(std::size_t i = first; i < last; ++i) {
      const std::size_t begin = i == 0 ? 0 : ends[i - 1], end = ends[i];
      double* o = out(i);
      if(begin == end) {
        for(std::size_t d = 0; d < n; ++d)
          o[d] = 0;
        continue;
      }
      if constexpr(D == 3) { // positions, normals: three named sums, kept in registers
        const double* x = in(indices[begin]);
        const double w0 = weights[begin];
        double a = x[0] * w0, b = x[1] * w0, c = x[2] * w0;
        for(std::size_t t = begin + 1; t < end; ++t) {
          const double* y = in(indices[t]);
          const double w = weights[t];
          a = a + y[0] * w;
          b = b + y[1] * w;
          c = c + y[2] * w;
        }
        o[0] = a;
        o[1] = b;
        o[2] = c;
      } else if constexpr(D > 0) {
        double acc[D];
        const double* x = in(indices[begin]);
        const double w0 = weights[begin];
        for(int d = 0; d < D; ++d)
          acc[d] = x[d] * w0;
        for(std::size_t t = begin + 1; t < end; ++t) {
          const double* y = in(indices[t]);
          const double w = weights[t];
          for(int d = 0; d < D; ++d)
            acc[d] = acc[d] + y[d] * w;
        }
        for(int d = 0; d < D; ++d)
          o[d] = acc[d];
      } else {
        const double* x = in(indices[begin]);
        const double w0 = weights[begin];
        for(std::size_t d = 0; d < n; ++d)
          o[d] = x[d] * w0;
        for(std::size_t t = begin + 1; t < end; ++t) {
          const double* y = in(indices[t]);
          const double w = weights[t];
          for(std::size_t d = 0; d < n; ++d)
            o[d] = o[d] + y[d] * w;
        }
      }
    }
  }

  // exact numbers: one thread
  template <class NamedParameters>
  internal::Parallel_loop loop_for(const NamedParameters& np) const
  {
    if constexpr(std::is_floating_point<FT>::value)
      return internal::parallel_loop(np);
    else
      return internal::Parallel_loop(1);
  }

  template <class In, class Out>
  void apply_flat(std::size_t dimension, const In& in, const Out& out, const internal::Parallel_loop& loop) const
  {
    static_assert(std::is_same<FT, double>::value, "the flat apply needs a table of double weights");
    loop.for_range(number_of_stencils(), 4096, [&](std::size_t first, std::size_t last) {
      switch(dimension) {
        case 1:
          apply_rows<1>(first, last, 1, in, out);
          break;
        case 2:
          apply_rows<2>(first, last, 2, in, out);
          break;
        case 3:
          apply_rows<3>(first, last, 3, in, out);
          break;
        case 4:
          apply_rows<4>(first, last, 4, in, out);
          break;
        default:
          apply_rows<0>(first, last, dimension, in, out);
      }
    });
  }

  std::size_t m_sources;
  internal::Raw_array<std::size_t> m_ends; // one past the last term of each stencil
  internal::Raw_array<Index> m_indices;
  internal::Value_array<FT> m_weights;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_STENCIL_TABLE_H
