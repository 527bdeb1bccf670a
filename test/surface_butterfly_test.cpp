// Butterfly, modified butterfly and linear triangle subdivision: regular and
// extraordinary weights, border rules, kernels, bad input. The properties
// every scheme has (weights summing to one, counts, affine invariance,
// planarity, Polyhedron_3) are in surface_properties.h.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include "mesh_builders.h"
#include "mesh_test_utils.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace S = CGAL::Subdiv;

using KE = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using FT = KE::FT;
using P = KE::Point_3;
using EMesh = CGAL::Surface_mesh<P>;
using V = EMesh::Vertex_index;
using Recorder = S::Stencil<V, FT>;

using K = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

using testing_utils::position_mismatch;
using testing_utils::shared_mesh;
using testing_utils::test_mesh;

namespace {

// ---------------------------------------------------------------- meshes

// two apexes of valence k over a ring of k vertices of valence 4 (closed),
// generic rational points
EMesh bipyramid(int k)
{
  testing_utils::Rationals r;
  const P top(r.next<FT>(), r.next<FT>(), FT(3));
  const P bottom(r.next<FT>(), r.next<FT>(), FT(-3));
  return testing_utils::bipyramid<EMesh>(
    k, top, bottom, [&](int i) { return P(FT(i) + r.next<FT>(), FT(i * i % 5) + r.next<FT>(), r.next<FT>()); });
}

// one interior vertex of valence k (vertex 0) and a border loop of k vertices
EMesh fan(int k)
{
  testing_utils::Rationals r;
  const P centre(r.next<FT>(), r.next<FT>(), r.next<FT>());
  return testing_utils::closed_fan<EMesh>(
    k, centre, [&](int i) { return P(FT(i) + r.next<FT>(), FT(i * i % 7) + r.next<FT>(), r.next<FT>()); });
}

// the lattice (i, j), 0 <= i <= n, 0 <= j <= m, cut by the diagonals
// (i, j)-(i+1, j+1): every interior vertex has valence 6 (a regular mesh)
struct Grid
{
  int n, m;
  EMesh mesh;
  V at(int i, int j) const { return testing_utils::grid_vertex<EMesh>(n, i, j); }
};

Grid grid(int n, int m, const std::function<P(int, int)>& point)
{
  return Grid{n, m, testing_utils::grid<EMesh>(n, m, point, true, testing_utils::Diagonal::ascending)};
}

Grid random_height_grid(int n, int m)
{
  testing_utils::Rationals r;
  return grid(n, m, [&](int i, int j) { return P(FT(i), FT(j), r.next<FT>()); });
}

// --------------------------------------------------------------- stencils

template <class Mask>
Recorder edge_stencil(const Mask& mask, const EMesh& mesh, EMesh::Halfedge_index h)
{
  Recorder s;
  mask.edge_node(S::edge_view(mask, mesh, h), s);
  return s;
}

template <class Mask>
Recorder edge_stencil(const Mask& mask, const EMesh& mesh, V a, V b)
{
  const auto h = mesh.halfedge(a, b);
  EXPECT_NE(h, EMesh::null_halfedge());
  return edge_stencil(mask, mesh, h);
}

bool same_stencil(const Recorder& x, const Recorder& y)
{
  for(const auto& term : x.terms())
    if(term.second != y.weight(term.first))
      return false;
  for(const auto& term : y.terms())
    if(term.second != x.weight(term.first))
      return false;
  return true;
}

std::string describe(const Recorder& s)
{
  std::ostringstream out;
  for(const auto& term : s.terms())
    out << " v" << term.first.idx() << ":" << term.second;
  return out.str();
}

// ---------------------------------------------------------------- helpers

// the border loop through vertex `start`, in the direction of its border halfedge
template <class M>
std::vector<typename M::Point> border_loop(const M& mesh, typename M::Vertex_index start)
{
  typename M::Halfedge_index first = M::null_halfedge();
  for(auto h : halfedges(mesh))
    if(mesh.is_border(h) && mesh.source(h) == start)
      first = h;
  std::vector<typename M::Point> loop;
  auto h = first;
  do {
    loop.push_back(mesh.point(mesh.source(h)));
    h = mesh.next(h);
  } while(h != first);
  return loop;
}

} // namespace

// =================================================================== tests

