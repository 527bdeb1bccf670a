// sqrt3 subdivision (Kobbelt) and interpolating sqrt3 (Labsik-Greiner):
// agreement with CGAL's Sqrt3_subdivision, the border phase across calls,
// exact weights, polynomial precision, Epeck, bad input. The properties every
// scheme has (weights summing to one, counts, affine invariance, planarity,
// Polyhedron_3) are in surface_properties.h.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Subdiv/limit.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "mesh_builders.h"
#include "mesh_test_utils.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace S = CGAL::Subdiv;
using testing_utils::points_of;
using testing_utils::same_mesh;
using K = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using KE = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using FT = KE::FT;
using PE = KE::Point_3;
using Exact_mesh = CGAL::Surface_mesh<PE>;

using testing_utils::position_mismatch;
using testing_utils::shared_mesh;
using testing_utils::test_mesh;

namespace {

// a bundled mesh (test/data)
template <class M>
M read(const std::string& name)
{
  M mesh;
  EXPECT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh(name), mesh)) << name;
  return mesh;
}

std::size_t border_edges(const Mesh& mesh)
{
  std::size_t count = 0;
  for(auto e : edges(mesh))
    count += mesh.is_border(e);
  return count;
}

// a regular triangulated N x N grid in lattice coordinates (an affine image
// of the equilateral lattice: every interior vertex has valence 6), z = f(x, y)
template <class F>
Exact_mesh regular_grid(int n, const F& f)
{
  return testing_utils::grid<Exact_mesh>(
    n, n, [&](int i, int j) { return PE(i, j, f(FT(i), FT(j))); }, true, testing_utils::Diagonal::descending);
}

FT cubic(const FT& x, const FT& y)
{
  return x * x * x - FT(2) * x * x * y + FT(3) * x * y * y - y * y * y + FT(5) * x * y - x + FT(7);
}

} // namespace

// ---------------------------------------------------------------------------
// Kobbelt's sqrt3 against CGAL's Subdivision_method_3

namespace {

void expect_closed_as_cgal(const Mesh& input, const std::string& name)
{
  for(int levels = 1; levels <= 3; ++levels) {
    Mesh ours = input, theirs = input;
    const std::size_t v = num_vertices(ours), f = num_faces(ours);
    S::sqrt3_subdivision(ours, CGAL::parameters::number_of_iterations(levels));
    CGAL::Subdivision_method_3::Sqrt3_subdivision(theirs, CGAL::parameters::number_of_iterations(levels));
    ASSERT_EQ(num_vertices(ours), num_vertices(theirs)) << name << " " << levels;
    ASSERT_EQ(num_faces(ours), num_faces(theirs)) << name << " " << levels;
    EXPECT_TRUE(ours.is_valid(false));
    const double mismatch = position_mismatch(ours, theirs);
    EXPECT_LT(mismatch, 1e-12) << name << " " << levels;
    if(levels == 1) {
      EXPECT_EQ(num_vertices(ours), v + f);
      EXPECT_EQ(num_faces(ours), 3 * f);
    }
  }
}

// one call of 1 to 4 levels, ours and CGAL's
void expect_border_as_cgal_within_one_call(const Mesh& input, const std::string& name)
{
  const std::size_t b = border_edges(input);
  ASSERT_GT(b, 0u);
  for(int levels = 1; levels <= 4; ++levels) {
    Mesh ours = input, theirs = input;
    S::sqrt3_subdivision(ours, CGAL::parameters::number_of_iterations(levels));
    CGAL::Subdivision_method_3::Sqrt3_subdivision(theirs, CGAL::parameters::number_of_iterations(levels));
    ASSERT_EQ(num_vertices(ours), num_vertices(theirs)) << name << " " << levels;
    ASSERT_EQ(num_faces(ours), num_faces(theirs)) << name << " " << levels;
    EXPECT_TRUE(ours.is_valid(false)) << name << " " << levels;
    EXPECT_LT(position_mismatch(ours, theirs), 1e-12) << name << " " << levels;
    // the border is split 1-to-3 every second level
    EXPECT_EQ(border_edges(ours), b * (levels >= 4 ? 9 : levels >= 2 ? 3 : 1)) << name << " " << levels;
  }
}

} // namespace

// Kobbelt's sqrt3 against CGAL's Subdivision_method_3
TEST(Sqrt3, matches_cgal_on_closed_meshes_at_levels_1_to_3)
{
  // valences 3, 5, and 4 to 6
  for(const std::string name : {"cgal/tetrahedron.off", "cgal/icosahedron.off", "opensubdiv/loop_cube.obj"})
    expect_closed_as_cgal(testing_utils::bundled<Mesh>(name), name);
}

// CGAL refines the border on the second, fourth, ... level of each call. One
// call with k levels agrees with ours; but two calls of one level never
// refine the border in CGAL (the border polygon stays the same), while ours
// reads the phase from the mesh and refines it on the second call.
TEST(Sqrt3, border_matches_cgal_within_one_call_and_differs_across_calls)
{
  // hedra_open (an octahedron without two faces) has the connectivity of a
  // resting step's output, but not its element order: it rests first too
  for(const std::string name : {"cgal/patch-23.off", "cgal/hedra_open.off", "cgal/corner_tris_with_hole.off"})
    expect_border_as_cgal_within_one_call(read<Mesh>(name), name);

  const Mesh input = read<Mesh>("cgal/patch-23.off");
  const std::size_t b = border_edges(input);
  Mesh ours = input, theirs = input, reference = input;
  for(int call = 0; call < 2; ++call) {
    S::sqrt3_subdivision(ours);
    CGAL::Subdivision_method_3::Sqrt3_subdivision(theirs, CGAL::parameters::number_of_iterations(1));
  }
  CGAL::Subdivision_method_3::Sqrt3_subdivision(reference, CGAL::parameters::number_of_iterations(2));
  EXPECT_EQ(border_edges(theirs), b);   // CGAL: the border was never refined
  EXPECT_EQ(border_edges(ours), 3 * b); // ours: refined on the second call
  EXPECT_EQ(num_vertices(ours), num_vertices(reference));
  EXPECT_LT(position_mismatch(ours, reference), 1e-12);
  EXPECT_NE(num_vertices(theirs), num_vertices(reference));
}

