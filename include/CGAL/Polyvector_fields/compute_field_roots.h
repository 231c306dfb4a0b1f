// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_COMPUTE_FIELD_ROOTS_H
#define CGAL_POLYVECTOR_FIELDS_COMPUTE_FIELD_ROOTS_H

/// \file compute_field_roots.h

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>
#include <CGAL/Polyvector_fields/internal/field_access.h>
#include <CGAL/Polyvector_fields/parameters.h>
#include <CGAL/Polyvector_fields/polyvector_polynomial.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/tags.h>

#include <complex>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// Roots of every face (N per face, counterclockwise, in the face frame). With
// CGAL::Parallel_tag (and TBB) the faces are shared among threads; each face's
// roots are computed by the same operations, so the result is bit-identical.
template <typename ConcurrencyTag = CGAL::Sequential_tag>
void field_roots(const std::vector<std::complex<double> >& coefficients, std::size_t N, bool sign_symmetric,
                 std::vector<std::complex<double> >& roots)
{
  const std::size_t F = coefficients.size() / N;
  roots.resize(F * N);
  for_each_range<ConcurrencyTag>(F, 4096, [&](std::size_t begin, std::size_t end) {
    for(std::size_t f = begin; f < end; ++f)
      polyvector_roots(coefficients.data() + f * N, N, roots.data() + f * N, sign_symmetric);
  });
}

// World-space roots of a bundle's faces, written into `root_map`.
template <typename Vector_3, typename Bundle, typename RootMap>
void write_world_roots(const Bundle& bundle, std::size_t N, const std::vector<std::complex<double> >& roots,
                       RootMap root_map)
{
  std::vector<Vector_3> vectors(N);
  for(std::size_t f = 0; f < bundle.number_of_faces(); ++f)
  {
    for(std::size_t k = 0; k < N; ++k)
    {
      const std::array<double, 3> w = bundle.frame(f).to_world(roots[f * N + k]);
      vectors[k] = Vector_3(w[0], w[1], w[2]);
    }
    put(root_map, bundle.face(f), vectors);
  }
}

} // namespace internal

/// \ingroup PkgPolyvectorFieldsPolynomial
///
/// computes the `N` vectors of every face, in world coordinates, from the
/// coefficients of the field (the roots of each face's polynomial, mapped
/// from the face frame to 3D; see `polyvector_roots()` for their order).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`:
///         with parallelism (TBB) the roots of the faces are computed in parallel (the maps are read and
///         written by the calling thread only); the result does not depend on it
/// \tparam Mesh_or_bundle a `Tangent_bundle`, or a model of `FaceListGraph` (whose bundle is then built
///         with the named parameter `vertex_point_map`)
/// \tparam CoefficientMap a model of `ReadablePropertyMap` from faces to `std::vector<std::complex<double>>` of size `N`
/// \tparam RootMap a model of `WritablePropertyMap` from faces to `std::vector<Vector_3>`, `Vector_3` the vector type of the kernel
///
/// \cgalNamedParamsBegin
///   \pvfParamVertexPointMap
///   \pvfParamGeomTraits
///   \pvfParamSignSymmetric
/// \cgalNamedParamsEnd
///
/// \returns `SUCCESS`, a mesh error (`EMPTY_MESH`, `NON_TRIANGLE_FACE`, `DEGENERATE_FACE`), `INVALID_DEGREE`,
///          `INCONSISTENT_DEGREE` (a coefficient vector not of size `N`) or `NON_FINITE_VALUE`.
///          On failure `root_map` is not written.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename Mesh_or_bundle, typename CoefficientMap, typename RootMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code compute_field_roots(const Mesh_or_bundle& mesh_or_bundle, std::size_t N, CoefficientMap coefficient_map,
                               RootMap root_map, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto& bundle = internal::bundle_of(mesh_or_bundle, np);
  typedef typename std::decay_t<decltype(bundle)>::Triangle_mesh Triangle_mesh;
  typedef typename CGAL::GetGeomTraits<Triangle_mesh, NamedParameters>::type Geom_traits;
  const bool sign_symmetric = choose_parameter(get_parameter(np, internal_np::sign_symmetric), false);
  if(N == 0 || (sign_symmetric && N % 2 != 0))
    return Error_code::INVALID_DEGREE;
  std::vector<std::complex<double> > coefficients, roots;
  const Error_code code = internal::read_coefficients(bundle, N, coefficient_map, coefficients);
  if(code != Error_code::SUCCESS)
    return code;
  internal::field_roots<ConcurrencyTag>(coefficients, N, sign_symmetric, roots);
  internal::write_world_roots<typename Geom_traits::Vector_3>(bundle, N, roots, root_map);
  return Error_code::SUCCESS;
}

/// \ingroup PkgPolyvectorFieldsPolynomial
///
/// computes the `N` vectors of every face of `field`, in world coordinates, as
/// the other overload does from a coefficient map (the symmetry is the field's).
///
/// \tparam RootMap a model of `WritablePropertyMap` from faces to `std::vector<Vector_3>`, `Vector_3` the vector
///         type of the kernel of the mesh's points
///
/// \returns `SUCCESS`, or the bundle's error; on failure `root_map` is not written.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TangentBundle, typename RootMap>
Error_code compute_field_roots(const Polyvector_field<TangentBundle>& field, RootMap root_map)
{
  const TangentBundle& bundle = field.tangent_bundle();
  if(bundle.status() != Error_code::SUCCESS)
    return bundle.status();
  typedef typename boost::property_traits<typename TangentBundle::Vertex_point_map>::value_type Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3 Vector_3;
  std::vector<std::complex<double> > roots;
  internal::field_roots<ConcurrencyTag>(field.coefficients(), field.degree(), field.is_sign_symmetric(), roots);
  internal::write_world_roots<Vector_3>(bundle, field.degree(), roots, root_map);
  return Error_code::SUCCESS;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_COMPUTE_FIELD_ROOTS_H