TEST(Butterfly, regular_edge_is_the_hand_formula_one_half_one_eighth_minus_one_sixteenth)
{
  const Grid g = random_height_grid(7, 7);
  EMesh mesh = g.mesh;
  S::butterfly_subdivision(mesh);
  const int i = 3, j = 3; // the edge (3,3)-(4,3)
  const auto z = [&](int a, int b) -> FT { return g.mesh.point(g.at(a, b)).z(); };
  const FT expected = (z(i, j) + z(i + 1, j)) / FT(2) + (z(i + 1, j + 1) + z(i, j - 1)) / FT(8) -
                      (z(i + 2, j + 1) + z(i, j + 1) + z(i - 1, j - 1) + z(i + 1, j - 1)) / FT(16);
  const auto e = edge(g.mesh.halfedge(g.at(i, j), g.at(i + 1, j)), g.mesh);
  const P& point = mesh.point(V(static_cast<EMesh::size_type>(num_vertices(g.mesh) + e.idx())));
  EXPECT_EQ(point, P(FT(7) / FT(2), FT(3), expected));
}

TEST(Butterfly, reproduces_cubics_on_a_regular_mesh_and_modified_butterfly_equals_it_at_valence_6)
{
  // z = cubic in (x, y); edges whose ends are both interior have the full stencil
  const auto cubic = [](const FT& x, const FT& y) -> FT {
    return FT(2) * x * x * x - x * x * y + FT(3) * x * y * y / FT(4) - y * y * y / FT(5) + x * y - FT(7) * y + FT(1);
  };
  const Grid g = grid(8, 8, [&](int i, int j) { return P(FT(i), FT(j), cubic(FT(i), FT(j))); });
  EMesh butterfly = g.mesh, modified = g.mesh, ten_point = g.mesh;
  S::butterfly_subdivision(butterfly);
  S::modified_butterfly_subdivision(modified);
  S::subdivide(ten_point, S::Modified_butterfly_mask<EMesh>(FT(1) / FT(32)));
  int regular_edges = 0;
  for(auto e : edges(g.mesh)) {
    const V a = source(halfedge(e, g.mesh), g.mesh), b = target(halfedge(e, g.mesh), g.mesh);
    if(g.mesh.is_border(a) || g.mesh.is_border(b))
      continue;
    ++regular_edges;
    const V new_vertex(static_cast<EMesh::size_type>(num_vertices(g.mesh) + e.idx()));
    const P mid = CGAL::midpoint(g.mesh.point(a), g.mesh.point(b));
    const P on_cubic(mid.x(), mid.y(), cubic(mid.x(), mid.y()));
    EXPECT_EQ(butterfly.point(new_vertex), on_cubic) << "edge " << e.idx();
    EXPECT_EQ(modified.point(new_vertex), butterfly.point(new_vertex)) << "edge " << e.idx();
    EXPECT_EQ(ten_point.point(new_vertex), on_cubic) << "edge " << e.idx();
  }
  EXPECT_EQ(regular_edges, 42 + 42 + 36); // between the 7 x 7 interior vertices: rows, columns, diagonals
}

TEST(Modified_butterfly, extraordinary_weights_are_the_papers)
{
  using W = S::Modified_butterfly_weights<FT>;
  const W three(3), four(4), six(6);
  EXPECT_EQ(three.ring, (std::vector<FT>{FT(5) / FT(12), FT(-1) / FT(12), FT(-1) / FT(12)}));
  EXPECT_EQ(three.centre, FT(3) / FT(4));
  EXPECT_EQ(four.ring, (std::vector<FT>{FT(3) / FT(8), FT(0), FT(-1) / FT(8), FT(0)}));
  EXPECT_EQ(four.centre, FT(3) / FT(4));
  // valence 6 (the formula; the mask uses the butterfly there): rational
  EXPECT_EQ(six.ring, (std::vector<FT>{FT(7) / FT(24), FT(1) / FT(12), FT(-1) / FT(12), FT(-1) / FT(24),
                                       FT(-1) / FT(12), FT(1) / FT(12)}));
  EXPECT_EQ(six.centre, FT(3) / FT(4));
  for(int k : {3, 4, 6})
    EXPECT_TRUE(W::is_exact(k)) << k;
  for(int k = 5; k <= 40; ++k) {
    if(k == 6)
      continue;
    EXPECT_FALSE(W::is_exact(k)) << k;
    const W weights(k);
    FT sum = weights.centre;
    for(int j = 0; j < k; ++j) {
      sum += weights.ring[j];
      EXPECT_EQ(weights.ring[j], weights.ring[(k - j) % k]) << "symmetric, k = " << k;
      const double pi = 3.14159265358979323846;
      const double formula = (0.25 + std::cos(2 * pi * j / k) + 0.5 * std::cos(4 * pi * j / k)) / k;
      EXPECT_NEAR(CGAL::to_double(weights.ring[j]), formula, 1e-15) << k << " " << j;
    }
    EXPECT_EQ(sum, FT(1)) << k;
    EXPECT_NEAR(CGAL::to_double(weights.centre), 0.75, 1e-15) << k;
  }
}

