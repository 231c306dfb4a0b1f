// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_COEFFICIENT_SYSTEM_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_COEFFICIENT_SYSTEM_H

// The quadratic energy in the PolyVector coefficients and its minimisation.
//
// Unknowns are the coefficients c_{f,m} of the monic polynomials, one complex
// number per face and per *active* degree m (a degree is inactive when it is
// zero everywhere: odd degrees of sign-symmetric fields, and degrees whose
// constraint values are all zero). The energy is
//
//   sum_{interior edges (f,g)} sum_m | c_{f,m} conj(e_f)^(N-m) - c_{g,m} conj(e_g)^(N-m) |^2   (smoothness, NOTES §1)
// + sum_{soft full constraints}    w_f sum_m |c_{f,m} - c^0_{f,m}|^2
// + sum_{soft partial constraints} w_f sum_rows |V_f c_f - b_f|^2
// + sum_{f,m} W_{f,m} |c_{f,m} - t_{f,m}|^2        (data term of the frame-field global steps)
//
// subject to the hard constraints: a full hard constraint fixes c_f, a partial
// hard constraint V_f c_f = b_f restricts c_f to the affine set p_f + Z_f t_f
// (Z_f an orthonormal basis of the null space of V_f). Every term is the
// squared modulus of an affine function of the unknowns, so the minimiser
// solves the Hermitian normal equations M x = r, assembled term by term.
//
// Without partial constraints the degrees never share a term: each degree is
// solved on its own, all with the same sparsity pattern. Partial constraints
// couple the degrees of their face: then all degrees are solved together.
//
// A connected component without any constraint (and no data term) gets the
// smoothest unit-norm N-RoSy field: the eigenvector of the smallest
// eigenvalue of the degree-0 connection Laplacian, scaled so that the mean of
// |c_0|^2 over the component is 1 (unit-length vectors); other degrees are 0.
// A component constrained only by partial constraints may leave a null space
// (a flat region where a rotation keeps P(u) = 0): a regularisation of
// relative size 1e-10 picks the minimum-norm minimiser there.
//
// With `parallel` (and TBB linked, and a solver whose Factorization is
// thread safe), the independent blocks are assembled, factored and solved in
// parallel. Each block is computed by the same operations whatever the thread,
// so the result is bit-identical to the sequential run.

#include <CGAL/Polyvector_fields/internal/Factorization.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// What a constraint asks of one face, in the face's frame.
struct Face_specification
{
  // Full constraint: values[m] for every degree m = 0..N-1.
  bool full = false;
  std::vector<Complex> values;
  // Partial constraint: rows . (c_{f,q})_q = rhs over the active degrees q.
  Eigen::MatrixXcd rows;
  Eigen::VectorXcd rhs;
  // Infinite: hard. Finite and positive: soft.
  double weight = std::numeric_limits<double>::infinity();

  bool is_hard() const { return std::isinf(weight); }
};

struct Stage_times
{
  double assembly = 0, factorization = 0, solve = 0;
};

template <typename Connection, typename SolverTraits>
class Coefficient_system
{
public:
  enum Face_kind { FREE, FIXED, PARTIAL, UNCONSTRAINED };

  static constexpr double regularisation = 1e-10;

  Coefficient_system(const Connection& connection, std::size_t N, const std::vector<int>& degrees,
                     const SolverTraits& solver_prototype = SolverTraits(), bool parallel = false)
    : m_connection(connection), m_N(N), m_degrees(degrees), m_solver_prototype(solver_prototype),
      m_parallel(parallel && Factorization<SolverTraits>::is_thread_safe)
  {
    const std::size_t F = connection.number_of_faces();
    m_transport.resize(m_degrees.size());
    const auto& edges = connection.interior_edges();
    for(std::size_t q = 0; q < m_degrees.size(); ++q)
    {
      const int power = int(N) - m_degrees[q];
      m_transport[q].resize(edges.size());
      for(std::size_t e = 0; e < edges.size(); ++e)
        m_transport[q][e] = { std::pow(std::conj(edges[e].e_f), power), std::pow(std::conj(edges[e].e_g), power) };
    }
    m_data_weight.assign(m_degrees.size(), std::vector<double>());
    m_data_target.assign(m_degrees.size(), std::vector<Complex>());
    (void)F;
  }