TEST(Sqrt3, larger_shared_meshes_agree_with_cgal_subdivision_method_3)
{
  SUBDIV_REQUIRE_SHARED_DATA();
  Mesh elephant, with_border, with_holes;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(shared_mesh("cgal/elephant.off"), elephant));
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(shared_mesh("cgal/mesh_with_border.off"), with_border));
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(shared_mesh("cgal/elephant-with-holes.off"), with_holes));
  expect_closed_as_cgal(elephant, "elephant");
  expect_border_as_cgal_within_one_call(with_border, "mesh_with_border");
  expect_border_as_cgal_within_one_call(with_holes, "elephant-with-holes");
}

TEST(Sqrt3, the_host_reads_the_border_phase_from_the_mesh)
{
  Mesh mesh = read<Mesh>("cgal/patch-23.off");
  const Mesh closed = read<Mesh>("cgal/icosahedron.off");
  EXPECT_FALSE(S::Sqrt3_split<Mesh>(closed).refines_border());
  for(int level = 0; level < 5; ++level) {
    EXPECT_EQ(S::Sqrt3_split<Mesh>(mesh).refines_border(), level % 2 == 1) << level;
    S::sqrt3_subdivision(mesh);
  }
  // after a resting step, reversing the vertex order hides the phase: the
  // border rests once more, then refines
  Mesh rested = read<Mesh>("cgal/patch-23.off");
  S::sqrt3_subdivision(rested);
  ASSERT_TRUE(S::Sqrt3_split<Mesh>(rested).refines_border());
  Mesh reversed;
  {
    std::vector<Mesh::Vertex_index> copy;
    std::vector<K::Point_3> points = points_of(rested);
    for(auto it = points.rbegin(); it != points.rend(); ++it)
      copy.push_back(reversed.add_vertex(*it));
    std::reverse(copy.begin(), copy.end());
    for(auto f : faces(rested)) {
      std::vector<Mesh::Vertex_index> corners;
      for(auto v : CGAL::vertices_around_face(halfedge(f, rested), rested))
        corners.push_back(copy[v.idx()]);
      reversed.add_face(corners);
    }
  }
  EXPECT_FALSE(S::Sqrt3_split<Mesh>(reversed).refines_border());
  S::sqrt3_subdivision(reversed);
  EXPECT_TRUE(S::Sqrt3_split<Mesh>(reversed).refines_border());

  // a closed component beside the bordered one does not disturb the phase
  Mesh both = read<Mesh>("cgal/patch-23.off");
  {
    const Mesh tetrahedron = read<Mesh>("cgal/tetrahedron.off");
    std::vector<Mesh::Vertex_index> copy;
    for(auto v : vertices(tetrahedron))
      copy.push_back(both.add_vertex(tetrahedron.point(v)));
    for(auto f : faces(tetrahedron)) {
      std::vector<Mesh::Vertex_index> corners;
      for(auto v : CGAL::vertices_around_face(halfedge(f, tetrahedron), tetrahedron))
        corners.push_back(copy[v.idx()]);
      both.add_face(corners);
    }
  }
  const std::size_t both_border = border_edges(both);
  Mesh both_once = both;
  S::sqrt3_subdivision(both);
  EXPECT_TRUE(S::Sqrt3_split<Mesh>(both).refines_border());
  S::sqrt3_subdivision(both);
  S::sqrt3_subdivision(both_once, CGAL::parameters::number_of_iterations(2));
  EXPECT_EQ(border_edges(both), 3 * both_border);
  EXPECT_TRUE(same_mesh(both, both_once));

  // a single triangle: rested, then its three edges split in three
  Mesh triangle;
  triangle.add_face(triangle.add_vertex(K::Point_3(0, 0, 0)), triangle.add_vertex(K::Point_3(3, 0, 0)),
                    triangle.add_vertex(K::Point_3(0, 3, 0)));
  S::sqrt3_subdivision(triangle);
  EXPECT_EQ(num_vertices(triangle), 4u);
  EXPECT_EQ(border_edges(triangle), 3u);
  S::sqrt3_subdivision(triangle);
  EXPECT_EQ(num_vertices(triangle), 4u + 6u); // no face point in a border face, two points per border edge
  EXPECT_EQ(num_faces(triangle), 9u);
  EXPECT_EQ(border_edges(triangle), 9u);
  EXPECT_TRUE(triangle.is_valid(false));
  S::sqrt3_subdivision(triangle, CGAL::parameters::number_of_iterations(2));
  EXPECT_EQ(num_faces(triangle), 81u);
  EXPECT_EQ(border_edges(triangle), 27u);
  EXPECT_TRUE(triangle.is_valid(false));
}

TEST(Sqrt3, one_call_of_two_levels_equals_two_calls_of_one_exactly)
{
  for(const std::string name : {"cgal/patch-23.off", "cgal/icosahedron.off", "cgal/hedra_open.off"}) {
    const Exact_mesh input = read<Exact_mesh>(name);
    Exact_mesh once = input, twice = input;
    S::sqrt3_subdivision(once, CGAL::parameters::number_of_iterations(2));
    S::sqrt3_subdivision(twice);
    S::sqrt3_subdivision(twice);
    EXPECT_TRUE(same_mesh(once, twice)) << name;
    once = input;
    twice = input;
    S::interpolating_sqrt3_subdivision(once, CGAL::parameters::number_of_iterations(2));
    S::interpolating_sqrt3_subdivision(twice);
    S::interpolating_sqrt3_subdivision(twice);
    EXPECT_TRUE(same_mesh(once, twice)) << name;
  }
}

// ---------------------------------------------------------------------------
// weights

TEST(Sqrt3, kobbelt_weights_are_rational_at_valences_3_4_6)
{
  using Mask = S::Sqrt3_mask<Exact_mesh>;
  EXPECT_EQ(Mask::alpha(3), FT(5) / FT(9));
  EXPECT_EQ(Mask::alpha(4), FT(4) / FT(9));
  EXPECT_EQ(Mask::alpha(6), FT(1) / FT(3));
  EXPECT_TRUE(Mask::is_exact(3) && Mask::is_exact(4) && Mask::is_exact(6));
  EXPECT_FALSE(Mask::is_exact(5) || Mask::is_exact(7));
  EXPECT_NEAR(CGAL::to_double(Mask::alpha(5)), (4 - 2 * std::cos(2 * CGAL_PI / 5)) / 9, 1e-16);
  using IMask = S::Interpolating_sqrt3_mask<Exact_mesh>;
  FT sum(0);
  for(int j = 0; j < 6; ++j)
    sum += IMask::ring_weight(6, j);
  EXPECT_EQ(sum, FT(1) / FT(3));
  EXPECT_EQ(IMask::ring_weight(6, 0), FT(5) / FT(18));
  EXPECT_EQ(IMask::ring_weight(6, 2), FT(-1) / FT(18));
}

