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
// CGAL's Epick kernel decide exactly, whatever the magnitudes. A simple one is
// cut by ear clipping into triangles of positive area in the projection,
// oriented as the polygon. A non-planar polygon that is not simple there is
// triangulated in 3D instead, as a hole bounded by its vertices; a planar one
// is refused, since no triangulation of it would be a surface. A quad is split
// by its better diagonal, in 3D.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/polygon_soup.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
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

// The cosine of the dihedral angle between triangles (p, q, r) and (p, r, s)
// (1: flat, -1: folded onto each other), and the smallest angle of both, for
// the diagonal p-r of the quad (p, q, r, s). A degenerate triangle gives -2
// and 0.
inline void diagonal_quality(const std::array<double, 3>& p, const std::array<double, 3>& q,
                             const std::array<double, 3>& r, const std::array<double, 3>& s, double& cosine,
                             double& smallest_angle)
{
  typedef CGAL::Epick::Vector_3 Vector_3;
  const Vector_3 pq(q[0] - p[0], q[1] - p[1], q[2] - p[2]), pr(r[0] - p[0], r[1] - p[1], r[2] - p[2]),
    ps(s[0] - p[0], s[1] - p[1], s[2] - p[2]);
  const Vector_3 n1 = CGAL::cross_product(pq, pr), n2 = CGAL::cross_product(pr, ps);
  const double l1 = std::sqrt(n1.squared_length()), l2 = std::sqrt(n2.squared_length());
  if(!(l1 > 0) || !(l2 > 0) || !std::isfinite(l1 * l2))
  {
    cosine = -2;
    smallest_angle = 0;
    return;
  }
  cosine = (n1 * n2) / (l1 * l2);
  auto angles = [](const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c) {
    const std::array<const std::array<double, 3>*, 3> v{ { &a, &b, &c } };
    double smallest = 4;
    for(int k = 0; k < 3; ++k)
    {
      const std::array<double, 3>&o = *v[std::size_t(k)], &x = *v[std::size_t((k + 1) % 3)], &y = *v[std::size_t((k + 2) % 3)];
      const Vector_3 u(x[0] - o[0], x[1] - o[1], x[2] - o[2]), w(y[0] - o[0], y[1] - o[1], y[2] - o[2]);
      smallest = (std::min)(smallest, std::atan2(std::sqrt(CGAL::cross_product(u, w).squared_length()), u * w));
    }
    return smallest;
  };
  smallest_angle = (std::min)(angles(p, q, r), angles(p, r, s));
}

// Whether the points lie on one plane, exactly (false if they are all on one line).
inline bool is_planar(const std::vector<std::array<double, 3> >& points)
{
  typedef CGAL::Epick::Point_3 Point_3;
  std::vector<Point_3> p;
  for(const std::array<double, 3>& x : points)
    p.emplace_back(x[0], x[1], x[2]);
  const std::size_t n = p.size();
  std::size_t j = 1;
  while(j < n && p[j] == p[0])
    ++j;
  std::size_t k = j + 1;
  while(k < n && CGAL::collinear(p[0], p[j], p[k]))
    ++k;
  if(k >= n)
    return false;
  for(std::size_t i = 1; i < n; ++i)
    if(!CGAL::coplanar(p[0], p[j], p[k], p[i]))
      return false;
  return true;
}

// A quad split by its better diagonal: the one whose two triangles make the
// smaller dihedral angle (a planar convex quad: both are flat; a planar
// non-convex one: the other diagonal folds), then, within 1e-9 in cosine, the
// one with the larger smallest angle. Triangles oriented as the quad. Returns
// false (and adds nothing) if both diagonals fold the quad flat onto itself
// (dihedral angle within 1e-6 radians of pi), as a bow tie in its plane:
// then no triangulation of it is a surface.
inline bool triangulate_quad(const std::vector<std::array<double, 3> >& points,
                             std::vector<std::array<std::size_t, 3> >& triangles)
{
  double cosine[2], angle[2];
  diagonal_quality(points[0], points[1], points[2], points[3], cosine[0], angle[0]);  // diagonal 0-2
  diagonal_quality(points[1], points[2], points[3], points[0], cosine[1], angle[1]);  // diagonal 1-3
  const bool second = cosine[1] > cosine[0] + 1e-9 || (!(cosine[0] > cosine[1] + 1e-9) && angle[1] > angle[0]);
  if(!(cosine[second ? 1 : 0] > -1 + 5e-13))  // 1 - cos(pi - 1e-6) = 5e-13
    return false;
  if(second)
  {
    triangles.push_back({ { 1, 2, 3 } });
    triangles.push_back({ { 1, 3, 0 } });
  }
  else
  {
    triangles.push_back({ { 0, 1, 2 } });
    triangles.push_back({ { 0, 2, 3 } });
  }
  return true;
}

