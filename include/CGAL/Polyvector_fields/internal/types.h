// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_TYPES_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_TYPES_H

// The types that the parts of the package share: complex numbers, the sparse
// and dense types of the linear systems, 2 pi, the stage times, the index
// that stands for "none" and the test for 2D points with x() and y().

#include <CGAL/number_type_config.h>

#include <Eigen/Sparse>

#include <CGAL/Polyvector_fields/internal/parallel.h>

#include <complex>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

typedef std::complex<double> Complex;
typedef Eigen::SparseMatrix<Complex> Sparse_matrix;
typedef Eigen::Matrix<Complex, Eigen::Dynamic, 1> Dense_vector;

constexpr double two_pi = 2 * CGAL_PI;

// Seconds of the stages of a solve.
struct Stage_times
{
  double assembly = 0, factorization = 0, solve = 0;
};

// The index of no element (no opposite corner on the border, no point, ...).
constexpr std::size_t npos = std::size_t(-1);

// Whether T has x() and y() (a 2D point), rather than [0] and [1].
template <typename T, typename = void>
struct Has_xy : std::false_type {};
template <typename T>
struct Has_xy<T, std::void_t<decltype(std::declval<const T&>().x()), decltype(std::declval<const T&>().y())> >
  : std::true_type {};

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_TYPES_H
