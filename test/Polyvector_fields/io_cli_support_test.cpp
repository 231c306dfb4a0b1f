// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// What the command-line program takes from the library: sharp-edge
// constraints, constraints carried through the mesh repair, the diagnosis of
// an out-of-range constraint vector, and the transaction of output files.

#include <CGAL/Polyvector_fields/IO/internal/atomic_file.h>
#include <CGAL/Polyvector_fields/IO/map_constraints_to_repaired_mesh.h>
#include <CGAL/Polyvector_fields/IO/read_triangle_mesh.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/find_out_of_range_constraint_vector.h>
#include <CGAL/Polyvector_fields/select_sharp_edge_constraints.h>

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/generators.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#ifndef PVF_DATA_DIR
#error "PVF_DATA_DIR (the folder of the bundled meshes) must be given by the build (CMake's pvf_link_package)"
#endif

#include "io_test_support.h"

namespace pvf_cli_support_test {

namespace PVF = CGAL::Polyvector_fields;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index Face;
typedef PVF::Face_constraint<Face, Vector> Constraint;
typedef PVF::Face_constraint<std::size_t, Vector> Id_constraint;

// The box [0, a] x [0, b] x [0, c], each side split into two triangles.
template <typename TriangleMesh = Mesh>
TriangleMesh box(double a, double b, double c)
{
  const std::vector<Point> points = { Point(0, 0, 0), Point(a, 0, 0), Point(a, b, 0), Point(0, b, 0),
                                      Point(0, 0, c), Point(a, 0, c), Point(a, b, c), Point(0, b, c) };
  const std::vector<std::vector<std::size_t> > quads = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 },
                                                         { 1, 2, 6, 5 }, { 2, 3, 7, 6 }, { 3, 0, 4, 7 } };
  std::vector<std::vector<std::size_t> > triangles;
  for(const auto& q : quads)
  {
    triangles.push_back({ q[0], q[1], q[2] });
    triangles.push_back({ q[0], q[2], q[3] });
  }
  TriangleMesh tm;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, tm);
  return tm;
}

bool is_axis(const Vector& v)
{
  int ones = 0, zeros = 0;
  for(double x : { v.x(), v.y(), v.z() })
  {
    ones += std::abs(x) == 1.;
    zeros += x == 0.;
  }
  return ones == 1 && zeros == 2;
}

// The unit direction of the edge of `f` parallel to `v`, if any (sign ignored).
bool is_edge_direction_of(const Mesh& tm, Face f, const Vector& v)
{
  for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
  {
    Vector d = tm.point(target(h, tm)) - tm.point(source(h, tm));
    d = d / std::sqrt(d.squared_length());
    if(std::abs(std::abs(d * v) - 1.) <= 1e-14)
      return true;
  }
  return false;
}

// ---------------------------------------------------------------------------
// select_sharp_edge_constraints()

TEST(CliSupportSharpEdges, BoxFacesFollowTheirTwoBoxEdges)
{
  const Mesh tm = box(2, 3, 5);
  std::vector<Constraint> constraints;
  ASSERT_EQ(PVF::select_sharp_edge_constraints(tm, 30, 2, constraints), PVF::Error_code::SUCCESS);
  // Every triangle has two edges of the box (90 degrees) and the diagonal of its side (0 degrees).
  ASSERT_EQ(constraints.size(), 12u);
  std::size_t previous = 0;
  for(std::size_t i = 0; i < constraints.size(); ++i)
  {
    const Constraint& c = constraints[i];
    if(i > 0)
      EXPECT_GT(std::size_t(c.face), previous) << "in the order of faces(tm)";
    previous = std::size_t(c.face);
    EXPECT_TRUE(std::isinf(c.weight)) << "hard";
    ASSERT_EQ(c.vectors.size(), 2u);
    for(const Vector& v : c.vectors)
    {
      EXPECT_TRUE(is_axis(v)) << v;  // a box edge, exactly unit
      EXPECT_TRUE(is_edge_direction_of(tm, c.face, v)) << v;
    }
    EXPECT_EQ(c.vectors[0] * c.vectors[1], 0.) << "the two box edges of the triangle";
  }
  // One vector per face: one of the two.
  std::vector<Constraint> one;
  ASSERT_EQ(PVF::select_sharp_edge_constraints(tm, 30, 1, one), PVF::Error_code::SUCCESS);
  ASSERT_EQ(one.size(), 12u);
  for(std::size_t i = 0; i < one.size(); ++i)
  {
    EXPECT_EQ(one[i].face, constraints[i].face);
    ASSERT_EQ(one[i].vectors.size(), 1u);
    EXPECT_TRUE(one[i].vectors[0] == constraints[i].vectors[0] || one[i].vectors[0] == constraints[i].vectors[1]);
  }
}

