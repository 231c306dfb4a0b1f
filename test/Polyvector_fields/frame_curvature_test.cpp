// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Principal curvature estimation (estimate_principal_curvatures.h) and
// curvature-based constraint selection (select_curvature_constraints.h).
//
// The meshes are sampled from analytic surfaces on parameter grids; each face
// is compared with the analytic curvatures at its barycentre projected onto the
// surface.

// The mesh types come first: the package's generic code calls CGAL's
// BGL free functions, which these headers declare.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "test_meshes.h"

#include <CGAL/Polyvector_fields/Principal_curvatures.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/select_curvature_constraints.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#ifndef PVF_DATA_DIR
#error "PVF_DATA_DIR (the folder of the bundled meshes) must be given by the build (CMake's pvf_link_package)"
#endif

// The names of this file stay in its own namespace: the group is built as one
// translation unit (unity build).
namespace pvf_frame_curvature_test {

namespace {

namespace PVF = CGAL::Polyvector_fields;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef PVF::Principal_curvatures<Vector> Curvatures;
typedef std::array<double, 3> Vec3;

using pvf_test::pi;

// ---------------------------------------------------------------- meshes

typedef pvf_test::Soup<Point> Soup;
using pvf_test::make_mesh;

Soup sphere(double R, int nu, int nv) { return pvf_test::sphere_soup<Point>(R, nu, nv); }
Soup cylinder(double R, double H, int nu, int nz) { return pvf_test::cylinder_soup<Point>(R, H, nu, nz); }
Soup torus(double R, double r, int nu, int nv) { return pvf_test::torus_soup<Point>(R, r, nu, nv); }

// A flat strip two vertices wide and n quads long, in the plane z = 0.
Soup flat_strip(int n)
{
  Soup strip;
  for(int i = 0; i <= n; ++i)
  {
    strip.points.push_back(Point(0.01 * i, 0, 0));
    strip.points.push_back(Point(0.01 * i, 0.01, 0));
  }
  for(int i = 0; i < n; ++i)
    strip.add_quad(2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1);
  return strip;
}

// Flat disk of radius 1 in the plane z = 0, on a polar grid: a centre and
// n_rings rings of n_theta points.
Soup flat_disk(int n_rings, int n_theta)
{
  Soup s;
  s.points.push_back(Point(0, 0, 0));
  for(int j = 1; j <= n_rings; ++j)
    for(int i = 0; i < n_theta; ++i)
    {
      const double rho = double(j) / n_rings, phi = 2 * pi * i / n_theta;
      s.points.push_back(Point(rho * std::cos(phi), rho * std::sin(phi), 0));
    }
  auto id = [n_theta](int i, int j) { return std::size_t(1 + (j - 1) * n_theta + (i % n_theta)); };
  for(int i = 0; i < n_theta; ++i)
    s.faces.push_back({ 0, id(i, 1), id(i + 1, 1) });
  for(int j = 1; j < n_rings; ++j)
    for(int i = 0; i < n_theta; ++i)
      s.add_quad(id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j));
  return s;
}

// Flat square [0,1]^2 triangulated on an n x n grid; its corners have one or two faces.
Soup flat_square(int n)
{
  Soup s;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      s.points.push_back(Point(double(i) / n, double(j) / n, 0));
  auto id = [n](int i, int j) { return std::size_t(j * (n + 1) + i); };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
      s.add_quad(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return s;
}

Soup tetrahedron()
{
  Soup s;
  s.points = { Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1) };
  s.faces = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 1 }, { 1, 3, 2 } };
  return s;
}

Soup octahedron()
{
  Soup s;
  s.points = { Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0), Point(0, -1, 0), Point(0, 0, 1), Point(0, 0, -1) };
  s.faces = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } };
  return s;
}

// Reverses the orientation of every face (the normals then point inwards).
Soup reversed(Soup s)
{
  for(auto& f : s.faces)
    std::reverse(f.begin(), f.end());
  return s;
}

// Splits face `fi` 1-to-3 at a new vertex `p`: the new vertex has valence 3.
Soup split_face(Soup s, std::size_t fi, const Point& p)
{
  const std::vector<std::size_t> f = s.faces[fi];
  const std::size_t c = s.points.size();
  s.points.push_back(p);
  s.faces[fi] = { f[0], f[1], c };
  s.faces.push_back({ f[1], f[2], c });
  s.faces.push_back({ f[2], f[0], c });
  return s;
}

// ---------------------------------------------------------------- helpers

