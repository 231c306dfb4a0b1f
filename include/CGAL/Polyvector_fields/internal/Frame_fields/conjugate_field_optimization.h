// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_CONJUGATE_FIELD_OPTIMIZATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_CONJUGATE_FIELD_OPTIMIZATION_H

// The conjugate frame field of paper Section 4.3 as a local-global
// optimization: its parameters, the shape operators of the faces, its local
// step (the closest conjugate pair, internal/Frame_fields/conjugacy_projection.h)
// and its measure (the residuals and deviations of Conjugate_field_result).

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/Principal_curvatures.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/conjugacy_projection.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/frame_field_optimization.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The named parameters of design_conjugate_frame_field(), read and checked.
struct Conjugate_field_parameters
{
  double orthogonality = 0;
  bool paper_rule = false;
  double tolerance = 0;
  Local_global_parameters schedule;
};

// `Rule` and `defaults_of` are the public stopping rule and its defaults
// (conjugate_frame_field.h).
template <typename Rule, typename Defaults, typename NamedParameters>
Error_code read_conjugate_field_parameters(const NamedParameters& np, Rule default_rule, Rule paper_rule,
                                           Defaults (*defaults_of)(Rule), Conjugate_field_parameters& p)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  p.orthogonality = choose_parameter(get_parameter(np, internal_np::orthogonality_weight), 0.0);
  const Rule rule = choose_parameter(get_parameter(np, internal_np::stopping_rule), default_rule);
  p.paper_rule = rule == paper_rule;
  const Defaults defaults = defaults_of(rule);
  p.tolerance = choose_parameter(get_parameter(np, internal_np::tolerance), defaults.tolerance);
  const Error_code code = read_local_global_parameters(np, defaults.iterations, defaults.maximum_lambda, p.schedule);
  if(code != Error_code::SUCCESS)
    return code;
  if(!std::isfinite(p.orthogonality) || !std::isfinite(p.tolerance))
    return Error_code::NON_FINITE_VALUE;
  if(!(p.orthogonality >= 0) || !(p.tolerance > 0))
    return Error_code::INVALID_PARAMETER;
  return Error_code::SUCCESS;
}

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

// The shape operators S, normalised |K| and largest |curvature| of the faces
// of `bundle`: from the named parameter `principal_curvature_map`, or
// estimated with the other named parameters (with ConcurrencyTag).
template <typename ConcurrencyTag, typename Bundle, typename NamedParameters>
Error_code face_curvature_of(const Bundle& bundle, const NamedParameters& np, std::vector<std::array<double, 4> >& S,
                             std::vector<double>& Khat, std::vector<double>& kmax)
{
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::principal_curvature_map_t>::value)
    return face_shape_operators(bundle, CGAL::parameters::get_parameter(np, internal_np::principal_curvature_map), S, Khat,
                                kmax);
  else
  {
    typedef typename CGAL::GetGeomTraits<typename Bundle::Triangle_mesh, NamedParameters>::type Geom_traits;
    std::map<typename Bundle::face_descriptor, Principal_curvatures<typename Geom_traits::Vector_3> > estimated;
    const Error_code code = estimate_principal_curvatures<ConcurrencyTag>(bundle, boost::make_assoc_property_map(estimated), np);
    if(code != Error_code::SUCCESS)
      return code;
    return face_shape_operators(bundle, boost::make_assoc_property_map(estimated), S, Khat, kmax);
  }
}

// The iterations on the frame field `field`, in place, with the shape
// operators S of its faces, their normalised |K| (Khat, the weights of the
// data term) and their largest |curvature| (kmax). `r` receives the report
// (a Conjugate_field_result), also when the iterations did not converge.
template <typename ConcurrencyTag, typename Bundle, typename NamedParameters, typename Result>
Error_code optimize_conjugate_field(Polyvector_field<Bundle>& field, const std::vector<std::array<double, 4> >& S,
                                    const std::vector<double>& Khat, const std::vector<double>& kmax,
                                    const Conjugate_field_parameters& p, const NamedParameters& np, Result& r)
{
  const std::vector<char> fixed = fixed_faces(field);
  const std::size_t F = field.tangent_bundle().number_of_faces();
  // The measure: residuals on the field scaled to unit root mean square
  // length, the scale being that of the field given.
  auto converged = [&](const std::vector<Complex>& c, std::size_t iteration, double lambda) {
    if(iteration == 0)
    {
      double mean_square = 0;
      for(std::size_t f = 0; f < F; ++f)
      {
        const auto uv = frame_vectors(&c[4 * f]);
        mean_square += (std::norm(uv.first) + std::norm(uv.second)) / (2.0 * double(F));
      }
      r.scale = mean_square > 0 ? 1.0 / std::sqrt(mean_square) : 1.0;
    }
    r.free_residual = r.constrained_residual = 0;
    double deviation_sum = 0, weight_sum = 0;
    for(std::size_t f = 0; f < F; ++f)
    {
      const auto uv = frame_vectors(&c[4 * f]);
      const double residual = std::abs(conjugacy_residual(S[f], uv.first, uv.second));
      (fixed[f] ? r.constrained_residual : r.free_residual) += r.scale * r.scale * residual;
      if(!fixed[f] && Khat[f] > 0)
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
    if(p.schedule.verbose && iteration > 0)
      std::cerr << "conjugate field: iteration " << iteration << ", lambda " << lambda
                << ", mean deviation (free faces) " << r.mean_deviation << ", residual (free faces) " << r.free_residual
                << ", (constrained faces) " << r.constrained_residual << "\n";
    return p.paper_rule ? r.free_residual < p.tolerance : r.mean_deviation <= p.tolerance;
  };
  // The local step: the closest conjugate pair.
  auto frame_step = [&S](std::size_t f, const Complex& u, const Complex& v) {
    return project_onto_conjugate_pair(S[f], u, v);
  };
  // The data term: lambda Khat_f on every face, and the orthogonality weight on c_2.
  Local_global_weights weights;
  weights.face_scale = Khat;
  weights.degree_penalty = { 0, 0, p.orthogonality, 0 };
  return optimize_frame_field<ConcurrencyTag>(field, weights, p.schedule, frame_step, converged, np, r);
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_CONJUGATE_FIELD_OPTIMIZATION_H
