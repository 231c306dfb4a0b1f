// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_POLYVECTOR_POLYNOMIAL_H
#define CGAL_POLYVECTOR_FIELDS_POLYVECTOR_POLYNOMIAL_H

/// \file polyvector_polynomial.h
/// Conversion between a PolyVector (an unordered set of `N` complex numbers)
/// and the coefficients of its monic polynomial.

#include <CGAL/Polyvector_fields/internal/Field_design/polynomial_roots.h>

#include <CGAL/assertions.h>

#include <complex>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsPolynomial
///
/// computes the coefficients of the monic polynomial whose roots are `roots`:
/// `P(z) = (z - roots[0]) (z - roots[1]) ... (z - roots[N-1])
///       = z^N + c_{N-1} z^{N-1} + ... + c_1 z + c_0`.
///
/// The leading coefficient 1 is not stored.
///
/// \param roots the `N` vectors of the PolyVector, as complex numbers in the face's frame;
///        repeated and zero values are allowed.
/// \returns the `N` coefficients; entry `m` is `c_m`, the coefficient of `z^m`.
///          An empty `roots` gives an empty vector.
///
/// A zero root multiplies by `z` exactly: with `k` zero roots, the coefficients
/// `c_0, ..., c_{k-1}` are exactly zero.
///
/// \sa `sign_symmetric_polyvector_coefficients()`
/// \sa `polyvector_roots()`
inline std::vector<std::complex<double> >
polyvector_coefficients(const std::vector<std::complex<double> >& roots)
{
  typedef std::complex<double> Complex;
  const std::size_t N = roots.size();
  // p[0..d] are the coefficients (low to high) of the product of the first d factors
  std::vector<Complex> p(N + 1, Complex(0., 0.));
  p[0] = Complex(1., 0.);
  for(std::size_t d = 0; d < N; ++d)
  {
    const Complex r = roots[d];
    // multiply by (z - r)
    p[d + 1] = p[d];
    for(std::size_t j = d; j > 0; --j)
      p[j] = p[j - 1] - r * p[j];
    p[0] = -r * p[0];
  }
  p.pop_back(); // the leading 1
  return p;
}

/// \ingroup PkgPolyvectorFieldsPolynomial
///
/// computes the coefficients of the monic polynomial of the sign-symmetric
/// PolyVector `{u_0, -u_0, u_1, -u_1, ...}`:
/// `P(z) = (z^2 - u_0^2) (z^2 - u_1^2) ... (z^2 - u_{K-1}^2)`, of degree `N = 2K`.
///
/// \param u one vector of each pair `{u_i, -u_i}`; either sign may be given.
/// \returns the `N = 2 * u.size()` coefficients; entry `m` is the coefficient of `z^m`.
///          Odd entries are exactly zero.
///
/// For a frame field (`N = 4`, `u = {u, v}`), `c_2 = -(u^2 + v^2)` and `c_0 = u^2 v^2`.
///
/// \sa `polyvector_coefficients()`
/// \sa `polyvector_roots()`
inline std::vector<std::complex<double> >
sign_symmetric_polyvector_coefficients(const std::vector<std::complex<double> >& u)
{
  typedef std::complex<double> Complex;
  std::vector<Complex> squares(u.size());
  for(std::size_t i = 0; i < u.size(); ++i)
    squares[i] = u[i] * u[i];
  const std::vector<Complex> in_w = polyvector_coefficients(squares); // polynomial in w = z^2
  std::vector<Complex> c(2 * u.size(), Complex(0., 0.));
  for(std::size_t k = 0; k < in_w.size(); ++k)
    c[2 * k] = in_w[k];
  return c;
}

