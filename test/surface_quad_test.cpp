// Catmull-Clark, linear quad split and Doo-Sabin: agreement with CGAL's
// Subdivision_method_3 and OpenSubdiv, the regular rules, valence-2 vertices,
// borders, Epeck, bad input. The properties every scheme has (weights summing
// to one, counts, affine invariance, planarity, Polyhedron_3) are in
// surface_properties.h.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Subdiv/stencils/Stencil.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

#include "mesh_builders.h"
#include "mesh_test_utils.h"
#include "opensubdiv_baselines.h"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace S = CGAL::Subdiv;
using K = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using KX = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using FX = KX::FT;
using PX = KX::Point_3;
using Exact_mesh = CGAL::Surface_mesh<PX>;
using VX = Exact_mesh::Vertex_index;

using testing_utils::Opensubdiv_case;
using testing_utils::position_mismatch;
using testing_utils::shared_mesh;
using testing_utils::test_mesh;

namespace {

// a bundled mesh (test/data)
Mesh read_mesh(const std::string& name)
{
  return testing_utils::bundled<Mesh>(name);
}

Mesh read_shared_mesh(const std::string& name)
{
  Mesh mesh;
  EXPECT_TRUE(testing_utils::read_mesh(shared_mesh(name), mesh)) << name;
  return mesh;
}

// the same mesh with exact coordinates (doubles convert exactly), same indices
Exact_mesh to_exact(const Mesh& mesh)
{
  return testing_utils::copy_mesh<Exact_mesh>(mesh);
}

template <class M>
long euler_characteristic(const M& mesh)
{
  return static_cast<long>(num_vertices(mesh)) - static_cast<long>(num_edges(mesh)) +
         static_cast<long>(num_faces(mesh));
}

template <class M>
std::size_t corner_count(const M& mesh)
{
  std::size_t c = 0;
  for(auto h : halfedges(mesh))
    c += CGAL::is_border(h, mesh) ? 0 : 1;
  return c;
}

// meshes of CGAL's data set, closed, with any face sizes: bundled (test/data)
// and larger ones in ../shared/data
const std::vector<std::string> closed_meshes = {"cgal/cube_quad.off", "cgal/corner.off", "cgal/P.off",
                                                "cgal/mpi.off",       "cgal/3torus.off", "cgal/corner_poly.off"};
const std::vector<std::string> border_meshes = {"cgal/corner_with_hole.off", "cgal/double-torus-3-holes.off",
                                                "cgal/corner_with_sharp_edge.off", "cgal/mesh_with_colors.off"};
const std::vector<std::string> shared_closed_meshes = {"cgal/cross_quad.off", "cgal/elephant.off",
                                                       "cgal/double-torus-example.off"};
const std::vector<std::string> shared_border_meshes = {"cgal/mesh_with_border.off"};

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b)
{
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

} // namespace

// ---------------------------------------------------------------------------
// Agreement with CGAL's Subdivision_method_3

