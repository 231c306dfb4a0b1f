// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// Cancellation of close pairs of opposite singularities before the combing
// (see comb_frame_field()): the matching is changed by whole quarter turns along
// the shortest edge path between the two vertices, as in the integer period
// jumps of Bommes, Zimmer, Kobbelt 2009 (mixed-integer quadrangulation).
//
// Why: the map places every singular vertex on an integer point. Two singular
// vertices closer than one quad land on the same point, and the faces between
// them fold over whatever the solver does. A pair of opposite indices closer
// than the quad size is noise of the field, not a feature of the surface.
//
// The frames then turn to follow the new matching (turn_frames_to_matching()):
// without that, the map is guided by frames that disagree with their matching
// by a quarter turn across every edge of every path, and shears along them.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_SINGULARITY_CANCELLATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_SINGULARITY_CANCELLATION_H

#include <CGAL/Polyvector_fields/internal/Field_design/singularity_indices.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/gaussian_integers.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The holonomy of the matching around interior vertex v, mod 4: the sum of the
// shifts met when walking around v from face(c) to face(opposite(next(c))),
// starting from a corner c whose target is v. Shifting corner e by +1 (and its
// opposite by -1) adds 1 at source(e) and takes 1 at target(e).
template <typename CornerMesh>
int matching_holonomy(const CornerMesh& M, const std::vector<int>& shift, std::size_t v)
{
  const std::size_t start = M.vertex_corner[v];
  if(start == npos || M.border_vertex[v])
    return 0;
  int sum = 0;
  std::size_t c = start;
  do
  {
    const std::size_t crossing = CornerMesh::next(c);
    sum += shift[crossing];
    c = M.opposite[crossing];
  } while(c != npos && c != start);
  return mod4(sum);
}

// Singular vertices joined by an edge shorter than this many times the
// separation distance also form a pair (see separate_close_singularities()).
constexpr double adjacent_pair_factor = 1.4142135623730951;

// Singularities closer than `distance` along mesh edges, or joined by one
// edge shorter than adjacent_pair_factor * distance, handled pair by pair, the
// closest first:
// - opposite indices (+k, -k) cancel: the index moves from one to the other;
// - a pair whose merged index k satisfies -2 <= k <= 1 (a quad vertex of valence
//   3 to 6) merges into one of the two;
// - any other pair (two +1, say: merged, a vertex of valence 2) is separated: one of
//   them moves to the closest interior vertex at least `distance` from every other
//   singular vertex, within 3 `distance`.
// Before the pairs, a vertex whose index would make a quad vertex of valence below
// 3 or above 6 (k > 1 or k < -2) is split: it gives one quarter turn at a time to
// such a vertex.
// An index moves from v to w by |k| quarter turns on the corners of the shortest
// edge path through interior vertices; the vertices inside the path keep their
// index (one quarter turn comes in, the same goes out). `shift` and `index` are
// updated; `turns` receives, per corner, the quarter turns added to its shift
// (not reduced mod 4; 0 where nothing moved). Nothing is changed, and
// `consistent` is set to false, when the holonomy of the matching does not
// agree with the indices.
struct Singularity_separation
{
  std::size_t cancelled = 0, merged = 0, separated = 0, split = 0, to_border = 0;
};

