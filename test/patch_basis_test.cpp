// The regular-patch bases of the limit surface (issue 13, limit/patch_basis.h):
// the bicubic B-spline patch of Catmull-Clark and the quartic box-spline patch
// of Loop, as weights over their control points. Exact in rationals: the
// weights sum to 1 and 0, reproduce linear functions, are the regular limit
// masks at the corners, equal the package's own refinement and limit at every
// dyadic parameter of levels 1 to 3, and their derivatives are those of the
// position (differences of polynomials of degree 4, extrapolated exactly). In
// double, central differences agree with the derivatives.
#include <CGAL/Subdiv/Carried_data.h>
#include <CGAL/Subdiv/catmull_clark_subdivision.h>
#include <CGAL/Subdiv/limit/patch_basis.h>
#include <CGAL/Subdiv/limit/project_to_limit.h>
#include <CGAL/Subdiv/loop_subdivision.h>

#include "mesh_builders.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <map>
#include <utility>
#include <vector>

namespace {

namespace SD = CGAL::Subdiv;
using Q = CGAL::Exact_rational;
using QK = CGAL::Simple_cartesian<Q>;
using Exact_mesh = CGAL::Surface_mesh<QK::Point_3>;
using Lattice = std::array<int, 2>;

/*
 * What the tests need of each patch: its weights, where its control points
 * sit on the lattice of the parameter plane (the patch's own numbering, as
 * the header documents it), its domain, its regular limit mask, and a mesh
 * of its scheme, refined and taken to the limit by the package.
 */
struct Bspline_patch
{
  static constexpr std::size_t size = 16;
  static constexpr bool triangle = false;
  /// point 4 r + c is at (c - 1, r - 1)
  static Lattice lattice(std::size_t k) { return {int(k % 4) - 1, int(k / 4) - 1}; }
  static bool in_domain(const Q& u, const Q& v) { return u >= 0 && v >= 0 && u <= 1 && v <= 1; }
  /// the corners of the face, in their order
  static std::vector<Lattice> corners() { return {{0, 0}, {1, 0}, {1, 1}, {0, 1}}; }
  /// the limit mask of a regular vertex at offset d from it: 16, 4 (edge),
  /// 1 (diagonal) / 36, the tensor square of the cubic B-spline's (1, 4, 1) / 6
  static Q limit_mask(const Lattice& d)
  {
    const int a = std::abs(d[0]), b = std::abs(d[1]);
    if(a > 1 || b > 1)
      return Q(0);
    return Q(a + b == 0 ? 16 : a + b == 1 ? 4 : 1) / Q(36);
  }
  /// the corner of the face at (0, 1)
  static constexpr int corner_at_v = 3;
  /// the base face: the cell (2, 2) of a grid of 6 x 6 quads
  static constexpr int cells = 6;
  static constexpr std::size_t face = 2 * cells + 2;

