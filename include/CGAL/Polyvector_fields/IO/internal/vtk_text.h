// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_VTK_TEXT_H
#define CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_VTK_TEXT_H

// The text of the legacy VTK file of write_VTK(), section by section, and the
// checks of its input.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/mesh_indices.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>
#include <CGAL/Polyvector_fields/IO/singularities.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {
namespace internal {

// Named per-face scalar arrays (the type of `Face_scalar_arrays`).
typedef std::vector<std::pair<std::string, std::vector<double> > > Vtk_face_scalar_arrays;

// Longest array name written; VTK's legacy reader keeps names in 256-byte buffers.
constexpr std::size_t vtk_max_name_length = 200;

// A VTK-safe name: letters, digits, '_', '-' and '.', at most
// vtk_max_name_length characters. Blanks would cut the name, and the legacy
// reader decodes '%' escapes.
inline bool is_vtk_safe_name(const std::string& name)
{
  if(name.empty() || name.size() > vtk_max_name_length)
    return false;
  for(char c : name)
  {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || is_digit(c) ||
                    c == '_' || c == '-' || c == '.';
    if(!ok)
      return false;
  }
  return true;
}

inline std::string vtk_root_name(std::size_t k)
{
  std::string name = "root_";
  append_integer(name, k);
  return name;
}

inline void append_scalar_header(std::string& text, const std::string& name, const char* type)
{
  text += "SCALARS ";
  text += name;
  text += ' ';
  text += type;
  text += " 1\nLOOKUP_TABLE default\n";
}

// Turns a list of constrained faces into one flag per face.
template <typename TriangleMesh>
Error_code constrained_flags(const TriangleMesh& tm,
                             const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& list,
                             std::vector<bool>& flags)
{
  const auto faces = face_list(tm);
  const auto face_index = make_index(faces);
  std::vector<bool> result(faces.size(), false);
  for(const auto f : list)
  {
    std::size_t id = 0;
    if(!face_index.find(f, id))
      return Error_code::INVALID_FACE;
    result[id] = true;
  }
  flags = std::move(result);
  return Error_code::SUCCESS;
}

// The names of the arrays: VTK-safe and pairwise distinct, reserved names
// included; each scalar array has one finite value per face.
inline Error_code check_vtk_arrays(std::size_t N, std::size_t F, bool has_constrained_flags,
                                   const Vtk_face_scalar_arrays& face_scalars)
{
  std::set<std::string> names;
  for(std::size_t k = 0; k < N; ++k)
    names.insert(vtk_root_name(k));
  names.insert("singularity_index");
  if(has_constrained_flags)
    names.insert("is_constrained");
  for(const auto& array : face_scalars)
  {
    if(!is_vtk_safe_name(array.first) || !names.insert(array.first).second || array.second.size() != F)
      return Error_code::INVALID_PARAMETER;
    for(double x : array.second)
      if(!std::isfinite(x))
        return Error_code::NON_FINITE_VALUE;
  }
  return Error_code::SUCCESS;
}

// POINTS: the vertices, in the order of `vertices`.
template <typename VertexList, typename VertexPointMap>
Error_code append_vtk_points(const VertexList& vertices, const VertexPointMap& vpm, std::string& text)
{
  using boost::get;
  text += "POINTS ";
  append_integer(text, vertices.size());
  text += " double\n";
  for(const auto v : vertices)
  {
    const auto& p = get(vpm, v);
    const double xyz[3] = { CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) };
    for(int c = 0; c < 3; ++c)
    {
      if(!std::isfinite(xyz[c]))
        return Error_code::NON_FINITE_VALUE;
      if(c > 0)
        text += ' ';
      append_double(text, xyz[c]);
    }
    text += '\n';
  }
  return Error_code::SUCCESS;
}

