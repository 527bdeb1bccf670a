// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: how far two libraries' refined points are from each other.
// The libraries number the new vertices differently, so the points are paired
// by position: each point of `a` with the nearest point of `b` within
// 1e-6 * diagonal (found through a hash grid of that cell size).
#ifndef SUBDIV_BENCH_AGREEMENT_H
#define SUBDIV_BENCH_AGREEMENT_H

#include "bench.h"

#include <string>
#include <vector>

namespace subdiv_bench {

struct Agreement
{
  bool same_count = false;   // as many points in both
  std::size_t unmatched = 0; // points of `a` with no point of `b` within 1e-6 * diagonal
  double max_relative = 0;   // largest distance between paired points / diagonal
};

Agreement compare_points(const std::vector<P3>& a, const std::vector<P3>& b, double diagonal);

/// "3.1e-16", "2 of 1000 points unmatched", "1000 vs 998 points"
std::string describe(const Agreement& agreement, std::size_t a_size, std::size_t b_size);

} // namespace subdiv_bench

#endif // SUBDIV_BENCH_AGREEMENT_H
