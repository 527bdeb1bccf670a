// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Uses the installed package: refines the closed unit square twice with
// Chaikin's scheme in exact rational arithmetic and checks three points and
// the point count exactly. Exit code 0 on success, 1 on a mismatch.

#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv.h>

#include <cstddef>
#include <iostream>
#include <vector>

using Kernel = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using FT = Kernel::FT;
using Point = Kernel::Point_2;

int main()
{
  const std::vector<Point> square = {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
  const std::vector<Point> refined = CGAL::Subdiv::refine_polyline(
    square, CGAL::Subdiv::Chaikin_scheme<FT>(), CGAL::Subdiv::parameters::number_of_iterations(2).closed(true));

  // level 1 starts (1/4, 0), (3/4, 0), (1, 1/4); level 2 cuts those corners again
  const std::vector<Point> expected = {Point(FT(3) / FT(8), FT(0)), Point(FT(5) / FT(8), FT(0)),
                                       Point(FT(13) / FT(16), FT(1) / FT(16))};
  bool ok = (refined.size() == 16);
  if(!ok)
    std::cerr << "expected 16 points, got " << refined.size() << "\n";
  for(std::size_t i = 0; ok && i < expected.size(); ++i)
    if(refined[i] != expected[i]) {
      std::cerr << "point " << i << ": expected " << expected[i] << ", got " << refined[i] << "\n";
      ok = false;
    }
  if(!ok)
    return 1;
  std::cout << "consumer: Chaikin on the unit square is exact: " << refined[2] << " ... (" << refined.size()
            << " points)\n";
  return 0;
}