TEST(Sqrt3, kobbelt_vertex_and_border_stencils)
{
  // a fan of 4 triangles around an interior vertex of valence 4, then its
  // border refined on the second step
  const PE ring_points[4] = {PE(1, 0, 0), PE(0, 1, 0), PE(-1, 0, 0), PE(0, -1, 0)};
  Exact_mesh mesh = testing_utils::closed_fan<Exact_mesh>(4, PE(0, 0, 1), [&](int i) { return ring_points[i]; });
  const Exact_mesh::Vertex_index c(0);
  Exact_mesh::Vertex_index ring[4] = {Exact_mesh::Vertex_index(1), Exact_mesh::Vertex_index(2),
                                      Exact_mesh::Vertex_index(3), Exact_mesh::Vertex_index(4)};
  S::sqrt3_subdivision(mesh);
  // centre: (1 - 4/9) c + 4/9 * mean(ring) = (0, 0, 5/9); border vertices kept
  EXPECT_EQ(mesh.point(c), PE(0, 0, FT(5) / FT(9)));
  EXPECT_EQ(mesh.point(ring[0]), PE(1, 0, 0));
  // face point of (c, r0, r1): the centroid
  EXPECT_EQ(mesh.point(Exact_mesh::Vertex_index(5)), PE(FT(1) / FT(3), FT(1) / FT(3), FT(1) / FT(3)));
  ASSERT_TRUE(S::Sqrt3_split<Exact_mesh>(mesh).refines_border());
  S::sqrt3_subdivision(mesh);
  // border vertex r0 with border neighbours r3, r1: (4 r3 + 19 r0 + 4 r1) / 27
  EXPECT_EQ(mesh.point(ring[0]), PE(FT(19) / FT(27), 0, 0));
  // the border points of edge (r0, r1): (16 r0 + 10 r1 + r3) / 27 and its mirror
  bool near_r0 = false, near_r1 = false;
  for(auto v : vertices(mesh)) {
    near_r0 = near_r0 || mesh.point(v) == PE(FT(16) / FT(27), FT(10 - 1) / FT(27), 0);
    near_r1 = near_r1 || mesh.point(v) == PE(FT(10 - 1) / FT(27), FT(16) / FT(27), 0);
  }
  EXPECT_TRUE(near_r0 && near_r1);
}

// ---------------------------------------------------------------------------
// exact properties

TEST(Sqrt3, interpolating_keeps_old_vertices_exactly)
{
  for(const std::string name : {"cgal/patch-23.off", "cgal/icosahedron.off"}) {
    Exact_mesh mesh = read<Exact_mesh>(name);
    for(int level = 0; level < 2; ++level) {
      const auto before = points_of(mesh);
      S::interpolating_sqrt3_subdivision(mesh);
      const auto after = points_of(mesh);
      ASSERT_GT(after.size(), before.size());
      EXPECT_TRUE(std::equal(before.begin(), before.end(), after.begin())) << name << " " << level;
      EXPECT_TRUE(mesh.is_valid(false));
    }
  }
}

// the regular 12-point stencil reproduces cubic polynomials; the border's
// ternary four-point rule reproduces cubics along a straight border
TEST(Sqrt3, interpolating_reproduces_cubics_on_a_regular_grid)
{
  const int n = 8;
  Exact_mesh mesh = regular_grid(n, cubic);
  const std::size_t old_count = num_vertices(mesh);
  S::interpolating_sqrt3_subdivision(mesh);
  std::size_t checked = 0;
  for(auto v : vertices(mesh)) {
    if(v.idx() < old_count)
      continue;
    const PE& p = mesh.point(v);
    // face points of faces with three interior corners of valence 6 lie
    // strictly inside [1, n-1]^2; there the rule is the 12-point stencil
    if(p.x() > 1 && p.y() > 1 && p.x() < n - 1 && p.y() < n - 1) {
      EXPECT_EQ(p.z(), cubic(p.x(), p.y())) << p;
      ++checked;
    }
  }
  EXPECT_GT(checked, 50u);
  // second step: the border y = 0 is split by the ternary four-point rule
  S::interpolating_sqrt3_subdivision(mesh);
  checked = 0;
  for(auto v : vertices(mesh)) {
    const PE& p = mesh.point(v);
    if(p.y() == 0 && p.x() > 1 && p.x() < n - 1) {
      EXPECT_EQ(p.z(), cubic(p.x(), FT(0))) << p;
      ++checked;
    }
  }
  // old vertices x = 2 .. n-2, two points on each edge (x, x+1), x = 1 .. n-2
  EXPECT_EQ(checked, std::size_t(3 * n - 7));
}

