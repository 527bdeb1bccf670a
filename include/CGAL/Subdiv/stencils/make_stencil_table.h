// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MAKE_STENCIL_TABLE_H
#define CGAL_SUBDIV_MAKE_STENCIL_TABLE_H

#include <CGAL/Subdiv/hosts/hosts.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/internal/mesh_checks.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/refinement/refine_level.h>
#include <CGAL/Subdiv/stencils/Row_builder.h>
#include <CGAL/Subdiv/stencils/Stencil.h>
#include <CGAL/Subdiv/stencils/Stencil_table.h>
#include <CGAL/Subdiv/views/Sharpness_tags.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

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

// the accumulator a mask reports to: old vertices by ordinal, merged (`Stencil::add`)
template <class Numbering, class Stencil>
struct Numbered_report
{
  const Numbering& number;
  Stencil& stencil;

  template <class VertexDescriptor, class FT>
  void add(VertexDescriptor v, const FT& w)
  {
    stencil.add(static_cast<std::uint32_t>(number(v)), w);
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
    ends[rows++] = size;
  }
  void finish()
  {
    resize_for_overwrite(ends, rows);
    resize_for_overwrite(indices, size);
    resize_for_overwrite(weights, size);
  }
};

/// the rows of consecutive new vertices made by one thread in the parallel
/// pass, in arrays of their own, copied into the table at the end
template <class FT>
struct Row_chunk
{
  std::size_t first = 0, rows = 0;
  Raw_array<std::size_t> ends;
  Raw_array<std::uint32_t> indices;
  Value_array<FT> weights;
  Row_sink<FT> sink{ends, indices, weights}; // over the arrays above: not copied, not moved

  Row_chunk() = default;
  Row_chunk(const Row_chunk&) = delete;
  Row_chunk& operator=(const Row_chunk&) = delete;

  void free_arrays()
  {
    ends = Raw_array<std::size_t>();
    indices = Raw_array<std::uint32_t>();
    weights = Value_array<FT>();
  }
};

/// what a thread needs to compose rows: the mask's report of one new vertex,
/// and the row builder over the coarse vertices
template <class FT>
struct Compose_scratch
{
  Stencil<std::uint32_t, FT> report;
  Row_builder<FT> builder;
};

/*
 * A row of terms (v, w) over the old vertices of a level (each v once), times
 * the rows v of `coarse` (the table of the levels before; null for the first
 * level: the terms themselves), written at open(most) as `compose_row` says.
 * Returns the number of terms.
 */
template <class FT, class Terms, class Open>
std::size_t compose_terms(const Terms& terms, const Stencil_table<FT>* coarse, std::size_t sources,
                          Row_builder<FT>& builder, const Open& open)
{
  if(coarse == nullptr) {
    const auto out = open(terms.size());
    for(std::size_t k = 0; k < terms.size(); ++k) {
      out.first[k] = terms[k].first;
      out.second[k] = terms[k].second;
    }
    return terms.size();
  }
  if(terms.empty())
    return 0;
  const std::size_t most = coarse->terms_under(terms);
  const auto out = open(most);
  builder.start(sources, most, out.first);
  const std::uint32_t* from = coarse->source_data();
  const FT* from_weights = coarse->weight_data();
  for(std::size_t k = 0; k < terms.size(); ++k) {
    const std::size_t v = terms[k].first;
    if(k == 0) // the first row brings only new sources
      builder.add_first_row(from, from_weights, coarse->stencil_begin(v), coarse->stencil_end(v), terms[k].second);
    else
      builder.add_row(from, from_weights, coarse->stencil_begin(v), coarse->stencil_end(v), terms[k].second);
  }
  builder.write_weights(out.second);
  return builder.size();
}

/*
 * Row j of a level composed with the table of the levels before (`coarse`,
 * from the coarse vertices to the old vertices of this level; null for the
 * first level): the mask's terms (v, w) of new vertex j, merged by old
 * vertex, times the rows v of `coarse`, written at open(most) (room for at
 * most `most` terms: a pair of pointers, indices and weights). Returns the
 * number of terms.
 */
