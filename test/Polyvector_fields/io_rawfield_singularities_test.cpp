// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Tests of IO/rawfield.h and IO/singularities.h, and of the shared parsing and
// all-or-nothing file writing they rely on.

#include <CGAL/Polyvector_fields/IO/rawfield.h>
#include <CGAL/Polyvector_fields/IO/singularities.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/properties.h>

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <limits>
#include <locale>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io_test_support.h"

namespace {

using namespace pvf_io_test;
namespace PIO = CGAL::Polyvector_fields::IO;

// A fresh, empty directory for one test; removed at the end of the test.


void set_content(const std::string& filename, const std::string& content)
{
  std::ofstream out(filename, std::ios::binary);
  out << content;
}

std::vector<std::string> lines_of(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while(std::getline(in, line))
    lines.push_back(line);
  return lines;
}

std::vector<std::string> tokens_of(const std::string& line)
{
  std::vector<std::string> tokens;
  std::istringstream in(line);
  std::string t;
  while(in >> t)
    tokens.push_back(t);
  return tokens;
}

// A decimal point ',' and '.' thousands separators grouped by 3: a locale that
// breaks naive text I/O of numbers.
struct Comma_numpunct : std::numpunct<char>
{
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

// ---------------------------------------------------------------------------
// Token parsing

TEST(IoParsing, DoubleGrammarAndRange)
{
  using PIO::internal::parse_double;
  using PIO::internal::Token_status;
  double x = 7;
  EXPECT_EQ(parse_double("1.5", x), Token_status::OK);
  EXPECT_EQ(x, 1.5);
  EXPECT_EQ(parse_double("+2e3", x), Token_status::OK);
  EXPECT_EQ(x, 2000.0);
  EXPECT_EQ(parse_double("-.25", x), Token_status::OK);
  EXPECT_EQ(x, -0.25);
  EXPECT_EQ(parse_double("5.", x), Token_status::OK);
  EXPECT_EQ(x, 5.0);
  EXPECT_EQ(parse_double("0.1", x), Token_status::OK);
  EXPECT_EQ(x, 0.1);
  EXPECT_EQ(parse_double("4.9406564584124654e-324", x), Token_status::OK);
  EXPECT_EQ(x, std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(parse_double("1e-400", x), Token_status::OK);  // underflow reads as zero
  EXPECT_EQ(x, 0.0);
  EXPECT_EQ(parse_double("-0.0000000000000000000000000001e-380", x), Token_status::OK);
  EXPECT_EQ(x, 0.0);
  EXPECT_TRUE(std::signbit(x));
  EXPECT_EQ(parse_double("1.7976931348623157e308", x), Token_status::OK);
  EXPECT_EQ(x, (std::numeric_limits<double>::max)());

  for(const char* t : { "nan", "NaN", "-nan", "inf", "-INF", "+Infinity", "1e400", "-2e309",
                        "100000000000000000000000000000000000000000000000000000000000000000000000000000000000000"
                        "000000000000000000000000000000000000000000000000000000000000000000000000000000000000000"
                        "000000000000000000000000000000000000000000000000000000000000000000000000000000000000000"
                        "0000000000000000000000000000000000000000000000000000000000000000000" })
  {
    x = 7;
    EXPECT_EQ(parse_double(t, x), Token_status::NON_FINITE) << t;
    EXPECT_EQ(x, 7.0) << t;
  }
  for(const char* t : { "", "+", "-", ".", "e5", "1e", "1e+", "0x1p3", "1,5", "1.5.2", "--1", "+-1", "1 ",
                        "abc", "nanx", "infinit", "1d0", "1.0f", "\x01" })
  {
    x = 7;
    EXPECT_EQ(parse_double(t, x), Token_status::MALFORMED) << t;
    EXPECT_EQ(x, 7.0) << t;
  }
}

TEST(IoParsing, Integers)
{
  using PIO::internal::parse_integer;
  using PIO::internal::Token_status;
  long long i = 7;
  EXPECT_EQ(parse_integer("42", i), Token_status::OK);
  EXPECT_EQ(i, 42);
  EXPECT_EQ(parse_integer("+42", i), Token_status::OK);
  EXPECT_EQ(i, 42);
  EXPECT_EQ(parse_integer("-42", i), Token_status::OK);
  EXPECT_EQ(i, -42);
  EXPECT_EQ(parse_integer("-9223372036854775808", i), Token_status::OK);
  EXPECT_EQ(i, (std::numeric_limits<long long>::min)());
  EXPECT_EQ(parse_integer("9223372036854775808", i), Token_status::OUT_OF_RANGE);
  EXPECT_EQ(parse_integer("-9223372036854775809", i), Token_status::OUT_OF_RANGE);
  std::size_t u = 7;
  EXPECT_EQ(parse_integer("-1", u), Token_status::OUT_OF_RANGE);
  EXPECT_EQ(parse_integer("-0", u), Token_status::OK);
  EXPECT_EQ(u, 0u);
  int k = 7;
  EXPECT_EQ(parse_integer("2147483648", k), Token_status::OUT_OF_RANGE);
  EXPECT_EQ(k, 7);
  for(const char* t : { "", "+", "1.0", "1e3", "0x10", "12a", " 1", "--1" })
    EXPECT_EQ(parse_integer(t, i), Token_status::MALFORMED) << t;
}

TEST(IoParsing, ShortestTextRoundTrips)
{
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 300);
  for(int i = 0; i < 20000; ++i)
  {
    const double x = std::ldexp(uniform(rng), exponent(rng));
    std::string text;
    PIO::internal::append_double(text, x);
    double y = 0;
    ASSERT_EQ(PIO::internal::parse_double(text, y), PIO::internal::Token_status::OK) << text;
    ASSERT_EQ(x, y) << text;
    ASSERT_LE(text.size(), 24u) << text;
  }
}

// ---------------------------------------------------------------------------
// All-or-nothing file writing

TEST(IoAtomicFile, ReplacesOrLeavesUntouched)
{
  Scratch_directory dir("atomic");
  const std::string target = dir.file("out.txt");
  EXPECT_EQ(PIO::internal::write_file_atomically(target, "first\n"), Error_code::SUCCESS);
  EXPECT_EQ(file_content(target), "first\n");
  EXPECT_EQ(PIO::internal::write_file_atomically(target, "second\n"), Error_code::SUCCESS);
  EXPECT_EQ(file_content(target), "second\n");
  EXPECT_EQ(dir.entries(), std::set<std::string>{ "out.txt" });

  // No directory: nothing is created.
  EXPECT_EQ(PIO::internal::write_file_atomically(dir.file("missing/out.txt"), "x"), Error_code::CANNOT_OPEN_FILE);
  // The destination is a directory: it stays, and no temporary is left behind.
  fs::create_directory(dir.file("a_directory"));
  EXPECT_EQ(PIO::internal::write_file_atomically(dir.file("a_directory"), "x"), Error_code::CANNOT_OPEN_FILE);
  EXPECT_TRUE(fs::is_directory(dir.file("a_directory")));
  EXPECT_EQ(PIO::internal::write_file_atomically("", "x"), Error_code::CANNOT_OPEN_FILE);
  EXPECT_EQ(dir.entries(), (std::set<std::string>{ "a_directory", "out.txt" }));
  EXPECT_EQ(file_content(target), "second\n");
}

// ---------------------------------------------------------------------------
// .rawfield

template <typename TriangleMesh>
struct Rawfield_test : ::testing::Test
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename CGAL::Kernel_traits<typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type>::Kernel Kernel;
  typedef typename Kernel::Vector_3 Vector_3;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<std::vector<Vector_3> > >::type
    Root_map;
};

typedef ::testing::Types<CGAL::Surface_mesh<SC::Point_3>, CGAL::Surface_mesh<EPICK::Point_3>,
                         CGAL::Polyhedron_3<SC>, CGAL::Polyhedron_3<EPICK> >
  Mesh_types;
TYPED_TEST_SUITE(Rawfield_test, Mesh_types);

template <typename Vector_3, typename TriangleMesh, typename RootMap>
void fill_random(const TriangleMesh& tm, RootMap roots, std::size_t N, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for(auto f : CGAL::faces(tm))
  {
    std::vector<Vector_3> u;
    for(std::size_t k = 0; k < N; ++k)
      u.emplace_back(uniform(rng), uniform(rng) * 1e-3, uniform(rng) * 1e5);
    put(roots, f, u);
  }
}

template <typename TriangleMesh, typename RootMap>
bool same_fields(const TriangleMesh& tm, RootMap a, RootMap b)
{
  for(auto f : CGAL::faces(tm))
  {
    const auto& u = get(a, f);
    const auto& v = get(b, f);
    if(u.size() != v.size())
      return false;
    for(std::size_t k = 0; k < u.size(); ++k)
      if(u[k].x() != v[k].x() || u[k].y() != v[k].y() || u[k].z() != v[k].z())
        return false;
  }
  return true;
}

TYPED_TEST(Rawfield_test, ExactRoundTripOnBumpy)
{
  typedef TypeParam Mesh;
  typedef typename TestFixture::Vector_3 Vector_3;
  const Mesh tm = load_mesh<Mesh>("bumpy.off");
  const std::size_t F = CGAL::num_faces(tm);
  ASSERT_EQ(F, 2496u);
  auto written = get(CGAL::dynamic_face_property_t<std::vector<Vector_3> >(), tm);
  auto read = get(CGAL::dynamic_face_property_t<std::vector<Vector_3> >(), tm);

  for(std::size_t N : { 1u, 3u, 4u })
  {
    fill_random<Vector_3>(tm, written, N, unsigned(N) * 17u);
    std::ostringstream os;
    ASSERT_EQ(PIO::write_rawfield(os, tm, written, N), Error_code::SUCCESS);

    // The layout: "N F", then F lines of 3N numbers.
    const auto lines = lines_of(os.str());
    ASSERT_EQ(lines.size(), F + 1);
    EXPECT_EQ(lines[0], std::to_string(N) + " " + std::to_string(F));
    for(std::size_t i = 1; i <= F; ++i)
      ASSERT_EQ(tokens_of(lines[i]).size(), 3 * N);

    fill_sentinel_roots(tm, read);
    std::size_t N_read = 0;
    std::istringstream is(os.str());
    ASSERT_EQ(PIO::read_rawfield(is, tm, read, N_read), Error_code::SUCCESS);
    EXPECT_EQ(N_read, N);
    EXPECT_TRUE(same_fields(tm, written, read));
  }

  // The file forms, and an expected degree that matches.
  Scratch_directory dir("rawfield_roundtrip");
  const std::string filename = dir.file("bumpy.rawfield");
  fill_random<Vector_3>(tm, written, 4, 99);
  ASSERT_EQ(PIO::write_rawfield(filename, tm, written, 4), Error_code::SUCCESS);
  EXPECT_EQ(dir.entries(), std::set<std::string>{ "bumpy.rawfield" });
  fill_sentinel_roots(tm, read);
  std::size_t N_read = 0;
  ASSERT_EQ(PIO::read_rawfield(filename, tm, read, N_read, PVF::parameters::expected_degree(std::size_t(4))),
            Error_code::SUCCESS);
  EXPECT_EQ(N_read, 4u);
  EXPECT_TRUE(same_fields(tm, written, read));
}

TEST(Rawfield, LocaleOfTheStreamDoesNotMatter)
{
  typedef CGAL::Surface_mesh<SC::Point_3> Mesh;
  const Mesh tm = load_mesh<Mesh>("bumpy.off");
  auto written = get(CGAL::dynamic_face_property_t<std::vector<SC::Vector_3> >(), tm);
  auto read = get(CGAL::dynamic_face_property_t<std::vector<SC::Vector_3> >(), tm);
  fill_random<SC::Vector_3>(tm, written, 2, 5);
  const std::locale comma(std::locale::classic(), new Comma_numpunct);

  std::ostringstream os;
  os.imbue(comma);
  os.precision(2);
  os << std::fixed;
  ASSERT_EQ(PIO::write_rawfield(os, tm, written, 2), Error_code::SUCCESS);
  EXPECT_EQ(os.str().find(','), std::string::npos);
  EXPECT_EQ(lines_of(os.str())[0], "2 2496");  // no thousands separator

  std::istringstream is(os.str());
  is.imbue(comma);
  std::size_t N = 0;
  ASSERT_EQ(PIO::read_rawfield(is, tm, read, N), Error_code::SUCCESS);
  EXPECT_TRUE(same_fields(tm, written, read));
}

TEST(Rawfield, BadInputLeavesOutputsUntouched)
{
  typedef CGAL::Surface_mesh<EPICK::Point_3> Mesh;
  typedef EPICK::Vector_3 Vector_3;
  // A small mesh: 2 triangles.
  Mesh tm;
  CGAL::make_triangle(EPICK::Point_3(0, 0, 0), EPICK::Point_3(1, 0, 0), EPICK::Point_3(0, 1, 0), tm);
  CGAL::make_triangle(EPICK::Point_3(0, 0, 1), EPICK::Point_3(1, 0, 1), EPICK::Point_3(0, 1, 1), tm);
  ASSERT_EQ(CGAL::faces(tm).size(), 2u);
  auto roots = get(CGAL::dynamic_face_property_t<std::vector<Vector_3> >(), tm);

  const std::string good = "2 2\n1 0 0 0 1 0\n-1 0 0 0 -1 0\n";
  {
    std::istringstream is(good);
    std::size_t N = 0;
    ASSERT_EQ(PIO::read_rawfield(is, tm, roots, N), Error_code::SUCCESS);
    EXPECT_EQ(N, 2u);
    EXPECT_EQ(get(roots, *CGAL::faces(tm).begin())[1], Vector_3(0, 1, 0));
  }
  // Blank lines, tabs, CRLF and a missing final newline are fine.
  {
    std::istringstream is("\n2 2\r\n\n1\t0 0 0 1 0  \r\n\r\n-1 0 0 0 -1 0");
    std::size_t N = 0;
    EXPECT_EQ(PIO::read_rawfield(is, tm, roots, N), Error_code::SUCCESS);
  }

  const std::vector<std::pair<std::string, Error_code> > cases = {
    { "", Error_code::MALFORMED_FILE },
    { "\n\n", Error_code::MALFORMED_FILE },
    { "2\n1 0 0 0 1 0\n-1 0 0 0 -1 0\n", Error_code::MALFORMED_FILE },
    { "2 2 2\n1 0 0 0 1 0\n-1 0 0 0 -1 0\n", Error_code::MALFORMED_FILE },
    { "0 2\n\n\n", Error_code::MALFORMED_FILE },
    { "-2 2\n1 0 0 0 1 0\n-1 0 0 0 -1 0\n", Error_code::MALFORMED_FILE },
    { "2.0 2\n1 0 0 0 1 0\n-1 0 0 0 -1 0\n", Error_code::MALFORMED_FILE },
    { "2 x\n1 0 0 0 1 0\n-1 0 0 0 -1 0\n", Error_code::MALFORMED_FILE },
    { "2 1\n1 0 0 0 1 0\n", Error_code::MALFORMED_FILE },                                   // F too small
    { "2 3\n1 0 0 0 1 0\n-1 0 0 0 -1 0\n1 0 0 0 1 0\n", Error_code::MALFORMED_FILE },       // F too large
    { "2 2\n1 0 0 0 1\n-1 0 0 0 -1 0\n", Error_code::MALFORMED_FILE },                      // missing number
    { "2 2\n1 0 0 0 1 0 0\n-1 0 0 0 -1 0\n", Error_code::MALFORMED_FILE },                  // extra number
    { "2 2\n1 0 0 0 1 0\n", Error_code::MALFORMED_FILE },                                   // missing line
    { "2 2\n1 0 0 0 1 0\n-1 0 0 0 -1 0\n5\n", Error_code::MALFORMED_FILE },                 // extra line
    { "2 2\n1 0 0 0 1 0 -1 0 0 0 -1 0\n", Error_code::MALFORMED_FILE },                     // one line for two faces
    { "2 2\n1 0 0 0 1 0\n-1 0 0 0 -1 O\n", Error_code::MALFORMED_FILE },                    // letter O
    { "2 2\n1,0 0 0 0 1 0\n-1 0 0 0 -1 0\n", Error_code::MALFORMED_FILE },
    { "2 2\n0x1p0 0 0 0 1 0\n-1 0 0 0 -1 0\n", Error_code::MALFORMED_FILE },
    { "2 2\n1 0 0 0 nan 0\n-1 0 0 0 -1 0\n", Error_code::NON_FINITE_VALUE },
    { "2 2\n1 0 0 0 1 0\n-1 0 0 0 -inf 0\n", Error_code::NON_FINITE_VALUE },
    { "2 2\n1 0 0 0 1 0\n-1 0 0 0 1e999 0\n", Error_code::NON_FINITE_VALUE },
    { std::string("2 2\n1 0 0\0 0 1 0\n-1 0 0 0 -1 0\n", 32), Error_code::MALFORMED_FILE },
  };
  for(const auto& c : cases)
  {
    fill_sentinel_roots(tm, roots);
    std::size_t N = 777;
    std::istringstream is(c.first);
    EXPECT_EQ(PIO::read_rawfield(is, tm, roots, N), c.second) << c.first;
    EXPECT_EQ(N, 777u) << c.first;
    EXPECT_TRUE(has_sentinel_roots(tm, roots)) << c.first;
  }

  // A degree other than the expected one.
  {
    fill_sentinel_roots(tm, roots);
    std::size_t N = 777;
    std::istringstream is(good);
    EXPECT_EQ(PIO::read_rawfield(is, tm, roots, N, PVF::parameters::expected_degree(std::size_t(4))),
              Error_code::INCONSISTENT_DEGREE);
    EXPECT_EQ(N, 777u);
    EXPECT_TRUE(has_sentinel_roots(tm, roots));
  }
  // Random bytes, as from a binary file given by mistake.
  {
    std::mt19937 rng(3);
    for(int trial = 0; trial < 50; ++trial)
    {
      std::string bytes = "2 2\n";
      for(int i = 0; i < 200; ++i)
        bytes += char(rng() & 0xFF);
      fill_sentinel_roots(tm, roots);
      std::size_t N = 777;
      std::istringstream is(bytes);
      const Error_code code = PIO::read_rawfield(is, tm, roots, N);
      EXPECT_TRUE(code == Error_code::MALFORMED_FILE || code == Error_code::NON_FINITE_VALUE);
      EXPECT_EQ(N, 777u);
      EXPECT_TRUE(has_sentinel_roots(tm, roots));
    }
  }
  // Unreadable stream and missing file.
  {
    fill_sentinel_roots(tm, roots);
    std::size_t N = 777;
    std::istringstream is(good);
    is.setstate(std::ios::failbit);
    EXPECT_EQ(PIO::read_rawfield(is, tm, roots, N), Error_code::CANNOT_OPEN_FILE);
    EXPECT_EQ(PIO::read_rawfield(std::string(PVF_DATA_DIR) + "/no_such_file.rawfield", tm, roots, N),
              Error_code::CANNOT_OPEN_FILE);
    EXPECT_EQ(PIO::read_rawfield(std::string(PVF_DATA_DIR), tm, roots, N), Error_code::CANNOT_OPEN_FILE);
    EXPECT_EQ(N, 777u);
    EXPECT_TRUE(has_sentinel_roots(tm, roots));
  }
}

TYPED_TEST(Rawfield_test, FailedWritesLeaveNoTrace)
{
  typedef TypeParam Mesh;
  typedef typename TestFixture::Vector_3 Vector_3;
  const Mesh tm = load_mesh<Mesh>("bumpy.off");
  auto roots = get(CGAL::dynamic_face_property_t<std::vector<Vector_3> >(), tm);
  fill_random<Vector_3>(tm, roots, 3, 1);

  Scratch_directory dir("rawfield_write");
  const std::string existing = dir.file("existing.rawfield");
  const std::string fresh = dir.file("fresh.rawfield");
  set_content(existing, "old content\n");

  auto expect_failure = [&](Error_code expected, std::size_t N) {
    std::ostringstream os;
    EXPECT_EQ(PIO::write_rawfield(os, tm, roots, N), expected);
    EXPECT_TRUE(os.str().empty());
    EXPECT_EQ(PIO::write_rawfield(existing, tm, roots, N), expected);
    EXPECT_EQ(PIO::write_rawfield(fresh, tm, roots, N), expected);
    EXPECT_EQ(file_content(existing), "old content\n");
    EXPECT_EQ(dir.entries(), std::set<std::string>{ "existing.rawfield" });
  };
  expect_failure(Error_code::INVALID_DEGREE, 0);
  expect_failure(Error_code::INCONSISTENT_DEGREE, 2);  // the faces hold 3 vectors

  // One face holds 2 vectors: found after many faces have been formatted.
  const auto last = *std::prev(CGAL::faces(tm).end());
  std::vector<Vector_3> saved = get(roots, last);
  put(roots, last, std::vector<Vector_3>(saved.begin(), saved.begin() + 2));
  expect_failure(Error_code::INCONSISTENT_DEGREE, 3);
  std::vector<Vector_3> bad = saved;
  bad[2] = Vector_3(0, std::numeric_limits<double>::quiet_NaN(), 0);
  put(roots, last, bad);
  expect_failure(Error_code::NON_FINITE_VALUE, 3);
  put(roots, last, saved);

  // A directory that does not exist; an unwritable stream.
  EXPECT_EQ(PIO::write_rawfield(dir.file("no_such_dir/field.rawfield"), tm, roots, 3), Error_code::CANNOT_OPEN_FILE);
  EXPECT_FALSE(fs::exists(dir.file("no_such_dir")));
  std::ostringstream broken;
  broken.setstate(std::ios::badbit);
  EXPECT_EQ(PIO::write_rawfield(broken, tm, roots, 3), Error_code::CANNOT_OPEN_FILE);
  EXPECT_EQ(dir.entries(), std::set<std::string>{ "existing.rawfield" });

  // And a good write replaces the old content completely.
  ASSERT_EQ(PIO::write_rawfield(existing, tm, roots, 3), Error_code::SUCCESS);
  EXPECT_EQ(lines_of(file_content(existing)).size(), CGAL::num_faces(tm) + 1);
  EXPECT_EQ(dir.entries(), std::set<std::string>{ "existing.rawfield" });
}

// ---------------------------------------------------------------------------
// .sings

template <typename TriangleMesh>
struct Singularities_test : ::testing::Test {};
TYPED_TEST_SUITE(Singularities_test, Mesh_types);

TYPED_TEST(Singularities_test, RoundTrip)
{
  typedef TypeParam Mesh;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef PVF::Singularity<vertex_descriptor> Singularity;
  const Mesh tm = load_mesh<Mesh>("bumpy.off");
  std::vector<vertex_descriptor> vertices(CGAL::vertices(tm).begin(), CGAL::vertices(tm).end());
  ASSERT_EQ(vertices.size(), 1250u);

  const std::vector<Singularity> written = { { vertices[1249], 1 }, { vertices[0], -1 }, { vertices[17], 2 },
                                             { vertices[600], -3 } };
  Scratch_directory dir("sings");
  const std::string filename = dir.file("bumpy.sings");
  ASSERT_EQ(PIO::write_singularities(filename, tm, 4, written), Error_code::SUCCESS);
  EXPECT_EQ(file_content(filename), "4 4\n1249 1\n0 -1\n17 2\n600 -3\n");

  std::vector<Singularity> read = { { vertices[5], 99 } };
  std::size_t N = 0;
  ASSERT_EQ(PIO::read_singularities(filename, tm, N, read), Error_code::SUCCESS);
  EXPECT_EQ(N, 4u);
  ASSERT_EQ(read.size(), written.size());
  for(std::size_t i = 0; i < read.size(); ++i)
  {
    EXPECT_TRUE(read[i].vertex == written[i].vertex);
    EXPECT_EQ(read[i].index_numerator, written[i].index_numerator);
  }

  // Stream forms, no singularity at all.
  std::ostringstream os;
  ASSERT_EQ(PIO::write_singularities(os, tm, 2, std::vector<Singularity>()), Error_code::SUCCESS);
  EXPECT_EQ(os.str(), "2 0\n");
  std::istringstream is(os.str());
  ASSERT_EQ(PIO::read_singularities(is, tm, N, read, PVF::parameters::expected_degree(std::size_t(2))),
            Error_code::SUCCESS);
  EXPECT_EQ(N, 2u);
  EXPECT_TRUE(read.empty());
}

TEST(Singularities, BadInput)
{
  typedef CGAL::Polyhedron_3<EPICK> Mesh;
  typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef PVF::Singularity<vertex_descriptor> Singularity;
  const Mesh tm = load_mesh<Mesh>("bumpy.off");  // 1250 vertices
  std::vector<vertex_descriptor> vertices(CGAL::vertices(tm).begin(), CGAL::vertices(tm).end());

  const std::vector<std::pair<std::string, Error_code> > cases = {
    { "", Error_code::MALFORMED_FILE },
    { "4\n", Error_code::MALFORMED_FILE },
    { "0 0\n", Error_code::MALFORMED_FILE },
    { "4 -1\n", Error_code::MALFORMED_FILE },
    { "4 1\n", Error_code::MALFORMED_FILE },                      // missing line
    { "4 1\n3 1\n4 1\n", Error_code::MALFORMED_FILE },            // extra line
    { "4 2\n3 1\n", Error_code::MALFORMED_FILE },
    { "4 1\n-1 1\n", Error_code::MALFORMED_FILE },                // bad vertex id
    { "4 1\n1250 1\n", Error_code::MALFORMED_FILE },
    { "4 1\n3.5 1\n", Error_code::MALFORMED_FILE },
    { "4 1\n3 0\n", Error_code::MALFORMED_FILE },                 // zero index
    { "4 1\n3 1.5\n", Error_code::MALFORMED_FILE },
    { "4 1\n3 99999999999\n", Error_code::MALFORMED_FILE },       // does not fit an int
    { "4 1\n3 1 7\n", Error_code::MALFORMED_FILE },
    { "4 1\n3\n", Error_code::MALFORMED_FILE },
    { "4 2\n3 1\n3 -1\n", Error_code::MALFORMED_FILE },           // vertex twice
    { "4 1251\n", Error_code::MALFORMED_FILE },                   // more than the vertices
    { "4 1\nx 1\n", Error_code::MALFORMED_FILE },
  };
  for(const auto& c : cases)
  {
    std::vector<Singularity> out = sentinel_singularities(tm);
    std::size_t N = 777;
    std::istringstream is(c.first);
    EXPECT_EQ(PIO::read_singularities(is, tm, N, out), c.second) << c.first;
    EXPECT_EQ(N, 777u);
    EXPECT_TRUE(is_sentinel(tm, out)) << c.first;
  }
  {
    std::vector<Singularity> out = sentinel_singularities(tm);
    std::size_t N = 777;
    std::istringstream is("4 1\n3 1\n");
    EXPECT_EQ(PIO::read_singularities(is, tm, N, out, PVF::parameters::expected_degree(6)),
              Error_code::INCONSISTENT_DEGREE);
    EXPECT_EQ(N, 777u);
    EXPECT_TRUE(is_sentinel(tm, out));
    EXPECT_EQ(PIO::read_singularities(std::string("/nonexistent/x.sings"), tm, N, out),
              Error_code::CANNOT_OPEN_FILE);
    EXPECT_TRUE(is_sentinel(tm, out));
  }

  // Writer: degree 0, zero index, vertex not in the mesh, vertex twice.
  Scratch_directory dir("sings_bad");
  const std::string existing = dir.file("old.sings");
  set_content(existing, "old\n");
  const Mesh other = load_mesh<Mesh>("bumpy.off");
  const std::vector<std::pair<std::vector<Singularity>, Error_code> > writes = {
    { { { vertices[1], 1 } }, Error_code::SUCCESS },
    { { { vertices[1], 0 } }, Error_code::INVALID_PARAMETER },
    { { { vertices[1], 1 }, { vertices[1], -1 } }, Error_code::INVALID_PARAMETER },
    { { { vertices[1], 1 }, { *CGAL::vertices(other).begin(), 1 } }, Error_code::INVALID_PARAMETER },
    { { { vertex_descriptor(), 1 } }, Error_code::INVALID_PARAMETER },
  };
  for(const auto& w : writes)
  {
    std::ostringstream os;
    EXPECT_EQ(PIO::write_singularities(os, tm, 4, w.first), w.second);
    EXPECT_EQ(os.str().empty(), w.second != Error_code::SUCCESS);
    if(w.second != Error_code::SUCCESS)
    {
      EXPECT_EQ(PIO::write_singularities(existing, tm, 4, w.first), w.second);
      EXPECT_EQ(file_content(existing), "old\n");
    }
  }
  std::ostringstream os;
  EXPECT_EQ(PIO::write_singularities(os, tm, 0, writes[0].first), Error_code::INVALID_DEGREE);
  EXPECT_TRUE(os.str().empty());
  EXPECT_EQ(PIO::write_singularities(dir.file("missing/x.sings"), tm, 4, writes[0].first),
            Error_code::CANNOT_OPEN_FILE);
  EXPECT_EQ(dir.entries(), std::set<std::string>{ "old.sings" });
}

TEST(Singularities, SurfaceMeshWithRemovedVertices)
{
  // Ids follow vertices(tm), which skips removed elements.
  typedef CGAL::Surface_mesh<SC::Point_3> Mesh;
  typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  Mesh tm = load_mesh<Mesh>("bumpy.off");
  const vertex_descriptor v0 = *CGAL::vertices(tm).begin();
  CGAL::Euler::remove_center_vertex(CGAL::halfedge(v0, tm), tm);
  ASSERT_TRUE(tm.has_garbage());
  std::vector<vertex_descriptor> vertices(CGAL::vertices(tm).begin(), CGAL::vertices(tm).end());
  ASSERT_EQ(vertices.size(), 1249u);

  std::ostringstream os;
  ASSERT_EQ(PIO::write_singularities(os, tm, 4, std::vector<PVF::Singularity<vertex_descriptor> >{ { vertices[0], 1 } }),
            Error_code::SUCCESS);
  EXPECT_EQ(os.str(), "4 1\n0 1\n");
  std::ostringstream removed;
  EXPECT_EQ(PIO::write_singularities(removed, tm, 4, std::vector<PVF::Singularity<vertex_descriptor> >{ { v0, 1 } }),
            Error_code::INVALID_PARAMETER);
  std::istringstream is("4 1\n1249 1\n");
  std::vector<PVF::Singularity<vertex_descriptor> > out;
  std::size_t N = 0;
  EXPECT_EQ(PIO::read_singularities(is, tm, N, out), Error_code::MALFORMED_FILE);
}

// The chunked writer: the text of every number is the shortest to_chars()
// text, also for the coordinates written by reuse of an earlier one (-x, and
// the opposite vectors of a sign-symmetric field), and reads back exactly.
// The .rawfield text of `roots` written number after number with plain
// std::to_chars (shortest round trip): what the writers must give.
template <typename Mesh, typename RootMap>
std::string plain_rawfield_text(const Mesh& tm, RootMap roots, std::size_t N)
{
  std::string text = std::to_string(N) + " " + std::to_string(num_faces(tm)) + "\n";
  for(auto f : faces(tm))
  {
    bool first = true;
    for(const auto& u : get(roots, f))
      for(double c : { u.x(), u.y(), u.z() })
      {
        char buffer[64];
        text += first ? "" : " ";
        text.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, c).ptr);
        first = false;
      }
    text += '\n';
  }
  return text;
}

