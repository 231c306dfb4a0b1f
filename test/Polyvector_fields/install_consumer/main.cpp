// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// A program outside the package: it is built against an installed copy found
// with find_package(CGAL_Polyvector_fields), and checks that the installed
// headers work on a tetrahedron.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>

#ifdef CGAL_PVF_HAS_CHOLMOD
#include <cholmod.h>
#endif

#include <cstdlib>
#include <iostream>

namespace PVF = CGAL::Polyvector_fields;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;

int main()
{
  Mesh tm;
  const Mesh::Vertex_index a = tm.add_vertex(Point_3(0, 0, 0));
  const Mesh::Vertex_index b = tm.add_vertex(Point_3(1, 0, 0));
  const Mesh::Vertex_index c = tm.add_vertex(Point_3(0, 1, 0));
  const Mesh::Vertex_index d = tm.add_vertex(Point_3(0, 0, 1));
  // Outward orientation: each face is counterclockwise seen from outside.
  tm.add_face(a, c, b);
  tm.add_face(a, b, d);
  tm.add_face(a, d, c);
  tm.add_face(b, c, d);
  if(tm.number_of_faces() != 4 || !CGAL::is_closed(tm)) {
    std::cerr << "install_consumer: could not build the tetrahedron" << std::endl;
    return EXIT_FAILURE;
  }

  const PVF::Tangent_bundle<Mesh> connection(tm);
  if(connection.status() != PVF::Error_code::SUCCESS) {
    std::cerr << "install_consumer: connection failed: "
              << PVF::get_error_message(connection.status()) << std::endl;
    return EXIT_FAILURE;
  }
  if(connection.number_of_faces() != 4 || connection.interior_edges().size() != 6) {
    std::cerr << "install_consumer: expected 4 faces and 6 interior edges, got "
              << connection.number_of_faces() << " and "
              << connection.interior_edges().size() << std::endl;
    return EXIT_FAILURE;
  }

#ifdef CGAL_PVF_HAS_CHOLMOD
  // Linking CGAL::Polyvector_fields_CHOLMOD_support must give a usable CHOLMOD.
  cholmod_common common;
  if(!cholmod_start(&common)) {
    std::cerr << "install_consumer: cholmod_start failed" << std::endl;
    return EXIT_FAILURE;
  }
  cholmod_finish(&common);
  const char* cholmod = "yes";
#else
  const char* cholmod = "no";
#endif

  std::cout << "install_consumer: tetrahedron has " << connection.number_of_faces()
            << " faces and " << connection.interior_edges().size()
            << " interior edges; CHOLMOD support: " << cholmod << std::endl;
  return EXIT_SUCCESS;
}
