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
#include <CGAL/Polyvector_fields/IO/internal/soup_repair.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>
#include <CGAL/Polyvector_fields/IO/internal/triangulate_polygons.h>
#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>

#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {

/// \ingroup PkgPolyvectorFieldsIO
///
/// says what `read_triangle_mesh()` changed to make the file a triangle mesh
/// that can carry a field. Every count is 0 for a file that was already one.
struct Mesh_repair_report
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

namespace internal {

template <typename Mesh, typename = void>
struct Has_collect_garbage : std::false_type {};
template <typename Mesh>
struct Has_collect_garbage<Mesh, std::void_t<decltype(std::declval<Mesh&>().collect_garbage())> > : std::true_type {};

// Makes the face list dense again after removals (Surface_mesh keeps removed
// elements until then).
template <typename Mesh>
void collect_garbage_if_any(Mesh& tm)
{
  if constexpr(Has_collect_garbage<Mesh>::value)
    tm.collect_garbage();
}

template <typename Mesh>
std::size_t count_faces(const Mesh& tm)
{
  std::size_t n = 0;
  for(auto f : faces(tm))
  {
    (void)f;
    ++n;
  }
  return n;
}

// The faces that cannot carry a frame, counted; the first in faces(tm) order.
template <typename Mesh>
std::size_t count_degenerate_faces(const Mesh& tm, typename boost::graph_traits<Mesh>::face_descriptor& first)
{
  using boost::get;
  const auto vpm = get(CGAL::vertex_point, tm);
  std::size_t count = 0;
  for(auto f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    Face_frame frame;
    if(Polyvector_fields::internal::triangle_frame(Polyvector_fields::internal::to_array(get(vpm, source(h, tm))),
                                                   Polyvector_fields::internal::to_array(get(vpm, target(h, tm))),
                                                   Polyvector_fields::internal::to_array(get(vpm, target(next(h, tm), tm))),
                                                   frame) != Error_code::SUCCESS && count++ == 0)
      first = f;
  }
  return count;
}

// The checks and repairs of read_triangle_mesh() on a soup already read.
template <typename TriangleMesh>
Error_code soup_to_triangle_mesh(Polygon_soup& soup, TriangleMesh& tm, Mesh_repair_report& report, bool repair,
                                 const Diagnostic& diagnostic)
{
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename Graph_traits::face_descriptor face_descriptor;
  typedef typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type Point;

  Mesh_repair_report r;
  r.file_vertices = soup.points.size();
  r.file_faces = soup.number_of_polygons();
  const std::vector<std::size_t> file_lines = soup.polygon_line;
  auto file_face_name = [&](std::size_t i) {
    return "face " + std::to_string(i) +
           (i < file_lines.size() ? " (line " + std::to_string(file_lines[i]) + ")" : std::string());
  };
  std::vector<std::size_t> source;
  Soup_repair_counts counts;
  Error_code code = check_or_repair_soup(soup, source, repair, counts, diagnostic);
  if(code != Error_code::SUCCESS)
    return code;
  r.merged_points = counts.merged_points;
  r.degenerate_polygons = counts.degenerate_polygons;
  r.duplicate_faces = counts.duplicate_faces;
  r.reoriented_faces = counts.reoriented_faces;
  r.split_vertices = counts.split_vertices;
  r.isolated_vertices = counts.isolated_vertices;

  if(repair)
  {
    code = triangulate_soup_polygons(soup, source, r.triangulated_faces, diagnostic);
    if(code != Error_code::SUCCESS)
      return code;
  }

  // The mesh, face by face in soup order.
  TriangleMesh mesh;
  auto vpm = get(CGAL::vertex_point, mesh);
  std::vector<vertex_descriptor> vertex(soup.points.size());
  for(std::size_t v = 0; v < soup.points.size(); ++v)
  {
    vertex[v] = add_vertex(mesh);
    put(vpm, vertex[v], Point(soup.points[v][0], soup.points[v][1], soup.points[v][2]));
  }
  // The file face of each face; a property of the mesh, so that it follows
  // the faces through triangulation and garbage collection.
  auto source_of = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  std::vector<vertex_descriptor> polygon;
  for(std::size_t i = 0; i < soup.number_of_polygons(); ++i)
  {
    polygon.clear();
    for(std::size_t k = 0; k < soup.size(i); ++k)
      polygon.push_back(vertex[soup.polygon(i)[k]]);
    const face_descriptor f = CGAL::Euler::add_face(polygon, mesh);
    if(f == Graph_traits::null_face())
      return diagnostic.fail(Error_code::NON_MANIFOLD_MESH, soup.face_name(i) + " cannot be added to the surface");
    put(source_of, f, source[i]);
  }

  face_descriptor degenerate;
  const std::size_t degenerate_faces = count_degenerate_faces(mesh, degenerate);
  if(degenerate_faces > 0)
  {
    if(!repair)
      return diagnostic.fail(Error_code::DEGENERATE_FACE,
                             file_face_name(get(source_of, degenerate)) + " is degenerate: its area is (numerically) zero");
    CGAL::Polygon_mesh_processing::remove_degenerate_faces(mesh);
    collect_garbage_if_any(mesh);
    r.degenerate_faces = degenerate_faces;
    if(!CGAL::is_valid_polygon_mesh(mesh) || !CGAL::is_triangle_mesh(mesh))
      return diagnostic.fail(Error_code::NON_MANIFOLD_MESH,
                             "the removal of the degenerate faces did not leave a valid triangle mesh");
    if(count_faces(mesh) == 0)
      return diagnostic.fail(Error_code::EMPTY_MESH, "no face is left once the degenerate ones are removed");
    if(count_degenerate_faces(mesh, degenerate) > 0)
      return diagnostic.fail(Error_code::DEGENERATE_FACE, "a triangle of zero area from " +
                                                            file_face_name(get(source_of, degenerate)) +
                                                            " cannot be removed");
  }

  for(face_descriptor f : faces(mesh))
    r.source_face.push_back(get(source_of, f));
  tm = std::move(mesh);
  report = std::move(r);
  return Error_code::SUCCESS;
}

} // namespace internal

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
/// - faces with more than three vertices (repair: triangulated by ear
///   clipping on the coordinate plane closest to the face, with exact
///   predicates; a face that is not a simple polygon there, or has more than
///   4096 vertices, is refused);
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
Error_code read_triangle_mesh(const std::string& filename, TriangleMesh& tm, Mesh_repair_report& report,
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
