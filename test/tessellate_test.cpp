// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
// tessellate(): the counts of the grids, a closed and valid output on closed
// meshes (no point made twice), every point the evaluator's at its parameter,
// the points on mesh vertices the limit masks', normals, an open grid, edge
// rates, and bad rates refused with the output unchanged.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/limit/Limit_surface.h>
#include <CGAL/Subdiv/limit/project_to_limit.h>
#include <CGAL/Subdiv/limit/tessellate.h>
#include <CGAL/Subdiv/masks/Loop_mask.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include "mesh_builders.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

namespace S = CGAL::Subdiv;
using K = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Out = CGAL::Surface_mesh<S::Limit_sample::Point>;
using CC = S::Limit_surface<Mesh>;
using Loop = S::Limit_surface<Mesh, S::Loop_mask<Mesh>>;

namespace {

double diagonal(const Out& out)
{
  const CGAL::Bbox_3 b = CGAL::bbox_3(out.points().begin(), out.points().end());
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

// valid, closed if asked, and no two points within 1e-12 of the diagonal (a point made twice)
void expect_watertight(const Out& out, bool closed = true)
{
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(out));
  EXPECT_EQ(CGAL::is_closed(out), closed);
  const double tolerance = 1e-12 * diagonal(out);
  std::vector<K::Point_3> points(out.points().begin(), out.points().end());
  std::size_t close = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
    for(std::size_t j = i + 1; j < points.size(); ++j)
      close += CGAL::squared_distance(points[i], points[j]) <= tolerance * tolerance;
  EXPECT_EQ(close, 0u);
}

// the evaluations at every grid point of every domain at rate n (sub-quads at n / 2)
template <class Surface>
std::vector<std::vector<K::Point_3>> grid_evaluations(const Surface& surface, const Mesh& mesh, int n, bool loop)
{
  std::vector<std::vector<K::Point_3>> by_face;
  for(const auto f : mesh.faces()) {
    std::vector<K::Point_3> points;
    const int corners = static_cast<int>(mesh.degree(f));
    if(loop) {
      for(int i = 0; i <= n; ++i)
        for(int j = 0; i + j <= n; ++j)
          points.push_back(surface.evaluate(f, double(i) / n, double(j) / n).position);
    } else if(corners == 4) {
      for(int i = 0; i <= n; ++i)
        for(int j = 0; j <= n; ++j)
          points.push_back(surface.evaluate(f, double(i) / n, double(j) / n).position);
    } else if constexpr(std::is_same_v<Surface, CC>) {
      const int m = n / 2;
      for(int c = 0; c < corners; ++c)
        for(int i = 0; i <= m; ++i)
          for(int j = 0; j <= m; ++j)
            points.push_back(surface.evaluate(f, c, double(i) / m, double(j) / m).position);
    }
    by_face.push_back(points);
  }
  return by_face;
}

// every output point is, bit for bit, an evaluation at its parameter in a face;
// every evaluation is an output point (1e-12 of the diagonal), bit for bit on face 0
void expect_evaluations(const Out& out, const std::vector<std::vector<K::Point_3>>& by_face)
{
  const double tolerance = 1e-12 * diagonal(out);
  std::vector<K::Point_3> all;
  for(std::size_t f = 0; f < by_face.size(); ++f)
    for(const K::Point_3& p : by_face[f]) {
      all.push_back(p);
      double nearest = 1e300;
      bool exact = false;
      for(const auto& q : out.points()) {
        nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(p, q)));
        exact = exact || p == q;
      }
      EXPECT_LE(nearest, tolerance) << "face " << f;
      if(f == 0) {
        EXPECT_TRUE(exact);
      }
    }
  for(const auto& q : out.points())
    EXPECT_NE(std::find(all.begin(), all.end(), q), all.end());
}

// the output point at each mesh vertex is its limit position (project_to_limit on a copy)
template <class Mask>
void expect_limit_at_vertices(const Out& out, const Mesh& mesh, const Mask& mask)
{
  Mesh limit = mesh;
  S::project_to_limit(limit, mask);
  const double tolerance = 1e-12 * diagonal(out);
  for(const auto& p : limit.points()) {
    double nearest = 1e300;
    for(const auto& q : out.points())
      nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(p, q)));
    EXPECT_LE(nearest, tolerance);
  }
}