  const std::vector<int>& degrees() const { return m_degrees; }

  // The constraints, keyed by face index. Changing them requires factor().
  std::map<std::size_t, Face_specification>& specifications() { return m_specs; }

  // Optional data term W_{f,q} |c_{f,q} - t_{f,q}|^2 (empty vectors: none).
  // Changing the weights requires refactor_numeric(); the targets only solve().
  std::vector<std::vector<double> >& data_weights() { return m_data_weight; }
  std::vector<std::vector<Complex> >& data_targets() { return m_data_target; }

  const Stage_times& times() const { return m_times; }

  // Classifies faces, lays out the unknowns, assembles, analyses and factors.
  bool factor()
  {
    typename Factorization<SolverTraits>::Solver_scope scope;
    return classify() && factor_new_pattern();
  }

  // Refactors after a change of weights only (same pattern, same symbolic
  // analysis): the new values are accumulated into the existing matrices. A
  // term outside the pattern (a weight that went from zero to nonzero) sends
  // it back to a new assembly and analysis.
  bool refactor_numeric()
  {
    typename Factorization<SolverTraits>::Solver_scope scope;
    if(m_factorizations.empty() || m_matrices.size() != m_factorizations.size())
      return factor_new_pattern();
    Timer timer;
    std::vector<char> complete(m_matrices.size(), 1);
    for_each_block(m_matrices.size(), [&](std::size_t b) {
      m_matrices[b].coeffs().setZero();
      Assembler assembler{ nullptr, nullptr, &m_matrices[b], &complete[b] };
      enumerate_terms(b, assembler);
      return true;
    });
    m_times.assembly = timer.elapsed();
    if(std::find(complete.begin(), complete.end(), 0) != complete.end())
      return factor_new_pattern();
    return factor_blocks(false);
  }

  // Solves with the current constraint values and data targets.
  // coefficients: N * F, face-major (coefficients[f * N + m]).
  bool solve(std::vector<Complex>& coefficients)
  {
    typename Factorization<SolverTraits>::Solver_scope scope;
    const std::size_t F = m_connection.number_of_faces();
    coefficients.assign(F * m_N, Complex(0));
    Timer timer;
    // Fixed and unconstrained faces first.
    for(std::size_t f = 0; f < F; ++f)
    {
      if(m_kind[f] == FIXED)
      {
        const Face_specification& s = m_specs.at(f);
        for(std::size_t q = 0; q < m_degrees.size(); ++q)
          coefficients[f * m_N + m_degrees[q]] = s.values[m_degrees[q]];
      }
      else if(m_kind[f] == UNCONSTRAINED)
        coefficients[f * m_N] = m_unconstrained_solution[f];
    }
    const std::size_t blocks = m_coupled ? 1 : m_degrees.size();
    // Blocks write disjoint coefficients (their own degree).
    const bool solved = for_each_block(blocks, [&](std::size_t b) {
      Dense_vector rhs = Dense_vector::Zero(Eigen::Index(m_block_size));
      Assembler assembler{ nullptr, &rhs };
      enumerate_terms(b, assembler);
      Dense_vector x;
      if(m_block_size > 0 && !m_factorizations[b]->solve(rhs, x))
        return false;
      for(std::size_t f = 0; f < F; ++f)
      {
        if(m_kind[f] != FREE && m_kind[f] != PARTIAL)
          continue;
        for(std::size_t q = 0; q < m_degrees.size(); ++q)
        {
          if(!m_coupled && q != b)
            continue;
          Affine c = coefficient(f, q, b);
          Complex value = c.constant;
          for(int j = 0; j < c.size; ++j)
            value += c.coefficient[j] * x[Eigen::Index(c.variable[j])];
          coefficients[f * m_N + m_degrees[q]] = value;
        }
      }
      return true;
    });
    m_times.solve = timer.elapsed();
    if(!solved)
      return false;
    for(const Complex& c : coefficients)
      if(!std::isfinite(c.real()) || !std::isfinite(c.imag()))
        return false;
    return true;
  }

private:
  // Runs task(b) for every block b, in parallel when allowed; true when every
  // task returned true.
  template <typename Task>
  bool for_each_block(std::size_t blocks, const Task& task) const
  {
    std::vector<char> ok(blocks, 0);
#ifdef CGAL_LINKED_WITH_TBB
    if(m_parallel && blocks > 1)
    {
      tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) { ok[b] = task(b) ? 1 : 0; });
      return std::find(ok.begin(), ok.end(), 0) == ok.end();
    }
