// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Tests of the PolyVector <-> polynomial conversion (polyvector_polynomial.h).
//
// Tolerances. Let eps = 2^-52 and, for a set of roots r_0..r_{N-1},
//   B_i  = prod_j (|r_i| + |r_j|)      (the polynomial prod_j (z + |r_j|) at |r_i|),
//   P'_i = prod_{j != i} (r_i - r_j)   (the derivative of P at r_i).
// Expanding the product (roots -> coefficients) perturbs each coefficient c_m by
// at most about N u c^_m, where c^_m is the coefficient of prod_j (z + |r_j|); a
// backward-stable root finder returns the exact roots of coefficients perturbed
// by a comparable amount. To first order a simple root then moves by at most
//   delta * B_i / |P'_i|   with delta ~ N eps,
// so a simple root is checked against  K N eps B_i / |P'_i| + 4 eps max|r|  with
// K = 4 (measured worst ratio over 16000 random cases: 0.34 of N eps B_i/|P'_i|).
// A root r of multiplicity m (the other roots r_j, j outside the cluster) moves by
// about (delta B / |Q(r)|)^(1/m) with Q(r) = prod_j (r - r_j): the tolerance is
// twice that with delta = K N eps, i.e. ~eps^(1/2) for a double root and
// ~eps^(1/3) for a triple root, relative to the size of the roots.
// Coefficients -> roots -> coefficients is checked coefficientwise against
// 8 N eps c^_m (measured worst: 0.89 N eps c^_m).

#include <CGAL/Polyvector_fields/polyvector_polynomial.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

namespace PVF = CGAL::Polyvector_fields;
typedef std::complex<double> Complex;

