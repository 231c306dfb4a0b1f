// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_AMG_FACTORIZATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_AMG_FACTORIZATION_H

// The model of the SparseFactorization concept for Amg_sparse_solver
// (conjugate gradient preconditioned by internal/Solvers/Smoothed_aggregation.h):
//
//   share_analysis(s)  all blocks of a system share the structure of the
//                      hierarchy (aggregates, spanning trees, patterns of the
//                      prolongators and of every Galerkin operator), which
//                      depends on the pattern only;
//   analyze(A)         the first call on a shared structure builds it (not
//                      concurrently with the others); a later call with another
//                      pattern gets a structure of its own;
//   factorize(A)       the numeric setup: A's values, the phases, the damping,
//                      the smoothed prolongators, the Galerkin operators and the
//                      dense factor of the coarsest level. A later factorize (new
//                      values, same pattern) recomputes what Parameters::reuse says;
//   solve(b, x)        CG to ||b - A x|| <= tolerance ||b|| (true residual), from
//                      the previous solution when warm_start and it is closer;
//                      if CG does not converge, a direct factorization of the
//                      same matrix finishes the solve.

#include <CGAL/Polyvector_fields/Amg_sparse_solver.h>
#include <CGAL/Polyvector_fields/Sparse_factorization.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>
#include <CGAL/Polyvector_fields/internal/Solvers/Smoothed_aggregation.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
template <>
class Sparse_factorization<Amg_sparse_solver, std::complex<double> >
{
  typedef internal::Sparse_matrix Sparse_matrix;
  typedef internal::Dense_vector Dense_vector;
  typedef internal::Complex Complex;
  typedef internal::Timer Timer;

public:
  typedef internal::Sparse_matrix Matrix;
  typedef Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic> Dense_matrix;
  typedef internal::amg::Structure Shared_analysis;
  struct Solver_scope
  {};
  // Each factorization owns its values; the shared structure is only read once built.
  static constexpr bool is_thread_safe = true;
  static constexpr bool keeps_matrix = false;  // the values are copied into the hierarchy

  explicit Sparse_factorization(const Amg_sparse_solver& solver = Amg_sparse_solver())
    : m_parameters(solver.parameters()), m_statistics(solver.statistics_sink())
  {}
  Sparse_factorization(const Sparse_factorization&) = delete;
  Sparse_factorization& operator=(const Sparse_factorization&) = delete;

  void share_analysis(const std::shared_ptr<Shared_analysis>& s) { m_structure = s; }

  bool analyze(const Sparse_matrix& A)
  {
    Timer timer;
    m_empty = false;
    if(!A.isCompressed() || A.rows() != A.cols())
      return false;
    if(A.rows() == 0)  // a system without unknowns: factored trivially
    {
      m_hierarchy.reset();
      m_factored = false;
      return (m_empty = true);
    }
    if(!m_structure)
      m_structure = std::make_shared<Shared_analysis>();
    const std::uint64_t fingerprint = pattern_fingerprint(A);
    if(m_structure->computed && m_structure->input_fingerprint != fingerprint)
      m_structure = std::make_shared<Shared_analysis>();
    const bool built = !m_structure->computed;
    if(built)
    {
      internal::amg::Pattern fine;
      fine.rows = fine.cols = int(A.rows());
      fine.ptr.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
      fine.idx.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
      // A Hermitian pattern is symmetric: its columns are its rows.
      internal::amg::build_structure(std::move(fine), m_parameters, *m_structure);
      m_structure->input_fingerprint = fingerprint;
    }
    m_hierarchy.reset(new internal::amg::Hierarchy);
    m_hierarchy->structure = m_structure.get();
    m_hierarchy->sweeps = m_parameters.sweeps;
    m_factored = false;
    m_fresh_iterations = -1;
    m_last_iterations = 0;
    m_last.resize(0);
    if(built)
    {
      const double seconds = timer.elapsed();
      std::vector<int> sizes;
      for(const auto& L : m_structure->levels)
        sizes.push_back(L.A.rows);
      report([&](Amg_statistics& s) {
        ++s.analyses;
        s.analysis_seconds += seconds;
        s.level_sizes = sizes;
      });
    }
    return true;
  }

  bool factorize(const Sparse_matrix& A)
  {
    Timer timer;
    if(m_empty)
      return (m_factored = (A.rows() == 0 && A.cols() == 0));
    if(!m_hierarchy || !A.isCompressed() || pattern_fingerprint(A) != m_structure->input_fingerprint)
      return false;
    const bool first = m_hierarchy->levels.empty() || !m_factored;
    if(m_hierarchy->levels.empty())
      m_hierarchy->levels.resize(1);
    // The hierarchy stores rows; row i of a Hermitian matrix is the conjugate
    // of its column i.
    std::vector<Complex>& a = m_hierarchy->levels[0].a;
    a.resize(std::size_t(A.nonZeros()));
    const Complex* v = A.valuePtr();
    const std::vector<int>& map = m_structure->input_map;
    if(map.empty())
      for(std::size_t k = 0; k < a.size(); ++k)
        a[k] = std::conj(v[k]);
    else
      for(std::size_t k = 0; k < a.size(); ++k)
        a[k] = std::conj(v[map[k]]);
    // reuse 2: keep the coarse levels while CG needs at most 30% (and 2) more
    // iterations than right after the last whole setup.
    const bool stale = m_last_iterations > m_fresh_iterations + (std::max)(2, (3 * m_fresh_iterations) / 10);
    bool ok;
    bool reused = false;
    if(!first && m_parameters.reuse == 2 && !stale)
    {
      ok = m_hierarchy->refresh_finest();
      reused = true;
    }
    else
    {
      ok = m_hierarchy->setup(m_parameters, !first && m_parameters.reuse >= 1);
      m_fresh_iterations = -1;  // set by the next solve
    }
    m_factored = ok;
    m_direct.reset();
    const double seconds = timer.elapsed();
    report([&](Amg_statistics& s) {
      if(reused)
        ++s.reused_setups;
      else
        ++s.setups;
      s.setup_seconds += seconds;
    });
    return ok;
  }