Vec3 to_vec(const Vector& v) { return { v.x(), v.y(), v.z() }; }
Vec3 to_vec(const Point& p) { return { p.x(), p.y(), p.z() }; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

template <typename TriangleMesh>
Vec3 barycentre(typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& tm)
{
  Vec3 b = { 0, 0, 0 };
  for(auto v : CGAL::vertices_around_face(CGAL::halfedge(f, tm), tm))
  {
    const Vec3 p = to_vec(get(CGAL::vertex_point, tm, v));
    for(int c = 0; c < 3; ++c)
      b[c] += p[c] / 3.;
  }
  return b;
}

// Analytic principal curvatures at the projection of a point onto a surface,
// with the convention of Principal_curvatures for outward normals.
struct Truth
{
  double k1, k2;
  Vec3 d1;          // unit direction of k1
  bool anisotropic; // d1 is defined
};

typedef std::function<Truth(const Vec3&)> Truth_function;

Truth_function sphere_truth(double R)
{
  return [R](const Vec3&) { return Truth{ 1. / R, 1. / R, { 1, 0, 0 }, false }; };
}

Truth_function cylinder_truth(double R)
{
  return [R](const Vec3& p) {
    const double phi = std::atan2(p[1], p[0]);
    return Truth{ 1. / R, 0., { -std::sin(phi), std::cos(phi), 0. }, true };
  };
}

// k1 = 1/r along the meridians (the tube circles), k2 = cos v / (R + r cos v) along the parallels.
Truth_function torus_truth(double R, double r)
{
  return [R, r](const Vec3& p) {
    const double u = std::atan2(p[1], p[0]);
    const double v = std::atan2(p[2], std::hypot(p[0], p[1]) - R);
    return Truth{ 1. / r, std::cos(v) / (R + r * std::cos(v)),
                  { -std::sin(v) * std::cos(u), -std::sin(v) * std::sin(u), std::cos(v) }, true };
  };
}

struct Errors
{
  double max_k = 0, mean_k = 0;      // max(|k1 - k1*|, |k2 - k2*|) / k_scale
  double max_dir = 0, mean_dir = 0;  // angle between d1 and the analytic d1 (projected on the face), radians
};

template <typename TriangleMesh, typename CurvatureMap>
Errors measure(const TriangleMesh& tm, const CurvatureMap& map, const Truth_function& truth, double k_scale)
{
  Errors e;
  std::size_t n = 0, n_dir = 0;
  for(auto f : CGAL::faces(tm))
  {
    const Truth t = truth(barycentre(f, tm));
    const Curvatures& c = get(map, f);
    const double ek = (std::max)(std::abs(c.k1 - t.k1), std::abs(c.k2 - t.k2)) / k_scale;
    e.max_k = (std::max)(e.max_k, ek);
    e.mean_k += ek;
    ++n;
    if(t.anisotropic)
    {
      PVF::Face_frame frame;
      PVF::face_frame(f, tm, frame);
      Vec3 d = t.d1;
      const double dn = dot(d, frame.normal);
      for(int i = 0; i < 3; ++i)
        d[i] -= dn * frame.normal[i];
      const double cosine = (std::min)(1., std::abs(dot(to_vec(c.d1), d)) / norm(d));
      const double angle = std::acos(cosine);
      e.max_dir = (std::max)(e.max_dir, angle);
      e.mean_dir += angle;
      ++n_dir;
    }
  }
  e.mean_k /= double(n);
  if(n_dir > 0)
    e.mean_dir /= double(n_dir);
  return e;
}

// Estimates on a Surface_mesh, expecting success; returns the errors.
template <typename NamedParameters>
Errors estimate_and_measure(const Soup& soup, const Truth_function& truth, double k_scale, const NamedParameters& np,
                            const char* label)
{
  const Mesh tm = make_mesh<Mesh>(soup);
  auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
  const PVF::Error_code code = PVF::estimate_principal_curvatures(tm, map, np);
  EXPECT_EQ(code, PVF::Error_code::SUCCESS) << label;
  if(code != PVF::Error_code::SUCCESS)
    return Errors{ 1e9, 1e9, 1e9, 1e9 };
  const Errors e = measure(tm, map, truth, k_scale);
  std::printf("  %-28s F=%6zu  k: max %.2e mean %.2e   d1: max %.2e mean %.2e rad\n", label, std::size_t(num_faces(tm)),
              e.max_k, e.mean_k, e.max_dir, e.mean_dir);
  return e;
}

// Checks the invariants of every value: finite, k1 >= k2, unit orthogonal
// directions in the face plane, (d1, d2, n) direct, d1 . e1 >= 0.
template <typename TriangleMesh, typename CurvatureMap>
void expect_well_formed(const TriangleMesh& tm, const CurvatureMap& map)
{
  for(auto f : CGAL::faces(tm))
  {
    const Curvatures& c = get(map, f);
    PVF::Face_frame frame;
    ASSERT_EQ(PVF::face_frame(f, tm, frame), PVF::Error_code::SUCCESS);
    const Vec3 d1 = to_vec(c.d1), d2 = to_vec(c.d2);
    ASSERT_TRUE(std::isfinite(c.k1) && std::isfinite(c.k2));
    EXPECT_GE(c.k1, c.k2);
    EXPECT_NEAR(norm(d1), 1., 1e-12);
    EXPECT_NEAR(norm(d2), 1., 1e-12);
    EXPECT_NEAR(dot(d1, d2), 0., 1e-12);
    EXPECT_NEAR(dot(d1, frame.normal), 0., 1e-12);
    EXPECT_NEAR(dot(d2, frame.normal), 0., 1e-12);
    EXPECT_NEAR(dot(cross(d1, d2), frame.normal), 1., 1e-12);
    EXPECT_GE(dot(d1, frame.e1), -1e-15);
  }
}

// A map that records every write, to check that a failing call writes nothing.
typedef std::map<Mesh::Face_index, Curvatures> Recording_store;

template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
PVF::Error_code estimate_into_store(const Mesh& tm, Recording_store& store,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  return PVF::estimate_principal_curvatures(tm, boost::make_assoc_property_map(store), np);
}

} // namespace

// ================================================================ estimation

TEST(CurvatureEstimation, SignConventionOnSphere)
{
  const double R = 2.;
  for(bool outward : { true, false })
  {
    const Soup soup = outward ? sphere(R, 32, 16) : reversed(sphere(R, 32, 16));
    const Mesh tm = make_mesh<Mesh>(soup);
    auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
    ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map), PVF::Error_code::SUCCESS);
    expect_well_formed(tm, map);
    const double expected = outward ? 1. / R : -1. / R;
    for(auto f : faces(tm))
    {
      // Face normal and outward direction agree (or not) as built.
      PVF::Face_frame frame;
      PVF::face_frame(f, tm, frame);
      const Vec3 b = barycentre(f, tm);
      EXPECT_EQ(dot(frame.normal, b) > 0, outward);
      EXPECT_NEAR(get(map, f).k1, expected, 0.05 / R);
      EXPECT_NEAR(get(map, f).k2, expected, 0.05 / R);
    }
  }
}

