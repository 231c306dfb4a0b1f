// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Stages and end-to-end time of a sign-symmetric 4-PolyVector design (frame
// field) with 1% of the faces under hard constraints, over bumpy.off after
// 1..max_level() Loop subdivisions (10k, 40k, 160k, 640k, 2.5M faces), with
// each available sparse solver (and the package's default, which picks between
// the direct solver and multigrid by size); plus the root kernel and the
// singularities.
// The argument of every size-dependent benchmark is the subdivision level;
// the counter `faces` gives the size.

#include "pvf_benchmark_common.h"

#include <CGAL/Polyvector_fields/Cholmod_solver.h>
#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>

#include <benchmark/benchmark.h>

namespace {

using namespace pvf_bench;

// Levels 1..4 (10k to 640k faces) for every variant; the package's default
// (CHOLMOD, parallel) also runs the levels above (level 5: 2.56M faces) when
// PVF_BENCH_MAX_LEVEL asks for them.
void add_levels(benchmark::internal::Benchmark* b, int last)
{
  for(int level = 1; level <= last; ++level)
    b->Arg(level);
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}
void level_arguments(benchmark::internal::Benchmark* b) { add_levels(b, (std::min)(4, max_level())); }
void all_level_arguments(benchmark::internal::Benchmark* b) { add_levels(b, max_level()); }

// Face frames and Levi-Civita connection.
void BM_connection(benchmark::State& state)
{
  const Mesh& tm = bumpy(int(state.range(0)));
  for(auto _ : state)
  {
    PVF::Tangent_bundle<Mesh> connection(tm);
    benchmark::DoNotOptimize(connection.number_of_faces());
  }
  state.counters["faces"] = double(tm.number_of_faces());
  state.SetItemsProcessed(state.iterations() * int64_t(tm.number_of_faces()));
}
BENCHMARK(BM_connection)->Apply(level_arguments);

// End to end, with the designer's own stage times as counters (seconds, mean
// over the iterations).
template <typename Solver, typename ConcurrencyTag>
void BM_design(benchmark::State& state)
{
  const Mesh& tm = bumpy(int(state.range(0)));
  const std::vector<Constraint> constraints = random_frame_constraints(tm);
  End_to_end_times sum;
  for(auto _ : state)
  {
    const End_to_end_times t = design_end_to_end<Solver, ConcurrencyTag>(tm, constraints);
    sum.degrees = t.degrees;
    sum.connection += t.connection;
    sum.assembly += t.assembly;
    sum.factorization += t.factorization;
    sum.solve += t.solve;
    sum.roots += t.roots;
  }
  const double n = double(state.iterations());
  state.counters["faces"] = double(tm.number_of_faces());
  state.counters["constraints"] = double(constraints.size());
  state.counters["degrees"] = double(sum.degrees);
  state.counters["connection_s"] = sum.connection / n;
  state.counters["assembly_s"] = sum.assembly / n;
  state.counters["factorization_s"] = sum.factorization / n;
  state.counters["solve_s"] = sum.solve / n;
  state.counters["roots_s"] = sum.roots / n;
  state.SetItemsProcessed(state.iterations() * int64_t(tm.number_of_faces()));
}
// Sequential and parallel (independent degrees factored at the same time, TBB).
BENCHMARK_TEMPLATE(BM_design, PVF::Simplicial_ldlt_solver, CGAL::Sequential_tag)->Name("BM_design/SimplicialLDLT")->Apply(level_arguments);
#ifdef CGAL_LINKED_WITH_TBB
BENCHMARK_TEMPLATE(BM_design, PVF::Simplicial_ldlt_solver, CGAL::Parallel_tag)->Name("BM_design/SimplicialLDLT_parallel")->Apply(level_arguments);
#endif
#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
BENCHMARK_TEMPLATE(BM_design, PVF::Cholmod_sparse_solver, CGAL::Sequential_tag)->Name("BM_design/CHOLMOD")->Apply(level_arguments);
#ifdef CGAL_LINKED_WITH_TBB
BENCHMARK_TEMPLATE(BM_design, PVF::Cholmod_sparse_solver, CGAL::Parallel_tag)->Name("BM_design/CHOLMOD_parallel")->Apply(level_arguments);
#endif
BENCHMARK_TEMPLATE(BM_design, Cholmod_metis_solver, CGAL::Sequential_tag)->Name("BM_design/CHOLMOD_METIS")->Apply(level_arguments);
#endif
// Multigrid-preconditioned conjugate gradient at every size, and the package's
// default (direct below 50,000 unknowns, multigrid above) at every size up to
// PVF_BENCH_MAX_LEVEL (level 5: 2.56M faces).
BENCHMARK_TEMPLATE(BM_design, PVF::Amg_sparse_solver, CGAL::Parallel_if_available_tag)->Name("BM_design/AMG_parallel")->Apply(level_arguments);
BENCHMARK_TEMPLATE(BM_design, PVF::Default_sparse_solver, CGAL::Parallel_if_available_tag)->Name("BM_design/default")->Apply(all_level_arguments);

// New constraint values on the same faces: the factorization is reused, so
// this is the cost of the triangular solves (and the right-hand sides).
template <typename Solver>
void BM_resolve(benchmark::State& state)
{
  typedef PVF::Polyvector_field_designer<Mesh, CGAL::Default, CGAL::Default, Solver> Designer;
  const Mesh& tm = bumpy(int(state.range(0)));
  const std::vector<Constraint> first = random_frame_constraints(tm, 0.01, 1);
  // The same faces, kinds and weights with other frames: {v, u + v/2} instead of {u, v}.
  std::vector<Constraint> second = first;
  for(Constraint& c : second)
    c.vectors = { c.vectors[1], c.vectors[0] + 0.5 * c.vectors[1] };
  Designer designer(tm, 4, PVF::parameters::sign_symmetric(true));
  designer.add_constraints(first);
  if(designer.solve(boost::dummy_property_map()) != PVF::Error_code::SUCCESS)
  {
    state.SkipWithError("design failed");
    return;
  }
  bool flip = false;
  double solve = 0;
  for(auto _ : state)
  {
    designer.clear_constraints();
    designer.add_constraints(flip ? first : second);
    flip = !flip;
    if(designer.solve(boost::dummy_property_map()) != PVF::Error_code::SUCCESS ||
       !designer.statistics().factorization_reused)
    {
      state.SkipWithError("the factorization was not reused");
      return;
    }
    solve += designer.statistics().solve;
  }
  state.counters["faces"] = double(tm.number_of_faces());
  state.counters["solve_s"] = solve / double(state.iterations());
}
BENCHMARK_TEMPLATE(BM_resolve, PVF::Simplicial_ldlt_solver)->Name("BM_resolve/SimplicialLDLT")->Apply(level_arguments);
#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
BENCHMARK_TEMPLATE(BM_resolve, PVF::Cholmod_sparse_solver)->Name("BM_resolve/CHOLMOD")->Apply(level_arguments);
#endif

// Coefficients of random frames {±u, ±v} (|u|, |v| in [0.5, 2]), 4 per face.
std::vector<Complex> random_frame_coefficients(std::size_t F, bool odd_coefficients)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0, 2 * CGAL_PI), length(0.5, 2);
  std::vector<Complex> c(4 * F);
  for(std::size_t f = 0; f < F; ++f)
  {
    const Complex u = std::polar(length(rng), angle(rng)), v = std::polar(length(rng), angle(rng));
    const Complex u2 = u * u, v2 = v * v;
    c[4 * f] = u2 * v2;
    c[4 * f + 2] = -(u2 + v2);
    if(odd_coefficients)  // a tiny perturbation: the general (companion) path
      c[4 * f + 1] = c[4 * f + 3] = Complex(1e-3, -1e-3);
  }
  return c;
}

