// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_ANGLE_BOUNDED_FRAME_FIELD_H
#define CGAL_POLYVECTOR_FIELDS_ANGLE_BOUNDED_FRAME_FIELD_H

/// \file angle_bounded_frame_field.h

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/Local_global_driver.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/angle_bound_projection.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// reports on a run of `design_angle_bounded_frame_field()`.
struct Angle_bound_result
{
  std::size_t iterations = 0;  ///< global steps done
  bool converged = false;      ///< every face that is not fixed by a hard full constraint is within the bound
  double minimum_angle = 0;    ///< smallest frame angle over all faces of the result, in radians
  double minimum_free_angle = 0;  ///< smallest frame angle over the faces not fixed by a hard full constraint
  std::size_t factorizations = 0;  ///< numerical factorizations of the global steps (one per new `lambda`; none at the cap)
};

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// designs, on a tangent bundle, a smooth frame field `{±u, ±v}` whose angle
/// between `u` and `v` is at least a bound `theta_min` in every face (paper,
/// Section 4.2).
///
/// Starting from the smoothest frame field that satisfies `constraints`, the
/// algorithm alternates a local step, which turns `u` and `v` of every face
/// symmetrically away from their bisector until their smallest angle reaches
/// `theta_min` (faces within the bound are left as they are), and a global
/// step, which finds the smoothest field close to the local one (Eq. 12,
/// weight `lambda`, multiplied by `lambda_factor` at each iteration) while
/// keeping the hard constraints. It stops when a global step leaves every face
/// within the bound, up to `tolerance`, or after `number_of_iterations` steps.
/// Faces fixed by a hard full constraint are not changed, even if the
/// constraint itself is below the bound (see `Angle_bound_result::minimum_angle`).
/// The user manual's section "Angle-bounded frame fields" states the local step.
///
/// \pvfFrameFieldTparams
///
/// \param mesh_or_bundle the tangent bundle of the mesh, or the mesh
/// \param constraints the constraints; each vector `u` stands for the pair `{u, -u}`
/// \param coefficient_map receives the 4 coefficients of each face
/// \param result receives the number of iterations and the angles reached
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{angle_bound}
///     \cgalParamDescription{the smallest allowed angle `theta_min` between `u` and `v`, in radians, in `(0, pi/2]`;
///                           given with `Polyvector_fields::parameters::angle_bound()`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{70 degrees}
///   \cgalParamNEnd
///   \cgalParamNBegin{tolerance}
///     \cgalParamDescription{how far below the bound, in radians, a face may stay at convergence, `>= 0`.
///                           The last fraction of a degree costs most of the iterations (on the Stanford bunny with
///                           20 random constraints and a 70-degree bound: 3 iterations to within 0.5 degree, 9 to
///                           within 0.06 degree, 32 to within 1e-7 radian)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.5 degree}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_lambda}
///     \cgalParamDescription{the largest weight `lambda` of the global step, `>= initial_lambda`; at the cap the
///                           factorization is reused}
///     \cgalParamType{`double`}
///     \cgalParamDefault{unbounded (the paper)}
///   \cgalParamNEnd
///   \pvfLocalGlobalParams{200}
/// \cgalNamedParamsEnd
///
/// \returns `SUCCESS` (also when the iterations did not converge: see `result.converged`),
///          `INVALID_PARAMETER` or `NON_FINITE_VALUE` for a bad parameter, or an error of
///          `Polyvector_field_designer::add_constraint()` and `Polyvector_field_designer::solve()`.
///          On failure `coefficient_map` and `result` are not written.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename Mesh_or_bundle, typename ConstraintRange, typename CoefficientMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code design_angle_bounded_frame_field(const Mesh_or_bundle& mesh_or_bundle, const ConstraintRange& constraints,
                                            CoefficientMap coefficient_map, Angle_bound_result& result,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  const double theta_min = choose_parameter(get_parameter(np, internal_np::angle_bound), 70.0 * CGAL_PI / 180.0);
  const double tolerance = choose_parameter(get_parameter(np, internal_np::tolerance), 0.5 * CGAL_PI / 180.0);
  internal::Local_global_parameters p;
  Error_code code = internal::read_local_global_parameters(np, 200, std::numeric_limits<double>::infinity(), p);
  if(code != Error_code::SUCCESS)
    return code;
  if(!std::isfinite(theta_min) || !std::isfinite(tolerance))
    return Error_code::NON_FINITE_VALUE;
  if(!(theta_min > 0) || theta_min > CGAL_PI / 2 || !(tolerance >= 0))
    return Error_code::INVALID_PARAMETER;

  const auto& bundle = internal::bundle_of(mesh_or_bundle, np);
  auto driver = internal::make_local_global_driver<ConcurrencyTag>(bundle, np);

  // The measure: the smallest frame angle over the free faces, and over all faces.
  Angle_bound_result r;
  auto converged = [&](const std::vector<std::complex<double> >& field, std::size_t iteration, double lambda) {
    r.minimum_free_angle = r.minimum_angle = std::numeric_limits<double>::infinity();
    for(std::size_t f = 0; f < bundle.number_of_faces(); ++f)
    {
      const auto uv = internal::frame_vectors(&field[4 * f]);
      const double a = internal::smallest_frame_angle(uv.first, uv.second);
      r.minimum_angle = (std::min)(r.minimum_angle, a);
      if(!driver.is_fixed(f))
        r.minimum_free_angle = (std::min)(r.minimum_free_angle, a);
    }
    if(p.verbose && iteration > 0)
      std::cerr << "angle bound: iteration " << iteration << ", lambda " << lambda
                << ", smallest angle " << r.minimum_free_angle * 180 / CGAL_PI << " degrees\n";
    return r.converged = r.minimum_free_angle >= theta_min - tolerance;
  };
  // The local step: u and v turned apart, symmetrically, up to the bound.
  auto local_step = [&](std::size_t, const std::complex<double>& u, const std::complex<double>& v) {
    return internal::enforce_angle_bound(u, v, theta_min);
  };
  return driver.design(constraints, std::vector<double>(bundle.number_of_faces(), 1.0), 0.0, p, local_step,
                       converged, coefficient_map, r, result);
}

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// designs the angle-bounded frame field as the other overload, without a report.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename Mesh_or_bundle, typename ConstraintRange, typename CoefficientMap,
          typename T = bool, typename Tag = CGAL::internal_np::all_default_t, typename Base = CGAL::internal_np::No_property>
Error_code design_angle_bounded_frame_field(const Mesh_or_bundle& mesh_or_bundle, const ConstraintRange& constraints,
                                            CoefficientMap coefficient_map,
                                            const CGAL::Named_function_parameters<T, Tag, Base>& np = CGAL::parameters::default_values())
{
  Angle_bound_result result;
  return design_angle_bounded_frame_field<ConcurrencyTag>(mesh_or_bundle, constraints, coefficient_map, result, np);
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_ANGLE_BOUNDED_FRAME_FIELD_H
