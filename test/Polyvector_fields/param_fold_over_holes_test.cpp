// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Tests of the quads that fill a polygon (with holes), of the fold-overs cut out of a
// map and filled, and of the tips that pull quad corners (issue 21). The properties
// are measured here from the outputs: areas, sides, Euler characteristics and
// distances written out in this file, and the check of each component's quads. Everything but the tests is in an anonymous
// namespace with Holes names, and the suites are named Holes*.

#include "test_meshes.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/point_generators_2.h>
#include <CGAL/random_polygon_2.h>

#include <CGAL/Polyvector_fields/extract_quad_mesh.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/component_check.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/fold_over_holes.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/polygon_quadrangulation.h>
#include <CGAL/property_map.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace PVF = CGAL::Polyvector_fields;
namespace QX = CGAL::Polyvector_fields::internal::qex;
using namespace pvf_test;  // Mesh, Point, Kernel, data, euler_characteristic, ...
typedef std::array<double, 2> Holes_point;
typedef std::vector<Holes_point> Holes_loop;

double holes_signed_area(const Holes_loop& loop)
{
  double a = 0;
  for(std::size_t i = 0; i < loop.size(); ++i)
  {
    const Holes_point &p = loop[i], &q = loop[(i + 1) % loop.size()];
    a += 0.5 * (p[0] * q[1] - q[0] * p[1]);
  }
  return a;
}

// What a filling of `loops` must be: every quad turns counterclockwise along both
// triangles of one of its diagonals, the quads' areas add up to the domain's, each side
// of a loop is a side of exactly one quad (in the loop's direction) and every other side
// of a quad is a side of exactly two (in opposite directions).
void holes_check_filling(const std::vector<Holes_loop>& loops, const QX::Quadrangulated_polygon& out)
{
  std::size_t n = 0;
  double domain = 0;
  std::map<std::pair<std::size_t, std::size_t>, int> loop_sides;
  for(const Holes_loop& loop : loops)
  {
    for(std::size_t i = 0; i < loop.size(); ++i)
    {
      ASSERT_EQ(out.points[n + i], loop[i]);  // the corners first, unmoved
      loop_sides[std::make_pair(n + i, n + (i + 1) % loop.size())] = 0;
    }
    n += loop.size();
    domain += holes_signed_area(loop);
  }
  double area = 0;
  std::map<std::pair<std::size_t, std::size_t>, int> sides;
  for(const auto& q : out.quads)
  {
    const Holes_point &a = out.points[q[0]], &b = out.points[q[1]], &c = out.points[q[2]], &d = out.points[q[3]];
    auto turn = [](const Holes_point& x, const Holes_point& y, const Holes_point& z) {
      return (y[0] - x[0]) * (z[1] - x[1]) - (y[1] - x[1]) * (z[0] - x[0]);
    };
    EXPECT_TRUE((turn(a, b, c) > 0 && turn(a, c, d) > 0) || (turn(b, c, d) > 0 && turn(b, d, a) > 0));
    area += 0.5 * (turn(a, b, c) + turn(a, c, d));
    for(int k = 0; k < 4; ++k)
      ++sides[std::make_pair(q[k], q[(k + 1) % 4])];
  }
  EXPECT_NEAR(area, domain, 1e-9 * std::abs(domain));
  for(const auto& s : sides)
  {
    EXPECT_EQ(s.second, 1);
    const bool on_loop = loop_sides.count(s.first) != 0;
    const bool twin = sides.count(std::make_pair(s.first.second, s.first.first)) != 0;
    EXPECT_NE(on_loop, twin) << "side " << s.first.first << " " << s.first.second;
    if(on_loop)
      ++loop_sides[s.first];
  }
  for(const auto& s : loop_sides)
    EXPECT_EQ(s.second, 1) << "loop side " << s.first.first << " " << s.first.second;
}

double holes_mean_side(const Holes_loop& loop)
{
  double sum = 0;
  for(std::size_t i = 0; i < loop.size(); ++i)
    sum += std::hypot(loop[(i + 1) % loop.size()][0] - loop[i][0], loop[(i + 1) % loop.size()][1] - loop[i][1]);
  return sum / double(loop.size());
}

