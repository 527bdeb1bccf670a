// Curve schemes and hosts, typed over kernels: exact equality where the kernel is exact.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>

#include <gtest/gtest.h>
#include <boost/range/iterator_range.hpp>

#include <cmath>
#include <limits>
#include <list>
#include <string>
#include <type_traits>
#include <vector>

namespace S = CGAL::Subdiv;

namespace {

template <class FT>
constexpr bool is_exact()
{
  return !std::is_floating_point<FT>::value;
}

template <class FT>
FT frac(int p, int q)
{
  return FT(p) / FT(q);
}

// equal in an exact kernel, equal to 1e-12 in a floating-point one
template <class Point>
::testing::AssertionResult same_point(const Point& a, const Point& b)
{
  using FT = S::internal::Point_FT<Point>;
  if constexpr(is_exact<FT>()) {
    if(a == b)
      return ::testing::AssertionSuccess();
  } else {
    if(CGAL::to_double(CGAL::squared_distance(a, b)) <= 1e-24)
      return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "(" << a << ") != (" << b << ")";
}

template <class Point>
::testing::AssertionResult same_points(const std::vector<Point>& a, const std::vector<Point>& b)
{
  if(a.size() != b.size())
    return ::testing::AssertionFailure() << "sizes " << a.size() << " != " << b.size();
  for(std::size_t i = 0; i < a.size(); ++i) {
    auto r = same_point(a[i], b[i]);
    if(!r)
      return r << " at index " << i;
  }
  return ::testing::AssertionSuccess();
}

template <class K>
std::vector<typename K::Point_2> star()
{
  using P = typename K::Point_2;
  return {P(0, 0), P(4, 1), P(8, 0), P(7, 4), P(8, 8), P(4, 6), P(0, 8), P(1, 4)};
}

template <class K>
std::vector<typename K::Point_3> helix()
{
  using P = typename K::Point_3;
  return {P(1, 0, 0), P(0, 1, 1), P(-1, 0, 2), P(0, -1, 3), P(1, 0, 4), P(0, 1, 5), P(-1, 0, 6)};
}

template <class Stencil>
std::string describe(const Stencil& s)
{
  std::string out;
  for(const auto& t : s.terms())
    out += " " + std::to_string(t.first) + ":" + std::to_string(CGAL::to_double(t.second));
  return out;
}

template <class K>
class Curve_schemes : public ::testing::Test
{};

using Kernels =
  ::testing::Types<CGAL::Simple_cartesian<double>, CGAL::Exact_predicates_inexact_constructions_kernel,
                   CGAL::Exact_predicates_exact_constructions_kernel, CGAL::Simple_cartesian<CGAL::Exact_rational>>;
TYPED_TEST_SUITE(Curve_schemes, Kernels);

} // namespace

TYPED_TEST(Curve_schemes, every_rule_sums_to_one)
{
  using FT = typename TypeParam::FT;
  const auto check = [](const auto& scheme) {
    for(int parity : {0, 1})
      EXPECT_TRUE(S::rule(scheme, parity).weight_sum() == FT(1)) << scheme.name() << " parity " << parity;
  };
  check(S::Chaikin_scheme<FT>());
  check(S::Corner_cutting_scheme<FT>(frac<FT>(1, 10), frac<FT>(7, 10)));
  check(S::Four_point_scheme<FT>());
  check(S::Four_point_scheme<FT>(frac<FT>(3, 16)));
  for(int k = 1; k <= 9; ++k)
    check(S::Uniform_bspline_scheme<FT>(k));
  for(int d = 1; d <= 6; ++d) {
    S::Bezier_scheme<FT> bezier(d);
    for(int j = 0; j <= 2 * d; ++j) {
      S::Stencil<int, FT> mask;
      bezier.split_mask(j, mask);
      EXPECT_TRUE(mask.weight_sum() == FT(1)) << "Bezier degree " << d << " point " << j;
    }
  }
}

TYPED_TEST(Curve_schemes, bspline_masks_from_doubling_and_averaging_are_the_closed_forms)
{
  using FT = typename TypeParam::FT;
  // degree 1: midpoints
  S::Uniform_bspline_scheme<FT> linear(1);
  EXPECT_TRUE(S::rule(linear, 0).size() == 1 && S::rule(linear, 0).weight(0) == FT(1));
  EXPECT_TRUE(S::rule(linear, 1).weight(0) == frac<FT>(1, 2) && S::rule(linear, 1).weight(1) == frac<FT>(1, 2));
  // degree 2: Chaikin's 3/4, 1/4 and 1/4, 3/4
  S::Uniform_bspline_scheme<FT> quadratic(2);
  EXPECT_TRUE(S::rule(quadratic, 0).weight(0) == frac<FT>(3, 4) && S::rule(quadratic, 0).weight(1) == frac<FT>(1, 4));
  EXPECT_TRUE(S::rule(quadratic, 1).weight(0) == frac<FT>(1, 4) && S::rule(quadratic, 1).weight(1) == frac<FT>(3, 4));
  EXPECT_EQ(S::rule(quadratic, 0).size(), 2u);
  // degree 3: vertex rule 1/8, 6/8, 1/8 and edge rule 1/2, 1/2
  S::Uniform_bspline_scheme<FT> cubic(3);
  const auto vertex = S::rule(cubic, 0), edge = S::rule(cubic, 1);
  EXPECT_EQ(vertex.size(), 3u) << describe(vertex);
  EXPECT_TRUE(vertex.weight(-1) == frac<FT>(1, 8) && vertex.weight(0) == frac<FT>(6, 8) &&
              vertex.weight(1) == frac<FT>(1, 8))
    << describe(vertex);
  EXPECT_EQ(edge.size(), 2u);
  EXPECT_TRUE(edge.weight(0) == frac<FT>(1, 2) && edge.weight(1) == frac<FT>(1, 2));
  // degree 4 and 5: binomial coefficients C(k+1, j) / 2^k split into even and odd
  S::Uniform_bspline_scheme<FT> quartic(4);
  EXPECT_TRUE(S::rule(quartic, 0).weight(-1) == frac<FT>(1, 16) && S::rule(quartic, 0).weight(0) == frac<FT>(10, 16) &&
              S::rule(quartic, 0).weight(1) == frac<FT>(5, 16));
  EXPECT_TRUE(S::rule(quartic, 1).weight(0) == frac<FT>(5, 16) && S::rule(quartic, 1).weight(1) == frac<FT>(10, 16) &&
              S::rule(quartic, 1).weight(2) == frac<FT>(1, 16));
  S::Uniform_bspline_scheme<FT> quintic(5);
  EXPECT_TRUE(S::rule(quintic, 0).weight(-1) == frac<FT>(6, 32) && S::rule(quintic, 0).weight(0) == frac<FT>(20, 32) &&
              S::rule(quintic, 0).weight(1) == frac<FT>(6, 32));
  EXPECT_TRUE(S::rule(quintic, 1).weight(-1) == frac<FT>(1, 32) && S::rule(quintic, 1).weight(0) == frac<FT>(15, 32) &&
              S::rule(quintic, 1).weight(1) == frac<FT>(15, 32) && S::rule(quintic, 1).weight(2) == frac<FT>(1, 32));
}

TYPED_TEST(Curve_schemes, degree_two_bspline_and_quarter_corner_cutting_equal_chaikin)
{
  using FT = typename TypeParam::FT;
  const auto points = star<TypeParam>();
  for(bool closed : {false, true}) {
    const auto options = S::parameters::number_of_iterations(3).closed(closed);
    const auto chaikin = S::refine_polyline(points, S::Chaikin_scheme<FT>(), options);
    EXPECT_EQ(chaikin.size(), closed ? 64u : 50u);
    EXPECT_TRUE(same_points(chaikin, S::refine_polyline(points, S::Uniform_bspline_scheme<FT>(2), options)));
    EXPECT_TRUE(same_points(
      chaikin, S::refine_polyline(points, S::Corner_cutting_scheme<FT>(frac<FT>(1, 4), frac<FT>(3, 4)), options)));
  }
  // Q = 3/4 P0 + 1/4 P1 and R = 1/4 P0 + 3/4 P1 on the first edge
  const auto once = S::refine_polyline(points, S::Chaikin_scheme<FT>());
  using P = typename TypeParam::Point_2;
  EXPECT_TRUE(same_point(once[0], P(1, frac<FT>(1, 4))));
  EXPECT_TRUE(same_point(once[1], P(3, frac<FT>(3, 4))));
}

TYPED_TEST(Curve_schemes, lane_riesenfeld_on_points_equals_the_masks)
{
  using FT = typename TypeParam::FT;
  const auto points = star<TypeParam>();
  for(int k = 1; k <= 6; ++k)
    for(bool closed : {false, true}) {
      const auto by_mask = S::refine_polyline(points, S::Uniform_bspline_scheme<FT>(k),
                                              S::parameters::closed(closed).end_rule(S::End_rule::shrink));
      EXPECT_TRUE(same_points(by_mask, S::lane_riesenfeld_refine(points, k, S::parameters::closed(closed))))
        << "degree " << k << (closed ? " closed" : " open");
    }
}

// The masks are read off in closed form (binomials); here they are checked
// against the doubling and averagings themselves, run on a unit impulse at
// source c, at every degree: new point 2j + r holds the weight of offset c - j
// in rule r (every offset of both rules, and the zeros outside them).
TYPED_TEST(Curve_schemes, bspline_masks_are_lane_riesenfeld_on_an_impulse_at_every_degree)
{
  using FT = typename TypeParam::FT;
  using P = typename TypeParam::Point_2;
  for(int k = 1; k <= S::Uniform_bspline_scheme<FT>::max_degree; ++k) {
    const S::Uniform_bspline_scheme<FT> scheme(k);
    const int n = 2 * k + 6, c = n / 2;
    std::vector<P> impulse(n, P(0, 0));
    impulse[c] = P(1, 0);
    const auto refined = S::lane_riesenfeld_refine(impulse, k, S::parameters::closed(true));
    ASSERT_EQ(refined.size(), std::size_t(2 * n));
    for(int j = 0; j < n; ++j)
      for(int r : {0, 1})
        EXPECT_TRUE(
          same_points(std::vector<P>{refined[2 * j + r]}, std::vector<P>{P(S::rule(scheme, r).weight(c - j), 0)}))
          << "degree " << k << " rule " << r << " offset " << c - j;
  }
}

TYPED_TEST(Curve_schemes, cubic_bspline_closed_form_rules)
{
  using FT = typename TypeParam::FT;
  using P = typename TypeParam::Point_2;
  const auto points = star<TypeParam>();
  const auto refined = S::refine_polyline(points, S::Uniform_bspline_scheme<FT>(3), S::parameters::closed(true));
  ASSERT_EQ(refined.size(), 2 * points.size());
  const std::size_t n = points.size();
  for(std::size_t i = 0; i < n; ++i) {
    const P& prev = points[(i + n - 1) % n];
    const P& here = points[i];
    const P& next = points[(i + 1) % n];
    const P vertex_point(frac<FT>(1, 8) * prev.x() + frac<FT>(6, 8) * here.x() + frac<FT>(1, 8) * next.x(),
                         frac<FT>(1, 8) * prev.y() + frac<FT>(6, 8) * here.y() + frac<FT>(1, 8) * next.y());
    EXPECT_TRUE(same_point(refined[2 * i], vertex_point));
    EXPECT_TRUE(same_point(refined[2 * i + 1], CGAL::midpoint(here, next)));
  }
}

TYPED_TEST(Curve_schemes, four_point_keeps_every_old_point_and_uses_its_weights)
{
  using FT = typename TypeParam::FT;
  const auto points = star<TypeParam>();
  const S::Four_point_scheme<FT> scheme; // w = 1/16
  const auto odd = S::rule(scheme, 1);
  EXPECT_TRUE(odd.weight(-1) == frac<FT>(-1, 16) && odd.weight(0) == frac<FT>(9, 16) &&
              odd.weight(1) == frac<FT>(9, 16) && odd.weight(2) == frac<FT>(-1, 16));

  for(bool closed : {false, true}) {
    const auto refined = S::refine_polyline(
      points, scheme, S::parameters::number_of_iterations(3).closed(closed).end_rule(S::End_rule::keep_ends));
    ASSERT_EQ(refined.size(), closed ? 8 * points.size() : 8 * (points.size() - 1) + 1);
    for(std::size_t i = 0; i < points.size(); ++i)
      EXPECT_TRUE(same_point(refined[8 * i], points[i])) << "old point " << i;
  }
  // in shrink mode the kept points still sit at even positions
  const S::internal::Polyline_level<S::Four_point_scheme<FT>> level(scheme, points.size(), false, S::End_rule::shrink);
  EXPECT_EQ(level.first_position(), 2); // the first new point is old point 1
  const auto shrunk = S::refine_polyline(points, scheme);
  EXPECT_EQ(shrunk.size(), 2 * points.size() - 5);
  EXPECT_TRUE(same_point(shrunk[0], points[1]));
  EXPECT_TRUE(same_point(shrunk.back(), points[points.size() - 2]));
}

TYPED_TEST(Curve_schemes, open_end_rules)
{
  using FT = typename TypeParam::FT;
  using P = typename TypeParam::Point_2;
  const auto points = star<TypeParam>();
  const S::Uniform_bspline_scheme<FT> cubic(3);

  // shrink: the end vertices drop out; the first new point is the midpoint of the first edge
  const auto shrunk = S::refine_polyline(points, cubic);
  EXPECT_EQ(shrunk.size(), 2 * points.size() - 3);
  EXPECT_TRUE(same_point(shrunk.front(), CGAL::midpoint(points[0], points[1])));
  // after many levels the first point approaches the limit point of p1, (p0 + 4 p1 + p2) / 6
  const auto deep = S::refine_polyline(points, cubic, S::parameters::number_of_iterations(12));
  const P limit(frac<FT>(1, 6) * (points[0].x() + 4 * points[1].x() + points[2].x()),
                frac<FT>(1, 6) * (points[0].y() + 4 * points[1].y() + points[2].y()));
  EXPECT_LT(CGAL::to_double(CGAL::squared_distance(deep.front(), limit)), 1e-6);

  // keep_ends: every scheme keeps the two end points
  const auto keeps_ends = [&](const auto& scheme) {
    const auto refined =
      S::refine_polyline(points, scheme, S::parameters::number_of_iterations(3).end_rule(S::End_rule::keep_ends));
    EXPECT_TRUE(same_point(refined.front(), points.front())) << scheme.name();
    EXPECT_TRUE(same_point(refined.back(), points.back())) << scheme.name();
  };
  keeps_ends(cubic);
  keeps_ends(S::Chaikin_scheme<FT>());
  keeps_ends(S::Corner_cutting_scheme<FT>(frac<FT>(1, 10), frac<FT>(7, 10)));
  keeps_ends(S::Four_point_scheme<FT>());
  for(int k = 1; k <= 6; ++k)
    keeps_ends(S::Uniform_bspline_scheme<FT>(k));

  // the cubic end rule is the reflection p_-1 = 2 p_0 - p_1: p'_1 = midpoint of the first edge
  const auto kept = S::refine_polyline(points, cubic, S::parameters::end_rule(S::End_rule::keep_ends));
  EXPECT_EQ(kept.size(), 2 * points.size() - 1);
  EXPECT_TRUE(same_point(kept[1], CGAL::midpoint(points[0], points[1])));
}

TYPED_TEST(Curve_schemes, de_casteljau_halves_reproduce_the_curve)
{
  using FT = typename TypeParam::FT;
  using P = typename TypeParam::Point_2;
  const std::vector<P> cubic{P(0, 0), P(1, 3), P(4, 3), P(6, -1)};
  const auto halves = S::de_casteljau_split(cubic, frac<FT>(1, 2));
  // P01, P012, P0123 and P123, P23
  EXPECT_TRUE(same_point(halves.first[1], P(frac<FT>(1, 2), frac<FT>(3, 2))));
  EXPECT_TRUE(same_point(halves.first[2], P(frac<FT>(6, 4), frac<FT>(9, 4))));
  EXPECT_TRUE(same_point(halves.first[3], P(frac<FT>(21, 8), frac<FT>(17, 8))));
  EXPECT_TRUE(same_point(halves.second[0], halves.first[3]));
  EXPECT_TRUE(same_point(halves.second[1], P(frac<FT>(15, 4), 2)));
  EXPECT_TRUE(same_point(halves.second[2], P(5, 1)));

  // the masks make the same split
  const auto split = S::bezier_subdivision(cubic, 3);
  ASSERT_EQ(split.size(), 7u);
  for(std::size_t j = 0; j < 4; ++j) {
    EXPECT_TRUE(same_point(split[j], halves.first[j]));
    EXPECT_TRUE(same_point(split[3 + j], halves.second[j]));
  }
  // the two halves are the curve on [0, 1/2] and [1/2, 1]: B_left(u) = B(u/2), B_right(u) = B((1+u)/2)
  for(int k = 0; k <= 8; ++k) {
    const FT u = frac<FT>(k, 8);
    EXPECT_TRUE(same_point(S::bezier_point(halves.first, u), S::bezier_point(cubic, u / 2)));
    EXPECT_TRUE(same_point(S::bezier_point(halves.second, u), S::bezier_point(cubic, (1 + u) / 2)));
  }
  // every degree: the halves at any level hold curve points at dyadic parameters
  for(int d = 1; d <= 5; ++d) {
    std::vector<P> control;
    for(int i = 0; i <= d; ++i)
      control.push_back(P(i, (i * i * 7) % 5 - 2));
    const auto refined = S::bezier_subdivision(control, d, S::parameters::number_of_iterations(3));
    ASSERT_EQ(refined.size(), static_cast<std::size_t>(8 * d + 1));
    for(int s = 0; s <= 8; ++s)
      EXPECT_TRUE(same_point(refined[s * d], S::bezier_point(control, frac<FT>(s, 8)))) << "degree " << d;
  }
}

TYPED_TEST(Curve_schemes, bezier_chains_open_closed_and_to_tolerance)
{
  using FT = typename TypeParam::FT;
  using P = typename TypeParam::Point_2;
  // a closed chain of two quadratic segments
  const std::vector<P> ring{P(0, 0), P(2, -1), P(4, 0), P(2, 3)};
  const auto closed = S::bezier_subdivision(ring, 2, S::parameters::closed(true).number_of_iterations(2));
  EXPECT_EQ(closed.size(), 16u);
  EXPECT_TRUE(same_point(closed[0], ring[0]));
  EXPECT_TRUE(same_point(closed[8], ring[2]));

  // enough subdivisions: every piece within the tolerance of its chord
  const std::vector<P> cubic{P(0, 0), P(1, 3), P(4, 3), P(6, -1)};
  const FT tolerance = frac<FT>(1, 100);
  const auto adaptive = S::bezier_subdivision_to_tolerance(cubic, 3, tolerance);
  ASSERT_EQ((adaptive.size() - 1) % 3, 0u);
  EXPECT_GT(adaptive.size(), 7u);
  EXPECT_TRUE(same_point(adaptive.front(), cubic.front()));
  EXPECT_TRUE(same_point(adaptive.back(), cubic.back()));
  for(std::size_t s = 0; s + 3 < adaptive.size(); s += 3) {
    const std::vector<P> piece(adaptive.begin() + s, adaptive.begin() + s + 4);
    EXPECT_TRUE(S::internal::is_flat(piece, tolerance * tolerance)) << "piece at " << s;
  }
  // a straight control polygon is flat at once
  const std::vector<P> straight{P(0, 0), P(1, 1), P(2, 2), P(3, 3)};
  EXPECT_EQ(S::bezier_subdivision_to_tolerance(straight, 3, tolerance).size(), 4u);
}

// Named parameters and point ranges only change how a call is written: every
// way of writing the same call gives the same points (exactly, in an exact kernel).
TYPED_TEST(Curve_schemes, any_point_range_gives_the_same_points)
{
  using FT = typename TypeParam::FT;
  using P = typename TypeParam::Point_2;
  const std::vector<P> vector = star<TypeParam>();
  const std::list<P> list(vector.begin(), vector.end());
  const auto range = boost::make_iterator_range(list.begin(), list.end());
  const S::Four_point_scheme<FT> four_point;
  const auto np = S::parameters::number_of_iterations(3).end_rule(S::End_rule::keep_ends);

  const auto from_vector = S::refine_polyline(vector, four_point, np);
  ASSERT_EQ(from_vector.size(), 57u); // keep_ends of a primal scheme: 2n - 1 points per level
  EXPECT_TRUE(same_points(S::refine_polyline(list, four_point, np), from_vector));
  EXPECT_TRUE(same_points(S::refine_polyline(range, four_point, np), from_vector));
  // the end points are kept; the first new point is the reflected four-point rule
  EXPECT_TRUE(same_point(from_vector.front(), vector.front()));
  EXPECT_TRUE(same_point(from_vector.back(), vector.back()));

  const std::vector<P> chain(vector.begin(), vector.begin() + 7); // two cubic segments
  const std::list<P> chain_list(chain.begin(), chain.end());
  const auto bezier = S::bezier_subdivision(chain, 3, S::parameters::number_of_iterations(2));
  EXPECT_EQ(bezier.size(), 25u);
  EXPECT_TRUE(same_points(S::bezier_subdivision(chain_list, 3, S::parameters::number_of_iterations(2)), bezier));
  EXPECT_TRUE(same_point(S::bezier_point(chain_list, frac<FT>(1, 2)), S::bezier_point(chain, frac<FT>(1, 2))));
  EXPECT_TRUE(same_points(S::de_casteljau_split(chain_list, frac<FT>(1, 3)).second,
                          S::de_casteljau_split(chain, frac<FT>(1, 3)).second));

  EXPECT_TRUE(same_points(S::lane_riesenfeld_refine(list, 3, S::parameters::closed(true)),
                          S::lane_riesenfeld_refine(vector, 3, S::parameters::closed(true))));
}

TYPED_TEST(Curve_schemes, cgal_and_subdiv_named_parameters_agree)
{
  using FT = typename TypeParam::FT;
  const auto points = star<TypeParam>();
  const S::Uniform_bspline_scheme<FT> cubic(3);
  const auto ours = S::refine_polyline(points, cubic, S::parameters::number_of_iterations(2));
  const auto cgal = S::refine_polyline(points, cubic, CGAL::parameters::number_of_iterations(2));
  EXPECT_EQ(ours.size(), 23u); // shrink: the cubic B-spline makes 2n - 3 points, 8 -> 13 -> 23
  EXPECT_TRUE(same_points(cgal, ours));
  // any integer type, as in CGAL
  EXPECT_TRUE(same_points(S::refine_polyline(points, cubic, CGAL::parameters::number_of_iterations(2u)), ours));

  const std::vector<typename TypeParam::Point_2> chain(points.begin(), points.begin() + 7);
  EXPECT_TRUE(same_points(S::bezier_subdivision(chain, 3, CGAL::parameters::number_of_iterations(2)),
                          S::bezier_subdivision(chain, 3, S::parameters::number_of_iterations(2))));
  EXPECT_TRUE(same_points(S::lane_riesenfeld_refine(points, 3, CGAL::parameters::number_of_iterations(2)),
                          S::lane_riesenfeld_refine(points, 3, S::parameters::number_of_iterations(2))));
}

TYPED_TEST(Curve_schemes, named_parameters_in_any_order_give_the_same_points)
{
  using FT = typename TypeParam::FT;
  const auto points = star<TypeParam>();
  const S::Chaikin_scheme<FT> chaikin;
  namespace np = S::parameters;
  const auto first = S::refine_polyline(
    points, chaikin, np::number_of_iterations(3).closed(true).end_rule(S::End_rule::keep_ends).max_output_points(100));
  ASSERT_EQ(first.size(), 64u); // closed: end_rule does not apply
  EXPECT_TRUE(
    same_points(S::refine_polyline(
                  points, chaikin,
                  np::max_output_points(100).end_rule(S::End_rule::keep_ends).closed(true).number_of_iterations(3)),
                first));
  EXPECT_TRUE(same_points(S::refine_polyline(points, chaikin,
                                             np::closed(true).max_output_points(100).number_of_iterations(3).end_rule(
                                               S::End_rule::keep_ends)),
                          first));
  EXPECT_TRUE(
    same_points(S::refine_polyline(
                  points, chaikin,
                  np::end_rule(S::End_rule::keep_ends).number_of_iterations(3).max_output_points(100).closed(true)),
                first));
  // the first point of level 1 is 3/4 P0 + 1/4 P1: (1, 1/4); the chain changed nothing
  EXPECT_TRUE(same_point(S::refine_polyline(points, chaikin, np::closed(true).number_of_iterations(1))[0],
                         typename TypeParam::Point_2(1, frac<FT>(1, 4))));

  // the defaults are those of the chain written out
  const auto defaults = S::refine_polyline(points, chaikin);
  EXPECT_TRUE(same_points(S::refine_polyline(points, chaikin, np::default_values()), defaults));
  EXPECT_TRUE(same_points(S::refine_polyline(points, chaikin,
                                             np::number_of_iterations(1)
                                               .closed(false)
                                               .end_rule(S::End_rule::shrink)
                                               .max_output_points(S::default_max_output_points)),
                          defaults));

  // Bezier: levels or a tolerance, in any order with the rest
  const std::vector<typename TypeParam::Point_2> ring(points.begin(), points.begin() + 6); // two closed cubics
  const auto levels = S::bezier_subdivision(ring, 3, np::number_of_iterations(2).closed(true).max_output_points(100));
  EXPECT_EQ(levels.size(), 24u);
  EXPECT_TRUE(same_points(
    S::bezier_subdivision(ring, 3, np::max_output_points(100).closed(true).number_of_iterations(2)), levels));
  const FT tolerance = frac<FT>(1, 10);
  const auto flat = S::bezier_subdivision(ring, 3, np::flatness_tolerance(tolerance).closed(true));
  EXPECT_GT(flat.size(), 6u);
  EXPECT_TRUE(same_points(S::bezier_subdivision(ring, 3, np::closed(true).flatness_tolerance(tolerance)), flat));
  EXPECT_TRUE(same_points(S::bezier_subdivision_to_tolerance(ring, 3, tolerance, np::closed(true)), flat));

  // lane_riesenfeld_refine: several levels are refine_polyline's levels
  for(bool closed : {false, true})
    EXPECT_TRUE(same_points(
      S::lane_riesenfeld_refine(points, 3, np::closed(closed).number_of_iterations(2)),
      S::refine_polyline(points, S::Uniform_bspline_scheme<FT>(3), np::number_of_iterations(2).closed(closed))))
      << (closed ? "closed" : "open");
}

TYPED_TEST(Curve_schemes, named_parameter_limits_are_refused)
{
  using FT = typename TypeParam::FT;
  using P = typename TypeParam::Point_2;
  const auto points = star<TypeParam>();
  namespace np = S::parameters;
  const auto refused = [](const auto& call, const std::string& part) {
    try {
      call();
    } catch(const S::Bad_input& e) {
      return ::testing::AssertionResult(std::string(e.what()).find(part) != std::string::npos) << e.what();
    }
    return ::testing::AssertionFailure() << "no exception";
  };
  // 8 points, 2 levels closed: 32 > 20
  EXPECT_TRUE(refused(
    [&] {
      S::refine_polyline(points, S::Chaikin_scheme<FT>(),
                         np::closed(true).number_of_iterations(2).max_output_points(20));
    },
    "max_output_points"));
  EXPECT_EQ(
    S::refine_polyline(points, S::Chaikin_scheme<FT>(), np::max_output_points(32).number_of_iterations(2).closed(true))
      .size(),
    32u);
  const std::vector<P> chain(points.begin(), points.begin() + 7);
  EXPECT_TRUE(refused([&] { S::bezier_subdivision(chain, 3, np::number_of_iterations(3).max_output_points(40)); },
                      "max_output_points"));
  EXPECT_TRUE(
    refused([&] { S::bezier_subdivision(chain, 3, np::flatness_tolerance(frac<FT>(1, 1000)).max_output_points(8)); },
            "max_output_points"));
  EXPECT_TRUE(refused([&] { S::bezier_subdivision(chain, 3, np::number_of_iterations(2).flatness_tolerance(FT(1))); },
                      "not both"));
  EXPECT_TRUE(refused([&] { S::bezier_subdivision(chain, 3, np::flatness_tolerance(FT(-1))); }, "positive"));
  // a tiny tolerance is refused before any work, from the bound on the points
  // it may need (the control points' second differences)
  EXPECT_TRUE(refused([&] { S::bezier_subdivision(chain, 3, np::flatness_tolerance(FT(1) / FT(1e30))); },
                      "the flatness tolerance may need up to"));
  EXPECT_TRUE(refused([&] { S::lane_riesenfeld_refine(points, 3, np::number_of_iterations(-1)); }, "negative"));
  EXPECT_TRUE(refused(
    [&] {
      S::lane_riesenfeld_refine(std::vector<P>(points.begin(), points.begin() + 3), 5, np::number_of_iterations(2));
    },
    "shrank"));
}

TYPED_TEST(Curve_schemes, affine_invariance_and_3d)
{
  using FT = typename TypeParam::FT;
  using P3 = typename TypeParam::Point_3;
  using Transformation = typename TypeParam::Aff_transformation_3;
  const auto points = helix<TypeParam>();
  const Transformation t(2, 1, 0, 3, 0, 1, 1, -1, 1, 0, 3, 2);
  std::vector<P3> moved;
  for(const P3& p : points)
    moved.push_back(t.transform(p));
  const auto check = [&](const auto& scheme, bool closed) {
    const auto options = S::parameters::number_of_iterations(2).closed(closed).end_rule(S::End_rule::keep_ends);
    auto refined = S::refine_polyline(points, scheme, options);
    for(P3& p : refined)
      p = t.transform(p);
    EXPECT_TRUE(same_points(refined, S::refine_polyline(moved, scheme, options))) << scheme.name();
  };
  for(bool closed : {false, true}) {
    check(S::Chaikin_scheme<FT>(), closed);
    check(S::Four_point_scheme<FT>(frac<FT>(1, 10)), closed);
    check(S::Uniform_bspline_scheme<FT>(5), closed);
    check(S::Corner_cutting_scheme<FT>(frac<FT>(1, 5), frac<FT>(1, 2)), closed);
  }
}

TYPED_TEST(Curve_schemes, bad_input_is_refused_with_a_clear_message)
{
  using FT = typename TypeParam::FT;
  using P = typename TypeParam::Point_2;
  const auto message = [](const auto& call) -> std::string {
    try {
      call();
    } catch(const S::Bad_input& e) {
      return e.what();
    }
    return "no exception";
  };
  const auto contains = [](const std::string& text, const std::string& part) {
    return ::testing::AssertionResult(text.find(part) != std::string::npos) << "message: " << text;
  };
  const auto points = star<TypeParam>();
  const S::Chaikin_scheme<FT> chaikin;
  EXPECT_TRUE(contains(message([&] { S::refine_polyline(std::vector<P>(), chaikin); }), "empty"));
  EXPECT_TRUE(contains(message([&] { S::refine_polyline(std::vector<P>{P(0, 0)}, chaikin); }), "at least 2"));
  EXPECT_TRUE(contains(message([&] {
                         S::refine_polyline(std::vector<P>{P(0, 0), P(1, 1)}, chaikin, S::parameters::closed(true));
                       }),
                       "at least 3"));
  EXPECT_TRUE(contains(message([&] {
                         S::refine_polyline(std::vector<P>{P(0, 0), P(1, 0), P(2, 0)}, S::Four_point_scheme<FT>());
                       }),
                       "too short"));
  EXPECT_TRUE(contains(message([&] {
                         S::refine_polyline(std::vector<P>{P(0, 0), P(1, 0)}, S::Uniform_bspline_scheme<FT>(7),
                                            S::parameters::end_rule(S::End_rule::keep_ends));
                       }),
                       "too short"));
  EXPECT_TRUE(contains(message([&] { S::refine_polyline(points, chaikin, S::parameters::number_of_iterations(-1)); }),
                       "negative"));
  EXPECT_TRUE(contains(message([&] { S::refine_polyline(points, chaikin, S::parameters::number_of_iterations(40)); }),
                       "max_output_points"));
  EXPECT_TRUE(
    contains(message([&] { S::Corner_cutting_scheme<FT>(frac<FT>(3, 4), frac<FT>(1, 4)); }), "0 < a < b < 1"));
  EXPECT_TRUE(contains(message([&] { S::Corner_cutting_scheme<FT>(FT(0), frac<FT>(1, 4)); }), "0 < a < b < 1"));
  EXPECT_TRUE(contains(message([&] { S::Four_point_scheme<FT>(frac<FT>(1, 4)); }), "tension"));
  EXPECT_TRUE(contains(message([&] { S::Four_point_scheme<FT>(frac<FT>(-1, 16)); }), "tension"));
  EXPECT_TRUE(contains(message([&] { S::Uniform_bspline_scheme<FT>(0); }), "degree"));
  EXPECT_TRUE(contains(message([&] { S::Bezier_scheme<FT>(0); }), "degree"));
  EXPECT_TRUE(contains(message([&] { S::bezier_subdivision(points, 3); }), "m d + 1"));
  EXPECT_TRUE(contains(message([&] {
                         S::bezier_subdivision(std::vector<P>(points.begin(), points.begin() + 7), 3,
                                               S::parameters::closed(true));
                       }),
                       "multiple of d"));
  EXPECT_TRUE(contains(
    message([&] { S::bezier_subdivision_to_tolerance(std::vector<P>(points.begin(), points.begin() + 4), 3, FT(0)); }),
    "tolerance"));
  if constexpr(!is_exact<FT>()) {
    std::vector<P> broken = points;
    broken[5] = P(std::numeric_limits<double>::quiet_NaN(), 0);
    EXPECT_TRUE(contains(message([&] { S::refine_polyline(broken, chaikin); }), "point 5 has a non-finite"));
    broken[5] = P(std::numeric_limits<double>::infinity(), 0);
    EXPECT_TRUE(contains(message([&] { S::refine_polyline(broken, chaikin); }), "point 5 has a non-finite"));
  }
}
