// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_CURVATURE_TENSOR_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_CURVATURE_TENSOR_H

// Small dense helpers for curvature tensors: moving a tangent frame from one
// plane to another, and the eigen-decomposition of a symmetric 2x2 matrix
// (also the shape operator's, in the conjugacy projection).

#include <CGAL/Polyvector_fields/face_frames.h>

#include <CGAL/number_type_config.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// Applies to `v` the rotation that maps the unit vector `from` onto the unit
// vector `to` and fixes their common orthogonal line (the smallest rotation
// between the two planes orthogonal to `from` and `to`). With c = from . to and
// a = from x to, it is v -> c v + a x v + (a . v) / (1 + c) a (Rodrigues).
//
// When `from` and `to` are (nearly) opposite the smallest rotation is not
// unique; the half-turn about `axis_hint` (a unit vector orthogonal to `to`)
// is used instead.
inline std::array<double, 3> curvature_rotate(const std::array<double, 3>& v,
                                              const std::array<double, 3>& from,
                                              const std::array<double, 3>& to,
                                              const std::array<double, 3>& axis_hint)
{
  const double c = dot(from, to);
  if(1. + c < 1e-8)
  {
    const double s = 2. * dot(axis_hint, v);
    return { s * axis_hint[0] - v[0], s * axis_hint[1] - v[1], s * axis_hint[2] - v[2] };
  }
  const std::array<double, 3> a = cross(from, to);
  const std::array<double, 3> axv = cross(a, v);
  const double t = dot(a, v) / (1. + c);
  return { c * v[0] + axv[0] + t * a[0], c * v[1] + axv[1] + t * a[1], c * v[2] + axv[2] + t * a[2] };
}

// Eigen-decomposition of the symmetric matrix [[a, b], [b, c]]: lambda_max >=
// lambda_min, and the unit eigenvector of lambda_max is (cos(angle),
// sin(angle)) with angle in (-pi/2, pi/2] (so its first coordinate is never
// negative). Where the two eigenvalues are equal the angle is 0. The
// eigenvalue of smaller magnitude loses its relative accuracy to cancellation
// when it is much smaller than the other one (a nearly parabolic shape
// operator): it is then recomputed as det / lambda_big, with the determinant
// ac - b^2 evaluated by Kahan's fma scheme, accurate to a few ulps.
struct Symmetric_eigen_2
{
  double lambda_max;
  double lambda_min;
  double angle;
};

inline Symmetric_eigen_2 symmetric_eigen_2(double a, double b, double c)
{
  // Scaled by a power of two first (exact), so that b^2 and ac cannot overflow
  // or underflow; the eigenvalues are scaled back.
  const double largest = (std::max)({ std::abs(a), std::abs(b), std::abs(c) });
  const int e = (largest > 0 && std::isfinite(largest)) ? std::ilogb(largest) : 0;
  a = std::ldexp(a, -e);
  b = std::ldexp(b, -e);
  c = std::ldexp(c, -e);
  const double mean = 0.5 * (a + c);
  const double half_difference = 0.5 * (a - c);
  const double radius = std::hypot(half_difference, b);
  Symmetric_eigen_2 result;
  result.lambda_max = mean + radius;
  result.lambda_min = mean - radius;
  double& small = (mean >= 0.) ? result.lambda_min : result.lambda_max;
  const double big = (mean >= 0.) ? result.lambda_max : result.lambda_min;
  if(std::abs(small) < 0.125 * std::abs(big))
  {
    const double bb = b * b;
    const double bb_error = std::fma(-b, b, bb);  // bb - b^2, exactly
    small = (std::fma(a, c, -bb) + bb_error) / big;
  }
  // The quadratic form at angle t is mean + half_difference cos(2t) + b sin(2t),
  // largest where (cos 2t, sin 2t) is along (half_difference, b).
  result.angle = (radius > 0.) ? 0.5 * std::atan2(b, half_difference) : 0.;
  if(result.angle <= -0.5 * CGAL_PI)
    result.angle += CGAL_PI;
  result.lambda_max = std::ldexp(result.lambda_max, e);
  result.lambda_min = std::ldexp(result.lambda_min, e);
  return result;
}

// Is the integral value `v` in [lo, hi]? Works for signed and unsigned types
// without sign-conversion surprises.
template <typename T>
bool curvature_integral_in_range(T v, long long lo, long long hi)
{
  static_assert(std::is_integral<T>::value, "this parameter must have an integral type");
  if constexpr(std::is_signed<T>::value)
    return static_cast<long long>(v) >= lo && static_cast<long long>(v) <= hi;
  else
    return (lo <= 0 || static_cast<unsigned long long>(v) >= static_cast<unsigned long long>(lo))
           && hi >= 0 && static_cast<unsigned long long>(v) <= static_cast<unsigned long long>(hi);
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_CURVATURE_TENSOR_H
