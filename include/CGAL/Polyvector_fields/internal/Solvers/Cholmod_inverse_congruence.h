// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_CHOLMOD_INVERSE_CONGRUENCE_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_CHOLMOD_INVERSE_CONGRUENCE_H

// The optional operation inverse_congruence() of the SparseFactorization
// concept, G = C^T A^-1 C for a sparse C, for Eigen's CHOLMOD solvers on real
// matrices (CholmodDecomposition, the default solver of the integer-grid map).
//
// With the factor P A P^T = L D L^T (D = I for an LL^T factor),
// G = W^T D^-1 W with W = L^-1 P C. A column of C with a few entries gives a
// column of W whose entries lie on the reach of those entries in the
// elimination tree: CHOLMOD's forward solve with a sparse right-hand side
// (cholmod_solve2 with a Bset) visits only those columns of L. On the factor
// of a surface mesh's matrix the reach is a small part of the n unknowns, so
// the m forward solves cost far less than m full solves (forward and backward
// over the whole factor), which is how a generic model computes G.
//
// Eigen keeps CHOLMOD's factor in a protected member; a class derived from
// the Eigen solver reads it. The header also gives Eigen's CHOLMOD solvers on
// real matrices the Solver_scope of the package's own CHOLMOD model.

#include <CGAL/Polyvector_fields/internal/Solvers/cholmod_available.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
#  include <CGAL/Polyvector_fields/internal/Solvers/Single_threaded_blas_scope.h>
#  include <Eigen/CholmodSupport>
#  include <cholmod.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// Whether the Eigen solver is one of Eigen's CHOLMOD solvers on real matrices
// with int indices; if so, `Solver` is the class that reads its factor, and
// `Solver_scope` keeps OpenBLAS on one thread while it is used (as for
// Cholmod_sparse_solver, and for the same reasons: the results of a
// supernodal factor depend on OpenBLAS's number of threads, and its threads
// slow CHOLMOD down when the cores are busy).
template <typename EigenSolver, typename = void>
struct Eigen_cholmod_solver
{
  static constexpr bool value = false;
  typedef EigenSolver Solver;
  struct Solver_scope
  {};
};

#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE

// A CHOLMOD factor freed with its owner.
class Cholmod_factor_copy
{
public:
  Cholmod_factor_copy(cholmod_factor* original, cholmod_common* common)
    : m_factor(cholmod_copy_factor(original, common)), m_common(common)
  {}
  ~Cholmod_factor_copy()
  {
    if(m_factor != nullptr)
      cholmod_free_factor(&m_factor, m_common);
  }
  Cholmod_factor_copy(const Cholmod_factor_copy&) = delete;
  Cholmod_factor_copy& operator=(const Cholmod_factor_copy&) = delete;
  cholmod_factor* get() const { return m_factor; }

private:
  cholmod_factor* m_factor;
  cholmod_common* m_common;
};

// The dense and sparse workspaces of cholmod_solve2(), freed with their owner.
struct Cholmod_solve2_workspace
{
  explicit Cholmod_solve2_workspace(cholmod_common* c) : common(c) {}
  ~Cholmod_solve2_workspace()
  {
    cholmod_free_dense(&B, common);
    cholmod_free_sparse(&Bset, common);
    cholmod_free_dense(&X, common);
    cholmod_free_sparse(&Xset, common);
    cholmod_free_dense(&Y, common);
    cholmod_free_dense(&E, common);
  }
  Cholmod_solve2_workspace(const Cholmod_solve2_workspace&) = delete;
  Cholmod_solve2_workspace& operator=(const Cholmod_solve2_workspace&) = delete;

  cholmod_common* common;
  cholmod_dense* B = nullptr;
  cholmod_sparse* Bset = nullptr;
  cholmod_dense* X = nullptr;
  cholmod_sparse* Xset = nullptr;
  cholmod_dense* Y = nullptr;
  cholmod_dense* E = nullptr;
};

