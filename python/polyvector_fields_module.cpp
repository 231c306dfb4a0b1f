// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// polyvector_fields._core: the package's algorithms on numpy arrays, in the
// conventions of libigl's Python bindings (V float64 #V x 3, F integer #F x 3,
// results as tuples of arrays plus a dict of figures). The pure-Python package
// polyvector_fields (__init__.py) re-exports these functions and composes the
// whole meshing road (quad_remesh) from them.
//
// Every function copies its numpy input into C++ containers, then releases the
// GIL for the work (meshes are built, fields designed, maps computed without
// the interpreter), then builds the numpy output with the GIL held again.
// A failure is a C++ Failure that the module turns into polyvector_fields.Error.
//
// One translation unit: it instantiates the whole road once.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Face_constraint.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/Principal_curvatures.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/compute_integer_grid_map.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>
#include <CGAL/Polyvector_fields/design_angle_bounded_frame_field.h>
#include <CGAL/Polyvector_fields/design_conjugate_frame_field.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/extract_quad_mesh.h>
#include <CGAL/Polyvector_fields/planarize_quad_mesh.h>
#include <CGAL/Polyvector_fields/polyvector_polynomial.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>
#include <CGAL/Polyvector_fields/refine_for_quad_size.h>
#include <CGAL/Polyvector_fields/select_curvature_constraints.h>
#include <CGAL/Polyvector_fields/select_sharp_edge_constraints.h>
#include <CGAL/Polyvector_fields/smoothness_energy.h>
#include <CGAL/Polyvector_fields/IO/html_viewer.h>
#include <CGAL/Polyvector_fields/IO/quad_mesh.h>
#include <CGAL/Polyvector_fields/IO/read_triangle_mesh.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace py = pybind11;
namespace PVF = CGAL::Polyvector_fields;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef Mesh::Face_index Face;
typedef Mesh::Halfedge_index Halfedge;
typedef Mesh::Edge_index Edge;
typedef PVF::Tangent_bundle<Mesh> Bundle;
typedef PVF::Polyvector_field<Bundle> Field;
typedef PVF::Face_constraint<Face, Vector> Constraint;
typedef std::complex<double> Complex;

// ---------------------------------------------------------------------------
// Errors
// ---------------------------------------------------------------------------

// The names of the Error_code values, in the order of the enum.
const char* const error_code_names[] = {
  "SUCCESS", "EMPTY_MESH", "NON_TRIANGLE_FACE", "DEGENERATE_FACE", "INVALID_DEGREE", "INVALID_FACE",
  "DUPLICATE_CONSTRAINT", "EMPTY_CONSTRAINT", "ZERO_CONSTRAINT_VECTOR", "NON_FINITE_VALUE",
  "TOO_MANY_CONSTRAINT_VECTORS", "INVALID_WEIGHT", "INCONSISTENT_DEGREE", "CANNOT_OPEN_FILE", "MALFORMED_FILE",
  "SOLVER_FAILURE", "INVALID_PARAMETER", "NOT_A_FRAME_FIELD", "CURVATURE_ESTIMATION_FAILED", "FILE_TOO_LARGE",
  "UNSUPPORTED_FORMAT", "DUPLICATE_FACE", "NON_MANIFOLD_MESH", "VALUE_OUT_OF_RANGE", "ZERO_FRAME",
  "NOT_AN_INTEGER_GRID_MAP", "UNREPAIRABLE_FOLD_OVER", "NON_QUAD_FACE", "DID_NOT_CONVERGE", "MAP_CHECK_FAILED",
  "NO_INTEGER_CELL", "TOO_FAR_FROM_SURFACE", "FOLDED_QUAD", "NON_DISK_CELL"
};
static_assert(sizeof(error_code_names) / sizeof(error_code_names[0]) ==
                std::size_t(PVF::Error_code::NON_DISK_CELL) + 1,
              "one name per Error_code value");

const char* code_name(PVF::Error_code code) { return error_code_names[std::size_t(code)]; }

// A refusal or a failure: `code` is the name of an Error_code value, or
// "BAD_ARRAY" for an argument that is not an array of the expected shape.
struct Failure : std::runtime_error
{
  std::string code;
  Failure(const std::string& message, std::string code_name) : std::runtime_error(message), code(std::move(code_name)) {}
};

[[noreturn]] void bad_array(const std::string& message) { throw Failure(message, "BAD_ARRAY"); }

// Throws for a code other than SUCCESS: "what: the package's message[: detail] (CODE)".
void check(PVF::Error_code code, const std::string& what, const std::string& detail = std::string())
{
  if(code == PVF::Error_code::SUCCESS)
    return;
  std::string message = what + ": " + PVF::get_error_message(code);
  if(!detail.empty())
    message += ": " + detail;
  throw Failure(message + " (" + code_name(code) + ")", code_name(code));
}

// ---------------------------------------------------------------------------
// numpy input, copied (with the GIL held) into plain C++ containers
// ---------------------------------------------------------------------------

struct Matrix_d
{
  std::size_t rows = 0, cols = 0;
  std::vector<double> data;  // row-major
  double operator()(std::size_t i, std::size_t j) const { return data[i * cols + j]; }
};

struct Matrix_i
{
  std::size_t rows = 0, cols = 0;
  std::vector<std::int64_t> data;  // row-major
  std::int64_t operator()(std::size_t i, std::size_t j) const { return data[i * cols + j]; }
};

std::string shape_text(const py::array& a)
{
  std::ostringstream s;
  s << "(";
  for(py::ssize_t d = 0; d < a.ndim(); ++d)
    s << (d ? ", " : "") << a.shape(d);
  s << (a.ndim() == 1 ? ",)" : ")");
  return s.str();
}

py::array as_array(py::handle object, const std::string& name)
{
  if(object.is_none())
    bad_array(name + ": an array is required, not None");
  py::array a = py::array::ensure(object);
  if(!a)
    bad_array(name + ": not convertible to a numpy array");
  return a;
}

// A real 2D array of `cols` columns (cols 0: any), copied in row-major order.
// With allow_nan false, NaN and infinities are refused; with it, NaN is kept (infinities still refused).
Matrix_d read_real(py::handle object, const std::string& name, std::size_t cols, bool allow_nan = false)
{
  py::array a = as_array(object, name);
  const char kind = a.dtype().kind();
  if(kind != 'f' && kind != 'i' && kind != 'u')
    bad_array(name + ": expected a real array (float64), got dtype " + std::string(py::str(a.dtype())));
  if(a.ndim() != 2 || (cols != 0 && std::size_t(a.shape(1)) != cols))
    bad_array(name + ": expected shape (n, " + (cols ? std::to_string(cols) : std::string("k")) + "), got " +
              shape_text(a));
  auto c = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  Matrix_d m;
  m.rows = std::size_t(c.shape(0));
  m.cols = std::size_t(c.shape(1));
  m.data.assign(c.data(), c.data() + m.rows * m.cols);
  for(std::size_t k = 0; k < m.data.size(); ++k)
    if(!std::isfinite(m.data[k]) && !(allow_nan && std::isnan(m.data[k])))
    {
      std::ostringstream s;
      s << name << "[" << k / m.cols << ", " << k % m.cols << "] is " << m.data[k] << ": values must be finite";
      throw Failure(s.str() + " (NON_FINITE_VALUE)", "NON_FINITE_VALUE");
    }
  return m;
}

// An integer 2D array of `cols` columns (int32, int64 or other integer types), copied in row-major
// order; with `one_d`, a 1D array is taken as one column.
Matrix_i read_integer(py::handle object, const std::string& name, std::size_t cols, bool one_d = false)
{
  py::array a = as_array(object, name);
  const char kind = a.dtype().kind();
  if(kind != 'i' && kind != 'u')
    bad_array(name + ": expected an integer array (int32 or int64), got dtype " + std::string(py::str(a.dtype())));
  if(one_d && a.ndim() == 1)
    a = a.attr("reshape")(-1, 1).cast<py::array>();
  if(a.ndim() != 2 || (cols != 0 && std::size_t(a.shape(1)) != cols))
    bad_array(name + ": expected shape (n, " + (cols ? std::to_string(cols) : std::string("k")) + ")" +
              (one_d ? " or (n,)" : "") + ", got " + shape_text(a));
  if(kind == 'u' && a.dtype().itemsize() == 8)
  {
    // uint64 values above int64's range are out of any index range anyway.
    auto u = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    for(py::ssize_t k = 0; k < u.size(); ++k)
      if(u.data()[k] > std::uint64_t((std::numeric_limits<std::int64_t>::max)()))
        bad_array(name + ": value " + std::to_string(u.data()[k]) + " is out of range");
  }
  auto c = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  Matrix_i m;
  m.rows = std::size_t(c.shape(0));
  m.cols = std::size_t(c.shape(1));
  m.data.assign(c.data(), c.data() + m.rows * m.cols);
  return m;
}

// An optional number argument (None: not given), refused with its name when it is not a number.
std::optional<double> read_number(py::handle h, const std::string& name)
{
  if(h.is_none())
    return std::nullopt;
  try
  {
    return h.cast<double>();
  }
  catch(const py::cast_error&)
  {
    throw Failure(name + ": expected a number or None (INVALID_PARAMETER)", "INVALID_PARAMETER");
  }
}

