// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// Trimmed cells (keep_trimmed_boundary) that go around the surface: where the
// quads are as large as a cylinder, a cell bounded by iso-lines and by the
// border can meet itself (its polygon passes twice through a point) and an
// iso-line can close on itself (a loop through one point) or join the same two
// points as another one. Such a cell is still one region of the surface, but
// not a polygon: here the iso-line segments that would be loops or double
// edges get points inside them (found by tracing the iso-line part of the
// way), and the polygons that pass twice through a vertex are cut by
// diagonals between their own corners until every piece is a simple polygon.
// The caller then checks the result (a polygon mesh with the Euler
// characteristic of the surface).

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_SPLIT_WRAPPING_CELLS_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_SPLIT_WRAPPING_CELLS_H

#include <CGAL/Polyvector_fields/internal/Quad_extraction/Chart_mesh.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/Extractor.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {
namespace qex {

// A point inside an iso-line segment: the face it lies in and its uv in that face's chart.
struct Inner_point
{
  std::size_t face = npos;
  P2 uv{ 0, 0 };
};

// True if some vertex appears twice in the cyclic polygon.
inline bool has_repeated_vertex(const std::vector<std::size_t>& polygon)
{
  std::vector<std::size_t> sorted(polygon);
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

// The length (in uv units, in (0, 1]) of the iso-line segment traced from slot s:
// 1 for a trace that reached an integer point, the distance to the border for one
// that left the surface. 0 if it cannot be told.
inline double traced_segment_length(const Chart_mesh& M, const Trace_end& E)
{
  if(E.complete)
    return 1;
  const int along = (E.dir & 1) ? 1 : 0;  // the coordinate that varies along the line
  double hit;
  if(E.hit_corner != npos)
    hit = M.uv[E.hit_corner][along];
  else if(E.hit_edge != npos)
  {
    const P2 &A = M.uv[E.hit_edge], &B = M.uv[Chart_mesh::next(E.hit_edge)];
    const int constant = 1 - along;
    if(A[constant] == B[constant])
      return 0;
    const double lam = (E.q[constant] - A[constant]) / (B[constant] - A[constant]);
    hit = A[along] + lam * (B[along] - A[along]);
  }
  else
    return 0;
  const double length = 1 - std::abs(E.q[along] - hit);
  return length > 0 && length <= 1 ? length : 0;
}

// In `polygons` (one per cell, parallel to `cells`: polygons[f][k] is the output
// vertex of the corner at slot cells[f][k]), inserts points inside the iso-line
// segments that join a vertex to itself (two points) or join the same two vertices
// as another segment (one point). The new points get the vertex indices
// vertex_count, vertex_count + 1, ... in the order of `inner`. `changed[f]` is set
// for the cells that got points. Returns the number of loops and of pairs of vertices
// joined by several segments that could not be resolved (points needed in a boundary
// piece, or a trace that did not reach its point).
inline std::size_t subdivide_wrapping_segments(const Chart_mesh& M, const Extractor& X,
                                               const std::vector<std::vector<std::size_t> >& cells,
                                               const std::vector<Trace_end>& ends, std::size_t vertex_count,
                                               std::vector<std::vector<std::size_t> >& polygons,
                                               std::vector<Inner_point>& inner, std::vector<char>& changed)
{
  // segment of the side leaving slot s: the smaller slot of the pair
  auto segment = [&](std::size_t s) { return (std::min)(s, X.slots[s].partner); };
  std::map<std::pair<std::size_t, std::size_t>, std::set<std::size_t> > segments_of_pair;
  for(std::size_t f = 0; f < cells.size(); ++f)
  {
    const std::size_t n = cells[f].size();
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::size_t a = polygons[f][k], b = polygons[f][(k + 1) % n];
      segments_of_pair[std::make_pair((std::min)(a, b), (std::max)(a, b))].insert(segment(cells[f][k]));
    }
  }
  // points to insert per segment, from the traced slot of the segment (ordered from it)
  std::map<std::size_t, std::pair<std::size_t, std::vector<std::size_t> > > points_of_segment;  // segment -> (traced slot, vertices)
  std::size_t failed = 0;
  for(const auto& entry : segments_of_pair)
  {
    const bool loop = entry.first.first == entry.first.second;
    if(!loop && entry.second.size() < 2)
      continue;
    const std::size_t count = loop ? 2 : 1;
    // a loop needs its points; of the segments that join the same two vertices, all
    // but one need a point (a boundary piece among them cannot get one)
    std::size_t without = 0;
    for(std::size_t seg : entry.second)
    {
      if(points_of_segment.count(seg) != 0)
        continue;
      // the slot whose trace gives the segment: a traced iso-line slot of the pair
      std::size_t traced = npos;
      for(std::size_t s : { seg, X.slots[seg].partner })
        if(traced == npos && s < ends.size() && X.slots[s].dir >= 0 && !ends[s].error &&
           (ends[s].complete || ends[s].hit_edge != npos || ends[s].hit_corner != npos))
          traced = s;
      const double length = traced == npos ? 0 : traced_segment_length(M, ends[traced]);
      if(length <= 0)
      {
        ++without;
        continue;
      }
      std::vector<std::size_t> vertices;
      for(std::size_t j = 1; j <= count; ++j)
      {
        const Trace_end E = X.trace(X.slots[traced], length * double(j) / double(count + 1));
        if(!E.complete || E.error)
          break;
        Inner_point p;
        p.face = E.face;
        p.uv = E.q;
        vertices.push_back(vertex_count + inner.size());
        inner.push_back(p);
      }
      if(vertices.size() != count)
      {
        inner.resize(inner.size() - vertices.size());
        ++without;
        continue;
      }
      points_of_segment.emplace(seg, std::make_pair(traced, vertices));
    }
    if(loop ? without != 0 : without > 1)
      ++failed;
  }
  if(points_of_segment.empty())
    return failed;
  for(std::size_t f = 0; f < cells.size(); ++f)
  {
    const std::size_t n = cells[f].size();
    std::vector<std::size_t> polygon;
    for(std::size_t k = 0; k < n; ++k)
    {
      polygon.push_back(polygons[f][k]);
      const std::size_t s = cells[f][k];
      auto it = points_of_segment.find(segment(s));
      if(it == points_of_segment.end())
        continue;
      const std::vector<std::size_t>& v = it->second.second;
      // the points are in the order of the traced slot; this side leaves slot s
      if(it->second.first == s)
        polygon.insert(polygon.end(), v.begin(), v.end());
      else
        polygon.insert(polygon.end(), v.rbegin(), v.rend());
      changed[f] = 1;
    }
    polygons[f].swap(polygon);
  }
  return failed;
}

// Cuts `polygon` by diagonals between its corners until no piece passes twice
// through a vertex; appends the pieces to `pieces`. A diagonal joins two vertices
// that appear once in the polygon and are not joined by an edge yet (`edges`, the
// undirected edges of all polygons, gets the diagonals), leaves at least 3 corners
// on each side, and leaves as few repeated vertices as possible; among those, the
// one whose shorter side is the longest (perimeter along the polygon minus the
// diagonal's length, with `position` the output points). Returns false if some
// piece keeps a repeated vertex (it is appended as it is).
inline bool split_at_repeated_vertices(const std::vector<std::size_t>& polygon,
                                       const std::vector<std::array<double, 3> >& position,
                                       std::set<std::pair<std::size_t, std::size_t> >& edges,
                                       std::vector<std::vector<std::size_t> >& pieces)
{
  auto distance = [&](std::size_t a, std::size_t b) {
    const auto &p = position[a], &q = position[b];
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  };
  bool ok = true;
  std::vector<std::vector<std::size_t> > stack(1, polygon);
  while(!stack.empty())
  {
    std::vector<std::size_t> p;
    p.swap(stack.back());
    stack.pop_back();
    const std::size_t n = p.size();
    // the pairs of positions of the same vertex
    std::map<std::size_t, std::vector<std::size_t> > at;
    for(std::size_t k = 0; k < n; ++k)
      at[p[k]].push_back(k);
    std::vector<std::pair<std::size_t, std::size_t> > repeats;
    std::vector<char> repeated(n, 0);
    for(const auto& entry : at)
      for(std::size_t i = 0; i < entry.second.size(); ++i)
      {
        repeated[entry.second[i]] = entry.second.size() > 1;
        for(std::size_t j = i + 1; j < entry.second.size(); ++j)
          repeats.emplace_back(entry.second[i], entry.second[j]);
      }
    if(repeats.empty())
    {
      pieces.push_back(p);
      continue;
    }
    std::vector<double> prefix(n + 1, 0);  // perimeter from corner 0 to corner k
    for(std::size_t k = 0; k < n; ++k)
      prefix[k + 1] = prefix[k] + distance(p[k], p[(k + 1) % n]);
    std::size_t best_i = npos, best_j = npos, best_left = repeats.size();
    double best_score = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      if(repeated[i])
        continue;
      for(std::size_t j = i + 2; j < n; ++j)
      {
        if(repeated[j] || (i == 0 && j + 1 == n))
          continue;
        if(edges.count(std::make_pair((std::min)(p[i], p[j]), (std::max)(p[i], p[j]))) != 0)
          continue;
        // sides [i..j] and [j..n-1, 0..i]: a repeat stays if both of its corners are on one side
        std::size_t left = 0;
        for(const auto& r : repeats)
          left += ((r.first > i && r.first < j) == (r.second > i && r.second < j)) ? 1 : 0;
        const double side = prefix[j] - prefix[i];
        const double score = (std::min)(side, prefix[n] - side) - distance(p[i], p[j]);
        if(left < best_left || (left == best_left && best_i != npos && score > best_score))
        {
          best_i = i;
          best_j = j;
          best_left = left;
          best_score = score;
        }
      }
    }
    if(best_i == npos)
    {
      ok = false;
      pieces.push_back(p);
      continue;
    }
    edges.insert(std::make_pair((std::min)(p[best_i], p[best_j]), (std::max)(p[best_i], p[best_j])));
    stack.emplace_back(p.begin() + std::ptrdiff_t(best_i), p.begin() + std::ptrdiff_t(best_j) + 1);
    std::vector<std::size_t> other(p.begin() + std::ptrdiff_t(best_j), p.end());
    other.insert(other.end(), p.begin(), p.begin() + std::ptrdiff_t(best_i) + 1);
    stack.push_back(other);
  }
  return ok;
}

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_SPLIT_WRAPPING_CELLS_H
