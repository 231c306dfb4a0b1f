// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_PRINCIPAL_CURVATURES_H
#define CGAL_POLYVECTOR_FIELDS_PRINCIPAL_CURVATURES_H

/// \file Principal_curvatures.h
/// The principal curvatures and directions of a face, and its shape operator.

#include <CGAL/Polyvector_fields/face_frames.h>

#include <CGAL/number_utils.h>

#include <array>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsCurvature
///
/// holds the principal curvatures and principal directions of a face.
///
/// <b>Sign convention.</b> Curvatures are signed with respect to the face
/// normal `n` of `Face_frame` (the normal along `(p1 - p0) x (p2 - p0)`, which
/// points to the side from which the face is seen counterclockwise): a normal
/// curvature is <em>positive where the surface bends away from `n`</em>. A
/// sphere of radius `R` whose faces are oriented so that their normals point
/// outwards therefore has `k1 = k2 = +1/R`; the same sphere with inward normals
/// has `k1 = k2 = -1/R`. The Monge form of CGAL's `Monge_via_jet_fitting` uses
/// the opposite sign (positive where the surface bends towards its normal).
///
/// <b>Ordering.</b> `k1 >= k2`, `d1` goes with `k1` and `d2` with `k2`.
/// `d1` and `d2` are unit vectors of the face plane, in world coordinates, and
/// `(d1, d2, n)` is a direct (right-handed) orthonormal frame, i.e.
/// `d2 = n x d1`. Only the line of `d1` is meaningful: `-d1`, `-d2` describe the
/// same curvature. Where `k1 = k2` (an umbilic, e.g. a sphere or a plane) the
/// directions are arbitrary.
///
/// The normal curvature in the unit tangent direction `t` of the face plane is
/// `k1 (t . d1)^2 + k2 (t . d2)^2`: this is the quadratic form of the shape
/// operator returned by `shape_operator()`.
///
/// \tparam Vector_3 the vector type of the mesh's kernel; it must be
///         constructible from three `double` values.
template <typename Vector_3>
struct Principal_curvatures
{
  double k1 = 0.;   ///< maximal principal curvature
  double k2 = 0.;   ///< minimal principal curvature, `k2 <= k1`
  Vector_3 d1;      ///< unit principal direction of `k1`, in the face plane, in world coordinates
  Vector_3 d2;      ///< unit principal direction of `k2`, `d2 = n x d1`
};

/// \ingroup PkgPolyvectorFieldsCurvature
///
/// returns the shape operator `S = k1 d1 d1^T + k2 d2 d2^T` of a face,
/// written in the face frame `frame` (see `Face_frame`), as the row-major
/// symmetric matrix `{S(0,0), S(0,1), S(1,0), S(1,1)}`.
///
/// With the complex coordinates `u = u_x + i u_y` and `v = v_x + i v_y` of two
/// tangent vectors in the face frame, the second fundamental form is
/// `II(u, v) = [u_x u_y] S [v_x v_y]^T`, and `u`, `v` are conjugate iff it is
/// zero (paper, Section 4.3). The sign convention is that of
/// `Principal_curvatures`.
///
/// The directions are projected onto the plane of `frame`, so `frame` should be
/// the frame of the face `pc` belongs to (`face_frame()`), for which the
/// projection changes nothing.
///
/// \tparam Vector_3 the vector type of the mesh's kernel
///
/// \sa `estimate_principal_curvatures()`
template <typename Vector_3>
std::array<double, 4> shape_operator(const Principal_curvatures<Vector_3>& pc, const Face_frame& frame)
{
  const std::array<double, 3> d1 = { CGAL::to_double(pc.d1.x()), CGAL::to_double(pc.d1.y()), CGAL::to_double(pc.d1.z()) };
  const std::array<double, 3> d2 = { CGAL::to_double(pc.d2.x()), CGAL::to_double(pc.d2.y()), CGAL::to_double(pc.d2.z()) };
  const double a1 = internal::dot(d1, frame.e1), b1 = internal::dot(d1, frame.e2);
  const double a2 = internal::dot(d2, frame.e1), b2 = internal::dot(d2, frame.e2);
  const double s00 = pc.k1 * a1 * a1 + pc.k2 * a2 * a2;
  const double s01 = pc.k1 * a1 * b1 + pc.k2 * a2 * b2;
  const double s11 = pc.k1 * b1 * b1 + pc.k2 * b2 * b2;
  return { s00, s01, s01, s11 };
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_PRINCIPAL_CURVATURES_H
