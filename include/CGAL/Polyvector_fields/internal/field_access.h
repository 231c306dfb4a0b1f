// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_ACCESS_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_ACCESS_H

// Reads a coefficient property map into a flat array (N per face, in the
// bundle's face order), checking sizes and finiteness, so that the
// algorithms run on contiguous data and never see a malformed field.

#include <CGAL/Polyvector_fields/Error_code.h>

#include <cmath>
#include <complex>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

template <typename Bundle, typename CoefficientMap>
Error_code read_coefficients(const Bundle& bundle, std::size_t N, CoefficientMap coefficients,
                             std::vector<std::complex<double> >& flat)
{
  using boost::get;
  if(bundle.status() != Error_code::SUCCESS)
    return bundle.status();
  if(N == 0)
    return Error_code::INVALID_DEGREE;
  const std::size_t F = bundle.number_of_faces();
  std::vector<std::complex<double> > result(F * N);
  for(std::size_t f = 0; f < F; ++f)
  {
    const auto& c = get(coefficients, bundle.face(f));
    if(c.size() != N)
      return Error_code::INCONSISTENT_DEGREE;
    for(std::size_t m = 0; m < N; ++m)
    {
      if(!std::isfinite(c[m].real()) || !std::isfinite(c[m].imag()))
        return Error_code::NON_FINITE_VALUE;
      result[f * N + m] = c[m];
    }
  }
  flat.swap(result);
  return Error_code::SUCCESS;
}

// Writes a flat coefficient array (N per face, in the bundle's face order)
// into a property map, one std::vector of N coefficients per face.
template <typename Bundle, typename CoefficientMap>
void write_coefficients(const Bundle& bundle, std::size_t N, const std::vector<std::complex<double> >& flat,
                        CoefficientMap coefficients)
{
  for(std::size_t f = 0; f < bundle.number_of_faces(); ++f)
    put(coefficients, bundle.face(f),
        std::vector<std::complex<double> >(flat.begin() + std::ptrdiff_t(f * N), flat.begin() + std::ptrdiff_t((f + 1) * N)));
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_ACCESS_H