namespace {

void expect_catmull_clark_as_cgal(Mesh ours, const std::string& name)
{
  Mesh theirs = ours;
  S::catmull_clark_subdivision(ours, CGAL::parameters::number_of_iterations(2));
  CGAL::Subdivision_method_3::CatmullClark_subdivision(theirs, CGAL::parameters::number_of_iterations(2));
  theirs.collect_garbage();
  ASSERT_EQ(num_vertices(ours), num_vertices(theirs)) << name;
  ASSERT_EQ(num_faces(ours), num_faces(theirs)) << name;
  EXPECT_TRUE(ours.is_valid(false)) << name;
  EXPECT_LT(position_mismatch(ours, theirs), 1e-12) << name;
}

void expect_doo_sabin_as_cgal(Mesh ours, const std::string& name)
{
  Mesh theirs = ours;
  S::doo_sabin_subdivision(ours, CGAL::parameters::number_of_iterations(2));
  CGAL::Subdivision_method_3::DooSabin_subdivision(theirs, CGAL::parameters::number_of_iterations(2));
  theirs.collect_garbage();
  ASSERT_EQ(num_vertices(ours), num_vertices(theirs)) << name;
  ASSERT_EQ(num_faces(ours), num_faces(theirs)) << name;
  EXPECT_TRUE(ours.is_valid(false)) << name;
  EXPECT_LT(position_mismatch(ours, theirs), 1e-12) << name;
}

// With a border, CGAL's Doo-Sabin moves every corner by the face rule and
// makes no face at border vertices; ours puts border corners on Chaikin's
// points and closes border vertices with 3 or more faces. Every new vertex of
// ours that is not on the border is a vertex of CGAL's result, and CGAL's has
// the border zigzag of extra faces.
void expect_doo_sabin_interior_as_cgal(Mesh ours, const std::string& name)
{
  Mesh theirs = ours;
  S::doo_sabin_subdivision(ours);
  CGAL::Subdivision_method_3::DooSabin_subdivision(theirs);
  theirs.collect_garbage();
  EXPECT_TRUE(ours.is_valid(false)) << name;
  EXPECT_EQ(num_vertices(ours), num_vertices(theirs)) << name; // one per corner in both
  std::vector<testing_utils::Double_point> inside;
  for(auto v : vertices(ours))
    if(!CGAL::is_border(v, ours))
      inside.push_back(testing_utils::Double_point(ours.point(v)));
  EXPECT_LT(position_mismatch(inside, testing_utils::double_points(theirs)), 1e-12) << name;
  EXPECT_GT(position_mismatch(ours, theirs), 1e-3) << name; // the border corners differ
}

} // namespace

TEST(CatmullClark, matches_cgal_subdivision_method_3_closed_and_with_border)
{
  for(const std::string& name : closed_meshes + border_meshes)
    expect_catmull_clark_as_cgal(read_mesh(name), name);
}

TEST(DooSabin, matches_cgal_subdivision_method_3_on_closed_meshes)
{
  for(const std::string& name : closed_meshes)
    expect_doo_sabin_as_cgal(read_mesh(name), name);
}

TEST(DooSabin, interior_agrees_with_cgal_on_meshes_with_border)
{
  for(const std::string& name : border_meshes)
    expect_doo_sabin_interior_as_cgal(read_mesh(name), name);
}

TEST(QuadSchemes, larger_shared_meshes_agree_with_cgal_subdivision_method_3)
{
  SUBDIV_REQUIRE_SHARED_DATA();
  for(const std::string& name : shared_closed_meshes + shared_border_meshes)
    expect_catmull_clark_as_cgal(read_shared_mesh(name), name);
  for(const std::string& name : shared_closed_meshes)
    expect_doo_sabin_as_cgal(read_shared_mesh(name), name);
  for(const std::string& name : shared_border_meshes)
    expect_doo_sabin_interior_as_cgal(read_shared_mesh(name), name);
}

// ---------------------------------------------------------------------------
// Agreement with OpenSubdiv's Hbr reference results (opensubdiv_baselines.h).

namespace {

// the baselines print 6 significant digits: catmark_flap is 0.3 across at 1.9
// from the origin, so its last digit is 1.7e-5 of its size
void expect_opensubdiv_results(const Opensubdiv_case& c, std::string (*path)(const std::string&))
{
  testing_utils::expect_opensubdiv_results<S::Catmull_clark_mask<Mesh>, Mesh>(c, path, 2e-5);
}

// catmark_cube and catmark_pyramid are closed; catmark_tent uses "edges
// only", and catmark_flap has no boundary tag: at their valence-2 corners
// the baselines follow the smooth border rule 1/8, 6/8, 1/8, as ours by
// default; catmark_edgecorner uses "edges and corners" (Border_corners::sharp).
std::vector<Opensubdiv_case> opensubdiv_cases(int last_level)
{
  return {{"catmark_cube", S::Border_corners::smooth, last_level},
          {"catmark_pyramid", S::Border_corners::smooth, last_level},
          {"catmark_tent", S::Border_corners::smooth, last_level},
          {"catmark_edgecorner", S::Border_corners::sharp, last_level},
          {"catmark_flap", S::Border_corners::smooth, last_level}};
}

} // namespace

