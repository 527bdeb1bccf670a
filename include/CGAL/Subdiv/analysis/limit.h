// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_LIMIT_H
#define CGAL_SUBDIV_ANALYSIS_LIMIT_H

/// \file limit.h
/// Limit positions and limit normals of the vertices of a mesh, from the limit
/// and tangent masks of the eigen-analysis (`analyse_surface_scheme()`), and
/// the displacement of the limit surface along its normals.
///
/// How it works (see doc/limit.md):
/// - for a vertex of valence n (interior) or with k faces (border), the masks
///   are those of the analysis at that configuration, computed once per
///   configuration and kept by the `Limit_evaluator`: the limit mask solved
///   exactly (`CGAL::Exact_rational`) from the exact local subdivision matrix,
///   the tangent masks from the analysis in double;
/// - the masks are written over the labels of the analysis (centre, then ring
///   by ring, counter-clockwise from a start edge); the same walk reads the
///   labels of the vertex's neighbourhood in the mesh. They apply when the
///   neighbourhood of `rings + 1` rings (`rings`: the invariant neighbourhood
///   of the scheme) has exactly the connectivity of the analysed one (every
///   other vertex regular and interior, up to that distance);
/// - a vertex whose neighbourhood does not match (next to another
///   extraordinary vertex or to the border, a non-quad face for
///   Catmull-Clark, ...) is evaluated on a copy of the mesh refined once more
///   by the scheme (its descendant has the same limit point and tangent
///   plane), up to `Limit_evaluator::max_extra_levels` levels.

#include <CGAL/Subdiv/Carried_data.h>
#include <CGAL/Subdiv/analysis/surface_analysis.h>
#include <CGAL/Subdiv/analysis/surface_neighbourhood.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/mesh_checks.h>
#include <CGAL/Subdiv/internal/mesh_traits.h>
#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/Subdiv/subdivide.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * The limit and tangent masks of a surface scheme at one configuration (an
 * interior vertex of valence `valence`, or a border vertex with `valence`
 * faces), over the labels of the analysis (`internal::label_neighbourhood`:
 * 0 the centre, then ring by ring counter-clockwise from the start edge; for
 * a border vertex the start edge is the border edge with its face on the left
 * of centre -> neighbour).
 */
struct Limit_masks
{
  std::string scheme; ///< `mask.name()`
  int valence = 0;    ///< interior: valence; border: number of faces
  bool border = false;
  int rings = 0; ///< rings of the invariant neighbourhood the masks are written over
  /// the limit mask (left eigenvector of 1, sum 1), solved exactly from the
  /// exact local subdivision matrix (weights that are rounded transcendental
  /// numbers, e.g. Loop's 1987 beta at n != 3, 4, 6, enter as the rationals
  /// the refinement uses)
  std::vector<CGAL::Exact_rational> limit;
  /// the two tangent masks of the analysis (double), the second possibly
  /// negated so that t0 x t1 points to the side from which the faces are
  /// counter-clockwise (the outside of an outward-oriented closed mesh)
  std::vector<double> tangent[2];
  /// the tangent masks give the tangent plane: the analysis proves the
  /// scheme C1 at this configuration (`Surface_analysis::c1`: a separated
  /// subdominant pair and a regular injective characteristic map), and on the
  /// planar regular layout of the neighbourhood t0 x t1 does not vanish.
  /// Otherwise the normals fall back to face normals (see `limit_normals()`):
  /// e.g. the butterfly at n = 3 or n >= 8, whose subdominant eigenvectors are
  /// not a tangent plane, border vertices with many faces
  bool tangents = false;
  /// the analysis' lambda_1, C1 condition and verdict (for reports)
  std::complex<double> subdominant{0, 0};
  bool c1_necessary = false;
  bool c1 = false;
  /// the connectivity of the analysed neighbourhood of `rings + 1` rings, as
  /// read by the labelling walk (see `internal::Neighbourhood_reader`)
  std::vector<int> connectivity;
  std::size_t neighbourhood_size = 0; ///< labels of that neighbourhood
};

namespace internal {

/*
 * The labelling walk of `label_neighbourhood()` on any FaceGraph, with a
 * transcript of the connectivity it sees: ring 0 is source(start); then in
 * label order every vertex of ring < `rings` is walked counter-clockwise
 * from the halfedge by which it was reached, over its faces, each face's
 * vertices listed in face order after it, every vertex not yet labelled
 * getting the next label. The transcript records, per walked vertex and per
 * halfedge around it, -1 for a border halfedge, or -(10 + face size)
 * followed by the labels of the face's other vertices, and -2 at the end of
 * the vertex. Two neighbourhoods with the same transcript have the same
 * labelled connectivity (faces around every vertex of ring < `rings`, which
 * of those vertices are on the border).
 */
template <class Mesh>
class Neighbourhood_reader
{
public:
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;

  explicit Neighbourhood_reader(const Mesh& mesh) : m_mesh(mesh), m_index(CGAL::get_initialized_vertex_index_map(mesh))
  {
    std::size_t size = 0;
    for(vertex_descriptor v : vertices(mesh))
      size = (std::max)(size, static_cast<std::size_t>(get(m_index, v)) + 1);
    m_label.assign(size, -1);
  }

