// Limit positions, limit normals and displacement (issue 4, limit part): the
// masks come from the analysis, mapped onto the mesh by the same labelling walk.
#include <CGAL/Subdiv/limit.h>
#include <CGAL/Subdiv/masks/Butterfly_mask.h>
#include <CGAL/Subdiv/masks/Catmull_clark_mask.h>
#include <CGAL/Subdiv/masks/Doo_sabin_mask.h>
#include <CGAL/Subdiv/masks/Interpolating_sqrt3_mask.h>
#include <CGAL/Subdiv/masks/Linear_triangle_mask.h>
#include <CGAL/Subdiv/masks/Loop_mask.h>
#include <CGAL/Subdiv/masks/Modified_butterfly_mask.h>
#include <CGAL/Subdiv/masks/Sqrt3_mask.h>
#include <CGAL/Subdiv/surface_subdivision.h>

#include "mesh_builders.h"
#include "mesh_test_utils.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

namespace SD = CGAL::Subdiv;
using K = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using QK = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using Exact_mesh = CGAL::Surface_mesh<QK::Point_3>;
using Q = CGAL::Exact_rational;
using V = Mesh::Vertex_index;

template <class M, class N = SD::internal::Mesh_FT<M>>
using Warren_loop = SD::Loop_warren_mask<M, N>;

const double pi = 3.14159265358979323846;

template <class SM = Mesh>
SM tetrahedron()
{
  return testing_utils::tetrahedron<SM>();
}

template <class SM = Mesh>
SM cube()
{
  return testing_utils::cube<SM>();
}

// the icosahedron, vertices on the unit sphere, faces outward
Mesh icosahedron()
{
  const double t = (1 + std::sqrt(5.0)) / 2, s = 1 / std::sqrt(1 + t * t);
  std::vector<K::Point_3> p = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                               {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for(auto& q : p)
    q = K::Point_3(q.x() * s, q.y() * s, q.z() * s);
  return testing_utils::mesh_of<Mesh>(
    p, {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}});
}

// an n x m grid in the plane z = 0, counter-clockwise seen from +z; triangles
// (each square split along alternating diagonals, so that valences vary) or quads
template <class SM = Mesh>
SM grid(int n, int m, bool triangles)
{
  using P = typename SM::Point;
  return testing_utils::grid<SM>(
    n, m, [](int i, int j) { return P(i, j, 0); }, triangles, testing_utils::Diagonal::alternating);
}

double distance(const K::Point_3& a, const K::Point_3& b)
{
  return std::sqrt(CGAL::squared_distance(a, b));
}

// the largest distance between the points of the first `count` vertices of two meshes
double largest_distance(const Mesh& a, const Mesh& b, std::size_t count)
{
  double worst = 0;
  for(std::size_t i = 0; i < count; ++i) {
    const V v(static_cast<Mesh::size_type>(i));
    worst = (std::max)(worst, distance(a.point(v), b.point(v)));
  }
  return worst;
}

std::vector<K::Point_3> points_of(const Mesh& mesh)
{
  return std::vector<K::Point_3>(mesh.points().begin(), mesh.points().end());
}

std::vector<K::Vector_3> normals_of(const Mesh& mesh,
                                    const std::function<void(const Mesh&, Mesh::Property_map<V, K::Vector_3>)>& compute)
{
  Mesh copy = mesh;
  auto map = copy.add_property_map<V, K::Vector_3>("v:n", K::Vector_3(0, 0, 0)).first;
  compute(copy, map);
  std::vector<K::Vector_3> out;
  for(V v : copy.vertices())
    out.push_back(map[v]);
  return out;
}

template <template <class, class> class M>
std::vector<K::Vector_3> limit_normals_of(const Mesh& mesh)
{
  return normals_of(
    mesh, [](const Mesh& m, Mesh::Property_map<V, K::Vector_3> map) { SD::limit_normals(m, M<Mesh, double>(), map); });
}

// ------------------------------------------------------------------ masks

// the masks are those of the analysis: closed forms of Loop and Catmull-Clark,
// border limit 1/6, 2/3, 1/6; the labelling walk reproduces the analysis' labels
// (checked inside compute_limit_masks, which throws otherwise)
TEST(LimitMasks, come_from_the_analysis)
{
  const auto warren = SD::Limit_evaluator<Warren_loop<Mesh, double>>();
  for(int n = 3; n <= 10; ++n) {
    const SD::Limit_masks& m = warren.masks(n, false);
    EXPECT_EQ(m.rings, 1);
    ASSERT_EQ(m.limit.size(), static_cast<std::size_t>(n + 1));
    const Q centre = n == 3 ? Q(2) / Q(5) : Q(1) / Q(2);
    EXPECT_EQ(m.limit[0], centre);
    for(int i = 1; i <= n; ++i)
      EXPECT_EQ(m.limit[static_cast<std::size_t>(i)], (Q(1) - centre) / Q(n));
    EXPECT_TRUE(m.tangents);
  }
  // Catmull-Clark from valence 2 (two quads sharing both edges at the centre,
  // OpenSubdiv's val2 shapes): (n^2 v + 4 sum e + sum f) / (n (n + 5)),
  // OpenSubdiv's closed form (Far takes the corner mask at n = 2 instead:
  // doc/limit.md). At n = 2 the subdominant 1/4 (twice) ties with -1/4: no
  // tangent plane, face normals
  const auto cc = SD::Limit_evaluator<SD::Catmull_clark_mask<Mesh, double>>();
  for(int n = 2; n <= 8; ++n) {
    const SD::Limit_masks& m = cc.masks(n, false);
    ASSERT_EQ(m.limit.size(), static_cast<std::size_t>(2 * n + 1));
    const Q d(n * (n + 5));
    EXPECT_EQ(m.limit[0], Q(n * n) / d);
    for(int i = 1; i <= 2 * n; ++i)
      EXPECT_EQ(m.limit[static_cast<std::size_t>(i)], (i % 2 == 1 ? Q(4) : Q(1)) / d);
    EXPECT_EQ(m.tangents, n >= 3) << "valence " << n;
  }
  EXPECT_NEAR(cc.masks(2, false).subdominant.real(), 0.25, 1e-12);
  EXPECT_NEAR(cc.masks(2, false).subdominant.imag(), 0, 1e-12);
  for(int k = 1; k <= 5; ++k) {
    const SD::Limit_masks& m = cc.masks(k, true);
    EXPECT_EQ(m.limit[0], Q(2) / Q(3));
    const SD::Limit_masks& l = warren.masks(k, true);
    EXPECT_EQ(l.limit[0], Q(2) / Q(3));
    EXPECT_EQ(l.limit[1], Q(1) / Q(6));
    EXPECT_EQ(l.limit[static_cast<std::size_t>(k + 1)], Q(1) / Q(6));
  }
  // interpolating schemes: the limit mask is the centre's unit vector
  const auto butterfly = SD::Limit_evaluator<SD::Butterfly_mask<Mesh, double>>();
  for(int n : {4, 5, 6, 7}) {
    const SD::Limit_masks& m = butterfly.masks(n, false);
    EXPECT_EQ(m.rings, 2);
    EXPECT_EQ(m.limit[0], Q(1));
    for(std::size_t i = 1; i < m.limit.size(); ++i)
      EXPECT_EQ(m.limit[i], Q(0));
    EXPECT_TRUE(m.tangents);
  }
  // the butterfly at n = 3 has no separated subdominant pair (1/4, 7 times): normals fall back
  EXPECT_FALSE(butterfly.masks(3, false).tangents);
}

