// Doo-Sabin with infinitely sharp creases and corners (issue 11): Chaikin's
// rule along a crease, corners kept, darts smooth, the refined tags, one level
// then another, untagged results unchanged, semi-sharp values refused. Exact
// in rationals.
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Subdiv/curves/Chaikin_scheme.h>
#include <CGAL/Subdiv/curves/refine_polyline.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "mesh_builders.h"
#include "mesh_test_utils.h"

#include <algorithm>
#include <functional>
#include <set>
#include <string>
#include <utility>
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
using Edge_tags = Exact_mesh::Property_map<Exact_mesh::Edge_index, FT>;
using Vertex_tags = Exact_mesh::Property_map<Exact_mesh::Vertex_index, FT>;

// subdivide() takes the tags for Doo-Sabin, the limit layer does not (the
// limit of a Doo-Sabin crease is not derived): project_to_limit(),
// limit_normals(), displace() and the limit stencil tables do not compile
// with them, while Loop's do
static_assert(S::internal::Takes_sharpness_tags<S::Doo_sabin_mask<Exact_mesh>>::value, "Doo-Sabin takes tags");
static_assert(!S::internal::Takes_semi_sharp_tags<S::Doo_sabin_mask<Exact_mesh>>::value, "infinitely sharp only");
static_assert(!S::internal::Limit_takes_sharpness_tags<S::Doo_sabin_mask<Exact_mesh>>::value, "no limit with tags");
static_assert(S::internal::Limit_takes_sharpness_tags<S::Loop_mask<Exact_mesh>>::value, "Loop's limit takes tags");

namespace {

FT height(int i, int j)
{
  return FT((i * 7 + j * 5) % 11) / FT(8) - FT(j * j) / FT(16);
}

template <class M>
typename M::Edge_index grid_edge(const M& mesh, int n, int i, int j, int k, int l)
{
  const auto h = mesh.halfedge(testing_utils::grid_vertex<M>(n, i, j), testing_utils::grid_vertex<M>(n, k, l));
  EXPECT_NE(h, M::null_halfedge()) << i << " " << j << " " << k << " " << l;
  return mesh.edge(h);
}

Edge_tags edge_tags(Exact_mesh& mesh)
{
  return mesh.add_property_map<Exact_mesh::Edge_index, FT>("e:sharpness", FT(0)).first;
}
Vertex_tags vertex_tags(Exact_mesh& mesh)
{
  return mesh.add_property_map<Exact_mesh::Vertex_index, FT>("v:sharpness", FT(0)).first;
}

void refine(Exact_mesh& mesh, int levels)
{
  S::doo_sabin_subdivision(mesh, S::parameters::number_of_iterations(levels)
                                   .edge_sharpness_map(edge_tags(mesh))
                                   .vertex_sharpness_map(vertex_tags(mesh)));
}

// the lattice points of the closed crease of a grid(8, 8, ..., triangles):
// the hexagon of the second ring around (4, 4) (every interior vertex has
// valence 6), each of its 12 vertices with 2 faces inside and 4 or 3 outside
const std::vector<std::pair<int, int>> hexagon = {{6, 4}, {6, 5}, {6, 6}, {5, 6}, {4, 6}, {3, 5},
                                                  {2, 4}, {2, 3}, {2, 2}, {3, 2}, {4, 2}, {5, 3}};

Exact_mesh hexagon_grid()
{
  Exact_mesh mesh = testing_utils::grid<Exact_mesh>(
    8, 8, [](int i, int j) { return PE(i, j, height(i, j)); }, true);
  const Edge_tags tags = edge_tags(mesh);
  for(std::size_t k = 0; k < hexagon.size(); ++k) {
    const auto a = hexagon[k], b = hexagon[(k + 1) % hexagon.size()];
    tags[grid_edge(mesh, 8, a.first, a.second, b.first, b.second)] = FT(10);
  }
  return mesh;
}

// a 4 x 4 quad grid with the crease line j = 2 from border to border: its
// ends have three sharp edges (corners)
Exact_mesh line_grid()
{
  Exact_mesh mesh = testing_utils::grid<Exact_mesh>(
    4, 4, [](int i, int j) { return PE(i, j, height(i, j)); }, false);
  const Edge_tags tags = edge_tags(mesh);
  for(int i = 0; i < 4; ++i)
    tags[grid_edge(mesh, 4, i, 2, i + 1, 2)] = FT(10);
  return mesh;
}

using Segment = std::pair<PE, PE>;

Segment segment(const PE& a, const PE& b)
{
  return a < b ? Segment(a, b) : Segment(b, a);
}

// the sharp edges that are not border edges, as segments
std::set<Segment> crease_segments(Exact_mesh& mesh)
{
  const Edge_tags tags = edge_tags(mesh);
  std::set<Segment> segments;
  for(auto e : edges(mesh))
    if(tags[e] >= FT(10) && !mesh.is_border(e))
      segments.insert(segment(mesh.point(mesh.vertex(e, 0)), mesh.point(mesh.vertex(e, 1))));
  return segments;
}

// the segments of a polyline (closed: the last point joins the first)
std::set<Segment> segments_of(const std::vector<PE>& points, bool closed)
{
  std::set<Segment> segments;
  for(std::size_t k = 0; k + (closed ? 0 : 1) < points.size(); ++k)
    segments.insert(segment(points[k], points[(k + 1) % points.size()]));
  return segments;
}

bool has_point(const Exact_mesh& mesh, const PE& p)
{
  for(auto v : vertices(mesh))
    if(mesh.point(v) == p)
      return true;
  return false;
}

int euler_characteristic(const Exact_mesh& mesh)
{
  return static_cast<int>(num_vertices(mesh)) - static_cast<int>(num_edges(mesh)) + static_cast<int>(num_faces(mesh));
}

} // namespace

