// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// design_polyvector_field: the command-line designer.
//
// Reads a triangle mesh and constraints, designs the smoothest N-PolyVector
// field, and writes the field (.rawfield), its singularities (.sings) and a
// VTK file for ParaView. Frame fields (N = 4, sign-symmetric) can then be
// optimised to bound their angles or to be conjugate (paper Section 4). With
// no argument it designs a frame field on the bundled architectural mesh from
// its 84 bundled constraints and writes output/inspired_mesh.{rawfield,sings,vtk}.
// Run with --help for the options.
//
// Errors are reported on one line of standard error with a non-zero exit
// status; no output file is written unless every stage succeeded.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/IO/rawfield.h>
#include <CGAL/Polyvector_fields/IO/singularities.h>
#include <CGAL/Polyvector_fields/IO/vtk.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/angle_bounded_frame_field.h>
#include <CGAL/Polyvector_fields/conjugate_frame_field.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/frame_field_measures.h>
#include <CGAL/Polyvector_fields/select_curvature_constraints.h>
#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>
#include <CGAL/Polyvector_fields/smoothness_energy.h>

#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
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

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index Face;
typedef Mesh::Vertex_index Vertex;
typedef PVF::Face_constraint<Face, Vector> Constraint;
typedef std::complex<double> Complex;
typedef PVF::Principal_curvatures<Vector> Curvatures;

namespace {

// A failure: one line on standard error, then a non-zero exit.
struct Failure : std::runtime_error
{
  int status;
  Failure(const std::string& message, int exit_status = 1) : std::runtime_error(message), status(exit_status) {}
};

const char* usage =
  "usage: design_polyvector_field [options]\n"
  "  --mesh FILE              triangle mesh (OFF, OBJ, PLY, ...); default: the bundled inspired_mesh.obj\n"
  "  --degree N               number of vectors per face, 1..32 (default 4)\n"
  "  --sign-symmetric         vectors come in pairs {u, -u} (N even): frame fields, N-RoSy of even N\n"
  "  --constraints FILE       constraint file: 'face_id x y z [x y z ...]' per line, '#' comments\n"
  "  --dmat-b FILE --dmat-bc FILE   libigl constraints: face ids (b) and vectors (bc)\n"
  "  --soft WEIGHT            make every constraint soft with this weight (> 0)\n"
  "  --sharp-edges DEGREES    partial constraints along edges whose dihedral angle exceeds DEGREES\n"
  "  --random-constraints K   full constraints with random vectors on K random faces (see --seed)\n"
  "  --seed S                 seed of --random-constraints (default 1)\n"
  "frame fields (imply --degree 4 --sign-symmetric):\n"
  "  --curvature-constraints PERCENT  constrain PERCENT % of the faces, the most anisotropic ones\n"
  "                           spread over the surface, to their principal curvature directions\n"
  "  --angle-bound DEGREES    optimise the field so that u and v make at least DEGREES (0, 90]\n"
  "  --conjugate              optimise the field to be conjugate (planar-quad remeshing)\n"
  "  --orthogonality W        with --conjugate: weight W >= 0 pulling the field towards a cross field\n"
  "  --iterations K           maximum number of frame-field iterations (default 200 / 100)\n"
  "output (default when none is given: output/<mesh name>.rawfield, .sings and .vtk):\n"
  "  --out-field FILE         write the field (.rawfield: N F, then 3N numbers per face)\n"
  "  --out-singularities FILE write the singularities (.sings: N count, then 'vertex numerator')\n"
  "  --out-vtk FILE           write a legacy VTK file for ParaView\n"
  "  --help                   print this help\n"
  "Without --mesh: the bundled <data>/inspired_mesh.obj and, unless other constraints are given,\n"
  "its 84 constraints (--dmat-b/--dmat-bc), as a frame field (--degree 4 --sign-symmetric).\n";

struct Options
{
  std::string mesh;
  std::size_t degree = 4;
  bool sign_symmetric = false;
  std::string constraints, dmat_b, dmat_bc;
  double soft_weight = 0;  // 0: hard
  double sharp_degrees = -1;  // < 0: no sharp-edge constraints
  std::size_t random_constraints = 0;
  unsigned seed = 1;
  std::string out_field, out_singularities, out_vtk;
  // Frame fields.
  double curvature_percent = -1;  // < 0: none
  double angle_bound_degrees = -1;  // < 0: none
  bool conjugate = false;
  double orthogonality = 0;
  std::size_t iterations = 0;  // 0: the algorithm's default
  bool default_outputs = false;  // output/<mesh name>.*, the folder made if needed

