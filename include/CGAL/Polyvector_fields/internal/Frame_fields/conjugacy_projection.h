// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_CONJUGACY_PROJECTION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_CONJUGACY_PROJECTION_H

// Local step of the conjugate frame-field iterations (paper Section 4.3 and
// Appendix A; the user manual's section "Conjugate frame fields"): the projection of a pair of tangent vectors
// (u0, v0) of one face onto the set of pairs that are conjugate with respect to
// the face's shape operator S, i.e. onto the quadric u^T S v = 0.
//
// Everything here is per-face arithmetic in the face's orthonormal frame; no
// mesh is involved. A complex number x + iy is the vector (x, y) of the frame.

#include <CGAL/Polyvector_fields/internal/Curvature/curvature_tensor.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

/// Returns `u^T S v`, where `S` is the 2x2 matrix stored row-major in
/// `S_row_major` and `u`, `v` are the vectors `(Re, Im)` of the complex numbers.
inline double conjugacy_residual(const std::array<double, 4>& S_row_major,
                                 std::complex<double> u,
                                 std::complex<double> v)
{
  const double Sv_x = S_row_major[0] * v.real() + S_row_major[1] * v.imag();
  const double Sv_y = S_row_major[2] * v.real() + S_row_major[3] * v.imag();
  return u.real() * Sv_x + u.imag() * Sv_y;
}

