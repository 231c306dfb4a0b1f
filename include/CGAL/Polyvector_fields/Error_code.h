// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_ERROR_CODE_H
#define CGAL_POLYVECTOR_FIELDS_ERROR_CODE_H

/// \file Error_code.h

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsEnums
///
/// lists the reasons for which a function of this package can refuse its input
/// or fail. Every function that returns an `Error_code` leaves its output
/// property maps and files untouched unless it returns `Error_code::SUCCESS`.
enum class Error_code
{
  SUCCESS = 0,                   ///< the function succeeded
  EMPTY_MESH,                    ///< the mesh has no face
  NON_TRIANGLE_FACE,             ///< a face of the mesh is not a triangle
  DEGENERATE_FACE,               ///< a face has (numerically) zero area or a non-finite vertex coordinate
  INVALID_DEGREE,                ///< the degree `N` is zero, or odd while sign symmetry is asked for
  INVALID_FACE,                  ///< a constraint or a file names a face that is not in the mesh
  DUPLICATE_CONSTRAINT,          ///< a face is constrained twice
  EMPTY_CONSTRAINT,              ///< a constraint gives no vector
  ZERO_CONSTRAINT_VECTOR,        ///< a constraint vector is zero, or vanishes once projected onto its face plane
  NON_FINITE_VALUE,              ///< a value (coordinate, weight, parameter) is NaN or infinite
  TOO_MANY_CONSTRAINT_VECTORS,   ///< a constraint gives more than `N` vectors (more than `N/2` with sign symmetry)
  INVALID_WEIGHT,                ///< a soft-constraint weight is neither infinite (hard) nor in `[1e-8, 1e8]`
  INCONSISTENT_DEGREE,           ///< a file or a field holds a degree other than the one asked for
  CANNOT_OPEN_FILE,              ///< a file cannot be opened for reading or writing
  MALFORMED_FILE,                ///< a file does not follow its format
  SOLVER_FAILURE,                ///< the sparse linear solver could not factor or solve the system
  INVALID_PARAMETER,             ///< a numerical parameter is out of its documented range
  NOT_A_FRAME_FIELD,             ///< a frame-field algorithm was called with `N != 4` or without sign symmetry
  CURVATURE_ESTIMATION_FAILED,   ///< the principal curvatures of a face could not be estimated
  FILE_TOO_LARGE,                ///< an input is larger than the size limit of its reader
  UNSUPPORTED_FORMAT,            ///< a file's format (its extension or header) is not one that the reader knows
  DUPLICATE_FACE,                ///< two faces of a mesh file have the same vertices
  NON_MANIFOLD_MESH,             ///< a mesh has an edge shared by more than two faces, a vertex whose faces do not form a fan, or faces that cannot be oriented consistently
  VALUE_OUT_OF_RANGE,            ///< a value is finite but too large or too small for the computation: a constraint vector of length `L` needs `1e-300 <= L^N <= 1e300`, and `1e-100 <= (L / sigma)^N <= 1e100` for the mean length `sigma` of all constraint vectors
  ZERO_FRAME,                    ///< a face of a frame field has a zero frame (both of its vectors are zero), which cannot be clamped to a usable frame
  NOT_AN_INTEGER_GRID_MAP,       ///< a uv map is missing or not seamless: a transition that is not a grid symmetry, or a vertex of non-zero index off the integer grid
  UNREPAIRABLE_FOLD_OVER,        ///< a uv map has flipped or degenerate triangles that the local repair could not remove
  NON_QUAD_FACE,                 ///< a face of a polygon mesh is not a quadrilateral
  DID_NOT_CONVERGE,              ///< an iterative method stopped at its iteration limit before reaching its target
  MAP_CHECK_FAILED,              ///< a computed integer-grid map failed the check made before it is returned: a seam not exact under its transition, a singular vertex off the integer grid, or transitions that do not compose to the identity around a regular vertex
  NO_INTEGER_CELL,               ///< a connected component of the surface has no whole cell of the integer-grid map: the quad size is larger than that part of the surface
  TOO_FAR_FROM_SURFACE,          ///< a moved vertex ended farther from the reference surface than the allowed distance (`planarize_quad_mesh()`'s `max_distance_to_surface`)
  FOLDED_QUAD,                   ///< a quad extracted from an integer-grid map is folded against the surface: neither of its diagonals splits it into two triangles that face the side of the input faces under it; or the planarization of a quad mesh folded a quad that the input did not fold
  NON_DISK_CELL                  ///< a cell of an integer-grid map is not a disk: it goes around a hole or a handle of the surface, or passes twice through a point, and cannot be made into polygons of a mesh: the quad size is larger than that part of the surface
};

