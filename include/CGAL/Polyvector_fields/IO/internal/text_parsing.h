// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_TEXT_PARSING_H
#define CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_TEXT_PARSING_H

// Locale-independent reading and writing of the text formats of this package.
//
// Files are read whole into a string, up to a size limit (named parameter
// `maximum_file_size`; a NUL byte in a text format is refused at once), then
// cut lazily into lines at '\n' and lines into tokens at blanks (space, tab,
// '\r', '\v', '\f'), so that a reader stops at the first bad token. Every
// token is parsed by hand or with <charconv>, so neither the global C locale
// nor the locale imbued in a user's stream changes what is read or written, and
// arbitrary bytes (a binary file given by mistake) only ever give MALFORMED.
// Readers report the reason of a failure, with its line, into the string of
// the named parameter `error_message`.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <iterator>
#include <limits>
#include <locale>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#if defined(__cpp_lib_to_chars) && !defined(CGAL_PVF_IO_NO_FLOATING_POINT_CHARCONV)
#  define CGAL_PVF_IO_FLOATING_POINT_CHARCONV 1
#endif

namespace CGAL {
namespace Polyvector_fields {
namespace IO {
namespace internal {

// The outcome of parsing one token.
enum class Token_status
{
  OK,            // a finite value that fits
  MALFORMED,     // not a number of the expected kind
  NON_FINITE,    // "nan", "inf", "infinity" (any case, any sign), or a decimal beyond the double range
  OUT_OF_RANGE   // an integer that does not fit the requested type
};

inline bool is_blank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }

inline char to_lower_ascii(char c) { return (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c; }

inline bool equals_ignoring_case(std::string_view a, std::string_view b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(to_lower_ascii(a[i]) != to_lower_ascii(b[i]))
      return false;
  return true;
}

// Parses a signed decimal integer: an optional '+' or '-', then digits only.
template <typename Integer>
Token_status parse_integer(std::string_view token, Integer& value)
{
  static_assert(std::numeric_limits<Integer>::is_integer, "parse_integer needs an integer type");
  // The common case first: at most 18 digits (no overflow of the
  // accumulator), no sign, a value that fits.
  if(!token.empty() && token.size() <= 18)
  {
    unsigned long long magnitude = 0;
    std::size_t i = 0;
    for(; i < token.size() && is_digit(token[i]); ++i)
      magnitude = magnitude * 10 + unsigned(token[i] - '0');
    if(i == token.size() && magnitude <= static_cast<unsigned long long>((std::numeric_limits<Integer>::max)()))
    {
      value = Integer(magnitude);
      return Token_status::OK;
    }
  }
  std::string_view digits = token;
  bool negative = false;
  if(!digits.empty() && (digits.front() == '+' || digits.front() == '-'))
  {
    negative = (digits.front() == '-');
    digits.remove_prefix(1);
  }
  if(digits.empty() || !std::all_of(digits.begin(), digits.end(), is_digit))
    return Token_status::MALFORMED;
  // from_chars accepts a leading '-' but no '+': give it the digits and the sign apart.
  unsigned long long magnitude = 0;
  const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), magnitude);
  if(result.ec == std::errc::result_out_of_range)
    return Token_status::OUT_OF_RANGE;
  if(result.ec != std::errc() || result.ptr != digits.data() + digits.size())
    return Token_status::MALFORMED;
  if(negative)
  {
    if(magnitude == 0)
    {
      value = Integer(0);
      return Token_status::OK;
    }
    if(!std::numeric_limits<Integer>::is_signed)
      return Token_status::OUT_OF_RANGE;
    // -(magnitude) >= lowest()  <=>  magnitude - 1 <= max()
    if(magnitude - 1 > static_cast<unsigned long long>((std::numeric_limits<Integer>::max)()))
      return Token_status::OUT_OF_RANGE;
    value = Integer(-Integer(magnitude - 1) - 1);
    return Token_status::OK;
  }
  if(magnitude > static_cast<unsigned long long>((std::numeric_limits<Integer>::max)()))
    return Token_status::OUT_OF_RANGE;
  value = Integer(magnitude);
  return Token_status::OK;
}

// Parses a decimal floating-point number: [+-] (d+[.d*] | .d+) [(e|E)[+-]d+],
// or [+-] nan / inf / infinity in any case. Hexadecimal floats, thousands
// separators, decimal commas and trailing characters are MALFORMED. A decimal
// whose magnitude exceeds the double range is NON_FINITE; one below the
// smallest subnormal reads as a signed zero.
inline Token_status parse_double(std::string_view token, double& value)
{
  std::string_view body = token;
  bool negative = false;
  if(!body.empty() && (body.front() == '+' || body.front() == '-'))
  {
    negative = (body.front() == '-');
    body.remove_prefix(1);
  }
#ifdef CGAL_PVF_IO_FLOATING_POINT_CHARCONV
  // The common case first. A body that starts with a digit or a point and
  // that from_chars reads whole, to a finite value, is one of the grammar
  // below (from_chars takes the same decimal grammar, and no "inf" or "nan"
  // that starts so), and the value is the one the full path gives.
  if(!body.empty() && (is_digit(body.front()) || body.front() == '.'))
  {
    double magnitude = 0;
    const auto result = std::from_chars(body.data(), body.data() + body.size(), magnitude, std::chars_format::general);
    if(result.ec == std::errc() && result.ptr == body.data() + body.size() && std::isfinite(magnitude))
    {
      value = negative ? -magnitude : magnitude;
      return Token_status::OK;
    }
  }
#endif
  if(equals_ignoring_case(body, "nan") || equals_ignoring_case(body, "inf") ||
     equals_ignoring_case(body, "infinity"))
    return Token_status::NON_FINITE;

  // Check the grammar and estimate the decimal order of magnitude, so that an
  // out-of-range conversion can be told apart as overflow or underflow.
  std::size_t i = 0;
  const std::size_t n = body.size();
  long long leading_order = 0;      // order of the first nonzero mantissa digit, before the exponent
  bool nonzero_seen = false;
  std::size_t integer_digits = 0, fraction_digits = 0;
  long long position = 0;           // digits of the integer part seen so far
  for(; i < n && is_digit(body[i]); ++i, ++integer_digits)
  {
    if(!nonzero_seen && body[i] != '0')
    {
      nonzero_seen = true;
      leading_order = 0;
      position = 0;
    }
    if(nonzero_seen && position < (std::numeric_limits<int>::max)())
      ++position;
  }
  if(nonzero_seen)
    leading_order = position - 1;
  if(i < n && body[i] == '.')
  {
    ++i;
    long long zeros = 0;
    for(; i < n && is_digit(body[i]); ++i, ++fraction_digits)
    {
      if(!nonzero_seen)
      {
        if(body[i] != '0')
        {
          nonzero_seen = true;
          leading_order = -zeros - 1;
        }
        else if(zeros < (std::numeric_limits<int>::max)())
          ++zeros;
      }
    }
  }
  if(integer_digits + fraction_digits == 0)
    return Token_status::MALFORMED;
  long long exponent = 0;
  if(i < n && (body[i] == 'e' || body[i] == 'E'))
  {
    ++i;
    bool exponent_negative = false;
    if(i < n && (body[i] == '+' || body[i] == '-'))
    {
      exponent_negative = (body[i] == '-');
      ++i;
    }
    const std::size_t exponent_begin = i;
    for(; i < n && is_digit(body[i]); ++i)
      if(exponent < 1000000000LL)
        exponent = exponent * 10 + (body[i] - '0');
    if(i == exponent_begin)
      return Token_status::MALFORMED;
    if(exponent_negative)
      exponent = -exponent;
  }
  if(i != n)
    return Token_status::MALFORMED;

  double magnitude = 0;
  bool out_of_range = false;
#ifdef CGAL_PVF_IO_FLOATING_POINT_CHARCONV
  const auto result = std::from_chars(body.data(), body.data() + n, magnitude, std::chars_format::general);
  if(result.ec == std::errc::result_out_of_range)
    out_of_range = true;
  else if(result.ec != std::errc() || result.ptr != body.data() + n)
    return Token_status::MALFORMED;
#else
  {
    std::istringstream stream{ std::string(body) };
    stream.imbue(std::locale::classic());
    stream >> magnitude;
    if(!stream)
      out_of_range = true;  // the grammar was checked: a failure here is a range error
  }
#endif
  if(out_of_range || !std::isfinite(magnitude))
  {
    if(nonzero_seen && leading_order + exponent > 0)
      return Token_status::NON_FINITE;
    magnitude = 0.0;  // underflow below the smallest subnormal
  }
  value = negative ? -magnitude : magnitude;
  return Token_status::OK;
}

// Appends the shortest decimal text that reads back as exactly `x` (finite).
inline void append_double(std::string& out, double x)
{
#ifdef CGAL_PVF_IO_FLOATING_POINT_CHARCONV
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), x);
  out.append(buffer, result.ptr);
#else
  std::ostringstream stream;
  stream.imbue(std::locale::classic());
  stream.precision(17);
  stream << x;
  out += stream.str();
#endif
}

