// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// IO::read_triangle_mesh(): each refusal has its own message, each repair is
// counted, and the source face of every output face is right; bounded reading
// of every reader (size limit, binary data, endless input).

#include "io_test_support.h"

#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/IO/rawfield.h>
#include <CGAL/Polyvector_fields/IO/read_triangle_mesh.h>

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace PVF = CGAL::Polyvector_fields;

namespace {

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef CGAL::Polyhedron_3<Kernel> Polyhedron;

struct Read
{
  PVF::Error_code code;
  std::string message;
  PVF::IO::Mesh_repair_result report;
  std::size_t faces = 0;
};

template <typename TriangleMesh = Mesh>
Read read_text(const std::string& name, const std::string& text, bool repair, TriangleMesh* out = nullptr)
{
  pvf_io_test::Scratch_directory dir("mesh_input");
  {
    std::ofstream file(dir.file(name), std::ios::binary);
    file << text;
  }
  TriangleMesh tm;
  Read r;
  r.code = PVF::IO::read_triangle_mesh(dir.file(name), tm, r.report,
                                       PVF::parameters::repair(repair, PVF::parameters::error_message(r.message)));
  r.faces = num_faces(tm);
  if(out)
    *out = tm;
  return r;
}

const std::string tetrahedron_points = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";

} // namespace

TEST(MeshInput, EachRefusalNamesItsCause)
{
  struct Case
  {
    const char* file;
    std::string text;
    PVF::Error_code code;
    const char* message;
  };
  const Case cases[] = {
    { "a.off", "OFF\n4 2 0\n0 0 0\n1 0 nan\n0 1 0\n0 0 1\n3 0 1 2\n3 0 2 3\n", PVF::Error_code::NON_FINITE_VALUE,
      "line 4: vertex 1 has the non-finite coordinate 'nan'" },
    { "a.off", "OFF\n4 2 0\n" + tetrahedron_points + "3 0 1 2\n3 0 2 7\n", PVF::Error_code::MALFORMED_FILE,
      "line 8: face 1 uses vertex 7, not in 0..3" },
    { "a.off", "OFF\n4 2 0\n" + tetrahedron_points + "3 0 1 1\n3 0 2 3\n", PVF::Error_code::DEGENERATE_FACE,
      "face 0 (line 7) repeats vertex 1 (line 4)" },
    { "a.off", "OFF\n4 3 0\n" + tetrahedron_points + "3 0 1 2\n3 0 2 3\n3 2 0 1\n", PVF::Error_code::DUPLICATE_FACE,
      "face 2 (line 9) has the same vertices as face 0 (line 7)" },
    { "a.off", "OFF\n5 3 0\n" + tetrahedron_points + "0 -1 0\n3 0 1 2\n3 1 0 3\n3 0 1 4\n",
      PVF::Error_code::NON_MANIFOLD_MESH, "the edge between vertices 0 and 1 is shared by 3 faces" },
    { "a.off", "OFF\n4 2 0\n" + tetrahedron_points + "3 0 1 2\n3 0 1 3\n", PVF::Error_code::NON_MANIFOLD_MESH,
      "face 0 (line 7) and face 1 (line 8) are oriented inconsistently" },
    { "a.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n", PVF::Error_code::NON_MANIFOLD_MESH,
      "vertex 0 (line 3) is pinched: its faces form 2 separate fans" },
    { "a.off", "OFF\n4 1 0\n" + tetrahedron_points + "4 0 1 2 3\n", PVF::Error_code::NON_TRIANGLE_FACE,
      "face 0 (line 7) has 4 vertices: the mesh is not a triangle mesh" },
    { "a.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n2 0 0\n0 0 1\n3 0 1 2\n3 0 2 3\n", PVF::Error_code::DEGENERATE_FACE,
      "face 0 (line 7) is degenerate" },
    { "a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", PVF::Error_code::MALFORMED_FILE,
      "line 4: face 0 uses vertex 0 (OBJ indices start at 1)" },
    { "a.off", "OFF BINARY\n", PVF::Error_code::UNSUPPORTED_FORMAT, "binary OFF is not supported" },
    { "a.xyz", "0 0 0\n", PVF::Error_code::UNSUPPORTED_FORMAT, "the extension '.xyz'" },
    { "a.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", PVF::Error_code::EMPTY_MESH, "the file has no face" },
    { "a.off", std::string("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1\0 0\n3 0 1 2\n", 36), PVF::Error_code::MALFORMED_FILE,
      "binary data" },
  };
  for(const Case& c : cases)
  {
    const Read r = read_text(c.file, c.text, false);
    EXPECT_EQ(r.code, c.code) << c.text;
    EXPECT_NE(r.message.find(c.message), std::string::npos) << "got: " << r.message;
    EXPECT_EQ(r.faces, 0u) << "the mesh must be left as it was";
  }
}