TEST(Sqrt3, interpolating_one_ring_rule_at_valence_6_is_quadratic_precise)
{
  // the one-ring rule at valence 6 (used next to irregular vertices), on a
  // regular ring in lattice coordinates, gives the value of a quadratic at
  // the face's centroid
  using IMask = S::Interpolating_sqrt3_mask<Exact_mesh>;
  // ring at lattice positions around the origin, the face between ring 5 and 0
  const int ring[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
  const auto quadratic = [](const FT& x, const FT& y) -> FT {
    return FT(3) * x * x - x * y + FT(2) * y * y + x - y + 1;
  };
  for(int start = 0; start < 6; ++start) {
    // face (origin, ring[start-1], ring[start]): centroid
    const int a = (start + 5) % 6;
    const FT cx = FT(ring[a][0] + ring[start][0]) / FT(3), cy = FT(ring[a][1] + ring[start][1]) / FT(3);
    FT value = quadratic(0, 0), sum(0);
    for(int j = 0; j < 6; ++j) {
      const int* r = ring[(start + j) % 6];
      const FT w = IMask::ring_weight(6, j);
      sum += w;
      value += w * (quadratic(r[0], r[1]) - quadratic(0, 0));
    }
    EXPECT_EQ(value, quadratic(cx, cy)) << start;
  }
}

TEST(Sqrt3, interpolating_at_irregular_vertices_stays_close_to_a_sphere)
{
  // the icosahedron (valence 5 everywhere) on the unit sphere: the refined
  // surface stays within a few percent of the sphere and is valid
  Mesh mesh = read<Mesh>("cgal/icosahedron.off");
  double radius = 0;
  for(auto v : vertices(mesh))
    radius = (std::max)(radius, std::sqrt(CGAL::squared_distance(mesh.point(v), K::Point_3(0, 0, 0))));
  S::interpolating_sqrt3_subdivision(mesh, CGAL::parameters::number_of_iterations(4));
  EXPECT_EQ(num_faces(mesh), 20u * 81u);
  for(auto v : vertices(mesh)) {
    const double r = std::sqrt(CGAL::squared_distance(mesh.point(v), K::Point_3(0, 0, 0))) / radius;
    EXPECT_GT(r, 0.85);
    EXPECT_LT(r, 1.01);
  }
}

// The one-ring rule near an irregular vertex v of valence n maps v's one-ring
// to the next level's one-ring (the n face points around v) by itself. Its
// eigenvalues are 1, then 1/sqrt(3) twice (the first harmonics, turned by
// pi/n), then 1/3 (the mean, and the second harmonics for n > 4), then 0: the
// necessary condition lambda1 = lambda2 > |lambda3| for tangent plane
// continuity, with the characteristic map of the first harmonics.
TEST(Sqrt3, interpolating_one_ring_rule_has_the_designed_spectrum)
{
  using IMask = S::Interpolating_sqrt3_mask<Mesh>;
  for(int n = 3; n <= 12; ++n) {
    Eigen::MatrixXd s = Eigen::MatrixXd::Zero(n + 1, n + 1);
    s(0, 0) = 1; // v is kept
    for(int j = 0; j < n; ++j) {
      double sum = 0;
      for(int l = 0; l < n; ++l) {
        const double w = IMask::ring_weight(n, l);
        s(1 + j, 1 + (j + l) % n) = w;
        sum += w;
      }
      s(1 + j, 0) = 1 - sum;
    }
    const Eigen::VectorXcd values = s.eigenvalues();
    std::vector<double> moduli;
    for(int i = 0; i <= n; ++i)
      moduli.push_back(std::abs(values[i]));
    std::sort(moduli.rbegin(), moduli.rend());
    EXPECT_NEAR(moduli[0], 1, 1e-12) << n;
    EXPECT_NEAR(moduli[1], 1 / std::sqrt(3.0), 1e-12) << n;
    EXPECT_NEAR(moduli[2], 1 / std::sqrt(3.0), 1e-12) << n;
    EXPECT_NEAR(moduli[3], 1.0 / 3, 1e-12) << n;
    for(int i = 4; i <= n; ++i)
      EXPECT_LE(moduli[i], 1.0 / 3 + 1e-12) << n;
  }
}

TEST(Sqrt3, carries_vertex_data_origins_and_face_data)
{
  Exact_mesh mesh = read<Exact_mesh>("cgal/patch-23.off");
  auto height = mesh.add_property_map<Exact_mesh::Vertex_index, FT>("v:height", FT(0)).first;
  auto label = mesh.add_property_map<Exact_mesh::Face_index, int>("f:label", -1).first;
  const auto linear = [](const PE& p) -> FT { return FT(3) * p.x() - p.y() + FT(7) * p.z() + FT(2); };
  for(auto v : vertices(mesh))
    height[v] = linear(mesh.point(v));
  int next_label = 0;
  for(auto f : faces(mesh))
    label[f] = next_label++;
  const std::size_t v0 = num_vertices(mesh), f0 = num_faces(mesh);
  std::size_t b0 = 0;
  for(auto e : edges(mesh))
    b0 += mesh.is_border(e);

  std::vector<S::Vertex_origin> origins;
  S::Carried_data<Exact_mesh> data;
  data.vertex_map(height).face_map(label).origins(origins);
  S::sqrt3_subdivision(mesh, S::parameters::number_of_iterations(2).carried_data(data));

  for(auto v : vertices(mesh))
    EXPECT_EQ(height[v], linear(mesh.point(v)));
  std::map<int, int> children;
  for(auto f : faces(mesh))
    ++children[label[f]];
  ASSERT_EQ(children.size(), f0);
  for(const auto& entry : children)
    EXPECT_EQ(entry.second, 9);
  // the second level refined the border: old vertices, face points of the
  // faces without border edge, two vertices per border edge
  const std::size_t v1 = v0 + f0, f1 = 3 * f0;
  ASSERT_EQ(origins.size(), num_vertices(mesh));
  ASSERT_EQ(origins.size(), v1 + f1 + b0);
  std::map<S::Origin_kind, std::size_t> kinds;
  for(const auto& origin : origins)
    ++kinds[origin.kind];
  EXPECT_EQ(kinds[S::Origin_kind::vertex], v1);
  EXPECT_EQ(kinds[S::Origin_kind::face], f1 - b0);
  EXPECT_EQ(kinds[S::Origin_kind::edge], 2 * b0);
  EXPECT_EQ(origins[v1].kind, S::Origin_kind::face);
  EXPECT_EQ(origins.back().kind, S::Origin_kind::edge);
}

// ---------------------------------------------------------------------------
// mesh types and bad input

TEST(Sqrt3, works_on_polyhedron_3_and_epeck)
{
  CGAL::Polyhedron_3<K> poly = read<CGAL::Polyhedron_3<K>>("cgal/patch-23.off");
  Mesh sm = read<Mesh>("cgal/patch-23.off");
  S::sqrt3_subdivision(poly);
  S::sqrt3_subdivision(poly);
  S::sqrt3_subdivision(sm, CGAL::parameters::number_of_iterations(2));
  EXPECT_TRUE(poly.is_valid());
  EXPECT_EQ(num_vertices(poly), num_vertices(sm));
  EXPECT_EQ(num_faces(poly), num_faces(sm));
  EXPECT_LT(position_mismatch(poly, sm), 1e-14);

  CGAL::Polyhedron_3<K> ipoly = read<CGAL::Polyhedron_3<K>>("cgal/patch-23.off");
  Mesh ism = read<Mesh>("cgal/patch-23.off");
  S::interpolating_sqrt3_subdivision(ipoly, CGAL::parameters::number_of_iterations(2));
  S::interpolating_sqrt3_subdivision(ism, CGAL::parameters::number_of_iterations(2));
  EXPECT_LT(position_mismatch(ipoly, ism), 1e-14);

  using KK = CGAL::Exact_predicates_exact_constructions_kernel;
  CGAL::Surface_mesh<KK::Point_3> epeck = read<CGAL::Surface_mesh<KK::Point_3>>("cgal/tetrahedron.off");
  S::sqrt3_subdivision(epeck, CGAL::parameters::number_of_iterations(2));
  EXPECT_EQ(num_faces(epeck), 36u);
  S::interpolating_sqrt3_subdivision(epeck);
  EXPECT_EQ(num_faces(epeck), 108u);
}

TEST(Sqrt3, a_quad_mesh_is_refused_and_left_unchanged)
{
  Mesh quad = read<Mesh>("cgal/cube_quad.off");
  const auto before = points_of(quad);
  for(int scheme = 0; scheme < 2; ++scheme) {
    const std::string message = testing_utils::bad_input_message([&] {
      if(scheme == 0)
        S::sqrt3_subdivision(quad);
      else
        S::interpolating_sqrt3_subdivision(quad);
    });
    EXPECT_NE(message.find("sqrt3"), std::string::npos) << message;
    EXPECT_NE(message.find("faces all have 3 vertices; face 0 has 4"), std::string::npos) << message;
    EXPECT_EQ(num_faces(quad), 6u);
    EXPECT_EQ(points_of(quad), before);
  }
}

// ---- creases (sharpness tags): infinitely sharp edges as borders ----------

namespace {

FT crease_height(int i, int j)
{
  return FT((i * 7 + j * 5) % 11) / FT(8) - FT(j * j) / FT(16);
}

// the edge of the lattice vertices (i, j) and (k, l) of a grid(n, n, ...)
template <class M>
typename M::Edge_index grid_edge(const M& mesh, int n, int i, int j, int k, int l)
{
  return mesh.edge(mesh.halfedge(testing_utils::grid_vertex<M>(n, i, j), testing_utils::grid_vertex<M>(n, k, l)));
}

// the closed crease around the square [3, 6] x [3, 6] of a grid(9, 9, ...)
// (12 infinitely sharp edges, their ends crease vertices) in the map
// "e:sharpness" of values `Sharpness`
template <class Sharpness, class M>
void add_square_crease(M& mesh)
{
  auto sharpness = mesh.template add_property_map<typename M::Edge_index, Sharpness>("e:sharpness", Sharpness(0)).first;
  for(int k = 3; k < 6; ++k) {
    sharpness[grid_edge(mesh, 9, k, 3, k + 1, 3)] = Sharpness(10);
    sharpness[grid_edge(mesh, 9, k, 6, k + 1, 6)] = Sharpness(10);
    sharpness[grid_edge(mesh, 9, 3, k, 3, k + 1)] = Sharpness(10);
    sharpness[grid_edge(mesh, 9, 6, k, 6, k + 1)] = Sharpness(10);
  }
}

// a 9 x 9 triangle grid at generic rational heights, with the square crease
// (`add_square_crease`)
Exact_mesh creased_grid(const std::function<FT(int, int)>& height)
{
  Exact_mesh mesh = testing_utils::grid<Exact_mesh>(
    9, 9, [&](int i, int j) { return PE(i, j, height(i, j)); }, true);
  add_square_crease<FT>(mesh);
  return mesh;
}

// the map "v:sharpness" of `mesh` (a creased_grid), with a corner (10) at
// the lattice point (4, 3) on the crease
Exact_mesh::Property_map<Exact_mesh::Vertex_index, FT> add_crease_corner(Exact_mesh& mesh)
{
  auto corners = mesh.add_property_map<Exact_mesh::Vertex_index, FT>("v:sharpness", FT(0)).first;
  corners[testing_utils::grid_vertex<Exact_mesh>(9, 4, 3)] = FT(10);
  return corners;
}

Exact_mesh::Property_map<Exact_mesh::Edge_index, FT> edge_tags(Exact_mesh& mesh)
{
  return mesh.property_map<Exact_mesh::Edge_index, FT>("e:sharpness").first;
}

template <class Mask>
void refine_creased(Exact_mesh& mesh, int levels = 2)
{
  S::subdivide(mesh, Mask(), S::parameters::number_of_iterations(levels).edge_sharpness_map(edge_tags(mesh)));
}

// the vertices of the faces reached from vertex 0 (a corner of the grid,
// outside the square) without crossing a sharp edge: that side, with the
// crease that bounds it
std::vector<Exact_mesh::Vertex_index> outer_side(Exact_mesh& mesh)
{
  const auto sharpness = edge_tags(mesh);
  std::vector<bool> seen_face(num_faces(mesh), false), seen_vertex(num_vertices(mesh), false);
  std::vector<Exact_mesh::Face_index> stack;
  for(auto f : CGAL::faces_around_target(mesh.halfedge(Exact_mesh::Vertex_index(0)), mesh))
    if(f != Exact_mesh::null_face())
      stack.push_back(f);
  std::vector<Exact_mesh::Vertex_index> side;
  while(!stack.empty()) {
    const auto f = stack.back();
    stack.pop_back();
    if(seen_face[f.idx()])
      continue;
    seen_face[f.idx()] = true;
    for(auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      if(!seen_vertex[mesh.target(h).idx()]) {
        seen_vertex[mesh.target(h).idx()] = true;
        side.push_back(mesh.target(h));
      }
      const auto across = mesh.face(mesh.opposite(h));
      if(across != Exact_mesh::null_face() && sharpness[mesh.edge(h)] == FT(0))
        stack.push_back(across);
    }
  }
  return side;
}

// the points of the vertices on sharp edges that are not border edges
std::vector<PE> crease_points(Exact_mesh& mesh)
{
  const auto sharpness = edge_tags(mesh);
  std::vector<PE> points;
  for(auto v : vertices(mesh)) {
    bool on_crease = false;
    for(auto h : CGAL::halfedges_around_target(v, mesh))
      on_crease = on_crease || (sharpness[mesh.edge(h)] >= FT(10) && !mesh.is_border(mesh.edge(h)));
    if(on_crease)
      points.push_back(mesh.point(v));
  }
  std::sort(points.begin(), points.end());
  return points;
}

// the points of the border of `mesh` after two levels of `Mask` without
// tags (a resting step, then one that refines the border), sorted
template <class Mask>
std::vector<PE> border_after_two_levels(Exact_mesh mesh)
{
  S::subdivide(mesh, Mask(), S::parameters::number_of_iterations(2));
  std::vector<PE> border;
  for(auto v : vertices(mesh))
    if(mesh.is_border(v))
      border.push_back(mesh.point(v));
  std::sort(border.begin(), border.end());
  return border;
}

} // namespace

// both sqrt3 schemes: their border rules are ternary (Kobbelt's cubic
// B-spline, the interpolating 4-point rule), applied on every second step
template <class Mask>
class Sqrt3_creases : public ::testing::Test
{};
using Sqrt3_crease_masks = ::testing::Types<S::Sqrt3_mask<Exact_mesh>, S::Interpolating_sqrt3_mask<Exact_mesh>>;
TYPED_TEST_SUITE(Sqrt3_creases, Sqrt3_crease_masks);

// Over two levels (a resting step, then one that refines the border and the
// crease), the crease loop is refined exactly as the border of the disk it
// bounds, cut out of the grid and refined without tags: the scheme's border
// rule along the crease, in rationals. Its children are sharp: 36 edges.
TYPED_TEST(Sqrt3_creases, a_crease_is_refined_as_the_border_of_the_disk_it_bounds)
{
  Exact_mesh mesh = creased_grid(crease_height);
  Exact_mesh disk = testing_utils::grid<Exact_mesh>(
    3, 3, [&](int i, int j) { return PE(i + 3, j + 3, crease_height(i + 3, j + 3)); }, true);
  refine_creased<TypeParam>(mesh, 1);
  EXPECT_TRUE(mesh.is_valid(false));
  EXPECT_EQ(crease_points(mesh).size(), 12u); // the resting step keeps the crease
  refine_creased<TypeParam>(mesh, 1);
  EXPECT_TRUE(mesh.is_valid(false));
  const std::vector<PE> border = border_after_two_levels<TypeParam>(disk);
  ASSERT_EQ(border.size(), 36u);
  EXPECT_EQ(crease_points(mesh), border);
  std::size_t sharp = 0;
  for(auto e : edges(mesh))
    sharp += edge_tags(mesh)[e] >= FT(10) && !mesh.is_border(e) ? 1 : 0;
  EXPECT_EQ(sharp, 36u);
  // without the tags the crease's new points are not the border's
  Exact_mesh untagged = creased_grid(crease_height);
  S::subdivide(untagged, TypeParam(), S::parameters::number_of_iterations(2));
  std::size_t on_border = 0;
  for(auto v : vertices(untagged))
    on_border += std::binary_search(border.begin(), border.end(), untagged.point(v)) ? 1 : 0;
  EXPECT_LT(on_border, 36u);
}

// Moving a vertex inside the square moves no vertex of the outer side nor of
// the crease over two levels; without the tags it moves some.
TYPED_TEST(Sqrt3_creases, the_two_sides_do_not_interact)
{
  const auto moved_height = [](int i, int j) -> FT { return crease_height(i, j) + (i == 4 && j == 5 ? FT(5) : FT(0)); };
  Exact_mesh a = creased_grid(crease_height), b = creased_grid(moved_height);
  refine_creased<TypeParam>(a);
  refine_creased<TypeParam>(b);
  ASSERT_EQ(num_vertices(a), num_vertices(b));
  const std::vector<Exact_mesh::Vertex_index> side = outer_side(a);
  EXPECT_GT(side.size(), num_vertices(a) / 2);
  std::size_t moved_outside = 0, moved = 0;
  for(auto v : side)
    moved_outside += a.point(v) != b.point(v) ? 1 : 0;
  for(auto v : vertices(a))
    moved += a.point(v) != b.point(v) ? 1 : 0;
  EXPECT_EQ(moved_outside, 0u);
  EXPECT_GT(moved, 0u);
  Exact_mesh c = creased_grid(crease_height), d = creased_grid(moved_height);
  S::subdivide(c, TypeParam(), S::parameters::number_of_iterations(2));
  S::subdivide(d, TypeParam(), S::parameters::number_of_iterations(2));
  std::size_t untagged_moved = 0;
  for(auto v : side)
    untagged_moved += c.point(v) != d.point(v) ? 1 : 0;
  EXPECT_GT(untagged_moved, 0u);
}

// Two levels with the tags are one level then another (the children of a
// sharp edge are sharp, and the phase is read with them), and the stencil
// table with the tags gives the same points, in rationals.
TYPED_TEST(Sqrt3_creases, levels_and_tables_agree)
{
  Exact_mesh twice = creased_grid(crease_height), by_levels = twice, coarse = twice;
  refine_creased<TypeParam>(twice, 3);
  for(int level = 0; level < 3; ++level)
    refine_creased<TypeParam>(by_levels, 1);
  EXPECT_TRUE(same_mesh(twice, by_levels));
  const S::Stencil_table<FT> table = S::make_stencil_table(
    coarse, TypeParam(), S::parameters::number_of_iterations(3).edge_sharpness_map(edge_tags(coarse)));
  std::vector<PE> from_table;
  table.apply(std::vector<PE>(coarse.points().begin(), coarse.points().end()), from_table);
  EXPECT_EQ(from_table, points_of(twice));
}

// Tags of 0 give the untagged result bit for bit, in doubles, border
// included; and the untagged result has not changed with creases.
TYPED_TEST(Sqrt3_creases, zero_tags_change_nothing)
{
  using DMask = decltype(TypeParam().template rebind<Mesh, double>());
  Mesh zero_tags = testing_utils::grid<Mesh>(
    7, 7, [](int i, int j) { return K::Point_3(i, j, CGAL::to_double(crease_height(i, j)) / 3); }, true);
  Mesh untagged = zero_tags;
  auto zeros = zero_tags.add_property_map<Mesh::Edge_index, double>("e:sharpness", 0.).first;
  auto corners = zero_tags.add_property_map<Mesh::Vertex_index, double>("v:sharpness", 0.).first;
  S::subdivide(zero_tags, DMask(),
               S::parameters::number_of_iterations(3).edge_sharpness_map(zeros).vertex_sharpness_map(corners));
  S::subdivide(untagged, DMask(), S::parameters::number_of_iterations(3));
  EXPECT_TRUE(same_mesh(zero_tags, untagged));
}

// A semi-sharp value is refused, naming the edge, and the mesh and its tags
// are left as they were.
TYPED_TEST(Sqrt3_creases, semi_sharp_is_refused)
{
  Exact_mesh mesh = creased_grid(crease_height);
  edge_tags(mesh)[Exact_mesh::Edge_index(7)] = FT(1) / FT(2);
  Exact_mesh before = mesh;
  const std::string message = testing_utils::bad_input_message([&] { refine_creased<TypeParam>(mesh); });
  EXPECT_NE(message.find(TypeParam().name() + ": edge 7 is semi-sharp"), std::string::npos) << message;
  EXPECT_TRUE(same_mesh(mesh, before));
  for(auto e : edges(mesh))
    ASSERT_EQ(edge_tags(mesh)[e], edge_tags(before)[e]);
}

// A corner on the crease loop ends it there: the corner stays, and the new
// point next to it on each of its sharp edges is the border rule with the
// polyline continued by point reflection (2 c - s before the corner c): for
// Kobbelt's rule (16 c + 10 s + (2 c - s)) / 27 = (2 c + s) / 3, for the
// interpolating one (-5 (2 c - s) + 60 c + 30 s - 4 s') / 81.
TYPED_TEST(Sqrt3_creases, a_corner_ends_the_crease)
{
  Exact_mesh mesh = creased_grid(crease_height);
  const auto corners = add_crease_corner(mesh);
  const auto corner = testing_utils::grid_vertex<Exact_mesh>(9, 4, 3);
  const PE c = mesh.point(corner);
  const PE s = mesh.point(testing_utils::grid_vertex<Exact_mesh>(9, 5, 3));
  const PE s2 = mesh.point(testing_utils::grid_vertex<Exact_mesh>(9, 6, 3));
  const PE t = mesh.point(testing_utils::grid_vertex<Exact_mesh>(9, 3, 3));
  const PE t2 = mesh.point(testing_utils::grid_vertex<Exact_mesh>(9, 3, 4));
  Exact_mesh no_corner = mesh;
  S::subdivide(
    mesh, TypeParam(),
    S::parameters::number_of_iterations(2).edge_sharpness_map(edge_tags(mesh)).vertex_sharpness_map(corners));
  EXPECT_EQ(mesh.point(corner), c);
  EXPECT_EQ(corners[corner], FT(10)); // the corner's child is a corner
  const bool interpolating = TypeParam().is_interpolating();
  const auto next_to_corner = [&](const PE& s1, const PE& beyond) {
    if(!interpolating)
      return CGAL::barycenter(c, FT(2), s1, FT(1));
    const FT w[3] = {FT(50) / FT(81), FT(35) / FT(81), FT(-4) / FT(81)};
    return PE(w[0] * c.x() + w[1] * s1.x() + w[2] * beyond.x(), w[0] * c.y() + w[1] * s1.y() + w[2] * beyond.y(),
              w[0] * c.z() + w[1] * s1.z() + w[2] * beyond.z());
  };
  const std::vector<PE> points = points_of(mesh);
  for(const PE& expected : {next_to_corner(s, s2), next_to_corner(t, t2)})
    EXPECT_EQ(std::count(points.begin(), points.end(), expected), 1) << expected;
  // without the corner the crease goes on through the vertex: other points
  refine_creased<TypeParam>(no_corner);
  const std::vector<PE> through = points_of(no_corner);
  EXPECT_EQ(std::count(through.begin(), through.end(), next_to_corner(s, s2)), 0);
}

// A closed mesh with a crease has a phase too: on the icosahedron with the
// crease loop around vertex 0 (its link, 5 edges), the first level rests and
// the second trisects the loop as the border of the cap it bounds (the 5
// faces at vertex 0, cut out and refined without tags); one level and one
// level are two levels, and the counts are V + F at each level.
TYPED_TEST(Sqrt3_creases, a_closed_mesh_with_a_crease_has_a_phase)
{
  Exact_mesh mesh = read<Exact_mesh>("cgal/icosahedron.off");
  auto sharpness = mesh.add_property_map<Exact_mesh::Edge_index, FT>("e:sharpness", FT(0)).first;
  const Exact_mesh::Vertex_index apex(0);
  Exact_mesh cap;
  std::map<Exact_mesh::Vertex_index, Exact_mesh::Vertex_index> in_cap;
  in_cap[apex] = cap.add_vertex(mesh.point(apex));
  for(auto h : CGAL::halfedges_around_target(apex, mesh)) {
    const auto u = mesh.source(h);
    in_cap[u] = cap.add_vertex(mesh.point(u));
    sharpness[mesh.edge(mesh.prev(h))] = FT(10); // the edge of the face of h opposite the apex
  }
  for(auto f : CGAL::faces_around_target(mesh.halfedge(apex), mesh)) {
    std::vector<Exact_mesh::Vertex_index> corners;
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      corners.push_back(in_cap.at(v));
    cap.add_face(corners);
  }
  ASSERT_EQ(num_faces(cap), 5u);
  Exact_mesh twice = mesh;
  refine_creased<TypeParam>(mesh, 1);
  EXPECT_EQ(num_vertices(mesh), 12u + 20u);
  EXPECT_EQ(crease_points(mesh).size(), 5u);
  refine_creased<TypeParam>(mesh, 1);
  EXPECT_EQ(num_vertices(mesh), 32u + 60u);
  EXPECT_TRUE(mesh.is_valid(false));
  refine_creased<TypeParam>(twice, 2);
  EXPECT_TRUE(same_mesh(mesh, twice));
  const std::vector<PE> border = border_after_two_levels<TypeParam>(cap);
  ASSERT_EQ(border.size(), 15u);
  EXPECT_EQ(crease_points(mesh), border);
}

// ---- the limit with creases (sharpness tags) -------------------------------

namespace {

// the 9 x 9 grid of `creased_grid` in doubles, with its square crease
Mesh creased_grid_in_doubles()
{
  Mesh mesh = testing_utils::grid<Mesh>(
    9, 9, [](int i, int j) { return K::Point_3(i, j, CGAL::to_double(crease_height(i, j))); }, true);
  add_square_crease<double>(mesh);
  return mesh;
}

Mesh::Property_map<Mesh::Edge_index, double> edge_tags(Mesh& mesh)
{
  return mesh.property_map<Mesh::Edge_index, double>("e:sharpness").first;
}

// the lattice points (i, j) of the square crease of a grid(9, 9, ...)
std::vector<std::pair<int, int>> square_crease_vertices()
{
  std::vector<std::pair<int, int>> on_square;
  for(int i = 3; i <= 6; ++i)
    for(int j = 3; j <= 6; ++j)
      if(i == 3 || i == 6 || j == 3 || j == 6)
        on_square.emplace_back(i, j);
  return on_square;
}

} // namespace

// A crease vertex goes to the limit of the border rule along the crease: the
// border limit of the disk the crease bounds, cut out and projected without
// tags, exactly. For Kobbelt's rule that is the cubic B-spline's
// (u + 4 v + w) / 6 over the crease neighbours u, w (not the vertex); the
// interpolating rule keeps the vertex.
TYPED_TEST(Sqrt3_creases, a_crease_vertex_goes_to_the_border_limit_of_the_disk)
{
  Exact_mesh mesh = creased_grid(crease_height);
  Exact_mesh disk = testing_utils::grid<Exact_mesh>(
    3, 3, [&](int i, int j) { return PE(i + 3, j + 3, crease_height(i + 3, j + 3)); }, true);
  const Exact_mesh control = mesh;
  S::project_to_limit(mesh, TypeParam(), S::parameters::edge_sharpness_map(edge_tags(mesh)));
  S::project_to_limit(disk, TypeParam());
  const std::vector<std::pair<int, int>> on_square = square_crease_vertices();
  ASSERT_EQ(on_square.size(), 12u);
  for(const auto& ij : on_square)
    EXPECT_EQ(mesh.point(testing_utils::grid_vertex<Exact_mesh>(9, ij.first, ij.second)),
              disk.point(testing_utils::grid_vertex<Exact_mesh>(3, ij.first - 3, ij.second - 3)))
      << ij.first << " " << ij.second;
  const auto at = [&](int i, int j) { return control.point(testing_utils::grid_vertex<Exact_mesh>(9, i, j)); };
  const PE expected =
    TypeParam().is_interpolating() ? at(4, 3) : CGAL::barycenter(at(3, 3), FT(1), at(4, 3), FT(4), at(5, 3), FT(1));
  EXPECT_EQ(mesh.point(testing_utils::grid_vertex<Exact_mesh>(9, 4, 3)), expected);
  if(!TypeParam().is_interpolating()) {
    EXPECT_NE(expected, at(4, 3));
  }
}

// A corner on the crease stays where it is (without the corner Kobbelt's
// rule moves it), and tags of 0 give the untagged limit, exactly.
TYPED_TEST(Sqrt3_creases, a_corner_stays_and_zero_tags_give_the_untagged_limit)
{
  Exact_mesh mesh = creased_grid(crease_height);
  const auto corners = add_crease_corner(mesh);
  const auto corner = testing_utils::grid_vertex<Exact_mesh>(9, 4, 3);
  const PE c = mesh.point(corner);
  Exact_mesh no_corner = mesh;
  S::project_to_limit(mesh, TypeParam(),
                      S::parameters::edge_sharpness_map(edge_tags(mesh)).vertex_sharpness_map(corners));
  EXPECT_EQ(mesh.point(corner), c);
  S::project_to_limit(no_corner, TypeParam(), S::parameters::edge_sharpness_map(edge_tags(no_corner)));
  EXPECT_EQ(no_corner.point(corner) == c, TypeParam().is_interpolating());

  Exact_mesh zero_tags = testing_utils::grid<Exact_mesh>(
    9, 9, [&](int i, int j) { return PE(i, j, crease_height(i, j)); }, true);
  Exact_mesh untagged = zero_tags;
  const Exact_mesh control = zero_tags;
  auto zeros = zero_tags.add_property_map<Exact_mesh::Edge_index, FT>("e:sharpness", FT(0)).first;
  auto zero_corners = zero_tags.add_property_map<Exact_mesh::Vertex_index, FT>("v:sharpness", FT(0)).first;
  S::project_to_limit(zero_tags, TypeParam(),
                      S::parameters::edge_sharpness_map(zeros).vertex_sharpness_map(zero_corners));
  S::project_to_limit(untagged, TypeParam());
  EXPECT_EQ(points_of(zero_tags), points_of(untagged));
  EXPECT_EQ(points_of(untagged) == points_of(control), TypeParam().is_interpolating());
}

// The limit is where refinement with the tags converges: the crease's old
// vertices approach their crease limit, by at least 4 times every two levels
// (Kobbelt's ternary rule: 9 times, its second difference shrinks by 9 per
// ternary step) to a hundredth of their first distance after six levels;
// the interpolating scheme keeps them at their limit at every level.
TYPED_TEST(Sqrt3_creases, refinement_converges_to_the_crease_limit)
{
  using DMask = decltype(TypeParam().template rebind<Mesh, double>());
  Mesh mesh = creased_grid_in_doubles(), limit = mesh;
  S::project_to_limit(limit, DMask(), S::parameters::edge_sharpness_map(edge_tags(limit)));
  std::vector<double> distance;
  for(int level = 0; level <= 6; level += 2) {
    if(level > 0)
      S::subdivide(mesh, DMask(), S::parameters::number_of_iterations(2).edge_sharpness_map(edge_tags(mesh)));
    double d = 0;
    for(const auto& ij : square_crease_vertices()) {
      const auto v = testing_utils::grid_vertex<Mesh>(9, ij.first, ij.second); // old vertices keep their index
      d = (std::max)(d, std::sqrt(CGAL::squared_distance(mesh.point(v), limit.point(v))));
    }
    distance.push_back(d);
  }
  ASSERT_EQ(distance.size(), 4u);
  if(TypeParam().is_interpolating()) {
    for(double d : distance)
      EXPECT_EQ(d, 0.0);
    return;
  }
  EXPECT_GT(distance[0], 0.01);
  for(std::size_t k = 1; k < distance.size(); ++k)
    EXPECT_LT(distance[k], distance[k - 1] / 4) << k;
  EXPECT_LT(distance.back(), distance.front() / 100);
}

// The limit stencil tables with the tags (a crease and a corner on it) are
// the refinement with the tags followed by the projection with the refined
// tags, up to rounding, at 0, 1 and 2 levels (both phases of the crease).
TYPED_TEST(Sqrt3_creases, limit_tables_with_tags_are_the_projection)
{
  using DMask = decltype(TypeParam().template rebind<Mesh, double>());
  Mesh coarse = creased_grid_in_doubles();
  auto corners = coarse.add_property_map<Mesh::Vertex_index, double>("v:sharpness", 0.).first;
  corners[testing_utils::grid_vertex<Mesh>(9, 4, 3)] = 10.;
  const std::vector<K::Point_3> control(coarse.points().begin(), coarse.points().end());
  for(int levels = 0; levels <= 2; ++levels) {
    Mesh refined = coarse;
    const auto refined_corners = refined.property_map<Mesh::Vertex_index, double>("v:sharpness").first;
    const auto tags = S::parameters::edge_sharpness_map(edge_tags(refined)).vertex_sharpness_map(refined_corners);
    S::subdivide(refined, DMask(), tags.number_of_iterations(levels));
    S::project_to_limit(refined, DMask(), tags);
    const S::Stencil_table<double> table = S::make_limit_stencil_table(
      coarse, DMask(),
      S::parameters::number_of_iterations(levels).edge_sharpness_map(edge_tags(coarse)).vertex_sharpness_map(corners));
    std::vector<K::Point_3> from_table;
    table.apply(control, from_table);
    const std::vector<K::Point_3> projected = points_of(refined);
    ASSERT_EQ(from_table.size(), projected.size()) << levels;
    double worst = 0;
    for(std::size_t k = 0; k < projected.size(); ++k)
      worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(from_table[k], projected[k])));
    EXPECT_LT(worst, 1e-12) << levels;
  }
}
