// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_AMG_SPARSE_SOLVER_H
#define CGAL_POLYVECTOR_FIELDS_AMG_SPARSE_SOLVER_H

/// \file Amg_sparse_solver.h
///
/// An iterative solver whose cost grows linearly with the mesh: conjugate
/// gradient preconditioned by smoothed-aggregation multigrid.

#include <CGAL/Polyvector_fields/internal/Solvers/Smoothed_aggregation.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/Eigen_sparse_matrix.h>
#include <CGAL/Eigen_vector.h>

#include <complex>
#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsSolvers
///
/// says what the factorizations and solves of an `Amg_sparse_solver` (and of
/// its copies) did.
struct Amg_statistics
{
  std::size_t analyses = 0;           ///< hierarchy structures built (one per sparsity pattern)
  std::size_t setups = 0;             ///< numeric setups of a whole hierarchy (the first one of a matrix, and rebuilds)
  std::size_t reused_setups = 0;      ///< refactorizations that kept the coarse levels of the previous values
  std::size_t solves = 0;             ///< right-hand sides solved
  std::size_t iterations = 0;         ///< conjugate-gradient iterations, over all solves
  std::size_t max_iterations = 0;     ///< the most iterations of one solve
  std::size_t fallbacks = 0;          ///< solves that did not converge and were finished by the direct solver
  double max_residual = 0;            ///< largest final relative residual \f$ \|b - Ax\| / \|b\| \f$ of a converged solve
  std::vector<int> level_sizes;       ///< unknowns on each level of the last hierarchy built, finest first
  double analysis_seconds = 0;        ///< time spent building structures
  double setup_seconds = 0;           ///< time spent in numeric setups
  double solve_seconds = 0;           ///< time spent in solves
};

namespace internal {

// What the factorizations made from one Amg_sparse_solver (and its copies)
// report, under a lock: blocks may be factored in parallel.
class Amg_statistics_sink
{
public:
  template <typename Update>
  void update(const Update& u)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    u(m_statistics);
  }
  Amg_statistics get() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_statistics;
  }
  void reset()
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_statistics = Amg_statistics();
  }

private:
  mutable std::mutex m_mutex;
  Amg_statistics m_statistics;
};

} // namespace internal

/// \cond SKIP_IN_MANUAL
template <typename SolverTraits, typename Scalar>
class Sparse_factorization;
/// \endcond

/// \ingroup PkgPolyvectorFieldsSolvers
///
/// is a sparse solver for the package's complex Hermitian positive definite
/// systems whose time and memory grow linearly with the number of unknowns:
/// conjugate gradient (CG) preconditioned by one V-cycle of smoothed-aggregation
/// multigrid (Vaněk, Mandel and Brezina 1996) per iteration.
///
/// The smoothness matrices of the package are connection Laplacians: a field
/// that is parallel along an edge costs nothing there, and the phase of an
/// off-diagonal entry is the edge's transport (Section 4 of the paper). The
/// multigrid hierarchy is built for them: faces are grouped into aggregates of
/// radius 2 (then 1 on the coarser levels), and each aggregate's coarse unknown
/// is a field carried parallel from its root along a spanning tree of the
/// aggregate, with the transport read off the matrix. The prolongator is
/// smoothed by one damped Jacobi step, the coarse operators are Galerkin
/// products, the smoother is one symmetric Gauss–Seidel sweep, and the coarsest
/// level (at most `Parameters::coarsest_size` unknowns) is solved by a dense
/// Cholesky factorization. The cycle is Hermitian positive definite, so CG
/// converges; it needs 15 to 20 iterations per system at every mesh size
/// measured, from 10k to 2.5M faces (Section \ref pvf_perf of the manual).
///
/// The aggregates depend on the sparsity pattern only. All coefficient degrees
/// of a field share one structure, and a numeric refactorization (a new
/// \f$ \lambda \f$ in the frame-field iterations, Section 6 of the paper) reuses
/// it; with `Parameters::reuse = 2` it also keeps the coarse levels of the
/// previous values as long as CG converges about as fast with them.
///
/// **Accuracy.** CG stops when \f$ \|b - Ax\|_2 \le \tau \|b\|_2 \f$ for the
/// true residual, \f$ \tau = \f$ `Parameters::tolerance` (default
/// \f$ 10^{-10} \f$). On the benchmark meshes (10k to 2.5M faces) this keeps
/// every coefficient within a few \f$ 10^{-9} \f$ of the direct solver's,
/// relative to the largest coefficient, below the \f$ 10^{-8} \f$ the
/// package's tests demand; \f$ \tau = 10^{-12} \f$ gives about
/// \f$ 10^{-11} \f$ at 20% more iterations. The prolongators are stored in
/// single precision (the coarse operators are the exact Galerkin products of
/// the stored values, so the cycle stays symmetric): this changes the
/// preconditioner, not the accuracy of the solution. A solve that does
/// not converge within `Parameters::max_iterations` is finished by a direct
/// factorization (Eigen's `SimplicialLDLT`) of the same matrix, and
/// `Amg_statistics::fallbacks` counts it. A matrix found not to be positive
/// definite (a non-positive diagonal entry, coarsest pivot or CG curvature)
/// makes the factorization or the solve fail, as a direct solver's would.
///
/// **Determinism.** The hierarchy and CG run the same operations whatever the
/// thread: a parallel design (degrees in parallel, TBB) is bit-identical to a
/// sequential one.
///
/// It is a model of `SparseLinearAlgebraWithFactorTraits_d` on
/// `std::complex<double>`, to be given as the `SolverTraits` template
/// parameter of `Polyvector_field_designer` or with the
/// `sparse_linear_solver` named parameter. Copies share their statistics.
///
/// \sa `Adaptive_sparse_solver`, `Default_sparse_solver`
class Amg_sparse_solver
{
public:
  /// \name Types
  /// @{
  typedef std::complex<double> NT;                  ///< number type
  typedef CGAL::Eigen_sparse_matrix<NT> Matrix;     ///< matrix type of the concept
  typedef CGAL::Eigen_vector<NT> Vector;            ///< vector type of the concept
  /// The settings, a struct with these fields:
  /// - `double tolerance = 1e-10`: CG stops at a true relative residual
  ///   \f$ \|b - Ax\|_2 / \|b\|_2 \f$ at most this;
  /// - `int max_iterations = 200`: more than this and the solve falls back
  ///   to the direct solver;
  /// - `int coarsest_size = 500`: a level with at most this many unknowns is
  ///   solved by a dense Cholesky factorization;
  /// - `int reuse = 2`: what a numeric refactorization recomputes: 0 every value
  ///   of the hierarchy; 1 the coarse operators but not the prolongators; 2
  ///   nothing but the finest matrix (the coarse levels of the earlier values
  ///   precondition the new ones) while CG needs at most 30% (and 2) more
  ///   iterations than right after the last whole setup, then as 1;
  /// - `bool warm_start = true`: CG starts from the previous solution of the
  ///   same factorization when its residual is below \f$ \|b\| \f$;
  /// - `int fine_radius = 2`, `int coarse_radius = 1`, `int sweeps = 1`,
  ///   `int max_levels = 12`: the aggregate radii, the Gauss–Seidel sweeps
  ///   before and after the coarse correction, and the number of levels.
  typedef internal::amg::Parameters Parameters;
  /// @}