  /// reads the neighbourhood; false (and a partial result) once more than
  /// `max_labels` vertices are labelled
  bool read(halfedge_descriptor start, int rings, std::size_t max_labels)
  {
    clear();
    std::vector<halfedge_descriptor> entry;
    const auto add = [&](vertex_descriptor v, int ring, halfedge_descriptor out) {
      m_label[get(m_index, v)] = static_cast<int>(vertices_by_label.size());
      vertices_by_label.push_back(v);
      ring_of_label.push_back(ring);
      entry.push_back(out);
    };
    add(source(start, m_mesh), 0, start);
    for(std::size_t i = 0; i < vertices_by_label.size(); ++i) {
      if(ring_of_label[i] >= rings)
        continue;
      const halfedge_descriptor first = entry[i];
      halfedge_descriptor h = first;
      std::size_t guard = 0;
      do {
        if(CGAL::is_border(h, m_mesh)) {
          transcript.push_back(-1);
        } else {
          int size = 0;
          for(halfedge_descriptor g : CGAL::halfedges_around_face(h, m_mesh)) {
            (void)g;
            ++size;
          }
          transcript.push_back(-(10 + size));
          for(halfedge_descriptor g = h; target(g, m_mesh) != source(h, m_mesh); g = next(g, m_mesh)) {
            const vertex_descriptor u = target(g, m_mesh);
            if(m_label[get(m_index, u)] < 0) {
              if(vertices_by_label.size() >= max_labels)
                return false;
              add(u, ring_of_label[i] + 1, next(g, m_mesh));
            }
            transcript.push_back(m_label[get(m_index, u)]);
          }
        }
        h = opposite(prev(h, m_mesh), m_mesh); // counter-clockwise around the vertex
        if(++guard > 100000)
          return false;
      } while(h != first);
      transcript.push_back(-2);
    }
    return true;
  }

  /// forgets the labels of the last read (the reader is reused vertex after vertex)
  void clear()
  {
    for(vertex_descriptor v : vertices_by_label)
      m_label[get(m_index, v)] = -1;
    vertices_by_label.clear();
    ring_of_label.clear();
    transcript.clear();
  }

