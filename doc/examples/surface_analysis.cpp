// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The eigen-analysis of a surface scheme, from its own mask: Loop at interior
// vertices of valence 3 to 7. For each valence it prints the subdominant
// eigenvalue, the C1 verdict and the centre weight of the limit mask, which
// is exact (Exact_rational) where the weights are rational. Checked: at the
// regular valence 6 the subdominant eigenvalue is 1/2 and the limit mask
// centre is exactly 1/2; at valence 3 (beta = 3/16) the centre is exactly 2/5.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdiv/analysis.h>
#include <CGAL/Subdiv/masks/Loop_mask.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Q = CGAL::Exact_rational;

int main()
{
  namespace SD = CGAL::Subdiv;
  // a mask over any mesh type: the analysis rebinds it to its own mesh and to Exact_rational
  const SD::Loop_mask<Mesh> loop;
  int failures = 0;
  for(int n = 3; n <= 7; ++n) {
    const SD::Surface_analysis<Q> a = SD::analyse(loop, n);
    std::cout << a.scheme << ", valence " << n << ": " << SD::to_string(a.status)
              << ", lambda_1 = " << a.subdominant.real() << ", C1: " << (a.c1 ? "yes" : "no") << ", limit mask centre ";
    if(a.exact)
      std::cout << a.limit_mask_centre() << " (exact)\n";
    else // Loop's beta is irrational at n != 3, 4, 6: the rational nearest the double weight
      std::cout << CGAL::to_double(a.limit_mask_centre()) << " (rounded weights)\n";
    if(a.status != SD::Analysis_status::success || !a.c1)
      ++failures;
    if(n == 6 && (std::abs(a.subdominant - 0.5) > 1e-12 || a.limit_mask_centre() != Q(1) / Q(2)))
      ++failures;
    if(n == 3 && a.limit_mask_centre() != Q(2) / Q(5))
      ++failures;
  }

  // the same with named parameters, at a border vertex with 2 faces, without
  // the (costlier) verification by refinement
  const SD::Surface_analysis<Q> border = SD::analyse_surface_scheme(loop, SD::Configuration(2, SD::Vertex_kind::border),
                                                                    SD::parameters::verify_limit(false));
  std::cout << "border vertex with 2 faces: lambda_1 = " << border.subdominant.real()
            << ", C1: " << (border.c1 ? "yes" : "no") << ", limit mask centre " << border.limit_mask_centre() << "\n";
  // the border is the cubic B-spline of the border polygon: limit (1, 4, 1) / 6
  if(border.status != SD::Analysis_status::success || border.limit_mask_centre() != Q(2) / Q(3))
    ++failures;

  std::cout << (failures == 0 ? "all checks passed\n" : "FAILED\n");
  return failures == 0 ? 0 : 1;
}
