// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_VERTEX_JET_FITS_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_VERTEX_JET_FITS_H

// The first estimator of estimate_principal_curvatures(): the points of the
// mesh scaled by a power of two, the area-weighted vertex normals, and one jet
// fit (CGAL's Monge_via_jet_fitting) per vertex on a ring neighbourhood grown
// until it determines the polynomial.

#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>

#include <CGAL/Eigen_svd.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// Largest fitting degree accepted. CGAL's jet fitting divides by factorials
// computed in `unsigned int`, which overflow beyond 12!.
constexpr long long curvature_max_degree_fitting = 12;

// A fit whose least-squares matrix (preconditioned by CGAL, hence independent
// of the scale of the mesh) has a larger condition number is rejected: its
// points do not determine a polynomial of the fitting degree (for instance they
// lie on a line, or on too few distinct positions over the fitting plane).
constexpr double curvature_max_condition_number = 1e10;

// Number of rings added, one at a time, to a neighbourhood whose fit is
// rejected, before the estimation gives up.
constexpr std::size_t curvature_max_extra_rings = 3;

// Number of coefficients of a bivariate polynomial of degree d.
inline std::size_t curvature_jet_coefficients(std::size_t d)
{
  return (d + 1) * (d + 2) / 2;
}

// Number of points the neighbourhood of an interior vertex grows to before it
// is fitted: one more than the coefficient count, so that the fit is a
// least-squares fit with at least one residual. For degree 2 this is the
// 1-ring of a vertex of valence 6 or more (7 points, 6 coefficients); a larger
// neighbourhood only adds bias on curved surfaces (measured: the error of
// degree 2 on a sphere is about 3.5 times larger with 2-rings).
inline std::size_t curvature_target_points(std::size_t d)
{
  return curvature_jet_coefficients(d) + 1;
}

// Number of points the neighbourhood of a boundary vertex grows to: twice the
// coefficient count. The fit extrapolates on the open side and needs more rows
// of points to pin its higher-order terms (measured: degree 4 on an open
// cylinder of 2304 faces, the error at the boundary falls from 17% to 0.6%).
inline std::size_t curvature_boundary_target_points(std::size_t d)
{
  return 2 * curvature_jet_coefficients(d);
}

// The Monge data of one vertex, with the sign convention of CGAL's Monge form
// (positive curvature where the surface bends towards `normal`).
struct Curvature_vertex_fit
{
  std::array<double, 3> normal;
  std::array<double, 3> d_max;
  std::array<double, 3> d_min;
  double k_max;
  double k_min;
};

