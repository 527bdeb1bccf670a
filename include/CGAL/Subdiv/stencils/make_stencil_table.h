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
#include <limits>
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
  static auto& ends(Stencil_table<FT>& t) { return t.m_ends; }
  template <class FT>
  static auto& indices(Stencil_table<FT>& t) { return t.m_indices; }
  template <class FT>
  static auto& weights(Stencil_table<FT>& t) { return t.m_weights; }
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
  struct Entry
  {
    FT sum;
    std::uint32_t stamp;
  };
  std::vector<std::pair<Index, FT>> report;
  std::vector<Entry> entries;
  std::vector<Index> order;
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
 * One level composed with the table of the levels before (`coarse`, from the
 * coarse vertices to the old vertices of this level; null for the first
 * level): row j of the result is sum over the mask's terms (v, w) of new
 * vertex j of w * row v of `coarse`, its terms in the order in which they
 * first appear (the order and the arithmetic of `Stencil_table::then`, so the
 * table is the same as composing the level tables one by one).
 *
 * In one thread, rows are appended in the order the host visits them, when
 * that is the order of the new vertices (all hosts but a sqrt3 step that
 * refines a border); otherwise, and in parallel, in two passes: the length of
 * every row, then its terms at its place.
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

  // calls emit(source, weight) for every term of new vertex j's row
  const auto compose = [&](Compose_scratch<FT>& scratch, const auto& report, const auto& emit) {
    Merging_report<Numbering, FT> acc{number, scratch.report};
    report(acc);
    const std::pair<Index, FT>* terms = scratch.report.data();
    if(coarse == nullptr) {
      for(std::size_t k = 0; k < acc.size; ++k)
        emit(terms[k].first, terms[k].second);
      return;
    }
    scratch.prepare(sources);
    const std::uint32_t generation = scratch.next_generation();
    std::size_t most = 0;
    for(std::size_t k = 0; k < acc.size; ++k)
      most += coarse_ends[terms[k].first] - (terms[k].first == 0 ? 0 : coarse_ends[terms[k].first - 1]);
    if(scratch.order.size() < most)
      scratch.order.resize(2 * most);
    Index* order = scratch.order.data();
    typename Compose_scratch<FT>::Entry* entries = scratch.entries.data();
    std::size_t count = 0;
    for(std::size_t k = 0; k < acc.size; ++k) {
      const Index v = terms[k].first;
      const FT& w = terms[k].second;
      const std::size_t begin = v == 0 ? 0 : coarse_ends[v - 1], end = coarse_ends[v];
      for(std::size_t t = begin; t < end; ++t) {
        const Index s = coarse_indices[t];
        auto& entry = entries[s];
        if(entry.stamp != generation) {
          entry.stamp = generation;
          order[count++] = s;
          entry.sum = w * coarse_weights[t];
        } else {
          entry.sum += w * coarse_weights[t];
        }
      }
    }
    for(std::size_t k = 0; k < count; ++k)
      emit(order[k], entries[order[k]].sum);
  };

  if(!loop.is_parallel()) {
    Compose_scratch<FT> scratch;
    // room for the terms: twice the mean row of the levels before, which
    // grows less than that from level to level (untouched room costs only
    // address space)
    const std::size_t mean = coarse ? coarse->number_of_terms() / std::max<std::size_t>(1, coarse->number_of_stencils()) : 0;
    const std::size_t room = rows * (std::max<std::size_t>)(16, 2 * mean + 4);
    ends.reserve(rows);
    indices.reserve(room);
    weights.reserve(room);
    bool in_order = true;
    host.for_each_new_vertex(mask, [&](std::size_t j, const auto& report) {
      if(!in_order || j != ends.size()) {
        in_order = false;
        return;
      }
      compose(scratch, report, [&](Index s, const FT& w) {
        indices.push_back(s);
        weights.push_back(w);
      });
      ends.push_back(indices.size());
    });
    if(in_order && ends.size() == rows)
      return table;
    ends.clear();
    indices.clear();
    weights.clear();
  }

  // two passes: lengths, then terms
  resize_for_overwrite(ends, rows);
  Per_thread<Compose_scratch<FT>> scratches;
  host.for_each_new_vertex(mask, [&](std::size_t j, const auto& report) {
    std::size_t length = 0;
    compose(scratches.local(), report, [&](Index, const FT&) { ++length; });
    ends[j] = length;
  }, loop);
  std::size_t total = 0;
  for(std::size_t j = 0; j < rows; ++j) {
    total += ends[j];
    ends[j] = total;
  }
  resize_for_overwrite(indices, total);
  resize_for_overwrite(weights, total);
  Index* out_indices = indices.data();
  FT* out_weights = weights.data();
  host.for_each_new_vertex(mask, [&](std::size_t j, const auto& report) {
    std::size_t t = j == 0 ? 0 : ends[j - 1];
    compose(scratches.local(), report, [&](Index s, const FT& w) {
      out_indices[t] = s;
      out_weights[t] = w;
      ++t;
    });
  }, loop);
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
  const Face_soup soup = host.faces(loop, false);
  mesh.resize(static_cast<typename SM::size_type>(soup.number_of_vertices()),
              static_cast<typename SM::size_type>(soup.number_of_edges()),
              static_cast<typename SM::size_type>(soup.number_of_faces()));
  wire_surface_mesh(mesh, soup, loop);
}

