// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
// Limit_surface against references that share no code with it (issue 13):
// OpenSubdiv Far's limit of uniformly refined vertices at dyadic parameters,
// OpenSubdiv Bfr's evaluation at random parameters, differences of our own
// positions and derivatives, and the agreement of the two faces of every edge.
// Catmull-Clark on closed meshes with valence 3 and 5 vertices, triangles and
// pentagons (sub-quads), a regular torus and open grids (both border-corner
// rules); Loop on an octahedron, an icosahedron, a bipyramid, a regular torus,
// open triangle grids (both border-corner rules) and a bipyramid with a hole.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/limit/Limit_surface.h>
#include <CGAL/Subdiv/subdivide.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "mesh_builders.h"
#include "mesh_test_utils.h"

#if defined(SUBDIV_TEST_WITH_OSD)
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include "opensubdiv_far.h"
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

namespace Sd = CGAL::Subdiv;
using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Point = Sd::Limit_sample::Point;
using Vector = Sd::Limit_sample::Vector;
using Cc_mask = Sd::Catmull_clark_mask<Mesh>;
using Loop_mask = Sd::Loop_mask<Mesh>;

enum class Scheme { catmark, loop };

/// a mesh and the scheme (and border-corner rule) its limit is taken with
struct Case
{
  std::string name;
  Scheme scheme;
  Sd::Border_corners corners;
  Mesh (*build)();
};

std::ostream& operator<<(std::ostream& out, const Case& c)
{
  return out << c.name;
}

/// a domain of the evaluator: a quad or a Loop triangle (corner -1), or the
/// sub-quad at `corner` of a Catmull-Clark face with n != 4 corners
struct Chart
{
  int face;
  int corner;
  bool operator<(const Chart& other) const { return std::tie(face, corner) < std::tie(other.face, other.corner); }
};

double length(const Vector& w)
{
  return std::sqrt(w.squared_length());
}

Vector unit(const Vector& w)
{
  const double l = length(w);
  return l > 0 ? w / l : w;
}

/// the limit surface of a case, whichever its scheme
class Evaluator
{
public:
  explicit Evaluator(const Case& c, const Mesh& mesh) : m_mesh(mesh)
  {
    if(c.scheme == Scheme::catmark)
      m_catmark.emplace(mesh, Cc_mask(c.corners));
    else
      m_loop.emplace(mesh, Loop_mask(c.corners));
  }

  Sd::Limit_sample operator()(const Chart& chart, double u, double v) const
  {
    const Mesh::Face_index f(static_cast<Mesh::size_type>(chart.face));
    if(m_loop)
      return m_loop->evaluate(f, u, v);
    return chart.corner < 0 ? m_catmark->evaluate(f, u, v) : m_catmark->evaluate(f, chart.corner, u, v);
  }

  /// the domains of the mesh's faces, by face
  std::vector<Chart> charts() const
  {
    std::vector<Chart> all;
    for(const Mesh::Face_index f : faces(m_mesh)) {
      const int n = static_cast<int>(m_mesh.degree(f));
      if(m_catmark && n != 4)
        for(int c = 0; c < n; ++c)
          all.push_back({static_cast<int>(f), c});
      else
        all.push_back({static_cast<int>(f), -1});
    }
    return all;
  }

  bool triangles() const { return m_loop.has_value(); }

private:
  const Mesh& m_mesh;
  std::optional<Sd::Limit_surface<Mesh, Cc_mask>> m_catmark;
  std::optional<Sd::Limit_surface<Mesh, Loop_mask>> m_loop;
};

// ---------------------------------------------------------------- the meshes

/// a torus of n x m cells (quads, or triangles of valence 6), its points moved a little
Mesh torus(int n, int m, bool triangles)
{
  testing_utils::Rationals r;
  std::vector<Point> points;
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < n; ++i) {
      const double theta = 2 * CGAL_PI * i / n, phi = 2 * CGAL_PI * j / m;
      const double radius = 3 + std::cos(phi);
      points.emplace_back(radius * std::cos(theta) + 0.1 * r.next(), radius * std::sin(theta) + 0.1 * r.next(),
                          std::sin(phi) + 0.1 * r.next());
    }
  const auto id = [n, m](int i, int j) { return (j % m) * n + i % n; };
  return testing_utils::mesh_of<Mesh>(points,
                                      testing_utils::lattice_faces(n, m, id, triangles, [](int, int) { return true; }));
}

/// an open n x m grid of quads over a bumpy height field
Point bumpy(int i, int j)
{
  return Point(i + 0.1 * j * j, j, 0.3 * std::sin(i + 2.0 * j));
}

/// the 4 x 4 grid without its 2 x 2 cells at i, j >= 2: an L whose inner
/// corner (2, 2) is a border vertex with three faces
Mesh l_shape()
{
  std::vector<Point> points;
  for(int j = 0; j <= 4; ++j)
    for(int i = 0; i <= 4; ++i)
      points.push_back(bumpy(i, j));
  const auto id = [](int i, int j) { return 5 * j + i; };
  std::vector<std::vector<int>> faces;
  for(const auto& face : testing_utils::lattice_faces(4, 4, id, false, [](int, int) { return true; }))
    if(!(face[0] % 5 >= 2 && face[0] / 5 >= 2))
      faces.push_back(face);
  // mesh_of keeps the vertices no face uses: none here but (3, 3), (4, 3), (3, 4), (4, 4)
  Mesh mesh = testing_utils::mesh_of<Mesh>(points, faces);
  for(const int v : {18, 19, 23, 24})
    mesh.remove_vertex(Mesh::Vertex_index(v));
  mesh.collect_garbage();
  return mesh;
}

/// a regular icosahedron, faces outward
Mesh icosahedron()
{
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Point> p = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                          {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  return testing_utils::mesh_of<Mesh>(
    p, {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}});
}

