// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_CHOLMOD_FACTORIZATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_CHOLMOD_FACTORIZATION_H

// The model of the SparseFactorization concept for `Cholmod_sparse_solver`, driving CHOLMOD's C
// interface directly rather than through Eigen's wrapper, for two reasons:
// - all blocks of a system share one pattern, so CHOLMOD's symbolic analysis
//   (fill-reducing ordering, elimination tree, supernodes) is done once, on
//   the first block, and each block factors a copy of that symbolic factor;
// - each Sparse_factorization owns its `cholmod_common`, so that the blocks can be
//   factored at the same time in different threads (CHOLMOD is reentrant as
//   long as no two threads share a `cholmod_common`).
// The matrices are given to CHOLMOD without a copy: full Hermitian storage
// read as "lower triangle only" (stype = -1).
//
// CHOLMOD chooses the ordering (AMD, or METIS when AMD's fill is large) and
// between simplicial LDL^* and supernodal LL^* (by the ratio of flops to
// factor entries), as in Eigen's `CholmodDecomposition` default mode.

#include <CGAL/Polyvector_fields/Sparse_factorization.h>
#include <CGAL/Polyvector_fields/internal/Solvers/Single_threaded_blas_scope.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <cholmod.h>

#include <cstddef>
#include <cstring>
#include <memory>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

typedef Eigen::CholmodDecomposition<Sparse_matrix, Eigen::Lower> Cholmod_decomposition;

} // namespace internal

class Cholmod_sparse_solver;  // Cholmod_solver.h

namespace internal {

// A `cholmod_common` that starts and finishes with its owner.
class Cholmod_workspace
{
public:
  // CHOLMOD prints its warnings (a matrix not positive definite) on stdout by
  // default; the package reports them as Error_code::SOLVER_FAILURE instead.
  Cholmod_workspace()
  {
    cholmod_start(&m_common);
    m_common.print = 0;
  }
  ~Cholmod_workspace() { cholmod_finish(&m_common); }
  Cholmod_workspace(const Cholmod_workspace&) = delete;
  Cholmod_workspace& operator=(const Cholmod_workspace&) = delete;
  cholmod_common* get() { return &m_common; }

private:
  cholmod_common m_common;
};

// CHOLMOD's symbolic factor of one pattern, shared by the blocks of a system.
struct Cholmod_symbolic_analysis
{
  Cholmod_workspace workspace;
  cholmod_factor* symbolic = nullptr;  // owned; only read once computed

  ~Cholmod_symbolic_analysis()
  {
    if(symbolic != nullptr)
      cholmod_free_factor(&symbolic, workspace.get());
  }
};

// A view of `A` (compressed, column-major, complex) as a CHOLMOD Hermitian
// matrix of which only the lower triangle is read.
inline cholmod_sparse cholmod_view(const Sparse_matrix& A)
{
  cholmod_sparse S;
  std::memset(&S, 0, sizeof(S));
  S.nrow = std::size_t(A.rows());
  S.ncol = std::size_t(A.cols());
  S.nzmax = std::size_t(A.nonZeros());
  S.p = const_cast<int*>(A.outerIndexPtr());
  S.i = const_cast<int*>(A.innerIndexPtr());
  S.x = const_cast<Complex*>(A.valuePtr());
  S.z = nullptr;
  S.nz = nullptr;
  S.stype = -1;
  S.itype = CHOLMOD_INT;
  S.xtype = CHOLMOD_COMPLEX;
  S.dtype = CHOLMOD_DOUBLE;
  S.sorted = 1;
  S.packed = 1;
  return S;
}

} // namespace internal

template <>
class Sparse_factorization<Cholmod_sparse_solver, std::complex<double> >
{
  typedef internal::Sparse_matrix Sparse_matrix;
  typedef internal::Complex Complex;

public:
  typedef internal::Sparse_matrix Matrix;
  typedef Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic> Dense_matrix;
  typedef internal::Cholmod_symbolic_analysis Shared_analysis;
  typedef internal::Single_threaded_blas_scope Solver_scope;
  static constexpr bool is_thread_safe = true;
  static constexpr bool keeps_matrix = false;  // CHOLMOD reads the matrix during the call only

  Sparse_factorization() {}
  explicit Sparse_factorization(const Cholmod_sparse_solver&) {}

