// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Tests of IO/constraints.h: the text constraint format and libigl's
// b.dmat / bc.dmat pairs.

#include <CGAL/Polyvector_fields/IO/constraints.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io_test_support.h"

namespace {

using namespace pvf_io_test;
namespace PIO = CGAL::Polyvector_fields::IO;

template <typename TriangleMesh>
struct Types
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename CGAL::Kernel_traits<typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type>::Kernel Kernel;
  typedef typename Kernel::Vector_3 Vector_3;
  typedef PVF::Face_constraint<face_descriptor, Vector_3> Constraint;
  typedef std::vector<Constraint> Constraints;
};

template <typename TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> face_vector(const TriangleMesh& tm)
{
  return { faces(tm).begin(), faces(tm).end() };
}

// ---------------------------------------------------------------------------
// Text format

template <typename TriangleMesh>
struct Constraints_test : ::testing::Test {};
typedef ::testing::Types<CGAL::Surface_mesh<SC::Point_3>, CGAL::Surface_mesh<EPICK::Point_3>,
                         CGAL::Polyhedron_3<SC>, CGAL::Polyhedron_3<EPICK> >
  Mesh_types;
TYPED_TEST_SUITE(Constraints_test, Mesh_types);

TYPED_TEST(Constraints_test, ReadsCommentsBlankLinesAndRoundTrips)
{
  typedef TypeParam Mesh;
  typedef typename Types<Mesh>::Vector_3 Vector_3;
  typedef typename Types<Mesh>::Constraints Constraints;
  const Mesh tm = load_mesh<Mesh>("bumpy.off");
  const auto fv = face_vector(tm);

  const std::string text =
    "# constraints for bumpy.off\n"
    "\n"
    "12   1 0 0   0 1 0      # full constraint, two vectors\n"
    "   \t  \r\n"
    "2495\t0.5 -0.25 1e-3\r\n"
    "#0 9 9 9  (commented out)\n"
    "+7 -1.5 2 3 # explicit plus sign\n"
    "0 0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9#no blank before the comment";
  Constraints out = sentinel_constraints(tm);
  std::istringstream is(text);
  ASSERT_EQ(PIO::read_constraints(is, tm, out), Error_code::SUCCESS);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_TRUE(out[0].face == fv[12]);
  EXPECT_TRUE(out[1].face == fv[2495]);
  EXPECT_TRUE(out[2].face == fv[7]);
  EXPECT_TRUE(out[3].face == fv[0]);
  ASSERT_EQ(out[0].vectors.size(), 2u);
  EXPECT_EQ(out[0].vectors[0], Vector_3(1, 0, 0));
  EXPECT_EQ(out[0].vectors[1], Vector_3(0, 1, 0));
  ASSERT_EQ(out[1].vectors.size(), 1u);
  EXPECT_EQ(out[1].vectors[0], Vector_3(0.5, -0.25, 1e-3));
  EXPECT_EQ(out[2].vectors[0], Vector_3(-1.5, 2, 3));
  ASSERT_EQ(out[3].vectors.size(), 3u);
  EXPECT_EQ(out[3].vectors[2], Vector_3(0.7, 0.8, 0.9));
  for(const auto& c : out)
    EXPECT_TRUE(std::isinf(c.weight) && c.weight > 0);

  // Write (with random full-precision vectors) and read back, in a file.
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> uniform(-10, 10);
  for(auto& c : out)
    for(auto& u : c.vectors)
      u = Vector_3(uniform(rng), uniform(rng), uniform(rng));
  Scratch_directory dir("constraints_roundtrip");
  const std::string filename = dir.file("c.txt");
  ASSERT_EQ(PIO::write_constraints(filename, tm, out), Error_code::SUCCESS);
  EXPECT_EQ(dir.entries(), std::set<std::string>{ "c.txt" });
  Constraints back = sentinel_constraints(tm);
  ASSERT_EQ(PIO::read_constraints(filename, tm, back), Error_code::SUCCESS);
  ASSERT_EQ(back.size(), out.size());
  for(std::size_t i = 0; i < out.size(); ++i)
  {
    EXPECT_TRUE(back[i].face == out[i].face);
    ASSERT_EQ(back[i].vectors.size(), out[i].vectors.size());
    for(std::size_t k = 0; k < out[i].vectors.size(); ++k)
      EXPECT_EQ(back[i].vectors[k], out[i].vectors[k]);
  }

  // An empty file (or only comments) is an empty list.
  std::istringstream empty("# nothing\n\n");
  ASSERT_EQ(PIO::read_constraints(empty, tm, back), Error_code::SUCCESS);
  EXPECT_TRUE(back.empty());
}

