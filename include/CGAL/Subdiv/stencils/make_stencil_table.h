// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MAKE_STENCIL_TABLE_H
#define CGAL_SUBDIV_MAKE_STENCIL_TABLE_H

#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/stencils/Stencil.h>
#include <CGAL/Subdiv/stencils/Stencil_table.h>
#include <CGAL/Subdiv/subdivide.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

template <class T>
struct Non_deduced
{
  using type = T;
};

struct Stencil_table_access
{
  template <class FT>
  static auto& ends(Stencil_table<FT>& t)
  {
    return t.m_ends;
  }
  template <class FT>
  static auto& indices(Stencil_table<FT>& t)
  {
    return t.m_indices;
  }
  template <class FT>
  static auto& weights(Stencil_table<FT>& t)
  {
    return t.m_weights;
  }
};

// records a mask's weights by ordinal of the old vertex
template <class Mesh, class FT>
struct Ordinal_stencil
{
  const Mesh_numbering<Mesh>& number;
  Stencil<std::size_t, FT> stencil;

  void add(typename boost::graph_traits<Mesh>::vertex_descriptor v, const FT& w) { stencil.add(number(v), w); }
};

/*
 * What one thread needs to compose rows: the mask's report of one new vertex,
 * merged by old vertex (as `Stencil::add` merges), and a dense accumulator
 * over the coarse vertices, whose entries are valid where their stamp holds
 * the current row's generation (so nothing is cleared between rows).
 */
template <class FT>
struct Compose_scratch
{
  using Index = std::uint32_t;
  std::vector<std::pair<Index, FT>> report;
  // the accumulator: sum and stamp side by side (one cache line for both:
  // better than two arrays when the coarse vertices outgrow the caches)
  struct Entry
  {
    FT sum;
    std::uint32_t stamp;
  };
  std::vector<Entry> entries;
  std::vector<Index> indices; // a row made outside a table (the two passes)
  std::vector<FT> weights;
  std::uint32_t generation = 0;

  void prepare(std::size_t sources)
  {
    if(entries.size() != sources) {
      entries.assign(sources, Entry{FT(0), 0});
      generation = 0;
    }
  }
  std::uint32_t next_generation()
  {
    if(++generation == 0) { // wrapped: forget every stamp
      for(Entry& e : entries)
        e.stamp = 0;
      generation = 1;
    }
    return generation;
  }
};

// the accumulator the mask reports to: merges repeated old vertices
template <class Numbering, class FT>
struct Merging_report
{
  const Numbering& number;
  std::vector<std::pair<std::uint32_t, FT>>& terms;
  std::size_t size = 0; // terms[0, size) are the report so far

  template <class VertexDescriptor>
  void add(VertexDescriptor v, const FT& w)
  {
    const auto s = static_cast<std::uint32_t>(number(v));
    auto* term = terms.data();
    for(std::size_t i = 0; i < size; ++i)
      if(term[i].first == s) {
        term[i].second += w;
        return;
      }
    if(size == terms.size())
      terms.resize(2 * size + 16);
    terms[size].first = s;
    terms[size].second = w;
    ++size;
  }
};

/*
 * Rows of a table being made: row ends, source indices and weights, appended
 * row by row. A row opens room for as many terms as it may have (its terms
 * are written in place, no copy) and is closed with the number it has; the
 * room of the terms grows by doubling (untouched room costs address space
 * only).
 */
template <class FT>
struct Row_sink
{
  using Index = std::uint32_t;
  // double weights: the arrays are kept at the size of their room (nothing is
  // initialised) and cut to their terms at the end; exact numbers: they grow
  // row by row (no room of constructed numbers)
  static constexpr bool raw = std::is_trivially_copyable<FT>::value;
  Raw_array<std::size_t>& ends;
  Raw_array<Index>& indices;
  Value_array<FT>& weights;
  std::size_t rows = 0; // rows closed
  std::size_t size = 0; // terms of the closed rows
  std::size_t room = 0;

