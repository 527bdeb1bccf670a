// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_LIMIT_EVALUATOR_H
#define CGAL_SUBDIV_LIMIT_LIMIT_EVALUATOR_H

/// \file Limit_evaluator.h
/// Limit positions and limit normals of the vertices of a mesh, and the
/// displacement of the limit surface along its normals: appliers of the
/// limit rows (`limit_rows.h`) made from the masks of the analysis.

#include <CGAL/Subdiv/Carried_data.h>
#include <CGAL/Subdiv/analysis/Configuration.h>
#include <CGAL/Subdiv/analysis/Limit_masks.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/hosts/hosts.h>
#include <CGAL/Subdiv/internal/mesh_checks.h>
#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/Subdiv/limit/limit_rows.h>
#include <CGAL/Subdiv/limit/limit_values.h>
#include <CGAL/Subdiv/limit/sharp_limit_rows.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/subdivide.h>
#include <CGAL/Subdiv/views/Sharpness_tags.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * Evaluates limit positions, limit normals and displacements for the scheme
 * of a mask object (`Loop_mask`, `Catmull_clark_mask`, `Doo_sabin_mask`,
 * `Sqrt3_mask`, the butterflies, the linear masks, over any mesh type and
 * number type: the evaluator rebinds it to the mesh and the kernel of each
 * call, keeping its options). It keeps the masks of every configuration it
 * met: reuse one evaluator for many meshes of the same scheme.
 *
 * Every evaluation is an application of the limit rows (`limit_rows.h`):
 * the limit and tangent masks of the analysis at each vertex's configuration
 * (`masks()`), read on the mesh with the analysis' own walk; a vertex whose
 * neighbourhood does not match the analysed one yet is evaluated at its
 * descendant one level further, its rows composed with that level's
 * stencils. Any `FaceGraph` (that level is made on a copy of the same type).
 *
 * Dual schemes (`Doo_sabin_mask`): a vertex's limit point is that of its
 * vertex face (the face the next step makes of the corners at it): the
 * centroid of the corners at an interior vertex (the limit mask of the
 * analysis centred at that n-gon), the midpoint of the two border corners at
 * a border vertex (the Chaikin border), the vertex itself at a corner with a
 * single face (both the limit masks of the analysis at the border face made
 * from the vertex); normals are face normals (see doc/limit.md).
 *
 * sqrt3 hosts: the border analysis is that of a resting step followed by a
 * refining one; on a mesh whose next step refines the border, border
 * vertices are evaluated one step further.
 */
template <class Mask>
class Limit_evaluator
{
public:
  /// extra levels of refinement allowed for vertices whose neighbourhood
  /// does not match the analysed one (sqrt3 hosts: one more)
  int max_extra_levels = 3;

  explicit Limit_evaluator(const Mask& mask = Mask()) : m_mask(mask) {}

  /// the scheme's mask for `Mesh` and `FT`, with the options of the evaluator's mask
  template <class Mesh, class FT>
  auto mask() const
  {
    return m_mask.template rebind<Mesh, FT>();
  }

  /// the masks at an interior vertex of valence n or a border vertex with n
  /// faces (computed on first use); \throws Bad_input where the analysis has none
  const Limit_masks& masks(int n, bool border) const
  {
    const auto key = std::make_pair(n, border);
    auto found = m_cache.find(key);
    if(found == m_cache.end()) {
      const Configuration where(n, border ? Vertex_kind::border : Vertex_kind::interior);
      found = m_cache.emplace(key, std::make_shared<Limit_masks>(internal::compute_limit_masks(m_mask, where))).first;
    }
    return *found->second;
  }

