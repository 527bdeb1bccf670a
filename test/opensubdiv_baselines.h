// OpenSubdiv's Hbr reference results, shared by the Loop and Catmull-Clark
// tests: opensubdiv_hbr_baseline/<shape>_levelN.obj holds N+1 uniform steps of
// opensubdiv/<shape>.obj (checked here by the counts), printed with 6
// significant digits from single-precision floats.
#ifndef CGAL_SUBDIV_TEST_OPENSUBDIV_BASELINES_H
#define CGAL_SUBDIV_TEST_OPENSUBDIV_BASELINES_H

#include <CGAL/Subdiv/hosts/hosts.h>
#include <CGAL/Subdiv/subdivide.h>
#include <CGAL/Subdiv/views/Vertex_view.h>

#include <gtest/gtest.h>

#include "mesh_test_utils.h"

#include <string>

namespace testing_utils {

struct Opensubdiv_case
{
  std::string shape;
  CGAL::Subdiv::Border_corners corners;
  int last_level; // the last baseline compared
};

/// refines opensubdiv/<shape>.obj level by level with `Mask(c.corners)` and
/// compares every level up to `c.last_level` with the baseline, matching
/// vertices by position: every point within `tolerance` of one of the other
/// mesh's and back (`path` is test_mesh or shared_mesh)
template <class Mask, class Mesh>
void expect_opensubdiv_results(const Opensubdiv_case& c, std::string (*path)(const std::string&), double tolerance)
{
  Mesh mesh;
  ASSERT_TRUE(read_mesh(path("opensubdiv/" + c.shape + ".obj"), mesh)) << c.shape;
  for(int level = 0; level <= c.last_level; ++level) {
    CGAL::Subdiv::subdivide(mesh, Mask(c.corners));
    Mesh reference;
    ASSERT_TRUE(
      read_mesh(path("opensubdiv_hbr_baseline/" + c.shape + "_level" + std::to_string(level) + ".obj"), reference));
    ASSERT_EQ(num_vertices(mesh), num_vertices(reference)) << c.shape << " level " << level;
    ASSERT_EQ(num_faces(mesh), num_faces(reference)) << c.shape << " level " << level;
    EXPECT_LT(position_mismatch(mesh, reference), tolerance) << c.shape << " level " << level;
  }
}

} // namespace testing_utils

#endif // CGAL_SUBDIV_TEST_OPENSUBDIV_BASELINES_H
