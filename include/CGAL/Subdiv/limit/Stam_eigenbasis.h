// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_STAM_EIGENBASIS_H
#define CGAL_SUBDIV_LIMIT_STAM_EIGENBASIS_H

/// \file Stam_eigenbasis.h
/// Stam's evaluation of a patch with one extraordinary corner (Stam 1998
/// for Catmull-Clark, 1999 for Loop) from the eigenstructure of its local
/// subdivision matrix: no mesh involved, only the matrices.

#include <CGAL/Subdiv/limit/patch_basis.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Subdiv {
namespace internal {

/*
 * A patch of K control points (the 1-ring of a face whose corner 0 is the
 * one extraordinary vertex, in the order of `Patch_points::ring_vertices()`)
 * refines into the same shape at corner 0, with control points A c (A is
 * K x K), and three regular children whose N control points are P_k c
 * (N x K). With A = V diag(lambda) V^-1, the limit over child k of the
 * patch L levels down is
 *
 *   sum_i lambda_i^L (b(u, v) . (P_k V)_i) (V^-1 c)_i,
 *
 * b the regular patch's basis: a point near the corner costs as much as
 * any other, with no refinement (Stam's eigenbasis functions, tabulated
 * here as the matrices P_k V rather than as polynomials).
 *
 * A is taken as diagonalisable when its eigenvalues are real, its
 * eigenvectors (orthonormal within each eigenspace) satisfy A V = V D to
 * rounding and V has a condition number below 1e6 (so that the evaluation
 * loses at most about 6 of the 16 digits of a double). Measured at
 * valences 3 to 16 (test/limit_surface_test.cpp): Catmull-Clark 79 to 171
 * (valence 3), Loop 17 to 34 (valence 5); Loop at valence 3 is defective
 * (its triple eigenvalues 1/8 and 1/16), `usable()` is false, and the
 * same limit is evaluated by powers of the matrix instead: the child's
 * control points P_k A^L c, L products of the K x K matrix (the points
 * taken from the extraordinary one, so that they shrink with the level and
 * keep their relative digits), rather than L local refinements.
 */
template <std::size_t N>
class Stam_eigenbasis
{
public:
  using Matrix = Eigen::MatrixXd;

  Stam_eigenbasis(const Matrix& A, const std::array<Matrix, 3>& children) : m_A(A), m_raw_children(children)
  {
    const Eigen::EigenSolver<Matrix> solver(A);
    if(solver.info() != Eigen::Success)
      return;
    // the real block-diagonal form: a 2 x 2 block for a complex pair, which
    // a repeated real eigenvalue may come out as, with an imaginary part of
    // the order of the rounding
    const Matrix D = solver.pseudoEigenvalueMatrix();
    const double scale = D.cwiseAbs().maxCoeff();
    m_lambda = D.diagonal();
    if((D - Matrix(m_lambda.asDiagonal())).cwiseAbs().maxCoeff() > 1e-12 * scale)
      return;
    const Matrix V = orthonormal_within_eigenspaces(solver.pseudoEigenvectors());
    const Eigen::JacobiSVD<Matrix> svd(V);
    const auto& sigma = svd.singularValues();
    m_condition = sigma(0) / sigma(sigma.size() - 1);
    if(!(m_condition < 1e6))
      return;
    if((A * V - V * D).cwiseAbs().maxCoeff() > 1e-9 * A.cwiseAbs().maxCoeff())
      return; // a defective eigenvalue: its vectors were not a basis of an eigenspace
    m_inverse_vectors = V.inverse();
    for(std::size_t k = 0; k < 3; ++k)
      m_children[k] = children[k] * V;
    for(Eigen::Index i = 0; i < m_lambda.size(); ++i)
      if(std::abs(m_lambda(i) - 1) < 1e-9)
        m_constant_mode = i;
    m_usable = true;
  }

  /// whether the matrix is diagonalisable in the reals, with a well-conditioned eigenbasis
  bool usable() const { return m_usable; }
  /// the condition number of the eigenvector matrix (infinite if not computed)
  double condition() const { return m_condition; }
  const Eigen::VectorXd& eigenvalues() const { return m_lambda; }

  /// the coordinates of the control points (one per row) in the eigenbasis (if usable; else the points)
  Matrix coefficients(const Matrix& control_points) const
  {
    if(!m_usable)
      return control_points;
    return m_inverse_vectors.lazyProduct(control_points); // (small: no blocking and packing)
  }

