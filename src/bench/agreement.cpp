// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: pairing refined points by position (see agreement.h).
#include "agreement.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <unordered_map>

namespace subdiv_bench {

Agreement compare_points(const std::vector<P3>& a, const std::vector<P3>& b, double diagonal)
{
  Agreement result;
  result.same_count = a.size() == b.size();
  if(a.empty() || b.empty()) {
    result.unmatched = a.size();
    return result;
  }
  P3 low = b.front();
  for(const P3& p : b)
    for(int k = 0; k < 3; ++k)
      low[k] = std::min(low[k], p[k]);
  const double cell = 1e-6 * diagonal;
  const auto coordinate = [&](double x, int k) { return static_cast<std::int64_t>(std::floor((x - low[k]) / cell)); };
  const auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return (static_cast<std::uint64_t>(i + 2) << 42) ^ (static_cast<std::uint64_t>(j + 2) << 21) ^
           static_cast<std::uint64_t>(k + 2);
  };
  std::unordered_multimap<std::uint64_t, std::uint32_t> grid;
  grid.reserve(b.size());
  for(std::size_t i = 0; i < b.size(); ++i)
    grid.emplace(key(coordinate(b[i][0], 0), coordinate(b[i][1], 1), coordinate(b[i][2], 2)),
                 static_cast<std::uint32_t>(i));
  for(const P3& p : a) {
    const std::int64_t ci = coordinate(p[0], 0), cj = coordinate(p[1], 1), ck = coordinate(p[2], 2);
    double best = 1e300;
    for(std::int64_t di = -1; di <= 1; ++di)
      for(std::int64_t dj = -1; dj <= 1; ++dj)
        for(std::int64_t dk = -1; dk <= 1; ++dk) {
          const auto range = grid.equal_range(key(ci + di, cj + dj, ck + dk));
          for(auto it = range.first; it != range.second; ++it) {
            const P3& q = b[it->second];
            const double d =
              std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
            best = std::min(best, d);
          }
        }
    if(best > cell)
      ++result.unmatched;
    else
      result.max_relative = std::max(result.max_relative, best / diagonal);
  }
  return result;
}

std::string describe(const Agreement& agreement, std::size_t a_size, std::size_t b_size)
{
  char text[128];
  if(!agreement.same_count)
    std::snprintf(text, sizeof text, "%zu vs %zu points", a_size, b_size);
  else if(agreement.unmatched > 0)
    std::snprintf(text, sizeof text, "%zu of %zu points > 1e-6 apart", agreement.unmatched, a_size);
  else
    std::snprintf(text, sizeof text, "%.1e", agreement.max_relative);
  return text;
}

} // namespace subdiv_bench
