// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_LIMIT_SURFACE_H
#define CGAL_SUBDIV_LIMIT_LIMIT_SURFACE_H

/// \file Limit_surface.h
/// The limit surface of Catmull-Clark anywhere: the position, first and
/// second derivatives and the normal at any (face, u, v), by local
/// refinement down to a regular patch, evaluated as a bicubic B-spline.

#include <CGAL/Kernel_traits.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/Carried_data.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/Mesh_numbering.h>
#include <CGAL/Subdiv/limit/patch_basis.h>
#include <CGAL/Subdiv/limit/project_to_limit.h>
#include <CGAL/Subdiv/masks/Catmull_clark_mask.h>
#include <CGAL/Subdiv/masks/Loop_mask.h>
#include <CGAL/Subdiv/subdivide.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * The limit surface at one parameter: the position, its partial derivatives
 * along the face's u and v (first and second), and the unit normal.
 */
struct Limit_sample
{
  using Point = CGAL::Simple_cartesian<double>::Point_3;
  using Vector = CGAL::Simple_cartesian<double>::Vector_3;
  Point position = CGAL::ORIGIN;
  Vector du = CGAL::NULL_VECTOR, dv = CGAL::NULL_VECTOR;
  Vector duu = CGAL::NULL_VECTOR, duv = CGAL::NULL_VECTOR, dvv = CGAL::NULL_VECTOR;
  Vector normal = CGAL::NULL_VECTOR;
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
 * `Border_corners`) or Loop (`Loop_mask`, either beta; closed meshes only,
 * a border is refused) at any parameter of any face (the first slice of
 * issue 13: the mesh's sharpness tags are not read yet).
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
 * regular too, the control points beyond the border extrapolated. Any other
 * face is refined locally (its 1-ring, with the library's own `subdivide()`,
 * in the mesh's number type) and the child that holds (u, v) is evaluated in
 * turn: every child away from an extraordinary vertex is regular after one
 * level, and a parameter at distance d from the extraordinary corner is
 * reached after about log2(1/d) levels. So the evaluation is exact in an
 * exact kernel (up to the final conversion to double) at every parameter
 * but an extraordinary vertex itself, where the position is the limit mask
 * of the analysis (`project_to_limit()`), the normal its tangent masks'
 * (`limit_normals()`), and the derivatives, which the parameterisation does
 * not have there, are zero. A parameter closer than 2^-`max_depth` to an
 * extraordinary corner is evaluated at that corner (the surface moves by
 * about lambda^`max_depth` times the patch's size there, lambda < 0.65 the
 * subdominant eigenvalue).
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

public:
  /// levels of local refinement at most before a parameter is taken at its extraordinary corner
  int max_depth = 60;

  /// the evaluator of `mesh` (kept by reference: it must outlive the evaluator and stay unchanged)
  /// under the scheme of `mask` (its options kept); \throws Bad_input under Loop if `mesh` has a
  /// border (not supported yet) or a face that is not a triangle
  explicit Limit_surface(const PolygonMesh& mesh, const Mask& mask = Mask())
    : m_mesh(&mesh), m_mask(mask.template rebind<Patch_mesh, FT>()),
      m_corners(std::make_shared<Corner_evaluator>(m_mask))
  {
    if constexpr(!quads) {
      for(const halfedge_descriptor h : halfedges(mesh))
        if(CGAL::is_border(h, mesh))
          internal::refuse(internal::Message() << "Limit_surface: the mesh has a border (vertex "
                                               << ordinal_of(target(h, mesh)) << "): not supported yet for Loop");
      for(const face_descriptor f : faces(mesh))
        if(degree_of(f) != 3)
          internal::refuse(internal::Message()
                           << "Limit_surface: face " << ordinal_of(f) << " is not a triangle (Loop)");
    }
  }

  /// the mesh whose limit this is
  const PolygonMesh& mesh() const { return *m_mesh; }

  /// the limit surface at (u, v) of quad (Catmull-Clark) or triangle (Loop) `f`; \throws Bad_input
  /// if `f` is a Catmull-Clark face with n != 4 corners, or (u, v) is not in its domain
  Limit_sample evaluate(face_descriptor f, double u, double v) const
  {
    check_parameters(u, v);
    if constexpr(quads) {
      const int corners = degree_of(f);
      if(corners != 4)
        internal::refuse(internal::Message()
                         << "Limit_surface: face " << ordinal_of(f) << " has " << corners << " corners: address it as "
                         << corners << " sub-quads (face, corner, u, v)");
    } else if(!(u + v <= 1))
      internal::refuse(internal::Message() << "Limit_surface: the parameter (" << std::to_string(u) << ", "
                                           << std::to_string(v) << ") is not in the triangle's domain (u + v <= 1)");
    return to_sample(evaluate_face(local_patch(*m_mesh, f), FT(u), FT(v), 0));
  }

  /// the limit surface at (u, v) of the sub-quad at `corner` of face `f` (n != 4 corners)
  Limit_sample evaluate(face_descriptor f, int corner, double u, double v) const
  {
    static_assert(quads, "Limit_surface: sub-quads are Catmull-Clark's");
    check_parameters(u, v);
    const int corners = degree_of(f);
    if(corners == 4)
      internal::refuse(internal::Message() << "Limit_surface: face " << ordinal_of(f)
                                           << " is a quad: address it as (face, u, v), without a corner");
    if(corner < 0 || corner >= corners)
      internal::refuse(internal::Message() << "Limit_surface: face " << ordinal_of(f) << " has no corner " << corner
                                           << " (it has " << corners << ")");
    // one level makes the sub-quad a quad of its own, with the same (u, v)
    Patch patch = local_patch(*m_mesh, f);
    const Child child = refine_and_find(patch, corner, {0, 0}, {0, 0});
    return to_sample(evaluate_face(local_patch(child.mesh, child.face_h0), FT(u), FT(v), 1));
  }

private:
  // a face of a small mesh, with the halfedge whose target is its corner 0
  struct Patch
  {
    Patch_mesh mesh;
    Patch_halfedge h0;
  };
  // the position and derivatives, in the mesh's number type
  struct Exact_sample
  {
    Point position;
    Vector du, dv, duu, duv, dvv;
    bool at_extraordinary_vertex = false;
    Vector normal; // at an extraordinary vertex only
  };
  struct Child
  {
    Patch_mesh mesh;
    Patch_halfedge face_h0;
  };
  using Patch_mask = decltype(std::declval<const Mask&>().template rebind<Patch_mesh, FT>());
  /*
   * The limit masks at an extraordinary corner come from the analysis of its
   * configuration (up to half a second each): one Limit_evaluator keeps them
   * for every evaluation (and every copy of this evaluator), behind a mutex
   * so that evaluate() stays safe to call from several threads.
   */
  struct Corner_evaluator
  {
    explicit Corner_evaluator(const Patch_mask& mask) : evaluator(mask) {}
    std::mutex mutex;
    Limit_evaluator<Patch_mask> evaluator;
  };

  template <class Element>
  std::size_t ordinal_of(Element e) const
  {
    return internal::Mesh_numbering<PolygonMesh>(*m_mesh)(e);
  }

  static void check_parameters(double u, double v)
  {
    if(!(u >= 0 && u <= 1 && v >= 0 && v <= 1))
      internal::refuse(internal::Message() << "Limit_surface: the parameter (" << std::to_string(u) << ", "
                                           << std::to_string(v) << ") is not in the face's domain [0, 1]^2");
  }

  int degree_of(face_descriptor f) const
  {
    return static_cast<int>(CGAL::halfedges_around_face(halfedge(f, *m_mesh), *m_mesh).size());
  }

  /*
   * The patch of face f of `source` (a copy of f and of every face that
   * shares a vertex with it, f first), its corner 0 at the target of
   * halfedge(f, source). Outside f's corners the patch has a border of its
   * own: the elements that a refinement makes there are never read.
   */
  template <class Source>
  static Patch local_patch(const Source& mesh, typename boost::graph_traits<Source>::face_descriptor f)
  {
    return local_patch(mesh, halfedge(f, mesh));
  }

  template <class Source>
  static Patch local_patch(const Source& mesh, typename boost::graph_traits<Source>::halfedge_descriptor h0)
  {
    using Source_face = typename boost::graph_traits<Source>::face_descriptor;
    using Source_vertex = typename boost::graph_traits<Source>::vertex_descriptor;
    const auto vpm = get(CGAL::vertex_point, mesh);
    const Source_face f = face(h0, mesh);
    std::vector<Source_face> ring{f};
    for(const auto corner : CGAL::vertices_around_face(h0, mesh))
      for(const Source_face g : CGAL::faces_around_target(halfedge(corner, mesh), mesh))
        if(g != boost::graph_traits<Source>::null_face() && std::find(ring.begin(), ring.end(), g) == ring.end())
          ring.push_back(g);
    Patch patch;
    std::map<Source_vertex, typename Patch_mesh::Vertex_index> copy;
    std::vector<typename Patch_mesh::Vertex_index> corners;
    for(const Source_face g : ring) {
      corners.clear();
      for(const Source_vertex w : CGAL::vertices_around_face(halfedge(g, mesh), mesh)) {
        auto [it, fresh] = copy.emplace(w, typename Patch_mesh::Vertex_index());
        if(fresh)
          it->second = patch.mesh.add_vertex(get(vpm, w));
        corners.push_back(it->second);
      }
      if(patch.mesh.add_face(corners) == Patch_mesh::null_face())
        internal::refuse(internal::Message()
                         << "Limit_surface: the faces around a face do not make a disk (a non-manifold neighbourhood)");
    }
    [[maybe_unused]] const auto [h, found] =
      CGAL::halfedge(copy.at(source(h0, mesh)), copy.at(target(h0, mesh)), patch.mesh);
    CGAL_assertion(found && patch.mesh.face(h) == typename Patch_mesh::Face_index(0));
    patch.h0 = h;
    // the domain of the face's children (Face_origin) starts at the target of its halfedge
    patch.mesh.set_halfedge(patch.mesh.face(h), h);
    return patch;
  }

  // the valence of a regular vertex, and the corners of a regular face
  static constexpr std::size_t regular_valence = quads ? 4 : 6;
  static constexpr std::size_t face_corners = quads ? 4 : 3;

  // the sides of the patch's quad on the border: bit i for the edge from
  // corner i to corner i+1
  static int border_sides(const Patch& patch)
  {
    int sides = 0;
    Patch_halfedge h = patch.mesh.next(patch.h0);
    for(int i = 0; i < 4; ++i, h = patch.mesh.next(h))
      if(patch.mesh.is_border(patch.mesh.opposite(h)))
        sides |= 1 << i;
    return sides;
  }

  // whether corner i of the patch's face is a border corner of one face that
  // the mask keeps sharp (Border_corners::sharp)
  bool is_sharp_corner(const Patch& patch, int i) const
  {
    if constexpr(quads) {
      Patch_halfedge h = patch.h0;
      for(int k = 0; k < i; ++k)
        h = patch.mesh.next(h);
      return m_mask.border_corners() == Border_corners::sharp && patch.mesh.is_border(patch.mesh.target(h)) &&
             patch.mesh.degree(patch.mesh.target(h)) == 2;
    } else
      return false;
  }

  // whether the face of h0 and the faces around its corners are all quads
  // (triangles) and its corners inner vertices of valence 4 (6); under
  // Catmull-Clark, also a quad with one side on the border, whose two ends
  // have two faces, the other corners being inner of valence 4, and with
  // sharp border corners a quad with two adjacent sides on the border, whose
  // common corner is a corner of one face (kept by the mask: the B-spline
  // interpolates it), their other ends having two faces and the fourth
  // corner being inner of valence 4
  bool is_regular(const Patch& patch) const
  {
    const Patch_mesh& mesh = patch.mesh;
    const int sides = quads ? border_sides(patch) : 0;
    if((sides & 5) == 5 || (sides & 10) == 10 ||
       (sides != 0 && (sides & (sides - 1)) != 0 && m_mask.border_corners() != Border_corners::sharp))
      return false; // opposite sides on the border, or a corner that is not kept
    int i = 0;
    for(const Patch_halfedge h : CGAL::halfedges_around_face(patch.h0, mesh)) {
      const auto corner = mesh.target(h);
      // corner i ends side i - 1 (from corner i - 1) and starts side i
      const int on_border = ((sides >> i) & 1) + ((sides >> ((i + 3) % 4)) & 1);
      ++i;
      if(on_border > 0 ? mesh.degree(corner) != std::size_t(4 - on_border) || !mesh.is_border(corner)
                       : mesh.degree(corner) != regular_valence || mesh.is_border(corner))
        return false;
      for(const auto g : CGAL::faces_around_target(h, mesh))
        if(g != Patch_mesh::null_face() && mesh.degree(g) != face_corners)
          return false;
    }
    return true;
  }

  /*
   * The 16 control points of a regular quad, numbered as
   * `bspline_patch_weights()` takes them (point 4 r + c in row r along v,
   * column c along u; corner i of the face at 5, 6, 10, 9). Across the edge
   * from corner i to corner i+1 lie the neighbours of both, and the diagonal
   * neighbour of corner i is the far corner of the face beyond. A side on
   * the border has nothing beyond: its row (column) is extrapolated, p =
   * 2 b - q from the border point b and the inner one q behind it, so that
   * the B-spline refines as Catmull-Clark's border rules do (a border
   * vertex 3/4, 1/8, 1/8; a border edge its midpoint; a sharp corner stays)
   * and its side is the cubic B-spline of the border points. With two sides
   * on the border, the second extrapolation also makes the point beyond
   * their common corner (the first one's there, read from points not made
   * yet, is overwritten).
   */
  static std::array<Point, 16> quad_control_points(const Patch& patch)
  {
    const Patch_mesh& m = patch.mesh;
    std::array<Patch_halfedge, 4> h;
    h[0] = patch.h0;
    for(int i = 1; i < 4; ++i)
      h[i] = m.next(h[i - 1]);
    const int sides = border_sides(patch);
    // by corner i: its point, the neighbours across the edge to corner i+1
    // (next to corner i, then to corner i+1), and its diagonal neighbour
    static const int corner_point[4] = {5, 6, 10, 9};
    static const int across[4][2] = {{1, 2}, {7, 11}, {14, 13}, {8, 4}};
    static const int diagonal[4] = {0, 3, 15, 12};
    std::array<Point, 16> points;
    points.fill(Point(CGAL::ORIGIN));
    for(int i = 0; i < 4; ++i) {
      points[corner_point[i]] = m.point(m.target(h[i]));
      if((sides >> i) & 1) // nothing beyond
        continue;
      const Patch_halfedge beyond = m.opposite(h[(i + 1) % 4]); // across the edge from corner i to corner i+1
      points[across[i][0]] = m.point(m.target(m.next(beyond)));
      points[across[i][1]] = m.point(m.target(m.next(m.next(beyond))));
      if(!((sides >> ((i + 3) % 4)) & 1)) // corner i's diagonal face is not beyond the border
        points[diagonal[i]] = m.point(m.source(m.prev(m.opposite(m.next(beyond)))));
    }
    for(int side = 0; side < 4; ++side)
      if((sides >> side) & 1)
        extrapolate_beyond(side, points);
    return points;
  }

  // the points beyond border side `side` of the grid: p = 2 b - q
  static void extrapolate_beyond(int side, std::array<Point, 16>& points)
  {
    // point (r, c) of the grid seen from the side: row 0 beyond the border,
    // row 1 on it, row 2 inside
    const auto at = [side](int r, int c) {
      switch(side) {
        case 0:
          return 4 * r + c; // bottom
        case 1:
          return 4 * c + (3 - r); // right
        case 2:
          return 4 * (3 - r) + (3 - c); // top
        default:
          return 4 * (3 - c) + r; // left
      }
    };
    for(int c = 0; c < 4; ++c)
      points[at(0, c)] = points[at(1, c)] + (points[at(1, c)] - points[at(2, c)]);
  }

  /*
   * The 12 control points of a regular triangle, numbered as
   * `box_spline_patch_weights()` takes them (corner 0 at 4, 1 at 5, 2 at 8).
   * Turning around corner i from the halfedge into it in the face
   * (opposite(next(g)) is the next halfedge into it), the sources are corner
   * i-1, corner i+1, then four vertices of the ring: around corner 0 the
   * points 1, 0, 3, 7, around corner 1 9, 6, 2, 1, around corner 2 7, 10, 11, 9.
   */
  static std::array<Point, 12> triangle_control_points(const Patch& patch)
  {
    const Patch_mesh& m = patch.mesh;
    static const int corner_point[3] = {4, 5, 8};
    static const int ring[3][4] = {{1, 0, 3, 7}, {9, 6, 2, 1}, {7, 10, 11, 9}};
    std::array<Point, 12> points;
    Patch_halfedge into = patch.h0;
    for(int i = 0; i < 3; ++i, into = m.next(into)) {
      points[corner_point[i]] = m.point(m.target(into));
      Patch_halfedge g = m.opposite(m.next(into)); // from corner i+1
      for(int k = 0; k < 4; ++k) {
        g = m.opposite(m.next(g));
        points[ring[i][k]] = m.point(m.source(g));
      }
    }
    return points;
  }

  template <std::size_t N>
  static Exact_sample combine(const std::array<Point, N>& points, const Patch_weights<FT, N>& w)
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
    s.duu = sum(w.duu);
    s.duv = sum(w.duv);
    s.dvv = sum(w.dvv);
    return s;
  }

  static Exact_sample evaluate_regular(const Patch& patch, const FT& u, const FT& v)
  {
    if constexpr(quads)
      return combine(quad_control_points(patch), bspline_patch_weights(u, v));
    else
      return combine(triangle_control_points(patch), box_spline_patch_weights(u, v));
  }

  // the corner of the patch's face at (u, v), if (u, v) is a corner; -1 otherwise
  static int corner_at(const FT& u, const FT& v)
  {
    const bool u0 = u == FT(0), u1 = u == FT(1), v0 = v == FT(0), v1 = v == FT(1);
    if(!quads && u0 && v1)
      return 2;
    return u0 && v0 ? 0 : u1 && v0 ? 1 : u1 && v1 ? 2 : u0 && v1 ? 3 : -1;
  }

  // the limit position and normal of corner i of the patch's face (the masks of the analysis)
  Exact_sample evaluate_at_corner(Patch patch, int i) const
  {
    Patch_halfedge h = patch.h0;
    for(int k = 0; k < i; ++k)
      h = patch.mesh.next(h);
    const auto corner = patch.mesh.target(h);
    Exact_sample s;
    s.du = s.dv = s.duu = s.duv = s.dvv = CGAL::NULL_VECTOR;
    s.at_extraordinary_vertex = true;
    const auto normals = patch.mesh
                           .template add_property_map<typename Patch_mesh::Vertex_index, Vector>(
                             "v:cgal_subdiv_limit_normal", CGAL::NULL_VECTOR)
                           .first;
    const std::lock_guard<std::mutex> lock(m_corners->mutex);
    m_corners->evaluator.limit_normals(patch.mesh, normals);
    s.normal = normals[corner];
    m_corners->evaluator.project_to_limit(patch.mesh);
    s.position = patch.mesh.point(corner);
    return s;
  }

  /*
   * Refines the patch one level and returns the child of its face (face 0)
   * in sub-quad `sub_quad` (-1: none) whose box starts at `box_min` and that
   * has a corner at `anchor`, with the halfedge into that corner: the
   * child's corner 0 (the parameters are dyadic, exact in double).
   */
  Child refine_and_find(Patch& patch, int sub_quad, std::array<double, 2> box_min, std::array<double, 2> anchor) const
  {
    auto origins =
      patch.mesh.template add_property_map<typename Patch_mesh::Face_index, Face_origin>("f:cgal_subdiv_limit_origin")
        .first;
    Carried_data<Patch_mesh, FT> data;
    data.face_origin_map(origins);
    subdivide(patch.mesh, m_mask, parameters::carried_data(data));
    for(const auto g : patch.mesh.faces()) {
      const Face_origin& origin = origins[g];
      const CGAL::Bbox_2 box = origin.box();
      if(origin.face != 0 || origin.sub_quad != sub_quad || box.xmin() != box_min[0] || box.ymin() != box_min[1])
        continue;
      Patch_halfedge h = patch.mesh.halfedge(g);
      for(int i = 0; i < origin.corners; ++i, h = patch.mesh.next(h))
        if(origin.uv[i][0] == anchor[0] && origin.uv[i][1] == anchor[1])
          return Child{std::move(patch.mesh), h};
    }
    internal::refuse(internal::Message() << "Limit_surface: no child holds the parameter (an internal error)");
    return Child{};
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
    std::array<double, 2> box_min, anchor;
    FT u, v;
    FT scale;
  };
  static Child_parameters child_parameters(const FT& u, const FT& v)
  {
    const FT half = FT(1) / FT(2);
    if(!quads && u < half && v < half && u + v > half) // the middle triangle
      return {{0, 0}, {0.5, 0.5}, FT(1) - FT(2) * u, FT(1) - FT(2) * v, FT(-2)};
    // a quarter of a quad; a corner triangle, u >= 1/2 the one at corner 1
    const FT a = u < half ? FT(0) : half, b = v < half || (!quads && a == half) ? FT(0) : half;
    const std::array<double, 2> corner{CGAL::to_double(a), CGAL::to_double(b)};
    return {corner, corner, FT(2) * (u - a), FT(2) * (v - b), FT(2)};
  }

  // the limit at (u, v) of the patch's face, `depth` levels below the mesh
  Exact_sample evaluate_face(Patch patch, const FT& u, const FT& v, int depth) const
  {
    if(is_regular(patch))
      return evaluate_regular(patch, u, v);
    const int corner = corner_at(u, v);
    // a sharp corner is regular one level down (its child quad has two sides on the border)
    if((corner >= 0 && !is_sharp_corner(patch, corner)) || depth >= max_depth)
      return evaluate_at_corner(std::move(patch), corner >= 0 ? corner : nearest_corner(u, v));
    const Child_parameters c = child_parameters(u, v);
    const Child child = refine_and_find(patch, -1, c.box_min, c.anchor);
    Exact_sample s = evaluate_face(local_patch(child.mesh, child.face_h0), c.u, c.v, depth + 1);
    // d/du = scale d/du' in the child's parameters
    s.du = s.du * c.scale;
    s.dv = s.dv * c.scale;
    s.duu = s.duu * (c.scale * c.scale);
    s.duv = s.duv * (c.scale * c.scale);
    s.dvv = s.dvv * (c.scale * c.scale);
    return s;
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

  const PolygonMesh* m_mesh;
  Patch_mask m_mask;
  std::shared_ptr<Corner_evaluator> m_corners;
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_LIMIT_SURFACE_H
