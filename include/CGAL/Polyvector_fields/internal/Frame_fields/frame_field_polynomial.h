// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_FRAME_FIELD_POLYNOMIAL_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_FRAME_FIELD_POLYNOMIAL_H

// A frame {u, v, -u, -v} and its polynomial (z^2 - u^2)(z^2 - v^2) =
// z^4 + c_2 z^2 + c_0, with c_0 = u^2 v^2 and c_2 = -(u^2 + v^2) (paper
// Section 4; the user manual's section "Frame fields").

#include <CGAL/Polyvector_fields/polyvector_polynomial.h>

#include <complex>
#include <utility>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// u = first root, v = second root in counterclockwise order: {u, v, -u, -v}.
inline std::pair<std::complex<double>, std::complex<double> > frame_vectors(const std::complex<double>* c)
{
  std::complex<double> roots[4];
  polyvector_roots(c, 4, roots, true);
  return { roots[0], roots[1] };
}

// The coefficients (c_0, c_1, c_2, c_3) of the frame {u, v, -u, -v}.
inline void frame_coefficients(const std::complex<double>& u, const std::complex<double>& v, std::complex<double>* c)
{
  const std::complex<double> u2 = u * u, v2 = v * v;
  c[0] = u2 * v2;
  c[1] = 0;
  c[2] = -(u2 + v2);
  c[3] = 0;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_FRAME_FIELD_POLYNOMIAL_H
