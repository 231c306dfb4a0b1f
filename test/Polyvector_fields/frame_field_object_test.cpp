// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// The field as an object: the designer makes a Polyvector_field, the later
// stages take it, and the frame-field algorithms optimise it in place without
// designing it again. The local-global optimizer is generic in N.

#include "test_meshes.h"

#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/design_angle_bounded_frame_field.h>
#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>
#include <CGAL/Polyvector_fields/design_conjugate_frame_field.h>
#include <CGAL/Polyvector_fields/frame_field_measures.h>
#include <CGAL/Polyvector_fields/internal/Field_design/Local_global_optimizer.h>
#include <CGAL/Polyvector_fields/smoothness_energy.h>

#include <gtest/gtest.h>

#include <complex>
#include <cstring>
#include <map>
#include <vector>

namespace PVF = CGAL::Polyvector_fields;
using namespace pvf_test;

namespace {

typedef std::complex<double> Complex;
typedef Mesh::Face_index Face;
typedef PVF::Tangent_bundle<Mesh> Bundle;
typedef PVF::Polyvector_field<Bundle> Field;
typedef PVF::Polyvector_field_designer<Mesh> Designer;

// The smooth frame field of `constraints` on `bundle`, from the designer.
Field smooth_frame_field(const Bundle& bundle, const std::vector<PVF::Face_constraint<Face, Vector> >& constraints)
{
  Designer designer(bundle, 4, PVF::parameters::sign_symmetric(true));
  EXPECT_EQ(designer.add_constraints(constraints), PVF::Error_code::SUCCESS);
  Field field(bundle, 4, true);
  EXPECT_EQ(designer.solve(field), PVF::Error_code::SUCCESS);
  return field;
}

bool same_bits(const std::vector<Complex>& a, const std::vector<Complex>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Complex)) == 0;
}

} // namespace

// The designer's field holds what the design was: its degree, symmetry,
// constraints and coefficients, the same as the coefficient-map overload's;
// the property-map view reads them.
TEST(FieldObject, DesignerMakesTheFieldOfItsConstraints)
{
  const Mesh tm = load("bumpy.off");
  const Bundle bundle(tm);
  const auto constraints = random_constraints(tm, 12, 2, 5);
  const Field field = smooth_frame_field(bundle, constraints);
  EXPECT_EQ(field.degree(), 4u);
  EXPECT_TRUE(field.is_sign_symmetric());
  EXPECT_TRUE(field.is_frame_field());
  EXPECT_EQ(field.number_of_constraints(), constraints.size());
  for(const auto& c : constraints)
    EXPECT_TRUE(field.is_fixed(c.face));  // two vectors, hard: a full constraint
  std::size_t fixed = 0;
  for(Face f : faces(tm))
    fixed += field.is_fixed(f) ? 1 : 0;
  EXPECT_EQ(fixed, constraints.size());

  Designer designer(bundle, 4, PVF::parameters::sign_symmetric(true));
  ASSERT_EQ(designer.add_constraints(constraints), PVF::Error_code::SUCCESS);
  std::map<Face, std::vector<Complex> > by_map;
  ASSERT_EQ(designer.solve(boost::make_assoc_property_map(by_map)), PVF::Error_code::SUCCESS);
  const auto view = field.coefficient_map();
  for(Face f : faces(tm))
  {
    const std::vector<Complex> c = get(view, f);
    ASSERT_EQ(c.size(), 4u);
    EXPECT_EQ(std::memcmp(c.data(), by_map[f].data(), 4 * sizeof(Complex)), 0);
  }
  // A field read back from the map is the same field, but without constraints.
  Field read(bundle, 4, true);
  ASSERT_EQ(read.read_coefficients(boost::make_assoc_property_map(by_map)), PVF::Error_code::SUCCESS);
  EXPECT_TRUE(same_bits(read.coefficients(), field.coefficients()));
  EXPECT_EQ(read.number_of_constraints(), 0u);
  // A map of the wrong degree is refused and leaves the field as it was.
  Field six(bundle, 6);
  EXPECT_EQ(six.read_coefficients(boost::make_assoc_property_map(by_map)), PVF::Error_code::INCONSISTENT_DEGREE);
  for(const Complex& c : six.coefficients())
    EXPECT_EQ(c, Complex(0));
}

