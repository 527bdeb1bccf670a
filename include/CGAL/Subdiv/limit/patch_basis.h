// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_LIMIT_PATCH_BASIS_H
#define CGAL_SUBDIV_LIMIT_PATCH_BASIS_H

/// \file patch_basis.h
/// The limit surface over a regular patch as weights over its control
/// points: the bicubic B-spline patch of Catmull-Clark and the quartic
/// box-spline patch of Loop, with first and second derivatives, in any
/// number type (no mesh involved).

#include <array>
#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivAnalysis
 * The weights, over the `N` control points of a patch, of the limit
 * position at a parameter (u, v) and of its first and second partial
 * derivatives with respect to u and v: the position is
 * sum_k `position[k]` p_k, the derivative along u is sum_k `du[k]` p_k, and
 * so on. The position weights sum to 1 and the weights of every derivative
 * sum to 0 (the patch reproduces constants); the derivatives are those of
 * the face's own parameter domain (unit square or unit triangle), unscaled.
 */
template <class FT, std::size_t N>
struct Patch_weights
{
  /// the number of control points
  static constexpr std::size_t size = N;
  std::array<FT, N> position; ///< the limit point
  std::array<FT, N> du;       ///< d/du
  std::array<FT, N> dv;       ///< d/dv
  std::array<FT, N> duu;      ///< d2/du2
  std::array<FT, N> duv;      ///< d2/dudv
  std::array<FT, N> dvv;      ///< d2/dv2
};

namespace internal {

/*
 * The uniform cubic B-spline basis over the span [0, 1] between control
 * points 1 and 2 of four (point 1 at t = 0), and its first and second
 * derivatives: 6 b = (1-t)^3, 3t^3 - 6t^2 + 4, -3t^3 + 3t^2 + 3t + 1, t^3.
 */
template <class FT>
struct Cubic_bspline_basis
{
  std::array<FT, 4> value, d1, d2;

