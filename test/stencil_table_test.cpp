// Stencil tables: the same masks as subdivide(), composed over levels.
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Subdiv/stencils/make_stencil_table.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "mesh_test_utils.h"

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
  const auto table = S::make_stencil_table(coarse, S::Loop_mask<Mesh>(), 3, &refined);
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
  const auto table = S::make_stencil_table(coarse, S::Loop_mask<Mesh, FT, S::Warren_beta>(), 2);
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
  EXPECT_NE(testing_utils::bad_input_message([&] { S::make_stencil_table(empty, S::Loop_mask<Mesh>(), 1); })
              .find("empty"),
            std::string::npos);
  const auto table = S::make_stencil_table(open_bipyramid_piece(), S::Loop_mask<Mesh>(), 1);
  std::vector<KE::Point_3> too_few(3), out;
  EXPECT_NE(testing_utils::bad_input_message([&] { table.apply(too_few, out); }).find("needs 6 source values"),
            std::string::npos);
}

TEST(Stencil_table, every_host_composes_exactly_what_subdivide_makes)
{
  // sqrt3 on a mesh with a border visits its new vertices out of order on
  // refining steps (the table is then written in two passes); Catmull-Clark
  // and Doo-Sabin on the triangles of the piece: faces of several sizes
  const Mesh coarse = open_bipyramid_piece();
  const auto check = [&](const auto& mask, const auto& refine, int levels) {
    Mesh refined;
    const auto table = S::make_stencil_table(coarse, mask, levels, &refined);
    Mesh reference = coarse;
    refine(reference, CGAL::parameters::number_of_iterations(levels));
    EXPECT_EQ(points_of(refined), points_of(reference)) << mask.name() << ", " << levels << " levels";
    std::vector<KE::Point_3> fine;
    table.apply(points_of(coarse), fine);
    EXPECT_EQ(fine, points_of(reference)) << mask.name() << ", " << levels << " levels";
  };
  for(int levels = 0; levels <= 3; ++levels) {
    check(S::Sqrt3_mask<Mesh>(), [](Mesh& m, const auto& np) { S::sqrt3_subdivision(m, np); }, levels);
    check(S::Catmull_clark_mask<Mesh>(), [](Mesh& m, const auto& np) { S::catmull_clark_subdivision(m, np); }, levels);
    check(S::Doo_sabin_mask<Mesh>(), [](Mesh& m, const auto& np) { S::doo_sabin_subdivision(m, np); }, levels);
    check(S::Butterfly_mask<Mesh>(), [](Mesh& m, const auto& np) { S::butterfly_subdivision(m, np); }, levels);
  }
}

TEST(Stencil_table, named_parameters_without_a_refined_mesh)
{
  const Mesh coarse = open_bipyramid_piece();
  const auto a = S::make_stencil_table(coarse, S::Loop_mask<Mesh>(), 2, S::threads(2));
  const auto b = S::make_stencil_table(coarse, S::Loop_mask<Mesh>(), 2, nullptr, S::threads(1));
  const auto c = S::make_stencil_table(coarse, S::Loop_mask<Mesh>(), 2);
  ASSERT_EQ(a.number_of_terms(), c.number_of_terms());
  ASSERT_EQ(b.number_of_terms(), c.number_of_terms());
  for(std::size_t t = 0; t < c.number_of_terms(); ++t) {
    EXPECT_EQ(a.weight(t), c.weight(t));
    EXPECT_EQ(b.source(t), c.source(t));
  }
  EXPECT_EQ(S::make_stencil_table(coarse, S::Loop_mask<Mesh>(), 0).number_of_terms(), num_vertices(coarse));
}
