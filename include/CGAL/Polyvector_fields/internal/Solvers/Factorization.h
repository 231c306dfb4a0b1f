// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_FACTORIZATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_FACTORIZATION_H

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
//
// All degrees of a field share one sparsity pattern, so for Eigen's
// SimplicialLDLT and SimplicialLLT with their default AMD ordering the
// fill-reducing permutation, the expensive part of the symbolic analysis, is
// computed once and shared (Shared_ordering): each degree's matrix is permuted
// with it and factored by the same solver with the natural ordering, whose own
// analysis is only the elimination tree. (internal/Cholmod_factorization.h
// does the same for CHOLMOD with its whole symbolic factor.)
//
// Protocol, for every Factorization<S>:
//   share_analysis(p)   p: a std::shared_ptr<Factorization<S>::Shared_analysis>
//                       common to the factorizations of one pattern;
//   analyze(A)          the first call on a shared analysis computes it and
//                       must not run concurrently with the other calls;
//   factorize(A)        numeric factorization (again after a change of values);
//   solve(b, x).
// `keeps_matrix` tells whether the factorization may keep a reference to
// the matrix given to factorize() (Eigen's iterative solvers do), which must
// then outlive it; the others keep what they need.
// `is_thread_safe` tells whether distinct factorizations that share an
// analysis may run analyze (after the first), factorize and solve in
// different threads at the same time. An object of type `Solver_scope` is
// alive while the factorizations of a system are computed or used, whether
// in parallel or not (for CHOLMOD it keeps OpenBLAS on one thread).

#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/Sparse>

#include <complex>
#include <cstddef>
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

// Generic model of SparseLinearAlgebraWithFactorTraits_d.
template <typename SolverTraits>
class Factorization
{
public:
  // Copies of a traits model may share state: never run two at once.
  static constexpr bool is_thread_safe = false;
  // The matrix is copied into the traits' own type.
  static constexpr bool keeps_matrix = false;

  explicit Factorization(const SolverTraits& prototype = SolverTraits()) : m_traits(prototype) {}

  // The generic concept has no separate symbolic step to share.
  struct Shared_analysis
  {};
  struct Solver_scope
  {};
  void share_analysis(const std::shared_ptr<Shared_analysis>&) {}

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
  typedef typename Natural_ordering_twin<EigenSolver>::type Twin;
  static constexpr bool shares_ordering = !std::is_void<Twin>::value;
  typedef typename std::conditional<shares_ordering, Twin, EigenSolver>::type Solver;

public:
  // Each factorization owns its solver; a shared ordering is only read once computed.
  static constexpr bool is_thread_safe = true;
  // A shared ordering factors a permuted copy; another Eigen solver may keep
  // a reference to the matrix (the iterative ones do).
  static constexpr bool keeps_matrix = !shares_ordering;

  explicit Factorization(const CGAL::Eigen_solver_traits<EigenSolver>& = CGAL::Eigen_solver_traits<EigenSolver>())
    : m_solver(new Solver)
  {}

  typedef Shared_ordering Shared_analysis;
  struct Solver_scope
  {};

  // Factorizations of matrices with the same pattern may share one ordering.
  void share_analysis(const std::shared_ptr<Shared_ordering>& ordering) { m_ordering = ordering; }

  bool analyze(const Sparse_matrix& A)
  {
    if constexpr(shares_ordering)
    {
      if(!m_ordering)
        m_ordering = std::make_shared<Shared_ordering>();
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
    return m_solver->info() == Eigen::Success;
  }

  bool factorize(const Sparse_matrix& A)
  {
    if constexpr(shares_ordering)
      m_solver->factorize(permuted(A));
    else
      m_solver->factorize(A);
    return m_solver->info() == Eigen::Success;
  }

  bool solve(const Dense_vector& b, Dense_vector& x)
  {
    if constexpr(shares_ordering)
    {
      // A x = b  <=>  (P A P^T)(P x) = P b
      const Dense_vector y = m_solver->solve(m_ordering->P * b);
      x = m_ordering->P.inverse() * y;
    }
    else
      x = m_solver->solve(b);
    return m_solver->info() == Eigen::Success;
  }

private:
  // The lower triangle of P A P^T, which the natural-ordering solver reads.
  Sparse_matrix permuted(const Sparse_matrix& A) const
  {
    Sparse_matrix B(A.rows(), A.cols());
    B.template selfadjointView<Eigen::Lower>() = A.template selfadjointView<Eigen::Lower>().twistedBy(m_ordering->P);
    return B;
  }

  std::unique_ptr<Solver> m_solver;
  std::shared_ptr<Shared_ordering> m_ordering;
};

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_FACTORIZATION_H
