// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The check of the extracted quads against the surface they came from: a quad
// is folded when neither of its diagonals splits it into two triangles that
// face the side of the input surface under it.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_FOLD_CHECK_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_FOLD_CHECK_H

#include <CGAL/Polyvector_fields/internal/Quad_extraction/Chart_mesh.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {
namespace qex {

typedef std::array<double, 3> P3;

inline P3 sub3(const P3& a, const P3& b) { return { a[0] - b[0], a[1] - b[1], a[2] - b[2] }; }
inline P3 cross3(const P3& a, const P3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline double dot3(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The (unnormalised) normal of face f of the chart mesh, on the side its charts are counterclockwise.
inline P3 face_normal(const Chart_mesh& M, std::size_t f)
{
  const P3 &a = M.point[M.vertex[3 * f]], &b = M.point[M.vertex[3 * f + 1]], &c = M.point[M.vertex[3 * f + 2]];
  return cross3(sub3(b, a), sub3(c, a));
}

// Is the quad q folded against the surface normal n: for each of its two diagonals,
// one of the two triangles faces away from n (or is orthogonal to it). A quad with
// one good diagonal (a dart, a corner near 180 degrees) is not folded.
inline bool is_folded_quad(const std::array<P3, 4>& q, const P3& n)
{
  const P3 split[2][2] = { { cross3(sub3(q[1], q[0]), sub3(q[2], q[0])), cross3(sub3(q[2], q[0]), sub3(q[3], q[0])) },
                           { cross3(sub3(q[2], q[1]), sub3(q[3], q[1])), cross3(sub3(q[3], q[1]), sub3(q[0], q[1])) } };
  for(int diagonal = 0; diagonal < 2; ++diagonal)
    if(dot3(split[diagonal][0], n) > 0 && dot3(split[diagonal][1], n) > 0)
      return false;
  return true;
}

// An AABB tree of triangles kept in a vector.
typedef CGAL::AABB_tree<CGAL::AABB_traits<
  Epick, CGAL::AABB_triangle_primitive<Epick, std::vector<Epick::Triangle_3>::const_iterator> > >
  Triangle_tree;

// The input surface near the quads: the faces of the chart mesh in an AABB tree.
class Fold_check
{
  typedef Epick::Point_3 Point;
  typedef Epick::Triangle_3 Triangle;
  typedef Triangle_tree Tree;

public:
  explicit Fold_check(const Chart_mesh& M) : M_(M)
  {
    triangles_.reserve(M.F);
    for(std::size_t f = 0; f < M.F; ++f)
    {
      const P3 &a = M.point[M.vertex[3 * f]], &b = M.point[M.vertex[3 * f + 1]], &c = M.point[M.vertex[3 * f + 2]];
      triangles_.emplace_back(Point(a[0], a[1], a[2]), Point(b[0], b[1], b[2]), Point(c[0], c[1], c[2]));
    }
    tree_.insert(triangles_.cbegin(), triangles_.cend());
    tree_.build();
    // the search tree of the distance queries too, here rather than lazily in
    // the first query: the queries of folded() come from several threads
    tree_.accelerate_distance_queries();
  }

  // The quad q is folded against the faces it came from: against the normal of an
  // input face nearest to its centroid (any of them, on a tie: the nearest point on an
  // edge or at a vertex), or against the sum of the normals of the faces
  // `under` it (the faces its sides were traced through).
  bool folded(const std::array<P3, 4>& q, const std::vector<std::size_t>& under) const
  {
    P3 sum{ 0, 0, 0 };
    for(std::size_t f : under)
    {
      const P3 nf = face_normal(M_, f);
      sum = { sum[0] + nf[0], sum[1] + nf[1], sum[2] + nf[2] };
    }
    if(!under.empty() && is_folded_quad(q, sum))
      return true;
    const Point centroid((q[0][0] + q[1][0] + q[2][0] + q[3][0]) / 4, (q[0][1] + q[1][1] + q[2][1] + q[3][1]) / 4,
                         (q[0][2] + q[1][2] + q[2][2] + q[3][2]) / 4);
    const auto hit = tree_.closest_point_and_primitive(centroid);
    const std::size_t f = std::size_t(hit.second - triangles_.cbegin());
    if(is_folded_quad(q, face_normal(M_, f)))
      return true;
    // the faces as near as f (the nearest point on an edge or at a vertex, as on a ridge)
    const double d2 = CGAL::squared_distance(centroid, hit.first);
    for(std::size_t k = 0; k < 3; ++k)
      for(std::size_t c : M_.fan[M_.vertex[3 * f + k]])
      {
        const std::size_t g = Chart_mesh::face(c);
        if(g != f && CGAL::squared_distance(centroid, triangles_[g]) <= d2 * (1 + 1e-9) &&
           is_folded_quad(q, face_normal(M_, g)))
          return true;
      }
    return false;
  }

private:
  const Chart_mesh& M_;
  std::vector<Triangle> triangles_;
  Tree tree_;
};

// The quads of the output and the faces under each of them, with the repair of the
// folded ones: a corner of a folded quad is moved to a point of the surface under the
// quads around it (a vertex of one of their faces, or the midpoint of an edge), the
// nearest one that leaves all these quads unfolded. A fold comes from a surface that
// bends by more than a right angle under one quad (a crease or a thin ridge of the
// input, at a scale finer than the quads): the corner moves onto the ridge.
struct Fold_report
{
  std::size_t folded = 0;          // quads folded before the repair
  std::size_t unfolded = 0;        // of which repaired
  std::size_t moved_vertices = 0;  // corners moved by the repair
  std::size_t first_folded = npos; // a quad still folded after the repair
  std::vector<std::size_t> still_folded;  // every such quad
};

// quads[f]: the output vertices of quad f (empty: a face that is not checked); under[f]:
// the input faces under it; pos: the output vertex positions, moved by the repair;
// check: the surface M in its tree. With `parallel`, the first check of every quad
// is shared among threads (each quad on its own: the same result).
inline Fold_report unfold_quads(const Chart_mesh& M, const Fold_check& check,
                                const std::vector<std::vector<std::size_t> >& quads,
                                const std::vector<std::vector<std::size_t> >& under, std::vector<P3>& pos, bool repair,
                                bool parallel)
{
  Fold_report report;
  auto folded = [&](std::size_t f) {
    const std::array<P3, 4> q{ { pos[quads[f][0]], pos[quads[f][1]], pos[quads[f][2]], pos[quads[f][3]] } };
    return check.folded(q, under[f]);
  };
  std::vector<char> is_folded(quads.size(), 0);
  for_each_range(parallel, quads.size(), 512, [&](std::size_t begin, std::size_t end) {
    for(std::size_t f = begin; f < end; ++f)
      is_folded[f] = quads[f].size() == 4 && folded(f) ? 1 : 0;
  });
  std::vector<std::size_t> list;
  for(std::size_t f = 0; f < quads.size(); ++f)
    if(is_folded[f])
      list.push_back(f);
  report.folded = list.size();
  if(repair && !list.empty())
  {
    std::vector<std::vector<std::size_t> > vertex_quads(pos.size());
    for(std::size_t f = 0; f < quads.size(); ++f)
      for(std::size_t v : quads[f])
        vertex_quads[v].push_back(f);
    for(int pass = 0; pass < 4; ++pass)
    {
      bool progress = false;
      for(std::size_t f : list)
      {
        if(!is_folded[f])
          continue;
        // the regular corners first (four quads around them): a singular point stays where the map put it if it can
        std::vector<std::size_t> corners = quads[f];
        std::stable_sort(corners.begin(), corners.end(),
                         [&](std::size_t a, std::size_t b) { return (vertex_quads[a].size() != 4) < (vertex_quads[b].size() != 4); });
        for(std::size_t v : corners)
        {
          // candidates: the vertices and edge midpoints of the faces under the quads at v
          std::vector<P3> candidates;
          for(std::size_t g : vertex_quads[v])
            for(std::size_t t : under[g])
              for(std::size_t k = 0; k < 3; ++k)
              {
                const P3 &a = M.point[M.vertex[3 * t + k]], &b = M.point[M.vertex[3 * t + (k + 1) % 3]];
                candidates.push_back(a);
                candidates.push_back({ 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) });
              }
          std::sort(candidates.begin(), candidates.end());
          candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
          const P3 old = pos[v];
          std::sort(candidates.begin(), candidates.end(), [&](const P3& a, const P3& b) {
            return dot3(sub3(a, old), sub3(a, old)) < dot3(sub3(b, old), sub3(b, old));
          });
          bool moved = false;
          for(const P3& c : candidates)
          {
            pos[v] = c;
            bool good = true;
            for(std::size_t g : vertex_quads[v])
              good = good && (quads[g].size() != 4 || !folded(g));
            if(good)
            {
              moved = true;
              break;
            }
          }
          if(!moved)
          {
            pos[v] = old;
            continue;
          }
          ++report.moved_vertices;
          for(std::size_t g : vertex_quads[v])
            is_folded[g] = 0;
          progress = true;
          break;
        }
      }
      if(!progress)
        break;
    }
  }
  for(std::size_t f : list)
    if(is_folded[f])
    {
      if(report.first_folded == npos)
        report.first_folded = f;
      report.still_folded.push_back(f);
    }
    else
      ++report.unfolded;
  return report;
}

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_FOLD_CHECK_H