template <typename CornerMesh>
Singularity_separation separate_close_singularities(const CornerMesh& M, double distance, std::vector<int>& shift,
                                                    std::vector<int>& index, std::vector<int>& turns, bool& consistent)
{
  Singularity_separation report;
  consistent = true;
  const std::size_t V = M.V, C = 3 * M.F;
  turns.assign(C, 0);
  if(!(distance > 0))
    return report;
  std::vector<std::size_t> singular;
  for(std::size_t v = 0; v < V; ++v)
    if(index[v] != 0 && !M.border_vertex[v])
      singular.push_back(v);
  if(singular.size() < 2)
    return report;

  // The sign that relates the holonomy to the index numerator: holonomy = sign * k (mod 4).
  int sign = 0;
  for(std::size_t v : singular)
  {
    const int h = matching_holonomy(M, shift, v);
    const int plus = mod4(index[v]), minus = mod4(-index[v]);
    if(plus == minus)
      continue;  // k = 2 mod 4 tells nothing
    const int s = h == plus ? 1 : (h == minus ? -1 : 0);
    if(s == 0 || (sign != 0 && s != sign))
    {
      consistent = false;
      return report;
    }
    sign = s;
  }
  if(sign == 0)
    return report;

  // Interior edges, as corners leaving each vertex.
  std::vector<std::vector<std::size_t> > out(V);
  for(std::size_t c = 0; c < C; ++c)
    if(M.opposite[c] != npos)
      out[M.source(c)].push_back(c);

  // Dijkstra through interior vertices within `radius` from the sources;
  // `visit(v, d)` returns true to stop. The arrays are reset after each search.
  std::vector<double> dist(V, -1);
  std::vector<std::size_t> via(V, npos), touched;
  typedef std::pair<double, std::size_t> Item;
  // With to_border, border vertices are reached (visited) but not passed through.
  auto search = [&](const std::vector<std::size_t>& sources, double radius, auto&& visit, bool to_border = false) {
    std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
    for(std::size_t s : sources)
    {
      dist[s] = 0;
      touched.push_back(s);
      queue.push({ 0.0, s });
    }
    while(!queue.empty())
    {
      const auto [d, v] = queue.top();
      queue.pop();
      if(d > dist[v])
        continue;
      if(visit(v, d))
        return;
      if(M.border_vertex[v])
        continue;
      for(std::size_t c : out[v])
      {
        const std::size_t w = M.target[c];
        const double dw = d + M.edge_length(c);
        if(dw >= radius || (M.border_vertex[w] && !to_border))
          continue;
        if(dist[w] < 0 || dw < dist[w])
        {
          if(dist[w] < 0)
            touched.push_back(w);
          dist[w] = dw;
          via[w] = c;
          queue.push({ dw, w });
        }
      }
    }
  };
  auto reset = [&]() {
    for(std::size_t v : touched)
    {
      dist[v] = -1;
      via[v] = npos;
    }
    touched.clear();
  };
  // Moves k of from's index to `to` along the path of the last search from `from`.
  auto transfer = [&](std::size_t from, std::size_t to, int k) {
    // Along corner c, index(source) -= k and index(target) += k: the holonomy at
    // the source changes by -sign*k, so the corner's shift does.
    for(std::size_t w = to; w != from;)
    {
      const std::size_t c = via[w];
      shift[c] = mod4(shift[c] - sign * k);
      shift[M.opposite[c]] = mod4(shift[M.opposite[c]] + sign * k);
      turns[c] -= sign * k;
      turns[M.opposite[c]] += sign * k;
      w = M.source(c);
    }
    index[to] += k;
    index[from] -= k;
  };
  // Moves `k` of v's index to the closest interior vertex of index 0 at least
  // `distance` from every other singular vertex, within 3 `distance`.
  auto move_away = [&](std::size_t v, int k) {
    std::vector<std::size_t> others;
    for(std::size_t w : singular)
      if(w != v && index[w] != 0)
        others.push_back(w);
    std::vector<double> clearance(V, std::numeric_limits<double>::infinity());
    search(others, 4 * distance, [&](std::size_t w, double d) {
      clearance[w] = d;
      return false;
    });
    reset();
    // v itself keeps index - k: it counts as a singular vertex unless that is 0
    std::size_t target = npos;
    search({ v }, 3 * distance, [&](std::size_t w, double d) {
      if(w != v && index[w] == 0 && !M.border_vertex[w] && clearance[w] >= distance &&
         (index[v] == k || d >= distance))
      {
        target = w;
        return true;
      }
      return false;
    });
    if(target != npos)
    {
      transfer(v, target, k);
      singular.push_back(target);
    }
    reset();
    return target != npos;
  };

  // Vertices of a valence below 3 or above 6 (index k > 1 or k < -2) give away
  // one quarter turn at a time.
  for(std::size_t i = 0; i < singular.size(); ++i)
  {
    const std::size_t v = singular[i];
    while(index[v] > 1 || index[v] < -2)
    {
      if(!move_away(v, index[v] > 0 ? 1 : -1))
        break;
      ++report.split;
    }
  }

  // Singular vertices closer than half `distance` to the border (along interior
  // edges), before the pairs and again after them: the border turns freely, so
  // their index moves onto the closest border vertex within that distance that
  // can take it, and is gone (a border vertex has no holonomy). Kept, such a vertex
  // would be put on an integer point less than half a quad from the border,
  // and the faces between them fold over when the border is on an iso-line,
  // or squeeze when it is free. Index k turns the border by k quarter turns at
  // the vertex that takes it: its angle theta (the sum of its corner angles
  // on the surface) becomes about theta - k pi/2 in the map, which must stay
  // within [pi/4, 7 pi/4], or the border would fold back or overlap itself.
  std::vector<double> border_angle(V, 0);
  for(std::size_t c = 0; c < C; ++c)
    if(M.border_vertex[M.target[c]])
      border_angle[M.target[c]] += corner_angle(M.bundle, M.halfedge[c]);
  auto give_to_border = [&]() {
    for(std::size_t i = 0; i < singular.size(); ++i)
    {
      const std::size_t v = singular[i];
      if(index[v] == 0)
        continue;
      std::size_t target = npos;
      search({ v }, 0.5 * distance, [&](std::size_t w, double) {
        if(!M.border_vertex[w])
          return false;
        const double turned = border_angle[w] - double(index[v]) * CGAL_PI / 2;
        if(!(turned >= CGAL_PI / 4 && turned <= 7 * CGAL_PI / 4))
          return false;
        target = w;
        return true;
      }, true);
      if(target != npos)
      {
        border_angle[target] -= double(index[v]) * CGAL_PI / 2;  // what the next one finds there
        transfer(v, target, index[v]);
        index[target] = 0;
        ++report.to_border;
      }
      reset();
    }
  };
  give_to_border();

  // Close pairs.
  struct Pair
  {
    double length;
    std::size_t a, b;
  };
  std::vector<Pair> pairs;
  for(std::size_t s : singular)
  {
    search({ s }, distance, [&](std::size_t v, double d) {
      if(v > s && index[v] != 0)
        pairs.push_back({ d, s, v });
      return false;
    });
    reset();
    // Two singular vertices joined by one edge shorter than sqrt(2) quads
    // (a coarse mesh) may still round to the same integer point: they are a
    // pair too, joined by that edge.
    for(std::size_t c : out[s])
    {
      const std::size_t v = M.target[c];
      const double length = M.edge_length(c);
      if(v > s && index[v] != 0 && !M.border_vertex[v] && length >= distance && length < adjacent_pair_factor * distance)
        pairs.push_back({ length, s, v });
    }
  }
  std::sort(pairs.begin(), pairs.end(),
            [](const Pair& x, const Pair& y) { return std::tie(x.length, x.a, x.b) < std::tie(y.length, y.a, y.b); });

  for(const Pair& pair : pairs)
  {
    if(index[pair.a] == 0 || index[pair.b] == 0)
      continue;
    const int merged = index[pair.a] + index[pair.b];
    if(merged >= -2 && merged <= 1)
    {
      // cancel or merge: move a's index onto b
      bool reached = false;
      search({ pair.a }, (std::max)(distance, std::nextafter(pair.length, 2 * pair.length + 1)),
             [&](std::size_t v, double) { return reached = (v == pair.b); });
      if(reached)
      {
        transfer(pair.a, pair.b, index[pair.a]);
        ++(merged == 0 ? report.cancelled : report.merged);
      }
      reset();
      continue;
    }
    // separate
    if(move_away(pair.a, index[pair.a]))
      ++report.separated;
  }
  // a singularity moved apart may have landed next to the border
  give_to_border();
  return report;
}

