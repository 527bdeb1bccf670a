// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_HOSTS_HOSTS_H
#define CGAL_SUBDIV_HOSTS_HOSTS_H

/// \file hosts.h
/// Every refinement host, so that `Host_for` knows every split: for code that
/// refines with any mask (stencil tables, the analysis, the limit).

#include <CGAL/Subdiv/hosts/Dual_split.h>
#include <CGAL/Subdiv/hosts/Quad_split.h>
#include <CGAL/Subdiv/hosts/Sqrt3_split.h>
#include <CGAL/Subdiv/hosts/Triangle_quadrisection.h>

#endif // CGAL_SUBDIV_HOSTS_HOSTS_H
