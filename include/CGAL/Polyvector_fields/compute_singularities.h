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
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/internal/field_access.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>
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
namespace internal {

// Angle of the corner of face(h) at target(h).
template <typename Bundle>
double corner_angle(const Bundle& bundle, typename Bundle::halfedge_descriptor h)
{
  using boost::get;
  const auto& tm = bundle.mesh();
  const auto vpm = bundle.vertex_point_map();
  std::array<double, 3> v = to_array(get(vpm, target(h, tm)));
  std::array<double, 3> p = to_array(get(vpm, source(h, tm)));
  std::array<double, 3> q = to_array(get(vpm, target(next(h, tm), tm)));
  scale_to_unit({ &v, &p, &q });  // the angle does not depend on the scale
  const std::array<double, 3> a = difference(p, v);
  const std::array<double, 3> b = difference(q, v);
  const std::array<double, 3> n = cross(a, b);
  return std::atan2(std::sqrt(dot(n, n)), dot(a, b));
}

// Index numerator of the interior vertex target(h0) (the user manual's section
// "Singularities and their indices"): walking once
// counterclockwise around the vertex (seen from the side the normals point
// to), sum the principal-matching angles of the constant coefficient y_f and
// N times the angle defect. `defined` is false if some y_f of the ring is 0.
template <typename Bundle>
int index_numerator(const Bundle& bundle, std::size_t N, const std::vector<std::complex<double> >& c,
                    typename Bundle::halfedge_descriptor h0, bool& defined, double& residual)
{
  const auto& tm = bundle.mesh();
  double angle_sum = 0, delta_sum = 0;
  defined = true;
  auto h = h0;
  do
  {
    const auto o = opposite(h, tm);
    // The matching angle of an edge is computed once, across its canonical
    // halfedge (the one whose face has the smaller index; halfedge(edge(h))
    // is no canonical choice: a Surface_mesh edge remembers the halfedge it
    // was made from), and taken with the opposite sign from the other side:
    // then the two vertices of the edge see exactly opposite angles, also
    // where the ratio is (nearly) real and negative, where arg() would give
    // +pi from both sides, and the indices add up to N chi exactly.
    const bool canonical = bundle.index(face(h, tm)) < bundle.index(face(o, tm));
    const auto hc = canonical ? h : o, oc = canonical ? o : h;
    const std::size_t f = bundle.index(face(hc, tm)), g = bundle.index(face(oc, tm));
    const std::complex<double> y_f = c[f * N], y_g = c[g * N];
    if(y_f == std::complex<double>(0) || y_g == std::complex<double>(0))
      defined = false;
    const std::complex<double> e_f = bundle.edge_direction(hc), e_g = -bundle.edge_direction(oc);
    // Arg( y_g conj(e_g)^N / (y_f conj(e_f)^N) ), for unit e_f: 1/conj(e_f)^N = e_f^N. The coefficients are
    // made unit first (std::abs does not overflow): y_g conj(y_f) itself overflows for |y| beyond 1e154.
    const std::complex<double> u_f = defined ? y_f / std::abs(y_f) : std::complex<double>(1);
    const std::complex<double> u_g = defined ? y_g / std::abs(y_g) : std::complex<double>(1);
    const double delta = std::arg(u_g * std::pow(std::conj(e_g), int(N)) * std::conj(u_f) * std::pow(e_f, int(N)));
    delta_sum += (h == hc) ? delta : -delta;
    angle_sum += corner_angle(bundle, h);
    h = prev(o, tm);  // the next face counterclockwise around target(h0)
  } while(h != h0);
  const double defect = two_pi - angle_sum;
  const double k = (double(N) * defect + delta_sum) / two_pi;
  residual = std::abs(k - std::round(k));
  return int(std::lround(k));
}

// The index numerators of all vertices, as index_numerator() computes them
// vertex by vertex, bit for bit, but with the matching angle of each interior
// edge computed once (from the transport of the bundle, which holds the same
// edge directions) and the vertices shared among threads with
// CGAL::Parallel_tag. `state[i]` is 0 for a boundary or isolated vertex of
// index i (no index), 1 for an index numerator `numerator[i]`, 2 for an
// undefined index.
template <typename ConcurrencyTag, typename Bundle>
void index_numerators(const Bundle& bundle, std::size_t N, const std::vector<std::complex<double> >& c,
                      std::vector<int>& numerator, std::vector<unsigned char>& state)
{
  typedef typename Bundle::Triangle_mesh Triangle_mesh;
  typedef typename boost::graph_traits<Triangle_mesh>::edge_descriptor edge_descriptor;
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor halfedge_descriptor;
  constexpr std::size_t grain = 4096;
  const Triangle_mesh& tm = bundle.mesh();
  const auto& edges = bundle.interior_edges();

  Numbering<edge_descriptor> edge_number;  // the position of an edge in `edges`
  edge_number.reserve(num_edges(tm));
  for(const auto& e : edges)
    edge_number.add(edge(e.h, tm));

  // The matching angle across the canonical halfedge of each edge, the one whose
  // face has the smaller index (see index_numerator()), and whether c_0 vanishes
  // on one side. The canonical halfedge is e.h if e.f < e.g, with the edge
  // directions e.e_f and e.e_g; otherwise it is opposite(e.h), with the
  // directions -e.e_g and -e.e_f (f != g: the bundle of a triangle mesh has no
  // face on both sides of an edge).
  std::vector<double> delta(edges.size());
  std::vector<unsigned char> vanishes(edges.size());
  for_each_range<ConcurrencyTag>(edges.size(), grain, [&](std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i)
    {
      const auto& e = edges[i];
      const bool canonical = e.f < e.g;
      const std::size_t f = canonical ? e.f : e.g, g = canonical ? e.g : e.f;
      const std::complex<double> y_f = c[f * N], y_g = c[g * N];
      if(y_f == std::complex<double>(0) || y_g == std::complex<double>(0))
      {
        vanishes[i] = 1;
        continue;
      }
      const std::complex<double> e_f = canonical ? e.e_f : -e.e_g, e_g = canonical ? e.e_g : -e.e_f;
      const std::complex<double> u_f = y_f / std::abs(y_f);
      const std::complex<double> u_g = y_g / std::abs(y_g);
      delta[i] = std::arg(u_g * std::pow(std::conj(e_g), int(N)) * std::conj(u_f) * std::pow(e_f, int(N)));
    }
  });

