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
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/internal/Frame_field_iterations.h>
#include <CGAL/Polyvector_fields/internal/conjugacy_projection.h>
#include <CGAL/Polyvector_fields/internal/field_access.h>
#include <CGAL/Polyvector_fields/internal/frame_field_setup.h>

#include <cmath>
#include <iostream>
#include <map>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// reports on a run of `design_conjugate_frame_field()`. Residuals are sums
/// over faces of `|u^T S v|`, measured on the field rescaled so that the root
/// mean square length of its vectors is 1 (`scale` is that factor).
struct Conjugate_field_result
{
  std::size_t iterations = 0;          ///< global steps done
  bool converged = false;              ///< `free_residual < tolerance`
  std::vector<double> residual_history;  ///< the free-face residual before the first step and after each step
  double residual = 0;                 ///< over all faces
  double free_residual = 0;            ///< over the faces not fixed by a hard full constraint
  double constrained_residual = 0;     ///< over the faces fixed by a hard full constraint
  double scale = 1;                    ///< the factor applied to the vectors when measuring residuals
};

namespace internal {

// Shape operators in the face frames and the normalised |K| of every face.
template <typename Connection, typename CurvatureMap>
void face_shape_operators(const Connection& connection, CurvatureMap curvatures,
                          std::vector<std::array<double, 4> >& S, std::vector<double>& normalised_gaussian)
{
  using boost::get;
  const std::size_t F = connection.number_of_faces();
  S.resize(F);
  normalised_gaussian.resize(F);
  double largest = 0;
  for(std::size_t f = 0; f < F; ++f)
  {
    const auto pc = get(curvatures, connection.face(f));
    S[f] = shape_operator(pc, connection.frame(f));
    normalised_gaussian[f] = std::abs(pc.k1 * pc.k2);
    largest = (std::max)(largest, normalised_gaussian[f]);
  }
  for(double& k : normalised_gaussian)
    k = largest > 0 ? k / largest : 0.0;
}

} // namespace internal

