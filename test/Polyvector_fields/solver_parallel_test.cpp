// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Parallel against sequential: with CGAL::Parallel_tag the independent
// coefficient degrees are assembled, factored and solved in different threads
// (TBB); the fields must be bit-identical to CGAL::Sequential_tag, for each
// solver, for the design and for both frame-field iterations. The meshes are
// large enough (about 10k faces) for CHOLMOD to take its supernodal (BLAS)
// path, where a change of the BLAS's threading changes the last bits.

#include <CGAL/Polyvector_fields/Cholmod_solver.h>
#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/design_angle_bounded_frame_field.h>
#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/design_conjugate_frame_field.h>

#include <CGAL/subdivision_method_3.h>

#include "test_meshes.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <complex>
#include <cstring>
#include <map>
#include <random>
#include <thread>
#include <vector>

namespace {

namespace PVF = CGAL::Polyvector_fields;
using namespace pvf_test;
typedef std::complex<double> Complex;
typedef Mesh::Face_index Face;
typedef PVF::Face_constraint<Face, Vector> Constraint;

#ifdef CGAL_LINKED_WITH_TBB

// bumpy.off after one Loop subdivision: 9984 faces, closed.
const Mesh& bumpy_10k()
{
  static const Mesh tm = [] {
    Mesh m = load("bumpy.off");
    CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
    return m;
  }();
  return tm;
}

// General frames {±u, ±v} (two active degrees) on 1% of the faces, some soft.
std::vector<Constraint> frame_constraints(const Mesh& tm)
{
  std::vector<Constraint> constraints = random_constraints(tm, num_faces(tm) / 100, 2, 5);
  for(std::size_t i = 0; i < constraints.size(); i += 4)
    constraints[i].weight = 50.0;
  return constraints;
}

// Exact equality of every bit (also of the sign of zeros), and a field that is not zero.
void expect_bit_identical(const std::vector<Complex>& a, const std::vector<Complex>& b)
{
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Complex)), 0);
  double largest = 0;
  for(const Complex& z : a)
    largest = (std::max)(largest, std::abs(z));
  EXPECT_GT(largest, 0.1);
}

template <typename Solver>
void check_design(const char* solver_name)
{
  SCOPED_TRACE(solver_name);
  const Mesh& tm = bumpy_10k();
  const std::vector<Constraint> frames = frame_constraints(tm);
  // Frame field: two independent degrees, solved in parallel.
  std::size_t degrees = 0;
  const auto sequential = designed_coefficients<Solver, CGAL::Sequential_tag>(tm, 4, true, frames, nullptr, &degrees);
  const auto parallel = designed_coefficients<Solver, CGAL::Parallel_tag>(tm, 4, true, frames);
  EXPECT_EQ(degrees, 2u);
  expect_bit_identical(sequential, parallel);
  // N = 3 from three vectors per face: three degrees.
  const std::vector<Constraint> triples = random_constraints(tm, 60, 3, 8);
  const auto sequential3 = designed_coefficients<Solver, CGAL::Sequential_tag>(tm, 3, false, triples, nullptr, &degrees);
  const auto parallel3 = designed_coefficients<Solver, CGAL::Parallel_tag>(tm, 3, false, triples);
  EXPECT_EQ(degrees, 3u);
  expect_bit_identical(sequential3, parallel3);
}

// The root extraction of a whole field, faces shared among threads: sign-symmetric
// N = 4 (closed form, with some degenerate faces: zero and double roots) and
// N = 5 (companion matrices).
TEST(Parallel, FieldRootsAreBitIdentical)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for(const std::size_t N : { std::size_t(4), std::size_t(5) })
  {
    const bool sign_symmetric = (N == 4);
    const std::size_t F = 50000;
    std::vector<Complex> c(F * N);
    for(std::size_t i = 0; i < c.size(); ++i)
      c[i] = (sign_symmetric && i % 2 == 1) ? Complex(0) : Complex(u(rng), u(rng));
    for(std::size_t f = 0; f < F; f += 97)
      c[f * N] = 0;  // a zero root (pair)
    for(std::size_t f = 1; f < F; f += 89)
      if(sign_symmetric)
        c[f * N] = c[f * N + 2] * c[f * N + 2] / 4.0;  // w double: two double roots
    std::vector<Complex> sequential, parallel;
    PVF::internal::field_roots<CGAL::Sequential_tag>(c, N, sign_symmetric, sequential);
    PVF::internal::field_roots<CGAL::Parallel_tag>(c, N, sign_symmetric, parallel);
    ASSERT_EQ(sequential.size(), F * N);
    expect_bit_identical(sequential, parallel);
    // and each face equals a call of the kernel on its own
    std::vector<Complex> one(N);
    for(std::size_t f = 0; f < F; f += 1013)
    {
      PVF::polyvector_roots(c.data() + f * N, N, one.data(), sign_symmetric);
      EXPECT_EQ(std::memcmp(one.data(), parallel.data() + f * N, N * sizeof(Complex)), 0);
    }
  }
}

TEST(Parallel, DesignIsBitIdenticalSimplicialLDLT) { check_design<PVF::Simplicial_ldlt_solver>("SimplicialLDLT"); }

#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
TEST(Parallel, DesignIsBitIdenticalCholmod) { check_design<PVF::Cholmod_sparse_solver>("CHOLMOD"); }
#endif

