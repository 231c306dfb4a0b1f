// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Tests of the two per-face local steps of the frame-field iterations:
// the projection onto conjugate pairs (NOTES.md Section 5, paper Appendix A)
// and the angle bound (NOTES.md Section 6, paper Section 4.2).

#include <CGAL/Polyvector_fields/internal/Frame_fields/angle_bound_projection.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/conjugacy_projection.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

// The names of this file stay in its own namespace: the group is built as one
// translation unit (unity build).
namespace pvf_frame_local_steps_test {

namespace {

namespace PVFi = CGAL::Polyvector_fields::internal;
typedef std::complex<double> Complex;
typedef std::array<double, 4> Matrix2; // row-major

const double pi = 3.14159265358979323846;

// S = k1 d1 d1^T + k2 d2 d2^T with d1 = (cos a, sin a), d2 = (-sin a, cos a).
Matrix2 shape_operator(double k1, double k2, double angle)
{
  const double c = std::cos(angle), s = std::sin(angle);
  const double off = (k1 - k2) * c * s;
  return {{k1 * c * c + k2 * s * s, off, off, k1 * s * s + k2 * c * c}};
}

double frobenius(const Matrix2& S)
{
  return std::sqrt(S[0] * S[0] + S[1] * S[1] + S[2] * S[2] + S[3] * S[3]);
}

double squared_norm(Complex u, Complex v) { return std::norm(u) + std::norm(v); }

double distance(Complex u, Complex v, Complex u0, Complex v0)
{
  return std::sqrt(std::norm(u - u0) + std::norm(v - v0));
}

bool finite(Complex z) { return std::isfinite(z.real()) && std::isfinite(z.imag()); }

// ---------------------------------------------------------------------------
// Brute force for the conjugate projection.
//
// Every feasible pair (u, v) has v on the line (S u)^perp (or anywhere when
// S u = 0). For a fixed u the best such v is the exact projection of v0 on that
// line, so the problem is the minimisation over u in R^2 of
//   F(u) = |u - u0|^2 + ((S u) . v0)^2 / |S u|^2      (|u - u0|^2 if S u = 0),
// the squared distance of an explicitly feasible pair. Its minimiser lies in
// the disc |u - u0|^2 <= F(u0). We search that disc on a grid, refine the best
// grid points by a compass search, do the same with the roles of u and v
// swapped, and add the points where S u = 0 or S v = 0 (the line is then free).
// ---------------------------------------------------------------------------
struct Vec2
{
  double x, y;
};

Vec2 apply(const Matrix2& S, Vec2 u) { return {S[0] * u.x + S[1] * u.y, S[2] * u.x + S[3] * u.y}; }

// Feasible v for u, closest to v0; returns the squared distance of (u, v) to (u0, v0).
double best_partner(const Matrix2& S, Vec2 u, Vec2 u0, Vec2 v0, Vec2* v_out = nullptr)
{
  const Vec2 a = apply(S, u);
  const double na = a.x * a.x + a.y * a.y;
  Vec2 v = v0;
  if(na > 0.)
  {
    const double t = (a.x * v0.x + a.y * v0.y) / na;
    v = {v0.x - t * a.x, v0.y - t * a.y};
  }
  if(v_out)
    *v_out = v;
  return (u.x - u0.x) * (u.x - u0.x) + (u.y - u0.y) * (u.y - u0.y) +
         (v.x - v0.x) * (v.x - v0.x) + (v.y - v0.y) * (v.y - v0.y);
}

// Minimises best_partner(S, ., u0, v0) over u; returns the smallest value found.
double brute_force_one_side(const Matrix2& S, Vec2 u0, Vec2 v0)
{
  const double R = std::sqrt(best_partner(S, u0, u0, v0));
  if(R == 0.)
    return 0.;
  const int n = 40;
  const double h0 = 2. * R / n;
  std::vector<std::pair<double, Vec2> > grid;
  for(int i = 0; i <= n; ++i)
    for(int k = 0; k <= n; ++k)
    {
      const Vec2 u = {u0.x - R + i * h0, u0.y - R + k * h0};
      grid.push_back({best_partner(S, u, u0, v0), u});
    }
  // Explicit candidates: u = 0, u = u0, and the projection of u0 on the kernel of S.
  grid.push_back({best_partner(S, {0., 0.}, u0, v0), {0., 0.}});
  grid.push_back({best_partner(S, u0, u0, v0), u0});
  {
    // kernel direction of S (if any): eigenvector of the smallest |eigenvalue|
    const double a = S[0], b = 0.5 * (S[1] + S[2]), c = S[3];
    const double phi = 0.5 * std::atan2(2. * b, a - c);
    const double m = 0.5 * (a + c), r = std::hypot(0.5 * (a - c), b);
    const Vec2 d = (std::abs(m + r) < std::abs(m - r)) ? Vec2{std::cos(phi), std::sin(phi)}
                                                      : Vec2{-std::sin(phi), std::cos(phi)};
    const double t = u0.x * d.x + u0.y * d.y;
    const Vec2 u = {t * d.x, t * d.y};
    grid.push_back({best_partner(S, u, u0, v0), u});
  }
  std::sort(grid.begin(), grid.end(),
            [](const std::pair<double, Vec2>& p, const std::pair<double, Vec2>& q) { return p.first < q.first; });
  double best = grid.front().first;
  const std::size_t starts = (std::min)(grid.size(), std::size_t(8));
  for(std::size_t s = 0; s < starts; ++s)
  {
    Vec2 u = grid[s].second;
    double value = grid[s].first;
    double h = h0;
    const double h_min = 1e-14 * (R + std::abs(u0.x) + std::abs(u0.y));
    static const double c8[8] = {1., 0.70710678118654752, 0., -0.70710678118654752, -1., -0.70710678118654752, 0., 0.70710678118654752};
    static const double s8[8] = {0., 0.70710678118654752, 1., 0.70710678118654752, 0., -0.70710678118654752, -1., -0.70710678118654752};
    // Compass search; a move must gain more than round-off, and the number of
    // steps is capped, so that it ends in flat or noisy regions.
    for(int steps = 0; steps < 4000 && h > h_min; ++steps)
    {
      bool moved = false;
      for(int dir = 0; dir < 8; ++dir)
      {
        const Vec2 w = {u.x + h * c8[dir], u.y + h * s8[dir]};
        const double f = best_partner(S, w, u0, v0);
        if(f < value - 1e-15 * value)
        {
          value = f;
          u = w;
          moved = true;
          break;
        }
      }
      h *= moved ? 1.5 : 0.5;
    }
    best = (std::min)(best, value);
  }
  return best;
}

// Smallest squared distance of the feasible pairs found by brute force.
double brute_force(const Matrix2& S, Complex u0, Complex v0)
{
  const Vec2 u = {u0.real(), u0.imag()}, v = {v0.real(), v0.imag()};
  const Matrix2 St = {{S[0], S[2], S[1], S[3]}}; // v^T S^T u = u^T S v
  return (std::min)(brute_force_one_side(S, u, v), brute_force_one_side(St, v, u));
}

// Tolerance of the residual check, for a result y = (u, v).
const double residual_factor = 1e-12; // |u^T S v| <= 1e-12 |S|_F |y|^2

void expect_conjugate(const Matrix2& S, Complex u, Complex v, const std::string& what)
{
  ASSERT_TRUE(finite(u) && finite(v)) << what;
  const double r = PVFi::conjugacy_residual(S, u, v);
  EXPECT_LE(std::abs(r), residual_factor * frobenius(S) * squared_norm(u, v))
    << what << " residual " << r;
}

using pvf_test::random_complex;

} // namespace

// ---------------------------------------------------------------------------
// Conjugacy projection
// ---------------------------------------------------------------------------

TEST(FrameLocalSteps, ConjugacyResidualIsBilinearForm)
{
  const Matrix2 S = {{1., 2., 3., 4.}}; // u^T S v, row-major
  EXPECT_EQ(PVFi::conjugacy_residual(S, Complex(1, 0), Complex(0, 1)), 2.);
  EXPECT_EQ(PVFi::conjugacy_residual(S, Complex(0, 1), Complex(1, 0)), 3.);
  // S v = (1*3 + 2*(-1), 3*3 + 4*(-1)) = (1, 5); u . S v = 1*1 + 2*5
  EXPECT_EQ(PVFi::conjugacy_residual(S, Complex(1, 2), Complex(3, -1)), 11.);
}

// The certificate of global optimality (one quadratic constraint): at the
// result y = (u, v), y0 - y = lambda grad(y^T H y)/2 = lambda H y with
// H = 1/2 [[0, S], [S, 0]], and I + lambda H is positive semidefinite, i.e.
// |lambda| max(|k1|, |k2|) / 2 <= 1. Checked on generic random inputs, where
// the gradient is far from zero.
TEST(FrameLocalSteps, ConjugacyMultiplierCertifiesGlobalMinimum)
{
  std::mt19937_64 rng(20261201);
  std::uniform_real_distribution<double> U11(-1., 1.);
  int cases = 0;
  for(int it = 0; it < 2000; ++it)
  {
    const double b = U11(rng);
    const Matrix2 S = {{U11(rng), b, b, U11(rng)}};
    const Complex u0(U11(rng), U11(rng)), v0(U11(rng), U11(rng));
    const std::pair<Complex, Complex> y = PVFi::project_onto_conjugate_pair(S, u0, v0);
    const Complex u = y.first, v = y.second;
    // H y = 1/2 (S v, S u), as complex numbers.
    const Complex Sv(S[0] * v.real() + S[1] * v.imag(), S[2] * v.real() + S[3] * v.imag());
    const Complex Su(S[0] * u.real() + S[1] * u.imag(), S[2] * u.real() + S[3] * u.imag());
    const Complex Hy_u = 0.5 * Sv, Hy_v = 0.5 * Su;
    const double Hy2 = std::norm(Hy_u) + std::norm(Hy_v);
    if(Hy2 < 1e-6) // near the singular point the multiplier is ill-determined
      continue;
    const Complex du = u0 - u, dv = v0 - v;
    const double lambda = (du.real() * Hy_u.real() + du.imag() * Hy_u.imag() +
                           dv.real() * Hy_v.real() + dv.imag() * Hy_v.imag()) / Hy2;
    // y0 - y is parallel to H y ...
    const double misfit = std::sqrt(std::norm(du - lambda * Hy_u) + std::norm(dv - lambda * Hy_v));
    EXPECT_LE(misfit, 1e-9 * (1. + std::sqrt(squared_norm(u0, v0)))) << "case " << it;
    // ... with a multiplier in the positive semidefinite interval.
    const double k1 = 0.5 * (S[0] + S[3]) + std::hypot(0.5 * (S[0] - S[3]), b);
    const double k2 = 0.5 * (S[0] + S[3]) - std::hypot(0.5 * (S[0] - S[3]), b);
    const double s_max = 0.5 * (std::max)(std::abs(k1), std::abs(k2));
    EXPECT_LE(std::abs(lambda) * s_max, 1. + 1e-9) << "case " << it << ", lambda " << lambda;
    ++cases;
  }
  EXPECT_GE(cases, 1500);
}

// Random shape operators of every type against brute force.
TEST(FrameLocalSteps, ConjugacyRandomAgainstBruteForce)
{
  std::mt19937_64 rng(20260101);
  std::uniform_real_distribution<double> U01(0., 1.);
  std::uniform_real_distribution<double> angle(0., 2. * pi);
  const char* names[] = {"elliptic", "hyperbolic", "parabolic (exact zero)", "parabolic (rotated)",
                         "umbilic", "zero", "k1 = -k2", "near umbilic", "near parabolic",
                         "random entries"};
  const int types = 10;
  const int per_type = 600; // 6000 random cases in all
  const double distance_tolerance = 1e-9;
  double worst_gain = -std::numeric_limits<double>::infinity(); // max (ours - brute force)
  double worst_brute_gap = 0.;                                   // max (brute force - ours)
  double worst_residual = 0.;                                    // max |u^T S v| / (|S|_F |y|^2)
  int cases = 0;
  for(int type = 0; type < types; ++type)
    for(int it = 0; it < per_type; ++it)
    {
      const double k = (0.2 + 3. * U01(rng)) * (U01(rng) < 0.5 ? -1. : 1.);
      const double k_other = 0.2 + 3. * U01(rng);
      const double a = angle(rng);
      Matrix2 S;
      switch(type)
      {
        case 0: S = shape_operator(k, (k > 0 ? 1. : -1.) * k_other, a); break;
        case 1: S = shape_operator(k, (k > 0 ? -1. : 1.) * k_other, a); break;
        case 2: S = (U01(rng) < 0.5) ? Matrix2{{k, 0., 0., 0.}} : Matrix2{{0., 0., 0., k}}; break;
        case 3: S = shape_operator(k, 0., a); break;
        case 4: S = {{k, 0., 0., k}}; break;
        case 5: S = {{0., 0., 0., 0.}}; break;
        case 6: { const double p = k * std::cos(a), q = k * std::sin(a); S = {{p, q, q, -p}}; } break;
        case 7: S = shape_operator(k, k * (1. + 1e-9 * U01(rng)), a); break;
        case 8: S = shape_operator(k, k * 1e-8 * (U01(rng) - 0.5), a); break;
        default: { const double b = 2. * U01(rng) - 1.; S = {{2. * U01(rng) - 1., b, b, 2. * U01(rng) - 1.}}; }
      }
      Complex u0 = random_complex(rng), v0 = random_complex(rng);
      if(it % 10 == 1) v0 = u0 * (U01(rng) + 0.5);        // parallel input
      if(it % 10 == 2) v0 = -u0;                           // antiparallel input
      if(it % 10 == 3) u0 = Complex(0., 0.);               // a zero vector
      if(it % 10 >= 7)
      {
        // y0 in the span of a random subset of the eigenvectors of
        // H = 1/2 [[0, S], [S, 0]], i.e. of (d, d) and (d, -d) for the
        // eigenvectors d of S: some components of z vanish, up to round-off,
        // which puts stationary points at or next to poles.
        const double phi = 0.5 * std::atan2(S[1] + S[2], S[0] - S[3]);
        const Complex d1 = std::polar(1., phi), d2 = Complex(0., 1.) * d1;
        const Complex dirs[4] = {d1, d1, d2, d2};
        const double signs[4] = {1., -1., 1., -1.};
        const int mask = 1 + int(U01(rng) * 14.999);
        std::normal_distribution<double> g(0., 1.);
        u0 = v0 = Complex(0., 0.);
        for(int col = 0; col < 4; ++col)
          if(mask & (1 << col))
          {
            const double t = g(rng);
            u0 += t * dirs[col];
            v0 += signs[col] * t * dirs[col];
          }
      }
      const std::pair<Complex, Complex> result = PVFi::project_onto_conjugate_pair(S, u0, v0);
      const std::string what = std::string(names[type]) + " case " + std::to_string(it);
      expect_conjugate(S, result.first, result.second, what);
      worst_residual = (std::max)(worst_residual,
                                  std::abs(PVFi::conjugacy_residual(S, result.first, result.second)) /
                                    (frobenius(S) * squared_norm(result.first, result.second) +
                                     std::numeric_limits<double>::min()));
      // Projecting again leaves the result in place.
      const std::pair<Complex, Complex> again = PVFi::project_onto_conjugate_pair(S, result.first, result.second);
      EXPECT_LE(distance(again.first, again.second, result.first, result.second),
                1e-14 * std::sqrt(squared_norm(u0, v0))) << what << ": not idempotent";
      const double ours = distance(result.first, result.second, u0, v0);
      const double brute = std::sqrt(brute_force(S, u0, v0));
      EXPECT_LE(ours, brute + distance_tolerance) << what << ": brute force found a closer conjugate pair";
      worst_gain = (std::max)(worst_gain, ours - brute);
      worst_brute_gap = (std::max)(worst_brute_gap, brute - ours);
      ++cases;
    }
  std::printf("[conjugacy] %d random cases; max(ours - brute force) = %.3g, max(brute force - ours) = %.3g, "
              "max relative residual = %.3g\n", cases, worst_gain, worst_brute_gap, worst_residual);
}

// Inputs that are already conjugate come back unchanged.
TEST(FrameLocalSteps, ConjugacyAlreadyConjugateUnchanged)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U01(0., 1.);
  for(int it = 0; it < 2000; ++it)
  {
    const Matrix2 S = shape_operator(4. * U01(rng) - 2., 4. * U01(rng) - 2., 2. * pi * U01(rng));
    const Complex u0 = random_complex(rng);
    // v0 along (S u0)^perp
    const Complex Su(S[0] * u0.real() + S[1] * u0.imag(), S[2] * u0.real() + S[3] * u0.imag());
    const Complex v0 = Complex(0., 1.) * Su * (0.5 + U01(rng));
    const std::pair<Complex, Complex> r = PVFi::project_onto_conjugate_pair(S, u0, v0);
    const double scale = std::sqrt(squared_norm(u0, v0));
    EXPECT_LE(distance(r.first, r.second, u0, v0), 1e-15 * scale) << "case " << it;
  }
  // Nearly conjugate: v0 = v + e with (u0, v) conjugate. The pair (u0, v) is
  // feasible at distance |e|, so the projection must be at least as close, and
  // must still be conjugate to the stated tolerance (round-off is not enough
  // to return the input unchanged).
  for(int it = 0; it < 2000; ++it)
  {
    const Matrix2 S = shape_operator(4. * U01(rng) - 2., 4. * U01(rng) - 2., 2. * pi * U01(rng));
    const Complex u0 = random_complex(rng);
    const Complex Su(S[0] * u0.real() + S[1] * u0.imag(), S[2] * u0.real() + S[3] * u0.imag());
    const Complex v = Complex(0., 1.) * Su * (0.5 + U01(rng));
    const double size = (it % 3 == 0) ? 1e-6 : (it % 3 == 1) ? 1e-9 : 1e-11;
    const Complex e = random_complex(rng, size);
    const Complex v0 = v + e;
    const std::pair<Complex, Complex> r = PVFi::project_onto_conjugate_pair(S, u0, v0);
    expect_conjugate(S, r.first, r.second, "nearly conjugate case " + std::to_string(it));
    EXPECT_LE(distance(r.first, r.second, u0, v0), std::abs(e) * (1. + 1e-6) + 1e-15 * std::abs(v0))
      << "nearly conjugate case " << it;
  }
  // Exactly conjugate: principal directions of an axis-aligned S, zero vectors, S = 0: bit-exact.
  const Matrix2 D = {{2., 0., 0., -0.5}};
  const std::vector<std::pair<Complex, Complex> > exact = {
    {Complex(3., 0.), Complex(0., -2.)}, {Complex(0., 1.), Complex(5., 0.)},
    {Complex(0., 0.), Complex(1., 2.)},  {Complex(1., 2.), Complex(0., 0.)}, {Complex(0., 0.), Complex(0., 0.)}};
  for(const auto& p : exact)
  {
    const std::pair<Complex, Complex> r = PVFi::project_onto_conjugate_pair(D, p.first, p.second);
    EXPECT_EQ(r.first, p.first);
    EXPECT_EQ(r.second, p.second);
  }
  const Matrix2 Z = {{0., 0., 0., 0.}};
  const std::pair<Complex, Complex> r = PVFi::project_onto_conjugate_pair(Z, Complex(1., 2.), Complex(3., -4.));
  EXPECT_EQ(r.first, Complex(1., 2.));
  EXPECT_EQ(r.second, Complex(3., -4.));
}

