// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// Quad-mesh extraction from a seamless integer-grid map,
// after Ebke, Bommes, Campen, Kobbelt 2013 (QEx). Written from the paper only.

#ifndef CGAL_POLYVECTOR_FIELDS_EXTRACT_QUAD_MESH_H
#define CGAL_POLYVECTOR_FIELDS_EXTRACT_QUAD_MESH_H

/// \file extract_quad_mesh.h
/// The quad mesh of an integer-grid map: its vertices are the integer points of
/// the map, its edges the integer iso-lines between them.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/qex_chart_mesh.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <chrono>
#ifdef CGAL_PVF_QEX_DEBUG
#include <iostream>
#endif
#include <string>
#include <map>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>


namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// reports on a run of `extract_quad_mesh()`.
struct Quad_extraction_result
{
  // input map
  std::size_t flipped_faces = 0;          ///< triangles with det(uv) <= 0 in the input map (fold-overs)
  std::size_t degenerate_uv_faces = 0;    ///< of which det(uv) == 0
  std::size_t repaired_regions = 0;       ///< fold-over regions re-embedded
  std::size_t repaired_vertices = 0;      ///< vertices whose uv the repair moved
  std::size_t repair_rings = 0;           ///< largest ring count the repair needed
  std::size_t seam_edges = 0;             ///< interior edges with a non-identity transition
  std::size_t degenerate_uv_edges = 0;    ///< interior edges of zero uv length
  // integer points and iso-lines
  std::size_t integer_points = 0;         ///< integer points of the map (in vertices, on edges, in faces)
  std::size_t points_at_vertices = 0;     ///< of which at mesh vertices
  std::size_t points_on_edges = 0;        ///< of which inside mesh edges
  std::size_t points_in_faces = 0;        ///< of which inside faces
  std::size_t singular_points = 0;        ///< interior integer points whose valence in the map is not 4
  std::size_t traced_half_edges = 0;      ///< iso-line traces (one per direction leaving an integer point)
  std::size_t boundary_traces = 0;        ///< traces that leave the surface before the next integer point
  std::size_t triangle_crossings = 0;     ///< triangles entered by all traces
  // output
  std::size_t vertices = 0;               ///< vertices of the output
  std::size_t faces = 0;                  ///< faces of the output
  std::size_t quads = 0;                  ///< of which whole cells (quads)
  std::size_t trimmed_polygons = 0;       ///< of which cells trimmed by the boundary (with `keep_trimmed_boundary`)
  std::size_t discarded_cells = 0;        ///< boundary cells dropped (whole-cell mode)
  std::size_t non_quad_cells = 0;         ///< closed cells with other than 4 corners (dropped; expected 0)
  std::size_t split_vertices = 0;         ///< vertices duplicated because their kept faces formed several fans
  std::size_t irregular_vertices = 0;     ///< interior output vertices of valence != 4
  std::size_t inconsistencies = 0;        ///< internal checks that failed (expected 0)
  std::string diagnostic;                 ///< on failure: which check failed
  // times in seconds
  double time_setup = 0;    ///< charts, transitions and vertex fans
  double time_repair = 0;   ///< fold-over repair and the checks after it
  double time_points = 0;   ///< integer points and their iso-line directions
  double time_tracing = 0;  ///< iso-line tracing
  double time_faces = 0;    ///< cells
  double time_output = 0;   ///< positions and the output mesh
  double time_total = 0;  ///< the whole call
};

namespace internal {
namespace qex {

// Empties the output mesh. A Surface_mesh keeps its property maps (the caller's
// vertex point map of np_out may be one of them); other meshes use CGAL::clear().
template <typename G, typename = void>
struct Has_clear_keeping_maps : std::false_type {};
template <typename G>
struct Has_clear_keeping_maps<G, std::void_t<decltype(std::declval<G&>().clear_without_removing_property_maps())> >
  : std::true_type {};
template <typename PolygonMesh>
void clear_output(PolygonMesh& pm)
{
  if constexpr(Has_clear_keeping_maps<PolygonMesh>::value)
    pm.clear_without_removing_property_maps();
  else
    CGAL::clear(pm);
}

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

