// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_UNIFORM_BSPLINE_SCHEME_H
#define CGAL_SUBDIV_UNIFORM_BSPLINE_SCHEME_H

#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/lane_riesenfeld.h>
#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/Subdiv/stencils/Stencil.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivCurveSchemes
 * Uniform B-spline of degree k by one doubling followed by k averagings
 * [Lane, Riesenfeld 1980]. The masks are the binomial coefficients
 * C(k+1, j) / 2^k, split into even and odd rules; they are derived here by
 * running the doubling and the averagings on unit impulses, never typed in.
 *
 * - degree 1 inserts edge midpoints (the polygon itself is the limit),
 * - degree 2 is Chaikin's scheme,
 * - degree 3 is the cubic B-spline: vertex rule 1/8, 6/8, 1/8, edge rule 1/2, 1/2.
 *
 * For odd k the new point 2i is the vertex point of old point i (primal
 * scheme); for even k the new points 2i, 2i+1 are on edge (i, i+1) (dual scheme).
 *
 * \cgalModels `CurveSubdivisionScheme`
 */
template <class FT>
class Uniform_bspline_scheme
{
public:
  using Number_type = FT;
  static constexpr int max_degree = 64;

  /// \throws Bad_input unless 1 <= degree <= max_degree
  explicit Uniform_bspline_scheme(int degree = 3) : m_degree(degree)
  {
    internal::require(
      degree >= 1 && degree <= max_degree,
      "B-spline degree must be between 1 and " + std::to_string(max_degree) + ", got " + std::to_string(degree));
    derive_masks();
  }

  std::string name() const { return "B-spline of degree " + std::to_string(m_degree); }
  bool is_interpolating() const { return m_degree == 1; }
  int degree() const { return m_degree; }

  template <class Accumulator>
  void even_mask(Accumulator& acc) const
  {
    for(const auto& term : m_even.terms())
      acc.add(term.first, term.second);
  }

  template <class Accumulator>
  void odd_mask(Accumulator& acc) const
  {
    for(const auto& term : m_odd.terms())
      acc.add(term.first, term.second);
  }

private:
  // Run the refinement on a periodic impulse e_source and read the weight
  // that the source gets in the new points 2c and 2c+1.
  void derive_masks()
  {
    const int n = 2 * m_degree + 6; // long enough that no stencil wraps around
    const int c = n / 2;
    const auto average = [](const FT& x, const FT& y) -> FT { return (x + y) / FT(2); };
    for(int source = 0; source < n; ++source) {
      std::vector<FT> impulse(n, FT(0));
      impulse[source] = FT(1);
      const std::vector<FT> refined = internal::lane_riesenfeld_closed(impulse, m_degree, average);
      if(refined[2 * c] != FT(0))
        m_even.add(source - c, refined[2 * c]);
      if(refined[2 * c + 1] != FT(0))
        m_odd.add(source - c, refined[2 * c + 1]);
    }
  }

  int m_degree;
  Stencil<int, FT> m_even;
  Stencil<int, FT> m_odd;
};

/*!
 * \ingroup PkgSubdivCurves
 * One level of Lane-Riesenfeld refinement applied to points directly: one
 * doubling, then `degree` averagings of neighbours. For a closed polyline the
 * result equals one level of `refine_polyline()` with
 * `Uniform_bspline_scheme(degree)`; for an open one it equals `End_rule::shrink`.
 * Mostly useful to see (and test) that the masks are what the algorithm does.
 */
template <class Point>
std::vector<Point> lane_riesenfeld_refine(const std::vector<Point>& points, int degree, bool closed)
{
  using FT = internal::Point_FT<Point>;
  Uniform_bspline_scheme<FT> check_degree(degree);
  (void)check_degree;
  internal::require(points.size() >= 2, "a polyline needs at least 2 points");
  const auto midpoint = [](const Point& p, const Point& q) { return p + (q - p) / FT(2); };
  if(closed)
    return internal::lane_riesenfeld_closed(points, degree, midpoint);
  return internal::lane_riesenfeld_open(points, degree, midpoint);
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_UNIFORM_BSPLINE_SCHEME_H
