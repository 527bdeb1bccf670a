// Loop subdivision: agreement with CGAL's Subdivision_method_3, exact weights, bad input.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <fstream>

#include <gtest/gtest.h>

#include "mesh_builders.h"
#include "mesh_test_utils.h"
#include "opensubdiv_baselines.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace S = CGAL::Subdiv;
using K = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

using testing_utils::Opensubdiv_case;
using testing_utils::position_mismatch;
using testing_utils::shared_mesh;
using testing_utils::test_mesh;

namespace {

// two levels of ours and of CGAL's Loop_subdivision on the mesh in `path`
void expect_same_as_cgal(const std::string& path)
{
  Mesh ours, theirs;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(path, ours)) << path;
  theirs = ours;
  S::loop_subdivision(ours, CGAL::parameters::number_of_iterations(2));
  CGAL::Subdivision_method_3::Loop_subdivision(theirs, CGAL::parameters::number_of_iterations(2));
  ASSERT_EQ(num_vertices(ours), num_vertices(theirs)) << path;
  ASSERT_EQ(num_faces(ours), num_faces(theirs)) << path;
  EXPECT_TRUE(ours.is_valid(false)) << path;
  EXPECT_LT(position_mismatch(ours, theirs), 1e-12) << path;
}

} // namespace

TEST(Loop, matches_cgal_subdivision_method_3_closed_and_with_border)
{
  // valence 3; valence 5; a border and valences 4 to 10
  for(const std::string name : {"cgal/tetrahedron.off", "cgal/icosahedron.off", "cgal/corner_tris_with_hole.off"})
    expect_same_as_cgal(test_mesh(name));
}

TEST(Loop, larger_shared_meshes_agree_with_cgal_subdivision_method_3)
{
  SUBDIV_REQUIRE_SHARED_DATA();
  for(const std::string name : {"cgal/elephant.off", "cgal/mesh_with_border.off"})
    expect_same_as_cgal(shared_mesh(name));
}

TEST(Loop, exact_kernel_weights_and_counts)
{
  using KE = CGAL::Simple_cartesian<CGAL::Exact_rational>;
  using P = KE::Point_3;
  using FT = KE::FT;
  // the octahedron, a bipyramid over a square: every vertex has valence 4,
  // where Loop's beta 31/256 is rational
  using Octahedron = CGAL::Surface_mesh<P>;
  const P e[4] = {P(1, 0, 0), P(0, 1, 0), P(-1, 0, 0), P(0, -1, 0)};
  Octahedron octahedron = testing_utils::bipyramid<Octahedron>(4, P(0, 0, 1), P(0, 0, -1), [&](int i) { return e[i]; });
  S::loop_subdivision(octahedron);
  EXPECT_EQ(num_vertices(octahedron), 6u + 12u);
  EXPECT_EQ(num_faces(octahedron), 32u);
  // old vertex: (1 - 4 beta) top + beta * (sum of the ring, which is 0): z = 1 - 124/256
  const P moved_top = octahedron.point(Octahedron::Vertex_index(0));
  EXPECT_EQ(moved_top, P(0, 0, FT(1) - FT(4 * 31) / FT(256)));
  // edge top-e0: 3/8 top + 3/8 e0 + 1/8 e1 + 1/8 e3 = (3/8, 0, 3/8)
  bool found = false;
  for(auto v : vertices(octahedron))
    found = found || octahedron.point(v) == P(FT(3) / FT(8), 0, FT(3) / FT(8));
  EXPECT_TRUE(found);
}

TEST(Loop, epeck_mesh_compiles_and_runs)
{
  using KE = CGAL::Exact_predicates_exact_constructions_kernel;
  CGAL::Surface_mesh<KE::Point_3> mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh("cgal/tetrahedron.off"), mesh));
  S::loop_subdivision(mesh, CGAL::parameters::number_of_iterations(2));
  EXPECT_EQ(num_faces(mesh), 64u);
}

