// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Robustness of the meshing road (issue 21): systems without unknowns, maps
// that are checked before they are returned, polygons of any shape in the
// input, and quad meshes that cannot be empty. The suites are named Robust*
// and everything else is in an anonymous namespace, so that the file shares no
// name with the other test files of the group.

#include "test_meshes.h"

#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Sparse_factorization.h>
#include <CGAL/Polyvector_fields/compute_integer_grid_map.h>
#include <CGAL/Polyvector_fields/design_polyvector_field.h>
#include <CGAL/Polyvector_fields/extract_quad_mesh.h>
#include <CGAL/Polyvector_fields/IO/read_triangle_mesh.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/comb_frame_field.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/generators.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

namespace PVF = CGAL::Polyvector_fields;
using namespace pvf_test;
typedef Mesh::Face_index Face;
typedef Mesh::Halfedge_index Halfedge;
typedef std::complex<double> Complex;
typedef std::array<double, 2> UV;

// The unit box as 12 triangles: its 8 corners are the only vertices.
Mesh box_of_triangles()
{
  Mesh tm;
  CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(0, 1, 1), Point(0, 0, 1),
                        Point(1, 0, 1), Point(1, 1, 1), tm);
  CGAL::Polygon_mesh_processing::triangulate_faces(tm);
  return tm;
}

// A frame field along the box's edges: each face constrained by one of its
// axes (the one of x, y, z that lies in its plane first).
void box_frame_field(const Mesh& tm, Mesh::Property_map<Face, std::vector<Complex> > field)
{
  std::vector<PVF::Face_constraint<Face, Vector> > constraints;
  for(Face f : faces(tm))
  {
    const Vector n = CGAL::Polygon_mesh_processing::compute_face_normal(f, tm);
    const Vector axis = std::abs(n.x()) < 0.5 ? Vector(1, 0, 0) : Vector(0, 1, 0);
    constraints.push_back(PVF::Face_constraint<Face, Vector>{ f, { axis } });
  }
  ASSERT_EQ(PVF::design_polyvector_field(tm, 4, constraints, field, PVF::parameters::sign_symmetric(true)),
            PVF::Error_code::SUCCESS);
}

// The map system of the stiffening tests: on a sphere, a frame field of 5
// random constraints, combed and cut, its seams reduced and its guidance
// system assembled for quads of 0.2. Made in place (the comb keeps the
// bundle, which keeps the mesh).
struct Sphere_map_system
{
  typedef PVF::Tangent_bundle<Mesh> Bundle;
  Mesh tm = sphere(2);
  std::unique_ptr<Bundle> bundle;
  PVF::Frame_field_comb<Bundle> comb;
  PVF::internal::Seamless_reduction R;
  PVF::internal::Guidance_system S;
  std::size_t nx = 0, m = 0;

  // call with ASSERT_NO_FATAL_FAILURE
  void make()
  {
    auto field = tm.add_property_map<Face, std::vector<Complex> >("f:field").first;
    ASSERT_EQ(PVF::design_polyvector_field(tm, 4, random_constraints(tm, 5, 2, 11), field,
                                           PVF::parameters::sign_symmetric(true)),
              PVF::Error_code::SUCCESS);
    bundle = std::make_unique<Bundle>(tm);
    ASSERT_EQ(comb.compute(*bundle, field, 10 * CGAL_PI / 180), PVF::Error_code::SUCCESS);
    ASSERT_EQ(PVF::internal::reduce_seamless_variables(comb.corner_mesh(), comb.data(), R), PVF::Error_code::SUCCESS);
    nx = R.continuous_columns;
    m = R.integer_columns;
    ASSERT_GT(m, 0u);
    PVF::internal::assemble_guidance(comb.corner_mesh(), comb.data(), R, 0.2, nx + m, S);
  }
};

// Square roots of row weights from 1 to 1e6 on a third of the faces of M (4
// rows per face), 1 elsewhere.
std::vector<double> stiffened_row_weights(std::size_t faces)
{
  std::vector<double> row_weight(4 * faces, 1.0);
  for(std::size_t f = 0; f < faces; f += 3)
    for(std::size_t k = 0; k < 4; ++k)
      row_weight[4 * f + k] = std::sqrt(std::pow(10.0, double(f % 7)));
  return row_weight;
}

// ---------------------------------------------------------------------------
// 1. Systems without unknowns.
// ---------------------------------------------------------------------------

// Every real and complex factorization of the package takes a matrix without
// rows as a trivial success, and refuses a right-hand side of another size.
template <typename Solver, typename Scalar>
void check_empty_system()
{
  PVF::Sparse_factorization<Solver, Scalar> factorization{ Solver() };
  const Eigen::SparseMatrix<Scalar> A(0, 0);
  ASSERT_TRUE(factorization.analyze(A));
  ASSERT_TRUE(factorization.factorize(A));
  typename PVF::Sparse_factorization<Solver, Scalar>::Dense_matrix B(0, 3), X;
  ASSERT_TRUE(factorization.solve(B, X));
  EXPECT_EQ(X.rows(), 0);
  EXPECT_EQ(X.cols(), 3);
  B.resize(2, 1);
  B.setOnes();
  EXPECT_FALSE(factorization.solve(B, X));
}

