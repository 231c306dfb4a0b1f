// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// A conjugate frame field (paper Section 4.3), the field that planar-quad
// meshes follow, from the bundled architectural surface and its 84
// constraints (the paper's Fig. 1 input), with the deviation from conjugacy
// before and after.
//
//   conjugate_frame_field [mesh.obj b.dmat bc.dmat]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/design_conjugate_frame_field.h>
#include <CGAL/Polyvector_fields/design_polyvector_field.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/frame_field_measures.h>

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
  const std::string data = PVF_DATA_DIR;
  const std::string mesh_file = argc > 3 ? argv[1] : data + "/inspired_mesh.obj";
  const std::string b_file = argc > 3 ? argv[2] : data + "/inspired_mesh_b.dmat";
  const std::string bc_file = argc > 3 ? argv[3] : data + "/inspired_mesh_bc.dmat";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(mesh_file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << mesh_file << std::endl;
    return EXIT_FAILURE;
  }
  std::vector<PVF::Face_constraint<Face, Vector> > constraints;
  std::string message;
  if(PVF::IO::read_dmat_constraints(b_file, bc_file, mesh, constraints, PVF::parameters::error_message(message)) !=
     PVF::Error_code::SUCCESS)
  {
    std::cerr << "cannot read the constraints: " << message << std::endl;
    return EXIT_FAILURE;
  }

  // The curvature, estimated once and given to the optimisation and the measure.
  auto curvatures = mesh.add_property_map<Face, PVF::Principal_curvatures<Vector> >("f:curvatures").first;
  auto smooth = mesh.add_property_map<Face, std::vector<std::complex<double> > >("f:smooth").first;
  auto conjugate = mesh.add_property_map<Face, std::vector<std::complex<double> > >("f:conjugate").first;
  PVF::Conjugate_field_result result;
  if(PVF::estimate_principal_curvatures(mesh, curvatures) != PVF::Error_code::SUCCESS ||
     PVF::design_polyvector_field(mesh, 4, constraints, smooth, PVF::parameters::sign_symmetric(true)) !=
       PVF::Error_code::SUCCESS ||
     PVF::design_conjugate_frame_field(mesh, constraints, conjugate, result,
                                       PVF::parameters::principal_curvature_map(curvatures)) != PVF::Error_code::SUCCESS)
  {
    std::cerr << "design failed" << std::endl;
    return EXIT_FAILURE;
  }

  // The deviation from conjugacy |u^T S v| / (|u| |v| max |k|), in [0, 1].
  auto deviation = mesh.add_property_map<Face, double>("f:deviation").first;
  auto mean_deviation = [&](auto field) {
    PVF::compute_conjugacy_deviation(mesh, field, curvatures, deviation);
    double sum = 0;
    for(Face f : faces(mesh))
      sum += deviation[f];
    return sum / double(mesh.number_of_faces());
  };
  std::cout << "mean deviation from conjugacy: " << mean_deviation(smooth) << " (smooth field), "
            << mean_deviation(conjugate) << " (conjugate field, " << result.iterations << " iterations, "
            << (result.converged ? "converged" : "not converged") << ")\n";
  return result.converged ? EXIT_SUCCESS : EXIT_FAILURE;
}
