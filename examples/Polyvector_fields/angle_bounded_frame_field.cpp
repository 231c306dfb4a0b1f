// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// A frame field {±u, ±v} whose u and v make at least 70 degrees in every face
// (paper Section 4.2), from random frame constraints, with the smallest angle
// before and after.
//
//   angle_bounded_frame_field [mesh.off]      (default: the bundled bumpy.off)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/design_angle_bounded_frame_field.h>
#include <CGAL/Polyvector_fields/design_polyvector_field.h>
#include <CGAL/Polyvector_fields/frame_field_measures.h>

#include <algorithm>
#include <complex>
#include <cstdlib>
#include <iostream>
#include <random>
#include <vector>

#ifndef PVF_DATA_DIR
#define PVF_DATA_DIR "data"
#endif

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Face_index Face;
namespace PVF = CGAL::Polyvector_fields;

int main(int argc, char** argv)
{
  const std::string filename = argc > 1 ? argv[1] : std::string(PVF_DATA_DIR) + "/bumpy.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh) || mesh.number_of_faces() < 30)
  {
    std::cerr << "cannot read a triangle mesh with 30 faces or more from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // 30 random frames: skewed ones make the smooth field skewed too.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> x(-1, 1);
  std::vector<PVF::Face_constraint<Face, Vector> > constraints;
  for(std::size_t i = 0; i < 30; ++i)
    constraints.push_back({ Face(Mesh::size_type(i * (mesh.number_of_faces() / 30))),
                            { Vector(x(rng), x(rng), x(rng)), Vector(x(rng), x(rng), x(rng)) } });

  auto smooth = mesh.add_property_map<Face, std::vector<std::complex<double> > >("f:smooth").first;
  auto bounded = mesh.add_property_map<Face, std::vector<std::complex<double> > >("f:bounded").first;
  auto angles = mesh.add_property_map<Face, double>("f:angle").first;
  PVF::Angle_bound_result result;
  const double bound = 70 * CGAL_PI / 180;
  if(PVF::design_polyvector_field(mesh, 4, constraints, smooth, PVF::parameters::sign_symmetric(true)) != PVF::Error_code::SUCCESS ||
     PVF::design_angle_bounded_frame_field(mesh, constraints, bounded, result, PVF::parameters::angle_bound(bound)) !=
       PVF::Error_code::SUCCESS)
  {
    std::cerr << "design failed" << std::endl;
    return EXIT_FAILURE;
  }
  auto smallest = [&](auto field) {
    PVF::compute_frame_angles(mesh, field, angles);
    double m = CGAL_PI;
    for(Face f : faces(mesh))
      m = (std::min)(m, angles[f]);
    return m * 180 / CGAL_PI;
  };
  std::cout << "smallest angle between u and v: " << smallest(smooth) << " degrees (smooth field), "
            << smallest(bounded) << " degrees after " << result.iterations << " iterations ("
            << result.minimum_free_angle * 180 / CGAL_PI << " on the faces free of constraints)\n";
  return result.converged ? EXIT_SUCCESS : EXIT_FAILURE;
}