  /// room for `row_count` rows (exactly) and `terms` terms (to begin with)
  void reserve(std::size_t row_count, std::size_t terms)
  {
    resize_for_overwrite(ends, rows + row_count);
    reserve_terms(terms);
  }
  void reserve_terms(std::size_t n)
  {
    if(n <= room)
      return;
    resize_for_overwrite(indices, size); // only the terms so far are moved
    resize_for_overwrite(weights, size);
    indices.reserve(n);
    weights.reserve(n);
    if constexpr(raw) {
      resize_for_overwrite(indices, n);
      resize_for_overwrite(weights, n);
    }
    room = n;
  }
  /// room for at most `most` terms of the next row: where its indices and weights go
  std::pair<Index*, FT*> open(std::size_t most)
  {
    if(size + most > room)
      reserve_terms((std::max)(2 * room, size + most));
    if constexpr(!raw) {
      resize_for_overwrite(indices, size + most);
      resize_for_overwrite(weights, size + most);
    }
    return {indices.data() + size, weights.data() + size};
  }
  void close(std::size_t count)
  {
    size += count;
    if(rows == ends.size()) // more rows than reserved (a host with several per element)
      resize_for_overwrite(ends, 2 * rows + 16);
    ends[rows++] = size;
  }
  void finish()
  {
    resize_for_overwrite(ends, rows);
    resize_for_overwrite(indices, size);
    resize_for_overwrite(weights, size);
  }
};

/*
 * The rows of one chunk of new vertices, made by one thread in the parallel
 * single pass: consecutive new vertices from `first` on, with their own
 * arrays, copied into the table at the end.
 */
template <class FT>
struct Row_chunk
{
  std::size_t first = 0, rows = 0;
  bool in_order = true;
  Compose_scratch<FT>* scratch = nullptr; // of the thread that makes the chunk
  Raw_array<std::size_t> ends;
  Raw_array<std::uint32_t> indices;
  Value_array<FT> weights;
  Row_sink<FT> sink{ends, indices, weights};
};

/// the chunk the calling thread is filling, if any (see `Chunked_loop`)
template <class FT>
Row_chunk<FT>*& current_chunk()
{
  static thread_local Row_chunk<FT>* chunk = nullptr;
  return chunk;
}

/*
 * The loop given to a host's `for_each_new_vertex` in the parallel single
 * pass: splits each of its loops into pieces of `piece` elements, run in
 * parallel by `loop`, and records a `Row_chunk` per piece (in the order of
 * the loops and pieces, which is the order of the new vertices for the hosts
 * of the package); while a piece runs, `current_chunk()` is its chunk in the
 * thread that runs it.
 */
template <class FT>
class Chunked_loop : public Parallel_loop // what it does not redefine runs unchunked: the two passes then
{
public:
  Chunked_loop(const Parallel_loop& loop, std::size_t piece, std::size_t room_per_row,
               std::vector<std::unique_ptr<Row_chunk<FT>>>& chunks, Per_thread<Compose_scratch<FT>>& scratches)
    : Parallel_loop(loop), m_piece(piece), m_room_per_row(room_per_row), m_chunks(chunks), m_scratches(scratches)
  {}

  template <class F>
  void for_range(std::size_t n, std::size_t, const F& f) const
  {
    const std::size_t pieces = (n + m_piece - 1) / m_piece, base = m_chunks.size();
    for(std::size_t p = 0; p < pieces; ++p)
      m_chunks.push_back(std::make_unique<Row_chunk<FT>>());
    Parallel_loop::for_range(pieces, 1, [&](std::size_t first, std::size_t last) {
      for(std::size_t p = first; p < last; ++p) {
        Row_chunk<FT>* chunk = m_chunks[base + p].get();
        const std::size_t begin = p * m_piece, end = (std::min)(n, begin + m_piece);
        chunk->sink.reserve(end - begin, (end - begin) * m_room_per_row);
        chunk->scratch = &m_scratches.local();
        struct Current // the chunk of this thread while f runs (even if it throws)
        {
          Row_chunk<FT>* const outer = current_chunk<FT>();
          explicit Current(Row_chunk<FT>* c) { current_chunk<FT>() = c; }
          ~Current() { current_chunk<FT>() = outer; }
        } current(chunk);
        f(begin, end);
      }
    });
  }

private:
  std::size_t m_piece, m_room_per_row;
  std::vector<std::unique_ptr<Row_chunk<FT>>>& m_chunks;
  Per_thread<Compose_scratch<FT>>& m_scratches;
};