TEST(RobustSolvers, EmptySystemIsATrivialSuccess)
{
  check_empty_system<PVF::Default_real_sparse_solver, double>();
  check_empty_system<CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > >, double>();
  check_empty_system<PVF::Default_sparse_solver, Complex>();
}

// The 12-triangle box: every vertex is a corner of valence 3, singular, so
// the map has no continuous unknown. It was a crash in CHOLMOD's analysis.
TEST(RobustMap, BoxWithoutContinuousUnknowns)
{
  const Mesh tm = box_of_triangles();
  ASSERT_EQ(num_faces(tm), 12u);
  Mesh& m = const_cast<Mesh&>(tm);
  auto field = m.add_property_map<Face, std::vector<Complex> >("f:field").first;
  box_frame_field(tm, field);
  std::map<Halfedge, UV> uv;
  PVF::Integer_grid_map_result r;
  const PVF::Error_code code = PVF::compute_integer_grid_map(tm, field, boost::make_assoc_property_map(uv), r);
  EXPECT_EQ(r.comb.singular_vertices, 8u);
  EXPECT_EQ(r.continuous_unknowns, 0u);
  ASSERT_EQ(code, PVF::Error_code::SUCCESS) << PVF::get_error_message(code);
  // every corner of the map is a singular vertex: on an integer point
  for(const auto& e : uv)
    for(int k = 0; k < 2; ++k)
      EXPECT_EQ(e.second[k], std::round(e.second[k]));
  EXPECT_EQ(r.max_seam_residual, 0.0);
  EXPECT_EQ(r.max_singularity_residual, 0.0);
}

// ---------------------------------------------------------------------------
// 2. Stiffening keeps the system solvable.
// ---------------------------------------------------------------------------

// Stiffening makes the faces near a flip heavier each round. Faces that stay
// flipped had their weight multiplied by at least 2 per round without bound,
// so that after tens of rounds the system was too ill-conditioned to solve
// (cow.off, h = 0.045: "the sparse linear solver failed" after 20 rounds,
// the Schur complement's eigenvalues from 0.008 to 4e16). Here the faces of a
// cap of a sphere stay flipped for 100 rounds: the weights stay bounded, and
// the mixed-integer system with them is still solved.
TEST(RobustMap, StiffeningWeightsStayBoundedAndSolvable)
{
  namespace I = PVF::internal;
  Sphere_map_system sys;
  ASSERT_NO_FATAL_FAILURE(sys.make());
  const auto& M = sys.comb.corner_mesh();
  const I::Guidance_system& S = sys.S;
  const std::size_t nx = sys.nx, m = sys.m;
  std::vector<std::vector<std::size_t> > vertex_faces(M.V);
  for(std::size_t c = 0; c < 3 * M.F; ++c)
    vertex_faces[M.target[c]].push_back(c / 3);
  const std::vector<Complex> zero_map(3 * M.F, Complex(0));
  std::vector<char> flag;
  ASSERT_EQ(I::flipped_faces(S, zero_map, flag), M.F);
  // the faces of the cap z > 0.7 stay flipped; the others keep weight 1 but near them
  std::size_t flipped = 0;
  for(std::size_t f = 0; f < M.F; ++f)
  {
    double z = 0;
    for(std::size_t k = 0; k < 3; ++k)
      z += M.point[M.target[3 * f + k]][2] / 3;
    flag[f] = z > 0.7;
    flipped += std::size_t(flag[f]);
  }
  ASSERT_GT(flipped, 0u);
  ASSERT_LT(flipped, M.F / 3);
  std::vector<double> weight(M.F, 1.0);
  for(int round = 0; round < 100; ++round)
    I::stiffen(M, S, vertex_faces, zero_map, flag, 1.0, weight);
  for(double w : weight)
  {
    EXPECT_GE(w, 1.0);
    EXPECT_LE(w, I::max_stiffening_weight);
  }
  std::vector<double> row_weight(4 * M.F);
  for(std::size_t k = 0; k < row_weight.size(); ++k)
    row_weight[k] = std::sqrt(weight[k / 4]);
  Eigen::VectorXd y_continuous, y_rounded;
  PVF::Integer_grid_map_result report;
  ASSERT_EQ(I::solve_mixed_integer(S.B1, S.d1, row_weight, nx, m, std::vector<I::Distinct_points>(),
                                   PVF::Default_real_sparse_solver(), false, y_continuous, y_rounded, report),
            PVF::Error_code::SUCCESS);
  ASSERT_EQ(y_rounded.size(), Eigen::Index(nx + m));
  EXPECT_TRUE(y_rounded.allFinite());
  for(std::size_t i = nx; i < nx + m; ++i)
    EXPECT_NEAR(y_rounded[Eigen::Index(i)], std::round(y_rounded[Eigen::Index(i)]), 1e-6);  // exact once snapped
}