// the bundled baselines: every shape's first level, two levels of the closed
// shapes and three of catmark_flap
TEST(CatmullClark, matches_opensubdiv_reference_results)
{
  const int last_level[] = {1, 1, 0, 0, 2};
  const std::vector<Opensubdiv_case> cases = opensubdiv_cases(0);
  for(std::size_t i = 0; i < cases.size(); ++i) {
    Opensubdiv_case c = cases[i];
    c.last_level = last_level[i];
    expect_opensubdiv_results(c, test_mesh);
  }
}

TEST(CatmullClark, every_level_of_the_shared_opensubdiv_baselines)
{
  SUBDIV_REQUIRE_SHARED_DATA();
  for(const Opensubdiv_case& c : opensubdiv_cases(2))
    expect_opensubdiv_results(c, shared_mesh);
}

// The deliberate difference: by default a corner with a single face follows
// the smooth border rule (CGAL, OpenSubdiv "edges only"); OpenSubdiv's "edges
// and corners" keeps it in place.
TEST(CatmullClark, default_border_corners_differ_from_opensubdiv_edge_and_corner_mode)
{
  Mesh smooth = read_mesh("opensubdiv/catmark_edgecorner.obj");
  const Mesh reference = read_mesh("opensubdiv_hbr_baseline/catmark_edgecorner_level0.obj");
  S::catmull_clark_subdivision(smooth);
  EXPECT_GT(position_mismatch(smooth, reference), 1e-3);
  // ... and only at the corners: every vertex but the moved corners has its partner
  std::vector<testing_utils::Double_point> not_corners;
  for(auto v : vertices(smooth))
    if(!(CGAL::is_border(v, smooth) && degree(v, smooth) == 2))
      not_corners.push_back(testing_utils::Double_point(smooth.point(v)));
  EXPECT_LT(position_mismatch(not_corners, testing_utils::double_points(reference)), 1e-6);
}

// ---------------------------------------------------------------------------
// The regular rules

namespace {

using Stencil = S::Stencil<VX, FX>;

bool same_stencil(const Stencil& a, const Stencil& b)
{
  if(a.size() != b.size())
    return false;
  for(const auto& term : a.terms())
    if(b.weight(term.first) != term.second)
      return false;
  return true;
}

// an n x n grid of quads' vertices (i, j, z_ij) with generic rational heights
Exact_mesh grid(int n, std::vector<std::vector<VX>>& id)
{
  id.assign(n, std::vector<VX>(n));
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      id[i][j] = testing_utils::grid_vertex<Exact_mesh>(n - 1, i, j);
  return testing_utils::grid<Exact_mesh>(
    n - 1, n - 1, [](int i, int j) { return PX(i, j, FX(3 * i * i + 7 * j + i * j + 1) / FX(5 + i + 2 * j)); }, false);
}

// the cubic B-spline curve masks: vertex (1/8, 6/8, 1/8), edge (1/2, 1/2)
FX vertex_mask(int d)
{
  return d == 0 ? FX(6) / FX(8) : FX(1) / FX(8);
}
FX edge_mask(int)
{
  return FX(1) / FX(2);
}

} // namespace

