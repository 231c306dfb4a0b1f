// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_SINGULARITIES_H
#define CGAL_POLYVECTOR_FIELDS_IO_SINGULARITIES_H

/// \file IO/singularities.h
/// Reading and writing the singular vertices of a field in the `.sings` format.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/atomic_file.h>
#include <CGAL/Polyvector_fields/IO/internal/mesh_indices.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>
#include <CGAL/Polyvector_fields/Singularity.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <istream>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {

namespace internal {

// Checks the singularities given by a caller and turns them into
// (vertex id, index numerator) pairs. Returns INVALID_PARAMETER for a vertex
// that is not in the mesh, a zero numerator, or a vertex listed twice.
template <typename TriangleMesh, typename SingularityRange>
Error_code singularity_ids(const TriangleMesh& tm, const SingularityRange& singularities,
                           std::vector<std::pair<std::size_t, int> >& ids)
{
  const auto vertices = vertex_list(tm);
  const auto vertex_index = make_index(vertices);
  std::vector<bool> seen(vertices.size(), false);
  std::vector<std::pair<std::size_t, int> > result;
  for(const auto& s : singularities)
  {
    std::size_t id = 0;
    if(!vertex_index.find(s.vertex, id) || s.index_numerator == 0 || seen[id])
      return Error_code::INVALID_PARAMETER;
    seen[id] = true;
    result.emplace_back(id, int(s.index_numerator));
  }
  ids = std::move(result);
  return Error_code::SUCCESS;
}

template <typename TriangleMesh, typename SingularityRange>
Error_code singularities_to_string(const TriangleMesh& tm, std::size_t N,
                                   const SingularityRange& singularities, std::string& out)
{
  if(N == 0)
    return Error_code::INVALID_DEGREE;
  std::vector<std::pair<std::size_t, int> > ids;
  const Error_code code = singularity_ids(tm, singularities, ids);
  if(code != Error_code::SUCCESS)
    return code;
  std::string text;
  append_integer(text, N);
  text += ' ';
  append_integer(text, ids.size());
  text += '\n';
  for(const auto& s : ids)
  {
    append_integer(text, s.first);
    text += ' ';
    append_integer(text, s.second);
    text += '\n';
  }
  out = std::move(text);
  return Error_code::SUCCESS;
}

template <typename TriangleMesh, typename NamedParameters>
Error_code read_singularities_from_text(
  std::string_view text, const TriangleMesh& tm, std::size_t& N_out,
  std::vector<Singularity<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >& out,
  const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const std::size_t expected_N =
    choose_parameter(get_parameter(np, Polyvector_fields::internal_np::expected_degree), std::size_t(0));

  const Diagnostic diagnostic = internal::diagnostic(np);
  Text_reader reader(text);
  std::string_view token;
  std::size_t N = 0, count = 0;
  if(!reader.next_line() || !reader.next_token(token) || parse_integer(token, N) != Token_status::OK ||
     !reader.next_token(token) || parse_integer(token, count) != Token_status::OK || reader.line_has_more() || N == 0)
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "the header is not two integers 'N count' with N >= 1");
  if(expected_N != 0 && N != expected_N)
    return diagnostic.fail_at(reader, Error_code::INCONSISTENT_DEGREE, "the degree is " + std::to_string(N) +
                                                                         ", not " + std::to_string(expected_N));