// Stiffening reweights a few faces per round. The system adds
// (w - 1) B_r^T B_r to the normal equations of unit weights for those rows
// only; here that is held to the system made from the weighted rows
// directly, on the sphere's map with weights from 1 to 1e6 on a third of the
// faces: the same rounded integers, and the continuous unknowns within
// 1e-9 of the largest. A round that keeps the integers
// (solve_for_integers()) gives the rounded minimiser again.
TEST(RobustMap, ReweightedSystemEqualsTheWeightedRows)
{
  namespace I = PVF::internal;
  Sphere_map_system sys;
  ASSERT_NO_FATAL_FAILURE(sys.make());
  const auto& M = sys.comb.corner_mesh();
  const I::Guidance_system& S = sys.S;
  const std::size_t nx = sys.nx, m = sys.m;
  const std::vector<double> row_weight = stiffened_row_weights(M.F);
  Eigen::SparseMatrix<double> Bw = S.B1;
  Eigen::VectorXd dw = S.d1;
  for(Eigen::Index k = 0; k < Bw.outerSize(); ++k)
    for(Eigen::SparseMatrix<double>::InnerIterator it(Bw, k); it; ++it)
      it.valueRef() *= row_weight[std::size_t(it.row())];
  for(Eigen::Index r = 0; r < dw.size(); ++r)
    dw[r] *= row_weight[std::size_t(r)];
  const std::vector<double> unit(4 * M.F, 1.0);
  const std::vector<I::Distinct_points> none;
  const PVF::Default_real_sparse_solver solver;
  PVF::Integer_grid_map_result report;
  // first unit weights, then the stiffened ones: the second set_weights()
  // starts again from the unit equations
  I::Mixed_integer_system<PVF::Default_real_sparse_solver> reweighted(S.B1, S.d1, nx, m, none, solver),
    direct(Bw, dw, nx, m, none, solver);
  Eigen::VectorXd yc1, yr1, yc2, yr2, kept;
  ASSERT_EQ(reweighted.set_weights(unit, report), PVF::Error_code::SUCCESS);
  ASSERT_EQ(reweighted.set_weights(row_weight, report), PVF::Error_code::SUCCESS);
  ASSERT_EQ(reweighted.round(false, yc1, yr1, report), PVF::Error_code::SUCCESS);
  ASSERT_EQ(direct.set_weights(unit, report), PVF::Error_code::SUCCESS);
  ASSERT_EQ(direct.round(false, yc2, yr2, report), PVF::Error_code::SUCCESS);
  const double scale = yc2.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0);
  EXPECT_LE((yc1 - yc2).cwiseAbs().maxCoeff(), 1e-9 * scale);
  EXPECT_EQ(yr1.tail(Eigen::Index(m)), yr2.tail(Eigen::Index(m)));
  EXPECT_LE((yr1 - yr2).cwiseAbs().maxCoeff(), 1e-9 * scale);
  ASSERT_EQ(reweighted.solve_for_integers(Eigen::VectorXd(yr1.tail(Eigen::Index(m))), kept, report),
            PVF::Error_code::SUCCESS);
  EXPECT_LE((kept - yr1).cwiseAbs().maxCoeff(), 1e-12 * scale);
  // one analysis, three numeric factorizations
  EXPECT_EQ(report.factorizations, 3u);
}