TEST(CliSupportSharpEdges, TheAngleMustBeExceeded)
{
  const Mesh tm = box(1, 1, 1);
  std::vector<Constraint> constraints;
  // Box edges are at exactly 90 degrees: not sharp at 90, sharp just below.
  ASSERT_EQ(PVF::select_sharp_edge_constraints(tm, 90, 2, constraints), PVF::Error_code::SUCCESS);
  EXPECT_TRUE(constraints.empty());
  ASSERT_EQ(PVF::select_sharp_edge_constraints(tm, 89.999, 2, constraints), PVF::Error_code::SUCCESS);
  EXPECT_EQ(constraints.size(), 12u);
  // At 0 degrees, every edge with a crease is sharp, and the flat diagonals are not.
  ASSERT_EQ(PVF::select_sharp_edge_constraints(tm, 0, 3, constraints), PVF::Error_code::SUCCESS);
  ASSERT_EQ(constraints.size(), 12u);
  for(const Constraint& c : constraints)
  {
    ASSERT_EQ(c.vectors.size(), 2u);
    EXPECT_TRUE(is_axis(c.vectors[0]) && is_axis(c.vectors[1]));
  }
}

// The unit box without its top side (two triangles at z = 1).
Mesh open_box()
{
  Mesh tm = box(1, 1, 1);
  std::vector<Face> top;
  for(Face f : faces(tm))
  {
    bool all_up = true;
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      all_up = all_up && tm.point(v).z() == 1.;
    if(all_up)
      top.push_back(f);
  }
  EXPECT_EQ(top.size(), 2u);
  for(Face f : top)
    CGAL::Euler::remove_face(halfedge(f, tm), tm);
  tm.collect_garbage();
  return tm;
}

TEST(CliSupportSharpEdges, BorderEdgesAreNotSharp)
{
  // One side of the box removed: its four border edges, which CGAL's
  // detect_sharp_edges() marks, give no constraint.
  const Mesh tm = open_box();
  std::vector<Constraint> constraints;
  ASSERT_EQ(PVF::select_sharp_edge_constraints(tm, 30, 2, constraints), PVF::Error_code::SUCCESS);
  ASSERT_EQ(constraints.size(), 10u);
  for(const Constraint& c : constraints)
  {
    // A side triangle at the open top keeps only its vertical box edge and
    // its bottom edge; no vector is horizontal at z = 1.
    for(const Vector& v : c.vectors)
      EXPECT_TRUE(is_axis(v));
    for(auto h : CGAL::halfedges_around_face(halfedge(c.face, tm), tm))
      if(CGAL::is_border(opposite(h, tm), tm))
      {
        Vector d = tm.point(target(h, tm)) - tm.point(source(h, tm));
        for(const Vector& v : c.vectors)
          EXPECT_NE(std::abs(d * v), 1.) << "a border edge gave a constraint";
      }
  }
}

