// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_POLYGON_SOUP_H
#define CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_POLYGON_SOUP_H

// A polygon soup read from a mesh file, and the readers that make it.
//
// OFF and OBJ, the text formats of most meshes, are read here, token by token
// with the package's locale-independent parsers: the first bad token stops the
// reader, with its line in the message. Other formats (PLY, STL) go through
// CGAL's soup readers, on the bytes already read under the size limit, and are
// then checked for non-finite coordinates and out-of-range indices here.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>

#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Simple_cartesian.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {
namespace internal {

// Points and polygons, polygons stored flat: polygon i has the vertex ids
// ids[first[i] .. first[i+1]-1]. `point_line` and `polygon_line` give the line
// of each in the file (0 for formats without lines).
struct Polygon_soup
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::size_t> first{ 0 };
  std::vector<std::size_t> ids;
  std::vector<std::size_t> point_line, polygon_line;

  std::size_t number_of_polygons() const { return first.size() - 1; }
  std::size_t size(std::size_t i) const { return first[i + 1] - first[i]; }
  const std::size_t* polygon(std::size_t i) const { return ids.data() + first[i]; }

  // "face 12 (line 20)", or "face 12" without line information.
  std::string face_name(std::size_t i) const
  {
    std::string name = "face " + std::to_string(i);
    if(i < polygon_line.size() && polygon_line[i] != 0)
      name += " (line " + std::to_string(polygon_line[i]) + ")";
    return name;
  }
  std::string vertex_name(std::size_t v) const
  {
    std::string name = "vertex " + std::to_string(v);
    if(v < point_line.size() && point_line[v] != 0)
      name += " (line " + std::to_string(point_line[v]) + ")";
    return name;
  }
};

inline Error_code read_soup_coordinate(Text_reader& reader, std::size_t vertex, double& x, const Diagnostic& diagnostic)
{
  std::string_view token;
  if(!reader.next_token(token))
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE,
                              "vertex " + std::to_string(vertex) + " has fewer than 3 coordinates");
  switch(parse_double(token, x))
  {
    case Token_status::OK: return Error_code::SUCCESS;
    case Token_status::NON_FINITE:
      return diagnostic.fail_at(reader, Error_code::NON_FINITE_VALUE,
                                "vertex " + std::to_string(vertex) + " has the non-finite coordinate " + quoted(token));
    default:
      return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE,
                                "vertex " + std::to_string(vertex) + ": " + quoted(token) + " is not a number");
  }
}

