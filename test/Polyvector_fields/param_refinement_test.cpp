// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// Tests of refine_for_quad_size() (issue 21): a coarse mesh refined for the
// quad size by splitting, on the surface, with its creases kept; and of the
// features it prepares: sharp edges and the border on integer iso-lines of
// the map (compute_integer_grid_map()), so that a box becomes a box of quads.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/compute_integer_grid_map.h>
#include <CGAL/Polyvector_fields/design_polyvector_field.h>
#include <CGAL/Polyvector_fields/extract_quad_mesh.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>
#include <CGAL/Polyvector_fields/refine_for_quad_size.h>
#include <CGAL/Polyvector_fields/select_sharp_edge_constraints.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <vector>

namespace {

namespace PVF = CGAL::Polyvector_fields;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index Face;
typedef Mesh::Edge_index Edge;
typedef K::Vector_3 Vector;
typedef PVF::Face_constraint<Face, Vector> Constraint;

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

// ---------------------------------------------------------------------------
// Features: sharp edges and the border on integer iso-lines.
// ---------------------------------------------------------------------------

// Whether the three corners of face f lie on features (feature edges, and the
// border when `border` is set).
bool three_feature_corners(const Mesh& tm, Face f, const Mesh::Property_map<Edge, bool>& features, bool border)
{
  for(auto h : CGAL::halfedges_around_face(tm.halfedge(f), tm))
  {
    bool on_feature = false;
    for(auto g : CGAL::halfedges_around_target(tm.target(h), tm))
      on_feature |= features[tm.edge(g)] || (border && tm.is_border(tm.edge(g)));
    if(!on_feature)
      return false;
  }
  return true;
}

// A triangle with its three corners on features has no area in a map that
// puts the features on iso-lines; the refinement splits the edges that join
// two feature vertices without being features.
TEST(RefineForQuadSize, EdgesBetweenFeaturesAreSplit)
{
  // the box: every diagonal of a side joins two box corners
  Mesh tm = box();
  auto features = tm.add_property_map<Edge, bool>("e:feature", false).first;
  std::vector<Constraint> constraints;
  ASSERT_EQ(PVF::select_sharp_edge_constraints(tm, 40, 2, constraints,
                                               CGAL::parameters::edge_is_constrained_map(features)),
            PVF::Error_code::SUCCESS);
  std::size_t sharp = 0;
  for(Edge e : edges(tm))
    sharp += features[e];
  EXPECT_EQ(sharp, 12u);
  std::vector<std::size_t> origin;
  // a quad size larger than the box: only the diagonals are split
  ASSERT_EQ(PVF::refine_for_quad_size(tm, 10.0, origin, CGAL::parameters::edge_is_constrained_map(features)),
            PVF::Error_code::SUCCESS);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(tm));
  EXPECT_EQ(num_faces(tm), 24u);
  EXPECT_EQ(num_vertices(tm), 14u);
  EXPECT_NEAR(PMP::area(tm), 24.0, 1e-12);
  sharp = 0;
  for(Edge e : edges(tm))
    sharp += features[e];
  EXPECT_EQ(sharp, 12u);  // the box edges, not split, still features; the new edges are not
  for(Face f : faces(tm))
    EXPECT_FALSE(three_feature_corners(tm, f, features, false));

  // a square of two triangles: with the border as a feature, its diagonal is split
  Mesh square;
  const auto a = square.add_vertex(Point(0, 0, 0)), b = square.add_vertex(Point(3, 0, 0)),
             c = square.add_vertex(Point(3, 2, 0)), d = square.add_vertex(Point(0, 2, 0));
  square.add_face(a, b, c);
  square.add_face(a, c, d);
  Mesh free_border = square;
  origin.clear();
  ASSERT_EQ(PVF::refine_for_quad_size(free_border, 10.0, origin), PVF::Error_code::SUCCESS);
  EXPECT_EQ(num_faces(free_border), 2u);  // no feature: nothing to split
  origin.clear();
  ASSERT_EQ(PVF::refine_for_quad_size(square, 10.0, origin, PVF::parameters::boundary_alignment(true)),
            PVF::Error_code::SUCCESS);
  EXPECT_EQ(num_faces(square), 4u);
  const auto none = square.add_property_map<Edge, bool>("e:feature", false).first;
  for(Face f : faces(square))
    EXPECT_FALSE(three_feature_corners(square, f, none, true));
}

// The road of a user's mesh with features, as the command-line program takes
// it: the features found on the coarse mesh, the refinement for the quad size,
// the constraints along the features on the refined mesh, the field, the map
// with the features on iso-lines, the quads.
struct Feature_road
{
  Mesh tm;
  Mesh::Property_map<Edge, bool> features;
  PVF::Integer_grid_map_result map;
  PVF::Quad_extraction_result extraction;
  Mesh quads;
};

