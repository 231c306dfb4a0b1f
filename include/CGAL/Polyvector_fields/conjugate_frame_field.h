// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_CONJUGATE_FRAME_FIELD_H
#define CGAL_POLYVECTOR_FIELDS_CONJUGATE_FRAME_FIELD_H

/// \file conjugate_frame_field.h

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Principal_curvatures.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/Local_global_driver.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/conjugacy_projection.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <type_traits>
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

namespace internal {

// Shape operators in the face frames and the normalised |K| of every face.
template <typename Bundle, typename CurvatureMap>
Error_code face_shape_operators(const Bundle& bundle, CurvatureMap curvatures, std::vector<std::array<double, 4> >& S,
                                std::vector<double>& normalised_gaussian, std::vector<double>& largest_curvature)
{
  using boost::get;
  const std::size_t F = bundle.number_of_faces();
  S.resize(F);
  normalised_gaussian.resize(F);
  largest_curvature.resize(F);
  double largest = 0;
  for(std::size_t f = 0; f < F; ++f)
  {
    const auto pc = get(curvatures, bundle.face(f));
    S[f] = shape_operator(pc, bundle.frame(f));
    for(double x : S[f])
      if(!std::isfinite(x))
        return Error_code::NON_FINITE_VALUE;
    normalised_gaussian[f] = std::abs(pc.k1 * pc.k2);
    largest_curvature[f] = (std::max)(std::abs(pc.k1), std::abs(pc.k2));
    largest = (std::max)(largest, normalised_gaussian[f]);
  }
  for(double& k : normalised_gaussian)
    k = largest > 0 ? k / largest : 0.0;
  return Error_code::SUCCESS;
}

} // namespace internal

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// designs, on a tangent bundle, a smooth frame field `{±u, ±v}` whose vectors
/// are conjugate with respect to the surface's second fundamental form,
/// `u^T S v = 0` in every face (paper, Section 4.3 and Appendix A): the
/// directions that planar-quad meshes follow.
///
/// Starting from the smoothest frame field that satisfies `constraints`, the
/// algorithm alternates a local step, which projects `(u, v)` of each face onto
/// the quadric `u^T S v = 0` (the closest conjugate pair; the user manual's
/// section "Conjugate frame fields" states the projection), and a global step,
/// which finds the smoothest field close to the local one with weights
/// `lambda * Khat_f` (Eq. 16, `Khat_f = |k1 k2|` normalised to `[0, 1]`) plus the
/// orthogonality term `w |c_2|^2` (Eq. 17), keeping the hard constraints.
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
/// \pvfFrameFieldTparams
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
/// \returns `SUCCESS` (also when the iterations did not converge: see `result.converged`),
///          `INVALID_PARAMETER` or `NON_FINITE_VALUE` for a bad parameter or curvature, an error of
///          `estimate_principal_curvatures()`, or an error of `Polyvector_field_designer::add_constraint()`
///          and `Polyvector_field_designer::solve()`. On failure `coefficient_map` and `result` are not written.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename Mesh_or_bundle, typename ConstraintRange, typename CoefficientMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code design_conjugate_frame_field(const Mesh_or_bundle& mesh_or_bundle, const ConstraintRange& constraints,
                                        CoefficientMap coefficient_map, Conjugate_field_result& result,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  typedef std::complex<double> Complex;

  const double orthogonality = choose_parameter(get_parameter(np, internal_np::orthogonality_weight), 0.0);
  const Conjugacy_stopping_rule rule =
    choose_parameter(get_parameter(np, internal_np::stopping_rule), Conjugacy_stopping_rule::MEAN_DEVIATION);
  const bool paper_rule = rule == Conjugacy_stopping_rule::RESIDUAL_SUM;
  const Conjugate_field_defaults defaults = conjugate_field_defaults(rule);
  const double tolerance = choose_parameter(get_parameter(np, internal_np::tolerance), defaults.tolerance);
  internal::Local_global_parameters p;
  Error_code code = internal::read_local_global_parameters(np, defaults.iterations, defaults.maximum_lambda, p);
  if(code != Error_code::SUCCESS)
    return code;
  if(!std::isfinite(orthogonality) || !std::isfinite(tolerance))
    return Error_code::NON_FINITE_VALUE;
  if(!(orthogonality >= 0) || !(tolerance > 0))
    return Error_code::INVALID_PARAMETER;

  const auto& bundle = internal::bundle_of(mesh_or_bundle, np);
  typedef std::decay_t<decltype(bundle)> Bundle;
  typedef typename CGAL::GetGeomTraits<typename Bundle::Triangle_mesh, NamedParameters>::type Geom_traits;
  auto driver = internal::make_local_global_driver<ConcurrencyTag>(bundle, np);
  // Curvature: given, or estimated.
  std::vector<std::array<double, 4> > S;
  std::vector<double> Khat, kmax;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::principal_curvature_map_t>::value)
    code = internal::face_shape_operators(bundle, get_parameter(np, internal_np::principal_curvature_map), S, Khat, kmax);
  else
  {
    std::map<typename Bundle::face_descriptor, Principal_curvatures<typename Geom_traits::Vector_3> > estimated;
    code = estimate_principal_curvatures(bundle, boost::make_assoc_property_map(estimated), np);
    if(code == Error_code::SUCCESS)
      code = internal::face_shape_operators(bundle, boost::make_assoc_property_map(estimated), S, Khat, kmax);
  }
  if(code != Error_code::SUCCESS)
    return code;

  // The measure: residuals on the field scaled to unit root mean square
  // length, the scale being that of the smooth field.
  const std::size_t F = bundle.number_of_faces();
  Conjugate_field_result r;
  auto converged = [&](const std::vector<Complex>& field, std::size_t iteration, double lambda) {
    if(iteration == 0)
    {
      double mean_square = 0;
      for(std::size_t f = 0; f < F; ++f)
      {
        const auto uv = internal::frame_vectors(&field[4 * f]);
        mean_square += (std::norm(uv.first) + std::norm(uv.second)) / (2.0 * double(F));
      }
      r.scale = mean_square > 0 ? 1.0 / std::sqrt(mean_square) : 1.0;
    }
    r.free_residual = r.constrained_residual = 0;
    double deviation_sum = 0, weight_sum = 0;
    for(std::size_t f = 0; f < F; ++f)
    {
      const auto uv = internal::frame_vectors(&field[4 * f]);
      const double residual = std::abs(internal::conjugacy_residual(S[f], uv.first, uv.second));
      (driver.is_fixed(f) ? r.constrained_residual : r.free_residual) += r.scale * r.scale * residual;
      if(!driver.is_fixed(f) && Khat[f] > 0)
      {
        const double size = std::abs(uv.first) * std::abs(uv.second) * kmax[f];
        deviation_sum += Khat[f] * (size > 0 ? residual / size : 0.0);
        weight_sum += Khat[f];
      }
    }
    r.residual = r.free_residual + r.constrained_residual;
    r.mean_deviation = weight_sum > 0 ? deviation_sum / weight_sum : 0.0;
    r.residual_history.push_back(r.free_residual);
    r.deviation_history.push_back(r.mean_deviation);
    r.final_lambda = iteration > 0 ? lambda : 0.0;
    if(p.verbose && iteration > 0)
      std::cerr << "conjugate field: iteration " << iteration << ", lambda " << lambda
                << ", mean deviation (free faces) " << r.mean_deviation << ", residual (free faces) " << r.free_residual
                << ", (constrained faces) " << r.constrained_residual << "\n";
    return r.converged = paper_rule ? r.free_residual < tolerance : r.mean_deviation <= tolerance;
  };
  // The local step: the closest conjugate pair.
  auto local_step = [&](std::size_t f, const Complex& u, const Complex& v) {
    return internal::project_onto_conjugate_pair(S[f], u, v);
  };
  return driver.design(constraints, Khat, orthogonality, p, local_step, converged, coefficient_map, r, result);
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

#endif // CGAL_POLYVECTOR_FIELDS_CONJUGATE_FRAME_FIELD_H