std::size_t count_faces_of_degree(const Out& out, std::size_t degree)
{
  std::size_t count = 0;
  for(const auto f : out.faces())
    count += out.degree(f) == degree;
  return count;
}

} // namespace

TEST(Tessellate, CubeCountsValuesAndLimitAtVertices)
{
  const Mesh mesh = testing_utils::cube<Mesh>();
  const CC surface(mesh);
  const std::size_t v = mesh.number_of_vertices(), e = mesh.number_of_edges(), f = mesh.number_of_faces();
  for(int n = 1; n <= 3; ++n) {
    SCOPED_TRACE("rate " + std::to_string(n));
    Out quads, triangles;
    S::tessellate(surface, quads, n);
    const std::size_t m = static_cast<std::size_t>(n - 1);
    EXPECT_EQ(quads.number_of_vertices(), v + e * m + f * m * m);
    EXPECT_EQ(quads.number_of_faces(), f * n * n);
    EXPECT_EQ(count_faces_of_degree(quads, 4), f * n * n);
    expect_watertight(quads);
    if(n < 3)
      continue;
    S::tessellate(surface, triangles, n, S::parameters::triangulate(true));
    EXPECT_EQ(triangles.number_of_vertices(), v + e * m + f * m * m);
    EXPECT_EQ(triangles.number_of_faces(), 2 * f * n * n);
    EXPECT_EQ(count_faces_of_degree(triangles, 3), 2 * f * n * n);
    expect_watertight(triangles);
    EXPECT_TRUE(std::equal(quads.points().begin(), quads.points().end(), triangles.points().begin()));
    expect_evaluations(quads, grid_evaluations(surface, mesh, n, false));
    expect_limit_at_vertices(quads, mesh, S::Catmull_clark_mask<Mesh>());
  }
}

TEST(Tessellate, NormalsAreUnitAndOutward)
{
  const Mesh mesh = testing_utils::cube<Mesh>();
  const CC surface(mesh);
  Out out;
  S::tessellate(surface, out, 3, S::parameters::output_normals(true));
  const auto [normal, found] = out.property_map<Out::Vertex_index, S::Limit_sample::Vector>("v:normal");
  ASSERT_TRUE(found);
  for(const auto w : out.vertices())
    EXPECT_NEAR(normal[w].squared_length(), 1.0, 1e-12);
  for(const auto g : out.faces()) {
    // Newell's normal of the output face
    S::Limit_sample::Vector n = CGAL::NULL_VECTOR;
    for(const auto h : CGAL::halfedges_around_face(out.halfedge(g), out)) {
      const auto& p = out.point(out.source(h));
      const auto& q = out.point(out.target(h));
      n = n + S::Limit_sample::Vector((p.y() - q.y()) * (p.z() + q.z()), (p.z() - q.z()) * (p.x() + q.x()),
                                      (p.x() - q.x()) * (p.y() + q.y()));
    }
    for(const auto w : CGAL::vertices_around_face(out.halfedge(g), out))
      EXPECT_GT(normal[w] * n, 0) << "face " << g.idx();
    // outward: away from the cube's centre
    EXPECT_GT(n * (out.point(out.target(out.halfedge(g))) - K::Point_3(0.5, 0.5, 0.5)), 0);
  }
  Out plain;
  S::tessellate(surface, plain, 3);
  EXPECT_FALSE((plain.property_map<Out::Vertex_index, S::Limit_sample::Vector>("v:normal").second));
}

TEST(Tessellate, MixedBoxSubQuads)
{
  const Mesh mesh = testing_utils::mixed_box<Mesh>();
  const CC surface(mesh);
  const std::size_t v = mesh.number_of_vertices(), e = mesh.number_of_edges();
  ASSERT_EQ(e, 13u);
  for(int n : {2}) {
    SCOPED_TRACE("rate " + std::to_string(n));
    Out out;
    S::tessellate(surface, out, n);
    // 5 quads at n x n, 2 triangles as 3 sub-quads at n / 2 x n / 2
    const std::size_t m = static_cast<std::size_t>(n - 1), h = static_cast<std::size_t>(n / 2);
    EXPECT_EQ(out.number_of_vertices(), v + e * m + 5 * m * m + 2 * (1 + 3 * (h - 1) + 3 * (h - 1) * (h - 1)));
    EXPECT_EQ(out.number_of_faces(), 5u * n * n + 2 * 3 * h * h);
    expect_watertight(out);
    expect_evaluations(out, grid_evaluations(surface, mesh, n, false));
    expect_limit_at_vertices(out, mesh, S::Catmull_clark_mask<Mesh>());
  }
  // odd rates next to the triangles (raised to even): EdgeRates
}

