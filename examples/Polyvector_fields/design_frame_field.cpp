// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// The smallest complete use of the package: a frame field {±u, ±v} on a
// Surface_mesh from two constraints, its vectors and its singularities.
//
//   design_frame_field [mesh.off]      (default: the bundled bumpy.off)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>
#include <CGAL/Polyvector_fields/design_polyvector_field.h>

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

  // Two hard constraints: each vector u stands for the pair {u, -u}.
  const std::vector<PVF::Face_constraint<Face, Vector> > constraints = {
    { Face(0), { Vector(1, 0, 0), Vector(0, 1, 0) } },
    { Face(Mesh::size_type(mesh.number_of_faces() / 2)), { Vector(0, 0, 1), Vector(1, 1, 0) } }
  };

  // The field: 4 coefficients per face, in the face's frame.
  auto coefficients = mesh.add_property_map<Face, std::vector<std::complex<double> > >("f:coefficients").first;
  const auto frame_field = PVF::parameters::sign_symmetric(true);
  PVF::Error_code code = PVF::design_polyvector_field(mesh, 4, constraints, coefficients, frame_field);
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "design failed: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }

  // Its vectors in world coordinates: u, v, -u, -v counterclockwise.
  auto vectors = mesh.add_property_map<Face, std::vector<Vector> >("f:vectors").first;
  code = PVF::compute_field_roots(mesh, 4, coefficients, vectors, frame_field);
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "roots failed: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "face 0: u = " << vectors[Face(0)][0] << ", v = " << vectors[Face(0)][1] << "\n";

  // Its singularities: indices k/4 that sum to 4 times the Euler characteristic on a closed mesh.
  std::vector<PVF::Singularity<Mesh::Vertex_index> > singularities;
  code = PVF::compute_singularities(mesh, 4, coefficients, std::back_inserter(singularities));
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "singularities failed: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }
  int sum = 0;
  for(const auto& s : singularities)
    sum += s.index_numerator;
  std::cout << singularities.size() << " singularities, indices summing to " << sum << "/4\n";
  return EXIT_SUCCESS;
}
