// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Peak memory of one end-to-end design, measured in a process of its own:
//
//   pvf_peak_memory LEVEL [ldlt|cg|cholmod|cholmod-metis|amg|default] [parallel|sequential]
//
// (default: ldlt, parallel; parallel means CGAL::Parallel_if_available_tag)
// (amg: Amg_sparse_solver; default: Default_sparse_solver, direct below 50,000
// unknowns and multigrid above; cg and cholmod-metis are proposals measured
// here, not solvers of the package;
// cg also prints the relative difference of its field to the SimplicialLDLT one)
//
// generates bumpy.off after LEVEL Loop subdivisions and the 1% constraints,
// then resets the kernel's peak-RSS mark (writing 5 to /proc/self/clear_refs,
// Linux >= 4.0), records VmRSS, runs the design once and reads VmHWM. It prints
// one line of key=value pairs:
//   mesh_rss_kb     resident memory before the design (mesh, constraints, libraries)
//   peak_kb         VmHWM after the design: the peak of the whole process during it
//   design_peak_kb  peak_kb - mesh_rss_kb: the peak the design itself added
//   hwm_reset       1 if the reset worked; 0 means peak_kb also holds the
//                   subdivision's own peak, and is an upper bound.
// This is not a Google Benchmark: a peak can only be attributed to one run per process.

#include "pvf_benchmark_common.h"

#include <CGAL/Polyvector_fields/Cholmod_solver.h>
#include <CGAL/Polyvector_fields/Default_sparse_solver.h>

#include <cstring>

namespace {

// max |a - b| / max |b| over the coefficients.
double relative_difference(const std::vector<std::complex<double> >& a, const std::vector<std::complex<double> >& b)
{
  double difference = 0, size = 0;
  for(std::size_t i = 0; i < b.size(); ++i)
  {
    difference = (std::max)(difference, std::abs(b[i] - a[i]));
    size = (std::max)(size, std::abs(b[i]));
  }
  return difference / size;
}

} // namespace

int main(int argc, char** argv)
{
  using namespace pvf_bench;
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " LEVEL [ldlt|cg|cholmod|cholmod-metis|amg|default] [parallel|sequential]\n";
    return EXIT_FAILURE;
  }
  const int level = std::atoi(argv[1]);
  const std::string solver = argc > 2 ? argv[2] : "ldlt";
  const std::string mode = argc > 3 ? argv[3] : "parallel";
  if(mode != "parallel" && mode != "sequential")
  {
    std::cerr << "unknown mode " << mode << " (parallel or sequential)\n";
    return EXIT_FAILURE;
  }
  const bool sequential = (mode == "sequential");
#ifndef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
  if(solver == "cholmod" || solver == "cholmod-metis")
  {
    std::cerr << "CHOLMOD is not available in this build\n";
    return EXIT_FAILURE;
  }
#endif
  if(solver != "ldlt" && solver != "cg" && solver != "cholmod" && solver != "cholmod-metis" && solver != "amg" &&
     solver != "default")
  {
    std::cerr << "unknown solver " << solver << "\n";
    return EXIT_FAILURE;
  }
  const Mesh& tm = bumpy(level);
  const std::vector<Constraint> constraints = random_frame_constraints(tm);
  const bool reset = reset_peak_rss();
  const long before = status_kb("VmRSS");
  End_to_end_times t;
#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
  if(solver == "cholmod")
    t = sequential ? design_end_to_end<CGAL::Polyvector_fields::Cholmod_sparse_solver, CGAL::Sequential_tag>(tm, constraints)
                   : design_end_to_end<CGAL::Polyvector_fields::Cholmod_sparse_solver>(tm, constraints);
  else if(solver == "cholmod-metis")
    t = sequential ? design_end_to_end<Cholmod_metis_solver, CGAL::Sequential_tag>(tm, constraints)
                   : design_end_to_end<Cholmod_metis_solver>(tm, constraints);
  else
#endif
  if(solver == "amg")
  {
    // Also reports the largest coefficient difference to the direct solver's
    // field, relative to its largest coefficient (the peak is read before the
    // direct solve).
    std::vector<Complex> iterative, direct;
    t = sequential ? design_end_to_end<CGAL::Polyvector_fields::Amg_sparse_solver, CGAL::Sequential_tag>(tm, constraints, &iterative)
                   : design_end_to_end<CGAL::Polyvector_fields::Amg_sparse_solver>(tm, constraints, &iterative);
    const long peak = status_kb("VmHWM");
    design_end_to_end<CGAL::Polyvector_fields::Direct_sparse_solver>(tm, constraints, &direct);
    const double difference = relative_difference(iterative, direct);
    std::cout << "solver=amg mode=" << mode << " level=" << level << " faces=" << t.faces << " seconds=" << t.total
              << " connection_s=" << t.connection << " assembly_s=" << t.assembly
              << " factorization_s=" << t.factorization << " solve_s=" << t.solve << " roots_s=" << t.roots
              << " mesh_rss_kb=" << before << " peak_kb=" << peak << " design_peak_kb=" << (peak - before)
              << " hwm_reset=" << (reset ? 1 : 0) << " relative_difference_to_direct=" << difference << std::endl;
    return EXIT_SUCCESS;
  }
  else if(solver == "default")
    t = sequential ? design_end_to_end<CGAL::Polyvector_fields::Default_sparse_solver, CGAL::Sequential_tag>(tm, constraints)
                   : design_end_to_end<CGAL::Polyvector_fields::Default_sparse_solver>(tm, constraints);
  else if(solver == "cg")
  {
    // Also reports the largest coefficient difference to the direct solver's field.
    std::vector<Complex> iterative, direct;
    t = design_end_to_end<Preconditioned_cg_solver>(tm, constraints, &iterative);
    const long peak = status_kb("VmHWM");
    design_end_to_end<CGAL::Polyvector_fields::Simplicial_ldlt_solver>(tm, constraints, &direct);
    const double difference = relative_difference(iterative, direct);
    std::cout << "solver=cg level=" << level << " faces=" << t.faces << " seconds=" << t.total
              << " factorization_s=" << t.factorization << " solve_s=" << t.solve << " mesh_rss_kb=" << before
              << " peak_kb=" << peak << " design_peak_kb=" << (peak - before) << " hwm_reset=" << (reset ? 1 : 0)
              << " relative_difference_to_ldlt=" << difference << std::endl;
    return EXIT_SUCCESS;
  }
  else
    t = sequential ? design_end_to_end<CGAL::Polyvector_fields::Simplicial_ldlt_solver, CGAL::Sequential_tag>(tm, constraints)
                   : design_end_to_end<CGAL::Polyvector_fields::Simplicial_ldlt_solver>(tm, constraints);
  const long peak = status_kb("VmHWM");
  std::cout << "solver=" << solver << " mode=" << mode << " level=" << level << " faces=" << t.faces << " seconds=" << t.total
            << " connection_s=" << t.connection << " assembly_s=" << t.assembly
            << " factorization_s=" << t.factorization << " solve_s=" << t.solve << " roots_s=" << t.roots
            << " mesh_rss_kb=" << before << " peak_kb=" << peak << " design_peak_kb=" << (peak - before)
            << " hwm_reset=" << (reset ? 1 : 0) << std::endl;
  return EXIT_SUCCESS;
}
