// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_H
#define CGAL_SUBDIV_LIMIT_H

/// \file limit.h
/// Convenience header of the limit surface: limit positions and normals,
/// displacement, limit stencil tables (they use the analysis' masks), and the
/// bases of the regular patches, the limit anywhere and its tessellation.

#include <CGAL/Subdiv/limit/Limit_evaluator.h>
#include <CGAL/Subdiv/limit/Limit_surface.h>
#include <CGAL/Subdiv/limit/face_varying_limit.h>
#include <CGAL/Subdiv/limit/make_limit_stencil_table.h>
#include <CGAL/Subdiv/limit/patch_basis.h>
#include <CGAL/Subdiv/limit/project_to_limit.h>
#include <CGAL/Subdiv/limit/tessellate.h>

#endif // CGAL_SUBDIV_LIMIT_H