// One level on `mesh`: returns the level's stencil table (new vertex -> old
// vertices, by ordinal) and replaces `mesh` by the refined topology. Points of
// the refined mesh are left at the origin: the caller computes them.
template <class Mask, class Mesh, class VertexPointMap>
Stencil_table<typename Mask::Number_type> refine_topology_once(Mesh& mesh, const Mask& mask, const VertexPointMap& vpm)
{
  using FT = typename Mask::Number_type;
  const typename Mask::Host host(mesh);
  const Mesh_numbering<Mesh> number(mesh);
  Stencil_table<FT> table =
    compose_level<FT>(host, mask, number, static_cast<const Stencil_table<FT>*>(nullptr), num_vertices(mesh),
                      Parallel_loop(1));
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
Stencil_table<typename Mask::Number_type>
make_stencil_table(const PolygonMesh& mesh, const Mask& mask, int levels,
                   typename internal::Non_deduced<PolygonMesh>::type* refined_mesh = nullptr,
                   const NamedParameters& np = parameters::default_values())
{
  using FT = typename Mask::Number_type;
  using Host = typename Mask::Host;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  internal::check_mesh(mesh, vpm, mask.name(), Host::required_face_size);
  internal::check_output_faces(mask.name(), static_cast<double>(num_faces(mesh)), Host::face_growth(), levels);

  internal::require(!internal::has_garbage(mesh), "make_stencil_table: call collect_garbage() on the mesh first");
  const internal::Parallel_loop loop =
    std::is_floating_point<FT>::value ? internal::parallel_loop(np) : internal::Parallel_loop(1);
  const std::size_t sources = num_vertices(mesh);
  if(levels == 0 && refined_mesh == nullptr)
    return Stencil_table<FT>::identity(sources);

  PolygonMesh work = mesh;
  const auto work_vpm = get(CGAL::vertex_point, work);
  const int topology_levels = refined_mesh != nullptr ? levels : levels - 1;
  internal::reserve_levels<Host>(work, topology_levels);
  Stencil_table<FT> table = Stencil_table<FT>::identity(sources);
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
Stencil_table<typename Mask::Number_type>
make_stencil_table(const PolygonMesh& mesh, const Mask& mask, int levels,
                   const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return make_stencil_table(mesh, mask, levels, static_cast<PolygonMesh*>(nullptr), np);
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MAKE_STENCIL_TABLE_H
