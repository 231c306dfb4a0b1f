// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Tests of comb_frame_field() and compute_integer_grid_map() (issue 12).
// Every property is checked by code written here, from the output maps only.
// Everything is in an anonymous namespace and the suites are named Igm*, so
// that the file shares no name with the other test files.

#include "test_meshes.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>
#include <CGAL/Polyvector_fields/design_conjugate_frame_field.h>
#include <CGAL/Polyvector_fields/design_polyvector_field.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/polyvector_polynomial.h>
#include <CGAL/Polyvector_fields/select_curvature_constraints.h>

#include <CGAL/Polyvector_fields/IO/integer_grid_map.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/comb_frame_field.h>
#include <CGAL/Polyvector_fields/compute_integer_grid_map.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>

namespace {

namespace PVF = CGAL::Polyvector_fields;
using namespace pvf_test;  // Mesh, Vector, Point, Kernel, pi, load, data, grid, sphere, torus, ...
typedef Mesh::Face_index Face;
typedef Mesh::Halfedge_index Halfedge;
typedef Mesh::Vertex_index Vertex;
typedef std::complex<double> Complex;
typedef std::array<double, 2> UV;
typedef PVF::Face_constraint<Face, Vector> Constraint;

// ---------------------------------------------------------------------------
// Fields of the measured runs, designed with the package's API.
// ---------------------------------------------------------------------------

struct Case
{
  std::string name;
  Mesh tm;
  Mesh::Property_map<Face, std::vector<Complex> > field;
  double h = -1;  // < 0: default
};

std::unique_ptr<Case> make_case(const std::string& name)
{
  auto c = std::make_unique<Case>();
  c->name = name;
  const bool inspired = name.rfind("inspired", 0) == 0;
  std::vector<Constraint> constraints;
  if(name == "sphere")
    c->tm = sphere(3);
  else if(name == "torus")
    c->tm = torus(40, 16);
  else
    c->tm = load(inspired ? "inspired_mesh.obj" : name + ".off");
  Mesh& tm = c->tm;
  auto curvatures = tm.add_property_map<Face, PVF::Principal_curvatures<Vector> >("f:k").first;
  if(inspired)
  {
    EXPECT_EQ(PVF::IO::read_dmat_constraints(data("inspired_mesh_b.dmat"), data("inspired_mesh_bc.dmat"), tm, constraints),
              PVF::Error_code::SUCCESS);
    c->h = 0.82;
  }
  else if(name == "fandisk")
    constraints = pvf_test::sharp_edge_constraints(tm, 30);
  else
  {
    EXPECT_EQ(PVF::estimate_principal_curvatures(tm, curvatures), PVF::Error_code::SUCCESS);
    EXPECT_EQ(PVF::select_curvature_constraints(tm, curvatures, constraints, PVF::parameters::constrained_fraction(0.01)),
              PVF::Error_code::SUCCESS);
    if(constraints.empty())
      constraints = random_constraints(tm, 3, 2, 7);
  }
  c->field = tm.add_property_map<Face, std::vector<Complex> >("f:field").first;
  EXPECT_EQ(PVF::design_polyvector_field(tm, 4, constraints, c->field, PVF::parameters::sign_symmetric(true)),
            PVF::Error_code::SUCCESS);
  if(name == "inspired_conjugate")
  {
    EXPECT_EQ(PVF::estimate_principal_curvatures(tm, curvatures), PVF::Error_code::SUCCESS);
    PVF::Conjugate_field_result r;
    EXPECT_EQ(PVF::design_conjugate_frame_field(tm, constraints, c->field, r,
                                                PVF::parameters::principal_curvature_map(curvatures)),
              PVF::Error_code::SUCCESS);
  }
  return c;
}

template <typename TM, typename FieldMap, typename UVMap>
PVF::Error_code run_igm(const TM& tm, FieldMap field, UVMap uv, double h, PVF::Integer_grid_map_result& r)
{
  if(h > 0)
    return PVF::compute_integer_grid_map(tm, field, uv, r, PVF::parameters::target_edge_length(h));
  return PVF::compute_integer_grid_map(tm, field, uv, r);
}

// ---------------------------------------------------------------------------
// Independent checks, from the uv map only.
// ---------------------------------------------------------------------------
inline UV rot(const UV& p, int r)
{
  switch(r & 3)
  {
    case 0: return p;
    case 1: return { -p[1], p[0] };
    case 2: return { -p[0], -p[1] };
    default: return { p[1], -p[0] };
  }
}

// Worst mismatch over all interior edges: the two sides must agree up to R^r
// (r in 0..3) and one integer translation for both endpoints.
template <typename TM, typename UVMap>
double worst_seam_mismatch(const TM& tm, UVMap uv, std::size_t* rotated_edges = nullptr)
{
  double worst = 0;
  std::size_t rotated = 0;
  for(auto e : edges(tm))
  {
    const auto h = halfedge(e, tm);
    if(CGAL::is_border_edge(h, tm))
      continue;
    const auto o = opposite(h, tm);
    const UV a1 = get(uv, h), a0 = get(uv, prev(h, tm)), b1 = get(uv, prev(o, tm)), b0 = get(uv, o);
    double best = std::numeric_limits<double>::infinity();
    int best_r = 0;
    for(int r = 0; r < 4; ++r)
    {
      const UV ra1 = rot(a1, r), ra0 = rot(a0, r);
      const double t1x = b1[0] - ra1[0], t1y = b1[1] - ra1[1], t0x = b0[0] - ra0[0], t0y = b0[1] - ra0[1];
      const double tx = std::round(t1x), ty = std::round(t1y);
      const double err = (std::max)({ std::abs(t1x - tx), std::abs(t1y - ty), std::abs(t0x - tx), std::abs(t0y - ty) });
      if(err < best)
      {
        best = err;
        best_r = r;
      }
    }
    rotated += best_r != 0;
    worst = (std::max)(worst, best);
  }
  if(rotated_edges)
    *rotated_edges = rotated;
  return worst;
}

template <typename TM, typename UVMap>
std::size_t count_flips(const TM& tm, UVMap uv)
{
  std::size_t flips = 0;
  for(auto f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    const UV a = get(uv, h), b = get(uv, next(h, tm)), c = get(uv, prev(h, tm));
    const double det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    flips += !(det > 0);
  }
  return flips;
}

// Index numerator of an interior vertex read from the map: the uv angles around
// it sum to 2 pi - k pi / 2.
template <typename TM, typename UVMap>
double map_index(const TM& tm, UVMap uv, typename boost::graph_traits<TM>::vertex_descriptor v)
{
  double sum = 0;
  for(auto h : halfedges_around_target(halfedge(v, tm), tm))
  {
    const UV p = get(uv, h), a = get(uv, next(h, tm)), b = get(uv, prev(h, tm));
    const double ax = a[0] - p[0], ay = a[1] - p[1], bx = b[0] - p[0], by = b[1] - p[1];
    sum += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  }
  return (2 * pi - sum) / (pi / 2);
}

struct Map_checks
{
  double seam = 0;
  std::size_t flips = 0, singular = 0, rotated_edges = 0;
  double singular_off_integer = 0, index_mismatch = 0, index_not_integer = 0;
};

Map_checks check_map(const Case& c, Mesh::Property_map<Halfedge, UV> uv)
{
  const Mesh& tm = c.tm;
  Map_checks m;
  m.seam = worst_seam_mismatch(tm, uv, &m.rotated_edges);
  m.flips = count_flips(tm, uv);
  std::vector<PVF::Singularity<Vertex> > sings;
  EXPECT_EQ(PVF::compute_singularities(tm, 4, c.field, std::back_inserter(sings)), PVF::Error_code::SUCCESS);
  std::map<Vertex, int> index;
  for(const auto& s : sings)
    index[s.vertex] = s.index_numerator;
  m.singular = sings.size();
  for(const auto& s : sings)
    for(auto h : halfedges_around_target(halfedge(s.vertex, tm), tm))
    {
      const UV p = uv[h];
      m.singular_off_integer = (std::max)({ m.singular_off_integer, std::abs(p[0] - std::round(p[0])), std::abs(p[1] - std::round(p[1])) });
    }
  for(Vertex v : vertices(tm))
  {
    if(CGAL::is_border(v, tm))
      continue;
    const double k = map_index(tm, uv, v);
    m.index_not_integer = (std::max)(m.index_not_integer, std::abs(k - std::round(k)));
    const int expected = index.count(v) ? index[v] : 0;
    m.index_mismatch = (std::max)(m.index_mismatch, std::abs(std::round(k) - expected));
  }
  return m;
}

// A constant frame field {u, v} (world vectors) in every face.
void constant_field(const Mesh& tm, const Vector& u, const Vector& v, Mesh::Property_map<Face, std::vector<Complex> > field)
{
  for(Face f : faces(tm))
  {
    PVF::Face_frame fr;
    ASSERT_EQ(PVF::face_frame(f, tm, fr), PVF::Error_code::SUCCESS);
    const Complex uc = fr.to_complex(u.x(), u.y(), u.z()), vc = fr.to_complex(v.x(), v.y(), v.z());
    field[f] = PVF::sign_symmetric_polyvector_coefficients({ uc, vc });
  }
}

// On a flat plane with a constant field, uv = R^k J* p + t with J* = h^-1 [u v]^-1, t integer.
void flat_plane_test(const Vector& u0, const Vector& v0, double h)
{
  Mesh tm = pvf_test::jittered_grid(9, 13, 3);
  auto field = tm.add_property_map<Face, std::vector<Complex> >("f:field").first;
  constant_field(tm, u0, v0, field);
  auto uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  PVF::Integer_grid_map_result r;
  ASSERT_EQ(run_igm(tm, field, uv, h, r), PVF::Error_code::SUCCESS);
  EXPECT_EQ(r.comb.singular_vertices, 0u);
  EXPECT_EQ(r.flipped_faces, 0u);
  // dual basis of the unit directions in the plane z = 0
  const Vector u = u0 / std::sqrt(u0.squared_length()), v = v0 / std::sqrt(v0.squared_length());
  const double det = u.x() * v.y() - u.y() * v.x();
  const double J[4] = { v.y() / det / h, -v.x() / det / h, -u.y() / det / h, u.x() / det / h };
  auto expected = [&](const Point& p) { return UV{ J[0] * p.x() + J[1] * p.y(), J[2] * p.x() + J[3] * p.y() }; };
  double best = std::numeric_limits<double>::infinity();
  for(int k = 0; k < 4; ++k)
  {
    const Halfedge h0 = *halfedges(tm).begin();
    const UV e0 = rot(expected(tm.point(target(h0, tm))), k);
    const UV t = { uv[h0][0] - e0[0], uv[h0][1] - e0[1] };
    double worst = (std::max)(std::abs(t[0] - std::round(t[0])), std::abs(t[1] - std::round(t[1])));
    for(Face f : faces(tm))
      for(Halfedge hh : halfedges_around_face(halfedge(f, tm), tm))
      {
        const UV e = rot(expected(tm.point(target(hh, tm))), k);
        worst = (std::max)({ worst, std::abs(uv[hh][0] - e[0] - t[0]), std::abs(uv[hh][1] - e[1] - t[1]) });
      }
    best = (std::min)(best, worst);
  }
  EXPECT_LT(best, 1e-9);
  EXPECT_LT(r.continuous_energy, 1e-20);
  EXPECT_LT(r.rounded_energy, 1e-20);
}

// ---------------------------------------------------------------------------

TEST(IgmFlatPlane, OrthogonalConstantFrame) { flat_plane_test(Vector(1, 0, 0), Vector(0, 1, 0), 0.7); }

TEST(IgmFlatPlane, Skewed60ConstantFrame)
{
  flat_plane_test(Vector(1, 0, 0), Vector(std::cos(pi / 3), std::sin(pi / 3), 0), 0.45);
  // and turned in the plane, with non-unit vectors (only directions count)
  flat_plane_test(Vector(2 * std::cos(0.3), 2 * std::sin(0.3), 0), Vector(0.5 * std::cos(0.3 + pi / 3), 0.5 * std::sin(0.3 + pi / 3), 0), 1.3);
}

// The 5 measured runs plus a sphere and a torus: seams, singularities, flips.
class IgmRuns : public ::testing::TestWithParam<std::string> {};

TEST_P(IgmRuns, SeamsSingularitiesAndFlips)
{
  std::unique_ptr<Case> c = make_case(GetParam());
  auto uv = c->tm.add_property_map<Halfedge, UV>("h:uv").first;
  PVF::Integer_grid_map_result r;
  ASSERT_EQ(run_igm(c->tm, c->field, uv, c->h, r), PVF::Error_code::SUCCESS);
  const Map_checks m = check_map(*c, uv);
  EXPECT_LT(m.seam, 1e-9);
  EXPECT_EQ(m.flips, 0u);
  EXPECT_EQ(r.flipped_faces, m.flips);
  EXPECT_LT(m.singular_off_integer, 1e-9);
  EXPECT_LT(m.index_not_integer, 1e-6);
  EXPECT_EQ(m.index_mismatch, 0.0);
  EXPECT_EQ(m.singular, r.comb.singular_vertices);
  EXPECT_EQ(r.inconsistencies, 0u);
  if(m.singular > 0)
  {
    EXPECT_GT(m.rotated_edges, 0u);  // seams with a rotation are exercised
  }
  std::printf("[ %s ] faces %zu singular %zu seams %zu integer unknowns %zu flips %zu (rounds %zu) ratio %.4f seam %.2g\n",
              GetParam().c_str(), r.faces, r.comb.singular_vertices, r.comb.seam_curves, r.integer_unknowns, m.flips,
              r.stiffening_rounds, r.energy_ratio, m.seam);
}

INSTANTIATE_TEST_SUITE_P(Igm, IgmRuns,
                         ::testing::Values("inspired", "inspired_conjugate", "bumpy", "eight", "fandisk", "sphere", "torus"));

// Stiffening rounds keep the integers of the last rounding while that removes
// flips, and a rounding comes only in the first round and after a round that
// did not lower the flips (round 1 always keeps them). A round that rounds
// factors the system; one that keeps the integers is solved by conjugate
// gradient with the last factor (on the sphere, it always converges). With
// stiffening_keeps_integers(false), every round rounds and factors. Both maps
// are checked maps without flips (the sphere needs stiffening rounds in both).
TEST(IgmStiffening, RoundsKeepTheIntegersUnlessAsked)
{
  std::unique_ptr<Case> c = make_case("sphere");
  auto uv = c->tm.add_property_map<Halfedge, UV>("h:uv").first;
  for(bool keep : { true, false })
  {
    PVF::Integer_grid_map_result r;
    const auto np = PVF::parameters::stiffening_keeps_integers(keep);
    ASSERT_EQ(c->h > 0 ? PVF::compute_integer_grid_map(c->tm, c->field, uv, r, PVF::parameters::target_edge_length(c->h, np))
                       : PVF::compute_integer_grid_map(c->tm, c->field, uv, r, np),
              PVF::Error_code::SUCCESS)
      << keep;
    ASSERT_GE(r.stiffening_rounds, 1u) << keep;
    EXPECT_EQ(r.flipped_faces, 0u) << keep;
    EXPECT_EQ(check_map(*c, uv).flips, 0u) << keep;
    EXPECT_EQ(r.factorizations, r.integer_roundings) << keep;
    EXPECT_EQ(r.cg_solves, r.stiffening_rounds + 1 - r.integer_roundings) << keep;
    if(keep)
    {
      EXPECT_GE(r.integer_roundings, 1u);
      EXPECT_LE(r.integer_roundings, r.stiffening_rounds);
      EXPECT_GE(r.cg_solves, 1u);
    }
    else
      EXPECT_EQ(r.integer_roundings, r.stiffening_rounds + 1);
    std::printf("[ sphere, keep integers %d ] %zu stiffening rounds, %zu roundings, %zu by conjugate gradient (%zu "
                "iterations), energy ratio %.4f\n",
                int(keep), r.stiffening_rounds, r.integer_roundings, r.cg_solves, r.cg_iterations, r.energy_ratio);
  }
}

// A triangle whose two edges are on the border and run along the same field
// direction (an ear: its tip has no other face) cannot have both of them on
// integer iso-lines: they share the tip, so its three corners would be on
// one iso-line, and the triangle would have no area. The shorter one is left
// free; the map is checked, without flips, and the ear keeps a positive area
// in uv. The ear's edges make 5.7 degrees with u.
TEST(IgmFeatures, BorderEarIsNotFlattened)
{
  Mesh tm;
  const Vertex a = tm.add_vertex(Point(0, 0, 0)), b = tm.add_vertex(Point(2, 0, 0)), c = tm.add_vertex(Point(4, 0, 0)),
               d = tm.add_vertex(Point(0, 2, 0)), e = tm.add_vertex(Point(2, 2, 0)), f = tm.add_vertex(Point(4, 2, 0)),
               tip = tm.add_vertex(Point(1, -0.1, 0));
  tm.add_face(a, b, e);
  tm.add_face(a, e, d);
  tm.add_face(b, c, f);
  tm.add_face(b, f, e);
  const Face ear = tm.add_face(a, tip, b);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(tm));
  auto field = tm.add_property_map<Face, std::vector<Complex> >("f:field").first;
  constant_field(tm, Vector(1, 0, 0), Vector(0, 1, 0), field);
  auto uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  PVF::Integer_grid_map_result r;
  ASSERT_EQ(PVF::compute_integer_grid_map(tm, field, uv, r,
                                          PVF::parameters::target_edge_length(0.5, PVF::parameters::boundary_alignment(true))),
            PVF::Error_code::SUCCESS)
    << r.diagnostic;
  EXPECT_EQ(r.feature_edges, 7u);
  EXPECT_EQ(r.flattening_feature_edges, 1u);
  EXPECT_EQ(r.aligned_feature_edges, 6u);
  EXPECT_EQ(r.flipped_faces, 0u);
  std::vector<UV> p;
  for(Halfedge h : CGAL::halfedges_around_face(halfedge(ear, tm), tm))
    p.push_back(uv[h]);
  const double area2 = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
  EXPECT_GT(area2, 0) << "the ear is flat or flipped in the map";
}

