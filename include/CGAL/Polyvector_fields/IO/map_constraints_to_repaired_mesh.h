// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_MAP_CONSTRAINTS_TO_REPAIRED_MESH_H
#define CGAL_POLYVECTOR_FIELDS_IO_MAP_CONSTRAINTS_TO_REPAIRED_MESH_H

/// \file map_constraints_to_repaired_mesh.h
/// Constraints on the faces of a mesh file, carried to the mesh that `IO::read_triangle_mesh()` made of it.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Face_constraint.h>
#include <CGAL/Polyvector_fields/IO/read_triangle_mesh.h>

#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {

/// \ingroup PkgPolyvectorFieldsIO
///
/// carries constraints given on the faces of a mesh file (0-based positions
/// in the file, as `read_constraints_by_id()` and
/// `read_dmat_constraints_by_id()` read them) to the faces of the triangle
/// mesh that `read_triangle_mesh()` made of that file.
///
/// A face of the file that the repair triangulated passes its constraint
/// (vectors and weight) to each of its triangles; a face it kept unchanged
/// passes it to itself. The constraints are stored in `out` in the order of
/// `file_constraints`, and the triangles of one file face in the order of
/// `faces(tm)`. A face of the file that the repair removed (a duplicate, or a
/// degenerate polygon) cannot carry a constraint.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceDescriptor `boost::graph_traits<TriangleMesh>::%face_descriptor` (deduced)
/// \tparam Vector_3 the vector type of the constraints
///
/// \param tm the mesh, as `read_triangle_mesh()` returned it
/// \param report the report of that call (its `source_face` is what is used)
/// \param file_constraints the constraints, with the position of a face in the file as face
/// \param out receives the constraints on the faces of `tm` (its former content is replaced); unchanged on failure
/// \param failed_constraint if not null, receives on failure the position in `file_constraints` of the
///        first constraint that could not be carried
///
/// \returns
/// - `Error_code::INVALID_PARAMETER` if `report.source_face` does not have one entry per face of `tm`
///   (the report is not that of `tm`);
/// - `Error_code::INVALID_FACE` if a constraint names a face that is not in the file
///   (not below `report.file_faces`) or that the repair removed;
/// - `Error_code::SUCCESS` otherwise.
///
/// \sa `read_triangle_mesh()`, `Mesh_repair_result`
template <typename TriangleMesh, typename FaceDescriptor, typename Vector_3>
Error_code map_constraints_to_repaired_mesh(const TriangleMesh& tm,
                                            const Mesh_repair_result& report,
                                            const std::vector<Face_constraint<std::size_t, Vector_3> >& file_constraints,
                                            std::vector<Face_constraint<FaceDescriptor, Vector_3> >& out,
                                            std::size_t* failed_constraint = nullptr)
{
  static_assert(std::is_same<FaceDescriptor, typename boost::graph_traits<TriangleMesh>::face_descriptor>::value,
                "the constraints must be on the faces of the mesh");
  if(report.source_face.size() != static_cast<std::size_t>(num_faces(tm)))
    return Error_code::INVALID_PARAMETER;
  // The faces of tm that come from each face of the file.
  std::vector<std::vector<FaceDescriptor> > faces_of_file_face(report.file_faces);
  std::size_t i = 0;
  for(FaceDescriptor f : faces(tm))
  {
    const std::size_t source = report.source_face[i++];
    if(source >= faces_of_file_face.size())
      return Error_code::INVALID_PARAMETER;
    faces_of_file_face[source].push_back(f);
  }
  std::vector<Face_constraint<FaceDescriptor, Vector_3> > result;
  for(std::size_t k = 0; k < file_constraints.size(); ++k)
  {
    const Face_constraint<std::size_t, Vector_3>& c = file_constraints[k];
    if(c.face >= faces_of_file_face.size() || faces_of_file_face[c.face].empty())
    {
      if(failed_constraint != nullptr)
        *failed_constraint = k;
      return Error_code::INVALID_FACE;
    }
    for(FaceDescriptor f : faces_of_file_face[c.face])
    {
      Face_constraint<FaceDescriptor, Vector_3> carried;
      carried.face = f;
      carried.vectors = c.vectors;
      carried.weight = c.weight;
      result.push_back(carried);
    }
  }
  out.swap(result);
  return Error_code::SUCCESS;
}

} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_MAP_CONSTRAINTS_TO_REPAIRED_MESH_H