TEST(CliSupportSharpEdges, FandiskFeatureLines)
{
  const Mesh tm = pvf_io_test::load_mesh<Mesh>("fandisk.off");
  const double degrees = 30, threshold = degrees * CGAL_PI / 180;
  std::vector<Constraint> constraints;
  ASSERT_EQ(PVF::select_sharp_edge_constraints(tm, degrees, 2, constraints), PVF::Error_code::SUCCESS);
  // Which faces: exactly those beside an edge whose normals make more than 30 degrees.
  std::map<Face, std::vector<double> > sharp_angles;  // the angles of the sharp edges of each face
  for(auto e : edges(tm))
  {
    const auto h = halfedge(e, tm);
    if(CGAL::is_border_edge(h, tm))
      continue;
    PVF::Face_frame a, b;
    ASSERT_EQ(PVF::face_frame(face(h, tm), tm, a), PVF::Error_code::SUCCESS);
    ASSERT_EQ(PVF::face_frame(face(opposite(h, tm), tm), tm, b), PVF::Error_code::SUCCESS);
    const double angle = std::acos((std::max)(-1., (std::min)(1., a.normal[0] * b.normal[0] + a.normal[1] * b.normal[1] + a.normal[2] * b.normal[2])));
    if(angle > threshold)
    {
      sharp_angles[face(h, tm)].push_back(angle);
      sharp_angles[face(opposite(h, tm), tm)].push_back(angle);
    }
  }
  ASSERT_GT(sharp_angles.size(), 100u);
  ASSERT_EQ(constraints.size(), sharp_angles.size());
  for(const Constraint& c : constraints)
  {
    ASSERT_TRUE(sharp_angles.count(c.face)) << std::size_t(c.face);
    const std::size_t sharp = sharp_angles[c.face].size();
    // Which directions: unit directions of edges of the face, as many as it has sharp edges (at most 2).
    ASSERT_EQ(c.vectors.size(), (std::min)(sharp, std::size_t(2)));
    for(const Vector& v : c.vectors)
    {
      EXPECT_NEAR(v.squared_length(), 1., 1e-15);
      EXPECT_TRUE(is_edge_direction_of(tm, c.face, v));
    }
  }
  // The same on a Polyhedron_3: as many constraints with as many vectors.
  typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
  const Polyhedron poly = pvf_io_test::load_mesh<Polyhedron>("fandisk.off");
  std::vector<PVF::Face_constraint<boost::graph_traits<Polyhedron>::face_descriptor, Vector> > on_poly;
  ASSERT_EQ(PVF::select_sharp_edge_constraints(poly, degrees, 2, on_poly), PVF::Error_code::SUCCESS);
  ASSERT_EQ(on_poly.size(), constraints.size());
  for(std::size_t i = 0; i < on_poly.size(); ++i)
    EXPECT_EQ(on_poly[i].vectors.size(), constraints[i].vectors.size());
}

// A roof: a crease C0 C1 C2 (two edges of length 2 * scale, at z = scale)
// that turns by `turn_degrees` at C1, with planar sides going down at 45
// degrees to z = 0 (the crease's dihedral angle is 90 degrees; the two side
// pieces of one side meet at an angle of acos((cos turn + 1) / 2): 21 degrees
// for a turn of 30, 41 for 60).
Mesh bent_roof(double turn_degrees, double scale)
{
  const double t = turn_degrees * CGAL_PI / 180, half = t / 2;
  const Vector d0(1, 0, 0), d1(std::cos(t), std::sin(t), 0);
  const Vector n0(0, 1, 0), n1(-std::sin(t), std::cos(t), 0);  // to the left of each edge
  const Vector bisector = (n0 + n1) / (2 * std::cos(half) * std::cos(half));  // distance 1 to both lines
  const Vector down(0, 0, -1);
  const Point c0(0, 0, 1), c1 = c0 + 2 * d0, c2 = c1 + 2 * d1;
  std::vector<Point> points = { c0, c1, c2, c0 + n0 + down, c1 + bisector + down, c2 + n1 + down,
                                c0 - n0 + down, c1 - bisector + down, c2 - n1 + down };
  for(Point& p : points)
    p = Point(scale * p.x(), scale * p.y(), scale * p.z());
  // crease 0 1 2, left 3 4 5, right 6 7 8; counter-clockwise seen from above
  const std::vector<std::vector<std::size_t> > triangles = { { 0, 1, 4 }, { 0, 4, 3 }, { 1, 2, 5 }, { 1, 5, 4 },
                                                             { 0, 6, 7 }, { 0, 7, 1 }, { 1, 7, 8 }, { 1, 8, 2 } };
  Mesh tm;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, tm);
  return tm;
}

