// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: number formatting, and the SVG bar chart of doc/figures/performance.svg.
#ifndef SUBDIV_BENCH_REPORT_H
#define SUBDIV_BENCH_REPORT_H

#include <string>
#include <vector>

namespace subdiv_bench {

/// seconds with 4 significant digits at most ("0.0123", "1.234"); "-" if not timed
std::string seconds(double s);
/// "%.2f" of x; "-" if not finite
std::string fixed(double x, int decimals = 2);
/// "%.1e" of x ("3.2e-16"); "-" if not finite
std::string scientific(double x);

struct Chart_group
{
  std::string label;
  std::vector<double> values; // one per series; NaN where the series has no value
};

/// horizontal grouped bars, one group per row, one bar per series, hand-made SVG
std::string bar_chart_svg(const std::string& title, const std::string& axis, const std::vector<std::string>& series,
                          const std::vector<Chart_group>& groups);

} // namespace subdiv_bench

#endif // SUBDIV_BENCH_REPORT_H