/*
 * One level composed with the table of the levels before (`coarse`, from the
 * coarse vertices to the old vertices of this level; null for the first
 * level): row j of the result is sum over the mask's terms (v, w) of new
 * vertex j of w * row v of `coarse`, its terms in the order in which they
 * first appear (the order and the arithmetic of `Stencil_table::then`, so the
 * table is the same as composing the level tables one by one).
 *
 * Every row is made once, its terms written in place: in one thread, rows
 * are appended to the table in the order the host visits them; in parallel,
 * each piece of the host's loops is appended to a chunk of its own, and the
 * chunks are copied into the table (in parallel) at the end. When a host does
 * not visit its new vertices in order (a sqrt3 step that refines a border),
 * rows are made in two passes: lengths, then terms at their place.
 */
template <class FT, class Host, class Mask, class Numbering>
Stencil_table<FT> compose_level(const Host& host, const Mask& mask, const Numbering& number,
                                const Stencil_table<FT>* coarse, std::size_t sources, const Parallel_loop& loop)
{
  using Index = std::uint32_t;
  using Access = Stencil_table_access;
  const std::size_t rows = host.number_of_new_vertices();
  Stencil_table<FT> table(sources);
  auto& ends = Access::ends(table);
  auto& indices = Access::indices(table);
  auto& weights = Access::weights(table);
  const std::size_t* coarse_ends = coarse ? Access::ends(const_cast<Stencil_table<FT>&>(*coarse)).data() : nullptr;
  const Index* coarse_indices = coarse ? Access::indices(const_cast<Stencil_table<FT>&>(*coarse)).data() : nullptr;
  const FT* coarse_weights = coarse ? Access::weights(const_cast<Stencil_table<FT>&>(*coarse)).data() : nullptr;

  // makes new vertex j's row at open(most), room for at most `most` terms
  // (a pair of pointers: indices, weights); returns its number of terms
  const auto compose = [&](Compose_scratch<FT>& scratch, const auto& report, const auto& open) -> std::size_t {
    Merging_report<Numbering, FT> acc{number, scratch.report};
    report(acc);
    const std::pair<Index, FT>* terms = scratch.report.data();
    if(coarse == nullptr) {
      const auto out = open(acc.size);
      for(std::size_t k = 0; k < acc.size; ++k) {
        out.first[k] = terms[k].first;
        out.second[k] = terms[k].second;
      }
      return acc.size;
    }
    if(acc.size == 0)
      return 0;
    std::size_t most = 0;
    for(std::size_t k = 0; k < acc.size; ++k)
      most += coarse_ends[terms[k].first] - (terms[k].first == 0 ? 0 : coarse_ends[terms[k].first - 1]);
    const auto out = open(most);
    Index* out_indices = out.first;
    scratch.prepare(sources);
    const std::uint32_t generation = scratch.next_generation();
    auto* entries = scratch.entries.data();
    const Index* from = coarse_indices;
    const FT* from_weights = coarse_weights;
    std::size_t count = 0;
    { // the first row brings only new sources (a row lists each source once)
      const Index v = terms[0].first;
      const FT w = terms[0].second;
      const std::size_t begin = v == 0 ? 0 : coarse_ends[v - 1], end = coarse_ends[v];
      for(std::size_t t = begin; t < end; ++t) {
        const Index s = from[t];
        entries[s].stamp = generation;
        out_indices[count++] = s;
        entries[s].sum = w * from_weights[t];
      }
    }
    for(std::size_t k = 1; k < acc.size; ++k) {
      const Index v = terms[k].first;
      const FT w = terms[k].second;
      const std::size_t begin = v == 0 ? 0 : coarse_ends[v - 1], end = coarse_ends[v];
      for(std::size_t t = begin; t < end; ++t) {
        const Index s = from[t];
        if(entries[s].stamp != generation) {
          entries[s].stamp = generation;
          out_indices[count++] = s;
          entries[s].sum = w * from_weights[t];
        } else {
          entries[s].sum += w * from_weights[t];
        }
      }
    }
    FT* out_weights = out.second;
    for(std::size_t c = 0; c < count; ++c)
      out_weights[c] = entries[out_indices[c]].sum;
    return count;
  };

  // room for the terms: twice the mean row of the levels before, which grows
  // less than that from level to level
  const std::size_t mean =
    coarse ? coarse->number_of_terms() / (std::max<std::size_t>)(1, coarse->number_of_stencils()) : 0;
  const std::size_t room_per_row = (std::max<std::size_t>)(16, 2 * mean + 4);

  if(!loop.is_parallel()) {
    Compose_scratch<FT> scratch;
    Row_sink<FT> sink{ends, indices, weights};
    sink.reserve(rows, rows * room_per_row);
    bool in_order = true;
    host.for_each_new_vertex(mask, [&](std::size_t j, const auto& report) {
      if(!in_order || j != sink.rows) {
        in_order = false;
        return;
      }
      sink.close(compose(scratch, report, [&](std::size_t most) { return sink.open(most); }));
    });
    sink.finish();
    if(in_order && sink.rows == rows)
      return table;
    ends.clear();
    indices.clear();
    weights.clear();
  } else {
    // one pass: each piece of the host's loops into a chunk of its own
    std::vector<std::unique_ptr<Row_chunk<FT>>> chunks;
    Per_thread<Compose_scratch<FT>> scratches;
    const std::size_t piece = 4096;
    const Chunked_loop<FT> chunked(loop, piece, room_per_row, chunks, scratches);
    host.for_each_new_vertex(
      mask,
      [&](std::size_t j, const auto& report) {
        Row_chunk<FT>* chunk = current_chunk<FT>();
        if(chunk == nullptr || !chunk->in_order)
          return;
        if(chunk->rows == 0)
          chunk->first = j;
        else if(j != chunk->first + chunk->rows) {
          chunk->in_order = false;
          return;
        }
        Row_sink<FT>& sink = chunk->sink;
        sink.close(compose(*chunk->scratch, report, [&](std::size_t most) { return sink.open(most); }));
        ++chunk->rows;
      },
      chunked);
    // the chunks must hold every row once, in order
    std::vector<std::size_t> offsets(chunks.size() + 1, 0);
    bool whole = true;
    std::size_t next = 0;
    for(std::size_t c = 0; c < chunks.size() && whole; ++c) {
      const Row_chunk<FT>& chunk = *chunks[c];
      whole = chunk.in_order && (chunk.rows == 0 || chunk.first == next);
      next += chunk.rows;
      offsets[c + 1] = offsets[c] + chunk.sink.size;
    }
    if(whole && next == rows) {
      resize_for_overwrite(ends, rows);
      resize_for_overwrite(indices, offsets.back());
      resize_for_overwrite(weights, offsets.back());
      loop.for_range(chunks.size(), 1, [&](std::size_t first, std::size_t last) {
        for(std::size_t c = first; c < last; ++c) {
          Row_chunk<FT>& chunk = *chunks[c];
          const std::size_t offset = offsets[c];
          std::copy(chunk.indices.data(), chunk.indices.data() + chunk.sink.size, indices.data() + offset);
          std::copy(chunk.weights.data(), chunk.weights.data() + chunk.sink.size, weights.data() + offset);
          for(std::size_t r = 0; r < chunk.rows; ++r)
            ends[chunk.first + r] = offset + chunk.ends[r];
          chunks[c].reset();
        }
      });
      return table;
    }
  }

  // two passes: lengths, then terms
  resize_for_overwrite(ends, rows);
  Per_thread<Compose_scratch<FT>> scratches;
  const auto in_scratch = [](Compose_scratch<FT>& scratch) {
    return [&scratch](std::size_t most) {
      if(scratch.indices.size() < most) {
        scratch.indices.resize(2 * most);
        scratch.weights.resize(2 * most);
      }
      return std::make_pair(scratch.indices.data(), scratch.weights.data());
    };
  };
  host.for_each_new_vertex(
    mask,
    [&](std::size_t j, const auto& report) {
      Compose_scratch<FT>& scratch = scratches.local();
      ends[j] = compose(scratch, report, in_scratch(scratch));
    },
    loop);
  std::size_t total = 0;
  for(std::size_t j = 0; j < rows; ++j) {
    total += ends[j];
    ends[j] = total;
  }
  resize_for_overwrite(indices, total);
  resize_for_overwrite(weights, total);
  Index* out_indices = indices.data();
  FT* out_weights = weights.data();
  host.for_each_new_vertex(
    mask,
    [&](std::size_t j, const auto& report) {
      Compose_scratch<FT>& scratch = scratches.local();
      const std::size_t t = j == 0 ? 0 : ends[j - 1];
      const std::size_t count = compose(scratch, report, in_scratch(scratch));
      std::copy(scratch.indices.data(), scratch.indices.data() + count, out_indices + t);
      std::copy(scratch.weights.data(), scratch.weights.data() + count, out_weights + t);
    },
    loop);
  return table;
}