// The map of a mesh, read from an OBJ with one texture coordinate per corner (as
// IO::write_integer_grid_map_OBJ() writes it).
struct Holes_map
{
  Mesh tm;
  Mesh::Property_map<Mesh::Halfedge_index, std::array<double, 2> > uv;
};

Holes_map holes_read_map(const std::string& path)
{
  Holes_map m;
  m.uv = m.tm.add_property_map<Mesh::Halfedge_index, std::array<double, 2> >("h:uv").first;
  std::ifstream in(path);
  std::vector<Mesh::Vertex_index> v;
  std::vector<std::array<double, 2> > t;
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if(tag == "v")
    {
      double x, y, z;
      s >> x >> y >> z;
      v.push_back(m.tm.add_vertex(Point(x, y, z)));
    }
    else if(tag == "vt")
    {
      double a, b;
      s >> a >> b;
      t.push_back({ a, b });
    }
    else if(tag == "f")
    {
      std::array<std::size_t, 3> pv, pt;
      for(std::size_t k = 0; k < 3; ++k)
      {
        std::string corner;
        s >> corner;
        const std::size_t slash = corner.find('/');
        pv[k] = std::stoul(corner.substr(0, slash)) - 1;
        pt[k] = std::stoul(corner.substr(slash + 1)) - 1;
      }
      const Mesh::Face_index f = m.tm.add_face(v[pv[0]], v[pv[1]], v[pv[2]]);
      EXPECT_NE(f, Mesh::null_face());
      for(Mesh::Halfedge_index h : halfedges_around_face(halfedge(f, m.tm), m.tm))
        for(std::size_t k = 0; k < 3; ++k)
          if(target(h, m.tm) == v[pv[k]])
            m.uv[h] = t[pt[k]];
    }
  }
  return m;
}

// The faces of a mesh as triangles: a triangle as it is, a quad cut along both of its
// diagonals (four triangles: the distance to them is at most the distance to either
// way of cutting it).
std::vector<Kernel::Triangle_3> holes_triangles(const Mesh& m)
{
  std::vector<Kernel::Triangle_3> t;
  for(Mesh::Face_index f : faces(m))
  {
    std::vector<Point> c;
    for(Mesh::Halfedge_index h : halfedges_around_face(halfedge(f, m), m))
      c.push_back(m.point(target(h, m)));
    if(c.size() == 3)
      t.emplace_back(c[0], c[1], c[2]);
    else if(c.size() == 4)
      for(std::size_t k = 0; k < 4; ++k)
        t.emplace_back(c[k], c[(k + 1) % 4], c[(k + 2) % 4]);
    else
      ADD_FAILURE() << "a face of " << c.size() << " corners";
  }
  return t;
}

