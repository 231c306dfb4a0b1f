// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Tests of IO/html_viewer.h and of write_quad_mesh_PLY() (IO/quad_mesh.h) on
// small meshes whose planarity is known in closed form. The page itself is
// drawn by a browser in the test cli_html_viewer_browser.

#include <CGAL/Polyvector_fields/IO/html_viewer.h>
#include <CGAL/Polyvector_fields/IO/quad_mesh.h>
#include <CGAL/Polyvector_fields/Singularity.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "io_test_support.h"

namespace pvf_html_test {

namespace PVF = CGAL::Polyvector_fields;
using PVF::Error_code;
typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef Mesh::Face_index Face;

// The unit square as two triangles, with the frame {±x, ±y} on both.
struct Square
{
  Mesh tm;
  Mesh::Property_map<Face, std::vector<K::Vector_3> > roots;
  std::vector<PVF::Singularity<Vertex> > singularities;
  Square()
  {
    const Vertex a = tm.add_vertex({ 0, 0, 0 }), b = tm.add_vertex({ 1, 0, 0 }), c = tm.add_vertex({ 1, 1, 0 }),
                 d = tm.add_vertex({ 0, 1, 0 });
    tm.add_face(a, b, c);
    tm.add_face(a, c, d);
    roots = tm.add_property_map<Face, std::vector<K::Vector_3> >("f:roots").first;
    for(Face f : faces(tm))
      roots[f] = { { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 }, { 0, -1, 0 } };
    singularities.push_back({ a, 1 });
  }
};

// Two quads side by side: the first planar, the second with its corner (2, 1) lifted by h.
Mesh two_quads(double h)
{
  Mesh pm;
  std::vector<Vertex> v;
  for(int y = 0; y < 2; ++y)
    for(int x = 0; x < 3; ++x)
      v.push_back(pm.add_vertex({ double(x), double(y), x == 2 && y == 1 ? h : 0.0 }));
  pm.add_face(v[0], v[1], v[4], v[3]);
  pm.add_face(v[1], v[2], v[5], v[4]);
  return pm;
}

// The planarity of the quad (0,0,0) (1,0,0) (1,1,h) (0,1,0), by hand: its
// diagonals (1,1,h) and (-1,1,0) have the common normal (-h,-h,2), so their
// distance is h / sqrt(2h^2 + 4); their mean length is (sqrt(2+h^2) + sqrt(2)) / 2.
double lifted_quad_planarity(double h)
{
  return (h / std::sqrt(2 * h * h + 4)) / ((std::sqrt(2 + h * h) + std::sqrt(2.0)) / 2);
}

// A folder with stand-ins for the two three.js files; the first holds the
// sequences that would end a script element.
std::string fake_three_js(const pvf_io_test::Scratch_directory& scratch)
{
  const std::string folder = scratch.file("three");
  std::filesystem::create_directories(folder + "/examples/js/controls");
  std::ofstream(folder + "/three.min.js") << "var THREE = { text: '</script><!-- x' };\n";
  std::ofstream(folder + "/examples/js/controls/OrbitControls.js") << "THREE.OrbitControls = function () {};\n";
  return folder;
}

std::size_t count(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for(std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

TEST(HtmlViewer, PageHoldsTheFiguresAndTheScriptsSafely)
{
  pvf_io_test::Scratch_directory scratch("html_page");
  Square square;
  const double h = 0.1;
  const Mesh quads = two_quads(h);
  const double worst = lifted_quad_planarity(h);
  const std::string page = scratch.file("page.html");
  std::vector<Face> constrained = { *faces(square.tm).begin() };
  ASSERT_EQ(PVF::IO::write_HTML_viewer(page, square.tm, square.roots, 4, square.singularities,
                                       PVF::parameters::quad_mesh(quads, PVF::parameters::three_js_directory(
                                         fake_three_js(scratch), PVF::parameters::page_title(std::string("a <square>"),
                                         PVF::parameters::constrained_faces(constrained))))),
            Error_code::SUCCESS);
  const std::string text = pvf_io_test::file_content(page);
  char figures[200];
  std::snprintf(figures, sizeof(figures), "a &lt;square&gt;: 2 faces, 1 singularities, 2 quads, planarity max %.3g%%, mean %.3g%%",
                100 * worst, 50 * worst);
  EXPECT_NE(text.find("<title>" + std::string(figures) + "</title>"), std::string::npos) << figures;
  // Five script elements (errors, three.js, OrbitControls, data, viewer), and
  // the copied file's "</script" and "<!--" escaped.
  EXPECT_EQ(count(text, "<script"), 5u);
  EXPECT_EQ(count(text, "</script>"), 5u);
  EXPECT_NE(text.find("text: '<\\/script><\\!-- x'"), std::string::npos);
  // The data: a symmetric field stored as one vector per pair, one constrained face, the title escaped for JSON.
  EXPECT_NE(text.find("\"symmetric\":true"), std::string::npos);
  EXPECT_NE(text.find("\"constrained\":\"AAAAAA==\""), std::string::npos);  // face 0 as a little-endian uint32
  EXPECT_NE(text.find("\"title\":\"a \\u003csquare\\u003e\""), std::string::npos);
  EXPECT_EQ(text.find("http"), std::string::npos);  // nothing fetched
}

TEST(HtmlViewer, MissingThreeJsFileWritesNothing)
{
  pvf_io_test::Scratch_directory scratch("html_missing");
  Square square;
  const std::string page = scratch.file("page.html");
  std::ofstream(page) << "old";
  std::string message;
  const std::string folder = scratch.file("no_three");
  EXPECT_EQ(PVF::IO::write_HTML_viewer(page, square.tm, square.roots, 4, square.singularities,
                                       PVF::parameters::three_js_directory(folder, PVF::parameters::error_message(message))),
            Error_code::CANNOT_OPEN_FILE);
  EXPECT_NE(message.find("'" + folder + "/three.min.js'"), std::string::npos) << message;
  EXPECT_NE(message.find("libjs-three"), std::string::npos) << message;
  EXPECT_EQ(pvf_io_test::file_content(page), "old");
  EXPECT_EQ(scratch.entries(), std::set<std::string>({ "page.html" }));
}

TEST(HtmlViewer, BadInputWritesNothing)
{
  pvf_io_test::Scratch_directory scratch("html_bad");
  Square square;
  const std::string three = fake_three_js(scratch);
  const std::string page = scratch.file("page.html");
  const auto np = PVF::parameters::three_js_directory(three);
  EXPECT_EQ(PVF::IO::write_HTML_viewer(page, square.tm, square.roots, 0, square.singularities, np), Error_code::INVALID_DEGREE);
  EXPECT_EQ(PVF::IO::write_HTML_viewer(page, square.tm, square.roots, 6, square.singularities, np),
            Error_code::INCONSISTENT_DEGREE);
  EXPECT_EQ(PVF::IO::write_HTML_viewer(page, square.tm, square.roots, 4, square.singularities,
                                       PVF::parameters::max_glyph_faces(std::size_t(0), np)),
            Error_code::INVALID_PARAMETER);
  const Mesh quads = two_quads(0.1), empty;
  EXPECT_EQ(PVF::IO::write_HTML_viewer(page, square.tm, square.roots, 4, square.singularities,
                                       PVF::parameters::quad_mesh(quads, PVF::parameters::planarity_colour_range(-1.0, np))),
            Error_code::INVALID_PARAMETER);
  std::string message;
  EXPECT_EQ(PVF::IO::write_HTML_viewer(page, square.tm, square.roots, 4, square.singularities,
                                       PVF::parameters::quad_mesh(empty, PVF::parameters::error_message(message, np))),
            Error_code::EMPTY_MESH);
  EXPECT_EQ(message, "the quad mesh has no face");
  std::vector<PVF::Singularity<Vertex> > twice = { square.singularities[0], square.singularities[0] };
  EXPECT_EQ(PVF::IO::write_HTML_viewer(page, square.tm, square.roots, 4, twice, np), Error_code::INVALID_PARAMETER);
  EXPECT_FALSE(std::filesystem::exists(page));
}

// The PLY file read back: per face its corners, quality and colour.
struct Ply_face
{
  std::vector<int> corners;
  double quality = 0;
  int red = -1, green = -1, blue = -1;
};

std::vector<Ply_face> read_ply_faces(const std::string& text)
{
  std::istringstream in(text);
  std::string line;
  std::size_t vertices = 0, faces = 0;
  std::vector<std::string> face_properties;
  bool in_faces = false;
  while(std::getline(in, line) && line != "end_header")
  {
    std::istringstream words(line);
    std::string a, b, c;
    words >> a >> b >> c;
    if(a == "element")
    {
      in_faces = b == "face";
      (in_faces ? faces : vertices) = std::stoul(c);
    }
    else if(a == "property" && in_faces)
      face_properties.push_back(line.substr(line.rfind(' ') + 1));
  }
  for(std::size_t i = 0; i < vertices; ++i)
    std::getline(in, line);
  std::vector<Ply_face> result;
  for(std::size_t i = 0; i < faces; ++i)
  {
    Ply_face f;
    std::size_t n = 0;
    in >> n;
    f.corners.resize(n);
    for(int& c : f.corners)
      in >> c;
    for(std::size_t p = 1; p < face_properties.size(); ++p)
    {
      double x = 0;
      in >> x;
      const std::string& name = face_properties[p];
      if(name == "quality") f.quality = x;
      else if(name == "red") f.red = int(x);
      else if(name == "green") f.green = int(x);
      else if(name == "blue") f.blue = int(x);
    }
    result.push_back(f);
  }
  return result;
}

TEST(QuadMeshPly, QualityIsThePlanarityAndColoursFollowTheMap)
{
  pvf_io_test::Scratch_directory scratch("ply");
  const double h = 0.25;
  const Mesh quads = two_quads(h);
  const std::string file = scratch.file("quads.ply");
  ASSERT_EQ(PVF::IO::write_quad_mesh_PLY(file, quads), Error_code::SUCCESS);
  const std::vector<Ply_face> faces = read_ply_faces(pvf_io_test::file_content(file));
  ASSERT_EQ(faces.size(), 2u);
  EXPECT_EQ(faces[0].corners.size(), 4u);
  EXPECT_EQ(faces[0].quality, 0.0);
  EXPECT_NEAR(faces[1].quality, lifted_quad_planarity(h), 1e-15);
  // Planar: the blue end of the map; the worst quad at the top of the default range: its red end.
  EXPECT_EQ(faces[0].red, 35);
  EXPECT_EQ(faces[0].green, 75);
  EXPECT_EQ(faces[0].blue, 200);
  EXPECT_EQ(faces[1].red, 210);
  EXPECT_EQ(faces[1].green, 25);
  EXPECT_EQ(faces[1].blue, 25);
  // With the range at twice the worst planarity, that quad is half-way: between the stops 0.3 and 0.55.
  ASSERT_EQ(PVF::IO::write_quad_mesh_PLY(file, quads, PVF::parameters::planarity_colour_range(2 * lifted_quad_planarity(h))),
            Error_code::SUCCESS);
  const std::vector<Ply_face> half = read_ply_faces(pvf_io_test::file_content(file));
  EXPECT_EQ(half[1].red, int(std::lround(80 + 0.8 * (245 - 80))));
  EXPECT_EQ(half[1].green, int(std::lround(170 + 0.8 * (240 - 170))));
  EXPECT_EQ(half[1].blue, int(std::lround(235 + 0.8 * (190 - 235))));
}

TEST(QuadMeshPly, BadInputWritesNothing)
{
  pvf_io_test::Scratch_directory scratch("ply_bad");
  const std::string file = scratch.file("quads.ply");
  const Mesh empty;
  EXPECT_EQ(PVF::IO::write_quad_mesh_PLY(file, empty), Error_code::EMPTY_MESH);
  Mesh quads = two_quads(0.1);
  EXPECT_EQ(PVF::IO::write_quad_mesh_PLY(file, quads, PVF::parameters::planarity_colour_range(0.0)),
            Error_code::INVALID_PARAMETER);
  quads.point(*vertices(quads).begin()) = K::Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  EXPECT_EQ(PVF::IO::write_quad_mesh_PLY(file, quads), Error_code::NON_FINITE_VALUE);
  EXPECT_TRUE(scratch.entries().empty());
}

} // namespace pvf_html_test
