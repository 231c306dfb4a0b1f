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
// with an exact update of the small dense system after each rounding.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Sparse_factorization.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// A factorization of a real symmetric positive definite matrix through the
// solver's Sparse_factorization (the model of the SparseFactorization concept),
// kept alive for several block solves. `A` must outlive it.
template <typename SolverTraits>
class Factored_real_system
{
  typedef Sparse_factorization<SolverTraits, double> Factorization;

public:
  explicit Factored_real_system(const SolverTraits& prototype) : m_factorization(prototype) {}
  bool factor(const Eigen::SparseMatrix<double>& A) { return m_factorization.analyze(A) && m_factorization.factorize(A); }
  // solves A X = B for a dense block B, all its columns at once
  bool solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) { return m_factorization.solve(B, X) && X.allFinite(); }

private:
  typename Factorization::Solver_scope m_scope;
  Factorization m_factorization;
};

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

// One solve of the mixed-integer problem with face weights w:
// minimise |W^(1/2)(B y - d)|^2, y = (x continuous, n integer), rounding so
// that no form of `distinct` becomes zero where the other integer next to the
// minimiser avoids it.
template <typename SolverTraits, typename Report>
Error_code solve_mixed_integer(const Eigen::SparseMatrix<double>& B1, const Eigen::VectorXd& d1,
                               const std::vector<double>& row_weight, std::size_t nx, std::size_t m,
                               const std::vector<Distinct_points>& distinct,
                               const SolverTraits& prototype, bool refactor_per_rounding,
                               Eigen::VectorXd& y_continuous, Eigen::VectorXd& y_rounded,
                               Report& result)
{
  auto t = std::chrono::steady_clock::now();
  Eigen::SparseMatrix<double> B = B1;
  Eigen::VectorXd d = d1;
  for(Eigen::Index k = 0; k < B.outerSize(); ++k)
    for(Eigen::SparseMatrix<double>::InnerIterator it(B, k); it; ++it)
      it.valueRef() *= row_weight[std::size_t(it.row())];
  for(Eigen::Index r = 0; r < d.size(); ++r)
    d[r] *= row_weight[std::size_t(r)];
  const Eigen::SparseMatrix<double> Bx = B.leftCols(Eigen::Index(nx));
  const Eigen::SparseMatrix<double> Bn = B.rightCols(Eigen::Index(m));
  const Eigen::SparseMatrix<double> BxT = Bx.transpose();
  // Eigen's pruned sparse product reads memory it does not own when a factor
  // has no column or no row (seen on the 12-triangle box, nx = 0): the empty
  // blocks are made directly.
  Eigen::SparseMatrix<double> Kxx{ Eigen::Index(nx), Eigen::Index(nx) }, Kxn{ Eigen::Index(nx), Eigen::Index(m) };
  Eigen::VectorXd bx = Eigen::VectorXd::Zero(Eigen::Index(nx));
  if(nx > 0)
  {
    Kxx = (BxT * Bx).pruned();
    bx = BxT * d;
    if(m > 0)
      Kxn = (BxT * Bn).pruned();  // few non-zero rows: the seams' neighbourhoods
  }
  Kxx.makeCompressed();
  Kxn.makeCompressed();
  result.time_assembly += seconds_since(t);

  t = std::chrono::steady_clock::now();
  Factored_real_system<SolverTraits> system(prototype);
  if(!system.factor(Kxx))
    return Error_code::SOLVER_FAILURE;
  ++result.factorizations;
  result.time_factorization += seconds_since(t);
  t = std::chrono::steady_clock::now();
  Eigen::MatrixXd X;
  if(!system.solve(bx, X))
    return Error_code::SOLVER_FAILURE;
  const Eigen::VectorXd x0 = X.col(0);
  y_continuous.resize(Eigen::Index(nx + m));
  y_rounded.resize(Eigen::Index(nx + m));
  if(m == 0)
  {
    y_continuous = x0;
    y_rounded = x0;
    result.time_schur += seconds_since(t);
    return Error_code::SUCCESS;
  }

  // Schur complement of the integer unknowns, S n = g, with
  // S = Knn - Kxn^T Kxx^-1 Kxn, g = bn - Kxn^T x0: block solves of 64 columns.
  const Eigen::SparseMatrix<double> KxnT = Kxn.transpose();
  Eigen::MatrixXd S = Eigen::MatrixXd(Eigen::SparseMatrix<double>(Bn.transpose() * Bn));
  const Eigen::VectorXd g = Bn.transpose() * d - KxnT * x0;
  const Eigen::Index block = 64;
  for(Eigen::Index j0 = 0; j0 < Eigen::Index(m); j0 += block)
  {
    const Eigen::Index w = (std::min)(block, Eigen::Index(m) - j0);
    const Eigen::MatrixXd R = Eigen::MatrixXd(Kxn.middleCols(j0, w));
    if(!system.solve(R, X))
      return Error_code::SOLVER_FAILURE;
    S.middleCols(j0, w) -= KxnT * X;
  }
  S = 0.5 * (S + S.transpose());
  result.time_schur += seconds_since(t);

  t = std::chrono::steady_clock::now();
  Eigen::LLT<Eigen::MatrixXd> llt(S);
  if(llt.info() != Eigen::Success)
    return Error_code::SOLVER_FAILURE;
  Eigen::MatrixXd H = llt.solve(Eigen::MatrixXd::Identity(S.rows(), S.cols()));
  Eigen::VectorXd n = llt.solve(g);
  result.time_rounding += seconds_since(t);
  // continuous unknowns for given integers: x = Kxx^-1 (bx - Kxn n)
  auto continuous_part = [&](const Eigen::VectorXd& nn, Eigen::VectorXd& x) {
    const auto t2 = std::chrono::steady_clock::now();
    Eigen::MatrixXd sol;
    const bool ok = system.solve(Eigen::VectorXd(bx - Kxn * nn), sol);
    if(ok)
      x = sol.col(0);
    result.time_schur += seconds_since(t2);
    return ok;
  };
  Eigen::VectorXd xc;
  if(!continuous_part(n, xc))
    return Error_code::SOLVER_FAILURE;
  y_continuous.head(Eigen::Index(nx)) = xc;
  y_continuous.tail(Eigen::Index(m)) = n;
  t = std::chrono::steady_clock::now();

  std::vector<char> free_var(m, 1);
  Collision_guard guard(distinct, m);
  if(!refactor_per_rounding)
  {
    // Greedy rounding, the unknown closest to an integer first. Fixing n_j = v
    // moves the minimiser of the others by H_.j (v - n_j) / H_jj and the inverse
    // of the remaining block is H - H_.j H_j. / H_jj: O(m^2) per rounding, no refactorization.
    for(std::size_t step = 0; step < m; ++step)
    {
      std::size_t j = m;
      double best = 2;
      for(std::size_t i = 0; i < m; ++i)
        if(free_var[i])
        {
          const double e = std::abs(n[Eigen::Index(i)] - std::round(n[Eigen::Index(i)]));
          if(e < best)
          {
            best = e;
            j = i;
          }
        }
      const Eigen::Index J = Eigen::Index(j);
      const double value = guard.choose(j, n[J], std::round(n[J]), n, result.integer_point_collisions_avoided),
                   hjj = H(J, J);
      if(!(hjj > 0))
        return Error_code::SOLVER_FAILURE;
      const Eigen::VectorXd h = H.col(J);
      n += h * ((value - n[J]) / hjj);
      H.noalias() -= h * (h.transpose() / hjj);
      n[J] = value;
      free_var[j] = 0;
      guard.fix(j);
    }
    result.time_rounding += seconds_since(t);
  }
  else
  {
    // Reference: after each rounding, refactor the system of the remaining unknowns.
    result.time_rounding += seconds_since(t);
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
      Factored_real_system<SolverTraits> reduced(prototype);
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
  Eigen::VectorXd xr;
  if(!continuous_part(n, xr))
    return Error_code::SOLVER_FAILURE;
  y_rounded.head(Eigen::Index(nx)) = xr;
  y_rounded.tail(Eigen::Index(m)) = n;
  return Error_code::SUCCESS;
}

} // namespace internal

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_MIXED_INTEGER_SOLVE_H