// On a regular grid, Catmull-Clark is the bicubic uniform B-spline: its rules
// are the tensor products of the cubic B-spline curve rules, and in the form
// of the lecture notes, with face points f (of the faces around) and edge
// neighbours e: edge point 1/4 (v + e + f + f'), vertex point
// 1/2 v + 1/16 sum e + 1/16 sum f.
TEST(CatmullClark, regular_grid_rules_are_the_bicubic_bspline_rules)
{
  std::vector<std::vector<VX>> id;
  const Exact_mesh mesh = grid(7, id);
  const S::Catmull_clark_mask<Exact_mesh> mask;
  const auto face_point = [&](int i, int j, const FX& s, Stencil& acc) { // face of cell (i, j)
    for(int a = 0; a < 2; ++a)
      for(int b = 0; b < 2; ++b)
        acc.add(id[i + a][j + b], s / FX(4));
  };
  for(int i = 2; i <= 4; ++i)
    for(int j = 2; j <= 4; ++j) {
      // vertex (i, j)
      Stencil ours, tensor, notes;
      mask.vertex_node(S::vertex_view(mask, mesh, id[i][j]), ours);
      for(int a = -1; a <= 1; ++a)
        for(int b = -1; b <= 1; ++b)
          tensor.add(id[i + a][j + b], vertex_mask(a) * vertex_mask(b));
      notes.add(id[i][j], FX(1) / FX(2));
      for(const auto& d : {std::make_pair(1, 0), std::make_pair(-1, 0), std::make_pair(0, 1), std::make_pair(0, -1)})
        notes.add(id[i + d.first][j + d.second], FX(1) / FX(16));
      for(int a = -1; a <= 0; ++a)
        for(int b = -1; b <= 0; ++b)
          face_point(i + a, j + b, FX(1) / FX(16), notes);
      EXPECT_TRUE(same_stencil(ours, tensor)) << i << " " << j;
      EXPECT_TRUE(same_stencil(ours, notes)) << i << " " << j;
      EXPECT_EQ(ours.weight(id[i][j]), FX(9) / FX(16));
      EXPECT_EQ(ours.weight(id[i + 1][j]), FX(3) / FX(32));
      EXPECT_EQ(ours.weight(id[i + 1][j + 1]), FX(1) / FX(64));

      // edge (i, j) - (i + 1, j), between cells (i, j - 1) and (i, j)
      Stencil ours_edge, tensor_edge, notes_edge;
      mask.edge_node(S::edge_view(mask, mesh, halfedge(id[i][j], id[i + 1][j], mesh).first), ours_edge);
      for(int a = 0; a <= 1; ++a)
        for(int b = -1; b <= 1; ++b)
          tensor_edge.add(id[i + a][j + b], edge_mask(a) * vertex_mask(b));
      notes_edge.add(id[i][j], FX(1) / FX(4));
      notes_edge.add(id[i + 1][j], FX(1) / FX(4));
      face_point(i, j - 1, FX(1) / FX(4), notes_edge);
      face_point(i, j, FX(1) / FX(4), notes_edge);
      EXPECT_TRUE(same_stencil(ours_edge, tensor_edge)) << i << " " << j;
      EXPECT_TRUE(same_stencil(ours_edge, notes_edge)) << i << " " << j;

      // face of cell (i, j)
      Stencil ours_face, tensor_face;
      mask.face_node(S::face_view(mask, mesh, face(halfedge(id[i][j], id[i + 1][j], mesh).first, mesh)), ours_face);
      for(int a = 0; a <= 1; ++a)
        for(int b = 0; b <= 1; ++b)
          tensor_face.add(id[i + a][j + b], edge_mask(a) * edge_mask(b));
      EXPECT_TRUE(same_stencil(ours_face, tensor_face)) << i << " " << j;
    }
}

// Doo-Sabin on a quad is the biquadratic B-spline: 9/16, 3/16, 3/16, 1/16
TEST(DooSabin, quad_weights_are_the_biquadratic_bspline_weights)
{
  std::vector<std::vector<VX>> id;
  const Exact_mesh mesh = grid(4, id);
  Stencil ours;
  S::Doo_sabin_mask<Exact_mesh>().corner_node(
    S::Corner_view<Exact_mesh>(mesh, halfedge(id[1][1], id[2][1], mesh).first), ours);
  EXPECT_EQ(ours.size(), 4u);
  EXPECT_EQ(ours.weight(id[2][1]), FX(9) / FX(16));
  EXPECT_EQ(ours.weight(id[1][1]), FX(3) / FX(16));
  EXPECT_EQ(ours.weight(id[2][2]), FX(3) / FX(16));
  EXPECT_EQ(ours.weight(id[1][2]), FX(1) / FX(16));
}

// ---------------------------------------------------------------------------
// Other cases

