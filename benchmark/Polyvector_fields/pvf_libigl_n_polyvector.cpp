// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// pvf_libigl_n_polyvector MESH.off CONSTRAINTS OUT.rawfield
//
// The paper's own implementation, libigl's igl::n_polyvector, on the input of
// run_benchmarks.py's comparison (group libigl of meshing_road.py): the torus
// of the previous issue and a constraint file in the command-line program's
// format, 'face_id ux uy uz vx vy vz' per line, the same file that
// design_polyvector_field --sign-symmetric --constraints reads. n_polyvector
// takes the constraints as rows (u, v) and solves for the frame field
// {±u, ±v} (its polynomial in z^2), one sparse LU per coefficient. The field
// is written as design_polyvector_field writes it (.rawfield: "4 F", then
// u, v, -u, -v per face), so that both programs do the same work, files
// included; the time of each part is printed as "time (s) load ...; design
// ...; write ...".
//
// n_polyvector left libigl for libdirectional in 2017: this program is built
// only when CMake is given -DPVF_LIBIGL_INCLUDE_DIR=<libigl>/include of a
// libigl commit that still has include/igl/n_polyvector.h (for instance the
// parent of the commit "migrating polyvector code to libdirectional"),
// header-only, with the system's Eigen.

#include <igl/n_polyvector.h>
#include <igl/readOFF.h>

#include <Eigen/Core>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

double since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int fail(const std::string& message)
{
  std::cerr << "pvf_libigl_n_polyvector: " << message << "\n";
  return 1;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 4)
  {
    std::cerr << "usage: pvf_libigl_n_polyvector MESH.off CONSTRAINTS OUT.rawfield\n";
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  if(!igl::readOFF(argv[1], V, F) || F.rows() == 0 || F.cols() != 3)
    return fail(std::string("cannot read a triangle mesh from '") + argv[1] + "'");
  std::ifstream in(argv[2]);
  if(!in)
    return fail(std::string("cannot open the constraint file '") + argv[2] + "'");
  std::vector<int> faces;
  std::vector<double> vectors;
  std::string line;
  std::size_t number = 0;
  while(std::getline(in, line))
  {
    ++number;
    const std::string data = line.substr(0, line.find('#'));
    std::istringstream words(data);
    long face = 0;
    double x[6];
    if(!(words >> face))
      continue;  // blank or comment
    for(double& c : x)
      if(!(words >> c))
        return fail("line " + std::to_string(number) + " of '" + argv[2] + "': expected 'face ux uy uz vx vy vz'");
    if(face < 0 || face >= F.rows())
      return fail("line " + std::to_string(number) + ": face " + std::to_string(face) + " is not a face of the mesh");
    faces.push_back(int(face));
    vectors.insert(vectors.end(), x, x + 6);
  }
  Eigen::VectorXi b(faces.size());
  Eigen::MatrixXd bc(faces.size(), 6);
  for(std::size_t i = 0; i < faces.size(); ++i)
  {
    b(i) = faces[i];
    for(int c = 0; c < 6; ++c)
      bc(i, c) = vectors[6 * i + c];
  }
  const double t_load = since(start);

  const auto design_start = std::chrono::steady_clock::now();
  Eigen::MatrixXd field;
  igl::n_polyvector(V, F, b, bc, field);
  const double t_design = since(design_start);
  if(field.rows() != F.rows() || field.cols() != 6)
    return fail("n_polyvector returned no field");

  const auto write_start = std::chrono::steady_clock::now();
  const std::string out = argv[3], tmp = out + ".tmp";
  {
    std::ofstream s(tmp);
    s.precision(17);
    s << "4 " << F.rows() << "\n";
    for(Eigen::Index f = 0; f < F.rows(); ++f)
    {
      for(int sign : { 1, -1 })
        for(int c = 0; c < 6; ++c)
          s << sign * field(f, c) << (sign == -1 && c == 5 ? "\n" : " ");
    }
    if(!s.flush())
    {
      std::remove(tmp.c_str());
      return fail("cannot write '" + tmp + "'");
    }
  }
  if(std::rename(tmp.c_str(), out.c_str()) != 0)
  {
    std::remove(tmp.c_str());
    return fail("cannot rename '" + tmp + "' to '" + out + "'");
  }
  std::cout << "faces " << F.rows() << ", constraints " << b.size() << "\n";
  std::cout << "time (s)        load mesh " << t_load << "; design " << t_design << "; write " << since(write_start)
            << ";\n";
  return EXIT_SUCCESS;
}
