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
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <CGAL/Polyvector_fields/internal/parallel.h>

#include <boost/property_map/property_map.hpp>


#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <istream>
#include <limits>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {

namespace internal {

// The checks of the writer, in the order of the text: the first face with
// another number of vectors than N, or a non-finite coordinate, is refused.
template <typename RootMap, typename FaceList>
Error_code check_rawfield(RootMap root_map, std::size_t N, const FaceList& face_ids)
{
  using boost::get;
  if(N == 0)
    return Error_code::INVALID_DEGREE;
  for(const auto f : face_ids)
  {
    const auto& roots = get(root_map, f);
    if(std::size_t(roots.size()) != N)
      return Error_code::INCONSISTENT_DEGREE;
    for(const auto& u : roots)
      if(!std::isfinite(CGAL::to_double(u.x())) || !std::isfinite(CGAL::to_double(u.y())) ||
         !std::isfinite(CGAL::to_double(u.z())))
        return Error_code::NON_FINITE_VALUE;
  }
  return Error_code::SUCCESS;
}

// Appends the lines of the faces face_ids[first, last) to `text`: the 3N
// coordinates of each face, shortest round-trip text, one space apart.
template <typename RootMap, typename FaceList>
void append_rawfield_lines(RootMap root_map, std::size_t N, const FaceList& face_ids, std::size_t first,
                           std::size_t last, std::string& text)
{
  using boost::get;
  // At most 25 characters for a number and its separator.
  const std::size_t line_size = 3 * N * 25 + 1;
  const std::size_t start = text.size();
  text.resize(start + (last - first) * line_size);
  char* p = &text[start];
  // The coordinates of a face already written, for the ones that repeat
  // their magnitude (the opposite vectors of a sign-symmetric field): the text
  // of -x is '-' followed by the text of x.
  constexpr std::size_t window = 32;
  double magnitude[window];
  std::size_t text_begin[window], text_size[window];
  for(std::size_t i = first; i < last; ++i)
  {
    const auto& roots = get(root_map, face_ids[i]);
    char* const line = p;
    std::size_t seen = 0;
    for(const auto& u : roots)
    {
      const double xyz[3] = { CGAL::to_double(u.x()), CGAL::to_double(u.y()), CGAL::to_double(u.z()) };
      for(double c : xyz)
      {
        if(p != line)
          *p++ = ' ';
        if(std::signbit(c))
          *p++ = '-';
        const double m = std::abs(c);
        std::size_t k = 0;
        const std::size_t known = (std::min)(seen, window);
        while(k < known && magnitude[k] != m)
          ++k;
        if(k < known)
        {
          std::memcpy(p, line + text_begin[k], text_size[k]);
          p += text_size[k];
        }
        else
        {
          char* const begin = p;
          p = std::to_chars(p, p + 24, m).ptr;
          const std::size_t slot = seen % window;
          magnitude[slot] = m;
          text_begin[slot] = std::size_t(begin - line);
          text_size[slot] = std::size_t(p - begin);
          ++seen;
        }
      }
    }
    *p++ = '\n';
  }
  text.resize(std::size_t(p - text.data()));
}

// Formats the rawfield of a field that check_rawfield() accepted, and hands
// the text to `sink(const char*, std::size_t)` (false: stop) in chunks of
// 4096 faces. With CGAL::Parallel_tag (and TBB) the chunks of a batch are
// formatted in parallel, then handed on in order: the same bytes.
// Returns false if the sink did.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename RootMap, typename FaceList, typename Sink>
bool format_rawfield(RootMap root_map, std::size_t N, const FaceList& face_ids, Sink&& sink)
{
  std::string header;
  {
    char buffer[64];
    char* p = std::to_chars(buffer, buffer + 32, N).ptr;
    *p++ = ' ';
    p = std::to_chars(p, p + 31, face_ids.size()).ptr;
    *p++ = '\n';
    header.assign(buffer, p);
  }
  if(!sink(static_cast<const char*>(header.data()), header.size()))
    return false;
  constexpr std::size_t chunk = 4096, batch = 16;
  std::vector<std::string> texts(batch);
  const std::size_t F = face_ids.size();
  for(std::size_t start = 0; start < F; start += chunk * batch)
  {
    const std::size_t chunks = (std::min)(batch, (F - start + chunk - 1) / chunk);
    auto format = [&](std::size_t c) {
      texts[c].clear();
      const std::size_t first = start + c * chunk;
      append_rawfield_lines(root_map, N, face_ids, first, (std::min)(F, first + chunk), texts[c]);
    };
    Polyvector_fields::internal::for_each_index(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value && chunks > 1, chunks,
                                                format);
    for(std::size_t c = 0; c < chunks; ++c)
      if(!sink(static_cast<const char*>(texts[c].data()), texts[c].size()))
        return false;
  }
  return true;
}

template <typename TriangleMesh, typename RootMap>
Error_code rawfield_to_string(const TriangleMesh& tm, RootMap root_map, std::size_t N, std::string& out)
{
  const auto face_ids = face_list(tm);
  const Error_code code = check_rawfield(root_map, N, face_ids);
  if(code != Error_code::SUCCESS)
    return code;
  std::string text;
  format_rawfield(root_map, N, face_ids, [&](const char* data, std::size_t size) {
    text.append(data, size);
    return true;
  });
  out = std::move(text);
  return Error_code::SUCCESS;
}

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
  const auto construct_vector = gt.construct_vector_3_object();

