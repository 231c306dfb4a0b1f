// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The reduced variables of a seamless map (see compute_integer_grid_map()).
//
// Write z = U + iV. Around a vertex v, the cut edges split its corners into
// sectors S_0 .. S_{m-1} (counterclockwise). Crossing a seam of curve c from
// side A to side B gives z_B = i^r z_A + t_c; crossing it from B to A gives
// z_A = i^-r (z_B - t_c). So every sector is z_S = i^a z_v + sum_c g_c t_c,
// with z_v the value of the first sector and g_c in Z[i]. Coming back to S_0
// after a full turn gives the closure relation of v:
//     (i^A - 1) z_v + sum_c G_c t_c = 0.
// It is trivial (A = 0, G = 0) at a vertex inside a seam curve; it ties the
// translations of the curves meeting at a regular branch vertex; at a singular
// vertex it ties them to z_v, which must be integer.
//
// The unknowns are: z_v per regular vertex (continuous), z_s per singular
// vertex (integer), t_c per seam curve (integer). The closure relations are
// eliminated exactly over the Gaussian integers: on a spanning tree of the seam
// graph (nodes: singular, branch and boundary vertices; arcs: curves), the
// relation of each non-root interior node has a unit coefficient (+-1, +-i) on
// the translation of the arc to its parent, which is solved for. Integer
// combinations with unit pivots keep integers integer, so rounding the free
// integer unknowns gives an integer translation on every curve and an integer
// point at every singular vertex. The relation at an interior root is checked
// (it is implied by the others in every test so far; if not, it is eliminated
// on a unit coefficient when there is one).

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_SEAMLESS_REDUCTION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_SEAMLESS_REDUCTION_H

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/comb_and_cut.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/gaussian_integers.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// uv_c = sum over terms of (u, v) * y[column]: each real unknown moves the
// corner's value along an integer vector (a unit one for a vertex's own unknowns).
struct Corner_term
{
  std::size_t column;
  double u, v;
};

// The columns are the continuous unknowns first (columns 0 .. continuous_columns - 1),
// then the integer ones. reduce_seamless_variables() gives two continuous columns
// per regular vertex (its first sector's u and v) and two integer ones per complex
// integer variable; align_features() (feature_alignment.h) then makes some of them integer
// and eliminates others.
struct Seamless_reduction
{
  std::size_t continuous_columns = 0;    // real continuous unknowns
  std::size_t integer_columns = 0;       // real integer unknowns (after elimination and pins)
  std::vector<std::vector<Corner_term> > corner_terms;  // per corner
  std::vector<int> vertex_kind;          // 0 continuous, 1 singular (integer), 2 pinned regular, 3 isolated
  std::vector<signed char> feature_coordinate;  // per corner: the coordinate (0: U, 1: V) constant along edge(c)
                                                // on an integer iso-line; -1: none, -2: a feature left free
  std::size_t inconsistencies = 0;
  std::size_t extra_relations = 0;
};

