// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_MAKE_FACE_VARYING_STENCIL_TABLE_H
#define CGAL_SUBDIV_MAKE_FACE_VARYING_STENCIL_TABLE_H

/// \file make_face_varying_stencil_table.h
/// The stencil table of a face-varying channel (OpenSubdiv's face-varying
/// stencils): the levels of a corner index map that `subdivide()` carries
/// (`Carried_data`), their rows composed into one table as they come.

#include <CGAL/Subdiv/Carried_data.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/refinement/Face_varying.h>
#include <CGAL/Subdiv/stencils/Row_builder.h>
#include <CGAL/Subdiv/stencils/Stencil.h>
#include <CGAL/Subdiv/stencils/Stencil_table.h>
#include <CGAL/Subdiv/stencils/make_stencil_table.h>
#include <CGAL/Subdiv/subdivide.h>
#include <CGAL/Subdiv/views/Sharpness_tags.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Subdiv {
namespace internal {

struct Carried_data_access
{
  /// a channel of value indices `indices` whose rows of every level also go
  /// to the visitor that `rows_of_level(topology)` makes for the level
  template <class Mesh, class FT, class IndexMap, class LevelRows>
  static void add_corner_rows(Carried_data<Mesh, FT>& data, Face_varying_interpolation interpolation, IndexMap indices,
                              LevelRows rows_of_level)
  {
    data.add_indexed_channel(interpolation, indices, {Carried_data<Mesh, FT>::row_map_level(std::move(rows_of_level))});
  }
};

/*
 * The table of the levels of a face-varying channel, made as `subdivide()`
 * carries its index map `indices`: every row of a level (over the level's
 * cut vertices) is read over the value indices of the old corners (the
 * sources on the first level, the row numbers of the level before after it),
 * merged, and composed with the table of the levels before
 * (`compose_terms`, as `make_stencil_table()` composes its levels).
 */
template <class Mesh, class FT, class IndexMap>
class Face_varying_table_levels
{
  using Access = Stencil_table_access;

public:
  Face_varying_table_levels(IndexMap indices, std::size_t sources) : m_indices(indices), m_sources(sources) {}

  Face_varying_table_levels(const Face_varying_table_levels&) = delete;
  Face_varying_table_levels& operator=(const Face_varying_table_levels&) = delete;

  /// the visitor of the rows of the level of `topology`: the level before is done
  Face_varying_row_visitor<FT> level(const Face_varying_topology<Mesh>& topology)
  {
    finish_level();
    m_sink.reset(new Row_sink<FT>{Access::ends(m_level), Access::indices(m_level), Access::weights(m_level)});
    const auto& cut = topology.cut();
    // a row per vertex, edge and face of the cut mesh at most
    const std::size_t rows = cut.number_of_vertices() + cut.number_of_edges() + cut.number_of_faces();
    m_sink->reserve(rows, 8 * rows);
    return [this, &topology](const Face_varying_row<FT>& row) { add_row(topology, row); };
  }

  /// the table of all the levels (the identity without any)
  Stencil_table<FT> table()
  {
    finish_level();
    return m_coarse ? std::move(*m_coarse) : Stencil_table<FT>::identity(m_sources);
  }

private:
  void add_row(const Face_varying_topology<Mesh>& topology, const Face_varying_row<FT>& row)
  {
    m_merged.clear();
    for(const auto& [v, w] : row) // cut vertices sharing an index are one old value
      m_merged.add(static_cast<std::uint32_t>(get(m_indices, topology.corner_of(v))), w);
    m_sink->close(compose_terms(m_merged.terms(), m_coarse.get(), m_sources, m_builder,
                                [&](std::size_t most) { return m_sink->open(most); }));
  }

  void finish_level()
  {
    if(!m_sink)
      return;
    m_sink->finish();
    m_sink.reset();
    m_coarse = std::make_unique<Stencil_table<FT>>(std::move(m_level));
    m_level = Stencil_table<FT>(m_sources);
  }

