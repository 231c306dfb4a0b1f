// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_COEFFICIENT_SYSTEM_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_COEFFICIENT_SYSTEM_H

// The minimisation of the quadratic energy in the PolyVector coefficients
// (internal/Quadratic_energy.h) under the hard constraints, on a tangent
// bundle, for the active degrees of a field:
//   factor()    lays out the unknowns (internal/Unknown_layout.h), gives the
//               unconstrained components their smoothest N-RoSy field
//               (internal/smoothest_rosy_field.h), assembles the normal
//               equations (internal/Hermitian_assembly.h), analyses their
//               common pattern once and factors every block
//               (internal/Solvers/Block_factorizations.h, through the
//               solver's Sparse_factorization);
//   refactor()  after new data-term weights: refills the matrices in place and
//               refactors numerically (a new analysis only if a term falls
//               outside the pattern);
//   solve()     with the current constraint values and data targets.
// Every failure (a null space, a factorization, a solve, a non-finite result)
// is reported as false.

#include <CGAL/Polyvector_fields/internal/Solvers/Block_factorizations.h>
#include <CGAL/Polyvector_fields/internal/Field_design/Hermitian_assembly.h>
#include <CGAL/Polyvector_fields/internal/Field_design/Quadratic_energy.h>
#include <CGAL/Polyvector_fields/internal/Field_design/Unknown_layout.h>
#include <CGAL/Polyvector_fields/internal/Field_design/constraint_specification.h>
#include <CGAL/Polyvector_fields/internal/Field_design/smoothest_rosy_field.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

template <typename Bundle, typename SolverTraits>
class Coefficient_system
{
public:
  Coefficient_system(const Bundle& bundle, std::size_t N, const std::vector<int>& degrees,
                     const SolverTraits& solver_prototype = SolverTraits(), bool parallel = false,
                     std::vector<double> edge_weights = std::vector<double>())
    : m_bundle(bundle), m_N(N), m_energy(bundle, N, degrees, std::move(edge_weights)),
      m_solver_prototype(solver_prototype), m_factorizations(solver_prototype, parallel)
  {}

  const std::vector<int>& degrees() const { return m_energy.degrees(); }
  const Stage_times& times() const { return m_times; }

  // The length unit sigma = 2^k of the design (see length_exponent()): the
  // system solves for c_m / sigma^(N-m). Changing it requires factor() when
  // there are partial constraints (their rows depend on it), solve() otherwise.
  void set_length_exponent(int k) { m_k = k; }
  int length_exponent() const { return m_k; }

  // The constraints, keyed by face index: changing which faces they are on,
  // their kinds or weights requires factor(); values only, solve().
  Specifications& specifications() { return m_specifications; }
  // The data term: new weights require refactor(), new targets only solve().
  Data_term& data_term() { return m_data; }

  bool factor()
  {
    typename Block_factorizations<SolverTraits>::Solver_scope scope;
    take_length_unit();
    if(!m_layout.build(m_bundle, degrees().size(), m_unit_specifications,
                       m_data.weighted_faces(m_bundle.number_of_faces())))
      return false;
    if(m_layout.has_unconstrained_faces())
    {
      std::vector<std::size_t> faces;
      for(std::size_t f = 0; f < m_layout.number_of_faces(); ++f)
        if(m_layout.kind(f) == Unknown_layout::UNCONSTRAINED)
          faces.push_back(f);
      std::vector<Complex>& rosy = m_layout.unconstrained_values();
      if(!smoothest_rosy_fields(m_bundle, m_N, faces, m_solver_prototype, rosy))
        return false;
      for(Complex& c : rosy)  // unit-length vectors whatever the unit
        c = scaled(c, -m_k * int(m_N));
    }
    return assemble_and_factor();
  }

  // Frees the assembled matrices when no refactor() will follow and the
  // factorizations keep no reference to them (solve() still works). A
  // refactor() after it assembles and analyses anew.
  void release_matrices()
  {
    if(Block_factorizations<SolverTraits>::keeps_matrices)
      return;
    std::vector<Sparse_matrix>().swap(m_matrices);
    std::vector<Dense_vector>().swap(m_fixed_values);
  }

  bool refactor()
  {
    typename Block_factorizations<SolverTraits>::Solver_scope scope;
    if(!refill())
      return assemble_and_factor();
    Timer factor_timer;
    const bool factored = m_factorizations.refactor(m_matrices);
    m_times.factorization = factor_timer.elapsed();
    return factored;
  }

