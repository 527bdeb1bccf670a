// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_CARRIED_DATA_H
#define CGAL_SUBDIV_CARRIED_DATA_H

#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/hosts/Vertex_origin.h>
#include <CGAL/Subdiv/internal/Carried_data_fwd.h>
#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/internal/parallel.h>
#include <CGAL/Subdiv/masks/Linear_quad_mask.h>
#include <CGAL/Subdiv/masks/Linear_triangle_mask.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/refinement/Face_varying.h>
#include <CGAL/Subdiv/refinement/Inherited_face_map.h>
#include <CGAL/Subdiv/refinement/Provenance.h>
#include <CGAL/Subdiv/refinement/Seam_free_corners.h>
#include <CGAL/Subdiv/refinement/carried_values.h>
#include <CGAL/Subdiv/refinement/refine_level.h>
#include <CGAL/Subdiv/stencils/Stencil.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/container_hash/hash.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivFunctions
 * How `Carried_data` interpolates a vertex map: OpenSubdiv's vertex and
 * varying primvar data.
 */
enum class Interpolation {
  /// with the scheme's rules: the weights of the new points
  smooth,
  /// with the rules of the linear scheme of the same split
  /// (`Linear_quad_mask` for Catmull-Clark, `Linear_triangle_mask` for Loop and
  /// the butterflies): an old vertex keeps its value, an edge point gets the
  /// mean of the edge's ends, a face point the mean of the face's corners;
  /// for Doo-Sabin and the sqrt3 schemes, which have no linear scheme, the
  /// linear rules of their split (`internal::Linear_dual_rules`,
  /// `internal::Linear_sqrt3_rules`): a Doo-Sabin corner gets the centre of
  /// its quad in the linear quad split of its face, a sqrt3 old vertex keeps
  /// its value and a face point gets the mean of the face's corners
  linear
};

