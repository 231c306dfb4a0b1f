// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_POLYNOMIAL_ROOTS_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_POLYNOMIAL_ROOTS_H

// Root finding for the monic polynomials that represent PolyVectors.
//
// Conventions of this file:
// - a monic polynomial of degree n is given by its n lower coefficients
//   d[0..n-1], entry m multiplying y^m (the leading coefficient 1 is implicit);
// - "counterclockwise order" means: sorted by argument in [0, 2 pi), a zero
//   root has argument 0 and comes first among the roots of argument 0.
//
// Contents:
// - small complex helpers that avoid the library's slow paths (complex
//   division calls a runtime routine, and std::sqrt of a complex goes through
//   hypot): they are only used where the arguments are known to be in a range
//   in which the naive formulas neither overflow nor underflow;
// - an exact orientation predicate (sign of Im(conj(a) b)) and the
//   counterclockwise comparison built on it;
// - the numerically stable quadratic formula;
// - the closed forms for sign-symmetric sets of 2 and 4 vectors; the latter
//   (frame fields) is the hot loop of the package and has a branch-free fast path;
// - the general path: eigenvalues of the companion matrix (Eigen's
//   ComplexEigenSolver), after exact deflation of zero roots and a
//   power-of-two scaling, with a guarded Newton polish; Aberth iteration is
//   the fallback should the eigensolver not converge.

#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// ---------------------------------------------------------------------------
// Small complex helpers
// ---------------------------------------------------------------------------

inline double max_abs_component(const Complex& z)
{
  return (std::max)(std::abs(z.real()), std::abs(z.imag()));
}

inline bool is_zero(const Complex& z)
{
  return z.real() == 0. && z.imag() == 0.;
}

inline bool is_finite(const Complex& z)
{
  return std::isfinite(z.real()) && std::isfinite(z.imag());
}

inline Complex complex_mul(const Complex& a, const Complex& b)
{
  return Complex(a.real() * b.real() - a.imag() * b.imag(),
                            a.real() * b.imag() + a.imag() * b.real());
}

inline Complex complex_nan()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return Complex(nan, nan);
}

// x * 2^k for both components (exact unless the result over- or underflows)
inline Complex complex_ldexp(const Complex& z, int k)
{
  return Complex(std::ldexp(z.real(), k), std::ldexp(z.imag(), k));
}

// Principal square root (real part >= 0). In the range 2^-500 < max(|x|,|y|) < 2^500
// the naive modulus sqrt(x^2 + y^2) neither overflows nor underflows, and
// r + |x| has no cancellation; outside that range the library routine is used.
inline Complex principal_sqrt(const Complex& z)
{
  const double x = z.real(), y = z.imag();
  const double m = (std::max)(std::abs(x), std::abs(y));
  if(!(m > 0x1p-500 && m < 0x1p+500))
  {
    if(m == 0.)
      return Complex(0., 0.);
    return std::sqrt(z);
  }
  const double r = std::sqrt(x * x + y * y);
  const double t = std::sqrt(0.5 * (r + std::abs(x))); // t > 0 since r >= m > 0
  if(x >= 0.)
    return Complex(t, 0.5 * y / t);
  return Complex(0.5 * std::abs(y) / t, std::copysign(t, y));
}

// `condition ? a : b` through bit masks: compilers tend to turn a ternary on
// doubles into a jump, which mispredicts half of the time on data of random sign.
inline double select_double(bool condition, double a, double b)
{
  std::uint64_t ua, ub;
  std::memcpy(&ua, &a, sizeof(double));
  std::memcpy(&ub, &b, sizeof(double));
  const std::uint64_t mask = std::uint64_t(0) - std::uint64_t(condition);
  const std::uint64_t r = (ua & mask) | (ub & ~mask);
  double out;
  std::memcpy(&out, &r, sizeof(double));
  return out;
}

// -1 if `negative`, +1 otherwise, without a jump
inline double sign_factor(bool negative)
{
  return 1. - 2. * double(int(negative));
}

