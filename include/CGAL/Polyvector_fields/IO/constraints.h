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
#include <CGAL/Polyvector_fields/parameters.h>

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

// Reads the number `token` of a coordinate, or says why it is not one
// (`context` comes before the line number in the message).
inline Error_code read_coordinate(std::string_view token, double& value, const Text_reader& reader,
                                  const Diagnostic& diagnostic, const std::string& context = std::string())
{
  switch(parse_double(token, value))
  {
    case Token_status::OK: return Error_code::SUCCESS;
    case Token_status::NON_FINITE:
      return diagnostic.fail(Error_code::NON_FINITE_VALUE, context + "line " + std::to_string(reader.line_number()) +
                                                             ": " + quoted(token) + " is not a finite number");
    default:
      return diagnostic.fail(Error_code::MALFORMED_FILE, context + "line " + std::to_string(reader.line_number()) +
                                                           ": " + quoted(token) + " is not a number");
  }
}

// Reads a face id `token` in 0..F-1, or says why it is not one.
inline Error_code read_face_id(std::string_view token, std::size_t F, std::size_t& id, const Text_reader& reader,
                               const Diagnostic& diagnostic)
{
  long long value = 0;
  const Token_status status = parse_integer(token, value);
  if(status == Token_status::MALFORMED)
    return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE, "face id " + quoted(token) + " is not an integer");
  if(status == Token_status::OUT_OF_RANGE || value < 0 || static_cast<unsigned long long>(value) >= F)
    return diagnostic.fail_at(reader, Error_code::INVALID_FACE,
                              "face id " + quoted(token) + " is not in 0.." + std::to_string(F == 0 ? 0 : F - 1) +
                              " (the mesh has " + std::to_string(F) + " faces)");
  id = std::size_t(value);
  return Error_code::SUCCESS;
}

// Reads constraints on face ids 0..F-1; `construct` makes a vector from x, y, z.
template <typename Vector_3, typename ConstructVector, typename NamedParameters>
Error_code read_id_constraints_from_text(std::string_view text, std::size_t F, ConstructVector construct,
                                         std::vector<Face_constraint<std::size_t, Vector_3> >& out,
                                         const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Diagnostic diagnostic = internal::diagnostic(np);
  // With an expected degree, a line may not hold more than N vectors: it is
  // refused at the first number too many.
  const std::size_t N = choose_parameter(get_parameter(np, Polyvector_fields::internal_np::expected_degree), std::size_t(0));
  std::vector<bool> constrained(F, false);
  std::vector<Face_constraint<std::size_t, Vector_3> > result;

  Text_reader reader(text, '#');
  std::string_view token;
  while(reader.next_line())
  {
    reader.next_token(token);
    std::size_t id = 0;
    Error_code code = read_face_id(token, F, id, reader, diagnostic);
    if(code != Error_code::SUCCESS)
      return code;
    if(constrained[id])
      return diagnostic.fail_at(reader, Error_code::DUPLICATE_CONSTRAINT,
                                "face " + std::to_string(id) + " is constrained a second time");
    constrained[id] = true;

    Face_constraint<std::size_t, Vector_3> constraint;
    constraint.face = id;
    double xyz[3];
    std::size_t count = 0;
    while(reader.next_token(token))
    {
      if(N != 0 && count == 3 * N)
        return diagnostic.fail_at(reader, Error_code::TOO_MANY_CONSTRAINT_VECTORS,
                                  "face " + std::to_string(id) + " has more than " + std::to_string(N) +
                                    " vectors (the degree is " + std::to_string(N) + ")");
      code = read_coordinate(token, xyz[count % 3], reader, diagnostic);
      if(code != Error_code::SUCCESS)
        return code;
      if(++count % 3 == 0)
        constraint.vectors.push_back(construct(xyz[0], xyz[1], xyz[2]));
    }
    if(count % 3 != 0)
      return diagnostic.fail_at(reader, Error_code::MALFORMED_FILE,
                                std::to_string(count) + " numbers after the face id: not a multiple of 3 (x y z per vector)");
    if(count == 0)
      return diagnostic.fail_at(reader, Error_code::EMPTY_CONSTRAINT, "face " + std::to_string(id) + " has no vector");
    result.push_back(std::move(constraint));
  }
  out = std::move(result);
  return Error_code::SUCCESS;
}

