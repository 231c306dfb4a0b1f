// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_MIXED_INTEGER_SOLVE_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_MIXED_INTEGER_SOLVE_H

// The least-squares problem of the integer-grid map with integer unknowns
// (compute_integer_grid_map()): minimise |W^(1/2) (B y - d)|^2 over
// y = (x continuous, n integer). The continuous block is factored once
// through the solver's Sparse_factorization; the integer unknowns are eliminated through
// their Schur complement and rounded greedily, closest to an integer first,
// with an exact update of the small dense system after each rounding. A round
// that keeps the integers and only raises weights is solved by conjugate
// gradient, preconditioned by the factor of the last factored weights.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Sparse_factorization.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// Whether a model F of SparseFactorization (Scalar = double) has the optional
// operation inverse_congruence().
template <typename F, typename = void>
struct Has_inverse_congruence : std::false_type
{};
template <typename F>
struct Has_inverse_congruence<F, std::void_t<decltype(std::declval<F&>().inverse_congruence(
                                   std::declval<const Eigen::SparseMatrix<double>&>(), std::declval<Eigen::MatrixXd&>()))> >
  : std::true_type
{};

// A factorization of a real symmetric positive definite matrix through the
// solver's Sparse_factorization (the model of the SparseFactorization concept),
// kept alive for several block solves. `A` must outlive it.
template <typename SolverTraits>
class Factored_real_system
{
  typedef Sparse_factorization<SolverTraits, double> Factorization;

public:
  explicit Factored_real_system(const SolverTraits& prototype) : m_factorization(prototype) {}
  bool factor(const Eigen::SparseMatrix<double>& A) { return analyze(A) && factorize(A); }
  // the ordering and symbolic analysis, for every matrix of A's pattern
  bool analyze(const Eigen::SparseMatrix<double>& A) { return m_factorization.analyze(A); }
  // the numeric factorization of a matrix of the analysed pattern
  bool factorize(const Eigen::SparseMatrix<double>& A) { return m_factorization.factorize(A); }
  // solves A X = B for a dense block B, all its columns at once
  bool solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) { return m_factorization.solve(B, X) && X.allFinite(); }

  // G = C^T A^-1 C for a sparse C: the factorization's inverse_congruence()
  // when its model has one, otherwise (or if it fails: the copy of a factor
  // that it may make can run out of memory) C^T X with A X = C solved by
  // blocks of 64 columns (the right-hand sides and solutions of one block
  // reuse their storage).
  bool inverse_congruence(const Eigen::SparseMatrix<double>& C, Eigen::MatrixXd& G)
  {
    if constexpr(Has_inverse_congruence<Factorization>::value)
      if(m_factorization.inverse_congruence(C, G) && G.allFinite())
        return true;
    const Eigen::Index n = C.rows(), m = C.cols(), block = 64;
    const Eigen::SparseMatrix<double> CT = C.transpose();
    G.resize(m, m);
    Eigen::MatrixXd R, X;
    for(Eigen::Index j0 = 0; j0 < m; j0 += block)
    {
      const Eigen::Index w = (std::min)(block, m - j0);
      R.setZero(n, w);
      for(Eigen::Index j = 0; j < w; ++j)
        for(Eigen::SparseMatrix<double>::InnerIterator it(C, j0 + j); it; ++it)
          R(it.row(), j) = it.value();
      if(!solve(R, X))
        return false;
      G.middleCols(j0, w).noalias() = CT * X;
    }
    G = (0.5 * (G + G.transpose())).eval();  // not in place: G is read transposed
    return true;
  }

private:
  typename Factorization::Solver_scope m_scope;
  Factorization m_factorization;
};