// The cut opens every component into a disk, passes through every singular
// vertex, and the combed frames match by the identity across every other edge.
TEST(IgmComb, CutIsADiskThroughSingularities)
{
  for(const std::string name : { "bumpy", "eight", "inspired_conjugate" })
  {
    std::unique_ptr<Case> c = make_case(name);
    Mesh& tm = c->tm;
    auto cut = tm.add_property_map<Mesh::Edge_index, bool>("e:cut").first;
    auto combed = tm.add_property_map<Face, std::array<Vector, 2> >("f:combed").first;
    auto rotation = tm.add_property_map<Halfedge, int>("h:rot").first;
    PVF::Comb_result r;
    ASSERT_EQ(PVF::comb_frame_field(tm, c->field, cut, combed, rotation, r), PVF::Error_code::SUCCESS);
    // singular vertices on the cut
    std::vector<PVF::Singularity<Vertex> > sings;
    ASSERT_EQ(PVF::compute_singularities(tm, 4, c->field, std::back_inserter(sings)), PVF::Error_code::SUCCESS);
    for(const auto& s : sings)
    {
      bool on_cut = false;
      for(auto h : halfedges_around_target(halfedge(s.vertex, tm), tm))
        on_cut |= cut[edge(h, tm)];
      EXPECT_TRUE(on_cut) << name;
    }
    // Euler characteristic of the cut-open mesh: corners glued across non-cut edges
    std::map<Halfedge, Halfedge> parent;
    std::function<Halfedge(Halfedge)> find = [&](Halfedge h) { return parent[h] == h ? h : parent[h] = find(parent[h]); };
    for(Halfedge h : halfedges(tm))
      if(!is_border(h, tm))
        parent[h] = h;
    std::size_t E = 0;
    for(auto e : edges(tm))
    {
      const Halfedge h = halfedge(e, tm), o = opposite(h, tm);
      if(is_border(h, tm) || is_border(o, tm))
      {
        ++E;
        continue;
      }
      if(cut[e])
      {
        E += 2;
        continue;
      }
      ++E;
      // corner at target(h) in face(h) ~ corner at target(h) in face(o), i.e. prev(o)
      parent[find(h)] = find(prev(o, tm));
      parent[find(prev(h, tm))] = find(o);
    }
    std::size_t Vc = 0;
    for(auto& kv : parent)
      Vc += find(kv.first) == kv.first;
    EXPECT_EQ(long(Vc) - long(E) + long(num_faces(tm)), 1) << name;  // one component: a disk
    // combed frames: across non-cut edges the matching is the identity
    double worst = 0;
    std::size_t nearest_disagree = 0;
    for(auto e : edges(tm))
    {
      const Halfedge h = halfedge(e, tm);
      if(CGAL::is_border_edge(h, tm) || cut[e])
        continue;
      const Face f = face(h, tm), g = face(opposite(h, tm), tm);
      // unfold: rotate u_f about the edge into g's plane
      PVF::Face_frame ff, fg;
      PVF::face_frame(f, tm, ff);
      PVF::face_frame(g, tm, fg);
      Vector d = tm.point(target(h, tm)) - tm.point(source(h, tm));
      d = d / std::sqrt(d.squared_length());
      const Vector nf(ff.normal[0], ff.normal[1], ff.normal[2]), ng(fg.normal[0], fg.normal[1], fg.normal[2]);
      const Vector bf = CGAL::cross_product(nf, d), bg = CGAL::cross_product(ng, d);
      // the four combed roots of f, moved into g's plane, against those of g, in the same order:
      // the sum of their rotations must lie in (-pi, pi] (the principal matching is the identity)
      auto turn = [&](const Vector& x) { return (x * d) * d + (x * bf) * bg; };
      const Vector rf[4] = { turn(combed[f][0]), turn(combed[f][1]), -turn(combed[f][0]), -turn(combed[f][1]) };
      const Vector rg[4] = { combed[g][0], combed[g][1], -combed[g][0], -combed[g][1] };
      double sum = 0;
      for(int k = 0; k < 4; ++k)
        sum += std::atan2(CGAL::cross_product(rf[k], rg[k]) * ng, rf[k] * rg[k]);
      worst = (std::max)(worst, double(!(sum > -pi && sum <= pi)));
      // and the nearest-vector matching agrees except where the frame changes shape a lot
      double best = 1e9;
      int arg = 0;
      for(int k = 0; k < 4; ++k)
        if((rf[0] - rg[k]).squared_length() < best)
        {
          best = (rf[0] - rg[k]).squared_length();
          arg = k;
        }
      nearest_disagree += arg != 0;
      EXPECT_EQ(rotation[h], 0);
    }
    EXPECT_EQ(worst, 0.0) << name;
    EXPECT_EQ(r.singular_vertices, sings.size());
    std::printf("[ %s ] cut edges %zu, non-cut edges where the nearest-u matching differs from the principal one: %zu\n",
                name.c_str(), r.cut_edges, nearest_disagree);
  }
}

