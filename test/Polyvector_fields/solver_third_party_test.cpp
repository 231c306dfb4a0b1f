// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// A solver back end that is not the package's: one specialization of
// Sparse_factorization (the SparseFactorization concept), written here around
// Eigen's SimplicialLDLT, for complex and real systems. The package must give
// the same fields as with its direct solver, factor the blocks of a field in
// parallel with the default concurrency tag, and use the model for the real
// systems too (the planarizer's).

#include <CGAL/Polyvector_fields/Sparse_factorization.h>

#include <Eigen/Sparse>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>

namespace third_party {

// What the factorizations made from one solver observed.
struct Call_log
{
  std::mutex mutex;
  std::condition_variable arrived;
  int in_flight = 0;              // factorize() calls running now
  int most_in_flight = 0;         // the most at one time
  bool gave_up_waiting = false;
  bool wait_for_company = false;  // whether a factorize() waits for a second one
  std::atomic<int> complex_factorizations{ 0 };
  std::atomic<int> real_factorizations{ 0 };
};

// The solver as the user passes it (sparse_linear_solver): a handle on its log.
struct Ldlt_solver
{
  std::shared_ptr<Call_log> log = std::make_shared<Call_log>();
};

// While alive, counts one running factorize(). With `wait_for_company`, the
// first one waits (up to 20 s, then never again) for a second one to run at
// the same time: if the blocks
// are factored in parallel, the second arrives; if they are factored one after
// the other, it cannot, and most_in_flight stays 1.
class In_flight
{
public:
  explicit In_flight(Call_log& log) : m_log(log)
  {
    std::unique_lock<std::mutex> lock(m_log.mutex);
    m_log.most_in_flight = (std::max)(m_log.most_in_flight, ++m_log.in_flight);
    m_log.arrived.notify_all();
    if(m_log.wait_for_company && m_log.most_in_flight < 2 && !m_log.gave_up_waiting)
      if(!m_log.arrived.wait_for(lock, std::chrono::seconds(20), [this] { return m_log.most_in_flight >= 2; }))
        m_log.gave_up_waiting = true;
  }
  ~In_flight()
  {
    std::lock_guard<std::mutex> lock(m_log.mutex);
    --m_log.in_flight;
  }

private:
  Call_log& m_log;
};

} // namespace third_party

namespace CGAL {
namespace Polyvector_fields {

// The whole back end: one traits class, for both scalar types.
template <typename Scalar>
class Sparse_factorization<third_party::Ldlt_solver, Scalar>
{
public:
  typedef Eigen::SparseMatrix<Scalar> Matrix;
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> Dense_matrix;
  struct Shared_analysis
  {};
  struct Solver_scope
  {};
  static constexpr bool is_thread_safe = true;  // each object owns its Eigen solver
  static constexpr bool keeps_matrix = false;

  explicit Sparse_factorization(const third_party::Ldlt_solver& solver = third_party::Ldlt_solver())
    : m_log(solver.log)
  {}
  Sparse_factorization(const Sparse_factorization&) = delete;
  Sparse_factorization& operator=(const Sparse_factorization&) = delete;

  void share_analysis(const std::shared_ptr<Shared_analysis>&) {}
  bool analyze(const Matrix& A)
  {
    m_ldlt.analyzePattern(A);
    return m_ldlt.info() == Eigen::Success;
  }
  bool factorize(const Matrix& A)
  {
    (std::is_same<Scalar, double>::value ? m_log->real_factorizations : m_log->complex_factorizations)++;
    third_party::In_flight observed(*m_log);
    m_ldlt.factorize(A);
    return m_ldlt.info() == Eigen::Success;
  }
  bool solve(const Dense_matrix& B, Dense_matrix& X)
  {
    X = m_ldlt.solve(B);
    return m_ldlt.info() == Eigen::Success;
  }

private:
  Eigen::SimplicialLDLT<Matrix> m_ldlt;
  std::shared_ptr<third_party::Call_log> m_log;
};

} // namespace Polyvector_fields
} // namespace CGAL

#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/design_conjugate_frame_field.h>
#include <CGAL/Polyvector_fields/planarize_quad_mesh.h>

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <map>
#include <type_traits>
#include <vector>

