// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_LOCAL_GLOBAL_OPTIMIZER_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_LOCAL_GLOBAL_OPTIMIZER_H

// The local-global iterations of the paper (Section 4) on an N-PolyVector
// field of any degree. From a designed field, alternate
//   a local step, which moves the coefficients of every face that no hard
//     full constraint fixes to those of the closest field that satisfies the
//     face's condition (an angle bound, conjugacy, ...), and
//   a global step, which finds the smoothest field close to the local one:
//     E_smooth + lambda sum_f s_f |c_f - chat_f|^2 + sum_f sum_m w_m |c_{f,m}|^2
//     (Eq. 12, 16, 17), with the hard constraints of the design held,
// until the measure of the algorithm says the field has converged. An
// algorithm is its local step, its face scales s_f, its penalties w_m and its
// measure; the rest is here.
//
// Every global step is one Coefficient_system on the degrees that the field's
// symmetry admits: its pattern never changes, so it is analysed once, and
// each step with a new lambda only refactors numerically.
//
// The planarization of quad meshes alternates local projections and a global
// least-squares step too, but on the vertex positions of another mesh, with a
// real system: it shares the schedule, not this class.

#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/Smoothness_weights.h>
#include <CGAL/Polyvector_fields/internal/Field_design/Coefficient_system.h>
#include <CGAL/Polyvector_fields/internal/Field_design/constraint_specification.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The schedule of the iterations, common to all algorithms.
struct Local_global_parameters
{
  double initial_lambda = 100;
  double lambda_factor = 1.5;
  double maximum_lambda = 0;  // lambda stops growing there (read_local_global_parameters() sets it)
  std::size_t maximum_iterations = 0;
  bool verbose = false;
};

template <typename NamedParameters>
Error_code read_local_global_parameters(const NamedParameters& np, std::size_t default_iterations,
                                        double default_maximum_lambda, Local_global_parameters& p)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  p.initial_lambda = choose_parameter(get_parameter(np, internal_np::initial_lambda), 100.0);
  p.lambda_factor = choose_parameter(get_parameter(np, internal_np::lambda_factor), 1.5);
  p.maximum_lambda = choose_parameter(get_parameter(np, internal_np::maximum_lambda), default_maximum_lambda);
  p.maximum_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), default_iterations);
  p.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  if(!std::isfinite(p.initial_lambda) || !std::isfinite(p.lambda_factor) || std::isnan(p.maximum_lambda))
    return Error_code::NON_FINITE_VALUE;
  if(!(p.initial_lambda > 0) || !(p.lambda_factor >= 1) || !(p.maximum_lambda >= p.initial_lambda))
    return Error_code::INVALID_PARAMETER;
  return Error_code::SUCCESS;
}

// The data term of an algorithm: the weight s_f of each face (scaled by
// lambda) and a penalty w_m on each coefficient degree m (0 for none), which
// pulls c_m towards 0 (the orthogonality term of Eq. 17 is w_2 on c_2).
struct Local_global_weights
{
  std::vector<double> face_scale;  // s_f, one per face
  std::vector<double> degree_penalty;  // w_m, one per degree 0 .. N-1
};

template <typename Bundle, typename SolverTraits>
class Local_global_optimizer
{
public:
  typedef Polyvector_field<Bundle> Field;

  // The iterations on `field`, holding the constraints it was designed with.
  Local_global_optimizer(const Field& field, const SolverTraits& solver, bool parallel,
                         std::vector<double> edge_weights)
    : m_bundle(field.tangent_bundle()), m_N(field.degree()),
      m_system(field.tangent_bundle(), field.degree(), admissible_degrees(field.degree(), field.is_sign_symmetric()),
               solver, parallel, std::move(edge_weights)),
      m_parallel(parallel)
  {
    m_system.specifications() = field.constraint_specifications();
    m_fixed.assign(m_bundle.number_of_faces(), 0);
    for(const auto& entry : field.constraint_specifications())
      if(entry.second.full && entry.second.is_hard())
        m_fixed[entry.first] = 1;
    m_system.set_length_exponent(length_exponent(field.constraint_specifications()));
  }

  // Faces whose coefficients a hard full constraint fixes.
  bool is_fixed(std::size_t f) const { return m_fixed[f] != 0; }