// A stiffening round that keeps the integers changes only weights, and only
// upwards (stiffen() multiplies them by at least 1, up to
// max_stiffening_weight): its continuous block K is at least the block M of
// the weights last factored (K - M is positive semidefinite). Conjugate
// gradient on K x = b preconditioned by M's factor then converges in few
// iterations (M^-1 K has eigenvalues of at least 1, and only the reweighted
// rows move them), and its stopping rule bounds the error: from
// r^T M^-1 r <= tol^2 b^T M^-1 b follows |x - x*|_K <= tol kappa^(1/2) |x*|_K,
// with kappa at most the largest ratio of a row's weight to its factored
// weight (so at most 1e6). Measured on the map of bumpy.off after three Loop
// steps (160k faces, the program's summary): 6 rounds in 114 iterations at
// 1e-12, each a solve with the factor, 2.9 s of stiffening against 4.0 s
// with a refactorization per round. After stiffening_cg_max_iterations without
// convergence, K is factored and solved directly.
constexpr double stiffening_cg_tolerance = 1e-12;
constexpr std::size_t stiffening_cg_max_iterations = 30;

inline double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Two integer points of one face (two singular vertices, say) that the
// rounding must not put on the same point, which would fold the faces
// between them: the difference of their uv in that face's chart, an integer
// linear form over the integer unknowns (indices 0 .. m-1), with Gaussian
// integer coefficients (the u and v of each unknown's contribution).
struct Distinct_points
{
  struct Term
  {
    std::size_t unknown;
    long long u, v;
  };
  std::vector<Term> terms;
};

// The greedy rounding's guard against Distinct_points: the forms that each
// unknown completes, and how many of each form's unknowns are still free.
class Collision_guard
{
public:
  Collision_guard(const std::vector<Distinct_points>& forms, std::size_t m) : m_forms(forms), m_of(m), m_free(forms.size())
  {
    for(std::size_t k = 0; k < forms.size(); ++k)
    {
      m_free[k] = forms[k].terms.size();
      for(const auto& t : forms[k].terms)
        m_of[t.unknown].push_back(k);
    }
  }
  // The integer for unknown j, whose minimiser is x and nearest integer
  // `value`: `value`, or the integer on the other side of x when `value`
  // would close a form at zero and the other would not. `n` holds the
  // integers already chosen.
  template <typename Vector>
  double choose(std::size_t j, double x, double value, const Vector& n, std::size_t& avoided) const
  {
    if(!collides(j, value, n))
      return value;
    const double other = value + (x >= value ? 1 : -1);
    if(collides(j, other, n))
      return value;
    ++avoided;
    return other;
  }
  void fix(std::size_t j)
  {
    for(std::size_t k : m_of[j])
      --m_free[k];
  }

private:
  template <typename Vector>
  bool collides(std::size_t j, double value, const Vector& n) const
  {
    for(std::size_t k : m_of[j])
    {
      if(m_free[k] != 1)
        continue;  // another unknown of the form is still free
      long long u = 0, v = 0;
      for(const auto& t : m_forms[k].terms)
      {
        const long long x = std::llround(t.unknown == j ? value : double(n[Eigen::Index(t.unknown)]));
        u += t.u * x;
        v += t.v * x;
      }
      if(u == 0 && v == 0)
        return true;
    }
    return false;
  }
  const std::vector<Distinct_points>& m_forms;
  std::vector<std::vector<std::size_t> > m_of;
  std::vector<std::size_t> m_free;
};

