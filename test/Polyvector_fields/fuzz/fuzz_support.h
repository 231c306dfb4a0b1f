// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// What the harnesses share: the mesh type, small meshes built in code (no
// file is read), and the checks that every reader must pass.

#ifndef CGAL_POLYVECTOR_FIELDS_TEST_FUZZ_SUPPORT_H
#define CGAL_POLYVECTOR_FIELDS_TEST_FUZZ_SUPPORT_H

#include "fuzz_target.h"
#include "../io_test_support.h"
#include "../test_meshes.h"

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Face_constraint.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/squared_distance_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/generators.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

namespace pvf_fuzz {

namespace PVF = CGAL::Polyvector_fields;
namespace PIO = CGAL::Polyvector_fields::IO;
using PVF::Error_code;

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef boost::graph_traits<Mesh>::face_descriptor Face;
typedef boost::graph_traits<Mesh>::vertex_descriptor Vertex;

// The mean edge length of a mesh.
inline double mean_edge(const Mesh& tm)
{
  double sum = 0;
  for(auto e : edges(tm))
    sum += std::sqrt(CGAL::squared_distance(tm.point(source(e, tm)), tm.point(target(e, tm))));
  return sum / double(num_edges(tm));
}

// The distance from p to the nearest face of tm, face by face (the meshes of
// the harnesses have a few dozen faces).
inline double distance_to_surface(const Point& p, const Mesh& tm)
{
  double best = std::numeric_limits<double>::infinity();
  for(auto f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    const Kernel::Triangle_3 t(tm.point(source(h, tm)), tm.point(target(h, tm)), tm.point(target(next(h, tm), tm)));
    best = (std::min)(best, CGAL::squared_distance(p, t));
  }
  return std::sqrt(best);
}

inline std::string as_text(const std::uint8_t* data, std::size_t size)
{
  return std::string(reinterpret_cast<const char*>(data), size);
}

inline std::string code_name(Error_code code)
{
  return std::to_string(int(code)) + " (" + PVF::get_error_message(code) + ")";
}

// A failure must be a known code with a message; the message names the input.
inline void check_failure_reported(Error_code code, const std::string& message, const char* what)
{
  PVF_FUZZ_CHECK(code != Error_code::SUCCESS, what);
  PVF_FUZZ_CHECK(std::string(PVF::get_error_message(code)) != "unknown error",
                 std::string(what) + ": code " + std::to_string(int(code)));
  PVF_FUZZ_CHECK(!message.empty(), std::string(what) + " failed with " + code_name(code) + " and no message");
}

// Reads the input byte by byte; past its end every byte is 0.
struct Byte_reader
{
  const std::uint8_t* data;
  std::size_t size, next = 0;
  std::uint8_t get() { return next < size ? data[next++] : 0; }
};

inline bool finite(const Vector& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

inline bool same_vector(const Vector& a, const Vector& b)
{
  // Bit for bit, so that -0 and +0 (which read and write back as such) count apart.
  const double x[3] = { a.x(), a.y(), a.z() }, y[3] = { b.x(), b.y(), b.z() };
  return std::memcmp(x, y, sizeof x) == 0;
}

inline bool same_vectors(const std::vector<Vector>& a, const std::vector<Vector>& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(!same_vector(a[i], b[i]))
      return false;
  return true;
}

inline std::string vector_text(const Vector& v)
{
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "(%.17g %.17g %.17g)", v.x(), v.y(), v.z());
  return buffer;
}

template <typename FaceDescriptor>
bool same_constraints(const std::vector<PVF::Face_constraint<FaceDescriptor, Vector> >& a,
                      const std::vector<PVF::Face_constraint<FaceDescriptor, Vector> >& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(!(a[i].face == b[i].face) || !same_vectors(a[i].vectors, b[i].vectors) ||
       std::memcmp(&a[i].weight, &b[i].weight, sizeof(double)) != 0)
      return false;
  return true;
}

// A closed tetrahedron: 4 vertices, 4 faces. The readers of files that name
// faces or vertices by id read on it.
inline const Mesh& tetrahedron()
{
  static const Mesh tm = [] {
    Mesh m;
    CGAL::make_tetrahedron(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), m);
    return m;
  }();
  return tm;
}

// The tests' meshes (test_meshes.h; Mesh is the same type) and the sentinels
// of the readers (io_test_support.h).
using pvf_test::grid;
using pvf_io_test::sentinel_degree;
using pvf_io_test::sentinel_constraints;
using pvf_io_test::sentinel_singularities;
using pvf_io_test::is_sentinel;
using pvf_io_test::fill_sentinel_roots;
using pvf_io_test::has_sentinel_roots;

// A scratch file of this process, for the readers that take a file name.
inline const std::string& scratch_file()
{
  static const std::string name = [] {
    // In memory when there is /dev/shm: on ext4, rewriting a truncated file
    // flushes it to disk at close, which would slow a fuzzer down to the disk.
    std::error_code ec;
    std::filesystem::path folder = "/dev/shm";
    if(!std::filesystem::is_directory(folder, ec) || ::access(folder.c_str(), W_OK) != 0)
    {
      folder = std::filesystem::temp_directory_path(ec);
      if(ec)
        folder = "/tmp";
    }
    return (folder / ("pvf_fuzz_" + std::to_string(::getpid()) + ".txt")).string();
  }();
  struct Remover
  {
    ~Remover() { std::remove(name.c_str()); }
  };
  static const Remover remover;
  return name;
}

inline void write_scratch_file(const std::string& content)
{
  std::ofstream out(scratch_file(), std::ios::binary | std::ios::trunc);
  out.write(content.data(), std::streamsize(content.size()));
  out.close();
  PVF_FUZZ_CHECK(bool(out), "cannot write the scratch file " + scratch_file());
}

} // namespace pvf_fuzz

#endif // CGAL_POLYVECTOR_FIELDS_TEST_FUZZ_SUPPORT_H