// G = C^T A^-1 C for the numeric factor `factor` of A (see the top of the
// file). `factor` is not changed: the sparse forward solves need a simplicial
// factor, so a supernodal one is converted on a copy (the next numeric
// factorization of the solver keeps its supernodes). Returns false on a
// CHOLMOD failure or a pivot that is not positive.
inline bool cholmod_inverse_congruence(cholmod_factor* factor, cholmod_common* common,
                                       const Eigen::SparseMatrix<double>& C, Eigen::MatrixXd& G)
{
  const std::size_t n = factor->n, m = std::size_t(C.cols());
  if(std::size_t(C.rows()) != n || factor->xtype != CHOLMOD_REAL || factor->itype != CHOLMOD_INT)
    return false;
  G.setZero(Eigen::Index(m), Eigen::Index(m));
  if(m == 0 || n == 0)
    return true;
  // A simplicial factor is read as it is (the solves do not change it); a
  // supernodal one is converted on a copy.
  std::unique_ptr<Cholmod_factor_copy> copy;
  cholmod_factor* L = factor;
  if(factor->is_super)
  {
    copy.reset(new Cholmod_factor_copy(factor, common));
    L = copy->get();
    if(L == nullptr || !cholmod_change_factor(CHOLMOD_REAL, /*to_ll*/ 1, /*to_super*/ 0, /*to_packed*/ 1,
                                              /*to_monotonic*/ 1, L, common))
      return false;
  }

  // D^(-1/2) (the first entry of each column of a simplicial LDL^T factor is
  // D's; an LL^T factor has D = I), and P as the new position of each row.
  const int* Lp = static_cast<const int*>(L->p);
  const double* Lx = static_cast<const double*>(L->x);
  std::vector<double> scale(n, 1.0);
  if(!L->is_ll)
    for(std::size_t k = 0; k < n; ++k)
    {
      const double d = Lx[Lp[k]];
      if(!(d > 0))
        return false;
      scale[k] = 1 / std::sqrt(d);
    }
  std::vector<int> position(n);
  const int* perm = static_cast<const int*>(L->Perm);
  for(std::size_t k = 0; k < n; ++k)
    position[perm != nullptr ? std::size_t(perm[k]) : k] = int(k);

  // The columns of D^(-1/2) W, one forward solve each.
  Cholmod_solve2_workspace work(common);
  work.B = cholmod_zeros(n, 1, CHOLMOD_REAL, common);
  Eigen::Index longest = 0;
  for(Eigen::Index j = 0; j < C.outerSize(); ++j)
    longest = (std::max)(longest, Eigen::Index(C.outerIndexPtr()[j + 1] - C.outerIndexPtr()[j]));
  work.Bset = cholmod_allocate_sparse(n, 1, std::size_t((std::max)(longest, Eigen::Index(1))), /*sorted*/ 0,
                                      /*packed*/ 1, /*stype*/ 0, CHOLMOD_PATTERN, common);
  if(work.B == nullptr || work.Bset == nullptr)
    return false;
  double* b = static_cast<double*>(work.B->x);
  int* bset_p = static_cast<int*>(work.Bset->p);
  int* bset_i = static_cast<int*>(work.Bset->i);
  std::vector<int> row_of, column_of;  // the entries of D^(-1/2) W, column after column
  std::vector<double> value_of;
  for(Eigen::Index j = 0; j < Eigen::Index(m); ++j)
  {
    int count = 0;
    for(Eigen::SparseMatrix<double>::InnerIterator it(C, j); it; ++it)
    {
      const int k = position[std::size_t(it.row())];
      bset_i[count++] = k;
      b[k] = it.value();
    }
    if(count == 0)
      continue;  // a zero column of C: a zero row and column of G
    bset_p[0] = 0;
    bset_p[1] = count;
    if(!cholmod_solve2(CHOLMOD_L, L, work.B, work.Bset, &work.X, &work.Xset, &work.Y, &work.E, common))
      return false;
    const int* xset_i = static_cast<const int*>(work.Xset->i);
    const int reach = static_cast<const int*>(work.Xset->p)[1];
    const double* x = static_cast<const double*>(work.X->x);
    for(int p = 0; p < reach; ++p)
    {
      const std::size_t k = std::size_t(xset_i[p]);
      if(x[k] == 0)
        continue;
      row_of.push_back(int(k));
      column_of.push_back(int(j));
      value_of.push_back(x[k] * scale[k]);
    }
  }
  if(common->status != CHOLMOD_OK)
    return false;

  // G = (D^(-1/2) W)^T (D^(-1/2) W), row after row of W: a row with few
  // entries adds their products one by one; the rows that reach most columns
  // (the separators near the root of the elimination tree) are gathered in a
  // dense block and added by one rank update.
  std::vector<std::size_t> start(n + 1, 0);
  for(int k : row_of)
    ++start[std::size_t(k) + 1];
  for(std::size_t k = 0; k < n; ++k)
    start[k + 1] += start[k];
  std::vector<int> entry_column(row_of.size());
  std::vector<double> entry_value(row_of.size());
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for(std::size_t e = 0; e < row_of.size(); ++e)  // by column: each row's columns stay increasing
    {
      const std::size_t at = next[std::size_t(row_of[e])]++;
      entry_column[at] = column_of[e];
      entry_value[at] = value_of[e];
    }
  }
  const std::size_t dense_from = (std::max)(std::size_t(8), m / 4);
  std::vector<std::size_t> dense_rows;
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::size_t length = start[k + 1] - start[k];
    if(length >= dense_from)
    {
      dense_rows.push_back(k);
      continue;
    }
    for(std::size_t p = start[k]; p < start[k + 1]; ++p)
      for(std::size_t q = start[k]; q <= p; ++q)
        G(entry_column[p], entry_column[q]) += entry_value[p] * entry_value[q];
  }
  if(!dense_rows.empty())
  {
    Eigen::MatrixXd U = Eigen::MatrixXd::Zero(Eigen::Index(m), Eigen::Index(dense_rows.size()));
    for(std::size_t r = 0; r < dense_rows.size(); ++r)
      for(std::size_t p = start[dense_rows[r]]; p < start[dense_rows[r] + 1]; ++p)
        U(entry_column[p], Eigen::Index(r)) = entry_value[p];
    G.selfadjointView<Eigen::Lower>().rankUpdate(U);
  }
  G.triangularView<Eigen::StrictlyUpper>() = G.transpose();
  return true;
}

template <typename EigenSolver>
struct Eigen_cholmod_solver<
  EigenSolver,
  std::enable_if_t<std::is_base_of<Eigen::CholmodBase<typename EigenSolver::MatrixType, EigenSolver::UpLo, EigenSolver>,
                                   EigenSolver>::value &&
                   std::is_same<typename EigenSolver::Scalar, double>::value &&
                   std::is_same<typename EigenSolver::StorageIndex, int>::value> >
{
  static constexpr bool value = true;
  typedef Single_threaded_blas_scope Solver_scope;

  class Solver : public EigenSolver
  {
  public:
    cholmod_factor* factor() const { return this->m_cholmodFactor; }
    cholmod_common* common() { return &this->cholmod(); }
  };

  static bool inverse_congruence(Solver& solver, const Eigen::SparseMatrix<double>& C, Eigen::MatrixXd& G)
  {
    return solver.factor() != nullptr && cholmod_inverse_congruence(solver.factor(), solver.common(), C, G);
  }
};

#endif // CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_CHOLMOD_INVERSE_CONGRUENCE_H