// An optional count argument (None: 0, the default), at least 1 when given.
std::size_t read_count(py::handle h, const std::string& name)
{
  if(h.is_none())
    return 0;
  long long v = 0;
  try
  {
    v = h.cast<long long>();
  }
  catch(const py::cast_error&)
  {
    throw Failure(name + ": expected an integer or None (INVALID_PARAMETER)", "INVALID_PARAMETER");
  }
  if(v < 1)
    throw Failure(name + ": " + std::to_string(v) + " is not at least 1 (INVALID_PARAMETER)", "INVALID_PARAMETER");
  return std::size_t(v);
}

// A whole-number argument (a Python or numpy integer, not a bool) in low..high,
// refused with its name and `code` otherwise (pybind11 would raise its own
// TypeError for a negative value given to a std::size_t).
std::int64_t read_whole(py::handle h, const std::string& name, std::int64_t low, std::int64_t high,
                        const std::string& code = "INVALID_PARAMETER")
{
  long long v = 0;
  bool integer = !h.is_none() && !py::isinstance<py::bool_>(h) && !PyFloat_Check(h.ptr()) && PyIndex_Check(h.ptr());
  if(integer)
  {
    try
    {
      v = h.cast<long long>();
    }
    catch(const py::cast_error&)
    {
      integer = false;  // beyond long long
      PyErr_Clear();
    }
  }
  if(!integer)
    throw Failure(name + ": expected an integer, got " + std::string(py::str(py::repr(h))) + " (" + code + ")", code);
  if(v < low || v > high)
    throw Failure(name + ": " + std::to_string(v) + " is not in " + std::to_string(low) + ".." + std::to_string(high) +
                    " (" + code + ")",
                  code);
  return std::int64_t(v);
}

// A number argument (not None, not a bool), refused with its name otherwise.
double read_real_number(py::handle h, const std::string& name)
{
  if(!h.is_none() && !py::isinstance<py::bool_>(h))
  {
    try
    {
      return h.cast<double>();
    }
    catch(const py::cast_error&)
    {
      PyErr_Clear();
    }
  }
  throw Failure(name + ": expected a number, got " + std::string(py::str(py::repr(h))) + " (INVALID_PARAMETER)",
                "INVALID_PARAMETER");
}

// A yes-or-no argument: True or False (Python's or numpy's bool), refused with its name otherwise.
bool read_flag(py::handle h, const std::string& name)
{
  if(py::isinstance<py::bool_>(h) || py::isinstance(h, py::module_::import("numpy").attr("bool_")))
    return h.cast<bool>();
  throw Failure(name + ": expected True or False, got " + std::string(py::str(py::repr(h))) + " (INVALID_PARAMETER)",
                "INVALID_PARAMETER");
}

// A text argument, refused with its name when it is not a str.
std::string read_text(py::handle h, const std::string& name)
{
  if(py::isinstance<py::str>(h))
    return h.cast<std::string>();
  throw Failure(name + ": expected a string, got " + std::string(py::str(py::repr(h))) + " (INVALID_PARAMETER)",
                "INVALID_PARAMETER");
}

// Checks that every entry of `m` is an index into 0..n-1; with `padded`, a row
// may end with -1 entries (a polygon of fewer corners than the array has columns).
void check_indices(const Matrix_i& m, std::size_t n, const std::string& name, const std::string& of_what,
                   bool padded = false)
{
  for(std::size_t k = 0; k < m.data.size(); ++k)
    if(padded && m.data[k] == -1)
    {
      const std::size_t row = k / m.cols, column = k % m.cols;
      if(column < 3)
        bad_array(name + " row " + std::to_string(row) + ": a polygon has at least 3 corners (-1 in column " +
                  std::to_string(column) + ")");
      if(column + 1 < m.cols && m.data[k + 1] != -1)
        bad_array(name + " row " + std::to_string(row) + ": -1 pads the end of a row only (column " +
                  std::to_string(column) + " is -1, column " + std::to_string(column + 1) + " is not)");
    }
    else if(m.data[k] < 0 || std::uint64_t(m.data[k]) >= n)
      bad_array(name + "[" + std::to_string(k / m.cols) + ", " + std::to_string(k % m.cols) + "] = " +
                std::to_string(m.data[k]) + " is not " + of_what + " (0.." + std::to_string(n) + "-1)");
}

// The mesh arrays V (#V x 3) and F (#F x k), checked.
struct Mesh_arrays
{
  Matrix_d V;
  Matrix_i F;
};

// corners 0: polygons, at least 3 columns, rows padded at their end with -1.
Mesh_arrays read_mesh_arrays(py::handle V, py::handle F, std::size_t corners = 3, const std::string& v_name = "V",
                             const std::string& f_name = "F")
{
  Mesh_arrays m;
  m.V = read_real(V, v_name, 3);
  m.F = read_integer(F, f_name, corners);
  if(corners == 0 && m.F.cols < 3)
    bad_array(f_name + ": expected shape (n, k) with k >= 3 (polygons), got (" + std::to_string(m.F.rows) + ", " +
              std::to_string(m.F.cols) + ")");
  if(m.F.rows == 0)
    throw Failure(f_name + ": the mesh has no face (EMPTY_MESH)", "EMPTY_MESH");
  check_indices(m.F, m.V.rows, f_name, "a vertex of " + v_name, corners == 0);
  return m;
}

// Builds a Surface_mesh whose vertex i and face i are V's row i and F's row i.
// Without the GIL.
void build_mesh(const Mesh_arrays& a, Mesh& tm, const std::string& f_name = "F")
{
  tm.clear();
  tm.reserve(Mesh::size_type(a.V.rows), Mesh::size_type(a.F.rows * 3), Mesh::size_type(a.F.rows));
  for(std::size_t i = 0; i < a.V.rows; ++i)
    tm.add_vertex(Point(a.V(i, 0), a.V(i, 1), a.V(i, 2)));
  std::vector<Vertex> face;
  for(std::size_t f = 0; f < a.F.rows; ++f)
  {
    std::size_t corners = a.F.cols;
    while(a.F(f, corners - 1) == -1)  // the padding of a polygon row (checked: 3 corners at least)
      --corners;
    face.resize(corners);
    for(std::size_t k = 0; k < corners; ++k)
    {
      face[k] = Vertex(Mesh::size_type(a.F(f, k)));
      for(std::size_t j = 0; j < k; ++j)
        if(face[j] == face[k])
          throw Failure(f_name + " row " + std::to_string(f) + ": face repeats vertex " + std::to_string(a.F(f, k)) +
                          " (DEGENERATE_FACE)",
                        "DEGENERATE_FACE");
    }
    if(tm.add_face(face) == Mesh::null_face())
      throw Failure(f_name + " row " + std::to_string(f) +
                      ": the face makes the mesh non-manifold (an edge already has two faces, or its orientation "
                      "disagrees with a neighbour's, or a vertex's faces would not form one fan) (NON_MANIFOLD_MESH)",
                    "NON_MANIFOLD_MESH");
  }
}

// The corner k of face f is the halfedge of f whose target is F(f, k).
std::array<Halfedge, 3> corner_halfedges(const Mesh& tm, Face f)
{
  std::array<Halfedge, 3> h;
  const Halfedge first = tm.halfedge(f);
  h[0] = first;
  h[1] = tm.next(first);
  h[2] = tm.next(h[1]);
  return h;
}

// Position (0..2) of the corner of F(f, .) that is the target of h.
std::size_t corner_of(const Mesh& tm, const Matrix_i& F, std::size_t f, Halfedge h)
{
  const std::int64_t v = std::int64_t(std::size_t(tm.target(h)));
  for(std::size_t k = 0; k < 3; ++k)
    if(F(f, k) == v)
      return k;
  throw std::logic_error("a halfedge of a face whose target is not one of its vertices");
}

// Calls visit(h, bundle_slot, array_slot) for every corner of every face: h
// the halfedge of the corner, bundle_slot = 3 i + j for the j-th corner of the
// bundle's i-th face (the order of the library's per-corner results),
// array_slot = 3 f + k for the corner F(f, k) of face f (row f of the arrays).
template <typename Visit>
void for_each_corner(const Bundle& bundle, const Mesh& tm, const Matrix_i& F, const Visit& visit)
{
  for(std::size_t i = 0; i < bundle.number_of_faces(); ++i)
  {
    const Face f = bundle.face(i);
    const std::size_t row = std::size_t(f);
    const auto corners = corner_halfedges(tm, f);
    for(std::size_t j = 0; j < 3; ++j)
      visit(corners[j], 3 * i + j, 3 * row + corner_of(tm, F, row, corners[j]));
  }
}

// The bundle of tm, checked.
void check_bundle(const Bundle& bundle, const std::string& f_name = "F")
{
  if(bundle.status() != PVF::Error_code::SUCCESS)
    check(bundle.status(), "mesh", "face " + std::to_string(bundle.first_invalid_face()) + " of " + f_name);
}

// ---------------------------------------------------------------------------
// numpy output
// ---------------------------------------------------------------------------

py::array_t<double> to_numpy(const std::vector<double>& data, std::size_t rows, std::size_t cols)
{
  py::array_t<double> a({ py::ssize_t(rows), py::ssize_t(cols) });
  std::copy(data.begin(), data.end(), a.mutable_data());
  return a;
}

py::array_t<std::int64_t> to_numpy(const std::vector<std::int64_t>& data, std::size_t rows, std::size_t cols)
{
  py::array_t<std::int64_t> a({ py::ssize_t(rows), py::ssize_t(cols) });
  std::copy(data.begin(), data.end(), a.mutable_data());
  return a;
}

template <typename T>
py::array_t<T> to_numpy_1d(const std::vector<T>& data)
{
  py::array_t<T> a(py::ssize_t(data.size()));
  std::copy(data.begin(), data.end(), a.mutable_data());
  return a;
}