template <typename CornerMesh>
Error_code reduce_seamless_variables(const CornerMesh& M, const Comb_data& D, Seamless_reduction& R)
{
  const std::size_t V = M.V, C = 3 * M.F;
  R = Seamless_reduction();

  // 1. Sectors: per corner (a, g) with z_c = i^a z_v + sum g_q t_q; per vertex its closure relation.
  std::vector<int> corner_a(C, 0);
  std::vector<Gform> corner_g(C);
  struct Relation
  {
    bool present = false;
    int A = 0;
    Gform G;
  };
  std::vector<Relation> relation(V);
  for(std::size_t v = 0; v < V; ++v)
  {
    const std::size_t c0 = M.vertex_corner[v];
    if(c0 == npos)
      continue;
    std::size_t start = npos, c = c0, guard = 0;
    if(M.border_vertex[v])
    {
      while(M.cw(c) != npos && guard++ < C)
        c = M.cw(c);
      start = c;
    }
    else
    {
      do
      {
        if(D.seam[CornerMesh::next(c)])
        {
          start = c;
          break;
        }
        c = M.cw(c);
      } while(c != c0 && c != npos && guard++ < C);
      if(start == npos)
        start = c0;
    }
    int a = 0;
    Gform g;
    bool crossed_seam = false;
    c = start;
    guard = 0;
    for(;;)
    {
      corner_a[c] = a;
      corner_g[c] = g;
      const std::size_t nc = M.ccw(c);
      if(nc == npos)
        break;
      if(D.seam[c])
      {
        crossed_seam = true;
        const std::size_t q = D.curve_of[c];
        const int r = D.curves[q].rotation;
        if(D.rotation[c] != (D.walk[c] ? r : mod4(-r)))
          ++R.inconsistencies;  // the rotation is not constant along the curve
        if(D.walk[c])
        {
          g = scaled(g, i_power(r));
          add_scaled(g, Gform{ { q, Gint(1, 0) } }, Gint(1, 0));
          a += r;
        }
        else
        {
          add_scaled(g, Gform{ { q, Gint(1, 0) } }, Gint(-1, 0));
          g = scaled(g, i_power(-r));
          a -= r;
        }
      }
      else if(D.rotation[c] != 0)
        ++R.inconsistencies;  // combing failed on a non-cut edge
      if(nc == start)
      {
        relation[v].present = crossed_seam;
        relation[v].A = mod4(a);
        relation[v].G = g;
        break;
      }
      c = nc;
      if(++guard > C)
        return Error_code::NON_MANIFOLD_MESH;  // not a manifold fan
    }
    if(!relation[v].present && (mod4(a) != 0 || !g.empty()) && !M.border_vertex[v])
      ++R.inconsistencies;
    // the closure rotation must agree with the field's index (mod 4)
    if(!M.border_vertex[v] && mod4(relation[v].A + D.index[v]) != 0 && mod4(relation[v].A - D.index[v]) != 0)
      ++R.inconsistencies;
    if(relation[v].present && !D.node[v] && (relation[v].A != 0 || !relation[v].G.empty()))
      ++R.inconsistencies;
  }

  // 2. Seam graph: BFS forest, rooted at a boundary node when there is one.
  const std::size_t Q = D.curves.size();
  std::vector<std::vector<std::pair<std::size_t, std::size_t> > > adjacent(V);
  for(std::size_t q = 0; q < Q; ++q)
  {
    adjacent[D.curves[q].start].emplace_back(q, D.curves[q].end);
    if(D.curves[q].end != D.curves[q].start)
      adjacent[D.curves[q].end].emplace_back(q, D.curves[q].start);
  }
  std::vector<char> seen(V, 0), visited(V, 0);
  std::vector<std::size_t> parent_arc(V, npos), order, roots;
  for(std::size_t v = 0; v < V; ++v)
  {
    if(!D.node[v] || visited[v])
      continue;
    // find the component, prefer a boundary root
    std::vector<std::size_t> component{ v };
    seen[v] = 1;
    std::size_t root = v;
    for(std::size_t i = 0; i < component.size(); ++i)
    {
      const std::size_t x = component[i];
      if(M.border_vertex[x] && !M.border_vertex[root])
        root = x;
      for(const auto& a : adjacent[x])
        if(!seen[a.second])
        {
          seen[a.second] = 1;
          component.push_back(a.second);
        }
    }
    roots.push_back(root);
    std::deque<std::size_t> queue{ root };
    visited[root] = 1;
    while(!queue.empty())
    {
      const std::size_t x = queue.front();
      queue.pop_front();
      order.push_back(x);
      for(const auto& a : adjacent[x])
        if(!visited[a.second])
        {
          visited[a.second] = 1;
          parent_arc[a.second] = a.first;
          queue.push_back(a.second);
        }
    }
  }
  std::vector<char> eliminated(Q, 0);
  for(std::size_t v = 0; v < V; ++v)
    if(parent_arc[v] != npos && relation[v].present)
      eliminated[parent_arc[v]] = 1;

  // 3. Integer variables: singular vertices, then the curves that are not eliminated.
  std::vector<std::size_t> vertex_var(V, npos), curve_var(Q, npos);
  std::size_t vars = 0;
  for(std::size_t v = 0; v < V; ++v)
    if(D.index[v] != 0 && M.vertex_corner[v] != npos)
      vertex_var[v] = vars++;
  std::vector<Gform> T(Q);
  for(std::size_t q = 0; q < Q; ++q)
    if(!eliminated[q])
    {
      curve_var[q] = vars++;
      T[q][curve_var[q]] = Gint(1, 0);
    }
  std::vector<char> ready(Q, 0);
  for(std::size_t q = 0; q < Q; ++q)
    ready[q] = !eliminated[q];
  auto substituted_relation = [&](std::size_t v, std::size_t skip, Gform& out) {
    out.clear();
    for(const auto& kv : relation[v].G)
      if(kv.first != skip)
      {
        if(!ready[kv.first])
          ++R.inconsistencies;
        add_scaled(out, T[kv.first], kv.second);
      }
    const Gint zc = i_power(relation[v].A) - Gint(1, 0);
    if(!zc.is_zero())
    {
      if(vertex_var[v] == npos)
        ++R.inconsistencies;
      else
        add_scaled(out, Gform{ { vertex_var[v], Gint(1, 0) } }, zc);
    }
  };
  for(auto it = order.rbegin(); it != order.rend(); ++it)
  {
    const std::size_t v = *it, q = parent_arc[v];
    if(q == npos || !eliminated[q])
      continue;
    const auto found = relation[v].G.find(q);
    if(found == relation[v].G.end() || !found->second.is_unit())
    {
      ++R.inconsistencies;
      return Error_code::SOLVER_FAILURE;
    }
    Gform rest;
    substituted_relation(v, q, rest);
    T[q] = scaled(rest, -unit_inverse(found->second));
    ready[q] = 1;
  }

  // 4. Relations left at interior roots; substitutions var -> form (pins are empty forms).
  std::map<std::size_t, Gform> substitution;
  std::function<Gform(const Gform&)> resolve = [&](const Gform& form) {
    Gform out;
    for(const auto& kv : form)
    {
      const auto s = substitution.find(kv.first);
      if(s == substitution.end())
        add_scaled(out, Gform{ { kv.first, Gint(1, 0) } }, kv.second);
      else
        add_scaled(out, resolve(s->second), kv.second);
    }
    return out;
  };
  for(std::size_t root : roots)
  {
    if(!relation[root].present)
      continue;
    Gform rest;
    substituted_relation(root, npos, rest);
    rest = resolve(rest);
    if(rest.empty())
      continue;
    ++R.extra_relations;
    // Reduce the relation by unimodular changes of variables (Euclid over Z[i])
    // until a coefficient is a unit, then solve for that variable.
    for(;;)
    {
      Gint g = rest.begin()->second;
      for(const auto& kv : rest)
        g = gaussian_gcd(g, kv.second);
      for(auto& kv : rest)
        kv.second = exact_divide(kv.second, g);
      auto unit = std::find_if(rest.begin(), rest.end(), [](const auto& kv) { return kv.second.is_unit(); });
      if(unit != rest.end())
      {
        const std::size_t j = unit->first;
        const Gint u = unit->second;
        rest.erase(j);
        substitution[j] = scaled(rest, -unit_inverse(u));
        break;
      }
      if(rest.size() < 2)
        return Error_code::SOLVER_FAILURE;  // a single non-unit coefficient: the variable is 0, not expected
      // b: the smallest coefficient, a: another one; y_q = w - k y_p with k = round(a / b)
      auto q = std::min_element(rest.begin(), rest.end(),
                                [](const auto& x, const auto& y) { return norm(x.second) < norm(y.second); });
      auto p = rest.begin() == q ? std::next(rest.begin()) : rest.begin();
      const Gint b = q->second, a = p->second, k = rounded_quotient(a, b);
      const std::size_t w = vars++;
      substitution[q->first] = Gform{ { w, Gint(1, 0) }, { p->first, -k } };
      p->second = a - k * b;
      if(p->second.is_zero())
        rest.erase(p);
      rest.erase(q);
      rest[w] = b;
    }
  }

  // 5. Pins: per component, a singular vertex at the origin, else the first vertex.
  R.vertex_kind.assign(V, 3);
  std::size_t components = 0;
  for(std::size_t f = 0; f < M.F; ++f)
    components = (std::max)(components, D.component[f] + 1);
  std::vector<std::size_t> pinned_singular(components, npos), first_vertex(components, npos);
  for(std::size_t v = 0; v < V; ++v)
  {
    if(M.vertex_corner[v] == npos)
      continue;
    const std::size_t comp = D.component[CornerMesh::face(M.vertex_corner[v])];
    if(first_vertex[comp] == npos)
      first_vertex[comp] = v;
    if(vertex_var[v] != npos && pinned_singular[comp] == npos && !substitution.count(vertex_var[v]))
      pinned_singular[comp] = v;
  }
  for(std::size_t comp = 0; comp < components; ++comp)
    if(pinned_singular[comp] != npos)
      substitution[vertex_var[pinned_singular[comp]]] = Gform();
  std::vector<std::size_t> column_of_vertex(V, npos);
  std::size_t continuous_vertices = 0;
  for(std::size_t v = 0; v < V; ++v)
  {
    if(M.vertex_corner[v] == npos)
      continue;
    const std::size_t comp = D.component[CornerMesh::face(M.vertex_corner[v])];
    if(vertex_var[v] != npos)
      R.vertex_kind[v] = 1;
    else if(pinned_singular[comp] == npos && first_vertex[comp] == v)
      R.vertex_kind[v] = 2;
    else
    {
      R.vertex_kind[v] = 0;
      column_of_vertex[v] = 2 * continuous_vertices++;
    }
  }
  const std::size_t nx = 2 * continuous_vertices;
  std::size_t integer_variables = 0;
  std::vector<std::size_t> column_of_var(vars, npos);
  for(std::size_t j = 0; j < vars; ++j)
    if(!substitution.count(j))
      column_of_var[j] = nx + 2 * integer_variables++;

  // 6. Corner terms.
  R.corner_terms.assign(C, std::vector<Corner_term>());
  for(std::size_t c = 0; c < C; ++c)
  {
    const std::size_t v = M.target[c];
    const Gint rot = i_power(corner_a[c]);
    Gform W;
    for(const auto& kv : corner_g[c])
      add_scaled(W, T[kv.first], kv.second);
    if(vertex_var[v] != npos)
      add_scaled(W, Gform{ { vertex_var[v], Gint(1, 0) } }, rot);
    W = resolve(W);
    auto& terms = R.corner_terms[c];
    // (p + iq)(y0 + i y1): y0 moves uv by (p, q), y1 by (-q, p)
    auto add_complex = [&terms](std::size_t column, Gint coefficient) {
      terms.push_back(Corner_term{ column, double(coefficient.re), double(coefficient.im) });
      terms.push_back(Corner_term{ column + 1, -double(coefficient.im), double(coefficient.re) });
    };
    if(R.vertex_kind[v] == 0)
      add_complex(column_of_vertex[v], rot);
    for(const auto& kv : W)
      add_complex(column_of_var[kv.first], kv.second);
  }
  R.continuous_columns = nx;
  R.integer_columns = 2 * integer_variables;
  return Error_code::SUCCESS;
}

