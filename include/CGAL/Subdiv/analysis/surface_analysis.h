// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_SURFACE_ANALYSIS_H
#define CGAL_SUBDIV_ANALYSIS_SURFACE_ANALYSIS_H

/// \file surface_analysis.h
/// Eigen-analysis of surface schemes at extraordinary vertices (and faces),
/// from the schemes' own masks: spectrum, C1 conditions, characteristic map,
/// limit and tangent masks, and a check of the limit mask by refinement.

#include <CGAL/Subdiv/analysis/Analysis_status.h>
#include <CGAL/Subdiv/analysis/Configuration.h>
#include <CGAL/Subdiv/analysis/analysis_result.h>
#include <CGAL/Subdiv/analysis/characteristic_map.h>
#include <CGAL/Subdiv/analysis/curve_analysis.h>     // sort_eigenvalues, to_double_matrix
#include <CGAL/Subdiv/analysis/curve_local_matrix.h> // exact ranks, left fixed vector
#include <CGAL/Subdiv/analysis/rational_eigenvalues.h>
#include <CGAL/Subdiv/analysis/sector_spectrum.h>
#include <CGAL/Subdiv/analysis/surface_neighbourhood.h>
#include <CGAL/Subdiv/analysis/verify_limit.h>
#include <CGAL/Subdiv/errors.h>
#include <CGAL/Subdiv/parameters.h>
#include <CGAL/assertions.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Subdiv {