// A round that keeps the integers after stiffening raised some weights is
// solved by conjugate gradient preconditioned by the factor of the weights
// before. Its stopping rule bounds the error in the energy norm of the new
// weights by 1e-12 sqrt(kappa) of the solution, kappa the largest ratio of a
// new weight to its factored one; held here to a system factored with the
// new weights, on the sphere's map:
// - the weights of 4 rounds of stiffen() around a flipped cap (kappa 16);
// - weights from 1 to 1e6 on a third of the faces: within the bound, or,
//   beyond 30 iterations, factored again and that system's solution to the
//   last bit;
// - no iteration allowed: factored again, the same solution to the last bit;
// - a weight lower than at the factorization: factored, not iterated.
TEST(RobustMap, StiffeningRoundByConjugateGradientMatchesTheFactoredSolve)
{
  namespace I = PVF::internal;
  typedef I::Mixed_integer_system<PVF::Default_real_sparse_solver> System;
  Sphere_map_system sys;
  ASSERT_NO_FATAL_FAILURE(sys.make());
  const auto& M = sys.comb.corner_mesh();
  const std::size_t F = M.F;
  const I::Guidance_system& S = sys.S;
  const std::size_t nx = sys.nx, m = sys.m;
  std::vector<std::vector<std::size_t> > vertex_faces(M.V);
  for(std::size_t c = 0; c < 3 * F; ++c)
    vertex_faces[M.target[c]].push_back(c / 3);
  const std::vector<Complex> zero_map(3 * F, Complex(0));
  std::vector<char> flag(F, 0);
  for(std::size_t f = 0; f < F; ++f)
    flag[f] = M.point[M.target[3 * f]][2] > 0.8;  // a cap of the sphere
  std::vector<double> weight(F, 1.0);
  for(int round = 0; round < 4; ++round)
    I::stiffen(M, S, vertex_faces, zero_map, flag, 1.0, weight);
  const double kappa = *std::max_element(weight.begin(), weight.end());  // factored with unit weights
  ASSERT_GT(kappa, 2.0);
  const std::vector<double> unit(4 * F, 1.0), large = stiffened_row_weights(F);
  std::vector<double> stiffened(4 * F);
  for(std::size_t k = 0; k < stiffened.size(); ++k)
    stiffened[k] = std::sqrt(weight[k / 4]);
  const std::vector<I::Distinct_points> none;
  const PVF::Default_real_sparse_solver solver;
  const Eigen::SparseMatrix<double> Bx = S.B1.leftCols(Eigen::Index(nx));

  // |x|_K with K = Bx^T W Bx, as the weighted rows' norm of Bx x
  auto energy_norm = [&](const std::vector<double>& row_weight, const Eigen::VectorXd& x) {
    const Eigen::VectorXd r = Bx * x;
    double sum = 0;
    for(Eigen::Index k = 0; k < r.size(); ++k)
      sum += std::pow(row_weight[std::size_t(k)] * r[k], 2);
    return std::sqrt(sum);
  };
  // The round with `row_weight` after a factorization with unit weights, by
  // a system allowed `iterations`, against a system factored with row_weight.
  auto check_round = [&](const std::vector<double>& row_weight, std::size_t iterations, double bound, bool must_iterate) {
    PVF::Integer_grid_map_result kept, factored;
    System cg(S.B1, S.d1, nx, m, none, solver), direct(S.B1, S.d1, nx, m, none, solver);
    cg.set_cg_max_iterations(iterations);
    Eigen::VectorXd yc, yr, y_cg, y_direct;
    ASSERT_EQ(cg.set_weights(unit, kept), PVF::Error_code::SUCCESS);
    ASSERT_EQ(cg.round(false, yc, yr, kept), PVF::Error_code::SUCCESS);
    const Eigen::VectorXd n = yr.tail(Eigen::Index(m));  // the integers of unit weights, kept
    ASSERT_EQ(cg.set_weights(row_weight, kept, false), PVF::Error_code::SUCCESS);
    ASSERT_EQ(cg.solve_for_integers(n, y_cg, kept), PVF::Error_code::SUCCESS);
    ASSERT_EQ(direct.set_weights(row_weight, factored), PVF::Error_code::SUCCESS);
    ASSERT_EQ(direct.solve_for_integers(n, y_direct, factored), PVF::Error_code::SUCCESS);
    EXPECT_EQ(factored.cg_solves, 0u);
    if(must_iterate)
      ASSERT_EQ(kept.cg_solves, 1u);
    if(kept.cg_solves == 1)
    {
      EXPECT_EQ(kept.factorizations, 1u);
      EXPECT_GE(kept.cg_iterations, 1u);
      const Eigen::VectorXd x_direct = y_direct.head(Eigen::Index(nx));
      const double error = energy_norm(row_weight, Eigen::VectorXd(y_cg.head(Eigen::Index(nx)) - x_direct)),
                   size = energy_norm(row_weight, x_direct);
      ASSERT_GT(size, 0);
      EXPECT_LE(error, bound * size);
      std::printf("[ conjugate gradient ] %zu iterations, energy-norm error %.3g of the solution (bound %.3g)\n",
                  kept.cg_iterations, error / size, bound);
    }
    else
    {
      EXPECT_EQ(kept.factorizations, 2u);  // factored again
      EXPECT_EQ(y_cg, y_direct);
      std::printf("[ conjugate gradient ] factored again after %zu iterations\n", iterations);
    }
  };
  ASSERT_NO_FATAL_FAILURE(check_round(stiffened, I::stiffening_cg_max_iterations, 1e-12 * std::sqrt(kappa), true));
  ASSERT_NO_FATAL_FAILURE(check_round(large, I::stiffening_cg_max_iterations, 1e-12 * std::sqrt(1e6), false));
  ASSERT_NO_FATAL_FAILURE(check_round(stiffened, 0, 0, false));

  // a weight below its factored value: the round factors, it does not iterate
  PVF::Integer_grid_map_result lowered;
  System system(S.B1, S.d1, nx, m, none, solver);
  Eigen::VectorXd yc, yr, y;
  ASSERT_EQ(system.set_weights(stiffened, lowered), PVF::Error_code::SUCCESS);
  ASSERT_EQ(system.round(false, yc, yr, lowered), PVF::Error_code::SUCCESS);
  ASSERT_EQ(system.set_weights(unit, lowered, false), PVF::Error_code::SUCCESS);
  ASSERT_EQ(system.solve_for_integers(Eigen::VectorXd(yr.tail(Eigen::Index(m))), y, lowered), PVF::Error_code::SUCCESS);
  EXPECT_EQ(lowered.factorizations, 2u);
  EXPECT_EQ(lowered.cg_solves, 0u);
}