  explicit Cubic_bspline_basis(const FT& t)
  {
    const FT one(1), s = one - t, t2 = t * t, s2 = s * s;
    const FT sixth = one / FT(6), half = one / FT(2);
    value = {s2 * s * sixth, (FT(3) * t2 * t - FT(6) * t2 + FT(4)) * sixth,
             (FT(-3) * t2 * t + FT(3) * t2 + FT(3) * t + one) * sixth, t2 * t * sixth};
    d1 = {-s2 * half, (FT(3) * t2 - FT(4) * t) * half, (FT(-3) * t2 + FT(2) * t + one) * half, t2 * half};
    d2 = {s, FT(3) * t - FT(2), one - FT(3) * t, t};
  }
};

/*
 * The quartic box-spline basis of the regular Loop patch (see
 * `box_spline_patch_weights()`): row k holds 12 times the basis function of
 * control point k, as integer coefficients of the monomials u^a v^b whose
 * exponents (a, b) are listed in `quartic_exponents` (total degree 0 to 4).
 * Derived from the definition, the limit of Loop refinement of a unit value
 * at one lattice point (exact, in rationals, fitted by one quartic at every
 * dyadic point of level 3), and checked in test/patch_basis_test.cpp against
 * the package's refinement and limit. With w = 1 - u - v the six simplest
 * rows factor as in Stam's appendix: 12 b_0 = w^3 (w + 2u),
 * 12 b_3 = w^3 (w + 2v), 12 b_2 = u^3 (u + 2w), 12 b_6 = u^3 (u + 2v),
 * 12 b_10 = v^3 (v + 2w), 12 b_11 = v^3 (v + 2u). The coefficient of
 * u^2 v^2 vanishes in every row.
 */
// clang-format off
inline constexpr std::array<std::array<int, 2>, 15> quartic_exponents = {{
  {0, 0},
  {1, 0}, {0, 1},
  {2, 0}, {1, 1}, {0, 2},
  {3, 0}, {2, 1}, {1, 2}, {0, 3},
  {4, 0}, {3, 1}, {2, 2}, {1, 3}, {0, 4}}};

inline constexpr int box_spline_denominator = 12;

inline constexpr std::array<std::array<int, 15>, 12> box_spline_coefficients = {{
  //  1    u    v   uu   uv   vv  uuu  uuv  uvv  vvv   u4  u3v uuvv  uv3   v4
  {   1,  -2,  -4,   0,   6,   6,   2,   0,  -6,  -4,  -1,  -2,   0,   2,   1}, // 0
  {   1,   2,  -2,   0,  -6,   0,  -4,   0,   6,   2,   2,   4,   0,  -2,  -1}, // 1
  {   0,   0,   0,   0,   0,   0,   2,   0,   0,   0,  -1,  -2,   0,   0,   0}, // 2
  {   1,  -4,  -2,   6,   6,   0,  -4,  -6,   0,   2,   1,   2,   0,  -2,  -1}, // 3
  {   6,   0,   0, -12, -12, -12,   8,  12,  12,   8,  -1,  -2,   0,  -2,  -1}, // 4
  {   1,   4,   2,   6,   6,   0,  -4,  -6, -12,  -4,  -1,  -2,   0,   4,   2}, // 5
  {   0,   0,   0,   0,   0,   0,   0,   0,   0,   0,   1,   2,   0,   0,   0}, // 6
  {   1,  -2,   2,   0,  -6,   0,   2,   6,   0,  -4,  -1,  -2,   0,   4,   2}, // 7
  {   1,   2,   4,   0,   6,   6,  -4, -12,  -6,  -4,   2,   4,   0,  -2,  -1}, // 8
  {   0,   0,   0,   0,   0,   0,   2,   6,   6,   2,  -1,  -2,   0,  -2,  -1}, // 9
  {   0,   0,   0,   0,   0,   0,   0,   0,   0,   2,   0,   0,   0,  -2,  -1}, // 10
  {   0,   0,   0,   0,   0,   0,   0,   0,   0,   0,   0,   0,   0,   2,   1} // 11
}};
// clang-format on

// x^0 .. x^4
template <class FT>
std::array<FT, 5> powers_to_4(const FT& x)
{
  std::array<FT, 5> p{FT(1), x, FT(0), FT(0), FT(0)};
  for(std::size_t i = 2; i < p.size(); ++i)
    p[i] = p[i - 1] * x;
  return p;
}

// a! / (a - k)!: the factor that differentiating x^a k times brings
constexpr int falling_factorial(int a, int k)
{
  int r = 1;
  for(int i = 0; i < k; ++i)
    r *= a - i;
  return r;
}

/*
 * The derivative of order (i, j) (i times along u, j times along v) of the
 * 15 monomials of `quartic_exponents` at (u, v), from their powers; exact
 * (no difference quotient).
 */
template <class FT>
std::array<FT, 15> quartic_monomials(const std::array<FT, 5>& pu, const std::array<FT, 5>& pv, int i, int j)
{
  std::array<FT, 15> m;
  for(std::size_t n = 0; n < m.size(); ++n) {
    const int a = quartic_exponents[n][0], b = quartic_exponents[n][1];
    if(a < i || b < j)
      m[n] = FT(0);
    else
      m[n] = FT(falling_factorial(a, i) * falling_factorial(b, j)) * pu[std::size_t(a - i)] * pv[std::size_t(b - j)];
  }
  return m;
}

// the coefficients of `box_spline_coefficients` in FT, converted once, by monomial
template <class FT>
const std::array<std::array<FT, 12>, 15>& box_spline_coefficients_by_monomial()
{
  static const std::array<std::array<FT, 12>, 15> converted = [] {
    std::array<std::array<FT, 12>, 15> c;
    for(std::size_t n = 0; n < c.size(); ++n)
      for(std::size_t k = 0; k < c[n].size(); ++k)
        c[n][k] = FT(box_spline_coefficients[k][n]);
    return c;
  }();
  return converted;
}

/*
 * The weights of the derivative of order (i, j) of the box-spline patch at
 * (u, v). Monomial by monomial, so that the 12 sums are independent (each
 * still adds its terms in the monomials' order): in floating point the loop
 * over the weights vectorises; in an exact number type the zero
 * coefficients are skipped. The monomials that the derivative makes zero
 * are skipped in both (adding them changed no bit: the sums start at +0).
 */
template <class FT>
std::array<FT, 12> box_spline_derivative(const std::array<FT, 5>& pu, const std::array<FT, 5>& pv, int i, int j)
{
  const std::array<FT, 15> m = quartic_monomials(pu, pv, i, j);
  const auto& coefficients = box_spline_coefficients_by_monomial<FT>();
  std::array<FT, 12> sum;
  sum.fill(FT(0));
  for(std::size_t n = 0; n < m.size(); ++n) {
    if(quartic_exponents[n][0] < i || quartic_exponents[n][1] < j)
      continue;       // a monomial that the derivative makes zero
#pragma GCC unroll 12 // (unrolled, the sums stay in registers rather than a store and a load per term)
    for(std::size_t k = 0; k < sum.size(); ++k)
      if constexpr(std::is_floating_point<FT>::value)
        sum[k] += coefficients[n][k] * m[n];
      else if(box_spline_coefficients[k][n] != 0)
        sum[k] += coefficients[n][k] * m[n];
  }
  const FT denominator(box_spline_denominator);
  for(FT& w : sum)
    w /= denominator;
  return sum;
}

} // namespace internal