TEST(CurvatureEstimation, ShapeOperatorInFaceFrame)
{
  const Mesh tm = make_mesh<Mesh>(torus(3., 1., 48, 16));
  auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
  ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map), PVF::Error_code::SUCCESS);
  for(auto f : faces(tm))
  {
    PVF::Face_frame frame;
    PVF::face_frame(f, tm, frame);
    const Curvatures& c = get(map, f);
    const std::array<double, 4> S = PVF::shape_operator(c, frame);
    EXPECT_DOUBLE_EQ(S[1], S[2]);
    const std::complex<double> u = frame.to_complex(c.d1.x(), c.d1.y(), c.d1.z());
    const std::complex<double> v = frame.to_complex(c.d2.x(), c.d2.y(), c.d2.z());
    auto form = [&S](const std::complex<double>& a, const std::complex<double>& b) {
      return a.real() * (S[0] * b.real() + S[1] * b.imag()) + a.imag() * (S[2] * b.real() + S[3] * b.imag());
    };
    const double scale = std::abs(c.k1) + std::abs(c.k2);
    EXPECT_NEAR(form(u, u), c.k1, 1e-12 * scale);
    EXPECT_NEAR(form(v, v), c.k2, 1e-12 * scale);
    EXPECT_NEAR(form(u, v), 0., 1e-12 * scale);  // principal directions are conjugate
    EXPECT_NEAR(S[0] + S[3], c.k1 + c.k2, 1e-12 * scale);
    EXPECT_NEAR(S[0] * S[3] - S[1] * S[2], c.k1 * c.k2, 1e-12 * scale * scale);
  }
}

// Errors against the analytic curvatures, at two resolutions (the fine mesh
// halves the edge lengths), degrees 2 and 4: the convergence order. A fit of
// degree 2 is second order on these regular meshes (the error falls by 4 when
// h halves; at least 3.5 is asked), degree 4 at least third order (8). The
// fine meshes must also be within 5% of the largest curvature, and degree 4
// must beat degree 2 there.
TEST(CurvatureEstimation, ConvergenceOnAnalyticSurfaces)
{
  struct Case
  {
    const char* name;
    std::function<Soup(int)> soup;  // resolution 1 (coarse) or 2 (fine)
    Truth_function truth;
    double k_scale;
    bool directions;  // the directions are defined (not an umbilic sphere)
  };
  const std::vector<Case> cases = {
    { "sphere R=2", [](int res) { return sphere(2., 32 * res, 16 * res); }, sphere_truth(2.), 0.5, false },
    { "open cylinder R=1 H=3", [](int res) { return cylinder(1., 3., 32 * res, 16 * res); }, cylinder_truth(1.), 1., true },
    { "torus R=3 r=1", [](int res) { return torus(3., 1., 48 * res, 16 * res); }, torus_truth(3., 1.), 1., true },
  };
  for(const Case& c : cases)
  {
    std::printf("%s\n", c.name);
    for(int degree : { 2, 4 })
    {
      Errors e[2];
      for(int res : { 1, 2 })
      {
        const std::string label = std::string("degree ") + std::to_string(degree) + (res == 1 ? " coarse" : " fine");
        e[res - 1] = estimate_and_measure(c.soup(res), c.truth, c.k_scale,
                                          CGAL::parameters::degree_fitting(degree).degree_monge(2), label.c_str());
      }
      const double order_factor = degree == 2 ? 3.5 : 8.0;
      EXPECT_GT(e[0].max_k / e[1].max_k, order_factor) << c.name << ", degree " << degree;
      EXPECT_GT(e[0].mean_k / e[1].mean_k, order_factor) << c.name << ", degree " << degree;
      EXPECT_LT(e[1].max_k, 0.05) << c.name << ", degree " << degree;
      if(c.directions)
      {
        EXPECT_GT(e[0].max_dir / e[1].max_dir, order_factor) << c.name << ", degree " << degree;
        EXPECT_GT(e[0].mean_dir / e[1].mean_dir, order_factor) << c.name << ", degree " << degree;
      }
    }
    const Errors fine2 = estimate_and_measure(c.soup(2), c.truth, c.k_scale,
                                              CGAL::parameters::degree_fitting(2).degree_monge(2), "degree 2 fine");
    const Errors fine4 = estimate_and_measure(c.soup(2), c.truth, c.k_scale,
                                              CGAL::parameters::degree_fitting(4).degree_monge(2), "degree 4 fine");
    EXPECT_LT(fine4.mean_k, fine2.mean_k / 3.) << c.name;
    EXPECT_LT(fine4.max_k, fine2.max_k) << c.name;
  }
}

TEST(CurvatureEstimation, FlatMeshesWithBoundary)
{
  for(const Soup& soup : { flat_disk(8, 24), flat_square(10) })
  {
    const Mesh tm = make_mesh<Mesh>(soup);
    for(int degree : { 2, 4 })
    {
      auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
      ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map, CGAL::parameters::degree_fitting(degree)),
                PVF::Error_code::SUCCESS)
        << "degree " << degree;
      expect_well_formed(tm, map);
      for(auto f : faces(tm))
      {
        EXPECT_NEAR(get(map, f).k1, 0., 1e-9);
        EXPECT_NEAR(get(map, f).k2, 0., 1e-9);
      }
    }
  }
}