// Two integer points that round to the same point fold every face between
// them: the rounding takes the other integer next to the minimiser for the
// last unknown of their difference. Here x (continuous) wants 0, and the
// integer unknowns n0 and n1 want 0.3 and 0.4: both round to 0 unless
// n0 - n1 must not vanish. n0 is rounded first (closer to an integer), then
// n1 takes 1. Both the greedy updates and the refactoring reference.
TEST(RobustMap, RoundingKeepsTwoIntegerPointsApart)
{
  namespace I = PVF::internal;
  Eigen::SparseMatrix<double> B(3, 3);
  B.insert(0, 0) = 1;
  B.insert(1, 1) = 1;
  B.insert(2, 2) = 1;
  B.makeCompressed();
  Eigen::VectorXd d(3);
  d << 0, 0.3, 0.4;
  const std::vector<double> row_weight(3, 1.0);
  I::Distinct_points apart;
  apart.terms = { { 0, 1, 0 }, { 1, -1, 0 } };
  for(bool refactor : { false, true })
  {
    Eigen::VectorXd y_continuous, y_rounded;
    PVF::Integer_grid_map_result report;
    ASSERT_EQ(I::solve_mixed_integer(B, d, row_weight, 1, 2, std::vector<I::Distinct_points>(),
                                     PVF::Default_real_sparse_solver(), refactor, y_continuous, y_rounded, report),
              PVF::Error_code::SUCCESS);
    EXPECT_EQ(y_rounded[1], 0.0);
    EXPECT_EQ(y_rounded[2], 0.0) << "without the form, both round to the same integer";
    EXPECT_EQ(report.integer_point_collisions_avoided, 0u);
    ASSERT_EQ(I::solve_mixed_integer(B, d, row_weight, 1, 2, std::vector<I::Distinct_points>{ apart },
                                     PVF::Default_real_sparse_solver(), refactor, y_continuous, y_rounded, report),
              PVF::Error_code::SUCCESS);
    EXPECT_EQ(y_rounded[1], 0.0) << refactor;
    EXPECT_EQ(y_rounded[2], 1.0) << refactor;
    EXPECT_EQ(report.integer_point_collisions_avoided, 1u) << refactor;
  }
}

// ---------------------------------------------------------------------------
// 3. Polygons that other tools accept.
// ---------------------------------------------------------------------------

struct Read_mesh
{
  PVF::Error_code code;
  Mesh tm;
  PVF::IO::Mesh_repair_result report;
};

Read_mesh read_off(const std::string& name, const std::string& text)
{
  const std::string path = ::testing::TempDir() + "pvf_robust_" + name;
  {
    std::ofstream out(path);
    out << text;
  }
  Read_mesh r;
  r.code = PVF::IO::read_triangle_mesh(path, r.tm, r.report);
  std::remove(path.c_str());
  return r;
}

// cos of the dihedral angle at the edge between two triangles sharing edge (a, b)
double dihedral_cosine(const Mesh& tm)
{
  std::vector<Vector> n;
  for(auto f : faces(tm))
    n.push_back(CGAL::Polygon_mesh_processing::compute_face_normal(f, tm));
  return n.size() == 2 ? n[0] * n[1] : -2;
}