// The vertices and faces of a mesh as row-major arrays, vertices numbered
// 0..n-1 in the order of vertices(m) (removed ones skipped). The faces have
// `width` columns, the largest number of corners; rows of smaller faces end
// with -1. `index` maps a vertex descriptor to its row.
struct Mesh_rows
{
  std::vector<double> V;
  std::vector<std::int64_t> F;
  std::vector<std::int64_t> index;
  std::size_t width = 3;
  std::size_t smallest = 3;  // the fewest corners of a face
  bool padded() const { return smallest != width; }
};

Mesh_rows mesh_rows(const Mesh& m)
{
  Mesh_rows r;
  r.index.assign(m.number_of_vertices() + m.number_of_removed_vertices(), -1);
  std::int64_t n = 0;
  for(Vertex v : vertices(m))
  {
    r.index[std::size_t(v)] = n++;
    const Point& p = m.point(v);
    r.V.insert(r.V.end(), { p.x(), p.y(), p.z() });
  }
  r.width = 0;
  r.smallest = std::numeric_limits<std::size_t>::max();
  for(Face f : faces(m))
  {
    const std::size_t d = std::size_t(CGAL::degree(f, m));
    r.width = (std::max)(r.width, d);
    r.smallest = (std::min)(r.smallest, d);
  }
  if(r.width == 0)
    r.width = r.smallest = 3;
  for(Face f : faces(m))
  {
    std::size_t k = 0;
    for(Vertex v : vertices_around_face(m.halfedge(f), m))
    {
      r.F.push_back(r.index[std::size_t(v)]);
      ++k;
    }
    r.F.insert(r.F.end(), r.width - k, -1);
  }
  return r;
}

// ---------------------------------------------------------------------------
// Constraints: b (#b) and bc (#b x 3k), NaN triples at the end of a row for fewer vectors
// ---------------------------------------------------------------------------

struct Constraint_arrays
{
  std::vector<std::size_t> faces;
  std::vector<std::vector<std::array<double, 3> > > vectors;
  std::vector<double> weights;  // infinite: hard
};

Constraint_arrays read_constraints(py::handle b, py::handle bc, py::handle soft, std::size_t number_of_faces)
{
  Constraint_arrays c;
  if(b.is_none() && bc.is_none())
  {
    if(!soft.is_none())
      bad_array("soft: given without constraints (b, bc)");
    return c;
  }
  if(b.is_none() || bc.is_none())
    bad_array(std::string(b.is_none() ? "b" : "bc") + ": b and bc go together (both or none)");
  const Matrix_i B = read_integer(b, "b", 1, true);
  const Matrix_d BC = read_real(bc, "bc", 0, true);
  if(BC.rows != B.rows)
    bad_array("bc: has " + std::to_string(BC.rows) + " rows, b has " + std::to_string(B.rows));
  if(BC.cols == 0 || BC.cols % 3 != 0)
    bad_array("bc: expected 3k columns (k vectors x, y, z per constrained face), got " + std::to_string(BC.cols));
  check_indices(B, number_of_faces, "b", "a face of F");
  std::vector<double> weights(B.rows, std::numeric_limits<double>::infinity());
  if(!soft.is_none())
  {
    if(py::isinstance<py::float_>(soft) || py::isinstance<py::int_>(soft))
      weights.assign(B.rows, soft.cast<double>());
    else
    {
      py::array w = as_array(soft, "soft");
      if(w.ndim() != 1 || std::size_t(w.shape(0)) != B.rows)
        bad_array("soft: expected a number or shape (" + std::to_string(B.rows) + ",) (one weight per row of b), got " +
                  shape_text(w));
      auto wd = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(w);
      weights.assign(wd.data(), wd.data() + B.rows);
    }
    for(std::size_t i = 0; i < weights.size(); ++i)
      if(!(weights[i] >= 1e-8 && weights[i] <= 1e8))
        throw Failure("soft[" + std::to_string(i) + "] = " + std::to_string(weights[i]) +
                        ": a soft weight must be in [1e-8, 1e8] (INVALID_WEIGHT)",
                      "INVALID_WEIGHT");
  }
  for(std::size_t i = 0; i < B.rows; ++i)
  {
    std::vector<std::array<double, 3> > vectors;
    bool ended = false;
    for(std::size_t k = 0; k < BC.cols / 3; ++k)
    {
      const double x = BC(i, 3 * k), y = BC(i, 3 * k + 1), z = BC(i, 3 * k + 2);
      const int nans = int(std::isnan(x)) + int(std::isnan(y)) + int(std::isnan(z));
      if(nans == 3)
      {
        ended = true;
        continue;
      }
      if(nans != 0 || ended)
        throw Failure("bc row " + std::to_string(i) + ", vector " + std::to_string(k) +
                        ": NaN is allowed only as whole trailing triples (fewer vectors on that face) (NON_FINITE_VALUE)",
                      "NON_FINITE_VALUE");
      vectors.push_back({ x, y, z });
    }
    if(vectors.empty())
      throw Failure("bc row " + std::to_string(i) + ": no vector (all NaN) (EMPTY_CONSTRAINT)", "EMPTY_CONSTRAINT");
    c.faces.push_back(std::size_t(B(i, 0)));
    c.vectors.push_back(vectors);
    c.weights.push_back(weights[i]);
  }
  return c;
}

std::vector<Constraint> to_constraints(const Constraint_arrays& a)
{
  std::vector<Constraint> out;
  for(std::size_t i = 0; i < a.faces.size(); ++i)
  {
    Constraint c;
    c.face = Face(Mesh::size_type(a.faces[i]));
    for(const auto& v : a.vectors[i])
      c.vectors.push_back(Vector(v[0], v[1], v[2]));
    c.weight = a.weights[i];
    out.push_back(c);
  }
  return out;
}

PVF::Smoothness_weights read_weights(const std::string& s)
{
  if(s == "uniform")
    return PVF::Smoothness_weights::UNIFORM;
  if(s == "harmonic")
    return PVF::Smoothness_weights::HARMONIC;
  throw Failure("smoothness_weights: '" + s + "' is neither 'uniform' nor 'harmonic' (INVALID_PARAMETER)",
                "INVALID_PARAMETER");
}

// ---------------------------------------------------------------------------
// The field of a run: designed, or made from roots
// ---------------------------------------------------------------------------

struct Design
{
  std::size_t full = 0, partial = 0, soft = 0;
  PVF::Design_statistics statistics;
};

// Designs the field from the constraints, as the command-line program does.
void design(const Bundle& bundle, const std::vector<Constraint>& constraints, std::size_t N, bool sign_symmetric,
            PVF::Smoothness_weights weights, Field& field, Design& d)
{
  PVF::Default_sparse_solver solver;
  PVF::Polyvector_field_designer<Mesh> designer(
    bundle, N,
    PVF::parameters::sign_symmetric(sign_symmetric, PVF::parameters::smoothness_weights(
                                                      weights, CGAL::parameters::sparse_linear_solver(solver))));
  check(designer.status(), "degree", "N = " + std::to_string(N) + (sign_symmetric ? ", sign-symmetric" : ""));
  const std::size_t full_size = sign_symmetric ? N / 2 : N;
  for(std::size_t i = 0; i < constraints.size(); ++i)
  {
    const PVF::Error_code code = designer.add_constraint(constraints[i]);
    check(code, "constraint " + std::to_string(i) + " (face " + std::to_string(std::size_t(constraints[i].face)) + ")");
    (constraints[i].vectors.size() == full_size ? d.full : d.partial) += 1;
    if(std::isfinite(constraints[i].weight))
      ++d.soft;
  }
  check(designer.solve(field), "design");
  d.statistics = designer.statistics();
}

// The world roots of the field, #F x 3N, row f = face f.
std::vector<double> world_roots(const Mesh& tm, const Field& field)
{
  auto roots = const_cast<Mesh&>(tm).add_property_map<Face, std::vector<Vector> >("f:pvf_py_roots").first;
  check(PVF::compute_field_roots(field, roots), "roots");
  const std::size_t N = field.degree();
  std::vector<double> out(num_faces(tm) * 3 * N);
  for(Face f : faces(tm))
    for(std::size_t k = 0; k < N; ++k)
    {
      const Vector& v = roots[f][k];
      double* row = out.data() + std::size_t(f) * 3 * N + 3 * k;
      row[0] = v.x();
      row[1] = v.y();
      row[2] = v.z();
    }
  const_cast<Mesh&>(tm).remove_property_map(roots);
  return out;
}

// Sets the coefficients of `field` from world roots X (#F x 3N). With sign
// symmetry, the first N/2 vectors of each face stand for the pairs {u, -u}.
void field_from_roots(const Bundle& bundle, const Matrix_d& X, Field& field)
{
  const std::size_t N = field.degree();
  std::vector<Complex>& c = field.coefficients();
  const std::size_t given = field.is_sign_symmetric() ? N / 2 : N;
  std::vector<Complex> z(given);
  for(std::size_t i = 0; i < bundle.number_of_faces(); ++i)
  {
    const std::size_t f = std::size_t(bundle.face(i));
    const PVF::Face_frame& frame = bundle.frame(i);
    for(std::size_t k = 0; k < given; ++k)
    {
      z[k] = frame.to_complex(X(f, 3 * k), X(f, 3 * k + 1), X(f, 3 * k + 2));
      if(z[k] == Complex(0))
        throw Failure("X row " + std::to_string(f) + ": vector " + std::to_string(k) +
                        " is zero in the face plane (ZERO_FRAME)",
                      "ZERO_FRAME");
    }
    const std::vector<Complex> coefficients =
      field.is_sign_symmetric() ? PVF::sign_symmetric_polyvector_coefficients(z) : PVF::polyvector_coefficients(z);
    for(std::size_t m = 0; m < N; ++m)
      c[i * N + m] = coefficients[m];
  }
}

