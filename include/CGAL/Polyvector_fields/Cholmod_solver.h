// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_CHOLMOD_SOLVER_H
#define CGAL_POLYVECTOR_FIELDS_CHOLMOD_SOLVER_H

/// \file Cholmod_solver.h
///
/// The SuiteSparse CHOLMOD model of the package's sparse solver. It exists only
/// when CHOLMOD is available: when `CGAL_PVF_HAS_CHOLMOD` is defined (the CMake
/// target `CGAL::Polyvector_fields_CHOLMOD_support` defines it and links
/// CHOLMOD), or, without that macro, when `<cholmod.h>` can be included; the
/// program must then link CHOLMOD itself. When it exists, the macro
/// `CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE` is defined.

#include <CGAL/Polyvector_fields/internal/Factorization.h>

#if defined(CGAL_PVF_HAS_CHOLMOD)
#  define CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE 1
#elif defined(__has_include)
#  if __has_include(<cholmod.h>)
#    define CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE 1
#  endif
#endif

#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <complex>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsSolvers
///
/// is a sparse solver for the package's complex Hermitian positive definite
/// systems: the supernodal Cholesky factorization `L L^*` of SuiteSparse's
/// CHOLMOD (fill-reducing ordering chosen by CHOLMOD: AMD, or METIS when CHOLMOD
/// was built with it), through Eigen's `CholmodSupernodalLLT` and
/// `CGAL::Eigen_solver_traits`.
///
/// It is a model of `SparseLinearAlgebraWithFactorTraits_d` on
/// `std::complex<double>`, to be given as the `SolverTraits` template parameter of
/// `Polyvector_field_designer` or with the `sparse_linear_solver` named parameter.
/// As with `Default_sparse_solver`, the symbolic analysis is done once per
/// sparsity pattern and only the numeric factorization is redone when the
/// values change.
///
/// Only the lower triangle of each matrix is read. A matrix that is not
/// positive definite makes the factorization fail, and the algorithm then
/// returns `Error_code::SOLVER_FAILURE`.
///
/// This type exists only when CHOLMOD is available (see the file description);
/// link the CMake target `CGAL::Polyvector_fields_CHOLMOD_support`.
///
/// \sa `Default_sparse_solver`
typedef CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<std::complex<double> > > >
  Cholmod_sparse_solver;

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE

#endif // CGAL_POLYVECTOR_FIELDS_CHOLMOD_SOLVER_H
