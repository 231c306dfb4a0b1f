// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Tests of extract_quad_mesh(), quad_planarity(), planarize_quad_mesh() and
// IO::write_quad_mesh_VTK() (issue 13), and of maps aligned with the boundary and
// the mesh edges, and of folded quads (issue 21). Every property is checked by code
// written here (own planarity formula, own AABB-tree distances, own lattice
// and valence counts), from the outputs only. Everything but the tests is in
// an anonymous namespace with Quad/quad names and the suites are named Quad*,
// so that the file shares no name with the other test files.

#include "test_meshes.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>
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
#include <CGAL/Polyvector_fields/comb_frame_field.h>
#include <CGAL/Polyvector_fields/compute_integer_grid_map.h>

#include <CGAL/Polyvector_fields/IO/quad_mesh.h>
#include <CGAL/Polyvector_fields/extract_quad_mesh.h>
#include <CGAL/Polyvector_fields/planarize_quad_mesh.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>

namespace {

namespace PVF = CGAL::Polyvector_fields;
using namespace pvf_test;  // Mesh, Vector, Point, Kernel, pi, load, data, grid, euler_characteristic, ...
typedef Mesh::Face_index Face;
typedef Mesh::Halfedge_index Halfedge;
typedef Mesh::Vertex_index Vertex;
typedef std::complex<double> Complex;
typedef std::array<double, 2> UV;
typedef PVF::Face_constraint<Face, Vector> Constraint;
typedef Mesh::Property_map<Halfedge, UV> Quad_uv_map;

// ---------------------------------------------------------------------------
// Independent measures
// ---------------------------------------------------------------------------
// distance between the two diagonals over their mean length, written out here
double quad_reference_planarity(const Point& p0, const Point& p1, const Point& p2, const Point& p3)
{
  const Vector d1 = p2 - p0, d2 = p3 - p1;
  const Vector n = CGAL::cross_product(d1, d2);
  const double mean = 0.5 * (std::sqrt(d1.squared_length()) + std::sqrt(d2.squared_length()));
  return std::abs(n * (p1 - p0)) / std::sqrt(n.squared_length()) / mean;
}

struct Quad_checks
{
  bool valid = false, all_quads = true, closed = true;
  std::size_t components = 0, irregular = 0, irregular_off_singularity = 0, singular_wrong_valence = 0, singular_seen = 0;
  int chi = 0;
  double max_planarity = 0, mean_planarity = 0, mean_edge = 0;
};

// singular: mesh vertex position -> index numerator (a singular vertex is an integer point
// at a mesh vertex, so its position is copied exactly)
Quad_checks quad_checks(const Mesh& qm, const std::map<std::array<double, 3>, int>& singular = {})
{
  Quad_checks c;
  c.valid = CGAL::is_valid_polygon_mesh(qm);
  auto fcc = const_cast<Mesh&>(qm).add_property_map<Face, std::size_t>("f:test_cc").first;
  c.components = CGAL::Polygon_mesh_processing::connected_components(qm, fcc);
  const_cast<Mesh&>(qm).remove_property_map(fcc);
  c.chi = euler_characteristic(qm);
  for(Halfedge h : halfedges(qm))
    c.closed = c.closed && !CGAL::is_border(h, qm);
  double sum = 0;
  for(Face f : faces(qm))
  {
    std::vector<Point> p;
    for(Halfedge h : halfedges_around_face(halfedge(f, qm), qm))
      p.push_back(qm.point(target(h, qm)));
    if(p.size() != 4)
    {
      c.all_quads = false;
      continue;
    }
    const double q = quad_reference_planarity(p[0], p[1], p[2], p[3]);
    c.max_planarity = (std::max)(c.max_planarity, q);
    sum += q;
  }
  c.mean_planarity = sum / double(num_faces(qm));
  double el = 0;
  for(auto e : edges(qm))
    el += std::sqrt(CGAL::squared_distance(qm.point(source(halfedge(e, qm), qm)), qm.point(target(halfedge(e, qm), qm))));
  c.mean_edge = el / double(num_edges(qm));
  for(Vertex v : vertices(qm))
  {
    if(CGAL::is_border(v, qm))
      continue;
    std::size_t valence = 0;
    for(Halfedge h : halfedges_around_target(halfedge(v, qm), qm))
    {
      (void)h;
      ++valence;
    }
    const Point& p = qm.point(v);
    auto it = singular.find({ p.x(), p.y(), p.z() });
    if(it != singular.end())
    {
      ++c.singular_seen;
      c.singular_wrong_valence += int(valence) != 4 - it->second;
    }
    if(valence != 4)
    {
      ++c.irregular;
      c.irregular_off_singularity += it == singular.end();
    }
  }
  return c;
}

double quad_max_distance_to(const Mesh& surface, const Mesh& qm)
{
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive> > Tree;
  Tree tree(faces(surface).first, faces(surface).second, surface);
  double d = 0;
  for(Vertex v : vertices(qm))
    d = (std::max)(d, std::sqrt(tree.squared_distance(qm.point(v))));
  return d;
}

// ---------------------------------------------------------------------------
// Fields and maps of the measured runs (package API + igm prototype)
// ---------------------------------------------------------------------------

struct Quad_case
{
  std::string name;
  Mesh tm;
  Quad_uv_map uv;
  std::map<std::array<double, 3>, int> singular;
  std::size_t singularities = 0;
};

std::unique_ptr<Quad_case> make_quad_case(const std::string& name)
{
  auto c = std::make_unique<Quad_case>();
  c->name = name;
  const bool inspired = name.rfind("inspired", 0) == 0;
  c->tm = load(inspired ? "inspired_mesh.obj" : name + ".off");
  Mesh& tm = c->tm;
  std::vector<Constraint> constraints;
  auto curvatures = tm.add_property_map<Face, PVF::Principal_curvatures<Vector> >("f:k").first;
  double h = -1;
  if(inspired)
  {
    EXPECT_EQ(PVF::IO::read_dmat_constraints(data("inspired_mesh_b.dmat"), data("inspired_mesh_bc.dmat"), tm, constraints),
              PVF::Error_code::SUCCESS);
    h = 0.82;
  }
  else if(name == "fandisk")
    constraints = pvf_test::sharp_edge_constraints(tm, 30);
  else
  {
    EXPECT_EQ(PVF::estimate_principal_curvatures(tm, curvatures), PVF::Error_code::SUCCESS);
    EXPECT_EQ(PVF::select_curvature_constraints(tm, curvatures, constraints, PVF::parameters::constrained_fraction(0.01)),
              PVF::Error_code::SUCCESS);
  }
  auto field = tm.add_property_map<Face, std::vector<Complex> >("f:field").first;
  EXPECT_EQ(PVF::design_polyvector_field(tm, 4, constraints, field, PVF::parameters::sign_symmetric(true)), PVF::Error_code::SUCCESS);
  if(name == "inspired_conjugate")
  {
    // the current default stopping rule (Conjugacy_stopping_rule::MEAN_DEVIATION)
    EXPECT_EQ(PVF::estimate_principal_curvatures(tm, curvatures), PVF::Error_code::SUCCESS);
    PVF::Conjugate_field_result r;
    EXPECT_EQ(PVF::design_conjugate_frame_field(tm, constraints, field, r, PVF::parameters::principal_curvature_map(curvatures)),
              PVF::Error_code::SUCCESS);
  }
  if(name == "inspired_conjugate_rs")
  {
    // the paper's rule, with which the prototype was measured
    EXPECT_EQ(PVF::estimate_principal_curvatures(tm, curvatures), PVF::Error_code::SUCCESS);
    PVF::Conjugate_field_result r;
    EXPECT_EQ(PVF::design_conjugate_frame_field(
                tm, constraints, field, r,
                PVF::parameters::principal_curvature_map(
                  curvatures, PVF::parameters::stopping_rule(PVF::Conjugacy_stopping_rule::RESIDUAL_SUM))),
              PVF::Error_code::SUCCESS);
  }
  std::vector<PVF::Singularity<Vertex> > sings;
  EXPECT_EQ(PVF::compute_singularities(tm, 4, field, std::back_inserter(sings)), PVF::Error_code::SUCCESS);
  for(const auto& s : sings)
  {
    const Point& p = tm.point(s.vertex);
    c->singular[{ p.x(), p.y(), p.z() }] = s.index_numerator;
  }
  c->singularities = sings.size();
  c->uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  PVF::Integer_grid_map_result r;
  if(h > 0)
    EXPECT_EQ(PVF::compute_integer_grid_map(tm, field, c->uv, r, PVF::parameters::target_edge_length(h)), PVF::Error_code::SUCCESS);
  else
    EXPECT_EQ(PVF::compute_integer_grid_map(tm, field, c->uv, r), PVF::Error_code::SUCCESS);
  return c;
}

// a constant frame field {u, v} (world vectors) in every face
void quad_constant_field(const Mesh& tm, const Vector& u, const Vector& v, Mesh::Property_map<Face, std::vector<Complex> > field)
{
  for(Face f : faces(tm))
  {
    PVF::Face_frame fr;
    ASSERT_EQ(PVF::face_frame(f, tm, fr), PVF::Error_code::SUCCESS);
    field[f] = PVF::sign_symmetric_polyvector_coefficients({ fr.to_complex(u.x(), u.y(), u.z()), fr.to_complex(v.x(), v.y(), v.z()) });
  }
}

// sorted vertex positions and faces (as sorted position lists, cyclically normalised)
typedef std::array<double, 3> Quad_P3;
std::pair<std::vector<Quad_P3>, std::vector<std::vector<Quad_P3> > > quad_signature(const Mesh& qm)
{
  std::vector<Quad_P3> V;
  for(Vertex v : vertices(qm))
    V.push_back({ qm.point(v).x(), qm.point(v).y(), qm.point(v).z() });
  std::sort(V.begin(), V.end());
  std::vector<std::vector<Quad_P3> > F;
  for(Face f : faces(qm))
  {
    std::vector<Quad_P3> poly;
    for(Halfedge h : halfedges_around_face(halfedge(f, qm), qm))
      poly.push_back({ qm.point(target(h, qm)).x(), qm.point(target(h, qm)).y(), qm.point(target(h, qm)).z() });
    std::rotate(poly.begin(), std::min_element(poly.begin(), poly.end()), poly.end());
    F.push_back(poly);
  }
  std::sort(F.begin(), F.end());
  return { V, F };
}

// ---------------------------------------------------------------------------
// Flat plane
// ---------------------------------------------------------------------------

// uv = s (x, y) given exactly: integer points at vertices, on edges, in faces; iso-lines
// along mesh edges and through vertices (the degenerate cases of the tracing).
} // namespace

TEST(QuadFlatPlane, ExactMapWithIsoLinesAlongEdges)
{
  for(int s : { 1, 2, 3 })
  {
    Mesh tm = grid(5, 7);
    auto uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
    for(Halfedge h : halfedges(tm))
      if(!CGAL::is_border(h, tm))
        uv[h] = { s * tm.point(target(h, tm)).x(), s * tm.point(target(h, tm)).y() };
    Mesh qm;
    PVF::Quad_extraction_result r;
    ASSERT_EQ(PVF::extract_quad_mesh(tm, uv, qm, r), PVF::Error_code::SUCCESS) << r.diagnostic;
    const Quad_checks c = quad_checks(qm);
    EXPECT_TRUE(c.valid);
    EXPECT_TRUE(c.all_quads);
    EXPECT_EQ(num_faces(qm), std::size_t(35 * s * s));
    EXPECT_EQ(num_vertices(qm), std::size_t((5 * s + 1) * (7 * s + 1)));
    EXPECT_EQ(c.irregular, 0u);
    EXPECT_EQ(c.components, 1u);
    EXPECT_LT(c.max_planarity, 1e-15);
    // every vertex exactly on the lattice (1/s) Z^2, every edge of length 1/s
    for(Vertex v : vertices(qm))
    {
      const Point& p = qm.point(v);
      EXPECT_NEAR(p.x() * s, std::round(p.x() * s), 1e-12);
      EXPECT_NEAR(p.y() * s, std::round(p.y() * s), 1e-12);
      EXPECT_EQ(p.z(), 0.0);
    }
    for(auto e : edges(qm))
      EXPECT_NEAR(std::sqrt(CGAL::squared_distance(qm.point(source(halfedge(e, qm), qm)), qm.point(target(halfedge(e, qm), qm)))),
                  1.0 / s, 1e-12);
  }
}