  const auto vertices = vertex_list(tm);
  if(count > vertices.size())
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, std::to_string(count) +
                                                                    " singularities announced, more than the " +
                                                                    std::to_string(vertices.size()) + " vertices");
  std::vector<bool> seen(vertices.size(), false);
  std::vector<Singularity<vertex_descriptor> > result;
  result.reserve(count);
  for(std::size_t i = 0; i < count; ++i)
  {
    if(!reader.next_line())
      return diagnostic.fail(Error_code::MALFORMED_FILE, "the file ends after " + std::to_string(i) + " of " +
                                                           std::to_string(count) + " singularities");
    std::size_t id = 0;
    int numerator = 0;
    if(!reader.next_token(token) || parse_integer(token, id) != Token_status::OK || id >= vertices.size())
      return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "the vertex id " + quoted(token) +
                                                                      " is not in 0.." +
                                                                      std::to_string(vertices.size() - 1));
    if(seen[id])
      return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "vertex " + std::to_string(id) + " is listed twice");
    if(!reader.next_token(token) || parse_integer(token, numerator) != Token_status::OK || numerator == 0 ||
       reader.line_has_more())
      return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "expected 'vertex numerator' with an integer numerator other than 0");
    seen[id] = true;
    result.push_back(Singularity<vertex_descriptor>{ vertices[id], numerator });
  }
  if(reader.next_line())
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "data after the announced singularities");

  out = std::move(result);
  N_out = N;
  return Error_code::SUCCESS;
}

} // namespace internal

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes the singular vertices of a field of degree `N` to `os` in the
/// `.sings` format of the Directional library.
///
/// The first line is `N count`; then comes one line `vertex_id k` per
/// singularity, in the order of the range, where `vertex_id` is the 0-based
/// position of the vertex in `vertices(tm)` and `k` the index numerator (the
/// index is `k/N`). Nothing is written to `os` unless the whole input is valid.
///
/// \tparam TriangleMesh a model of `FaceListGraph` (and `VertexListGraph`)
/// \tparam SingularityRange a range of
///         `Singularity<boost::graph_traits<TriangleMesh>::%vertex_descriptor>`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param os the output stream
/// \param tm the mesh
/// \param N the degree of the field
/// \param singularities the singular vertices
/// \param np an optional sequence of named parameters; none is read at present
///
/// \returns
/// - `Error_code::INVALID_DEGREE` if `N == 0`;
/// - `Error_code::INVALID_PARAMETER` if a singularity names a vertex that is not in
///   `tm`, has a zero index numerator, or repeats a vertex;
/// - `Error_code::CANNOT_OPEN_FILE` if `os` is not writable or writing fails;
/// - `Error_code::SUCCESS` otherwise.
///
/// \sa `read_singularities()`
template <typename TriangleMesh, typename SingularityRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code write_singularities(std::ostream& os, const TriangleMesh& tm, std::size_t N,
                               const SingularityRange& singularities,
                               const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  CGAL_USE(np);
  std::string text;
  const Error_code code = internal::singularities_to_string(tm, N, singularities, text);
  if(code != Error_code::SUCCESS)
    return code;
  return internal::write_to_stream(os, text);
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes the singular vertices of a field of degree `N` to the file
/// `filename` in the `.sings` format; see the stream overload.
///
/// The file is written to a temporary file in the same directory, renamed to
/// `filename` once complete: on failure, `filename` is left as it was and no
/// temporary file remains.
///
/// \returns the codes of the stream overload; `Error_code::CANNOT_OPEN_FILE` if
///          the file cannot be created, written or renamed.
template <typename TriangleMesh, typename SingularityRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code write_singularities(const std::string& filename, const TriangleMesh& tm, std::size_t N,
                               const SingularityRange& singularities,
                               const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  CGAL_USE(np);
  std::string text;
  const Error_code code = internal::singularities_to_string(tm, N, singularities, text);
  if(code != Error_code::SUCCESS)
    return code;
  return internal::write_file_atomically(filename, text);
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// reads singular vertices in the `.sings` format from `is` (read to its end).
///
/// The file must hold a first line `N count` with `N >= 1`, then exactly
/// `count` lines `vertex_id k` of two integers, with `vertex_id` in
/// `0 .. num_vertices-1` (in `vertices(tm)` order), no vertex twice, and
/// `k != 0` fitting in an `int`. Blank lines are ignored.
///
/// `out` is replaced by the singularities in file order and `N` receives the
/// degree; on failure both are left untouched.
///
/// \tparam TriangleMesh a model of `FaceListGraph` (and `VertexListGraph`)
/// \tparam NamedParameters a sequence of named parameters
///
/// \param is the input stream
/// \param tm the mesh
/// \param N receives the degree read from the file
/// \param out receives the singularities
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \pvfParamExpectedDegree
///   \pvfParamMaximumFileSize
///   \pvfParamErrorMessage{its line}
/// \cgalNamedParamsEnd
///
/// \returns
/// - `Error_code::CANNOT_OPEN_FILE` if `is` is not readable;
/// - `Error_code::FILE_TOO_LARGE` if the input is larger than `maximum_file_size`;
/// - `Error_code::MALFORMED_FILE` if the input holds a NUL byte, if the header is not two non-negative integers
///   or `N == 0`; if a line is not two integers; if a vertex id is out of range
///   or repeated (there is no dedicated code for a bad vertex id); if an index
///   numerator is zero or does not fit in an `int`; if there are fewer or more
///   lines than `count`;
/// - `Error_code::INCONSISTENT_DEGREE` if `expected_degree` is given and differs from `N`;
/// - `Error_code::SUCCESS` otherwise.
///
/// \sa `write_singularities()`
template <typename TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code read_singularities(
  std::istream& is, const TriangleMesh& tm, std::size_t& N,
  std::vector<Singularity<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >& out,
  const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code = internal::read_text(is, text, np);
  if(code != Error_code::SUCCESS)
    return code;
  return internal::read_singularities_from_text(text, tm, N, out, np);
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// reads the `.sings` file `filename`; see the stream overload.
///
/// \returns the codes of the stream overload; `Error_code::CANNOT_OPEN_FILE` if
///          the file cannot be opened.
template <typename TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code read_singularities(
  const std::string& filename, const TriangleMesh& tm, std::size_t& N,
  std::vector<Singularity<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >& out,
  const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code = internal::read_text(filename, text, np);
  if(code != Error_code::SUCCESS)
    return code;
  return internal::read_singularities_from_text(text, tm, N, out, np);
}

} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_SINGULARITIES_H