template <class FT, class Host, class Mask, class Numbering, class Open>
std::size_t compose_row(std::size_t j, const Host& host, const Mask& mask, const Numbering& number,
                        const Stencil_table<FT>* coarse, std::size_t sources, Compose_scratch<FT>& scratch,
                        const Open& open)
{
  scratch.report.clear();
  Numbered_report<Numbering, Stencil<std::uint32_t, FT>> acc{number, scratch.report};
  host.report(j, mask, acc);
  return compose_terms(scratch.report.terms(), coarse, sources, scratch.builder, open);
}

/*
 * One level composed with the table of the levels before (`coarse`; null
 * for the first level): row j of the result is `compose_row(j)`, so the table
 * is the same as composing the level tables one by one with
 * `Stencil_table::then`. Every row is made once, its terms written in place:
 * in one thread, rows are appended to the table in order; in parallel, the
 * loop hands out chunks of `piece` consecutive new vertices, each made into
 * its own arrays, which are copied into the table (in parallel) at the end.
 */
template <class FT, class Host, class Mask, class Numbering>
Stencil_table<FT> compose_level(const Host& host, const Mask& mask, const Numbering& number,
                                const Stencil_table<FT>* coarse, std::size_t sources, const Parallel_loop& loop)
{
  using Access = Stencil_table_access;
  const std::size_t rows = host.number_of_new_vertices();
  Stencil_table<FT> table(sources);
  auto& ends = Access::ends(table);
  auto& indices = Access::indices(table);
  auto& weights = Access::weights(table);
  // room for the terms: twice the mean row of the levels before, which grows
  // less than that from level to level
  const std::size_t mean =
    coarse ? coarse->number_of_terms() / (std::max<std::size_t>)(1, coarse->number_of_stencils()) : 0;
  const std::size_t room_per_row = (std::max<std::size_t>)(16, 2 * mean + 4);

  if(!loop.is_parallel() || !Numbering::dense) {
    Compose_scratch<FT> scratch;
    Row_sink<FT> sink{ends, indices, weights};
    sink.reserve(rows, rows * room_per_row);
    for(std::size_t j = 0; j < rows; ++j)
      sink.close(compose_row(j, host, mask, number, coarse, sources, scratch,
                             [&](std::size_t most) { return sink.open(most); }));
    sink.finish();
    return table;
  }

  const std::size_t piece = 4096;
  std::vector<Row_chunk<FT>> chunks((rows + piece - 1) / piece);
  Per_thread<Compose_scratch<FT>> scratches;
  loop.for_range(chunks.size(), 1, [&](std::size_t first, std::size_t last) {
    Compose_scratch<FT>& scratch = scratches.local();
    for(std::size_t c = first; c < last; ++c) {
      Row_chunk<FT>& chunk = chunks[c];
      chunk.first = c * piece;
      chunk.rows = (std::min)(rows, chunk.first + piece) - chunk.first;
      chunk.sink.reserve(chunk.rows, chunk.rows * room_per_row);
      for(std::size_t j = chunk.first; j < chunk.first + chunk.rows; ++j)
        chunk.sink.close(compose_row(j, host, mask, number, coarse, sources, scratch,
                                     [&](std::size_t most) { return chunk.sink.open(most); }));
    }
  });
  std::vector<std::size_t> offsets(chunks.size() + 1, 0);
  for(std::size_t c = 0; c < chunks.size(); ++c)
    offsets[c + 1] = offsets[c] + chunks[c].sink.size;
  resize_for_overwrite(ends, rows);
  resize_for_overwrite(indices, offsets.back());
  resize_for_overwrite(weights, offsets.back());
  loop.for_range(chunks.size(), 1, [&](std::size_t first, std::size_t last) {
    for(std::size_t c = first; c < last; ++c) {
      Row_chunk<FT>& chunk = chunks[c];
      const std::size_t offset = offsets[c];
      std::copy(chunk.indices.data(), chunk.indices.data() + chunk.sink.size, indices.data() + offset);
      std::copy(chunk.weights.data(), chunk.weights.data() + chunk.sink.size, weights.data() + offset);
      for(std::size_t r = 0; r < chunk.rows; ++r)
        ends[chunk.first + r] = offset + chunk.ends[r];
      chunk.free_arrays();
    }
  });
  return table;
}

/// a sink of `refine_level`: the level composed with the table before
template <class FT>
struct Composed_level
{
  const Stencil_table<FT>* coarse;
  std::size_t sources;
  Stencil_table<FT> table{0};