TEST(Constraints, BadTextLeavesOutputUntouched)
{
  typedef CGAL::Surface_mesh<EPICK::Point_3> Mesh;
  const Mesh tm = load_mesh<Mesh>("bumpy.off");  // 2496 faces
  const std::vector<std::pair<std::string, Error_code> > cases = {
    { "abc 1 2 3\n", Error_code::MALFORMED_FILE },
    { "3.5 1 2 3\n", Error_code::MALFORMED_FILE },
    { "3.0 1 2 3\n", Error_code::MALFORMED_FILE },
    { "1e2 1 2 3\n", Error_code::MALFORMED_FILE },
    { "nan 1 2 3\n", Error_code::MALFORMED_FILE },
    { "-1 1 2 3\n", Error_code::INVALID_FACE },
    { "2496 1 2 3\n", Error_code::INVALID_FACE },
    { "99999999999999999999999 1 2 3\n", Error_code::INVALID_FACE },
    { "-99999999999999999999999 1 2 3\n", Error_code::INVALID_FACE },
    { "0 1 2\n", Error_code::MALFORMED_FILE },
    { "0 1 2 3 4\n", Error_code::MALFORMED_FILE },
    { "0 1 2 x\n", Error_code::MALFORMED_FILE },
    { "0 1,5 2 3\n", Error_code::MALFORMED_FILE },
    { "0 1 2 3\n1 1 2 3 garbage\n", Error_code::MALFORMED_FILE },
    { "0 nan 2 3\n", Error_code::NON_FINITE_VALUE },
    { "0 1 2 3\n5 1 -inf 3\n", Error_code::NON_FINITE_VALUE },
    { "0 1 1e500 3\n", Error_code::NON_FINITE_VALUE },
    { "0\n", Error_code::EMPTY_CONSTRAINT },
    { "0 # vectors forgotten\n", Error_code::EMPTY_CONSTRAINT },
    { "0 1 2 3\n4 1 0 0\n0 0 1 0\n", Error_code::DUPLICATE_CONSTRAINT },
    { "0 1 2 3\n+0 1 0 0\n", Error_code::DUPLICATE_CONSTRAINT },
    { std::string("0 1 2\0 3\n", 9), Error_code::MALFORMED_FILE },
  };
  for(const auto& c : cases)
  {
    auto out = sentinel_constraints(tm);
    std::istringstream is(c.first);
    EXPECT_EQ(PIO::read_constraints(is, tm, out), c.second) << c.first;
    EXPECT_TRUE(is_sentinel(tm, out)) << c.first;
  }
  auto out = sentinel_constraints(tm);
  EXPECT_EQ(PIO::read_constraints(data_file("no_such_file.txt"), tm, out), Error_code::CANNOT_OPEN_FILE);
  std::istringstream failed("0 1 0 0\n");
  failed.setstate(std::ios::failbit);
  EXPECT_EQ(PIO::read_constraints(failed, tm, out), Error_code::CANNOT_OPEN_FILE);
  EXPECT_TRUE(is_sentinel(tm, out));
}