TEST(MeshInput, RepairsAndCountsWhatItChanged)
{
  // A quad cube: 6 quads, each split into 2 triangles with its source.
  Mesh cube;
  const Read quads =
    read_text("cube.off",
              "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n"
              "4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n",
              true, &cube);
  ASSERT_EQ(quads.code, PVF::Error_code::SUCCESS) << quads.message;
  EXPECT_EQ(quads.report.triangulated_faces, 6u);
  EXPECT_EQ(num_faces(cube), 12u);
  EXPECT_TRUE(CGAL::is_triangle_mesh(cube));
  EXPECT_TRUE(CGAL::is_closed(cube));
  std::map<std::size_t, int> per_source;
  for(std::size_t s : quads.report.source_face)
    ++per_source[s];
  ASSERT_EQ(per_source.size(), 6u);
  for(const auto& entry : per_source)
    EXPECT_EQ(entry.second, 2) << "file face " << entry.first;
  // Each triangle lies in the plane of its source quad: face 0 of the file is z = 0.
  std::size_t i = 0;
  for(auto f : faces(cube))
  {
    if(quads.report.source_face[i++] != 0)
      continue;
    for(auto v : vertices_around_face(halfedge(f, cube), cube))
      EXPECT_EQ(cube.point(v).z(), 0.0);
  }

  // Duplicate face, inconsistent orientation, a repeated vertex and an isolated vertex.
  const Read soup = read_text("soup.off",
                              "OFF\n6 5 0\n" + tetrahedron_points + "5 5 5\n0 0 -1\n"
                              "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n3 1 2 0\n",
                              true);
  ASSERT_EQ(soup.code, PVF::Error_code::SUCCESS) << soup.message;
  EXPECT_EQ(soup.report.duplicate_faces, 1u);
  EXPECT_EQ(soup.report.isolated_vertices, 2u);
  EXPECT_EQ(soup.faces, 4u);

  const Read flipped = read_text("flip.off", "OFF\n4 4 0\n" + tetrahedron_points + "3 0 2 1\n3 0 1 3\n3 2 1 3\n3 0 3 2\n",
                                 true);
  ASSERT_EQ(flipped.code, PVF::Error_code::SUCCESS) << flipped.message;
  EXPECT_EQ(flipped.report.reoriented_faces, 1u);

  const Read repeated = read_text("rep.off", "OFF\n5 3 0\n" + tetrahedron_points + "0 -1 0\n3 0 1 2\n4 0 3 3 1\n3 0 4 1\n",
                                  true);
  ASSERT_EQ(repeated.code, PVF::Error_code::SUCCESS) << repeated.message;
  EXPECT_EQ(repeated.report.degenerate_polygons, 1u);
  EXPECT_EQ(repeated.faces, 3u);

  // An STL-like soup: every triangle with its own points, merged into one closed surface.
  std::string separate = "OFF\n12 4 0\n";
  const char* tri[4][3] = { { "0 0 0", "0 1 0", "1 0 0" }, { "0 0 0", "1 0 0", "0 0 1" },
                            { "1 0 0", "0 1 0", "0 0 1" }, { "0 0 0", "0 0 1", "0 1 0" } };
  for(const auto& t : tri)
    for(const char* p : t)
      separate += std::string(p) + "\n";
  separate += "3 0 1 2\n3 3 4 5\n3 6 7 8\n3 9 10 11\n";
  Mesh merged;
  const Read stl = read_text("separate.off", separate, true, &merged);
  ASSERT_EQ(stl.code, PVF::Error_code::SUCCESS) << stl.message;
  EXPECT_EQ(stl.report.merged_points, 8u);
  EXPECT_EQ(num_vertices(merged), 4u);
  EXPECT_TRUE(CGAL::is_closed(merged));

  // A zero-area triangle in a fan is collapsed away.
  const Read degenerate =
    read_text("degen.off", "OFF\n5 4 0\n0 0 0\n2 0 0\n1 1 0\n1 0 0\n1 -1 0\n3 0 3 2\n3 3 1 2\n3 0 1 3\n3 0 4 1\n", true);
  ASSERT_EQ(degenerate.code, PVF::Error_code::SUCCESS) << degenerate.message;
  EXPECT_GE(degenerate.report.degenerate_faces, 1u);
}

