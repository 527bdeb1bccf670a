// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Concept page (documentation only: compiled by Doxygen, never by a compiler).

/*!
 * \ingroup PkgSubdivConcepts
 * \cgalConcept
 *
 * What a mask reports its weights to: the one call `acc.add(source, weight)`
 * per contribution to the new point being made. Masks (models of
 * `SurfaceSubdivisionMask` and `CurveSubdivisionScheme`) take the accumulator
 * as a template parameter, by non-const reference, and call nothing else on it,
 * so what happens to the weights is up to the accumulator: sum points, record a
 * stencil, compose a row of a stencil table, fill a row of a matrix.
 *
 * The source is what a weight refers to:
 * - for a surface mask, a `boost::graph_traits<Mask::Polygon_mesh>::%vertex_descriptor`
 *   of the old mesh;
 * - for a curve scheme, an `int` offset k: old point i + k contributes to new
 *   point 2i (`even_mask()`) or 2i + 1 (`odd_mask()`).
 *
 * The weight is a value of the mask's `Number_type`; an accumulator may take
 * another type that this one converts to implicitly (the fast path of
 * `CGAL::Subdiv::subdivide()` takes `double`).
 *
 * <b>Semantics the masks rely on.</b>
 * - Contributions add up: a source reported twice contributes the sum of its
 *   weights (Catmull-Clark reports a vertex once per face point it is in).
 *   `CGAL::Subdiv::Stencil::add()` merges them into one term.
 * - Weights may be negative and need not be reported in any particular order
 *   of sources, but the order of the calls is the mask's, and accumulators that
 *   keep terms keep that order (the first appearance of each source), so that
 *   every consumer combines the terms in the same order.
 * - The return value of `add` is ignored.
 *
 * An accumulator is made by its consumer for one new point (or one row) and is
 * used by one thread at a time.
 *
 * \cgalHasModelsBegin
 * \cgalHasModels{CGAL::Subdiv::Stencil: the (source, weight) list of one new point; records rules (`CGAL::Subdiv::rule()`, the documentation tables, the tests) and the stencils of carried data}
 * \cgalHasModels{`internal::Mesh_point_sum` (refinement/point_sums.h): sums weight * (point - ORIGIN) over a vertex point map, any kernel}
 * \cgalHasModels{`internal::Flat_point_sum` (refinement/point_sums.h): the same on an array of 3D points with double coordinates, bit for bit}
 * \cgalHasModels{`internal::Point_sum` (internal/points.h): points by index, for curves}
 * \cgalHasModels{`internal::Row_builder` (stencils/Row_builder.h), through the report of `make_stencil_table()` that maps vertices to ordinals: composes rows of stencil tables}
 * \cgalHasModels{the row recorders of the curve analysis: a row of the local subdivision matrix, or the coefficients of the symbol}
 * \cgalHasModelsEnd
 *
 * \sa `SurfaceSubdivisionMask`, `CurveSubdivisionScheme`
 */
class SubdivisionAccumulator
{
public:
  /// adds `weight` times `source` to the point being made
  void add(const Source& source, const FT& weight);
};
