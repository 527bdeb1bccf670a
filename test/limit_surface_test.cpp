// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
// Limit_surface: the Catmull-Clark limit at any (face, u, v), against the
// library's refinement and limit masks (another path: global refinement,
// then the limit masks of the analysis at the vertex that sits at the
// parameter), exactly; derivatives against differences of positions; bad
// parameters refused.

#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Subdiv/limit/Limit_surface.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/number_type_config.h>

#include <gtest/gtest.h>

#include "mesh_builders.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace S = CGAL::Subdiv;
using KE = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using Exact_mesh = CGAL::Surface_mesh<KE::Point_3>;
using K = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

namespace {

// a prism over an n-gon and a bipyramid over one, refined once by Catmull-Clark
// and Loop: every face a quad (triangle), vertices of valence n and the regular one
template <class M = Mesh>
M refined_prism(int n)
{
  M quads = testing_utils::prism<M>(n);
  S::catmull_clark_subdivision(quads, S::parameters::number_of_iterations(1));
  return quads;
}
template <class M = Mesh>
M refined_bipyramid(int n)
{
  M triangles = testing_utils::bipyramid<M>(n);
  S::loop_subdivision(triangles, S::parameters::number_of_iterations(1));
  return triangles;
}

S::Limit_sample::Point to_double(const KE::Point_3& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

S::Limit_sample::Vector unit(const KE::Vector_3& n)
{
  const S::Limit_sample::Vector d(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z()));
  return d / std::sqrt(d.squared_length());
}

/*
 * Every vertex v of `refined` (`base` refined, the face origins in
 * `origin`) at its parameter in each base face it lies in: there the
 * evaluator's position is `limit`'s point of v converted to double, bit for
 * bit, and, where `compare_normal(v)`, its normal the direction of
 * normal[v]. Returns the vertices checked, once per base face they lie in.
 */
template <class Mask, class Surface, class CompareNormal>
std::vector<Exact_mesh::Vertex_index> expect_limits_at_parameters(
  const Surface& surface, const Exact_mesh& base, const Exact_mesh& refined,
  const Exact_mesh::Property_map<Exact_mesh::Face_index, S::Face_origin>& origin, const Exact_mesh& limit,
  const Exact_mesh::Property_map<Exact_mesh::Vertex_index, KE::Vector_3>& normal, const CompareNormal& compare_normal)
{
  const std::vector<Exact_mesh::Face_index> base_faces(base.faces().begin(), base.faces().end());
  std::map<std::pair<std::size_t, Exact_mesh::Vertex_index>, bool> done; // (base face, vertex)
  std::vector<Exact_mesh::Vertex_index> checked;
  for(const auto f : refined.faces()) {
    const S::Face_origin& o = origin[f];
    int i = 0;
    for(const auto h : CGAL::halfedges_around_face(refined.halfedge(f), refined)) {
      const auto v = refined.target(h);
      const auto [u, w] = std::make_pair(o.uv[i][0], o.uv[i][1]);
      ++i;
      if(!done.emplace(std::make_pair(o.face, v), true).second)
        continue;
      SCOPED_TRACE("base face " + std::to_string(o.face) + " sub-quad " + std::to_string(o.sub_quad) + " (u, v) = (" +
                   std::to_string(u) + ", " + std::to_string(w) + ")");
      S::Limit_sample s;
      if constexpr(std::is_same<Mask, S::Catmull_clark_mask<Exact_mesh>>::value)
        s = o.sub_quad < 0 ? surface.evaluate(base_faces[o.face], u, w)
                           : surface.evaluate(base_faces[o.face], o.sub_quad, u, w);
      else
        s = surface.evaluate(base_faces[o.face], u, w);
      EXPECT_EQ(s.position, to_double(limit.point(v)));
      if(compare_normal(v)) {
        EXPECT_NEAR((s.normal - unit(normal[v])).squared_length(), 0, 1e-24);
      }
      checked.push_back(v);
    }
  }
  return checked;
}

/*
 * Every vertex of `base` refined `levels` levels sits at a parameter of the
 * base faces around it (face_origin_map): there the evaluator's position is
 * the exact limit of that vertex (project_to_limit), converted to double,
 * bit for bit, and its normal the limit normal's direction (limit_normals)
 * but at a border corner with one face. The same whether the evaluator
 * starts from the whole mesh refined once or refines each face's
 * neighbourhood.
 */
template <class Mask>
void expect_limit_of_refined_vertices(const Exact_mesh& base, int levels, const Mask& mask, bool refine_whole_mesh)
{
  S::Limit_surface<Exact_mesh, Mask> surface(base, mask);
  surface.refine_whole_mesh = refine_whole_mesh;
  Exact_mesh refined = base;
  const auto origin = refined.add_property_map<Exact_mesh::Face_index, S::Face_origin>("f:origin").first;
  S::Carried_data<Exact_mesh> data;
  data.face_origin_map(origin);
  S::subdivide(refined, mask, S::parameters::number_of_iterations(levels).carried_data(data));
  const auto normal = refined.add_property_map<Exact_mesh::Vertex_index, KE::Vector_3>("v:normal").first;
  S::limit_normals(refined, mask, normal);
  Exact_mesh limit = refined;
  S::project_to_limit(limit, mask);

  // (at a corner with one face the analysis finds no C1 tangent plane, and
  // limit_normals averages the faces around, which depends on the level)
  const std::vector<Exact_mesh::Vertex_index> checked = expect_limits_at_parameters<Mask>(
    surface, base, refined, origin, limit, normal,
    [&](Exact_mesh::Vertex_index v) { return !(refined.is_border(v) && refined.degree(v) == 2); });
  const std::size_t regular_valence = std::is_same<Mask, S::Catmull_clark_mask<Exact_mesh>>::value ? 4 : 6;
  const auto extraordinary = std::count_if(
    checked.begin(), checked.end(), [&](Exact_mesh::Vertex_index v) { return refined.degree(v) != regular_valence; });
  EXPECT_GT(extraordinary, 0);
  EXPECT_GT(checked.size(), refined.number_of_vertices()); // the vertices on base edges, from both faces
}

template <class Mask = S::Catmull_clark_mask<Exact_mesh>>
void expect_limit_of_refined_vertices(const Exact_mesh& base, int levels, const Mask& mask = Mask())
{
  for(const bool whole_mesh : {true, false}) {
    SCOPED_TRACE(whole_mesh ? "the whole mesh refined once" : "each neighbourhood refined");
    expect_limit_of_refined_vertices(base, levels, mask, whole_mesh);
  }
}

} // namespace

TEST(LimitSurface, catmull_clark_equals_the_limit_of_refined_vertices_on_a_box_of_quads_and_triangles)
{
  expect_limit_of_refined_vertices(testing_utils::mixed_box<Exact_mesh>(), 2);
}

