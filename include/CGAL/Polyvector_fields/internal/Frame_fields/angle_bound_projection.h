// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_ANGLE_BOUND_PROJECTION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_ANGLE_BOUND_PROJECTION_H

// Local step of the angle-bounded frame-field iterations (paper Section 4.2;
// the user manual's section "Angle-bounded frame fields"), as per-face arithmetic on the two vectors u, v of a
// frame {u, v, -u, -v}, written as complex numbers in the face's frame.

#include <CGAL/assertions.h>
#include <CGAL/number_type_config.h>

#include <cmath>
#include <complex>
#include <utility>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

/// Returns the smallest angle between two distinct vectors of the frame
/// `{u, v, -u, -v}`, in `[0, pi/2]`: the angle between the lines spanned by `u`
/// and `v`.
///
/// A frame with a zero vector has no angle. By convention the function then
/// returns `pi/2`, so that such a frame counts as satisfying every bound; this
/// matches `enforce_angle_bound()`, which leaves it unchanged. Callers that
/// must tell degenerate frames apart test for zero vectors themselves.
inline double smallest_frame_angle(std::complex<double> u, std::complex<double> v)
{
  if(u == 0. || v == 0.)
    return 0.5 * CGAL_PI;
  const std::complex<double> p = std::conj(u) * v; // |u||v| e^{i (arg v - arg u)}
  return std::atan2(std::abs(p.imag()), std::abs(p.real()));
}

/// Enforces the minimal angle `theta_min` on the frame `{u, v, -u, -v}`.
///
/// Let `theta = smallest_frame_angle(u, v)`. If `theta >= theta_min`, `(u, v)`
/// is returned unchanged (bit for bit). Otherwise the two vectors that realise
/// `theta` (`u` and `v` if `<u, v> >= 0`, else `u` and `-v`) are rotated
/// symmetrically away from their bisector, each by `(theta_min - theta)/2`, so
/// that their angle becomes `theta_min`; lengths and the bisector are kept. The
/// returned pair keeps the roles and signs: the first entry is the rotated `u`,
/// the second the rotated `v` (not `-v`).
///
/// Degenerate inputs: if `u` or `v` is zero, the angle is undefined and the
/// pair is returned unchanged. If `u` and `v` are parallel or antiparallel
/// (`theta = 0`), the bisector is the direction of `u`: `u` is turned clockwise
/// and `v` (or `-v`) counterclockwise by `theta_min/2`.
///
/// \pre `0 < theta_min <= pi/2` (the public API validates the user's value).
inline std::pair<std::complex<double>, std::complex<double> >
enforce_angle_bound(std::complex<double> u, std::complex<double> v, double theta_min)
{
  CGAL_precondition(theta_min > 0. && theta_min <= 0.5 * CGAL_PI * (1. + 1e-15));

  if(u == 0. || v == 0.)
    return std::make_pair(u, v);

  const std::complex<double> p = std::conj(u) * v;
  const double theta = std::atan2(std::abs(p.imag()), std::abs(p.real()));
  if(!(theta < theta_min))
    return std::make_pair(u, v);

  // The pair (u, w) realises theta, with w = sign * v.
  const double sign = (p.real() >= 0.) ? 1. : -1.;
  // Orientation of w relative to u; for parallel vectors (cross product 0)
  // w is taken as counterclockwise from u.
  const double cross = sign * p.imag();
  const double orientation = (cross >= 0.) ? 1. : -1.;
  const double half_opening = 0.5 * (theta_min - theta);
  const std::complex<double> turn = std::polar(1., orientation * half_opening);
  // u turns away from w, w away from u; the bisector does not move.
  return std::make_pair(u * std::conj(turn), v * turn);
}

/// Enforces the minimal angle `theta_min` on the frame `{u, v, -u, -v}` as
/// `enforce_angle_bound()` does, but keeps one of the two vectors where it is:
/// `u` if `keep_u`, else `v`. The other one turns by the whole deficit
/// `theta_min - theta`, away from the kept one. For a face whose frame a hard
/// partial constraint holds by one of its vectors.
inline std::pair<std::complex<double>, std::complex<double> >
enforce_angle_bound_keeping(std::complex<double> u, std::complex<double> v, double theta_min, bool keep_u)
{
  const std::pair<std::complex<double>, std::complex<double> > sym = enforce_angle_bound(u, v, theta_min);
  if(sym.first == u && sym.second == v)
    return sym;  // within the bound, or degenerate: unchanged
  // The symmetric step turned u and v by opposite unit rotations; undo the
  // kept vector's, on both. |u| = |sym.first| and |v| = |sym.second|.
  const std::complex<double> back = keep_u ? u / sym.first : v / sym.second;
  const std::complex<double> unit = back / std::abs(back);
  return keep_u ? std::make_pair(u, sym.second * unit) : std::make_pair(sym.first * unit, v);
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_ANGLE_BOUND_PROJECTION_H
