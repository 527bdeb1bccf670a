// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Refining one curve: input points -> output points (and what the figure shows).
#ifndef CGAL_SUBDIV_CLI_CURVE_H
#define CGAL_SUBDIV_CLI_CURVE_H

#include "common.h"

#include <array>
#include <ostream>
#include <string>
#include <vector>

namespace cgal_subdiv {

/// What an SVG figure shows, in doubles (3D points projected to xy).
struct Figure
{
  std::string title;
  bool closed = false;
  std::vector<std::vector<std::array<double, 2>>> levels; // levels[0]: control polygon
  std::vector<double> curvature;                          // at the points of the last level
  std::vector<double> arc_length;                         // at the same points, from the first
  bool has_curvature = false;
};

/*
 * refines `input` as `job` says, writes the final points to `points_out` (one
 * per line; exact fractions if job.exact, else 17 significant digits) and,
 * if `figure` is not null, fills it. Returns the number of output points.
 * \throws CGAL::Subdiv::Bad_input, Input_error
 */
std::size_t run_curve(const Curve_job& job, const Input_polyline& input, std::ostream& points_out, Figure* figure);

/// run_curve() in one kernel; defined in curve_impl.h, instantiated in curve_*.cpp
template <class Kernel>
std::size_t compute_curve(const Curve_job& job, const Input_polyline& input, std::ostream& points_out, Figure* figure);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_CURVE_H