TEST(LimitSurface, catmull_clark_equals_the_limit_of_refined_vertices_on_a_prism)
{
  expect_limit_of_refined_vertices(testing_utils::prism<Exact_mesh>(5), 2);
}

// one level of the prism makes vertices of valence 3, 4 and 5 and only
// quads: parameters two levels deep, near each kind of extraordinary corner
TEST(LimitSurface, catmull_clark_equals_the_limit_of_refined_vertices_near_valence_5)
{
  Exact_mesh mesh = testing_utils::prism<Exact_mesh>(5);
  S::catmull_clark_subdivision(mesh, S::parameters::number_of_iterations(1));
  expect_limit_of_refined_vertices(mesh, 2);
}

// Catmull-Clark with borders: a quad with one side on the border is a
// regular patch with its row beyond extrapolated; the corners of a grid (one
// face: smooth corners, refined by the border rule), the border vertices of
// valence 3 of an open prism (its top cap removed) and its pentagon are
// refined until regular
TEST(LimitSurface, catmull_clark_equals_the_limit_of_refined_vertices_with_borders)
{
  testing_utils::Rationals r;
  const auto point = [&r](int i, int j) {
    return KE::Point_3(i + r.next<CGAL::Exact_rational>(), j + r.next<CGAL::Exact_rational>(),
                       ((i * j) % 3) + r.next<CGAL::Exact_rational>());
  };
  expect_limit_of_refined_vertices(testing_utils::grid<Exact_mesh>(3, 3, point, false), 2);
  Exact_mesh open = testing_utils::prism<Exact_mesh>(5);
  CGAL::Euler::remove_face(open.halfedge(*std::next(open.faces().begin())), open); // the top cap
  open.collect_garbage();
  expect_limit_of_refined_vertices(open, 2);
}

// Loop, either beta: a tetrahedron (valence 3), a bipyramid (valence 5 and
// 4), and the bipyramid refined once (valence 4, 5 and 6: the middle
// triangles of the split, turned by a half turn, evaluated too)
TEST(LimitSurface, loop_equals_the_limit_of_refined_vertices)
{
  expect_limit_of_refined_vertices(testing_utils::tetrahedron<Exact_mesh>(), 2, S::Loop_mask<Exact_mesh>());
  expect_limit_of_refined_vertices(testing_utils::bipyramid<Exact_mesh>(5), 2,
                                   S::Loop_mask<Exact_mesh, CGAL::Exact_rational, S::Warren_beta>());
  Exact_mesh mesh = testing_utils::bipyramid<Exact_mesh>(5);
  S::loop_subdivision(mesh, S::parameters::number_of_iterations(1));
  expect_limit_of_refined_vertices(mesh, 2, S::Loop_mask<Exact_mesh>());
}

// Loop with borders: a triangle with one corner or one side on the border,
// each such corner with three faces, is a regular patch, its points beyond
// the border extrapolated; the rest is refined until regular. A triangle
// grid (corners of one and two faces, with both corner rules), a grid of
// valences 4 and 8 (border vertices with two and four faces) and a
// bipyramid with one face removed (border vertices with three and four
// faces around the hole)
TEST(LimitSurface, loop_equals_the_limit_of_refined_vertices_with_borders)
{
  testing_utils::Rationals r;
  const auto point = [&r](int i, int j) {
    return KE::Point_3(i + r.next<CGAL::Exact_rational>(), j + r.next<CGAL::Exact_rational>(),
                       ((i * j) % 3) + r.next<CGAL::Exact_rational>());
  };
  const Exact_mesh grid = testing_utils::grid<Exact_mesh>(4, 4, point, true);
  expect_limit_of_refined_vertices(grid, 2, S::Loop_mask<Exact_mesh>());
  expect_limit_of_refined_vertices(grid, 2, S::Loop_mask<Exact_mesh>(S::Border_corners::sharp));
  expect_limit_of_refined_vertices(
    testing_utils::grid<Exact_mesh>(3, 3, point, true, testing_utils::Diagonal::alternating), 2,
    S::Loop_mask<Exact_mesh>());
  Exact_mesh open = testing_utils::bipyramid<Exact_mesh>(5);
  CGAL::Euler::remove_face(open.halfedge(*open.faces().begin()), open);
  open.collect_garbage();
  expect_limit_of_refined_vertices(open, 2, S::Loop_mask<Exact_mesh, CGAL::Exact_rational, S::Warren_beta>());
}

// which triangles of a 4 x 4 triangle grid are regular Loop patches: all
// but the 6 at its corners (of one and two faces) and the 2 beside its
// corners of one face, whose two border corners do not end a border side;
// whichever corner the walk starts from
TEST(LimitSurface, loop_border_triangles_are_regular_patches)
{
  const Mesh grid = testing_utils::grid<Mesh>(
    4, 4, [](int i, int j) { return K::Point_3(i, j, 0); }, true);
  std::size_t regular = 0;
  for(const auto f : grid.faces()) {
    std::size_t starts = 0;
    for(const auto h : CGAL::halfedges_around_face(grid.halfedge(f), grid))
      starts += S::internal::Patch_points<Mesh, false>(grid, h).is_regular() ? 1 : 0;
    EXPECT_TRUE(starts == 0 || starts == 3);
    regular += starts / 3;
  }
  EXPECT_EQ(regular, 32u - 6u - 2u);
}

/*
 * With sharpness tags: every vertex of `base` refined `levels` levels, with
 * the tags decaying, sits at a parameter of a base face; there the
 * evaluator (given the same tags) is the exact limit of that vertex under
 * the tags of its level (project_to_limit with the refined maps), bit for
 * bit, and its normal the limit normal's direction at the vertices without
 * an infinitely sharp tag (at a crease vertex the limit has a tangent
 * plane per side). The tags must have decayed to 0 or be infinite at
 * `levels` (a semi-sharp value left would make the refined mesh's rule
 * OpenSubdiv's approximation, not the limit).
 */