TEST(MeshInput, SurfaceMeshAndPolyhedronAgree)
{
  const std::string quads = "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 3 2 1\n"
                            "4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
  const Read a = read_text<Mesh>("cube.off", quads, true);
  const Read b = read_text<Polyhedron>("cube.off", quads, true);
  ASSERT_EQ(a.code, PVF::Error_code::SUCCESS);
  ASSERT_EQ(b.code, PVF::Error_code::SUCCESS);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.report.source_face, b.report.source_face);
  for(const char* name : { "bumpy.off", "inspired_mesh.obj", "fandisk.off" })
  {
    Mesh tm;
    PVF::IO::Mesh_repair_result report;
    ASSERT_EQ(PVF::IO::read_triangle_mesh(pvf_io_test::data_file(name), tm, report, PVF::parameters::repair(false)),
              PVF::Error_code::SUCCESS)
      << name;
    const Mesh reference = pvf_io_test::load_mesh<Mesh>(name);
    ASSERT_EQ(num_faces(tm), num_faces(reference)) << name;
    EXPECT_FALSE(report.changed()) << name;
    auto p = vertices(tm).begin();
    for(auto v : vertices(reference))
      EXPECT_EQ(tm.point(*p++), reference.point(v)) << name;
  }
}

TEST(BoundedReading, SizeLimitBinaryDataAndEndlessInput)
{
  const Mesh tm = pvf_io_test::load_mesh<Mesh>("bumpy.off");
  typedef std::vector<PVF::Face_constraint<Mesh::Face_index, Kernel::Vector_3> > Constraints;
  pvf_io_test::Scratch_directory dir("bounded");
  const std::string big = dir.file("big.txt");
  {
    std::ofstream out(big);
    for(int i = 0; i < 2000; ++i)
      out << i << " 1 0 0\n";
  }
  Constraints constraints;
  std::string message;
  // The file holds ~19 kB: a 10 kB limit refuses it before it is read.
  EXPECT_EQ(PVF::IO::read_constraints(big, tm, constraints,
                                      PVF::parameters::maximum_file_size(10000, PVF::parameters::error_message(message))),
            PVF::Error_code::FILE_TOO_LARGE);
  EXPECT_NE(message.find("larger than the size limit of 10000 bytes"), std::string::npos) << message;
  EXPECT_TRUE(constraints.empty());
  EXPECT_EQ(PVF::IO::read_constraints(big, tm, constraints), PVF::Error_code::SUCCESS);
  EXPECT_EQ(constraints.size(), 2000u);

  // A stream that never ends (an endless generator behind a streambuf) is
  // refused once the limit is passed.
  struct Endless : std::streambuf
  {
    char buffer[4096];
    int_type underflow() override
    {
      std::fill(buffer, buffer + sizeof buffer, '1');
      setg(buffer, buffer, buffer + sizeof buffer);
      return traits_type::to_int_type('1');
    }
  } endless;
  std::istream endless_stream(&endless);
  Constraints none;
  EXPECT_EQ(PVF::IO::read_constraints(endless_stream, tm, none, PVF::parameters::maximum_file_size(1 << 20)),
            PVF::Error_code::FILE_TOO_LARGE);

  std::istringstream binary(std::string("0 1 0 0\n\0\n", 10));
  EXPECT_EQ(PVF::IO::read_constraints(binary, tm, none, PVF::parameters::error_message(message)),
            PVF::Error_code::MALFORMED_FILE);
  EXPECT_NE(message.find("binary data"), std::string::npos) << message;

  // Readers stop at the first bad token and say where it is.
  std::istringstream bad("0 1 0 0\n1 0 1 0\n2 1 x 0\n3 1 0 0\n");
  EXPECT_EQ(PVF::IO::read_constraints(bad, tm, none, PVF::parameters::error_message(message)),
            PVF::Error_code::MALFORMED_FILE);
  EXPECT_EQ(message, "line 3: 'x' is not a number");
  std::istringstream too_many("0 1 0 0 0 1 0 1 1 0\n");
  EXPECT_EQ(PVF::IO::read_constraints(too_many, tm, none,
                                      PVF::parameters::expected_degree(2, PVF::parameters::error_message(message))),
            PVF::Error_code::TOO_MANY_CONSTRAINT_VECTORS);
  EXPECT_EQ(message, "line 1: face 0 has more than 2 vectors (the degree is 2)");
  EXPECT_TRUE(none.empty());

  // The rawfield reader's messages.
  std::istringstream short_field("4 2496\n1 0 0 0 1 0 -1 0 0 0 -1 0\n");
  typedef std::map<Mesh::Face_index, std::vector<Kernel::Vector_3> > Roots;
  Roots roots;
  std::size_t N = 0;
  EXPECT_EQ(PVF::IO::read_rawfield(short_field, tm, boost::make_assoc_property_map(roots), N,
                                   PVF::parameters::error_message(message)),
            PVF::Error_code::MALFORMED_FILE);
  EXPECT_EQ(message, "the file ends after 1 of 2496 faces");
  EXPECT_TRUE(roots.empty());
}

