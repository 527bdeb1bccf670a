// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "curve.h"
#include "numbers.h"

namespace cgal_subdiv {

std::string describe(const Scheme_spec& scheme)
{
  switch(scheme.kind) {
    case Scheme_kind::bezier:
      return "Bezier of degree " + std::to_string(scheme.degree);
    case Scheme_kind::bspline:
      return "B-spline of degree " + std::to_string(scheme.degree);
    case Scheme_kind::chaikin:
      return "Chaikin";
    case Scheme_kind::corner_cutting:
      return "corner cutting a=" + format_exact(scheme.a) + " b=" + format_exact(scheme.b);
    case Scheme_kind::four_point:
      return "four-point w=" + format_exact(scheme.w);
  }
  return "?";
}

std::string describe(const Refine_spec& refine)
{
  std::string text = refine.closed ? "closed" : "open";
  if(!refine.closed && refine.end_rule == CGAL::Subdiv::End_rule::keep_ends)
    text += ", kept ends";
  if(refine.use_tolerance)
    return text + ", tolerance " + format_exact(refine.tolerance);
  return text + ", " + std::to_string(refine.levels) + (refine.levels == 1 ? " level" : " levels");
}

std::size_t run_curve(const Curve_job& job, const Input_polyline& input, std::ostream& points_out, Figure* figure)
{
  if(figure) {
    figure->title = describe(job.scheme) + " (" + describe(job.refine) + ")" +
                    (input.dimension == 3 ? ", projected onto the xy plane" : "");
    figure->closed = job.refine.closed;
  }
  if(job.exact)
    return compute_curve<Exact_kernel>(job, input, points_out, figure);
  return compute_curve<Double_kernel>(job, input, points_out, figure);
}

} // namespace cgal_subdiv
