// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The fold-overs that the repair leaves: cut out of the map, the quads
// extracted around them, and the holes that they leave in the quad mesh
// filled with quads laid out in a parametrization of the surface under them.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_FOLD_OVER_HOLES_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_FOLD_OVER_HOLES_H

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/Chart_mesh.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/Extractor.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/fold_check.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/fold_over_repair.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/polygon_quadrangulation.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#ifdef CGAL_PVF_QEX_DEBUG
#include <iostream>
#endif
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {
namespace qex {

// ---------------------------------------------------------------------------
// The cut. The faces that still fold after the repair (and the faces around a
// vertex whose remaining faces would form several fans, or whose remaining star
// winds) are cut out of the map: the cut mesh keeps every other face, its charts
// and its exact transitions, and the cut edges become border edges. Whole cells
// are then extracted from the cut mesh: the cells that would cross the cut are
// not closed, so the quads stop short of it.
// ---------------------------------------------------------------------------
struct Fold_over_cut
{
  std::vector<char> removed;               // per face of the surface
  std::vector<std::size_t> surface_face;   // per face of the cut mesh: its face on the surface
};

// The runs of kept faces around vertex v (a run is a fan of the cut mesh).
inline std::size_t kept_runs(const Chart_mesh& M, std::size_t v, const std::vector<char>& removed)
{
  const auto& fan = M.fan[v];
  const std::size_t n = fan.size();
  const bool cyclic = !M.border_vertex[v];
  std::size_t runs = 0, kept = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const bool here = !removed[Chart_mesh::face(fan[i])];
    const bool before = i > 0 ? !removed[Chart_mesh::face(fan[i - 1])] : cyclic && !removed[Chart_mesh::face(fan[n - 1])];
    runs += here && !before;
    kept += here;
  }
  return kept == n && cyclic ? 1 : runs;
}

// S: the faces of M that are not removed, in their order, with the same vertices.
inline void build_cut_mesh(const Chart_mesh& M, const std::vector<char>& removed, Chart_mesh& S,
                           std::vector<std::size_t>& surface_face)
{
  S = Chart_mesh();
  surface_face.clear();
  S.V = M.V;
  S.point = M.point;
  S.border_vertex = M.border_vertex;
  std::vector<std::size_t> cut_face(M.F, npos);
  for(std::size_t f = 0; f < M.F; ++f)
  {
    if(removed[f])
      continue;
    cut_face[f] = surface_face.size();
    surface_face.push_back(f);
    for(std::size_t k = 0; k < 3; ++k)
    {
      S.vertex.push_back(M.vertex[3 * f + k]);
      S.uv.push_back(M.uv[3 * f + k]);
    }
  }
  S.F = surface_face.size();
  S.opp.assign(3 * S.F, npos);
  S.trans.assign(3 * S.F, Grid_map());
  for(std::size_t g = 0; g < S.F; ++g)
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t e = 3 * surface_face[g] + k, o = M.opp[e];
      if(o == npos)
        continue;
      if(removed[Chart_mesh::face(o)])
      {
        S.border_vertex[M.vertex[e]] = 1;
        S.border_vertex[M.vertex[Chart_mesh::next(e)]] = 1;
        continue;
      }
      S.opp[3 * g + k] = 3 * cut_face[Chart_mesh::face(o)] + o % 3;
      S.trans[3 * g + k] = M.trans[e];
    }
}

// Cuts the faces that fold in M (after the repair) out of it: S is a manifold mesh
// without fold-over. False if nothing of the surface would be left.
inline bool cut_out_fold_overs(const Chart_mesh& M, Fold_over_cut& cut, Chart_mesh& S)
{
  cut.removed = folded_faces(M);
  for(int round = 0; round < 64; ++round)
  {
    // vertices whose kept faces would form several fans lose them all
    for(bool changed = true; changed;)
    {
      changed = false;
      for(std::size_t v = 0; v < M.V; ++v)
        if(kept_runs(M, v, cut.removed) > 1)
        {
          for(std::size_t c : M.fan[v])
            cut.removed[Chart_mesh::face(c)] = 1;
          changed = true;
        }
    }
    build_cut_mesh(M, cut.removed, S, cut.surface_face);
    if(S.F == 0)
      return false;
    if(check_transitions(S) != Error_code::SUCCESS || build_fans(S) != Error_code::SUCCESS)
      return false;  // not expected: the transitions and fans of M hold on its faces
    // a vertex of the cut whose remaining star winds (turns 2 pi or more) folds too
    const std::vector<char> folded = folded_faces(S);
    if(std::find(folded.begin(), folded.end(), char(1)) == folded.end())
      return true;
    for(std::size_t g = 0; g < S.F; ++g)
      if(folded[g])
        cut.removed[cut.surface_face[g]] = 1;
  }
  return false;
}

// ---------------------------------------------------------------------------
// The holes. The quad mesh of the cut mesh has a hole around each cut-out
// region, bounded by a loop of its edges. For each region, a disk of surface
// faces around it (the region grown ring by ring until it is a disk holding a
// loop that goes around the region) is parametrized on the unit disk by mean
// value coordinates (Floater 2003, CGAL's Surface_mesh_parameterization: one to
// one on a convex border); the loop is a simple polygon there, filled with quads
// (quadrangulate_polygon()), whose new corners go back to the surface through the
// parametrization's triangles: every new vertex lies on the input surface.
// Quads of the cut mesh that the loop encloses (an island) are replaced too.
// ---------------------------------------------------------------------------