// The mixed-integer problem with row weights w: minimise
// |W^(1/2)(B y - d)|^2, y = (x continuous, n integer). set_weights() makes
// the normal equations for the current weights and factors the continuous
// block; then round() rounds the integers (Schur complement and greedy
// rounding), and solve_for_integers() gives the continuous unknowns for
// integers already chosen (one solve, no rounding). set_weights() with
// factor = false keeps the factor when no weight is lower than at its
// factorization: solve_for_integers() then runs conjugate gradient
// preconditioned by it, from its last solution (see stiffening_cg_tolerance);
// round() factors first.
//
// The normal equations of unit weights are made once; a call of
// set_weights() adds (w_r - 1) B_r^T B_r for the rows whose weight is not 1
// (stiffening reweights few faces), on the same pattern: the ordering and
// symbolic analysis of the first factorization serve every later one.
template <typename SolverTraits>
class Mixed_integer_system
{
  typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Row_matrix;

public:
  Mixed_integer_system(const Eigen::SparseMatrix<double>& B1, const Eigen::VectorXd& d1, std::size_t nx, std::size_t m,
                       const std::vector<Distinct_points>& distinct, const SolverTraits& prototype)
    : m_B1(B1), m_d1(d1), m_nx(nx), m_m(m), m_distinct(distinct), m_prototype(prototype), m_system(prototype)
  {}

  // `row_weight` holds w_r^(1/2) per row of B. With factor = false, the
  // factor is kept only if one was made and no weight is lower than at that
  // factorization (otherwise the matrix is factored).
  template <typename Report>
  Error_code set_weights(const std::vector<double>& row_weight, Report& result, bool factor = true)
  {
    auto t = std::chrono::steady_clock::now();
    if(!m_unit_made)
      make_unit_equations();
    m_row_weight = row_weight;
    m_Kxx = m_Kxx1;
    m_Kxn = m_Kxn1;
    m_Knn = m_Knn1;
    m_bx = m_bx1;
    m_bn = m_bn1;
    const std::size_t nx = m_nx;
    for(Eigen::Index r = 0; r < m_rows.rows(); ++r)
    {
      const double c = row_weight[std::size_t(r)] * row_weight[std::size_t(r)] - 1;
      if(c == 0)
        continue;
      for(Row_matrix::InnerIterator a(m_rows, r); a; ++a)
      {
        const std::size_t i = std::size_t(a.col());
        const double ca = c * a.value();
        if(i < nx)
          m_bx[Eigen::Index(i)] += ca * m_d1[r];
        else
          m_bn[Eigen::Index(i - nx)] += ca * m_d1[r];
        for(Row_matrix::InnerIterator b(m_rows, r); b; ++b)
        {
          const std::size_t j = std::size_t(b.col());
          if(i < nx && j < nx)
            m_Kxx.coeffRef(a.col(), b.col()) += ca * b.value();
          else if(i < nx)
            m_Kxn.coeffRef(a.col(), Eigen::Index(j - nx)) += ca * b.value();
          else if(j >= nx)
            m_Knn(Eigen::Index(i - nx), Eigen::Index(j - nx)) += ca * b.value();
        }
      }
    }
    result.time_assembly += seconds_since(t);

    m_stale = m_factored && !factor;
    for(std::size_t r = 0; m_stale && r < row_weight.size(); ++r)
      m_stale = row_weight[r] >= m_factored_row_weight[r];
    return m_stale ? Error_code::SUCCESS : factor_block(result);
  }

  // y = (Kxx^-1 (bx - Kxn n), n) for the integers n: with the factor of the
  // current weights, one solve; with an earlier one, conjugate gradient
  // preconditioned by it, or a new factorization and one solve if that does
  // not converge within cg_max_iterations.
  template <typename Report>
  Error_code solve_for_integers(const Eigen::VectorXd& n, Eigen::VectorXd& y, Report& result)
  {
    auto t = std::chrono::steady_clock::now();
    const Eigen::VectorXd b = m_bx - m_Kxn * n;
    y.resize(Eigen::Index(m_nx + m_m));
    y.tail(Eigen::Index(m_m)) = n;
    if(m_stale)
    {
      Eigen::VectorXd x = m_last_x;
      std::size_t iterations = 0;
      const bool converged = preconditioned_cg(b, x, iterations);
      result.time_cg += seconds_since(t);
      if(converged)
      {
        ++result.cg_solves;
        result.cg_iterations += iterations;
        m_last_x = x;
        y.head(Eigen::Index(m_nx)) = x;
        return Error_code::SUCCESS;
      }
      const Error_code code = factor_block(result);
      if(code != Error_code::SUCCESS)
        return code;
      t = std::chrono::steady_clock::now();
    }
    Eigen::MatrixXd sol;
    const bool ok = m_system.solve(b, sol);
    result.time_schur += seconds_since(t);
    if(!ok)
      return Error_code::SOLVER_FAILURE;
    m_last_x = sol.col(0);
    y.head(Eigen::Index(m_nx)) = m_last_x;
    return Error_code::SUCCESS;
  }