template <class Mask>
void expect_tagged_limit_of_refined_vertices(const Exact_mesh& mesh, int levels, const Mask& mask,
                                             const std::vector<std::pair<std::array<int, 2>, int>>& edges,
                                             const std::vector<std::pair<int, int>>& vertices)
{
  using Q = CGAL::Exact_rational;
  Exact_mesh base = mesh;
  const auto base_edges = base.add_property_map<Exact_mesh::Edge_index, Q>("e:sharpness", Q(0)).first;
  const auto base_vertices = base.add_property_map<Exact_mesh::Vertex_index, Q>("v:sharpness", Q(0)).first;
  for(const auto& [ends, sharpness] : edges) {
    const auto [h, found] = CGAL::halfedge(Exact_mesh::Vertex_index(ends[0]), Exact_mesh::Vertex_index(ends[1]), base);
    ASSERT_TRUE(found);
    base_edges[base.edge(h)] = Q(sharpness) / Q(2); // halves: semi-sharp 1/2, 3/2, ...; 20 is infinite
  }
  for(const auto& [v, sharpness] : vertices)
    base_vertices[Exact_mesh::Vertex_index(v)] = Q(sharpness) / Q(2);
  const auto tags = [](Exact_mesh& m) {
    return S::parameters::edge_sharpness_map(m.property_map<Exact_mesh::Edge_index, Q>("e:sharpness").first)
      .vertex_sharpness_map(m.property_map<Exact_mesh::Vertex_index, Q>("v:sharpness").first);
  };
  const S::Limit_surface<Exact_mesh, Mask> surface(base, mask, tags(base));
  Exact_mesh refined = base; // (with its maps)
  const auto origin = refined.add_property_map<Exact_mesh::Face_index, S::Face_origin>("f:origin").first;
  S::Carried_data<Exact_mesh> data;
  data.face_origin_map(origin);
  S::subdivide(refined, mask, tags(refined).number_of_iterations(levels).carried_data(data));
  const auto normal = refined.add_property_map<Exact_mesh::Vertex_index, KE::Vector_3>("v:normal").first;
  S::limit_normals(refined, mask, normal, tags(refined));
  Exact_mesh limit = refined;
  S::project_to_limit(limit, mask, tags(limit));
  const auto refined_edges = refined.property_map<Exact_mesh::Edge_index, Q>("e:sharpness").first;
  const auto refined_vertices = refined.property_map<Exact_mesh::Vertex_index, Q>("v:sharpness").first;
  const auto infinitely_sharp = [&](Exact_mesh::Vertex_index v) {
    if(refined_vertices[v] >= Q(10))
      return true;
    for(const auto h : CGAL::halfedges_around_target(v, refined))
      if(refined_edges[refined.edge(h)] >= Q(10))
        return true;
    return false;
  };
  for(const auto e : refined.edges()) // decayed to 0 or infinite
    ASSERT_TRUE(refined_edges[e] == Q(0) || refined_edges[e] >= Q(10));
  const std::vector<Exact_mesh::Vertex_index> checked =
    expect_limits_at_parameters<Mask>(surface, base, refined, origin, limit, normal, [&](Exact_mesh::Vertex_index v) {
      return !infinitely_sharp(v) && !(refined.is_border(v) && refined.degree(v) == 2);
    });
  const auto sharp = std::count_if(checked.begin(), checked.end(), infinitely_sharp);
  EXPECT_GT(sharp, 0);
  EXPECT_GT(checked.size(), refined.number_of_vertices());
}

// Catmull-Clark and Loop with tags: an infinitely sharp crease (three
// edges) from the border (a corner there: the border edges are sharp) to a
// corner vertex, a semi-sharp edge of 1 (it decays over one level) and one
// of 3/2, on a bumpy 4 x 4 grid of quads and of triangles (vertex 5 j + i
// at (i, j)), refined two levels. (No dart: its limit masks are
// OpenSubdiv's smooth ones, not its limit, which the evaluator approaches
// by refining.)
TEST(LimitSurface, tags_equal_the_limit_of_refined_vertices)
{
  testing_utils::Rationals r;
  const auto point = [&r](int i, int j) {
    return KE::Point_3(i + r.next<CGAL::Exact_rational>(), j + r.next<CGAL::Exact_rational>(),
                       ((i * j) % 3) + r.next<CGAL::Exact_rational>());
  };
  const std::vector<std::pair<std::array<int, 2>, int>> edges = {
    {{5, 6}, 20}, {{6, 7}, 20}, {{7, 8}, 20}, {{16, 17}, 2}, {{11, 12}, 3}};
  const std::vector<std::pair<int, int>> vertices = {{8, 20}};
  const Exact_mesh quads = testing_utils::grid<Exact_mesh>(4, 4, point, false);
  expect_tagged_limit_of_refined_vertices(quads, 2, S::Catmull_clark_mask<Exact_mesh>(), edges, vertices);
  const Exact_mesh triangles = testing_utils::grid<Exact_mesh>(4, 4, point, true);
  expect_tagged_limit_of_refined_vertices(triangles, 2, S::Loop_mask<Exact_mesh>(), edges, vertices);
}

// the derivatives of the position, at parameters away from the corners (in
// double), against central differences
template <class Mask>
void expect_derivatives_of_positions(const Mesh& mesh, const Mask& mask,
                                     const std::vector<std::pair<double, double>>& parameters)
{
  const S::Limit_surface<Mesh, Mask> surface(mesh, mask);
  const double h = 1e-5;
  int faces = 0;
  for(const auto f : mesh.faces()) {
    if(++faces > 12)
      break;
    for(const auto& [u, v] : parameters) {
      const S::Limit_sample s = surface.evaluate(f, u, v);
      const auto du = (surface.evaluate(f, u + h, v).position - surface.evaluate(f, u - h, v).position) / (2 * h);
      const auto dv = (surface.evaluate(f, u, v + h).position - surface.evaluate(f, u, v - h).position) / (2 * h);
      const auto duu = (surface.evaluate(f, u + h, v).du - surface.evaluate(f, u - h, v).du) / (2 * h);
      const auto duv = (surface.evaluate(f, u, v + h).du - surface.evaluate(f, u, v - h).du) / (2 * h);
      const auto dvv = (surface.evaluate(f, u, v + h).dv - surface.evaluate(f, u, v - h).dv) / (2 * h);
      const double scale = 1 + std::sqrt(s.du.squared_length() + s.dv.squared_length());
      EXPECT_LT(std::sqrt((du - s.du).squared_length()), 1e-6 * scale);
      EXPECT_LT(std::sqrt((dv - s.dv).squared_length()), 1e-6 * scale);
      EXPECT_LT(std::sqrt((duu - s.duu).squared_length()), 1e-4 * scale);
      EXPECT_LT(std::sqrt((duv - s.duv).squared_length()), 1e-4 * scale);
      EXPECT_LT(std::sqrt((dvv - s.dvv).squared_length()), 1e-4 * scale);
      EXPECT_NEAR(s.normal.squared_length(), 1, 1e-12);
      EXPECT_NEAR(s.normal * s.du, 0, 1e-9 * std::sqrt(s.du.squared_length()));
    }
  }
}

TEST(LimitSurface, derivatives_agree_with_differences_of_positions)
{
  expect_derivatives_of_positions(refined_prism(5), S::Catmull_clark_mask<Mesh>(),
                                  {{0.3, 0.6}, {0.05, 0.1}, {0.81, 0.27}});
  expect_derivatives_of_positions(refined_bipyramid(5), S::Loop_mask<Mesh>(), {{0.3, 0.6}, {0.05, 0.1}, {0.21, 0.27}});
}

