// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ANALYSIS_CURVE_LOCAL_MATRIX_H
#define CGAL_SUBDIV_ANALYSIS_CURVE_LOCAL_MATRIX_H

/// \file curve_local_matrix.h
/// The local subdivision matrix of a binary curve scheme around one old point,
/// assembled from the scheme's masks, and exact linear algebra on it.

#include <CGAL/Subdiv/analysis/curve_symbol.h>
#include <CGAL/Subdiv/curves/curve_mask.h>
#include <CGAL/Subdiv/errors.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * The smallest invariant window [L, R] of offsets that contains [-1, 1]:
 * every new point at position q in [L, R] (q = 2i + parity, the rule of that
 * parity reading old points i + [lo, hi]) reads only old points in [L, R].
 * The window grows from [-1, 1] until it is closed under this rule; it stops
 * because a window of width w only asks for width about w/2 + support.
 *
 * Cubic B-spline: [-1, 1]; Chaikin and corner cutting: [-1, 1];
 * four-point: [-2, 2].
 */
template <class Scheme>
std::pair<int, int> invariant_window(const Scheme& scheme)
{
  const std::pair<int, int> support[2] = {rule_support(scheme, 0), rule_support(scheme, 1)};
  int L = -1, R = 1;
  for(int round = 0; round < 4096; ++round) {
    int new_L = L, new_R = R;
    for(int q = L; q <= R; ++q) {
      const int parity = ((q % 2) + 2) % 2;
      const int i = (q - parity) / 2;
      new_L = (std::min)(new_L, i + support[parity].first);
      new_R = (std::max)(new_R, i + support[parity].second);
    }
    if(new_L == L && new_R == R)
      return {L, R};
    L = new_L;
    R = new_R;
  }
  throw Bad_input("the masks of " + scheme.name() + " have no invariant window");
}

/*!
 * \ingroup PkgSubdivAnalysis
 * The local subdivision matrix S of the invariant window [L, R]
 * (`invariant_window()`): row q - L holds the weights of the new point at
 * position q over the old points at offsets L..R, so that
 * new window = S * old window. The rows are filled by calling the scheme's
 * masks through an accumulator that maps an offset to a column; nothing is
 * typed in. Exact for exact `FT`. For the cubic B-spline:
 * \f$ S = \frac18 \begin{pmatrix} 4 & 4 & 0 \\ 1 & 6 & 1 \\ 0 & 4 & 4 \end{pmatrix} \f$.
 */
template <class Scheme>
Eigen::Matrix<typename Scheme::Number_type, Eigen::Dynamic, Eigen::Dynamic> local_subdivision_matrix(
  const Scheme& scheme)
{
  using FT = typename Scheme::Number_type;
  using Matrix = Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic>;
  const std::pair<int, int> window = invariant_window(scheme);
  const int L = window.first, n = window.second - window.first + 1;
  Matrix S(n, n);
  for(int r = 0; r < n; ++r)
    for(int c = 0; c < n; ++c)
      S(r, c) = FT(0);
  // the matrix recorder: offset i + k of the old point -> column i + k - L
  struct Row_acc
  {
    Matrix& S;
    int row, i, L;
    void add(int k, const FT& w) { S(row, i + k - L) += w; }
  };
  for(int q = window.first; q <= window.second; ++q) {
    const int parity = ((q % 2) + 2) % 2;
    Row_acc acc{S, q - L, (q - parity) / 2, L};
    if(parity == 0)
      scheme.even_mask(acc);
    else
      scheme.odd_mask(acc);
  }
  return S;
}

/*!
 * \ingroup PkgSubdivAnalysis
 * The shift \f$ \sigma = -2 \sum_k k\, w_k \f$ of the even rule: in the
 * scheme's own parametrisation old point i sits at parameter \f$ i + \sigma \f$
 * and new point j at \f$ (j + \sigma) / 2 \f$ (in units of the old spacing).
 * Zero for primal symmetric schemes (odd-degree B-splines, four-point),
 * -1/2 for Chaikin, -2a for corner cutting.
 */
template <class Scheme>
typename Scheme::Number_type parametric_shift(const Scheme& scheme)
{
  using FT = typename Scheme::Number_type;
  FT moment(0);
  const auto even = rule(scheme, 0); // a named stencil: terms() of a temporary would dangle
  for(const auto& term : even.terms())
    moment += FT(term.first) * term.second;
  return FT(-2) * moment;
}

/*!
 * \ingroup PkgSubdivAnalysis
 * true if the scheme reproduces linear functions in its own parametrisation:
 * with \f$ \sigma \f$ = `parametric_shift(scheme)`, both rules map the samples
 * \f$ i + \sigma \f$ to \f$ (j + \sigma)/2 \f$, i.e. both rules sum to 1 and
 * \f$ \sum_k k\, w^{odd}_k = \frac12 + \sum_k k\, w^{even}_k \f$. Exact for exact
 * `FT`. True for B-splines, Chaikin, four-point; for corner cutting exactly
 * when b = a + 1/2.
 */
template <class Scheme>
bool reproduces_linear(const Scheme& scheme)
{
  using FT = typename Scheme::Number_type;
  const auto even = rule(scheme, 0), odd = rule(scheme, 1);
  FT even_moment(0), odd_moment(0);
  for(const auto& term : even.terms())
    even_moment += FT(term.first) * term.second;
  for(const auto& term : odd.terms())
    odd_moment += FT(term.first) * term.second;
  const FT one(1);
  return internal::is_negligible(FT(even.weight_sum() - one), one) &&
         internal::is_negligible(FT(odd.weight_sum() - one), one) &&
         internal::is_negligible(FT(odd_moment - even_moment - one / FT(2)), one);
}

