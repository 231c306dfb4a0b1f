// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_DEFAULT_SPARSE_SOLVER_H
#define CGAL_POLYVECTOR_FIELDS_DEFAULT_SPARSE_SOLVER_H

/// \file Default_sparse_solver.h
///
/// The sparse solvers that are always available, and the package's defaults:
/// `Default_sparse_solver` for the complex systems of the fields,
/// `Default_real_sparse_solver` for the real ones of the map and the planarization.

#include <CGAL/Polyvector_fields/Adaptive_sparse_solver.h>
#include <CGAL/Polyvector_fields/Amg_sparse_solver.h>
#include <CGAL/Polyvector_fields/Sparse_factorization.h>

#if defined(CGAL_PVF_HAS_CHOLMOD)
#  include <CGAL/Polyvector_fields/Cholmod_solver.h>
#  include <Eigen/CholmodSupport>
#endif

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/Sparse>

#include <complex>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsSolvers
///
/// is Eigen's `SimplicialLDLT` on complex Hermitian matrices, through
/// `CGAL::Eigen_solver_traits`: the solver that is always available (Eigen only).
/// The package computes its AMD ordering once for all the coefficient degrees
/// of a field and factors the degrees in parallel when TBB is linked.
typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<std::complex<double> > > >
  Simplicial_ldlt_solver;

#if defined(DOXYGEN_RUNNING)
/// \ingroup PkgPolyvectorFieldsSolvers
///
/// is the direct solver of the package: `Cholmod_sparse_solver` when the
/// macro `CGAL_PVF_HAS_CHOLMOD` is defined (the CMake target
/// `CGAL::Polyvector_fields_CHOLMOD_support` defines it when CMake found
/// CHOLMOD at configure time), `Simplicial_ldlt_solver` otherwise. Both give the
/// same fields to rounding; CHOLMOD is faster on large meshes (about 2.5 times
/// at 640k faces, see the benchmark suite).
typedef unspecified_type Direct_sparse_solver;
#elif defined(CGAL_PVF_HAS_CHOLMOD)
typedef Cholmod_sparse_solver Direct_sparse_solver;
#else
typedef Simplicial_ldlt_solver Direct_sparse_solver;
#endif

/// \ingroup PkgPolyvectorFieldsSolvers
///
/// is the solver used when none is given: `Direct_sparse_solver` for systems
/// of fewer than 8,000 unknowns, `Amg_sparse_solver` (multigrid-preconditioned
/// conjugate gradient, whose cost grows linearly) for larger ones.
typedef Adaptive_sparse_solver<Direct_sparse_solver> Default_sparse_solver;

#if defined(DOXYGEN_RUNNING)
/// \ingroup PkgPolyvectorFieldsSolvers
///
/// is the sparse solver of the real systems when none is given, those of
/// `compute_integer_grid_map()` and `planarize_quad_mesh()`: a model of
/// `SparseLinearAlgebraWithFactorTraits_d` on `double` (both systems are real,
/// symmetric and positive definite): CHOLMOD through Eigen's
/// `CholmodDecomposition` when the macro `CGAL_PVF_HAS_CHOLMOD` is defined (as
/// for `Direct_sparse_solver`), Eigen's `SimplicialLDLT` otherwise. With CHOLMOD,
/// OpenBLAS runs on one thread while the package factors and solves, as for
/// `Cholmod_sparse_solver`, so that a map does not depend on the number of
/// OpenBLAS threads; and the Schur complement of the integer unknowns is made by
/// sparse forward solves (the operation `inverse_congruence()` of the concept
/// `SparseFactorization`).
typedef unspecified_type Default_real_sparse_solver;
#elif defined(CGAL_PVF_HAS_CHOLMOD)
typedef CGAL::Eigen_solver_traits<Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> >
  Default_real_sparse_solver;
#else
typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > > Default_real_sparse_solver;
#endif

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_DEFAULT_SPARSE_SOLVER_H