double holes_diagonal(const Mesh& tm)
{
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(tm);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

// the largest distance of a vertex of `from` to the faces of `to`
double holes_largest_distance(const Mesh& from, const Mesh& to)
{
  typedef std::vector<Kernel::Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<Kernel, Iterator> Primitive;
  const std::vector<Kernel::Triangle_3> triangles = holes_triangles(to);
  CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive> > tree(triangles.cbegin(), triangles.cend());
  tree.accelerate_distance_queries();
  double d = 0;
  for(Mesh::Vertex_index v : vertices(from))
    d = (std::max)(d, std::sqrt(tree.squared_distance(from.point(v))));
  return d;
}

double holes_area(const Mesh& m)
{
  double a = 0;
  for(Mesh::Face_index f : faces(m))
  {
    std::vector<Point> p;
    for(Mesh::Halfedge_index h : halfedges_around_face(halfedge(f, m), m))
      p.push_back(m.point(target(h, m)));
    for(std::size_t k = 1; k + 1 < p.size(); ++k)
      a += std::sqrt(CGAL::cross_product(p[k] - p[0], p[k + 1] - p[0]).squared_length()) / 2;
  }
  return a;
}

// The quads of a cube on points first..first+7, outward.
std::vector<std::vector<std::size_t> > holes_cube_quads(std::size_t first)
{
  const std::size_t q[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 },
                                { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  std::vector<std::vector<std::size_t> > out;
  for(const auto& f : q)
    out.push_back({ first + f[0], first + f[1], first + f[2], first + f[3] });
  return out;
}

} // namespace

// Random simple polygons, star-shaped and general (CGAL's random_polygon_2), with an even
// number of corners, and annuli (a star-shaped polygon around a clockwise hole).
TEST(HolesQuadrangulation, FillsPolygonsAndDomainsWithHoles)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  std::size_t filled = 0, quads = 0;
  for(int trial = 0; trial < 300; ++trial)
  {
    const std::size_t n = 4 + 2 * std::size_t(rng() % 20);
    Holes_loop outer;
    if(trial % 3 == 2)
    {
      typedef Kernel::Point_2 P2;
      std::vector<P2> points;
      CGAL::Random random(trial);
      CGAL::Random_points_in_square_2<P2> generator(1.0, random);
      CGAL::random_polygon_2(n, std::back_inserter(points), generator);
      CGAL::Polygon_2<Kernel> polygon(points.begin(), points.end());
      if(!polygon.is_simple() || polygon.size() != n)
        continue;
      if(polygon.orientation() != CGAL::COUNTERCLOCKWISE)
        polygon.reverse_orientation();
      for(const P2& p : polygon.vertices())
        outer.push_back({ p.x(), p.y() });
    }
    else
    {
      // corners at increasing angles, at least a little apart, radius in [0.6, 1]
      for(std::size_t i = 0; i < n; ++i)
      {
        const double angle = 2 * pi * (double(i) + 0.8 * unit(rng)) / double(n), r = 0.6 + 0.4 * unit(rng);
        outer.push_back({ r * std::cos(angle), r * std::sin(angle) });
      }
    }
    std::vector<Holes_loop> loops{ outer };
    if(trial % 3 == 1 && n >= 8)
    {
      // a clockwise hole of radius 0.2, with an even number of corners: the sides of the
      // star-shaped polygon above (two corners at most 1.8 * 2 pi / n apart) stay at least
      // 0.6 cos(1.8 pi / 8) > 0.45 from the centre
      const std::size_t k = 4 + 2 * std::size_t(rng() % 4);
      Holes_loop hole;
      for(std::size_t i = 0; i < k; ++i)
        hole.push_back({ 0.2 * std::cos(-2 * pi * double(i) / double(k)), 0.2 * std::sin(-2 * pi * double(i) / double(k)) });
      loops.push_back(hole);
    }
    QX::Quadrangulated_polygon out;
    std::string why;
    ASSERT_TRUE(QX::quadrangulate_domain(loops, holes_mean_side(outer), out, &why)) << "trial " << trial << ": " << why;
    holes_check_filling(loops, out);
    ++filled;
    quads += out.quads.size();
  }
  EXPECT_GT(filled, 280u);  // the few general polygons that CGAL could not make simple are skipped
  EXPECT_GT(quads, 10 * filled);  // points inside, not a fan of the corners
}

