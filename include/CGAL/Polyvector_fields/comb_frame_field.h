// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_COMB_FRAME_FIELD_H
#define CGAL_POLYVECTOR_FIELDS_COMB_FRAME_FIELD_H

/// \file comb_frame_field.h
/// Combing of a frame field along a dual spanning tree, and the cut graph that
/// opens each component of the mesh into a disk (Bommes, Zimmer, Kobbelt 2009,
/// Section 3; Kaelberer, Nieser, Polthier 2007, Section 4), on the faces,
/// numbering and transport of one `Tangent_bundle`.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Singularity.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>
#include <CGAL/Polyvector_fields/polyvector_polynomial.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
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
#include <limits>
#include <map>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// reports what `comb_frame_field()` (and the first stage of
/// `compute_integer_grid_map()`) found.
struct Comb_result
{
  std::size_t clamped_faces = 0;       ///< faces whose frame was clamped (angle below the bound, or one zero vector)
  std::size_t singular_vertices = 0;   ///< interior vertices of non-zero index
  std::size_t cut_edges = 0;           ///< interior edges of the cut graph (the seams)
  std::size_t boundary_edges = 0;      ///< boundary edges (always in the cut)
  std::size_t seam_curves = 0;         ///< maximal seam paths between nodes of the cut graph
  std::size_t components = 0;          ///< connected components of the mesh
  std::size_t first_invalid_face = 0;  ///< on `NOT_A_FRAME_FIELD`, `ZERO_FRAME` or a non-finite coefficient (`NON_FINITE_VALUE`): the index of the first bad face, in the bundle's numbering (the order of `faces(tm)`)
};

namespace internal {

constexpr std::size_t igm_npos = std::size_t(-1);

// ---------------------------------------------------------------------------
// Gaussian integers: the coefficients of the seam relations. A rotation by
// R^r (r quarter turns counterclockwise) of a uv vector is the multiplication
// of U + iV by i^r, so every seam relation has coefficients in Z[i].
// ---------------------------------------------------------------------------
struct Gint
{
  long long re = 0, im = 0;
  Gint() {}
  Gint(long long r, long long i) : re(r), im(i) {}
  bool is_zero() const { return re == 0 && im == 0; }
  bool is_unit() const { return std::llabs(re) + std::llabs(im) == 1; }
};
inline Gint operator+(Gint a, Gint b) { return Gint(a.re + b.re, a.im + b.im); }
inline Gint operator-(Gint a, Gint b) { return Gint(a.re - b.re, a.im - b.im); }
inline Gint operator-(Gint a) { return Gint(-a.re, -a.im); }
inline Gint operator*(Gint a, Gint b) { return Gint(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re); }
inline bool operator==(Gint a, Gint b) { return a.re == b.re && a.im == b.im; }
inline Gint i_power(int r)
{
  switch(((r % 4) + 4) % 4)
  {
    case 0: return Gint(1, 0);
    case 1: return Gint(0, 1);
    case 2: return Gint(-1, 0);
    default: return Gint(0, -1);
  }
}
inline Gint unit_inverse(Gint u) { return Gint(u.re, -u.im); }  // for |u| = 1
inline int mod4(int r) { return ((r % 4) + 4) % 4; }
inline long long norm(Gint a) { return a.re * a.re + a.im * a.im; }
// nearest Gaussian integer to a / b
inline Gint rounded_quotient(Gint a, Gint b)
{
  const Gint n = a * Gint(b.re, -b.im);
  const double d = double(norm(b));
  return Gint(std::llround(double(n.re) / d), std::llround(double(n.im) / d));
}
inline Gint gaussian_gcd(Gint a, Gint b)
{
  while(!b.is_zero())
  {
    const Gint r = a - rounded_quotient(a, b) * b;
    a = b;
    b = r;
  }
  return a;
}
// a / b, b dividing a
inline Gint exact_divide(Gint a, Gint b) { return rounded_quotient(a, b); }

// A Z[i]-linear form: variable -> coefficient (zero coefficients removed).
typedef std::map<std::size_t, Gint> Gform;
inline void add_scaled(Gform& a, const Gform& b, Gint s)
{
  for(const auto& kv : b)
  {
    Gint& x = a[kv.first];
    x = x + s * kv.second;
    if(x.is_zero())
      a.erase(kv.first);
  }
}
inline Gform scaled(const Gform& a, Gint s)
{
  Gform out;
  add_scaled(out, a, s);
  return out;
}

// ---------------------------------------------------------------------------
// The mesh by corners, on a tangent bundle: corner 3f+k is the k-th halfedge of
// face f (the bundle's face index), starting at halfedge(f). Vertices, frames
// and components are the bundle's; only the corners are numbered here.
// ---------------------------------------------------------------------------
template <typename Bundle>
struct Corner_mesh
{
  typedef typename Bundle::Triangle_mesh TriangleMesh;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  const Bundle& bundle;
  const TriangleMesh& tm;
  std::size_t F = 0, V = 0;
  Numbering<halfedge_descriptor> corner_index;
  std::vector<std::array<double, 3> > point;      // per vertex index
  std::vector<char> border_vertex;                // per vertex index
  std::vector<halfedge_descriptor> halfedge;      // per corner
  std::vector<std::size_t> target, opposite;      // per corner; opposite = npos on the border
  std::vector<std::size_t> vertex_corner;         // per vertex: one corner whose target it is (npos: isolated)

