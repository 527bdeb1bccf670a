// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_LIMIT_SAMPLE_H
#define CGAL_SUBDIV_LIMIT_LIMIT_SAMPLE_H

/// \file Limit_sample.h
/// What `Limit_surface` returns at one parameter, and the curvatures that
/// follow from it (its first and second fundamental forms).

#include <CGAL/Simple_cartesian.h>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * The limit surface at one parameter: the position, its partial derivatives
 * along the face's u and v (first and second), and the unit normal.
 */
struct Limit_sample
{
  using Point = CGAL::Simple_cartesian<double>::Point_3;
  using Vector = CGAL::Simple_cartesian<double>::Vector_3;
  Point position = CGAL::ORIGIN;
  Vector du = CGAL::NULL_VECTOR, dv = CGAL::NULL_VECTOR;
  Vector duu = CGAL::NULL_VECTOR, duv = CGAL::NULL_VECTOR, dvv = CGAL::NULL_VECTOR;
  Vector normal = CGAL::NULL_VECTOR;
};

namespace internal {

// the coefficients of the first (E, F, G) and second (L, M, N) fundamental forms of a sample
struct Fundamental_forms
{
  double E, F, G, L, M, N;
  explicit Fundamental_forms(const Limit_sample& s)
    : E(s.du * s.du), F(s.du * s.dv), G(s.dv * s.dv), L(s.duu * s.normal), M(s.duv * s.normal), N(s.dvv * s.normal)
  {}
};

} // namespace internal

/*!
 * \ingroup PkgSubdivAnalysis
 * The Gaussian curvature (LN - M^2) / (EG - F^2) of the limit surface at a
 * sample. Not a number where the first fundamental form is singular: at an
 * extraordinary vertex itself, whose derivatives `Limit_surface` returns as
 * zero (the parameterisation has none there).
 */
inline double gaussian_curvature(const Limit_sample& s)
{
  const internal::Fundamental_forms f(s);
  return (f.L * f.N - f.M * f.M) / (f.E * f.G - f.F * f.F);
}

/*!
 * \ingroup PkgSubdivAnalysis
 * The mean curvature (EN - 2FM + GL) / (2 (EG - F^2)) of the limit surface
 * at a sample, positive where the surface bends towards its normal. Not a
 * number where `gaussian_curvature()` is not.
 */
inline double mean_curvature(const Limit_sample& s)
{
  const internal::Fundamental_forms f(s);
  return (f.E * f.N - 2 * f.F * f.M + f.G * f.L) / (2 * (f.E * f.G - f.F * f.F));
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_LIMIT_SAMPLE_H
