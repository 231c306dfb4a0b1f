// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_TENSOR_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_TENSOR_H

// Small dense helpers for curvature tensors: moving a tangent frame from one
// plane to another, and the eigen-decomposition of a symmetric 2x2 matrix.

#include <CGAL/Polyvector_fields/face_frames.h>

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

// Eigen-decomposition of the symmetric matrix [[s00, s01], [s01, s11]]:
// lambda_max >= lambda_min, and the unit eigenvector of lambda_max is
// (cos(angle), sin(angle)) with angle in (-pi/2, pi/2] (so its first
// coordinate is never negative). Where the two eigenvalues are equal the
// angle is 0.
struct Curvature_eigen_2
{
  double lambda_max;
  double lambda_min;
  double angle;
};

inline Curvature_eigen_2 curvature_eigen_2(double s00, double s01, double s11)
{
  const double mean = 0.5 * (s00 + s11);
  const double half_difference = 0.5 * (s00 - s11);
  const double radius = std::hypot(half_difference, s01);
  Curvature_eigen_2 result;
  result.lambda_max = mean + radius;
  result.lambda_min = mean - radius;
  // The quadratic form at angle t is mean + half_difference cos(2t) + s01 sin(2t),
  // largest where (cos 2t, sin 2t) is along (half_difference, s01).
  result.angle = (radius > 0.) ? 0.5 * std::atan2(s01, half_difference) : 0.;
  if(result.angle <= -0.5 * 3.14159265358979323846)
    result.angle += 3.14159265358979323846;
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

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_TENSOR_H