TEST(Loop, bad_input_is_refused_and_the_mesh_is_unchanged)
{
  const auto message = [](Mesh& mesh, int levels = 1) -> std::string {
    try {
      S::loop_subdivision(mesh, CGAL::parameters::number_of_iterations(levels));
    } catch(const S::Bad_input& e) {
      return e.what();
    }
    return "no exception";
  };
  Mesh empty;
  EXPECT_NE(message(empty).find("empty"), std::string::npos);

  Mesh quad;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh("cgal/cube_quad.off"), quad));
  const Mesh quad_copy = quad;
  const std::string not_triangles = message(quad);
  EXPECT_NE(not_triangles.find("faces all have 3 vertices; face 0 has 4"), std::string::npos) << not_triangles;
  EXPECT_EQ(num_faces(quad), num_faces(quad_copy));

  Mesh isolated;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh("cgal/tetrahedron.off"), isolated));
  isolated.add_vertex(K::Point_3(5, 5, 5));
  EXPECT_NE(message(isolated).find("vertex 4 is isolated"), std::string::npos) << message(isolated);
  EXPECT_EQ(num_faces(isolated), 4u);

  // a Surface_mesh that still holds a removed face: refused, with the fix
  Mesh with_garbage;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh("cgal/icosahedron.off"), with_garbage));
  CGAL::Euler::remove_face(halfedge(*faces(with_garbage).begin(), with_garbage), with_garbage);
  ASSERT_TRUE(with_garbage.has_garbage());
  const std::string garbage_message = message(with_garbage);
  EXPECT_NE(garbage_message.find(": the mesh still holds removed elements (garbage); call collect_garbage()"),
            std::string::npos)
    << garbage_message;
  EXPECT_EQ(with_garbage.number_of_faces(), 19u);
  EXPECT_TRUE(with_garbage.has_garbage());
  with_garbage.collect_garbage();
  EXPECT_EQ(message(with_garbage), "no exception");
  EXPECT_EQ(with_garbage.number_of_faces(), 76u);

  Mesh broken;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh("cgal/tetrahedron.off"), broken));
  broken.point(decltype(broken)::Vertex_index(2)) = K::Point_3(std::nan(""), 0, 0);
  EXPECT_NE(message(broken).find("vertex 2 has a non-finite coordinate"), std::string::npos);

  // two triangles sharing one vertex (a bow tie): a non-manifold vertex
  Mesh pinched;
  const auto o = pinched.add_vertex(K::Point_3(0, 0, 0));
  const auto a = pinched.add_vertex(K::Point_3(1, 0, 0)), b = pinched.add_vertex(K::Point_3(1, 1, 0));
  const auto c = pinched.add_vertex(K::Point_3(-1, 0, 0)), d = pinched.add_vertex(K::Point_3(-1, -1, 0));
  ASSERT_NE(pinched.add_face(o, a, b), Mesh::null_face());
  ASSERT_NE(pinched.add_face(o, c, d), Mesh::null_face());
  const std::string pinched_message = message(pinched);
  EXPECT_NE(pinched_message.find("vertex 0 is non-manifold"), std::string::npos) << pinched_message;

  // broken connectivity (a halfedge whose next leaves its face, a target out
  // of range): refused as invalid, without walking off the arrays
  Mesh tangled;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh("cgal/tetrahedron.off"), tangled));
  const Mesh::Halfedge_index h0(0), h1(1);
  tangled.set_next(h0, tangled.next(h1));
  const std::string tangled_message = message(tangled);
  EXPECT_NE(tangled_message.find("(Loop 1987 beta): the mesh is not a valid polygon mesh"), std::string::npos)
    << tangled_message;
  Mesh out_of_range;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh("cgal/tetrahedron.off"), out_of_range));
  out_of_range.set_target(h0, Mesh::Vertex_index(99));
  const std::string range_message = message(out_of_range);
  EXPECT_NE(range_message.find("(Loop 1987 beta): the mesh is not a valid polygon mesh"), std::string::npos)
    << range_message;

  // 40 levels: 80 faces times 4^40 would not fit in any memory
  Mesh big;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh("cgal/icosahedron.off"), big));
  EXPECT_NE(message(big, 40).find("memory"), std::string::npos);
  EXPECT_NE(message(big, -1).find("negative"), std::string::npos);
  EXPECT_EQ(num_faces(big), 20u);
}