// Where an output vertex lies on the surface: a combination of up to 3 vertices,
// with the surface faces that hold it (none for a vertex).
struct Surface_location
{
  std::size_t n = 0;
  std::array<std::size_t, 3> v{ { npos, npos, npos } };
  std::array<double, 3> w{ { 0, 0, 0 } };
  std::array<std::size_t, 2> face{ { npos, npos } };
  std::size_t edge = npos;  // with n == 2: the surface edge (corner index) from v[0] to v[1]
};

inline Surface_location surface_location(const Chart_mesh& M, const Chart_mesh& S,
                                         const std::vector<std::size_t>& surface_face, const Qpoint& P)
{
  Surface_location L;
  auto on_edge = [&](std::size_t e, double lambda) {
    L.n = 2;
    L.v = { S.vertex[e], S.vertex[Chart_mesh::next(e)], npos };
    L.w = { 1 - lambda, lambda, 0 };
    const std::size_t f = surface_face[Chart_mesh::face(e)], me = 3 * f + e % 3;
    L.face = { f, M.opp[me] == npos ? npos : Chart_mesh::face(M.opp[me]) };
    L.edge = me;
  };
  if(P.loc == AT_VERTEX)
  {
    L.n = 1;
    L.v[0] = P.elem;
    L.w[0] = 1;
  }
  else if(P.loc == ON_EDGE)
  {
    const P2 &A = S.uv[P.elem], &B = S.uv[Chart_mesh::next(P.elem)];
    const int coord = A[0] != B[0] ? 0 : 1;
    on_edge(P.elem, (P.uv[coord] - A[coord]) / (B[coord] - A[coord]));
  }
  else if(P.loc == BOUNDARY_HIT)
    on_edge(P.elem, CGAL::to_double(P.lambda));
  else
  {
    const std::size_t f = P.elem;
    const P2 &a = S.corner_uv(f, 0), &b = S.corner_uv(f, 1), &c = S.corner_uv(f, 2);
    const double area = orient2(a, b, c);
    L.n = 3;
    L.v = { S.vertex[3 * f], S.vertex[3 * f + 1], S.vertex[3 * f + 2] };
    L.w = { orient2(P.uv, b, c) / area, orient2(a, P.uv, c) / area, orient2(a, b, P.uv) / area };
    L.face = { surface_face[f], npos };
  }
  return L;
}

// The connected components of the surface through its edges: the component of each
// face, and the number of faces of each component.
inline void face_components(const Chart_mesh& M, std::vector<std::size_t>& component, std::vector<std::size_t>& size)
{
  component.assign(M.F, npos);
  size.clear();
  for(const std::vector<std::size_t>& region : edge_connected_regions(M, std::vector<char>(M.F, 1)))
  {
    for(std::size_t f : region)
      component[f] = size.size();
    size.push_back(region.size());
  }
}

struct Hole_fill_report
{
  std::size_t holes = 0;           // loops filled
  std::size_t quads = 0;           // quads made
  std::size_t replaced = 0;        // quads of the cut mesh that a loop enclosed
  std::size_t rings = 0;           // largest growth of a region
  std::size_t uncovered = 0;       // cut-out faces that no filled loop encloses (0 on success)
  std::vector<std::size_t> uncovered_faces;
  std::string diagnostic;
};

// The soup of the quad mesh of the cut mesh, to which the fills are added:
// positions, polygons, the surface location of each vertex, the surface faces under
// each polygon, and the polygons that the fills replace.
struct Quad_soup
{
  std::vector<P3> position;
  std::vector<std::vector<std::size_t> > polygons;
  std::vector<Surface_location> location;
  std::vector<std::vector<std::size_t> > under;
  std::vector<char> dropped;
};

// The loops of the soup's boundary, each with the soup on its right (the hole on its
// left, counterclockwise around it); a vertex with several boundary edges in or out
// puts its loops aside (they cannot be filled).
inline std::vector<std::vector<std::size_t> > hole_loops(const Quad_soup& soup)
{
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
  {
    if(soup.dropped[f])
      continue;
    const auto& poly = soup.polygons[f];
    for(std::size_t k = 0; k < poly.size(); ++k)
      ++directed[std::make_pair(poly[k], poly[(k + 1) % poly.size()])];
  }
  // the loop goes b -> a along each boundary edge a -> b of a polygon
  std::vector<std::size_t> loop_next(soup.position.size(), npos);
  std::vector<char> ambiguous(soup.position.size(), 0);
  for(const auto& d : directed)
    if(directed.find(std::make_pair(d.first.second, d.first.first)) == directed.end())
    {
      const std::size_t b = d.first.second, a = d.first.first;
      if(loop_next[b] != npos || d.second != 1)
        ambiguous[b] = 1;
      loop_next[b] = a;
    }
  std::vector<std::vector<std::size_t> > loops;
  std::vector<char> used(soup.position.size(), 0);
  for(std::size_t v0 = 0; v0 < loop_next.size(); ++v0)
  {
    if(loop_next[v0] == npos || used[v0])
      continue;
    std::vector<std::size_t> loop;
    bool ok = true;
    for(std::size_t v = v0; !used[v]; v = loop_next[v])
    {
      used[v] = 1;
      ok = ok && !ambiguous[v] && loop_next[v] != npos;
      loop.push_back(v);
      if(loop_next[v] == npos)
        break;
    }
    if(ok && loop_next[loop.back()] == v0)
      loops.push_back(loop);
  }
  return loops;
}

// The parametrization of a disk of surface faces on the unit disk.
struct Disk_parametrization
{
  std::vector<std::size_t> faces;             // surface faces
  std::vector<std::size_t> local;             // per surface vertex: its index here, or npos
  std::vector<Q2> uv;                         // per local vertex
  std::vector<std::size_t> vertex;            // per local vertex: the surface vertex
  // the loops of the surface's border that the faces go around (holes of the surface,
  // closed by a fan for the parametrization), as surface edges (corner indices) in
  // their order, the surface on their left
  std::vector<std::vector<std::size_t> > inner_loops;

