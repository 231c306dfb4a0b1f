// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The input vertices that the quads leave far away (the tip of a spike, the end
// of a thin part finer than the quads), each pulling the nearest quad corner onto
// itself, and the largest distance of an input vertex or face centroid to the quads
// in each component.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_TIP_SNAPPING_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_TIP_SNAPPING_H

#include <CGAL/Polyvector_fields/internal/Quad_extraction/Chart_mesh.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/fold_check.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {
namespace qex {

// The distance of points to the quads, each quad cut along its diagonal from corner 0.
class Quad_distance
{
  typedef Epick::Point_3 Point;
  typedef Epick::Triangle_3 Triangle;
  typedef Triangle_tree Tree;

public:
  Quad_distance(const std::vector<std::vector<std::size_t> >& quads, const std::vector<P3>& pos)
  {
    auto point = [&](std::size_t v) { return Point(pos[v][0], pos[v][1], pos[v][2]); };
    for(std::size_t f = 0; f < quads.size(); ++f)
      if(quads[f].size() == 4)
        for(std::size_t k = 1; k < 3; ++k)
        {
          triangles_.emplace_back(point(quads[f][0]), point(quads[f][k]), point(quads[f][k + 1]));
          quad_.push_back(f);
        }
    if(!triangles_.empty())
    {
      tree_.insert(triangles_.cbegin(), triangles_.cend());
      tree_.build();
      tree_.accelerate_distance_queries();
    }
  }
  bool empty() const { return triangles_.empty(); }
  // the distance of p to the quads, and the quad of its nearest point
  std::pair<double, std::size_t> nearest(const P3& p) const
  {
    const auto hit = tree_.closest_point_and_primitive(Point(p[0], p[1], p[2]));
    return { std::sqrt(CGAL::squared_distance(hit.first, Point(p[0], p[1], p[2]))),
             quad_[std::size_t(hit.second - triangles_.cbegin())] };
  }