TEST(BoundedReading, ConstraintsById)
{
  pvf_io_test::Scratch_directory dir("by_id");
  {
    std::ofstream out(dir.file("c.txt"));
    out << "5 1 0 0\n2 0 1 0 1 0 0\n";
  }
  std::vector<PVF::Face_constraint<std::size_t, Kernel::Vector_3> > by_id;
  ASSERT_EQ(PVF::IO::read_constraints_by_id(dir.file("c.txt"), 6, by_id), PVF::Error_code::SUCCESS);
  ASSERT_EQ(by_id.size(), 2u);
  EXPECT_EQ(by_id[0].face, 5u);
  EXPECT_EQ(by_id[1].face, 2u);
  EXPECT_EQ(by_id[1].vectors.size(), 2u);
  std::string message;
  EXPECT_EQ(PVF::IO::read_constraints_by_id(dir.file("c.txt"), 5, by_id, PVF::parameters::error_message(message)),
            PVF::Error_code::INVALID_FACE);
  EXPECT_EQ(message, "line 1: face id '5' is not in 0..4 (the mesh has 5 faces)");
  EXPECT_EQ(PVF::IO::read_constraints_by_id(dir.file("none.txt"), 5, by_id, PVF::parameters::error_message(message)),
            PVF::Error_code::CANNOT_OPEN_FILE);
  EXPECT_EQ(message, "does not exist");
}

// The triangulation of polygon faces: a concave polygon is cut into n - 2
// triangles of the polygon's orientation that cover exactly its area; a
// polygon that is not simple on its plane, or whose coordinates differ by
// 1e19 (beyond what inexact double predicates can order), is refused or cut
// correctly, never turned into an invalid mesh.
TEST(MeshInput, PolygonTriangulationIsExactOrRefused)
{
  // An L-shaped hexagon in the plane x + y + z = const (tilted), area 3 in its
  // projection onto z = 0; the reflex vertex is vertex 3.
  auto lifted = [](double x, double y) { return std::to_string(x) + " " + std::to_string(y) + " " +
                                                std::to_string(0.25 * x - 0.5 * y) + "\n"; };
  const std::string hexagon = "OFF\n6 1 0\n" + lifted(0, 0) + lifted(2, 0) + lifted(2, 1) + lifted(1, 1) +
                              lifted(1, 2) + lifted(0, 2) + "6 0 1 2 3 4 5\n";
  Mesh tm;
  const Read l = read_text("l.off", hexagon, true, &tm);
  ASSERT_EQ(l.code, PVF::Error_code::SUCCESS) << l.message;
  EXPECT_EQ(l.report.triangulated_faces, 1u);
  ASSERT_EQ(num_faces(tm), 4u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(tm));
  double projected_area = 0;
  for(auto f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    const Kernel::Point_3 &a = tm.point(source(h, tm)), &b = tm.point(target(h, tm)),
                          &c = tm.point(target(next(h, tm), tm));
    const double signed_area = 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()));
    EXPECT_GT(signed_area, 0) << "a triangle is flipped or flat";  // counterclockwise, as the polygon
    projected_area += signed_area;
  }
  EXPECT_NEAR(projected_area, 3.0, 1e-12);

  // Self-overlapping: the boundary folds back along a line (a "bow tie" with
  // a spike), so no triangulation is a surface.
  const Read bow_tie = read_text("bow_tie.off", "OFF\n4 1 0\n0 0 0\n1 1 0\n1 0 0\n0 1 0\n4 0 1 2 3\n", true);
  EXPECT_EQ(bow_tie.code, PVF::Error_code::NON_TRIANGLE_FACE);
  EXPECT_NE(bow_tie.message.find("face 0 (line 7)"), std::string::npos) << bow_tie.message;
  EXPECT_NE(bow_tie.message.find("not a simple polygon"), std::string::npos) << bow_tie.message;
  const Read spike = read_text("spike.off", "OFF\n5 1 0\n0 0 0\n2 0 0\n1 0 0\n1 1 0\n0 1 0\n5 0 1 2 3 4\n", true);
  EXPECT_EQ(spike.code, PVF::Error_code::NON_TRIANGLE_FACE) << spike.message;

  // A convex quad with coordinates near 1e19 and a side of length 1: exact
  // predicates cut it into two triangles, but one is a sliver that no frame
  // can be built on and that CGAL's removal of degenerate faces (exact
  // collinearity) leaves in place: refused, with the face named, rather than
  // a mesh returned that cannot carry a field.
  const Read big = read_text("huge.off", "OFF\n4 1 0\n1e19 0 0\n1e19 1 0\n0 1e19 0\n0 0 0\n4 0 1 2 3\n", true);
  EXPECT_EQ(big.code, PVF::Error_code::DEGENERATE_FACE);
  EXPECT_NE(big.message.find("face 0 (line 7)"), std::string::npos) << big.message;
}

