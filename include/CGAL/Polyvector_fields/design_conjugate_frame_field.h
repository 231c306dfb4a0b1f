// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_DESIGN_CONJUGATE_FRAME_FIELD_H
#define CGAL_POLYVECTOR_FIELDS_DESIGN_CONJUGATE_FRAME_FIELD_H

/// \file design_conjugate_frame_field.h

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Principal_curvatures.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/conjugate_field_optimization.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <limits>
#include <array>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// the stopping rules of `design_conjugate_frame_field()`.
enum class Conjugacy_stopping_rule
{
  /// the mean normalised deviation `|u^T S v| / (|u| |v| max(|k1|, |k2|))` over
  /// the free faces, weighted by `Khat_f` as the conjugacy term of Eq. 16 weighs them, is at most `tolerance`
  /// (default `5e-3`): a number without units, the same on every mesh
  MEAN_DEVIATION,
  /// the paper's rule: the sum of `|u^T S v|` over the free faces, on the field
  /// scaled to unit root mean square length, is below `tolerance` (default
  /// `1e-4`); it grows stricter with the number of faces and the curvature
  RESIDUAL_SUM
};

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// the defaults of the named parameters of `design_conjugate_frame_field()`
/// that depend on its stopping rule.
struct Conjugate_field_defaults
{
  double tolerance;              ///< `tolerance`
  double maximum_lambda;         ///< `maximum_lambda`
  std::size_t iterations;        ///< `number_of_iterations`
};

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// returns the defaults of `design_conjugate_frame_field()` for `rule`: with
/// the mean deviation, a tolerance of `5e-3`, `lambda` capped at `1e4` and 50
/// iterations at most; with the paper's residual sum, its tolerance `1e-4`,
/// no cap and 100 iterations.
inline Conjugate_field_defaults conjugate_field_defaults(Conjugacy_stopping_rule rule)
{
  if(rule == Conjugacy_stopping_rule::RESIDUAL_SUM)
    return { 1e-4, std::numeric_limits<double>::infinity(), 100 };
  return { 5e-3, 1e4, 50 };
}

namespace internal {

// The named parameters of design_conjugate_frame_field(), with its rules and defaults.
template <typename NamedParameters>
Error_code read_conjugate_field_parameters(const NamedParameters& np, Conjugate_field_parameters& p)
{
  return read_conjugate_field_parameters(np, Conjugacy_stopping_rule::MEAN_DEVIATION,
                                         Conjugacy_stopping_rule::RESIDUAL_SUM, &conjugate_field_defaults, p);
}

} // namespace internal

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// reports on a run of `design_conjugate_frame_field()`. Residuals are sums
/// over faces of `|u^T S v|`, measured on the field rescaled so that the root
/// mean square length of its vectors is 1 (`scale` is that factor); deviations
/// are the normalised `|u^T S v| / (|u| |v| max(|k1|, |k2|))` of
/// `compute_conjugacy_deviation()`.
struct Conjugate_field_result
{
  std::size_t iterations = 0;          ///< global steps done
  bool converged = false;              ///< the stopping rule was met
  double mean_deviation = 0;           ///< mean deviation over the free faces, weighted by `Khat_f` (the weight of their conjugacy term)
  std::vector<double> deviation_history;  ///< `mean_deviation` before the first step and after each step
  std::vector<double> residual_history;  ///< the free-face residual before the first step and after each step
  double residual = 0;                 ///< over all faces
  double free_residual = 0;            ///< over the faces not fixed by a hard full constraint
  double constrained_residual = 0;     ///< over the faces fixed by a hard full constraint
  double scale = 1;                    ///< the factor applied to the vectors when measuring residuals
  double final_lambda = 0;             ///< the weight `lambda` of the last global step
  std::size_t factorizations = 0;      ///< numerical factorizations of the global steps (one per new `lambda`; none at the cap)
};