// The constraints on ids, on the faces of `tm` (id i: the i-th face of faces(tm)).
template <typename TriangleMesh, typename Vector_3>
std::vector<Face_constraint<typename boost::graph_traits<TriangleMesh>::face_descriptor, Vector_3> >
constraints_on_faces(const TriangleMesh& tm, std::vector<Face_constraint<std::size_t, Vector_3> >& by_id)
{
  const auto faces = face_list(tm);
  std::vector<Face_constraint<typename boost::graph_traits<TriangleMesh>::face_descriptor, Vector_3> > result;
  result.reserve(by_id.size());
  for(auto& c : by_id)
    result.push_back({ faces[c.face], std::move(c.vectors), c.weight });
  return result;
}

template <typename TriangleMesh, typename NamedParameters>
Error_code read_constraints_from_text(std::string_view text, const TriangleMesh& tm,
                                      Constraint_list<TriangleMesh, NamedParameters>& out,
                                      const NamedParameters& np)
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
  const Geom_traits gt = CGAL::parameters::choose_parameter<Geom_traits>(
    CGAL::parameters::get_parameter(np, CGAL::internal_np::geom_traits));
  std::vector<Face_constraint<std::size_t, typename Geom_traits::Vector_3> > by_id;
  const Error_code code = read_id_constraints_from_text(text, face_list(tm).size(), gt.construct_vector_3_object(), by_id, np);
  if(code == Error_code::SUCCESS)
    out = constraints_on_faces(tm, by_id);
  return code;
}

// Constructs Vector_3(x, y, z).
template <typename Vector_3>
struct Construct_from_coordinates
{
  Vector_3 operator()(double x, double y, double z) const { return Vector_3(x, y, z); }
};

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
// `name` names the matrix in messages.
inline Error_code parse_dmat(std::string_view text, const std::string& name, std::size_t& cols, std::size_t& rows,
                             std::vector<double>& values, const Diagnostic& diagnostic)
{
  Text_reader reader(text);
  std::string_view token;
  std::size_t c = 0, r = 0;
  if(!reader.next_token_anywhere(token) || parse_integer(token, c) != Token_status::OK ||
     !reader.next_token_anywhere(token) || parse_integer(token, r) != Token_status::OK)
    return diagnostic.fail(Error_code::MALFORMED_FILE, name + ": the header is not two integers 'cols rows'");
  // Each value takes at least two characters: a header announcing more is refused before any allocation.
  if(c != 0 && r > (text.size() / 2 + 1) / c)
    return diagnostic.fail(Error_code::MALFORMED_FILE, name + ": the header announces " + std::to_string(c) + " x " +
                                                         std::to_string(r) + " values, more than the file can hold");
  const std::size_t count = c * r;
  std::vector<double> result;
  result.reserve(count);
  for(std::size_t i = 0; i < count; ++i)
  {
    double value = 0;
    if(!reader.next_token_anywhere(token))
      return diagnostic.fail(Error_code::MALFORMED_FILE, name + ": the file ends after " + std::to_string(i) + " of " +
                                                           std::to_string(count) + " values");
    const Error_code code = read_coordinate(token, value, reader, diagnostic, name + ", ");
    if(code != Error_code::SUCCESS)
      return code;
    result.push_back(value);
  }
  if(reader.next_token_anywhere(token))
    return diagnostic.fail(Error_code::MALFORMED_FILE, name + ", line " + std::to_string(reader.line_number()) +
                                                         ": data after the " + std::to_string(count) + " announced values");
  cols = c;
  rows = r;
  values = std::move(result);
  return Error_code::SUCCESS;
}