// A vertex that no face uses has no iso-line directions: the check of the points off
// the integer grid passes over it (it took it for a singular point with 0 directions,
// NOT_AN_INTEGER_GRID_MAP), and the quads are those of the mesh without it.
TEST(QuadFlatPlane, IsolatedVertexIsIgnored)
{
  for(const bool trimmed : { false, true })
  {
    Mesh tm = grid(5, 7);
    auto uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
    for(Halfedge h : halfedges(tm))
      if(!CGAL::is_border(h, tm))
        uv[h] = { 2 * tm.point(target(h, tm)).x(), 2 * tm.point(target(h, tm)).y() };
    Mesh reference;
    PVF::Quad_extraction_result r0;
    ASSERT_EQ(PVF::extract_quad_mesh(tm, uv, reference, r0, PVF::parameters::keep_trimmed_boundary(trimmed)),
              PVF::Error_code::SUCCESS)
      << r0.diagnostic;
    // inside the grid's bounding box, and far from it
    for(const Point& p : { Point(2.5, 3.5, 0), Point(100, -50, 7) })
    {
      Mesh with = tm;
      with.add_vertex(p);
      auto uv_with = with.property_map<Halfedge, UV>("h:uv").first;
      Mesh qm;
      PVF::Quad_extraction_result r;
      ASSERT_EQ(PVF::extract_quad_mesh(with, uv_with, qm, r, PVF::parameters::keep_trimmed_boundary(trimmed)),
                PVF::Error_code::SUCCESS)
        << r.diagnostic << (trimmed ? " (trimmed)" : "");
      EXPECT_EQ(num_faces(qm), num_faces(reference));
      EXPECT_EQ(num_vertices(qm), num_vertices(reference));
      EXPECT_EQ(r.singular_points, 0u);
      EXPECT_EQ(quad_signature(qm), quad_signature(reference));
    }
  }
}

namespace {

// The full pipeline: constant field on a jittered grid -> integer-grid map -> quads.
// Expected: the exact lattice of whole cells inside the rectangle, planarity 0.
void quad_constant_field_grid(const Vector& u0, const Vector& v0, double h)
{
  const int rows = 9, cols = 13;
  Mesh tm = pvf_test::jittered_grid(rows, cols, 3);
  auto field = tm.add_property_map<Face, std::vector<Complex> >("f:field").first;
  quad_constant_field(tm, u0, v0, field);
  auto uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  PVF::Integer_grid_map_result ir;
  ASSERT_EQ(PVF::compute_integer_grid_map(tm, field, uv, ir, PVF::parameters::target_edge_length(h)), PVF::Error_code::SUCCESS);
  Mesh qm;
  PVF::Quad_extraction_result r;
  ASSERT_EQ(PVF::extract_quad_mesh(tm, uv, qm, r), PVF::Error_code::SUCCESS) << r.diagnostic;
  const Quad_checks c = quad_checks(qm);
  EXPECT_TRUE(c.valid);
  EXPECT_TRUE(c.all_quads);
  EXPECT_EQ(c.irregular, 0u);
  EXPECT_EQ(c.components, 1u);
  EXPECT_LT(c.max_planarity, 1e-12);
  // the affine map uv(p) from one face of the map (it is global: flat, constant field)
  const Halfedge h0 = halfedge(*faces(tm).begin(), tm);
  const Point a = tm.point(target(h0, tm)), b = tm.point(target(next(h0, tm), tm)), cc = tm.point(target(prev(h0, tm), tm));
  const UV ua = uv[h0], ub = uv[next(h0, tm)], uc = uv[prev(h0, tm)];
  // [uv] = L [p - a] + ua
  const double det = (b.x() - a.x()) * (cc.y() - a.y()) - (b.y() - a.y()) * (cc.x() - a.x());
  double L[2][2];
  for(int k = 0; k < 2; ++k)
  {
    const double du1 = ub[k] - ua[k], du2 = uc[k] - ua[k];
    L[k][0] = (du1 * (cc.y() - a.y()) - du2 * (b.y() - a.y())) / det;
    L[k][1] = (du2 * (b.x() - a.x()) - du1 * (cc.x() - a.x())) / det;
  }
  auto map = [&](double x, double y) {
    return UV{ L[0][0] * (x - a.x()) + L[0][1] * (y - a.y()) + ua[0], L[1][0] * (x - a.x()) + L[1][1] * (y - a.y()) + ua[1] };
  };
  const double ldet = L[0][0] * L[1][1] - L[0][1] * L[1][0];
  auto inverse = [&](double u, double v) {
    const double du = u - ua[0], dv = v - ua[1];
    return std::array<double, 2>{ a.x() + (L[1][1] * du - L[0][1] * dv) / ldet, a.y() + (-L[1][0] * du + L[0][0] * dv) / ldet };
  };
  // vertices: integer in uv
  for(Vertex v : vertices(qm))
  {
    const UV w = map(qm.point(v).x(), qm.point(v).y());
    EXPECT_NEAR(w[0], std::round(w[0]), 1e-9);
    EXPECT_NEAR(w[1], std::round(w[1]), 1e-9);
  }
  // the whole cells: [i, i+1] x [j, j+1] with all 4 corners inside the rectangle
  double lo[2] = { 1e300, 1e300 }, hi[2] = { -1e300, -1e300 };
  for(double x : { 0.0, double(cols) })
    for(double y : { 0.0, double(rows) })
    {
      const UV w = map(x, y);
      for(int k = 0; k < 2; ++k)
      {
        lo[k] = (std::min)(lo[k], w[k]);
        hi[k] = (std::max)(hi[k], w[k]);
      }
    }
  std::size_t cells = 0;
  auto inside = [&](double u, double v) {
    const auto p = inverse(u, v);
    return p[0] >= -1e-9 && p[0] <= cols + 1e-9 && p[1] >= -1e-9 && p[1] <= rows + 1e-9;
  };
  for(double i = std::floor(lo[0]) - 1; i <= hi[0] + 1; ++i)
    for(double j = std::floor(lo[1]) - 1; j <= hi[1] + 1; ++j)
      cells += inside(i, j) && inside(i + 1, j) && inside(i, j + 1) && inside(i + 1, j + 1);
  EXPECT_EQ(num_faces(qm), cells);
  // edges: the images of unit uv steps
  const double lu = h, lv = h;  // one uv unit along a unit field direction is h
  for(auto e : edges(qm))
  {
    const double len = std::sqrt(CGAL::squared_distance(qm.point(source(halfedge(e, qm), qm)), qm.point(target(halfedge(e, qm), qm))));
    EXPECT_TRUE(std::abs(len - lu) < 1e-9 || std::abs(len - lv) < 1e-9) << len;
  }
}

} // namespace

// (turned by 0.1 rad so that no iso-line runs along the rectangle, where round-off would decide)
TEST(QuadFlatPlane, ConstantOrthogonalField) { quad_constant_field_grid(Vector(std::cos(0.1), std::sin(0.1), 0), Vector(-std::sin(0.1), std::cos(0.1), 0), 0.7); }
TEST(QuadFlatPlane, ConstantSkewedField) { quad_constant_field_grid(Vector(std::cos(0.3), std::sin(0.3), 0), Vector(std::cos(0.3 + pi / 3), std::sin(0.3 + pi / 3), 0), 0.45); }

// ---------------------------------------------------------------------------
// Closed meshes: bumpy (sphere), eight (genus 2), fandisk (sharp edges)
// ---------------------------------------------------------------------------
namespace {
class QuadClosed : public ::testing::TestWithParam<std::string> {};
} // namespace

TEST_P(QuadClosed, AllQuadsSameEulerCharacteristic)
{
  std::unique_ptr<Quad_case> c = make_quad_case(GetParam());
  Mesh qm;
  PVF::Quad_extraction_result r;
  ASSERT_EQ(PVF::extract_quad_mesh(c->tm, c->uv, qm, r), PVF::Error_code::SUCCESS) << r.diagnostic;
  const Quad_checks q = quad_checks(qm, c->singular);
  EXPECT_TRUE(q.valid);
  EXPECT_TRUE(q.all_quads);
  EXPECT_TRUE(q.closed);
  EXPECT_EQ(q.chi, euler_characteristic(c->tm));
  EXPECT_EQ(q.components, 1u);
  EXPECT_EQ(q.irregular_off_singularity, 0u);
  EXPECT_EQ(q.singular_seen, c->singularities);
  EXPECT_EQ(q.singular_wrong_valence, 0u);
  EXPECT_EQ(r.inconsistencies, 0u);
}
INSTANTIATE_TEST_SUITE_P(Quad, QuadClosed, ::testing::Values("bumpy", "eight", "fandisk"));

// Re-gauging every face chart by its own grid symmetry R^r x + t keeps the map seamless
// (the transitions change): the quad mesh must be the same, bit for bit.
// The meshing road on one bundle: comb once, map that comb, extract with the
// map's exact transitions. The map of the comb is the map of the field; every
// transition maps the uv of its edge exactly (both endpoints) with the comb's
// rotation; the extraction that consumes them gives the mesh of the uv overload,
// vertex for vertex; transitions that disagree with the uv are refused.
TEST(QuadSeams, CombMapAndExtractionCarryTheSeams)
{
  Mesh tm = load("bumpy.off");
  auto curvatures = tm.add_property_map<Face, PVF::Principal_curvatures<Vector> >("f:k").first;
  std::vector<Constraint> constraints;
  ASSERT_EQ(PVF::estimate_principal_curvatures(tm, curvatures), PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::select_curvature_constraints(tm, curvatures, constraints, PVF::parameters::constrained_fraction(0.01)),
            PVF::Error_code::SUCCESS);
  auto field = tm.add_property_map<Face, std::vector<Complex> >("f:field").first;
  ASSERT_EQ(PVF::design_polyvector_field(tm, 4, constraints, field, PVF::parameters::sign_symmetric(true)),
            PVF::Error_code::SUCCESS);
  typedef PVF::Tangent_bundle<Mesh> Bundle;
  const Bundle bundle(tm);
  PVF::Frame_field_comb<Bundle> comb;
  ASSERT_FALSE(comb.is_valid());
  ASSERT_EQ(PVF::comb_frame_field(bundle, field, comb), PVF::Error_code::SUCCESS);
  ASSERT_TRUE(comb.is_valid());
  EXPECT_GT(comb.report().cut_edges, 0u);
  EXPECT_EQ(comb.number_of_seam_curves(), comb.report().seam_curves);

  auto uv = tm.add_property_map<Halfedge, UV>("h:road_uv").first;
  auto uv_field = tm.add_property_map<Halfedge, UV>("h:road_uv_field").first;
  PVF::Integer_grid_map_result map, map_field;
  ASSERT_EQ(PVF::compute_integer_grid_map(comb, uv, map), PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::compute_integer_grid_map(bundle, field, uv_field, map_field), PVF::Error_code::SUCCESS);
  EXPECT_EQ(map.inconsistencies, 0u);
  EXPECT_EQ(map.comb.cut_edges, comb.report().cut_edges);
  EXPECT_EQ(map.factorizations, map_field.factorizations);
  for(Halfedge h : halfedges(tm))
    if(!CGAL::is_border(h, tm))
      ASSERT_EQ(uv[h], uv_field[h]);

  // the transitions: exact on both endpoints, the comb's rotation, identity off the cut
  ASSERT_EQ(map.seam_transitions.size(), 3 * num_faces(tm));
  std::size_t translated = 0;
  for(Halfedge h : halfedges(tm))
  {
    if(CGAL::is_border_edge(h, tm))
      continue;
    const PVF::Seam_transition& T = map.seam_transitions[comb.corner(h)];
    ASSERT_EQ(T.rotation, comb.rotation(h));
    if(!comb.is_cut(h))
    {
      ASSERT_EQ(T.rotation, 0);
      ASSERT_EQ(T.translation[0], 0);
      ASSERT_EQ(T.translation[1], 0);
    }
    translated += T.translation[0] != 0 || T.translation[1] != 0;
    const Halfedge o = opposite(h, tm);
    // target(h) is seen by prev(o) in face(o); source(h) by o
    for(const auto& pair : { std::make_pair(h, prev(o, tm)), std::make_pair(prev(h, tm), o) })
    {
      Complex a(uv[pair.first][0], uv[pair.first][1]);
      for(int k = 0; k < T.rotation; ++k)
        a *= Complex(0, 1);
      ASSERT_EQ(a.real() + double(T.translation[0]), uv[pair.second][0]);
      ASSERT_EQ(a.imag() + double(T.translation[1]), uv[pair.second][1]);
    }
  }
  EXPECT_GT(translated, 0u);

  // extraction with the map's transitions = extraction from the uv, vertex for vertex
  Mesh from_map, from_uv;
  PVF::Quad_extraction_result rm, ru;
  ASSERT_EQ(PVF::extract_quad_mesh(bundle, uv, map, from_map, rm), PVF::Error_code::SUCCESS) << rm.diagnostic;
  ASSERT_EQ(PVF::extract_quad_mesh(tm, uv, from_uv, ru), PVF::Error_code::SUCCESS) << ru.diagnostic;
  EXPECT_GT(num_faces(from_map), 100u);
  ASSERT_EQ(num_vertices(from_map), num_vertices(from_uv));
  ASSERT_EQ(num_faces(from_map), num_faces(from_uv));
  for(Vertex v : vertices(from_map))
    ASSERT_EQ(from_map.point(v), from_uv.point(v));
  EXPECT_EQ(rm.seam_edges, ru.seam_edges);
  EXPECT_EQ(rm.integer_points, ru.integer_points);

  // a wrong translation, and transitions of another size, are refused
  PVF::Integer_grid_map_result wrong = map;
  for(PVF::Seam_transition& T : wrong.seam_transitions)
    if(T.translation[0] != 0)
    {
      T.translation[0] += 1;
      break;
    }
  Mesh refused;
  EXPECT_EQ(PVF::extract_quad_mesh(bundle, uv, wrong, refused, rm), PVF::Error_code::NOT_AN_INTEGER_GRID_MAP);
  EXPECT_FALSE(rm.diagnostic.empty());
  wrong.seam_transitions.pop_back();
  EXPECT_EQ(PVF::extract_quad_mesh(bundle, uv, wrong, refused, rm), PVF::Error_code::NOT_AN_INTEGER_GRID_MAP);
  EXPECT_EQ(num_faces(refused), 0u);
  // an invalid comb is refused by the map
  PVF::Frame_field_comb<Bundle> empty;
  EXPECT_EQ(PVF::compute_integer_grid_map(empty, uv, map), PVF::Error_code::INVALID_PARAMETER);
}

