// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_LIMIT_MASKS_H
#define CGAL_SUBDIV_ANALYSIS_LIMIT_MASKS_H

/// \file Limit_masks.h
/// What the analysis gives the limit: the limit and tangent masks of a scheme
/// at one configuration, over the labels of the one neighbourhood walk.

#include <CGAL/Subdiv/analysis/Configuration.h>
#include <CGAL/Subdiv/analysis/Neighbourhood_walk.h>
#include <CGAL/Subdiv/analysis/sector_spectrum.h>
#include <CGAL/Subdiv/analysis/surface_analysis.h>
#include <CGAL/Subdiv/analysis/surface_neighbourhood.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/assertions.h>

#include <CGAL/Exact_rational.h>

#include <cmath>
#include <complex>
#include <cstddef>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * The limit and tangent masks of a surface scheme at one configuration (an
 * interior vertex of valence `valence`, or a border vertex with `valence`
 * faces), over the labels of `internal::Neighbourhood_walk`: 0 the centre,
 * then ring by ring counter-clockwise from the start edge; for a border
 * vertex the start edge is the border edge with its face on the left of
 * centre -> neighbour.
 */
struct Limit_masks
{
  std::string scheme; ///< `mask.name()`
  int valence = 0;    ///< interior: valence; border: number of faces
  bool border = false;
  int rings = 0; ///< rings of the invariant neighbourhood the masks are written over
  /// the limit mask (left eigenvector of 1, sum 1), solved exactly from the
  /// exact local subdivision matrix (weights that are rounded transcendental
  /// numbers, e.g. Loop's 1987 beta at n != 3, 4, 6, enter as the rationals
  /// the refinement uses)
  std::vector<CGAL::Exact_rational> limit;
  /// the two tangent masks of the analysis (double), the second possibly
  /// negated so that t0 x t1 points to the side from which the faces are
  /// counter-clockwise (the outside of an outward-oriented closed mesh)
  std::vector<double> tangent[2];
  /// the tangent masks give the tangent plane: the analysis proves the
  /// scheme C1 at this configuration (`Surface_analysis::c1`: a separated
  /// subdominant pair and a regular injective characteristic map), and on the
  /// planar regular layout of the neighbourhood t0 x t1 does not vanish.
  /// Otherwise the normals fall back to face normals (see `limit_normals()`):
  /// e.g. the butterfly at n = 3 or n >= 8, whose subdominant eigenvectors are
  /// not a tangent plane, border vertices with many faces
  bool tangents = false;
  /// the analysis' lambda_1, C1 condition and verdict (for reports)
  std::complex<double> subdominant{0, 0};
  bool c1_necessary = false;
  bool c1 = false;
  /// the transcript of the walk over the analysed neighbourhood of `rings + 1`
  /// rings: a mesh's vertex whose walk reads the same has that neighbourhood
  std::vector<int> connectivity;
  std::size_t neighbourhood_size = 0; ///< labels of that neighbourhood
};

