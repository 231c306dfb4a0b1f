// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The planarity of quads (paper, Section 5).

#ifndef CGAL_POLYVECTOR_FIELDS_QUAD_PLANARITY_H
#define CGAL_POLYVECTOR_FIELDS_QUAD_PLANARITY_H

/// \file quad_planarity.h

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// the largest and the mean planarity of a quad mesh, filled by `quad_planarity()`.
struct Planarity_result
{
  std::size_t faces = 0;  ///< faces measured
  double max = 0;         ///< largest planarity
  double mean = 0;        ///< mean planarity
};

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// returns the planarity of the quad p0 p1 p2 p3: the distance between its diagonals divided
/// by their mean length. With d1 = p2 - p0, d2 = p3 - p1 and n = d1 x d2 / |d1 x d2|,
/// it is |n . (p1 - p0)| / ((|d1| + |d2|) / 2). Parallel diagonals: their distance
/// |(p1 - p0) x d1| / |d1|. Zero for a quad whose diagonals both vanish.
inline double quad_planarity(const std::array<double, 3>& p0, const std::array<double, 3>& p1,
                             const std::array<double, 3>& p2, const std::array<double, 3>& p3)
{
  auto sub = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{ a[0] - b[0], a[1] - b[1], a[2] - b[2] };
  };
  auto cross = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{ a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
  };
  auto dot = [](const std::array<double, 3>& a, const std::array<double, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const auto d1 = sub(p2, p0), d2 = sub(p3, p1), w = sub(p1, p0);
  const double l1 = std::sqrt(dot(d1, d1)), l2 = std::sqrt(dot(d2, d2));
  const double mean = (l1 + l2) / 2;
  if(!(mean > 0))
    return 0;
  const auto n = cross(d1, d2);
  const double nn = std::sqrt(dot(n, n));
  double distance;
  if(nn > 1e-14 * l1 * l2)
    distance = std::abs(dot(n, w)) / nn;
  else
  {
    const auto& d = l1 >= l2 ? d1 : d2;
    const auto c = cross(w, d);
    distance = std::sqrt(dot(c, c)) / (std::max)(l1, l2);
  }
  return distance / mean;
}

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// writes the planarity of every face of the quad mesh `pm` into `planarity_map`,
/// its vertices taken in the order of `halfedges_around_face(halfedge(f, pm), pm)`,
/// and fills `stats`. Computed in `double`, whatever the kernel.
///
/// \tparam PolygonMesh a model of `FaceListGraph`
/// \tparam FacePlanarityMap a model of `WritablePropertyMap` from faces of `pm` to `double`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<PolygonMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::SUCCESS`, `EMPTY_MESH`, or `NON_QUAD_FACE` (then neither `planarity_map` nor
///          `stats` is written beyond its reset).
///
/// \sa `planarize_quad_mesh()`, `IO::write_quad_mesh_VTK()`
template <typename PolygonMesh, typename FacePlanarityMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code quad_planarity(const PolygonMesh& pm, FacePlanarityMap planarity_map, Planarity_result& stats,
                          const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    CGAL::get_const_property_map(CGAL::vertex_point, pm));
  stats = Planarity_result();
  if(faces(pm).empty())
    return Error_code::EMPTY_MESH;
  for(auto f : faces(pm))
    if(degree(f, pm) != 4)
      return Error_code::NON_QUAD_FACE;
  double sum = 0;
  for(auto f : faces(pm))
  {
    std::array<std::array<double, 3>, 4> p;
    std::size_t i = 0;
    for(auto h : halfedges_around_face(halfedge(f, pm), pm))
    {
      const auto& x = get(vpm, target(h, pm));
      p[i++] = { CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z()) };
    }
    const double q = quad_planarity(p[0], p[1], p[2], p[3]);
    put(planarity_map, f, q);
    stats.max = (std::max)(stats.max, q);
    sum += q;
    ++stats.faces;
  }
  stats.mean = sum / double(stats.faces);
  return Error_code::SUCCESS;
}

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// writes the planarity of every face of `pm` into `planarity_map`, as the overload
/// with statistics.
template <typename PolygonMesh, typename FacePlanarityMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code quad_planarity(const PolygonMesh& pm, FacePlanarityMap planarity_map,
                          const NamedParameters& np = CGAL::parameters::default_values())
{
  Planarity_result stats;
  return quad_planarity(pm, planarity_map, stats, np);
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_QUAD_PLANARITY_H