void feature_road(Mesh input, double h, bool border, Feature_road& road)
{
  road.tm = input;
  Mesh& tm = road.tm;
  road.features = tm.add_property_map<Edge, bool>("e:feature", false).first;
  const auto np = PVF::parameters::boundary_alignment(border);
  std::vector<Constraint> constraints;
  ASSERT_EQ(PVF::select_sharp_edge_constraints(tm, 40, 2, constraints, np.edge_is_constrained_map(road.features)),
            PVF::Error_code::SUCCESS);
  std::vector<std::size_t> origin;
  ASSERT_EQ(PVF::refine_for_quad_size(tm, h, origin, np.edge_is_constrained_map(road.features)),
            PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::select_sharp_edge_constraints(tm, 40, 2, constraints, np.edge_is_constrained_map(road.features)),
            PVF::Error_code::SUCCESS);
  auto field = tm.add_property_map<Face, std::vector<std::complex<double> > >("f:field").first;
  ASSERT_EQ(PVF::design_polyvector_field(tm, 4, constraints, field, PVF::parameters::sign_symmetric(true)),
            PVF::Error_code::SUCCESS);
  auto uv = tm.add_property_map<Mesh::Halfedge_index, std::array<double, 2> >("h:uv").first;
  const PVF::Tangent_bundle<Mesh> bundle(tm);
  const PVF::Error_code code = PVF::compute_integer_grid_map(
    bundle, field, uv, road.map,
    PVF::parameters::target_edge_length(h, PVF::parameters::boundary_alignment(border))
      .edge_is_constrained_map(road.features));
  ASSERT_EQ(code, PVF::Error_code::SUCCESS) << PVF::get_error_message(code) << " " << road.map.diagnostic;
  ASSERT_EQ(PVF::extract_quad_mesh(bundle, uv, road.map, road.quads, road.extraction), PVF::Error_code::SUCCESS);
}

// The area of a polygon mesh, each face as the fan of triangles from its first
// vertex (PMP::area() takes the faces as triangles).
double polygon_area(const Mesh& m)
{
  double area = 0;
  for(Face f : faces(m))
  {
    std::vector<Point> p;
    for(auto v : CGAL::vertices_around_face(m.halfedge(f), m))
      p.push_back(m.point(v));
    for(std::size_t k = 1; k + 1 < p.size(); ++k)
      area += std::sqrt(CGAL::squared_area(p[0], p[k], p[k + 1]));
  }
  return area;
}

std::size_t valence(const Mesh& m, Mesh::Vertex_index v)
{
  std::size_t n = 0;
  for(auto h : CGAL::halfedges_around_target(v, m))
  {
    (void)h;
    ++n;
  }
  return n;
}

// Issue 21: "A box becomes a box: six grids, 8 corners of valence 3, every box
// edge made of quad edges, planarity 0."
TEST(Features, BoxBecomesABoxOfQuads)
{
  Feature_road road;
  feature_road(box(), 0.25, false, road);
  if(HasFatalFailure())
    return;
  const PVF::Integer_grid_map_result& r = road.map;
  // every piece of the 12 box edges (length 24 in all) is a feature, on an iso-line
  std::size_t features = 0;
  double feature_length = 0;
  for(Edge e : edges(road.tm))
    if(road.features[e])
    {
      ++features;
      feature_length += PMP::edge_length(e, road.tm);
    }
  EXPECT_NEAR(feature_length, 24.0, 1e-12);
  EXPECT_EQ(r.feature_edges, features);
  EXPECT_EQ(r.aligned_feature_edges, features);
  EXPECT_EQ(r.unaligned_feature_edges + r.dropped_feature_edges + r.released_feature_edges, 0u);
  EXPECT_EQ(r.flipped_faces, 0u);
  EXPECT_EQ(r.comb.singular_vertices, 8u);

  // six 8 x 8 grids: sides of 2 at quads of 0.25
  const Mesh& q = road.quads;
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(q));
  ASSERT_TRUE(CGAL::is_closed(q));
  EXPECT_EQ(num_faces(q), 6u * 64);
  EXPECT_EQ(num_vertices(q), 6u * 64 + 2);
  for(Face f : faces(q))
    EXPECT_EQ(CGAL::halfedges_around_face(q.halfedge(f), q).size(), 4u);
  // valence 3 exactly at the 8 box corners, 4 elsewhere
  std::size_t corners = 0;
  for(auto v : vertices(q))
  {
    const Point& p = q.point(v);
    const bool corner = std::abs(std::abs(p.x()) - 1) < 1e-12 && std::abs(std::abs(p.y()) - 1) < 1e-12 &&
                        std::abs(std::abs(p.z()) - 1) < 1e-12;
    corners += corner;
    EXPECT_EQ(valence(q, v), corner ? 3u : 4u);
  }
  EXPECT_EQ(corners, 8u);
  // the box edges are made of quad edges: those with two coordinates at +-1 add up to 24
  double on_box_edges = 0;
  for(Edge e : edges(q))
  {
    const Point& s = q.point(q.source(q.halfedge(e)));
    const Point& t = q.point(q.target(q.halfedge(e)));
    int extreme = 0;
    for(int axis = 0; axis < 3; ++axis)
      extreme += std::abs(std::abs(s[axis]) - 1) < 1e-12 && std::abs(std::abs(t[axis]) - 1) < 1e-12 &&
                 std::abs(s[axis] - t[axis]) < 1e-12;
    if(extreme >= 2)
      on_box_edges += PMP::edge_length(e, q);
  }
  EXPECT_NEAR(on_box_edges, 24.0, 1e-9);
  // planar: every quad lies on one side of the box
  auto planarity = road.quads.add_property_map<Face, double>("f:planarity").first;
  PVF::Planarity_result stats;
  ASSERT_EQ(PVF::quad_planarity(road.quads, planarity, stats), PVF::Error_code::SUCCESS);
  EXPECT_LT(stats.max, 1e-12);
  EXPECT_NEAR(polygon_area(q), 24.0, 1e-9);
}