TEST(Tessellate, LoopTriangles)
{
  for(const Mesh& mesh : {testing_utils::tetrahedron<Mesh>(), testing_utils::bipyramid<Mesh>(5)}) {
    const Loop surface(mesh);
    const std::size_t v = mesh.number_of_vertices(), e = mesh.number_of_edges(), f = mesh.number_of_faces();
    for(int n : {1, 3}) {
      SCOPED_TRACE("rate " + std::to_string(n) + ", " + std::to_string(f) + " faces");
      Out out;
      S::tessellate(surface, out, n);
      const std::size_t m = static_cast<std::size_t>(n - 1);
      EXPECT_EQ(out.number_of_vertices(), v + e * m + (n > 1 ? f * m * (m - 1) / 2 : 0));
      EXPECT_EQ(out.number_of_faces(), f * n * n);
      expect_watertight(out);
      if(n == 3) {
        expect_evaluations(out, grid_evaluations(surface, mesh, n, true));
        expect_limit_at_vertices(out, mesh, S::Loop_mask<Mesh>());
      }
    }
  }
}

TEST(Tessellate, OpenGrid)
{
  const Mesh mesh = testing_utils::grid<Mesh>(
    3, 3, [](int i, int j) { return K::Point_3(i, j, (i * j) % 3); }, false);
  const CC surface(mesh);
  for(int n : {2}) {
    Out out;
    S::tessellate(surface, out, n);
    const std::size_t m = static_cast<std::size_t>(n - 1);
    EXPECT_EQ(out.number_of_vertices(), 16 + 24 * m + 9 * m * m);
    EXPECT_EQ(out.number_of_faces(), 9u * n * n);
    expect_watertight(out, false);
    std::size_t border = 0;
    for(const auto h : out.halfedges())
      border += out.is_border(h);
    EXPECT_EQ(border, 12u * n); // the 12 border edges, n segments each
    expect_evaluations(out, grid_evaluations(surface, mesh, n, false));
  }
}

// Loop with a border: a 3 x 3 triangle grid (16 vertices, 33 edges, 18
// faces, 12 border edges), n segments on each border edge
TEST(Tessellate, OpenTriangleGrid)
{
  const Mesh mesh = testing_utils::grid<Mesh>(
    3, 3, [](int i, int j) { return K::Point_3(i, j, (i * j) % 3); }, true);
  const Loop surface(mesh);
  const int n = 3;
  Out out;
  S::tessellate(surface, out, n);
  const std::size_t m = static_cast<std::size_t>(n - 1);
  EXPECT_EQ(out.number_of_vertices(), 16 + 33 * m + 18 * m * (m - 1) / 2);
  EXPECT_EQ(out.number_of_faces(), 18u * n * n);
  expect_watertight(out, false);
  std::size_t border = 0;
  for(const auto h : out.halfedges())
    border += out.is_border(h);
  EXPECT_EQ(border, 12u * n);
  expect_evaluations(out, grid_evaluations(surface, mesh, n, true));
  expect_limit_at_vertices(out, mesh, S::Loop_mask<Mesh>());
}

