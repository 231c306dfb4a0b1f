// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Fuzz target `planarize`: planarize_quad_mesh() on tiny random quad meshes
// (1 to 9 quads: grids, a cube, open cylinders, saddles, with random vertex
// displacements), against the unperturbed surface (triangulated, itself
// displaced a little), with random parameters, some of them out of range.
//
// Input (missing bytes count as 0):
//   byte 0: bits 0-1 the quad mesh: 0 a flat (1 + b1 % 3) x (1 + b2 % 3)
//           grid, 1 a cube of 6 quads, 2 an open cylinder of 3 + b1 % 3 x
//           1 + b2 % 2 quads, 3 the (1 + b1 % 3) x (1 + b1 / 4 % 3) grid on the
//           saddle z = (b2 - 128) / 64 x y;
//           bit 2: max_distance_to_surface given;
//   bytes 1, 2: the mesh's sizes;
//   byte 3: the displacement of the quad mesh's vertices, up to b / 255 of an edge;
//   byte 4: the displacement of the reference's vertices, up to b / 2550 of an edge;
//   byte 5: planarity_threshold 10^(-(b % 64) / 8);
//   byte 6: closeness_weight 10^((b % 64) / 8 - 4);
//   byte 7: fairness_weight 10^((b % 64) / 8 - 5), 0 when b >= 192;
//   byte 8: closeness_decay (b + 1) / 256;
//   byte 9: max_distance_to_surface, 10^((b % 64) / 16 - 3) edges;
//   byte 10: number_of_iterations 1 + b % 8;
//   byte 11: a bad input, by b % 24: 16 threshold 0, 17 a NaN closeness
//            weight, 18 fairness weight -1, 19 decay 1.5, 20 a NaN vertex,
//            21 a triangle in the quad mesh (none when the first quad,
//            displaced, cannot be split), 22 a quad in the reference,
//            23 an empty reference; otherwise none;
//   then 3 bytes per vertex of the quad mesh, then of the reference.
// Checked: the code is the documented one for a bad input, and one of the
// documented codes otherwise; on failure the points of the quad mesh are
// unchanged (bit for bit); on SUCCESS result.converged, every quad at most
// planarity_threshold (quad_planarity() of its points), no quad folded that
// the input did not fold (and FOLDED_QUAD only with a count), every vertex finite
// and at most result.distance_bound from the reference (the parameter when
// given), at most number_of_iterations iterations, and none when the input
// was already planar enough (points unchanged).

#include "fuzz_support.h"

#include <CGAL/Polyvector_fields/planarize_quad_mesh.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

namespace pvf_fuzz_planarize {

using namespace pvf_fuzz;

// a number in a failed check's message, to its last digit
std::string number(double x)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

inline Mesh quad_grid(std::size_t rows, std::size_t cols, double saddle)
{
  Mesh qm;
  std::vector<Vertex> v;
  for(std::size_t i = 0; i <= rows; ++i)
    for(std::size_t j = 0; j <= cols; ++j)
    {
      const double x = double(j) - double(cols) / 2, y = double(i) - double(rows) / 2;
      v.push_back(qm.add_vertex(Point(x, y, saddle * x * y)));
    }
  for(std::size_t i = 0; i < rows; ++i)
    for(std::size_t j = 0; j < cols; ++j)
    {
      const std::size_t p = i * (cols + 1) + j;
      qm.add_face(v[p], v[p + 1], v[p + cols + 2], v[p + cols + 1]);
    }
  return qm;
}

inline Mesh quad_mesh(std::uint8_t kind, std::uint8_t a, std::uint8_t b)
{
  switch(kind % 4)
  {
    case 0: return quad_grid(1 + a % 3, 1 + b % 3, 0);
    case 1:
    {
      Mesh qm;
      CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(0, 1, 1), Point(0, 0, 1),
                            Point(1, 0, 1), Point(1, 1, 1), qm);
      return qm;
    }
    case 2:
    {
      const std::size_t n = 3 + a % 3, rows = 1 + b % 2;
      Mesh qm;
      std::vector<Vertex> v;
      for(std::size_t i = 0; i <= rows; ++i)
        for(std::size_t k = 0; k < n; ++k)
          v.push_back(qm.add_vertex(Point(std::cos(2 * CGAL_PI * double(k) / double(n)),
                                          std::sin(2 * CGAL_PI * double(k) / double(n)), double(i))));
      for(std::size_t i = 0; i < rows; ++i)
        for(std::size_t k = 0; k < n; ++k)
        {
          const std::size_t p = i * n + k, q = i * n + (k + 1) % n;
          qm.add_face(v[p], v[q], v[q + n], v[p + n]);
        }
      return qm;
    }
    default: return quad_grid(1 + a % 3, 1 + a / 4 % 3, (double(b) - 128) / 64);
  }
}