// A closed crease is refined by Chaikin's rule: the new sharp edges are the
// segments of Chaikin's refinement of the old crease polygon (the library's
// curve scheme), exactly, at one and at two levels; every new crease vertex
// is welded across the crease (24, then 48 segments).
TEST(DooSabinCreases, a_closed_crease_is_refined_by_chaikin)
{
  Exact_mesh mesh = hexagon_grid();
  std::vector<PE> polygon;
  for(const auto& p : hexagon)
    polygon.push_back(mesh.point(testing_utils::grid_vertex<Exact_mesh>(8, p.first, p.second)));
  for(int level = 1; level <= 2; ++level) {
    refine(mesh, 1);
    ASSERT_TRUE(mesh.is_valid(false));
    const std::vector<PE> chaikin =
      S::refine_polyline(polygon, S::Chaikin_scheme<FT>(), S::parameters::number_of_iterations(level).closed(true));
    ASSERT_EQ(chaikin.size(), 12u << level);
    const std::set<Segment> expected = segments_of(chaikin, true), found = crease_segments(mesh);
    EXPECT_EQ(found.size(), 12u << level);
    EXPECT_EQ(found, expected) << "level " << level;
  }
  // without the tags the crease's corners are not welded: no new vertex is
  // Chaikin's point 3/4 a + 1/4 b of the first crease edge
  Exact_mesh untagged = testing_utils::grid<Exact_mesh>(
    8, 8, [](int i, int j) { return PE(i, j, height(i, j)); }, true);
  S::doo_sabin_subdivision(untagged, S::parameters::number_of_iterations(1));
  const PE a = polygon[0], b = polygon[1];
  EXPECT_FALSE(has_point(untagged, CGAL::barycenter(a, FT(3) / FT(4), b, FT(1) / FT(4))));
}