/*!
 * \ingroup PkgSubdivFunctions
 * Per-element data that `subdivide()` carries to the refined mesh besides the
 * points.
 *
 * - `vertex_map(map)`, `vertex_map(map, Interpolation::linear)`: a vertex
 *   property map; every new vertex gets the combination of old values that the
 *   scheme's mask gives its point, with the same weights (so data is
 *   interpolated exactly as the geometry is), or with `Interpolation::linear`
 *   the weights of the linear scheme. The values are scalars, vectors
 *   (`Vector_2`, `Vector_3`, Eigen vectors, any type with `value * weight` and
 *   `value + value`), points (`Point_2` UVs, `Point_3`), or `CGAL::IO::Color`
 *   (combined in double, then rounded and clamped to [0, 255]). The weight is
 *   the mask's `FT` when the values are made of it (the `FT` itself, or a
 *   kernel object of a kernel with that `FT`: exact values stay exact), a
 *   `double` otherwise.
 * - `corner_map(map, mode)`: a halfedge property map of per-corner values
 *   (the value of face(h) at target(h)), such as UVs with seams: two corners
 *   at one vertex with different values are a seam (values are compared with
 *   `==`). With the smooth modes (`Face_varying_interpolation`), the mesh is
 *   cut along the seams, every value being a vertex of the cut mesh and every
 *   seam a border of it; the cut mesh is refined with the scheme's mask and
 *   the level's sharpness tags, the vertices that the mode keeps being made
 *   infinitely sharp: so a seam follows the border rules, as in OpenSubdiv.
 *   With `all` (and with the linear schemes in every mode), every corner of a
 *   new face gets the combination of the corner values of its parent face
 *   that the linear scheme of the split gives its vertex. A seam stays a
 *   seam; border halfedges are left alone. Doo-Sabin and the sqrt3 schemes,
 *   which make new faces across the old edges (a face there would straddle a
 *   seam), carry a corner map only when it has no seam (every vertex holds one
 *   value at all its corners; else `subdivide()` throws `Bad_input` naming
 *   the first seam, the mesh and the maps unchanged): such a map is a vertex
 *   map, carried as `vertex_map` carries one, with `Interpolation::smooth` in
 *   every smooth mode (the scheme's own rules, border rules included: the
 *   smooth modes are one) and with `Interpolation::linear` in `all`.
 * - `corner_map(map, mode, index_map)`: the same, the face-varying topology
 *   coming from a halfedge map of value indices (as OpenSubdiv's face-varying
 *   channels and OBJ's `vt` references give it): two corners at one vertex
 *   are one value when their indices are equal, whatever their values. The
 *   refined corners get the indices of their new values (one per value, from
 *   0 on every level), so that an indexed file can be written.
 * - `corner_maps(mode, index_map, map1, map2, ...)`: several corner maps that
 *   share one index map, as the maps of one OpenSubdiv face-varying channel
 *   (UVs and tangents, say): the face-varying topology and the rows of a
 *   level are made once for all of them. Each map ends as it would alone.
 * - `non_manifold_copies(map)`: a readable vertex property map giving every
 *   vertex the point of the polygon soup it copies (what
 *   `Non_manifold_split::origin` gives by vertex, for a mesh made by
 *   `split_non_manifold()`). The copies of one point are one non-manifold
 *   vertex for the corner maps, as for OpenSubdiv: when the corners of all its
 *   copies do not hold one value, every value at every copy is kept where it
 *   is (a corner), and so are the values of their children on the next levels
 *   (the maps of the mesh of the call are read on the first level a channel
 *   carries). If the map is writable, the new vertices get points too: the
 *   child of a vertex its parent's, every other new vertex a point of its own
 *   (above all the others), so that the map still says which vertices
 *   descend from one non-manifold vertex (`face_varying_limit()` reads it so).
 * - `face_map(map)`: a face property map; every new face gets the value of the
 *   old face it lies in (for dual schemes, the faces made from an old edge or
 *   vertex get the value of an adjacent old face).
 * - `origins(vector)`: fills `vector` with the origin of every vertex of the
 *   last level (the old vertex, edge, face or corner it came from, by ordinal
 *   in the iteration order of the mesh before that level; see `Vertex_origin`).
 * - `face_origin_map(map)`: a face property map of `Face_origin`: for every
 *   face of the refined mesh, the face of the base mesh (the mesh given to
 *   `subdivide()`) it lies in, and the parameters of its corners in that
 *   face's domain.
 * - `base_origin_map(map)`: a vertex property map of `Vertex_origin`: for
 *   every vertex of the refined mesh, the element of the base mesh it lies on
 *   (a vertex, inside an edge, inside a face), by ordinal in the base mesh's
 *   iteration order.
 * The last two are for the schemes that split edges (Catmull-Clark, Loop, the
 *   butterflies, linear); Doo-Sabin and the sqrt3 schemes make faces across the
 *   old edges, and refuse them (doc/provenance.md).
 *
 * Include `<CGAL/Subdiv/Carried_data.h>` (or `<CGAL/Subdiv.h>`), and pass it
 * with the named parameter `carried_data`:
 * `CGAL::Subdiv::parameters::number_of_iterations(2).carried_data(data)`.
 * The maps must accept the new descriptors: property maps of the mesh itself
 * do (for `Surface_mesh`, maps made with `add_property_map`).
 */
template <class Mesh, class FT>
class Carried_data
{
public:
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;
  /// the recorded stencil of every new vertex, by new index
  using Vertex_stencils = std::vector<Stencil<vertex_descriptor, FT>>;
  /// after the rebuild: writes the values of the new vertices
  using Vertex_writer = std::function<void(const std::vector<vertex_descriptor>&)>;
  /// a new face of a level, its parent and its vertices
  using New_face = internal::New_face<Mesh>;
  /// after the rebuild: writes the values of corners of new faces, a block
  /// at a time, given their halfedges (into the corner's vertex) and their
  /// rows in the level
  using Corner_writer = std::function<void(const std::vector<halfedge_descriptor>&, const std::vector<std::size_t>&)>;
  /// where the corners of a level of a corner map take their values from
  using Face_varying_rows = internal::Face_varying_rows<Mesh, FT>;
  /// after the rebuild: writes the values of the new faces, given the parent (old face ordinal) of each
  using Face_writer = std::function<void(const std::vector<face_descriptor>&, const std::vector<std::size_t>&)>;

