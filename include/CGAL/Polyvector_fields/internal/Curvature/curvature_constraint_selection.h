// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_CURVATURE_CONSTRAINT_SELECTION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_CURVATURE_CONSTRAINT_SELECTION_H

// The rule of select_curvature_constraints(): the anisotropic faces ranked by
// their curvature gap, chosen greedily with the exclusion of the k-ring of
// each chosen face.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Face_constraint.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
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

// A face that may be constrained (its position in the face list) and its curvature gap |k1 - k2|.
struct Curvature_candidate
{
  std::size_t face;
  double gap;
};

// The candidates (rule, steps 1 and 2), ranked by decreasing gap, ties in the
// order of `face_list`. Returns NON_FINITE_VALUE if a curvature or a direction is.
template <typename CurvatureMap, typename FaceDescriptor>
Error_code curvature_candidates(CurvatureMap curvature_map, const std::vector<FaceDescriptor>& face_list,
                                double threshold, std::vector<Curvature_candidate>& candidates)
{
  using boost::get;
  for(std::size_t i = 0; i < face_list.size(); ++i)
  {
    const auto& pc = get(curvature_map, face_list[i]);
    if(!std::isfinite(pc.k1) || !std::isfinite(pc.k2) || !curvature_vector_finite(pc.d1)
       || !curvature_vector_finite(pc.d2))
      return Error_code::NON_FINITE_VALUE;
    const double gap = std::abs(pc.k1 - pc.k2);
    if(!std::isfinite(gap))
      return Error_code::NON_FINITE_VALUE;
    if(gap > 0. && curvature_anisotropy(pc.k1, pc.k2) >= threshold && curvature_vector_finite_nonzero(pc.d1)
       && curvature_vector_finite_nonzero(pc.d2))
      candidates.push_back({ i, gap });
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Curvature_candidate& a, const Curvature_candidate& b) { return a.gap > b.gap; });
  return Error_code::SUCCESS;
}

// The greedy choice (rule, steps 3 and 4): at most `budget` candidates, in
// their order, each excluding the faces within `rings` rings of it. Returns
// the positions of the chosen faces in `face_list`, in the order chosen.
template <typename TriangleMesh>
std::vector<std::size_t> choose_spread_faces(
  const TriangleMesh& tm, const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_list,
  const Numbering<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_index,
  const std::vector<Curvature_candidate>& candidates, std::size_t budget, std::size_t rings)
{
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::face_descriptor face_descriptor;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename Graph_traits::halfedge_descriptor halfedge_descriptor;

  Numbering<vertex_descriptor> vertex_index;
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
  // Marks the vertex `w` as reached at this stamp and adds it to `to`.
  auto reach = [&](vertex_descriptor w, std::vector<std::size_t>& to) {
    const std::size_t wi = vertex_index(w);
    if(vertex_stamp[wi] != stamp)
    {
      vertex_stamp[wi] = stamp;
      to.push_back(wi);
    }
  };

  for(const Curvature_candidate& candidate : candidates)
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
      reach(v, level);
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
            for(vertex_descriptor w : CGAL::vertices_around_face(h, tm))
              reach(w, next_level);
        }
      }
      level.swap(next_level);
    }
  }
  return chosen;
}

// The whole rule on valid parameters: the faces, their checks, the candidates,
// the choice, and the constraints, written to `out` only on success.
template <typename TriangleMesh, typename CurvatureMap, typename Vector_3>
Error_code select_curvature_constraint_faces(
  const TriangleMesh& tm, CurvatureMap curvature_map, double fraction, double threshold,
  std::vector<Face_constraint<typename boost::graph_traits<TriangleMesh>::face_descriptor, Vector_3> >& out)
{
  using boost::get;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  // ---- faces
  std::vector<face_descriptor> face_list;
  face_list.reserve(num_faces(tm));
  Numbering<face_descriptor> face_index;
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
  std::vector<Curvature_candidate> candidates;
  const Error_code code = curvature_candidates(curvature_map, face_list, threshold, candidates);
  if(code != Error_code::SUCCESS)
    return code;

  const double budget_real = std::floor(fraction * double(face_list.size()));
  const std::size_t budget = budget_real < 1. ? std::size_t(1) : static_cast<std::size_t>(budget_real);
  const std::size_t rings = curvature_exclusion_rings(fraction);

  // ---- greedy choice with exclusion of the k-ring of each chosen face
  const std::vector<std::size_t> chosen = choose_spread_faces(tm, face_list, face_index, candidates, budget, rings);

  std::vector<Face_constraint<face_descriptor, Vector_3> > result;
  result.reserve(chosen.size());
  for(std::size_t i : chosen)
  {
    const auto& pc = get(curvature_map, face_list[i]);
    Face_constraint<face_descriptor, Vector_3> constraint;
    constraint.face = face_list[i];
    constraint.vectors.push_back(curvature_convert_vector<Vector_3>(pc.d1));
    constraint.vectors.push_back(curvature_convert_vector<Vector_3>(pc.d2));
    result.push_back(constraint);
  }
  out.swap(result);
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_CURVATURE_CURVATURE_CONSTRAINT_SELECTION_H