namespace {

namespace PVF = CGAL::Polyvector_fields;
using namespace pvf_test;
typedef std::complex<double> Complex;
typedef PVF::Face_constraint<Mesh::Face_index, Vector> Constraint;

// max |a - b| / max |b|
double relative_difference(const std::vector<Complex>& a, const std::vector<Complex>& b)
{
  EXPECT_EQ(a.size(), b.size());
  double difference = 0, largest = 0;
  for(std::size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    difference = (std::max)(difference, std::abs(a[i] - b[i]));
    largest = (std::max)(largest, std::abs(b[i]));
  }
  EXPECT_GT(largest, 0.1);
  return difference / largest;
}

// A general 4-PolyVector field (four degrees, four blocks) with the default
// concurrency tag.
template <typename Solver>
std::vector<Complex> design(const Mesh& tm, const std::vector<Constraint>& constraints, const Solver& solver,
                            std::size_t& degrees)
{
  PVF::Polyvector_field_designer<Mesh, CGAL::Default, CGAL::Default, Solver> designer(
    tm, 4, CGAL::parameters::sparse_linear_solver(solver));
  EXPECT_EQ(designer.add_constraints(constraints), PVF::Error_code::SUCCESS);
  EXPECT_EQ(designer.solve(boost::dummy_property_map()), PVF::Error_code::SUCCESS);
  degrees = designer.statistics().number_of_degrees_solved;
  return designer.coefficient_array();
}

TEST(ThirdPartySolver, FieldEqualsTheDirectSolversAndBlocksRunInParallel)
{
  const Mesh tm = load("bumpy.off");
  const std::vector<Constraint> constraints = random_constraints(tm, 40, 4, 11);
  third_party::Ldlt_solver solver;
  solver.log->wait_for_company = true;
  std::size_t degrees = 0, direct_degrees = 0;
  const std::vector<Complex> field = design(tm, constraints, solver, degrees);
  const std::vector<Complex> direct = design(tm, constraints, PVF::Direct_sparse_solver(), direct_degrees);
  EXPECT_EQ(degrees, 4u);
  EXPECT_EQ(direct_degrees, 4u);
  EXPECT_LT(relative_difference(field, direct), 1e-10);
  EXPECT_EQ(solver.log->complex_factorizations.load(), 4);
#ifdef CGAL_LINKED_WITH_TBB
  // The default tag is Parallel_if_available_tag: with TBB, the four blocks
  // are factored by the parallel helper, two at a time at least.
  EXPECT_GE(solver.log->most_in_flight, 2);
  EXPECT_FALSE(solver.log->gave_up_waiting);
#else
  EXPECT_EQ(solver.log->most_in_flight, 1);
#endif
}

// The global steps of a frame-field algorithm: refactorizations of both
// degrees at every iteration, through the model.
TEST(ThirdPartySolver, ConjugateFrameFieldEqualsTheDirectSolvers)
{
  const Mesh tm = load("inspired_mesh.obj");
  const std::vector<Constraint> constraints = random_constraints(tm, 30, 2, 5);
  third_party::Ldlt_solver solver;
  std::vector<Complex> fields[2];
  PVF::Conjugate_field_result results[2];
  for(int k = 0; k < 2; ++k)
  {
    std::map<Mesh::Face_index, std::vector<Complex> > field;
    const auto np = CGAL::parameters::number_of_iterations(6);
    const PVF::Error_code code =
      k == 0 ? PVF::design_conjugate_frame_field(tm, constraints, boost::make_assoc_property_map(field), results[k],
                                                 np.sparse_linear_solver(solver))
             : PVF::design_conjugate_frame_field(tm, constraints, boost::make_assoc_property_map(field), results[k],
                                                 np.sparse_linear_solver(PVF::Direct_sparse_solver()));
    ASSERT_EQ(code, PVF::Error_code::SUCCESS);
    for(const auto& entry : field)
      fields[k].insert(fields[k].end(), entry.second.begin(), entry.second.end());
  }
  EXPECT_EQ(results[0].factorizations, results[1].factorizations);
  EXPECT_GT(solver.log->complex_factorizations.load(), 2);
  EXPECT_LT(relative_difference(fields[0], fields[1]), 1e-8);
}

// A quad grid over a bumpy height field, and the triangulated grid as the reference.
void bumpy_quad_grid(int n, Mesh& quads, Mesh& triangles)
{
  std::vector<Mesh::Vertex_index> qv, tv;
  for(int i = 0; i <= n; ++i)
    for(int j = 0; j <= n; ++j)
    {
      const double x = double(i) / n, y = double(j) / n;
      const Point p(x, y, 0.08 * std::sin(7 * x) * std::cos(5 * y) + 0.01 * std::sin(31 * x * y));
      qv.push_back(quads.add_vertex(p));
      tv.push_back(triangles.add_vertex(p));
    }
  auto id = [n](int i, int j) { return std::size_t(i * (n + 1) + j); };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      quads.add_face(qv[id(i, j)], qv[id(i + 1, j)], qv[id(i + 1, j + 1)], qv[id(i, j + 1)]);
      triangles.add_face(tv[id(i, j)], tv[id(i + 1, j)], tv[id(i + 1, j + 1)]);
      triangles.add_face(tv[id(i, j)], tv[id(i + 1, j + 1)], tv[id(i, j + 1)]);
    }
}

