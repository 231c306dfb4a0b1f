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
//   general-frame constraints;
// - the conjugate field from 1% curvature constraints on every bundled mesh
//   and on bunny.off, the cost of one of its steps on bunny.off against a
//   fresh factorization, and the 70-degree angle bound on bunny.off from 20
//   random constraints.
// Each with every available sparse solver.

#include "pvf_benchmark_common.h"

#include <CGAL/Polyvector_fields/Cholmod_solver.h>
#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/design_angle_bounded_frame_field.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>
#include <CGAL/Polyvector_fields/design_conjugate_frame_field.h>
#include <CGAL/Polyvector_fields/design_polyvector_field.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/frame_field_measures.h>
#include <CGAL/Polyvector_fields/select_curvature_constraints.h>

#include <benchmark/benchmark.h>

#include <map>

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
BENCHMARK_TEMPLATE(BM_conjugate_per_iteration, PVF::Amg_sparse_solver)
  ->Name("BM_conjugate_per_iteration/AMG")->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK_TEMPLATE(BM_conjugate_per_iteration, PVF::Default_sparse_solver)
  ->Name("BM_conjugate_per_iteration/default")->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

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

// ---------------------------------------------------------------------------
// The conjugate field from 1% curvature constraints on every bundled mesh and
// on the Stanford bunny (75,408 faces), with the default stopping rule: its
// time (curvature and constraints excluded), iterations, singularities of the
// smooth field it starts from and of the result, and its mean normalised
// deviation |u^T S v| / (|u| |v| max|k|), weighted as the stopping rule
// weighs it and plain over all faces.
// ---------------------------------------------------------------------------
const char* const curvature_meshes[] = { "botanic-garden-bubble.off", "bumpy.off", "eight.off", "fandisk.off",
                                         "inspired_mesh.obj", "lilium.obj", "bunny.off" };

struct Curvature_setup
{
  std::map<face_descriptor, PVF::Principal_curvatures<Vector_3> > curvatures;
  std::vector<Constraint> constraints;
  std::size_t smooth_singularities = 0;
};

const Curvature_setup& curvature_setup(const Mesh& tm)
{
  static std::map<const Mesh*, Curvature_setup> setups;
  auto it = setups.find(&tm);
  if(it != setups.end())
    return it->second;
  Curvature_setup& s = setups[&tm];
  const auto curvatures = boost::make_assoc_property_map(s.curvatures);
  std::map<face_descriptor, std::vector<Complex> > smooth;
  std::vector<PVF::Singularity<boost::graph_traits<Mesh>::vertex_descriptor> > singularities;
  if(PVF::estimate_principal_curvatures(tm, curvatures) != PVF::Error_code::SUCCESS ||
     PVF::select_curvature_constraints(tm, curvatures, s.constraints, PVF::parameters::constrained_fraction(0.01)) !=
       PVF::Error_code::SUCCESS ||
     PVF::design_polyvector_field(tm, 4, s.constraints, boost::make_assoc_property_map(smooth),
                                  PVF::parameters::sign_symmetric(true)) != PVF::Error_code::SUCCESS ||
     PVF::compute_singularities(tm, 4, boost::make_assoc_property_map(smooth), std::back_inserter(singularities)) !=
       PVF::Error_code::SUCCESS)
  {
    std::cerr << "cannot set up the curvature constraints\n";
    std::exit(EXIT_FAILURE);
  }
  s.smooth_singularities = singularities.size();
  return s;
}