#endif
    for(std::size_t b = 0; b < blocks; ++b)
      if(!task(b))
        return false;
    return true;
  }

  struct Timer
  {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
  };

  // c_{f,q} = constant + sum_j coefficient[j] * x[variable[j]]
  struct Affine
  {
    Complex constant = 0;
    int size = 0;
    const Complex* coefficient = nullptr;
    const std::size_t* variable = nullptr;
  };

  // A term |sum_j alpha_j x_j + gamma|^2, accumulated into the normal
  // equations: the matrix as triplets, or into the entries of an assembled
  // matrix of the same pattern (`complete` is cleared if one is missing); the
  // right-hand side.
  struct Assembler
  {
    std::vector<Eigen::Triplet<Complex> >* triplets;
    Dense_vector* rhs;
    Sparse_matrix* matrix = nullptr;
    char* complete = nullptr;

    void add(const std::vector<std::size_t>& variable, const std::vector<Complex>& alpha, const Complex& gamma) const
    {
      for(std::size_t i = 0; i < variable.size(); ++i)
      {
        if(triplets)
          for(std::size_t j = 0; j < variable.size(); ++j)
            triplets->emplace_back(int(variable[i]), int(variable[j]), std::conj(alpha[i]) * alpha[j]);
        if(matrix)
          for(std::size_t j = 0; j < variable.size(); ++j)
          {
            Complex* entry = find_entry(*matrix, variable[i], variable[j]);
            if(entry)
              *entry += std::conj(alpha[i]) * alpha[j];
            else
              *complete = 0;
          }
        if(rhs)
          (*rhs)[Eigen::Index(variable[i])] -= std::conj(alpha[i]) * gamma;
      }
    }

    // The stored entry (row, column) of a compressed matrix, or null.
    static Complex* find_entry(Sparse_matrix& A, std::size_t row, std::size_t column)
    {
      const int* rows = A.innerIndexPtr();
      const int* begin = rows + A.outerIndexPtr()[column];
      const int* end = rows + A.outerIndexPtr()[column + 1];
      const int* it = std::lower_bound(begin, end, int(row));
      return (it != end && std::size_t(*it) == row) ? A.valuePtr() + (it - rows) : nullptr;
    }
  };

  bool classify()
  {
    const std::size_t F = m_connection.number_of_faces();
    const std::size_t C = m_connection.number_of_components();
    m_kind.assign(F, FREE);
    std::vector<char> determined(C, 0), touched(C, 0);
    m_coupled = false;
    m_partial_basis.clear();
    for(const auto& entry : m_specs)
    {
      const std::size_t f = entry.first;
      const Face_specification& s = entry.second;
      const std::size_t c = m_connection.component(f);
      touched[c] = 1;
      if(s.full)
      {
        determined[c] = 1;
        if(s.is_hard())
          m_kind[f] = FIXED;
      }
      else
      {
        m_coupled = true;
        if(s.is_hard())
        {
          m_kind[f] = PARTIAL;
          if(!null_space_parametrisation(s, m_partial_basis[f]))
            return false;
        }
      }
    }
    for(std::size_t q = 0; q < m_data_weight.size(); ++q)
      for(std::size_t f = 0; f < m_data_weight[q].size(); ++f)
        if(m_data_weight[q][f] > 0)
          determined[m_connection.component(f)] = touched[m_connection.component(f)] = 1;

    m_regularised.assign(C, 0);
    for(std::size_t c = 0; c < C; ++c)
      m_regularised[c] = touched[c] && !determined[c];

    // Unconstrained components: smoothest unit N-RoSy field.
    m_unconstrained_solution.assign(F, Complex(0));
    std::vector<std::size_t> untouched;
    for(std::size_t c = 0; c < C; ++c)
      if(!touched[c])
        untouched.push_back(c);
    for(std::size_t f = 0; f < F; ++f)
      if(!touched[m_connection.component(f)])
        m_kind[f] = UNCONSTRAINED;
    if(!untouched.empty())
      smoothest_rosy_fields();

    // Unknown layout.
    const std::size_t slots = m_degrees.size();
    m_first_variable.assign(F, 0);
    m_block_size = 0;
    for(std::size_t f = 0; f < F; ++f)
    {
      m_first_variable[f] = m_block_size;
      if(m_kind[f] == FREE)
        m_block_size += m_coupled ? slots : 1;
      else if(m_kind[f] == PARTIAL)
        m_block_size += std::size_t(m_partial_basis[f].Z.cols());
    }
    // Scratch of coefficient(), one per slot: blocks may be enumerated in parallel.
    m_identity_variables.resize(slots);
    m_partial_row_coefficients.resize(slots);
    m_partial_row_variables.resize(slots);
    m_unit = Complex(1);
    return true;
  }

  struct Partial_basis
  {
    Eigen::VectorXcd p;   // particular solution (minimum norm)
    Eigen::MatrixXcd Z;   // orthonormal null-space basis, slots x r
  };

  // The null space of the rows of a partial constraint, and its minimum-norm
  // particular solution. The rows are scaled to a largest entry of 1 first
  // (the equations, hence the solution set, do not change), so that the SVD's
  // rank threshold is relative to each row. Returns false if the SVD fails.
  static bool null_space_parametrisation(const Face_specification& s, Partial_basis& basis)
  {
    Eigen::MatrixXcd rows = s.rows;
    Eigen::VectorXcd rhs = s.rhs;
    for(Eigen::Index r = 0; r < rows.rows(); ++r)
    {
      const double largest = (std::max)(rows.row(r).cwiseAbs().maxCoeff(), std::abs(rhs[r]));
      if(largest > 0)
      {
        rows.row(r) /= largest;
        rhs[r] /= largest;
      }
    }
    Eigen::JacobiSVD<Eigen::MatrixXcd> svd(rows, Eigen::ComputeFullU | Eigen::ComputeFullV);
    if(svd.info() != Eigen::Success)
      return false;
    svd.setThreshold(1e-12);
    const Eigen::Index rank = svd.rank();
    basis.p = svd.solve(rhs);
    basis.Z = svd.matrixV().rightCols(rows.cols() - rank);
    return basis.p.allFinite() && basis.Z.allFinite();
  }

  // The affine expression of c_{f,q} in the unknowns of block b.
  Affine coefficient(std::size_t f, std::size_t q, std::size_t /*block*/)
  {
    Affine a;
    switch(m_kind[f])
    {
      case FIXED:
        a.constant = m_specs.at(f).values[m_degrees[q]];
        break;
      case FREE:
        m_identity_variables[q] = m_first_variable[f] + (m_coupled ? q : 0);
        a.size = 1;
        a.coefficient = &m_unit;
        a.variable = &m_identity_variables[q];
        break;
      case PARTIAL:
      {
        const Partial_basis& basis = m_partial_basis.at(f);
        const Eigen::Index r = basis.Z.cols();
        std::vector<Complex>& coefficients = m_partial_row_coefficients[q];
        std::vector<std::size_t>& variables = m_partial_row_variables[q];
        coefficients.resize(std::size_t(r));
        variables.resize(std::size_t(r));
        for(Eigen::Index j = 0; j < r; ++j)
        {
          coefficients[std::size_t(j)] = basis.Z(Eigen::Index(q), j);
          variables[std::size_t(j)] = m_first_variable[f] + std::size_t(j);
        }
        a.constant = basis.p[Eigen::Index(q)];
        a.size = int(r);
        a.coefficient = coefficients.data();
        a.variable = variables.data();
        break;
      }
      case UNCONSTRAINED:
        a.constant = (m_degrees[q] == 0) ? m_unconstrained_solution[f] : Complex(0);
        break;
    }
    return a;
  }

  // Appends scale * c_{f,q} to the term (variables, alpha, gamma).
  void append(std::size_t f, std::size_t q, std::size_t block, const Complex& scale,
              std::vector<std::size_t>& variables, std::vector<Complex>& alpha, Complex& gamma)
  {
    const Affine a = coefficient(f, q, block);
    gamma += scale * a.constant;
    for(int j = 0; j < a.size; ++j)
    {
      variables.push_back(a.variable[j]);
      alpha.push_back(scale * a.coefficient[j]);
    }
  }

  // Enumerates every term of block b (one degree, or all degrees when coupled).
  void enumerate_terms(std::size_t block, const Assembler& assembler)
  {
    const std::size_t slots = m_degrees.size();
    std::vector<std::size_t> variables;
    std::vector<Complex> alpha;
    auto in_block = [&](std::size_t q) { return m_coupled || q == block; };
    auto flush = [&](const Complex& gamma) {
      if(!variables.empty())
        assembler.add(variables, alpha, gamma);
      variables.clear();
      alpha.clear();
    };

    // Smoothness.
    const auto& edges = m_connection.interior_edges();
    for(std::size_t e = 0; e < edges.size(); ++e)
    {
      const std::size_t f = edges[e].f, g = edges[e].g;
      if(m_kind[f] == UNCONSTRAINED)
        continue;  // then g is in the same component
      if((m_kind[f] == FIXED) && (m_kind[g] == FIXED))
        continue;
      for(std::size_t q = 0; q < slots; ++q)
      {
        if(!in_block(q))
          continue;
        Complex gamma = 0;
        append(f, q, block, m_transport[q][e].first, variables, alpha, gamma);
        append(g, q, block, -m_transport[q][e].second, variables, alpha, gamma);
        flush(gamma);
      }
    }

    // Soft constraints.
    for(const auto& entry : m_specs)
    {
      const std::size_t f = entry.first;
      const Face_specification& s = entry.second;
      if(s.is_hard())
        continue;
      const double root_weight = std::sqrt(s.weight);
      if(s.full)
      {
        for(std::size_t q = 0; q < slots; ++q)
        {
          if(!in_block(q))
            continue;
          Complex gamma = -root_weight * s.values[m_degrees[q]];
          append(f, q, block, root_weight, variables, alpha, gamma);
          flush(gamma);
        }
      }
      else
      {
        for(Eigen::Index row = 0; row < s.rows.rows(); ++row)
        {
          Complex gamma = -root_weight * s.rhs[row];
          for(std::size_t q = 0; q < slots; ++q)
            append(f, q, block, root_weight * s.rows(row, Eigen::Index(q)), variables, alpha, gamma);
          flush(gamma);
        }
      }
    }

    // Data term of the frame-field iterations.
    for(std::size_t q = 0; q < slots; ++q)
    {
      if(!in_block(q) || m_data_weight[q].empty())
        continue;
      for(std::size_t f = 0; f < m_data_weight[q].size(); ++f)
      {
        const double w = m_data_weight[q][f];
        if(!(w > 0) || m_kind[f] == FIXED)
          continue;
        const double root_weight = std::sqrt(w);
        Complex gamma = -root_weight * (m_data_target[q].empty() ? Complex(0) : m_data_target[q][f]);
        append(f, q, block, root_weight, variables, alpha, gamma);
        flush(gamma);
      }
    }

    // Regularisation of components fixed only by partial constraints.
    const double root_epsilon = std::sqrt(regularisation);
    for(std::size_t f = 0; f < m_kind.size(); ++f)
    {
      if(!m_regularised[m_connection.component(f)] || (m_kind[f] != FREE && m_kind[f] != PARTIAL))
        continue;
      const std::size_t first = m_first_variable[f];
      const std::size_t count = (m_kind[f] == FREE) ? (m_coupled ? slots : 1)
                                                   : std::size_t(m_partial_basis[f].Z.cols());
      for(std::size_t j = 0; j < count; ++j)
      {
        variables.push_back(first + j);
        alpha.push_back(root_epsilon);
        flush(Complex(0));
      }
    }
  }

  // New factorizations sharing a new analysis, on matrices assembled anew.
  bool factor_new_pattern()
  {
    m_factorizations.clear();
    // All blocks have one pattern: they share one symbolic analysis.
    const std::size_t blocks = m_coupled ? 1 : m_degrees.size();
    const auto analysis = std::make_shared<typename Factorization<SolverTraits>::Shared_analysis>();
    for(std::size_t b = 0; b < blocks; ++b)
    {
      m_factorizations.emplace_back(new Factorization<SolverTraits>(m_solver_prototype));
      m_factorizations.back()->share_analysis(analysis);
    }
    Timer timer;
    // Kept alive as members: some solvers (Eigen's iterative ones) keep a
    // reference, and refactor_numeric() refills them.
    std::vector<Sparse_matrix>& matrices = m_matrices;
    matrices.assign(blocks, Sparse_matrix());
    for_each_block(blocks, [&](std::size_t b) {
      std::vector<Eigen::Triplet<Complex> > triplets;
      triplets.reserve(m_connection.interior_edges().size() * 4 + m_block_size);
      Assembler assembler{ &triplets, nullptr };
      enumerate_terms(b, assembler);
      matrices[b].resize(Eigen::Index(m_block_size), Eigen::Index(m_block_size));
      matrices[b].setFromTriplets(triplets.begin(), triplets.end());
      matrices[b].makeCompressed();
      return true;
    });
    m_times.assembly = timer.elapsed();
    return factor_blocks(true);
  }

  // Analysis (when `analyse`) and numeric factorization of the assembled blocks.
  bool factor_blocks(bool analyse)
  {
    const std::size_t blocks = m_factorizations.size();
    std::vector<Sparse_matrix>& matrices = m_matrices;
    Timer factor_timer;
    if(m_block_size > 0)
    {
      // The first analysis computes the shared one, alone; then every block.
      if(analyse && !m_factorizations[0]->analyze(matrices[0]))
        return false;
      const bool factored = for_each_block(blocks, [&](std::size_t b) {
        if(analyse && b > 0 && !m_factorizations[b]->analyze(matrices[b]))
          return false;
        return m_factorizations[b]->factorize(matrices[b]);
      });
      if(!factored)
        return false;
    }
    m_times.factorization = factor_timer.elapsed();
    return true;
  }

  // Inverse iteration on the degree-0 connection Laplacian of each component
  // without constraints (shifted by a tiny multiple of the identity so that a
  // flat component, whose smallest eigenvalue is 0, can be factored).
  void smoothest_rosy_fields()
  {
    const std::size_t F = m_connection.number_of_faces();
    const auto& edges = m_connection.interior_edges();
    const int power = int(m_N);
    std::vector<std::size_t> local(F, std::size_t(-1));
    std::vector<std::size_t> faces;
    for(std::size_t f = 0; f < F; ++f)
      if(m_kind[f] == UNCONSTRAINED)
      {
        local[f] = faces.size();
        faces.push_back(f);
      }
    const Eigen::Index n = Eigen::Index(faces.size());
    std::vector<Eigen::Triplet<Complex> > triplets;
    for(const auto& e : edges)
    {
      if(local[e.f] == std::size_t(-1))
        continue;
      const Complex a = std::pow(std::conj(e.e_f), power), b = -std::pow(std::conj(e.e_g), power);
      const int i = int(local[e.f]), j = int(local[e.g]);
      triplets.emplace_back(i, i, std::norm(a));
      triplets.emplace_back(j, j, std::norm(b));
      triplets.emplace_back(i, j, std::conj(a) * b);
      triplets.emplace_back(j, i, std::conj(b) * a);
    }
    const double shift = 1e-8;
    for(Eigen::Index i = 0; i < n; ++i)
      triplets.emplace_back(int(i), int(i), Complex(shift));
    Sparse_matrix A(n, n);
    A.setFromTriplets(triplets.begin(), triplets.end());
    Factorization<SolverTraits> factorization(m_solver_prototype);
    if(!factorization.analyze(A) || !factorization.factorize(A))
      return;  // left at zero: solve() then reports a non-finite-free but zero field

    // Components are decoupled in A, so one inverse iteration serves them all
    // as long as each component is normalised on its own.
    Dense_vector x = Dense_vector::Ones(n), y;
    // Per component: unit mean |c_0|^2, and the phase that best aligns with
    // `reference` (the previous iterate), so that the iteration converges.
    auto normalise = [&](Dense_vector& v, const Dense_vector& reference) {
      std::map<std::size_t, double> norm2;
      std::map<std::size_t, std::size_t> count;
      std::map<std::size_t, Complex> alignment;
      for(Eigen::Index i = 0; i < n; ++i)
      {
        const std::size_t c = m_connection.component(faces[std::size_t(i)]);
        norm2[c] += std::norm(v[i]);
        count[c] += 1;
        alignment[c] += std::conj(reference[i]) * v[i];
      }
      for(Eigen::Index i = 0; i < n; ++i)
      {
        const std::size_t c = m_connection.component(faces[std::size_t(i)]);
        const Complex a = alignment[c];
        const Complex phase = std::abs(a) > 0 ? std::conj(a) / std::abs(a) : Complex(1);
        v[i] *= phase / std::sqrt(norm2[c] / double(count[c]));
      }
    };
    normalise(x, x);
    for(int iteration = 0; iteration < 1000; ++iteration)
    {
      if(!factorization.solve(x, y))
        return;
      normalise(y, x);
      const double change = (y - x).norm() / std::sqrt(double(n));
      x.swap(y);
      if(change < 1e-12)
        break;
    }
    for(Eigen::Index i = 0; i < n; ++i)
      m_unconstrained_solution[faces[std::size_t(i)]] = x[i];
  }

  const Connection& m_connection;
  std::size_t m_N;
  std::vector<int> m_degrees;
  SolverTraits m_solver_prototype;
  bool m_parallel;
  std::vector<std::vector<std::pair<Complex, Complex> > > m_transport;  // per slot, per edge: conj(e_f)^(N-m), conj(e_g)^(N-m)
  std::map<std::size_t, Face_specification> m_specs;
  std::vector<std::vector<double> > m_data_weight;
  std::vector<std::vector<Complex> > m_data_target;

  std::vector<Face_kind> m_kind;
  std::map<std::size_t, Partial_basis> m_partial_basis;
  std::vector<char> m_regularised;
  std::vector<Complex> m_unconstrained_solution;
  std::vector<std::size_t> m_first_variable;
  std::size_t m_block_size = 0;
  bool m_coupled = false;
  std::vector<Sparse_matrix> m_matrices;
  std::vector<std::unique_ptr<Factorization<SolverTraits> > > m_factorizations;
  Stage_times m_times;

  // scratch for Affine expressions
  std::vector<std::size_t> m_identity_variables;
  Complex m_unit = 1;
  std::vector<std::vector<Complex> > m_partial_row_coefficients;
  std::vector<std::vector<std::size_t> > m_partial_row_variables;
};

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_COEFFICIENT_SYSTEM_H
