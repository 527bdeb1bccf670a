// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_H
#define CGAL_SUBDIV_H

/// \file Subdiv.h
/// Convenience header: includes every public header of CGAL Subdiv.

#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/stencils/Stencil.h>

#include <CGAL/Subdiv/analysis/curve_analysis.h>
#include <CGAL/Subdiv/analysis/limit.h>
#include <CGAL/Subdiv/analysis/surface_analysis.h>
#include <CGAL/Subdiv/curves/Bezier_scheme.h>
#include <CGAL/Subdiv/curves/Chaikin_scheme.h>
#include <CGAL/Subdiv/curves/Corner_cutting_scheme.h>
#include <CGAL/Subdiv/curves/Four_point_scheme.h>
#include <CGAL/Subdiv/curves/Uniform_bspline_scheme.h>
#include <CGAL/Subdiv/curves/curve_mask.h>
#include <CGAL/Subdiv/curves/refine_polyline.h>

#include <CGAL/Subdiv/stencils/Stencil_table.h>
#include <CGAL/Subdiv/stencils/make_limit_stencil_table.h>
#include <CGAL/Subdiv/stencils/make_stencil_table.h>
#include <CGAL/Subdiv/subdivide.h>
#include <CGAL/Subdiv/surface_subdivision.h>

#endif // CGAL_SUBDIV_H
