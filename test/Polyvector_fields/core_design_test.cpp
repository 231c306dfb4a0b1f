// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Field design (paper Section 3.6): transport, constraints, components,
// invariance, generic meshes and bad input.

#include "test_meshes.h"

#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/design_polyvector_field.h>
#include <CGAL/Polyvector_fields/smoothness_energy.h>

#include <CGAL/Polyhedron_3.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <complex>
#include <map>
#include <random>

namespace PVF = CGAL::Polyvector_fields;
using namespace pvf_test;

typedef std::complex<double> Complex;
typedef Mesh::Face_index Face;
typedef PVF::Face_constraint<Face, Vector> Constraint;
typedef Mesh::Property_map<Face, std::vector<Complex> > Coefficient_map;
typedef Mesh::Property_map<Face, std::vector<Vector> > Root_map;

namespace {

struct Field
{
  Coefficient_map coefficients;
  Root_map roots;
};

Field add_field(Mesh& tm, const std::string& name = "test")
{
  Field field;
  field.coefficients = tm.add_property_map<Face, std::vector<Complex> >("f:c_" + name).first;
  field.roots = tm.add_property_map<Face, std::vector<Vector> >("f:r_" + name).first;
  return field;
}

// Designs a field and its world roots; fails the test on error.
template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
Field design(Mesh& tm, std::size_t N, const std::vector<Constraint>& constraints,
             const NamedParameters& np = CGAL::parameters::default_values(), const std::string& name = "test")
{
  Field field = add_field(tm, name);
  EXPECT_EQ(PVF::design_polyvector_field(tm, N, constraints, field.coefficients, np), PVF::Error_code::SUCCESS);
  EXPECT_EQ(PVF::compute_field_roots(tm, N, field.coefficients, field.roots, np), PVF::Error_code::SUCCESS);
  return field;
}

// The constraint vectors projected onto the face plane, lengths kept, and
// completed with their opposites under sign symmetry.
std::vector<Vector> expected_roots(const Mesh& tm, const Constraint& c, bool sign_symmetric)
{
  PVF::Face_frame frame;
  PVF::face_frame(c.face, tm, frame);
  const Vector n(frame.normal[0], frame.normal[1], frame.normal[2]);
  std::vector<Vector> roots;
  for(const Vector& v : c.vectors)
  {
    Vector p = v - (v * n) * n;
    p = p * std::sqrt(v.squared_length() / p.squared_length());
    roots.push_back(p);
    if(sign_symmetric)
      roots.push_back(-p);
  }
  return roots;
}

double max_length(const std::vector<Vector>& vs)
{
  double m = 0;
  for(const Vector& v : vs)
    m = (std::max)(m, std::sqrt(v.squared_length()));
  return m;
}

} // namespace

// On a flat mesh, equal constraints give exactly that constant field and zero
// energy, for every degree: a wrong transport power fails at once (NOTES §1).
TEST(Design, FlatMeshConstantField)
{
  for(bool sign_symmetric : { false, true })
    for(std::size_t N = 1; N <= 6; ++N)
    {
      if(sign_symmetric && N % 2)
        continue;
      Mesh tm = grid(8, 9);
      Rigid_motion{ unsigned(N) }.move(tm);  // a tilted plane, not z = 0
      std::mt19937 rng{ unsigned(7 * N) };
      PVF::Face_frame frame;
      PVF::face_frame(*faces(tm).begin(), tm, frame);
      const Vector e1(frame.e1[0], frame.e1[1], frame.e1[2]), e2(frame.e2[0], frame.e2[1], frame.e2[2]);
      std::uniform_real_distribution<double> u(-1, 1);
      std::vector<Vector> field_vectors;  // in the plane
      for(std::size_t k = 0; k < (sign_symmetric ? N / 2 : N); ++k)
        field_vectors.push_back(u(rng) * e1 + u(rng) * e2);
      std::vector<Constraint> constraints;
      for(std::size_t f : { 0u, 40u, 101u, 143u })
        constraints.push_back(Constraint{ Face(Mesh::size_type(f)), field_vectors });
      Field field = design(tm, N, constraints, PVF::parameters::sign_symmetric(sign_symmetric));
      const Constraint expected{ constraints[0].face, field_vectors };
      const std::vector<Vector> target = expected_roots(tm, expected, sign_symmetric);
      double worst = 0;
      for(Face f : faces(tm))
        worst = (std::max)(worst, set_distance(field.roots[f], target));
      EXPECT_LT(worst, 1e-9 * max_length(target)) << "N = " << N << " sign symmetric " << sign_symmetric;
      const double energy = PVF::smoothness_energy(tm, N, field.coefficients);
      EXPECT_LT(energy, 1e-20 * std::pow(max_length(target), 2.0 * N) * double(num_faces(tm)))
        << "N = " << N;
    }
}