  // the distance of the input vertex v to the quads, for each v with `wanted[v]` (0 for the others);
  // the queries only read the tree, so with `parallel` they are shared among threads
  std::vector<double> vertex_distances(const Chart_mesh& M, const std::vector<char>& wanted, bool parallel) const
  {
    std::vector<double> d(M.V, 0.);
    for_each_range(parallel, M.V, 1024, [&](std::size_t begin, std::size_t end) {
      for(std::size_t v = begin; v < end; ++v)
        if(wanted[v])
          d[v] = nearest(M.point[v]).first;
    });
    return d;
  }

private:
  std::vector<Triangle> triangles_;
  std::vector<std::size_t> quad_;
  Tree tree_;
};

// The quads in their tree, and the distance of every vertex of a face of the
// input to them (0 for the other vertices), for one set of quad positions.
struct Quad_distances
{
  std::unique_ptr<Quad_distance> tree;
  std::vector<double> vertex;
};

// The input vertices of faces (the vertices measured by Quad_distances).
inline std::vector<char> vertices_in_faces(const Chart_mesh& M)
{
  std::vector<char> in_face(M.V, 0);
  for(std::size_t f = 0; f < M.F; ++f)
    for(std::size_t k = 0; k < 3; ++k)
      in_face[M.vertex[3 * f + k]] = 1;
  return in_face;
}

inline Quad_distances quad_distances(const Chart_mesh& M, const std::vector<std::vector<std::size_t> >& quads,
                                     const std::vector<P3>& pos, bool parallel)
{
  Quad_distances d;
  d.tree.reset(new Quad_distance(quads, pos));
  d.vertex = d.tree->empty() ? std::vector<double>(M.V, 0.) : d.tree->vertex_distances(M, vertices_in_faces(M), parallel);
  return d;
}

struct Tip_report
{
  std::size_t snapped = 0;        // quad corners moved onto input vertices
  Quad_distances final_distances; // of the positions after the snapping (no tree: not measured)
};

// quads[f]: the corners of quad f (empty: not a quad); under[f]: the surface faces under
// it (the faces around a vertex that a corner moves onto are added); pos: the corners'
// positions. An input vertex farther than `threshold` from the quads moves the nearest
// corner of its nearest quad onto itself, if every quad at that corner then stays
// unfolded on the surface and keeps its sides longer than a hundredth of the threshold;
// each corner moves once, and the corners on the border of the quads never; the vertices on
// the surface's border pull none.
// check: the surface M in its tree. With `parallel`, the distances are computed on
// several threads (the same result).
inline Tip_report snap_to_tips(const Chart_mesh& M, const Fold_check& check,
                               const std::vector<std::vector<std::size_t> >& quads,
                               std::vector<std::vector<std::size_t> >& under, std::vector<P3>& pos, double threshold,
                               bool parallel)
{
  Tip_report report;
  // (not the border's vertices: a border left free is the strip that whole cells leave)
  std::vector<char> pulling(M.V, 0);
  for(std::size_t v = 0; v < M.V; ++v)
    pulling[v] = !M.fan[v].empty() && !M.border_vertex[v];
  if(threshold > 0)
  {
    std::vector<std::vector<std::size_t> > corner_quads(pos.size());
    for(std::size_t f = 0; f < quads.size(); ++f)
      for(std::size_t c : quads[f])
        corner_quads[c].push_back(f);
    // corners on the border of the quads stay (they keep the quads up to the surface's border)
    std::vector<char> moved(pos.size(), 0);
    {
      std::map<std::pair<std::size_t, std::size_t>, int> sides;
      for(const auto& q : quads)
        for(std::size_t k = 0; k < q.size(); ++k)
          ++sides[std::make_pair((std::min)(q[k], q[(k + 1) % q.size()]), (std::max)(q[k], q[(k + 1) % q.size()]))];
      for(const auto& s : sides)
        if(s.second == 1)
          moved[s.first.first] = moved[s.first.second] = 1;
    }
    for(int pass = 0; pass < 3; ++pass)
    {
      Quad_distances measured = quad_distances(M, quads, pos, parallel);
      const Quad_distance& distance = *measured.tree;
      if(distance.empty())
        break;
      std::vector<std::pair<double, std::size_t> > far;
      const std::vector<double>& d = measured.vertex;
      for(std::size_t v = 0; v < M.V; ++v)
        if(pulling[v] && d[v] > threshold)
          far.emplace_back(d[v], v);
      if(far.empty())
      {
        report.final_distances = std::move(measured);  // nothing moves any more
        break;
      }
      std::sort(far.begin(), far.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
      std::vector<char> locked(quads.size(), 0);
      std::size_t snapped = 0;
      for(const auto& x : far)
      {
        const P3& tip = M.point[x.second];
        const std::size_t f = distance.nearest(tip).second;
        if(locked[f])
          continue;
        std::vector<std::size_t> corners = quads[f];
        std::sort(corners.begin(), corners.end(), [&](std::size_t a, std::size_t b) {
          return dot3(sub3(pos[a], tip), sub3(pos[a], tip)) < dot3(sub3(pos[b], tip), sub3(pos[b], tip));
        });
        std::vector<std::size_t> fan_faces;
        for(std::size_t c : M.fan[x.second])
          fan_faces.push_back(Chart_mesh::face(c));
        for(std::size_t c : corners)
        {
          if(moved[c])
            continue;
          bool free = true;
          for(std::size_t g : corner_quads[c])
            free = free && !locked[g];
          if(!free)
            continue;
          const P3 old = pos[c];
          pos[c] = tip;
          bool good = true;
          for(std::size_t g : corner_quads[c])
          {
            std::vector<std::size_t> below = under[g];
            below.insert(below.end(), fan_faces.begin(), fan_faces.end());
            const std::array<P3, 4> q{ { pos[quads[g][0]], pos[quads[g][1]], pos[quads[g][2]], pos[quads[g][3]] } };
            for(int k = 0; k < 4 && good; ++k)
            {
              const P3 side = sub3(q[(k + 1) % 4], q[k]);
              good = dot3(side, side) > 1e-4 * threshold * threshold;
            }
            good = good && !check.folded(q, below);
            if(!good)
              break;
          }
          if(!good)
          {
            pos[c] = old;
            continue;
          }
          moved[c] = 1;
          ++snapped;
          for(std::size_t g : corner_quads[c])
          {
            locked[g] = 1;
            under[g].insert(under[g].end(), fan_faces.begin(), fan_faces.end());
            std::sort(under[g].begin(), under[g].end());
            under[g].erase(std::unique(under[g].begin(), under[g].end()), under[g].end());
          }
          break;
        }
      }
      report.snapped += snapped;
      if(snapped == 0)
      {
        report.final_distances = std::move(measured);  // nothing moved: still these positions
        break;
      }
    }
  }
  return report;
}

// The largest distance of an input vertex or face centroid to the quads, for each
// connected component of the input (`component` of each face, `components` of them).
// Each vertex is measured once, and not again when `known` has a tree (then it holds
// the distances of these quads and positions); with `parallel`, the distances are
// computed on several threads (a maximum of the same distances: the same result).
inline std::vector<double> input_distances(const Chart_mesh& M, const std::vector<std::vector<std::size_t> >& quads,
                                           const std::vector<P3>& pos, const std::vector<std::size_t>& component,
                                           std::size_t components, bool parallel, Quad_distances known = {})
{
  std::vector<double> largest(components, 0);
  const Quad_distances measured = known.tree ? std::move(known) : quad_distances(M, quads, pos, parallel);
  const Quad_distance& distance = *measured.tree;
  if(distance.empty())
    return largest;
  const std::vector<double>& vertex = measured.vertex;
  std::vector<double> centroid(M.F, 0.);
  for_each_range(parallel, M.F, 1024, [&](std::size_t begin, std::size_t end) {
    for(std::size_t f = begin; f < end; ++f)
    {
      P3 c{ 0, 0, 0 };
      for(std::size_t k = 0; k < 3; ++k)
        for(int a = 0; a < 3; ++a)
          c[a] += M.point[M.vertex[3 * f + k]][a] / 3;
      centroid[f] = distance.nearest(c).first;
    }
  });
  for(std::size_t f = 0; f < M.F; ++f)
  {
    double& l = largest[component[f]];
    l = (std::max)(l, centroid[f]);
    for(std::size_t k = 0; k < 3; ++k)
      l = (std::max)(l, vertex[M.vertex[3 * f + k]]);
  }
  return largest;
}

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_TIP_SNAPPING_H