// A square root (either one) of x + iy, 2^-500 < max(|x|, |y|) < 2^500, without
// jumps: (t, h) for x >= 0, (h, t) for x < 0, with t = sqrt((|z| + |x|)/2),
// h = y / (2t); for x < 0, (h + it)^2 = h^2 - t^2 + i y = x + i y.
inline Complex some_sqrt_in_range(double x, double y)
{
  const double r = std::sqrt(x * x + y * y);
  const double t = std::sqrt(0.5 * (r + std::abs(x)));
  const double h = 0.5 * y / t;
  const bool negative = x < 0.;
  return Complex(select_double(negative, h, t), select_double(negative, t, h));
}

// ---------------------------------------------------------------------------
// Exact orientation and counterclockwise order
// ---------------------------------------------------------------------------

// Sign of ax*by - ay*bx computed with Kahan's fma-based 2x2 determinant, whose
// relative error is at most 2 ulps (Jeannerod, Louvet, Muller 2013) and whose
// sign is therefore exact. Each vector is first scaled by a power of two (which
// does not change the sign) so that its largest component is in [1, 2): this
// keeps the products away from overflow and underflow.
inline int orientation_sign_exact(const Complex& a, const Complex& b)
{
  const double ma = max_abs_component(a), mb = max_abs_component(b);
  if(!(ma > 0.) || !(mb > 0.) || !std::isfinite(ma) || !std::isfinite(mb))
    return 0;
  const Complex sa = complex_ldexp(a, -std::ilogb(ma));
  const Complex sb = complex_ldexp(b, -std::ilogb(mb));
  const double w = sa.imag() * sb.real();
  const double e = std::fma(-sa.imag(), sb.real(), w);  // w - ay*bx, exactly
  const double f = std::fma(sa.real(), sb.imag(), -w);  // ax*by - w, rounded once
  const double det = f + e;
  return (det > 0.) - (det < 0.);
}

// Sign of Im(conj(a) * b) = ax*by - ay*bx: positive when b is counterclockwise
// from a by an angle in (0, pi). A floating-point filter decides almost all
// cases; the exact routine above handles the rest. The filter: each product
// has relative error <= u = 2^-53 (plus 2^-1075 absolute when it underflows),
// the difference adds u * |result|, so |error| <= 2u(|p|+|q|) + 2^-1074 for
// the result; the bound 4u(|p|+|q|) + 2^-1070 is safe.
inline int orientation_sign(const Complex& a, const Complex& b)
{
  const double p = a.real() * b.imag();
  const double q = a.imag() * b.real();
  const double det = p - q;
  const double bound = 0x1p-51 * (std::abs(p) + std::abs(q)) + 0x1p-1070;
  if(std::abs(det) > bound) // decided; the sign itself is computed without a jump
    return (det > 0.) - (det < 0.);
  return orientation_sign_exact(a, b);
}

// 0: the zero root (argument 0 by convention);
// 1: argument in [0, pi)  (imaginary part > 0, or on the positive real axis);
// 2: argument in [pi, 2 pi) (and NaN, which cannot be ordered).
inline int ccw_half(const Complex& z)
{
  if(z.imag() > 0. || (z.imag() == 0. && z.real() > 0.))
    return 1;
  if(is_zero(z))
    return 0;
  return 2;
}

// Strict weak order "argument of a < argument of b" (arguments in [0, 2 pi)),
// with zero before every other root. Within one half the arguments differ by
// less than pi, so the orientation sign decides exactly.
inline bool ccw_less(const Complex& a, const Complex& b)
{
  const int ha = ccw_half(a), hb = ccw_half(b);
  if(ha != hb)
    return ha < hb;
  if(ha == 0)
    return false;
  return orientation_sign(a, b) > 0;
}

// Insertion sort: n is small, and it stays in bounds whatever the comparison does
// (with NaN, for instance).
inline void sort_ccw(Complex* z, std::size_t n)
{
  for(std::size_t i = 1; i < n; ++i)
  {
    const Complex key = z[i];
    std::size_t j = i;
    while(j > 0 && ccw_less(key, z[j - 1]))
    {
      z[j] = z[j - 1];
      --j;
    }
    z[j] = key;
  }
}

// The one of {z, -z} whose argument is in [0, pi); zero is returned as +0.
inline Complex upper_half_representative(const Complex& z)
{
  switch(ccw_half(z))
  {
    case 0: return Complex(0., 0.);
    case 1: return z;
    default: return -z;
  }
}