// Whether world roots X (#F x 3N) come in pairs {u, -u}: vector k + N/2 is exactly -vector k.
bool roots_are_sign_symmetric(const Matrix_d& X, std::size_t N)
{
  if(N % 2 != 0)
    return false;
  for(std::size_t f = 0; f < X.rows; ++f)
    for(std::size_t j = 0; j < 3 * N / 2; ++j)
      if(X(f, j + 3 * N / 2) != -X(f, j))
        return false;
  return true;
}

std::size_t degree_of(const Matrix_d& X, std::size_t number_of_faces, const std::string& name = "X")
{
  if(X.rows != number_of_faces)
    bad_array(name + ": expected one row per face of F (" + std::to_string(number_of_faces) + "), got " +
              std::to_string(X.rows));
  if(X.cols == 0 || X.cols % 3 != 0)
    bad_array(name + ": expected 3N columns (N vectors x, y, z per face), got " + std::to_string(X.cols));
  return X.cols / 3;
}

py::dict design_info(const Design& d, const Field& field, std::size_t components)
{
  py::dict info;
  info["degree"] = field.degree();
  info["sign_symmetric"] = field.is_sign_symmetric();
  info["full_constraints"] = d.full;
  info["partial_constraints"] = d.partial;
  info["soft_constraints"] = d.soft;
  info["components"] = components;
  info["time_connection"] = d.statistics.connection;
  info["time_assembly"] = d.statistics.assembly;
  info["time_factorization"] = d.statistics.factorization;
  info["time_solve"] = d.statistics.solve;
  return info;
}

// ---------------------------------------------------------------------------
// The bound functions
// ---------------------------------------------------------------------------

py::tuple read_triangle_mesh(const std::string& filename, py::handle repair_arg)
{
  const bool repair = read_flag(repair_arg, "repair");
  Mesh tm;
  PVF::IO::Mesh_repair_result report;
  std::vector<double> V;
  std::vector<std::int64_t> F;
  {
    py::gil_scoped_release release;
    std::string message;
    const PVF::Error_code code = PVF::IO::read_triangle_mesh(
      filename, tm, report, PVF::parameters::repair(repair, PVF::parameters::error_message(message)));
    check(code, "mesh '" + filename + "'", message);
    Mesh_rows rows = mesh_rows(tm);
    V = std::move(rows.V);
    F = std::move(rows.F);
  }
  py::dict info;
  info["file_vertices"] = report.file_vertices;
  info["file_faces"] = report.file_faces;
  info["merged_points"] = report.merged_points;
  info["duplicate_faces"] = report.duplicate_faces;
  info["reoriented_faces"] = report.reoriented_faces;
  info["split_vertices"] = report.split_vertices;
  info["triangulated_faces"] = report.triangulated_faces;
  info["degenerate_faces"] = report.degenerate_faces;
  std::vector<std::int64_t> source(report.source_face.begin(), report.source_face.end());
  info["source_face"] = to_numpy_1d(source);
  return py::make_tuple(to_numpy(V, V.size() / 3, 3), to_numpy(F, F.size() / 3, 3), info);
}

py::tuple design_field(py::handle V, py::handle F, py::handle b, py::handle bc, py::handle degree_arg,
                       py::handle sign_symmetric_arg, py::handle soft, py::handle smoothness_weights)
{
  const std::size_t degree = std::size_t(read_whole(degree_arg, "degree", 1, 32, "INVALID_DEGREE"));
  const bool sign_symmetric = read_flag(sign_symmetric_arg, "sign_symmetric");
  const Mesh_arrays a = read_mesh_arrays(V, F);
  const Constraint_arrays ca = read_constraints(b, bc, soft, a.F.rows);
  const PVF::Smoothness_weights weights = read_weights(read_text(smoothness_weights, "smoothness_weights"));
  std::vector<double> X;
  Design d;
  std::optional<Field> field;
  double energy = 0;
  std::size_t components = 0;
  {
    py::gil_scoped_release release;
    Mesh tm;
    build_mesh(a, tm);
    const Bundle bundle(tm);
    check_bundle(bundle);
    components = bundle.number_of_components();
    field.emplace(bundle, degree, sign_symmetric);
    design(bundle, to_constraints(ca), degree, sign_symmetric, weights, *field, d);
    energy = PVF::smoothness_energy(*field);
    X = world_roots(tm, *field);
  }
  py::dict info = design_info(d, *field, components);
  info["smoothness_energy"] = energy;
  return py::make_tuple(to_numpy(X, a.F.rows, 3 * degree), info);
}

py::tuple frame_field(py::handle V, py::handle F, py::handle b, py::handle bc, py::handle curvature_constraints,
                      py::handle conjugate_arg, py::handle angle_bound, py::handle soft, py::handle orthogonality_weight_arg,
                      py::handle number_of_iterations, py::handle tolerance, py::handle smoothness_weights)
{
  const bool conjugate = read_flag(conjugate_arg, "conjugate");
  const double orthogonality_weight = read_real_number(orthogonality_weight_arg, "orthogonality_weight");
  const Mesh_arrays a = read_mesh_arrays(V, F);
  const Constraint_arrays ca = read_constraints(b, bc, soft, a.F.rows);
  const PVF::Smoothness_weights weights = read_weights(read_text(smoothness_weights, "smoothness_weights"));
  const std::optional<double> fraction = read_number(curvature_constraints, "curvature_constraints");
  const std::optional<double> bound = read_number(angle_bound, "angle_bound");
  const std::size_t iterations = read_count(number_of_iterations, "number_of_iterations");
  // soft given as one number: the curvature constraints are soft with it too
  const bool soft_for_all = !soft.is_none() && (py::isinstance<py::float_>(soft) || py::isinstance<py::int_>(soft));
  const std::optional<double> tol = read_number(tolerance, "tolerance");
  if(bound && !(*bound > 0 && *bound <= 90))
    throw Failure("angle_bound: " + std::to_string(*bound) + " degrees is not in (0, 90] (INVALID_PARAMETER)",
                  "INVALID_PARAMETER");
  if(!(orthogonality_weight >= 0 && orthogonality_weight <= 1e30))
    throw Failure("orthogonality_weight: must be in [0, 1e30] (INVALID_PARAMETER)", "INVALID_PARAMETER");

  std::vector<double> X;
  Design d;
  std::optional<Field> field;
  py::dict info;
  std::size_t components = 0, curvature_faces = 0, fallback_vertices = 0;
  double energy_before = 0, energy = 0;
  std::optional<PVF::Angle_bound_result> angle_result;
  std::optional<PVF::Conjugate_field_result> conjugate_result;
  PVF::Error_code angle_code = PVF::Error_code::SUCCESS, conjugate_code = PVF::Error_code::SUCCESS;
  {
    py::gil_scoped_release release;
    Mesh tm;
    build_mesh(a, tm);
    const Bundle bundle(tm);
    check_bundle(bundle);
    components = bundle.number_of_components();
    std::vector<Constraint> constraints = to_constraints(ca);
    // The curvature, estimated once when a constraint or the conjugacy needs it.
    auto curvature = tm.add_property_map<Face, PVF::Principal_curvatures<Vector> >("f:pvf_py_curvature").first;
    bool estimated = false;
    auto estimate = [&]() {
      if(!estimated)
        check(PVF::estimate_principal_curvatures(bundle, curvature,
                                                 PVF::parameters::fallback_vertices(fallback_vertices)),
              "curvature");
      estimated = true;
    };
    if(fraction)
    {
      estimate();
      std::vector<Constraint> principal;
      check(PVF::select_curvature_constraints(bundle, curvature, principal,
                                              PVF::parameters::constrained_fraction(*fraction)),
            "curvature constraints", "curvature_constraints = " + std::to_string(*fraction) + ", a fraction in (0, 1]");
      std::set<std::size_t> constrained(ca.faces.begin(), ca.faces.end());
      const double weight = ca.weights.empty() ? std::numeric_limits<double>::infinity() : ca.weights.front();
      for(Constraint& c : principal)
        if(constrained.insert(std::size_t(c.face)).second)
        {
          if(soft_for_all)
            c.weight = weight;
          constraints.push_back(c);
          ++curvature_faces;
        }
    }
    field.emplace(bundle, 4, true);
    design(bundle, constraints, 4, true, weights, *field, d);
    PVF::Default_sparse_solver solver;
    if(bound || conjugate)
      energy_before = PVF::smoothness_energy(*field);
    if(bound)
    {
      PVF::Angle_bound_result r;
      const double t = (tol ? *tol : 0.5) * CGAL_PI / 180;
      const auto np = PVF::parameters::angle_bound(
        *bound * CGAL_PI / 180,
        PVF::parameters::tolerance(t, PVF::parameters::smoothness_weights(
                                        weights, CGAL::parameters::sparse_linear_solver(solver))));
      angle_code = iterations ? PVF::design_angle_bounded_frame_field(*field, r, np.number_of_iterations(iterations))
                              : PVF::design_angle_bounded_frame_field(*field, r, np);
      if(angle_code != PVF::Error_code::DID_NOT_CONVERGE)
        check(angle_code, "angle bound");
      angle_result = r;
    }
    if(conjugate)
    {
      estimate();
      PVF::Conjugate_field_result r;
      const PVF::Conjugacy_stopping_rule rule = PVF::Conjugacy_stopping_rule::MEAN_DEVIATION;
      const PVF::Conjugate_field_defaults defaults = PVF::conjugate_field_defaults(rule);
      namespace P = PVF::parameters;
      const auto np = P::principal_curvature_map(
        curvature,
        P::orthogonality_weight(
          orthogonality_weight,
          P::stopping_rule(rule, P::tolerance(tol ? *tol : defaults.tolerance,
                                              P::maximum_lambda(defaults.maximum_lambda,
                                                                P::smoothness_weights(
                                                                  weights, CGAL::parameters::number_of_iterations(
                                                                             iterations ? iterations : defaults.iterations)
                                                                             .sparse_linear_solver(solver)))))));
      conjugate_code = PVF::design_conjugate_frame_field(*field, r, np);
      if(conjugate_code != PVF::Error_code::DID_NOT_CONVERGE)
        check(conjugate_code, "conjugate field");
      conjugate_result = r;
    }
    energy = PVF::smoothness_energy(*field);
    X = world_roots(tm, *field);
  }
  info = design_info(d, *field, components);
  info["curvature_constraints"] = curvature_faces;
  info["curvature_fallback_vertices"] = fallback_vertices;
  info["smoothness_energy"] = energy;
  if(angle_result)
  {
    info["smoothness_energy_before"] = energy_before;
    info["angle_bound_converged"] = angle_result->converged;
    info["angle_bound_status"] = code_name(angle_code);
    info["angle_bound_iterations"] = angle_result->iterations;
    info["minimum_angle"] = angle_result->minimum_angle * 180 / CGAL_PI;
    info["minimum_free_angle"] = angle_result->minimum_free_angle * 180 / CGAL_PI;
    info["projected_faces"] = angle_result->projected_faces;
  }
  if(conjugate_result)
  {
    info["smoothness_energy_before"] = energy_before;
    info["conjugate_converged"] = conjugate_result->converged;
    info["conjugate_status"] = code_name(conjugate_code);
    info["conjugate_iterations"] = conjugate_result->iterations;
    info["conjugacy_mean_deviation"] = conjugate_result->mean_deviation;
    info["conjugacy_residual"] = conjugate_result->residual;
    info["final_lambda"] = conjugate_result->final_lambda;
  }
  return py::make_tuple(to_numpy(X, a.F.rows, 12), info);
}

