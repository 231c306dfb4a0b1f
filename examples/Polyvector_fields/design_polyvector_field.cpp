// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// design_polyvector_field: the command-line designer.
//
// Reads a mesh and constraints, designs the smoothest N-PolyVector field, and
// writes the field (.rawfield), its singularities (.sings) and a VTK file for
// ParaView. Frame fields (N = 4, sign-symmetric) can then be optimised to
// bound their angles or to be conjugate (paper Section 4), and guide a
// seamless integer-grid map (--parametrize, written as an OBJ file with one
// texture coordinate per corner). With no argument it
// designs a frame field on the bundled architectural mesh from its 84 bundled
// constraints and writes output/inspired_mesh.{rawfield,sings,vtk}. Run with
// --help for the options.
//
// A polygon mesh or a polygon soup is repaired into a triangle mesh first (see
// IO::read_triangle_mesh()), and the summary says what changed; --no-repair
// refuses such a mesh instead. Errors are reported on one line of standard
// error with a non-zero exit status: 2 for a bad command line, 1 otherwise.
// Outputs are written all or none: every destination is checked before the
// work starts, and the files are published only once every stage succeeded.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/IO/integer_grid_map.h>
#include <CGAL/Polyvector_fields/IO/quad_mesh.h>
#include <CGAL/Polyvector_fields/IO/rawfield.h>
#include <CGAL/Polyvector_fields/IO/read_triangle_mesh.h>
#include <CGAL/Polyvector_fields/IO/singularities.h>
#include <CGAL/Polyvector_fields/IO/vtk.h>
#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/Smoothness_weights.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/angle_bounded_frame_field.h>
#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>
#include <CGAL/Polyvector_fields/conjugate_frame_field.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/frame_field_measures.h>
#include <CGAL/Polyvector_fields/extract_quad_mesh.h>
#include <CGAL/Polyvector_fields/compute_integer_grid_map.h>
#include <CGAL/Polyvector_fields/planarize_quad_mesh.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>
#include <CGAL/Polyvector_fields/select_curvature_constraints.h>
#include <CGAL/Polyvector_fields/smoothness_energy.h>

#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef PVF_DATA_DIR
#define PVF_DATA_DIR "data"
#endif

namespace PVF = CGAL::Polyvector_fields;
namespace fs = std::filesystem;

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index Face;
typedef Mesh::Vertex_index Vertex;
typedef PVF::Face_constraint<Face, Vector> Constraint;
typedef std::complex<double> Complex;
typedef PVF::Principal_curvatures<Vector> Curvatures;
typedef PVF::Tangent_bundle<Mesh> Bundle;

namespace {

// A failure: one line on standard error, then a non-zero exit.
struct Failure : std::runtime_error
{
  int status;
  Failure(const std::string& message, int exit_status = 1) : std::runtime_error(message), status(exit_status) {}
};

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
  "  --sharp-edges DEGREES    partial constraints along edges whose dihedral angle exceeds DEGREES\n"
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
  "                           (default 5e-3); with --angle-bound: the angle in degrees that a face may\n"
  "                           stay below the bound (default 0.5)\n"
  "  --max-lambda L           with --conjugate: cap of the weight lambda of the global step (default 1e4)\n"
  "  --paper-stopping-rule    with --conjugate: the paper's rule, sum |u^T S v| < T on the unit-size\n"
  "                           field (default T 1e-4), lambda unbounded\n"
  "parametrization (a seamless integer-grid map guided by the frame field; implies a frame field):\n"
  "  --parametrize            compute the map; one unit of uv is one quad of side about --edge-length\n"
  "  --edge-length H          the quad size in mesh units, > 0 (default: the mean edge length)\n"
  "  --out-param FILE.obj     write the map as OBJ with one texture coordinate per corner (implies\n"
  "                           --parametrize; default with --parametrize: output/<mesh name>.param.obj)\n"
  "quad meshes (from the map; imply --parametrize):\n"
  "  --quad-mesh FILE         write the quad mesh of the map's integer iso-lines (.off or .obj); with\n"
  "                           --out-vtk, also <vtk name>.quads.vtk with the planarity of each quad\n"
  "  --planarize [T]          move the quad vertices until every quad is planar to T (default 0.01,\n"
  "                           the paper's 1%: diagonal distance over mean diagonal length), keeping\n"
  "                           them close to the surface\n"
  "output (default when none is given: output/<mesh name>.rawfield, .sings and .vtk):\n"
  "  --out-field FILE         write the field (.rawfield: N F, then 3N numbers per face)\n"
  "  --out-singularities FILE write the singularities (.sings: N count, then 'vertex numerator')\n"
  "  --out-vtk FILE           write a legacy VTK file for ParaView\n"
  "  --out-mesh FILE          write the (repaired) triangle mesh the outputs refer to, as OFF\n"
  "  --help                   print this help\n"
  "Without --mesh: the bundled <data>/inspired_mesh.obj and, unless other constraints are given,\n"
  "its 84 constraints (--dmat-b/--dmat-bc), as a frame field (--degree 4 --sign-symmetric).\n"
  "Exit status: 0 on success, 2 for a bad command line, 1 for bad input or a failure; on failure\n"
  "no output file is written.\n";

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
  std::string out_field, out_singularities, out_vtk, out_mesh, out_param, out_quads, out_quads_vtk;
  double planarity_threshold = 0;  // 0: no planarization
  bool default_outputs = false;  // output/<mesh name>.*, the folder made if needed

  bool frame_field() const { return curvature_percent >= 0 || angle_bound_degrees >= 0 || conjugate || parametrize; }
  std::size_t vectors_per_constraint() const { return sign_symmetric ? degree / 2 : degree; }
};