// Issue 21: on a plane in general position (tilted, irregular points), the fit
// returns round-off, with directions that mean nothing; the estimate says
// exactly 0, and no face of the plane is constrained to curvature directions.
TEST(CurvatureEstimation, TiltedPlaneIsExactlyFlat)
{
  Soup soup = flat_square(12);
  const Vec3 e1 = { 0.6, 0.0, -0.8 }, e2 = { 0.48, 0.6, 0.36 };  // orthonormal, tilted
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for(Point& p : soup.points)
  {
    const double x = p.x() + jitter(rng), y = p.y() + jitter(rng);
    p = Point(3 + x * e1[0] + y * e2[0], -1 + x * e1[1] + y * e2[1], 7 + x * e1[2] + y * e2[2]);
  }
  const Mesh tm = make_mesh<Mesh>(soup);
  auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
  ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map), PVF::Error_code::SUCCESS);
  for(auto f : faces(tm))
  {
    EXPECT_EQ(get(map, f).k1, 0.);
    EXPECT_EQ(get(map, f).k2, 0.);
  }
  std::vector<PVF::Face_constraint<Mesh::Face_index, Vector> > none(1);
  EXPECT_EQ(PVF::select_curvature_constraints(tm, map, none), PVF::Error_code::SUCCESS);
  EXPECT_TRUE(none.empty());
}

TEST(CurvatureEstimation, BoundaryOfOpenCylinder)
{
  // Boundary faces are estimated too, with a one-sided neighbourhood: bounded
  // error, but larger than in the interior.
  const Mesh tm = make_mesh<Mesh>(cylinder(1., 1., 32, 8));
  auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
  for(int degree : { 2, 4 })
  {
    ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map, CGAL::parameters::degree_fitting(degree)),
              PVF::Error_code::SUCCESS);
    expect_well_formed(tm, map);
    const Errors e = measure(tm, map, cylinder_truth(1.), 1.);
    EXPECT_LT(e.max_k, degree == 2 ? 0.06 : 0.25) << degree;
    EXPECT_LT(e.max_dir, 0.05) << degree;
  }
}

TEST(CurvatureEstimation, LowValenceVertices)
{
  // Tetrahedron (4 vertices cannot determine a quadric of 6 coefficients) and
  // regular octahedron (6 vertices whose covariance is isotropic, so that two
  // opposite vertices project onto one position of the fitting plane): no fit
  // is possible, and every vertex falls back to the normal-variation estimate.
  // By symmetry each face is umbilic, and since the vertex normals are radial
  // (n = p / R) the curvature is positive and at most 1/R (the face tensors
  // are exactly I/R; the average in the vertex's tangent plane shrinks them).
  for(int shape = 0; shape < 2; ++shape)
    for(int degree : { 2, 4 })
    {
      const Soup soup = shape == 0 ? tetrahedron() : octahedron();
      const double R = shape == 0 ? std::sqrt(3.) : 1.;
      const Mesh tm = make_mesh<Mesh>(soup);
      auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
      std::size_t fallbacks = 0;
      ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map, PVF::parameters::fallback_vertices(fallbacks, CGAL::parameters::degree_fitting(degree))),
                PVF::Error_code::SUCCESS);
      EXPECT_EQ(fallbacks, soup.points.size());
      expect_well_formed(tm, map);
      for(auto f : faces(tm))
      {
        EXPECT_NEAR(get(map, f).k1, get(map, f).k2, 1e-12 / R) << shape;
        EXPECT_GT(get(map, f).k2, 0.) << shape;
        EXPECT_LE(get(map, f).k1, 1. / R + 1e-12) << shape;
      }
    }
  // A sphere with one face split 1-to-3: the new vertex has valence 3; its
  // 1-ring (4 points) is too small and grows to the 2-ring.
  {
    const double R = 1.;
    Soup soup = sphere(R, 24, 12);
    const std::size_t fi = soup.faces.size() / 2;
    Vec3 c = { 0, 0, 0 };
    for(std::size_t vi : soup.faces[fi])
      for(int k = 0; k < 3; ++k)
        c[k] += to_vec(soup.points[vi])[k] / 3.;
    const double l = norm(c);
    soup = split_face(soup, fi, Point(R * c[0] / l, R * c[1] / l, R * c[2] / l));
    const Mesh tm = make_mesh<Mesh>(soup);
    const Mesh::Vertex_index centre(static_cast<Mesh::size_type>(soup.points.size() - 1));
    ASSERT_EQ(tm.degree(centre), 3u);
    for(int degree : { 2, 4 })
    {
      auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
      ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map, CGAL::parameters::degree_fitting(degree)),
                PVF::Error_code::SUCCESS);
      expect_well_formed(tm, map);
      for(auto f : faces_around_target(halfedge(centre, tm), tm))
      {
        EXPECT_NEAR(get(map, f).k1, 1. / R, 0.15 / R) << degree;
        EXPECT_NEAR(get(map, f).k2, 1. / R, 0.15 / R) << degree;
      }
    }
  }
}

