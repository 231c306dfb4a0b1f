// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_QUADRATIC_ENERGY_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_QUADRATIC_ENERGY_H

// The energy in the PolyVector coefficients, as a sum of terms
// |sum_j alpha_j x_j + gamma|^2 in the unknowns x of an Unknown_layout:
//
//   sum_{interior edges (f,g)} w_e sum_q | c_{f,q} conj(e_f)^(N-m_q) - c_{g,q} conj(e_g)^(N-m_q) |^2   (smoothness)
// + sum_{soft full constraints}    w_f sum_q |c_{f,q} - c^0_{f,q}|^2
// + sum_{soft partial constraints} w_f sum_rows |V_f c_f - b_f|^2
// + sum_{f,q} W_{f,q} |c_{f,q} - t_{f,q}|^2        (a data term: targets t with weights W)
// + epsilon |x|^2 on the unknowns of regularised components
//
// where m_q is the degree of slot q and w_e the weight of edge e (1: the
// paper's uniform weights). The transport power is N - m: a frame change by a
// unit complex number r turns the roots by r and c_m by r^(N-m) (user manual,
// "Transport"). enumerate_terms() hands every term of one block to a sink
// (internal/Hermitian_assembly.h), which accumulates it into the normal
// equations.

#include <CGAL/Polyvector_fields/internal/Field_design/Unknown_layout.h>
#include <CGAL/Polyvector_fields/internal/Field_design/constraint_specification.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <cmath>
#include <complex>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// A data term W_{f,q} |c_{f,q} - t_{f,q}|^2: weight[q][f] and target[q][f] per
// slot and face; an empty slot has no term.
struct Data_term
{
  std::vector<std::vector<double> > weight;
  std::vector<std::vector<Complex> > target;

  bool empty() const
  {
    for(const auto& w : weight)
      if(!w.empty())
        return false;
    return true;
  }
  // Whether face f has a positive weight in some slot.
  std::vector<char> weighted_faces(std::size_t F) const
  {
    std::vector<char> weighted(F, 0);
    for(const auto& w : weight)
      for(std::size_t f = 0; f < w.size(); ++f)
        weighted[f] = weighted[f] || w[f] > 0;
    return weighted;
  }
};

// The energy's fixed parts: degrees, transport powers of every interior edge,
// edge weights, and the regularisation.
class Quadratic_energy
{
public:
  static constexpr double regularisation = 1e-10;

  template <typename Bundle>
  Quadratic_energy(const Bundle& bundle, std::size_t N, const std::vector<int>& degrees,
                   std::vector<double> edge_weights = std::vector<double>())
    : m_degrees(degrees), m_edge_weights(std::move(edge_weights))
  {
    const auto& edges = bundle.interior_edges();
    m_edges.reserve(edges.size());
    for(const auto& e : edges)
      m_edges.push_back({ e.f, e.g });
    m_transport.resize(degrees.size());
    for(std::size_t q = 0; q < degrees.size(); ++q)
    {
      const int power = int(N) - degrees[q];
      m_transport[q].reserve(edges.size());
      for(const auto& e : edges)
        m_transport[q].push_back({ std::pow(std::conj(e.e_f), power), std::pow(std::conj(e.e_g), power) });
    }
  }

  const std::vector<int>& degrees() const { return m_degrees; }

  // Which terms enumerate_terms() hands on: all of them, or the data term
  // alone (the only one that the global steps of the frame-field iterations
  // change), or all but the data term.
  enum Terms { ALL_TERMS, DATA_TERM, ALL_BUT_DATA_TERM };

  // Hands every term of `block` (among `which`) to sink.add(term) (see Term).
  template <typename Sink>
  void enumerate_terms(const Unknown_layout& layout, const Specifications& specifications, const Data_term& data,
                       std::size_t block, Sink& sink, Terms which = ALL_TERMS) const
  {
    const std::size_t slots = m_degrees.size();
    Term term;
    if(which != DATA_TERM)
      enumerate_fixed_terms(layout, specifications, block, sink, term);
    if(which == ALL_BUT_DATA_TERM)
      return;
    // Data term.
    for(std::size_t q = 0; q < slots && q < data.weight.size(); ++q)
    {
      if(!layout.in_block(q, block))
        continue;
      for(std::size_t f = 0; f < data.weight[q].size(); ++f)
      {
        const double w = data.weight[q][f];
        if(!(w > 0) || layout.kind(f) == Unknown_layout::FIXED)
          continue;
        const double root_weight = std::sqrt(w);
        term.clear(-root_weight * (data.target[q].empty() ? Complex(0) : data.target[q][f]));
        term.append(layout.coefficient(f, q, m_degrees[q]), root_weight);
        sink.add(term);
      }
    }
  }

