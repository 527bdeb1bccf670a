// Stencil tables: the same masks as subdivide(), composed over levels.
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Subdiv/limit.h>
#include <CGAL/Subdiv/stencils/make_stencil_table.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <gtest/gtest.h>

#include "mesh_builders.h"
#include "mesh_test_utils.h"
#include "threads_test_utils.h"

#include <array>
#include <cmath>
#include <cstring>
#include <list>
#include <string>
#include <utility>
#include <vector>

namespace S = CGAL::Subdiv;
using KE = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using FT = KE::FT;
using Mesh = CGAL::Surface_mesh<KE::Point_3>;

namespace {

Mesh open_bipyramid_piece()
{
  // an octahedron with one face removed: valences 3 and 4, a border
  Mesh mesh;
  const KE::Point_3 p[6] = {KE::Point_3(0, 0, 1), KE::Point_3(0, 0, -1), KE::Point_3(1, 0, 0),
                            KE::Point_3(0, 1, 0), KE::Point_3(-1, 0, 0), KE::Point_3(0, -1, 0)};
  Mesh::Vertex_index v[6];
  for(int i = 0; i < 6; ++i)
    v[i] = mesh.add_vertex(p[i]);
  for(int i = 0; i < 4; ++i) {
    if(i != 2)
      mesh.add_face(v[0], v[2 + i], v[2 + (i + 1) % 4]);
    mesh.add_face(v[1], v[2 + (i + 1) % 4], v[2 + i]);
  }
  return mesh;
}

std::vector<KE::Point_3> points_of(const Mesh& mesh)
{
  std::vector<KE::Point_3> points;
  for(auto v : vertices(mesh))
    points.push_back(mesh.point(v));
  return points;
}

} // namespace

TEST(Stencil_table, three_levels_of_loop_in_one_table_equal_subdivide_exactly)
{
  const Mesh coarse = open_bipyramid_piece();
  Mesh refined;
  const auto table =
    S::make_stencil_table(coarse, S::Loop_mask<Mesh>(), S::parameters::number_of_iterations(3).refined_mesh(refined));
  Mesh reference = coarse;
  S::loop_subdivision(reference, CGAL::parameters::number_of_iterations(3));
  ASSERT_EQ(table.number_of_stencils(), num_vertices(reference));
  ASSERT_EQ(table.number_of_sources(), num_vertices(coarse));
  EXPECT_EQ(points_of(refined), points_of(reference));
  EXPECT_EQ(num_faces(refined), num_faces(reference));
  // every composed stencil still sums to exactly 1
  for(std::size_t i = 0; i < table.number_of_stencils(); ++i) {
    FT sum = 0;
    for(std::size_t t = table.stencil_begin(i); t < table.stencil_end(i); ++t)
      sum += table.weight(t);
    EXPECT_EQ(sum, FT(1)) << "stencil " << i;
  }
}

TEST(Stencil_table, re_evaluates_moved_control_points_and_other_data)
{
  const Mesh coarse = open_bipyramid_piece();
  const auto table =
    S::make_stencil_table(coarse, S::Loop_mask<Mesh, FT, S::Warren_beta>(), S::parameters::number_of_iterations(2));
  // move the control points: the table gives what subdividing the moved mesh gives
  Mesh moved = coarse;
  for(auto v : vertices(moved))
    moved.point(v) = moved.point(v) + KE::Vector_3(FT(int(v.idx()) % 3), FT(1) / FT(3), FT(int(v.idx())));
  std::vector<KE::Point_3> fine;
  table.apply(points_of(moved), fine);
  S::loop_warren_subdivision(moved, CGAL::parameters::number_of_iterations(2));
  EXPECT_EQ(fine, points_of(moved));
  // scalars: a linear function of position stays that function
  std::vector<FT> heights, fine_heights;
  for(const auto& p : points_of(coarse))
    heights.push_back(2 * p.x() - p.z() + 5);
  table.apply(heights, fine_heights);
  Mesh reference = coarse;
  S::loop_warren_subdivision(reference, CGAL::parameters::number_of_iterations(2));
  const auto reference_points = points_of(reference);
  for(std::size_t i = 0; i < fine_heights.size(); ++i)
    EXPECT_EQ(fine_heights[i], 2 * reference_points[i].x() - reference_points[i].z() + 5);
}