TEST(Modified_butterfly, edge_stencils_at_extraordinary_ends)
{
  using W = S::Modified_butterfly_weights<FT>;
  const S::Modified_butterfly_mask<EMesh> mask;
  for(int k = 3; k <= 12; ++k) {
    // a fan: the edge from the interior apex (valence k != 6) to a border
    // vertex uses the apex's stencil alone; at valence 6 the reflected butterfly
    const EMesh f = fan(k);
    const W weights(k);
    const V apex(0), first(1);
    const Recorder s = edge_stencil(mask, f, apex, first);
    if(k == 6) {
      EXPECT_TRUE(same_stencil(s, edge_stencil(S::Butterfly_mask<EMesh>(), f, apex, first))) << describe(s);
    } else {
      EXPECT_EQ(s.weight(apex), weights.centre) << k;
      for(int j = 0; j < k; ++j)
        EXPECT_EQ(s.weight(V(static_cast<EMesh::size_type>(1 + j))), weights.ring[j]) << k << " " << j;
    }

    // a bipyramid: apex (valence k) to a ring vertex (valence 4): the average
    // of the two stencils (only the ring vertex's when the apex is regular, k = 6)
    const EMesh b = bipyramid(k);
    const V top(0), bottom(1), ring0(2);
    const Recorder t = edge_stencil(mask, b, top, ring0);
    Recorder expected;
    const FT apex_share = k == 6 ? FT(0) : FT(1) / FT(2);
    const FT ring_share = k == 6 ? FT(1) : FT(1) / FT(2);
    expected.add(top, apex_share * weights.centre);
    for(int j = 0; j < k; ++j) // ring0, ring1, ... around the top
      expected.add(V(static_cast<EMesh::size_type>(2 + j)), apex_share * weights.ring[j]);
    const W four(4); // around ring0: top, ring1, bottom, ring_{k-1}
    expected.add(ring0, ring_share * four.centre);
    expected.add(top, ring_share * four.ring[0]);
    expected.add(V(3), ring_share * four.ring[1]);
    expected.add(bottom, ring_share * four.ring[2]);
    expected.add(V(static_cast<EMesh::size_type>(2 + k - 1)), ring_share * four.ring[3]);
    EXPECT_TRUE(same_stencil(t, expected)) << k << ":" << describe(t) << " vs" << describe(expected);
  }
}

TEST(Butterfly, missing_outer_vertex_is_reflected_through_the_border_edge)
{
  // edge (2,0)-(3,1) of a grid: the outer vertex across the border edge
  // (2,0)-(3,0) is missing; the reflection (2,0) + (3,0) - (3,1) moves -1/16
  // onto those three vertices
  const Grid g = random_height_grid(5, 3);
  const S::Butterfly_mask<EMesh> mask;
  const Recorder s = edge_stencil(mask, g.mesh, g.at(2, 0), g.at(3, 1));
  Recorder expected;
  expected.add(g.at(2, 0), FT(7) / FT(16));
  expected.add(g.at(3, 1), FT(9) / FT(16));
  expected.add(g.at(3, 0), FT(1) / FT(16));
  expected.add(g.at(2, 1), FT(1) / FT(8));
  expected.add(g.at(4, 1), FT(-1) / FT(16));
  expected.add(g.at(3, 2), FT(-1) / FT(16));
  expected.add(g.at(1, 0), FT(-1) / FT(16));
  EXPECT_TRUE(same_stencil(s, expected)) << describe(s);

  // on a linear function the reflected stencil still gives the midpoint
  const Grid linear = grid(5, 3, [](int i, int j) { return P(FT(i), FT(j), FT(3 * i - 2 * j) / FT(7)); });
  EMesh mesh = linear.mesh;
  S::butterfly_subdivision(mesh);
  const auto e = edge(linear.mesh.halfedge(linear.at(2, 0), linear.at(3, 1)), linear.mesh);
  EXPECT_EQ(mesh.point(V(static_cast<EMesh::size_type>(num_vertices(linear.mesh) + e.idx()))),
            P(FT(5) / FT(2), FT(1) / FT(2), FT(13) / FT(14)));
}

