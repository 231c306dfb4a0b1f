// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// design_polyvector_field: the stages of a run, from the mesh to the files
// (stages 3 to 9). Each is a function called by run() in main.cpp; the
// summary (summary.h) reports what they return.

#ifndef PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_STAGES_H
#define PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_STAGES_H

#include "common.h"
#include "options.h"
#include "output_files.h"

#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/IO/html_viewer.h>
#include <CGAL/Polyvector_fields/IO/integer_grid_map.h>
#include <CGAL/Polyvector_fields/IO/map_constraints_to_repaired_mesh.h>
#include <CGAL/Polyvector_fields/IO/quad_mesh.h>
#include <CGAL/Polyvector_fields/IO/rawfield.h>
#include <CGAL/Polyvector_fields/IO/read_triangle_mesh.h>
#include <CGAL/Polyvector_fields/IO/singularities.h>
#include <CGAL/Polyvector_fields/IO/vtk.h>
#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/design_angle_bounded_frame_field.h>
#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>
#include <CGAL/Polyvector_fields/design_conjugate_frame_field.h>
#include <CGAL/Polyvector_fields/estimate_principal_curvatures.h>
#include <CGAL/Polyvector_fields/extract_quad_mesh.h>
#include <CGAL/Polyvector_fields/find_out_of_range_constraint_vector.h>
#include <CGAL/Polyvector_fields/frame_field_measures.h>
#include <CGAL/Polyvector_fields/compute_integer_grid_map.h>
#include <CGAL/Polyvector_fields/planarize_quad_mesh.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>
#include <CGAL/Polyvector_fields/refine_for_quad_size.h>
#include <CGAL/Polyvector_fields/select_curvature_constraints.h>
#include <CGAL/Polyvector_fields/select_sharp_edge_constraints.h>
#include <CGAL/Polyvector_fields/smoothness_energy.h>

#include <array>
#include <cmath>
#include <iterator>
#include <random>
#include <set>
#include <sstream>
#include <utility>
#include <vector>
#include <optional>
#include <string>
#include <vector>

