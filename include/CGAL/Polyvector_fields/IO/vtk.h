// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_VTK_H
#define CGAL_POLYVECTOR_FIELDS_IO_VTK_H

/// \file IO/vtk.h
/// Writing a field, its singularities and per-face diagnostics to a legacy VTK
/// file for ParaView.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/atomic_file.h>
#include <CGAL/Polyvector_fields/IO/internal/vtk_text.h>
#include <CGAL/Polyvector_fields/IO/singularities.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {

/// \ingroup PkgPolyvectorFieldsIO
///
/// is a list of named per-face scalar arrays for `write_VTK()`: each entry is
/// a name and one value per face, in the order of `faces(tm)`.
typedef std::vector<std::pair<std::string, std::vector<double> > > Face_scalar_arrays;

namespace internal {

// Reads the named parameters of write_VTK() and builds the whole file.
template <typename TriangleMesh, typename RootMap, typename SingularityRange, typename NamedParameters>
Error_code vtk_to_string(const TriangleMesh& tm, RootMap root_map, std::size_t N,
                         const SingularityRange& singularities, const NamedParameters& np, std::string& out)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;

  static const Face_scalar_arrays no_arrays;
  const Face_scalar_arrays& face_scalars = *choose_parameter(
    get_parameter(np, Polyvector_fields::internal_np::face_scalars), &no_arrays);
  // The constrained faces, as a list or as one flag per face.
  const std::vector<bool>* flags =
    choose_parameter(get_parameter(np, Polyvector_fields::internal_np::is_constrained), static_cast<const std::vector<bool>*>(nullptr));
  const std::vector<face_descriptor>* list = choose_parameter(
    get_parameter(np, Polyvector_fields::internal_np::constrained_faces), static_cast<const std::vector<face_descriptor>*>(nullptr));
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    CGAL::get_const_property_map(CGAL::vertex_point, tm));
  return vtk_text(tm, root_map, N, singularities, face_scalars, flags, list, vpm, out);
}

} // namespace internal

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes a field of `N` vectors per face, its singularities and optional
/// per-face data to `os` as a legacy VTK file (ASCII, version 3.0,
/// `UNSTRUCTURED_GRID`) that ParaView and VisIt open.
///
/// The file holds:
/// - `POINTS`: the vertices of `tm`, in the order of `vertices(tm)`;
/// - `CELLS`: the triangles of `tm` (VTK type 5), in the order of `faces(tm)`,
///   their vertices in the order `source(h)`, `target(h)`, `target(next(h))`
///   with `h = halfedge(f, tm)`; then one `VTK_VERTEX` cell (type 1) per
///   singularity, on its vertex, in the order of `singularities`;
/// - `CELL_DATA`, one value per cell:
///   - `VECTORS root_k double`, `k = 0 .. N-1`: the `k`-th vector of each
///     face, in world coordinates (zero on the singularity cells);
///   - `SCALARS singularity_index double`: `k/N` on each singularity cell, `0`
///     on the triangles;
///   - `SCALARS is_constrained int` (only if `constrained_faces` or
///     `is_constrained` is given): `1` on constrained faces, `0` elsewhere and
///     on singularity cells;
///   - one `SCALARS <name> double` per entry of `face_scalars`: its values on
///     the triangles, `0` on singularity cells.
///
/// In ParaView, color by `singularity_index` and show the singular vertices
/// with a Threshold on the cell type or the index; draw each `root_k` with
/// Cell Centers followed by Glyph. Coordinates are converted to `double` and
/// written so that they read back exactly. Nothing is written to `os` unless
/// the whole input is valid.
///
/// \tparam TriangleMesh a model of `FaceListGraph` (and `VertexListGraph`)
/// \tparam RootMap a model of `ReadablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and
///         `std::vector<Vector_3>` as value type, where `Vector_3` has `x()`, `y()`
///         and `z()` convertible by `CGAL::to_double()`
/// \tparam SingularityRange a range of
///         `Singularity<boost::graph_traits<TriangleMesh>::%vertex_descriptor>`
///         (an empty `std::vector` if there is none)
/// \tparam NamedParameters a sequence of named parameters
///
/// \param os the output stream
/// \param tm the triangle mesh
/// \param root_map the `N` vectors of each face
/// \param N the number of vectors per face
/// \param singularities the singular vertices, whose index is `index_numerator / N`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{face_scalars}
///     \cgalParamDescription{named per-face arrays of `num_faces` values each, in the order of `faces(tm)`,
///       for example `{ {"conjugacy_deviation", deviation}, {"min_angle_degrees", angles} }`. Names use
///       only letters, digits, `_`, `-` and `.` (at most 200 characters) and must differ from each other
///       and from the arrays above. Given with `Polyvector_fields::parameters::face_scalars()`, which keeps a
///       reference: the arrays must outlive the call}
///     \cgalParamType{`Face_scalar_arrays`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{constrained_faces}
///     \cgalParamDescription{the constrained faces (duplicates are allowed), for the `is_constrained` array;
///       given with `Polyvector_fields::parameters::constrained_faces()`, which keeps a reference}
///     \cgalParamType{`std::vector<face_descriptor>`}
///     \cgalParamDefault{none: no `is_constrained` array}
///   \cgalParamNEnd
///   \cgalParamNBegin{is_constrained}
///     \cgalParamDescription{the same as one flag per face, in the order of `faces(tm)` (ignored when
///       `constrained_faces` is given); given with `Polyvector_fields::parameters::is_constrained()`, which keeps a reference}
///     \cgalParamType{`std::vector<bool>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \pvfParamVertexPointMap
/// \cgalNamedParamsEnd
///
/// \returns
/// - `Error_code::INVALID_DEGREE` if `N == 0`;
/// - `Error_code::EMPTY_MESH` if `tm` has no face;
/// - `Error_code::NON_TRIANGLE_FACE` if a face is not a triangle;
/// - `Error_code::INCONSISTENT_DEGREE` if a face holds a number of vectors other than `N`;
/// - `Error_code::NON_FINITE_VALUE` if a point, vector or scalar value is NaN or
///   infinite (VTK's legacy reader cannot read them);
/// - `Error_code::INVALID_FACE` if `constrained_faces` names a face that is not in `tm`;
/// - `Error_code::INVALID_PARAMETER` if a scalar array has a bad or repeated
///   name or a size other than the number of faces, if a flag vector has a size
///   other than the number of faces, or if a singularity names a vertex that is
///   not in `tm`, has a zero numerator, or repeats a vertex;
/// - `Error_code::CANNOT_OPEN_FILE` if `os` is not writable or writing fails;
/// - `Error_code::SUCCESS` otherwise.
///
/// \sa `write_rawfield()`, `write_singularities()`
template <typename TriangleMesh, typename RootMap, typename SingularityRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code write_VTK(std::ostream& os, const TriangleMesh& tm, RootMap root_map, std::size_t N,
                     const SingularityRange& singularities, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code = internal::vtk_to_string(tm, root_map, N, singularities, np, text);
  return code != Error_code::SUCCESS ? code : internal::write_to_stream(os, text);
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes a legacy VTK file to `filename`; see the stream overload.
///
/// The file is written to a temporary file in the same directory, renamed to
/// `filename` once complete: on failure, `filename` is left as it was and no
/// temporary file remains.
///
/// \returns the codes of the stream overload; `Error_code::CANNOT_OPEN_FILE` if
///          the file cannot be created, written or renamed.
template <typename TriangleMesh, typename RootMap, typename SingularityRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code write_VTK(const std::string& filename, const TriangleMesh& tm, RootMap root_map, std::size_t N,
                     const SingularityRange& singularities, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code = internal::vtk_to_string(tm, root_map, N, singularities, np, text);
  return code != Error_code::SUCCESS ? code : internal::write_file_atomically(filename, text);
}

} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_VTK_H
