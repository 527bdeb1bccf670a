// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: the speed baseline of CGAL Subdiv's surface schemes against
// CGAL's own Subdivision_method_3, in one process, on the same inputs.
//
//   build/src/subdiv-bench [--runs N] [--quick]
//
// Inputs (made here, outside any timer):
//   - an irregular closed triangle torus, about 20,000 faces: a torus grid whose
//     quads are split along random diagonals, then random edge flips
//     (CGAL::Euler::flip_edge) so that valences range over 3..9;
//   - a closed quad torus grid of 200,000 faces.
// For each scheme both libraries have (Loop, Catmull-Clark, Doo-Sabin, sqrt3)
// and each level count, both run on copies of the same mesh (copies made
// outside the timer): one warm-up run each, then N (default 5) timed runs each,
// interleaved; the minimum counts. Ratio = ours / CGAL; "SLOWER" marks a
// ratio above 1.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/internal/mesh_checks.h>
#include <CGAL/Subdiv/surface_subdivision.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

// Ours: a scheme whose wrapper is not in surface_subdivision.h yet resolves to
// this fallback, and the bench says so instead of failing to build. It lives
// in a namespace at global scope, like CGAL::Subdiv, so that the using-directives
// below make both visible in the same scope and overload resolution picks.
namespace subdiv_bench_fallback {
struct Not_available
{
};
template <class... Args>
Not_available loop_subdivision(Args&&...) { return {}; }
template <class... Args>
Not_available catmull_clark_subdivision(Args&&...) { return {}; }
template <class... Args>
Not_available doo_sabin_subdivision(Args&&...) { return {}; }
template <class... Args>
Not_available sqrt3_subdivision(Args&&...) { return {}; }
} // namespace subdiv_bench_fallback

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using vertex_descriptor = Mesh::Vertex_index;

// --- the inputs ------------------------------------------------------------------

Point torus_point(double u, double v, double R, double r)
{
  return Point((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
}

// an nu x nv torus grid of quads, or of triangles along random diagonals
Mesh torus(int nu, int nv, bool triangles, std::mt19937& random)
{
  const double pi = 3.14159265358979323846;
  Mesh mesh;
  std::vector<vertex_descriptor> v(static_cast<std::size_t>(nu * nv));
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j) {
      const double du = triangles ? jitter(random) : 0, dv = triangles ? jitter(random) : 0;
      v[static_cast<std::size_t>(i * nv + j)] =
        mesh.add_vertex(torus_point(2 * pi * (i + du) / nu, 2 * pi * (j + dv) / nv, 1.0, 0.4));
    }
  const auto at = [&](int i, int j) { return v[static_cast<std::size_t>((i % nu) * nv + (j % nv))]; };
  std::bernoulli_distribution coin(0.5);
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j) {
      const vertex_descriptor a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if(!triangles) {
        mesh.add_face(a, b, c, d);
      } else if(coin(random)) {
        mesh.add_face(a, b, c);
        mesh.add_face(a, c, d);
      } else {
        mesh.add_face(a, b, d);
        mesh.add_face(b, c, d);
      }
    }
  return mesh;
}

// random edge flips that keep every valence within 3..9
void flip_randomly(Mesh& mesh, double probability, std::mt19937& random)
{
  std::vector<Mesh::Edge_index> edges(mesh.edges().begin(), mesh.edges().end());
  std::shuffle(edges.begin(), edges.end(), random);
  std::bernoulli_distribution flip(probability);
  for(const Mesh::Edge_index e : edges) {
    if(!flip(random))
      continue;
    const Mesh::Halfedge_index h = mesh.halfedge(e), o = mesh.opposite(h);
    const vertex_descriptor a = mesh.source(h), b = mesh.target(h);
    const vertex_descriptor c = mesh.target(mesh.next(h)), d = mesh.target(mesh.next(o));
    if(c == d || CGAL::halfedge(c, d, mesh).second)
      continue;
    if(mesh.degree(a) <= 3 || mesh.degree(b) <= 3 || mesh.degree(c) >= 9 || mesh.degree(d) >= 9)
      continue;
    CGAL::Euler::flip_edge(h, mesh);
  }
}

std::string valence_range(const Mesh& mesh)
{
  unsigned low = 1000, high = 0;
  for(const vertex_descriptor v : mesh.vertices()) {
    low = std::min(low, mesh.degree(v));
    high = std::max(high, mesh.degree(v));
  }
  return std::to_string(low) + ".." + std::to_string(high);
}