// the new topology of one level, points left as they are (Surface_mesh: the
// new vertices' points are default values; other meshes: the origin)
template <class Host, class Mesh, class VertexPointMap>
void refine_topology(const Host& host, Mesh& mesh, const VertexPointMap& vpm, const Parallel_loop&)
{
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  const Face_soup soup = host.faces();
  rebuild_mesh(mesh, vpm, std::vector<Point>(soup.number_of_vertices(), Point(CGAL::ORIGIN)), soup);
}

template <class Host, class P, class VertexPointMap>
void refine_topology(const Host& host, CGAL::Surface_mesh<P>& mesh, const VertexPointMap&, const Parallel_loop& loop)
{
  using SM = CGAL::Surface_mesh<P>;
  using size_type = typename SM::size_type;
  if constexpr(Wires_from_snapshot<Host>::value) { // the edge splits: no soup, as `refine_once` does
    const std::size_t old_vertices = num_vertices(mesh);
    const Split_snapshot snapshot = host.snapshot(loop, true);
    mesh.resize(static_cast<size_type>(host.number_of_new_vertices()),
                static_cast<size_type>(host.number_of_new_edges()), static_cast<size_type>(host.number_of_new_faces()));
    wire_split(mesh, host, snapshot, old_vertices, loop);
  } else {
    const Face_soup soup = host.faces(loop, false);
    mesh.resize(static_cast<size_type>(soup.number_of_vertices()), static_cast<size_type>(soup.number_of_edges()),
                static_cast<size_type>(soup.number_of_faces()));
    wire_surface_mesh(mesh, soup, loop);
  }
}

