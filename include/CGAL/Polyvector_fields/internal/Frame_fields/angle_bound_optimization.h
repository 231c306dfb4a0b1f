// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_ANGLE_BOUND_OPTIMIZATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_ANGLE_BOUND_OPTIMIZATION_H

// The angle-bounded frame field of paper Section 4.2 as a local-global
// optimization: its parameters, its local step (u and v turned apart up to
// the bound, internal/Frame_fields/angle_bound_projection.h) and its measure
// (the smallest frame angle of the free faces).

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/angle_bound_projection.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/frame_field_optimization.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The named parameters of design_angle_bounded_frame_field(), read and checked.
struct Angle_bound_parameters
{
  double theta_min = 0;
  double tolerance = 0;
  Local_global_parameters schedule;
};

template <typename NamedParameters>
Error_code read_angle_bound_parameters(const NamedParameters& np, Angle_bound_parameters& p)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  p.theta_min = choose_parameter(get_parameter(np, internal_np::angle_bound), 70.0 * CGAL_PI / 180.0);
  p.tolerance = choose_parameter(get_parameter(np, internal_np::tolerance), 0.5 * CGAL_PI / 180.0);
  const Error_code code = read_local_global_parameters(np, 200, std::numeric_limits<double>::infinity(), p.schedule);
  if(code != Error_code::SUCCESS)
    return code;
  if(!std::isfinite(p.theta_min) || !std::isfinite(p.tolerance))
    return Error_code::NON_FINITE_VALUE;
  if(!(p.theta_min > 0) || p.theta_min > CGAL_PI / 2 || !(p.tolerance >= 0))
    return Error_code::INVALID_PARAMETER;
  return Error_code::SUCCESS;
}

// The iterations on the frame field `field`, in place; `r` receives the
// report (an Angle_bound_result), also when the iterations did not converge.
template <typename ConcurrencyTag, typename Bundle, typename NamedParameters, typename Result>
Error_code optimize_angle_bounded_field(Polyvector_field<Bundle>& field, const Angle_bound_parameters& p,
                                        const NamedParameters& np, Result& r)
{
  const std::vector<char> fixed = fixed_faces(field);
  const std::size_t F = field.tangent_bundle().number_of_faces();
  // The measure: the smallest frame angle over the free faces, and over all faces.
  auto converged = [&](const std::vector<Complex>& c, std::size_t iteration, double lambda) {
    r.minimum_free_angle = r.minimum_angle = std::numeric_limits<double>::infinity();
    for(std::size_t f = 0; f < F; ++f)
    {
      const auto uv = frame_vectors(&c[4 * f]);
      const double a = smallest_frame_angle(uv.first, uv.second);
      r.minimum_angle = (std::min)(r.minimum_angle, a);
      if(!fixed[f])
        r.minimum_free_angle = (std::min)(r.minimum_free_angle, a);
    }
    if(p.schedule.verbose && iteration > 0)
      std::cerr << "angle bound: iteration " << iteration << ", lambda " << lambda
                << ", smallest angle " << r.minimum_free_angle * 180 / CGAL_PI << " degrees\n";
    return r.minimum_free_angle >= p.theta_min - p.tolerance;
  };
  // The local step: u and v turned apart, symmetrically, up to the bound.
  const double theta_min = p.theta_min;
  auto frame_step = [theta_min](std::size_t, const Complex& u, const Complex& v) {
    return enforce_angle_bound(u, v, theta_min);
  };
  Local_global_weights weights;
  weights.face_scale.assign(F, 1.0);
  weights.degree_penalty.assign(4, 0.0);
  return optimize_frame_field<ConcurrencyTag>(field, weights, p.schedule, frame_step, converged, np, r);
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_ANGLE_BOUND_OPTIMIZATION_H