// u0 = v0 = c d1 (an eigenvector of H): every stationary point is at a pole of
// the secular equation, with a free component. The exact optimum is
//   |y - y0|^2 = |y0|^2 min(1/2, |k1| / (|k1| + |k2|)),
// reached either by (c d1, 0) or by u = a d1 + b d2, v = a d1 -+ b d2.
// Small perturbations of y0 test the near-pole roots: the distance to the
// quadric is 1-Lipschitz, so it may move by at most |perturbation|.
TEST(FrameLocalSteps, ConjugacyPoleCases)
{
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> U01(0., 1.);
  int cases = 0;
  for(int it = 0; it < 3000; ++it)
  {
    double k1 = (0.1 + 3. * U01(rng)) * (U01(rng) < 0.5 ? -1. : 1.);
    double k2 = (0.1 + 3. * U01(rng)) * (U01(rng) < 0.5 ? -1. : 1.);
    if(it % 6 == 1) k2 = 0.;       // parabolic, y0 along the curved direction
    if(it % 6 == 2) k2 = k1;       // umbilic
    if(it % 6 == 3) k2 = -k1;      // k1 = -k2
    const double a = (it % 2 == 0) ? 0. : 2. * pi * U01(rng); // axis-aligned half of the time
    const Matrix2 S = shape_operator(k1, k2, a);
    const Complex d1(std::cos(a), std::sin(a));
    const Complex c = 0.3 + 2. * U01(rng);
    const double sign = (it % 4 < 2) ? 1. : -1.; // v0 = +-u0: eigenvector of +-k1/2
    const Complex u0 = c * d1, v0 = sign * c * d1;
    const double y0_norm = std::sqrt(squared_norm(u0, v0));
    const double expected =
      y0_norm * std::sqrt((std::min)(0.5, std::abs(k1) / (std::abs(k1) + std::abs(k2))));

    const std::pair<Complex, Complex> r = PVFi::project_onto_conjugate_pair(S, u0, v0);
    const std::string what = "pole case " + std::to_string(it);
    expect_conjugate(S, r.first, r.second, what);
    EXPECT_NEAR(distance(r.first, r.second, u0, v0), expected, 1e-12 * y0_norm) << what;

    for(double eps : {1e-4, 1e-8, 1e-12, 1e-15})
    {
      const Complex du = random_complex(rng, eps), dv = random_complex(rng, eps);
      const Complex u1 = u0 + du, v1 = v0 + dv;
      const double moved = std::sqrt(squared_norm(du, dv));
      const std::pair<Complex, Complex> q = PVFi::project_onto_conjugate_pair(S, u1, v1);
      const std::string what_eps = what + " perturbed by " + std::to_string(eps);
      expect_conjugate(S, q.first, q.second, what_eps);
      EXPECT_NEAR(distance(q.first, q.second, u1, v1), expected, moved + 1e-12 * y0_norm) << what_eps;
      ++cases;
    }
    ++cases;
  }
  std::printf("[conjugacy] %d pole and near-pole cases\n", cases);
}

