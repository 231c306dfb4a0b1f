// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// The frame-field algorithms of paper Section 4, run to convergence:
// - the conjugate frame field on inspired_mesh.obj (4288 faces) with its 84
//   bundled constraints (including the curvature estimation it starts with);
// - its cost per global step on inspired_mesh.obj after two Loop subdivisions
//   (68,608 faces, 1% random constraints): (time of 6 steps - time of 1 step) / 5;
// - the angle-bounded frame field (70 degrees) on bumpy.off with 1% random
//   general-frame constraints.
// Each with every available sparse solver.

#include "pvf_benchmark_common.h"

#include <CGAL/Polyvector_fields/Cholmod_solver.h>
#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/angle_bounded_frame_field.h>
#include <CGAL/Polyvector_fields/conjugate_frame_field.h>

#include <benchmark/benchmark.h>

namespace {

using namespace pvf_bench;

const std::vector<Constraint>& inspired_constraints()
{
  static std::vector<Constraint> constraints;
  static bool read = false;
  if(!read)
  {
    const std::string data(PVF_DATA_DIR);
    if(PVF::IO::read_dmat_constraints(data + "/inspired_mesh_b.dmat", data + "/inspired_mesh_bc.dmat",
                                      subdivided_mesh("inspired_mesh.obj", 0), constraints) != PVF::Error_code::SUCCESS)
    {
      std::cerr << "cannot read the inspired_mesh constraints\n";
      std::exit(EXIT_FAILURE);
    }
    read = true;
  }
  return constraints;
}

template <typename Solver>
void BM_conjugate_inspired(benchmark::State& state)
{
  const Mesh& tm = subdivided_mesh("inspired_mesh.obj", 0);
  const std::vector<Constraint>& constraints = inspired_constraints();
  PVF::Conjugate_field_result result;
  for(auto _ : state)
  {
    auto coefficients = boost::dummy_property_map();
    if(PVF::design_conjugate_frame_field(tm, constraints, coefficients, result,
                                         CGAL::parameters::sparse_linear_solver(Solver())) != PVF::Error_code::SUCCESS)
    {
      state.SkipWithError("design_conjugate_frame_field failed");
      return;
    }
  }
  state.counters["faces"] = double(tm.number_of_faces());
  state.counters["constraints"] = double(constraints.size());
  state.counters["iterations"] = double(result.iterations);
  state.counters["converged"] = result.converged ? 1 : 0;
  state.counters["residual"] = result.free_residual;
}
BENCHMARK_TEMPLATE(BM_conjugate_inspired, PVF::Simplicial_ldlt_solver)
  ->Name("BM_conjugate_inspired/SimplicialLDLT")->Unit(benchmark::kMillisecond)->UseRealTime();
#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
BENCHMARK_TEMPLATE(BM_conjugate_inspired, PVF::Cholmod_sparse_solver)
  ->Name("BM_conjugate_inspired/CHOLMOD")->Unit(benchmark::kMillisecond)->UseRealTime();
#endif

// Per-iteration cost of the conjugate field at subdivision level range(0) of
// inspired_mesh.obj (the convergence test is disabled by a zero-like tolerance).
template <typename Solver>
void BM_conjugate_per_iteration(benchmark::State& state)
{
  const Mesh& tm = subdivided_mesh("inspired_mesh.obj", int(state.range(0)));
  const std::vector<Constraint> constraints = random_frame_constraints(tm);
  auto run = [&](std::size_t steps) {
    PVF::Conjugate_field_result result;
    auto coefficients = boost::dummy_property_map();
    const auto start = std::chrono::steady_clock::now();
    const PVF::Error_code code = PVF::design_conjugate_frame_field(
      tm, constraints, coefficients, result,
      PVF::parameters::tolerance(1e-300, CGAL::parameters::sparse_linear_solver(Solver()).number_of_iterations(steps)));
    if(code != PVF::Error_code::SUCCESS || result.iterations != steps)
      return -1.0;
    return seconds_since(start);
  };
  double one = 0, six = 0;
  for(auto _ : state)
  {
    one = run(1);
    six = run(6);
    if(one < 0 || six < 0)
    {
      state.SkipWithError("design_conjugate_frame_field failed");
      return;
    }
  }
  state.counters["faces"] = double(tm.number_of_faces());
  state.counters["first_step_total_s"] = one;
  state.counters["per_iteration_s"] = (six - one) / 5;
}
BENCHMARK_TEMPLATE(BM_conjugate_per_iteration, PVF::Simplicial_ldlt_solver)
  ->Name("BM_conjugate_per_iteration/SimplicialLDLT")->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
BENCHMARK_TEMPLATE(BM_conjugate_per_iteration, PVF::Cholmod_sparse_solver)
  ->Name("BM_conjugate_per_iteration/CHOLMOD")->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
#endif

template <typename Solver>
void BM_angle_bound_bumpy(benchmark::State& state)
{
  const Mesh& tm = bumpy(int(state.range(0)));
  const std::vector<Constraint> constraints = random_frame_constraints(tm);
  PVF::Angle_bound_result result;
  for(auto _ : state)
  {
    auto coefficients = boost::dummy_property_map();
    if(PVF::design_angle_bounded_frame_field(tm, constraints, coefficients, result,
                                             PVF::parameters::angle_bound(70.0 * CGAL_PI / 180.0,
                                                                          CGAL::parameters::sparse_linear_solver(Solver()))) !=
       PVF::Error_code::SUCCESS)
    {
      state.SkipWithError("design_angle_bounded_frame_field failed");
      return;
    }
  }
  state.counters["faces"] = double(tm.number_of_faces());
  state.counters["constraints"] = double(constraints.size());
  state.counters["iterations"] = double(result.iterations);
  state.counters["converged"] = result.converged ? 1 : 0;
  state.counters["min_free_angle_deg"] = result.minimum_free_angle * 180.0 / CGAL_PI;
}
BENCHMARK_TEMPLATE(BM_angle_bound_bumpy, PVF::Simplicial_ldlt_solver)
  ->Name("BM_angle_bound_bumpy/SimplicialLDLT")->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
BENCHMARK_TEMPLATE(BM_angle_bound_bumpy, PVF::Cholmod_sparse_solver)
  ->Name("BM_angle_bound_bumpy/CHOLMOD")->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif

} // namespace

BENCHMARK_MAIN();
