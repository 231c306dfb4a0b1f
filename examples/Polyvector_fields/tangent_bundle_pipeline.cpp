// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// A pipeline on one tangent bundle: the frames, numbering and connection of
// the mesh are built once and passed to the designer and to every evaluation.
//
//   tangent_bundle_pipeline [mesh.off]      (default: the bundled bumpy.off)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>
#include <CGAL/Polyvector_fields/smoothness_energy.h>

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

  // Frames, numbering, transport and components: once.
  const PVF::Tangent_bundle<Mesh> bundle(mesh);
  if(bundle.status() != PVF::Error_code::SUCCESS)
  {
    std::cerr << "the mesh cannot carry a field: " << PVF::get_error_message(bundle.status()) << std::endl;
    return EXIT_FAILURE;
  }

  // A 3-PolyVector field (three independent vectors) from two constraints.
  PVF::Polyvector_field_designer<Mesh> designer(bundle, 3);
  designer.add_constraint(Face(0), { Vector(1, 0, 0), Vector(0, 1, 0), Vector(-1, -1, 0) });
  designer.add_constraint(bundle.face(bundle.number_of_faces() / 2), { Vector(0, 0, 1), Vector(1, 0, 0), Vector(0, 1, 0) });
  auto coefficients = mesh.add_property_map<Face, std::vector<std::complex<double> > >("f:coefficients").first;
  const PVF::Error_code code = designer.solve(coefficients);
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "design failed: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }

  // Every evaluation takes the same bundle.
  auto vectors = mesh.add_property_map<Face, std::vector<Vector> >("f:vectors").first;
  std::vector<PVF::Singularity<Mesh::Vertex_index> > singularities;
  auto matching = mesh.add_property_map<Mesh::Edge_index, int>("e:matching").first;
  if(PVF::compute_field_roots(bundle, 3, coefficients, vectors) != PVF::Error_code::SUCCESS ||
     PVF::compute_singularities(bundle, 3, coefficients, std::back_inserter(singularities)) != PVF::Error_code::SUCCESS ||
     PVF::principal_matching(bundle, 3, coefficients, matching) != PVF::Error_code::SUCCESS)
  {
    std::cerr << "evaluation failed" << std::endl;
    return EXIT_FAILURE;
  }
  int sum = 0;
  for(const auto& s : singularities)
    sum += s.index_numerator;
  std::cout << bundle.number_of_faces() << " faces, " << bundle.interior_edges().size() << " interior edges, "
            << bundle.number_of_components() << " component(s)\n"
            << "energy " << PVF::smoothness_energy(bundle, 3, coefficients) << ", " << singularities.size()
            << " singularities, indices summing to " << sum << "/3\n";
  return EXIT_SUCCESS;
}
