// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_LIMIT_SURFACE_H
#define CGAL_SUBDIV_LIMIT_LIMIT_SURFACE_H

/// \file Limit_surface.h
/// The limit surface of Catmull-Clark anywhere: the position, first and
/// second derivatives and the normal at any (face, u, v), by local
/// refinement down to a regular patch, evaluated as a bicubic B-spline.

#include <CGAL/Iterator_range.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/Carried_data.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/limit/Limit_sample.h>
#include <CGAL/Subdiv/limit/Stam_eigenbasis.h>
#include <CGAL/Subdiv/limit/local_patch.h>
#include <CGAL/Subdiv/limit/patch_basis.h>
#include <CGAL/Subdiv/limit/patch_points.h>
#include <CGAL/Subdiv/limit/project_to_limit.h>
#include <CGAL/Subdiv/masks/Catmull_clark_mask.h>
#include <CGAL/Subdiv/masks/Loop_mask.h>
#include <CGAL/Subdiv/stencils/Stencil_table.h>
#include <CGAL/Subdiv/subdivide.h>
#include <CGAL/Subdiv/views/Sharpness.h>
#include <CGAL/Subdiv/views/Sharpness_tags.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivStencils
 * Limit stencils at (face, u, v) locations (`Limit_surface::stencil_tables()`):
 * row i of each table belongs to location i, its sources are the vertices of
 * the mesh.
 */
template <class FT>
struct Limit_location_stencils
{
  Stencil_table<FT> position;      ///< the limit point (weights summing to 1)
  Stencil_table<FT> du, dv;        ///< the first derivatives (weights summing to 0)
  Stencil_table<FT> duu, duv, dvv; ///< the second derivatives
  /// the six tables, in the order above
  std::array<Stencil_table<FT>*, 6> all() { return {&position, &du, &dv, &duu, &duv, &dvv}; }
};

namespace internal {

/// whether `Mask` is a Catmull-Clark or a Loop mask: the schemes whose
/// regular patches `Limit_surface` evaluates
template <class Mask>
struct Patch_scheme
{
  static constexpr bool catmull_clark = false, loop = false;
};
template <class Mesh, class FT, bool Tagged>
struct Patch_scheme<Catmull_clark_mask<Mesh, FT, Tagged>>
{
  static constexpr bool catmull_clark = true, loop = false;
};
template <class Mesh, class FT, class Beta, bool Tagged>
struct Patch_scheme<Loop_mask<Mesh, FT, Beta, Tagged>>
{
  static constexpr bool catmull_clark = false, loop = true;
};

} // namespace internal

/*!
 * \ingroup PkgSubdivAnalysis
 * Evaluates the limit surface of a mesh under Catmull-Clark
 * (`Catmull_clark_mask`, the default, with borders and either
 * `Border_corners`) or Loop (`Loop_mask`, either beta and either
 * `Border_corners`) at any parameter of any face, closed or with borders,
 * with OpenSubdiv's sharpness tags if given (the constructor with named
 * parameters).
 *
 * Parameters (doc/provenance.md, "Faces"): a quad has corner 0 (the target
 * of `halfedge(f)`) at (0,0), corner 1 at (1,0), corner 2 at (1,1) and
 * corner 3 at (0,1); a triangle (Loop) corner 0 at (0,0), corner 1 at (1,0)
 * and corner 2 at (0,1), with u + v <= 1; under Catmull-Clark a face with
 * n != 4 corners is addressed as n sub-quads (face, corner c, u, v): (0,0)
 * at corner c, u towards the midpoint of the edge from corner c to corner
 * c+1, v towards the midpoint of the edge from corner c-1 to corner c,
 * (1,1) at the face point.
 *
 * Method: a quad whose four corners have valence 4 (and only quads around
 * them) is a regular patch, evaluated exactly as the bicubic B-spline of its
 * 16 control points (`bspline_patch_weights()`); so is a triangle whose
 * three corners have valence 6 (and only triangles around them), as the
 * quartic box spline of its 12 (`box_spline_patch_weights()`). Under
 * Catmull-Clark a quad with one side on the border, or with
 * `Border_corners::sharp` two sides meeting at a corner of one face, is
 * regular too, and under Loop a triangle with one corner or one side on the
 * border, each such corner with three faces: the control points beyond the
 * border are extrapolated (`Patch_points`). In a
 * floating-point kernel, a patch whose one extraordinary corner is inner
 * (all its faces quads, or triangles) is evaluated by Stam's method
 * (`Stam_eigenbasis.h`): the local subdivision matrix of the patch and of
 * its three regular children, read off the mask's own refinement of the
 * patch, are diagonalised once per valence (cached), and a parameter at
 * any distance from the corner costs one product with the eigenbasis, no
 * refinement; where the matrix is not diagonalisable (Loop at valence 3)
 * the child's control points are taken through powers of the matrix (one
 * K x K product per level), still with no refinement. Any other
 * face (and every face in an exact kernel) is refined (with the library's
 * own `subdivide()`, in the mesh's number type; see below for where) and
 * the child that holds (u, v) is evaluated in turn: every child away from an
 * extraordinary vertex is regular after one level, and a parameter at
 * distance d from the extraordinary corner is reached after about
 * log2(1/d) levels. So the evaluation is exact in an exact kernel (up to
 * the final conversion to double) at every parameter but an extraordinary
 * vertex itself, where the position is the limit mask of the analysis
 * (`project_to_limit()`), the normal its tangent masks'
 * (`limit_normals()`), and the derivatives, which the parameterisation does
 * not have there, are zero. A parameter closer than 2^-`max_depth` to an
 * extraordinary corner is evaluated at that corner (the surface moves by
 * about lambda^`max_depth` times the patch's size there, lambda < 0.65 the
 * subdominant eigenvalue).
 *
 * A face of the mesh that is not a direct patch starts from its children
 * in the whole mesh refined once (`refine_whole_mesh`, made by the first
 * evaluation that needs it and kept): after one level they are regular or
 * Stam patches, but near several extraordinary vertices, so most
 * evaluations refine nothing at all. The values are those of the local
 * refinement, exactly in an exact kernel (up to rounding in double).
 *
 * What an evaluation makes is kept for the next ones on the same face
 * (`cached_faces`): the face's direct patch (control points, or Stam's
 * eigen-coefficients) or its children, down to the ones the parameters
 * reached; the values are bit for bit those of a fresh evaluation.
 * Evaluations may run in several threads at once (copies of the evaluator
 * share what is kept).
 */
template <class PolygonMesh, class Mask = Catmull_clark_mask<PolygonMesh>>
class Limit_surface
{
  static_assert(internal::Patch_scheme<Mask>::catmull_clark || internal::Patch_scheme<Mask>::loop,
                "Limit_surface: Catmull_clark_mask or Loop_mask");
  static constexpr bool quads = internal::Patch_scheme<Mask>::catmull_clark;
  using GT = boost::graph_traits<PolygonMesh>;
  using face_descriptor = typename GT::face_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using Vpm = typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::const_type;
  using Point = typename boost::property_traits<Vpm>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  using FT = typename Kernel::FT;
  using Vector = typename Kernel::Vector_3;
  // the local patches: a face and its 1-ring, refined level by level
  using Patch_mesh = CGAL::Surface_mesh<Point>;
  using Patch_halfedge = typename Patch_mesh::Halfedge_index;
  // sharpness tags: by ordinal for the mesh, in property maps of the local meshes (refined with them)
  using Sharpness = internal::Sharpness_number<FT>;
  using Crease_rules = internal::Crease_rules<Sharpness>;
  using Edge_sharpness_map = typename Patch_mesh::template Property_map<typename Patch_mesh::Edge_index, Sharpness>;
  using Vertex_sharpness_map = typename Patch_mesh::template Property_map<typename Patch_mesh::Vertex_index, Sharpness>;

public:
  /// levels of local refinement at most before a parameter is taken at its extraordinary corner
  int max_depth = 60;
  /// whether a patch with one extraordinary corner is evaluated with Stam's eigenbasis (floating-point
  /// kernels only; exact kernels always refine): `false` refines it, for comparisons
  bool eigenbasis = true;
  /// faces whose refined neighbourhoods (down to the patches that evaluations reached) are kept, so that
  /// the next evaluation on them refines nothing; the oldest face is dropped first. 0 keeps none.
  std::size_t cached_faces = 4096;
  /// whether the first evaluation on a face that is not a direct patch refines the whole mesh once, kept
  /// for all the evaluations after it (about four times the mesh's memory), which then start from the
  /// children of their faces there, and the first one at an extraordinary vertex of the mesh computes the
  /// limit position and normal of every vertex once; `false` copies and refines each such face's
  /// neighbourhood instead
  bool refine_whole_mesh = true;
  /// whether `evaluate()` makes the second derivatives (`duu`, `duv`, `dvv`; the curvatures of
  /// `Limit_sample` need them); `false` returns them zero and spares their weights: half the basis
  /// functions and half the rows of Stam's products, for users who need positions and normals only
  /// (`stencil_tables()` then has empty second-derivative rows)
  bool second_derivatives = true;

