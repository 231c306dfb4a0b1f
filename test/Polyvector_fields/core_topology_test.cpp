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

#include <gtest/gtest.h>

#include <complex>
#include <random>
#include <set>

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
