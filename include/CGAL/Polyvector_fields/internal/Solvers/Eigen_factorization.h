// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_EIGEN_FACTORIZATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_EIGEN_FACTORIZATION_H

// The model of the SparseFactorization concept for `CGAL::Eigen_solver_traits<S>`
// (Simplicial_ldlt_solver, and the real direct solvers): the Eigen solver `S`
// is driven directly, so that the symbolic analysis (`analyzePattern`) and the
// numeric factorization (`factorize`) are separate steps: a matrix whose values
// change but whose pattern does not (a new lambda in the frame-field
// iterations) is only refactored numerically. Each Sparse_factorization owns
// its Eigen solver (copies of Eigen_solver_traits would share one).
//
// All degrees of a field share one sparsity pattern, so for Eigen's
// SimplicialLDLT and SimplicialLLT with their default AMD ordering the
// fill-reducing permutation, the expensive part of the symbolic analysis, is
// computed once and shared (Shared_ordering): each degree's matrix is permuted
// with it and factored by the same solver with the natural ordering, whose own
// analysis is only the elimination tree. (Cholmod_factorization.h does the same for CHOLMOD with its whole symbolic
// factor.)
//
// Eigen's CHOLMOD solvers on real matrices (the default solver of the map and
// of the planarizer) get two more things, from Cholmod_inverse_congruence.h:
// the optional operation inverse_congruence() by sparse forward solves, and
// the Solver_scope that keeps OpenBLAS on one thread.

#include <CGAL/Polyvector_fields/Sparse_factorization.h>
#include <CGAL/Polyvector_fields/internal/Solvers/Cholmod_inverse_congruence.h>

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/Sparse>

#include <complex>
#include <memory>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// A fill-reducing permutation P shared by factorizations of matrices with one
// pattern; they factor P A P^T.
struct Shared_ordering
{
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P;
  bool computed = false;
};

// Which Eigen solvers can use a shared ordering, and their natural-ordering twin.
template <typename EigenSolver>
struct Natural_ordering_twin
{
  typedef void type;
};

template <typename Matrix, int UpLo>
struct Natural_ordering_twin<Eigen::SimplicialLDLT<Matrix, UpLo, Eigen::AMDOrdering<int> > >
{
  typedef Eigen::SimplicialLDLT<Matrix, UpLo, Eigen::NaturalOrdering<int> > type;
};

template <typename Matrix, int UpLo>
struct Natural_ordering_twin<Eigen::SimplicialLLT<Matrix, UpLo, Eigen::AMDOrdering<int> > >
{
  typedef Eigen::SimplicialLLT<Matrix, UpLo, Eigen::NaturalOrdering<int> > type;
};

// Eigen's CHOLMOD wrappers report success from analyzePattern() even when
// CHOLMOD's analysis failed (and then dereference the missing factor in
// factorize()): their `cholmod()` workspace tells.
template <typename Solver, typename = void>
struct Has_cholmod_workspace : std::false_type
{};

template <typename Solver>
struct Has_cholmod_workspace<Solver, std::void_t<decltype(std::declval<Solver&>().cholmod().status)> > : std::true_type
{};

} // namespace internal

template <typename EigenSolver, typename Scalar>
class Sparse_factorization<CGAL::Eigen_solver_traits<EigenSolver>, Scalar>
{
  static_assert(std::is_same<typename EigenSolver::Scalar, Scalar>::value,
                "Sparse_factorization: the Eigen solver's scalar type must be the system's");
  typedef typename internal::Natural_ordering_twin<EigenSolver>::type Twin;
  // The blocks of a field share the ordering. The real systems of the package
  // (the integer-grid map, the planarizer) are single matrices: nothing to
  // share, and the solver orders them itself.
  static constexpr bool shares_ordering =
    !std::is_void<Twin>::value && std::is_same<Scalar, std::complex<double> >::value;
  // Eigen's CHOLMOD solvers on real matrices are driven through a class that
  // reads their factor, for inverse_congruence(), with OpenBLAS on one thread.
  typedef internal::Eigen_cholmod_solver<EigenSolver> Cholmod_traits;
  typedef typename std::conditional<shares_ordering, Twin, typename Cholmod_traits::Solver>::type Solver;

public:
  typedef Eigen::SparseMatrix<Scalar> Matrix;
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Dense_matrix;
  typedef internal::Shared_ordering Shared_analysis;
  typedef typename Cholmod_traits::Solver_scope Solver_scope;