// Scaling S and y0 by powers of two scales the result exactly; no overflow or
// underflow for extreme magnitudes.
TEST(FrameLocalSteps, ConjugacyScalingAndExtremeMagnitudes)
{
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U01(0., 1.);
  for(int it = 0; it < 500; ++it)
  {
    const Matrix2 S = shape_operator(4. * U01(rng) - 2., 4. * U01(rng) - 2., 2. * pi * U01(rng));
    const Complex u0 = random_complex(rng), v0 = random_complex(rng);
    const std::pair<Complex, Complex> r = PVFi::project_onto_conjugate_pair(S, u0, v0);
    for(int ps : {-900, -40, 0, 33, 900})
      for(int py : {-1000, -20, 0, 17, 1000})
      {
        const Matrix2 Ss = {{std::ldexp(S[0], ps), std::ldexp(S[1], ps), std::ldexp(S[2], ps), std::ldexp(S[3], ps)}};
        const std::pair<Complex, Complex> q = PVFi::project_onto_conjugate_pair(
          Ss, Complex(std::ldexp(u0.real(), py), std::ldexp(u0.imag(), py)),
          Complex(std::ldexp(v0.real(), py), std::ldexp(v0.imag(), py)));
        ASSERT_TRUE(finite(q.first) && finite(q.second));
        EXPECT_EQ(std::ldexp(q.first.real(), -py), r.first.real());
        EXPECT_EQ(std::ldexp(q.first.imag(), -py), r.first.imag());
        EXPECT_EQ(std::ldexp(q.second.real(), -py), r.second.real());
        EXPECT_EQ(std::ldexp(q.second.imag(), -py), r.second.imag());
      }
  }
  // Hand-picked extreme inputs: finite, and conjugate relative to |S| |y|^2.
  const std::vector<Matrix2> operators = {{{1e300, 0., 0., -1e300}}, {{1e-300, 2e-300, 2e-300, 1e-310}},
                                          {{0., 1., 1., 0.}}, {{1., 0., 0., 1e-300}}, {{5e-324, 0., 0., 0.}}};
  const std::vector<std::pair<Complex, Complex> > pairs = {
    {Complex(1e300, 1e300), Complex(-1e300, 1e299)}, {Complex(1e-300, 0.), Complex(1e-300, 1e-300)},
    {Complex(1., 1.), Complex(1., 1.)}, {Complex(1., 0.), Complex(1., 0.)}};
  for(const Matrix2& S : operators)
    for(const auto& p : pairs)
    {
      const std::pair<Complex, Complex> q = PVFi::project_onto_conjugate_pair(S, p.first, p.second);
      ASSERT_TRUE(finite(q.first) && finite(q.second));
      // The residual is checked on S and y divided by their largest entries, so
      // that the check itself neither overflows nor underflows.
      const double ymax = (std::max)({std::abs(q.first.real()), std::abs(q.first.imag()),
                                      std::abs(q.second.real()), std::abs(q.second.imag())});
      const double smax = (std::max)({std::abs(S[0]), std::abs(S[1]), std::abs(S[3])});
      const Matrix2 Sn = {{S[0] / smax, S[1] / smax, S[2] / smax, S[3] / smax}};
      expect_conjugate(Sn, q.first / ymax, q.second / ymax, "extreme input");
    }
  // Subnormal input: the exact projection is not representable (it underflows),
  // so only finiteness is required.
  for(const Matrix2& S : operators)
  {
    const Complex tiny(std::numeric_limits<double>::denorm_min(), 0.);
    const std::pair<Complex, Complex> q = PVFi::project_onto_conjugate_pair(S, tiny, tiny);
    EXPECT_TRUE(finite(q.first) && finite(q.second));
  }
}