// ---------------------------------------------------------------------------
// The linear-time reader: the same numbers, faces, lines and messages.
// ---------------------------------------------------------------------------
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

} // namespace

TEST(MeshInputFast, OffTokensReadAsStrtodReadsThem)
{
  namespace I = PVF::IO::internal;
  // Exponents, '+' signs, -0, CRLF, tabs, comments, a blank line, extra
  // numbers per vertex, subnormals, and no newline at the end.
  const std::string text = "# header comment\r\nOFF\t5 2 0\r\n"
                           "1.5e+2 +3.25 -0.0 # trailing comment\r\n"
                           "\t.5 1E-3\t  7 0.1 0.2\n"
                           "\n   # a comment line\n"
                           "1e308 -2.2250738585072014e-308 4.9406564584124654e-324\n"
                           "0.1000000000000000055511151231257827 3. +0\n"
                           "123456789012345678901234567890 -1e-400 2.5e-1\n"
                           "3 0 1 2\r\n"
                           "4\t+0 2 3 4 # x";
  const char* tokens[5][3] = { { "1.5e+2", "3.25", "-0.0" },
                               { ".5", "1E-3", "7" },
                               { "1e308", "-2.2250738585072014e-308", "4.9406564584124654e-324" },
                               { "0.1000000000000000055511151231257827", "3.", "0" },
                               { "123456789012345678901234567890", "-0.0", "2.5e-1" } };
  I::Polygon_soup soup;
  std::string message;
  ASSERT_EQ(I::read_off_soup(text, soup, I::Diagnostic(&message)), PVF::Error_code::SUCCESS) << message;
  ASSERT_EQ(soup.points.size(), 5u);
  for(std::size_t v = 0; v < 5; ++v)
    for(int c = 0; c < 3; ++c)
      EXPECT_TRUE(same_bits(soup.points[v][c], std::strtod(tokens[v][c], nullptr)))
        << "vertex " << v << " coordinate " << c << ": " << soup.points[v][c];
  EXPECT_EQ(soup.point_line, (std::vector<std::size_t>{ 3, 4, 7, 8, 9 }));
  EXPECT_EQ(soup.first, (std::vector<std::size_t>{ 0, 3, 7 }));
  EXPECT_EQ(soup.ids, (std::vector<std::size_t>{ 0, 1, 2, 0, 2, 3, 4 }));
  EXPECT_EQ(soup.polygon_line, (std::vector<std::size_t>{ 10, 11 }));

  // The same file with one bad token: the reader stops there, with its line.
  std::string bad = text;
  bad.replace(bad.find("1E-3"), 4, "1E-3x");
  EXPECT_EQ(I::read_off_soup(bad, soup, I::Diagnostic(&message)), PVF::Error_code::MALFORMED_FILE);
  EXPECT_EQ(message, "line 4: vertex 1: '1E-3x' is not a number");
  bad = text;
  bad.replace(bad.find("4\t+0"), 4, "4\t+9");
  EXPECT_EQ(I::read_off_soup(bad, soup, I::Diagnostic(&message)), PVF::Error_code::MALFORMED_FILE);
  EXPECT_EQ(message, "line 11: face 1 uses vertex +9, not in 0..4");
}

