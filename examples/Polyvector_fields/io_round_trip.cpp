// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// The file formats: a mesh read (and repaired if it needs it) with
// IO::read_triangle_mesh(), constraints, a field (.rawfield) and its
// singularities (.sings) written and read back exactly, and a VTK file.
//
//   io_round_trip [mesh] [output folder]      (default: the bundled lilium.obj, the current folder)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/IO/rawfield.h>
#include <CGAL/Polyvector_fields/IO/read_triangle_mesh.h>
#include <CGAL/Polyvector_fields/IO/singularities.h>
#include <CGAL/Polyvector_fields/IO/vtk.h>
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
typedef Mesh::Vertex_index Vertex;
namespace PVF = CGAL::Polyvector_fields;

int main(int argc, char** argv)
{
  const std::string filename = argc > 1 ? argv[1] : std::string(PVF_DATA_DIR) + "/lilium.obj";
  const std::string folder = argc > 2 ? argv[2] : ".";
  Mesh mesh;
  PVF::IO::Mesh_repair_result report;
  std::string message;
  if(PVF::IO::read_triangle_mesh(filename, mesh, report, PVF::parameters::error_message(message)) !=
     PVF::Error_code::SUCCESS)
  {
    std::cerr << filename << ": " << message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << filename << ": " << mesh.number_of_faces() << " faces" << (report.changed() ? " (repaired)" : "") << "\n";

  // Constraints written and read back.
  const std::vector<PVF::Face_constraint<Face, Vector> > constraints = {
    { Face(0), { Vector(1, 0, 0), Vector(0, 1, 0), Vector(0, 0, 1) } } };
  std::vector<PVF::Face_constraint<Face, Vector> > read_back;
  if(PVF::IO::write_constraints(folder + "/constraints.txt", mesh, constraints) != PVF::Error_code::SUCCESS ||
     PVF::IO::read_constraints(folder + "/constraints.txt", mesh, read_back) != PVF::Error_code::SUCCESS)
  {
    std::cerr << "cannot write or read " << folder << "/constraints.txt" << std::endl;
    return EXIT_FAILURE;
  }

  // A 3-PolyVector field, its vectors and its singularities, to files.
  auto coefficients = mesh.add_property_map<Face, std::vector<std::complex<double> > >("f:c").first;
  auto roots = mesh.add_property_map<Face, std::vector<Vector> >("f:roots").first;
  std::vector<PVF::Singularity<Vertex> > singularities;
  if(PVF::design_polyvector_field(mesh, 3, read_back, coefficients) != PVF::Error_code::SUCCESS ||
     PVF::compute_field_roots(mesh, 3, coefficients, roots) != PVF::Error_code::SUCCESS ||
     PVF::compute_singularities(mesh, 3, coefficients, std::back_inserter(singularities)) != PVF::Error_code::SUCCESS ||
     PVF::IO::write_rawfield(folder + "/field.rawfield", mesh, roots, 3) != PVF::Error_code::SUCCESS ||
     PVF::IO::write_singularities(folder + "/field.sings", mesh, 3, singularities) != PVF::Error_code::SUCCESS ||
     PVF::IO::write_VTK(folder + "/field.vtk", mesh, roots, 3, singularities) != PVF::Error_code::SUCCESS)
  {
    std::cerr << "cannot design or write the field" << std::endl;
    return EXIT_FAILURE;
  }

  // Read back: the vectors are the same doubles.
  auto reread = mesh.add_property_map<Face, std::vector<Vector> >("f:reread").first;
  std::size_t N = 0;
  std::vector<PVF::Singularity<Vertex> > reread_singularities;
  if(PVF::IO::read_rawfield(folder + "/field.rawfield", mesh, reread, N, PVF::parameters::expected_degree(3)) !=
       PVF::Error_code::SUCCESS ||
     PVF::IO::read_singularities(folder + "/field.sings", mesh, N, reread_singularities) != PVF::Error_code::SUCCESS)
  {
    std::cerr << "cannot read the field back" << std::endl;
    return EXIT_FAILURE;
  }
  for(Face f : faces(mesh))
    if(reread[f] != roots[f])
    {
      std::cerr << "face " << f << " differs after the round trip" << std::endl;
      return EXIT_FAILURE;
    }
  std::cout << "field and " << reread_singularities.size() << " singularities written to " << folder
            << " and read back exactly\n";
  return EXIT_SUCCESS;
}
