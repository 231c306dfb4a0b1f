// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// The planar-quad pipeline, stage by stage (field, integer-grid map, quad
// extraction, planarity, planarization), once per run:
// - inspired_mesh.obj (4288 faces) with its 84 bundled constraints, the
//   conjugate field, quads of size 0.82 (the paper's), planarized to 1%;
// - bumpy.off after three Loop subdivisions (159,744 faces), the smooth frame
//   field of 1% curvature constraints, quads of the mean edge length, and 20
//   planarization iterations (to time an iteration; such a smooth field's
//   quads do not become planar to 1%, see the user manual).

#include "pvf_benchmark_common.h"

#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/design_conjugate_frame_field.h>
#include <CGAL/Polyvector_fields/design_polyvector_field.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/extract_quad_mesh.h>
#include <CGAL/Polyvector_fields/compute_integer_grid_map.h>
#include <CGAL/Polyvector_fields/planarize_quad_mesh.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>
#include <CGAL/Polyvector_fields/select_curvature_constraints.h>

#include <benchmark/benchmark.h>

#include <array>
#include <map>

namespace {

using namespace pvf_bench;

void BM_planar_quads(benchmark::State& state)
{
  const bool inspired = state.range(0) == 0;
  const Mesh& tm = inspired ? subdivided_mesh("inspired_mesh.obj", 0) : bumpy(3);
  std::vector<Constraint> constraints;
  std::map<face_descriptor, PVF::Principal_curvatures<Vector_3> > curvature;
  const auto curvature_map = boost::make_assoc_property_map(curvature);
  if(inspired)
  {
    const std::string data(PVF_DATA_DIR);
    if(PVF::IO::read_dmat_constraints(data + "/inspired_mesh_b.dmat", data + "/inspired_mesh_bc.dmat", tm, constraints) !=
       PVF::Error_code::SUCCESS)
    {
      state.SkipWithError("cannot read the constraints");
      return;
    }
  }
  else if(PVF::estimate_principal_curvatures(tm, curvature_map) != PVF::Error_code::SUCCESS ||
          PVF::select_curvature_constraints(tm, curvature_map, constraints,
                                            PVF::parameters::constrained_fraction(0.01)) != PVF::Error_code::SUCCESS)
  {
    state.SkipWithError("cannot make curvature constraints");
    return;
  }
  double t_field = 0, t_map = 0, t_extraction = 0, t_planarity = 0, t_planarization = 0;
  PVF::Integer_grid_map_result map_result;
  PVF::Quad_extraction_result extraction;
  PVF::Planarity_result before, after;
  PVF::Planarization_result planarization;
  for(auto _ : state)
  {
    const PVF::Tangent_bundle<Mesh> bundle(tm);
    std::map<face_descriptor, std::vector<Complex> > field;
    auto start = std::chrono::steady_clock::now();
    PVF::Error_code code;
    if(inspired)
    {
      PVF::Conjugate_field_result result;
      code = PVF::design_conjugate_frame_field(bundle, constraints, boost::make_assoc_property_map(field), result);
    }
    else
      code = PVF::design_polyvector_field(tm, 4, constraints, boost::make_assoc_property_map(field),
                                          PVF::parameters::sign_symmetric(true));
    t_field = seconds_since(start);
    std::map<boost::graph_traits<Mesh>::halfedge_descriptor, std::array<double, 2> > uv;
    start = std::chrono::steady_clock::now();
    if(code == PVF::Error_code::SUCCESS)
      code = inspired ? PVF::compute_integer_grid_map(bundle, boost::make_assoc_property_map(field),
                                                      boost::make_assoc_property_map(uv), map_result,
                                                      PVF::parameters::target_edge_length(0.82))
                      : PVF::compute_integer_grid_map(bundle, boost::make_assoc_property_map(field),
                                                      boost::make_assoc_property_map(uv), map_result);
    t_map = seconds_since(start);
    Mesh quads;
    start = std::chrono::steady_clock::now();
    if(code == PVF::Error_code::SUCCESS)
      code = PVF::extract_quad_mesh(bundle, boost::make_assoc_property_map(uv), map_result, quads, extraction);
    t_extraction = seconds_since(start);
    auto planarity = quads.add_property_map<Mesh::Face_index, double>("f:planarity").first;
    start = std::chrono::steady_clock::now();
    if(code == PVF::Error_code::SUCCESS)
      code = PVF::quad_planarity(quads, planarity, before);
    t_planarity = seconds_since(start);
    start = std::chrono::steady_clock::now();
    if(code == PVF::Error_code::SUCCESS)
    {
      code = inspired ? PVF::planarize_quad_mesh(quads, tm, planarization)
                      : PVF::planarize_quad_mesh(quads, tm, planarization, CGAL::parameters::number_of_iterations(20));
      if(!inspired && code == PVF::Error_code::DID_NOT_CONVERGE)
        code = PVF::Error_code::SUCCESS;  // 20 iterations, timed
    }
    t_planarization = seconds_since(start);
    if(code != PVF::Error_code::SUCCESS)
    {
      state.SkipWithError(PVF::get_error_message(code));
      return;
    }
    PVF::quad_planarity(quads, planarity, after);
  }
  state.SetLabel(inspired ? "inspired_mesh, conjugate field, h 0.82" : "bumpy level 3, smooth field, h mean edge");
  state.counters["faces"] = double(tm.number_of_faces());
  state.counters["quads"] = double(extraction.quads);
  state.counters["flipped_faces"] = double(map_result.flipped_faces);
  state.counters["field_s"] = t_field;
  state.counters["map_s"] = t_map;
  state.counters["map_factorization_s"] = map_result.time_factorization;
  state.counters["map_stiffening_s"] = map_result.time_stiffening;
  state.counters["extraction_s"] = t_extraction;
  state.counters["planarity_s"] = t_planarity;
  state.counters["planarization_s"] = t_planarization;
  state.counters["planarization_iterations"] = double(planarization.iterations);
  state.counters["planarization_closest_points_s"] = planarization.time_closest;
  state.counters["planarity_max_before"] = before.max;
  state.counters["planarity_mean_before"] = before.mean;
  state.counters["planarity_max_after"] = planarization.max_planarity_after;
}
BENCHMARK(BM_planar_quads)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

} // namespace

BENCHMARK_MAIN();