template <typename Vector_3, typename ConstructVector, typename NamedParameters>
Error_code read_id_dmat_constraints_from_text(std::string_view b_text, std::string_view bc_text, std::size_t F,
                                              ConstructVector construct,
                                              std::vector<Face_constraint<std::size_t, Vector_3> >& out,
                                              const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Diagnostic diagnostic = internal::diagnostic(np);

  std::size_t b_cols = 0, b_rows = 0, bc_cols = 0, bc_rows = 0;
  std::vector<double> b, bc;
  Error_code code = parse_dmat(b_text, "b", b_cols, b_rows, b, diagnostic);
  if(code == Error_code::NON_FINITE_VALUE)
    return diagnostic.fail(Error_code::MALFORMED_FILE, "b: a face id is not finite");
  if(code != Error_code::SUCCESS)
    return code;
  code = parse_dmat(bc_text, "bc", bc_cols, bc_rows, bc, diagnostic);
  if(code != Error_code::SUCCESS)
    return code;
  if(b_cols != 1)
    return diagnostic.fail(Error_code::MALFORMED_FILE, "b has " + std::to_string(b_cols) + " columns, not 1");
  if(bc_rows != b_rows)
    return diagnostic.fail(Error_code::MALFORMED_FILE, "b has " + std::to_string(b_rows) + " rows but bc has " +
                                                         std::to_string(bc_rows));
  if(bc_cols % 3 != 0)
    return diagnostic.fail(Error_code::MALFORMED_FILE,
                           "bc has " + std::to_string(bc_cols) + " columns, not a multiple of 3 (x y z per vector)");
  if(b_rows > 0 && bc_cols == 0)
    return diagnostic.fail(Error_code::EMPTY_CONSTRAINT, "bc has no column: the constraints have no vector");
  const std::size_t N = choose_parameter(get_parameter(np, Polyvector_fields::internal_np::expected_degree), std::size_t(0));
  if(N != 0 && bc_cols / 3 > N)
    return diagnostic.fail(Error_code::TOO_MANY_CONSTRAINT_VECTORS, "bc has " + std::to_string(bc_cols / 3) +
                                                                      " vectors per face, more than the degree " +
                                                                      std::to_string(N));

  std::vector<bool> constrained(F, false);
  std::vector<Face_constraint<std::size_t, Vector_3> > result;
  result.reserve(b_rows);
  for(std::size_t row = 0; row < b_rows; ++row)
  {
    const double id = b[row];
    const std::string where = "b, row " + std::to_string(row) + ": ";
    if(id != std::floor(id))
      return diagnostic.fail(Error_code::MALFORMED_FILE, where + "face id is not an integer");
    if(id < 0 || !(id < double(F)))
      return diagnostic.fail(Error_code::INVALID_FACE, where + "face id is not in 0.." + std::to_string(F == 0 ? 0 : F - 1));
    const std::size_t f = std::size_t(id);
    if(constrained[f])
      return diagnostic.fail(Error_code::DUPLICATE_CONSTRAINT, where + "face " + std::to_string(f) + " is constrained a second time");
    constrained[f] = true;

    Face_constraint<std::size_t, Vector_3> constraint;
    constraint.face = f;
    for(std::size_t col = 0; col < bc_cols; col += 3)
      constraint.vectors.push_back(construct(bc[col * bc_rows + row], bc[(col + 1) * bc_rows + row],
                                             bc[(col + 2) * bc_rows + row]));
    result.push_back(std::move(constraint));
  }
  out = std::move(result);
  return Error_code::SUCCESS;
}

