// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The integer points of an integer-grid map, the iso-line directions leaving
// them (slots) and the exact tracing of the iso-lines between them, on a
// Chart_mesh. Written from Ebke, Bommes, Campen, Kobbelt 2013 (QEx), not from its code.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_EXTRACTOR_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_EXTRACTOR_H

#include <CGAL/Polyvector_fields/internal/Quad_extraction/Chart_mesh.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {
namespace qex {

enum Location { AT_VERTEX, ON_EDGE, IN_FACE, BOUNDARY_HIT };

struct Qpoint
{
  Location loc = IN_FACE;
  std::size_t elem = npos;   // vertex, canonical edge, face; BOUNDARY_HIT: the border edge (npos at a vertex)
  std::size_t vertex = npos; // BOUNDARY_HIT at a mesh vertex
  P2 uv{ 0, 0 };             // IN_FACE / ON_EDGE: in the chart of face(elem)
  CGAL::Exact_rational lambda;  // BOUNDARY_HIT on an edge: parameter from corner elem to next(elem)
  bool border = false;
  std::vector<std::size_t> slots;     // counterclockwise
  std::vector<char> adjacent_next;    // sector from slots[i] to slots[i+1] lies on the surface
};

struct Slot
{
  std::size_t point = npos, face = npos;
  int dir = 0;                 // direction in the chart of `face`; -1: a boundary slot
  P2 start{ 0, 0 };            // the point in the chart of `face`
  std::size_t partner = npos;  // the slot at the other end of the iso-line (or boundary piece)
  int state = 0;               // 0 not traced, 1 complete, 2 leaves the surface
};

struct Trace_end
{
  bool complete = false;
  std::size_t face = npos;  // complete: q lies in face; hit: the face where the trace left
  P2 q{ 0, 0 };
  int dir = 0;
  std::size_t hit_edge = npos, hit_corner = npos;  // hit through a border edge, or at the vertex of a corner
  std::size_t crossings = 0;
  bool error = false;
  std::vector<std::size_t> faces;  // the faces the iso-line went through, in order (the start face first)
};

class Extractor
{
public:
  Extractor(const Chart_mesh& mesh, bool trimmed) : M(mesh), trimmed_(trimmed) {}

  const Chart_mesh& M;
  bool trimmed_;
  std::vector<Qpoint> points;
  std::vector<Slot> slots;
  std::vector<std::size_t> vertex_point;  // per mesh vertex
  std::map<std::tuple<int, std::size_t, double, double>, std::size_t> key_point;
  std::size_t inconsistencies = 0;

  std::size_t canonical_edge(std::size_t e) const { return M.opp[e] == npos ? e : (std::min)(e, M.opp[e]); }

  bool in_closed(std::size_t f, const P2& q) const
  {
    return orientation(M.corner_uv(f, 0), M.corner_uv(f, 1), q) >= 0 && orientation(M.corner_uv(f, 1), M.corner_uv(f, 2), q) >= 0 &&
           orientation(M.corner_uv(f, 2), M.corner_uv(f, 0), q) >= 0;
  }

  // where q (in the closed triangle f) lies: corner k (0..2), edge k (3..5), inside (6)
  int classify(std::size_t f, const P2& q) const
  {
    for(int k = 0; k < 3; ++k)
      if(M.corner_uv(f, std::size_t(k)) == q)
        return k;
    for(int k = 0; k < 3; ++k)
      if(orientation(M.corner_uv(f, std::size_t(k)), M.corner_uv(f, std::size_t(k + 1)), q) == 0)
        return 3 + k;
    return 6;
  }

  // ------------------------------------------------------------------ points
  std::size_t find_or_add_point(std::size_t f, const P2& q, int where)
  {
    if(where < 3)
    {
      const std::size_t v = M.vertex[3 * f + std::size_t(where)];
      if(vertex_point[v] == npos)
      {
        Qpoint p;
        p.loc = AT_VERTEX;
        p.elem = v;
        p.border = M.border_vertex[v];
        vertex_point[v] = points.size();
        points.push_back(p);
      }
      return vertex_point[v];
    }
    if(where < 6)
    {
      const std::size_t e = 3 * f + std::size_t(where - 3), ec = canonical_edge(e);
      const P2 qc = ec == e ? q : M.trans[e](q);
      const auto key = std::make_tuple(1, ec, qc[0], qc[1]);
      auto it = key_point.find(key);
      if(it != key_point.end())
        return it->second;
      Qpoint p;
      p.loc = ON_EDGE;
      p.elem = ec;
      p.uv = qc;
      p.border = M.opp[ec] == npos;
      key_point.emplace(key, points.size());
      points.push_back(p);
      return points.size() - 1;
    }
    const auto key = std::make_tuple(2, f, q[0], q[1]);
    auto it = key_point.find(key);
    if(it != key_point.end())
      return it->second;
    Qpoint p;
    p.loc = IN_FACE;
    p.elem = f;
    p.uv = q;
    key_point.emplace(key, points.size());
    points.push_back(p);
    return points.size() - 1;
  }

