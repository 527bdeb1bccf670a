// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Must compile (test/compile_tests.cmake): the Loop scheme's own header is
// enough for loop_subdivision(), and with a mask, for subdivide().
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/loop_subdivision.h>
#include <CGAL/Surface_mesh.h>

using Mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

void refine(Mesh& mesh)
{
  CGAL::Subdiv::loop_subdivision(mesh, CGAL::Subdiv::parameters::number_of_iterations(2));
  CGAL::Subdiv::subdivide(mesh, CGAL::Subdiv::Loop_mask<Mesh>());
}
