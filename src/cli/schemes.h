// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The one place where a Scheme_spec becomes a scheme object.
#ifndef CGAL_SUBDIV_CLI_SCHEMES_H
#define CGAL_SUBDIV_CLI_SCHEMES_H

#include "common.h"
#include "numbers.h"

#include <CGAL/Subdiv/curves/Bezier_scheme.h>
#include <CGAL/Subdiv/curves/Chaikin_scheme.h>
#include <CGAL/Subdiv/curves/Corner_cutting_scheme.h>
#include <CGAL/Subdiv/curves/Four_point_scheme.h>
#include <CGAL/Subdiv/curves/Uniform_bspline_scheme.h>

#include <stdexcept>

namespace cgal_subdiv {

/*
 * calls `f(scheme)` with the scheme that `spec` names, its weights in the
 * number type FT; the constructors check the parameters (Bad_input).
 */
template <class FT, class F>
decltype(auto) with_scheme(const Scheme_spec& spec, F&& f)
{
  namespace S = CGAL::Subdiv;
  switch(spec.kind) {
    case Scheme_kind::bezier:
      return f(S::Bezier_scheme<FT>(spec.degree));
    case Scheme_kind::bspline:
      return f(S::Uniform_bspline_scheme<FT>(spec.degree));
    case Scheme_kind::chaikin:
      return f(S::Chaikin_scheme<FT>());
    case Scheme_kind::corner_cutting:
      return f(S::Corner_cutting_scheme<FT>(to_ft<FT>(spec.a), to_ft<FT>(spec.b)));
    case Scheme_kind::four_point:
      return f(S::Four_point_scheme<FT>(to_ft<FT>(spec.w)));
  }
  throw std::logic_error("unknown scheme kind");
}

template <class Scheme>
struct Is_bezier : std::false_type
{};

template <class FT>
struct Is_bezier<CGAL::Subdiv::Bezier_scheme<FT>> : std::true_type
{};

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_SCHEMES_H
