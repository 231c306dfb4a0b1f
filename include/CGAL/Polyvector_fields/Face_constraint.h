// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_FACE_CONSTRAINT_H
#define CGAL_POLYVECTOR_FIELDS_FACE_CONSTRAINT_H

/// \file Face_constraint.h

#include <limits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsDesign
///
/// is a constraint on the PolyVector of one face.
///
/// The vectors are given in world coordinates; each is projected onto the
/// face plane and rescaled to its original length. With `k` vectors:
/// - `k = N` fixes the whole PolyVector (a full constraint);
/// - `k < N` asks that each given vector be one of the `N` vectors (a partial
///   constraint, the linear condition `P(u) = 0`); a vector given `j` times is
///   a root of multiplicity `j`.
///
/// With sign symmetry each vector `u` stands for the pair `{u, -u}`, so `k`
/// is at most `N/2`, and `k = N/2` is a full constraint.
///
/// An infinite `weight` makes the constraint hard: it holds exactly. A finite,
/// strictly positive weight makes it soft: the design adds
/// `weight * |c_f - c_f^0|^2` (full) or `weight * sum_u |P_f(u)|^2` (partial)
/// to the smoothness energy.
///
/// \tparam FaceDescriptor the face descriptor of the mesh
/// \tparam Vector_3 the vector type of the mesh's kernel
template <typename FaceDescriptor, typename Vector_3>
struct Face_constraint
{
  FaceDescriptor face;                  ///< the constrained face
  std::vector<Vector_3> vectors;        ///< the vectors, in world coordinates
  double weight = std::numeric_limits<double>::infinity();  ///< infinite: hard; finite and positive: soft
};

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_FACE_CONSTRAINT_H