// The stages that take the field give what they give from its coefficient map.
TEST(FieldObject, StagesTakeTheField)
{
  const Mesh tm = load("bumpy.off");
  const Bundle bundle(tm);
  const Field field = smooth_frame_field(bundle, random_constraints(tm, 12, 2, 7));
  std::map<Face, std::vector<Complex> > c;
  field.write_coefficients(boost::make_assoc_property_map(c));
  const auto cmap = boost::make_assoc_property_map(c);

  std::map<Face, std::vector<Vector> > roots_field, roots_map;
  ASSERT_EQ(PVF::compute_field_roots(field, boost::make_assoc_property_map(roots_field)), PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::compute_field_roots(bundle, 4, cmap, boost::make_assoc_property_map(roots_map),
                                     PVF::parameters::sign_symmetric(true)),
            PVF::Error_code::SUCCESS);
  ASSERT_EQ(roots_field.size(), num_faces(tm));
  for(Face f : faces(tm))
    for(std::size_t k = 0; k < 4; ++k)
      EXPECT_EQ(roots_field[f][k], roots_map[f][k]);

  std::vector<PVF::Singularity<Mesh::Vertex_index> > s_field, s_map;
  ASSERT_EQ(PVF::compute_singularities(field, std::back_inserter(s_field)), PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::compute_singularities(bundle, 4, cmap, std::back_inserter(s_map)), PVF::Error_code::SUCCESS);
  ASSERT_EQ(s_field.size(), s_map.size());
  int sum = 0;
  for(std::size_t i = 0; i < s_field.size(); ++i)
  {
    EXPECT_EQ(s_field[i].vertex, s_map[i].vertex);
    EXPECT_EQ(s_field[i].index_numerator, s_map[i].index_numerator);
    sum += s_field[i].index_numerator;
  }
  EXPECT_EQ(sum, 4 * euler_characteristic(tm));  // Poincare-Hopf on the closed bumpy sphere

  EXPECT_EQ(PVF::smoothness_energy(field), PVF::smoothness_energy(bundle, 4, cmap));
  std::map<Face, double> a_field, a_map;
  ASSERT_EQ(PVF::compute_frame_angles(field, boost::make_assoc_property_map(a_field)), PVF::Error_code::SUCCESS);
  ASSERT_EQ(PVF::compute_frame_angles(bundle, cmap, boost::make_assoc_property_map(a_map)), PVF::Error_code::SUCCESS);
  EXPECT_EQ(a_field, a_map);
  // Frame-field measures refuse a field that is not a frame field.
  EXPECT_EQ(PVF::compute_frame_angles(Field(bundle, 6), boost::make_assoc_property_map(a_field)),
            PVF::Error_code::NOT_A_FRAME_FIELD);
}

// The frame-field algorithms optimise the field they are given, holding the
// constraints of its design: the result is bit for bit the one of the
// overload that takes the constraints, and the frames of the constrained
// faces do not move.
TEST(FieldObject, FrameFieldsOptimiseTheGivenField)
{
  const Mesh tm = load("bumpy.off");
  const Bundle bundle(tm);
  const auto constraints = random_constraints(tm, 20, 2, 11);
  const Field smooth = smooth_frame_field(bundle, constraints);

  Field bounded = smooth;
  PVF::Angle_bound_result ab;
  ASSERT_EQ(PVF::design_angle_bounded_frame_field(bounded, ab), PVF::Error_code::SUCCESS);
  EXPECT_TRUE(ab.converged);
  EXPECT_GE(ab.iterations, 1u);
  std::map<Face, std::vector<Complex> > by_constraints;
  PVF::Angle_bound_result ab2;
  ASSERT_EQ(PVF::design_angle_bounded_frame_field(bundle, constraints, boost::make_assoc_property_map(by_constraints), ab2),
            PVF::Error_code::SUCCESS);
  EXPECT_EQ(ab2.iterations, ab.iterations);
  Field other(bundle, 4, true);
  ASSERT_EQ(other.read_coefficients(boost::make_assoc_property_map(by_constraints)), PVF::Error_code::SUCCESS);
  EXPECT_TRUE(same_bits(other.coefficients(), bounded.coefficients()));
  for(const auto& c : constraints)
    EXPECT_EQ(bounded.coefficients_of(c.face), smooth.coefficients_of(c.face));
  EXPECT_FALSE(same_bits(bounded.coefficients(), smooth.coefficients()));  // the free faces did move

  // The conjugate field, on curvature given as a map: every face bends one way.
  std::map<Face, PVF::Principal_curvatures<Vector> > curvatures;
  for(Face f : faces(tm))
    curvatures[f] = PVF::Principal_curvatures<Vector>{ 1.0, 0.2, Vector(1, 0, 0), Vector(0, 1, 0) };
  Field conjugate = smooth;
  PVF::Conjugate_field_result cr;
  const auto np = PVF::parameters::principal_curvature_map(boost::make_assoc_property_map(curvatures));
  const PVF::Error_code code = PVF::design_conjugate_frame_field(conjugate, cr, np);
  EXPECT_EQ(code, cr.converged ? PVF::Error_code::SUCCESS : PVF::Error_code::DID_NOT_CONVERGE);
  EXPECT_EQ(cr.deviation_history.size(), cr.iterations + 1);
  EXPECT_LT(cr.mean_deviation, cr.deviation_history.front());
  for(const auto& c : constraints)
    EXPECT_EQ(conjugate.coefficients_of(c.face), smooth.coefficients_of(c.face));
}

