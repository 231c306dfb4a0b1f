// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Topology (paper Section 3.4, NOTES §4): singularity indices and principal matching.

#include "test_meshes.h"

#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>
#include <CGAL/Polyvector_fields/design_polyvector_field.h>

#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/tags.h>

#include <boost/functional/hash.hpp>
#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <complex>
#include <cstring>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace PVF = CGAL::Polyvector_fields;
using namespace pvf_test;

typedef std::complex<double> Complex;
typedef Mesh::Face_index Face;
typedef Mesh::Vertex_index Vertex;
typedef PVF::Face_constraint<Face, Vector> Constraint;

namespace {

// Designs a field and returns its singularities; also checks that every
// interior vertex's index is an integer multiple of 1/N up to round-off.
std::vector<PVF::Singularity<Vertex> > singularities(Mesh& tm, std::size_t N, bool sign_symmetric,
                                                     const std::vector<Constraint>& constraints)
{
  auto cmap = tm.add_property_map<Face, std::vector<Complex> >("f:c").first;
  EXPECT_EQ(PVF::design_polyvector_field(tm, N, constraints, cmap, PVF::parameters::sign_symmetric(sign_symmetric)),
            PVF::Error_code::SUCCESS);
  PVF::Tangent_bundle<Mesh> connection(tm);
  std::vector<Complex> flat;
  EXPECT_EQ(PVF::internal::read_coefficients(connection, N, cmap, flat), PVF::Error_code::SUCCESS);
  double worst = 0;
  for(Vertex v : vertices(tm))
  {
    if(CGAL::is_border(v, tm))
      continue;
    bool defined;
    double residual;
    PVF::internal::index_numerator(connection, N, flat, halfedge(v, tm), defined, residual);
    EXPECT_TRUE(defined);
    worst = (std::max)(worst, residual);
  }
  EXPECT_LT(worst, 1e-6) << "indices are not multiples of 1/N: wrong orientation convention?";
  std::vector<PVF::Singularity<Vertex> > found;
  std::vector<Vertex> undefined;
  EXPECT_EQ(PVF::compute_singularities(tm, N, cmap, std::back_inserter(found), std::back_inserter(undefined)),
            PVF::Error_code::SUCCESS);
  EXPECT_TRUE(undefined.empty());
  tm.remove_property_map(cmap);
  return found;
}

} // namespace

// Poincaré–Hopf: on a closed mesh the numerators sum to N times the Euler characteristic.
TEST(Topology, PoincareHopf)
{
  struct Named { std::string name; Mesh mesh; };
  std::vector<Named> meshes;
  meshes.push_back({ "sphere", sphere(3) });
  meshes.push_back({ "torus", torus(40, 20) });
  meshes.push_back({ "eight.off", load("eight.off") });
  meshes.push_back({ "bumpy.off", load("bumpy.off") });
  const int expected_chi[] = { 2, 0, -2, 2 };
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    Mesh& tm = meshes[i].mesh;
    ASSERT_EQ(euler_characteristic(tm), expected_chi[i]) << meshes[i].name;
    for(std::size_t N : { 1u, 2u, 4u, 6u })
    {
      const bool sign_symmetric = (N >= 4);
      const auto constraints = random_constraints(tm, 12, sign_symmetric ? N / 2 : N, unsigned(N + 100 * i));
      int sum = 0;
      for(const auto& s : singularities(tm, N, sign_symmetric, constraints))
      {
        EXPECT_NE(s.index_numerator, 0);
        sum += s.index_numerator;
      }
      EXPECT_EQ(sum, int(N) * expected_chi[i]) << meshes[i].name << ", N = " << N;
    }
  }
}