  static void refine(Exact_mesh& mesh, int levels, const SD::Carried_data<Exact_mesh>& data)
  {
    SD::catmull_clark_subdivision(mesh, SD::parameters::number_of_iterations(levels).carried_data(data));
  }
  static void limit(Exact_mesh& mesh) { SD::project_to_limit(mesh, SD::Catmull_clark_mask<Exact_mesh>()); }
};

struct Box_spline_patch
{
  static constexpr std::size_t size = 12;
  static constexpr bool triangle = true;
  /// OpenSubdiv's numbering: rows j = -1 .. 2 of the lattice of e_u, e_v
  static Lattice lattice(std::size_t k)
  {
    static const std::array<Lattice, 12> at = {
      {{0, -1}, {1, -1}, {2, -1}, {-1, 0}, {0, 0}, {1, 0}, {2, 0}, {-1, 1}, {0, 1}, {1, 1}, {-1, 2}, {0, 2}}};
    return at[k];
  }
  static bool in_domain(const Q& u, const Q& v) { return u >= 0 && v >= 0 && u + v <= 1; }
  static std::vector<Lattice> corners() { return {{0, 0}, {1, 0}, {0, 1}}; }
  /// the limit mask of a regular vertex at offset d from it: 1/2, 1/12 at each
  /// of the 6 neighbours (the lattice's edges run along e_u, e_v, e_v - e_u)
  static Q limit_mask(const Lattice& d)
  {
    if(d == Lattice{0, 0})
      return Q(1) / Q(2);
    static const std::array<Lattice, 6> ring = {{{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {-1, 1}, {1, -1}}};
    return std::find(ring.begin(), ring.end(), d) != ring.end() ? Q(1) / Q(12) : Q(0);
  }
  static constexpr int corner_at_v = 2;
  /// the base face: the first triangle of the cell (2, 2) of a grid of 6 x 6
  /// squares, each cut along its ascending diagonal (every interior vertex
  /// has valence 6)
  static constexpr int cells = 6;
  static constexpr std::size_t face = 2 * (2 * cells + 2);

  static void refine(Exact_mesh& mesh, int levels, const SD::Carried_data<Exact_mesh>& data)
  {
    SD::loop_subdivision(mesh, SD::parameters::number_of_iterations(levels).carried_data(data));
  }
  static void limit(Exact_mesh& mesh) { SD::project_to_limit(mesh, SD::Loop_mask<Exact_mesh>()); }
};

/// the weights of the patch at (u, v)
template <class Patch, class FT>
auto weights(const FT& u, const FT& v)
{
  if constexpr(Patch::triangle)
    return SD::box_spline_patch_weights<FT>(u, v);
  else
    return SD::bspline_patch_weights<FT>(u, v);
}

template <class Patch>
class Patch_basis : public ::testing::Test
{};
using Patches = ::testing::Types<Bspline_patch, Box_spline_patch>;
TYPED_TEST_SUITE(Patch_basis, Patches);

template <class FT, std::size_t N>
FT sum(const std::array<FT, N>& w)
{
  FT s(0);
  for(const FT& x : w)
    s += x;
  return s;
}

/// the combination sum_k w_k p_k of values (the coordinates x or y of the lattice)
template <std::size_t N, class Of>
Q combine(const std::array<Q, N>& w, const Of& value_of)
{
  Q s(0);
  for(std::size_t k = 0; k < N; ++k)
    s += w[k] * value_of(k);
  return s;
}

/// rational parameters, corners and edges included, inside the patch's domain
template <class Patch>
std::vector<std::array<Q, 2>> parameters()
{
  const std::vector<std::array<Q, 2>> all = {
    {Q(0), Q(0)},       {Q(1), Q(0)},       {Q(0), Q(1)},         {Q(1), Q(1)},       {Q(1, 3), Q(1, 5)},
    {Q(2, 7), Q(3, 5)}, {Q(1, 2), Q(1, 2)}, {Q(3, 4), Q(1, 8)},   {Q(5, 6), Q(2, 3)}, {Q(1, 10), Q(9, 10)},
    {Q(0), Q(4, 9)},    {Q(7, 11), Q(0)},   {Q(13, 17), Q(1, 3)}, {Q(1, 2), Q(1)},    {Q(0), Q(1, 1000)}};
  std::vector<std::array<Q, 2>> inside;
  for(const auto& uv : all)
    if(Patch::in_domain(uv[0], uv[1]))
      inside.push_back(uv);
  return inside;
}

/// the six weight arrays of `w`, for the checks that treat them alike
template <class FT, std::size_t N>
std::array<const std::array<FT, N>*, 6> all_weights(const SD::Patch_weights<FT, N>& w)
{
  return {&w.position, &w.du, &w.dv, &w.duu, &w.duv, &w.dvv};
}

const char* const weight_names[6] = {"position", "du", "dv", "duu", "duv", "dvv"};

} // namespace

// the patch reproduces constants: position weights sum to 1, derivative weights to 0
TYPED_TEST(Patch_basis, weights_sum_to_one_and_derivatives_to_zero_exactly)
{
  using Patch = TypeParam;
  for(const auto& [u, v] : parameters<Patch>()) {
    const auto w = weights<Patch>(u, v);
    const auto arrays = all_weights(w);
    for(std::size_t i = 0; i < arrays.size(); ++i)
      EXPECT_EQ(sum(*arrays[i]), Q(i == 0 ? 1 : 0)) << weight_names[i] << " at " << u << ", " << v;
  }
}

// Epeck's lazy exact FT too: sums and linear precision of the position
TYPED_TEST(Patch_basis, weights_are_exact_in_epeck)
{
  using Patch = TypeParam;
  using E = CGAL::Epeck::FT;
  const E u = E(2) / E(7), v = E(3) / E(5);
  const auto w = weights<Patch>(u, v);
  E x(0), y(0);
  for(std::size_t k = 0; k < Patch::size; ++k) {
    x += w.position[k] * E(Patch::lattice(k)[0]);
    y += w.position[k] * E(Patch::lattice(k)[1]);
  }
  EXPECT_TRUE(sum(w.position) == E(1) && sum(w.du) == E(0) && sum(w.dvv) == E(0));
  EXPECT_TRUE(x == u && y == v);
}

// linear precision: control point k at its lattice position (i, j) gives the
// patch (u, v), its first derivatives the unit vectors, its second ones 0
TYPED_TEST(Patch_basis, linear_precision_is_exact)
{
  using Patch = TypeParam;
  const auto x = [](std::size_t k) { return Q(Patch::lattice(k)[0]); };
  const auto y = [](std::size_t k) { return Q(Patch::lattice(k)[1]); };
  for(const auto& [u, v] : parameters<Patch>()) {
    const auto w = weights<Patch>(u, v);
    const std::array<std::array<Q, 2>, 6> expected = {
      {{u, v}, {Q(1), Q(0)}, {Q(0), Q(1)}, {Q(0), Q(0)}, {Q(0), Q(0)}, {Q(0), Q(0)}}};
    const auto arrays = all_weights(w);
    for(std::size_t i = 0; i < arrays.size(); ++i) {
      EXPECT_EQ(combine(*arrays[i], x), expected[i][0]) << weight_names[i] << " x at " << u << ", " << v;
      EXPECT_EQ(combine(*arrays[i], y), expected[i][1]) << weight_names[i] << " y at " << u << ", " << v;
    }
  }
}

// at each corner of the face the position weights are the scheme's regular
// limit mask centred at that corner's control point
TYPED_TEST(Patch_basis, corners_are_the_regular_limit_masks)
{
  using Patch = TypeParam;
  for(const Lattice& corner : Patch::corners()) {
    const auto w = weights<Patch>(Q(corner[0]), Q(corner[1]));
    for(std::size_t k = 0; k < Patch::size; ++k) {
      const Lattice at = Patch::lattice(k);
      EXPECT_EQ(w.position[k], Patch::limit_mask({at[0] - corner[0], at[1] - corner[1]}))
        << "point " << k << " at corner (" << corner[0] << ", " << corner[1] << ")";
    }
  }
}

/*
 * The derivatives are those of the position, exactly: every weight is a
 * polynomial of degree at most 4 in each variable, so the central difference
 * D(h) = (f(t + h) - f(t - h)) / 2h is f' + h^2 f''' / 6 with no further
 * term, and (4 D(h) - D(2h)) / 3 is f' exactly; the same for the second
 * difference (f(t + h) - 2 f(t) + f(t - h)) / h^2 = f'' + h^2 f'''' / 12. The
 * mixed derivative is the difference along v of the derivative along u.
 */
TYPED_TEST(Patch_basis, derivatives_are_those_of_the_position_exactly)
{
  using Patch = TypeParam;
  const Q h(1, 8);
  for(const auto& [u, v] : parameters<Patch>()) {
    // (Q(...): the arguments are numbers, not expression templates of Boost.Multiprecision)
    const auto at = [&](int i, int j) { return weights<Patch>(Q(u + Q(i) * h), Q(v + Q(j) * h)); };
    const auto w = at(0, 0);
    const auto pu1 = at(1, 0), mu1 = at(-1, 0), pu2 = at(2, 0), mu2 = at(-2, 0);
    const auto pv1 = at(0, 1), mv1 = at(0, -1), pv2 = at(0, 2), mv2 = at(0, -2);
    for(std::size_t k = 0; k < Patch::size; ++k) {
      const auto first = [&](const Q& p1, const Q& m1, const Q& p2, const Q& m2) -> Q {
        return (Q(4) * (p1 - m1) / (Q(2) * h) - (p2 - m2) / (Q(4) * h)) / Q(3);
      };
      const auto second = [&](const Q& c, const Q& p1, const Q& m1, const Q& p2, const Q& m2) -> Q {
        return (Q(4) * (p1 - Q(2) * c + m1) / (h * h) - (p2 - Q(2) * c + m2) / (Q(4) * h * h)) / Q(3);
      };
      EXPECT_EQ(w.du[k], first(pu1.position[k], mu1.position[k], pu2.position[k], mu2.position[k])) << k;
      EXPECT_EQ(w.dv[k], first(pv1.position[k], mv1.position[k], pv2.position[k], mv2.position[k])) << k;
      EXPECT_EQ(w.duu[k], second(w.position[k], pu1.position[k], mu1.position[k], pu2.position[k], mu2.position[k]))
        << k;
      EXPECT_EQ(w.dvv[k], second(w.position[k], pv1.position[k], mv1.position[k], pv2.position[k], mv2.position[k]))
        << k;
      EXPECT_EQ(w.duv[k], first(pv1.du[k], mv1.du[k], pv2.du[k], mv2.du[k])) << k;
      EXPECT_EQ(w.duv[k], first(pu1.dv[k], mu1.dv[k], pu2.dv[k], mu2.dv[k])) << k;
    }
  }
}

// in double: central differences of the position (h = 1e-5) give the first
// derivatives, and differences of the first derivatives the second ones
TYPED_TEST(Patch_basis, derivatives_match_finite_differences_in_double)
{
  using Patch = TypeParam;
  const double h = 1e-5;
  const std::array<std::array<double, 2>, 5> points = {
    {{0.3, 0.4}, {0.1, 0.7}, {0.55, 0.2}, {0.25, 0.25}, {0.6, 0.35}}};
  for(const auto& [u, v] : points) {
    const auto w = weights<Patch>(u, v);
    const auto pu = weights<Patch>(u + h, v), mu = weights<Patch>(u - h, v);
    const auto pv = weights<Patch>(u, v + h), mv = weights<Patch>(u, v - h);
    const auto near = [](double difference, double exact) {
      return std::abs(difference - exact) <= 1e-8 * std::max(1.0, std::abs(exact));
    };
    for(std::size_t k = 0; k < Patch::size; ++k) {
      const auto d = [h](double p, double m) { return (p - m) / (2 * h); };
      EXPECT_PRED2(near, d(pu.position[k], mu.position[k]), w.du[k]) << k << " at " << u << ", " << v;
      EXPECT_PRED2(near, d(pv.position[k], mv.position[k]), w.dv[k]) << k << " at " << u << ", " << v;
      EXPECT_PRED2(near, d(pu.du[k], mu.du[k]), w.duu[k]) << k << " at " << u << ", " << v;
      EXPECT_PRED2(near, d(pv.dv[k], mv.dv[k]), w.dvv[k]) << k << " at " << u << ", " << v;
      EXPECT_PRED2(near, d(pv.du[k], mv.du[k]), w.duv[k]) << k << " at " << u << ", " << v;
      EXPECT_PRED2(near, d(pu.dv[k], mu.dv[k]), w.duv[k]) << k << " at " << u << ", " << v;
    }
  }
}

/*
 * Against the package: a grid of the patch's scheme with generic rational
 * points (not planar), whose base face `Patch::face` and its 1-ring are
 * regular and far from the border, refined L = 1, 2, 3 levels with
 * `face_origin_map`. The refined vertex at a dyadic (u, v) of the base face
 * is the corner of a refined face whose Face_origin names the base face and
 * gives that corner the parameter (u, v) (provenance, doc/provenance.md);
 * its limit position (project_to_limit on the refined mesh) must be the
 * patch at (u, v) over the base points, exactly. The control points are read
 * off the base face's corners: lattice point (i, j) is the grid vertex
 * c0 + i (c1 - c0) + j (c_v - c0), c_v the corner at (0, 1).
 */
TYPED_TEST(Patch_basis, equals_the_refined_limit_at_dyadic_parameters_exactly)
{
  using Patch = TypeParam;
  const int n = Patch::cells;
  testing_utils::Rationals random;
  const Exact_mesh base = testing_utils::grid<Exact_mesh>(
    n, n,
    [&random](int i, int j) {
      const Q x = Q(i) + random.next<Q>() / Q(4), y = Q(j) + random.next<Q>() / Q(4);
      return QK::Point_3(x, y, random.next<Q>());
    },
    Patch::triangle);
  const auto base_face = *std::next(faces(base).begin(), std::ptrdiff_t(Patch::face));
  std::vector<Lattice> corner; // the grid (i, j) of the face's corners
  for(auto h : CGAL::halfedges_around_face(halfedge(base_face, base), base)) {
    const int id = int(target(h, base).idx());
    corner.push_back({id % (n + 1), id / (n + 1)});
  }
  ASSERT_EQ(corner.size(), Patch::corners().size());
  std::vector<QK::Point_3> control;
  for(std::size_t k = 0; k < Patch::size; ++k) {
    const Lattice l = Patch::lattice(k);
    const Lattice& c0 = corner[0];
    const Lattice& c1 = corner[1];
    const Lattice& cv = corner[Patch::corner_at_v];
    const int i = c0[0] + l[0] * (c1[0] - c0[0]) + l[1] * (cv[0] - c0[0]);
    const int j = c0[1] + l[0] * (c1[1] - c0[1]) + l[1] * (cv[1] - c0[1]);
    ASSERT_TRUE(i > 0 && i < n && j > 0 && j < n) << "point " << k << " is on or beyond the border";
    control.push_back(base.point(testing_utils::grid_vertex<Exact_mesh>(n, i, j)));
  }
  const auto patch_at = [&control](const Q& u, const Q& v) {
    const auto w = weights<Patch>(u, v);
    QK::Vector_3 s = CGAL::NULL_VECTOR;
    for(std::size_t k = 0; k < Patch::size; ++k)
      s = s + w.position[k] * (control[k] - CGAL::ORIGIN);
    return CGAL::ORIGIN + s;
  };

  for(int levels = 1; levels <= 3; ++levels) {
    Exact_mesh mesh = base;
    auto origin = mesh.add_property_map<Exact_mesh::Face_index, SD::Face_origin>("f:origin").first;
    SD::Carried_data<Exact_mesh> data;
    data.face_origin_map(origin);
    Patch::refine(mesh, levels, data);
    std::map<std::array<double, 2>, Exact_mesh::Vertex_index> at; // the refined vertices of the base face
    for(auto f : faces(mesh)) {
      if(origin[f].face != Patch::face)
        continue;
      int i = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
        at[origin[f].uv[std::size_t(i++)]] = target(h, mesh);
    }
    Exact_mesh limit = mesh;
    Patch::limit(limit);

    const int steps = 1 << levels;
    std::size_t checked = 0, told_apart = 0;
    for(int a = 0; a <= steps; ++a)
      for(int b = 0; b <= steps; ++b) {
        const Q u(a, steps), v(b, steps);
        if(!Patch::in_domain(u, v))
          continue;
        const auto found = at.find({double(a) / steps, double(b) / steps});
        ASSERT_NE(found, at.end()) << "no refined vertex at " << u << ", " << v << ", level " << levels;
        const QK::Point_3& expected = limit.point(found->second);
        EXPECT_EQ(patch_at(u, v), expected) << "at " << u << ", " << v << ", level " << levels;
        ++checked;
        // the points are generic enough to tell the parameter from its mirror image
        if(a != b && Patch::in_domain(v, u)) {
          EXPECT_NE(patch_at(v, u), expected) << "at " << u << ", " << v << ", level " << levels;
          ++told_apart;
        }
      }
    const std::size_t side = std::size_t(steps) + 1;
    EXPECT_EQ(checked, Patch::triangle ? side * (side + 1) / 2 : side * side) << "level " << levels;
    EXPECT_GT(told_apart, 0u);
  }
}