  bool frame_field() const { return curvature_percent >= 0 || angle_bound_degrees >= 0 || conjugate; }
};

double parse_number(const std::string& flag, const std::string& text)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if(text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
    throw Failure(flag + " expects a finite number, got '" + text + "'", 2);
  return value;
}

Options parse(int argc, char** argv)
{
  Options o;
  bool degree_given = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string flag = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw Failure(flag + " expects a value", 2);
      return argv[++i];
    };
    auto integer = [&](double low, double high) {
      const std::string text = value();
      const double d = parse_number(flag, text);
      if(d != std::floor(d) || d < low || d > high)
        throw Failure(flag + " expects an integer in " + std::to_string(long(low)) + ".." + std::to_string(long(high)) +
                      ", got '" + text + "'", 2);
      return d;
    };
    if(flag == "--help" || flag == "-h")
    {
      std::cout << usage;
      std::exit(EXIT_SUCCESS);
    }
    else if(flag == "--mesh") o.mesh = value();
    else if(flag == "--degree")
    {
      o.degree = std::size_t(integer(1, 32));
      degree_given = true;
    }
    else if(flag == "--sign-symmetric") o.sign_symmetric = true;
    else if(flag == "--constraints") o.constraints = value();
    else if(flag == "--dmat-b") o.dmat_b = value();
    else if(flag == "--dmat-bc") o.dmat_bc = value();
    else if(flag == "--soft")
    {
      o.soft_weight = parse_number(flag, value());
      if(!(o.soft_weight > 0))
        throw Failure("--soft expects a weight > 0", 2);
    }
    else if(flag == "--sharp-edges")
    {
      o.sharp_degrees = parse_number(flag, value());
      if(o.sharp_degrees < 0 || o.sharp_degrees >= 180)
        throw Failure("--sharp-edges expects an angle in [0, 180) degrees", 2);
    }
    else if(flag == "--random-constraints") o.random_constraints = std::size_t(integer(0, 4e9));
    else if(flag == "--seed") o.seed = unsigned(integer(0, 4e9));
    else if(flag == "--curvature-constraints")
    {
      o.curvature_percent = parse_number(flag, value());
      if(!(o.curvature_percent > 0) || o.curvature_percent > 100)
        throw Failure("--curvature-constraints expects a percentage in (0, 100]", 2);
    }
    else if(flag == "--angle-bound")
    {
      o.angle_bound_degrees = parse_number(flag, value());
      if(!(o.angle_bound_degrees > 0) || o.angle_bound_degrees > 90)
        throw Failure("--angle-bound expects an angle in (0, 90] degrees", 2);
    }
    else if(flag == "--conjugate") o.conjugate = true;
    else if(flag == "--orthogonality")
    {
      o.orthogonality = parse_number(flag, value());
      if(o.orthogonality < 0)
        throw Failure("--orthogonality expects a weight >= 0", 2);
    }
    else if(flag == "--iterations") o.iterations = std::size_t(integer(1, 1e6));
    else if(flag == "--out-field") o.out_field = value();
    else if(flag == "--out-singularities") o.out_singularities = value();
    else if(flag == "--out-vtk") o.out_vtk = value();
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
  if(o.sign_symmetric && o.degree % 2 != 0)
    throw Failure("--sign-symmetric needs an even --degree", 2);
  if(o.out_field.empty() && o.out_singularities.empty() && o.out_vtk.empty())
  {
    const std::string stem = "output/" + std::filesystem::path(o.mesh).stem().string();
    o.out_field = stem + ".rawfield";
    o.out_singularities = stem + ".sings";
    o.out_vtk = stem + ".vtk";
    o.default_outputs = true;
  }
  return o;
}

void check(PVF::Error_code code, const std::string& what)
{
  if(code != PVF::Error_code::SUCCESS)
    throw Failure(what + ": " + PVF::get_error_message(code));
}

struct Stopwatch
{
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double lap()
  {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - start).count();
    start = now;
    return seconds;
  }
};

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
    Vector d = tm.point(target(h, tm)) - tm.point(source(h, tm));
    d = d / std::sqrt(d.squared_length());
    edges_of_face[f].emplace_back(angle, d);
    edges_of_face[g].emplace_back(angle, d);
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

