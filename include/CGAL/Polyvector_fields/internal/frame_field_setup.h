// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELD_SETUP_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELD_SETUP_H

// What the frame-field algorithms share before iterating: parameter checks
// and the smooth frame field designed from the constraints.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/internal/Frame_field_iterations.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

template <typename TriangleMesh, typename NamedParameters, typename ConcurrencyTag>
struct Frame_field_types
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type Vertex_point_map;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::sparse_linear_solver_t, NamedParameters,
                                                             Default_sparse_solver>::type Solver;
  typedef Polyvector_field_designer<TriangleMesh, Geom_traits, Vertex_point_map, Solver, ConcurrencyTag> Designer;
  typedef Frame_field_iterations<typename Designer::Connection, Solver> Iterations;

  // The global steps on the field of `designer` (its connection, hard
  // constraints and solver), with data weights lambda * scale[f].
  static Iterations iterations(const Designer& designer, std::vector<double> scale, double orthogonality_weight)
  {
    return Iterations(designer.connection(), designer.specifications(), designer.solver_prototype(), std::move(scale),
                      orthogonality_weight, std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value);
  }
};

// The iteration parameters common to both algorithms.
struct Local_global_parameters
{
  double initial_lambda = 100;
  double lambda_factor = 1.5;
  std::size_t maximum_iterations = 0;
  bool verbose = false;
};

template <typename NamedParameters>
Error_code read_local_global_parameters(const NamedParameters& np, std::size_t default_iterations,
                                        Local_global_parameters& p)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  p.initial_lambda = choose_parameter(get_parameter(np, internal_np::initial_lambda), 100.0);
  p.lambda_factor = choose_parameter(get_parameter(np, internal_np::lambda_factor), 1.5);
  p.maximum_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), default_iterations);
  p.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  if(!std::isfinite(p.initial_lambda) || !std::isfinite(p.lambda_factor))
    return Error_code::NON_FINITE_VALUE;
  if(!(p.initial_lambda > 0) || !(p.lambda_factor >= 1))
    return Error_code::INVALID_PARAMETER;
  return Error_code::SUCCESS;
}

// Checks that the call is for a frame field and designs the smooth field from
// the constraints; on success `designer` holds it.
template <typename ConcurrencyTag, typename TriangleMesh, typename ConstraintRange, typename NamedParameters>
Error_code smooth_frame_field(const TriangleMesh& tm, std::size_t N, const ConstraintRange& constraints,
                              const NamedParameters& np,
                              std::unique_ptr<typename Frame_field_types<TriangleMesh, NamedParameters, ConcurrencyTag>::Designer>& designer)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if(N != 4 || !choose_parameter(get_parameter(np, internal_np::sign_symmetric), true))
    return Error_code::NOT_A_FRAME_FIELD;
  designer.reset(new typename Frame_field_types<TriangleMesh, NamedParameters, ConcurrencyTag>::Designer(
    tm, 4, parameters::combine(np, parameters::sign_symmetric(true))));
  if(designer->status() != Error_code::SUCCESS)
    return designer->status();
  const Error_code code = designer->add_constraints(constraints);
  if(code != Error_code::SUCCESS)
    return code;
  return designer->solve(boost::dummy_property_map());
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELD_SETUP_H
