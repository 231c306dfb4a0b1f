// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_TRIANGULATE_POLYGONS_H
#define CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_TRIANGULATE_POLYGONS_H

// The triangulation of the polygons of a soup, for the mesh repair of
// read_triangle_mesh(). Each polygon is projected onto the coordinate plane
// most nearly parallel to it (the largest component of its Newell normal):
// dropping a coordinate keeps the doubles exact, so that the predicates of
// CGAL's Epick kernel decide exactly, whatever the magnitudes. A polygon whose
// projection is not simple is refused, since no triangulation of it would be
// a surface; a simple one is cut by ear clipping into triangles of positive
// area in the projection, oriented as the polygon.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/polygon_soup.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {
namespace internal {

// Polygons of more vertices are not triangulated (the checks are quadratic).
constexpr std::size_t maximum_polygon_size = 4096;

// Ear clipping of the polygon `points` (3D, n >= 3). Appends triangles of
// local indices to `triangles`. Returns false if the projection of the
// polygon is not a simple polygon of non-zero area.
inline bool triangulate_polygon(const std::vector<std::array<double, 3> >& points,
                                std::vector<std::array<std::size_t, 3> >& triangles)
{
  typedef CGAL::Epick::Point_2 Point_2;
  typedef CGAL::Epick::Segment_2 Segment_2;
  const std::size_t n = points.size();
  if(n > maximum_polygon_size)
    return false;
  // Newell normal, on coordinates scaled by a power of two so that it cannot
  // overflow; only the index of its largest component is used.
  double largest = 0.;
  for(const std::array<double, 3>& p : points)
    for(double x : p)
      largest = (std::max)(largest, std::abs(x));
  int exponent = 0;
  std::frexp(largest, &exponent);
  double normal[3] = { 0., 0., 0. };
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::array<double, 3>& p = points[k];
    const std::array<double, 3>& r = points[(k + 1) % n];
    for(int a = 0; a < 3; ++a)
    {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      normal[a] += std::ldexp(p[b] - r[b], -exponent) * std::ldexp(p[c] + r[c], -exponent);
    }
  }
  int axis = 0;
  for(int a = 1; a < 3; ++a)
    if(std::abs(normal[a]) > std::abs(normal[axis]))
      axis = a;
  std::vector<Point_2> q(n);
  for(std::size_t k = 0; k < n; ++k)
    q[k] = Point_2(points[k][(axis + 1) % 3], points[k][(axis + 2) % 3]);

  // Simple: non-adjacent edges do not meet, adjacent ones meet only at their
  // common vertex (no spike folding back along an edge).
  for(std::size_t i = 0; i < n; ++i)
  {
    const Segment_2 e(q[i], q[(i + 1) % n]);
    if(e.is_degenerate())
      return false;
    const Point_2& next = q[(i + 2) % n];
    if(CGAL::orientation(q[i], q[(i + 1) % n], next) == CGAL::COLLINEAR &&
       CGAL::angle(q[i], q[(i + 1) % n], next) == CGAL::ACUTE)
      return false;
    for(std::size_t j = i + 2; j < n; ++j)
      if(!(i == 0 && j == n - 1) && CGAL::do_intersect(e, Segment_2(q[j], q[(j + 1) % n])))
        return false;
  }

  // Counterclockwise, by the exact turn at the lexicographically smallest
  // vertex (strict there, the polygon being simple); else mirrored in x.
  std::size_t lowest = 0;
  for(std::size_t k = 1; k < n; ++k)
    if(CGAL::compare_xy(q[k], q[lowest]) == CGAL::SMALLER)
      lowest = k;
  if(CGAL::orientation(q[(lowest + n - 1) % n], q[lowest], q[(lowest + 1) % n]) != CGAL::LEFT_TURN)
    for(Point_2& point : q)
      point = Point_2(-point.x(), point.y());