// The sharp edges kept with minimum_feature_length(length), above `degrees`
// (the roof's crease at 50: its side pieces meet at less); `constraints`
// receives the constraints.
std::size_t kept_crease_edges(const Mesh& tm, double length, double degrees = 50,
                              std::vector<Constraint>* constraints = nullptr)
{
  std::map<Mesh::Edge_index, bool> flags;
  std::vector<Constraint> local;
  EXPECT_EQ(PVF::select_sharp_edge_constraints(
              tm, degrees, 2, constraints ? *constraints : local,
              PVF::parameters::minimum_feature_length(length).edge_is_constrained_map(
                boost::make_assoc_property_map(flags))),
            PVF::Error_code::SUCCESS);
  std::size_t kept = 0;
  for(const auto& flag : flags)
    kept += flag.second ? 1 : 0;
  return kept;
}

TEST(CliSupportSharpEdges, ShortCreasesAreDropped)
{
  // A crease that turns by 30 degrees is one curve of length 4: kept below
  // 4, dropped above (its network is shorter too).
  const Mesh gentle = bent_roof(30, 1);
  EXPECT_EQ(kept_crease_edges(gentle, 0), 2u);
  EXPECT_EQ(kept_crease_edges(gentle, 3), 2u);
  EXPECT_EQ(kept_crease_edges(gentle, 5), 0u);
  // Turning by 60 degrees (more than 45), it is two curves of length 2 with
  // free ends, each shorter than 3: dropped, though their network is 4 long.
  const Mesh sharp_turn = bent_roof(60, 1);
  EXPECT_EQ(kept_crease_edges(sharp_turn, 0), 2u);
  EXPECT_EQ(kept_crease_edges(sharp_turn, 3), 0u);
  EXPECT_EQ(kept_crease_edges(sharp_turn, 1.9), 2u);
  // Lengths are in mesh units, whatever the size of the coordinates.
  const double small = 1.0 / 64;
  const Mesh tiny = bent_roof(30, small);
  EXPECT_EQ(kept_crease_edges(tiny, 3 * small), 2u);
  EXPECT_EQ(kept_crease_edges(tiny, 4.1 * small), 0u);
  EXPECT_EQ(kept_crease_edges(tiny, 3.9 * small), 2u);
  // The edges of a box are curves of length 1 between corners where three
  // of them meet: kept whatever the length asked for.
  std::vector<Constraint> constraints;
  EXPECT_EQ(kept_crease_edges(box(1, 1, 1), 3, 30, &constraints), 12u);
  EXPECT_EQ(constraints.size(), 12u);
  // Open at the top, without boundary alignment: a vertical edge ends at a
  // bottom corner (three sharp edges) and at a top corner (one sharp edge and
  // two border edges, which count though they are not kept): all 8 kept.
  EXPECT_EQ(kept_crease_edges(open_box(), 3, 30), 8u);
}

TEST(CliSupportSharpEdges, RefusesBadParameters)
{
  const Mesh tm = box(1, 1, 1);
  std::vector<Constraint> constraints(1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(PVF::select_sharp_edge_constraints(tm, 180, 2, constraints), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::select_sharp_edge_constraints(tm, -1, 2, constraints), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::select_sharp_edge_constraints(tm, nan, 2, constraints), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::select_sharp_edge_constraints(tm, 30, 0, constraints), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::select_sharp_edge_constraints(Mesh(), 30, 2, constraints), PVF::Error_code::EMPTY_MESH);
  Mesh quads;
  CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(0, 1, 1),
                        Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), quads);
  EXPECT_EQ(PVF::select_sharp_edge_constraints(quads, 30, 2, constraints), PVF::Error_code::NON_TRIANGLE_FACE);
  EXPECT_EQ(constraints.size(), 1u) << "unchanged on failure";
}