// ASCII OFF (with the optional ST, C, N prefixes of the header, whose extra
// numbers per vertex and colours per face are skipped). A file may start with
// the counts when it has no header. Binary OFF is refused.
inline Error_code read_off_soup(std::string_view text, Polygon_soup& soup, const Diagnostic& diagnostic)
{
  Text_reader reader(text, '#');
  std::string_view token;
  if(!reader.next_line() || !reader.next_token(token))
    return diagnostic.fail(Error_code::MALFORMED_FILE, "the file is empty");
  std::size_t counts[3] = { 0, 0, 0 };
  std::size_t counted = 0;
  if(token.size() >= 3 && token.substr(token.size() - 3) == "OFF")
  {
    const std::string_view prefix = token.substr(0, token.size() - 3);
    for(char c : prefix)
      if(c != 'S' && c != 'T' && c != 'C' && c != 'N')
        return diagnostic.fail_at(reader, Error_code::UNSUPPORTED_FORMAT,
                                  "the header " + quoted(token) + " is not an OFF variant this reader knows (ST, C, N)");
    if(reader.next_token(token))
    {
      if(token == "BINARY")
        return diagnostic.fail_at(reader, Error_code::UNSUPPORTED_FORMAT, "binary OFF is not supported: convert it to ASCII");
      // The counts may follow the header on the same line.
      if(parse_integer(token, counts[0]) != Token_status::OK)
        return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, quoted(token) + " is not a vertex count");
      counted = 1;
    }
  }
  else if(parse_integer(token, counts[0]) == Token_status::OK)
    counted = 1;  // no header: the counts come first
  else
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "the header " + quoted(token) + " is not 'OFF'");
  while(counted < 3)
  {
    if(!reader.next_token(token))
    {
      if(counted >= 2)
        break;  // the edge count is optional
      if(!reader.next_line() || !reader.next_token(token))
        return diagnostic.fail(Error_code::MALFORMED_FILE, "the file ends before the counts 'vertices faces edges'");
    }
    if(parse_integer(token, counts[counted]) != Token_status::OK)
      return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, quoted(token) + " is not a count");
    ++counted;
  }
  const std::size_t nv = counts[0], nf = counts[1];
  // A vertex takes at least 6 characters and a face 8: larger counts cannot be true.
  if(nv > text.size() / 6 + 1 || nf > text.size() / 8 + 1)
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE,
                              "the counts (" + std::to_string(nv) + " vertices, " + std::to_string(nf) +
                                " faces) are more than the file can hold");

  Polygon_soup result;
  result.points.resize(nv);
  result.point_line.resize(nv);
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(!reader.next_line())
      return diagnostic.fail(Error_code::MALFORMED_FILE, "the file ends after " + std::to_string(v) + " of " +
                                                           std::to_string(nv) + " vertices");
    result.point_line[v] = reader.line_number();
    for(int c = 0; c < 3; ++c)
    {
      const Error_code code = read_soup_coordinate(reader, v, result.points[v][c], diagnostic);
      if(code != Error_code::SUCCESS)
        return code;
    }
  }
  result.first.reserve(nf + 1);
  result.ids.reserve(3 * nf);
  result.polygon_line.resize(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(!reader.next_line())
      return diagnostic.fail(Error_code::MALFORMED_FILE, "the file ends after " + std::to_string(f) + " of " +
                                                           std::to_string(nf) + " faces");
    result.polygon_line[f] = reader.line_number();
    std::size_t n = 0;
    reader.next_token(token);
    if(parse_integer(token, n) != Token_status::OK)
      return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE,
                                "face " + std::to_string(f) + ": " + quoted(token) + " is not a vertex count");
    if(n < 3)
      return diagnostic.fail_at(reader, Error_code::DEGENERATE_FACE,
                                "face " + std::to_string(f) + " has " + std::to_string(n) + " vertices; a face needs 3");
    for(std::size_t k = 0; k < n; ++k)
    {
      std::size_t id = 0;
      if(!reader.next_token(token))
        return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "face " + std::to_string(f) + " announces " +
                                                                        std::to_string(n) + " vertices but lists " +
                                                                        std::to_string(k));
      const Token_status status = parse_integer(token, id);
      if(status == Token_status::MALFORMED)
        return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE,
                                  "face " + std::to_string(f) + ": " + quoted(token) + " is not a vertex index");
      if(status != Token_status::OK || id >= nv)
        return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE,
                                  "face " + std::to_string(f) + " uses vertex " + std::string(token) +
                                    ", not in 0.." + std::to_string(nv == 0 ? 0 : nv - 1));
      result.ids.push_back(id);
    }
    result.first.push_back(result.ids.size());
    // Anything left on the line is a colour: ignored.
  }
  soup = std::move(result);
  return Error_code::SUCCESS;
}

// The vertex index of an OBJ face token "i", "i/t", "i//n" or "i/t/n"; negative
// indices count back from the last vertex read.
inline Error_code read_obj_index(std::string_view token, std::size_t vertices_so_far, std::size_t face,
                                 const Text_reader& reader, std::size_t& id, const Diagnostic& diagnostic)
{
  const std::string_view index = token.substr(0, token.find('/'));
  long long value = 0;
  const Token_status status = parse_integer(index, value);
  if(status == Token_status::MALFORMED)
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE,
                              "face " + std::to_string(face) + ": " + quoted(token) + " is not a vertex index");
  const long long n = static_cast<long long>(vertices_so_far);
  if(status != Token_status::OK || value == 0 || value > n || value < -n)
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE,
                              "face " + std::to_string(face) + " uses vertex " + std::string(index) +
                                (value == 0 ? " (OBJ indices start at 1)"
                                            : ", not in 1.." + std::to_string(n) + " (or -" + std::to_string(n) + "..-1)"));
  id = value > 0 ? std::size_t(value - 1) : std::size_t(n + value);
  return Error_code::SUCCESS;
}