  // Follows the iso-line from the slot's point to q = start + axis(d), through the
  // triangles and across the edges by the exact transitions. Only exact tests:
  // comparisons of uv coordinates with integers and orientation predicates.
  Trace_end trace(const Slot& s) const
  {
    Trace_end out;
    std::size_t f = s.face;
    int d = s.dir;
    const P2 a = axis(d);
    P2 q{ s.start[0] + a[0], s.start[1] + a[1] };
    for(std::size_t step = 0; step < 100000; ++step)
    {
      ++out.crossings;
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

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// extracts the quad mesh of the integer-grid map `uv_map` of the triangle mesh
/// `tm` (after QEx, Ebke et al. 2013): one vertex per integer point of the map,
/// one edge per integer iso-line segment between two of them, one face per cell.
///
/// <b>Map.</b> `uv_map[h]` is the uv of `target(h)` inside `face(h)`. Across every
/// interior edge the two charts must be related exactly (in floating point) by
/// `uv_B = R^r uv_A + t`, `R` the quarter turn and `t` integer, and every vertex of
/// non-zero index must be on an integer point: what `compute_integer_grid_map()` writes.
///
/// <b>Exactness.</b> The transitions are found and checked exactly; integer points,
/// iso-line/edge crossings and point-in-triangle tests are decided by exact
/// comparisons and orientation predicates on the uv values; a point on an edge or
/// at a vertex is one point for all the triangles around it (found through the mesh
/// connectivity, never by distance). Positions: barycentric coordinates computed
/// in exact rationals, rounded once.
///
/// <b>Singular vertices.</b> A vertex whose uv angles sum to `(4 - k) pi/2` has
/// `4 - k` iso-line directions, hence valence `4 - k` in the output.
///
/// <b>Boundary.</b> By default only whole cells are kept (all quads). With
/// `keep_trimmed_boundary(true)`, the cells cut by the boundary become polygons
/// bounded by the iso-lines and by the mesh boundary (through its vertices).
///
/// <b>Fold-overs.</b> Triangles with `det <= 0` are repaired before extraction:
/// they and up to `fold_over_repair_rings` rings around them are re-embedded
/// (Tutte, ring boundary fixed, exact transitions). Reported in `result`.
///
/// All computations are done in `double` (and exact rationals where stated),
/// whatever the kernels of `tm` and `quad_mesh`.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph` whose faces are triangles
/// \tparam UVMap a model of `ReadablePropertyMap` from halfedges of `tm` to a 2D point (with `x()` and `y()`)
///         or to a pair of numbers indexed by `[0]` and `[1]` (`std::array<double, 2>`), as written by
///         `compute_integer_grid_map()`: the value at `target(h)` inside `face(h)`
/// \tparam PolygonMesh a model of `MutableFaceGraph` (the output)
///
/// \param tm the triangle mesh
/// \param uv_map the integer-grid map
/// \param quad_mesh receives the quad mesh (cleared first), on success only
/// \param result receives the counts, the diagnostic and the times (also on failure, as far as they were computed)
/// \param np an optional sequence of named parameters for `tm`, among the ones listed below
/// \param np_out an optional sequence of named parameters for `quad_mesh`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{keep_trimmed_boundary}
///     \cgalParamDescription{keep the cells cut by the mesh boundary as polygons bounded by the iso-lines and
///                           the boundary (through its vertices); given with
///                           `Polyvector_fields::parameters::keep_trimmed_boundary()`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`: whole cells only, so that every face is a quad}
///   \cgalParamNEnd
///   \cgalParamNBegin{fold_over_repair_rings}
///     \cgalParamDescription{the largest number of vertex rings around a fold-over that its repair may
///                           re-embed (0: no repair); given with `Polyvector_fields::parameters::fold_over_repair_rings()`}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{6}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// The named parameters of `np_out`:
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `quad_mesh`}
///     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<PolygonMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` (constructible from three `double`) as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, quad_mesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::SUCCESS`; `EMPTY_MESH`; `NON_TRIANGLE_FACE`; `DEGENERATE_FACE` (a face with a repeated
///          vertex) or `NON_MANIFOLD_MESH` (a vertex whose faces do not form one fan); `NON_FINITE_VALUE` (a
///          coordinate or a uv value); `NOT_AN_INTEGER_GRID_MAP` (no face of positive uv area, a transition
///          that is not a grid symmetry, a vertex of non-zero index off the integer grid, or traces that do not
///          close up: see `result.diagnostic`); `UNREPAIRABLE_FOLD_OVER`. `quad_mesh` is written only on
///          success; `tm` is never changed.
///
/// \sa `compute_integer_grid_map()`, `quad_planarity()`, `planarize_quad_mesh()`, `IO::write_quad_mesh_VTK()`
template <typename TriangleMesh, typename UVMap, typename PolygonMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename NamedParametersOut = CGAL::parameters::Default_named_parameters>
Error_code extract_quad_mesh(const TriangleMesh& tm, UVMap uv_map, PolygonMesh& quad_mesh, Quad_extraction_result& result,
                             const NamedParameters& np = CGAL::parameters::default_values(),
                             const NamedParametersOut& np_out = CGAL::parameters::default_values())
{
  using namespace internal::qex;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef std::chrono::steady_clock Clock;
  auto seconds = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const auto start = Clock::now();
  result = Quad_extraction_result();

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    CGAL::get_const_property_map(CGAL::vertex_point, tm));
  const bool trimmed = choose_parameter(get_parameter(np, internal_np::keep_trimmed_boundary), false);
  const std::size_t rings = choose_parameter(get_parameter(np, internal_np::fold_over_repair_rings), std::size_t(6));

  // ---- charts, transitions, fans
  auto t = Clock::now();
  Chart_mesh M;
  Error_code code = build_chart_mesh(tm, vpm, uv_map, M);
  if(code != Error_code::SUCCESS)
    return code;
  code = compute_transitions(M);
  if(code != Error_code::SUCCESS)
  {
    result.diagnostic = "an interior edge whose two charts are not related by a grid symmetry";
    return code;
  }
  code = build_fans(M);
  if(code != Error_code::SUCCESS)
  {
    result.diagnostic = "a non-manifold vertex";
    return code;
  }
  result.time_setup = seconds(t);

  // ---- fold-overs
  t = Clock::now();
  Fold_over_report fo;
  code = repair_fold_overs(M, rings, fo);
  if(code != Error_code::SUCCESS)
    result.diagnostic = fo.remaining ? "fold-overs left after the repair" : "every triangle has zero uv area";
  result.flipped_faces = fo.flipped_faces;
  result.degenerate_uv_faces = fo.degenerate_faces;
  result.repaired_regions = fo.regions;
  result.repaired_vertices = fo.moved_vertices;
  result.repair_rings = fo.rings_used;
  if(code != Error_code::SUCCESS)
    return code;
  if(fo.flipped_faces != 0)
  {
    // the repair keeps the transitions; check them again
    code = compute_transitions(M);
    if(code != Error_code::SUCCESS)
      return code;
    code = build_fans(M);
    if(code != Error_code::SUCCESS)
      return code;
  }
  {
    std::size_t seams = 0;
    for(std::size_t e = 0; e < 3 * M.F; ++e)
      if(M.opp[e] != npos && M.opp[e] > e && !(M.trans[e] == Grid_map()))
        ++seams;
    result.seam_edges = seams;
  }
  result.degenerate_uv_edges = M.degenerate_uv_edges;
  result.time_repair = seconds(t);

  // ---- integer points and their directions
  t = Clock::now();
  Extractor X(M, trimmed);
  X.enumerate_points();
  X.create_slots();
  // every interior vertex that is not an integer point must be regular (4 directions)
  {
    std::vector<int> dirs;
    for(std::size_t v = 0; v < M.V; ++v)
    {
      if(M.border_vertex[v] || X.vertex_point[v] != npos)
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
  result.time_points = seconds(t);

  // ---- trace every direction
  t = Clock::now();
  const std::size_t iso_slots = X.slots.size();
  std::vector<Trace_end> ends(iso_slots);
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

  // ---- trimmed mode: boundary points and boundary pieces
  if(trimmed)
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
        const std::size_t v = M.vertex[E.hit_corner];
        if(X.vertex_point[v] == npos)
        {
          Qpoint P;
          P.loc = AT_VERTEX;
          P.elem = v;
          P.border = true;
          X.vertex_point[v] = X.points.size();
          X.points.push_back(P);
        }
        p = X.vertex_point[v];
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
      if(M.border_vertex[v] && X.vertex_point[v] == npos)
      {
        Qpoint P;
        P.loc = AT_VERTEX;
        P.elem = v;
        P.border = true;
        X.vertex_point[v] = X.points.size();
        X.points.push_back(P);
      }
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
  }
  result.time_tracing = seconds(t);

  // ---- faces: next(s) = the slot before partner(s) in the counterclockwise order at its point
  t = Clock::now();
  std::vector<std::size_t> position(X.slots.size(), npos);
  for(const Qpoint& P : X.points)
    for(std::size_t i = 0; i < P.slots.size(); ++i)
      position[P.slots[i]] = i;
  std::vector<char> visited(X.slots.size(), 0);
  std::vector<std::vector<std::size_t> > cells;  // slots of each kept face
  std::vector<char> has_boundary_piece;
  for(std::size_t s0 = 0; s0 < X.slots.size(); ++s0)
  {
    if(visited[s0] || X.slots[s0].state != 1)
      continue;
    std::vector<std::size_t> cycle;
    std::size_t s = s0;
    bool ok = true, boundary_piece = false;
    while(true)
    {
      visited[s] = 1;
      cycle.push_back(s);
      boundary_piece = boundary_piece || X.slots[s].dir < 0;
      const std::size_t b = X.slots[s].partner;
      const Qpoint& P = X.points[X.slots[b].point];
      const std::size_t n = P.slots.size(), i = position[b], ip = (i + n - 1) % n;
      if(!P.adjacent_next[ip])
      {
        ok = false;
        break;
      }
      s = P.slots[ip];
      if(X.slots[s].state != 1)
      {
        ok = false;
        break;
      }
      if(s == s0)
        break;
      if(visited[s])
      {
        ok = false;  // joins a chain already found open
        break;
      }
    }
    if(!ok)
    {
      ++result.discarded_cells;
      continue;
    }
    if(!trimmed && cycle.size() != 4)
    {
      ++result.non_quad_cells;
      continue;
    }
    cells.push_back(cycle);
    has_boundary_piece.push_back(boundary_piece);
  }
  result.time_faces = seconds(t);

  // ---- output: split vertices whose kept faces form several fans, then build the mesh
  t = Clock::now();
  // sector i at point P: between slots[i] (outgoing of a face corner) and slots[i+1]
  std::vector<std::vector<std::size_t> > sector_face(X.points.size());
  for(std::size_t p = 0; p < X.points.size(); ++p)
    sector_face[p].assign(X.points[p].slots.size(), npos);
  for(std::size_t f = 0; f < cells.size(); ++f)
    for(std::size_t s : cells[f])
    {
      // the face corner at point(s) lies between s and the slot after it (the one whose partner precedes s)
      const Qpoint& P = X.points[X.slots[s].point];
      (void)P;
      sector_face[X.slots[s].point][position[s]] = f;
    }
  // corner (f, s) -> output vertex
  std::vector<std::size_t> corner_vertex_of_slot(X.slots.size(), npos);
  std::vector<std::size_t> out_point;  // output vertex -> point
  for(std::size_t p = 0; p < X.points.size(); ++p)
  {
    const std::size_t n = X.points[p].slots.size();
    const auto& sf = sector_face[p];
    // a fan: a maximal run of sectors with faces, joined through interior slots
    std::size_t start_i = npos;
    bool any = false;
    for(std::size_t i = 0; i < n; ++i)
      if(sf[i] != npos)
        any = true;
    if(!any)
      continue;
    // start after an empty sector (or anywhere if all are full)
    for(std::size_t i = 0; i < n; ++i)
      if(sf[(i + n - 1) % n] == npos)
      {
        start_i = i;
        break;
      }
    bool full = start_i == npos;
    if(full)
      start_i = 0;
    std::size_t fans = 0, current = npos;
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::size_t i = (start_i + k) % n;
      if(sf[i] == npos)
      {
        current = npos;
        continue;
      }
      if(current == npos)
      {
        current = out_point.size();
        out_point.push_back(p);
        ++fans;
      }
      corner_vertex_of_slot[X.points[p].slots[i]] = current;
    }
    if(fans > 1)
      result.split_vertices += fans - 1;
  }
  // positions
  typedef typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type Default_out_vpm;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::vertex_point_t, NamedParametersOut,
                                                             Default_out_vpm>::type Out_vpm;
  typedef typename boost::property_traits<Out_vpm>::value_type Out_point;
  typedef CGAL::Exact_rational Q;
  auto lerp3 = [&](const std::array<double, 3>* P, const double* w, std::size_t n) {
    double x[3] = { 0, 0, 0 };
    for(std::size_t i = 0; i < n; ++i)
      for(int a = 0; a < 3; ++a)
        x[a] += w[i] * P[i][a];
    return Out_point(x[0], x[1], x[2]);
  };
  std::vector<Out_point> positions;
  positions.reserve(out_point.size());
  for(std::size_t p : out_point)
  {
    const Qpoint& P = X.points[p];
    if(P.loc == AT_VERTEX)
    {
      const auto& x = M.point[P.elem];
      positions.push_back(Out_point(x[0], x[1], x[2]));
    }
    else if(P.loc == ON_EDGE || P.loc == BOUNDARY_HIT)
    {
      // parameter along the edge from its lower-index vertex, exact then rounded once
      const std::size_t e = P.elem;
      std::size_t a = e, b = Chart_mesh::next(e);
      Q lam;
      if(P.loc == BOUNDARY_HIT)
        lam = P.lambda;
      else
      {
        const P2 &A = M.uv[a], &B = M.uv[b];
        const int coord = A[0] != B[0] ? 0 : 1;
        lam = (Q(P.uv[coord]) - Q(A[coord])) / (Q(B[coord]) - Q(A[coord]));
      }
      if(M.vertex[b] < M.vertex[a])
      {
        std::swap(a, b);
        lam = Q(1) - lam;
      }
      const double l = CGAL::to_double(lam);
      const std::array<double, 3> PP[2] = { M.point[M.vertex[a]], M.point[M.vertex[b]] };
      const double w[2] = { 1 - l, l };
      positions.push_back(lerp3(PP, w, 2));
    }
    else
    {
      const std::size_t f = P.elem;
      Q U[3][2];
      for(std::size_t k = 0; k < 3; ++k)
        for(int c = 0; c < 2; ++c)
          U[k][c] = Q(M.corner_uv(f, k)[c]);
      const Q qx(P.uv[0]), qy(P.uv[1]);
      auto det = [](const Q& ax, const Q& ay, const Q& bx, const Q& by, const Q& cx, const Q& cy) -> Q {
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
      };
      const Q area = det(U[0][0], U[0][1], U[1][0], U[1][1], U[2][0], U[2][1]);
      double w[3];
      for(std::size_t k = 0; k < 3; ++k)
      {
        const std::size_t k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        w[k] = CGAL::to_double(det(qx, qy, U[k1][0], U[k1][1], U[k2][0], U[k2][1]) / area);
      }
      const std::array<double, 3> PP[3] = { M.point[M.vertex[3 * f]], M.point[M.vertex[3 * f + 1]], M.point[M.vertex[3 * f + 2]] };
      positions.push_back(lerp3(PP, w, 3));
    }
  }
  std::vector<std::vector<std::size_t> > polygons;
  for(std::size_t f = 0; f < cells.size(); ++f)
  {
    std::vector<std::size_t> poly;
    for(std::size_t s : cells[f])
      poly.push_back(corner_vertex_of_slot[s]);
    polygons.push_back(poly);
    if(poly.size() == 4 && !has_boundary_piece[f])
      ++result.quads;
    else
      ++result.trimmed_polygons;
  }
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
  {
    ++result.inconsistencies;
    result.diagnostic = "the cells do not form a polygon mesh";
    return Error_code::NOT_AN_INTEGER_GRID_MAP;
  }
  clear_output(quad_mesh);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(positions, polygons, quad_mesh, CGAL::parameters::default_values(), np_out);
  result.vertices = num_vertices(quad_mesh);
  result.faces = num_faces(quad_mesh);
  for(auto v : vertices(quad_mesh))
    if(!CGAL::is_border(v, quad_mesh) && degree(v, quad_mesh) != 4)
      ++result.irregular_vertices;
  result.time_output = seconds(t);
  result.time_total = seconds(start);
  return Error_code::SUCCESS;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_EXTRACT_QUAD_MESH_H