  explicit Corner_mesh(const Bundle& b) : bundle(b), tm(b.mesh())
  {
    if(bundle.status() != Error_code::SUCCESS)
      return;
    V = bundle.number_of_vertices();
    F = bundle.number_of_faces();
    point.reserve(V);
    for(std::size_t v = 0; v < V; ++v)
      point.push_back(bundle.point(v));
    border_vertex.assign(V, 0);
    halfedge.resize(3 * F);
    target.resize(3 * F);
    opposite.assign(3 * F, igm_npos);
    vertex_corner.assign(V, igm_npos);
    for(std::size_t f = 0; f < F; ++f)
    {
      halfedge_descriptor h = CGAL::halfedge(bundle.face(f), tm);
      for(std::size_t k = 0; k < 3; ++k, h = CGAL::next(h, tm))
      {
        halfedge[3 * f + k] = h;
        corner_index.add(h);
        target[3 * f + k] = bundle.index(CGAL::target(h, tm));
        vertex_corner[target[3 * f + k]] = 3 * f + k;
      }
    }
    for(std::size_t c = 0; c < 3 * F; ++c)
    {
      const halfedge_descriptor o = CGAL::opposite(halfedge[c], tm);
      if(CGAL::is_border(o, tm))
      {
        border_vertex[target[c]] = 1;
        border_vertex[source(c)] = 1;
      }
      else
        opposite[c] = corner_index(o);
    }
  }

  Error_code status() const { return bundle.status(); }
  static std::size_t next(std::size_t c) { return c - c % 3 + (c % 3 + 1) % 3; }
  static std::size_t prev(std::size_t c) { return c - c % 3 + (c % 3 + 2) % 3; }
  static std::size_t face(std::size_t c) { return c / 3; }
  std::size_t source(std::size_t c) const { return target[prev(c)]; }
  // next corner counterclockwise around target(c), crossing edge(c); npos at the border
  std::size_t ccw(std::size_t c) const { return opposite[c] == igm_npos ? igm_npos : prev(opposite[c]); }
  // previous corner counterclockwise around target(c)
  std::size_t cw(std::size_t c) const { return opposite[next(c)]; }
  // 2D coordinates in the frame of face(c) of target(c), relative to source(halfedge(face))
  std::complex<double> local_point(std::size_t c) const
  {
    const std::size_t f = face(c);
    const std::array<double, 3>& p0 = point[target[3 * f + 2]];
    const std::array<double, 3> d = difference(point[target[c]], p0);
    return bundle.frame(f).to_complex(d[0], d[1], d[2]);
  }
};

// A seam curve: a maximal path of interior cut edges between nodes of the cut
// graph. `corners` are oriented along the path; the face of each is side A,
// the face of its opposite side B, and uv_B = i^rotation uv_A + t.
struct Seam_curve
{
  std::size_t start = igm_npos, end = igm_npos;  // vertex indices
  int rotation = 0;
  std::vector<std::size_t> corners;
};

// Everything the combing and the cut produce, on the corner mesh.
struct Comb_data
{
  std::vector<std::array<std::complex<double>, 4> > roots;  // per face: cleaned unit roots, counterclockwise
  std::vector<std::vector<std::complex<double> > > clean;   // per face: their coefficients
  std::vector<int> offset;        // per face: the combed u is roots[offset], v is roots[offset + 1]
  std::vector<int> shift;         // per corner: principal matching, root i of face(c) ~ root i + shift of face(opposite)
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
  Comb_result report;
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
    const std::size_t c = m.mesh->corner_index(CGAL::halfedge(e, m.mesh->tm));
    (*m.shift)[c] = mod4(s);
    if(m.mesh->opposite[c] != igm_npos)
      (*m.shift)[m.mesh->opposite[c]] = mod4(-s);
  }
};

