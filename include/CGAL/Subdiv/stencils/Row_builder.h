// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_STENCILS_ROW_BUILDER_H
#define CGAL_SUBDIV_STENCILS_ROW_BUILDER_H

/// \file Row_builder.h
/// The sparse-row kernel: everywhere rows of weights are combined (a level's
/// stencils composed with the table of the levels before, two tables chained,
/// limit rows composed with level stencils, the analysis' double steps), a
/// row is the sum of weighted rows, made by this builder. Its terms come in
/// the order in which their sources first appear, each summed in the order of
/// the contributions, so every composition gives the same numbers bit for bit.
/// (Merging one mask's repeated vertices is `Stencil::add`.)

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * A dense accumulator over the sources (0..sources-1) whose entries are
 * valid where their stamp holds the current row's generation, so nothing is
 * cleared between rows: `start()` a row, add weights or weighted rows, read
 * the terms with `size()`, `source(i)` and `weight(i)`, or write their
 * weights out with `write_weights`. The sources of the terms are written, as
 * they first appear, where `start` says: straight into a table being made, or
 * into the builder's own room.
 */
template <class FT>
class Row_builder
{
public:
  using Index = std::uint32_t;

  /// starts a new row over `sources` sources, with room for `room` terms;
  /// the sources of its terms go to `order` (room for `room` of them) or, if
  /// null, to the builder's own room
  void start(std::size_t sources, std::size_t room, Index* order = nullptr)
  {
    if(m_entries.size() != sources) {
      m_entries.assign(sources, Entry{FT(0), 0});
      m_generation = 0;
    }
    if(++m_generation == 0) { // wrapped: forget every stamp
      for(Entry& e : m_entries)
        e.stamp = 0;
      m_generation = 1;
    }
    if(order == nullptr) {
      if(m_room.size() < room)
        m_room.resize(2 * room);
      order = m_room.data();
    }
    m_order = order;
    m_size = 0;
  }

  /// adds w to the weight of source s
  void add(Index s, const FT& w) { add_to(m_entries.data(), m_order, m_generation, m_size, s, w); }

  /// adds w times a row, given as terms [begin, end) of parallel arrays
  /// `sources` and `weights`
  void add_row(const Index* sources, const FT* weights, std::size_t begin, std::size_t end, const FT& w)
  {
    // the members in locals: the stores of stamps and sources (32-bit) would
    // otherwise make the compiler reload the generation after each of them
    Entry* const entries = m_entries.data();
    Index* const order = m_order;
    const std::uint32_t generation = m_generation;
    std::size_t size = m_size;
    for(std::size_t t = begin; t < end; ++t)
      add_to(entries, order, generation, size, sources[t], w * weights[t]);
    m_size = size;
  }

  /// the same for the first row of a sum, whose sources all are new (a row
  /// lists each source once): no stamp is read
  void add_first_row(const Index* sources, const FT* weights, std::size_t begin, std::size_t end, const FT& w)
  {
    Entry* const entries = m_entries.data();
    Index* const order = m_order;
    const std::uint32_t generation = m_generation;
    std::size_t size = m_size;
    for(std::size_t t = begin; t < end; ++t) {
      const Index s = sources[t];
      entries[s].stamp = generation;
      order[size++] = s;
      entries[s].sum = w * weights[t];
    }
    m_size = size;
  }

  /// adds w times a row given as a range of (source, weight), the sources
  /// turned into indices by `index_of`
  template <class Terms, class IndexOf>
  void add_terms(const Terms& terms, const FT& w, const IndexOf& index_of)
  {
    for(const auto& term : terms)
      add(static_cast<Index>(index_of(term.first)), w * term.second);
  }

  std::size_t size() const { return m_size; }
  Index source(std::size_t i) const { return m_order[i]; }
  const FT& weight(std::size_t i) const { return m_entries[m_order[i]].sum; }

  /// writes the weights of the row's terms, in their order, to `weights`
  void write_weights(FT* weights) const
  {
    for(std::size_t i = 0; i < m_size; ++i)
      weights[i] = m_entries[m_order[i]].sum;
  }

private:
  // sum and stamp side by side: one cache line for both, better than two
  // arrays when the sources outgrow the caches
  struct Entry
  {
    FT sum;
    std::uint32_t stamp;
  };
  // the one accumulation step: a new source is stamped and listed, a listed one summed
  static void add_to(Entry* entries, Index* order, std::uint32_t generation, std::size_t& size, Index s, const FT& w)
  {
    Entry& e = entries[s];
    if(e.stamp != generation) {
      e.stamp = generation;
      order[size++] = s;
      e.sum = w;
    } else {
      e.sum += w;
    }
  }

  std::vector<Entry> m_entries;
  std::vector<Index> m_room;
  Index* m_order = nullptr;
  std::size_t m_size = 0;
  std::uint32_t m_generation = 0;
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_STENCILS_ROW_BUILDER_H
