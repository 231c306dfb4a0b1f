// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// Quad extraction on a Chart_mesh, step by step: transitions and fans,
// fold-over repair, integer points, iso-line tracing, cells, output mesh.
// Written from Ebke, Bommes, Campen, Kobbelt 2013 (QEx), not from its code.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_EXTRACT_FROM_CHART_MESH_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_EXTRACT_FROM_CHART_MESH_H

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/Chart_mesh.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/Extractor.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/fold_over_repair.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/quad_cells.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/trimmed_boundary.h>
#include <CGAL/Polyvector_fields/parameters.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#ifdef CGAL_PVF_QEX_DEBUG
#include <iostream>
#endif
#include <string>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {
namespace qex {

typedef std::chrono::steady_clock Clock;
inline double seconds(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The transitions (found from the uv, or given and checked) and the vertex fans.
inline Error_code transitions_and_fans(Chart_mesh& M, bool given_transitions, std::string* diagnostic)
{
  Error_code code = given_transitions ? check_transitions(M) : compute_transitions(M);
  if(code != Error_code::SUCCESS)
  {
    if(diagnostic)
      *diagnostic = given_transitions ? "an interior edge whose two charts are not related by the map's transition"
                                      : "an interior edge whose two charts are not related by a grid symmetry";
    return code;
  }
  code = build_fans(M);
  if(code != Error_code::SUCCESS && diagnostic)
    *diagnostic = "a non-manifold vertex";
  return code;
}

template <typename Report>
Error_code repair_and_count_seams(Chart_mesh& M, bool given_transitions, std::size_t rings, Report& result)
{
  Fold_over_result fo;
  Error_code code = repair_fold_overs(M, rings, fo);
  if(code != Error_code::SUCCESS)
    result.diagnostic = fo.remaining ? "fold-overs left after the repair: " + std::to_string(fo.remaining) +
                                         " triangles still fold after re-embedding up to " + std::to_string(rings) +
                                         " rings around the " + std::to_string(fo.flipped_faces) +
                                         " that folded in the map"
                                     : "every triangle has zero uv area";
  result.flipped_faces = fo.flipped_faces;
  result.degenerate_uv_faces = fo.degenerate_faces;
  result.repaired_regions = fo.regions;
  result.repaired_vertices = fo.moved_vertices;
  result.repair_rings = fo.rings_used;
  if(code != Error_code::SUCCESS && code != Error_code::UNREPAIRABLE_FOLD_OVER)
    return code;
  if(fo.flipped_faces != 0)
  {
    // the repair keeps the transitions; check them again
    const Error_code checked = transitions_and_fans(M, given_transitions, nullptr);
    if(checked != Error_code::SUCCESS)
      return checked;
  }
  {
    std::size_t seams = 0;
    for(std::size_t e = 0; e < 3 * M.F; ++e)
      if(M.opp[e] != npos && M.opp[e] > e && !(M.trans[e] == Grid_map()))
        ++seams;
    result.seam_edges = seams;
  }
  result.degenerate_uv_edges = M.degenerate_uv_edges;
  return code;  // UNREPAIRABLE_FOLD_OVER: what is left may still be cut out
}

// Integer points, their slots, and the check that every other interior vertex is regular.
template <typename Report>
Error_code find_integer_points(const Chart_mesh& M, Extractor& X, Report& result)
{
  X.enumerate_points();
  X.create_slots();
  // every interior vertex that is not an integer point must be regular (4 directions);
  // a vertex with no incident face (empty fan) has no directions and no say in the quads
  {
    std::vector<int> dirs;
    for(std::size_t v = 0; v < M.V; ++v)
    {
      if(M.border_vertex[v] || X.vertex_point[v] != npos || M.fan[v].empty())
        continue;
      std::size_t n = 0;
      for(std::size_t c : M.fan[v])
      {
        sector_directions(M, c, false, dirs);
        n += dirs.size();
      }
      if(n != 4)
      {
        result.diagnostic = "a vertex of non-zero index off the integer grid (vertex " + std::to_string(v) + ", " +
                            std::to_string(n) + " directions)";
        return Error_code::NOT_AN_INTEGER_GRID_MAP;
      }
    }
  }
  for(const Qpoint& p : X.points)
  {
    ++result.integer_points;
    result.points_at_vertices += p.loc == AT_VERTEX;
    result.points_on_edges += p.loc == ON_EDGE;
    result.points_in_faces += p.loc == IN_FACE;
    if(!p.border && p.slots.size() != 4)
      ++result.singular_points;
  }
  return Error_code::SUCCESS;
}

// Traces every slot; ends[s] is where the trace of slot s ended.
template <typename Report>
Error_code trace_iso_lines(Extractor& X, bool trimmed, std::vector<Trace_end>& ends, Report& result)
{
  const std::size_t iso_slots = X.slots.size();
  ends.assign(iso_slots, Trace_end());
  for(std::size_t s = 0; s < iso_slots; ++s)
  {
    if(trimmed && X.along_border(X.slots[s].face, X.slots[s].dir, X.slots[s].start))
    {
      X.slots[s].state = 3;  // replaced by a boundary piece
      continue;
    }
    ends[s] = X.trace(X.slots[s]);
    result.triangle_crossings += ends[s].crossings;
    ++result.traced_half_edges;
    if(ends[s].error)
    {
      ++result.inconsistencies;
      result.diagnostic = "a trace met an impossible configuration (slot " + std::to_string(s) + ")";
      return Error_code::NOT_AN_INTEGER_GRID_MAP;
    }
    if(!ends[s].complete)
    {
      ++result.boundary_traces;
      X.slots[s].state = 2;
      continue;
    }
    const std::size_t p = X.lookup_point(ends[s].face, ends[s].q, X.classify(ends[s].face, ends[s].q));
    const std::size_t back = p == npos ? npos : X.find_slot(p, ends[s].face, (ends[s].dir + 2) & 3);
    if(back == npos)
    {
      ++result.inconsistencies;
      result.diagnostic = std::string("a trace ended at no known point or direction (") + (p == npos ? "point" : "direction") + ")";
      X.slots[s].state = 2;
      continue;
    }
    X.slots[s].state = 1;
    X.slots[s].partner = back;
  }
  for(std::size_t s = 0; s < iso_slots; ++s)
    if(X.slots[s].state == 1 && X.slots[X.slots[s].partner].partner != s)
    {
      ++result.inconsistencies;
      result.diagnostic = "two traces of one iso-line do not pair up";
#ifdef CGAL_PVF_QEX_DEBUG
      {
        auto show = [&](std::size_t x) {
          const Slot& S = X.slots[x];
          const Qpoint& P = X.points[S.point];
          std::cerr << "  slot " << x << " point " << S.point << " loc " << P.loc << " elem " << P.elem << " uv " << P.uv[0] << "," << P.uv[1]
                    << " face " << S.face << " dir " << S.dir << " start " << S.start[0] << "," << S.start[1] << " state " << S.state
                    << " partner " << S.partner << " nslots " << P.slots.size() << "\n";
        };
        std::cerr << "mismatch:\n";
        show(s);
        show(X.slots[s].partner);
        if(X.slots[X.slots[s].partner].partner != npos) show(X.slots[X.slots[s].partner].partner);
        std::cerr << "  end face " << ends[s].face << " q " << ends[s].q[0] << "," << ends[s].q[1] << " dir " << ends[s].dir << "\n";
      }
#endif
    }
  if(result.inconsistencies != 0)
    return Error_code::NOT_AN_INTEGER_GRID_MAP;

  return Error_code::SUCCESS;
}

// Everything after the chart mesh is read, with the named parameters of
// extract_quad_mesh() in np: `result` is a Quad_extraction_result; setup_start
// is when the setup began (its time includes reading the charts). With
// `parallel`, the independent queries are shared among threads (same result).
template <typename NamedParameters, typename PolygonMesh, typename NamedParametersOut, typename Report>
Error_code extract_from_chart_mesh(Chart_mesh& M, bool given_transitions, bool parallel, const NamedParameters& np,
                                   PolygonMesh& quad_mesh, const NamedParametersOut& np_out, Report& result,
                                   Clock::time_point setup_start)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const bool trimmed = choose_parameter(get_parameter(np, internal_np::keep_trimmed_boundary), false);
  const std::size_t rings = choose_parameter(get_parameter(np, internal_np::fold_over_repair_rings), std::size_t(6));
  const bool fill = choose_parameter(get_parameter(np, internal_np::fill_fold_overs), true);
  Error_code code = transitions_and_fans(M, given_transitions, &result.diagnostic);
  if(code != Error_code::SUCCESS)
    return code;
  result.time_setup = seconds(setup_start);
  auto t = Clock::now();
  code = repair_and_count_seams(M, given_transitions, rings, result);
  // what the repair leaves is cut out, and the holes in the quads are filled (whole cells only)
  Fold_over_cut cut;
  Chart_mesh S;
  const bool cut_out = code == Error_code::UNREPAIRABLE_FOLD_OVER && fill && !trimmed && rings > 0 &&
                       result.flipped_faces != 0 && cut_out_fold_overs(M, cut, S);
  if(code != Error_code::SUCCESS && !cut_out)
    return code;
  if(cut_out)
  {
    result.cut_faces = std::size_t(std::count(cut.removed.begin(), cut.removed.end(), char(1)));
    result.diagnostic.clear();
  }
  const Chart_mesh& W = cut_out ? S : M;
  result.time_repair = seconds(t);
  t = Clock::now();
  Extractor X(W, trimmed);
  code = find_integer_points(W, X, result);
  if(code != Error_code::SUCCESS)
    return code;
  result.time_points = seconds(t);
  t = Clock::now();
  std::vector<Trace_end> ends;
  code = trace_iso_lines(X, trimmed, ends, result);
  if(code == Error_code::SUCCESS && trimmed)
    code = close_trimmed_boundary(M, X, ends, ends.size(), result);
  if(code != Error_code::SUCCESS)
    return code;
  result.time_tracing = seconds(t);
  t = Clock::now();
  Cells cells;
  collect_cells(X, trimmed, cells, result);
  result.time_faces = seconds(t);
  t = Clock::now();
  Quad_mesh_settings settings;
  settings.rings = 2 * rings;
  settings.repair_folds = rings > 0;
  settings.fill = fill;
  settings.split_small = choose_parameter(get_parameter(np, internal_np::split_components_without_cells), false);
  settings.tip_distance = choose_parameter(get_parameter(np, internal_np::tip_snapping_distance), 0.3);
  settings.max_distance = choose_parameter(get_parameter(np, internal_np::max_input_distance), 0.0);
  settings.parallel = parallel;
  code = build_quad_mesh(M, W, cut_out ? &cut : nullptr, X, cells, ends, settings, quad_mesh, np_out, result);
  if(code != Error_code::SUCCESS)
    return code;
  result.time_output = seconds(t);
  return Error_code::SUCCESS;
}

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_EXTRACT_FROM_CHART_MESH_H
