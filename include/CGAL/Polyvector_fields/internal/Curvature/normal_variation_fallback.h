// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_NORMAL_VARIATION_FALLBACK_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_NORMAL_VARIATION_FALLBACK_H

// The second estimator of estimate_principal_curvatures(), for the vertices
// whose jet fit fails: the shape operators of their faces estimated from the
// variation of the vertex normals, averaged in the vertex's tangent plane.

#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/internal/Curvature/curvature_tensor.h>
#include <CGAL/Polyvector_fields/internal/Curvature/vertex_jet_fits.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The shape operator of a triangle from the variation of its vertex normals
// (the second estimator, for vertices whose fit fails): the symmetric S of the
// face plane that best maps each edge e = p_j - p_i onto n_j - n_i, in least
// squares (S e_k = dn_k, 6 equations for the 3 entries of S). Returned in 3D,
// row-major, with the package's sign (positive where the surface bends away
// from the normals: they spread out, as on a sphere with outward normals).
inline std::array<double, 9> normal_variation_tensor(const std::array<double, 3>* p, const std::array<double, 3>* n,
                                                     const Face_frame& frame)
{
  double M[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } }, r[3] = { 0, 0, 0 };
  for(int k = 0; k < 3; ++k)
  {
    const int i = k, j = (k + 1) % 3;
    const std::array<double, 3> e = difference(p[j], p[i]), dn = difference(n[j], n[i]);
    const double ex = dot(e, frame.e1), ey = dot(e, frame.e2), dx = dot(dn, frame.e1), dy = dot(dn, frame.e2);
    // a ex + b ey = dx, b ex + c ey = dy: rows (ex, ey, 0) and (0, ex, ey).
    const double rows[2][3] = { { ex, ey, 0 }, { 0, ex, ey } }, rhs[2] = { dx, dy };
    for(int q = 0; q < 2; ++q)
      for(int a = 0; a < 3; ++a)
      {
        r[a] += rows[q][a] * rhs[q];
        for(int b = 0; b < 3; ++b)
          M[a][b] += rows[q][a] * rows[q][b];
      }
  }
  // The 3x3 normal equations, by Cramer's rule (M is positive definite for a
  // non-degenerate triangle).
  const double det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                     M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  double x[3] = { 0, 0, 0 };
  if(det != 0 && std::isfinite(det))
    for(int c = 0; c < 3; ++c)
    {
      double A[3][3];
      for(int a = 0; a < 3; ++a)
        for(int b = 0; b < 3; ++b)
          A[a][b] = (b == c) ? r[a] : M[a][b];
      x[c] = (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
              A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0])) / det;
    }
  std::array<double, 9> T;
  for(int a = 0; a < 3; ++a)
    for(int b = 0; b < 3; ++b)
      T[3 * a + b] = x[0] * frame.e1[a] * frame.e1[b] + x[1] * (frame.e1[a] * frame.e2[b] + frame.e2[a] * frame.e1[b]) +
                     x[2] * frame.e2[a] * frame.e2[b];
  return T;
}

// The unit vertex normals (zero where the normal vanishes).
inline std::vector<std::array<double, 3> > curvature_unit_normals(const std::vector<std::array<double, 3> >& normals)
{
  std::vector<std::array<double, 3> > unit_normals(normals.size());
  for(std::size_t vi = 0; vi < normals.size(); ++vi)
  {
    const double l = std::sqrt(dot(normals[vi], normals[vi]));
    unit_normals[vi] = l > 0 ? std::array<double, 3>{ normals[vi][0] / l, normals[vi][1] / l, normals[vi][2] / l }
                             : std::array<double, 3>{ 0., 0., 0. };
  }
  return unit_normals;
}

// The normal-variation tensor of every face, from the unit vertex normals.
template <typename Bundle>
std::vector<std::array<double, 9> > normal_variation_face_tensors(const Bundle& bundle,
                                                                  const std::vector<std::array<double, 3> >& points,
                                                                  const std::vector<std::array<double, 3> >& unit_normals)
{
  typedef typename Bundle::halfedge_descriptor halfedge_descriptor;
  const auto& tm = bundle.mesh();
  const std::size_t nf = bundle.number_of_faces();
  std::vector<std::array<double, 9> > face_tensor(nf);
  for(std::size_t fi = 0; fi < nf; ++fi)
  {
    const halfedge_descriptor h = halfedge(bundle.face(fi), tm);
    const std::size_t c[3] = { bundle.index(source(h, tm)), bundle.index(target(h, tm)),
                               bundle.index(target(next(h, tm), tm)) };
    const std::array<double, 3> p[3] = { points[c[0]], points[c[1]], points[c[2]] };
    const std::array<double, 3> n[3] = { unit_normals[c[0]], unit_normals[c[1]], unit_normals[c[2]] };
    face_tensor[fi] = normal_variation_tensor(p, n, bundle.frame(fi));
  }
  return face_tensor;
}