namespace {

const double eps = std::numeric_limits<double>::epsilon();
const double two_pi = 6.283185307179586476925286766559;

using pvf_test::random_complex;

std::vector<Complex> random_roots(std::mt19937_64& rng, std::size_t n, double scale)
{
  std::vector<Complex> r(n);
  for(Complex& z : r)
    z = random_complex(rng, scale);
  return r;
}

double max_modulus(const std::vector<Complex>& z)
{
  double m = 0.;
  for(const Complex& x : z)
    m = (std::max)(m, std::abs(x));
  return m;
}

// Argument in [0, 2 pi); 0 for the zero root.
double argument(const Complex& z)
{
  if(z == Complex(0., 0.))
    return 0.;
  double t = std::atan2(z.imag(), z.real());
  if(t < 0.)
    t += two_pi;
  return t;
}

// The ordering contract: every root finite, arguments in [0, 2 pi) and
// non-decreasing. atan2 is accurate to about one ulp, so two exactly ordered
// roots of nearly equal argument may come out of atan2 swapped by ~1e-16: the
// check allows 1e-15 rad.
void expect_counterclockwise(const std::vector<Complex>& roots)
{
  for(const Complex& z : roots)
    ASSERT_TRUE(std::isfinite(z.real()) && std::isfinite(z.imag())) << z;
  for(std::size_t i = 0; i < roots.size(); ++i)
  {
    const double t = argument(roots[i]);
    EXPECT_GE(t, 0.);
    EXPECT_LE(t, two_pi);
    if(i + 1 < roots.size())
    {
      EXPECT_GE(argument(roots[i + 1]), t - 1e-15)
        << "roots " << i << " and " << i + 1 << ": " << roots[i] << " " << roots[i + 1];
    }
  }
}

// Bottleneck matching: the smallest, over all one-to-one matchings of computed
// to expected roots, of max_i |computed(i) - expected_i| / tolerance_i.
// Binary search over the N^2 candidate values, each tested for a perfect
// bipartite matching with Kuhn's augmenting paths: polynomial, whatever the data.
bool augment(std::size_t i, const std::vector<std::vector<double> >& cost, double threshold,
             std::vector<bool>& visited, std::vector<std::size_t>& owner)
{
  const std::size_t none = std::size_t(-1);
  for(std::size_t j = 0; j < cost[i].size(); ++j)
  {
    if(visited[j] || !(cost[i][j] <= threshold))
      continue;
    visited[j] = true;
    if(owner[j] == none || augment(owner[j], cost, threshold, visited, owner))
    {
      owner[j] = i;
      return true;
    }
  }
  return false;
}

bool perfect_matching_exists(const std::vector<std::vector<double> >& cost, double threshold)
{
  const std::size_t n = cost.size();
  std::vector<std::size_t> owner(n, std::size_t(-1));
  for(std::size_t i = 0; i < n; ++i)
  {
    std::vector<bool> visited(n, false);
    if(!augment(i, cost, threshold, visited, owner))
      return false;
  }
  return true;
}

double matching_error(const std::vector<Complex>& expected, const std::vector<Complex>& computed,
                      const std::vector<double>& tolerance)
{
  const std::size_t n = expected.size();
  if(computed.size() != n || tolerance.size() != n)
    return std::numeric_limits<double>::infinity();
  std::vector<std::vector<double> > cost(n, std::vector<double>(n));
  std::vector<double> values;
  for(std::size_t i = 0; i < n; ++i)
  {
    for(std::size_t j = 0; j < n; ++j)
    {
      const double e = std::abs(computed[j] - expected[i]) / tolerance[i];
      cost[i][j] = std::isnan(e) ? std::numeric_limits<double>::infinity() : e;
      values.push_back(cost[i][j]);
    }
  }
  std::sort(values.begin(), values.end());
  if(n == 0)
    return 0.;
  if(!perfect_matching_exists(cost, values.back()))
    return std::numeric_limits<double>::infinity();
  std::size_t lo = 0, hi = values.size() - 1; // the answer is values[k] for the smallest feasible k
  while(lo < hi)
  {
    const std::size_t mid = (lo + hi) / 2;
    if(perfect_matching_exists(cost, values[mid]))
      hi = mid;
    else
      lo = mid + 1;
  }
  return values[lo];
}

// Tolerance of each simple root (see the comment at the top of the file).
std::vector<double> simple_root_tolerances(const std::vector<Complex>& r, double K = 4.)
{
  const std::size_t N = r.size();
  const double R = max_modulus(r);
  std::vector<double> tol(N);
  for(std::size_t i = 0; i < N; ++i)
  {
    double B = 1., D = 1.;
    for(std::size_t j = 0; j < N; ++j)
    {
      B *= std::abs(r[i]) + std::abs(r[j]);
      if(j != i)
        D *= std::abs(r[i] - r[j]);
    }
    if(r[i] == Complex(0., 0.))
      tol[i] = 4. * eps * R + 1e-300; // zero roots come out exactly zero (tested separately)
    else if(D == 0.)
      tol[i] = std::numeric_limits<double>::infinity(); // repeated: the caller sets a cluster tolerance
    else
      tol[i] = K * double(N) * eps * B / D + 4. * eps * R;
  }
  return tol;
}

// max_i (B_i / |P'_i|) / max|r|: the relative condition number of the root set.
double relative_condition(const std::vector<Complex>& r)
{
  const std::size_t N = r.size();
  double kappa = 0.;
  for(std::size_t i = 0; i < N; ++i)
  {
    double B = 1., D = 1.;
    for(std::size_t j = 0; j < N; ++j)
    {
      B *= std::abs(r[i]) + std::abs(r[j]);
      if(j != i)
        D *= std::abs(r[i] - r[j]);
    }
    kappa = (std::max)(kappa, B / D);
  }
  return kappa / max_modulus(r);
}

// Coefficients of prod_j (z + |r_j|), nonnegative: the scale of rounding errors
// in the coefficients of prod_j (z - r_j).
std::vector<double> absolute_coefficients(const std::vector<Complex>& r)
{
  std::vector<Complex> minus_abs(r.size());
  for(std::size_t i = 0; i < r.size(); ++i)
    minus_abs[i] = -std::abs(r[i]);
  const std::vector<Complex> c = PVF::polyvector_coefficients(minus_abs);
  std::vector<double> a(c.size());
  for(std::size_t i = 0; i < c.size(); ++i)
    a[i] = c[i].real();
  return a;
}

// Tolerance for the roots of a cluster {r, r, ..., r} (multiplicity m) among `roots`.
double cluster_tolerance(const std::vector<Complex>& roots, const Complex& r, int m, double K = 4.)
{
  double B = 1., Q = 1.;
  for(const Complex& x : roots)
  {
    B *= std::abs(r) + std::abs(x);
    if(x != r)
      Q *= std::abs(r - x);
  }
  const double R = max_modulus(roots);
  return 2. * std::pow(K * double(roots.size()) * eps * B / Q, 1. / double(m)) + 4. * eps * R;
}

std::vector<Complex> roots_of(const std::vector<Complex>& c, bool sign_symmetric = false)
{
  return PVF::polyvector_roots(c, sign_symmetric);
}

std::vector<Complex> companion_path(const std::vector<Complex>& c, bool sign_symmetric)
{
  std::vector<Complex> r(c.size());
  PVF::internal::companion_roots(c.data(), c.size(), r.data(), sign_symmetric);
  return r;
}

} // namespace

// ---------------------------------------------------------------------------
// Coefficients
// ---------------------------------------------------------------------------

TEST(CorePolynomial, CoefficientsOfSmallProductsAreExact)
{
  // (z - 2)(z - 3) = z^2 - 5 z + 6, (z - i)(z + i) = z^2 + 1: small integers are exact
  const std::vector<Complex> c = PVF::polyvector_coefficients({Complex(2, 0), Complex(3, 0)});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0], Complex(6, 0));
  EXPECT_EQ(c[1], Complex(-5, 0));
  const std::vector<Complex> d = PVF::polyvector_coefficients({Complex(0, 1), Complex(0, -1)});
  EXPECT_EQ(d[0], Complex(1, 0));
  EXPECT_EQ(d[1], Complex(0, 0));
  const std::vector<Complex> one = PVF::polyvector_coefficients({Complex(1.5, -2)});
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], Complex(-1.5, 2));
  EXPECT_TRUE(PVF::polyvector_coefficients({}).empty());
}

