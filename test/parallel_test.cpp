// The fast paths: the same results with any number of threads (bit for bit),
// the same results as the generic paths, and stencil tables that agree with
// refinement.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Subdiv/stencils/make_stencil_table.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <gtest/gtest.h>

#include "mesh_builders.h"
#include "threads_test_utils.h"

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <random>
#include <vector>

namespace S = CGAL::Subdiv;
using K = CGAL::Simple_cartesian<double>;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using V = Mesh::Vertex_index;

namespace {

// an nu x nv torus grid of quads, or of triangles along random diagonals with
// some random flips (valences 3 to 9), with every `hole`-th face removed
Mesh torus(int nu, int nv, bool triangles, int hole = 0)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  const double pi = 3.14159265358979323846;
  std::vector<Point> points;
  for(int j = 0; j < nv; ++j)
    for(int i = 0; i < nu; ++i) {
      const double u = 2 * pi * (i + jitter(random)) / nu, w = 2 * pi * (j + jitter(random)) / nv;
      points.emplace_back((1 + 0.4 * std::cos(w)) * std::cos(u), (1 + 0.4 * std::cos(w)) * std::sin(u),
                          0.4 * std::sin(w));
    }
  const auto id = [nu, nv](int i, int j) { return (j % nv) * nu + (i % nu); };
  std::bernoulli_distribution coin(0.5);
  Mesh mesh = testing_utils::mesh_of<Mesh>(
    points, testing_utils::lattice_faces(nu, nv, id, triangles, [&](int, int) { return coin(random); }));
  if(triangles) {
    std::bernoulli_distribution flip(0.3);
    std::vector<Mesh::Edge_index> edges(mesh.edges().begin(), mesh.edges().end());
    for(const auto e : edges) {
      const auto h = mesh.halfedge(e), o = mesh.opposite(h);
      const V c = mesh.target(mesh.next(h)), d = mesh.target(mesh.next(o));
      if(!flip(random) || c == d || CGAL::halfedge(c, d, mesh).second || mesh.degree(mesh.source(h)) <= 3 ||
         mesh.degree(mesh.target(h)) <= 3 || mesh.degree(c) >= 9 || mesh.degree(d) >= 9)
        continue;
      CGAL::Euler::flip_edge(h, mesh);
    }
  }
  if(hole > 0) { // holes of one face, apart from one another (the mesh stays manifold)
    std::vector<Mesh::Face_index> faces(mesh.faces().begin(), mesh.faces().end());
    for(std::size_t k = 0; k < faces.size(); k += static_cast<std::size_t>(hole)) {
      bool apart = true;
      for(const V u : CGAL::vertices_around_face(mesh.halfedge(faces[k]), mesh))
        apart = apart && !mesh.is_border(u);
      if(apart)
        CGAL::Euler::remove_face(mesh.halfedge(faces[k]), mesh);
    }
  }
  mesh.collect_garbage();
  return mesh;
}

// the connectivity only (targets, next, prev, faces of halfedges, halfedges
// of vertices and faces)
std::vector<std::uint64_t> connectivity(const Mesh& mesh)
{
  std::vector<std::uint64_t> out;
  for(const V v : mesh.vertices())
    out.push_back(mesh.halfedge(v));
  for(const auto h : mesh.halfedges()) {
    out.push_back(mesh.target(h));
    out.push_back(mesh.next(h));
    out.push_back(mesh.prev(h));
    out.push_back(mesh.face(h));
  }
  for(const auto f : mesh.faces())
    out.push_back(mesh.halfedge(f));
  return out;
}

// everything of a Surface_mesh, bit for bit: the points, then the connectivity
std::vector<std::uint64_t> fingerprint(const Mesh& mesh)
{
  std::vector<std::uint64_t> out;
  const auto bits = [](double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  };
  for(const V v : mesh.vertices()) {
    out.push_back(bits(mesh.point(v).x()));
    out.push_back(bits(mesh.point(v).y()));
    out.push_back(bits(mesh.point(v).z()));
  }
  const std::vector<std::uint64_t> links = connectivity(mesh);
  out.insert(out.end(), links.begin(), links.end());
  return out;
}

