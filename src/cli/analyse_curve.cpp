// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The curve schemes' eigen-analysis in Exact_rational.
#include "analyse_schemes.h"
#include "schemes.h"

#include <CGAL/Subdiv/analysis/curve_analysis.h>

#include <algorithm>
#include <type_traits>

namespace cgal_subdiv {
namespace {

namespace S = CGAL::Subdiv;

std::vector<std::pair<int, Exact>> terms_of(const S::Stencil<int, Exact>& stencil)
{
  std::vector<std::pair<int, Exact>> terms(stencil.terms().begin(), stencil.terms().end());
  std::sort(terms.begin(), terms.end(),
            [](const std::pair<int, Exact>& x, const std::pair<int, Exact>& y) { return x.first < y.first; });
  return terms;
}

} // namespace

Curve_summary analyse_curve(const Scheme_spec& spec)
{
  Curve_summary s;
  s.scheme = scheme_keyword(spec.kind);
  with_scheme<Exact>(spec, [&](const auto& scheme) {
    using Scheme = std::decay_t<decltype(scheme)>;
    S::Curve_analysis<Exact> a;
    if constexpr(Is_bezier<Scheme>::value) {
      a = S::analyse_bezier(scheme);
      for(int j = 0; j <= scheme.degree(); ++j) {
        S::Stencil<int, Exact> row;
        scheme.split_mask(j, row);
        s.rules.push_back(terms_of(row));
        s.rule_names.push_back("split " + std::to_string(j));
      }
      s.c_infinity = true;
    } else {
      a = S::analyse_curve_scheme(scheme);
      s.rules.push_back(terms_of(S::rule(scheme, 0)));
      s.rule_names.push_back("even (2i)");
      s.rules.push_back(terms_of(S::rule(scheme, 1)));
      s.rule_names.push_back("odd (2i+1)");
    }
    s.name = a.scheme;
    s.window_first = a.window_first;
    s.window_last = a.window_last;
    for(Eigen::Index r = 0; r < a.matrix.rows(); ++r) {
      s.matrix.emplace_back();
      for(Eigen::Index c = 0; c < a.matrix.cols(); ++c)
        s.matrix.back().push_back(a.matrix(r, c));
    }
    s.eigenvalues = a.eigenvalues;
    s.one_is_simple_and_dominant = a.one_is_simple_and_dominant;
    s.c1_necessary = a.c1_necessary;
    s.limit_mask = a.limit_mask;
    s.converges = a.converges;
    s.smoothness = s.c_infinity ? -1 : a.smoothness;
    s.holder_exponent = s.c_infinity ? 0 : a.holder_exponent;
    s.predicted_rate = a.predicted_rate;
    return 0;
  });
  return s;
}

std::string smoothness_text(const Curve_summary& summary)
{
  if(summary.c_infinity)
    return "C^inf";
  if(summary.smoothness < 0)
    return "not proven";
  return "C^" + std::to_string(summary.smoothness);
}

} // namespace cgal_subdiv
