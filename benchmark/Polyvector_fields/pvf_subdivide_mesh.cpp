// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// pvf_subdivide_mesh IN SCHEME OUT.off
//
// Writes the triangle mesh IN after the subdivision steps of SCHEME, one
// letter per step in order: L for one Loop step (4 times the faces), S for one
// sqrt(3) step (3 times the faces); "-" for none. run_benchmarks.py makes the
// inputs of its meshing-road rows with it: bumpy.off after LLL is the
// 159,744-face mesh of pvf_quad_benchmark (the same CGAL Loop step as
// pvf_benchmark_common.h, on the same mesh, so the same vertices in the same
// order), and bunny.off after LL the 1,206,528-face scan. It prints
// "faces F vertices V" on success. The file is written to OUT.tmp and renamed,
// so a failed run leaves no OUT; a bad argument or input names the cause and
// exits with status 2 or 1.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

namespace {

int fail(const std::string& message, int status)
{
  std::cerr << "pvf_subdivide_mesh: " << message << "\n";
  return status;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 4)
    return fail("usage: pvf_subdivide_mesh IN SCHEME OUT.off (SCHEME: letters L (Loop) and S (sqrt 3), or -)", 2);
  const std::string in = argv[1], scheme = argv[2], out = argv[3];
  if(scheme != "-" && scheme.find_first_not_of("LS") != std::string::npos)
    return fail("SCHEME '" + scheme + "' has a letter other than L (Loop) and S (sqrt 3); '-' for no step", 2);
  if(out.size() < 4 || out.compare(out.size() - 4, 4, ".off") != 0)
    return fail("the output '" + out + "' must end in .off", 2);

  Mesh tm;
  if(!CGAL::IO::read_polygon_mesh(in, tm))
    return fail("cannot read a polygon mesh from '" + in + "'", 1);
  if(tm.number_of_faces() == 0)
    return fail("'" + in + "' has no face", 1);
  if(!CGAL::is_triangle_mesh(tm))
    return fail("'" + in + "' has faces that are not triangles: Loop and sqrt(3) steps need a triangle mesh", 1);
  if(scheme != "-")
    for(char step : scheme)
    {
      if(step == 'L')
        CGAL::Subdivision_method_3::Loop_subdivision(tm, CGAL::parameters::number_of_iterations(1));
      else
        CGAL::Subdivision_method_3::Sqrt3_subdivision(tm, CGAL::parameters::number_of_iterations(1));
      tm.collect_garbage();
    }

  const std::string tmp = out + ".tmp";
  {
    std::ofstream stream(tmp);
    if(!stream || !CGAL::IO::write_OFF(stream, tm, CGAL::parameters::stream_precision(17)) || !stream.flush())
    {
      std::remove(tmp.c_str());
      return fail("cannot write '" + tmp + "'", 1);
    }
  }
  if(std::rename(tmp.c_str(), out.c_str()) != 0)
  {
    std::remove(tmp.c_str());
    return fail("cannot rename '" + tmp + "' to '" + out + "'", 1);
  }
  std::cout << "faces " << tm.number_of_faces() << " vertices " << tm.number_of_vertices() << "\n";
  return EXIT_SUCCESS;
}
