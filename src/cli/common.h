// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Types shared by the parts of the cgal-subdiv command-line tool.
#ifndef CGAL_SUBDIV_CLI_COMMON_H
#define CGAL_SUBDIV_CLI_COMMON_H

#include "errors.h"

#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdiv/curves/refine_polyline.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace cgal_subdiv {

using Exact = CGAL::Exact_rational;
using Exact_kernel = CGAL::Simple_cartesian<Exact>;
using Double_kernel = CGAL::Simple_cartesian<double>;

/// The points of an input file, every coordinate exact.
struct Input_polyline
{
  int dimension = 2;
  std::vector<std::array<Exact, 3>> points; // third coordinate 0 in 2D
  std::vector<std::string> notes;           // what was read and what was ignored
};

enum class Scheme_kind { bezier, bspline, chaikin, corner_cutting, four_point };

/// Which scheme, with its parameters as given (exact).
struct Scheme_spec
{
  Scheme_kind kind = Scheme_kind::bspline;
  int degree = 3;
  Exact a = Exact(1) / Exact(4);
  Exact b = Exact(3) / Exact(4);
  Exact w = Exact(1) / Exact(16);
};

/// How to refine: a level count, or a flatness tolerance (Bezier only).
struct Refine_spec
{
  int levels = 0;
  bool closed = false;
  CGAL::Subdiv::End_rule end_rule = CGAL::Subdiv::End_rule::shrink;
  bool use_tolerance = false;
  Exact tolerance = Exact(0);
};

/// One curve to compute: the scheme, the refinement, the kernel.
struct Curve_job
{
  Scheme_spec scheme;
  Refine_spec refine;
  bool exact = false;
};

/// the keyword of `cgal-subdiv curve --scheme KIND`: "bezier", "corner-cutting", ...
/// (inline: the analyses, compiled apart from the refinement code, use it too)
inline std::string scheme_keyword(Scheme_kind kind)
{
  switch(kind) {
    case Scheme_kind::bezier:
      return "bezier";
    case Scheme_kind::bspline:
      return "bspline";
    case Scheme_kind::chaikin:
      return "chaikin";
    case Scheme_kind::corner_cutting:
      return "corner-cutting";
    case Scheme_kind::four_point:
      return "four-point";
  }
  return "?";
}
/// e.g. "B-spline of degree 3", "corner cutting a=1/10 b=3/5", "four-point w=1/16"
std::string describe(const Scheme_spec& scheme);
/// e.g. "closed", "open, shrinking ends", "open, kept ends"
std::string describe(const Refine_spec& refine);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_COMMON_H
