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
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The anisotropy |k1 - k2| / (|k1| + |k2|) of a face, in [0, 1]; 0 where both curvatures vanish.
inline double curvature_anisotropy(double k1, double k2)
{
  const double sum = std::abs(k1) + std::abs(k2);
  return sum > 0. ? (std::min)(1., std::abs(k1 - k2) / sum) : 0.;
}

// The exclusion radius k, in rings of faces, for a constrained fraction phi:
// k = max(1, floor(0.5 / sqrt(phi))). Measured on regular triangulations
// (torus, cylinder), faces at least k + 1 rings apart can fill about
// 0.26 / k^2 to 0.6 / k^2 of the faces, i.e. 1 to 2.7 times the budget phi for phi < 1/16:
// the exclusion prevents clumps without starving the budget. k >= 1 keeps two
// constrained faces from sharing a vertex, which caps the choice at about 1/6
// of the faces.
inline std::size_t curvature_exclusion_rings(double phi)
{
  const double k = std::floor(0.5 / std::sqrt(phi));
  return k < 1. ? std::size_t(1) : static_cast<std::size_t>((std::min)(k, 1e6));
}

template <typename Vector_out, typename Vector_in>
Vector_out curvature_convert_vector(const Vector_in& v)
{
  if constexpr(std::is_same<Vector_out, Vector_in>::value)
    return v;
  else
    return Vector_out(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
}

template <typename Vector>
bool curvature_vector_finite_nonzero(const Vector& v)
{
  const double x = CGAL::to_double(v.x()), y = CGAL::to_double(v.y()), z = CGAL::to_double(v.z());
  return std::isfinite(x) && std::isfinite(y) && std::isfinite(z) && (x != 0. || y != 0. || z != 0.);
}

template <typename Vector>
bool curvature_vector_finite(const Vector& v)
{
  return std::isfinite(CGAL::to_double(v.x())) && std::isfinite(CGAL::to_double(v.y()))
         && std::isfinite(CGAL::to_double(v.z()));
}

} // namespace internal

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
  using boost::get;

  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::face_descriptor face_descriptor;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename Graph_traits::halfedge_descriptor halfedge_descriptor;

  // ---- parameters
  const double fraction = static_cast<double>(
    choose_parameter(get_parameter(np, Polyvector_fields::internal_np::constrained_fraction), 0.01));
  const double threshold = static_cast<double>(
    choose_parameter(get_parameter(np, Polyvector_fields::internal_np::anisotropy_threshold), 0.5));
  if(!(fraction > 0. && fraction <= 1.) || !(threshold >= 0. && threshold <= 1.))
    return Error_code::INVALID_PARAMETER;

  // ---- faces
  std::vector<face_descriptor> face_list;
  face_list.reserve(num_faces(tm));
  internal::Numbering<face_descriptor> face_index;
  for(face_descriptor f : faces(tm))
  {
    face_index.add(f);
    face_list.push_back(f);
  }
  if(face_list.empty())
    return Error_code::EMPTY_MESH;
  for(face_descriptor f : face_list)
  {
    const halfedge_descriptor h = halfedge(f, tm);
    if(next(next(next(h, tm), tm), tm) != h)
      return Error_code::NON_TRIANGLE_FACE;
  }

  // ---- candidates, ranked by the curvature gap
  struct Candidate
  {
    std::size_t face;
    double gap;
  };
  std::vector<Candidate> candidates;
  for(std::size_t i = 0; i < face_list.size(); ++i)
  {
    const auto& pc = get(curvature_map, face_list[i]);
    if(!std::isfinite(pc.k1) || !std::isfinite(pc.k2) || !internal::curvature_vector_finite(pc.d1)
       || !internal::curvature_vector_finite(pc.d2))
      return Error_code::NON_FINITE_VALUE;
    const double gap = std::abs(pc.k1 - pc.k2);
    if(!std::isfinite(gap))
      return Error_code::NON_FINITE_VALUE;
    if(gap > 0. && internal::curvature_anisotropy(pc.k1, pc.k2) >= threshold
       && internal::curvature_vector_finite_nonzero(pc.d1) && internal::curvature_vector_finite_nonzero(pc.d2))
      candidates.push_back({ i, gap });
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.gap > b.gap; });

  const double budget_real = std::floor(fraction * double(face_list.size()));
  const std::size_t budget = budget_real < 1. ? std::size_t(1) : static_cast<std::size_t>(budget_real);
  const std::size_t rings = internal::curvature_exclusion_rings(fraction);

  // ---- greedy choice with exclusion of the k-ring of each chosen face
  internal::Numbering<vertex_descriptor> vertex_index;
  std::vector<vertex_descriptor> vertex_list;
  for(vertex_descriptor v : vertices(tm))
  {
    vertex_index.add(v);
    vertex_list.push_back(v);
  }
  std::vector<char> excluded(face_list.size(), 0);
  std::vector<std::size_t> vertex_stamp(vertex_list.size(), 0);
  std::vector<std::size_t> level, next_level;
  std::vector<std::size_t> chosen;
  std::size_t stamp = 0;

  for(const Candidate& candidate : candidates)
  {
    if(chosen.size() >= budget)
      break;
    if(excluded[candidate.face])
      continue;
    chosen.push_back(candidate.face);
    excluded[candidate.face] = 1;

    // Vertices at levels 0 .. rings-1 from the face; the faces around them are
    // the faces within `rings` rings.
    ++stamp;
    level.clear();
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(face_list[candidate.face], tm), tm))
    {
      const std::size_t vi = vertex_index(v);
      if(vertex_stamp[vi] != stamp)
      {
        vertex_stamp[vi] = stamp;
        level.push_back(vi);
      }
    }
    for(std::size_t depth = 0; depth < rings && !level.empty(); ++depth)
    {
      next_level.clear();
      for(std::size_t vi : level)
      {
        for(halfedge_descriptor h : CGAL::halfedges_around_target(vertex_list[vi], tm))
        {
          const face_descriptor g = face(h, tm);
          if(g == Graph_traits::null_face())
            continue;
          excluded[face_index(g)] = 1;
          if(depth + 1 < rings)
          {
            for(vertex_descriptor w : CGAL::vertices_around_face(h, tm))
            {
              const std::size_t wi = vertex_index(w);
              if(vertex_stamp[wi] != stamp)
              {
                vertex_stamp[wi] = stamp;
                next_level.push_back(wi);
              }
            }
          }
        }
      }
      level.swap(next_level);
    }
  }

  std::vector<Face_constraint<face_descriptor, Vector_3> > result;
  result.reserve(chosen.size());
  for(std::size_t i : chosen)
  {
    const auto& pc = get(curvature_map, face_list[i]);
    Face_constraint<face_descriptor, Vector_3> constraint;
    constraint.face = face_list[i];
    constraint.vectors.push_back(internal::curvature_convert_vector<Vector_3>(pc.d1));
    constraint.vectors.push_back(internal::curvature_convert_vector<Vector_3>(pc.d2));
    result.push_back(constraint);
  }
  out.swap(result);
  return Error_code::SUCCESS;
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
