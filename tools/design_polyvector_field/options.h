// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// design_polyvector_field: the options, their --help text, and the parsing of
// the command line (stage 1). Numbers are read with the package's strict,
// locale-independent parsers: "0x4", " 4" or "4abc" are refused.

#ifndef PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_OPTIONS_H
#define PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_OPTIONS_H

#include "common.h"

#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Smoothness_weights.h>
#include <CGAL/Polyvector_fields/planarize_quad_mesh.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>

#include <cstdlib>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>
#include <string>

namespace pvf_cli {

const char* usage =
  "usage: design_polyvector_field [options]\n"
  "input:\n"
  "  --mesh FILE              mesh (.off, .obj, .ply, .stl); default: the bundled inspired_mesh.obj.\n"
  "                           Polygon faces are triangulated and polygon soups repaired (duplicate\n"
  "                           points merged, duplicate and degenerate faces removed, faces reoriented,\n"
  "                           non-manifold vertices split); the summary says what changed\n"
  "  --no-repair              refuse a mesh that needs a repair, with the reason\n"
  "  --max-input-size MB      refuse input files larger than MB mebibytes (default 1024)\n"
  "field:\n"
  "  --degree N               number of vectors per face, 1..32 (default 4)\n"
  "  --sign-symmetric         vectors come in pairs {u, -u} (N even): frame fields, N-RoSy of even N\n"
  "  --smoothness-weights uniform|harmonic  weight of each edge in the smoothness energy: 1 (the\n"
  "                           paper's, default) or 3|e|^2/(A_f+A_g), which follows the geometry, not\n"
  "                           the density of the triangulation\n"
  "  --solver auto|direct|amg the sparse solver: 'direct' (CHOLMOD when found, else Eigen's\n"
  "                           SimplicialLDLT), 'amg' (conjugate gradient with multigrid, linear\n"
  "                           time, fields within 1e-8 of the direct solver's), or 'auto' (default):\n"
  "                           direct below 8,000 unknowns per system, multigrid above\n"
  "constraints (face ids are 0-based positions in the mesh file):\n"
  "  --constraints FILE       constraint file: 'face_id x y z [x y z ...]' per line, '#' comments\n"
  "  --dmat-b FILE --dmat-bc FILE   libigl constraints: face ids (b) and vectors (bc)\n"
  "  --soft WEIGHT            make every constraint soft with this weight, in [1e-8, 1e8]\n"
  "  --sharp-edges DEGREES    partial constraints along edges whose dihedral angle exceeds DEGREES;\n"
  "                           with --parametrize these edges also lie on integer iso-lines, so they\n"
  "                           become quad edges (default with --parametrize and --mesh: 40)\n"
  "  --no-sharp-edges         no sharp edges (with --parametrize: a smooth surface's creases are free)\n"
  "  --free-boundary          with --parametrize: the boundary is free, as the paper's (default without\n"
  "                           --mesh); by default the field follows the boundary and the map puts it\n"
  "                           on integer iso-lines, so the quads cover the surface up to its border\n"
  "  --random-constraints K   full constraints with random vectors on K random faces (see --seed)\n"
  "  --seed S                 seed of --random-constraints (default 1)\n"
  "frame fields (imply --degree 4 --sign-symmetric):\n"
  "  --curvature-constraints PERCENT  constrain PERCENT % of the faces, the most anisotropic ones\n"
  "                           spread over the surface, to their principal curvature directions\n"
  "  --angle-bound DEGREES    optimise the field so that u and v make at least DEGREES (0, 90]\n"
  "  --conjugate              optimise the field to be conjugate (planar-quad remeshing)\n"
  "  --orthogonality W        with --conjugate: weight W in [0, 1e30] pulling the field towards a cross field\n"
  "  --iterations K           maximum number of frame-field iterations (default 200 / 50, 100 with\n"
  "                           --paper-stopping-rule)\n"
  "  --tolerance T            with --conjugate: stop when the mean normalised deviation from conjugacy\n"
  "                           |u^T S v| / (|u| |v| max|k|) of the free faces, weighted by |k1 k2|, is at most T\n"
  "                           (default 5e-3); with --angle-bound: how far, in degrees, the iterations may\n"
  "                           stop below the bound before the free faces are projected onto it (default 0.5)\n"
  "  --max-lambda L           with --conjugate: cap of the weight lambda of the global step (default 1e4)\n"
  "  --paper-stopping-rule    with --conjugate: the paper's rule, sum |u^T S v| < T on the unit-size\n"
  "                           field (default T 1e-4), lambda unbounded\n"
  "parametrization (a seamless integer-grid map guided by the frame field; implies a frame field):\n"
  "  --parametrize            compute the map; one unit of uv is one quad of side about --edge-length\n"
  "  --edge-length H          the quad size in mesh units, > 0 (default: the mean edge length)\n"
  "  --quads N                about N quads: the quad size is sqrt(surface area / N) (instead of\n"
  "                           --edge-length)\n"
  "  --max-deviation F        every input vertex and face centroid within F bounding-box diagonals\n"
  "                           of the extracted quads, before --planarize (default 0.009 with the\n"
  "                           default quad size, which is made finer, by sqrt(2) up to 4 times,\n"
  "                           until it is, or until finer quads come no closer (one size in vain, two\n"
  "                           in a row on a mesh of one component); none with --edge-length or\n"
  "                           --quads, unless given); at the last size, a component still farther\n"
  "                           gets its triangles split into quads\n"
  "  --singularity-separation F  singularities of the field closer than F quads are cancelled\n"
  "                           (opposite indices), merged (into one vertex of valence 3 to 6) or moved\n"
  "                           apart, since two of them on one integer point fold the map over\n"
  "                           (default 1; 0 keeps every singularity of the field)\n"
  "  --out-param FILE.obj     write the map as OBJ with one texture coordinate per corner (implies\n"
  "                           --parametrize; default with --parametrize: output/<mesh name>.param.obj)\n"
  "quad meshes (from the map; imply --parametrize):\n"
  "  --quad-mesh FILE         write the quad mesh of the map's integer iso-lines (.off or .obj); with\n"
  "                           --out-vtk, also <vtk name>.quads.vtk with the planarity of each quad;\n"
  "                           with the default quad size, on a mesh of one component, where the\n"
  "                           quads cannot fill the map's fold-overs, the size is made finer as for\n"
  "                           --max-deviation\n"
  "  --planarize [T]          move the quad vertices until every quad is planar to T (default 0.01,\n"
  "                           the paper's 1%: diagonal distance over mean diagonal length), keeping\n"
  "                           them close to the surface, the border and the creases on them\n"
  "  --max-surface-distance F with --planarize: a vertex may move at most F mean quad edges away\n"
  "                           from the surface, and the surface at most F farther from the quads\n"
  "                           than from the extracted ones (default 0.05); a planarization that\n"
  "                           needs more is reported and the quad mesh is written as extracted\n"
  "  --gauss-newton-steps K   with --planarize: at most K steps of the second method, which runs\n"
  "                           when the local-global iterations fail (default 50; 0: none, the\n"
  "                           local-global failure is reported at once)\n"
  "output (default when none of the first five is given: output/<mesh name>.rawfield, .sings and .vtk):\n"
  "  --out-field FILE         write the field (.rawfield: N F, then 3N numbers per face)\n"
  "  --out-singularities FILE write the singularities (.sings: N count, then 'vertex numerator')\n"
  "  --out-vtk FILE           write a legacy VTK file for ParaView\n"
  "  --out-mesh FILE          write the (repaired) triangle mesh the outputs refer to, as OFF\n"
  "  --out-html FILE.html     write a self-contained web page (works offline) that shows the surface,\n"
  "                           the field, the singularities, the constrained faces and, with\n"
  "                           --quad-mesh, the quads coloured by planarity; it copies three.js from\n"
  "                           Debian's libjs-three (/usr/share/javascript/three) into the page\n"
  "  --out-ply FILE.ply       with --quad-mesh: write the quad mesh as PLY with each face's planarity\n"
  "                           (property quality) and its colour (blue planar to red worst), for MeshLab\n"
  "  --help                   print this help\n"
  "Without --mesh: the bundled <data>/inspired_mesh.obj and, unless other constraints are given,\n"
  "its 84 constraints (--dmat-b/--dmat-bc), as a frame field (--degree 4 --sign-symmetric).\n"
  "Exit status: 0 on success, 2 for a bad command line, 1 for bad input or a failure; on failure\n"
  "no output file is written.\n";

// The crease angle of a user's mesh with --parametrize: the dihedral angle
// above which an edge is sharp (QuadWild's and Instant Meshes' defaults are
// of the same order).
constexpr double default_sharp_degrees = 40;

struct Options
{
  std::string mesh;
  bool repair = true;
  std::size_t max_input_bytes = std::size_t(1024) << 20;
  std::size_t degree = 4;
  bool sign_symmetric = false;
  PVF::Smoothness_weights weights = PVF::Smoothness_weights::UNIFORM;
  std::size_t amg_threshold = PVF::Default_sparse_solver::default_amg_threshold;  // --solver
  std::string constraints, dmat_b, dmat_bc;
  double soft_weight = 0;  // 0: hard
  double sharp_degrees = -1;  // < 0: no sharp-edge constraints
  bool no_sharp_edges = false;      // --no-sharp-edges
  bool free_boundary = false;       // --free-boundary
  bool boundary_alignment = false;  // the border edges are features (set by the parser)
  std::size_t random_constraints = 0;
  unsigned seed = 1;
  double curvature_percent = -1;  // < 0: none
  double angle_bound_degrees = -1;  // < 0: none
  bool conjugate = false;
  double orthogonality = 0;
  std::size_t iterations = 0;  // 0: the algorithm's default
  double tolerance = 0;        // 0: the stopping rule's default
  double max_lambda = 0;       // 0: the stopping rule's default
  bool paper_stopping_rule = false;
  bool parametrize = false;
  double edge_length = 0;  // 0: the default, the mean edge length
  std::size_t quads = 0;   // --quads N: the edge length from the area; 0: not given
  double singularity_separation = 1;  // in quads
  double max_deviation = -1;  // --max-deviation, in bounding-box diagonals; < 0: not given
  std::string out_field, out_singularities, out_vtk, out_mesh, out_param, out_quads, out_quads_vtk;
  std::string out_html, out_ply;  // --out-html, --out-ply
  double planarity_threshold = 0;  // 0: no planarization
  // --max-surface-distance, in mean quad edges; the function's own default
  double max_surface_distance = PVF::internal::default_distance_fraction;
  // --gauss-newton-steps; the function's own default
  std::size_t gauss_newton_steps = PVF::internal::Planarization_parameters().gauss_newton_steps;
  bool default_outputs = false;  // output/<mesh name>.*, the folder made if needed

