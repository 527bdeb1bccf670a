// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The eigen-analysis of every scheme of cgal-subdiv, behind a non-template
// interface: `cgal-subdiv analyse`, the analysis summary of `cgal-subdiv demo`
// and the documentation tables (src/doc_tables) all call these functions, so
// that the costly template instantiations are compiled once (analyse_surface.cpp,
// analyse_curve.cpp).
#ifndef CGAL_SUBDIV_CLI_ANALYSE_SCHEMES_H
#define CGAL_SUBDIV_CLI_ANALYSE_SCHEMES_H

#include "common.h"
#include "numbers.h" // json_number, json_string

#include <CGAL/Subdiv/analysis/Configuration.h>

#include <complex>
#include <string>
#include <utility>
#include <vector>

namespace cgal_subdiv {

/// What the analysis knows about a surface scheme keyword.
struct Surface_scheme_facts
{
  std::string keyword; ///< "loop", ...
  std::string split;   ///< "1-to-4 triangle split", ...
  bool dual = false;   ///< centred at a face (Doo-Sabin)
  bool interpolating = false;
  bool border_analysis = false; ///< border vertices are analysed
  bool sharp_analysis = false;  ///< crease, dart and corner vertices are analysed (the scheme takes sharpness tags)
};

/// the surface schemes analyse_surface() accepts, in the order of the tables
/// (every keyword of `cgal-subdiv surface` but linear)
const std::vector<Surface_scheme_facts>& analysable_surface_schemes();

/// the facts of `keyword`, or nullptr if it is not analysable
const Surface_scheme_facts* find_analysable_surface_scheme(const std::string& keyword);

/// `CGAL::Subdiv::Surface_analysis<Exact_rational>` without the template,
/// see `analyse_surface_scheme()` for the meaning of every field
struct Surface_summary
{
  std::string scheme; ///< the keyword
  std::string name;   ///< the mask's name()
  int valence = 0;
  bool boundary = false;
  CGAL::Subdiv::Configuration configuration; ///< where: its kind, and a crease's sides
  bool face_centred = false;
  int rings = 0;
  std::vector<int> ring; ///< ring of every label
  bool exact = false;
  bool rows_sum_to_one = false;
  std::vector<std::complex<double>> eigenvalues; ///< by modulus, largest first
  std::vector<std::pair<Exact, int>> exact_eigenvalues;
  bool one_is_simple_and_dominant = false;
  std::complex<double> subdominant{0, 0}, second_subdominant{0, 0};
  int subdominant_multiplicity = 0;
  bool c1_necessary = false;
  int extended_rings = 0;
  double extended_largest_other = 0;
  bool extended_spectrum_ok = false;
  std::string characteristic_map; ///< "regular_injective", "not_regular", "not_injective", "not_applicable"
  int characteristic_map_levels = 0, annulus_inner = 0, annulus_outer = 0;
  bool c1 = false;
  std::vector<Exact> limit_mask; ///< by label (exact when `exact`, else from rounded weights)
  std::vector<double> limit_mask_double;
  std::vector<double> tangent_mask[2];
  int host_levels = 0, cropped_levels = 0;
  double host_error = -1, limit_error = -1;
  /// a crease: `block_triangular` and its two sides (`Surface_analysis::Side`)
  bool block_triangular = false;
  struct Side
  {
    int faces = 0;
    bool same_as_border = false, c1_necessary = false, c1 = false;
    std::string characteristic_map;
  };
  std::vector<Side> sides;
};

/// the ranges of the sharp configurations `cgal-subdiv analyse` and the tables take
constexpr int max_crease_side = 8;
constexpr int min_sharp_valence = 3, max_sharp_valence = 16;

/// the largest valence (or number of border faces) `cgal-subdiv analyse` accepts
constexpr int max_analysed_valence = 32;

/*
 * analyses the surface scheme `keyword` at an interior vertex of valence
 * `valence` (Doo-Sabin: a face with `valence` corners) or, with `boundary`,
 * at a border vertex with `valence` faces (Doo-Sabin: the border face made
 * from it), in Exact_rational.
 * \throws Usage_error for an unknown keyword, Input_error for linear, a
 *         valence out of range or a border vertex of a scheme whose border is
 *         not analysed
 */
Surface_summary analyse_surface(const std::string& keyword, int valence, bool boundary, bool characteristic_map = true,
                                bool verify_limit = true);

/*
 * analyses the surface scheme `keyword` at a crease, dart or corner vertex
 * (`where.sharp()`), with OpenSubdiv's infinitely sharp tags.
 * \throws Usage_error for an unknown keyword, Input_error for a scheme without
 *         sharpness tags or a configuration out of the ranges above (the
 *         message names the option: --crease, --dart, --corner)
 */
Surface_summary analyse_sharp_vertex(const std::string& keyword, const CGAL::Subdiv::Configuration& where,
                                     bool characteristic_map = true, bool verify_limit = true);

/// `CGAL::Subdiv::Curve_analysis<Exact_rational>` without the template
struct Curve_summary
{
  std::string scheme; ///< the keyword
  std::string name;   ///< the scheme's name()
  int window_first = 0, window_last = 0;
  std::vector<std::vector<Exact>> matrix;
  std::vector<std::complex<double>> eigenvalues;
  bool one_is_simple_and_dominant = false;
  bool c1_necessary = false;
  std::vector<Exact> limit_mask; ///< offsets window_first..window_last
  bool converges = false;
  bool c_infinity = false;
  int smoothness = -1;        ///< largest proven k of C^k, -1 if none (meaningless if c_infinity)
  double holder_exponent = 0; ///< lower bound (meaningless if c_infinity)
  double predicted_rate = 0;
  /// the even and odd rules: (offset, weight); Bezier: the rows of the split matrix
  std::vector<std::vector<std::pair<int, Exact>>> rules;
  std::vector<std::string> rule_names;
};

/// analyses a curve scheme in Exact_rational; \throws CGAL::Subdiv::Bad_input for bad parameters
Curve_summary analyse_curve(const Scheme_spec& spec);

/// "C^2", "C^inf", "C^0", "not proven"
std::string smoothness_text(const Curve_summary& summary);

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_ANALYSE_SCHEMES_H
