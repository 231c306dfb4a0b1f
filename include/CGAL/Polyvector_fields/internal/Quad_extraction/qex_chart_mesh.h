// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The charted triangle mesh that quad extraction works on (one uv chart per
// face, exact transitions, vertex fans, exact sector tests, fold-over repair).
// Written from Ebke, Bommes, Campen, Kobbelt 2013 (QEx), not from its code.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_QEX_CHART_MESH_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_QEX_CHART_MESH_H

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <Eigen/Sparse>

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

constexpr std::size_t npos = std::size_t(-1);
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
template <typename T, typename = void>
struct Has_xy : std::false_type {};
template <typename T>
struct Has_xy<T, std::void_t<decltype(std::declval<const T&>().x()), decltype(std::declval<const T&>().y())> >
  : std::true_type {};
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
  // both sides must agree: trans[opp] = trans^-1
  for(std::size_t e = 0; e < C; ++e)
    if(M.opp[e] != npos)
    {
      if(M.opp[e] > e && M.degenerate_uv_edges == 0 && !(M.trans[M.opp[e]] == inverse(M.trans[e])))
        return Error_code::NOT_AN_INTEGER_GRID_MAP;
      if(M.opp[e] > e && M.degenerate_uv_edges != 0)
        M.trans[M.opp[e]] = inverse(M.trans[e]);
      if(M.opp[e] > e)
      {
        M.rotated_edges += M.trans[e].r != 0;
        M.translated_edges += M.trans[e].tx != 0 || M.trans[e].ty != 0;
      }
    }
  return Error_code::SUCCESS;
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

// ---------------------------------------------------------------------------
// Fold-over repair: the flipped (or degenerate) faces and a few rings around them
// are unfolded into one chart through the exact transitions, their inner vertices
// are placed by Tutte's barycentric embedding with the ring boundary fixed, and the
// values are snapped to a dyadic grid and mapped back into each face's chart by the
// same exact transitions. A region is kept only if all its faces come out positive.
// ---------------------------------------------------------------------------
struct Fold_over_report
{
  std::size_t flipped_faces = 0;      // faces with det <= 0 in the input map
  std::size_t degenerate_faces = 0;   // of which det == 0
  std::size_t regions = 0;            // regions repaired
  std::size_t moved_vertices = 0;
  std::size_t rings_used = 0;         // largest ring count needed
  std::size_t remaining = 0;          // flipped faces left (0 on success)
};

// The holonomy of the fan of an interior vertex: the grid map accumulated once around.
inline bool trivial_holonomy(const Chart_mesh& M, std::size_t v)
{
  const auto& fan = M.fan[v];
  if(M.border_vertex[v] || fan.empty())
    return false;
  const Grid_map around = compose(M.trans[Chart_mesh::prev(fan.back())], M.fan_map[v].back());
  return around == Grid_map();
}