  // The iterations from `c` (N coefficients per face), in place.
  // `local_step(f, c_f, target_f)` writes the N target coefficients of free
  // face f from its current ones; `converged(c, iterations, lambda)`
  // measures the field after the global step of weight lambda (0 for the
  // field given), and may report it. Lambda grows by lambda_factor up to
  // maximum_lambda; at the cap the factorization is reused. Returns
  // SOLVER_FAILURE if a global step fails; `converged_at_end` says whether
  // the measure was met.
  template <typename LocalStep, typename Converged>
  Error_code iterate(const Local_global_weights& weights, const Local_global_parameters& p,
                     const LocalStep& local_step, const Converged& converged, std::vector<Complex>& c,
                     std::size_t& iterations, bool& converged_at_end)
  {
    const std::size_t F = m_bundle.number_of_faces();
    std::vector<Complex> targets(m_N * F);
    double lambda = p.initial_lambda, factored_lambda = 0;
    iterations = 0;
    converged_at_end = converged(c, iterations, factored_lambda);
    while(!converged_at_end && iterations < p.maximum_iterations)
    {
      // Faces are independent: in parallel when allowed (the same result).
      for_each_range(m_parallel, F, 4096, [&](std::size_t begin, std::size_t end) {
        for(std::size_t f = begin; f < end; ++f)
        {
          if(is_fixed(f))
            std::copy(&c[m_N * f], &c[m_N * f] + m_N, &targets[m_N * f]);
          else
            local_step(f, &c[m_N * f], &targets[m_N * f]);
        }
      });
      set_data_term(lambda, weights, targets);
      // At the cap the matrix does not change: only the targets, hence only
      // the right-hand side, are new, and the factorization is reused.
      if(iterations == 0 || lambda != factored_lambda)
      {
        if(!(iterations == 0 ? m_system.factor() : m_system.refactor()))
          return Error_code::SOLVER_FAILURE;
        ++m_factorizations;
        factored_lambda = lambda;
      }
      if(!m_system.solve(c))
        return Error_code::SOLVER_FAILURE;
      ++iterations;
      lambda = (std::min)(lambda * p.lambda_factor, p.maximum_lambda);
      converged_at_end = converged(c, iterations, factored_lambda);
    }
    return Error_code::SUCCESS;
  }

  // Numerical factorizations of the global steps so far.
  std::size_t factorizations() const { return m_factorizations; }

  const Stage_times& times() const { return m_system.times(); }

private:
  // data |c - chat|^2 + penalty |c_m|^2 = w |c - data chat / w|^2 + constant,
  // with data = lambda s_f and w = data + penalty_m.
  void set_data_term(double lambda, const Local_global_weights& weights, const std::vector<Complex>& targets)
  {
    const std::size_t F = m_bundle.number_of_faces();
    const std::vector<int>& degrees = m_system.degrees();
    Data_term& data = m_system.data_term();
    data.weight.assign(degrees.size(), std::vector<double>(F, 0));
    data.target.assign(degrees.size(), std::vector<Complex>(F, Complex(0)));
    for(std::size_t f = 0; f < F; ++f)
      for(std::size_t q = 0; q < degrees.size(); ++q)
      {
        const std::size_t m = std::size_t(degrees[q]);
        const double d = lambda * weights.face_scale[f], w = d + weights.degree_penalty[m];
        data.weight[q][f] = w;
        data.target[q][f] = (w > 0) ? targets[f * m_N + m] * (d / w) : Complex(0);
      }
  }

  const Bundle& m_bundle;
  std::size_t m_N;
  Coefficient_system<Bundle, SolverTraits> m_system;
  std::vector<char> m_fixed;
  bool m_parallel;
  std::size_t m_factorizations = 0;  // of the global steps
};

// The optimizer of an algorithm called with `np` on `field`: the solver of
// the named parameter `sparse_linear_solver` (default `Default_sparse_solver`),
// in parallel when `ConcurrencyTag` is `Parallel_tag`, with the edge weights
// of the named parameter `smoothness_weights` (default: those the field was
// designed with).
template <typename ConcurrencyTag, typename Bundle, typename NamedParameters>
auto make_local_global_optimizer(const Polyvector_field<Bundle>& field, const NamedParameters& np)
{
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::sparse_linear_solver_t, NamedParameters,
                                                             Default_sparse_solver>::type Solver;
  const Smoothness_weights weights = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np::smoothness_weights), field.smoothness_weights());
  return Local_global_optimizer<Bundle, Solver>(
    field,
    CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::sparse_linear_solver),
                                       Solver()),
    std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value, smoothness_edge_weights(field.tangent_bundle(), weights));
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_LOCAL_GLOBAL_OPTIMIZER_H