/// \ingroup PkgPolyvectorFieldsFrameFields
///
/// designs a smooth frame field `{±u, ±v}` whose vectors are conjugate with
/// respect to the surface's second fundamental form, `u^T S v = 0` in every
/// face (paper, Section 4.3 and Appendix A): the directions that planar-quad
/// meshes follow.
///
/// Starting from the smoothest frame field that satisfies `constraints`, the
/// algorithm alternates a local step, which projects `(u, v)` of each face onto
/// the quadric `u^T S v = 0` (the closest conjugate pair), and a global step,
/// which finds the smoothest field close to the local one with weights
/// `lambda * Khat_f` (Eq. 16, `Khat_f = |k1 k2|` normalised to `[0, 1]`) plus the
/// orthogonality term `w |c_2|^2` (Eq. 17), keeping the hard constraints.
/// `lambda` is multiplied by `lambda_factor` at each iteration. It stops when
/// the residual `sum |u^T S v|` over the faces not fixed by a hard full
/// constraint falls below `tolerance`, the field being rescaled so that the root
/// mean square length of its vectors is 1, or after `number_of_iterations` steps.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`:
///         the two degrees of each global step are factored and solved in parallel with TBB (unless a constraint
///         gives a single vector, which couples the degrees into one system); the result does not depend on it
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam ConstraintRange a range of `Face_constraint<face_descriptor, Vector_3>` (at most 2 vectors each)
/// \tparam CoefficientMap a model of `WritablePropertyMap` from faces to `std::vector<std::complex<double>>`
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
///     \cgalParamDescription{the residual below which the iterations stop, `> 0`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1e-4}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the maximum number of global steps}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{100}
///   \cgalParamNEnd
///   \cgalParamNBegin{verbose}
///     \cgalParamDescription{print the residual of each iteration on `std::cerr`}
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
///          or `NON_FINITE_VALUE` for a bad parameter, `CURVATURE_ESTIMATION_FAILED`, or an error of
///          `design_polyvector_field()`. On failure `coefficient_map` is not written.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename TriangleMesh, typename ConstraintRange, typename CoefficientMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code design_conjugate_frame_field(const TriangleMesh& tm, std::size_t N, const ConstraintRange& constraints,
                                        CoefficientMap coefficient_map, Conjugate_field_result& result,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  typedef std::complex<double> Complex;
  typedef internal::Frame_field_types<TriangleMesh, NamedParameters, ConcurrencyTag> Types;
  typedef typename Types::Geom_traits Geom_traits;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;

  const double orthogonality = choose_parameter(get_parameter(np, internal_np::orthogonality_weight), 0.0);
  const double tolerance = choose_parameter(get_parameter(np, internal_np::tolerance), 1e-4);
  internal::Local_global_parameters p;
  Error_code code = internal::read_local_global_parameters(np, 100, p);
  if(code != Error_code::SUCCESS)
    return code;
  if(!std::isfinite(orthogonality) || !std::isfinite(tolerance))
    return Error_code::NON_FINITE_VALUE;
  if(!(orthogonality >= 0) || !(tolerance > 0))
    return Error_code::INVALID_PARAMETER;

  std::unique_ptr<typename Types::Designer> designer;
  code = internal::smooth_frame_field<ConcurrencyTag>(tm, N, constraints, np, designer);
  if(code != Error_code::SUCCESS)
    return code;
  const auto& connection = designer->connection();
  const std::size_t F = connection.number_of_faces();

  // Curvature: given, or estimated.
  std::vector<std::array<double, 4> > S;
  std::vector<double> Khat;
  typedef Principal_curvatures<typename Geom_traits::Vector_3> Curvatures;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::principal_curvature_map_t>::value)
  {
    internal::face_shape_operators(connection, get_parameter(np, internal_np::principal_curvature_map), S, Khat);
  }
  else
  {
    std::map<face_descriptor, Curvatures> estimated;
    code = estimate_principal_curvatures(tm, boost::make_assoc_property_map(estimated), np);
    if(code != Error_code::SUCCESS)
      return code;
    internal::face_shape_operators(connection, boost::make_assoc_property_map(estimated), S, Khat);
  }
  for(const auto& s : S)
    for(double x : s)
      if(!std::isfinite(x))
        return Error_code::NON_FINITE_VALUE;

  std::vector<Complex> c = designer->coefficient_array(), targets(4 * F);
  typename Types::Iterations iterations = Types::iterations(*designer, Khat, orthogonality);

  // Residuals are measured on the field scaled to unit root mean square length.
  Conjugate_field_result r;
  double mean_square = 0;
  for(std::size_t f = 0; f < F; ++f)
  {
    const auto uv = internal::frame_vectors(&c[4 * f]);
    mean_square += (std::norm(uv.first) + std::norm(uv.second)) / (2.0 * double(F));
  }
  r.scale = mean_square > 0 ? 1.0 / std::sqrt(mean_square) : 1.0;
  auto measure = [&]() {
    r.free_residual = r.constrained_residual = 0;
    for(std::size_t f = 0; f < F; ++f)
    {
      const auto uv = internal::frame_vectors(&c[4 * f]);
      const double e = r.scale * r.scale * std::abs(internal::conjugacy_residual(S[f], uv.first, uv.second));
      (iterations.is_fixed(f) ? r.constrained_residual : r.free_residual) += e;
    }
    r.residual = r.free_residual + r.constrained_residual;
  };

  measure();
  r.residual_history.push_back(r.free_residual);
  double lambda = p.initial_lambda;
  while(!(r.free_residual < tolerance) && r.iterations < p.maximum_iterations)
  {
    // Local step: the closest conjugate pair of each free face.
    for(std::size_t f = 0; f < F; ++f)
    {
      const auto uv = internal::frame_vectors(&c[4 * f]);
      const auto conjugate = iterations.is_fixed(f) ? uv : internal::project_onto_conjugate_pair(S[f], uv.first, uv.second);
      internal::frame_coefficients(conjugate.first, conjugate.second, &targets[4 * f]);
    }
    // Global step.
    if(!iterations.global_step(lambda, targets, c))
      return Error_code::SOLVER_FAILURE;
    ++r.iterations;
    measure();
    r.residual_history.push_back(r.free_residual);
    if(p.verbose)
      std::cerr << "conjugate field: iteration " << r.iterations << ", lambda " << lambda << ", residual (free faces) "
                << r.free_residual << ", (constrained faces) " << r.constrained_residual << "\n";
    lambda *= p.lambda_factor;
  }
  r.converged = r.free_residual < tolerance;
  internal::write_coefficients(connection, 4, c, coefficient_map);
  result = r;
  return Error_code::SUCCESS;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_CONJUGATE_FRAME_FIELD_H
