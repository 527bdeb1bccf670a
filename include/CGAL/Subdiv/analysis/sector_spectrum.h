// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_SECTOR_SPECTRUM_H
#define CGAL_SUBDIV_ANALYSIS_SECTOR_SPECTRUM_H

/// \file sector_spectrum.h
/// The spectrum of a local subdivision matrix whose sectors are alike, by
/// the discrete Fourier transform over the sectors.
///
/// At an interior vertex of valence n whose n sectors are alike (every face
/// around it has the scheme's regular face size), the local matrix commutes
/// with the rotation by one sector. The Fourier transform over the sectors
/// splits it into n blocks, one per frequency j, of the size of one sector
/// (plus the centre at j = 0): this is how Doo and Sabin (1978) and Ball and
/// Storry (1988) analyse subdivision at extraordinary vertices. The spectrum
/// is the union of the blocks' spectra; a left eigenvector of block j is
/// l(b, r) = l_b w^(-j r) over slot b of sector r, w = exp(2 pi i / n). So the
/// spectrum and the left eigenvectors the limit needs cost n solves of a few
/// rows instead of one dense solve of about n rows (seconds at valence 360).

#include <CGAL/Subdiv/analysis/curve_analysis.h>     // sort_eigenvalues
#include <CGAL/Subdiv/analysis/curve_local_matrix.h> // normalised_left_fixed_vector

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <complex>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * Up to this valence the analysis solves the local matrix densely, as it
 * always did (the generated tables come from that solve); above it, where a
 * dense solve takes a second or more, it uses the sector blocks when the
 * matrix has them.
 */
constexpr int max_dense_spectrum_valence = 24;

/*
 * The labels of a neighbourhood with n alike sectors: the centre is label 0,
 * and each "slot" (one vertex of a sector, ring by ring) has its sector-0
 * label `first` and the distance `stride` between the labels of consecutive
 * sectors (the labels of a ring run counter-clockwise, a fixed count per
 * sector).
 */
struct Sector_layout
{
  int sectors = 0;
  std::vector<Eigen::Index> first, stride;

  std::size_t slots() const { return first.size(); }
  Eigen::Index label(std::size_t slot, int sector) const { return first[slot] + stride[slot] * sector; }
};

template <class FT>
bool same_weight(const FT& a, const FT& b)
{
  if constexpr(std::is_floating_point<FT>::value)
    return std::abs(a - b) <= 1e-12 * (1 + std::abs(a) + std::abs(b));
  else
    return a == b;
}

/*
 * The layout of `S` over the labels of `ring` (the ring of every label, in
 * the canonical order) at an interior vertex of valence `valence`, if S
 * commutes with the rotation by one sector (exactly for exact FT); none
 * otherwise, e.g. when the faces around the vertex are not all alike.
 */
template <class FT>
std::optional<Sector_layout> sector_layout(const Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic>& S,
                                           const std::vector<int>& ring, int valence)
{
  const Eigen::Index m = S.rows();
  if(valence < 3 || m < 2 || static_cast<Eigen::Index>(ring.size()) != m || ring[0] != 0)
    return std::nullopt;
  Sector_layout layout;
  layout.sectors = valence;
  for(Eigen::Index start = 1; start < m;) {
    if(ring[start] <= ring[start - 1]) // the rings are not contiguous
      return std::nullopt;
    Eigen::Index end = start;
    while(end < m && ring[end] == ring[start])
      ++end;
    if((end - start) % valence != 0)
      return std::nullopt;
    const Eigen::Index per_sector = (end - start) / valence;
    for(Eigen::Index s = 0; s < per_sector; ++s) {
      layout.first.push_back(start + s);
      layout.stride.push_back(per_sector);
    }
    start = end;
  }
  std::vector<Eigen::Index> rotated(static_cast<std::size_t>(m), 0);
  for(std::size_t slot = 0; slot < layout.slots(); ++slot)
    for(int r = 0; r < valence; ++r)
      rotated[layout.label(slot, r)] = layout.label(slot, (r + 1) % valence);
  for(Eigen::Index i = 0; i < m; ++i)
    for(Eigen::Index j = 0; j < m; ++j)
      if(!same_weight(S(rotated[i], rotated[j]), S(i, j)))
        return std::nullopt;
  return layout;
}

// w^(j d), w = exp(2 pi i / n)
inline std::complex<double> root_of_unity_power(int j, int d, int n)
{
  const double angle = 2 * 3.14159265358979323846 * static_cast<double>((static_cast<long>(j) * d) % n) / n;
  return {std::cos(angle), std::sin(angle)};
}

/*
 * Frequency 0 with the centre: label 0 the centre, 1 + b slot b (a vector
 * constant over the sectors). Its rows sum to one as S's do.
 */
template <class FT>
Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic> sector_block_0(
  const Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic>& S, const Sector_layout& layout)
{
  const Eigen::Index k = static_cast<Eigen::Index>(layout.slots());
  Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic> B(k + 1, k + 1);
  B(0, 0) = S(0, 0);
  for(Eigen::Index b = 0; b < k; ++b) {
    FT from_centre(0);
    for(int d = 0; d < layout.sectors; ++d)
      from_centre += S(0, layout.label(b, d));
    B(0, 1 + b) = from_centre;
    B(1 + b, 0) = S(layout.label(b, 0), 0);
  }
  for(Eigen::Index a = 0; a < k; ++a)
    for(Eigen::Index b = 0; b < k; ++b) {
      FT sum(0);
      for(int d = 0; d < layout.sectors; ++d)
        sum += S(layout.label(a, 0), layout.label(b, d));
      B(1 + a, 1 + b) = sum;
    }
  return B;
}