// Interior vertices of valence 2 (OpenSubdiv's val2 shapes): Doo-Sabin makes
// no 2-gon there, the two edge quads share an edge; every scheme gives a
// valid mesh with the same Euler characteristic.
TEST(QuadSchemes, interior_valence_2_vertices)
{
  for(const std::string name : {"opensubdiv/catmark_val2_interior.obj", "opensubdiv/catmark_val2_back2back.obj",
                                "opensubdiv/catmark_val2_foldover.obj", "opensubdiv/catmark_gregory_test8.obj"}) {
    const Mesh mesh = read_mesh(name);
    std::size_t valence_2 = 0;
    for(auto v : vertices(mesh))
      valence_2 += (!CGAL::is_border(v, mesh) && degree(v, mesh) == 2) ? 1 : 0;
    EXPECT_GT(valence_2, 0u) << name;
    Mesh cc = mesh, ds = mesh;
    S::catmull_clark_subdivision(cc, CGAL::parameters::number_of_iterations(2));
    S::doo_sabin_subdivision(ds);
    EXPECT_TRUE(cc.is_valid(false) && CGAL::is_valid_polygon_mesh(cc)) << name;
    EXPECT_TRUE(ds.is_valid(false) && CGAL::is_valid_polygon_mesh(ds)) << name;
    EXPECT_EQ(euler_characteristic(cc), euler_characteristic(mesh)) << name;
    EXPECT_EQ(euler_characteristic(ds), euler_characteristic(mesh)) << name;
    EXPECT_EQ(num_vertices(ds), corner_count(mesh)) << name;
    for(auto f : faces(ds))
      EXPECT_GE(degree(f, ds), 3u) << name;
    S::doo_sabin_subdivision(ds); // no interior vertex of valence 2 is left
    EXPECT_TRUE(ds.is_valid(false)) << name;
  }
}

TEST(LinearQuad, points_are_the_old_vertices_edge_midpoints_and_face_centroids)
{
  const Exact_mesh mesh = to_exact(read_mesh("cgal/P.off"));
  std::set<PX> expected;
  for(auto v : vertices(mesh))
    expected.insert(mesh.point(v));
  for(auto e : edges(mesh))
    expected.insert(CGAL::midpoint(mesh.point(source(e, mesh)), mesh.point(target(e, mesh))));
  for(auto f : faces(mesh)) {
    KX::Vector_3 sum = CGAL::NULL_VECTOR;
    int size = 0;
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      sum = sum + (mesh.point(v) - CGAL::ORIGIN);
      ++size;
    }
    expected.insert(CGAL::ORIGIN + sum / FX(size));
  }
  Exact_mesh linear = mesh;
  S::linear_quad_subdivision(linear);
  std::set<PX> got;
  for(auto v : vertices(linear))
    got.insert(linear.point(v));
  EXPECT_EQ(got, expected);
  EXPECT_EQ(num_vertices(linear), num_vertices(mesh) + num_edges(mesh) + num_faces(mesh));
}

// ---------------------------------------------------------------------------
// Borders