void BM_conjugate_curvature(benchmark::State& state)
{
  const Mesh& tm = subdivided_mesh(curvature_meshes[state.range(0)], 0);
  const Curvature_setup& setup = curvature_setup(tm);
  const auto curvatures = boost::make_assoc_property_map(const_cast<Curvature_setup&>(setup).curvatures);
  PVF::Conjugate_field_result result;
  std::map<face_descriptor, std::vector<Complex> > field;
  for(auto _ : state)
  {
    field.clear();
    if(setup.constraints.empty() ||
       PVF::design_conjugate_frame_field(tm, setup.constraints, boost::make_assoc_property_map(field), result,
                                         PVF::parameters::principal_curvature_map(curvatures)) != PVF::Error_code::SUCCESS)
    {
      state.SkipWithError("design_conjugate_frame_field failed");
      return;
    }
  }
  std::vector<PVF::Singularity<boost::graph_traits<Mesh>::vertex_descriptor> > singularities;
  PVF::compute_singularities(tm, 4, boost::make_assoc_property_map(field), std::back_inserter(singularities));
  std::map<face_descriptor, double> deviation;
  PVF::compute_conjugacy_deviation(tm, boost::make_assoc_property_map(field), curvatures,
                                   boost::make_assoc_property_map(deviation));
  double sum = 0;
  for(const auto& entry : deviation)
    sum += entry.second;
  state.SetLabel(curvature_meshes[state.range(0)]);
  state.counters["faces"] = double(tm.number_of_faces());
  state.counters["constraints"] = double(setup.constraints.size());
  state.counters["iterations"] = double(result.iterations);
  state.counters["converged"] = result.converged ? 1 : 0;
  state.counters["factorizations"] = double(result.factorizations);
  state.counters["smooth_singularities"] = double(setup.smooth_singularities);
  state.counters["singularities"] = double(singularities.size());
  state.counters["weighted_deviation_start"] = result.deviation_history.front();
  state.counters["weighted_deviation"] = result.mean_deviation;
  state.counters["mean_deviation_all_faces"] = deviation.empty() ? 0.0 : sum / double(deviation.size());
}
BENCHMARK(BM_conjugate_curvature)->DenseRange(0, 6)->Unit(benchmark::kMillisecond)->UseRealTime();

// On the bunny: one global step of the conjugate field against a fresh
// factorization of the same system. The step is (time of 6 steps - time of
// 1 step) / 5, without a stopping test (tolerance 1e-300); the factorization is
// that of the smooth frame field by the designer (both degrees).
void BM_conjugate_step_bunny(benchmark::State& state)
{
  const Mesh& tm = subdivided_mesh("bunny.off", 0);
  const Curvature_setup& setup = curvature_setup(tm);
  const auto curvatures = boost::make_assoc_property_map(const_cast<Curvature_setup&>(setup).curvatures);
  auto run = [&](std::size_t steps) {
    PVF::Conjugate_field_result result;
    auto coefficients = boost::dummy_property_map();
    const auto start = std::chrono::steady_clock::now();
    const PVF::Error_code code = PVF::design_conjugate_frame_field(
      tm, setup.constraints, coefficients, result,
      PVF::parameters::principal_curvature_map(
        curvatures, PVF::parameters::tolerance(1e-300, CGAL::parameters::number_of_iterations(steps))));
    return (code == PVF::Error_code::SUCCESS && result.iterations == steps) ? seconds_since(start) : -1.0;
  };
  double one = 0, six = 0, factorization = 0;
  for(auto _ : state)
  {
    one = run(1);
    six = run(6);
    PVF::Polyvector_field_designer<Mesh> designer(tm, 4, PVF::parameters::sign_symmetric(true));
    auto coefficients = boost::dummy_property_map();
    if(one < 0 || six < 0 || designer.add_constraints(setup.constraints) != PVF::Error_code::SUCCESS ||
       designer.solve(coefficients) != PVF::Error_code::SUCCESS)
    {
      state.SkipWithError("the bunny's conjugate field failed");
      return;
    }
    factorization = designer.statistics().factorization;
  }
  state.counters["faces"] = double(tm.number_of_faces());
  state.counters["per_iteration_s"] = (six - one) / 5;
  state.counters["fresh_factorization_s"] = factorization;
  state.counters["iteration_over_factorization"] = (six - one) / 5 / factorization;
}
BENCHMARK(BM_conjugate_step_bunny)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

// The angle bound of 70 degrees on the bunny from 20 random general-frame constraints.
void BM_angle_bound_bunny(benchmark::State& state)
{
  const Mesh& tm = subdivided_mesh("bunny.off", 0);
  const std::vector<Constraint> constraints = random_frame_constraints(tm, 20.5 / double(tm.number_of_faces()));
  PVF::Angle_bound_result result;
  for(auto _ : state)
  {
    auto coefficients = boost::dummy_property_map();
    if(PVF::design_angle_bounded_frame_field(tm, constraints, coefficients, result,
                                             PVF::parameters::angle_bound(70.0 * CGAL_PI / 180.0)) !=
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
  state.counters["factorizations"] = double(result.factorizations);
  state.counters["min_free_angle_deg"] = result.minimum_free_angle * 180.0 / CGAL_PI;
}
BENCHMARK(BM_angle_bound_bunny)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
