// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_UNIFORM_BSPLINE_SCHEME_H
#define CGAL_SUBDIV_UNIFORM_BSPLINE_SCHEME_H

#include <CGAL/Subdiv/curves/curve_parameters.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/internal/lane_riesenfeld.h>
#include <CGAL/Subdiv/internal/points.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/Subdiv/stencils/Stencil.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivCurveSchemes
 * Uniform B-spline of degree k by one doubling followed by k averagings
 * [Lane, Riesenfeld 1980]. The masks are the binomial coefficients
 * C(k+1, j) / 2^k, split into even and odd rules: what the doubling and the
 * averagings do to a unit impulse (derived below, and checked against
 * `lane_riesenfeld_refine` in the test suite), never typed in.
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
    if(degree < 1 || degree > max_degree)
      internal::refuse(internal::Message()
                       << "B-spline degree must be between 1 and " << int(max_degree) << ", got " << degree);
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
  // What one doubling and k averagings do to an impulse at source s: the
  // doubling puts 1 at 2s and 2s+1, and each averaging q'_j = (q_j + q_j+1) / 2
  // spreads it one step down, so that (Pascal's rule) point j then holds
  // C(k+1, 2s+1-j) / 2^k. `lane_riesenfeld_shift` re-indexes point j as
  // j + shift: binomial i lands on new point 2s + 1 - i + shift, i.e. on the
  // even (r = 0) or odd (r = 1) point of offset o = s - c from the centre c,
  // with i = 2o + 1 - r + shift. Read off in closed form rather than by
  // running the averagings: it costs every program with a border less to
  // compile, and the test suite checks it against `lane_riesenfeld_refine`.
  void derive_masks()
  {
    const int k = m_degree, shift = internal::lane_riesenfeld_shift(k);
    FT scale(1);
    for(int i = 0; i < k; ++i)
      scale /= FT(2);
    unsigned long long binomial[max_degree + 2] = {1}; // row k+1 of Pascal's triangle, below 2^62
    for(int n = 1; n <= k + 1; ++n)
      for(int i = n; i > 0; --i)
        binomial[i] += binomial[i - 1];
    for(int i = 0; i <= k + 1; ++i) {
      const int r = (i + 1 + shift) % 2;
      const int offset = (i + r - 1 - shift) / 2;
      (r == 0 ? m_even : m_odd).add(offset, exact_ft(binomial[i]) * scale);
    }
  }

  // an integer below 2^64 as FT, rounded once (exact in rationals): in two
  // halves, since FT need not be constructible from 64-bit integers
  static FT exact_ft(unsigned long long n)
  {
    const double high = static_cast<double>(n >> 32), low = static_cast<double>(n & 0xffffffffULL);
    return FT(high) * FT(4294967296.0) + FT(low);
  }

  int m_degree;
  Stencil<int, FT> m_even;
  Stencil<int, FT> m_odd;
};

/*!
 * \ingroup PkgSubdivCurves
 * Lane-Riesenfeld refinement applied to points directly: every level is one
 * doubling, then `degree` averagings of neighbours. For a closed polyline the
 * result equals `refine_polyline()` with `Uniform_bspline_scheme(degree)`; for
 * an open one it equals `End_rule::shrink`. Mostly useful to see (and test)
 * that the masks are what the algorithm does.
 *
 * \tparam PointRange a range of `Point_2` or `Point_3` of any CGAL kernel
 * \param points the control polygon, left unchanged
 * \param degree the degree k of the B-spline (k averagings per level)
 * \param np optional named parameters, in any order: `number_of_iterations`
 *   (default 1), `closed` (default false) and `max_output_points` (default
 *   `default_max_output_points`), as for `refine_polyline()`.
 * \throws Bad_input for a degree out of range, fewer than 2 points, a negative
 *         level count or too large an output.
 */
template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
std::vector<internal::Range_point<PointRange>> lane_riesenfeld_refine(
  const PointRange& points, int degree, const NamedParameters& np = parameters::default_values())
{
  using Point = internal::Range_point<PointRange>;
  using FT = internal::Point_FT<Point>;
  Uniform_bspline_scheme<FT> check_degree(degree);
  (void)check_degree;
  const internal::Curve_parameters p = internal::read_curve_parameters(np);
  std::vector<Point> current = internal::to_point_vector(points);
  internal::require(current.size() >= 2, "a polyline needs at least 2 points");
  internal::check_output_size(current.size(), p.levels, p.max_output_points);
  const auto midpoint = [](const Point& a, const Point& b) { return a + (b - a) / FT(2); };
  for(int level = 0; level < p.levels; ++level) {
    // an open polyline shrinks on every level: say so, as refine_polyline() does
    if(level > 0)
      internal::require(current.size() >= 2, "level " + std::to_string(level + 1) + ": the polyline shrank to " +
                                               std::to_string(current.size()) + " points");
    current = p.closed ? internal::lane_riesenfeld_closed(current, degree, midpoint)
                       : internal::lane_riesenfeld_open(current, degree, midpoint);
  }
  return current;
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_UNIFORM_BSPLINE_SCHEME_H
