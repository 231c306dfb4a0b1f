// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_SMOOTHEST_ROSY_FIELD_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_SMOOTHEST_ROSY_FIELD_H

// The field of a connected component without any constraint: the smoothest
// unit-length N-RoSy field, i.e. the eigenvector of the smallest eigenvalue of
// the component's degree-0 connection Laplacian, scaled so that the mean of
// |c_0|^2 over the component is 1 (unit-length vectors). Computed by inverse
// iteration on the Laplacian shifted by a tiny multiple of the identity (so
// that a flat component, whose smallest eigenvalue is 0, can be factored).

#include <CGAL/Polyvector_fields/Sparse_factorization.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <Eigen/Sparse>

#include <cmath>
#include <complex>
#include <cstddef>
#include <map>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// `faces` (indices of the bundle) are the faces of the components without
// constraint; c0[f] receives the field of each. Returns false if the
// factorization or a solve fails.
template <typename Bundle, typename SolverTraits>
bool smoothest_rosy_fields(const Bundle& bundle, std::size_t N, const std::vector<std::size_t>& faces,
                           const SolverTraits& solver_prototype, std::vector<Complex>& c0)
{
  const std::size_t F = bundle.number_of_faces();
  std::vector<std::size_t> local(F, std::size_t(-1));
  for(std::size_t i = 0; i < faces.size(); ++i)
    local[faces[i]] = i;
  const Eigen::Index n = Eigen::Index(faces.size());
  std::vector<Eigen::Triplet<Complex> > triplets;
  for(const auto& e : bundle.interior_edges())
  {
    if(local[e.f] == std::size_t(-1))
      continue;
    const Complex a = std::pow(std::conj(e.e_f), int(N)), b = -std::pow(std::conj(e.e_g), int(N));
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
  typedef Sparse_factorization<SolverTraits, Complex> Factorization;
  Factorization factorization(solver_prototype);
  typename Factorization::Solver_scope scope;
  if(!factorization.analyze(A) || !factorization.factorize(A))
    return false;

  // Components are decoupled in A, so one inverse iteration serves them all
  // as long as each component is normalised on its own: unit mean |c_0|^2,
  // and the phase that best aligns with the previous iterate, so that the
  // iteration converges.
  auto normalise = [&](Dense_vector& v, const Dense_vector& reference) {
    std::map<std::size_t, double> norm2;
    std::map<std::size_t, std::size_t> count;
    std::map<std::size_t, Complex> alignment;
    for(Eigen::Index i = 0; i < n; ++i)
    {
      const std::size_t c = bundle.component(faces[std::size_t(i)]);
      norm2[c] += std::norm(v[i]);
      count[c] += 1;
      alignment[c] += std::conj(reference[i]) * v[i];
    }
    for(Eigen::Index i = 0; i < n; ++i)
    {
      const std::size_t c = bundle.component(faces[std::size_t(i)]);
      const Complex a = alignment[c];
      const Complex phase = std::abs(a) > 0 ? std::conj(a) / std::abs(a) : Complex(1);
      v[i] *= phase / std::sqrt(norm2[c] / double(count[c]));
    }
  };
  Dense_vector x = Dense_vector::Ones(n), y;
  typename Factorization::Dense_matrix solution;
  normalise(x, x);
  for(int iteration = 0; iteration < 1000; ++iteration)
  {
    if(!factorization.solve(x, solution))
      return false;
    y = solution.col(0);
    normalise(y, x);
    const double change = (y - x).norm() / std::sqrt(double(n));
    x.swap(y);
    if(change < 1e-12)
      break;
  }
  for(Eigen::Index i = 0; i < n; ++i)
    c0[faces[std::size_t(i)]] = x[i];
  return x.allFinite();
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_SMOOTHEST_ROSY_FIELD_H