template <class F>
void expect_same_with_any_thread_count(const Mesh& input, const F& refine, int levels)
{
  Mesh sequential = input;
  refine(sequential, S::parameters::number_of_iterations(levels).threads(1));
  for(const int threads : {2, 0}) {
    Mesh parallel = input;
    refine(parallel, S::parameters::number_of_iterations(levels).threads(threads));
    ASSERT_TRUE(CGAL::is_valid_polygon_mesh(parallel));
    EXPECT_EQ(fingerprint(parallel), fingerprint(sequential)) << threads << " threads, " << levels << " levels";
  }
}

const auto loop = [](Mesh& m, const auto& np) { S::loop_subdivision(m, np); };
const auto catmull_clark = [](Mesh& m, const auto& np) { S::catmull_clark_subdivision(m, np); };

} // namespace

TEST(Parallel, loop_is_the_same_with_any_number_of_threads)
{
  SUBDIV_REQUIRE_THREADS();
  for(const int hole : {0, 13})
    for(int levels = 1; levels <= 3; ++levels)
      expect_same_with_any_thread_count(torus(40, 30, true, hole), loop, levels);
}

TEST(Parallel, catmull_clark_is_the_same_with_any_number_of_threads)
{
  SUBDIV_REQUIRE_THREADS();
  for(const int hole : {0, 17}) {
    for(int levels = 1; levels <= 3; ++levels)
      expect_same_with_any_thread_count(torus(40, 30, false, hole), catmull_clark, levels);
    // triangles and quads mixed after one level: faces of every size on the first
    expect_same_with_any_thread_count(torus(40, 30, true, hole), catmull_clark, 2);
  }
}

TEST(Parallel, other_schemes_are_the_same_with_any_number_of_threads)
{
  SUBDIV_REQUIRE_THREADS();
  const Mesh triangles = torus(30, 30, true, 11), quads = torus(30, 30, false, 11);
  expect_same_with_any_thread_count(
    triangles, [](Mesh& m, const auto& np) { S::sqrt3_subdivision(m, np); }, 3);
  expect_same_with_any_thread_count(
    triangles, [](Mesh& m, const auto& np) { S::modified_butterfly_subdivision(m, np); }, 2);
  expect_same_with_any_thread_count(
    quads, [](Mesh& m, const auto& np) { S::doo_sabin_subdivision(m, np); }, 2);
}

TEST(Parallel, edge_splits_beside_the_resize_are_the_same_with_any_number_of_threads)
{
  SUBDIV_REQUIRE_THREADS();
#if defined(NDEBUG) && !defined(_GLIBCXX_ASSERTIONS)
  // with threads, the resize runs beside the snapshot and the masks here
  EXPECT_TRUE(S::internal::resize_beside_reads);
#endif
  const auto butterfly = [](Mesh& m, const auto& np) { S::butterfly_subdivision(m, np); };
  const auto linear = [](Mesh& m, const auto& np) { S::linear_triangle_subdivision(m, np); };
  const auto linear_quad = [](Mesh& m, const auto& np) { S::linear_quad_subdivision(m, np); };
  for(const int hole : {0, 5}) {
    const Mesh triangles = torus(24, 20, true, hole), quads = torus(24, 20, false, hole);
    for(int levels = 1; levels <= 3; ++levels) {
      expect_same_with_any_thread_count(triangles, butterfly, levels);
      expect_same_with_any_thread_count(triangles, linear, levels);
      expect_same_with_any_thread_count(quads, catmull_clark, levels);
      expect_same_with_any_thread_count(quads, linear_quad, levels);
    }
  }
  // one level, with room reserved beforehand (the arrays do not move) and
  // with none (a copy: the room is made first, then the resize runs beside)
  for(const bool triangles : {true, false}) {
    const Mesh input = torus(30, 20, triangles, 7);
    Mesh sequential = input;
    const auto refine = [&](Mesh& m, const auto& p) {
      if(triangles)
        S::loop_subdivision(m, p);
      else
        S::catmull_clark_subdivision(m, p);
    };
    refine(sequential, S::parameters::number_of_iterations(1).threads(1));
    for(const bool reserved : {false, true}) {
      Mesh parallel = input;
      if(reserved)
        parallel.reserve(100000, 300000, 200000);
      refine(parallel, S::parameters::number_of_iterations(1).threads(2));
      ASSERT_TRUE(CGAL::is_valid_polygon_mesh(parallel));
      EXPECT_EQ(fingerprint(parallel), fingerprint(sequential)) << (reserved ? "reserved" : "not reserved");
    }
  }
}