  // the point of border vertex v, made if it is not one yet (trimmed mode)
  std::size_t border_vertex_point(std::size_t v)
  {
    if(vertex_point[v] == npos)
    {
      Qpoint p;
      p.loc = AT_VERTEX;
      p.elem = v;
      p.border = true;
      vertex_point[v] = points.size();
      points.push_back(p);
    }
    return vertex_point[v];
  }

  std::size_t lookup_point(std::size_t f, const P2& q, int where) const
  {
    if(where < 3)
      return vertex_point[M.vertex[3 * f + std::size_t(where)]];
    std::tuple<int, std::size_t, double, double> key;
    if(where < 6)
    {
      const std::size_t e = 3 * f + std::size_t(where - 3), ec = canonical_edge(e);
      const P2 qc = ec == e ? q : M.trans[e](q);
      key = std::make_tuple(1, ec, qc[0], qc[1]);
    }
    else
      key = std::make_tuple(2, f, q[0], q[1]);
    auto it = key_point.find(key);
    return it == key_point.end() ? npos : it->second;
  }

  void enumerate_points()
  {
    vertex_point.assign(M.V, npos);
    for(std::size_t f = 0; f < M.F; ++f)
    {
      double lo[2], hi[2];
      for(int a = 0; a < 2; ++a)
      {
        lo[a] = std::ceil((std::min)({ M.corner_uv(f, 0)[a], M.corner_uv(f, 1)[a], M.corner_uv(f, 2)[a] }));
        hi[a] = std::floor((std::max)({ M.corner_uv(f, 0)[a], M.corner_uv(f, 1)[a], M.corner_uv(f, 2)[a] }));
      }
      for(double i = lo[0]; i <= hi[0]; ++i)
        for(double j = lo[1]; j <= hi[1]; ++j)
        {
          const P2 q{ i, j };
          if(in_closed(f, q))
            find_or_add_point(f, q, classify(f, q));
        }
    }
  }

  // ------------------------------------------------------------------ slots
  // The slot of point p for the axis direction d leaving it, given in the chart of
  // face f (a face that holds p): the rule that makes every direction belong to
  // exactly one (face, direction) pair. npos if the direction leaves the surface.
  struct Slot_key { std::size_t face = npos; int dir = 0; int order = 0; };

  // Edge point on canonical edge ec, direction d in the chart of face(ec).
  Slot_key edge_rule(std::size_t ec, int d) const
  {
    const std::size_t f = Chart_mesh::face(ec);
    const P2 &A = M.uv[ec], &B = M.uv[Chart_mesh::next(ec)];
    const int s = cross_edge_axis(A, B, d), dt = dot_edge_axis(A, B, d);
    Slot_key key;
    const std::size_t o = M.opp[ec];
    if(s > 0 || (s == 0 && dt > 0) || (o == npos && s == 0))
      key.face = f, key.dir = d;
    else if(o != npos)
      key.face = Chart_mesh::face(o), key.dir = (d + M.trans[ec].r) & 3;
    return key;
  }

  // Vertex point v, direction d in the chart of face(fan[v][j]), pointing into or next to
  // that sector (an arrival). The direction is carried edge by edge, nearest sectors
  // first (j, j+1, j-1, ...): around a cone the charts do not close up, so a direction
  // is only meaningful near the sector it was given in.
  Slot_key vertex_rule(std::size_t v, std::size_t j, int d) const
  {
    const auto& fan = M.fan[v];
    const std::size_t n = fan.size();
    const bool border = M.border_vertex[v];
    Slot_key key;
    auto test = [&](std::size_t m, int dm) {
      if(in_sector(M, fan[m], dm, border && m + 1 == n))
      {
        key.face = Chart_mesh::face(fan[m]);
        key.dir = dm;
        return true;
      }
      return false;
    };
    if(test(j, d))
      return key;
    int dccw = d, dcw = d;
    std::size_t mccw = j, mcw = j;
    for(std::size_t k = 1; k <= n; ++k)
    {
      // one step counterclockwise: across the edge prev(corner)
      if(!(border && mccw + 1 == n))
      {
        dccw = (dccw + M.trans[Chart_mesh::prev(fan[mccw])].r) & 3;
        mccw = (mccw + 1) % n;
        if(test(mccw, dccw))
          return key;
      }
      // one step clockwise: across the edge of the corner
      if(!(border && mcw == 0))
      {
        dcw = (dcw + M.trans[fan[mcw]].r) & 3;
        mcw = (mcw + n - 1) % n;
        if(test(mcw, dcw))
          return key;
      }
    }
    return key;
  }