  /*!
   * the limit rows of every vertex of `mesh` (in the order of
   * `vertices(mesh)`), over the vertices of `mesh` by ordinal, in `FT`,
   * with the sharpness tags `tags` of the mesh's level
   * (`internal::sharpness_tags_of`; by default none). Checks the mesh and the
   * tags as `subdivide()` does. \throws Bad_input
   */
  template <class FT, class PolygonMesh, class VertexPointMap, class Tags = internal::No_sharpness_tags>
  internal::Limit_rows<FT> rows(const PolygonMesh& mesh, const VertexPointMap& vpm, const std::string& caller,
                                const Tags& tags = Tags()) const
  {
    const auto m = mask<PolygonMesh, FT>();
    using M = std::decay_t<decltype(m)>;
    using Host = Host_of<M>;
    internal::check_mesh(mesh, vpm, m.name(), Host::required_face_size);
    const auto cached = [this](int n, bool border) -> const Limit_masks& { return masks(n, border); };
    const std::string who = caller + " (" + m.name() + ")";
    if constexpr(Host::face_centred) {
      static_assert(std::is_same<Tags, internal::No_sharpness_tags>::value,
                    "the limit of Doo-Sabin does not take sharpness tags (edge_sharpness_map, "
                    "vertex_sharpness_map): the limit of its creases is not derived (subdivide() takes them)");
      return internal::dual_limit_rows(cached, m, mesh, who);
    } else {
      internal::Limit_rows<FT> result; // sized by sharpen() where there are tags
      const std::vector<std::size_t> smooth = sharpen(result, mesh, tags, who);
      internal::Limit_rows<FT> analysed =
        internal::limit_rows(cached, m, mesh, smooth, smooth, max_extra_levels, 0, who);
      if constexpr(internal::Has_crease_curve<M>::value)
        if(internal::border_corners_of(m) == Border_corners::sharp &&
           !internal::crease_tangent_weights(m.crease_curve()).empty()) // Loop and Catmull-Clark (as sharpen())
          internal::kept_corner_tangent_rows(analysed, smooth, mesh);
      if(smooth.size() == num_vertices(mesh))
        return analysed; // no vertex is a corner or a crease
      for(std::size_t k = 0; k < smooth.size(); ++k) {
        result.position[smooth[k]] = std::move(analysed.position[k]);
        for(int a = 0; a < 2; ++a)
          result.tangent[a][smooth[k]] = std::move(analysed.tangent[a][k]);
        result.has_tangents[smooth[k]] = analysed.has_tangents[k];
      }
      return result;
    }
  }

private:
  /*
   * The sharpness tags `tags` (`internal::sharpness_tags_of`), if any, at the
   * mesh's level (`internal::sharp_limit_rows`): checked as `subdivide()`
   * checks them, then the corners and creases get their limit rows in
   * `rows` (sized to the mesh). Returns the other vertices (ordinals), those the analysis
   * evaluates. The linear masks take tags and move no point for them: every
   * vertex is the analysis'.
   */
  template <class FT, class PolygonMesh, class Tags>
  std::vector<std::size_t> sharpen(internal::Limit_rows<FT>& rows, const PolygonMesh& mesh, const Tags& tags,
                                   const std::string& who) const
  {
    if constexpr(!std::is_same<Tags, internal::No_sharpness_tags>::value) {
      const auto m = mask<PolygonMesh, FT>();
      using M = std::decay_t<decltype(m)>;
      static_assert(internal::Limit_takes_sharpness_tags<M>::value,
                    "the limit of this scheme does not take sharpness tags (edge_sharpness_map, "
                    "vertex_sharpness_map) yet (Doo-Sabin: the limit of its creases is not derived)");
      if constexpr(internal::Has_crease_curve<M>::value || M::split == Split::sqrt3) {
        tags.check(mesh, m, who);
        rows = internal::Limit_rows<FT>(num_vertices(mesh));
        std::vector<FT> crease, along;
        internal::Sharp_tangents tangents = internal::Sharp_tangents::none;
        if constexpr(M::split == Split::sqrt3) {
          // the crease rule is the border rule: the border analysis' limit,
          // at the regular border vertex (3 triangles; the border rule reads
          // the border alone, so any number of faces gives the same weights)
          try {
            crease = internal::crease_limit_weights<FT>(masks(3, true));
          } catch(const Bad_input& e) {
            throw Bad_input(who + ": " + e.what());
          }
        } else {
          crease = internal::crease_limit_weights(m.crease_curve());
          // the tangents of Loop and Catmull-Clark (not of the butterflies,
          // whose crease rule interpolates: no along-crease tangent)
          along = internal::crease_tangent_weights(m.crease_curve());
          if(!along.empty())
            tangents =
              M::split == Split::quad ? internal::Sharp_tangents::catmull_clark : internal::Sharp_tangents::loop;
        }
        // the rules of this level do not depend on how sharpness decays
        return internal::sharp_limit_rows(rows, mesh, tags.level(mesh, internal::border_corners_of(m)), crease, along,
                                          tangents);
      }
    }
    (void)tags, (void)who;
    std::vector<std::size_t> every(num_vertices(mesh));
    for(std::size_t k = 0; k < every.size(); ++k)
      every[k] = k;
    return every;
  }

public:
  /*!
   * the limit point, the two tangent vectors (double) and the limit of
   * `heights` (a vertex property map of scalars, optional) of every vertex of
   * `mesh`, in the order of `vertices(mesh)`. \throws Bad_input naming `caller`
   */
  template <class PolygonMesh, class VertexPointMap, class HeightMap = internal::No_heights>
  std::vector<internal::Vertex_limit<typename boost::property_traits<VertexPointMap>::value_type>> evaluate(
    const PolygonMesh& mesh, const VertexPointMap& vpm, const HeightMap* heights = nullptr,
    const std::string& caller = "evaluate") const
  {
    using Point = typename boost::property_traits<VertexPointMap>::value_type;
    using FT = internal::Point_FT<Point>;
    const Evaluation<PolygonMesh, VertexPointMap> e(*this, mesh, vpm, caller);
    std::vector<FT> carried;
    if constexpr(!std::is_same<HeightMap, internal::No_heights>::value)
      for(auto v : vertices(mesh))
        carried.push_back(FT(get(*heights, v)));
    std::vector<internal::Vertex_limit<Point>> results(e.limits.size());
    for(std::size_t k = 0; k < results.size(); ++k) {
      results[k].limit = e.limits[k];
      results[k].tangent = e.tangents[k];
      results[k].tangents = e.rows.has_tangents[k] != 0;
      if constexpr(!std::is_same<HeightMap, internal::No_heights>::value)
        results[k].height = internal::apply_value_row(e.rows.position[k], [&](std::size_t i) { return carried[i]; });
    }
    return results;
  }