inline bool curvature_all_finite(const std::array<double, 3>& a)
{
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

// The points of the vertices of the bundle, scaled by one power of two 2^-e,
// so that the largest coordinate is in [1, 2): the fits cannot overflow or
// underflow whatever the scale of the mesh. Returns e: curvatures, which scale
// like 1/length, are scaled back by 2^-e.
template <typename Bundle>
int curvature_scaled_points(const Bundle& bundle, std::vector<std::array<double, 3> >& points)
{
  const std::size_t nv = bundle.number_of_vertices();
  points.assign(nv, std::array<double, 3>());
  double largest = 0;
  for(std::size_t i = 0; i < nv; ++i)
  {
    points[i] = bundle.point(i);
    for(double x : points[i])
      largest = (std::max)(largest, std::abs(x));
  }
  const int scale_exponent = (largest > 0 && std::isfinite(largest)) ? std::ilogb(largest) : 0;
  for(auto& p : points)
    for(double& x : p)
      x = std::ldexp(x, -scale_exponent);
  return scale_exponent;
}

// The area-weighted normal of each vertex (the sum of the non-normalised
// normals of its faces), the sum of the doubled areas of its faces, and
// whether it is a vertex of some face.
struct Curvature_vertex_normals
{
  std::vector<std::array<double, 3> > normal;
  std::vector<double> incident_area;
  std::vector<char> in_face;
};

template <typename Bundle>
void curvature_vertex_normals(const Bundle& bundle, const std::vector<std::array<double, 3> >& points,
                              Curvature_vertex_normals& normals)
{
  typedef typename Bundle::halfedge_descriptor halfedge_descriptor;
  const auto& tm = bundle.mesh();
  const std::size_t nv = bundle.number_of_vertices();
  normals.normal.assign(nv, std::array<double, 3>{ 0., 0., 0. });
  normals.incident_area.assign(nv, 0.);
  normals.in_face.assign(nv, 0);
  for(std::size_t fi = 0; fi < bundle.number_of_faces(); ++fi)
  {
    const halfedge_descriptor h = halfedge(bundle.face(fi), tm);
    const std::size_t i0 = bundle.index(source(h, tm));
    const std::size_t i1 = bundle.index(target(h, tm));
    const std::size_t i2 = bundle.index(target(next(h, tm), tm));
    const std::array<double, 3> n = cross(difference(points[i1], points[i0]), difference(points[i2], points[i0]));
    const double area2 = std::sqrt(dot(n, n));
    for(std::size_t i : { i0, i1, i2 })
    {
      for(int c = 0; c < 3; ++c)
        normals.normal[i][c] += n[c];
      normals.incident_area[i] += area2;
      normals.in_face[i] = 1;
    }
  }
}

// The neighbourhood of a vertex, grown ring by ring through edges over the
// vertices of faces; its points are those fitted.
template <typename Bundle, typename Point>
class Curvature_ring_neighbourhood
{
public:
  Curvature_ring_neighbourhood(const Bundle& bundle, const std::vector<std::array<double, 3> >& points,
                               const std::vector<char>& in_face)
    : m_bundle(bundle), m_points(points), m_in_face(in_face), m_visit_stamp(bundle.number_of_vertices(), 0)
  {}

  // Restarts with the vertex `vi` alone (ring 0).
  void start(std::size_t vi)
  {
    m_stamp = vi + 1;
    m_neighbourhood.clear();
    m_ring.assign(1, vi);
    m_visit_stamp[vi] = m_stamp;
    m_neighbourhood.emplace_back(m_points[vi][0], m_points[vi][1], m_points[vi][2]);
    m_rings = 0;
  }

  // Adds the next ring; returns false if it is empty (the component is exhausted).
  bool grow_one_ring()
  {
    typedef typename Bundle::halfedge_descriptor halfedge_descriptor;
    const auto& tm = m_bundle.mesh();
    m_next_ring.clear();
    for(std::size_t wi : m_ring)
    {
      for(halfedge_descriptor h : CGAL::halfedges_around_target(m_bundle.vertex(wi), tm))
      {
        const std::size_t ui = m_bundle.index(source(h, tm));
        if(m_visit_stamp[ui] == m_stamp || !m_in_face[ui])
          continue;
        m_visit_stamp[ui] = m_stamp;
        m_next_ring.push_back(ui);
        m_neighbourhood.emplace_back(m_points[ui][0], m_points[ui][1], m_points[ui][2]);
      }
    }
    m_ring.swap(m_next_ring);
    ++m_rings;
    return !m_ring.empty();
  }

  std::size_t rings() const { return m_rings; }
  const std::vector<Point>& points() const { return m_neighbourhood; }

private:
  const Bundle& m_bundle;
  const std::vector<std::array<double, 3> >& m_points;
  const std::vector<char>& m_in_face;
  std::vector<std::size_t> m_visit_stamp;
  std::size_t m_stamp = 0;
  std::size_t m_rings = 0;
  std::vector<std::size_t> m_ring, m_next_ring;
  std::vector<Point> m_neighbourhood;
};

// The degrees and neighbourhood sizes of the jet fits.
struct Curvature_fit_settings
{
  std::size_t degree_fitting;
  std::size_t degree_monge;
  std::size_t ring_size;
};

// Vertices per task of the parallel jet fits. Each thread has its own
// neighbourhood, whose stamps take one entry per vertex of the mesh (one per
// task would make that quadratic in the number of vertices).
constexpr std::size_t curvature_fit_grain = 2048;

// The jet fits of the vertices of faces. `fallback[vi]` is set for a vertex
// that no fit determines (no normal to orient a fit, a neighbourhood that never
// determines the polynomial, or a non-finite result): its fit comes from the
// second estimator. The fit of a vertex depends on that vertex only, so the
// result does not depend on `ConcurrencyTag`.
template <typename ConcurrencyTag, typename Bundle>
void fit_vertex_jets(const Bundle& bundle, const std::vector<std::array<double, 3> >& points,
                     const Curvature_vertex_normals& normals, int scale_exponent,
                     const Curvature_fit_settings& settings, std::vector<Curvature_vertex_fit>& fits,
                     std::vector<char>& fallback)
{
  typedef CGAL::Simple_cartesian<double> Local_kernel;
  typedef CGAL::Monge_via_jet_fitting<Local_kernel, Local_kernel, CGAL::Eigen_svd> Jet_fitting;
  typedef typename Jet_fitting::Monge_form Monge_form;

  const auto& tm = bundle.mesh();
  const std::size_t nv = bundle.number_of_vertices();
  const std::size_t minimal_points = curvature_jet_coefficients(settings.degree_fitting);
  const std::size_t target_points = curvature_target_points(settings.degree_fitting);
  const std::size_t boundary_target_points = curvature_boundary_target_points(settings.degree_fitting);

  fits.assign(nv, Curvature_vertex_fit());
  fallback.assign(nv, 0);
  typedef Curvature_ring_neighbourhood<Bundle, Local_kernel::Point_3> Neighbourhood;
  // the stamps of a neighbourhood are the vertex's index + 1 (start()): any
  // vertex may follow any other
  const auto make_neighbourhood = [&]() { return Neighbourhood(bundle, points, normals.in_face); };
  for_each_range_with_scratch<ConcurrencyTag>(nv, curvature_fit_grain, make_neighbourhood,
                                              [&](Neighbourhood& neighbourhood, std::size_t begin, std::size_t end) {
    Jet_fitting jet_fitting;
    for(std::size_t vi = begin; vi < end; ++vi)
    {
      if(!normals.in_face[vi])
        continue;

      const std::array<double, 3>& vertex_normal = normals.normal[vi];
      const double normal_length = std::sqrt(dot(vertex_normal, vertex_normal));
      if(!(normal_length > 1e-12 * normals.incident_area[vi]))
      {
        fallback[vi] = 1;  // no normal to orient a fit
        continue;
      }

      neighbourhood.start(vi);
      bool exhausted = false;
      const std::size_t vertex_target = CGAL::is_border(bundle.vertex(vi), tm) ? boundary_target_points : target_points;
      while(!exhausted && (neighbourhood.rings() < settings.ring_size || neighbourhood.points().size() < vertex_target))
        exhausted = !neighbourhood.grow_one_ring();

      // Fit; a neighbourhood that does not determine the polynomial (for instance
      // a fan whose outer vertices lie on one conic) gets one more ring, at most
      // `curvature_max_extra_rings` times (a strip two vertices wide never
      // determines a quadric, however far it is grown).
      Monge_form monge;
      bool fitted = false;
      for(std::size_t extra_rings = 0;; ++extra_rings)
      {
        if(neighbourhood.points().size() >= minimal_points)
        {
          monge = jet_fitting(neighbourhood.points().begin(), neighbourhood.points().end(), settings.degree_fitting,
                              settings.degree_monge);
          fitted = jet_fitting.condition_number() <= curvature_max_condition_number;
          if(fitted)
            break;
        }
        if(exhausted || extra_rings == curvature_max_extra_rings || !neighbourhood.grow_one_ring())
          break;
      }
      if(!fitted)
      {
        fallback[vi] = 1;
        continue;
      }
      monge.comply_wrt_given_normal(Local_kernel::Vector_3(vertex_normal[0], vertex_normal[1], vertex_normal[2]));

      Curvature_vertex_fit& fit = fits[vi];
      const Local_kernel::Vector_3 n = monge.normal_direction();
      const Local_kernel::Vector_3 d_max = monge.maximal_principal_direction();
      const Local_kernel::Vector_3 d_min = monge.minimal_principal_direction();
      fit.normal = { n.x(), n.y(), n.z() };
      fit.d_max = { d_max.x(), d_max.y(), d_max.z() };
      fit.d_min = { d_min.x(), d_min.y(), d_min.z() };
      fit.k_max = std::ldexp(monge.principal_curvatures(0), -scale_exponent);
      fit.k_min = std::ldexp(monge.principal_curvatures(1), -scale_exponent);
      if(!curvature_all_finite(fit.normal) || !curvature_all_finite(fit.d_max) || !curvature_all_finite(fit.d_min)
         || !std::isfinite(fit.k_max) || !std::isfinite(fit.k_min))
        fallback[vi] = 1;
    }
  });
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_VERTEX_JET_FITS_H