// Meshes where no vertex, or only some, can be fitted: the whole mesh still
// gets curvatures, flat parts get exactly zero, and the fitted part is the same
// as on its own.
TEST(CurvatureEstimation, FallbackOnUnfittableParts)
{
  // One flat triangle: three vertices with one normal, hence zero curvature.
  {
    Soup one;
    one.points = { Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0) };
    one.faces = { { 0, 1, 2 } };
    const Mesh tm = make_mesh<Mesh>(one);
    auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
    std::size_t fallbacks = 0;
    ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map, PVF::parameters::fallback_vertices(fallbacks)),
              PVF::Error_code::SUCCESS);
    EXPECT_EQ(fallbacks, 3u);
    for(auto f : faces(tm))
    {
      EXPECT_EQ(get(map, f).k1, 0.);
      EXPECT_EQ(get(map, f).k2, 0.);
    }
  }
  // A long flat strip two vertices wide: its points lie on two lines, which
  // never determine a quadric however far the ring grows (the growth stops
  // three rings after the target); every vertex falls back, with curvature 0.
  {
    const Soup strip = flat_strip(2000);
    const Mesh tm = make_mesh<Mesh>(strip);
    auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
    std::size_t fallbacks = 0;
    ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map, PVF::parameters::fallback_vertices(fallbacks)),
              PVF::Error_code::SUCCESS);
    EXPECT_EQ(fallbacks, strip.points.size());
    for(auto f : faces(tm))
      ASSERT_TRUE(get(map, f).k1 == 0. && get(map, f).k2 == 0.);
  }
  // A sphere plus a separate triangle: the triangle falls back to zero, the
  // sphere keeps its fitted curvatures, equal to those of the sphere alone.
  {
    const Soup alone = sphere(1., 16, 8);
    Soup soup = alone;
    const std::size_t n = soup.points.size();
    soup.points.push_back(Point(5, 0, 0));
    soup.points.push_back(Point(6, 0, 0));
    soup.points.push_back(Point(5, 1, 0));
    soup.faces.push_back({ n, n + 1, n + 2 });
    const Mesh tm = make_mesh<Mesh>(soup), tm_alone = make_mesh<Mesh>(alone);
    auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
    auto map_alone = get(CGAL::dynamic_face_property_t<Curvatures>(), tm_alone);
    std::size_t fallbacks = 0, fallbacks_alone = 0;
    ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map, PVF::parameters::fallback_vertices(fallbacks)),
              PVF::Error_code::SUCCESS);
    ASSERT_EQ(PVF::estimate_principal_curvatures(tm_alone, map_alone, PVF::parameters::fallback_vertices(fallbacks_alone)),
              PVF::Error_code::SUCCESS);
    EXPECT_EQ(fallbacks_alone, 0u);
    EXPECT_EQ(fallbacks, 3u);
    for(auto f : faces(tm_alone))
    {
      EXPECT_NEAR(get(map, f).k1, get(map_alone, f).k1, 1e-12);
      EXPECT_NEAR(get(map, f).k2, get(map_alone, f).k2, 1e-12);
    }
    const Mesh::Face_index last(static_cast<Mesh::size_type>(soup.faces.size() - 1));
    EXPECT_EQ(get(map, last).k1, 0.);
    EXPECT_EQ(get(map, last).k2, 0.);
  }
  // A failure (here a bad parameter) leaves a pre-filled map as it was.
  {
    const Mesh tm = make_mesh<Mesh>(sphere(1., 16, 8));
    auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
    Curvatures sentinel;
    sentinel.k1 = 42.;
    sentinel.k2 = -42.;
    sentinel.d1 = Vector(1, 2, 3);
    sentinel.d2 = Vector(4, 5, 6);
    for(auto f : faces(tm))
      put(map, f, sentinel);
    EXPECT_EQ(PVF::estimate_principal_curvatures(tm, map, CGAL::parameters::degree_fitting(1).degree_monge(1)),
              PVF::Error_code::INVALID_PARAMETER);
    for(auto f : faces(tm))
    {
      EXPECT_EQ(get(map, f).k1, 42.);
      EXPECT_EQ(get(map, f).d2, Vector(4, 5, 6));
    }
  }
}