  std::size_t corner_of(std::size_t f, std::size_t v) const
  {
    for(std::size_t k = 0; k < 3; ++k)
      if(M.vertex[3 * f + k] == v)
        return 3 * f + k;
    return npos;
  }

  // the slot of point p leaving in direction d (chart of face f)
  std::size_t find_slot(std::size_t p, std::size_t f, int d) const
  {
    const Qpoint& P = points[p];
    Slot_key key;
    if(P.loc == IN_FACE)
      key.face = f, key.dir = d;
    else if(P.loc == ON_EDGE)
    {
      const std::size_t ec = P.elem, fc = Chart_mesh::face(ec);
      int dc = d;
      if(f != fc)
        dc = (d + M.trans[M.opp[ec]].r) & 3;
      key = edge_rule(ec, dc);
    }
    else if(P.loc == AT_VERTEX)
    {
      const std::size_t c = corner_of(f, P.elem);
      if(c == npos)
        return npos;
      key = vertex_rule(P.elem, M.fan_pos[c], d);
    }
    if(key.face == npos)
      return npos;
    for(std::size_t s : P.slots)
      if(slots[s].face == key.face && slots[s].dir == key.dir)
        return s;
    return npos;
  }

  std::size_t add_slot(std::size_t p, std::size_t f, int d, const P2& start)
  {
    Slot s;
    s.point = p;
    s.face = f;
    s.dir = d;
    s.start = start;
    slots.push_back(s);
    points[p].slots.push_back(slots.size() - 1);
    return slots.size() - 1;
  }

  // in trimmed mode, iso-lines along a border edge are left to the boundary pieces
  bool along_border(std::size_t f, int d, const P2& start) const
  {
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t e = 3 * f + k;
      if(M.opp[e] != npos)
        continue;
      const P2 &A = M.uv[e], &B = M.uv[Chart_mesh::next(e)];
      if(cross_edge_axis(A, B, d) == 0 && orientation(A, B, start) == 0)
        return true;
    }
    return false;
  }

  void create_slots()
  {
    std::vector<int> dirs;
    for(std::size_t p = 0; p < points.size(); ++p)
    {
      Qpoint& P = points[p];
      if(P.loc == IN_FACE)
      {
        for(int d = 0; d < 4; ++d)
          add_slot(p, P.elem, d, P.uv);
        P.adjacent_next.assign(4, 1);
      }
      else if(P.loc == ON_EDGE)
      {
        const std::size_t ec = P.elem, f = Chart_mesh::face(ec);
        const P2 &A = M.uv[ec], &B = M.uv[Chart_mesh::next(ec)];
        int first = 0;
        for(int d = 0; d < 4; ++d)
          if(dot_edge_axis(A, B, d) > 0 && cross_edge_axis(A, B, d) >= 0)
            first = d;
        const bool border = M.opp[ec] == npos;
        for(int k = 0; k < 4; ++k)
        {
          const int d = (first + k) & 3;
          if(border && cross_edge_axis(A, B, d) < 0)
            continue;
          const Slot_key key = edge_rule(ec, d);
          const P2 start = key.face == f ? P.uv : M.trans[ec](P.uv);
          add_slot(p, key.face, key.dir, start);
        }
        P.adjacent_next.assign(P.slots.size(), 1);
        if(border)
          P.adjacent_next.back() = 0;
      }
      else if(P.loc == AT_VERTEX)
      {
        const std::size_t v = P.elem;
        const auto& fan = M.fan[v];
        for(std::size_t m = 0; m < fan.size(); ++m)
        {
          sector_directions(M, fan[m], M.border_vertex[v] && m + 1 == fan.size(), dirs);
          for(int d : dirs)
            add_slot(p, Chart_mesh::face(fan[m]), d, M.uv[fan[m]]);
        }
        P.adjacent_next.assign(P.slots.size(), 1);
        if(M.border_vertex[v] && !P.slots.empty())
          P.adjacent_next.back() = 0;
      }
    }
  }