// ---------------------------------------------------------------------------
// IO::map_constraints_to_repaired_mesh()

TEST(CliSupportRepairedConstraints, TriangulatedFacesPassTheirConstraint)
{
  pvf_io_test::Scratch_directory dir("repaired_constraints");
  const std::string file = dir.file("cube.off");
  std::ofstream(file) << "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                         "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
  Mesh tm;
  PVF::IO::Mesh_repair_result report;
  ASSERT_EQ(PVF::IO::read_triangle_mesh(file, tm, report), PVF::Error_code::SUCCESS);
  ASSERT_EQ(num_faces(tm), 12u);
  ASSERT_EQ(report.file_faces, 6u);
  Id_constraint on_top{ 1, { Vector(1, 0, 0) } };
  Id_constraint on_front{ 2, { Vector(1, 0, 0), Vector(0, 0, 1) }, 0.5 };
  std::vector<Constraint> carried;
  ASSERT_EQ(PVF::IO::map_constraints_to_repaired_mesh(tm, report, std::vector<Id_constraint>{ on_top, on_front }, carried),
            PVF::Error_code::SUCCESS);
  ASSERT_EQ(carried.size(), 4u);
  // The triangles of file face 1 (z = 1), then those of file face 2 (y = 0), each in the order of faces(tm).
  for(std::size_t i = 0; i < 4; ++i)
  {
    const Id_constraint& from = i < 2 ? on_top : on_front;
    EXPECT_EQ(report.source_face[std::size_t(carried[i].face)], from.face);
    EXPECT_EQ(carried[i].vectors, from.vectors);
    EXPECT_EQ(carried[i].weight, from.weight);
    for(auto v : CGAL::vertices_around_face(halfedge(carried[i].face, tm), tm))
      EXPECT_EQ(i < 2 ? tm.point(v).z() : tm.point(v).y(), i < 2 ? 1. : 0.);
  }
  EXPECT_LT(carried[0].face, carried[1].face);
  EXPECT_LT(carried[2].face, carried[3].face);
  EXPECT_NE(carried[0].face, carried[2].face);
}

TEST(CliSupportRepairedConstraints, RemovedFacesAndForeignReports)
{
  pvf_io_test::Scratch_directory dir("removed_constraints");
  const std::string file = dir.file("duplicate.off");
  // Face 2 repeats face 0 (rotated): the repair removes it.
  std::ofstream(file) << "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 2 3\n3 2 0 1\n";
  Mesh tm;
  PVF::IO::Mesh_repair_result report;
  ASSERT_EQ(PVF::IO::read_triangle_mesh(file, tm, report), PVF::Error_code::SUCCESS);
  ASSERT_EQ(report.duplicate_faces, 1u);
  ASSERT_EQ(num_faces(tm), 2u);
  std::vector<Constraint> carried(1);
  std::size_t failed = 99;
  const std::vector<Id_constraint> ok_then_removed = { { 1, { Vector(0, 0, 1) } }, { 2, { Vector(1, 0, 0) } } };
  EXPECT_EQ(PVF::IO::map_constraints_to_repaired_mesh(tm, report, ok_then_removed, carried, &failed),
            PVF::Error_code::INVALID_FACE);
  EXPECT_EQ(failed, 1u);
  EXPECT_EQ(carried.size(), 1u) << "unchanged on failure";
  const std::vector<Id_constraint> past_the_end = { { 3, { Vector(1, 0, 0) } } };
  EXPECT_EQ(PVF::IO::map_constraints_to_repaired_mesh(tm, report, past_the_end, carried, &failed),
            PVF::Error_code::INVALID_FACE);
  EXPECT_EQ(failed, 0u);
  // A report of another mesh.
  PVF::IO::Mesh_repair_result other = report;
  other.source_face.push_back(0);
  EXPECT_EQ(PVF::IO::map_constraints_to_repaired_mesh(tm, other, std::vector<Id_constraint>(), carried),
            PVF::Error_code::INVALID_PARAMETER);
  // The faces kept carry their constraint.
  ASSERT_EQ(PVF::IO::map_constraints_to_repaired_mesh(tm, report, std::vector<Id_constraint>{ ok_then_removed[0] },
                                                      carried),
            PVF::Error_code::SUCCESS);
  ASSERT_EQ(carried.size(), 1u);
  EXPECT_EQ(report.source_face[std::size_t(carried[0].face)], 1u);
}