// Given the representatives a[0..k-1] (argument in [0, pi), or zero) of the
// pairs {a, -a}, writes the 2k roots in counterclockwise order: the zero ones,
// then the others sorted, then their negatives in the same order (whose
// arguments are those of the former plus pi). So roots[z + i + k'] ==
// -roots[z + i], with z zero roots and k' nonzero pairs.
inline void write_sign_symmetric_roots(Complex* a, std::size_t k,
                                       Complex* roots)
{
  std::size_t zeros = 0;
  for(std::size_t i = 0; i < k; ++i)
    if(is_zero(a[i]))
      std::swap(a[i], a[zeros++]);
  sort_ccw(a + zeros, k - zeros);
  const std::size_t pairs = k - zeros;
  for(std::size_t i = 0; i < 2 * zeros; ++i)
    roots[i] = Complex(0., 0.);
  for(std::size_t i = 0; i < pairs; ++i)
  {
    roots[2 * zeros + i] = a[zeros + i];
    roots[2 * zeros + pairs + i] = -a[zeros + i];
  }
}

// ---------------------------------------------------------------------------
// Quadratic formula
// ---------------------------------------------------------------------------

// Roots of y^2 + b y + c when 2^-250 < max|b| < 2^250 or 2^-500 < max|c| < 2^500
// (both below the upper bound); max| | is the largest component magnitude.
// In that range b^2 - 4c, its modulus and |q|^2 neither overflow nor underflow
// in a harmful way. The root of larger magnitude, q = -(b +- sqrt(b^2-4c))/2
// with the sign that avoids cancellation, is computed first; the other root is
// c / q (Vieta), which is accurate even when |c| << |b|^2.
inline void quadratic_roots_in_range(const Complex& b, const Complex& c,
                                     Complex& r1, Complex& r2)
{
  const Complex disc = complex_mul(b, b) - 4. * c;
  const Complex d = principal_sqrt(disc);
  // Re(conj(b) d) >= 0 means |b + d| >= |b - d|
  const double dot = b.real() * d.real() + b.imag() * d.imag();
  const Complex q = (dot >= 0.) ? -0.5 * (b + d) : -0.5 * (b - d);
  if(is_zero(q))
  {
    // |q|^2 >= (|b|^2 + |d|^2)/2, so b = d = 0, hence c = 0: a double zero root
    r1 = r2 = Complex(0., 0.);
    return;
  }
  const double inverse_nq = 1. / (q.real() * q.real() + q.imag() * q.imag());
  r1 = q;
  r2 = Complex((c.real() * q.real() + c.imag() * q.imag()) * inverse_nq,
                          (c.imag() * q.real() - c.real() * q.imag()) * inverse_nq);
}

/// Roots of the monic quadratic y^2 + b y + c, the one of larger magnitude in `r1`.
/// Finite input gives finite output (unless a root exceeds the double range);
/// a double root or a zero root is handled; non-finite input gives NaN.
inline void stable_quadratic_roots(const Complex& b, const Complex& c,
                                   Complex& r1, Complex& r2)
{
  const double mb = max_abs_component(b), mc = max_abs_component(c);
  if(mb < 0x1p+250 && mc < 0x1p+500 && (mb > 0x1p-250 || mc > 0x1p-500))
  {
    quadratic_roots_in_range(b, c, r1, r2);
    return;
  }
  if(mb == 0. && mc == 0.)
  {
    r1 = r2 = Complex(0., 0.);
    return;
  }
  if(!std::isfinite(mb) || !std::isfinite(mc))
  {
    r1 = r2 = complex_nan();
    return;
  }
  // y = 2^k t, with 2^k about the size of the larger root: t^2 + (b 2^-k) t + c 2^-2k,
  // whose larger root q has |q| >= 1/4 or so. The smaller root is c / (2^k q), computed
  // as (c 2^-k) / q: c 2^-2k may underflow when |c| << |b|^2, c 2^-k does not
  // (unless the smaller root itself is below the double range).
  const int k = std::ilogb((std::max)(mb, std::sqrt(mc)));
  Complex q, unused;
  quadratic_roots_in_range(complex_ldexp(b, -k), complex_ldexp(c, -2 * k), q, unused);
  if(is_zero(q))
  {
    r1 = r2 = Complex(0., 0.);
    return;
  }
  const Complex cs = complex_ldexp(c, -k);
  const double inverse_nq = 1. / (q.real() * q.real() + q.imag() * q.imag());
  r1 = complex_ldexp(q, k);
  r2 = Complex((cs.real() * q.real() + cs.imag() * q.imag()) * inverse_nq,
                          (cs.imag() * q.real() - cs.real() * q.imag()) * inverse_nq);
}