// A rigid motion changes the map only by a rotation in Z4 and a translation.
TEST(IgmInvariance, RigidMotion)
{
  std::unique_ptr<Case> c = make_case("inspired_conjugate");
  auto uv = c->tm.add_property_map<Halfedge, UV>("h:uv").first;
  PVF::Integer_grid_map_result r;
  ASSERT_EQ(run_igm(c->tm, c->field, uv, c->h, r), PVF::Error_code::SUCCESS);

  const Rigid_motion motion(12);
  Mesh moved = c->tm;
  motion.move(moved);
  std::vector<Constraint> constraints;
  ASSERT_EQ(PVF::IO::read_dmat_constraints(data("inspired_mesh_b.dmat"), data("inspired_mesh_bc.dmat"), moved, constraints),
            PVF::Error_code::SUCCESS);
  motion.move(constraints);
  auto field = moved.add_property_map<Face, std::vector<Complex> >("f:moved_field").first;
  ASSERT_EQ(PVF::design_polyvector_field(moved, 4, constraints, field, PVF::parameters::sign_symmetric(true)),
            PVF::Error_code::SUCCESS);
  auto curvatures = moved.add_property_map<Face, PVF::Principal_curvatures<Vector> >("f:moved_k").first;
  ASSERT_EQ(PVF::estimate_principal_curvatures(moved, curvatures), PVF::Error_code::SUCCESS);
  PVF::Conjugate_field_result cr;
  ASSERT_EQ(PVF::design_conjugate_frame_field(moved, constraints, field, cr, PVF::parameters::principal_curvature_map(curvatures)),
            PVF::Error_code::SUCCESS);
  auto uv2 = moved.add_property_map<Halfedge, UV>("h:uv2").first;
  PVF::Integer_grid_map_result r2;
  ASSERT_EQ(run_igm(moved, field, uv2, c->h, r2), PVF::Error_code::SUCCESS);
  double best = std::numeric_limits<double>::infinity();
  for(int k = 0; k < 4; ++k)
  {
    const Halfedge h0 = halfedge(*faces(moved).begin(), moved);
    const UV a = rot(uv[h0], k);
    const UV t = { uv2[h0][0] - a[0], uv2[h0][1] - a[1] };
    double worst = 0;
    for(Face f : faces(moved))
      for(Halfedge h : halfedges_around_face(halfedge(f, moved), moved))
      {
        const UV b = rot(uv[h], k);
        worst = (std::max)({ worst, std::abs(uv2[h][0] - b[0] - t[0]), std::abs(uv2[h][1] - b[1] - t[1]) });
      }
    best = (std::min)(best, worst);
  }
  EXPECT_LT(best, 1e-6);
  EXPECT_GT(r.comb.singular_vertices, 0u);
}