// Issue 21: with the border on iso-lines, the quads cover the surface up to its
// edge (without, only the whole cells inside it are kept).
TEST(Features, BorderOnIsoLinesIsCoveredToTheEdge)
{
  Mesh square;
  const auto a = square.add_vertex(Point(0, 0, 0)), b = square.add_vertex(Point(3, 0, 0)),
             c = square.add_vertex(Point(3, 2, 0)), d = square.add_vertex(Point(0, 2, 0));
  square.add_face(a, b, c);
  square.add_face(a, c, d);
  Feature_road road;
  feature_road(square, 0.25, true, road);
  if(HasFatalFailure())
    return;
  const PVF::Integer_grid_map_result& r = road.map;
  EXPECT_GT(r.feature_edges, 0u);
  EXPECT_EQ(r.aligned_feature_edges, r.feature_edges);
  EXPECT_EQ(r.comb.singular_vertices, 0u);
  // 12 x 8 quads of 0.25 cover the 3 x 2 square exactly
  const Mesh& q = road.quads;
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(q));
  EXPECT_EQ(num_faces(q), 96u);
  EXPECT_EQ(num_vertices(q), 13u * 9);
  EXPECT_NEAR(polygon_area(q), 6.0, 1e-9);
  double border = 0;
  for(auto h : halfedges(q))
    if(q.is_border(h))
      border += PMP::edge_length(h, q);
  EXPECT_NEAR(border, 10.0, 1e-9);
}

// Issue 21: a feature curve that bends at a vertex between two edges longer
// than a quad (the rim of a coarse cylinder) has a quad corner there, so that
// the quad edges, straight in space, follow the polygon instead of cutting its
// corners. Without it, the 16-gon rims below get 31 or 32 quad edges each
// whose ends fall anywhere on the polygon.
TEST(Features, PolygonalRimHasAQuadCornerAtEveryBend)
{
  const int sides = 16;
  const double pi = CGAL_PI;
  // the open cylinder of radius 1 and height 1 on two 16-gons, one quad (two
  // triangles) per side; the polygon is uneven (sides of 1.35 to 2.5 quads),
  // so that a map without corners would not meet its vertices by chance
  auto angle = [&](int i) { return 2 * pi * i / sides + 0.06 * std::sin(3.0 * i); };
  Mesh cylinder;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j <= 1; ++j)
    for(int i = 0; i < sides; ++i)
      v.push_back(cylinder.add_vertex(Point(std::cos(angle(i)), std::sin(angle(i)), double(j))));
  for(int i = 0; i < sides; ++i)
  {
    const int k = (i + 1) % sides;
    cylinder.add_face(v[i], v[k], v[sides + k]);
    cylinder.add_face(v[i], v[sides + k], v[sides + i]);
  }
  Feature_road road;
  feature_road(cylinder, 0.2, true, road);
  if(HasFatalFailure())
    return;
  const PVF::Integer_grid_map_result& r = road.map;
  EXPECT_EQ(r.aligned_feature_edges, r.feature_edges);
  EXPECT_EQ(r.flipped_faces, 0u);
  // the 2 x 16 rim vertices are quad vertices
  const Mesh& q = road.quads;
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(q));
  std::size_t rim_corners = 0;
  for(int j = 0; j <= 1; ++j)
    for(int i = 0; i < sides; ++i)
    {
      const Point p(std::cos(angle(i)), std::sin(angle(i)), double(j));
      double nearest = std::numeric_limits<double>::infinity();
      for(auto v : vertices(q))
        nearest = (std::min)(nearest, std::sqrt(CGAL::squared_distance(p, q.point(v))));
      rim_corners += nearest < 1e-9;
    }
  EXPECT_EQ(rim_corners, std::size_t(2 * sides));
  // the quad mesh's border is the two polygons
  double border = 0, perimeter = 0;
  for(auto h : halfedges(q))
    if(q.is_border(h))
      border += PMP::edge_length(h, q);
  for(int i = 0; i < sides; ++i)
    perimeter += 2 * 2 * std::abs(std::sin((angle((i + 1) % sides) - angle(i)) / 2));
  EXPECT_NEAR(border, perimeter, 1e-9);
}

} // namespace