template <typename Integer>
void append_integer(std::string& out, Integer x)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), x);
  out.append(buffer, result.ptr);
}

// The outcome of reading a whole input.
enum class Read_status
{
  OK,
  MISSING,       // no such file
  DIRECTORY,     // a directory, not a file
  CANNOT_OPEN,   // the stream or file cannot be read
  TOO_LARGE,     // more than the size limit
  BINARY         // a NUL byte in a text format
};

// Reads what is left of `is` into `text`, at most `limit` bytes, in chunks, so
// that an endless input (/dev/zero, a pipe) is refused after `limit` bytes, and
// a text input holding a NUL byte (binary data) after the chunk that holds it.
// Appends a chunk of `count` bytes read to `result`, with the checks of a
// bounded read: no NUL byte in a text format, at most `limit` bytes in all.
inline Read_status append_chunk(const char* buffer, std::size_t count, std::size_t limit, bool text_only,
                                std::string& result)
{
  if(text_only && std::memchr(buffer, '\0', count) != nullptr)
    return Read_status::BINARY;
  if(count > limit - (std::min)(limit, result.size()))
    return Read_status::TOO_LARGE;
  result.append(buffer, count);
  return Read_status::OK;
}

inline Read_status read_bounded(std::istream& is, std::size_t limit, bool text_only, std::string& text)
{
  if(!is.good())
    return Read_status::CANNOT_OPEN;
  std::string result;
  char buffer[1 << 16];
  while(true)
  {
    is.read(buffer, sizeof(buffer));
    const std::size_t count = std::size_t(is.gcount());
    if(count > 0)
    {
      const Read_status status = append_chunk(buffer, count, limit, text_only, result);
      if(status != Read_status::OK)
        return status;
    }
    if(is.bad())
      return Read_status::CANNOT_OPEN;
    if(!is)
      break;  // end of input
  }
  text = std::move(result);
  return Read_status::OK;
}