// More faces than one batch of chunks (16 x 4096): the chunks formatted in
// parallel give the bytes of the sequential writer, which are those of plain
// to_chars, number after number.
TEST(Rawfield, ParallelFormattingGivesTheSequentialBytes)
{
  typedef CGAL::Surface_mesh<SC::Point_3> Mesh;
  typedef SC::Vector_3 Vector_3;
  Mesh tm;
  CGAL::make_grid(300, 120, tm, [](std::size_t i, std::size_t j) { return SC::Point_3(double(i), double(j), 0); }, true);
  ASSERT_EQ(num_faces(tm), 72000u);
  auto roots = get(CGAL::dynamic_face_property_t<std::vector<Vector_3> >(), tm);
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for(auto f : faces(tm))
  {
    const Vector_3 u(uniform(random), uniform(random), 0.0), v(uniform(random), uniform(random), -0.0);
    put(roots, f, std::vector<Vector_3>{ u, v, -u, -v });
  }
  const auto face_ids = PIO::internal::face_list(tm);
  std::string sequential, parallel;
  std::size_t sequential_calls = 0;
  ASSERT_TRUE(PIO::internal::format_rawfield<CGAL::Sequential_tag>(roots, 4, face_ids, [&](const char* d, std::size_t n) {
    sequential.append(d, n);
    ++sequential_calls;
    return true;
  }));
  ASSERT_TRUE(PIO::internal::format_rawfield<CGAL::Parallel_if_available_tag>(roots, 4, face_ids,
                                                                              [&](const char* d, std::size_t n) {
                                                                                parallel.append(d, n);
                                                                                return true;
                                                                              }));
  EXPECT_EQ(sequential_calls, 1u + (72000u + 4095u) / 4096u);  // the header, then one call per chunk
  EXPECT_TRUE(parallel == sequential);
  EXPECT_TRUE(sequential == plain_rawfield_text(tm, roots, 4));
  // A sink that fails stops the writer.
  std::size_t calls = 0;
  EXPECT_FALSE(PIO::internal::format_rawfield<CGAL::Parallel_if_available_tag>(roots, 4, face_ids,
                                                                               [&](const char*, std::size_t) {
                                                                                 return ++calls < 3;
                                                                               }));
  EXPECT_EQ(calls, 3u);
}

