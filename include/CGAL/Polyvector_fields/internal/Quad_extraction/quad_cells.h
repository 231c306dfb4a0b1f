// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The cells of the traced iso-lines (faces of the quad mesh), and the output
// mesh: vertices split where their kept faces form several fans, positions
// from barycentric coordinates computed in exact rationals, rounded once.
// Written from Ebke, Bommes, Campen, Kobbelt 2013 (QEx), not from its code.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_QUAD_CELLS_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_QUAD_CELLS_H

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/Chart_mesh.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/component_check.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/Extractor.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/fold_check.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/fold_over_holes.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/split_wrapping_cells.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/tip_snapping.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <algorithm>
#include <cstddef>
#include <memory>
#include <numeric>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
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

// The closed cycles of slots: next(s) = the slot before partner(s) in the
// counterclockwise order at its point.
struct Cells
{
  std::vector<std::vector<std::size_t> > cells;  // slots of each kept face
  std::vector<char> has_boundary_piece;          // per cell
  std::vector<std::size_t> position;             // per slot: its position at its point
};

template <typename Report>
void collect_cells(const Extractor& X, bool trimmed, Cells& C, Report& result)
{
  std::vector<std::size_t>& position = C.position;
  position.assign(X.slots.size(), npos);
  for(const Qpoint& P : X.points)
    for(std::size_t i = 0; i < P.slots.size(); ++i)
      position[P.slots[i]] = i;
  std::vector<char> visited(X.slots.size(), 0);
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
    C.cells.push_back(cycle);
    C.has_boundary_piece.push_back(boundary_piece);
  }
}

// What build_quad_mesh() does beyond whole cells: the named parameters of
// extract_quad_mesh() (fold_over_repair_rings, fill_fold_overs,
// split_components_without_cells, tip_snapping_distance, max_input_distance)
// and its concurrency.
struct Quad_mesh_settings
{
  std::size_t rings = 0;      // the regions of holes grown by up to this many rings
  bool repair_folds = true;   // folded quads are repaired
  bool fill = true;           // the quads still folded after their repair are cut out and filled
  bool split_small = false;   // a component without a whole cell gets its triangles split into quads
  double tip_distance = 0;    // input vertices farther than this many mean quad sides pull a corner (0: none)
  double max_distance = 0;    // a component whose input is farther from its quads is split into quads (0: none)
  bool parallel = false;      // the distances of the input to the quads are shared among threads
};

