// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_INTEGER_GRID_MAP_H
#define CGAL_POLYVECTOR_FIELDS_IO_INTEGER_GRID_MAP_H

/// \file IO/integer_grid_map.h
/// OBJ with one texture coordinate per corner, and legacy VTK, for uv per halfedge.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/atomic_file.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

template <typename UV>
std::pair<double, double> uv_pair(const UV& p)
{
  if constexpr(Has_xy<UV>::value)
    return { CGAL::to_double(p.x()), CGAL::to_double(p.y()) };
  else
    return { double(p[0]), double(p[1]) };
}

// The vertex point map of the writers' named parameters.
template <typename TriangleMesh, typename NamedParameters>
auto uv_writer_points(const TriangleMesh& tm, const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                            CGAL::get_const_property_map(CGAL::vertex_point, tm));
}

template <typename TriangleMesh, typename UVMap, typename VertexPointMap>
Error_code integer_grid_map_obj_text(const TriangleMesh& tm, UVMap uv_map, VertexPointMap vpm, std::string& text)
{
  using boost::get;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  for(auto f : faces(tm))
    for(auto h : halfedges_around_face(halfedge(f, tm), tm))
    {
      const auto uv = Polyvector_fields::internal::uv_pair(get(uv_map, h));
      if(!std::isfinite(uv.first) || !std::isfinite(uv.second))
        return Error_code::NON_FINITE_VALUE;
    }
  // (numbers as the shortest text that reads back as the same double)
  using Polyvector_fields::IO::internal::append_double;
  using Polyvector_fields::IO::internal::append_integer;
  text = "# integer-grid map: one vt per corner, one uv unit per quad\n";
  Polyvector_fields::internal::Numbering<vertex_descriptor> index;
  for(vertex_descriptor v : vertices(tm))
  {
    index.add(v);
    const auto& p = get(vpm, v);
    text += "v ";
    append_double(text, CGAL::to_double(p.x()));
    text += ' ';
    append_double(text, CGAL::to_double(p.y()));
    text += ' ';
    append_double(text, CGAL::to_double(p.z()));
    text += '\n';
  }
  for(auto f : faces(tm))
    for(auto h : halfedges_around_face(halfedge(f, tm), tm))
    {
      const auto uv = Polyvector_fields::internal::uv_pair(get(uv_map, h));
      text += "vt ";
      append_double(text, uv.first);
      text += ' ';
      append_double(text, uv.second);
      text += '\n';
    }
  std::size_t corner = 0;
  for(auto f : faces(tm))
  {
    text += 'f';
    for(auto h : halfedges_around_face(halfedge(f, tm), tm))
    {
      text += ' ';
      append_integer(text, index(target(h, tm)) + 1);
      text += '/';
      append_integer(text, ++corner);
    }
    text += '\n';
  }
  return Error_code::SUCCESS;
}


template <typename TriangleMesh, typename UVMap, typename VertexPointMap>
Error_code integer_grid_map_vtk_text(const TriangleMesh& tm, UVMap uv_map, VertexPointMap vpm, std::string& text)
{
  using boost::get;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  Polyvector_fields::internal::Numbering<vertex_descriptor> index;
  for(vertex_descriptor v : vertices(tm))
    index.add(v);
  std::vector<std::array<double, 3> > points;
  std::vector<std::pair<double, double> > uvs;
  std::vector<std::size_t> ids;
  std::vector<int> orientation;
  for(auto f : faces(tm))
  {
    std::array<std::pair<double, double>, 3> t;
    int k = 0;
    for(auto h : halfedges_around_face(halfedge(f, tm), tm))
    {
      if(k == 3)
        return Error_code::NON_TRIANGLE_FACE;
      const auto& p = get(vpm, target(h, tm));
      points.push_back({ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) });
      t[k++] = Polyvector_fields::internal::uv_pair(get(uv_map, h));
      if(!std::isfinite(t[k - 1].first) || !std::isfinite(t[k - 1].second))
        return Error_code::NON_FINITE_VALUE;
      uvs.push_back(t[k - 1]);
      ids.push_back(index(target(h, tm)));
    }
    const double det = (t[1].first - t[0].first) * (t[2].second - t[0].second) -
                       (t[1].second - t[0].second) * (t[2].first - t[0].first);
    orientation.push_back(det > 0 ? 1 : (det < 0 ? -1 : 0));
  }
  using Polyvector_fields::IO::internal::append_double;
  using Polyvector_fields::IO::internal::append_integer;
  auto pair_line = [&text](double a, double b, const char* end) {
    append_double(text, a);
    text += ' ';
    append_double(text, b);
    text += end;
  };
  text = "# vtk DataFile Version 3.0\ninteger-grid map\nASCII\nDATASET POLYDATA\n";
  text += "POINTS " + std::to_string(points.size()) + " double\n";
  for(const auto& p : points)
  {
    append_double(text, p[0]);
    text += ' ';
    pair_line(p[1], p[2], "\n");
  }
  const std::size_t F = orientation.size();
  text += "POLYGONS " + std::to_string(F) + ' ' + std::to_string(4 * F) + '\n';
  for(std::size_t f = 0; f < F; ++f)
  {
    text += "3 ";
    append_integer(text, 3 * f);
    text += ' ';
    append_integer(text, 3 * f + 1);
    text += ' ';
    append_integer(text, 3 * f + 2);
    text += '\n';
  }
  text += "POINT_DATA " + std::to_string(points.size()) + '\n';
  text += "TEXTURE_COORDINATES tcoords 2 double\n";
  for(const auto& t : uvs)
    pair_line(t.first, t.second, "\n");
  text += "VECTORS uv double\n";
  for(const auto& t : uvs)
    pair_line(t.first, t.second, " 0\n");
  text += "SCALARS vertex_id int 1\nLOOKUP_TABLE default\n";
  for(std::size_t i : ids)
  {
    append_integer(text, i);
    text += '\n';
  }
  text += "CELL_DATA " + std::to_string(F) + '\n';
  text += "SCALARS uv_orientation int 1\nLOOKUP_TABLE default\n";
  for(int o : orientation)
  {
    append_integer(text, o);
    text += '\n';
  }
  return Error_code::SUCCESS;
}


} // namespace internal

