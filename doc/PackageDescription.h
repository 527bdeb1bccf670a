// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The groups of the reference manual (documentation only: read by Doxygen).

/*!
 * \defgroup PkgSubdivRef CGAL Subdiv reference
 * Everything the package documents, by layer (doc/design.md).
 */

/*!
 * \defgroup PkgSubdivConcepts Concepts
 * \ingroup PkgSubdivRef
 * What the masks, their accumulators, the refinement hosts and the curve schemes
 * must provide: the expressions the code really uses.
 */

/*!
 * \defgroup PkgSubdivFunctions Surface subdivision
 * \ingroup PkgSubdivRef
 * `subdivide()`, the one-line wrappers per scheme, named parameters, carried data.
 */

/*!
 * \defgroup PkgSubdivMasks Surface masks and views
 * \ingroup PkgSubdivRef
 * The weights of the surface schemes (models of `SurfaceSubdivisionMask`) and the
 * views through which they see the old mesh.
 */

/*!
 * \defgroup PkgSubdivHosts Refinement hosts
 * \ingroup PkgSubdivRef
 * The topological splits (models of `SubdivisionHost`).
 */

/*!
 * \defgroup PkgSubdivStencils Stencils and stencil tables
 * \ingroup PkgSubdivRef
 * Stencils, stencil tables and `make_stencil_table()`.
 */

/*!
 * \defgroup PkgSubdivCurveSchemes Curve schemes
 * \ingroup PkgSubdivRef
 * The binary curve rules (models of `CurveSubdivisionScheme`) and Bezier curves.
 */

/*!
 * \defgroup PkgSubdivCurves Curve refinement
 * \ingroup PkgSubdivRef
 * `refine_polyline()`, the Bezier functions and their parameters.
 */

/*!
 * \defgroup PkgSubdivAnalysis Analysis and limit
 * \ingroup PkgSubdivRef
 * Local subdivision matrices, spectra, verdicts, limit and tangent masks
 * (`<CGAL/Subdiv/analysis.h>`), and the limit surface: positions, normals,
 * displacement (`<CGAL/Subdiv/limit.h>`).
 */

/*!
 * \defgroup PkgSubdivErrors Errors
 * \ingroup PkgSubdivRef
 * `Bad_input` and how the package reports what it refuses.
 */

/*!
 * \example catmull_clark_house.cpp
 * Surface subdivision: Catmull-Clark on a mesh read with CGAL's IO, with named
 * parameters; the counts of the quad split are checked.
 *
 * \example carried_data.cpp
 * Carried data: a vertex scalar and a face label through two Loop levels.
 *
 * \example uv_seams.cpp
 * UVs with seams (a corner map in corners plus1), material ids and colours
 * through two Catmull-Clark levels of a cube whose faces are texture islands.
 *
 * \example stencil_table.cpp
 * Stencil re-evaluation: one table for three Loop levels, applied to moved
 * control points and compared with subdividing the moved mesh.
 *
 * \example surface_analysis.cpp
 * The eigen-analysis of Loop at valences 3 to 7 and at a border vertex.
 *
 * \example loop_limit.cpp
 * Limit points and limit normals of Loop subdivision.
 *
 * \example chaikin_square.cpp
 * Curve refinement: Chaikin's corner cutting on the unit square.
 *
 * \example four_point_exact.cpp
 * The four-point scheme in exact rational arithmetic reproduces a cubic.
 */
