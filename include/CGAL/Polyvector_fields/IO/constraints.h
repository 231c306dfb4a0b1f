// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_CONSTRAINTS_H
#define CGAL_POLYVECTOR_FIELDS_IO_CONSTRAINTS_H

/// \file IO/constraints.h
/// Reading and writing face constraints: a plain text format, and libigl's
/// `b.dmat` / `bc.dmat` pairs.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Face_constraint.h>
#include <CGAL/Polyvector_fields/IO/internal/atomic_file.h>
#include <CGAL/Polyvector_fields/IO/internal/mesh_indices.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <istream>
#include <limits>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {

namespace internal {

template <typename TriangleMesh, typename NamedParameters>
using Constraint_list =
  std::vector<Face_constraint<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                              typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type::Vector_3> >;

// Maps the status of a coordinate token to an error code.
inline Error_code coordinate_error(Token_status status)
{
  switch(status)
  {
    case Token_status::OK: return Error_code::SUCCESS;
    case Token_status::NON_FINITE: return Error_code::NON_FINITE_VALUE;
    default: return Error_code::MALFORMED_FILE;
  }
}

template <typename TriangleMesh, typename NamedParameters>
Error_code read_constraints_from_text(std::string_view text, const TriangleMesh& tm,
                                      Constraint_list<TriangleMesh, NamedParameters>& out,
                                      const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
  typedef typename Constraint_list<TriangleMesh, NamedParameters>::value_type Constraint;

  const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const auto construct_vector = gt.construct_vector_3_object();
  const auto faces = face_list(tm);
  std::vector<bool> constrained(faces.size(), false);
  Constraint_list<TriangleMesh, NamedParameters> result;

  Line_reader lines(text);
  std::vector<std::string_view> tokens;
  while(next_nonblank_line(lines, tokens, '#'))
  {
    long long id = 0;
    const Token_status id_status = parse_integer(tokens[0], id);
    if(id_status == Token_status::MALFORMED)
      return Error_code::MALFORMED_FILE;
    if(id_status == Token_status::OUT_OF_RANGE || id < 0 ||
       static_cast<unsigned long long>(id) >= faces.size())
      return Error_code::INVALID_FACE;

    const std::size_t number_count = tokens.size() - 1;
    std::vector<double> numbers(number_count);
    for(std::size_t i = 0; i < number_count; ++i)
    {
      const Error_code code = coordinate_error(parse_double(tokens[i + 1], numbers[i]));
      if(code != Error_code::SUCCESS)
        return code;
    }
    if(number_count % 3 != 0)
      return Error_code::MALFORMED_FILE;
    if(number_count == 0)
      return Error_code::EMPTY_CONSTRAINT;
    if(constrained[std::size_t(id)])
      return Error_code::DUPLICATE_CONSTRAINT;
    constrained[std::size_t(id)] = true;

    Constraint constraint;
    constraint.face = faces[std::size_t(id)];
    for(std::size_t i = 0; i < number_count; i += 3)
      constraint.vectors.push_back(construct_vector(numbers[i], numbers[i + 1], numbers[i + 2]));
    result.push_back(std::move(constraint));
  }
  out = std::move(result);
  return Error_code::SUCCESS;
}

template <typename TriangleMesh, typename ConstraintRange>
Error_code constraints_to_string(const TriangleMesh& tm, const ConstraintRange& constraints, std::string& out)
{
  const auto faces = face_list(tm);
  const auto face_index = make_index(faces);
  std::vector<bool> constrained(faces.size(), false);
  std::string text = "# face_id, then x y z of each constraint vector (world coordinates)\n";
  for(const auto& constraint : constraints)
  {
    std::size_t id = 0;
    if(!face_index.find(constraint.face, id))
      return Error_code::INVALID_FACE;
    if(constrained[id])
      return Error_code::DUPLICATE_CONSTRAINT;
    constrained[id] = true;
    if(constraint.vectors.empty())
      return Error_code::EMPTY_CONSTRAINT;
    append_integer(text, id);
    for(const auto& u : constraint.vectors)
    {
      const double xyz[3] = { CGAL::to_double(u.x()), CGAL::to_double(u.y()), CGAL::to_double(u.z()) };
      for(double c : xyz)
      {
        if(!std::isfinite(c))
          return Error_code::NON_FINITE_VALUE;
        text += ' ';
        append_double(text, c);
      }
    }
    text += '\n';
  }
  out = std::move(text);
  return Error_code::SUCCESS;
}

// Reads an ASCII libigl .dmat matrix: `cols rows`, then rows*cols numbers in
// column-major order, nothing after. A binary .dmat (whose first line is
// `0 0`, followed by the real header and raw bytes) gives MALFORMED_FILE.
inline Error_code parse_dmat(std::string_view text, std::size_t& cols, std::size_t& rows,
                             std::vector<double>& values)
{
  Token_reader tokens(text);
  std::string_view token;
  std::size_t c = 0, r = 0;
  if(!tokens.next(token) || parse_integer(token, c) != Token_status::OK ||
     !tokens.next(token) || parse_integer(token, r) != Token_status::OK)
    return Error_code::MALFORMED_FILE;
  if(c != 0 && r > (std::numeric_limits<std::size_t>::max)() / c)
    return Error_code::MALFORMED_FILE;
  const std::size_t count = c * r;
  std::vector<double> result;
  result.reserve((std::min)(count, text.size() / 2 + 1));  // each value takes at least two characters
  for(std::size_t i = 0; i < count; ++i)
  {
    double value = 0;
    if(!tokens.next(token))
      return Error_code::MALFORMED_FILE;  // short file
    const Error_code code = coordinate_error(parse_double(token, value));
    if(code != Error_code::SUCCESS)
      return code;
    result.push_back(value);
  }
  if(tokens.next(token))
    return Error_code::MALFORMED_FILE;  // trailing data, e.g. the body of a binary .dmat
  cols = c;
  rows = r;
  values = std::move(result);
  return Error_code::SUCCESS;
}

template <typename TriangleMesh, typename NamedParameters>
Error_code read_dmat_constraints_from_text(std::string_view b_text, std::string_view bc_text,
                                           const TriangleMesh& tm,
                                           Constraint_list<TriangleMesh, NamedParameters>& out,
                                           const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
  typedef typename Constraint_list<TriangleMesh, NamedParameters>::value_type Constraint;

  const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const auto construct_vector = gt.construct_vector_3_object();

  std::size_t b_cols = 0, b_rows = 0, bc_cols = 0, bc_rows = 0;
  std::vector<double> b, bc;
  Error_code code = parse_dmat(b_text, b_cols, b_rows, b);
  if(code == Error_code::NON_FINITE_VALUE)
    return Error_code::MALFORMED_FILE;  // a face id must be an integer
  if(code != Error_code::SUCCESS)
    return code;
  code = parse_dmat(bc_text, bc_cols, bc_rows, bc);
  if(code != Error_code::SUCCESS)
    return code;
  if(b_cols != 1 || bc_rows != b_rows || bc_cols % 3 != 0)
    return Error_code::MALFORMED_FILE;
  if(b_rows > 0 && bc_cols == 0)
    return Error_code::EMPTY_CONSTRAINT;

  const auto faces = face_list(tm);
  std::vector<bool> constrained(faces.size(), false);
  Constraint_list<TriangleMesh, NamedParameters> result;
  result.reserve(b_rows);
  for(std::size_t row = 0; row < b_rows; ++row)
  {
    const double id = b[row];
    if(id != std::floor(id))
      return Error_code::MALFORMED_FILE;
    if(id < 0 || !(id < double(faces.size())))
      return Error_code::INVALID_FACE;
    const std::size_t f = std::size_t(id);
    if(constrained[f])
      return Error_code::DUPLICATE_CONSTRAINT;
    constrained[f] = true;

    Constraint constraint;
    constraint.face = faces[f];
    for(std::size_t col = 0; col < bc_cols; col += 3)
      constraint.vectors.push_back(construct_vector(bc[col * bc_rows + row],
                                                    bc[(col + 1) * bc_rows + row],
                                                    bc[(col + 2) * bc_rows + row]));
    result.push_back(std::move(constraint));
  }
  out = std::move(result);
  return Error_code::SUCCESS;
}

} // namespace internal

