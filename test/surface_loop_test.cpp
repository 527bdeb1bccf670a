// Loop subdivision: agreement with CGAL's Subdivision_method_3, exact weights, bad input.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <fstream>

#include <gtest/gtest.h>

#include "mesh_test_utils.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace S = CGAL::Subdiv;
using K = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

using testing_utils::position_mismatch;
using testing_utils::shared_mesh;

TEST(Loop, matches_cgal_subdivision_method_3_closed_and_with_border)
{
  SUBDIV_REQUIRE_SHARED_DATA();
  for(const std::string name : {"cgal/elephant.off", "cgal/mesh_with_border.off", "cgal/tetrahedron.off"}) {
    Mesh ours, theirs;
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(shared_mesh(name), ours)) << name;
    theirs = ours;
    S::loop_subdivision(ours, CGAL::parameters::number_of_iterations(2));
    CGAL::Subdivision_method_3::Loop_subdivision(theirs, CGAL::parameters::number_of_iterations(2));
    ASSERT_EQ(num_vertices(ours), num_vertices(theirs)) << name;
    ASSERT_EQ(num_faces(ours), num_faces(theirs)) << name;
    EXPECT_TRUE(ours.is_valid(false)) << name;
    EXPECT_LT(position_mismatch(ours, theirs), 1e-12) << name;
  }
}

TEST(Loop, works_on_polyhedron_3)
{
  SUBDIV_REQUIRE_SHARED_DATA();
  CGAL::Polyhedron_3<K> poly;
  Mesh sm;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(shared_mesh("cgal/mesh_with_border.off"), poly));
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(shared_mesh("cgal/mesh_with_border.off"), sm));
  S::loop_subdivision(poly, CGAL::parameters::number_of_iterations(2));
  S::loop_subdivision(sm, CGAL::parameters::number_of_iterations(2));
  EXPECT_TRUE(poly.is_valid());
  EXPECT_EQ(num_vertices(poly), num_vertices(sm));
  EXPECT_LT(position_mismatch(poly, sm), 1e-14);
}

TEST(Loop, exact_kernel_weights_and_counts)
{
  using KE = CGAL::Simple_cartesian<CGAL::Exact_rational>;
  using P = KE::Point_3;
  using FT = KE::FT;
  CGAL::Surface_mesh<P> octahedron; // every vertex has valence 4: Loop's beta 31/256 is rational there
  const P top(0, 0, 1), bottom(0, 0, -1), e[4] = {P(1, 0, 0), P(0, 1, 0), P(-1, 0, 0), P(0, -1, 0)};
  auto t = octahedron.add_vertex(top), b = octahedron.add_vertex(bottom);
  decltype(t) ring[4];
  for(int i = 0; i < 4; ++i)
    ring[i] = octahedron.add_vertex(e[i]);
  for(int i = 0; i < 4; ++i) {
    octahedron.add_face(t, ring[i], ring[(i + 1) % 4]);
    octahedron.add_face(b, ring[(i + 1) % 4], ring[i]);
  }
  S::loop_subdivision(octahedron);
  EXPECT_EQ(num_vertices(octahedron), 6u + 12u);
  EXPECT_EQ(num_faces(octahedron), 32u);
  // old vertex: (1 - 4 beta) top + beta * (sum of the ring, which is 0): z = 1 - 124/256
  const P moved_top = octahedron.point(decltype(t)(0));
  EXPECT_EQ(moved_top, P(0, 0, FT(1) - FT(4 * 31) / FT(256)));
  // edge top-e0: 3/8 top + 3/8 e0 + 1/8 e1 + 1/8 e3 = (3/8, 0, 3/8)
  bool found = false;
  for(auto v : vertices(octahedron))
    found = found || octahedron.point(v) == P(FT(3) / FT(8), 0, FT(3) / FT(8));
  EXPECT_TRUE(found);
}

TEST(Loop, epeck_mesh_compiles_and_runs)
{
  SUBDIV_REQUIRE_SHARED_DATA();
  using KE = CGAL::Exact_predicates_exact_constructions_kernel;
  CGAL::Surface_mesh<KE::Point_3> mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(shared_mesh("cgal/tetrahedron.off"), mesh));
  S::loop_subdivision(mesh, CGAL::parameters::number_of_iterations(2));
  EXPECT_EQ(num_faces(mesh), 64u);
}