TEST(Constraints, BadConstraintsAreNotWritten)
{
  typedef CGAL::Polyhedron_3<SC> Mesh;
  typedef Types<Mesh>::Constraint Constraint;
  typedef Types<Mesh>::Vector_3 Vector_3;
  const Mesh tm = load_mesh<Mesh>("bumpy.off");
  const Mesh other = load_mesh<Mesh>("bumpy.off");
  const auto fv = face_vector(tm);
  const double nan = std::numeric_limits<double>::quiet_NaN();

  Constraint good{ fv[3], { Vector_3(1, 0, 0) } };
  Constraint soft{ fv[4], { Vector_3(0, 1, 0), Vector_3(1, 0, 0) }, 2.5 };
  const std::vector<std::pair<std::vector<Constraint>, Error_code> > cases = {
    { { good, Constraint{ *faces(other).begin(), { Vector_3(1, 0, 0) } } }, Error_code::INVALID_FACE },
    { { good, Constraint{ boost::graph_traits<Mesh>::face_descriptor(), { Vector_3(1, 0, 0) } } },
      Error_code::INVALID_FACE },
    { { good, soft, good }, Error_code::DUPLICATE_CONSTRAINT },
    { { good, Constraint{ fv[5], {} } }, Error_code::EMPTY_CONSTRAINT },
    { { good, Constraint{ fv[5], { Vector_3(1, nan, 0) } } }, Error_code::NON_FINITE_VALUE },
  };
  Scratch_directory dir("constraints_write");
  const std::string existing = dir.file("old.txt");
  {
    std::ofstream(existing) << "old\n";
  }
  for(const auto& c : cases)
  {
    std::ostringstream os;
    EXPECT_EQ(PIO::write_constraints(os, tm, c.first), c.second);
    EXPECT_TRUE(os.str().empty());
    EXPECT_EQ(PIO::write_constraints(existing, tm, c.first), c.second);
    EXPECT_EQ(PIO::write_constraints(dir.file("new.txt"), tm, c.first), c.second);
    EXPECT_EQ(file_content(existing), "old\n");
  }
  EXPECT_EQ(PIO::write_constraints(dir.file("missing/c.txt"), tm, std::vector<Constraint>{ good }),
            Error_code::CANNOT_OPEN_FILE);
  EXPECT_EQ(dir.entries(), std::set<std::string>{ "old.txt" });

  // A soft constraint is written (its weight is not stored) and reads back hard.
  std::ostringstream os;
  ASSERT_EQ(PIO::write_constraints(os, tm, std::vector<Constraint>{ good, soft }), Error_code::SUCCESS);
  std::istringstream is(os.str());
  std::vector<Constraint> back;
  ASSERT_EQ(PIO::read_constraints(is, tm, back), Error_code::SUCCESS);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_TRUE(back[1].face == fv[4]);
  EXPECT_EQ(back[1].vectors.size(), 2u);
  EXPECT_TRUE(std::isinf(back[1].weight));
}

// ---------------------------------------------------------------------------
// libigl .dmat pairs

// Reads the numbers of an ASCII .dmat file with plain stream extraction.
std::vector<double> dmat_tokens(const std::string& filename)
{
  std::ifstream in(filename);
  std::vector<double> values;
  double x;
  while(in >> x)
    values.push_back(x);
  return values;
}

template <typename TriangleMesh>
struct Dmat_test : ::testing::Test {};
TYPED_TEST_SUITE(Dmat_test, Mesh_types);