// Doo-Sabin's border: the new border polygon is Chaikin's refinement of the
// old one (points 3/4 u + 1/4 v and 1/4 u + 3/4 v on every border edge (u, v)),
// except that a vertex with a single face stays and takes the place of both
// its Chaikin points. Checked exactly, edge by edge.
TEST(DooSabin, border_is_chaikins_refinement_of_the_border_polygon)
{
  using Edge = std::pair<PX, PX>;
  const auto edge_of = [](const PX& a, const PX& b) { return a < b ? Edge(a, b) : Edge(b, a); };
  for(const std::string name : {"opensubdiv/catmark_tent.obj", "cgal/double-torus-3-holes.off",
                                "cgal/corner_with_hole.off", "cgal/mesh_with_colors.off"}) {
    const Exact_mesh mesh = to_exact(read_mesh(name));
    const auto corner = [&](VX v) { return degree(v, mesh) == 2; };
    const auto near = [&](VX u, VX v) -> PX { // the Chaikin point of (u, v) near u
      if(corner(u))
        return mesh.point(u);
      return CGAL::barycenter(mesh.point(u), FX(3) / FX(4), mesh.point(v), FX(1) / FX(4));
    };
    std::set<Edge> expected;
    for(auto h : halfedges(mesh)) {
      if(!CGAL::is_border(h, mesh))
        continue;
      const VX u = source(h, mesh), v = target(h, mesh), w = target(next(h, mesh), mesh);
      expected.insert(edge_of(near(u, v), near(v, u)));
      if(!corner(v))
        expected.insert(edge_of(near(v, u), near(v, w)));
    }
    Exact_mesh refined = mesh;
    S::doo_sabin_subdivision(refined);
    std::set<Edge> got;
    for(auto h : halfedges(refined))
      if(CGAL::is_border(h, refined))
        got.insert(edge_of(refined.point(source(h, refined)), refined.point(target(h, refined))));
    EXPECT_EQ(got.size(), expected.size()) << name;
    EXPECT_TRUE(got == expected) << name;
    // and the corners stay at every level
    S::doo_sabin_subdivision(refined);
    std::set<PX> points;
    for(auto v : vertices(refined))
      points.insert(refined.point(v));
    for(auto v : vertices(mesh))
      if(CGAL::is_border(v, mesh) && corner(v)) {
        EXPECT_EQ(points.count(mesh.point(v)), 1u) << name;
      }
  }
}

// Catmull-Clark's border: the new border polygon is the cubic B-spline
// refinement of the old one (midpoints, and 1/8, 6/8, 1/8 at the vertices).
TEST(CatmullClark, border_is_the_cubic_bspline_refinement_of_the_border_polygon)
{
  for(const std::string name : {"opensubdiv/catmark_tent.obj", "cgal/double-torus-3-holes.off"}) {
    const Exact_mesh mesh = to_exact(read_mesh(name));
    std::set<PX> expected;
    for(auto h : halfedges(mesh)) {
      if(!CGAL::is_border(h, mesh))
        continue;
      const PX& u = mesh.point(source(h, mesh));
      const PX& v = mesh.point(target(h, mesh));
      const PX& w = mesh.point(target(next(h, mesh), mesh));
      expected.insert(CGAL::midpoint(u, v));
      expected.insert(CGAL::barycenter(u, FX(1) / FX(8), v, FX(6) / FX(8), w, FX(1) / FX(8)));
    }
    Exact_mesh refined = mesh;
    S::catmull_clark_subdivision(refined);
    std::set<PX> got;
    for(auto v : vertices(refined))
      if(CGAL::is_border(v, refined))
        got.insert(refined.point(v));
    EXPECT_TRUE(got == expected) << name;
  }
}

// ---------------------------------------------------------------------------
// Other kernels

TEST(QuadSchemes, epeck_mesh_compiles_and_runs)
{
  using KE = CGAL::Exact_predicates_exact_constructions_kernel;
  using EpeckMesh = CGAL::Surface_mesh<KE::Point_3>;
  EpeckMesh cube;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh("cgal/cube_quad.off"), cube));
  EpeckMesh cc = cube, ds = cube, linear = cube;
  S::catmull_clark_subdivision(cc, CGAL::parameters::number_of_iterations(2));
  S::doo_sabin_subdivision(ds, CGAL::parameters::number_of_iterations(2));
  S::linear_quad_subdivision(linear);
  EXPECT_EQ(num_faces(cc), 96u);
  EXPECT_EQ(num_vertices(ds), 96u);
  EXPECT_EQ(num_faces(linear), 24u);
  // a cube's Catmull-Clark points are symmetric: the centroid stays at the centre
  KE::Vector_3 sum = CGAL::NULL_VECTOR;
  for(auto v : vertices(cc))
    sum = sum + (cc.point(v) - CGAL::ORIGIN);
  KE::Vector_3 before = CGAL::NULL_VECTOR;
  for(auto v : vertices(cube))
    before = before + (cube.point(v) - CGAL::ORIGIN);
  EXPECT_EQ(sum / KE::FT(num_vertices(cc)), before / KE::FT(num_vertices(cube)));
}

// ---------------------------------------------------------------------------
// Bad input (the checks are shared; this shows Catmull-Clark and Doo-Sabin use them)