// How far from the changed edges the frames turn, in separation distances.
// Measured on the corpus meshes that fold (the flipped faces of the map, then
// the triangles that its repair left folded, with the CLI's defaults and
// --curvature-constraints 1), for radii 0 (no turning), 2, 3 and 5:
// cow.off 112/62, 52/14, 40/3, 37/5; cheburashka.off 24/22, 12/9, 13/7, 24/11;
// camel_b.obj 62/51, 29/27, 21/5, 16/9; decimated-knight.off 49/34, 9/0,
// 13/11, 15/6. Solving over the whole component (radius 100) was no better.
// The faces beside sharp edges turn too, and a feature edge that the field no
// longer follows is left free by the map (feature_alignment.h): keeping their
// frames (a_f = 0 there) left 72 flipped faces on cow.off, 62 of them folded
// after the repair, and keeping the paths of the transfers off the features
// (fewer cancellations) 177 and 154; on such coarse meshes the edges sharper
// than 40 degrees are mostly noise.
constexpr double frame_turning_radius = 3;

// After separate_close_singularities(): the frames turned to follow the new
// matching. A transfer changes the matching on the edges of its path by whole
// quarter turns and leaves the frames as they were, so that across each edge
// of the path the frames of its two faces disagree with their matching by
// about a quarter turn: the map, guided by the frames, would shear the whole
// path. Each face f near the path turns its frame by the angle a_f that
// minimises
//   sum over interior edges (f, g) of (a_g - a_f + t_fg pi / 2)^2,
// t_fg the quarter turns that the transfers added to the matching from f to g
// (`turns`), with a_f = 0 for the faces farther than `radius` along the edges
// from every changed edge: the mismatch is spread over the faces around the
// path, as in a smooth field with the new singularities. `roots` (per face,
// the four roots of its frame) turn by a_f, and `coefficients` (per face, the
// coefficients c_0, c_1, c_2, c_3 of its polynomial, of degree 4 in z) with
// them: c_k by 4 - k times a_f. Returns the number of faces within the radius;
// 0, with the frames as they were, if the solve fails.
template <typename CornerMesh>
std::size_t turn_frames_to_matching(const CornerMesh& M, const std::vector<int>& turns, double radius,
                                    std::vector<std::array<std::complex<double>, 4> >& roots,
                                    std::vector<std::vector<std::complex<double> > >& coefficients)
{
  const std::size_t V = M.V, F = M.F, C = 3 * F;
  // the vertices within `radius` of a changed edge, by Dijkstra along the edges
  std::vector<std::vector<std::size_t> > out(V);
  for(std::size_t c = 0; c < C; ++c)
    out[M.source(c)].push_back(c);
  std::vector<double> dist(V, std::numeric_limits<double>::infinity());
  typedef std::pair<double, std::size_t> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
  for(std::size_t c = 0; c < C; ++c)
    if(turns[c] != 0)
      for(std::size_t v : { M.target[c], M.source(c) })
        if(dist[v] != 0)
        {
          dist[v] = 0;
          queue.push({ 0.0, v });
        }
  if(queue.empty())
    return 0;
  while(!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if(d > dist[v])
      continue;
    for(std::size_t c : out[v])
    {
      const std::size_t w = M.target[c];
      const double dw = d + M.edge_length(c);
      if(dw < radius && dw < dist[w])
      {
        dist[w] = dw;
        queue.push({ dw, w });
      }
    }
  }
  // the faces of the region, numbered
  std::vector<std::size_t> unknown(F, npos), faces;
  for(std::size_t f = 0; f < F; ++f)
    for(std::size_t k = 0; k < 3; ++k)
      if(std::isfinite(dist[M.target[3 * f + k]]) && unknown[f] == npos)
      {
        unknown[f] = faces.size();
        faces.push_back(f);
      }
  const Eigen::Index n = Eigen::Index(faces.size());
  std::vector<Eigen::Triplet<double> > entries;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  const double quarter = CGAL_PI / 2;
  for(std::size_t c = 0; c < C; ++c)
  {
    const std::size_t o = M.opposite[c];
    if(o == npos)
      continue;
    const std::size_t i = unknown[CornerMesh::face(c)], j = unknown[CornerMesh::face(o)];
    if(i == npos)
      continue;
    // the row of face(c) for edge(c): a_f - a_g = t pi / 2
    entries.emplace_back(Eigen::Index(i), Eigen::Index(i), 1.0);
    if(j != npos)
      entries.emplace_back(Eigen::Index(i), Eigen::Index(j), -1.0);
    b[Eigen::Index(i)] += turns[c] * quarter;
  }
  // a tiny pull towards 0, so that a region that covers a whole component
  // (no face outside it to hold it) has one solution
  for(Eigen::Index i = 0; i < n; ++i)
    entries.emplace_back(i, i, 1e-9);
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > ldlt(L);
  if(ldlt.info() != Eigen::Success)
    return 0;
  const Eigen::VectorXd a = ldlt.solve(b);
  if(ldlt.info() != Eigen::Success || !a.allFinite())
    return 0;
  for(std::size_t i = 0; i < faces.size(); ++i)
  {
    const std::complex<double> turn = std::polar(1.0, a[Eigen::Index(i)]);
    for(auto& r : roots[faces[i]])
      r *= turn;
    std::vector<std::complex<double> >& c = coefficients[faces[i]];
    for(std::size_t k = 0; k < c.size(); ++k)
      c[k] *= std::pow(turn, int(c.size() - k));
  }
  return faces.size();
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_SINGULARITY_CANCELLATION_H