// ---------------------------------------------------------------------------
// Closed forms
// ---------------------------------------------------------------------------

/// Roots of z^2 + c0 (the sign-symmetric pair {a, -a}, a = sqrt(-c0)) in
/// counterclockwise order.
inline void sign_symmetric_quadratic_roots(const Complex& c0, Complex* roots)
{
  const Complex a = upper_half_representative(principal_sqrt(-c0));
  roots[0] = a;
  roots[1] = is_zero(a) ? a : -a;
}

// Roots of z^4 + c2 z^2 + c0 through the generic steps: stable quadratic in
// w = z^2, principal square roots, explicit zero handling. Used outside the
// range of the fast path (c0 zero or tiny, coefficients huge).
inline void sign_symmetric_quartic_roots_generic(const Complex& c0, const Complex& c2,
                                                 Complex* roots)
{
  Complex w1, w2;
  stable_quadratic_roots(c2, c0, w1, w2);
  const Complex a = upper_half_representative(principal_sqrt(w1));
  const Complex b = upper_half_representative(principal_sqrt(w2));
  const bool a_zero = is_zero(a), b_zero = is_zero(b);
  if(a_zero || b_zero)
  {
    const Complex v = a_zero ? b : a; // zero too when both are
    roots[0] = roots[1] = Complex(0., 0.);
    roots[2] = v;
    roots[3] = is_zero(v) ? v : -v;
    return;
  }
  const int first = (orientation_sign(a, b) < 0) ? 1 : 0;
  const Complex pair[2] = {a, b};
  roots[0] = pair[first];
  roots[1] = pair[1 - first];
  roots[2] = -roots[0];
  roots[3] = -roots[1];
}

/// Roots of z^4 + c2 z^2 + c0 = (z^2 - w1)(z^2 - w2) in counterclockwise order:
/// w solves w^2 + c2 w + c0 = 0, the roots are {+-sqrt(w1), +-sqrt(w2)}.
///
/// This is the hot loop of frame fields: no heap, no trigonometry, and the
/// data-dependent choices (sign in the quadratic formula, branch of the square
/// roots, half plane, order) are selects rather than jumps. Fast path, for
/// 2^-500 < max|c0| < 2^500 and max|c2| < 2^250 (max| | = largest component):
/// - d = sqrt(c2^2 - 4 c0), either root; w1 = q = -(c2 + s d)/2 with the sign s
///   that avoids cancellation: |q| >= sqrt(|c0|) > 0;
/// - a = the square root of q in the upper half plane (argument in [0, pi));
/// - b = sqrt(c0) / a = sqrt(c0) conj(a) / |q|, a square root of w2 = c0 / w1
///   (Vieta, accurate even when |w2| << |w1|), flipped into the upper half plane;
/// - a, b, -a, -b or b, a, -b, -a, by the exact orientation of (a, b).
inline void sign_symmetric_quartic_roots(const Complex& c0, const Complex& c2,
                                         Complex* roots)
{
  const double m0 = max_abs_component(c0), m2 = max_abs_component(c2);
  if(!(m0 > 0x1p-500 && m0 < 0x1p+500 && m2 < 0x1p+250))
  {
    sign_symmetric_quartic_roots_generic(c0, c2, roots);
    return;
  }
  const double c0x = c0.real(), c0y = c0.imag(), c2x = c2.real(), c2y = c2.imag();
  // discriminant, |disc| < 2^503; it may vanish (double root in w)
  const double dx = c2x * c2x - c2y * c2y - 4. * c0x;
  const double dy = 2. * c2x * c2y - 4. * c0y;
  const double md = (std::max)(std::abs(dx), std::abs(dy));
  const Complex d = (md > 0x1p-500) ? some_sqrt_in_range(dx, dy) : principal_sqrt(Complex(dx, dy));
  const Complex s0 = some_sqrt_in_range(c0x, c0y);
  const double s = std::copysign(1., c2x * d.real() + c2y * d.imag());
  const double qx = -0.5 * (c2x + s * d.real());
  const double qy = -0.5 * (c2y + s * d.imag());
  // a: square root of q in the upper half plane; |q| in [2^-250, 2^253)
  const double rq = std::sqrt(qx * qx + qy * qy);
  const double inverse_rq = 1. / rq;
  const double t = std::sqrt(0.5 * (rq + std::abs(qx)));
  const double h = 0.5 * qy / t;
  const bool qx_negative = qx < 0.;
  const double sy = sign_factor(qy < 0.);
  const double ax = select_double(qx_negative, h, sy * t);
  const double ay = select_double(qx_negative, t, sy * h);
  // b = s0 conj(a) / |a|^2, |a|^2 = |q|, then into the upper half plane
  double bx = (s0.real() * ax + s0.imag() * ay) * inverse_rq;
  double by = (s0.imag() * ax - s0.real() * ay) * inverse_rq;
  const int b_lower = int(by < 0.) | (int(by == 0.) & int(bx < 0.));
  const double sb = sign_factor(b_lower != 0);
  bx *= sb;
  by *= sb;
  const Complex pair[2] = {Complex(ax, ay), Complex(bx, by)};
  const int first = (orientation_sign(pair[0], pair[1]) < 0) ? 1 : 0;
  roots[0] = pair[first];
  roots[1] = pair[1 - first];
  roots[2] = -roots[0];
  roots[3] = -roots[1];
}