// Reads the file `filename` as read_bounded() does. A regular file larger than
// `limit` is refused before it is read.
inline Read_status read_file_bounded(const std::string& filename, std::size_t limit, bool text_only,
                                     std::string& text)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path path(filename);
  if(filename.empty() || !fs::exists(path, ec))
    return Read_status::MISSING;
  if(fs::is_directory(path, ec))
    return Read_status::DIRECTORY;  // opening a directory may succeed, reading it fails
  std::uintmax_t size = 0;
  if(fs::is_regular_file(path, ec))
  {
    size = fs::file_size(path, ec);
    if(ec)
      size = 0;
    else if(size > limit)
      return Read_status::TOO_LARGE;
  }
  // The bytes of a regular file in one read into a string of its size, then
  // in chunks whatever follows (a file that grew, or a special file of size
  // 0), with the checks of read_bounded().
  std::FILE* file = std::fopen(filename.c_str(), "rb");
  if(file == nullptr)
    return Read_status::CANNOT_OPEN;
  struct Closer
  {
    std::FILE* file;
    ~Closer() { std::fclose(file); }
  } closer{ file };
  std::string result;
  result.resize(std::size_t(size));
  std::size_t count = size == 0 ? 0 : std::fread(&result[0], 1, result.size(), file);
  result.resize(count);
  if(text_only && count > 0 && std::memchr(result.data(), '\0', count) != nullptr)
    return Read_status::BINARY;
  char buffer[1 << 16];
  while(!std::ferror(file) && !std::feof(file))
  {
    count = std::fread(buffer, 1, sizeof(buffer), file);
    if(count > 0)
    {
      const Read_status status = append_chunk(buffer, count, limit, text_only, result);
      if(status != Read_status::OK)
        return status;
    }
  }
  if(std::ferror(file))
    return Read_status::CANNOT_OPEN;
  text = std::move(result);
  return Read_status::OK;
}

// A text cut into lines at '\n' ('\r' is blank), and lines into tokens at
// blanks, read lazily: a reader takes one token at a time, so that it can stop
// at the first bad one, and never holds more than one token of a line.
// Lines are numbered from 1. Text after the comment character, if any, is
// ignored to the end of its line.
class Text_reader
{
public:
  explicit Text_reader(std::string_view text, char comment = '\0') : m_text(text), m_comment(comment) {}

  // Moves to the next line that holds a token; false at the end of the text.
  bool next_line()
  {
    while(m_next < m_text.size() || (m_next == m_text.size() && !m_ended))
    {
      const std::size_t end = m_text.find('\n', m_next);
      if(end == std::string_view::npos)
      {
        m_line = m_text.substr(m_next);
        m_next = m_text.size();
        m_ended = true;
      }
      else
      {
        m_line = m_text.substr(m_next, end - m_next);
        m_next = end + 1;
      }
      ++m_line_number;
      if(m_comment != '\0')
      {
        const std::size_t hash = m_line.find(m_comment);
        if(hash != std::string_view::npos)
          m_line = m_line.substr(0, hash);
      }
      m_position = 0;
      skip_blanks();
      if(m_position < m_line.size())
        return true;
    }
    m_line = std::string_view();
    m_position = 0;
    return false;
  }