// above valence max_exact_limit_valence, in doubles, the masks come from the
// double spectrum alone (the pole shapes of OpenSubdiv: valence 64 took 8 s,
// 360 did not finish): still the closed forms, to double precision, and the
// tangents stand
// Catmull-Clark at an interior vertex of valence 2 (OpenSubdiv's
// catmark_val2_interior: vertex 16 splits a quad of a grid in two): the
// refined points of the vertex converge to the analysis' limit, the error
// shrinking by about 4 per level (the subdominant eigenvalue 1/4). OpenSubdiv's
// PrimvarRefiner::Limit returns the vertex itself there (the corner mask),
// which refinement leaves behind (sharp_features_test).
TEST(LimitMasks, valence_2_is_where_refinement_converges)
{
  Mesh coarse;
  ASSERT_TRUE(
    testing_utils::read_obj_positions(testing_utils::test_mesh("opensubdiv/catmark_val2_interior.obj"), coarse));
  const V centre(16);
  ASSERT_FALSE(coarse.is_border(centre));
  ASSERT_EQ(coarse.degree(centre), 2u);
  Mesh limit = coarse;
  SD::project_to_limit(limit, SD::Catmull_clark_mask<Mesh>());
  EXPECT_NEAR(limit.point(centre).y(), -0.5 * 2 / 7, 1e-15); // 2/7 of the vertex, its four neighbours at y = 0
  Mesh refined = coarse;
  double error = std::sqrt(CGAL::squared_distance(refined.point(centre), limit.point(centre)));
  for(int level = 1; level <= 5; ++level) {
    SD::catmull_clark_subdivision(refined, SD::parameters::number_of_iterations(1));
    const double finer = std::sqrt(CGAL::squared_distance(refined.point(centre), limit.point(centre)));
    EXPECT_LT(finer, error / 3) << "level " << level;
    error = finer;
  }
  EXPECT_LT(error, 1e-3);
}

TEST(LimitMasks, high_valence_in_doubles_keeps_the_closed_forms)
{
  ASSERT_EQ(SD::internal::max_exact_limit_valence, 24);
  const auto cc = SD::Limit_evaluator<SD::Catmull_clark_mask<Mesh, double>>();
  for(int n : {25, 64, 200}) {
    const SD::Limit_masks& m = cc.masks(n, false);
    ASSERT_EQ(m.limit.size(), static_cast<std::size_t>(2 * n + 1));
    const double d = n * (n + 5.0);
    EXPECT_NEAR(CGAL::to_double(m.limit[0]), n * n / d, 1e-13) << n;
    for(int i = 1; i <= 2 * n; ++i)
      EXPECT_NEAR(CGAL::to_double(m.limit[static_cast<std::size_t>(i)]), (i % 2 == 1 ? 4 : 1) / d, 1e-13) << n;
    EXPECT_TRUE(m.tangents) << n;
  }
  const auto warren = SD::Limit_evaluator<Warren_loop<Mesh, double>>();
  for(int n : {25, 64, 360}) {
    const SD::Limit_masks& m = warren.masks(n, false);
    ASSERT_EQ(m.limit.size(), static_cast<std::size_t>(n + 1));
    EXPECT_NEAR(CGAL::to_double(m.limit[0]), 0.5, 1e-13) << n;
    for(int i = 1; i <= n; ++i)
      EXPECT_NEAR(CGAL::to_double(m.limit[static_cast<std::size_t>(i)]), 0.5 / n, 1e-13) << n;
    EXPECT_TRUE(m.tangents) << n;
  }
}

// ------------------------------------------------------------------ limit positions

// after L more levels an old vertex is within |lambda_1|^L (times the size of
// its neighbourhood) of its limit: lambda_1 = 1/2 for valence 6 and 3/8 +
// cos(2 pi / 5) / 4 < 1/2 for valence 5
TEST(ProjectToLimit, loop_agrees_with_deep_refinement)
{
  Mesh mesh = icosahedron();
  SD::loop_subdivision(mesh, CGAL::parameters::number_of_iterations(1));
  Mesh limit = mesh;
  SD::project_to_limit(limit, SD::Loop_mask<decltype(limit)>());
  const std::size_t old = mesh.number_of_vertices();
  const double edge = distance(mesh.point(V(0)), mesh.point(mesh.source(mesh.halfedge(V(0)))));
  Mesh deep = mesh;
  for(int L = 1; L <= 6; ++L) {
    SD::loop_subdivision(deep, CGAL::parameters::number_of_iterations(1));
    const double worst = largest_distance(deep, limit, old);
    EXPECT_LE(worst, 2 * edge * std::pow(0.5, L)) << "L = " << L;
    if(L == 6) {
      EXPECT_GT(worst, 0.0);
    }
  }
}