  // Ear clipping on the polygon, now known to be simple.
  std::vector<std::size_t> left(n);
  for(std::size_t k = 0; k < n; ++k)
    left[k] = k;
  const std::size_t first = triangles.size();
  // k walks around the polygon; `misses` counts the vertices since the last ear.
  for(std::size_t k = 0, misses = 0; left.size() > 3;)
  {
    const std::size_t m = left.size();
    k %= m;
    if(misses > m) // no ear left: not simple after all (cannot happen in exact arithmetic)
    {
      triangles.resize(first);
      return false;
    }
    const std::size_t a = left[(k + m - 1) % m], b = left[k], c = left[(k + 1) % m];
    bool ear = CGAL::orientation(q[a], q[b], q[c]) == CGAL::LEFT_TURN;
    for(std::size_t i = 0; ear && i < m; ++i)
    {
      const std::size_t other = left[i];
      ear = other == a || other == b || other == c || CGAL::orientation(q[a], q[b], q[other]) == CGAL::RIGHT_TURN ||
            CGAL::orientation(q[b], q[c], q[other]) == CGAL::RIGHT_TURN ||
            CGAL::orientation(q[c], q[a], q[other]) == CGAL::RIGHT_TURN;
    }
    if(!ear)
    {
      ++k;
      ++misses;
      continue;
    }
    triangles.push_back({ { a, b, c } });
    left.erase(left.begin() + std::ptrdiff_t(k));
    k = (k + m - 2) % (m - 1); // back to the vertex before: it may have become an ear
    misses = 0;
  }
  if(CGAL::orientation(q[left[0]], q[left[1]], q[left[2]]) != CGAL::LEFT_TURN)
  {
    triangles.resize(first);
    return false;
  }
  triangles.push_back({ { left[0], left[1], left[2] } });
  return true;
}

// Replaces every polygon of more than 3 vertices of `soup` by triangles that
// keep its `source` and its line, and counts the polygons split.
inline Error_code triangulate_soup_polygons(Polygon_soup& soup, std::vector<std::size_t>& source,
                                            std::size_t& triangulated, const Diagnostic& diagnostic)
{
  triangulated = 0;
  // Every polygon has at least 3 vertices: 3 per polygon means triangles only,
  // and nothing to do.
  if(soup.ids.size() == 3 * soup.number_of_polygons())
    return Error_code::SUCCESS;
  Polygon_soup result;
  result.points = soup.points;
  result.point_line = soup.point_line;
  std::vector<std::size_t> result_source;
  std::vector<std::array<double, 3> > corners;
  std::vector<std::array<std::size_t, 3> > triangles;
  triangulated = 0;
  for(std::size_t i = 0; i < soup.number_of_polygons(); ++i)
  {
    const std::size_t* p = soup.polygon(i);
    const std::size_t n = soup.size(i);
    triangles.clear();
    if(n == 3)
      triangles.push_back({ { 0, 1, 2 } });
    else
    {
      corners.clear();
      for(std::size_t k = 0; k < n; ++k)
        corners.push_back(soup.points[p[k]]);
      if(!triangulate_polygon(corners, triangles))
        return diagnostic.fail(Error_code::NON_TRIANGLE_FACE,
                               soup.face_name(i) + " has " + std::to_string(n) +
                                 (n > maximum_polygon_size ? " vertices, more than the " + std::to_string(maximum_polygon_size) +
                                                              " that are triangulated"
                                                            : " vertices and is not a simple polygon on its plane: it "
                                                              "cannot be triangulated"));
      ++triangulated;
    }
    for(const std::array<std::size_t, 3>& t : triangles)
    {
      for(std::size_t corner : t)
        result.ids.push_back(p[corner]);
      result.first.push_back(result.ids.size());
      result_source.push_back(source[i]);
      if(i < soup.polygon_line.size())
        result.polygon_line.push_back(soup.polygon_line[i]);
    }
  }
  soup = std::move(result);
  source = std::move(result_source);
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_TRIANGULATE_POLYGONS_H
