// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Must not compile (test/compile_tests.cmake): subdivide() with a mask whose
// host is not included stops at Host_for's static_assert, which names the
// headers to include.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/masks/Loop_mask.h>
#include <CGAL/Subdiv/subdivide.h>
#include <CGAL/Surface_mesh.h>

using Mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

void refine(Mesh& mesh)
{
  CGAL::Subdiv::subdivide(mesh, CGAL::Subdiv::Loop_mask<Mesh>());
}