// The fit of the vertex `vi` by the second estimator: the average of the
// tensors of its faces in its tangent plane, diagonalised, in Monge's sign.
// Returns false if a non-finite value comes out.
template <typename Bundle>
bool normal_variation_vertex_fit(const Bundle& bundle, std::size_t vi, const std::array<double, 3>& unit_normal,
                                 const std::vector<std::array<double, 9> >& face_tensor, int scale_exponent,
                                 Curvature_vertex_fit& fit)
{
  typedef typename Bundle::halfedge_descriptor halfedge_descriptor;
  const auto& tm = bundle.mesh();
  std::array<double, 9> T{};
  std::size_t count = 0;
  std::array<double, 3> normal = unit_normal;
  for(halfedge_descriptor h : CGAL::halfedges_around_target(bundle.vertex(vi), tm))
  {
    if(CGAL::is_border(h, tm))
      continue;
    const std::size_t fi = bundle.index(face(h, tm));
    for(int a = 0; a < 9; ++a)
      T[a] += face_tensor[fi][a];
    ++count;
    if(normal == std::array<double, 3>{ 0., 0., 0. })
      normal = bundle.frame(fi).normal;
  }
  // A frame (t1, t2) of the vertex's tangent plane, and T there.
  const std::array<double, 3> axis = std::abs(normal[0]) < 0.9 ? std::array<double, 3>{ 1., 0., 0. }
                                                               : std::array<double, 3>{ 0., 1., 0. };
  std::array<double, 3> t1 = cross(normal, axis);
  const double l1 = std::sqrt(dot(t1, t1));
  t1 = { t1[0] / l1, t1[1] / l1, t1[2] / l1 };
  const std::array<double, 3> t2 = cross(normal, t1);
  auto form = [&](const std::array<double, 3>& x, const std::array<double, 3>& y) {
    double value = 0;
    for(int a = 0; a < 3; ++a)
      for(int b = 0; b < 3; ++b)
        value += x[a] * T[3 * a + b] * y[b];
    return value / double((std::max)(count, std::size_t(1)));
  };
  const Symmetric_eigen_2 eigen = symmetric_eigen_2(form(t1, t1), form(t1, t2), form(t2, t2));
  const double cs = std::cos(eigen.angle), sn = std::sin(eigen.angle);
  fit.normal = normal;
  fit.d_max = { cs * t1[0] + sn * t2[0], cs * t1[1] + sn * t2[1], cs * t1[2] + sn * t2[2] };
  fit.d_min = cross(normal, fit.d_max);
  // In Monge's sign, the opposite of ours.
  fit.k_max = std::ldexp(-eigen.lambda_max, -scale_exponent);  // the points are scaled by 2^-scale_exponent
  fit.k_min = std::ldexp(-eigen.lambda_min, -scale_exponent);
  return curvature_all_finite(fit.d_max) && std::isfinite(fit.k_max) && std::isfinite(fit.k_min);
}

// The vertices whose fit failed (`fallback`): the normal-variation tensors of
// their faces, averaged in the vertex's tangent plane (zero on a flat region).
// Returns false if a non-finite value comes out.
template <typename Bundle>
bool fit_fallback_vertices(const Bundle& bundle, const std::vector<std::array<double, 3> >& points,
                           const Curvature_vertex_normals& normals, const std::vector<char>& fallback,
                           int scale_exponent, std::vector<Curvature_vertex_fit>& fits)
{
  const std::vector<std::array<double, 3> > unit_normals = curvature_unit_normals(normals.normal);
  const std::vector<std::array<double, 9> > face_tensor = normal_variation_face_tensors(bundle, points, unit_normals);
  for(std::size_t vi = 0; vi < bundle.number_of_vertices(); ++vi)
  {
    if(!normals.in_face[vi] || !fallback[vi])
      continue;
    if(!normal_variation_vertex_fit(bundle, vi, unit_normals[vi], face_tensor, scale_exponent, fits[vi]))
      return false;
  }
  return true;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_NORMAL_VARIATION_FALLBACK_H
