// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// design_polyvector_field: what every part of the program shares (the mesh
// and vector types, the failure that ends a run, the stopwatch of the stages).
// The program is one translation unit: main.cpp includes these headers once.

#ifndef PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_COMMON_H
#define PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_COMMON_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Face_constraint.h>
#include <CGAL/Polyvector_fields/Principal_curvatures.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>

#include <complex>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>

#ifndef PVF_DATA_DIR
#define PVF_DATA_DIR "data"
#endif

namespace pvf_cli {

namespace PVF = CGAL::Polyvector_fields;
namespace fs = std::filesystem;

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index Face;
typedef Mesh::Vertex_index Vertex;
typedef PVF::Face_constraint<Face, Vector> Constraint;
typedef std::complex<double> Complex;
typedef PVF::Principal_curvatures<Vector> Curvatures;
typedef PVF::Tangent_bundle<Mesh> Bundle;

// A failure: one line on standard error, then a non-zero exit.
struct Failure : std::runtime_error
{
  int status;
  Failure(const std::string& message, int exit_status = 1) : std::runtime_error(message), status(exit_status) {}
};

void check(PVF::Error_code code, const std::string& what, const std::string& detail = std::string())
{
  if(code != PVF::Error_code::SUCCESS)
    throw Failure(what + ": " + (detail.empty() ? PVF::get_error_message(code) : detail));
}

// The time of each stage, summed when a stage runs more than once.
struct Stopwatch
{
  PVF::internal::Timer timer;
  std::map<std::string, double> times;
  void lap(const std::string& stage)
  {
    times[stage] += timer.elapsed();
    timer = PVF::internal::Timer();
  }
};

} // namespace pvf_cli

#endif // PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_COMMON_H
