// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_DESIGN_POLYVECTOR_FIELD_H
#define CGAL_POLYVECTOR_FIELDS_DESIGN_POLYVECTOR_FIELD_H

/// \file design_polyvector_field.h

#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>

#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsDesign
///
/// designs the smoothest N-PolyVector field that satisfies `constraints`, in one call.
/// See `Polyvector_field_designer` for the energy, the kinds of constraints and
/// the treatment of components; use that class to solve again for new
/// constraint values without factoring again.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`
///         (see `Polyvector_field_designer`; the result does not depend on it)
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam ConstraintRange a range of `Face_constraint<face_descriptor, Vector_3>`
/// \tparam CoefficientMap a model of `WritablePropertyMap` from faces to `std::vector<std::complex<double>>`
///
/// \param tm the mesh
/// \param N the degree, at least 1 (even with sign symmetry)
/// \param constraints the constraints
/// \param coefficient_map receives the `N` coefficients of each face, in its frame (see `Face_frame`)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \pvfParamVertexPointMap
///   \pvfParamGeomTraits
///   \pvfParamSignSymmetric
///   \pvfParamSmoothnessWeights
///   \cgalParamNBegin{sparse_linear_solver}
///     \cgalParamDescription{a model of `SparseLinearAlgebraWithFactorTraits_d` on `std::complex<double>`}
///     \cgalParamDefault{`Default_sparse_solver`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::SUCCESS` or the reason of the failure (see `Polyvector_field_designer::status()`,
///          `Polyvector_field_designer::add_constraint()` and `Polyvector_field_designer::solve()`);
///          on failure `coefficient_map` is not written.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename TriangleMesh, typename ConstraintRange, typename CoefficientMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code design_polyvector_field(const TriangleMesh& tm, std::size_t N, const ConstraintRange& constraints,
                                   CoefficientMap coefficient_map,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type Vertex_point_map;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::sparse_linear_solver_t, NamedParameters,
                                                             Default_sparse_solver>::type Solver;
  Polyvector_field_designer<TriangleMesh, Geom_traits, Vertex_point_map, Solver, ConcurrencyTag> designer(tm, N, np);
  if(designer.status() != Error_code::SUCCESS)
    return designer.status();
  const Error_code code = designer.add_constraints(constraints);
  if(code != Error_code::SUCCESS)
    return code;
  return designer.solve(coefficient_map);
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_DESIGN_POLYVECTOR_FIELD_H