  /*
   * The limit over child `k` of the patch `level` levels down from the one
   * whose eigen-coefficients are `coefficients`, at the child's parameters
   * of weights `w`: the position, then d/du, d/dv, d2/du2, d2/dudv, d2/dv2
   * in the child's parameters times 2^level (4^level for the second
   * derivatives), i.e. in the parameters of the patch `level` levels up
   * (up to the child's own factor). Without `second_derivatives` the last
   * three are zero, and the products have half the rows.
   */
  std::array<Eigen::RowVector3d, 6> evaluate(const Matrix& coefficients, std::size_t k, int level,
                                             const Patch_weights<double, N>& w, bool second_derivatives = true) const
  {
    if(second_derivatives)
      return evaluate_rows<6>(coefficients, k, level, w);
    return evaluate_rows<4>(coefficients, k, level, w);
  }

private:
  /*
   * `evaluate()` over R rows: 6 with the second derivatives; 4 without,
   * the position and the first derivatives and a zero row, so that the
   * products are vectorised in the same pairs of rows as with 6 (and give
   * the same bits: 3 rows change the order of the sums)
   */
  template <int R>
  std::array<Eigen::RowVector3d, 6> evaluate_rows(const Matrix& coefficients, std::size_t k, int level,
                                                  const Patch_weights<double, N>& w) const
  {
    // the rows of basis weights in the eigenbasis, in one product
    Eigen::Matrix<double, R, int(N)> basis;
    const std::array<const std::array<double, N>*, 6> rows = {&w.position, &w.du, &w.dv, &w.duu, &w.duv, &w.dvv};
    for(int r = 0; r < R; ++r)
      if(r < 3 || R == 6)
        basis.row(r) = Eigen::Map<const Eigen::Matrix<double, 1, int(N)>>(rows[std::size_t(r)]->data());
      else
        basis.row(r).setZero();
    if(!m_usable)
      return by_powers<R>(basis, coefficients, k, level);
    Eigen::Matrix<double, R, Eigen::Dynamic> eigen_weights = basis.lazyProduct(m_children[k]);
    // times lambda_i^level, and 2^level or 4^level for the derivatives (exact)
    for(Eigen::Index i = 0; i < eigen_weights.cols(); ++i)
      eigen_weights.col(i) *= integer_power(m_lambda(i), level);
    scale_derivatives(eigen_weights, level);
    // the constant mode (eigenvalue 1: a translation) has no derivative; its
    // weight is a sum of derivative weights, zero but for rounding, which the
    // factor 2^level or 4^level would blow up near the corner
    if(m_constant_mode >= 0)
      eigen_weights.col(m_constant_mode).template tail<R - 1>().setZero();
    return rows_of<R>(eigen_weights.lazyProduct(coefficients));
  }

  // the rows of `basis` over the child's control points P_k A^level c, the derivatives times
  // 2^level and 4^level (where the matrix is not diagonalisable)
  template <int R>
  std::array<Eigen::RowVector3d, 6> by_powers(const Eigen::Matrix<double, R, int(N)>& basis, Matrix points,
                                              std::size_t k, int level) const
  {
    for(int l = 0; l < level; ++l)
      points = m_A.lazyProduct(points).eval();
    Eigen::Matrix<double, R, 3> values = basis.lazyProduct(m_raw_children[k].lazyProduct(points).eval());
    scale_derivatives(values, level);
    return rows_of<R>(values);
  }

  // rows 1 and 2 (first derivatives) times 2^level, rows 3 to 5 (second) times 4^level
  template <class Rows>
  static void scale_derivatives(Rows& rows, int level)
  {
    rows.template middleRows<2>(1) *= std::ldexp(1.0, level);
    if(rows.rows() > 3)
      rows.bottomRows(rows.rows() - 3) *= std::ldexp(1.0, 2 * level);
  }

  // the rows of `values` (of R rows: the second derivatives zero if R is not 6)
  template <int R, class Values>
  static std::array<Eigen::RowVector3d, 6> rows_of(const Values& values)
  {
    const Eigen::Matrix<double, R, 3> evaluated = values;
    std::array<Eigen::RowVector3d, 6> out;
    for(int r = 0; r < 6; ++r)
      out[std::size_t(r)] = r < 3 || R == 6 ? Eigen::RowVector3d(evaluated.row(r)) : Eigen::RowVector3d::Zero();
    return out;
  }

  // x^n by squaring (std::pow costs more, and n is a small level)
  static double integer_power(double x, int n)
  {
    double result = 1;
    for(; n > 0; n >>= 1, x *= x)
      if(n & 1)
        result *= x;
    return result;
  }

  /*
   * The eigenvectors with the same eigenvalue made an orthonormal basis of
   * their eigenspace, and the others of unit length: any basis of an
   * eigenspace diagonalises A, but the one the solver returns inside a
   * repeated eigenvalue depends on rounding (the condition number of V
   * moved 100-fold between two builds), this one only on A.
   */
  Matrix orthonormal_within_eigenspaces(Matrix V) const
  {
    const Eigen::Index K = V.cols();
    std::vector<bool> done(std::size_t(K), false);
    for(Eigen::Index i = 0; i < K; ++i) {
      if(done[std::size_t(i)])
        continue;
      std::vector<Eigen::Index> same;
      for(Eigen::Index j = i; j < K; ++j)
        if(!done[std::size_t(j)] && std::abs(m_lambda(j) - m_lambda(i)) <= 1e-9 * std::max(1.0, std::abs(m_lambda(i))))
          same.push_back(j);
      Matrix block(V.rows(), Eigen::Index(same.size()));
      for(std::size_t c = 0; c < same.size(); ++c)
        block.col(Eigen::Index(c)) = V.col(same[c]);
      const Eigen::HouseholderQR<Matrix> qr(block);
      const Matrix Q = qr.householderQ() * Matrix::Identity(V.rows(), block.cols());
      for(std::size_t c = 0; c < same.size(); ++c) {
        V.col(same[c]) = Q.col(Eigen::Index(c));
        done[std::size_t(same[c])] = true;
      }
    }
    return V;
  }

  bool m_usable = false;
  Eigen::Index m_constant_mode = -1; // the eigenvalue 1
  double m_condition = std::numeric_limits<double>::infinity();
  Eigen::VectorXd m_lambda;
  Matrix m_inverse_vectors;
  std::array<Matrix, 3> m_children; // P_k V
  Matrix m_A;                       // the local subdivision matrix, and the children's P_k
  std::array<Matrix, 3> m_raw_children;
};

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_STAM_EIGENBASIS_H