TEST(MeshInputFast, BundledMeshesReadAsCgalReadsThem)
{
  namespace I = PVF::IO::internal;
  for(const char* name : { "bumpy.off", "fandisk.off", "eight.off", "lilium.obj" })
  {
    const std::string path = std::string(PVF_DATA_DIR) + "/" + name;
    I::Polygon_soup soup;
    std::string message;
    ASSERT_EQ(I::read_polygon_soup_file(path, std::size_t(1) << 30, soup, I::Diagnostic(&message)),
              PVF::Error_code::SUCCESS)
      << name << ": " << message;
    std::vector<Kernel::Point_3> points;
    std::vector<std::vector<std::size_t> > polygons;
    ASSERT_TRUE(CGAL::IO::read_polygon_soup(path, points, polygons)) << name;
    ASSERT_EQ(soup.points.size(), points.size()) << name;
    ASSERT_EQ(soup.number_of_polygons(), polygons.size()) << name;
    std::size_t different = 0;
    for(std::size_t v = 0; v < points.size(); ++v)
      for(int c = 0; c < 3; ++c)
        different += same_bits(soup.points[v][c], points[v][c]) ? 0 : 1;
    EXPECT_EQ(different, 0u) << name;
    for(std::size_t i = 0; i < polygons.size(); ++i)
      ASSERT_EQ(std::vector<std::size_t>(soup.polygon(i), soup.polygon(i) + soup.size(i)), polygons[i])
        << name << " face " << i;
  }
}

TEST(MeshInputFast, LinearTimeChecksKeepTheirMessages)
{
  // A vertex shared by two fans of 3 triangles (the small-fan path), and by
  // two fans of 10 (more than 16 corners: the sorted path).
  for(std::size_t fan : { 3u, 10u })
  {
    std::string text = "OFF\n" + std::to_string(1 + 2 * (fan + 1)) + " " + std::to_string(2 * fan) + " 0\n0 0 0\n";
    for(int side = 0; side < 2; ++side)
      for(std::size_t k = 0; k <= fan; ++k)
        text += std::to_string(std::cos(0.3 * double(k))) + " " + std::to_string(std::sin(0.3 * double(k))) + " " +
                (side == 0 ? "1\n" : "-1\n");
    for(int side = 0; side < 2; ++side)
      for(std::size_t k = 0; k < fan; ++k)
      {
        const std::size_t a = 1 + side * (fan + 1) + k;
        text += "3 0 " + std::to_string(a) + " " + std::to_string(a + 1) + "\n";
      }
    const Read r = read_text("pinched.off", text, false);
    EXPECT_EQ(r.code, PVF::Error_code::NON_MANIFOLD_MESH);
    EXPECT_EQ(r.message, "vertex 0 (line 3) is pinched: its faces form 2 separate fans") << fan;
    const Read repaired = read_text("pinched.off", text, true);
    EXPECT_EQ(repaired.code, PVF::Error_code::SUCCESS) << repaired.message;
    EXPECT_EQ(repaired.report.split_vertices, 1u);
  }
  // An edge of three faces, reported with the three faces in file order.
  const Read three = read_text("three.off",
                               "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n", false);
  EXPECT_EQ(three.code, PVF::Error_code::NON_MANIFOLD_MESH);
  EXPECT_EQ(three.message, "the edge between vertices 0 and 1 is shared by 3 faces (face 0 (line 8), face 1 (line 9), "
                           "face 2 (line 10))");
  // Duplicate polygons: a quad repeated in another rotation, among triangles.
  const Read duplicate = read_text("duplicate.off",
                                   "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n4 0 1 2 3\n3 0 1 4\n4 2 3 0 1\n", false);
  EXPECT_EQ(duplicate.code, PVF::Error_code::NON_TRIANGLE_FACE);
  const Read removed = read_text("duplicate.off",
                                 "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n4 0 1 2 3\n3 0 1 4\n4 2 3 0 1\n", true);
  EXPECT_EQ(removed.report.duplicate_faces, 1u) << removed.message;
  const Read triangles = read_text("duplicate.off",
                                   "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 2 0 1\n", false);
  EXPECT_EQ(triangles.code, PVF::Error_code::DUPLICATE_FACE);
  EXPECT_EQ(triangles.message, "face 2 (line 9) has the same vertices as face 0 (line 7)");
}
