// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_H
#define CGAL_SUBDIV_H

/// \file Subdiv.h
/// Convenience header, as CGAL/subdivision_method_3.h: the curve schemes, the
/// surface schemes and `subdivide()`, and the stencil tables. The analysis
/// (Eigen, exact rationals) is in <CGAL/Subdiv/analysis.h>, the limit
/// positions and normals in <CGAL/Subdiv/limit.h>: a program that only
/// refines does not compile them.

#include <CGAL/Subdiv/Carried_data.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/parameters.h>

#include <CGAL/Subdiv/curves/Bezier_scheme.h>
#include <CGAL/Subdiv/curves/Chaikin_scheme.h>
#include <CGAL/Subdiv/curves/Corner_cutting_scheme.h>
#include <CGAL/Subdiv/curves/Four_point_scheme.h>
#include <CGAL/Subdiv/curves/Uniform_bspline_scheme.h>
#include <CGAL/Subdiv/curves/curve_mask.h>
#include <CGAL/Subdiv/curves/refine_polyline.h>

#include <CGAL/Subdiv/subdivide.h>
#include <CGAL/Subdiv/surface_subdivision.h>

#include <CGAL/Subdiv/stencils/Stencil_table.h>
#include <CGAL/Subdiv/stencils/make_face_varying_stencil_table.h>
#include <CGAL/Subdiv/stencils/make_stencil_table.h>

#endif // CGAL_SUBDIV_H
