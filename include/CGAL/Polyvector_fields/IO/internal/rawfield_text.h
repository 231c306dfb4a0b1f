// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_RAWFIELD_TEXT_H
#define CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_RAWFIELD_TEXT_H

// The text of a `.rawfield` file: its checks and formatting for
// write_rawfield(), its parsing for read_rawfield().

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/mesh_indices.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>

#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstring>
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

// The header `N F` of a rawfield: N >= 1, no larger than the text can hold,
// equal to `expected_N` unless that is 0; F is returned unchecked.
inline Error_code parse_rawfield_header(Text_reader& reader, std::size_t text_size, std::size_t expected_N,
                                        const Diagnostic& diagnostic, std::size_t& N, std::size_t& F)
{
  std::string_view token;
  if(!reader.next_line() || !reader.next_token(token) || parse_integer(token, N) != Token_status::OK ||
     !reader.next_token(token) || parse_integer(token, F) != Token_status::OK || reader.line_has_more())
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "the header is not two integers 'N F'");
  // Each of the 3N numbers of a face line takes at least 2 characters: an N
  // that the text cannot hold is refused before anything is allocated.
  if(N == 0 || N > (text_size / 2 + 1) / 3)
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "the degree N = " + std::to_string(N) +
                                                                    " is not valid for a file of " +
                                                                    std::to_string(text_size) + " bytes");
  if(expected_N != 0 && N != expected_N)
    return diagnostic.fail_at(reader, Error_code::INCONSISTENT_DEGREE, "the degree is " + std::to_string(N) +
                                                                         ", not " + std::to_string(expected_N));
  return Error_code::SUCCESS;
}

// The line of the face `f`: exactly 3N numbers, made into N vectors.
template <typename Vector_3, typename ConstructVector>
Error_code parse_rawfield_face(Text_reader& reader, std::size_t f, std::size_t N, std::size_t F,
                               const ConstructVector& construct_vector, const Diagnostic& diagnostic,
                               std::vector<Vector_3>& roots)
{
  std::string_view token;
  if(!reader.next_line())
    return diagnostic.fail(Error_code::MALFORMED_FILE, "the file ends after " + std::to_string(f) + " of " +
                                                         std::to_string(F) + " faces");
  roots.reserve(N);
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
      roots.push_back(construct_vector(xyz[0], xyz[1], xyz[2]));
  }
  if(reader.line_has_more())
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE,
                              "face " + std::to_string(f) + " has more than 3N = " + std::to_string(3 * N) + " numbers");
  return Error_code::SUCCESS;
}

// Parses a whole rawfield for the faces of `tm`; `root_map` and `N_out` are
// written only once everything is read and checked.
template <typename Vector_3, typename TriangleMesh, typename RootMap, typename ConstructVector>
Error_code parse_rawfield(std::string_view text, const TriangleMesh& tm, RootMap root_map, std::size_t expected_N,
                          const ConstructVector& construct_vector, const Diagnostic& diagnostic, std::size_t& N_out)
{
  Text_reader reader(text);
  std::size_t N = 0, F = 0;
  Error_code code = parse_rawfield_header(reader, text.size(), expected_N, diagnostic, N, F);
  if(code != Error_code::SUCCESS)
    return code;
  const auto face_ids = face_list(tm);
  if(F != face_ids.size())
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "the file has " + std::to_string(F) +
                                                                    " faces, the mesh " + std::to_string(face_ids.size()));

  std::vector<std::vector<Vector_3> > roots(F);
  using boost::put;
  for(std::size_t f = 0; f < F; ++f)
  {
    code = parse_rawfield_face(reader, f, N, F, construct_vector, diagnostic, roots[f]);
    if(code != Error_code::SUCCESS)
      return code;
  }
  if(reader.next_line())
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "data after the last face");

  for(std::size_t f = 0; f < F; ++f)
    put(root_map, face_ids[f], std::move(roots[f]));
  N_out = N;
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_RAWFIELD_TEXT_H