// N-RoSy constraints: only the constant coefficient is interpolated, all
// others are exactly zero everywhere (maximum principle, Section 3.6).
TEST(Design, RosyConstraintsGiveRosyField)
{
  Mesh tm = load("bumpy.off");
  for(std::size_t N : { 3u, 4u, 6u })
  {
    std::mt19937 rng{ unsigned(N) };
    std::vector<Constraint> constraints;
    for(std::size_t f : { 3u, 300u, 900u, 1500u, 2200u })
    {
      PVF::Face_frame frame;
      PVF::face_frame(Face(Mesh::size_type(f)), tm, frame);
      std::uniform_real_distribution<double> u(-1, 1);
      const Complex w(u(rng), u(rng));
      Constraint c{ Face(Mesh::size_type(f)), {} };
      for(std::size_t k = 0; k < N; ++k)
      {
        const std::array<double, 3> x = frame.to_world(w * std::polar(1.0, 2 * CGAL_PI * double(k) / double(N)));
        c.vectors.push_back(Vector(x[0], x[1], x[2]));
      }
      constraints.push_back(c);
    }
    PVF::Polyvector_field_designer<Mesh> designer(tm, N);
    ASSERT_EQ(designer.add_constraints(constraints), PVF::Error_code::SUCCESS);
    Field field = add_field(tm, "rosy" + std::to_string(N));
    ASSERT_EQ(designer.solve(field.coefficients), PVF::Error_code::SUCCESS);
    EXPECT_EQ(designer.statistics().number_of_degrees_solved, 1u);
    for(Face f : faces(tm))
    {
      EXPECT_GT(std::abs(field.coefficients[f][0]), 0.0);
      for(std::size_t m = 1; m < N; ++m)
        ASSERT_EQ(field.coefficients[f][m], Complex(0)) << "N = " << N << " m = " << m;
    }
  }
}

// Hard constraints are reproduced exactly (up to round-off).
TEST(Design, HardConstraintsAreReproduced)
{
  Mesh tm = load("bumpy.off");
  for(bool sign_symmetric : { false, true })
    for(std::size_t N : { 2u, 4u })
    {
      const auto constraints = random_constraints(tm, 12, sign_symmetric ? N / 2 : N, unsigned(N + 10 * sign_symmetric));
      Field field = design(tm, N, constraints, PVF::parameters::sign_symmetric(sign_symmetric));
      for(const Constraint& c : constraints)
      {
        const auto target = expected_roots(tm, c, sign_symmetric);
        EXPECT_LT(set_distance(field.roots[c.face], target), 1e-12 * max_length(target) * 16);
      }
    }
}

// Soft constraints converge to the hard solution as the weight grows.
TEST(Design, SoftConstraintsConvergeToHard)
{
  Mesh tm = load("bumpy.off");
  const std::size_t N = 4;
  auto constraints = random_constraints(tm, 10, 2, 5);
  Field hard = design(tm, N, constraints, PVF::parameters::sign_symmetric(true), "hard");
  double previous = std::numeric_limits<double>::infinity();
  for(double weight : { 1e-1, 1e1, 1e3, 1e5, 1e7 })
  {
    for(Constraint& c : constraints)
      c.weight = weight;
    Field soft = design(tm, N, constraints, PVF::parameters::sign_symmetric(true), "soft" + std::to_string(weight));
    double difference = 0;
    for(Face f : faces(tm))
      for(std::size_t m = 0; m < N; ++m)
        difference = (std::max)(difference, std::abs(soft.coefficients[f][m] - hard.coefficients[f][m]));
    EXPECT_LT(difference, previous) << "weight " << weight;
    previous = difference;
  }
  EXPECT_LT(previous, 1e-5);
}