  IndexMap m_indices;
  std::size_t m_sources;
  std::unique_ptr<Stencil_table<FT>> m_coarse; // the levels before; null before the first is done
  Stencil_table<FT> m_level{m_sources};        // the level being made, through m_sink
  std::unique_ptr<Row_sink<FT>> m_sink;
  Stencil<std::uint32_t, FT> m_merged;
  Row_builder<FT> m_builder;
};

/// the number of values of `indices` on the corners of `mesh` (the largest
/// index plus one); refuses a negative index or one too large for a table
template <class PolygonMesh, class IndexMap>
std::size_t number_of_corner_values(const PolygonMesh& mesh, const IndexMap& indices)
{
  using Index = typename boost::property_traits<IndexMap>::value_type;
  static_assert(std::is_integral<Index>::value, "make_face_varying_stencil_table: the corner indices are integers");
  const Mesh_numbering<PolygonMesh> number(mesh);
  const unsigned long long most = std::numeric_limits<std::uint32_t>::max();
  std::size_t values = 0;
  for(auto f : faces(mesh))
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      const Index index = get(indices, h);
      bool negative = false;
      if constexpr(std::is_signed<Index>::value)
        negative = index < 0;
      if(negative || static_cast<unsigned long long>(index) >= most)
        refuse(Message() << "make_face_varying_stencil_table: the corner of face " << number(f) << " at vertex "
                         << number(target(h, mesh)) << " has the value index " << static_cast<long long>(index)
                         << "; every corner needs the index of its value, from 0 (less than 2^32 - 1)");
      values = (std::max)(values, static_cast<std::size_t>(index) + 1);
    }
  return values;
}

/// the index of the value of every corner of `mesh` by halfedge ordinal, in
/// `out`; `none` for a border halfedge
template <class PolygonMesh, class IndexMap, class Out>
void write_corner_indices(const PolygonMesh& mesh, const IndexMap& indices, Out& out)
{
  const Mesh_numbering<PolygonMesh> number(mesh);
  out.assign(num_halfedges(mesh), static_cast<typename Out::value_type>(-1));
  for(auto h : halfedges(mesh))
    if(!CGAL::is_border(h, mesh))
      out[number(h)] = static_cast<typename Out::value_type>(get(indices, h));
}

/*
 * `make_face_varying_stencil_table()` with its input checked: `subdivide()`
 * refines `work` (a copy of `mesh`) carrying a copy of `corner_indices` and
 * the channel of its rows, which makes the table. The sharpness tags of `np`
 * are read into maps of `work` (`Copied_sharpness`), and the refined indices
 * written to the `refined_corner_indices` of `np`, if any, before the maps
 * of `work` are removed.
 */
template <class PolygonMesh, class Mask, class IndexMap, class NamedParameters>
Stencil_table<typename Mask::Number_type> refined_face_varying_table(const PolygonMesh& mesh, PolygonMesh& work,
                                                                     const Mask& mask, const IndexMap& corner_indices,
                                                                     Face_varying_interpolation mode,
                                                                     std::size_t sources, const NamedParameters& np)
{
  using FT = typename Mask::Number_type;
  using Index = typename boost::property_traits<IndexMap>::value_type;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto work_indices = get(CGAL::dynamic_halfedge_property_t<Index>(), work);
  {
    const Mesh_numbering<PolygonMesh> from(mesh), to(work);
    for(std::size_t h = 0; h < num_halfedges(mesh); ++h)
      if(!CGAL::is_border(from.halfedge(h), mesh))
        put(work_indices, to.halfedge(h), get(corner_indices, from.halfedge(h)));
  }
  Face_varying_table_levels<PolygonMesh, FT, std::remove_const_t<decltype(work_indices)>> levels(work_indices, sources);
  Carried_data<PolygonMesh, FT> data;
  Carried_data_access::add_corner_rows(data, mode, work_indices,
                                       [&levels](const auto& topology) { return levels.level(topology); });

  const auto level_np =
    parameters::number_of_iterations(choose_parameter(get_parameter(np, internal_np::number_of_iterations), 1))
      .max_memory(max_memory_of(np))
      .threads(choose_parameter(get_parameter(np, threads_t()), 1))
      .carried_data(data);
  if constexpr(has_sharpness_tags<NamedParameters>()) {
    const auto tags = sharpness_tags_of<PolygonMesh, FT>(np);
    const Copied_sharpness<PolygonMesh, FT> copied(mesh, work, tags);
    subdivide(work, mask,
              level_np.edge_sharpness_map(copied.edge_map())
                .vertex_sharpness_map(copied.vertex_map())
                .crease_method(tags.method()));
  } else
    subdivide(work, mask, level_np);

  if constexpr(!parameters::is_default_parameter<NamedParameters, refined_corner_indices_t>::value)
    write_corner_indices(work, work_indices, *get_parameter(np, refined_corner_indices_t()));
  return levels.table();
}

} // namespace internal

