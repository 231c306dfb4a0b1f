// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// Feature curves on integer iso-lines (see compute_integer_grid_map()).
//
// A feature edge (a sharp edge or a border edge) along which the combed field
// runs, within max_feature_angle, must lie on an integer iso-line: in the chart
// of a face f beside it, the coordinate j that does not change along the
// field direction of the edge (V along u, U along v) has the same integer
// value at both ends. In the reduced unknowns of seamless_reduction.h that
// coordinate of a corner is +-(one unknown of its vertex) plus an integer
// combination of integer unknowns, because the rotations between charts are
// quarter turns. So:
//  - the vertex unknown that carries the coordinate becomes integer (it was
//    continuous for a regular vertex; a singular or pinned vertex is integer
//    already): the vertex is on an integer line;
//  - each feature edge gives one relation between integer unknowns, "the
//    coordinate at its two ends is equal", which is eliminated exactly: it is
//    solved for an unknown whose coefficient is +-1 (a vertex unknown of the
//    feature first), so rounding the unknowns that remain keeps every feature
//    edge on an integer line. The relations of consecutive edges chain: one
//    integer unknown per feature curve remains.
// A feature vertex whose edges ask for both coordinates (a corner of the
// features, where the field follows both curves) is then on an integer
// point. A relation that has no coefficient +-1 after the substitutions (a
// closed feature curve whose holonomy reverses the coordinate, never seen on a
// test mesh) cannot be eliminated over the integers: its edge is left free and
// counted. An edge along which the field does not run (feature curves that
// meet at an angle the frame does not have, or a border that the field
// crosses) is left free and counted too.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_FEATURE_ALIGNMENT_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_FEATURE_ALIGNMENT_H

#include <CGAL/Polyvector_fields/internal/Integer_grid_map/comb_and_cut.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/seamless_reduction.h>
#include <CGAL/Polyvector_fields/internal/types.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The largest angle between a feature edge and the field direction it is
// taken to follow (compute_integer_grid_map()'s documentation gives it). A
// field designed with the features as constraints runs exactly along them;
// the margin covers a field that follows a border without being told to.
constexpr double max_feature_angle = CGAL_PI / 6;

// A feature curve that turns by more than this at a vertex, between two edges
// of at least min_corner_edge quads, has a quad corner there (align_features()).
constexpr double min_feature_turn = CGAL_PI / 36;  // 5 degrees
constexpr double min_corner_edge = 1.0;

// The feature corners of the named parameters: edge_is_constrained_map (sharp
// edges), and the border edges with boundary_alignment. Returns whether there is one.
template <typename CornerMesh, typename NamedParameters>
bool feature_corners(const CornerMesh& M, const NamedParameters& np, std::vector<char>& feature)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const std::size_t C = 3 * M.F;
  feature.assign(C, 0);
  bool any = false;
  if(choose_parameter(get_parameter(np, internal_np::boundary_alignment), false))
    for(std::size_t c = 0; c < C; ++c)
      if(M.opposite[c] == npos)
        any = feature[c] = 1;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value)
  {
    const auto ecm = get_parameter(np, CGAL::internal_np::edge_is_constrained);
    for(std::size_t c = 0; c < C; ++c)
      if(get(ecm, edge(M.halfedge[c], M.tm)))
        any = feature[c] = 1;
  }
  return any;
}

struct Feature_alignment_report
{
  std::size_t feature_edges = 0;    // edges asked to be on iso-lines (sharp and border)
  std::size_t aligned_edges = 0;    // of them, on an integer iso-line in the map
  std::size_t unaligned_edges = 0;  // of them, free: the field does not run along them
  std::size_t dropped_edges = 0;    // of them, free: their relation had no unit coefficient
  std::size_t flattening_edges = 0; // of them, free: with another feature edge of a face on one iso-line, they would flatten it
  std::size_t feature_vertices = 0; // vertices on an aligned edge
  std::size_t feature_corners = 0;  // of them, on an integer point (both coordinates)
};

