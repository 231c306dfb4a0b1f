// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_ADAPTIVE_SPARSE_SOLVER_H
#define CGAL_POLYVECTOR_FIELDS_ADAPTIVE_SPARSE_SOLVER_H

/// \file Adaptive_sparse_solver.h
///
/// A sparse solver that picks a direct factorization for small systems and
/// multigrid-preconditioned conjugate gradient for large ones.

#include <CGAL/Polyvector_fields/Amg_sparse_solver.h>
#include <CGAL/Polyvector_fields/Sparse_factorization.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/Eigen_sparse_matrix.h>
#include <CGAL/Eigen_vector.h>

#include <complex>
#include <cstddef>
#include <memory>
#include <type_traits>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsSolvers
///
/// is a sparse solver that solves each system with `DirectSolver` when it has
/// fewer than `amg_threshold()` unknowns, and with `Amg_sparse_solver` (whose
/// cost grows linearly) otherwise. A direct Cholesky factorization of a
/// surface mesh's matrix costs about \f$ n^{1.5} \f$: it is the faster one on
/// small meshes, multigrid on large ones. The default threshold, 8,000
/// unknowns, is where the two cost the same for a frame field on the bundled
/// meshes: the direct solver is faster up to lilium (6,590 faces), multigrid
/// from eight (11,092 faces) on, and twice as fast on fandisk (14,454 faces)
/// and at 40k faces (Section \ref pvf_perf of the manual).
///
/// The choice is made per system, by its number of unknowns: the free faces
/// of one coefficient degree, or twice that for the coupled degrees of partial
/// constraints. Fields computed either way agree to a few \f$ 10^{-9} \f$
/// (see `Amg_sparse_solver`).
///
/// It is a model of `SparseLinearAlgebraWithFactorTraits_d` on
/// `std::complex<double>`, to be given as the `SolverTraits` template
/// parameter of `Polyvector_field_designer` or with the
/// `sparse_linear_solver` named parameter.
///
/// \tparam DirectSolver a model of `SparseLinearAlgebraWithFactorTraits_d` on
///         `std::complex<double>` whose `Matrix` is `CGAL::Eigen_sparse_matrix<std::complex<double>>`,
///         such as `Cholmod_sparse_solver` or `Simplicial_ldlt_solver`.
///
/// \sa `Default_sparse_solver`
template <typename DirectSolver>
class Adaptive_sparse_solver
{
public:
  /// \name Types
  /// @{
  typedef std::complex<double> NT;               ///< number type
  typedef CGAL::Eigen_sparse_matrix<NT> Matrix;  ///< matrix type of the concept
  typedef CGAL::Eigen_vector<NT> Vector;         ///< vector type of the concept
  typedef DirectSolver Direct_solver;            ///< the solver of small systems
  /// @}

  static_assert(std::is_same<typename DirectSolver::Matrix, Matrix>::value,
                "Adaptive_sparse_solver: the direct solver must take CGAL::Eigen_sparse_matrix<std::complex<double>>");

  /// the number of unknowns from which `Amg_sparse_solver` is used by default.
  static constexpr std::size_t default_amg_threshold = 8000;

  /// multigrid from `amg_threshold` unknowns on, `direct` below.
  explicit Adaptive_sparse_solver(std::size_t amg_threshold = default_amg_threshold,
                                  const DirectSolver& direct = DirectSolver(),
                                  const Amg_sparse_solver& amg = Amg_sparse_solver())
    : m_threshold(amg_threshold), m_direct(direct), m_amg(amg)
  {}

  /// the number of unknowns from which multigrid is used.
  std::size_t amg_threshold() const { return m_threshold; }
  /// sets it (0: always multigrid; a huge value: never).
  void set_amg_threshold(std::size_t t) { m_threshold = t; }
  /// returns whether a system of `unknowns` unknowns is solved by multigrid.
  bool uses_amg(std::size_t unknowns) const { return unknowns >= m_threshold; }

  /// the solver of small systems.
  const DirectSolver& direct_solver() const { return m_direct; }
  /// the solver of large systems; its `statistics()` cover the systems it solved.
  const Amg_sparse_solver& amg_solver() const { return m_amg; }
  /// the solver of large systems, to change its settings.
  Amg_sparse_solver& amg_solver() { return m_amg; }

  /// \name Model of `SparseLinearAlgebraWithFactorTraits_d`
  /// @{