// The field of roots X on the mesh: degree from X's columns, sign symmetry as asked or detected.
struct Field_input
{
  Mesh_arrays mesh;
  Matrix_d X;
  std::size_t N = 0;
  bool sign_symmetric = false;
};

Field_input read_field_input(py::handle V, py::handle F, py::handle X, py::handle sign_symmetric)
{
  Field_input in;
  in.mesh = read_mesh_arrays(V, F);
  in.X = read_real(X, "X", 0);
  in.N = degree_of(in.X, in.mesh.F.rows);
  in.sign_symmetric =
    sign_symmetric.is_none() ? roots_are_sign_symmetric(in.X, in.N) : read_flag(sign_symmetric, "sign_symmetric");
  if(in.sign_symmetric && in.N % 2 != 0)
    throw Failure("X: sign symmetry needs an even number of vectors per face, X has " + std::to_string(in.N) +
                    " (INVALID_DEGREE)",
                  "INVALID_DEGREE");
  return in;
}

py::tuple singularities(py::handle V, py::handle F, py::handle X, py::handle sign_symmetric)
{
  const Field_input in = read_field_input(V, F, X, sign_symmetric);
  std::vector<std::int64_t> vertex, numerator, undefined;
  {
    py::gil_scoped_release release;
    Mesh tm;
    build_mesh(in.mesh, tm);
    const Bundle bundle(tm);
    check_bundle(bundle);
    Field field(bundle, in.N, in.sign_symmetric);
    field_from_roots(bundle, in.X, field);
    std::vector<PVF::Singularity<Vertex> > s;
    std::vector<Vertex> u;
    check(PVF::compute_singularities(field, std::back_inserter(s), std::back_inserter(u)), "singularities");
    for(const auto& x : s)
    {
      vertex.push_back(std::int64_t(std::size_t(x.vertex)));
      numerator.push_back(x.index_numerator);
    }
    for(Vertex v : u)
      undefined.push_back(std::int64_t(std::size_t(v)));
  }
  std::vector<double> index(numerator.size());
  for(std::size_t i = 0; i < index.size(); ++i)
    index[i] = double(numerator[i]) / double(in.N);
  py::dict info;
  info["degree"] = in.N;
  info["sign_symmetric"] = in.sign_symmetric;
  info["index_numerators"] = to_numpy_1d(numerator);
  info["undefined_vertices"] = to_numpy_1d(undefined);
  return py::make_tuple(to_numpy_1d(vertex), to_numpy_1d(index), info);
}

py::tuple principal_curvatures(py::handle V, py::handle F)
{
  const Mesh_arrays a = read_mesh_arrays(V, F);
  std::vector<double> d1, d2, k1, k2;
  std::size_t fallback = 0;
  {
    py::gil_scoped_release release;
    Mesh tm;
    build_mesh(a, tm);
    const Bundle bundle(tm);
    check_bundle(bundle);
    auto map = tm.add_property_map<Face, PVF::Principal_curvatures<Vector> >("f:pvf_py_curvature").first;
    check(PVF::estimate_principal_curvatures(bundle, map, PVF::parameters::fallback_vertices(fallback)), "curvature");
    for(Face f : faces(tm))
    {
      const auto& pc = map[f];
      d1.insert(d1.end(), { pc.d1.x(), pc.d1.y(), pc.d1.z() });
      d2.insert(d2.end(), { pc.d2.x(), pc.d2.y(), pc.d2.z() });
      k1.push_back(pc.k1);
      k2.push_back(pc.k2);
    }
  }
  py::dict info;
  info["fallback_vertices"] = fallback;
  return py::make_tuple(to_numpy(d1, a.F.rows, 3), to_numpy(d2, a.F.rows, 3), to_numpy_1d(k1), to_numpy_1d(k2), info);
}

// Feature edges E (#E x 2 vertex pairs) into an edge map of tm.
template <typename EdgeMap>
void read_features(const Mesh& tm, const Matrix_i& E, EdgeMap features)
{
  for(std::size_t i = 0; i < E.rows; ++i)
  {
    const auto h = CGAL::halfedge(Vertex(Mesh::size_type(E(i, 0))), Vertex(Mesh::size_type(E(i, 1))), tm);
    if(!h.second)
      bad_array("features row " + std::to_string(i) + ": vertices " + std::to_string(E(i, 0)) + " and " +
                std::to_string(E(i, 1)) + " are not joined by an edge of the mesh");
    put(features, CGAL::edge(h.first, tm), true);
  }
}

template <typename EdgeMap>
std::vector<std::int64_t> write_features(const Mesh& tm, EdgeMap features)
{
  std::vector<std::int64_t> E;
  for(Edge e : edges(tm))
    if(get(features, e))
    {
      const Halfedge h = tm.halfedge(e);
      E.push_back(std::int64_t(std::size_t(tm.source(h))));
      E.push_back(std::int64_t(std::size_t(tm.target(h))));
    }
  return E;
}

std::optional<Matrix_i> read_optional_features(py::handle features, std::size_t number_of_vertices)
{
  if(features.is_none())
    return std::nullopt;
  Matrix_i E = read_integer(features, "features", 2);
  check_indices(E, number_of_vertices, "features", "a vertex of V");
  return E;
}

py::tuple sharp_edges(py::handle V, py::handle F, py::handle angle_arg, py::handle boundary_alignment_arg,
                      py::handle minimum_feature_length_arg, py::handle vectors_per_face_arg)
{
  const double angle = read_real_number(angle_arg, "angle");
  const bool boundary_alignment = read_flag(boundary_alignment_arg, "boundary_alignment");
  const double minimum_feature_length = read_real_number(minimum_feature_length_arg, "minimum_feature_length");
  const std::size_t vectors_per_face = std::size_t(read_whole(vectors_per_face_arg, "vectors_per_face", 1, 2));
  const Mesh_arrays a = read_mesh_arrays(V, F);
  std::vector<std::int64_t> E, b;
  std::vector<double> bc;
  std::size_t width = vectors_per_face;
  {
    py::gil_scoped_release release;
    Mesh tm;
    build_mesh(a, tm);
    auto features = tm.add_property_map<Edge, bool>("e:pvf_py_feature", false).first;
    std::vector<Constraint> out;
    check(PVF::select_sharp_edge_constraints(
            tm, angle, vectors_per_face, out,
            PVF::parameters::boundary_alignment(
              boundary_alignment, PVF::parameters::minimum_feature_length(minimum_feature_length))
              .edge_is_constrained_map(features)),
          "sharp edges",
          "angle " + std::to_string(angle) + " degrees, vectors_per_face " + std::to_string(vectors_per_face) +
            ", minimum_feature_length " + std::to_string(minimum_feature_length));
    E = write_features(tm, features);
    for(const Constraint& c : out)
    {
      b.push_back(std::int64_t(std::size_t(c.face)));
      for(std::size_t k = 0; k < width; ++k)
      {
        if(k < c.vectors.size())
          bc.insert(bc.end(), { c.vectors[k].x(), c.vectors[k].y(), c.vectors[k].z() });
        else
          bc.insert(bc.end(), 3, std::numeric_limits<double>::quiet_NaN());
      }
    }
  }
  py::dict info;
  info["feature_edges"] = E.size() / 2;
  info["constrained_faces"] = b.size();
  return py::make_tuple(to_numpy(E, E.size() / 2, 2), to_numpy_1d(b), to_numpy(bc, b.size(), 3 * width), info);
}

