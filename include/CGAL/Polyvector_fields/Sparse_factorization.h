// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_SPARSE_FACTORIZATION_H
#define CGAL_POLYVECTOR_FIELDS_SPARSE_FACTORIZATION_H

/// \file Sparse_factorization.h
///
/// The traits class through which the package factors and solves every sparse
/// system, and its generic model for any `SparseLinearAlgebraWithFactorTraits_d`.

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <complex>
#include <cstddef>
#include <memory>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsSolvers
///
/// is the factorization of one sparse Hermitian (for `Scalar = std::complex<double>`)
/// or symmetric (for `Scalar = double`) positive definite matrix by the sparse
/// solver `SolverTraits`: every linear system of the package is factored and
/// solved through a class of this template. Each specialization is a model of
/// the concept `SparseFactorization`; a new back end is one specialization
/// (see Section \ref pvf_solver_concept of the manual).
///
/// The package specializes it for `Cholmod_sparse_solver`, `Amg_sparse_solver`,
/// `Adaptive_sparse_solver`, and `CGAL::Eigen_solver_traits` (this header
/// includes that last one, so that every translation unit that names the
/// template sees it). The primary template, documented here, drives any model
/// of `SparseLinearAlgebraWithFactorTraits_d` whose number type is `Scalar`
/// through its `factor()` and `linear_solver()`: the matrix is copied into the
/// model's `Matrix`, and the numeric factorization is redone from scratch on
/// every call. Copies of such a model may share state (copies of
/// `CGAL::Eigen_solver_traits` share their Eigen solver), so the primary template
/// sets `is_thread_safe` to `false` and the blocks of a system are then
/// factored one after the other; a specialization that owns its state gets
/// them factored in parallel.
///
/// It is a model of the concept `SparseFactorization`.
///
/// \tparam SolverTraits the sparse solver, as given to the `sparse_linear_solver`
///         named parameter or to the `SolverTraits` template parameter of
///         `Polyvector_field_designer`
/// \tparam Scalar `std::complex<double>` or `double`
template <typename SolverTraits, typename Scalar>
class Sparse_factorization
{
public:
  /// \name Types
  /// @{
  typedef Eigen::SparseMatrix<Scalar> Matrix;                               ///< both triangles stored, column-major
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Dense_matrix;  ///< right-hand sides, one per column
  /// nothing to share: the model has no separate symbolic step
  struct Shared_analysis
  {};
  /// nothing to set up
  struct Solver_scope
  {};
  /// @}

  /// copies of a `SparseLinearAlgebraWithFactorTraits_d` model may share state
  static constexpr bool is_thread_safe = false;
  /// the matrix is copied into the model's own `Matrix`
  static constexpr bool keeps_matrix = false;

  /// a factorization by a copy of `solver`.
  explicit Sparse_factorization(const SolverTraits& solver = SolverTraits()) : m_solver(solver) {}
  /// \cond SKIP_IN_MANUAL
  Sparse_factorization(const Sparse_factorization&) = delete;
  Sparse_factorization& operator=(const Sparse_factorization&) = delete;
  /// \endcond

  /// does nothing.
  void share_analysis(const std::shared_ptr<Shared_analysis>&) {}
  /// does nothing: the model's `factor()` makes both steps.
  bool analyze(const Matrix&) { return true; }

  /// copies `A` into the model's `Matrix` and calls its `factor()`. A matrix
  /// with no row (a system without unknowns) is factored trivially.
  bool factorize(const Matrix& A)
  {
    m_empty = (A.rows() == 0 && A.cols() == 0);
    m_rows = A.rows();
    m_factored = false;
    if(m_empty)
      return (m_factored = true);
    m_matrix.reset(new typename SolverTraits::Matrix(std::size_t(A.rows()), std::size_t(A.cols())));
    for(Eigen::Index k = 0; k < A.outerSize(); ++k)
      for(typename Matrix::InnerIterator it(A, k); it; ++it)
        m_matrix->add_coef(it.row(), it.col(), it.value());
    typename SolverTraits::NT D;
    m_factored = m_solver.factor(*m_matrix, D);
    return m_factored;
  }

  /// solves for each column of `B` with the model's `linear_solver()`; fails
  /// if the matrix was not factored or `B` has not its number of rows.
  bool solve(const Dense_matrix& B, Dense_matrix& X)
  {
    if(!m_factored || B.rows() != m_rows)
      return false;
    if(m_empty)
    {
      X.resize(0, B.cols());
      return true;
    }
    typename SolverTraits::Vector b(B.rows()), x(B.rows());
    X.resize(B.rows(), B.cols());
    for(Eigen::Index j = 0; j < B.cols(); ++j)
    {
      for(Eigen::Index i = 0; i < B.rows(); ++i)
        b[i] = B(i, j);
      if(!m_solver.linear_solver(b, x))
        return false;
      for(Eigen::Index i = 0; i < B.rows(); ++i)
        X(i, j) = x[i];
    }
    return true;
  }

private:
  SolverTraits m_solver;
  std::unique_ptr<typename SolverTraits::Matrix> m_matrix;  // factor() may keep a pointer to it
  Eigen::Index m_rows = 0;
  bool m_empty = false;     // a system without unknowns
  bool m_factored = false;  // the last factorize() succeeded
};

} // namespace Polyvector_fields
} // namespace CGAL

// The specialization for CGAL::Eigen_solver_traits (the model of the package's
// Simplicial_ldlt_solver and of the default real solvers).
#include <CGAL/Polyvector_fields/internal/Solvers/Eigen_factorization.h>

#endif // CGAL_POLYVECTOR_FIELDS_SPARSE_FACTORIZATION_H
