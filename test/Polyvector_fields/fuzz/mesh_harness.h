// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// The body of the fuzz targets `off_mesh` and `obj_mesh`: a soup parser of
// IO/internal/polygon_soup.h, then IO::internal::soup_to_triangle_mesh(), the
// checks and repairs of read_triangle_mesh().
//
// Input: byte 0 chooses the repair (bit 0 set: repair on); the rest is the
// file. Checked:
//  - a parser failure has a known code and a message, and leaves the soup as it was;
//  - a parsed soup has ids in range and polygons of at least 3 vertices;
//  - a mesh failure has a known code and a message, and leaves `tm` and the report as they were;
//  - a success gives a valid triangle mesh (is_valid_polygon_mesh, or Surface_mesh::is_valid
//    when isolated vertices are kept without repair; is_triangle_mesh)
//    with at least one face, finite points, no face that cannot carry a frame,
//    one source face per face (a face of the file), and, without repair,
//    exactly the faces and vertices of the file in file order.

#ifndef CGAL_POLYVECTOR_FIELDS_TEST_FUZZ_MESH_HARNESS_H
#define CGAL_POLYVECTOR_FIELDS_TEST_FUZZ_MESH_HARNESS_H

#include "fuzz_support.h"

#include <CGAL/Polyvector_fields/IO/internal/polygon_soup.h>
#include <CGAL/Polyvector_fields/IO/read_triangle_mesh.h>
#include <CGAL/Polyvector_fields/face_frames.h>

#include <CGAL/boost/graph/helpers.h>

