// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_HTML_VIEWER_H
#define CGAL_POLYVECTOR_FIELDS_IO_HTML_VIEWER_H

/// \file IO/html_viewer.h
/// A self-contained web page that shows a field, its singularities, its
/// constrained faces and a quad mesh coloured by planarity.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/atomic_file.h>
#include <CGAL/Polyvector_fields/IO/internal/html_viewer_text.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {
namespace internal {

// The default of the named parameter max_glyph_faces.
constexpr std::size_t default_max_glyph_faces = 20000;

template <typename TriangleMesh, typename RootMap, typename SingularityRange, typename NamedParameters>
Error_code html_viewer_text_checked(const TriangleMesh& tm, RootMap root_map, std::size_t N,
                                    const SingularityRange& singularities, const NamedParameters& np,
                                    std::string& out, std::string& message)
{
  using boost::get;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  namespace inp = Polyvector_fields::internal_np;

  const std::size_t max_glyph_faces =
    choose_parameter(get_parameter(np, inp::max_glyph_faces), default_max_glyph_faces);
  const auto faces = face_list(tm);
  const auto vertices = vertex_list(tm);
  const std::size_t F = faces.size();
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    CGAL::get_const_property_map(CGAL::vertex_point, tm));

  // The constrained faces, as a list or one flag per face.
  const std::vector<bool>* flags =
    choose_parameter(get_parameter(np, inp::is_constrained), static_cast<const std::vector<bool>*>(nullptr));
  const std::vector<face_descriptor>* list = choose_parameter(
    get_parameter(np, inp::constrained_faces), static_cast<const std::vector<face_descriptor>*>(nullptr));
  std::vector<bool> list_flags;
  if(N != 0 && max_glyph_faces == 0)  // a degree of 0 is named first
  {
    message = "max_glyph_faces must be at least 1";
    return Error_code::INVALID_PARAMETER;
  }
  std::vector<std::pair<std::size_t, int> > singular;
  Error_code code = check_field_output(tm, N, F, list, singularities, flags, list_flags, singular, message);
  if(code != Error_code::SUCCESS)
    return code;