namespace internal {

// the tangent masks of `result` from a basis (a, b) of the subdominant left
// eigenspace, put in the canonical basis
template <class FT>
void set_tangent_pair(Eigen::VectorXd a, Eigen::VectorXd b, Surface_analysis<FT>& result)
{
  canonical_pair(a, b);
  result.tangent_mask[0].assign(a.data(), a.data() + a.size());
  result.tangent_mask[1].assign(b.data(), b.data() + b.size());
}

// the tangent masks from a dense left eigen-solve: the real and imaginary
// parts of lambda_1's left eigenvector if it is complex, else the left
// eigenvectors of lambda_1 and lambda_2; put in the canonical basis
template <class FT>
void dense_tangent_pair(const Eigen::MatrixXd& D, const std::vector<std::complex<double>>& ev,
                        Surface_analysis<FT>& result)
{
  const Eigen::Index m = D.rows();
  Eigen::EigenSolver<Eigen::MatrixXd> left(D.transpose(), true);
  if(left.info() != Eigen::Success) {
    result.status = Analysis_status::no_convergence;
    return;
  }
  std::vector<Eigen::Index> near; // eigenvalues of the pair: lambda_1 first
  for(const std::complex<double>& target : {ev[1], ev.size() > 2 ? ev[2] : ev[1]})
    for(Eigen::Index i = 0; i < m; ++i)
      if(std::abs(left.eigenvalues()[i] - target) < 1e-7 && std::find(near.begin(), near.end(), i) == near.end()) {
        near.push_back(i);
        break;
      }
  Eigen::VectorXd a, b;
  if(std::abs(ev[1].imag()) > 1e-12 && !near.empty()) {
    a = left.eigenvectors().col(near[0]).real();
    b = left.eigenvectors().col(near[0]).imag();
  } else if(near.size() >= 2) {
    a = left.eigenvectors().col(near[0]).real();
    b = left.eigenvectors().col(near[1]).real();
  }
  if(a.size() == m)
    set_tangent_pair(a, b, result);
}

/*
 * The side of every label of a crease's neighbourhood of `rings` rings: 0 on
 * the crease (the centre and the sharp rays), 1 on the first side (between
 * rays 0 and `first_side` counter-clockwise), 2 on the second; read from the
 * planar layout of the patch (`build_patch`, `tag_patch`).
 */
template <class Mask>
std::vector<int> crease_sides(const Mask& mask, const Configuration& where, int rings)
{
  const Patch patch = analysis_patch(mask, where, rings);
  const Labelling labels = label_neighbourhood(patch.mesh, patch.start, false, rings);
  const auto& centre = patch.mesh.point(patch.mesh.source(patch.start));
  const double two_pi = 2 * 3.14159265358979323846;
  const double split = two_pi * where.first_side / where.valence;
  const auto on_ray = [](double x, double y, double angle) {
    const double dx = std::cos(angle), dy = std::sin(angle);
    return std::abs(x * dy - y * dx) < 1e-9 && x * dx + y * dy > 0;
  };
  std::vector<int> side;
  for(Analysis_vertex v : labels.vertex_of) {
    const double x = patch.mesh.point(v).x() - centre.x(), y = patch.mesh.point(v).y() - centre.y();
    double angle = std::atan2(y, x);
    if(angle < 0)
      angle += two_pi;
    if(std::hypot(x, y) < 1e-12 || on_ray(x, y, 0) || on_ray(x, y, split))
      side.push_back(0);
    else
      side.push_back(angle < split ? 1 : 2);
  }
  return side;
}

/*
 * A crease's sides (`Surface_analysis::block_triangular`, `sides`): the
 * block structure of the matrix, and for each side the spectrum of its block
 * against the border analysis of as many faces (`border`), whose verdicts
 * the side takes.
 */
template <class FT, class Border>
void analyse_crease_sides(const std::vector<int>& side, const Border& border, Surface_analysis<FT>& result)
{
  const Eigen::Index m = result.matrix.rows();
  result.block_triangular = true;
  for(Eigen::Index i = 0; i < m; ++i)
    for(Eigen::Index j = 0; j < m; ++j)
      if(result.matrix(i, j) != FT(0) && side[j] != 0 && side[j] != side[i])
        result.block_triangular = false;
  result.sides.clear();
  const Eigen::MatrixXd D = to_double_matrix(result.matrix);
  for(int s = 1; s <= 2; ++s) {
    typename Surface_analysis<FT>::Side one;
    one.faces = s == 1 ? result.configuration.first_side : result.configuration.second_side();
    std::vector<Eigen::Index> kept;
    for(Eigen::Index i = 0; i < m; ++i)
      if(side[static_cast<std::size_t>(i)] == 0 || side[static_cast<std::size_t>(i)] == s)
        kept.push_back(i);
    Eigen::MatrixXd block(kept.size(), kept.size());
    for(std::size_t a = 0; a < kept.size(); ++a)
      for(std::size_t b = 0; b < kept.size(); ++b)
        block(a, b) = D(kept[a], kept[b]);
    one.eigenvalues = sorted_eigenvalues(block);
    const auto border_analysis = border(one.faces);
    // the same multiset, each eigenvalue matched with the nearest unmatched
    // one: 1e-6, since a defective eigenvalue (a Jordan block) is found to
    // about sqrt(machine epsilon) only, and not always in the same order
    std::vector<std::complex<double>> unmatched = border_analysis.eigenvalues;
    one.same_as_border = one.eigenvalues.size() == unmatched.size();
    for(std::size_t k = 0; one.same_as_border && k < one.eigenvalues.size(); ++k) {
      std::size_t nearest = 0;
      for(std::size_t j = 1; j < unmatched.size(); ++j)
        if(std::abs(unmatched[j] - one.eigenvalues[k]) < std::abs(unmatched[nearest] - one.eigenvalues[k]))
          nearest = j;
      one.same_as_border = std::abs(unmatched[nearest] - one.eigenvalues[k]) < 1e-6;
      unmatched.erase(unmatched.begin() + static_cast<std::ptrdiff_t>(nearest));
    }
    one.c1_necessary = border_analysis.c1_necessary;
    one.extended_spectrum_ok = border_analysis.extended_spectrum_ok;
    one.characteristic_map = border_analysis.characteristic_map;
    one.c1 = border_analysis.c1;
    result.sides.push_back(one);
  }
  // the crease's verdicts: both sides' (each a border with its faces)
  const auto& a = result.sides[0];
  const auto& b = result.sides[1];
  const bool sides_are_borders = result.block_triangular && a.same_as_border && b.same_as_border;
  result.c1_necessary = result.one_is_simple_and_dominant && sides_are_borders && a.c1_necessary && b.c1_necessary;
  result.extended_spectrum_ok = a.extended_spectrum_ok && b.extended_spectrum_ok;
  result.characteristic_map =
    a.characteristic_map != Characteristic_map_verdict::regular_injective ? a.characteristic_map : b.characteristic_map;
  result.c1 = result.c1_necessary && a.c1 && b.c1;
}

} // namespace internal

