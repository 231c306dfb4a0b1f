// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// The fast solver paths against a simple one: the same designed fields with
// CHOLMOD (Cholmod_sparse_solver), Eigen's SimplicialLDLT (Simplicial_ldlt_solver)
// and a dense reference (Eigen's dense LDLT of the same matrix, through a
// SparseLinearAlgebraWithFactorTraits_d model written here) agree to 1e-10
// relative to the size of the field, on small meshes. The multigrid solver
// (Amg_sparse_solver) agrees with them to 1e-8 (its documented accuracy), with
// a coarsest level made small enough that these meshes get several levels, and
// so does the size-adaptive default (Adaptive_sparse_solver). The real CHOLMOD
// model's inverse_congruence() (the Schur complement of the integer-grid map)
// agrees with full solves of SimplicialLDLT, and its Solver_scope keeps
// OpenBLAS on one thread.

#include <CGAL/Polyvector_fields/Adaptive_sparse_solver.h>
#include <CGAL/Polyvector_fields/Amg_sparse_solver.h>
#include <CGAL/Polyvector_fields/Cholmod_solver.h>
#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/design_angle_bounded_frame_field.h>
#include <CGAL/Polyvector_fields/design_conjugate_frame_field.h>
#include <CGAL/Polyvector_fields/internal/Field_design/Coefficient_system.h>
#include <CGAL/Polyvector_fields/internal/Field_design/constraint_specification.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/mixed_integer_solve.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/subdivision_method_3.h>

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include "test_support.h"

#if defined(__unix__) || defined(__APPLE__)
#  include <dlfcn.h>
#endif

#include <cmath>
#include <complex>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <random>
#include <type_traits>
#include <vector>

namespace {

namespace PVF = CGAL::Polyvector_fields;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;
typedef PVF::Face_constraint<face_descriptor, Vector_3> Constraint;
typedef std::complex<double> Complex;
using pvf_test::designed_coefficients;
using pvf_test::relative_difference;

// A dense model of SparseLinearAlgebraWithFactorTraits_d on complex numbers:
// the whole matrix is stored and factored by Eigen's dense LDLT (Hermitian,
// pivoting). Only for small systems.
class Dense_LDLT_traits
{
public:
  typedef Complex NT;
  class Matrix
  {
  public:
    Matrix(std::size_t rows, std::size_t cols) : m(Eigen::MatrixXcd::Zero(Eigen::Index(rows), Eigen::Index(cols))) {}
    void add_coef(std::size_t i, std::size_t j, const NT& value) { m(Eigen::Index(i), Eigen::Index(j)) += value; }
    void set_coef(std::size_t i, std::size_t j, const NT& value, bool = false) { m(Eigen::Index(i), Eigen::Index(j)) = value; }
    std::size_t row_dimension() const { return std::size_t(m.rows()); }
    std::size_t column_dimension() const { return std::size_t(m.cols()); }
    Eigen::MatrixXcd m;
  };
  typedef std::vector<NT> Vector;