// A radial field imposed on the boundary of a flat square has total index +1
// (numerators summing to N): for N = 1, 2 a single singularity at the centre;
// a 4-PolyVector field splits it into four +1/4 singularities placed
// symmetrically about the centre, as cross fields do.
TEST(Topology, RadialFieldHasIndexOneAtCentre)
{
  for(std::size_t N : { 1u, 2u, 4u })
  {
    Mesh tm = grid(10, 10);
    const Point centre(5, 5, 0);
    std::vector<Constraint> constraints;
    for(Face f : faces(tm))
    {
      bool on_border = false;
      Vector barycentre(0, 0, 0);
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      {
        on_border = on_border || CGAL::is_border(opposite(h, tm), tm);
        barycentre = barycentre + (tm.point(target(h, tm)) - CGAL::ORIGIN) / 3.0;
      }
      if(!on_border)
        continue;
      const Vector radial = (CGAL::ORIGIN + barycentre) - centre;
      Constraint c{ f, {} };
      // N vectors: the radial direction turned by multiples of 2 pi / N.
      for(std::size_t k = 0; k < N; ++k)
      {
        const double a = 2 * CGAL_PI * double(k) / double(N);
        c.vectors.push_back(Vector(std::cos(a) * radial.x() - std::sin(a) * radial.y(),
                                   std::sin(a) * radial.x() + std::cos(a) * radial.y(), 0));
      }
      constraints.push_back(c);
    }
    const auto found = singularities(tm, N, false, constraints);
    int sum = 0;
    Vector mean(0, 0, 0);
    for(const auto& s : found)
    {
      sum += s.index_numerator;
      mean = mean + (tm.point(s.vertex) - centre) / double(found.size());
    }
    EXPECT_EQ(sum, int(N));
    EXPECT_LT(mean.squared_length(), 1e-24);
    if(N < 4)
    {
      ASSERT_EQ(found.size(), 1u) << "N = " << N;
      EXPECT_EQ(tm.point(found[0].vertex), centre);
    }
    else
    {
      ASSERT_EQ(found.size(), 4u);
      for(const auto& s : found)
        EXPECT_EQ(s.index_numerator, 1);
    }
  }
}

// Principal matching on a constant field of a flat mesh matches each
// transported root with the root it is parallel to.
TEST(Topology, PrincipalMatchingOnConstantField)
{
  Mesh tm = grid(6, 6);
  const std::size_t N = 3;
  const std::vector<Vector> vectors{ Vector(1, 0.2, 0), Vector(-0.3, 1, 0), Vector(-1, -1.5, 0) };
  std::vector<Constraint> constraints{ Constraint{ Face(0), vectors }, Constraint{ Face(50), vectors } };
  auto cmap = tm.add_property_map<Face, std::vector<Complex> >("f:c").first;
  auto rmap = tm.add_property_map<Face, std::vector<Vector> >("f:r").first;
  ASSERT_EQ(PVF::design_polyvector_field(tm, N, constraints, cmap), PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::compute_field_roots(tm, N, cmap, rmap), PVF::Error_code::SUCCESS);
  auto matching = tm.add_property_map<Mesh::Edge_index, int>("e:m", -1).first;
  ASSERT_EQ(PVF::principal_matching(tm, N, cmap, matching), PVF::Error_code::SUCCESS);
  std::size_t checked = 0;
  for(auto e : edges(tm))
  {
    const auto h = halfedge(e, tm);
    if(CGAL::is_border_edge(h, tm))
    {
      EXPECT_EQ(matching[e], -1);
      continue;
    }
    const int s = matching[e];
    ASSERT_GE(s, 0);
    ASSERT_LT(s, int(N));
    const auto& a = rmap[face(h, tm)];
    const auto& b = rmap[face(opposite(h, tm), tm)];
    for(std::size_t i = 0; i < N; ++i)
      EXPECT_LT(distance(a[i], b[(i + std::size_t(s)) % N]), 1e-9);
    ++checked;
  }
  EXPECT_GT(checked, 0u);
}

// A face with a zero constant coefficient makes the index of its vertices
// undefined: they are reported, not guessed.
TEST(Topology, UndefinedIndexIsReported)
{
  Mesh tm = grid(4, 4);
  auto cmap = tm.add_property_map<Face, std::vector<Complex> >("f:c", std::vector<Complex>{ Complex(1), Complex(0) }).first;
  const Face zero(Mesh::size_type(12));
  cmap[zero] = { Complex(0), Complex(1) };
  std::vector<PVF::Singularity<Vertex> > found;
  std::vector<Vertex> undefined;
  ASSERT_EQ(PVF::compute_singularities(tm, 2, cmap, std::back_inserter(found), std::back_inserter(undefined)),
            PVF::Error_code::SUCCESS);
  std::set<Vertex> expected;
  for(Vertex v : CGAL::vertices_around_face(halfedge(zero, tm), tm))
    if(!CGAL::is_border(v, tm))
      expected.insert(v);
  EXPECT_FALSE(expected.empty());
  EXPECT_EQ(std::set<Vertex>(undefined.begin(), undefined.end()), expected);
  for(const auto& s : found)
    EXPECT_EQ(expected.count(s.vertex), 0u);

  // Malformed fields are refused.
  cmap[zero] = { Complex(0) };
  EXPECT_EQ(PVF::compute_singularities(tm, 2, cmap, std::back_inserter(found)), PVF::Error_code::INCONSISTENT_DEGREE);
}