namespace pvf_cli {

// ---------------------------------------------------------------------------
// Stage 3: the mesh, repaired unless --no-repair.
// ---------------------------------------------------------------------------
struct Input_mesh
{
  Mesh tm;
  PVF::IO::Mesh_repair_result report;
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
  return input;
}

// ---------------------------------------------------------------------------
// Stage 3b (with a map): the quad size, and the mesh refined where it is too
// coarse for it (edges longer than two quads split; see refine_for_quad_size()).
// ---------------------------------------------------------------------------
struct Quad_size
{
  double h = 0;                // the quad size, in mesh units
  bool from_mean_edge = false; // the default rule chose the mean edge length (the map's own default)
  bool default_size = false;   // neither --edge-length nor --quads
  double scale = 1;            // of the default size (made finer when the quads are too far from the surface,
                               // or cannot fill the map's fold-overs)
  std::size_t faces_before = 0, faces_after = 0;
  bool refined() const { return faces_after != faces_before; }
};

// The default quad sizes tried, with how far the quads were from the input (in
// bounding-box diagonals), and the deviation of the quads that were kept.
struct Sizing
{
  std::vector<std::pair<double, double> > tries;  // (quad size, deviation) of the sizes made finer
  // the sizes made finer because the extraction could not fill the map's
  // fold-overs there: (quad size, whether a quad stayed folded against the
  // surface; otherwise a component was split into quads on its triangles)
  std::vector<std::pair<double, bool> > unfilled;
  double deviation = -1;  // of the quads kept; < 0: not measured
  double split_at = -1;   // >= 0: the deviation at the last size, before the far components were split
  double bound = 0;
};

double bounding_box_diagonal(const Mesh& tm)
{
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(tm);
  const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(), dz = box.zmax() - box.zmin();
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// At least this many quads by default, so that a coarse mesh (a box of 12
// triangles, a 50-face scan) gets a useful quad mesh.
constexpr double default_minimum_quads = 1000;

// The dihedral angle above which an edge is sharp. With the boundary alone,
// only a fold of nearly 180 degrees (a degenerate crease) counts as sharp.
double crease_degrees(const Options& o) { return o.sharp_degrees >= 0 ? o.sharp_degrees : 179.9; }

// With a map, creases shorter than this many quads (noise on a scan: a quad
// mesh cannot follow them) are not features: networks of sharp edges shorter
// in all, and crease curves shorter that do not join two corners (see
// select_sharp_edge_constraints(), minimum_feature_length).
constexpr double minimum_crease_quads = 3;

// The named parameters of the sharp edges: the border with boundary alignment,
// and with a map, the shortest crease network kept.
auto feature_parameters(const Options& o, double quad_size)
{
  return PVF::parameters::boundary_alignment(
    o.boundary_alignment, PVF::parameters::minimum_feature_length(o.parametrize ? minimum_crease_quads * quad_size : 0.0));
}

// `scale` multiplies the default size.
Quad_size choose_quad_size(const Options& o, Input_mesh& input, double scale = 1)
{
  Quad_size q;
  q.scale = scale;
  Mesh& tm = input.tm;
  q.faces_before = q.faces_after = num_faces(tm);
  if(!o.parametrize)
    return q;
  const double area = CGAL::Polygon_mesh_processing::area(tm);
  if(o.edge_length > 0)
    q.h = o.edge_length;
  else if(o.quads > 0)
    q.h = std::sqrt(area / double(o.quads));
  else
  {
    double sum = 0;
    for(auto e : edges(tm))
      sum += CGAL::Polygon_mesh_processing::edge_length(e, tm);
    const double mean = num_edges(tm) > 0 ? sum / double(num_edges(tm)) : 0;
    const double small = std::sqrt(area / default_minimum_quads);
    q.from_mean_edge = mean <= small && scale == 1;
    q.h = scale * (mean <= small ? mean : small);
    q.default_size = true;
  }
  if(!(q.h > 0) || !std::isfinite(q.h))
    throw Failure("mesh '" + o.mesh + "': it has no area, so no quad size");
  std::vector<std::size_t> origin = input.report.source_face;
  if(origin.size() != num_faces(tm))
    origin.clear();
  if(o.sharp_degrees >= 0 || o.boundary_alignment)
  {
    // The features, so that the refinement splits the edges between them
    // (the constraints stage finds the same edges on the refined mesh).
    const auto features = tm.add_property_map<Mesh::Edge_index, bool>("e:pvf_feature", false).first;
    std::vector<Constraint> unused;
    const auto np = feature_parameters(o, q.h);
    check(PVF::select_sharp_edge_constraints(tm, crease_degrees(o), o.vectors_per_constraint(), unused,
                                             np.edge_is_constrained_map(features)),
          "sharp edges");
    check(PVF::refine_for_quad_size(tm, q.h, origin, np.edge_is_constrained_map(features)), "refinement");
  }
  else
    check(PVF::refine_for_quad_size(tm, q.h, origin), "refinement");
  q.faces_after = num_faces(tm);
  if(q.refined())
    input.report.source_face = origin;
  return q;
}

// ---------------------------------------------------------------------------
// Stage 4: the constraints.
// ---------------------------------------------------------------------------

struct Constraint_set
{
  std::vector<Constraint> list;
  std::size_t from_files = 0, random = 0, sharp = 0, from_curvature = 0;
  std::string note;  // said in the summary
  // The edges that the map puts on integer iso-lines (sharp edges, and the
  // border with boundary alignment), by the rule of the sharp-edge constraints.
  std::optional<Mesh::Property_map<Mesh::Edge_index, bool> > features;

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
  std::size_t failed = 0;
  if(PVF::IO::map_constraints_to_repaired_mesh(input.tm, input.report, by_id, set.list, &failed) !=
     PVF::Error_code::SUCCESS)
    throw Failure("constraint on face " + std::to_string(by_id[failed].face) +
                  ": the repair removed that face (a duplicate or degenerate face)");
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

Constraint_set gather_constraints(const Options& o, Input_mesh& input, const Quad_size& size, const Bundle& bundle,
                                  Curvature& curvature, Stopwatch& clock)
{
  Constraint_set set;
  add_file_constraints(o, input, set);
  add_random_constraints(o, input.tm, set);
  if(o.sharp_degrees >= 0 || o.boundary_alignment)
  {
    // Faces already constrained are left alone.
    std::vector<Constraint> sharp;
    const double degrees = crease_degrees(o);
    if(o.parametrize)
      set.features = input.tm.add_property_map<Mesh::Edge_index, bool>("e:pvf_feature", false).first;
    const auto np = feature_parameters(o, size.h);
    check(set.features ? PVF::select_sharp_edge_constraints(input.tm, degrees, o.vectors_per_constraint(), sharp,
                                                            np.edge_is_constrained_map(*set.features))
                       : PVF::select_sharp_edge_constraints(input.tm, degrees, o.vectors_per_constraint(), sharp, np),
          "sharp-edge constraints");
    const std::set<Face> constrained = set.faces();
    for(const Constraint& c : sharp)
      if(!constrained.count(c.face))
      {
        set.list.push_back(c);
        ++set.sharp;
      }
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
    std::size_t index = 0;
    double log10_length = 0;
    if(PVF::find_out_of_range_constraint_vector(c.vectors, o.degree, index, log10_length))
    {
      m << "a vector of length " << std::pow(10.0, log10_length) << " is out of range for degree " << o.degree
        << " (the package needs 1e-300 <= length^" << o.degree << " <= 1e300)";
      return m.str();
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
    report << "angle bound     " << o.angle_bound_degrees << " degrees: "
           << (result.converged ? "reached" : "NOT reached") << " in " << result.iterations
           << " iterations (to within " << tolerance * 180 / CGAL_PI << " degree, then " << result.projected_faces
           << " free faces projected onto the bound); smallest angle " << result.minimum_free_angle * 180 / CGAL_PI
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
  // computed again, rounding the integers in every stiffening round, because
  // the extraction could not repair the fold-overs of the first map
  bool recomputed = false;
  Mesh::Property_map<Mesh::Halfedge_index, std::array<double, 2> > uv;  // at target(h) inside face(h)
  PVF::Integer_grid_map_result result;
};

Parametrization parametrize(const Options& o, Mesh& tm, const Quad_size& size, const Constraint_set& constraints,
                            const Field& field, Stopwatch& clock, bool stiffening_keeps_integers = true)
{
  Parametrization p;
  if(!o.parametrize)
    return p;
  p.uv = tm.add_property_map<Mesh::Halfedge_index, std::array<double, 2> >("h:pvf_uv").first;
  const double h = size.h;
  // Singularities closer than one quad would meet on one integer point; the
  // features (the border among them) lie on integer iso-lines.
  const auto features = constraints.features ? *constraints.features
                                             : tm.add_property_map<Mesh::Edge_index, bool>("e:pvf_feature", false).first;
  const auto np = PVF::parameters::stiffening_keeps_integers(
                    stiffening_keeps_integers,
                    PVF::parameters::singularity_cancellation_distance(
                      o.singularity_separation * h, PVF::parameters::boundary_alignment(o.boundary_alignment)))
                    .edge_is_constrained_map(features);
  // With the mean edge length of an unrefined mesh, the map takes it itself.
  const PVF::Error_code code =
    !size.from_mean_edge || size.refined()
      ? PVF::compute_integer_grid_map(*field.polyvector, p.uv, p.result, PVF::parameters::target_edge_length(h, np))
      : PVF::compute_integer_grid_map(*field.polyvector, p.uv, p.result, np);
  check(code, "parametrization", code == PVF::Error_code::MAP_CHECK_FAILED ? p.result.diagnostic : std::string());
  p.computed = true;
  p.recomputed = !stiffening_keeps_integers;
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
  PVF::Planarity_result before, after;
  bool planarized = false;
  // the extraction left a quad folded against the surface (FOLDED_QUAD) and
  // was allowed to say so rather than fail (make_quad_mesh()'s may_refine)
  bool folded = false;
  PVF::Planarization_result planarization;
  PVF::Error_code planarization_code = PVF::Error_code::SUCCESS;
  double time_extraction = 0, time_planarization = 0;
};

// Returns false, and makes nothing, when the extraction could not repair the
// fold-overs of a map that can be computed again (may_retry).
// `max_distance` > 0: the components of the surface farther than that from their quads
// are split into quads (extract_quad_mesh()'s max_input_distance).
// may_refine: a quad left folded against the surface sets q.folded and
// makes nothing, instead of an error (another quad size will be tried).
// Components of the quad mesh split into quads on their triangles because
// the extraction could not fill the fold-overs of their map.
std::size_t unfilled_components(const PVF::Quad_extraction_result& e)
{
  return e.split_components - e.split_small_components - e.split_far_components - e.split_defective_components;
}

bool make_quad_mesh(const Options& o, const Mesh& tm, const Bundle& bundle, const Parametrization& param, Quad_stage& q,
                    Stopwatch& clock, bool may_retry = false, double max_distance = 0, bool may_refine = false)
{
  if(o.out_quads.empty())
    return true;
  const PVF::internal::Timer extraction_timer;
  // A component too small for a whole quad gets its triangles split into quads (the
  // summary names how many), rather than failing the whole mesh.
  const PVF::Error_code extracted =
    PVF::extract_quad_mesh(bundle, param.uv, param.result, q.quads, q.extraction,
                           PVF::parameters::split_components_without_cells(true, PVF::parameters::max_input_distance(max_distance)));
  if(extracted == PVF::Error_code::UNREPAIRABLE_FOLD_OVER && may_retry)
  {
    clock.lap("quad mesh");
    return false;
  }
  if(extracted == PVF::Error_code::FOLDED_QUAD && may_refine)
  {
    q.folded = true;
    clock.lap("quad mesh");
    return true;
  }
  check(extracted, "quad mesh", q.extraction.diagnostic);
  q.time_extraction = extraction_timer.elapsed();
  auto planarity = q.quads.add_property_map<Mesh::Face_index, double>("f:pvf_planarity").first;
  check(PVF::quad_planarity(q.quads, planarity, q.before), "planarity");
  q.after = q.before;
  clock.lap("quad mesh");
  if(o.planarity_threshold > 0)
  {
    const PVF::internal::Timer planarization_timer;
    // The bound on the distance to the surface: a fraction of the mean quad edge.
    double mean_edge = 0;
    for(auto e : edges(q.quads))
      mean_edge += CGAL::Polygon_mesh_processing::edge_length(e, q.quads) / double(num_edges(q.quads));
    const PVF::Error_code code = PVF::planarize_quad_mesh(
      q.quads, tm, q.planarization,
      PVF::parameters::max_distance_to_surface(
        o.max_surface_distance * mean_edge,
        PVF::parameters::gauss_newton_steps(
          o.gauss_newton_steps, PVF::parameters::crease_angle(
                                  crease_degrees(o), PVF::parameters::planarity_threshold(o.planarity_threshold)))));
    // Not reaching the threshold within the iterations, or only by leaving the
    // surface or folding a quad, is reported, not fatal: the quad mesh is then
    // kept as extracted.
    q.planarization_code = code;
    if(code != PVF::Error_code::DID_NOT_CONVERGE && code != PVF::Error_code::TOO_FAR_FROM_SURFACE &&
       code != PVF::Error_code::FOLDED_QUAD)
      check(code, "planarization");
    q.planarized = true;
    check(PVF::quad_planarity(q.quads, planarity, q.after), "planarity");
    q.time_planarization = planarization_timer.elapsed();
    clock.lap("planarization");
  }
  q.computed = true;
  return true;
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
                    return PVF::IO::write_VTK(s, tm, a.roots, o.degree, a.singularities,
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
  if(!o.out_ply.empty())
    outputs.write(o.out_ply, [&](std::ostream& s) { return PVF::IO::write_quad_mesh_PLY(s, q.quads); }, o.out_ply);
  if(!o.out_html.empty())
  {
    std::vector<Face> constrained;
    for(const Constraint& c : constraints.list)
      constrained.push_back(c.face);
    std::string message;
    const auto np = PVF::parameters::page_title(fs::path(o.mesh).filename().string(),
                                                PVF::parameters::constrained_faces(constrained,
                                                                                   PVF::parameters::error_message(message)));
    outputs.write(o.out_html, [&](std::ostream& s) {
                    return q.computed ? PVF::IO::write_HTML_viewer(s, tm, a.roots, o.degree, a.singularities,
                                                                   PVF::parameters::quad_mesh(q.quads, np))
                                      : PVF::IO::write_HTML_viewer(s, tm, a.roots, o.degree, a.singularities, np);
                  }, o.out_html, message);
  }
  outputs.publish();
  clock.lap("write");
}

} // namespace pvf_cli

#endif // PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_STAGES_H
