// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_READ_TRIANGLE_MESH_H
#define CGAL_POLYVECTOR_FIELDS_IO_READ_TRIANGLE_MESH_H

/// \file IO/read_triangle_mesh.h
/// Reading a mesh file into a triangle mesh that can carry a field, with a
/// reason for every refusal and a report of every repair.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/polygon_soup.h>
#include <CGAL/Polyvector_fields/IO/internal/soup_to_mesh.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {

/// \ingroup PkgPolyvectorFieldsIO
///
/// says what `read_triangle_mesh()` changed to make the file a triangle mesh
/// that can carry a field. Every count is 0 for a file that was already one.
struct Mesh_repair_result
{
  std::size_t file_vertices = 0;        ///< vertices in the file
  std::size_t file_faces = 0;           ///< faces (polygons) in the file
  std::size_t merged_points = 0;        ///< vertices merged into an earlier vertex at the same position
  std::size_t degenerate_polygons = 0;  ///< polygons that repeated a vertex: the repetition removed, or the polygon dropped
  std::size_t duplicate_faces = 0;      ///< faces dropped because an earlier face has the same vertices
  std::size_t reoriented_faces = 0;     ///< faces whose orientation was reversed to agree with their neighbours
  std::size_t split_vertices = 0;       ///< vertices duplicated to make the surface manifold (non-manifold edges, pinched vertices)
  std::size_t isolated_vertices = 0;    ///< vertices of no face: removed with repair, kept (and counted) without
  std::size_t triangulated_faces = 0;   ///< faces with more than three vertices, split into triangles
  std::size_t faces_triangulated_in_3d = 0;  ///< of the triangulated faces, the non-planar quads and the non-planar larger faces that are not simple on their coordinate plane
  std::size_t degenerate_faces = 0;     ///< triangles of zero area, removed by edge collapses and flips
  /// for each face of the result, in the order of `faces(tm)`, the 0-based
  /// position in the file of the face it comes from (a triangulated face gives
  /// several triangles with the same source)
  std::vector<std::size_t> source_face;

  /// returns whether the mesh differs from the file (isolated vertices kept without repair do not count).
  bool changed(bool repaired = true) const
  {
    return merged_points || degenerate_polygons || duplicate_faces || reoriented_faces || split_vertices ||
           (repaired && isolated_vertices) || triangulated_faces || degenerate_faces;
  }
};

/// \ingroup PkgPolyvectorFieldsIO
///
/// reads the mesh file `filename` into `tm`, a triangle mesh on which a field can be designed.
///
/// The formats are ASCII OFF and OBJ, read by this package (the first bad token
/// stops the reader; its line is in the message), and PLY and STL, read by
/// CGAL's readers; the format is told by the extension, in any case.
///
/// The file is first read as a polygon soup, then checked, in this order, and
/// each problem either refused, with a message that names it, or repaired,
/// and counted in `report`:
/// - duplicate points (repair: merged, which joins a soup of separate
///   triangles, as an STL file holds, into one surface; never refused);
/// - faces that repeat a vertex (repair: the repetition removed, or the face dropped);
/// - faces with more than three vertices (repair: triangulated; a quad by its
///   diagonal whose two triangles make the smaller dihedral angle, then the
///   larger smallest angle; a larger face by ear clipping on the coordinate
///   plane closest to it, with exact predicates, or, if it is not a simple
///   polygon there and not planar, in 3D by
///   `CGAL::Polygon_mesh_processing::triangulate_hole_polyline()` (a fan
///   beyond 200 vertices); refused: a planar face that is not a simple polygon
///   (it folds onto itself: no triangulation is a surface), and a face of more
///   than 4096 vertices);
/// - duplicate faces, with the vertices of an earlier face in any order (repair: dropped);
/// - edges shared by more than two faces, faces oriented inconsistently with a
///   neighbour, and pinched vertices (repair: `CGAL::Polygon_mesh_processing::orient_polygon_soup()`,
///   which reverses faces and duplicates vertices);
/// - vertices of no face (repair: removed; without repair they are kept, as
///   they change no field, and counted);
/// - triangles of zero area, judged as `face_frame()` judges them (repair:
///   `CGAL::Polygon_mesh_processing::remove_degenerate_faces()`; what it cannot
///   remove is refused).
/// Non-finite coordinates, out-of-range vertex indices, faces with fewer than
/// three vertices and malformed tokens are always refused.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph`, default constructible and move assignable,
///         whose internal vertex point map holds points constructible from three `double`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param filename the file
/// \param tm receives the mesh; it is assigned only on success
/// \param report receives what was changed, and the source face of each face of `tm`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{repair}
///     \cgalParamDescription{whether the problems listed above are repaired (`true`) or refused (`false`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \pvfParamMaximumFileSize
///   \pvfParamErrorMessage{its place (face, vertex or line)}
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::SUCCESS`, or the reason of the refusal: `CANNOT_OPEN_FILE`, `FILE_TOO_LARGE`,
///          `UNSUPPORTED_FORMAT` (another extension, binary OFF), `MALFORMED_FILE` (a bad token or index, a NUL
///          byte in a text format), `NON_FINITE_VALUE`, `EMPTY_MESH`, `DEGENERATE_FACE` (fewer than three vertices,
///          a repeated vertex, zero area), `NON_TRIANGLE_FACE`, `DUPLICATE_FACE` or `NON_MANIFOLD_MESH`.
///          On failure `tm` and `report` are left as they were.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code read_triangle_mesh(const std::string& filename, TriangleMesh& tm, Mesh_repair_result& report,
                              const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const bool repair = choose_parameter(get_parameter(np, Polyvector_fields::internal_np::repair), true);
  const internal::Diagnostic diagnostic = internal::diagnostic(np);

  internal::Polygon_soup soup;
  const Error_code code = internal::read_polygon_soup_file(filename, internal::maximum_file_size(np), soup, diagnostic);
  if(code != Error_code::SUCCESS)
    return code;
  return internal::soup_to_triangle_mesh(soup, tm, report, repair, diagnostic);
}


} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_READ_TRIANGLE_MESH_H