  /// the evaluator of `mesh` (kept by reference: it must outlive the evaluator and stay unchanged)
  /// under the scheme of `mask` (its options kept); \throws Bad_input under Loop if `mesh` has a
  /// face that is not a triangle
  explicit Limit_surface(const PolygonMesh& mesh, const Mask& mask = Mask())
    : m_mesh(&mesh), m_mask(mask.template rebind<Patch_mesh, FT>()),
      m_numbering(std::make_shared<const internal::Mesh_numbering<PolygonMesh>>(mesh)),
      m_eigenbases(std::make_shared<Eigenbases>(m_mask)), m_cache(std::make_shared<Cache>())
  {
    if constexpr(!quads) {
      for(const face_descriptor f : faces(mesh))
        if(corners_of(f) != 3)
          internal::refuse(internal::Message()
                           << "Limit_surface: face " << ordinal_of(f) << " is not a triangle (Loop)");
    }
  }

  /*!
   * The same with the sharpness tags of `np` (`edge_sharpness_map`,
   * `vertex_sharpness_map`, `crease_method`), read once (the maps must not
   * change meanwhile either): OpenSubdiv's semantics, as `subdivide()`
   * refines them. A patch with a tag at a corner or on an edge at a corner
   * is refined (with the tags, decaying) until it has none; a parameter at
   * a vertex with an infinitely sharp tag (a crease or corner vertex) takes
   * the limit masks of its rule there (`project_to_limit()`,
   * `limit_normals()`, with the tags). A parameter on an infinitely sharp
   * crease edge never reaches a patch without tags: it is evaluated at the
   * nearest vertex `max_depth` levels down (its position to about 2^-60 of
   * the face's size, its derivatives zero). \throws Bad_input for the tags
   * `subdivide()` refuses (negative, NaN), and for the Chaikin crease method
   * (not supported yet: its decay reads the edges around both ends, which
   * a local patch does not have)
   */
  template <class NamedParameters>
  Limit_surface(const PolygonMesh& mesh, const Mask& mask, const NamedParameters& np) : Limit_surface(mesh, mask)
  {
    const auto tags = internal::sharpness_tags_of<PolygonMesh, FT>(np);
    if constexpr(!std::is_same<std::decay_t<decltype(tags)>, internal::No_sharpness_tags>::value) {
      tags.check(mesh, mask, "Limit_surface");
      if(tags.method() != Crease_method::uniform)
        internal::refuse(internal::Message()
                         << "Limit_surface: the Chaikin crease method is not supported yet (uniform only)");
      auto by_ordinal = std::make_shared<internal::Sharpness_by_ordinal<FT>>();
      bool any = false;
      const auto edge_sharpness = tags.edge_reader();
      const auto vertex_sharpness = tags.vertex_reader();
      for(std::size_t e = 0; e < num_edges(mesh); ++e) {
        by_ordinal->edges.push_back(Sharpness(edge_sharpness(m_numbering->edge(e))));
        any = any || Crease_rules::is_sharp(by_ordinal->edges.back());
      }
      for(std::size_t v = 0; v < num_vertices(mesh); ++v) {
        by_ordinal->vertices.push_back(Sharpness(vertex_sharpness(m_numbering->vertex(v))));
        any = any || Crease_rules::is_sharp(by_ordinal->vertices.back());
      }
      if(any)
        m_tags = std::make_shared<const Tags>(Tags{std::move(by_ordinal), m_numbering, &mesh});
    }
  }

  /// the valences whose Stam eigenbasis has been built so far (by the evaluations near them), with the
  /// condition number of its eigenvector matrix: infinite where it is not used (not diagonalisable in
  /// the reals, or too ill-conditioned), and those patches are evaluated by powers of the local
  /// subdivision matrix instead
  std::map<std::size_t, double> eigenbasis_conditions() const
  {
    const std::lock_guard<std::mutex> lock(m_eigenbases->mutex);
    std::map<std::size_t, double> conditions;
    for(const auto& [n, basis] : m_eigenbases->by_valence)
      conditions[n] = basis->usable() ? basis->condition() : std::numeric_limits<double>::infinity();
    return conditions;
  }

  /// the valences whose Stam eigenbasis has been built so far, with the eigenvalues of the local
  /// subdivision matrix as the eigenbasis has them (the diagonal of Eigen's real block-diagonal
  /// form, in its order; also where the basis is not used; empty if the eigen-solver failed)
  std::map<std::size_t, std::vector<double>> eigenbasis_eigenvalues() const
  {
    const std::lock_guard<std::mutex> lock(m_eigenbases->mutex);
    std::map<std::size_t, std::vector<double>> eigenvalues;
    for(const auto& [n, basis] : m_eigenbases->by_valence) {
      const Eigen::VectorXd& lambda = basis->eigenvalues();
      eigenvalues[n].assign(lambda.data(), lambda.data() + lambda.size());
    }
    return eigenvalues;
  }

  /// the mesh whose limit this is
  const PolygonMesh& mesh() const { return *m_mesh; }

  /// the number of corners of face `f`: a Catmull-Clark face with n != 4 is addressed as n sub-quads
  int corners_of(face_descriptor f) const
  {
    return static_cast<int>(CGAL::halfedges_around_face(halfedge(f, *m_mesh), *m_mesh).size());
  }

  /// the limit surface at (u, v) of quad (Catmull-Clark) or triangle (Loop) `f`; \throws Bad_input
  /// if `f` is a Catmull-Clark face with n != 4 corners, or (u, v) is not in its domain
  Limit_sample evaluate(face_descriptor f, double u, double v) const
  {
    check_location({f, -1, u, v});
    return to_sample(evaluate_kept({f, -1, u, v}));
  }

  /// the limit surface at (u, v) of the sub-quad at `corner` of face `f` (n != 4 corners)
  Limit_sample evaluate(face_descriptor f, int corner, double u, double v) const
  {
    static_assert(quads, "Limit_surface: sub-quads are Catmull-Clark's");
    if(corner < 0)
      internal::refuse(internal::Message() << "Limit_surface: face " << ordinal_of(f) << " has no corner " << corner);
    check_location({f, corner, u, v});
    return to_sample(evaluate_kept({f, corner, u, v}));
  }

  /// a parameter: (face, u, v), or (face, corner, u, v) for a Catmull-Clark sub-quad (corner -1: none)
  struct Location
  {
    face_descriptor face;
    int corner = -1;
    double u = 0, v = 0;
  };