/// a bipyramid of 6 sides without one face: border vertices with 3 and 5 faces
Mesh open_bipyramid()
{
  Mesh mesh = testing_utils::bipyramid<Mesh>(6);
  CGAL::Euler::remove_face(mesh.halfedge(*mesh.faces().begin()), mesh);
  mesh.collect_garbage();
  return mesh;
}

/// a pentagonal prism refined once: quads only, two vertices of valence 5
Mesh refined_prism()
{
  Mesh mesh = testing_utils::prism<Mesh>(5);
  Sd::subdivide(mesh, Cc_mask());
  return mesh;
}

std::vector<Case> every_case()
{
  const auto smooth = Sd::Border_corners::smooth, sharp = Sd::Border_corners::sharp;
  return {
    {"cube", Scheme::catmark, smooth, [] { return testing_utils::cube<Mesh>(); }},
    {"refined_prism", Scheme::catmark, smooth, refined_prism},
    {"prism", Scheme::catmark, smooth, [] { return testing_utils::prism<Mesh>(5); }},
    {"mixed_box", Scheme::catmark, smooth, [] { return testing_utils::mixed_box<Mesh>(); }},
    {"quad_torus", Scheme::catmark, smooth, [] { return torus(8, 6, false); }},
    {"grid_smooth_corners", Scheme::catmark, smooth, [] { return testing_utils::grid<Mesh>(5, 4, bumpy, false); }},
    {"grid_sharp_corners", Scheme::catmark, sharp, [] { return testing_utils::grid<Mesh>(5, 4, bumpy, false); }},
    {"l_shape", Scheme::catmark, smooth, l_shape},
    {"octahedron", Scheme::loop, smooth, [] { return testing_utils::bipyramid<Mesh>(4); }},
    {"icosahedron", Scheme::loop, smooth, icosahedron},
    {"bipyramid", Scheme::loop, smooth, [] { return testing_utils::bipyramid<Mesh>(7); }},
    {"triangle_torus", Scheme::loop, smooth, [] { return torus(8, 6, true); }},
    {"triangle_grid_smooth_corners", Scheme::loop, smooth, [] { return testing_utils::grid<Mesh>(5, 4, bumpy, true); }},
    {"triangle_grid_sharp_corners", Scheme::loop, sharp, [] { return testing_utils::grid<Mesh>(5, 4, bumpy, true); }},
    {"open_bipyramid", Scheme::loop, smooth, open_bipyramid},
  };
}

double diagonal_of(const Mesh& mesh)
{
  return testing_utils::diagonal(testing_utils::double_points(mesh));
}

/// the largest value seen in a category, printed and recorded once per test
class Maximum
{
public:
  explicit Maximum(std::string name) : m_name(std::move(name)) {}
  void add(double value) { m_value = (std::max)(m_value, value); }
  double value() const { return m_value; }
  ~Maximum()
  {
    std::cout << "  max " << m_name << ": " << m_value << "\n";
    testing::Test::RecordProperty(m_name, std::to_string(m_value));
  }

private:
  std::string m_name;
  double m_value = 0;
};

class LimitSurfaceOsd : public testing::TestWithParam<Case>
{};

// ------------------------------------------- differences of our own values

// Central differences (h = 1e-4) of the positions give du and dv, of du and
// dv the second derivatives, at random parameters inside every domain (at
// least 0.1 from its sides, so that no extraordinary corner is near, and
// 2 h from every multiple of 1/64, so that no difference straddles the seam
// of two patches of the local refinement, where the third derivative jumps).
TEST_P(LimitSurfaceOsd, derivatives_are_differences_of_positions)
{
  const Case& c = GetParam();
  const Mesh mesh = c.build();
  const Evaluator surface(c, mesh);
  const double h = 1e-4;
  std::mt19937 random(20261207);
  std::uniform_real_distribution<double> inside(0.1, 0.9);
  const auto off_seams = [h](double x) {
    const double k = std::round(x * 64);
    return std::abs(x - k / 64) > 2 * h;
  };
  Maximum first("first_derivative_error"), second("second_derivative_error");
  for(const Chart& chart : surface.charts())
    for(int k = 0; k < 3;) {
      const double u = inside(random), v = inside(random);
      if(!off_seams(u) || !off_seams(v) || (surface.triangles() && u + v > 0.9))
        continue;
      ++k;
      const Sd::Limit_sample s = surface(chart, u, v);
      const auto at = [&](double du, double dv) { return surface(chart, u + du, v + dv); };
      const Sd::Limit_sample u0 = at(-h, 0), u1 = at(h, 0), v0 = at(0, -h), v1 = at(0, h);
      const double scale1 = (std::max)(length(s.du), length(s.dv));
      const double scale2 = (std::max)({length(s.duu), length(s.duv), length(s.dvv), scale1});
      const double e1 = (std::max)(length((u1.position - u0.position) / (2 * h) - s.du),
                                   length((v1.position - v0.position) / (2 * h) - s.dv)) /
                        scale1;
      const double e2 =
        (std::max)({length((u1.du - u0.du) / (2 * h) - s.duu), length((v1.dv - v0.dv) / (2 * h) - s.dvv),
                    length((v1.du - v0.du) / (2 * h) - s.duv), length((u1.dv - u0.dv) / (2 * h) - s.duv)}) /
        scale2;
      first.add(e1);
      second.add(e2);
      EXPECT_LT(e1, 1e-6) << c.name << " face " << chart.face << " corner " << chart.corner << " at " << u << ", " << v;
      EXPECT_LT(e2, 1e-6) << c.name << " face " << chart.face << " corner " << chart.corner << " at " << u << ", " << v;
    }
}

// ------------------------------------------------------- across the edges