TEST(ProjectToLimit, catmull_clark_agrees_with_deep_refinement)
{
  Mesh mesh = cube();
  SD::catmull_clark_subdivision(mesh, CGAL::parameters::number_of_iterations(1));
  Mesh limit = mesh;
  SD::project_to_limit(limit, SD::Catmull_clark_mask<decltype(limit)>());
  const std::size_t old = mesh.number_of_vertices();
  Mesh deep = mesh;
  // valence 3: lambda_1 = (5 + c + cos(pi/3) sqrt(18 + 2c)) / 16 with c = cos(2 pi / 3)
  const double c = std::cos(2 * pi / 3),
               lambda = (std::max)(0.5, (5 + c + std::cos(pi / 3) * std::sqrt(18 + 2 * c)) / 16);
  for(int L = 1; L <= 5; ++L) {
    SD::catmull_clark_subdivision(deep, CGAL::parameters::number_of_iterations(1));
    const double worst = largest_distance(deep, limit, old);
    EXPECT_LE(worst, std::pow(lambda, L)) << "L = " << L; // the cube's level-1 edges are 1/2 long
  }
}

// the limit point of a vertex does not change under refinement: exactly, in
// exact arithmetic, at every vertex of the coarser mesh (also those next to
// extraordinary vertices, evaluated on a further refined copy)
template <template <class, class> class M, class Refine>
void expect_invariant_under_refinement(Exact_mesh mesh, const Refine& refine)
{
  const auto evaluator = SD::Limit_evaluator<M<Mesh, double>>();
  refine(mesh);
  Exact_mesh a = mesh;
  evaluator.project_to_limit(a);
  Exact_mesh finer = mesh;
  refine(finer);
  evaluator.project_to_limit(finer);
  for(auto v : mesh.vertices())
    EXPECT_EQ(a.point(v), finer.point(v)) << "vertex " << v.idx();
}

TEST(ProjectToLimit, exactly_invariant_under_refinement)
{
  expect_invariant_under_refinement<Warren_loop>(tetrahedron<Exact_mesh>(),
                                                 [](Exact_mesh& m) { SD::loop_warren_subdivision(m); });
  expect_invariant_under_refinement<SD::Catmull_clark_mask>(cube<Exact_mesh>(),
                                                            [](Exact_mesh& m) { SD::catmull_clark_subdivision(m); });
  // Loop's 1987 beta: rational at 3, 4, 6 (the tetrahedron and its refinements)
  expect_invariant_under_refinement<SD::Loop_mask>(tetrahedron<Exact_mesh>(),
                                                   [](Exact_mesh& m) { SD::loop_subdivision(m); });
  // borders: a quad grid (border vertices with 1 and 2 faces)
  expect_invariant_under_refinement<SD::Catmull_clark_mask>(grid<Exact_mesh>(2, 1, false),
                                                            [](Exact_mesh& m) { SD::catmull_clark_subdivision(m); });
}

// border vertices: the border is the cubic B-spline of the border polygon, so
// the limit of a border vertex is (p_prev + 4 p + p_next) / 6, exactly
TEST(ProjectToLimit, border_vertices_are_on_the_cubic_bspline)
{
  Exact_mesh mesh = grid<Exact_mesh>(3, 2, true);
  // lift the points so that nothing is planar
  for(auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    mesh.point(v) = QK::Point_3(p.x(), p.y(), p.x() * p.y() + Q(v.idx() % 3) / Q(7));
  }
  SD::loop_warren_subdivision(mesh);
  Exact_mesh limit = mesh;
  SD::project_to_limit(limit, Warren_loop<decltype(limit)>());
  int border = 0;
  for(auto v : mesh.vertices()) {
    const SD::Vertex_view<Exact_mesh> view(mesh, v);
    if(!view.on_border())
      continue;
    ++border;
    const auto& prev = mesh.point(mesh.source(view.border_in()));
    const auto& next = mesh.point(mesh.target(view.border_out()));
    const auto& p = mesh.point(v);
    const QK::Point_3 expected((prev.x() + Q(4) * p.x() + next.x()) / Q(6), (prev.y() + Q(4) * p.y() + next.y()) / Q(6),
                               (prev.z() + Q(4) * p.z() + next.z()) / Q(6));
    EXPECT_EQ(limit.point(v), expected) << "vertex " << v.idx();
  }
  EXPECT_EQ(border, 20);
}

// interpolating schemes leave every point where it is (limit mask e0)
TEST(ProjectToLimit, interpolating_schemes_keep_the_points)
{
  Mesh open = grid(4, 3, true);
  for(V v : open.vertices())
    open.point(v) = K::Point_3(open.point(v).x(), open.point(v).y(), std::sin(double(v.idx())));
  Mesh closed = icosahedron();
  SD::loop_subdivision(closed);
  for(const Mesh* input : {&open, &closed}) {
    Mesh a = *input, b = *input;
    SD::butterfly_subdivision(a);
    SD::modified_butterfly_subdivision(b);
    Mesh pa = a, pb = b;
    SD::project_to_limit(pa, SD::Butterfly_mask<decltype(pa)>());
    SD::project_to_limit(pb, SD::Modified_butterfly_mask<decltype(pb)>());
    EXPECT_EQ(points_of(pa), points_of(a));
    EXPECT_EQ(points_of(pb), points_of(b));
  }
  Mesh c = closed;
  SD::interpolating_sqrt3_subdivision(c, CGAL::parameters::number_of_iterations(2));
  Mesh pc = c;
  SD::project_to_limit(pc, SD::Interpolating_sqrt3_mask<decltype(pc)>());
  EXPECT_EQ(points_of(pc), points_of(c));
}

