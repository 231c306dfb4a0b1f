// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_UNKNOWN_LAYOUT_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_UNKNOWN_LAYOUT_H

// The unknowns of the linear system: which coefficients are free, and how
// every coefficient c_{f,q} (face f, slot q of the active degrees) is an
// affine function of them.
//
// - FIXED faces (a hard full constraint) have no unknown: c_f is the value.
// - PARTIAL faces (a hard partial constraint V_f c_f = b_f) have c_f = p_f + Z_f t_f,
//   Z_f a basis of the null space of V_f: the unknowns are t_f.
// - FREE faces have one unknown per slot, or, when partial constraints couple
//   the degrees, one per slot of their own in a single block.
// - UNCONSTRAINED faces (in a component without constraint or data term) have
//   no unknown: their field is the smoothest unit N-RoSy field, set from outside.
// Without partial constraints the slots are independent blocks that share one
// layout (the same unknowns, degree by degree).
// A component whose constraints are all partial may leave a null space; it is
// marked `regularised`, and the energy adds a tiny multiple of |unknowns|^2.

#include <CGAL/Polyvector_fields/internal/Field_design/constraint_specification.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstddef>
#include <map>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

class Unknown_layout
{
public:
  enum Face_kind { FREE, FIXED, PARTIAL, UNCONSTRAINED };

  // c_{f,q} = constant + sum_{j < size} coefficient[j] * x[first + j]
  struct Affine
  {
    Complex constant = 0;
    int size = 0;
    const Complex* coefficient = nullptr;
    std::size_t first = 0;
  };

  // Lays out the unknowns of the faces of a bundle for `slots` active degrees.
  // `has_data_term[f]`: a data term weighs face f (it then determines its
  // component like a full constraint). Returns false if a partial
  // constraint's null space cannot be computed.
  template <typename Bundle>
  bool build(const Bundle& bundle, std::size_t slots, const Specifications& specifications,
             const std::vector<char>& has_data_term)
  {
    const std::size_t F = bundle.number_of_faces(), C = bundle.number_of_components();
    m_slots = slots;
    m_kind.assign(F, FREE);
    m_partial.clear();
    m_coupled = false;
    std::vector<char> determined(C, 0), touched(C, 0);
    for(const auto& entry : specifications)
    {
      const std::size_t f = entry.first, c = bundle.component(f);
      const Face_specification& s = entry.second;
      touched[c] = 1;
      if(s.full)
      {
        determined[c] = 1;
        if(s.is_hard())
          m_kind[f] = FIXED;
        continue;
      }
      m_coupled = true;
      if(s.is_hard())
      {
        m_kind[f] = PARTIAL;
        if(!null_space_parametrisation(s, m_partial[f]))
          return false;
      }
    }
    for(std::size_t f = 0; f < has_data_term.size(); ++f)
      if(has_data_term[f])
        determined[bundle.component(f)] = touched[bundle.component(f)] = 1;
    m_regularised.assign(F, 0);
    for(std::size_t f = 0; f < F; ++f)
    {
      const std::size_t c = bundle.component(f);
      if(!touched[c])
        m_kind[f] = UNCONSTRAINED;
      m_regularised[f] = touched[c] && !determined[c] && (m_kind[f] == FREE || m_kind[f] == PARTIAL);
    }
    m_first.assign(F, 0);
    m_size = 0;
    for(std::size_t f = 0; f < F; ++f)
    {
      m_first[f] = m_size;
      m_size += number_of_unknowns(f);
    }
    m_unconstrained_values.assign(F, Complex(0));
    set_fixed_values(specifications);
    return true;
  }

  // Takes the values of the hard full constraints: again when only they
  // changed (same faces, see same_matrices()).
  void set_fixed_values(const Specifications& specifications)
  {
    m_fixed_offset.assign(m_kind.size(), 0);
    m_fixed_values.clear();
    for(const auto& entry : specifications)
      if(m_kind[entry.first] == FIXED)
      {
        m_fixed_offset[entry.first] = m_fixed_values.size();
        m_fixed_values.insert(m_fixed_values.end(), entry.second.values.begin(), entry.second.values.end());
      }
  }

  std::size_t number_of_faces() const { return m_kind.size(); }
  Face_kind kind(std::size_t f) const { return m_kind[f]; }
  bool coupled() const { return m_coupled; }
  std::size_t slots() const { return m_slots; }
  // One block of all slots when coupled, one block per slot otherwise.
  std::size_t number_of_blocks() const { return m_coupled ? 1 : m_slots; }
  bool in_block(std::size_t q, std::size_t block) const { return m_coupled || q == block; }
  // The number of unknowns of one block.
  std::size_t size() const { return m_size; }
  std::size_t first_unknown(std::size_t f) const { return m_first[f]; }
  std::size_t number_of_unknowns(std::size_t f) const
  {
    switch(m_kind[f])
    {
      case FREE: return m_coupled ? m_slots : 1;
      case PARTIAL: return std::size_t(m_partial.at(f).Z.cols());
      default: return 0;
    }
  }
  bool regularised(std::size_t f) const { return m_regularised[f] != 0; }

  bool has_unconstrained_faces() const
  {
    for(Face_kind k : m_kind)
      if(k == UNCONSTRAINED)
        return true;
    return false;
  }
  // The degree-0 coefficient of the UNCONSTRAINED faces (their other degrees are 0).
  std::vector<Complex>& unconstrained_values() { return m_unconstrained_values; }

  // c_{f,q} as an affine function of the unknowns; `degree` is the degree of slot q.
  Affine coefficient(std::size_t f, std::size_t q, int degree) const
  {
    static const Complex one(1);
    Affine a;
    switch(m_kind[f])
    {
      case FIXED: a.constant = m_fixed_values[m_fixed_offset[f] + std::size_t(degree)]; break;
      case UNCONSTRAINED: a.constant = (degree == 0) ? m_unconstrained_values[f] : Complex(0); break;
      case FREE:
        a.size = 1;
        a.coefficient = &one;
        a.first = m_first[f] + (m_coupled ? q : 0);
        break;
      case PARTIAL:
      {
        const Partial_basis& basis = m_partial.at(f);
        a.constant = basis.p[Eigen::Index(q)];
        a.size = int(basis.Z.cols());
        a.coefficient = basis.Z.data() + Eigen::Index(q) * basis.Z.cols();  // row q, stored contiguously
        a.first = m_first[f];
        break;
      }
    }
    return a;
  }

private:
  struct Partial_basis
  {
    Eigen::VectorXcd p;                                                         // a particular solution
    Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Z;  // a null-space basis, slots x r
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

  std::size_t m_slots = 0;
  bool m_coupled = false;
  std::vector<Face_kind> m_kind;
  std::vector<std::size_t> m_fixed_offset;  // per face: where its N values start in m_fixed_values
  std::vector<Complex> m_fixed_values;
  std::map<std::size_t, Partial_basis> m_partial;
  std::vector<char> m_regularised;
  std::vector<std::size_t> m_first;
  std::size_t m_size = 0;
  std::vector<Complex> m_unconstrained_values;
};

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_UNKNOWN_LAYOUT_H