// ---------------------------------------------------------------------------
// Stage 1: the command line. Numbers are read with the package's strict,
// locale-independent parsers: "0x4", " 4" or "4abc" are refused.
// ---------------------------------------------------------------------------
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
    else if(flag == "--parametrize") o.parametrize = true;
    else if(flag == "--edge-length") o.edge_length = line.number(0, 1e300, true);
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
    else if(flag == "--planarize")
      o.planarity_threshold = line.optional_number(0, 1, 0.01);
    else
      throw Failure("unknown option '" + flag + "' (see --help)", 2);
  }
  if(o.dmat_b.empty() != o.dmat_bc.empty())
    throw Failure("--dmat-b and --dmat-bc go together", 2);
  if(o.mesh.empty())
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
  if(o.planarity_threshold > 0 && o.out_quads.empty())
    throw Failure("--planarize goes with --quad-mesh", 2);
  if(!o.out_quads.empty())
  {
    const std::string extension = fs::path(o.out_quads).extension().string();
    if(extension != ".off" && extension != ".obj")
      throw Failure("--quad-mesh '" + o.out_quads + "': the file name must end in .off or .obj", 2);
  }
  // The field's default outputs unless one of them is named (--out-param and
  // --quad-mesh come in addition).
  if(o.out_field.empty() && o.out_singularities.empty() && o.out_vtk.empty() && o.out_mesh.empty())
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

void check(PVF::Error_code code, const std::string& what, const std::string& detail = std::string())
{
  if(code != PVF::Error_code::SUCCESS)
    throw Failure(what + ": " + (detail.empty() ? PVF::get_error_message(code) : detail));
}

// ---------------------------------------------------------------------------
// Stage 2: the outputs, checked before any work, written all or none.
// ---------------------------------------------------------------------------
// An output stream buffer on a C file, for the temporary files of
// Output_files: "wbx" (refuse an existing file) has no iostream equivalent.
class File_buffer : public std::streambuf
{
public:
  explicit File_buffer(std::FILE* file) : m_file(file), m_buffer(std::size_t(1) << 20)
  {
    setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
  }
  ~File_buffer() override { close(); }

  // Writes what is buffered and closes the file; false if any write failed.
  bool close()
  {
    if(m_file == nullptr)
      return m_ok;
    drain();
    m_ok = (std::fflush(m_file) == 0) && m_ok;
    m_ok = (std::fclose(m_file) == 0) && m_ok;
    m_file = nullptr;
    return m_ok;
  }

protected:
  int_type overflow(int_type c) override
  {
    if(!drain())
      return traits_type::eof();
    if(!traits_type::eq_int_type(c, traits_type::eof()))
    {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char* data, std::streamsize n) override
  {
    if(n < std::streamsize(m_buffer.size()))
      return std::streambuf::xsputn(data, n);
    // A large block (a whole formatted file): straight to the file.
    if(!drain() || std::fwrite(data, 1, std::size_t(n), m_file) != std::size_t(n))
      return m_ok = false, 0;
    return n;
  }
  int sync() override { return drain() ? 0 : -1; }

private:
  bool drain()
  {
    const std::size_t n = std::size_t(pptr() - pbase());
    if(m_file == nullptr || (n > 0 && std::fwrite(pbase(), 1, n, m_file) != n))
      m_ok = false;
    setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
    return m_ok;
  }

  std::FILE* m_file;
  std::vector<char> m_buffer;
  bool m_ok = true;
};

class Output_files
{
public:
  // Checks every destination: a distinct file (not an input, not another
  // output, not a directory) in an existing, writable folder.
  Output_files(const Options& o)
  {
    std::map<std::string, std::string> claimed;  // canonical path -> what claims it
    for(const std::string* input : { &o.mesh, &o.constraints, &o.dmat_b, &o.dmat_bc })
      if(!input->empty())
        claimed[canonical(*input)] = "the input '" + *input + "'";
    const std::pair<const char*, const std::string*> outputs[] = {
      { "--out-field", &o.out_field }, { "--out-singularities", &o.out_singularities },
      { "--out-vtk", &o.out_vtk }, { "--out-mesh", &o.out_mesh }, { "--out-param", &o.out_param },
      { "--quad-mesh", &o.out_quads }, { "the quad-mesh VTK file of --quad-mesh and --out-vtk", &o.out_quads_vtk } };
    for(const auto& output : outputs)
    {
      const std::string& path = *output.second;
      if(path.empty())
        continue;
      const std::string key = canonical(path);
      const auto previous = claimed.find(key);
      if(previous != claimed.end())
        throw Failure(std::string(output.first) + " '" + path + "' is the same file as " + previous->second, 2);
      claimed[key] = std::string(output.first) + " '" + path + "'";
      std::error_code ec;
      if(fs::is_directory(path, ec))
        throw Failure(std::string(output.first) + " '" + path + "' is a directory", 2);
      fs::path folder = fs::path(path).parent_path();
      if(folder.empty())
        folder = ".";
      if(!(o.default_outputs && folder == "output"))
      {
        if(!fs::exists(folder, ec))
          throw Failure(std::string(output.first) + " '" + path + "': the folder '" + folder.string() + "' does not exist", 2);
        if(!fs::is_directory(folder, ec))
          throw Failure(std::string(output.first) + " '" + path + "': '" + folder.string() + "' is not a folder", 2);
        if(::access(folder.c_str(), W_OK | X_OK) != 0)
          throw Failure(std::string(output.first) + " '" + path + "': the folder '" + folder.string() + "' is not writable", 2);
      }
      m_destinations.push_back(path);
    }
  }

  // Creates the default folder output/ if the outputs go there by default.
  void prepare(bool create_default_folder)
  {
    if(!create_default_folder)
      return;
    std::error_code ec;
    fs::create_directories("output", ec);
    if(ec)
      throw Failure("cannot create the folder output/: " + ec.message());
  }

  // Writes the content of `path` through `write` (which returns an
  // Error_code) into a fresh temporary file beside it, streamed: no copy of a
  // large output is kept in memory. publish() renames them all into place.
  template <typename Write>
  void write(const std::string& path, const Write& write, const std::string& what)
  {
    const std::string temporary = sibling(path, ".tmp-");
    std::FILE* file = std::fopen(temporary.c_str(), "wbx");
    if(file == nullptr)
      throw Failure("cannot write '" + path + "': " + std::strerror(errno));
    m_temporaries[path] = temporary;
    File_buffer buffer(file);
    std::ostream stream(&buffer);
    const PVF::Error_code code = write(stream);
    stream.flush();
    const bool ok = buffer.close() && bool(stream);
    check(code, "writing " + what);
    if(!ok)
      throw Failure("cannot write '" + path + "': " + std::strerror(errno));
  }

