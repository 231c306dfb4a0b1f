// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_QUAD_MESH_H
#define CGAL_POLYVECTOR_FIELDS_IO_QUAD_MESH_H

/// \file IO/quad_mesh.h
/// Legacy VTK and coloured PLY for a polygon mesh with the planarity of each face.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/atomic_file.h>
#include <CGAL/Polyvector_fields/IO/internal/planarity_colours.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>
#include <CGAL/Polyvector_fields/parameters.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>

#include <CGAL/IO/Color.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <locale>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The whole VTK file of `write_quad_mesh_VTK()`, or NON_FINITE_VALUE / EMPTY_MESH (then `text` is not written).
template <typename PolygonMesh, typename NamedParameters>
Error_code quad_mesh_vtk_text(const PolygonMesh& pm, const NamedParameters& np, std::string& text)
{
  using boost::get;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                      CGAL::get_const_property_map(CGAL::vertex_point, pm));
  if(faces(pm).empty())
    return Error_code::EMPTY_MESH;
  Polyvector_fields::internal::Numbering<vertex_descriptor> index;
  std::vector<std::array<double, 3> > points;
  for(vertex_descriptor v : vertices(pm))
  {
    index.add(v);
    const auto& p = get(vpm, v);
    points.push_back({ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) });
    for(double x : points.back())
      if(!std::isfinite(x))
        return Error_code::NON_FINITE_VALUE;
  }
  std::size_t total = 0, face_count = 0;
  for(auto f : faces(pm))
  {
    total += 1 + degree(f, pm);
    ++face_count;
  }
  // (numbers as the shortest text that reads back as the same double)
  using Polyvector_fields::IO::internal::append_double;
  using Polyvector_fields::IO::internal::append_integer;
  text = "# vtk DataFile Version 3.0\nquad mesh with planarity\nASCII\nDATASET POLYDATA\n";
  text += "POINTS " + std::to_string(points.size()) + " double\n";
  for(const auto& p : points)
  {
    append_double(text, p[0]);
    text += ' ';
    append_double(text, p[1]);
    text += ' ';
    append_double(text, p[2]);
    text += '\n';
  }
  text += "POLYGONS " + std::to_string(face_count) + ' ' + std::to_string(total) + '\n';
  std::vector<double> planarity;
  std::vector<std::array<double, 3> > p;
  for(auto f : faces(pm))
  {
    append_integer(text, degree(f, pm));
    p.clear();
    for(auto h : halfedges_around_face(halfedge(f, pm), pm))
    {
      const std::size_t i = index(target(h, pm));
      text += ' ';
      append_integer(text, i);
      p.push_back(points[i]);
    }
    text += '\n';
    planarity.push_back(p.size() == 4 ? quad_planarity(p[0], p[1], p[2], p[3]) : -1.0);
  }
  text += "CELL_DATA " + std::to_string(face_count) + "\nSCALARS planarity double 1\nLOOKUP_TABLE default\n";
  for(double q : planarity)
  {
    append_double(text, q);
    text += '\n';
  }
  return Error_code::SUCCESS;
}


// The planarity of each face of `pm` in the order of faces(pm): the measure of
// quad_planarity() for a quad, -1 for another polygon; with their statistics
// over the quads. NON_FINITE_VALUE for a NaN or infinite coordinate.
template <typename PolygonMesh, typename VertexPointMap>
Error_code face_planarities(const PolygonMesh& pm, const VertexPointMap& vpm, std::vector<double>& planarity,
                            Planarity_result& stats)
{
  using boost::get;
  std::vector<double> result;
  Planarity_result s;
  double sum = 0;
  for(auto f : faces(pm))
  {
    std::vector<std::array<double, 3> > p;
    for(auto h : halfedges_around_face(halfedge(f, pm), pm))
    {
      const auto& x = get(vpm, target(h, pm));
      p.push_back({ CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z()) });
      for(double c : p.back())
        if(!std::isfinite(c))
          return Error_code::NON_FINITE_VALUE;
    }
    if(p.size() != 4)
    {
      result.push_back(-1.0);
      continue;
    }
    const double q = quad_planarity(p[0], p[1], p[2], p[3]);
    result.push_back(q);
    s.max = (std::max)(s.max, q);
    sum += q;
    ++s.faces;
  }
  if(s.faces > 0)
    s.mean = sum / double(s.faces);
  planarity = std::move(result);
  stats = s;
  return Error_code::SUCCESS;
}