  /*!
   * Limit stencils at `locations`, like OpenSubdiv's `LimitStencilTable`:
   * row i of each table is location i, its sources the vertices of the mesh
   * in the order of `vertices(mesh)`, its weights those of the position
   * (summing to 1) and of each derivative (summing to 0) in the mesh's
   * number type, exact in an exact kernel. So `position.apply(points)` and
   * `du.apply(points)` re-evaluate the locations for moved control points
   * in one sparse pass (a derivative comes out as the point whose
   * coordinates are the vector's). The evaluation is linear in the control
   * points, so the weights are the evaluations of each location's patch
   * with its points set to unit points, three at a time: the same code path
   * as `evaluate()`, no rule written twice. No normal row: the normal is not
   * linear. \throws Bad_input for a location `evaluate()` refuses.
   */
  Limit_location_stencils<FT> stencil_tables(const std::vector<Location>& locations) const
  {
    const internal::Mesh_numbering<PolygonMesh> number(*m_mesh);
    const std::size_t sources = num_vertices(*m_mesh);
    Limit_location_stencils<FT> tables;
    for(Stencil_table<FT>* table : tables.all())
      *table = Stencil_table<FT>(sources);
    for(const Location& at : locations)
      check_location(at);
    std::array<std::vector<std::pair<std::size_t, FT>>, 6> rows;
    for(const Location& at : locations) {
      std::vector<vertex_descriptor> patch_sources;
      const Patch patch = local_patch_of(m_tags, *m_mesh, halfedge(at.face, *m_mesh), &patch_sources);
      for(auto& row : rows)
        row.clear();
      for(std::size_t first = 0; first < patch_sources.size(); first += 3) {
        Patch unit = patch;
        for(std::size_t j = 0; j < patch_sources.size(); ++j) {
          const auto coordinate = [&](std::size_t d) { return j == first + d ? FT(1) : FT(0); };
          unit.mesh.point(typename Patch_mesh::Vertex_index(static_cast<std::uint32_t>(j))) =
            Point(coordinate(0), coordinate(1), coordinate(2));
        }
        // a tree of its own, not kept: its points are not the mesh's
        const std::unique_ptr<Node> root = make_node(unit.mesh, unit.h0);
        const Exact_sample s = evaluate_leaf(descend(*root, at));
        const std::array<Vector, 6> values = {s.position - CGAL::ORIGIN, s.du, s.dv, s.duu, s.duv, s.dvv};
        for(std::size_t d = 0; d < 3 && first + d < patch_sources.size(); ++d)
          for(std::size_t q = 0; q < 6; ++q)
            if(values[q][int(d)] != FT(0))
              rows[q].emplace_back(number(patch_sources[first + d]), values[q][int(d)]);
      }
      const auto all = tables.all();
      for(std::size_t q = 0; q < 6; ++q)
        all[q]->add_stencil(rows[q]); // (a derivative at an extraordinary vertex: no terms, zero)
    }
    return tables;
  }

private:
  using Eigenbasis = internal::Stam_eigenbasis<quads ? 16 : 12>;
  using Patch = internal::Local_patch<Point>;

  /*
   * The sharpness tags, if any: of the mesh by ordinal, of a local mesh in
   * its property maps (copied from the mesh, then refined by `subdivide()`
   * with them). Shared by the evaluator's copies and its nodes.
   */
  struct Tags
  {
    std::shared_ptr<const internal::Sharpness_by_ordinal<FT>> mesh_sharpness;
    std::shared_ptr<const internal::Mesh_numbering<PolygonMesh>> numbering;
    const PolygonMesh* mesh;

    static constexpr const char* edge_name = "e:cgal_subdiv_limit_sharpness";
    static constexpr const char* vertex_name = "v:cgal_subdiv_limit_sharpness";

    // the maps of a local mesh (none if it was made without tags)
    static std::optional<std::pair<Edge_sharpness_map, Vertex_sharpness_map>> maps(const Patch_mesh& mesh)
    {
      const auto e = mesh.template property_map<typename Patch_mesh::Edge_index, Sharpness>(edge_name);
      const auto v = mesh.template property_map<typename Patch_mesh::Vertex_index, Sharpness>(vertex_name);
      if(!e.second || !v.second)
        return std::nullopt;
      return std::make_pair(e.first, v.first);
    }
    static std::pair<Edge_sharpness_map, Vertex_sharpness_map> add_maps(Patch_mesh& mesh)
    {
      return {
        mesh.template add_property_map<typename Patch_mesh::Edge_index, Sharpness>(edge_name, Sharpness(0)).first,
        mesh.template add_property_map<typename Patch_mesh::Vertex_index, Sharpness>(vertex_name, Sharpness(0)).first};
    }

    /*
     * The sharpness of the edges and vertices of one mesh, its maps looked
     * up once: the mesh's by ordinal, a local mesh's in its maps, 0 for a
     * mesh without tags.
     */
    template <class Source>
    class Reader
    {
    public:
      Reader(const Tags& tags, const Source& m) : m_tags(&tags)
      {
        if constexpr(std::is_same<Source, PolygonMesh>::value)
          m_of_mesh = &m == tags.mesh;
        if constexpr(std::is_same<Source, Patch_mesh>::value)
          if(!m_of_mesh)
            m_maps = maps(m);
      }
      // of an edge or a vertex of the mesh
      template <class Element>
      Sharpness operator()(Element x) const
      {
        constexpr bool is_edge = std::is_same<Element, typename boost::graph_traits<Source>::edge_descriptor>::value;
        if constexpr(std::is_same<Source, PolygonMesh>::value)
          if(m_of_mesh)
            return (is_edge ? m_tags->mesh_sharpness->edges
                            : m_tags->mesh_sharpness->vertices)[(*m_tags->numbering)(x)];
        if constexpr(std::is_same<Source, Patch_mesh>::value) {
          if(m_maps) {
            if constexpr(is_edge)
              return m_maps->first[x];
            else
              return m_maps->second[x];
          }
        }
        return Sharpness(0);
      }

    private:
      const Tags* m_tags;
      bool m_of_mesh = false;
      std::optional<std::pair<Edge_sharpness_map, Vertex_sharpness_map>> m_maps;
    };

    /*
     * What the tags make of the target of `h`: `smooth` (no tag at it nor on
     * an edge at it); `sharp` if its rule stays and its limit masks are exact
     * (an infinitely sharp vertex, or two or more infinitely sharp edges,
     * border edges counted: a crease or a corner); `decaying` otherwise,
     * where refining towards it is the way to its limit: a semi-sharp tag
     * (which decays), or a dart (one sharp edge: OpenSubdiv's smooth masks
     * there are not its limit, and it stays a dart), approached until the
     * parameter is reached or `max_depth`.
     */
    enum class Corner { smooth, decaying, sharp };
    template <class Source>
    Corner at_corner(const Source& m, typename boost::graph_traits<Source>::halfedge_descriptor h) const
    {
      return at_corner(Reader<Source>(*this, m), m, h);
    }
    template <class Source>
    static Corner at_corner(const Reader<Source>& sharpness, const Source& m,
                            typename boost::graph_traits<Source>::halfedge_descriptor h)
    {
      const Sharpness at = sharpness(target(h, m));
      if(Crease_rules::is_semi_sharp(at))
        return Corner::decaying;
      int sharp_edges = 0, tagged = 0;
      for(const auto g : CGAL::halfedges_around_target(h, m)) {
        if(CGAL::is_border(edge(g, m), m)) {
          ++sharp_edges;
          continue;
        }
        const Sharpness s = sharpness(edge(g, m));
        if(Crease_rules::is_semi_sharp(s))
          return Corner::decaying;
        if(Crease_rules::is_infinite(s)) {
          ++sharp_edges;
          ++tagged;
        }
      }
      if(Crease_rules::is_infinite(at))
        return Corner::sharp;
      if(tagged == 0)
        return Corner::smooth;
      return sharp_edges >= 2 ? Corner::sharp : Corner::decaying;
    }

