// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_CONSTRAINT_SPECIFICATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_CONSTRAINT_SPECIFICATION_H

// From a constraint in world coordinates to what it asks of the coefficients.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/polyvector_polynomial.h>
#include <CGAL/Polyvector_fields/internal/Coefficient_system.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The degrees m in 0..N-1 a field can use: all of them, or with sign symmetry
// those with N - m even.
inline std::vector<int> admissible_degrees(std::size_t N, bool sign_symmetric)
{
  std::vector<int> degrees;
  for(std::size_t m = 0; m < N; ++m)
    if(!sign_symmetric || (N - m) % 2 == 0)
      degrees.push_back(int(m));
  return degrees;
}

inline double binomial(std::size_t n, std::size_t k)
{
  double b = 1;
  for(std::size_t i = 1; i <= k; ++i)
    b = b * double(n - k + i) / double(i);
  return b;
}

// Coefficients computed from roots carry round-off of about
// eps * binom(N, m) * s^(N-m), s the largest root: below a small multiple of
// that, a coefficient is exactly zero (an N-RoSy has exactly one non-zero
// coefficient), so that the degree can be skipped.
inline void clean_round_off(std::vector<Complex>& c, const std::vector<Complex>& roots)
{
  double s = 0;
  for(const Complex& u : roots)
    s = (std::max)(s, std::abs(u));
  const std::size_t N = c.size();
  for(std::size_t m = 0; m < N; ++m)
    if(std::abs(c[m]) <= 64 * std::numeric_limits<double>::epsilon() * binomial(N, m) * std::pow(s, double(N - m)))
      c[m] = 0;
}

// The range of constraint vectors: a vector of length L gives coefficients
// of magnitude up to about L^N (L^(N-m) binom(N, m) for c_m), which the
// energies square. The package accepts 1e-100 <= L^N <= 1e100, so that every
// coefficient and its squared modulus, times a soft weight, is a normal double.
constexpr double constraint_magnitude_exponent = 100;

// Whether the length L = length * 2^e has 1e-100 <= L^N <= 1e100.
inline bool constraint_length_in_range(double length, int e, std::size_t N)
{
  const double log10_length = std::log10(length) + double(e) * 0.30102999566398119521;
  return std::abs(double(N) * log10_length) <= constraint_magnitude_exponent;
}

// The range of soft-constraint weights, relative to the unit weights of the
// smoothness terms. Above 1e8 = 1/sqrt(machine epsilon) the normal equations
// lose every digit in the directions that a soft partial constraint leaves
// free (its term has rank one per vector): such a weight is a hard constraint
// in all but name, and should be given as one. Below 1e-8 a constraint only
// matters where nothing else does; the bound keeps the range symmetric.
constexpr double minimum_soft_weight = 1e-8;
constexpr double maximum_soft_weight = 1e8;

// Converts the world vectors of a constraint on the face with `frame` into a
// specification. Each vector is projected onto the face plane and keeps its
// length. `degrees` are the active degrees of the system (used for the rows of
// a partial constraint).
template <typename Vector_3>
Error_code make_face_specification(const Face_frame& frame,
                                   const std::vector<Vector_3>& vectors,
                                   double weight,
                                   std::size_t N,
                                   bool sign_symmetric,
                                   Face_specification& specification)
{
  if(vectors.empty())
    return Error_code::EMPTY_CONSTRAINT;
  if(std::isnan(weight))
    return Error_code::NON_FINITE_VALUE;
  if(!(weight > 0) || (!std::isinf(weight) && !(weight >= minimum_soft_weight && weight <= maximum_soft_weight)))
    return Error_code::INVALID_WEIGHT;
  const std::size_t n = sign_symmetric ? N / 2 : N;
  if(vectors.size() > n)
    return Error_code::TOO_MANY_CONSTRAINT_VECTORS;

  std::vector<Complex> roots;
  for(const Vector_3& v : vectors)
  {
    std::array<double, 3> w = { CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()) };
    if(!std::isfinite(w[0]) || !std::isfinite(w[1]) || !std::isfinite(w[2]))
      return Error_code::NON_FINITE_VALUE;
    // Scaled by a power of two first, so that no square overflows or underflows;
    // the root is the same, bit for bit, as without the scaling.
    const int e = scale_to_unit({ &w });
    const double length = std::sqrt(dot(w, w));
    const Complex u = frame.to_complex(w[0], w[1], w[2]);
    const double projected = std::abs(u);
    if(!(length > 0) || !(projected > 1e-9 * length))
      return Error_code::ZERO_CONSTRAINT_VECTOR;
    if(!constraint_length_in_range(length, e, N))
      return Error_code::VALUE_OUT_OF_RANGE;
    const Complex root = u * (length / projected);
    roots.push_back(Complex(std::ldexp(root.real(), e), std::ldexp(root.imag(), e)));
  }

  Face_specification s;
  s.weight = weight;
  if(roots.size() == n)
  {
    s.full = true;
    s.values = sign_symmetric ? sign_symmetric_polyvector_coefficients(roots) : polyvector_coefficients(roots);
    std::vector<Complex> all_roots = roots;
    clean_round_off(s.values, all_roots);
  }
  else
  {
    // P(u) = 0 for every given u, in the variable x = u (or x = u^2 with sign
    // symmetry, where P(z) = Q(z^2)). The j-th repetition of the same x asks
    // that the j-th derivative vanish too: a root of multiplicity j+1.
    const std::vector<int> degrees = admissible_degrees(N, sign_symmetric);
    const std::size_t slots = degrees.size();
    std::vector<Complex> xs;
    std::vector<int> order;
    for(const Complex& u : roots)
    {
      const Complex x = sign_symmetric ? u * u : u;
      int repeated = 0;
      for(const Complex& previous : xs)
        if(std::abs(previous - x) <= 1e-12 * (std::max)(std::abs(previous), std::abs(x)))
          ++repeated;
      xs.push_back(x);
      order.push_back(repeated);
    }
    s.rows.resize(Eigen::Index(xs.size()), Eigen::Index(slots));
    s.rhs.resize(Eigen::Index(xs.size()));
    // Q(x) = x^n + sum_q c_{degrees[q]} x^q, derivative j: falling factorials.
    auto falling = [](std::size_t a, int j) {
      double r = 1;
      for(int i = 0; i < j; ++i)
        r *= double(a) - i;
      return r;
    };
    for(std::size_t r = 0; r < xs.size(); ++r)
    {
      const int j = order[r];
      for(std::size_t q = 0; q < slots; ++q)
        s.rows(Eigen::Index(r), Eigen::Index(q)) =
          (int(q) >= j) ? falling(q, j) * std::pow(xs[r], int(q) - j) : Complex(0);
      s.rhs[Eigen::Index(r)] = -falling(n, j) * std::pow(xs[r], int(n) - j);
    }
  }
  specification = s;
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_CONSTRAINT_SPECIFICATION_H