// The planarity drawn red: the named parameter planarity_colour_range, or the
// largest planarity of the quads (1% when they are all planar).
// INVALID_PARAMETER for a range that is not a positive finite number.
template <typename NamedParameters>
Error_code planarity_colour_range(const NamedParameters& np, const Planarity_result& stats, double& range)
{
  const double given = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, Polyvector_fields::internal_np::planarity_colour_range), -1.0);
  if(CGAL::parameters::is_default_parameter<NamedParameters, Polyvector_fields::internal_np::planarity_colour_range_t>::value)
  {
    range = stats.max > 0 ? stats.max : 0.01;
    return Error_code::SUCCESS;
  }
  if(!(given > 0) || !std::isfinite(given))
    return Error_code::INVALID_PARAMETER;
  range = given;
  return Error_code::SUCCESS;
}

// The whole PLY file of `write_quad_mesh_PLY()`, written by CGAL's PLY writer
// of Surface_mesh from a copy of `pm` that holds only the face properties
// "f:color" and "f:quality".
template <typename PolygonMesh, typename NamedParameters>
Error_code quad_mesh_ply_text(const PolygonMesh& pm, const NamedParameters& np, std::string& text)
{
  typedef CGAL::Simple_cartesian<double>::Point_3 Point;
  typedef CGAL::Surface_mesh<Point> Copy;
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                      CGAL::get_const_property_map(CGAL::vertex_point, pm));
  if(faces(pm).empty())
    return Error_code::EMPTY_MESH;
  std::vector<double> planarity;
  Planarity_result stats;
  Error_code code = face_planarities(pm, vpm, planarity, stats);
  if(code != Error_code::SUCCESS)
    return code;
  double range = 0;
  code = planarity_colour_range(np, stats, range);
  if(code != Error_code::SUCCESS)
    return code;

  Copy copy;
  std::vector<std::pair<face_descriptor, Copy::Face_index> > face_pairs;
  CGAL::copy_face_graph(pm, copy,
                        CGAL::parameters::vertex_point_map(vpm).face_to_face_output_iterator(std::back_inserter(face_pairs)));
  auto colour = copy.add_property_map<Copy::Face_index, CGAL::IO::Color>("f:color").first;
  auto quality = copy.add_property_map<Copy::Face_index, double>("f:quality").first;
  std::size_t i = 0;
  for(const auto& pair : face_pairs)  // in the order of faces(pm)
  {
    const auto c = IO::internal::planarity_colour(planarity[i], range);
    put(colour, pair.second, CGAL::IO::Color(c[0], c[1], c[2]));
    put(quality, pair.second, planarity[i]);
    ++i;
  }
  std::ostringstream out;
  out.imbue(std::locale::classic());
  std::ostringstream comment;
  comment.imbue(std::locale::classic());
  comment << std::setprecision(17) << "face quality: planarity (distance between the diagonals over their mean length; "
          << "-1 on faces that are not quads)\nface colour: blue planar to red at planarity " << range
          << " and above; grey on faces that are not quads";
  if(!CGAL::IO::write_PLY(out, copy, comment.str(), CGAL::parameters::stream_precision(17)))
    return Error_code::CANNOT_OPEN_FILE;
  text = out.str();
  return Error_code::SUCCESS;
}
} // namespace internal