TEST(QuadSchemes, bad_input_is_refused_and_the_mesh_is_unchanged)
{
  Mesh empty;
  const std::string empty_message = testing_utils::bad_input_message([&] { S::catmull_clark_subdivision(empty); });
  EXPECT_NE(empty_message.find("Catmull-Clark: the mesh is empty"), std::string::npos) << empty_message;

  Mesh isolated = read_mesh("cgal/cube_quad.off");
  isolated.add_vertex(K::Point_3(5, 5, 5));
  const Mesh copy = isolated;
  const std::string isolated_message =
    testing_utils::bad_input_message([&] { S::catmull_clark_subdivision(isolated); });
  EXPECT_NE(isolated_message.find("vertex 8 is isolated"), std::string::npos) << isolated_message;
  EXPECT_EQ(num_faces(isolated), 6u);
  EXPECT_EQ(num_vertices(isolated), 9u);
  EXPECT_LT(position_mismatch(isolated, copy), 1e-300);

  const std::string doo_sabin_message = testing_utils::bad_input_message([&] { S::doo_sabin_subdivision(isolated); });
  EXPECT_NE(doo_sabin_message.find("Doo-Sabin: vertex 8 is isolated"), std::string::npos) << doo_sabin_message;
  EXPECT_EQ(num_faces(isolated), 6u);
}

// Isolated vertices, which OpenSubdiv accepts: dropped, or kept unrefined
// after the refined vertices; the rest refines as if they were not there
std::vector<K::Point_3> sorted_points(const Mesh& mesh)
{
  std::vector<K::Point_3> points;
  for(auto v : vertices(mesh))
    points.push_back(mesh.point(v));
  std::sort(points.begin(), points.end());
  return points;
}

template <class Subdivide>
void expect_isolated_vertices_set_aside(const Mesh& clean, const Subdivide& subdivide_with)
{
  Mesh with_isolated;
  with_isolated.add_vertex(K::Point_3(5, 5, 5)); // before the others: they are renumbered
  CGAL::copy_face_graph(clean, with_isolated);
  with_isolated.add_vertex(K::Point_3(-5, 4, 3));
  Mesh expected = clean;
  subdivide_with(expected, S::Isolated_vertices::refuse);

  Mesh dropped = with_isolated;
  subdivide_with(dropped, S::Isolated_vertices::drop);
  EXPECT_EQ(num_faces(dropped), num_faces(expected));
  EXPECT_EQ(num_vertices(dropped), num_vertices(expected));
  // the same up to the order of the sums (the vertices are renumbered)
  EXPECT_LT(position_mismatch(dropped, expected), 1e-15);

  Mesh kept = with_isolated;
  subdivide_with(kept, S::Isolated_vertices::keep);
  ASSERT_EQ(num_vertices(kept), num_vertices(expected) + 2);
  EXPECT_EQ(num_faces(kept), num_faces(expected));
  const Mesh::Vertex_index first(static_cast<Mesh::size_type>(num_vertices(expected)));
  const Mesh::Vertex_index second(static_cast<Mesh::size_type>(num_vertices(expected) + 1));
  EXPECT_EQ(kept.point(first), K::Point_3(5, 5, 5));
  EXPECT_EQ(kept.point(second), K::Point_3(-5, 4, 3));
  EXPECT_TRUE(kept.is_isolated(first) && kept.is_isolated(second));
  Mesh kept_faces = kept;
  kept_faces.remove_vertex(first);
  kept_faces.remove_vertex(second);
  kept_faces.collect_garbage();
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(kept_faces));
  EXPECT_LT(position_mismatch(kept_faces, expected), 1e-15);

  // refused (the default, QuadSchemes.bad_input_is_refused_and_the_mesh_is_unchanged)
  // with the parameter named; kept or dropped with carried data: refused
  const Mesh copy = with_isolated;
  const std::string refused =
    testing_utils::bad_input_message([&] { subdivide_with(with_isolated, S::Isolated_vertices::refuse); });
  EXPECT_NE(refused.find("vertex 0 is isolated (it belongs to no face); the named parameter "
                         "isolated_vertices(Isolated_vertices::keep)"),
            std::string::npos)
    << refused;
  S::Carried_data<Mesh> data;
  auto weight = with_isolated.add_property_map<Mesh::Vertex_index, double>("v:weight", 1.0).first;
  data.vertex_map(weight);
  const std::string carried = testing_utils::bad_input_message([&] {
    S::subdivide(with_isolated, S::Catmull_clark_mask<Mesh>(),
                 S::parameters::isolated_vertices(S::Isolated_vertices::keep).carried_data(data));
  });
  EXPECT_NE(carried.find("2 isolated vertices, and isolated_vertices(keep or drop) cannot be combined with "
                         "carried_data yet"),
            std::string::npos)
    << carried;
  EXPECT_EQ(num_vertices(with_isolated), num_vertices(copy));
  EXPECT_EQ(sorted_points(with_isolated), sorted_points(copy));
}

