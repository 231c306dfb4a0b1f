// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_FACE_FRAMES_H
#define CGAL_POLYVECTOR_FIELDS_FACE_FRAMES_H

/// \file face_frames.h
/// Face frames: the identification of each face plane with the complex plane.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <cmath>
#include <complex>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsFrames
///
/// is an orthonormal frame of a face plane, in `double` precision.
///
/// <b>Convention.</b> Let `h = halfedge(f, tm)`, `p0` the point of `source(h)`,
/// `p1` the point of `target(h)` and `p2` the point of `target(next(h))`. Then
/// - `normal` is the unit vector along `(p1 - p0) x (p2 - p0)`: it points to the
///   side from which the face is seen counterclockwise;
/// - `e1` is the unit vector along `p1 - p0`;
/// - `e2 = normal x e1`.
///
/// A tangent vector `x e1 + y e2` of the face is the complex number `x + i y`.
/// All PolyVector coefficients of a face are expressed in this complex plane.
/// Choosing another halfedge of the face turns the frame by a unit complex
/// number; world-space results do not depend on that choice.
struct Face_frame
{
  std::array<double, 3> e1;      ///< first axis, the real axis of the complex plane
  std::array<double, 3> e2;      ///< second axis, the imaginary axis
  std::array<double, 3> normal;  ///< unit normal, `e1 x e2`

  /// returns the complex coordinate of the projection of `(x, y, z)` onto the face plane.
  std::complex<double> to_complex(double x, double y, double z) const
  {
    return { x * e1[0] + y * e1[1] + z * e1[2], x * e2[0] + y * e2[1] + z * e2[2] };
  }

  /// returns the world coordinates of the tangent vector with complex coordinate `c`.
  std::array<double, 3> to_world(const std::complex<double>& c) const
  {
    return { c.real() * e1[0] + c.imag() * e2[0],
             c.real() * e1[1] + c.imag() * e2[1],
             c.real() * e1[2] + c.imag() * e2[2] };
  }
};

namespace internal {

inline std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

inline double dot(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline std::array<double, 3> difference(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

template <typename Point>
std::array<double, 3> to_array(const Point& p)
{
  return { CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) };
}

// The points scaled by one power of two, chosen so that their largest
// coordinate is in [1, 2): differences and products of the scaled points can
// neither overflow nor underflow, and every quantity that does not depend on
// the scale (a direction, an angle, a frame) comes out bit-identical to the
// unscaled computation whenever that one does not overflow or underflow.
// Returns the exponent e of the scale 2^-e (0 when the points are all zero).
inline int scale_to_unit(std::initializer_list<std::array<double, 3>*> points)
{
  double m = 0;
  for(const auto* p : points)
    for(double x : *p)
      m = (std::max)(m, std::abs(x));
  if(!(m > 0) || !std::isfinite(m))
    return 0;
  const int e = std::ilogb(m);
  if(e == 0)
    return 0;
  if(-1022 <= e && e <= 1022)
  {
    // 2^-e is a normal double: x * 2^-e is the correctly rounded x 2^-e, as
    // is std::ldexp(x, -e), so the two are bit-identical; the product is
    // several times cheaper than the call.
    const double scale = std::ldexp(1.0, -e);
    for(auto* p : points)
      for(double& x : *p)
        x *= scale;
    return e;
  }
  for(auto* p : points)
    for(double& x : *p)
      x = std::ldexp(x, -e);
  return e;
}

// The direction of b - a, scaled by a power of two (see scale_to_unit()).
inline std::array<double, 3> scaled_difference(std::array<double, 3> b, std::array<double, 3> a)
{
  scale_to_unit({ &a, &b });
  return difference(b, a);
}

// Relative area below which a triangle is degenerate: |(p1-p0) x (p2-p0)| is
// compared with the square of the longest edge.
constexpr double degenerate_face_tolerance = 1e-12;

// Builds the frame of the triangle p0 p1 p2 (see `Face_frame`). Returns
// DEGENERATE_FACE for a non-finite coordinate or a (numerically) zero area.
// Safe over the whole range of double: the points are scaled first.
inline Error_code triangle_frame(std::array<double, 3> p0,
                                 std::array<double, 3> p1,
                                 std::array<double, 3> p2,
                                 Face_frame& frame)
{
  for(const auto* p : { &p0, &p1, &p2 })
    for(double x : *p)
      if(!std::isfinite(x))
        return Error_code::DEGENERATE_FACE;
  scale_to_unit({ &p0, &p1, &p2 });  // the frame does not depend on the scale

  const std::array<double, 3> a = difference(p1, p0), b = difference(p2, p0), c = difference(p2, p1);
  const std::array<double, 3> n = cross(a, b);
  const double n_length = std::sqrt(dot(n, n));
  const double longest = (std::max)({ dot(a, a), dot(b, b), dot(c, c) });
  if(!(n_length > degenerate_face_tolerance * longest))
    return Error_code::DEGENERATE_FACE;

  const double a_length = std::sqrt(dot(a, a));
  frame.normal = { n[0] / n_length, n[1] / n_length, n[2] / n_length };
  frame.e1 = { a[0] / a_length, a[1] / a_length, a[2] / a_length };
  frame.e2 = cross(frame.normal, frame.e1);
  return Error_code::SUCCESS;
}

} // namespace internal

/// \ingroup PkgPolyvectorFieldsFrames
///
/// computes the frame of the triangle `f` with the convention of `Face_frame`.
///
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param f a triangle face of `tm`
/// \param tm the mesh
/// \param frame receives the frame; unchanged on failure
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \pvfParamVertexPointMap
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::NON_TRIANGLE_FACE` if `f` is not a triangle,
///          `Error_code::DEGENERATE_FACE` if it has zero area or a non-finite
///          coordinate, `Error_code::SUCCESS` otherwise.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code face_frame(typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                      const TriangleMesh& tm,
                      Face_frame& frame,
                      const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using boost::get;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    CGAL::get_const_property_map(CGAL::vertex_point, tm));
  const auto h = halfedge(f, tm);
  if(next(next(next(h, tm), tm), tm) != h)
    return Error_code::NON_TRIANGLE_FACE;
  return internal::triangle_frame(internal::to_array(get(vpm, source(h, tm))),
                                  internal::to_array(get(vpm, target(h, tm))),
                                  internal::to_array(get(vpm, target(next(h, tm), tm))),
                                  frame);
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_FACE_FRAMES_H
