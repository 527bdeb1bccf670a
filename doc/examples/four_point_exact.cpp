// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The four-point scheme (w = 1/16) in exact rational arithmetic. It keeps the
// old points and reproduces cubics: refining samples of y = x^3 puts every new
// point exactly on the cubic, with no rounding at all.

#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/curves/Four_point_scheme.h>
#include <CGAL/Subdiv/curves/refine_polyline.h>

#include <iostream>
#include <vector>

using Kernel = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using FT = Kernel::FT;
using Point = Kernel::Point_2;

int main()
{
  std::vector<Point> samples;
  for(int i = 0; i < 7; ++i)
    samples.push_back(Point(i, i * i * i));

  // default end rule: only the new points whose whole stencil lies on the polyline
  const CGAL::Subdiv::Four_point_scheme<FT> four_point; // w = 1/16
  const std::vector<Point> refined =
    CGAL::Subdiv::refine_polyline(samples, four_point, CGAL::Subdiv::parameters::number_of_iterations(2));

  std::cout << "four-point, 2 levels, samples of y = x^3 at x = 0..6: " << refined.size() << " points\n";
  int failures = 0;
  for(const Point& p : refined) {
    const bool on_cubic = (p.y() == p.x() * p.x() * p.x());
    std::cout << "  (" << p.x() << ", " << p.y() << ")" << (on_cubic ? "" : "  <- not on y = x^3") << "\n";
    if(!on_cubic)
      ++failures;
  }
  if(refined.size() < 3)
    ++failures;
  std::cout << (failures == 0 ? "every point is exactly on the cubic\n" : "FAILED\n");
  return failures == 0 ? 0 : 1;
}