inline std::vector<Point> points_of(const Mesh& m)
{
  std::vector<Point> p;
  for(auto v : vertices(m))
    p.push_back(m.point(v));
  return p;
}

inline bool same_points(const std::vector<Point>& a, const std::vector<Point>& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
  {
    const double x[3] = { a[i].x(), a[i].y(), a[i].z() }, y[3] = { b[i].x(), b[i].y(), b[i].z() };
    if(std::memcmp(x, y, sizeof x) != 0)
      return false;
  }
  return true;
}

inline double face_planarity(Face f, const Mesh& m)
{
  std::vector<std::array<double, 3> > p;
  for(auto v : CGAL::vertices_around_face(halfedge(f, m), m))
    p.push_back({ m.point(v).x(), m.point(v).y(), m.point(v).z() });
  return PVF::quad_planarity(p[0], p[1], p[2], p[3]);
}

// A quad folded at the points `at`: neither diagonal splits it into two
// triangles that face the side of its normal at the points `input` (the cross
// product of its diagonals), the definition of planarize_quad_mesh(),
// written again here with CGAL's vectors.
inline bool folded_face(Face f, const Mesh& m, const std::vector<Point>& input, const std::vector<Point>& at)
{
  std::vector<std::size_t> v;
  for(auto w : CGAL::vertices_around_face(halfedge(f, m), m))
    v.push_back(std::size_t(w));
  const Vector normal = CGAL::cross_product(input[v[2]] - input[v[0]], input[v[3]] - input[v[1]]);
  auto against = [&](int a, int b, int c) {
    return CGAL::cross_product(at[v[b]] - at[v[a]], at[v[c]] - at[v[a]]) * normal <= 0;
  };
  return (against(0, 1, 2) || against(0, 2, 3)) && (against(1, 2, 3) || against(1, 3, 0));
}

// The other side of the distance to the surface, by brute force: the largest
// distance from a sample (a vertex of the reference, or an input point) to the
// quads at the points `at`, each quad taken as the four triangles of its two
// diagonals (the definition of planarize_quad_mesh()).
inline double surface_to_quads(const Mesh& reference, const Mesh& m, const std::vector<Point>& input,
                               const std::vector<Point>& at)
{
  std::vector<Kernel::Triangle_3> triangles;
  for(Face f : faces(m))
  {
    std::vector<std::size_t> v;
    for(auto w : CGAL::vertices_around_face(halfedge(f, m), m))
      v.push_back(std::size_t(w));
    for(std::size_t k = 0; k < 4; ++k)
      triangles.emplace_back(at[v[k]], at[v[(k + 1) % 4]], at[v[(k + 2) % 4]]);
  }
  std::vector<Point> samples = input;
  for(auto v : vertices(reference))
    samples.push_back(reference.point(v));
  double largest = 0;
  for(const Point& p : samples)
  {
    double d2 = std::numeric_limits<double>::infinity();
    for(const auto& t : triangles)
      d2 = (std::min)(d2, CGAL::to_double(CGAL::squared_distance(p, t)));
    largest = (std::max)(largest, std::sqrt(d2));
  }
  return largest;
}

inline void displace(Mesh& m, Byte_reader& in, double scale)
{
  for(auto v : vertices(m))
  {
    double d[3];
    for(double& x : d)
      x = (double(in.get()) - 127.5) / 127.5 * scale;
    m.point(v) = m.point(v) + Vector(d[0], d[1], d[2]);
  }
}