// frequency j = 1 .. n-1 (the centre takes no part)
inline Eigen::MatrixXcd sector_block(const Eigen::MatrixXd& D, const Sector_layout& layout, int j)
{
  const Eigen::Index k = static_cast<Eigen::Index>(layout.slots());
  Eigen::MatrixXcd B = Eigen::MatrixXcd::Zero(k, k);
  for(int d = 0; d < layout.sectors; ++d) {
    const std::complex<double> w = root_of_unity_power(j, d, layout.sectors);
    for(Eigen::Index a = 0; a < k; ++a)
      for(Eigen::Index b = 0; b < k; ++b)
        B(a, b) += D(layout.label(a, 0), layout.label(b, d)) * w;
  }
  return B;
}

/*
 * The spectrum of D, sorted as `sorted_eigenvalues` sorts it, and the
 * frequency of every eigenvalue; empty if a block's solver failed.
 */
struct Sector_spectrum
{
  std::vector<std::complex<double>> eigenvalues;
  std::vector<int> frequency;
};

inline Sector_spectrum sector_spectrum(const Eigen::MatrixXd& D, const Sector_layout& layout)
{
  std::vector<std::pair<std::complex<double>, int>> found;
  {
    Eigen::EigenSolver<Eigen::MatrixXd> solver(sector_block_0(D, layout), false);
    if(solver.info() != Eigen::Success)
      return {};
    for(Eigen::Index i = 0; i < solver.eigenvalues().size(); ++i)
      found.emplace_back(solver.eigenvalues()[i], 0);
  }
  for(int j = 1; j < layout.sectors; ++j) {
    Eigen::ComplexEigenSolver<Eigen::MatrixXcd> solver(sector_block(D, layout, j), false);
    if(solver.info() != Eigen::Success)
      return {};
    for(Eigen::Index i = 0; i < solver.eigenvalues().size(); ++i)
      found.emplace_back(solver.eigenvalues()[i], j);
  }
  Sector_spectrum result;
  for(const auto& value : found)
    result.eigenvalues.push_back(value.first);
  sort_eigenvalues(result.eigenvalues);
  // the frequency of each sorted value: the nearest unused one found
  std::vector<bool> used(found.size(), false);
  for(const std::complex<double>& value : result.eigenvalues) {
    std::size_t best = 0;
    double distance = -1;
    for(std::size_t i = 0; i < found.size(); ++i)
      if(!used[i] && (distance < 0 || std::abs(found[i].first - value) < distance)) {
        best = i;
        distance = std::abs(found[i].first - value);
      }
    used[best] = true;
    result.frequency.push_back(found[best].second);
  }
  return result;
}

/*
 * The left fixed vector of S, summing to 1, from frequency 0: with l the
 * fixed vector of block 0 (sum 1), the centre takes l_0 and every vertex of
 * slot b takes l_b / n. Exact for exact FT. It is unique in block 0; the
 * caller checks from the spectrum that 1 is in no other block.
 */
template <class FT>
std::vector<FT> left_fixed_vector_over_sectors(const Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic>& S,
                                               const Sector_layout& layout)
{
  const std::vector<FT> block = normalised_left_fixed_vector(sector_block_0(S, layout));
  if(block.empty())
    return {};
  std::vector<FT> full(static_cast<std::size_t>(S.rows()), FT(0));
  full[0] = block[0];
  for(std::size_t b = 0; b < layout.slots(); ++b)
    for(int r = 0; r < layout.sectors; ++r)
      full[static_cast<std::size_t>(layout.label(b, r))] = block[1 + b] / FT(layout.sectors);
  return full;
}

/*
 * A left eigenvector of D for the eigenvalue of block j (1 <= j < n) nearest
 * `lambda`: l(b, r) = l_b w^(-j r), zero at the centre. Its real and
 * imaginary parts span the real left eigenvectors of frequencies j and n - j.
 * Empty if the solver failed.
 */
inline Eigen::VectorXcd sector_left_eigenvector(const Eigen::MatrixXd& D, const Sector_layout& layout, int j,
                                                std::complex<double> lambda)
{
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> solver(sector_block(D, layout, j).transpose(), true);
  if(solver.info() != Eigen::Success || solver.eigenvalues().size() == 0)
    return {};
  Eigen::Index nearest = 0;
  for(Eigen::Index i = 1; i < solver.eigenvalues().size(); ++i)
    if(std::abs(solver.eigenvalues()[i] - lambda) < std::abs(solver.eigenvalues()[nearest] - lambda))
      nearest = i;
  Eigen::VectorXcd full = Eigen::VectorXcd::Zero(D.rows());
  for(std::size_t b = 0; b < layout.slots(); ++b)
    for(int r = 0; r < layout.sectors; ++r)
      full[layout.label(b, r)] = solver.eigenvectors()(static_cast<Eigen::Index>(b), nearest) *
                                 std::conj(root_of_unity_power(j, r, layout.sectors));
  return full;
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_SECTOR_SPECTRUM_H
