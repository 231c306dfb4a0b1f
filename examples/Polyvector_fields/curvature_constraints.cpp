// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Principal curvatures per face by jet fitting, and sparse frame constraints
// along the principal directions of the most anisotropic faces (the input of
// the paper's frame-field results), from which a smooth frame field follows.
//
//   curvature_constraints [mesh.off [percent]]   (default: the bundled fandisk.off, 1%)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/design_polyvector_field.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/select_curvature_constraints.h>

#include <complex>
#include <cstdlib>
#include <iostream>
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
  const std::string filename = argc > 1 ? argv[1] : std::string(PVF_DATA_DIR) + "/fandisk.off";
  const double percent = argc > 2 ? std::atof(argv[2]) : 1.0;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  auto curvatures = mesh.add_property_map<Face, PVF::Principal_curvatures<Vector> >("f:curvatures").first;
  PVF::Error_code code = PVF::estimate_principal_curvatures(mesh, curvatures, CGAL::parameters::degree_fitting(2));
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "curvature: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }
  std::vector<PVF::Face_constraint<Face, Vector> > constraints;
  code = PVF::select_curvature_constraints(mesh, curvatures, constraints,
                                           PVF::parameters::constrained_fraction(percent / 100));
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "selection: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }
  auto field = mesh.add_property_map<Face, std::vector<std::complex<double> > >("f:field").first;
  code = PVF::design_polyvector_field(mesh, 4, constraints, field, PVF::parameters::sign_symmetric(true));
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "design: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }
  const auto& first = curvatures[constraints.front().face];
  std::cout << constraints.size() << " of " << mesh.number_of_faces() << " faces constrained to their principal directions; "
            << "the first has k1 = " << first.k1 << ", k2 = " << first.k2 << ", d1 = " << first.d1 << "\n";
  return EXIT_SUCCESS;
}
