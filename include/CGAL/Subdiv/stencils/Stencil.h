// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_STENCIL_H
#define CGAL_SUBDIV_STENCIL_H

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivStencils
 * A stencil: the list of `(source, weight)` pairs that make one new point,
 * new = sum_i weight_i * source_i.
 *
 * It is also the simplest model of the `SubdivisionAccumulator` concept
 * through which every mask of the package reports its weights: a mask calls
 * `acc.add(source, weight)` once per contribution, and knows nothing of what
 * the accumulator does with it (sum points, record a stencil, fill a matrix).
 * `add` merges contributions of the same source, so that a stencil never
 * lists a source twice.
 *
 * \tparam Source what a weight refers to: an offset (`int`) for curve masks,
 *         a vertex index for surface masks
 * \tparam FT the number type of the weights
 */
template <class Source, class FT>
class Stencil
{
public:
  using Term = std::pair<Source, FT>;

  void add(const Source& source, const FT& weight)
  {
    for(Term& term : m_terms)
      if(term.first == source) {
        term.second += weight;
        return;
      }
    m_terms.emplace_back(source, weight);
  }

  /// room for `n` terms, so that adding them allocates once
  void reserve(std::size_t n) { m_terms.reserve(n); }

  const std::vector<Term>& terms() const { return m_terms; }
  typename std::vector<Term>::const_iterator begin() const { return m_terms.begin(); }
  typename std::vector<Term>::const_iterator end() const { return m_terms.end(); }
  std::size_t size() const { return m_terms.size(); }
  bool empty() const { return m_terms.empty(); }
  void clear() { m_terms.clear(); }

  /// the weight of `source`, zero if it does not contribute
  FT weight(const Source& source) const
  {
    for(const Term& term : m_terms)
      if(term.first == source)
        return term.second;
    return FT(0);
  }

  FT weight_sum() const
  {
    FT sum(0);
    for(const Term& term : m_terms)
      sum += term.second;
    return sum;
  }

private:
  std::vector<Term> m_terms;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_STENCIL_H
