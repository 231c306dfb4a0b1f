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

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/generators.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <complex>
#include <map>
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

} // namespace
