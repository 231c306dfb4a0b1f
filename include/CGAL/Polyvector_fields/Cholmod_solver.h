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

#include <CGAL/Polyvector_fields/internal/Solvers/cholmod_available.h>

#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE

#include <CGAL/Polyvector_fields/internal/Solvers/Cholmod_factorization.h>

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <complex>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsSolvers
///
/// is a sparse solver for the package's complex Hermitian positive definite
/// systems: SuiteSparse's CHOLMOD, which chooses the fill-reducing ordering
/// (AMD, or METIS when AMD's fill is large and CHOLMOD was built with it) and
/// between a simplicial \f$ LDL^* \f$ and a supernodal \f$ LL^* \f$
/// factorization (supernodal, with BLAS, when the factor is dense enough).
/// It is `Direct_sparse_solver` (the direct solver of `Default_sparse_solver`)
/// when `CGAL_PVF_HAS_CHOLMOD` is defined.
///
/// It is a model of `SparseLinearAlgebraWithFactorTraits_d` on
/// `std::complex<double>` (Eigen's `CholmodDecomposition` through
/// `CGAL::Eigen_solver_traits`, its base class), to be given as the `SolverTraits` template
/// parameter of `Polyvector_field_designer` or with the `sparse_linear_solver`
/// named parameter. The package drives CHOLMOD directly when it receives this
/// type: the symbolic analysis is done once for all the coefficient degrees of
/// a field (they share one sparsity pattern) and kept for later numeric
/// refactorizations; the degrees may then be factored in parallel.
///
/// A matrix that is not positive definite makes the factorization fail, and the
/// algorithm then returns `Error_code::SOLVER_FAILURE`.
///
/// For speed, CHOLMOD needs an optimised BLAS (Debian: `libopenblas0-pthread`,
/// which `scripts/install_dependencies.sh` installs); the reference BLAS makes
/// the supernodal factorization about twice as slow on large meshes. While the
/// package factors and solves with CHOLMOD, OpenBLAS runs on one thread (its
/// thread count is restored afterwards): its threads do not speed up these
/// factors, would compete with the parallel degrees, and would change the
/// rounding between parallel and sequential runs.
///
/// It is a type of its own (not a typedef) so that the package's CHOLMOD
/// driver is chosen for it in every translation unit.
///
/// \sa `Default_sparse_solver`, `Simplicial_ldlt_solver`
class Cholmod_sparse_solver
  : public CGAL::Eigen_solver_traits<Eigen::CholmodDecomposition<Eigen::SparseMatrix<std::complex<double> >, Eigen::Lower> >
{
public:
  /// CHOLMOD's default settings.
  Cholmod_sparse_solver() {}
};

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE

#endif // CGAL_POLYVECTOR_FIELDS_CHOLMOD_SOLVER_H
