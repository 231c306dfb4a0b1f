// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_CONSTRAINT_SPECIFICATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_CONSTRAINT_SPECIFICATION_H

// From a constraint in world coordinates to what it asks of the coefficients
// (`Face_specification`), the degrees a set of specifications leaves active,
// and the rule that tells when new specifications can reuse a factorization.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/polyvector_polynomial.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// What a constraint asks of one face, in the face's frame.
struct Face_specification
{
  // Full constraint: values[m] for every degree m = 0..N-1.
  bool full = false;
  std::vector<Complex> values;
  // Partial constraint: rows . (c_{f,q})_q = rhs over the admissible degrees q.
  Eigen::MatrixXcd rows;
  Eigen::VectorXcd rhs;
  // log2 |u| of each of the constraint's vectors: what the length unit of the
  // design is made of (see length_exponent()).
  std::vector<double> log2_lengths;
  // Infinite: hard. Finite and positive: soft.
  double weight = std::numeric_limits<double>::infinity();

  bool is_hard() const { return std::isinf(weight); }
};

// The specifications of the constrained faces, keyed by face index.
typedef std::map<std::size_t, Face_specification> Specifications;

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

// The range of constraint vectors. A vector of length L gives coefficients of
// size up to about L^N. The design works in the length unit sigma of its
// constraints (see length_exponent()), so only the field's coefficients in the
// caller's unit must be doubles: 1e-300 <= L^N <= 1e300; and within one design
// the lengths relative to the unit must keep their powers, and their squares
// in the energies, well inside the double range: 1e-100 <= (L / sigma)^N <= 1e100.
constexpr double constraint_magnitude_exponent = 300;
constexpr double relative_magnitude_exponent = 100;

// Whether the length L = length * 2^e has 1e-300 <= L^N <= 1e300.
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
  std::vector<double> log2_lengths;
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
    log2_lengths.push_back(std::log2(length) + double(e));
  }

  Face_specification s;
  s.weight = weight;
  s.log2_lengths = log2_lengths;
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

// The length unit sigma = 2^k of a design: the power of two nearest the
// geometric mean of the lengths of its constraint vectors (k = 0 without
// constraints). The design solves for c_m / sigma^(N-m), whose sizes are about
// 1 whatever the unit of the constraints, and scales back exactly: a field
// with constraints of unit-size vectors is computed as without the unit, and
// scaling every constraint by a power of two scales the field exactly.
inline int length_exponent(const Specifications& specifications)
{
  double sum = 0;
  std::size_t count = 0;
  for(const auto& entry : specifications)
    for(double log2_length : entry.second.log2_lengths)
    {
      sum += log2_length;
      ++count;
    }
  return count > 0 ? int(std::lround(sum / double(count))) : 0;
}

// Whether every constraint vector has 1e-100 <= (L / 2^k)^N <= 1e100.
inline bool lengths_in_range(const Specifications& specifications, int k, std::size_t N)
{
  for(const auto& entry : specifications)
    for(double log2_length : entry.second.log2_lengths)
      if(std::abs(double(N) * (log2_length - double(k))) * 0.30102999566398119521 > relative_magnitude_exponent)
        return false;
  return true;
}

// The specification in the unit sigma = 2^k: full values c_m / sigma^(N-m);
// partial rows over the slots of degrees m(q), whose x = u (or u^2) and P(x)
// scale by sigma (or sigma^2) and sigma^N: column q times sigma^-m(q) and the
// right-hand side times sigma^-N. All exact (powers of two).
inline Face_specification in_length_unit(const Face_specification& s, int k, std::size_t N)
{
  Face_specification t = s;
  if(k == 0)
    return t;
  for(std::size_t m = 0; m < t.values.size(); ++m)
    t.values[m] = Complex(std::ldexp(t.values[m].real(), -k * int(N - m)), std::ldexp(t.values[m].imag(), -k * int(N - m)));
  // The slots of partial rows are the admissible degrees: all of them, or the
  // even ones with sign symmetry (then there are N/2 columns).
  const int step = (t.rows.cols() == Eigen::Index(N)) ? 1 : 2;
  for(Eigen::Index q = 0; q < t.rows.cols(); ++q)
  {
    const int degree = step * int(q);
    for(Eigen::Index r = 0; r < t.rows.rows(); ++r)
      t.rows(r, q) = Complex(std::ldexp(t.rows(r, q).real(), -k * degree), std::ldexp(t.rows(r, q).imag(), -k * degree));
  }
  for(Eigen::Index r = 0; r < t.rhs.size(); ++r)
    t.rhs[r] = Complex(std::ldexp(t.rhs[r].real(), -k * int(N)), std::ldexp(t.rhs[r].imag(), -k * int(N)));
  return t;
}

// The degrees that are not identically zero under `specifications`: a degree
// whose full constraint values are all zero has the exact solution zero.
// Partial constraints involve every admissible degree.
inline std::vector<int> active_degrees(const Specifications& specifications, std::size_t N, bool sign_symmetric)
{
  const std::vector<int> admissible = admissible_degrees(N, sign_symmetric);
  std::vector<char> used(N, 0);
  for(const auto& entry : specifications)
  {
    if(!entry.second.full)
      return admissible;
    for(int m : admissible)
      if(entry.second.values[std::size_t(m)] != Complex(0))
        used[std::size_t(m)] = 1;
  }
  std::vector<int> degrees;
  for(int m : admissible)
    if(used[std::size_t(m)])
      degrees.push_back(m);
  return degrees;
}

// The reuse rule: the matrices of the linear system depend on the constrained
// faces, their kinds (full or partial, hard or soft), their weights and the
// rows of partial constraints, not on the values of full constraints. Two sets
// of specifications that agree on those can share one factorization.
inline bool same_matrices(const Specifications& a, const Specifications& b)
{
  if(a.size() != b.size())
    return false;
  for(auto i = a.begin(), j = b.begin(); i != a.end(); ++i, ++j)
  {
    const Face_specification &s = i->second, &t = j->second;
    if(i->first != j->first || s.full != t.full || s.weight != t.weight)
      return false;
    if(!s.full && (s.rows.rows() != t.rows.rows() || s.rows.cols() != t.rows.cols() || s.rows != t.rows ||
                   s.rhs != t.rhs))
      return false;
  }
  return true;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_CONSTRAINT_SPECIFICATION_H