namespace internal {

/*
 * Solves the left eigenproblem v^T S = lambda v^T, w . v = 1, by Gaussian
 * elimination on the (n+1) x n system [S^T - lambda I; w^T] v = [0; 1].
 * Exact types: the first nonzero pivot, exact zero tests. Floating point:
 * partial pivoting and a relative tolerance. Returns an empty vector if the
 * solution is not unique (lambda not a simple eigenvalue) or does not exist
 * (w orthogonal to the eigenvector).
 */
template <class FT>
std::vector<FT> normalised_left_eigenvector(const Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic>& S,
                                            const FT& lambda, const std::vector<FT>& w)
{
  const int n = static_cast<int>(S.rows());
  CGAL_precondition(w.size() == static_cast<std::size_t>(n));
  std::vector<std::vector<FT>> A(static_cast<std::size_t>(n + 1),
                                 std::vector<FT>(static_cast<std::size_t>(n + 1), FT(0)));
  FT scale(1);
  for(int r = 0; r < n; ++r)
    for(int c = 0; c < n; ++c) {
      A[r][c] = S(c, r) - (r == c ? lambda : FT(0));
      if(internal::absolute(A[r][c]) > scale)
        scale = internal::absolute(A[r][c]);
    }
  for(int k = 0; k < n; ++k)
    A[n][k] = w[k];
  A[n][n] = FT(1); // right-hand side column
  int row = 0;
  for(int col = 0; col < n; ++col, ++row) {
    int pivot = -1;
    for(int r = row; r <= n; ++r) {
      if(internal::is_negligible(A[r][col], scale))
        continue;
      if constexpr(std::is_floating_point<FT>::value) {
        if(pivot < 0 || std::abs(A[r][col]) > std::abs(A[pivot][col]))
          pivot = r;
      } else {
        pivot = r;
        break;
      }
    }
    if(pivot < 0)
      return {}; // rank deficient: the fixed vector is not unique
    std::swap(A[row], A[pivot]);
    for(int r = 0; r <= n; ++r) {
      if(r == row || A[r][col] == FT(0))
        continue;
      const FT factor = A[r][col] / A[row][col];
      for(int c = col; c <= n; ++c)
        A[r][c] = A[r][c] - factor * A[row][c];
    }
  }
  // the one row left over must read 0 = 0
  if(!internal::is_negligible(A[n][n], scale))
    return {};
  std::vector<FT> v(static_cast<std::size_t>(n));
  for(int k = 0; k < n; ++k)
    v[k] = A[k][n] / A[k][k];
  return v;
}

/*
 * The left fixed vector of S: v^T S = v^T, sum v = 1
 * (`normalised_left_eigenvector` for 1); empty if 1 is not a simple eigenvalue.
 */
template <class FT>
std::vector<FT> normalised_left_fixed_vector(const Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic>& S)
{
  return normalised_left_eigenvector(S, FT(1), std::vector<FT>(static_cast<std::size_t>(S.rows()), FT(1)));
}

/*
 * Rank of a matrix by Gaussian elimination: exact for exact types (first
 * nonzero pivot), partial pivoting with a relative tolerance for floating
 * point. Used to tell a Jordan block from a repeated eigenvalue with two
 * eigenvectors: rank(S - lambda I).
 */
template <class FT>
int matrix_rank(Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic> A)
{
  const int rows = static_cast<int>(A.rows()), cols = static_cast<int>(A.cols());
  FT scale(1);
  for(int r = 0; r < rows; ++r)
    for(int c = 0; c < cols; ++c)
      if(internal::absolute(A(r, c)) > scale)
        scale = internal::absolute(A(r, c));
  int rank = 0;
  for(int col = 0; col < cols && rank < rows; ++col) {
    int pivot = -1;
    for(int r = rank; r < rows; ++r) {
      if(internal::is_negligible(A(r, col), scale))
        continue;
      if constexpr(std::is_floating_point<FT>::value) {
        if(pivot < 0 || std::abs(A(r, col)) > std::abs(A(pivot, col)))
          pivot = r;
      } else {
        pivot = r;
        break;
      }
    }
    if(pivot < 0)
      continue;
    for(int c = 0; c < cols; ++c)
      std::swap(A(rank, c), A(pivot, c));
    for(int r = rank + 1; r < rows; ++r) {
      if(A(r, col) == FT(0))
        continue;
      const FT factor = A(r, col) / A(rank, col);
      for(int c = col; c < cols; ++c)
        A(r, c) = A(r, c) - factor * A(rank, c);
    }
    ++rank;
  }
  return rank;
}

/*
 * Algebraic multiplicity of lambda as an eigenvalue of the square matrix S:
 * dim ker (S - lambda I)^k once it stops growing (exact for exact types).
 */
template <class FT>
int algebraic_multiplicity(const Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic>& S, const FT& lambda)
{
  using Matrix = Eigen::Matrix<FT, Eigen::Dynamic, Eigen::Dynamic>;
  const int n = static_cast<int>(S.rows());
  Matrix B = S;
  for(int i = 0; i < n; ++i)
    B(i, i) = B(i, i) - lambda;
  Matrix power = B;
  int kernel = n - matrix_rank(power);
  for(int k = 1; k < n && kernel > 0; ++k) {
    Matrix next(n, n);
    for(int r = 0; r < n; ++r)
      for(int c = 0; c < n; ++c) {
        FT sum(0);
        for(int m = 0; m < n; ++m)
          if(power(r, m) != FT(0) && B(m, c) != FT(0))
            sum += power(r, m) * B(m, c);
        next(r, c) = sum;
      }
    power.swap(next);
    const int grown = n - matrix_rank(power);
    if(grown == kernel)
      break;
    kernel = grown;
  }
  return kernel;
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ANALYSIS_CURVE_LOCAL_MATRIX_H