TEST(QuadSeams, ChartRegaugingGivesTheSameMesh)
{
  std::unique_ptr<Quad_case> c = make_quad_case("bumpy");
  Mesh q1, q2;
  PVF::Quad_extraction_result r1, r2;
  ASSERT_EQ(PVF::extract_quad_mesh(c->tm, c->uv, q1, r1), PVF::Error_code::SUCCESS);
  auto uv2 = c->tm.add_property_map<Halfedge, UV>("h:uv2").first;
  std::mt19937 rng(11);
  for(Face f : faces(c->tm))
  {
    const int r = int(rng() % 4);
    const double tx = double(int(rng() % 41) - 20), ty = double(int(rng() % 41) - 20);
    for(Halfedge h : halfedges_around_face(halfedge(f, c->tm), c->tm))
    {
      UV p = c->uv[h];
      for(int k = 0; k < r; ++k)
        p = { -p[1], p[0] };
      uv2[h] = { p[0] + tx, p[1] + ty };
    }
  }
  ASSERT_EQ(PVF::extract_quad_mesh(c->tm, uv2, q2, r2), PVF::Error_code::SUCCESS) << r2.diagnostic;
  EXPECT_GT(r2.seam_edges, r1.seam_edges);
  EXPECT_TRUE(quad_signature(q1) == quad_signature(q2));
}

// ---------------------------------------------------------------------------
// inspired_mesh with its 84 constraints, h = 0.82
// ---------------------------------------------------------------------------
namespace {

struct Quad_inspired
{
  std::unique_ptr<Quad_case> c;
  Mesh qm, planar;
  Quad_checks before, after;
  PVF::Quad_extraction_result xr;
  PVF::Planarization_result pr;
  PVF::Error_code extraction = PVF::Error_code::SUCCESS, planarization = PVF::Error_code::SUCCESS;
  double distance = 0;
};

const Quad_inspired& quad_inspired(const std::string& name)
{
  static std::map<std::string, std::unique_ptr<Quad_inspired> > cache;
  auto& slot = cache[name];
  if(!slot)
  {
    slot = std::make_unique<Quad_inspired>();
    slot->c = make_quad_case(name);
    slot->extraction = PVF::extract_quad_mesh(slot->c->tm, slot->c->uv, slot->qm, slot->xr);
    slot->before = quad_checks(slot->qm, slot->c->singular);
    slot->planar = slot->qm;
    slot->planarization = PVF::planarize_quad_mesh(slot->planar, slot->c->tm, slot->pr);
    slot->after = quad_checks(slot->planar, slot->c->singular);
    slot->distance = quad_max_distance_to(slot->c->tm, slot->planar);
  }
  return *slot;
}

class QuadInspiredRuns : public ::testing::TestWithParam<std::string> {};

} // namespace

TEST_P(QuadInspiredRuns, ValidQuadsOneComponentRegular)
{
  const Quad_inspired& I = quad_inspired(GetParam());
  ASSERT_EQ(I.extraction, PVF::Error_code::SUCCESS) << I.xr.diagnostic;
  EXPECT_TRUE(I.before.valid);
  EXPECT_TRUE(I.before.all_quads);
  EXPECT_EQ(I.before.components, 1u);
  EXPECT_EQ(I.before.irregular_off_singularity, 0u);
  EXPECT_EQ(I.before.singular_wrong_valence, 0u);
  EXPECT_EQ(I.before.chi, euler_characteristic(I.c->tm));
  std::printf("   [%s] quads %zu, irregular %zu, planarity mean %.4f%% max %.4f%%\n", GetParam().c_str(), num_faces(I.qm),
              I.before.irregular, 100 * I.before.mean_planarity, 100 * I.before.max_planarity);
}

TEST_P(QuadInspiredRuns, PlanarizedWithinOnePercentAndCloseToTheSurface)
{
  const Quad_inspired& I = quad_inspired(GetParam());
  ASSERT_EQ(I.planarization, PVF::Error_code::SUCCESS);
  EXPECT_LE(I.after.max_planarity, 0.01 + 1e-12);
  EXPECT_LE(I.distance, 0.05 * I.before.mean_edge);
  EXPECT_TRUE(I.after.valid);
  EXPECT_EQ(num_faces(I.planar), num_faces(I.qm));
  // the result agrees with its own report
  EXPECT_NEAR(I.pr.max_planarity_after, I.after.max_planarity, 1e-12);
  std::printf("   [%s] after %zu iterations: max %.4f%% mean %.4f%%, distance %.4g = %.3f%% of the mean edge\n", GetParam().c_str(),
              I.pr.iterations, 100 * I.after.max_planarity, 100 * I.after.mean_planarity, I.distance,
              100 * I.distance / I.before.mean_edge);
}
INSTANTIATE_TEST_SUITE_P(Quad, QuadInspiredRuns, ::testing::Values("inspired", "inspired_conjugate", "inspired_conjugate_rs"));

TEST(QuadInspired, ConjugateFieldGivesMorePlanarQuads)
{
  const Quad_inspired& S = quad_inspired("inspired");
  for(const char* name : { "inspired_conjugate", "inspired_conjugate_rs" })
  {
    const Quad_inspired& C = quad_inspired(name);
    EXPECT_LT(C.before.mean_planarity, S.before.mean_planarity) << name;
    EXPECT_LE(C.before.mean_planarity, 0.0028) << name;  // the paper's 0.28%
  }
}

TEST(QuadInspired, TrimmedBoundaryKeepsTheWholeQuads)
{
  const Quad_inspired& S = quad_inspired("inspired");
  Mesh qm;
  PVF::Quad_extraction_result r;
  ASSERT_EQ(PVF::extract_quad_mesh(S.c->tm, S.c->uv, qm, r, PVF::parameters::keep_trimmed_boundary(true)), PVF::Error_code::SUCCESS)
      << r.diagnostic;
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(qm));
  EXPECT_EQ(r.quads, num_faces(S.qm));
  EXPECT_GT(num_faces(qm), num_faces(S.qm));
  EXPECT_EQ(euler_characteristic(qm), euler_characteristic(S.c->tm));
  // every border vertex of the output lies on the border of the input
  double worst = 0;
  for(Vertex v : vertices(qm))
  {
    if(!CGAL::is_border(v, qm))
      continue;
    double best = 1e300;
    for(Halfedge h : halfedges(S.c->tm))
      if(CGAL::is_border(h, S.c->tm))
      {
        const Kernel::Segment_3 s(S.c->tm.point(source(h, S.c->tm)), S.c->tm.point(target(h, S.c->tm)));
        best = (std::min)(best, std::sqrt(CGAL::squared_distance(qm.point(v), s)));
      }
    worst = (std::max)(worst, best);
  }
  EXPECT_LT(worst, 1e-9);
}

// ---------------------------------------------------------------------------
// Generic: Surface_mesh and Polyhedron_3 give the same quad mesh
// ---------------------------------------------------------------------------
TEST(QuadGeneric, SurfaceMeshAndPolyhedron)
{
  typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
  std::unique_ptr<Quad_case> c = make_quad_case("bumpy");
  Polyhedron P = load<Polyhedron>("bumpy.off");
  ASSERT_EQ(num_faces(P), num_faces(c->tm));
  // the same map, corner by corner: (face rank, vertex rank) -> uv
  std::map<std::pair<std::size_t, std::size_t>, UV> corner;
  {
    std::map<Vertex, std::size_t> vr;
    std::size_t i = 0;
    for(Vertex v : vertices(c->tm))
      vr[v] = i++;
    std::size_t f = 0;
    for(Face fa : faces(c->tm))
    {
      for(Halfedge h : halfedges_around_face(halfedge(fa, c->tm), c->tm))
        corner[{ f, vr[target(h, c->tm)] }] = c->uv[h];
      ++f;
    }
  }
  typedef boost::graph_traits<Polyhedron>::halfedge_descriptor PH;
  std::map<PH, UV> puv_storage;
  std::map<boost::graph_traits<Polyhedron>::vertex_descriptor, std::size_t> pvr;
  {
    std::size_t i = 0;
    for(auto v : vertices(P))
      pvr[v] = i++;
    std::size_t f = 0;
    for(auto fa : faces(P))
    {
      for(auto h : halfedges_around_face(halfedge(fa, P), P))
        puv_storage[h] = corner.at({ f, pvr[target(h, P)] });
      ++f;
    }
  }
  auto puv = boost::make_assoc_property_map(puv_storage);
  Mesh q1, q2;
  PVF::Quad_extraction_result r1, r2;
  ASSERT_EQ(PVF::extract_quad_mesh(c->tm, c->uv, q1, r1), PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::extract_quad_mesh(P, puv, q2, r2), PVF::Error_code::SUCCESS) << r2.diagnostic;
  ASSERT_EQ(num_vertices(q1), num_vertices(q2));
  ASSERT_EQ(num_faces(q1), num_faces(q2));
  // identical in order, not only as sets
  auto v1 = vertices(q1).begin(), v2 = vertices(q2).begin();
  for(; v1 != vertices(q1).end(); ++v1, ++v2)
    EXPECT_TRUE(q1.point(*v1) == q2.point(*v2));
  auto f1 = faces(q1).begin(), f2 = faces(q2).begin();
  for(; f1 != faces(q1).end(); ++f1, ++f2)
  {
    std::vector<std::size_t> a, b;
    for(Halfedge h : halfedges_around_face(halfedge(*f1, q1), q1))
      a.push_back(std::size_t(target(h, q1)));
    for(Halfedge h : halfedges_around_face(halfedge(*f2, q2), q2))
      b.push_back(std::size_t(target(h, q2)));
    EXPECT_EQ(a, b);
  }
}

