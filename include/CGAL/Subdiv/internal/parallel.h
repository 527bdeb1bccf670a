// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_PARALLEL_H
#define CGAL_SUBDIV_INTERNAL_PARALLEL_H

#include <CGAL/Subdiv/parameters.h>

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>
#endif

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * How the fast paths run their loops: `threads == 1` runs every loop in the
 * calling thread; otherwise, when the package is compiled with TBB
 * (CGAL_LINKED_WITH_TBB, the CMake option SUBDIV_WITH_TBB), loops are split
 * into chunks run by TBB: `threads == 0` uses TBB's default (all cores, or
 * what a `tbb::global_control` allows), `threads > 1` at most that many.
 * Every parallel loop of the package writes each output element from exactly
 * one iteration, computed as the sequential loop computes it, so the results
 * are the same bit for bit with any number of threads.
 */
class Parallel_loop
{
public:
  explicit Parallel_loop(int threads = 1) : m_threads(threads < 0 ? 1 : threads)
  {
#ifdef CGAL_LINKED_WITH_TBB
    // one arena for all the loops of this object (and its copies): a worker
    // joins an arena that is already there at once, a new one often late
    if(m_threads > 1)
      m_arena = std::make_shared<tbb::task_arena>(m_threads);
#endif
  }

  int threads() const
  {
    return m_threads;
  }

  bool is_parallel() const
  {
#ifdef CGAL_LINKED_WITH_TBB
    return m_threads != 1;
#else
    return false;
#endif
  }

  /// calls f(begin, end) on chunks that cover [0, n), each chunk at least
  /// `grain` long (but the last); in this thread when sequential
  template <class F>
  void for_range(std::size_t n, std::size_t grain, const F& f) const
  {
    if(n == 0)
      return;
#ifdef CGAL_LINKED_WITH_TBB
    if(is_parallel() && n > grain) {
      run([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                          [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
      });
      return;
    }
#endif
    (void)grain;
    f(std::size_t(0), n);
  }

  /// runs f() in an arena of `threads` threads (or in TBB's default one);
  /// a loop made by `in_arena()` runs f() where it is called
  template <class F>
  void run(const F& f) const
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(m_arena && !m_in_arena) {
      m_arena->execute(f);
      return;
    }
#endif
    f();
  }

  /// the same loop, for calls from inside its own `run()`: its loops join
  /// the arena they are called from instead of making one of their own, so
  /// that the threads of `run()` take part in them
  Parallel_loop in_arena() const
  {
    Parallel_loop inner = *this;
    inner.m_in_arena = true;
    return inner;
  }

  /// calls a() and b(), side by side when parallel, in the arena of `run()`:
  /// a() as a task the other threads take (its parallel loops in chunks), b()
  /// in this thread, which then helps with what is left of a(); so b() should
  /// be the sequential part, and nothing waits for a thread that comes late
  /// or not at all
  template <class A, class B>
  void invoke(const A& a, const B& b) const
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(is_parallel()) {
      run([&] {
        tbb::task_group group;
        group.run([&] { a(); });
        b();
        group.wait();
      });
      return;
    }
#endif
    a();
    b();
  }

private:
  int m_threads;
  bool m_in_arena = false;
#ifdef CGAL_LINKED_WITH_TBB
  std::shared_ptr<tbb::task_arena> m_arena;
#endif
};

/// one T per thread (scratch space of parallel loops), found by the thread's
/// index in its TBB arena (a cheap look-up, done once per element)
template <class T>
class Per_thread
{
public:
  Per_thread()
  {
#ifdef CGAL_LINKED_WITH_TBB
    m_values.resize(static_cast<std::size_t>(tbb::info::default_concurrency()) + 1);
#else
    m_values.resize(1);
#endif
  }

  T& local()
  {
#ifdef CGAL_LINKED_WITH_TBB
    const int index = tbb::this_task_arena::current_thread_index();
    if(index >= 0 && static_cast<std::size_t>(index) < m_values.size())
      return m_values[static_cast<std::size_t>(index)].value;
    return m_others.local();
#else
    return m_values[0].value;
#endif
  }

private:
  // each thread's value on cache lines of its own: scratch members written
  // for every term (sizes, vector ends) would otherwise bounce between the
  // cores (false sharing); 128 bytes, as the adjacent-line prefetch pairs lines
  struct alignas(128) Slot
  {
    T value;
  };
  std::vector<Slot> m_values;
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<T> m_others; // threads beyond the default concurrency
#endif
};

template <class NamedParameters>
Parallel_loop parallel_loop(const NamedParameters& np)
{
  return Parallel_loop(parameters::choose_parameter(parameters::get_parameter(np, threads_t()), 1));
}

} // namespace internal

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_PARALLEL_H