// Partial constraints: every given vector is a root of its face; a vector
// given twice is a double root.
TEST(Design, PartialConstraintsHold)
{
  Mesh tm = load("bumpy.off");
  struct Case { std::size_t N; bool sign_symmetric; std::size_t k; };
  for(const Case& test : { Case{ 4, true, 1 }, Case{ 3, false, 1 }, Case{ 3, false, 2 }, Case{ 6, true, 2 }, Case{ 5, false, 3 } })
  {
    auto constraints = random_constraints(tm, 15, test.k, unsigned(test.N * 10 + test.k));
    // Two full constraints as well, for a change.
    auto full = random_constraints(tm, 2, test.sign_symmetric ? test.N / 2 : test.N, 99);
    for(const Constraint& c : full)
      if(std::none_of(constraints.begin(), constraints.end(), [&](const Constraint& d) { return d.face == c.face; }))
        constraints.push_back(c);
    Field field = design(tm, test.N, constraints, PVF::parameters::sign_symmetric(test.sign_symmetric),
                         "partial" + std::to_string(test.N) + std::to_string(test.k));
    for(const Constraint& c : constraints)
      for(const Vector& u : expected_roots(tm, c, test.sign_symmetric))
      {
        double nearest = std::numeric_limits<double>::infinity();
        for(const Vector& r : field.roots[c.face])
          nearest = (std::min)(nearest, distance(r, u));
        EXPECT_LT(nearest, 1e-9 * std::sqrt(u.squared_length())) << "N = " << test.N;
      }
  }

  // Multiplicity: the same vector twice in a degree-3 field.
  Mesh flat = grid(5, 5);
  Constraint twice{ Face(0), { Vector(1, 0.5, 0), Vector(1, 0.5, 0) } };
  Constraint other{ Face(30), { Vector(0, 1, 0), Vector(1, 1, 0), Vector(-1, 0.2, 0) } };
  Field field = design(flat, 3, { twice, other });
  int near = 0;
  for(const Vector& r : field.roots[Face(0)])
    near += distance(r, Vector(1, 0.5, 0)) < 1e-6;
  EXPECT_EQ(near, 2);
}

// A flat mesh constrained only partially keeps a free rotation: the
// regularised solve still returns a finite field that satisfies the constraint.
TEST(Design, PartialOnlyOnFlatMesh)
{
  Mesh tm = grid(6, 6);
  const Constraint c{ Face(10), { Vector(1, 2, 0) } };
  Field field = design(tm, 4, { c }, PVF::parameters::sign_symmetric(true));
  double nearest = std::numeric_limits<double>::infinity();
  for(const Vector& r : field.roots[Face(10)])
    nearest = (std::min)(nearest, distance(r, Vector(1, 2, 0)));
  EXPECT_LT(nearest, 1e-9);
  for(Face f : faces(tm))
    for(const Complex& x : field.coefficients[f])
      EXPECT_TRUE(std::isfinite(x.real()) && std::isfinite(x.imag()));
}

namespace {

// The degree-0 connection Laplacian (dense) of a mesh: A = D^H D.
Eigen::MatrixXcd dense_connection_laplacian(const Mesh& tm, std::size_t N)
{
  PVF::Tangent_bundle<Mesh> connection(tm);
  const Eigen::Index F = Eigen::Index(connection.number_of_faces());
  Eigen::MatrixXcd A = Eigen::MatrixXcd::Zero(F, F);
  for(const auto& e : connection.interior_edges())
  {
    const Complex a = std::pow(std::conj(e.e_f), int(N)), b = -std::pow(std::conj(e.e_g), int(N));
    const Eigen::Index f = Eigen::Index(e.f), g = Eigen::Index(e.g);
    A(f, f) += std::norm(a);
    A(g, g) += std::norm(b);
    A(f, g) += std::conj(a) * b;
    A(g, f) += std::conj(b) * a;
  }
  return A;
}

} // namespace