namespace IO {

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes `tm` as an OBJ file with one texture coordinate per corner:
/// `v x y z` per vertex, `vt u v` per halfedge of every face (the value of
/// `uv_map` at `target(h)` inside `face(h)`), and `f a/i b/j c/k` per face.
/// One unit of uv is one quad: a checkerboard texture of period 1 shows the
/// integer grid. Values are written with 17 significant digits (round trip).
/// Vertices are numbered in the order of `vertices(tm)`, texture coordinates in
/// the order of `faces(tm)` and of the halfedges of each face from `halfedge(f)`.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
/// \tparam UVMap a model of `ReadablePropertyMap` from halfedges to a 2D point (with `x()` and `y()`)
///         or to a pair of numbers indexed by `[0]` and `[1]` (`std::array<double, 2>`), as written
///         by `compute_integer_grid_map()`
///
/// \cgalNamedParamsBegin
///   \pvfParamVertexPointMap
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::SUCCESS`; `CANNOT_OPEN_FILE` if `os` is not writable or writing fails;
///          `NON_FINITE_VALUE` if a texture coordinate is NaN or infinite (then nothing is written).
///
/// \sa `compute_integer_grid_map()`, `write_integer_grid_map_VTK()`
template <typename TriangleMesh, typename UVMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_integer_grid_map_OBJ(std::ostream& os, const TriangleMesh& tm, UVMap uv_map,
                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code =
    Polyvector_fields::internal::integer_grid_map_obj_text(tm, uv_map, Polyvector_fields::internal::uv_writer_points(tm, np), text);
  return code == Error_code::SUCCESS ? IO::internal::write_to_stream(os, text) : code;
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes the OBJ file of the stream overload to `filename`, through a
/// temporary file in the same directory renamed once complete: on failure,
/// `filename` is left as it was and no temporary file remains.
template <typename TriangleMesh, typename UVMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_integer_grid_map_OBJ(const std::string& filename, const TriangleMesh& tm, UVMap uv_map,
                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code =
    Polyvector_fields::internal::integer_grid_map_obj_text(tm, uv_map, Polyvector_fields::internal::uv_writer_points(tm, np), text);
  return code == Error_code::SUCCESS ? IO::internal::write_file_atomically(filename, text) : code;
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes the map cut open along its seams as a legacy VTK poly-data file: one
/// point per corner, the uv as `TEXTURE_COORDINATES` and as a 3-component
/// point vector `uv` (for a checkerboard in ParaView's calculator), the
/// vertex index as point data, and per face the sign of `det(grad uv)`
/// (`uv_orientation`: 1, 0 or -1; a valid map has 1 everywhere).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
/// \tparam UVMap as for `write_integer_grid_map_OBJ()`
///
/// \cgalNamedParamsBegin
///   \pvfParamVertexPointMap
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::SUCCESS`; `CANNOT_OPEN_FILE` if `os` is not writable or writing fails;
///          `NON_TRIANGLE_FACE`; `NON_FINITE_VALUE` if a texture coordinate is NaN or infinite (in
///          both last cases nothing is written).
///
/// \sa `write_integer_grid_map_OBJ()`
template <typename TriangleMesh, typename UVMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_integer_grid_map_VTK(std::ostream& os, const TriangleMesh& tm, UVMap uv_map,
                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code =
    Polyvector_fields::internal::integer_grid_map_vtk_text(tm, uv_map, Polyvector_fields::internal::uv_writer_points(tm, np), text);
  return code == Error_code::SUCCESS ? IO::internal::write_to_stream(os, text) : code;
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes the VTK file of the stream overload to `filename`, atomically (see
/// the `filename` overload of `write_integer_grid_map_OBJ()`).
template <typename TriangleMesh, typename UVMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_integer_grid_map_VTK(const std::string& filename, const TriangleMesh& tm, UVMap uv_map,
                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code =
    Polyvector_fields::internal::integer_grid_map_vtk_text(tm, uv_map, Polyvector_fields::internal::uv_writer_points(tm, np), text);
  return code == Error_code::SUCCESS ? IO::internal::write_file_atomically(filename, text) : code;
}

} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTEGER_GRID_MAP_H