// A skew quad, as face 0 of the gridded box cube_40k.obj (a quad whose
// projection on its best coordinate plane is not simple): split by the
// diagonal with the smaller dihedral angle, never refused.
TEST(RobustInput, NonPlanarQuadIsSplitByItsBetterDiagonal)
{
  const Read_mesh r = read_off("skew.off", "OFF\n4 1 0\n0 0 0\n0 -1 0\n-1 -1 -1\n0 -1 -1\n4 0 1 2 3\n");
  ASSERT_EQ(r.code, PVF::Error_code::SUCCESS);
  EXPECT_EQ(r.report.triangulated_faces, 1u);
  EXPECT_EQ(r.report.faces_triangulated_in_3d, 1u);
  ASSERT_EQ(num_faces(r.tm), 2u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(r.tm));
  // the other diagonal, by hand: the two splits' dihedral cosines
  const Vector p0(0, 0, 0), p1(0, -1, 0), p2(-1, -1, -1), p3(0, -1, -1);
  auto cosine = [](const Vector& a, const Vector& b, const Vector& c, const Vector& d) {
    const Vector n1 = CGAL::cross_product(b - a, c - a), n2 = CGAL::cross_product(c - a, d - a);
    return (n1 * n2) / std::sqrt(n1.squared_length() * n2.squared_length());
  };
  const double best = (std::max)(cosine(p0, p1, p2, p3), cosine(p1, p2, p3, p0));
  EXPECT_NEAR(dihedral_cosine(r.tm), best, 1e-12);
  // orientation kept: both triangles turn as the quad (normals on the same side as its Newell normal)
  const Vector newell(0.5 * ((p0.y() - p1.y()) * (p0.z() + p1.z()) + (p1.y() - p2.y()) * (p1.z() + p2.z()) +
                             (p2.y() - p3.y()) * (p2.z() + p3.z()) + (p3.y() - p0.y()) * (p3.z() + p0.z())),
                      0.5 * ((p0.z() - p1.z()) * (p0.x() + p1.x()) + (p1.z() - p2.z()) * (p1.x() + p2.x()) +
                             (p2.z() - p3.z()) * (p2.x() + p3.x()) + (p3.z() - p0.z()) * (p3.x() + p0.x())),
                      0.5 * ((p0.x() - p1.x()) * (p0.y() + p1.y()) + (p1.x() - p2.x()) * (p1.y() + p2.y()) +
                             (p2.x() - p3.x()) * (p2.y() + p3.y()) + (p3.x() - p0.x()) * (p3.y() + p0.y())));
  for(auto f : faces(r.tm))
    EXPECT_GT(CGAL::Polygon_mesh_processing::compute_face_normal(f, r.tm) * newell, 0);
}

// A planar non-convex quad (a dart): the diagonal inside it, not the one
// that folds it; a planar convex quad: the diagonal of the larger smallest angle.
TEST(RobustInput, PlanarQuadsSplitWithoutFold)
{
  const Read_mesh dart = read_off("dart.off", "OFF\n4 1 0\n0 0 0\n2 1 0\n0 2 0\n0.5 1 0\n4 0 1 2 3\n");
  ASSERT_EQ(dart.code, PVF::Error_code::SUCCESS);
  EXPECT_EQ(dart.report.faces_triangulated_in_3d, 0u);
  ASSERT_EQ(num_faces(dart.tm), 2u);
  EXPECT_NEAR(dihedral_cosine(dart.tm), 1.0, 1e-12);
  // a long thin rectangle with a shifted corner: the diagonal 1-3 gives the fatter triangles
  const Read_mesh kite = read_off("kite.off", "OFF\n4 1 0\n0 0 0\n3 0 0\n3.2 1 0\n0 1 0\n4 0 1 2 3\n");
  ASSERT_EQ(kite.code, PVF::Error_code::SUCCESS);
  ASSERT_EQ(num_faces(kite.tm), 2u);
  bool has_diagonal_13 = false;
  for(auto e : edges(kite.tm))
  {
    const Point a = kite.tm.point(source(e, kite.tm)), b = kite.tm.point(target(e, kite.tm));
    if(!is_border(e, kite.tm))
      has_diagonal_13 = (a == Point(3, 0, 0) && b == Point(0, 1, 0)) || (b == Point(3, 0, 0) && a == Point(0, 1, 0));
  }
  EXPECT_TRUE(has_diagonal_13);
}

// A non-planar hexagon whose projection on every coordinate plane folds (a
// zig-zag crown): triangulated in 3D into 4 triangles, a valid surface.
TEST(RobustInput, NonPlanarHexagonTriangulatedIn3D)
{
  std::string off = "OFF\n6 1 0\n";
  for(int k = 0; k < 6; ++k)
  {
    const double a = 2 * CGAL_PI * double(k) / 6;
    off += std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " " + (k % 2 ? "1.5" : "-1.5") + "\n";
  }
  // vertices in the order 0 2 4 1 3 5: a star whose projection on z = 0 crosses itself
  off += "6 0 2 4 1 3 5\n";
  const Read_mesh r = read_off("crown.off", off);
  ASSERT_EQ(r.code, PVF::Error_code::SUCCESS);
  EXPECT_EQ(r.report.triangulated_faces, 1u);
  EXPECT_EQ(r.report.faces_triangulated_in_3d, 1u);
  EXPECT_EQ(num_faces(r.tm), 4u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(r.tm));
  // still refused: a planar polygon that folds onto itself (a bow tie)
  const Read_mesh bow_tie = read_off("bow.off", "OFF\n4 1 0\n0 0 0\n1 1 0\n1 0 0\n0 1 0\n4 0 1 2 3\n");
  EXPECT_EQ(bow_tie.code, PVF::Error_code::NON_TRIANGLE_FACE);
}

