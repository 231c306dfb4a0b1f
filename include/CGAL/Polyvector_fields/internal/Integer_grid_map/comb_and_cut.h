// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The combing of a frame field along a dual spanning tree and its cut graph
// (see comb_frame_field()): frames cleaned and clamped, principal matching,
// combing, cut graph, pruning, seam curves, on the corners of a tangent bundle.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_COMB_AND_CUT_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_COMB_AND_CUT_H

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Singularity.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/Corner_mesh.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/gaussian_integers.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/singularity_cancellation.h>
#include <CGAL/Polyvector_fields/parameters.h>
#include <CGAL/Polyvector_fields/internal/types.h>
#include <CGAL/Polyvector_fields/polyvector_polynomial.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/iterator.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <deque>
#include <iterator>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// A seam curve: a maximal path of interior cut edges between nodes of the cut
// graph. `corners` are oriented along the path; the face of each is side A,
// the face of its opposite side B, and uv_B = i^rotation uv_A + t.
struct Seam_curve
{
  std::size_t start = npos, end = npos;  // vertex indices
  int rotation = 0;
  std::vector<std::size_t> corners;
};

// Everything the combing and the cut produce, on the corner mesh.
struct Comb_data
{
  std::vector<std::array<std::complex<double>, 4> > roots;  // per face: cleaned unit roots, counterclockwise
                                                            // (turned to the matching near a separation)
  std::vector<std::vector<std::complex<double> > > clean;   // per face: their coefficients
  std::vector<int> offset;        // per face: the combed u is roots[offset], v is roots[offset + 1]
  std::vector<int> shift;         // per corner: principal matching (changed by the separation of singularities),
                                  // root i of face(c) ~ root i + shift of face(opposite)
  std::vector<int> rotation;      // per corner: combed matching r, u of face(c) ~ R^r-th combed root of face(opposite)
  std::vector<char> tree;         // per corner: the dual spanning tree crosses edge(c)
  std::vector<char> seam;         // per corner: edge(c) is an interior cut edge
  std::vector<int> index;         // per vertex: index numerator k (k/4), 0 if regular or on the border
  std::vector<Seam_curve> curves;
  std::vector<std::size_t> curve_of;  // per corner: its seam curve, npos if edge(c) is not a seam
  std::vector<char> walk;             // per corner: c is the oriented corner of its curve (side A)
  std::vector<char> node;             // per vertex: a node of the seam graph
  std::vector<std::size_t> component; // per face: the bundle's component
  std::size_t pruned_nonzero_rotation = 0;  // sanity: pruned edges must have r = 0
  bool matching_inconsistent = false;       // sanity: the holonomy of the matching disagrees with the indices
};

// Reads and cleans the frame of one face: returns 0 if fine, 1 if clamped,
// -1 if not a frame field (size, odd coefficients), -2 if zero (ZERO_FRAME).
inline int clean_frame(const std::vector<std::complex<double> >& c, double min_angle,
                       std::complex<double>& u, std::complex<double>& v)
{
  typedef std::complex<double> Complex;
  if(c.size() != 4)
    return -1;
  const double scale = (std::max)(std::sqrt(std::abs(c[2])), std::sqrt(std::sqrt(std::abs(c[0]))));
  if(!(scale > 0))
    return -2;
  const double tol = 1e-8;
  if(std::abs(c[3]) > tol * scale || std::abs(c[1]) > tol * scale * scale * scale)
    return -1;
  Complex r[4];
  polyvector_roots(c.data(), 4, r, true);
  const double big = (std::max)({ std::abs(r[0]), std::abs(r[1]), std::abs(r[2]), std::abs(r[3]) });
  int status = 0;
  if(std::abs(r[0]) <= 1e-12 * big || std::abs(r[1]) <= 1e-12 * big)
  {
    // one pair is zero: roots are (0, 0, a, -a); keep a, put the other at 90 degrees
    Complex a = std::abs(r[2]) > std::abs(r[0]) ? r[2] : r[0];
    if(std::abs(a) <= 1e-12 * big)
      a = r[3];
    u = a / std::abs(a);
    v = Complex(0, 1) * u;
    return 1;
  }
  u = r[0] / std::abs(r[0]);
  v = r[1] / std::abs(r[1]);
  double phi = std::arg(v * std::conj(u));  // angle from u to v, in [0, pi) for sorted roots
  if(phi < 0)
    phi += 2 * CGAL_PI;
  const double lo = min_angle, hi = CGAL_PI - min_angle;
  if(phi < lo || phi > hi)
  {
    const double target = phi < lo ? lo : hi;
    const Complex bisector = u * std::polar(1.0, phi / 2);
    u = bisector * std::polar(1.0, -target / 2);
    v = bisector * std::polar(1.0, target / 2);
    status = 1;
  }
  return status;
}