TEST(ProjectToLimit, sqrt3_agrees_with_deep_refinement)
{
  Mesh mesh = icosahedron();
  SD::sqrt3_subdivision(mesh, CGAL::parameters::number_of_iterations(2));
  Mesh limit = mesh;
  SD::project_to_limit(limit, SD::Sqrt3_mask<decltype(limit)>());
  Mesh deep = mesh;
  SD::sqrt3_subdivision(deep, CGAL::parameters::number_of_iterations(8));
  double worst = 0;
  for(V v : mesh.vertices())
    worst = (std::max)(worst, distance(deep.point(v), limit.point(v)));
  // two steps contract by (2 + 2 cos(2 pi / n)) / 9 <= 4/9 (n = 5, 6)
  EXPECT_LE(worst, std::pow(4.0 / 9, 4));
}

// sqrt3 border vertices (analysed over a resting step and a refining step):
// the limit point is exactly invariant under refinement, in both phases of
// the border (after an odd number of steps the next step refines the border,
// and border vertices are evaluated one step later), valences 4, 6, 8 and
// border vertices with 1 to 4 faces
TEST(ProjectToLimit, sqrt3_border_vertices_exactly_invariant)
{
  const auto one_step = [](Exact_mesh& m) { SD::sqrt3_subdivision(m); };
  // the grid as read (its border rests first), after one step (the border is
  // refined first) and after two
  Exact_mesh mesh = grid<Exact_mesh>(2, 2, true);
  for(auto v : mesh.vertices()) // not planar
    mesh.point(v) = QK::Point_3(mesh.point(v).x(), mesh.point(v).y(), Q(int(v.idx() % 4)) / Q(3));
  Exact_mesh a = mesh, b = mesh, c = mesh, d = mesh;
  SD::project_to_limit(a, SD::Sqrt3_mask<decltype(a)>());
  one_step(b);
  SD::project_to_limit(b, SD::Sqrt3_mask<decltype(b)>());
  one_step(c);
  one_step(c);
  SD::project_to_limit(c, SD::Sqrt3_mask<decltype(c)>());
  // three steps: the border is refined next, and most border vertices have
  // the analysed neighbourhood (evaluated one step later all the same)
  one_step(d);
  one_step(d);
  one_step(d);
  ASSERT_TRUE(SD::Sqrt3_split<Exact_mesh>(d).refines_border());
  SD::project_to_limit(d, SD::Sqrt3_mask<decltype(d)>());
  for(auto v : mesh.vertices()) {
    EXPECT_EQ(a.point(v), b.point(v)) << "vertex " << v.idx();
    EXPECT_EQ(a.point(v), c.point(v)) << "vertex " << v.idx();
    EXPECT_EQ(a.point(v), d.point(v)) << "vertex " << v.idx();
  }
  // the interpolating scheme keeps the points, border vertices included
  Mesh open = grid(3, 2, true);
  SD::interpolating_sqrt3_subdivision(open);
  Mesh kept = open;
  SD::project_to_limit(kept, SD::Interpolating_sqrt3_mask<decltype(kept)>());
  EXPECT_EQ(points_of(kept), points_of(open));
}

// and agrees with deep refinement (double), border vertices on the border
// curve: the ternary cubic B-spline, (p_prev + 4 p + p_next) / 6
TEST(ProjectToLimit, sqrt3_border_agrees_with_deep_refinement)
{
  Mesh mesh = grid(3, 2, true);
  for(V v : mesh.vertices())
    mesh.point(v) = K::Point_3(mesh.point(v).x(), mesh.point(v).y(), std::sin(double(v.idx())));
  Mesh limit = mesh;
  SD::project_to_limit(limit, SD::Sqrt3_mask<decltype(limit)>());
  Mesh deep = mesh;
  SD::sqrt3_subdivision(deep, CGAL::parameters::number_of_iterations(8));
  double worst = 0;
  for(V v : mesh.vertices())
    worst = (std::max)(worst, distance(deep.point(v), limit.point(v)));
  // four pairs of steps; the slowest configuration here (k = 4 border
  // faces) contracts by (2 + 2 cos(pi / 4)) / 9 = 0.38 per pair
  EXPECT_LE(worst, 5 * std::pow(0.38, 4));
  for(V v : mesh.vertices()) {
    const SD::Vertex_view<Mesh> view(mesh, v);
    if(!view.on_border())
      continue;
    const auto& p = mesh.point(mesh.source(view.border_in()));
    const auto& q = mesh.point(v);
    const auto& r = mesh.point(mesh.target(view.border_out()));
    const K::Point_3 expected((p.x() + 4 * q.x() + r.x()) / 6, (p.y() + 4 * q.y() + r.y()) / 6,
                              (p.z() + 4 * q.z() + r.z()) / 6);
    EXPECT_LT(distance(limit.point(v), expected), 1e-14) << "vertex " << v.idx();
  }
}

