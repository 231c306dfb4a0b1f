// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_LOCAL_GLOBAL_DRIVER_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_LOCAL_GLOBAL_DRIVER_H

// The local-global iterations of the frame-field algorithms (paper Section 4):
// from the smoothest frame field of the constraints, alternate
//   a local step, which moves the frame {±u, ±v} of every face that no hard
//     full constraint fixes to the closest frame that satisfies the face's
//     condition (an angle bound, conjugacy), and
//   a global step, which finds the smoothest field close to the local one:
//     E_smooth + lambda sum_f s_f |c_f - chat_f|^2 + w sum_f |c_{f,2}|^2
//     (Eq. 12, 16, 17), for c_0 and c_2, with the hard constraints held,
// until the measure of the algorithm says the field has converged. An
// algorithm is its local step and its measure; the rest is here.
//
// The smooth field and every global step are one Coefficient_system on the
// degrees {0, 2}: its pattern never changes, so it is analysed once, and each
// global step (a new lambda) only refactors numerically.

#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Smoothness_weights.h>
#include <CGAL/Polyvector_fields/internal/Field_design/Coefficient_system.h>
#include <CGAL/Polyvector_fields/internal/Field_design/constraint_specification.h>
#include <CGAL/Polyvector_fields/internal/field_access.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/frame_field_polynomial.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/blocked_range.h>
#  include <tbb/parallel_for.h>
#endif

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

// The schedule of the iterations, common to both algorithms.
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

template <typename Bundle, typename SolverTraits>
class Local_global_driver
{
public:
  Local_global_driver(const Bundle& bundle, const SolverTraits& solver, bool parallel,
                      std::vector<double> edge_weights = std::vector<double>())
    : m_bundle(bundle), m_system(bundle, 4, { 0, 2 }, solver, parallel, std::move(edge_weights)), m_parallel(parallel)
  {}

  // The smoothest frame field of `constraints` (each vector u stands for
  // {u, -u}), into `c` (4 coefficients per face).
  template <typename ConstraintRange>
  Error_code smooth_field(const ConstraintRange& constraints, std::vector<Complex>& c)
  {
    if(m_bundle.status() != Error_code::SUCCESS)
      return m_bundle.status();
    Specifications& specifications = m_system.specifications();
    for(const auto& constraint : constraints)
    {
      if(!m_bundle.contains(constraint.face))
        return Error_code::INVALID_FACE;
      const std::size_t f = m_bundle.index(constraint.face);
      if(specifications.count(f))
        return Error_code::DUPLICATE_CONSTRAINT;
      Face_specification s;
      const Error_code code = make_face_specification(m_bundle.frame(f), constraint.vectors, constraint.weight, 4, true, s);
      if(code != Error_code::SUCCESS)
        return code;
      specifications.emplace(f, std::move(s));
    }
    m_fixed.assign(m_bundle.number_of_faces(), 0);
    for(const auto& entry : specifications)
      if(entry.second.full && entry.second.is_hard())
        m_fixed[entry.first] = 1;
    const int k = length_exponent(specifications);
    if(!lengths_in_range(specifications, k, 4))
      return Error_code::VALUE_OUT_OF_RANGE;
    m_system.set_length_exponent(k);
    if(!m_system.factor() || !m_system.solve(c))
      return Error_code::SOLVER_FAILURE;
    return Error_code::SUCCESS;
  }

  // Faces whose frame a hard full constraint fixes.
  bool is_fixed(std::size_t f) const { return m_fixed[f] != 0; }