/*!
 * \ingroup PkgSubdivAnalysis
 * analyses a surface scheme at `where`: an interior vertex of valence
 * `valence`, or a border vertex with `valence` faces, or, for a dual scheme
 * (`Dual_split`: Doo-Sabin), an interior face with `valence` corners (or, at
 * the border, the border face made from a border vertex with `valence`
 * faces, see below); all
 * other vertices of the neighbourhood are regular (see
 * `local_subdivision_matrix()`). As in [Reif 1995, "A unified approach to
 * subdivision algorithms near extraordinary vertices"] and [Zorin 2000,
 * "Smoothness of stationary subdivision on irregular meshes"]:
 *
 * 1. the local subdivision matrix S of the smallest invariant neighbourhood,
 *    assembled in FT from the scheme's own host and mask (exact where the
 *    weights are rational); its rows must sum to 1;
 * 2. its eigenvalues (Eigen's `EigenSolver` in double), rational ones
 *    confirmed exactly; whether 1 is simple and dominant (its algebraic
 *    multiplicity is computed exactly for exact FT); the subdominant
 *    eigenvalue lambda_1 and its multiplicity; the necessary condition for
 *    C1, lambda_1 = lambda_2 real > |lambda_3| (at a border vertex
 *    lambda_1 >= lambda_2 > |lambda_3|, both real, as in [Zorin 2000]: the
 *    border curve and the interior have eigenvalues of their own);
 * 3. the limit mask: the left eigenvector of 1 normalised to sum 1, solved
 *    exactly in FT (Gaussian elimination); the tangent masks: left
 *    eigenvectors of the subdominant pair (double);
 * 4. the extended spectrum: the matrix of a larger neighbourhood (2r + 2
 *    rings, in double) must have no eigenvalue other than 1 and the
 *    subdominant pair of modulus >= |lambda_1|: eigenvalues of the outer
 *    rings would otherwise dominate the tangent plane;
 * 5. the characteristic map [Reif 1995]: the two real eigenvectors of the
 *    subdominant pair of the larger matrix (real and imaginary part for a
 *    complex pair) are the x and y of a planar control net over the larger
 *    neighbourhood, refined by the real host and the mask (in double) until
 *    the part of the net that the patch border has not reached (tracked
 *    through the stencils) covers 24 rings, at most 8 levels and about
 *    `options.max_faces` faces. If that part stays under 6 rings (wide
 *    stencils: interpolating sqrt3 at n != 6, whose invariant neighbourhood
 *    is the one-ring), steps 4 and 5 are redone with 2 more rings, up to
 *    2r + 8 (`extended_rings` is the count used). The net over the annulus of rings
 *    [outer / g - 1, outer] (g = 2, or 3 for two sqrt3 steps) is tested:
 *    regular if every corner of every face turns the same way (cross product
 *    beyond 1e-12 times the squared radius of the annulus: the faces are
 *    strictly convex and consistently oriented); injective if moreover the
 *    boundary of the annulus is made of simple, pairwise disjoint closed
 *    polygons: for an interior vertex two, winding once around the origin
 *    (the image of the centre) in opposite directions, for a border vertex
 *    one, oriented as the faces. By the degree argument, a consistently
 *    oriented net whose boundary is such is one-to-one, and by the scaling
 *    S x = lambda x the annuli of all levels tile a punctured neighbourhood of
 *    the origin;
 * 6. the verdict `c1`: 1 simple and dominant, the C1 condition, the extended
 *    spectrum and a regular injective characteristic map. For a complex
 *    subdominant pair the characteristic map is still tested but `c1` is
 *    false;
 * 7. verification of the limit mask (`options.verify_limit`): a patch of the
 *    neighbourhood and two more rings, with random points in [-1, 1]^3, is
 *    refined by the real host and mask (double) while it stays under
 *    `max_faces` (`host_error`, of order |lambda_1|^levels), then cropped
 *    back to those rings and refined again, level after level, until the
 *    centre moves less than 1e-15 of the diameter: `limit_error` is its
 *    distance to the point the limit mask predicts, relative to the diameter
 *    of the neighbourhood.
 *
 * Schemes with a mask for border vertices are analysed at border vertices,
 * the sqrt3 schemes too: their border is refined on every second step only,
 * and the analysed double step at a border vertex is a resting step followed
 * by a refining step (a freshly built patch rests first, as a mesh read from
 * a file; the neighbourhood is invariant over the pair, which splits the
 * border 1-to-3 like the interior). Doo-Sabin (dual, centred at a face) is
 * analysed at the border face made from a border vertex with `valence` = k
 * faces: the face the host makes of the corners at that vertex (k >= 3: its
 * vertex face, a k-gon with a border edge; k = 2: the edge quad of the
 * interior edge at it, on the regular border; k = 1: the face face of its
 * single face, a corner). Its neighbourhood is not one of regular vertices
 * (the border corners of a border k-gon have 3 faces and a border triangle
 * beside them, at every level): the patches are made by refinement, as real
 * meshes have them (`internal::border_face_patch`).
 *
 * Sharp vertices (`Configuration::crease()`, `dart()`, `corner()`; schemes
 * that take sharpness tags: Loop, Catmull-Clark): the interior patch carries
 * infinitely sharp tags (10) along whole rays of edges, or a vertex
 * sharpness of 10 at a corner, and is refined through `Sharpness_tags` as
 * `subdivide()` refines a tagged mesh, so the rules are OpenSubdiv's, taken
 * from the masks. A dart or a corner has no rotational symmetry that would
 * make lambda_1 = lambda_2: the condition is the border's, lambda_1 >=
 * lambda_2 > |lambda_3|, and the characteristic map is tested over the whole
 * neighbourhood as at an interior vertex. A crease vertex is judged by its
 * sides: its matrix is block triangular (the crease rows read the crease
 * only, neither side reads the other, `block_triangular`), each side's block
 * (the crease and that side) is refined as a border with as many faces, which
 * is checked on its spectrum, and the side takes the verdicts of the border
 * analysis of as many faces (`sides`); the crease is C1 on both sides when
 * both are. Semi-sharp tags have no stationary local matrix (their sharpness
 * decays with the level) and are not analysed.
 *
 * \tparam FT exact field type of the matrix (default `CGAL::Exact_rational`)
 * \param any_mask the scheme: a mask over any mesh type and number type, with
 *         its options (a tension, a `Border_corners` value, ...); it is rebound
 *         to `Analysis_mesh` with FT (the matrix) and with `double`
 *         (characteristic map, verification)
 * \param where the configuration (`Configuration`: valence, interior or border)
 * \param np named parameters: `characteristic_map` (default true),
 *         `verify_limit` (default true), `max_faces` (default 120000), `seed`
 *         (default 20260)
 * \returns the analysis; its `status` says whether every step ran
 * \throws Bad_input for an impossible configuration
 */