// With CGAL::Parallel_tag the extraction computes the quad points, the first
// fold check of the quads and the distances of the input to the quads on
// several threads, each value on its own: the quad mesh and every count and
// distance of the result must be the same to the last bit as with
// CGAL::Sequential_tag. The maps have more quads and vertices than one range
// of that work (512 and 1024), so that several ranges run at once.
TEST(QuadGeneric, ParallelIsBitIdenticalToSequential)
{
  for(const std::string name : { "bumpy", "eight" })
  {
    std::unique_ptr<Quad_case> c = make_quad_case(name);
    Mesh sequential, parallel;
    PVF::Quad_extraction_result rs, rp;
    ASSERT_EQ(PVF::extract_quad_mesh<CGAL::Sequential_tag>(c->tm, c->uv, sequential, rs), PVF::Error_code::SUCCESS)
      << name << ": " << rs.diagnostic;
#ifdef CGAL_LINKED_WITH_TBB
    ASSERT_EQ(PVF::extract_quad_mesh<CGAL::Parallel_tag>(c->tm, c->uv, parallel, rp), PVF::Error_code::SUCCESS)
      << name << ": " << rp.diagnostic;
#else
    // CGAL::Parallel_tag needs TBB; the default tag is then sequential.
    ASSERT_EQ(PVF::extract_quad_mesh(c->tm, c->uv, parallel, rp), PVF::Error_code::SUCCESS) << name << ": " << rp.diagnostic;
#endif
    ASSERT_GT(rs.quads, 512u) << name;
    EXPECT_EQ(rs.quads, rp.quads) << name;
    EXPECT_EQ(rs.vertices, rp.vertices) << name;
    EXPECT_EQ(rs.singular_points, rp.singular_points) << name;
    EXPECT_EQ(rs.unfolded_quads, rp.unfolded_quads) << name;
    EXPECT_EQ(rs.moved_quad_vertices, rp.moved_quad_vertices) << name;
    EXPECT_EQ(rs.snapped_tips, rp.snapped_tips) << name;
    EXPECT_EQ(std::memcmp(&rs.largest_input_distance, &rp.largest_input_distance, sizeof(double)), 0)
      << name << ": " << rs.largest_input_distance << " against " << rp.largest_input_distance;
    ASSERT_EQ(num_vertices(sequential), num_vertices(parallel)) << name;
    ASSERT_EQ(num_faces(sequential), num_faces(parallel)) << name;
    std::size_t differing_points = 0, differing_faces = 0;
    auto v1 = vertices(sequential).begin(), v2 = vertices(parallel).begin();
    for(; v1 != vertices(sequential).end(); ++v1, ++v2)
    {
      const Point& a = sequential.point(*v1);
      const Point& b = parallel.point(*v2);
      const double x[3] = { a.x(), a.y(), a.z() }, y[3] = { b.x(), b.y(), b.z() };
      if(std::memcmp(x, y, sizeof(x)) != 0)
        ++differing_points;
    }
    auto f1 = faces(sequential).begin(), f2 = faces(parallel).begin();
    for(; f1 != faces(sequential).end(); ++f1, ++f2)
    {
      std::vector<std::size_t> a, b;
      for(Halfedge h : halfedges_around_face(halfedge(*f1, sequential), sequential))
        a.push_back(std::size_t(target(h, sequential)));
      for(Halfedge h : halfedges_around_face(halfedge(*f2, parallel), parallel))
        b.push_back(std::size_t(target(h, parallel)));
      if(a != b)
        ++differing_faces;
    }
    EXPECT_EQ(differing_points, 0u) << name;
    EXPECT_EQ(differing_faces, 0u) << name;
  }
}

// ---------------------------------------------------------------------------
// Fold-overs
// ---------------------------------------------------------------------------
TEST(QuadFoldOvers, LocalFoldIsRepaired)
{
  Mesh tm = grid(8, 8);
  auto uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  const double s = 1.5;
  for(Halfedge h : halfedges(tm))
    if(!CGAL::is_border(h, tm))
      uv[h] = { s * tm.point(target(h, tm)).x() + 0.25, s * tm.point(target(h, tm)).y() + 0.25 };
  Mesh ref;
  PVF::Quad_extraction_result r0;
  ASSERT_EQ(PVF::extract_quad_mesh(tm, uv, ref, r0), PVF::Error_code::SUCCESS);
  EXPECT_EQ(r0.flipped_faces, 0u);
  // push vertex (4, 4) past its neighbour (5, 5) in uv: its triangles fold over
  Vertex moved;
  for(Vertex v : vertices(tm))
    if(tm.point(v) == Point(4, 4, 0))
      moved = v;
  for(Halfedge h : halfedges_around_target(halfedge(moved, tm), tm))
    if(!CGAL::is_border(h, tm))
      uv[h] = { s * 5.6 + 0.25, s * 5.3 + 0.25 };
  std::size_t flipped = 0;
  for(Face f : faces(tm))
  {
    const Halfedge h = halfedge(f, tm);
    const UV a = uv[h], b = uv[next(h, tm)], c = uv[prev(h, tm)];
    flipped += (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) <= 0;
  }
  ASSERT_GT(flipped, 0u);
  Mesh qm;
  PVF::Quad_extraction_result r;
  ASSERT_EQ(PVF::extract_quad_mesh(tm, uv, qm, r), PVF::Error_code::SUCCESS) << r.diagnostic;
  EXPECT_EQ(r.flipped_faces, flipped);
  EXPECT_GE(r.repaired_regions, 1u);
  const Quad_checks c = quad_checks(qm);
  EXPECT_TRUE(c.valid);
  EXPECT_TRUE(c.all_quads);
  EXPECT_EQ(c.irregular, 0u);
  EXPECT_EQ(num_faces(qm), num_faces(ref));
  EXPECT_EQ(num_vertices(qm), num_vertices(ref));
}

// ---------------------------------------------------------------------------
// Planarity measure and planarizer
// ---------------------------------------------------------------------------
TEST(QuadPlanarity, ClosedForm)
{
  for(double z : { 0.0, 0.01, 0.3, 2.0 })
  {
    const std::array<double, 3> p0{ 0, 0, 0 }, p1{ 1, 0, 0 }, p2{ 1, 1, 0 }, p3{ 0, 1, z };
    const double expected = (z / std::sqrt(2 * z * z + 4)) / ((std::sqrt(2.0) + std::sqrt(2 + z * z)) / 2);
    EXPECT_NEAR(PVF::quad_planarity(p0, p1, p2, p3), expected, 1e-15);
    // invariant under a cyclic shift and a reversal of the vertex order
    EXPECT_NEAR(PVF::quad_planarity(p1, p2, p3, p0), expected, 1e-15);
    EXPECT_NEAR(PVF::quad_planarity(p3, p2, p1, p0), expected, 1e-15);
  }
}

TEST(QuadPlanarity, FaceMapAndStatistics)
{
  const Quad_inspired& S = quad_inspired("inspired");
  Mesh qm = S.qm;
  auto fp = qm.add_property_map<Face, double>("f:p").first;
  PVF::Planarity_result st;
  ASSERT_EQ(PVF::quad_planarity(qm, fp, st), PVF::Error_code::SUCCESS);
  double mx = 0;
  for(Face f : faces(qm))
  {
    std::vector<Point> p;
    for(Halfedge h : halfedges_around_face(halfedge(f, qm), qm))
      p.push_back(qm.point(target(h, qm)));
    EXPECT_NEAR(fp[f], quad_reference_planarity(p[0], p[1], p[2], p[3]), 1e-14);
    mx = (std::max)(mx, fp[f]);
  }
  EXPECT_NEAR(st.max, mx, 1e-15);
  EXPECT_EQ(st.faces, num_faces(qm));
}

TEST(QuadPlanarize, AlreadyPlanarNeedsNoIteration)
{
  Mesh tm = grid(4, 4);
  auto uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  for(Halfedge h : halfedges(tm))
    if(!CGAL::is_border(h, tm))
      uv[h] = { tm.point(target(h, tm)).x(), tm.point(target(h, tm)).y() };
  Mesh qm;
  PVF::Quad_extraction_result r;
  ASSERT_EQ(PVF::extract_quad_mesh(tm, uv, qm, r), PVF::Error_code::SUCCESS);
  const auto before = quad_signature(qm);
  PVF::Planarization_result pr;
  ASSERT_EQ(PVF::planarize_quad_mesh(qm, tm, pr), PVF::Error_code::SUCCESS);
  EXPECT_EQ(pr.iterations, 0u);
  EXPECT_TRUE(quad_signature(qm) == before);
}

// ---------------------------------------------------------------------------
// Bad input: an Error_code, and no output
// ---------------------------------------------------------------------------
namespace {

class QuadBadInput : public ::testing::Test
{
protected:
  void SetUp() override
  {
    tm = grid(4, 5);
    uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
    for(Halfedge h : halfedges(tm))
      if(!CGAL::is_border(h, tm))
        uv[h] = { 1.5 * tm.point(target(h, tm)).x() + 0.1, 1.5 * tm.point(target(h, tm)).y() + 0.2 };
    CGAL::make_triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), out);  // must stay untouched
  }
  PVF::Error_code extract()
  {
    PVF::Quad_extraction_result r;
    return PVF::extract_quad_mesh(tm, uv, out, r);
  }
  bool untouched() const { return num_faces(out) == 1 && num_vertices(out) == 3; }
  Mesh tm, out;
  Quad_uv_map uv;
};

} // namespace

TEST_F(QuadBadInput, NoMap)
{
  for(Halfedge h : halfedges(tm))
    uv[h] = { 0, 0 };
  EXPECT_EQ(extract(), PVF::Error_code::NOT_AN_INTEGER_GRID_MAP);
  EXPECT_TRUE(untouched());
}

TEST_F(QuadBadInput, NotSeamless)
{
  const Halfedge h = halfedge(*std::next(faces(tm).begin(), 7), tm);
  uv[h] = { uv[h][0] + 0.25, uv[h][1] };
  EXPECT_EQ(extract(), PVF::Error_code::NOT_AN_INTEGER_GRID_MAP);
  EXPECT_TRUE(untouched());
}

TEST_F(QuadBadInput, NonFiniteValue)
{
  const Halfedge h = halfedge(*faces(tm).begin(), tm);
  uv[h] = { std::nan(""), 0 };
  EXPECT_EQ(extract(), PVF::Error_code::NON_FINITE_VALUE);
  EXPECT_TRUE(untouched());
}

TEST_F(QuadBadInput, FlipsBeyondRepair)
{
  // mirrored map: every triangle reversed
  for(Halfedge h : halfedges(tm))
    if(!CGAL::is_border(h, tm))
      uv[h] = { uv[h][0], -uv[h][1] };
  EXPECT_EQ(extract(), PVF::Error_code::UNREPAIRABLE_FOLD_OVER);
  EXPECT_TRUE(untouched());
}

TEST_F(QuadBadInput, NotATriangleMesh)
{
  Mesh quad;
  CGAL::make_quad(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), quad);
  auto quv = quad.add_property_map<Halfedge, UV>("h:uv").first;
  PVF::Quad_extraction_result r;
  EXPECT_EQ(PVF::extract_quad_mesh(quad, quv, out, r), PVF::Error_code::NON_TRIANGLE_FACE);
  EXPECT_TRUE(untouched());
}

TEST_F(QuadBadInput, PlanarizerRefusesNonQuadsAndBadThresholds)
{
  PVF::Planarization_result pr;
  Mesh tri = tm;
  const auto before = quad_signature(tri);
  EXPECT_EQ(PVF::planarize_quad_mesh(tri, tm, pr), PVF::Error_code::NON_QUAD_FACE);
  EXPECT_TRUE(quad_signature(tri) == before);
  Mesh qm;
  PVF::Quad_extraction_result r;
  ASSERT_EQ(PVF::extract_quad_mesh(tm, uv, qm, r), PVF::Error_code::SUCCESS);
  const auto qbefore = quad_signature(qm);
  for(double t : { 0.0, -0.01 })
    EXPECT_EQ(PVF::planarize_quad_mesh(qm, tm, pr, PVF::parameters::planarity_threshold(t)), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::planarize_quad_mesh(qm, tm, pr, PVF::parameters::planarity_threshold(std::nan(""))), PVF::Error_code::NON_FINITE_VALUE);
  EXPECT_TRUE(quad_signature(qm) == qbefore);
  auto fp = tri.add_property_map<Face, double>("f:p", -7.0).first;
  EXPECT_EQ(PVF::quad_planarity(tri, fp), PVF::Error_code::NON_QUAD_FACE);
  for(Face f : faces(tri))
    EXPECT_EQ(fp[f], -7.0);
}

TEST(QuadPlanarize, IterationLimitLeavesTheMeshUntouched)
{
  const Quad_inspired& S = quad_inspired("inspired");
  Mesh qm = S.qm;
  const auto before = quad_signature(qm);
  PVF::Planarization_result pr;
  EXPECT_EQ(PVF::planarize_quad_mesh(qm, S.c->tm, pr,
                                     PVF::parameters::planarity_threshold(1e-6, PVF::parameters::gauss_newton_steps(2))
                                       .number_of_iterations(2)),
            PVF::Error_code::DID_NOT_CONVERGE);
  EXPECT_EQ(pr.iterations, 2u);
  EXPECT_TRUE(pr.gauss_newton_ran);
  EXPECT_LE(pr.gauss_newton_steps, 2u);
  EXPECT_TRUE(quad_signature(qm) == before);
}