TEST(CorePolynomial, PaperFigure3Example)
{
  // Two independent vectors u1, u2 and a 2-RoSy {u3, -u3}:
  // P(z) = (z - u1)(z - u2)(z^2 - u3^2). The paper lists the coefficients from
  // degree 3 down to degree 0: (-u1-u2, u1u2-u3^2, (u1+u2)u3^2, -u1u2u3^2),
  // so c_3 = -u1-u2, ..., c_0 = -u1u2u3^2 in our convention (c_m multiplies z^m).
  const Complex u1(1., 2.), u2(-0.5, 0.3), u3(0.7, -1.1);
  const std::vector<Complex> roots = {u1, u2, u3, -u3};
  const std::vector<Complex> c = PVF::polyvector_coefficients(roots);
  ASSERT_EQ(c.size(), 4u);
  const Complex u3s = u3 * u3;
  const std::vector<Complex> paper_high_to_low = {-u1 - u2, u1 * u2 - u3s, (u1 + u2) * u3s, -u1 * u2 * u3s};
  const std::vector<double> scale = absolute_coefficients(roots);
  for(std::size_t m = 0; m < 4; ++m)
    EXPECT_LE(std::abs(c[m] - paper_high_to_low[3 - m]), 8. * 4. * eps * scale[m]) << "c_" << m;
  // c_3 is minus the sum of the roots, c_0 their product (N even)
  EXPECT_LE(std::abs(c[3] + (u1 + u2)), 8. * eps * scale[3]);

  const std::vector<Complex> r = roots_of(c);
  expect_counterclockwise(r);
  EXPECT_LE(matching_error(roots, r, simple_root_tolerances(roots)), 1.);
}

TEST(CorePolynomial, SignSymmetricCoefficients)
{
  std::mt19937_64 rng(7);
  for(std::size_t K = 1; K <= 4; ++K)
  {
    for(int t = 0; t < 50; ++t)
    {
      const std::vector<Complex> u = random_roots(rng, K, 1.);
      const std::vector<Complex> c = PVF::sign_symmetric_polyvector_coefficients(u);
      ASSERT_EQ(c.size(), 2 * K);
      std::vector<Complex> all;
      for(const Complex& x : u)
      {
        all.push_back(x);
        all.push_back(-x);
      }
      const std::vector<Complex> reference = PVF::polyvector_coefficients(all);
      const std::vector<double> scale = absolute_coefficients(all);
      for(std::size_t m = 0; m < 2 * K; ++m)
      {
        if(m % 2 == 1)
        {
          EXPECT_EQ(c[m].real(), 0.);
          EXPECT_EQ(c[m].imag(), 0.);
        }
        EXPECT_LE(std::abs(c[m] - reference[m]), 8. * double(2 * K) * eps * scale[m]);
      }
    }
  }
  // frame field: c_2 = -(u^2 + v^2), c_0 = u^2 v^2 (NOTES.md, Section 3)
  const Complex u(1., 0.5), v(-0.25, 2.);
  const std::vector<Complex> c = PVF::sign_symmetric_polyvector_coefficients({u, v});
  EXPECT_LE(std::abs(c[2] + (u * u + v * v)), 4. * eps * 8.);
  EXPECT_LE(std::abs(c[0] - u * u * v * v), 4. * eps * 16.);
  EXPECT_TRUE(PVF::sign_symmetric_polyvector_coefficients({}).empty());
}

// ---------------------------------------------------------------------------
// Round trips
// ---------------------------------------------------------------------------