namespace internal {

/*
 * Above this valence, at interior vertices, a mesh with double coordinates
 * takes masks computed in doubles: the limit mask is the double left fixed
 * vector of the local matrix (relative error about 1e-14, held as the
 * rationals of those doubles), and the tangent masks' C1 check is the
 * spectrum's (a simple dominant 1, a real double subdominant eigenvalue, a
 * gap) without the extended spectrum and the characteristic map, whose
 * eigen-solve on about twice the rings took seconds at valence 64 and did not
 * finish at 360. The spectrum and the masks are then taken by frequency
 * (sector_spectrum.h). Exact kernels keep the exact masks at every valence.
 */
constexpr int max_exact_limit_valence = 24;

/*
 * The masks of one configuration, from the analysis of `mask` (any mesh
 * type and number type: it is rebound): its tangent masks and verdict in
 * double (with the characteristic map, without the verification by
 * refinement), the limit mask solved exactly from the exact local matrix of
 * the same neighbourhood (the analysis' own rule,
 * `normalised_left_fixed_vector`), and the transcript of the walk over the
 * analysed neighbourhood (on its patch).
 */
template <class Mask>
Limit_masks compute_limit_masks(const Mask& mask, const Configuration& where)
{
  using Traits = Host_of<decltype(mask.template rebind<Analysis_mesh, double>())>;
  // high valence in doubles: the masks from the double spectrum only
  const bool in_double = std::is_floating_point<typename Mask::Number_type>::value && !Traits::face_centred &&
                         where.valence > max_exact_limit_valence && !where.on_border();
  const Surface_analysis<double> analysis = analyse_surface_scheme<double>(
    mask, where, parameters::characteristic_map(true).verify_limit(false).extended_spectrum(!in_double));
  const int valence = where.valence;
  const bool border = where.on_border();
  Limit_masks masks;
  masks.scheme = analysis.scheme;
  masks.valence = valence;
  masks.border = border;
  masks.rings = analysis.rings;
  masks.subdominant = analysis.subdominant;
  masks.c1_necessary = analysis.c1_necessary;
  masks.c1 = analysis.c1;
  const std::string at =
    analysis.scheme + (border
                         ? " at a border vertex with " + std::to_string(valence) + " faces"
                         : (Traits::face_centred ? " at a face with " + std::to_string(valence) + " corners"
                                                 : " at an interior vertex of valence " + std::to_string(valence)));
  require(analysis.one_is_simple_and_dominant, at + ": 1 is not a simple dominant eigenvalue, there is no limit mask");
  if(in_double) {
    for(const double w : analysis.limit_mask) // the double solve, held exactly
      masks.limit.push_back(CGAL::Exact_rational(w));
  } else {
    const Local_subdivision_matrix<CGAL::Exact_rational> exact =
      local_subdivision_matrix<CGAL::Exact_rational>(mask, where, parameters::rings(analysis.rings));
    CGAL_assertion_msg(exact.invariant && exact.S.rows() == analysis.matrix.rows(),
                       "the exact local matrix does not match the analysed one");
    // the analysis proved 1 simple: at an interior vertex with alike
    // sectors, frequency 0 alone gives the fixed vector, exactly
    const std::optional<Sector_layout> sectors =
      border || Traits::face_centred ? std::nullopt : sector_layout(exact.S, exact.ring, valence);
    masks.limit = sectors ? left_fixed_vector_over_sectors(exact.S, *sectors) : normalised_left_fixed_vector(exact.S);
  }
  require(!masks.limit.empty(), at + ": the limit mask is not unique");
  if constexpr(Traits::face_centred) {
    // a dual scheme: the analysis is centred at an n-gon (labels 0..n-1 its
    // corners); the limit uses the limit mask only if it is the centroid of
    // the central face (then the face alone is invariant and its limit point
    // does not depend on the faces around it). At the border (the face made
    // of the corners at a border vertex with k faces, labelled from the first
    // corner after its border edges): only if it is the midpoint of its first
    // and last corners, the two corners at the vertex on the new border (k >=
    // 3: the k-gon's border corners; k = 2: those of the border quad), or,
    // k = 1, its corner 3, the kept corner of the corner face.
    const std::size_t corners = static_cast<std::size_t>(border && valence < 3 ? 4 : valence);
    for(std::size_t i = 0; i < masks.limit.size(); ++i) {
      const CGAL::Exact_rational one(1);
      CGAL::Exact_rational expected(0);
      if(!border && i < corners)
        expected = one / CGAL::Exact_rational(valence);
      else if(border && valence == 1 && i == 3)
        expected = one;
      else if(border && valence >= 2 && (i == 0 || i == corners - 1))
        expected = one / CGAL::Exact_rational(2);
      require(masks.limit[i] == expected, at + (border ? ": the limit mask of the border face is not the midpoint "
                                                         "of its border corners"
                                                       : ": the limit mask of the face is not its centroid"));
    }
    masks.tangents = false;
    return masks;
  }

  // the neighbourhood of rings + 1 rings on the analysis' own patch: its
  // first labels are those of the analysis (the walk is breadth first)
  const Patch patch = build_patch(Traits::regular_face_size, false, valence, border, masks.rings + 2);
  Neighbourhood_walk<Analysis_mesh> walk(patch.mesh);
  walk.read(patch.start, false, masks.rings + 1);
  masks.connectivity = walk.transcript;
  masks.neighbourhood_size = walk.size();
  CGAL_assertion(walk.size() >= masks.limit.size());

  // tangent masks, oriented on the planar layout (faces counter-clockwise seen from +z)
  if(analysis.tangent_mask[0].size() == masks.limit.size() && analysis.tangent_mask[1].size() == masks.limit.size()) {
    masks.tangent[0] = analysis.tangent_mask[0];
    masks.tangent[1] = analysis.tangent_mask[1];
    double t[2][2] = {{0, 0}, {0, 0}};
    const auto& centre = patch.mesh.point(walk.vertices[0]);
    for(int a = 0; a < 2; ++a)
      for(std::size_t i = 0; i < masks.limit.size(); ++i) {
        const auto& p = patch.mesh.point(walk.vertices[i]);
        t[a][0] += masks.tangent[a][i] * (p.x() - centre.x());
        t[a][1] += masks.tangent[a][i] * (p.y() - centre.y());
      }
    const double z = t[0][0] * t[1][1] - t[0][1] * t[1][0];
    const double scale = std::hypot(t[0][0], t[0][1]) * std::hypot(t[1][0], t[1][1]);
    // in doubles at high valence there is no C1 verdict: the spectrum's C1
    // conditions stand in for it (see max_exact_limit_valence)
    const bool smooth = in_double ? analysis.c1_necessary : analysis.c1;
    masks.tangents = smooth && std::abs(z) > 1e-8 * scale && scale > 0;
    if(z < 0)
      for(double& w : masks.tangent[1])
        w = -w;
  }
  return masks;
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_LIMIT_MASKS_H
