// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_SELECT_CURVATURE_CONSTRAINTS_H
#define CGAL_POLYVECTOR_FIELDS_SELECT_CURVATURE_CONSTRAINTS_H

/// \file select_curvature_constraints.h
/// Sparse frame constraints along the principal directions of curvature.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Face_constraint.h>
#include <CGAL/Polyvector_fields/Principal_curvatures.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/internal/Curvature/curvature_constraint_selection.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsCurvature
///
/// selects a sparse, spread-out set of faces where the curvature is strongly
/// anisotropic and constrains each of them to its principal directions, for the
/// design of a sign-symmetric frame field (`N = 4`, the vectors `{d1, d2}`
/// standing for `{±d1, ±d2}`), as the paper does for its frame-field and
/// conjugate-field results (Section 4).
///
/// <b>Rule.</b> Let `F` be the number of faces, `phi` the constrained fraction
/// and `t` the anisotropy threshold.
/// 1. The anisotropy of a face is `a_f = |k1 - k2| / (|k1| + |k2|)`, in `[0, 1]`
///    (`0` where `k1 = k2 = 0`). It does not depend on the scale of the mesh:
///    `0` at an umbilic (sphere, plane), `1` on a cylinder or at a saddle with
///    `k1 = -k2`. The candidates are the faces with `a_f >= t` and `k1 != k2`
///    (the directions of an umbilic are undefined, so such a face is never
///    chosen) whose `d1` and `d2` are not zero.
/// 2. Candidates are ranked by decreasing `a_f (|k1| + |k2|) = |k1 - k2|`, the
///    gap between the principal curvatures. The error of an estimated principal
///    direction is the error of the curvature tensor divided by this gap, so the
///    ranking puts first the faces whose directions are the most reliable, and
///    these are the most curved anisotropic regions. Ties are broken by the
///    order of `faces(tm)`.
/// 3. Faces are taken greedily in that order. A chosen face excludes every face
///    within `k` rings of it (ring 1: the faces that share a vertex with it;
///    ring `j`: the faces that share a vertex with ring `j - 1`), with
///    `k = max(1, floor(0.5 / sqrt(phi)))`, so that constraints do not clump:
///    two chosen faces never share a vertex, and on a regular triangulation
///    the faces left free can still hold 1 to 2.7 times the budget (for
///    `phi < 1/16`; with `k = 1`, at most about a sixth of the faces can be
///    chosen).
/// 4. At most `max(1, floor(phi F))` faces are chosen; fewer when the
///    candidates run out (possibly none, e.g. on a sphere).
///
/// Each chosen face `f` gives the hard constraint (infinite weight)
/// `{face = f, vectors = {d1, d2}}`, with `d1`, `d2` copied from
/// `curvature_map` (unit vectors when the map comes from
/// `estimate_principal_curvatures()`). The constraints are stored in `out` in
/// the order they were chosen (decreasing gap). Only the connectivity of `tm`
/// is used; no constraint is guaranteed in every connected component.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam CurvatureMap a model of `ReadablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and
///         `Principal_curvatures<Vector_3>` as value type
/// \tparam FaceDescriptor `boost::graph_traits<TriangleMesh>::%face_descriptor` (deduced)
/// \tparam Vector_3 the vector type of the constraints; constructible from three
///         `double` values when it differs from the vector type of the map
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param curvature_map the principal curvatures of every face, for instance
///        filled by `estimate_principal_curvatures()`
/// \param out receives the constraints (its former content is replaced); unchanged on failure
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{constrained_fraction}
///     \cgalParamDescription{the largest fraction `phi` of the faces to constrain
///                           (`CGAL::Polyvector_fields::parameters::constrained_fraction`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0.01`}
///     \cgalParamExtra{must be in `(0, 1]`; otherwise `Error_code::INVALID_PARAMETER` is returned}
///   \cgalParamNEnd
///   \cgalParamNBegin{anisotropy_threshold}
///     \cgalParamDescription{the smallest anisotropy `a_f` of a constrained face
///                           (`CGAL::Polyvector_fields::parameters::anisotropy_threshold`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0.5`, i.e. `k1 >= 3 k2` on a convex region}
///     \cgalParamExtra{must be in `[0, 1]`; otherwise `Error_code::INVALID_PARAMETER` is returned}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns
/// - `Error_code::INVALID_PARAMETER` if a parameter is out of its range (NaN included);
/// - `Error_code::EMPTY_MESH` if `tm` has no face;
/// - `Error_code::NON_TRIANGLE_FACE` if a face is not a triangle;
/// - `Error_code::NON_FINITE_VALUE` if a curvature or a direction of the map is NaN or infinite;
/// - `Error_code::SUCCESS` otherwise, even when no face qualifies (`out` is then empty).
///
/// \sa `estimate_principal_curvatures()`, `Face_constraint`
template <typename TriangleMesh,
          typename CurvatureMap,
          typename FaceDescriptor,
          typename Vector_3,
          typename NamedParameters = CGAL::parameters::Default_named_parameters
#ifndef DOXYGEN_RUNNING
          , typename = std::enable_if_t<!internal::Is_tangent_bundle<TriangleMesh>::value>
#endif
          >
Error_code select_curvature_constraints(
  const TriangleMesh& tm,
  CurvatureMap curvature_map,
  std::vector<Face_constraint<FaceDescriptor, Vector_3> >& out,
  const NamedParameters& np = CGAL::parameters::default_values())
{
  // (The face type is deduced, not written as graph_traits<TriangleMesh>, so
  // that overload resolution for a Tangent_bundle never instantiates
  // boost::graph_traits on it, which is a hard error.)
  static_assert(std::is_same<FaceDescriptor, typename boost::graph_traits<TriangleMesh>::face_descriptor>::value,
                "the constraints must be on the faces of the mesh");
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  // ---- parameters
  const double fraction = static_cast<double>(
    choose_parameter(get_parameter(np, Polyvector_fields::internal_np::constrained_fraction), 0.01));
  const double threshold = static_cast<double>(
    choose_parameter(get_parameter(np, Polyvector_fields::internal_np::anisotropy_threshold), 0.5));
  if(!(fraction > 0. && fraction <= 1.) || !(threshold >= 0. && threshold <= 1.))
    return Error_code::INVALID_PARAMETER;

  return internal::select_curvature_constraint_faces(tm, curvature_map, fraction, threshold, out);
}

/// \ingroup PkgPolyvectorFieldsCurvature
///
/// selects curvature constraints on the mesh of a tangent bundle; see the other overload.
template <typename TriangleMesh, typename VertexPointMap, typename CurvatureMap, typename Vector_3,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code select_curvature_constraints(
  const Tangent_bundle<TriangleMesh, VertexPointMap>& bundle, CurvatureMap curvature_map,
  std::vector<Face_constraint<typename boost::graph_traits<TriangleMesh>::face_descriptor, Vector_3> >& out,
  const NamedParameters& np = CGAL::parameters::default_values())
{
  return select_curvature_constraints(bundle.mesh(), curvature_map, out, np);
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_SELECT_CURVATURE_CONSTRAINTS_H