TEST(CurvatureEstimation, InvalidInput)
{
  const Mesh tm = make_mesh<Mesh>(sphere(1., 16, 8));
  Recording_store store;
  using CGAL::parameters::degree_fitting;
  using CGAL::parameters::degree_monge;
  EXPECT_EQ(estimate_into_store(tm, store, degree_fitting(1).degree_monge(1)), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(estimate_into_store(tm, store, degree_fitting(2).degree_monge(1)), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(estimate_into_store(tm, store, degree_fitting(2).degree_monge(3)), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(estimate_into_store(tm, store, degree_fitting(5).degree_monge(5)), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(estimate_into_store(tm, store, degree_fitting(13)), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(estimate_into_store(tm, store, degree_fitting(-2)), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(estimate_into_store(tm, store, degree_fitting(std::size_t(-1))), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(estimate_into_store(tm, store, PVF::parameters::ring_size(0)), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(estimate_into_store(tm, store, PVF::parameters::ring_size(-1)), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_TRUE(store.empty());

  // Empty mesh, quad face, degenerate face, non-finite coordinate.
  Mesh empty;
  EXPECT_EQ(estimate_into_store(empty, store), PVF::Error_code::EMPTY_MESH);
  Soup quad = flat_square(3);
  quad.faces.pop_back();
  quad.faces.back() = { 10, 11, 15, 14 };  // the last quad, whole
  EXPECT_EQ(estimate_into_store(make_mesh<Mesh>(quad), store), PVF::Error_code::NON_TRIANGLE_FACE);
  Soup degenerate = sphere(1., 16, 8);
  degenerate.points[1] = degenerate.points[2];  // a zero-length edge
  EXPECT_EQ(estimate_into_store(make_mesh<Mesh>(degenerate), store), PVF::Error_code::DEGENERATE_FACE);
  Soup nan = sphere(1., 16, 8);
  nan.points[5] = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  EXPECT_EQ(estimate_into_store(make_mesh<Mesh>(nan), store), PVF::Error_code::DEGENERATE_FACE);
  EXPECT_TRUE(store.empty());

  // Accepted extremes.
  EXPECT_EQ(estimate_into_store(tm, store, degree_fitting(4).degree_monge(4)), PVF::Error_code::SUCCESS);
  EXPECT_EQ(estimate_into_store(tm, store, degree_fitting(std::size_t(3)).degree_monge(3)), PVF::Error_code::SUCCESS);
  EXPECT_EQ(store.size(), num_faces(tm));
}

TEST(CurvatureEstimation, SurfaceMeshAndPolyhedronAgree)
{
  const Soup soup = torus(3., 1., 36, 12);
  const Mesh sm = make_mesh<Mesh>(soup);
  const Polyhedron ph = make_mesh<Polyhedron>(soup);
  for(int degree : { 2, 4 })
  {
    auto sm_map = get(CGAL::dynamic_face_property_t<Curvatures>(), sm);
    auto ph_map = get(CGAL::dynamic_face_property_t<Curvatures>(), ph);
    const auto np = CGAL::parameters::degree_fitting(degree);
    ASSERT_EQ(PVF::estimate_principal_curvatures(sm, sm_map, np), PVF::Error_code::SUCCESS);
    ASSERT_EQ(PVF::estimate_principal_curvatures(ph, ph_map, np), PVF::Error_code::SUCCESS);
    expect_well_formed(ph, ph_map);
    auto fs = faces(sm).begin();
    auto fp = faces(ph).begin();
    ASSERT_EQ(num_faces(sm), num_faces(ph));
    for(; fs != faces(sm).end(); ++fs, ++fp)
    {
      // same face: same barycentre
      const Vec3 bs = barycentre(*fs, sm), bp = barycentre(*fp, ph);
      ASSERT_LT(norm({ bs[0] - bp[0], bs[1] - bp[1], bs[2] - bp[2] }), 1e-15);
      const Curvatures& a = get(sm_map, *fs);
      const Curvatures& b = get(ph_map, *fp);
      EXPECT_NEAR(a.k1, b.k1, 1e-12);
      EXPECT_NEAR(a.k2, b.k2, 1e-12);
      // directions up to sign (the two meshes may start faces at different halfedges)
      EXPECT_NEAR(std::abs(dot(to_vec(a.d1), to_vec(b.d1))), 1., 1e-12);
      EXPECT_NEAR(std::abs(dot(to_vec(a.d2), to_vec(b.d2))), 1., 1e-12);
    }
  }
}

// The jet fits and the face averages are shared among threads with
// CGAL::Parallel_tag; each depends on its own vertex or face only, so the
// curvatures must be the same to the last bit as with CGAL::Sequential_tag.
// The torus has more vertices than one range of fits (2048), so that several
// ranges run at once; the strip's vertices all take the fallback.
TEST(CurvatureEstimation, ParallelIsBitIdenticalToSequential)
{
  auto check = [](const Soup& soup, const std::string& what) {
    const Mesh tm = make_mesh<Mesh>(soup);
    ASSERT_GT(num_vertices(tm), 2u * 2048u) << what;
    auto sequential = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
    auto parallel = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
    std::size_t sequential_fallbacks = 0, parallel_fallbacks = 0;
    ASSERT_EQ(PVF::estimate_principal_curvatures<CGAL::Sequential_tag>(
                tm, sequential, PVF::parameters::fallback_vertices(sequential_fallbacks)),
              PVF::Error_code::SUCCESS) << what;
#ifdef CGAL_LINKED_WITH_TBB
    ASSERT_EQ(PVF::estimate_principal_curvatures<CGAL::Parallel_tag>(
                tm, parallel, PVF::parameters::fallback_vertices(parallel_fallbacks)),
              PVF::Error_code::SUCCESS) << what;
#else
    // CGAL::Parallel_tag needs TBB; the default tag is then sequential.
    ASSERT_EQ(PVF::estimate_principal_curvatures(tm, parallel, PVF::parameters::fallback_vertices(parallel_fallbacks)),
              PVF::Error_code::SUCCESS) << what;
#endif
    EXPECT_EQ(sequential_fallbacks, parallel_fallbacks) << what;
    std::size_t differing = 0;
    for(auto f : faces(tm))
    {
      const Curvatures& a = get(sequential, f);
      const Curvatures& b = get(parallel, f);
      const std::array<double, 8> x = { a.k1, a.k2, a.d1.x(), a.d1.y(), a.d1.z(), a.d2.x(), a.d2.y(), a.d2.z() };
      const std::array<double, 8> y = { b.k1, b.k2, b.d1.x(), b.d1.y(), b.d1.z(), b.d2.x(), b.d2.y(), b.d2.z() };
      for(std::size_t i = 0; i < x.size(); ++i)
        if(std::memcmp(&x[i], &y[i], sizeof(double)) != 0)
          ++differing;
    }
    EXPECT_EQ(differing, 0u) << what << ": values that differ between the sequential and the parallel run";
  };
  check(torus(3., 1., 160, 40), "torus");
  check(flat_strip(2500), "flat strip (every vertex falls back)");
}

TEST(CurvatureEstimation, NamedParameters)
{
  const Soup soup = cylinder(1., 3., 32, 16);
  const Mesh tm = make_mesh<Mesh>(soup);

  // A vertex point map scaled by 2 halves the curvatures.
  auto scaled = get(CGAL::dynamic_vertex_property_t<Point>(), tm);
  for(auto v : vertices(tm))
  {
    const Point& p = tm.point(v);
    put(scaled, v, Point(2 * p.x(), 2 * p.y(), 2 * p.z()));
  }
  auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
  auto scaled_map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
  ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map), PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::estimate_principal_curvatures(tm, scaled_map, CGAL::parameters::vertex_point_map(scaled).geom_traits(K())),
            PVF::Error_code::SUCCESS);
  for(auto f : faces(tm))
  {
    EXPECT_NEAR(get(scaled_map, f).k1, get(map, f).k1 / 2, 1e-12);
    EXPECT_NEAR(get(scaled_map, f).k2, get(map, f).k2 / 2, 1e-12);
    EXPECT_NEAR(std::abs(dot(to_vec(get(scaled_map, f).d1), to_vec(get(map, f).d1))), 1., 1e-9);
  }

  // ring_size: the package's parameter, alone, stacked on CGAL's, and followed by CGAL's members.
  auto ring2 = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
  auto ring2_deg4 = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
  auto ring2_deg4_b = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
  ASSERT_EQ(PVF::estimate_principal_curvatures(tm, ring2, PVF::parameters::ring_size(2)), PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::estimate_principal_curvatures(tm, ring2_deg4,
                                               PVF::parameters::ring_size(2, CGAL::parameters::degree_fitting(4))),
            PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::estimate_principal_curvatures(tm, ring2_deg4_b, PVF::parameters::ring_size(2).degree_fitting(4)),
            PVF::Error_code::SUCCESS);
  const Errors e1 = measure(tm, map, cylinder_truth(1.), 1.);
  const Errors e2 = measure(tm, ring2, cylinder_truth(1.), 1.);
  const Errors e4 = measure(tm, ring2_deg4, cylinder_truth(1.), 1.);
  // Degree 2 on 2-rings fits more points over a wider, more curved patch: a
  // different and (on this exact data) larger error than on 1-rings.
  EXPECT_GT(e2.mean_k, 1.5 * e1.mean_k);
  EXPECT_LT(e2.max_k, 0.1);
  EXPECT_LT(e4.mean_k, e2.mean_k);
  for(auto f : faces(tm))
  {
    EXPECT_EQ(get(ring2_deg4, f).k1, get(ring2_deg4_b, f).k1);
    EXPECT_EQ(get(ring2_deg4, f).k2, get(ring2_deg4_b, f).k2);
  }
}

TEST(CurvatureEstimation, DataMeshes)
{
  // Real meshes: every call succeeds, and values are well formed.
  for(const char* name : { "fandisk.off", "bumpy.off" })
  {
    Mesh tm;
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(std::string(PVF_DATA_DIR) + "/" + name, tm)) << name;
    for(int degree : { 2, 4 })
    {
      auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
      const auto start = std::chrono::steady_clock::now();
      ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map, CGAL::parameters::degree_fitting(degree)),
                PVF::Error_code::SUCCESS)
        << name;
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      std::printf("  %s (%zu faces), degree %d: %.0f ms\n", name, std::size_t(num_faces(tm)), degree, ms);
      expect_well_formed(tm, map);
    }
  }
}

// ================================================================ selection

namespace {

typedef PVF::Face_constraint<Mesh::Face_index, Vector> Constraint;

// The faces within `rings` vertex-rings of f (ring 1: the faces that share a vertex with f).
std::set<Mesh::Face_index> faces_within(const Mesh& tm, Mesh::Face_index f, std::size_t rings)
{
  std::set<Mesh::Face_index> reached = { f };
  std::vector<Mesh::Face_index> frontier = { f };
  for(std::size_t d = 0; d < rings; ++d)
  {
    std::vector<Mesh::Face_index> next;
    for(Mesh::Face_index h : frontier)
      for(auto v : vertices_around_face(halfedge(h, tm), tm))
        for(auto k : faces_around_target(halfedge(v, tm), tm))
          if(k != Mesh::null_face() && reached.insert(k).second)
            next.push_back(k);
    frontier.swap(next);
  }
  return reached;
}

// Checks that no two constrained faces are within `rings` rings of each other.
void expect_spread(const Mesh& tm, const std::vector<Constraint>& out, std::size_t rings)
{
  std::set<Mesh::Face_index> chosen;
  for(const Constraint& c : out)
    EXPECT_TRUE(chosen.insert(c.face).second) << "face chosen twice";
  for(const Constraint& c : out)
  {
    const std::set<Mesh::Face_index> near = faces_within(tm, c.face, rings);
    for(Mesh::Face_index g : near)
      EXPECT_TRUE(g == c.face || chosen.count(g) == 0) << "faces " << c.face << " and " << g << " are too close";
  }
}

} // namespace

TEST(CurvatureConstraints, TorusSelection)
{
  const Mesh tm = make_mesh<Mesh>(torus(3., 1., 96, 32));
  auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
  ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map), PVF::Error_code::SUCCESS);

  for(double fraction : { 0.002, 0.01, 0.05 })
    for(double threshold : { 0.5, 0.8 })
    {
      std::vector<Constraint> out(3);  // replaced
      ASSERT_EQ(PVF::select_curvature_constraints(tm, map, out,
                                                  PVF::parameters::constrained_fraction(
                                                    fraction, PVF::parameters::anisotropy_threshold(threshold))),
                PVF::Error_code::SUCCESS);
      const std::size_t budget = std::size_t(std::floor(fraction * double(num_faces(tm))));
      ASSERT_GT(out.size(), 0u);
      EXPECT_LE(out.size(), budget);
      const std::size_t k = PVF::internal::curvature_exclusion_rings(fraction);
      EXPECT_EQ(k, std::size_t(std::max(1., std::floor(0.5 / std::sqrt(fraction)))));

      double previous_gap = std::numeric_limits<double>::infinity();
      for(const Constraint& c : out)
      {
        const Curvatures& pc = get(map, c.face);
        const double a = std::abs(pc.k1 - pc.k2) / (std::abs(pc.k1) + std::abs(pc.k2));
        EXPECT_GE(a, threshold);
        ASSERT_EQ(c.vectors.size(), 2u);
        EXPECT_EQ(c.vectors[0], pc.d1);
        EXPECT_EQ(c.vectors[1], pc.d2);
        EXPECT_TRUE(std::isinf(c.weight));
        EXPECT_LE(pc.k1 - pc.k2, previous_gap);  // decreasing gap
        previous_gap = pc.k1 - pc.k2;
      }
      // The first choice is the candidate with the largest gap.
      double best_gap = 0;
      for(auto f : faces(tm))
      {
        const Curvatures& pc = get(map, f);
        if(std::abs(pc.k1 - pc.k2) / (std::abs(pc.k1) + std::abs(pc.k2)) >= threshold)
          best_gap = std::max(best_gap, pc.k1 - pc.k2);
      }
      EXPECT_EQ(get(map, out.front().face).k1 - get(map, out.front().face).k2, best_gap);

      // Spread: chosen faces are more than k rings apart, so never adjacent.
      expect_spread(tm, out, k);
    }
}

TEST(CurvatureConstraints, ThresholdAndFullFraction)
{
  const Mesh tm = make_mesh<Mesh>(torus(3., 1., 48, 16));
  auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
  ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map), PVF::Error_code::SUCCESS);

  // On this torus the anisotropy is 0.6 on the outer equator and 1 where k2 = 0 or
  // k2 < 0: a threshold of 0.9 keeps only the inner part (|cos v| small or cos v < 0).
  std::vector<Constraint> out;
  ASSERT_EQ(PVF::select_curvature_constraints(tm, map, out,
                                              PVF::parameters::constrained_fraction(1., PVF::parameters::anisotropy_threshold(0.9))),
            PVF::Error_code::SUCCESS);
  ASSERT_FALSE(out.empty());
  for(const Constraint& c : out)
  {
    const Vec3 b = barycentre(c.face, tm);
    EXPECT_LT(std::hypot(b[0], b[1]), 3. + 0.5);  // cos v < ~0.47 there
  }
  // fraction 1: everything not excluded; no two faces share a vertex.
  expect_spread(tm, out, 1);

  // Umbilic sphere: nothing qualifies at the default threshold.
  const Mesh ball = make_mesh<Mesh>(sphere(1., 32, 16));
  auto ball_map = get(CGAL::dynamic_face_property_t<Curvatures>(), ball);
  ASSERT_EQ(PVF::estimate_principal_curvatures(ball, ball_map), PVF::Error_code::SUCCESS);
  std::vector<Constraint> none(2);
  EXPECT_EQ(PVF::select_curvature_constraints(ball, ball_map, none), PVF::Error_code::SUCCESS);
  EXPECT_TRUE(none.empty());

  // Default parameters on the torus: 1% of the faces.
  std::vector<Constraint> defaults;
  EXPECT_EQ(PVF::select_curvature_constraints(tm, map, defaults), PVF::Error_code::SUCCESS);
  EXPECT_GT(defaults.size(), 0u);
  EXPECT_LE(defaults.size(), std::size_t(0.01 * num_faces(tm)));

  // The overload for a tangent bundle (it once failed to compile: overload
  // resolution formed boost::graph_traits of the bundle) chooses the same faces.
  const PVF::Tangent_bundle<Mesh> bundle(tm);
  std::vector<Constraint> from_bundle;
  EXPECT_EQ(PVF::select_curvature_constraints(bundle, map, from_bundle), PVF::Error_code::SUCCESS);
  ASSERT_EQ(from_bundle.size(), defaults.size());
  for(std::size_t i = 0; i < defaults.size(); ++i)
    EXPECT_EQ(from_bundle[i].face, defaults[i].face);
}