// Surface_mesh and Polyhedron_3 give identical maps.
TEST(IgmGeneric, SurfaceMeshAndPolyhedron)
{
  typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
  typedef boost::graph_traits<Polyhedron>::face_descriptor P_face;
  typedef boost::graph_traits<Polyhedron>::halfedge_descriptor P_halfedge;
  for(const std::string name : { "bumpy.off", "fandisk.off" })
  {
    Mesh sm = load(name);
    Polyhedron poly = load<Polyhedron>(name);
    const auto constraints = random_constraints(sm, 12, 2, 5);
    auto sfield = sm.add_property_map<Face, std::vector<Complex> >("f:field").first;
    ASSERT_EQ(PVF::design_polyvector_field(sm, 4, constraints, sfield, PVF::parameters::sign_symmetric(true)),
              PVF::Error_code::SUCCESS);
    std::vector<P_face> pf(faces(poly).begin(), faces(poly).end());
    std::vector<PVF::Face_constraint<P_face, Vector> > pc;
    for(const Constraint& c : constraints)
      pc.push_back({ pf[std::size_t(c.face)], c.vectors, c.weight });
    std::map<P_face, std::vector<Complex> > pcoef;
    auto pfield = boost::make_assoc_property_map(pcoef);
    ASSERT_EQ(PVF::design_polyvector_field(poly, 4, pc, pfield, PVF::parameters::sign_symmetric(true)),
              PVF::Error_code::SUCCESS);
    auto suv = sm.add_property_map<Halfedge, UV>("h:uv").first;
    std::map<P_halfedge, UV> puv_store;
    auto puv = boost::make_assoc_property_map(puv_store);
    PVF::Integer_grid_map_result sr, pr;
    ASSERT_EQ(PVF::compute_integer_grid_map(sm, sfield, suv, sr), PVF::Error_code::SUCCESS);
    ASSERT_EQ(PVF::compute_integer_grid_map(poly, pfield, puv, pr), PVF::Error_code::SUCCESS);
    double worst = 0;
    std::size_t i = 0;
    std::vector<Face> sf(faces(sm).begin(), faces(sm).end());
    for(P_face f : pf)
    {
      auto hs = halfedge(sf[i++], sm);
      auto hp = halfedge(f, poly);
      for(int k = 0; k < 3; ++k, hs = next(hs, sm), hp = next(hp, poly))
        worst = (std::max)({ worst, std::abs(suv[hs][0] - puv[hp][0]), std::abs(suv[hs][1] - puv[hp][1]) });
    }
    EXPECT_EQ(worst, 0.0) << name;
    EXPECT_EQ(sr.integer_unknowns, pr.integer_unknowns);
    EXPECT_EQ(sr.flipped_faces, pr.flipped_faces);
  }
}

// Greedy rounding through the Schur complement gives the same integers as
// refactoring the whole system after each rounding.
TEST(IgmRounding, SchurUpdateMatchesRefactorization)
{
  std::unique_ptr<Case> c = make_case("bumpy");
  auto a = c->tm.add_property_map<Halfedge, UV>("h:a").first;
  auto b = c->tm.add_property_map<Halfedge, UV>("h:b").first;
  PVF::Integer_grid_map_result ra, rb;
  ASSERT_EQ(PVF::compute_integer_grid_map(c->tm, c->field, a, ra, CGAL::parameters::number_of_iterations(0)),
            PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::compute_integer_grid_map(c->tm, c->field, b, rb,
                                          PVF::parameters::rounding_by_refactorization(true, CGAL::parameters::number_of_iterations(0))),
            PVF::Error_code::SUCCESS);
  double worst = 0;
  for(Halfedge h : halfedges(c->tm))
    if(!is_border(h, c->tm))
      worst = (std::max)({ worst, std::abs(a[h][0] - b[h][0]), std::abs(a[h][1] - b[h][1]) });
  EXPECT_LT(worst, 1e-8);
  EXPECT_EQ(rb.factorizations, 1 + rb.integer_unknowns);
  EXPECT_EQ(ra.factorizations, 1u);
}

// The OBJ writer: one vt per corner, integer points exactly at integers.
TEST(IgmOutput, ObjWithTextureCoordinates)
{
  std::unique_ptr<Case> c = make_case("bumpy");
  auto uv = c->tm.add_property_map<Halfedge, UV>("h:uv").first;
  PVF::Integer_grid_map_result r;
  ASSERT_EQ(run_igm(c->tm, c->field, uv, c->h, r), PVF::Error_code::SUCCESS);
  const std::string file = "igm_test_output.obj";
  ASSERT_EQ(PVF::IO::write_integer_grid_map_OBJ(file, c->tm, uv), PVF::Error_code::SUCCESS);
  std::ifstream in(file);
  std::string line;
  std::size_t v = 0, vt = 0, f = 0;
  std::vector<UV> tex;
  std::vector<std::array<std::size_t, 6> > fs;
  while(std::getline(in, line))
  {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if(tag == "v") ++v;
    else if(tag == "vt") { UV t; s >> t[0] >> t[1]; tex.push_back(t); ++vt; }
    else if(tag == "f")
    {
      std::array<std::size_t, 6> x;
      char slash;
      for(int k = 0; k < 3; ++k)
        s >> x[2 * k] >> slash >> x[2 * k + 1];
      fs.push_back(x);
      ++f;
    }
  }
  EXPECT_EQ(v, num_vertices(c->tm));
  EXPECT_EQ(f, num_faces(c->tm));
  EXPECT_EQ(vt, 3 * num_faces(c->tm));
  // the values read back are the map's, to the last bit
  std::size_t i = 0;
  double worst = 0;
  for(Face fc : faces(c->tm))
    for(Halfedge h : halfedges_around_face(halfedge(fc, c->tm), c->tm))
    {
      worst = (std::max)({ worst, std::abs(tex[i][0] - uv[h][0]), std::abs(tex[i][1] - uv[h][1]) });
      ++i;
    }
  EXPECT_EQ(worst, 0.0);
  std::remove(file.c_str());
  EXPECT_EQ(PVF::IO::write_integer_grid_map_OBJ("/nonexistent/dir/x.obj", c->tm, uv), PVF::Error_code::CANNOT_OPEN_FILE);
}