// --- the schemes ------------------------------------------------------------------


// false if ours is not available; the arguments are lvalues of the wrappers'
// exact parameter types, so the real wrapper (more specialised) wins when it exists
#define SUBDIV_BENCH_OURS(function)                                                                  \
  [](Mesh& mesh, int levels) {                                                                       \
    using namespace CGAL::Subdiv;                                                                    \
    using namespace subdiv_bench_fallback;                                                           \
    const auto np = CGAL::parameters::number_of_iterations(levels);                                  \
    using Result = decltype(function(mesh, np));                                                     \
    constexpr bool available = !std::is_same<Result, subdiv_bench_fallback::Not_available>::value; \
    return available ? (function(mesh, np), true) : false;                                           \
  }

struct Scheme
{
  std::string name;
  bool triangles_only;
  std::function<bool(Mesh&, int)> ours; // false: not available
  std::function<void(Mesh&, int)> cgal;
};

template <class F>
std::function<void(Mesh&, int)> cgal_method(F f)
{
  return [f](Mesh& mesh, int levels) { f(mesh, CGAL::parameters::number_of_iterations(levels)); };
}

std::vector<Scheme> schemes()
{
  namespace SM = CGAL::Subdivision_method_3;
  return {
    {"Loop", true, SUBDIV_BENCH_OURS(loop_subdivision),
     cgal_method([](Mesh& m, const auto& np) { SM::Loop_subdivision(m, np); })},
    {"Catmull-Clark", false, SUBDIV_BENCH_OURS(catmull_clark_subdivision),
     cgal_method([](Mesh& m, const auto& np) { SM::CatmullClark_subdivision(m, np); })},
    {"Doo-Sabin", false, SUBDIV_BENCH_OURS(doo_sabin_subdivision),
     cgal_method([](Mesh& m, const auto& np) { SM::DooSabin_subdivision(m, np); })},
    {"sqrt3", true, SUBDIV_BENCH_OURS(sqrt3_subdivision),
     cgal_method([](Mesh& m, const auto& np) { SM::Sqrt3_subdivision(m, np); })},
  };
}

// --- timing ------------------------------------------------------------------------

using Clock = std::chrono::steady_clock;

// runs `f` on a copy of `input` made outside the timer; the result is freed
// outside the timer too. Returns seconds, and the result's face count.
template <class F>
double timed_run(const Mesh& input, const F& f, std::size_t& faces, Point& centroid)
{
  Mesh mesh = input;
  const auto start = Clock::now();
  f(mesh);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  faces = mesh.number_of_faces();
  double x = 0, y = 0, z = 0;
  for(const vertex_descriptor v : mesh.vertices()) {
    x += mesh.point(v).x();
    y += mesh.point(v).y();
    z += mesh.point(v).z();
  }
  const double n = static_cast<double>(std::max<std::size_t>(1, mesh.number_of_vertices()));
  centroid = Point(x / n, y / n, z / n);
  return seconds;
}

struct Input
{
  std::string name;
  Mesh mesh;
  bool triangles;
  int max_levels;
};

} // namespace

