// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Compile-time switch for the parts of the tool that need the analysis layer
// (--report, the convergence tables of `demo`, the curvature plot):
// SUBDIV_CLI_WITH_ANALYSIS is 1 when <CGAL/Subdiv/analysis/curve_analysis.h>
// exists, unless SUBDIV_CLI_NO_ANALYSIS is defined.
#ifndef CGAL_SUBDIV_CLI_ANALYSIS_CONFIG_H
#define CGAL_SUBDIV_CLI_ANALYSIS_CONFIG_H

#if !defined(SUBDIV_CLI_NO_ANALYSIS) && __has_include(<CGAL/Subdiv/analysis/curve_analysis.h>)
#define SUBDIV_CLI_WITH_ANALYSIS 1
#include <CGAL/Subdiv/analysis/curve_analysis.h>
#else
#define SUBDIV_CLI_WITH_ANALYSIS 0
#endif

#endif // CGAL_SUBDIV_CLI_ANALYSIS_CONFIG_H