TEST(CorePolynomial, RootsToCoefficientsToRoots)
{
  std::mt19937_64 rng(20140601);
  std::uniform_real_distribution<double> log_scale(-3., 3.);
  int checked = 0;
  double worst = 0.;
  for(std::size_t N = 1; N <= 8; ++N)
  {
    for(int t = 0; t < 100; ++t)
    {
      const double scale = std::pow(10., log_scale(rng));
      const std::vector<Complex> roots = random_roots(rng, N, scale);
      const std::vector<Complex> c = PVF::polyvector_coefficients(roots);
      const std::vector<Complex> r = roots_of(c);
      ASSERT_EQ(r.size(), N);
      expect_counterclockwise(r);
      const double e = matching_error(roots, r, simple_root_tolerances(roots));
      worst = (std::max)(worst, e);
      EXPECT_LE(e, 1.) << "N = " << N << ", case " << t;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 800);
  std::cout << "roots -> coefficients -> roots: worst error / tolerance = " << worst << std::endl;
}

TEST(CorePolynomial, WellConditionedRootsToNineDigits)
{
  // The fixed relative tolerance 1e-9 max|r| follows from the tolerance above
  // for sets whose relative condition max_i B_i / |P'_i| / max|r| is at most 1e5:
  // 4 N eps 1e5 max|r| < 7.2e-10 max|r| for N <= 8. Most random sets qualify.
  std::mt19937_64 rng(99);
  int checked = 0, total = 0;
  for(std::size_t N = 1; N <= 8; ++N)
  {
    for(int t = 0; t < 100; ++t, ++total)
    {
      const std::vector<Complex> roots = random_roots(rng, N, 1.);
      if(relative_condition(roots) > 1e5)
        continue;
      const std::vector<Complex> r = roots_of(PVF::polyvector_coefficients(roots));
      const std::vector<double> tol(N, 1e-9 * max_modulus(roots));
      EXPECT_LE(matching_error(roots, r, tol), 1.) << "N = " << N;
      ++checked;
    }
  }
  EXPECT_GE(checked, total * 9 / 10);
}

TEST(CorePolynomial, CoefficientsToRootsToCoefficients)
{
  std::mt19937_64 rng(31415);
  std::uniform_real_distribution<double> log_scale(-3., 3.);
  double worst = 0.;
  for(std::size_t N = 1; N <= 8; ++N)
  {
    for(int t = 0; t < 100; ++t)
    {
      const double scale = std::pow(10., log_scale(rng));
      const std::vector<Complex> c = random_roots(rng, N, scale); // random coefficients
      const std::vector<Complex> r = roots_of(c);
      expect_counterclockwise(r);
      const std::vector<Complex> back = PVF::polyvector_coefficients(r);
      const std::vector<double> hat = absolute_coefficients(r);
      for(std::size_t m = 0; m < N; ++m)
      {
        const double ratio = std::abs(back[m] - c[m]) / (double(N) * eps * hat[m]);
        worst = (std::max)(worst, ratio);
        EXPECT_LE(ratio, 8.) << "N = " << N << ", m = " << m;
      }
    }
  }
  std::cout << "coefficients -> roots -> coefficients: worst error / (N eps c^_m) = " << worst << std::endl;
}

TEST(CorePolynomial, HeapPathForLargeDegree)
{
  // N > 16 leaves the stack buffers
  std::mt19937_64 rng(5);
  for(std::size_t N : {17u, 20u, 24u})
  {
    for(int t = 0; t < 5; ++t)
    {
      // roots near the circle |z| = 1, well separated: a moderately conditioned set
      std::vector<Complex> roots(N);
      std::uniform_real_distribution<double> jitter(-0.2, 0.2);
      for(std::size_t i = 0; i < N; ++i)
        roots[i] = std::polar(1. + 0.5 * jitter(rng), two_pi * (double(i) + jitter(rng)) / double(N));
      const std::vector<Complex> r = roots_of(PVF::polyvector_coefficients(roots));
      expect_counterclockwise(r);
      EXPECT_LE(matching_error(roots, r, simple_root_tolerances(roots)), 1.) << "N = " << N;
    }
  }
  // z^20 - 1: the 20th roots of unity, in counterclockwise order starting at 1
  std::vector<Complex> c(20, Complex(0., 0.));
  c[0] = Complex(-1., 0.);
  const std::vector<Complex> r = roots_of(c);
  ASSERT_EQ(r.size(), 20u);
  for(std::size_t k = 0; k < 20; ++k)
    EXPECT_LE(std::abs(r[k] - std::polar(1., two_pi * double(k) / 20.)), 1e-14) << k;
}

// ---------------------------------------------------------------------------
// Zero and repeated roots
// ---------------------------------------------------------------------------

TEST(CorePolynomial, RepeatedRoots)
{
  std::mt19937_64 rng(2718);
  for(int multiplicity : {2, 3})
  {
    for(std::size_t N = std::size_t(multiplicity); N <= 8; ++N)
    {
      for(int t = 0; t < 20; ++t)
      {
        const Complex r0 = random_complex(rng);
        std::vector<Complex> roots(std::size_t(multiplicity), r0);
        for(std::size_t i = roots.size(); i < N; ++i)
          roots.push_back(r0 + std::polar(0.5 + 0.5 * std::abs(random_complex(rng)),
                                          two_pi * double(i) / double(N)));
        const std::vector<Complex> r = roots_of(PVF::polyvector_coefficients(roots));
        expect_counterclockwise(r);
        // every root within its tolerance: the cluster's (~eps^(1/m)) or a simple root's
        std::vector<double> tol = simple_root_tolerances(roots);
        const double cluster = cluster_tolerance(roots, r0, multiplicity);
        for(std::size_t i = 0; i < std::size_t(multiplicity); ++i)
          tol[i] = cluster;
        // state the size of the cluster tolerance: about eps^(1/m) = 1.5e-8 or 6e-6,
        // times (4 N B / |Q|)^(1/m)
        EXPECT_LE(cluster, (multiplicity == 2 ? 1e-4 : 1e-3) * max_modulus(roots));
        EXPECT_LE(matching_error(roots, r, tol), 1.) << "m = " << multiplicity << ", N = " << N;
      }
    }
  }
}

TEST(CorePolynomial, AllRootsEqual)
{
  for(std::size_t N = 1; N <= 8; ++N)
  {
    const Complex r0(0.6, -0.8);
    const std::vector<Complex> roots(N, r0);
    const std::vector<Complex> r = roots_of(PVF::polyvector_coefficients(roots));
    expect_counterclockwise(r);
    // all N roots within 2 (4 N eps 2^N)^(1/N) of r0 (|r0| = 1, B = 2^N, Q = 1)
    const double tol = cluster_tolerance(roots, r0, int(N));
    for(const Complex& z : r)
      EXPECT_LE(std::abs(z - r0), tol) << "N = " << N;
  }
}

TEST(CorePolynomial, ZeroRoots)
{
  std::mt19937_64 rng(1618);
  for(std::size_t N = 1; N <= 8; ++N)
  {
    for(std::size_t zeros = 1; zeros <= N; ++zeros)
    {
      std::vector<Complex> roots(zeros, Complex(0., 0.));
      while(roots.size() < N)
        roots.push_back(random_complex(rng));
      const std::vector<Complex> c = PVF::polyvector_coefficients(roots);
      for(std::size_t m = 0; m < zeros; ++m)
        EXPECT_EQ(c[m], Complex(0., 0.)); // exact: multiplying by z
      for(bool via_pointer : {false, true})
      {
        std::vector<Complex> r(N);
        if(via_pointer)
          PVF::polyvector_roots(c.data(), N, r.data());
        else
          r = roots_of(c);
        expect_counterclockwise(r);
        // exactly `zeros` roots are exactly zero, and they come first (argument 0)
        std::size_t exact_zeros = 0;
        for(const Complex& z : r)
          exact_zeros += (z == Complex(0., 0.));
        EXPECT_EQ(exact_zeros, zeros) << "N = " << N;
        for(std::size_t i = 0; i < zeros; ++i)
          EXPECT_EQ(r[i], Complex(0., 0.));
        EXPECT_LE(matching_error(roots, r, simple_root_tolerances(roots)), 1.) << "N = " << N;
      }
    }
  }
}

TEST(CorePolynomial, ZeroAndRepeatedTogether)
{
  // a triple zero root and a double root elsewhere
  const Complex a(-0.3, 0.9), b(1.2, 0.1);
  const std::vector<Complex> roots = {0., 0., 0., a, a, b};
  const std::vector<Complex> r = roots_of(PVF::polyvector_coefficients(roots));
  expect_counterclockwise(r);
  EXPECT_EQ(r[0], Complex(0., 0.));
  EXPECT_EQ(r[1], Complex(0., 0.));
  EXPECT_EQ(r[2], Complex(0., 0.));
  std::vector<double> tol = simple_root_tolerances(roots);
  tol[3] = tol[4] = cluster_tolerance(roots, a, 2);
  tol[0] = tol[1] = tol[2] = 0.;
  std::vector<Complex> nonzero_expected = {a, a, b}, nonzero_computed = {r[3], r[4], r[5]};
  EXPECT_LE(matching_error(nonzero_expected, nonzero_computed, {tol[3], tol[4], tol[5]}), 1.);
}

TEST(CorePolynomial, AllZero)
{
  for(std::size_t N = 1; N <= 20; ++N)
  {
    for(bool sign_symmetric : {false, true})
    {
      if(sign_symmetric && N % 2 == 1)
        continue;
      const std::vector<Complex> c(N, Complex(0., 0.));
      const std::vector<Complex> r = roots_of(c, sign_symmetric);
      ASSERT_EQ(r.size(), N);
      for(const Complex& z : r)
        EXPECT_EQ(z, Complex(0., 0.)) << "N = " << N;
    }
  }
}

TEST(CorePolynomial, ExtremeScales)
{
  // relative accuracy does not depend on the scale; no overflow in intermediate steps
  std::mt19937_64 rng(123);
  const std::vector<std::pair<std::size_t, double> > cases = {
    {1, 1e300}, {2, 1e150}, {2, 1e-150}, {3, 1e100}, {3, 1e-100}, {5, 1e60}, {5, 1e-60}, {8, 1e35}, {8, 1e-35}};
  for(const auto& nc : cases)
  {
    for(int t = 0; t < 10; ++t)
    {
      const std::vector<Complex> roots = random_roots(rng, nc.first, nc.second);
      const std::vector<Complex> r = roots_of(PVF::polyvector_coefficients(roots));
      expect_counterclockwise(r);
      EXPECT_LE(matching_error(roots, r, simple_root_tolerances(roots)), 1.)
        << "N = " << nc.first << ", scale " << nc.second;
    }
  }
  for(double scale : {1e75, 1e-75, 1e150, 1e-150})
  {
    for(int t = 0; t < 10; ++t)
    {
      // sign-symmetric N = 4 (closed form) and N = 2
      const std::vector<Complex> u = random_roots(rng, scale < 1e100 && scale > 1e-100 ? 2 : 1, scale);
      std::vector<Complex> all;
      for(const Complex& x : u)
      {
        all.push_back(x);
        all.push_back(-x);
      }
      const std::vector<Complex> r = roots_of(PVF::sign_symmetric_polyvector_coefficients(u), true);
      expect_counterclockwise(r);
      EXPECT_LE(matching_error(all, r, simple_root_tolerances(all)), 1.) << "scale " << scale;
    }
  }
}

TEST(CorePolynomial, NonFiniteCoefficientsGiveNaN)
{
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for(std::size_t N : {1u, 2u, 3u, 4u, 6u, 17u})
  {
    for(bool sign_symmetric : {false, true})
    {
      if(sign_symmetric && N % 2 == 1)
        continue;
      for(double bad : {inf, -inf, nan})
      {
        std::vector<Complex> c(N, Complex(0.5, -0.25));
        c[0] = Complex(1., bad);
        const std::vector<Complex> r = roots_of(c, sign_symmetric);
        ASSERT_EQ(r.size(), N);
        for(const Complex& z : r)
          EXPECT_TRUE(std::isnan(z.real()) && std::isnan(z.imag()));
      }
    }
  }
  // an ignored odd coefficient of a sign-symmetric set does not matter
  std::vector<Complex> c = {Complex(-1., 0.), Complex(nan, nan), Complex(0., 0.), Complex(inf, 0.)};
  const std::vector<Complex> r = roots_of(c, true); // z^4 - 1
  const std::vector<Complex> expected = {Complex(1, 0), Complex(0, 1), Complex(-1, 0), Complex(0, -1)};
  for(std::size_t k = 0; k < 4; ++k)
    EXPECT_LE(std::abs(r[k] - expected[k]), 4. * eps) << k;
}

// ---------------------------------------------------------------------------
// Sign-symmetric sets
// ---------------------------------------------------------------------------

TEST(CorePolynomial, SignSymmetricRootsComeInExactPairs)
{
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> log_scale(-2., 2.);
  for(std::size_t K = 1; K <= 6; ++K)
  {
    for(int t = 0; t < 50; ++t)
    {
      const std::vector<Complex> u = random_roots(rng, K, std::pow(10., log_scale(rng)));
      const std::vector<Complex> c = PVF::sign_symmetric_polyvector_coefficients(u);
      const std::vector<Complex> r = roots_of(c, true);
      ASSERT_EQ(r.size(), 2 * K);
      expect_counterclockwise(r);
      for(std::size_t i = 0; i < K; ++i)
      {
        EXPECT_EQ(r[i + K].real(), -r[i].real());
        EXPECT_EQ(r[i + K].imag(), -r[i].imag());
      }
      std::vector<Complex> all;
      for(const Complex& x : u)
      {
        all.push_back(x);
        all.push_back(-x);
      }
      EXPECT_LE(matching_error(all, r, simple_root_tolerances(all)), 1.) << "K = " << K;
    }
  }
}

TEST(CorePolynomial, SignSymmetricDegenerateFrames)
{
  const Complex u(0.8, 0.6);
  // u = v (double w root), u = -v (the same set), u = i v (w = +-u^2, not degenerate),
  // v = 0, u = v = 0
  const std::vector<std::vector<Complex> > cases = {
    {u, u}, {u, -u}, {u, Complex(0, 1) * u}, {u, Complex(0., 0.)}, {Complex(0., 0.), Complex(0., 0.)}};
  for(const std::vector<Complex>& uv : cases)
  {
    const std::vector<Complex> c = PVF::sign_symmetric_polyvector_coefficients(uv);
    for(bool closed_form : {true, false})
    {
      const std::vector<Complex> r = closed_form ? roots_of(c, true) : companion_path(c, true);
      expect_counterclockwise(r);
      // exact pairs after the zero roots: roots[z + i + k] == -roots[z + i]
      const std::size_t zeros = std::size_t(std::count(r.begin(), r.end(), Complex(0., 0.)));
      ASSERT_EQ(zeros % 2, 0u);
      const std::size_t pairs = (4 - zeros) / 2;
      for(std::size_t i = 0; i < pairs; ++i)
        EXPECT_EQ(r[zeros + i + pairs], -r[zeros + i]);
      std::vector<Complex> all = {uv[0], -uv[0], uv[1], -uv[1]};
      std::vector<double> tol = simple_root_tolerances(all);
      if(uv[0] == uv[1] || uv[0] == -uv[1])
        tol.assign(4, cluster_tolerance(all, uv[0], 2));
      if(uv[1] == Complex(0., 0.))
      {
        // zero w root: the two zero roots are exact and first; a tolerance of
        // 1e-300 only accepts an exact zero
        EXPECT_EQ(r[0], Complex(0., 0.));
        EXPECT_EQ(r[1], Complex(0., 0.));
        tol[2] = tol[3] = 1e-300;
        if(uv[0] == Complex(0., 0.))
          tol.assign(4, 1e-300);
      }
      EXPECT_LE(matching_error(all, r, tol), 1.) << uv[0] << " " << uv[1];
    }
  }
}

TEST(CorePolynomial, ClosedFormsAgreeWithCompanionPath)
{
  std::mt19937_64 rng(8128);
  for(int t = 0; t < 300; ++t)
  {
    // general N = 2
    {
      const std::vector<Complex> c = random_roots(rng, 2, 1.);
      const std::vector<Complex> closed = roots_of(c);
      const std::vector<Complex> companion = companion_path(c, false);
      expect_counterclockwise(closed);
      expect_counterclockwise(companion);
      const std::vector<double> tol(2, 1e-12 * max_modulus(closed));
      EXPECT_LE(matching_error(companion, closed, tol), 1.) << c[0] << " " << c[1];
    }
    // sign-symmetric N = 2 and N = 4: random coefficients (only even ones matter),
    // odd ones set to garbage to check they are ignored
    for(std::size_t N : {2u, 4u})
    {
      std::vector<Complex> c = random_roots(rng, N, 1.);
      const std::vector<Complex> closed = roots_of(c, true);
      const std::vector<Complex> companion = companion_path(c, true);
      expect_counterclockwise(closed);
      expect_counterclockwise(companion);
      const std::vector<double> tol(N, 1e-12 * max_modulus(closed));
      EXPECT_LE(matching_error(companion, closed, tol), 1.) << "N = " << N;
      // and against the general (non-sign-symmetric) companion path on the even part
      for(std::size_t m = 1; m < N; m += 2)
        c[m] = Complex(0., 0.);
      const std::vector<Complex> general = companion_path(c, false);
      EXPECT_LE(matching_error(general, closed, std::vector<double>(N, 1e-10 * max_modulus(closed))), 1.);
    }
  }
}

TEST(CorePolynomial, FrameFieldFastPathAgreesWithGenericSteps)
{
  // the branch-free fast path of the sign-symmetric N = 4 closed form against the
  // generic steps (stable quadratic, principal square roots) it replaces: the same
  // roots to 1e-13 relative, both in counterclockwise order, exact pairs
  std::mt19937_64 rng(6174);
  std::uniform_real_distribution<double> log_scale(-20., 20.);
  for(int t = 0; t < 2000; ++t)
  {
    const double scale = std::pow(10., log_scale(rng));
    Complex c0 = random_complex(rng, scale * scale), c2 = random_complex(rng, scale);
    if(t % 10 == 0)
      c2 = Complex(0., 0.); // orthogonal frames of equal lengths (4-RoSy)
    if(t % 10 == 1)
      c2 = Complex(c2.real(), 0.);
    if(t % 10 == 2)
      c0 = Complex(0., c0.imag());
    std::vector<Complex> fast(4), generic(4);
    PVF::internal::sign_symmetric_quartic_roots(c0, c2, fast.data());
    PVF::internal::sign_symmetric_quartic_roots_generic(c0, c2, generic.data());
    expect_counterclockwise(fast);
    expect_counterclockwise(generic);
    EXPECT_EQ(fast[2], -fast[0]);
    EXPECT_EQ(fast[3], -fast[1]);
    EXPECT_LE(matching_error(generic, fast, std::vector<double>(4, 1e-13 * max_modulus(generic))), 1.)
      << "c0 = " << c0 << ", c2 = " << c2;
  }
}

TEST(CorePolynomial, PointerAndVectorFormsAgree)
{
  std::mt19937_64 rng(77);
  for(std::size_t N = 1; N <= 10; ++N)
  {
    for(bool sign_symmetric : {false, true})
    {
      if(sign_symmetric && N % 2 == 1)
        continue;
      const std::vector<Complex> c = random_roots(rng, N, 1.);
      const std::vector<Complex> a = roots_of(c, sign_symmetric);
      std::vector<Complex> b(N, Complex(7., 7.));
      PVF::polyvector_roots(c.data(), N, b.data(), sign_symmetric);
      for(std::size_t i = 0; i < N; ++i)
        EXPECT_EQ(a[i], b[i]);
    }
  }
}

// ---------------------------------------------------------------------------
// Ordering
// ---------------------------------------------------------------------------

TEST(CorePolynomial, OrderStartsAtArgumentZero)
{
  // z^4 - 1 and z^4 + 1 as general and as sign-symmetric sets, and z^3 - 1
  const std::vector<Complex> c4 = {Complex(-1, 0), 0., 0., 0.};
  for(bool sign_symmetric : {false, true})
  {
    const std::vector<Complex> r = roots_of(c4, sign_symmetric);
    for(std::size_t k = 0; k < 4; ++k)
      EXPECT_LE(std::abs(r[k] - std::polar(1., two_pi * double(k) / 4.)), 4. * eps) << k;
    const std::vector<Complex> s = roots_of({Complex(1, 0), 0., 0., 0.}, sign_symmetric);
    for(std::size_t k = 0; k < 4; ++k)
      EXPECT_LE(std::abs(s[k] - std::polar(1., two_pi * (double(k) + 0.5) / 4.)), 4. * eps) << k;
  }
  const std::vector<Complex> r3 = roots_of({Complex(-1, 0), 0., 0.});
  for(std::size_t k = 0; k < 3; ++k)
    EXPECT_LE(std::abs(r3[k] - std::polar(1., two_pi * double(k) / 3.)), 16. * eps) << k;
}

TEST(CorePolynomial, OrientationPredicateIsExact)
{
  // b differs from a direction by one ulp in one component, after scaling by a
  // power of two: the sign of ax*by - ay*bx is known exactly, while the naive
  // formula rounds it away.
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  int decided_by_exact_path = 0;
  for(int t = 0; t < 2000; ++t)
  {
    const double x = uniform(rng), y = uniform(rng);
    if(x == 0. || y == 0.)
      continue;
    const int e = int(t % 41) - 20;
    const double up = std::nextafter(y, 2.);
    const double right = std::nextafter(x, 2.);
    const Complex a(x, y);
    // (x, y+) : det = x (y+ - y), sign of x
    const Complex b1 = std::ldexp(1., e) * Complex(x, up);
    EXPECT_EQ(PVF::internal::orientation_sign(a, b1), x > 0. ? 1 : -1);
    EXPECT_EQ(PVF::internal::orientation_sign(b1, a), x > 0. ? -1 : 1);
    // (x+, y) : det = -y (x+ - x), sign of -y
    const Complex b2 = std::ldexp(1., e) * Complex(right, y);
    EXPECT_EQ(PVF::internal::orientation_sign(a, b2), y > 0. ? -1 : 1);
    // parallel: det = 0
    EXPECT_EQ(PVF::internal::orientation_sign(a, std::ldexp(1., e) * a), 0);
    const double p = x * (std::ldexp(1., e) * up), q = y * (std::ldexp(1., e) * x);
    decided_by_exact_path += (std::abs(p - q) <= 0x1p-51 * (std::abs(p) + std::abs(q)));
  }
  EXPECT_GT(decided_by_exact_path, 1000); // the test does reach the exact path
}

TEST(CorePolynomial, SortNearTheCut)
{
  // arguments: 0 (zero), 0 (positive real), tiny positive, pi/2, pi (both signs
  // of zero imaginary part), 3pi/2, just below 2 pi
  const double tiny = 1e-300;
  const std::vector<Complex> sorted = {Complex(0., 0.), Complex(2., 0.), Complex(1., tiny), Complex(0., 1.),
                                       Complex(-1., 0.), Complex(0., -3.), Complex(1., -tiny)};
  std::vector<Complex> z = {sorted[6], sorted[3], sorted[1], sorted[5], sorted[0], sorted[2], sorted[4]};
  PVF::internal::sort_ccw(z.data(), z.size());
  for(std::size_t i = 0; i < z.size(); ++i)
    EXPECT_EQ(z[i], sorted[i]) << i;
  // (-1, -0) has argument pi as well
  EXPECT_FALSE(PVF::internal::ccw_less(Complex(-1., -0.), Complex(-1., 0.)));
  EXPECT_FALSE(PVF::internal::ccw_less(Complex(-1., 0.), Complex(-1., -0.)));
  EXPECT_TRUE(PVF::internal::ccw_less(Complex(0., 1.), Complex(-1., -0.)));
  EXPECT_TRUE(PVF::internal::ccw_less(Complex(-1., -0.), Complex(-1., -tiny)));
}

// ---------------------------------------------------------------------------
// Internals: stable quadratic and the Aberth fallback
// ---------------------------------------------------------------------------

TEST(CorePolynomial, StableQuadraticAvoidsCancellation)
{
  // z^2 - 2 b z + c with b = 1e8, c = 1: roots 2e8 - 5e-9 and 5e-9 (1 / 2e8):
  // the naive formula loses the small root entirely.
  Complex r1, r2;
  PVF::internal::stable_quadratic_roots(Complex(-2e8, 0.), Complex(1., 0.), r1, r2);
  EXPECT_LE(std::abs(r1 - 2e8) / 2e8, 4. * eps);
  EXPECT_LE(std::abs(r2 - 5e-9) / 5e-9, 4. * eps);
  // zero constant coefficient: an exact zero root
  PVF::internal::stable_quadratic_roots(Complex(3., -1.), Complex(0., 0.), r1, r2);
  EXPECT_EQ(r1, Complex(-3., 1.));
  EXPECT_EQ(r2, Complex(0., 0.));
  // zero discriminant: (z - (1+i))^2 = z^2 - 2(1+i) z + 2i
  PVF::internal::stable_quadratic_roots(Complex(-2., -2.), Complex(0., 2.), r1, r2);
  EXPECT_EQ(r1, Complex(1., 1.));
  EXPECT_EQ(r2, Complex(1., 1.));
  // tiny and huge coefficients (outside the fast range): scaled by powers of two
  // (z - 2^-530)(z - 3 2^-531) = z^2 - 5 2^-531 z + 3 2^-1061 (a subnormal, exactly representable)
  PVF::internal::stable_quadratic_roots(Complex(-5. * std::ldexp(1., -531), 0.),
                                        Complex(3. * std::ldexp(1., -1061), 0.), r1, r2);
  EXPECT_LE(std::abs(r1 - 3. * std::ldexp(1., -531)), 4. * eps * 3. * std::ldexp(1., -531));
  EXPECT_LE(std::abs(r2 - std::ldexp(1., -530)), 4. * eps * std::ldexp(1., -530));
  PVF::internal::stable_quadratic_roots(Complex(-3e300, 0.), Complex(2e300, 0.), r1, r2); // roots 3e300 - 2/3 and 2/3
  EXPECT_LE(std::abs(r1 - 3e300) / 3e300, 4. * eps);
  EXPECT_LE(std::abs(r2 - 2. / 3.), 4. * eps);
}

TEST(CorePolynomial, AberthFallbackFindsTheRoots)
{
  // the fallback runs when the eigensolver does not converge; check it on its own
  std::mt19937_64 rng(11);
  for(std::size_t N = 1; N <= 8; ++N)
  {
    for(int t = 0; t < 20; ++t)
    {
      const std::vector<Complex> roots = random_roots(rng, N, 1.);
      const std::vector<Complex> c = PVF::polyvector_coefficients(roots);
      std::vector<Complex> r(N);
      PVF::internal::aberth_roots(c.data(), N, r.data());
      EXPECT_LE(matching_error(roots, r, simple_root_tolerances(roots, 16.)), 1.) << "N = " << N;
    }
  }
}