  // at most this many iterations of conjugate gradient per solve (0: every
  // solve with a stale factor factors again)
  void set_cg_max_iterations(std::size_t n) { m_cg_max_iterations = n; }

  // Rounds the integers for the current weights: y_continuous is the
  // unrounded minimiser, y_rounded the minimiser with the rounded integers.
  // No form of `distinct` becomes zero where the other integer next to the
  // minimiser avoids it.
  template <typename Report>
  Error_code round(bool refactor_per_rounding, Eigen::VectorXd& y_continuous, Eigen::VectorXd& y_rounded, Report& result);

private:
  // the numeric factorization of the continuous block (the symbolic analysis
  // once)
  template <typename Report>
  Error_code factor_block(Report& result)
  {
    const auto t = std::chrono::steady_clock::now();
    if(!m_analyzed)
    {
      if(!m_system.analyze(m_Kxx))
        return Error_code::SOLVER_FAILURE;
      m_analyzed = true;
    }
    if(!m_system.factorize(m_Kxx))
      return Error_code::SOLVER_FAILURE;
    m_factored = true;
    m_stale = false;
    m_factored_row_weight = m_row_weight;
    ++result.factorizations;
    result.time_factorization += seconds_since(t);
    return Error_code::SUCCESS;
  }

  // Conjugate gradient on Kxx x = b from x, preconditioned by the factor of
  // earlier weights (see stiffening_cg_tolerance); whether it converged.
  bool preconditioned_cg(const Eigen::VectorXd& b, Eigen::VectorXd& x, std::size_t& iterations)
  {
    iterations = 0;
    Eigen::MatrixXd z;
    if(x.size() != b.size() || !m_system.solve(b, z))
      return false;
    const double tolerance2 = stiffening_cg_tolerance * stiffening_cg_tolerance * b.dot(z.col(0));
    Eigen::VectorXd r = b - m_Kxx * x;
    if(!m_system.solve(r, z))
      return false;
    Eigen::VectorXd p = z.col(0), q;
    double rz = r.dot(p);
    while(!(rz <= tolerance2))
    {
      if(iterations == m_cg_max_iterations || !std::isfinite(rz))
        return false;
      ++iterations;
      q.noalias() = m_Kxx * p;
      const double alpha = rz / p.dot(q);
      x += alpha * p;
      r -= alpha * q;
      if(!m_system.solve(r, z))
        return false;
      const double rz_next = r.dot(z.col(0));
      p = z.col(0) + (rz_next / rz) * p;
      rz = rz_next;
    }
    return x.allFinite();
  }

