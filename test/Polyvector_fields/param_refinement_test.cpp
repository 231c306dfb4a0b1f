// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// Tests of refine_for_quad_size() (issue 21): a coarse mesh refined for the
// quad size by splitting, on the surface, with its creases kept.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/refine_for_quad_size.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace {

namespace PVF = CGAL::Polyvector_fields;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index Face;

// The box [-1, 1]^3 as 12 triangles, two per side.
Mesh box()
{
  Mesh tm;
  std::vector<Mesh::Vertex_index> v;
  for(int i = 0; i < 8; ++i)
    v.push_back(tm.add_vertex(Point(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)));
  const int quads[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  for(const auto& q : quads)
  {
    tm.add_face(v[q[0]], v[q[1]], v[q[2]]);
    tm.add_face(v[q[0]], v[q[2]], v[q[3]]);
  }
  return tm;
}

std::array<Point, 3> corners(const Mesh& tm, Face f)
{
  const auto h = tm.halfedge(f);
  return { { tm.point(tm.source(h)), tm.point(tm.target(h)), tm.point(tm.target(tm.next(h))) } };
}

// Whether p lies in triangle t, to within tol (barycentric coordinates and distance to its plane).
bool inside(const Point& p, const std::array<Point, 3>& t, double tol)
{
  const K::Vector_3 n = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
  const double area2 = std::sqrt(n.squared_length());
  if(std::abs((p - t[0]) * n) / area2 > tol)
    return false;
  for(int k = 0; k < 3; ++k)
  {
    const K::Vector_3 nk = CGAL::cross_product(t[(k + 2) % 3] - t[(k + 1) % 3], p - t[(k + 1) % 3]);
    if(nk * n / (area2 * area2) < -tol)
      return false;
  }
  return true;
}

TEST(RefineForQuadSize, BoxIsSplitOnItsSidesWithItsEdgesKept)
{
  Mesh tm = box();
  const Mesh input = tm;
  std::vector<std::size_t> origin;
  ASSERT_EQ(PVF::refine_for_quad_size(tm, 0.1, origin), PVF::Error_code::SUCCESS);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(tm));
  ASSERT_TRUE(CGAL::is_closed(tm));
  ASSERT_TRUE(CGAL::is_triangle_mesh(tm));
  EXPECT_EQ(int(num_vertices(tm)) - int(num_edges(tm)) + int(num_faces(tm)), 2);
  ASSERT_EQ(origin.size(), num_faces(tm));
  EXPECT_GT(num_faces(tm), 12u * 50);  // sides of area 4 with edges of at most 0.2

  double longest = 0;
  for(auto e : edges(tm))
    longest = (std::max)(longest, PMP::edge_length(e, tm));
  EXPECT_LE(longest, 0.2);
  // Every vertex on the box, exactly: midpoints of points with a coordinate at +-1.
  for(auto v : vertices(tm))
  {
    const Point& p = tm.point(v);
    EXPECT_EQ((std::max)({ std::abs(p.x()), std::abs(p.y()), std::abs(p.z()) }), 1.0);
  }
  // The creases are kept: every triangle lies on one side (one coordinate at the
  // same +-1 for its three corners), so no face bends over a box edge.
  for(Face f : faces(tm))
  {
    const auto t = corners(tm, f);
    bool on_one_side = false;
    for(int axis = 0; axis < 3; ++axis)
      for(double side : { -1.0, 1.0 })
        on_one_side |= t[0][axis] == side && t[1][axis] == side && t[2][axis] == side;
    EXPECT_TRUE(on_one_side);
  }
  EXPECT_NEAR(PMP::area(tm), 24.0, 1e-12);
  // Each face lies in the face it was cut from.
  std::vector<std::array<Point, 3> > before;
  for(Face f : faces(input))
    before.push_back(corners(input, f));
  for(Face f : faces(tm))
  {
    const auto t = corners(tm, f);
    const Point c = CGAL::centroid(t[0], t[1], t[2]);
    ASSERT_LT(origin[std::size_t(f)], before.size());
    for(const Point& p : t)
      EXPECT_TRUE(inside(p, before[origin[std::size_t(f)]], 1e-12));
    EXPECT_TRUE(inside(c, before[origin[std::size_t(f)]], 1e-12));
  }
}

TEST(RefineForQuadSize, OriginValuesFollowTheFaces)
{
  Mesh tm = box();
  std::vector<std::size_t> origin;
  for(std::size_t i = 0; i < 12; ++i)
    origin.push_back(100 + i / 2);  // one value per side
  ASSERT_EQ(PVF::refine_for_quad_size(tm, 0.25, origin), PVF::Error_code::SUCCESS);
  std::vector<std::size_t> per_side(6, 0);
  for(Face f : faces(tm))
  {
    ASSERT_GE(origin[std::size_t(f)], 100u);
    ASSERT_LT(origin[std::size_t(f)], 106u);
    ++per_side[origin[std::size_t(f)] - 100];
  }
  // the box is symmetric and each side is split alike up to its diagonal
  for(std::size_t n : per_side)
    EXPECT_GT(n, 2u);
}

TEST(RefineForQuadSize, NothingToSplitAndBadInput)
{
  Mesh tm = box();
  std::vector<std::size_t> origin;
  ASSERT_EQ(PVF::refine_for_quad_size(tm, 2.0, origin), PVF::Error_code::SUCCESS);  // longest edge 2 sqrt(2) < 4
  EXPECT_EQ(num_faces(tm), 12u);
  ASSERT_EQ(origin.size(), 12u);
  for(std::size_t i = 0; i < 12; ++i)
    EXPECT_EQ(origin[i], i);

  origin.clear();
  EXPECT_EQ(PVF::refine_for_quad_size(tm, 0.0, origin), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::refine_for_quad_size(tm, -1.0, origin), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::refine_for_quad_size(tm, std::numeric_limits<double>::quiet_NaN(), origin),
            PVF::Error_code::NON_FINITE_VALUE);
  origin.assign(5, 0);
  EXPECT_EQ(PVF::refine_for_quad_size(tm, 0.1, origin), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(num_faces(tm), 12u);  // unchanged on error

  Mesh quad;
  const auto a = quad.add_vertex(Point(0, 0, 0)), b = quad.add_vertex(Point(1, 0, 0)),
             c = quad.add_vertex(Point(1, 1, 0)), d = quad.add_vertex(Point(0, 1, 0));
  quad.add_face(a, b, c, d);
  origin.clear();
  EXPECT_EQ(PVF::refine_for_quad_size(quad, 0.1, origin), PVF::Error_code::NON_TRIANGLE_FACE);
  EXPECT_EQ(num_faces(quad), 1u);
}

} // namespace