TEST(Tessellate, EdgeRates)
{
  const auto rate = [](auto e) { return 1 + static_cast<int>(e.idx() % 3); };
  const Mesh cube = testing_utils::cube<Mesh>(), box = testing_utils::mixed_box<Mesh>(),
             bipyramid = testing_utils::bipyramid<Mesh>(5);
  const CC cube_surface(cube), box_surface(box);
  const Loop loop_surface(bipyramid);
  Out constant, uniform;
  S::tessellate(cube_surface, constant, [](Mesh::Edge_index) { return 3; });
  S::tessellate(cube_surface, uniform, 3);
  EXPECT_TRUE(
    std::equal(constant.points().begin(), constant.points().end(), uniform.points().begin(), uniform.points().end()));
  EXPECT_EQ(constant.number_of_faces(), uniform.number_of_faces());
  // every mesh edge carries its rate's points (the rate raised to even next to the box's triangles)
  const auto expect_edge_points = [](const Out& out, const Mesh& mesh, const auto& surface, auto edge_rate) {
    for(const auto e : mesh.edges()) {
      const auto h = mesh.halfedge(e);
      const auto f = mesh.face(h);
      const int r = edge_rate(e);
      // the index of h in f (h is the halfedge into corner i: side i - 1)
      int i = 0;
      for(auto g = mesh.halfedge(f); g != h; g = mesh.next(g))
        ++i;
      if(mesh.degree(f) != 4 && mesh.degree(f) != 3)
        continue;
      const std::size_t corners = mesh.degree(f);
      const bool triangle = corners == 3 && !std::is_same_v<std::decay_t<decltype(surface)>, CC>;
      if(corners == 3 && !triangle)
        continue; // a sub-quad's sides: covered by watertightness
      const double tolerance = 1e-12 * diagonal(out);
      // side i - 1, from corner i - 1 (the source of h): (t, 0), (1, t), (1 - t, 1), (0, 1 - t) on a
      // quad, (t, 0), (1 - t, t), (0, 1 - t) on a triangle
      const int side = (i + static_cast<int>(corners) - 1) % static_cast<int>(corners);
      for(int k = 1; k < r; ++k) {
        const double t = double(k) / r;
        double u = 0, v = 0;
        if(side == 0)
          u = t;
        else if(triangle && side == 1)
          u = 1 - t, v = t;
        else if(triangle)
          v = 1 - t;
        else if(side == 1)
          u = 1, v = t;
        else if(side == 2)
          u = 1 - t, v = 1;
        else
          v = 1 - t;
        const auto p = surface.evaluate(f, u, v).position;
        double nearest = 1e300;
        for(const auto& q : out.points())
          nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(p, q)));
        EXPECT_LE(nearest, tolerance) << "edge " << e.idx() << " point " << k;
      }
    }
  };
  Out a, b, c, d;
  S::tessellate(cube_surface, a, rate);
  S::tessellate(cube_surface, b, rate, S::parameters::triangulate(true));
  S::tessellate(box_surface, c, rate);
  S::tessellate(loop_surface, d, rate);
  for(const Out* out : {&a, &b, &c, &d})
    expect_watertight(*out);
  EXPECT_TRUE(std::equal(a.points().begin(), a.points().end(), b.points().begin(), b.points().end()));
  EXPECT_EQ(count_faces_of_degree(b, 3), b.number_of_faces());
  EXPECT_EQ(count_faces_of_degree(d, 3), d.number_of_faces());
  expect_edge_points(a, cube, cube_surface, rate);
  expect_edge_points(d, bipyramid, loop_surface, rate);
}

TEST(Tessellate, BadRatesRefused)
{
  const Mesh mesh = testing_utils::cube<Mesh>();
  const CC surface(mesh);
  Out out;
  S::tessellate(surface, out, 1);
  const std::size_t vertices = out.number_of_vertices(), faces = out.number_of_faces();
  const K::Point_3 first = out.point(*out.vertices().begin());
  const auto expect_refused = [&](const std::function<void()>& call, const std::string& message) {
    try {
      call();
      ADD_FAILURE() << "not refused: " << message;
    } catch(const S::Bad_input& error) {
      EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
    }
    EXPECT_EQ(out.number_of_vertices(), vertices);
    EXPECT_EQ(out.number_of_faces(), faces);
    EXPECT_EQ(out.point(*out.vertices().begin()), first);
  };
  expect_refused([&] { S::tessellate(surface, out, 0); }, "tessellate: the rate of edge 0 is 0, not >= 1");
  expect_refused([&] { S::tessellate(surface, out, -3); }, "the rate of edge 0 is -3");
  expect_refused([&] { S::tessellate(surface, out, [](Mesh::Edge_index e) { return e.idx() == 5 ? 0 : 2; }); },
                 "the rate of edge 5 is 0");
  expect_refused([&] { S::tessellate(surface, out, 100000); }, "more than the max_output_points limit");
  expect_refused([&] { S::tessellate(surface, out, 2147483647); }, "more than the max_output_points limit");
  expect_refused([&] { S::tessellate(surface, out, 2, S::parameters::max_output_points(53)); },
                 "more than the max_output_points limit (53");
  // within the limit: replaced
  S::tessellate(surface, out, 2, S::parameters::max_output_points(54));
  EXPECT_EQ(out.number_of_faces(), 24u);
}
