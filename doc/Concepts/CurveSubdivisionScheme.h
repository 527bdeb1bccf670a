// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Concept page (documentation only: compiled by Doxygen, never by a compiler).

/*!
 * \ingroup PkgSubdivConcepts
 * \cgalConcept
 *
 * The rules of a binary, stationary curve subdivision scheme: one level makes
 * new point 2i from the even rule and new point 2i + 1 from the odd rule, both
 * read from the scheme's masks as offsets around old point i. A call
 * `acc.add(k, w)` in `even_mask()` means that old point i + k contributes with
 * weight w to new point 2i; in `odd_mask()`, to new point 2i + 1.
 *
 * The masks are read once, through `CGAL::Subdiv::rule()` (a
 * `CGAL::Subdiv::Stencil<int, Number_type>`), by every consumer:
 * `CGAL::Subdiv::refine_polyline()` (which maps the offsets to old indices,
 * periodic for closed polylines, with the `End_rule` at open ends), the curve
 * analysis (`CGAL::Subdiv::analyse_curve_scheme()`: local subdivision matrix,
 * symbol, limit mask), and `CGAL::Subdiv::Border_curve_rule`, which applies
 * the same rules along the border of the surface masks. The masks must be
 * `const`, report the same terms in the same order at every call, and call
 * nothing but `acc.add()` (see `SubdivisionAccumulator`); their weights should
 * sum to 1. Rational weights are written as ratios of `Number_type`.
 *
 * `CGAL::Subdiv::Bezier_scheme` is not a model: its de Casteljau split has a
 * rule per new control point (`split_mask(j, acc)`), not an even and an odd one.
 *
 * \cgalHasModelsBegin
 * \cgalHasModels{CGAL::Subdiv::Chaikin_scheme}
 * \cgalHasModels{CGAL::Subdiv::Corner_cutting_scheme}
 * \cgalHasModels{CGAL::Subdiv::Four_point_scheme}
 * \cgalHasModels{CGAL::Subdiv::Uniform_bspline_scheme}
 * \cgalHasModelsEnd
 *
 * \sa `SubdivisionAccumulator`, `SurfaceSubdivisionMask`
 */
class CurveSubdivisionScheme
{
public:
  /// \name Types
  /// @{

  /// the number type of the weights; the points refined must have it as their
  /// kernel's `FT`
  typedef unspecified_type Number_type;

  /// @}

  /// \name Operations
  /// @{

  /// the name of the scheme, in the messages of `CGAL::Subdiv::Bad_input` and
  /// in the reports of the analysis
  std::string name() const;

  /// reports the even rule: `acc.add(k, w)`, old point i + k to new point 2i
  template <class Accumulator>
  void even_mask(Accumulator& acc) const;

  /// reports the odd rule: `acc.add(k, w)`, old point i + k to new point 2i + 1
  template <class Accumulator>
  void odd_mask(Accumulator& acc) const;

  /// @}
};