namespace conjugacy_projection_impl {

typedef std::array<double, 4> Vec4; // y = (u_x, u_y, v_x, v_y)

// One eigenvalue of H = 1/2 [[0, S], [S, 0]] together with the columns of U
// that span its eigenspace (1 or 2 of them once equal eigenvalues are merged).
struct Eigen_group
{
  double s = 0.;         // eigenvalue of H (for the normalised S)
  int count = 0;         // number of columns of U in the group
  int column[2] = {0, 0};
  double Z = 0.;         // squared norm of the component of y0 in the group
};

// The problem after normalisation: S scaled by a power of two so that its
// largest entry lies in [0.5, 1), y0 likewise.
struct Problem
{
  double a = 0., b = 0., c = 0.; // normalised symmetric S = [[a, b], [b, c]]
  Vec4 y0 = {{0., 0., 0., 0.}};
  std::array<Vec4, 4> U;         // orthonormal eigenvectors of H (columns)
  std::array<double, 4> z = {{0., 0., 0., 0.}}; // z = U^T y0
  std::vector<Eigen_group> groups;      // distinct non-zero eigenvalues of H
  std::vector<int> kernel_columns;      // columns of U with eigenvalue exactly 0
};

inline double dot4(const Vec4& p, const Vec4& q)
{
  return p[0] * q[0] + p[1] * q[1] + p[2] * q[2] + p[3] * q[3];
}

inline double residual(const Problem& P, const Vec4& y)
{
  const double Sv_x = P.a * y[2] + P.b * y[3];
  const double Sv_y = P.b * y[2] + P.c * y[3];
  return y[0] * Sv_x + y[1] * Sv_y;
}

inline double squared_distance(const Vec4& p, const Vec4& q)
{
  double d = 0.;
  for(int i = 0; i < 4; ++i)
    d += (p[i] - q[i]) * (p[i] - q[i]);
  return d;
}

inline bool is_finite(const Vec4& y)
{
  return std::isfinite(y[0]) && std::isfinite(y[1]) && std::isfinite(y[2]) && std::isfinite(y[3]);
}

// Moves y onto the quadric by the smaller of two exact projections: v onto the
// line (S u)^perp with u fixed, or u onto (S v)^perp with v fixed. For a point
// that is nearly on the quadric this is a tiny move; afterwards the residual is
// a few ulps of |S| |u| |v|.
inline void make_conjugate(const Problem& P, Vec4& y)
{
  for(int iteration = 0; iteration < 2; ++iteration)
  {
    const double Su_x = P.a * y[0] + P.b * y[1], Su_y = P.b * y[0] + P.c * y[1];
    const double Sv_x = P.a * y[2] + P.b * y[3], Sv_y = P.b * y[2] + P.c * y[3];
    const double r = y[0] * Sv_x + y[1] * Sv_y;
    if(r == 0.)
      return;
    const double nSu = Su_x * Su_x + Su_y * Su_y;
    const double nSv = Sv_x * Sv_x + Sv_y * Sv_y;
    if(nSu == 0. && nSv == 0.)
      return;
    if(nSu >= nSv)
    {
      const double t = r / nSu;
      y[2] -= t * Su_x;
      y[3] -= t * Su_y;
    }
    else
    {
      const double t = r / nSv;
      y[0] -= t * Sv_x;
      y[1] -= t * Sv_y;
    }
  }
}

// Denominator 1 + lambda s_m written in the variable tau = 1 + lambda s_j of
// the pole of group j, which keeps it accurate when lambda is close to -1/s_j.
inline double shifted_denominator(double s_j, double s_m, double tau)
{
  return ((s_j - s_m) + tau * s_m) / s_j;
}

// h_j(tau) = tau^2 f(lambda), where f(lambda) = sum_m Z_m s_m / (1 + lambda s_m)^2
// is the secular function and tau = 1 + lambda s_j: no pole at tau = 0, the
// sign of f for tau > 0. Also returns `magnitude`, the sum of the absolute
// values of its terms, which bounds its round-off.
inline void evaluate_shifted(const Problem& P, std::size_t j, double tau, double& h, double& dh,
                             double& magnitude)
{
  const double s_j = P.groups[j].s;
  double R = 0., dR = 0., R_abs = 0.;
  for(std::size_t m = 0; m < P.groups.size(); ++m)
  {
    if(m == j)
      continue;
    const double s_m = P.groups[m].s;
    const double d = shifted_denominator(s_j, s_m, tau); // > 0 inside the interval
    const double q = P.groups[m].Z * s_m / (d * d);
    R += q;
    R_abs += std::abs(q);
    dR += -2. * q * (s_m / s_j) / d;
  }
  h = P.groups[j].Z * s_j + tau * tau * R;
  dh = 2. * tau * R + tau * tau * dR;
  magnitude = std::abs(P.groups[j].Z * s_j) + tau * tau * R_abs;
}

// The root tau in (0, 1] of h_j, given the sign `sign_at_zero` of f next to
// the pole (tau -> 0+) and the opposite sign at tau = 1 (lambda = 0): Newton
// steps inside a bracket that shrinks at every step, bisection (geometric once
// the bracket spans orders of magnitude) when a step leaves it.
inline double secular_root(const Problem& P, std::size_t j, double sign_at_zero)
{
  const double eps = std::numeric_limits<double>::epsilon();
  double low = 0., high = 1., tau = 1.;
  for(int iteration = 0; iteration < 2000; ++iteration)
  {
    double h = 0., dh = 0., magnitude = 0.;
    evaluate_shifted(P, j, tau, h, dh, magnitude);
    if(std::abs(h) <= 4. * eps * magnitude)
      break;
    (h * sign_at_zero > 0. ? low : high) = tau;
    if(high - low <= 2. * eps * high)
      break;
    double next = tau - h / dh;
    if(!(next > low && next < high))
      next = (low > 0. && high > 4. * low) ? std::sqrt(low * high)
                                           : (low > 0. ? 0.5 * (low + high) : 0.25 * high);
    tau = next;
  }
  return tau;
}

// Stationary point y = U (I + lambda diag(s))^{-1} z, with lambda given through
// tau = 1 + lambda s_j. Returns false if a denominator vanishes.
inline bool stationary_point(const Problem& P, std::size_t j, double tau, Vec4& y)
{
  y = {{0., 0., 0., 0.}};
  const double s_j = P.groups[j].s;
  for(std::size_t m = 0; m < P.groups.size(); ++m)
  {
    const double d = (m == j) ? tau : shifted_denominator(s_j, P.groups[m].s, tau);
    if(d == 0.)
      return false;
    for(int k = 0; k < P.groups[m].count; ++k)
    {
      const int col = P.groups[m].column[k];
      const double w = P.z[col] / d;
      for(int i = 0; i < 4; ++i)
        y[i] += w * P.U[col][i];
    }
  }
  for(int col : P.kernel_columns)
    for(int i = 0; i < 4; ++i)
      y[i] += P.z[col] * P.U[col][i];
  return is_finite(y);
}

// Candidate at the pole lambda = -1/s_j when y0 has no component in the
// eigenspace of s_j: that component of the stationary point is free, and its
// norm t is fixed by the constraint. Returns false if t^2 < 0.
inline bool pole_point(const Problem& P, std::size_t j, Vec4& y)
{
  y = {{0., 0., 0., 0.}};
  const double s_j = P.groups[j].s;
  double sum = 0.; // sum over the other groups of s_m |w_m|^2
  for(std::size_t m = 0; m < P.groups.size(); ++m)
  {
    if(m == j)
      continue;
    const double d = shifted_denominator(s_j, P.groups[m].s, 0.);
    for(int k = 0; k < P.groups[m].count; ++k)
    {
      const int col = P.groups[m].column[k];
      const double w = P.z[col] / d;
      sum += P.groups[m].s * w * w;
      for(int i = 0; i < 4; ++i)
        y[i] += w * P.U[col][i];
    }
  }
  const double t2 = -sum / s_j;
  if(!(t2 >= 0.))
    return false;
  // The free component may point anywhere in the eigenspace: the distance to
  // y0 does not depend on its direction, so take the first column.
  const double t = std::sqrt(t2);
  const int col = P.groups[j].column[0];
  for(int i = 0; i < 4; ++i)
    y[i] += t * P.U[col][i];
  for(int col_k : P.kernel_columns)
    for(int i = 0; i < 4; ++i)
      y[i] += P.z[col_k] * P.U[col_k][i];
  return is_finite(y);
}

// Closed-form eigen-decomposition of H = 1/2 [[0, S], [S, 0]]. With
// S = k1 d1 d1^T + k2 d2 d2^T, H has the eigenpairs
//   k1/2: (d1, d1)/sqrt2,  -k1/2: (d1, -d1)/sqrt2,
//   k2/2: (d2, d2)/sqrt2,  -k2/2: (d2, -d2)/sqrt2.
// Equal eigenvalues (umbilic S, or k1 = -k2) are merged into one group; zero
// eigenvalues (parabolic S) go to the kernel.
inline void decompose(Problem& P)
{
  const Symmetric_eigen_2 eigen = symmetric_eigen_2(P.a, P.b, P.c);
  const double k1 = eigen.lambda_max, k2 = eigen.lambda_min, phi = eigen.angle;
  const double c = std::cos(phi), s = std::sin(phi);
  const double r = 1. / std::sqrt(2.);
  // d1 = (c, s), d2 = (-s, c)
  P.U[0] = {{r * c, r * s, r * c, r * s}};
  P.U[1] = {{r * c, r * s, -r * c, -r * s}};
  P.U[2] = {{-r * s, r * c, -r * s, r * c}};
  P.U[3] = {{-r * s, r * c, r * s, -r * c}};
  const double eigenvalue[4] = {0.5 * k1, -0.5 * k1, 0.5 * k2, -0.5 * k2};
  for(int col = 0; col < 4; ++col)
  {
    P.z[col] = dot4(P.U[col], P.y0);
    if(eigenvalue[col] == 0.)
    {
      P.kernel_columns.push_back(col);
      continue;
    }
    bool merged = false;
    for(Eigen_group& g : P.groups)
      if(g.s == eigenvalue[col])
      {
        g.column[g.count++] = col;
        g.Z += P.z[col] * P.z[col];
        merged = true;
        break;
      }
    if(!merged)
    {
      Eigen_group g;
      g.s = eigenvalue[col];
      g.count = 1;
      g.column[0] = col;
      g.Z = P.z[col] * P.z[col];
      P.groups.push_back(g);
    }
  }
}

inline int binary_exponent(double x)
{
  int e = 0;
  std::frexp(x, &e);
  return e;
}

} // namespace conjugacy_projection_impl

