// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// The range of the input: every computation that squares or powers user data
// is safe over the whole double range, or refuses with the cause.

#include "test_meshes.h"

#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/polyvector_polynomial.h>

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <limits>
#include <vector>

namespace PVF = CGAL::Polyvector_fields;
using namespace pvf_test;

typedef std::complex<double> Complex;
typedef Mesh::Face_index Face;

namespace {

Mesh scaled(const Mesh& tm, double s)
{
  Mesh copy = tm;
  for(auto v : vertices(copy))
    copy.point(v) = Point(copy.point(v).x() * s, copy.point(v).y() * s, copy.point(v).z() * s);
  return copy;
}

// The field of 12 random frame constraints (unit-scale vectors) on `tm`.
std::vector<Complex> frame_field(const Mesh& tm)
{
  PVF::Polyvector_field_designer<Mesh> designer(tm, 4, PVF::parameters::sign_symmetric(true));
  EXPECT_EQ(designer.status(), PVF::Error_code::SUCCESS);
  EXPECT_EQ(designer.add_constraints(random_constraints(tm, 12, 2, 7)), PVF::Error_code::SUCCESS);
  EXPECT_EQ(designer.solve(boost::dummy_property_map()), PVF::Error_code::SUCCESS);
  return designer.coefficient_array();
}

} // namespace

// A power-of-two scale of the mesh leaves every frame, hence the whole field,
// bit-identical, from 2^-1000 to 2^1000; a decimal scale changes only rounding.
TEST(Range, MeshScaleOverTheWholeDoubleRange)
{
  const Mesh tm = load("bumpy.off");
  const std::vector<Complex> reference = frame_field(tm);
  for(int e : { -1000, -500, 500, 1000 })
    EXPECT_EQ(frame_field(scaled(tm, std::ldexp(1.0, e))), reference) << "scale 2^" << e;
  for(double s : { 1e-300, 1e-150, 1e150, 1e300 })
  {
    const std::vector<Complex> c = frame_field(scaled(tm, s));
    ASSERT_EQ(c.size(), reference.size());
    double worst = 0, largest = 0;
    for(std::size_t i = 0; i < c.size(); ++i)
    {
      worst = (std::max)(worst, std::abs(c[i] - reference[i]));
      largest = (std::max)(largest, std::abs(reference[i]));
    }
    EXPECT_LT(worst, 1e-9 * largest) << "scale " << s;
  }
  // Curvature scales like 1/length, exactly for a power of two.
  typedef PVF::Principal_curvatures<Vector> Curvatures;
  auto curvatures = [](const Mesh& m) {
    std::map<Face, Curvatures> k;
    EXPECT_EQ(PVF::estimate_principal_curvatures(m, boost::make_assoc_property_map(k)), PVF::Error_code::SUCCESS);
    return k;
  };
  const auto k = curvatures(tm), k_small = curvatures(scaled(tm, std::ldexp(1.0, -900)));
  for(Face f : faces(tm))
  {
    EXPECT_EQ(k_small.at(f).k1, std::ldexp(k.at(f).k1, 900));
    EXPECT_EQ(k_small.at(f).d1, k.at(f).d1);
  }
}

// A constraint vector of length L is accepted for 1e-300 <= L^N <= 1e300 (the
// field's coefficients are doubles), and refused with VALUE_OUT_OF_RANGE
// beyond, at both ends and for any direction; within one design the lengths
// relative to their mean sigma need 1e-100 <= (L / sigma)^N <= 1e100.
TEST(Range, ConstraintLengths)
{
  const Mesh tm = grid(3, 3);
  auto code = [&](std::size_t N, bool sign_symmetric, std::vector<double> lengths, std::size_t vectors) {
    PVF::Polyvector_field_designer<Mesh> designer(tm, N, PVF::parameters::sign_symmetric(sign_symmetric));
    for(std::size_t c = 0; c < lengths.size(); ++c)
    {
      std::vector<Vector> v;
      for(std::size_t i = 0; i < vectors; ++i)
        v.push_back(Vector(lengths[c] * std::cos(0.3 + i), lengths[c] * std::sin(0.3 + i), 0));
      const PVF::Error_code added = designer.add_constraint(Face(Mesh::size_type(c)), v);
      if(added != PVF::Error_code::SUCCESS)
        return added;
    }
    const PVF::Error_code solved = designer.solve(boost::dummy_property_map());
    for(const Complex& c : designer.coefficient_array())
      EXPECT_TRUE(std::isfinite(c.real()) && std::isfinite(c.imag()));
    return solved;
  };
  EXPECT_EQ(code(4, true, { 1e74 }, 2), PVF::Error_code::SUCCESS);
  EXPECT_EQ(code(4, true, { 1e76 }, 2), PVF::Error_code::VALUE_OUT_OF_RANGE);
  EXPECT_EQ(code(4, true, { 1e-74 }, 2), PVF::Error_code::SUCCESS);
  EXPECT_EQ(code(4, true, { 1e-76 }, 2), PVF::Error_code::VALUE_OUT_OF_RANGE);
  EXPECT_EQ(code(32, false, { 2e9 }, 32), PVF::Error_code::SUCCESS);    // 2e9^32 = 4e297
  EXPECT_EQ(code(32, false, { 3e9 }, 32), PVF::Error_code::VALUE_OUT_OF_RANGE);  // 3e9^32 = 2e303
  // Relative lengths: two constraints 1e48 apart at N = 4 are (1e24)^4 from their mean.
  EXPECT_EQ(code(4, true, { 1e-23, 1e23 }, 2), PVF::Error_code::SUCCESS);
  EXPECT_EQ(code(4, true, { 1e-26, 1e26 }, 2), PVF::Error_code::VALUE_OUT_OF_RANGE);
  // Partial constraints (the SVD of their rows) over the same range.
  EXPECT_EQ(code(32, false, { 1e3 }, 1), PVF::Error_code::SUCCESS);
  EXPECT_EQ(code(32, false, { 1.41421e11 }, 1), PVF::Error_code::VALUE_OUT_OF_RANGE);
  EXPECT_EQ(code(4, false, { 1e-70 }, 1), PVF::Error_code::SUCCESS);
  EXPECT_EQ(code(4, false, { 1e-200 }, 1), PVF::Error_code::VALUE_OUT_OF_RANGE);
  // Huge and tiny components whose squares over- or underflow are not "zero".
  PVF::Polyvector_field_designer<Mesh> designer(tm, 2);
  EXPECT_EQ(designer.add_constraint(Face(0), { Vector(1e20, 1e20, 0) }), PVF::Error_code::SUCCESS);
  EXPECT_EQ(designer.add_constraint(Face(1), { Vector(1e-40, 0, 0) }), PVF::Error_code::SUCCESS);
  EXPECT_EQ(designer.add_constraint(Face(2), { Vector(1e200, 1e200, 0) }), PVF::Error_code::VALUE_OUT_OF_RANGE);
}

