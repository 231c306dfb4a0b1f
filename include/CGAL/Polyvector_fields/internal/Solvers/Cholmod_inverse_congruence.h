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
// The forward solves (by ranges of columns) and the products of G (by blocks
// of columns) run on TBB's threads when it is linked. G does not depend on
// them: each column of W is solved alone, and each entry of G is summed in
// the same order on any number of threads.
//
// Eigen keeps CHOLMOD's factor in a protected member; a class derived from
// the Eigen solver reads it. The header also gives Eigen's CHOLMOD solvers on
// real matrices the Solver_scope of the package's own CHOLMOD model.

#include <CGAL/Polyvector_fields/internal/Solvers/cholmod_available.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
#  include <CGAL/Polyvector_fields/internal/Solvers/Single_threaded_blas_scope.h>
#  include <Eigen/CholmodSupport>
#  include <cholmod.h>
#endif

#include <algorithm>
#include <atomic>
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

// An entry of a column of D^(-1/2) W (see cholmod_inverse_congruence()).
struct Solved_entry
{
  int row;
  double value;
};

// Sparse forward solves with a simplicial factor, one column at a time: a
// CHOLMOD workspace of its own (so that several of them solve with one factor
// at the same time: cholmod_solve2() with a Bset and CHOLMOD_L only reads the
// factor) and the right-hand side, solution and work arrays of
// cholmod_solve2(), freed with it.
class Cholmod_forward_solver
{
public:
  // for factors of n rows, right-hand sides of at most `longest` entries
  Cholmod_forward_solver(std::size_t n, std::size_t longest)
  {
    cholmod_start(&m_common);
    m_B = cholmod_zeros(n, 1, CHOLMOD_REAL, &m_common);
    m_Bset = cholmod_allocate_sparse(n, 1, longest, /*sorted*/ 0, /*packed*/ 1, /*stype*/ 0, CHOLMOD_PATTERN,
                                     &m_common);
  }
  ~Cholmod_forward_solver()
  {
    cholmod_free_dense(&m_B, &m_common);
    cholmod_free_sparse(&m_Bset, &m_common);
    cholmod_free_dense(&m_X, &m_common);
    cholmod_free_sparse(&m_Xset, &m_common);
    cholmod_free_dense(&m_Y, &m_common);
    cholmod_free_dense(&m_E, &m_common);
    cholmod_finish(&m_common);
  }
  Cholmod_forward_solver(const Cholmod_forward_solver&) = delete;
  Cholmod_forward_solver& operator=(const Cholmod_forward_solver&) = delete;

  // The entries of column j of D^(-1/2) L^-1 P C (L the simplicial factor,
  // `position` P as the new position of each row, `scale` D^(-1/2)), in the
  // order of the solve's reach, without zeros; false on a CHOLMOD failure.
  bool solve(cholmod_factor* L, const Eigen::SparseMatrix<double>& C, Eigen::Index j, const std::vector<int>& position,
             const std::vector<double>& scale, std::vector<Solved_entry>& entries)
  {
    entries.clear();
    if(m_B == nullptr || m_Bset == nullptr)
      return false;
    double* b = static_cast<double*>(m_B->x);
    int* bset_p = static_cast<int*>(m_Bset->p);
    int* bset_i = static_cast<int*>(m_Bset->i);
    int count = 0;
    for(Eigen::SparseMatrix<double>::InnerIterator it(C, j); it; ++it)
    {
      const int k = position[std::size_t(it.row())];
      bset_i[count++] = k;
      b[k] = it.value();
    }
    if(count == 0)
      return true;  // a zero column of C: a zero row and column of G
    bset_p[0] = 0;
    bset_p[1] = count;
    if(!cholmod_solve2(CHOLMOD_L, L, m_B, m_Bset, &m_X, &m_Xset, &m_Y, &m_E, &m_common) ||
       m_common.status != CHOLMOD_OK)
      return false;
    const int* xset_i = static_cast<const int*>(m_Xset->i);
    const int reach = static_cast<const int*>(m_Xset->p)[1];
    const double* x = static_cast<const double*>(m_X->x);
    entries.reserve(std::size_t(reach));
    for(int p = 0; p < reach; ++p)
    {
      const std::size_t k = std::size_t(xset_i[p]);
      if(x[k] != 0)
        entries.push_back(Solved_entry{int(k), x[k] * scale[k]});
    }
    return true;
  }

private:
  cholmod_common m_common;
  cholmod_dense* m_B = nullptr;
  cholmod_sparse* m_Bset = nullptr;
  cholmod_dense* m_X = nullptr;
  cholmod_sparse* m_Xset = nullptr;
  cholmod_dense* m_Y = nullptr;
  cholmod_dense* m_E = nullptr;
};

