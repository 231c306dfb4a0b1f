// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The work of refine_for_quad_size(): long edges split by CGAL's
// split_long_edges() until none is longer than two quads; then every edge
// that joins two feature vertices without being a feature itself is split at
// its midpoint. A triangle whose three vertices lie on features has two of
// them, or all three, on one integer iso-line of a feature-aligned map (an ear
// of the border, a triangle across a thin crease): it has no area in the map,
// whatever the solve. After the split every such triangle has a vertex off
// the features. Last, each face gets the value of the face it was cut from: the
// face at its place with the same corners, or else the face nearest to its
// centroid among the faces before (an AABB tree).

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_REFINEMENT_REFINEMENT_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_REFINEMENT_REFINEMENT_H

#include <CGAL/Polyvector_fields/Error_code.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Kernel_traits.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// Splits the interior edge e at its midpoint and the two faces beside it
// from the new vertex; the four new or shortened edges are not features.
template <typename TriangleMesh, typename VPM, typename FeatureMap>
void split_edge_and_faces(typename boost::graph_traits<TriangleMesh>::edge_descriptor e, TriangleMesh& tm, VPM vpm,
                          FeatureMap features)
{
  const auto h = halfedge(e, tm);
  const auto midpoint = CGAL::midpoint(get(vpm, source(h, tm)), get(vpm, target(h, tm)));
  // hnew runs from source(h) to the new vertex, and next(hnew) == h
  const auto hnew = CGAL::Euler::split_edge(h, tm);
  put(vpm, target(hnew, tm), midpoint);
  const auto a = CGAL::Euler::split_face(hnew, next(h, tm), tm);
  const auto o = opposite(h, tm);  // from target(h) to the new vertex
  const auto b = CGAL::Euler::split_face(o, next(opposite(hnew, tm), tm), tm);
  for(const auto g : { hnew, h, a, b })
    put(features, edge(g, tm), false);
}

template <typename TriangleMesh, typename VPM, typename FeatureMap>
Error_code refine_for_quad_size(TriangleMesh& tm, double quad_size, std::vector<std::size_t>& face_origin, VPM vpm,
                                FeatureMap features, bool with_border, std::size_t& feature_splits)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename boost::property_traits<VPM>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel K;
  typedef typename K::Triangle_3 Triangle;
  typedef typename std::vector<Triangle>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;

  feature_splits = 0;
  const std::size_t F = num_faces(tm);
  if(face_origin.empty())
    for(std::size_t i = 0; i < F; ++i)
      face_origin.push_back(i);
  if(face_origin.size() != F)
    return Error_code::INVALID_PARAMETER;

  const double max_length = 2 * quad_size;
  auto long_edges = [&]() {
    std::vector<edge_descriptor> found;
    for(auto e : edges(tm))
    {
      const auto h = halfedge(e, tm);
      if(std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm))))) >
         max_length)
        found.push_back(e);
    }
    return found;
  };
  auto is_feature = [&](edge_descriptor e) {
    return get(features, e) || (with_border && CGAL::is_border(e, tm));
  };
  auto on_feature = [&](typename GT::vertex_descriptor v) {
    for(const auto h : CGAL::halfedges_around_target(v, tm))
      if(is_feature(edge(h, tm)))
        return true;
    return false;
  };
  auto edges_between_features = [&]() {
    std::vector<edge_descriptor> found;
    for(auto e : edges(tm))
    {
      const auto h = halfedge(e, tm);
      if(!CGAL::is_border(e, tm) && !is_feature(e) && on_feature(source(h, tm)) && on_feature(target(h, tm)))
        found.push_back(e);
    }
    return found;
  };
  std::vector<edge_descriptor> to_split = long_edges(), between = edges_between_features();
  if(to_split.empty() && between.empty())
    return Error_code::SUCCESS;

  // The faces before: each face of the result lies inside one of them, and the
  // closest to its centroid is the one it was cut from.
  std::vector<Triangle> before;
  before.reserve(F);
  for(face_descriptor f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    before.emplace_back(get(vpm, source(h, tm)), get(vpm, target(h, tm)), get(vpm, target(next(h, tm), tm)));
  }
  // split_long_edges() splits the edges it is given (the halves of a feature
  // edge stay features); the edges it draws across the faces beside them can
  // be long too, so it is called until none is (each round at least halves the
  // longest edge of a face, so a few rounds suffice).
  for(int round = 0; round < 64 && !to_split.empty(); ++round)
  {
    CGAL::Polygon_mesh_processing::split_long_edges(
      to_split, max_length, tm, CGAL::parameters::vertex_point_map(vpm).edge_is_constrained_map(features));
    to_split = long_edges();
  }
  for(edge_descriptor e : edges_between_features())
  {
    split_edge_and_faces(e, tm, vpm, features);
    ++feature_splits;
  }
  Tree tree(before.begin(), before.end());
  // A face that keeps its place in faces(tm) and its three corners (most faces,
  // untouched by the splits) is the face that was there; the others are found in
  // the tree (its search structure is built at the first query, if there is one).
  std::vector<std::size_t> origin;
  origin.reserve(num_faces(tm));
  std::size_t i = 0;
  for(face_descriptor f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    const Point p[3] = { get(vpm, source(h, tm)), get(vpm, target(h, tm)), get(vpm, target(next(h, tm), tm)) };
    bool same = false;
    for(int r = 0; r < 3 && i < F && !same; ++r)
      same = p[0] == before[i][r] && p[1] == before[i][(r + 1) % 3] && p[2] == before[i][(r + 2) % 3];
    if(same)
      origin.push_back(face_origin[i]);
    else
    {
      const auto closest = tree.closest_point_and_primitive(CGAL::centroid(p[0], p[1], p[2]));
      origin.push_back(face_origin[std::size_t(closest.second - before.begin())]);
    }
    ++i;
  }
  face_origin.swap(origin);
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_REFINEMENT_REFINEMENT_H
