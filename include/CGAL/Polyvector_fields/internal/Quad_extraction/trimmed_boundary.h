// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The trimmed mode of quad extraction (keep_trimmed_boundary): the points
// where iso-lines leave the surface, the border vertices, and the boundary
// pieces between them, so that the cells cut by the boundary close up.
// Written from Ebke, Bommes, Campen, Kobbelt 2013 (QEx), not from its code.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_TRIMMED_BOUNDARY_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_TRIMMED_BOUNDARY_H

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/Chart_mesh.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/Extractor.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {
namespace qex {

// Turns the traces that left the surface (ends[s], s < iso_slots) into points
// on the boundary and joins the boundary points by boundary pieces.
// `result` is a Quad_extraction_result.
template <typename Report>
Error_code close_trimmed_boundary(const Chart_mesh& M, Extractor& X, const std::vector<Trace_end>& ends,
                                  std::size_t iso_slots, Report& result)
{
  // boundary hits become points, with the iso-line slot pointing back inside
  std::map<std::pair<std::size_t, CGAL::Exact_rational>, std::size_t> edge_hits;
  std::vector<std::size_t> hit_point(iso_slots, npos);
  for(std::size_t s = 0; s < iso_slots; ++s)
  {
    if(X.slots[s].state != 2)
      continue;
    const Trace_end& E = ends[s];
    std::size_t p = npos;
    if(E.hit_corner != npos)
    {
      p = X.border_vertex_point(M.vertex[E.hit_corner]);
    }
    else
    {
      // iso-line through q in direction d meets border edge e = (A, B): exact parameter
      const std::size_t e = E.hit_edge;
      const P2 &A = M.uv[e], &B = M.uv[Chart_mesh::next(e)];
      const int coord = (E.dir & 1) ? 0 : 1;  // the constant coordinate of the line
      const CGAL::Exact_rational lam = (CGAL::Exact_rational(E.q[coord]) - CGAL::Exact_rational(A[coord])) /
                                       (CGAL::Exact_rational(B[coord]) - CGAL::Exact_rational(A[coord]));
      auto key = std::make_pair(e, lam);
      auto it = edge_hits.find(key);
      if(it == edge_hits.end())
      {
        Qpoint P;
        P.loc = BOUNDARY_HIT;
        P.elem = e;
        P.lambda = lam;
        P.border = true;
        it = edge_hits.emplace(key, X.points.size()).first;
        X.points.push_back(P);
      }
      p = it->second;
    }
    hit_point[s] = p;
  }
  // iso-line slots at the hits (direction back along the line), paired with their trace
  for(std::size_t s = 0; s < iso_slots; ++s)
  {
    if(hit_point[s] == npos)
      continue;
    const Trace_end& E = ends[s];
    Slot b;
    b.point = hit_point[s];
    b.face = E.face;
    b.dir = (E.dir + 2) & 3;
    if(E.hit_corner != npos)
    {
      // the back direction belongs to one sector around the vertex (same rule as the slots)
      const auto key = X.vertex_rule(M.vertex[E.hit_corner], M.fan_pos[E.hit_corner], b.dir);
      if(key.face == npos)
      {
        ++result.inconsistencies;
        continue;
      }
      b.face = key.face;
      b.dir = key.dir;
    }
    b.state = 1;
    b.partner = s;
    X.slots.push_back(b);
    X.slots[s].state = 1;
    X.slots[s].partner = X.slots.size() - 1;
  }
  // each border vertex and each point on the border: ordered slots, with one boundary
  // slot forward (first) and one backward (last) along the border
  // position key of an iso-line slot around a border vertex: (fan position, order)
  std::vector<std::vector<std::size_t> > hits_on_edge(3 * M.F);
  for(std::size_t p = 0; p < X.points.size(); ++p)
  {
    const Qpoint& P = X.points[p];
    if(P.loc == BOUNDARY_HIT)
      hits_on_edge[P.elem].push_back(p);
    else if(P.loc == ON_EDGE && P.border)
      hits_on_edge[P.elem].push_back(p);
  }
  auto edge_param = [&](std::size_t p) -> CGAL::Exact_rational {
    const Qpoint& P = X.points[p];
    if(P.loc == BOUNDARY_HIT)
      return P.lambda;
    const P2 &A = M.uv[P.elem], &B = M.uv[Chart_mesh::next(P.elem)];
    const int coord = A[0] != B[0] ? 0 : 1;
    return (CGAL::Exact_rational(P.uv[coord]) - CGAL::Exact_rational(A[coord])) /
           (CGAL::Exact_rational(B[coord]) - CGAL::Exact_rational(A[coord]));
  };
  // border vertices that are not points yet become points
  for(std::size_t v = 0; v < M.V; ++v)
    if(M.border_vertex[v])
      X.border_vertex_point(v);
  // rebuild the slot order of every border point: forward boundary, iso-lines ccw, backward boundary
  auto iso_order = [&](std::size_t s) {
    // (fan position, angle order in the sector) of an iso-line slot at a border vertex
    const Slot& S = X.slots[s];
    const Qpoint& P = X.points[S.point];
    const std::size_t c = X.corner_of(S.face, P.elem);
    const std::size_t m = M.fan_pos[c];
    std::vector<int> dirs;
    sector_directions(M, c, m + 1 == M.fan[P.elem].size(), dirs);
    int k = 0;
    for(std::size_t i = 0; i < dirs.size(); ++i)
      if(dirs[i] == S.dir)
        k = int(i);
    return std::make_pair(m, k);
  };
  std::vector<std::size_t> forward_slot(X.points.size(), npos), backward_slot(X.points.size(), npos);
  // collect iso slots per border point (slots with state 1)
  std::vector<std::vector<std::size_t> > iso_of(X.points.size());
  for(std::size_t s = 0; s < X.slots.size(); ++s)
    if(X.slots[s].state == 1 && X.points[X.slots[s].point].border)
      iso_of[X.slots[s].point].push_back(s);
  for(std::size_t p = 0; p < X.points.size(); ++p)
  {
    Qpoint& P = X.points[p];
    if(!P.border)
      continue;
    std::vector<std::size_t>& iso = iso_of[p];
    if(P.loc == AT_VERTEX)
      std::sort(iso.begin(), iso.end(), [&](std::size_t a, std::size_t b) { return iso_order(a) < iso_order(b); });
    else
    {
      // on a border edge (A -> B, face on the left): ccw from +AB
      const std::size_t e = P.elem;
      const P2 &A = M.uv[e], &B = M.uv[Chart_mesh::next(e)];
      int first = 0;
      for(int d = 0; d < 4; ++d)
        if(dot_edge_axis(A, B, d) > 0 && cross_edge_axis(A, B, d) >= 0)
          first = d;
      std::sort(iso.begin(), iso.end(),
                [&](std::size_t a, std::size_t b) { return ((X.slots[a].dir - first) & 3) < ((X.slots[b].dir - first) & 3); });
    }
    Slot fw, bw;
    fw.point = bw.point = p;
    fw.dir = bw.dir = -1;
    fw.state = bw.state = 4;
    X.slots.push_back(fw);
    forward_slot[p] = X.slots.size() - 1;
    X.slots.push_back(bw);
    backward_slot[p] = X.slots.size() - 1;
    P.slots.clear();
    P.slots.push_back(forward_slot[p]);
    for(std::size_t s : iso)
      P.slots.push_back(s);
    P.slots.push_back(backward_slot[p]);
    P.adjacent_next.assign(P.slots.size(), 1);
    P.adjacent_next.back() = 0;
  }
  // boundary pieces: along each border edge, the points in order
  for(std::size_t e = 0; e < 3 * M.F; ++e)
  {
    if(M.opp[e] != npos)
      continue;
    std::vector<std::size_t>& on = hits_on_edge[e];
    std::vector<std::pair<CGAL::Exact_rational, std::size_t> > sorted;
    for(std::size_t p : on)
      sorted.emplace_back(edge_param(p), p);
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::size_t> chain{ X.vertex_point[M.vertex[e]] };
    for(auto& x : sorted)
      chain.push_back(x.second);
    chain.push_back(X.vertex_point[M.vertex[Chart_mesh::next(e)]]);
    for(std::size_t i = 0; i + 1 < chain.size(); ++i)
    {
      const std::size_t a = forward_slot[chain[i]], b = backward_slot[chain[i + 1]];
      X.slots[a].partner = b;
      X.slots[b].partner = a;
      X.slots[a].state = X.slots[b].state = 1;
    }
  }
  for(std::size_t s = 0; s < X.slots.size(); ++s)
    if(X.slots[s].state == 4 || (X.slots[s].state == 1 && X.slots[X.slots[s].partner].partner != s))
      ++result.inconsistencies;
  if(result.inconsistencies != 0)
    return Error_code::NOT_AN_INTEGER_GRID_MAP;
  return Error_code::SUCCESS;
}

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_TRIMMED_BOUNDARY_H
