// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_HTML_VIEWER_TEXT_H
#define CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_HTML_VIEWER_TEXT_H

// The page of write_HTML_viewer(), built in memory: the input checked, the
// data block (JSON whose arrays are little-endian float32 / uint32 / int32 in
// base64), the three.js files read from disk and spliced in.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/html_viewer_page.h>
#include <CGAL/Polyvector_fields/IO/internal/mesh_indices.h>
#include <CGAL/Polyvector_fields/IO/internal/planarity_colours.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>
#include <CGAL/Polyvector_fields/IO/internal/vtk_text.h>
#include <CGAL/Polyvector_fields/IO/quad_mesh.h>
#include <CGAL/Polyvector_fields/IO/singularities.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {
namespace internal {

// The folder of Debian's libjs-three.
inline const char* default_three_js_directory() { return "/usr/share/javascript/three"; }

// The files of that folder copied into the page, in this order.
inline std::vector<std::string> three_js_files()
{
  return { "three.min.js", "examples/js/controls/OrbitControls.js" };
}

// Appends the base64 encoding of `size` bytes.
inline void append_base64(std::string& out, const unsigned char* data, std::size_t size)
{
  static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::size_t i = 0;
  for(; i + 2 < size; i += 3)
  {
    const unsigned v = (unsigned(data[i]) << 16) | (unsigned(data[i + 1]) << 8) | unsigned(data[i + 2]);
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += digits[(v >> 6) & 63];
    out += digits[v & 63];
  }
  if(i + 1 == size)
  {
    const unsigned v = unsigned(data[i]) << 16;
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += "==";
  }
  else if(i + 2 == size)
  {
    const unsigned v = (unsigned(data[i]) << 16) | (unsigned(data[i + 1]) << 8);
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += digits[(v >> 6) & 63];
    out += '=';
  }
}

// 32-bit words, little-endian, whatever the byte order of the machine.
inline void append_words_base64(std::string& out, const std::vector<std::uint32_t>& words)
{
  std::vector<unsigned char> bytes(4 * words.size());
  for(std::size_t i = 0; i < words.size(); ++i)
    for(int b = 0; b < 4; ++b)
      bytes[4 * i + b] = static_cast<unsigned char>((words[i] >> (8 * b)) & 0xFF);
  out += '"';
  append_base64(out, bytes.data(), bytes.size());
  out += '"';
}

inline void append_floats_base64(std::string& out, const std::vector<float>& values)
{
  std::vector<std::uint32_t> words(values.size());
  static_assert(sizeof(float) == 4, "float32 expected");
  for(std::size_t i = 0; i < values.size(); ++i)
    std::memcpy(&words[i], &values[i], 4);
  append_words_base64(out, words);
}

inline void append_ints_base64(std::string& out, const std::vector<std::int32_t>& values)
{
  std::vector<std::uint32_t> words(values.size());
  for(std::size_t i = 0; i < values.size(); ++i)
    words[i] = static_cast<std::uint32_t>(values[i]);
  append_words_base64(out, words);
}

inline void append_shorts_base64(std::string& out, const std::vector<std::int16_t>& values)
{
  std::vector<unsigned char> bytes(2 * values.size());
  for(std::size_t i = 0; i < values.size(); ++i)
  {
    const std::uint16_t v = static_cast<std::uint16_t>(values[i]);
    bytes[2 * i] = static_cast<unsigned char>(v & 0xFF);
    bytes[2 * i + 1] = static_cast<unsigned char>(v >> 8);
  }
  out += '"';
  append_base64(out, bytes.data(), bytes.size());
  out += '"';
}

// A JSON string; '<', '>' and '&' escaped so that it cannot close the script element.
inline void append_json_string(std::string& out, const std::string& text)
{
  out += '"';
  for(unsigned char c : text)
  {
    if(c == '"' || c == '\\')
    {
      out += '\\';
      out += char(c);
    }
    else if(c < 0x20 || c == '<' || c == '>' || c == '&')
    {
      char buffer[8];
      std::snprintf(buffer, sizeof(buffer), "\\u%04x", unsigned(c));
      out += buffer;
    }
    else
      out += char(c);
  }
  out += '"';
}

inline std::string html_escaped(const std::string& text)
{
  std::string out;
  for(char c : text)
  {
    switch(c)
    {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// A percentage with 3 significant digits: 0.00998 -> "0.998%".
inline std::string percent(double x)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.3g%%", 100 * x);
  return buffer;
}

// A script copied into the page: "</script" and "<!--" would end or confuse
// the script element; written "<\/script" and "<\!--", the same in a JS string.
inline std::string inline_script(const std::string& code)
{
  std::string out;
  out.reserve(code.size());
  for(std::size_t i = 0; i < code.size(); ++i)
  {
    if(code[i] == '<' && i + 1 < code.size() && (code[i + 1] == '/' || code[i + 1] == '!'))
    {
      std::string next;
      for(std::size_t j = i + 1; j < code.size() && j < i + 8; ++j)
        next += char(std::tolower(static_cast<unsigned char>(code[j])));
      if(next.rfind("/script", 0) == 0 || next.rfind("!--", 0) == 0)
      {
        out += "<\\";
        continue;
      }
    }
    out += code[i];
  }
  return out;
}

// Reads the three.js files; CANNOT_OPEN_FILE, with `message` naming the file, if one is missing or empty.
inline Error_code read_three_js(const std::string& directory, std::vector<std::string>& scripts, std::string& message)
{
  scripts.clear();
  for(const std::string& name : three_js_files())
  {
    const std::string path = directory + "/" + name;
    std::ifstream in(path, std::ios::binary);
    std::ostringstream content;
    if(in)
      content << in.rdbuf();
    if(!in || content.str().empty())
    {
      message = "cannot read the three.js file '" + path + "'" + (in ? ": it is empty" : ": " + std::string(std::strerror(errno))) +
                " (it comes with Debian's package libjs-three; or give its folder with the named parameter three_js_directory)";
      return Error_code::CANNOT_OPEN_FILE;
    }
    scripts.push_back(inline_script(content.str()));
  }
  return Error_code::SUCCESS;
}

// What the page shows of a quad mesh: its vertices (relative to `centre`),
// face sizes, corners, planarity and colours; and the summary figures.
struct Html_quads
{
  std::vector<float> vertices;
  std::vector<std::uint32_t> sizes, corners, colours;
  std::vector<float> planarity;
  Planarity_result stats;
  double range = 0;
};

template <typename PolygonMesh, typename NamedParameters>
Error_code html_quads(const PolygonMesh& pm, const NamedParameters& np, const std::array<double, 3>& centre,
                      Html_quads& q)
{
  using boost::get;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  const auto vpm = CGAL::get_const_property_map(CGAL::vertex_point, pm);
  if(faces(pm).empty())
    return Error_code::EMPTY_MESH;
  std::vector<double> planarity;
  Error_code code = Polyvector_fields::internal::face_planarities(pm, vpm, planarity, q.stats);
  if(code != Error_code::SUCCESS)
    return code;
  code = Polyvector_fields::internal::planarity_colour_range(np, q.stats, q.range);
  if(code != Error_code::SUCCESS)
    return code;
  Polyvector_fields::internal::Numbering<vertex_descriptor> index;
  for(vertex_descriptor v : vertices(pm))
  {
    index.add(v);
    const auto& p = get(vpm, v);
    const double xyz[3] = { CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) };
    for(int c = 0; c < 3; ++c)
      q.vertices.push_back(float(xyz[c] - centre[c]));
  }
  std::size_t i = 0;
  for(auto f : faces(pm))
  {
    std::uint32_t size = 0;
    for(auto h : halfedges_around_face(halfedge(f, pm), pm))
    {
      q.corners.push_back(std::uint32_t(index(target(h, pm))));
      ++size;
    }
    q.sizes.push_back(size);
    q.planarity.push_back(float(planarity[i]));
    const auto c = planarity_colour(planarity[i], q.range);
    q.colours.push_back((std::uint32_t(c[0]) << 16) | (std::uint32_t(c[1]) << 8) | std::uint32_t(c[2]));
    ++i;
  }
  return Error_code::SUCCESS;
}

// The parts of the page that do not depend on the quad mesh's type.
struct Html_page_parts
{
  std::string title;           // the caller's title
  std::string summary;         // the figures, after the title
  std::string data;            // the JSON data block
  std::vector<std::string> scripts;  // three.js and OrbitControls
};

inline std::string html_page(const Html_page_parts& parts)
{
  const std::string heading = html_escaped(parts.title + ": " + parts.summary);
  std::string page;
  std::size_t size = parts.data.size() + 20000;
  for(const std::string& s : parts.scripts)
    size += s.size() + 64;
  page.reserve(size);
  page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>";
  page += heading;
  page += "</title>\n<meta name=\"generator\" content=\"CGAL Polyvector Fields, IO::write_HTML_viewer()\">\n";
  page += html_viewer_style();
  page += "</head>\n<body>\n<div id=\"pvf-panel\">\n<h1 id=\"pvf-title\">";
  page += heading;
  page += "</h1>\n<div id=\"pvf-layers\"></div>\n<div id=\"pvf-help\">drag: rotate; right drag: pan; wheel: zoom</div>\n</div>\n";
  page += "<div id=\"pvf-colour-bar\"><div class=\"pvf-bar-caption\">planarity</div><div class=\"pvf-bar-body\">"
          "<div id=\"pvf-colour-ramp\"></div><span id=\"pvf-colour-top\"></span><span id=\"pvf-colour-middle\"></span>"
          "<span id=\"pvf-colour-bottom\">0%</span></div></div>\n";
  page += "<pre id=\"pvf-errors\"></pre>\n<div id=\"pvf-status\" data-state=\"loading\" data-errors=\"0\" hidden></div>\n";
  page += "<script>\n";
  page += html_viewer_error_script();
  page += "</script>\n";
  for(const std::string& s : parts.scripts)
  {
    page += "<script>\n";
    page += s;
    page += "\n</script>\n";
  }
  page += "<script id=\"pvf-data\" type=\"application/json\">\n";
  page += parts.data;
  page += "\n</script>\n<script>\n";
  page += html_viewer_script();
  page += "</script>\n</body>\n</html>\n";
  return page;
}

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_HTML_VIEWER_TEXT_H