  // Gets the next token of the current line; false at the end of the line.
  bool next_token(std::string_view& token)
  {
    skip_blanks();
    if(m_position >= m_line.size())
      return false;
    const std::size_t begin = m_position;
    while(m_position < m_line.size() && !is_blank(m_line[m_position]))
      ++m_position;
    token = m_line.substr(begin, m_position - begin);
    return true;
  }

  // Gets the next token, on this line or a later one (formats whose line
  // breaks carry no meaning); false at the end of the text.
  bool next_token_anywhere(std::string_view& token)
  {
    while(!next_token(token))
      if(!next_line())
        return false;
    return true;
  }

  // Whether the current line holds another token.
  bool line_has_more()
  {
    skip_blanks();
    return m_position < m_line.size();
  }

  // The number of the current line, from 1 (0 before the first).
  std::size_t line_number() const { return m_line_number; }

private:
  void skip_blanks()
  {
    while(m_position < m_line.size() && is_blank(m_line[m_position]))
      ++m_position;
  }

  std::string_view m_text;
  char m_comment;
  std::string_view m_line;
  std::size_t m_next = 0, m_position = 0, m_line_number = 0;
  bool m_ended = false;
};

// A token shortened for a message: at most 40 characters, non-printable bytes as '?'.
inline std::string quoted(std::string_view token)
{
  std::string s = "'";
  for(std::size_t i = 0; i < token.size() && i < 40; ++i)
    s += (token[i] >= 0x20 && token[i] < 0x7f) ? token[i] : '?';
  if(token.size() > 40)
    s += "...";
  return s + "'";
}

// Where a reader reports the reason of a failure, and the numbers it is given.
class Diagnostic
{
public:
  explicit Diagnostic(std::string* message = nullptr) : m_message(message) {}

  // Records `what` (when a message is wanted) and returns `code`.
  Error_code fail(Error_code code, const std::string& what) const
  {
    if(m_message != nullptr)
      *m_message = what;
    return code;
  }

  // As fail(), with the line of `reader` in front.
  Error_code fail_at(const Text_reader& reader, Error_code code, const std::string& what) const
  {
    return fail(code, "line " + std::to_string(reader.line_number()) + ": " + what);
  }

  bool wanted() const { return m_message != nullptr; }

private:
  std::string* m_message;
};

// Maps the status of a read to an error code, with a message (after `context`).
inline Error_code read_error(Read_status status, std::size_t limit, const Diagnostic& diagnostic,
                             const std::string& context)
{
  switch(status)
  {
    case Read_status::OK: return Error_code::SUCCESS;
    case Read_status::MISSING: return diagnostic.fail(Error_code::CANNOT_OPEN_FILE, context + "does not exist");
    case Read_status::DIRECTORY: return diagnostic.fail(Error_code::CANNOT_OPEN_FILE, context + "is a directory");
    case Read_status::CANNOT_OPEN: return diagnostic.fail(Error_code::CANNOT_OPEN_FILE, context + "cannot be read");
    case Read_status::TOO_LARGE:
      return diagnostic.fail(Error_code::FILE_TOO_LARGE,
                             context + "larger than the size limit of " + std::to_string(limit) + " bytes");
    case Read_status::BINARY: return diagnostic.fail(Error_code::MALFORMED_FILE, context + "binary data (a NUL byte) in a text format");
  }
  return Error_code::MALFORMED_FILE;
}

// The size limit and the message of the named parameters `np` of a reader,
// and the reading of its text input (a file name or a stream) under them.
template <typename NamedParameters>
std::size_t maximum_file_size(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, Polyvector_fields::internal_np::maximum_file_size), default_maximum_file_size);
}

template <typename NamedParameters>
Diagnostic diagnostic(const NamedParameters& np)
{
  return Diagnostic(CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, Polyvector_fields::internal_np::error_message), static_cast<std::string*>(nullptr)));
}

template <typename NamedParameters>
Error_code read_text(const std::string& filename, std::string& text, const NamedParameters& np,
                     const std::string& context = std::string())
{
  const std::size_t limit = maximum_file_size(np);
  return read_error(read_file_bounded(filename, limit, true, text), limit, diagnostic(np), context);
}

template <typename NamedParameters>
Error_code read_text(std::istream& is, std::string& text, const NamedParameters& np,
                     const std::string& context = std::string())
{
  const std::size_t limit = maximum_file_size(np);
  return read_error(read_bounded(is, limit, true, text), limit, diagnostic(np), context);
}

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_TEXT_PARSING_H