TEST(Stencil_table, refuses_what_subdivide_refuses_and_mismatched_inputs)
{
  Mesh empty;
  EXPECT_NE(testing_utils::bad_input_message([&] {
              S::make_stencil_table(empty, S::Loop_mask<Mesh>(), S::parameters::number_of_iterations(1));
            }).find("empty"),
            std::string::npos);
  Mesh with_garbage = open_bipyramid_piece();
  CGAL::Euler::remove_face(halfedge(*faces(with_garbage).begin(), with_garbage), with_garbage);
  EXPECT_NE(testing_utils::bad_input_message([&] {
              S::make_stencil_table(with_garbage, S::Loop_mask<Mesh>(), S::parameters::number_of_iterations(1));
            }).find(": the mesh still holds removed elements (garbage); call collect_garbage()"),
            std::string::npos);
  const auto table =
    S::make_stencil_table(open_bipyramid_piece(), S::Loop_mask<Mesh>(), S::parameters::number_of_iterations(1));
  std::vector<KE::Point_3> too_few(3), out;
  EXPECT_NE(testing_utils::bad_input_message([&] { table.apply(too_few, out); }).find("needs 6 source values"),
            std::string::npos);
}

TEST(Stencil_table, applies_to_any_range_and_through_property_maps)
{
  const Mesh coarse = open_bipyramid_piece();
  Mesh refined;
  const auto table =
    S::make_stencil_table(coarse, S::Loop_mask<Mesh>(), S::parameters::number_of_iterations(2).refined_mesh(refined));
  const auto expected = points_of(refined);
  // a list in (no random access), a fixed-size array out (not resized)
  const auto control = points_of(coarse);
  const std::list<KE::Point_3> listed(control.begin(), control.end());
  std::vector<KE::Point_3> room(table.number_of_stencils());
  table.apply(listed, room);
  EXPECT_EQ(room, expected);
  std::array<KE::Point_3, 2> too_small;
  EXPECT_NE(testing_utils::bad_input_message([&] { table.apply(control, too_small); }).find("needs room for"),
            std::string::npos);
  // vertex property maps: coarse mesh in, another mesh with the refined connectivity out
  Mesh target = refined;
  for(auto v : vertices(target))
    target.point(v) = KE::Point_3(7, 7, 7);
  table.apply(vertices(coarse), get(CGAL::vertex_point, coarse), vertices(target), get(CGAL::vertex_point, target));
  EXPECT_EQ(points_of(target), expected);
  // a scalar property map in, one out
  Mesh with_heights = coarse;
  auto height = with_heights.add_property_map<Mesh::Vertex_index, FT>("v:height", FT(0)).first;
  for(auto v : vertices(with_heights))
    height[v] = with_heights.point(v).x() - 2 * with_heights.point(v).y();
  Mesh scalar_target = refined;
  auto fine_height = scalar_target.add_property_map<Mesh::Vertex_index, FT>("v:height", FT(0)).first;
  table.apply(vertices(with_heights), height, vertices(scalar_target), fine_height);
  for(auto v : vertices(scalar_target))
    EXPECT_EQ(fine_height[v], refined.point(v).x() - 2 * refined.point(v).y());
  // the key ranges must match the table
  EXPECT_NE(testing_utils::bad_input_message([&] {
              table.apply(vertices(coarse), height, vertices(coarse), fine_height);
            }).find("output keys"),
            std::string::npos);
}

// a row without terms (a limit derivative at an extraordinary vertex) is
// zero through every way of applying a table
TEST(Stencil_table, a_row_without_terms_is_zero)
{
  S::Stencil_table<FT> table(2);
  table.add_stencil(std::vector<std::pair<std::size_t, FT>>{{1, FT(1) / FT(2)}});
  table.add_stencil(std::vector<std::pair<std::size_t, FT>>{});
  const std::vector<KE::Point_3> points{{1, 2, 3}, {4, 6, 8}};
  EXPECT_EQ(table.evaluate(points, 0), KE::Point_3(2, 3, 4));
  EXPECT_EQ(table.evaluate(points, 1), CGAL::ORIGIN);
  EXPECT_EQ(table.evaluate(std::vector<FT>{FT(5), FT(7)}, 1), FT(0));
  std::vector<KE::Point_3> out(2);
  table.apply(points, out);
  EXPECT_EQ(out[1], CGAL::ORIGIN);
  S::Stencil_table<double> doubles(2);
  doubles.add_stencil(std::vector<std::pair<std::size_t, double>>{});
  const std::vector<CGAL::Simple_cartesian<double>::Point_3> double_points{{1, 2, 3}, {4, 6, 8}};
  std::vector<CGAL::Simple_cartesian<double>::Point_3> double_out(1, {9, 9, 9});
  doubles.apply(double_points, double_out);
  EXPECT_EQ(double_out[0], CGAL::ORIGIN);
  EXPECT_EQ(doubles.evaluate(double_points, 0), CGAL::ORIGIN);
}

