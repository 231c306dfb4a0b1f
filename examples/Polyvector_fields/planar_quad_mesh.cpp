// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// From a mesh to a planar-quad mesh (paper, Section 5): a conjugate frame field
// is designed from the bundled constraints, a seamless integer-grid map is
// computed on the same tangent bundle, its quad mesh is extracted, and the
// quads are planarized to 1% before the mesh is written as an OFF file.
//
//   planar_quad_mesh [mesh.obj b.dmat bc.dmat [out.off [edge_length]]]
//   (default: the bundled inspired_mesh.obj with its 84 constraints,
//    planar_quad_mesh.off, edge length 0.82)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/comb_frame_field.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/design_conjugate_frame_field.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/extract_quad_mesh.h>
#include <CGAL/Polyvector_fields/compute_integer_grid_map.h>
#include <CGAL/Polyvector_fields/planarize_quad_mesh.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>

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
  const std::string data = PVF_DATA_DIR;
  const bool own_input = argc > 3;
  const std::string filename = own_input ? argv[1] : data + "/inspired_mesh.obj";
  const std::string b_file = own_input ? argv[2] : data + "/inspired_mesh_b.dmat";
  const std::string bc_file = own_input ? argv[3] : data + "/inspired_mesh_bc.dmat";
  const std::string out = argc > 4 ? argv[4] : "planar_quad_mesh.off";
  const double edge_length = argc > 5 ? std::atof(argv[5]) : 0.82;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  std::vector<PVF::Face_constraint<Face, Vector> > constraints;
  PVF::Error_code code = PVF::IO::read_dmat_constraints(b_file, bc_file, mesh, constraints);
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "constraints: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }

  // Frames, numbering, transport and components: once, for the whole pipeline.
  const PVF::Tangent_bundle<Mesh> bundle(mesh);
  if(bundle.status() != PVF::Error_code::SUCCESS)
  {
    std::cerr << "the mesh cannot carry a field: " << PVF::get_error_message(bundle.status()) << std::endl;
    return EXIT_FAILURE;
  }

  // 1. The smooth frame field of the constraints, designed once: the field object carries its
  //    bundle, degree, symmetry and constraints to the next stages.
  PVF::Polyvector_field_designer<Mesh> designer(bundle, 4, PVF::parameters::sign_symmetric(true));
  PVF::Polyvector_field<PVF::Tangent_bundle<Mesh> > field(bundle, 4, true);
  code = designer.add_constraints(constraints);
  if(code == PVF::Error_code::SUCCESS)
    code = designer.solve(field);
  // 2. Made conjugate in place: its two directions become conjugate for the curvature,
  //    the directions along which quads can be planar; the constraints stay held.
  auto curvatures = mesh.add_property_map<Face, PVF::Principal_curvatures<Vector> >("f:curvatures").first;
  PVF::Conjugate_field_result conjugate;
  if(code == PVF::Error_code::SUCCESS)
    code = PVF::estimate_principal_curvatures(bundle, curvatures);
  if(code == PVF::Error_code::SUCCESS)
    code = PVF::design_conjugate_frame_field(field, conjugate, PVF::parameters::principal_curvature_map(curvatures));
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "conjugate field: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }

  // 3. Combed once, cut into a disk, then the seamless integer-grid map of the comb: one uv unit is
  //    one quad of side edge_length, and the map returns the exact transition across every seam.
  PVF::Frame_field_comb<PVF::Tangent_bundle<Mesh> > comb;
  auto uv = mesh.add_property_map<Halfedge, std::array<double, 2> >("h:uv").first;
  PVF::Integer_grid_map_result grid_map;
  code = PVF::comb_frame_field(field, comb);
  if(code == PVF::Error_code::SUCCESS)
    code = PVF::compute_integer_grid_map(comb, uv, grid_map, PVF::parameters::target_edge_length(edge_length));
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "integer-grid map: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }

  // 4. The quad mesh: one vertex per integer point, one edge per iso-line segment (whole quads only),
  //    traced through the seams by the exact transitions the map returned.
  Mesh quads;
  PVF::Quad_extraction_result extraction;
  code = PVF::extract_quad_mesh(bundle, uv, grid_map, quads, extraction);
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "quad extraction: " << PVF::get_error_message(code) << " (" << extraction.diagnostic << ")" << std::endl;
    return EXIT_FAILURE;
  }

  // 5. Planarity (distance between the diagonals over their mean length), then planarization to 1%,
  //    close to the input surface.
  auto planarity = quads.add_property_map<Face, double>("f:planarity").first;
  PVF::Planarity_result before;
  code = PVF::quad_planarity(quads, planarity, before);
  PVF::Planarization_result planarization;
  if(code == PVF::Error_code::SUCCESS)
    code = PVF::planarize_quad_mesh(quads, mesh, planarization, PVF::parameters::planarity_threshold(0.01));
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "planarization: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }

  if(!CGAL::IO::write_polygon_mesh(out, quads, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "cannot write " << out << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << num_faces(mesh) << " triangles, " << constraints.size() << " constraints, conjugate field in "
            << conjugate.iterations << " iterations\n"
            << grid_map.comb.singular_vertices << " singularities, " << grid_map.flipped_faces << " flipped faces in the map\n"
            << extraction.quads << " quads, " << extraction.irregular_vertices << " irregular vertices\n"
            << "planarity max " << 100 * before.max << "% mean " << 100 * before.mean << "% -> max "
            << 100 * planarization.max_planarity_after << "% mean " << 100 * planarization.mean_planarity_after << "% in "
            << planarization.iterations << " iterations, largest distance to the surface "
            << planarization.max_distance << "\n"
            << "wrote " << out << std::endl;
  return EXIT_SUCCESS;
}
