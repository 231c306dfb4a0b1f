// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_FRAME_FIELD_MEASURES_H
#define CGAL_POLYVECTOR_FIELDS_FRAME_FIELD_MEASURES_H

/// \file frame_field_measures.h
/// Per-face measures of frame fields: the angle between `u` and `v`, and the deviation from conjugacy.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/Principal_curvatures.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/angle_bound_projection.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/conjugacy_projection.h>
#include <CGAL/Polyvector_fields/internal/field_access.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/frame_field_polynomial.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <complex>
#include <array>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

namespace internal {

// SUCCESS for a field of degree 4 on a valid bundle, the reason otherwise.
template <typename TangentBundle>
Error_code check_frame_field(const Polyvector_field<TangentBundle>& field)
{
  if(field.tangent_bundle().status() != Error_code::SUCCESS)
    return field.tangent_bundle().status();
  return field.degree() == 4 ? Error_code::SUCCESS : Error_code::NOT_A_FRAME_FIELD;
}

} // namespace internal

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// computes, for every face of the frame field `field`, the smallest angle
/// between two of its vectors, in radians, in `[0, pi/2]`.
///
/// \tparam AngleMap a model of `WritablePropertyMap` from faces to `double`
///
/// \returns `SUCCESS`, the bundle's error, or `NOT_A_FRAME_FIELD` if `field` is not of degree 4; nothing is written on failure.
template <typename TangentBundle, typename AngleMap>
Error_code compute_frame_angles(const Polyvector_field<TangentBundle>& field, AngleMap angle_map)
{
  const Error_code code = internal::check_frame_field(field);
  if(code != Error_code::SUCCESS)
    return code;
  const TangentBundle& bundle = field.tangent_bundle();
  const std::vector<std::complex<double> >& c = field.coefficients();
  for(std::size_t f = 0; f < bundle.number_of_faces(); ++f)
  {
    const auto uv = internal::frame_vectors(&c[4 * f]);
    put(angle_map, bundle.face(f), internal::smallest_frame_angle(uv.first, uv.second));
  }
  return Error_code::SUCCESS;
}

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// computes, for every face of the frame field `field`, its deviation from
/// conjugacy `|u^T S v| / (|u| |v| max(|k1|, |k2|))`, as the overload that
/// takes a coefficient map does.
///
/// \tparam CurvatureMap a model of `ReadablePropertyMap` from faces to `Principal_curvatures<Vector_3>`
/// \tparam DeviationMap a model of `WritablePropertyMap` from faces to `double`
///
/// \returns as `compute_frame_angles()`, and `NON_FINITE_VALUE` for a non-finite curvature; nothing is
///          written on failure.
template <typename TangentBundle, typename CurvatureMap, typename DeviationMap>
Error_code compute_conjugacy_deviation(const Polyvector_field<TangentBundle>& field, CurvatureMap curvature_map,
                                       DeviationMap deviation_map)
{
  using boost::get;
  const Error_code code = internal::check_frame_field(field);
  if(code != Error_code::SUCCESS)
    return code;
  const TangentBundle& bundle = field.tangent_bundle();
  const std::vector<std::complex<double> >& c = field.coefficients();
  std::vector<double> deviation(bundle.number_of_faces());
  for(std::size_t f = 0; f < bundle.number_of_faces(); ++f)
  {
    const auto pc = get(curvature_map, bundle.face(f));
    const std::array<double, 4> S = shape_operator(pc, bundle.frame(f));
    const double k = (std::max)(std::abs(pc.k1), std::abs(pc.k2));
    if(!std::isfinite(k) || !std::isfinite(S[0]) || !std::isfinite(S[1]) || !std::isfinite(S[3]))
      return Error_code::NON_FINITE_VALUE;
    const auto uv = internal::frame_vectors(&c[4 * f]);
    const double scale = std::abs(uv.first) * std::abs(uv.second) * k;
    deviation[f] = scale > 0 ? std::abs(internal::conjugacy_residual(S, uv.first, uv.second)) / scale : 0.0;
  }
  for(std::size_t f = 0; f < bundle.number_of_faces(); ++f)
    put(deviation_map, bundle.face(f), deviation[f]);
  return Error_code::SUCCESS;
}

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// computes, for every face of a frame field `{±u, ±v}` on a tangent bundle
/// or a mesh, the smallest angle between two of its vectors, in radians, in
/// `[0, pi/2]`.
///
/// \tparam Mesh_or_bundle a `Tangent_bundle`, or a model of `FaceListGraph` (whose bundle is then built
///         with the named parameter `vertex_point_map`)
/// \tparam CoefficientMap a model of `ReadablePropertyMap` from faces to `std::vector<std::complex<double>>` of size 4
/// \tparam AngleMap a model of `WritablePropertyMap` from faces to `double`
///
/// \returns `SUCCESS`, a mesh error, `INCONSISTENT_DEGREE` (a coefficient vector not of size 4) or
///          `NON_FINITE_VALUE`; nothing is written on failure.
template <typename Mesh_or_bundle, typename CoefficientMap, typename AngleMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code compute_frame_angles(const Mesh_or_bundle& mesh_or_bundle, CoefficientMap coefficient_map, AngleMap angle_map,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto& bundle = internal::bundle_of(mesh_or_bundle, np);
  Polyvector_field<std::decay_t<decltype(bundle)> > field(bundle, 4, true);
  const Error_code code = field.read_coefficients(coefficient_map);
  if(code != Error_code::SUCCESS)
    return code;
  return compute_frame_angles(field, angle_map);
}

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// computes, for every face of a frame field `{±u, ±v}` on a tangent bundle
/// or a mesh, its deviation from conjugacy `|u^T S v| / (|u| |v| max(|k1|, |k2|))`,
/// a number in `[0, 1]` that does not depend on the lengths of `u` and `v` nor
/// on the size of the mesh; it is 0 where `u` and `v` are conjugate (and where
/// the face is flat).
///
/// \tparam Mesh_or_bundle a `Tangent_bundle`, or a model of `FaceListGraph` (whose bundle is then built
///         with the named parameter `vertex_point_map`)
/// \tparam CoefficientMap a model of `ReadablePropertyMap` from faces to `std::vector<std::complex<double>>` of size 4
/// \tparam CurvatureMap a model of `ReadablePropertyMap` from faces to `Principal_curvatures<Vector_3>`
/// \tparam DeviationMap a model of `WritablePropertyMap` from faces to `double`
///
/// \returns as `compute_frame_angles()`, and `NON_FINITE_VALUE` for a non-finite curvature; nothing is written on failure.
template <typename Mesh_or_bundle, typename CoefficientMap, typename CurvatureMap, typename DeviationMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code compute_conjugacy_deviation(const Mesh_or_bundle& mesh_or_bundle, CoefficientMap coefficient_map,
                                       CurvatureMap curvature_map, DeviationMap deviation_map,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto& bundle = internal::bundle_of(mesh_or_bundle, np);
  Polyvector_field<std::decay_t<decltype(bundle)> > field(bundle, 4, true);
  const Error_code code = field.read_coefficients(coefficient_map);
  if(code != Error_code::SUCCESS)
    return code;
  return compute_conjugacy_deviation(field, curvature_map, deviation_map);
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_FRAME_FIELD_MEASURES_H