// ---------------------------------------------------------------------------
// Angle bound
// ---------------------------------------------------------------------------

// Reference: the smallest angle between two distinct members of {u, v, -u, -v}
// that are not opposite, by enumeration.
double reference_frame_angle(Complex u, Complex v)
{
  const Complex members[4] = {u, v, -u, -v};
  double smallest = pi;
  for(int i = 0; i < 4; ++i)
    for(int k = i + 1; k < 4; ++k)
    {
      if(k == i + 2)
        continue; // u and -u, v and -v
      smallest = (std::min)(smallest, std::abs(std::arg(members[k] / members[i])));
    }
  return smallest;
}

// Unit bisector of u and w (the angle between them is below pi/2).
Complex bisector(Complex u, Complex w) { const Complex b = u / std::abs(u) + w / std::abs(w); return b / std::abs(b); }

TEST(FrameLocalSteps, SmallestFrameAngleMatchesEnumeration)
{
  std::mt19937_64 rng(11);
  for(int it = 0; it < 100000; ++it)
  {
    const Complex u = random_complex(rng), v = random_complex(rng);
    const double theta = PVFi::smallest_frame_angle(u, v);
    EXPECT_GE(theta, 0.);
    EXPECT_LE(theta, pi / 2.);
    EXPECT_NEAR(theta, reference_frame_angle(u, v), 1e-12);
  }
  EXPECT_DOUBLE_EQ(PVFi::smallest_frame_angle(Complex(1, 0), Complex(0, 3)), pi / 2.);
  EXPECT_DOUBLE_EQ(PVFi::smallest_frame_angle(Complex(1, 0), Complex(-1, 1)), pi / 4.);
  EXPECT_EQ(PVFi::smallest_frame_angle(Complex(2, 1), Complex(4, 2)), 0.);
  EXPECT_EQ(PVFi::smallest_frame_angle(Complex(2, 1), Complex(-2, -1)), 0.);
  // Zero vector: documented convention pi/2.
  EXPECT_DOUBLE_EQ(PVFi::smallest_frame_angle(Complex(0, 0), Complex(1, 1)), pi / 2.);
  EXPECT_DOUBLE_EQ(PVFi::smallest_frame_angle(Complex(1, 1), Complex(0, 0)), pi / 2.);
}