  std::vector<vertex_descriptor> vertices_by_label;
  std::vector<int> ring_of_label;
  std::vector<int> transcript;

private:
  const Mesh& m_mesh;
  typename CGAL::GetInitializedVertexIndexMap<Mesh>::const_type m_index;
  std::vector<int> m_label;
};

/*
 * Where the walk around v starts and what configuration v is: interior (the
 * valence, any halfedge leaving v) or border (the number of faces, the
 * halfedge leaving v along the border edge whose face is on its left).
 */
template <class Mesh>
struct Vertex_configuration
{
  typename boost::graph_traits<Mesh>::halfedge_descriptor start;
  int valence = 0;
  bool border = false;
};

template <class Mesh>
Vertex_configuration<Mesh> vertex_configuration(typename boost::graph_traits<Mesh>::vertex_descriptor v,
                                                const Mesh& mesh)
{
  Vertex_configuration<Mesh> c;
  int degree = 0;
  c.start = opposite(halfedge(v, mesh), mesh);
  for(auto h : CGAL::halfedges_around_source(v, mesh)) {
    ++degree;
    if(!CGAL::is_border(h, mesh) && CGAL::is_border(opposite(h, mesh), mesh)) {
      c.border = true;
      c.start = h;
    }
  }
  c.valence = c.border ? degree - 1 : degree;
  return c;
}

/*
 * The masks of one configuration, from the analysis: its tangent masks and
 * verdict in double (with the characteristic map, without the verification
 * by refinement), the limit mask solved exactly from the exact
 * local matrix of the same neighbourhood (the analysis' own rule,
 * `normalised_left_fixed_vector`). The connectivity of the analysed
 * neighbourhood is read on its patch with the same walk as the mesh will be,
 * and checked against the analysis' labelling.
 */
template <template <class, class> class MaskTemplate, class... Args>
Limit_masks compute_limit_masks(int valence, bool border, const Args&... args)
{
  using Traits = Host_of<MaskTemplate<Analysis_mesh, double>>;
  Surface_analysis_options options;
  options.characteristic_map = true; // the verdict decides whether the tangent masks are used
  options.verify_limit = false;
  const Surface_analysis<double> analysis =
    analyse_surface_scheme<MaskTemplate, double>(valence, border, options, args...);
  Limit_masks masks;
  masks.scheme = analysis.scheme;
  masks.valence = valence;
  masks.border = border;
  masks.rings = analysis.rings;
  masks.subdominant = analysis.subdominant;
  masks.c1_necessary = analysis.c1_necessary;
  masks.c1 = analysis.c1;
  const std::string where =
    analysis.scheme + (border
                         ? " at a border vertex with " + std::to_string(valence) + " faces"
                         : (Traits::face_centred ? " at a face with " + std::to_string(valence) + " corners"
                                                 : " at an interior vertex of valence " + std::to_string(valence)));
  require(analysis.one_is_simple_and_dominant,
          where + ": 1 is not a simple dominant eigenvalue, there is no limit mask");
  const Local_subdivision_matrix<CGAL::Exact_rational> exact =
    local_subdivision_matrix<MaskTemplate, CGAL::Exact_rational>(valence, border, analysis.rings, args...);
  require(exact.invariant && exact.S.rows() == analysis.matrix.rows(),
          where + ": the exact local matrix does not match");
  masks.limit = normalised_left_fixed_vector(exact.S);
  require(!masks.limit.empty(), where + ": the limit mask is not unique");
  if constexpr(Traits::face_centred) {
    // a dual scheme: the analysis is centred at an n-gon (labels 0..n-1 its
    // corners); the evaluator uses the limit mask only if it is the centroid
    // of the central face (then the face alone is invariant and its limit
    // point does not depend on the faces around it). At the border (the face
    // made of the corners at a border vertex with k faces, labelled from the
    // first corner after its border edges): only if it is the midpoint of its
    // first and last corners, the two corners at the vertex on the new border
    // (k >= 3: the k-gon's border corners; k = 2: those of the border quad),
    // or, k = 1, its corner 3, the kept corner of the corner face.
    const std::size_t corners = static_cast<std::size_t>(border && valence < 3 ? 4 : valence);
    for(std::size_t i = 0; i < masks.limit.size(); ++i) {
      const CGAL::Exact_rational one(1);
      CGAL::Exact_rational expected(0);
      if(!border && i < corners)
        expected = one / CGAL::Exact_rational(valence);
      else if(border && valence == 1 && i == 3)
        expected = one;
      else if(border && valence >= 2 && (i == 0 || i == corners - 1))
        expected = one / CGAL::Exact_rational(2);
      require(masks.limit[i] == expected, where + (border ? ": the limit mask of the border face is not the midpoint "
                                                            "of its border corners"
                                                          : ": the limit mask of the face is not its centroid"));
    }
    masks.tangents = false;
    return masks;
  }

  // the neighbourhood of rings + 1 rings on the analysis' own patch
  const Patch patch = build_patch(Traits::regular_face_size, false, valence, border, masks.rings + 2);
  Neighbourhood_reader<Analysis_mesh> reader(patch.mesh);
  reader.read(patch.start, masks.rings + 1, patch.mesh.number_of_vertices() + 1);
  masks.connectivity = reader.transcript;
  masks.neighbourhood_size = reader.vertices_by_label.size();
  const Labelling labels = label_neighbourhood(patch.mesh, patch.start, false, masks.rings);
  require(labels.size() == masks.limit.size() && labels.size() <= reader.vertices_by_label.size() &&
            std::equal(labels.vertex_of.begin(), labels.vertex_of.end(), reader.vertices_by_label.begin()),
          where + ": the labelling walk does not reproduce the analysis' labels");

  // tangent masks, oriented on the planar layout (faces counter-clockwise seen from +z)
  if(analysis.tangent_mask[0].size() == masks.limit.size() && analysis.tangent_mask[1].size() == masks.limit.size()) {
    masks.tangent[0] = analysis.tangent_mask[0];
    masks.tangent[1] = analysis.tangent_mask[1];
    double t[2][3] = {{0, 0, 0}, {0, 0, 0}};
    const auto& centre = patch.mesh.point(labels.vertex_of[0]);
    for(int a = 0; a < 2; ++a)
      for(std::size_t i = 0; i < labels.size(); ++i) {
        const auto& p = patch.mesh.point(labels.vertex_of[i]);
        t[a][0] += masks.tangent[a][i] * (p.x() - centre.x());
        t[a][1] += masks.tangent[a][i] * (p.y() - centre.y());
      }
    const double z = t[0][0] * t[1][1] - t[0][1] * t[1][0];
    const double scale = std::hypot(t[0][0], t[0][1]) * std::hypot(t[1][0], t[1][1]);
    masks.tangents = analysis.c1 && std::abs(z) > 1e-8 * scale && scale > 0;
    if(z < 0)
      for(double& w : masks.tangent[1])
        w = -w;
  }
  return masks;
}

// a weight of the exact limit mask in the number type of the mesh: itself
// when the types agree or FT can hold it, otherwise the nearest double
template <class FT>
FT exact_weight_as(const CGAL::Exact_rational& w)
{
  if constexpr(std::is_same<FT, CGAL::Exact_rational>::value)
    return w;
  else if constexpr(std::is_floating_point<FT>::value)
    return FT(CGAL::to_double(w));
  else if constexpr(std::is_constructible<FT, CGAL::Exact_rational>::value)
    return FT(w);
  else
    return FT(CGAL::to_double(w));
}

/// no height channel
struct No_heights
{};

// what the evaluation finds at one vertex
template <class Point>
struct Vertex_limit
{
  Point limit;
  Point_FT<Point> height = Point_FT<Point>(0); // limit of the carried heights, if any
  std::array<std::array<double, 3>, 2> tangent{};
  bool tangents = false;
};

template <class Point>
std::array<double, 3> to_double3(const Point& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

inline std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline double norm(const std::array<double, 3>& a)
{
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

} // namespace internal

/*!
 * \ingroup PkgSubdivAnalysis
 * Evaluates limit positions, limit normals and displacements for the scheme
 * `MaskTemplate` (a mask class template `MaskTemplate<Mesh, FT>`, as taken by
 * `analyse_surface_scheme()`: `Loop_mask`, `Catmull_clark_mask`,
 * `Sqrt3_mask`, `Butterfly_mask`, `Modified_butterfly_mask`,
 * `Interpolating_sqrt3_mask`, `Linear_triangle_mask`, `Linear_quad_mask`, an
 * alias template for Warren's Loop), with the mask constructor arguments
 * `Args` (a tension, `Border_corners`, ...). It keeps the masks of every
 * configuration it met: reuse one evaluator for many meshes of the same
 * scheme. Make one with `make_limit_evaluator<MaskTemplate>(args...)`.
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
 * vertices are evaluated on a copy refined once more.
 */
template <template <class, class> class MaskTemplate, class... Args>
class Limit_evaluator
{
public:
  /// extra levels of refinement allowed for vertices whose neighbourhood
  /// does not match the analysed one (sqrt3 hosts: one more)
  int max_extra_levels = 3;

  explicit Limit_evaluator(const Args&... args) : m_args(args...) {}

  /// the masks at an interior vertex of valence n or a border vertex with n
  /// faces (computed on first use); \throws Bad_input where the analysis has none
  const Limit_masks& masks(int n, bool border) const
  {
    const auto key = std::make_pair(n, border);
    auto found = m_cache.find(key);
    if(found == m_cache.end()) {
      Limit_masks computed = std::apply(
        [&](const auto&... a) { return internal::compute_limit_masks<MaskTemplate>(n, border, a...); }, m_args);
      found = m_cache.emplace(key, std::make_shared<Limit_masks>(std::move(computed))).first;
    }
    return *found->second;
  }

  /// the mask of the scheme for `Mesh` and `FT`
  template <class Mesh, class FT>
  MaskTemplate<Mesh, FT> mask() const
  {
    return std::apply([](const auto&... a) { return MaskTemplate<Mesh, FT>(a...); }, m_args);
  }

  /*!
   * moves every vertex of `mesh` to its limit position. np:
   * `vertex_point_map`; `vertex_normal_map` (optional): also writes the limit
   * normals (see `limit_normals()`), computed before the points move.
   */
  template <class PolygonMesh, class NamedParameters = parameters::Default_named_parameters>
  void project_to_limit(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values()) const
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    using parameters::is_default_parameter;
    const auto vpm =
      choose_parameter(get_parameter(np, internal_np::vertex_point), get_property_map(CGAL::vertex_point, mesh));
    const auto results = evaluate(mesh, vpm, static_cast<const internal::No_heights*>(nullptr), "project_to_limit");
    if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_normal_map_t>::value)
      write_normals(mesh, vpm, results, get_parameter(np, internal_np::vertex_normal_map));
    std::size_t k = 0;
    for(auto v : vertices(mesh))
      put(vpm, v, results[k++].limit);
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
   * kernel's FT.
   */
  template <class PolygonMesh, class NormalMap, class NamedParameters = parameters::Default_named_parameters>
  void limit_normals(const PolygonMesh& mesh, NormalMap normals,
                     const NamedParameters& np = parameters::default_values()) const
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    const auto vpm =
      choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, mesh));
    const auto results = evaluate(mesh, vpm, static_cast<const internal::No_heights*>(nullptr), "limit_normals");
    write_normals(mesh, vpm, results, normals);
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
   *   the geometry is, and h is its limit value at the vertex (the limit mask
   *   applied to the carried heights): the heights form a subdivision
   *   function over the same surface, e.g. a linear function of the control
   *   points gives the same linear function of the limit points. The map must
   *   accept the new vertices (for `Surface_mesh`, a map of the mesh); it
   *   holds the carried heights of the refined mesh afterwards.
   * A vertex with a null normal (see `limit_normals()`) stays at its limit
   * position. np: `number_of_iterations`, `vertex_point_map`,
   * `vertex_normal_map` (optional: receives the normals used).
   */
  template <class PolygonMesh, class Height, class NamedParameters = parameters::Default_named_parameters>
  void displace(PolygonMesh& mesh, const Height& height, const NamedParameters& np = parameters::default_values()) const
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    using parameters::is_default_parameter;
    const auto vpm =
      choose_parameter(get_parameter(np, internal_np::vertex_point), get_property_map(CGAL::vertex_point, mesh));
    using Point = typename boost::property_traits<std::remove_const_t<decltype(vpm)>>::value_type;
    using FT = internal::Point_FT<Point>;
    using Vector = internal::Point_vector<Point>;
    const int levels = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 0);
    constexpr bool callable = std::is_invocable<const Height&, const Point&>::value;
    std::vector<internal::Vertex_limit<Point>> results;
    const auto level_np = parameters::number_of_iterations(levels).vertex_point_map(vpm);
    if constexpr(callable) {
      if(levels > 0)
        subdivide(mesh, mask<PolygonMesh, FT>(), level_np);
      results = evaluate(mesh, vpm, static_cast<const internal::No_heights*>(nullptr), "displace");
      for(auto& r : results)
        r.height = FT(height(r.limit));
    } else {
      if(levels > 0) {
        Carried_data<PolygonMesh, FT> data;
        data.vertex_map(height);
        subdivide(mesh, mask<PolygonMesh, FT>(), level_np.carried_data(data));
      }
      results = evaluate(mesh, vpm, &height, "displace");
    }
    const std::vector<std::array<double, 3>> unit = normals_of(mesh, vpm, results);
    if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_normal_map_t>::value) {
      auto normal_map = get_parameter(np, internal_np::vertex_normal_map);
      std::size_t k = 0;
      for(auto v : vertices(mesh)) {
        put(normal_map, v, Vector(FT(unit[k][0]), FT(unit[k][1]), FT(unit[k][2])));
        ++k;
      }
    }
    std::size_t k = 0;
    for(auto v : vertices(mesh)) {
      const Vector n(FT(unit[k][0]), FT(unit[k][1]), FT(unit[k][2]));
      const FT h = results[k].height;
      put(vpm, v, results[k].limit + n * h);
      ++k;
    }
  }

  /*
   * The limit (and, with `heights`, the limit height) and the tangent vectors
   * of every vertex of `mesh`, in the order of vertices(mesh). Checks the mesh
   * as `subdivide()` does. \throws Bad_input
   */
  template <class PolygonMesh, class VPM, class HeightMap>
  std::vector<internal::Vertex_limit<typename boost::property_traits<VPM>::value_type>> evaluate(
    const PolygonMesh& mesh, const VPM& vpm, const HeightMap* heights, const std::string& caller) const
  {
    using Point = typename boost::property_traits<VPM>::value_type;
    using FT = internal::Point_FT<Point>;
    const auto m = mask<PolygonMesh, FT>();
    internal::check_mesh(mesh, vpm, m.name(), Host_of<MaskTemplate<PolygonMesh, FT>>::required_face_size);
    if constexpr(Traits::face_centred) {
      std::vector<internal::Vertex_limit<Point>> results;
      evaluate_dual(mesh, vpm, heights, results, caller + " (" + m.name() + ")");
      return results;
    }
    std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> targets(vertices(mesh).begin(),
                                                                                      vertices(mesh).end());
    std::vector<std::size_t> ids(targets.size());
    for(std::size_t k = 0; k < ids.size(); ++k)
      ids[k] = k;
    std::vector<internal::Vertex_limit<Point>> results(targets.size());
    evaluate_at(mesh, vpm, heights, targets, ids, results, 0, caller + " (" + m.name() + ")");
    return results;
  }