/// Projects the pair `(u0, v0)` onto the set of pairs that are conjugate with
/// respect to the symmetric 2x2 shape operator `S` (row-major): returns the
/// `(u, v)` that minimises `|u - u0|^2 + |v - v0|^2` subject to `u^T S v = 0`.
///
/// Method (paper Appendix A, made precise in the user manual): with
/// `y = (u, v)` and `H = 1/2 [[0, S], [S, 0]] = U diag(s) U^T` (closed form),
/// `z = U^T y0`, the stationary points are `y = U (I + lambda diag(s))^{-1} z`
/// with `lambda` a real root of the secular equation
/// `f(lambda) = sum_m z_m^2 s_m / (1 + lambda s_m)^2 = 0`. The global minimiser
/// is the one whose `I + lambda H` is positive semidefinite, that is
/// `|lambda| <= 1/s_max` (the spectrum of `H` is `+-k1/2, +-k2/2`), where `f`
/// decreases strictly: a single root, found by safeguarded Newton in the
/// variable `tau = 1 + lambda s_j` of the pole it lies next to, which keeps the
/// stationary point accurate when the root is close to that pole. When `z` has
/// no component in the pole's eigenspace and `f` keeps its sign (the "hard
/// case"), the minimiser is the pole point: that component is free and its
/// norm follows from the constraint. The candidate is moved exactly onto the
/// quadric (projection of `v` onto `(S u)^perp` or of `u` onto `(S v)^perp`,
/// whichever moves less) and compared with two always-feasible fallbacks,
/// `y0` moved onto the quadric and the singular point nearest to `y0`.
///
/// Degenerate inputs: if `S = 0` or `(u0, v0)` is already conjugate up to
/// round-off (`|u0^T S v0| <= 32 eps |S|_F |u0| |v0|`), `(u0, v0)` is returned
/// unchanged. A zero curvature (parabolic `S`), equal curvatures (umbilic `S`),
/// `k1 = -k2`, repeated roots and roots at the poles are all handled.
///
/// The result satisfies `|u^T S v| <= O(eps) |S| |u| |v|` and is finite. The
/// problem is scale invariant; `S` and `(u0, v0)` are scaled by powers of two
/// internally, so there is no overflow for any finite input, and scaling `S` or
/// `(u0, v0)` by a power of two scales the result exactly (barring underflow
/// of a subnormal result).
///
/// Accuracy: the distance to `y0` is optimal up to about
/// `eps |S| |y|^2 / |grad|`, where `|grad| = |(S v, S u)|` at the solution: the
/// band of pairs that are conjugate up to round-off is that thick. This is
/// about `1e-16 |y|` for well-conditioned inputs; it reaches about `1e-11 |y|`
/// for a nearly parabolic `S` (`|k2| ~ 1e-8 |k1|`) with `(u0, v0)` almost along
/// the flat direction.
///
/// \pre all entries finite; `S` symmetric (an asymmetric `S` is replaced by its
/// symmetric part `(S + S^T)/2`, which defines a different constraint).
inline std::pair<std::complex<double>, std::complex<double> >
project_onto_conjugate_pair(const std::array<double, 4>& S_row_major,
                            std::complex<double> u0,
                            std::complex<double> v0)
{
  namespace impl = conjugacy_projection_impl;
  CGAL_precondition(std::isfinite(S_row_major[0]) && std::isfinite(S_row_major[1]) &&
                    std::isfinite(S_row_major[2]) && std::isfinite(S_row_major[3]));
  CGAL_precondition(std::isfinite(u0.real()) && std::isfinite(u0.imag()) &&
                    std::isfinite(v0.real()) && std::isfinite(v0.imag()));

  const std::pair<std::complex<double>, std::complex<double> > unchanged(u0, v0);

  const double S_max = (std::max)((std::max)(std::abs(S_row_major[0]), std::abs(S_row_major[1])),
                                  (std::max)(std::abs(S_row_major[2]), std::abs(S_row_major[3])));
  const double y_max = (std::max)((std::max)(std::abs(u0.real()), std::abs(u0.imag())),
                                  (std::max)(std::abs(v0.real()), std::abs(v0.imag())));
  if(!(S_max > 0.) || !(y_max > 0.)) // S = 0: every pair is conjugate; y0 = 0 is on the quadric
    return unchanged;

  // Normalise by powers of two (exact).
  const int S_exponent = impl::binary_exponent(S_max);
  const int y_exponent = impl::binary_exponent(y_max);
  impl::Problem P;
  P.a = std::ldexp(S_row_major[0], -S_exponent);
  P.b = std::ldexp(0.5 * (S_row_major[1] + S_row_major[2]), -S_exponent);
  P.c = std::ldexp(S_row_major[3], -S_exponent);
  P.y0 = {{std::ldexp(u0.real(), -y_exponent), std::ldexp(u0.imag(), -y_exponent),
           std::ldexp(v0.real(), -y_exponent), std::ldexp(v0.imag(), -y_exponent)}};

  // Already on the quadric, up to round-off?
  {
    const double S_frobenius = std::sqrt(P.a * P.a + 2. * P.b * P.b + P.c * P.c);
    const double u_norm = std::hypot(P.y0[0], P.y0[1]);
    const double v_norm = std::hypot(P.y0[2], P.y0[3]);
    const double r = impl::residual(P, P.y0);
    if(std::abs(r) <= 32. * std::numeric_limits<double>::epsilon() * S_frobenius * u_norm * v_norm)
      return unchanged;
  }

  impl::decompose(P);

  impl::Vec4 best = P.y0;
  double best_distance = std::numeric_limits<double>::infinity();
  auto consider = [&](impl::Vec4 y)
  {
    impl::make_conjugate(P, y);
    if(!impl::is_finite(y))
      return;
    const double d = impl::squared_distance(y, P.y0);
    if(d < best_distance)
    {
      best_distance = d;
      best = y;
    }
  };

  // The global minimiser has a multiplier lambda with I + lambda H positive
  // semidefinite (one quadratic constraint: the S-lemma). The spectrum of H is
  // symmetric, +-s_max, so lambda lies in [-1/s_max, 1/s_max], where the
  // secular function f decreases strictly. Its root lies on the side of
  // lambda = 0 where f changes sign, next to the pole of the group j with
  // s_j = -sign(f(0)) s_max; it is sought in that pole's variable tau.
  double f0 = 0.;
  for(const impl::Eigen_group& g : P.groups)
    f0 += g.Z * g.s;
  std::size_t j = 0;
  for(std::size_t m = 1; m < P.groups.size(); ++m)
    if((f0 > 0. ? -1. : 1.) * P.groups[m].s > (f0 > 0. ? -1. : 1.) * P.groups[j].s)
      j = m;
  const double sign_at_zero = -(f0 > 0. ? 1. : -1.);
  bool root_inside = true;
  if(P.groups[j].Z == 0.)
  {
    // f(0+) = R_j(0), the sum over the other groups. If it does not have the
    // sign that brackets a root, this is the hard case: the minimiser sits at
    // the pole, with a free component in the eigenspace of s_j.
    double R0 = 0.;
    for(std::size_t m = 0; m < P.groups.size(); ++m)
      if(m != j)
      {
        const double d = impl::shifted_denominator(P.groups[j].s, P.groups[m].s, 0.);
        R0 += P.groups[m].Z * P.groups[m].s / (d * d);
      }
    root_inside = R0 * sign_at_zero > 0.;
    impl::Vec4 y;
    if(!root_inside && impl::pole_point(P, j, y))
      consider(y);
  }
  impl::Vec4 y;
  if(root_inside && impl::stationary_point(P, j, impl::secular_root(P, j, sign_at_zero), y))
    consider(y);
  // Safety nets against round-off: y0 moved onto the quadric, and the singular
  // point nearest to y0 (the components outside the kernel of H set to zero).
  consider(P.y0);
  {
    impl::Vec4 y = {{0., 0., 0., 0.}};
    for(int col : P.kernel_columns)
      for(int i = 0; i < 4; ++i)
        y[i] += P.z[col] * P.U[col][i];
    consider(y);
  }

  return std::make_pair(std::complex<double>(std::ldexp(best[0], y_exponent), std::ldexp(best[1], y_exponent)),
                        std::complex<double>(std::ldexp(best[2], y_exponent), std::ldexp(best[3], y_exponent)));
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_CONJUGACY_PROJECTION_H