  bool frame_field() const { return curvature_percent >= 0 || angle_bound_degrees >= 0 || conjugate || parametrize; }
  std::size_t vectors_per_constraint() const { return sign_symmetric ? degree / 2 : degree; }
};


class Command_line
{
public:
  Command_line(int argc, char** argv) : m_argc(argc), m_argv(argv) {}

  bool next(std::string& flag)
  {
    if(++m_i >= m_argc)
      return false;
    flag = m_argv[m_i];
    if(flag.rfind("--", 0) == 0 && flag != "--help" && !m_seen.insert(flag).second)
      throw Failure(flag + " is given twice", 2);
    m_flag = flag;
    return true;
  }

  std::string text(const char* what = "a file name")
  {
    if(m_i + 1 >= m_argc)
      throw Failure(m_flag + " expects " + what, 2);
    const std::string value = m_argv[++m_i];
    if(value.empty())
      throw Failure(m_flag + " expects " + what + ", got an empty string", 2);
    return value;
  }

  double number(double low, double high, bool low_open = false)
  {
    const std::string value = text("a number");
    double x = 0;
    const auto status = PVF::IO::internal::parse_double(value, x);
    if(status != PVF::IO::internal::Token_status::OK || !(low_open ? x > low : x >= low) || !(x <= high))
      throw Failure(m_flag + " expects a number in " + std::string(low_open ? "(" : "[") + format(low) + ", " +
                      format(high) + "], got '" + value + "'", 2);
    return x;
  }

