// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// One frame field designed with the direct solver, with multigrid and with the
// default solver, and how far they are from the direct solver's.
//
//   solver_choice [mesh.off]      (default: the bundled bumpy.off)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <boost/property_map/property_map.hpp>

#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/design_polyvector_field.h>

#include <algorithm>
#include <complex>
#include <cstdlib>
#include <iostream>
#include <map>
#include <vector>

#ifndef PVF_DATA_DIR
#define PVF_DATA_DIR "data"
#endif
typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Face_index Face;
typedef std::vector<std::complex<double> > Coefficients;
namespace PVF = CGAL::Polyvector_fields;

// The frame field of `constraints` designed with `solver`, face after face.
template <typename Solver>
bool design(const Mesh& mesh, const std::vector<PVF::Face_constraint<Face, Vector> >& constraints,
            const Solver& solver, Coefficients& field)
{
  std::map<Face, Coefficients> per_face;
  const PVF::Error_code code =
    PVF::design_polyvector_field(mesh, 4, constraints, boost::make_assoc_property_map(per_face),
                                 PVF::parameters::sign_symmetric(true, CGAL::parameters::sparse_linear_solver(solver)));
  if(code != PVF::Error_code::SUCCESS)
    std::cerr << "design failed: " << PVF::get_error_message(code) << std::endl;
  for(const auto& face_and_coefficients : per_face)
    field.insert(field.end(), face_and_coefficients.second.begin(), face_and_coefficients.second.end());
  return code == PVF::Error_code::SUCCESS;
}

// max |a - b| / max |b|
double relative_difference(const Coefficients& a, const Coefficients& b)
{
  double difference = 0, largest = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
  {
    difference = (std::max)(difference, std::abs(a[i] - b[i]));
    largest = (std::max)(largest, std::abs(b[i]));
  }
  return difference / largest;
}

int main(int argc, char** argv)
{
  const std::string filename = argc > 1 ? argv[1] : std::string(PVF_DATA_DIR) + "/bumpy.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh) || mesh.number_of_faces() < 2)
  {
    std::cerr << "cannot read a triangle mesh with two faces or more from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  const std::vector<PVF::Face_constraint<Face, Vector> > constraints = {
    { Face(0), { Vector(1, 0, 0), Vector(0, 1, 0) } },
    { Face(Mesh::size_type(mesh.number_of_faces() / 2)), { Vector(0, 0, 1), Vector(1, 1, 0) } }
  };
  Coefficients direct, multigrid, by_default;
  if(!design(mesh, constraints, PVF::Direct_sparse_solver(), direct) ||
     !design(mesh, constraints, PVF::Amg_sparse_solver(), multigrid) ||
     !design(mesh, constraints, PVF::Default_sparse_solver(), by_default))
    return EXIT_FAILURE;
  std::cout << mesh.number_of_faces() << " faces; largest difference to the direct solver, relative to the largest coefficient:\n"
            << "  multigrid: " << relative_difference(multigrid, direct) << "\n"
            << "  default:   " << relative_difference(by_default, direct) << std::endl;
  return relative_difference(multigrid, direct) < 1e-6 ? EXIT_SUCCESS : EXIT_FAILURE;
}