  // One term |sum_j alphas[j] x[variables[j]] + gamma|^2.
  struct Term
  {
    std::vector<std::size_t> variables;
    std::vector<Complex> alphas;
    Complex gamma = 0;

    void clear(const Complex& constant = Complex(0))
    {
      variables.clear();
      alphas.clear();
      gamma = constant;
    }
    // Adds scale * c, c an affine function of the unknowns.
    void append(const Unknown_layout::Affine& c, const Complex& scale)
    {
      gamma += scale * c.constant;
      for(int j = 0; j < c.size; ++j)
      {
        variables.push_back(c.first + std::size_t(j));
        alphas.push_back(scale * c.coefficient[j]);
      }
    }
  };

private:
  // The smoothness, soft-constraint and regularisation terms.
  template <typename Sink>
  void enumerate_fixed_terms(const Unknown_layout& layout, const Specifications& specifications, std::size_t block,
                             Sink& sink, Term& term) const
  {
    const std::size_t slots = m_degrees.size();
    // Smoothness.
    for(std::size_t e = 0; e < m_edges.size(); ++e)
    {
      const std::size_t f = m_edges[e].first, g = m_edges[e].second;
      if(layout.kind(f) == Unknown_layout::UNCONSTRAINED ||
         (layout.kind(f) == Unknown_layout::FIXED && layout.kind(g) == Unknown_layout::FIXED))
        continue;  // no unknown (UNCONSTRAINED: then g is in the same component)
      const double root_weight = m_edge_weights.empty() ? 1.0 : std::sqrt(m_edge_weights[e]);
      for(std::size_t q = 0; q < slots; ++q)
        if(layout.in_block(q, block))
        {
          term.clear();
          term.append(layout.coefficient(f, q, m_degrees[q]), root_weight * m_transport[q][e].first);
          term.append(layout.coefficient(g, q, m_degrees[q]), -root_weight * m_transport[q][e].second);
          sink.add(term);
        }
    }
    // Soft constraints.
    for(const auto& entry : specifications)
    {
      const std::size_t f = entry.first;
      const Face_specification& s = entry.second;
      if(s.is_hard())
        continue;
      const double root_weight = std::sqrt(s.weight);
      if(s.full)
      {
        for(std::size_t q = 0; q < slots; ++q)
          if(layout.in_block(q, block))
          {
            term.clear(-root_weight * s.values[std::size_t(m_degrees[q])]);
            term.append(layout.coefficient(f, q, m_degrees[q]), root_weight);
            sink.add(term);
          }
        continue;
      }
      for(Eigen::Index row = 0; row < s.rows.rows(); ++row)
      {
        term.clear(-root_weight * s.rhs[row]);
        for(std::size_t q = 0; q < slots; ++q)
          term.append(layout.coefficient(f, q, m_degrees[q]), root_weight * s.rows(row, Eigen::Index(q)));
        sink.add(term);
      }
    }
    // Regularisation of components fixed only by partial constraints.
    const double root_epsilon = std::sqrt(regularisation);
    for(std::size_t f = 0; f < layout.number_of_faces(); ++f)
    {
      if(!layout.regularised(f))
        continue;
      for(std::size_t j = 0; j < layout.number_of_unknowns(f); ++j)
      {
        term.clear();
        term.variables.push_back(layout.first_unknown(f) + j);
        term.alphas.push_back(root_epsilon);
        sink.add(term);
      }
    }
  }

  std::vector<int> m_degrees;
  std::vector<std::pair<std::size_t, std::size_t> > m_edges;                    // (f, g) per interior edge
  std::vector<std::vector<std::pair<Complex, Complex> > > m_transport;          // per slot, per edge: conj(e_f)^(N-m), conj(e_g)^(N-m)
  std::vector<double> m_edge_weights;                                           // per edge; empty: 1
};

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_QUADRATIC_ENERGY_H