// Not converging within the iterations is DID_NOT_CONVERGE, with the field of
// the last step and its report written, for both algorithms and both overloads.
TEST(FieldObject, NonConvergenceIsReportedOneWay)
{
  const Mesh tm = load("bumpy.off");
  const Bundle bundle(tm);
  const auto constraints = random_constraints(tm, 20, 2, 13);
  const Field smooth = smooth_frame_field(bundle, constraints);

  Field bounded = smooth;
  PVF::Angle_bound_result ab;
  const auto one_step = PVF::parameters::angle_bound(89.9 * CGAL_PI / 180, CGAL::parameters::number_of_iterations(1));
  ASSERT_EQ(PVF::design_angle_bounded_frame_field(bounded, ab, PVF::parameters::tolerance(0.0, one_step)),
            PVF::Error_code::DID_NOT_CONVERGE);
  EXPECT_FALSE(ab.converged);
  EXPECT_EQ(ab.iterations, 1u);
  EXPECT_LT(ab.minimum_free_angle, 89.9 * CGAL_PI / 180);
  EXPECT_FALSE(same_bits(bounded.coefficients(), smooth.coefficients()));  // the step was taken and kept

  std::map<Face, std::vector<Complex> > out;
  PVF::Angle_bound_result ab2;
  ASSERT_EQ(PVF::design_angle_bounded_frame_field(bundle, constraints, boost::make_assoc_property_map(out), ab2,
                                                  PVF::parameters::tolerance(0.0, one_step)),
            PVF::Error_code::DID_NOT_CONVERGE);
  EXPECT_EQ(out.size(), num_faces(tm));
  EXPECT_FALSE(ab2.converged);

  // A field that is not a frame field is refused, and not touched.
  Field six(bundle, 6);
  EXPECT_EQ(PVF::design_angle_bounded_frame_field(six, ab), PVF::Error_code::NOT_A_FRAME_FIELD);
  PVF::Conjugate_field_result cr;
  EXPECT_EQ(PVF::design_conjugate_frame_field(six, cr), PVF::Error_code::NOT_A_FRAME_FIELD);
  // A bad parameter is reported before anything is computed.
  Field untouched = smooth;
  EXPECT_EQ(PVF::design_angle_bounded_frame_field(untouched, ab, PVF::parameters::angle_bound(0.0)),
            PVF::Error_code::INVALID_PARAMETER);
  EXPECT_TRUE(same_bits(untouched.coefficients(), smooth.coefficients()));
}

// The local-global optimizer is generic in N: a unit-length line field
// (N = 2, sign-symmetric) whose local step rescales c_0 to unit modulus ends
// with every free face within the tolerance, the constrained faces unmoved.
TEST(FieldObject, LocalGlobalOptimizerWorksForAnyDegree)
{
  const Mesh tm = load("bumpy.off");
  const Bundle bundle(tm);
  PVF::Polyvector_field_designer<Mesh> designer(bundle, 2, PVF::parameters::sign_symmetric(true));
  std::vector<PVF::Face_constraint<Face, Vector> > constraints;
  for(const auto& c : random_constraints(tm, 10, 1, 17))
    constraints.push_back({ c.face, { c.vectors[0] * 3.0 }, c.weight });  // away from unit length
  ASSERT_EQ(designer.add_constraints(constraints), PVF::Error_code::SUCCESS);
  Field field(bundle, 2, true);
  ASSERT_EQ(designer.solve(field), PVF::Error_code::SUCCESS);
  const Field designed = field;

  auto optimizer = PVF::internal::make_local_global_optimizer<CGAL::Sequential_tag>(field, CGAL::parameters::default_values());
  const double tolerance = 1e-3;
  double worst = 0;
  auto unit = [](std::size_t, const Complex* c, Complex* target) {
    target[0] = std::abs(c[0]) > 0 ? c[0] / std::abs(c[0]) : Complex(1);
    target[1] = 0;
  };
  auto converged = [&](const std::vector<Complex>& c, std::size_t, double) {
    worst = 0;
    for(std::size_t f = 0; f < bundle.number_of_faces(); ++f)
      if(!optimizer.is_fixed(f))
        worst = (std::max)(worst, std::abs(std::abs(c[2 * f]) - 1));
    return worst <= tolerance;
  };
  PVF::internal::Local_global_weights weights;
  weights.face_scale.assign(bundle.number_of_faces(), 1.0);
  weights.degree_penalty.assign(2, 0.0);
  PVF::internal::Local_global_parameters p;
  p.maximum_lambda = 1e12;
  p.maximum_iterations = 200;
  std::vector<Complex> c = field.coefficients();
  std::size_t iterations = 0;
  bool done = false;
  ASSERT_EQ(optimizer.iterate(weights, p, unit, converged, c, iterations, done), PVF::Error_code::SUCCESS);
  EXPECT_TRUE(done);
  EXPECT_LE(worst, tolerance);
  EXPECT_GE(iterations, 1u);
  EXPECT_GE(optimizer.factorizations(), 1u);
  EXPECT_LE(optimizer.factorizations(), iterations);
  for(const auto& k : constraints)
  {
    const std::size_t f = bundle.index(k.face);
    EXPECT_TRUE(optimizer.is_fixed(f));
    EXPECT_EQ(c[2 * f], designed.coefficients()[2 * f]);
  }
}