TEST(Parallel, edge_splits_wired_from_the_snapshot_equal_the_soup)
{
  // with carried data, the levels go through the face soup and the generic
  // rebuild; without, the edge splits wire the mesh from a snapshot of the
  // old faces: every link must be the same (the points differ in the last
  // bits: the carried path sums merged stencils)
  const auto check = [](const Mesh& input, const auto& refine, int levels) {
    Mesh soup = input, snapshot = input;
    auto label = soup.add_property_map<Mesh::Face_index, int>("f:label", 0).first;
    S::Carried_data<Mesh> data;
    data.face_map(label);
    refine(soup, S::parameters::number_of_iterations(levels).carried_data(data));
    for(const int threads : {1, 2}) {
      Mesh fast = snapshot;
      refine(fast, S::parameters::number_of_iterations(levels).threads(threads));
      ASSERT_TRUE(CGAL::is_valid_polygon_mesh(fast));
      EXPECT_EQ(connectivity(fast), connectivity(soup)) << levels << " levels, " << threads << " threads";
    }
  };
  for(const int hole : {0, 7}) {
    const Mesh triangles = torus(24, 20, true, hole), quads = torus(24, 20, false, hole);
    for(int levels = 1; levels <= 3; ++levels) {
      check(triangles, loop, levels);
      check(quads, catmull_clark, levels);
      check(triangles, catmull_clark, levels); // triangles, then quads
    }
  }
}

TEST(Parallel, fast_path_equals_the_generic_path)
{
  // a point map that is not the mesh's own goes through the generic point
  // path (one vector of points, written with put()); the mesh's own map
  // through the flat accumulator: the same bits
  for(const bool triangles : {true, false}) {
    const Mesh input = torus(30, 20, triangles, 7);
    Mesh fast = input, generic = input;
    using Map = std::map<V, Point>;
    Map points;
    for(const V v : generic.vertices())
      points[v] = generic.point(v);
    boost::associative_property_map<Map> vpm(points);
    const auto np = CGAL::parameters::number_of_iterations(2);
    if(triangles) {
      S::loop_subdivision(fast, np);
      S::loop_subdivision(generic, np.vertex_point_map(vpm));
    } else {
      S::catmull_clark_subdivision(fast, np);
      S::catmull_clark_subdivision(generic, np.vertex_point_map(vpm));
    }
    ASSERT_EQ(fast.number_of_vertices(), generic.number_of_vertices());
    for(const V v : fast.vertices())
      EXPECT_EQ(fast.point(v), points[v]) << "vertex " << v;
  }
}

TEST(Parallel, stencil_tables_are_the_same_with_any_number_of_threads)
{
  SUBDIV_REQUIRE_THREADS();
  const auto same = [](const S::Stencil_table<double>& a, const S::Stencil_table<double>& b) {
    ASSERT_EQ(a.number_of_stencils(), b.number_of_stencils());
    ASSERT_EQ(a.number_of_terms(), b.number_of_terms());
    for(std::size_t i = 0; i < a.number_of_stencils(); ++i)
      ASSERT_EQ(a.stencil_end(i), b.stencil_end(i));
    for(std::size_t t = 0; t < a.number_of_terms(); ++t) {
      ASSERT_EQ(a.source(t), b.source(t));
      ASSERT_EQ(a.weight(t), b.weight(t));
    }
  };
  const Mesh triangles = torus(30, 20, true, 9), quads = torus(30, 20, false, 9);
  for(int levels = 1; levels <= 3; ++levels) {
    same(
      S::make_stencil_table(triangles, S::Loop_mask<Mesh>(), S::parameters::number_of_iterations(levels).threads(1)),
      S::make_stencil_table(triangles, S::Loop_mask<Mesh>(), S::parameters::number_of_iterations(levels).threads(2)));
    same(S::make_stencil_table(quads, S::Catmull_clark_mask<Mesh>(),
                               S::parameters::number_of_iterations(levels).threads(1)),
         S::make_stencil_table(quads, S::Catmull_clark_mask<Mesh>(),
                               S::parameters::number_of_iterations(levels).threads(0)));
    // sqrt3 with a border: new vertices are not visited in order (two passes)
    same(
      S::make_stencil_table(triangles, S::Sqrt3_mask<Mesh>(), S::parameters::number_of_iterations(levels).threads(1)),
      S::make_stencil_table(triangles, S::Sqrt3_mask<Mesh>(), S::parameters::number_of_iterations(levels).threads(2)));
  }
}