TEST(QuadPlanarize, ParameterChecksAndReference)
{
  const Quad_inspired& S = quad_inspired("inspired");
  Mesh qm = S.qm;
  const auto before = quad_signature(qm);
  PVF::Planarization_result pr;
  EXPECT_EQ(PVF::planarize_quad_mesh(qm, S.c->tm, pr, PVF::parameters::closeness_decay(0.0)), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::planarize_quad_mesh(qm, S.c->tm, pr, PVF::parameters::closeness_decay(1.5)), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::planarize_quad_mesh(qm, S.c->tm, pr, PVF::parameters::closeness_weight(0.0)), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::planarize_quad_mesh(qm, S.c->tm, pr, PVF::parameters::fairness_weight(-1.0)), PVF::Error_code::INVALID_PARAMETER);
  EXPECT_EQ(PVF::planarize_quad_mesh(qm, S.c->tm, pr, PVF::parameters::fairness_weight(std::nan(""))),
            PVF::Error_code::NON_FINITE_VALUE);
  Mesh quad_reference;
  CGAL::make_quad(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), quad_reference);
  EXPECT_EQ(PVF::planarize_quad_mesh(qm, quad_reference, pr), PVF::Error_code::NON_TRIANGLE_FACE);
  Mesh empty;
  EXPECT_EQ(PVF::planarize_quad_mesh(empty, S.c->tm, pr), PVF::Error_code::EMPTY_MESH);
  EXPECT_TRUE(quad_signature(qm) == before);
}

// The documented forms of the named parameters: ours alone, stacked on CGAL's,
// CGAL's members chained after ours, and combine().
TEST(QuadParameters, ChainingForms)
{
  const Quad_inspired& S = quad_inspired("inspired");
  Mesh a = S.qm, b = S.qm, c = S.qm;
  PVF::Planarization_result ra, rb, rc;
  EXPECT_EQ(PVF::planarize_quad_mesh(a, S.c->tm, ra, PVF::parameters::planarity_threshold(0.01, CGAL::parameters::number_of_iterations(3))),
            PVF::Error_code::SUCCESS);
  EXPECT_EQ(PVF::planarize_quad_mesh(b, S.c->tm, rb,
                                     PVF::parameters::combine(PVF::parameters::planarity_threshold(0.01),
                                                              CGAL::parameters::number_of_iterations(3))),
            PVF::Error_code::SUCCESS);
  EXPECT_EQ(PVF::planarize_quad_mesh(c, S.c->tm, rc, PVF::parameters::planarity_threshold(0.01).number_of_iterations(3)),
            PVF::Error_code::SUCCESS);
  EXPECT_EQ(ra.iterations, 3u);
  EXPECT_EQ(rb.iterations, 3u);
  EXPECT_EQ(rc.iterations, 3u);
  // 3 local-global iterations do not reach 1% here: the Gauss-Newton steps that follow do
  EXPECT_TRUE(ra.gauss_newton_ran && rb.gauss_newton_ran && rc.gauss_newton_ran);
  EXPECT_EQ(ra.gauss_newton_steps, rb.gauss_newton_steps);
  EXPECT_EQ(ra.gauss_newton_steps, rc.gauss_newton_steps);
  EXPECT_EQ(ra.max_planarity_after, rb.max_planarity_after);
  EXPECT_EQ(ra.max_planarity_after, rc.max_planarity_after);
  // extraction: keep_trimmed_boundary with CGAL's vertex_point_map chained after it, on both meshes
  Mesh q1, q2;
  PVF::Quad_extraction_result r1, r2;
  ASSERT_EQ(PVF::extract_quad_mesh(S.c->tm, S.c->uv, q1, r1,
                                   PVF::parameters::keep_trimmed_boundary(false).vertex_point_map(get(CGAL::vertex_point, S.c->tm)),
                                   CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, q1))),
            PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::extract_quad_mesh(S.c->tm, S.c->uv, q2, r2, PVF::parameters::fold_over_repair_rings(std::size_t(0))),
            PVF::Error_code::SUCCESS);  // no fold-over in this map: the repair is not needed
  EXPECT_TRUE(quad_signature(q1) == quad_signature(S.qm));
  EXPECT_TRUE(quad_signature(q2) == quad_signature(S.qm));
  // the output points in a property map of the caller, which the extraction keeps
  Mesh q3;
  auto mine = q3.add_property_map<Vertex, Point>("v:quad_points", Point(7, 7, 7)).first;
  PVF::Quad_extraction_result r3;
  ASSERT_EQ(PVF::extract_quad_mesh(S.c->tm, S.c->uv, q3, r3, CGAL::parameters::default_values(),
                                   CGAL::parameters::vertex_point_map(mine)),
            PVF::Error_code::SUCCESS);
  ASSERT_EQ(num_vertices(q3), num_vertices(q1));
  auto p1 = vertices(q1).begin();
  for(Vertex v : vertices(q3))
    EXPECT_TRUE(mine[v] == q1.point(*p1++));
}

// The planarizer on a Polyhedron_3 gives the Surface_mesh result.
TEST(QuadGeneric, PlanarizePolyhedron)
{
  typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
  const Quad_inspired& S = quad_inspired("inspired");
  Polyhedron P;
  CGAL::copy_face_graph(S.qm, P);
  PVF::Planarization_result pr;
  ASSERT_EQ(PVF::planarize_quad_mesh(P, S.c->tm, pr), PVF::Error_code::SUCCESS);
  EXPECT_EQ(pr.iterations, S.pr.iterations);
  EXPECT_NEAR(pr.max_planarity_after, S.pr.max_planarity_after, 1e-12);
  EXPECT_NEAR(pr.max_distance, S.pr.max_distance, 1e-12);
}

// A uv map of 2D points gives the same quads as one of std::array.
TEST(QuadGeneric, PointUvMap)
{
  Mesh tm = grid(5, 7);
  auto uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  auto uv2 = tm.add_property_map<Halfedge, Kernel::Point_2>("h:uv2").first;
  for(Halfedge h : halfedges(tm))
    if(!CGAL::is_border(h, tm))
    {
      uv[h] = { 1.5 * tm.point(target(h, tm)).x() + 0.25, 1.5 * tm.point(target(h, tm)).y() + 0.25 };
      uv2[h] = Kernel::Point_2(uv[h][0], uv[h][1]);
    }
  Mesh q1, q2;
  PVF::Quad_extraction_result r1, r2;
  ASSERT_EQ(PVF::extract_quad_mesh(tm, uv, q1, r1), PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::extract_quad_mesh(tm, uv2, q2, r2), PVF::Error_code::SUCCESS);
  EXPECT_GT(num_faces(q1), 0u);
  EXPECT_TRUE(quad_signature(q1) == quad_signature(q2));
}

// The VTK writer: the stream and the file give the same text, with one planarity per face
// (-1 on a face that is not a quad); on failure nothing is written and an old file stays.
TEST(QuadOutput, VtkStreamAndFile)
{
  const Quad_inspired& S = quad_inspired("inspired");
  std::ostringstream os;
  ASSERT_EQ(PVF::IO::write_quad_mesh_VTK(os, S.qm), PVF::Error_code::SUCCESS);
  std::istringstream in(os.str());
  std::string line, word;
  std::getline(in, line);
  EXPECT_EQ(line, "# vtk DataFile Version 3.0");
  std::size_t n = 0, m = 0, total = 0;
  while(in >> word && word != "POINTS") {}
  in >> n >> word;
  EXPECT_EQ(n, num_vertices(S.qm));
  std::vector<Point> points;
  for(std::size_t i = 0; i < n; ++i)
  {
    double x, y, z;
    in >> x >> y >> z;
    points.emplace_back(x, y, z);
  }
  in >> word >> m >> total;
  EXPECT_EQ(word, "POLYGONS");
  EXPECT_EQ(m, num_faces(S.qm));
  EXPECT_EQ(total, 5 * m);
  std::vector<double> expected;
  for(std::size_t f = 0; f < m; ++f)
  {
    std::size_t k, i[4];
    in >> k >> i[0] >> i[1] >> i[2] >> i[3];
    ASSERT_EQ(k, 4u);
    expected.push_back(quad_reference_planarity(points[i[0]], points[i[1]], points[i[2]], points[i[3]]));
  }
  in >> word >> m >> word >> word >> word >> word >> word >> word;
  EXPECT_EQ(word, "default");
  for(std::size_t f = 0; f < m; ++f)
  {
    double q;
    in >> q;
    EXPECT_NEAR(q, expected[f], 1e-12);
  }
  EXPECT_TRUE(bool(in));

  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "pvf_quad_mesh_test";
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "quads.vtk").string();
  ASSERT_EQ(PVF::IO::write_quad_mesh_VTK(file, S.qm), PVF::Error_code::SUCCESS);
  {
    std::ifstream f(file);
    std::stringstream text;
    text << f.rdbuf();
    EXPECT_EQ(text.str(), os.str());
  }
  // a NaN coordinate: NON_FINITE_VALUE, the old file unchanged, nothing on the stream
  Mesh bad = S.qm;
  bad.point(*vertices(bad).begin()) = Point(std::nan(""), 0, 0);
  std::ostringstream bad_os;
  EXPECT_EQ(PVF::IO::write_quad_mesh_VTK(file, bad), PVF::Error_code::NON_FINITE_VALUE);
  EXPECT_EQ(PVF::IO::write_quad_mesh_VTK(bad_os, bad), PVF::Error_code::NON_FINITE_VALUE);
  EXPECT_TRUE(bad_os.str().empty());
  {
    std::ifstream f(file);
    std::stringstream text;
    text << f.rdbuf();
    EXPECT_EQ(text.str(), os.str());
  }
  EXPECT_EQ(PVF::IO::write_quad_mesh_VTK((dir / "no_such_dir" / "q.vtk").string(), S.qm), PVF::Error_code::CANNOT_OPEN_FILE);
  EXPECT_EQ(PVF::IO::write_quad_mesh_VTK(os, Mesh()), PVF::Error_code::EMPTY_MESH);
  // the faces that are not quads (trimmed polygons other than quadrilaterals) get -1
  Mesh trimmed;
  PVF::Quad_extraction_result r;
  ASSERT_EQ(PVF::extract_quad_mesh(S.c->tm, S.c->uv, trimmed, r, PVF::parameters::keep_trimmed_boundary(true)), PVF::Error_code::SUCCESS);
  std::ostringstream tos;
  ASSERT_EQ(PVF::IO::write_quad_mesh_VTK(tos, trimmed), PVF::Error_code::SUCCESS);
  const std::string t = tos.str();
  std::istringstream tin(t.substr(t.find("LOOKUP_TABLE default\n") + 21));
  std::size_t minus_one = 0;
  double q;
  while(tin >> q)
    minus_one += q == -1.0;
  std::size_t non_quads = 0;
  for(Face f : faces(trimmed))
    non_quads += degree(f, trimmed) != 4;
  EXPECT_GT(non_quads, 0u);
  EXPECT_LE(non_quads, r.trimmed_polygons);
  EXPECT_EQ(minus_one, non_quads);
  std::filesystem::remove_all(dir);
}