  // ------------------------------------------------------------------ tracing
  // side of corner uv P with respect to the iso-line through q in direction d: +1 left
  static int side(int d, const P2& P, const P2& q)
  {
    switch(d & 3)
    {
      case 0: return sgn_cmp(P[1], q[1]);
      case 1: return sgn_cmp(q[0], P[0]);
      case 2: return sgn_cmp(q[1], P[1]);
      default: return sgn_cmp(P[0], q[0]);
    }
  }

  // Follows the iso-line from the slot's point to q = start + length axis(d), through
  // the triangles and across the edges by the exact transitions. Only exact tests:
  // comparisons of uv coordinates with integers and orientation predicates. A length
  // below 1 finds a point inside an iso-line segment (see split_wrapping_cells.h).
  Trace_end trace(const Slot& s, double length = 1) const
  {
    Trace_end out;
    std::size_t f = s.face;
    int d = s.dir;
    const P2 a = axis(d);
    P2 q{ s.start[0] + length * a[0], s.start[1] + length * a[1] };
    for(std::size_t step = 0; step < 100000; ++step)
    {
      ++out.crossings;
      if(out.faces.empty() || out.faces.back() != f)
        out.faces.push_back(f);
      if(in_closed(f, q))
      {
        out.complete = true;
        out.face = f;
        out.q = q;
        out.dir = d;
        return out;
      }
      int sg[3];
      for(std::size_t k = 0; k < 3; ++k)
        sg[k] = side(d, M.corner_uv(f, k), q);
      int exit_edge = -1, exit_corner = -1;
      for(int k = 0; k < 3; ++k)
      {
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        if(sg[k] < 0 && sg[k1] > 0)
          exit_edge = k;
        if(sg[k] == 0 && sg[k1] > 0 && sg[k2] < 0)
          exit_corner = k;
        if(sg[k] == 0 && sg[k1] == 0)
        {
          // along edge k: the forward corner
          const int c = dot_edge_axis(M.corner_uv(f, std::size_t(k)), M.corner_uv(f, std::size_t(k1)), d);
          exit_corner = c > 0 ? k1 : k;
        }
      }
      if((exit_edge >= 0) == (exit_corner >= 0))
      {
        out.error = true;
        return out;
      }
      if(exit_edge >= 0)
      {
        const std::size_t e = 3 * f + std::size_t(exit_edge);
        if(M.opp[e] == npos)
        {
          out.face = f;
          out.q = q;
          out.dir = d;
          out.hit_edge = e;
          return out;
        }
        const Grid_map& T = M.trans[e];
        q = T(q);
        d = (d + T.r) & 3;
        f = Chart_mesh::face(M.opp[e]);
        continue;
      }
      // through the vertex of corner c: the sector beyond it, around the vertex
      const std::size_t c = 3 * f + std::size_t(exit_corner), v = M.vertex[c];
      const std::size_t j = M.fan_pos[c];
      const auto& fan = M.fan[v];
      const int d0 = (d - M.fan_map[v][j].r) & 3;
      std::size_t found = npos;
      int dm = 0;
      for(std::size_t m = 0; m < fan.size(); ++m)
      {
        if(m == j)
          continue;
        const int dd = (d0 + M.fan_map[v][m].r) & 3;
        if(in_sector(M, fan[m], dd, M.border_vertex[v] && m + 1 == fan.size()))
        {
          if(found != npos)
          {
            out.error = true;  // two sectors: a cone off the integer grid
            return out;
          }
          found = m;
          dm = dd;
        }
      }
      bool stop = found == npos;
      if(!stop && trimmed_ && M.border_vertex[v])
      {
        // in trimmed mode, stop where the iso-line would run along the border
        const std::size_t cm = fan[found];
        const bool first_along = found == 0 && cross_edge_axis(M.uv[cm], M.uv[Chart_mesh::next(cm)], dm) == 0;
        const bool last_along = found + 1 == fan.size() && cross_edge_axis(M.uv[cm], M.uv[Chart_mesh::prev(cm)], dm) == 0;
        stop = first_along || last_along;
      }
      if(stop)
      {
        out.face = f;
        out.q = q;
        out.dir = d;
        out.hit_corner = c;
        return out;
      }
      const Grid_map T = compose(M.fan_map[v][found], inverse(M.fan_map[v][j]));
      q = T(q);
      d = dm;
      f = Chart_mesh::face(fan[found]);
    }
    out.error = true;
    return out;
  }
};

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_EXTRACTOR_H