// Builds the quad mesh (cleared first) from the cells, `ends` being the traces of the
// iso-line slots; folded quads are repaired if `settings.repair_folds`. `result` is a
// Quad_extraction_result. The cells were extracted from W: the surface M itself, or,
// with `cut`, M without its fold-overs, whose holes are then filled (whole cells only),
// the regions grown by up to `settings.rings` rings; with `settings.fill`, the quads still
// folded after their repair are cut out and filled in the same way, and a component where
// they cannot be filled gets its triangles split into quads; with `settings.split_small`,
// so does a component without a whole cell (unless every component is without), and with
// `settings.max_distance` > 0, a component whose input is farther than that from the quads.
// Input vertices farther than `settings.tip_distance` mean quad sides from the quads pull a
// corner onto themselves (0: none).
template <typename PolygonMesh, typename NamedParametersOut, typename Report>
Error_code build_quad_mesh(const Chart_mesh& M, const Chart_mesh& W, const Fold_over_cut* cut, const Extractor& X,
                           const Cells& C, const std::vector<Trace_end>& ends, const Quad_mesh_settings& settings,
                           PolygonMesh& quad_mesh, const NamedParametersOut& np_out, Report& result)
{
  const std::size_t rings = settings.rings;
  const bool repair_folds = settings.repair_folds, fill = settings.fill, split_small = settings.split_small;
  const double tip_distance = settings.tip_distance, max_distance = settings.max_distance;
  // a face of W on the surface M
  auto surface_face = [&](std::size_t w) { return cut ? cut->surface_face[w] : w; };
  // sector i at point P: between slots[i] (outgoing of a face corner) and slots[i+1]
  std::vector<std::vector<std::size_t> > sector_face(X.points.size());
  for(std::size_t p = 0; p < X.points.size(); ++p)
    sector_face[p].assign(X.points[p].slots.size(), npos);
  for(std::size_t f = 0; f < C.cells.size(); ++f)
    for(std::size_t s : C.cells[f])
    {
      // the face corner at point(s) lies between s and the slot after it (the one whose partner precedes s)
      const Qpoint& P = X.points[X.slots[s].point];
      (void)P;
      sector_face[X.slots[s].point][C.position[s]] = f;
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
  // sum of w[i] P[i], exact, rounded once per coordinate: a point that the map puts at a
  // mesh vertex, or at a point with exact coordinates, gets exactly these coordinates
  auto lerp3 = [&](const std::array<double, 3>* P, const Q* w, std::size_t n) {
    P3 x;
    for(int a = 0; a < 3; ++a)
    {
      Q sum(0);
      for(std::size_t i = 0; i < n; ++i)
        sum += w[i] * Q(P[i][a]);
      x[a] = CGAL::to_double(sum);
    }
    return x;
  };
  // the point of uv q in the closed triangle f (in its chart), by its barycentric coordinates
  auto in_face = [&](std::size_t f, const P2& q) {
    Q U[3][2];
    for(std::size_t k = 0; k < 3; ++k)
      for(int c = 0; c < 2; ++c)
        U[k][c] = Q(W.corner_uv(f, k)[c]);
    const Q qx(q[0]), qy(q[1]);
    auto det = [](const Q& ax, const Q& ay, const Q& bx, const Q& by, const Q& cx, const Q& cy) -> Q {
      return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    };
    const Q area = det(U[0][0], U[0][1], U[1][0], U[1][1], U[2][0], U[2][1]);
    Q w[3];
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      w[k] = det(qx, qy, U[k1][0], U[k1][1], U[k2][0], U[k2][1]) / area;
    }
    const std::array<double, 3> PP[3] = { W.point[W.vertex[3 * f]], W.point[W.vertex[3 * f + 1]], W.point[W.vertex[3 * f + 2]] };
    return lerp3(PP, w, 3);
  };
  // (each point on its own, in doubles: shared among threads with settings.parallel;
  // the output points are made after, on this thread)
  std::vector<P3> coordinates(out_point.size());
  for_each_range(settings.parallel, out_point.size(), 512, [&](std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i)
    {
      const Qpoint& P = X.points[out_point[i]];
      if(P.loc == AT_VERTEX)
        coordinates[i] = W.point[P.elem];
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
          const P2 &A = W.uv[a], &B = W.uv[b];
          const int coord = A[0] != B[0] ? 0 : 1;
          lam = (Q(P.uv[coord]) - Q(A[coord])) / (Q(B[coord]) - Q(A[coord]));
        }
        if(W.vertex[b] < W.vertex[a])
        {
          std::swap(a, b);
          lam = Q(1) - lam;
        }
        const std::array<double, 3> PP[2] = { W.point[W.vertex[a]], W.point[W.vertex[b]] };
        const Q w[2] = { Q(1) - lam, lam };
        coordinates[i] = lerp3(PP, w, 2);
      }
      else
        coordinates[i] = in_face(P.elem, P.uv);
    }
  });
  std::vector<Out_point> positions;
  positions.reserve(coordinates.size());
  for(const P3& x : coordinates)
    positions.push_back(Out_point(x[0], x[1], x[2]));
  std::vector<std::vector<std::size_t> > polygons;
  std::vector<std::size_t> polygon_face;  // a surface face under each polygon
  for(std::size_t f = 0; f < C.cells.size(); ++f)
  {
    std::vector<std::size_t> poly;
    std::size_t face = npos;
    for(std::size_t s : C.cells[f])
    {
      poly.push_back(corner_vertex_of_slot[s]);
      if(face == npos && X.slots[s].face != npos && X.slots[s].face < W.F)
        face = surface_face(X.slots[s].face);
    }
    polygons.push_back(poly);
    polygon_face.push_back(face);
  }
  // the surface faces under each cell: the faces its sides were traced through
  std::vector<std::vector<std::size_t> > under(C.cells.size());
  for(std::size_t f = 0; f < C.cells.size(); ++f)
  {
    for(std::size_t s : C.cells[f])
    {
      if(s < ends.size())
        for(std::size_t g : ends[s].faces)
          under[f].push_back(surface_face(g));
      if(X.slots[s].face < W.F)
        under[f].push_back(surface_face(X.slots[s].face));
    }
    std::sort(under[f].begin(), under[f].end());
    under[f].erase(std::unique(under[f].begin(), under[f].end()), under[f].end());
  }
  // polygons replaced by the filling of a hole (an island inside it)
  std::vector<char> dropped(C.cells.size(), 0);
  // Whole cells: the holes that fold-overs leave are filled, then or once the quads are
  // checked (fill_holes() on the soup of the polygons made so far).
  std::vector<Surface_location> location;
  if(!X.trimmed_)
  {
    std::vector<std::size_t> same(cut ? 0 : W.F);
    std::iota(same.begin(), same.end(), std::size_t(0));
    for(std::size_t p : out_point)
      location.push_back(surface_location(M, W, cut ? cut->surface_face : same, X.points[p]));
  }
  std::vector<std::size_t> uncovered;  // cut-out faces that the last filling could not cover
  auto fill_holes = [&](const std::vector<char>& removed, std::size_t max_rings, std::string& why) {
    Quad_soup soup;
    for(const Out_point& x : positions)
      soup.position.push_back({ CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z()) });
    soup.location = location;
    soup.polygons = polygons;
    soup.under = under;
    soup.dropped = dropped;
    Hole_fill_report fill;
    const bool filled = fill_fold_over_holes(M, removed, max_rings, soup, fill);
    result.filled_holes += fill.holes;
    result.filling_quads += fill.quads;
    result.replaced_quads += fill.replaced;
    result.filling_rings = (std::max)(result.filling_rings, fill.rings);
    why = fill.diagnostic;
    uncovered = fill.uncovered_faces;
    for(std::size_t v = positions.size(); v < soup.position.size(); ++v)
      positions.push_back(Out_point(soup.position[v][0], soup.position[v][1], soup.position[v][2]));
    for(std::size_t f = polygons.size(); f < soup.polygons.size(); ++f)
      polygon_face.push_back(soup.under[f].empty() ? npos : soup.under[f][0]);
    polygons.swap(soup.polygons);
    under.swap(soup.under);
    dropped.swap(soup.dropped);
    location.swap(soup.location);
    return filled;
  };
  std::vector<std::size_t> component, component_faces;
  face_components(M, component, component_faces);
  // A component whose holes cannot be filled gets its triangles split into quads, three
  // each, around their centroids and through their edge midpoints (on the surface, its
  // edges kept, never folded).
  auto split_components = [&](const std::vector<std::size_t>& faces_in) {
    std::vector<char> split(component_faces.size(), 0);
    for(std::size_t t : faces_in)
      split[component[t]] = 1;
    for(std::size_t f = 0; f < polygons.size(); ++f)
      if(polygon_face[f] != npos && split[component[polygon_face[f]]])
        dropped[f] = 1;
    auto add_point = [&](const P3& x, const Surface_location& L) {
      positions.push_back(Out_point(x[0], x[1], x[2]));
      location.push_back(L);
      return positions.size() - 1;
    };
    std::vector<std::size_t> at_vertex(M.V, npos), at_edge(3 * M.F, npos);
    for(std::size_t t = 0; t < M.F; ++t)
    {
      if(!split[component[t]])
        continue;
      std::size_t corner[3], middle[3];
      for(std::size_t k = 0; k < 3; ++k)
      {
        const std::size_t v = M.vertex[3 * t + k];
        if(at_vertex[v] == npos)
        {
          Surface_location L;
          L.n = 1;
          L.v[0] = v;
          L.w[0] = 1;
          at_vertex[v] = add_point(M.point[v], L);
        }
        corner[k] = at_vertex[v];
        const std::size_t e = 3 * t + k, canonical = M.opp[e] == npos ? e : (std::min)(e, M.opp[e]);
        if(at_edge[canonical] == npos)
        {
          Surface_location L;
          L.n = 2;
          L.v = { M.vertex[e], M.vertex[Chart_mesh::next(e)], npos };
          L.w = { 0.5, 0.5, 0 };
          L.face = { t, M.opp[e] == npos ? npos : Chart_mesh::face(M.opp[e]) };
          L.edge = e;
          const P3 &a = M.point[L.v[0]], &b = M.point[L.v[1]];
          at_edge[canonical] = add_point({ 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) }, L);
        }
        middle[k] = at_edge[canonical];
      }
      Surface_location L;
      L.n = 3;
      P3 g{ 0, 0, 0 };
      for(std::size_t k = 0; k < 3; ++k)
      {
        L.v[k] = M.vertex[3 * t + k];
        L.w[k] = 1.0 / 3;
        for(int a = 0; a < 3; ++a)
          g[a] += M.point[L.v[k]][a] / 3;
      }
      L.face = { t, npos };
      const std::size_t centre = add_point(g, L);
      for(std::size_t k = 0; k < 3; ++k)
      {
        polygons.push_back({ corner[k], middle[k], centre, middle[(k + 2) % 3] });
        under.push_back({ t });
        dropped.push_back(0);
        polygon_face.push_back(t);
      }
      ++result.split_triangles;
    }
    for(char s : split)
      result.split_components += s;
  };
  if(cut)
  {
    std::string why;
    if(!fill_holes(cut->removed, rings, why))
      split_components(uncovered);
  }
  // Every connected component of the surface must get faces: one without is
  // smaller than a quad at the map's scale (or its map has no integer cell).
  {
    std::vector<std::size_t> component_cells(component_faces.size(), 0);
    for(std::size_t f = 0; f < polygons.size(); ++f)
      if(!dropped[f] && polygon_face[f] != npos)
        ++component_cells[component[polygon_face[f]]];
    result.components = component_faces.size();
    std::size_t first_empty = npos;
    for(std::size_t k = 0; k < component_faces.size(); ++k)
      if(component_cells[k] == 0)
      {
        ++result.components_without_cells;
        if(first_empty == npos)
          first_empty = k;
      }
    // with `split_small`, components without a cell (not all of them) are split into quads
    if(first_empty != npos && split_small && !X.trimmed_ && result.components_without_cells < component_faces.size())
    {
      std::vector<std::size_t> faces_in;
      for(std::size_t t = 0; t < M.F; ++t)
        if(component_cells[component[t]] == 0)
        {
          faces_in.push_back(t);
          component_cells[component[t]] = 1;
        }
      split_components(faces_in);
      result.split_small_components = result.components_without_cells;
      result.components_without_cells = 0;
      first_empty = npos;
    }
    if(first_empty != npos)
    {
      std::size_t face_of_first = 0;
      while(component[face_of_first] != first_empty)
        ++face_of_first;
      result.diagnostic =
        (component_faces.size() == 1 ? std::string("the surface") :
                                       std::to_string(result.components_without_cells) + " of the " +
                                         std::to_string(component_faces.size()) + " components, the first one (" +
                                         std::to_string(component_faces[first_empty]) + " faces, face " +
                                         std::to_string(face_of_first) + "),") +
        " has no whole integer cell of the map: the quad size is larger than the surface there";
      return Error_code::NO_INTEGER_CELL;
    }
  }
  // Trimmed cells that go around the surface (split_wrapping_cells.h): points inside
  // the iso-lines that would be loops or double edges, then diagonals; `changed`
  // cells are replaced by their pieces once the quads are checked.
  std::vector<char> changed(polygons.size(), 0);
  std::vector<std::vector<std::size_t> > pieces;
  bool simple = true;
  if(X.trimmed_)
  {
    std::vector<Inner_point> inner;
    const std::size_t failed = subdivide_wrapping_segments(W, X, C.cells, ends, positions.size(), polygons, inner, changed);
    for(const Inner_point& p : inner)
    {
      const P3 x = in_face(p.face, p.uv);
      positions.push_back(Out_point(x[0], x[1], x[2]));
    }
    std::set<std::pair<std::size_t, std::size_t> > edges;
    for(const std::vector<std::size_t>& poly : polygons)
      for(std::size_t k = 0; k < poly.size(); ++k)
      {
        const std::size_t a = poly[k], b = poly[(k + 1) % poly.size()];
        edges.insert(std::make_pair((std::min)(a, b), (std::max)(a, b)));
      }
    std::vector<std::array<double, 3> > at(positions.size());
    for(std::size_t v = 0; v < positions.size(); ++v)
      at[v] = { CGAL::to_double(positions[v].x()), CGAL::to_double(positions[v].y()), CGAL::to_double(positions[v].z()) };
    for(std::size_t f = 0; f < polygons.size(); ++f)
      if(changed[f] || has_repeated_vertex(polygons[f]))
      {
        changed[f] = 1;
        simple = split_at_repeated_vertices(polygons[f], at, edges, pieces) && simple;
      }
    simple = simple && failed == 0;
    for(std::size_t f = 0; f < polygons.size(); ++f)
      result.split_cells += changed[f];
    result.added_vertices = inner.size();
  }
  auto boundary_piece = [&](std::size_t f) { return f < C.cells.size() && C.has_boundary_piece[f]; };
  for(std::size_t f = 0; f < polygons.size(); ++f)
    if(changed[f] || dropped[f])
      continue;
    else if(polygons[f].size() == 4 && !boundary_piece(f))
      ++result.quads;
    else
      ++result.trimmed_polygons;
  result.trimmed_polygons += pieces.size();
  // Every quad is checked against the input faces under it (the faces its sides were
  // traced through, and the face nearest to its centroid); the folded ones are repaired
  // by moving their corners on the surface, or the extraction fails.
  {
    std::vector<std::vector<std::size_t> > quads;
    std::vector<P3> pos;
    // `out`: the polygons kept so far that are quads (a cell that passes twice through a
    // vertex is refused below: NON_DISK_CELL), and `pos` their points in double
    auto kept_quads = [&](std::vector<std::vector<std::size_t> >& out) {
      changed.resize(polygons.size(), 0);
      out.assign(polygons.size(), {});
      for(std::size_t f = 0; f < polygons.size(); ++f)
        if(polygons[f].size() == 4 && !boundary_piece(f) && !changed[f] && !dropped[f] && !has_repeated_vertex(polygons[f]))
          out[f] = polygons[f];
      pos.resize(positions.size());
      for(std::size_t v = 0; v < positions.size(); ++v)
        pos[v] = { CGAL::to_double(positions[v].x()), CGAL::to_double(positions[v].y()), CGAL::to_double(positions[v].z()) };
    };
    // the surface in an AABB tree, for the fold check and the tips: made once, when first needed
    std::unique_ptr<Fold_check> surface;
    auto surface_check = [&]() -> const Fold_check& {
      if(!surface)
        surface.reset(new Fold_check(M));
      return *surface;
    };
    auto check_quads = [&]() {
      kept_quads(quads);
      const Fold_report report = unfold_quads(M, surface_check(), quads, under, pos, repair_folds, settings.parallel);
      std::vector<std::vector<std::size_t> > corner_quads(positions.size());
      for(std::size_t f = 0; f < quads.size(); ++f)
        for(std::size_t v : quads[f])
          corner_quads[v].push_back(f);
      for(std::size_t v = 0; v < positions.size(); ++v)
      {
        const P3 before{ CGAL::to_double(positions[v].x()), CGAL::to_double(positions[v].y()),
                         CGAL::to_double(positions[v].z()) };
        if(before == pos[v])
          continue;
        positions[v] = Out_point(pos[v][0], pos[v][1], pos[v][2]);
        // where the repair moved the corner: a vertex or an edge midpoint of a face under its quads
        if(location.empty())
          continue;
        for(std::size_t f : corner_quads[v])
          for(std::size_t t : under[f])
            for(std::size_t k = 0; k < 3; ++k)
            {
              const std::size_t e = 3 * t + k, a = M.vertex[e], b = M.vertex[Chart_mesh::next(e)];
              const P3 middle{ 0.5 * (M.point[a][0] + M.point[b][0]), 0.5 * (M.point[a][1] + M.point[b][1]),
                               0.5 * (M.point[a][2] + M.point[b][2]) };
              Surface_location L;
              if(M.point[a] == pos[v])
              {
                L.n = 1;
                L.v[0] = a;
                L.w[0] = 1;
              }
              else if(middle == pos[v])
              {
                L.n = 2;
                L.v = { a, b, npos };
                L.w = { 0.5, 0.5, 0 };
                L.face = { t, M.opp[e] == npos ? npos : Chart_mesh::face(M.opp[e]) };
                L.edge = e;
              }
              else
                continue;
              location[v] = L;
            }
      }
      return report;
    };
    Fold_report fold = check_quads();
    result.folded_quads = fold.folded - fold.unfolded;
    result.unfolded_quads = fold.unfolded;
    result.moved_quad_vertices = fold.moved_vertices;
    if(result.folded_quads != 0 && fill && !X.trimmed_ && repair_folds)
    {
      // the quads still folded, and those that share a corner with them, are cut out, and
      // the faces under the folded ones filled as the holes of fold-overs are
      std::vector<char> removed(M.F, 0);
      std::vector<std::vector<std::size_t> > corner_quads(positions.size());
      for(std::size_t f = 0; f < quads.size(); ++f)
        for(std::size_t v : quads[f])
          corner_quads[v].push_back(f);
      for(std::size_t f : fold.still_folded)
      {
        for(std::size_t t : under[f])
          removed[t] = 1;
        for(std::size_t v : quads[f])
          for(std::size_t g : corner_quads[v])
            dropped[g] = 1;
      }
      std::string why;
      if(!fill_holes(removed, rings, why))
        split_components(uncovered);
      {
        const Fold_report again = check_quads();
        result.refilled_quads = fold.still_folded.size();
        result.folded_quads = again.folded - again.unfolded;
        result.unfolded_quads += again.unfolded;
        result.moved_quad_vertices += again.moved_vertices;
        fold = again;
      }
    }
    if(result.folded_quads != 0)
    {
      P3 centre{ 0, 0, 0 };
      for(std::size_t v : polygons[fold.first_folded])
        for(int a = 0; a < 3; ++a)
          centre[a] += 0.25 * pos[v][a];
      result.diagnostic = std::to_string(result.folded_quads) + " of the " + std::to_string(polygons.size()) +
                          " quads fold against the surface (neither diagonal gives two triangles on the side of the input "
                          "faces under the quad), " + std::to_string(result.unfolded_quads) + " others were repaired; the first one near (" +
                          std::to_string(centre[0]) + ", " + std::to_string(centre[1]) + ", " + std::to_string(centre[2]) +
                          "): the surface bends by more than a right angle under one quad there";
      return Error_code::FOLDED_QUAD;
    }
    // Each component's quads are checked (component_check.h): one polygon mesh, in one
    // piece, and on a closed component closed with its Euler characteristic. With
    // `split_small`, a component that fails gets its triangles split into quads.
    if(!X.trimmed_)
    {
      std::vector<char> skip(polygons.size(), 0);
      for(std::size_t f = 0; f < polygons.size(); ++f)
        skip[f] = (f < changed.size() && changed[f]) || dropped[f];
      const std::vector<Component_defect> defects =
        defective_components(M, component, component_faces.size(), polygons, polygon_face, skip);
      if(!defects.empty() && !(split_small && defects.size() < component_faces.size()))
      {
        const Component_defect& d = defects.front();
        result.diagnostic =
          (component_faces.size() == 1 ? std::string("the quads of the surface:") :
                                         std::to_string(defects.size()) + " of the " + std::to_string(component_faces.size()) +
                                           " components are not each one quad mesh, the first one (" +
                                           std::to_string(component_faces[d.component]) + " faces, face " +
                                           std::to_string(d.face) + "):") +
          " " + d.why + ": the quad size is larger than that part of the surface";
        return Error_code::NON_DISK_CELL;
      }
      if(!defects.empty())
      {
        std::vector<std::size_t> faces_in;
        for(const Component_defect& d : defects)
          faces_in.push_back(d.face);
        split_components(faces_in);
        result.split_defective_components = defects.size();
        kept_quads(quads);
      }
    }
    // input vertices far from the quads (tips finer than the quads) pull a corner onto themselves
    Tip_report tips;
    {
      double mean_side = 0;
      std::size_t sides = 0;
      for(const auto& q : quads)
        for(std::size_t k = 0; k < q.size(); ++k)
        {
          const P3 d = sub3(pos[q[(k + 1) % q.size()]], pos[q[k]]);
          mean_side += std::sqrt(dot3(d, d));
          ++sides;
        }
      mean_side = sides > 0 ? mean_side / double(sides) : 0;
      if(repair_folds && tip_distance > 0 && !X.trimmed_)
      {
        tips = snap_to_tips(M, surface_check(), quads, under, pos, tip_distance * mean_side, settings.parallel);
        result.snapped_tips = tips.snapped;
      }
    }
    for(std::size_t v = 0; v < positions.size(); ++v)
      if(pos[v][0] != CGAL::to_double(positions[v].x()) || pos[v][1] != CGAL::to_double(positions[v].y()) ||
         pos[v][2] != CGAL::to_double(positions[v].z()))
        positions[v] = Out_point(pos[v][0], pos[v][1], pos[v][2]);
    // how far the input is from the quads; with `max_distance`, a component farther is split into quads
    std::vector<double> far =
      input_distances(M, quads, pos, component, component_faces.size(), settings.parallel, std::move(tips.final_distances));
    if(max_distance > 0 && !X.trimmed_ && *std::max_element(far.begin(), far.end()) > max_distance)
    {
      std::vector<std::size_t> faces_in;
      for(std::size_t t = 0; t < M.F; ++t)
        if(far[component[t]] > max_distance)
        {
          faces_in.push_back(t);
          far[component[t]] = 0;
          ++result.split_far_components;
        }
      split_components(faces_in);
      std::vector<std::vector<std::size_t> > now;
      kept_quads(now);
      far = input_distances(M, now, pos, component, component_faces.size(), settings.parallel);
    }
    result.largest_input_distance = far.empty() ? 0 : *std::max_element(far.begin(), far.end());
  }
  {
    std::size_t kept = 0;
    for(std::size_t f = 0; f < polygons.size(); ++f)
      if(!changed[f] && !dropped[f])
        polygons[kept++].swap(polygons[f]);
    polygons.resize(kept);
    polygons.insert(polygons.end(), pieces.begin(), pieces.end());
  }
  // A cell that meets itself or goes around the surface is not a polygon: the
  // quads are too large for that part of the surface.
  std::size_t self_meeting = 0, first_self_meeting = npos;
  for(std::size_t f = 0; f < polygons.size(); ++f)
    if(has_repeated_vertex(polygons[f]))
    {
      ++self_meeting;
      if(first_self_meeting == npos)
        first_self_meeting = f;
    }
  auto centre_of = [&](const std::vector<std::size_t>& poly) {
    double c[3] = { 0, 0, 0 };
    for(std::size_t v : poly)
    {
      c[0] += CGAL::to_double(positions[v].x()) / double(poly.size());
      c[1] += CGAL::to_double(positions[v].y()) / double(poly.size());
      c[2] += CGAL::to_double(positions[v].z()) / double(poly.size());
    }
    return "near (" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) + ")";
  };
  if(self_meeting != 0)
  {
    result.diagnostic = std::to_string(self_meeting) + (self_meeting == 1 ? " cell" : " cells") +
                        " of the map pass twice through a point, the first one " + centre_of(polygons[first_self_meeting]) +
                        (X.trimmed_ ? ", and could not be cut into simple polygons" : "") +
                        ": the quad size is larger than that part of the surface";
    return Error_code::NON_DISK_CELL;
  }
  if(!simple)
  {
    result.diagnostic = "an iso-line closes on itself or joins the same two points as another iso-line or the border, "
                        "and could not be cut: the quad size is larger than that part of the surface";
    return Error_code::NON_DISK_CELL;
  }
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
  {
    ++result.inconsistencies;
    result.diagnostic = "the cells do not form a polygon mesh";
    return Error_code::NOT_AN_INTEGER_GRID_MAP;
  }
  if(X.trimmed_)
  {
    // The trimmed cells cover the surface: the polygons have its Euler characteristic
    // unless a cell is not a disk (an annulus around a cylinder, around a handle).
    std::set<std::pair<std::size_t, std::size_t> > edges;
    std::set<std::size_t> used;
    for(const std::vector<std::size_t>& poly : polygons)
      for(std::size_t k = 0; k < poly.size(); ++k)
      {
        const std::size_t a = poly[k], b = poly[(k + 1) % poly.size()];
        edges.insert(std::make_pair((std::min)(a, b), (std::max)(a, b)));
        used.insert(a);
      }
    std::set<std::size_t> surface_vertices(M.vertex.begin(), M.vertex.end());
    std::size_t surface_edges = 0;
    for(std::size_t e = 0; e < 3 * M.F; ++e)
      surface_edges += (M.opp[e] == npos || e < M.opp[e]) ? 1 : 0;
    const long long chi_cells = (long long)(used.size()) - (long long)(edges.size()) + (long long)(polygons.size());
    const long long chi_surface = (long long)(surface_vertices.size()) - (long long)(surface_edges) + (long long)(M.F);
    if(chi_cells != chi_surface)
    {
      // a border loop that no iso-line reaches is the inner border of an annulus
      std::size_t lone_loops = 0;
      for(const std::vector<std::size_t>& cell : C.cells)
      {
        bool border_only = true;
        for(std::size_t s : cell)
          border_only = border_only && X.slots[s].dir < 0;
        lone_loops += border_only ? 1 : 0;
      }
      result.diagnostic = "the cells have Euler characteristic " + std::to_string(chi_cells) + ", the surface " +
                          std::to_string(chi_surface) + " (" + std::to_string(lone_loops) +
                          " border loops that no iso-line reaches)" +
                          ": a cell goes around a hole or a handle of the surface (it is not a disk), the quad size is "
                          "larger than that part of the surface";
      return Error_code::NON_DISK_CELL;
    }
  }
  if(!X.trimmed_)
    result.quads = polygons.size();  // with the fillings and the splits
  // the points of no polygon (those of the polygons that a filling or a split replaced) go
  {
    std::vector<std::size_t> index(positions.size(), npos);
    std::vector<Out_point> kept;
    for(std::vector<std::size_t>& poly : polygons)
      for(std::size_t& v : poly)
      {
        if(index[v] == npos)
        {
          index[v] = kept.size();
          kept.push_back(positions[v]);
        }
        v = index[v];
      }
    positions.swap(kept);
  }
  clear_output(quad_mesh);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(positions, polygons, quad_mesh, CGAL::parameters::default_values(), np_out);
  result.vertices = num_vertices(quad_mesh);
  result.faces = num_faces(quad_mesh);
  for(auto v : vertices(quad_mesh))
    if(!CGAL::is_border(v, quad_mesh) && degree(v, quad_mesh) != 4)
      ++result.irregular_vertices;
  return Error_code::SUCCESS;
}

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_QUAD_CELLS_H