  template <class VertexMap>
  Carried_data& vertex_map(VertexMap map, Interpolation interpolation = Interpolation::smooth)
  {
    const auto make_writer = [map](const Vertex_stencils& stencils) -> Vertex_writer {
      using Value = typename boost::property_traits<VertexMap>::value_type;
      const auto value_of = [&map](vertex_descriptor v) -> Value { return get(map, v); };
      auto values = std::make_shared<std::vector<Value>>();
      values->reserve(stencils.size());
      for(const auto& stencil : stencils)
        values->push_back(internal::combine_values<Value>(value_of, stencil.terms()));
      return [map, values](const std::vector<vertex_descriptor>& new_vertices) {
        for(std::size_t j = 0; j < new_vertices.size(); ++j)
          put(map, new_vertices[j], (*values)[j]);
      };
    };
    m_vertex_channels.push_back(Vertex_channel{interpolation, make_writer});
    return *this;
  }

  template <class CornerMap>
  Carried_data& corner_map(CornerMap map, Face_varying_interpolation interpolation)
  {
    const auto same = [map](halfedge_descriptor a, halfedge_descriptor b) { return get(map, a) == get(map, b); };
    m_corner_channels.push_back(Corner_channel{interpolation, same, {value_map_level(map)}});
    return *this;
  }

  template <class CornerMap, class IndexMap>
  Carried_data& corner_map(CornerMap map, Face_varying_interpolation interpolation, IndexMap indices)
  {
    return corner_maps(interpolation, indices, map);
  }

  template <class IndexMap, class... CornerMaps>
  Carried_data& corner_maps(Face_varying_interpolation interpolation, IndexMap indices, CornerMaps... maps)
  {
    static_assert(sizeof...(CornerMaps) > 0, "corner_maps: give at least one corner map");
    add_indexed_channel(interpolation, indices, {value_map_level(maps)...});
    return *this;
  }

  template <class VertexMap>
  Carried_data& non_manifold_copies(VertexMap point_of)
  {
    m_point_of = [point_of](vertex_descriptor v) { return static_cast<std::size_t>(get(point_of, v)); };
    using Category = typename boost::property_traits<VertexMap>::category;
    if constexpr(std::is_convertible<Category, boost::writable_property_map_tag>::value) {
      using Value = typename boost::property_traits<VertexMap>::value_type;
      m_put_point = [point_of](vertex_descriptor v, std::size_t point) { put(point_of, v, static_cast<Value>(point)); };
    }
    return *this;
  }

  template <class FaceMap>
  Carried_data& face_map(FaceMap map)
  {
    m_face_channels.push_back([map](const Mesh& mesh) -> Face_writer {
      auto inherited = std::make_shared<internal::Inherited_face_map<Mesh, FaceMap>>(mesh, map);
      inherited->read_old_values();
      return [inherited](const std::vector<face_descriptor>& new_faces, const std::vector<std::size_t>& parents) {
        inherited->write_new_values(new_faces, parents);
      };
    });
    return *this;
  }

  Carried_data& origins(std::vector<Vertex_origin>& out)
  {
    m_origins = &out;
    return *this;
  }

  template <class FaceMap>
  Carried_data& face_origin_map(FaceMap map)
  {
    m_provenance.put_face = [map](face_descriptor f, const Face_origin& origin) { put(map, f, origin); };
    return *this;
  }

  template <class VertexMap>
  Carried_data& base_origin_map(VertexMap map)
  {
    m_provenance.put_vertex = [map](vertex_descriptor v, const Vertex_origin& origin) { put(map, v, origin); };
    return *this;
  }

  /// whether the levels record the stencil of every new vertex (for the
  /// vertex maps, whose values are combined with the weights of the points,
  /// and then the points are too); corner and face data do without
  bool records_vertex_stencils() const { return !m_vertex_channels.empty(); }

  bool empty() const
  {
    return m_vertex_channels.empty() && m_corner_channels.empty() && m_face_channels.empty() && m_origins == nullptr &&
           !wants_provenance() && !m_put_point;
  }

private:
  struct Corner_channel; // corner maps that share one face-varying topology
  friend struct internal::Carried_data_access;

public:
  /*
   * The sink of `internal::refine_level` that carries the data through one
   * level: it records every new vertex's stencil (merged, `Stencil::add`) and
   * the old values, and writes the new values once the level is made. Its
   * stencils also give the new points (`internal::Row_points`), so that
   * points and data are combined alike.
   */
  class Level
  {
  public:
    Level(const Carried_data& data, const Mesh& mesh) : m_data(&data), m_mesh(&mesh) {}

    const Vertex_stencils& stencils() const { return m_stencils.rows; }