// Doo-Sabin: the limit point of a vertex is that of its vertex face (the face
// the next step makes of the corners at it): the centroid of the corners at
// an interior vertex; at a border vertex the midpoint of its two border
// corners, 3/4 v + 1/8 (u + w) (the quadratic B-spline of the border
// polygon), and v itself at a corner with a single face. Checked against the
// refinement: the vertex face is face F + I + j of the next level (j: its
// rank among the vertices with 3 or more faces), and keeps its index at every
// further level (face faces come first, in face order); its corners converge
// to the predicted point, by 1/2 per level inside and 3/4 at the border (the
// eigenvalue of its interior corners), and at the border the midpoint of its
// two border corners stays exactly on it.
TEST(ProjectToLimit, doo_sabin_vertex_faces_converge_to_the_limit)
{
  using EV = Exact_mesh::Vertex_index;
  for(bool open : {false, true}) {
    Exact_mesh mesh = open ? grid<Exact_mesh>(3, 2, false) : cube<Exact_mesh>();
    if(open) { // a border vertex with 3 faces, an interior vertex of valence 5: one quad split in two triangles
      Exact_mesh other = mesh;
      mesh.clear();
      std::vector<EV> v;
      for(EV u : other.vertices())
        v.push_back(
          mesh.add_vertex(QK::Point_3(other.point(u).x(), other.point(u).y(), Q(int((u.idx() * 7) % 5)) / Q(4))));
      for(auto f : other.faces()) {
        std::vector<EV> corners;
        for(EV u : CGAL::vertices_around_face(other.halfedge(f), other))
          corners.push_back(v[u.idx()]);
        if(f.idx() == 1) { // the quad (1, 2, 6, 5): two triangles
          mesh.add_face(corners[0], corners[1], corners[2]);
          mesh.add_face(corners[0], corners[2], corners[3]);
        } else {
          mesh.add_face(corners);
        }
      }
    }
    Exact_mesh limit = mesh;
    SD::project_to_limit(limit, SD::Doo_sabin_mask<decltype(limit)>());
    std::size_t interior_edges = 0;
    for(auto e : mesh.edges())
      interior_edges += mesh.is_border(e) ? 0 : 1;
    Exact_mesh refined = mesh;
    SD::doo_sabin_subdivision(refined);
    std::size_t j = 0;
    int tracked = 0;
    for(EV v : mesh.vertices()) {
      SCOPED_TRACE("vertex " + std::to_string(v.idx()));
      int faces = 0;
      bool border = false;
      std::vector<EV> border_neighbours;
      for(auto h : CGAL::halfedges_around_target(v, mesh)) {
        if(mesh.is_border(h)) {
          border = true;
          border_neighbours.push_back(mesh.source(h));
        } else {
          ++faces;
        }
        if(mesh.is_border(mesh.opposite(h)))
          border_neighbours.push_back(mesh.source(h));
      }
      const QK::Point_3& predicted = limit.point(v);
      if(border) { // 3/4 v + 1/8 (u + w), or v at a single face
        ASSERT_EQ(border_neighbours.size(), 2u);
        const auto& p = mesh.point(v);
        const auto& u = mesh.point(border_neighbours[0]);
        const auto& w = mesh.point(border_neighbours[1]);
        const Q a = faces == 1 ? Q(1) : Q(3) / Q(4), b = (Q(1) - a) / Q(2);
        EXPECT_EQ(predicted, QK::Point_3(a * p.x() + b * (u.x() + w.x()), a * p.y() + b * (u.y() + w.y()),
                                         a * p.z() + b * (u.z() + w.z())));
      }
      if(faces < 3)
        continue;
      // the vertex face, followed over 6 more levels in double
      const std::size_t index = mesh.number_of_faces() + interior_edges + j++;
      Mesh level;
      for(EV u : refined.vertices())
        level.add_vertex(K::Point_3(CGAL::to_double(refined.point(u).x()), CGAL::to_double(refined.point(u).y()),
                                    CGAL::to_double(refined.point(u).z())));
      for(auto f : refined.faces()) {
        std::vector<V> corners;
        for(EV u : CGAL::vertices_around_face(refined.halfedge(f), refined))
          corners.push_back(V(u.idx()));
        level.add_face(corners);
      }
      const K::Point_3 target(CGAL::to_double(predicted.x()), CGAL::to_double(predicted.y()),
                              CGAL::to_double(predicted.z()));
      const auto spread = [&](const Mesh& m) {
        double d = 0;
        for(V u : CGAL::vertices_around_face(m.halfedge(Mesh::Face_index(static_cast<Mesh::size_type>(index))), m))
          d = (std::max)(d, distance(m.point(u), target));
        return d;
      };
      const double first = spread(level);
      ASSERT_GT(first, 0.0);
      EXPECT_EQ(
        CGAL::vertices_around_face(level.halfedge(Mesh::Face_index(static_cast<Mesh::size_type>(index))), level).size(),
        static_cast<std::size_t>(faces));
      SD::doo_sabin_subdivision(level, CGAL::parameters::number_of_iterations(6));
      const double last = spread(level);
      EXPECT_LE(last, first * (border ? 0.25 : 0.03)); // 0.75^6 = 0.18 (2/3 for a triangle), 0.5^6 = 0.016
      ++tracked;
    }
    EXPECT_EQ(tracked, open ? 3 : 8); // the open mesh: 2 interior vertices, a border vertex with 3 faces
  }
}

// The evaluator's Doo-Sabin border limit points are the limit masks of the
// analysis at the border faces (k >= 2: 1/2 on the two border corners of the
// face made of the corners at the vertex, labels 0 and m - 1; k = 1: the kept
// corner, label 3 of the corner face), checked exactly when computed
TEST(ProjectToLimit, doo_sabin_border_masks_are_the_border_face_analysis)
{
  const SD::Limit_evaluator<SD::Doo_sabin_mask<Mesh>> evaluator;
  for(int k = 1; k <= 8; ++k) {
    SCOPED_TRACE("k = " + std::to_string(k));
    const SD::Limit_masks& masks = evaluator.masks(k, true);
    EXPECT_TRUE(masks.c1);
    EXPECT_FALSE(masks.tangents);
    const std::size_t last = static_cast<std::size_t>(k >= 3 ? k - 1 : 3);
    ASSERT_EQ(masks.limit.size(), k == 1 ? 9u : k == 2 ? 12u : static_cast<std::size_t>(4 * k - 2));
    for(std::size_t i = 0; i < masks.limit.size(); ++i)
      EXPECT_EQ(masks.limit[i], k == 1 ? Q(i == 3 ? 1 : 0) : Q(i == 0 || i == last ? 1 : 0) / Q(2));
  }
}

// ------------------------------------------------------------------ normals