    // whether a corner of the face at h0 has a tag at it or on an edge at it
    template <class Source>
    bool at_corners(const Source& m, typename boost::graph_traits<Source>::halfedge_descriptor h0) const
    {
      const Reader<Source> sharpness(*this, m);
      for(const auto h : CGAL::halfedges_around_face(h0, m))
        if(at_corner(sharpness, m, h) != Corner::smooth)
          return true;
      return false;
    }

    // the tags of `source` copied into `patch`, a local patch of it whose vertex j is `sources[j]`
    template <class Source>
    void copy_into(const Source& source,
                   const std::vector<typename boost::graph_traits<Source>::vertex_descriptor>& sources,
                   Patch_mesh& patch) const
    {
      const auto [edges, vertices] = add_maps(patch);
      const Reader<Source> sharpness(*this, source);
      for(const auto v : patch.vertices())
        vertices[v] = sharpness(sources[v.idx()]);
      for(const auto e : patch.edges()) {
        const auto h = patch.halfedge(e);
        const auto [g, found] = CGAL::halfedge(sources[patch.source(h).idx()], sources[patch.target(h).idx()], source);
        edges[e] = found ? sharpness(edge(g, source)) : Sharpness(0);
      }
    }
  };

  // the local patch of the face at h0 of `mesh` (`internal::local_patch`), with the tags if any
  template <class Source>
  static Patch local_patch_of(const std::shared_ptr<const Tags>& tags, const Source& mesh,
                              typename boost::graph_traits<Source>::halfedge_descriptor h0,
                              std::vector<typename boost::graph_traits<Source>::vertex_descriptor>* sources = nullptr)
  {
    if(!tags)
      return internal::local_patch<Point>(mesh, h0, sources);
    std::vector<typename boost::graph_traits<Source>::vertex_descriptor> own;
    auto& copied = sources != nullptr ? *sources : own;
    Patch patch = internal::local_patch<Point>(mesh, h0, &copied);
    tags->copy_into(mesh, copied, patch.mesh);
    return patch;
  }

  struct Node; // a face, or a child of one, on the way down to a parameter (below)
  // the position and derivatives, in the mesh's number type
  struct Exact_sample
  {
    Point position;
    Vector du, dv, duu, duv, dvv;
    bool at_extraordinary_vertex = false;
    Vector normal; // at an extraordinary vertex only
  };
  template <class Element>
  std::size_t ordinal_of(Element e) const
  {
    return (*m_numbering)(e);
  }

  // refuses a location outside its face's domain, or addressed with a wrong corner
  void check_location(const Location& at) const
  {
    const auto [f, corner, u, v] = at;
    if(!(u >= 0 && u <= 1 && v >= 0 && v <= 1))
      internal::refuse(internal::Message() << "Limit_surface: the parameter (" << std::to_string(u) << ", "
                                           << std::to_string(v) << ") is not in the face's domain [0, 1]^2");
    if constexpr(!quads) {
      if(corner >= 0)
        internal::refuse(internal::Message()
                         << "Limit_surface: a corner (" << corner << ") is for Catmull-Clark's sub-quads");
      if(!(u + v <= 1))
        internal::refuse(internal::Message() << "Limit_surface: the parameter (" << std::to_string(u) << ", "
                                             << std::to_string(v) << ") is not in the triangle's domain (u + v <= 1)");
      return;
    }
    const int corners = corners_of(f);
    if(corner < 0 && corners != 4)
      internal::refuse(internal::Message()
                       << "Limit_surface: face " << ordinal_of(f) << " has " << corners << " corners: address it as "
                       << corners << " sub-quads (face, corner, u, v)");
    if(corner >= 0 && corners == 4)
      internal::refuse(internal::Message() << "Limit_surface: face " << ordinal_of(f)
                                           << " is a quad: address it as (face, u, v), without a corner");
    if(corner >= corners)
      internal::refuse(internal::Message() << "Limit_surface: face " << ordinal_of(f) << " has no corner " << corner
                                           << " (it has " << corners << ")");
  }

  // the sample of a regular patch's `points` with weights `w` (the second derivatives if they are wanted)
  template <std::size_t N>
  Exact_sample combine(const std::array<Point, N>& points, const Patch_weights<FT, N>& w) const
  {
    const auto sum = [&](const std::array<FT, N>& weights) {
      Vector total = CGAL::NULL_VECTOR;
      for(std::size_t k = 0; k < N; ++k)
        total = total + (points[k] - CGAL::ORIGIN) * weights[k];
      return total;
    };
    Exact_sample s;
    s.position = CGAL::ORIGIN + sum(w.position);
    s.du = sum(w.du);
    s.dv = sum(w.dv);
    s.duu = s.duv = s.dvv = CGAL::NULL_VECTOR;
    if(!second_derivatives)
      return s;
    s.duu = sum(w.duu);
    s.duv = sum(w.duv);
    s.dvv = sum(w.dvv);
    return s;
  }

  auto basis_weights(const FT& u, const FT& v) const
  {
    if constexpr(quads)
      return bspline_patch_weights(u, v, second_derivatives);
    else
      return box_spline_patch_weights(u, v, second_derivatives);
  }

  // the corner of the patch's face at (u, v), if (u, v) is a corner; -1 otherwise
  static int corner_at(const FT& u, const FT& v)
  {
    const bool u0 = u == FT(0), u1 = u == FT(1), v0 = v == FT(0), v1 = v == FT(1);
    if(!quads && u0 && v1)
      return 2;
    return u0 && v0 ? 0 : u1 && v0 ? 1 : u1 && v1 ? 2 : u0 && v1 ? 3 : -1;
  }

  // whether the mask keeps the border corners of one face (Border_corners::sharp, Catmull-Clark)
  bool sharp_corners() const
  {
    if constexpr(quads)
      return m_mask.border_corners() == Border_corners::sharp;
    else
      return false;
  }

  /*
   * Whether corner i of the patch's face is an inner vertex of the regular
   * valence, or a border vertex with two quads (three triangles), or under
   * Catmull-Clark a border corner of one face that the mask keeps: the children around it
   * become regular patches, which give the derivatives there too (the limit
   * masks do not).
   */
  template <class Source>
  bool is_ordinary_corner(const Source& mesh, typename boost::graph_traits<Source>::halfedge_descriptor h0, int i) const
  {
    for(int k = 0; k < i; ++k)
      h0 = next(h0, mesh);
    if(m_tags) {
      const auto tags = m_tags->at_corner(mesh, h0);
      if(tags != Tags::Corner::smooth) // a decaying tag is refined away, an infinitely sharp one stays
        return tags == Tags::Corner::decaying;
    }
    const std::size_t valence = CGAL::halfedges_around_target(h0, mesh).size();
    if(!CGAL::is_border(target(h0, mesh), mesh))
      return valence == (quads ? 4u : 6u);
    return quads ? valence == 3 || (valence == 2 && sharp_corners()) : valence == 4;
  }
  bool is_ordinary_corner(Node& node, int i) const
  {
    if(node.mesh_face)
      return is_ordinary_corner(*m_mesh, halfedge(m_numbering->face(*node.mesh_face), *m_mesh), i);
    return is_ordinary_corner(node.local_patch().mesh, node.local_patch().h0, i);
  }

  // the sample at an extraordinary vertex: its limit position and normal, no derivatives
  static Exact_sample vertex_sample(const Point& position, const Vector& normal)
  {
    Exact_sample s;
    s.position = position;
    s.du = s.dv = s.duu = s.duv = s.dvv = CGAL::NULL_VECTOR;
    s.at_extraordinary_vertex = true;
    s.normal = normal;
    return s;
  }