  bool factor(const Matrix& A, NT& D)
  {
    m_ldlt.compute(A.m);
    D = NT(1);
    return m_ldlt.info() == Eigen::Success && m_ldlt.isPositive();
  }
  bool linear_solver(const Vector& b, Vector& x)
  {
    const Eigen::VectorXcd B = Eigen::Map<const Eigen::VectorXcd>(b.data(), Eigen::Index(b.size()));
    const Eigen::VectorXcd X = m_ldlt.solve(B);
    x.assign(X.data(), X.data() + X.size());
    return m_ldlt.info() == Eigen::Success;
  }

private:
  Eigen::LDLT<Eigen::MatrixXcd> m_ldlt;
};

// A closed surface (icosahedron after two Loop subdivisions: 320 faces, projected
// onto the unit sphere then made bumpy) and an open one (a 12 x 10 grid with a height field).
Mesh closed_mesh()
{
  Mesh tm;
  CGAL::make_icosahedron<Mesh, Point_3>(tm, Point_3(0, 0, 0), 1.0);
  CGAL::Subdivision_method_3::Loop_subdivision(tm, CGAL::parameters::number_of_iterations(2));
  for(auto v : tm.vertices())
  {
    const Vector_3 p = tm.point(v) - CGAL::ORIGIN;
    const double r = std::sqrt(p.squared_length());
    const double bump = 1.0 + 0.15 * std::sin(3 * p.x() / r) * std::cos(2 * p.y() / r);
    tm.point(v) = CGAL::ORIGIN + (bump / r) * p;
  }
  return tm;
}

Mesh open_mesh()
{
  Mesh tm;
  CGAL::make_grid(12, 10, tm, [](std::size_t i, std::size_t j) {
    const double x = double(i) / 12, y = double(j) / 10;
    return Point_3(x, y, 0.2 * std::sin(4 * x) * std::cos(3 * y));
  }, true);
  return tm;
}

// Hard constraints on `count` faces (faces spread over the mesh), general frames
// {±u, ±v} when sign-symmetric, N independent vectors otherwise, some soft.
std::vector<Constraint> constraints_for(const Mesh& tm, std::size_t N, bool sign_symmetric, std::size_t count,
                                        std::size_t partial = 0)
{
  std::vector<face_descriptor> faces(tm.faces().begin(), tm.faces().end());
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(0, 2 * CGAL_PI), length(0.5, 1.5);
  std::vector<Constraint> constraints;
  const std::size_t step = faces.size() / count;
  for(std::size_t i = 0; i < count; ++i)
  {
    const face_descriptor f = faces[i * step];
    const auto h = tm.halfedge(f);
    const Vector_3 a = tm.point(tm.target(h)) - tm.point(tm.source(h));
    const Vector_3 b = tm.point(tm.target(tm.next(h))) - tm.point(tm.source(h));
    const Vector_3 n = CGAL::cross_product(a, b);
    const Vector_3 e1 = a / std::sqrt(a.squared_length());
    Vector_3 e2 = CGAL::cross_product(n, a);
    e2 = e2 / std::sqrt(e2.squared_length());
    std::size_t k = sign_symmetric ? N / 2 : N;
    if(i < partial)
      k = 1;
    Constraint c;
    c.face = f;
    for(std::size_t j = 0; j < k; ++j)
    {
      const double t = angle(rng);
      c.vectors.push_back(length(rng) * (std::cos(t) * e1 + std::sin(t) * e2));
    }
    if(i % 3 == 2)
      c.weight = 10.0;  // soft
    constraints.push_back(c);
  }
  return constraints;
}

struct Case
{
  const char* name;
  bool closed;
  std::size_t N;
  bool sign_symmetric;
  std::size_t count, partial;
};

const Case cases[] = {
  { "frame field, closed", true, 4, true, 12, 0 },
  { "frame field, open, partial", false, 4, true, 10, 4 },
  { "N = 3, closed, partial", true, 3, false, 8, 3 },
  { "N = 6, open", false, 6, false, 6, 0 },
};

TEST(SolverAgreement, SimplicialLDLTMatchesDenseLDLT)
{
  for(const Case& c : cases)
  {
    SCOPED_TRACE(c.name);
    const Mesh tm = c.closed ? closed_mesh() : open_mesh();
    const auto constraints = constraints_for(tm, c.N, c.sign_symmetric, c.count, c.partial);
    const auto dense = designed_coefficients<Dense_LDLT_traits>(tm, c.N, c.sign_symmetric, constraints);
    const auto ldlt = designed_coefficients<PVF::Simplicial_ldlt_solver>(tm, c.N, c.sign_symmetric, constraints);
    ASSERT_EQ(dense.size(), tm.number_of_faces() * c.N);
    EXPECT_LT(relative_difference(dense, ldlt), 1e-10);
    // The field is not trivial: a zero field would agree with anything.
    double largest = 0;
    for(const Complex& z : dense)
      largest = (std::max)(largest, std::abs(z));
    EXPECT_GT(largest, 0.1);
  }
}

TEST(SolverAgreement, CholmodMatchesSimplicialLDLTAndDense)
{
#ifndef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
  GTEST_SKIP() << "CHOLMOD is not available in this build";
#else
  for(const Case& c : cases)
  {
    SCOPED_TRACE(c.name);
    const Mesh tm = c.closed ? closed_mesh() : open_mesh();
    const auto constraints = constraints_for(tm, c.N, c.sign_symmetric, c.count, c.partial);
    const auto dense = designed_coefficients<Dense_LDLT_traits>(tm, c.N, c.sign_symmetric, constraints);
    const auto ldlt = designed_coefficients<PVF::Simplicial_ldlt_solver>(tm, c.N, c.sign_symmetric, constraints);
    const auto cholmod = designed_coefficients<PVF::Cholmod_sparse_solver>(tm, c.N, c.sign_symmetric, constraints);
    EXPECT_LT(relative_difference(dense, cholmod), 1e-10);
    EXPECT_LT(relative_difference(ldlt, cholmod), 1e-10);
  }
#endif
}

// The iterations refactor numerically with a new lambda at every step: the
// CHOLMOD path (symbolic analysis kept) must follow the SimplicialLDLT one.
TEST(SolverAgreement, CholmodAngleBoundMatchesSimplicialLDLT)
{
#ifndef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
  GTEST_SKIP() << "CHOLMOD is not available in this build";
#else
  const Mesh tm = closed_mesh();
  const auto constraints = constraints_for(tm, 4, true, 12);
  std::map<face_descriptor, std::vector<Complex> > a, b;
  PVF::Angle_bound_result ra, rb;
  ASSERT_EQ(PVF::design_angle_bounded_frame_field(tm, constraints, boost::make_assoc_property_map(a), ra,
                                                  CGAL::parameters::sparse_linear_solver(PVF::Simplicial_ldlt_solver())),
            PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::design_angle_bounded_frame_field(
              tm, constraints, boost::make_assoc_property_map(b), rb,
              CGAL::parameters::sparse_linear_solver(PVF::Cholmod_sparse_solver())),
            PVF::Error_code::SUCCESS);
  EXPECT_GT(ra.iterations, 0u);
  EXPECT_EQ(ra.iterations, rb.iterations);
  std::vector<Complex> ca, cb;
  for(face_descriptor f : tm.faces())
  {
    ASSERT_EQ(a[f].size(), 4u);
    ASSERT_EQ(b[f].size(), 4u);
    ca.insert(ca.end(), a[f].begin(), a[f].end());
    cb.insert(cb.end(), b[f].begin(), b[f].end());
  }
  EXPECT_LT(relative_difference(ca, cb), 1e-10);
#endif
}

// The frame-field iterations refactor with new weights by accumulating the new
// values into the assembled matrices (same pattern, analysis kept); the result
// must be the one of a system assembled and analysed from scratch.
template <typename Solver>
void check_refactor_matches_fresh_factorization(const char* name)
{
  SCOPED_TRACE(name);
  typedef PVF::Tangent_bundle<Mesh> Bundle;
  typedef PVF::internal::Coefficient_system<Bundle, Solver> System;
  const Mesh tm = closed_mesh();
  const Bundle bundle(tm);
  const std::size_t F = bundle.number_of_faces();
  PVF::internal::Specifications specifications;
  for(const auto& c : constraints_for(tm, 4, true, 12))
  {
    PVF::internal::Face_specification s;
    ASSERT_EQ(PVF::internal::make_face_specification(bundle.frame(bundle.index(c.face)), c.vectors, c.weight, 4, true, s),
              PVF::Error_code::SUCCESS);
    specifications[bundle.index(c.face)] = s;
  }
  // The smooth field, then targets: the smooth field rotated by a face-dependent angle.
  System smooth(bundle, 4, { 0, 2 }, Solver());
  smooth.specifications() = specifications;
  std::vector<Complex> targets;
  ASSERT_TRUE(smooth.factor() && smooth.solve(targets));
  for(std::size_t f = 0; f < F; ++f)
  {
    targets[4 * f] *= std::polar(1.0, 0.3 * std::sin(double(f)));
    targets[4 * f + 2] *= std::polar(1.0, -0.2 * std::cos(double(f)));
  }
  // Data weights lambda s_f, plus 0.25 on c_2 (an orthogonality term).
  auto set_weights = [&](System& system, double lambda) {
    PVF::internal::Data_term& data = system.data_term();
    data.weight.assign(2, std::vector<double>(F));
    data.target.assign(2, std::vector<Complex>(F));
    for(std::size_t f = 0; f < F; ++f)
    {
      const double s_f = 0.5 + 0.5 * std::abs(std::sin(0.7 * double(f)));
      data.weight[0][f] = lambda * s_f;
      data.weight[1][f] = lambda * s_f + 0.25;
      data.target[0][f] = targets[4 * f];
      data.target[1][f] = targets[4 * f + 2] * (lambda * s_f / (lambda * s_f + 0.25));
    }
  };
  System refactored(bundle, 4, { 0, 2 }, Solver());
  refactored.specifications() = specifications;
  std::vector<Complex> first, second, fresh;
  set_weights(refactored, 3.0);
  ASSERT_TRUE(refactored.factor() && refactored.solve(first));
  set_weights(refactored, 40.0);
  ASSERT_TRUE(refactored.refactor() && refactored.solve(second));
  System from_scratch(bundle, 4, { 0, 2 }, Solver());
  from_scratch.specifications() = specifications;
  set_weights(from_scratch, 40.0);
  ASSERT_TRUE(from_scratch.factor() && from_scratch.solve(fresh));
  EXPECT_LT(relative_difference(fresh, second), 1e-12);
  EXPECT_GT(relative_difference(first, second), 1e-3);  // the weights did change the field
}

TEST(SolverAgreement, RefactorWithNewWeightsMatchesFreshFactorization)
{
  check_refactor_matches_fresh_factorization<PVF::Simplicial_ldlt_solver>("SimplicialLDLT");
#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
  check_refactor_matches_fresh_factorization<PVF::Cholmod_sparse_solver>("CHOLMOD");
#endif
  check_refactor_matches_fresh_factorization<Dense_LDLT_traits>("dense");
}

// The direct solver is CHOLMOD exactly when the program is linked with
// CHOLMOD (asked of the dynamic linker, not of the macros that chose it), and
// Eigen's SimplicialLDLT otherwise; the default adapts between it and multigrid.
TEST(SolverAgreement, DirectSolverIsCholmodWhenLinked)
{
  EXPECT_TRUE((std::is_same<PVF::Default_sparse_solver, PVF::Adaptive_sparse_solver<PVF::Direct_sparse_solver> >::value));
#if defined(__unix__) || defined(__APPLE__)
  const bool linked = dlsym(RTLD_DEFAULT, "cholmod_analyze") != nullptr;
  EXPECT_EQ((std::is_same<PVF::Direct_sparse_solver, PVF::Simplicial_ldlt_solver>::value), !linked);
#  ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
  EXPECT_EQ((std::is_same<PVF::Direct_sparse_solver, PVF::Cholmod_sparse_solver>::value), linked);
#  endif
#else
  GTEST_SKIP() << "no dlsym";
#endif
}

// ---------------------------------------------------------------------------
// Multigrid-preconditioned conjugate gradient.
// ---------------------------------------------------------------------------

// A multigrid solver whose coarsest level is small enough for the meshes of
// these tests (320 and 240 faces) to get three or four levels.
PVF::Amg_sparse_solver small_amg(int reuse = 2, bool warm_start = true, int max_iterations = 200)
{
  PVF::Amg_sparse_solver amg;
  amg.parameters().coarsest_size = 8;
  amg.parameters().reuse = reuse;
  amg.parameters().warm_start = warm_start;
  amg.parameters().max_iterations = max_iterations;
  return amg;
}

// Every case: decoupled degrees, partial constraints (one coupled block of
// two unknowns per free face, the null-space parametrisation), N = 3 and 6.
TEST(SolverAgreement, AmgMatchesSimplicialLDLT)
{
  for(const Case& c : cases)
  {
    SCOPED_TRACE(c.name);
    const Mesh tm = c.closed ? closed_mesh() : open_mesh();
    const auto constraints = constraints_for(tm, c.N, c.sign_symmetric, c.count, c.partial);
    const auto ldlt = designed_coefficients<PVF::Simplicial_ldlt_solver>(tm, c.N, c.sign_symmetric, constraints);
    const PVF::Amg_sparse_solver amg = small_amg();
    const auto a = designed_coefficients<PVF::Amg_sparse_solver, CGAL::Sequential_tag>(tm, c.N, c.sign_symmetric, constraints, &amg);
    EXPECT_LT(relative_difference(ldlt, a), 1e-8);
    const PVF::Amg_statistics s = amg.statistics();
    EXPECT_GE(s.level_sizes.size(), 3u);  // real multigrid, not the dense coarsest level alone
    EXPECT_GT(s.solves, 0u);
    EXPECT_EQ(s.fallbacks, 0u);
    EXPECT_LE(s.max_residual, amg.parameters().tolerance);
    EXPECT_LE(s.max_iterations, 40u);
  }
}

// A mesh the default settings coarsen (bumpy after one Loop subdivision, 9984
// faces): the default tolerance keeps the field within 1e-8 of the direct
// solver's, in 15 to 25 iterations; degrees in parallel give the same bits.
TEST(SolverAgreement, AmgDefaultsOnTenThousandFaces)
{
  Mesh tm;
  {
    std::ifstream in(std::string(PVF_DATA_DIR) + "/bumpy.off");
    ASSERT_TRUE(CGAL::IO::read_OFF(in, tm));
  }
  CGAL::Subdivision_method_3::Loop_subdivision(tm, CGAL::parameters::number_of_iterations(1));
  ASSERT_EQ(tm.number_of_faces(), 9984u);
  const auto constraints = constraints_for(tm, 4, true, 100, 30);  // partial: one coupled block
  const auto full = constraints_for(tm, 4, true, 100);
  for(const auto* set : { &full, &constraints })
  {
    const auto ldlt = designed_coefficients<PVF::Simplicial_ldlt_solver>(tm, 4, true, *set);
    const PVF::Amg_sparse_solver amg;
    const auto sequential = designed_coefficients<PVF::Amg_sparse_solver, CGAL::Sequential_tag>(tm, 4, true, *set, &amg);
    EXPECT_LT(relative_difference(ldlt, sequential), 1e-8);
    const PVF::Amg_statistics s = amg.statistics();
    EXPECT_GE(s.level_sizes.size(), 2u);
    EXPECT_EQ(s.analyses, 1u);  // one structure for all the blocks of the system
    EXPECT_GE(s.max_iterations, 10u);
    EXPECT_LE(s.max_iterations, 30u);
    EXPECT_EQ(s.fallbacks, 0u);
#ifdef CGAL_LINKED_WITH_TBB
    const auto parallel = designed_coefficients<PVF::Amg_sparse_solver, CGAL::Parallel_tag>(tm, 4, true, *set, &amg);
    ASSERT_EQ(parallel.size(), sequential.size());
    EXPECT_EQ(std::memcmp(parallel.data(), sequential.data(), parallel.size() * sizeof(Complex)), 0);
#endif
  }
}

// The frame-field iterations refactor with a new lambda at every step: every
// reuse of the hierarchy, with and without warm starts, follows the direct
// solver's iterations to 1e-8 after six steps; reuse 2 does keep coarse levels.
TEST(SolverAgreement, AmgConjugateFieldStepsMatchSimplicialLDLT)
{
  const Mesh tm = closed_mesh();
  const auto constraints = constraints_for(tm, 4, true, 12);
  auto run = [&](const auto& solver) {
    std::map<face_descriptor, std::vector<Complex> > out;
    PVF::Conjugate_field_result result;
    EXPECT_EQ(PVF::design_conjugate_frame_field(tm, constraints, boost::make_assoc_property_map(out), result,
                                                PVF::parameters::tolerance(1e-300, CGAL::parameters::sparse_linear_solver(solver)
                                                                                     .number_of_iterations(6))),
              PVF::Error_code::DID_NOT_CONVERGE);  // a tolerance of 1e-300 is never met: six steps, then the last field
    EXPECT_FALSE(result.converged);
    EXPECT_EQ(result.iterations, 6u);
    std::vector<Complex> c;
    for(face_descriptor f : tm.faces())
      c.insert(c.end(), out[f].begin(), out[f].end());
    return c;
  };
  const auto ref = run(PVF::Simplicial_ldlt_solver());
  for(int reuse : { 0, 1, 2 })
    for(bool warm : { false, true })
    {
      SCOPED_TRACE("reuse " + std::to_string(reuse) + (warm ? ", warm" : ", cold"));
      const PVF::Amg_sparse_solver amg = small_amg(reuse, warm);
      EXPECT_LT(relative_difference(ref, run(amg)), 1e-8);
      const PVF::Amg_statistics s = amg.statistics();
      EXPECT_EQ(s.fallbacks, 0u);
      if(reuse == 2)
        EXPECT_GT(s.reused_setups, 0u);
      else
        EXPECT_EQ(s.reused_setups, 0u);
    }
}

// One iteration allowed: every solve falls back to the direct factorization,
// says so, and the field is still the direct solver's.
TEST(SolverAgreement, AmgFallsBackToDirectSolverAndSaysSo)
{
  const Mesh tm = closed_mesh();
  const auto constraints = constraints_for(tm, 4, true, 12);
  const auto ldlt = designed_coefficients<PVF::Simplicial_ldlt_solver>(tm, 4, true, constraints);
  const PVF::Amg_sparse_solver amg = small_amg(2, true, 1);
  const auto a = designed_coefficients<PVF::Amg_sparse_solver, CGAL::Sequential_tag>(tm, 4, true, constraints, &amg);
  EXPECT_LT(relative_difference(ldlt, a), 1e-10);
  const PVF::Amg_statistics s = amg.statistics();
  EXPECT_EQ(s.solves, 2u);  // the two degrees of a frame field
  EXPECT_EQ(s.fallbacks, 2u);
}

// The concept's own interface (factor, linear_solver) on a Hermitian positive
// definite matrix; an indefinite one is refused; a NaN right-hand side too.
TEST(SolverAgreement, AmgConceptInterfaceAndIndefiniteMatrices)
{
  const int n = 200;
  PVF::Amg_sparse_solver::Matrix A(n, n);
  const Complex i(0, 1);
  for(int k = 0; k < n; ++k)
  {
    A.add_coef(k, k, Complex(2.5));
    if(k + 1 < n)
    {
      A.add_coef(k, k + 1, -std::polar(1.0, 0.1 * k));
      A.add_coef(k + 1, k, -std::polar(1.0, -0.1 * k));
    }
  }
  PVF::Amg_sparse_solver amg = small_amg();
  PVF::Amg_sparse_solver::Vector B(n), X(n);
  for(int k = 0; k < n; ++k)
    B[k] = Complex(std::cos(k), std::sin(0.5 * k));
  Complex D;
  ASSERT_TRUE(amg.factor(A, D));
  EXPECT_EQ(D, Complex(1));
  ASSERT_TRUE(amg.linear_solver(B, X));
  const Eigen::VectorXcd residual = A.eigen_object() * X - B;
  EXPECT_LE(residual.norm(), 2 * amg.parameters().tolerance * B.norm());  // the same residual, summed in another order
  EXPECT_GE(amg.statistics().level_sizes.size(), 3u);
  PVF::Amg_sparse_solver::Vector nan_rhs = B;
  nan_rhs[3] = Complex(std::nan(""), 0);
  EXPECT_FALSE(amg.linear_solver(nan_rhs, X));

  PVF::Amg_sparse_solver::Matrix M(n, n);
  for(int k = 0; k < n; ++k)
  {
    M.add_coef(k, k, Complex(k == 7 ? -1.0 : 2.5));
    if(k + 1 < n)
    {
      M.add_coef(k, k + 1, -i);
      M.add_coef(k + 1, k, i);
    }
  }
  PVF::Amg_sparse_solver refused = small_amg();
  EXPECT_FALSE(refused.factor(M, D) && refused.linear_solver(B, X));
}

// The adaptive solver: below its threshold the direct solver's own bits,
// above it multigrid (to 1e-8), chosen per system by its number of unknowns.
TEST(SolverAgreement, AdaptiveSolverPicksBySize)
{
  typedef PVF::Adaptive_sparse_solver<PVF::Simplicial_ldlt_solver> Adaptive;
  const Mesh tm = closed_mesh();
  const auto constraints = constraints_for(tm, 4, true, 12);
  const auto ldlt = designed_coefficients<PVF::Simplicial_ldlt_solver>(tm, 4, true, constraints);
  const std::size_t unknowns = tm.number_of_faces() - 8;  // the 8 hard constraints fix their faces
  const Adaptive direct(unknowns + 1, PVF::Simplicial_ldlt_solver(), small_amg());
  const auto below = designed_coefficients<Adaptive, CGAL::Sequential_tag>(tm, 4, true, constraints, &direct);
  ASSERT_EQ(below.size(), ldlt.size());
  EXPECT_EQ(std::memcmp(below.data(), ldlt.data(), ldlt.size() * sizeof(Complex)), 0);
  EXPECT_EQ(direct.amg_solver().statistics().solves, 0u);
  const Adaptive amg(unknowns, PVF::Simplicial_ldlt_solver(), small_amg());
  const auto above = designed_coefficients<Adaptive, CGAL::Sequential_tag>(tm, 4, true, constraints, &amg);
  EXPECT_LT(relative_difference(ldlt, above), 1e-8);
  EXPECT_GT(relative_difference(ldlt, above), 0.0);  // a different computation
  EXPECT_EQ(amg.amg_solver().statistics().solves, 2u);
}

#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
// The package's own CHOLMOD driver: a Hermitian positive definite matrix is
// solved to rounding; an indefinite one is refused (not factored with a
// negative pivot), and so is a solve before any factorization.
TEST(SolverAgreement, CholmodFactorizationRefusesIndefiniteMatrices)
{
  typedef PVF::Sparse_factorization<PVF::Cholmod_sparse_solver, Complex> Factorization;
  const Complex i(0, 1);
  // Hermitian 3x3, full storage.
  Eigen::MatrixXcd dense(3, 3);
  dense << 4.0, 1.0 + i, 0.0,
           1.0 - i, 3.0, 0.5 * i,
           0.0, -0.5 * i, 2.0;
  PVF::internal::Sparse_matrix A = dense.sparseView();
  A.makeCompressed();
  Factorization positive;
  Factorization::Dense_matrix x, b(3, 1);
  b << 1.0, i, 2.0 - i;
  EXPECT_FALSE(positive.solve(b, x));
  ASSERT_TRUE(positive.analyze(A));
  ASSERT_TRUE(positive.factorize(A));
  ASSERT_TRUE(positive.solve(b, x));
  EXPECT_LT((dense * x - b).norm(), 1e-14 * b.norm());

  Eigen::MatrixXcd indefinite = dense;
  indefinite(2, 2) = -2.0;
  PVF::internal::Sparse_matrix B = indefinite.sparseView();
  B.makeCompressed();
  Factorization negative;
  ASSERT_TRUE(negative.analyze(B));
  EXPECT_FALSE(negative.factorize(B));
}

// The shifted Laplacian of a k x k grid (a real symmetric positive definite
// matrix whose factor has the elimination tree of a surface mesh's), both
// triangles stored.
Eigen::SparseMatrix<double> grid_matrix(int k, double shift)
{
  std::vector<Eigen::Triplet<double> > t;
  auto edge = [&t](int a, int b, double w) {
    t.emplace_back(a, a, w);
    t.emplace_back(b, b, w);
    t.emplace_back(a, b, -w);
    t.emplace_back(b, a, -w);
  };
  for(int i = 0; i < k; ++i)
    for(int j = 0; j < k; ++j)
    {
      t.emplace_back(i * k + j, i * k + j, shift);
      if(i + 1 < k)
        edge(i * k + j, (i + 1) * k + j, 1 + 0.5 * std::sin(0.37 * i + 0.11 * j));  // varied coefficients
      if(j + 1 < k)
        edge(i * k + j, i * k + j + 1, 1.0);
    }
  Eigen::SparseMatrix<double> A(k * k, k * k);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

// m sparse columns of 1 to 4 random entries; column 3 is zero.
Eigen::SparseMatrix<double> sparse_columns(Eigen::Index n, Eigen::Index m, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_int_distribution<Eigen::Index> row(0, n - 1);
  std::uniform_int_distribution<int> count(1, 4);
  std::uniform_real_distribution<double> value(-1, 1);
  std::vector<Eigen::Triplet<double> > t;
  for(Eigen::Index j = 0; j < m; ++j)
    if(j != 3)
      for(int c = count(random); c > 0; --c)
        t.emplace_back(row(random), j, value(random));
  Eigen::SparseMatrix<double> C(n, m);
  C.setFromTriplets(t.begin(), t.end());
  C.makeCompressed();
  return C;
}

// G = C^T A^-1 C by full solves of Eigen's own SimplicialLDLT: the reference.
Eigen::MatrixXd reference_congruence(const Eigen::SparseMatrix<double>& A, const Eigen::SparseMatrix<double>& C)
{
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > ldlt(A);
  const Eigen::MatrixXd X = ldlt.solve(Eigen::MatrixXd(C));
  return Eigen::MatrixXd(C.transpose()) * X;
}

// G = C^T A^-1 C by CHOLMOD's sparse forward solves (the Schur complement of
// the integer-grid map's integer unknowns) against full solves of another
// solver, for a supernodal LL^T factor and a simplicial LDL^T one. The
// supernodal factor is converted on a copy only: it still solves, and
// refactors with new values, as before.
template <typename Eigen_cholmod>
void check_inverse_congruence(const char* name, bool supernodal)
{
  SCOPED_TRACE(name);
  typedef typename PVF::internal::Eigen_cholmod_solver<Eigen_cholmod> Access;
  static_assert(Access::value, "Eigen's CHOLMOD solvers on real matrices expose their factor");
  const Eigen::SparseMatrix<double> A = grid_matrix(150, 1e-3), C = sparse_columns(A.rows(), 40, 7);
  typename Access::Solver solver;
  solver.compute(A);
  ASSERT_EQ(solver.info(), Eigen::Success);
  ASSERT_EQ(bool(solver.factor()->is_super), supernodal);
  Eigen::MatrixXd G;
  ASSERT_TRUE(Access::inverse_congruence(solver, C, G));
  EXPECT_EQ(bool(solver.factor()->is_super), supernodal);
  const Eigen::MatrixXd R = reference_congruence(A, C);
  ASSERT_EQ(G.rows(), 40);
  ASSERT_EQ(G.cols(), 40);
  EXPECT_LT((G - R).cwiseAbs().maxCoeff(), 1e-10 * R.cwiseAbs().maxCoeff());
  EXPECT_EQ(G, G.transpose());
  EXPECT_EQ(G.row(3).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(R.cwiseAbs().maxCoeff(), 1.0);  // a matrix worth comparing
  // The forward solves by ranges of 8 columns and the products by blocks of
  // 32 columns on TBB's threads give G bit for bit as on the calling thread.
  Eigen::MatrixXd G_sequential;
  ASSERT_TRUE(PVF::internal::cholmod_inverse_congruence(solver.factor(), solver.common(), C, G_sequential, false));
  EXPECT_TRUE(G_sequential == G);

  // The factor still solves, and refactors with new values.
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1, 1);
  const Eigen::VectorXd x = solver.solve(b);
  EXPECT_LT((A * x - b).norm(), 1e-9 * b.norm());
  const Eigen::SparseMatrix<double> A2 = grid_matrix(150, 0.5);
  solver.factorize(A2);
  ASSERT_EQ(solver.info(), Eigen::Success);
  ASSERT_TRUE(Access::inverse_congruence(solver, C, G));
  const Eigen::MatrixXd R2 = reference_congruence(A2, C);
  EXPECT_LT((G - R2).cwiseAbs().maxCoeff(), 1e-10 * R2.cwiseAbs().maxCoeff());
  EXPECT_GT((R2 - R).cwiseAbs().maxCoeff(), 0.1 * R.cwiseAbs().maxCoeff());  // the new values changed G
}

TEST(SolverAgreement, CholmodInverseCongruenceMatchesFullSolves)
{
  check_inverse_congruence<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> >("supernodal", true);
  check_inverse_congruence<Eigen::CholmodSimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> >("simplicial LDL^T",
                                                                                                     false);
  // The concept's optional operation, on the default solver of the
  // integer-grid map (Default_real_sparse_solver when CHOLMOD is linked); no
  // column, and no row, are handled.
  typedef CGAL::Eigen_solver_traits<Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> > Real_cholmod;
  typedef PVF::Sparse_factorization<Real_cholmod, double> Factorization;
  // the map finds the operation (else it would quietly use block solves)
  static_assert(PVF::internal::Has_inverse_congruence<Factorization>::value, "the real CHOLMOD model has it");
  static_assert(!PVF::internal::Has_inverse_congruence<PVF::Sparse_factorization<
                  CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > >, double> >::value,
                "Eigen's SimplicialLDLT model has not");
  const Eigen::SparseMatrix<double> A = grid_matrix(40, 1e-2), C = sparse_columns(A.rows(), 12, 3);
  Factorization factorization;
  Eigen::MatrixXd G;
  EXPECT_FALSE(factorization.inverse_congruence(C, G));  // not factored yet
  ASSERT_TRUE(factorization.analyze(A) && factorization.factorize(A));
  ASSERT_TRUE(factorization.inverse_congruence(C, G));
  const Eigen::MatrixXd R = reference_congruence(A, C);
  EXPECT_LT((G - R).cwiseAbs().maxCoeff(), 1e-10 * R.cwiseAbs().maxCoeff());
  ASSERT_TRUE(factorization.inverse_congruence(Eigen::SparseMatrix<double>(A.rows(), 0), G));
  EXPECT_EQ(G.size(), 0);
  Factorization empty;
  const Eigen::SparseMatrix<double> none(0, 0);
  ASSERT_TRUE(empty.analyze(none) && empty.factorize(none));
  ASSERT_TRUE(empty.inverse_congruence(Eigen::SparseMatrix<double>(0, 5), G));
  EXPECT_EQ(G, Eigen::MatrixXd::Zero(5, 5));
}

// The model of Eigen's CHOLMOD solvers on real matrices (the map's and the
// planarizer's default) keeps OpenBLAS on one thread while its Solver_scope
// is alive, as Cholmod_sparse_solver's does (a supernodal factor depends on
// OpenBLAS's thread count in its last bits), and restores the count after.
TEST(SolverAgreement, RealCholmodScopeRunsOpenBlasOnOneThread)
{
  const pvf_test::Openblas_threads blas;
  int original = 1;
  if(!blas.set_two(original))
    GTEST_SKIP() << "the BLAS is not OpenBLAS, or it does not allow 2 threads here";
  typedef CGAL::Eigen_solver_traits<Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> > Real_cholmod;
  {
    PVF::Sparse_factorization<Real_cholmod, double>::Solver_scope scope;
    EXPECT_EQ(blas.get(), 1);
  }
  EXPECT_EQ(blas.get(), 2);
  blas.set(original);
}
#endif

} // namespace
