// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: the named parameters of every call of ours. The library's
// default may be "all cores" one day, so every call passes its thread count.
#ifndef SUBDIV_BENCH_THREADS_PARAMETER_H
#define SUBDIV_BENCH_THREADS_PARAMETER_H

#include <CGAL/Subdiv/parameters.h>

namespace subdiv_bench {

/// CGAL Subdiv has the named parameter `threads`
constexpr bool has_threads = true;

/// `levels` levels with `threads` threads
inline auto ours_parameters(int levels, int threads)
{
  return CGAL::Subdiv::parameters::number_of_iterations(levels).threads(threads);
}

} // namespace subdiv_bench

#endif // SUBDIV_BENCH_THREADS_PARAMETER_H