// max_memory: the output estimate (faces times the host's measured peak
// bytes per face) is compared with it before any work, in constant time
TEST(Loop, max_memory_refuses_before_any_work)
{
  Mesh mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh("cgal/icosahedron.off"), mesh));
  const double per_face = S::Host_of<S::Loop_mask<Mesh>>::peak_bytes_per_face();
  EXPECT_EQ(per_face, 90);
  // 3 levels: 20 x 4^3 = 1280 faces, 115200 bytes
  std::string said = "no exception";
  try {
    S::loop_subdivision(mesh, S::parameters::number_of_iterations(3).max_memory(100000));
  } catch(const S::Bad_input& e) {
    said = e.what();
  }
  EXPECT_NE(said.find(": 3 levels on 20 faces would make 1280 faces, about 115 kB at 90 bytes per face, more than the "
                      "memory limit of 100 kB; the named parameter max_memory raises it"),
            std::string::npos)
    << said;
  EXPECT_EQ(num_faces(mesh), 20u);
  S::loop_subdivision(mesh, S::parameters::number_of_iterations(3).max_memory(115200));
  EXPECT_EQ(num_faces(mesh), 1280u);

  // a billion levels are refused at once, with the size as a power of ten
  Mesh again;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh("cgal/icosahedron.off"), again));
  try {
    S::loop_subdivision(again, S::parameters::number_of_iterations(1000000000));
    said = "no exception";
  } catch(const S::Bad_input& e) {
    said = e.what();
  }
  EXPECT_NE(said.find(": 1000000000 levels on 20 faces would make about 10^602059992 faces"), std::string::npos)
    << said;

  // the stencil tables read it too
  try {
    S::make_stencil_table(again, S::Loop_mask<Mesh>(), S::parameters::number_of_iterations(3).max_memory(100000));
    said = "no exception";
  } catch(const S::Bad_input& e) {
    said = e.what();
  }
  EXPECT_NE(said.find("would make 1280 faces"), std::string::npos) << said;
}

// OpenSubdiv's Hbr reference results (opensubdiv_baselines.h): written from
// floats with 6 significant digits, the Loop shapes agree to 1e-6
namespace {
void expect_opensubdiv_results(const Opensubdiv_case& c, std::string (*path)(const std::string&))
{
  testing_utils::expect_opensubdiv_results<S::Loop_mask<Mesh>, Mesh>(c, path, 1e-6);
}
} // namespace

// the bundled baselines: a closed shape and a shape with sharp border corners
TEST(Loop, matches_opensubdiv_reference_results)
{
  for(const Opensubdiv_case& c : {Opensubdiv_case{"loop_cube", S::Border_corners::smooth, 1},
                                  Opensubdiv_case{"loop_saddle_edgecorner", S::Border_corners::sharp, 2},
                                  Opensubdiv_case{"loop_triangle_edgecorner", S::Border_corners::sharp, 0}})
    expect_opensubdiv_results(c, test_mesh);
}

// every baseline of the shapes: loop_cube and loop_icosahedron are closed; the
// two *_edgecorner shapes use OpenSubdiv's "edges and corners" boundary rule:
// Border_corners::sharp
TEST(Loop, every_level_of_the_shared_opensubdiv_baselines)
{
  SUBDIV_REQUIRE_SHARED_DATA();
  for(const Opensubdiv_case& c : {Opensubdiv_case{"loop_cube", S::Border_corners::smooth, 2},
                                  Opensubdiv_case{"loop_icosahedron", S::Border_corners::smooth, 2},
                                  Opensubdiv_case{"loop_saddle_edgecorner", S::Border_corners::sharp, 2},
                                  Opensubdiv_case{"loop_triangle_edgecorner", S::Border_corners::sharp, 2}})
    expect_opensubdiv_results(c, shared_mesh);
}

// The deliberate difference: by default a border corner follows the smooth
// border rule (as in CGAL), which OpenSubdiv's "edges and corners" mode does not.
TEST(Loop, default_border_corners_differ_from_opensubdiv_edge_and_corner_mode)
{
  Mesh smooth, reference;
  ASSERT_TRUE(testing_utils::read_obj_positions(test_mesh("opensubdiv/loop_triangle_edgecorner.obj"), smooth));
  ASSERT_TRUE(testing_utils::read_obj_positions(
    test_mesh("opensubdiv_hbr_baseline/loop_triangle_edgecorner_level0.obj"), reference));
  S::loop_subdivision(smooth);
  EXPECT_GT(position_mismatch(smooth, reference), 1e-3);
}

namespace {

using KE = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using Exact_mesh = CGAL::Surface_mesh<KE::Point_3>;
using EFT = KE::FT;

} // namespace

