// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_CONJUGACY_PROJECTION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_CONJUGACY_PROJECTION_H

// Local step of the conjugate frame-field iterations (paper Section 4.3 and
// Appendix A; NOTES.md Section 5): the projection of a pair of tangent vectors
// (u0, v0) of one face onto the set of pairs that are conjugate with respect to
// the face's shape operator S, i.e. onto the quadric u^T S v = 0.
//
// Everything here is per-face arithmetic in the face's orthonormal frame; no
// mesh is involved. A complex number x + iy is the vector (x, y) of the frame.

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

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

// h_j(tau) = tau^2 * secular(lambda): no pole at tau = 0, same roots as the
// secular equation elsewhere. Also returns `magnitude`, the sum of the absolute
// values of its terms, which bounds its round-off. Returns false at another
// pole.
inline bool evaluate_shifted(const Problem& P, std::size_t j, double tau, double& h, double& dh,
                             double& magnitude)
{
  const double s_j = P.groups[j].s;
  double R = 0., dR = 0., R_abs = 0.;
  for(std::size_t m = 0; m < P.groups.size(); ++m)
  {
    if(m == j)
      continue;
    const double s_m = P.groups[m].s;
    const double d = shifted_denominator(s_j, s_m, tau);
    if(d == 0.)
      return false;
    const double q = P.groups[m].Z * s_m / (d * d);
    R += q;
    R_abs += std::abs(q);
    dR += -2. * q * (s_m / s_j) / d;
  }
  h = P.groups[j].Z * s_j + tau * tau * R;
  dh = 2. * tau * R + tau * tau * dR;
  magnitude = std::abs(P.groups[j].Z * s_j) + tau * tau * R_abs;
  return std::isfinite(h) && std::isfinite(dh);
}