py::tuple refine_for_quad_size(py::handle V, py::handle F, py::handle quad_size_arg, py::handle features,
                               py::handle boundary_alignment_arg)
{
  const double quad_size = read_real_number(quad_size_arg, "quad_size");
  const bool boundary_alignment = read_flag(boundary_alignment_arg, "boundary_alignment");
  const Mesh_arrays a = read_mesh_arrays(V, F);
  const std::optional<Matrix_i> E = read_optional_features(features, a.V.rows);
  std::vector<double> V2;
  std::vector<std::int64_t> F2, E2, origin2;
  {
    py::gil_scoped_release release;
    Mesh tm;
    build_mesh(a, tm);
    auto feature_map = tm.add_property_map<Edge, bool>("e:pvf_py_feature", false).first;
    if(E)
      read_features(tm, *E, feature_map);
    std::vector<std::size_t> origin;
    const auto np = PVF::parameters::boundary_alignment(boundary_alignment);
    check(E || boundary_alignment
            ? PVF::refine_for_quad_size(tm, quad_size, origin, np.edge_is_constrained_map(feature_map))
            : PVF::refine_for_quad_size(tm, quad_size, origin),
          "refinement", "quad_size " + std::to_string(quad_size));
    Mesh_rows rows = mesh_rows(tm);
    V2 = std::move(rows.V);
    F2 = std::move(rows.F);
    const std::vector<std::int64_t>& index = rows.index;
    for(Edge e : edges(tm))
      if(feature_map[e])
      {
        const Halfedge h = tm.halfedge(e);
        E2.push_back(index[std::size_t(tm.source(h))]);
        E2.push_back(index[std::size_t(tm.target(h))]);
      }
    origin2.assign(origin.begin(), origin.end());
  }
  return py::make_tuple(to_numpy(V2, V2.size() / 3, 3), to_numpy(F2, F2.size() / 3, 3), to_numpy_1d(origin2),
                        to_numpy(E2, E2.size() / 2, 2));
}

py::tuple integer_grid_map(py::handle V, py::handle F, py::handle X, py::handle edge_length, py::handle quads,
                           py::handle features, py::handle boundary_alignment_arg,
                           py::handle singularity_cancellation_distance, py::handle stiffening_keeps_integers_arg)
{
  const bool boundary_alignment = read_flag(boundary_alignment_arg, "boundary_alignment");
  const bool stiffening_keeps_integers = read_flag(stiffening_keeps_integers_arg, "stiffening_keeps_integers");
  const Mesh_arrays a = read_mesh_arrays(V, F);
  const Matrix_d Xm = read_real(X, "X", 0);
  const std::size_t N = degree_of(Xm, a.F.rows);
  if(N != 4 && N != 2)
    bad_array("X: a frame field has 4 vectors per face (u, v, -u, -v: 12 columns) or 2 (u, v: 6 columns), got " +
              std::to_string(N));
  if(N == 4 && !roots_are_sign_symmetric(Xm, 4))
    throw Failure("X: not a frame field: vectors 2 and 3 of a face must be exactly -u and -v (NOT_A_FRAME_FIELD)",
                  "NOT_A_FRAME_FIELD");
  if(!edge_length.is_none() && !quads.is_none())
    throw Failure("integer_grid_map: give edge_length or quads, not both (INVALID_PARAMETER)", "INVALID_PARAMETER");
  const std::optional<Matrix_i> E = read_optional_features(features, a.V.rows);
  const double given_h = read_number(edge_length, "edge_length").value_or(0.);
  const double given_quads = read_number(quads, "quads").value_or(0.);
  if(!edge_length.is_none() && !(given_h > 0 && std::isfinite(given_h)))
    throw Failure("edge_length: must be positive and finite (INVALID_PARAMETER)", "INVALID_PARAMETER");
  if(!quads.is_none() && !(given_quads >= 1 && std::isfinite(given_quads)))
    throw Failure("quads: must be at least 1 (INVALID_PARAMETER)", "INVALID_PARAMETER");
  const std::optional<double> cancellation =
    read_number(singularity_cancellation_distance, "singularity_cancellation_distance");

  std::vector<double> UV;
  std::vector<std::int64_t> FUV, transitions;
  PVF::Integer_grid_map_result r;
  PVF::Error_code code;
  {
    py::gil_scoped_release release;
    Mesh tm;
    build_mesh(a, tm);
    const Bundle bundle(tm);
    check_bundle(bundle);
    Field field(bundle, 4, true);
    // u and v of each face: the first two vectors of X.
    Matrix_d uv_vectors = Xm;
    field_from_roots(bundle, uv_vectors, field);
    auto feature_map = tm.add_property_map<Edge, bool>("e:pvf_py_feature", false).first;
    if(E)
      read_features(tm, *E, feature_map);
    double h = given_h;
    if(given_quads > 0)
      h = std::sqrt(CGAL::Polygon_mesh_processing::area(tm) / given_quads);
    auto uv = tm.add_property_map<Halfedge, std::array<double, 2> >("h:pvf_py_uv").first;
    const auto np = PVF::parameters::stiffening_keeps_integers(
                      stiffening_keeps_integers,
                      PVF::parameters::singularity_cancellation_distance(
                        cancellation ? *cancellation : (h > 0 ? h : 0.),
                        PVF::parameters::boundary_alignment(boundary_alignment)))
                      .edge_is_constrained_map(feature_map);
    code = h > 0 ? PVF::compute_integer_grid_map(field, uv, r, PVF::parameters::target_edge_length(h, np))
                 : PVF::compute_integer_grid_map(field, uv, r, np);
    if(code == PVF::Error_code::SUCCESS)
    {
      UV.resize(a.F.rows * 6);
      FUV.resize(a.F.rows * 3);
      transitions.resize(a.F.rows * 9);
      for_each_corner(bundle, tm, a.F, [&](Halfedge h, std::size_t slot, std::size_t c) {
        UV[2 * c] = uv[h][0];
        UV[2 * c + 1] = uv[h][1];
        FUV[c] = std::int64_t(c);
        const PVF::Seam_transition& t = r.seam_transitions[slot];
        transitions[3 * c] = t.rotation;
        transitions[3 * c + 1] = t.translation[0];
        transitions[3 * c + 2] = t.translation[1];
      });
    }
  }
  if(code != PVF::Error_code::SUCCESS)
    check(code, "integer_grid_map", r.diagnostic);
  py::dict info;
  info["target_edge_length"] = r.target_edge_length;
  info["mean_edge_length"] = r.mean_edge_length;
  info["singular_vertices"] = r.comb.singular_vertices;
  info["cancelled_singularity_pairs"] = r.comb.cancelled_singularity_pairs;
  info["cut_edges"] = r.comb.cut_edges;
  info["feature_edges"] = r.feature_edges;
  info["aligned_feature_edges"] = r.aligned_feature_edges;
  info["flipped_faces"] = r.flipped_faces;
  info["stiffening_rounds"] = r.stiffening_rounds;
  info["integer_roundings"] = r.integer_roundings;
  info["energy_ratio"] = r.energy_ratio;
  info["max_seam_residual"] = r.max_seam_residual;
  info["stiffening_keeps_integers"] = stiffening_keeps_integers;
  info["time_total"] = r.time_total;
  py::array_t<std::int64_t> T({ py::ssize_t(a.F.rows), py::ssize_t(3), py::ssize_t(3) });
  std::copy(transitions.begin(), transitions.end(), T.mutable_data());
  info["seam_transitions"] = T;
  return py::make_tuple(to_numpy(UV, 3 * a.F.rows, 2), to_numpy(FUV, a.F.rows, 3), info);
}