// Tutte's embedding with a connection: each free vertex v has its uv X_v in the chart of
// face(fan[v][0]); a neighbour w seen in face f contributes X_v - A_v^-1 (A_w X_w), with
// A_v, A_w the exact grid maps from the vertices' charts to the chart of f. Cones and
// border vertices stay fixed, so the region needs no single chart.
// Moves free vertex v (its uv in the chart of fan[v][0]) to the centroid of the kernel of
// its star (the points that see every opposite edge on their left); true if all the faces
// around v are then positive.
inline bool move_into_kernel(Chart_mesh& M, std::size_t v)
{
  const auto& fan = M.fan[v];
  std::vector<std::pair<P2, P2> > edges;
  double lo[2] = { 1e300, 1e300 }, hi[2] = { -1e300, -1e300 };
  for(std::size_t j = 0; j < fan.size(); ++j)
  {
    const Grid_map inv = inverse(M.fan_map[v][j]);
    const P2 a = inv(M.uv[Chart_mesh::next(fan[j])]), b = inv(M.uv[Chart_mesh::prev(fan[j])]);
    edges.emplace_back(a, b);
    for(int k = 0; k < 2; ++k)
    {
      lo[k] = (std::min)({ lo[k], a[k], b[k] });
      hi[k] = (std::max)({ hi[k], a[k], b[k] });
    }
  }
  std::vector<P2> poly{ { lo[0], lo[1] }, { hi[0], lo[1] }, { hi[0], hi[1] }, { lo[0], hi[1] } };
  for(const auto& e : edges)
  {
    // keep cross(b - a, x - a) >= 0 (Sutherland-Hodgman)
    const double ex = e.second[0] - e.first[0], ey = e.second[1] - e.first[1];
    auto side = [&](const P2& x) { return ex * (x[1] - e.first[1]) - ey * (x[0] - e.first[0]); };
    std::vector<P2> out;
    for(std::size_t i = 0; i < poly.size(); ++i)
    {
      const P2 &p = poly[i], &q = poly[(i + 1) % poly.size()];
      const double sp = side(p), sq = side(q);
      if(sp >= 0)
        out.push_back(p);
      if((sp >= 0) != (sq >= 0))
      {
        const double t = sp / (sp - sq);
        out.push_back({ p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]) });
      }
    }
    poly.swap(out);
    if(poly.size() < 3)
      return false;
  }
  P2 c{ 0, 0 };
  for(const P2& p : poly)
    c = { c[0] + p[0] / double(poly.size()), c[1] + p[1] / double(poly.size()) };
  double largest = 1;
  for(std::size_t j = 0; j < fan.size(); ++j)
    for(std::size_t k = 0; k < 3; ++k)
      largest = (std::max)({ largest, std::abs(M.uv[3 * Chart_mesh::face(fan[j]) + k][0]), std::abs(M.uv[3 * Chart_mesh::face(fan[j]) + k][1]) });
  largest = (std::max)({ largest, std::abs(c[0]), std::abs(c[1]) });
  const int ex = int(std::ceil(std::log2(8 * largest + 8)));
  const double quantum = std::ldexp(1.0, (std::min)(-1, ex - 50));
  const P2 x{ std::round(c[0] / quantum) * quantum, std::round(c[1] / quantum) * quantum };
  std::vector<P2> saved;
  for(std::size_t j = 0; j < fan.size(); ++j)
  {
    saved.push_back(M.uv[fan[j]]);
    M.uv[fan[j]] = M.fan_map[v][j](x);
  }
  bool ok = true;
  for(std::size_t j = 0; j < fan.size(); ++j)
    ok = ok && M.face_orientation(Chart_mesh::face(fan[j])) > 0;
  if(!ok)
    for(std::size_t j = 0; j < fan.size(); ++j)
      M.uv[fan[j]] = saved[j];
  return ok;
}

// Sweeps over the free vertices next to a non-positive face, moving each into its kernel.
inline void untangle(Chart_mesh& M, const std::vector<std::size_t>& free_vertices, std::size_t sweeps)
{
  for(std::size_t s = 0; s < sweeps; ++s)
  {
    bool any = false;
    for(std::size_t v : free_vertices)
    {
      bool bad = false;
      for(std::size_t c : M.fan[v])
        bad = bad || M.face_orientation(Chart_mesh::face(c)) <= 0;
      if(bad)
      {
        any = true;
        move_into_kernel(M, v);
      }
    }
    if(!any)
      return;
  }
}