// ---------------------------------------------------------------------------
// find_out_of_range_constraint_vector()

TEST(CliSupportOutOfRange, NamesTheVectorTheDesignerRefuses)
{
  const double inf = std::numeric_limits<double>::infinity();
  std::size_t index = 99;
  double log10_length = 0;
  // N = 4: L^4 within [1e-300, 1e300] means L within [1e-75, 1e75].
  EXPECT_FALSE(PVF::find_out_of_range_constraint_vector(std::vector<Vector>{ Vector(1e74, 0, 0), Vector(0, 1e-74, 0) },
                                                        4, index, log10_length));
  EXPECT_EQ(index, 99u) << "unchanged when every vector is in range";
  EXPECT_TRUE(PVF::find_out_of_range_constraint_vector(std::vector<Vector>{ Vector(1, 0, 0), Vector(0, 1e76, 0) }, 4,
                                                       index, log10_length));
  EXPECT_EQ(index, 1u);
  EXPECT_NEAR(log10_length, 76, 1e-12);
  EXPECT_TRUE(PVF::find_out_of_range_constraint_vector(std::vector<Vector>{ Vector(0, 0, 1e-76) }, 4, index, log10_length));
  EXPECT_EQ(index, 0u);
  EXPECT_NEAR(log10_length, -76, 1e-12);
  // Lengths whose squares overflow are measured: |(1e200, 1e200, 0)| = sqrt(2) 1e200.
  const std::vector<Vector> huge = { Vector(1e200, 1e200, 0) };
  EXPECT_FALSE(PVF::find_out_of_range_constraint_vector(huge, 1, index, log10_length));
  EXPECT_TRUE(PVF::find_out_of_range_constraint_vector(huge, 2, index, log10_length));
  EXPECT_NEAR(log10_length, 200 + 0.5 * std::log10(2.), 1e-12);
  // Zero and non-finite vectors are refused for other reasons: skipped.
  EXPECT_TRUE(PVF::find_out_of_range_constraint_vector(
    std::vector<Vector>{ Vector(0, 0, 0), Vector(inf, 0, 0), Vector(1e-80, 0, 0) }, 4, index, log10_length));
  EXPECT_EQ(index, 2u);
  EXPECT_NEAR(log10_length, -80, 1e-12);

  // The same verdict as the designer's: VALUE_OUT_OF_RANGE exactly for the constraints it names.
  const Mesh tm = box(1, 1, 1);
  const Face f = *faces(tm).begin();
  const std::vector<std::vector<Vector> > cases = {
    { Vector(1, 0, 0) }, { Vector(1e74, 0, 0) }, { Vector(1e76, 0, 0) }, { Vector(1e-76, 0, 0) },
    { Vector(1, 0, 0), Vector(0, 1e76, 0) }, { Vector(1e75, 1e75, 0) }, { Vector(1e-75, 1e-75, 0) } };
  for(const auto& vectors : cases)
  {
    Constraint c;
    c.face = f;
    for(const Vector& v : vectors)
      c.vectors.push_back(v);
    PVF::Polyvector_field_designer<Mesh> designer(tm, 4);
    ASSERT_EQ(designer.status(), PVF::Error_code::SUCCESS);
    const bool refused = designer.add_constraint(c) == PVF::Error_code::VALUE_OUT_OF_RANGE;
    EXPECT_EQ(PVF::find_out_of_range_constraint_vector(c.vectors, 4, index, log10_length), refused) << vectors[0];
  }
}

