// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The analysis summary of `cgal-subdiv demo`: every analysable surface scheme
// at interior valences 3..8, its subdominant eigenvalue and C1 verdict.
#ifndef CGAL_SUBDIV_CLI_ANALYSE_SUMMARY_H
#define CGAL_SUBDIV_CLI_ANALYSE_SUMMARY_H

#include <complex>
#include <iosfwd>
#include <string>
#include <vector>

namespace cgal_subdiv {

struct Analysis_summary_row
{
  std::string scheme; // keyword
  std::vector<int> valences;
  std::vector<std::complex<double>> subdominant; // by valence
  std::vector<bool> c1;                          // by valence
  std::string failure;
};

/// analyses every scheme of analysable_surface_schemes() at valences 3..8 (exact, a few seconds)
std::vector<Analysis_summary_row> analysis_summary();
/// the table on stdout
void print_analysis_summary(const std::vector<Analysis_summary_row>& rows);
/// the Markdown section of index.md
void write_analysis_index(const std::vector<Analysis_summary_row>& rows, std::ostream& out);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_ANALYSE_SUMMARY_H