// Chaikin's refinement of an open polyline whose ends are corners, kept:
// p0, then for every edge (a, b) 3/4 a + 1/4 b (but at p0) and 1/4 a + 3/4 b
// (but at the last point)
std::vector<PE> chaikin_with_kept_ends(const std::vector<PE>& line)
{
  std::vector<PE> result = {line.front()};
  for(std::size_t k = 0; k + 1 < line.size(); ++k) {
    if(k > 0)
      result.push_back(CGAL::barycenter(line[k], FT(3) / FT(4), line[k + 1], FT(1) / FT(4)));
    if(k + 2 < line.size())
      result.push_back(CGAL::barycenter(line[k], FT(1) / FT(4), line[k + 1], FT(3) / FT(4)));
  }
  result.push_back(line.back());
  return result;
}

// Counts, on the 4 x 4 quad grid with a crease line (3 crease vertices with
// two faces on either side, 2 corner ends with one face on either side).
// Without tags: V' = 64 corners, F' = 16 + 24 + 9. With the crease: each
// crease vertex welds its 4 corners into 2 (-6), each end its 2 into 1 (-2);
// the 4 crease edges' quads collapse (-4) and the crease vertices' sectors of
// two faces make edges, not faces (-3). The ends stay exactly where they are,
// and the crease is Chaikin's refinement of the line with its ends kept.
// Level 2: 97 edges, 26 on the border, so 2 * 97 - 26 = 168 corners, less 2
// for each of the 6 crease vertices and 1 for each end: 154; faces: 42 face
// faces, 97 - 26 - 7 edge quads (7 crease edges collapse), 24 vertex faces
// (30 interior vertices, 6 of them crease vertices with sectors of 2 faces).
TEST(DooSabinCreases, a_crease_line_on_a_quad_grid)
{
  Exact_mesh mesh = line_grid();
  std::vector<PE> line;
  for(int i = 0; i <= 4; ++i)
    line.push_back(mesh.point(testing_utils::grid_vertex<Exact_mesh>(4, i, 2)));
  Exact_mesh untagged = mesh;
  S::doo_sabin_subdivision(untagged, S::parameters::number_of_iterations(1));
  EXPECT_EQ(num_vertices(untagged), 64u);
  EXPECT_EQ(num_faces(untagged), 49u);

  refine(mesh, 1);
  ASSERT_TRUE(mesh.is_valid(false));
  EXPECT_EQ(num_vertices(mesh), 56u);
  EXPECT_EQ(num_faces(mesh), 42u);
  EXPECT_EQ(num_edges(mesh), 97u);
  EXPECT_EQ(euler_characteristic(mesh), 1);
  EXPECT_TRUE(has_point(mesh, line.front()));
  EXPECT_TRUE(has_point(mesh, line.back()));
  const std::vector<PE> once = chaikin_with_kept_ends(line);
  ASSERT_EQ(once.size(), 8u);
  EXPECT_EQ(crease_segments(mesh), segments_of(once, false));

  refine(mesh, 1);
  ASSERT_TRUE(mesh.is_valid(false));
  EXPECT_EQ(num_vertices(mesh), 154u);
  EXPECT_EQ(num_faces(mesh), 130u);
  EXPECT_EQ(euler_characteristic(mesh), 1);
  EXPECT_TRUE(has_point(mesh, line.front()));
  EXPECT_TRUE(has_point(mesh, line.back()));
  const std::vector<PE> twice = chaikin_with_kept_ends(once);
  ASSERT_EQ(twice.size(), 14u);
  EXPECT_EQ(crease_segments(mesh), segments_of(twice, false));
}

// A cube whose 12 edges are infinitely sharp has a corner at every vertex
// (three sharp edges): each keeps one new vertex at itself, every edge quad
// collapses, and the refined cube is the cube, at every level.
TEST(DooSabinCreases, a_cube_with_sharp_edges_is_its_own_refinement)
{
  Exact_mesh cube = testing_utils::cube<Exact_mesh>();
  const Edge_tags tags = edge_tags(cube);
  for(auto e : edges(cube))
    tags[e] = FT(10);
  Exact_mesh mesh = cube;
  for(int level = 1; level <= 2; ++level) {
    refine(mesh, 1);
    ASSERT_TRUE(mesh.is_valid(false));
    EXPECT_EQ(num_vertices(mesh), 8u);
    EXPECT_EQ(num_faces(mesh), 6u);
    std::vector<PE> before = points_of(cube), after = points_of(mesh);
    std::sort(before.begin(), before.end());
    std::sort(after.begin(), after.end());
    EXPECT_EQ(after, before);
    EXPECT_EQ(crease_segments(mesh).size(), 12u);
  }
}