// ---------------------------------------------------------------------------
// Parallel against sequential: the tangent bundle and the singularities are
// computed element by element, so CGAL::Parallel_tag must give the same bits
// as CGAL::Sequential_tag and as the one-element-at-a-time functions
// (face_frame(), edge_direction(), index_numerator()). The meshes have some
// 40,000-50,000 faces: several of TBB's ranges of 4096 faces or edges.
// ---------------------------------------------------------------------------
namespace {

typedef CGAL::Polyhedron_3<Kernel> Parallel_test_polyhedron;

// The number of elements of `a` and `b` (of equal size) whose bytes differ.
template <typename T>
std::size_t differing_bytes(const T& a, const T& b)
{
  return std::memcmp(&a, &b, sizeof(T)) == 0 ? 0 : 1;
}

// Expects `a` and `b` to be the same bundle, bit for bit.
template <typename Bundle>
void expect_identical_bundles(const Bundle& a, const Bundle& b, const std::string& what)
{
  ASSERT_EQ(a.status(), b.status()) << what;
  EXPECT_EQ(a.first_invalid_face(), b.first_invalid_face()) << what;
  ASSERT_EQ(a.number_of_faces(), b.number_of_faces()) << what;
  ASSERT_EQ(a.number_of_vertices(), b.number_of_vertices()) << what;
  std::size_t faces = 0, frames = 0, vertices = 0, edges = 0, components = 0;
  for(std::size_t i = 0; i < a.number_of_faces(); ++i)
  {
    faces += a.face(i) == b.face(i) && a.index(a.face(i)) == i && b.index(b.face(i)) == i ? 0 : 1;
    frames += differing_bytes(a.frame(i), b.frame(i));
  }
  for(std::size_t i = 0; i < a.number_of_vertices(); ++i)
    vertices += a.vertex(i) == b.vertex(i) && b.index(b.vertex(i)) == i ? 0 : 1;
  ASSERT_EQ(a.interior_edges().size(), b.interior_edges().size()) << what;
  for(std::size_t i = 0; i < a.interior_edges().size(); ++i)
  {
    const auto& d = a.interior_edges()[i];
    const auto& e = b.interior_edges()[i];
    edges += d.h == e.h && d.f == e.f && d.g == e.g ? differing_bytes(d.e_f, e.e_f) + differing_bytes(d.e_g, e.e_g) : 1;
  }
  if(a.status() == PVF::Error_code::SUCCESS)
  {
    EXPECT_EQ(a.number_of_components(), b.number_of_components()) << what;
    for(std::size_t i = 0; i < a.number_of_faces(); ++i)
      components += a.component(i) == b.component(i) ? 0 : 1;
  }
  EXPECT_EQ(faces, 0u) << what;
  EXPECT_EQ(frames, 0u) << what;
  EXPECT_EQ(vertices, 0u) << what;
  EXPECT_EQ(edges, 0u) << what;
  EXPECT_EQ(components, 0u) << what;
}

// Builds the bundle of `tm` sequentially, in parallel and with the default tag,
// expects them identical, and identical to face_frame() and edge_direction().
template <typename TriangleMesh>
void expect_parallel_bundle_identical(const TriangleMesh& tm, const std::string& what)
{
  typedef PVF::Tangent_bundle<TriangleMesh> Bundle;
  const Bundle sequential(tm, CGAL::Sequential_tag());
  const Bundle by_default(tm);
  ASSERT_EQ(sequential.status(), PVF::Error_code::SUCCESS) << what;
  ASSERT_GT(sequential.number_of_faces(), 8 * 4096u) << what << ": too small to be split among threads";
  expect_identical_bundles(sequential, by_default, what + ", default tag");
#ifdef CGAL_LINKED_WITH_TBB
  const Bundle parallel(tm, CGAL::Parallel_tag());
  const Bundle with_map(tm, CGAL::get_const_property_map(CGAL::vertex_point, tm), CGAL::Parallel_tag());
  expect_identical_bundles(sequential, parallel, what + ", Parallel_tag");
  expect_identical_bundles(sequential, with_map, what + ", Parallel_tag and point map");
#else
  // CGAL::Parallel_tag needs TBB; the default tag is then sequential.
  const Bundle& parallel = by_default;
#endif

  std::size_t frames = 0, directions = 0;
  for(std::size_t i = 0; i < parallel.number_of_faces(); ++i)
  {
    PVF::Face_frame frame;
    ASSERT_EQ(PVF::face_frame(parallel.face(i), tm, frame), PVF::Error_code::SUCCESS);
    frames += differing_bytes(frame, parallel.frame(i));
  }
  for(const auto& d : parallel.interior_edges())
  {
    directions += differing_bytes(d.e_f, parallel.edge_direction(d.h));
    directions += differing_bytes(d.e_g, std::complex<double>(-parallel.edge_direction(opposite(d.h, tm))));
  }
  EXPECT_EQ(frames, 0u) << what;
  EXPECT_EQ(directions, 0u) << what;
}

// A bent, jittered grid with 96 x 250 quads, some faces removed: a boundary,
// holes and, for Surface_mesh, removed elements numbered around.
Mesh bent_grid_with_holes()
{
  Mesh tm = jittered_grid(96, 250, 17);
  for(auto v : vertices(tm))
  {
    const Point& p = tm.point(v);
    tm.point(v) = Point(p.x(), p.y(), 0.3 * std::sin(0.2 * p.x()) * std::cos(0.3 * p.y()));
  }
  std::vector<Face> removed;
  for(auto f : faces(tm))
    if(std::size_t(f) % 211 == 5)
      removed.push_back(f);
  for(Face f : removed)
    CGAL::Euler::remove_face(halfedge(f, tm), tm);
  EXPECT_TRUE(tm.has_garbage());
  return tm;
}

// The singularities of compute_singularities<Tag>() against those of the vertex-by-vertex loop of
// index_numerator() (the computation before the parallel one), on a random field with some zeros.
template <typename TriangleMesh>
void expect_parallel_singularities_identical(const TriangleMesh& tm, std::size_t N, const std::string& what)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const PVF::Tangent_bundle<TriangleMesh> bundle(tm, CGAL::Sequential_tag());
  std::unordered_map<face_descriptor, std::vector<Complex>, boost::hash<face_descriptor> > field;
  std::mt19937 rng(23);
  std::normal_distribution<double> normal;
  std::size_t i = 0;
  for(face_descriptor f : faces(tm))
  {
    std::vector<Complex> c(N);
    for(auto& x : c)
      x = Complex(normal(rng), normal(rng));
    if(i++ % 997 == 3)
      c[0] = Complex(0);  // undefined index at its vertices
    field[f] = c;
  }
  const auto cmap = boost::make_assoc_property_map(field);

