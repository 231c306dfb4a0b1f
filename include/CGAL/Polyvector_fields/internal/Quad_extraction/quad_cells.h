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
#include <CGAL/Polyvector_fields/internal/Quad_extraction/Extractor.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/fold_check.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/split_wrapping_cells.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <algorithm>
#include <cstddef>
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

// Builds the quad mesh (cleared first) from the cells, `ends` being the traces of the
// iso-line slots; folded quads are repaired if `repair_folds`. `result` is a
// Quad_extraction_result.
template <typename PolygonMesh, typename NamedParametersOut, typename Report>
Error_code build_quad_mesh(const Chart_mesh& M, const Extractor& X, const Cells& C, const std::vector<Trace_end>& ends,
                           bool repair_folds, PolygonMesh& quad_mesh, const NamedParametersOut& np_out, Report& result)
{
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
    double x[3];
    for(int a = 0; a < 3; ++a)
    {
      Q sum(0);
      for(std::size_t i = 0; i < n; ++i)
        sum += w[i] * Q(P[i][a]);
      x[a] = CGAL::to_double(sum);
    }
    return Out_point(x[0], x[1], x[2]);
  };
  // the point of uv q in the closed triangle f (in its chart), by its barycentric coordinates
  auto in_face = [&](std::size_t f, const P2& q) {
    Q U[3][2];
    for(std::size_t k = 0; k < 3; ++k)
      for(int c = 0; c < 2; ++c)
        U[k][c] = Q(M.corner_uv(f, k)[c]);
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
    const std::array<double, 3> PP[3] = { M.point[M.vertex[3 * f]], M.point[M.vertex[3 * f + 1]], M.point[M.vertex[3 * f + 2]] };
    return lerp3(PP, w, 3);
  };
  std::vector<Out_point> positions;
  positions.reserve(out_point.size());
  for(std::size_t p : out_point)
  {
    const Qpoint& P = X.points[p];
    if(P.loc == AT_VERTEX)
    {
      const auto& x = M.point[P.elem];
      positions.push_back(Out_point(x[0], x[1], x[2]));
    }
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
        const P2 &A = M.uv[a], &B = M.uv[b];
        const int coord = A[0] != B[0] ? 0 : 1;
        lam = (Q(P.uv[coord]) - Q(A[coord])) / (Q(B[coord]) - Q(A[coord]));
      }
      if(M.vertex[b] < M.vertex[a])
      {
        std::swap(a, b);
        lam = Q(1) - lam;
      }
      const std::array<double, 3> PP[2] = { M.point[M.vertex[a]], M.point[M.vertex[b]] };
      const Q w[2] = { Q(1) - lam, lam };
      positions.push_back(lerp3(PP, w, 2));
    }
    else
      positions.push_back(in_face(P.elem, P.uv));
  }
  // Every connected component of the surface must get cells: one without is
  // smaller than a quad at the map's scale (or its map has no integer cell).
  {
    std::vector<std::size_t> component(M.F, npos), component_faces, component_cells;
    std::vector<std::size_t> stack;
    for(std::size_t f0 = 0; f0 < M.F; ++f0)
    {
      if(component[f0] != npos)
        continue;
      const std::size_t k = component_faces.size();
      component_faces.push_back(0);
      component[f0] = k;
      stack.assign(1, f0);
      while(!stack.empty())
      {
        const std::size_t f = stack.back();
        stack.pop_back();
        ++component_faces[k];
        for(std::size_t e = 3 * f; e < 3 * f + 3; ++e)
          if(M.opp[e] != npos && component[Chart_mesh::face(M.opp[e])] == npos)
          {
            component[Chart_mesh::face(M.opp[e])] = k;
            stack.push_back(Chart_mesh::face(M.opp[e]));
          }
      }
    }
    component_cells.assign(component_faces.size(), 0);
    for(const std::vector<std::size_t>& cell : C.cells)
      for(std::size_t s : cell)
        if(X.slots[s].face != npos && X.slots[s].face < M.F)
        {
          ++component_cells[component[X.slots[s].face]];
          break;
        }
    result.components = component_faces.size();
    std::size_t first_empty = npos;
    for(std::size_t k = 0; k < component_faces.size(); ++k)
      if(component_cells[k] == 0)
      {
        ++result.components_without_cells;
        if(first_empty == npos)
          first_empty = k;
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
  std::vector<std::vector<std::size_t> > polygons;
  for(std::size_t f = 0; f < C.cells.size(); ++f)
  {
    std::vector<std::size_t> poly;
    for(std::size_t s : C.cells[f])
      poly.push_back(corner_vertex_of_slot[s]);
    polygons.push_back(poly);
  }
  // Trimmed cells that go around the surface (split_wrapping_cells.h): points inside
  // the iso-lines that would be loops or double edges, then diagonals; `changed`
  // cells are replaced by their pieces once the quads are checked.
  std::vector<char> changed(C.cells.size(), 0);
  std::vector<std::vector<std::size_t> > pieces;
  bool simple = true;
  if(X.trimmed_)
  {
    std::vector<Inner_point> inner;
    const std::size_t failed = subdivide_wrapping_segments(M, X, C.cells, ends, positions.size(), polygons, inner, changed);
    for(const Inner_point& p : inner)
      positions.push_back(in_face(p.face, p.uv));
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
  for(std::size_t f = 0; f < C.cells.size(); ++f)
    if(changed[f])
      continue;
    else if(polygons[f].size() == 4 && !C.has_boundary_piece[f])
      ++result.quads;
    else
      ++result.trimmed_polygons;
  result.trimmed_polygons += pieces.size();
  // Every quad is checked against the input faces under it (the faces its sides were
  // traced through, and the face nearest to its centroid); the folded ones are repaired
  // by moving their corners on the surface, or the extraction fails.
  {
    std::vector<std::vector<std::size_t> > quads(C.cells.size()), under(C.cells.size());
    for(std::size_t f = 0; f < C.cells.size(); ++f)
    {
      // (a cell that passes twice through a vertex is refused below: NON_DISK_CELL)
      if(polygons[f].size() != 4 || C.has_boundary_piece[f] || changed[f] || has_repeated_vertex(polygons[f]))
        continue;
      quads[f] = polygons[f];
      for(std::size_t s : C.cells[f])
      {
        if(s < ends.size())
          under[f].insert(under[f].end(), ends[s].faces.begin(), ends[s].faces.end());
        if(X.slots[s].face < M.F)
          under[f].push_back(X.slots[s].face);
      }
      std::sort(under[f].begin(), under[f].end());
      under[f].erase(std::unique(under[f].begin(), under[f].end()), under[f].end());
    }
    std::vector<P3> pos(positions.size());
    for(std::size_t v = 0; v < positions.size(); ++v)
      pos[v] = { CGAL::to_double(positions[v].x()), CGAL::to_double(positions[v].y()), CGAL::to_double(positions[v].z()) };
    const Fold_report fold = unfold_quads(M, quads, under, pos, repair_folds);
    result.folded_quads = fold.folded - fold.unfolded;
    result.unfolded_quads = fold.unfolded;
    result.moved_quad_vertices = fold.moved_vertices;
    if(result.folded_quads != 0)
    {
      P3 centre{ 0, 0, 0 };
      for(std::size_t v : polygons[fold.first_folded])
        for(int a = 0; a < 3; ++a)
          centre[a] += 0.25 * pos[v][a];
      result.diagnostic = std::to_string(result.folded_quads) + " of the " + std::to_string(polygons.size()) +
                          " quads fold against the surface (neither diagonal gives two triangles on the side of the input "
                          "faces under the quad), " + std::to_string(fold.unfolded) + " others were repaired; the first one near (" +
                          std::to_string(centre[0]) + ", " + std::to_string(centre[1]) + ", " + std::to_string(centre[2]) +
                          "): the surface bends by more than a right angle under one quad there";
      return Error_code::FOLDED_QUAD;
    }
    for(std::size_t v = 0; v < positions.size(); ++v)
      if(pos[v][0] != CGAL::to_double(positions[v].x()) || pos[v][1] != CGAL::to_double(positions[v].y()) ||
         pos[v][2] != CGAL::to_double(positions[v].z()))
        positions[v] = Out_point(pos[v][0], pos[v][1], pos[v][2]);
  }
  {
    std::size_t kept = 0;
    for(std::size_t f = 0; f < polygons.size(); ++f)
      if(!changed[f])
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