// ---------------------------------------------------------------------------
// General path: companion matrix
// ---------------------------------------------------------------------------

/// Small buffer with inline storage for up to 16 complex numbers and heap storage beyond.
class Complex_buffer
{
public:
  explicit Complex_buffer(std::size_t n)
  {
    if(n > inline_capacity)
    {
      heap_.reset(new Complex[n]);
      data_ = heap_.get();
    }
    else
      data_ = inline_;
  }
  Complex_buffer(const Complex_buffer&) = delete;
  Complex_buffer& operator=(const Complex_buffer&) = delete;
  Complex* data() { return data_; }
  Complex& operator[](std::size_t i) { return data_[i]; }

  static constexpr std::size_t inline_capacity = 16;

private:
  Complex inline_[inline_capacity];
  std::unique_ptr<Complex[]> heap_;
  Complex* data_;
};

// p(y) and p'(y) for the monic p(y) = y^n + sum_m d[m] y^m, and sum_m |d_m| |y|^m
// and sum_m m |d_m| |y|^(m-1) (with |d_n| = 1), the scales of their rounding errors.
inline void evaluate_monic(const Complex* d, std::size_t n, const Complex& y,
                           Complex& p, Complex& dp,
                           double& p_scale, double& dp_scale)
{
  const double ay = std::abs(y);
  p = Complex(1., 0.);
  dp = Complex(0., 0.);
  p_scale = 1.;
  dp_scale = 0.;
  for(std::size_t m = n; m-- > 0;)
  {
    dp = complex_mul(dp, y) + p;
    p = complex_mul(p, y) + d[m];
    dp_scale = dp_scale * ay + p_scale;
    p_scale = p_scale * ay + std::abs(d[m]);
  }
}

// At most two Newton steps per root, each accepted only if it provably does not
// make things worse: the derivative must be well above its rounding noise (so not
// near a multiple root), the step must be shorter than a tenth of the distance
// to the nearest other root (so the root cannot jump to a neighbour's basin),
// and the residual |p| must decrease.
inline void polish_roots(const Complex* d, std::size_t n, Complex* y)
{
  if(n < 2)
    return;
  const double eps = std::numeric_limits<double>::epsilon();
  for(std::size_t i = 0; i < n; ++i)
  {
    for(int step = 0; step < 2; ++step)
    {
      Complex p, dp;
      double p_scale, dp_scale;
      evaluate_monic(d, n, y[i], p, dp, p_scale, dp_scale);
      if(is_zero(p) || !(std::abs(dp) > 1e3 * eps * dp_scale))
        break;
      const Complex delta = p / dp;
      if(!is_finite(delta))
        break;
      double nearest = std::numeric_limits<double>::infinity();
      for(std::size_t j = 0; j < n; ++j)
        if(j != i)
          nearest = (std::min)(nearest, std::abs(y[i] - y[j]));
      if(!(std::abs(delta) < 0.1 * nearest))
        break;
      const Complex candidate = y[i] - delta;
      Complex p_new, dp_new;
      double s1, s2;
      evaluate_monic(d, n, candidate, p_new, dp_new, s1, s2);
      if(!(std::abs(p_new) < std::abs(p)))
        break;
      y[i] = candidate;
    }
  }
}