  /*!
   * moves every vertex of `mesh` to its limit position. np:
   * `vertex_point_map`; `vertex_normal_map` (optional): also writes the limit
   * normals (see `limit_normals()`), computed before the points move;
   * `edge_sharpness_map`, `vertex_sharpness_map` (Loop, Catmull-Clark, the
   * linear masks): the sharpness tags of the mesh's level, as OpenSubdiv's
   * `PrimvarRefiner::Limit` takes them (a corner stays, a crease goes to the
   * limit of the curve rule along its two sharp edges, other vertices as
   * without tags; semi-sharp counts as sharp; see doc/sharp_features.md).
   * Interpolating schemes leave the points where they are.
   */
  template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
  void project_to_limit(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values()) const
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    using parameters::is_default_parameter;
    const auto vpm =
      choose_parameter(get_parameter(np, internal_np::vertex_point), get_property_map(CGAL::vertex_point, mesh));
    const Evaluation<PolygonMesh, decltype(vpm)> e(*this, mesh, vpm, "project_to_limit", np);
    if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_normal_map_t>::value)
      e.write_normals(get_parameter(np, internal_np::vertex_normal_map));
    e.write_limit_points();
  }

  /*!
   * writes the unit limit normal of every vertex into `normals` (a vertex
   * property map of the kernel's `Vector_3`). np: `vertex_point_map`.
   * The normal is t0 x t1 for the tangent vectors t0, t1 of the tangent masks,
   * oriented as the faces (counter-clockwise faces: the normal points towards
   * the viewer). Where the tangent masks are not usable (see
   * `Limit_masks::tangents`) or |t0 x t1| <= 1e-10 |t0| |t1| (flat-folded or
   * degenerate neighbourhoods), it is the area-weighted average of the
   * normals of the faces around the vertex with the corners at their limit
   * positions; if that vanishes too (relative to the sum of the face areas,
   * 1e-12), the same with the control points; if that vanishes, the null
   * vector. Never NaN. The normals are computed in double and converted to the
   * kernel's FT. With sharpness tags (`edge_sharpness_map`,
   * `vertex_sharpness_map`, as in `project_to_limit()`), corners and creases
   * of Loop and Catmull-Clark take tangent rows as OpenSubdiv Far's
   * `PrimvarRefiner::Limit` does (`internal::sharp_limit_rows`): along and
   * across a crease, on the side of Far's first face at the vertex, and along
   * the two edges of that face at a corner (see doc/sharp_features.md); the
   * other schemes' take the face normals.
   */
  template <class PolygonMesh, class NormalMap, class NamedParameters = parameters::Default_named_parameters>
  void limit_normals(const PolygonMesh& mesh, NormalMap normals,
                     const NamedParameters& np = parameters::default_values()) const
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    const auto vpm =
      choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, mesh));
    const Evaluation<PolygonMesh, decltype(vpm)> e(*this, mesh, vpm, "limit_normals", np);
    e.write_normals(normals);
  }

  /*!
   * displacement mapping: refines `mesh` `number_of_iterations` times (np,
   * default 0), then moves every vertex to limit + h n, with n its unit limit
   * normal (`limit_normals()`) and h its height:
   * - `height` a callable `Point -> FT` (anything convertible to FT): h is
   *   its value at the vertex's limit position;
   * - otherwise `height` is a vertex property map of scalars (FT, or
   *   convertible to FT) on the coarse mesh: it is carried through the levels
   *   with the scheme's stencils (`Carried_data`), so it is refined exactly as
   *   the geometry is, and h is its limit value at the vertex (the limit row
   *   applied to the carried heights): the heights form a subdivision
   *   function over the same surface, e.g. a linear function of the control
   *   points gives the same linear function of the limit points. The map must
   *   accept the new vertices (for `Surface_mesh`, a map of the mesh); it
   *   holds the carried heights of the refined mesh afterwards.
   * A vertex with a null normal (see `limit_normals()`) stays at its limit
   * position. np: `number_of_iterations`, `vertex_point_map`,
   * `vertex_normal_map` (optional: receives the normals used); the sharpness
   * tags of `subdivide()` (`edge_sharpness_map`, `vertex_sharpness_map`,
   * `crease_method`, `face_hole_map`, `boundary_interpolation`,
   * `triangle_subdivision`): the levels refine them, and the limit takes
   * those of the refined mesh, as `project_to_limit()` does.
   */
  template <class PolygonMesh, class Height, class NamedParameters = parameters::Default_named_parameters>
  void displace(PolygonMesh& mesh, const Height& height, const NamedParameters& np = parameters::default_values()) const
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    using parameters::is_default_parameter;
    const auto vpm =
      choose_parameter(get_parameter(np, internal_np::vertex_point), get_property_map(CGAL::vertex_point, mesh));
    using VPM = std::remove_const_t<decltype(vpm)>;
    using Point = typename boost::property_traits<VPM>::value_type;
    using FT = internal::Point_FT<Point>;
    using Vector = internal::Point_vector<Point>;
    const int levels = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 0);
    constexpr bool callable = std::is_invocable<const Height&, const Point&>::value;
    // the levels take the tags of np (and refine them), if there are some:
    // then np is a chain of the package's parameters
    const auto level_np = [&]() {
      if constexpr(internal::has_sharpness_tags<NamedParameters>())
        return np.number_of_iterations(levels).vertex_point_map(vpm);
      else
        return parameters::number_of_iterations(levels).vertex_point_map(vpm).max_memory(internal::max_memory_of(np));
    }();
    if constexpr(callable) {
      if(levels > 0)
        subdivide(mesh, mask<PolygonMesh, FT>(), level_np);
    } else if(levels > 0) {
      Carried_data<PolygonMesh, FT> data;
      data.vertex_map(height);
      subdivide(mesh, mask<PolygonMesh, FT>(), level_np.carried_data(data));
    }
    const Evaluation<PolygonMesh, VPM> e(*this, mesh, vpm, "displace", np);
    std::vector<FT> heights(e.limits.size());
    if constexpr(callable) {
      for(std::size_t k = 0; k < heights.size(); ++k)
        heights[k] = FT(height(e.limits[k]));
    } else {
      std::vector<FT> carried;
      for(auto v : vertices(mesh))
        carried.push_back(FT(get(height, v)));
      for(std::size_t k = 0; k < heights.size(); ++k)
        heights[k] = internal::apply_value_row(e.rows.position[k], [&](std::size_t i) { return carried[i]; });
    }
    const std::vector<std::array<double, 3>> unit = e.normals();
    std::size_t k = 0;
    for(auto v : vertices(mesh)) {
      const Vector n(FT(unit[k][0]), FT(unit[k][1]), FT(unit[k][2]));
      if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_normal_map_t>::value)
        put(get_parameter(np, internal_np::vertex_normal_map), v, n);
      put(vpm, v, e.limits[k] + n * heights[k]);
      ++k;
    }
  }