/// \ingroup PkgPolyvectorFieldsPolynomial
///
/// computes the `N` roots of the monic polynomial
/// `z^N + c[N-1] z^{N-1} + ... + c[1] z + c[0]`, that is, the vectors of the
/// PolyVector, in counterclockwise order. This form allocates no memory for
/// `N <= 16` and is meant for loops over faces.
///
/// <b>Order.</b> The roots are sorted by argument in `[0, 2 pi)`; a zero root has
/// argument 0 and comes before the other roots of argument 0; roots of equal
/// argument (repeated roots, for instance) are in any order. The comparisons are
/// exact for the computed roots: they use an exact orientation predicate, not
/// `atan2`.
///
/// <b>Method.</b> Closed forms where they exist: `N = 1`; `N = 2` (quadratic
/// formula arranged to avoid cancellation); sign-symmetric `N = 2`
/// (`+-sqrt(-c[0])`); sign-symmetric `N = 4` (`w = z^2` solves
/// `w^2 + c[2] w + c[0] = 0`, then `+-sqrt(w)`). Otherwise, the eigenvalues of
/// the companion matrix (for sign-symmetric input, of the `N/2 x N/2` one of
/// the polynomial in `w = z^2`), after scaling by a power of two, refined by at
/// most two guarded Newton steps that are skipped near multiple roots.
///
/// <b>Accuracy.</b> A simple root is accurate to about machine precision times
/// its condition number; a root of multiplicity `m` only to about
/// `eps^(1/m)` relative to the size of the roots (this is the conditioning of
/// the problem, not of the method). Exactly zero coefficients
/// `c[0], ..., c[k-1]` give exactly `k` zero roots (in `w = z^2` for
/// sign-symmetric input), and zero or repeated roots never produce NaN.
///
/// \param c the `N` coefficients; `c[m]` multiplies `z^m`.
/// \param N the degree.
/// \param roots receives the `N` roots.
/// \param sign_symmetric promises that the set is made of pairs `{w, -w}`, that
///        is, that the odd coefficients are zero: they are then not read, and
///        the roots come out as exact pairs: with `k` pairs of nonzero roots
///        after `z` zero roots, `roots[z + i + k] == -roots[z + i]`.
///
/// If a coefficient that is read is not finite, every root is set to NaN.
/// `N = 0` does nothing.
///
/// \pre `sign_symmetric` implies that `N` is even (in builds without
///      preconditions, an odd `N` is treated as not sign-symmetric).
///
/// \sa `polyvector_coefficients()`
/// \sa `sign_symmetric_polyvector_coefficients()`
inline void polyvector_roots(const std::complex<double>* c, std::size_t N,
                             std::complex<double>* roots, bool sign_symmetric = false)
{
  typedef std::complex<double> Complex;
  if(N == 0)
    return;
  CGAL_precondition(!sign_symmetric || N % 2 == 0);
  if(sign_symmetric && N % 2 != 0)
    sign_symmetric = false;

  // the hot case: frame fields
  if(sign_symmetric && N == 4)
  {
    if(internal::is_finite(c[0]) && internal::is_finite(c[2]))
      internal::sign_symmetric_quartic_roots(c[0], c[2], roots);
    else
      roots[0] = roots[1] = roots[2] = roots[3] = internal::complex_nan();
    return;
  }

  const std::size_t stride = sign_symmetric ? 2 : 1;
  for(std::size_t m = 0; m < N; m += stride)
  {
    if(!internal::is_finite(c[m]))
    {
      for(std::size_t i = 0; i < N; ++i)
        roots[i] = internal::complex_nan();
      return;
    }
  }

  if(sign_symmetric)
  {
    if(N == 2)
      internal::sign_symmetric_quadratic_roots(c[0], roots);
    else
      internal::companion_roots(c, N, roots, true);
    return;
  }

  if(N == 1)
  {
    roots[0] = Complex(0., 0.) - c[0];
    return;
  }
  if(N == 2)
  {
    internal::stable_quadratic_roots(c[1], c[0], roots[0], roots[1]);
    if(internal::ccw_less(roots[1], roots[0]))
      std::swap(roots[0], roots[1]);
    return;
  }
  internal::companion_roots(c, N, roots, false);
}

/// \ingroup PkgPolyvectorFieldsPolynomial
///
/// computes the `N = c.size()` roots of the monic polynomial
/// `z^N + c[N-1] z^{N-1} + ... + c[0]` in counterclockwise order.
///
/// This is the convenience form of
/// `polyvector_roots(const std::complex<double>*, std::size_t, std::complex<double>*, bool)`,
/// which documents the order, the method and the accuracy.
///
/// \param c the coefficients; `c[m]` multiplies `z^m`.
/// \param sign_symmetric promises that the odd coefficients are zero (they are not read);
///        the roots then come in exact pairs `{w, -w}`.
/// \returns the `N` roots sorted by argument in `[0, 2 pi)`.
///
/// \pre `sign_symmetric` implies that `c.size()` is even.
///
/// \sa `polyvector_coefficients()`
inline std::vector<std::complex<double> >
polyvector_roots(const std::vector<std::complex<double> >& c, bool sign_symmetric = false)
{
  std::vector<std::complex<double> > roots(c.size());
  polyvector_roots(c.data(), c.size(), roots.data(), sign_symmetric);
  return roots;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_POLYVECTOR_POLYNOMIAL_H