  std::vector<Complex> flat;
  ASSERT_EQ(PVF::internal::read_coefficients(bundle, N, cmap, flat), PVF::Error_code::SUCCESS);
  std::vector<std::pair<vertex_descriptor, int> > expected_found;
  std::vector<vertex_descriptor> expected_undefined;
  for(std::size_t v = 0; v < bundle.number_of_vertices(); ++v)
  {
    const vertex_descriptor vd = bundle.vertex(v);
    if(halfedge(vd, tm) == boost::graph_traits<TriangleMesh>::null_halfedge() || CGAL::is_border(vd, tm))
      continue;
    bool defined;
    double residual;
    const int k = PVF::internal::index_numerator(bundle, N, flat, halfedge(vd, tm), defined, residual);
    if(!defined)
      expected_undefined.push_back(vd);
    else if(k != 0)
      expected_found.emplace_back(vd, k);
  }
  ASSERT_GT(expected_found.size(), 1000u) << what;
  ASSERT_GT(expected_undefined.size(), 10u) << what;

  auto check = [&](auto tag, const std::string& how) {
    typedef decltype(tag) Tag;
    std::vector<PVF::Singularity<vertex_descriptor> > found;
    std::vector<vertex_descriptor> undefined;
    ASSERT_EQ(PVF::compute_singularities<Tag>(bundle, N, cmap, std::back_inserter(found), std::back_inserter(undefined)),
              PVF::Error_code::SUCCESS);
    ASSERT_EQ(found.size(), expected_found.size()) << what << how;
    std::size_t differ = 0;
    for(std::size_t j = 0; j < found.size(); ++j)
      differ += found[j].vertex == expected_found[j].first && found[j].index_numerator == expected_found[j].second ? 0 : 1;
    EXPECT_EQ(differ, 0u) << what << how;
    EXPECT_TRUE(undefined == expected_undefined) << what << how;
    // The overload without undefined vertices.
    std::vector<PVF::Singularity<vertex_descriptor> > found_only;
    ASSERT_EQ(PVF::compute_singularities<Tag>(bundle, N, cmap, std::back_inserter(found_only)), PVF::Error_code::SUCCESS);
    EXPECT_EQ(found_only.size(), found.size()) << what << how;
  };
  check(CGAL::Sequential_tag(), ", Sequential_tag");
#ifdef CGAL_LINKED_WITH_TBB
  check(CGAL::Parallel_tag(), ", Parallel_tag");
#endif
  check(CGAL::Parallel_if_available_tag(), ", Parallel_if_available_tag");
}

