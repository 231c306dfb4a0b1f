// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// design_polyvector_field: the summary of a run on standard output (stage 10).

#ifndef PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_SUMMARY_H
#define PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_SUMMARY_H

#include "common.h"
#include "options.h"
#include "output_files.h"
#include "stages.h"

#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

namespace pvf_cli {

// ---------------------------------------------------------------------------
// Stage 10: the summary.
// ---------------------------------------------------------------------------
// Which solver solved the systems, and what multigrid did when it was used.
std::string solver_report(const PVF::Default_sparse_solver& solver)
{
#ifdef CGAL_PVF_HAS_CHOLMOD
  const char* direct = "direct (CHOLMOD)";
#else
  const char* direct = "direct (Eigen SimplicialLDLT)";
#endif
  const PVF::Amg_statistics s = solver.amg_solver().statistics();
  std::ostringstream m;
  if(s.solves == 0)
  {
    m << direct;
    if(solver.amg_threshold() != std::numeric_limits<std::size_t>::max())
      m << " (systems of fewer than " << solver.amg_threshold() << " unknowns)";
    return m.str();
  }
  m << "multigrid-preconditioned conjugate gradient: " << s.level_sizes.size() << " levels (";
  for(std::size_t l = 0; l < s.level_sizes.size(); ++l)
    m << (l ? ", " : "") << s.level_sizes[l];
  m << " unknowns), " << s.solves << " solves, " << s.iterations << " iterations (at most " << s.max_iterations
    << "), residual at most " << s.max_residual << ", " << s.setups << " setups";
  if(s.reused_setups)
    m << " and " << s.reused_setups << " refactorizations on kept coarse levels";
  m << " (time summed over the systems: structure " << std::fixed << std::setprecision(3) << s.analysis_seconds
    << " s, setups " << s.setup_seconds << " s, solves " << s.solve_seconds << " s)";
  m.unsetf(std::ios::fixed);
  if(s.fallbacks)
    m << "; " << s.fallbacks << " solves did not converge and were finished by the direct solver";
  return m.str();
}

void print_summary(const Options& o, const Input_mesh& input, const Quad_size& size, const Sizing& sizing,
                   const Constraint_set& constraints,
                   const Field& field, const Analysis& a, const Parametrization& param, const Quad_stage& q, const Output_files& outputs,
                   const Stopwatch& clock, bool written = true)
{
  const Mesh& tm = input.tm;
  const PVF::IO::Mesh_repair_result& r = input.report;
  int sum = 0, positive = 0, negative = 0;
  for(const auto& s : a.singularities)
  {
    sum += s.index_numerator;
    (s.index_numerator > 0 ? positive : negative) += 1;
  }
  std::size_t border_edges = 0, used_vertices = 0;
  for(auto e : edges(tm))
    border_edges += CGAL::is_border(e, tm);
  for(Vertex v : vertices(tm))
    used_vertices += (halfedge(v, tm) == Mesh::null_halfedge()) ? 0 : 1;
  // Isolated vertices (kept with --no-repair) are not part of the surface.
  const int chi = int(used_vertices) - int(num_edges(tm)) + int(num_faces(tm));
  std::cout << std::setprecision(6);
  std::cout << "mesh            " << o.mesh << ": " << num_faces(tm) << " faces, " << used_vertices << " vertices, "
            << field.components << " component(s), " << (border_edges ? "with boundary" : "closed")
            << ", Euler characteristic " << chi << "\n";
  if(r.changed(o.repair))
  {
    std::cout << "repair          " << r.file_faces << " faces in the file ->";
    const std::pair<std::size_t, const char*> items[] = {
      { r.triangulated_faces, "polygons triangulated" }, { r.merged_points, "duplicate points merged" },
      { r.duplicate_faces, "duplicate faces removed" }, { r.degenerate_polygons, "faces with a repeated vertex fixed or removed" },
      { r.degenerate_faces, "zero-area triangles repaired" }, { r.reoriented_faces, "faces reoriented" },
      { r.split_vertices, "vertices split (non-manifold)" }, { r.isolated_vertices, "isolated vertices removed" } };
    const char* separator = " ";
    for(const auto& item : items)
      if(item.first)
      {
        std::cout << separator << item.first << " " << item.second;
        separator = ", ";
      }
    std::cout << "; the outputs refer to the repaired mesh" << (o.out_mesh.empty() ? " (write it with --out-mesh)" : "") << "\n";
  }
  else if(r.isolated_vertices)
    std::cout << "note            " << r.isolated_vertices << " isolated vertices are ignored\n";
  if(!sizing.tries.empty() || !sizing.unfilled.empty() || sizing.split_at >= 0)
  {
    std::cout << "quad size       " << size.h;
    if(!sizing.unfilled.empty())
    {
      std::cout << ", the default made finer " << sizing.unfilled.size()
                << " times because the quads could not fill the map's fold-overs: at";
      for(std::size_t i = 0; i < sizing.unfilled.size(); ++i)
        std::cout << (i ? "," : "") << " " << sizing.unfilled[i].first
                  << (sizing.unfilled[i].second ? " a quad stayed folded against the surface"
                                                : " a component would have been split into quads on its triangles");
    }
    if(!sizing.tries.empty())
    {
      std::cout << (sizing.unfilled.empty() ? ", the default made finer " : "; made finer ") << sizing.tries.size()
                << " times: at";
      for(std::size_t i = 0; i < sizing.tries.size(); ++i)
        std::cout << (i ? "," : "") << " " << sizing.tries[i].first << " an input point was "
                  << 100 * sizing.tries[i].second << "%";
      std::cout << " of the bounding-box diagonal from the quads";
    }
    if(!sizing.tries.empty())
      std::cout << " (bound " << 100 * sizing.bound << "%)";
    if(sizing.split_at >= 0)
    {
      std::cout << "; at " << size.h << ", " << 100 * sizing.split_at << "%";
      if(sizing.tries.empty())
        std::cout << " (bound " << 100 * sizing.bound << "%)";
      std::cout << ": the components farther than the bound split into quads";
    }
    std::cout << "\n";
  }
  if(size.refined())
    std::cout << "refinement      " << size.faces_before << " -> " << size.faces_after
              << " faces: edges longer than two quads (" << 2 * size.h
              << ") split at their midpoints; the outputs refer to the refined mesh"
              << (o.out_mesh.empty() ? " (write it with --out-mesh)" : "") << "\n";
  std::cout << "field           degree " << o.degree << (o.sign_symmetric ? ", sign-symmetric" : "") << ", "
            << field.statistics.number_of_degrees_solved << " coefficient degree(s) solved\n";
  std::cout << "constraints     " << constraints.list.size() << " faces (" << field.full << " full, " << field.partial
            << " partial" << (constraints.sharp ? ", " + std::to_string(constraints.sharp) + " from sharp edges" : std::string())
            << (constraints.from_curvature ? ", " + std::to_string(constraints.from_curvature) + " from curvature" : std::string())
            << "), ";
  if(o.soft_weight > 0)
    std::cout << "soft, weight " << o.soft_weight << "\n";
  else
    std::cout << "hard\n";
  if(!constraints.note.empty())
    std::cout << "note            " << constraints.note << "\n";
  std::cout << "solver          " << solver_report(field.solver) << "\n";
  std::cout << "energy          " << a.energy << " (smoothness, Eq. 6"
            << (o.weights == PVF::Smoothness_weights::HARMONIC ? ", harmonic weights)" : ")");
  if(o.angle_bound_degrees > 0 || o.conjugate)
    std::cout << "; smooth field before optimisation " << field.smooth_energy;
  std::cout << "\n" << field.frame_report;
  std::cout << "singularities   " << a.singularities.size() << " (" << positive << " positive, " << negative
            << " negative), sum of indices " << sum << "/" << o.degree;
  if(!border_edges)
    std::cout << " (Poincare-Hopf: N * chi = " << int(o.degree) * chi << ")";
  std::cout << "\n";
  if(!a.undefined.empty())
    std::cout << "undefined index " << a.undefined.size() << " vertices next to faces with a zero constant coefficient\n";
  if(!a.note.empty())
    std::cout << "note            " << a.note << "\n";
  if(param.computed)
  {
    const PVF::Integer_grid_map_result& r = param.result;
    std::cout << "parametrization edge length " << r.target_edge_length << " (mean edge " << r.mean_edge_length << "); "
              << r.comb.singular_vertices << " singular vertices on integer points";
    if(r.comb.cancelled_singularity_pairs + r.comb.merged_singularity_pairs + r.comb.moved_singularities +
         r.comb.split_singularities + r.comb.singularities_moved_to_border > 0)
      std::cout << " (of the field's singularities closer than a quad: " << r.comb.cancelled_singularity_pairs
                << " opposite pairs cancelled, " << r.comb.merged_singularity_pairs << " pairs merged, "
                << r.comb.moved_singularities << " moved apart, " << r.comb.singularities_moved_to_border
                << " moved onto the border; " << r.comb.split_singularities
                << " quarter turns split off vertices of valence below 3 or above 6; the frames of "
                << r.comb.turned_frames << " faces turned to follow)";
    std::cout << ", " << r.comb.seam_curves << " seam curves ("
              << r.comb.cut_edges << " cut edges), " << r.integer_unknowns << " integer unknowns; " << r.flipped_faces
              << " flipped faces";
    if(r.stiffening_rounds > 0)
      std::cout << " after " << r.stiffening_rounds << " stiffening rounds (" << r.integer_roundings - 1
                << " of them rounding the integers again, " << r.cg_solves << " solved by conjugate gradient in "
                << r.cg_iterations << " iterations)";
    std::cout << "; worst seam residual " << r.max_seam_residual << "; energy rounded/continuous " << r.energy_ratio;
    if(r.comb.clamped_faces > 0)
      std::cout << "; " << r.comb.clamped_faces << " near-degenerate frames clamped";
    if(param.recomputed)
      std::cout << "; computed again with the integers rounded in every stiffening round, after the quad extraction"
                   " could not repair the degenerate faces of the first map";
    if(r.feature_edges > 0)
      std::cout << "\nfeatures        " << r.aligned_feature_edges << " of " << r.feature_edges
                << " feature edges (sharp" << (o.boundary_alignment ? " and border" : "") << ") on integer iso-lines, "
                << r.feature_corners << " feature corners on integer points; " << r.unaligned_feature_edges
                << " left free (the field does not follow them)"
                << (r.released_feature_edges
                      ? ", " + std::to_string(r.released_feature_edges) + " left free because faces beside them folded"
                      : std::string())
                << (r.flattening_feature_edges
                      ? ", " + std::to_string(r.flattening_feature_edges) +
                          " left free because another feature edge of their triangle is on the same iso-line"
                      : std::string())
                << (r.dropped_feature_edges ? ", " + std::to_string(r.dropped_feature_edges) + " with no integer solution"
                                            : std::string());
    const auto old_flags = std::cout.flags();
    const auto old_precision = std::cout.precision();
    std::cout << std::fixed << std::setprecision(3) << "\n                (time: comb and cut " << r.time_comb
              << ", seam reduction " << r.time_reduction << ", assembly " << r.time_assembly << ", factorization "
              << r.time_factorization << ", conjugate gradient " << r.time_cg << ", integer rounding "
              << r.time_schur + r.time_rounding << ", stiffening "
              << r.time_stiffening << ")\n";
    std::cout.flags(old_flags);
    std::cout.precision(old_precision);
  }
  if(q.computed)
  {
    const PVF::Quad_extraction_result& e = q.extraction;
    std::cout << "quad mesh       " << e.quads << " quads";
    if(e.trimmed_polygons > 0)
      std::cout << " and " << e.trimmed_polygons << " trimmed boundary polygons";
    std::cout << ", " << e.vertices << " vertices, " << e.irregular_vertices << " irregular vertices (valence != 4)";
    if(e.flipped_faces > 0)
      std::cout << "; " << e.flipped_faces << " flipped faces of the map, " << e.repaired_regions << " regions repaired";
    if(e.unfolded_quads > 0)
      std::cout << "; " << e.unfolded_quads << " folded quads repaired (" << e.moved_quad_vertices
                << " vertices moved on the surface)";
    if(e.filled_holes > 0)
      std::cout << "; " << e.cut_faces << " triangles that still folded cut out of the map, the " << e.filled_holes
                << " holes they left filled with " << e.filling_quads << " quads";
    if(e.split_components > 0)
      std::cout << "; " << e.split_components << " of the " << e.components << " components ("
                << e.split_triangles << " triangles) split into quads, three per triangle: "
                << e.split_small_components << " smaller than a quad, " << e.split_far_components
                << " that the quads could not follow within the deviation bound, " << e.split_defective_components
                << " whose quads were not one closed quad mesh of them, " << unfilled_components(e)
                << " whose fold-overs could not be filled";
    if(e.refilled_quads > 0)
      std::cout << "; " << e.refilled_quads << " quads still folded cut out with the quads around them and filled";
    if(e.snapped_tips > 0)
      std::cout << "; " << e.snapped_tips << " corners moved onto tips of the surface finer than the quads";
    if(sizing.deviation >= 0)
      std::cout << "; every input point within " << 100 * sizing.deviation << "% of the bounding-box diagonal";
    {
      const auto old_flags = std::cout.flags();
      const auto old_precision = std::cout.precision();
      std::cout << std::fixed << std::setprecision(3) << "\n                (time: charts " << e.time_setup
                << ", fold-over repair " << e.time_repair << ", integer points " << e.time_points << ", tracing "
                << e.time_tracing << ", cells " << e.time_faces << ", quads and their checks " << e.time_output << ")";
      std::cout.flags(old_flags);
      std::cout.precision(old_precision);
    }
    std::cout << "\nplanarity       max " << 100 * q.before.max << "%, mean " << 100 * q.before.mean << "%";
    if(q.planarized)
    {
      const PVF::Planarization_result& r = q.planarization;
      if(q.planarization_code == PVF::Error_code::SUCCESS && r.gauss_newton_ran)
        std::cout << " -> after " << r.iterations << " local-global iterations (they "
                  << (r.left_surface ? "left the surface" : "failed") << ") and " << r.gauss_newton_steps
                  << " Gauss-Newton steps (" << r.gauss_newton_rejected_steps << " rejected) max " << 100 * q.after.max
                  << "%, mean " << 100 * q.after.mean << "% (threshold " << 100 * r.threshold
                  << "%); largest distance to the surface, its border or creases " << r.max_distance << " ("
                  << 100 * r.max_distance / r.mean_edge_length << "% of the mean quad edge)";
      else if(q.planarization_code == PVF::Error_code::TOO_FAR_FROM_SURFACE && r.left_surface)
        std::cout << "; the planarization stopped after " << r.iterations << " iterations at max "
                  << 100 * r.max_planarity_after << "%, mean " << 100 * r.mean_planarity_after
                  << "%: a vertex was " << r.max_distance << " (" << 100 * r.max_distance / r.mean_edge_length
                  << "% of the mean quad edge) from the surface, beyond the bound " << r.distance_bound << " ("
                  << 100 * o.max_surface_distance
                  << "%), with the pull towards the surface at its floor: the quad mesh is written as extracted";
      else if(q.planarization_code == PVF::Error_code::TOO_FAR_FROM_SURFACE && r.max_distance <= r.distance_bound)
        std::cout << "; the planarization reached " << 100 * r.max_planarity_after
                  << "% only with quads that no longer covered the surface: a point of it was "
                  << 100 * (r.max_distance_to_quads - r.max_distance_to_quads_before) / r.mean_edge_length
                  << "% of the mean quad edge farther from them than from the quads as extracted, beyond the bound ("
                  << 100 * o.max_surface_distance << "%): the quad mesh is written as extracted";
      else if(q.planarization_code == PVF::Error_code::TOO_FAR_FROM_SURFACE)
        std::cout << "; the planarization reached " << 100 * r.max_planarity_after << "% only by moving a vertex "
                  << r.max_distance << " (" << 100 * r.max_distance / r.mean_edge_length
                  << "% of the mean quad edge) from the surface, beyond the bound " << r.distance_bound << " ("
                  << 100 * o.max_surface_distance << "%): the quad mesh is written as extracted";
      else if(q.planarization_code == PVF::Error_code::FOLDED_QUAD)
        std::cout << "; the planarization reached " << 100 * r.max_planarity_after << "% only by folding "
                  << r.folded_quads << " quad(s): the quad mesh is written as extracted";
      else if(r.converged)
        std::cout << " -> after " << r.iterations << " iterations max " << 100 * q.after.max << "%, mean "
                  << 100 * q.after.mean << "% (threshold " << 100 * r.threshold << "%); largest distance to the surface, its border or creases "
                  << r.max_distance << " (" << 100 * r.max_distance / r.mean_edge_length << "% of the mean quad edge)";
      else
        std::cout << "; the planarization did NOT reach " << 100 * r.threshold << "% in " << r.iterations
                  << " iterations (it got to max " << 100 * r.max_planarity_after << "%, mean "
                  << 100 * r.mean_planarity_after << "%): the quad mesh is written as extracted";
      if(q.planarization_code != PVF::Error_code::SUCCESS && r.gauss_newton_ran)
      {
        std::cout << "; then " << r.gauss_newton_steps << " Gauss-Newton steps (" << r.gauss_newton_rejected_steps
                  << " rejected) got to max " << 100 * r.gauss_newton_max_planarity << "% with a vertex "
                  << 100 * r.gauss_newton_max_distance / r.mean_edge_length << "% of the mean quad edge away";
        if(r.gauss_newton_max_planarity <= r.threshold && r.gauss_newton_max_distance <= r.distance_bound &&
           r.gauss_newton_max_distance_to_quads > r.max_distance_to_quads_before + r.distance_bound)
          std::cout << ", but with quads that no longer covered the surface (a point of it "
                    << 100 * (r.gauss_newton_max_distance_to_quads - r.max_distance_to_quads_before) / r.mean_edge_length
                    << "% of the mean quad edge farther from them than from the quads as extracted)";
        if(r.gauss_newton_stalled)
          std::cout << " (they stopped: three steps made no progress)";
      }
    }
    std::cout << "\n";
  }
  std::cout << "time (s)       ";
  for(const char* stage : { "load mesh", "refinement", "frames and connection", "constraints", "curvature", "design", "frame field",
                            "roots", "singularities", "diagnostics", "parametrization", "quad mesh", "planarization",
                            "write" })
    if(clock.times.count(stage))
      std::cout << " " << stage << " " << std::fixed << std::setprecision(3) << clock.times.at(stage) << ";";
  std::cout << " (design: assembly " << field.statistics.assembly << ", factorization " << field.statistics.factorization
            << ", solve " << field.statistics.solve << ")\n";
  if(!written)
  {
    std::cout << "wrote           nothing: the quad mesh could not be made (the error follows)\n";
    return;
  }
  for(const std::string& out : outputs.destinations())
    std::cout << "wrote           " << out << "\n";
}

} // namespace pvf_cli

#endif // PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_SUMMARY_H
