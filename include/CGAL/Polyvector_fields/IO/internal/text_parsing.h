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
// Files are read whole into a string, cut into lines at '\n', and lines into
// tokens at blanks (space, tab, '\r', '\v', '\f'). Every token is parsed by
// hand or with <charconv>, so neither the global C locale nor the locale
// imbued in a user's stream changes what is read or written, and arbitrary
// bytes (a binary file given by mistake) only ever give MALFORMED.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
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

// Reads what is left of `is` into `text`. Returns false if the stream is not
// readable or a read error occurs.
inline bool read_whole_stream(std::istream& is, std::string& text)
{
  if(!is.good())
    return false;
  std::ostringstream buffer;
  buffer << is.rdbuf();
  if(is.bad())
    return false;
  text = buffer.str();
  return true;
}

inline bool read_whole_file(const std::string& filename, std::string& text)
{
  std::error_code ec;
  if(std::filesystem::is_directory(std::filesystem::path(filename), ec))
    return false;  // opening a directory may succeed, reading it fails
  std::ifstream in(filename, std::ios::in | std::ios::binary);
  if(!in)
    return false;
  return read_whole_stream(in, text);
}

// Walks through the lines of a text, '\n' separated, '\r' kept (it is blank).
class Line_reader
{
public:
  explicit Line_reader(std::string_view text) : m_text(text) {}

  // Gets the next line; returns false at the end of the text.
  bool next(std::string_view& line)
  {
    if(m_position > m_text.size() || (m_position == m_text.size() && m_ended))
      return false;
    const std::size_t end = m_text.find('\n', m_position);
    if(end == std::string_view::npos)
    {
      line = m_text.substr(m_position);
      m_position = m_text.size();
      m_ended = true;
    }
    else
    {
      line = m_text.substr(m_position, end - m_position);
      m_position = end + 1;
    }
    return true;
  }

private:
  std::string_view m_text;
  std::size_t m_position = 0;
  bool m_ended = false;
};

// Cuts `line` at blanks into `tokens` (cleared first).
inline void split_tokens(std::string_view line, std::vector<std::string_view>& tokens)
{
  tokens.clear();
  std::size_t i = 0;
  while(i < line.size())
  {
    while(i < line.size() && is_blank(line[i]))
      ++i;
    const std::size_t begin = i;
    while(i < line.size() && !is_blank(line[i]))
      ++i;
    if(i > begin)
      tokens.push_back(line.substr(begin, i - begin));
  }
}

// Gets the tokens of the next line that has any; returns false at the end of the text.
inline bool next_nonblank_line(Line_reader& lines, std::vector<std::string_view>& tokens,
                               char comment = '\0')
{
  std::string_view line;
  while(lines.next(line))
  {
    if(comment != '\0')
    {
      const std::size_t hash = line.find(comment);
      if(hash != std::string_view::npos)
        line = line.substr(0, hash);
    }
    split_tokens(line, tokens);
    if(!tokens.empty())
      return true;
  }
  tokens.clear();
  return false;
}

// Whitespace-separated tokens of a whole text, one at a time (for formats
// such as .dmat whose line breaks carry no meaning).
class Token_reader
{
public:
  explicit Token_reader(std::string_view text) : m_text(text) {}

  bool next(std::string_view& token)
  {
    while(m_position < m_text.size() && (is_blank(m_text[m_position]) || m_text[m_position] == '\n'))
      ++m_position;
    if(m_position == m_text.size())
      return false;
    const std::size_t begin = m_position;
    while(m_position < m_text.size() && !is_blank(m_text[m_position]) && m_text[m_position] != '\n')
      ++m_position;
    token = m_text.substr(begin, m_position - begin);
    return true;
  }

private:
  std::string_view m_text;
  std::size_t m_position = 0;
};

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_TEXT_PARSING_H