template <class FT = CGAL::Exact_rational, class AnyMask, class NamedParameters = parameters::Default_named_parameters>
Surface_analysis<FT> analyse_surface_scheme(const AnyMask& any_mask, const Configuration& where,
                                            const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto mask = any_mask.template rebind<Analysis_mesh, FT>();
  const auto double_mask = any_mask.template rebind<Analysis_mesh, double>();
  using Traits = Host_of<std::decay_t<decltype(mask)>>;
  internal::Surface_analysis_options options;
  options.extended_spectrum = choose_parameter(get_parameter(np, internal::extended_spectrum_t()), true);
  options.characteristic_map = choose_parameter(get_parameter(np, internal::characteristic_map_t()), true);
  options.verify_limit = choose_parameter(get_parameter(np, internal::verify_limit_t()), true);
  options.max_faces = choose_parameter(get_parameter(np, internal::max_faces_t()), options.max_faces);
  options.seed = choose_parameter(get_parameter(np, internal::seed_t()), options.seed);
  const int valence = where.valence;
  const bool boundary = where.on_border();
  Surface_analysis<FT> result;
  result.scheme = mask.name();
  result.valence = valence;
  result.boundary = boundary;
  result.configuration = where;
  result.face_centred = Traits::face_centred;

  // 1. the matrix
  Local_subdivision_matrix<FT> local = local_subdivision_matrix<FT>(any_mask, where);
  result.matrix = local.S;
  result.ring = local.ring;
  result.rings = local.rings;
  const Eigen::Index m = result.matrix.rows();
  result.exact = !std::is_floating_point<FT>::value;
  result.rows_sum_to_one = true;
  for(Eigen::Index r = 0; r < m; ++r) {
    FT sum(0);
    for(Eigen::Index c = 0; c < m; ++c) {
      sum += result.matrix(r, c);
      if(result.exact && !internal::has_small_denominator(result.matrix(r, c)))
        result.exact = false;
    }
    result.rows_sum_to_one = result.rows_sum_to_one && internal::is_negligible(FT(sum - FT(1)), FT(1));
  }

  // 2. the spectrum
  if(!result.rows_sum_to_one)
    result.status = Analysis_status::not_affine_invariant;
  const Eigen::MatrixXd D = internal::to_double_matrix(result.matrix);
  // high valence: the spectrum by frequency, when the sectors are alike
  const std::optional<internal::Sector_layout> sectors =
    !boundary && !Traits::face_centred && valence > internal::max_dense_spectrum_valence
      ? internal::sector_layout(result.matrix, result.ring, valence)
      : std::nullopt;
  internal::Sector_spectrum by_frequency;
  if(sectors) {
    by_frequency = internal::sector_spectrum(D, *sectors);
    result.eigenvalues = by_frequency.eigenvalues;
  } else
    result.eigenvalues = internal::sorted_eigenvalues(D);
  if(result.eigenvalues.size() != static_cast<std::size_t>(D.rows())) { // the solver did not converge
    result.status = Analysis_status::no_convergence;
    return result;
  }
  // a sharp vertex: the crease curve's 1/2, 1/4, 1/8 may be defective (a
  // Jordan block with a side's equal eigenvalue), which a double solver finds
  // to about sqrt(machine epsilon) only; they are confirmed exactly first, as
  // for curves (up to 64 x 64)
  if constexpr(!std::is_floating_point<FT>::value)
    if(where.sharp())
      internal::snap_dyadic_eigenvalues(result.matrix, result.eigenvalues, 64);
  internal::confirm_rational_eigenvalues(result.matrix, result.eigenvalues, result.exact_eigenvalues);
  const auto& ev = result.eigenvalues;
  if(ev.size() < 2)
    return result;
  const double tol = 1e-8;
  int ones = 0;
  bool others_inside = true;
  for(const auto& value : ev) {
    if(std::abs(value - 1.0) < tol)
      ++ones;
    else if(std::abs(value) >= 1 - tol)
      others_inside = false;
  }
  if constexpr(!std::is_floating_point<FT>::value)
    ones = internal::algebraic_multiplicity(result.matrix, FT(1));
  result.one_is_simple_and_dominant = ones == 1 && others_inside && std::abs(ev[0] - 1.0) < tol;
  result.subdominant = ev[1];
  result.second_subdominant = ev.size() > 2 ? ev[2] : std::complex<double>(0, 0);
  result.subdominant_multiplicity = 0;
  for(const auto& value : ev)
    if(std::abs(value - ev[1]) < tol)
      ++result.subdominant_multiplicity;
  const bool real_pair =
    ev.size() >= 3 && std::abs(ev[1].imag()) < tol && std::abs(ev[2].imag()) < tol && ev[2].real() > tol;
  const bool gap = ev.size() < 4 || std::abs(ev[3]) < ev[2].real() - tol;
  if(where.kind != Vertex_kind::interior) // border, sharp: no symmetry makes lambda_1 = lambda_2
    result.c1_necessary = result.one_is_simple_and_dominant && real_pair && gap;
  else
    result.c1_necessary = result.one_is_simple_and_dominant && real_pair && result.subdominant_multiplicity == 2 && gap;

  // 3. limit and tangent masks
  if(sectors) {
    if(ones == 1)
      result.limit_mask = internal::left_fixed_vector_over_sectors(result.matrix, *sectors);
    const int j = by_frequency.frequency[1]; // the subdominant's
    if(j != 0 && 2 * j != valence) {
      const Eigen::VectorXcd l = internal::sector_left_eigenvector(D, *sectors, j, ev[1]);
      if(l.size() == m)
        internal::set_tangent_pair(l.real(), l.imag(), result);
    }
  } else {
    result.limit_mask = internal::normalised_left_fixed_vector(result.matrix);
    internal::dense_tangent_pair(D, ev, result);
  }

  // 4.-6. extended spectrum, characteristic map, verdict; a crease by its sides
  if(where.kind == Vertex_kind::crease) {
    const auto border = [&](int k) {
      return analyse_surface_scheme<FT>(any_mask, Configuration(k, Vertex_kind::border),
                                        parameters::verify_limit(false)
                                          .characteristic_map(options.characteristic_map)
                                          .extended_spectrum(options.extended_spectrum)
                                          .max_faces(options.max_faces));
    };
    internal::analyse_crease_sides(internal::crease_sides(mask, where, result.rings), border, result);
  } else if(result.one_is_simple_and_dominant && options.extended_spectrum)
    internal::characteristic_map_and_extended_spectrum(double_mask, result, options);
  if(where.kind != Vertex_kind::crease)
    result.c1 = result.one_is_simple_and_dominant && result.c1_necessary && result.extended_spectrum_ok &&
                result.characteristic_map == Characteristic_map_verdict::regular_injective;

  // 7. verification of the limit mask
  if(options.verify_limit && !result.limit_mask.empty() && result.one_is_simple_and_dominant) {
    std::vector<double> mask_double;
    for(const FT& w : result.limit_mask)
      mask_double.push_back(CGAL::to_double(w));
    internal::verify_limit(double_mask, result, mask_double, options);
  }
  return result;
}

/*!
 * \ingroup PkgSubdivAnalysis
 * `analyse_surface_scheme(mask, Configuration(valence))`: the analysis at an
 * interior vertex (or face) of the given valence, as in the design sketch
 * `analyse(Loop_mask<Mesh>(), valence)`.
 */
template <class Mask>
Surface_analysis<CGAL::Exact_rational> analyse(const Mask& mask, int valence)
{
  return analyse_surface_scheme(mask, Configuration(valence));
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_SURFACE_ANALYSIS_H