  // The points, relative to the centre of their bounding box.
  std::vector<std::array<double, 3> > points;
  std::array<double, 3> low{ { HUGE_VAL, HUGE_VAL, HUGE_VAL } }, high{ { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL } };
  for(const auto v : vertices)
  {
    const auto& p = get(vpm, v);
    points.push_back({ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) });
    for(int c = 0; c < 3; ++c)
    {
      if(!std::isfinite(points.back()[c]))
        return Error_code::NON_FINITE_VALUE;
      low[c] = (std::min)(low[c], points.back()[c]);
      high[c] = (std::max)(high[c], points.back()[c]);
    }
  }
  std::array<double, 3> centre, extent;
  for(int c = 0; c < 3; ++c)
  {
    centre[c] = 0.5 * (low[c] + high[c]);
    extent[c] = high[c] - low[c];
  }
  const double radius = 0.5 * std::sqrt(extent[0] * extent[0] + extent[1] * extent[1] + extent[2] * extent[2]);
  std::vector<float> positions;
  for(const auto& p : points)
    for(int c = 0; c < 3; ++c)
      positions.push_back(float(p[c] - centre[c]));

  // The triangles, and the mean edge length (each interior edge counted twice).
  const auto vertex_index = make_index(vertices);
  std::vector<std::uint32_t> triangles;
  double edge_sum = 0;
  for(const auto f : faces)
  {
    const auto h = halfedge(f, tm);
    if(next(next(next(h, tm), tm), tm) != h)
      return Error_code::NON_TRIANGLE_FACE;
    std::size_t ids[3];
    int k = 0;
    for(const auto v : { source(h, tm), target(h, tm), target(next(h, tm), tm) })
    {
      if(!vertex_index.find(v, ids[k]))
        return Error_code::INVALID_PARAMETER;
      triangles.push_back(std::uint32_t(ids[k++]));
    }
    for(int e = 0; e < 3; ++e)
    {
      const auto& a = points[ids[e]];
      const auto& b = points[ids[(e + 1) % 3]];
      edge_sum += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }
  }
  const double mean_edge = edge_sum / double(3 * F);

  // The field on every stride-th face; glyphs of the mean length 0.4 mean edge.
  std::vector<std::vector<double> > roots;
  code = vtk_root_coordinates(root_map, N, faces, roots);
  if(code != Error_code::SUCCESS)
    return code;
  const std::size_t stride = (F + max_glyph_faces - 1) / max_glyph_faces;
  std::vector<std::uint32_t> glyph_faces;
  for(std::size_t i = 0; i < F; i += stride)
    glyph_faces.push_back(std::uint32_t(i));
  // A sign-symmetric field (the vectors of every drawn face in pairs {u, -u})
  // stores one vector of each pair, drawn through the centroid.
  std::vector<std::vector<std::size_t> > kept(glyph_faces.size());
  bool symmetric = N % 2 == 0;
  for(std::size_t g = 0; g < glyph_faces.size() && symmetric; ++g)
  {
    const std::size_t i = glyph_faces[g];
    std::vector<bool> paired(N, false);
    for(std::size_t k = 0; k < N && symmetric; ++k)
    {
      if(paired[k])
        continue;
      const double* u = &roots[k][3 * i];
      const double size = (std::max)({ std::abs(u[0]), std::abs(u[1]), std::abs(u[2]) });
      symmetric = false;
      for(std::size_t j = k + 1; j < N && !symmetric; ++j)
      {
        const double* w = &roots[j][3 * i];
        if(!paired[j] && std::abs(u[0] + w[0]) <= 1e-6 * size && std::abs(u[1] + w[1]) <= 1e-6 * size &&
           std::abs(u[2] + w[2]) <= 1e-6 * size)
        {
          paired[k] = paired[j] = symmetric = true;
          kept[g].push_back(k);
        }
      }
    }
  }
  // The vectors as 16-bit integers, in units of the largest coordinate / 32767.
  double largest = 0, length_sum = 0;
  std::size_t length_count = 0;
  for(std::size_t g = 0; g < glyph_faces.size(); ++g)
  {
    if(!symmetric)
    {
      kept[g].clear();
      for(std::size_t k = 0; k < N; ++k)
        kept[g].push_back(k);
    }
    for(std::size_t k : kept[g])
    {
      const double* u = &roots[k][3 * glyph_faces[g]];
      largest = (std::max)({ largest, std::abs(u[0]), std::abs(u[1]), std::abs(u[2]) });
      length_sum += std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      ++length_count;
    }
  }
  const double unit = largest > 0 ? largest / 32767 : 0.0;
  std::vector<std::int16_t> glyph_vectors;
  for(std::size_t g = 0; g < glyph_faces.size(); ++g)
    for(std::size_t k : kept[g])
      for(int c = 0; c < 3; ++c)
        glyph_vectors.push_back(unit > 0 ? std::int16_t(std::lround(roots[k][3 * glyph_faces[g] + c] / unit)) : 0);
  const double mean_length = length_count > 0 ? length_sum / double(length_count) : 0.0;
  const double glyph_scale = mean_length > 0 ? 0.4 * mean_edge / mean_length : 0.0;

  // The quad mesh, if any.
  Html_quads quads;
  bool has_quads = false;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, inp::quad_mesh_t>::value)
  {
    const auto* pm = get_parameter(np, inp::quad_mesh);
    code = html_quads(*pm, np, centre, quads);
    if(code == Error_code::EMPTY_MESH)
      message = "the quad mesh has no face";
    if(code != Error_code::SUCCESS)
      return code;
    has_quads = true;
  }
  else
  {
    if(!CGAL::parameters::is_default_parameter<NamedParameters, inp::planarity_colour_range_t>::value)
    {
      const double range = choose_parameter(get_parameter(np, inp::planarity_colour_range), 1.0);
      if(!(range > 0) || !std::isfinite(range))
        return Error_code::INVALID_PARAMETER;
    }
  }

  // The three.js files, last: a bad input is reported before a missing file.
  const std::string directory =
    choose_parameter(get_parameter(np, inp::three_js_directory), std::string(default_three_js_directory()));
  Html_page_parts parts;
  code = read_three_js(directory, parts.scripts, message);
  if(code != Error_code::SUCCESS)
    return code;

  parts.title = choose_parameter(get_parameter(np, inp::page_title), std::string("CGAL Polyvector Fields"));
  parts.summary = std::to_string(F) + " faces, " + std::to_string(singular.size()) + " singularities";
  if(has_quads)
    parts.summary += ", " + std::to_string(quads.stats.faces) + " quads, planarity max " + percent(quads.stats.max) +
                     ", mean " + percent(quads.stats.mean);

  std::string& d = parts.data;
  d += "{\"title\":";
  append_json_string(d, parts.title);
  d += ",\n\"surface\":{\"faces\":";
  append_integer(d, F);
  d += ",\"radius\":";
  append_double(d, radius);
  d += ",\"mean_edge\":";
  append_double(d, mean_edge);
  d += ",\"extent\":[";
  for(int c = 0; c < 3; ++c)
  {
    if(c > 0)
      d += ',';
    append_double(d, extent[c]);
  }
  d += "],\n\"vertices\":";
  append_floats_base64(d, positions);
  d += ",\n\"triangles\":";
  append_words_base64(d, triangles);
  d += "},\n\"field\":{\"N\":";
  append_integer(d, N);
  d += ",\"stride\":";
  append_integer(d, stride);
  d += ",\"symmetric\":";
  d += symmetric ? "true" : "false";
  d += ",\"scale\":";
  append_double(d, glyph_scale * unit);
  d += ",\n\"faces\":";
  append_words_base64(d, glyph_faces);
  d += ",\n\"vectors\":";
  append_shorts_base64(d, glyph_vectors);
  d += '}';
  if(!singular.empty())
  {
    std::vector<std::uint32_t> ids;
    std::vector<std::int32_t> numerators;
    for(const auto& s : singular)
    {
      ids.push_back(std::uint32_t(s.first));
      numerators.push_back(std::int32_t(s.second));
    }
    d += ",\n\"singularities\":{\"vertices\":";
    append_words_base64(d, ids);
    d += ",\"numerators\":";
    append_ints_base64(d, numerators);
    d += '}';
  }
  if(flags != nullptr)
  {
    std::vector<std::uint32_t> constrained;
    for(std::size_t i = 0; i < F; ++i)
      if((*flags)[i])
        constrained.push_back(std::uint32_t(i));
    if(!constrained.empty())
    {
      d += ",\n\"constrained\":";
      append_words_base64(d, constrained);
    }
  }
  if(has_quads)
  {
    d += ",\n\"quads\":{\"quads\":";
    append_integer(d, quads.stats.faces);
    d += ",\"max\":";
    append_double(d, quads.stats.max);
    d += ",\"mean\":";
    append_double(d, quads.stats.mean);
    d += ",\"range\":";
    append_double(d, quads.range);
    d += ",\"colour_stops\":[";
    bool first = true;
    for(const auto& s : planarity_colour_stops())
    {
      d += first ? "[" : ",[";
      first = false;
      append_double(d, s.t);
      for(const int x : { int(s.r), int(s.g), int(s.b) })
      {
        d += ',';
        append_integer(d, x);
      }
      d += ']';
    }
    d += "],\n\"vertices\":";
    append_floats_base64(d, quads.vertices);
    d += ",\n\"sizes\":";
    append_words_base64(d, quads.sizes);
    d += ",\n\"indices\":";
    append_words_base64(d, quads.corners);
    d += ",\n\"planarity\":";
    append_floats_base64(d, quads.planarity);
    d += ",\n\"colours\":";
    append_words_base64(d, quads.colours);
    d += '}';
  }
  d += '}';
  out = html_page(parts);
  return Error_code::SUCCESS;
}

