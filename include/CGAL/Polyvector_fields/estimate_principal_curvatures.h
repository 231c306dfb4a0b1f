// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_ESTIMATE_PRINCIPAL_CURVATURES_H
#define CGAL_POLYVECTOR_FIELDS_ESTIMATE_PRINCIPAL_CURVATURES_H

/// \file estimate_principal_curvatures.h
/// Per-face principal curvatures and directions by local polynomial (jet) fitting.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Principal_curvatures.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/curvature_tensor.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>

#include <CGAL/Eigen_svd.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>
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

// The shape operator of a triangle from the variation of its vertex normals
// (the second estimator, for vertices whose fit fails): the symmetric S of the
// face plane that best maps each edge e = p_j - p_i onto n_j - n_i, in least
// squares (S e_k = dn_k, 6 equations for the 3 entries of S). Returned in 3D,
// row-major, with the package's sign (positive where the surface bends away
// from the normals: they spread out, as on a sphere with outward normals).
inline std::array<double, 9> normal_variation_tensor(const std::array<double, 3>* p, const std::array<double, 3>* n,
                                                     const Face_frame& frame)
{
  double M[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } }, r[3] = { 0, 0, 0 };
  for(int k = 0; k < 3; ++k)
  {
    const int i = k, j = (k + 1) % 3;
    const std::array<double, 3> e = difference(p[j], p[i]), dn = difference(n[j], n[i]);
    const double ex = dot(e, frame.e1), ey = dot(e, frame.e2), dx = dot(dn, frame.e1), dy = dot(dn, frame.e2);
    // a ex + b ey = dx, b ex + c ey = dy: rows (ex, ey, 0) and (0, ex, ey).
    const double rows[2][3] = { { ex, ey, 0 }, { 0, ex, ey } }, rhs[2] = { dx, dy };
    for(int q = 0; q < 2; ++q)
      for(int a = 0; a < 3; ++a)
      {
        r[a] += rows[q][a] * rhs[q];
        for(int b = 0; b < 3; ++b)
          M[a][b] += rows[q][a] * rows[q][b];
      }
  }
  // The 3x3 normal equations, by Cramer's rule (M is positive definite for a
  // non-degenerate triangle).
  const double det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                     M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  double x[3] = { 0, 0, 0 };
  if(det != 0 && std::isfinite(det))
    for(int c = 0; c < 3; ++c)
    {
      double A[3][3];
      for(int a = 0; a < 3; ++a)
        for(int b = 0; b < 3; ++b)
          A[a][b] = (b == c) ? r[a] : M[a][b];
      x[c] = (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
              A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0])) / det;
    }
  std::array<double, 9> T;
  for(int a = 0; a < 3; ++a)
    for(int b = 0; b < 3; ++b)
      T[3 * a + b] = x[0] * frame.e1[a] * frame.e1[b] + x[1] * (frame.e1[a] * frame.e2[b] + frame.e2[a] * frame.e1[b]) +
                     x[2] * frame.e2[a] * frame.e2[b];
  return T;
}

} // namespace internal