/*!
 * \ingroup PkgSubdivAnalysis
 * The weights of the regular Catmull-Clark patch at (u, v) in the unit
 * square: the bicubic uniform B-spline patch, which is the limit of
 * Catmull-Clark refinement over a quad whose four corners have valence 4 and
 * no border or tag in their 1-rings (Stam, "Exact Evaluation of
 * Catmull-Clark Subdivision Surfaces at Arbitrary Parameter Values",
 * SIGGRAPH 1998: its regular case). Each weight is the product
 * b_c(u) b_r(v) of the uniform cubic B-spline basis functions, 6 b_0(t) =
 * (1-t)^3, 6 b_1(t) = 3t^3 - 6t^2 + 4, 6 b_2(t) = -3t^3 + 3t^2 + 3t + 1,
 * 6 b_3(t) = t^3, and the derivatives are those of these polynomials.
 *
 * The 16 control points form a 4 x 4 grid, numbered row by row: point
 * 4 r + c is in row r (along v) and column c (along u). The face is the
 * middle square, with the quad parameterisation of the limit surface:
 * corner 0 at point 5, (u, v) = (0, 0); corner 1 at point 6, (1, 0);
 * corner 2 at point 10, (1, 1); corner 3 at point 9, (0, 1).
 * \verbatim
     v
     ^
     12----13----14----15
     |     |     |     |
     8-----9-----10----11
     |     |face |     |
     4-----5-----6-----7
     |     |     |     |
     0-----1-----2-----3   > u
   \endverbatim
 * With point 4 r + c at (c - 1, r - 1) the patch is (u, v) (linear
 * precision). At a corner the position weights are the regular limit mask
 * of Catmull-Clark: 16/36 at the corner, 4/36 at its four edge neighbours,
 * 1/36 at its four diagonal neighbours. The position weights sum to 1, the
 * weights of each derivative to 0.
 *
 * `FT` is any field type (`double`, `CGAL::Exact_rational`, ...): the weights
 * are polynomials in u and v with rational coefficients, exact in an exact
 * `FT`. Meant for 0 <= u, v <= 1 (outside, the polynomials of this piece).
 * Without `second_derivatives` the second derivatives' weights are zero
 * (not computed).
 */
template <class FT>
Patch_weights<FT, 16> bspline_patch_weights(const FT& u, const FT& v, bool second_derivatives = true)
{
  const internal::Cubic_bspline_basis<FT> bu(u), bv(v);
  Patch_weights<FT, 16> w;
  for(std::size_t r = 0; r < 4; ++r)
    for(std::size_t c = 0; c < 4; ++c) {
      const std::size_t k = 4 * r + c;
      w.position[k] = bu.value[c] * bv.value[r];
      w.du[k] = bu.d1[c] * bv.value[r];
      w.dv[k] = bu.value[c] * bv.d1[r];
    }
  if(!second_derivatives) {
    w.duu.fill(FT(0));
    w.duv.fill(FT(0));
    w.dvv.fill(FT(0));
    return w;
  }
  for(std::size_t r = 0; r < 4; ++r)
    for(std::size_t c = 0; c < 4; ++c) {
      const std::size_t k = 4 * r + c;
      w.duu[k] = bu.d2[c] * bv.value[r];
      w.duv[k] = bu.d1[c] * bv.d1[r];
      w.dvv[k] = bu.value[c] * bv.d2[r];
    }
  return w;
}