  /// factors `A` with the solver its size calls for; `D` is set to 1.
  bool factor(const Matrix& A, NT& D)
  {
    m_amg_in_use = uses_amg(std::size_t(A.row_dimension()));
    return m_amg_in_use ? m_amg.factor(A, D) : m_direct.factor(A, D);
  }
  /// solves \f$ AX = B \f$ for the matrix of the last `factor()`.
  bool linear_solver(const Vector& B, Vector& X)
  {
    return m_amg_in_use ? m_amg.linear_solver(B, X) : m_direct.linear_solver(B, X);
  }
  /// factors `A` and solves \f$ AX = B \f$; `D` is set to 1.
  bool linear_solver(const Matrix& A, const Vector& B, Vector& X, NT& D) { return factor(A, D) && linear_solver(B, X); }
  /// @}

private:
  std::size_t m_threshold;
  DirectSolver m_direct;
  Amg_sparse_solver m_amg;
  bool m_amg_in_use = false;
};

/// \cond SKIP_IN_MANUAL
// The model of the SparseFactorization concept for Adaptive_sparse_solver:
// the direct solver's factorization or the multigrid one, chosen in analyze()
// by the matrix's size.
template <typename DirectSolver>
class Sparse_factorization<Adaptive_sparse_solver<DirectSolver>, std::complex<double> >
{
  typedef Sparse_factorization<DirectSolver, std::complex<double> > Direct;
  typedef Sparse_factorization<Amg_sparse_solver, std::complex<double> > Amg;

public:
  typedef internal::Sparse_matrix Matrix;
  typedef Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic> Dense_matrix;
  static constexpr bool is_thread_safe = Direct::is_thread_safe && Amg::is_thread_safe;
  static constexpr bool keeps_matrix = Direct::keeps_matrix || Amg::keeps_matrix;
  // Kept alive by the caller while blocks are computed: the direct solver's
  // scope (for CHOLMOD, OpenBLAS on one thread) costs nothing when unused.
  typedef typename Direct::Solver_scope Solver_scope;

  // The analyses of both kinds, each made on first use.
  struct Shared_analysis
  {
    std::shared_ptr<typename Direct::Shared_analysis> direct;
    std::shared_ptr<typename Amg::Shared_analysis> amg;
  };

  explicit Sparse_factorization(const Adaptive_sparse_solver<DirectSolver>& solver = Adaptive_sparse_solver<DirectSolver>())
    : m_solver(solver)
  {}
  Sparse_factorization(const Sparse_factorization&) = delete;
  Sparse_factorization& operator=(const Sparse_factorization&) = delete;

  void share_analysis(const std::shared_ptr<Shared_analysis>& s) { m_shared = s; }

  bool analyze(const Matrix& A)
  {
    if(!m_shared)
      m_shared = std::make_shared<Shared_analysis>();
    m_amg_in_use = m_solver.uses_amg(std::size_t(A.rows()));
    if(m_amg_in_use)
    {
      if(!m_shared->amg)
        m_shared->amg = std::make_shared<typename Amg::Shared_analysis>();
      if(!m_amg)
      {
        m_amg.reset(new Amg(m_solver.amg_solver()));
        m_amg->share_analysis(m_shared->amg);
      }
      return m_amg->analyze(A);
    }
    if(!m_shared->direct)
      m_shared->direct = std::make_shared<typename Direct::Shared_analysis>();
    if(!m_direct)
    {
      m_direct.reset(new Direct(m_solver.direct_solver()));
      m_direct->share_analysis(m_shared->direct);
    }
    return m_direct->analyze(A);
  }

  bool factorize(const Matrix& A)
  {
    if(m_amg_in_use)
      return m_amg && m_amg->factorize(A);
    return m_direct && m_direct->factorize(A);
  }

  bool solve(const Dense_matrix& b, Dense_matrix& x)
  {
    if(m_amg_in_use)
      return m_amg && m_amg->solve(b, x);
    return m_direct && m_direct->solve(b, x);
  }

private:
  Adaptive_sparse_solver<DirectSolver> m_solver;
  std::shared_ptr<Shared_analysis> m_shared;
  std::unique_ptr<Direct> m_direct;
  std::unique_ptr<Amg> m_amg;
  bool m_amg_in_use = false;
};
/// \endcond

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_ADAPTIVE_SPARSE_SOLVER_H