/// \ingroup PkgPolyvectorFieldsEnums
///
/// returns a one-line English message that describes `code`.
inline const char* get_error_message(Error_code code)
{
  switch(code)
  {
    case Error_code::SUCCESS: return "success";
    case Error_code::EMPTY_MESH: return "the mesh has no face";
    case Error_code::NON_TRIANGLE_FACE: return "the mesh has a face that is not a triangle";
    case Error_code::DEGENERATE_FACE: return "the mesh has a degenerate face (zero area or non-finite coordinates)";
    case Error_code::INVALID_DEGREE: return "invalid degree: N must be at least 1, and even with sign symmetry";
    case Error_code::INVALID_FACE: return "a constraint names a face that is not in the mesh";
    case Error_code::DUPLICATE_CONSTRAINT: return "a face is constrained more than once";
    case Error_code::EMPTY_CONSTRAINT: return "a constraint gives no vector";
    case Error_code::ZERO_CONSTRAINT_VECTOR: return "a constraint vector is zero or normal to its face";
    case Error_code::NON_FINITE_VALUE: return "a value is NaN or infinite";
    case Error_code::TOO_MANY_CONSTRAINT_VECTORS: return "a constraint gives more vectors than the degree allows";
    case Error_code::INVALID_WEIGHT: return "a soft-constraint weight is not in [1e-8, 1e8] (or infinite, for a hard constraint)";
    case Error_code::INCONSISTENT_DEGREE: return "the degree in the data differs from the degree asked for";
    case Error_code::CANNOT_OPEN_FILE: return "a file cannot be opened";
    case Error_code::MALFORMED_FILE: return "a file is malformed";
    case Error_code::SOLVER_FAILURE: return "the sparse linear solver failed";
    case Error_code::INVALID_PARAMETER: return "a parameter is out of its valid range";
    case Error_code::NOT_A_FRAME_FIELD: return "the algorithm needs a sign-symmetric field of degree 4 (a frame field)";
    case Error_code::CURVATURE_ESTIMATION_FAILED: return "the principal curvatures could not be estimated";
    case Error_code::FILE_TOO_LARGE: return "a file is larger than the size limit";
    case Error_code::UNSUPPORTED_FORMAT: return "the file format is not supported";
    case Error_code::DUPLICATE_FACE: return "the mesh has two faces with the same vertices";
    case Error_code::NON_MANIFOLD_MESH: return "the mesh is not a manifold surface (an edge with more than two faces, a pinched vertex, or inconsistent orientations)";
    case Error_code::VALUE_OUT_OF_RANGE: return "a constraint vector is too long or too short for the degree N (its length L needs 1e-300 <= L^N <= 1e300, and within 1e-100 <= (L / sigma)^N <= 1e100 of the mean length sigma of all constraint vectors)";
    case Error_code::ZERO_FRAME: return "a face of the frame field has a zero frame (both vectors zero), which cannot be clamped";
    case Error_code::NOT_AN_INTEGER_GRID_MAP: return "the uv map is missing or is not a seamless integer-grid map";
    case Error_code::UNREPAIRABLE_FOLD_OVER: return "the uv map has fold-overs that could not be repaired";
    case Error_code::NON_QUAD_FACE: return "the mesh has a face that is not a quadrilateral";
    case Error_code::DID_NOT_CONVERGE: return "the iteration limit was reached before the target";
    case Error_code::MAP_CHECK_FAILED: return "the computed integer-grid map failed its check (a seam not exact, a singular vertex off the integer grid, or transitions that do not close up around a regular vertex)";
    case Error_code::NO_INTEGER_CELL: return "the quad size is larger than the surface: a connected component has no whole integer cell, so no quad";
    case Error_code::TOO_FAR_FROM_SURFACE: return "a vertex moved farther from the reference surface than the allowed distance (max_distance_to_surface)";
    case Error_code::FOLDED_QUAD: return "a quad of the quad mesh is folded against the surface (neither diagonal gives two triangles facing the surface's side)";
    case Error_code::NON_DISK_CELL: return "the quad size is larger than a part of the surface: a cell of the map goes around a hole or a handle, or passes twice through a point, so it is not a polygon of the quad mesh";
  }
  return "unknown error";
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_ERROR_CODE_H