// A mesh with no constraint gets the smoothest unit N-RoSy field: the
// eigenvector of the smallest eigenvalue of the connection Laplacian.
TEST(Design, UnconstrainedComponentIsSmallestEigenvector)
{
  Mesh tm = sphere(2);  // 320 faces
  for(std::size_t N : { 1u, 4u })
  {
    Field field = design(tm, N, {}, CGAL::parameters::default_values(), "eig" + std::to_string(N));
    const Eigen::MatrixXcd A = dense_connection_laplacian(tm, N);
    const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>(A).eigenvalues()[0];
    Eigen::VectorXcd x(A.rows());
    PVF::Tangent_bundle<Mesh> connection(tm);
    double mean_square = 0;
    for(Face f : faces(tm))
    {
      x[Eigen::Index(connection.index(f))] = field.coefficients[f][0];
      mean_square += std::norm(field.coefficients[f][0]) / double(num_faces(tm));
      for(std::size_t m = 1; m < N; ++m)
        EXPECT_EQ(field.coefficients[f][m], Complex(0));
    }
    EXPECT_NEAR(mean_square, 1.0, 1e-12);
    const double rayleigh = (x.adjoint() * A * x)(0, 0).real() / x.squaredNorm();
    EXPECT_NEAR(rayleigh, smallest, 1e-7 * (1 + smallest)) << "N = " << N;
    EXPECT_LT((A * x - smallest * x).norm() / x.norm(), 1e-4) << "N = " << N;
  }
}

// Components are solved on their own: a constrained component gives the same
// field as alone, an unconstrained flat one a constant unit field.
TEST(Design, ComponentsAreIndependent)
{
  Mesh alone = load("bumpy.off");
  Mesh both = alone;
  Mesh flat = grid(4, 4);
  for(auto v : vertices(flat))
    flat.point(v) = flat.point(v) + Vector(10, 0, 0);
  CGAL::copy_face_graph(flat, both);
  const auto constraints = random_constraints(alone, 8, 2, 3);
  Field a = design(alone, 4, constraints, PVF::parameters::sign_symmetric(true));
  Field b = design(both, 4, constraints, PVF::parameters::sign_symmetric(true));
  for(Face f : faces(alone))
    EXPECT_LT(set_distance(a.roots[f], b.roots[f]), 1e-10);
  std::vector<Vector> first;
  for(Face f : faces(both))
  {
    if(std::size_t(f) < num_faces(alone))
      continue;
    if(first.empty())
      first = b.roots[f];
    EXPECT_LT(set_distance(b.roots[f], first), 1e-9);
    for(const Vector& r : b.roots[f])
      EXPECT_NEAR(r.squared_length(), 1.0, 1e-9);
  }
}

// A mesh with boundary: natural boundary conditions, constraints hold.
TEST(Design, MeshWithBoundary)
{
  Mesh tm = load("lilium.obj");
  ASSERT_TRUE(CGAL::is_triangle_mesh(tm));
  const auto constraints = random_constraints(tm, 20, 2, 11);
  Field field = design(tm, 4, constraints, PVF::parameters::sign_symmetric(true));
  for(const Constraint& c : constraints)
    EXPECT_LT(set_distance(field.roots[c.face], expected_roots(tm, c, true)), 1e-10);
  EXPECT_TRUE(std::isfinite(PVF::smoothness_energy(tm, 4, field.coefficients)));

  // The natural boundary condition: boundary edges carry no term, so on a flat
  // square with one constraint the field is that constraint everywhere, up to
  // the boundary (any term at the boundary would pull it away there).
  Mesh square = grid(6, 6);
  const Constraint c{ Face(17), { Vector(1, 2, 0), Vector(-3, 1, 0) } };
  Field flat = design(square, 4, std::vector<Constraint>{ c }, PVF::parameters::sign_symmetric(true), "flat");
  const std::vector<Vector> expected = expected_roots(square, c, true);
  for(Face f : faces(square))
    EXPECT_LT(set_distance(flat.roots[f], expected), 1e-12 * max_length(expected)) << "face " << f;
  EXPECT_LT(PVF::smoothness_energy(square, 4, flat.coefficients), 1e-20);
}