  // One conjugate-gradient solve per column of B.
  bool solve(const Dense_matrix& B, Dense_matrix& X)
  {
    if(m_empty)
    {
      X.resize(0, B.cols());
      return m_factored && B.rows() == 0;
    }
    X.resize(B.rows(), B.cols());
    for(Eigen::Index j = 0; j < B.cols(); ++j)
    {
      Dense_vector x;
      if(!solve(Dense_vector(B.col(j)), x))
        return false;
      X.col(j) = x;
    }
    return true;
  }

  bool solve(const Dense_vector& b, Dense_vector& x)
  {
    Timer timer;
    if(m_empty)
    {
      x.resize(0);
      return m_factored && b.size() == 0;
    }
    if(!m_factored || !m_hierarchy || b.size() != m_hierarchy->structure->levels[0].A.rows)
      return false;
    const int n = int(b.size());
    // In the hierarchy's numbering.
    const std::vector<int>& perm = m_structure->permutation;
    Dense_vector bp(n), x0;
    for(int i = 0; i < n; ++i)
      bp[i] = perm.empty() ? b[i] : b[perm[std::size_t(i)]];
    if(!bp.allFinite())
      return false;
    // From the last solution (if its residual is below ||b||), else from 0.
    bool warm = m_parameters.warm_start && m_last.size() == n;
    if(warm)
      x0.swap(m_last);
    else
      x0.resize(n);
    double residual = 0;
    bool converged = false;
    const int it = internal::amg::pcg(*m_hierarchy, bp.data(), x0.data(), n, m_parameters.tolerance, m_parameters.max_iterations,
                            residual, converged, warm);
    if(it < 0)
      return false;  // not positive definite
    m_last_iterations = it;
    if(m_fresh_iterations < 0)
      m_fresh_iterations = it;
    if(!converged && !direct_solve(bp, x0))
      return false;
    x.resize(n);
    for(int i = 0; i < n; ++i)
      x[perm.empty() ? i : perm[std::size_t(i)]] = x0[i];
    if(m_parameters.warm_start)
      m_last.swap(x0);
    const double seconds = timer.elapsed();
    report([&](Amg_statistics& s) {
      ++s.solves;
      s.iterations += std::size_t(it);
      s.max_iterations = (std::max)(s.max_iterations, std::size_t(it));
      if(converged)
        s.max_residual = (std::max)(s.max_residual, residual);
      else
        ++s.fallbacks;
      s.solve_seconds += seconds;
    });
    return true;
  }

private:
  template <typename Update>
  void report(const Update& u)
  {
    if(m_statistics)
      m_statistics->update(u);
  }

  // A hash of the pattern (n, column starts, row indices).
  static std::uint64_t pattern_fingerprint(const Sparse_matrix& A)
  {
    std::uint64_t h = 1469598103934665603ull ^ std::uint64_t(A.rows());
    const int* p = A.outerIndexPtr();
    for(Eigen::Index k = 0; k <= A.outerSize(); ++k)
      h = (h ^ std::uint64_t(p[k])) * 1099511628211ull;
    const int* i = A.innerIndexPtr();
    for(Eigen::Index k = 0; k < A.nonZeros(); ++k)
      h = (h ^ std::uint64_t(i[k])) * 1099511628211ull;
    return h;
  }

  // The fallback: a direct factorization of the stored finest matrix (in the
  // hierarchy's numbering, as b and x are here).
  bool direct_solve(const Dense_vector& b, Dense_vector& x)
  {
    if(!m_direct)
    {
      const internal::amg::Pattern& P = m_hierarchy->structure->levels[0].A;
      const std::vector<Complex>& a = m_hierarchy->levels[0].a;
      Sparse_matrix A(P.rows, P.rows);
      A.resizeNonZeros(Eigen::Index(P.nnz()));
      std::memcpy(A.outerIndexPtr(), P.ptr.data(), P.ptr.size() * sizeof(int));
      std::memcpy(A.innerIndexPtr(), P.idx.data(), P.idx.size() * sizeof(int));
      for(std::size_t k = 0; k < a.size(); ++k)
        A.valuePtr()[k] = std::conj(a[k]);
      m_direct.reset(new Eigen::SimplicialLDLT<Sparse_matrix>(A));
      if(m_direct->info() != Eigen::Success)
        return false;
    }
    x = m_direct->solve(b);
    return m_direct->info() == Eigen::Success;
  }

  internal::amg::Parameters m_parameters;
  std::shared_ptr<internal::Amg_statistics_sink> m_statistics;
  std::shared_ptr<Shared_analysis> m_structure;
  std::unique_ptr<internal::amg::Hierarchy> m_hierarchy;
  bool m_factored = false;
  bool m_empty = false;  // the analysed matrix has no row
  int m_fresh_iterations = -1, m_last_iterations = 0;
  Dense_vector m_last;
  std::unique_ptr<Eigen::SimplicialLDLT<Sparse_matrix> > m_direct;
};

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_AMG_FACTORIZATION_H
