// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_COMPUTE_SINGULARITIES_H
#define CGAL_POLYVECTOR_FIELDS_COMPUTE_SINGULARITIES_H

/// \file compute_singularities.h
/// Topology of PolyVector fields: principal matching and singularities (paper, Section 3.4).

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/Singularity.h>
#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/internal/Field_design/singularity_indices.h>
#include <CGAL/Polyvector_fields/internal/field_access.h>
#include <CGAL/Polyvector_fields/parameters.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/iterator.h>
#include <CGAL/tags.h>

#include <cmath>
#include <complex>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsTopology
///
/// computes the singular vertices of an N-PolyVector field and their indices.
///
/// The singularities of a PolyVector field are those of the N-RoSy field of its
/// constant coefficient `c_0` (paper, Section 3.4). For every interior vertex `v`,
/// with angle defect `K_v`, walking once counterclockwise around `v` (seen from
/// the side the face normals point to) and taking at each crossing from `f` to
/// `g` the principal-matching angle `delta_e = Arg(c_{g,0} conj(e_g)^N / (c_{f,0} conj(e_f)^N))`
/// in `(-pi, pi]`, the index of `v` is `k/N` with `k = (N K_v + sum delta_e) / (2 pi)`,
/// an integer. Vertices with `k != 0` are written to `singularities`. On a closed
/// mesh of Euler characteristic `chi`, the numerators sum to `N chi`. Boundary
/// vertices carry no index.
///
/// If some face around an interior vertex has `c_0 = 0`, the index there is
/// undefined: the vertex is written to `undefined_vertices` and to no other output.
///
/// Both outputs are written in the order of the vertex numbering of the bundle
/// (the order of `vertices(tm)`), whatever the concurrency tag.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`:
///         with parallelism (TBB) the vertices are shared among threads, which read the mesh and the
///         vertex point map of the bundle at the same time (the coefficient map and the output iterators
///         are used by the calling thread only); the result does not depend on it
/// \tparam Mesh_or_bundle a `Tangent_bundle`, or a model of `FaceListGraph` (whose bundle is then built
///         with the named parameter `vertex_point_map`)
/// \tparam CoefficientMap a model of `ReadablePropertyMap` from faces to `std::vector<std::complex<double>>` of size `N`
/// \tparam SingularityOutputIterator an output iterator accepting `Singularity<vertex_descriptor>`
/// \tparam VertexOutputIterator an output iterator accepting `vertex_descriptor`
///
/// \returns `SUCCESS`, a mesh error, `INVALID_DEGREE`, `INCONSISTENT_DEGREE` or `NON_FINITE_VALUE`;
///          nothing is written on failure.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename Mesh_or_bundle, typename CoefficientMap, typename SingularityOutputIterator,
          typename VertexOutputIterator, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code compute_singularities(const Mesh_or_bundle& mesh_or_bundle, std::size_t N, CoefficientMap coefficient_map,
                                 SingularityOutputIterator singularities, VertexOutputIterator undefined_vertices,
                                 const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto& bundle = internal::bundle_of(mesh_or_bundle, np);
  typedef typename std::decay_t<decltype(bundle)>::vertex_descriptor vertex_descriptor;
  std::vector<std::complex<double> > c;
  const Error_code code = internal::read_coefficients(bundle, N, coefficient_map, c);
  if(code != Error_code::SUCCESS)
    return code;
  Polyvector_field<std::decay_t<decltype(bundle)> > field(bundle, N);
  field.coefficients().swap(c);
  return compute_singularities<ConcurrencyTag>(field, singularities, undefined_vertices);
}

/// \ingroup PkgPolyvectorFieldsTopology
///
/// computes the singularities as the other overload, and drops the vertices of undefined index.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename Mesh_or_bundle, typename CoefficientMap, typename SingularityOutputIterator,
          typename T = bool, typename Tag = CGAL::internal_np::all_default_t,
          typename Base = CGAL::internal_np::No_property>
Error_code compute_singularities(const Mesh_or_bundle& mesh_or_bundle, std::size_t N, CoefficientMap coefficient_map,
                                 SingularityOutputIterator singularities,
                                 const CGAL::Named_function_parameters<T, Tag, Base>& np = CGAL::parameters::default_values())
{
  return compute_singularities<ConcurrencyTag>(mesh_or_bundle, N, coefficient_map, singularities,
                                               CGAL::Emptyset_iterator(), np);
}