  // The normal equations of unit weights, by blocks: the products are not
  // pruned, so that each block holds every entry that a weight can change.
  // Eigen's sparse product reads memory it does not own when a factor has no
  // column or no row (seen on the 12-triangle box, nx = 0): the empty blocks
  // are made directly.
  void make_unit_equations()
  {
    const Eigen::Index nx = Eigen::Index(m_nx), m = Eigen::Index(m_m);
    m_rows = Row_matrix(m_B1);
    const Eigen::SparseMatrix<double> Bn = m_B1.rightCols(m);
    m_Kxx1 = Eigen::SparseMatrix<double>(nx, nx);
    m_Kxn1 = Eigen::SparseMatrix<double>(nx, m);
    m_bx1 = Eigen::VectorXd::Zero(nx);
    if(nx > 0)
    {
      const Eigen::SparseMatrix<double> Bx = m_B1.leftCols(nx);
      const Eigen::SparseMatrix<double> BxT = Bx.transpose();
      m_Kxx1 = BxT * Bx;
      m_bx1 = BxT * m_d1;
      if(m > 0)
        m_Kxn1 = BxT * Bn;
    }
    m_Kxx1.makeCompressed();
    m_Kxn1.makeCompressed();
    m_Knn1 = Eigen::MatrixXd::Zero(m, m);
    m_bn1 = Eigen::VectorXd::Zero(m);
    if(m > 0)
    {
      const Eigen::SparseMatrix<double> BnT = Bn.transpose();
      m_Knn1 = Eigen::MatrixXd(Eigen::SparseMatrix<double>(BnT * Bn));
      m_bn1 = BnT * m_d1;
    }
    m_unit_made = true;
  }

  const Eigen::SparseMatrix<double>& m_B1;
  const Eigen::VectorXd& m_d1;
  std::size_t m_nx, m_m;
  const std::vector<Distinct_points>& m_distinct;
  const SolverTraits& m_prototype;
  Factored_real_system<SolverTraits> m_system;
  bool m_unit_made = false, m_analyzed = false;
  bool m_factored = false;  // a numeric factorization was made
  bool m_stale = false;     // of other (lower) weights than the current ones
  std::vector<double> m_factored_row_weight;  // the row weights of the factorization
  std::size_t m_cg_max_iterations = stiffening_cg_max_iterations;
  Eigen::VectorXd m_last_x;  // the continuous unknowns of the last solve
  Row_matrix m_rows;                                  // B1 by rows
  Eigen::SparseMatrix<double> m_Kxx1, m_Kxn1, m_Kxx, m_Kxn;
  Eigen::MatrixXd m_Knn1, m_Knn;
  Eigen::VectorXd m_bx1, m_bn1, m_bx, m_bn;
  std::vector<double> m_row_weight;
};

