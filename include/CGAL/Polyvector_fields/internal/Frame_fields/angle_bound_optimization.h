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
// the bound, internal/Frame_fields/angle_bound_projection.h), its measure
// (the smallest frame angle of the free faces) and its final projection of
// the free faces onto the bound.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/angle_bound_projection.h>
#include <CGAL/Polyvector_fields/internal/Field_design/constraint_specification.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/frame_field_optimization.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/frame_field_polynomial.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
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

// The smallest frame angle of the coefficients `c` (4 per face) over the
// faces that are not `fixed`, and over all faces.
inline void smallest_frame_angles(const std::vector<Complex>& c, const std::vector<char>& fixed, double& free_faces,
                                  double& all_faces)
{
  free_faces = all_faces = std::numeric_limits<double>::infinity();
  for(std::size_t f = 0; f < fixed.size(); ++f)
  {
    const auto uv = frame_vectors(&c[4 * f]);
    const double a = smallest_frame_angle(uv.first, uv.second);
    all_faces = (std::min)(all_faces, a);
    if(!fixed[f])
      free_faces = (std::min)(free_faces, a);
  }
}

// How far the frame coefficients `c` (c_0..c_3 of one face) are from the
// partial constraint `s`: the largest |row . c - rhs|, over the slots of the
// admissible degrees (the even ones of a frame field: c_0 and c_2).
inline double partial_constraint_residual(const Face_specification& s, const Complex* c)
{
  const int step = (s.rows.cols() == 4) ? 1 : 2;
  double largest = 0;
  for(Eigen::Index r = 0; r < s.rows.rows(); ++r)
  {
    Complex sum = -s.rhs[r];
    for(Eigen::Index q = 0; q < s.rows.cols(); ++q)
      sum += s.rows(r, q) * c[step * q];
    largest = (std::max)(largest, std::abs(sum));
  }
  return largest;
}

// The final step of design_angle_bounded_frame_field(): every free face whose
// frame angle is below `theta_min` is turned onto it exactly, as the local
// step does (u and v apart from their bisector). On a face held by a hard
// partial constraint, the vector the constraint gives stays where it is and
// the other one turns by the whole deficit. Writes the counts of `r`.
template <typename Bundle, typename Result>
void project_onto_angle_bound(Polyvector_field<Bundle>& field, const std::vector<char>& fixed, double theta_min,
                              Result& r)
{
  std::vector<Complex>& c = field.coefficients();
  const Specifications& specifications = field.constraint_specifications();
  r.projected_faces = 0;
  for(std::size_t f = 0; f < fixed.size(); ++f)
  {
    if(fixed[f])
      continue;
    Complex* cf = &c[4 * f];
    const auto uv = frame_vectors(cf);
    if(!(smallest_frame_angle(uv.first, uv.second) < theta_min))
      continue;
    const auto spec = specifications.find(f);
    std::pair<Complex, Complex> moved;
    if(spec != specifications.end() && !spec->second.full && spec->second.is_hard() && spec->second.rows.rows() > 0)
    {
      // Keep the vector that the constraint holds: the candidate that leaves its rows satisfied.
      Complex keep_u[4], keep_v[4];
      const auto by_u = enforce_angle_bound_keeping(uv.first, uv.second, theta_min, true);
      const auto by_v = enforce_angle_bound_keeping(uv.first, uv.second, theta_min, false);
      frame_coefficients(by_u.first, by_u.second, keep_u);
      frame_coefficients(by_v.first, by_v.second, keep_v);
      moved = partial_constraint_residual(spec->second, keep_u) <= partial_constraint_residual(spec->second, keep_v)
                ? by_u : by_v;
    }
    else
      moved = enforce_angle_bound(uv.first, uv.second, theta_min);
    frame_coefficients(moved.first, moved.second, cf);
    ++r.projected_faces;
  }
}

// The rounding, in radians, that the frame angle of a projected face may
// show below the bound once written as coefficients and measured again.
constexpr double angle_bound_rounding = 1e-12;

// The iterations on the frame field `field`, in place; `r` receives the
// report (an Angle_bound_result), also when the iterations did not converge.
// When they converge (every free face within the tolerance of the bound), the
// free faces still below the bound are projected onto it
// (project_onto_angle_bound()), and the measures are taken again on the
// result: SUCCESS only when no free face is below the bound, up to
// angle_bound_rounding.
template <typename ConcurrencyTag, typename Bundle, typename NamedParameters, typename Result>
Error_code optimize_angle_bounded_field(Polyvector_field<Bundle>& field, const Angle_bound_parameters& p,
                                        const NamedParameters& np, Result& r)
{
  const std::vector<char> fixed = fixed_faces(field);
  const std::size_t F = field.tangent_bundle().number_of_faces();
  // The measure: the smallest frame angle over the free faces, and over all faces.
  auto converged = [&](const std::vector<Complex>& c, std::size_t iteration, double lambda) {
    smallest_frame_angles(c, fixed, r.minimum_free_angle, r.minimum_angle);
    r.minimum_free_angle_before_projection = r.minimum_free_angle;
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
  const Error_code code = optimize_frame_field<ConcurrencyTag>(field, weights, p.schedule, frame_step, converged, np, r);
  if(code != Error_code::SUCCESS)
    return code;  // DID_NOT_CONVERGE: the field of the last step, not projected
  project_onto_angle_bound(field, fixed, p.theta_min, r);
  smallest_frame_angles(field.coefficients(), fixed, r.minimum_free_angle, r.minimum_angle);
  if(!(r.minimum_free_angle >= p.theta_min - angle_bound_rounding))
  {
    r.converged = false;
    return Error_code::DID_NOT_CONVERGE;
  }
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_ANGLE_BOUND_OPTIMIZATION_H
