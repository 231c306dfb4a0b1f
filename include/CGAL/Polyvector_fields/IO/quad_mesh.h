// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_QUAD_MESH_H
#define CGAL_POLYVECTOR_FIELDS_IO_QUAD_MESH_H

/// \file IO/quad_mesh.h
/// Legacy VTK for a polygon mesh with the planarity of each face.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/atomic_file.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <locale>
#include <ostream>
#include <sstream>
#include <string>
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
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << std::setprecision(17);
  out << "# vtk DataFile Version 3.0\nquad mesh with planarity\nASCII\nDATASET POLYDATA\n";
  out << "POINTS " << points.size() << " double\n";
  for(const auto& p : points)
    out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  out << "POLYGONS " << face_count << ' ' << total << '\n';
  std::vector<double> planarity;
  for(auto f : faces(pm))
  {
    out << degree(f, pm);
    std::vector<std::array<double, 3> > p;
    for(auto h : halfedges_around_face(halfedge(f, pm), pm))
    {
      const std::size_t i = index(target(h, pm));
      out << ' ' << i;
      p.push_back(points[i]);
    }
    out << '\n';
    planarity.push_back(p.size() == 4 ? quad_planarity(p[0], p[1], p[2], p[3]) : -1.0);
  }
  out << "CELL_DATA " << face_count << "\nSCALARS planarity double 1\nLOOKUP_TABLE default\n";
  for(double q : planarity)
    out << q << '\n';
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

} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_QUAD_MESH_H