  // The iterations from `c` (the smooth field). `scale[f]` is s_f;
  // `local_step(f, u, v)` returns the frame of free face f after the local
  // step; `converged(c, iterations, lambda)` measures the field after the
  // global step of weight lambda (0 for the smooth field), and may report
  // it. Lambda grows by lambda_factor up to maximum_lambda; at the cap the
  // factorization is reused. Returns SOLVER_FAILURE if a global step fails.
  template <typename LocalStep, typename Converged>
  Error_code iterate(const std::vector<double>& scale, double orthogonality, const Local_global_parameters& p,
                     const LocalStep& local_step, const Converged& converged, std::vector<Complex>& c,
                     std::size_t& iterations)
  {
    const std::size_t F = m_bundle.number_of_faces();
    std::vector<Complex> targets(4 * F);
    double lambda = p.initial_lambda, factored_lambda = 0;
    iterations = 0;
    while(!converged(c, iterations, factored_lambda) && iterations < p.maximum_iterations)
    {
      // Faces are independent: in parallel when allowed (the same result).
      for_each_face_range(F, [&](std::size_t begin, std::size_t end) {
        for(std::size_t f = begin; f < end; ++f)
        {
          const auto uv = frame_vectors(&c[4 * f]);
          const auto moved = is_fixed(f) ? uv : local_step(f, uv.first, uv.second);
          frame_coefficients(moved.first, moved.second, &targets[4 * f]);
        }
      });
      set_data_term(lambda, scale, orthogonality, targets);
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
    }
    return Error_code::SUCCESS;
  }

  // The whole algorithm: the smooth field of `constraints`, the iterations
  // (counted in `report.iterations`), then the field into `coefficient_map`
  // and `report` into `result`, both written only on success.
  template <typename ConstraintRange, typename LocalStep, typename Converged, typename CoefficientMap,
            typename Report>
  Error_code design(const ConstraintRange& constraints, const std::vector<double>& scale, double orthogonality,
                    const Local_global_parameters& p, const LocalStep& local_step, const Converged& converged,
                    CoefficientMap coefficient_map, Report& report, Report& result)
  {
    std::vector<Complex> c;
    Error_code code = smooth_field(constraints, c);
    if(code == Error_code::SUCCESS)
      code = iterate(scale, orthogonality, p, local_step, converged, c, report.iterations);
    if(code != Error_code::SUCCESS)
      return code;
    report.factorizations = m_factorizations;
    write_coefficients(m_bundle, 4, c, coefficient_map);
    result = report;
    return Error_code::SUCCESS;
  }

  const Stage_times& times() const { return m_system.times(); }

private:
  // Runs task(begin, end) on ranges that cover 0 .. n-1.
  template <typename Task>
  void for_each_face_range(std::size_t n, const Task& task) const
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(m_parallel)
    {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
                        [&](const tbb::blocked_range<std::size_t>& r) { task(r.begin(), r.end()); });
      return;
    }
#endif
    task(std::size_t(0), n);
  }

  // data |c - chat|^2 + orthogonality |c_2|^2 = w |c - data chat / w|^2 + constant,
  // with data = lambda s_f and w = data (+ orthogonality for c_2).
  void set_data_term(double lambda, const std::vector<double>& scale, double orthogonality,
                     const std::vector<Complex>& targets)
  {
    const std::size_t F = m_bundle.number_of_faces();
    Data_term& data = m_system.data_term();
    data.weight.assign(2, std::vector<double>(F, 0));
    data.target.assign(2, std::vector<Complex>(F, Complex(0)));
    for(std::size_t f = 0; f < F; ++f)
      for(std::size_t q = 0; q < 2; ++q)
      {
        const double d = lambda * scale[f], w = d + (q == 1 ? orthogonality : 0);
        data.weight[q][f] = w;
        data.target[q][f] = (w > 0) ? targets[f * 4 + 2 * q] * (d / w) : Complex(0);
      }
  }

  const Bundle& m_bundle;
  Coefficient_system<Bundle, SolverTraits> m_system;
  std::vector<char> m_fixed;
  bool m_parallel;
  std::size_t m_factorizations = 0;  // of the global steps
};

// The driver of an algorithm called with `np`: the solver of the named
// parameter `sparse_linear_solver` (default `Default_sparse_solver`), in
// parallel when `ConcurrencyTag` is `Parallel_tag`, with the edge weights of
// the named parameter `smoothness_weights`.
template <typename ConcurrencyTag, typename Bundle, typename NamedParameters>
auto make_local_global_driver(const Bundle& bundle, const NamedParameters& np)
{
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::sparse_linear_solver_t, NamedParameters,
                                                             Default_sparse_solver>::type Solver;
  return Local_global_driver<Bundle, Solver>(
    bundle, CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::sparse_linear_solver),
                                               Solver()),
    std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
    smoothness_edge_weights(bundle, read_smoothness_weights(np)));
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FRAME_FIELDS_LOCAL_GLOBAL_DRIVER_H
