// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The convergence report: distances between successive levels, measured on
// the input, next to what the eigen-analysis of the scheme predicts.
#ifndef CGAL_SUBDIV_CLI_REPORT_H
#define CGAL_SUBDIV_CLI_REPORT_H

#include "common.h"

#include <ostream>
#include <string>

namespace cgal_subdiv {

/// the figures the demo lists per scheme
struct Report_summary
{
  double last_ratio = 0;     ///< measured distance ratio of the last level (NaN if none)
  double predicted_rate = 0; ///< from the eigenvalues
  std::string verdict;       ///< "C^1", "C^inf", "C^0", "not proven"
};

/*
 * writes, as Markdown, the table of distances between successive levels of
 * `input` refined as `job` says (measured in double) and the eigen-analysis of
 * the scheme (in Exact_rational: matrix, eigenvalues, limit mask, verdict,
 * predicted rate next to the measured ratios).
 * \throws Input_error if the tool was built without the analysis layer
 */
Report_summary write_report(const Curve_job& job, const Input_polyline& input, std::ostream& out);

/// false if the tool was built without the analysis layer (see analysis_config.h)
bool report_available();

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_REPORT_H
