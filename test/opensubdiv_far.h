// Helpers for the tests that compare with OpenSubdiv (Debian's libosd-dev),
// built only when test/CMakeLists.txt found it (SUBDIV_TEST_WITH_OSD).
#ifndef CGAL_SUBDIV_TEST_OPENSUBDIV_FAR_H
#define CGAL_SUBDIV_TEST_OPENSUBDIV_FAR_H

namespace testing_utils {

/// a point as OpenSubdiv Far's PrimvarRefiner takes it (Clear, AddWithWeight), in double
struct Osd_vertex
{
  double p[3];
  void Clear() { p[0] = p[1] = p[2] = 0; }
  void AddWithWeight(const Osd_vertex& v, double w)
  {
    for(int i = 0; i < 3; ++i)
      p[i] += w * v.p[i];
  }
};

} // namespace testing_utils

#endif // CGAL_SUBDIV_TEST_OPENSUBDIV_FAR_H