TEST(FrameLocalSteps, AngleBoundRandom)
{
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> U01(0., 1.);
  int changed = 0, unchanged = 0;
  for(int it = 0; it < 100000; ++it)
  {
    Complex u = random_complex(rng) * std::exp(3. * (U01(rng) - 0.5));
    Complex v = random_complex(rng) * std::exp(3. * (U01(rng) - 0.5));
    if(it % 3 == 0) // concentrate on small angles
      v = u * std::polar(0.2 + U01(rng), (U01(rng) - 0.5) * 0.3 + (U01(rng) < 0.5 ? pi : 0.));
    const double theta_min = (it % 50 == 0) ? pi / 2. : (pi / 2.) * (1e-3 + (1. - 1e-3) * U01(rng));
    const double theta = PVFi::smallest_frame_angle(u, v);
    const std::pair<Complex, Complex> r = PVFi::enforce_angle_bound(u, v, theta_min);
    if(theta >= theta_min)
    {
      EXPECT_EQ(r.first, u);
      EXPECT_EQ(r.second, v);
      ++unchanged;
      continue;
    }
    ++changed;
    const double theta_new = PVFi::smallest_frame_angle(r.first, r.second);
    EXPECT_GE(theta_new, theta_min - 1e-12);
    EXPECT_NEAR(theta_new, theta_min, 1e-12);
    EXPECT_NEAR(std::abs(r.first), std::abs(u), 1e-14 * std::abs(u));
    EXPECT_NEAR(std::abs(r.second), std::abs(v), 1e-14 * std::abs(v));
    // The realising pair is (u, w), w = +-v; its bisector does not move.
    const double sign = (std::real(std::conj(u) * v) >= 0.) ? 1. : -1.;
    const Complex b_old = bisector(u, sign * v), b_new = bisector(r.first, sign * r.second);
    EXPECT_LE(std::abs(std::arg(b_new / b_old)), 1e-12);
    // Roles and signs kept: each vector turned by exactly (theta_min - theta) / 2.
    EXPECT_NEAR(std::abs(std::arg(r.first / u)), 0.5 * (theta_min - theta), 1e-12);
    EXPECT_NEAR(std::abs(std::arg(r.second / v)), 0.5 * (theta_min - theta), 1e-12);
    // Symmetric: turned in opposite senses, away from each other.
    EXPECT_LE(std::arg(r.first / u) * std::arg(r.second / v), 0.);
    EXPECT_GT(std::abs(std::arg(r.second * sign / r.first)), std::abs(std::arg(v * sign / u)) - 1e-15);
  }
  EXPECT_GT(changed, 10000);
  EXPECT_GT(unchanged, 10000);
  std::printf("[angle bound] %d frames rotated, %d left unchanged\n", changed, unchanged);
}

