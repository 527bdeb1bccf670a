// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// What the limit surface evaluator (Limit_surface.h) uses per valence, for
// the documentation: the table of its Stam eigenbases and the curvature
// figure of doc/limit.md, both read from the evaluator itself (through the
// tool's Limit_evaluator, compiled once for cgal-subdiv and this tool).
#ifndef CGAL_SUBDIV_DOC_TABLES_LIMIT_TABLES_H
#define CGAL_SUBDIV_DOC_TABLES_LIMIT_TABLES_H

#include <string>

namespace subdiv_doc_tables {

/// a table as Markdown (a whole page) and as CSV
struct Limit_tables
{
  std::string markdown, csv;
};

/*
 * Stam's eigenbasis of Catmull-Clark and Loop at interior valences
 * `first_valence`..`last_valence`: the size of the local subdivision matrix,
 * its leading eigenvalues as the evaluator's eigenbasis has them, the
 * condition number of its eigenvector matrix (as the bound the evaluator
 * checks: its value depends on rounding, limit_tables.cpp), and
 * whether the evaluator uses it (or the patch is regular, or refined).
 */
Limit_tables limit_eigenbasis_tables(int first_valence, int last_valence);

/// the file name of the curvature figure in doc/figures
inline constexpr const char* curvature_figure_name = "limit-curvature-catmull-clark.svg";

/*
 * The SVG figure of the Gaussian curvature of the Catmull-Clark limit
 * surface over the faces around an inner vertex of valence 3, 4 and 5, on
 * the same height field, from the evaluator's first and second
 * derivatives (curvature_figure.cpp).
 */
std::string curvature_figure();

} // namespace subdiv_doc_tables

#endif // CGAL_SUBDIV_DOC_TABLES_LIMIT_TABLES_H