PVF_FUZZ_TARGET(planarize)
{
  Byte_reader in{ data, size };
  const std::uint8_t kind = in.get(), a = in.get(), b = in.get(), jitter = in.get(), reference_jitter = in.get(),
                     threshold_byte = in.get(), closeness_byte = in.get(), fairness_byte = in.get(),
                     decay_byte = in.get(), distance_byte = in.get(), iterations_byte = in.get(), bad_byte = in.get();
  Mesh qm = quad_mesh(kind, a, b);
  const double edge = mean_edge(qm);
  Mesh reference = qm;
  CGAL::Polygon_mesh_processing::triangulate_faces(reference);
  displace(qm, in, double(jitter) / 255 * edge);
  displace(reference, in, double(reference_jitter) / 2550 * edge);

  double threshold = std::pow(10.0, -double(threshold_byte % 64) / 8);
  double closeness = std::pow(10.0, double(closeness_byte % 64) / 8 - 4);
  double fairness = fairness_byte >= 192 ? 0.0 : std::pow(10.0, double(fairness_byte % 64) / 8 - 5);
  double decay = (double(decay_byte) + 1) / 256;
  const bool distance_given = (kind & 4) != 0;
  const double max_distance = std::pow(10.0, double(distance_byte % 64) / 16 - 3) * edge;
  const std::size_t iterations = 1 + iterations_byte % 8;
  const int bad = bad_byte % 24;
  Error_code expected = Error_code::SUCCESS;
  switch(bad)
  {
    case 16: threshold = 0; expected = Error_code::INVALID_PARAMETER; break;
    case 17: closeness = std::numeric_limits<double>::quiet_NaN(); expected = Error_code::NON_FINITE_VALUE; break;
    case 18: fairness = -1; expected = Error_code::INVALID_PARAMETER; break;
    case 19: decay = 1.5; expected = Error_code::INVALID_PARAMETER; break;
    case 20:
      qm.point(*vertices(qm).begin()) = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
      expected = Error_code::NON_FINITE_VALUE;
      break;
    case 21:
      // a quad that the displacement made degenerate may not split: then
      // the input has no triangle, and is not a bad input
      if(CGAL::Polygon_mesh_processing::triangulate_face(*faces(qm).begin(), qm))
        expected = Error_code::NON_QUAD_FACE;
      break;
    case 22:
      reference = qm;
      expected = Error_code::NON_TRIANGLE_FACE;
      break;
    case 23:
      reference.clear();
      expected = Error_code::EMPTY_MESH;
      break;
    default: break;
  }
  const std::vector<Point> before = points_of(qm);
  double planarity_before = 0;
  if(expected == Error_code::SUCCESS)
    for(Face f : faces(qm))
      planarity_before = (std::max)(planarity_before, face_planarity(f, qm));

  PVF::Planarization_result result;
  const auto np = PVF::parameters::planarity_threshold(
    threshold, PVF::parameters::closeness_weight(
                 closeness, PVF::parameters::fairness_weight(
                              fairness, PVF::parameters::closeness_decay(
                                          decay, CGAL::parameters::number_of_iterations(iterations)))));
  const Error_code code = distance_given
                            ? PVF::planarize_quad_mesh(qm, reference, result, PVF::parameters::max_distance_to_surface(max_distance, np))
                            : PVF::planarize_quad_mesh(qm, reference, result, np);
  if(expected != Error_code::SUCCESS)
    PVF_FUZZ_CHECK(code == expected, "bad input " + std::to_string(bad) + ": " + code_name(code) + " instead of " +
                                       code_name(expected));
  else
    PVF_FUZZ_CHECK(code == Error_code::SUCCESS || code == Error_code::DID_NOT_CONVERGE ||
                     code == Error_code::TOO_FAR_FROM_SURFACE || code == Error_code::FOLDED_QUAD ||
                     code == Error_code::SOLVER_FAILURE,
                   "undocumented code " + code_name(code));
  PVF_FUZZ_CHECK(!result.left_surface || code == Error_code::TOO_FAR_FROM_SURFACE ||
                   (code == Error_code::SUCCESS && result.gauss_newton_ran),
                 "left_surface with " + code_name(code));
  PVF_FUZZ_CHECK(result.gauss_newton_steps <= 50, std::to_string(result.gauss_newton_steps) + " Gauss-Newton steps");
  // a stop for want of progress takes four kept steps (one sets the marks) and is a failure
  PVF_FUZZ_CHECK(!result.gauss_newton_stalled ||
                   (result.gauss_newton_ran && result.gauss_newton_steps >= 4 && code != Error_code::SUCCESS),
                 "stalled after " + std::to_string(result.gauss_newton_steps) + " Gauss-Newton steps with " +
                   code_name(code));
  // too far: a vertex from the surface, or the surface from the quads
  if(code == Error_code::TOO_FAR_FROM_SURFACE)
    PVF_FUZZ_CHECK(!(result.max_distance <= result.distance_bound) ||
                     !(result.max_distance_to_quads <= result.max_distance_to_quads_before + result.distance_bound),
                   "TOO_FAR_FROM_SURFACE within distance_bound on both sides");
  if(code == Error_code::FOLDED_QUAD)
    PVF_FUZZ_CHECK(result.folded_quads > 0, "FOLDED_QUAD without a folded quad");
  if(code != Error_code::SUCCESS)
  {
    PVF_FUZZ_CHECK(same_points(before, points_of(qm)), "a failed planarization moved the points: " + code_name(code));
    return;
  }
  PVF_FUZZ_CHECK(result.converged, "SUCCESS without convergence");
  PVF_FUZZ_CHECK(result.iterations <= iterations, std::to_string(result.iterations) + " iterations");
  PVF_FUZZ_CHECK(result.max_planarity_after <= threshold, "max_planarity_after above the threshold");
  if(distance_given)
    PVF_FUZZ_CHECK(result.distance_bound == max_distance, "distance_bound is not max_distance_to_surface");
  PVF_FUZZ_CHECK(result.max_distance <= result.distance_bound, "max_distance above distance_bound");
  if(planarity_before <= threshold * (1 - 1e-9))
  {
    // no local-global iteration; the points move only when the input was
    // farther than the bound from the (displaced) reference and the
    // Gauss-Newton steps brought it within
    PVF_FUZZ_CHECK(result.iterations == 0, "iterations on a planar enough input");
    PVF_FUZZ_CHECK(same_points(before, points_of(qm)) || result.gauss_newton_ran, "a planar enough input was moved");
    PVF_FUZZ_CHECK(!result.gauss_newton_ran || !(result.max_distance_before <= result.distance_bound),
                   "Gauss-Newton steps on a planar enough input within the bound");
  }
  for(Face f : faces(qm))
  {
    const double planarity = face_planarity(f, qm);
    PVF_FUZZ_CHECK(planarity <= threshold * (1 + 1e-6) + 1e-12,
                   "a face of planarity " + number(planarity) + " above " + number(threshold) +
                     " (result.max_planarity_after " + number(result.max_planarity_after) + ", Gauss-Newton " +
                     (result.gauss_newton_ran ? "ran" : "did not run") + ")");
  }
  const std::vector<Point> after = points_of(qm);
  const double covered_before = surface_to_quads(reference, qm, before, before);
  const double covered_after = surface_to_quads(reference, qm, before, after);
  PVF_FUZZ_CHECK(covered_after <= covered_before + result.distance_bound * (1 + 1e-9) + 1e-9 * edge,
                 "the surface " + number(covered_after) + " from the quads, " + number(covered_before) +
                   " before, bound " + number(result.distance_bound));
  PVF_FUZZ_CHECK(std::abs(result.max_distance_to_quads - covered_after) <= 1e-9 * edge &&
                   std::abs(result.max_distance_to_quads_before - covered_before) <= 1e-9 * edge,
                 "max_distance_to_quads " + number(result.max_distance_to_quads) + " (before " +
                   number(result.max_distance_to_quads_before) + "), measured " + number(covered_after) + " (" +
                   number(covered_before) + ")");
  for(Face f : faces(qm))
    PVF_FUZZ_CHECK(folded_face(f, qm, before, before) || !folded_face(f, qm, before, after),
                   "a quad folded by a successful planarization");
  PVF_FUZZ_CHECK(result.folded_quads == 0, "SUCCESS with folded_quads");
  for(auto v : vertices(qm))
  {
    const Point& p = qm.point(v);
    PVF_FUZZ_CHECK(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()), "a non-finite point");
    const double d = distance_to_surface(p, reference);
    PVF_FUZZ_CHECK(d <= result.distance_bound * (1 + 1e-9) + 1e-12 * edge,
                   "a vertex " + std::to_string(d) + " from the reference, bound " +
                     std::to_string(result.distance_bound));
  }
}

} // namespace pvf_fuzz_planarize