// Builds the page; on failure `message` says why (the code's message unless a more precise one is known),
// and is copied to the named parameter error_message if given.
template <typename TriangleMesh, typename RootMap, typename SingularityRange, typename NamedParameters>
Error_code html_viewer_text(const TriangleMesh& tm, RootMap root_map, std::size_t N,
                            const SingularityRange& singularities, const NamedParameters& np, std::string& out)
{
  std::string message;
  const Error_code code = html_viewer_text_checked(tm, root_map, N, singularities, np, out, message);
  if(code != Error_code::SUCCESS)
  {
    if(message.empty())
      message = get_error_message(code);
    std::string* error_message = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, Polyvector_fields::internal_np::error_message), static_cast<std::string*>(nullptr));
    if(error_message != nullptr)
      *error_message = message;
  }
  return code;
}

} // namespace internal

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes a web page that shows a field of `N` vectors per face on the
/// triangle mesh `tm`, its singularities, its constrained faces and, if one is
/// given, a quad mesh coloured by the planarity of its faces. The page is
/// self-contained and works offline: it fetches nothing, and holds the data
/// and the code that draws it, including three.js (r111) and its
/// `OrbitControls`, copied from the files of Debian's package `libjs-three`
/// when the page is written.
///
/// The page has orbit controls (drag to rotate, right drag to pan, wheel to
/// zoom), a check box per layer, and a title that holds the figures: the
/// number of faces and of singularities, and with a quad mesh the number of
/// quads and their largest and mean planarity. The layers are:
/// - the surface (light grey);
/// - the field: on each face, a line from its centroid along each of its `N`
///   vectors, of the mean length 0.4 times the mean edge length (the lengths
///   of the vectors are kept relative to each other). Above `max_glyph_faces`
///   faces, the field is drawn on every `k`-th face in the order of
///   `faces(tm)`, `k = ceil(num_faces / max_glyph_faces)`. A sign-symmetric
///   field (the vectors of every face in pairs `{u, -u}`) is drawn as `N/2`
///   lines through the centroid;
/// - the singularities: a ball on each singular vertex, red for a positive
///   index and blue for a negative one, larger for a larger index;
/// - the constrained faces (orange), when `constrained_faces` or
///   `is_constrained` is given;
/// - the quad mesh, with its edges, each face coloured by its planarity
///   (the measure of `quad_planarity()`), from blue for a planar quad through
///   light blue, pale yellow and orange to red at the top of the range (by
///   default the largest planarity), with a colour bar as in the paper's
///   planar-quad figures. Faces that are not quads are grey.
///
/// Without a quad mesh the surface, the field, the singularities and the
/// constrained faces are shown; with one, the quad mesh and the
/// singularities (the other layers are a click away). The address of the page
/// can choose: `page.html#layers=quads,field` shows those layers only
/// (`surface`, `field`, `singularities`, `constraints`, `quads`), and
/// `#view=worst` looks straight at the quad of largest planarity.
///
/// The coordinates are stored as 32-bit floats relative to the centre of the
/// bounding box, the vectors as 16-bit integers (one of each pair `{u, -u}`),
/// and the arrays in base64: a page weighs 0.88 MB of three.js plus about 50
/// bytes per face of the mesh (30 when the field is drawn on 1 face in 4) and
/// 55 per quad.
///
/// \tparam TriangleMesh a model of `FaceListGraph` (and `VertexListGraph`)
/// \tparam RootMap a model of `ReadablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and
///         `std::vector<Vector_3>` as value type
/// \tparam SingularityRange a range of
///         `Singularity<boost::graph_traits<TriangleMesh>::%vertex_descriptor>`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param os the output stream
/// \param tm the triangle mesh
/// \param root_map the `N` vectors of each face
/// \param N the number of vectors per face
/// \param singularities the singular vertices
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{quad_mesh}
///     \cgalParamDescription{a polygon mesh (a model of `FaceListGraph` and `VertexListGraph` whose points have
///       `x()`, `y()`, `z()`), shown coloured by planarity; given with
///       `Polyvector_fields::parameters::quad_mesh()`, which keeps a reference}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{planarity_colour_range}
///     \cgalParamDescription{the planarity drawn red (and larger ones)}
///     \cgalParamType{`double`, positive}
///     \cgalParamDefault{the largest planarity of the quads, or 0.01 if they are all planar}
///   \cgalParamNEnd
///   \cgalParamNBegin{constrained_faces}
///     \cgalParamDescription{the constrained faces, drawn in orange; given with
///       `Polyvector_fields::parameters::constrained_faces()`, which keeps a reference}
///     \cgalParamType{`std::vector<face_descriptor>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{is_constrained}
///     \cgalParamDescription{the same as one flag per face, in the order of `faces(tm)` (ignored when
///       `constrained_faces` is given)}
///     \cgalParamType{`std::vector<bool>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{page_title}
///     \cgalParamDescription{the title of the page, followed by its figures}
///     \cgalParamType{`std::string`}
///     \cgalParamDefault{`"CGAL Polyvector Fields"`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_glyph_faces}
///     \cgalParamDescription{above this many faces, the field is drawn on a subsample of about this many}
///     \cgalParamType{`std::size_t`, at least 1}
///     \cgalParamDefault{20000}
///   \cgalParamNEnd
///   \cgalParamNBegin{three_js_directory}
///     \cgalParamDescription{the folder of three.js r111 that holds `three.min.js` and
///       `examples/js/controls/OrbitControls.js`}
///     \cgalParamType{`std::string`}
///     \cgalParamDefault{`"/usr/share/javascript/three"`, where Debian's `libjs-three` installs them}
///   \cgalParamNEnd
///   \cgalParamNBegin{error_message}
///     \cgalParamDescription{receives, on failure, a sentence that says why; for a missing three.js file, its path}
///     \cgalParamType{`std::string&`, given with `Polyvector_fields::parameters::error_message()`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \pvfParamVertexPointMap
/// \cgalNamedParamsEnd
///
/// \returns
/// - `Error_code::INVALID_DEGREE` if `N == 0`;
/// - `Error_code::EMPTY_MESH` if `tm` or the quad mesh has no face;
/// - `Error_code::NON_TRIANGLE_FACE` if a face of `tm` is not a triangle;
/// - `Error_code::INCONSISTENT_DEGREE` if a face holds a number of vectors other than `N`;
/// - `Error_code::NON_FINITE_VALUE` if a point or vector is NaN or infinite;
/// - `Error_code::INVALID_FACE` if `constrained_faces` names a face that is not in `tm`;
/// - `Error_code::INVALID_PARAMETER` if a flag vector has a size other than the number of faces, if a
///   singularity names a vertex that is not in `tm`, has a zero numerator or repeats a vertex, if
///   `max_glyph_faces` is 0, or if `planarity_colour_range` is not a positive finite number;
/// - `Error_code::CANNOT_OPEN_FILE` if a three.js file cannot be read (`error_message` names it), or if
///   `os` is not writable or writing fails;
/// - `Error_code::SUCCESS` otherwise.
///
/// Nothing is written unless the whole input is valid and the three.js files were read.
///
/// \sa `write_VTK()`, `write_quad_mesh_PLY()`
template <typename TriangleMesh, typename RootMap, typename SingularityRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code write_HTML_viewer(std::ostream& os, const TriangleMesh& tm, RootMap root_map, std::size_t N,
                             const SingularityRange& singularities, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code = internal::html_viewer_text(tm, root_map, N, singularities, np, text);
  return code != Error_code::SUCCESS ? code : internal::write_to_stream(os, text);
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes the page of the stream overload to `filename`, through a temporary
/// file in the same directory renamed once complete: on failure, `filename`
/// is left as it was and no temporary file remains.
///
/// \returns the codes of the stream overload; `Error_code::CANNOT_OPEN_FILE` if
///          the file cannot be created, written or renamed.
template <typename TriangleMesh, typename RootMap, typename SingularityRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code write_HTML_viewer(const std::string& filename, const TriangleMesh& tm, RootMap root_map, std::size_t N,
                             const SingularityRange& singularities, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code = internal::html_viewer_text(tm, root_map, N, singularities, np, text);
  return code != Error_code::SUCCESS ? code : internal::write_file_atomically(filename, text);
}

} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_HTML_VIEWER_H