TEST(Butterfly_family, every_border_loop_is_refined_by_the_four_point_curve_scheme)
{
  const Grid g = random_height_grid(5, 4);
  const auto check = [&](const auto& mask, const FT& w) {
    EMesh mesh = g.mesh;
    S::subdivide(mesh, mask, CGAL::parameters::number_of_iterations(2));
    const std::vector<P> expected = S::refine_polyline(border_loop(g.mesh, V(0)), S::Four_point_scheme<FT>(w),
                                                       S::parameters::closed(true).number_of_iterations(2));
    EXPECT_EQ(border_loop(mesh, V(0)), expected) << mask.name() << ", w = " << w;
  };
  check(S::Butterfly_mask<EMesh>(), FT(1) / FT(16));
  check(S::Butterfly_mask<EMesh>(FT(1) / FT(10)), FT(1) / FT(10)); // the tension reaches the border
  check(S::Modified_butterfly_mask<EMesh>(), FT(1) / FT(16));
  check(S::Modified_butterfly_mask<EMesh>(FT(-1) / FT(32)), FT(1) / FT(16));
  check(S::Linear_triangle_mask<EMesh>(), FT(0));
}

TEST(Linear_triangle, refined_mesh_lies_on_the_old_faces_with_exact_midpoints)
{
  for(const EMesh& input : {bipyramid(5), random_height_grid(3, 3).mesh, fan(6)}) {
    EMesh mesh = input;
    S::linear_triangle_subdivision(mesh);
    for(V v : vertices(input))
      EXPECT_EQ(mesh.point(v), input.point(v));
    for(auto e : edges(input)) {
      const V new_vertex(static_cast<EMesh::size_type>(num_vertices(input) + e.idx()));
      EXPECT_EQ(mesh.point(new_vertex), CGAL::midpoint(input.point(source(halfedge(e, input), input)),
                                                       input.point(target(halfedge(e, input), input))));
    }
    for(auto f : faces(mesh)) { // new face f lies in old face f / 4
      const auto parent = EMesh::Face_index(static_cast<EMesh::size_type>(f.idx() / 4));
      const auto h = halfedge(parent, input);
      const KE::Triangle_3 old(input.point(source(h, input)), input.point(target(h, input)),
                               input.point(target(next(h, input), input)));
      for(V v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        EXPECT_TRUE(old.has_on(mesh.point(v))) << "face " << f.idx();
    }
  }
}

TEST(Butterfly_family, tension_out_of_range_is_refused)
{
  using testing_utils::bad_input_message;
  EXPECT_NE(bad_input_message([] { S::Butterfly_mask<EMesh>(FT(-1) / FT(100)); }).find("0 <= w < 1/4"),
            std::string::npos);
  EXPECT_NE(bad_input_message([] { S::Butterfly_mask<EMesh>(FT(1) / FT(4)); }).find("tension"), std::string::npos);
  EXPECT_EQ(bad_input_message([] { S::Butterfly_mask<EMesh>(FT(0)); }), "no exception");
  EXPECT_NE(bad_input_message([] { S::Modified_butterfly_mask<EMesh>(FT(1) / FT(8)); }).find("-1/16 <= w <= 1/16"),
            std::string::npos);
}

TEST(Butterfly_family, quad_mesh_is_refused_and_left_unchanged)
{
  Mesh quad;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh("cgal/cube_quad.off"), quad));
  const std::vector<K::Point_3> before = testing_utils::double_points(quad);
  const std::size_t faces_before = num_faces(quad);
  using Call = std::function<void()>;
  for(const auto& [name, call] : std::vector<std::pair<std::string, Call>>{
        {"butterfly", [&] { S::butterfly_subdivision(quad); }},
        {"modified butterfly", [&] { S::modified_butterfly_subdivision(quad); }},
        {"linear triangle", [&] { S::linear_triangle_subdivision(quad); }}}) {
    const std::string message = testing_utils::bad_input_message(call);
    EXPECT_EQ(message.rfind(name + " needs a mesh whose faces all have 3 vertices; face 0 has 4", 0), 0u) << message;
    EXPECT_EQ(num_faces(quad), faces_before);
    EXPECT_EQ(testing_utils::double_points(quad), before);
  }
}