// Polygons of at most this many vertices that are not simple on their plane
// are triangulated in 3D by CGAL's triangulate_hole_polyline() (cubic in the
// size); larger ones by a fan.
constexpr std::size_t maximum_polygon_size_in_3d = 200;

// A polygon that is not simple on its plane: the triangulation of the closed
// polyline of its vertices that CGAL's triangulate_hole_polyline() finds
// (minimum dihedral angle, then area), oriented as the polygon; a fan from the
// first vertex when there is none or the polygon is too large.
inline void triangulate_polygon_in_3d(const std::vector<std::array<double, 3> >& points,
                                      std::vector<std::array<std::size_t, 3> >& triangles)
{
  const std::size_t n = points.size(), first = triangles.size();
  if(n <= maximum_polygon_size_in_3d)
  {
    std::vector<CGAL::Epick::Point_3> polyline;
    for(const std::array<double, 3>& p : points)
      polyline.emplace_back(p[0], p[1], p[2]);
    std::vector<CGAL::Triple<int, int, int> > patch;
    CGAL::Polygon_mesh_processing::triangulate_hole_polyline(polyline, std::back_inserter(patch));
    if(patch.size() == n - 2)
    {
      for(const CGAL::Triple<int, int, int>& t : patch)
      {
        // indices increasing along the polyline: oriented as the polygon
        std::array<std::size_t, 3> tri{ { std::size_t(t.first), std::size_t(t.second), std::size_t(t.third) } };
        std::sort(tri.begin(), tri.end());
        if(tri[2] >= n || tri[0] == tri[1] || tri[1] == tri[2])
        {
          triangles.resize(first);
          break;
        }
        triangles.push_back(tri);
      }
      if(triangles.size() == first + n - 2)
        return;
    }
  }
  for(std::size_t k = 1; k + 1 < n; ++k)
    triangles.push_back({ { 0, k, k + 1 } });
}

// Replaces every polygon of more than 3 vertices of `soup` by triangles that
// keep its `source` and its line, and counts the polygons split (and, in
// `in_3d`, the non-planar quads and the polygons triangulated in 3D). A quad is split
// by its better diagonal (triangulate_quad()); a larger polygon by ear
// clipping on its plane when it is simple there, else, if it is not planar,
// in 3D (triangulate_polygon_in_3d()). Refused: a polygon of more than
// maximum_polygon_size vertices, and a planar one that is not simple (a bow
// tie, a spike), which no triangulation makes a surface.
inline Error_code triangulate_soup_polygons(Polygon_soup& soup, std::vector<std::size_t>& source,
                                            std::size_t& triangulated, std::size_t& in_3d,
                                            const Diagnostic& diagnostic)
{
  triangulated = 0;
  in_3d = 0;
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
      if(n > maximum_polygon_size)
        return diagnostic.fail(Error_code::NON_TRIANGLE_FACE,
                               soup.face_name(i) + " has " + std::to_string(n) + " vertices, more than the " +
                                 std::to_string(maximum_polygon_size) + " that are triangulated");
      bool done = n == 4 ? triangulate_quad(corners, triangles) : triangulate_polygon(corners, triangles);
      if(done && n == 4 && !is_planar(corners))
        ++in_3d;
      if(!done && n == 4)
        done = triangulate_polygon(corners, triangles);
      if(!done && !is_planar(corners))
      {
        triangulate_polygon_in_3d(corners, triangles);
        ++in_3d;
        done = true;
      }
      if(!done)
        return diagnostic.fail(Error_code::NON_TRIANGLE_FACE,
                               soup.face_name(i) + " has " + std::to_string(n) +
                                 " vertices and is not a simple polygon on its plane: it folds onto itself, and no "
                                 "triangulation of it is a surface");
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
