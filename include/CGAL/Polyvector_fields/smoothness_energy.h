// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_SMOOTHNESS_ENERGY_H
#define CGAL_POLYVECTOR_FIELDS_SMOOTHNESS_ENERGY_H

/// \file smoothness_energy.h

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/Smoothness_weights.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/internal/field_access.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <complex>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// Eq. 6 with the transport power N - m, on a flat coefficient array, with
// the weights of smoothness_edge_weights() (empty: all 1).
template <typename Bundle>
double smoothness_energy(const Bundle& bundle, std::size_t N, const std::vector<std::complex<double> >& c,
                         const std::vector<double>& edge_weights = std::vector<double>())
{
  double energy = 0;
  const auto& edges = bundle.interior_edges();
  for(std::size_t i = 0; i < edges.size(); ++i)
  {
    const auto& e = edges[i];
    double edge_energy = 0;
    for(std::size_t m = 0; m < N; ++m)
    {
      const int power = int(N - m);
      edge_energy += std::norm(c[e.f * N + m] * std::pow(std::conj(e.e_f), power)
                               - c[e.g * N + m] * std::pow(std::conj(e.e_g), power));
    }
    energy += edge_weights.empty() ? edge_energy : edge_weights[i] * edge_energy;
  }
  return energy;
}

} // namespace internal

/// \ingroup PkgPolyvectorFieldsDesign
///
/// returns the smoothness energy of a PolyVector field (paper Eq. 6, with the
/// transport power `N - m` of the user manual's section "Smoothness"): the sum
/// over interior edges `(f, g)` and degrees `m` of
/// `w_e |c_{f,m} conj(e_f)^(N-m) - c_{g,m} conj(e_g)^(N-m)|^2`, where `e_f`, `e_g`
/// are the unit direction of the common edge in the frames of `f` and `g` and
/// `w_e` the edge's weight (see `Smoothness_weights`; 1 by default).
/// It is zero exactly for a field that is Levi-Civita parallel across every edge.
///
/// \tparam Mesh_or_bundle a `Tangent_bundle`, or a model of `FaceListGraph` (whose bundle is then built
///         with the named parameter `vertex_point_map`)
/// \tparam CoefficientMap a model of `ReadablePropertyMap` from faces to `std::vector<std::complex<double>>` of size `N`
///
/// \cgalNamedParamsBegin
///   \pvfParamVertexPointMap
///   \pvfParamSmoothnessWeights
/// \cgalNamedParamsEnd
///
/// \returns the energy, or a quiet NaN when the mesh is not a valid triangle mesh, `N` is 0,
///          or a coefficient vector is not of size `N` or not finite.
template <typename Mesh_or_bundle, typename CoefficientMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
double smoothness_energy(const Mesh_or_bundle& mesh_or_bundle, std::size_t N, CoefficientMap coefficient_map,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto& bundle = internal::bundle_of(mesh_or_bundle, np);
  std::vector<std::complex<double> > c;
  if(internal::read_coefficients(bundle, N, coefficient_map, c) != Error_code::SUCCESS)
    return std::numeric_limits<double>::quiet_NaN();
  return internal::smoothness_energy(bundle, N, c,
                                     internal::smoothness_edge_weights(bundle, internal::read_smoothness_weights(np)));
}

/// \ingroup PkgPolyvectorFieldsDesign
///
/// returns the smoothness energy of `field`, with the edge weights it was
/// designed with, as the other overload computes it.
template <typename TangentBundle>
double smoothness_energy(const Polyvector_field<TangentBundle>& field)
{
  const TangentBundle& bundle = field.tangent_bundle();
  if(bundle.status() != Error_code::SUCCESS)
    return std::numeric_limits<double>::quiet_NaN();
  return internal::smoothness_energy(bundle, field.degree(), field.coefficients(),
                                     internal::smoothness_edge_weights(bundle, field.smoothness_weights()));
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_SMOOTHNESS_ENERGY_H
