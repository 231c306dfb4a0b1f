// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The charted triangle mesh that quad extraction works on: one uv chart per
// face, the exact transitions between charts (found from the uv, or given by
// the integer-grid map and checked), vertex fans and exact sector tests.
// Written from Ebke, Bommes, Campen, Kobbelt 2013 (QEx), not from its code.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_CHART_MESH_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_CHART_MESH_H

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <deque>
#include <type_traits>
#include <utility>
#include <vector>
#ifdef CGAL_PVF_QEX_DEBUG
#include <iostream>
#endif

namespace CGAL {
namespace Polyvector_fields {
namespace internal {
namespace qex {

typedef std::array<double, 2> P2;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;

inline int sgn_cmp(double a, double b) { return (a > b) - (a < b); }

// p turned by r quarter turns counterclockwise: exact in floating point
inline P2 rot(const P2& p, int r)
{
  switch(r & 3)
  {
    case 0: return p;
    case 1: return { -p[1], p[0] };
    case 2: return { -p[0], -p[1] };
    default: return { p[1], -p[0] };
  }
}

// a - b, and whether the floating-point result is exact (Knuth's TwoSum error term)
inline bool exact_difference(double a, double b, double& s)
{
  const double c = -b;
  s = a + c;
  const double bb = s - a;
  const double err = (a - (s - bb)) + (c - bb);
  return err == 0 && std::isfinite(s);
}

// x -> R^r x + t, t integer: a symmetry of the integer grid
struct Grid_map
{
  int r = 0;
  double tx = 0, ty = 0;
  P2 operator()(const P2& p) const
  {
    const P2 q = rot(p, r);
    return { q[0] + tx, q[1] + ty };
  }
  bool operator==(const Grid_map& o) const { return ((r - o.r) & 3) == 0 && tx == o.tx && ty == o.ty; }
};
// a o b
inline Grid_map compose(const Grid_map& a, const Grid_map& b)
{
  const P2 t = a(P2{ b.tx, b.ty });
  return Grid_map{ (a.r + b.r) & 3, t[0], t[1] };
}
inline Grid_map inverse(const Grid_map& a)
{
  const P2 t = rot(P2{ -a.tx, -a.ty }, -a.r);
  return Grid_map{ (4 - a.r) & 3, t[0], t[1] };
}

// Direction d in {0: +u, 1: +v, 2: -u, 3: -v}; the quarter turn maps d to d + 1.
inline P2 axis(int d)
{
  static const double D[4][2] = { { 1, 0 }, { 0, 1 }, { -1, 0 }, { 0, -1 } };
  return { D[d & 3][0], D[d & 3][1] };
}
// sign of cross(b - a, axis(d)), exact
inline int cross_edge_axis(const P2& a, const P2& b, int d)
{
  switch(d & 3)
  {
    case 0: return sgn_cmp(a[1], b[1]);   // -(b.y - a.y)
    case 1: return sgn_cmp(b[0], a[0]);   //   b.x - a.x
    case 2: return sgn_cmp(b[1], a[1]);   //   b.y - a.y
    default: return sgn_cmp(a[0], b[0]);  // -(b.x - a.x)
  }
}
// sign of dot(b - a, axis(d)), exact
inline int dot_edge_axis(const P2& a, const P2& b, int d)
{
  switch(d & 3)
  {
    case 0: return sgn_cmp(b[0], a[0]);
    case 1: return sgn_cmp(b[1], a[1]);
    case 2: return sgn_cmp(a[0], b[0]);
    default: return sgn_cmp(a[1], b[1]);
  }
}

inline int orientation(const P2& a, const P2& b, const P2& c)
{
  return int(CGAL::orientation(Epick::Point_2(a[0], a[1]), Epick::Point_2(b[0], b[1]), Epick::Point_2(c[0], c[1])));
}

// The triangle mesh with one uv chart per face. Face f has corners 3f, 3f+1, 3f+2
// (counterclockwise, corner 0 at its smallest vertex index); edge 3f+k goes from
// corner k to corner k+1, so an edge and the corner it starts at share their index.
struct Chart_mesh
{
  std::size_t V = 0, F = 0;
  std::vector<std::size_t> vertex;     // per corner: vertex index
  std::vector<P2> uv;                  // per corner: uv in the chart of its face
  std::vector<std::array<double, 3> > point;  // per vertex
  std::vector<char> border_vertex;     // per vertex
  std::vector<std::size_t> opp;        // per edge: opposite edge (npos on the border)
  std::vector<Grid_map> trans;         // per interior edge 3f+k: chart of f -> chart of face(opp)
  // fans: the corners at each vertex, counterclockwise; for a border vertex, from the
  // corner whose outgoing edge is on the border to the one whose incoming edge is.
  std::vector<std::vector<std::size_t> > fan;
  std::vector<std::vector<Grid_map> > fan_map;  // chart of face(fan[0]) -> chart of face(fan[j])
  std::vector<std::size_t> fan_pos;             // per corner
  std::size_t degenerate_uv_edges = 0;          // interior edges of zero uv length (transition ambiguous)
  std::size_t rotated_edges = 0;                // interior edges whose transition has r != 0
  std::size_t translated_edges = 0;             // interior edges whose transition has t != 0