// ---------------------------------------------------------------------------
// 4. Every map is checked before it is returned.
// ---------------------------------------------------------------------------

// The maps that come back are exact under their own transitions, and the
// check (internal/Integer_grid_map/map_check.h) finds every kind of damage
// done to one of them: a translation, a rotation, a singular value moved off
// the grid.
TEST(RobustMap, ReturnedMapsPassTheCheckAndDamageIsFound)
{
  typedef PVF::Tangent_bundle<Mesh> Bundle;
  Mesh tm = sphere(2);
  auto field = tm.add_property_map<Face, std::vector<Complex> >("f:field").first;
  ASSERT_EQ(PVF::design_polyvector_field(tm, 4, random_constraints(tm, 5, 2, 11), field, PVF::parameters::sign_symmetric(true)),
            PVF::Error_code::SUCCESS);
  const Bundle bundle(tm);
  PVF::Frame_field_comb<Bundle> comb;
  ASSERT_EQ(comb.compute(bundle, field, 10 * CGAL_PI / 180), PVF::Error_code::SUCCESS);
  std::map<Halfedge, UV> uv;
  PVF::Integer_grid_map_result r;
  ASSERT_EQ(PVF::compute_integer_grid_map(comb, boost::make_assoc_property_map(uv), r, PVF::parameters::target_edge_length(0.3)),
            PVF::Error_code::SUCCESS);
  EXPECT_TRUE(r.diagnostic.empty());
  EXPECT_EQ(r.max_seam_residual, 0.0);
  EXPECT_EQ(r.max_singularity_residual, 0.0);
  ASSERT_GT(r.comb.singular_vertices, 0u);
  ASSERT_GT(r.comb.cut_edges, 0u);

  const auto& M = comb.corner_mesh();
  const auto& D = comb.data();
  std::vector<Complex> values(3 * M.F);
  for(std::size_t c = 0; c < 3 * M.F; ++c)
    values[c] = Complex(uv[M.halfedge[c]][0], uv[M.halfedge[c]][1]);
  namespace I = PVF::internal;
  EXPECT_EQ(I::check_integer_grid_map(M, D, values, r.seam_transitions), "");
  // an interior edge with a transition, one off the cut, a singular corner
  std::size_t seam = 0, plain = 0, singular = 0;
  while(!(M.opposite[seam] != I::npos && (r.seam_transitions[seam].rotation != 0 ||
                                          r.seam_transitions[seam].translation != std::array<std::int64_t, 2>{ { 0, 0 } })))
    ++seam;
  while(M.opposite[plain] == I::npos || D.seam[plain])
    ++plain;
  while(D.index[M.target[singular]] == 0)
    ++singular;
  auto damaged = [&](auto change) {
    auto v = values;
    auto t = r.seam_transitions;
    change(v, t);
    return I::check_integer_grid_map(M, D, v, t);
  };
  const std::string translated = damaged([&](auto&, auto& t) { t[seam].translation[0] += 1; });
  EXPECT_NE(translated.find("not exact"), std::string::npos) << translated;
  const std::string rotated = damaged([&](auto&, auto& t) { t[plain].rotation = (t[plain].rotation + 1) % 4; });
  EXPECT_FALSE(rotated.empty());
  const std::string off_grid = damaged([&](auto& v, auto&) {
    for(std::size_t c = 0; c < v.size(); ++c)
      if(M.target[c] == M.target[singular])
        v[c] += Complex(0.25, 0);
  });
  EXPECT_FALSE(off_grid.empty());
}

// ---------------------------------------------------------------------------
// 5. No empty quad mesh.
// ---------------------------------------------------------------------------

// A frame along the axes on every face of a flat mesh.
void axis_frames(const Mesh& tm, Mesh::Property_map<Face, std::vector<Complex> > field)
{
  std::vector<PVF::Face_constraint<Face, Vector> > constraints;
  for(Face f : faces(tm))
    constraints.push_back(PVF::Face_constraint<Face, Vector>{ f, { Vector(1, 0, 0), Vector(0, 1, 0) } });
  ASSERT_EQ(PVF::design_polyvector_field(tm, 4, constraints, field, PVF::parameters::sign_symmetric(true)),
            PVF::Error_code::SUCCESS);
}

