// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

/*!
\ingroup PkgPolyvectorFieldsConcepts
\cgalConcept

The concept `SparseFactorization` describes how the package factors and solves
its sparse linear systems with a given sparse solver: complex Hermitian positive
definite systems (`Scalar = std::complex<double>`: the field design, the global
steps of the frame-field algorithms) and real symmetric positive definite ones
(`Scalar = double`: the integer-grid map, the planarization of quad meshes).
Every solve of the package goes through a model of this concept.

A model is the specialization `CGAL::Polyvector_fields::Sparse_factorization<SolverTraits, Scalar>`
for the solver type `SolverTraits` that the user gives (with the named parameter
`sparse_linear_solver`, or as the `SolverTraits` template parameter of
`CGAL::Polyvector_fields::Polyvector_field_designer`): a new back end is one
such traits class, written beside the solver type and visible wherever the solver
is used.

The work is split in three steps, so that the package can share and reuse:
- the <em>symbolic analysis</em> (`analyze()`) depends on the sparsity pattern
  only. The blocks of one system (one per coefficient degree of a field) have
  one pattern: they share one `Shared_analysis` object, which the first call of
  `analyze()` computes and the others read;
- the <em>numeric factorization</em> (`factorize()`) depends on the values. A
  matrix whose values change on the same pattern (a new weight
  \f$ \lambda \f$ in the frame-field iterations) is factored again without a new
  analysis;
- the <em>solve</em> (`solve()`) of one or several right-hand sides, the
  columns of a dense matrix.

<b>Concurrency.</b> When `is_thread_safe` is `true` and TBB is linked, the
package calls `analyze()` (after the first call on a shared analysis),
`factorize()` and `solve()` of distinct objects at the same time from
different threads (with `CGAL::Parallel_tag`, and with
`CGAL::Parallel_if_available_tag`, the default); a model then owns everything it
writes, and only reads its shared analysis once computed. The first
`analyze()` on a shared analysis is never concurrent with the other calls on it.
For the results not to depend on the threads, a model should compute each block
by the same operations whatever the thread.

<b>Lifetime.</b> The matrix given to `factorize()` outlives the object when
`keeps_matrix` is `true`; otherwise the model may not refer to it after the call.
An object of type `Solver_scope` is alive while the package factors or solves,
whether in parallel or not: a model sets a process-wide state there (the
package's CHOLMOD models, for `CGAL::Polyvector_fields::Cholmod_sparse_solver` and for
Eigen's CHOLMOD solvers on real matrices, run OpenBLAS on one thread in it).

<b>Has models:</b>
- `CGAL::Polyvector_fields::Sparse_factorization<CGAL::Eigen_solver_traits<EigenSolver>, Scalar>`,
  for Eigen's direct solvers (`CGAL::Polyvector_fields::Simplicial_ldlt_solver`, the
  real solvers of `CGAL::Polyvector_fields::compute_integer_grid_map()` and
  `CGAL::Polyvector_fields::planarize_quad_mesh()`);
- `CGAL::Polyvector_fields::Sparse_factorization<CGAL::Polyvector_fields::Cholmod_sparse_solver, std::complex<double>>`;
- `CGAL::Polyvector_fields::Sparse_factorization<CGAL::Polyvector_fields::Amg_sparse_solver, std::complex<double>>`;
- `CGAL::Polyvector_fields::Sparse_factorization<CGAL::Polyvector_fields::Adaptive_sparse_solver<DirectSolver>, std::complex<double>>`;
- the primary template `CGAL::Polyvector_fields::Sparse_factorization<SolverTraits, Scalar>`,
  for any model of `SparseLinearAlgebraWithFactorTraits_d` whose number type is
  `Scalar` (sequential: `is_thread_safe` is `false`).

\sa Section \ref pvf_solver_concept of the manual, and the example
`Polyvector_fields/solver_choice.cpp`.
*/
class SparseFactorization
{
public:
  /// \name Types
  /// @{

  /// `Eigen::SparseMatrix<Scalar>`: column-major and compressed, with both
  /// triangles stored (a Hermitian or symmetric matrix).
  typedef unspecified_type Matrix;

  /// `Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>`: right-hand sides and
  /// solutions, one per column.
  typedef unspecified_type Dense_matrix;

  /// what the factorizations of matrices with one sparsity pattern share (the
  /// symbolic analysis); default constructible. An empty struct when the model
  /// shares nothing.
  typedef unspecified_type Shared_analysis;

  /// default constructible; an object of this type is alive while the package
  /// factors or solves. An empty struct when the model needs none.
  typedef unspecified_type Solver_scope;

  /// @}

  /// \name Constants
  /// @{

  /// whether distinct objects may analyze (after the first analysis of a shared
  /// analysis), factorize and solve at the same time in different threads.
  static constexpr bool is_thread_safe;

  /// whether the object may refer to the matrix of `factorize()` after the call.
  static constexpr bool keeps_matrix;

  /// @}

  /// \name Creation
  /// The type is neither copied nor assigned.
  /// @{

  /// a factorization with the settings of `solver`, the object the user gave.
  explicit SparseFactorization(const SolverTraits& solver);

  /// @}

  /// \name Operations
  /// @{

  /// makes the object use `analysis`, shared with other objects whose matrices
  /// have the same pattern. Without a call, `analyze()` makes an analysis of
  /// its own.
  void share_analysis(const std::shared_ptr<Shared_analysis>& analysis);

  /// the symbolic analysis of the pattern of `A`, computed if the shared
  /// analysis has not been yet. Returns `false` on failure.
  bool analyze(const Matrix& A);

  /// the numeric factorization of `A`, whose pattern is the one analysed; it
  /// may be called again with new values. Returns `false` on failure, also
  /// when `A` is found not to be positive definite.
  bool factorize(const Matrix& A);

  /// solves \f$ A X = B \f$ for the matrix of the last `factorize()`, each
  /// column of `B` a right-hand side; `X` is resized. Returns `false` on failure.
  bool solve(const Dense_matrix& B, Dense_matrix& X);

  /// @}

  /// \name Optional operation
  /// A model may have this member; the package finds it at compile time and,
  /// without it (or when it returns `false`), computes the same matrix with
  /// `solve()`.
  /// @{

  /// computes \f$ G = C^T A^{-1} C \f$ (symmetric, `C.cols()` by `C.cols()`) for a
  /// sparse `C` with as many rows as the matrix of the last `factorize()`; `G`
  /// is resized. The integer-grid map uses it for the Schur complement of its
  /// integer unknowns (Section \ref pvf_param), where `C` has a
  /// few entries per column: a model can then solve with sparse right-hand
  /// sides instead of dense ones. The model of Eigen's CHOLMOD solvers on
  /// real matrices has it (forward solves only, over the reach of each column
  /// in the elimination tree, on TBB's threads when it is linked, with the
  /// same result on any number of threads). Real models only (`Scalar = double`). Returns
  /// `false` on failure.
  bool inverse_congruence(const Matrix& C, Dense_matrix& G);

  /// @}
};