TEST(HolesQuadrangulation, RefusesWhatIsNotADomain)
{
  QX::Quadrangulated_polygon out;
  const Holes_loop square{ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  EXPECT_TRUE(QX::quadrangulate_polygon(square, 0.25, out));
  const Holes_loop pentagon{ { 0, 0 }, { 1, 0 }, { 1.3, 0.6 }, { 0.5, 1 }, { -0.3, 0.6 } };
  EXPECT_FALSE(QX::quadrangulate_polygon(pentagon, 0.25, out));  // odd
  const Holes_loop clockwise(square.rbegin(), square.rend());
  EXPECT_FALSE(QX::quadrangulate_polygon(clockwise, 0.25, out));
  const Holes_loop bowtie{ { 0, 0 }, { 1, 1 }, { 1, 0.5 }, { 1, 0 }, { 0, 1 }, { 0, 0.5 } };
  EXPECT_FALSE(QX::quadrangulate_polygon(bowtie, 0.25, out));  // its sides cross
  const Holes_loop outside{ { 3, 0 }, { 3, 1 }, { 4, 1 }, { 4, 0 } };  // clockwise, but not inside
  EXPECT_FALSE(QX::quadrangulate_domain({ square, outside }, 0.25, out));
  EXPECT_FALSE(QX::quadrangulate_polygon(square, 0, out));
}

// Each component's quads are checked on their own: a cube on a tetrahedron passes,
// a torus grid (Euler characteristic 0), an open quad, two cubes apart, two cubes
// joined at a corner and a quad through a point twice do not, each for its cause; an
// open component takes any one piece; a polygon on no face joins the component of the
// quads it shares points with; a skipped polygon is not looked at.
TEST(HolesComponents, EachComponentIsOneQuadMeshOfIt)
{
  Mesh tm;
  for(int k = 0; k < 6; ++k)
    CGAL::make_tetrahedron(Point(3 * k, 0, 0), Point(3 * k + 1, 0, 0), Point(3 * k, 1, 0), Point(3 * k, 0, 1), tm);
  {
    const auto a = tm.add_vertex(Point(0, 5, 0)), b = tm.add_vertex(Point(1, 5, 0)), c = tm.add_vertex(Point(1, 6, 0)),
               d = tm.add_vertex(Point(0, 6, 0));
    tm.add_face(a, b, c);
    tm.add_face(a, c, d);
  }
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(tm));
  QX::Chart_mesh M;
  const CGAL::Constant_property_map<Mesh::Halfedge_index, std::array<double, 2> > zero({ 0.0, 0.0 });
  ASSERT_EQ(QX::build_chart_mesh(tm, get(CGAL::vertex_point, tm), zero, M), PVF::Error_code::SUCCESS);
  std::vector<std::size_t> component, sizes;
  QX::face_components(M, component, sizes);
  ASSERT_EQ(sizes.size(), 7u);
  // tetrahedron k has faces 4k..4k+3, the square 24 and 25
  std::vector<std::vector<std::size_t> > polygons;
  std::vector<std::size_t> face;
  std::vector<char> skip;
  auto add = [&](const std::vector<std::vector<std::size_t> >& polys, std::size_t f, char skipped = 0) {
    for(const auto& p : polys)
    {
      polygons.push_back(p);
      face.push_back(f);
      skip.push_back(skipped);
    }
  };
  add(holes_cube_quads(0), 0);
  face.back() = PVF::internal::npos;  // joins tetrahedron 0 through its points
  add({ { 0, 1, 2, 3 } }, 0, 1);  // skipped: it would make edges used three times
  std::vector<std::vector<std::size_t> > torus;
  for(std::size_t j = 0; j < 4; ++j)
    for(std::size_t i = 0; i < 4; ++i)
      torus.push_back({ 100 + i + 4 * j, 100 + (i + 1) % 4 + 4 * j, 100 + (i + 1) % 4 + 4 * ((j + 1) % 4),
                        100 + i + 4 * ((j + 1) % 4) });
  add(torus, 4);
  add({ { 200, 201, 202, 203 } }, 8);
  add(holes_cube_quads(300), 12);
  add(holes_cube_quads(310), 12);
  std::vector<std::vector<std::size_t> > pinched = holes_cube_quads(400), second = holes_cube_quads(407);
  pinched.insert(pinched.end(), second.begin(), second.end());  // point 407 in both cubes
  add(pinched, 16);
  add({ { 500, 501, 502, 501 } }, 20);
  add({ { 600, 601, 602, 603 }, { 601, 604, 605, 602 } }, 24);  // a 2x1 patch on the open square
  std::vector<std::size_t> polygon_face = face;
  const std::vector<QX::Component_defect> defects =
    QX::defective_components(M, component, sizes.size(), polygons, polygon_face, skip);
  std::map<std::size_t, std::string> why;  // by tetrahedron
  for(const QX::Component_defect& d : defects)
  {
    EXPECT_EQ(component[d.face], d.component);
    for(std::size_t k = 0; k < 7; ++k)
      if(component[4 * k] == d.component)
        why[k] = d.why;
  }
  EXPECT_EQ(why.size(), 5u);
  EXPECT_EQ(why.count(0), 0u) << why[0];
  EXPECT_NE(why[1].find("Euler characteristic 0, the component 2"), std::string::npos) << why[1];
  EXPECT_NE(why[2].find("leave a hole (4 border edges)"), std::string::npos) << why[2];
  EXPECT_NE(why[3].find("fall into 2 pieces"), std::string::npos) << why[3];
  EXPECT_NE(why[4].find("do not form a polygon mesh"), std::string::npos) << why[4];
  EXPECT_NE(why[5].find("passes twice through a point"), std::string::npos) << why[5];
  EXPECT_EQ(why.count(6), 0u) << why[6];
  // the polygon on no face got one of tetrahedron 0
  EXPECT_EQ(component[polygon_face[5]], component[0]);
}