  bool holds(const Surface_location& L, const std::vector<char>& in_disk) const
  {
    if(L.n == 1)
      return local[L.v[0]] != npos;
    return (L.face[0] != npos && in_disk[L.face[0]]) || (L.face[1] != npos && in_disk[L.face[1]]);
  }
  // the face of the disk whose image holds p (or comes nearest), and p's barycentric
  // coordinates in it (clamped to the face); npos if no face has a positive image
  std::size_t locate(const Chart_mesh& M, const Q2& p, std::array<double, 3>& w) const
  {
    std::size_t best = npos;
    double best_low = -std::numeric_limits<double>::infinity();
    for(std::size_t f : faces)
    {
      const Q2 &a = uv[local[M.vertex[3 * f]]], &b = uv[local[M.vertex[3 * f + 1]]], &c = uv[local[M.vertex[3 * f + 2]]];
      const double area = orient2(a, b, c);
      if(!(area > 0))
        continue;
      const std::array<double, 3> x{ { orient2(p, b, c) / area, orient2(a, p, c) / area, orient2(a, b, p) / area } };
      const double low = (std::min)({ x[0], x[1], x[2] });
      if(low > best_low)
      {
        best_low = low;
        best = f;
        w = x;
      }
      if(low >= 0)
        break;
    }
    if(best != npos)
    {
      for(double& x : w)
        x = (std::max)(0.0, x);
      const double sum = w[0] + w[1] + w[2];
      for(double& x : w)
        x /= sum;
    }
    return best;
  }
  Q2 at(const Surface_location& L) const
  {
    Q2 p{ 0, 0 };
    for(std::size_t i = 0; i < L.n; ++i)
      for(int a = 0; a < 2; ++a)
        p[a] += L.w[i] * uv[local[L.v[i]]][a];
    return p;
  }
};

// Parametrizes the faces `faces` of M (a disk: connected, manifold, one border loop,
// Euler characteristic 1) on the unit disk, orientation kept; false if they are not a
// disk or the parametrization fails.
inline bool parametrize_disk(const Chart_mesh& M, const std::vector<std::size_t>& faces, Disk_parametrization& D)
{
  typedef CGAL::Surface_mesh<Epick::Point_3> SM;
  typedef boost::graph_traits<SM>::vertex_descriptor SV;
  namespace SMP = CGAL::Surface_mesh_parameterization;
  D.faces = faces;
  D.local.assign(M.V, npos);
  D.vertex.clear();
  SM sm;
  std::vector<SV> handle;
  for(std::size_t f : faces)
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t v = M.vertex[3 * f + k];
      if(D.local[v] != npos)
        continue;
      D.local[v] = D.vertex.size();
      D.vertex.push_back(v);
      handle.push_back(sm.add_vertex(Epick::Point_3(M.point[v][0], M.point[v][1], M.point[v][2])));
    }
  for(std::size_t f : faces)
    if(sm.add_face(handle[D.local[M.vertex[3 * f]]], handle[D.local[M.vertex[3 * f + 1]]],
                   handle[D.local[M.vertex[3 * f + 2]]]) == SM::null_face())
      return false;
  // a disk: one border loop, Euler characteristic 1, no vertex where two fans meet; loops
  // made of the surface's border edges only (holes of the surface) are closed by a fan
  std::size_t border_loops = 0;
  boost::graph_traits<SM>::halfedge_descriptor border = boost::graph_traits<SM>::null_halfedge();
  {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> surface_border;  // local (a, b) -> edge a to b
    for(std::size_t f : faces)
      for(std::size_t k = 0; k < 3; ++k)
        if(M.opp[3 * f + k] == npos)
          surface_border[std::make_pair(D.local[M.vertex[3 * f + k]], D.local[M.vertex[3 * f + (k + 1) % 3]])] = 3 * f + k;
    std::vector<char> seen(sm.number_of_halfedges(), 0);
    std::vector<boost::graph_traits<SM>::halfedge_descriptor> closable;
    std::size_t open = 0;
    for(auto h : halfedges(sm))
      if(CGAL::is_border(h, sm) && !seen[h.idx()])
      {
        bool on_surface_border = true;
        for(auto g : CGAL::halfedges_around_face(h, sm))
        {
          seen[g.idx()] = 1;
          on_surface_border = on_surface_border &&
                              surface_border.count(std::make_pair(std::size_t(target(g, sm)), std::size_t(source(g, sm))));
        }
        if(on_surface_border)
          closable.push_back(h);
        else
        {
          ++open;
          border = h;
        }
      }
    if(open != 1)
      return false;
    for(auto h : closable)
    {
      // the loop as surface edges, the surface on their left: each border halfedge reversed
      std::vector<std::size_t> loop;
      std::vector<boost::graph_traits<SM>::halfedge_descriptor> cycle;
      for(auto g : CGAL::halfedges_around_face(h, sm))
        cycle.push_back(g);
      for(auto it = cycle.rbegin(); it != cycle.rend(); ++it)
        loop.push_back(surface_border[std::make_pair(std::size_t(target(*it, sm)), std::size_t(source(*it, sm)))]);
      D.inner_loops.push_back(loop);
      double c[3] = { 0, 0, 0 };
      for(auto g : cycle)
        for(int a = 0; a < 3; ++a)
          c[a] += M.point[D.vertex[std::size_t(target(g, sm))]][a] / double(cycle.size());
      const SV centre = sm.add_vertex(Epick::Point_3(c[0], c[1], c[2]));
      for(auto g : cycle)
        if(sm.add_face(source(g, sm), target(g, sm), centre) == SM::null_face())
          return false;
    }
    border_loops = open;
  }
  if(border_loops != 1 ||
     long(sm.number_of_vertices()) - long(sm.number_of_edges()) + long(sm.number_of_faces()) != 1)
    return false;
  for(auto v : vertices(sm))
  {
    std::size_t borders = 0;
    for(auto h : CGAL::halfedges_around_target(v, sm))
      borders += CGAL::is_border(h, sm);
    if(borders > 1)
      return false;
  }
  auto uvmap = sm.add_property_map<SV, Epick::Point_2>("v:uv").first;
  typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::COLAMDOrdering<int> > > Solver;
  typedef SMP::Circular_border_arc_length_parameterizer_3<SM> Border;
  // mean value coordinates, or Tutte's uniform weights where those are not defined (a
  // triangle of zero area or an edge of zero length: CGAL asserts or gives no number)
  auto solved = [&](auto&& parameterizer) {
    try
    {
      if(SMP::parameterize(sm, parameterizer, border, uvmap) != SMP::OK)
        return false;
    }
    catch(const CGAL::Failure_exception&)
    {
      return false;
    }
    D.uv.resize(D.vertex.size());
    for(std::size_t i = 0; i < D.vertex.size(); ++i)
    {
      const Epick::Point_2 p = uvmap[handle[i]];
      D.uv[i] = { p.x(), p.y() };
      if(!std::isfinite(D.uv[i][0]) || !std::isfinite(D.uv[i][1]))
        return false;
    }
    return true;
  };
  if(!solved(SMP::Mean_value_coordinates_parameterizer_3<SM, Border, Solver>()) &&
     !solved(SMP::Barycentric_mapping_parameterizer_3<SM, Border, Solver>()))
    return false;
  // the surface's orientation: the faces counterclockwise
  double area = 0;
  for(std::size_t f : faces)
    area += orient2(D.uv[D.local[M.vertex[3 * f]]], D.uv[D.local[M.vertex[3 * f + 1]]], D.uv[D.local[M.vertex[3 * f + 2]]]);
  if(area < 0)
    for(Q2& p : D.uv)
      p[1] = -p[1];
  return true;
}

