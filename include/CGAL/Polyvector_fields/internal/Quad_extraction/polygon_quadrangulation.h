// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// Quads that fill a simple polygon of the plane with an even number of
// corners, without a point on its sides: a constrained Delaunay triangulation
// with points inside, whose triangles become quads once a parity is settled.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_POLYGON_QUADRANGULATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_POLYGON_QUADRANGULATION_H

#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/max_cardinality_matching.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {
namespace qex {

// ---------------------------------------------------------------------------
// The method. The polygon's inside is triangulated (constrained Delaunay, with
// points on a triangular lattice inside it). A triangle becomes quads when an odd
// number of its sides are split at their midpoints: three (three quads around its
// centroid) or one (one quad, with a straight angle at the midpoint). The sides of
// the polygon are never split, so the triangles along it start with an even count;
// they are paired, either merged with a neighbour into one convex quad (which needs
// an even count, and gets one), or joined to another one by a path of triangles
// across which the split of every side is switched (each triangle inside the path
// keeps its parity, the two ends change theirs). A pairing exists because the
// triangles are even in number: n + 2i - 2 for n corners and i inner points.
// The inner points are then smoothed, each move kept only if every quad around
// the point stays valid (not folded: one of its diagonals cuts it into two
// counterclockwise triangles).
// ---------------------------------------------------------------------------
struct Quadrangulated_polygon
{
  std::vector<std::array<double, 2> > points;       // the corners first (in their order), then the points inside
  std::vector<std::array<std::size_t, 4> > quads;   // counterclockwise
};

typedef std::array<double, 2> Q2;

// For Boost's matching: start from the matching already in the mate map.
template <typename Graph, typename MateMap>
struct Keep_matching
{
  static void find_matching(const Graph&, MateMap) {}
};

inline double orient2(const Q2& a, const Q2& b, const Q2& c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// Not folded: one diagonal cuts the quad into two counterclockwise triangles, each of
// area above `min_area`.
inline bool valid_quad(const Q2& a, const Q2& b, const Q2& c, const Q2& d, double min_area = 0)
{
  return (orient2(a, b, c) > min_area && orient2(a, c, d) > min_area) ||
         (orient2(b, c, d) > min_area && orient2(b, d, a) > min_area);
}

inline bool strictly_convex_quad(const Q2& a, const Q2& b, const Q2& c, const Q2& d)
{
  return orient2(a, b, c) > 0 && orient2(b, c, d) > 0 && orient2(c, d, a) > 0 && orient2(d, a, b) > 0;
}

// The smallest angle of a convex quad, for ranking merges.
inline double smallest_angle(const std::array<Q2, 4>& q)
{
  double smallest = CGAL_PI;
  for(int i = 0; i < 4; ++i)
  {
    const Q2 &p = q[i], &a = q[(i + 1) % 4], &b = q[(i + 3) % 4];
    const double ax = a[0] - p[0], ay = a[1] - p[1], bx = b[0] - p[0], by = b[1] - p[1];
    smallest = (std::min)(smallest, std::atan2(std::abs(ax * by - ay * bx), ax * bx + ay * by));
  }
  return smallest;
}

// Fills the domain bounded by `loops` with quads about `spacing` in size: loops[0] a
// simple counterclockwise polygon, the others simple clockwise polygons inside it (its
// holes), disjoint, an even number of corners in all (at least 4). The points of
// `out` are the loops' corners, loop after loop, then the points inside. False (with
// `why`) if the loops are not such a domain.
inline bool quadrangulate_domain(const std::vector<std::vector<Q2> >& loops, double spacing, Quadrangulated_polygon& out,
                                 std::string* why = nullptr)
{
  typedef Epick K;
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K> Vb;
  typedef CGAL::Constrained_triangulation_face_base_2<K> Fb0;
  typedef CGAL::Triangulation_face_base_with_info_2<int, K, Fb0> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag> CDT;
  auto fail = [&](const char* reason) {
    if(why)
      *why = reason;
    return false;
  };
  out = Quadrangulated_polygon();
  if(loops.empty())
    return fail("there is no polygon");
  // all the corners, and the next corner on each one's loop
  std::vector<Q2> corners;
  std::vector<std::size_t> next_corner;
  for(std::size_t l = 0; l < loops.size(); ++l)
  {
    if(loops[l].size() < 3)
      return fail("a loop has fewer than 3 corners");
    CGAL::Polygon_2<K> polygon;
    for(const Q2& p : loops[l])
    {
      if(!std::isfinite(p[0]) || !std::isfinite(p[1]))
        return fail("a corner is not finite");
      polygon.push_back(K::Point_2(p[0], p[1]));
    }
    if(!polygon.is_simple())
      return fail("the polygon is not simple");
    if(polygon.orientation() != (l == 0 ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE))
      return fail(l == 0 ? "the polygon is not counterclockwise" : "a hole is not clockwise");
    const std::size_t first = corners.size();
    for(std::size_t i = 0; i < loops[l].size(); ++i)
    {
      corners.push_back(loops[l][i]);
      next_corner.push_back(i + 1 < loops[l].size() ? corners.size() : first);
    }
  }
  const std::size_t n = corners.size(), holes = loops.size() - 1;
  if(n < 4 || n % 2 != 0)
    return fail("the polygon has an odd number of corners, or fewer than 4");
  if(!(spacing > 0) || !std::isfinite(spacing))
    return fail("the spacing is not a positive number");
  out.points = corners;
  // points inside, on a square lattice turned to the sides' main direction (their angles
  // modulo a quarter turn), at least half the spacing from the sides
  {
    double c4 = 0, s4 = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      const Q2 &a = corners[i], &b = corners[next_corner[i]];
      const double dx = b[0] - a[0], dy = b[1] - a[1], length = std::sqrt(dx * dx + dy * dy);
      const double angle = 4 * std::atan2(dy, dx);
      c4 += length * std::cos(angle);
      s4 += length * std::sin(angle);
    }
    const double turn = std::atan2(s4, c4) / 4, ct = std::cos(turn), st = std::sin(turn);
    // the corners in the lattice's frame
    std::vector<Q2> local(n);
    for(std::size_t i = 0; i < n; ++i)
      local[i] = { ct * corners[i][0] + st * corners[i][1], -st * corners[i][0] + ct * corners[i][1] };
    double lo[2] = { local[0][0], local[0][1] }, hi[2] = { lo[0], lo[1] };
    for(const Q2& p : local)
      for(int a = 0; a < 2; ++a)
      {
        lo[a] = (std::min)(lo[a], p[a]);
        hi[a] = (std::max)(hi[a], p[a]);
      }
    const double clearance2 = 0.25 * spacing * spacing;
    if(((hi[0] - lo[0]) / spacing + 2) * ((hi[1] - lo[1]) / spacing + 2) > 1e6)
      return fail("the spacing is too small for the polygon");
    auto segment_distance2 = [](const Q2& p, const Q2& a, const Q2& b) {
      const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
      double t = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0;
      t = (std::max)(0.0, (std::min)(1.0, t));
      const double ex = a[0] + t * dx - p[0], ey = a[1] + t * dy - p[1];
      return ex * ex + ey * ey;
    };
    // the lattice centred on the bounding box
    const double x0 = 0.5 * (lo[0] + hi[0]) - spacing * std::floor(0.5 * (hi[0] - lo[0]) / spacing);
    const double y0 = 0.5 * (lo[1] + hi[1]) - spacing * std::floor(0.5 * (hi[1] - lo[1]) / spacing);
    for(double y = y0; y < hi[1]; y += spacing)
      for(double x = x0; x < hi[0]; x += spacing)
      {
        const Q2 p{ x, y };
        // inside: the crossing number of a ray towards +x
        bool inside = false;
        double nearest = clearance2;
        for(std::size_t i = 0; i < n && nearest >= clearance2; ++i)
        {
          const Q2 &a = local[i], &b = local[next_corner[i]];
          if((a[1] > y) != (b[1] > y) && x < a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
            inside = !inside;
          nearest = (std::min)(nearest, segment_distance2(p, a, b));
        }
        if(inside && nearest >= clearance2)
          out.points.push_back({ ct * x - st * y, st * x + ct * y });
      }
  }
  CDT cdt;
  std::vector<CDT::Vertex_handle> handle(out.points.size());
  try
  {
    for(std::size_t i = 0; i < out.points.size(); ++i)
    {
      handle[i] = cdt.insert(K::Point_2(out.points[i][0], out.points[i][1]));
      handle[i]->info() = i;
    }
    for(std::size_t i = 0; i < n; ++i)
      cdt.insert_constraint(handle[i], handle[next_corner[i]]);
  }
  catch(const CGAL::Failure_exception&)
  {
    return fail("the sides of the polygon cross");
  }
  catch(const CDT::Intersection_of_constraints_exception&)
  {
    return fail("the sides of the polygon cross");
  }
  if(cdt.number_of_vertices() != out.points.size())
    return fail("two points of the polygon coincide");
  // the inside: faces reached from the infinite face across one side (inside a hole: two)
  for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    f->info() = -1;
  {
    std::deque<CDT::Face_handle> queue{ cdt.infinite_face() };
    cdt.infinite_face()->info() = 0;
    while(!queue.empty())
    {
      const CDT::Face_handle f = queue.front();
      queue.pop_front();
      for(int i = 0; i < 3; ++i)
      {
        const CDT::Face_handle g = f->neighbor(i);
        if(g->info() != -1)
          continue;
        g->info() = f->info() + (cdt.is_constrained(CDT::Edge(f, i)) ? 1 : 0);
        if(cdt.is_constrained(CDT::Edge(f, i)))
          queue.push_back(g);
        else
          queue.push_front(g);
      }
    }
  }
  // the inside triangles, with their neighbours across unconstrained sides
  std::vector<CDT::Face_handle> triangles;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if(f->info() == 1)
      triangles.push_back(f);
    else if(f->info() != 0 && f->info() != 2)
      return fail("the holes are not inside the polygon, or not apart");
  const std::size_t T = triangles.size();
  if(T % 2 != 0 || T != n + 2 * (out.points.size() - n) + 2 * holes - 2)
    return fail("the triangulation does not fill the polygon");
  std::vector<std::array<std::size_t, 3> > corner(T);       // counterclockwise
  std::vector<std::array<std::size_t, 3> > across(T);       // across side k (corner k to k+1): a triangle, or npos
  {
    for(std::size_t t = 0; t < T; ++t)
      triangles[t]->info() = int(2 + t);  // inside faces now carry their index
    for(std::size_t t = 0; t < T; ++t)
    {
      const CDT::Face_handle f = triangles[t];
      for(int k = 0; k < 3; ++k)
        corner[t][k] = f->vertex(k)->info();
      for(int k = 0; k < 3; ++k)
      {
        // side from vertex k to k+1 is opposite vertex k+2
        const int opposite = (k + 2) % 3;
        const CDT::Face_handle g = f->neighbor(opposite);
        across[t][k] = (!cdt.is_constrained(CDT::Edge(f, opposite)) && g->info() >= 2) ? std::size_t(g->info() - 2) : npos;
      }
    }
  }
  // sides: one index per unordered pair, split flags
  std::vector<std::array<std::size_t, 3> > side(T);
  std::vector<char> split;
  std::vector<std::pair<std::size_t, std::size_t> > side_triangles;  // the two triangles of an inner side
  for(std::size_t t = 0; t < T; ++t)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t u = across[t][k];
      if(u == npos)
      {
        side[t][k] = npos;
        continue;
      }
      if(u < t)
      {
        for(int j = 0; j < 3; ++j)
          if(across[u][j] == t)
            side[t][k] = side[u][j];
        continue;
      }
      side[t][k] = split.size();
      split.push_back(0);
      side_triangles.emplace_back(t, u);
    }
  // groups: a triangle alone, or two merged across a removed side
  std::vector<std::size_t> partner(T, npos), removed_side(T, npos);
  auto split_count = [&](std::size_t t) {
    int c = 0;
    for(int k = 0; k < 3; ++k)
      c += side[t][k] != npos && split[side[t][k]] && side[t][k] != removed_side[t];
    return c;
  };
  auto bad = [&](std::size_t t) { return partner[t] == npos && split_count(t) % 2 == 0; };
  // the triangles merged in pairs into strictly convex quads: a matching of the
  // largest size (Edmonds, from Boost), started from the best shaped merges
  {
    typedef boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS> Graph;
    typedef boost::graph_traits<Graph>::vertex_descriptor Node;
    struct Merge { double angle; std::size_t s; };
    std::vector<Merge> merges;
    Graph graph(T);
    for(std::size_t s = 0; s < side_triangles.size(); ++s)
    {
      const std::size_t t = side_triangles[s].first, u = side_triangles[s].second;
      int kt = 0, ku = 0;
      while(side[t][kt] != s) ++kt;
      while(side[u][ku] != s) ++ku;
      const std::array<Q2, 4> q{ { out.points[corner[t][(kt + 1) % 3]], out.points[corner[t][(kt + 2) % 3]],
                                   out.points[corner[t][kt]], out.points[corner[u][(ku + 2) % 3]] } };
      if(!strictly_convex_quad(q[0], q[1], q[2], q[3]))
        continue;
      merges.push_back({ smallest_angle(q), s });
      boost::add_edge(Node(t), Node(u), graph);
    }
    std::stable_sort(merges.begin(), merges.end(), [](const Merge& x, const Merge& y) { return x.angle > y.angle; });
    std::vector<Node> mate(T, boost::graph_traits<Graph>::null_vertex());
    for(const Merge& m : merges)
    {
      const std::size_t t = side_triangles[m.s].first, u = side_triangles[m.s].second;
      if(mate[t] == boost::graph_traits<Graph>::null_vertex() && mate[u] == boost::graph_traits<Graph>::null_vertex())
      {
        mate[t] = Node(u);
        mate[u] = Node(t);
      }
    }
    boost::matching<Graph, Node*, boost::property_map<Graph, boost::vertex_index_t>::type,
                    boost::edmonds_augmenting_path_finder, Keep_matching, boost::no_matching_verifier>(
      graph, mate.data(), boost::get(boost::vertex_index, graph));
    for(std::size_t t = 0; t < T; ++t)
    {
      if(mate[t] == boost::graph_traits<Graph>::null_vertex() || std::size_t(mate[t]) < t)
        continue;
      const std::size_t u = std::size_t(mate[t]);
      int k = 0;
      while(across[t][k] != u) ++k;
      partner[t] = u;
      partner[u] = t;
      removed_side[t] = removed_side[u] = side[t][k];
    }
  }
  // the other bad triangles in pairs, by the shortest path between them (through
  // inner sides that are not removed), switching the splits along it
  {
    std::vector<std::size_t> from(T), from_side(T);
    std::vector<char> seen(T);
    for(std::size_t t0 = 0; t0 < T; ++t0)
    {
      if(!bad(t0))
        continue;
      std::fill(seen.begin(), seen.end(), 0);
      std::deque<std::size_t> queue{ t0 };
      seen[t0] = 1;
      std::size_t end = npos;
      while(!queue.empty() && end == npos)
      {
        const std::size_t t = queue.front();
        queue.pop_front();
        // a merged pair is one node: leave it through either triangle
        const std::size_t members[2] = { t, partner[t] };
        for(std::size_t m : members)
        {
          if(m == npos)
            continue;
          for(int k = 0; k < 3 && end == npos; ++k)
          {
            const std::size_t s = side[m][k];
            if(s == npos || s == removed_side[m])
              continue;
            const std::size_t u = across[m][k];
            const std::size_t node = partner[u] != npos ? (std::min)(u, partner[u]) : u;
            if(seen[node])
              continue;
            seen[node] = 1;
            from[node] = t;
            from_side[node] = s;
            if(partner[u] == npos && bad(u))
              end = node;
            else
              queue.push_back(node);
          }
        }
      }
      if(end == npos)
        return fail("a triangle along the polygon could not be paired");
      for(std::size_t node = end; node != t0 && !(partner[t0] != npos && node == (std::min)(t0, partner[t0])); node = from[node])
        split[from_side[node]] ^= 1;
    }
  }
  // quads from the groups
  std::vector<std::size_t> midpoint(split.size(), npos);
  auto mid = [&](std::size_t s) {
    if(midpoint[s] == npos)
    {
      const std::size_t t = side_triangles[s].first;
      int k = 0;
      while(side[t][k] != s) ++k;
      const Q2 &a = out.points[corner[t][k]], &b = out.points[corner[t][(k + 1) % 3]];
      midpoint[s] = out.points.size();
      out.points.push_back({ 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]) });
    }
    return midpoint[s];
  };
  auto centre = [&](const std::vector<std::size_t>& ring) {
    Q2 c{ 0, 0 };
    for(std::size_t v : ring)
      for(int a = 0; a < 2; ++a)
        c[a] += out.points[v][a] / double(ring.size());
    out.points.push_back(c);
    return out.points.size() - 1;
  };
  for(std::size_t t = 0; t < T; ++t)
  {
    // the polygon of the group, with its split sides: w[i] and whether side i (w[i] to w[i+1]) is split
    std::vector<std::size_t> w;
    std::vector<std::size_t> sides;
    if(partner[t] == npos)
    {
      for(int k = 0; k < 3; ++k)
      {
        w.push_back(corner[t][k]);
        sides.push_back(side[t][k]);
      }
    }
    else
    {
      const std::size_t u = partner[t];
      if(u < t)
        continue;
      int kt = 0, ku = 0;
      while(side[t][kt] != removed_side[t]) ++kt;
      while(side[u][ku] != removed_side[u]) ++ku;
      w = { corner[t][(kt + 1) % 3], corner[t][(kt + 2) % 3], corner[t][kt], corner[u][(ku + 2) % 3] };
      sides = { side[t][(kt + 1) % 3], side[t][(kt + 2) % 3], side[u][(ku + 1) % 3], side[u][(ku + 2) % 3] };
    }
    const std::size_t m = w.size();
    std::vector<std::size_t> split_at;
    for(std::size_t i = 0; i < m; ++i)
      if(sides[i] != npos && split[sides[i]])
        split_at.push_back(i);
    const std::size_t c = split_at.size();
    if(m == 3 && c == 1)
    {
      const std::size_t i = split_at[0];
      out.quads.push_back({ w[i], mid(sides[i]), w[(i + 1) % 3], w[(i + 2) % 3] });
    }
    else if(c == m)
    {
      // every side split: m quads around the centre
      const std::size_t g = centre(w);
      for(std::size_t i = 0; i < m; ++i)
        out.quads.push_back({ w[i], mid(sides[i]), g, mid(sides[(i + m - 1) % m]) });
    }
    else if(m == 4 && c == 0)
      out.quads.push_back({ w[0], w[1], w[2], w[3] });
    else if(m == 4 && c == 2 && (split_at[1] - split_at[0]) == 2)
    {
      const std::size_t i = split_at[0];
      const std::size_t a = mid(sides[i]), b = mid(sides[i + 2]);
      out.quads.push_back({ w[i], a, b, w[(i + 3) % 4] });
      out.quads.push_back({ a, w[i + 1], w[i + 2], b });
    }
    else if(m == 4 && c == 2)
    {
      // two sides split at one corner w[i+1]: three quads around a centre
      const std::size_t i = (split_at[1] - split_at[0]) == 1 ? split_at[0] : split_at[1];
      const std::size_t a = mid(sides[i]), b = mid(sides[(i + 1) % 4]);
      const std::size_t g = centre(w);
      out.quads.push_back({ a, w[(i + 1) % 4], b, g });
      out.quads.push_back({ g, b, w[(i + 2) % 4], w[(i + 3) % 4] });
      out.quads.push_back({ w[i], a, g, w[(i + 3) % 4] });
    }
    else
      return fail("a triangle was left with the wrong parity");
  }
  // smoothing of the inner points: the mean of the parallelogram rule of each quad
  // around a point and of its neighbours' centroid, a move kept if its quads stay valid
  {
    const std::size_t P = out.points.size();
    std::vector<std::vector<std::pair<std::size_t, int> > > around(P);  // (quad, corner)
    for(std::size_t q = 0; q < out.quads.size(); ++q)
      for(int k = 0; k < 4; ++k)
        around[out.quads[q][k]].emplace_back(q, k);
    double min_area = 1e-12 * spacing * spacing;
    auto quad_ok = [&](std::size_t q) {
      const auto& Q = out.quads[q];
      return valid_quad(out.points[Q[0]], out.points[Q[1]], out.points[Q[2]], out.points[Q[3]], min_area);
    };
    for(std::size_t q = 0; q < out.quads.size(); ++q)
      if(!valid_quad(out.points[out.quads[q][0]], out.points[out.quads[q][1]], out.points[out.quads[q][2]],
                     out.points[out.quads[q][3]]))
        return fail("a quad of the filling is folded");
    for(int iteration = 0; iteration < 40; ++iteration)
      for(std::size_t v = n; v < P; ++v)
      {
        Q2 para{ 0, 0 }, ring{ 0, 0 };
        for(const auto& a : around[v])
        {
          const auto& Q = out.quads[a.first];
          const Q2 &p = out.points[Q[(a.second + 1) % 4]], &o = out.points[Q[(a.second + 2) % 4]],
                   &r = out.points[Q[(a.second + 3) % 4]];
          for(int c = 0; c < 2; ++c)
          {
            para[c] += (p[c] + r[c] - o[c]) / double(around[v].size());
            ring[c] += 0.5 * (p[c] + r[c]) / double(around[v].size());
          }
        }
        const Q2 old = out.points[v];
        const Q2 target{ 0.5 * (para[0] + ring[0]), 0.5 * (para[1] + ring[1]) };
        for(double step : { 1.0, 0.5, 0.25 })
        {
          out.points[v] = { old[0] + step * (target[0] - old[0]), old[1] + step * (target[1] - old[1]) };
          bool ok = true;
          for(const auto& a : around[v])
            ok = ok && quad_ok(a.first);
          if(ok)
            break;
          out.points[v] = old;
        }
      }
  }
  return true;
}

// The domain of one simple counterclockwise polygon.
inline bool quadrangulate_polygon(const std::vector<Q2>& corners, double spacing, Quadrangulated_polygon& out,
                                  std::string* why = nullptr)
{
  return quadrangulate_domain(std::vector<std::vector<Q2> >{ corners }, spacing, out, why);
}

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_POLYGON_QUADRANGULATION_H