// A corner (vertex sharpness 10) on a smooth cube keeps one new vertex at its
// point exactly, at one and two levels, and stays a corner in the refined
// tags; its vertex face goes and its three corners become one vertex
// (V' = 24 - 2, F' = 26 - 1).
TEST(DooSabinCreases, a_corner_keeps_its_vertex)
{
  Exact_mesh mesh = testing_utils::cube<Exact_mesh>();
  const auto v = *vertices(mesh).begin();
  const PE corner = mesh.point(v);
  vertex_tags(mesh)[v] = FT(10);
  refine(mesh, 1);
  ASSERT_TRUE(mesh.is_valid(false));
  EXPECT_EQ(num_vertices(mesh), 22u);
  EXPECT_EQ(num_faces(mesh), 25u);
  std::size_t corners = 0;
  for(auto w : vertices(mesh))
    if(vertex_tags(mesh)[w] >= FT(10)) {
      ++corners;
      EXPECT_EQ(mesh.point(w), corner);
    }
  EXPECT_EQ(corners, 1u);
  refine(mesh, 1);
  ASSERT_TRUE(mesh.is_valid(false));
  EXPECT_TRUE(has_point(mesh, corner));
  Exact_mesh smooth = testing_utils::cube<Exact_mesh>();
  S::doo_sabin_subdivision(smooth, S::parameters::number_of_iterations(2));
  EXPECT_FALSE(has_point(smooth, corner));
}

// One level then another is two levels, points, faces and tags, on every
// configuration above; the stencil table with the tags gives the same points.
TEST(DooSabinCreases, one_level_then_another_is_two_levels)
{
  Exact_mesh cube = testing_utils::cube<Exact_mesh>();
  vertex_tags(cube)[*vertices(cube).begin()] = FT(10);
  for(const Exact_mesh& start : {hexagon_grid(), line_grid(), cube}) {
    Exact_mesh twice = start, by_levels = start, coarse = start;
    refine(twice, 2);
    refine(by_levels, 1);
    refine(by_levels, 1);
    EXPECT_TRUE(same_mesh(twice, by_levels));
    for(auto e : edges(twice))
      ASSERT_EQ(edge_tags(twice)[e], edge_tags(by_levels)[e]);
    for(auto v : vertices(twice))
      ASSERT_EQ(vertex_tags(twice)[v], vertex_tags(by_levels)[v]);
    const S::Stencil_table<FT> table = S::make_stencil_table(coarse, S::Doo_sabin_mask<Exact_mesh>(),
                                                             S::parameters::number_of_iterations(2)
                                                               .edge_sharpness_map(edge_tags(coarse))
                                                               .vertex_sharpness_map(vertex_tags(coarse)));
    std::vector<PE> from_table;
    table.apply(points_of(coarse), from_table);
    EXPECT_EQ(from_table, points_of(twice));
  }
}

