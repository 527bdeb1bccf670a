// Tests about several threads: without TBB (CGAL_LINKED_WITH_TBB undefined),
// threads(n) runs in one thread, so such a test would only compare one thread
// with one thread; it reports itself skipped instead.
#ifndef CGAL_SUBDIV_TEST_THREADS_TEST_UTILS_H
#define CGAL_SUBDIV_TEST_THREADS_TEST_UTILS_H

#include <gtest/gtest.h>

#ifdef CGAL_LINKED_WITH_TBB
#define SUBDIV_REQUIRE_THREADS() static_cast<void>(0)
#else
#define SUBDIV_REQUIRE_THREADS() \
  GTEST_SKIP() << "built without TBB (CGAL_LINKED_WITH_TBB undefined): threads(n) runs in one thread"
#endif

#endif // CGAL_SUBDIV_TEST_THREADS_TEST_UTILS_H