py::tuple quad_mesh(py::handle V, py::handle F, py::handle UV, py::handle FUV, py::handle seam_transitions,
                    py::handle keep_trimmed_boundary, py::handle split_components, py::handle max_input_distance_arg)
{
  const bool trimmed = read_flag(keep_trimmed_boundary, "keep_trimmed_boundary");
  const bool split = read_flag(split_components, "split_components");
  double max_input_distance = 0;
  if(!max_input_distance_arg.is_none())
  {
    max_input_distance = read_real_number(max_input_distance_arg, "max_input_distance");
    if(!(max_input_distance > 0) || !std::isfinite(max_input_distance))
      throw Failure("quad_mesh: max_input_distance must be a positive distance, got " +
                      std::to_string(max_input_distance) + " (INVALID_PARAMETER)",
                    "INVALID_PARAMETER");
  }
  if(trimmed && (split || max_input_distance > 0))
    throw Failure("quad_mesh: keep_trimmed_boundary keeps the border's polygons, which are not split: give it "
                  "without split_components and max_input_distance (INVALID_PARAMETER)",
                  "INVALID_PARAMETER");
  const Mesh_arrays a = read_mesh_arrays(V, F);
  const Matrix_d UVm = read_real(UV, "UV", 2);
  const Matrix_i FUVm = read_integer(FUV, "FUV", 3);
  if(FUVm.rows != a.F.rows)
    bad_array("FUV: expected one row per face of F (" + std::to_string(a.F.rows) + "), got " +
              std::to_string(FUVm.rows));
  check_indices(FUVm, UVm.rows, "FUV", "a row of UV");
  std::optional<std::vector<std::int64_t> > T;
  if(!seam_transitions.is_none())
  {
    py::array t = as_array(seam_transitions, "seam_transitions");
    if(t.dtype().kind() != 'i' || t.ndim() != 3 || std::size_t(t.shape(0)) != a.F.rows || t.shape(1) != 3 ||
       t.shape(2) != 3)
      bad_array("seam_transitions: expected an integer array of shape (" + std::to_string(a.F.rows) +
                ", 3, 3) as integer_grid_map returns it, got " + shape_text(t));
    auto c = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(t);
    T.emplace(c.data(), c.data() + c.size());
  }
  Mesh_rows q;
  PVF::Quad_extraction_result r;
  PVF::Error_code code;
  {
    py::gil_scoped_release release;
    Mesh tm;
    build_mesh(a, tm);
    const Bundle bundle(tm);
    check_bundle(bundle);
    auto uv = tm.add_property_map<Halfedge, std::array<double, 2> >("h:pvf_py_uv").first;
    PVF::Integer_grid_map_result map;
    if(T)
      map.seam_transitions.resize(3 * a.F.rows);
    for_each_corner(bundle, tm, a.F, [&](Halfedge h, std::size_t slot, std::size_t c) {
      const std::size_t row_of_uv = std::size_t(FUVm.data[c]);
      uv[h] = { UVm(row_of_uv, 0), UVm(row_of_uv, 1) };
      if(T)
      {
        const std::int64_t* t = T->data() + 3 * c;
        if(t[0] < 0 || t[0] > 3)
          throw Failure("seam_transitions[" + std::to_string(c / 3) + ", " + std::to_string(c % 3) +
                          "]: rotation must be in 0..3 (NOT_AN_INTEGER_GRID_MAP)",
                        "NOT_AN_INTEGER_GRID_MAP");
        PVF::Seam_transition& s = map.seam_transitions[slot];
        s.rotation = int(t[0]);
        s.translation = { t[1], t[2] };
      }
    });
    Mesh qm;
    const auto np = PVF::parameters::keep_trimmed_boundary(
      trimmed, PVF::parameters::split_components_without_cells(
                 split, PVF::parameters::max_input_distance(max_input_distance)));
    code = T ? PVF::extract_quad_mesh(bundle, uv, map, qm, r, np) : PVF::extract_quad_mesh(tm, uv, qm, r, np);
    if(code == PVF::Error_code::SUCCESS)
    {
      q = mesh_rows(qm);
      if(!trimmed && (q.width != 4 || q.padded()))
        throw Failure("quad_mesh: the extraction made a face of " +
                        std::to_string(q.width != 4 ? q.width : q.smallest) + " vertices (NON_QUAD_FACE)",
                      "NON_QUAD_FACE");
    }
  }
  if(code != PVF::Error_code::SUCCESS)
  {
    std::string message = std::string("quad_mesh: ") + PVF::get_error_message(code);
    if(!r.diagnostic.empty())
      message += ": " + r.diagnostic;
    throw Failure(message + " (" + code_name(code) + ")", code_name(code));
  }
  py::dict info;
  info["quads"] = r.quads;
  info["vertices"] = r.vertices;
  info["irregular_vertices"] = r.irregular_vertices;
  info["singular_points"] = r.singular_points;
  info["flipped_faces"] = r.flipped_faces;
  info["repaired_regions"] = r.repaired_regions;
  info["unfolded_quads"] = r.unfolded_quads;
  info["discarded_cells"] = r.discarded_cells;
  info["trimmed_polygons"] = r.trimmed_polygons;
  info["largest_input_distance"] = r.largest_input_distance;
  info["split_components"] = r.split_components;
  info["split_small_components"] = r.split_small_components;
  info["split_far_components"] = r.split_far_components;
  info["split_defective_components"] = r.split_defective_components;
  info["time_total"] = r.time_total;
  return py::make_tuple(to_numpy(q.V, q.V.size() / 3, 3), to_numpy(q.F, q.F.size() / q.width, q.width), info);
}

py::tuple quad_planarity(py::handle Vq, py::handle Fq)
{
  const Mesh_arrays q = read_mesh_arrays(Vq, Fq, 4, "Vq", "Fq");
  std::vector<double> P;
  PVF::Planarity_result r;
  {
    py::gil_scoped_release release;
    Mesh qm;
    build_mesh(q, qm, "Fq");
    auto map = qm.add_property_map<Face, double>("f:pvf_py_planarity").first;
    check(PVF::quad_planarity(qm, map, r), "quad_planarity");
    for(Face f : faces(qm))
      P.push_back(map[f]);
  }
  py::dict info;
  info["max"] = r.max;
  info["mean"] = r.mean;
  info["faces"] = r.faces;
  return py::make_tuple(to_numpy_1d(P), info);
}

py::tuple planarize(py::handle Vq, py::handle Fq, py::handle V, py::handle F, py::handle threshold_arg,
                    py::handle max_distance_to_surface, py::handle number_of_iterations,
                    py::handle gauss_newton_steps_arg, py::handle crease_angle_arg)
{
  const double threshold = read_real_number(threshold_arg, "threshold");
  const double crease_angle = read_real_number(crease_angle_arg, "crease_angle");
  const Mesh_arrays q = read_mesh_arrays(Vq, Fq, 4, "Vq", "Fq");
  const Mesh_arrays a = read_mesh_arrays(V, F);
  const std::optional<double> distance = read_number(max_distance_to_surface, "max_distance_to_surface");
  // the function's own defaults where None is given
  const PVF::internal::Planarization_parameters defaults;
  const std::size_t given_iterations = read_count(number_of_iterations, "number_of_iterations");
  const std::size_t iterations = given_iterations > 0 ? given_iterations : defaults.max_iterations;
  const std::size_t gauss_newton_steps =
    gauss_newton_steps_arg.is_none() ? defaults.gauss_newton_steps
                                     : std::size_t(read_whole(gauss_newton_steps_arg, "gauss_newton_steps", 0, 1000000));
  std::vector<double> out;
  PVF::Planarization_result r;
  PVF::Error_code code;
  {
    py::gil_scoped_release release;
    Mesh qm, tm;
    build_mesh(q, qm, "Fq");
    build_mesh(a, tm);
    namespace P = PVF::parameters;
    const auto np =
      P::gauss_newton_steps(gauss_newton_steps, P::crease_angle(crease_angle, P::planarity_threshold(threshold)
                                                                               .number_of_iterations(iterations)));
    // without a distance, the function's default bound (5% of the mean quad edge)
    if(distance)
      code = PVF::planarize_quad_mesh(qm, tm, r, P::max_distance_to_surface(*distance, np));
    else
      code = PVF::planarize_quad_mesh(qm, tm, r, np);
    // Not reaching the threshold, or only by leaving the surface or folding a quad, is
    // reported, not raised: the quad mesh is then returned as it was given (the
    // command-line program does the same).
    if(code != PVF::Error_code::DID_NOT_CONVERGE && code != PVF::Error_code::TOO_FAR_FROM_SURFACE &&
       code != PVF::Error_code::FOLDED_QUAD)
    {
      // the parameters given, so that an INVALID_PARAMETER can be read against them
      std::string given = "threshold " + std::to_string(threshold) + ", crease_angle " + std::to_string(crease_angle);
      if(distance)
        given += ", max_distance_to_surface " + std::to_string(*distance);
      check(code, "planarize", given);
    }
    if(code == PVF::Error_code::SUCCESS)
      for(Vertex v : vertices(qm))
      {
        const Point& p = qm.point(v);
        out.insert(out.end(), { p.x(), p.y(), p.z() });
      }
    else
      out = q.V.data;
  }
  py::dict info;
  info["status"] = code_name(code);
  info["converged"] = r.converged;
  info["left_surface"] = r.left_surface;
  info["folded_quads"] = r.folded_quads;
  info["gauss_newton_ran"] = r.gauss_newton_ran;
  info["gauss_newton_steps"] = r.gauss_newton_steps;
  info["gauss_newton_rejected_steps"] = r.gauss_newton_rejected_steps;
  info["gauss_newton_stalled"] = r.gauss_newton_stalled;
  info["gauss_newton_max_planarity"] = r.gauss_newton_max_planarity;
  info["gauss_newton_max_distance"] = r.gauss_newton_max_distance;
  info["gauss_newton_max_distance_to_quads"] = r.gauss_newton_max_distance_to_quads;
  info["max_distance_to_quads_before"] = r.max_distance_to_quads_before;
  info["max_distance_to_quads"] = r.max_distance_to_quads;
  info["iterations"] = r.iterations;
  info["threshold"] = r.threshold;
  info["max_planarity_before"] = r.max_planarity_before;
  info["mean_planarity_before"] = r.mean_planarity_before;
  info["max_planarity_after"] = r.max_planarity_after;
  info["mean_planarity_after"] = r.mean_planarity_after;
  info["max_distance"] = r.max_distance;
  info["distance_bound"] = r.distance_bound;
  info["time_total"] = r.time_total;
  return py::make_tuple(to_numpy(out, q.V.rows, 3), info);
}

// ---------------------------------------------------------------------------
// Writers: the web page and the PLY file coloured by planarity
// ---------------------------------------------------------------------------

// The quads Vq, Fq (or polygons: rows of Fq padded at their end with -1), both or neither.
std::optional<Mesh_arrays> read_optional_polygons(py::handle Vq, py::handle Fq)
{
  if(Vq.is_none() && Fq.is_none())
    return std::nullopt;
  if(Vq.is_none() || Fq.is_none())
    bad_array(std::string(Vq.is_none() ? "Vq" : "Fq") + ": Vq and Fq go together (both or none)");
  return read_mesh_arrays(Vq, Fq, 0, "Vq", "Fq");
}

