// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Chaikin's corner cutting on the unit square: every level replaces each edge
// by the points at 1/4 and 3/4 of it. Prints the 16 points of level 2; the
// polygon converges to the uniform quadratic B-spline of the square.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdiv/curves/Chaikin_scheme.h>
#include <CGAL/Subdiv/curves/refine_polyline.h>

#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

int main()
{
  const std::vector<Point> square = {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};

  const CGAL::Subdiv::Chaikin_scheme<Kernel::FT> chaikin;
  const std::vector<Point> refined =
    CGAL::Subdiv::refine_polyline(square, chaikin, CGAL::Subdiv::parameters::number_of_iterations(2).closed(true));

  std::cout << "Chaikin, 2 levels, closed unit square: " << refined.size() << " points\n";
  for(const Point& p : refined)
    std::cout << "  " << p << "\n";

  // every level doubles the point count of a closed polygon
  return refined.size() == 16 ? 0 : 1;
}