namespace IO {

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// writes the polygon mesh `pm` as a legacy VTK poly-data file with the cell
/// scalar `planarity`: the measure of `quad_planarity()` for each quad, `-1` on
/// the faces that are not quads (trimmed boundary polygons), for a pseudocolour
/// plot in ParaView. Vertices are numbered in the order of `vertices(pm)`, faces
/// written in the order of `faces(pm)`, each from `halfedge(f)`. Values are
/// written with 17 significant digits.
///
/// \tparam PolygonMesh a model of `FaceListGraph` and `VertexListGraph`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<PolygonMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::SUCCESS`; `CANNOT_OPEN_FILE` if `os` is not writable or writing fails;
///          `EMPTY_MESH` if `pm` has no face; `NON_FINITE_VALUE` if a coordinate is NaN or infinite
///          (in both last cases nothing is written).
///
/// \sa `quad_planarity()`, `extract_quad_mesh()`, `planarize_quad_mesh()`
template <typename PolygonMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_quad_mesh_VTK(std::ostream& os, const PolygonMesh& pm,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code = Polyvector_fields::internal::quad_mesh_vtk_text(pm, np, text);
  return code == Error_code::SUCCESS ? IO::internal::write_to_stream(os, text) : code;
}

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// writes the VTK file of the stream overload to `filename`, through a
/// temporary file in the same directory renamed once complete: on failure,
/// `filename` is left as it was and no temporary file remains.
template <typename PolygonMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_quad_mesh_VTK(const std::string& filename, const PolygonMesh& pm,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code = Polyvector_fields::internal::quad_mesh_vtk_text(pm, np, text);
  return code == Error_code::SUCCESS ? IO::internal::write_file_atomically(filename, text) : code;
}

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// writes the polygon mesh `pm` as an ASCII PLY file with, on each face, the
/// properties `quality` (`double`): the measure of `quad_planarity()`, `-1` on
/// the faces that are not quads; and `red`, `green`, `blue`, `alpha`
/// (`uchar`): the colour of that planarity on the map of the HTML viewer,
/// blue for a planar quad to red at the top of the range, grey on the faces
/// that are not quads. MeshLab shows both (Render, Color, Per Face; and the
/// filters on face quality). The file is written by CGAL's PLY writer of
/// `CGAL::Surface_mesh`, from a copy of `pm` (coordinates as `double`, 17
/// significant digits): the faces are in the order of `faces(pm)`, the
/// vertices in the order of the copy (`CGAL::copy_face_graph()`).
///
/// \tparam PolygonMesh a model of `FaceListGraph` and `VertexListGraph`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<PolygonMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{planarity_colour_range}
///     \cgalParamDescription{the planarity drawn red (larger ones too), given with
///       `Polyvector_fields::parameters::planarity_colour_range()`}
///     \cgalParamType{`double`, positive}
///     \cgalParamDefault{the largest planarity of the quads of `pm`, or 0.01 if they are all planar}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::SUCCESS`; `CANNOT_OPEN_FILE` if `os` is not writable or writing fails;
///          `EMPTY_MESH` if `pm` has no face; `NON_FINITE_VALUE` if a coordinate is NaN or infinite;
///          `INVALID_PARAMETER` if `planarity_colour_range` is not a positive finite number (in
///          these last three cases nothing is written).
///
/// \sa `write_quad_mesh_VTK()`, `write_HTML_viewer()`, `quad_planarity()`
template <typename PolygonMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_quad_mesh_PLY(std::ostream& os, const PolygonMesh& pm,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code = Polyvector_fields::internal::quad_mesh_ply_text(pm, np, text);
  return code == Error_code::SUCCESS ? IO::internal::write_to_stream(os, text) : code;
}

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// writes the PLY file of the stream overload to `filename`, through a
/// temporary file in the same directory renamed once complete: on failure,
/// `filename` is left as it was and no temporary file remains.
template <typename PolygonMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_quad_mesh_PLY(const std::string& filename, const PolygonMesh& pm,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code = Polyvector_fields::internal::quad_mesh_ply_text(pm, np, text);
  return code == Error_code::SUCCESS ? IO::internal::write_file_atomically(filename, text) : code;
}

} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_QUAD_MESH_H