/// Aberth-Ehrlich iteration for the monic p(y) = y^n + sum_m d[m] y^m whose
/// roots are of magnitude about 1 (the caller scales). Fallback of the
/// eigensolver; also exposed for testing.
inline void aberth_roots(const Complex* d, std::size_t n, Complex* y)
{
  if(n == 0)
    return;
  // start on a circle whose radius bounds the roots (Fujiwara), rotated off the axes
  double radius = 0.;
  for(std::size_t m = 0; m < n; ++m)
  {
    const double a = std::abs(d[m]);
    if(a > 0.)
      radius = (std::max)(radius, std::pow(m == 0 ? 0.5 * a : a, 1. / double(n - m)));
  }
  radius = (radius > 0.) ? 2. * radius : 1.;
  for(std::size_t i = 0; i < n; ++i)
    y[i] = std::polar(radius, two_pi * (double(i) + 0.25) / double(n) + 0.4);
  const double eps = std::numeric_limits<double>::epsilon();
  for(int iteration = 0; iteration < 500; ++iteration)
  {
    bool moved = false;
    for(std::size_t i = 0; i < n; ++i)
    {
      Complex p, dp;
      double p_scale, dp_scale;
      evaluate_monic(d, n, y[i], p, dp, p_scale, dp_scale);
      if(std::abs(p) <= 4. * eps * p_scale)
        continue; // y[i] is a root within rounding
      Complex sum(0., 0.);
      for(std::size_t j = 0; j < n; ++j)
        if(j != i && y[j] != y[i])
          sum += 1. / (y[i] - y[j]);
      const Complex ratio = p / dp;
      const Complex denominator = 1. - ratio * sum;
      const Complex w = is_zero(denominator) ? ratio : ratio / denominator;
      if(!is_finite(w))
        continue;
      y[i] -= w;
      if(std::abs(w) > 4. * eps * (std::max)(1., std::abs(y[i])))
        moved = true;
    }
    if(!moved)
      break;
  }
}

// Balances a square matrix in place by a diagonal similarity with powers of two
// (exact, eigenvalues unchanged), so that each row and the matching column have
// comparable 1-norms (Parlett and Reinsch's iteration). Eigen's complex
// eigensolver does not balance; for a companion matrix, whose last column can
// span many orders of magnitude, this is what makes the small roots accurate.
template <typename Matrix>
void balance_matrix(Matrix& a)
{
  const Eigen::Index n = a.rows();
  for(int sweep = 0; sweep < 100; ++sweep)
  {
    bool changed = false;
    for(Eigen::Index i = 0; i < n; ++i)
    {
      double column = 0., row = 0.;
      for(Eigen::Index j = 0; j < n; ++j)
      {
        if(j == i)
          continue;
        column += std::abs(a(j, i).real()) + std::abs(a(j, i).imag());
        row += std::abs(a(i, j).real()) + std::abs(a(i, j).imag());
      }
      if(!(column > 0.) || !(row > 0.) || !std::isfinite(column + row))
        continue;
      const double sum = column + row;
      int k = 0; // scale column i by 2^k and row i by 2^-k
      double c = column, r = row;
      while(c < 0.5 * r && k < 2000) { c *= 2.; r *= 0.5; ++k; }
      while(c >= 2. * r && k > -2000) { c *= 0.5; r *= 2.; --k; }
      if(k != 0 && c + r < 0.95 * sum)
      {
        changed = true;
        for(Eigen::Index j = 0; j < n; ++j)
        {
          a(j, i) = complex_ldexp(a(j, i), k);
          a(i, j) = complex_ldexp(a(i, j), -k);
        }
      }
    }
    if(!changed)
      break;
  }
}