TEST(Loop, bad_input_is_refused_and_the_mesh_is_unchanged)
{
  SUBDIV_REQUIRE_SHARED_DATA();
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
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(shared_mesh("cgal/cube_quad.off"), quad));
  const Mesh quad_copy = quad;
  const std::string not_triangles = message(quad);
  EXPECT_NE(not_triangles.find("faces all have 3 vertices; face 0 has 4"), std::string::npos) << not_triangles;
  EXPECT_EQ(num_faces(quad), num_faces(quad_copy));

  Mesh isolated;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(shared_mesh("cgal/tetrahedron.off"), isolated));
  isolated.add_vertex(K::Point_3(5, 5, 5));
  EXPECT_NE(message(isolated).find("vertex 4 is isolated"), std::string::npos) << message(isolated);
  EXPECT_EQ(num_faces(isolated), 4u);

  Mesh broken;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(shared_mesh("cgal/tetrahedron.off"), broken));
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

  Mesh big;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(shared_mesh("cgal/elephant.off"), big));
  EXPECT_NE(message(big, 40).find("memory"), std::string::npos);
  EXPECT_NE(message(big, -1).find("negative"), std::string::npos);
  EXPECT_EQ(num_faces(big), 5558u);
}

// OpenSubdiv's Hbr reference results: <shape>_levelN.obj holds N+1 uniform steps
// of opensubdiv/<shape>.obj, written from single-precision floats.
TEST(Loop, matches_opensubdiv_reference_results)
{
  SUBDIV_REQUIRE_SHARED_DATA();
  struct Case
  {
    std::string shape;
    S::Border_corners corners;
  };
  // loop_cube and loop_icosahedron are closed; the two *_edgecorner shapes use
  // OpenSubdiv's "edges and corners" boundary rule: Border_corners::sharp
  for(const Case& c :
      {Case{"loop_cube", S::Border_corners::smooth}, Case{"loop_icosahedron", S::Border_corners::smooth},
       Case{"loop_saddle_edgecorner", S::Border_corners::sharp},
       Case{"loop_triangle_edgecorner", S::Border_corners::sharp}}) {
    Mesh mesh;
    ASSERT_TRUE(testing_utils::read_obj_positions(shared_mesh("opensubdiv/" + c.shape + ".obj"), mesh)) << c.shape;
    for(int level = 0; level <= 2; ++level) {
      S::subdivide(mesh, S::Loop_mask<Mesh>(c.corners));
      Mesh reference;
      ASSERT_TRUE(testing_utils::read_obj_positions(
        shared_mesh("opensubdiv_hbr_baseline/" + c.shape + "_level" + std::to_string(level) + ".obj"), reference));
      ASSERT_EQ(num_vertices(mesh), num_vertices(reference)) << c.shape << " level " << level;
      ASSERT_EQ(num_faces(mesh), num_faces(reference)) << c.shape << " level " << level;
      EXPECT_LT(position_mismatch(mesh, reference), 1e-6) << c.shape << " level " << level;
    }
  }
}

// The deliberate difference: by default a border corner follows the smooth
// border rule (as in CGAL), which OpenSubdiv's "edges and corners" mode does not.
TEST(Loop, default_border_corners_differ_from_opensubdiv_edge_and_corner_mode)
{
  SUBDIV_REQUIRE_SHARED_DATA();
  Mesh smooth, reference;
  ASSERT_TRUE(testing_utils::read_obj_positions(shared_mesh("opensubdiv/loop_triangle_edgecorner.obj"), smooth));
  ASSERT_TRUE(testing_utils::read_obj_positions(
    shared_mesh("opensubdiv_hbr_baseline/loop_triangle_edgecorner_level0.obj"), reference));
  S::loop_subdivision(smooth);
  EXPECT_GT(position_mismatch(smooth, reference), 1e-3);
}