// CELLS and CELL_TYPES: the triangles, then one VTK_VERTEX per singularity.
template <typename TriangleMesh, typename FaceList, typename VertexList>
Error_code append_vtk_cells(const TriangleMesh& tm, const FaceList& faces, const VertexList& vertices,
                            const std::vector<std::pair<std::size_t, int> >& singular, std::string& text)
{
  const std::size_t F = faces.size(), S = singular.size();
  const auto vertex_index = make_index(vertices);
  text += "CELLS ";
  append_integer(text, F + S);
  text += ' ';
  append_integer(text, 4 * F + 2 * S);
  text += '\n';
  for(const auto f : faces)
  {
    // Unqualified calls: the graph functions are found by ADL whatever the
    // order in which the mesh header and this one were included.
    const auto h = halfedge(f, tm);
    if(next(next(next(h, tm), tm), tm) != h)
      return Error_code::NON_TRIANGLE_FACE;
    text += '3';
    for(const auto v : { source(h, tm), target(h, tm), target(next(h, tm), tm) })
    {
      std::size_t id = 0;
      if(!vertex_index.find(v, id))
        return Error_code::INVALID_PARAMETER;  // a face refers to a vertex outside vertices(tm)
      text += ' ';
      append_integer(text, id);
    }
    text += '\n';
  }
  for(const auto& s : singular)
  {
    text += "1 ";
    append_integer(text, s.first);
    text += '\n';
  }
  text += "CELL_TYPES ";
  append_integer(text, F + S);
  text += '\n';
  for(std::size_t i = 0; i < F; ++i)
    text += "5\n";
  for(std::size_t i = 0; i < S; ++i)
    text += "1\n";
  return Error_code::SUCCESS;
}

// The N vectors of each face, as N arrays of 3F coordinates.
template <typename RootMap, typename FaceList>
Error_code vtk_root_coordinates(RootMap root_map, std::size_t N, const FaceList& faces,
                                std::vector<std::vector<double> >& roots)
{
  using boost::get;
  const std::size_t F = faces.size();
  roots.assign(N, std::vector<double>(3 * F));
  for(std::size_t i = 0; i < F; ++i)
  {
    const auto& face_roots = get(root_map, faces[i]);
    if(std::size_t(face_roots.size()) != N)
      return Error_code::INCONSISTENT_DEGREE;
    std::size_t k = 0;
    for(const auto& u : face_roots)
    {
      const double xyz[3] = { CGAL::to_double(u.x()), CGAL::to_double(u.y()), CGAL::to_double(u.z()) };
      for(int c = 0; c < 3; ++c)
      {
        if(!std::isfinite(xyz[c]))
          return Error_code::NON_FINITE_VALUE;
        roots[k][3 * i + c] = xyz[c];
      }
      ++k;
    }
  }
  return Error_code::SUCCESS;
}

// The cell data after the header CELL_DATA: the vectors, the singularity
// index, the constrained flags if any, and the scalar arrays, each with a
// value per triangle then one per singularity cell.
inline void append_vtk_cell_data(const std::vector<std::vector<double> >& roots, std::size_t N, std::size_t F,
                                 const std::vector<std::pair<std::size_t, int> >& singular,
                                 const std::vector<bool>* is_constrained, const Vtk_face_scalar_arrays& face_scalars,
                                 std::string& text)
{
  const std::size_t S = singular.size();
  for(std::size_t k = 0; k < N; ++k)
  {
    text += "VECTORS ";
    text += vtk_root_name(k);
    text += " double\n";
    for(std::size_t i = 0; i < F; ++i)
    {
      append_double(text, roots[k][3 * i]);
      text += ' ';
      append_double(text, roots[k][3 * i + 1]);
      text += ' ';
      append_double(text, roots[k][3 * i + 2]);
      text += '\n';
    }
    for(std::size_t i = 0; i < S; ++i)
      text += "0 0 0\n";
  }

  append_scalar_header(text, "singularity_index", "double");
  for(std::size_t i = 0; i < F; ++i)
    text += "0\n";
  for(const auto& s : singular)
  {
    append_double(text, double(s.second) / double(N));
    text += '\n';
  }

  if(is_constrained != nullptr)
  {
    append_scalar_header(text, "is_constrained", "int");
    for(std::size_t i = 0; i < F; ++i)
      text += (*is_constrained)[i] ? "1\n" : "0\n";
    for(std::size_t i = 0; i < S; ++i)
      text += "0\n";
  }

  for(const auto& array : face_scalars)
  {
    append_scalar_header(text, array.first, "double");
    for(double x : array.second)
    {
      append_double(text, x);
      text += '\n';
    }
    for(std::size_t i = 0; i < S; ++i)
      text += "0\n";
  }
}