TEST(Stencil_table, every_host_composes_exactly_what_subdivide_makes)
{
  // sqrt3 on a mesh with a border visits its new vertices out of order on
  // refining steps (the table is then written in two passes); Catmull-Clark
  // and Doo-Sabin on the triangles of the piece: faces of several sizes
  const Mesh coarse = open_bipyramid_piece();
  const auto check = [&](const auto& mask, const auto& refine, int levels) {
    Mesh refined;
    const auto table =
      S::make_stencil_table(coarse, mask, S::parameters::number_of_iterations(levels).refined_mesh(refined));
    Mesh reference = coarse;
    refine(reference, CGAL::parameters::number_of_iterations(levels));
    EXPECT_EQ(points_of(refined), points_of(reference)) << mask.name() << ", " << levels << " levels";
    std::vector<KE::Point_3> fine;
    table.apply(points_of(coarse), fine);
    EXPECT_EQ(fine, points_of(reference)) << mask.name() << ", " << levels << " levels";
  };
  for(int levels = 0; levels <= 3; ++levels) {
    check(
      S::Sqrt3_mask<Mesh>(), [](Mesh& m, const auto& np) { S::sqrt3_subdivision(m, np); }, levels);
    check(
      S::Catmull_clark_mask<Mesh>(), [](Mesh& m, const auto& np) { S::catmull_clark_subdivision(m, np); }, levels);
    check(
      S::Doo_sabin_mask<Mesh>(), [](Mesh& m, const auto& np) { S::doo_sabin_subdivision(m, np); }, levels);
    check(
      S::Butterfly_mask<Mesh>(), [](Mesh& m, const auto& np) { S::butterfly_subdivision(m, np); }, levels);
  }
}

TEST(Stencil_table, named_parameters_without_a_refined_mesh)
{
  const Mesh coarse = open_bipyramid_piece();
  const auto a = S::make_stencil_table(coarse, S::Loop_mask<Mesh>(), S::parameters::number_of_iterations(2).threads(2));
  const auto b = S::make_stencil_table(coarse, S::Loop_mask<Mesh>(), S::parameters::number_of_iterations(2).threads(1));
  const auto c = S::make_stencil_table(coarse, S::Loop_mask<Mesh>(), S::parameters::number_of_iterations(2));
  ASSERT_EQ(a.number_of_terms(), c.number_of_terms());
  ASSERT_EQ(b.number_of_terms(), c.number_of_terms());
  for(std::size_t t = 0; t < c.number_of_terms(); ++t) {
    EXPECT_EQ(a.weight(t), c.weight(t));
    EXPECT_EQ(b.source(t), c.source(t));
  }
  EXPECT_EQ(
    S::make_stencil_table(coarse, S::Loop_mask<Mesh>(), S::parameters::number_of_iterations(0)).number_of_terms(),
    num_vertices(coarse));
}