// ---------------------------------------------------------------------------
// Maps aligned with the boundary and with mesh edges (exact integer iso-lines)
// ---------------------------------------------------------------------------
namespace {

typedef std::array<long, 2> Quad_lattice_point;

// A flat mesh of the triangles (indices into `points`, counterclockwise) with the identity
// map uv = (x, y): exact, since the points are integers or halves.
Mesh quad_flat_mesh(const std::vector<std::array<double, 2> >& points, const std::vector<std::array<std::size_t, 3> >& triangles)
{
  Soup<Point> soup;
  for(const auto& p : points)
    soup.points.emplace_back(p[0], p[1], 0);
  for(const auto& t : triangles)
    soup.faces.push_back({ t[0], t[1], t[2] });
  return make_mesh<Mesh>(soup);
}

void quad_identity_map(const Mesh& tm, Quad_uv_map uv)
{
  for(Halfedge h : halfedges(tm))
    if(!CGAL::is_border(h, tm))
      uv[h] = { tm.point(target(h, tm)).x(), tm.point(target(h, tm)).y() };
}

// A map whose every triangle is positive but which covers the plane twice around a
// vertex off the integer grid (a branch point, as z^2): a fold-over, found by the turn
// of the vertex's star (4 pi), not an integer-grid map with an 8-direction vertex.
// The border winds twice too, so no re-embedding inside it can unfold the disk.
TEST(QuadFoldOvers, BranchPointIsAFoldOver)
{
  const std::size_t n = 8;
  std::vector<std::array<double, 2> > points{ { 0, 0 } };
  std::vector<std::array<std::size_t, 3> > triangles;
  for(std::size_t k = 0; k < n; ++k)
  {
    points.push_back({ std::cos(2 * pi * double(k) / double(n)), std::sin(2 * pi * double(k) / double(n)) });
    triangles.push_back({ 0, 1 + k, 1 + (k + 1) % n });
  }
  Mesh tm = quad_flat_mesh(points, triangles);
  auto uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  const double radius = 3, cx = 0.5, cy = 0.25;  // the centre off the integer grid
  for(Halfedge h : halfedges(tm))
    if(!CGAL::is_border(h, tm))
    {
      const Point p = tm.point(target(h, tm));
      const double angle = 2 * std::atan2(p.y(), p.x());  // twice the angle: each 45-degree corner is 90 in uv
      const bool centre = p.x() == 0 && p.y() == 0;
      uv[h] = { cx + (centre ? 0 : radius * std::cos(angle)), cy + (centre ? 0 : radius * std::sin(angle)) };
    }
  for(Face f : faces(tm))
  {
    const Halfedge h = halfedge(f, tm);
    const UV a = uv[h], b = uv[next(h, tm)], c = uv[prev(h, tm)];
    ASSERT_GT((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]), 0);  // no triangle is flipped
  }
  Mesh qm;
  PVF::Quad_extraction_result r;
  EXPECT_EQ(PVF::extract_quad_mesh(tm, uv, qm, r), PVF::Error_code::UNREPAIRABLE_FOLD_OVER) << r.diagnostic;
  EXPECT_EQ(r.flipped_faces, n);      // the star of the branch point
  EXPECT_EQ(r.repaired_regions, 0u);  // no re-embedding inside the doubly wound border unfolds it
  EXPECT_EQ(num_faces(qm), 0u);
}

// Polygon (counterclockwise, integer corners) -> triangles by ear clipping with exact
// integer orientation tests: coarse triangles whose edges run along grid lines and through
// lattice points.
std::vector<std::array<std::size_t, 3> > quad_ear_clipping(const std::vector<std::array<double, 2> >& poly)
{
  auto orient = [](const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c) {
    const double d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    return (d > 0) - (d < 0);
  };
  std::vector<std::size_t> idx(poly.size());
  for(std::size_t i = 0; i < idx.size(); ++i)
    idx[i] = i;
  std::vector<std::array<std::size_t, 3> > out;
  while(idx.size() > 3)
  {
    bool cut = false;
    for(std::size_t i = 0; i < idx.size() && !cut; ++i)
    {
      const std::size_t a = idx[(i + idx.size() - 1) % idx.size()], b = idx[i], c = idx[(i + 1) % idx.size()];
      if(orient(poly[a], poly[b], poly[c]) <= 0)
        continue;
      bool empty = true;
      for(std::size_t j : idx)
        if(j != a && j != b && j != c && orient(poly[a], poly[b], poly[j]) >= 0 && orient(poly[b], poly[c], poly[j]) >= 0 &&
           orient(poly[c], poly[a], poly[j]) >= 0)
          empty = false;
      if(!empty)
        continue;
      out.push_back({ a, b, c });
      idx.erase(idx.begin() + std::ptrdiff_t(i));
      cut = true;
    }
    if(!cut)
      return {};
  }
  out.push_back({ idx[0], idx[1], idx[2] });
  return out;
}

// The expected quad mesh of a flat region made of whole unit cells with the identity map:
// one unit square per cell, its corners at the cell corners.
struct Quad_lattice_checks
{
  bool valid = false, all_unit_squares = true;
  std::size_t faces = 0, vertices = 0, border_edges = 0, border_edges_on_boundary = 0;
  std::set<Quad_lattice_point> cells;
};

// `on_boundary(a, b)`: the segment between two lattice points lies on the region's boundary
template <typename OnBoundary>
Quad_lattice_checks quad_lattice_checks(const Mesh& qm, OnBoundary on_boundary)
{
  Quad_lattice_checks c;
  c.valid = CGAL::is_valid_polygon_mesh(qm);
  c.faces = num_faces(qm);
  c.vertices = num_vertices(qm);
  auto lattice = [&](Vertex v) {
    const Point& p = qm.point(v);
    return Quad_lattice_point{ long(std::lround(p.x())), long(std::lround(p.y())) };
  };
  for(Vertex v : vertices(qm))
  {
    const Point& p = qm.point(v);
    c.all_unit_squares = c.all_unit_squares && p.x() == std::round(p.x()) && p.y() == std::round(p.y()) && p.z() == 0;
  }
  for(Face f : faces(qm))
  {
    std::vector<Quad_lattice_point> q;
    for(Halfedge h : halfedges_around_face(halfedge(f, qm), qm))
      q.push_back(lattice(target(h, qm)));
    bool unit = q.size() == 4;
    long lo[2] = { 1L << 40, 1L << 40 };
    for(std::size_t k = 0; unit && k < 4; ++k)
    {
      const Quad_lattice_point &a = q[k], &b = q[(k + 1) % 4];
      unit = std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) == 1;
      // counterclockwise: the turn at every corner is to the left
      const Quad_lattice_point& n = q[(k + 2) % 4];
      unit = unit && (b[0] - a[0]) * (n[1] - b[1]) - (b[1] - a[1]) * (n[0] - b[0]) == 1;
      lo[0] = (std::min)(lo[0], a[0]);
      lo[1] = (std::min)(lo[1], a[1]);
    }
    c.all_unit_squares = c.all_unit_squares && unit;
    c.cells.insert({ lo[0], lo[1] });
  }
  for(Halfedge h : halfedges(qm))
    if(CGAL::is_border(h, qm))
    {
      ++c.border_edges;
      c.border_edges_on_boundary += on_boundary(lattice(source(h, qm)), lattice(target(h, qm)));
    }
  return c;
}

// A union of unit cells: its boundary segments, its lattice points.
struct Quad_cell_region
{
  std::set<Quad_lattice_point> cells;
  bool has(long x, long y) const { return cells.count({ x, y }) != 0; }
  // the unit segment a-b is on the boundary: exactly one of its two cells is in the region
  bool on_boundary(const Quad_lattice_point& a, const Quad_lattice_point& b) const
  {
    if(a[1] == b[1] && std::abs(a[0] - b[0]) == 1)
    {
      const long x = (std::min)(a[0], b[0]);
      return has(x, a[1]) != has(x, a[1] - 1);
    }
    if(a[0] == b[0] && std::abs(a[1] - b[1]) == 1)
    {
      const long y = (std::min)(a[1], b[1]);
      return has(a[0], y) != has(a[0] - 1, y);
    }
    return false;
  }
  std::size_t lattice_points() const
  {
    std::set<Quad_lattice_point> p;
    for(const auto& c : cells)
      for(long dx = 0; dx < 2; ++dx)
        for(long dy = 0; dy < 2; ++dy)
          p.insert({ c[0] + dx, c[1] + dy });
    return p.size();
  }
  std::size_t boundary_segments() const
  {
    std::size_t n = 0;
    for(const auto& c : cells)
      n += !has(c[0] - 1, c[1]) + !has(c[0] + 1, c[1]) + !has(c[0], c[1] - 1) + !has(c[0], c[1] + 1);
    return n;
  }
};

// The region's boundary as one counterclockwise polygon through its corners only (collinear
// lattice points dropped); empty if the boundary is not one simple closed curve.
std::vector<std::array<double, 2> > quad_region_polygon(const Quad_cell_region& R)
{
  // directed unit boundary segments, the region on their left
  std::map<Quad_lattice_point, std::vector<Quad_lattice_point> > next;
  std::size_t count = 0;
  for(const auto& c : R.cells)
  {
    const long x = c[0], y = c[1];
    if(!R.has(x, y - 1)) next[{ x, y }].push_back({ x + 1, y }), ++count;
    if(!R.has(x + 1, y)) next[{ x + 1, y }].push_back({ x + 1, y + 1 }), ++count;
    if(!R.has(x, y + 1)) next[{ x + 1, y + 1 }].push_back({ x, y + 1 }), ++count;
    if(!R.has(x - 1, y)) next[{ x, y + 1 }].push_back({ x, y }), ++count;
  }
  for(const auto& n : next)
    if(n.second.size() != 1)
      return {};  // a pinched boundary point
  std::vector<Quad_lattice_point> loop{ next.begin()->first };
  while(true)
  {
    const Quad_lattice_point n = next[loop.back()][0];
    if(n == loop.front())
      break;
    loop.push_back(n);
  }
  if(loop.size() != count)
    return {};  // several boundary curves: a hole
  std::vector<std::array<double, 2> > poly;
  for(std::size_t i = 0; i < loop.size(); ++i)
  {
    const Quad_lattice_point &a = loop[(i + loop.size() - 1) % loop.size()], &b = loop[i], &c = loop[(i + 1) % loop.size()];
    if((b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]) != 0)
      poly.push_back({ double(b[0]), double(b[1]) });
  }
  return poly;
}

void quad_expect_cells_of_region(const Mesh& tm, const Quad_cell_region& R, const std::string& what)
{
  Mesh m = tm;
  auto uv = m.add_property_map<Halfedge, UV>("h:uv").first;
  quad_identity_map(m, uv);
  Mesh qm;
  PVF::Quad_extraction_result r;
  ASSERT_EQ(PVF::extract_quad_mesh(m, uv, qm, r), PVF::Error_code::SUCCESS) << what << ": " << r.diagnostic;
  const Quad_lattice_checks c = quad_lattice_checks(qm, [&](const Quad_lattice_point& a, const Quad_lattice_point& b) { return R.on_boundary(a, b); });
  EXPECT_TRUE(c.valid) << what;
  EXPECT_TRUE(c.all_unit_squares) << what;
  EXPECT_EQ(c.faces, R.cells.size()) << what;
  EXPECT_EQ(c.cells, R.cells) << what;
  EXPECT_EQ(c.vertices, R.lattice_points()) << what;
  EXPECT_EQ(c.border_edges, R.boundary_segments()) << what;
  EXPECT_EQ(c.border_edges_on_boundary, c.border_edges) << what;
  EXPECT_EQ(r.folded_quads, 0u) << what;
  EXPECT_EQ(r.inconsistencies, 0u) << what;
}

Quad_cell_region quad_rectangle(long w, long h)
{
  Quad_cell_region R;
  for(long x = 0; x < w; ++x)
    for(long y = 0; y < h; ++y)
      R.cells.insert({ x, y });
  return R;
}

} // namespace

// The square [0,3] x [0,2] in a few triangles, uv = (x, y): its boundary on integer
// lines, grid lines along mesh edges and through mesh vertices, lattice points at
// vertices and inside edges. Exactly its 6 cells, bounded by quad edges.
TEST(QuadAligned, RectangleInFewTriangles)
{
  const Quad_cell_region R = quad_rectangle(3, 2);
  typedef std::vector<std::array<double, 2> > Points;
  typedef std::vector<std::array<std::size_t, 3> > Triangles;
  // two triangles, either diagonal
  quad_expect_cells_of_region(quad_flat_mesh(Points{ { 0, 0 }, { 3, 0 }, { 3, 2 }, { 0, 2 } }, Triangles{ { 0, 1, 2 }, { 0, 2, 3 } }), R, "two triangles");
  quad_expect_cells_of_region(quad_flat_mesh(Points{ { 0, 0 }, { 3, 0 }, { 3, 2 }, { 0, 2 } }, Triangles{ { 0, 1, 3 }, { 1, 2, 3 } }), R, "other diagonal");
  // a fan around a centre off the grid, and around a lattice point
  for(const std::array<double, 2> centre : { std::array<double, 2>{ 1.5, 1 }, std::array<double, 2>{ 1, 1 }, std::array<double, 2>{ 2, 1 },
                                             std::array<double, 2>{ 0.5, 0.5 } })
    quad_expect_cells_of_region(quad_flat_mesh(Points{ { 0, 0 }, { 3, 0 }, { 3, 2 }, { 0, 2 }, centre },
                                               Triangles{ { 0, 1, 4 }, { 1, 2, 4 }, { 2, 3, 4 }, { 3, 0, 4 } }),
                                R, "fan around (" + std::to_string(centre[0]) + ", " + std::to_string(centre[1]) + ")");
  // boundary vertices inside the sides, at lattice points and between them
  quad_expect_cells_of_region(quad_flat_mesh(Points{ { 0, 0 }, { 1, 0 }, { 3, 0 }, { 3, 2 }, { 1.5, 2 }, { 0, 2 } },
                                             Triangles{ { 0, 1, 5 }, { 1, 4, 5 }, { 1, 2, 4 }, { 2, 3, 4 } }),
                              R, "vertices inside the sides");
  // a mesh edge along the whole grid line y = 1
  quad_expect_cells_of_region(quad_flat_mesh(Points{ { 0, 0 }, { 3, 0 }, { 3, 1 }, { 3, 2 }, { 0, 2 }, { 0, 1 } },
                                             Triangles{ { 0, 1, 2 }, { 0, 2, 5 }, { 5, 2, 3 }, { 5, 3, 4 } }),
                              R, "an edge along y = 1");
}

