// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Meshes and helpers shared by the tests.

#ifndef CGAL_POLYVECTOR_FIELDS_TEST_MESHES_H
#define CGAL_POLYVECTOR_FIELDS_TEST_MESHES_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Polyvector_fields/Face_constraint.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#ifndef PVF_DATA_DIR
#define PVF_DATA_DIR "/work/main/data"
#endif

namespace pvf_test {

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;

inline std::string data(const std::string& name) { return std::string(PVF_DATA_DIR) + "/" + name; }

template <typename TriangleMesh = Mesh>
TriangleMesh load(const std::string& name)
{
  TriangleMesh tm;
  if(!CGAL::IO::read_polygon_mesh(data(name), tm))
    throw std::runtime_error("cannot read " + name);
  return tm;
}

// A (rows x cols) grid of squares split into triangles, in the plane z = 0,
// spanning [0, cols] x [0, rows]; alternate diagonals avoid a bias.
template <typename TriangleMesh = Mesh>
TriangleMesh grid(int rows, int cols)
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  for(int i = 0; i <= rows; ++i)
    for(int j = 0; j <= cols; ++j)
      points.emplace_back(j, i, 0);
  auto id = [cols](int i, int j) { return std::size_t(i * (cols + 1) + j); };
  for(int i = 0; i < rows; ++i)
    for(int j = 0; j < cols; ++j)
    {
      if((i + j) % 2 == 0)
      {
        triangles.push_back({ id(i, j), id(i, j + 1), id(i + 1, j + 1) });
        triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i + 1, j) });
      }
      else
      {
        triangles.push_back({ id(i, j), id(i, j + 1), id(i + 1, j) });
        triangles.push_back({ id(i, j + 1), id(i + 1, j + 1), id(i + 1, j) });
      }
    }
  TriangleMesh tm;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, tm);
  return tm;
}

// A torus of radii R > r, n x m quads split into triangles (closed, genus 1).
inline Mesh torus(int n, int m, double R = 2, double r = 0.7)
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  const double pi = 3.14159265358979323846;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      const double a = 2 * pi * i / n, b = 2 * pi * j / m;
      points.emplace_back((R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a), r * std::sin(b));
    }
  auto id = [n, m](int i, int j) { return std::size_t(((i + n) % n) * m + (j + m) % m); };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  Mesh tm;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, tm);
  return tm;
}

// An icosahedron refined `levels` times by Loop subdivision, projected onto the unit sphere.
inline Mesh sphere(int levels)
{
  Mesh tm;
  CGAL::make_icosahedron(tm, Point(0, 0, 0), 1.0);
  CGAL::Subdivision_method_3::Loop_subdivision(tm, CGAL::parameters::number_of_iterations(levels));
  for(auto v : vertices(tm))
  {
    const Vector p = tm.point(v) - CGAL::ORIGIN;
    tm.point(v) = CGAL::ORIGIN + p / std::sqrt(p.squared_length());
  }
  return tm;
}

// Euler characteristic V - E + F.
template <typename TriangleMesh>
int euler_characteristic(const TriangleMesh& tm)
{
  return int(num_vertices(tm)) - int(num_edges(tm)) + int(num_faces(tm));
}

// A random rotation (from a random unit quaternion) and translation.
struct Rigid_motion
{
  std::array<double, 9> R;
  Vector t;

  explicit Rigid_motion(unsigned seed)
  {
    std::mt19937 rng(seed);
    std::normal_distribution<double> g;
    double q[4] = { g(rng), g(rng), g(rng), g(rng) };
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for(double& x : q)
      x /= n;
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    R = { 1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
          2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
          2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y) };
    t = Vector(g(rng), g(rng), g(rng));
  }

  Vector operator()(const Vector& v) const
  {
    return Vector(R[0] * v.x() + R[1] * v.y() + R[2] * v.z(),
                  R[3] * v.x() + R[4] * v.y() + R[5] * v.z(),
                  R[6] * v.x() + R[7] * v.y() + R[8] * v.z());
  }
  Point operator()(const Point& p) const { return CGAL::ORIGIN + (*this)(p - CGAL::ORIGIN) + t; }
};

inline Vector random_vector(std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-1, 1);
  return Vector(u(rng), u(rng), u(rng));
}

inline double distance(const Vector& a, const Vector& b) { return std::sqrt((a - b).squared_length()); }

// Largest distance between two sets of vectors under the best matching
// (exhaustive over permutations: sets here have at most 8 elements).
inline double set_distance(std::vector<Vector> a, std::vector<Vector> b)
{
  if(a.size() != b.size())
    return std::numeric_limits<double>::infinity();
  std::vector<std::size_t> p(b.size());
  for(std::size_t i = 0; i < p.size(); ++i)
    p[i] = i;
  double best = std::numeric_limits<double>::infinity();
  do
  {
    double worst = 0;
    for(std::size_t i = 0; i < a.size() && worst < best; ++i)
      worst = (std::max)(worst, distance(a[i], b[p[i]]));
    best = (std::min)(best, worst);
  } while(std::next_permutation(p.begin(), p.end()));
  return best;
}

// Hard constraints on `count` distinct random faces, each with `k` random vectors.
inline std::vector<CGAL::Polyvector_fields::Face_constraint<Mesh::Face_index, Vector> >
random_constraints(const Mesh& tm, std::size_t count, std::size_t k, unsigned seed)
{
  std::mt19937 rng(seed);
  std::vector<CGAL::Polyvector_fields::Face_constraint<Mesh::Face_index, Vector> > constraints;
  std::set<std::size_t> used;
  while(constraints.size() < count)
  {
    const std::size_t f = rng() % num_faces(tm);
    if(!used.insert(f).second)
      continue;
    constraints.push_back({ Mesh::Face_index(Mesh::size_type(f)), {} });
    for(std::size_t i = 0; i < k; ++i)
      constraints.back().vectors.push_back(random_vector(rng));
  }
  return constraints;
}

} // namespace pvf_test

#endif // CGAL_POLYVECTOR_FIELDS_TEST_MESHES_H