// Damped Newton iteration on h_j, from tau. Stops when |h_j| is at its
// round-off level, when the step is below one ulp of tau, or when |h_j| stops
// decreasing.
inline double newton_shifted(const Problem& P, std::size_t j, double tau)
{
  const double eps = std::numeric_limits<double>::epsilon();
  double h = 0., dh = 0., magnitude = 0.;
  if(!evaluate_shifted(P, j, tau, h, dh, magnitude))
    return tau;
  for(int iteration = 0; iteration < 100; ++iteration)
  {
    if(std::abs(h) <= 4. * eps * magnitude || dh == 0.)
      break;
    double step = h / dh;
    bool accepted = false;
    for(int halving = 0; halving < 30; ++halving)
    {
      const double tau_new = tau - step;
      double h_new = 0., dh_new = 0., magnitude_new = 0.;
      if(evaluate_shifted(P, j, tau_new, h_new, dh_new, magnitude_new) && std::abs(h_new) < std::abs(h))
      {
        tau = tau_new;
        h = h_new;
        dh = dh_new;
        magnitude = magnitude_new;
        accepted = true;
        break;
      }
      step *= 0.5;
    }
    if(!accepted || std::abs(step) <= eps * std::abs(tau))
      break;
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

// Real polynomial, coefficients from degree 0 up.
typedef std::vector<double> Polynomial;

inline Polynomial multiply(const Polynomial& p, const Polynomial& q)
{
  Polynomial r(p.size() + q.size() - 1, 0.);
  for(std::size_t i = 0; i < p.size(); ++i)
    for(std::size_t k = 0; k < q.size(); ++k)
      r[i + k] += p[i] * q[k];
  return r;
}

inline void evaluate(const Polynomial& p, double x, double& value, double& derivative)
{
  value = 0.;
  derivative = 0.;
  for(std::size_t i = p.size(); i-- > 0;)
  {
    derivative = derivative * x + value;
    value = value * x + p[i];
  }
}

// Numerator of the secular equation sum_m Z_m s_m / (1 + lambda s_m)^2 = 0,
// multiplied by prod_j (1 + lambda s_j)^2 over the distinct non-zero s_j:
// degree at most 2 (#groups - 1) <= 6.
inline Polynomial secular_numerator(const Problem& P)
{
  Polynomial p(1, 0.);
  for(std::size_t m = 0; m < P.groups.size(); ++m)
  {
    Polynomial term(1, P.groups[m].Z * P.groups[m].s);
    for(std::size_t j = 0; j < P.groups.size(); ++j)
    {
      if(j == m)
        continue;
      const double s_j = P.groups[j].s;
      term = multiply(term, Polynomial{1., 2. * s_j, s_j * s_j});
    }
    if(term.size() > p.size())
      p.resize(term.size(), 0.);
    for(std::size_t i = 0; i < term.size(); ++i)
      p[i] += term[i];
  }
  return p;
}

// Real parts of the roots of p (degree at most 6) whose imaginary part is small, from the
// eigenvalues of the (balanced) companion matrix. The threshold is generous on
// purpose: a double root comes out as a complex pair with an imaginary part of
// order sqrt(eps), and a spurious seed costs nothing since every candidate is
// made feasible and compared by distance.
inline std::vector<double> real_roots(Polynomial p)
{
  std::vector<double> roots;
  double scale = 0.;
  for(double c : p)
    scale = (std::max)(scale, std::abs(c));
  if(scale == 0.) // identically zero: no information
    return roots;
  // Drop negligible leading coefficients: their roots lie beyond |lambda| ~ 1e13,
  // where the stationary point is, to that accuracy, the singular point of the
  // quadric, which is a candidate anyway.
  std::size_t n = p.size() - 1;
  while(n > 0 && std::abs(p[n]) <= 1e-13 * scale)
    --n;
  CGAL_assertion(n <= 6); // 4 groups at most
  if(n == 0 || n > 6)
    return roots;
  typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6> Companion; // no heap
  Companion C = Companion::Zero(n, n);
  for(std::size_t i = 1; i < n; ++i)
    C(i, i - 1) = 1.;
  for(std::size_t i = 0; i < n; ++i)
    C(i, n - 1) = -p[i] / p[n];
  // Balancing by powers of two (Parlett-Reinsch): similar matrix, exact scaling.
  for(bool converged = false; !converged;)
  {
    converged = true;
    for(Eigen::Index i = 0; i < Eigen::Index(n); ++i)
    {
      double col = 0., row = 0.;
      for(Eigen::Index k = 0; k < Eigen::Index(n); ++k)
        if(k != i)
        {
          col += std::abs(C(k, i));
          row += std::abs(C(i, k));
        }
      if(col == 0. || row == 0.)
        continue;
      double f = 1.;
      const double total = col + row;
      while(col < row / 2.) { col *= 2.; row /= 2.; f *= 2.; }
      while(col >= row * 2.) { col /= 2.; row *= 2.; f /= 2.; }
      if(col + row < 0.95 * total)
      {
        converged = false;
        C.col(i) *= f;
        C.row(i) /= f;
      }
    }
  }
  Eigen::EigenSolver<Companion> solver(C, false);
  if(solver.info() != Eigen::Success)
    return roots;
  for(Eigen::Index i = 0; i < solver.eigenvalues().size(); ++i)
  {
    const std::complex<double> r = solver.eigenvalues()[i];
    if(std::isfinite(r.real()) && std::abs(r.imag()) <= 1e-4 * (std::max)(1., std::abs(r.real())))
    {
      // Guarded Newton polish on the polynomial itself.
      double x = r.real(), value = 0., derivative = 0.;
      evaluate(p, x, value, derivative);
      for(int iteration = 0; iteration < 20 && value != 0. && derivative != 0.; ++iteration)
      {
        const double x_new = x - value / derivative;
        double value_new = 0., derivative_new = 0.;
        evaluate(p, x_new, value_new, derivative_new);
        if(!(std::abs(value_new) < std::abs(value)))
          break;
        x = x_new;
        value = value_new;
        derivative = derivative_new;
      }
      roots.push_back(x);
    }
  }
  return roots;
}

// Index of the group whose pole -1/s is nearest to lambda.
inline std::size_t nearest_pole(const Problem& P, double lambda)
{
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for(std::size_t j = 0; j < P.groups.size(); ++j)
  {
    const double d = std::abs(lambda + 1. / P.groups[j].s);
    if(d < best_distance)
    {
      best_distance = d;
      best = j;
    }
  }
  return best;
}

// Refines a root of the secular equation from (j, tau), switching to the
// variable of the nearest pole when it changes, and returns the stationary
// point there.
inline bool refined_stationary_point(const Problem& P, std::size_t j, double tau, Vec4& y)
{
  for(int pass = 0; pass < 4; ++pass)
  {
    tau = newton_shifted(P, j, tau);
    // Which denominator is smallest now? Re-express in its pole's variable.
    std::size_t j_best = j;
    double smallest = std::abs(tau);
    for(std::size_t m = 0; m < P.groups.size(); ++m)
    {
      if(m == j)
        continue;
      const double d = std::abs(shifted_denominator(P.groups[j].s, P.groups[m].s, tau));
      if(d < 0.5 * smallest)
      {
        smallest = d;
        j_best = m;
      }
    }
    if(j_best == j)
      break;
    tau = shifted_denominator(P.groups[j].s, P.groups[j_best].s, tau);
    j = j_best;
  }
  return stationary_point(P, j, tau, y);
}

// Closed-form eigen-decomposition of H = 1/2 [[0, S], [S, 0]]. With
// S = k1 d1 d1^T + k2 d2 d2^T, H has the eigenpairs
//   k1/2: (d1, d1)/sqrt2,  -k1/2: (d1, -d1)/sqrt2,
//   k2/2: (d2, d2)/sqrt2,  -k2/2: (d2, -d2)/sqrt2.
// Equal eigenvalues (umbilic S, or k1 = -k2) are merged into one group; zero
// eigenvalues (parabolic S) go to the kernel.
inline void decompose(Problem& P)
{
  const double mean = 0.5 * (P.a + P.c);
  const double half_difference = 0.5 * (P.a - P.c);
  const double radius = std::hypot(half_difference, P.b);
  double k1 = mean + radius, k2 = mean - radius;
  // The eigenvalue of smaller magnitude loses its relative accuracy to
  // cancellation when it is much smaller than the other one (nearly parabolic
  // S). It is then recomputed as det(S) / k_big, with det(S) = ac - b^2
  // evaluated by Kahan's fma scheme, which is accurate to a few ulps.
  double& k_small = (mean >= 0.) ? k2 : k1;
  const double k_big = (mean >= 0.) ? k1 : k2;
  if(std::abs(k_small) < 0.125 * std::abs(k_big))
  {
    const double bb = P.b * P.b;
    const double bb_error = std::fma(-P.b, P.b, bb); // bb - b^2, exactly
    const double det = std::fma(P.a, P.c, -bb) + bb_error;
    k_small = det / k_big;
  }
  const double phi = 0.5 * std::atan2(2. * P.b, P.a - P.c);
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
/// Method (paper Appendix A, made precise in NOTES.md Section 5): with
/// `y = (u, v)` and `H = 1/2 [[0, S], [S, 0]] = U diag(s) U^T` (closed form),
/// `z = U^T y0`, the stationary points are `y = U (I + lambda diag(s))^{-1} z`
/// with `lambda` a real root of `sum_m z_m^2 s_m / (1 + lambda s_m)^2 = 0`.
/// The numerator of that equation is a polynomial of degree at most 6; its real
/// roots (companion matrix) seed a Newton iteration on the secular equation
/// written in the shifted variable `tau = 1 + lambda s_j` of the nearest pole,
/// which keeps the stationary point accurate for roots close to a pole. More
/// Newton seeds: the two leading-order roots `tau = +-sqrt(-Z_j s_j / R_j(0))`
/// next to each pole (a pair of roots that the polynomial cannot separate when
/// `z` has almost no component in the eigenspace of `s_j`), and points between
/// and beyond the poles. Further candidates: the pole points `lambda = -1/s_j`
/// when `z` has no component in the eigenspace of `s_j` (that component is then
/// free and its norm follows from the constraint), `y0` itself moved onto the
/// quadric, and the singular point of the quadric nearest to `y0`. Every
/// candidate is moved exactly onto the quadric (projection of `v` onto
/// `(S u)^perp` or of `u` onto `(S v)^perp`, whichever moves less) and the
/// candidate closest to `y0` is returned.
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

  // Fast path. With a single quadratic constraint, the global minimiser is the
  // stationary point whose multiplier makes I + lambda H positive semidefinite,
  // i.e. lambda in the central interval (-1/s_max, -1/s_min) between the poles
  // of the largest and the smallest eigenvalue of H. There the secular function
  // f(lambda) = sum_g Z_g s_g / (1 + lambda s_g)^2 decreases strictly, from +inf
  // to -inf when y0 has a component in both extreme eigenspaces, so it has
  // exactly one root, found by Newton safeguarded by bisection. When an extreme
  // component is (nearly) zero the root approaches a pole (the "hard case"),
  // and the general method below takes over.
  {
    const impl::Eigen_group* largest = nullptr;
    const impl::Eigen_group* smallest = nullptr;
    double total = 0.;
    for(const impl::Eigen_group& g : P.groups)
    {
      total += g.Z;
      if(!largest || g.s > largest->s)
        largest = &g;
      if(!smallest || g.s < smallest->s)
        smallest = &g;
    }
    for(int col : P.kernel_columns)
      total += P.z[col] * P.z[col];
    if(largest && smallest && largest->s > 0. && smallest->s < 0. &&
       largest->Z > 1e-6 * total && smallest->Z > 1e-6 * total)
    {
      double low = -1. / largest->s, high = -1. / smallest->s, lambda = 0.;
      for(int iteration = 0; iteration < 200; ++iteration)
      {
        double f = 0., df = 0.;
        for(const impl::Eigen_group& g : P.groups)
        {
          const double d = 1. + lambda * g.s;
          f += g.Z * g.s / (d * d);
          df -= 2. * g.Z * g.s * g.s / (d * d * d);
        }
        if(f == 0.)
          break;
        (f > 0. ? low : high) = lambda;  // f decreases: the root is right of a positive value
        double next = lambda - f / df;
        if(!(next > low && next < high))
          next = 0.5 * (low + high);
        const double step = next - lambda;
        lambda = next;
        if(std::abs(step) <= 4. * std::numeric_limits<double>::epsilon() * (std::abs(lambda) + 1e-300))
          break;
      }
      impl::Vec4 y = {{0., 0., 0., 0.}};
      for(int col = 0; col < 4; ++col)
      {
        double eigenvalue = 0.;
        for(const impl::Eigen_group& g : P.groups)
          for(int k = 0; k < g.count; ++k)
            if(g.column[k] == col)
              eigenvalue = g.s;
        const double w = P.z[col] / (1. + lambda * eigenvalue);
        for(int i = 0; i < 4; ++i)
          y[i] += w * P.U[col][i];
      }
      impl::make_conjugate(P, y);
      if(impl::is_finite(y))
        return { std::complex<double>(std::ldexp(y[0], y_exponent), std::ldexp(y[1], y_exponent)),
                 std::complex<double>(std::ldexp(y[2], y_exponent), std::ldexp(y[3], y_exponent)) };
    }
  }

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

  // Always-feasible fallbacks: y0 moved onto the quadric, and the singular
  // point nearest to y0 (all components outside the kernel of H set to zero).
  consider(P.y0);
  {
    impl::Vec4 y = {{0., 0., 0., 0.}};
    for(int col : P.kernel_columns)
      for(int i = 0; i < 4; ++i)
        y[i] += P.z[col] * P.U[col][i];
    consider(y);
  }

  if(!P.groups.empty())
  {
    impl::Vec4 y;
    // Roots of the secular numerator.
    for(double lambda : impl::real_roots(impl::secular_numerator(P)))
    {
      const std::size_t j = impl::nearest_pole(P, lambda);
      if(impl::refined_stationary_point(P, j, 1. + lambda * P.groups[j].s, y))
        consider(y);
    }
    for(std::size_t j = 0; j < P.groups.size(); ++j)
    {
      // Pole with a free component.
      if(P.groups[j].Z == 0.)
      {
        if(impl::pole_point(P, j, y))
          consider(y);
        continue;
      }
      // Near a pole, the two roots tau ~ +-sqrt(-Z_j s_j / R_j(0)): extra seeds,
      // so that neither of a close pair of roots can be missed.
      double R0 = 0.; // R_j(0) = sum over the other groups of Z_m s_m / (1 - s_m/s_j)^2
      for(std::size_t m = 0; m < P.groups.size(); ++m)
        if(m != j)
        {
          const double d = impl::shifted_denominator(P.groups[j].s, P.groups[m].s, 0.);
          R0 += P.groups[m].Z * P.groups[m].s / (d * d);
        }
      const double tau2 = -P.groups[j].Z * P.groups[j].s / R0;
      if(tau2 > 0. && std::isfinite(tau2))
        for(double sign : {1., -1.})
          if(impl::refined_stationary_point(P, j, sign * std::sqrt(tau2), y))
            consider(y);
    }
    // Seeds between consecutive poles and beyond them.
    std::vector<double> poles;
    for(const impl::Eigen_group& g : P.groups)
      poles.push_back(-1. / g.s);
    std::sort(poles.begin(), poles.end());
    std::vector<double> seeds;
    for(std::size_t i = 0; i + 1 < poles.size(); ++i)
      seeds.push_back(0.5 * (poles[i] + poles[i + 1]));
    seeds.push_back(poles.front() - 1. - std::abs(poles.front()));
    seeds.push_back(poles.back() + 1. + std::abs(poles.back()));
    for(double lambda : seeds)
    {
      const std::size_t j = impl::nearest_pole(P, lambda);
      if(impl::refined_stationary_point(P, j, 1. + lambda * P.groups[j].s, y))
        consider(y);
    }
  }

  return std::make_pair(std::complex<double>(std::ldexp(best[0], y_exponent), std::ldexp(best[1], y_exponent)),
                        std::complex<double>(std::ldexp(best[2], y_exponent), std::ldexp(best[3], y_exponent)));
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_CONJUGACY_PROJECTION_H