TEST(Loop, vertex_weights_of_loop_and_warren)
{
  // Loop's 1987 beta, rational at valences 3, 4, 6
  EXPECT_EQ(S::Loop_beta::beta<EFT>(3), EFT(3) / EFT(16));
  EXPECT_EQ(S::Loop_beta::beta<EFT>(4), EFT(31) / EFT(256));
  EXPECT_EQ(S::Loop_beta::beta<EFT>(6), EFT(1) / EFT(16));
  EXPECT_TRUE(S::Loop_beta::is_exact(6));
  EXPECT_FALSE(S::Loop_beta::is_exact(5));
  EXPECT_NEAR(S::Loop_beta::beta<double>(5), (0.625 - std::pow(0.375 + 0.25 * std::cos(2 * M_PI / 5), 2)) / 5, 1e-17);
  // Warren: 3/(8n), and 3/16 at valence 3; the lecture notes' valence-8 example 5/8 + 8 * 3/64
  EXPECT_EQ(S::Warren_beta::beta<EFT>(3), EFT(3) / EFT(16));
  EXPECT_EQ(S::Warren_beta::beta<EFT>(8), EFT(3) / EFT(64));
  const Exact_mesh mesh = testing_utils::bipyramid<Exact_mesh>(8);
  S::Stencil<Exact_mesh::Vertex_index, EFT> apex, low_valence;
  const S::Loop_mask<Exact_mesh, EFT, S::Warren_beta> warren;
  warren.vertex_node(S::vertex_view(warren, mesh, Exact_mesh::Vertex_index(0)), apex);
  EXPECT_EQ(apex.weight(Exact_mesh::Vertex_index(0)), EFT(5) / EFT(8));
  EXPECT_EQ(apex.weight(Exact_mesh::Vertex_index(2)), EFT(3) / EFT(64));
  const Exact_mesh tetra_like = testing_utils::bipyramid<Exact_mesh>(3); // apexes of valence 3: 7/16 and 3/16
  warren.vertex_node(S::vertex_view(warren, tetra_like, Exact_mesh::Vertex_index(0)), low_valence);
  EXPECT_EQ(low_valence.weight(Exact_mesh::Vertex_index(0)), EFT(7) / EFT(16));
  EXPECT_EQ(low_valence.weight(Exact_mesh::Vertex_index(2)), EFT(3) / EFT(16));
}

TEST(Loop, carries_vertex_data_with_the_same_stencils_and_face_data_to_children)
{
  Exact_mesh mesh = testing_utils::open_fan<Exact_mesh>(5);
  // a scalar that is a linear function of position, and an exact vector: both
  // must come out as that function of the new positions
  auto height = mesh.add_property_map<Exact_mesh::Vertex_index, EFT>("v:height", EFT(0)).first;
  auto shifted = mesh.add_property_map<Exact_mesh::Vertex_index, KE::Vector_3>("v:shifted", CGAL::NULL_VECTOR).first;
  auto label = mesh.add_property_map<Exact_mesh::Face_index, int>("f:label", -1).first;
  const auto linear = [](const KE::Point_3& p) -> EFT { return 3 * p.x() - p.y() + 7 * p.z() + 2; };
  for(auto v : vertices(mesh)) {
    height[v] = linear(mesh.point(v));
    shifted[v] = mesh.point(v) - CGAL::ORIGIN + KE::Vector_3(1, 2, 3);
  }
  int next_label = 100;
  for(auto f : faces(mesh))
    label[f] = next_label++;

  std::vector<S::Vertex_origin> origins;
  S::Carried_data<Exact_mesh> data;
  data.vertex_map(height).vertex_map(shifted).face_map(label).origins(origins);
  const std::size_t vertices_before_last_level = 7 + 11; // V + E of the fan
  S::loop_subdivision(mesh, S::parameters::number_of_iterations(2).carried_data(data));

  EXPECT_EQ(num_faces(mesh), 16u * 5u);
  // old vertices first, then one vertex per edge
  ASSERT_EQ(origins.size(), num_vertices(mesh));
  EXPECT_EQ(origins[0].kind, S::Origin_kind::vertex);
  EXPECT_EQ(origins[vertices_before_last_level - 1].kind, S::Origin_kind::vertex);
  EXPECT_EQ(origins[vertices_before_last_level].kind, S::Origin_kind::edge);
  EXPECT_EQ(origins[vertices_before_last_level].index, 0u);
  EXPECT_EQ(origins.back().index, 36u); // after one level the fan has 2 * 11 + 3 * 5 = 37 edges
  for(auto v : vertices(mesh)) {
    EXPECT_EQ(height[v], linear(mesh.point(v)));
    EXPECT_EQ(shifted[v], mesh.point(v) - CGAL::ORIGIN + KE::Vector_3(1, 2, 3));
  }
  // every old face has 16 descendants, which keep its label
  std::map<int, int> children;
  for(auto f : faces(mesh))
    ++children[label[f]];
  ASSERT_EQ(children.size(), 5u);
  for(const auto& entry : children) {
    EXPECT_GE(entry.first, 100);
    EXPECT_EQ(entry.second, 16);
  }
}
