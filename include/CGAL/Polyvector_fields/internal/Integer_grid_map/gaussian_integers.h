// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// Gaussian integers Z[i] and Z[i]-linear forms: the exact arithmetic of the
// seam relations of a seamless map (see seamless_reduction.h).

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_GAUSSIAN_INTEGERS_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_GAUSSIAN_INTEGERS_H

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <map>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// ---------------------------------------------------------------------------
// Gaussian integers: the coefficients of the seam relations. A rotation by
// R^r (r quarter turns counterclockwise) of a uv vector is the multiplication
// of U + iV by i^r, so every seam relation has coefficients in Z[i].
// ---------------------------------------------------------------------------
struct Gint
{
  long long re = 0, im = 0;
  Gint() {}
  Gint(long long r, long long i) : re(r), im(i) {}
  bool is_zero() const { return re == 0 && im == 0; }
  bool is_unit() const { return std::llabs(re) + std::llabs(im) == 1; }
};
inline Gint operator+(Gint a, Gint b) { return Gint(a.re + b.re, a.im + b.im); }
inline Gint operator-(Gint a, Gint b) { return Gint(a.re - b.re, a.im - b.im); }
inline Gint operator-(Gint a) { return Gint(-a.re, -a.im); }
inline Gint operator*(Gint a, Gint b) { return Gint(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re); }
inline bool operator==(Gint a, Gint b) { return a.re == b.re && a.im == b.im; }
inline Gint i_power(int r)
{
  switch(((r % 4) + 4) % 4)
  {
    case 0: return Gint(1, 0);
    case 1: return Gint(0, 1);
    case 2: return Gint(-1, 0);
    default: return Gint(0, -1);
  }
}
inline Gint unit_inverse(Gint u) { return Gint(u.re, -u.im); }  // for |u| = 1
inline int mod4(int r) { return ((r % 4) + 4) % 4; }
inline long long norm(Gint a) { return a.re * a.re + a.im * a.im; }
// nearest Gaussian integer to a / b
inline Gint rounded_quotient(Gint a, Gint b)
{
  const Gint n = a * Gint(b.re, -b.im);
  const double d = double(norm(b));
  return Gint(std::llround(double(n.re) / d), std::llround(double(n.im) / d));
}
inline Gint gaussian_gcd(Gint a, Gint b)
{
  while(!b.is_zero())
  {
    const Gint r = a - rounded_quotient(a, b) * b;
    a = b;
    b = r;
  }
  return a;
}
// a / b, b dividing a
inline Gint exact_divide(Gint a, Gint b) { return rounded_quotient(a, b); }

// A Z[i]-linear form: variable -> coefficient (zero coefficients removed).
typedef std::map<std::size_t, Gint> Gform;
inline void add_scaled(Gform& a, const Gform& b, Gint s)
{
  for(const auto& kv : b)
  {
    Gint& x = a[kv.first];
    x = x + s * kv.second;
    if(x.is_zero())
      a.erase(kv.first);
  }
}
inline Gform scaled(const Gform& a, Gint s)
{
  Gform out;
  add_scaled(out, a, s);
  return out;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_GAUSSIAN_INTEGERS_H