    template <class Host, class Mask>
    void read(const Host& host, const Mask& mask, const internal::Parallel_loop& loop)
    {
      if(m_data->records_vertex_stencils())
        m_stencils.read(host, mask, loop);
      if(m_data->interpolates(Interpolation::linear) || m_data->wants_provenance())
        m_linear_stencils.read(host, linear_mask(mask), loop);
      if(m_data->m_put_point)
        read_points();
      if(m_data->m_origins != nullptr || m_data->wants_provenance() || !m_data->m_corner_channels.empty() ||
         m_data->m_put_point) {
        m_new_origins.clear();
        for(std::size_t j = 0; j < host.number_of_new_vertices(); ++j)
          m_new_origins.push_back(host.origin(j));
        if(m_data->m_origins != nullptr)
          *m_data->m_origins = m_new_origins;
      }
      if(m_data->wants_provenance())
        read_provenance(mask);
      for(const auto& channel : m_data->m_vertex_channels)
        m_vertex_writers.push_back(channel.make_writer(
          channel.interpolation == Interpolation::linear ? m_linear_stencils.rows : m_stencils.rows));
      for(const auto& channel : m_data->m_corner_channels)
        if constexpr(carries_seams<Mask>())
          m_corner_levels.push_back(read_channel(channel, mask));
        else
          m_seam_free_levels.push_back(read_seam_free_channel(channel, host, mask));
      for(const auto& channel : m_data->m_face_channels)
        m_face_writers.push_back(channel(*m_mesh));
    }

    template <class New_level>
    void write(const New_level& level)
    {
      if(m_data->wants_provenance())
        write_provenance(internal::new_faces_of<Mesh>(level), level.elements().vertices);
      if(!m_corner_levels.empty()) {
        write_corners(level);
        pin_children(level.elements().vertices);
      }
      for(const auto& seam_free : m_seam_free_levels)
        seam_free.write(level);
      if(m_data->m_put_point)
        write_points(level.elements().vertices);
      if(m_vertex_writers.empty() && m_face_writers.empty())
        return;
      const auto& elements = level.elements();
      for(const auto& write : m_vertex_writers)
        write(elements.vertices);
      if(m_face_writers.empty())
        return;
      const std::vector<std::size_t> parents = level.parents();
      for(const auto& write : m_face_writers)
        write(elements.faces, parents);
    }

  private:
    // a corner channel on this level: its topology is made and refined
    // once, every row going to each of its maps
    struct Corner_level
    {
      const Corner_channel* channel;
      Face_varying_rows rows;
      std::vector<Corner_writer> writers;
    };

    template <class Mask>
    Corner_level read_channel(const Corner_channel& channel, const Mask& mask)
    {
      if(!channel.refined && m_data->m_point_of)
        channel.pinned = internal::non_manifold_corners(*m_mesh, m_data->m_point_of, channel.same);
      const internal::Face_varying_topology<Mesh> topology(*m_mesh, channel.same, !channel.refined, channel.pinned);
      channel.refined = true;
      std::vector<Corner_map_level> maps;
      for(const auto& start : channel.maps)
        maps.push_back(start(topology));
      const internal::Face_varying_row_visitor<FT> visit = [&](const internal::Face_varying_row<FT>& row) {
        for(Corner_map_level& map : maps)
          if(map.add_row)
            map.add_row(row);
      };
      Corner_level result;
      result.channel = &channel;
      const auto refine = [&]() {
        if constexpr(has_sharp_level<Mask>::value)
          if(channel.interpolation != Face_varying_interpolation::all)
            return internal::smooth_face_varying_rows<Mesh, FT>(topology, mask, channel.interpolation, visit);
        // linear in every face (the linear schemes are linear in every mode)
        return internal::linear_face_varying_rows<Mesh, FT>(topology, linear_mask(mask), visit);
      };
      result.rows = refine();
      for(Corner_map_level& map : maps)
        result.writers.push_back(std::move(map.write));
      return result;
    }