template <typename TriangleMesh, typename NamedParameters>
Error_code read_dmat_constraints_from_text(std::string_view b_text, std::string_view bc_text,
                                           const TriangleMesh& tm,
                                           Constraint_list<TriangleMesh, NamedParameters>& out,
                                           const NamedParameters& np)
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
  const Geom_traits gt = CGAL::parameters::choose_parameter<Geom_traits>(
    CGAL::parameters::get_parameter(np, CGAL::internal_np::geom_traits));
  std::vector<Face_constraint<std::size_t, typename Geom_traits::Vector_3> > by_id;
  const Error_code code = read_id_dmat_constraints_from_text(b_text, bc_text, face_list(tm).size(),
                                                             gt.construct_vector_3_object(), by_id, np);
  if(code == Error_code::SUCCESS)
    out = constraints_on_faces(tm, by_id);
  return code;
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
///   \pvfParamGeomTraits
///   \cgalParamNBegin{expected_degree}
///     \cgalParamDescription{the degree `N` of the field: a face with more than `N` vectors is refused at its first
///                           number too many (`Error_code::TOO_MANY_CONSTRAINT_VECTORS`); `0` accepts any count}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \pvfParamMaximumFileSize
///   \pvfParamErrorMessage{its place (line or row and face)}
/// \cgalNamedParamsEnd
///
/// \returns
/// - `Error_code::CANNOT_OPEN_FILE` if `is` is not readable;
/// - `Error_code::FILE_TOO_LARGE` if the input is larger than `maximum_file_size`;
/// - `Error_code::MALFORMED_FILE` if the input holds a NUL byte, a face id is not an integer, a number is
///   not a decimal number, or the count of numbers on a line is not a multiple of 3;
/// - `Error_code::TOO_MANY_CONSTRAINT_VECTORS` if a face has more than `expected_degree` vectors;
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
  const Error_code code = internal::read_text(is, text, np);
  return code != Error_code::SUCCESS ? code : internal::read_constraints_from_text(text, tm, out, np);
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
  const Error_code code = internal::read_text(filename, text, np);
  return code != Error_code::SUCCESS ? code : internal::read_constraints_from_text(text, tm, out, np);
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
///   \pvfParamGeomTraits
///   \cgalParamNBegin{expected_degree}
///     \cgalParamDescription{the degree `N` of the field: a face with more than `N` vectors is refused at its first
///                           number too many (`Error_code::TOO_MANY_CONSTRAINT_VECTORS`); `0` accepts any count}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \pvfParamMaximumFileSize
///   \pvfParamErrorMessage{its place (line or row and face)}
/// \cgalNamedParamsEnd
///
/// \returns
/// - `Error_code::CANNOT_OPEN_FILE` if a stream is not readable;
/// - `Error_code::FILE_TOO_LARGE` if an input is larger than `maximum_file_size`;
/// - `Error_code::MALFORMED_FILE` if an input holds a NUL byte, a header is not two non-negative integers, a
///   file is short or has trailing data (as a binary `.dmat` has), a value is
///   not a decimal number, `b` has other than one column, a face id is not an
///   integer, the row counts differ, or the column count of `bc` is not a multiple of 3;
/// - `Error_code::EMPTY_CONSTRAINT` if `b` has rows and `bc` has no column;
/// - `Error_code::TOO_MANY_CONSTRAINT_VECTORS` if `bc` has more than `expected_degree` vectors per row;
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
  Error_code code = internal::read_text(b, b_text, np, "b: ");
  if(code == Error_code::SUCCESS)
    code = internal::read_text(bc, bc_text, np, "bc: ");
  return code != Error_code::SUCCESS ? code : internal::read_dmat_constraints_from_text(b_text, bc_text, tm, out, np);
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
  Error_code code = internal::read_text(b_filename, b_text, np, "b: ");
  if(code == Error_code::SUCCESS)
    code = internal::read_text(bc_filename, bc_text, np, "bc: ");
  return code != Error_code::SUCCESS ? code : internal::read_dmat_constraints_from_text(b_text, bc_text, tm, out, np);
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// reads the constraint file `filename` as `read_constraints()` does, but on
/// face ids `0 .. number_of_faces-1` rather than on the faces of a mesh: for a
/// mesh that has been changed since the file was made (see
/// `read_triangle_mesh()` and `Mesh_repair_result::source_face`).
///
/// \tparam Vector_3 a vector type constructible from three `double`
///
/// \returns the codes of `read_constraints()`.
template <typename Vector_3, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code read_constraints_by_id(const std::string& filename, std::size_t number_of_faces,
                                  std::vector<Face_constraint<std::size_t, Vector_3> >& out,
                                  const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string text;
  const Error_code code = internal::read_text(filename, text, np);
  return code != Error_code::SUCCESS
           ? code
           : internal::read_id_constraints_from_text(text, number_of_faces, internal::Construct_from_coordinates<Vector_3>(),
                                                     out, np);
}

/// \ingroup PkgPolyvectorFieldsIO
///
/// reads the `.dmat` files `b_filename` and `bc_filename` as
/// `read_dmat_constraints()` does, but on face ids `0 .. number_of_faces-1`
/// (see `read_constraints_by_id()`).
///
/// \tparam Vector_3 a vector type constructible from three `double`
///
/// \returns the codes of `read_dmat_constraints()`.
template <typename Vector_3, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code read_dmat_constraints_by_id(const std::string& b_filename, const std::string& bc_filename,
                                       std::size_t number_of_faces,
                                       std::vector<Face_constraint<std::size_t, Vector_3> >& out,
                                       const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  std::string b_text, bc_text;
  Error_code code = internal::read_text(b_filename, b_text, np, "b: ");
  if(code == Error_code::SUCCESS)
    code = internal::read_text(bc_filename, bc_text, np, "bc: ");
  return code != Error_code::SUCCESS
           ? code
           : internal::read_id_dmat_constraints_from_text(b_text, bc_text, number_of_faces,
                                                          internal::Construct_from_coordinates<Vector_3>(), out, np);
}

} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_CONSTRAINTS_H
