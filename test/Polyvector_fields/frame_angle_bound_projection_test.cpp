// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// The promise of design_angle_bounded_frame_field() (issue 21, part 6): with
// a bound A, every free face of the field it returns with SUCCESS has a frame
// angle of at least A, also with the default tolerance, which lets the
// iterations stop up to half a degree below A. The field of the iterations
// alone is obtained from the same function by a run of as many iterations
// with a zero tolerance, which returns it unprojected (DID_NOT_CONVERGE); the
// angles are measured here from the coefficients.

#include "test_meshes.h"

#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/design_angle_bounded_frame_field.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/angle_bound_projection.h>
#include <CGAL/Polyvector_fields/internal/Frame_fields/frame_field_polynomial.h>

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <vector>

// The names of this file stay in its own namespace: the group is built as one
// translation unit (unity build).
namespace pvf_frame_angle_bound_projection_test {

namespace PVF = CGAL::Polyvector_fields;
using namespace pvf_test;

typedef std::complex<double> Complex;
typedef Mesh::Face_index Face;
typedef PVF::Tangent_bundle<Mesh> Bundle;
typedef PVF::Polyvector_field<Bundle> Field;
typedef PVF::Face_constraint<Face, Vector> Constraint;

const double degree = CGAL_PI / 180;

// The smallest angle between the lines of the two vectors of a frame, written here.
double line_angle(Complex a, Complex b)
{
  const double c = std::abs(a.real() * b.real() + a.imag() * b.imag());
  const double s = std::abs(a.real() * b.imag() - a.imag() * b.real());
  return std::atan2(s, c);
}

// The two vectors u, v of face i of a frame field, as the roots of
// z^4 + c_2 z^2 + c_0: u^2 and v^2 are the roots of w^2 + c_2 w + c_0.
std::pair<Complex, Complex> frame_of(const Field& field, std::size_t i)
{
  const Complex* c = &field.coefficients()[4 * i];
  const Complex d = std::sqrt(c[2] * c[2] - 4. * c[0]);
  return { std::sqrt((-c[2] + d) / 2.), std::sqrt((-c[2] - d) / 2.) };
}

double frame_angle(const Field& field, std::size_t i)
{
  const auto uv = frame_of(field, i);
  return line_angle(uv.first, uv.second);
}

Field smooth_frame_field(const Bundle& bundle, const std::vector<Constraint>& constraints)
{
  PVF::Polyvector_field_designer<Mesh> designer(bundle, 4, PVF::parameters::sign_symmetric(true));
  EXPECT_EQ(designer.add_constraints(constraints), PVF::Error_code::SUCCESS);
  Field field(bundle, 4, true);
  EXPECT_EQ(designer.solve(field), PVF::Error_code::SUCCESS);
  return field;
}

bool same_bits(const Complex* a, const Complex* b) { return std::memcmp(a, b, 4 * sizeof(Complex)) == 0; }

// The field returned with the default tolerance against the field of as many
// iterations without the final projection.
struct Runs
{
  Field bounded, iterated;
  PVF::Angle_bound_result result, iterated_result;
  std::set<std::size_t> constrained;
};

Runs run_both(const Bundle& bundle, const std::vector<Constraint>& constraints, double theta)
{
  const Field smooth = smooth_frame_field(bundle, constraints);
  Runs r{ smooth, smooth, {}, {}, {} };
  for(const Constraint& c : constraints)
    r.constrained.insert(bundle.index(c.face));
  EXPECT_EQ(PVF::design_angle_bounded_frame_field(r.bounded, r.result, PVF::parameters::angle_bound(theta)),
            PVF::Error_code::SUCCESS);
  EXPECT_TRUE(r.result.converged);
  EXPECT_GT(r.result.iterations, 0u);
  // The same iterations (the schedule does not depend on the tolerance), stopped at the
  // same count without reaching a zero tolerance: the field of the last step, unprojected.
  EXPECT_EQ(PVF::design_angle_bounded_frame_field(
              r.iterated, r.iterated_result,
              PVF::parameters::angle_bound(theta, PVF::parameters::tolerance(
                                                    0.0, CGAL::parameters::number_of_iterations(r.result.iterations)))),
            PVF::Error_code::DID_NOT_CONVERGE);
  EXPECT_EQ(r.iterated_result.iterations, r.result.iterations);
  return r;
}

// Full hard constraints (two vectors each) on bumpy.off, a bound of 70
// degrees and the default tolerance (0.5 degree): the iterations alone end
// below 70 degrees on some free faces; the result has every free face at 70
// degrees or more, moves only those faces, and onto the bound exactly.
TEST(AngleBoundProjection, DefaultToleranceEndsAtTheBound)
{
  const Mesh tm = load("bumpy.off");
  const Bundle bundle(tm);
  const double theta = 70 * degree;
  const Runs r = run_both(bundle, random_constraints(tm, 30, 2, 3), theta);

  double iterated_min = std::numeric_limits<double>::infinity(), bounded_min = iterated_min;
  std::size_t below = 0;
  for(std::size_t i = 0; i < bundle.number_of_faces(); ++i)
  {
    const Complex* before = &r.iterated.coefficients()[4 * i];
    const Complex* after = &r.bounded.coefficients()[4 * i];
    if(r.constrained.count(i))
    {
      EXPECT_TRUE(same_bits(before, after)) << "constrained face " << i;
      continue;
    }
    const double a0 = frame_angle(r.iterated, i), a1 = frame_angle(r.bounded, i);
    iterated_min = (std::min)(iterated_min, a0);
    bounded_min = (std::min)(bounded_min, a1);
    EXPECT_GE(a1, theta - 1e-9) << "free face " << i;
    if(a0 < theta)
    {
      ++below;
      EXPECT_NEAR(a1, theta, 1e-9) << "face " << i << " is turned onto the bound, not past it";
    }
    else
      EXPECT_TRUE(same_bits(before, after)) << "face " << i << " was within the bound and must not move";
  }
  // The case exists: the optimizer alone ends below the bound, within the tolerance.
  EXPECT_LT(iterated_min, theta);
  EXPECT_GE(iterated_min, theta - 0.5 * degree);
  EXPECT_GT(below, 0u);
  std::cout << "bumpy.off: " << r.result.iterations << " iterations end at " << iterated_min / degree << " degrees; "
            << below << " free faces projected, smallest free angle now " << bounded_min / degree << " degrees\n";
  // The report tells the same.
  EXPECT_EQ(r.result.projected_faces, below);
  EXPECT_NEAR(r.result.minimum_free_angle_before_projection, iterated_min, 1e-12);
  EXPECT_NEAR(r.result.minimum_free_angle, bounded_min, 1e-12);
  EXPECT_GE(r.result.minimum_free_angle, theta - 1e-12);
  EXPECT_EQ(r.iterated_result.projected_faces, 0u);
  EXPECT_FALSE(r.iterated_result.converged);
}

// Hard partial constraints (one vector each) leave their faces free: the
// projection keeps the vector a constraint gives and turns the other one.
TEST(AngleBoundProjection, PartialConstraintsKeepTheirVector)
{
  const Mesh tm = load("bumpy.off");
  const Bundle bundle(tm);
  const double theta = 75 * degree;
  const std::vector<Constraint> constraints = random_constraints(tm, 60, 1, 7);
  const Runs r = run_both(bundle, constraints, theta);
  std::size_t projected_constrained = 0;
  for(std::size_t i = 0; i < bundle.number_of_faces(); ++i)
    EXPECT_GE(frame_angle(r.bounded, i), theta - 1e-9) << "face " << i;
  for(const Constraint& c : constraints)
  {
    const std::size_t i = bundle.index(c.face);
    const Vector& w3 = c.vectors.front();
    const Complex w = bundle.frame(i).to_complex(w3.x(), w3.y(), w3.z());
    const auto uv = frame_of(r.bounded, i);
    EXPECT_LT((std::min)(line_angle(w, uv.first), line_angle(w, uv.second)), 1e-7) << "face " << i;
    projected_constrained += frame_angle(r.iterated, i) < theta;
  }
  std::cout << "partial constraints: " << r.result.projected_faces << " faces projected, " << projected_constrained
            << " of them constrained\n";
  EXPECT_GT(r.result.projected_faces, 0u);
  EXPECT_GE(r.result.minimum_free_angle, theta - 1e-12);
}

// The per-face step that keeps one vector: the kept vector is bit for bit the
// same, the other keeps its length, and the angle is the bound.
TEST(AngleBoundProjection, KeepingOneVector)
{
  const double theta = 70 * degree;
  for(double opening : { 0.0, 10 * degree, 69.9 * degree, 110 * degree, 179 * degree })
    for(bool keep_u : { true, false })
    {
      const Complex u = std::polar(1.3, 0.4), v = std::polar(0.7, 0.4 + opening);
      const auto moved = PVF::internal::enforce_angle_bound_keeping(u, v, theta, keep_u);
      EXPECT_EQ(keep_u ? moved.first : moved.second, keep_u ? u : v);
      EXPECT_NEAR(std::abs(moved.first), std::abs(u), 1e-15);
      EXPECT_NEAR(std::abs(moved.second), std::abs(v), 1e-15);
      EXPECT_NEAR(line_angle(moved.first, moved.second), theta, 1e-12) << opening / degree;
    }
  // Within the bound: unchanged.
  const Complex u(1, 0), v = std::polar(1.0, 80 * degree);
  const auto same = PVF::internal::enforce_angle_bound_keeping(u, v, theta, true);
  EXPECT_EQ(same.first, u);
  EXPECT_EQ(same.second, v);
}

} // namespace pvf_frame_angle_bound_projection_test