TEST(CurvatureConstraints, InvalidInput)
{
  const Mesh tm = make_mesh<Mesh>(torus(3., 1., 24, 8));
  auto map = get(CGAL::dynamic_face_property_t<Curvatures>(), tm);
  ASSERT_EQ(PVF::estimate_principal_curvatures(tm, map), PVF::Error_code::SUCCESS);
  std::vector<Constraint> out(1);
  out[0].face = *faces(tm).begin();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for(double fraction : { 0., -0.1, 1.5, nan })
    EXPECT_EQ(PVF::select_curvature_constraints(tm, map, out, PVF::parameters::constrained_fraction(fraction)),
              PVF::Error_code::INVALID_PARAMETER)
      << fraction;
  for(double threshold : { -0.1, 1.1, nan })
    EXPECT_EQ(PVF::select_curvature_constraints(tm, map, out, PVF::parameters::anisotropy_threshold(threshold)),
              PVF::Error_code::INVALID_PARAMETER)
      << threshold;
  EXPECT_EQ(out.size(), 1u);

  Curvatures broken = get(map, *faces(tm).begin());
  broken.k2 = nan;
  put(map, *faces(tm).begin(), broken);
  EXPECT_EQ(PVF::select_curvature_constraints(tm, map, out), PVF::Error_code::NON_FINITE_VALUE);
  EXPECT_EQ(out.size(), 1u);

  Mesh empty;
  auto empty_map = get(CGAL::dynamic_face_property_t<Curvatures>(), empty);
  EXPECT_EQ(PVF::select_curvature_constraints(empty, empty_map, out), PVF::Error_code::EMPTY_MESH);
  EXPECT_EQ(out.size(), 1u);
}

} // namespace pvf_frame_curvature_test