// The checks that a field's VTK file and its HTML page share: a degree N of at
// least 1, a mesh with F > 0 faces, and the constrained faces as one flag per
// face. Those given as a list (`list`, which wins over `flags`) are turned into
// flags in `list_flags`; on success `flags` points to the flags to use (null
// when none was given), and `singular` holds the singularities as (vertex
// index, index numerator). A flag vector of the wrong size is
// INVALID_PARAMETER, said in `message`.
template <typename TriangleMesh, typename SingularityRange>
Error_code check_field_output(const TriangleMesh& tm, std::size_t N, std::size_t F,
                              const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>* list,
                              const SingularityRange& singularities, const std::vector<bool>*& flags,
                              std::vector<bool>& list_flags, std::vector<std::pair<std::size_t, int> >& singular,
                              std::string& message)
{
  if(N == 0)
    return Error_code::INVALID_DEGREE;
  if(F == 0)
    return Error_code::EMPTY_MESH;
  if(list != nullptr)
  {
    const Error_code code = constrained_flags(tm, *list, list_flags);
    if(code != Error_code::SUCCESS)
      return code;
    flags = &list_flags;
  }
  if(flags != nullptr && flags->size() != F)
  {
    message = "the constrained-face flags have " + std::to_string(flags->size()) + " entries for " +
              std::to_string(F) + " faces";
    return Error_code::INVALID_PARAMETER;
  }
  return singularity_ids(tm, singularities, singular);
}

// Builds the whole file. The constrained faces are given as a list (`list`,
// which wins) or as one flag per face (`flags`); both are null when no
// constraint is given.
template <typename TriangleMesh, typename RootMap, typename SingularityRange, typename VertexPointMap>
Error_code vtk_text(const TriangleMesh& tm, RootMap root_map, std::size_t N, const SingularityRange& singularities,
                    const Vtk_face_scalar_arrays& face_scalars, const std::vector<bool>* flags,
                    const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>* list,
                    const VertexPointMap& vpm, std::string& out)
{
  const auto faces = face_list(tm);
  const auto vertices = vertex_list(tm);
  const std::size_t F = faces.size();
  std::vector<bool> list_flags;
  std::vector<std::pair<std::size_t, int> > singular;
  std::string message;  // the VTK writer reports the code alone
  Error_code code = check_field_output(tm, N, F, list, singularities, flags, list_flags, singular, message);
  if(code != Error_code::SUCCESS)
    return code;
  const std::vector<bool>* is_constrained = flags;
  code = check_vtk_arrays(N, F, is_constrained != nullptr, face_scalars);
  if(code != Error_code::SUCCESS)
    return code;
  const std::size_t S = singular.size();

  std::string text = "# vtk DataFile Version 3.0\nCGAL Polyvector Fields: ";
  append_integer(text, N);
  text += "-PolyVector field\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  code = append_vtk_points(vertices, vpm, text);
  if(code != Error_code::SUCCESS)
    return code;
  code = append_vtk_cells(tm, faces, vertices, singular, text);
  if(code != Error_code::SUCCESS)
    return code;

  text += "CELL_DATA ";
  append_integer(text, F + S);
  text += '\n';
  std::vector<std::vector<double> > roots;
  code = vtk_root_coordinates(root_map, N, faces, roots);
  if(code != Error_code::SUCCESS)
    return code;
  append_vtk_cell_data(roots, N, F, singular, is_constrained, face_scalars, text);

  out = std::move(text);
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_VTK_TEXT_H
