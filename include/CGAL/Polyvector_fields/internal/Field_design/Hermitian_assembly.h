// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_HERMITIAN_ASSEMBLY_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_HERMITIAN_ASSEMBLY_H

// The sinks of Quadratic_energy::enumerate_terms(): each accumulates a term
// |alpha . x + gamma|^2 into the Hermitian normal equations M x = r, with
// M += alpha^H alpha and r -= alpha^H gamma.
// - Triplet_sink collects the matrix as triplets, for a new pattern;
// - Pattern_sink adds into the entries of an assembled matrix of the same
//   pattern (zeroed first), and says when a term falls outside it;
// - Right_hand_side_sink builds r.

#include <CGAL/Polyvector_fields/internal/types.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <complex>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

class Triplet_sink
{
public:
  explicit Triplet_sink(std::size_t expected = 0) { m_triplets.reserve(expected); }

  template <typename Term>
  void add(const Term& t)
  {
    for(std::size_t i = 0; i < t.variables.size(); ++i)
      for(std::size_t j = 0; j < t.variables.size(); ++j)
        m_triplets.emplace_back(int(t.variables[i]), int(t.variables[j]), std::conj(t.alphas[i]) * t.alphas[j]);
  }

  // The assembled n x n matrix, compressed.
  Sparse_matrix matrix(std::size_t n) const
  {
    const Eigen::Index size = Eigen::Index(n);
    Sparse_matrix A(size, size);
    A.setFromTriplets(m_triplets.begin(), m_triplets.end());
    A.makeCompressed();
    return A;
  }

private:
  std::vector<Eigen::Triplet<Complex> > m_triplets;
};

class Pattern_sink
{
public:
  // `A` is compressed; the terms are added to its values, which are set to
  // zero first unless `keep_values`.
  explicit Pattern_sink(Sparse_matrix& A, bool keep_values = false) : m_A(A)
  {
    if(!keep_values)
      m_A.coeffs().setZero();
  }

  template <typename Term>
  void add(const Term& t)
  {
    for(std::size_t i = 0; i < t.variables.size(); ++i)
      for(std::size_t j = 0; j < t.variables.size(); ++j)
      {
        Complex* entry = find_entry(t.variables[i], t.variables[j]);
        if(entry)
          *entry += std::conj(t.alphas[i]) * t.alphas[j];
        else
          m_complete = false;
      }
  }

  // Whether every term fell inside the pattern.
  bool complete() const { return m_complete; }

private:
  Complex* find_entry(std::size_t row, std::size_t column)
  {
    const int* rows = m_A.innerIndexPtr();
    const int* begin = rows + m_A.outerIndexPtr()[column];
    const int* end = rows + m_A.outerIndexPtr()[column + 1];
    const int* it = std::lower_bound(begin, end, int(row));
    return (it != end && std::size_t(*it) == row) ? m_A.valuePtr() + (it - rows) : nullptr;
  }

  Sparse_matrix& m_A;
  bool m_complete = true;
};

class Right_hand_side_sink
{
public:
  explicit Right_hand_side_sink(std::size_t n) : m_r(Dense_vector::Zero(Eigen::Index(n))) {}

  template <typename Term>
  void add(const Term& t)
  {
    for(std::size_t i = 0; i < t.variables.size(); ++i)
      m_r[Eigen::Index(t.variables[i])] -= std::conj(t.alphas[i]) * t.gamma;
  }

  const Dense_vector& vector() const { return m_r; }

private:
  Dense_vector m_r;
};

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_HERMITIAN_ASSEMBLY_H