  // coefficients: N per face, face after face (coefficients[f * N + m]).
  bool solve(std::vector<Complex>& coefficients)
  {
    typename Block_factorizations<SolverTraits>::Solver_scope scope;
    take_length_unit();
    m_layout.set_fixed_values(m_unit_specifications);
    const std::size_t F = m_layout.number_of_faces(), slots = degrees().size();
    coefficients.assign(F * m_N, Complex(0));
    // The data targets in the unit (the weights do not change).
    Data_term unit_data = m_data;
    for(std::size_t q = 0; q < unit_data.target.size() && q < slots; ++q)
      for(Complex& t : unit_data.target[q])
        t = scaled(t, -m_k * (int(m_N) - degrees()[q]));
    Timer timer;
    // Blocks write disjoint coefficients (their own degrees); fixed and
    // unconstrained faces have constant expressions.
    const bool solved = for_each_block(m_layout.number_of_blocks(), m_factorizations.parallel(), [&](std::size_t b) {
      Right_hand_side_sink rhs(m_layout.size());
      m_energy.enumerate_terms(m_layout, m_unit_specifications, unit_data, b, rhs);
      typename Block_factorizations<SolverTraits>::Dense_matrix x;
      if(m_layout.size() > 0 && !m_factorizations.solve(b, rhs.vector(), x))
        return false;
      for(std::size_t f = 0; f < F; ++f)
        for(std::size_t q = 0; q < slots; ++q)
        {
          if(!m_layout.in_block(q, b) || m_layout.kind(f) == Unknown_layout::UNCONSTRAINED)
            continue;
          const Unknown_layout::Affine c = m_layout.coefficient(f, q, degrees()[q]);
          Complex value = c.constant;
          for(int j = 0; j < c.size; ++j)
            value += c.coefficient[j] * x(Eigen::Index(c.first + std::size_t(j)), 0);
          coefficients[f * m_N + std::size_t(degrees()[q])] = scaled(value, m_k * (int(m_N) - degrees()[q]));
        }
      return true;
    });
    m_times.solve = timer.elapsed();
    if(!solved)
      return false;
    // Components without constraint: their N-RoSy field, whatever degrees are active.
    for(std::size_t f = 0; f < F; ++f)
      if(m_layout.kind(f) == Unknown_layout::UNCONSTRAINED)
        coefficients[f * m_N] = scaled(m_layout.unconstrained_values()[f], m_k * int(m_N));
    for(const Complex& c : coefficients)
      if(!std::isfinite(c.real()) || !std::isfinite(c.imag()))
        return false;
    return true;
  }

private:
  // Refills the matrices in their pattern with the current terms; false if a
  // term falls outside it (then the matrices must be assembled anew). Only
  // the data term is enumerated: the others are copied from the values
  // without it, computed at the first refill after an assembly (a design
  // that is never refactored does not pay for them).
  bool refill()
  {
    if(m_factorizations.empty() || m_matrices.size() != m_layout.number_of_blocks())
      return false;
    Timer timer;
    std::vector<char> complete(m_matrices.size(), 1);
    const bool first = m_fixed_values.size() != m_matrices.size();
    if(first)
      m_fixed_values.assign(m_matrices.size(), Dense_vector());
    for_each_block(m_matrices.size(), m_factorizations.parallel(), [&](std::size_t b) {
      if(first)
      {
        Sparse_matrix fixed = m_matrices[b];
        Pattern_sink fixed_sink(fixed);
        m_energy.enumerate_terms(m_layout, m_unit_specifications, m_data, b, fixed_sink,
                                 Quadratic_energy::ALL_BUT_DATA_TERM);
        m_fixed_values[b] = fixed.coeffs();
      }
      m_matrices[b].coeffs() = m_fixed_values[b];
      Pattern_sink sink(m_matrices[b], true);
      m_energy.enumerate_terms(m_layout, m_unit_specifications, m_data, b, sink, Quadratic_energy::DATA_TERM);
      complete[b] = sink.complete();
      return true;
    });
    m_times.assembly = timer.elapsed();
    return std::find(complete.begin(), complete.end(), 0) == complete.end();
  }

  static Complex scaled(const Complex& c, int e) { return Complex(std::ldexp(c.real(), e), std::ldexp(c.imag(), e)); }

  void take_length_unit()
  {
    m_unit_specifications.clear();
    for(const auto& entry : m_specifications)
      m_unit_specifications.emplace(entry.first, in_length_unit(entry.second, m_k, m_N));
  }

  // New matrices from triplets, a new shared analysis, and the factorizations.
  // The matrices are members: refactor() refills them.
  bool assemble_and_factor()
  {
    Timer timer;
    const std::size_t blocks = m_layout.number_of_blocks();
    m_matrices.assign(blocks, Sparse_matrix());
    m_fixed_values.clear();  // refill() computes them for these matrices
    for_each_block(blocks, m_factorizations.parallel(), [&](std::size_t b) {
      Triplet_sink sink(4 * m_bundle.interior_edges().size() + m_layout.size());
      m_energy.enumerate_terms(m_layout, m_unit_specifications, m_data, b, sink);
      m_matrices[b] = sink.matrix(m_layout.size());
      return true;
    });
    m_times.assembly = timer.elapsed();
    Timer factor_timer;
    const bool factored = m_factorizations.factor(m_matrices);
    m_times.factorization = factor_timer.elapsed();
    return factored;
  }

  const Bundle& m_bundle;
  std::size_t m_N;
  Quadratic_energy m_energy;
  SolverTraits m_solver_prototype;
  Block_factorizations<SolverTraits> m_factorizations;
  Specifications m_specifications, m_unit_specifications;
  int m_k = 0;
  Data_term m_data;
  Unknown_layout m_layout;
  std::vector<Sparse_matrix> m_matrices;
  std::vector<Dense_vector> m_fixed_values;  // per block: the values of the matrix without the data term
  Stage_times m_times;
};

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_COEFFICIENT_SYSTEM_H
