// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_FACE_PRINCIPAL_CURVATURES_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_FACE_PRINCIPAL_CURVATURES_H

// The principal curvatures of the faces, as estimate_principal_curvatures()
// documents them: the jet fits of the vertices (the normal-variation estimator
// where a fit fails), rotated into each face plane, averaged and diagonalised.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/internal/Curvature/curvature_tensor.h>
#include <CGAL/Polyvector_fields/internal/Curvature/normal_variation_fallback.h>
#include <CGAL/Polyvector_fields/internal/Curvature/vertex_jet_fits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The curvature of the face of index `fi`: the tensors of its three vertices
// averaged in the face frame, diagonalised. Returns false if a non-finite
// value comes out.
template <typename Bundle, typename Curvature_value>
bool average_face_curvature(const Bundle& bundle, const std::vector<Curvature_vertex_fit>& fits, std::size_t fi,
                            Curvature_value& value)
{
  typedef typename Bundle::halfedge_descriptor halfedge_descriptor;
  typedef std::decay_t<decltype(std::declval<Curvature_value&>().d1)> Output_vector;
  const auto& tm = bundle.mesh();
  const Face_frame& frame = bundle.frame(fi);
  const halfedge_descriptor h = halfedge(bundle.face(fi), tm);
  const std::size_t corners[3] = { bundle.index(source(h, tm)), bundle.index(target(h, tm)),
                                   bundle.index(target(next(h, tm), tm)) };
  double s00 = 0., s01 = 0., s11 = 0.;
  for(std::size_t vi : corners)
  {
    const Curvature_vertex_fit& fit = fits[vi];
    // Monge's sign is the opposite of ours: our tensor is -(k_max d_max d_max^T + k_min d_min d_min^T).
    const std::pair<double, const std::array<double, 3>*> terms[2] = { { -fit.k_max, &fit.d_max },
                                                                        { -fit.k_min, &fit.d_min } };
    for(const auto& term : terms)
    {
      const std::array<double, 3> d = curvature_rotate(*term.second, fit.normal, frame.normal, frame.e1);
      const double x = dot(d, frame.e1), y = dot(d, frame.e2);
      s00 += term.first * x * x;
      s01 += term.first * x * y;
      s11 += term.first * y * y;
    }
  }
  const Symmetric_eigen_2 eigen = symmetric_eigen_2(s00 / 3., s01 / 3., s11 / 3.);
  const double c = std::cos(eigen.angle), s = std::sin(eigen.angle);
  const std::array<double, 3> d1 = { c * frame.e1[0] + s * frame.e2[0], c * frame.e1[1] + s * frame.e2[1],
                                     c * frame.e1[2] + s * frame.e2[2] };
  const std::array<double, 3> d2 = cross(frame.normal, d1);
  if(!std::isfinite(eigen.lambda_max) || !std::isfinite(eigen.lambda_min) || !curvature_all_finite(d1)
     || !curvature_all_finite(d2))
    return false;

  value.k1 = eigen.lambda_max;
  value.k2 = eigen.lambda_min;
  value.d1 = Output_vector(d1[0], d1[1], d1[2]);
  value.d2 = Output_vector(d2[0], d2[1], d2[2]);
  return true;
}

// Curvatures below this over the bounding-box diagonal are those of a plane
// (see estimate_face_principal_curvatures()).
constexpr double flat_curvature_tolerance = 1e-6;

// The principal curvatures of every face of a valid bundle, in the order of
// its face numbering, and the number of vertices estimated by the fallback.
// Returns SUCCESS or CURVATURE_ESTIMATION_FAILED (then `values` is undefined).
// With `CGAL::Parallel_tag`, the jet fits and the faces are shared among
// threads; the result is the same.
template <typename ConcurrencyTag, typename Bundle, typename Curvature_value>
Error_code estimate_face_principal_curvatures(const Bundle& bundle, const Curvature_fit_settings& settings,
                                              std::vector<Curvature_value>& values, std::size_t& fallbacks)
{
  const std::size_t nv = bundle.number_of_vertices();
  const std::size_t nf = bundle.number_of_faces();

  std::vector<std::array<double, 3> > points;
  const int scale_exponent = curvature_scaled_points(bundle, points);
  Curvature_vertex_normals normals;
  curvature_vertex_normals(bundle, points, normals);

  std::vector<Curvature_vertex_fit> fits;
  std::vector<char> fallback;
  fit_vertex_jets<ConcurrencyTag>(bundle, points, normals, scale_exponent, settings, fits, fallback);

  fallbacks = 0;
  for(std::size_t vi = 0; vi < nv; ++vi)
    fallbacks += (normals.in_face[vi] && fallback[vi]) ? 1 : 0;
  if(fallbacks > 0 && !fit_fallback_vertices(bundle, points, normals, fallback, scale_exponent, fits))
    return Error_code::CURVATURE_ESTIMATION_FAILED;

  std::vector<Curvature_value>(nf).swap(values);
  std::vector<char> finite(nf, 1);
  for_each_range<ConcurrencyTag>(nf, 4096, [&](std::size_t begin, std::size_t end) {
    for(std::size_t fi = begin; fi < end; ++fi)
      finite[fi] = average_face_curvature(bundle, fits, fi, values[fi]) ? 1 : 0;
  });
  if(std::find(finite.begin(), finite.end(), 0) != finite.end())
    return Error_code::CURVATURE_ESTIMATION_FAILED;

  // Flat faces: a curvature radius above 1/flat_curvature_tolerance times the
  // bounding-box diagonal is the round-off of the fit on a plane, whose
  // directions mean nothing; both curvatures are then exactly 0.
  std::array<double, 3> lo = { 0, 0, 0 }, hi = { 0, 0, 0 };
  for(std::size_t vi = 0; vi < nv; ++vi)
    for(int k = 0; k < 3; ++k)
    {
      const double x = bundle.point(vi)[std::size_t(k)];
      lo[std::size_t(k)] = vi == 0 ? x : (std::min)(lo[std::size_t(k)], x);
      hi[std::size_t(k)] = vi == 0 ? x : (std::max)(hi[std::size_t(k)], x);
    }
  // (hypot: no underflow or overflow of the squares, whatever the scale of the mesh)
  const double diagonal = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  for(Curvature_value& value : values)
    if(std::abs(value.k1) * diagonal < flat_curvature_tolerance && std::abs(value.k2) * diagonal < flat_curvature_tolerance)
      value.k1 = value.k2 = 0;
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_FACE_PRINCIPAL_CURVATURES_H