TEST(QuadSchemes, isolated_vertices_are_dropped_or_kept_on_request)
{
  using Policy = S::Isolated_vertices;
  const auto with = [](int levels, Policy policy) {
    return S::parameters::number_of_iterations(levels).isolated_vertices(policy);
  };
  const Mesh cube = read_mesh("cgal/cube_quad.off");
  expect_isolated_vertices_set_aside(cube,
                                     [&](Mesh& m, const Policy& p) { S::catmull_clark_subdivision(m, with(2, p)); });
  expect_isolated_vertices_set_aside(cube, [&](Mesh& m, const Policy& p) { S::doo_sabin_subdivision(m, with(1, p)); });
  Mesh tetrahedron;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(test_mesh("cgal/tetrahedron.off"), tetrahedron));
  expect_isolated_vertices_set_aside(tetrahedron,
                                     [&](Mesh& m, const Policy& p) { S::loop_subdivision(m, with(2, p)); });
  expect_isolated_vertices_set_aside(tetrahedron,
                                     [&](Mesh& m, const Policy& p) { S::sqrt3_subdivision(m, with(2, p)); });

  // the stencil tables have no such parameter: their refusal names none
  Mesh for_table;
  CGAL::copy_face_graph(cube, for_table);
  for_table.add_vertex(K::Point_3(5, 5, 5));
  const std::string table_message =
    testing_utils::bad_input_message([&] { S::make_stencil_table(for_table, S::Catmull_clark_mask<Mesh>()); });
  EXPECT_NE(table_message.find("vertex 8 is isolated (it belongs to no face)"), std::string::npos) << table_message;
  EXPECT_EQ(table_message.find("isolated_vertices("), std::string::npos) << table_message;

  // any FaceGraph: a Polyhedron_3 (the generic checks) drops and keeps alike
  using Polyhedron = CGAL::Polyhedron_3<K>;
  const auto polyhedron_with_isolated = [&] {
    Polyhedron p;
    CGAL::copy_face_graph(cube, p);
    put(CGAL::vertex_point, p, add_vertex(p), K::Point_3(5, 5, 5));
    return p;
  };
  Mesh expected = cube;
  S::catmull_clark_subdivision(expected, with(2, Policy::refuse));
  Polyhedron refused = polyhedron_with_isolated();
  const std::string message =
    testing_utils::bad_input_message([&] { S::catmull_clark_subdivision(refused, with(2, Policy::refuse)); });
  EXPECT_NE(message.find("vertex 8 is isolated"), std::string::npos) << message;
  Polyhedron dropped = polyhedron_with_isolated();
  S::catmull_clark_subdivision(dropped, with(2, Policy::drop));
  EXPECT_EQ(num_vertices(dropped), num_vertices(expected));
  EXPECT_LT(position_mismatch(dropped, expected), 1e-15);
  Polyhedron kept = polyhedron_with_isolated();
  S::catmull_clark_subdivision(kept, with(2, Policy::keep));
  EXPECT_EQ(num_vertices(kept), num_vertices(expected) + 1);
  EXPECT_EQ(num_faces(kept), num_faces(expected));
}