/// \ingroup PkgPolyvectorFieldsCurvature
///
/// estimates the principal curvatures and principal directions of every face
/// of a triangle mesh.
///
/// <b>Method.</b> CGAL's `Monge_via_jet_fitting` fits a bivariate polynomial
/// of degree `d = degree_fitting` at each vertex `v` of a face, on the points
/// of a ring neighbourhood of `v`: the `ring_size`-ring of `v`, grown ring by
/// ring until it holds at least `(d+1)(d+2)/2 + 1` points (one more than the
/// number of coefficients; `(d+1)(d+2)` points at a boundary vertex, where the
/// fit extrapolates on the open side), or until it is the whole connected
/// component of `v`. If the points do not determine the polynomial (for
/// instance the 1-ring of a pole of a latitude-longitude sphere, whose outer
/// points all lie on one circle), one more ring is added and the fit is done
/// again, at most three times.
///
/// <b>Fallback.</b> A vertex that no fit determines (its connected component
/// has too few points, as on a tetrahedron; its points are degenerate for the
/// fit, as on an octahedron or a strip two vertices wide; its normal
/// vanishes) does not fail the mesh: its tensor is the average, in its tangent
/// plane, of the shape operators of its faces estimated from the variation of
/// the vertex normals along their edges (the least-squares `S` with
/// `S (p_j - p_i) = n_j - n_i` on the three edges). Flat regions get zero
/// curvature there, as the paper wants (no conjugacy term). The number of such
/// vertices is returned through the named parameter `fallback_vertices`.
///
/// The Monge frame of the fit is oriented with the vertex normal (the
/// area-weighted sum of the normals of the incident faces). For each face, the
/// curvature tensor of each of its three vertices is rotated into the face
/// plane (by the smallest rotation that takes the fitted normal onto the face
/// normal), the three 2x2 tensors are averaged in the frame of the face, and
/// the average is diagonalised.
///
/// The fit is done at the vertices because `Monge_via_jet_fitting` computes
/// the Monge form at (the projection of) its first input point: a fit centred
/// at a face barycenter, which is not on the surface, has a bias that does not
/// shrink with refinement.
///
/// All computations are done in `double`, whatever the kernel.
///
/// <b>Conventions.</b> The sign and ordering conventions are those of
/// `Principal_curvatures`: curvatures are positive where the surface bends
/// away from the face normal of `Face_frame` (a sphere with outward normals
/// has `k1 = k2 = 1/R`), `k1 >= k2`, `(d1, d2, normal)` is direct. The
/// directions are chosen with `d1 . e1 >= 0` (`e1` of `Face_frame`).
///
/// <b>Accuracy.</b> Measured on latitude-longitude and parameter-grid meshes of
/// a sphere, an open cylinder and a torus (test `frame_curvature_test.cpp`),
/// the largest curvature error relative to the largest curvature is, for
/// about 1000 to 1500 faces and then 4000 to 6000 faces, 3-4% then 0.7-1% with
/// degree 2 (it falls like `h^2` on these regular meshes), and 0.7-4% then
/// 0.05-0.3% with degree 4, whose error falls faster but which needs larger
/// neighbourhoods and is the less accurate one on very coarse meshes. Degree 4
/// suits smooth, finely sampled surfaces; degree 2 is the more robust choice
/// for noisy or coarse meshes.
///
/// \tparam Mesh_or_bundle a `Tangent_bundle`, or a model of `FaceListGraph` and `VertexListGraph`
///         (whose bundle is then built with the named parameter `vertex_point_map`)
/// \tparam CurvatureMap a model of `WritablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and
///         `Principal_curvatures<Vector_3>` as value type, where `Vector_3` is
///         constructible from three `double` values (typically the `Vector_3`
///         of the geometric traits)
/// \tparam NamedParameters a sequence of named parameters
///
/// \param mesh_or_bundle the tangent bundle of the mesh, or the mesh; it is not modified
/// \param curvature_map receives the curvatures of every face; written only
///        when the function returns `Error_code::SUCCESS`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \pvfParamVertexPointMap
///   \pvfParamGeomTraits
///   \cgalParamNBegin{degree_fitting}
///     \cgalParamDescription{the degree `d` of the fitted polynomial (CGAL's tag `CGAL::parameters::degree_fitting`)}
///     \cgalParamType{an integral type}
///     \cgalParamDefault{`2`}
///     \cgalParamExtra{must be in `[degree_monge, 12]`; otherwise `Error_code::INVALID_PARAMETER` is returned}
///   \cgalParamNEnd
///   \cgalParamNBegin{degree_monge}
///     \cgalParamDescription{the degree of the Monge form computed by CGAL's fitting (CGAL's tag `CGAL::parameters::degree_monge`);
///                           only its second-order part is used here}
///     \cgalParamType{an integral type}
///     \cgalParamDefault{`2`}
///     \cgalParamExtra{must be in `[2, 4]` and at most `degree_fitting`; otherwise `Error_code::INVALID_PARAMETER` is returned}
///   \cgalParamNEnd
///   \cgalParamNBegin{ring_size}
///     \cgalParamDescription{the minimal number of rings of the neighbourhood fitted at each vertex
///                           (`CGAL::Polyvector_fields::parameters::ring_size`); the neighbourhood is grown
///                           beyond it until it holds enough points}
///     \cgalParamType{an integral type}
///     \cgalParamDefault{`1`: the ring growth already brings enough points for the fitting degree (the
///                       1-ring of a vertex of valence 6 holds 7 points, enough for degree 2), and a smaller
///                       neighbourhood keeps the fit local: with `ring_size = 2`, degree 2 fits a wider, more
///                       curved patch and its error on a sphere or a cylinder is 3.5 to 4.5 times larger. Larger
///                       values smooth noisy meshes.}
///     \cgalParamExtra{must be at least `1`; otherwise `Error_code::INVALID_PARAMETER` is returned}
///   \cgalParamNEnd
///   \cgalParamNBegin{fallback_vertices}
///     \cgalParamDescription{receives the number of vertices whose curvature comes from the fallback estimator
///                           (`CGAL::Polyvector_fields::parameters::fallback_vertices()`)}
///     \cgalParamType{`std::size_t&`}
///     \cgalParamDefault{not reported}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns
/// - `Error_code::INVALID_PARAMETER` if a degree or the ring size is out of its range;
/// - `Error_code::EMPTY_MESH` if `tm` has no face;
/// - `Error_code::NON_TRIANGLE_FACE` if a face is not a triangle;
/// - `Error_code::DEGENERATE_FACE` if a face has zero area or a non-finite coordinate;
/// - `Error_code::CURVATURE_ESTIMATION_FAILED` only if a non-finite value comes out (no vertex can be estimated);
/// - `Error_code::SUCCESS` otherwise.
///
/// \sa `Principal_curvatures`, `shape_operator()`, `select_curvature_constraints()`
template <typename Mesh_or_bundle,
          typename CurvatureMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code estimate_principal_curvatures(const Mesh_or_bundle& mesh_or_bundle,
                                         CurvatureMap curvature_map,
                                         const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using boost::put;

  const auto& bundle = internal::bundle_of(mesh_or_bundle, np);
  typedef typename std::decay_t<decltype(bundle)>::Triangle_mesh TriangleMesh;
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::halfedge_descriptor halfedge_descriptor;

  typedef typename boost::property_traits<CurvatureMap>::value_type Curvature_value;
  typedef std::decay_t<decltype(std::declval<Curvature_value&>().d1)> Output_vector;

  // ---- parameters
  const auto degree_fitting_value = choose_parameter(get_parameter(np, CGAL::internal_np::degree_fitting), 2);
  const auto degree_monge_value = choose_parameter(get_parameter(np, CGAL::internal_np::degree_monge), 2);
  const auto ring_size_value = choose_parameter(get_parameter(np, Polyvector_fields::internal_np::ring_size), 1);

  if(!internal::curvature_integral_in_range(degree_monge_value, 2, 4)
     || !internal::curvature_integral_in_range(degree_fitting_value, 2, internal::curvature_max_degree_fitting)
     || !internal::curvature_integral_in_range(ring_size_value, 1, (std::numeric_limits<long long>::max)()))
    return Error_code::INVALID_PARAMETER;
  const std::size_t degree_fitting = static_cast<std::size_t>(degree_fitting_value);
  const std::size_t degree_monge = static_cast<std::size_t>(degree_monge_value);
  if(degree_fitting < degree_monge)
    return Error_code::INVALID_PARAMETER;
  const std::size_t ring_size = static_cast<std::size_t>(ring_size_value);

  // ---- faces and their frames: the bundle's
  if(bundle.status() != Error_code::SUCCESS)
    return bundle.status();
  const TriangleMesh& tm = bundle.mesh();
  const std::size_t nf = bundle.number_of_faces();

  // ---- vertices: points scaled by one power of two 2^-e, so that the largest
  // coordinate is in [1, 2): the fits cannot overflow or underflow whatever the
  // scale of the mesh; curvatures, which scale like 1/length, are scaled back by 2^-e.
  const std::size_t nv = bundle.number_of_vertices();
  std::vector<std::array<double, 3> > points(nv);
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

  // ---- area-weighted vertex normals
  std::vector<std::array<double, 3> > vertex_normals(nv, std::array<double, 3>{ 0., 0., 0. });
  std::vector<double> incident_area(nv, 0.);
  std::vector<char> in_face(nv, 0);
  for(std::size_t fi = 0; fi < nf; ++fi)
  {
    const halfedge_descriptor h = halfedge(bundle.face(fi), tm);
    const std::size_t i0 = bundle.index(source(h, tm));
    const std::size_t i1 = bundle.index(target(h, tm));
    const std::size_t i2 = bundle.index(target(next(h, tm), tm));
    const std::array<double, 3> n = internal::cross(internal::difference(points[i1], points[i0]),
                                                    internal::difference(points[i2], points[i0]));
    const double area2 = std::sqrt(internal::dot(n, n));
    for(std::size_t i : { i0, i1, i2 })
    {
      for(int c = 0; c < 3; ++c)
        vertex_normals[i][c] += n[c];
      incident_area[i] += area2;
      in_face[i] = 1;
    }
  }

  // ---- one jet fit per vertex of a face
  typedef CGAL::Simple_cartesian<double> Local_kernel;
  typedef CGAL::Monge_via_jet_fitting<Local_kernel, Local_kernel, CGAL::Eigen_svd> Jet_fitting;
  typedef typename Jet_fitting::Monge_form Monge_form;

  const std::size_t minimal_points = internal::curvature_jet_coefficients(degree_fitting);
  const std::size_t target_points = internal::curvature_target_points(degree_fitting);
  const std::size_t boundary_target_points = internal::curvature_boundary_target_points(degree_fitting);

  std::vector<internal::Curvature_vertex_fit> fits(nv);
  std::vector<char> fallback(nv, 0);
  std::vector<std::size_t> visit_stamp(nv, 0);
  std::vector<std::size_t> ring, next_ring;
  std::vector<Local_kernel::Point_3> neighbourhood;
  Jet_fitting jet_fitting;

  for(std::size_t vi = 0; vi < nv; ++vi)
  {
    if(!in_face[vi])
      continue;

    const double normal_length = std::sqrt(internal::dot(vertex_normals[vi], vertex_normals[vi]));
    if(!(normal_length > 1e-12 * incident_area[vi]))
    {
      fallback[vi] = 1;  // no normal to orient a fit
      continue;
    }

    // The neighbourhood grows ring by ring, through edges, over vertices of faces.
    const std::size_t stamp = vi + 1;
    neighbourhood.clear();
    ring.assign(1, vi);
    visit_stamp[vi] = stamp;
    neighbourhood.emplace_back(points[vi][0], points[vi][1], points[vi][2]);
    std::size_t rings = 0;
    auto grow_one_ring = [&]() -> bool
    {
      next_ring.clear();
      for(std::size_t wi : ring)
      {
        for(halfedge_descriptor h : CGAL::halfedges_around_target(bundle.vertex(wi), tm))
        {
          const std::size_t ui = bundle.index(source(h, tm));
          if(visit_stamp[ui] == stamp || !in_face[ui])
            continue;
          visit_stamp[ui] = stamp;
          next_ring.push_back(ui);
          neighbourhood.emplace_back(points[ui][0], points[ui][1], points[ui][2]);
        }
      }
      ring.swap(next_ring);
      ++rings;
      return !ring.empty();
    };
    bool exhausted = false;
    const std::size_t vertex_target = CGAL::is_border(bundle.vertex(vi), tm) ? boundary_target_points : target_points;
    while(!exhausted && (rings < ring_size || neighbourhood.size() < vertex_target))
      exhausted = !grow_one_ring();

    // Fit; a neighbourhood that does not determine the polynomial (for instance
    // a fan whose outer vertices lie on one conic) gets one more ring, at most
    // `curvature_max_extra_rings` times (a strip two vertices wide never
    // determines a quadric, however far it is grown).
    // A vertex that no fit determines falls back to the second estimator below.
    Monge_form monge;
    bool fitted = false;
    for(std::size_t extra_rings = 0;; ++extra_rings)
    {
      if(neighbourhood.size() >= minimal_points)
      {
        monge = jet_fitting(neighbourhood.begin(), neighbourhood.end(), degree_fitting, degree_monge);
        fitted = jet_fitting.condition_number() <= internal::curvature_max_condition_number;
        if(fitted)
          break;
      }
      if(exhausted || extra_rings == internal::curvature_max_extra_rings || !grow_one_ring())
        break;
    }
    if(!fitted)
    {
      fallback[vi] = 1;
      continue;
    }
    monge.comply_wrt_given_normal(Local_kernel::Vector_3(vertex_normals[vi][0], vertex_normals[vi][1],
                                                         vertex_normals[vi][2]));

    internal::Curvature_vertex_fit& fit = fits[vi];
    const Local_kernel::Vector_3 n = monge.normal_direction();
    const Local_kernel::Vector_3 d_max = monge.maximal_principal_direction();
    const Local_kernel::Vector_3 d_min = monge.minimal_principal_direction();
    fit.normal = { n.x(), n.y(), n.z() };
    fit.d_max = { d_max.x(), d_max.y(), d_max.z() };
    fit.d_min = { d_min.x(), d_min.y(), d_min.z() };
    fit.k_max = std::ldexp(monge.principal_curvatures(0), -scale_exponent);
    fit.k_min = std::ldexp(monge.principal_curvatures(1), -scale_exponent);
    if(!internal::curvature_all_finite(fit.normal) || !internal::curvature_all_finite(fit.d_max)
       || !internal::curvature_all_finite(fit.d_min) || !std::isfinite(fit.k_max) || !std::isfinite(fit.k_min))
      fallback[vi] = 1;
  }

  // ---- the vertices whose fit failed: the normal-variation tensors of their
  // faces, averaged in the vertex's tangent plane (zero on a flat region)
  std::vector<std::array<double, 9> > face_tensor;
  std::size_t fallbacks = 0;
  for(std::size_t vi = 0; vi < nv; ++vi)
    fallbacks += (in_face[vi] && fallback[vi]) ? 1 : 0;
  if(fallbacks > 0)
  {
    std::vector<std::array<double, 3> > unit_normals(nv);
    for(std::size_t vi = 0; vi < nv; ++vi)
    {
      const double l = std::sqrt(internal::dot(vertex_normals[vi], vertex_normals[vi]));
      unit_normals[vi] = l > 0 ? std::array<double, 3>{ vertex_normals[vi][0] / l, vertex_normals[vi][1] / l,
                                                        vertex_normals[vi][2] / l }
                               : std::array<double, 3>{ 0., 0., 0. };
    }
    face_tensor.resize(nf);
    for(std::size_t fi = 0; fi < nf; ++fi)
    {
      const halfedge_descriptor h = halfedge(bundle.face(fi), tm);
      const std::size_t c[3] = { bundle.index(source(h, tm)), bundle.index(target(h, tm)),
                                 bundle.index(target(next(h, tm), tm)) };
      const std::array<double, 3> p[3] = { points[c[0]], points[c[1]], points[c[2]] };
      const std::array<double, 3> n[3] = { unit_normals[c[0]], unit_normals[c[1]], unit_normals[c[2]] };
      face_tensor[fi] = internal::normal_variation_tensor(p, n, bundle.frame(fi));
    }
    for(std::size_t vi = 0; vi < nv; ++vi)
    {
      if(!in_face[vi] || !fallback[vi])
        continue;
      std::array<double, 9> T{};
      std::size_t count = 0;
      std::array<double, 3> normal = unit_normals[vi];
      for(halfedge_descriptor h : CGAL::halfedges_around_target(bundle.vertex(vi), tm))
      {
        if(CGAL::is_border(h, tm))
          continue;
        const std::size_t fi = bundle.index(face(h, tm));
        for(int a = 0; a < 9; ++a)
          T[a] += face_tensor[fi][a];
        ++count;
        if(normal == std::array<double, 3>{ 0., 0., 0. })
          normal = bundle.frame(fi).normal;
      }
      // A frame (t1, t2) of the vertex's tangent plane, and T there.
      const std::array<double, 3> axis = std::abs(normal[0]) < 0.9 ? std::array<double, 3>{ 1., 0., 0. }
                                                                   : std::array<double, 3>{ 0., 1., 0. };
      std::array<double, 3> t1 = internal::cross(normal, axis);
      const double l1 = std::sqrt(internal::dot(t1, t1));
      t1 = { t1[0] / l1, t1[1] / l1, t1[2] / l1 };
      const std::array<double, 3> t2 = internal::cross(normal, t1);
      auto form = [&](const std::array<double, 3>& x, const std::array<double, 3>& y) {
        double value = 0;
        for(int a = 0; a < 3; ++a)
          for(int b = 0; b < 3; ++b)
            value += x[a] * T[3 * a + b] * y[b];
        return value / double((std::max)(count, std::size_t(1)));
      };
      const internal::Symmetric_eigen_2 eigen = internal::symmetric_eigen_2(form(t1, t1), form(t1, t2), form(t2, t2));
      const double cs = std::cos(eigen.angle), sn = std::sin(eigen.angle);
      internal::Curvature_vertex_fit& fit = fits[vi];
      fit.normal = normal;
      fit.d_max = { cs * t1[0] + sn * t2[0], cs * t1[1] + sn * t2[1], cs * t1[2] + sn * t2[2] };
      fit.d_min = internal::cross(normal, fit.d_max);
      // In Monge's sign, the opposite of ours.
      fit.k_max = std::ldexp(-eigen.lambda_max, -scale_exponent);  // the points are scaled by 2^-scale_exponent
      fit.k_min = std::ldexp(-eigen.lambda_min, -scale_exponent);
      if(!internal::curvature_all_finite(fit.d_max) || !std::isfinite(fit.k_max) || !std::isfinite(fit.k_min))
        return Error_code::CURVATURE_ESTIMATION_FAILED;
    }
  }

  // ---- per face: average the three tensors in the face frame, diagonalise
  std::vector<Curvature_value> values(nf);
  for(std::size_t fi = 0; fi < nf; ++fi)
  {
    const Face_frame& frame = bundle.frame(fi);
    const halfedge_descriptor h = halfedge(bundle.face(fi), tm);
    const std::size_t corners[3] = { bundle.index(source(h, tm)), bundle.index(target(h, tm)),
                                     bundle.index(target(next(h, tm), tm)) };
    double s00 = 0., s01 = 0., s11 = 0.;
    for(std::size_t vi : corners)
    {
      const internal::Curvature_vertex_fit& fit = fits[vi];
      // Monge's sign is the opposite of ours: our tensor is -(k_max d_max d_max^T + k_min d_min d_min^T).
      const std::pair<double, const std::array<double, 3>*> terms[2] = { { -fit.k_max, &fit.d_max },
                                                                          { -fit.k_min, &fit.d_min } };
      for(const auto& term : terms)
      {
        const std::array<double, 3> d = internal::curvature_rotate(*term.second, fit.normal, frame.normal, frame.e1);
        const double x = internal::dot(d, frame.e1), y = internal::dot(d, frame.e2);
        s00 += term.first * x * x;
        s01 += term.first * x * y;
        s11 += term.first * y * y;
      }
    }
    const internal::Symmetric_eigen_2 eigen = internal::symmetric_eigen_2(s00 / 3., s01 / 3., s11 / 3.);
    const double c = std::cos(eigen.angle), s = std::sin(eigen.angle);
    const std::array<double, 3> d1 = { c * frame.e1[0] + s * frame.e2[0], c * frame.e1[1] + s * frame.e2[1],
                                       c * frame.e1[2] + s * frame.e2[2] };
    const std::array<double, 3> d2 = internal::cross(frame.normal, d1);
    if(!std::isfinite(eigen.lambda_max) || !std::isfinite(eigen.lambda_min) || !internal::curvature_all_finite(d1)
       || !internal::curvature_all_finite(d2))
      return Error_code::CURVATURE_ESTIMATION_FAILED;

    Curvature_value& value = values[fi];
    value.k1 = eigen.lambda_max;
    value.k2 = eigen.lambda_min;
    value.d1 = Output_vector(d1[0], d1[1], d1[2]);
    value.d2 = Output_vector(d2[0], d2[1], d2[2]);
  }

  for(std::size_t fi = 0; fi < nf; ++fi)
    put(curvature_map, bundle.face(fi), values[fi]);
  if(std::size_t* count = choose_parameter(get_parameter(np, Polyvector_fields::internal_np::fallback_vertices),
                                           static_cast<std::size_t*>(nullptr)))
    *count = fallbacks;
  return Error_code::SUCCESS;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_ESTIMATE_PRINCIPAL_CURVATURES_H