  static std::size_t face(std::size_t c) { return c / 3; }
  static std::size_t next(std::size_t c) { return c - c % 3 + (c % 3 + 1) % 3; }
  static std::size_t prev(std::size_t c) { return c - c % 3 + (c % 3 + 2) % 3; }
  const P2& corner_uv(std::size_t f, std::size_t k) const { return uv[3 * f + (k % 3)]; }
  int face_orientation(std::size_t f) const { return orientation(uv[3 * f], uv[3 * f + 1], uv[3 * f + 2]); }
  // the next corner counterclockwise around the vertex of corner c (npos on the border)
  std::size_t ccw(std::size_t c) const { return opp[prev(c)]; }
  std::size_t cw(std::size_t c) const { return opp[c] == npos ? npos : next(opp[c]); }
};

// A uv value as two doubles: a 2D point (with x() and y()) or a pair indexed by [0] and [1].
template <typename UV>
P2 uv_value(const UV& p)
{
  if constexpr(Has_xy<UV>::value)
    return { CGAL::to_double(p.x()), CGAL::to_double(p.y()) };
  else
    return { CGAL::to_double(p[0]), CGAL::to_double(p[1]) };
}

// Reads the mesh and the map. uv_map[h] is the value at target(h) inside face(h).
template <typename TriangleMesh, typename VertexPointMap, typename UVMap>
Error_code build_chart_mesh(const TriangleMesh& tm, VertexPointMap vpm, UVMap uv_map, Chart_mesh& M)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  using boost::get;
  Numbering<vertex_descriptor> vindex;
  Numbering<halfedge_descriptor> hindex;  // halfedge -> the edge index it is in the chart mesh
  for(vertex_descriptor v : vertices(tm))
  {
    vindex.add(v);
    const auto p = get(vpm, v);
    M.point.push_back({ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) });
    if(!std::isfinite(M.point.back()[0]) || !std::isfinite(M.point.back()[1]) || !std::isfinite(M.point.back()[2]))
      return Error_code::NON_FINITE_VALUE;
  }
  M.V = M.point.size();
  M.border_vertex.assign(M.V, 0);
  std::vector<halfedge_descriptor> edge_halfedge;
  for(auto f : faces(tm))
  {
    std::array<halfedge_descriptor, 3> h;
    std::size_t n = 0;
    for(halfedge_descriptor x : halfedges_around_face(halfedge(f, tm), tm))
    {
      if(n == 3)
        return Error_code::NON_TRIANGLE_FACE;
      h[n++] = x;
    }
    if(n != 3)
      return Error_code::NON_TRIANGLE_FACE;
    std::size_t first = 0;
    for(std::size_t k = 1; k < 3; ++k)
      if(vindex(target(h[k], tm)) < vindex(target(h[first], tm)))
        first = k;
    for(std::size_t k = 0; k < 3; ++k)
    {
      const halfedge_descriptor hk = h[(first + k) % 3];
      M.vertex.push_back(vindex(target(hk, tm)));
      const auto value = get(uv_map, hk);
      const P2 u = uv_value(value);
      if(!std::isfinite(u[0]) || !std::isfinite(u[1]))
        return Error_code::NON_FINITE_VALUE;
      M.uv.push_back(u);
    }
    // edge k goes from corner k to corner k+1: it is the halfedge of corner k+1
    for(std::size_t k = 0; k < 3; ++k)
    {
      const halfedge_descriptor hk = h[(first + k + 1) % 3];
      hindex.add(hk);
      edge_halfedge.push_back(hk);
    }
  }
  M.F = M.vertex.size() / 3;
  if(M.F == 0)
    return Error_code::EMPTY_MESH;
  const std::size_t C = 3 * M.F;
  for(std::size_t c = 0; c < C; ++c)
    if(M.vertex[c] == M.vertex[Chart_mesh::next(c)])
      return Error_code::DEGENERATE_FACE;
  M.opp.assign(C, npos);
  M.trans.assign(C, Grid_map());
  for(std::size_t e = 0; e < C; ++e)
  {
    const halfedge_descriptor o = opposite(edge_halfedge[e], tm);
    if(CGAL::is_border(o, tm))
    {
      M.border_vertex[M.vertex[e]] = 1;
      M.border_vertex[M.vertex[Chart_mesh::next(e)]] = 1;
    }
    else
      M.opp[e] = hindex(o);
  }
  return Error_code::SUCCESS;
}

// Both sides of every interior edge: the transition of the opposite edge must be
// the inverse (or is made so, with `make_inverse`); counts the rotated and
// translated edges.
inline Error_code pair_transitions(Chart_mesh& M, bool make_inverse)
{
  for(std::size_t e = 0; e < 3 * M.F; ++e)
  {
    const std::size_t o = M.opp[e];
    if(o == npos || o < e)
      continue;
    if(make_inverse)
      M.trans[o] = inverse(M.trans[e]);
    else if(!(M.trans[o] == inverse(M.trans[e])))
      return Error_code::NOT_AN_INTEGER_GRID_MAP;
    M.rotated_edges += M.trans[e].r != 0;
    M.translated_edges += M.trans[e].tx != 0 || M.trans[e].ty != 0;
  }
  return Error_code::SUCCESS;
}

// The transition of every interior edge: the grid symmetry that maps the edge's two
// endpoints in one chart exactly onto the same endpoints in the other chart.
inline Error_code compute_transitions(Chart_mesh& M)
{
  M.degenerate_uv_edges = M.rotated_edges = M.translated_edges = 0;
  const std::size_t C = 3 * M.F;
  for(std::size_t e = 0; e < C; ++e)
  {
    const std::size_t o = M.opp[e];
    if(o == npos)
      continue;
    // in face(e): A = corner e, B = corner next(e); in face(o): B = corner o, A = corner next(o)
    const P2 &A = M.uv[e], &B = M.uv[Chart_mesh::next(e)], &Bo = M.uv[o], &Ao = M.uv[Chart_mesh::next(o)];
    int found = -1, count = 0;
    Grid_map g;
    for(int r = 0; r < 4; ++r)
    {
      const P2 ra = rot(A, r), rb = rot(B, r);
      double t[4];
      if(!exact_difference(Ao[0], ra[0], t[0]) || !exact_difference(Ao[1], ra[1], t[1]) ||
         !exact_difference(Bo[0], rb[0], t[2]) || !exact_difference(Bo[1], rb[1], t[3]))
        continue;
      if(t[0] != t[2] || t[1] != t[3] || t[0] != std::floor(t[0]) || t[1] != std::floor(t[1]))
        continue;
      if(found < 0)
      {
        found = r;
        g = Grid_map{ r, t[0], t[1] };
      }
      ++count;
    }
    if(found < 0)
      return Error_code::NOT_AN_INTEGER_GRID_MAP;
    if(count > 1)
      ++M.degenerate_uv_edges;
    M.trans[e] = g;
  }
  // both sides must agree: trans[opp] = trans^-1 (made so across an edge of zero uv length)
  return pair_transitions(M, M.degenerate_uv_edges != 0);
}

// Reads the mesh of a tangent bundle and a map on it, with the transitions the
// map gives: `transition[c]` for the corner c = 3f+k of the bundle's numbering
// (the k-th halfedge of face f from halfedge(face)), from face(c) to
// face(opposite(c)), with `rotation` and `translation`. The charts are numbered
// as by build_chart_mesh(): the bundle's faces and vertices (the orders of
// faces(tm) and vertices(tm)), corner 0 at the smallest vertex index.
template <typename Bundle, typename UVMap, typename Transition>
Error_code build_chart_mesh(const Bundle& bundle, UVMap uv_map, const std::vector<Transition>& transition, Chart_mesh& M)
{
  typedef typename Bundle::halfedge_descriptor halfedge_descriptor;
  using boost::get;
  const auto& tm = bundle.mesh();
  if(bundle.status() != Error_code::SUCCESS)
    return bundle.status();
  M.V = bundle.number_of_vertices();
  M.F = bundle.number_of_faces();
  if(M.F == 0)
    return Error_code::EMPTY_MESH;
  if(transition.size() != 3 * M.F)
    return Error_code::NOT_AN_INTEGER_GRID_MAP;
  for(std::size_t v = 0; v < M.V; ++v)
    M.point.push_back(bundle.point(v));
  M.border_vertex.assign(M.V, 0);
  const std::size_t C = 3 * M.F;
  std::vector<std::size_t> edge_of_bundle_corner(C);
  std::vector<halfedge_descriptor> edge_halfedge(C);
  for(std::size_t f = 0; f < M.F; ++f)
  {
    std::array<halfedge_descriptor, 3> h;
    h[0] = halfedge(bundle.face(f), tm);
    h[1] = next(h[0], tm);
    h[2] = next(h[1], tm);
    std::size_t first = 0;
    for(std::size_t k = 1; k < 3; ++k)
      if(bundle.index(target(h[k], tm)) < bundle.index(target(h[first], tm)))
        first = k;
    for(std::size_t k = 0; k < 3; ++k)
    {
      const halfedge_descriptor hk = h[(first + k) % 3];
      M.vertex.push_back(bundle.index(target(hk, tm)));
      const P2 u = uv_value(get(uv_map, hk));
      if(!std::isfinite(u[0]) || !std::isfinite(u[1]))
        return Error_code::NON_FINITE_VALUE;
      M.uv.push_back(u);
      // edge k goes from corner k to corner k+1: it is the halfedge of corner k+1
      edge_of_bundle_corner[3 * f + (first + k + 1) % 3] = 3 * f + k;
      edge_halfedge[3 * f + k] = h[(first + k + 1) % 3];
    }
  }
  for(std::size_t c = 0; c < C; ++c)
    if(M.vertex[c] == M.vertex[Chart_mesh::next(c)])
      return Error_code::DEGENERATE_FACE;
  M.opp.assign(C, npos);
  M.trans.assign(C, Grid_map());
  for(std::size_t b = 0; b < C; ++b)
  {
    const std::size_t e = edge_of_bundle_corner[b];
    const halfedge_descriptor o = opposite(edge_halfedge[e], tm);
    if(CGAL::is_border(o, tm))
    {
      M.border_vertex[M.vertex[e]] = 1;
      M.border_vertex[M.vertex[Chart_mesh::next(e)]] = 1;
      continue;
    }
    const std::size_t g = bundle.index(face(o, tm));
    const halfedge_descriptor hg = halfedge(bundle.face(g), tm);
    const std::size_t kg = hg == o ? 0 : next(hg, tm) == o ? 1 : 2;
    M.opp[e] = edge_of_bundle_corner[3 * g + kg];
    const Transition& T = transition[b];
    M.trans[e] = Grid_map{ T.rotation & 3, double(T.translation[0]), double(T.translation[1]) };
  }
  return Error_code::SUCCESS;
}

// Checks given transitions: each one maps the two endpoints of its edge exactly
// onto the same endpoints in the other chart, and the two sides are inverse;
// counts the edges as compute_transitions() does.
inline Error_code check_transitions(Chart_mesh& M)
{
  M.degenerate_uv_edges = M.rotated_edges = M.translated_edges = 0;
  const std::size_t C = 3 * M.F;
  for(std::size_t e = 0; e < C; ++e)
  {
    const std::size_t o = M.opp[e];
    if(o == npos)
      continue;
    const P2 &A = M.uv[e], &B = M.uv[Chart_mesh::next(e)], &Bo = M.uv[o], &Ao = M.uv[Chart_mesh::next(o)];
    const Grid_map& g = M.trans[e];
    if(g.tx != std::floor(g.tx) || g.ty != std::floor(g.ty))
      return Error_code::NOT_AN_INTEGER_GRID_MAP;
    for(const auto& pair : { std::make_pair(A, Ao), std::make_pair(B, Bo) })
    {
      // t = target - R^r source, exactly; it must be the transition's translation
      const P2 ra = rot(pair.first, g.r);
      double t[2];
      if(!exact_difference(pair.second[0], ra[0], t[0]) || !exact_difference(pair.second[1], ra[1], t[1]) ||
         t[0] != g.tx || t[1] != g.ty)
        return Error_code::NOT_AN_INTEGER_GRID_MAP;
    }
    // an edge of zero uv length that several grid symmetries fit (counted from both sides, as
    // compute_transitions() does): there the uv alone cannot tell the transition
    int fits = 0;
    for(int r = 0; r < 4 && A == B && Ao == Bo; ++r)
    {
      const P2 ra = rot(A, r);
      double t[2];
      fits += exact_difference(Ao[0], ra[0], t[0]) && exact_difference(Ao[1], ra[1], t[1]) && t[0] == std::floor(t[0]) &&
              t[1] == std::floor(t[1]);
    }
    M.degenerate_uv_edges += fits > 1;
  }
  return pair_transitions(M, false);
}

inline Error_code build_fans(Chart_mesh& M)
{
  const std::size_t C = 3 * M.F;
  M.fan.assign(M.V, {});
  M.fan_map.assign(M.V, {});
  M.fan_pos.assign(C, npos);
  std::vector<std::size_t> count(M.V, 0);
  for(std::size_t c = 0; c < C; ++c)
    ++count[M.vertex[c]];
  for(std::size_t c0 = 0; c0 < C; ++c0)
  {
    const std::size_t v = M.vertex[c0];
    if(!M.fan[v].empty())
      continue;
    std::size_t first = c0;
    if(M.border_vertex[v])
    {
      // walk clockwise to the corner whose outgoing edge is on the border
      std::size_t steps = 0;
      while(M.opp[first] != npos)
      {
        first = M.cw(first);
        if(++steps > count[v])
          return Error_code::NON_MANIFOLD_MESH;  // not a manifold vertex
      }
    }
    std::size_t c = first;
    Grid_map g;
    do
    {
      M.fan_pos[c] = M.fan[v].size();
      M.fan[v].push_back(c);
      M.fan_map[v].push_back(g);
      const std::size_t e = Chart_mesh::prev(c);
      if(M.opp[e] == npos)
        break;
      g = compose(M.trans[e], g);
      c = M.opp[e];
      if(M.fan[v].size() > count[v])
        return Error_code::NON_MANIFOLD_MESH;
    } while(c != first);
    if(M.fan[v].size() != count[v])
      return Error_code::NON_MANIFOLD_MESH;  // several fans at a vertex: not a manifold mesh
  }
  return Error_code::SUCCESS;
}

// Is axis direction d (in the chart of face(c)) in the sector of corner c:
// [e1, e2) counterclockwise, e1 to the next corner, e2 to the previous one;
// [e1, e2] when closed (the last sector of a border vertex).
inline bool in_sector(const Chart_mesh& M, std::size_t c, int d, bool closed)
{
  const P2 &P = M.uv[c], &Q1 = M.uv[Chart_mesh::next(c)], &Q2 = M.uv[Chart_mesh::prev(c)];
  const int s1 = cross_edge_axis(P, Q1, d);   // cross(e1, d)
  const int s2 = -cross_edge_axis(P, Q2, d);  // cross(d, e2)
  if(s1 < 0)
    return false;
  if(s1 == 0 && dot_edge_axis(P, Q1, d) < 0)
    return false;
  if(!closed)
    return s2 > 0;
  if(s2 < 0)
    return false;
  return !(s2 == 0 && dot_edge_axis(P, Q2, d) < 0);
}

// The axis directions in the sector of corner c, counterclockwise from e1.
inline void sector_directions(const Chart_mesh& M, std::size_t c, bool closed, std::vector<int>& out)
{
  out.clear();
  const P2 &P = M.uv[c], &Q1 = M.uv[Chart_mesh::next(c)];
  int first = 0;
  for(int d = 0; d < 4; ++d)
    if(dot_edge_axis(P, Q1, d) > 0 && cross_edge_axis(P, Q1, d) >= 0)  // angle from e1 in [0, 90)
      first = d;
  for(int k = 0; k < 4; ++k)
  {
    const int d = (first + k) & 3;
    if(!in_sector(M, c, d, closed))
      break;
    out.push_back(d);
  }
}

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_CHART_MESH_H