  const std::size_t V = bundle.number_of_vertices();
  numerator.assign(V, 0);
  state.assign(V, 0);
  for_each_range<ConcurrencyTag>(V, grain, [&](std::size_t begin, std::size_t end) {
    for(std::size_t v = begin; v < end; ++v)
    {
      const halfedge_descriptor h0 = halfedge(bundle.vertex(v), tm);
      if(h0 == boost::graph_traits<Triangle_mesh>::null_halfedge() || CGAL::is_border(bundle.vertex(v), tm))
        continue;
      // The walk of index_numerator(), with the same sums in the same order.
      double angle_sum = 0, delta_sum = 0;
      bool defined = true, interior = true;
      halfedge_descriptor h = h0;
      do
      {
        std::size_t i;
        if(!edge_number.find(edge(h, tm), i))
        {
          interior = false;  // not a manifold ring: no index, as for a boundary vertex
          break;
        }
        const auto& e = edges[i];
        if(vanishes[i])
          defined = false;
        delta_sum += ((h == e.h) == (e.f < e.g)) ? delta[i] : -delta[i];
        angle_sum += corner_angle(bundle, h);
        h = prev(opposite(h, tm), tm);  // the next face counterclockwise around the vertex
      } while(h != h0);
      if(!interior)
        continue;
      if(!defined)
      {
        state[v] = 2;
        continue;
      }
      const double defect = two_pi - angle_sum;
      const double k = (double(N) * defect + delta_sum) / two_pi;
      numerator[v] = int(std::lround(k));
      state[v] = 1;
    }
  });
}

} // namespace internal

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