/// \ingroup PkgPolyvectorFieldsIO
///
/// reads face constraints in the text format of this package from `is` (read
/// to its end).
///
/// Each constrained face takes one line: its id (0-based position in
/// `faces(tm)`, written as an integer), then `3k` numbers, the world
/// coordinates `x y z` of its `k >= 1` vectors. A `#` starts a comment that
/// runs to the end of the line, also after data; blank lines are ignored.
/// Numbers are read in the "C" locale whatever the locale of `is`. For example:
/// \code
/// # face   u (x y z)          v (x y z)
/// 12       1 0 0              0 1 0
/// 40       0.5 0.5 0          # a partial constraint: one vector
/// \endcode
///
/// `out` is replaced by the constraints in file order; they are hard
/// (infinite weight). The number of vectors relative to the degree, and zero
/// vectors, are checked by the design functions, not here. On failure `out`
/// is left untouched; the first problem in file order is reported.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param is the input stream
/// \param tm the mesh
/// \param out receives the constraints: a `std::vector<Face_constraint<face_descriptor, GT::Vector_3> >`,
///        `GT` being the geometric traits (see `geom_traits`)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class; its `Vector_3` is the vector type of `out`}
///     \cgalParamType{a class model of `Kernel`}
///     \cgalParamDefault{a \cgal Kernel deduced from the point type of `tm`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns
/// - `Error_code::CANNOT_OPEN_FILE` if `is` is not readable;
/// - `Error_code::MALFORMED_FILE` if a face id is not an integer, a number is
///   not a decimal number, or the count of numbers on a line is not a multiple of 3;
/// - `Error_code::INVALID_FACE` if a face id is negative or not smaller than the number of faces;
/// - `Error_code::NON_FINITE_VALUE` if a coordinate is NaN or infinite;
/// - `Error_code::EMPTY_CONSTRAINT` if a line holds a face id and no vector;
/// - `Error_code::DUPLICATE_CONSTRAINT` if a face appears on two lines;
/// - `Error_code::SUCCESS` otherwise.
///
/// \sa `write_constraints()`, `read_dmat_constraints()`
template <typename TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code read_constraints(std::istream& is, const TriangleMesh& tm,
                            internal::Constraint_list<TriangleMesh, CGAL_NP_CLASS>& out,
                            const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string text;
  if(!internal::read_whole_stream(is, text))
    return Error_code::CANNOT_OPEN_FILE;
  return internal::read_constraints_from_text(text, tm, out, np);
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// reads the constraint file `filename`; see the stream overload.
///
/// \returns the codes of the stream overload; `Error_code::CANNOT_OPEN_FILE` if
///          the file cannot be opened.
template <typename TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code read_constraints(const std::string& filename, const TriangleMesh& tm,
                            internal::Constraint_list<TriangleMesh, CGAL_NP_CLASS>& out,
                            const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string text;
  if(!internal::read_whole_file(filename, text))
    return Error_code::CANNOT_OPEN_FILE;
  return internal::read_constraints_from_text(text, tm, out, np);
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes face constraints to `os` in the text format read by `read_constraints()`.
///
/// A comment line comes first, then one line per constraint, in the order of
/// the range. Coordinates are converted to `double` and written with the
/// shortest text that reads back exactly. Weights are not stored: constraints
/// read back are hard. Nothing is written unless every constraint is valid.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam ConstraintRange a range of
///         `Face_constraint<boost::graph_traits<TriangleMesh>::%face_descriptor, Vector_3>`,
///         where `Vector_3` has `x()`, `y()` and `z()` convertible by `CGAL::to_double()`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param os the output stream
/// \param tm the mesh
/// \param constraints the constraints
/// \param np an optional sequence of named parameters; none is read at present
///
/// \returns
/// - `Error_code::INVALID_FACE` if a constraint names a face that is not in `tm`;
/// - `Error_code::DUPLICATE_CONSTRAINT` if a face is constrained twice;
/// - `Error_code::EMPTY_CONSTRAINT` if a constraint has no vector;
/// - `Error_code::NON_FINITE_VALUE` if a coordinate is NaN or infinite;
/// - `Error_code::CANNOT_OPEN_FILE` if `os` is not writable or writing fails;
/// - `Error_code::SUCCESS` otherwise.
///
/// \sa `read_constraints()`
template <typename TriangleMesh, typename ConstraintRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code write_constraints(std::ostream& os, const TriangleMesh& tm, const ConstraintRange& constraints,
                             const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  CGAL_USE(np);
  std::string text;
  const Error_code code = internal::constraints_to_string(tm, constraints, text);
  if(code != Error_code::SUCCESS)
    return code;
  return internal::write_to_stream(os, text);
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// writes face constraints to the file `filename`; see the stream overload.
///
/// The file is written to a temporary file in the same directory, renamed to
/// `filename` once complete: on failure, `filename` is left as it was and no
/// temporary file remains.
///
/// \returns the codes of the stream overload; `Error_code::CANNOT_OPEN_FILE` if
///          the file cannot be created, written or renamed.
template <typename TriangleMesh, typename ConstraintRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code write_constraints(const std::string& filename, const TriangleMesh& tm,
                             const ConstraintRange& constraints,
                             const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  CGAL_USE(np);
  std::string text;
  const Error_code code = internal::constraints_to_string(tm, constraints, text);
  if(code != Error_code::SUCCESS)
    return code;
  return internal::write_file_atomically(filename, text);
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// reads face constraints from a pair of ASCII `.dmat` matrices as used by
/// libigl: `b` lists the constrained faces and `bc` their vectors.
///
/// An ASCII `.dmat` holds `cols rows`, then the `rows * cols` values in
/// column-major order. `b` has one column of face ids (0-based positions in
/// `faces(tm)`, stored as numbers with integral values); `bc` has as many rows
/// as `b` and `3k` columns: row `i` gives the world coordinates `x y z` of the
/// `k` vectors of face `b(i)`. Binary `.dmat` files are not supported.
///
/// `out` is replaced by the constraints in row order; they are hard (infinite
/// weight). On failure `out` is left untouched.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param b the stream of the face-id matrix (read to its end)
/// \param bc the stream of the vector matrix (read to its end)
/// \param tm the mesh
/// \param out receives the constraints: a `std::vector<Face_constraint<face_descriptor, GT::Vector_3> >`,
///        `GT` being the geometric traits (see `geom_traits`)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class; its `Vector_3` is the vector type of `out`}
///     \cgalParamType{a class model of `Kernel`}
///     \cgalParamDefault{a \cgal Kernel deduced from the point type of `tm`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns
/// - `Error_code::CANNOT_OPEN_FILE` if a stream is not readable;
/// - `Error_code::MALFORMED_FILE` if a header is not two non-negative integers, a
///   file is short or has trailing data (as a binary `.dmat` has), a value is
///   not a decimal number, `b` has other than one column, a face id is not an
///   integer, the row counts differ, or the column count of `bc` is not a multiple of 3;
/// - `Error_code::EMPTY_CONSTRAINT` if `b` has rows and `bc` has no column;
/// - `Error_code::INVALID_FACE` if a face id is negative or not smaller than the number of faces;
/// - `Error_code::DUPLICATE_CONSTRAINT` if a face id appears twice;
/// - `Error_code::NON_FINITE_VALUE` if a value of `bc` is NaN or infinite;
/// - `Error_code::SUCCESS` otherwise.
///
/// \sa `read_constraints()`
template <typename TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code read_dmat_constraints(std::istream& b, std::istream& bc, const TriangleMesh& tm,
                                 internal::Constraint_list<TriangleMesh, CGAL_NP_CLASS>& out,
                                 const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string b_text, bc_text;
  if(!internal::read_whole_stream(b, b_text) || !internal::read_whole_stream(bc, bc_text))
    return Error_code::CANNOT_OPEN_FILE;
  return internal::read_dmat_constraints_from_text(b_text, bc_text, tm, out, np);
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// reads face constraints from the `.dmat` files `b_filename` and
/// `bc_filename`; see the stream overload.
///
/// \returns the codes of the stream overload; `Error_code::CANNOT_OPEN_FILE` if
///          a file cannot be opened.
template <typename TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code read_dmat_constraints(const std::string& b_filename, const std::string& bc_filename,
                                 const TriangleMesh& tm,
                                 internal::Constraint_list<TriangleMesh, CGAL_NP_CLASS>& out,
                                 const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string b_text, bc_text;
  if(!internal::read_whole_file(b_filename, b_text) || !internal::read_whole_file(bc_filename, bc_text))
    return Error_code::CANNOT_OPEN_FILE;
  return internal::read_dmat_constraints_from_text(b_text, bc_text, tm, out, np);
}

} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_CONSTRAINTS_H