/*!
 * \ingroup PkgSubdivAnalysis
 * The weights of the regular Loop patch at (u, v), u, v >= 0, u + v <= 1:
 * the quartic three-direction box spline, which is the limit of Loop
 * refinement over a triangle whose three corners have valence 6 and no
 * border or tag in their 1-rings (J. Stam, "Evaluation of Loop Subdivision
 * Surfaces", SIGGRAPH 98 CD-ROM: its appendix gives the 12 basis functions
 * in barycentric coordinates, in another numbering). Here each basis
 * function is a polynomial in u and v (`internal::box_spline_coefficients`)
 * and the derivatives are those of the polynomials.
 *
 * The face has the triangle parameterisation of the limit surface: corner 0
 * at (u, v) = (0, 0), corner 1 at (1, 0), corner 2 at (0, 1). Its 12 control
 * points are the face's corners and their 1-rings, numbered as OpenSubdiv
 * numbers its regular Loop patch (Far, patchBasis.cpp, "Quartic Box spline
 * triangle"): point k lies at the lattice position (i, j) = i e_u + j e_v of
 * the parameter plane, e_u = (1, 0) and e_v = (0, 1) being the edges from
 * corner 0 to corners 1 and 2; drawn with e_v leaning right:
 * \verbatim
                 10----11                 j =  2
                /  \  /  \
              7-----8-----9               j =  1
             / \   /f\   / \
           3-----4-----5-----6            j =  0
            \   / \   / \   /
              0-----1-----2               j = -1
   \endverbatim
 * that is 0 (0, -1), 1 (1, -1), 2 (2, -1), 3 (-1, 0), 4 (0, 0), 5 (1, 0),
 * 6 (2, 0), 7 (-1, 1), 8 (0, 1), 9 (1, 1), 10 (-1, 2), 11 (0, 2).
 * The face f is the triangle 4 (corner 0), 5 (corner 1), 8 (corner 2); the
 * lattice's edges run along e_u, e_v and e_v - e_u, so every corner has its
 * 6 neighbours among the 12 points. With point k at its (i, j) the patch is
 * (u, v) (linear precision). At a corner the position weights are the
 * regular limit mask of Loop: 1/2 at the corner, 1/12 at each of its 6
 * neighbours. The position weights sum to 1, the weights of each derivative
 * to 0.
 *
 * `FT` is any field type (`double`, `CGAL::Exact_rational`, ...): the weights
 * are polynomials in u and v with rational coefficients (denominator 12),
 * exact in an exact `FT`. Without `second_derivatives` the second
 * derivatives' weights are zero (not computed).
 */
template <class FT>
Patch_weights<FT, 12> box_spline_patch_weights(const FT& u, const FT& v, bool second_derivatives = true)
{
  const std::array<FT, 5> pu = internal::powers_to_4(u), pv = internal::powers_to_4(v);
  Patch_weights<FT, 12> w;
  w.position = internal::box_spline_derivative(pu, pv, 0, 0);
  w.du = internal::box_spline_derivative(pu, pv, 1, 0);
  w.dv = internal::box_spline_derivative(pu, pv, 0, 1);
  if(!second_derivatives) {
    w.duu.fill(FT(0));
    w.duv.fill(FT(0));
    w.dvv.fill(FT(0));
    return w;
  }
  w.duu = internal::box_spline_derivative(pu, pv, 2, 0);
  w.duv = internal::box_spline_derivative(pu, pv, 1, 1);
  w.dvv = internal::box_spline_derivative(pu, pv, 0, 2);
  return w;
}

} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_LIMIT_PATCH_BASIS_H