std::optional<double> read_colour_range(py::handle h)
{
  if(h.is_none())
    return std::nullopt;
  return read_real_number(h, "planarity_colour_range");
}

// Calls `write` with `np`, to which the planarity colour range is added when one is given.
template <typename NamedParameters, typename Write>
PVF::Error_code with_colour_range(const std::optional<double>& range, const NamedParameters& np, const Write& write)
{
  return range ? write(PVF::parameters::planarity_colour_range(*range, np)) : write(np);
}

void write_html_viewer(const std::string& filename, py::handle V, py::handle F, py::handle X,
                       py::handle singularities_arg, py::handle Vq, py::handle Fq, py::handle constrained_faces_arg,
                       py::handle page_title, py::handle max_glyph_faces, py::handle planarity_colour_range,
                       py::handle three_js_directory)
{
  const Mesh_arrays a = read_mesh_arrays(V, F);
  const Matrix_d Xm = read_real(X, "X", 0);
  const std::size_t N = degree_of(Xm, a.F.rows);
  const std::optional<Mesh_arrays> q = read_optional_polygons(Vq, Fq);
  std::optional<Matrix_i> S;
  if(!singularities_arg.is_none())
  {
    S = read_integer(singularities_arg, "singularities", 2);
    for(std::size_t i = 0; i < S->rows; ++i)
    {
      if((*S)(i, 0) < 0 || std::uint64_t((*S)(i, 0)) >= a.V.rows)
        bad_array("singularities[" + std::to_string(i) + ", 0] = " + std::to_string((*S)(i, 0)) +
                  " is not a vertex of V (0.." + std::to_string(a.V.rows) + "-1)");
      if(std::abs((*S)(i, 1)) > (std::numeric_limits<int>::max)())
        bad_array("singularities[" + std::to_string(i) + ", 1] = " + std::to_string((*S)(i, 1)) +
                  " is out of the range of an index numerator");
    }
  }
  std::optional<Matrix_i> C;
  if(!constrained_faces_arg.is_none())
  {
    C = read_integer(constrained_faces_arg, "constrained_faces", 1, true);
    check_indices(*C, a.F.rows, "constrained_faces", "a face of F");
  }
  const std::string title = page_title.is_none() ? std::string("CGAL Polyvector Fields")
                                                 : read_text(page_title, "page_title");
  const std::size_t glyph_faces =
    max_glyph_faces.is_none()
      ? PVF::IO::internal::default_max_glyph_faces
      : std::size_t(read_whole(max_glyph_faces, "max_glyph_faces", 0, (std::numeric_limits<std::int64_t>::max)()));
  const std::optional<double> range = read_colour_range(planarity_colour_range);
  const std::string three_js = three_js_directory.is_none() ? std::string(PVF::IO::internal::default_three_js_directory())
                                                            : read_text(three_js_directory, "three_js_directory");
  PVF::Error_code code;
  std::string message;
  {
    py::gil_scoped_release release;
    Mesh tm;
    build_mesh(a, tm);
    auto roots = tm.add_property_map<Face, std::vector<Vector> >("f:pvf_py_roots").first;
    for(Face f : faces(tm))
      for(std::size_t k = 0; k < N; ++k)
      {
        const std::size_t row = std::size_t(f);
        roots[f].push_back(Vector(Xm(row, 3 * k), Xm(row, 3 * k + 1), Xm(row, 3 * k + 2)));
      }
    std::vector<PVF::Singularity<Vertex> > singular;
    if(S)
      for(std::size_t i = 0; i < S->rows; ++i)
        singular.push_back({ Vertex(Mesh::size_type((*S)(i, 0))), int((*S)(i, 1)) });
    else
    {
      // As singularities() finds them.
      const Bundle bundle(tm);
      check_bundle(bundle);
      Field field(bundle, N, roots_are_sign_symmetric(Xm, N));
      field_from_roots(bundle, Xm, field);
      check(PVF::compute_singularities(field, std::back_inserter(singular)), "singularities");
    }
    std::vector<Face> constrained;
    if(C)
      for(std::int64_t f : C->data)
        constrained.push_back(Face(Mesh::size_type(f)));
    namespace P = PVF::parameters;
    const auto np = P::page_title(
      title, P::max_glyph_faces(glyph_faces, P::three_js_directory(three_js, P::constrained_faces(
                                                                                 constrained, P::error_message(message)))));
    Mesh qm;
    if(q)
    {
      build_mesh(*q, qm, "Fq");
      code = with_colour_range(range, P::quad_mesh(qm, np), [&](const auto& all) {
        return PVF::IO::write_HTML_viewer(filename, tm, roots, N, singular, all);
      });
    }
    else
      code = with_colour_range(range, np, [&](const auto& all) {
        return PVF::IO::write_HTML_viewer(filename, tm, roots, N, singular, all);
      });
  }
  // error_message holds the package's message when there is nothing more specific to say
  check(code, "write_html_viewer '" + filename + "'", message == PVF::get_error_message(code) ? std::string() : message);
}

void write_quad_mesh_ply(const std::string& filename, py::handle Vq, py::handle Fq, py::handle planarity_colour_range)
{
  const Mesh_arrays q = read_mesh_arrays(Vq, Fq, 0, "Vq", "Fq");
  const std::optional<double> range = read_colour_range(planarity_colour_range);
  PVF::Error_code code;
  {
    py::gil_scoped_release release;
    Mesh qm;
    build_mesh(q, qm, "Fq");
    code = with_colour_range(range, CGAL::parameters::default_values(), [&](const auto& np) {
      return PVF::IO::write_quad_mesh_PLY(filename, qm, np);
    });
  }
  check(code, "write_quad_mesh_ply '" + filename + "'");
}

} // namespace

PYBIND11_MODULE(_core, m)
{
  m.doc() = "The C++ core of polyvector_fields: see the package's docstrings.";

  static py::handle error_type;
  {
    py::object error =
      py::reinterpret_steal<py::object>(PyErr_NewException("polyvector_fields._core.Error", PyExc_ValueError, nullptr));
    m.attr("Error") = error;
    error_type = error.release();
  }
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p)
        std::rethrow_exception(p);
    }
    catch(const Failure& failure)
    {
      py::object exc = py::reinterpret_borrow<py::object>(error_type)(failure.what());
      exc.attr("code") = failure.code;
      PyErr_SetObject(error_type.ptr(), exc.ptr());
    }
  });

  using namespace pybind11::literals;
  m.def("read_triangle_mesh", &read_triangle_mesh, "filename"_a, "repair"_a = true);
  m.def("write_html_viewer", &write_html_viewer, "filename"_a, "V"_a, "F"_a, "X"_a, "singularities"_a = py::none(),
        "Vq"_a = py::none(), "Fq"_a = py::none(), "constrained_faces"_a = py::none(), "page_title"_a = py::none(),
        "max_glyph_faces"_a = py::none(), "planarity_colour_range"_a = py::none(),
        "three_js_directory"_a = py::none());
  m.def("write_quad_mesh_ply", &write_quad_mesh_ply, "filename"_a, "Vq"_a, "Fq"_a,
        "planarity_colour_range"_a = py::none());
  m.def("design_field", &design_field, "V"_a, "F"_a, "b"_a, "bc"_a, "degree"_a = 4, "sign_symmetric"_a = false,
        "soft"_a = py::none(), "smoothness_weights"_a = "uniform");
  m.def("frame_field", &frame_field, "V"_a, "F"_a, "b"_a = py::none(), "bc"_a = py::none(),
        "curvature_constraints"_a = py::none(), "conjugate"_a = false, "angle_bound"_a = py::none(),
        "soft"_a = py::none(), "orthogonality_weight"_a = 0.0, "number_of_iterations"_a = py::none(),
        "tolerance"_a = py::none(), "smoothness_weights"_a = "uniform");
  m.def("singularities", &singularities, "V"_a, "F"_a, "X"_a, "sign_symmetric"_a = py::none());
  m.def("principal_curvatures", &principal_curvatures, "V"_a, "F"_a);
  m.def("sharp_edges", &sharp_edges, "V"_a, "F"_a, "angle"_a = 40.0, "boundary_alignment"_a = true,
        "minimum_feature_length"_a = 0.0, "vectors_per_face"_a = 2);
  m.def("refine_for_quad_size", &refine_for_quad_size, "V"_a, "F"_a, "quad_size"_a, "features"_a = py::none(),
        "boundary_alignment"_a = false);
  m.def("integer_grid_map", &integer_grid_map, "V"_a, "F"_a, "X"_a, "edge_length"_a = py::none(),
        "quads"_a = py::none(), "features"_a = py::none(), "boundary_alignment"_a = false,
        "singularity_cancellation_distance"_a = py::none(), "stiffening_keeps_integers"_a = true);
  m.def("quad_mesh", &quad_mesh, "V"_a, "F"_a, "UV"_a, "FUV"_a, "seam_transitions"_a = py::none(),
        "keep_trimmed_boundary"_a = false, "split_components"_a = false, "max_input_distance"_a = py::none());
  m.def("quad_planarity", &quad_planarity, "Vq"_a, "Fq"_a);
  m.def("planarize", &planarize, "Vq"_a, "Fq"_a, "V"_a, "F"_a, "threshold"_a = 0.01,
        "max_distance_to_surface"_a = py::none(), "number_of_iterations"_a = py::none(),
        "gauss_newton_steps"_a = py::none(), "crease_angle"_a = 40.0);
}