// The per-face root kernel of sign-symmetric N = 4 (closed form), on F faces.
void BM_roots_sign_symmetric(benchmark::State& state)
{
  const std::size_t F = std::size_t(state.range(0));
  const std::vector<Complex> c = random_frame_coefficients(F, false);
  std::vector<Complex> roots(4 * F);
  for(auto _ : state)
  {
    for(std::size_t f = 0; f < F; ++f)
      PVF::polyvector_roots(c.data() + 4 * f, 4, roots.data() + 4 * f, true);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * int64_t(F));
}
BENCHMARK(BM_roots_sign_symmetric)->Arg(10000)->Arg(640000)->Arg(2560000)->Unit(benchmark::kMillisecond)->UseRealTime();

// Root extraction of a whole field (the loop of compute_field_roots(), face
// frame roots of F faces), sequential and with the faces shared among threads.
template <typename ConcurrencyTag>
void BM_field_roots(benchmark::State& state)
{
  const std::size_t F = std::size_t(state.range(0));
  const std::vector<Complex> c = random_frame_coefficients(F, false);
  std::vector<Complex> roots(4 * F);  // allocated (and its pages touched) outside the timing, as in BM_roots_*
  for(auto _ : state)
  {
    PVF::internal::field_roots<ConcurrencyTag>(c, 4, true, roots);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * int64_t(F));
}
BENCHMARK_TEMPLATE(BM_field_roots, CGAL::Sequential_tag)->Name("BM_field_roots_sign_symmetric/sequential")
  ->Arg(640000)->Arg(2560000)->Unit(benchmark::kMillisecond)->UseRealTime();