// OBJ: the `v` and `f` statements; others (vt, vn, g, o, s, usemtl, l, ...) are skipped.
inline Error_code read_obj_soup(std::string_view text, Polygon_soup& soup, const Diagnostic& diagnostic)
{
  Text_reader reader(text, '#');
  std::string_view token;
  Polygon_soup result;
  while(reader.next_line())
  {
    reader.next_token(token);
    if(token == "v")
    {
      std::array<double, 3> p;
      for(int c = 0; c < 3; ++c)
      {
        const Error_code code = read_soup_coordinate(reader, result.points.size(), p[c], diagnostic);
        if(code != Error_code::SUCCESS)
          return code;
      }
      result.points.push_back(p);
      result.point_line.push_back(reader.line_number());
    }
    else if(token == "f")
    {
      const std::size_t f = result.number_of_polygons();
      std::size_t n = 0, id = 0;
      while(reader.next_token(token))
      {
        const Error_code code = read_obj_index(token, result.points.size(), f, reader, id, diagnostic);
        if(code != Error_code::SUCCESS)
          return code;
        result.ids.push_back(id);
        ++n;
      }
      if(n < 3)
        return diagnostic.fail_at(reader, Error_code::DEGENERATE_FACE,
                                  "face " + std::to_string(f) + " has " + std::to_string(n) + " vertices; a face needs 3");
      result.first.push_back(result.ids.size());
      result.polygon_line.push_back(reader.line_number());
    }
  }
  soup = std::move(result);
  return Error_code::SUCCESS;
}

// PLY and STL through CGAL, from the bytes in memory; then the checks that the
// text readers make as they go.
inline Error_code read_cgal_soup(const std::string& bytes, const std::string& extension, Polygon_soup& soup,
                                 const Diagnostic& diagnostic)
{
  typedef CGAL::Simple_cartesian<double>::Point_3 Point;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  std::istringstream in(bytes, std::ios::in | std::ios::binary);
  bool ok = false;
  try
  {
    if(extension == ".ply")
      ok = CGAL::IO::read_PLY(in, points, polygons, CGAL::parameters::verbose(false));
    else
      ok = CGAL::IO::read_STL(in, points, polygons, CGAL::parameters::verbose(false));
  }
  catch(const std::exception&)
  {
    ok = false;
  }
  if(!ok)
    return diagnostic.fail(Error_code::MALFORMED_FILE, "CGAL's " + extension.substr(1) + " reader cannot read it");
  Polygon_soup result;
  result.points.resize(points.size());
  for(std::size_t v = 0; v < points.size(); ++v)
  {
    result.points[v] = { points[v].x(), points[v].y(), points[v].z() };
    for(double x : result.points[v])
      if(!std::isfinite(x))
        return diagnostic.fail(Error_code::NON_FINITE_VALUE, "vertex " + std::to_string(v) + " has a non-finite coordinate");
  }
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    if(polygons[f].size() < 3)
      return diagnostic.fail(Error_code::DEGENERATE_FACE, "face " + std::to_string(f) + " has " +
                                                            std::to_string(polygons[f].size()) + " vertices; a face needs 3");
    for(std::size_t id : polygons[f])
    {
      if(id >= points.size())
        return diagnostic.fail(Error_code::MALFORMED_FILE, "face " + std::to_string(f) + " uses vertex " +
                                                             std::to_string(id) + ", not in 0.." +
                                                             std::to_string(points.size() - 1));
      result.ids.push_back(id);
    }
    result.first.push_back(result.ids.size());
  }
  soup = std::move(result);
  return Error_code::SUCCESS;
}

// Reads the soup of `filename` under the size limit, by its extension
// (case-insensitive): .off, .obj, .ply, .stl.
inline Error_code read_polygon_soup_file(const std::string& filename, std::size_t limit, Polygon_soup& soup,
                                         const Diagnostic& diagnostic)
{
  std::string extension = std::filesystem::path(filename).extension().string();
  for(char& c : extension)
    c = to_lower_ascii(c);
  const bool text = (extension == ".off" || extension == ".obj");
  const bool known = text || extension == ".ply" || extension == ".stl";
  // A missing file or a directory is said as such, whatever its name.
  std::string bytes;
  const Read_status status = read_file_bounded(filename, known ? limit : 0, text, bytes);
  if(status == Read_status::MISSING || status == Read_status::DIRECTORY || status == Read_status::CANNOT_OPEN)
    return read_error(status, limit, diagnostic, std::string());
  if(!known)
    return diagnostic.fail(Error_code::UNSUPPORTED_FORMAT,
                           "the extension '" + extension + "' is not one of .off, .obj, .ply, .stl");
  const Error_code code = read_error(status, limit, diagnostic, std::string());
  if(code != Error_code::SUCCESS)
    return code;
  if(extension == ".off")
    return read_off_soup(bytes, soup, diagnostic);
  if(extension == ".obj")
    return read_obj_soup(bytes, soup, diagnostic);
  return read_cgal_soup(bytes, extension, soup, diagnostic);
}

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_POLYGON_SOUP_H