TEST(Rawfield, ChunkedWriterGivesTheShortestTextOfEveryNumber)
{
  typedef CGAL::Surface_mesh<SC::Point_3> Mesh;
  typedef SC::Vector_3 Vector_3;
  const Mesh tm = load_mesh<Mesh>("bumpy.off");
  auto written = get(CGAL::dynamic_face_property_t<std::vector<Vector_3> >(), tm);
  auto read = get(CGAL::dynamic_face_property_t<std::vector<Vector_3> >(), tm);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const double specials[] = { 0.0, -0.0, 1e-320, -4.9406564584124654e-324, 1.7976931348623157e308, 0.1, -0.1,
                              1e21, 1e-7, 123456.0 };
  std::size_t i = 0;
  for(auto f : faces(tm))
  {
    auto pick = [&]() { return (i++ % 3 == 0) ? specials[(i / 3) % 10] : uniform(random); };
    const Vector_3 u(pick(), pick(), pick()), v(pick(), -pick(), pick());
    put(written, f, std::vector<Vector_3>{ u, v, -u, -v, Vector_3(u.x(), -u.x(), v.z()) });
  }
  std::ostringstream os;
  ASSERT_EQ(PIO::write_rawfield(os, tm, written, 5), Error_code::SUCCESS);
  const std::string text = os.str();

  const std::string expected = plain_rawfield_text(tm, written, 5);
  EXPECT_EQ(text.size(), expected.size());
  EXPECT_TRUE(text == expected);
  EXPECT_NE(text.find(" -0 "), std::string::npos);

  // More than the 1 MB of a chunk, to a file: the same bytes.
  Scratch_directory dir("rawfield_chunks");
  std::string large_expected;
  {
    std::ostringstream large;
    auto many = get(CGAL::dynamic_face_property_t<std::vector<Vector_3> >(), tm);
    for(auto f : faces(tm))
    {
      std::vector<Vector_3> roots;
      for(int k = 0; k < 40; ++k)
        roots.emplace_back(uniform(random), uniform(random), k % 2 ? -roots.back().x() : uniform(random));
      put(many, f, roots);
    }
    ASSERT_EQ(PIO::write_rawfield(large, tm, many, 40), Error_code::SUCCESS);
    large_expected = large.str();
    EXPECT_GT(large_expected.size(), std::size_t(1) << 21);
    ASSERT_EQ(PIO::write_rawfield(dir.file("large.rawfield"), tm, many, 40), Error_code::SUCCESS);
    std::ifstream in(dir.file("large.rawfield"), std::ios::binary);
    const std::string on_disk((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_TRUE(on_disk == large_expected);
    EXPECT_EQ(dir.entries(), std::set<std::string>{ "large.rawfield" });
  }

  // Bit-identical read back.
  std::istringstream is(text);
  std::size_t N = 0;
  ASSERT_EQ(PIO::read_rawfield(is, tm, read, N), Error_code::SUCCESS);
  ASSERT_EQ(N, 5u);
  std::size_t different = 0;
  for(auto f : faces(tm))
    for(std::size_t k = 0; k < 5; ++k)
      for(int c = 0; c < 3; ++c)
      {
        const double a = get(written, f)[k][c], b = get(read, f)[k][c];
        different += std::memcmp(&a, &b, sizeof a) == 0 ? 0 : 1;
      }
  EXPECT_EQ(different, 0u);
}

} // namespace
