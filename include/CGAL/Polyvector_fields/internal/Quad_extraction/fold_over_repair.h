// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// Fold-over repair of an integer-grid map before quad extraction: the flipped
// faces and a few rings around them are re-embedded with the exact transitions.
// Written from Ebke, Bommes, Campen, Kobbelt 2013 (QEx), not from its code.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_FOLD_OVER_REPAIR_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_FOLD_OVER_REPAIR_H

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/Chart_mesh.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <deque>
#include <utility>
#include <vector>
#ifdef CGAL_PVF_QEX_DEBUG
#include <iostream>
#endif

namespace CGAL {
namespace Polyvector_fields {
namespace internal {
namespace qex {

// ---------------------------------------------------------------------------
// Fold-over repair: the flipped (or degenerate) faces and a few rings around them
// are unfolded into one chart through the exact transitions, their inner vertices
// are placed by Tutte's barycentric embedding with the ring boundary fixed, and the
// values are snapped to a dyadic grid and mapped back into each face's chart by the
// same exact transitions. A region is repaired when all its faces come out positive
// and none of its vertices is wound (wound_vertex()); a re-embedding with fewer such
// faces and vertices than before is kept too, as the start of the next, larger region.
// ---------------------------------------------------------------------------
struct Fold_over_result
{
  std::size_t flipped_faces = 0;      // faces with det <= 0 in the input map, and the faces
                                      // around its wound vertices (see wound_vertex())
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

// The angle by which the star of vertex v turns in the map: the sum of its signed uv
// corner angles (for an interior vertex, a multiple of pi/2 up to round-off, even
// with flipped corners).
inline double star_turn(const Chart_mesh& M, std::size_t v)
{
  double turn = 0;
  for(std::size_t c : M.fan[v])
  {
    const P2 &p = M.uv[c], &q1 = M.uv[Chart_mesh::next(c)], &q2 = M.uv[Chart_mesh::prev(c)];
    const double ax = q1[0] - p[0], ay = q1[1] - p[1], bx = q2[0] - p[0], by = q2[1] - p[1];
    turn += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  }
  return turn;
}

// Is the vertex v wound: off the integer grid, every face around it positive, and
// - interior, with a trivial holonomy (not a cone), yet its star turns by another angle
//   than 2 pi in the map, for instance 4 pi (a branch point: the map covers the plane
//   twice there, and find_integer_points() would see 8 directions at a vertex that is
//   no quad corner);
// - or on the border, and its star turns by 2 pi or more: the border overlaps itself
//   there, and a trace along it would leave the vertex into two sectors.
inline bool wound_vertex(const Chart_mesh& M, std::size_t v)
{
  const auto& fan = M.fan[v];
  if(fan.empty())
    return false;
  const P2& x = M.uv[fan[0]];
  if(x[0] == std::floor(x[0]) && x[1] == std::floor(x[1]))
    return false;
  if(!M.border_vertex[v] && !trivial_holonomy(M, v))
    return false;
  for(std::size_t c : fan)
    if(M.face_orientation(Chart_mesh::face(c)) <= 0)
      return false;  // a fold-over already
  const double turn = star_turn(M, v);
  if(M.border_vertex[v])
    return !(turn < 2 * CGAL_PI - 1e-9);
  return !(std::abs(turn - 2 * CGAL_PI) < CGAL_PI / 4);
}

// The faces that the map does not lay out injectively: det <= 0, or around a wound vertex.
inline std::vector<char> folded_faces(const Chart_mesh& M)
{
  std::vector<char> folded(M.F, 0);
  for(std::size_t f = 0; f < M.F; ++f)
    folded[f] = M.face_orientation(f) <= 0;
  for(std::size_t v = 0; v < M.V; ++v)
    if(wound_vertex(M, v))
      for(std::size_t c : M.fan[v])
        folded[Chart_mesh::face(c)] = 1;
  return folded;
}

// The faces of `region` that folded_faces() would flag: not positive, or around a
// wound vertex of the region (each face once).
inline std::size_t region_folds(const Chart_mesh& M, const std::vector<std::size_t>& region)
{
  std::vector<std::size_t> flagged;
  for(std::size_t f : region)
  {
    if(M.face_orientation(f) <= 0)
      flagged.push_back(f);
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t v = M.vertex[3 * f + k];
      if(wound_vertex(M, v))
        for(std::size_t c : M.fan[v])
          flagged.push_back(Chart_mesh::face(c));
    }
  }
  std::sort(flagged.begin(), flagged.end());
  return std::size_t(std::unique(flagged.begin(), flagged.end()) - flagged.begin());
}

// The uv of the corners of the faces of `region`, to put back with restore_region_uv().
inline std::vector<P2> region_uv(const Chart_mesh& M, const std::vector<std::size_t>& region)
{
  std::vector<P2> uv;
  for(std::size_t f : region)
    for(std::size_t k = 0; k < 3; ++k)
      uv.push_back(M.uv[3 * f + k]);
  return uv;
}

inline void restore_region_uv(Chart_mesh& M, const std::vector<std::size_t>& region, const std::vector<P2>& uv)
{
  std::size_t i = 0;
  for(std::size_t f : region)
    for(std::size_t k = 0; k < 3; ++k)
      M.uv[3 * f + k] = uv[i++];
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
  // the cone's angle in the map, fixed by its holonomy
  const double total = std::round(star_turn(M, v) / (CGAL_PI / 2)) * (CGAL_PI / 2);
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

// Re-embeds `region`: mode 0 untangles its free vertices, mode 1 places them by
// Tutte's embedding first, mode 2 re-spreads the stars of its cones first. True
// if the region comes out unfolded; otherwise its uv are put back, unless
// keep_progress and the re-embedding has fewer folds (region_folds()).
inline bool repair_region(Chart_mesh& M, const std::vector<std::size_t>& region, const std::vector<char>& in_region,
                          Fold_over_result& report, int mode, bool keep_progress = false)
{
  const std::size_t region_folds_before = keep_progress ? region_folds(M, region) : 0;
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
  const std::vector<P2> saved = region_uv(M, region);
  auto restore = [&]() { restore_region_uv(M, region, saved); };
  // every face positive and no wound vertex left: a re-embedding that leaves the
  // branch point of a region with no reversed face as it was is no repair
  auto unfolded = [&]() {
    for(std::size_t f : region)
      if(M.face_orientation(f) <= 0)
        return false;
    for(std::size_t f : region)
      for(std::size_t k = 0; k < 3; ++k)
        if(wound_vertex(M, M.vertex[3 * f + k]))
          return false;
    return true;
  };
  if(!tutte)
  {
    untangle(M, free_vertices, 20);
    if(!unfolded())
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
  bool ok = unfolded();
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
    if(!keep_progress || !(region_folds(M, region) < region_folds_before))
      restore();
    return false;
  }
  ++report.regions;
  report.moved_vertices += n;
  return true;
}

// Adds to `mask` the faces around its vertices (one vertex ring).
inline void grow_by_a_ring(const Chart_mesh& M, std::vector<char>& mask)
{
  std::vector<char> grown = mask;
  for(std::size_t f = 0; f < M.F; ++f)
    if(mask[f])
      for(std::size_t k = 0; k < 3; ++k)
        for(std::size_t c : M.fan[M.vertex[3 * f + k]])
          grown[Chart_mesh::face(c)] = 1;
  mask.swap(grown);
}

// The faces of `mask` in edge-connected regions, each from its smallest face outwards.
inline std::vector<std::vector<std::size_t> > edge_connected_regions(const Chart_mesh& M, const std::vector<char>& mask)
{
  std::vector<std::vector<std::size_t> > regions;
  std::vector<char> done(M.F, 0);
  for(std::size_t f0 = 0; f0 < M.F; ++f0)
  {
    if(!mask[f0] || done[f0])
      continue;
    std::vector<std::size_t> region{ f0 };
    done[f0] = 1;
    for(std::size_t i = 0; i < region.size(); ++i)
      for(std::size_t k = 0; k < 3; ++k)
      {
        const std::size_t o = M.opp[3 * region[i] + k];
        if(o != npos && mask[Chart_mesh::face(o)] && !done[Chart_mesh::face(o)])
        {
          done[Chart_mesh::face(o)] = 1;
          region.push_back(Chart_mesh::face(o));
        }
      }
    regions.push_back(region);
  }
  return regions;
}

inline Error_code repair_fold_overs(Chart_mesh& M, std::size_t max_rings, Fold_over_result& report)
{
  report = Fold_over_result();
  std::size_t positive = 0;
  for(std::size_t f = 0; f < M.F; ++f)
  {
    const int o = M.face_orientation(f);
    report.degenerate_faces += o == 0;
    positive += o != 0;
  }
  if(positive == 0)
    return Error_code::NOT_AN_INTEGER_GRID_MAP;  // no map at all: every triangle has zero uv area
  std::vector<char> folded = folded_faces(M);
  report.flipped_faces = std::size_t(std::count(folded.begin(), folded.end(), char(1)));
  for(std::size_t rings = 1; rings <= max_rings; ++rings)
  {
    if(rings > 1)
      folded = folded_faces(M);
    std::vector<std::size_t> bad;
    for(std::size_t f = 0; f < M.F; ++f)
      if(folded[f])
        bad.push_back(f);
    if(bad.empty())
      break;
    report.rings_used = rings;
    // dilate by vertex rings
    std::vector<char> in_region(M.F, 0);
    for(std::size_t f : bad)
      in_region[f] = 1;
    for(std::size_t r = 0; r < rings; ++r)
      grow_by_a_ring(M, in_region);
    for(const std::vector<std::size_t>& region : edge_connected_regions(M, in_region))
    {
      bool has_bad = false;
      for(std::size_t f : region)
        has_bad = has_bad || folded[f];
      if(!has_bad)
        continue;
      std::vector<char> mask(M.F, 0);
      for(std::size_t f : region)
        mask[f] = 1;
      if(repair_region(M, region, mask, report, 0))
        continue;
      // Tutte's embedding, then with the cones' stars re-spread, both from the
      // map's uv; when neither unfolds the region, the one with fewer folds
      // than the map is kept, as the start of the next, larger region
      const std::vector<P2> start = region_uv(M, region);
      if(repair_region(M, region, mask, report, 1, true))
        continue;
      const std::size_t folds_tutte = region_folds(M, region);
      const std::vector<P2> tutte = region_uv(M, region);
      restore_region_uv(M, region, start);
      if(repair_region(M, region, mask, report, 2, true))
        continue;
      if(folds_tutte < region_folds(M, region))
        restore_region_uv(M, region, tutte);
    }
  }
  folded = folded_faces(M);
  report.remaining = std::size_t(std::count(folded.begin(), folded.end(), char(1)));
#ifdef CGAL_PVF_QEX_DEBUG
  for(std::size_t f = 0; f < M.F; ++f)
    if(folded[f])
    {
      std::cerr << "left: face " << f << " orientation " << M.face_orientation(f);
      for(std::size_t k = 0; k < 3; ++k)
      {
        const std::size_t v = M.vertex[3 * f + k];
        std::cerr << " | v" << v << (M.border_vertex[v] ? " border" : trivial_holonomy(M, v) ? "" : " cone")
                  << (wound_vertex(M, v) ? " wound" : "") << " (" << M.uv[3 * f + k][0] << "," << M.uv[3 * f + k][1] << ")";
      }
      std::cerr << "\n";
    }
#endif
  if(report.remaining != 0)
    return Error_code::UNREPAIRABLE_FOLD_OVER;
  return Error_code::SUCCESS;
}

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_FOLD_OVER_REPAIR_H
