// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FACTORIZATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FACTORIZATION_H

// One sparse Hermitian factorization behind a model of CGAL's
// `SparseLinearAlgebraWithFactorTraits_d`.
//
// The package assembles its matrices as `Eigen::SparseMatrix<std::complex<double>>`
// (full Hermitian storage). For `CGAL::Eigen_solver_traits<S>` the Eigen
// solver `S` is driven directly, so that the symbolic analysis
// (`analyzePattern`) and the numeric factorization (`factorize`) are separate
// steps: a matrix whose values change but whose pattern does not (a new lambda
// in the frame-field iterations) is only refactored numerically. Any other
// model goes through its own `Matrix`, `Vector`, `factor()` and
// `linear_solver()`.

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/Sparse>

#include <complex>
#include <cstddef>
#include <memory>
#include <utility>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

typedef std::complex<double> Complex;
typedef Eigen::SparseMatrix<Complex> Sparse_matrix;
typedef Eigen::Matrix<Complex, Eigen::Dynamic, 1> Dense_vector;

// Generic model of SparseLinearAlgebraWithFactorTraits_d.
template <typename SolverTraits>
class Factorization
{
public:
  explicit Factorization(const SolverTraits& prototype = SolverTraits()) : m_traits(prototype) {}

  // Both steps at once: the generic concept has no separate symbolic step.
  bool analyze(const Sparse_matrix&) { return true; }

  bool factorize(const Sparse_matrix& A)
  {
    m_matrix.reset(new typename SolverTraits::Matrix(A.rows(), A.cols()));
    for(int k = 0; k < A.outerSize(); ++k)
      for(Sparse_matrix::InnerIterator it(A, k); it; ++it)
        m_matrix->add_coef(it.row(), it.col(), it.value());
    typename SolverTraits::NT D;
    return m_traits.factor(*m_matrix, D);
  }

  bool solve(const Dense_vector& b, Dense_vector& x)
  {
    typename SolverTraits::Vector B(b.size()), X(b.size());
    for(Eigen::Index i = 0; i < b.size(); ++i)
      B[i] = b[i];
    if(!m_traits.linear_solver(B, X))
      return false;
    x.resize(b.size());
    for(Eigen::Index i = 0; i < b.size(); ++i)
      x[i] = X[i];
    return true;
  }

private:
  SolverTraits m_traits;
  std::unique_ptr<typename SolverTraits::Matrix> m_matrix;  // factor() may keep a pointer to it
};

// Eigen solvers: separate symbolic and numeric steps. Each Factorization owns
// its own Eigen solver (copies of Eigen_solver_traits would share one).
template <typename EigenSolver>
class Factorization<CGAL::Eigen_solver_traits<EigenSolver> >
{
public:
  explicit Factorization(const CGAL::Eigen_solver_traits<EigenSolver>& = CGAL::Eigen_solver_traits<EigenSolver>())
    : m_solver(new EigenSolver)
  {}

  bool analyze(const Sparse_matrix& A)
  {
    m_solver->analyzePattern(A);
    return m_solver->info() == Eigen::Success;
  }

  bool factorize(const Sparse_matrix& A)
  {
    m_solver->factorize(A);
    return m_solver->info() == Eigen::Success;
  }

  bool solve(const Dense_vector& b, Dense_vector& x)
  {
    x = m_solver->solve(b);
    return m_solver->info() == Eigen::Success;
  }

private:
  std::unique_ptr<EigenSolver> m_solver;
};

} // namespace internal

/// \ingroup PkgPolyvectorFieldsSolvers
///
/// is the default sparse solver of the package: Eigen's `SimplicialLDLT` on
/// complex Hermitian matrices, through `CGAL::Eigen_solver_traits`.
typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<std::complex<double> > > >
  Default_sparse_solver;

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FACTORIZATION_H