// Re-spreads the 1-ring of an interior cone v (total uv angle (number of axis
// directions) pi/2, fixed by its holonomy): each neighbour at its mean uv distance, at
// angles proportional to the 3D corner angles, in the developed fan. Only neighbours in
// `movable` move; false if one of them cannot.
inline bool spread_cone_star(Chart_mesh& M, std::size_t v, const std::vector<char>& movable)
{
  const auto& fan = M.fan[v];
  const std::size_t n = fan.size();
  if(M.border_vertex[v] || n < 3)
    return false;
  // the cone's angle in the map: the sum of the signed uv corner angles (a multiple of
  // pi/2 up to round-off, even with flipped corners)
  double signed_sum = 0;
  for(std::size_t c : fan)
  {
    const P2 &p = M.uv[c], &q1 = M.uv[Chart_mesh::next(c)], &q2 = M.uv[Chart_mesh::prev(c)];
    const double ax = q1[0] - p[0], ay = q1[1] - p[1], bx = q2[0] - p[0], by = q2[1] - p[1];
    signed_sum += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  }
  const double total = std::round(signed_sum / (CGAL_PI / 2)) * (CGAL_PI / 2);
  if(!(total > 0))
    return false;
  std::vector<double> alpha(n), length3(n);
  double sum = 0, radius = 0, mean3 = 0;
  for(std::size_t j = 0; j < n; ++j)
  {
    const auto &P = M.point[v], &A = M.point[M.vertex[Chart_mesh::next(fan[j])]], &B = M.point[M.vertex[Chart_mesh::prev(fan[j])]];
    double a[3], b[3];
    for(int k = 0; k < 3; ++k)
    {
      a[k] = A[k] - P[k];
      b[k] = B[k] - P[k];
    }
    const double cr[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
    alpha[j] = std::atan2(std::sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
    sum += alpha[j];
    const P2 &p = M.uv[fan[j]], &q = M.uv[Chart_mesh::next(fan[j])];
    radius += std::hypot(q[0] - p[0], q[1] - p[1]) / double(n);
    length3[j] = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    mean3 += length3[j] / double(n);
  }
  // a compact star (half the scaled 3D lengths) leaves room for the Tutte step around it
  if(!(sum > 0) || !(radius > 0))
    return false;
  // the first neighbour keeps its direction in the chart of fan[0]
  const P2 P0 = M.uv[fan[0]], Q0 = M.uv[Chart_mesh::next(fan[0])];
  double phi = std::atan2(Q0[1] - P0[1], Q0[0] - P0[0]);
  for(std::size_t j = 0; j < n; ++j)
  {
    const std::size_t wc = Chart_mesh::next(fan[j]), w = M.vertex[wc];
    if(!movable[w])
      return false;
    // developed angle phi, in the chart of face(fan[j]): minus the chart's quarter turns
    const double ang = phi + double(M.fan_map[v][j].r) * CGAL_PI / 2;
    const P2 Pj = M.uv[fan[j]];
    const double rj = 0.5 * radius * length3[j] / mean3;
    const P2 x{ Pj[0] + rj * std::cos(ang), Pj[1] + rj * std::sin(ang) };
    // into every corner of w, through w's own fan charts
    const Grid_map to_w = inverse(M.fan_map[w][M.fan_pos[wc]]);
    const P2 xw = to_w(x);
    double largest = 1;
    for(std::size_t c : M.fan[w])
      largest = (std::max)({ largest, std::abs(M.uv[c][0]), std::abs(M.uv[c][1]), std::abs(xw[0]), std::abs(xw[1]) });
    const int ex = int(std::ceil(std::log2(8 * largest + 8)));
    const double quantum = std::ldexp(1.0, (std::min)(-1, ex - 50));
    const P2 xs{ std::round(xw[0] / quantum) * quantum, std::round(xw[1] / quantum) * quantum };
    for(std::size_t k = 0; k < M.fan[w].size(); ++k)
      M.uv[M.fan[w][k]] = M.fan_map[w][k](xs);
    phi += alpha[j] / sum * total;
  }
  return true;
}

inline bool repair_region(Chart_mesh& M, const std::vector<std::size_t>& region, const std::vector<char>& in_region,
                          Fold_over_report& report, int mode)
{
  const bool tutte = mode >= 1;
  std::vector<std::size_t> local(M.V, npos);
  std::vector<std::size_t> free_vertices;
  for(std::size_t f : region)
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t v = M.vertex[3 * f + k];
      if(local[v] != npos || !trivial_holonomy(M, v))
        continue;
      bool inside = true;
      for(std::size_t c : M.fan[v])
        inside = inside && in_region[Chart_mesh::face(c)];
      if(inside)
      {
        local[v] = free_vertices.size();
        free_vertices.push_back(v);
      }
    }
  if(free_vertices.empty())
    return false;
  const std::size_t n = free_vertices.size();
  std::vector<P2> saved;
  for(std::size_t f : region)
    for(std::size_t k = 0; k < 3; ++k)
      saved.push_back(M.uv[3 * f + k]);
  auto restore = [&]() {
    std::size_t i = 0;
    for(std::size_t f : region)
      for(std::size_t k = 0; k < 3; ++k)
        M.uv[3 * f + k] = saved[i++];
  };
  auto all_positive = [&]() {
    for(std::size_t f : region)
      if(M.face_orientation(f) <= 0)
        return false;
    return true;
  };
  if(!tutte)
  {
    untangle(M, free_vertices, 20);
    if(!all_positive())
    {
      restore();
      return false;
    }
    ++report.regions;
    report.moved_vertices += n;
    return true;
  }
  if(mode == 2)
  {
    // cones next to a non-positive face: re-spread their stars, then keep them fixed
    std::vector<char> movable(M.V, 0);
    for(std::size_t v : free_vertices)
      movable[v] = 1;
    std::vector<std::size_t> cones;
    for(std::size_t f : region)
      if(M.face_orientation(f) <= 0)
        for(std::size_t k = 0; k < 3; ++k)
        {
          const std::size_t v = M.vertex[3 * f + k];
          if(!M.border_vertex[v] && !trivial_holonomy(M, v))
            cones.push_back(v);
        }
    std::sort(cones.begin(), cones.end());
    cones.erase(std::unique(cones.begin(), cones.end()), cones.end());
    if(cones.empty())
      return false;
    for(std::size_t v : cones)
    {
      if(!spread_cone_star(M, v, movable))
      {
        restore();
        return false;
      }
      for(std::size_t c : M.fan[v])
        local[M.vertex[Chart_mesh::next(c)]] = npos;
    }
    free_vertices.clear();
    for(std::size_t f : region)
      for(std::size_t k = 0; k < 3; ++k)
      {
        const std::size_t v = M.vertex[3 * f + k];
        if(local[v] != npos && std::find(free_vertices.begin(), free_vertices.end(), v) == free_vertices.end())
          free_vertices.push_back(v);
      }
    for(std::size_t i = 0; i < free_vertices.size(); ++i)
      local[free_vertices[i]] = i;
  }
  const std::size_t nt = free_vertices.size();
  if(nt == 0)
  {
    restore();
    return false;
  }
  std::vector<Eigen::Triplet<double> > T;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(Eigen::Index(2 * nt));
  auto rotation = [](int r, double R[2][2]) {
    const P2 c0 = rot(P2{ 1, 0 }, r), c1 = rot(P2{ 0, 1 }, r);
    R[0][0] = c0[0]; R[1][0] = c0[1]; R[0][1] = c1[0]; R[1][1] = c1[1];
  };
  for(std::size_t i = 0; i < nt; ++i)
  {
    const std::size_t v = free_vertices[i];
    const auto& fan = M.fan[v];
    for(std::size_t j = 0; j < fan.size(); ++j)
    {
      const std::size_t c = fan[j];
      const Grid_map inv_v = inverse(M.fan_map[v][j]);  // chart of face(c) -> chart of v
      for(std::size_t w_corner : { Chart_mesh::next(c), Chart_mesh::prev(c) })
      {
        const std::size_t w = M.vertex[w_corner];
        for(int a = 0; a < 2; ++a)
          T.emplace_back(Eigen::Index(2 * i + a), Eigen::Index(2 * i + a), 1.0);
        if(local[w] == npos)
        {
          const P2 x = inv_v(M.uv[w_corner]);
          b[Eigen::Index(2 * i)] += x[0];
          b[Eigen::Index(2 * i + 1)] += x[1];
        }
        else
        {
          // A_v^-1 A_w X_w = R X_w + t
          const Grid_map G = compose(inv_v, M.fan_map[w][M.fan_pos[w_corner]]);
          double R[2][2];
          rotation(G.r, R);
          for(int a = 0; a < 2; ++a)
            for(int bb = 0; bb < 2; ++bb)
              if(R[a][bb] != 0)
                T.emplace_back(Eigen::Index(2 * i + a), Eigen::Index(2 * local[w] + bb), -R[a][bb]);
          b[Eigen::Index(2 * i)] += G.tx;
          b[Eigen::Index(2 * i + 1)] += G.ty;
        }
      }
    }
  }
  Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(2 * nt), static_cast<Eigen::Index>(2 * nt));
  A.setFromTriplets(T.begin(), T.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > solver(A);
  if(solver.info() != Eigen::Success)
  {
    restore();
    return false;
  }
  const Eigen::VectorXd x = solver.solve(b);
  if(solver.info() != Eigen::Success || !x.allFinite())
  {
    restore();
    return false;
  }
  double largest = 1;
  for(std::size_t f : region)
    for(std::size_t k = 0; k < 3; ++k)
      largest = (std::max)({ largest, std::abs(M.uv[3 * f + k][0]), std::abs(M.uv[3 * f + k][1]) });
  for(Eigen::Index i = 0; i < x.size(); ++i)
    largest = (std::max)(largest, std::abs(x[i]));
  const int ex = int(std::ceil(std::log2(8 * largest + 8)));
  const double quantum = std::ldexp(1.0, (std::min)(-1, ex - 50));
  for(std::size_t f : region)
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t c = 3 * f + k, v = M.vertex[c];
      if(local[v] == npos)
        continue;
      const P2 p{ std::round(x[Eigen::Index(2 * local[v])] / quantum) * quantum,
                  std::round(x[Eigen::Index(2 * local[v] + 1)] / quantum) * quantum };
      M.uv[c] = M.fan_map[v][M.fan_pos[c]](p);
    }
  untangle(M, free_vertices, 20);
  bool ok = all_positive();
#ifdef CGAL_PVF_QEX_DEBUG
  {
    std::size_t bad = 0;
    for(std::size_t f : region)
      bad += M.face_orientation(f) <= 0;
    std::cerr << "repair: region of " << region.size() << " faces, " << n << " free vertices: " << bad << " flipped after Tutte\n";
    for(std::size_t f : region)
      if(M.face_orientation(f) <= 0)
        for(std::size_t k = 0; k < 3; ++k)
        {
          const std::size_t v = M.vertex[3 * f + k];
          std::cerr << "   face " << f << " vertex " << v << (local[v] != npos ? " free" : " fixed")
                    << (trivial_holonomy(M, v) ? "" : " cone/border") << " uv " << M.uv[3 * f + k][0] << "," << M.uv[3 * f + k][1] << "\n";
        }
  }
#endif
  if(!ok)
  {
    restore();
    return false;
  }
  ++report.regions;
  report.moved_vertices += n;
  return true;
}