Mesh subdivided_eight()
{
  Mesh tm = load("eight.off");
  CGAL::Subdivision_method_3::Loop_subdivision(tm, CGAL::parameters::number_of_iterations(1));
  return tm;
}

Parallel_test_polyhedron subdivided_bumpy_polyhedron()
{
  Parallel_test_polyhedron poly = load<Parallel_test_polyhedron>("bumpy.off");
  CGAL::Subdivision_method_3::Loop_subdivision(poly, CGAL::parameters::number_of_iterations(2));
  return poly;
}

} // namespace

TEST(Parallel, TangentBundleIsBitIdentical)
{
  expect_parallel_bundle_identical(subdivided_eight(), "eight.off subdivided");
  expect_parallel_bundle_identical(bent_grid_with_holes(), "bent grid with holes");
  expect_parallel_bundle_identical(subdivided_bumpy_polyhedron(), "bumpy.off subdivided, Polyhedron_3");
}

// Invalid faces in several ranges: every build reports the first one, with the same partial bundle.
TEST(Parallel, TangentBundleReportsTheFirstInvalidFace)
{
  Mesh tm = grid(100, 256);  // 51,200 faces
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for(std::size_t v : { 20000u, 7777u, 24000u })
    tm.point(Vertex(Mesh::size_type(v))) = Point(nan, 0, 0);
  std::size_t expected = std::size_t(-1), i = 0;
  for(Face f : faces(tm))
  {
    PVF::Face_frame frame;
    if(PVF::face_frame(f, tm, frame) != PVF::Error_code::SUCCESS)
    {
      expected = i;
      break;
    }
    ++i;
  }
  ASSERT_GT(expected, 4096u);
  ASSERT_LT(expected, 20000u);
  const PVF::Tangent_bundle<Mesh> sequential(tm, CGAL::Sequential_tag());
#ifdef CGAL_LINKED_WITH_TBB
  const PVF::Tangent_bundle<Mesh> parallel(tm, CGAL::Parallel_tag());
#else
  const PVF::Tangent_bundle<Mesh> parallel(tm);  // CGAL::Parallel_tag needs TBB; the default tag is then sequential
#endif
  EXPECT_EQ(sequential.status(), PVF::Error_code::DEGENERATE_FACE);
  EXPECT_EQ(sequential.first_invalid_face(), expected);
  EXPECT_TRUE(sequential.interior_edges().empty());
  std::size_t zero_frames = 0;
  for(std::size_t j = expected; j < parallel.number_of_faces(); ++j)
    zero_frames += differing_bytes(parallel.frame(j), PVF::Face_frame()) == 0 ? 1 : 0;
  EXPECT_EQ(zero_frames, parallel.number_of_faces() - expected);  // not computed
  expect_identical_bundles(sequential, parallel, "grid with invalid faces");
}

TEST(Parallel, SingularitiesAreBitIdentical)
{
  expect_parallel_singularities_identical(subdivided_eight(), 4, "eight.off subdivided");
  expect_parallel_singularities_identical(bent_grid_with_holes(), 3, "bent grid with holes");
  expect_parallel_singularities_identical(subdivided_bumpy_polyhedron(), 4, "bumpy.off subdivided, Polyhedron_3");
}