// Stage 1 of the pipeline: clean, match, comb, cut, prune, trace the seam curves.
template <typename CornerMesh, typename CoefficientMap>
Error_code comb_and_cut(const CornerMesh& M, CoefficientMap coefficient_map, double min_angle, Comb_data& D)
{
  typedef std::complex<double> Complex;
  using boost::get;
  const std::size_t F = M.F, V = M.V, C = 3 * F;
  const auto& bundle = M.bundle;
  D = Comb_data();
  D.roots.resize(F);
  D.clean.resize(F);

  // 1. Frames: read, check, normalise, clamp.
  for(std::size_t f = 0; f < F; ++f)
  {
    const std::vector<Complex>& c = get(coefficient_map, bundle.face(f));
    for(const Complex& x : c)
      if(!std::isfinite(x.real()) || !std::isfinite(x.imag()))
      {
        D.report.first_invalid_face = f;
        return Error_code::NON_FINITE_VALUE;
      }
    Complex u, v;
    const int s = clean_frame(c, min_angle, u, v);
    if(s < 0)
    {
      D.report.first_invalid_face = f;
      return s == -2 ? Error_code::ZERO_FRAME : Error_code::NOT_A_FRAME_FIELD;
    }
    D.report.clamped_faces += (s == 1);
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
  D.report.singular_vertices = singularities.size();

  // 3. Combing along a breadth-first dual spanning tree, one per component of
  //    the bundle, seeded at its first face.
  D.offset.assign(F, -1);
  D.tree.assign(C, 0);
  D.component.resize(F);
  for(std::size_t f = 0; f < F; ++f)
    D.component[f] = bundle.component(f);
  D.report.components = bundle.number_of_components();
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
        if(o == igm_npos)
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
    if(M.opposite[c] != igm_npos)
      D.rotation[c] = mod4(D.offset[CornerMesh::face(c)] + D.shift[c] - D.offset[CornerMesh::face(M.opposite[c])]);

  // 4. Cut graph: edges not crossed by the tree; boundary edges belong to it.
  //    Prune dangling branches that do not end at a singular vertex.
  D.seam.assign(C, 0);
  std::vector<int> degree(V, 0);
  for(std::size_t c = 0; c < C; ++c)
  {
    const std::size_t o = M.opposite[c];
    if(o == igm_npos)
    {
      ++degree[M.target[c]];
      ++degree[M.source(c)];
      ++D.report.boundary_edges;
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
    std::size_t c = igm_npos;
    for(std::size_t x : out[v])
      if(D.seam[x])
        c = x;
    if(c == igm_npos)
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
        ++D.report.cut_edges;
    }
  D.node.assign(V, 0);
  for(std::size_t v = 0; v < V; ++v)
    D.node[v] = seam_degree[v] > 0 && (D.index[v] != 0 || seam_degree[v] != 2 || M.border_vertex[v]);
  D.curve_of.assign(C, igm_npos);
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
      std::size_t n = igm_npos;
      for(std::size_t x : out[w])
        if(x != M.opposite[c])
          n = x;
      if(n == igm_npos || D.curve_of[n] != igm_npos)
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
          untraced |= D.curve_of[c] == igm_npos;
        if(!untraced)
          continue;
        D.node[v] = 1;
      }
      if(!D.node[v])
        continue;
      for(std::size_t c : out[v])
        if(D.curve_of[c] == igm_npos)
          trace(v, c);
    }
  D.report.seam_curves = D.curves.size();
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

} // namespace internal

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// combs the frame field `{+-u, +-v}` of a mesh along a dual spanning tree and
/// computes its cut graph (Bommes, Zimmer, Kobbelt 2009, Section 3).
///
/// The field is read as 4 coefficients per face (a sign-symmetric 4-PolyVector,
/// as `design_polyvector_field()` with `sign_symmetric(true)`,
/// `Polyvector_field_designer` and the frame-field algorithms write it). Per
/// face, `u` and `v` are two consecutive roots in the counterclockwise order of
/// `polyvector_roots()`, normalised to unit length; if they make an angle below
/// `minimum_frame_angle` (or above pi minus it), they are turned symmetrically
/// about their bisector to that angle, and if one of them is zero it is replaced
/// by the other turned by 90 degrees: both faces are counted in
/// `Comb_result::clamped_faces`.
///
/// Combing chooses, per face, which root is `u` so that the principal matching
/// of the cleaned field (see `principal_matching()`) is the identity on every
/// edge that a breadth-first dual spanning tree crosses (one tree per connected
/// component, rooted at its first face). The cut graph is made of the other
/// edges, boundary edges included; its dangling branches are pruned unless they
/// end at a singular vertex (see `compute_singularities()`), so it passes
/// through every singular vertex and every handle and opens each component
/// into a disk.
///
/// All computations are done in `double`, in the frames of the tangent bundle.
///
/// \tparam Mesh_or_bundle a `Tangent_bundle`, or a model of `FaceListGraph` (whose bundle is then built
///         with the named parameter `vertex_point_map`); in both cases the mesh is a triangle mesh
/// \tparam CoefficientMap a model of `ReadablePropertyMap` from faces to `std::vector<std::complex<double>>` of size 4
/// \tparam CutEdgeMap a model of `WritablePropertyMap` from edges to `bool`: true on the cut graph, boundary edges included
/// \tparam CombedFrameMap a model of `WritablePropertyMap` from faces to `std::array<Vector_3, 2>`:
///         the combed unit `u` and `v`, in world coordinates
/// \tparam RotationMap a model of `WritablePropertyMap` from halfedges to `int` in `0..3`: the rotation `r`
///         of the transition from `face(h)` to `face(opposite(h))` (`uv' = R^r uv + t`, `R` the quarter
///         turn); written for both halfedges of every interior edge, 0 off the cut
///
/// \param mesh_or_bundle the mesh, or its tangent bundle
/// \param coefficient_map the frame field
/// \param cut_edge_map receives the cut graph
/// \param combed_frame_map receives the combed frames
/// \param rotation_map receives the rotations of the transitions
/// \param result receives the counts of the combing and the cut (also on failure, as far as they were computed)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{minimum_frame_angle}
///     \cgalParamDescription{the smallest angle, in radians, between `u` and `v`: frames below it are
///                           clamped to it; given with `Polyvector_fields::parameters::minimum_frame_angle()`}
///     \cgalParamType{`double` in `(0, pi/2]`}
///     \cgalParamDefault{10 degrees}
///   \cgalParamNEnd
///   \pvfParamVertexPointMap
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::SUCCESS`; a mesh error of the bundle (`EMPTY_MESH`, `NON_TRIANGLE_FACE`,
///          `DEGENERATE_FACE`); `NON_FINITE_VALUE` for a coefficient or a parameter;
///          `NOT_A_FRAME_FIELD` if a face does not hold 4 coefficients or has non-zero odd
///          coefficients; `ZERO_FRAME` if a face's frame is zero (it cannot be clamped);
///          `INVALID_PARAMETER` for `minimum_frame_angle` out of range. For the errors of the
///          field, `result.first_invalid_face` is the face. Nothing is written to the maps on failure.
///
/// \sa `compute_integer_grid_map()`, `principal_matching()`, `compute_singularities()`
template <typename Mesh_or_bundle, typename CoefficientMap, typename CutEdgeMap, typename CombedFrameMap,
          typename RotationMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code comb_frame_field(const Mesh_or_bundle& mesh_or_bundle, CoefficientMap coefficient_map,
                            CutEdgeMap cut_edge_map, CombedFrameMap combed_frame_map, RotationMap rotation_map,
                            Comb_result& result, const NamedParameters& np = CGAL::parameters::default_values())
{
  result = Comb_result();
  double min_angle = 0;
  const Error_code parameter_code = internal::read_minimum_frame_angle(np, min_angle);
  if(parameter_code != Error_code::SUCCESS)
    return parameter_code;
  const auto& bundle = internal::bundle_of(mesh_or_bundle, np);
  if(bundle.status() != Error_code::SUCCESS)
    return bundle.status();
  typedef std::decay_t<decltype(bundle)> Bundle;
  const auto& tm = bundle.mesh();
  internal::Corner_mesh<Bundle> M(bundle);
  internal::Comb_data D;
  const Error_code code = internal::comb_and_cut(M, coefficient_map, min_angle, D);
  result = D.report;
  if(code != Error_code::SUCCESS)
    return code;
  typedef typename boost::property_traits<CombedFrameMap>::value_type Frame_pair;
  typedef typename Frame_pair::value_type Vector_3;
  for(std::size_t f = 0; f < M.F; ++f)
  {
    const auto a = bundle.frame(f).to_world(D.roots[f][D.offset[f]]);
    const auto b = bundle.frame(f).to_world(D.roots[f][(D.offset[f] + 1) % 4]);
    put(combed_frame_map, bundle.face(f), Frame_pair{ { Vector_3(a[0], a[1], a[2]), Vector_3(b[0], b[1], b[2]) } });
  }
  for(auto e : edges(tm))
  {
    const auto h = CGAL::halfedge(e, tm);
    const bool border = CGAL::is_border_edge(h, tm);
    bool cut = border;
    if(!border)
    {
      const std::size_t c = M.corner_index(h);
      cut = D.seam[c] != 0;
      put(rotation_map, h, cut ? D.rotation[c] : 0);
      put(rotation_map, CGAL::opposite(h, tm), cut ? D.rotation[M.opposite[c]] : 0);
    }
    put(cut_edge_map, e, cut);
  }
  return Error_code::SUCCESS;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_COMB_FRAME_FIELD_H