/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// optimizes a frame field `{±u, ±v}` in place so that its vectors
/// are conjugate with respect to the surface's second fundamental form,
/// `u^T S v = 0` in every face (paper, Section 4.3 and Appendix A): the
/// directions that planar-quad meshes follow.
///
/// Starting from `field` (typically the smooth field of
/// `Polyvector_field_designer::solve()`), the algorithm alternates a local step, which projects `(u, v)` of each face onto
/// the quadric `u^T S v = 0` (the closest conjugate pair; the user manual's
/// section "Conjugate frame fields" states the projection), and a global step,
/// which finds the smoothest field close to the local one with weights
/// `lambda * Khat_f` (Eq. 16, `Khat_f = |k1 k2|` normalised to `[0, 1]`) plus the
/// orthogonality term `w |c_2|^2` (Eq. 17), keeping the hard constraints of the design of `field`.
/// `lambda` is multiplied by `lambda_factor` at each iteration, up to
/// `maximum_lambda`; from there on the matrix no longer changes, and each
/// iteration reuses its factorization (one solve). By default it stops when
/// the mean normalised deviation `|u^T S v| / (|u| |v| max(|k1|, |k2|))` over
/// the free faces, weighted by `Khat_f`, is at most `tolerance`
/// (`Conjugacy_stopping_rule::MEAN_DEVIATION`), a test without units that
/// means the same on every mesh; the paper's rule, the sum of `|u^T S v|` on
/// the field scaled to unit size, is `Conjugacy_stopping_rule::RESIDUAL_SUM`.
/// It also stops after `number_of_iterations` steps. The user manual's section
/// "Conjugate frame fields" gives the reasons for the defaults and what a
/// tolerance means for the planarity of quads.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`:
///         the degrees of each global step are factored and solved in parallel with TBB; the result does not depend on it
/// \tparam TangentBundle the tangent bundle type of the field
///
/// \param field a frame field (degree 4, sign-symmetric); on success, and when the iterations did not
///        converge, it receives the optimized field
/// \param result receives the report
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{principal_curvature_map}
///     \cgalParamDescription{the curvature of each face, given with `Polyvector_fields::parameters::principal_curvature_map()`;
///                           a model of `ReadablePropertyMap` from faces to `Principal_curvatures<Vector_3>`}
///     \cgalParamDefault{estimated by `estimate_principal_curvatures()` with the named parameters given here
///                       (`degree_fitting`, `degree_monge`, `ring_size`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{orthogonality_weight}
///     \cgalParamDescription{the weight `w >= 0` of the orthogonality term}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{stopping_rule}
///     \cgalParamDescription{when the iterations stop: a `Conjugacy_stopping_rule`}
///     \cgalParamDefault{`Conjugacy_stopping_rule::MEAN_DEVIATION`}
///   \cgalParamNEnd
///   \cgalParamNBegin{tolerance}
///     \cgalParamDescription{the tolerance of the stopping rule, `> 0`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`5e-3` for the mean deviation, `1e-4` for the paper's residual sum}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_lambda}
///     \cgalParamDescription{the largest weight `lambda` of the global step, `>= initial_lambda`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e4` with the mean deviation; unbounded (the paper) with the residual sum}
///   \cgalParamNEnd
///   \pvfLocalGlobalParams{50 with the mean deviation\, 100 with the residual sum}
/// \cgalNamedParamsEnd
///
/// \returns `SUCCESS`; `DID_NOT_CONVERGE` when the stopping rule was not met within the iterations (then
///          `field` and `result` hold the field of the last step and its report); `NOT_A_FRAME_FIELD`
///          if `field` is not a frame field; `INVALID_PARAMETER` or `NON_FINITE_VALUE` for a bad parameter
///          or curvature; an error of `estimate_principal_curvatures()`; or `SOLVER_FAILURE`. On any
///          other failure `field` and `result` are not written.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TangentBundle,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code design_conjugate_frame_field(Polyvector_field<TangentBundle>& field, Conjugate_field_result& result,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::Conjugate_field_parameters p;
  Error_code code = internal::read_conjugate_field_parameters(np, p);
  if(code != Error_code::SUCCESS)
    return code;
  return internal::optimize_in_place(field, result, [&](Polyvector_field<TangentBundle>& optimized,
                                                        Conjugate_field_result& r) {
    std::vector<std::array<double, 4> > S;
    std::vector<double> Khat, kmax;
    const Error_code curvature = internal::face_curvature_of<ConcurrencyTag>(optimized.tangent_bundle(), np, S, Khat, kmax);
    if(curvature != Error_code::SUCCESS)
      return curvature;
    return internal::optimize_conjugate_field<ConcurrencyTag>(optimized, S, Khat, kmax, p, np, r);
  });
}

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// designs, on a tangent bundle or a mesh, the smoothest frame field that
/// satisfies `constraints` (with `Polyvector_field_designer`, the solver and
/// the smoothness weights of `np`), then makes it conjugate with the other
/// overload, and writes it into `coefficient_map`.
///
/// \pvfFrameFieldTparams
///
/// \returns as the other overload, and an error of `Polyvector_field_designer::add_constraint()` and
///          `Polyvector_field_designer::solve()`. `coefficient_map` and `result` are written when the other
///          overload writes its field and report.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename Mesh_or_bundle, typename ConstraintRange, typename CoefficientMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code design_conjugate_frame_field(const Mesh_or_bundle& mesh_or_bundle, const ConstraintRange& constraints,
                                        CoefficientMap coefficient_map, Conjugate_field_result& result,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  // The parameters first: a bad one is reported before any design.
  internal::Conjugate_field_parameters p;
  const Error_code code = internal::read_conjugate_field_parameters(np, p);
  if(code != Error_code::SUCCESS)
    return code;
  return internal::design_then_optimize<ConcurrencyTag>(
    mesh_or_bundle, constraints, coefficient_map, np,
    [&](auto& field) { return design_conjugate_frame_field<ConcurrencyTag>(field, result, np); });
}

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// designs the conjugate frame field as the other overload, without a report.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename Mesh_or_bundle, typename ConstraintRange, typename CoefficientMap,
          typename T = bool, typename Tag = CGAL::internal_np::all_default_t, typename Base = CGAL::internal_np::No_property>
Error_code design_conjugate_frame_field(const Mesh_or_bundle& mesh_or_bundle, const ConstraintRange& constraints,
                                        CoefficientMap coefficient_map,
                                        const CGAL::Named_function_parameters<T, Tag, Base>& np = CGAL::parameters::default_values())
{
  Conjugate_field_result result;
  return design_conjugate_frame_field<ConcurrencyTag>(mesh_or_bundle, constraints, coefficient_map, result, np);
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_DESIGN_CONJUGATE_FRAME_FIELD_H