  // the limit positions and normals of every vertex of `mesh` (the masks of the analysis), by vertex index
  std::vector<Exact_sample> limits_of_vertices(Patch_mesh mesh) const
  {
    const auto normals = mesh
                           .template add_property_map<typename Patch_mesh::Vertex_index, Vector>(
                             "v:cgal_subdiv_limit_normal", CGAL::NULL_VECTOR)
                           .first;
    {
      // the evaluator keeps the masks of the analysis per configuration
      const std::lock_guard<std::mutex> lock(m_eigenbases->mutex);
      if(const auto tags = Tags::maps(mesh)) { // the rules of the tags at this level
        const auto np = parameters::edge_sharpness_map(tags->first).vertex_sharpness_map(tags->second);
        m_eigenbases->limit.limit_normals(mesh, normals, np);
        m_eigenbases->limit.project_to_limit(mesh, np);
      } else {
        m_eigenbases->limit.limit_normals(mesh, normals);
        m_eigenbases->limit.project_to_limit(mesh);
      }
    }
    std::vector<Exact_sample> limits;
    limits.reserve(mesh.number_of_vertices());
    for(const auto v : mesh.vertices())
      limits.push_back(vertex_sample(mesh.point(v), normals[v]));
    return limits;
  }

  // the limit position and normal of corner i of the patch's face
  Exact_sample evaluate_at_corner(const Patch& patch, int i) const
  {
    Patch_halfedge h = patch.h0;
    for(int k = 0; k < i; ++k)
      h = patch.mesh.next(h);
    return limits_of_vertices(patch.mesh)[patch.mesh.target(h).idx()];
  }

  /*
   * The limit position and normal of corner i of the node's face: for a face
   * of the mesh, from the limits of all the mesh's vertices, computed the
   * first time (the caller holds the cache's lock), as the mesh refined once
   * is; otherwise from its local patch.
   */
  Exact_sample evaluate_at_corner(Node& node, int i) const
  {
    if(!node.mesh_face)
      return evaluate_at_corner(node.local_patch(), i);
    std::vector<Exact_sample>& limits = m_cache->vertex_limits;
    if(limits.empty()) {
      Mesh_copy copy = copy_of_mesh();
      const std::vector<Exact_sample> by_copy = limits_of_vertices(std::move(copy.mesh));
      limits.resize(by_copy.size());
      for(const auto& [v, c] : copy.vertices)
        limits[ordinal_of(v)] = by_copy[c.idx()];
    }
    halfedge_descriptor h = halfedge(m_numbering->face(*node.mesh_face), *m_mesh);
    for(int k = 0; k < i; ++k)
      h = next(h, *m_mesh);
    return limits[ordinal_of(target(h, *m_mesh))];
  }

  // where a child lies in its parent's face: the sub-quad (-1: none), the
  // corner of its box and its corner 0 (the parameters are dyadic, exact in double)
  struct Child_place
  {
    int sub_quad;
    std::array<double, 2> box_min, anchor;
  };

  // refines the patch one level, each new face with its origin
  using Origin_map = typename Patch_mesh::template Property_map<typename Patch_mesh::Face_index, Face_origin>;
  Origin_map refine(Patch_mesh& mesh) const
  {
    auto origins =
      mesh.template add_property_map<typename Patch_mesh::Face_index, Face_origin>("f:cgal_subdiv_limit_origin").first;
    Carried_data<Patch_mesh, FT> data;
    data.face_origin_map(origins);
    if(const auto tags = Tags::maps(mesh)) // the children's tags decay into the same maps
      subdivide(mesh, m_mask,
                parameters::carried_data(data).edge_sharpness_map(tags->first).vertex_sharpness_map(tags->second));
    else
      subdivide(mesh, m_mask, parameters::carried_data(data));
    return origins;
  }

  // the halfedge into corner 0 of the child at `place` of face `parent`, among the faces `candidates`
  // of the refined mesh
  template <class Faces>
  static Patch_halfedge find_child(const Patch_mesh& mesh, const Origin_map& origins, const Faces& candidates,
                                   std::size_t parent, const Child_place& place)
  {
    for(const auto g : candidates) {
      const Face_origin& origin = origins[g];
      const CGAL::Bbox_2 box = origin.box();
      if(origin.face != parent || origin.sub_quad != place.sub_quad || box.xmin() != place.box_min[0] ||
         box.ymin() != place.box_min[1])
        continue;
      Patch_halfedge h = mesh.halfedge(g);
      for(int i = 0; i < origin.corners; ++i, h = mesh.next(h))
        if(origin.uv[i][0] == place.anchor[0] && origin.uv[i][1] == place.anchor[1])
          return h;
    }
    internal::refuse(internal::Message() << "Limit_surface: no child holds the parameter (an internal error)");
    return Patch_halfedge();
  }

  /*
   * The child of the face that holds (u, v), as the split makes it: the
   * quarter of a quad, or of a triangle a corner triangle or the middle one
   * (turned by a half turn: its corner 0 at (1/2, 1/2), u' = 1 - 2u and
   * v' = 1 - 2v), with (u, v) in the child's parameters and the factor that
   * d/du' is to d/du (2 or -2)
   */
  struct Child_parameters
  {
    Child_place place;
    FT u, v;
    FT scale;
  };
  static Child_parameters child_parameters(const FT& u, const FT& v)
  {
    const FT half = FT(1) / FT(2);
    if(!quads && u < half && v < half && u + v > half) // the middle triangle
      return {{-1, {0, 0}, {0.5, 0.5}}, FT(1) - FT(2) * u, FT(1) - FT(2) * v, FT(-2)};
    // a quarter of a quad; a corner triangle, u >= 1/2 the one at corner 1
    const FT a = u < half ? FT(0) : half, b = v < half || (!quads && a == half) ? FT(0) : half;
    const std::array<double, 2> corner{CGAL::to_double(a), CGAL::to_double(b)};
    return {{-1, corner, corner}, FT(2) * (u - a), FT(2) * (v - b), FT(2)};
  }

  // the regular children of a patch whose corner 0 is extraordinary, as `child_parameters` places them
  static const std::array<Child_place, 3>& regular_children()
  {
    static const std::array<Child_place, 3> places =
      quads
        ? std::array<Child_place, 3>{{{-1, {0.5, 0}, {0.5, 0}}, {-1, {0.5, 0.5}, {0.5, 0.5}}, {-1, {0, 0.5}, {0, 0.5}}}}
        : std::array<Child_place, 3>{{{-1, {0.5, 0}, {0.5, 0}}, {-1, {0, 0.5}, {0, 0.5}}, {-1, {0, 0}, {0.5, 0.5}}}};
    return places;
  }
  static std::size_t regular_child_index(const Child_place& place)
  {
    const auto& places = regular_children();
    for(std::size_t k = 0; k < places.size(); ++k)
      if(places[k].box_min == place.box_min && places[k].anchor == place.anchor)
        return k;
    internal::refuse(internal::Message() << "Limit_surface: not a regular child (an internal error)");
    return 0;
  }
  // whether (u, v) is in the child at corner 0 (the one that keeps the extraordinary vertex)
  static bool in_corner_child(const FT& u, const FT& v)
  {
    const FT half = FT(1) / FT(2);
    return u < half && v < half && (quads || !(u + v > half));
  }