  // Each factorization owns its solver; a shared ordering is only read once computed.
  static constexpr bool is_thread_safe = true;
  // A shared ordering factors a permuted copy; another Eigen solver may keep
  // a reference to the matrix (the iterative ones do).
  static constexpr bool keeps_matrix = !shares_ordering;

  explicit Sparse_factorization(const CGAL::Eigen_solver_traits<EigenSolver>& = CGAL::Eigen_solver_traits<EigenSolver>())
    : m_solver(new Solver)
  {}
  Sparse_factorization(const Sparse_factorization&) = delete;
  Sparse_factorization& operator=(const Sparse_factorization&) = delete;

  // Factorizations of matrices with the same pattern may share one ordering.
  void share_analysis(const std::shared_ptr<Shared_analysis>& ordering) { m_ordering = ordering; }

  // A matrix without rows (a system without unknowns) is factored trivially:
  // Eigen's and CHOLMOD's solvers do not all accept it.
  bool analyze(const Matrix& A)
  {
    m_rows = A.rows();
    m_analyzed = m_factored = false;
    if(A.rows() != A.cols())
      return false;
    if(A.rows() == 0)
      return (m_analyzed = true);
    if constexpr(shares_ordering)
    {
      if(!m_ordering)
        m_ordering = std::make_shared<Shared_analysis>();
      if(!m_ordering->computed)
      {
        Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
        Eigen::AMDOrdering<int>()(A, inverse);  // A holds both triangles
        m_ordering->P = inverse.inverse();
        m_ordering->computed = true;
      }
      m_solver->analyzePattern(permuted(A));
    }
    else
      m_solver->analyzePattern(A);
    if constexpr(internal::Has_cholmod_workspace<Solver>::value)
      if(m_solver->cholmod().status < 0)  // CHOLMOD_OK is 0, errors are negative
        return false;
    m_analyzed = (m_solver->info() == Eigen::Success);
    return m_analyzed;
  }

  bool factorize(const Matrix& A)
  {
    m_factored = false;
    if(!m_analyzed || A.rows() != m_rows || A.cols() != m_rows)
      return false;
    if(A.rows() == 0)
      return (m_factored = true);
    if constexpr(shares_ordering)
      m_solver->factorize(permuted(A));
    else
      m_solver->factorize(A);
    m_factored = (m_solver->info() == Eigen::Success);
    return m_factored;
  }

  bool solve(const Dense_matrix& B, Dense_matrix& X)
  {
    if(!m_factored || B.rows() != m_rows)
      return false;
    if(m_rows == 0)
    {
      X.resize(0, B.cols());
      return true;
    }
    if constexpr(shares_ordering)
    {
      // A X = B  <=>  (P A P^T)(P X) = P B
      const Dense_matrix Y = m_solver->solve(m_ordering->P * B);
      X = m_ordering->P.inverse() * Y;
    }
    else
      X = m_solver->solve(B);
    return m_solver->info() == Eigen::Success;
  }

  // G = C^T A^-1 C for a sparse C, the optional operation of the concept,
  // for Eigen's CHOLMOD solvers on real matrices only: sparse forward solves
  // (Cholmod_inverse_congruence.h).
  template <bool available = Cholmod_traits::value, std::enable_if_t<available, int> = 0>
  bool inverse_congruence(const Matrix& C, Dense_matrix& G)
  {
    if(!m_factored || C.rows() != m_rows)
      return false;
    if(m_rows == 0)
    {
      G.setZero(C.cols(), C.cols());
      return true;
    }
    return Cholmod_traits::inverse_congruence(*m_solver, C, G);
  }

private:
  // The lower triangle of P A P^T, which the natural-ordering solver reads.
  Matrix permuted(const Matrix& A) const
  {
    Matrix B(A.rows(), A.cols());
    B.template selfadjointView<Eigen::Lower>() = A.template selfadjointView<Eigen::Lower>().twistedBy(m_ordering->P);
    return B;
  }

  std::unique_ptr<Solver> m_solver;
  std::shared_ptr<Shared_analysis> m_ordering;
  Eigen::Index m_rows = 0;
  bool m_analyzed = false, m_factored = false;
};

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_EIGEN_FACTORIZATION_H