// World-space roots do not depend on a rigid motion of the mesh and the constraints.
TEST(Invariance, RigidMotion)
{
  for(bool sign_symmetric : { false, true })
  {
    const std::size_t N = sign_symmetric ? 4 : 3;
    Mesh tm = load("bumpy.off");
    const auto constraints = random_constraints(tm, 10, sign_symmetric ? 2 : 3, 17);
    Field field = design(tm, N, constraints, PVF::parameters::sign_symmetric(sign_symmetric));
    const Rigid_motion motion(23);
    Mesh moved = tm;
    motion.move(moved);
    std::vector<Constraint> moved_constraints = constraints;
    motion.move(moved_constraints);
    Field moved_field = design(moved, N, moved_constraints, PVF::parameters::sign_symmetric(sign_symmetric), "moved");
    double worst = 0;
    for(Face f : faces(tm))
    {
      std::vector<Vector> rotated;
      for(const Vector& r : field.roots[f])
        rotated.push_back(motion(r));
      worst = (std::max)(worst, set_distance(rotated, moved_field.roots[f]));
    }
    EXPECT_LT(worst, 1e-9);
  }
}

// World-space roots do not depend on the halfedge that defines each face frame.
TEST(Invariance, FaceFrameChoice)
{
  for(bool sign_symmetric : { false, true })
  {
    const std::size_t N = sign_symmetric ? 6 : 3;
    Mesh tm = load("bumpy.off");
    const auto constraints = random_constraints(tm, 10, 3, 29);
    Field field = design(tm, N, constraints, PVF::parameters::sign_symmetric(sign_symmetric));
    Mesh turned = tm;
    std::size_t i = 0;
    for(Face f : faces(turned))
    {
      auto h = halfedge(f, turned);
      for(std::size_t k = 0; k <= i % 2; ++k)
        h = next(h, turned);
      CGAL::set_halfedge(f, h, turned);
      ++i;
    }
    Field turned_field = design(turned, N, constraints, PVF::parameters::sign_symmetric(sign_symmetric), "turned");
    double worst = 0, frame_change = 0;
    for(Face f : faces(tm))
    {
      worst = (std::max)(worst, set_distance(field.roots[f], turned_field.roots[f]));
      frame_change = (std::max)(frame_change, std::abs(field.coefficients[f][0] - turned_field.coefficients[f][0]));
    }
    EXPECT_LT(worst, 1e-9);
    EXPECT_GT(frame_change, 1e-3);  // the coefficients themselves did change
  }
}

// Surface_mesh and Polyhedron_3 give the same field.
TEST(Generic, SurfaceMeshAndPolyhedron)
{
  typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
  typedef boost::graph_traits<Polyhedron>::face_descriptor P_face;
  Mesh sm = load("bumpy.off");
  Polyhedron poly = load<Polyhedron>("bumpy.off");
  const auto constraints = random_constraints(sm, 10, 2, 31);
  Field field = design(sm, 4, constraints, PVF::parameters::sign_symmetric(true));

  std::vector<P_face> poly_faces(faces(poly).begin(), faces(poly).end());
  std::vector<PVF::Face_constraint<P_face, Vector> > poly_constraints;
  for(const Constraint& c : constraints)
    poly_constraints.push_back({ poly_faces[std::size_t(c.face)], c.vectors, c.weight });
  std::map<P_face, std::vector<Complex> > coefficients;
  std::map<P_face, std::vector<Vector> > roots;
  auto cmap = boost::make_assoc_property_map(coefficients);
  auto rmap = boost::make_assoc_property_map(roots);
  ASSERT_EQ(PVF::design_polyvector_field(poly, 4, poly_constraints, cmap, PVF::parameters::sign_symmetric(true)),
            PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::compute_field_roots(poly, 4, cmap, rmap, PVF::parameters::sign_symmetric(true)), PVF::Error_code::SUCCESS);
  double worst = 0;
  for(std::size_t i = 0; i < poly_faces.size(); ++i)
    worst = (std::max)(worst, set_distance(roots[poly_faces[i]], field.roots[Face(Mesh::size_type(i))]));
  EXPECT_LT(worst, 1e-12);
}