// The coordinate (0: U, 1: V) that stays constant along the edge of corner c
// in face(c), or -1 when the field runs along the edge neither within
// max_angle (radians) nor closer to one direction than to the other.
template <typename CornerMesh>
int constant_coordinate(const CornerMesh& M, const Comb_data& D, std::size_t c, double max_angle)
{
  typedef std::complex<double> Complex;
  const std::size_t f = CornerMesh::face(c);
  const Complex e = M.local_point(c) - M.local_point(CornerMesh::prev(c));
  const double length = std::abs(e);
  if(!(length > 0))
    return -1;
  const Complex u = D.roots[f][std::size_t(D.offset[f])], v = D.roots[f][std::size_t((D.offset[f] + 1) % 4)];
  // |sin| of the angle between the edge and each unit direction
  const double su = std::abs(std::imag(e * std::conj(u))) / length;
  const double sv = std::abs(std::imag(e * std::conj(v))) / length;
  const double limit = std::sin(max_angle);
  if(su <= sv && su <= limit)
    return 1;  // along u: V is constant
  if(sv < su && sv <= limit)
    return 0;  // along v: U is constant
  return -1;
}

// Makes the feature edges of `feature` (per corner: edge(c) is a feature) lie
// on integer iso-lines, by the change of unknowns described above; R's corner
// terms, column counts and feature_coordinate are rewritten.
template <typename CornerMesh>
void align_features(const CornerMesh& M, const Comb_data& D, const std::vector<char>& feature, double max_angle,
                    double quad_size, Seamless_reduction& R, Feature_alignment_report& report)
{
  typedef std::map<std::size_t, long long> Form;  // column -> integer coefficient
  const std::size_t C = 3 * M.F, nx = R.continuous_columns, columns = nx + R.integer_columns;
  R.feature_coordinate.assign(C, -1);

  // 1. The coordinate of each feature edge, in each face beside it.
  std::vector<char> seen_edge(C, 0);
  for(std::size_t c = 0; c < C; ++c)
  {
    if(!feature[c])
      continue;
    const std::size_t o = M.opposite[c];
    if(!seen_edge[c])
    {
      ++report.feature_edges;
      seen_edge[c] = 1;
      if(o != npos)
        seen_edge[o] = 1;
    }
    R.feature_coordinate[c] = static_cast<signed char>(constant_coordinate(M, D, c, max_angle));
  }

  // 1b. Two feature edges of one face that keep the same coordinate meet at
  //     a vertex, so they lie on one iso-line, and the face's three corners
  //     with them: the face would have no area in the map (an ear of the
  //     border, or a triangle across a crease that the field follows on
  //     both sides). The shorter of the two is left free, on both of its
  //     sides (marked -3, counted apart).
  for(std::size_t f = 0; f < M.F; ++f)
    for(std::size_t k = 0; k < 3; ++k)
      for(std::size_t l = k + 1; l < 3; ++l)
      {
        const std::size_t a = 3 * f + k, b = 3 * f + l;
        const int ja = R.feature_coordinate[a], jb = R.feature_coordinate[b];
        if(ja < 0 || ja != jb)
          continue;
        const double la = std::abs(M.local_point(a) - M.local_point(CornerMesh::prev(a))),
                     lb = std::abs(M.local_point(b) - M.local_point(CornerMesh::prev(b)));
        const std::size_t freed = la < lb ? a : b;
        R.feature_coordinate[freed] = -3;
        if(M.opposite[freed] != npos)
          R.feature_coordinate[M.opposite[freed]] = -3;
      }

  // The coordinate j of corner k as a form over the columns.
  auto coordinate_form = [&R](std::size_t k, int j, long long sign, Form& out) {
    for(const Corner_term& term : R.corner_terms[k])
    {
      const long long a = std::llround(j == 0 ? term.u : term.v);
      if(a != 0)
        out[term.column] += sign * a;
    }
  };

  // 2. Vertex unknowns on a feature become integer.
  std::vector<char> integer_column(columns, 0), promoted(columns, 0);
  for(std::size_t k = nx; k < columns; ++k)
    integer_column[k] = 1;
  for(std::size_t c = 0; c < C; ++c)
  {
    const int j = R.feature_coordinate[c];
    if(j < 0)
      continue;
    for(std::size_t k : { CornerMesh::prev(c), c })
    {
      Form f;
      coordinate_form(k, j, 1, f);
      for(const auto& kv : f)
        if(kv.first < nx && kv.second != 0)
          integer_column[kv.first] = promoted[kv.first] = 1;
    }
  }

  // 2b. Turning vertices: a regular vertex with exactly two aligned feature
  //     edges, which turn there by more than min_feature_turn and are both at
  //     least min_corner_edge quads long, goes on an integer point (both of
  //     its unknowns integer). A quad edge between two integer points of one
  //     iso-line is straight in space: without this, it would cut the corner of
  //     a polygonal feature (the rim of a coarse cylinder) instead of following
  //     it. Shorter edges (a finely sampled curve) are left alone: two integer
  //     points closer than one quad would fold the map.
  {
    std::vector<std::vector<std::size_t> > neighbours(M.V);
    for(std::size_t c = 0; c < C; ++c)
    {
      if(R.feature_coordinate[c] < 0)
        continue;
      const std::size_t a = M.source(c), b = M.target[c];
      for(const auto& [x, y] : { std::make_pair(a, b), std::make_pair(b, a) })
        if(std::find(neighbours[x].begin(), neighbours[x].end(), y) == neighbours[x].end())
          neighbours[x].push_back(y);
    }
    const double cos_turn = std::cos(min_feature_turn);
    for(std::size_t v = 0; v < M.V; ++v)
    {
      if(neighbours[v].size() != 2 || R.vertex_kind[v] != 0 || M.vertex_corner[v] == npos)
        continue;
      const std::array<double, 3> in = difference(M.point[v], M.point[neighbours[v][0]]),
                                  out = difference(M.point[neighbours[v][1]], M.point[v]);
      const double a = std::sqrt(in[0] * in[0] + in[1] * in[1] + in[2] * in[2]),
                   b = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
      if(!(a >= min_corner_edge * quad_size) || !(b >= min_corner_edge * quad_size))
        continue;
      if((in[0] * out[0] + in[1] * out[1] + in[2] * out[2]) / (a * b) > cos_turn)
        continue;  // straight there
      for(int j = 0; j < 2; ++j)
      {
        Form f;
        coordinate_form(M.vertex_corner[v], j, 1, f);
        for(const auto& kv : f)
          if(kv.first < nx && kv.second != 0)
            integer_column[kv.first] = promoted[kv.first] = 1;
      }
    }
  }

  // 3. The relations, eliminated in turn; substitution[k] is the form that
  //    replaces column k, kept in terms of columns that are not replaced.
  std::vector<Form> substitution(columns);
  std::vector<char> replaced(columns, 0);
  std::vector<std::vector<std::size_t> > users(columns);  // columns whose substitution mentions k
  for(std::size_t c = 0; c < C; ++c)
  {
    const int j = R.feature_coordinate[c];
    if(j < 0)
      continue;
    Form relation, resolved;
    coordinate_form(CornerMesh::prev(c), j, 1, relation);
    coordinate_form(c, j, -1, relation);
    for(const auto& kv : relation)
    {
      if(kv.second == 0)
        continue;
      if(!replaced[kv.first])
        resolved[kv.first] += kv.second;
      else
        for(const auto& s : substitution[kv.first])
          resolved[s.first] += kv.second * s.second;
    }
    for(auto it = resolved.begin(); it != resolved.end();)
      it = it->second == 0 ? resolved.erase(it) : std::next(it);
    if(resolved.empty())
      continue;  // implied by the relations already eliminated
    // the pivot: a unit coefficient, on a promoted vertex unknown if there is one
    std::size_t pivot = npos;
    for(const auto& kv : resolved)
      if(std::llabs(kv.second) == 1 && (pivot == npos || (promoted[kv.first] && !promoted[pivot])))
        pivot = kv.first;
    if(pivot == npos)
    {
      R.feature_coordinate[c] = -2;  // dropped
      continue;
    }
    const long long a = resolved[pivot];
    resolved.erase(pivot);
    Form form;
    for(const auto& kv : resolved)
      form[kv.first] = -kv.second * a;  // a = +-1 is its own inverse
    for(const auto& kv : form)
      users[kv.first].push_back(pivot);
    // columns replaced earlier whose forms mention the pivot now use its form
    for(std::size_t user : users[pivot])
    {
      if(!replaced[user])
        continue;
      auto found = substitution[user].find(pivot);
      if(found == substitution[user].end())
        continue;
      const long long b = found->second;
      substitution[user].erase(found);
      for(const auto& kv : form)
      {
        long long& x = substitution[user][kv.first];
        x += b * kv.second;
        users[kv.first].push_back(user);
        if(x == 0)
          substitution[user].erase(kv.first);
      }
    }
    users[pivot].clear();
    substitution[pivot] = form;
    replaced[pivot] = 1;
  }

  // 4. New columns: the continuous ones first, then the integer ones.
  std::vector<std::size_t> new_column(columns, npos);
  std::size_t continuous = 0, integer = 0;
  for(std::size_t k = 0; k < columns; ++k)
    if(!replaced[k] && !integer_column[k])
      new_column[k] = continuous++;
  for(std::size_t k = 0; k < columns; ++k)
    if(!replaced[k] && integer_column[k])
      new_column[k] = continuous + integer++;
  for(std::size_t c = 0; c < C; ++c)
  {
    std::map<std::size_t, std::pair<double, double> > merged;
    for(const Corner_term& term : R.corner_terms[c])
    {
      if(!replaced[term.column])
      {
        auto& x = merged[new_column[term.column]];
        x.first += term.u;
        x.second += term.v;
        continue;
      }
      for(const auto& s : substitution[term.column])
      {
        auto& x = merged[new_column[s.first]];
        x.first += term.u * double(s.second);
        x.second += term.v * double(s.second);
      }
    }
    auto& terms = R.corner_terms[c];
    terms.clear();
    for(const auto& kv : merged)
      if(kv.second.first != 0 || kv.second.second != 0)
        terms.push_back(Corner_term{ kv.first, kv.second.first, kv.second.second });
  }
  R.continuous_columns = continuous;
  R.integer_columns = integer;

  // 5. Counts, per edge and per vertex.
  std::vector<char> feature_vertex(M.V, 0);
  for(std::size_t c = 0; c < C; ++c)
  {
    if(!feature[c])
      continue;
    const std::size_t o = M.opposite[c];
    if(o != npos && o < c)
      continue;  // counted from the other side
    const int a = R.feature_coordinate[c], b = o == npos ? -1 : R.feature_coordinate[o];
    if(a >= 0 || b >= 0)
    {
      ++report.aligned_edges;
      feature_vertex[M.target[c]] = feature_vertex[M.source(c)] = 1;
    }
    else if(a == -2 || b == -2)
      ++report.dropped_edges;
    else if(a == -3 || b == -3)
      ++report.flattening_edges;
    else
      ++report.unaligned_edges;
  }
  // A regular vertex is a corner of the features when none of its unknowns is continuous any more.
  std::vector<char> on_point(M.V, 1);
  for(std::size_t c = 0; c < C; ++c)
    for(const Corner_term& term : R.corner_terms[c])
      if(term.column < continuous)
        on_point[M.target[c]] = 0;
  for(std::size_t v = 0; v < M.V; ++v)
    if(feature_vertex[v])
    {
      ++report.feature_vertices;
      if(on_point[v] && R.vertex_kind[v] == 0)
        ++report.feature_corners;
    }
}

// The exact check of the alignment: at both ends of every aligned edge, the
// constant coordinate is the same integer. Empty when it holds; else says where.
template <typename CornerMesh>
std::string check_feature_alignment(const CornerMesh& M, const std::vector<signed char>& feature_coordinate,
                                    const std::vector<std::complex<double> >& uv)
{
  for(std::size_t c = 0; c < feature_coordinate.size(); ++c)
  {
    const int j = feature_coordinate[c];
    if(j < 0)
      continue;
    const std::size_t p = CornerMesh::prev(c);
    const double a = j == 0 ? uv[p].real() : uv[p].imag(), b = j == 0 ? uv[c].real() : uv[c].imag();
    if(a != b || a != std::round(a))
    {
      std::ostringstream s;
      s.precision(17);
      s << "the feature edge of corner " << c << " (vertices " << M.target[p] << ", " << M.target[c]
        << ") is not on an integer iso-line: its " << (j == 0 ? "u" : "v") << " goes from " << a << " to " << b;
      return s.str();
    }
  }
  return std::string();
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_FEATURE_ALIGNMENT_H