/// the chart and parameter of the point at `t` from source(h) to target(h)
/// along halfedge h of a face (or, if h is -1, on the seam of sub-quads
/// `corner` and `corner` + 1 from the edge's midpoint to the face point)
struct On_face
{
  Chart chart;
  double u, v;
};

On_face point_on_edge(const Mesh& mesh, bool catmark, Mesh::Halfedge_index h, double t)
{
  const Mesh::Face_index f = mesh.face(h);
  const int n = static_cast<int>(mesh.degree(f));
  int k = 0; // h goes from corner k - 1 to corner k
  for(Mesh::Halfedge_index g = mesh.halfedge(f); g != h; g = mesh.next(g))
    ++k;
  const int from = (k + n - 1) % n, to = k % n;
  const int face = static_cast<int>(f);
  if(catmark && n != 4) // the first half in sub-quad `from` along u, the second in sub-quad `to` along v
    return t <= 0.5 ? On_face{{face, from}, 2 * t, 0} : On_face{{face, to}, 0, 2 * (1 - t)};
  static const double quad[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  static const double triangle[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  const double(*corner)[2] = n == 4 ? quad : triangle;
  return {{face, -1}, (1 - t) * corner[from][0] + t * corner[to][0], (1 - t) * corner[from][1] + t * corner[to][1]};
}

// Every point of an edge (and of the seams between the sub-quads of a face),
// evaluated from the faces on either side, is the same point with the same
// normal: 1e-12 of the diagonal and 1e-9.
TEST_P(LimitSurfaceOsd, faces_agree_along_every_edge)
{
  const Case& c = GetParam();
  const Mesh mesh = c.build();
  const Evaluator surface(c, mesh);
  const double diagonal = diagonal_of(mesh);
  const bool catmark = c.scheme == Scheme::catmark;
  Maximum positions("edge_position_gap"), normals("edge_normal_gap");
  std::mt19937 random(7);
  std::uniform_real_distribution<double> anywhere(0, 1);
  const auto expect_same = [&](const On_face& a, const On_face& b, const std::string& where) {
    const Sd::Limit_sample sa = surface(a.chart, a.u, a.v), sb = surface(b.chart, b.u, b.v);
    const double gap = std::sqrt(CGAL::squared_distance(sa.position, sb.position)) / diagonal;
    const double turn = length(sa.normal - sb.normal);
    positions.add(gap);
    normals.add(turn);
    EXPECT_LT(gap, 1e-12) << c.name << " " << where;
    EXPECT_LT(turn, 1e-9) << c.name << " " << where;
  };
  int pairs = 0;
  for(const Mesh::Edge_index e : mesh.edges()) {
    const Mesh::Halfedge_index h = mesh.halfedge(e);
    if(mesh.is_border(e))
      continue;
    for(const double t : {0.0, 0.25, 1.0 / 3, 0.5, 0.7, 1.0, anywhere(random), anywhere(random)}) {
      expect_same(point_on_edge(mesh, catmark, h, t), point_on_edge(mesh, catmark, mesh.opposite(h), 1 - t),
                  "edge " + std::to_string(static_cast<int>(e)) + " at " + std::to_string(t));
      ++pairs;
    }
  }
  for(const Mesh::Face_index f : faces(mesh)) {
    const int n = static_cast<int>(mesh.degree(f));
    if(!catmark || n == 4)
      continue;
    // the seam from the midpoint of the edge from corner i to i+1 to the face point
    for(int i = 0; i < n; ++i)
      for(const double s : {0.0, 0.3, 0.5, 1.0, anywhere(random)}) {
        expect_same({{static_cast<int>(f), i}, 1, s}, {{static_cast<int>(f), (i + 1) % n}, s, 1},
                    "face " + std::to_string(static_cast<int>(f)) + " seam " + std::to_string(i));
        ++pairs;
      }
  }
  EXPECT_GT(pairs, 0);
}

#if defined(SUBDIV_TEST_WITH_OSD)
namespace Far = OpenSubdiv::Far;
namespace Bfr = OpenSubdiv::Bfr;
using testing_utils::Osd_vertex;

/// OpenSubdiv's refiner of the mesh, not refined yet: face f is face f of
/// the mesh, its vertex 0 the target of halfedge(f), as the evaluator's corner 0
std::unique_ptr<Far::TopologyRefiner> far_refiner(const Case& c, const Mesh& mesh)
{
  std::vector<int> sizes, indices;
  for(const Mesh::Face_index f : faces(mesh)) {
    sizes.push_back(static_cast<int>(mesh.degree(f)));
    for(const Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
      indices.push_back(static_cast<int>(mesh.target(h)));
  }
  Far::TopologyDescriptor descriptor;
  descriptor.numVertices = static_cast<int>(mesh.number_of_vertices());
  descriptor.numFaces = static_cast<int>(sizes.size());
  descriptor.numVertsPerFace = sizes.data();
  descriptor.vertIndicesPerFace = indices.data();
  // the library's smooth border corners are OpenSubdiv's "edges only", its sharp ones "edges and corners"
  // (Border_corners, views/Vertex_view.h)
  OpenSubdiv::Sdc::Options options;
  options.SetVtxBoundaryInterpolation(c.corners == Sd::Border_corners::sharp
                                        ? OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER
                                        : OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  const auto type = c.scheme == Scheme::catmark ? OpenSubdiv::Sdc::SCHEME_CATMARK : OpenSubdiv::Sdc::SCHEME_LOOP;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(descriptor, Factory::Options(type, options)));
  EXPECT_TRUE(refiner != nullptr) << c.name;
  return refiner;
}

std::vector<Osd_vertex> far_points(const Mesh& mesh)
{
  std::vector<Osd_vertex> points;
  for(const Mesh::Vertex_index v : vertices(mesh))
    points.push_back(Osd_vertex{{mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()}});
  return points;
}

Point point_of(const Osd_vertex& v)
{
  return Point(v.p[0], v.p[1], v.p[2]);
}
Vector vector_of(const Osd_vertex& v)
{
  return Vector(v.p[0], v.p[1], v.p[2]);
}

/// a vertex of the last level of a uniform refinement, at a parameter of a domain of the base mesh
struct Dyadic_vertex
{
  Chart chart;
  double u, v;
  int vertex;
};

/*
 * Where every vertex of level `levels` sits in the domains of the base
 * faces, from Far's own parent-child relations (not from positions): a
 * child of a parent's vertex sits at that vertex's parameter, of an edge at
 * the midpoint of its ends', of a face at the mean of its corners'. A
 * Catmull-Clark base face with n != 4 corners is its n sub-quads after one
 * level: the child at its corner c is sub-quad c, (0,0) at the corner, (1,0)
 * at the midpoint of the edge from corner c to c+1, (0,1) of the edge from
 * corner c-1 to c, (1,1) at the face point.
 */
std::vector<Dyadic_vertex> dyadic_vertices(const Far::TopologyRefiner& refiner, bool catmark, int levels)
{
  using Uv = std::array<double, 2>;
  struct Face_domain
  {
    Chart chart;
    std::vector<Uv> uv; // by face vertex; empty for a base face with n != 4 corners under Catmull-Clark
  };
  std::map<int, Face_domain> domains; // by face of the current level
  const Far::TopologyLevel& base = refiner.GetLevel(0);
  for(int f = 0; f < base.GetNumFaces(); ++f) {
    const int n = base.GetFaceVertices(f).size();
    if(catmark && n != 4)
      domains[f] = {{f, -1}, {}};
    else if(n == 4)
      domains[f] = {{f, -1}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    else
      domains[f] = {{f, -1}, {{0, 0}, {1, 0}, {0, 1}}};
  }
  for(int level = 0; level < levels; ++level) {
    const Far::TopologyLevel& parent = refiner.GetLevel(level);
    const Far::TopologyLevel& child = refiner.GetLevel(level + 1);
    // what each child vertex is the child of: (0, vertex), (1, edge) or (2, face)
    std::vector<std::pair<int, int>> origin(child.GetNumVertices(), {-1, -1});
    for(int v = 0; v < parent.GetNumVertices(); ++v)
      origin[parent.GetVertexChildVertex(v)] = {0, v};
    for(int e = 0; e < parent.GetNumEdges(); ++e)
      origin[parent.GetEdgeChildVertex(e)] = {1, e};
    for(int f = 0; catmark && f < parent.GetNumFaces(); ++f) // Loop makes no face points
      origin[parent.GetFaceChildVertex(f)] = {2, f};
    std::map<int, Face_domain> children;
    for(const auto& [f, domain] : domains) {
      const auto corners = parent.GetFaceVertices(f);
      const int n = corners.size();
      const auto corner_of = [&](int vertex) {
        for(int i = 0; i < n; ++i)
          if(corners[i] == vertex)
            return i;
        ADD_FAILURE() << "vertex " << vertex << " is not a corner of face " << f;
        return 0;
      };
      for(const int g : parent.GetFaceChildFaces(f)) {
        const auto child_corners = child.GetFaceVertices(g);
        Face_domain next{domain.chart, {}};
        if(domain.uv.empty()) { // sub-quad: the corner of f it holds
          int c = -1;
          for(const int w : child_corners)
            if(origin[w].first == 0)
              c = corner_of(origin[w].second);
          next.chart.corner = c;
          for(const int w : child_corners) {
            const auto [kind, index] = origin[w];
            if(kind == 0)
              next.uv.push_back({0, 0});
            else if(kind == 2)
              next.uv.push_back({1, 1});
            else {
              const auto ends = parent.GetEdgeVertices(index);
              const int other = corner_of(ends[0]) == c ? corner_of(ends[1]) : corner_of(ends[0]);
              next.uv.push_back(other == (c + 1) % n ? Uv{1, 0} : Uv{0, 1});
            }
          }
        } else
          for(const int w : child_corners) {
            const auto [kind, index] = origin[w];
            if(kind == 0)
              next.uv.push_back(domain.uv[corner_of(index)]);
            else if(kind == 1) {
              const auto ends = parent.GetEdgeVertices(index);
              const Uv a = domain.uv[corner_of(ends[0])], b = domain.uv[corner_of(ends[1])];
              next.uv.push_back({(a[0] + b[0]) / 2, (a[1] + b[1]) / 2});
            } else {
              Uv mean{0, 0};
              for(const Uv& p : domain.uv)
                mean = {mean[0] + p[0] / n, mean[1] + p[1] / n};
              next.uv.push_back(mean);
            }
          }
        children[g] = next;
      }
    }
    domains = std::move(children);
  }
  std::map<std::tuple<int, int, double, double>, int> seen;
  std::vector<Dyadic_vertex> result;
  const Far::TopologyLevel& last = refiner.GetLevel(levels);
  for(const auto& [f, domain] : domains) {
    const auto corners = last.GetFaceVertices(f);
    for(int i = 0; i < corners.size(); ++i) {
      const auto key = std::make_tuple(domain.chart.face, domain.chart.corner, domain.uv[i][0], domain.uv[i][1]);
      const auto [it, fresh] = seen.emplace(key, corners[i]);
      if(fresh)
        result.push_back({domain.chart, domain.uv[i][0], domain.uv[i][1], corners[i]});
      else
        EXPECT_EQ(it->second, corners[i]) << "two vertices at one parameter";
    }
  }
  return result;
}

/// the base mesh's vertex at a dyadic parameter, if it is at one: a corner
/// of a quad or triangle, corner (0,0) of a sub-quad
std::optional<Mesh::Vertex_index> base_vertex_at(const Mesh& mesh, bool catmark, const Dyadic_vertex& d)
{
  const Mesh::Face_index f(static_cast<Mesh::size_type>(d.chart.face));
  const int n = static_cast<int>(mesh.degree(f));
  int corner = -1;
  if(d.chart.corner >= 0)
    corner = d.u == 0 && d.v == 0 ? d.chart.corner : -1;
  else if(d.u == 0 && d.v == 0)
    corner = 0;
  else if(d.u == 1 && d.v == 0)
    corner = 1;
  else if(d.u == 1 && d.v == 1 && catmark)
    corner = 2;
  else if(d.u == 0 && d.v == 1)
    corner = n == 4 ? 3 : 2;
  if(corner < 0)
    return std::nullopt;
  Mesh::Halfedge_index h = mesh.halfedge(f);
  for(int k = 0; k < corner; ++k)
    h = mesh.next(h);
  return mesh.target(h);
}

// Refined uniformly L = 1, 2, 3 levels by OpenSubdiv Far, then taken to the
// limit by PrimvarRefiner::Limit: every vertex of level L, at its dyadic
// parameter of the base face (from Far's parent-child relations), is our
// evaluation there: the position to 1e-12 of the diagonal; Far's tangents are
// in a frame of their own, so its normal is compared (1e-9, and the same
// side) and our du and dv lie in its tangent plane (1e-9 relative). At an
// extraordinary vertex, where our derivatives are zero, the position and the
// normal.
TEST_P(LimitSurfaceOsd, dyadic_parameters_are_far_limit_points)
{
  const Case& c = GetParam();
  const Mesh mesh = c.build();
  const Evaluator surface(c, mesh);
  const double diagonal = diagonal_of(mesh);
  Maximum positions("far_position_error"), normals("far_normal_error"), planes("far_tangent_plane_error"),
    far_border("far_normal_error_at_border_vertices_of_3_faces");
  std::array<double, 3> border_turn{0, 0, 0}; // by level
  for(int levels = 1; levels <= 3; ++levels) {
    const std::unique_ptr<Far::TopologyRefiner> refiner = far_refiner(c, mesh);
    ASSERT_TRUE(refiner != nullptr);
    Far::TopologyRefiner::UniformOptions uniform(levels);
    uniform.fullTopologyInLastLevel = true; // Limit needs the last level's neighbourhoods
    refiner->RefineUniform(uniform);
    std::vector<Osd_vertex> points = far_points(mesh);
    Far::PrimvarRefinerReal<double> primvar(*refiner);
    for(int level = 1; level <= levels; ++level) {
      std::vector<Osd_vertex> next(refiner->GetLevel(level).GetNumVertices());
      primvar.Interpolate(level, points, next);
      points = std::move(next);
    }
    std::vector<Osd_vertex> limit(points.size()), tangent1(points.size()), tangent2(points.size());
    primvar.Limit(points, limit, tangent1, tangent2);
    const std::vector<Dyadic_vertex> samples = dyadic_vertices(*refiner, c.scheme == Scheme::catmark, levels);
    const std::size_t per_face_vertex = c.scheme == Scheme::catmark ? 4 : 3;
    EXPECT_GE(samples.size(), mesh.number_of_faces() * per_face_vertex) << c.name;
    int at_corners = 0;
    for(const Dyadic_vertex& d : samples) {
      const Sd::Limit_sample s = surface(d.chart, d.u, d.v);
      const std::string where = c.name + " level " + std::to_string(levels) + " face " + std::to_string(d.chart.face) +
                                " corner " + std::to_string(d.chart.corner) + " at " + std::to_string(d.u) + ", " +
                                std::to_string(d.v);
      const double error = std::sqrt(CGAL::squared_distance(s.position, point_of(limit[d.vertex]))) / diagonal;
      positions.add(error);
      EXPECT_LT(error, 1e-12) << where;
      const Vector far_normal = unit(CGAL::cross_product(vector_of(tangent1[d.vertex]), vector_of(tangent2[d.vertex])));
      const double turn = length(s.normal - far_normal);
      const std::optional<Mesh::Vertex_index> w = base_vertex_at(mesh, c.scheme == Scheme::catmark, d);
      const bool border = w && mesh.is_border(*w);
      if(border && mesh.degree(*w) == 2 && c.corners == Sd::Border_corners::smooth) {
        // a smooth corner of one face has no tangent plane (the normals around
        // it depend on the direction of approach): Far's and ours are conventions
      } else if(border && mesh.degree(*w) > (c.scheme == Scheme::catmark ? 3u : 4u)) {
        // Far's tangent masks at a border vertex with more faces than a
        // regular one (2 quads, 3 triangles) are not
        // the limit's (they approach it as Far refines further: the error
        // halves with every level); ours are the analysis' eigenvectors,
        // which the limit normals of the neighbouring parameters approach
        // (0.38 at level 1 under Loop at the apex of the open bipyramid, a
        // border vertex with 5 faces far from flat)
        far_border.add(turn);
        border_turn[levels - 1] = (std::max)(border_turn[levels - 1], turn);
        EXPECT_LT(turn, 0.5 / (1 << (levels - 1))) << where;
      } else {
        normals.add(turn);
        EXPECT_LT(turn, 1e-9) << where;
      }
      if(s.du == CGAL::NULL_VECTOR && s.dv == CGAL::NULL_VECTOR) {
        ++at_corners;
        continue;
      }
      const double off_plane =
        (std::max)(std::abs(s.du * far_normal) / length(s.du), std::abs(s.dv * far_normal) / length(s.dv));
      planes.add(off_plane);
      EXPECT_LT(off_plane, 1e-9) << where;
    }
    std::cout << "  " << c.name << " level " << levels << ": " << samples.size() << " parameters, " << at_corners
              << " at extraordinary vertices\n";
  }
  if(border_turn[0] > 0) { // Far's border normals converge to ours
    EXPECT_LT(border_turn[1], 0.75 * border_turn[0]) << c.name;
    EXPECT_LT(border_turn[2], 0.75 * border_turn[1]) << c.name;
  }
}

// ------------------------------------------------------------------- Bfr

/// the corner squares of a domain where Bfr's surface is approximate: at its
/// extraordinary corners (0,0), (1,0), (1,1), (0,1) of a quad or sub-quad,
/// of a triangle (0,0), (1,0), (0,1)
std::vector<int> irregular_corners(const Mesh& mesh, const Case& c, const Chart& chart)
{
  const bool catmark = c.scheme == Scheme::catmark;
  const Mesh::Face_index f(static_cast<Mesh::size_type>(chart.face));
  const auto irregular = [&](Mesh::Vertex_index w) {
    if(mesh.is_border(w)) // a border vertex with 2 quads (3 triangles), or a sharp corner of one quad, is regular
      return catmark ? !(mesh.degree(w) == 3 || (mesh.degree(w) == 2 && c.corners == Sd::Border_corners::sharp))
                     : mesh.degree(w) != 4;
    return mesh.degree(w) != (catmark ? 4u : 6u);
  };
  std::vector<Mesh::Vertex_index> corners;
  for(const Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
    corners.push_back(mesh.target(h));
  std::vector<int> result;
  if(chart.corner >= 0) { // the face point (1,1) has the valence n != 4; the edge points are regular
    result.push_back(2);
    if(irregular(corners[chart.corner]))
      result.push_back(0);
    return result;
  }
  for(int i = 0; i < static_cast<int>(corners.size()); ++i)
    if(irregular(corners[i]))
      result.push_back(i);
  return result;
}

/// Bfr's surface of one base face, its patch points ready
struct Bfr_face
{
  Bfr::Surface<double> surface;
  std::vector<double> patch_points;

  bool init(const Bfr::SurfaceFactory& factory, int face, const std::vector<double>& mesh_points)
  {
    if(!factory.InitVertexSurface(face, &surface))
      return false;
    patch_points.resize(3 * surface.GetNumPatchPoints());
    surface.PreparePatchPoints(mesh_points.data(), 3, patch_points.data(), 3);
    return true;
  }

  /// position, first derivatives (s, t) and second (ss, st, tt) at Bfr's (s, t)
  std::array<Vector, 6> evaluate(const std::array<double, 2>& st, Point& p) const
  {
    double q[3], ds[3], dt[3], dss[3], dst[3], dtt[3];
    surface.Evaluate(st.data(), patch_points.data(), 3, q, ds, dt, dss, dst, dtt);
    p = Point(q[0], q[1], q[2]);
    const auto vec = [](const double* w) { return Vector(w[0], w[1], w[2]); };
    return {vec(ds), vec(dt), vec(dss), vec(dst), vec(dtt), CGAL::NULL_VECTOR};
  }
};

// Random parameters (fixed seed) of every domain, evaluated by OpenSubdiv
// Bfr (RefinerSurfaceFactory over the base mesh, default options): a
// sub-quad's parameters are Bfr's normalised sub-face coordinates
// (Parameterization::ConvertNormalizedSubFaceToCoord), the derivatives
// mapped by that affine map. Bfr's surface is exact (B-spline or box-spline
// patches, to rounding) wherever its patch tree has reached regular patches;
// at an extraordinary corner it stops refining at its smooth approximation
// level (2 by default: the corner squares of 1/4 of a face, 1/2 of a
// sub-quad, already one level down) and puts a Gregory patch there, which
// only approximates the limit surface. So: positions, first and second
// derivatives to 1e-12 (of the diagonal) outside those squares; inside, the
// error is recorded, bounded loosely (5e-2 of the diagonal: 2.5e-2 next to the
// apex of the open bipyramid, a border vertex with 5 faces far from flat), and must shrink
// with Bfr's approximation level 4 (a quarter of it at most).
//
// OpenSubdiv 3.5's Bfr returns the second derivatives of the middle
// (rotated) sub-triangles of its Loop patch tree negated: there its own
// first derivatives, differenced along s, give ours, not its second ones. So
// under Loop the second derivatives are compared up to their sign, and a
// negated one must be matched by that difference.
TEST_P(LimitSurfaceOsd, random_parameters_are_bfr_evaluations)
{
  const Case& c = GetParam();
  const Mesh mesh = c.build();
  const Evaluator surface(c, mesh);
  const bool catmark = c.scheme == Scheme::catmark;
  const double diagonal = diagonal_of(mesh);
  const std::unique_ptr<Far::TopologyRefiner> refiner = far_refiner(c, mesh);
  ASSERT_TRUE(refiner != nullptr);
  const Bfr::RefinerSurfaceFactory<> factory(*refiner);
  Bfr::SurfaceFactory::Options finer_options;
  finer_options.SetApproxLevelSmooth(4);
  const Bfr::RefinerSurfaceFactory<> finer_factory(*refiner, finer_options);
  const int approximation_level = Bfr::SurfaceFactory::Options().GetApproxLevelSmooth();
  std::vector<double> mesh_points;
  for(const Osd_vertex& p : far_points(mesh))
    mesh_points.insert(mesh_points.end(), p.p, p.p + 3);
  Maximum exact_position("bfr_exact_position_error"), exact_derivative("bfr_exact_derivative_error"),
    exact_second("bfr_exact_second_derivative_error"), near_position("bfr_near_extraordinary_position_error"),
    near_normal("bfr_near_extraordinary_normal_error"), finer_position("bfr_level_4_near_extraordinary_position_error");
  std::mt19937 random(1234);
  std::uniform_real_distribution<double> anywhere(0, 1);
  int exact_count = 0, near_count = 0, negated_second = 0;
  int last_face = -1;
  Bfr_face bfr, finer;
  for(const Chart& chart : surface.charts()) {
    if(chart.face != last_face) {
      last_face = chart.face;
      ASSERT_TRUE(bfr.init(factory, chart.face, mesh_points)) << c.name << " face " << chart.face;
      ASSERT_TRUE(finer.init(finer_factory, chart.face, mesh_points)) << c.name << " face " << chart.face;
    }
    const Bfr::Parameterization parameterization = bfr.surface.GetParameterization();
    // Bfr's (s, t) = origin + jacobian (u, v)
    const auto to_bfr = [&](double u, double v) {
      std::array<double, 2> st{u, v};
      if(chart.corner >= 0) {
        const double uv[2] = {u, v};
        parameterization.ConvertNormalizedSubFaceToCoord(chart.corner, uv, st.data());
      }
      return st;
    };
    const std::array<double, 2> o = to_bfr(0, 0), ju = to_bfr(1, 0), jv = to_bfr(0, 1);
    const double j[2][2] = {{ju[0] - o[0], jv[0] - o[0]}, {ju[1] - o[1], jv[1] - o[1]}}; // j[bfr][ours]
    // ours from Bfr's by the chain rule: d/du_a = sum_r j[r][a] d/ds_r
    const auto first = [&](const std::array<Vector, 6>& d, int a) { return d[0] * j[0][a] + d[1] * j[1][a]; };
    const auto second = [&](const std::array<Vector, 6>& d, int a, int b) {
      const Vector dd[2][2] = {{d[2], d[3]}, {d[3], d[4]}};
      Vector total = CGAL::NULL_VECTOR;
      for(int r = 0; r < 2; ++r)
        for(int q = 0; q < 2; ++q)
          total = total + dd[r][q] * (j[r][a] * j[q][b]);
      return total;
    };
    const std::vector<int> approximate_corners = irregular_corners(mesh, c, chart);
    const double square = std::ldexp(1.0, -(approximation_level - (chart.corner >= 0 ? 1 : 0)));
    // whether (u, v) is in the square of an approximate corner
    const auto near_corner = [&](double u, double v) {
      for(const int i : approximate_corners) {
        if(!catmark) {
          const double weight = i == 0 ? 1 - u - v : i == 1 ? u : v; // barycentric
          if(weight > 1 - square)
            return true;
        } else if(std::abs(u - (i == 1 || i == 2 ? 1 : 0)) < square && std::abs(v - (i >= 2 ? 1 : 0)) < square)
          return true;
      }
      return false;
    };
    // uniform samples, then some in each corner square
    std::vector<std::array<double, 2>> samples;
    while(samples.size() < 24) {
      const double u = anywhere(random), v = anywhere(random);
      if(catmark || u + v <= 1)
        samples.push_back({u, v});
    }
    for(const int i : approximate_corners)
      for(int k = 0; k < 6; ++k) {
        const double a = square * anywhere(random), b = square * anywhere(random) * (catmark ? 1 : 1 - a / square);
        if(catmark)
          samples.push_back({i == 1 || i == 2 ? 1 - a : a, i >= 2 ? 1 - b : b});
        else
          samples.push_back(i == 0   ? std::array<double, 2>{a, b}
                            : i == 1 ? std::array<double, 2>{1 - a - b, a}
                                     : std::array<double, 2>{b, 1 - a - b});
      }
    for(const auto& [u, v] : samples) {
      const Sd::Limit_sample s = surface(chart, u, v);
      const std::array<double, 2> st = to_bfr(u, v);
      Point p;
      const std::array<Vector, 6> d = bfr.evaluate(st, p);
      const double position_error = std::sqrt(CGAL::squared_distance(s.position, p)) / diagonal;
      const std::string where = c.name + " face " + std::to_string(chart.face) + " corner " +
                                std::to_string(chart.corner) + " at " + std::to_string(u) + ", " + std::to_string(v);
      if(near_corner(u, v)) {
        ++near_count;
        near_position.add(position_error);
        near_normal.add(length(s.normal - unit(CGAL::cross_product(first(d, 0), first(d, 1)))));
        EXPECT_LT(position_error, 5e-2) << where;
        Point q;
        finer.evaluate(st, q);
        finer_position.add(std::sqrt(CGAL::squared_distance(s.position, q)) / diagonal);
        continue;
      }
      ++exact_count;
      const double derivative_error = (std::max)(length(s.du - first(d, 0)), length(s.dv - first(d, 1))) / diagonal;
      const auto second_error = [&](double sign) {
        return (std::max)({length(s.duu - sign * second(d, 0, 0)), length(s.duv - sign * second(d, 0, 1)),
                           length(s.dvv - sign * second(d, 1, 1))}) /
               diagonal;
      };
      double error2 = second_error(1);
      if(!catmark && second_error(-1) < error2) { // Bfr's negated second derivatives (above)
        ++negated_second;
        error2 = second_error(-1);
        const double h = 1e-6;
        Point ignored;
        const std::array<Vector, 6> ds = bfr.evaluate({st[0] + h, st[1]}, ignored);
        const double difference = length((first(ds, 0) - first(d, 0)) / h - s.duu) / length(s.duu);
        EXPECT_LT(difference, 1e-4) << where;
      }
      exact_position.add(position_error);
      exact_derivative.add(derivative_error);
      exact_second.add(error2);
      EXPECT_LT(position_error, 1e-12) << where;
      EXPECT_LT(derivative_error, 1e-12) << where;
      EXPECT_LT(error2, 1e-12) << where;
    }
  }
  std::cout << "  " << c.name << ": " << exact_count << " parameters where Bfr is exact, " << near_count
            << " near extraordinary corners; Bfr's second derivatives negated at " << negated_second << "\n";
  EXPECT_GT(exact_count, 0);
  if(catmark) {
    EXPECT_EQ(negated_second, 0);
  }
  if(near_count > 0) { // Bfr approaches the limit as it refines further
    EXPECT_LT(finer_position.value(), 0.25 * near_position.value()) << c.name;
  }
}

// Sharpness tags: an infinitely sharp crease across a bumpy 6 x 5 grid of
// quads, from border to border along row 2 (its vertices regular on each
// side: Bfr's patches there are regular boundary patches, exact), given to
// Far (creases of sharpness 10) and to ours (edge_sharpness_map). At random
// parameters of every face away from the grid's four corners (irregular:
// Bfr approximates there) positions and first derivatives agree to 1e-12
// of the diagonal, on the faces along the crease too (which ours refines
// towards the parameter until its patch has no tag).
TEST(LimitSurfaceOsdTags, infinitely_sharp_crease_is_bfr_evaluation)
{
  const Mesh mesh = testing_utils::grid<Mesh>(6, 5, bumpy, false);
  const auto vertex = [](int i, int j) { return 7 * j + i; };
  std::vector<int> crease_ends;
  Mesh tagged = mesh;
  const auto sharpness = tagged.add_property_map<Mesh::Edge_index, float>("e:sharpness", 0.f).first;
  for(int i = 0; i < 6; ++i) {
    crease_ends.insert(crease_ends.end(), {vertex(i, 2), vertex(i + 1, 2)});
    const auto [h, found] =
      CGAL::halfedge(Mesh::Vertex_index(vertex(i, 2)), Mesh::Vertex_index(vertex(i + 1, 2)), tagged);
    ASSERT_TRUE(found);
    sharpness[tagged.edge(h)] = 10.f;
  }
  const Sd::Limit_surface<Mesh, Cc_mask> surface(tagged, Cc_mask(), Sd::parameters::edge_sharpness_map(sharpness));

  std::vector<int> sizes, indices;
  for(const Mesh::Face_index f : faces(tagged)) {
    sizes.push_back(static_cast<int>(tagged.degree(f)));
    for(const Mesh::Halfedge_index h : CGAL::halfedges_around_face(tagged.halfedge(f), tagged))
      indices.push_back(static_cast<int>(tagged.target(h)));
  }
  const std::vector<float> weights(6, 10.f);
  Far::TopologyDescriptor descriptor;
  descriptor.numVertices = static_cast<int>(tagged.number_of_vertices());
  descriptor.numFaces = static_cast<int>(sizes.size());
  descriptor.numVertsPerFace = sizes.data();
  descriptor.vertIndicesPerFace = indices.data();
  descriptor.numCreases = 6;
  descriptor.creaseVertexIndexPairs = crease_ends.data();
  descriptor.creaseWeights = weights.data();
  OpenSubdiv::Sdc::Options options;
  options.SetVtxBoundaryInterpolation(OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  const std::unique_ptr<Far::TopologyRefiner> refiner(
    Factory::Create(descriptor, Factory::Options(OpenSubdiv::Sdc::SCHEME_CATMARK, options)));
  ASSERT_TRUE(refiner != nullptr);
  const Bfr::RefinerSurfaceFactory<> factory(*refiner);
  std::vector<double> mesh_points;
  for(const Osd_vertex& p : far_points(tagged))
    mesh_points.insert(mesh_points.end(), p.p, p.p + 3);

  const double diagonal = diagonal_of(tagged);
  Maximum position("bfr_crease_position_error"), derivative("bfr_crease_derivative_error");
  std::mt19937 random(4321);
  std::uniform_real_distribution<double> anywhere(0, 1);
  int compared = 0, along_crease = 0;
  for(const Mesh::Face_index f : faces(tagged)) {
    bool at_grid_corner = false, on_crease = false;
    for(const Mesh::Vertex_index w : CGAL::vertices_around_face(tagged.halfedge(f), tagged)) {
      at_grid_corner = at_grid_corner || tagged.degree(w) == 2;
      on_crease = on_crease || std::find(crease_ends.begin(), crease_ends.end(), int(w)) != crease_ends.end();
    }
    if(at_grid_corner)
      continue;
    Bfr_face bfr;
    ASSERT_TRUE(bfr.init(factory, int(f), mesh_points));
    for(int k = 0; k < 20; ++k) {
      const double u = anywhere(random), v = anywhere(random);
      const Sd::Limit_sample s = surface.evaluate(f, u, v);
      Point p;
      const std::array<Vector, 6> d = bfr.evaluate({u, v}, p);
      const double e = std::sqrt(CGAL::squared_distance(s.position, p)) / diagonal;
      const double de = (std::max)(length(s.du - d[0]), length(s.dv - d[1])) / diagonal;
      position.add(e);
      derivative.add(de);
      EXPECT_LT(e, 1e-12) << "face " << f << " at " << u << ", " << v;
      EXPECT_LT(de, 1e-12) << "face " << f << " at " << u << ", " << v;
      ++compared;
      along_crease += on_crease ? 1 : 0;
    }
  }
  EXPECT_GT(along_crease, 200);
  EXPECT_GT(compared, along_crease);
}

#else
TEST(LimitSurfaceOsdDependencies, opensubdiv_is_installed)
{
  FAIL() << "OpenSubdiv (Debian's libosd-dev) was not found when the tests were configured: the comparison with "
            "Far and Bfr needs it (bash src/scripts/quickstart.sh deps --with-peers installs it)";
}
#endif

INSTANTIATE_TEST_SUITE_P(Meshes, LimitSurfaceOsd, testing::ValuesIn(every_case()),
                         [](const testing::TestParamInfo<Case>& info) { return info.param.name; });

} // namespace