/*!
 * \ingroup PkgSubdivStencils
 * composes the levels of a face-varying channel (per-corner data such as UVs
 * with seams, OpenSubdiv's face-varying stencils) into one table: stencil i
 * gives the value of index i after `number_of_iterations` levels from the
 * values of `mesh`, value k being the one of index k. The value of index i is
 * the one that `subdivide()` with
 * `Carried_data().corner_map(map, mode, corner_indices)` gives the corners
 * to which it writes index i: the table comes from the same rows (the
 * channel's face-varying topology, refined with the scheme's mask and the
 * mode), so applying it to the base values gives exactly the carried values
 * in an exact kernel (in double, the values of one level bit for bit, those
 * of more levels up to the rounding of the composed weights).
 *
 * How: `subdivide()` refines a copy of `mesh` carrying a copy of the index
 * map, and each level's rows are composed at once with the table of the
 * levels before, as `make_stencil_table()` composes its levels.
 *
 * A value that OpenSubdiv keeps over sectors that seams separate is one
 * value, at the row of its first sector: the rows of the others have
 * stencils too, which no corner takes.
 *
 * \tparam PolygonMesh a model of `MutableFaceGraph`
 * \tparam Mask a model of `SurfaceSubdivisionMask` of a scheme that splits
 *         edges (Catmull-Clark, Loop, the butterflies, linear)
 * \tparam IndexMap a readable halfedge property map of integers
 * \param mesh the coarse mesh, left unchanged (the levels are refined on a copy)
 * \param mask the rules of the scheme, with their options
 * \param corner_indices the index of the value of every corner of `mesh` (a
 *        halfedge with a face, the corner of that face at its target), from
 *        0, as OBJ's `vt` references or an OpenSubdiv face-varying channel
 *        give them: the sources of the table are the values 0 to the largest
 *        index (an index that no corner takes is a source of no stencil)
 * \param mode how the values are interpolated (`Face_varying_interpolation`)
 * \param np named parameters (`CGAL::Subdiv::parameters`):
 *   - `number_of_iterations` (default 1): how many levels;
 *   - `refined_mesh(out)`: `out` receives the refined mesh (with its points);
 *   - `refined_corner_indices(v)` (a `std::vector` of integers): `v`
 *     receives the index of the value of every corner of the refined mesh
 *     (the stencil that gives it), by halfedge in the iteration order of
 *     `halfedges(out)`, and -1 (converted) for a border halfedge;
 *   - `max_memory`, `threads`: as `subdivide()`;
 *   - `edge_sharpness_map`, `vertex_sharpness_map`, `crease_method`: the
 *     sharpness tags of `mesh`, as `subdivide()` takes them; only read (the
 *     levels refine a copy of them), as `make_stencil_table()` does;
 *   - `boundary_interpolation`, `triangle_subdivision`: checked against the
 *     mask, as `subdivide()` does.
 * \throws Bad_input as `subdivide()` with that `Carried_data` does (a scheme
 * that does not split edges included), and for a negative corner index or
 * one of 2^32 - 1 or more.
 */
template <class PolygonMesh, class Mask, class IndexMap, class NamedParameters = parameters::Default_named_parameters>
Stencil_table<typename Mask::Number_type> make_face_varying_stencil_table(
  const PolygonMesh& mesh, const Mask& mask, IndexMap corner_indices, Face_varying_interpolation mode,
  const NamedParameters& np = parameters::default_values())
{
  using FT = typename Mask::Number_type;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  internal::check_mask_options(mask, np);
  const std::size_t sources = internal::number_of_corner_values(mesh, corner_indices);
  const auto tags = internal::sharpness_tags_of<PolygonMesh, FT>(np);
  tags.check(mesh, mask, mask.name());

  PolygonMesh work = mesh;
  Stencil_table<FT> table = internal::refined_face_varying_table(mesh, work, mask, corner_indices, mode, sources, np);
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal::refined_mesh_t>::value)
    *get_parameter(np, internal::refined_mesh_t()) = std::move(work);
  return table;
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_MAKE_FACE_VARYING_STENCIL_TABLE_H
