// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Combing a frame field: a field is designed from 1% curvature constraints,
// combed along a dual spanning tree and cut; the example prints the size of the
// cut graph and the seam curves that join its singular vertices.
//
//   comb_frame_field [mesh.off]   (default: the bundled bumpy.off)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/comb_frame_field.h>
#include <CGAL/Polyvector_fields/design_polyvector_field.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/select_curvature_constraints.h>

#include <complex>
#include <cstdlib>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#ifndef PVF_DATA_DIR
#define PVF_DATA_DIR "data"
#endif

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Face_index Face;
namespace PVF = CGAL::Polyvector_fields;

int main(int argc, char** argv)
{
  const std::string filename = argc > 1 ? argv[1] : std::string(PVF_DATA_DIR) + "/bumpy.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  const PVF::Tangent_bundle<Mesh> bundle(mesh);
  auto curvatures = mesh.add_property_map<Face, PVF::Principal_curvatures<Kernel::Vector_3> >("f:k").first;
  auto field = mesh.add_property_map<Face, std::vector<std::complex<double> > >("f:field").first;
  std::vector<PVF::Face_constraint<Face, Kernel::Vector_3> > constraints;
  PVF::Error_code code = PVF::estimate_principal_curvatures(bundle, curvatures);
  if(code == PVF::Error_code::SUCCESS)
    code = PVF::select_curvature_constraints(bundle, curvatures, constraints, PVF::parameters::constrained_fraction(0.01));
  if(code == PVF::Error_code::SUCCESS)
    code = PVF::design_polyvector_field(mesh, 4, constraints, field, PVF::parameters::sign_symmetric(true));

  // The comb: cut graph, rotations and combed frames, in the bundle's numbering.
  PVF::Frame_field_comb<PVF::Tangent_bundle<Mesh> > comb;
  if(code == PVF::Error_code::SUCCESS)
    code = PVF::comb_frame_field(bundle, field, comb);
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "frame field: " << PVF::get_error_message(code) << std::endl;
    return EXIT_FAILURE;
  }
  const PVF::Comb_result& r = comb.report();
  std::cout << num_faces(mesh) << " faces, " << r.singular_vertices << " singular vertices, cut graph of "
            << r.cut_edges << " edges in " << comb.number_of_seam_curves() << " seam curves\n";
  // The seam curves run between the nodes of the cut graph: its singular vertices and branch points.
  std::set<Mesh::Vertex_index> joined;
  for(std::size_t i = 0; i < comb.number_of_seam_curves(); ++i)
  {
    const auto ends = comb.seam_curve_ends(i);
    const int a = comb.index_numerator(ends.first), b = comb.index_numerator(ends.second);
    if(a != 0) joined.insert(ends.first);
    if(b != 0) joined.insert(ends.second);
    if(i < 4)
      std::cout << "  seam curve " << i << ": " << comb.seam_curve_halfedges(i).size() << " edges from vertex "
                << ends.first << " (index " << a << "/4) to vertex " << ends.second << " (index " << b << "/4)\n";
  }
  std::cout << "the cut graph joins " << joined.size() << " of the " << r.singular_vertices << " singular vertices\n";
  return joined.size() == r.singular_vertices ? EXIT_SUCCESS : EXIT_FAILURE;  // it goes through all of them
}
