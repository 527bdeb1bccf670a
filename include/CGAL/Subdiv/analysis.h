// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_H
#define CGAL_SUBDIV_ANALYSIS_H

/// \file analysis.h
/// Convenience header of the eigen-analysis of curve and surface schemes
/// (Eigen, exact rationals): local subdivision matrices, spectra, verdicts,
/// limit and tangent masks.

#include <CGAL/Subdiv/analysis/Analysis_status.h>
#include <CGAL/Subdiv/analysis/Configuration.h>
#include <CGAL/Subdiv/analysis/Limit_masks.h>
#include <CGAL/Subdiv/analysis/curve_analysis.h>
#include <CGAL/Subdiv/analysis/surface_analysis.h>

#endif // CGAL_SUBDIV_ANALYSIS_H
