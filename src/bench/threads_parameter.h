// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: whether CGAL Subdiv has the named parameter
// `CGAL::Subdiv::threads(n, np)` (its multi-threaded paths). If not, the
// fallback below is the only `threads` found, and the bench times ours in one
// thread only. Where it exists the library's default may be "all cores", so
// every call of ours in the bench passes threads(1) or threads(2).
#ifndef SUBDIV_BENCH_THREADS_PARAMETER_H
#define SUBDIV_BENCH_THREADS_PARAMETER_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Subdiv/subdivide.h>

#include <type_traits>

namespace subdiv_bench_fallback {
struct No_threads_parameter
{};
template <class... Args>
No_threads_parameter threads(Args&&...)
{
  return {};
}
} // namespace subdiv_bench_fallback

namespace subdiv_bench {

template <class NP>
auto threads_call(int n, const NP& np)
{
  using namespace CGAL::Subdiv;
  using namespace subdiv_bench_fallback;
  return threads(n, np);
}

constexpr bool has_threads = !std::is_same<decltype(threads_call(1, CGAL::parameters::default_values())),
                                           subdiv_bench_fallback::No_threads_parameter>::value;

/// np with `threads(n)` added when the library has it
template <class NP>
auto with_threads(int n, const NP& np)
{
  if constexpr(has_threads)
    return threads_call(n, np);
  else
    return np;
}

} // namespace subdiv_bench

#endif // SUBDIV_BENCH_THREADS_PARAMETER_H
