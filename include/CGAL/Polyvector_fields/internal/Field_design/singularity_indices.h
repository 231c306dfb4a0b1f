// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_SINGULARITY_INDICES_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_SINGULARITY_INDICES_H

// The index numerators of the vertices of a PolyVector field (the user
// manual's section "Singularities and their indices"), for
// compute_singularities(): vertex by vertex, and for all vertices at once from
// the principal-matching angles of the interior edges.

#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
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

// Faces and edges per thread range for the index numerators of all vertices.
constexpr std::size_t index_numerators_grain = 4096;

// The matching angle across the canonical halfedge of each interior edge of
// the bundle, the one whose face has the smaller index (see
// index_numerator()), and whether c_0 vanishes on one side. The canonical
// halfedge is e.h if e.f < e.g, with the edge directions e.e_f and e.e_g;
// otherwise it is opposite(e.h), with the directions -e.e_g and -e.e_f (f != g:
// the bundle of a triangle mesh has no face on both sides of an edge).
template <typename ConcurrencyTag, typename Bundle>
void edge_matching_angles(const Bundle& bundle, std::size_t N, const std::vector<std::complex<double> >& c,
                          std::vector<double>& delta, std::vector<unsigned char>& vanishes)
{
  const auto& edges = bundle.interior_edges();
  delta.resize(edges.size());
  vanishes.resize(edges.size());
  for_each_range<ConcurrencyTag>(edges.size(), index_numerators_grain, [&](std::size_t begin, std::size_t end) {
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
  const Triangle_mesh& tm = bundle.mesh();
  const auto& edges = bundle.interior_edges();

  Numbering<edge_descriptor> edge_number;  // the position of an edge in `edges`
  edge_number.reserve(num_edges(tm));
  for(const auto& e : edges)
    edge_number.add(edge(e.h, tm));

  std::vector<double> delta;
  std::vector<unsigned char> vanishes;
  edge_matching_angles<ConcurrencyTag>(bundle, N, c, delta, vanishes);

  const std::size_t V = bundle.number_of_vertices();
  numerator.assign(V, 0);
  state.assign(V, 0);
  for_each_range<ConcurrencyTag>(V, index_numerators_grain, [&](std::size_t begin, std::size_t end) {
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
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_SINGULARITY_INDICES_H
