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
#include <CGAL/Polyvector_fields/internal/Frame_field_iterations.h>
#include <CGAL/Polyvector_fields/internal/angle_bound_projection.h>
#include <CGAL/Polyvector_fields/internal/field_access.h>
#include <CGAL/Polyvector_fields/internal/frame_field_setup.h>

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
};

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// designs a smooth frame field `{±u, ±v}` whose angle between `u` and `v`
/// is at least a bound `theta_min` in every face (paper, Section 4.2).
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
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`:
///         the two degrees of each global step are factored and solved in parallel with TBB (unless a constraint
///         gives a single vector, which couples the degrees into one system); the result does not depend on it
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam ConstraintRange a range of `Face_constraint<face_descriptor, Vector_3>` (at most 2 vectors each)
/// \tparam CoefficientMap a model of `WritablePropertyMap` from faces to `std::vector<std::complex<double>>`
///
/// \param tm the mesh
/// \param N the degree, which must be 4
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
///   \cgalParamNBegin{initial_lambda}
///     \cgalParamDescription{the first weight `lambda` of the global step, `> 0`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{100}
///   \cgalParamNEnd
///   \cgalParamNBegin{lambda_factor}
///     \cgalParamDescription{the factor of `lambda` at each iteration, `>= 1`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1.5}
///   \cgalParamNEnd
///   \cgalParamNBegin{tolerance}
///     \cgalParamDescription{how far below the bound, in radians, a face may stay at convergence, `>= 0`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1e-7}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the maximum number of global steps}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{200}
///   \cgalParamNEnd
///   \cgalParamNBegin{verbose}
///     \cgalParamDescription{print the progress of each iteration on `std::cerr`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class, model of `Kernel`}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{sparse_linear_solver}
///     \cgalParamDescription{a model of `SparseLinearAlgebraWithFactorTraits_d` on `std::complex<double>`}
///     \cgalParamDefault{`Default_sparse_solver`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `SUCCESS` (also when the iterations did not converge: see `result.converged`),
///          `NOT_A_FRAME_FIELD` if `N != 4` or `sign_symmetric(false)` is given, `INVALID_PARAMETER`
///          or `NON_FINITE_VALUE` for a bad parameter, or an error of `design_polyvector_field()`.
///          On failure `coefficient_map` is not written.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename TriangleMesh, typename ConstraintRange, typename CoefficientMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code design_angle_bounded_frame_field(const TriangleMesh& tm, std::size_t N, const ConstraintRange& constraints,
                                            CoefficientMap coefficient_map, Angle_bound_result& result,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef std::complex<double> Complex;

  const double theta_min = choose_parameter(get_parameter(np, internal_np::angle_bound), 70.0 * CGAL_PI / 180.0);
  const double tolerance = choose_parameter(get_parameter(np, internal_np::tolerance), 1e-7);
  internal::Local_global_parameters p;
  Error_code code = internal::read_local_global_parameters(np, 200, p);
  if(code != Error_code::SUCCESS)
    return code;
  if(!std::isfinite(theta_min) || !std::isfinite(tolerance))
    return Error_code::NON_FINITE_VALUE;
  if(!(theta_min > 0) || theta_min > CGAL_PI / 2 || !(tolerance >= 0))
    return Error_code::INVALID_PARAMETER;

  typedef internal::Frame_field_types<TriangleMesh, NamedParameters, ConcurrencyTag> Types;
  std::unique_ptr<typename Types::Designer> designer;
  code = internal::smooth_frame_field<ConcurrencyTag>(tm, N, constraints, np, designer);
  if(code != Error_code::SUCCESS)
    return code;
  const auto& connection = designer->connection();
  const std::size_t F = connection.number_of_faces();
  std::vector<Complex> c = designer->coefficient_array(), targets(4 * F);

  typename Types::Iterations iterations = Types::iterations(*designer, std::vector<double>(F, 1.0), 0.0);

  // Smallest frame angle over the faces that are not fixed, and over all faces.
  auto smallest_angles = [&](double& free_faces, double& all_faces) {
    free_faces = all_faces = std::numeric_limits<double>::infinity();
    for(std::size_t f = 0; f < F; ++f)
    {
      const auto uv = internal::frame_vectors(&c[4 * f]);
      const double a = internal::smallest_frame_angle(uv.first, uv.second);
      all_faces = (std::min)(all_faces, a);
      if(!iterations.is_fixed(f))
        free_faces = (std::min)(free_faces, a);
    }
  };

  Angle_bound_result r;
  double lambda = p.initial_lambda, free_angle, all_angle;
  smallest_angles(free_angle, all_angle);
  while(!(free_angle >= theta_min - tolerance) && r.iterations < p.maximum_iterations)
  {
    // Local step.
    for(std::size_t f = 0; f < F; ++f)
    {
      const auto uv = internal::frame_vectors(&c[4 * f]);
      const auto bounded = iterations.is_fixed(f) ? uv : internal::enforce_angle_bound(uv.first, uv.second, theta_min);
      internal::frame_coefficients(bounded.first, bounded.second, &targets[4 * f]);
    }
    // Global step.
    if(!iterations.global_step(lambda, targets, c))
      return Error_code::SOLVER_FAILURE;
    ++r.iterations;
    smallest_angles(free_angle, all_angle);
    if(p.verbose)
      std::cerr << "angle bound: iteration " << r.iterations << ", lambda " << lambda << ", smallest angle "
                << free_angle * 180 / CGAL_PI << " degrees\n";
    lambda *= p.lambda_factor;
  }
  r.converged = free_angle >= theta_min - tolerance;
  r.minimum_angle = all_angle;
  r.minimum_free_angle = free_angle;
  internal::write_coefficients(connection, 4, c, coefficient_map);
  result = r;
  return Error_code::SUCCESS;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_ANGLE_BOUNDED_FRAME_FIELD_H