  /*
   * The eigenbasis of a patch with one extraordinary corner of valence n:
   * its local subdivision matrix and its children's, read off the
   * refinement of the patch by the mask itself, three control points at a
   * time set to the unit points (so the matrices are the mask's weights).
   */
  Eigenbasis build_eigenbasis(const Patch& patch) const
  {
    using Points = internal::Patch_points<Patch_mesh, quads>;
    const auto ring = Points(patch.mesh, patch.h0).ring_vertices();
    const Eigen::Index K = static_cast<Eigen::Index>(ring.size());
    constexpr Eigen::Index N = quads ? 16 : 12;
    Eigen::MatrixXd A(K, K);
    std::array<Eigen::MatrixXd, 3> children;
    children.fill(Eigen::MatrixXd(N, K));
    for(Eigen::Index first = 0; first < K; first += 3) {
      Patch_mesh mesh = patch.mesh;
      for(Eigen::Index j = 0; j < K; ++j) {
        const auto unit = [&](Eigen::Index d) { return j == first + d ? FT(1) : FT(0); };
        mesh.point(ring[j]) = Point(unit(0), unit(1), unit(2));
      }
      const Origin_map origins = refine(mesh);
      const auto set_columns = [&](Eigen::MatrixXd& matrix, Eigen::Index row, const Point& p) {
        for(Eigen::Index d = 0; d < 3 && first + d < K; ++d)
          matrix(row, first + d) = CGAL::to_double(p[int(d)]);
      };
      const auto child_ring =
        Points(mesh, find_child(mesh, origins, mesh.faces(), 0, {-1, {0, 0}, {0, 0}})).ring_vertices();
      CGAL_assertion(child_ring.size() == ring.size());
      for(Eigen::Index r = 0; r < K; ++r)
        set_columns(A, r, mesh.point(child_ring[r]));
      for(std::size_t k = 0; k < 3; ++k) {
        const auto points =
          Points(mesh, find_child(mesh, origins, mesh.faces(), 0, regular_children()[k])).control_points();
        for(Eigen::Index r = 0; r < N; ++r)
          set_columns(children[k], r, points[r]);
      }
    }
    return Eigenbasis(A, children);
  }

  // the eigenbasis of valence n, built from the patch at h0 of `mesh` the first time (if not usable,
  // it evaluates by powers of the local matrix)
  template <class Source>
  const Eigenbasis* eigenbasis_of(std::size_t n, const Source& mesh,
                                  typename boost::graph_traits<Source>::halfedge_descriptor h0) const
  {
    const std::lock_guard<std::mutex> lock(m_eigenbases->mutex);
    std::unique_ptr<const Eigenbasis>& slot = m_eigenbases->by_valence[n];
    if(!slot)
      slot = std::make_unique<const Eigenbasis>(build_eigenbasis(internal::local_patch<Point>(mesh, h0)));
    return slot.get();
  }

  /*
   * A patch that is evaluated without refining it: a regular patch, from
   * its control points, or (in a floating-point kernel) a patch with one
   * extraordinary inner corner, from the coordinates of its control points
   * in the eigenbasis of that corner's valence (Stam). Both are computed
   * once per patch.
   */
  struct Direct_patch
  {
    std::optional<std::array<Point, quads ? 16 : 12>> points; // regular: the control points
    const Eigenbasis* basis = nullptr;                        // Stam: the eigenbasis
    int corner = 0;                                           // the extraordinary corner
    Point origin = CGAL::ORIGIN;                              // its point
    Eigen::MatrixXd coefficients;                             // the ring's points from it, in the eigenbasis
  };

  // the direct form of the patch at h0 of `mesh`, if it has one
  template <class Source>
  std::optional<Direct_patch> direct_patch(const Source& mesh,
                                           typename boost::graph_traits<Source>::halfedge_descriptor h0) const
  {
    if(m_tags && m_tags->at_corners(mesh, h0))
      return std::nullopt; // refined until the tags at its corners have decayed (or for ever: a crease)
    const internal::Patch_points<Source, quads> patch(mesh, h0);
    if(patch.is_regular(sharp_corners())) {
      Direct_patch direct;
      direct.points = patch.control_points();
      return direct;
    }
    if constexpr(std::is_floating_point_v<FT>) {
      if(!eigenbasis)
        return std::nullopt;
      const auto corner = patch.extraordinary_corner();
      if(corner.valence == 0)
        return std::nullopt;
      const Eigenbasis* basis = eigenbasis_of(corner.valence, mesh, corner.into);
      if(!basis)
        return std::nullopt;
      // the control points from the extraordinary vertex's (ring[0]): the
      // derivative weights sum to 0 only up to rounding, times 2^level
      const auto vpm = get(CGAL::vertex_point, mesh);
      const Point origin = get(vpm, corner.ring[0]);
      Eigen::MatrixXd points(static_cast<Eigen::Index>(corner.ring.size()), 3);
      for(Eigen::Index r = 0; r < points.rows(); ++r) {
        const Vector p = get(vpm, corner.ring[std::size_t(r)]) - origin;
        points.row(r) << p.x(), p.y(), p.z();
      }
      Direct_patch direct;
      direct.basis = basis;
      direct.corner = corner.index;
      direct.origin = origin;
      direct.coefficients = basis->coefficients(points);
      return direct;
    }
    return std::nullopt;
  }

  /*
   * The parameters (s, t) = L (u, v) + o of the face seen from its corner
   * i (the corner at (0, 0), the next one at (1, 0)): the derivatives along
   * u and v are L^T those along s and t, and the second derivatives
   * L^T H L.
   */
  struct Turn
  {
    std::array<std::array<int, 2>, 2> L;
    std::array<int, 2> o;

    std::pair<FT, FT> operator()(const FT& u, const FT& v) const
    {
      return {FT(L[0][0]) * u + FT(L[0][1]) * v + FT(o[0]), FT(L[1][0]) * u + FT(L[1][1]) * v + FT(o[1])};
    }
    // the derivatives along (s, t) as derivatives along (u, v)
    void turn_back(Exact_sample& s) const
    {
      const Vector ds = s.du, dt = s.dv, dss = s.duu, dst = s.duv, dtt = s.dvv;
      const auto second = [&](int a, int b) {
        return dss * FT(L[0][a] * L[0][b]) + dst * FT(L[0][a] * L[1][b] + L[1][a] * L[0][b]) +
               dtt * FT(L[1][a] * L[1][b]);
      };
      s.du = ds * FT(L[0][0]) + dt * FT(L[1][0]);
      s.dv = ds * FT(L[0][1]) + dt * FT(L[1][1]);
      s.duu = second(0, 0);
      s.duv = second(0, 1);
      s.dvv = second(1, 1);
    }
  };
  static Turn turn_to_corner(int i)
  {
    if constexpr(quads) {
      static const Turn turns[4] = {{{{{1, 0}, {0, 1}}}, {0, 0}},
                                    {{{{0, 1}, {-1, 0}}}, {0, 1}},
                                    {{{{-1, 0}, {0, -1}}}, {1, 1}},
                                    {{{{0, -1}, {1, 0}}}, {1, 0}}};
      return turns[i];
    } else {
      static const Turn turns[3] = {
        {{{{1, 0}, {0, 1}}}, {0, 0}}, {{{{0, 1}, {-1, -1}}}, {0, 1}}, {{{{-1, -1}, {1, 0}}}, {1, 0}}};
      return turns[i];
    }
  }

  // the levels from the extraordinary corner (s, t) of a Stam patch lies at: -1 at the corner itself
  static int levels_to_regular_child(FT s, FT t)
  {
    if(s == FT(0) && t == FT(0))
      return -1;
    int level = 0;
    for(; in_corner_child(s, t); ++level, s *= FT(2), t *= FT(2)) {
    }
    return level;
  }

  // whether the patch gives (u, v) `depth` levels below the mesh directly (not a Stam patch's
  // corner, nor a parameter closer to it than 2^-max_depth)
  bool evaluates_directly(const Direct_patch& patch, const FT& u, const FT& v, int depth) const
  {
    if(!patch.basis)
      return true;
    const auto [s, t] = turn_to_corner(patch.corner)(u, v);
    const int level = levels_to_regular_child(s, t);
    return level >= 0 && depth + level < max_depth;
  }