  template <class Host, class Mask>
  void read(const Host& host, const Mask& mask, const Parallel_loop& loop)
  {
    table = compose_level<FT>(host, mask, host.numbering(), coarse, sources, loop);
  }
  template <class Level>
  void write(const Level&)
  {}
};

} // namespace internal

namespace internal {

/// one level of `mask` on `mesh` with its `tags`, composed with `coarse`
template <class FT, class PolygonMesh, class Mask, class Tags>
Stencil_table<FT> compose_on_host(const PolygonMesh& mesh, const Mask& mask, const Tags& tags,
                                  const Stencil_table<FT>* coarse, std::size_t sources, const Parallel_loop& loop)
{
  return tags.on_level(mesh, mask, [&](const auto& level_mask) {
    const Host_of<Mask> host = make_host(mesh, level_mask);
    return internal::compose_level<FT>(host, level_mask, host.numbering(), coarse, sources, loop);
  });
}

/*
 * The table of `levels` levels of `mask` refined on `work` (a copy of the
 * mesh, its vertices the `sources`), with the sharpness tags `tags` of the
 * copy: the topology of the first `topology_levels` levels is refined on
 * `work`, the last level, if it is not, is composed on its host.
 */
template <class PolygonMesh, class Mask, class Tags>
Stencil_table<typename Mask::Number_type> refined_table(PolygonMesh& work, const Mask& mask, const Tags& tags,
                                                        int levels, int topology_levels, std::size_t sources,
                                                        const Parallel_loop& loop)
{
  using FT = typename Mask::Number_type;
  using Host = Host_of<Mask>;
  const auto work_vpm = get(CGAL::vertex_point, work);
  internal::reserve_levels<Host>(work, topology_levels);
  Stencil_table<FT> table = levels == 0 ? Stencil_table<FT>::identity(sources) : Stencil_table<FT>(sources);
  for(int level = 0; level < levels; ++level) {
    const Stencil_table<FT>* coarse = level == 0 ? nullptr : &table;
    if(level < topology_levels) {
      internal::Composed_level<FT> composed{coarse, sources};
      tags.refine(work, mask, [&](const auto& level_mask, auto&... sinks) {
        internal::refine_level(work, level_mask, internal::No_points<decltype(work_vpm)>{work_vpm}, loop, composed,
                               sinks...);
      });
      table = std::move(composed.table);
    } else
      table = compose_on_host<FT>(work, mask, tags, coarse, sources, loop);
  }
  return table;
}

/*
 * `make_stencil_table()` with its parameters read; `np` gives the sharpness
 * tags, if any (`sharpness_tags_of`), which are only read: the levels refine
 * copies of them, which `refined_sharpness` (if not null) receives, by
 * ordinal of the refined mesh, when the refined mesh is made.
 */
template <class PolygonMesh, class Mask, class VertexPointMap, class NamedParameters>
Stencil_table<typename Mask::Number_type> stencil_table_of(
  const PolygonMesh& mesh, const Mask& mask, const VertexPointMap& vpm, int levels, PolygonMesh* refined_mesh,
  const Parallel_loop& loop, double max_memory, const NamedParameters& np,
  Sharpness_by_ordinal<typename Mask::Number_type>* refined_sharpness = nullptr)
{
  using FT = typename Mask::Number_type;
  using Host = Host_of<Mask>;
  internal::check_mask_options(mask, np);
  internal::check_mesh(mesh, vpm, mask.name(), Host::required_face_size);
  const auto tags = sharpness_tags_of<PolygonMesh, FT>(np);
  tags.check(mesh, mask, mask.name());
  internal::check_output_faces(mask.name(), static_cast<double>(num_faces(mesh)), Host::face_growth(),
                               Host::peak_bytes_per_face(), levels, max_memory);

  const std::size_t sources = num_vertices(mesh);
  if(levels == 0 && refined_mesh == nullptr)
    return Stencil_table<FT>::identity(sources);

  const int topology_levels = refined_mesh != nullptr ? levels : levels - 1;
  if(topology_levels == 0 && levels == 1) // the input's topology is all it needs: no copy
    return compose_on_host<FT>(mesh, mask, tags, nullptr, sources, loop);
  PolygonMesh work = mesh;
  const auto refine_work = [&]() {
    if constexpr(has_sharpness_tags<NamedParameters>()) {
      // the copy's tags are properties of the copy until it is handed out
      const Copied_sharpness<PolygonMesh, FT> copied(mesh, work, tags);
      Stencil_table<FT> refined = refined_table(work, mask, copied.tags(), levels, topology_levels, sources, loop);
      if(refined_sharpness != nullptr && refined_mesh != nullptr)
        *refined_sharpness = copied.by_ordinal();
      return refined;
    } else
      return refined_table(work, mask, tags, levels, topology_levels, sources, loop);
  };
  Stencil_table<FT> table = refine_work();

  if(refined_mesh != nullptr) {
    const auto work_vpm = get(CGAL::vertex_point, work);
    table.apply(vertices(mesh), vpm, vertices(work), work_vpm, parameters::threads(loop.threads()));
    *refined_mesh = std::move(work);
  }
  return table;
}

} // namespace internal