// The planarizer's real system through the model, against the default solver:
// 20 iterations towards a threshold of 0.2% (not reached, or reached: the
// same either way), one factorization through the model.
TEST(ThirdPartySolver, PlanarizerUsesTheModelOnRealSystems)
{
  Mesh quads, reference;
  bumpy_quad_grid(20, quads, reference);
  Mesh by_default = quads, by_model = quads;
  third_party::Ldlt_solver solver;
  PVF::Planarization_result r_default, r_model;
  // the local-global iterations alone (no Gauss-Newton step): see below
  const auto np = PVF::parameters::planarity_threshold(0.002, PVF::parameters::gauss_newton_steps(0)).number_of_iterations(20);
  const PVF::Error_code code_default = PVF::planarize_quad_mesh(by_default, reference, r_default, np);
  const PVF::Error_code code_model =
    PVF::planarize_quad_mesh(by_model, reference, r_model, np.sparse_linear_solver(solver));
  EXPECT_EQ(code_model, code_default);
  EXPECT_TRUE(code_model == PVF::Error_code::SUCCESS || code_model == PVF::Error_code::DID_NOT_CONVERGE);
  EXPECT_EQ(solver.log->real_factorizations.load(), 1);
  EXPECT_GT(r_model.max_planarity_before, 0.002);
  EXPECT_GT(r_model.iterations, 0u);
  EXPECT_EQ(r_model.iterations, r_default.iterations);
  EXPECT_LT(r_model.max_planarity_after, r_model.max_planarity_before);
  EXPECT_GT(r_model.max_displacement, 0.0);
  EXPECT_NEAR(r_model.max_displacement, r_default.max_displacement, 1e-12);
  EXPECT_NEAR(r_model.max_planarity_after, r_default.max_planarity_after, 1e-12);
  EXPECT_NEAR(r_model.max_distance, r_default.max_distance, 1e-12);
  double largest = 0;
  for(auto v : vertices(quads))
    largest = (std::max)(largest, std::sqrt(CGAL::squared_distance(by_model.point(v), by_default.point(v))));
  EXPECT_LT(largest, 1e-10);  // the meshes as they were, or both planarized alike
  // With the Gauss-Newton steps that follow a failure (2 local-global
  // iterations do not reach 0.2% here): they factor through the model too,
  // once per attempt.
  {
    Mesh gn = quads;
    third_party::Ldlt_solver solver_gn;
    PVF::Planarization_result r_gn;
    const PVF::Error_code code_gn = PVF::planarize_quad_mesh(
      gn, reference, r_gn,
      PVF::parameters::planarity_threshold(0.002, PVF::parameters::gauss_newton_steps(3))
        .number_of_iterations(2)
        .sparse_linear_solver(solver_gn));
    EXPECT_TRUE(code_gn == PVF::Error_code::SUCCESS || code_gn == PVF::Error_code::DID_NOT_CONVERGE);
    EXPECT_EQ(r_gn.iterations, 2u);
    EXPECT_TRUE(r_gn.gauss_newton_ran);
    EXPECT_GT(r_gn.gauss_newton_steps + r_gn.gauss_newton_rejected_steps, 0u);
    EXPECT_EQ(std::size_t(solver_gn.log->real_factorizations.load()),
              1 + r_gn.gauss_newton_steps + r_gn.gauss_newton_rejected_steps);
  }
}

} // namespace