    // every corner of every new face, to every corner writer, in blocks (a
    // writer is called once a block, not once a corner): corner i of a new
    // face is the target of the halfedge from corner i - 1
    template <class New_level>
    void write_corners(const New_level& level)
    {
      constexpr std::size_t block = 4096;
      std::vector<halfedge_descriptor> halfedges;
      halfedges.reserve(block);
      std::vector<std::vector<std::size_t>> rows(m_corner_levels.size());
      for(std::vector<std::size_t>& channel_rows : rows)
        channel_rows.reserve(block);
      const auto flush = [&]() {
        for(std::size_t c = 0; c < m_corner_levels.size(); ++c) {
          for(const Corner_writer& write : m_corner_levels[c].writers)
            write(halfedges, rows[c]);
          rows[c].clear();
        }
        halfedges.clear();
      };
      const auto& record = level.faces();
      for(std::size_t b = 0; b < record.number_of_blocks(); ++b)
        record.for_each_face_in_block(b, [&](std::size_t, const auto* corners, std::size_t size, std::size_t parent) {
          for(std::size_t i = 0; i < size; ++i) {
            halfedges.push_back(level.halfedge(corners[i == 0 ? size - 1 : i - 1].halfedge));
            const Vertex_origin& origin = m_new_origins[corners[i].vertex];
            for(std::size_t c = 0; c < m_corner_levels.size(); ++c)
              rows[c].push_back(m_corner_levels[c].rows.row_of(parent, origin));
          }
          if(halfedges.size() >= block)
            flush();
        });
      flush();
    }

    // the children of the pinned vertices of a channel are pinned (OpenSubdiv's
    // vertex values inherit their parents' tags)
    void pin_children(const std::vector<vertex_descriptor>& new_vertices)
    {
      for(const Corner_level& corner_level : m_corner_levels) {
        std::vector<bool>& pinned = corner_level.channel->pinned;
        if(pinned.empty())
          continue;
        const internal::Mesh_numbering<Mesh> number(*m_mesh);
        std::vector<bool> children(num_vertices(*m_mesh), false);
        for(std::size_t j = 0; j < new_vertices.size(); ++j)
          if(m_new_origins[j].kind == Origin_kind::vertex && pinned[m_new_origins[j].index])
            children[number(new_vertices[j])] = true;
        pinned = std::move(children);
      }
    }

    // the points of the non-manifold copies of the old vertices, by ordinal
    void read_points()
    {
      m_old_points.clear();
      for(const vertex_descriptor v : vertices(*m_mesh))
        m_old_points.push_back(m_data->m_point_of(v));
    }

    // the child of a vertex copies its parent's point; a new vertex inside
    // an edge or a face is a point of its own, above all the old ones
    void write_points(const std::vector<vertex_descriptor>& new_vertices)
    {
      const std::size_t first_new =
        m_old_points.empty() ? 0 : *std::max_element(m_old_points.begin(), m_old_points.end()) + 1;
      for(std::size_t j = 0; j < new_vertices.size(); ++j) {
        const Vertex_origin& origin = m_new_origins[j];
        m_data->m_put_point(new_vertices[j],
                            origin.kind == Origin_kind::vertex ? m_old_points[origin.index] : first_new + j);
      }
    }

    // a channel carried by a scheme that makes new faces across the old
    // edges: its maps have no seam (`prepare`), and are carried as vertex maps
    template <class Host, class Mask>
    internal::Seam_free_corners<Mesh, FT> read_seam_free_channel(const Corner_channel& channel, const Host& host,
                                                                 const Mask& mask) const
    {
      const internal::Face_varying_topology<Mesh> topology(*m_mesh, channel.same);
      internal::Seam_free_corners<Mesh, FT> result;
      for(const auto& start : channel.maps) {
        Corner_map_level map = start(topology);
        result.add_map(std::move(map.add_row), std::move(map.write));
      }
      result.read(topology, host, mask, channel.interpolation);
      return result;
    }

    template <class Mask>
    void read_provenance(const Mask&)
    {
      Provenance& provenance = m_data->m_provenance;
      const auto origin_of = [&](face_descriptor f) { return provenance.faces.at(f); };
      m_provenance.read(*m_mesh, provenance.base_pending, Mask::split == Split::quad, origin_of, provenance.base);
    }

    void write_provenance(const std::vector<New_face>& new_faces, const std::vector<vertex_descriptor>& new_vertices)
    {
      Provenance& provenance = m_data->m_provenance;
      provenance.faces.clear();
      const auto put_face = [&](face_descriptor f, const Face_origin& origin) {
        provenance.faces[f] = origin;
        if(provenance.put_face)
          provenance.put_face(f, origin);
      };
      m_provenance.write(*m_mesh, new_faces, new_vertices, m_new_origins, m_linear_stencils.rows, put_face,
                         provenance.put_vertex);
      provenance.base_pending = false;
    }

