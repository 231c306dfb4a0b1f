// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_REFINE_FOR_QUAD_SIZE_H
#define CGAL_POLYVECTOR_FIELDS_REFINE_FOR_QUAD_SIZE_H

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Kernel_traits.h>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// refines the triangle mesh `tm` for a quad mesh of quad size `quad_size`: every
/// edge longer than `2 * quad_size` is split at its midpoint, and the faces on either
/// side with it, until no edge is longer
/// (`CGAL::Polygon_mesh_processing::split_long_edges()`).
///
/// A seamless map needs a few triangles per quad and room around each singularity;
/// on a coarse mesh (a box of 12 triangles, a cylinder whose caps are fans of long
/// thin triangles) the quads asked for are smaller than the triangles. Splitting
/// moves no vertex: every new vertex is the midpoint of an edge, so it lies on the
/// input surface, and an edge on a crease becomes edges on the same crease.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` with an internal point property map
///
/// \param tm the mesh, refined in place
/// \param quad_size the target quad size `h > 0`, in mesh units
/// \param face_origin on input, one value per face of `tm` in the order of `faces(tm)`
///        (for example the face's position in a file); on output, one value per face of the
///        refined mesh, in the order of `faces(tm)`: the value of the face it was cut from.
///        An empty vector on input gives the faces' positions.
///
/// \returns `SUCCESS`; `INVALID_PARAMETER` if `quad_size` is not positive or `face_origin`
///          has neither 0 nor `num_faces(tm)` entries; `NON_FINITE_VALUE` for a non-finite
///          `quad_size`; `NON_TRIANGLE_FACE` if a face is not a triangle. On error, `tm`
///          is unchanged.
template <typename TriangleMesh>
Error_code refine_for_quad_size(TriangleMesh& tm, double quad_size, std::vector<std::size_t>& face_origin)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel K;
  typedef typename K::Triangle_3 Triangle;
  typedef typename std::vector<Triangle>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;

  if(!std::isfinite(quad_size))
    return Error_code::NON_FINITE_VALUE;
  if(!(quad_size > 0))
    return Error_code::INVALID_PARAMETER;
  if(!CGAL::is_triangle_mesh(tm))
    return Error_code::NON_TRIANGLE_FACE;
  const std::size_t F = num_faces(tm);
  if(face_origin.empty())
    for(std::size_t i = 0; i < F; ++i)
      face_origin.push_back(i);
  if(face_origin.size() != F)
    return Error_code::INVALID_PARAMETER;

  const double max_length = 2 * quad_size;
  const VPM vpm = get(CGAL::vertex_point, tm);
  auto long_edges = [&]() {
    std::vector<typename GT::edge_descriptor> found;
    for(auto e : edges(tm))
    {
      const auto h = halfedge(e, tm);
      if(std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm))))) >
         max_length)
        found.push_back(e);
    }
    return found;
  };
  std::vector<typename GT::edge_descriptor> to_split = long_edges();
  if(to_split.empty())
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
  // split_long_edges() splits the edges it is given; the edges it draws across the
  // faces beside them can be long too, so it is called until none is (each round
  // at least halves the longest edge of a face, so a few rounds suffice).
  for(int round = 0; round < 64 && !to_split.empty(); ++round)
  {
    CGAL::Polygon_mesh_processing::split_long_edges(to_split, max_length, tm);
    to_split = long_edges();
  }
  Tree tree(before.begin(), before.end());
  tree.accelerate_distance_queries();
  std::vector<std::size_t> origin;
  origin.reserve(num_faces(tm));
  for(face_descriptor f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    const Point c = CGAL::centroid(get(vpm, source(h, tm)), get(vpm, target(h, tm)), get(vpm, target(next(h, tm), tm)));
    const auto closest = tree.closest_point_and_primitive(c);
    origin.push_back(face_origin[std::size_t(closest.second - before.begin())]);
  }
  face_origin.swap(origin);
  return Error_code::SUCCESS;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_REFINE_FOR_QUAD_SIZE_H