// L-shaped and non-convex polygons with integer corners, triangulated coarsely (ear
// clipping): one unit quad per cell, the boundary made of quad edges.
TEST(QuadAligned, NonConvexPolygonsCoarselyTriangulated)
{
  auto region = [](const std::vector<Quad_lattice_point>& cells) {
    Quad_cell_region R;
    R.cells.insert(cells.begin(), cells.end());
    return R;
  };
  const std::vector<Quad_cell_region> shapes{
    region({ { 0, 0 }, { 1, 0 }, { 2, 0 }, { 0, 1 }, { 0, 2 } }),                                  // L
    region({ { 0, 0 }, { 1, 0 }, { 2, 0 }, { 3, 0 }, { 0, 1 }, { 3, 1 }, { 0, 2 }, { 3, 2 } }),    // U
    region({ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 2, 1 }, { 2, 2 }, { 3, 2 } }),                       // staircase
    region({ { 1, 0 }, { 0, 1 }, { 1, 1 }, { 2, 1 }, { 1, 2 } }),                                  // plus
  };
  for(std::size_t i = 0; i < shapes.size(); ++i)
  {
    const auto poly = quad_region_polygon(shapes[i]);
    ASSERT_FALSE(poly.empty());
    const auto triangles = quad_ear_clipping(poly);
    ASSERT_EQ(triangles.size(), poly.size() - 2);
    quad_expect_cells_of_region(quad_flat_mesh(poly, triangles), shapes[i], "shape " + std::to_string(i));
  }
  // random simply connected unions of cells, seeded
  std::mt19937 rng(7);
  std::size_t tested = 0;
  for(int trial = 0; trial < 400 && tested < 60; ++trial)
  {
    Quad_cell_region R;
    R.cells.insert({ 0, 0 });
    const int n = 3 + int(rng() % 14);
    while(int(R.cells.size()) < n)
    {
      auto it = R.cells.begin();
      std::advance(it, std::ptrdiff_t(rng() % R.cells.size()));
      const int d = int(rng() % 4);
      const long dx[4] = { 1, 0, -1, 0 }, dy[4] = { 0, 1, 0, -1 };
      R.cells.insert({ (*it)[0] + dx[d], (*it)[1] + dy[d] });
    }
    const auto poly = quad_region_polygon(R);
    if(poly.empty())
      continue;  // a hole or a pinched corner
    const auto triangles = quad_ear_clipping(poly);
    ASSERT_EQ(triangles.size(), poly.size() - 2);
    ++tested;
    quad_expect_cells_of_region(quad_flat_mesh(poly, triangles), R, "random region " + std::to_string(trial));
    // each triangle split at its centroid (regular vertices off the grid, coordinates not dyadic)
    std::vector<std::array<double, 2> > points = poly;
    std::vector<std::array<std::size_t, 3> > split;
    for(const auto& t : triangles)
    {
      points.push_back({ (poly[t[0]][0] + poly[t[1]][0] + poly[t[2]][0]) / 3, (poly[t[0]][1] + poly[t[1]][1] + poly[t[2]][1]) / 3 });
      for(std::size_t k = 0; k < 3; ++k)
        split.push_back({ t[k], t[(k + 1) % 3], points.size() - 1 });
    }
    quad_expect_cells_of_region(quad_flat_mesh(points, split), R, "random region " + std::to_string(trial) + ", split");
  }
  EXPECT_GE(tested, 40u);
}
namespace {

// The box [0,1]^3, each side in two triangles (`centres`: four triangles around its
// centre), and a hand-made seamless map: each side of the box mapped to the square
// [0,3]^2 of its own chart (u, v) = 3 ((p - o).e1, (p - o).e2), with e1 x e2 the outward
// normal. Across every box edge the charts differ by a quarter turn and an integer
// translation; every box corner is a cone of three right angles (valence 3).
struct Quad_box
{
  Mesh tm;
  Quad_uv_map uv;
};

std::unique_ptr<Quad_box> quad_box(bool centres)
{
  struct Side { std::array<double, 3> o, e1, e2; };
  const Side sides[6] = { { { 0, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 } }, { { 0, 0, 1 }, { 1, 0, 0 }, { 0, 1, 0 } },
                          { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 1 } }, { { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 0 } },
                          { { 0, 0, 0 }, { 0, 0, 1 }, { 0, 1, 0 } }, { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } };
  Soup<Point> soup;
  std::map<std::array<double, 3>, std::size_t> index;
  auto vertex = [&](const std::array<double, 3>& p) {
    auto it = index.find(p);
    if(it != index.end())
      return it->second;
    index[p] = soup.points.size();
    soup.points.emplace_back(p[0], p[1], p[2]);
    return soup.points.size() - 1;
  };
  for(const Side& s : sides)
  {
    std::array<std::size_t, 4> c;
    for(int k = 0; k < 4; ++k)
    {
      const double a = (k == 1 || k == 2) ? 1 : 0, b = k >= 2 ? 1 : 0;
      c[std::size_t(k)] = vertex({ s.o[0] + a * s.e1[0] + b * s.e2[0], s.o[1] + a * s.e1[1] + b * s.e2[1], s.o[2] + a * s.e1[2] + b * s.e2[2] });
    }
    if(centres)
    {
      const std::size_t m = vertex({ s.o[0] + 0.5 * (s.e1[0] + s.e2[0]), s.o[1] + 0.5 * (s.e1[1] + s.e2[1]), s.o[2] + 0.5 * (s.e1[2] + s.e2[2]) });
      for(std::size_t k = 0; k < 4; ++k)
        soup.faces.push_back({ c[k], c[(k + 1) % 4], m });
    }
    else
      soup.add_quad(c[0], c[1], c[2], c[3]);
  }
  auto box = std::make_unique<Quad_box>();
  box->tm = make_mesh<Mesh>(soup);
  Mesh& tm = box->tm;
  box->uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  for(Face f : faces(tm))
  {
    // the side of f: the one whose outward normal is f's normal
    const Halfedge h0 = halfedge(f, tm);
    const Vector n = CGAL::cross_product(tm.point(target(h0, tm)) - tm.point(source(h0, tm)),
                                         tm.point(target(next(h0, tm), tm)) - tm.point(target(h0, tm)));
    const Side* side = nullptr;
    for(const Side& s : sides)
    {
      const Vector e1(s.e1[0], s.e1[1], s.e1[2]), e2(s.e2[0], s.e2[1], s.e2[2]);
      if(n * CGAL::cross_product(e1, e2) > 0)
        side = &s;
    }
    for(Halfedge h : halfedges_around_face(h0, tm))
    {
      const Point& p = tm.point(target(h, tm));
      const Vector d = p - Point(side->o[0], side->o[1], side->o[2]);
      box->uv[h] = { 3 * (d * Vector(side->e1[0], side->e1[1], side->e1[2])), 3 * (d * Vector(side->e2[0], side->e2[1], side->e2[2])) };
    }
  }
  return box;
}

// The transition of every corner of the bundle's numbering (the k-th halfedge of face i
// from halfedge(face), corner 3i + k): the grid symmetry z -> i^r z + t that maps the uv of
// its edge's two endpoints in face(h) onto their uv in face(opposite(h)); false if none does.
template <typename Bundle>
bool quad_box_transitions(const Bundle& bundle, const Mesh& tm, Quad_uv_map uv, std::vector<PVF::Seam_transition>& out)
{
  out.assign(3 * num_faces(tm), PVF::Seam_transition());
  auto turn = [](const UV& p, int r) {
    UV q = p;
    for(int k = 0; k < r; ++k)
      q = { -q[1], q[0] };
    return q;
  };
  for(std::size_t i = 0; i < num_faces(tm); ++i)
  {
    Halfedge h = halfedge(bundle.face(i), tm);
    for(std::size_t k = 0; k < 3; ++k, h = next(h, tm))
    {
      const Halfedge o = opposite(h, tm);
      if(CGAL::is_border(o, tm))
        continue;
      // target(h): uv[h] here, uv[prev(o)] there; source(h): uv[prev(h)] here, uv[o] there
      bool found = false;
      for(int r = 0; r < 4 && !found; ++r)
      {
        const UV a = turn(uv[h], r), b = turn(uv[prev(h, tm)], r);
        const double tx = uv[prev(o, tm)][0] - a[0], ty = uv[prev(o, tm)][1] - a[1];
        if(uv[o][0] - b[0] == tx && uv[o][1] - b[1] == ty && tx == std::floor(tx) && ty == std::floor(ty))
        {
          out[3 * i + k].rotation = r;
          out[3 * i + k].translation = { { std::int64_t(tx), std::int64_t(ty) } };
          found = true;
        }
      }
      if(!found)
        return false;
    }
  }
  return true;
}

} // namespace

// A box with a hand-made seamless map (quarter turns across its edges, a cone of valence 3
// at each corner): 6 sides of 3 x 3 quads, 54 quads, 56 vertices, a closed manifold of
// Euler characteristic 2; the 8 box corners of valence 3, every box edge made of quad
// edges. Grid lines run along the mesh edges (the box edges are seams) and along or
// across the diagonals of the sides.
TEST(QuadAligned, BoxWithQuarterTurnSeams)
{
  for(bool centres : { false, true })
  {
    SCOPED_TRACE(centres ? "4 triangles per side" : "2 triangles per side");
    std::unique_ptr<Quad_box> box = quad_box(centres);
    const Mesh& tm = box->tm;
    ASSERT_EQ(num_faces(tm), centres ? 24u : 12u);
    typedef PVF::Tangent_bundle<Mesh> Bundle;
    const Bundle bundle(tm);
    ASSERT_EQ(bundle.status(), PVF::Error_code::SUCCESS);
    PVF::Integer_grid_map_result map;
    ASSERT_TRUE(quad_box_transitions(bundle, tm, box->uv, map.seam_transitions));
    std::size_t rotated = 0;
    for(const PVF::Seam_transition& T : map.seam_transitions)
      rotated += T.rotation != 0;
    EXPECT_GT(rotated, 0u);
    for(int overload = 0; overload < 2; ++overload)
    {
      Mesh qm;
      PVF::Quad_extraction_result r;
      const PVF::Error_code code = overload == 0 ? PVF::extract_quad_mesh(bundle, box->uv, map, qm, r)
                                                 : PVF::extract_quad_mesh(tm, box->uv, qm, r);
      ASSERT_EQ(code, PVF::Error_code::SUCCESS) << r.diagnostic;
      const Quad_checks c = quad_checks(qm);
      EXPECT_TRUE(c.valid);
      EXPECT_TRUE(c.all_quads);
      EXPECT_TRUE(c.closed);
      EXPECT_EQ(num_faces(qm), 54u);
      EXPECT_EQ(num_vertices(qm), 56u);
      EXPECT_EQ(c.chi, 2);
      EXPECT_EQ(c.components, 1u);
      EXPECT_EQ(c.irregular, 8u);
      EXPECT_EQ(r.singular_points, 8u);
      EXPECT_EQ(r.folded_quads, 0u);
      EXPECT_EQ(c.max_planarity, 0.0);
      // every vertex on the lattice (1/3) Z^3 on the box, every edge of length 1/3 along an axis
      std::size_t corners_of_valence_3 = 0;
      for(Vertex v : vertices(qm))
      {
        const Point& p = qm.point(v);
        for(int a = 0; a < 3; ++a)
          EXPECT_NEAR(3 * p[a], std::round(3 * p[a]), 1e-12);
        const bool corner = (p.x() == 0 || p.x() == 1) && (p.y() == 0 || p.y() == 1) && (p.z() == 0 || p.z() == 1);
        corners_of_valence_3 += corner && degree(v, qm) == 3;
      }
      EXPECT_EQ(corners_of_valence_3, 8u);
      for(auto e : edges(qm))
      {
        const Vector d = qm.point(target(halfedge(e, qm), qm)) - qm.point(source(halfedge(e, qm), qm));
        EXPECT_NEAR(std::abs(d.x()) + std::abs(d.y()) + std::abs(d.z()), 1.0 / 3, 1e-12);
        EXPECT_NEAR(std::sqrt(d.squared_length()), 1.0 / 3, 1e-12);
      }
    }
  }
}
namespace {

// The strip [0, 1] x [0, 2] of uv = (x, y) (a grid of 24 x 4 squares, the identity map,
// no fold-over) bent around a cylinder of axis y, by `angle` radians over its width:
// for an angle of 3 pi / 2, each of its two cells wraps three quarters around the axis
// and the straight quad between its corners faces the inside of the bend, against the
// surface at both of its sides.
Mesh quad_bent_strip(double angle, Quad_uv_map& uv)
{
  Mesh tm = grid(4, 24);
  uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  for(Halfedge h : halfedges(tm))
    if(!CGAL::is_border(h, tm))
    {
      const Point& p = tm.point(target(h, tm));
      uv[h] = { p.x() / 24, p.y() / 2 };
    }
  const double rho = 0.25;
  for(Vertex v : vertices(tm))
  {
    const Point p = tm.point(v);
    const double phi = angle * p.x() / 24;
    tm.point(v) = Point(rho * std::sin(phi), p.y() / 2, rho * (1 - std::cos(phi)));
  }
  return tm;
}

} // namespace