// ---------------------------------------------------------------------------
// Bad input.
// ---------------------------------------------------------------------------
struct Failing_solver : PVF::Default_real_sparse_solver
{
  bool factor(const Matrix&, NT& D)
  {
    D = 1;
    return false;
  }
};

struct IgmBadInput : ::testing::Test
{
  Mesh tm = pvf_test::jittered_grid(4, 5, 1);
  Mesh::Property_map<Face, std::vector<Complex> > field;
  Mesh::Property_map<Halfedge, UV> uv;
  void SetUp() override
  {
    field = tm.add_property_map<Face, std::vector<Complex> >("f:field").first;
    constant_field(tm, Vector(1, 0, 0), Vector(0, 1, 0), field);
    uv = tm.add_property_map<Halfedge, UV>("h:uv", UV{ 7, 7 }).first;
  }
  bool untouched() const
  {
    for(Halfedge h : halfedges(tm))
      if(uv[h] != UV{ 7, 7 })
        return false;
    return true;
  }
};

TEST_F(IgmBadInput, NotAFrameField)
{
  PVF::Integer_grid_map_result r;
  const Face f(7);
  field[f][1] = Complex(0.3, 0);  // odd coefficient
  EXPECT_EQ(PVF::compute_integer_grid_map(tm, field, uv, r), PVF::Error_code::NOT_A_FRAME_FIELD);
  EXPECT_EQ(r.comb.first_invalid_face, 7u);
  field[f].resize(3);  // wrong size
  EXPECT_EQ(PVF::compute_integer_grid_map(tm, field, uv, r), PVF::Error_code::NOT_A_FRAME_FIELD);
  field[f] = std::vector<Complex>(4, Complex(0));  // zero frame: cannot be clamped
  EXPECT_EQ(PVF::compute_integer_grid_map(tm, field, uv, r), PVF::Error_code::ZERO_FRAME);
  EXPECT_EQ(r.comb.first_invalid_face, 7u);
  EXPECT_STREQ(PVF::get_error_message(PVF::Error_code::ZERO_FRAME),
               "a face of the frame field has a zero frame (both vectors zero), which cannot be clamped");
  field[f] = { Complex(std::nan(""), 0), 0, 1, 0 };
  EXPECT_EQ(PVF::compute_integer_grid_map(tm, field, uv, r), PVF::Error_code::NON_FINITE_VALUE);
  EXPECT_TRUE(untouched());
}

TEST_F(IgmBadInput, DegenerateFramesAreClamped)
{
  PVF::Integer_grid_map_result r;
  PVF::Face_frame fr;
  PVF::face_frame(Face(3), tm, fr);
  // u and v 1 degree apart
  field[Face(3)] = PVF::sign_symmetric_polyvector_coefficients({ Complex(1, 0), std::polar(1.0, pi / 180) });
  // one zero vector
  field[Face(9)] = PVF::sign_symmetric_polyvector_coefficients({ Complex(0, 0), Complex(0.3, 0.4) });
  ASSERT_EQ(PVF::compute_integer_grid_map(tm, field, uv, r), PVF::Error_code::SUCCESS);
  EXPECT_EQ(r.comb.clamped_faces, 2u);
  EXPECT_EQ(count_flips(tm, uv), 0u);
}

TEST_F(IgmBadInput, EdgeLength)
{
  PVF::Integer_grid_map_result r;
  EXPECT_EQ(PVF::compute_integer_grid_map(tm, field, uv, r, PVF::parameters::target_edge_length(0.0)),
            PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::compute_integer_grid_map(tm, field, uv, r, PVF::parameters::target_edge_length(-1.0)),
            PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::compute_integer_grid_map(tm, field, uv, r, PVF::parameters::target_edge_length(std::nan(""))),
            PVF::Error_code::NON_FINITE_VALUE);
  EXPECT_EQ(PVF::compute_integer_grid_map(tm, field, uv, r, PVF::parameters::minimum_frame_angle(0.0)),
            PVF::Error_code::INVALID_PARAMETER);
  EXPECT_TRUE(untouched());
  ASSERT_EQ(PVF::compute_integer_grid_map(tm, field, uv, r), PVF::Error_code::SUCCESS);
  EXPECT_NEAR(r.target_edge_length, r.mean_edge_length, 0.0);  // the default
}

TEST_F(IgmBadInput, SolverFailure)
{
  PVF::Integer_grid_map_result r;
  EXPECT_EQ(PVF::compute_integer_grid_map(tm, field, uv, r, CGAL::parameters::sparse_linear_solver(Failing_solver())),
            PVF::Error_code::SOLVER_FAILURE);
  EXPECT_TRUE(untouched());
}

TEST_F(IgmBadInput, NotATriangleMesh)
{
  Mesh quads;
  CGAL::make_quad(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), quads);
  auto f = quads.add_property_map<Face, std::vector<Complex> >("f:field", std::vector<Complex>{ 1, 0, 0, 0 }).first;
  auto u = quads.add_property_map<Halfedge, UV>("h:uv").first;
  PVF::Integer_grid_map_result r;
  EXPECT_EQ(PVF::compute_integer_grid_map(quads, f, u, r), PVF::Error_code::NON_TRIANGLE_FACE);
}

// The independent checks above detect what they are meant to detect: each is
// run on a corrupted copy of a correct map.
TEST(IgmChecks, DetectCorruption)
{
  std::unique_ptr<Case> c = make_case("bumpy");
  Mesh& tm = c->tm;
  auto uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  PVF::Integer_grid_map_result r;
  ASSERT_EQ(run_igm(tm, c->field, uv, c->h, r), PVF::Error_code::SUCCESS);
  ASSERT_LT(check_map(*c, uv).seam, 1e-9);
  // a seam corner moved by 1e-6: the seam check fails
  auto bad = tm.add_property_map<Halfedge, UV>("h:bad").first;
  for(Halfedge h : halfedges(tm))
    bad[h] = uv[h];
  std::vector<PVF::Singularity<Vertex> > sings;
  ASSERT_EQ(PVF::compute_singularities(tm, 4, c->field, std::back_inserter(sings)), PVF::Error_code::SUCCESS);
  ASSERT_FALSE(sings.empty());
  const Halfedge hs = halfedge(sings.front().vertex, tm);
  bad[hs][0] += 1e-6;
  EXPECT_GT(worst_seam_mismatch(tm, bad), 1e-7);
  EXPECT_GT(check_map(*c, bad).singular_off_integer, 1e-7);
  // a face turned over: the flip count fails
  for(Halfedge h : halfedges(tm))
    bad[h] = uv[h];
  const Halfedge hf = halfedge(*faces(tm).begin(), tm);
  std::swap(bad[hf], bad[next(hf, tm)]);
  EXPECT_GT(count_flips(tm, bad), 0u);
  // the uv scaled by 1.01 about the origin: translations are no longer integer
  for(Halfedge h : halfedges(tm))
    bad[h] = { 1.01 * uv[h][0], 1.01 * uv[h][1] };
  EXPECT_GT(worst_seam_mismatch(tm, bad), 1e-3);
  // the map of another field (turned by 45 degrees in every face): the index check fails
  auto turned = tm.add_property_map<Face, std::vector<Complex> >("f:turned").first;
  for(Face f : faces(tm))
  {
    turned[f] = c->field[f];
    turned[f][0] *= std::polar(1.0, double(std::size_t(f) % 7));  // scrambles c0's argument
  }
  auto uv2 = tm.add_property_map<Halfedge, UV>("h:uv2").first;
  // (a scrambled frame field is still a frame field: the map must be computed, then fail the check)
  ASSERT_EQ(PVF::compute_integer_grid_map(tm, turned, uv2, r, CGAL::parameters::number_of_iterations(0)),
            PVF::Error_code::SUCCESS);
  const Map_checks m = check_map(*c, uv2);  // checked against the original field's singularities
  EXPECT_TRUE(m.index_mismatch > 0 || m.flips > 0);
  std::printf("[ scrambled field ] %zu singularities, %zu integer unknowns, index mismatch %g, flips %zu\n",
              r.comb.singular_vertices, r.integer_unknowns, m.index_mismatch, m.flips);
}

