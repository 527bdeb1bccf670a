// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The rules (masks) of the surface schemes, read for the documentation
// tables: each mask reports its weights to a Stencil accumulator on a small
// patch built as a real mesh; nothing is typed in.
#ifndef CGAL_SUBDIV_DOC_TABLES_RULES_H
#define CGAL_SUBDIV_DOC_TABLES_RULES_H

#include <CGAL/Exact_rational.h>

#include <string>
#include <vector>

namespace subdiv_doc_tables {

using Exact = CGAL::Exact_rational;

/// one term of a rule: an old vertex of the patch, by its label in the
/// canonical order of the analysis (ring by ring, counter-clockwise), and its weight
struct Rule_term
{
  int label = 0;
  int ring = 0;
  Exact weight;
  bool rational = true; ///< false: a rounded irrational weight (denominator >= 2^40)
};

/// one rule of a scheme at one configuration
struct Rule
{
  std::string name;             ///< "vertex", "edge", "face", "corner", "border vertex", "border edge"
  std::string description;      ///< which new vertex it makes
  std::vector<Rule_term> terms; ///< by label
  std::vector<int> ring_sizes;  ///< number of labels in every ring of the patch
};

/*
 * the rules of the surface scheme `keyword` (as in `cgal-subdiv surface`)
 * around an interior vertex of valence n (Doo-Sabin: a face with n corners)
 * or, with `boundary`, a border vertex with n faces (Doo-Sabin: the border
 * face made from it, see `analyse_surface_scheme()`).
 */
std::vector<Rule> read_rules(const std::string& keyword, int n, bool boundary);

} // namespace subdiv_doc_tables

#endif // CGAL_SUBDIV_DOC_TABLES_RULES_H