  // Renames every temporary file over its destination. If any step fails,
  // the destinations are as they were before (replaced files are restored)
  // and no temporary remains.
  void publish()
  {
    for(const std::string& path : m_destinations)
      if(m_temporaries.count(path) == 0)
        throw Failure("internal error: '" + path + "' was not written");
    // Existing destinations are moved aside first, so that they can be restored.
    std::vector<std::pair<std::string, std::string> > backups;  // destination, backup
    std::vector<std::string> placed;
    auto undo = [&]() {
      std::error_code ec;
      for(const std::string& path : placed)
        fs::remove(path, ec);
      for(const auto& b : backups)
        fs::rename(b.second, b.first, ec);
    };
    for(std::size_t i = 0; i < m_destinations.size(); ++i)
    {
      const std::string& path = m_destinations[i];
      std::error_code ec;
      if(fs::exists(path, ec))
      {
        const std::string backup = sibling(path, ".old-");
        fs::rename(path, backup, ec);
        if(ec)
        {
          undo();
          throw Failure("cannot replace '" + path + "': " + ec.message());
        }
        backups.emplace_back(path, backup);
      }
      fs::rename(m_temporaries.at(path), path, ec);
      if(ec)
      {
        undo();
        throw Failure("cannot write '" + path + "': " + ec.message());
      }
      placed.push_back(path);
    }
    m_temporaries.clear();
    std::error_code ec;
    for(const auto& b : backups)
      fs::remove(b.second, ec);
  }

  ~Output_files()
  {
    std::error_code ec;
    for(const auto& t : m_temporaries)
      fs::remove(t.second, ec);
  }

  const std::vector<std::string>& destinations() const { return m_destinations; }

private:
  static std::string canonical(const std::string& path)
  {
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? path : p.string();
  }

