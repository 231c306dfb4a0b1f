// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Quad extraction from a given map: the uv of every corner is given by the user
// (here the map x -> (x, y) / h of a planar grid, scaled so that one quad is h;
// it could be read from a file or come from another program), and the quad
// mesh of its integer iso-lines is extracted and written.
//
//   extract_quad_mesh_from_map [h [out.off]]   (default: 0.25, quads_from_map.off)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/extract_quad_mesh.h>

#include <array>
#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Halfedge_index Halfedge;
namespace PVF = CGAL::Polyvector_fields;

int main(int argc, char** argv)
{
  const double h = argc > 1 ? std::atof(argv[1]) : 0.25;
  const std::string out = argc > 2 ? argv[2] : "quads_from_map.off";
  if(!(h > 0))
  {
    std::cerr << "the quad size must be positive" << std::endl;
    return EXIT_FAILURE;
  }
  // A triangulated 8 x 6 grid of unit squares in the plane z = 0.
  Mesh mesh;
  CGAL::make_grid(8, 6, mesh, [](std::size_t i, std::size_t j) { return Point(double(i), double(j), 0); }, true);
  if(!CGAL::is_triangle_mesh(mesh))
    return EXIT_FAILURE;

  // The given map: uv at target(h) inside face(h), one chart per face (here all the same).
  auto uv = mesh.add_property_map<Halfedge, std::array<double, 2> >("h:uv").first;
  for(Halfedge hd : halfedges(mesh))
    if(!CGAL::is_border(hd, mesh))
    {
      const Point& p = mesh.point(target(hd, mesh));
      uv[hd] = { p.x() / h, p.y() / h };
    }

  // The uv overload finds the transitions from the uv itself.
  Mesh quads;
  PVF::Quad_extraction_result result;
  const PVF::Error_code code = PVF::extract_quad_mesh(mesh, uv, quads, result);
  if(code != PVF::Error_code::SUCCESS)
  {
    std::cerr << "extraction: " << PVF::get_error_message(code) << " (" << result.diagnostic << ")" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << result.integer_points << " integer points, " << result.quads << " quads, " << result.irregular_vertices
            << " irregular vertices\n";
  if(!CGAL::IO::write_polygon_mesh(out, quads, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "cannot write " << out << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << out << "\n";
  return result.quads == num_faces(quads) && result.irregular_vertices == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