  ~Sparse_factorization()
  {
    if(m_factor != nullptr)
      cholmod_free_factor(&m_factor, m_workspace.get());
  }

  Sparse_factorization(const Sparse_factorization&) = delete;
  Sparse_factorization& operator=(const Sparse_factorization&) = delete;

  void share_analysis(const std::shared_ptr<Shared_analysis>& analysis) { m_analysis = analysis; }

  // The first call on a shared analysis computes it; the others copy it.
  // The first call must not run concurrently with the others.
  // A matrix without rows (a system without unknowns) is factored trivially:
  // CHOLMOD refuses it.
  bool analyze(const Sparse_matrix& A)
  {
    m_empty = false;
    if(!A.isCompressed() || A.rows() != A.cols())
      return false;
    if(m_factor != nullptr)
      cholmod_free_factor(&m_factor, m_workspace.get());
    if(A.rows() == 0)
      return (m_empty = true);
    if(!m_analysis)
      m_analysis = std::make_shared<Shared_analysis>();
    if(m_factor != nullptr)
      cholmod_free_factor(&m_factor, m_workspace.get());
    cholmod_sparse S = internal::cholmod_view(A);
    if(m_analysis->symbolic == nullptr)
    {
      m_analysis->symbolic = cholmod_analyze(&S, m_analysis->workspace.get());
      if(m_analysis->symbolic == nullptr || m_analysis->workspace.get()->status != CHOLMOD_OK)
        return false;
    }
    m_factor = cholmod_copy_factor(m_analysis->symbolic, m_workspace.get());
    return m_factor != nullptr;
  }

  bool factorize(const Sparse_matrix& A)
  {
    if(m_empty)
      return A.rows() == 0 && A.cols() == 0;
    if(m_factor == nullptr || !A.isCompressed() || std::size_t(A.rows()) != m_factor->n || A.cols() != A.rows())
      return false;
    cholmod_sparse S = internal::cholmod_view(A);
    cholmod_common* common = m_workspace.get();
    if(!cholmod_factorize(&S, m_factor, common))
      return false;
    // CHOLMOD_NOT_POSDEF is a warning for CHOLMOD, a failure for us.
    if(common->status != CHOLMOD_OK || m_factor->minor != m_factor->n)
      return false;
    // A simplicial LDL^* factorization only stops at a zero pivot: a negative
    // one (an indefinite matrix) must be refused here. D(j) is the first entry
    // of column j (complex entries: real parts at even offsets).
    if(!m_factor->is_super && !m_factor->is_ll)
    {
      const int* Lp = static_cast<const int*>(m_factor->p);
      const double* Lx = static_cast<const double*>(m_factor->x);
      for(std::size_t j = 0; j < m_factor->n; ++j)
        if(!(Lx[2 * std::size_t(Lp[j])] > 0))
          return false;
    }
    return true;
  }

  // All the columns of B in one call.
  bool solve(const Dense_matrix& b, Dense_matrix& x)
  {
    if(m_empty && b.rows() == 0)
    {
      x.resize(0, b.cols());
      return true;
    }
    if(m_factor == nullptr || std::size_t(b.rows()) != m_factor->n)
      return false;
    cholmod_dense B;
    std::memset(&B, 0, sizeof(B));
    B.nrow = m_factor->n;
    B.ncol = std::size_t(b.cols());
    B.nzmax = m_factor->n * std::size_t(b.cols());
    B.d = m_factor->n;
    B.x = const_cast<Complex*>(b.data());
    B.z = nullptr;
    B.xtype = CHOLMOD_COMPLEX;
    B.dtype = CHOLMOD_DOUBLE;
    cholmod_common* common = m_workspace.get();
    x.resize(b.rows(), b.cols());  // before CHOLMOD allocates: nothing below throws
    cholmod_dense* X = cholmod_solve(CHOLMOD_A, m_factor, &B, common);
    if(X == nullptr)
      return false;
    std::memcpy(x.data(), X->x, std::size_t(x.size()) * sizeof(Complex));
    cholmod_free_dense(&X, common);
    return common->status == CHOLMOD_OK;
  }

private:
  internal::Cholmod_workspace m_workspace;
  std::shared_ptr<Shared_analysis> m_analysis;
  cholmod_factor* m_factor = nullptr;
  bool m_empty = false;  // the analysed matrix has no row
};

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_CHOLMOD_FACTORIZATION_H