  /*
   * The limit at (u, v) of a direct patch: a regular one from its basis; a
   * Stam patch from its extraordinary corner, where (s, t) lies in a
   * regular child of the patch `level` levels down towards the corner, and
   * that child's control points are a combination of the eigen-coefficients
   * (`Stam_eigenbasis`).
   */
  Exact_sample evaluate_direct(const Direct_patch& patch, const FT& u, const FT& v) const
  {
    if(patch.points)
      return combine(*patch.points, basis_weights(u, v));
    if constexpr(std::is_floating_point_v<FT>) { // (exact kernels have no Stam patches)
      const Turn turn = turn_to_corner(patch.corner);
      const auto [s, t] = turn(u, v);
      const int level = levels_to_regular_child(s, t);
      const Child_parameters c = child_parameters(std::ldexp(s, level), std::ldexp(t, level));
      const auto values = patch.basis->evaluate(patch.coefficients, regular_child_index(c.place), level,
                                                basis_weights(c.u, c.v), second_derivatives);
      const auto vector = [](const Eigen::RowVector3d& w, const FT& factor) {
        return Vector(w(0), w(1), w(2)) * factor;
      };
      Exact_sample sample;
      sample.position = patch.origin + vector(values[0], FT(1));
      sample.du = vector(values[1], c.scale);
      sample.dv = vector(values[2], c.scale);
      sample.duu = vector(values[3], c.scale * c.scale);
      sample.duv = vector(values[4], c.scale * c.scale);
      sample.dvv = vector(values[5], c.scale * c.scale);
      turn.turn_back(sample);
      return sample;
    }
    return Exact_sample();
  }

  /*
   * A face, or a child of one, on the way down to the parameters evaluated
   * on it: a direct patch, or a local patch that is refined once (the
   * refined mesh and the children made of it kept) and whose children are
   * evaluated instead. So a face's neighbourhood is refined once for all
   * the parameters on it.
   */
  struct Refined
  {
    Patch_mesh mesh;
    Origin_map origins;
  };
  struct Node
  {
    std::optional<Direct_patch> direct;
    // the local patch, made the first time it is needed (to refine, or for the limit masks at a
    // corner; a direct patch rarely needs it): a copy out of the mesh it lies in, which outlives it
    std::function<Patch()> make_patch;
    std::optional<Patch> patch;
    // a face of the mesh (its ordinal) whose children are those of the mesh refined once
    // (`First_level`); or, if none, the local patch refined once
    std::optional<std::size_t> mesh_face;
    std::unique_ptr<Refined> refined;
    std::vector<std::unique_ptr<Node>> children; // by `child_slot()`

    Patch& local_patch()
    {
      if(!patch)
        patch = make_patch();
      return *patch;
    }
    std::array<std::optional<Exact_sample>, 4> at_corner; // the limit masks' values at its corners
  };

  // the node of the patch at h0 of `mesh`
  template <class Source>
  std::unique_ptr<Node> make_node(const Source& mesh,
                                  typename boost::graph_traits<Source>::halfedge_descriptor h0) const
  {
    return make_node(mesh, h0, direct_patch(mesh, h0));
  }
  // the same, its direct form (if any) known
  template <class Source>
  std::unique_ptr<Node> make_node(const Source& mesh, typename boost::graph_traits<Source>::halfedge_descriptor h0,
                                  std::optional<Direct_patch> direct) const
  {
    auto node = std::make_unique<Node>();
    node->direct = std::move(direct);
    node->make_patch = [&mesh, h0, tags = m_tags] { return local_patch_of(tags, mesh, h0); };
    return node;
  }

  // a child's number among its siblings: a quarter of a quad 0 to 3 (by its box), a corner triangle
  // 0 to 2 and the middle one 3, the sub-quad at corner c 4 + c
  static std::size_t child_slot(const Child_place& place)
  {
    if(place.sub_quad >= 0)
      return 4 + std::size_t(place.sub_quad);
    if(place.anchor != place.box_min)
      return 3;
    return (place.box_min[0] > 0 ? 1 : 0) + (place.box_min[1] > 0 ? 2 : 0);
  }

  /*
   * The child of the node's face at `place`: for a face of the mesh, its
   * child in the mesh refined once (made the first time, the caller holding
   * the cache's lock); for any other node, its child in its local patch,
   * refined the first time.
   */
  Node& child_of(Node& node, const Child_place& place) const
  {
    const std::size_t slot = child_slot(place);
    if(node.children.size() <= slot)
      node.children.resize(slot + 1);
    std::unique_ptr<Node>& child = node.children[slot];
    if(child)
      return *child;
    if(node.mesh_face) {
      const First_level& level = first_level();
      const auto children = level.children_of(*node.mesh_face);
      child =
        make_node(level.mesh, find_child(level.mesh, level.origins, children, level.copy[*node.mesh_face], place));
      return *child;
    }
    if(!node.refined) {
      node.refined = std::make_unique<Refined>();
      node.refined->mesh = node.local_patch().mesh;
      node.refined->origins = refine(node.refined->mesh);
    }
    const Refined& refined = *node.refined;
    child = make_node(refined.mesh, find_child(refined.mesh, refined.origins, refined.mesh.faces(), 0, place));
    return *child;
  }

  /*
   * The mesh refined once, with each face's children by its ordinal: a
   * face of the mesh that is not a direct patch finds its children here,
   * so that no evaluation copies and refines a neighbourhood of the mesh.
   * (After one level every child is a regular patch or has one
   * extraordinary corner, but at a corner of several extraordinary
   * vertices, an n-gon's sub-quad at an extraordinary corner, Loop's
   * valence 3 and some border configurations; those refine their local
   * patches from here.)
   */
  struct First_level
  {
    Patch_mesh mesh;
    Origin_map origins;
    std::vector<std::size_t> copy;                         // face k's index in the copy refined
    std::vector<std::size_t> first;                        // face k's children: [first[k], first[k + 1])
    std::vector<typename Patch_mesh::Face_index> children; // of the faces, by the ordinal of their parent

    CGAL::Iterator_range<typename std::vector<typename Patch_mesh::Face_index>::const_iterator> children_of(
      std::size_t face) const
    {
      return {children.begin() + std::ptrdiff_t(first[face]), children.begin() + std::ptrdiff_t(first[face + 1])};
    }
  };

  // the mesh refined once, made the first time (the caller holds the cache's lock)
  const First_level& first_level() const
  {
    std::unique_ptr<First_level>& level = m_cache->first_level;
    if(!level)
      level = refine_mesh_once();
    return *level;
  }