// ---------------------------------------------------------------------------
// IO::internal::File_transaction

TEST(CliSupportFileTransaction, AllOrNone)
{
  namespace fs = std::filesystem;
  using pvf_io_test::file_content;
  typedef PVF::IO::internal::File_transaction Transaction;
  pvf_io_test::Scratch_directory dir("transaction");
  const std::string a = dir.file("a.txt"), b = dir.file("b.txt");
  auto text = [](const std::string& content) {
    return [content](std::ostream& os) {
      os << content;
      return PVF::Error_code::SUCCESS;
    };
  };
  // Both written, an existing file replaced.
  std::ofstream(a) << "old a\n";
  {
    Transaction t;
    ASSERT_EQ(t.stage(a, text("new a\n")), PVF::Error_code::SUCCESS);
    ASSERT_EQ(t.stage(b, text(std::string(3u << 20, 'b'))), PVF::Error_code::SUCCESS);  // larger than the buffer
    EXPECT_TRUE(t.is_staged(a) && t.is_staged(b));
    EXPECT_EQ(file_content(a), "old a\n") << "nothing is published before commit()";
    ASSERT_EQ(t.commit(), PVF::Error_code::SUCCESS);
    EXPECT_TRUE(t.error_message().empty());
  }
  EXPECT_EQ(file_content(a), "new a\n");
  EXPECT_EQ(file_content(b), std::string(3u << 20, 'b'));
  EXPECT_EQ(dir.entries(), (std::set<std::string>{ "a.txt", "b.txt" }));

  // A writer fails: its code comes back, nothing is published, no temporary stays.
  {
    Transaction t;
    ASSERT_EQ(t.stage(a, text("newer a\n")), PVF::Error_code::SUCCESS);
    EXPECT_EQ(t.stage(b, [](std::ostream& os) {
                os << "part";
                return PVF::Error_code::NON_FINITE_VALUE;
              }),
              PVF::Error_code::NON_FINITE_VALUE);
    EXPECT_TRUE(t.error_message().empty()) << "the writer says what went wrong";
  }
  EXPECT_EQ(file_content(a), "new a\n");
  EXPECT_EQ(dir.entries(), (std::set<std::string>{ "a.txt", "b.txt" }));

  // No folder: the temporary cannot be created; the message names the file.
  {
    Transaction t;
    const std::string missing = dir.file("missing/c.txt");
    EXPECT_EQ(t.stage(missing, text("c")), PVF::Error_code::CANNOT_OPEN_FILE);
    EXPECT_EQ(t.error_message().rfind("cannot write '" + missing + "': ", 0), 0u) << t.error_message();
  }

  // commit() fails on the second file (its destination became a folder): the
  // first one is restored, and no temporary or backup remains.
  {
    Transaction t;
    ASSERT_EQ(t.stage(a, text("newest a\n")), PVF::Error_code::SUCCESS);
    const std::string c = dir.file("c");
    ASSERT_EQ(t.stage(c, text("c\n")), PVF::Error_code::SUCCESS);
    fs::create_directory(c);
    std::ofstream(dir.file("c/inside")) << "x";
    EXPECT_EQ(t.commit(), PVF::Error_code::CANNOT_OPEN_FILE);
    EXPECT_NE(t.error_message().find("'" + c + "'"), std::string::npos) << t.error_message();
  }
  EXPECT_EQ(file_content(a), "new a\n");
  EXPECT_TRUE(fs::is_directory(dir.file("c")));
  EXPECT_EQ(dir.entries(), (std::set<std::string>{ "a.txt", "b.txt", "c" }));
}

} // namespace pvf_cli_support_test