// The designer factors once: new values on the same faces reuse the factorization
// and give the same field as a fresh design.
TEST(Designer, ResolveWithNewValues)
{
  Mesh tm = load("bumpy.off");
  PVF::Polyvector_field_designer<Mesh> designer(tm, 4, PVF::parameters::sign_symmetric(true));
  ASSERT_EQ(designer.status(), PVF::Error_code::SUCCESS);
  auto first = random_constraints(tm, 10, 2, 41);
  ASSERT_EQ(designer.add_constraints(first), PVF::Error_code::SUCCESS);
  Field a = add_field(tm, "a");
  ASSERT_EQ(designer.solve(a.coefficients), PVF::Error_code::SUCCESS);
  EXPECT_FALSE(designer.statistics().factorization_reused);

  auto second = random_constraints(tm, 10, 2, 41);  // same faces
  std::mt19937 rng(5);
  for(Constraint& c : second)
    for(Vector& v : c.vectors)
      v = random_vector(rng);
  designer.clear_constraints();
  ASSERT_EQ(designer.add_constraints(second), PVF::Error_code::SUCCESS);
  Field b = add_field(tm, "b");
  ASSERT_EQ(designer.solve(b.coefficients), PVF::Error_code::SUCCESS);
  EXPECT_TRUE(designer.statistics().factorization_reused);

  Field fresh = design(tm, 4, second, PVF::parameters::sign_symmetric(true), "fresh");
  double worst = 0;
  for(Face f : faces(tm))
    for(std::size_t m = 0; m < 4; ++m)
      worst = (std::max)(worst, std::abs(b.coefficients[f][m] - fresh.coefficients[f][m]));
  EXPECT_LT(worst, 1e-12);
}

// Every Error_code has its own message.
// A partial constraint whose number of vectors changes between two solves
// gives rows of another shape: the factorization cannot be reused, and the
// test of reuse must not compare matrices of different sizes (it aborted in
// Debug builds and read out of bounds in Release builds).
TEST(Designer, PartialConstraintChangesItsVectorCount)
{
  Mesh two;
  auto a = two.add_vertex(Point(0, 0, 0)), b = two.add_vertex(Point(1, 0, 0)), c = two.add_vertex(Point(0, 1, 0)),
       d = two.add_vertex(Point(1, 1, 0));
  two.add_face(a, b, c);
  two.add_face(b, d, c);
  PVF::Polyvector_field_designer<Mesh> designer(two, 4);
  const Vector u(1, 0, 0), v(0.5, 0.5, 0);
  ASSERT_EQ(designer.add_constraint(Face(0), { u }), PVF::Error_code::SUCCESS);
  ASSERT_EQ(designer.solve(boost::dummy_property_map()), PVF::Error_code::SUCCESS);
  designer.clear_constraints();
  ASSERT_EQ(designer.add_constraint(Face(0), { u, v }), PVF::Error_code::SUCCESS);
  ASSERT_EQ(designer.solve(boost::dummy_property_map()), PVF::Error_code::SUCCESS);
  EXPECT_FALSE(designer.statistics().factorization_reused);
  // Both vectors are roots of face 0's polynomial now.
  const std::vector<Complex>& coefficients = designer.coefficient_array();
  PVF::Face_frame frame;
  PVF::face_frame(Face(0), two, frame);
  for(const Vector& w : { u, v })
  {
    const Complex z = frame.to_complex(w.x(), w.y(), w.z());
    Complex p = std::pow(z, 4);
    for(int m = 0; m < 4; ++m)
      p += coefficients[std::size_t(m)] * std::pow(z, m);
    EXPECT_LT(std::abs(p), 1e-12);
  }
}