namespace pvf_fuzz_mesh {

using namespace pvf_fuzz;

enum class Format
{
  OFF,
  OBJ
};

inline PIO::internal::Polygon_soup sentinel_soup()
{
  PIO::internal::Polygon_soup soup;
  soup.points = { { 1.5, 2.5, 3.5 } };
  soup.ids = { 0, 0, 0 };
  soup.first = { 0, 3 };
  soup.polygon_line = { 17 };
  soup.point_line = { 16 };
  return soup;
}

inline bool same_soup(const PIO::internal::Polygon_soup& a, const PIO::internal::Polygon_soup& b)
{
  return a.points == b.points && a.first == b.first && a.ids == b.ids && a.point_line == b.point_line &&
         a.polygon_line == b.polygon_line;
}

inline void run(Format format, const std::uint8_t* data, std::size_t size)
{
  if(size == 0)
    return;
  const bool repair = (data[0] & 1) != 0;
  const std::string text = as_text(data + 1, size - 1);
  const char* parser = format == Format::OFF ? "read_off_soup" : "read_obj_soup";

  PIO::internal::Polygon_soup soup = sentinel_soup();
  std::string message;
  const PIO::internal::Diagnostic diagnostic(&message);
  Error_code code = format == Format::OFF ? PIO::internal::read_off_soup(text, soup, diagnostic)
                                          : PIO::internal::read_obj_soup(text, soup, diagnostic);
  if(code != Error_code::SUCCESS)
  {
    check_failure_reported(code, message, parser);
    PVF_FUZZ_CHECK(same_soup(soup, sentinel_soup()), std::string("a failed ") + parser + " changed the soup");
    return;
  }
  const std::size_t file_vertices = soup.points.size(), file_faces = soup.number_of_polygons();
  PVF_FUZZ_CHECK(!soup.first.empty() && soup.first.front() == 0 && soup.first.back() == soup.ids.size(),
                 "the soup's polygon offsets do not cover its ids");
  for(std::size_t i = 0; i < file_faces; ++i)
  {
    PVF_FUZZ_CHECK(soup.first[i] <= soup.first[i + 1], "the soup's polygon offsets decrease");
    PVF_FUZZ_CHECK(soup.size(i) >= 3, soup.face_name(i) + " has fewer than 3 vertices");
  }
  for(std::size_t id : soup.ids)
    PVF_FUZZ_CHECK(id < file_vertices, "a polygon uses vertex " + std::to_string(id) + " of " +
                                         std::to_string(file_vertices));
  for(const auto& p : soup.points)
    PVF_FUZZ_CHECK(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]), "a non-finite point was read");

  Mesh tm = tetrahedron();
  PIO::Mesh_repair_result report;
  report.file_vertices = 777;
  report.source_face = { 1, 2, 3 };
  message.clear();
  code = PIO::internal::soup_to_triangle_mesh(soup, tm, report, repair, diagnostic);
  if(code != Error_code::SUCCESS)
  {
    check_failure_reported(code, message, "soup_to_triangle_mesh");
    PVF_FUZZ_CHECK(num_vertices(tm) == 4 && num_faces(tm) == 4 && tm.is_valid(false),
                   "a failed soup_to_triangle_mesh changed the mesh");
    PVF_FUZZ_CHECK(report.file_vertices == 777 && report.source_face == std::vector<std::size_t>({ 1, 2, 3 }),
                   "a failed soup_to_triangle_mesh changed the report");
    return;
  }
  const std::string mode = repair ? " (repair on)" : " (repair off)";
  // Without repair, isolated vertices are kept (documented); CGAL 5.5's
  // is_valid_polygon_mesh() refuses any vertex without a halfedge, so such a
  // mesh is checked by Surface_mesh::is_valid(), which accepts them.
  std::size_t isolated = 0;
  for(Vertex v : vertices(tm))
    isolated += tm.is_isolated(v) ? 1 : 0;
  PVF_FUZZ_CHECK(isolated == (repair ? 0 : report.isolated_vertices),
                 std::to_string(isolated) + " isolated vertices, the report says " +
                   std::to_string(report.isolated_vertices) + mode);
  if(isolated == 0)
    PVF_FUZZ_CHECK(CGAL::is_valid_polygon_mesh(tm), "the mesh is not valid" + mode);
  else
    PVF_FUZZ_CHECK(tm.is_valid(false), "the mesh is not valid" + mode);
  PVF_FUZZ_CHECK(CGAL::is_triangle_mesh(tm), "the mesh is not a triangle mesh" + mode);
  PVF_FUZZ_CHECK(num_faces(tm) > 0, "the mesh has no face" + mode);
  PVF_FUZZ_CHECK(report.source_face.size() == num_faces(tm),
                 std::to_string(report.source_face.size()) + " source faces for " + std::to_string(num_faces(tm)) +
                   " faces" + mode);
  PVF_FUZZ_CHECK(report.file_vertices == file_vertices && report.file_faces == file_faces,
                 "the report counts other vertices or faces than the file has" + mode);
  for(std::size_t s : report.source_face)
    PVF_FUZZ_CHECK(s < file_faces, "source face " + std::to_string(s) + " of " + std::to_string(file_faces) + mode);
  for(Vertex v : vertices(tm))
  {
    const Point& p = tm.point(v);
    PVF_FUZZ_CHECK(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()), "a non-finite point" + mode);
  }
  for(Face f : faces(tm))
  {
    PVF::Face_frame frame;
    const Error_code frame_code = PVF::face_frame(f, tm, frame);
    PVF_FUZZ_CHECK(frame_code == Error_code::SUCCESS, "face " + std::to_string(std::size_t(f)) +
                                                        " cannot carry a frame: " + code_name(frame_code) + mode);
  }
  if(!repair)
  {
    PVF_FUZZ_CHECK(!report.changed(false), "the mesh was changed without repair");
    PVF_FUZZ_CHECK(num_faces(tm) == file_faces && num_vertices(tm) == file_vertices,
                   "without repair the mesh has other faces or vertices than the file");
    for(std::size_t i = 0; i < report.source_face.size(); ++i)
      PVF_FUZZ_CHECK(report.source_face[i] == i, "without repair face " + std::to_string(i) + " comes from face " +
                                                   std::to_string(report.source_face[i]));
  }
}

} // namespace pvf_fuzz_mesh

#endif // CGAL_POLYVECTOR_FIELDS_TEST_FUZZ_MESH_HARNESS_H