#ifdef CGAL_LINKED_WITH_TBB
BENCHMARK_TEMPLATE(BM_field_roots, CGAL::Parallel_tag)->Name("BM_field_roots_sign_symmetric/parallel")
  ->Arg(640000)->Arg(2560000)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif

// The general N = 4 kernel (companion matrix) on the same kind of input.
void BM_roots_general(benchmark::State& state)
{
  const std::size_t F = std::size_t(state.range(0));
  const std::vector<Complex> c = random_frame_coefficients(F, true);
  std::vector<Complex> roots(4 * F);
  for(auto _ : state)
  {
    for(std::size_t f = 0; f < F; ++f)
      PVF::polyvector_roots(c.data() + 4 * f, 4, roots.data() + 4 * f, false);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * int64_t(F));
}
BENCHMARK(BM_roots_general)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();

// Singularities of a designed field (the public function, which builds its
// own connection).
void BM_singularities(benchmark::State& state)
{
  const Mesh& tm = bumpy(int(state.range(0)));
  std::vector<Complex> c;
#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
  design_end_to_end<PVF::Cholmod_sparse_solver>(tm, random_frame_constraints(tm), &c);
#else
  design_end_to_end<PVF::Simplicial_ldlt_solver>(tm, random_frame_constraints(tm), &c);
#endif
  Mesh copy = tm;  // property maps are added to a copy, not to the cached mesh
  auto coefficients = copy.add_property_map<face_descriptor, std::vector<Complex> >("f:pvf_coefficients").first;
  std::size_t f = 0;
  for(face_descriptor fd : copy.faces())
  {
    coefficients[fd].assign(c.begin() + std::ptrdiff_t(4 * f), c.begin() + std::ptrdiff_t(4 * f + 4));
    ++f;
  }
  std::size_t count = 0;
  for(auto _ : state)
  {
    std::vector<PVF::Singularity<boost::graph_traits<Mesh>::vertex_descriptor> > singularities;
    if(PVF::compute_singularities(copy, 4, coefficients, std::back_inserter(singularities)) != PVF::Error_code::SUCCESS)
    {
      state.SkipWithError("compute_singularities failed");
      return;
    }
    count = singularities.size();
  }
  state.counters["faces"] = double(tm.number_of_faces());
  state.counters["singularities"] = double(count);
  state.SetItemsProcessed(state.iterations() * int64_t(tm.number_of_vertices()));
}
BENCHMARK(BM_singularities)->Apply(level_arguments);

} // namespace

BENCHMARK_MAIN();