    const Carried_data* m_data;
    const Mesh* m_mesh;
    internal::Stencil_recorder<Mesh, FT> m_stencils;
    internal::Stencil_recorder<Mesh, FT> m_linear_stencils;
    std::vector<Vertex_origin> m_new_origins;
    std::vector<std::size_t> m_old_points; // non_manifold_copies, by old vertex ordinal
    internal::Provenance_level<Mesh> m_provenance;
    std::vector<Vertex_writer> m_vertex_writers;
    std::vector<Corner_level> m_corner_levels;
    std::vector<internal::Seam_free_corners<Mesh, FT>> m_seam_free_levels;
    std::vector<Face_writer> m_face_writers;
  };

  /// called by `subdivide()` before the first level, `mesh` untouched yet:
  /// throws `Bad_input` if `mask` cannot carry these maps (the provenance
  /// maps, `Face_origin`; a corner map with a seam, `carries_seams()`), and
  /// makes the mesh of the call the base of the provenance maps
  template <class Mask>
  void prepare(const Mesh& mesh, const Mask& mask) const
  {
    if constexpr(!carries_seams<Mask>()) {
      if(wants_provenance())
        internal::refuse(internal::Message()
                         << "Carried_data: face_origin_map and base_origin_map need a scheme that splits edges "
                            "(Catmull-Clark, Loop, the butterflies, linear); "
                         << mask.name() << " makes faces across the old edges");
      for(const Corner_channel& channel : m_corner_channels)
        internal::refuse_seams(mesh, channel.same, mask.name());
    } else
      (void)mesh;
    m_provenance.base_pending = true;
  }

  /// true if the scheme of `Mask` splits the old edges (Catmull-Clark, Loop,
  /// the butterflies, linear): only such a scheme carries corner maps with
  /// seams and the provenance maps; Doo-Sabin and the sqrt3 schemes, which
  /// make new faces across the old edges, carry corner maps without seams
  template <class Mask>
  static constexpr bool carries_seams()
  {
    return Mask::split == Split::quad || Mask::split == Split::triangle_quadrisection;
  }

private:
  // the linear scheme of the mask's split, or its linear rules: see
  // `Interpolation::linear`
  template <class Mask>
  static auto linear_mask(const Mask& mask)
  {
    if constexpr(!carries_seams<Mask>())
      return internal::linear_rules_across_edges<Mesh, FT>(mask);
    else if constexpr(Mask::split == Split::quad)
      return Linear_quad_mask<Mesh, FT>();
    else
      return Linear_triangle_mask<Mesh, FT>();
  }

  // the state of the provenance maps from level to level
  struct Provenance
  {
    std::function<void(face_descriptor, const Face_origin&)> put_face;
    std::function<void(vertex_descriptor, const Vertex_origin&)> put_vertex;
    bool base_pending = true;
    internal::Base_faces base;
    std::unordered_map<face_descriptor, Face_origin, boost::hash<face_descriptor>> faces;
  };

  bool wants_provenance() const { return bool(m_provenance.put_face) || bool(m_provenance.put_vertex); }

  struct Vertex_channel
  {
    Interpolation interpolation;
    /// reads the old values, combines them by the stencils of the new vertices
    std::function<Vertex_writer(const Vertex_stencils&)> make_writer;
  };

  bool interpolates(Interpolation interpolation) const
  {
    return std::any_of(m_vertex_channels.begin(), m_vertex_channels.end(),
                       [&](const Vertex_channel& c) { return c.interpolation == interpolation; });
  }

  // a corner map on one level: `add_row` combines its old values by each row
  // of the level in turn (none for an index map), `write` puts a new corner's
  // value, given its row
  struct Corner_map_level
  {
    internal::Face_varying_row_visitor<FT> add_row;
    Corner_writer write;
  };
  using Corner_map_start = std::function<Corner_map_level(const internal::Face_varying_topology<Mesh>&)>;

  // corner maps that share one face-varying topology
  struct Corner_channel
  {
    Face_varying_interpolation interpolation;
    /// whether two corners hold the same value (the same index, with an index map)
    std::function<bool(halfedge_descriptor, halfedge_descriptor)> same;
    std::vector<Corner_map_start> maps;
    /// whether a level was carried: the values of the first one are told
    /// apart as on OpenSubdiv's base level, and inherited after
    mutable bool refined = false;
    /// by vertex ordinal of the level being carried, the vertices whose values
    /// are all kept (copies of a non-manifold vertex, and their children);
    /// empty if none
    mutable std::vector<bool> pinned{};
  };