TEST(Butterfly_family, surface_mesh_polyhedron_and_epeck_agree)
{
  using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
  const std::string name = test_mesh("cgal/patch-23.off"); // a border, valences 2 to 8
  CGAL::Polyhedron_3<K> poly;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(name, poly));
  CGAL::Surface_mesh<Epeck::Point_3> exact;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(name, exact));
  Mesh sm;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(name, sm));
  for(int scheme = 0; scheme < 3; ++scheme) {
    auto p = poly;
    auto e = exact;
    auto s = sm;
    const auto run = [scheme](auto& mesh, int levels) {
      const auto np = CGAL::parameters::number_of_iterations(levels);
      if(scheme == 0)
        S::butterfly_subdivision(mesh, np);
      else if(scheme == 1)
        S::modified_butterfly_subdivision(mesh, np);
      else
        S::linear_triangle_subdivision(mesh, np);
    };
    run(p, 2);
    run(s, 2);
    EXPECT_TRUE(p.is_valid()) << scheme;
    EXPECT_EQ(num_vertices(p), num_vertices(s)) << scheme;
    EXPECT_LT(position_mismatch(p, s), 1e-14) << scheme;
    Mesh s1 = sm;
    run(s1, 1);
    run(e, 1);
    EXPECT_EQ(num_faces(e), 4 * num_faces(sm)) << scheme;
    EXPECT_LT(position_mismatch(e, s1), 1e-14) << scheme;
  }
}

namespace {

void expect_two_valid_levels(const std::string& path)
{
  for(int scheme = 0; scheme < 3; ++scheme) {
    Mesh mesh;
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(path, mesh)) << path;
    const std::size_t v = num_vertices(mesh), e = num_edges(mesh), f = num_faces(mesh);
    const auto np = CGAL::parameters::number_of_iterations(2);
    if(scheme == 0)
      S::butterfly_subdivision(mesh, np);
    else if(scheme == 1)
      S::modified_butterfly_subdivision(mesh, np);
    else
      S::linear_triangle_subdivision(mesh, np);
    EXPECT_TRUE(mesh.is_valid(false)) << path << " " << scheme;
    EXPECT_EQ(num_faces(mesh), 16 * f) << path;
    EXPECT_EQ(num_vertices(mesh), v + e + (2 * e + 3 * f)) << path; // level 2 adds one per level-1 edge
    for(auto w : vertices(mesh))
      EXPECT_TRUE(std::isfinite(mesh.point(w).x()));
  }
}

} // namespace

TEST(Butterfly_family, meshes_with_borders_run_two_levels_and_stay_valid)
{
  for(const std::string name : {"cgal/corner_tris_with_hole.off", "cgal/patch-23.off"})
    expect_two_valid_levels(test_mesh(name));
}

TEST(Butterfly_family, larger_shared_meshes_run_two_levels_and_stay_valid)
{
  SUBDIV_REQUIRE_SHARED_DATA();
  for(const std::string name : {"cgal/mesh_with_border.off", "cgal/elephant-with-holes.off", "cgal/elephant.off"})
    expect_two_valid_levels(shared_mesh(name));
}

// ---- creases (sharpness tags): infinitely sharp edges as borders ----------

namespace {

// a 6 x 6 triangle grid at generic rational heights, with the crease of its
// row j = 3 from i = 1 to i = 5 (4 infinitely sharp edges, ending at two
// darts) in the map "e:sharpness"
EMesh creased_grid(const std::function<FT(int, int)>& height)
{
  EMesh mesh = testing_utils::grid<EMesh>(
    6, 6, [&](int i, int j) { return P(i, j, height(i, j)); }, true);
  auto sharpness = mesh.add_property_map<EMesh::Edge_index, FT>("e:sharpness", FT(0)).first;
  for(int i = 1; i < 5; ++i) {
    const auto h =
      mesh.halfedge(testing_utils::grid_vertex<EMesh>(6, i, 3), testing_utils::grid_vertex<EMesh>(6, i + 1, 3));
    sharpness[mesh.edge(h)] = FT(10);
  }
  return mesh;
}

FT grid_height(int i, int j)
{
  return FT((i * 7 + j * 5) % 11) / FT(8) - FT(j * j) / FT(16);
}

template <class Mask>
void refine_creased(EMesh& mesh, int levels = 1)
{
  S::subdivide(mesh, Mask(),
               S::parameters::number_of_iterations(levels).edge_sharpness_map(
                 mesh.property_map<EMesh::Edge_index, FT>("e:sharpness").first));
}

} // namespace

