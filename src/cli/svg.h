// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_CLI_SVG_H
#define CGAL_SUBDIV_CLI_SVG_H

#include "curve.h"

#include <ostream>

namespace cgal_subdiv {

/*
 * writes a self-contained SVG figure of `figure`: the control polygon (grey,
 * dashed, with dots), the intermediate levels (thin, coloured from light to
 * dark), the last level (bold), and below, in a second panel, the discrete
 * curvature of the last level against its arc length.
 */
void write_svg(const Figure& figure, std::ostream& out);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_SVG_H