// `split`: split_components_without_cells
PVF::Error_code quads_of(const Mesh& tm, double h, Mesh& quads, PVF::Quad_extraction_result& extraction,
                         bool split = false)
{
  Mesh& m = const_cast<Mesh&>(tm);
  auto field = m.add_property_map<Face, std::vector<Complex> >("f:axes").first;
  axis_frames(tm, field);
  typedef PVF::Tangent_bundle<Mesh> Bundle;
  const Bundle bundle(tm);
  PVF::Frame_field_comb<Bundle> comb;
  EXPECT_EQ(comb.compute(bundle, field, 10 * CGAL_PI / 180), PVF::Error_code::SUCCESS);
  std::map<Halfedge, UV> uv;
  PVF::Integer_grid_map_result r;
  const PVF::Error_code code =
    PVF::compute_integer_grid_map(comb, boost::make_assoc_property_map(uv), r, PVF::parameters::target_edge_length(h));
  EXPECT_EQ(code, PVF::Error_code::SUCCESS);
  if(code != PVF::Error_code::SUCCESS)
    return code;
  return PVF::extract_quad_mesh(bundle, boost::make_assoc_property_map(uv), r, quads, extraction,
                                PVF::parameters::split_components_without_cells(split));
}

// The 2-triangle unit square with quads of size 2: no integer cell. An
// error that says so, not an empty mesh.
TEST(RobustQuads, QuadLargerThanTheSurfaceIsAnError)
{
  const Mesh square = grid(1, 1);
  ASSERT_EQ(num_faces(square), 2u);
  Mesh quads;
  CGAL::make_triangle(Point(5, 5, 5), Point(6, 5, 5), Point(5, 6, 5), quads);  // untouched on failure
  PVF::Quad_extraction_result extraction;
  EXPECT_EQ(quads_of(square, 2.0, quads, extraction), PVF::Error_code::NO_INTEGER_CELL);
  EXPECT_EQ(extraction.components, 1u);
  EXPECT_EQ(extraction.components_without_cells, 1u);
  EXPECT_NE(extraction.diagnostic.find("the surface has no whole integer cell"), std::string::npos) << extraction.diagnostic;
  EXPECT_EQ(num_faces(quads), 1u);
  // a quad size that fits: 4 quads
  Mesh fine;
  ASSERT_EQ(quads_of(square, 0.5, fine, extraction), PVF::Error_code::SUCCESS) << extraction.diagnostic;
  EXPECT_EQ(num_faces(fine), 4u);
}

// Two components, a 4 x 4 grid and a square of side 0.4 beside it: with quads
// of size 1 the small one gets none. Refused, and the diagnostic names it.
TEST(RobustQuads, ComponentWithoutQuadIsNamed)
{
  Mesh tm = grid(4, 4);
  const std::size_t big_faces = num_faces(tm);
  const Mesh small = grid(1, 1);
  std::map<Mesh::Vertex_index, Mesh::Vertex_index> to;
  for(auto v : vertices(small))
    to[v] = tm.add_vertex(Point(10 + 0.4 * small.point(v).x(), 0.4 * small.point(v).y(), 0));
  for(auto f : faces(small))
  {
    std::vector<Mesh::Vertex_index> vs;
    for(auto v : CGAL::vertices_around_face(halfedge(f, small), small))
      vs.push_back(to[v]);
    tm.add_face(vs);
  }
  Mesh quads;
  PVF::Quad_extraction_result extraction;
  EXPECT_EQ(quads_of(tm, 1.0, quads, extraction), PVF::Error_code::NO_INTEGER_CELL);
  EXPECT_EQ(extraction.components, 2u);
  EXPECT_EQ(extraction.components_without_cells, 1u);
  EXPECT_NE(extraction.diagnostic.find("1 of the 2 components, the first one (2 faces, face " + std::to_string(big_faces) + ")"),
            std::string::npos)
    << extraction.diagnostic;
  EXPECT_EQ(num_faces(quads), 0u);
  // split_components_without_cells: the small square's two triangles become six quads,
  // the grid keeps its 16, two components of quads (the square's a disk: chi 1)
  Mesh split;
  ASSERT_EQ(quads_of(tm, 1.0, split, extraction, true), PVF::Error_code::SUCCESS) << extraction.diagnostic;
  EXPECT_EQ(extraction.split_small_components, 1u);
  EXPECT_EQ(extraction.split_components, 1u);
  EXPECT_EQ(extraction.split_triangles, 2u);
  EXPECT_EQ(num_faces(split), 16u + 6u);
  auto fcc = split.add_property_map<Mesh::Face_index, std::size_t>("f:cc").first;
  EXPECT_EQ(CGAL::Polygon_mesh_processing::connected_components(split, fcc), 2u);
  std::size_t small_quads = 0;
  for(Mesh::Face_index f : faces(split))
  {
    const Point c = CGAL::centroid(split.point(target(halfedge(f, split), split)),
                                   split.point(target(next(halfedge(f, split), split), split)),
                                   split.point(target(next(next(halfedge(f, split), split), split), split)));
    small_quads += c.x() > 9;  // the square lies at x in [10, 10.4]
  }
  EXPECT_EQ(small_quads, 6u);
  // every component without a cell: still an error, the quad size is wrong
  const Mesh square = grid(1, 1);
  EXPECT_EQ(quads_of(square, 2.0, split, extraction, true), PVF::Error_code::NO_INTEGER_CELL);
}

} // namespace