// Several components: each one is cut, pinned and rounded on its own.
TEST(IgmComponents, TwoComponents)
{
  Case c;
  c.name = "two";
  Mesh a = sphere(2), b = torus(30, 12);
  for(Vertex v : vertices(b))
    b.point(v) = b.point(v) + Vector(5, 0, 0);
  CGAL::copy_face_graph(a, c.tm);
  CGAL::copy_face_graph(b, c.tm);
  std::vector<Constraint> constraints = random_constraints(c.tm, 12, 2, 3);
  constraints.push_back({ Face(0), { Vector(1, 0.2, 0.1) } });
  constraints.push_back({ Face(Mesh::size_type(num_faces(a) + 1)), { Vector(0.3, 1, 0.2) } });
  std::set<Face> seen;
  constraints.erase(std::remove_if(constraints.begin(), constraints.end(),
                                   [&](const Constraint& k) { return !seen.insert(k.face).second; }),
                    constraints.end());
  c.field = c.tm.add_property_map<Face, std::vector<Complex> >("f:field").first;
  ASSERT_EQ(PVF::design_polyvector_field(c.tm, 4, constraints, c.field, PVF::parameters::sign_symmetric(true)),
            PVF::Error_code::SUCCESS);
  auto uv = c.tm.add_property_map<Halfedge, UV>("h:uv").first;
  PVF::Integer_grid_map_result r;
  ASSERT_EQ(PVF::compute_integer_grid_map(c.tm, c.field, uv, r, PVF::parameters::target_edge_length(0.2)),
            PVF::Error_code::SUCCESS);
  EXPECT_EQ(r.comb.components, 2u);
  const Map_checks m = check_map(c, uv);
  EXPECT_LT(m.seam, 1e-9);
  EXPECT_EQ(m.flips, 0u);
  EXPECT_LT(m.singular_off_integer, 1e-9);
  EXPECT_EQ(m.index_mismatch, 0.0);
  EXPECT_GT(m.singular, 0u);
}

// The pipeline form: one Tangent_bundle given to both steps gives the maps of
// the tm + np form, bit for bit; CGAL's members chain after the package's parameters.
TEST(IgmBundle, SameAsMeshForm)
{
  std::unique_ptr<Case> c = make_case("bumpy");
  Mesh& tm = c->tm;
  const PVF::Tangent_bundle<Mesh> bundle(tm);
  ASSERT_EQ(bundle.status(), PVF::Error_code::SUCCESS);
  auto a = tm.add_property_map<Halfedge, UV>("h:a").first;
  auto b = tm.add_property_map<Halfedge, UV>("h:b").first;
  PVF::Integer_grid_map_result ra, rb;
  ASSERT_EQ(PVF::compute_integer_grid_map(tm, c->field, a, ra,
                                          PVF::parameters::target_edge_length(0.5).vertex_point_map(tm.points())),
            PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::compute_integer_grid_map(bundle, c->field, b, rb, PVF::parameters::target_edge_length(0.5)),
            PVF::Error_code::SUCCESS);
  double worst = 0;
  for(Face f : faces(tm))
    for(Halfedge h : halfedges_around_face(halfedge(f, tm), tm))
      worst = (std::max)({ worst, std::abs(a[h][0] - b[h][0]), std::abs(a[h][1] - b[h][1]) });
  EXPECT_EQ(worst, 0.0);
  EXPECT_EQ(ra.target_edge_length, 0.5);
  EXPECT_EQ(ra.integer_unknowns, rb.integer_unknowns);
  EXPECT_EQ(rb.flipped_faces, 0u);
  EXPECT_GT(rb.comb.seam_curves, 0u);

  auto cut_a = tm.add_property_map<Mesh::Edge_index, bool>("e:cut_a").first;
  auto cut_b = tm.add_property_map<Mesh::Edge_index, bool>("e:cut_b").first;
  auto combed_a = tm.add_property_map<Face, std::array<Vector, 2> >("f:combed_a").first;
  auto combed_b = tm.add_property_map<Face, std::array<Vector, 2> >("f:combed_b").first;
  auto rot_a = tm.add_property_map<Halfedge, int>("h:rot_a").first;
  auto rot_b = tm.add_property_map<Halfedge, int>("h:rot_b").first;
  PVF::Comb_result ca, cb;
  ASSERT_EQ(PVF::comb_frame_field(tm, c->field, cut_a, combed_a, rot_a, ca), PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::comb_frame_field(bundle, c->field, cut_b, combed_b, rot_b, cb), PVF::Error_code::SUCCESS);
  std::size_t interior_cut = 0;
  for(auto e : edges(tm))
  {
    EXPECT_EQ(cut_a[e], cut_b[e]);
    interior_cut += cut_b[e] && !CGAL::is_border_edge(halfedge(e, tm), tm);
  }
  for(Halfedge h : halfedges(tm))
    if(!CGAL::is_border_edge(h, tm))
    {
      EXPECT_EQ(rot_a[h], rot_b[h]);
    }
  for(Face f : faces(tm))
    EXPECT_EQ(distance(combed_a[f][0], combed_b[f][0]) + distance(combed_a[f][1], combed_b[f][1]), 0.0);
  // the counts of the combing are those of the map's first stage
  EXPECT_EQ(cb.cut_edges, interior_cut);
  EXPECT_EQ(cb.cut_edges, rb.comb.cut_edges);
  EXPECT_EQ(cb.seam_curves, rb.comb.seam_curves);
  EXPECT_EQ(cb.singular_vertices, rb.comb.singular_vertices);
  EXPECT_EQ(cb.components, 1u);
  // bad parameters of the combing
  EXPECT_EQ(PVF::comb_frame_field(bundle, c->field, cut_b, combed_b, rot_b, cb, PVF::parameters::minimum_frame_angle(2.0)),
            PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::comb_frame_field(bundle, c->field, cut_b, combed_b, rot_b, cb,
                                  PVF::parameters::minimum_frame_angle(std::nan(""))),
            PVF::Error_code::NON_FINITE_VALUE);
}

// The VTK writer: the map cut open, one point per corner, every face positively oriented.
TEST(IgmOutput, VtkAndNonFiniteValues)
{
  Mesh tm = pvf_test::jittered_grid(5, 6, 2);
  auto field = tm.add_property_map<Face, std::vector<Complex> >("f:field").first;
  constant_field(tm, Vector(1, 0.2, 0), Vector(-0.1, 1, 0), field);
  auto uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  PVF::Integer_grid_map_result r;
  ASSERT_EQ(PVF::compute_integer_grid_map(tm, field, uv, r), PVF::Error_code::SUCCESS);
  const std::string file = "igm_test_output.vtk";
  ASSERT_EQ(PVF::IO::write_integer_grid_map_VTK(file, tm, uv), PVF::Error_code::SUCCESS);
  std::ifstream in(file);
  std::string line;
  std::size_t points = 0, positive = 0;
  bool orientation = false;
  while(std::getline(in, line))
  {
    if(line.rfind("POINTS ", 0) == 0)
      points = std::stoul(line.substr(7));
    else if(line.rfind("SCALARS uv_orientation", 0) == 0)
    {
      orientation = true;
      std::getline(in, line);  // LOOKUP_TABLE
    }
    else if(orientation)
      positive += line == "1";
  }
  in.close();
  EXPECT_EQ(points, 3 * num_faces(tm));
  EXPECT_EQ(positive, num_faces(tm));
  std::remove(file.c_str());
  // a NaN texture coordinate: refused, nothing written
  uv[halfedge(*faces(tm).begin(), tm)][0] = std::nan("");
  EXPECT_EQ(PVF::IO::write_integer_grid_map_VTK(file, tm, uv), PVF::Error_code::NON_FINITE_VALUE);
  EXPECT_EQ(PVF::IO::write_integer_grid_map_OBJ("igm_test_nan.obj", tm, uv), PVF::Error_code::NON_FINITE_VALUE);
  EXPECT_FALSE(std::ifstream(file).good());
  EXPECT_FALSE(std::ifstream("igm_test_nan.obj").good());
}

} // namespace