TEST(Errors, Messages)
{
  std::set<std::string> messages;
  for(int code = 0; code <= int(PVF::Error_code::DID_NOT_CONVERGE); ++code)
  {
    const std::string message = PVF::get_error_message(PVF::Error_code(code));
    EXPECT_FALSE(message.empty());
    EXPECT_NE(message, "unknown error");
    messages.insert(message);
  }
  EXPECT_EQ(messages.size(), std::size_t(int(PVF::Error_code::DID_NOT_CONVERGE) + 1));
  EXPECT_EQ(std::string(PVF::get_error_message(PVF::Error_code(1000))), "unknown error");
}

// Bad meshes and degrees are refused with their codes, the output untouched.
TEST(Errors, BadMeshesAndDegrees)
{
  auto code_for = [](const Mesh& tm, std::size_t N, bool sign_symmetric = false) {
    Mesh copy = tm;
    auto cmap = copy.add_property_map<Face, std::vector<Complex> >("f:c", std::vector<Complex>{ Complex(42) }).first;
    const PVF::Error_code code = PVF::design_polyvector_field(copy, N, std::vector<Constraint>(), cmap,
                                                              PVF::parameters::sign_symmetric(sign_symmetric));
    if(code != PVF::Error_code::SUCCESS)
      for(Face f : faces(copy))
        EXPECT_EQ(cmap[f], std::vector<Complex>{ Complex(42) });
    return code;
  };
  EXPECT_EQ(code_for(Mesh(), 4), PVF::Error_code::EMPTY_MESH);

  Mesh quad;
  auto a = quad.add_vertex(Point(0, 0, 0)), b = quad.add_vertex(Point(1, 0, 0)), c = quad.add_vertex(Point(1, 1, 0)),
       d = quad.add_vertex(Point(0, 1, 0));
  quad.add_face(a, b, c, d);
  EXPECT_EQ(code_for(quad, 4), PVF::Error_code::NON_TRIANGLE_FACE);

  Mesh degenerate = grid(3, 3);
  degenerate.point(*vertices(degenerate).begin()) = Point(1, 0, 0) + Vector(0.5, 0, 0) - Vector(0.5, 0, 0);
  // vertex 0 now coincides with vertex 1: its triangles have zero area
  EXPECT_EQ(code_for(degenerate, 4), PVF::Error_code::DEGENERATE_FACE);

  Mesh not_a_number = grid(3, 3);
  not_a_number.point(*vertices(not_a_number).begin()) = Point(std::nan(""), 0, 0);
  EXPECT_EQ(code_for(not_a_number, 4), PVF::Error_code::DEGENERATE_FACE);

  Mesh fine = grid(3, 3);
  EXPECT_EQ(code_for(fine, 0), PVF::Error_code::INVALID_DEGREE);
  EXPECT_EQ(code_for(fine, 3, true), PVF::Error_code::INVALID_DEGREE);
  EXPECT_EQ(code_for(fine, 4, true), PVF::Error_code::SUCCESS);

  // The input mesh is never changed.
  Mesh original = load("bumpy.off");
  const Mesh copy = original;
  auto cmap = original.add_property_map<Face, std::vector<Complex> >("f:c").first;
  ASSERT_EQ(PVF::design_polyvector_field(original, 4, random_constraints(original, 5, 2, 1), cmap,
                                         PVF::parameters::sign_symmetric(true)),
            PVF::Error_code::SUCCESS);
  for(auto v : vertices(copy))
    EXPECT_EQ(copy.point(v), original.point(v));
}

