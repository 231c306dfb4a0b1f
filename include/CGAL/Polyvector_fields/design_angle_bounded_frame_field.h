// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_DESIGN_ANGLE_BOUNDED_FRAME_FIELD_H
#define CGAL_POLYVECTOR_FIELDS_DESIGN_ANGLE_BOUNDED_FRAME_FIELD_H

/// \file design_angle_bounded_frame_field.h

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/angle_bound_optimization.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// reports on a run of `design_angle_bounded_frame_field()`.
struct Angle_bound_result
{
  std::size_t iterations = 0;  ///< global steps done
  bool converged = false;      ///< the iterations brought every free face (not fixed by a hard full constraint) to within `tolerance` of the bound, and the final projection to the bound
  double minimum_angle = 0;    ///< smallest frame angle over all faces of the result, in radians
  double minimum_free_angle = 0;  ///< smallest frame angle over the free faces of the result (after the final projection), in radians: at least the bound (up to 1e-12 radian of rounding) when the function succeeds
  double minimum_free_angle_before_projection = 0;  ///< smallest frame angle over the free faces after the last global step, before the final projection, in radians
  std::size_t projected_faces = 0;  ///< free faces below the bound after the iterations, turned onto it by the final projection
  std::size_t factorizations = 0;  ///< numerical factorizations of the global steps (one per new `lambda`; none at the cap)
};

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// optimizes a frame field `{±u, ±v}` in place so that its angle
/// between `u` and `v` is at least a bound `theta_min` in every face (paper,
/// Section 4.2).
///
/// Starting from `field` (typically the smooth field of
/// `Polyvector_field_designer::solve()`), the algorithm alternates a local step, which turns `u` and `v` of every face
/// symmetrically away from their bisector until their smallest angle reaches
/// `theta_min` (faces within the bound are left as they are), and a global
/// step, which finds the smoothest field close to the local one (Eq. 12,
/// weight `lambda`, multiplied by `lambda_factor` at each iteration) while
/// keeping the hard constraints of the design of `field`. It stops when a global step leaves every face
/// within the bound, up to `tolerance`, or after `number_of_iterations` steps.
/// Then every free face still below the bound (by at most `tolerance`) is projected onto it
/// exactly, as the local step does; on a face held by a hard partial constraint, the
/// constrained vector stays and the other one turns. So on success every free face has a frame
/// angle of at least `theta_min` (up to 1e-12 radian of rounding, see
/// `Angle_bound_result::minimum_free_angle`); the function never returns `SUCCESS` otherwise.
/// Faces fixed by a hard full constraint are not changed, even if the
/// constraint itself is below the bound (see `Angle_bound_result::minimum_angle`).
/// The user manual's section "Angle-bounded frame fields" states the local step.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`:
///         the degrees of each global step are factored and solved in parallel with TBB; the result does not depend on it
/// \tparam TangentBundle the tangent bundle type of the field
///
/// \param field a frame field (degree 4, sign-symmetric); on success, and when the iterations did not
///        converge, it receives the optimized field
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
///     \cgalParamDescription{how far below the bound, in radians, the iterations may leave a free face before
///                           the final projection turns it onto the bound, `>= 0`: it trades smoothness near
///                           the bound for iterations, never the bound itself.
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
/// \returns `SUCCESS` (every free face at or above the bound); `DID_NOT_CONVERGE` when some free face is still
///          more than `tolerance` below the bound after the iterations (then `field` and `result` hold the field
///          of the last step, not projected, and its report);
///          `NOT_A_FRAME_FIELD` if `field` is not a frame field; `INVALID_PARAMETER` or `NON_FINITE_VALUE`
///          for a bad parameter; or `SOLVER_FAILURE`. On any other failure `field` and `result` are not written.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TangentBundle,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code design_angle_bounded_frame_field(Polyvector_field<TangentBundle>& field, Angle_bound_result& result,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::Angle_bound_parameters p;
  const Error_code code = internal::read_angle_bound_parameters(np, p);
  if(code != Error_code::SUCCESS)
    return code;
  return internal::optimize_in_place(field, result, [&](Polyvector_field<TangentBundle>& optimized, Angle_bound_result& r) {
    return internal::optimize_angle_bounded_field<ConcurrencyTag>(optimized, p, np, r);
  });
}

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// designs, on a tangent bundle or a mesh, the smoothest frame field that
/// satisfies `constraints` (with `Polyvector_field_designer`, the solver and
/// the smoothness weights of `np`), then bounds its angles with the other
/// overload, and writes it into `coefficient_map`.
///
/// \pvfFrameFieldTparams
///
/// \param mesh_or_bundle the tangent bundle of the mesh, or the mesh
/// \param constraints the constraints; each vector `u` stands for the pair `{u, -u}`
/// \param coefficient_map receives the 4 coefficients of each face
/// \param result receives the number of iterations and the angles reached
/// \param np the named parameters of the other overload
///
/// \returns as the other overload, and an error of `Polyvector_field_designer::add_constraint()` and
///          `Polyvector_field_designer::solve()`. `coefficient_map` and `result` are written when the other
///          overload writes its field and report.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename Mesh_or_bundle, typename ConstraintRange, typename CoefficientMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code design_angle_bounded_frame_field(const Mesh_or_bundle& mesh_or_bundle, const ConstraintRange& constraints,
                                            CoefficientMap coefficient_map, Angle_bound_result& result,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  // The parameters first: a bad one is reported before any design.
  internal::Angle_bound_parameters p;
  const Error_code code = internal::read_angle_bound_parameters(np, p);
  if(code != Error_code::SUCCESS)
    return code;
  return internal::design_then_optimize<ConcurrencyTag>(
    mesh_or_bundle, constraints, coefficient_map, np,
    [&](auto& field) { return design_angle_bounded_frame_field<ConcurrencyTag>(field, result, np); });
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

#endif // CGAL_POLYVECTOR_FIELDS_DESIGN_ANGLE_BOUNDED_FRAME_FIELD_H
