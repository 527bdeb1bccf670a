// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_ANALYSIS_RESULT_H
#define CGAL_SUBDIV_ANALYSIS_ANALYSIS_RESULT_H

/// \file analysis_result.h
/// What the analysis of a surface scheme finds at one configuration
/// (`Surface_analysis`, filled by `analyse_surface_scheme()`).

#include <CGAL/Subdiv/analysis/Analysis_status.h>
#include <CGAL/Subdiv/analysis/Configuration.h>
#include <CGAL/Subdiv/analysis/characteristic_map.h> // Characteristic_map_verdict

#include <Eigen/Core>

#include <complex>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * The analysis of a surface scheme at one vertex (or face) configuration,
 * see `analyse_surface_scheme()`. Vertices of the neighbourhood are in the
 * canonical order of `local_subdivision_matrix()`: label 0 is the centre
 * (for a face-centred scheme, labels 0..n-1 are the corners of the central
 * face), then ring by ring; `ring[i]` is the ring of label i.
 */
template <class FT>
struct Surface_analysis
{
  /// whether every step ran (`no_convergence`: an eigen-solver failed, the
  /// spectrum or the tangent masks are missing; `not_affine_invariant`: the
  /// rows of the matrix do not sum to 1); the verdicts mean something only
  /// with `success`
  Analysis_status status = Analysis_status::success;
  std::string scheme; ///< `mask.name()`
  int valence = 0;    ///< valence n (border: number of faces k; dual: corners of the central face; dual at
                      ///< the border: faces k of the border vertex the central face was made from)
  bool boundary = false;
  /// the configuration analysed (its kind: interior, border, or a sharp
  /// vertex: crease, dart, corner)
  Configuration configuration;
  bool face_centred = false; ///< dual scheme: the neighbourhood is centred at an n-gon
  int rings = 0;             ///< rings of the (smallest invariant) neighbourhood
  std::vector<int> ring;     ///< ring of every label
  /// the local subdivision matrix over the neighbourhood, in FT
  Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic> matrix;
  /// every entry is an exact rational of the scheme: FT is exact and no
  /// weight is a rounded transcendental number (every denominator < 2^40;
  /// a weight rounded from a double has a denominator >= 2^50)
  bool exact = false;
  /// every row of the matrix sums to 1 (exactly, for exact FT)
  bool rows_sum_to_one = false;
  /// all eigenvalues (Eigen, in double), by modulus, largest first (ties:
  /// real part, then imaginary part, largest first). For exact matrices (up
  /// to 64 x 64) every real eigenvalue within 1e-9 of a rational p/q
  /// (q <= 4096) is tested exactly (rank of (S - p/q I)^k in FT) and, when
  /// confirmed, reported exactly with its algebraic multiplicity.
  std::vector<std::complex<double>> eigenvalues;
  /// the eigenvalues confirmed exactly, with their algebraic multiplicities
  std::vector<std::pair<FT, int>> exact_eigenvalues;
  /// eigenvalue 1 is simple (exactly, for exact FT) and every other |lambda| < 1
  bool one_is_simple_and_dominant = false;
  /// lambda_1 (largest modulus after lambda_0 = 1)
  std::complex<double> subdominant{0, 0};
  /// how many eigenvalues equal lambda_1 (tolerance 1e-8; a complex lambda_1 counts once)
  int subdominant_multiplicity = 0;
  /// lambda_2, the other eigenvalue of the subdominant pair
  std::complex<double> second_subdominant{0, 0};
  /// the necessary condition for C1: lambda_0 = 1 simple and dominant and,
  /// at an interior vertex, lambda_1 = lambda_2 real positive > |lambda_3|;
  /// at a border vertex, where the border curve and the interior have their
  /// own eigenvalues, the condition of [Zorin 2000] instead: lambda_1 >=
  /// lambda_2 > |lambda_3|, both real positive (the characteristic map is then
  /// built from the eigenvectors of lambda_1 and lambda_2); the same at a
  /// dart and a corner; at a crease, both sides' (`sides`)
  bool c1_necessary = false;
  /// rings of the larger neighbourhood used for the characteristic map
  int extended_rings = 0;
  /// largest |lambda| of the larger neighbourhood's matrix apart from 1 and
  /// the subdominant pair: eigenvalues that the smallest invariant
  /// neighbourhood does not see (they come from its outer rings)
  double extended_largest_other = 0;
  /// the larger matrix has 1 simple, the same subdominant pair, and
  /// nothing else of modulus >= |lambda_1| (tolerance 1e-9)
  bool extended_spectrum_ok = false;
  /// the characteristic-map verdict
  Characteristic_map_verdict characteristic_map = Characteristic_map_verdict::not_applicable;
  /// refinement levels the characteristic map was computed with, and the
  /// rings [inner, outer] of the annulus that was tested
  int characteristic_map_levels = 0, annulus_inner = 0, annulus_outer = 0;
  /// the final verdict: one_is_simple_and_dominant, c1_necessary,
  /// extended_spectrum_ok and a regular injective characteristic map (a
  /// crease: see `sides`)
  bool c1 = false;
  /// a crease vertex: the crease rows (the centre and the vertices on the
  /// sharp rays) read crease vertices only, and the rows of each side read
  /// no vertex of the other side, so the matrix is block triangular
  bool block_triangular = false;
  /// a crease vertex: each side's block (the crease and that side's
  /// vertices), side 0 with `configuration.first_side` faces, side 1 with
  /// the others; the surface is C1 on each side up to the crease when the
  /// side is, and the two sides meet along the crease curve only
  struct Side
  {
    int faces = 0;                                 ///< faces k on this side
    std::vector<std::complex<double>> eigenvalues; ///< of the side's block, sorted as `eigenvalues`
    /// the side's eigenvalues are those of the border analysis of k faces
    /// (the same multiset, tolerance 1e-6): the side is refined as a border
    /// with k faces
    bool same_as_border = false;
    bool c1_necessary = false;         ///< the border analysis's
    bool extended_spectrum_ok = false; ///< the border analysis's
    Characteristic_map_verdict characteristic_map = Characteristic_map_verdict::not_applicable; ///< the border's
    bool c1 = false;                                                                            ///< the border's
  };
  std::vector<Side> sides; ///< a crease: its two sides (empty otherwise)
  /// left eigenvector of 1 normalised to sum 1, by label (exact for exact
  /// FT); empty if 1 is not simple. The limit of the centre is
  /// sum_i limit_mask[i] * p_i.
  std::vector<FT> limit_mask;
  /// two left eigenvectors of the subdominant pair (real and imaginary part
  /// for a complex pair), by label, orthonormalised and rotated so that the
  /// first has the largest possible weight on label 1 and the second a zero
  /// weight there (for Loop: cos(2 pi i/n) and sin(2 pi i/n) on ring 1, up to scale)
  std::vector<double> tangent_mask[2];

  /// verification: levels of the real host on the whole random patch, the
  /// distance of the centre to the predicted limit after them (relative to
  /// the diameter of the neighbourhood), and |lambda_1|^levels
  int host_levels = 0;
  double host_error = -1, host_lambda_power = 0;
  /// verification: further levels, each the real host on the patch cropped to
  /// the neighbourhood and 2 more rings, until the centre stops moving, and
  /// the final relative distance to the predicted limit
  int cropped_levels = 0;
  double limit_error = -1;

  /// the limit-mask weight of the centre (label 0; for a face-centred
  /// neighbourhood, of the first corner)
  FT limit_mask_centre() const { return limit_mask.empty() ? FT(0) : limit_mask.front(); }
};

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_ANALYSIS_RESULT_H