// both butterflies (the modified one with its four-point rule of 1/16, the
// butterfly's default tension)
template <class Mask>
class Butterfly_creases : public ::testing::Test
{};
using Crease_masks = ::testing::Types<S::Butterfly_mask<EMesh>, S::Modified_butterfly_mask<EMesh>>;
TYPED_TEST_SUITE(Butterfly_creases, Crease_masks);

// The crease is refined by the four-point curve scheme alone, the polyline
// continued by point reflection at its ends (End_rule::keep_ends): its new
// points are that curve's, exactly, in rationals.
TYPED_TEST(Butterfly_creases, crease_is_the_four_point_curve_with_reflected_ends)
{
  EMesh mesh = creased_grid(grid_height);
  std::vector<P> crease;
  for(int i = 1; i <= 5; ++i)
    crease.push_back(mesh.point(testing_utils::grid_vertex<EMesh>(6, i, 3)));
  refine_creased<TypeParam>(mesh);
  const std::vector<P> curve = S::refine_polyline(
    crease, S::Four_point_scheme<FT>(), S::parameters::number_of_iterations(1).end_rule(S::End_rule::keep_ends));
  ASSERT_EQ(curve.size(), 9u);
  const auto sharpness = mesh.property_map<EMesh::Edge_index, FT>("e:sharpness").first;
  for(std::size_t k = 1; k < curve.size(); k += 2) { // the new points, each between two sharp halves
    std::size_t found = 0;
    for(auto v : vertices(mesh))
      if(mesh.point(v) == curve[k]) {
        ++found;
        int sharp_halves = 0;
        for(auto h : CGAL::halfedges_around_target(v, mesh))
          sharp_halves += sharpness[mesh.edge(h)] == FT(10) ? 1 : 0;
        EXPECT_EQ(sharp_halves, 2) << "curve point " << k;
      }
    EXPECT_EQ(found, 1u) << "curve point " << k;
  }
  // without the tags the edge points on the crease are the butterfly's, not the curve's (3 of 4 differ)
  EMesh untagged = creased_grid(grid_height);
  S::subdivide(untagged, TypeParam());
  std::size_t on_curve = 0;
  for(auto v : vertices(untagged))
    for(std::size_t k = 1; k < curve.size(); k += 2)
      on_curve += untagged.point(v) == curve[k] ? 1 : 0;
  EXPECT_LT(on_curve, 2u); // one may agree by chance
}

// A corner (a vertex sharpness of 10) on the crease ends its polyline there:
// the crease refines as the two curves on either side of it, each with its
// ends reflected.
TYPED_TEST(Butterfly_creases, a_corner_ends_the_crease)
{
  EMesh mesh = creased_grid(grid_height);
  auto corners = mesh.add_property_map<EMesh::Vertex_index, FT>("v:sharpness", FT(0)).first;
  corners[testing_utils::grid_vertex<EMesh>(6, 3, 3)] = FT(10);
  std::vector<P> left, right;
  for(int i = 1; i <= 5; ++i) {
    const P p = mesh.point(testing_utils::grid_vertex<EMesh>(6, i, 3));
    if(i <= 3)
      left.push_back(p);
    if(i >= 3)
      right.push_back(p);
  }
  S::subdivide(mesh, TypeParam(),
               S::parameters::edge_sharpness_map(mesh.property_map<EMesh::Edge_index, FT>("e:sharpness").first)
                 .vertex_sharpness_map(corners));
  const auto keep_ends = S::parameters::number_of_iterations(1).end_rule(S::End_rule::keep_ends);
  for(const std::vector<P>& polyline : {left, right}) {
    const std::vector<P> curve = S::refine_polyline(polyline, S::Four_point_scheme<FT>(), keep_ends);
    ASSERT_EQ(curve.size(), 5u);
    for(std::size_t k = 1; k < curve.size(); k += 2) {
      std::size_t found = 0;
      for(auto v : vertices(mesh))
        found += mesh.point(v) == curve[k] ? 1 : 0;
      EXPECT_EQ(found, 1u) << "curve point " << k;
    }
  }
  EXPECT_EQ(corners[testing_utils::grid_vertex<EMesh>(6, 3, 3)], FT(10)); // the corner's child is a corner
}

