// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_FRAME_FIELD_OPTIMIZATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_FRAME_FIELD_OPTIMIZATION_H

// What the frame-field algorithms (angle bound, conjugacy) share: the
// smoothest frame field of a set of constraints (the designer's, for the
// overloads that take constraints), and the local-global iterations of
// Local_global_optimizer with a local step stated on the frame (u, v) of a
// face rather than on its coefficients.

#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/Smoothness_weights.h>
#include <CGAL/Polyvector_fields/internal/Field_design/Local_global_optimizer.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/frame_field_polynomial.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <complex>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The smoothest frame field {±u, ±v} of `constraints` (each vector u stands
// for {u, -u}) on `bundle`, designed with the solver and the smoothness
// weights of `np`, into `field`.
template <typename ConcurrencyTag, typename Bundle, typename ConstraintRange, typename NamedParameters>
Error_code design_smooth_frame_field(const Bundle& bundle, const ConstraintRange& constraints,
                                     const NamedParameters& np, Polyvector_field<Bundle>& field)
{
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::sparse_linear_solver_t, NamedParameters,
                                                             Default_sparse_solver>::type Solver;
  typedef Polyvector_field_designer<typename Bundle::Triangle_mesh, CGAL::Default, typename Bundle::Vertex_point_map,
                                    Solver, ConcurrencyTag> Designer;
  Designer designer(bundle, 4,
                    Polyvector_fields::parameters::sign_symmetric(
                      true, Polyvector_fields::parameters::smoothness_weights(
                              read_smoothness_weights(np),
                              CGAL::parameters::sparse_linear_solver(CGAL::parameters::choose_parameter(
                                CGAL::parameters::get_parameter(np, CGAL::internal_np::sparse_linear_solver), Solver())))));
  Error_code code = designer.status();
  for(const auto& constraint : constraints)
  {
    if(code != Error_code::SUCCESS)
      break;
    code = designer.add_constraint(constraint.face, constraint.vectors, constraint.weight);
  }
  if(code == Error_code::SUCCESS)
    code = designer.solve(field);
  return code;
}

// The faces whose frame a hard full constraint of the design fixes, by index.
template <typename Bundle>
std::vector<char> fixed_faces(const Polyvector_field<Bundle>& field)
{
  std::vector<char> fixed(field.tangent_bundle().number_of_faces(), 0);
  for(const auto& entry : field.constraint_specifications())
    if(entry.second.full && entry.second.is_hard())
      fixed[entry.first] = 1;
  return fixed;
}

// The local-global iterations on the frame field `field`, in place:
// `frame_step(f, u, v)` returns the frame of free face f after the local step,
// `converged(c, iterations, lambda)` is the algorithm's measure (see
// Local_global_optimizer::iterate()); `r` (an Angle_bound_result or a
// Conjugate_field_result) receives the counts. Returns NOT_A_FRAME_FIELD if
// `field` is not a frame field, SOLVER_FAILURE if a global step fails, and
// DID_NOT_CONVERGE (with the field of the last step) if the measure was not
// met within the iterations.
template <typename ConcurrencyTag, typename Bundle, typename NamedParameters, typename FrameStep, typename Converged,
          typename Result>
Error_code optimize_frame_field(Polyvector_field<Bundle>& field, const Local_global_weights& weights,
                                const Local_global_parameters& p, const FrameStep& frame_step,
                                const Converged& converged, const NamedParameters& np, Result& r)
{
  if(!field.is_frame_field())
    return Error_code::NOT_A_FRAME_FIELD;
  auto optimizer = make_local_global_optimizer<ConcurrencyTag>(field, np);
  auto local_step = [&frame_step](std::size_t f, const Complex* c, Complex* target) {
    const auto uv = frame_vectors(c);
    const auto moved = frame_step(f, uv.first, uv.second);
    frame_coefficients(moved.first, moved.second, target);
  };
  std::vector<Complex> c = field.coefficients();
  bool met = false;
  const Error_code code = optimizer.iterate(weights, p, local_step, converged, c, r.iterations, met);
  r.converged = met;
  if(code != Error_code::SUCCESS)
    return code;
  r.factorizations = optimizer.factorizations();
  field.coefficients().swap(c);
  return met ? Error_code::SUCCESS : Error_code::DID_NOT_CONVERGE;
}

// The public overloads on a field: `run(optimized, report)` optimises a copy
// of `field`; the field and `result` are written when it succeeds or does not
// converge, and left as they were on any other failure.
template <typename Bundle, typename Result, typename Run>
Error_code optimize_in_place(Polyvector_field<Bundle>& field, Result& result, const Run& run)
{
  if(!field.is_frame_field())
    return Error_code::NOT_A_FRAME_FIELD;
  Polyvector_field<Bundle> optimized = field;
  Result r;
  const Error_code code = run(optimized, r);
  if(code == Error_code::SUCCESS || code == Error_code::DID_NOT_CONVERGE)
  {
    field = std::move(optimized);
    result = r;
  }
  return code;
}

// The public overloads on constraints and a coefficient map: the smooth field
// of the constraints, then `optimize(field)` (the overload on a field); the
// map is written when that one writes its field.
template <typename ConcurrencyTag, typename Mesh_or_bundle, typename ConstraintRange, typename CoefficientMap,
          typename NamedParameters, typename Optimize>
Error_code design_then_optimize(const Mesh_or_bundle& mesh_or_bundle, const ConstraintRange& constraints,
                                CoefficientMap coefficient_map, const NamedParameters& np, const Optimize& optimize)
{
  const auto& bundle = bundle_of(mesh_or_bundle, np);
  Polyvector_field<std::decay_t<decltype(bundle)> > field(bundle, 4, true);
  Error_code code = design_smooth_frame_field<ConcurrencyTag>(bundle, constraints, np, field);
  if(code == Error_code::SUCCESS)
    code = optimize(field);
  if(code == Error_code::SUCCESS || code == Error_code::DID_NOT_CONVERGE)
    field.write_coefficients(coefficient_map);
  return code;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_FRAME_FIELD_OPTIMIZATION_H