TEST(FrameLocalSteps, AngleBoundParallelAntiparallelAndZero)
{
  const double theta_min = 70. * pi / 180.;
  const Complex u(1.5, -0.5);
  for(double c : {2., 0.25, -1., -3.})
  {
    const Complex v = c * u; // exactly parallel (c > 0) or antiparallel (c < 0)
    EXPECT_EQ(PVFi::smallest_frame_angle(u, v), 0.);
    const std::pair<Complex, Complex> r = PVFi::enforce_angle_bound(u, v, theta_min);
    EXPECT_NEAR(PVFi::smallest_frame_angle(r.first, r.second), theta_min, 1e-12);
    EXPECT_NEAR(std::abs(r.first), std::abs(u), 1e-14 * std::abs(u));
    EXPECT_NEAR(std::abs(r.second), std::abs(v), 1e-14 * std::abs(v));
    // Documented choice: bisector along u, u turned clockwise, v (or -v) counterclockwise.
    EXPECT_NEAR(std::arg(r.first / u), -0.5 * theta_min, 1e-14);
    EXPECT_NEAR(std::arg(r.second / v), 0.5 * theta_min, 1e-14);
    const Complex w = (c > 0.) ? r.second : -r.second;
    EXPECT_LE(std::abs(std::arg(bisector(r.first, w) / u)), 1e-14);
  }
  // pi/2: the frame becomes orthogonal.
  {
    const std::pair<Complex, Complex> r = PVFi::enforce_angle_bound(u, 3. * u, pi / 2.);
    EXPECT_LE(std::abs(std::real(std::conj(r.first) * r.second)), 1e-14 * std::abs(u) * 3. * std::abs(u));
  }
  // Zero vectors: unchanged, bit for bit.
  for(const auto& p : std::vector<std::pair<Complex, Complex> >{
        {Complex(0., 0.), Complex(1., 2.)}, {Complex(1., 2.), Complex(0., 0.)}, {Complex(0., 0.), Complex(0., 0.)}})
  {
    const std::pair<Complex, Complex> r = PVFi::enforce_angle_bound(p.first, p.second, theta_min);
    EXPECT_EQ(r.first, p.first);
    EXPECT_EQ(r.second, p.second);
  }
  // Just below the bound: rotated up to it. Just above: unchanged.
  for(double delta : {1e-6, 1e-10, 1e-13})
  {
    const Complex a(0.6, 0.8);
    const Complex below = a * std::polar(2., theta_min - delta);
    ASSERT_LT(PVFi::smallest_frame_angle(a, below), theta_min);
    const std::pair<Complex, Complex> r = PVFi::enforce_angle_bound(a, below, theta_min);
    EXPECT_GE(PVFi::smallest_frame_angle(r.first, r.second), theta_min - 1e-12);
    EXPECT_NEAR(PVFi::smallest_frame_angle(r.first, r.second), theta_min, 1e-12);
    const Complex above = a * std::polar(2., theta_min + delta);
    ASSERT_GE(PVFi::smallest_frame_angle(a, above), theta_min);
    const std::pair<Complex, Complex> q = PVFi::enforce_angle_bound(a, above, theta_min);
    EXPECT_EQ(q.first, a);
    EXPECT_EQ(q.second, above);
  }
}

} // namespace pvf_frame_local_steps_test
