// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Interactive design with Polyvector_field_designer: the matrices are
// factored once; new constraint values on the same faces (here, a constraint
// that turns) are solved for with triangular solves only.
//
//   designer_new_values [mesh.off]      (default: the bundled bumpy.off)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>

#include <cmath>
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
  const std::string filename = argc > 1 ? argv[1] : std::string(PVF_DATA_DIR) + "/bumpy.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh) || mesh.number_of_faces() < 2)
  {
    std::cerr << "cannot read a triangle mesh with two faces or more from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  PVF::Polyvector_field_designer<Mesh> designer(mesh, 4, PVF::parameters::sign_symmetric(true));
  if(designer.status() != PVF::Error_code::SUCCESS)
  {
    std::cerr << "the mesh cannot carry a field: " << PVF::get_error_message(designer.status()) << std::endl;
    return EXIT_FAILURE;
  }
  auto field = mesh.add_property_map<Face, std::vector<std::complex<double> > >("f:field").first;
  const Face fixed(0), turning(Mesh::size_type(mesh.number_of_faces() / 2));
  for(int step = 0; step < 4; ++step)
  {
    // The same faces, kinds and weights; only the vectors of `turning` change.
    const double a = step * CGAL_PI / 8;
    designer.clear_constraints();
    designer.add_constraint(fixed, { Vector(1, 0, 0), Vector(0, 1, 0) });
    designer.add_constraint(turning, { Vector(std::cos(a), std::sin(a), 0), Vector(0, 0, 1) });
    const PVF::Error_code code = designer.solve(field);
    if(code != PVF::Error_code::SUCCESS)
    {
      std::cerr << "design failed: " << PVF::get_error_message(code) << std::endl;
      return EXIT_FAILURE;
    }
    const PVF::Design_statistics& s = designer.statistics();
    std::cout << "step " << step << ": " << (s.factorization_reused ? "factorization reused" : "factored") << ", "
              << s.factorization << " s factoring, " << s.solve << " s solving\n";
  }
  return designer.statistics().factorization_reused ? EXIT_SUCCESS : EXIT_FAILURE;
}