// planar meshes: every normal is exactly +z (faces counter-clockwise seen from
// +z), border vertices included, for every scheme
TEST(LimitNormals, planar_meshes_have_the_plane_normal)
{
  Mesh triangles = grid(5, 4, true);
  Mesh quads = grid(4, 3, false);
  SD::loop_subdivision(triangles);
  SD::catmull_clark_subdivision(quads);
  const auto expect_plus_z = [](const std::vector<K::Vector_3>& normals, const std::string& scheme) {
    for(std::size_t i = 0; i < normals.size(); ++i)
      EXPECT_EQ(normals[i], K::Vector_3(0, 0, 1)) << scheme << " vertex " << i;
  };
  expect_plus_z(limit_normals_of<SD::Loop_mask>(triangles), "Loop");
  expect_plus_z(limit_normals_of<SD::Catmull_clark_mask>(quads), "Catmull-Clark");
  expect_plus_z(limit_normals_of<SD::Butterfly_mask>(triangles), "butterfly");
  expect_plus_z(limit_normals_of<SD::Modified_butterfly_mask>(triangles), "modified butterfly");
  expect_plus_z(limit_normals_of<SD::Linear_triangle_mask>(triangles), "linear");
  // sqrt3 border vertices (tangent masks of the border analysis where C1), Doo-Sabin (face normals)
  Mesh coarse = grid(4, 3, true);
  expect_plus_z(limit_normals_of<SD::Sqrt3_mask>(coarse), "sqrt3");
  expect_plus_z(limit_normals_of<SD::Interpolating_sqrt3_mask>(coarse), "interpolating sqrt3");
  expect_plus_z(limit_normals_of<SD::Doo_sabin_mask>(quads), "Doo-Sabin");
}

// a subdivided icosahedron is nearly a sphere: the limit normal is close to
// the direction of the limit point; and the tangent plane is that of the
// deeply refined, projected mesh (finite differences)
TEST(LimitNormals, sphere_like_mesh)
{
  Mesh mesh = icosahedron();
  SD::loop_subdivision(mesh, CGAL::parameters::number_of_iterations(2));
  Mesh limit = mesh;
  SD::project_to_limit(limit, SD::Loop_mask<decltype(limit)>());
  const std::vector<K::Vector_3> normals = limit_normals_of<SD::Loop_mask>(mesh);
  for(V v : mesh.vertices()) {
    const K::Vector_3 radial = limit.point(v) - CGAL::ORIGIN;
    EXPECT_NEAR(normals[v.idx()].squared_length(), 1.0, 1e-14);
    EXPECT_GT(normals[v.idx()] * radial / std::sqrt(radial.squared_length()), 0.99) << v.idx();
  }
  // refinement does not change the tangent plane
  Mesh finer = mesh;
  SD::loop_subdivision(finer);
  const std::vector<K::Vector_3> finer_normals = limit_normals_of<SD::Loop_mask>(finer);
  for(V v : mesh.vertices())
    EXPECT_NEAR(normals[v.idx()] * finer_normals[v.idx()], 1.0, 1e-12) << v.idx();
  // finite differences: L more levels, projected to the limit; the normal of
  // the limit points around the old vertex, area-weighted
  Mesh deep = mesh;
  SD::loop_subdivision(deep, CGAL::parameters::number_of_iterations(4));
  SD::project_to_limit(deep, SD::Loop_mask<decltype(deep)>());
  double worst = 0;
  for(V v : mesh.vertices()) {
    K::Vector_3 sum(0, 0, 0);
    for(auto f : CGAL::faces_around_target(deep.halfedge(v), deep)) {
      const auto h = deep.halfedge(f);
      sum = sum + CGAL::cross_product(deep.point(deep.target(h)) - deep.point(deep.source(h)),
                                      deep.point(deep.target(deep.next(h))) - deep.point(deep.source(h)));
    }
    sum = sum / std::sqrt(sum.squared_length());
    worst = (std::max)(worst, 1 - sum * normals[v.idx()]);
  }
  EXPECT_LT(worst, 1e-3);
}

TEST(LimitNormals, catmull_clark_cube_normals_point_outward)
{
  Mesh mesh = cube();
  SD::catmull_clark_subdivision(mesh, CGAL::parameters::number_of_iterations(2));
  Mesh limit = mesh;
  SD::project_to_limit(limit, SD::Catmull_clark_mask<decltype(limit)>());
  const std::vector<K::Vector_3> normals = limit_normals_of<SD::Catmull_clark_mask>(mesh);
  const K::Point_3 centre(0.5, 0.5, 0.5);
  for(V v : mesh.vertices()) {
    const K::Vector_3 radial = limit.point(v) - centre;
    EXPECT_GT(normals[v.idx()] * radial / std::sqrt(radial.squared_length()), 0.5) << v.idx();
  }
  // by symmetry, the normal at a corner of the cube is along its diagonal
  for(Mesh::size_type i = 0; i < 8; ++i) {
    const K::Vector_3 radial = limit.point(V(i)) - centre;
    EXPECT_NEAR(normals[i] * radial / std::sqrt(radial.squared_length()), 1.0, 1e-12);
  }
}