// Runs `algorithm(tag, map)` sequentially or in parallel into a fresh field map
// and returns the field, face after face. The iterations are capped, so the
// status is SUCCESS or DID_NOT_CONVERGE, as `result.converged` says.
template <typename Result, typename Algorithm>
std::vector<Complex> frame_field(const Mesh& tm, bool parallel, const Result& result, const Algorithm& algorithm)
{
  std::map<Face, std::vector<Complex> > field;
  auto map = boost::make_assoc_property_map(field);
  const PVF::Error_code code = parallel ? algorithm(CGAL::Parallel_tag(), map) : algorithm(CGAL::Sequential_tag(), map);
  EXPECT_EQ(code, result.converged ? PVF::Error_code::SUCCESS : PVF::Error_code::DID_NOT_CONVERGE);
  std::vector<Complex> flat;
  for(Face f : faces(tm))
    flat.insert(flat.end(), field[f].begin(), field[f].end());
  return flat;
}

// The global steps refactor both degrees numerically at every iteration.
template <typename Solver>
void check_frame_fields(const char* solver_name)
{
  SCOPED_TRACE(solver_name);
  const Mesh& tm = bumpy_10k();
  const std::vector<Constraint> frames = frame_constraints(tm);
  PVF::Angle_bound_result angle[2];
  const auto angle_np = CGAL::parameters::sparse_linear_solver(Solver()).number_of_iterations(10);
  std::vector<Complex> angle_fields[2];
  for(int parallel = 0; parallel < 2; ++parallel)
    angle_fields[parallel] = frame_field(tm, parallel != 0, angle[parallel], [&](auto tag, auto map) {
      return PVF::design_angle_bounded_frame_field<decltype(tag)>(tm, frames, map, angle[parallel], angle_np);
    });
  EXPECT_GT(angle[0].iterations, 1u);
  EXPECT_EQ(angle[0].iterations, angle[1].iterations);
  expect_bit_identical(angle_fields[0], angle_fields[1]);

  Mesh inspired = load("inspired_mesh.obj");
  std::vector<Constraint> constraints;
  ASSERT_EQ(PVF::IO::read_dmat_constraints(data("inspired_mesh_b.dmat"), data("inspired_mesh_bc.dmat"), inspired,
                                           constraints),
            PVF::Error_code::SUCCESS);
  PVF::Conjugate_field_result conjugate[2];
  const auto conjugate_np = CGAL::parameters::sparse_linear_solver(Solver()).number_of_iterations(8);
  std::vector<Complex> conjugate_fields[2];
  for(int parallel = 0; parallel < 2; ++parallel)
    conjugate_fields[parallel] = frame_field(inspired, parallel != 0, conjugate[parallel], [&](auto tag, auto map) {
      return PVF::design_conjugate_frame_field<decltype(tag)>(inspired, constraints, map, conjugate[parallel],
                                                              conjugate_np);
    });
  EXPECT_GT(conjugate[0].residual_history.size(), 1u);
  EXPECT_EQ(conjugate[0].residual_history, conjugate[1].residual_history);
  expect_bit_identical(conjugate_fields[0], conjugate_fields[1]);
}

TEST(Parallel, FrameFieldsAreBitIdenticalSimplicialLDLT)
{
  check_frame_fields<PVF::Simplicial_ldlt_solver>("SimplicialLDLT");
}

#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
TEST(Parallel, FrameFieldsAreBitIdenticalCholmod) { check_frame_fields<PVF::Cholmod_sparse_solver>("CHOLMOD"); }

// While CHOLMOD runs OpenBLAS runs on one thread; its thread count must be
// back afterwards.
TEST(Parallel, OpenBlasThreadCountIsRestored)
{
  // A count other than 1, so that "restored" is not "left at 1".
  const pvf_test::Openblas_threads blas;
  int original = 1;
  if(!blas.set_two(original))
    GTEST_SKIP() << "the BLAS is not OpenBLAS, or it does not allow 2 threads here";
  const Mesh& tm = bumpy_10k();
  designed_coefficients<PVF::Cholmod_sparse_solver, CGAL::Parallel_tag>(tm, 4, true, frame_constraints(tm));
  EXPECT_EQ(blas.get(), 2);
  blas.set(original);
}

// Designs running at the same time in two threads of a program: the shared
// OpenBLAS setting stays at one thread until both are done, so that both
// fields are those of a design run alone, and it is restored at the end.
TEST(Parallel, ConcurrentCholmodDesignsInTwoThreads)
{
  const Mesh& tm = bumpy_10k();
  const std::vector<Constraint> frames = frame_constraints(tm);
  const std::vector<Constraint> others = random_constraints(tm, num_faces(tm) / 50, 2, 9);
  const auto alone_a = designed_coefficients<PVF::Cholmod_sparse_solver, CGAL::Sequential_tag>(tm, 4, true, frames);
  const auto alone_b = designed_coefficients<PVF::Cholmod_sparse_solver, CGAL::Sequential_tag>(tm, 4, true, others);
  const pvf_test::Openblas_threads blas;
  const int before = blas.get ? blas.get() : 0;
  for(int round = 0; round < 3; ++round)
  {
    std::vector<Complex> a, b;
    std::thread first([&] { a = designed_coefficients<PVF::Cholmod_sparse_solver, CGAL::Parallel_tag>(tm, 4, true, frames); });
    std::thread second([&] { b = designed_coefficients<PVF::Cholmod_sparse_solver, CGAL::Sequential_tag>(tm, 4, true, others); });
    first.join();
    second.join();
    expect_bit_identical(alone_a, a);
    expect_bit_identical(alone_b, b);
  }
  if(blas.get)
    EXPECT_EQ(blas.get(), before);
}
#endif

#else
TEST(Parallel, RequiresTbb) { GTEST_SKIP() << "TBB is not linked (CGAL_LINKED_WITH_TBB): nothing runs in parallel"; }
#endif

} // namespace