private:
  /*
   * One evaluation of a mesh: its limit rows and what they give, by vertex
   * order: the limit points and the tangent vectors (double).
   */
  template <class PolygonMesh, class VPM>
  struct Evaluation
  {
    using Point = typename boost::property_traits<VPM>::value_type;
    using FT = internal::Point_FT<Point>;

    const PolygonMesh& mesh;
    const VPM& vpm;
    std::vector<Point> control;
    internal::Limit_rows<FT> rows;
    std::vector<Point> limits;
    std::vector<std::array<std::array<double, 3>, 2>> tangents;

    template <class NamedParameters = parameters::Default_named_parameters>
    Evaluation(const Limit_evaluator& evaluator, const PolygonMesh& m, const VPM& map, const std::string& caller,
               const NamedParameters& np = parameters::default_values())
      : mesh(m), vpm(map),
        rows(evaluator.template rows<FT>(m, map, caller, internal::sharpness_tags_of<PolygonMesh, FT>(np)))
    {
      for(auto v : vertices(mesh))
        control.push_back(get(vpm, v));
      const auto point_of = [&](std::size_t i) -> const Point& { return control[i]; };
      for(std::size_t k = 0; k < control.size(); ++k) {
        limits.push_back(internal::apply_row<Point>(rows.position[k], point_of));
        const std::array<double, 3> centre = internal::to_double3(control[k]);
        tangents.push_back({internal::apply_difference_row(rows.tangent[0][k], point_of, centre),
                            internal::apply_difference_row(rows.tangent[1][k], point_of, centre)});
      }
    }

    void write_limit_points() const
    {
      std::size_t k = 0;
      for(auto v : vertices(mesh))
        put(vpm, v, limits[k++]);
    }

    // unit normals in double, by vertex order (see limit_normals())
    std::vector<std::array<double, 3>> normals() const
    {
      const internal::Mesh_numbering<PolygonMesh> number(mesh);
      std::vector<std::array<double, 3>> limit_points, control_points;
      for(const Point& p : control)
        control_points.push_back(internal::to_double3(p));
      for(const Point& p : limits)
        limit_points.push_back(internal::to_double3(p));
      // area-weighted normal of the faces around v (Newell), nothing if it vanishes
      const auto faces_normal = [&](auto v, const std::vector<std::array<double, 3>>& points,
                                    std::array<double, 3>& out) -> bool {
        std::array<double, 3> sum{0, 0, 0};
        double areas = 0;
        for(auto f : CGAL::faces_around_target(halfedge(v, mesh), mesh)) {
          if(f == boost::graph_traits<PolygonMesh>::null_face())
            continue;
          std::array<double, 3> n{0, 0, 0};
          for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
            const std::array<double, 3> c =
              internal::cross(points[number(source(h, mesh))], points[number(target(h, mesh))]);
            for(int d = 0; d < 3; ++d)
              n[d] += 0.5 * c[d];
          }
          for(int d = 0; d < 3; ++d)
            sum[d] += n[d];
          areas += internal::norm(n);
        }
        const double length = internal::norm(sum);
        if(!(std::isfinite(length) && length > 1e-12 * areas && length > 0))
          return false;
        for(int d = 0; d < 3; ++d)
          out[d] = sum[d] / length;
        return true;
      };
      std::vector<std::array<double, 3>> result(control.size(), std::array<double, 3>{0, 0, 0});
      std::size_t k = 0;
      for(auto v : vertices(mesh)) {
        std::array<double, 3>& out = result[k];
        if(rows.has_tangents[k]) {
          const std::array<double, 3> n = internal::cross(tangents[k][0], tangents[k][1]);
          const double length = internal::norm(n);
          const double scale = internal::norm(tangents[k][0]) * internal::norm(tangents[k][1]);
          if(std::isfinite(length) && std::isfinite(scale) && scale > 0 && length > 1e-10 * scale) {
            for(int d = 0; d < 3; ++d)
              out[d] = n[d] / length;
            ++k;
            continue;
          }
        }
        if(!faces_normal(v, limit_points, out) && !faces_normal(v, control_points, out))
          out = {0, 0, 0};
        ++k;
      }
      return result;
    }

    template <class NormalMap>
    void write_normals(NormalMap normal_map) const
    {
      using Vector = typename boost::property_traits<NormalMap>::value_type;
      const std::vector<std::array<double, 3>> unit = normals();
      std::size_t k = 0;
      for(auto v : vertices(mesh)) {
        put(normal_map, v, Vector(FT(unit[k][0]), FT(unit[k][1]), FT(unit[k][2])));
        ++k;
      }
    }
  };

  Mask m_mask;
  mutable std::map<std::pair<int, bool>, std::shared_ptr<Limit_masks>> m_cache;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_LIMIT_EVALUATOR_H