// a flat-folded neighbourhood: every neighbour of v on one line through v, so
// both tangent vectors are multiples of that line's direction; the normal is
// the documented fallback (area-weighted normal of the faces at the limit points)
TEST(LimitNormals, parallel_tangents_fall_back_to_face_normals)
{
  Mesh mesh = grid(6, 6, true);
  SD::loop_subdivision(mesh); // every vertex of the interior regular enough
  V centre;
  for(V v : mesh.vertices())
    if(mesh.point(v) == K::Point_3(3, 3, 0))
      centre = v;
  const K::Vector_3 d(1, 2, 3);
  for(V u : CGAL::vertices_around_target(mesh.halfedge(centre), mesh)) {
    const K::Vector_3 offset = mesh.point(u) - mesh.point(centre);
    mesh.point(u) = mesh.point(centre) + d * (offset.x() + 0.3 * offset.y());
  }
  const auto evaluator = SD::Limit_evaluator<SD::Loop_mask<Mesh, double>>();
  const auto results =
    evaluator.evaluate(mesh, mesh.points(), static_cast<const SD::internal::No_heights*>(nullptr), "test");
  const auto& r = results[centre.idx()];
  ASSERT_TRUE(r.tangents);
  const auto n = SD::internal::cross(r.tangent[0], r.tangent[1]);
  EXPECT_LE(SD::internal::norm(n), 1e-10 * SD::internal::norm(r.tangent[0]) * SD::internal::norm(r.tangent[1]));
  const std::vector<K::Vector_3> normals = limit_normals_of<SD::Loop_mask>(mesh);
  const K::Vector_3 normal = normals[centre.idx()];
  EXPECT_TRUE(std::isfinite(normal.x()) && std::isfinite(normal.y()) && std::isfinite(normal.z()));
  EXPECT_NEAR(normal.squared_length(), 1.0, 1e-12);
  // the fallback: faces around the centre with their corners at the limit points
  K::Vector_3 sum(0, 0, 0);
  for(auto f : CGAL::faces_around_target(mesh.halfedge(centre), mesh)) {
    const auto h = mesh.halfedge(f);
    const auto& a = results[mesh.source(h).idx()].limit;
    const auto& b = results[mesh.target(h).idx()].limit;
    const auto& c = results[mesh.target(mesh.next(h)).idx()].limit;
    sum = sum + CGAL::cross_product(b - a, c - a);
  }
  sum = sum / std::sqrt(sum.squared_length());
  EXPECT_NEAR(normal * sum, 1.0, 1e-12);
  // all control points on one line: no face has an area, the normal is null, not NaN
  Mesh line = grid(2, 2, true);
  for(V v : line.vertices())
    line.point(v) = K::Point_3(line.point(v).x() + line.point(v).y(), 0, 0);
  for(const K::Vector_3& m : limit_normals_of<SD::Linear_triangle_mask>(line))
    EXPECT_EQ(m, K::Vector_3(0, 0, 0));
}

// A border vertex of one face that the mask keeps (Border_corners::sharp)
// is a corner: its normal is its face's (the tangents along its two edges,
// as at a tagged corner and in OpenSubdiv Far), under Loop and
// Catmull-Clark, on a bumpy grid; the analysis finds no tangent plane there,
// and the fallback (the face with its corners at their limits) is another
// direction. With smooth corners the fallback stays.
TEST(LimitNormals, kept_corners_of_one_face_have_their_face_normal)
{
  const auto bumpy = [](int i, int j) { return K::Point_3(i + 0.1 * j * j, j, 0.3 * std::sin(i + 2.0 * j)); };
  const auto expect_face_normals = [](const Mesh& mesh, const auto& mask, bool kept, int expected_corners) {
    Mesh copy = mesh;
    const auto normals = copy.add_property_map<V, K::Vector_3>("v:n").first;
    SD::limit_normals(copy, mask, normals);
    int corners = 0;
    for(V v : copy.vertices()) {
      if(!(copy.is_border(v) && copy.degree(v) == 2))
        continue;
      ++corners;
      const auto out = copy.opposite(copy.halfedge(v)); // from v, in its face (halfedge(v) is the border's)
      const K::Vector_3 n =
        CGAL::normal(copy.point(v), copy.point(copy.target(out)), copy.point(copy.source(copy.prev(out))));
      const double turn = std::sqrt((normals[v] - n / std::sqrt(n.squared_length())).squared_length());
      if(kept)
        EXPECT_LT(turn, 1e-15);
      else
        EXPECT_GT(turn, 1e-3);
    }
    EXPECT_EQ(corners, expected_corners);
  };
  const Mesh triangles = testing_utils::grid<Mesh>(5, 4, bumpy, true);
  expect_face_normals(triangles, SD::Loop_mask<Mesh>(SD::Border_corners::sharp), true, 2);
  expect_face_normals(triangles, SD::Loop_mask<Mesh>(SD::Border_corners::smooth), false, 2);
  const Mesh quads = testing_utils::grid<Mesh>(5, 4, bumpy, false);
  expect_face_normals(quads, SD::Catmull_clark_mask<Mesh>(SD::Border_corners::sharp), true, 4);
  expect_face_normals(quads, SD::Catmull_clark_mask<Mesh>(SD::Border_corners::smooth), false, 4);
}

// ------------------------------------------------------------------ displacement

TEST(Displace, zero_height_is_the_limit_surface)
{
  Mesh mesh = icosahedron();
  Mesh displaced = mesh, limit = mesh;
  SD::Limit_evaluator<SD::Loop_mask<Mesh>>().displace(
    displaced, [](const K::Point_3&) { return 0.0; }, CGAL::parameters::number_of_iterations(2));
  SD::loop_subdivision(limit, CGAL::parameters::number_of_iterations(2));
  SD::project_to_limit(limit, SD::Loop_mask<decltype(limit)>());
  EXPECT_EQ(points_of(displaced), points_of(limit));
}

TEST(Displace, constant_height_moves_along_the_unit_normal)
{
  Mesh mesh = icosahedron();
  SD::loop_subdivision(mesh);
  Mesh limit = mesh;
  auto normals = limit.add_property_map<V, K::Vector_3>("v:normal", K::Vector_3(0, 0, 0)).first;
  SD::project_to_limit(limit, SD::Loop_mask<decltype(limit)>(), CGAL::parameters::vertex_normal_map(normals));
  Mesh displaced = mesh;
  auto heights = displaced.add_property_map<V, double>("v:height", 0.25).first;
  SD::Limit_evaluator<SD::Loop_mask<Mesh>>().displace(displaced, heights);
  for(V v : mesh.vertices()) {
    EXPECT_NEAR(distance(displaced.point(v), limit.point(v)), 0.25, 1e-14);
    const K::Vector_3 move = displaced.point(v) - limit.point(v);
    EXPECT_NEAR(move * normals[v] / 0.25, 1.0, 1e-12);
    // outward: the sphere grows
    EXPECT_GT(std::sqrt((displaced.point(v) - CGAL::ORIGIN).squared_length()),
              std::sqrt((limit.point(v) - CGAL::ORIGIN).squared_length()) + 0.2);
  }
}

