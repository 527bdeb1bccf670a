// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_LANE_RIESENFELD_H
#define CGAL_SUBDIV_INTERNAL_LANE_RIESENFELD_H

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

// Lane-Riesenfeld refinement of degree k: one doubling (every value twice),
// then k rounds of averaging neighbours, q'_j = (q_j + q_j+1) / 2.
// The result is re-indexed by s = floor((k-1)/2) so that, for odd k, the new
// point 2i sits on old point i (its vertex rule is centred, like the cubic
// 1/8, 6/8, 1/8), and for even k the new points 2i, 2i+1 lie on edge (i, i+1).
//
// This is the one place where the rule lives: Uniform_bspline_scheme derives
// its masks by running it on unit impulses, and lane_riesenfeld_refine runs it
// on points.
inline int lane_riesenfeld_shift(int degree)
{
  return (degree - 1) / 2;
}

// periodic sequence of n values -> periodic sequence of 2n values
template <class T, class Average>
std::vector<T> lane_riesenfeld_closed(const std::vector<T>& values, int degree, const Average& average)
{
  const std::size_t m = 2 * values.size();
  std::vector<T> q;
  q.reserve(m);
  for(const T& v : values) {
    q.push_back(v);
    q.push_back(v);
  }
  std::vector<T> next;
  next.reserve(m);
  for(int round = 0; round < degree; ++round) {
    next.clear();
    for(std::size_t j = 0; j < m; ++j)
      next.push_back(average(q[j], q[(j + 1) % m]));
    q.swap(next);
  }
  const std::size_t s = static_cast<std::size_t>(lane_riesenfeld_shift(degree)) % m;
  std::vector<T> result;
  result.reserve(m);
  for(std::size_t j = 0; j < m; ++j)
    result.push_back(q[(j + m - s) % m]);
  return result;
}

// open sequence of n values -> the 2n - k values that the averagings can form;
// the first of them has index s = floor((k-1)/2) in the numbering of the new level
template <class T, class Average>
std::vector<T> lane_riesenfeld_open(const std::vector<T>& values, int degree, const Average& average)
{
  std::vector<T> q;
  q.reserve(2 * values.size());
  for(const T& v : values) {
    q.push_back(v);
    q.push_back(v);
  }
  for(int round = 0; round < degree && !q.empty(); ++round) {
    for(std::size_t j = 0; j + 1 < q.size(); ++j)
      q[j] = average(q[j], q[j + 1]);
    q.pop_back();
  }
  return q;
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_LANE_RIESENFELD_H