// A partial constraint holds (P(u) = 0 relative to |u|^N) across the range:
// the design works in the unit of its constraints.
TEST(Range, PartialConstraintHoldsAtLargeDegree)
{
  const Mesh tm = grid(3, 3);
  for(double length : { 1e-3, 1.0, 900.0, 1e9 })
  {
    PVF::Polyvector_field_designer<Mesh> designer(tm, 32);
    const Vector u(length * 0.6, length * 0.8, 0);
    ASSERT_EQ(designer.add_constraint(Face(4), { u }), PVF::Error_code::SUCCESS);
    ASSERT_EQ(designer.add_constraint(Face(0), std::vector<Vector>(32, Vector(length, 0, 0))), PVF::Error_code::SUCCESS);
    ASSERT_EQ(designer.solve(boost::dummy_property_map()), PVF::Error_code::SUCCESS) << "length " << length;
    PVF::Face_frame frame;
    PVF::face_frame(Face(4), tm, frame);
    const Complex z = frame.to_complex(u.x(), u.y(), u.z());
    const std::vector<Complex>& c = designer.coefficient_array();
    // P(z) = z^32 + sum_m c_m z^m, every term of size about |z|^32.
    Complex p = std::pow(z, 32);
    double scale = std::abs(p);
    for(std::size_t m = 0; m < 32; ++m)
    {
      const Complex term = c[4 * 32 + m] * std::pow(z, int(m));
      p += term;
      scale = (std::max)(scale, std::abs(term));
    }
    EXPECT_LT(std::abs(p), 1e-9 * scale) << "length " << length;
  }
}

// Scaling every constraint by a power of two scales the field exactly: the
// design works in the unit of its constraints, partial constraints included.
TEST(Range, ConstraintScaleEquivariance)
{
  const Mesh tm = load("bumpy.off");
  auto field = [&](double s) {
    PVF::Polyvector_field_designer<Mesh> designer(tm, 4);
    auto constraints = random_constraints(tm, 6, 4, 3);
    constraints.push_back({ Face(1000), { Vector(0.2, 0.5, 0.1) } });  // partial: couples the degrees
    for(auto& c : constraints)
      for(Vector& v : c.vectors)
        v = v * s;
    EXPECT_EQ(designer.add_constraints(constraints), PVF::Error_code::SUCCESS);
    EXPECT_EQ(designer.solve(boost::dummy_property_map()), PVF::Error_code::SUCCESS);
    return designer.coefficient_array();
  };
  const std::vector<Complex> unit = field(1.0);
  for(int e : { -30, 17 })
  {
    const std::vector<Complex> c = field(std::ldexp(1.0, e));
    ASSERT_EQ(c.size(), unit.size());
    for(std::size_t i = 0; i < c.size(); ++i)
    {
      const int m = int(i % 4);
      EXPECT_EQ(c[i], Complex(std::ldexp(unit[i].real(), e * (4 - m)), std::ldexp(unit[i].imag(), e * (4 - m))))
        << "scale 2^" << e << ", coefficient " << i;
    }
  }
}

TEST(Range, SoftWeights)
{
  const Mesh tm = grid(3, 3);
  PVF::Polyvector_field_designer<Mesh> designer(tm, 2);
  const std::vector<Vector> v{ Vector(1, 0, 0) };
  EXPECT_EQ(designer.add_constraint(Face(0), v, 0.99e-8), PVF::Error_code::INVALID_WEIGHT);
  EXPECT_EQ(designer.add_constraint(Face(0), v, 1.01e8), PVF::Error_code::INVALID_WEIGHT);
  EXPECT_EQ(designer.add_constraint(Face(0), v, 1e-320), PVF::Error_code::INVALID_WEIGHT);
  // The extreme weights on partial constraints (rank-one terms) still factor.
  EXPECT_EQ(designer.add_constraint(Face(0), v, 1e-8), PVF::Error_code::SUCCESS);
  EXPECT_EQ(designer.add_constraint(Face(1), v, 1e8), PVF::Error_code::SUCCESS);
  EXPECT_EQ(designer.add_constraint(Face(2), v, std::numeric_limits<double>::infinity()), PVF::Error_code::SUCCESS);
  EXPECT_EQ(designer.solve(boost::dummy_property_map()), PVF::Error_code::SUCCESS);
}