  /// the default settings.
  Amg_sparse_solver() : m_statistics(std::make_shared<internal::Amg_statistics_sink>()) {}
  /// the settings `p`.
  explicit Amg_sparse_solver(const Parameters& p)
    : m_parameters(p), m_statistics(std::make_shared<internal::Amg_statistics_sink>())
  {}

  /// the settings.
  const Parameters& parameters() const { return m_parameters; }
  /// the settings, to change them.
  Parameters& parameters() { return m_parameters; }

  /// what the factorizations made with this object and its copies did so far.
  Amg_statistics statistics() const { return m_statistics->get(); }
  /// forgets the statistics (of the copies too).
  void reset_statistics() { m_statistics->reset(); }

  /// \name Model of `SparseLinearAlgebraWithFactorTraits_d`
  /// @{

  /// sets the solver up for the Hermitian positive definite `A` (both
  /// triangles stored); `D` is set to 1. Returns `false` when `A` is not
  /// positive definite.
  bool factor(const Matrix& A, NT& D);
  /// solves \f$ AX = B \f$ for the matrix of the last `factor()`.
  bool linear_solver(const Vector& B, Vector& X);
  /// factors `A` and solves \f$ AX = B \f$; `D` is set to 1.
  bool linear_solver(const Matrix& A, const Vector& B, Vector& X, NT& D)
  {
    return factor(A, D) && linear_solver(B, X);
  }
  /// @}

  /// \cond SKIP_IN_MANUAL
  const std::shared_ptr<internal::Amg_statistics_sink>& statistics_sink() const { return m_statistics; }
  /// \endcond

private:
  Parameters m_parameters;
  std::shared_ptr<internal::Amg_statistics_sink> m_statistics;
  std::shared_ptr<Sparse_factorization<Amg_sparse_solver, std::complex<double> > > m_factorization;  // for factor() / linear_solver()
};

} // namespace Polyvector_fields
} // namespace CGAL

// The model of SparseFactorization for the class, beside it (it needs the class complete).
#include <CGAL/Polyvector_fields/internal/Solvers/Amg_factorization.h>

namespace CGAL {
namespace Polyvector_fields {

inline bool Amg_sparse_solver::factor(const Matrix& A, NT& D)
{
  D = 1;
  m_factorization = std::make_shared<Sparse_factorization<Amg_sparse_solver, std::complex<double> > >(*this);
  const internal::Sparse_matrix& M = A.eigen_object();
  internal::Sparse_matrix compressed;
  const internal::Sparse_matrix* input = &M;
  if(!M.isCompressed())
  {
    compressed = M;
    compressed.makeCompressed();
    input = &compressed;
  }
  return m_factorization->analyze(*input) && m_factorization->factorize(*input);
}

inline bool Amg_sparse_solver::linear_solver(const Vector& B, Vector& X)
{
  if(!m_factorization)
    return false;
  internal::Dense_vector x;
  if(!m_factorization->solve(B, x))
    return false;
  X = x;
  return true;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_AMG_SPARSE_SOLVER_H
