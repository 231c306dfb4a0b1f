// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELD_ITERATIONS_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELD_ITERATIONS_H

// The global step shared by the local-global frame-field algorithms
// (paper Section 4, Eq. 12, 16, 17): for frame fields {±u, ±v} the unknowns
// are c_0 = u^2 v^2 and c_2 = -(u^2 + v^2) (N = 4, sign-symmetric), and the
// global step minimises
//
//   E_smooth + lambda * sum_f s_f |c_f - chat_f|^2 + w sum_f |c_{f,2}|^2
//
// with the hard constraints of the designer still held. s_f is 1 for the
// angle bound and the normalised |K| for conjugacy; w is the orthogonality
// weight. The matrix pattern never changes: the first step analyses and
// factors, later steps (new lambda) only refactor numerically.

#include <CGAL/Polyvector_fields/internal/Coefficient_system.h>
#include <CGAL/Polyvector_fields/polyvector_polynomial.h>

#include <complex>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// u = first root, v = second root in counterclockwise order: {u, v, -u, -v}.
inline std::pair<Complex, Complex> frame_vectors(const Complex* c)
{
  Complex roots[4];
  polyvector_roots(c, 4, roots, true);
  return { roots[0], roots[1] };
}

// Coefficients (c_0, c_1, c_2, c_3) of (z^2 - u^2)(z^2 - v^2).
inline void frame_coefficients(const Complex& u, const Complex& v, Complex* c)
{
  const Complex u2 = u * u, v2 = v * v;
  c[0] = u2 * v2;
  c[1] = 0;
  c[2] = -(u2 + v2);
  c[3] = 0;
}

template <typename Connection, typename SolverTraits>
class Frame_field_iterations
{
public:
  Frame_field_iterations(const Connection& connection,
                         const std::map<std::size_t, Face_specification>& specifications,
                         const SolverTraits& solver_prototype,
                         std::vector<double> data_scale,
                         double orthogonality_weight,
                         bool parallel = false)
    : m_system(connection, 4, { 0, 2 }, solver_prototype, parallel),
      m_scale(std::move(data_scale)),
      m_orthogonality(orthogonality_weight)
  {
    m_system.specifications() = specifications;
    m_fixed.assign(connection.number_of_faces(), 0);
    for(const auto& entry : specifications)
      if(entry.second.full && entry.second.is_hard())
        m_fixed[entry.first] = 1;
  }

  // Faces whose PolyVector a hard full constraint fixes.
  bool is_fixed(std::size_t f) const { return m_fixed[f] != 0; }

  // One global step towards the targets (N = 4 coefficients per face).
  bool global_step(double lambda, const std::vector<Complex>& targets, std::vector<Complex>& coefficients)
  {
    const std::size_t F = m_fixed.size();
    auto& weights = m_system.data_weights();
    auto& goals = m_system.data_targets();
    weights.assign(2, std::vector<double>(F, 0));
    goals.assign(2, std::vector<Complex>(F, Complex(0)));
    for(std::size_t f = 0; f < F; ++f)
      for(std::size_t q = 0; q < 2; ++q)
      {
        const double data = lambda * m_scale[f];
        const double w = data + (q == 1 ? m_orthogonality : 0);
        weights[q][f] = w;
        // data |c - chat|^2 + orth |c|^2 = w |c - data chat / w|^2 + constant
        goals[q][f] = (w > 0) ? targets[f * 4 + 2 * q] * (data / w) : Complex(0);
      }
    const bool factored = m_analysed ? m_system.refactor_numeric() : m_system.factor();
    m_analysed = true;
    if(!factored)
      return false;
    return m_system.solve(coefficients);
  }

  const Stage_times& times() const { return m_system.times(); }

private:
  Coefficient_system<Connection, SolverTraits> m_system;
  std::vector<double> m_scale;
  double m_orthogonality;
  std::vector<char> m_fixed;
  bool m_analysed = false;
};

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELD_ITERATIONS_H
