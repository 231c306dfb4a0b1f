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
#include <CGAL/Polyvector_fields/internal/types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
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

private:
  std::vector<Triangle> triangles_;
  std::vector<std::size_t> quad_;
  Tree tree_;
};

struct Tip_report
{
  std::size_t snapped = 0;        // quad corners moved onto input vertices
};

// quads[f]: the corners of quad f (empty: not a quad); under[f]: the surface faces under
// it (the faces around a vertex that a corner moves onto are added); pos: the corners'
// positions. An input vertex farther than `threshold` from the quads moves the nearest
// corner of its nearest quad onto itself, if every quad at that corner then stays
// unfolded on the surface and keeps its sides longer than a hundredth of the threshold;
// each corner moves once, and the corners on the border of the quads never; the vertices on
// the surface's border pull none.
inline Tip_report snap_to_tips(const Chart_mesh& M, const std::vector<std::vector<std::size_t> >& quads,
                               std::vector<std::vector<std::size_t> >& under, std::vector<P3>& pos, double threshold,
                               bool snap)
{
  Tip_report report;
  std::vector<char> used(M.V, 0);
  for(std::size_t v = 0; v < M.V; ++v)
    used[v] = !M.fan[v].empty();
  if(snap && threshold > 0)
  {
    std::vector<std::vector<std::size_t> > corner_quads(pos.size());
    for(std::size_t f = 0; f < quads.size(); ++f)
      for(std::size_t c : quads[f])
        corner_quads[c].push_back(f);
    const Fold_check check(M);
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
      const Quad_distance distance(quads, pos);
      if(distance.empty())
        break;
      std::vector<std::pair<double, std::size_t> > far;
      // (not the border's vertices: a border left free is the strip that whole cells leave)
      for(std::size_t v = 0; v < M.V; ++v)
        if(used[v] && !M.border_vertex[v])
        {
          const double d = distance.nearest(M.point[v]).first;
          if(d > threshold)
            far.emplace_back(d, v);
        }
      if(far.empty())
        break;
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
        break;
    }
  }
  return report;
}

// The largest distance of an input vertex or face centroid to the quads, for each
// connected component of the input (`component` of each face, `components` of them).
inline std::vector<double> input_distances(const Chart_mesh& M, const std::vector<std::vector<std::size_t> >& quads,
                                           const std::vector<P3>& pos, const std::vector<std::size_t>& component,
                                           std::size_t components)
{
  std::vector<double> largest(components, 0);
  const Quad_distance distance(quads, pos);
  if(distance.empty())
    return largest;
  for(std::size_t f = 0; f < M.F; ++f)
  {
    P3 c{ 0, 0, 0 };
    for(std::size_t k = 0; k < 3; ++k)
    {
      const P3& x = M.point[M.vertex[3 * f + k]];
      largest[component[f]] = (std::max)(largest[component[f]], distance.nearest(x).first);
      for(int a = 0; a < 3; ++a)
        c[a] += x[a] / 3;
    }
    largest[component[f]] = (std::max)(largest[component[f]], distance.nearest(c).first);
  }
  return largest;
}

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_TIP_SNAPPING_H