/*!
 * \ingroup PkgSubdivStencils
 * composes the levels of the scheme of `mask` on the topology of `mesh` into
 * one table: stencil i gives vertex i of the refined mesh (in the order
 * `subdivide()` creates them) from the vertices of `mesh` (in its iteration
 * order). Then `table.apply(coarse_points, refined_points)` re-evaluates the
 * refined points for moved control points in one pass, and the same table
 * carries any other per-vertex data.
 *
 * The stencils come from the same masks as `subdivide()`, so applying the
 * table to the points of `mesh` gives exactly the points of `subdivide()`
 * (exactly, in an exact kernel).
 *
 * How: each level's rows are composed at once with the table of the levels
 * before (a mask's terms times rows of that table, `internal::Row_builder`),
 * without building the level's own table; only the topology of the levels
 * before the last is refined (and the last one's when `refined_mesh` is
 * asked for), without points.
 *
 * \tparam PolygonMesh a model of `FaceGraph`
 * \tparam Mask a model of `SurfaceSubdivisionMask`
 * \param mesh the coarse mesh, left unchanged: its vertices are the sources
 *        of the table (the levels are refined on a copy)
 * \param mask the rules of the scheme, with their options
 * \param np named parameters (`CGAL::Subdiv::parameters`):
 *   - `number_of_iterations` (default 1): how many levels;
 *   - `vertex_point_map` (default the mesh's): the points of the refined mesh;
 *   - `refined_mesh(out)`: `out` receives the refined mesh, with the points
 *     that the table gives for the current points of `mesh`;
 *   - `max_memory` (default this machine's memory, in bytes): as `subdivide()`;
 *   - `threads` (default 1): with TBB, a `Surface_mesh` and double weights,
 *     the levels are composed in parallel; the table is the same with any
 *     number of threads;
 *   - `edge_sharpness_map`, `vertex_sharpness_map`, `crease_method`: the
 *     sharpness tags of `mesh`, as `subdivide()` takes them (Loop,
 *     Catmull-Clark, the linear masks). They are only read: the levels refine
 *     a copy of them, so the table is that of `subdivide()` with the same tags
 *     (the maps of `mesh` are not given the children's sharpness; refine the
 *     `refined_mesh` with `subdivide()` to have it);
 *   - `boundary_interpolation`, `triangle_subdivision`: checked against the
 *     mask, as `subdivide()` does. A `face_hole_map` changes no row (the
 *     vertices of a hole take part in the rules of their neighbours), so the
 *     table does not read one.
 * \throws Bad_input as `subdivide()` does (a negative or NaN sharpness
 * included).
 */
template <class PolygonMesh, class Mask, class NamedParameters = parameters::Default_named_parameters>
Stencil_table<typename Mask::Number_type> make_stencil_table(const PolygonMesh& mesh, const Mask& mask,
                                                             const NamedParameters& np = parameters::default_values())
{
  using FT = typename Mask::Number_type;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm =
    choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, mesh));
  const int levels = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 1);
  PolygonMesh* refined_mesh = choose_parameter<PolygonMesh*>(get_parameter(np, internal::refined_mesh_t()), nullptr);
  const internal::Parallel_loop loop =
    std::is_floating_point<FT>::value ? internal::parallel_loop(np) : internal::Parallel_loop(1);
  return internal::stencil_table_of(mesh, mask, vpm, levels, refined_mesh, loop, internal::max_memory_of(np), np);
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MAKE_STENCIL_TABLE_H