// Neither side of a crease reaches across it: moving a vertex next to the
// crease on one side (y = 4) leaves every new point on the other side and on
// the crease (y <= 3; the scheme reproduces the planar lattice, so a new
// point's y is its edge's midpoint's) where it was; without the tags it
// moves some of them.
TYPED_TEST(Butterfly_creases, the_two_sides_do_not_interact)
{
  const auto moved_height = [](int i, int j) -> FT { return grid_height(i, j) + (i == 3 && j == 4 ? FT(5) : FT(0)); };
  const auto differences_below = [](const EMesh& a, const EMesh& b) {
    std::size_t count = 0;
    for(auto v : vertices(a)) {
      EXPECT_EQ(a.point(v).y(), b.point(v).y());
      if(a.point(v).y() <= 3 && a.point(v) != b.point(v))
        ++count;
    }
    return count;
  };
  EMesh a = creased_grid(grid_height), b = creased_grid(moved_height);
  refine_creased<TypeParam>(a);
  refine_creased<TypeParam>(b);
  EXPECT_EQ(differences_below(a, b), 0u);
  EMesh c = creased_grid(grid_height), d = creased_grid(moved_height);
  S::subdivide(c, TypeParam());
  S::subdivide(d, TypeParam());
  EXPECT_GT(differences_below(c, d), 0u);
}

// Two levels with the tags are one level then another (the children of an
// infinitely sharp edge are infinitely sharp), and the stencil table with the
// tags gives the same points, in rationals; tags of 0 change nothing.
TYPED_TEST(Butterfly_creases, levels_and_tables_agree)
{
  EMesh twice = creased_grid(grid_height), by_levels = twice, coarse = twice;
  refine_creased<TypeParam>(twice, 2);
  refine_creased<TypeParam>(by_levels);
  refine_creased<TypeParam>(by_levels);
  ASSERT_EQ(num_vertices(twice), num_vertices(by_levels));
  for(auto v : vertices(twice))
    ASSERT_EQ(twice.point(v), by_levels.point(v)) << "vertex " << v;
  const auto sharpness = coarse.property_map<EMesh::Edge_index, FT>("e:sharpness").first;
  const S::Stencil_table<FT> table =
    S::make_stencil_table(coarse, TypeParam(), S::parameters::number_of_iterations(2).edge_sharpness_map(sharpness));
  std::vector<P> from_table;
  table.apply(std::vector<P>(coarse.points().begin(), coarse.points().end()), from_table);
  ASSERT_EQ(from_table.size(), num_vertices(twice));
  for(auto v : vertices(twice))
    ASSERT_EQ(from_table[v.idx()], twice.point(v)) << "vertex " << v;

  EMesh zero_tags = testing_utils::grid<EMesh>(
    6, 6, [](int i, int j) { return P(i, j, grid_height(i, j)); }, true);
  EMesh untagged = zero_tags;
  auto zeros = zero_tags.add_property_map<EMesh::Edge_index, FT>("e:sharpness", FT(0)).first;
  S::subdivide(zero_tags, TypeParam(), S::parameters::edge_sharpness_map(zeros));
  S::subdivide(untagged, TypeParam());
  for(auto v : vertices(untagged))
    ASSERT_EQ(zero_tags.point(v), untagged.point(v)) << "vertex " << v;
}

// A semi-sharp value is refused, naming the edge, and the mesh and its tags
// are left as they were.
TYPED_TEST(Butterfly_creases, semi_sharp_is_refused)
{
  EMesh mesh = creased_grid(grid_height);
  auto sharpness = mesh.property_map<EMesh::Edge_index, FT>("e:sharpness").first;
  sharpness[EMesh::Edge_index(7)] = FT(1) / FT(2);
  const EMesh before = mesh;
  try {
    refine_creased<TypeParam>(mesh);
    ADD_FAILURE() << "a semi-sharp edge was accepted";
  } catch(const S::Bad_input& e) {
    EXPECT_NE(std::string(e.what()).find(TypeParam().name() + ": edge 7 is semi-sharp"), std::string::npos) << e.what();
  }
  ASSERT_EQ(num_vertices(mesh), num_vertices(before));
  for(auto v : vertices(mesh))
    ASSERT_EQ(mesh.point(v), before.point(v));
  EXPECT_EQ(sharpness[EMesh::Edge_index(7)], FT(1) / FT(2));
}