namespace {

using KD = CGAL::Simple_cartesian<double>;
using Double_mesh = CGAL::Surface_mesh<KD::Point_3>;

// a bumpy quad grid with a border (Catmull-Clark), or its triangulation
// along alternating diagonals (Loop): valences 2 to 8, corners, a border
Double_mesh bumpy_grid(bool triangles, int n = 7)
{
  return testing_utils::grid<Double_mesh>(
    n, n,
    [](int i, int j) { return KD::Point_3(i + 0.1 * std::sin(3.0 * j), j, std::cos(0.7 * i) * std::sin(0.9 * j)); },
    triangles, [](int i, int j) { return (i + j) % 3 == 0; });
}

template <template <class, class> class MaskTemplate>
void expect_limit_tables_equal_subdivide_and_project(const Double_mesh& coarse, int levels)
{
  Double_mesh refined;
  const auto tables = S::make_limit_stencil_tables(coarse, MaskTemplate<Double_mesh, double>(),
                                                   S::parameters::number_of_iterations(levels).refined_mesh(refined));
  Double_mesh reference = coarse;
  S::subdivide(reference, MaskTemplate<Double_mesh, double>(), CGAL::parameters::number_of_iterations(levels));
  auto normals = reference.add_property_map<Double_mesh::Vertex_index, KD::Vector_3>("v:n").first;
  S::limit_normals(reference, MaskTemplate<Double_mesh, double>(), normals);
  S::project_to_limit(reference, MaskTemplate<Double_mesh, double>());
  const std::vector<KD::Point_3> control(coarse.points().begin(), coarse.points().end());
  std::vector<KD::Point_3> limit;
  tables.position.apply(control, limit);
  ASSERT_EQ(limit.size(), reference.number_of_vertices());
  std::vector<std::array<double, 3>> control3, tangent[2];
  for(const auto& p : control)
    control3.push_back({p.x(), p.y(), p.z()});
  tables.tangent[0].apply(control3, tangent[0]);
  tables.tangent[1].apply(control3, tangent[1]);
  double worst = 0, worst_normal = 0;
  std::size_t with_tangents = 0;
  for(auto v : reference.vertices()) {
    worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(limit[v.idx()], reference.point(v))));
    if(!tables.has_tangents[v.idx()])
      continue;
    ++with_tangents;
    const KD::Vector_3 t0(tangent[0][v.idx()][0], tangent[0][v.idx()][1], tangent[0][v.idx()][2]);
    const KD::Vector_3 t1(tangent[1][v.idx()][0], tangent[1][v.idx()][1], tangent[1][v.idx()][2]);
    KD::Vector_3 normal = CGAL::cross_product(t0, t1);
    normal = normal / std::sqrt(normal.squared_length());
    worst_normal = (std::max)(worst_normal, std::sqrt((normal - normals[v]).squared_length()));
  }
  EXPECT_LT(worst, 1e-12) << levels << " levels";
  EXPECT_LT(worst_normal, 1e-9) << levels << " levels";
  EXPECT_GT(with_tangents, reference.number_of_vertices() / 2);
}

} // namespace

TEST(Stencil_table, limit_tables_give_subdivide_then_project_to_limit)
{
  for(int levels = 0; levels <= 2; ++levels) {
    expect_limit_tables_equal_subdivide_and_project<S::Loop_mask>(bumpy_grid(true), levels);
    expect_limit_tables_equal_subdivide_and_project<S::Loop_warren_mask>(bumpy_grid(true), levels);
    expect_limit_tables_equal_subdivide_and_project<S::Catmull_clark_mask>(bumpy_grid(false), levels);
    expect_limit_tables_equal_subdivide_and_project<S::Catmull_clark_mask>(bumpy_grid(true), levels);
  }
  // the shorthand: positions only
  const Double_mesh coarse = bumpy_grid(true);
  const auto table =
    S::make_limit_stencil_table(coarse, S::Loop_mask<Double_mesh>(), S::parameters::number_of_iterations(1));
  EXPECT_EQ(table.number_of_sources(), coarse.number_of_vertices());
  for(std::size_t i = 0; i < table.number_of_stencils(); ++i) {
    double sum = 0;
    for(std::size_t t = table.stencil_begin(i); t < table.stencil_end(i); ++t)
      sum += table.weight(t);
    EXPECT_NEAR(sum, 1, 1e-14);
  }
}

