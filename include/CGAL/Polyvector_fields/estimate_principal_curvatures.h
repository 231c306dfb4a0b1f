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
#include <CGAL/Polyvector_fields/internal/Curvature/curvature_tensor.h>
#include <CGAL/Polyvector_fields/internal/Curvature/face_principal_curvatures.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

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
/// <b>Flat faces.</b> A face whose two curvatures are both below `1e-6 / D`
/// (`D` the diagonal of the bounding box of the mesh: a radius of curvature
/// above a million times the size of the mesh) gets `k1 = k2 = 0` exactly:
/// on a plane the fit returns round-off, with directions that mean nothing,
/// and `select_curvature_constraints()` never constrains a face where
/// `k1 = k2`.
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
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`:
///         with parallelism (TBB) the jet fits of the vertices and the faces are shared among threads;
///         each fit depends on its vertex only, so the result is the same to the last bit
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
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename Mesh_or_bundle,
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
  typedef typename boost::property_traits<CurvatureMap>::value_type Curvature_value;

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

  std::vector<Curvature_value> values;
  std::size_t fallbacks = 0;
  const Error_code code = internal::estimate_face_principal_curvatures<ConcurrencyTag>(
    bundle, internal::Curvature_fit_settings{ degree_fitting, degree_monge, ring_size }, values, fallbacks);
  if(code != Error_code::SUCCESS)
    return code;

  const std::size_t nf = bundle.number_of_faces();
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