// One level on `mesh`: returns the level's stencil table (new vertex -> old
// vertices, by ordinal) and replaces `mesh` by the refined topology. Points of
// the refined mesh are left at the origin: the caller computes them.
template <class Mask, class Mesh, class VertexPointMap>
Stencil_table<typename Mask::Number_type> refine_topology_once(Mesh& mesh, const Mask& mask, const VertexPointMap& vpm)
{
  using FT = typename Mask::Number_type;
  const Host_of<Mask> host(mesh);
  const Mesh_numbering<Mesh> number(mesh);
  Stencil_table<FT> table = compose_level<FT>(host, mask, number, static_cast<const Stencil_table<FT>*>(nullptr),
                                              num_vertices(mesh), Parallel_loop(1));
  refine_topology(host, mesh, vpm, Parallel_loop(1));
  return table;
}

} // namespace internal

/*!
 * \ingroup PkgSubdivStencils
 * composes `levels` levels of the scheme of `mask` on the topology of `mesh`
 * into one table: stencil i gives vertex i of the refined mesh (in the order
 * `subdivide()` creates them) from the vertices of `mesh` (in its iteration
 * order). Then `table.apply(coarse_points, refined_points)` re-evaluates the
 * refined points for moved control points in one pass, and the same table
 * carries any other per-vertex data.
 *
 * If `refined_mesh` is given, it receives the refined mesh, with the points
 * that the table gives for the current points of `mesh`.
 *
 * The stencils come from the same masks as `subdivide()`, so applying the
 * table to the points of `mesh` gives exactly the points of `subdivide()`
 * (exactly, in an exact kernel).
 *
 * How: each level's rows are composed at once with the table of the levels
 * before (a mask's terms times rows of that table, summed in a dense
 * accumulator), without building the level's own table; only the topology of
 * the levels before the last is refined (and the last one's when
 * `refined_mesh` is asked for), without points. Named parameters:
 * `vertex_point_map`, and `threads` (`CGAL::Subdiv::threads(n)`; with TBB, a
 * `Surface_mesh` and double weights, the levels are composed in parallel; the
 * table is the same with any number of threads).
 * \throws Bad_input as `subdivide()` does.
 */