// Quads folded against the surface are never returned: without the filling, the strip
// bent by three quarter turns gives FOLDED_QUAD with the number of folded quads (both), and
// the output mesh is left untouched; with it, its triangles are split into quads; bent by a
// quarter turn, it gives its two quads.
TEST(QuadFolds, FoldedQuadIsAnError)
{
  {
    Quad_uv_map uv;
    const Mesh tm = quad_bent_strip(pi / 2, uv);
    Mesh qm;
    PVF::Quad_extraction_result r;
    ASSERT_EQ(PVF::extract_quad_mesh(tm, uv, qm, r), PVF::Error_code::SUCCESS) << r.diagnostic;
    EXPECT_EQ(r.folded_quads, 0u);
    EXPECT_EQ(num_faces(qm), 2u);
  }
  Quad_uv_map uv;
  const Mesh tm = quad_bent_strip(3 * pi / 2, uv);
  // without the repair, and with it but without the filling: no corner position on the
  // surface unfolds them
  for(std::size_t rings : { std::size_t(0), std::size_t(6) })
  {
    Mesh qm = grid(1, 3);
    PVF::Quad_extraction_result r;
    EXPECT_EQ(PVF::extract_quad_mesh(tm, uv, qm, r,
                                     PVF::parameters::fold_over_repair_rings(rings, PVF::parameters::fill_fold_overs(false))),
              PVF::Error_code::FOLDED_QUAD);
    EXPECT_EQ(r.flipped_faces, 0u);
    EXPECT_EQ(r.folded_quads, 2u);
    EXPECT_EQ(r.unfolded_quads, 0u);
    EXPECT_NE(r.diagnostic.find("2 of the 2 quads fold against the surface"), std::string::npos) << r.diagnostic;
    EXPECT_EQ(num_faces(qm), 6u);  // untouched
  }
  // with the filling (the default): the two quads are the whole strip, too much of it to
  // fill, so its triangles are split into quads, three each, on the surface and unfolded
  {
    Mesh qm;
    PVF::Quad_extraction_result r;
    ASSERT_EQ(PVF::extract_quad_mesh(tm, uv, qm, r), PVF::Error_code::SUCCESS) << r.diagnostic;
    EXPECT_EQ(r.split_components, 1u);
    EXPECT_EQ(r.split_triangles, num_faces(tm));
    EXPECT_EQ(num_faces(qm), 3 * num_faces(tm));
    EXPECT_EQ(euler_characteristic(qm), euler_characteristic(tm));
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(qm));
    // each quad lies in one input triangle: its corners are coplanar, and it turns like the triangle
    for(Face f : faces(qm))
    {
      std::vector<Point> c;
      for(Halfedge h : halfedges_around_face(halfedge(f, qm), qm))
        c.push_back(qm.point(target(h, qm)));
      ASSERT_EQ(c.size(), 4u);
      const Vector n1 = CGAL::cross_product(c[1] - c[0], c[2] - c[0]), n2 = CGAL::cross_product(c[2] - c[0], c[3] - c[0]);
      EXPECT_GT(n1 * n2, 0.999 * std::sqrt(n1.squared_length() * n2.squared_length()));
    }
  }
  EXPECT_STREQ(PVF::get_error_message(PVF::Error_code::FOLDED_QUAD),
               "a quad of the quad mesh is folded against the surface (neither diagonal gives two triangles facing the surface's side)");
}

namespace {

// A tube of n x rows squares (two triangles each) around the z axis: an open cylinder
// of circumference and height 1, or (torus) the same squares closed into a torus. Its
// map: uv = (k / n - su, i / rows - sv) at the vertex k around and i along, so that one
// quad of the map is the whole circumference (and the whole length of the torus), with
// the integer point (0, 0) inside a face for shifts su, sv off the grid's steps. With
// shifts that are exact binary fractions, the seams are exact translations by 1.
Mesh quad_tube(std::size_t n, std::size_t rows, bool torus, double su, double sv, Quad_uv_map& uv)
{
  Mesh tm;
  const std::size_t layers = torus ? rows : rows + 1;
  std::vector<Vertex> vertex;
  for(std::size_t i = 0; i < layers; ++i)
    for(std::size_t k = 0; k < n; ++k)
    {
      const double a = 2 * pi * double(k) / double(n), b = 2 * pi * double(i) / double(rows);
      if(torus)
        vertex.push_back(tm.add_vertex(Point((1 + 0.3 * std::cos(b)) * std::cos(a), (1 + 0.3 * std::cos(b)) * std::sin(a),
                                             0.3 * std::sin(b))));
      else
        vertex.push_back(tm.add_vertex(Point(std::cos(a) / (2 * pi), std::sin(a) / (2 * pi), double(i) / double(rows))));
    }
  // the corners of each face, unwrapped: (k, i) with k up to n and i up to rows
  std::map<Face, std::map<Vertex, UV> > face_uv;
  for(std::size_t i = 0; i < rows; ++i)
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::array<std::size_t, 2> p{ k, i }, q{ k + 1, i }, pp{ k, i + 1 }, qq{ k + 1, i + 1 };
      for(const auto& t : { std::array<std::array<std::size_t, 2>, 3>{ p, q, qq }, std::array<std::array<std::size_t, 2>, 3>{ p, qq, pp } })
      {
        std::map<Vertex, UV> corners;
        std::vector<Vertex> vs;
        for(const auto& c : t)
        {
          const Vertex v = vertex[(c[1] % layers) * n + c[0] % n];
          vs.push_back(v);
          corners[v] = { double(c[0]) / double(n) - su, double(c[1]) / double(rows) - sv };
        }
        const Face f = tm.add_face(vs[0], vs[1], vs[2]);
        face_uv[f] = corners;
      }
    }
  uv = tm.add_property_map<Halfedge, UV>("h:uv").first;
  for(Halfedge h : halfedges(tm))
    if(!CGAL::is_border(h, tm))
      uv[h] = face_uv[face(h, tm)][target(h, tm)];
  return tm;
}

std::size_t quad_border_cycles(const Mesh& qm)
{
  std::set<Halfedge> seen;
  std::size_t cycles = 0;
  for(Halfedge h : halfedges(qm))
    if(CGAL::is_border(h, qm) && seen.insert(h).second)
    {
      ++cycles;
      for(Halfedge g = next(h, qm); g != h; g = next(g, qm))
        seen.insert(g);
    }
  return cycles;
}

} // namespace

// On an open cylinder one quad of the map around (FOUND_BUGS.md of the fuzz
// harnesses, quad_map target), the trimmed cells go around the cylinder: the
// iso-line v = 0 closes on itself through the one integer point, and u = 0 runs
// from border to border, so that the cells above and below pass twice through
// its ends. keep_trimmed_boundary cuts each of them into two polygons (two points
// added inside the closed iso-line): a valid cylinder of 4 polygons on the surface.
// Whole cells: none (NO_INTEGER_CELL).
TEST(QuadWrappingCells, TrimmedCylinderCellsAreCut)
{
  for(std::size_t n : { std::size_t(5), std::size_t(6), std::size_t(9) })
  {
    SCOPED_TRACE("n = " + std::to_string(n));
    Quad_uv_map uv;
    const Mesh tm = quad_tube(n, 2, false, 0.3125, 0.375, uv);
    ASSERT_TRUE(CGAL::is_valid_polygon_mesh(tm));
    ASSERT_EQ(euler_characteristic(tm), 0);
    Mesh qm;
    PVF::Quad_extraction_result r;
    ASSERT_EQ(PVF::extract_quad_mesh(tm, uv, qm, r, PVF::parameters::keep_trimmed_boundary(true)), PVF::Error_code::SUCCESS)
      << r.diagnostic;
    EXPECT_EQ(r.flipped_faces, 0u);
    EXPECT_EQ(r.integer_points, 1u);
    EXPECT_EQ(r.singular_points, 0u);
    EXPECT_EQ(r.inconsistencies, 0u);
    EXPECT_EQ(r.split_cells, 2u);
    EXPECT_EQ(r.added_vertices, 2u);
    EXPECT_EQ(r.quads, 0u);
    EXPECT_EQ(r.trimmed_polygons, 4u);
    ASSERT_TRUE(CGAL::is_valid_polygon_mesh(qm));
    EXPECT_EQ(num_faces(qm), 4u);
    EXPECT_EQ(r.faces, 4u);
    // the integer point, the two added points, the two ends of u = 0 on the border, the 2 n border vertices
    EXPECT_EQ(num_vertices(qm), 2 * n + 5);
    EXPECT_EQ(euler_characteristic(qm), 0);
    EXPECT_EQ(quad_border_cycles(qm), 2u);
    for(Face f : faces(qm))
    {
      std::set<Vertex> corners;
      for(Halfedge h : CGAL::halfedges_around_face(halfedge(f, qm), qm))
        corners.insert(target(h, qm));
      EXPECT_GE(corners.size(), 3u);
      EXPECT_EQ(corners.size(), degree(f, qm));
    }
    EXPECT_LE(quad_max_distance_to(tm, qm), 1e-12);

    Mesh whole;
    PVF::Quad_extraction_result rw;
    EXPECT_EQ(PVF::extract_quad_mesh(tm, uv, whole, rw), PVF::Error_code::NO_INTEGER_CELL);
    EXPECT_EQ(num_faces(whole), 0u);
  }
}

// On a torus one quad of the map in both directions, the one whole cell passes four
// times through the integer point: NON_DISK_CELL (the quad size is larger than the
// torus), never a mesh that is not valid, and the output left untouched.
TEST(QuadWrappingCells, OneCellTorusIsRefusedAsWholeCells)
{
  Quad_uv_map uv;
  const Mesh tm = quad_tube(8, 6, true, 0.3125, 0.375, uv);
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(tm));
  ASSERT_TRUE(CGAL::is_closed(tm));
  Mesh qm = grid(1, 2);
  PVF::Quad_extraction_result r;
  EXPECT_EQ(PVF::extract_quad_mesh(tm, uv, qm, r), PVF::Error_code::NON_DISK_CELL);
  EXPECT_EQ(r.integer_points, 1u);
  EXPECT_EQ(r.inconsistencies, 0u);
  EXPECT_NE(r.diagnostic.find("the quad size is larger than that part of the surface"), std::string::npos) << r.diagnostic;
  EXPECT_EQ(num_faces(qm), 4u);  // untouched
  EXPECT_STREQ(PVF::get_error_message(PVF::Error_code::NON_DISK_CELL),
               "the quad size is larger than a part of the surface: a cell of the map goes around a hole or a handle, or "
               "passes twice through a point, so it is not a polygon of the quad mesh");
}
