// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_FIND_OUT_OF_RANGE_CONSTRAINT_VECTOR_H
#define CGAL_POLYVECTOR_FIELDS_FIND_OUT_OF_RANGE_CONSTRAINT_VECTOR_H

/// \file find_out_of_range_constraint_vector.h
/// Which constraint vector is too long or too short for the degree of the field.

#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/internal/Field_design/constraint_specification.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsDesign
///
/// finds the first vector of a constraint whose length is out of the range
/// of an `N`-PolyVector field: the coefficients of a vector of length `L` are
/// of the order of `L^N`, and the design needs `1e-300 <= L^N <= 1e300`. It
/// is the test that makes `Polyvector_field_designer::add_constraint()` (and
/// `design_polyvector_field()`) return `Error_code::VALUE_OUT_OF_RANGE` for
/// one constraint, so that a program can say which vector is wrong. The
/// length is measured without overflow or underflow, whatever the
/// coordinates. Vectors that are zero or not finite are skipped: they are
/// refused for another reason (`ZERO_CONSTRAINT_VECTOR`, `NON_FINITE_VALUE`).
///
/// The other range, `1e-100 <= (L / sigma)^N <= 1e100` for the mean length
/// `sigma` of the vectors of all the constraints, depends on the whole set of
/// constraints; it is checked by the solve, not here.
///
/// \tparam Vector_3 a vector type with `x()`, `y()` and `z()`
///
/// \param vectors the vectors of a constraint (see `Face_constraint`)
/// \param N the degree of the field, at least 1
/// \param index receives the position in `vectors` of the first vector out of range
/// \param log10_length receives the decimal logarithm of its length (the length itself
///        may be beyond the range of `double`)
///
/// \returns whether a vector is out of range; `index` and `log10_length` are unchanged if none is.
template <typename Vector_3>
bool find_out_of_range_constraint_vector(const std::vector<Vector_3>& vectors, std::size_t N, std::size_t& index,
                                         double& log10_length)
{
  for(std::size_t k = 0; k < vectors.size(); ++k)
  {
    const Vector_3& v = vectors[k];
    std::array<double, 3> w = { CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()) };
    if(!std::isfinite(w[0]) || !std::isfinite(w[1]) || !std::isfinite(w[2]))
      continue;
    // L = length * 2^e, the vector being scaled by a power of two first.
    const int e = internal::scale_to_unit({ &w });
    const double length = std::sqrt(internal::dot(w, w));
    if(!(length > 0.))
      continue;
    if(!internal::constraint_length_in_range(length, e, N))
    {
      index = k;
      log10_length = std::log10(length) + double(e) * std::log10(2.0);
      return true;
    }
  }
  return false;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_FIND_OUT_OF_RANGE_CONSTRAINT_VECTOR_H
