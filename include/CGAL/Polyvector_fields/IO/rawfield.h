// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_RAWFIELD_H
#define CGAL_POLYVECTOR_FIELDS_IO_RAWFIELD_H

/// \file IO/rawfield.h
/// Reading and writing the N vectors of every face in Directional's `.rawfield` format.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/atomic_file.h>
#include <CGAL/Polyvector_fields/IO/internal/mesh_indices.h>
#include <CGAL/Polyvector_fields/IO/internal/rawfield_text.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <istream>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {

namespace internal {

// Reads the named parameters of read_rawfield() and parses `text`.
template <typename TriangleMesh, typename RootMap, typename NamedParameters>
Error_code read_rawfield_from_text(std::string_view text, const TriangleMesh& tm, RootMap root_map,
                                   std::size_t& N_out, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
  typedef typename Geom_traits::Vector_3 Vector_3;

  const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const std::size_t expected_N =
    choose_parameter(get_parameter(np, Polyvector_fields::internal_np::expected_degree), std::size_t(0));
  return parse_rawfield<Vector_3>(text, tm, root_map, expected_N, gt.construct_vector_3_object(), internal::diagnostic(np),
                                  N_out);
}

} // namespace internal

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes the `N` vectors of every face of `tm` to `os` in the `.rawfield`
/// format of the Directional library.
///
/// The first line is `N F`, with `F` the number of faces; then comes one line
/// per face, in the order of `faces(tm)`, holding the `3N` world coordinates
/// `x y z` of its `N` vectors. Coordinates are converted to `double` and
/// written with the shortest decimal text that reads back as the same `double`
/// (at most 17 significant digits), whatever the locale of `os`, so that
/// `read_rawfield()` restores them exactly.
///
/// Nothing is written to `os` unless the whole field is valid.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam RootMap a model of `ReadablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and
///         `std::vector<Vector_3>` as value type, where `Vector_3` has `x()`, `y()`
///         and `z()` convertible by `CGAL::to_double()`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param os the output stream
/// \param tm the mesh
/// \param root_map the vectors of each face (for instance, the roots of a PolyVector field)
/// \param N the number of vectors per face
/// \param np an optional sequence of named parameters; none is read at present,
///        the parameter is there for uniformity with the readers
///
/// \returns
/// - `Error_code::INVALID_DEGREE` if `N == 0`;
/// - `Error_code::INCONSISTENT_DEGREE` if a face holds a number of vectors other than `N`;
/// - `Error_code::NON_FINITE_VALUE` if a coordinate is NaN or infinite;
/// - `Error_code::CANNOT_OPEN_FILE` if `os` is not writable or writing fails;
/// - `Error_code::SUCCESS` otherwise.
///
/// \sa `read_rawfield()`
template <typename TriangleMesh, typename RootMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code write_rawfield(std::ostream& os, const TriangleMesh& tm, RootMap root_map, std::size_t N,
                          const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  CGAL_USE(np);
  const auto face_ids = internal::face_list(tm);
  const Error_code code = internal::check_rawfield(root_map, N, face_ids);
  if(code != Error_code::SUCCESS)
    return code;
  if(!os.good())
    return Error_code::CANNOT_OPEN_FILE;
  internal::format_rawfield(root_map, N, face_ids, [&](const char* data, std::size_t size) {
    os.write(data, static_cast<std::streamsize>(size));
    return os.good();
  });
  os.flush();
  return os.good() ? Error_code::SUCCESS : Error_code::CANNOT_OPEN_FILE;
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes the `N` vectors of every face of `tm` to the file `filename` in the
/// `.rawfield` format; see the stream overload for the format.
///
/// The file is written to a temporary file in the same directory, which is
/// renamed to `filename` only once it is complete: on failure, `filename` is
/// left as it was (absent, or with its old content) and no temporary file remains.
///
/// \returns the codes of the stream overload; `Error_code::CANNOT_OPEN_FILE` if
///          the file cannot be created, written or renamed.
template <typename TriangleMesh, typename RootMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code write_rawfield(const std::string& filename, const TriangleMesh& tm, RootMap root_map, std::size_t N,
                          const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  CGAL_USE(np);
  const auto face_ids = internal::face_list(tm);
  const Error_code code = internal::check_rawfield(root_map, N, face_ids);
  if(code != Error_code::SUCCESS)
    return code;
  return internal::write_file_atomically_with(filename, [&](auto&& sink) {
    return internal::format_rawfield(root_map, N, face_ids, sink);
  });
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// reads a field in the `.rawfield` format of the Directional library from
/// `is` (read to its end) and stores the vectors of each face in `root_map`.
///
/// The file must hold a first line `N F`, with `N >= 1` and `F` equal to the
/// number of faces of `tm`, then exactly `F` lines of exactly `3N` numbers:
/// line `i` gives the world coordinates `x y z` of the `N` vectors of the
/// `i`-th face of `faces(tm)`. Blank lines are ignored; numbers are read in the
/// "C" locale whatever the locale of `is`.
///
/// The whole stream is parsed and checked before `root_map` and `N` are
/// written: on failure they are left untouched.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam RootMap a model of `WritablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and
///         `std::vector<GT::Vector_3>` as value type, `GT` being the geometric traits
/// \tparam NamedParameters a sequence of named parameters
///
/// \param is the input stream
/// \param tm the mesh
/// \param root_map receives the `N` vectors of each face
/// \param N receives the degree read from the file
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \pvfParamGeomTraits
///   \pvfParamExpectedDegree
///   \pvfParamMaximumFileSize
///   \pvfParamErrorMessage{its line}
/// \cgalNamedParamsEnd
///
/// \returns
/// - `Error_code::CANNOT_OPEN_FILE` if `is` is not readable;
/// - `Error_code::FILE_TOO_LARGE` if the input is larger than `maximum_file_size`;
/// - `Error_code::MALFORMED_FILE` if the input holds a NUL byte, if the header is not two non-negative integers,
///   if `N == 0`, if `F` differs from the number of faces, if a line does not
///   hold exactly `3N` numbers, if a token is not a decimal number, or if
///   non-blank lines follow the last face;
/// - `Error_code::INCONSISTENT_DEGREE` if `expected_degree` is given and differs from `N`;
/// - `Error_code::NON_FINITE_VALUE` if a coordinate is NaN or infinite
///   (or beyond the range of `double`);
/// - `Error_code::SUCCESS` otherwise.
///
/// \sa `write_rawfield()`
template <typename TriangleMesh, typename RootMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code read_rawfield(std::istream& is, const TriangleMesh& tm, RootMap root_map, std::size_t& N,
                         const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code = internal::read_text(is, text, np);
  return code != Error_code::SUCCESS ? code : internal::read_rawfield_from_text(text, tm, root_map, N, np);
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// reads the `.rawfield` file `filename`; see the stream overload.
///
/// \returns the codes of the stream overload; `Error_code::CANNOT_OPEN_FILE` if
///          the file cannot be opened.
template <typename TriangleMesh, typename RootMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code read_rawfield(const std::string& filename, const TriangleMesh& tm, RootMap root_map, std::size_t& N,
                         const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code = internal::read_text(filename, text, np);
  return code != Error_code::SUCCESS ? code : internal::read_rawfield_from_text(text, tm, root_map, N, np);
}

} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_RAWFIELD_H