TEST(Parallel, composed_tables_give_the_refined_points)
{
  // double weights: the table's sums are associated differently from the
  // level-by-level refinement, so the points agree to rounding
  for(const bool triangles : {true, false}) {
    const Mesh input = torus(30, 20, triangles, 9);
    Mesh refined = input;
    S::Stencil_table<double> table;
    if(triangles) {
      table = S::make_stencil_table(input, S::Loop_mask<Mesh>(), S::parameters::number_of_iterations(3));
      S::loop_subdivision(refined, CGAL::parameters::number_of_iterations(3));
    } else {
      table = S::make_stencil_table(input, S::Catmull_clark_mask<Mesh>(), S::parameters::number_of_iterations(3));
      S::catmull_clark_subdivision(refined, CGAL::parameters::number_of_iterations(3));
    }
    std::vector<Point> coarse(input.points().begin(), input.points().end()), fine;
    table.apply(coarse, fine, S::parameters::threads(2));
    ASSERT_EQ(fine.size(), refined.number_of_vertices());
    double worst = 0;
    for(const V v : refined.vertices())
      worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(fine[v.idx()], refined.point(v))));
    EXPECT_LT(worst, 1e-14);
  }
}

TEST(Parallel, flat_apply_equals_the_generic_apply)
{
  const Mesh input = torus(30, 20, false, 9);
  const auto table =
    S::make_stencil_table(input, S::Catmull_clark_mask<Mesh>(), S::parameters::number_of_iterations(2));
  const std::vector<Point> coarse(input.points().begin(), input.points().end());
  std::vector<Point> fine;
  table.apply(coarse, fine);
  // positions as three doubles per vertex, and as std::array: the same bits
  std::vector<double> flat_in, flat_out(3 * table.number_of_stencils());
  std::vector<std::array<double, 3>> array_in, array_out;
  for(const Point& p : coarse) {
    flat_in.insert(flat_in.end(), {p.x(), p.y(), p.z()});
    array_in.push_back({p.x(), p.y(), p.z()});
  }
  for(const int threads : {1, 2}) {
    table.apply(flat_in.data(), flat_out.data(), 3, S::parameters::threads(threads));
    table.apply(array_in, array_out, S::parameters::threads(threads));
    for(std::size_t i = 0; i < fine.size(); ++i) {
      ASSERT_EQ(flat_out[3 * i], fine[i].x());
      ASSERT_EQ(flat_out[3 * i + 1], fine[i].y());
      ASSERT_EQ(flat_out[3 * i + 2], fine[i].z());
      ASSERT_EQ(array_out[i][0], fine[i].x());
      ASSERT_EQ(array_out[i][2], fine[i].z());
    }
  }
  // any other dimension: each channel is the scalar apply of that channel
  for(const std::size_t dimension : {1, 2, 4, 5}) {
    std::vector<double> in(dimension * coarse.size()), out(dimension * table.number_of_stencils());
    for(std::size_t k = 0; k < in.size(); ++k)
      in[k] = std::sin(0.37 * static_cast<double>(k));
    table.apply(in.data(), out.data(), dimension, S::parameters::threads(2));
    for(std::size_t d = 0; d < dimension; ++d) {
      std::vector<double> channel, channel_out;
      for(std::size_t s = 0; s < coarse.size(); ++s)
        channel.push_back(in[s * dimension + d]);
      table.apply(channel, channel_out);
      for(std::size_t i = 0; i < channel_out.size(); ++i)
        ASSERT_EQ(out[i * dimension + d], channel_out[i]) << "dimension " << dimension;
    }
  }
  // the parallel generic apply gives the same points
  std::vector<Point> fine_parallel;
  table.apply(coarse, fine_parallel, S::parameters::threads(2));
  EXPECT_EQ(fine_parallel, fine);
}