template <class PolygonMesh, class Mask, class NamedParameters = parameters::Default_named_parameters>
Stencil_table<typename Mask::Number_type> make_stencil_table(
  const PolygonMesh& mesh, const Mask& mask, int levels,
  typename internal::Non_deduced<PolygonMesh>::type* refined_mesh = nullptr,
  const NamedParameters& np = parameters::default_values())
{
  using FT = typename Mask::Number_type;
  using Host = Host_of<Mask>;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm =
    choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, mesh));
  internal::check_mesh(mesh, vpm, mask.name(), Host::required_face_size);
  internal::check_output_faces(mask.name(), static_cast<double>(num_faces(mesh)), Host::face_growth(), levels);

  internal::require(!internal::has_garbage(mesh), "make_stencil_table: call collect_garbage() on the mesh first");
  const internal::Parallel_loop loop =
    std::is_floating_point<FT>::value ? internal::parallel_loop(np) : internal::Parallel_loop(1);
  const std::size_t sources = num_vertices(mesh);
  if(levels == 0 && refined_mesh == nullptr)
    return Stencil_table<FT>::identity(sources);

  const int topology_levels = refined_mesh != nullptr ? levels : levels - 1;
  if(topology_levels == 0 && levels == 1) { // the input's topology is all it needs: no copy
    const Host host(mesh);
    const internal::Mesh_numbering<PolygonMesh> number(mesh);
    return internal::compose_level<FT>(host, mask, number, static_cast<const Stencil_table<FT>*>(nullptr), sources,
                                       loop);
  }
  PolygonMesh work = mesh;
  const auto work_vpm = get(CGAL::vertex_point, work);
  internal::reserve_levels<Host>(work, topology_levels);
  Stencil_table<FT> table = levels == 0 ? Stencil_table<FT>::identity(sources) : Stencil_table<FT>(sources);
  for(int level = 0; level < levels; ++level) {
    const Host host(work);
    const internal::Mesh_numbering<PolygonMesh> number(work);
    table = internal::compose_level<FT>(host, mask, number, level == 0 ? nullptr : &table, sources, loop);
    if(level < topology_levels)
      internal::refine_topology(host, work, work_vpm, loop);
  }

  if(refined_mesh != nullptr) {
    using Point = typename boost::property_traits<decltype(work_vpm)>::value_type;
    std::vector<Point> coarse, fine;
    for(auto v : vertices(mesh))
      coarse.push_back(get(vpm, v));
    table.apply(coarse, fine, loop.threads());
    std::size_t i = 0;
    for(auto v : vertices(work))
      put(work_vpm, v, fine[i++]);
    *refined_mesh = std::move(work);
  }
  return table;
}

/// `make_stencil_table(mesh, mask, levels, nullptr, np)`:
/// `make_stencil_table(mesh, mask, 3, CGAL::Subdiv::threads(2))`
template <class PolygonMesh, class Mask, class T, class Tag, class Base>
Stencil_table<typename Mask::Number_type> make_stencil_table(const PolygonMesh& mesh, const Mask& mask, int levels,
                                                             const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return make_stencil_table(mesh, mask, levels, static_cast<PolygonMesh*>(nullptr), np);
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MAKE_STENCIL_TABLE_H