// The map of the decimated knight (1000 faces of a scan, refined to 2634; the map of
// design_polyvector_field --curvature-constraints 1): its repair leaves fold-overs.
// They are cut out and filled: the result is a closed quad mesh with the surface's
// Euler characteristic, on the surface, covering it; without the filling the same map
// is refused.
TEST(HolesExtraction, KnightFoldOversCutOutAndFilled)
{
  Holes_map m = holes_read_map(data("decimated-knight-map.obj"));
  ASSERT_EQ(num_faces(m.tm), 2634u);
  ASSERT_TRUE(CGAL::is_closed(m.tm));
  Mesh refused;
  PVF::Quad_extraction_result r0;
  EXPECT_EQ(PVF::extract_quad_mesh(m.tm, m.uv, refused, r0, PVF::parameters::fill_fold_overs(false)),
            PVF::Error_code::UNREPAIRABLE_FOLD_OVER);
  EXPECT_EQ(num_faces(refused), 0u);
  Mesh qm;
  PVF::Quad_extraction_result r;
  ASSERT_EQ(PVF::extract_quad_mesh(m.tm, m.uv, qm, r), PVF::Error_code::SUCCESS) << r.diagnostic;
  EXPECT_GT(r.cut_faces, 0u);
  EXPECT_GE(r.filled_holes, 1u);
  EXPECT_GT(r.filling_quads, 0u);
  // a closed manifold quad mesh of the surface's topology
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(qm));
  EXPECT_TRUE(CGAL::is_closed(qm));
  for(Mesh::Face_index f : faces(qm))
    EXPECT_EQ(degree(f, qm), 4u);
  EXPECT_EQ(num_faces(qm), r.quads);
  EXPECT_EQ(euler_characteristic(qm), euler_characteristic(m.tm));
  // on the surface (every vertex, filled or not), and covering it
  const double diagonal = holes_diagonal(m.tm);
  EXPECT_LE(holes_largest_distance(qm, m.tm), 1e-9 * diagonal);
  EXPECT_GT(holes_area(qm), 0.98 * holes_area(m.tm));
  EXPECT_LT(holes_area(qm), 1.02 * holes_area(m.tm));
  // the input's vertices within the distance the extraction reports (measured here to both
  // ways of cutting each quad, hence no farther)
  EXPECT_LE(holes_largest_distance(m.tm, qm), r.largest_input_distance * (1 + 1e-9));
}

// Tips: without the snapping, the knight's spikes are far from the quads; with it, a
// corner moves onto them, every moved corner is at an input vertex, and the input comes
// closer to the quads.
TEST(HolesExtraction, TipsPullQuadCorners)
{
  Holes_map m = holes_read_map(data("decimated-knight-map.obj"));
  Mesh plain, snapped;
  PVF::Quad_extraction_result r0, r1;
  ASSERT_EQ(PVF::extract_quad_mesh(m.tm, m.uv, plain, r0, PVF::parameters::tip_snapping_distance(0.0)),
            PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::extract_quad_mesh(m.tm, m.uv, snapped, r1), PVF::Error_code::SUCCESS);
  EXPECT_EQ(r0.snapped_tips, 0u);
  EXPECT_GT(r1.snapped_tips, 0u);
  ASSERT_EQ(num_vertices(plain), num_vertices(snapped));
  ASSERT_EQ(num_faces(plain), num_faces(snapped));
  std::set<std::array<double, 3> > input;
  for(Mesh::Vertex_index v : vertices(m.tm))
    input.insert({ m.tm.point(v).x(), m.tm.point(v).y(), m.tm.point(v).z() });
  std::size_t moved = 0;
  auto p = vertices(plain).begin();
  for(Mesh::Vertex_index v : vertices(snapped))
  {
    const Point a = plain.point(*p++), b = snapped.point(v);
    if(a == b)
      continue;
    ++moved;
    EXPECT_TRUE(input.count({ b.x(), b.y(), b.z() })) << "a moved corner is not at an input vertex";
  }
  EXPECT_EQ(moved, r1.snapped_tips);
  const double far0 = holes_largest_distance(m.tm, plain);
  const double far1 = holes_largest_distance(m.tm, snapped);
  EXPECT_LT(far1, 0.75 * far0);
}