namespace {

// make_stencil_table makes each row once, in one pass (in parallel: in chunks
// of rows, copied into place): the table must be the level tables composed by
// Stencil_table::then, to the bit, whatever the number of threads. Grids large
// enough for many chunks, with a border.
void expect_same_table(const S::Stencil_table<double>& a, const S::Stencil_table<double>& b, const std::string& what)
{
  ASSERT_EQ(a.number_of_stencils(), b.number_of_stencils()) << what;
  ASSERT_EQ(a.number_of_terms(), b.number_of_terms()) << what;
  ASSERT_EQ(a.number_of_sources(), b.number_of_sources()) << what;
  for(std::size_t i = 0; i < a.number_of_stencils(); ++i)
    ASSERT_EQ(a.stencil_end(i), b.stencil_end(i)) << what << ", stencil " << i;
  for(std::size_t t = 0; t < a.number_of_terms(); ++t) {
    ASSERT_EQ(a.source(t), b.source(t)) << what << ", term " << t;
    const double x = a.weight(t), y = b.weight(t);
    ASSERT_EQ(std::memcmp(&x, &y, sizeof x), 0) << what << ", term " << t << ": " << x << " vs " << y;
  }
}

// one level's own table, and its topology
template <class Mask>
S::Stencil_table<double> level_table(Double_mesh& work, const Mask& mask)
{
  S::internal::Composed_level<double> level{nullptr, num_vertices(work)};
  const auto points = get(CGAL::vertex_point, work);
  S::internal::refine_level(work, mask, S::internal::No_points<decltype(points)>{points}, S::internal::Parallel_loop(1),
                            level);
  return level.table;
}

// the table made with each number of threads, and with the refined mesh (with
// the first number of threads), against the level tables composed
template <class Mask>
void expect_level_tables_composed(const Double_mesh& coarse, const Mask& mask, int levels,
                                  const std::vector<int>& threads)
{
  Double_mesh work = coarse;
  auto composed = level_table(work, mask);
  for(int level = 1; level < levels; ++level)
    composed = composed.then(level_table(work, mask));
  for(const int n : threads)
    expect_same_table(S::make_stencil_table(coarse, mask, S::parameters::number_of_iterations(levels).threads(n)),
                      composed, mask.name() + ", " + std::to_string(levels) + " levels, threads " + std::to_string(n));
  Double_mesh refined;
  expect_same_table(
    S::make_stencil_table(coarse, mask,
                          S::parameters::number_of_iterations(levels).refined_mesh(refined).threads(threads.front())),
    composed, mask.name() + ", " + std::to_string(levels) + " levels, with the refined mesh");
  // the refined mesh: the connectivity subdivide() makes, link for link
  Double_mesh reference = coarse;
  S::subdivide(reference, mask, CGAL::parameters::number_of_iterations(levels));
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(refined)) << mask.name();
  ASSERT_EQ(refined.number_of_halfedges(), reference.number_of_halfedges()) << mask.name();
  for(auto h : halfedges(reference)) {
    ASSERT_EQ(refined.next(h), reference.next(h)) << mask.name();
    ASSERT_EQ(refined.target(h), reference.target(h)) << mask.name();
    ASSERT_EQ(refined.face(h), reference.face(h)) << mask.name();
  }
  for(auto v : vertices(reference))
    ASSERT_EQ(refined.halfedge(v), reference.halfedge(v)) << mask.name();
}

void expect_level_tables_composed_for_every_host(const std::vector<int>& threads)
{
  const Double_mesh triangles = bumpy_grid(true, 40), quads = bumpy_grid(false, 40);
  for(int levels = 1; levels <= 3; ++levels) {
    expect_level_tables_composed(triangles, S::Loop_mask<Double_mesh>(), levels, threads);
    expect_level_tables_composed(quads, S::Catmull_clark_mask<Double_mesh>(), levels, threads);
    expect_level_tables_composed(triangles, S::Catmull_clark_mask<Double_mesh>(), levels, threads);
    expect_level_tables_composed(triangles, S::Modified_butterfly_mask<Double_mesh>(), levels, threads);
    expect_level_tables_composed(triangles, S::Sqrt3_mask<Double_mesh>(), levels, threads);
    expect_level_tables_composed(quads, S::Doo_sabin_mask<Double_mesh>(), levels, threads);
  }
}

} // namespace

TEST(Stencil_table, double_tables_are_the_level_tables_composed_bit_for_bit)
{
  expect_level_tables_composed_for_every_host({1});
}

TEST(Stencil_table, double_tables_are_the_level_tables_composed_bit_for_bit_with_any_number_of_threads)
{
  SUBDIV_REQUIRE_THREADS();
  expect_level_tables_composed_for_every_host({2, 0});
}
