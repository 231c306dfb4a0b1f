// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// From a mesh to a seamless integer-grid map (a quad-meshing parametrization):
// a frame field is designed from 1% curvature constraints, then the map is
// computed on the same tangent bundle and written as an OBJ file with one
// texture coordinate per corner, where one unit of uv is one quad.
//
//   integer_grid_map [mesh.off [out.obj [edge_length]]]
//   (default: the bundled bumpy.off, integer_grid_map.obj, the mean edge length)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/IO/integer_grid_map.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/compute_integer_grid_map.h>
#include <CGAL/Polyvector_fields/select_curvature_constraints.h>

#include <array>
#include <complex>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#ifndef PVF_DATA_DIR
#define PVF_DATA_DIR "data"
#endif

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Face_index Face;
typedef Mesh::Halfedge_index Halfedge;
namespace PVF = CGAL::Polyvector_fields;

int main(int argc, char** argv)
{
  const std::string filename = argc > 1 ? argv[1] : std::string(PVF_DATA_DIR) + "/bumpy.off";
  const std::string out = argc > 2 ? argv[2] : "integer_grid_map.obj";
  const double edge_length = argc > 3 ? std::atof(argv[3]) : 0;  // 0: the default, the mean edge length
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // Frames, numbering, transport and components: once, for the whole pipeline.
  const PVF::Tangent_bundle<Mesh> bundle(mesh);
  if(bundle.status() != PVF::Error_code::SUCCESS)
  {
    std::cerr << "the mesh cannot carry a field: " << PVF::get_error_message(bundle.status()) << std::endl;
    return EXIT_FAILURE;
  }

  // 1. A smooth frame field {+-u, +-v} along the principal directions of the 1% most anisotropic faces.
  auto curvatures = mesh.add_property_map<Face, PVF::Principal_curvatures<Vector> >("f:curvatures").first;
  std::vector<PVF::Face_constraint<Face, Vector> > constraints;
  PVF::Error_code code = PVF::estimate_principal_curvatures(bundle, curvatures);
  if(code == PVF::Error_code::SUCCESS)
    code = PVF::select_curvature_constraints(mesh, curvatures, constraints, PVF::parameters::constrained_fraction(0.01));
  if(code != PVF::Error_code::SUCCESS || constraints.empty())
  {
    std::cerr << "curvature constraints: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }
  PVF::Polyvector_field_designer<Mesh> designer(bundle, 4, PVF::parameters::sign_symmetric(true));
  auto field = mesh.add_property_map<Face, std::vector<std::complex<double> > >("f:field").first;
  code = designer.add_constraints(constraints);
  if(code == PVF::Error_code::SUCCESS)
    code = designer.solve(field);
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "design: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }

  // 2. The seamless integer-grid map, on the same bundle: uv per corner (halfedge).
  auto uv = mesh.add_property_map<Halfedge, std::array<double, 2> >("h:uv").first;
  PVF::Integer_grid_map_result result;
  if(edge_length > 0)
    code = PVF::compute_integer_grid_map(bundle, field, uv, result, PVF::parameters::target_edge_length(edge_length));
  else
    code = PVF::compute_integer_grid_map(bundle, field, uv, result);
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "integer-grid map: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }

  // 3. The OBJ with texture coordinates: a checkerboard of period 1 shows the quads.
  code = PVF::IO::write_integer_grid_map_OBJ(out, mesh, uv);
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << out << ": " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << result.faces << " faces, " << constraints.size() << " constraints, edge length "
            << result.target_edge_length << "\n"
            << result.comb.singular_vertices << " singularities, " << result.comb.seam_curves << " seam curves, "
            << result.integer_unknowns << " integer unknowns\n"
            << result.flipped_faces << " flipped faces, worst seam residual " << result.max_seam_residual
            << ", rounded/continuous energy " << result.energy_ratio << "\n"
            << "wrote " << out << " (" << result.time_total << " s)\n";
  return result.flipped_faces == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