  // the mesh copied into a Patch_mesh, with the copy of each element
  struct Mesh_copy
  {
    Patch_mesh mesh;
    std::vector<std::pair<vertex_descriptor, typename Patch_mesh::Vertex_index>> vertices;
    std::vector<std::pair<halfedge_descriptor, Patch_halfedge>> halfedges;
    std::vector<std::pair<face_descriptor, typename Patch_mesh::Face_index>> faces;
  };
  Mesh_copy copy_of_mesh() const
  {
    Mesh_copy copy;
    CGAL::copy_face_graph(*m_mesh, copy.mesh,
                          CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(copy.vertices))
                            .halfedge_to_halfedge_output_iterator(std::back_inserter(copy.halfedges))
                            .face_to_face_output_iterator(std::back_inserter(copy.faces)));
    if(m_tags) {
      const auto [edges, vertices] = Tags::add_maps(copy.mesh);
      const typename Tags::template Reader<PolygonMesh> sharpness(*m_tags, *m_mesh);
      for(const auto& [v, w] : copy.vertices)
        vertices[w] = sharpness(v);
      for(const auto& [h, g] : copy.halfedges)
        edges[copy.mesh.edge(g)] = sharpness(edge(h, *m_mesh));
    }
    return copy;
  }

  std::unique_ptr<First_level> refine_mesh_once() const
  {
    auto level = std::make_unique<First_level>();
    Mesh_copy mesh_copy = copy_of_mesh();
    level->mesh = std::move(mesh_copy.mesh);
    const auto& halfedge_copies = mesh_copy.halfedges;
    const auto& face_copies = mesh_copy.faces;
    std::vector<Patch_halfedge> copy_of(halfedge_copies.size());
    for(const auto& [h, copy] : halfedge_copies)
      copy_of[ordinal_of(h)] = copy;
    // the copy's faces by the ordinal of theirs in the mesh, each with its corner 0 where the mesh has it
    std::vector<std::size_t> parent(num_faces(level->mesh));
    level->copy.resize(parent.size());
    for(const auto& [f, copy] : face_copies) {
      parent[copy.idx()] = ordinal_of(f);
      level->copy[ordinal_of(f)] = copy.idx();
      level->mesh.set_halfedge(copy, copy_of[ordinal_of(halfedge(f, *m_mesh))]);
    }
    level->origins = refine(level->mesh);
    const std::size_t faces_of_mesh = parent.size();
    level->first.assign(faces_of_mesh + 1, 0);
    for(const auto g : level->mesh.faces())
      ++level->first[parent[level->origins[g].face] + 1];
    for(std::size_t k = 0; k < faces_of_mesh; ++k)
      level->first[k + 1] += level->first[k];
    level->children.resize(level->first.back());
    std::vector<std::size_t> next(level->first.begin(), level->first.end() - 1);
    for(const auto g : level->mesh.faces())
      level->children[next[parent[level->origins[g].face]]++] = g;
    return level;
  }

  // where the walk down to a parameter ends: a direct patch or a corner of a node, with the
  // parameter there and the factor its derivatives are to the face's
  struct Leaf
  {
    const Node* node;
    int corner; // -1: the direct patch
    FT u, v;
    FT scale;
  };

  /*
   * Walks down from `node` (`depth` levels below the mesh) to the patch
   * that gives (u, v) directly, making the children on the way: every child
   * away from an extraordinary vertex is regular after one level, and a
   * parameter at distance d from the extraordinary corner is reached after
   * about log2(1/d) levels; at a corner that is not ordinary (or below
   * `max_depth`), the limit masks of the analysis give the corner's value.
   */
  Leaf descend(Node& node, FT u, FT v, int depth) const
  {
    FT scale(1);
    for(Node* at = &node;; ++depth) {
      if(at->direct && evaluates_directly(*at->direct, u, v, depth))
        return {at, -1, u, v, scale};
      const int corner = corner_at(u, v);
      if((corner >= 0 && !is_ordinary_corner(*at, corner)) || depth >= max_depth) {
        const int i = corner >= 0 ? corner : nearest_corner(u, v);
        if(!at->at_corner[std::size_t(i)])
          at->at_corner[std::size_t(i)] = evaluate_at_corner(*at, i);
        return {at, i, u, v, scale};
      }
      const Child_parameters c = child_parameters(u, v);
      at = &child_of(*at, c.place);
      u = c.u;
      v = c.v;
      scale *= c.scale; // d/du = scale d/du' in the child's parameters
    }
  }

  // the limit at the leaf, in the parameters of the face the walk started from
  Exact_sample evaluate_leaf(const Leaf& leaf) const
  {
    if(leaf.corner >= 0)
      return *leaf.node->at_corner[std::size_t(leaf.corner)];
    Exact_sample s = evaluate_direct(*leaf.node->direct, leaf.u, leaf.v);
    s.du = s.du * leaf.scale;
    s.dv = s.dv * leaf.scale;
    s.duu = s.duu * (leaf.scale * leaf.scale);
    s.duv = s.duv * (leaf.scale * leaf.scale);
    s.dvv = s.dvv * (leaf.scale * leaf.scale);
    return s;
  }

  // the leaf of `at` below `root`, the node of its face: a sub-quad is the child of its face at its
  // corner (one level makes it a quad of its own, with the same (u, v))
  Leaf descend(Node& root, const Location& at) const
  {
    if(at.corner < 0)
      return descend(root, FT(at.u), FT(at.v), 0);
    return descend(child_of(root, {at.corner, {0, 0}, {0, 0}}), FT(at.u), FT(at.v), 1);
  }

  // the faces whose trees are kept (by ordinal; null: none), the oldest first in `order`
  struct Cache
  {
    std::mutex mutex;
    std::vector<std::shared_ptr<Node>> roots;
    std::deque<std::size_t> order;
    std::unique_ptr<First_level> first_level; // kept whatever `cached_faces` is
    std::vector<Exact_sample> vertex_limits;  // of the mesh's vertices, by ordinal (if needed)
  };

  /*
   * The limit at `at`, through the kept tree of its face (made the first
   * time): the walk down, which keeps what it makes, under the cache's
   * lock; the evaluation at the leaf outside it (a tree dropped meanwhile
   * lives on in `root`).
   */
  Exact_sample evaluate_kept(const Location& at) const
  {
    const halfedge_descriptor h = halfedge(at.face, *m_mesh);
    std::optional<Direct_patch> direct;
    const bool keeps_nothing = cached_faces == 0 && at.corner < 0;
    if(keeps_nothing) { // a face that is a direct patch there is evaluated without making its node
      direct = direct_patch(*m_mesh, h);
      if(direct && evaluates_directly(*direct, FT(at.u), FT(at.v), 0))
        return evaluate_direct(*direct, FT(at.u), FT(at.v));
    }
    std::shared_ptr<Node> root;
    std::unique_lock<std::mutex> lock(m_cache->mutex);
    const std::size_t key = ordinal_of(at.face);
    if(cached_faces > 0 && m_cache->roots.empty())
      m_cache->roots.resize(num_faces(*m_mesh));
    if(cached_faces > 0 && m_cache->roots[key])
      root = m_cache->roots[key];
    else {
      root = keeps_nothing ? make_node(*m_mesh, h, std::move(direct)) : make_node(*m_mesh, h);
      if(refine_whole_mesh)
        root->mesh_face = key;
      if(cached_faces > 0) {
        m_cache->roots[key] = root;
        m_cache->order.push_back(key);
      }
      for(; m_cache->order.size() > cached_faces; m_cache->order.pop_front())
        m_cache->roots[m_cache->order.front()].reset();
    }
    const Leaf leaf = descend(*root, at);
    lock.unlock();
    return evaluate_leaf(leaf);
  }

  static int nearest_corner(const FT& u, const FT& v)
  {
    const FT half = FT(1) / FT(2);
    if(!quads)
      return u >= half ? 1 : v >= half ? 2 : 0;
    return u < half ? (v < half ? 0 : 3) : (v < half ? 1 : 2);
  }

  static Limit_sample to_sample(const Exact_sample& s)
  {
    const auto vector = [](const Vector& w) {
      return Limit_sample::Vector(CGAL::to_double(w.x()), CGAL::to_double(w.y()), CGAL::to_double(w.z()));
    };
    Limit_sample out;
    out.position = Limit_sample::Point(CGAL::to_double(s.position.x()), CGAL::to_double(s.position.y()),
                                       CGAL::to_double(s.position.z()));
    out.du = vector(s.du);
    out.dv = vector(s.dv);
    out.duu = vector(s.duu);
    out.duv = vector(s.duv);
    out.dvv = vector(s.dvv);
    const Limit_sample::Vector n = s.at_extraordinary_vertex ? vector(s.normal) : CGAL::cross_product(out.du, out.dv);
    const double length = std::sqrt(n.squared_length());
    out.normal = length > 0 ? n / length : n;
    return out;
  }

  using Patch_mask = decltype(std::declval<const Mask&>().template rebind<Patch_mesh, FT>());
  // what evaluations share: the eigenbases by valence, the limit masks (under one lock)
  struct Eigenbases
  {
    explicit Eigenbases(const Patch_mask& mask) : limit(mask) {}
    std::mutex mutex;
    Limit_evaluator<Patch_mask> limit;
    std::map<std::size_t, std::unique_ptr<const Eigenbasis>> by_valence;
  };

  const PolygonMesh* m_mesh;
  Patch_mask m_mask;
  std::shared_ptr<const internal::Mesh_numbering<PolygonMesh>> m_numbering;
  std::shared_ptr<Eigenbases> m_eigenbases;
  std::shared_ptr<Cache> m_cache;
  std::shared_ptr<const Tags> m_tags; // none without sharpness tags
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_LIMIT_SURFACE_H