// ---------------------------------------------------------------------------
// Close singularities (issue 21): cancelled, merged or moved apart by the comb.
// ---------------------------------------------------------------------------

namespace {

// bumpy, with a frame field that has many close singularities: 60 random full constraints.
class IgmSingularities : public ::testing::Test
{
protected:
  void SetUp() override
  {
    tm = load("bumpy.off");
    field = tm.add_property_map<Face, std::vector<Complex> >("f:field").first;
    ASSERT_EQ(PVF::design_polyvector_field(tm, 4, random_constraints(tm, 60, 2, 11), field,
                                           PVF::parameters::sign_symmetric(true)),
              PVF::Error_code::SUCCESS);
  }
  Mesh tm;
  Mesh::Property_map<Face, std::vector<Complex> > field;
};

} // namespace

// A field with many close singularities: 60 random full constraints on bumpy.
// The comb with a separation distance of twice the mean edge must keep the sum
// of the indices, leave the counts it reports, and agree with the map: the index
// that the map shows at every interior vertex (read from the uv angles, not from
// the comb) is the comb's, and the map is seamless and has its singular corners
// on integer points.
TEST_F(IgmSingularities, CloseOnesAreCancelledMergedOrMovedApart)
{
  std::vector<PVF::Singularity<Vertex> > sings;
  ASSERT_EQ(PVF::compute_singularities(tm, 4, field, std::back_inserter(sings)), PVF::Error_code::SUCCESS);
  int field_sum = 0;
  for(const auto& s : sings)
    field_sum += s.index_numerator;
  double mean = 0;
  for(auto e : edges(tm))
    mean += CGAL::Polygon_mesh_processing::edge_length(e, tm);
  mean /= double(num_edges(tm));
  const double d = 2 * mean;

  typedef PVF::Tangent_bundle<Mesh> Bundle;
  const Bundle bundle(tm);
  PVF::Frame_field_comb<Bundle> kept, separated;
  ASSERT_EQ(PVF::comb_frame_field(bundle, field, kept), PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::comb_frame_field(bundle, field, separated, PVF::parameters::singularity_cancellation_distance(d)),
            PVF::Error_code::SUCCESS);
  const PVF::Comb_result& r = separated.report();
  EXPECT_EQ(kept.report().singular_vertices, sings.size());  // the default keeps them all
  EXPECT_EQ(kept.report().cancelled_singularity_pairs + kept.report().merged_singularity_pairs +
              kept.report().moved_singularities, 0u);
  ASSERT_GT(r.cancelled_singularity_pairs + r.merged_singularity_pairs, 0u) << "the case must exercise the cancellation";
  int comb_sum = 0;
  std::size_t comb_singular = 0;
  for(Vertex v : vertices(tm))
  {
    comb_sum += separated.index_numerator(v);
    comb_singular += separated.index_numerator(v) != 0;
    const int k = separated.index_numerator(v);
    EXPECT_TRUE(k >= -2 && k <= 1) << "a merged vertex of valence " << 4 - k;
  }
  EXPECT_EQ(comb_sum, field_sum);  // Poincare-Hopf is kept
  EXPECT_EQ(comb_singular, r.singular_vertices);
  EXPECT_EQ(comb_singular,
            sings.size() - 2 * r.cancelled_singularity_pairs - r.merged_singularity_pairs + r.split_singularities);

  auto uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  PVF::Integer_grid_map_result map;
  ASSERT_EQ(PVF::compute_integer_grid_map(separated, uv, map, PVF::parameters::target_edge_length(d)),
            PVF::Error_code::SUCCESS);
  EXPECT_EQ(map.inconsistencies, 0u);
  EXPECT_EQ(worst_seam_mismatch(tm, uv), 0.0);
  std::size_t mismatched = 0;
  double off_integer = 0;
  for(Vertex v : vertices(tm))
  {
    if(CGAL::is_border(v, tm))
      continue;
    bool next_to_flip = false;  // the angles of a flipped face do not tell the index
    for(auto h : halfedges_around_target(halfedge(v, tm), tm))
    {
      const UV a = uv[h], b = uv[next(h, tm)], c = uv[prev(h, tm)];
      next_to_flip |= !((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) > 0);
    }
    if(next_to_flip)
      continue;
    mismatched += std::abs(map_index(tm, uv, v) - separated.index_numerator(v)) > 1e-6;
    if(separated.index_numerator(v) != 0)
      for(auto h : halfedges_around_target(halfedge(v, tm), tm))
        off_integer = (std::max)({ off_integer, std::abs(uv[h][0] - std::round(uv[h][0])),
                                   std::abs(uv[h][1] - std::round(uv[h][1])) });
  }
  EXPECT_EQ(mismatched, 0u);
  EXPECT_EQ(off_integer, 0.0);
  std::printf("[ bumpy, 60 random constraints ] %zu field singularities -> %zu (cancelled %zu, merged %zu, moved %zu, "
              "split %zu); %zu flipped faces\n",
              sings.size(), r.singular_vertices, r.cancelled_singularity_pairs, r.merged_singularity_pairs,
              r.moved_singularities, r.split_singularities, map.flipped_faces);
  EXPECT_EQ(PVF::comb_frame_field(bundle, field, separated, PVF::parameters::singularity_cancellation_distance(-1.0)),
            PVF::Error_code::INVALID_PARAMETER);
}