/// \ingroup PkgPolyvectorFieldsTopology
///
/// computes the singular vertices of `field` and their indices, as the other
/// overloads do from a coefficient map.
///
/// \returns `SUCCESS` or the bundle's error; nothing is written on failure.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TangentBundle,
          typename SingularityOutputIterator, typename VertexOutputIterator = CGAL::Emptyset_iterator>
Error_code compute_singularities(const Polyvector_field<TangentBundle>& field, SingularityOutputIterator singularities,
                                 VertexOutputIterator undefined_vertices = VertexOutputIterator())
{
  const TangentBundle& bundle = field.tangent_bundle();
  if(bundle.status() != Error_code::SUCCESS)
    return bundle.status();
  typedef typename TangentBundle::vertex_descriptor vertex_descriptor;
  std::vector<int> numerator;
  std::vector<unsigned char> state;
  internal::index_numerators<ConcurrencyTag>(bundle, field.degree(), field.coefficients(), numerator, state);
  for(std::size_t i = 0; i < bundle.number_of_vertices(); ++i)
    if(state[i] == 1 && numerator[i] != 0)
      *singularities++ = Singularity<vertex_descriptor>{ bundle.vertex(i), numerator[i] };
  for(std::size_t i = 0; i < bundle.number_of_vertices(); ++i)
    if(state[i] == 2)
      *undefined_vertices++ = bundle.vertex(i);
  return Error_code::SUCCESS;
}

/// \ingroup PkgPolyvectorFieldsTopology
///
/// computes the principal matching of every interior edge: with `h = halfedge(e)`,
/// the roots of `face(h)` and of `face(opposite(h))` in the counterclockwise order
/// of `polyvector_roots()`, root `i` of `face(h)` matches root `(i + s) mod N`
/// of `face(opposite(h))`, where the shift `s` is the one for which the sum of the
/// rotations of the matched roots after Levi-Civita transport lies in `(-pi, pi]`
/// (paper, Section 3.4).
///
/// \tparam MatchingMap a model of `WritablePropertyMap` from `edge_descriptor` to `int`;
///         boundary edges are not written
///
/// \cgalNamedParamsBegin
///   \pvfParamVertexPointMap
///   \pvfParamSignSymmetric
/// \cgalNamedParamsEnd
///
/// \returns as `compute_singularities()`; nothing is written on failure.
template <typename Mesh_or_bundle, typename CoefficientMap, typename MatchingMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code principal_matching(const Mesh_or_bundle& mesh_or_bundle, std::size_t N, CoefficientMap coefficient_map,
                              MatchingMap matching, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto& bundle = internal::bundle_of(mesh_or_bundle, np);
  const bool sign_symmetric = choose_parameter(get_parameter(np, internal_np::sign_symmetric), false);
  if(N == 0 || (sign_symmetric && N % 2 != 0))
    return Error_code::INVALID_DEGREE;
  std::vector<std::complex<double> > c, roots;
  const Error_code code = internal::read_coefficients(bundle, N, coefficient_map, c);
  if(code != Error_code::SUCCESS)
    return code;
  internal::field_roots(c, N, sign_symmetric, roots);
  auto lifted_sum = [N](const std::complex<double>* r) {
    // Arguments in [0, 2 pi), non-decreasing by the ordering of polyvector_roots().
    double s = 0;
    for(std::size_t i = 0; i < N; ++i)
    {
      double a = std::arg(r[i]);
      if(a < 0)
        a += internal::two_pi;
      s += a;
    }
    return s;
  };
  for(const auto& e : bundle.interior_edges())
  {
    // Transport from f to g turns every vector by rho = Arg(conj(e_f) e_g).
    const double rho = std::arg(std::conj(e.e_f) * e.e_g);
    const double S0 = lifted_sum(roots.data() + e.g * N) - lifted_sum(roots.data() + e.f * N) - double(N) * rho;
    // S(s) = S0 + 2 pi s must lie in (-pi, pi].
    long s = -std::lround(S0 / internal::two_pi);
    while(S0 + internal::two_pi * double(s) > internal::two_pi / 2)
      --s;
    while(S0 + internal::two_pi * double(s) <= -internal::two_pi / 2)
      ++s;
    const long n = long(N);
    put(matching, edge(e.h, bundle.mesh()), int(((s % n) + n) % n));
  }
  return Error_code::SUCCESS;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_COMPUTE_SINGULARITIES_H