// Worst seam residual of corner values: for every interior edge, both sides
// must match by uv_B = i^r uv_A + t with the edge's combed rotation r and
// one t in Z^2 for both endpoints (t = 0 off the cut).
template <typename CornerMesh>
double seam_residual(const CornerMesh& M, const Comb_data& D, const std::vector<std::complex<double> >& uv)
{
  typedef std::complex<double> Complex;
  double worst = 0;
  for(std::size_t c = 0; c < 3 * M.F; ++c)
  {
    const std::size_t o = M.opposite[c];
    if(o == npos || o < c)
      continue;
    const Gint rg = i_power(D.seam[c] ? D.rotation[c] : 0);
    const Complex rot(double(rg.re), double(rg.im));
    // corner c: value at target(c) in face(c); same vertex in face(o) is prev(o)'s target... :
    // target(c) = source(o) = target(prev(o)); source(c) = target(o).
    const Complex a1 = uv[c], b1 = uv[CornerMesh::prev(o)];
    const Complex a2 = uv[CornerMesh::prev(c)], b2 = uv[o];
    const Complex t1 = b1 - rot * a1, t2 = b2 - rot * a2;
    const Complex t(std::round(t1.real()), std::round(t1.imag()));
    worst = (std::max)({ worst, std::abs(t1 - t), std::abs(t2 - t) });
    if(!D.seam[c])
      worst = (std::max)(worst, std::abs(t));
  }
  return worst;
}

// Worst distance of the value of a singular vertex (in any of its corners) to the integer grid.
template <typename CornerMesh>
double singularity_residual(const CornerMesh& M, const Comb_data& D, const std::vector<std::complex<double> >& uv)
{
  double worst = 0;
  for(std::size_t c = 0; c < 3 * M.F; ++c)
    if(D.index[M.target[c]] != 0)
    {
      const std::complex<double> z = uv[c];
      worst = (std::max)({ worst, std::abs(z.real() - std::round(z.real())), std::abs(z.imag() - std::round(z.imag())) });
    }
  return worst;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_SEAMLESS_REDUCTION_H
