// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// One road from a mesh to planar quads, as the command-line program takes it:
// design, conjugate field, combing, integer-grid map, extraction,
// planarization. Each stage takes what the stage before it returned; a
// solver that counts its factorizations shows that none is computed twice.

#include <CGAL/Polyvector_fields/Sparse_factorization.h>

#include <atomic>
#include <memory>

namespace road {

// A solver as the user passes it: the solver `Inner`, and a counter of the
// numeric factorizations made with it.
template <typename Inner>
struct Counting_solver
{
  Inner inner;
  std::shared_ptr<std::atomic<int> > factorizations = std::make_shared<std::atomic<int> >(0);
};

} // namespace road

namespace CGAL {
namespace Polyvector_fields {

// The model of SparseFactorization: the one of `Inner`, counting.
template <typename Inner, typename Scalar>
class Sparse_factorization<road::Counting_solver<Inner>, Scalar> : public Sparse_factorization<Inner, Scalar>
{
  typedef Sparse_factorization<Inner, Scalar> Base;

public:
  explicit Sparse_factorization(const road::Counting_solver<Inner>& solver = road::Counting_solver<Inner>())
    : Base(solver.inner), m_count(solver.factorizations)
  {}
  bool factorize(const typename Base::Matrix& A)
  {
    ++*m_count;
    return Base::factorize(A);
  }

private:
  std::shared_ptr<std::atomic<int> > m_count;
};

} // namespace Polyvector_fields
} // namespace CGAL

#include "test_meshes.h"

#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/comb_frame_field.h>
#include <CGAL/Polyvector_fields/compute_integer_grid_map.h>
#include <CGAL/Polyvector_fields/design_conjugate_frame_field.h>
#include <CGAL/Polyvector_fields/extract_quad_mesh.h>
#include <CGAL/Polyvector_fields/planarize_quad_mesh.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <vector>

namespace {

namespace PVF = CGAL::Polyvector_fields;
using namespace pvf_test;

typedef PVF::Tangent_bundle<Mesh> Bundle;
typedef road::Counting_solver<PVF::Default_sparse_solver> Complex_solver;
typedef road::Counting_solver<PVF::Default_real_sparse_solver> Real_solver;

} // namespace

// The paper's Fig. 1 input, from the mesh to planar quads: the field is
// designed once (one factorization per coefficient degree), the conjugate
// field factors only its own global steps, the map combs the field it is
// given and factors as often as it says, and the planarizer factors once.
TEST(Road, EveryStageComputesOnce)
{
  const Mesh tm = load("inspired_mesh.obj");
  std::vector<PVF::Face_constraint<Mesh::Face_index, Vector> > constraints;
  ASSERT_EQ(PVF::IO::read_dmat_constraints(data("inspired_mesh_b.dmat"), data("inspired_mesh_bc.dmat"), tm, constraints),
            PVF::Error_code::SUCCESS);
  const Bundle bundle(tm);
  const Complex_solver complex_solver;
  const Real_solver real_solver;

  // Design.
  PVF::Polyvector_field_designer<Mesh, CGAL::Default, CGAL::Default, Complex_solver> designer(
    bundle, 4, PVF::parameters::sign_symmetric(true, CGAL::parameters::sparse_linear_solver(complex_solver)));
  ASSERT_EQ(designer.add_constraints(constraints), PVF::Error_code::SUCCESS);
  PVF::Polyvector_field<Bundle> field(bundle, 4, true);
  ASSERT_EQ(designer.solve(field), PVF::Error_code::SUCCESS);
  const int degrees = int(designer.statistics().number_of_degrees_solved);
  EXPECT_EQ(degrees, 2);  // c_0 and c_2, full constraints: one block each
  EXPECT_EQ(*complex_solver.factorizations, degrees);

  // The conjugate field: the global steps of the designed field, and nothing else.
  PVF::Conjugate_field_result conjugate;
  ASSERT_EQ(PVF::design_conjugate_frame_field(field, conjugate, CGAL::parameters::sparse_linear_solver(complex_solver)),
            PVF::Error_code::SUCCESS);
  EXPECT_TRUE(conjugate.converged);
  EXPECT_GE(conjugate.factorizations, 1u);
  EXPECT_EQ(*complex_solver.factorizations, degrees * int(1 + conjugate.factorizations));

  // Combing once; the map takes the comb.
  PVF::Frame_field_comb<Bundle> comb;
  ASSERT_EQ(PVF::comb_frame_field(field, comb), PVF::Error_code::SUCCESS);
  ASSERT_TRUE(comb.is_valid());
  std::map<Mesh::Halfedge_index, std::array<double, 2> > uv;
  PVF::Integer_grid_map_result map;
  ASSERT_EQ(PVF::compute_integer_grid_map(comb, boost::make_assoc_property_map(uv), map,
                                          PVF::parameters::target_edge_length(
                                            0.82, CGAL::parameters::sparse_linear_solver(real_solver))),
            PVF::Error_code::SUCCESS);
  EXPECT_EQ(map.comb.cut_edges, comb.report().cut_edges);
  EXPECT_GE(map.factorizations, 1u);
  EXPECT_EQ(*real_solver.factorizations, int(map.factorizations));
  EXPECT_EQ(*complex_solver.factorizations, degrees * int(1 + conjugate.factorizations));  // no design in the map

  // Extraction from the map's own transitions, then planarization with one factorization.
  Mesh quads;
  PVF::Quad_extraction_result extraction;
  ASSERT_EQ(PVF::extract_quad_mesh(bundle, boost::make_assoc_property_map(uv), map, quads, extraction),
            PVF::Error_code::SUCCESS);
  ASSERT_GT(num_faces(quads), 1000u);
  for(auto f : faces(quads))
    ASSERT_EQ(CGAL::halfedges_around_face(halfedge(f, quads), quads).size(), 4u);
  PVF::Planarization_result planarization;
  const int before_planarization = *real_solver.factorizations;
  ASSERT_EQ(PVF::planarize_quad_mesh(quads, tm, planarization, CGAL::parameters::sparse_linear_solver(real_solver)),
            PVF::Error_code::SUCCESS);
  EXPECT_TRUE(planarization.converged);
  EXPECT_LE(planarization.max_planarity_after, 0.01);
  EXPECT_EQ(*real_solver.factorizations - before_planarization, 1);
}