TEST(LimitSurface, bad_parameters_are_refused_naming_the_problem)
{
  const Mesh box = testing_utils::mixed_box<Mesh>();
  const S::Limit_surface<Mesh> surface(box);
  const auto quad = *box.faces().begin(); // {0, 2, 3, 1}
  const auto triangle = *std::next(box.faces().begin());
  const auto expect_refusal = [](const auto& call, const std::string& words) {
    try {
      call();
      ADD_FAILURE() << "not refused: " << words;
    } catch(const S::Bad_input& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  expect_refusal([&] { surface.evaluate(quad, 1.5, 0.5); }, "not in the face's domain");
  expect_refusal([&] { surface.evaluate(quad, 0.5, std::nan("")); }, "not in the face's domain");
  expect_refusal([&] { surface.evaluate(triangle, 0.5, 0.5); }, "face 1 has 3 corners");
  expect_refusal([&] { surface.evaluate(quad, 0, 0.5, 0.5); }, "face 0 is a quad");
  expect_refusal([&] { surface.evaluate(triangle, 3, 0.5, 0.5); }, "face 1 has no corner 3");
  expect_refusal([&] { S::Limit_surface<Mesh, S::Loop_mask<Mesh>> loop(box); }, "face 0 is not a triangle");
  // tags: a negative sharpness, and the Chaikin crease method (not supported yet); the maps unchanged
  Mesh tagged = testing_utils::cube<Mesh>();
  const auto sharpness = tagged.add_property_map<Mesh::Edge_index, float>("e:sharpness", 0.f).first;
  sharpness[Mesh::Edge_index(3)] = -1.f;
  expect_refusal(
    [&] {
      S::Limit_surface<Mesh> s(tagged, S::Catmull_clark_mask<Mesh>(), S::parameters::edge_sharpness_map(sharpness));
    },
    "the sharpness of edge 3 is negative or NaN");
  EXPECT_EQ(sharpness[Mesh::Edge_index(3)], -1.f);
  sharpness[Mesh::Edge_index(3)] = 2.f;
  expect_refusal(
    [&] {
      S::Limit_surface<Mesh> s(tagged, S::Catmull_clark_mask<Mesh>(),
                               S::parameters::edge_sharpness_map(sharpness).crease_method(S::Crease_method::chaikin));
    },
    "Limit_surface: the Chaikin crease method is not supported yet");
  EXPECT_EQ(sharpness[Mesh::Edge_index(3)], 2.f);
  const Mesh triangles = testing_utils::tetrahedron<Mesh>();
  const S::Limit_surface<Mesh, S::Loop_mask<Mesh>> loop(triangles);
  expect_refusal([&] { loop.evaluate(*triangles.faces().begin(), 0.5, 0.75); }, "not in the triangle's domain");
}

// Stam's eigenbasis (double kernels) against the exact refinement of the
// same patches: a prism refined once has valence 3 and n, a bipyramid
// refined once valence 4 and n, and every face is evaluated at parameters
// near and away from its corners. The eigenbasis must have been used.
template <class Mask, class Exact_mask>
void expect_eigenbasis_to_agree_with_exact_refinement(const Mesh& mesh, const Exact_mesh& exact, std::size_t valence)
{
  const S::Limit_surface<Mesh, Mask> surface(mesh);
  const S::Limit_surface<Exact_mesh, Exact_mask> truth(exact);
  const bool quads = std::is_same_v<Mask, S::Catmull_clark_mask<Mesh>>;
  const std::vector<std::pair<double, double>> parameters = {{0.3, 0.6},    {0.004, 0.0031}, {0.71, 0.02},
                                                             {0.99, 0.004}, {0.8, 0.9},      {0.02, 0.97}};
  auto g = exact.faces().begin();
  for(const auto f : mesh.faces()) {
    const auto exact_face = *g++;
    for(auto [u, v] : parameters) {
      if(!quads && u + v > 1)
        std::tie(u, v) = std::make_pair(1 - u, 1 - v);
      const S::Limit_sample s = surface.evaluate(f, u, v), t = truth.evaluate(exact_face, u, v);
      const double scale = 1 + std::sqrt(t.du.squared_length() + t.dv.squared_length());
      const double scale2 = 1 + std::sqrt(t.duu.squared_length() + t.duv.squared_length() + t.dvv.squared_length());
      EXPECT_LT(std::sqrt((s.position - t.position).squared_length()), 1e-13);
      EXPECT_LT(std::sqrt((s.du - t.du).squared_length()), 1e-11 * scale);
      EXPECT_LT(std::sqrt((s.dv - t.dv).squared_length()), 1e-11 * scale);
      EXPECT_LT(std::sqrt((s.duu - t.duu).squared_length()), 1e-9 * scale2);
      EXPECT_LT(std::sqrt((s.duv - t.duv).squared_length()), 1e-9 * scale2);
      EXPECT_LT(std::sqrt((s.dvv - t.dvv).squared_length()), 1e-9 * scale2);
    }
  }
  const auto conditions = surface.eigenbasis_conditions();
  ASSERT_EQ(conditions.count(valence), 1u);
  if(quads || valence != 3)
    EXPECT_LT(conditions.at(valence), 1e4);
  else // defective: evaluated by powers of the local matrix
    EXPECT_EQ(conditions.at(valence), std::numeric_limits<double>::infinity());
}

TEST(LimitSurface, stam_eigenbasis_agrees_with_exact_refinement)
{
  for(const int n : {3, 5, 8}) {
    expect_eigenbasis_to_agree_with_exact_refinement<S::Catmull_clark_mask<Mesh>, S::Catmull_clark_mask<Exact_mesh>>(
      refined_prism(n), refined_prism<Exact_mesh>(n), n);
  }
  for(const int n : {3, 4, 5, 8}) {
    expect_eigenbasis_to_agree_with_exact_refinement<S::Loop_mask<Mesh>, S::Loop_mask<Exact_mesh>>(
      refined_bipyramid(n), refined_bipyramid<Exact_mesh>(n), n);
  }
}

/*
 * What the eigen-decomposition of the local subdivision matrix finds, by
 * valence: diagonalisable in the reals for Catmull-Clark at valences 3 to
 * 16 and Loop at 4 to 16, the condition number of the eigenvectors
 * (orthonormal within each eigenspace) between 79 and 171 (Catmull-Clark,
 * the largest at valence 3) and between 17 and 34 (Loop, the largest at
 * valence 5), so below 500 here; Loop at
 * valence 3 is not (its eigenvector matrix is singular to rounding: the
 * triple eigenvalues 1/8 and 1/16 are defective), so those patches are
 * evaluated by powers of the matrix instead (and still evaluated: finite
 * values at its apex).
 */
TEST(LimitSurface, diagonalisability_of_the_local_matrix_by_valence)
{
  for(int n = 3; n <= 16; ++n) {
    const Mesh quads = refined_prism(n);
    const S::Limit_surface<Mesh> cc(quads);
    const Mesh triangles = refined_bipyramid(n);
    const S::Limit_surface<Mesh, S::Loop_mask<Mesh>> loop(triangles);
    for(const auto f : quads.faces()) // near each corner: the extraordinary one may be any
      for(const auto& [u, v] : {std::make_pair(0.01, 0.02), {0.98, 0.03}, {0.97, 0.99}, {0.02, 0.96}})
        EXPECT_TRUE(std::isfinite(cc.evaluate(f, u, v).du.x()));
    for(const auto f : triangles.faces())
      for(const auto& [u, v] : {std::make_pair(0.01, 0.02), {0.97, 0.01}, {0.02, 0.96}})
        EXPECT_TRUE(std::isfinite(loop.evaluate(f, u, v).du.x()));
    if(n != 4) { // a prism over a square is a cube
      EXPECT_LT(cc.eigenbasis_conditions().at(n), 500) << "Catmull-Clark, valence " << n;
      std::cout << "valence " << n << ": condition of V " << cc.eigenbasis_conditions().at(n) << " (Catmull-Clark), "
                << (n == 6 ? 1.0 : loop.eigenbasis_conditions().at(n)) << " (Loop)\n";
    }
    if(n == 3) {
      EXPECT_EQ(loop.eigenbasis_conditions().at(n), std::numeric_limits<double>::infinity());
    } else if(n != 6) { // regular
      EXPECT_LT(loop.eigenbasis_conditions().at(n), 500) << "Loop, valence " << n;
    }
  }
}

namespace {

// the eigenvalues of the eigenbasis (what doc/tables/limit-eigenbasis.md
// shows), by decreasing modulus
std::vector<double> leading_eigenvalues(const std::map<std::size_t, std::vector<double>>& by_valence, int n)
{
  std::vector<double> lambda = by_valence.at(static_cast<std::size_t>(n));
  std::sort(lambda.begin(), lambda.end(), [](double a, double b) { return std::abs(a) > std::abs(b); });
  return lambda;
}

} // namespace

// K = 2n + 8 (Catmull-Clark) and n + 6 (Loop) eigenvalues, 1 the largest,
// then the subdominant pair of the closed forms: Catmull-Clark's (Doo and
// Sabin) and Loop's 3/8 + cos(2 pi / n) / 4; also at Loop's valence 3, where
// the basis is not used
TEST(LimitSurface, eigenbasis_eigenvalues_by_valence)
{
  const double pi = 3.14159265358979323846;
  for(int n : {3, 5, 8}) {
    const Mesh quads = refined_prism(n);
    const S::Limit_surface<Mesh> cc(quads);
    const Mesh triangles = refined_bipyramid(n);
    const S::Limit_surface<Mesh, S::Loop_mask<Mesh>> loop(triangles);
    for(const auto f : quads.faces())
      for(const auto& [u, v] : {std::make_pair(0.01, 0.02), {0.98, 0.03}, {0.97, 0.99}, {0.02, 0.96}})
        cc.evaluate(f, u, v);
    for(const auto f : triangles.faces())
      for(const auto& [u, v] : {std::make_pair(0.01, 0.02), {0.97, 0.01}, {0.02, 0.96}})
        loop.evaluate(f, u, v);
    const double c = std::cos(2 * pi / n);
    const double cc_subdominant = (5 + c + std::cos(pi / n) * std::sqrt(2 * (9 + c))) / 16;
    const std::vector<double> a = leading_eigenvalues(cc.eigenbasis_eigenvalues(), n);
    ASSERT_EQ(a.size(), static_cast<std::size_t>(2 * n + 8)) << "Catmull-Clark, valence " << n;
    EXPECT_NEAR(a[0], 1, 1e-12) << "Catmull-Clark, valence " << n;
    EXPECT_NEAR(a[1], cc_subdominant, 1e-12) << "Catmull-Clark, valence " << n;
    EXPECT_NEAR(a[2], cc_subdominant, 1e-12) << "Catmull-Clark, valence " << n;
    const std::vector<double> b = leading_eigenvalues(loop.eigenbasis_eigenvalues(), n);
    ASSERT_EQ(b.size(), static_cast<std::size_t>(n + 6)) << "Loop, valence " << n;
    EXPECT_NEAR(b[0], 1, 1e-12) << "Loop, valence " << n;
    EXPECT_NEAR(b[1], 3.0 / 8 + c / 4, 1e-9) << "Loop, valence " << n;
    EXPECT_NEAR(b[2], 3.0 / 8 + c / 4, 1e-9) << "Loop, valence " << n;
  }
}

// a parameter at a vertex of the local refinement that is not extraordinary
// (the centre of a cube's face, the middle of its edge) has derivatives: the
// refinement goes on there instead of taking the vertex's limit masks
TEST(LimitSurface, derivatives_at_ordinary_vertices_of_the_local_refinement)
{
  const Exact_mesh cube = testing_utils::prism<Exact_mesh>(4);
  const Mesh double_cube = testing_utils::prism<Mesh>(4);
  const S::Limit_surface<Exact_mesh> exact(cube);
  const S::Limit_surface<Mesh> stam(double_cube);
  for(const auto& [u, v] : {std::make_pair(0.5, 0.5), {0.5, 0.0}, {0.25, 0.5}}) {
    const S::Limit_sample s = exact.evaluate(*cube.faces().begin(), u, v);
    const S::Limit_sample t = stam.evaluate(*double_cube.faces().begin(), u, v);
    EXPECT_GT(s.du.squared_length(), 0.01) << u << " " << v;
    EXPECT_GT(s.dv.squared_length(), 0.01) << u << " " << v;
    EXPECT_LT(std::sqrt((s.position - t.position).squared_length()), 1e-14);
    EXPECT_LT(std::sqrt((s.du - t.du).squared_length()), 1e-13);
    EXPECT_LT(std::sqrt((s.dv - t.dv).squared_length()), 1e-13);
    EXPECT_LT(std::sqrt((s.normal - t.normal).squared_length()), 1e-13);
  }
}

/*
 * Limit stencils at locations: applied to the mesh's points they give what
 * evaluate() gives (exactly in an exact kernel: quads, sub-quads, Loop
 * triangles); applied to moved points, what an evaluator of the moved mesh
 * gives (double: the Stam eigenbasis path too).
 */
template <class M, class Mask>
void expect_stencils_to_evaluate(M mesh, const Mask& mask, double tolerance)
{
  using Surface = S::Limit_surface<M, Mask>;
  using Point = typename M::Point;
  constexpr bool quads = std::is_same_v<Mask, S::Catmull_clark_mask<M>>;
  std::vector<typename Surface::Location> locations;
  for(const auto f : mesh.faces()) {
    const int corners = static_cast<int>(mesh.degree(f));
    for(const auto& [u, v] : {std::make_pair(0.0, 0.0), {0.25, 0.5}, {0.0625, 0.125}, {0.5, 0.375}})
      locations.push_back({f, quads && corners != 4 ? corners - 1 : -1, u, v});
  }
  const auto compare = [&](const Surface& surface,
                           const S::Limit_location_stencils<typename CGAL::Kernel_traits<Point>::Kernel::FT>& tables) {
    std::vector<Point> points(mesh.points().begin(), mesh.points().end()), position, du, dv, duv;
    tables.position.apply(points, position);
    tables.du.apply(points, du);
    tables.dv.apply(points, dv);
    tables.duv.apply(points, duv);
    ASSERT_EQ(position.size(), locations.size());
    for(std::size_t i = 0; i < locations.size(); ++i) {
      const auto& at = locations[i];
      const S::Limit_sample s = [&] {
        if constexpr(quads)
          if(at.corner >= 0)
            return surface.evaluate(at.face, at.corner, at.u, at.v);
        return surface.evaluate(at.face, at.u, at.v);
      }();
      const auto as_vector = [](const Point& p) {
        return S::Limit_sample::Vector(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      };
      EXPECT_LE(std::sqrt((as_vector(position[i]) - (s.position - CGAL::ORIGIN)).squared_length()), tolerance) << i;
      EXPECT_LE(std::sqrt((as_vector(du[i]) - s.du).squared_length()), tolerance * 16) << i;
      EXPECT_LE(std::sqrt((as_vector(dv[i]) - s.dv).squared_length()), tolerance * 16) << i;
      EXPECT_LE(std::sqrt((as_vector(duv[i]) - s.duv).squared_length()), tolerance * 256) << i;
    }
  };
  const Surface surface(mesh, mask);
  const auto tables = surface.stencil_tables(locations);
  EXPECT_EQ(tables.position.number_of_stencils(), locations.size());
  compare(surface, tables);
  for(const auto v : mesh.vertices()) // moved control points, the same tables
    mesh.point(v) = mesh.point(v) + typename CGAL::Kernel_traits<Point>::Kernel::Vector_3(
                                      int(v.idx() % 3), int(v.idx() % 5) - 2, int(v.idx() % 2));
  compare(Surface(mesh, mask), tables);
}

TEST(LimitSurface, stencil_tables_re_evaluate_the_locations)
{
  expect_stencils_to_evaluate(testing_utils::mixed_box<Exact_mesh>(), S::Catmull_clark_mask<Exact_mesh>(), 0);
  expect_stencils_to_evaluate(testing_utils::bipyramid<Exact_mesh>(5), S::Loop_mask<Exact_mesh>(), 0);
  expect_stencils_to_evaluate(refined_prism(5), S::Catmull_clark_mask<Mesh>(), 1e-12);
  expect_stencils_to_evaluate(refined_bipyramid(5), S::Loop_mask<Mesh>(), 1e-12);
  const Mesh box = testing_utils::mixed_box<Mesh>();
  const S::Limit_surface<Mesh> surface(box);
  EXPECT_THROW(surface.stencil_tables({{*box.faces().begin(), -1, 2.0, 0.5}}), S::Bad_input);
}

// the midpoints of the edges of a triangle: from corner i to corner i+1
const std::pair<double, double> triangle_edge_midpoints[3] = {{0.5, 0}, {0.5, 0.5}, {0, 0.5}};

// whether the faces around the corners of f, put in a mesh of their own, pinch a vertex (two fans at it)
bool has_pinched_ring(const Mesh& mesh, Mesh::Face_index f)
{
  std::vector<Mesh::Face_index> ring;
  for(const auto corner : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    for(const auto g : CGAL::faces_around_target(mesh.halfedge(corner), mesh))
      if(std::find(ring.begin(), ring.end(), g) == ring.end())
        ring.push_back(g);
  Mesh copy;
  std::map<Mesh::Vertex_index, Mesh::Vertex_index> copied;
  for(const auto g : ring) {
    std::vector<Mesh::Vertex_index> corners;
    for(const auto w : CGAL::vertices_around_face(mesh.halfedge(g), mesh)) {
      if(!copied.count(w))
        copied[w] = copy.add_vertex(mesh.point(w));
      corners.push_back(copied[w]);
    }
    if(copy.add_face(corners) == Mesh::null_face())
      return true;
  }
  for(const auto v : copy.vertices()) {
    int border_fans = 0;
    for(const auto h : CGAL::halfedges_around_target(v, copy))
      border_fans += copy.is_border(h) ? 1 : 0;
    if(border_fans > 1)
      return true;
  }
  return false;
}

/*
 * A triangle torus with random edge flips (fixed seed, as the bench's
 * irregular tori) has faces whose 1-ring pinches a vertex beyond the
 * corners (reached from two corners through faces that share no edge
 * there): the local patch keeps a copy of it per fan, so every face is
 * evaluated, and the midpoint of every edge is the same point from both
 * of its faces.
 */
TEST(LimitSurface, loop_evaluates_faces_whose_ring_pinches_a_vertex)
{
  const int n = 24, m = 12;
  std::vector<K::Point_3> points;
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < n; ++i) {
      const double a = 2 * CGAL_PI * i / n, b = 2 * CGAL_PI * j / m;
      points.emplace_back((3 + std::cos(b)) * std::cos(a), (3 + std::cos(b)) * std::sin(a), std::sin(b));
    }
  const auto id = [&](int i, int j) { return (j % m) * n + (i % n); };
  Mesh mesh =
    testing_utils::mesh_of<Mesh>(points, testing_utils::lattice_faces(n, m, id, true, [](int, int) { return true; }));
  std::mt19937 random(7);
  for(int k = 0; k < 3000; ++k) {
    const Mesh::Halfedge_index h(static_cast<Mesh::size_type>(random() % mesh.number_of_halfedges()));
    const auto o = mesh.opposite(h);
    const auto c = mesh.target(mesh.next(h)), d = mesh.target(mesh.next(o));
    if(c == d || CGAL::halfedge(c, d, mesh).second || mesh.degree(mesh.source(h)) <= 3 ||
       mesh.degree(mesh.target(h)) <= 3 || mesh.degree(c) >= 9 || mesh.degree(d) >= 9)
      continue;
    CGAL::Euler::flip_edge(h, mesh);
  }
  int pinched = 0;
  for(const auto f : mesh.faces())
    pinched += has_pinched_ring(mesh, f) ? 1 : 0;
  ASSERT_GT(pinched, 0);
  const S::Limit_surface<Mesh, S::Loop_mask<Mesh>> surface(mesh);
  const double diagonal = 8;
  for(const auto f : mesh.faces()) {
    auto h = mesh.halfedge(f);
    for(int i = 0; i < 3; ++i) {
      h = mesh.next(h); // from corner i to corner i+1
      const auto g = mesh.face(mesh.opposite(h));
      int j = 0;
      for(auto k = mesh.next(mesh.halfedge(g)); k != mesh.opposite(h); k = mesh.next(k))
        ++j;
      const auto [u, v] = triangle_edge_midpoints[i];
      const auto [s, t] = triangle_edge_midpoints[j];
      const S::Limit_sample here = surface.evaluate(f, u, v), there = surface.evaluate(g, s, t);
      EXPECT_LT(std::sqrt((here.position - there.position).squared_length()), 1e-12 * diagonal);
      EXPECT_LT(std::sqrt((here.normal - there.normal).squared_length()), 1e-9);
    }
  }
}

/*
 * The evaluator keeps each face's refined neighbourhood (`cached_faces`):
 * a parameter evaluated through the kept children gives, bit for bit, what
 * a fresh refinement gives (cached_faces = 0), whatever was evaluated
 * before, and also when faces are dropped as others come (cached_faces =
 * 1). Parameters at corners, near them, on sub-quads and anywhere, on
 * faces with several extraordinary corners, Stam patches and Loop's
 * defective valence 3.
 */
template <class Mask>
void expect_kept_children_to_agree(const Mesh& mesh)
{
  using Surface = S::Limit_surface<Mesh, Mask>;
  std::vector<typename Surface::Location> locations;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(0, 1);
  const bool quads = std::is_same_v<Mask, S::Catmull_clark_mask<Mesh>>;
  for(const auto f : mesh.faces()) {
    const int corners = static_cast<int>(mesh.degree(f));
    const int sub_quads = quads && corners != 4 ? corners : 1;
    for(int corner = 0; corner < sub_quads; ++corner)
      for(const auto& [u, v] : {std::pair{0.0, 0.0},
                                {1.0, 0.0},
                                {0.0, 1.0},
                                {1e-5, 3e-6},
                                {0.25, 0.5},
                                {uniform(random) / 2, uniform(random) / 2}}) {
        locations.push_back({f, sub_quads > 1 ? corner : -1, u, v});
      }
  }
  std::shuffle(locations.begin(), locations.end(), random);
  Surface fresh(mesh), kept(mesh), churning(mesh);
  fresh.cached_faces = 0;
  churning.cached_faces = 1;
  const auto evaluate = [](const Surface& surface, const typename Surface::Location& at) {
    if constexpr(std::is_same_v<Mask, S::Catmull_clark_mask<Mesh>>)
      if(at.corner >= 0)
        return surface.evaluate(at.face, at.corner, at.u, at.v);
    return surface.evaluate(at.face, at.u, at.v);
  };
  for(int pass = 0; pass < 2; ++pass)
    for(const auto& at : locations) {
      const S::Limit_sample a = evaluate(fresh, at), b = evaluate(kept, at), c = evaluate(churning, at);
      for(const S::Limit_sample& s : {b, c}) {
        EXPECT_EQ(a.position, s.position) << "face " << at.face << " (" << at.u << ", " << at.v << ")";
        EXPECT_EQ(a.du, s.du);
        EXPECT_EQ(a.dv, s.dv);
        EXPECT_EQ(a.duu, s.duu);
        EXPECT_EQ(a.duv, s.duv);
        EXPECT_EQ(a.dvv, s.dvv);
        EXPECT_EQ(a.normal, s.normal);
      }
    }
}

// Without the second derivatives (second_derivatives = false) the position,
// the first derivatives and the normal are bit for bit those with them, and
// the second derivatives zero: regular patches, Stam patches (Catmull-Clark
// valence 3 and 5, Loop valence 4 and 5), Loop's valence 3 by powers, and
// n-gons' sub-quads refined locally
TEST(LimitSurface, without_second_derivatives_the_rest_is_the_same)
{
  Mesh prism = testing_utils::prism<Mesh>(5);
  S::catmull_clark_subdivision(prism, S::parameters::number_of_iterations(1));
  Mesh bipyramid = testing_utils::bipyramid<Mesh>(5);
  S::loop_subdivision(bipyramid, S::parameters::number_of_iterations(1));
  const auto expect_same = [](const auto& with, auto without, const auto& evaluate) {
    without.second_derivatives = false;
    std::size_t nonzero_second = 0, evaluations = 0;
    const Mesh& mesh = with.mesh();
    for(const auto f : mesh.faces())
      for(const auto& [u, v] : {std::pair{0.25, 0.125}, {1e-3, 2e-3}, {0.0, 0.0}, {0.3, 0.6}}) {
        const S::Limit_sample a = evaluate(with, f, u, v), b = evaluate(without, f, u, v);
        EXPECT_EQ(a.position, b.position);
        EXPECT_EQ(a.du, b.du);
        EXPECT_EQ(a.dv, b.dv);
        EXPECT_EQ(a.normal, b.normal);
        EXPECT_EQ(b.duu, S::Limit_sample::Vector(0, 0, 0));
        EXPECT_EQ(b.duv, S::Limit_sample::Vector(0, 0, 0));
        EXPECT_EQ(b.dvv, S::Limit_sample::Vector(0, 0, 0));
        nonzero_second += a.duu != S::Limit_sample::Vector(0, 0, 0) ? 1 : 0;
        ++evaluations;
      }
    EXPECT_GT(nonzero_second, evaluations / 2);
  };
  const auto quad = [](const auto& surface, Mesh::Face_index f, double u, double v) {
    return surface.evaluate(f, u, v);
  };
  const S::Limit_surface<Mesh> cc(prism);
  expect_same(cc, cc, quad);
  const S::Limit_surface<Mesh, S::Loop_mask<Mesh>> loop(bipyramid);
  expect_same(loop, loop, quad);
  const Mesh tetrahedron = testing_utils::tetrahedron<Mesh>();
  const S::Limit_surface<Mesh, S::Loop_mask<Mesh>> valence_3(tetrahedron);
  expect_same(valence_3, valence_3, quad);
  const Mesh box = testing_utils::mixed_box<Mesh>();
  const S::Limit_surface<Mesh> mixed(box);
  expect_same(mixed, mixed, [](const auto& surface, Mesh::Face_index f, double u, double v) {
    return surface.corners_of(f) == 4 ? surface.evaluate(f, u, v) : surface.evaluate(f, 1, u, v);
  });
}

TEST(LimitSurface, kept_children_give_the_values_of_a_fresh_refinement)
{
  expect_kept_children_to_agree<S::Catmull_clark_mask<Mesh>>(testing_utils::mixed_box<Mesh>());
  expect_kept_children_to_agree<S::Catmull_clark_mask<Mesh>>(refined_prism(5));
  for(const int n : {3, 5}) {
    const Mesh triangles = testing_utils::bipyramid<Mesh>(n);
    expect_kept_children_to_agree<S::Loop_mask<Mesh>>(triangles);
  }
}

/*
 * Near an extraordinary vertex, Stam's second derivatives in double keep
 * their digits: the constant mode, whose derivative weights sum to zero
 * only up to rounding, is left out (times 4^level it made the curvature
 * next to a vertex of valence 3 wrong by 13% at 2^-20). The Gaussian
 * curvature at 2^-20 from vertices of valence 3 and 5 against the exact
 * evaluator's, whose local refinement goes down the 20 levels.
 */
TEST(LimitSurface, curvature_next_to_an_extraordinary_vertex_keeps_its_digits)
{
  for(const int n : {3, 5}) {
    Mesh quads = refined_prism(n);
    Exact_mesh exact = refined_prism<Exact_mesh>(n);
    // a curved surface: lift the points off the prism's planes
    for(const auto v : quads.vertices()) {
      const K::Point_3 p = quads.point(v);
      quads.point(v) = K::Point_3(p.x(), p.y(), p.z() + (p.x() * p.x() + 2 * p.y() * p.y()) / 8);
      const KE::Point_3 q = exact.point(Exact_mesh::Vertex_index(std::uint32_t(v)));
      exact.point(Exact_mesh::Vertex_index(std::uint32_t(v))) =
        KE::Point_3(q.x(), q.y(), q.z() + (q.x() * q.x() + 2 * q.y() * q.y()) / 8);
    }
    const S::Limit_surface<Mesh> surface(quads);
    const S::Limit_surface<Exact_mesh> truth(exact);
    int checked = 0;
    const double a = std::ldexp(0.3, -20), b = std::ldexp(0.7, -20);
    for(const auto f : quads.faces()) {
      int i = 0; // the corner of valence n, if any, and (u, v) next to it
      for(auto h = quads.halfedge(f); quads.degree(quads.target(h)) != std::size_t(n) && i < 4; h = quads.next(h))
        ++i;
      if(i == 4 || checked == 2)
        continue;
      const double u = i == 0 || i == 3 ? a : 1 - a, v = i < 2 ? b : 1 - b;
      const double k = S::gaussian_curvature(surface.evaluate(f, u, v));
      const double k_exact = S::gaussian_curvature(truth.evaluate(Exact_mesh::Face_index(std::uint32_t(f)), u, v));
      EXPECT_NEAR(k, k_exact, 1e-6 * std::abs(k_exact)) << "valence " << n << ", face " << f;
      ++checked;
    }
    EXPECT_EQ(checked, 2) << "valence " << n;
  }
}

// Evaluations from several threads at once share the kept trees (the walk
// down under the evaluator's lock, the leaf outside it) and give the values
// one thread gives, bit for bit, also while faces are dropped.
TEST(LimitSurface, evaluations_from_several_threads_give_the_values_of_one)
{
  const Mesh mesh = testing_utils::mixed_box<Mesh>();
  std::vector<std::tuple<Mesh::Face_index, int, double, double>> locations;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(0, 1);
  for(int k = 0; k < 400; ++k) {
    const auto f = Mesh::Face_index(static_cast<std::uint32_t>(random() % mesh.number_of_faces()));
    const int corners = static_cast<int>(mesh.degree(f));
    locations.emplace_back(f, corners == 4 ? -1 : int(random() % std::uint32_t(corners)), uniform(random),
                           uniform(random));
  }
  const auto evaluate = [&](const S::Limit_surface<Mesh>& surface, std::size_t i) {
    const auto& [f, corner, u, v] = locations[i];
    return corner < 0 ? surface.evaluate(f, u, v) : surface.evaluate(f, corner, u, v);
  };
  const S::Limit_surface<Mesh> alone(mesh);
  std::vector<S::Limit_sample> expected;
  for(std::size_t i = 0; i < locations.size(); ++i)
    expected.push_back(evaluate(alone, i));
  for(const std::size_t kept : {std::size_t(4096), std::size_t(2)}) {
    S::Limit_surface<Mesh> shared(mesh);
    shared.cached_faces = kept;
    std::vector<S::Limit_sample> found[4];
    std::vector<std::thread> threads;
    for(int t = 0; t < 4; ++t)
      threads.emplace_back([&, t] {
        for(std::size_t i = 0; i < locations.size(); ++i) // each thread in its own order
          found[t].push_back(evaluate(shared, (i * (2 * std::size_t(t) + 1)) % locations.size()));
      });
    for(std::thread& thread : threads)
      thread.join();
    for(int t = 0; t < 4; ++t)
      for(std::size_t i = 0; i < locations.size(); ++i) {
        const S::Limit_sample& a = expected[(i * (2 * std::size_t(t) + 1)) % locations.size()];
        EXPECT_EQ(a.position, found[t][i].position) << "thread " << t << ", kept " << kept;
        EXPECT_EQ(a.du, found[t][i].du);
        EXPECT_EQ(a.dvv, found[t][i].dvv);
        EXPECT_EQ(a.normal, found[t][i].normal);
      }
  }
}

/*
 * The curvatures of a sample: the bicubic B-spline of control points on
 * the paraboloid z = x^2 + y^2 is that paraboloid (raised by 2/3), whose
 * Gaussian curvature is 4 / W^2 and mean curvature 2 (1 + 2 x^2 + 2 y^2) /
 * W^(3/2), W = 1 + 4 x^2 + 4 y^2, towards +z; at an extraordinary vertex,
 * whose derivatives are zero, neither is a number.
 */
TEST(LimitSurface, curvatures_of_a_paraboloid)
{
  const Mesh paraboloid = testing_utils::grid<Mesh>(
    6, 6, [](int i, int j) { return K::Point_3(i - 3, j - 3, (i - 3) * (i - 3) + (j - 3) * (j - 3)); }, false);
  const S::Limit_surface<Mesh> surface(paraboloid);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::size_t checked = 0;
  for(const auto f : paraboloid.faces()) {
    const auto corner = paraboloid.point(paraboloid.target(paraboloid.halfedge(f)));
    if(std::abs(corner.x()) > 1.5 || std::abs(corner.y()) > 1.5)
      continue; // the regular patches only: every corner's ring inside the grid
    const S::Limit_sample s = surface.evaluate(f, uniform(random), uniform(random));
    const double x = s.position.x(), y = s.position.y(), W = 1 + 4 * x * x + 4 * y * y;
    EXPECT_NEAR(s.position.z(), x * x + y * y + 2.0 / 3, 1e-12);
    const double towards_normal = s.normal.z() > 0 ? 1 : -1;
    EXPECT_NEAR(S::gaussian_curvature(s), 4 / (W * W), 1e-12);
    EXPECT_NEAR(S::mean_curvature(s), towards_normal * 2 * (1 + 2 * x * x + 2 * y * y) / std::pow(W, 1.5), 1e-12);
    ++checked;
  }
  EXPECT_GE(checked, 9u);
  const Mesh cube = testing_utils::cube<Mesh>();
  const S::Limit_sample at_vertex = S::Limit_surface<Mesh>(cube).evaluate(*cube.faces().begin(), 0, 0);
  EXPECT_TRUE(std::isnan(S::gaussian_curvature(at_vertex)));
  EXPECT_TRUE(std::isnan(S::mean_curvature(at_vertex)));
}