// Writes every output under a temporary name first and renames them all at the
// end, so that a failure leaves no output behind.
class Output_set
{
public:
  std::string temporary(const std::string& destination)
  {
    const std::string path = destination + ".partial";
    m_pending.emplace_back(path, destination);
    return path;
  }
  void commit()
  {
    for(const auto& p : m_pending)
    {
      std::error_code error;
      std::filesystem::rename(p.first, p.second, error);
      if(error)
        throw Failure("cannot write " + p.second + ": " + error.message());
    }
    m_pending.clear();
  }
  ~Output_set()
  {
    for(const auto& p : m_pending)
      std::remove(p.first.c_str());
  }

private:
  std::vector<std::pair<std::string, std::string> > m_pending;
};

int run(const Options& o)
{
  Stopwatch clock;
  std::map<std::string, double> times;

  Mesh tm;
  if(!std::filesystem::exists(o.mesh))
    throw Failure("cannot open mesh file '" + o.mesh + "'");
  if(!CGAL::IO::read_polygon_mesh(o.mesh, tm) || CGAL::is_empty(tm))
    throw Failure("cannot read a polygon mesh from '" + o.mesh + "'");
  if(!CGAL::is_triangle_mesh(tm))
    throw Failure("'" + o.mesh + "' is not a triangle mesh");
  times["load mesh"] = clock.lap();

  PVF::Polyvector_field_designer<Mesh> designer(tm, o.degree, PVF::parameters::sign_symmetric(o.sign_symmetric));
  check(designer.status(), "mesh '" + o.mesh + "'");
  times["frames and connection"] = clock.lap();

  std::vector<Constraint> constraints;
  if(!o.constraints.empty())
    check(PVF::IO::read_constraints(o.constraints, tm, constraints), "constraints '" + o.constraints + "'");
  if(!o.dmat_b.empty())
  {
    std::vector<Constraint> dmat;
    check(PVF::IO::read_dmat_constraints(o.dmat_b, o.dmat_bc, tm, dmat), "dmat constraints");
    constraints.insert(constraints.end(), dmat.begin(), dmat.end());
  }
  if(o.random_constraints > 0)
  {
    if(o.random_constraints > num_faces(tm))
      throw Failure("--random-constraints asks for more faces than the mesh has");
    std::mt19937 rng(o.seed);
    std::uniform_real_distribution<double> coordinate(-1, 1);
    std::set<Face> constrained;
    for(const Constraint& c : constraints)
      constrained.insert(c.face);
    const std::vector<Face> all(faces(tm).begin(), faces(tm).end());
    std::size_t added = 0;
    while(added < o.random_constraints && constrained.size() < all.size())
    {
      const Face f = all[rng() % all.size()];
      if(!constrained.insert(f).second)
        continue;
      Constraint c{ f, {} };
      for(std::size_t k = 0; k < (o.sign_symmetric ? o.degree / 2 : o.degree); ++k)
        c.vectors.push_back(Vector(coordinate(rng), coordinate(rng), coordinate(rng)));
      constraints.push_back(c);
      ++added;
    }
  }
  std::size_t sharp = 0;
  if(o.sharp_degrees >= 0)
  {
    std::set<Face> constrained;
    for(const Constraint& c : constraints)
      constrained.insert(c.face);
    const auto edge_constraints =
      sharp_edge_constraints(tm, o.sharp_degrees, o.sign_symmetric ? o.degree / 2 : o.degree, constrained);
    sharp = edge_constraints.size();
    constraints.insert(constraints.end(), edge_constraints.begin(), edge_constraints.end());
  }
  // Curvature: for curvature constraints, the conjugate field, and the VTK output of frame fields.
  auto curvatures = tm.add_property_map<Face, Curvatures>("f:pvf_curvatures").first;
  const bool has_curvature = o.frame_field();
  std::size_t from_curvature = 0;
  if(has_curvature)
  {
    times["constraints"] += clock.lap();
    check(PVF::estimate_principal_curvatures(tm, curvatures), "curvature");
    times["curvature"] = clock.lap();
  }
  if(o.curvature_percent > 0)
  {
    std::vector<Constraint> principal;
    check(PVF::select_curvature_constraints(tm, curvatures, principal,
                                            PVF::parameters::constrained_fraction(o.curvature_percent / 100)),
          "curvature constraints");
    std::set<Face> constrained;
    for(const Constraint& c : constraints)
      constrained.insert(c.face);
    for(const Constraint& c : principal)
      if(constrained.insert(c.face).second)
      {
        constraints.push_back(c);
        ++from_curvature;
      }
  }
  if(o.soft_weight > 0)
    for(Constraint& c : constraints)
      c.weight = o.soft_weight;
  std::size_t full = 0, partial = 0;
  for(std::size_t i = 0; i < constraints.size(); ++i)
  {
    const Constraint& c = constraints[i];
    const PVF::Error_code code = designer.add_constraint(c);
    if(code != PVF::Error_code::SUCCESS)
      throw Failure("constraint on face " + std::to_string(std::size_t(c.face)) + ": " + PVF::get_error_message(code));
    (c.vectors.size() == (o.sign_symmetric ? o.degree / 2 : o.degree) ? full : partial) += 1;
  }
  times["constraints"] += clock.lap();

  auto coefficients = tm.add_property_map<Face, std::vector<Complex> >("f:pvf_coefficients").first;
  auto roots = tm.add_property_map<Face, std::vector<Vector> >("f:pvf_roots").first;
  check(designer.solve(coefficients), "design");
  clock.lap();
  const PVF::Design_statistics& statistics = designer.statistics();
  times["assembly"] = statistics.assembly;
  times["factorization"] = statistics.factorization;
  times["solve"] = statistics.solve;

  const double smooth_energy = PVF::smoothness_energy(tm, o.degree, coefficients);

  // Frame-field optimisation (Section 4), from the same constraints.
  std::ostringstream frame_report;
  if(o.angle_bound_degrees > 0)
  {
    PVF::Angle_bound_result result;
    const auto np = PVF::parameters::angle_bound(o.angle_bound_degrees * CGAL_PI / 180);
    check(o.iterations ? PVF::design_angle_bounded_frame_field(tm, 4, constraints, coefficients, result,
                                                                np.number_of_iterations(o.iterations))
                       : PVF::design_angle_bounded_frame_field(tm, 4, constraints, coefficients, result, np),
          "angle bound");
    frame_report << "angle bound     " << o.angle_bound_degrees << " degrees: " << (result.converged ? "converged" : "NOT converged")
                 << " in " << result.iterations << " iterations; smallest angle " << result.minimum_free_angle * 180 / CGAL_PI
                 << " degrees (free faces), " << result.minimum_angle * 180 / CGAL_PI << " degrees (all faces)\n";
    times["frame field"] = clock.lap();
  }
  if(o.conjugate)
  {
    PVF::Conjugate_field_result result;
    const auto np = PVF::parameters::principal_curvature_map(curvatures,
                                                             PVF::parameters::orthogonality_weight(o.orthogonality));
    check(o.iterations ? PVF::design_conjugate_frame_field(tm, 4, constraints, coefficients, result,
                                                            np.number_of_iterations(o.iterations))
                       : PVF::design_conjugate_frame_field(tm, 4, constraints, coefficients, result, np),
          "conjugate field");
    frame_report << "conjugate       " << (result.converged ? "converged" : "NOT converged") << " in " << result.iterations
                 << " iterations (orthogonality weight " << o.orthogonality << "); residual sum |u^T S v| (unit-size field): "
                 << result.residual_history.front() << " -> free faces " << result.free_residual << ", constrained faces "
                 << result.constrained_residual << ", all faces " << result.residual << "\n";
    times["frame field"] = clock.lap();
  }

  const auto np = PVF::parameters::sign_symmetric(o.sign_symmetric);
  check(PVF::compute_field_roots(tm, o.degree, coefficients, roots, np), "roots");
  times["roots"] = clock.lap();

  std::vector<PVF::Singularity<Vertex> > singularities;
  std::vector<Vertex> undefined;
  check(PVF::compute_singularities(tm, o.degree, coefficients, std::back_inserter(singularities),
                                   std::back_inserter(undefined)),
        "singularities");
  times["singularities"] = clock.lap();
  const double energy = PVF::smoothness_energy(tm, o.degree, coefficients);

  if(o.default_outputs)
  {
    std::error_code error;
    std::filesystem::create_directories("output", error);
    if(error)
      throw Failure("cannot create the folder output/: " + error.message());
  }
  Output_set outputs;
  if(!o.out_field.empty())
    check(PVF::IO::write_rawfield(outputs.temporary(o.out_field), tm, roots, o.degree), "writing " + o.out_field);
  if(!o.out_singularities.empty())
    check(PVF::IO::write_singularities(outputs.temporary(o.out_singularities), tm, o.degree, singularities),
          "writing " + o.out_singularities);
  if(!o.out_vtk.empty())
  {
    std::vector<Face> constrained;
    for(const Constraint& c : constraints)
      constrained.push_back(c.face);
    PVF::IO::Face_scalar_arrays arrays;
    if(o.sign_symmetric && o.degree == 4)
    {
      std::vector<double> angles;
      auto angle_map = tm.add_property_map<Face, double>("f:pvf_angle").first;
      check(PVF::compute_frame_angles(tm, coefficients, angle_map), "frame angles");
      for(Face f : faces(tm))
        angles.push_back(angle_map[f] * 180 / CGAL_PI);
      arrays.emplace_back("min_angle_degrees", angles);
      tm.remove_property_map(angle_map);
    }
    if(has_curvature)
    {
      std::vector<double> deviation;
      auto deviation_map = tm.add_property_map<Face, double>("f:pvf_deviation").first;
      check(PVF::compute_conjugacy_deviation(tm, coefficients, curvatures, deviation_map), "conjugacy deviation");
      for(Face f : faces(tm))
        deviation.push_back(deviation_map[f]);
      arrays.emplace_back("conjugacy_deviation", deviation);
      tm.remove_property_map(deviation_map);
    }
    check(PVF::IO::write_vtk(outputs.temporary(o.out_vtk), tm, roots, o.degree, singularities, arrays, constrained),
          "writing " + o.out_vtk);
  }
  outputs.commit();
  times["write"] = clock.lap();

  // Summary.
  int sum = 0, positive = 0, negative = 0;
  for(const auto& s : singularities)
  {
    sum += s.index_numerator;
    (s.index_numerator > 0 ? positive : negative) += 1;
  }
  std::size_t border_edges = 0;
  for(auto e : edges(tm))
    border_edges += CGAL::is_border(e, tm);
  const int chi = int(num_vertices(tm)) - int(num_edges(tm)) + int(num_faces(tm));
  std::cout << std::setprecision(6);
  std::cout << "mesh            " << o.mesh << ": " << num_faces(tm) << " faces, " << num_vertices(tm) << " vertices, "
            << designer.connection().number_of_components() << " component(s), "
            << (border_edges ? "with boundary" : "closed") << ", Euler characteristic " << chi << "\n";
  std::cout << "field           degree " << o.degree << (o.sign_symmetric ? ", sign-symmetric" : "") << ", "
            << statistics.number_of_degrees_solved << " coefficient degree(s) solved\n";
  std::cout << "constraints     " << constraints.size() << " faces (" << full << " full, " << partial << " partial"
            << (sharp ? ", " + std::to_string(sharp) + " from sharp edges" : std::string())
            << (from_curvature ? ", " + std::to_string(from_curvature) + " from curvature" : std::string()) << "), "
            << (o.soft_weight > 0 ? "soft, weight " + std::to_string(o.soft_weight) : std::string("hard")) << "\n";
  std::cout << "energy          " << energy << " (smoothness, Eq. 6)";
  if(o.frame_field() && (o.angle_bound_degrees > 0 || o.conjugate))
    std::cout << "; smooth field before optimisation " << smooth_energy;
  std::cout << "\n" << frame_report.str();
  std::cout << "singularities   " << singularities.size() << " (" << positive << " positive, " << negative
            << " negative), sum of indices " << sum << "/" << o.degree;
  if(!border_edges)
    std::cout << " (Poincare-Hopf: N * chi = " << int(o.degree) * chi << ")";
  std::cout << "\n";
  if(!undefined.empty())
    std::cout << "undefined index " << undefined.size() << " vertices next to faces with a zero constant coefficient\n";
  std::cout << "time (s)       ";
  for(const char* stage : { "load mesh", "frames and connection", "curvature", "constraints", "assembly", "factorization",
                            "solve", "frame field", "roots", "singularities", "write" })
    if(times.count(stage))
    std::cout << " " << stage << " " << std::fixed << std::setprecision(3) << times[stage] << ";";
  std::cout << "\n";
  for(const std::string* out : { &o.out_field, &o.out_singularities, &o.out_vtk })
    if(!out->empty())
      std::cout << "wrote           " << *out << "\n";
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Options options = parse(argc, argv);
    return run(options);
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
