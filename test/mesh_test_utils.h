// Helpers shared by the surface tests.
#ifndef CGAL_SUBDIV_TEST_MESH_TEST_UTILS_H
#define CGAL_SUBDIV_TEST_MESH_TEST_UTILS_H

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/number_utils.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace testing_utils {

using Double_point = CGAL::Simple_cartesian<double>::Point_3;

/// path of a file bundled with the tests, in test/data (test/data/LICENSE-NOTICES.md
/// says where each comes from): `test_mesh("cgal/tetrahedron.off")` is the same file
/// as `shared_mesh("cgal/tetrahedron.off")`, present in every clone
inline std::string test_mesh(const std::string& name)
{
  return std::string(SUBDIV_TEST_DATA_DIR) + "/" + name;
}

/// path of a file in ../shared/data/meshes
inline std::string shared_mesh(const std::string& name)
{
  return std::string(SUBDIV_SHARED_DATA_DIR) + "/meshes/" + name;
}

/// true when ../shared/data is beside the checkout (tests that need it skip otherwise)
inline bool have_shared_data()
{
  return std::ifstream(shared_mesh("SOURCES.md")).good();
}

/// true when the running test has "shared" in its name, as every test that
/// needs ../shared/data must: test/CMakeLists.txt gives those the ctest label shared-data
inline bool test_name_says_shared()
{
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return info && std::string(info->name()).find("shared") != std::string::npos;
}

/// skips the test without ../shared/data (a plain clone); the test's name has
/// "shared" in it (ctest label shared-data), or it fails
#define SUBDIV_REQUIRE_SHARED_DATA()                                                            \
  ASSERT_TRUE(testing_utils::test_name_says_shared())                                           \
    << "a test that needs ../shared/data has \"shared\" in its name (ctest label shared-data)"; \
  if(!testing_utils::have_shared_data())                                                        \
  GTEST_SKIP() << "../shared/data is not beside the checkout"

template <class Mesh>
std::vector<Double_point> double_points(const Mesh& mesh)
{
  std::vector<Double_point> points;
  for(auto v : vertices(mesh)) {
    const auto& p = get(CGAL::vertex_point, mesh, v);
    points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  return points;
}

inline double diagonal(const std::vector<Double_point>& points)
{
  const auto box = CGAL::bbox_3(points.begin(), points.end());
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

/// largest distance from a point of `a` to the nearest point of `b`, relative
/// to the bounding-box diagonal of `b`: vertices are matched by position, not
/// by order. Assumes the two point sets are close (searches a thin x-slab).
inline double position_mismatch(const std::vector<Double_point>& a, std::vector<Double_point> b)
{
  std::sort(b.begin(), b.end());
  const double d = diagonal(b);
  const double slab = 1e-6 * d;
  double worst = 0;
  for(const Double_point& p : a) {
    double best = 1e300;
    for(auto it = std::lower_bound(b.begin(), b.end(), Double_point(p.x() - slab, -1e300, -1e300));
        it != b.end() && it->x() <= p.x() + slab; ++it)
      best = (std::min)(best, CGAL::squared_distance(*it, p));
    worst = (std::max)(worst, std::sqrt(best));
  }
  return worst / d;
}

/// both ways: every vertex of each mesh has a partner in the other
template <class MeshA, class MeshB>
double position_mismatch(const MeshA& a, const MeshB& b)
{
  const auto pa = double_points(a), pb = double_points(b);
  return (std::max)(position_mismatch(pa, pb), position_mismatch(pb, pa));
}

/// reads the `v` and `f` lines of an OBJ file (OpenSubdiv's shapes carry `vt`,
/// `vn` and `t` tag lines that CGAL's reader does not expect); false on failure
template <class Mesh>
bool read_obj_positions(const std::string& path, Mesh& mesh)
{
  using Point =
    typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
  std::ifstream in(path);
  if(!in)
    return false;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  std::string line;
  while(std::getline(in, line)) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if(tag == "v") {
      double x, y, z;
      words >> x >> y >> z;
      points.emplace_back(x, y, z);
    } else if(tag == "f") {
      std::vector<std::size_t> face;
      std::string corner;
      while(words >> corner)
        face.push_back(std::stoul(corner.substr(0, corner.find('/'))) - 1);
      faces.push_back(face);
    }
  }
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(faces))
    return false;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, mesh);
  return true;
}

/// reads an OFF/PLY/... file with CGAL's reader, an OBJ file with
/// read_obj_positions(); false on failure
template <class Mesh>
bool read_mesh(const std::string& path, Mesh& mesh)
{
  const bool obj = path.size() > 4 && path.substr(path.size() - 4) == ".obj";
  return obj ? read_obj_positions(path, mesh) : CGAL::IO::read_polygon_mesh(path, mesh);
}

/// the bundled mesh `name` (test_mesh()); a failed read is a test failure
template <class Mesh>
Mesh bundled(const std::string& name)
{
  Mesh mesh;
  EXPECT_TRUE(read_mesh(test_mesh(name), mesh)) << test_mesh(name);
  return mesh;
}

/// the points of a Surface_mesh, in the order of its vertices
template <class M>
std::vector<typename M::Point> points_of(const M& mesh)
{
  std::vector<typename M::Point> points;
  for(auto v : vertices(mesh))
    points.push_back(mesh.point(v));
  return points;
}

/// same points in the same order, and the same faces with the same corners
template <class M>
bool same_mesh(const M& a, const M& b)
{
  if(points_of(a) != points_of(b) || num_faces(a) != num_faces(b))
    return false;
  for(auto f : faces(a)) {
    std::vector<std::size_t> fa, fb;
    for(auto v : CGAL::vertices_around_face(halfedge(f, a), a))
      fa.push_back(v.idx());
    for(auto v : CGAL::vertices_around_face(halfedge(f, b), b))
      fb.push_back(v.idx());
    if(fa != fb)
      return false;
  }
  return true;
}

/// the message of the Bad_input that `call` throws, or "no exception"
template <class Call>
std::string bad_input_message(const Call& call)
{
  try {
    call();
  } catch(const CGAL::Subdiv::Bad_input& e) {
    return e.what();
  }
  return "no exception";
}

} // namespace testing_utils

#endif // CGAL_SUBDIV_TEST_MESH_TEST_UTILS_H