template <typename SolverTraits>
template <typename Report>
Error_code Mixed_integer_system<SolverTraits>::round(bool refactor_per_rounding, Eigen::VectorXd& y_continuous,
                                                     Eigen::VectorXd& y_rounded, Report& result)
{
  const std::size_t nx = m_nx, m = m_m;
  const Eigen::SparseMatrix<double>& Kxn = m_Kxn;
  if(m_stale)
  {
    // the Schur complement needs the factor of the current weights
    const Error_code factored = factor_block(result);
    if(factored != Error_code::SUCCESS)
      return factored;
  }
  auto t = std::chrono::steady_clock::now();
  Eigen::MatrixXd X;
  if(!m_system.solve(m_bx, X))
    return Error_code::SOLVER_FAILURE;
  const Eigen::VectorXd x0 = X.col(0);
  y_continuous.resize(Eigen::Index(nx + m));
  y_rounded.resize(Eigen::Index(nx + m));
  if(m == 0)
  {
    m_last_x = x0;
    y_continuous = x0;
    y_rounded = x0;
    result.time_schur += seconds_since(t);
    return Error_code::SUCCESS;
  }

  // Schur complement of the integer unknowns, S n = g, with
  // S = Knn - Kxn^T Kxx^-1 Kxn, g = bn - Kxn^T x0.
  Eigen::MatrixXd S;
  if(!m_system.inverse_congruence(Kxn, S))
    return Error_code::SOLVER_FAILURE;
  // symmetric to the last bit: Knn's entries (i, j) and (j, i) may differ in
  // their rounding (set_weights() adds products in either order)
  S = m_Knn - S;
  S = (0.5 * (S + S.transpose())).eval();
  const Eigen::VectorXd g = m_bn - Kxn.transpose() * x0;
  result.time_schur += seconds_since(t);

  t = std::chrono::steady_clock::now();
  Eigen::LLT<Eigen::MatrixXd> llt(S);
  if(llt.info() != Eigen::Success)
    return Error_code::SOLVER_FAILURE;
  Eigen::MatrixXd H = llt.solve(Eigen::MatrixXd::Identity(S.rows(), S.cols()));
  Eigen::VectorXd n = llt.solve(g);
  result.time_rounding += seconds_since(t);
  Error_code code = solve_for_integers(n, y_continuous, result);
  if(code != Error_code::SUCCESS)
    return code;
  t = std::chrono::steady_clock::now();

  Collision_guard guard(m_distinct, m);
  if(!refactor_per_rounding)
  {
    // Greedy rounding, the unknown closest to an integer first (the lowest
    // index among equals). Fixing n_j = v moves the minimiser of the others by
    // H_.j (v - n_j) / H_jj and the inverse of the remaining block is
    // H - H_.j H_j. / H_jj: O(f^2) per rounding with f unknowns still free, no
    // refactorization. The free unknowns are kept in the leading f rows and
    // columns of H (a fixed one is swapped to position f - 1), so that each
    // update touches the free block only, about m^3 / 3 operations in all
    // instead of m^3; the values of the free block are those of the update of
    // the whole matrix, operation for operation.
    std::vector<std::size_t> unknown_at(m);  // the unknown at each position of H and n
    for(std::size_t i = 0; i < m; ++i)
      unknown_at[i] = i;
    Eigen::VectorXd chosen = n;  // by unknown: the integers already chosen (read by the guard)
    for(std::size_t f = m; f > 0; --f)
    {
      std::size_t p = f;
      double best = 2;
      for(std::size_t i = 0; i < f; ++i)
      {
        const double e = std::abs(n[Eigen::Index(i)] - std::round(n[Eigen::Index(i)]));
        if(e < best || (e == best && unknown_at[i] < unknown_at[p]))
        {
          best = e;
          p = i;
        }
      }
      if(p == f)
        return Error_code::SOLVER_FAILURE;  // a minimiser that is not finite
      const std::size_t j = unknown_at[p];
      const Eigen::Index P = Eigen::Index(p), L = Eigen::Index(f - 1);
      if(P != L)
      {
        H.col(P).head(L + 1).swap(H.col(L).head(L + 1));
        H.row(P).head(L + 1).swap(H.row(L).head(L + 1));
        std::swap(n[P], n[L]);
        std::swap(unknown_at[p], unknown_at[f - 1]);
      }
      const double value = guard.choose(j, n[L], std::round(n[L]), chosen, result.integer_point_collisions_avoided),
                   hjj = H(L, L);
      if(!(hjj > 0))
        return Error_code::SOLVER_FAILURE;
      const Eigen::VectorXd h = H.col(L).head(L);
      n.head(L) += h * ((value - n[L]) / hjj);
      H.topLeftCorner(L, L).noalias() -= h * (h.transpose() / hjj);
      chosen[Eigen::Index(j)] = value;
      guard.fix(j);
    }
    n = chosen;
    result.time_rounding += seconds_since(t);
    return solve_for_integers(n, y_rounded, result);
  }
  // Reference: after each rounding, refactor the system of the remaining
  // unknowns, made from the weighted rows.
  result.time_rounding += seconds_since(t);
  std::vector<char> free_var(m, 1);
  Eigen::SparseMatrix<double> B = m_B1;
  Eigen::VectorXd d = m_d1;
  for(Eigen::Index k = 0; k < B.outerSize(); ++k)
    for(Eigen::SparseMatrix<double>::InnerIterator it(B, k); it; ++it)
      it.valueRef() *= m_row_weight[std::size_t(it.row())];
  for(Eigen::Index r = 0; r < d.size(); ++r)
    d[r] *= m_row_weight[std::size_t(r)];
  const Eigen::SparseMatrix<double> Bn = B.rightCols(Eigen::Index(m));
  Eigen::VectorXd current = n;  // free entries: current minimiser; fixed entries: their integer
  for(std::size_t step = 0; step < m; ++step)
  {
    std::size_t j = m;
    double best = 2;
    for(std::size_t i = 0; i < m; ++i)
      if(free_var[i])
      {
        const double e = std::abs(current[Eigen::Index(i)] - std::round(current[Eigen::Index(i)]));
        if(e < best)
        {
          best = e;
          j = i;
        }
      }
    const double x = current[Eigen::Index(j)];
    current[Eigen::Index(j)] = guard.choose(j, x, std::round(x), current, result.integer_point_collisions_avoided);
    free_var[j] = 0;
    guard.fix(j);
    auto t1 = std::chrono::steady_clock::now();
    std::vector<Eigen::Triplet<double> > select;
    Eigen::VectorXd fixed_part = Eigen::VectorXd::Zero(Eigen::Index(m));
    std::vector<std::size_t> free_list;
    for(std::size_t i = 0; i < nx; ++i)
      select.emplace_back(Eigen::Index(i), Eigen::Index(i), 1.0);
    for(std::size_t i = 0; i < m; ++i)
      if(free_var[i])
      {
        select.emplace_back(Eigen::Index(nx + i), Eigen::Index(nx + free_list.size()), 1.0);
        free_list.push_back(i);
      }
      else
        fixed_part[Eigen::Index(i)] = current[Eigen::Index(i)];
    const std::size_t columns = nx + free_list.size();
    Eigen::SparseMatrix<double> Sel(Eigen::Index(nx + m), Eigen::Index(columns));
    Sel.setFromTriplets(select.begin(), select.end());
    const Eigen::SparseMatrix<double> Br = B * Sel;
    const Eigen::VectorXd dr = d - Bn * fixed_part;
    const Eigen::SparseMatrix<double> BrT = Br.transpose();
    Eigen::SparseMatrix<double> Kr = (BrT * Br).pruned();
    Eigen::MatrixXd r(Eigen::Index(columns), 1);
    r.col(0) = BrT * dr;
    result.time_assembly += seconds_since(t1);
    const auto t2 = std::chrono::steady_clock::now();
    Factored_real_system<SolverTraits> reduced(m_prototype);
    Eigen::MatrixXd sol;
    if(!reduced.factor(Kr) || !reduced.solve(r, sol))
      return Error_code::SOLVER_FAILURE;
    result.time_factorization += seconds_since(t2);
    ++result.factorizations;
    for(std::size_t k = 0; k < free_list.size(); ++k)
      current[Eigen::Index(free_list[k])] = sol(Eigen::Index(nx + k), 0);
    if(step + 1 == m)
      y_rounded.head(Eigen::Index(nx)) = sol.col(0).head(Eigen::Index(nx));
  }
  y_rounded.tail(Eigen::Index(m)) = current;
  return Error_code::SUCCESS;
}

// One solve of the mixed-integer problem with face weights w (one
// Mixed_integer_system, weighted once, rounded once).
template <typename SolverTraits, typename Report>
Error_code solve_mixed_integer(const Eigen::SparseMatrix<double>& B1, const Eigen::VectorXd& d1,
                               const std::vector<double>& row_weight, std::size_t nx, std::size_t m,
                               const std::vector<Distinct_points>& distinct,
                               const SolverTraits& prototype, bool refactor_per_rounding,
                               Eigen::VectorXd& y_continuous, Eigen::VectorXd& y_rounded,
                               Report& result)
{
  Mixed_integer_system<SolverTraits> system(B1, d1, nx, m, distinct, prototype);
  const Error_code code = system.set_weights(row_weight, result);
  if(code != Error_code::SUCCESS)
    return code;
  return system.round(refactor_per_rounding, y_continuous, y_rounded, result);
}

} // namespace internal

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_MIXED_INTEGER_SOLVE_H