// A sharp edge with a dart at each end is refined smooth: nothing is welded,
// and the result is the untagged one exactly (its points, and its faces on
// the first level; the crease path numbers the edges otherwise, so the
// second level lists the same faces in another order).
TEST(DooSabinCreases, darts_are_refined_smooth)
{
  Exact_mesh mesh = testing_utils::grid<Exact_mesh>(
    4, 4, [](int i, int j) { return PE(i, j, height(i, j)); }, false);
  Exact_mesh untagged = mesh;
  edge_tags(mesh)[grid_edge(mesh, 4, 2, 2, 3, 2)] = FT(10);
  refine(mesh, 1);
  S::doo_sabin_subdivision(untagged, S::parameters::number_of_iterations(1));
  EXPECT_TRUE(same_mesh(mesh, untagged));
  std::size_t sharp = 0;
  for(auto e : edges(mesh))
    sharp += edge_tags(mesh)[e] >= FT(10) && !mesh.is_border(e) ? 1 : 0;
  EXPECT_EQ(sharp, 0u); // the crease does not go on past its darts
  refine(mesh, 1);
  S::doo_sabin_subdivision(untagged, S::parameters::number_of_iterations(1));
  std::vector<PE> a = points_of(mesh), b = points_of(untagged);
  EXPECT_EQ(a, b);
  EXPECT_EQ(num_faces(mesh), num_faces(untagged));
}

// Without tags, with tags of 0 and with the border edges tagged 10 (they are
// sharp anyway), Doo-Sabin gives the same mesh bit for bit in doubles, border
// included; and CGAL's DooSabin_subdivision's interior points are unchanged.
TEST(DooSabinCreases, untagged_results_are_unchanged)
{
  for(bool closed : {false, true}) {
    Mesh untagged = closed
                      ? testing_utils::cube<Mesh>()
                      : testing_utils::grid<Mesh>(
                          5, 4, [](int i, int j) { return K::Point_3(i, j, CGAL::to_double(height(i, j))); }, false);
    Mesh zeros = untagged, border = untagged;
    S::doo_sabin_subdivision(untagged, S::parameters::number_of_iterations(3));
    auto zero_edges = zeros.add_property_map<Mesh::Edge_index, double>("e:sharpness", 0.).first;
    auto zero_vertices = zeros.add_property_map<Mesh::Vertex_index, double>("v:sharpness", 0.).first;
    S::doo_sabin_subdivision(
      zeros, S::parameters::number_of_iterations(3).edge_sharpness_map(zero_edges).vertex_sharpness_map(zero_vertices));
    auto border_edges = border.add_property_map<Mesh::Edge_index, double>("e:sharpness", 0.).first;
    for(auto e : edges(border))
      border_edges[e] = border.is_border(e) ? 10. : 0.;
    S::doo_sabin_subdivision(border, S::parameters::number_of_iterations(3).edge_sharpness_map(border_edges));
    EXPECT_TRUE(same_mesh(zeros, untagged));
    EXPECT_TRUE(same_mesh(border, untagged));
    if(closed) { // V = the corners of the level before: 2 E, with E = 192 after two levels
      EXPECT_EQ(num_vertices(untagged), 384u);
    }
  }
}

// A semi-sharp value is refused with Bad_input naming the edge or the vertex,
// and the mesh and its tags are left as they were.
TEST(DooSabinCreases, semi_sharp_is_refused)
{
  Exact_mesh mesh = hexagon_grid();
  edge_tags(mesh)[Exact_mesh::Edge_index(7)] = FT(1) / FT(2);
  const Exact_mesh before = mesh;
  std::string message = testing_utils::bad_input_message([&] { refine(mesh, 1); });
  EXPECT_NE(message.find("Doo-Sabin: edge 7 is semi-sharp (above 0, below 10)"), std::string::npos) << message;
  EXPECT_TRUE(same_mesh(mesh, before));
  EXPECT_EQ(edge_tags(mesh)[Exact_mesh::Edge_index(7)], FT(1) / FT(2));
  edge_tags(mesh)[Exact_mesh::Edge_index(7)] = FT(0);
  vertex_tags(mesh)[Exact_mesh::Vertex_index(3)] = FT(5);
  message = testing_utils::bad_input_message([&] { refine(mesh, 1); });
  EXPECT_NE(message.find("Doo-Sabin: vertex 3 is semi-sharp"), std::string::npos) << message;
  EXPECT_EQ(num_vertices(mesh), num_vertices(before));
}