// Bad constraints are refused with their codes; add_constraints is all or nothing.
TEST(Errors, BadConstraints)
{
  Mesh tm = grid(4, 4);
  PVF::Polyvector_field_designer<Mesh> designer(tm, 4, PVF::parameters::sign_symmetric(true));
  PVF::Polyvector_field_designer<Mesh> general(tm, 3);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  EXPECT_EQ(designer.add_constraint(Face(1000), { Vector(1, 0, 0) }), PVF::Error_code::INVALID_FACE);
  EXPECT_EQ(designer.add_constraint(Face(0), {}), PVF::Error_code::EMPTY_CONSTRAINT);
  EXPECT_EQ(designer.add_constraint(Face(0), { Vector(0, 0, 0) }), PVF::Error_code::ZERO_CONSTRAINT_VECTOR);
  EXPECT_EQ(designer.add_constraint(Face(0), { Vector(0, 0, 1) }), PVF::Error_code::ZERO_CONSTRAINT_VECTOR);
  EXPECT_EQ(designer.add_constraint(Face(0), { Vector(nan, 0, 0) }), PVF::Error_code::NON_FINITE_VALUE);
  EXPECT_EQ(designer.add_constraint(Face(0), { Vector(inf, 0, 0) }), PVF::Error_code::NON_FINITE_VALUE);
  EXPECT_EQ(designer.add_constraint(Face(0), { Vector(1, 0, 0), Vector(0, 1, 0), Vector(1, 1, 0) }),
            PVF::Error_code::TOO_MANY_CONSTRAINT_VECTORS);
  EXPECT_EQ(general.add_constraint(Face(0), { Vector(1, 0, 0), Vector(0, 1, 0), Vector(1, 1, 0), Vector(1, 2, 0) }),
            PVF::Error_code::TOO_MANY_CONSTRAINT_VECTORS);
  EXPECT_EQ(designer.add_constraint(Face(0), { Vector(1, 0, 0) }, 0.0), PVF::Error_code::INVALID_WEIGHT);
  EXPECT_EQ(designer.add_constraint(Face(0), { Vector(1, 0, 0) }, -1.0), PVF::Error_code::INVALID_WEIGHT);
  EXPECT_EQ(designer.add_constraint(Face(0), { Vector(1, 0, 0) }, nan), PVF::Error_code::NON_FINITE_VALUE);
  EXPECT_EQ(designer.number_of_constraints(), 0u);

  EXPECT_EQ(designer.add_constraint(Face(0), { Vector(1, 0, 0) }), PVF::Error_code::SUCCESS);
  EXPECT_EQ(designer.add_constraint(Face(0), { Vector(0, 1, 0) }), PVF::Error_code::DUPLICATE_CONSTRAINT);
  const std::vector<Constraint> batch{ Constraint{ Face(1), { Vector(1, 0, 0) } }, Constraint{ Face(2), {} } };
  EXPECT_EQ(designer.add_constraints(batch), PVF::Error_code::EMPTY_CONSTRAINT);
  EXPECT_EQ(designer.number_of_constraints(), 1u);

  // Through the free function, the output stays untouched.
  auto cmap = tm.add_property_map<Face, std::vector<Complex> >("f:c", std::vector<Complex>{ Complex(7) }).first;
  EXPECT_EQ(PVF::design_polyvector_field(tm, 4, batch, cmap, PVF::parameters::sign_symmetric(true)),
            PVF::Error_code::EMPTY_CONSTRAINT);
  for(Face f : faces(tm))
    EXPECT_EQ(cmap[f], std::vector<Complex>{ Complex(7) });
}

// Malformed fields given to the evaluation functions.
TEST(Errors, BadFields)
{
  Mesh tm = grid(3, 3);
  auto cmap = tm.add_property_map<Face, std::vector<Complex> >("f:c", std::vector<Complex>(4, Complex(1))).first;
  auto rmap = tm.add_property_map<Face, std::vector<Vector> >("f:r").first;
  EXPECT_EQ(PVF::compute_field_roots(tm, 3, cmap, rmap), PVF::Error_code::INCONSISTENT_DEGREE);
  EXPECT_TRUE(std::isnan(PVF::smoothness_energy(tm, 3, cmap)));
  cmap[Face(2)][1] = Complex(std::nan(""), 0);
  EXPECT_EQ(PVF::compute_field_roots(tm, 4, cmap, rmap), PVF::Error_code::NON_FINITE_VALUE);
  EXPECT_TRUE(std::isnan(PVF::smoothness_energy(tm, 4, cmap)));
  for(Face f : faces(tm))
    EXPECT_TRUE(rmap[f].empty());
  EXPECT_EQ(PVF::compute_field_roots(tm, 4, cmap, rmap, PVF::parameters::sign_symmetric(true)),
            PVF::Error_code::NON_FINITE_VALUE);
}