TYPED_TEST(Dmat_test, InspiredMesh)
{
  typedef TypeParam Mesh;
  typedef typename Types<Mesh>::Constraints Constraints;
  const Mesh tm = load_mesh<Mesh>("inspired_mesh.obj");
  ASSERT_EQ(faces(tm).size(), 4288u);
  const auto fv = face_vector(tm);

  Constraints out = sentinel_constraints(tm);
  ASSERT_EQ(PIO::read_dmat_constraints(data_file("inspired_mesh_b.dmat"), data_file("inspired_mesh_bc.dmat"), tm, out),
            Error_code::SUCCESS);
  ASSERT_EQ(out.size(), 84u);

  // The same numbers, read independently: b = [1 84 ids...], bc = [6 84, then column-major].
  const std::vector<double> b = dmat_tokens(data_file("inspired_mesh_b.dmat"));
  const std::vector<double> bc = dmat_tokens(data_file("inspired_mesh_bc.dmat"));
  ASSERT_EQ(b.size(), 2u + 84u);
  ASSERT_EQ(bc.size(), 2u + 6u * 84u);
  ASSERT_EQ(bc[0], 6.0);
  ASSERT_EQ(bc[1], 84.0);
  EXPECT_TRUE(out[0].face == fv[26]);
  // First row: bc(0, j) is the first value of column j, at 2 + 84 j.
  ASSERT_EQ(out[0].vectors.size(), 2u);
  EXPECT_EQ(out[0].vectors[0].x(), -0.35349288582801819);
  EXPECT_EQ(out[0].vectors[0].x(), bc[2 + 0 * 84]);
  EXPECT_EQ(out[0].vectors[0].y(), bc[2 + 1 * 84]);
  EXPECT_EQ(out[0].vectors[0].z(), bc[2 + 2 * 84]);
  EXPECT_EQ(out[0].vectors[1].x(), bc[2 + 3 * 84]);
  EXPECT_EQ(out[0].vectors[1].y(), bc[2 + 4 * 84]);
  EXPECT_EQ(out[0].vectors[1].z(), bc[2 + 5 * 84]);

  auto vpm = get(CGAL::vertex_point, tm);
  for(std::size_t i = 0; i < 84; ++i)
  {
    ASSERT_TRUE(out[i].face == fv[std::size_t(b[2 + i])]);
    ASSERT_EQ(out[i].vectors.size(), 2u);
    EXPECT_TRUE(std::isinf(out[i].weight));
    for(std::size_t k = 0; k < 2; ++k)
    {
      EXPECT_EQ(out[i].vectors[k].x(), bc[2 + (3 * k + 0) * 84 + i]);
      EXPECT_EQ(out[i].vectors[k].y(), bc[2 + (3 * k + 1) * 84 + i]);
      EXPECT_EQ(out[i].vectors[k].z(), bc[2 + (3 * k + 2) * 84 + i]);
    }
    // A sign that the column-major reading is right: the vectors lie in their
    // face plane. The file stores float32 values (relative error ~6e-8); the
    // largest |cos(u, n)| is 2.8e-8, while a row-major reading gives 0.97.
    const auto h = halfedge(out[i].face, tm);
    const auto p0 = get(vpm, source(h, tm)), p1 = get(vpm, target(h, tm)), p2 = get(vpm, target(next(h, tm), tm));
    const auto n = CGAL::cross_product(p1 - p0, p2 - p0);
    for(const auto& u : out[i].vectors)
      EXPECT_LT(std::abs(CGAL::to_double(u * n)) /
                  std::sqrt(CGAL::to_double(u.squared_length()) * CGAL::to_double(n.squared_length())),
                1e-6)
        << "row " << i;
  }
}