  // A fresh name beside `path`: .<name><tag><pid>-<counter>.
  static std::string sibling(const std::string& path, const char* tag)
  {
    static unsigned counter = 0;
    fs::path p(path);
    p.replace_filename("." + p.filename().string() + tag + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    return p.string();
  }

  std::vector<std::string> m_destinations;
  std::map<std::string, std::string> m_temporaries;  // destination -> its temporary file
};

struct Stopwatch
{
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::map<std::string, double> times;
  void lap(const std::string& stage)
  {
    const auto now = std::chrono::steady_clock::now();
    times[stage] += std::chrono::duration<double>(now - start).count();
    start = now;
  }
};

// ---------------------------------------------------------------------------
// Stage 3: the mesh, repaired unless --no-repair.
// ---------------------------------------------------------------------------
struct Input_mesh
{
  Mesh tm;
  PVF::IO::Mesh_repair_report report;
  std::vector<std::vector<Face> > faces_of_file_face;  // file face id -> faces of tm
};

Input_mesh load_mesh(const Options& o)
{
  Input_mesh input;
  std::string message;
  const PVF::Error_code code = PVF::IO::read_triangle_mesh(
    o.mesh, input.tm, input.report,
    PVF::parameters::repair(o.repair, PVF::parameters::maximum_file_size(o.max_input_bytes,
                                                                          PVF::parameters::error_message(message))));
  if(code != PVF::Error_code::SUCCESS)
  {
    const bool repairable = code == PVF::Error_code::NON_TRIANGLE_FACE || code == PVF::Error_code::DUPLICATE_FACE ||
                            code == PVF::Error_code::NON_MANIFOLD_MESH ||
                            (code == PVF::Error_code::DEGENERATE_FACE && message.find("repeats") != std::string::npos);
    throw Failure("mesh '" + o.mesh + "': " + message +
                  (!o.repair && repairable ? " (without --no-repair it would be repaired)" : ""));
  }
  input.faces_of_file_face.resize(input.report.file_faces);
  std::size_t i = 0;
  for(Face f : faces(input.tm))
    input.faces_of_file_face[input.report.source_face[i++]].push_back(f);
  return input;
}

// ---------------------------------------------------------------------------
// Stage 4: the constraints.
// ---------------------------------------------------------------------------

// Partial constraints along sharp edges: each face beside an edge whose
// dihedral angle (between the face normals) exceeds the threshold gets the
// edge's unit direction; a face with more sharp edges than its constraint can
// hold keeps the sharpest ones. Faces already constrained are left alone.
std::vector<Constraint> sharp_edge_constraints(const Mesh& tm, double degrees, std::size_t capacity,
                                               const std::set<Face>& already_constrained)
{
  const double threshold = degrees * CGAL_PI / 180.0;
  std::map<Face, std::vector<std::pair<double, Vector> > > edges_of_face;
  for(auto e : edges(tm))
  {
    const auto h = halfedge(e, tm);
    if(CGAL::is_border_edge(h, tm))
      continue;
    const Face f = face(h, tm), g = face(opposite(h, tm), tm);
    PVF::Face_frame a, b;
    PVF::face_frame(f, tm, a);
    PVF::face_frame(g, tm, b);
    const double cosine = a.normal[0] * b.normal[0] + a.normal[1] * b.normal[1] + a.normal[2] * b.normal[2];
    const double angle = std::acos((std::max)(-1.0, (std::min)(1.0, cosine)));
    if(angle <= threshold)
      continue;
    // The direction, scaled first so that its squared length cannot overflow.
    const std::array<double, 3> d = PVF::internal::scaled_difference(PVF::internal::to_array(tm.point(target(h, tm))),
                                                                     PVF::internal::to_array(tm.point(source(h, tm))));
    const double length = std::sqrt(PVF::internal::dot(d, d));
    const Vector direction(d[0] / length, d[1] / length, d[2] / length);
    edges_of_face[f].emplace_back(angle, direction);
    edges_of_face[g].emplace_back(angle, direction);
  }
  std::vector<Constraint> constraints;
  for(auto& entry : edges_of_face)
  {
    if(already_constrained.count(entry.first))
      continue;
    auto& list = entry.second;
    std::sort(list.begin(), list.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    Constraint c{ entry.first, {} };
    for(std::size_t i = 0; i < list.size() && i < capacity; ++i)
      c.vectors.push_back(list[i].second);
    constraints.push_back(c);
  }
  return constraints;
}

struct Constraint_set
{
  std::vector<Constraint> list;
  std::size_t from_files = 0, random = 0, sharp = 0, from_curvature = 0;
  std::string note;  // said in the summary

  std::set<Face> faces() const
  {
    std::set<Face> s;
    for(const Constraint& c : list)
      s.insert(c.face);
    return s;
  }
};

// The constraints of the files, on the faces of the file: a face that the
// repair triangulated passes its constraint to each of its triangles.
void add_file_constraints(const Options& o, const Input_mesh& input, Constraint_set& set)
{
  typedef PVF::Face_constraint<std::size_t, Vector> Id_constraint;
  std::vector<Id_constraint> by_id;
  std::string message;
  const auto np = PVF::parameters::expected_degree(
    o.vectors_per_constraint(),
    PVF::parameters::maximum_file_size(o.max_input_bytes, PVF::parameters::error_message(message)));
  if(!o.constraints.empty())
    check(PVF::IO::read_constraints_by_id(o.constraints, input.report.file_faces, by_id, np),
          "constraints '" + o.constraints + "'", message);
  if(!o.dmat_b.empty())
  {
    std::vector<Id_constraint> dmat;
    check(PVF::IO::read_dmat_constraints_by_id(o.dmat_b, o.dmat_bc, input.report.file_faces, dmat, np),
          "constraints '" + o.dmat_b + "', '" + o.dmat_bc + "'", message);
    std::set<std::size_t> ids;
    for(const Id_constraint& c : by_id)
      ids.insert(c.face);
    for(const Id_constraint& c : dmat)
      if(ids.count(c.face))
        throw Failure("constraints: face " + std::to_string(c.face) + " is constrained by both --constraints and --dmat-b");
    by_id.insert(by_id.end(), dmat.begin(), dmat.end());
  }
  for(const Id_constraint& c : by_id)
  {
    const auto& targets = input.faces_of_file_face[c.face];
    if(targets.empty())
      throw Failure("constraint on face " + std::to_string(c.face) +
                    ": the repair removed that face (a duplicate or degenerate face)");
    for(Face f : targets)
      set.list.push_back(Constraint{ f, c.vectors, c.weight });
  }
  set.from_files = set.list.size();
}

void add_random_constraints(const Options& o, const Mesh& tm, Constraint_set& set)
{
  if(o.random_constraints == 0)
    return;
  if(o.random_constraints > num_faces(tm))
    throw Failure("--random-constraints " + std::to_string(o.random_constraints) + " asks for more faces than the mesh's " +
                  std::to_string(num_faces(tm)));
  std::mt19937 rng(o.seed);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  std::set<Face> constrained = set.faces();
  const std::vector<Face> all(faces(tm).begin(), faces(tm).end());
  while(set.random < o.random_constraints && constrained.size() < all.size())
  {
    const Face f = all[rng() % all.size()];
    if(!constrained.insert(f).second)
      continue;
    Constraint c{ f, {} };
    for(std::size_t k = 0; k < o.vectors_per_constraint(); ++k)
      c.vectors.push_back(Vector(coordinate(rng), coordinate(rng), coordinate(rng)));
    set.list.push_back(c);
    ++set.random;
  }
}

// Curvature, estimated once when a result needs it.
struct Curvature
{
  bool estimated = false;
  PVF::Error_code status = PVF::Error_code::SUCCESS;
  Mesh::Property_map<Face, Curvatures> map;
  std::size_t fallback_vertices = 0;  // vertices no jet fit determined (normal-variation estimate)
};

Curvature& estimate_curvature(Mesh& tm, const Bundle& bundle, Curvature& curvature)
{
  if(!curvature.estimated)
  {
    curvature.map = tm.add_property_map<Face, Curvatures>("f:pvf_curvatures").first;
    curvature.status = PVF::estimate_principal_curvatures(
      bundle, curvature.map, PVF::parameters::fallback_vertices(curvature.fallback_vertices));
    curvature.estimated = true;
  }
  return curvature;
}

Constraint_set gather_constraints(const Options& o, Input_mesh& input, const Bundle& bundle, Curvature& curvature,
                                  Stopwatch& clock)
{
  Constraint_set set;
  add_file_constraints(o, input, set);
  add_random_constraints(o, input.tm, set);
  if(o.sharp_degrees >= 0)
  {
    const auto sharp = sharp_edge_constraints(input.tm, o.sharp_degrees, o.vectors_per_constraint(), set.faces());
    set.sharp = sharp.size();
    set.list.insert(set.list.end(), sharp.begin(), sharp.end());
  }
  clock.lap("constraints");
  if(o.curvature_percent > 0)
  {
    check(estimate_curvature(input.tm, bundle, curvature).status, "curvature");
    clock.lap("curvature");
    std::vector<Constraint> principal;
    check(PVF::select_curvature_constraints(bundle, curvature.map, principal,
                                            PVF::parameters::constrained_fraction(o.curvature_percent / 100)),
          "curvature constraints");
    std::set<Face> constrained = set.faces();
    for(const Constraint& c : principal)
      if(constrained.insert(c.face).second)
      {
        set.list.push_back(c);
        ++set.from_curvature;
      }
    if(set.from_curvature == 0)
      set.note = "no face is anisotropic enough for a curvature constraint (|k1 - k2| / (|k1| + |k2|) >= 0.5)";
  }
  if(o.soft_weight > 0)
    for(Constraint& c : set.list)
      c.weight = o.soft_weight;
  clock.lap("constraints");
  return set;
}

// ---------------------------------------------------------------------------
// Stage 5: the field, and its optimisation for frame fields.
// ---------------------------------------------------------------------------
typedef Mesh::Property_map<Face, std::vector<Complex> > Coefficient_map;

struct Field
{
  std::optional<PVF::Polyvector_field<Bundle> > polyvector;  // designed once, then optimised in place
  Coefficient_map coefficients;  // the final field as a property map, for the writers
  PVF::Design_statistics statistics;
  PVF::Default_sparse_solver solver;  // its multigrid statistics cover every stage
  std::size_t components = 0;
  std::size_t full = 0, partial = 0;
  double smooth_energy = 0;
  std::string frame_report;
};

// The message for a refused constraint: what is wrong with which face.
std::string constraint_failure(PVF::Error_code code, const Constraint& c, const Options& o)
{
  std::ostringstream m;
  m << "constraint on face " << std::size_t(c.face) << ": ";
  if(code == PVF::Error_code::VALUE_OUT_OF_RANGE)
  {
    // The first vector whose length L has L^N outside [1e-300, 1e300].
    for(const Vector& v : c.vectors)
    {
      std::array<double, 3> w = { v.x(), v.y(), v.z() };
      const int e = PVF::internal::scale_to_unit({ &w });
      const double log10_length = std::log10(std::sqrt(PVF::internal::dot(w, w))) + e * std::log10(2.0);
      if(std::abs(double(o.degree) * log10_length) > 300)
      {
        m << "a vector of length " << std::pow(10.0, log10_length) << " is out of range for degree " << o.degree
          << " (the package needs 1e-300 <= length^" << o.degree << " <= 1e300)";
        return m.str();
      }
    }
    m << PVF::get_error_message(code);
  }
  else
    m << PVF::get_error_message(code);
  return m.str();
}

Field design_field(const Options& o, Mesh& tm, const Bundle& bundle, const Constraint_set& constraints,
                   Curvature& curvature, Stopwatch& clock)
{
  Field field;
  field.solver.set_amg_threshold(o.amg_threshold);
  PVF::Polyvector_field_designer<Mesh> designer(
    bundle, o.degree,
    PVF::parameters::sign_symmetric(o.sign_symmetric, PVF::parameters::smoothness_weights(
                                                        o.weights, CGAL::parameters::sparse_linear_solver(field.solver))));
  check(designer.status(), "degree");
  field.components = bundle.number_of_components();
  for(const Constraint& c : constraints.list)
  {
    const PVF::Error_code code = designer.add_constraint(c);
    if(code != PVF::Error_code::SUCCESS)
      throw Failure(constraint_failure(code, c, o));
    (c.vectors.size() == o.vectors_per_constraint() ? field.full : field.partial) += 1;
  }
  field.polyvector.emplace(bundle, o.degree, o.sign_symmetric);
  PVF::Polyvector_field<Bundle>& pvf = *field.polyvector;
  const PVF::Error_code solved = designer.solve(pvf);
  check(solved, "design",
        solved != PVF::Error_code::VALUE_OUT_OF_RANGE
          ? std::string()
          : "the constraint vectors' lengths are too far apart for degree " + std::to_string(o.degree) +
              ": each length L needs 1e-100 <= (L / sigma)^N <= 1e100, sigma their geometric mean");
  clock.lap("design");
  field.statistics = designer.statistics();
  // The energy before an optimisation (the summary gives both); without one,
  // analyse_field() measures the field once.
  if(o.angle_bound_degrees > 0 || o.conjugate)
    field.smooth_energy = PVF::smoothness_energy(pvf);

  std::ostringstream report;
  if(o.angle_bound_degrees > 0)
  {
    PVF::Angle_bound_result result;
    const double tolerance = (o.tolerance > 0 ? o.tolerance : 0.5) * CGAL_PI / 180;  // the library's default: 0.5 degree
    const auto np = PVF::parameters::angle_bound(
      o.angle_bound_degrees * CGAL_PI / 180,
      PVF::parameters::tolerance(tolerance, PVF::parameters::smoothness_weights(
                                              o.weights, CGAL::parameters::sparse_linear_solver(field.solver))));
    // Not reaching the bound within the iterations is reported, not fatal.
    const PVF::Error_code code = o.iterations ? PVF::design_angle_bounded_frame_field(pvf, result, np.number_of_iterations(o.iterations))
                                              : PVF::design_angle_bounded_frame_field(pvf, result, np);
    if(code != PVF::Error_code::DID_NOT_CONVERGE)
      check(code, "angle bound");
    report << "angle bound     " << o.angle_bound_degrees << " degrees (to within " << tolerance * 180 / CGAL_PI
           << "): " << (result.converged ? "converged" : "NOT converged")
           << " in " << result.iterations << " iterations; smallest angle " << result.minimum_free_angle * 180 / CGAL_PI
           << " degrees (free faces), " << result.minimum_angle * 180 / CGAL_PI << " degrees (all faces); "
           << result.factorizations << " factorizations\n";
    clock.lap("frame field");
  }
  if(o.conjugate)
  {
    check(estimate_curvature(tm, bundle, curvature).status, "curvature");
    clock.lap("curvature");
    PVF::Conjugate_field_result result;
    const PVF::Conjugacy_stopping_rule rule = o.paper_stopping_rule ? PVF::Conjugacy_stopping_rule::RESIDUAL_SUM
                                                                    : PVF::Conjugacy_stopping_rule::MEAN_DEVIATION;
    const PVF::Conjugate_field_defaults defaults = PVF::conjugate_field_defaults(rule);
    namespace P = PVF::parameters;
    const auto np = P::principal_curvature_map(
      curvature.map,
      P::orthogonality_weight(
        o.orthogonality,
        P::stopping_rule(rule, P::tolerance(o.tolerance > 0 ? o.tolerance : defaults.tolerance,
                                            P::maximum_lambda(o.max_lambda > 0 ? o.max_lambda : defaults.maximum_lambda,
                                                              P::smoothness_weights(
                                                                o.weights, CGAL::parameters::number_of_iterations(
                                                                             o.iterations ? o.iterations
                                                                                          : defaults.iterations)
                                                                             .sparse_linear_solver(field.solver)))))));
    // Not meeting the stopping rule within the iterations is reported, not fatal.
    const PVF::Error_code code = PVF::design_conjugate_frame_field(pvf, result, np);
    if(code != PVF::Error_code::DID_NOT_CONVERGE)
      check(code, "conjugate field");
    report << "conjugate       " << (result.converged ? "converged" : "NOT converged") << " in " << result.iterations
           << " iterations (orthogonality weight " << o.orthogonality << ", last lambda " << result.final_lambda
           << "); mean deviation |u^T S v| / (|u| |v| max|k|) of the free faces " << result.deviation_history.front()
           << " -> " << result.mean_deviation << "; residual sum |u^T S v| (unit-size field): "
           << result.residual_history.front() << " -> free faces " << result.free_residual << ", constrained faces "
           << result.constrained_residual << ", all faces " << result.residual << "; " << result.factorizations
           << " factorizations\n";
    if(curvature.fallback_vertices > 0)
      report << "note            the curvature of " << curvature.fallback_vertices
             << " vertices comes from the variation of the normals (no jet fit determined it)\n";
    clock.lap("frame field");
  }
  field.frame_report = report.str();
  field.coefficients = tm.add_property_map<Face, std::vector<Complex> >("f:pvf_coefficients").first;
  pvf.write_coefficients(field.coefficients);
  return field;
}

// ---------------------------------------------------------------------------
// Stage 6: what the field is: roots, singularities, energy, diagnostics.
// ---------------------------------------------------------------------------
struct Analysis
{
  Mesh::Property_map<Face, std::vector<Vector> > roots;
  std::vector<PVF::Singularity<Vertex> > singularities;
  std::vector<Vertex> undefined;
  double energy = 0;
  PVF::IO::Face_scalar_arrays face_arrays;  // for the VTK file
  std::string note;
};

Analysis analyse_field(const Options& o, Mesh& tm, const Bundle& bundle, const Field& field, Curvature& curvature,
                       Stopwatch& clock)
{
  Analysis a;
  a.roots = tm.add_property_map<Face, std::vector<Vector> >("f:pvf_roots").first;
  check(PVF::compute_field_roots(*field.polyvector, a.roots),
        "roots");
  clock.lap("roots");
  check(PVF::compute_singularities(*field.polyvector, std::back_inserter(a.singularities),
                                   std::back_inserter(a.undefined)),
        "singularities");
  clock.lap("singularities");
  a.energy = PVF::smoothness_energy(*field.polyvector);
  if(o.out_vtk.empty() || !(o.sign_symmetric && o.degree == 4))
    return a;
  // Frame-field diagnostics for the VTK file; they never fail the run.
  auto angle_map = tm.add_property_map<Face, double>("f:pvf_angle").first;
  if(PVF::compute_frame_angles(*field.polyvector, angle_map) == PVF::Error_code::SUCCESS)
  {
    std::vector<double> angles;
    for(Face f : faces(tm))
      angles.push_back(angle_map[f] * 180 / CGAL_PI);
    a.face_arrays.emplace_back("min_angle_degrees", angles);
  }
  tm.remove_property_map(angle_map);
  // The conjugacy deviation only where the curvature is already known (a
  // conjugate field, curvature constraints): a diagnostic never estimates it.
  if(o.frame_field() && curvature.estimated)
  {
    if(curvature.status != PVF::Error_code::SUCCESS)
      a.note = "the VTK file has no conjugacy_deviation: the curvature could not be estimated (" +
               std::string(PVF::get_error_message(curvature.status)) + ")";
    else
    {
      auto deviation_map = tm.add_property_map<Face, double>("f:pvf_deviation").first;
      if(PVF::compute_conjugacy_deviation(*field.polyvector, curvature.map, deviation_map) == PVF::Error_code::SUCCESS)
      {
        std::vector<double> deviation;
        for(Face f : faces(tm))
          deviation.push_back(deviation_map[f]);
        a.face_arrays.emplace_back("conjugacy_deviation", deviation);
      }
      tm.remove_property_map(deviation_map);
    }
  }
  clock.lap("diagnostics");
  return a;
}

// ---------------------------------------------------------------------------
// Stage 7: the seamless integer-grid map guided by the frame field (--parametrize).
// ---------------------------------------------------------------------------
struct Parametrization
{
  bool computed = false;
  Mesh::Property_map<Mesh::Halfedge_index, std::array<double, 2> > uv;  // at target(h) inside face(h)
  PVF::Integer_grid_map_result result;
};

Parametrization parametrize(const Options& o, Mesh& tm, const Bundle& bundle, const Field& field, Stopwatch& clock)
{
  Parametrization p;
  if(!o.parametrize)
    return p;
  p.uv = tm.add_property_map<Mesh::Halfedge_index, std::array<double, 2> >("h:pvf_uv").first;
  const PVF::Error_code code =
    o.edge_length > 0 ? PVF::compute_integer_grid_map(bundle, field.coefficients, p.uv, p.result,
                                                      PVF::parameters::target_edge_length(o.edge_length))
                      : PVF::compute_integer_grid_map(bundle, field.coefficients, p.uv, p.result);
  check(code, "parametrization");
  p.computed = true;
  clock.lap("parametrization");
  return p;
}

// ---------------------------------------------------------------------------
// Stage 8: the quad mesh of the map's integer iso-lines, planarized on request.
// ---------------------------------------------------------------------------
struct Quad_stage
{
  bool computed = false;
  Mesh quads;
  PVF::Quad_extraction_result extraction;
  PVF::Planarity_statistics before, after;
  bool planarized = false;
  PVF::Planarization_result planarization;
  double time_extraction = 0, time_planarization = 0;
};

void make_quad_mesh(const Options& o, const Mesh& tm, const Bundle& bundle, const Parametrization& param, Quad_stage& q, Stopwatch& clock)
{
  if(o.out_quads.empty())
    return;
  const auto start = std::chrono::steady_clock::now();
  check(PVF::extract_quad_mesh(bundle, param.uv, param.result, q.quads, q.extraction), "quad mesh");
  q.time_extraction = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  auto planarity = q.quads.add_property_map<Mesh::Face_index, double>("f:pvf_planarity").first;
  check(PVF::quad_planarity(q.quads, planarity, q.before), "planarity");
  q.after = q.before;
  clock.lap("quad mesh");
  if(o.planarity_threshold > 0)
  {
    const auto planarize_start = std::chrono::steady_clock::now();
    const PVF::Error_code code = PVF::planarize_quad_mesh(q.quads, tm, q.planarization,
                                                          PVF::parameters::planarity_threshold(o.planarity_threshold));
    // Not reaching the threshold within the iterations is reported, not fatal.
    if(code != PVF::Error_code::DID_NOT_CONVERGE)
      check(code, "planarization");
    q.planarized = true;
    check(PVF::quad_planarity(q.quads, planarity, q.after), "planarity");
    q.time_planarization = std::chrono::duration<double>(std::chrono::steady_clock::now() - planarize_start).count();
    clock.lap("planarization");
  }
  q.computed = true;
}

// ---------------------------------------------------------------------------
// Stage 9: the files.
// ---------------------------------------------------------------------------
void write_outputs(const Options& o, const Mesh& tm, const Constraint_set& constraints, const Analysis& a,
                   const Parametrization& param, const Quad_stage& q, Output_files& outputs, Stopwatch& clock)
{
  outputs.prepare(o.default_outputs);
  if(!o.out_field.empty())
    outputs.write(o.out_field, [&](std::ostream& s) { return PVF::IO::write_rawfield(s, tm, a.roots, o.degree); },
                  o.out_field);
  if(!o.out_singularities.empty())
    outputs.write(o.out_singularities,
                  [&](std::ostream& s) { return PVF::IO::write_singularities(s, tm, o.degree, a.singularities); },
                  o.out_singularities);
  if(!o.out_vtk.empty())
  {
    std::vector<Face> constrained;
    for(const Constraint& c : constraints.list)
      constrained.push_back(c.face);
    outputs.write(o.out_vtk, [&](std::ostream& s) {
                    return PVF::IO::write_vtk(s, tm, a.roots, o.degree, a.singularities,
                                              PVF::parameters::face_scalars(a.face_arrays, PVF::parameters::constrained_faces(constrained)));
                  }, o.out_vtk);
  }
  // CGAL's writers say only whether they succeeded.
  auto cgal_writer = [](bool written) { return written ? PVF::Error_code::SUCCESS : PVF::Error_code::CANNOT_OPEN_FILE; };
  if(!o.out_mesh.empty())
    outputs.write(o.out_mesh, [&](std::ostream& s) {
                    return cgal_writer(CGAL::IO::write_OFF(s, tm, CGAL::parameters::stream_precision(17)));
                  }, o.out_mesh + " (the mesh)");
  if(!o.out_param.empty())
    outputs.write(o.out_param, [&](std::ostream& s) { return PVF::IO::write_integer_grid_map_OBJ(s, tm, param.uv); },
                  o.out_param);
  if(!o.out_quads.empty())
  {
    const bool obj = fs::path(o.out_quads).extension() == ".obj";
    outputs.write(o.out_quads, [&](std::ostream& s) {
                    return cgal_writer(obj ? CGAL::IO::write_OBJ(s, q.quads, CGAL::parameters::stream_precision(17))
                                           : CGAL::IO::write_OFF(s, q.quads, CGAL::parameters::stream_precision(17)));
                  }, o.out_quads + " (the quad mesh)");
  }
  if(!o.out_quads_vtk.empty())
    outputs.write(o.out_quads_vtk, [&](std::ostream& s) { return PVF::IO::write_quad_mesh_VTK(s, q.quads); },
                  o.out_quads_vtk);
  outputs.publish();
  clock.lap("write");
}

// ---------------------------------------------------------------------------
// Stage 10: the summary.
// ---------------------------------------------------------------------------
// Which solver solved the systems, and what multigrid did when it was used.
std::string solver_report(const PVF::Default_sparse_solver& solver)
{
#ifdef CGAL_PVF_HAS_CHOLMOD
  const char* direct = "direct (CHOLMOD)";
#else
  const char* direct = "direct (Eigen SimplicialLDLT)";
#endif
  const PVF::Amg_statistics s = solver.amg_solver().statistics();
  std::ostringstream m;
  if(s.solves == 0)
  {
    m << direct;
    if(solver.amg_threshold() != std::numeric_limits<std::size_t>::max())
      m << " (systems of fewer than " << solver.amg_threshold() << " unknowns)";
    return m.str();
  }
  m << "multigrid-preconditioned conjugate gradient: " << s.level_sizes.size() << " levels (";
  for(std::size_t l = 0; l < s.level_sizes.size(); ++l)
    m << (l ? ", " : "") << s.level_sizes[l];
  m << " unknowns), " << s.solves << " solves, " << s.iterations << " iterations (at most " << s.max_iterations
    << "), residual at most " << s.max_residual << ", " << s.setups << " setups";
  if(s.reused_setups)
    m << " and " << s.reused_setups << " refactorizations on kept coarse levels";
  m << " (time summed over the systems: structure " << std::fixed << std::setprecision(3) << s.analysis_seconds
    << " s, setups " << s.setup_seconds << " s, solves " << s.solve_seconds << " s)";
  m.unsetf(std::ios::fixed);
  if(s.fallbacks)
    m << "; " << s.fallbacks << " solves did not converge and were finished by the direct solver";
  return m.str();
}

void print_summary(const Options& o, const Input_mesh& input, const Constraint_set& constraints, const Field& field,
                   const Analysis& a, const Parametrization& param, const Quad_stage& q, const Output_files& outputs,
                   const Stopwatch& clock)
{
  const Mesh& tm = input.tm;
  const PVF::IO::Mesh_repair_report& r = input.report;
  int sum = 0, positive = 0, negative = 0;
  for(const auto& s : a.singularities)
  {
    sum += s.index_numerator;
    (s.index_numerator > 0 ? positive : negative) += 1;
  }
  std::size_t border_edges = 0, used_vertices = 0;
  for(auto e : edges(tm))
    border_edges += CGAL::is_border(e, tm);
  for(Vertex v : vertices(tm))
    used_vertices += (halfedge(v, tm) == Mesh::null_halfedge()) ? 0 : 1;
  // Isolated vertices (kept with --no-repair) are not part of the surface.
  const int chi = int(used_vertices) - int(num_edges(tm)) + int(num_faces(tm));
  std::cout << std::setprecision(6);
  std::cout << "mesh            " << o.mesh << ": " << num_faces(tm) << " faces, " << used_vertices << " vertices, "
            << field.components << " component(s), " << (border_edges ? "with boundary" : "closed")
            << ", Euler characteristic " << chi << "\n";
  if(r.changed(o.repair))
  {
    std::cout << "repair          " << r.file_faces << " faces in the file ->";
    const std::pair<std::size_t, const char*> items[] = {
      { r.triangulated_faces, "polygons triangulated" }, { r.merged_points, "duplicate points merged" },
      { r.duplicate_faces, "duplicate faces removed" }, { r.degenerate_polygons, "faces with a repeated vertex fixed or removed" },
      { r.degenerate_faces, "zero-area triangles repaired" }, { r.reoriented_faces, "faces reoriented" },
      { r.split_vertices, "vertices split (non-manifold)" }, { r.isolated_vertices, "isolated vertices removed" } };
    const char* separator = " ";
    for(const auto& item : items)
      if(item.first)
      {
        std::cout << separator << item.first << " " << item.second;
        separator = ", ";
      }
    std::cout << "; the outputs refer to the repaired mesh" << (o.out_mesh.empty() ? " (write it with --out-mesh)" : "") << "\n";
  }
  else if(r.isolated_vertices)
    std::cout << "note            " << r.isolated_vertices << " isolated vertices are ignored\n";
  std::cout << "field           degree " << o.degree << (o.sign_symmetric ? ", sign-symmetric" : "") << ", "
            << field.statistics.number_of_degrees_solved << " coefficient degree(s) solved\n";
  std::cout << "constraints     " << constraints.list.size() << " faces (" << field.full << " full, " << field.partial
            << " partial" << (constraints.sharp ? ", " + std::to_string(constraints.sharp) + " from sharp edges" : std::string())
            << (constraints.from_curvature ? ", " + std::to_string(constraints.from_curvature) + " from curvature" : std::string())
            << "), ";
  if(o.soft_weight > 0)
    std::cout << "soft, weight " << o.soft_weight << "\n";
  else
    std::cout << "hard\n";
  if(!constraints.note.empty())
    std::cout << "note            " << constraints.note << "\n";
  std::cout << "solver          " << solver_report(field.solver) << "\n";
  std::cout << "energy          " << a.energy << " (smoothness, Eq. 6"
            << (o.weights == PVF::Smoothness_weights::HARMONIC ? ", harmonic weights)" : ")");
  if(o.angle_bound_degrees > 0 || o.conjugate)
    std::cout << "; smooth field before optimisation " << field.smooth_energy;
  std::cout << "\n" << field.frame_report;
  std::cout << "singularities   " << a.singularities.size() << " (" << positive << " positive, " << negative
            << " negative), sum of indices " << sum << "/" << o.degree;
  if(!border_edges)
    std::cout << " (Poincare-Hopf: N * chi = " << int(o.degree) * chi << ")";
  std::cout << "\n";
  if(!a.undefined.empty())
    std::cout << "undefined index " << a.undefined.size() << " vertices next to faces with a zero constant coefficient\n";
  if(!a.note.empty())
    std::cout << "note            " << a.note << "\n";
  if(param.computed)
  {
    const PVF::Integer_grid_map_result& r = param.result;
    std::cout << "parametrization edge length " << r.target_edge_length << " (mean edge " << r.mean_edge_length << "); "
              << r.comb.singular_vertices << " singular vertices on integer points, " << r.comb.seam_curves << " seam curves ("
              << r.comb.cut_edges << " cut edges), " << r.integer_unknowns << " integer unknowns; " << r.flipped_faces
              << " flipped faces";
    if(r.stiffening_rounds > 0)
      std::cout << " after " << r.stiffening_rounds << " stiffening rounds";
    std::cout << "; worst seam residual " << r.max_seam_residual << "; energy rounded/continuous " << r.energy_ratio;
    if(r.comb.clamped_faces > 0)
      std::cout << "; " << r.comb.clamped_faces << " near-degenerate frames clamped";
    const auto old_flags = std::cout.flags();
    const auto old_precision = std::cout.precision();
    std::cout << std::fixed << std::setprecision(3) << "\n                (time: comb and cut " << r.time_comb
              << ", seam reduction " << r.time_reduction << ", assembly " << r.time_assembly << ", factorization "
              << r.time_factorization << ", integer rounding " << r.time_schur + r.time_rounding << ", stiffening "
              << r.time_stiffening << ")\n";
    std::cout.flags(old_flags);
    std::cout.precision(old_precision);
  }
  if(q.computed)
  {
    const PVF::Quad_extraction_result& e = q.extraction;
    std::cout << "quad mesh       " << e.quads << " quads";
    if(e.trimmed_polygons > 0)
      std::cout << " and " << e.trimmed_polygons << " trimmed boundary polygons";
    std::cout << ", " << e.vertices << " vertices, " << e.irregular_vertices << " irregular vertices (valence != 4)";
    if(e.flipped_faces > 0)
      std::cout << "; " << e.flipped_faces << " flipped faces of the map, " << e.repaired_regions << " regions repaired";
    std::cout << "\nplanarity       max " << 100 * q.before.max << "%, mean " << 100 * q.before.mean << "%";
    if(q.planarized)
    {
      const PVF::Planarization_result& r = q.planarization;
      if(r.converged)
        std::cout << " -> after " << r.iterations << " iterations max " << 100 * q.after.max << "%, mean "
                  << 100 * q.after.mean << "% (threshold " << 100 * r.threshold << "%); largest distance to the surface "
                  << r.max_distance << " (" << 100 * r.max_distance / r.mean_edge_length << "% of the mean quad edge)";
      else
        std::cout << "; the planarization did NOT reach " << 100 * r.threshold << "% in " << r.iterations
                  << " iterations (it got to max " << 100 * r.max_planarity_after << "%, mean "
                  << 100 * r.mean_planarity_after << "%): the quad mesh is written as extracted";
    }
    std::cout << "\n";
  }
  std::cout << "time (s)       ";
  for(const char* stage : { "load mesh", "frames and connection", "constraints", "curvature", "design", "frame field",
                            "roots", "singularities", "diagnostics", "parametrization", "quad mesh", "planarization",
                            "write" })
    if(clock.times.count(stage))
      std::cout << " " << stage << " " << std::fixed << std::setprecision(3) << clock.times.at(stage) << ";";
  std::cout << " (design: assembly " << field.statistics.assembly << ", factorization " << field.statistics.factorization
            << ", solve " << field.statistics.solve << ")\n";
  for(const std::string& out : outputs.destinations())
    std::cout << "wrote           " << out << "\n";
}

int run(const Options& o)
{
  Stopwatch clock;
  Output_files outputs(o);
  Input_mesh input = load_mesh(o);
  clock.lap("load mesh");
  // The frames, numbering and connection of the mesh, built once for every stage.
  const Bundle bundle(input.tm);
  check(bundle.status(), "mesh '" + o.mesh + "'");
  clock.lap("frames and connection");
  Curvature curvature;
  const Constraint_set constraints = gather_constraints(o, input, bundle, curvature, clock);
  const Field field = design_field(o, input.tm, bundle, constraints, curvature, clock);
  const Analysis analysis = analyse_field(o, input.tm, bundle, field, curvature, clock);
  const Parametrization param = parametrize(o, input.tm, bundle, field, clock);
  Quad_stage quads;
  make_quad_mesh(o, input.tm, bundle, param, quads, clock);
  write_outputs(o, input.tm, constraints, analysis, param, quads, outputs, clock);
  print_summary(o, input, constraints, field, analysis, param, quads, outputs, clock);
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    return run(parse_options(argc, argv));
  }
  catch(const Failure& failure)
  {
    std::cerr << "design_polyvector_field: " << failure.what() << std::endl;
    return failure.status;
  }
  catch(const std::exception& e)
  {
    std::cerr << "design_polyvector_field: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}
