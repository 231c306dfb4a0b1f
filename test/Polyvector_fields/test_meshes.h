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
#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/select_sharp_edge_constraints.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <stdexcept>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#ifndef PVF_DATA_DIR
#error "PVF_DATA_DIR (the folder of the bundled meshes) must be given by the build (CMake's pvf_link_package)"
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

// A polygon soup: the parametric surfaces of the tests are made as soups, then
// turned into any mesh type with make_mesh().
template <typename Point_type = Point>
struct Soup
{
  std::vector<Point_type> points;
  std::vector<std::vector<std::size_t> > faces;

  void add_quad(std::size_t a, std::size_t b, std::size_t c, std::size_t d)
  {
    faces.push_back({ a, b, c });
    faces.push_back({ a, c, d });
  }
};

template <typename TriangleMesh, typename Point_type>
TriangleMesh make_mesh(const Soup<Point_type>& s)
{
  TriangleMesh tm;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(s.points, s.faces, tm);
  return tm;
}

constexpr double pi = 3.14159265358979323846;

// grid(rows, cols) with every interior vertex moved by up to 0.15 in x and y
// (seeded): a flat mesh that is not a regular grid.
inline Mesh jittered_grid(int rows, int cols, unsigned seed)
{
  Mesh tm = grid(rows, cols);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-0.15, 0.15);
  for(auto v : vertices(tm))
    if(!CGAL::is_border(v, tm))
      tm.point(v) = tm.point(v) + Vector(d(rng), d(rng), 0);
  return tm;
}

// Partial constraints along the sharp edges of `tm` (dihedral angle above
// `degrees`): each face of such an edge gets the direction of its sharpest
// one or two edges (select_sharp_edge_constraints(), as the command-line
// program's --sharp-edges for a sign-symmetric 4-field).
inline std::vector<CGAL::Polyvector_fields::Face_constraint<Mesh::Face_index, Vector>> sharp_edge_constraints(const Mesh& tm, double degrees)
{
  std::vector<CGAL::Polyvector_fields::Face_constraint<Mesh::Face_index, Vector>> constraints;
  if(CGAL::Polyvector_fields::select_sharp_edge_constraints(tm, degrees, 2, constraints) !=
     CGAL::Polyvector_fields::Error_code::SUCCESS)
    throw std::runtime_error("select_sharp_edge_constraints failed");
  return constraints;
}

// Latitude-longitude sphere of radius R, normals outward; nu meridians, nv bands.
template <typename Point_type = Point>
Soup<Point_type> sphere_soup(double R, int nu, int nv)
{
  Soup<Point_type> s;
  s.points.push_back(Point_type(0, 0, -R));
  for(int j = 1; j < nv; ++j)
    for(int i = 0; i < nu; ++i)
    {
      const double theta = pi * j / nv, phi = 2 * pi * i / nu;
      s.points.push_back(Point_type(R * std::sin(theta) * std::cos(phi), R * std::sin(theta) * std::sin(phi),
                                    -R * std::cos(theta)));
    }
  const std::size_t north = s.points.size();
  s.points.push_back(Point_type(0, 0, R));
  auto id = [nu](int i, int j) { return std::size_t(1 + (j - 1) * nu + (i % nu)); };
  for(int i = 0; i < nu; ++i)
    s.faces.push_back({ 0, id(i + 1, 1), id(i, 1) });
  for(int j = 1; j < nv - 1; ++j)
    for(int i = 0; i < nu; ++i)
      s.add_quad(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  for(int i = 0; i < nu; ++i)
    s.faces.push_back({ id(i, nv - 1), id(i + 1, nv - 1), north });
  return s;
}

// Open cylinder x^2 + y^2 = R^2, 0 <= z <= H, normals outward.
template <typename Point_type = Point>
Soup<Point_type> cylinder_soup(double R, double H, int nu, int nz)
{
  Soup<Point_type> s;
  for(int j = 0; j <= nz; ++j)
    for(int i = 0; i < nu; ++i)
    {
      const double phi = 2 * pi * i / nu;
      s.points.push_back(Point_type(R * std::cos(phi), R * std::sin(phi), H * j / nz));
    }
  auto id = [nu](int i, int j) { return std::size_t(j * nu + (i % nu)); };
  for(int j = 0; j < nz; ++j)
    for(int i = 0; i < nu; ++i)
      s.add_quad(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return s;
}

// Torus of radii R (axis to tube centre) > r (tube), nu x nv quads split into
// triangles, normals outward (closed, genus 1).
template <typename Point_type = Point>
Soup<Point_type> torus_soup(double R, double r, int nu, int nv)
{
  Soup<Point_type> s;
  for(int j = 0; j < nv; ++j)
    for(int i = 0; i < nu; ++i)
    {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      s.points.push_back(Point_type((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)));
    }
  auto id = [nu, nv](int i, int j) { return std::size_t((j % nv) * nu + (i % nu)); };
  for(int j = 0; j < nv; ++j)
    for(int i = 0; i < nu; ++i)
      s.add_quad(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return s;
}

// A torus of radii R > r with n x m quads split into triangles, as a Surface_mesh.
inline Mesh torus(int n, int m, double R = 2, double r = 0.7) { return make_mesh<Mesh>(torus_soup(R, r, n, m)); }

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

  // Moves every point of a mesh.
  template <typename TriangleMesh>
  void move(TriangleMesh& tm) const
  {
    for(auto v : vertices(tm))
      tm.point(v) = (*this)(tm.point(v));
  }

  // Turns every vector of the constraints (faces and weights stay).
  template <typename FaceDescriptor>
  void move(std::vector<CGAL::Polyvector_fields::Face_constraint<FaceDescriptor, Vector> >& constraints) const
  {
    for(auto& c : constraints)
      for(Vector& v : c.vectors)
        v = (*this)(v);
  }
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