private:
  using Traits = Host_of<MaskTemplate<Analysis_mesh, double>>;

  // weights reported by a mask, scaled
  template <class Vertex, class FT>
  struct Scaled_weights
  {
    std::map<Vertex, FT>* weights;
    FT scale;
    void add(const Vertex& v, const FT& w) { (*weights)[v] += scale * w; }
  };

  /*
   * Dual schemes (Doo-Sabin): the limit point of a vertex v is the limit of
   * the face that the next step makes of the corners at v (the vertex face).
   * Interior v of valence n: that face is an n-gon, and its limit is the
   * centroid of its corners (the limit mask of the analysis centred at an
   * n-gon, checked to be exactly that): (1/n) sum of the corner_node
   * stencils of the corners at v. Border v: the border corners of the new
   * faces at v (the corners of the first and last face around v, on the new
   * border, joined by a border edge) are Chaikin points of the two border
   * edges at v; the vertex face (k >= 3 faces) or the edge quad (k = 2) has
   * that border edge, whose two ends are refined by Chaikin's rule on it
   * alone and converge to its midpoint: the limit is the midpoint of the two
   * border corners, 3/4 v + 1/8 (u + w) for the border neighbours u, w (the
   * quadratic B-spline of the border polygon at v); a corner with a single
   * face is kept (the limit is v). That is the limit mask of the analysis at
   * the border face made from v, checked to be exactly that. Tangent masks:
   * none (face normals; the analysis' tangent masks are over the corners of
   * the next level, which this evaluation does not read).
   */
  template <class Mesh, class VPM, class HeightMap>
  void evaluate_dual(const Mesh& mesh, const VPM& vpm, const HeightMap* heights,
                     std::vector<internal::Vertex_limit<typename boost::property_traits<VPM>::value_type>>& results,
                     const std::string& caller) const
  {
    using Point = typename boost::property_traits<VPM>::value_type;
    using FT = internal::Point_FT<Point>;
    using Vector = internal::Point_vector<Point>;
    using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
    using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
    const auto m = mask<Mesh, FT>();
    std::size_t k = 0;
    for(vertex_descriptor v : vertices(mesh)) {
      std::vector<halfedge_descriptor> corners, border_corners;
      bool border = false;
      for(halfedge_descriptor h : CGAL::halfedges_around_target(v, mesh)) {
        if(CGAL::is_border(h, mesh)) {
          border = true;
          continue;
        }
        corners.push_back(h);
        if(CGAL::is_border(opposite(h, mesh), mesh) || CGAL::is_border(opposite(next(h, mesh), mesh), mesh))
          border_corners.push_back(h);
      }
      const int n = static_cast<int>(corners.size());
      if(border && (border_corners.size() > 2 || border_corners.empty()))
        throw Bad_input(caller + ": vertex " + std::to_string(k) + " has " + std::to_string(border_corners.size()) +
                        " faces with a border edge at it");
      try {
        // the analysis at an n-gon: its limit is its centroid; at the border
        // face made from a border vertex with n faces: the midpoint of its
        // two corners on the border, or the kept corner (checked there)
        masks(n, border);
      } catch(const Bad_input& e) {
        throw Bad_input(caller + ": vertex " + std::to_string(k) + ": " + e.what());
      }
      std::map<vertex_descriptor, FT> weights;
      const std::vector<halfedge_descriptor>& used = border ? border_corners : corners;
      Scaled_weights<vertex_descriptor, FT> acc{&weights, FT(1) / FT(static_cast<int>(used.size()))};
      for(halfedge_descriptor h : used)
        m.corner_node(Corner_view<Mesh>(mesh, h), acc);
      internal::Vertex_limit<Point>& r = results.emplace_back();
      Vector sum = CGAL::NULL_VECTOR;
      FT height(0);
      for(const auto& [u, w] : weights) {
        if(w == FT(0))
          continue;
        sum = sum + (get(vpm, u) - CGAL::ORIGIN) * w;
        if constexpr(!std::is_same<HeightMap, internal::No_heights>::value)
          height = height + FT(get(*heights, u)) * w;
      }
      r.limit = CGAL::ORIGIN + sum;
      r.height = height;
      r.tangents = false;
      ++k;
    }
  }

  template <class Mesh, class VPM, class HeightMap>
  void evaluate_at(const Mesh& mesh, const VPM& vpm, const HeightMap* heights,
                   const std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& targets,
                   const std::vector<std::size_t>& ids,
                   std::vector<internal::Vertex_limit<typename boost::property_traits<VPM>::value_type>>& results,
                   int depth, const std::string& caller) const
  {
    using Point = typename boost::property_traits<VPM>::value_type;
    using FT = internal::Point_FT<Point>;
    using Vector = internal::Point_vector<Point>;
    internal::Neighbourhood_reader<Mesh> reader(mesh);
    std::map<std::pair<int, bool>, std::vector<FT>> weights; // the limit masks in FT
    std::vector<std::size_t> pending;
    // sqrt3 hosts: the border masks are those of a resting step followed by a
    // refining one; on a mesh whose next step refines the border, border
    // vertices are evaluated one step later
    const bool border_phase_differs = border_is_pending(mesh);
    for(std::size_t k = 0; k < targets.size(); ++k) {
      const auto v = targets[k];
      const internal::Vertex_configuration<Mesh> c = internal::vertex_configuration(v, mesh);
      if(c.border && border_phase_differs) {
        pending.push_back(k);
        continue;
      }
      const Limit_masks* found = nullptr;
      try {
        found = &masks(c.valence, c.border);
      } catch(const Bad_input& e) {
        throw Bad_input(caller + ": vertex " + std::to_string(ids[k]) + ": " + e.what());
      }
      const Limit_masks& lm = *found;
      if(!reader.read(c.start, lm.rings + 1, lm.neighbourhood_size) || reader.transcript != lm.connectivity) {
        pending.push_back(k);
        continue;
      }
      auto w = weights.find({c.valence, c.border});
      if(w == weights.end()) {
        std::vector<FT> converted;
        for(const CGAL::Exact_rational& x : lm.limit)
          converted.push_back(internal::exact_weight_as<FT>(x));
        w = weights.emplace(std::make_pair(c.valence, c.border), std::move(converted)).first;
      }
      const std::vector<FT>& limit = w->second;
      internal::Vertex_limit<Point>& r = results[ids[k]];
      Vector sum = CGAL::NULL_VECTOR;
      FT height(0);
      for(std::size_t i = 0; i < limit.size(); ++i) {
        if(limit[i] == FT(0))
          continue;
        sum = sum + (get(vpm, reader.vertices_by_label[i]) - CGAL::ORIGIN) * limit[i];
        if constexpr(!std::is_same<HeightMap, internal::No_heights>::value)
          height = height + FT(get(*heights, reader.vertices_by_label[i])) * limit[i];
      }
      r.limit = CGAL::ORIGIN + sum;
      r.height = height;
      const std::array<double, 3> centre = internal::to_double3(get(vpm, reader.vertices_by_label[0]));
      for(int a = 0; a < 2; ++a) {
        r.tangent[a] = {0, 0, 0};
        for(std::size_t i = 1; i < lm.tangent[a].size(); ++i) {
          const std::array<double, 3> p = internal::to_double3(get(vpm, reader.vertices_by_label[i]));
          for(int d = 0; d < 3; ++d)
            r.tangent[a][d] += lm.tangent[a][i] * (p[d] - centre[d]);
        }
      }
      r.tangents = lm.tangents;
    }
    if(pending.empty())
      return;
    if(depth >= max_extra_levels + (Traits::analysis_steps == 2 ? 1 : 0))
      throw Bad_input(caller + ": vertex " + std::to_string(ids[pending.front()]) +
                      ": its neighbourhood does not become the analysed one after " + std::to_string(depth) +
                      " more levels");
    // one more level of the scheme on a copy; the descendants of the pending
    // vertices have their limit points and tangent planes
    // the copy keeps the order of the vertices and of the faces (unlike
    // copy_face_graph, which reorders the faces): the sqrt3 hosts read the
    // border phase from that order
    using Copy = CGAL::Surface_mesh<Point>;
    Copy copy;
    std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor, typename Copy::Vertex_index>> v2v;
    {
      const auto index = CGAL::get_initialized_vertex_index_map(mesh);
      std::size_t size = 0;
      for(auto v : vertices(mesh))
        size = (std::max)(size, static_cast<std::size_t>(get(index, v)) + 1);
      std::vector<typename Copy::Vertex_index> copied(size);
      for(auto v : vertices(mesh)) {
        copied[get(index, v)] = copy.add_vertex(get(vpm, v));
        v2v.emplace_back(v, copied[get(index, v)]);
      }
      std::vector<typename Copy::Vertex_index> corners;
      for(auto f : faces(mesh)) {
        corners.clear();
        for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
          corners.push_back(copied[get(index, v)]);
        if(copy.add_face(corners) == Copy::null_face())
          throw Bad_input(caller + ": the mesh cannot be copied for a further level of refinement");
      }
    }
    std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, typename Copy::Vertex_index> copy_of(v2v.begin(),
                                                                                                         v2v.end());
    auto copy_heights =
      copy.template add_property_map<typename Copy::Vertex_index, FT>("v:subdiv_limit_height", FT(0)).first;
    if constexpr(!std::is_same<HeightMap, internal::No_heights>::value)
      for(const auto& pair : v2v)
        put(copy_heights, pair.second, FT(get(*heights, pair.first)));
    std::vector<Vertex_origin> origins;
    Carried_data<Copy, FT> data;
    data.origins(origins);
    if constexpr(!std::is_same<HeightMap, internal::No_heights>::value)
      data.vertex_map(copy_heights);
    if(border_is_pending(copy) != border_is_pending(mesh))
      throw Bad_input(caller + ": the copy of the mesh does not keep the border phase of sqrt3");
    subdivide(copy, mask<Copy, FT>(), parameters::number_of_iterations(1).carried_data(data));
    std::vector<typename Copy::Vertex_index> descendant_of_old(v2v.size() + 1);
    std::vector<char> has_descendant(v2v.size() + 1, 0);
    for(std::size_t j = 0; j < origins.size(); ++j)
      if(origins[j].kind == Origin_kind::vertex && origins[j].index < descendant_of_old.size()) {
        descendant_of_old[origins[j].index] = typename Copy::Vertex_index(static_cast<typename Copy::size_type>(j));
        has_descendant[origins[j].index] = 1;
      }
    std::vector<typename Copy::Vertex_index> next_targets;
    std::vector<std::size_t> next_ids;
    for(std::size_t k : pending) {
      const std::size_t old_index = copy_of.at(targets[k]).idx();
      if(!has_descendant[old_index])
        throw Bad_input(caller + ": vertex " + std::to_string(ids[k]) + " has no descendant after refinement");
      next_targets.push_back(descendant_of_old[old_index]);
      next_ids.push_back(ids[k]);
    }
    if constexpr(std::is_same<HeightMap, internal::No_heights>::value)
      evaluate_at(copy, copy.points(), heights, next_targets, next_ids, results, depth + 1, caller);
    else
      evaluate_at(copy, copy.points(), &copy_heights, next_targets, next_ids, results, depth + 1, caller);
  }

  // whether the next step of a sqrt3 host refines the border (false for other hosts)
  template <class Mesh>
  static bool border_is_pending(const Mesh& mesh)
  {
    if constexpr(Traits::analysis_steps == 2) {
      const Host_of<MaskTemplate<Mesh, double>> host(mesh);
      return host.refines_border();
    } else {
      (void)mesh;
      return false;
    }
  }

  // unit normals in double, by vertex order (see limit_normals())
  template <class Mesh, class VPM, class Point>
  static std::vector<std::array<double, 3>> normals_of(const Mesh& mesh, const VPM& vpm,
                                                       const std::vector<internal::Vertex_limit<Point>>& results)
  {
    const auto index = CGAL::get_initialized_vertex_index_map(mesh);
    std::size_t size = 0;
    for(auto v : vertices(mesh))
      size = (std::max)(size, static_cast<std::size_t>(get(index, v)) + 1);
    std::vector<std::size_t> ordinal(size, 0);
    std::vector<std::array<double, 3>> limit_points, control_points;
    std::size_t k = 0;
    for(auto v : vertices(mesh)) {
      ordinal[get(index, v)] = k++;
      control_points.push_back(internal::to_double3(get(vpm, v)));
    }
    for(const auto& r : results)
      limit_points.push_back(internal::to_double3(r.limit));
    // area-weighted normal of the faces around v (Newell), nothing if it vanishes
    const auto faces_normal = [&](auto v, const std::vector<std::array<double, 3>>& points,
                                  std::array<double, 3>& out) -> bool {
      std::array<double, 3> sum{0, 0, 0};
      double areas = 0;
      for(auto f : CGAL::faces_around_target(halfedge(v, mesh), mesh)) {
        if(f == boost::graph_traits<Mesh>::null_face())
          continue;
        std::array<double, 3> n{0, 0, 0};
        for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
          const auto& p = points[ordinal[get(index, source(h, mesh))]];
          const auto& q = points[ordinal[get(index, target(h, mesh))]];
          const std::array<double, 3> c = internal::cross(p, q);
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
    std::vector<std::array<double, 3>> normals(results.size(), std::array<double, 3>{0, 0, 0});
    k = 0;
    for(auto v : vertices(mesh)) {
      const auto& r = results[k];
      std::array<double, 3>& out = normals[k];
      ++k;
      if(r.tangents) {
        const std::array<double, 3> n = internal::cross(r.tangent[0], r.tangent[1]);
        const double length = internal::norm(n);
        const double scale = internal::norm(r.tangent[0]) * internal::norm(r.tangent[1]);
        if(std::isfinite(length) && std::isfinite(scale) && scale > 0 && length > 1e-10 * scale) {
          for(int d = 0; d < 3; ++d)
            out[d] = n[d] / length;
          continue;
        }
      }
      if(!faces_normal(v, limit_points, out) && !faces_normal(v, control_points, out))
        out = {0, 0, 0};
    }
    return normals;
  }

  template <class Mesh, class VPM, class Point, class NormalMap>
  static void write_normals(const Mesh& mesh, const VPM& vpm, const std::vector<internal::Vertex_limit<Point>>& results,
                            NormalMap normals)
  {
    using FT = internal::Point_FT<Point>;
    using Vector = typename boost::property_traits<NormalMap>::value_type;
    const std::vector<std::array<double, 3>> unit = normals_of(mesh, vpm, results);
    std::size_t k = 0;
    for(auto v : vertices(mesh)) {
      put(normals, v, Vector(FT(unit[k][0]), FT(unit[k][1]), FT(unit[k][2])));
      ++k;
    }
  }

  std::tuple<Args...> m_args;
  mutable std::map<std::pair<int, bool>, std::shared_ptr<Limit_masks>> m_cache;
};

/*!
 * \ingroup PkgSubdivAnalysis
 * an evaluator for `MaskTemplate` with mask constructor arguments, e.g.
 * `make_limit_evaluator<Loop_mask>(Border_corners::sharp)`.
 */
template <template <class, class> class MaskTemplate, class... Args>
Limit_evaluator<MaskTemplate, Args...> make_limit_evaluator(const Args&... args)
{
  return Limit_evaluator<MaskTemplate, Args...>(args...);
}

/*!
 * \ingroup PkgSubdivAnalysis
 * moves every vertex of `mesh` to its limit position under the scheme
 * `MaskTemplate`, e.g. `project_to_limit<Loop_mask>(mesh)`; see
 * `Limit_evaluator::project_to_limit()`. Interpolating schemes leave the
 * points where they are (their limit masks are the unit vector of the centre).
 * \throws Bad_input for a mesh the scheme does not apply to, a vertex whose
 * configuration the analysis does not cover (Doo-Sabin: an interior vertex of
 * valence 2).
 */
template <template <class, class> class MaskTemplate, class PolygonMesh,
          class NamedParameters = parameters::Default_named_parameters>
void project_to_limit(PolygonMesh& mesh, const NamedParameters& np = parameters::default_values())
{
  Limit_evaluator<MaskTemplate>().project_to_limit(mesh, np);
}

/*!
 * \ingroup PkgSubdivAnalysis
 * writes the unit limit normal of every vertex into `normals`, e.g.
 * `limit_normals<Catmull_clark_mask>(mesh, normal_map)`; see
 * `Limit_evaluator::limit_normals()` (tangent masks, fallback to face normals).
 */
template <template <class, class> class MaskTemplate, class PolygonMesh, class NormalMap,
          class NamedParameters = parameters::Default_named_parameters>
void limit_normals(const PolygonMesh& mesh, NormalMap normals, const NamedParameters& np = parameters::default_values())
{
  Limit_evaluator<MaskTemplate>().limit_normals(mesh, normals, np);
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_LIMIT_H
