// Every mesh of ../shared/data/meshes through every applicable scheme: a valid
// refined mesh or a clear Bad_input, never a crash, and a refused call leaves
// the mesh unchanged.
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include "mesh_test_utils.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace S = CGAL::Subdiv;
using K = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

namespace {

struct Scheme
{
  std::string name;
  std::function<void(Mesh&)> run;
};

std::vector<Scheme> schemes()
{
  const auto one = CGAL::parameters::number_of_iterations(1);
  return {{"loop", [=](Mesh& m) { S::loop_subdivision(m, one); }},
          {"loop-warren", [=](Mesh& m) { S::loop_warren_subdivision(m, one); }},
          {"catmull-clark", [=](Mesh& m) { S::catmull_clark_subdivision(m, one); }},
          {"doo-sabin", [=](Mesh& m) { S::doo_sabin_subdivision(m, one); }},
          {"sqrt3", [=](Mesh& m) { S::sqrt3_subdivision(m, one); }},
          {"butterfly", [=](Mesh& m) { S::butterfly_subdivision(m, one); }},
          {"modified-butterfly", [=](Mesh& m) { S::modified_butterfly_subdivision(m, one); }},
          {"interpolating-sqrt3", [=](Mesh& m) { S::interpolating_sqrt3_subdivision(m, one); }},
          {"linear", [=](Mesh& m) { S::linear_subdivision(m, one); }}};
}

// what a user gets from a file: CGAL's reader, or else the polygon soup made
// into a mesh where that is possible (OpenSubdiv's OBJ files carry tags)
bool load(const std::string& path, Mesh& mesh)
{
  if(CGAL::IO::read_polygon_mesh(path, mesh) && !faces(mesh).empty())
    return true;
  mesh.clear();
  return testing_utils::read_obj_positions(path, mesh) && !faces(mesh).empty();
}

bool all_points_finite(const Mesh& mesh)
{
  for(auto v : vertices(mesh)) {
    const K::Point_3& p = mesh.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return false;
  }
  return true;
}

} // namespace

TEST(Sweep, every_shared_mesh_through_every_scheme_gives_a_mesh_or_a_clear_error)
{
  SUBDIV_REQUIRE_SHARED_DATA();
  std::size_t files = 0, refined = 0, refused = 0;
  for(const auto& entry : std::filesystem::recursive_directory_iterator(testing_utils::shared_mesh(""))) {
    const std::string ext = entry.path().extension().string();
    if(ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".stl")
      continue;
    Mesh input;
    if(!load(entry.path().string(), input))
      continue; // not a polygon mesh at all (non-manifold soups): the CLI reports those
    ++files;
    for(const Scheme& scheme : schemes()) {
      Mesh mesh = input;
      try {
        scheme.run(mesh);
        ++refined;
        EXPECT_TRUE(mesh.is_valid(false)) << scheme.name << " on " << entry.path();
        EXPECT_TRUE(all_points_finite(mesh)) << scheme.name << " on " << entry.path();
        // (Doo-Sabin on a single open face makes one face again)
        EXPECT_GE(num_faces(mesh), num_faces(input)) << scheme.name << " on " << entry.path();
      } catch(const S::Bad_input& e) {
        ++refused;
        EXPECT_GT(std::string(e.what()).size(), 10u);
        if(std::getenv("SUBDIV_SWEEP_VERBOSE"))
          std::cout << scheme.name << " refused " << entry.path().filename() << ": " << e.what() << "\n";
        EXPECT_EQ(num_faces(mesh), num_faces(input)) << scheme.name << " changed " << entry.path();
        EXPECT_EQ(num_vertices(mesh), num_vertices(input)) << scheme.name << " changed " << entry.path();
      }
    }
  }
  std::cout << files << " meshes, " << refined << " refined, " << refused << " refused with a message\n";
  EXPECT_GT(files, 200u);
  EXPECT_GT(refined, refused);
}

TEST(Sweep, linear_subdivision_splits_triangles_1_to_4_and_other_meshes_into_quads)
{
  Mesh triangle, quad;
  const auto a = triangle.add_vertex(K::Point_3(0, 0, 0)), b = triangle.add_vertex(K::Point_3(2, 0, 0)),
             c = triangle.add_vertex(K::Point_3(0, 2, 0));
  triangle.add_face(a, b, c);
  S::linear_subdivision(triangle);
  EXPECT_EQ(num_faces(triangle), 4u);
  EXPECT_EQ(num_vertices(triangle), 6u);
  const auto p = quad.add_vertex(K::Point_3(0, 0, 0)), q = quad.add_vertex(K::Point_3(2, 0, 0)),
             r = quad.add_vertex(K::Point_3(2, 2, 0)), s = quad.add_vertex(K::Point_3(0, 2, 0));
  quad.add_face(p, q, r, s);
  S::linear_subdivision(quad);
  EXPECT_EQ(num_faces(quad), 4u);
  EXPECT_EQ(num_vertices(quad), 9u);
  bool centre = false;
  for(auto v : vertices(quad))
    centre = centre || quad.point(v) == K::Point_3(1, 1, 0);
  EXPECT_TRUE(centre);
}