inline Error_code repair_fold_overs(Chart_mesh& M, std::size_t max_rings, Fold_over_report& report)
{
  report = Fold_over_report();
  std::vector<char> flipped(M.F, 0);
  std::size_t positive = 0;
  for(std::size_t f = 0; f < M.F; ++f)
  {
    const int o = M.face_orientation(f);
    flipped[f] = o <= 0;
    report.flipped_faces += o <= 0;
    report.degenerate_faces += o == 0;
    positive += o != 0;
  }
  if(positive == 0)
    return Error_code::NOT_AN_INTEGER_GRID_MAP;  // no map at all: every triangle has zero uv area
  for(std::size_t rings = 1; rings <= max_rings; ++rings)
  {
    std::vector<std::size_t> bad;
    for(std::size_t f = 0; f < M.F; ++f)
      if(M.face_orientation(f) <= 0)
        bad.push_back(f);
    if(bad.empty())
      break;
    report.rings_used = rings;
    // dilate by vertex rings
    std::vector<char> in_region(M.F, 0);
    for(std::size_t f : bad)
      in_region[f] = 1;
    for(std::size_t r = 0; r < rings; ++r)
    {
      std::vector<char> grown = in_region;
      for(std::size_t f = 0; f < M.F; ++f)
        if(in_region[f])
          for(std::size_t k = 0; k < 3; ++k)
            for(std::size_t c : M.fan[M.vertex[3 * f + k]])
              grown[Chart_mesh::face(c)] = 1;
      in_region.swap(grown);
    }
    // edge-connected components
    std::vector<char> done(M.F, 0);
    for(std::size_t f0 = 0; f0 < M.F; ++f0)
    {
      if(!in_region[f0] || done[f0])
        continue;
      std::vector<std::size_t> region{ f0 };
      done[f0] = 1;
      for(std::size_t i = 0; i < region.size(); ++i)
        for(std::size_t k = 0; k < 3; ++k)
        {
          const std::size_t o = M.opp[3 * region[i] + k];
          if(o != npos && in_region[Chart_mesh::face(o)] && !done[Chart_mesh::face(o)])
          {
            done[Chart_mesh::face(o)] = 1;
            region.push_back(Chart_mesh::face(o));
          }
        }
      bool has_bad = false;
      for(std::size_t f : region)
        has_bad = has_bad || M.face_orientation(f) <= 0;
      if(!has_bad)
        continue;
      std::vector<char> mask(M.F, 0);
      for(std::size_t f : region)
        mask[f] = 1;
      if(!repair_region(M, region, mask, report, 0) && !repair_region(M, region, mask, report, 1))
        repair_region(M, region, mask, report, 2);
    }
  }
  for(std::size_t f = 0; f < M.F; ++f)
    report.remaining += M.face_orientation(f) <= 0;
  if(report.remaining != 0)
    return Error_code::UNREPAIRABLE_FOLD_OVER;
  return Error_code::SUCCESS;
}

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_QEX_CHART_MESH_H