TEST(Dmat, BadPairsLeaveOutputUntouched)
{
  typedef CGAL::Surface_mesh<SC::Point_3> Mesh;
  const Mesh tm = load_mesh<Mesh>("bumpy.off");  // 2496 faces
  const std::string b2 = "1 2\n3\n5\n";
  const std::string bc2 = "3 2\n1\n4\n0\n0\n0\n1\n";  // rows (1 0 0) and (4 0 1)
  {
    auto out = sentinel_constraints(tm);
    std::istringstream b(b2), bc(bc2);
    ASSERT_EQ(PIO::read_dmat_constraints(b, bc, tm, out), Error_code::SUCCESS);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_TRUE(out[1].face == face_vector(tm)[5]);
    EXPECT_EQ(out[1].vectors[0], SC::Vector_3(4, 0, 1));
  }

  // A binary .dmat as libigl writes it: "0 0", the real header, raw doubles.
  std::string binary_bc = "0 0\n3 2\n";
  for(double x : { 1.0, 4.0, 0.0, 0.0, 0.0, 1.0 })
  {
    char bytes[sizeof(double)];
    std::memcpy(bytes, &x, sizeof(double));
    binary_bc.append(bytes, sizeof(double));
  }
  std::string binary_b = "0 0\n1 2\n";
  for(double x : { 3.0, 5.0 })
  {
    char bytes[sizeof(double)];
    std::memcpy(bytes, &x, sizeof(double));
    binary_b.append(bytes, sizeof(double));
  }

  const std::vector<std::tuple<std::string, std::string, Error_code> > cases = {
    { "", bc2, Error_code::MALFORMED_FILE },
    { b2, "", Error_code::MALFORMED_FILE },
    { "1\n", bc2, Error_code::MALFORMED_FILE },
    { "2 2\n3\n5\n1\n1\n", bc2, Error_code::MALFORMED_FILE },          // b has 2 columns
    { "1 3\n3\n5\n7\n", bc2, Error_code::MALFORMED_FILE },             // 3 rows against 2
    { "1 2\n3\n", bc2, Error_code::MALFORMED_FILE },                   // short b
    { b2, "3 2\n1\n4\n0\n0\n0\n", Error_code::MALFORMED_FILE },        // short bc
    { b2, bc2 + "7\n", Error_code::MALFORMED_FILE },                   // trailing value
    { b2, "2 2\n1\n4\n0\n0\n", Error_code::MALFORMED_FILE },           // 2 columns: not x y z
    { b2, "4 2\n1\n4\n0\n0\n0\n1\n0\n0\n", Error_code::MALFORMED_FILE },
    { b2, "3 2\n1\n4\n0\nzero\n0\n1\n", Error_code::MALFORMED_FILE },
    { "1 2\n3.5\n5\n", bc2, Error_code::MALFORMED_FILE },              // non-integer id
    { "1 2\nnan\n5\n", bc2, Error_code::MALFORMED_FILE },
    { "1 2\n3\n-1\n", bc2, Error_code::INVALID_FACE },
    { "1 2\n3\n2496\n", bc2, Error_code::INVALID_FACE },
    { "1 2\n3\n1e300\n", bc2, Error_code::INVALID_FACE },
    { "1 2\n3\n3.0\n", bc2, Error_code::DUPLICATE_CONSTRAINT },
    { b2, "3 2\n1\n4\nnan\n0\n0\n1\n", Error_code::NON_FINITE_VALUE },
    { b2, "3 2\n1\n4\n0\n0\n0\ninf\n", Error_code::NON_FINITE_VALUE },
    { b2, "0 2\n", Error_code::EMPTY_CONSTRAINT },
    { "-1 2\n3\n5\n", bc2, Error_code::MALFORMED_FILE },
    { "1 99999999999999999999\n3\n5\n", bc2, Error_code::MALFORMED_FILE },
    { "1 2\n3\n5\n", "3 9223372036854775807\n1\n", Error_code::MALFORMED_FILE },
    { b2, binary_bc, Error_code::MALFORMED_FILE },
    { binary_b, bc2, Error_code::MALFORMED_FILE },
    { binary_b, binary_bc, Error_code::MALFORMED_FILE },
  };
  for(const auto& c : cases)
  {
    auto out = sentinel_constraints(tm);
    std::istringstream b(std::get<0>(c)), bc(std::get<1>(c));
    EXPECT_EQ(PIO::read_dmat_constraints(b, bc, tm, out), std::get<2>(c)) << std::get<0>(c) << "|" << std::get<1>(c);
    EXPECT_TRUE(is_sentinel(tm, out));
  }

  // An empty pair is an empty list.
  {
    auto out = sentinel_constraints(tm);
    std::istringstream b("1 0\n"), bc("6 0\n");
    ASSERT_EQ(PIO::read_dmat_constraints(b, bc, tm, out), Error_code::SUCCESS);
    EXPECT_TRUE(out.empty());
  }
  // Missing files, and the real files against a mesh with fewer faces.
  auto out = sentinel_constraints(tm);
  EXPECT_EQ(PIO::read_dmat_constraints(data_file("no_such_b.dmat"), data_file("inspired_mesh_bc.dmat"), tm, out),
            Error_code::CANNOT_OPEN_FILE);
  EXPECT_EQ(PIO::read_dmat_constraints(data_file("inspired_mesh_b.dmat"), data_file("no_such_bc.dmat"), tm, out),
            Error_code::CANNOT_OPEN_FILE);
  EXPECT_EQ(PIO::read_dmat_constraints(data_file("inspired_mesh_b.dmat"), data_file("inspired_mesh_bc.dmat"), tm, out),
            Error_code::INVALID_FACE);  // ids up to 4259 on a mesh of 2496 faces
  EXPECT_TRUE(is_sentinel(tm, out));
}

TEST(Dmat, GeomTraitsNamedParameter)
{
  // The vector type of the output follows geom_traits: Simple_cartesian
  // vectors for a mesh with Epick points.
  typedef CGAL::Surface_mesh<EPICK::Point_3> Mesh;
  const Mesh tm = load_mesh<Mesh>("inspired_mesh.obj");
  std::vector<PVF::Face_constraint<boost::graph_traits<Mesh>::face_descriptor, SC::Vector_3> > out;
  ASSERT_EQ(PIO::read_dmat_constraints(data_file("inspired_mesh_b.dmat"), data_file("inspired_mesh_bc.dmat"), tm, out,
                                       CGAL::parameters::geom_traits(SC())),
            Error_code::SUCCESS);
  EXPECT_EQ(out.size(), 84u);
}

} // namespace