  // a map of values: the new value of a row is the combination of the old
  // values of its terms
  template <class CornerMap>
  static Corner_map_start value_map_level(CornerMap map)
  {
    return [map](const internal::Face_varying_topology<Mesh>& topology) {
      using Value = typename boost::property_traits<CornerMap>::value_type;
      // the old values by cut vertex, read once: the rows read them in the
      // cut's order, not the corners'
      const auto& cut = topology.cut();
      auto old_values = std::make_shared<std::vector<Value>>();
      old_values->reserve(cut.number_of_vertices());
      for(const auto v : cut.vertices())
        old_values->push_back(get(map, topology.corner_of(v)));
      auto values = std::make_shared<std::vector<Value>>();
      // room for a row per vertex, edge and face of the cut mesh: at least as
      // many as the split makes
      values->reserve(cut.number_of_vertices() + cut.number_of_edges() + cut.number_of_faces());
      const auto add_row = [old_values, values](const internal::Face_varying_row<FT>& row) {
        const auto value_of = [&](typename internal::Face_varying_cut_mesh::Vertex_index v) -> const Value& {
          return (*old_values)[v.idx()];
        };
        values->push_back(internal::combine_values<Value>(value_of, row));
      };
      const auto write = [map, values](const std::vector<halfedge_descriptor>& halfedges,
                                       const std::vector<std::size_t>& rows) {
        for(std::size_t k = 0; k < halfedges.size(); ++k)
          put(map, halfedges[k], (*values)[rows[k]]);
      };
      return Corner_map_level{add_row, write};
    };
  }

  // a channel of value indices (`corner_maps`) whose rows also go to `maps`
  template <class IndexMap>
  void add_indexed_channel(Face_varying_interpolation interpolation, IndexMap indices,
                           std::vector<Corner_map_start> maps)
  {
    const auto same = [indices](halfedge_descriptor a, halfedge_descriptor b) {
      return get(indices, a) == get(indices, b);
    };
    maps.insert(maps.begin(), index_map_level(indices));
    m_corner_channels.push_back(Corner_channel{interpolation, same, std::move(maps)});
  }

  // rows only, for `internal::Carried_data_access`: `rows_of_level(topology)`
  // makes the visitor of the rows of the level of `topology`; nothing is
  // written (the channel's index map numbers the new values)
  template <class LevelRows>
  static Corner_map_start row_map_level(LevelRows rows_of_level)
  {
    return [rows_of_level](const internal::Face_varying_topology<Mesh>& topology) {
      return Corner_map_level{rows_of_level(topology),
                              [](const std::vector<halfedge_descriptor>&, const std::vector<std::size_t>&) {}};
    };
  }

  // an index map: a new value's index is its row, so corners with one value
  // share it
  template <class IndexMap>
  static Corner_map_start index_map_level(IndexMap indices)
  {
    return [indices](const internal::Face_varying_topology<Mesh>&) {
      const auto write = [indices](const std::vector<halfedge_descriptor>& halfedges,
                                   const std::vector<std::size_t>& rows) {
        for(std::size_t k = 0; k < halfedges.size(); ++k)
          put(indices, halfedges[k], static_cast<typename boost::property_traits<IndexMap>::value_type>(rows[k]));
      };
      return Corner_map_level{nullptr, write};
    };
  }

  // whether a mask refines with sharpness tags (the smooth face-varying modes
  // cut the mesh and tag the cut); the linear masks are linear in every mode
  template <class Mask, class = void>
  struct has_sharp_level : std::false_type
  {};
  template <class Mask>
  struct has_sharp_level<Mask, std::void_t<decltype(std::declval<const Mask&>().sharp_level())>> : std::true_type
  {};

  std::vector<Vertex_channel> m_vertex_channels;
  std::vector<Corner_channel> m_corner_channels;
  std::vector<std::function<Face_writer(const Mesh&)>> m_face_channels;
  std::vector<Vertex_origin>* m_origins = nullptr;
  std::function<std::size_t(vertex_descriptor)> m_point_of;        // non_manifold_copies
  std::function<void(vertex_descriptor, std::size_t)> m_put_point; // the same, if it is writable
  mutable Provenance m_provenance;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_CARRIED_DATA_H