int main(int argc, char** argv)
{
  int runs = 5;
  bool quick = false;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if(arg == "--runs" && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if(arg == "--quick") {
      quick = true;
    } else {
      std::printf("usage: subdiv-bench [--runs N] [--quick]\n\n"
                  "Times CGAL Subdiv's Loop, Catmull-Clark, Doo-Sabin and sqrt3 against CGAL's\n"
                  "Subdivision_method_3 on a ~20k-face irregular triangle torus and a 200k-face quad\n"
                  "torus: minimum of N runs (default 5) after a warm-up. --quick: inputs 10x smaller.\n");
      return arg == "-h" || arg == "--help" ? 0 : 2;
    }
  }

  std::mt19937 random(20261122);
  std::vector<Input> inputs;
  {
    Mesh triangles = quick ? torus(32, 32, true, random) : torus(100, 100, true, random);
    flip_randomly(triangles, 0.3, random);
    const std::string range = valence_range(triangles);
    inputs.push_back(Input{"tri torus " + std::to_string(triangles.number_of_faces()) + " F (valence " + range + ")",
                           std::move(triangles), true, 3});
    Mesh quads = quick ? torus(100, 200, false, random) : torus(500, 400, false, random);
    inputs.push_back(Input{"quad torus " + std::to_string(quads.number_of_faces()) + " F", std::move(quads), false, 2});
  }
  for(const Input& input : inputs)
    if(!CGAL::is_valid_polygon_mesh(input.mesh) || !CGAL::is_closed(input.mesh)) {
      std::printf("subdiv-bench: the input '%s' is not a valid closed mesh\n", input.name.c_str());
      return 1;
    }

  std::printf("subdiv-bench: minimum of %d runs after a warm-up, copies made outside the timer%s\n\n", runs,
              quick ? " (--quick: small inputs)" : "");
  std::printf("| scheme | input | levels | output faces | ours (s) | CGAL (s) | ours/CGAL | |\n"
              "|---|---|---:|---:|---:|---:|---:|---|\n");
  std::fflush(stdout);
  std::vector<std::string> slower, unavailable, disagreements;
  for(const Scheme& scheme : schemes()) {
    {
      Mesh probe = inputs.front().mesh;
      if(!scheme.ours(probe, 0)) {
        unavailable.push_back(scheme.name);
        continue;
      }
    }
    for(const Input& input : inputs) {
      if(scheme.triangles_only && !input.triangles)
        continue;
      for(int levels = 1; levels <= input.max_levels; ++levels) {
        const auto ours = [&](Mesh& m) { scheme.ours(m, levels); };
        const auto cgal = [&](Mesh& m) { scheme.cgal(m, levels); };
        std::size_t ours_faces = 0, cgal_faces = 0;
        Point ours_centroid, cgal_centroid;
        timed_run(input.mesh, ours, ours_faces, ours_centroid); // warm-up
        timed_run(input.mesh, cgal, cgal_faces, cgal_centroid);
        double best_ours = 1e300, best_cgal = 1e300;
        for(int r = 0; r < runs; ++r) {
          best_ours = std::min(best_ours, timed_run(input.mesh, ours, ours_faces, ours_centroid));
          best_cgal = std::min(best_cgal, timed_run(input.mesh, cgal, cgal_faces, cgal_centroid));
        }
        const double ratio = best_ours / best_cgal;
        const bool agree =
          ours_faces == cgal_faces && std::sqrt(CGAL::squared_distance(ours_centroid, cgal_centroid)) < 1e-6;
        std::printf("| %s | %s | %d | %zu | %.3f | %.3f | %.2f | %s%s |\n", scheme.name.c_str(), input.name.c_str(),
                    levels, ours_faces, best_ours, best_cgal, ratio, ratio > 1 ? "SLOWER" : "",
                    agree ? "" : " (results differ from CGAL's)");
        std::fflush(stdout);
        if(ratio > 1)
          slower.push_back(scheme.name + " on " + input.name + ", " + std::to_string(levels) + " level(s): " +
                           std::to_string(ratio).substr(0, 4) + "x CGAL's time");
        if(!agree)
          disagreements.push_back(scheme.name + " on " + input.name + ", " + std::to_string(levels) +
                                  " level(s): " + std::to_string(ours_faces) + " faces against " +
                                  std::to_string(cgal_faces) + ", or another centroid");
      }
    }
  }
  // what every call of ours spends on checking its input, for reading the level-1 rows
  std::printf("\nour input check alone (CGAL::Subdiv::internal::check_mesh, part of every call above):\n");
  for(const Input& input : inputs) {
    double best = 1e300;
    for(int r = 0; r <= runs; ++r) {
      const auto start = Clock::now();
      CGAL::Subdiv::internal::check_mesh(input.mesh, get(CGAL::vertex_point, input.mesh), "bench", 0);
      best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
    }
    std::printf("  %s: %.4f s\n", input.name.c_str(), best);
  }
  std::printf("\n");
  for(const std::string& name : unavailable)
    std::printf("not yet available in CGAL Subdiv, not timed: %s\n", name.c_str());
  for(const std::string& line : slower)
    std::printf("SLOWER: %s\n", line.c_str());
  for(const std::string& line : disagreements)
    std::printf("DIFFERENT RESULT: %s\n", line.c_str());
  if(slower.empty() && unavailable.size() < schemes().size())
    std::printf("ours is at least as fast as CGAL's in every row\n");
  return 0;
}