// Eigenvalues of the (balanced) companion matrix of the monic y^n + sum_m d[m] y^m.
// MaxN = 16 keeps all of Eigen's storage on the stack.
template <int MaxN>
bool companion_eigenvalues(const Complex* d, std::size_t n, Complex* y)
{
  typedef Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic, 0, MaxN, MaxN> Matrix;
  const Eigen::Index size = static_cast<Eigen::Index>(n);
  Matrix companion = Matrix::Zero(size, size);
  for(Eigen::Index i = 1; i < size; ++i)
    companion(i, i - 1) = 1.;
  for(Eigen::Index i = 0; i < size; ++i)
    companion(i, size - 1) = -d[i];
  balance_matrix(companion);
  Eigen::ComplexEigenSolver<Matrix> solver(companion, false);
  if(solver.info() != Eigen::Success)
    return false;
  for(Eigen::Index i = 0; i < size; ++i)
  {
    y[i] = solver.eigenvalues()[i];
    if(!is_finite(y[i]))
      return false;
  }
  return true;
}

// Roots (unordered) of the monic z^n + sum_m c[m] z^m, n >= 1, finite coefficients.
// Exactly zero low coefficients c[0..k-1] give exactly k zero roots (deflation).
// The rest is scaled by a power of two 2^s (z = 2^s y, exact) so that the scaled
// coefficient of y^m is of magnitude below 2^(1 + (n-m)/2) and at least one of
// them is of magnitude about 1, which keeps the roots of order 1; then
// companion eigenvalues, Newton polish, scale back.
inline void unordered_polynomial_roots(const Complex* c, std::size_t n,
                                       Complex* z)
{
  std::size_t zeros = 0;
  while(zeros < n && is_zero(c[zeros]))
    z[zeros++] = Complex(0., 0.);
  const std::size_t degree = n - zeros;
  if(degree == 0)
    return;
  const Complex* cr = c + zeros; // reduced polynomial, degree `degree`
  Complex* roots = z + zeros;
  if(degree == 1)
  {
    roots[0] = Complex(0., 0.) - cr[0];
    return;
  }
  int s = std::numeric_limits<int>::min();
  for(std::size_t m = 0; m < degree; ++m)
  {
    const double a = max_abs_component(cr[m]);
    if(a > 0.)
    {
      const int e = std::ilogb(a);
      const int k = int(std::floor(double(e) / double(degree - m) + 0.5));
      s = (std::max)(s, k);
    }
  }
  CGAL_assertion(s != std::numeric_limits<int>::min()); // cr[0] != 0
  Complex_buffer d(degree);
  for(std::size_t m = 0; m < degree; ++m)
    d[m] = complex_ldexp(cr[m], -s * int(degree - m));
  bool ok;
  if(degree <= Complex_buffer::inline_capacity)
    ok = companion_eigenvalues<int(Complex_buffer::inline_capacity)>(d.data(), degree, roots);
  else
    ok = companion_eigenvalues<Eigen::Dynamic>(d.data(), degree, roots);
  if(!ok)
    aberth_roots(d.data(), degree, roots);
  polish_roots(d.data(), degree, roots);
  for(std::size_t i = 0; i < degree; ++i)
    roots[i] = complex_ldexp(roots[i], s);
}

/// Roots of the monic polynomial with coefficients c[0..N-1] through the
/// companion matrix, in counterclockwise order. With `sign_symmetric` (N even),
/// only the even coefficients are read: the N/2 roots w of
/// w^(N/2) + sum_k c[2k] w^k give the pairs {sqrt(w), -sqrt(w)}.
/// This is the general path of `polyvector_roots()`, exposed for testing the
/// closed forms against it. Precondition: finite coefficients.
inline void companion_roots(const Complex* c, std::size_t N, Complex* roots,
                            bool sign_symmetric = false)
{
  if(N == 0)
    return;
  if(!sign_symmetric)
  {
    unordered_polynomial_roots(c, N, roots);
    sort_ccw(roots, N);
    return;
  }
  CGAL_precondition(N % 2 == 0);
  const std::size_t k = N / 2;
  Complex_buffer e(k), w(k);
  for(std::size_t i = 0; i < k; ++i)
    e[i] = c[2 * i];
  unordered_polynomial_roots(e.data(), k, w.data());
  for(std::size_t i = 0; i < k; ++i)
    w[i] = upper_half_representative(principal_sqrt(w[i]));
  write_sign_symmetric_roots(w.data(), k, roots);
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_POLYNOMIAL_ROOTS_H