  const Diagnostic diagnostic = internal::diagnostic(np);
  Text_reader reader(text);
  std::string_view token;
  std::size_t N = 0, F = 0;
  if(!reader.next_line() || !reader.next_token(token) || parse_integer(token, N) != Token_status::OK ||
     !reader.next_token(token) || parse_integer(token, F) != Token_status::OK || reader.line_has_more())
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "the header is not two integers 'N F'");
  // Each of the 3N numbers of a face line takes at least 2 characters: an N
  // that the text cannot hold is refused before anything is allocated.
  if(N == 0 || N > (text.size() / 2 + 1) / 3)
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "the degree N = " + std::to_string(N) +
                                                                    " is not valid for a file of " +
                                                                    std::to_string(text.size()) + " bytes");
  if(expected_N != 0 && N != expected_N)
    return diagnostic.fail_at(reader, Error_code::INCONSISTENT_DEGREE, "the degree is " + std::to_string(N) +
                                                                         ", not " + std::to_string(expected_N));
  const auto face_ids = face_list(tm);
  if(F != face_ids.size())
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "the file has " + std::to_string(F) +
                                                                    " faces, the mesh " + std::to_string(face_ids.size()));

  std::vector<std::vector<Vector_3> > roots(F);
  using boost::put;
  for(std::size_t f = 0; f < F; ++f)
  {
    if(!reader.next_line())
      return diagnostic.fail(Error_code::MALFORMED_FILE, "the file ends after " + std::to_string(f) + " of " +
                                                           std::to_string(F) + " faces");
    roots[f].reserve(N);
    double xyz[3];
    for(std::size_t k = 0; k < 3 * N; ++k)
    {
      if(!reader.next_token(token))
        return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "face " + std::to_string(f) + " has " +
                                                                        std::to_string(k) + " numbers, not 3N = " +
                                                                        std::to_string(3 * N));
      const Token_status status = parse_double(token, xyz[k % 3]);
      if(status == Token_status::NON_FINITE)
        return diagnostic.fail_at(reader, Error_code::NON_FINITE_VALUE, quoted(token) + " is not a finite number");
      if(status != Token_status::OK)
        return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, quoted(token) + " is not a number");
      if(k % 3 == 2)
        roots[f].push_back(construct_vector(xyz[0], xyz[1], xyz[2]));
    }
    if(reader.line_has_more())
      return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE,
                                "face " + std::to_string(f) + " has more than 3N = " + std::to_string(3 * N) + " numbers");
  }
  if(reader.next_line())
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "data after the last face");

  for(std::size_t f = 0; f < F; ++f)
    put(root_map, face_ids[f], std::move(roots[f]));
  N_out = N;
  return Error_code::SUCCESS;
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