// heights carried through the levels with the geometry: a linear function of
// the coarse control points stays that linear function of the limit points, exactly
TEST(Displace, carried_heights_reproduce_a_linear_function)
{
  Exact_mesh mesh = tetrahedron<Exact_mesh>();
  const auto linear = [](const QK::Point_3& p) -> Q {
    return Q(2) * p.x() - Q(3) * p.y() + p.z() / Q(5) + Q(1) / Q(7);
  };
  auto heights = mesh.add_property_map<Exact_mesh::Vertex_index, Q>("v:height", Q(0)).first;
  for(auto v : mesh.vertices())
    heights[v] = linear(mesh.point(v));
  const auto evaluator = SD::Limit_evaluator<Warren_loop<Mesh, double>>();
  SD::Carried_data<Exact_mesh> data;
  data.vertex_map(heights);
  SD::subdivide(mesh, Warren_loop<Exact_mesh, Q>(), SD::parameters::number_of_iterations(2).carried_data(data));
  for(auto v : mesh.vertices())
    EXPECT_EQ(heights[v], linear(mesh.point(v)));
  const auto results = evaluator.evaluate(mesh, mesh.points(), &heights, "test");
  for(const auto& r : results)
    EXPECT_EQ(r.height, linear(r.limit));
  // displace does the same: the displacement of every vertex is that height along the normal
  Exact_mesh coarse = tetrahedron<Exact_mesh>();
  auto coarse_heights = coarse.add_property_map<Exact_mesh::Vertex_index, Q>("v:height", Q(0)).first;
  for(auto v : coarse.vertices())
    coarse_heights[v] = linear(coarse.point(v));
  evaluator.displace(coarse, coarse_heights, CGAL::parameters::number_of_iterations(2));
  ASSERT_EQ(coarse.number_of_vertices(), results.size());
  for(auto v : coarse.vertices()) {
    const double moved = std::sqrt(CGAL::to_double(CGAL::squared_distance(coarse.point(v), results[v.idx()].limit)));
    EXPECT_NEAR(moved, std::abs(CGAL::to_double(results[v.idx()].height)), 1e-12);
  }
}

TEST(Displace, callable_height_is_evaluated_at_the_limit_point)
{
  Mesh mesh = cube();
  Mesh displaced = mesh;
  auto normals = displaced.add_property_map<V, K::Vector_3>("v:normal", K::Vector_3(0, 0, 0)).first;
  SD::Limit_evaluator<SD::Catmull_clark_mask<Mesh>>().displace(
    displaced, [](const K::Point_3& p) { return p.z(); },
    CGAL::parameters::number_of_iterations(2).vertex_normal_map(normals));
  Mesh limit = mesh;
  SD::catmull_clark_subdivision(limit, CGAL::parameters::number_of_iterations(2));
  SD::project_to_limit(limit, SD::Catmull_clark_mask<decltype(limit)>());
  for(V v : limit.vertices()) {
    const K::Vector_3 expected = normals[v] * limit.point(v).z();
    EXPECT_NEAR(std::sqrt((displaced.point(v) - limit.point(v) - expected).squared_length()), 0.0, 1e-14);
  }
}

// Epeck: the same exact limit points as Simple_cartesian<Exact_rational>, normals unit up to rounding
TEST(ProjectToLimit, epeck)
{
  using EK = CGAL::Epeck;
  using Epeck_mesh = CGAL::Surface_mesh<EK::Point_3>;
  Epeck_mesh mesh = tetrahedron<Epeck_mesh>();
  Exact_mesh reference = tetrahedron<Exact_mesh>();
  SD::loop_subdivision(mesh);
  SD::loop_subdivision(reference);
  auto normals = mesh.add_property_map<Epeck_mesh::Vertex_index, EK::Vector_3>("v:normal").first;
  SD::project_to_limit(mesh, SD::Loop_mask<decltype(mesh)>(), CGAL::parameters::vertex_normal_map(normals));
  SD::project_to_limit(reference, SD::Loop_mask<decltype(reference)>());
  for(auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    const auto& q = reference.point(Exact_mesh::Vertex_index(v.idx()));
    EXPECT_TRUE(CGAL::exact(p.x()) == q.x() && CGAL::exact(p.y()) == q.y() && CGAL::exact(p.z()) == q.z());
    EXPECT_NEAR(CGAL::to_double(normals[v].squared_length()), 1.0, 1e-12);
  }
}

// ------------------------------------------------------------------ refusals

TEST(LimitErrors, refusals_name_the_problem)
{
  Mesh quads = cube();
  EXPECT_NE(testing_utils::bad_input_message([&] {
              SD::project_to_limit(quads, SD::Loop_mask<decltype(quads)>());
            }).find("needs a mesh whose faces all have 3 vertices"),
            std::string::npos);
  // Doo-Sabin at an interior vertex of valence 2 (two quads glued along their border): no vertex face
  Mesh pillow =
    testing_utils::mesh_of<Mesh>({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}, {3, 2, 1, 0}});
  const std::string dual =
    testing_utils::bad_input_message([&] { SD::project_to_limit(pillow, SD::Doo_sabin_mask<decltype(pillow)>()); });
  EXPECT_NE(dual.find("project_to_limit (Doo-Sabin): vertex 0: "), std::string::npos) << dual;
  EXPECT_EQ(points_of(pillow)[0], K::Point_3(0, 0, 0)); // unchanged
  // Loop at an interior vertex of valence 2 (two triangles sharing all three edges): no analysed neighbourhood
  Mesh triangles = testing_utils::mesh_of<Mesh>({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {2, 1, 0}});
  ASSERT_EQ(num_faces(triangles), 2u);
  const std::string loop =
    testing_utils::bad_input_message([&] { SD::project_to_limit(triangles, SD::Loop_mask<decltype(triangles)>()); });
  EXPECT_NE(loop.find("vertex 0: an interior vertex of valence 2: the eigen-analysis of triangle schemes covers "
                      "valence 3 or more"),
            std::string::npos)
    << loop;
  EXPECT_EQ(points_of(triangles)[1], K::Point_3(1, 0, 0)); // unchanged
}

} // namespace