// Singularities closer than half the separation distance to the border give
// their index to the border (a flat square with fields of 30 random
// constraints, distance 4 edges): none is left within that distance of a
// border vertex that could take it (on a straight border, for an index of
// +-1/4, every one but the four corners), the border vertices have index 0,
// and the map of the comb is seamless.
TEST(IgmBorderSingularities, CloseToTheBorderMoveOntoIt)
{
  const Mesh tm = grid(24, 24);
  const double d = 4;  // edges of the grid have length 1 or sqrt(2)
  // the distance along edges from each vertex to the nearest border vertex that is not a corner of the square
  std::map<Vertex, double> to_border;
  std::vector<std::pair<double, Vertex> > queue;
  auto corner = [&](Vertex v) {
    const Point& p = tm.point(v);
    return (p.x() == 0 || p.x() == 24) && (p.y() == 0 || p.y() == 24);
  };
  for(Vertex v : vertices(tm))
    if(CGAL::is_border(v, tm) && !corner(v))
      queue.emplace_back(0.0, v);
  std::make_heap(queue.begin(), queue.end(), std::greater<>());
  while(!queue.empty())
  {
    std::pop_heap(queue.begin(), queue.end(), std::greater<>());
    const auto [dv, v] = queue.back();
    queue.pop_back();
    if(to_border.count(v))
      continue;
    to_border[v] = dv;
    for(auto h : halfedges_around_target(halfedge(v, tm), tm))
      if(!to_border.count(source(h, tm)))
      {
        queue.emplace_back(dv + std::sqrt(CGAL::squared_distance(tm.point(v), tm.point(source(h, tm)))), source(h, tm));
        std::push_heap(queue.begin(), queue.end(), std::greater<>());
      }
  }
  std::size_t moved = 0;
  for(unsigned seed : { 5u, 6u, 7u, 8u })
  {
    Mesh mesh = tm;
    auto field = mesh.add_property_map<Face, std::vector<Complex> >("f:field").first;
    ASSERT_EQ(PVF::design_polyvector_field(mesh, 4, random_constraints(mesh, 30, 2, seed), field,
                                           PVF::parameters::sign_symmetric(true)),
              PVF::Error_code::SUCCESS);
    typedef PVF::Tangent_bundle<Mesh> Bundle;
    const Bundle bundle(mesh);
    PVF::Frame_field_comb<Bundle> kept, separated;
    ASSERT_EQ(PVF::comb_frame_field(bundle, field, kept), PVF::Error_code::SUCCESS);
    ASSERT_EQ(PVF::comb_frame_field(bundle, field, separated, PVF::parameters::singularity_cancellation_distance(d)),
              PVF::Error_code::SUCCESS);
    const PVF::Comb_result& r = separated.report();
    moved += r.singularities_moved_to_border;
    std::size_t near = 0, near_before = 0;
    for(Vertex v : vertices(mesh))
    {
      if(CGAL::is_border(v, mesh))
      {
        EXPECT_EQ(separated.index_numerator(v), 0) << seed;
        continue;
      }
      near_before += kept.index_numerator(v) != 0 && to_border[v] < d / 2;
      near += separated.index_numerator(v) != 0 && to_border[v] < d / 2;
    }
    EXPECT_EQ(near, 0u) << seed;
    EXPECT_GE(near_before, r.singularities_moved_to_border) << seed;
    auto uv = mesh.add_property_map<Halfedge, UV>("h:uv").first;
    PVF::Integer_grid_map_result map;
    ASSERT_EQ(PVF::compute_integer_grid_map(separated, uv, map, PVF::parameters::target_edge_length(d)),
              PVF::Error_code::SUCCESS);
    EXPECT_EQ(map.inconsistencies, 0u);
    EXPECT_EQ(worst_seam_mismatch(mesh, uv), 0.0);
    std::printf("[ flat square, 30 random constraints, seed %u ] %zu singularities near the border, %zu moved onto "
                "it; %zu flipped faces\n", seed, near_before, r.singularities_moved_to_border, map.flipped_faces);
  }
  ASSERT_GT(moved, 0u) << "the cases must exercise the move onto the border";
}

// Two singular vertices joined by one edge a little longer than the separation
// distance (a coarse mesh: no path between them is shorter than that edge)
// may round to the same integer point, and fold every face between them: the
// comb pairs them too. The case: an edge of length L between two singular
// vertices that no other singular vertex comes within L of; with the distance
// L / 1.2, the pair is only found through its edge.
TEST_F(IgmSingularities, NeighboursJoinedByALongEdgeArePaired)
{
  typedef PVF::Tangent_bundle<Mesh> Bundle;
  const Bundle bundle(tm);
  PVF::Frame_field_comb<Bundle> kept;
  ASSERT_EQ(PVF::comb_frame_field(bundle, field, kept), PVF::Error_code::SUCCESS);
  std::vector<Vertex> singular;
  for(Vertex v : vertices(tm))
    if(kept.index_numerator(v) != 0 && !CGAL::is_border(v, tm))
      singular.push_back(v);
  // an isolated pair: no third singular vertex within L (Euclidean, so none along edges either)
  Vertex a, b;
  double L = 0;
  for(auto e : edges(tm))
  {
    const Vertex s = source(halfedge(e, tm), tm), t = target(halfedge(e, tm), tm);
    if(kept.index_numerator(s) == 0 || kept.index_numerator(t) == 0 || CGAL::is_border(s, tm) || CGAL::is_border(t, tm))
      continue;
    const double length = CGAL::Polygon_mesh_processing::edge_length(e, tm);
    bool isolated = true;
    for(Vertex w : singular)
      if(w != s && w != t &&
         (std::sqrt(CGAL::squared_distance(tm.point(w), tm.point(s))) <= length ||
          std::sqrt(CGAL::squared_distance(tm.point(w), tm.point(t))) <= length))
        isolated = false;
    if(isolated && kept.index_numerator(s) + kept.index_numerator(t) >= -2 && kept.index_numerator(s) + kept.index_numerator(t) <= 1)
    {
      a = s;
      b = t;
      L = length;
      break;
    }
  }
  ASSERT_GT(L, 0.0) << "the case must have two neighbouring singular vertices apart from the others";
  PVF::Frame_field_comb<Bundle> separated;
  ASSERT_EQ(PVF::comb_frame_field(bundle, field, separated, PVF::parameters::singularity_cancellation_distance(L / 1.2)),
            PVF::Error_code::SUCCESS);
  // cancelled or merged: one of the two is regular now, and the index sum is kept
  EXPECT_TRUE(separated.index_numerator(a) == 0 || separated.index_numerator(b) == 0)
    << "indices " << separated.index_numerator(a) << " and " << separated.index_numerator(b);
  EXPECT_EQ(separated.index_numerator(a) + separated.index_numerator(b),
            kept.index_numerator(a) + kept.index_numerator(b));
}

namespace {

// The largest rotation, over the interior edges, from a face's combed frame
// transported across the edge to the frame of the other face as the comb
// matches them (rotation(h) quarter turns on a seam, none elsewhere): the mean
// of the rotations of u and of v, the angle that the principal matching keeps
// within 45 degrees.
template <typename Comb>
double largest_frame_mismatch(const Comb& comb)
{
  double largest = 0;
  for(const auto& e : comb.bundle().interior_edges())
  {
    const auto a = comb.combed_frame(e.f), b = comb.combed_frame(e.g);
    const int r = comb.rotation(e.h);
    const std::array<Complex, 4> roots_g = { b[0], b[1], -b[0], -b[1] };
    double mean = 0;
    for(int k = 0; k < 2; ++k)
      mean += std::arg(roots_g[std::size_t((r + k) % 4)] / (a[std::size_t(k)] * std::conj(e.e_f) * e.e_g)) / 2;
    largest = (std::max)(largest, std::abs(mean));
  }
  return largest;
}

} // namespace

// Cancelling, merging or moving a singularity changes the matching by whole
// quarter turns along a path of edges. The frames must follow: a frame left
// as it was disagrees with its neighbour across each edge of the path by about
// a quarter turn, and the map it guides shears along the whole path (on the
// corpus: 112 flipped faces of the map on cow.off instead of 40). The comb
// turns the frames near the path so that the quarter turn is spread over
// many edges. The bar: no edge mismatched by 60 degrees or more, while a
// frame that did not turn would be mismatched by 90 degrees minus the field's
// own mismatch across that edge, which is at most 45 degrees for the
// principal matching (the comb without separation checks that).
TEST_F(IgmSingularities, FramesFollowTheMatchingChangedByTheSeparation)
{
  double mean = 0;
  for(auto e : edges(tm))
    mean += CGAL::Polygon_mesh_processing::edge_length(e, tm);
  mean /= double(num_edges(tm));
  typedef PVF::Tangent_bundle<Mesh> Bundle;
  const Bundle bundle(tm);
  PVF::Frame_field_comb<Bundle> kept, separated;
  ASSERT_EQ(PVF::comb_frame_field(bundle, field, kept), PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::comb_frame_field(bundle, field, separated, PVF::parameters::singularity_cancellation_distance(2 * mean)),
            PVF::Error_code::SUCCESS);
  const PVF::Comb_result& r = separated.report();
  ASSERT_GT(r.cancelled_singularity_pairs + r.merged_singularity_pairs + r.moved_singularities, 0u);
  EXPECT_EQ(kept.report().turned_frames, 0u);
  EXPECT_GT(r.turned_frames, 0u);
  const double kept_mismatch = largest_frame_mismatch(kept), separated_mismatch = largest_frame_mismatch(separated);
  std::printf("[ bumpy, 60 random constraints ] largest frame mismatch: %g degrees without separation, %g with "
              "(%zu frames turned)\n",
              kept_mismatch * 180 / pi, separated_mismatch * 180 / pi, r.turned_frames);
  EXPECT_LE(kept_mismatch, pi / 4 + 1e-9);
  EXPECT_LT(separated_mismatch, pi / 3);
}