  // A number in (low, high] if the next argument is not an option, `fallback` otherwise.
  double optional_number(double low, double high, double fallback)
  {
    if(m_i + 1 >= m_argc || std::string(m_argv[m_i + 1]).rfind("--", 0) == 0)
      return fallback;
    return number(low, high, true);
  }

  std::size_t integer(unsigned long long low, unsigned long long high)
  {
    const std::string value = text("an integer");
    unsigned long long n = 0;
    if(PVF::IO::internal::parse_integer(value, n) != PVF::IO::internal::Token_status::OK || n < low || n > high ||
       value[0] == '+')
      throw Failure(m_flag + " expects an integer in " + std::to_string(low) + ".." + std::to_string(high) + ", got '" +
                      value + "'", 2);
    return std::size_t(n);
  }

  static std::string format(double x)
  {
    std::ostringstream s;
    s << x;
    return s.str();
  }

private:
  int m_argc;
  char** m_argv;
  int m_i = 0;
  std::string m_flag;
  std::set<std::string> m_seen;
};

Options parse_options(int argc, char** argv)
{
  Options o;
  bool separation_given = false, surface_distance_given = false, gauss_newton_given = false;
  bool degree_given = false;
  Command_line line(argc, argv);
  std::string flag;
  while(line.next(flag))
  {
    if(flag == "--help" || flag == "-h")
    {
      std::cout << usage;
      std::exit(EXIT_SUCCESS);
    }
    else if(flag == "--mesh") o.mesh = line.text();
    else if(flag == "--no-repair") o.repair = false;
    else if(flag == "--max-input-size") o.max_input_bytes = line.integer(1, 1u << 20) << 20;
    else if(flag == "--degree")
    {
      o.degree = line.integer(1, 32);
      degree_given = true;
    }
    else if(flag == "--sign-symmetric") o.sign_symmetric = true;
    else if(flag == "--constraints") o.constraints = line.text();
    else if(flag == "--dmat-b") o.dmat_b = line.text();
    else if(flag == "--dmat-bc") o.dmat_bc = line.text();
    else if(flag == "--soft") o.soft_weight = line.number(1e-8, 1e8);
    else if(flag == "--sharp-edges")
    {
      o.sharp_degrees = line.number(0, 180);
      if(o.sharp_degrees >= 180)
        throw Failure("--sharp-edges expects an angle in [0, 180) degrees", 2);
    }
    else if(flag == "--no-sharp-edges") o.no_sharp_edges = true;
    else if(flag == "--free-boundary") o.free_boundary = true;
    else if(flag == "--random-constraints") o.random_constraints = line.integer(0, 4000000000ull);
    else if(flag == "--seed") o.seed = unsigned(line.integer(0, 4294967295ull));
    else if(flag == "--curvature-constraints") o.curvature_percent = line.number(0, 100, true);
    else if(flag == "--angle-bound") o.angle_bound_degrees = line.number(0, 90, true);
    else if(flag == "--conjugate") o.conjugate = true;
    else if(flag == "--orthogonality") o.orthogonality = line.number(0, 1e30);
    else if(flag == "--iterations") o.iterations = line.integer(1, 1000000);
    else if(flag == "--tolerance") o.tolerance = line.number(1e-300, 1e300);
    else if(flag == "--max-lambda") o.max_lambda = line.number(1e-300, 1e300);
    else if(flag == "--paper-stopping-rule") o.paper_stopping_rule = true;
    else if(flag == "--smoothness-weights")
    {
      const std::string kind = line.text();
      if(kind == "uniform") o.weights = PVF::Smoothness_weights::UNIFORM;
      else if(kind == "harmonic") o.weights = PVF::Smoothness_weights::HARMONIC;
      else throw Failure("--smoothness-weights expects 'uniform' or 'harmonic', not '" + kind + "'", 2);
    }
    else if(flag == "--solver")
    {
      const std::string kind = line.text();
      if(kind == "auto") o.amg_threshold = PVF::Default_sparse_solver::default_amg_threshold;
      else if(kind == "direct") o.amg_threshold = std::numeric_limits<std::size_t>::max();
      else if(kind == "amg") o.amg_threshold = 0;
      else throw Failure("--solver expects 'auto', 'direct' or 'amg', not '" + kind + "'", 2);
    }
    else if(flag == "--out-field") o.out_field = line.text();
    else if(flag == "--out-singularities") o.out_singularities = line.text();
    else if(flag == "--out-vtk") o.out_vtk = line.text();
    else if(flag == "--out-mesh") o.out_mesh = line.text();
    else if(flag == "--out-html") o.out_html = line.text();
    else if(flag == "--out-ply") o.out_ply = line.text();
    else if(flag == "--parametrize") o.parametrize = true;
    else if(flag == "--edge-length") o.edge_length = line.number(0, 1e300, true);
    else if(flag == "--quads") o.quads = line.integer(1, 1000000000ull);
    else if(flag == "--max-deviation") o.max_deviation = line.number(0, 1, true);
    else if(flag == "--singularity-separation")
    {
      o.singularity_separation = line.number(0, 1e6);
      separation_given = true;
    }
    else if(flag == "--out-param")
    {
      o.out_param = line.text();
      o.parametrize = true;
    }
    else if(flag == "--quad-mesh")
    {
      o.out_quads = line.text();
      o.parametrize = true;
    }
    else if(flag == "--max-surface-distance")
    {
      o.max_surface_distance = line.number(0, 1e6, true);
      surface_distance_given = true;
    }
    else if(flag == "--gauss-newton-steps")
    {
      o.gauss_newton_steps = line.integer(0, 1000000);
      gauss_newton_given = true;
    }
    else if(flag == "--planarize")
      o.planarity_threshold = line.optional_number(0, 1, 0.01);
    else
      throw Failure("unknown option '" + flag + "' (see --help)", 2);
  }
  if(o.dmat_b.empty() != o.dmat_bc.empty())
    throw Failure("--dmat-b and --dmat-bc go together", 2);
  const bool bundled = o.mesh.empty();
  if(o.no_sharp_edges && o.sharp_degrees >= 0)
    throw Failure("--sharp-edges and --no-sharp-edges contradict each other", 2);
  if(o.free_boundary && !o.parametrize)
    throw Failure("--free-boundary goes with --parametrize or --quad-mesh", 2);
  if(o.parametrize && !bundled)
  {
    // A user's mesh gets its creases and its boundary as quad edges; the
    // bundled run is the paper's, with a free boundary.
    if(o.sharp_degrees < 0 && !o.no_sharp_edges)
      o.sharp_degrees = default_sharp_degrees;
    o.boundary_alignment = !o.free_boundary;
  }
  if(bundled)
  {
    // The bundled architectural mesh, with its constraints unless others are given.
    const std::string data = PVF_DATA_DIR;
    o.mesh = data + "/inspired_mesh.obj";
    if(o.constraints.empty() && o.dmat_b.empty() && o.random_constraints == 0 && o.sharp_degrees < 0 &&
       o.curvature_percent < 0)
    {
      o.dmat_b = data + "/inspired_mesh_b.dmat";
      o.dmat_bc = data + "/inspired_mesh_bc.dmat";
    }
    if(!degree_given)
      o.sign_symmetric = true;
  }
  if(o.frame_field())
  {
    if(o.degree != 4)
      throw Failure("frame-field options need --degree 4", 2);
    o.sign_symmetric = true;
  }
  if(o.angle_bound_degrees >= 0 && o.conjugate)
    throw Failure("--angle-bound and --conjugate are two different optimisations: choose one", 2);
  if(o.orthogonality > 0 && !o.conjugate)
    throw Failure("--orthogonality goes with --conjugate", 2);
  if(o.tolerance > 0 && !o.conjugate && o.angle_bound_degrees < 0)
    throw Failure("--tolerance goes with --conjugate or --angle-bound", 2);
  if((o.max_lambda > 0 || o.paper_stopping_rule) && !o.conjugate)
    throw Failure("--max-lambda and --paper-stopping-rule go with --conjugate", 2);
  if(o.sign_symmetric && o.degree % 2 != 0)
    throw Failure("--sign-symmetric needs an even --degree", 2);
  if(o.edge_length > 0 && !o.parametrize)
    throw Failure("--edge-length goes with --parametrize", 2);
  if(o.quads > 0 && !o.parametrize)
    throw Failure("--quads goes with --parametrize or --quad-mesh", 2);
  if(o.max_deviation >= 0 && o.out_quads.empty())
    throw Failure("--max-deviation goes with --quad-mesh", 2);
  if(o.quads > 0 && o.edge_length > 0)
    throw Failure("--quads and --edge-length both set the quad size: give one", 2);
  if(separation_given && !o.parametrize)
    throw Failure("--singularity-separation goes with --parametrize or --quad-mesh", 2);
  if(surface_distance_given && o.planarity_threshold <= 0)
    throw Failure("--max-surface-distance goes with --planarize", 2);
  if(gauss_newton_given && o.planarity_threshold <= 0)
    throw Failure("--gauss-newton-steps goes with --planarize", 2);
  if(o.planarity_threshold > 0 && o.out_quads.empty())
    throw Failure("--planarize goes with --quad-mesh", 2);
  if(!o.out_ply.empty() && o.out_quads.empty())
    throw Failure("--out-ply writes the quad mesh with its planarity: it goes with --quad-mesh", 2);
  if(!o.out_quads.empty())
  {
    const std::string extension = fs::path(o.out_quads).extension().string();
    if(extension != ".off" && extension != ".obj")
      throw Failure("--quad-mesh '" + o.out_quads + "': the file name must end in .off or .obj", 2);
  }
  // The field's default outputs unless one of them (or the page) is named
  // (--out-param, --quad-mesh and --out-ply come in addition).
  if(o.out_field.empty() && o.out_singularities.empty() && o.out_vtk.empty() && o.out_mesh.empty() && o.out_html.empty())
  {
    const std::string stem = "output/" + fs::path(o.mesh).stem().string();
    o.out_field = stem + ".rawfield";
    o.out_singularities = stem + ".sings";
    o.out_vtk = stem + ".vtk";
    if(o.parametrize && o.out_param.empty())
      o.out_param = stem + ".param.obj";
    o.default_outputs = true;
  }
  if(!o.out_quads.empty() && !o.out_vtk.empty())
    o.out_quads_vtk = (fs::path(o.out_vtk).parent_path() / fs::path(o.out_vtk).stem()).string() + ".quads.vtk";
  return o;
}

} // namespace pvf_cli

#endif // PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_OPTIONS_H