inline bool inside_polygon(const Q2& p, const std::vector<Q2>& polygon)
{
  bool inside = false;
  const std::size_t n = polygon.size();
  for(std::size_t i = 0; i < n; ++i)
  {
    const Q2 &a = polygon[i], &b = polygon[(i + 1) % n];
    if((a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
      inside = !inside;
  }
  return inside;
}

// Fills the holes of `soup` around the faces `removed` of M. A region is grown by
// up to `max_rings` rings; a region that would take more than half of its connected
// component is not filled. Returns false (with report.diagnostic and
// report.uncovered_faces) when a cut-out face is left outside every filled loop; the
// holes that were filled stay in `soup`.
inline bool fill_fold_over_holes(const Chart_mesh& M, const std::vector<char>& removed, std::size_t max_rings,
                                 Quad_soup& soup, Hole_fill_report& report)
{
  report = Hole_fill_report();
  // the loops of the soup's boundary and the polygons at each vertex, made again after each filling
  std::vector<std::vector<std::size_t> > loops;
  std::vector<std::size_t> loop_of;
  std::vector<std::vector<std::size_t> > vertex_polygons;
  auto refresh = [&]() {
    loops = hole_loops(soup);
    loop_of.assign(soup.position.size(), npos);
    for(std::size_t l = 0; l < loops.size(); ++l)
      for(std::size_t v : loops[l])
        loop_of[v] = l;
    vertex_polygons.assign(soup.position.size(), {});
    for(std::size_t f = 0; f < soup.polygons.size(); ++f)
      if(!soup.dropped[f])
        for(std::size_t v : soup.polygons[f])
          vertex_polygons[v].push_back(f);
  };
  refresh();
  // the connected components of the surface, for the size bound
  std::vector<std::size_t> component, component_size;
  face_components(M, component, component_size);
  std::vector<char> covered(M.F, 0);
  auto centroid_of = [&](const Disk_parametrization& D, std::size_t f) {
    Q2 c{ 0, 0 };
    for(std::size_t k = 0; k < 3; ++k)
      for(int a = 0; a < 2; ++a)
        c[a] += D.uv[D.local[M.vertex[3 * f + k]]][a] / 3;
    return c;
  };
  auto uncovered_left = [&]() {
    for(std::size_t f = 0; f < M.F; ++f)
      if(removed[f] && !covered[f])
        return true;
    return false;
  };
  // on the border of the surface (not of the cut)
  auto on_border = [&](const Surface_location& L) {
    return (L.n == 1 && M.border_vertex[L.v[0]]) || (L.n == 2 && L.edge != npos && M.opp[L.edge] == npos);
  };
  struct Border_point
  {
    Surface_location location;
    P3 position;
  };
  // The points that close a chain from A = chain.front() to B = chain.back() along the
  // surface's border, from B to A (the surface on the left): from B, or from the border
  // point nearest to it if B is not on the border (within 1.5 of the chain's mean side),
  // to A or the border point nearest to it; about as far apart as the chain's corners,
  // in a number that makes the polygon's corners even.
  auto border_closing = [&](const Disk_parametrization& D, const std::vector<char>& in_disk,
                            const std::vector<std::size_t>& chain, std::vector<Border_point>& closing) {
    closing.clear();
    auto at = [&](std::size_t e, double t) {
      const P3 &a = M.point[M.vertex[e]], &b = M.point[M.vertex[Chart_mesh::next(e)]];
      return P3{ a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]) };
    };
    auto point_at = [&](std::size_t e, double t) {
      Border_point b;
      b.location.n = 2;
      b.location.v = { M.vertex[e], M.vertex[Chart_mesh::next(e)], npos };
      b.location.w = { 1 - t, t, 0 };
      b.location.face = { Chart_mesh::face(e), npos };
      b.location.edge = e;
      b.position = at(e, t);
      return b;
    };
    double chain_length = 0;
    for(std::size_t i = 0; i + 1 < chain.size(); ++i)
    {
      const P3 d = sub3(soup.position[chain[i + 1]], soup.position[chain[i]]);
      chain_length += std::sqrt(dot3(d, d)) / double(chain.size() - 1);
    }
    if(!(chain_length > 0))
      return false;
    // where the closing starts or ends: at the vertex itself, or at the nearest border point
    auto border_end = [&](std::size_t v, std::size_t& e, double& t, bool& added) {
      const Surface_location& L = soup.location[v];
      added = false;
      if(L.n == 1 && M.border_vertex[L.v[0]])
      {
        e = M.fan[L.v[0]].front();
        t = 0;
        return true;
      }
      if(L.n == 2 && L.edge != npos && M.opp[L.edge] == npos)
      {
        e = L.edge;
        t = L.w[1];
        return true;
      }
      // (not onto a hole of the surface that the disk goes around: the quads do not reach
      // it, and the whole hole is filled at once, see surface_holes())
      const P3& p = soup.position[v];
      double best = std::numeric_limits<double>::infinity();
      std::vector<char> inner(3 * M.F, 0);
      for(const std::vector<std::size_t>& loop : D.inner_loops)
        for(std::size_t g : loop)
          inner[g] = 1;
      for(std::size_t f : D.faces)
        for(std::size_t k = 0; k < 3; ++k)
        {
          const std::size_t g = 3 * f + k;
          if(M.opp[g] != npos || inner[g])
            continue;
          const P3 &a = M.point[M.vertex[g]], d = sub3(M.point[M.vertex[Chart_mesh::next(g)]], a);
          const double l2 = dot3(d, d);
          const double u = l2 > 0 ? (std::min)(1.0, (std::max)(0.0, dot3(sub3(p, a), d) / l2)) : 0;
          const P3 x = sub3(at(g, u), p);
          if(dot3(x, x) < best)
          {
            best = dot3(x, x);
            e = g;
            t = u;
          }
        }
      added = true;
      return best <= 2.25 * chain_length * chain_length;
    };
    std::size_t e = npos, e_a = npos;
    double t = 0, t_a = 0;
    bool add_start = false, add_end = false;
    if(!border_end(chain.back(), e, t, add_start) || !border_end(chain.front(), e_a, t_a, add_end))
      return false;
    struct Piece { std::size_t edge; double t0, t1, length; };
    std::vector<Piece> pieces;
    double total = 0;
    const std::size_t first_edge = e;
    for(std::size_t steps = 0;; ++steps)
    {
      if(steps > M.V || M.opp[e] != npos || !in_disk[Chart_mesh::face(e)] || (steps > 0 && e == first_edge))
        return false;
      const bool last = e == e_a && t_a >= t;
      const double t1 = last ? t_a : 1;
      const double length = std::sqrt(dot3(sub3(at(e, t1), at(e, t)), sub3(at(e, t1), at(e, t))));
      pieces.push_back({ e, t, t1, length });
      total += length;
      if(last)
        break;
      const std::size_t w = M.vertex[Chart_mesh::next(e)];
      if(D.local[w] == npos || M.fan[w].empty())
        return false;
      e = M.fan[w].front();
      t = 0;
    }
    if(add_start)
      closing.push_back(point_at(pieces.front().edge, pieces.front().t0));
    const double ideal = total / chain_length;
    std::size_t segments = (std::max)(std::size_t(1), std::size_t(std::lround(ideal)));
    if((chain.size() + segments - 1 + add_start + add_end) % 2 != 0)
      segments = segments == 1 || ideal > double(segments) ? segments + 1 : segments - 1;
    // the points at equal arc lengths
    std::size_t k = 0;
    double before = 0;
    for(std::size_t j = 1; j < segments; ++j)
    {
      const double s = total * double(j) / double(segments);
      while(k + 1 < pieces.size() && before + pieces[k].length < s)
        before += pieces[k++].length;
      const Piece& P = pieces[k];
      const double u = P.length > 0 ? (std::min)(1.0, (std::max)(0.0, (s - before) / P.length)) : 0;
      closing.push_back(point_at(P.edge, P.t0 + u * (P.t1 - P.t0)));
    }
    if(add_end)
      closing.push_back(point_at(pieces.back().edge, pieces.back().t1));
    // no two corners of the polygon at one point
    const double apart = 1e-3 * chain_length;
    std::vector<P3> ends{ soup.position[chain.back()] };
    for(const Border_point& b : closing)
      ends.push_back(b.position);
    ends.push_back(soup.position[chain.front()]);
    for(std::size_t i = 0; i + 1 < ends.size(); ++i)
      if(dot3(sub3(ends[i + 1], ends[i]), sub3(ends[i + 1], ends[i])) <= apart * apart)
        return false;
    return true;
  };
  // `count` points at equal arc lengths along the chain of surface edges `edges`, from
  // the start of the first one (a closed loop: the last one ends where the first starts).
  auto points_along = [&](const std::vector<std::size_t>& edges, std::size_t count) {
    std::vector<double> length;
    double total = 0;
    for(std::size_t e : edges)
    {
      const P3 d = sub3(M.point[M.vertex[Chart_mesh::next(e)]], M.point[M.vertex[e]]);
      length.push_back(std::sqrt(dot3(d, d)));
      total += length.back();
    }
    std::vector<Border_point> points(count);
    std::size_t k = 0;
    double before = 0;
    for(std::size_t j = 0; j < count; ++j)
    {
      const double s = total * double(j) / double(count);
      while(k + 1 < edges.size() && before + length[k] < s)
        before += length[k++];
      const std::size_t e = edges[k];
      const double t = length[k] > 0 ? (std::min)(1.0, (std::max)(0.0, (s - before) / length[k])) : 0;
      Border_point& b = points[j];
      b.location.n = 2;
      b.location.v = { M.vertex[e], M.vertex[Chart_mesh::next(e)], npos };
      b.location.w = { 1 - t, t, 0 };
      b.location.face = { Chart_mesh::face(e), npos };
      b.location.edge = e;
      const P3 &p = M.point[M.vertex[e]], &q = M.point[M.vertex[Chart_mesh::next(e)]];
      b.position = { p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2]) };
    }
    return std::make_pair(points, total);
  };
  // The holes of the surface inside the polygon of the soup vertices `corners` followed
  // by the `closing` points, as points on their border edges about as far apart as the
  // polygon's corners (at least 3 a hole), in numbers that make all the corners even.
  auto surface_holes = [&](const Disk_parametrization& D, const std::vector<std::size_t>& loop,
                           const std::vector<Border_point>& closing) {
    std::vector<std::vector<Border_point> > holes;
    std::vector<Q2> polygon;
    std::vector<P3> at;
    for(std::size_t v : loop)
    {
      polygon.push_back(D.at(soup.location[v]));
      at.push_back(soup.position[v]);
    }
    for(const Border_point& b : closing)
    {
      polygon.push_back(D.at(b.location));
      at.push_back(b.position);
    }
    double side = 0;
    for(std::size_t i = 0; i < at.size(); ++i)
    {
      const P3 d = sub3(at[(i + 1) % at.size()], at[i]);
      side += std::sqrt(dot3(d, d)) / double(at.size());
    }
    std::vector<const std::vector<std::size_t>*> inside;
    std::vector<std::size_t> count;
    std::size_t corners = polygon.size();
    // (a hole whose border the polygon follows is not inside it)
    std::vector<char> touched(M.V, 0);
    auto touch = [&](const Surface_location& L) {
      if(on_border(L))
        for(std::size_t i = 0; i < L.n; ++i)
          touched[L.v[i]] = 1;
    };
    for(std::size_t v : loop)
      touch(soup.location[v]);
    for(const Border_point& b : closing)
      touch(b.location);
    for(const std::vector<std::size_t>& edges : D.inner_loops)
    {
      bool apart = true;
      for(std::size_t e : edges)
        apart = apart && !touched[M.vertex[e]];
      if(apart && inside_polygon(D.uv[D.local[M.vertex[edges.front()]]], polygon))
      {
        inside.push_back(&edges);
        const double total = points_along(edges, 1).second;
        count.push_back((std::max)(std::size_t(3), std::size_t(std::lround(total / side))));
        corners += count.back();
      }
    }
    if(corners % 2 != 0 && !count.empty())
      ++count.back();
    for(std::size_t i = 0; i < inside.size(); ++i)
      holes.push_back(points_along(*inside[i], count[i]).first);
    return holes;
  };
  // Fills the polygon of the soup vertices `corners` followed by the new `closing`
  // points, in the disk D, if it goes around a cut-out face not covered yet.
  auto fill_polygon = [&](const Disk_parametrization& D, const std::vector<char>& in_disk,
                          const std::vector<std::size_t>& corners, const std::vector<Border_point>& closing,
                          const std::vector<std::vector<Border_point> >& holes, std::size_t l) {
    std::vector<Q2> polygon;
    for(std::size_t v : corners)
      polygon.push_back(D.at(soup.location[v]));
    for(const Border_point& b : closing)
      polygon.push_back(D.at(b.location));
    double length = 0;
    for(std::size_t i = 0; i < polygon.size(); ++i)
    {
      const Q2 &a = polygon[i], &b = polygon[(i + 1) % polygon.size()];
      length += std::hypot(b[0] - a[0], b[1] - a[1]) / double(polygon.size());
    }
    std::vector<std::vector<Q2> > domain{ polygon };
    std::vector<Border_point> added = closing;
    for(const auto& hole : holes)
    {
      domain.emplace_back();
      for(const Border_point& b : hole)
      {
        domain.back().push_back(D.at(b.location));
        added.push_back(b);
      }
    }
    std::size_t n = 0;
    for(const auto& loop : domain)
      n += loop.size();
    // the polygon must go around a cut-out face that no fill covers yet
    std::vector<std::size_t> enclosed;
    for(std::size_t f : D.faces)
      if(removed[f] && !covered[f] && inside_polygon(centroid_of(D, f), polygon))
        enclosed.push_back(f);
    if(enclosed.empty())
      return false;
    // polygons of the soup inside it (an island) are replaced
    std::vector<std::size_t> island;
    for(std::size_t v = 0; v < loop_of.size(); ++v)
    {
      if(loop_of[v] == l || vertex_polygons[v].empty() || !D.holds(soup.location[v], in_disk) ||
         !inside_polygon(D.at(soup.location[v]), polygon))
        continue;
      for(std::size_t f : vertex_polygons[v])
        if(!soup.dropped[f])
          island.push_back(f);
    }
    std::sort(island.begin(), island.end());
    island.erase(std::unique(island.begin(), island.end()), island.end());
    for(std::size_t f : island)
      for(std::size_t v : soup.polygons[f])
        if(loop_of[v] != l && !(D.holds(soup.location[v], in_disk) && inside_polygon(D.at(soup.location[v]), polygon)))
          return false;
    // nor a polygon of the soup whose corners are all on the loop but lies inside it
    for(std::size_t v : corners)
      for(std::size_t f : vertex_polygons[v])
      {
        if(soup.dropped[f])
          continue;
        Q2 centre{ 0, 0 };
        bool held = true;
        for(std::size_t u : soup.polygons[f])
        {
          held = held && loop_of[u] == l && D.holds(soup.location[u], in_disk);
          if(held)
            for(int a = 0; a < 2; ++a)
              centre[a] += D.at(soup.location[u])[a] / double(soup.polygons[f].size());
        }
        if(held && inside_polygon(centre, polygon) && !std::binary_search(island.begin(), island.end(), f))
        {
#ifdef CGAL_PVF_QEX_DEBUG
          std::cerr << "no filling: a polygon of the soup with its corners on the loop lies inside\n";
#endif
          return false;
        }
      }
    Quadrangulated_polygon fill;
    std::string why;
    if(!quadrangulate_domain(domain, length, fill, &why))
    {
#ifdef CGAL_PVF_QEX_DEBUG
      std::cerr << "no filling: " << why << "\n";
#endif
      return false;
    }
    // the new points on the surface: the closing points, then the inner points through
    // the triangle of the disk that holds them
    std::vector<Surface_location> location(fill.points.size());
    std::vector<P3> position(fill.points.size());
    for(std::size_t i = corners.size(); i < n; ++i)
    {
      location[i] = added[i - corners.size()].location;
      position[i] = added[i - corners.size()].position;
    }
    for(std::size_t i = n; i < fill.points.size(); ++i)
    {
      std::array<double, 3> w;
      const std::size_t face = D.locate(M, fill.points[i], w);
      if(face == npos)
        return false;
      Surface_location& L = location[i];
      L.n = 3;
      position[i] = { 0, 0, 0 };
      for(std::size_t k = 0; k < 3; ++k)
      {
        L.v[k] = M.vertex[3 * face + k];
        L.w[k] = w[k];
        for(int a = 0; a < 3; ++a)
          position[i][a] += w[k] * M.point[L.v[k]][a];
      }
      L.face = { face, npos };
    }
    std::vector<std::size_t> index(fill.points.size());
    for(std::size_t i = 0; i < fill.points.size(); ++i)
    {
      if(i < corners.size())
      {
        index[i] = corners[i];
        continue;
      }
      index[i] = soup.position.size();
      soup.position.push_back(position[i]);
      soup.location.push_back(location[i]);
    }
    for(std::size_t f : island)
      soup.dropped[f] = 1;
    report.replaced += island.size();
    for(const auto& q : fill.quads)
    {
      std::vector<std::size_t> poly(4), under;
      Q2 centre{ 0, 0 };
      for(int k = 0; k < 4; ++k)
      {
        poly[k] = index[q[k]];
        for(std::size_t g : soup.location[poly[k]].face)
          if(g != npos)
            under.push_back(g);
        for(int a = 0; a < 2; ++a)
          centre[a] += fill.points[q[k]][a] / 4;
      }
      // the face under the quad's centre first (a quad whose corners are all at vertices has no other)
      std::array<double, 3> w;
      const std::size_t below = D.locate(M, centre, w);
      if(below != npos)
        under.insert(under.begin(), below);
      std::sort(under.begin() + (below != npos ? 1 : 0), under.end());
      under.erase(std::unique(under.begin(), under.end()), under.end());
      soup.polygons.push_back(poly);
      soup.under.push_back(under);
      soup.dropped.push_back(0);
    }
    for(std::size_t f : D.faces)
      if(removed[f] && inside_polygon(centroid_of(D, f), polygon))
        covered[f] = 1;
#ifdef CGAL_PVF_QEX_DEBUG
    std::cerr << "fill: polygon of " << corners.size() << " corners, " << closing.size() << " border points and "
              << holes.size() << " holes, region of "
              << D.faces.size() << " faces, " << enclosed.size() << " cut-out faces enclosed, island " << island.size()
              << ", " << fill.quads.size() << " quads\n";
#endif
    ++report.holes;
    report.quads += fill.quads.size();
    return true;
  };
  std::vector<char> region = removed;
  for(std::size_t rings = 0; rings <= max_rings && uncovered_left(); ++rings)
  {
    if(rings > 0)
      grow_by_a_ring(M, region);
    // the regions: edge-connected, with the faces they enclose (islands of the rest)
    for(std::vector<std::size_t> faces : edge_connected_regions(M, region))
    {
      const std::size_t f0 = faces.front();
      bool wanted = false;
      for(std::size_t f : faces)
        wanted = wanted || (removed[f] && !covered[f]);
      if(!wanted)
        continue;
      // islands: the pieces of the rest next to the region that are smaller than
      // four times the region (the largest one is the outside)
      {
        std::vector<char> in_region(M.F, 0);
        for(std::size_t f : faces)
          in_region[f] = 1;
        std::vector<char> seen(M.F, 0);
        std::vector<std::vector<std::size_t> > pieces;
        for(std::size_t f : std::vector<std::size_t>(faces))
          for(std::size_t k = 0; k < 3; ++k)
          {
            const std::size_t o = M.opp[3 * f + k];
            if(o == npos || in_region[Chart_mesh::face(o)] || seen[Chart_mesh::face(o)])
              continue;
            std::vector<std::size_t> piece{ Chart_mesh::face(o) };
            seen[piece[0]] = 1;
            bool large = false;
            for(std::size_t i = 0; i < piece.size() && !large; ++i)
              for(std::size_t j = 0; j < 3; ++j)
              {
                const std::size_t q = M.opp[3 * piece[i] + j];
                if(q == npos || in_region[Chart_mesh::face(q)] || seen[Chart_mesh::face(q)])
                  continue;
                seen[Chart_mesh::face(q)] = 1;
                piece.push_back(Chart_mesh::face(q));
                if(piece.size() > 4 * faces.size())
                {
                  large = true;
                  break;
                }
              }
            pieces.push_back(large ? std::vector<std::size_t>() : piece);
          }
        // the largest small piece may be the outside of a small component: keep it out
        std::size_t largest = npos;
        for(std::size_t i = 0; i < pieces.size(); ++i)
          if(!pieces[i].empty() && (largest == npos || pieces[i].size() > pieces[largest].size()))
            largest = i;
        bool any_large = false;
        for(const auto& p : pieces)
          any_large = any_large || p.empty();
        for(std::size_t i = 0; i < pieces.size(); ++i)
          if(!pieces[i].empty() && (any_large || i != largest))
            faces.insert(faces.end(), pieces[i].begin(), pieces[i].end());
      }
      if(2 * faces.size() > component_size[component[f0]])
        continue;
      Disk_parametrization D;
      if(!parametrize_disk(M, faces, D))
        continue;
      std::vector<char> in_disk(M.F, 0);
      for(std::size_t f : faces)
        in_disk[f] = 1;
      // a cut-out face inside a whole cell (that no trace crosses): the cell goes, and its
      // sides become a loop around the face
      {
        std::vector<std::size_t> inside;
        for(std::size_t f : D.faces)
          if(removed[f] && !covered[f])
            inside.push_back(f);
        bool any = false;
        for(std::size_t g = 0; g < soup.polygons.size() && !inside.empty(); ++g)
        {
          if(soup.dropped[g])
            continue;
          std::vector<Q2> cell;
          for(std::size_t u : soup.polygons[g])
            if(D.holds(soup.location[u], in_disk))
              cell.push_back(D.at(soup.location[u]));
          if(cell.size() != soup.polygons[g].size())
            continue;
          for(std::size_t f : inside)
            if(inside_polygon(centroid_of(D, f), cell))
            {
              soup.dropped[g] = 1;
              ++report.replaced;
              any = true;
              break;
            }
        }
        if(any)
          refresh();
      }
      for(bool again = true; again;)
      {
        again = false;
      for(std::size_t l = 0; l < loops.size() && !again; ++l)
      {
        const std::vector<std::size_t> loop = loops[l];
        bool held = true, touches_border = false;
        for(std::size_t v : loop)
        {
          held = held && D.holds(soup.location[v], in_disk);
          touches_border = touches_border || on_border(soup.location[v]);
        }
        if(held && !touches_border && fill_polygon(D, in_disk, loop, {}, surface_holes(D, loop, {}), l))
        {
          report.rings = (std::max)(report.rings, rings);
          refresh();
          again = true;
          continue;
        }
        // a hole at the surface's border: the loop leaves the border (or a free border, near
        // it) at A, goes around the hole and comes back at B; the border from B to A closes
        // the polygon. The chains are the runs of the loop's corners that the disk holds,
        // without the stretches along the border at their ends.
        const std::size_t m = loop.size();
        if(held && !touches_border)
          continue;
        // the sequences of held corners: the runs between corners that the disk does not
        // hold, or the whole loop from a corner on the border back to it
        std::vector<std::vector<std::size_t> > runs;
        if(held)
        {
          std::size_t b = 0;
          while(!on_border(soup.location[loop[b]]))
            ++b;
          runs.emplace_back();
          for(std::size_t j = 0; j <= m; ++j)
            runs.back().push_back(loop[(b + j) % m]);
        }
        else
          for(std::size_t start = 0; start < m; ++start)
          {
            if(!D.holds(soup.location[loop[start]], in_disk) || D.holds(soup.location[loop[(start + m - 1) % m]], in_disk))
              continue;
            runs.emplace_back();
            for(std::size_t j = start; D.holds(soup.location[loop[j]], in_disk); j = (j + 1) % m)
              runs.back().push_back(loop[j]);
          }
        // the chains: the parts of a run away from the border, between two corners on it
        // (or from an end of the run that is off the border)
        std::vector<std::vector<std::size_t> > chains;
        for(const std::vector<std::size_t>& run : runs)
        {
          std::size_t from = 0;
          for(std::size_t j = 1; j <= run.size(); ++j)
          {
            const bool end = j == run.size();
            if(!end && !on_border(soup.location[run[j]]))
              continue;
            const std::size_t to = end ? run.size() - 1 : j;
            if(to > from + (on_border(soup.location[run[from]]) && on_border(soup.location[run[to]]) ? 1 : 0))
              chains.emplace_back(run.begin() + std::ptrdiff_t(from), run.begin() + std::ptrdiff_t(to) + 1);
            from = to;
          }
        }
        for(std::size_t c = 0; c < chains.size() && !again; ++c)
        {
          const std::vector<std::size_t>& chain = chains[c];
          std::vector<Border_point> closing;
          const bool closed = border_closing(D, in_disk, chain, closing);
          if(closed && fill_polygon(D, in_disk, chain, closing, surface_holes(D, chain, closing), l))
          {
            report.rings = (std::max)(report.rings, rings);
            refresh();
            again = true;
          }
        }
      }
      }
    }
  }
  for(std::size_t f = 0; f < M.F; ++f)
    if(removed[f] && !covered[f])
      report.uncovered_faces.push_back(f);
  report.uncovered = report.uncovered_faces.size();
  if(report.uncovered != 0)
  {
    report.diagnostic = std::to_string(report.uncovered) + " cut-out triangles are in no hole of the quads that could be filled";
    return false;
  }
  return true;
}

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_FOLD_OVER_HOLES_H