namespace {

using KE = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using Exact_mesh = CGAL::Surface_mesh<KE::Point_3>;
using EFT = KE::FT;

// a closed bipyramid: two apexes of valence n over a ring of n vertices of valence 4
Exact_mesh bipyramid(int n)
{
  Exact_mesh mesh;
  const auto top = mesh.add_vertex(KE::Point_3(0, 0, 2)), bottom = mesh.add_vertex(KE::Point_3(1, 0, -3));
  std::vector<Exact_mesh::Vertex_index> ring;
  for(int i = 0; i < n; ++i) // rational points near a circle
    ring.push_back(mesh.add_vertex(KE::Point_3(EFT(10 * (i % 3) + i), EFT(i * i % 7) - EFT(3), EFT(i % 2))));
  for(int i = 0; i < n; ++i) {
    mesh.add_face(top, ring[i], ring[(i + 1) % n]);
    mesh.add_face(bottom, ring[(i + 1) % n], ring[i]);
  }
  return mesh;
}

// an open fan: a centre vertex with n triangles around it, the last one missing (border)
Exact_mesh open_fan(int n)
{
  Exact_mesh mesh;
  const auto centre = mesh.add_vertex(KE::Point_3(0, 0, 0));
  std::vector<Exact_mesh::Vertex_index> ring;
  for(int i = 0; i <= n; ++i)
    ring.push_back(mesh.add_vertex(KE::Point_3(EFT(i + 1), EFT(i * i - 2), EFT(i % 3))));
  for(int i = 0; i < n; ++i)
    mesh.add_face(centre, ring[i], ring[i + 1]);
  return mesh;
}

template <class Mask>
void expect_every_stencil_sums_to_one(const Exact_mesh& mesh, const Mask& mask)
{
  for(auto v : vertices(mesh)) {
    S::Stencil<Exact_mesh::Vertex_index, EFT> stencil;
    mask.vertex_node(S::vertex_view(mask, mesh, v), stencil);
    EXPECT_EQ(stencil.weight_sum(), EFT(1)) << mask.name() << " vertex " << v;
  }
  for(auto e : edges(mesh)) {
    S::Stencil<Exact_mesh::Vertex_index, EFT> stencil;
    mask.edge_node(S::edge_view(mask, mesh, halfedge(e, mesh)), stencil);
    EXPECT_EQ(stencil.weight_sum(), EFT(1)) << mask.name() << " edge " << e;
  }
}

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
  const Exact_mesh mesh = bipyramid(8);
  S::Stencil<Exact_mesh::Vertex_index, EFT> apex, low_valence;
  const S::Loop_mask<Exact_mesh, EFT, S::Warren_beta> warren;
  warren.vertex_node(S::vertex_view(warren, mesh, Exact_mesh::Vertex_index(0)), apex);
  EXPECT_EQ(apex.weight(Exact_mesh::Vertex_index(0)), EFT(5) / EFT(8));
  EXPECT_EQ(apex.weight(Exact_mesh::Vertex_index(2)), EFT(3) / EFT(64));
  const Exact_mesh tetra_like = bipyramid(3); // apexes of valence 3: 7/16 and 3/16
  warren.vertex_node(S::vertex_view(warren, tetra_like, Exact_mesh::Vertex_index(0)), low_valence);
  EXPECT_EQ(low_valence.weight(Exact_mesh::Vertex_index(0)), EFT(7) / EFT(16));
  EXPECT_EQ(low_valence.weight(Exact_mesh::Vertex_index(2)), EFT(3) / EFT(16));
}

TEST(Loop, exact_properties_at_valences_3_to_9_and_on_borders)
{
  for(int n = 3; n <= 9; ++n) {
    for(const Exact_mesh& mesh : {bipyramid(n), open_fan(n)}) {
      expect_every_stencil_sums_to_one(mesh, S::Loop_mask<Exact_mesh>());
      expect_every_stencil_sums_to_one(mesh, S::Loop_mask<Exact_mesh, EFT, S::Warren_beta>());

      // counts: V + E vertices, 4F faces, Euler characteristic kept
      Exact_mesh refined = mesh;
      S::loop_warren_subdivision(refined, CGAL::parameters::number_of_iterations(2));
      const auto euler = [](const Exact_mesh& m) {
        return long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m));
      };
      EXPECT_EQ(num_faces(refined), 16 * num_faces(mesh));
      EXPECT_EQ(euler(refined), euler(mesh));
      EXPECT_TRUE(refined.is_valid(false));

      // affine invariance, exactly: subdivide(T(mesh)) == T(subdivide(mesh))
      const KE::Aff_transformation_3 t(2, 1, 0, 3, 0, 1, 1, -1, 1, 0, 3, 2);
      Exact_mesh moved = mesh;
      for(auto v : vertices(moved))
        moved.point(v) = t.transform(moved.point(v));
      S::loop_subdivision(moved);
      Exact_mesh plain = mesh;
      S::loop_subdivision(plain);
      for(auto v : vertices(plain))
        EXPECT_EQ(moved.point(v), t.transform(plain.point(v))) << "valence " << n;
    }
  }
}

TEST(Loop, a_planar_mesh_stays_in_its_plane_exactly)
{
  Exact_mesh mesh = open_fan(7);
  const KE::Plane_3 plane(KE::Point_3(0, 0, 0), KE::Vector_3(1, 2, 5));
  for(auto v : vertices(mesh)) // project to the plane x + 2y + 5z = 0
    mesh.point(v) = plane.projection(mesh.point(v));
  S::loop_subdivision(mesh, CGAL::parameters::number_of_iterations(2));
  for(auto v : vertices(mesh))
    EXPECT_TRUE(plane.has_on(mesh.point(v)));
}

TEST(Loop, carries_vertex_data_with_the_same_stencils_and_face_data_to_children)
{
  Exact_mesh mesh = open_fan(5);
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