// A readable map face -> the cleaned coefficients, for the package's matching and singularities.
template <typename Bundle>
struct Clean_coefficient_map
{
  typedef typename Bundle::face_descriptor key_type;
  typedef std::vector<std::complex<double> > value_type;
  typedef const value_type& reference;
  typedef boost::readable_property_map_tag category;
  const Bundle* bundle;
  const std::vector<value_type>* data;
  friend reference get(const Clean_coefficient_map& m, const key_type& f) { return (*m.data)[m.bundle->index(f)]; }
};

// A writable map edge -> principal matching shift, stored per corner.
template <typename CornerMesh>
struct Matching_writer
{
  typedef typename CornerMesh::GT::edge_descriptor key_type;
  typedef int value_type;
  typedef int reference;
  typedef boost::writable_property_map_tag category;
  const CornerMesh* mesh;
  std::vector<int>* shift;
  friend void put(const Matching_writer& m, const key_type& e, int s)
  {
    const std::size_t c = m.mesh->corner_index(halfedge(e, m.mesh->tm));
    (*m.shift)[c] = mod4(s);
    if(m.mesh->opposite[c] != npos)
      (*m.shift)[m.mesh->opposite[c]] = mod4(-s);
  }
};

// Stage 1 of the pipeline: clean, match, cancel, merge or separate the
// singularities closer than `cancellation_distance` (0: none) and turn the
// frames to the new matching, comb, cut, prune, trace the seam curves.
// `report` is a `Comb_result` (see comb_frame_field.h), reset here.
template <typename CornerMesh, typename CoefficientMap, typename Report>
Error_code comb_and_cut(const CornerMesh& M, CoefficientMap coefficient_map, double min_angle,
                        double cancellation_distance, Comb_data& D, Report& report)
{
  typedef std::complex<double> Complex;
  using boost::get;
  const std::size_t F = M.F, V = M.V, C = 3 * F;
  const auto& bundle = M.bundle;
  D = Comb_data();
  report = Report();
  D.roots.resize(F);
  D.clean.resize(F);

  // 1. Frames: read, check, normalise, clamp.
  for(std::size_t f = 0; f < F; ++f)
  {
    const std::vector<Complex>& c = get(coefficient_map, bundle.face(f));
    for(const Complex& x : c)
      if(!std::isfinite(x.real()) || !std::isfinite(x.imag()))
      {
        report.first_invalid_face = f;
        return Error_code::NON_FINITE_VALUE;
      }
    Complex u, v;
    const int s = clean_frame(c, min_angle, u, v);
    if(s < 0)
    {
      report.first_invalid_face = f;
      return s == -2 ? Error_code::ZERO_FRAME : Error_code::NOT_A_FRAME_FIELD;
    }
    report.clamped_faces += (s == 1);
    D.clean[f] = { u * u * v * v, Complex(0), -(u * u + v * v), Complex(0) };
    Complex r[4];
    polyvector_roots(D.clean[f].data(), 4, r, true);
    for(int k = 0; k < 4; ++k)
      D.roots[f][k] = r[k];
  }

  // 2. Principal matching and singularities of the cleaned field (the package's definitions).
  //    Both read the bundle: no frame or numbering is rebuilt.
  typedef std::decay_t<decltype(bundle)> Bundle;
  Clean_coefficient_map<Bundle> cmap{ &bundle, &D.clean };
  D.shift.assign(C, 0);
  Matching_writer<CornerMesh> writer{ &M, &D.shift };
  Error_code code = principal_matching(bundle, 4, cmap, writer, parameters::sign_symmetric(true));
  if(code != Error_code::SUCCESS)
    return code;
  typedef typename CornerMesh::vertex_descriptor vertex_descriptor;
  std::vector<Singularity<vertex_descriptor> > singularities;
  code = compute_singularities(bundle, 4, cmap, std::back_inserter(singularities), CGAL::Emptyset_iterator());
  if(code != Error_code::SUCCESS)
    return code;
  D.index.assign(V, 0);
  for(const auto& s : singularities)
    D.index[bundle.index(s.vertex)] = s.index_numerator;
  bool consistent = true;
  std::vector<int> turns;
  const Singularity_separation separation =
    separate_close_singularities(M, cancellation_distance, D.shift, D.index, turns, consistent);
  if(consistent)
    report.turned_frames =
      turn_frames_to_matching(M, turns, frame_turning_radius * cancellation_distance, D.roots, D.clean);
  report.cancelled_singularity_pairs = separation.cancelled;
  report.merged_singularity_pairs = separation.merged;
  report.moved_singularities = separation.separated;
  report.split_singularities = separation.split;
  report.singularities_moved_to_border = separation.to_border;
  D.matching_inconsistent = !consistent;
  report.singular_vertices = 0;
  for(std::size_t v = 0; v < V; ++v)
    report.singular_vertices += D.index[v] != 0;

  // 3. Combing along a breadth-first dual spanning tree, one per component of
  //    the bundle, seeded at its first face.
  D.offset.assign(F, -1);
  D.tree.assign(C, 0);
  D.component.resize(F);
  for(std::size_t f = 0; f < F; ++f)
    D.component[f] = bundle.component(f);
  report.components = bundle.number_of_components();
  std::deque<std::size_t> queue;
  for(std::size_t seed = 0; seed < F; ++seed)
  {
    if(D.offset[seed] >= 0)
      continue;
    D.offset[seed] = 0;
    queue.push_back(seed);
    while(!queue.empty())
    {
      const std::size_t f = queue.front();
      queue.pop_front();
      for(std::size_t k = 0; k < 3; ++k)
      {
        const std::size_t c = 3 * f + k, o = M.opposite[c];
        if(o == npos)
          continue;
        const std::size_t g = CornerMesh::face(o);
        if(D.offset[g] >= 0)
          continue;
        D.offset[g] = mod4(D.offset[f] + D.shift[c]);
        D.tree[c] = D.tree[o] = 1;
        queue.push_back(g);
      }
    }
  }
  D.rotation.assign(C, 0);
  for(std::size_t c = 0; c < C; ++c)
    if(M.opposite[c] != npos)
      D.rotation[c] = mod4(D.offset[CornerMesh::face(c)] + D.shift[c] - D.offset[CornerMesh::face(M.opposite[c])]);

  // 4. Cut graph: edges not crossed by the tree; boundary edges belong to it.
  //    Prune dangling branches that do not end at a singular vertex.
  D.seam.assign(C, 0);
  std::vector<int> degree(V, 0);
  for(std::size_t c = 0; c < C; ++c)
  {
    const std::size_t o = M.opposite[c];
    if(o == npos)
    {
      ++degree[M.target[c]];
      ++degree[M.source(c)];
      ++report.boundary_edges;
    }
    else if(!D.tree[c])
    {
      D.seam[c] = 1;
      if(c < o)
      {
        ++degree[M.target[c]];
        ++degree[M.source(c)];
      }
    }
  }
  // one seam corner out of each vertex (corner whose source is the vertex), for pruning
  std::vector<std::vector<std::size_t> > out(V);
  for(std::size_t c = 0; c < C; ++c)
    if(D.seam[c])
      out[M.source(c)].push_back(c);
  std::vector<std::size_t> stack;
  for(std::size_t v = 0; v < V; ++v)
    if(degree[v] == 1 && D.index[v] == 0 && !M.border_vertex[v])
      stack.push_back(v);
  while(!stack.empty())
  {
    const std::size_t v = stack.back();
    stack.pop_back();
    if(degree[v] != 1)
      continue;
    std::size_t c = npos;
    for(std::size_t x : out[v])
      if(D.seam[x])
        c = x;
    if(c == npos)
      continue;
    const std::size_t o = M.opposite[c], w = M.target[c];
    if(D.rotation[c] != 0)
      ++D.pruned_nonzero_rotation;
    D.seam[c] = D.seam[o] = 0;
    --degree[v];
    --degree[w];
    if(degree[w] == 1 && D.index[w] == 0 && !M.border_vertex[w])
      stack.push_back(w);
  }

  // 5. Seam curves between nodes: singular vertices, vertices of seam degree != 2, boundary vertices on a seam.
  std::vector<int> seam_degree(V, 0);
  for(std::size_t c = 0; c < C; ++c)
    if(D.seam[c])
    {
      ++seam_degree[M.source(c)];
      if(c < M.opposite[c])
        ++report.cut_edges;
    }
  D.node.assign(V, 0);
  for(std::size_t v = 0; v < V; ++v)
    D.node[v] = seam_degree[v] > 0 && (D.index[v] != 0 || seam_degree[v] != 2 || M.border_vertex[v]);
  D.curve_of.assign(C, npos);
  D.walk.assign(C, 0);
  for(std::size_t v = 0; v < V; ++v)
    out[v].erase(std::remove_if(out[v].begin(), out[v].end(), [&](std::size_t c) { return !D.seam[c]; }), out[v].end());
  auto trace = [&](std::size_t v, std::size_t c0) {
    Seam_curve curve;
    curve.start = v;
    curve.rotation = D.rotation[c0];
    const std::size_t id = D.curves.size();
    std::size_t c = c0;
    for(;;)
    {
      D.curve_of[c] = D.curve_of[M.opposite[c]] = id;
      D.walk[c] = 1;
      curve.corners.push_back(c);
      const std::size_t w = M.target[c];
      if(D.node[w])
      {
        curve.end = w;
        break;
      }
      std::size_t n = npos;
      for(std::size_t x : out[w])
        if(x != M.opposite[c])
          n = x;
      if(n == npos || D.curve_of[n] != npos)
      {
        curve.end = w;
        break;
      }
      c = n;
    }
    D.curves.push_back(curve);
  };
  for(int pass = 0; pass < 2; ++pass)
    for(std::size_t v = 0; v < V; ++v)
    {
      if(pass == 1 && seam_degree[v] > 0 && !D.node[v])
      {
        // a closed seam loop without node: make v a node
        bool untraced = false;
        for(std::size_t c : out[v])
          untraced |= D.curve_of[c] == npos;
        if(!untraced)
          continue;
        D.node[v] = 1;
      }
      if(!D.node[v])
        continue;
      for(std::size_t c : out[v])
        if(D.curve_of[c] == npos)
          trace(v, c);
    }
  report.seam_curves = D.curves.size();
  return Error_code::SUCCESS;
}

// Reads and checks `minimum_frame_angle`.
template <typename NamedParameters>
Error_code read_minimum_frame_angle(const NamedParameters& np, double& min_angle)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  min_angle = choose_parameter(get_parameter(np, internal_np::minimum_frame_angle), 10.0 * CGAL_PI / 180);
  if(!std::isfinite(min_angle))
    return Error_code::NON_FINITE_VALUE;
  if(!(min_angle > 0) || min_angle > CGAL_PI / 2)
    return Error_code::INVALID_PARAMETER;
  return Error_code::SUCCESS;
}

// Reads and checks `singularity_cancellation_distance` (default 0: none).
template <typename NamedParameters>
Error_code read_cancellation_distance(const NamedParameters& np, double& distance)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  distance = choose_parameter(get_parameter(np, internal_np::singularity_cancellation_distance), 0.0);
  if(!std::isfinite(distance))
    return Error_code::NON_FINITE_VALUE;
  if(distance < 0)
    return Error_code::INVALID_PARAMETER;
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_COMB_AND_CUT_H
