// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_SOUP_TO_MESH_H
#define CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_SOUP_TO_MESH_H

// The checks and repairs of read_triangle_mesh() on a polygon soup already
// read: the soup checked or repaired, triangulated, made into a mesh face by
// face, and its degenerate triangles refused or removed.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/polygon_soup.h>
#include <CGAL/Polyvector_fields/IO/internal/soup_repair.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>
#include <CGAL/Polyvector_fields/IO/internal/triangulate_polygons.h>
#include <CGAL/Polyvector_fields/face_frames.h>

#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {
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

// Why CGAL::Euler::add_face() refused polygon `i` of `soup`: an edge that
// already has a face on the same side, or a vertex whose faces cannot take
// one more fan.
template <typename TriangleMesh, typename Vertex>
std::string why_not_added(const Polygon_soup& soup, std::size_t i, const std::vector<Vertex>& vertex,
                          const TriangleMesh& mesh)
{
  const std::size_t n = soup.size(i);
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::size_t a = soup.polygon(i)[k], b = soup.polygon(i)[(k + 1) % n];
    const auto h = halfedge(vertex[a], vertex[b], mesh);
    if(h.second && face(h.first, mesh) != boost::graph_traits<TriangleMesh>::null_face())
      return "its edge from " + soup.vertex_name(a) + " to " + soup.vertex_name(b) +
             " already has a face on that side, so it would have more than two faces (a surface has at most two;"
             " a volume mesh, or faces inside the solid, has more)";
  }
  return "one of its vertices would join two separate fans of faces (a pinched vertex)";
}

// The mesh of the soup, face by face in soup order; `source_of` (a dynamic
// property of `mesh`, so that it follows the faces through triangulation and
// garbage collection) receives the file face `source[i]` of each face.
template <typename TriangleMesh, typename SourceMap>
Error_code add_soup_faces(const Polygon_soup& soup, const std::vector<std::size_t>& source, TriangleMesh& mesh,
                          SourceMap source_of, const Diagnostic& diagnostic)
{
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename Graph_traits::face_descriptor face_descriptor;
  typedef typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type Point;

  auto vpm = get(CGAL::vertex_point, mesh);
  std::vector<vertex_descriptor> vertex(soup.points.size());
  for(std::size_t v = 0; v < soup.points.size(); ++v)
  {
    vertex[v] = add_vertex(mesh);
    put(vpm, vertex[v], Point(soup.points[v][0], soup.points[v][1], soup.points[v][2]));
  }
  std::vector<vertex_descriptor> polygon;
  for(std::size_t i = 0; i < soup.number_of_polygons(); ++i)
  {
    polygon.clear();
    for(std::size_t k = 0; k < soup.size(i); ++k)
      polygon.push_back(vertex[soup.polygon(i)[k]]);
    const face_descriptor f = CGAL::Euler::add_face(polygon, mesh);
    if(f == Graph_traits::null_face())
      return diagnostic.fail(Error_code::NON_MANIFOLD_MESH,
                             soup.face_name(i) + " cannot be added to the surface: " + why_not_added(soup, i, vertex, mesh));
    put(source_of, f, source[i]);
  }
  return Error_code::SUCCESS;
}

// The triangles of zero area of `mesh`: refused without repair, removed with
// it (their number in `removed`); what cannot be removed is refused.
// `file_face_name` names the file face of a face from its source.
template <typename TriangleMesh, typename SourceMap>
Error_code remove_degenerate_triangles(TriangleMesh& mesh, SourceMap source_of, bool repair,
                                       const std::function<std::string(std::size_t)>& file_face_name,
                                       std::size_t& removed, const Diagnostic& diagnostic)
{
  typename boost::graph_traits<TriangleMesh>::face_descriptor degenerate;
  const std::size_t degenerate_faces = count_degenerate_faces(mesh, degenerate);
  if(degenerate_faces == 0)
    return Error_code::SUCCESS;
  if(!repair)
    return diagnostic.fail(Error_code::DEGENERATE_FACE,
                           file_face_name(get(source_of, degenerate)) + " is degenerate: its area is (numerically) zero");
  CGAL::Polygon_mesh_processing::remove_degenerate_faces(mesh);
  collect_garbage_if_any(mesh);
  removed = degenerate_faces;
  if(!CGAL::is_valid_polygon_mesh(mesh) || !CGAL::is_triangle_mesh(mesh))
    return diagnostic.fail(Error_code::NON_MANIFOLD_MESH,
                           "the removal of the degenerate faces did not leave a valid triangle mesh");
  if(count_faces(mesh) == 0)
    return diagnostic.fail(Error_code::EMPTY_MESH, "no face is left once the degenerate ones are removed");
  if(count_degenerate_faces(mesh, degenerate) > 0)
    return diagnostic.fail(Error_code::DEGENERATE_FACE, "a triangle of zero area from " +
                                                          file_face_name(get(source_of, degenerate)) +
                                                          " cannot be removed");
  return Error_code::SUCCESS;
}

// The checks and repairs of read_triangle_mesh() on a soup already read.
// `Report` is `Mesh_repair_result`; `tm` and `report` are assigned only on success.
template <typename TriangleMesh, typename Report>
Error_code soup_to_triangle_mesh(Polygon_soup& soup, TriangleMesh& tm, Report& report, bool repair,
                                 const Diagnostic& diagnostic)
{
  Report r;
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
    code = triangulate_soup_polygons(soup, source, r.triangulated_faces, r.faces_triangulated_in_3d, diagnostic);
    if(code != Error_code::SUCCESS)
      return code;
  }

  TriangleMesh mesh;
  auto source_of = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  code = add_soup_faces(soup, source, mesh, source_of, diagnostic);
  if(code != Error_code::SUCCESS)
    return code;
  code = remove_degenerate_triangles(mesh, source_of, repair, file_face_name, r.degenerate_faces, diagnostic);
  if(code != Error_code::SUCCESS)
    return code;

  for(auto f : faces(mesh))
    r.source_face.push_back(get(source_of, f));
  tm = std::move(mesh);
  report = std::move(r);
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_SOUP_TO_MESH_H