// G = C^T A^-1 C for the numeric factor `factor` of A (see the top of the
// file). `factor` is not changed: the sparse forward solves need a simplicial
// factor, so a supernodal one is converted on a copy (the next numeric
// factorization of the solver keeps its supernodes). Returns false on a
// CHOLMOD failure or a pivot that is not positive.
inline bool cholmod_inverse_congruence(cholmod_factor* factor, cholmod_common* common,
                                       const Eigen::SparseMatrix<double>& C, Eigen::MatrixXd& G, bool parallel = true)
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

  // The columns of D^(-1/2) W, one forward solve each, by ranges of columns
  // on TBB's threads when `parallel` (each thread with its own CHOLMOD
  // workspace; the solves only read L). Each column is solved alone, so its
  // entries do not depend on the threads.
  Eigen::Index longest = 1;
  for(Eigen::Index j = 0; j < C.outerSize(); ++j)
    longest = (std::max)(longest, Eigen::Index(C.outerIndexPtr()[j + 1] - C.outerIndexPtr()[j]));
  std::vector<std::vector<Solved_entry> > column_entries(m);  // column j of D^(-1/2) W
  std::atomic<bool> failed(false);
  auto make = [n, longest]() { return Cholmod_forward_solver(n, std::size_t(longest)); };
  auto solve_range = [&](Cholmod_forward_solver& solver, std::size_t begin, std::size_t end) {
    for(std::size_t j = begin; j < end && !failed; ++j)
      if(!solver.solve(L, C, Eigen::Index(j), position, scale, column_entries[j]))
        failed = true;
  };
  if(parallel)
    for_each_range_with_scratch<CGAL::Parallel_if_available_tag>(m, 8, make, solve_range);
  else
    for_each_range_with_scratch<CGAL::Sequential_tag>(m, 8, make, solve_range);
  if(failed)
    return false;

  // G = (D^(-1/2) W)^T (D^(-1/2) W), row after row of W: a row with few
  // entries adds their products one by one; the rows that reach most columns
  // (the separators near the root of the elimination tree) are gathered in a
  // dense block U and added as U U^T, by blocks of columns (below).
  std::vector<std::size_t> start(n + 1, 0);
  for(const std::vector<Solved_entry>& column : column_entries)
    for(const Solved_entry& e : column)
      ++start[std::size_t(e.row) + 1];
  for(std::size_t k = 0; k < n; ++k)
    start[k + 1] += start[k];
  std::vector<int> entry_column(start[n]);
  std::vector<double> entry_value(start[n]);
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for(std::size_t j = 0; j < m; ++j)  // by column: each row's columns stay increasing
    {
      for(const Solved_entry& e : column_entries[j])
      {
        const std::size_t at = next[std::size_t(e.row)]++;
        entry_column[at] = int(j);
        entry_value[at] = e.value;
      }
      std::vector<Solved_entry>().swap(column_entries[j]);
    }
  }
  const std::size_t dense_from = (std::max)(std::size_t(8), m / 4);
  std::vector<std::size_t> sparse_rows, dense_rows;
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::size_t length = start[k + 1] - start[k];
    if(length >= dense_from)
      dense_rows.push_back(k);
    else if(length > 0)
      sparse_rows.push_back(k);
  }
  Eigen::MatrixXd U = Eigen::MatrixXd::Zero(Eigen::Index(m), Eigen::Index(dense_rows.size()));
  for(std::size_t r = 0; r < dense_rows.size(); ++r)
    for(std::size_t p = start[dense_rows[r]]; p < start[dense_rows[r] + 1]; ++p)
      U(entry_column[p], Eigen::Index(r)) = entry_value[p];
  // The lower triangle of G by blocks of columns, on TBB's threads when
  // `parallel`: each block adds the products of the sparse rows in the order
  // of the rows, then those of the dense rows, so that every entry is summed
  // in the same order whatever the threads.
  const std::size_t width = 32, blocks = (m + width - 1) / width;
  for_each_index(parallel, blocks, [&](std::size_t block) {
    const int c0 = int(block * width), c1 = int((std::min)(m, (block + 1) * width));
    for(std::size_t k : sparse_rows)
    {
      const int* first = entry_column.data() + start[k];
      const int* last = entry_column.data() + start[k + 1];
      if(last[-1] < c0 || first[0] >= c1)
        continue;
      const std::size_t end = start[k + 1];
      for(std::size_t q = std::size_t(std::lower_bound(first, last, c0) - entry_column.data());
          q < end && entry_column[q] < c1; ++q)
        for(std::size_t p = q; p < end; ++p)
          G(entry_column[p], entry_column[q]) += entry_value[p] * entry_value[q];
    }
    if(!dense_rows.empty())
    {
      const Eigen::Index rows = Eigen::Index(m) - c0, w = c1 - c0;
      G.block(c0, c0, rows, w).noalias() += U.middleRows(c0, rows) * U.middleRows(c0, w).transpose();
    }
  });
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
