// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_PVF_BENCHMARK_COMMON_H
#define CGAL_POLYVECTOR_FIELDS_PVF_BENCHMARK_COMMON_H

// What the benchmark programs share: the mesh series (Loop subdivision of a
// bundled mesh, generated at run time and kept in memory), the 1% random hard
// constraints, the end-to-end design, and readers of /proc/self/status.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Polyvector_fields/Cholmod_solver.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/polyvector_polynomial.h>

#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#ifndef PVF_DATA_DIR
#define PVF_DATA_DIR "/work/main/data"
#endif

namespace pvf_bench {

namespace PVF = CGAL::Polyvector_fields;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;
typedef PVF::Face_constraint<face_descriptor, Vector_3> Constraint;
typedef std::complex<double> Complex;

#ifdef CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE
// A variant measured as a proposal, not offered by the package: CHOLMOD's
// supernodal Cholesky with the METIS nested-dissection ordering forced
// (CHOLMOD's default tries AMD first and keeps it unless its fill is large).
template <typename Matrix>
class Cholmod_metis_llt : public Eigen::CholmodSupernodalLLT<Matrix>
{
public:
  Cholmod_metis_llt()
  {
    this->cholmod().nmethods = 1;
    this->cholmod().method[0].ordering = CHOLMOD_METIS;
    this->cholmod().postorder = 1;
  }
};
typedef CGAL::Eigen_solver_traits<Cholmod_metis_llt<Eigen::SparseMatrix<std::complex<double> > > > Cholmod_metis_solver;
#endif

// Another proposal measured here only: an iterative solver (conjugate gradient
// with an incomplete Cholesky preconditioner, relative residual 1e-10). Eigen's
// iterative solvers keep a reference to the matrix, which the package's
// adapter does not keep alive after factorize(): this class keeps a copy.
template <typename Matrix>
class Preconditioned_cg
  : public Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper,
                                    Eigen::IncompleteCholesky<typename Matrix::Scalar, Eigen::Lower, Eigen::AMDOrdering<int> > >
{
  typedef Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper,
                                   Eigen::IncompleteCholesky<typename Matrix::Scalar, Eigen::Lower, Eigen::AMDOrdering<int> > > Base;

public:
  Preconditioned_cg() { this->setTolerance(1e-10); }
  Preconditioned_cg& analyzePattern(const Matrix& A)
  {
    m_matrix = A;
    Base::analyzePattern(m_matrix);
    return *this;
  }
  Preconditioned_cg& factorize(const Matrix& A)
  {
    m_matrix = A;
    Base::factorize(m_matrix);
    return *this;
  }

private:
  Matrix m_matrix;
};
typedef CGAL::Eigen_solver_traits<Preconditioned_cg<Eigen::SparseMatrix<std::complex<double> > > > Preconditioned_cg_solver;

// Highest subdivision level of the default suite; PVF_BENCH_MAX_LEVEL raises or lowers it.
inline int max_level(int default_level = 4)
{
  if(const char* s = std::getenv("PVF_BENCH_MAX_LEVEL"))
    return std::atoi(s);
  return default_level;
}

// `name` (a file of the data directory) after `level` Loop subdivisions:
// each multiplies the number of faces by 4. Meshes are kept for the process.
inline const Mesh& subdivided_mesh(const std::string& name, int level)
{
  static std::map<std::pair<std::string, int>, std::unique_ptr<Mesh> > cache;
  auto& slot = cache[{ name, level }];
  if(!slot)
  {
    slot.reset(new Mesh);
    if(level == 0)
    {
      const std::string path = std::string(PVF_DATA_DIR) + "/" + name;
      if(!CGAL::IO::read_polygon_mesh(path, *slot) || !CGAL::is_triangle_mesh(*slot) || slot->number_of_faces() == 0)
      {
        std::cerr << "cannot read the triangle mesh " << path << "\n";
        std::exit(EXIT_FAILURE);
      }
    }
    else
    {
      *slot = subdivided_mesh(name, level - 1);
      CGAL::Subdivision_method_3::Loop_subdivision(*slot, CGAL::parameters::number_of_iterations(1));
      slot->collect_garbage();
    }
  }
  return *slot;
}

inline const Mesh& bumpy(int level) { return subdivided_mesh("bumpy.off", level); }

// Hard full frame constraints {±u, ±v} on `fraction` of the faces (at least
// one), chosen at random with a fixed seed; u has a random direction in the
// face plane, v makes with u an angle drawn in [45, 135] degrees, or exactly
// 90 degrees when `cross` is true. (Orthogonal unit frames have c_2 = 0, so a
// cross-field design solves one degree; general frames need two.)
inline std::vector<Constraint> random_frame_constraints(const Mesh& tm, double fraction = 0.01,
                                                        unsigned seed = 20140709, bool cross = false)
{
  std::vector<face_descriptor> faces(tm.faces().begin(), tm.faces().end());
  std::mt19937 rng(seed);
  const std::size_t k = (std::max)(std::size_t(1), std::size_t(fraction * double(faces.size())));
  for(std::size_t i = 0; i < k; ++i)
  {
    std::uniform_int_distribution<std::size_t> pick(i, faces.size() - 1);
    std::swap(faces[i], faces[pick(rng)]);
  }
  std::uniform_real_distribution<double> angle(0, 2 * CGAL_PI), opening(CGAL_PI / 4, 3 * CGAL_PI / 4);
  std::vector<Constraint> constraints;
  constraints.reserve(k);
  for(std::size_t i = 0; i < k; ++i)
  {
    const auto h = tm.halfedge(faces[i]);
    const Point_3& p0 = tm.point(tm.source(h));
    const Point_3& p1 = tm.point(tm.target(h));
    const Point_3& p2 = tm.point(tm.target(tm.next(h)));
    Vector_3 e1 = p1 - p0;
    const Vector_3 n = CGAL::cross_product(p1 - p0, p2 - p0);
    Vector_3 e2 = CGAL::cross_product(n, e1);
    e1 = e1 / std::sqrt(e1.squared_length());
    e2 = e2 / std::sqrt(e2.squared_length());
    const double a = angle(rng);
    const double frame_angle = cross ? CGAL_PI / 2 : opening(rng);
    const Vector_3 u = std::cos(a) * e1 + std::sin(a) * e2;
    const Vector_3 v = std::cos(a + frame_angle) * e1 + std::sin(a + frame_angle) * e2;
    constraints.push_back(Constraint{ faces[i], { u, v }, std::numeric_limits<double>::infinity() });
  }
  return constraints;
}

// Seconds of each stage of one end-to-end design.
struct End_to_end_times
{
  double connection = 0, assembly = 0, factorization = 0, solve = 0, roots = 0, total = 0;
  std::size_t faces = 0, degrees = 0;
};

inline double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Sign-symmetric 4-PolyVector design, end to end (I/O excluded): face frames
// and connection, assembly, factorization, solves, and the 4 world-space
// vectors of every face (closed-form roots mapped out of the face frames).
// Exits on failure: a benchmark that failed has no figure to report.
template <typename Solver, typename ConcurrencyTag = CGAL::Parallel_if_available_tag>
End_to_end_times design_end_to_end(const Mesh& tm, const std::vector<Constraint>& constraints,
                                   std::vector<Complex>* coefficients = nullptr,
                                   std::vector<std::array<double, 3> >* world_roots = nullptr)
{
  typedef PVF::Polyvector_field_designer<Mesh, CGAL::Default, CGAL::Default, Solver, ConcurrencyTag> Designer;
  End_to_end_times t;
  const auto start = std::chrono::steady_clock::now();
  Designer designer(tm, 4, PVF::parameters::sign_symmetric(true));
  if(designer.status() != PVF::Error_code::SUCCESS || designer.add_constraints(constraints) != PVF::Error_code::SUCCESS ||
     designer.solve(boost::dummy_property_map()) != PVF::Error_code::SUCCESS)
  {
    std::cerr << "the design failed\n";
    std::exit(EXIT_FAILURE);
  }
  const auto roots_start = std::chrono::steady_clock::now();
  const std::vector<Complex>& c = designer.coefficient_array();
  const std::size_t F = designer.tangent_bundle().number_of_faces();
  std::vector<std::array<double, 3> > local_roots;
  std::vector<std::array<double, 3> >& world = world_roots ? *world_roots : local_roots;
  world.resize(4 * F);
  std::vector<Complex> roots;
  PVF::internal::field_roots<ConcurrencyTag>(c, 4, true, roots);  // what compute_field_roots() does
  for(std::size_t f = 0; f < F; ++f)
  {
    const PVF::Face_frame& frame = designer.tangent_bundle().frame(f);
    for(std::size_t k = 0; k < 4; ++k)
      world[4 * f + k] = frame.to_world(roots[4 * f + k]);
  }
  t.roots = seconds_since(roots_start);
  t.total = seconds_since(start);
  const PVF::Design_statistics& s = designer.statistics();
  t.connection = s.connection;
  t.assembly = s.assembly;
  t.factorization = s.factorization;
  t.solve = s.solve;
  t.faces = F;
  t.degrees = s.number_of_degrees_solved;
  if(coefficients)
    *coefficients = c;
  return t;
}

// A value of /proc/self/status in kB ("VmRSS", "VmHWM"), or -1.
inline long status_kb(const std::string& key)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, key.size() + 1, key + ":") == 0)
      return std::atol(line.c_str() + key.size() + 1);
  return -1;
}

// Resets VmHWM to the current RSS (Linux >= 4.0); returns false if refused.
inline bool reset_peak_rss()
{
  std::ofstream out("/proc/self/clear_refs");
  out << "5" << std::flush;
  return bool(out);
}

} // namespace pvf_bench

#endif // CGAL_POLYVECTOR_FIELDS_PVF_BENCHMARK_COMMON_H
