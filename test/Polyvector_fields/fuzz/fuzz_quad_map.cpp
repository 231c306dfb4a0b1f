// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Fuzz target `quad_map`: the meshing road after the field design, fast
// enough for millions of executions: a random frame field (random angles per
// face, no design solve) on a tiny mesh (1 to 32 triangles), with features
// from select_sharp_edge_constraints() and/or random edges, optionally
// refine_for_quad_size(), then comb_frame_field(), compute_integer_grid_map()
// (with or without edge_is_constrained_map, boundary_alignment on or off) and
// extract_quad_mesh() (the map's transitions; whole cells or
// keep_trimmed_boundary, a random fold_over_repair_rings).
//
// Input (missing bytes count as 0):
//   byte 0: bits 0-2 the mesh: 0 a (1 + b1 % 3) x (1 + b2 % 2) grid, 1 an
//           icosahedron, 2 a tetrahedron, 3 the 12-triangle box, 4 an
//           octahedron, 5 a fan of 3 + b1 % 6 triangles around a vertex lifted
//           by b2, 6 an open cylinder of 3 + b1 % 4 x 1 + b2 % 2 squares,
//           7 one triangle; bit 3 boundary_alignment; bits 4-5 the features:
//           0 none (no edge_is_constrained_map), 1 random edges, 2 the sharp
//           edges, 3 both; bit 6 refine_for_quad_size() first; bit 7
//           keep_trimmed_boundary;
//   bytes 1, 2: the mesh's sizes;
//   byte 3: the quad size h, the mean edge length times 2^(b / 128) (1 .. 4: a
//           few quads, so that an execution takes about a millisecond);
//   byte 4: the stiffening rounds b % 2, fold_over_repair_rings (b / 2) % 8;
//   byte 5: the sharp-edge angle, b * 180 / 256 degrees;
//   byte 6: the size of the vertex displacements, up to 0.3 of the mean edge;
//   then 3 bytes per vertex (its displacement), then one bit per edge (random
//   features), then 3 bytes per face of the (refined) mesh: the angle of u,
//   the angle from u to v ((b + 64) * pi / 256: 0 is a right angle) and
//   |v| / |u| = 2^((b - 128) / 64).
// Any error code with a message is fine, but no crash and no exception. Checked:
//  - select_sharp_edge_constraints(): the marked edges are the border edges
//    (boundary_alignment only) and the interior edges whose dihedral angle is
//    above the threshold (clear cases: 0.01 degree away from it);
//  - refine_for_quad_size(): a valid triangle mesh, one origin per face, the
//    same area, no edge longer than 2 h, the feature length kept, and no
//    interior non-feature edge between two feature vertices;
//  - a failed map writes nothing; a SUCCESS map has seam and singularity
//    residuals 0, one transition per corner, and counts as features exactly
//    the marked edges and (boundary_alignment) the border edges;
//  - extract_quad_mesh() never says NOT_AN_INTEGER_GRID_MAP of a map that
//    compute_integer_grid_map() returned with SUCCESS, without flipped faces
//    and without singular points of valence 2 or less;
//  - a failed extraction writes no face; a SUCCESS quad mesh is a non-empty
//    valid polygon mesh of quads (polygons of at least 3 corners with
//    keep_trimmed_boundary, and then the Euler characteristic of the input),
//    as many faces as result.faces, no folded quad, no isolated vertex, finite
//    points, every vertex on the input surface (1e-9 of its size), and on a
//    closed input, closed quads of its Euler characteristic (whole cells, the
//    holes of cut-out fold-overs filled, components split into quads).

#include "fuzz_support.h"

#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/comb_frame_field.h>
#include <CGAL/Polyvector_fields/compute_integer_grid_map.h>
#include <CGAL/Polyvector_fields/extract_quad_mesh.h>
#include <CGAL/Polyvector_fields/polyvector_polynomial.h>
#include <CGAL/Polyvector_fields/refine_for_quad_size.h>
#include <CGAL/Polyvector_fields/select_sharp_edge_constraints.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <limits>
#include <map>
#include <vector>

namespace pvf_fuzz_quad_map {

using namespace pvf_fuzz;

typedef std::complex<double> Complex;
typedef PVF::Face_constraint<Face, Vector> Constraint;
typedef PVF::Tangent_bundle<Mesh> Bundle;
typedef std::array<double, 2> UV;
typedef Mesh::Edge_index Edge;

// Faces past which an execution stops (after the refinement): ~1 ms each.
const std::size_t max_faces = 32;

inline Mesh soup_mesh(const std::vector<Point>& points, const std::vector<std::vector<std::size_t> >& polygons)
{
  Mesh tm;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, tm);
  return tm;
}

inline Mesh base_mesh(std::uint8_t kind, std::uint8_t a, std::uint8_t b)
{
  Mesh tm;
  switch(kind % 8)
  {
    case 0: tm = grid(1 + a % 3, 1 + b % 2); break;
    case 1: CGAL::make_icosahedron(tm, Point(0, 0, 0), 1.0); break;
    case 2: CGAL::make_tetrahedron(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), tm); break;
    case 3:
      CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(0, 1, 1), Point(0, 0, 1),
                            Point(1, 0, 1), Point(1, 1, 1), tm);
      CGAL::Polygon_mesh_processing::triangulate_faces(tm);
      break;
    case 4:
      tm = soup_mesh({ Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0), Point(0, -1, 0), Point(0, 0, 1), Point(0, 0, -1) },
                     { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } });
      break;
    case 5:
    {
      const std::size_t n = 3 + a % 6;
      std::vector<Point> points{ Point(0, 0, (double(b) - 127.5) / 127.5) };
      std::vector<std::vector<std::size_t> > triangles;
      for(std::size_t k = 0; k < n; ++k)
      {
        points.emplace_back(std::cos(2 * CGAL_PI * double(k) / double(n)), std::sin(2 * CGAL_PI * double(k) / double(n)), 0);
        triangles.push_back({ 0, 1 + k, 1 + (k + 1) % n });
      }
      tm = soup_mesh(points, triangles);
      break;
    }
    case 6:
    {
      const std::size_t n = 3 + a % 4, rows = 1 + b % 2;
      std::vector<Point> points;
      std::vector<std::vector<std::size_t> > triangles;
      for(std::size_t i = 0; i <= rows; ++i)
        for(std::size_t k = 0; k < n; ++k)
          points.emplace_back(std::cos(2 * CGAL_PI * double(k) / double(n)), std::sin(2 * CGAL_PI * double(k) / double(n)),
                              double(i));
      for(std::size_t i = 0; i < rows; ++i)
        for(std::size_t k = 0; k < n; ++k)
        {
          const std::size_t p = i * n + k, q = i * n + (k + 1) % n;
          triangles.push_back({ p, q, q + n });
          triangles.push_back({ p, q + n, p + n });
        }
      tm = soup_mesh(points, triangles);
      break;
    }
    default: tm = soup_mesh({ Point(0, 0, 0), Point(1, 0, 0), Point(0.3, 0.9, 0) }, { { 0, 1, 2 } });
  }
  return tm;
}

inline double edge_length(Edge e, const Mesh& tm)
{
  return std::sqrt(CGAL::squared_distance(tm.point(source(e, tm)), tm.point(target(e, tm))));
}

// The angle in degrees between the normals of the two faces of an interior edge.
inline double dihedral_degrees(Edge e, const Mesh& tm)
{
  const auto h = halfedge(e, tm), o = opposite(h, tm);
  auto normal = [&tm](Mesh::Halfedge_index g) {
    const Point &p = tm.point(source(g, tm)), &q = tm.point(target(g, tm)), &r = tm.point(target(next(g, tm), tm));
    return CGAL::cross_product(q - p, r - p);
  };
  const Vector a = normal(h), b = normal(o);
  const double c = a * b / std::sqrt(a.squared_length() * b.squared_length());
  return std::acos((std::max)(-1.0, (std::min)(1.0, c))) * 180 / CGAL_PI;
}

inline bool finite(const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }


PVF_FUZZ_TARGET(quad_map)
{
  Byte_reader in{ data, size };
  const std::uint8_t flags = in.get(), a = in.get(), b = in.get(), size_byte = in.get(), rounds_byte = in.get(),
                     angle_byte = in.get(), jitter_byte = in.get();
  const bool border = (flags & 8) != 0, random_features = (flags & 16) != 0, sharp_features = (flags & 32) != 0,
             refine = (flags & 64) != 0, trimmed = (flags & 128) != 0, with_features = random_features || sharp_features;
  Mesh tm = base_mesh(flags, a, b);
  const double mean = mean_edge(tm);
  const double h = mean * std::exp2(double(size_byte) / 128);
  const std::size_t rounds = rounds_byte % 2, rings = (rounds_byte / 2) % 8;
  const double sharp_angle = double(angle_byte) * 180 / 256;
  const double jitter = double(jitter_byte) / 255 * 0.3 * mean;
  for(auto v : vertices(tm))
  {
    double d[3];
    for(double& x : d)
      x = (double(in.get()) - 127.5) / 127.5 * jitter;
    tm.point(v) = tm.point(v) + Vector(d[0], d[1], d[2]);
  }

  // the features
  auto features = tm.add_property_map<Edge, bool>("e:feature", false).first;
  const auto np_border = PVF::parameters::boundary_alignment(border);
  if(sharp_features)
  {
    std::vector<Constraint> constraints;
    const Error_code code =
      PVF::select_sharp_edge_constraints(tm, sharp_angle, 2, constraints, np_border.edge_is_constrained_map(features));
    if(code != Error_code::SUCCESS)
    {
      PVF_FUZZ_CHECK(code == Error_code::DEGENERATE_FACE, "select_sharp_edge_constraints: " + code_name(code));
      return;
    }
    for(Edge e : edges(tm))
    {
      if(tm.is_border(e))
      {
        PVF_FUZZ_CHECK(features[e] == border, "a border edge marked against boundary_alignment");
        continue;
      }
      // acos() near 1 loses half of the digits: a dihedral angle of ~1e-6
      // degree is 0 to detect_sharp_edges(); only clear cases are checked.
      const double angle = dihedral_degrees(e, tm);
      if(angle > sharp_angle + 1e-2)
        PVF_FUZZ_CHECK(features[e], "a sharp edge (" + std::to_string(angle) + " degrees) not marked");
      if(angle < sharp_angle - 1e-2)
        PVF_FUZZ_CHECK(!features[e], "an edge of " + std::to_string(angle) + " degrees marked sharp");
    }
  }
  if(random_features)
  {
    std::uint8_t bits = 0;
    std::size_t k = 0;
    for(Edge e : edges(tm))
    {
      if(k++ % 8 == 0)
        bits = in.get();
      if(bits & 1)
        features[e] = true;
      bits >>= 1;
    }
  }

  // the refinement
  if(refine)
  {
    const double area = CGAL::Polygon_mesh_processing::area(tm);
    double feature_length = 0;
    for(Edge e : edges(tm))
      feature_length += features[e] ? edge_length(e, tm) : 0;
    const std::size_t faces_before = num_faces(tm);
    std::vector<std::size_t> origin;
    const Error_code code =
      with_features ? PVF::refine_for_quad_size(tm, h, origin, np_border.edge_is_constrained_map(features))
                    : PVF::refine_for_quad_size(tm, h, origin, np_border);
    PVF_FUZZ_CHECK(code == Error_code::SUCCESS, "refine_for_quad_size: " + code_name(code));
    PVF_FUZZ_CHECK(CGAL::is_valid_polygon_mesh(tm) && CGAL::is_triangle_mesh(tm), "refined mesh not a valid triangle mesh");
    PVF_FUZZ_CHECK(origin.size() == num_faces(tm), "not one origin per refined face");
    for(std::size_t o : origin)
      PVF_FUZZ_CHECK(o < faces_before, "an origin out of range");
    const double refined_area = CGAL::Polygon_mesh_processing::area(tm);
    PVF_FUZZ_CHECK(std::abs(refined_area - area) <= 1e-9 * area, "the refinement changed the area");
    double refined_feature_length = 0;
    for(Edge e : edges(tm))
    {
      PVF_FUZZ_CHECK(edge_length(e, tm) <= 2 * h * (1 + 1e-12), "an edge longer than 2 h after the refinement");
      refined_feature_length += features[e] ? edge_length(e, tm) : 0;
    }
    PVF_FUZZ_CHECK(std::abs(refined_feature_length - feature_length) <= 1e-9 * (feature_length + mean),
                   "the refinement changed the feature length");
    if(with_features || border)
    {
      auto on_feature = [&](Vertex v) {
        for(auto g : CGAL::halfedges_around_target(v, tm))
          if((with_features && features[tm.edge(g)]) || (border && tm.is_border(tm.edge(g))))
            return true;
        return false;
      };
      for(Edge e : edges(tm))
        if(!tm.is_border(e) && !(with_features && features[e]))
          PVF_FUZZ_CHECK(!(on_feature(source(e, tm)) && on_feature(target(e, tm))),
                         "an interior edge between two feature vertices is left");
    }
  }
  if(num_faces(tm) > max_faces)
    return;

  // a random frame field: u and v per face, in the face's frame
  auto field = tm.add_property_map<Face, std::vector<Complex> >("f:field").first;
  for(Face f : faces(tm))
  {
    const double angle_u = double(in.get()) * 2 * CGAL_PI / 256;
    const double angle_uv = double(std::uint8_t(in.get() + 64)) * CGAL_PI / 256;
    const double length_v = std::exp2((double(in.get()) - 128) / 64);
    field[f] = PVF::sign_symmetric_polyvector_coefficients(
      { std::polar(1.0, angle_u), std::polar(length_v, angle_u + angle_uv) });
  }
  const Bundle bundle(tm);
  if(bundle.status() != Error_code::SUCCESS)
  {
    PVF_FUZZ_CHECK(bundle.status() == Error_code::DEGENERATE_FACE, "the bundle: " + code_name(bundle.status()));
    return;
  }
  PVF::Frame_field_comb<Bundle> comb;
  const Error_code comb_code = comb.compute(bundle, field, 10 * CGAL_PI / 180);
  if(comb_code != Error_code::SUCCESS)
  {
    PVF_FUZZ_CHECK(!comb.is_valid(), "a failed comb is valid");
    PVF_FUZZ_CHECK(std::string(PVF::get_error_message(comb_code)) != "unknown error", "comb: " + code_name(comb_code));
    return;
  }

  // the map
  std::map<Mesh::Halfedge_index, UV> uv;
  PVF::Integer_grid_map_result map;
  const auto np = PVF::parameters::target_edge_length(
    h, PVF::parameters::boundary_alignment(border, CGAL::parameters::number_of_iterations(rounds)));
  const Error_code map_code =
    with_features ? PVF::compute_integer_grid_map(comb, boost::make_assoc_property_map(uv), map,
                                                  np.edge_is_constrained_map(features))
                  : PVF::compute_integer_grid_map(comb, boost::make_assoc_property_map(uv), map, np);
  if(map_code != Error_code::SUCCESS)
  {
    PVF_FUZZ_CHECK(uv.empty(), "a failed map wrote values");
    PVF_FUZZ_CHECK(std::string(PVF::get_error_message(map_code)) != "unknown error", "map: " + code_name(map_code));
    return;
  }
  PVF_FUZZ_CHECK(map.max_seam_residual == 0, "seam residual " + std::to_string(map.max_seam_residual));
  PVF_FUZZ_CHECK(map.max_singularity_residual == 0, "singularity residual " + std::to_string(map.max_singularity_residual));
  PVF_FUZZ_CHECK(map.seam_transitions.size() == 3 * num_faces(tm), "one transition per corner");
  std::size_t marked = 0;
  for(Edge e : edges(tm))
    marked += ((with_features && features[e]) || (border && tm.is_border(e))) ? 1 : 0;
  PVF_FUZZ_CHECK(map.feature_edges == marked, std::to_string(map.feature_edges) + " feature edges counted, " +
                                                std::to_string(marked) + " marked");
  for(auto hh : halfedges(tm))
    if(!tm.is_border(hh))
      PVF_FUZZ_CHECK(uv.count(hh) == 1 && std::isfinite(uv[hh][0]) && std::isfinite(uv[hh][1]),
                     "a halfedge of a face without a finite uv");

  // the quads
  Mesh quads;
  PVF::Quad_extraction_result extraction;
  const Error_code quad_code =
    PVF::extract_quad_mesh(bundle, boost::make_assoc_property_map(uv), map, quads, extraction,
                           PVF::parameters::keep_trimmed_boundary(trimmed, PVF::parameters::fold_over_repair_rings(rings)));
  // Singular points of valence 2 or less make cells that share two edges: the
  // extraction refuses them (an open limitation, FOUND_BUGS.md).
  bool low_valence = false;
  for(int k : comb.data().index)
    low_valence = low_valence || k >= 2;
  if(map.flipped_faces == 0 && !low_valence)
    PVF_FUZZ_CHECK(quad_code != Error_code::NOT_AN_INTEGER_GRID_MAP,
                   "a checked map without flips refused by the extraction: " + extraction.diagnostic + " (" +
                     std::to_string(num_faces(tm)) + " faces, " + std::to_string(map.feature_edges) + " feature edges, " +
                     std::to_string(map.aligned_feature_edges) + " aligned, boundary alignment " +
                     std::to_string(border) + ", trimmed " + std::to_string(trimmed) + ", " +
                     std::to_string(extraction.integer_points) + " integer points, " +
                     std::to_string(extraction.singular_points) + " singular, " +
                     std::to_string(extraction.degenerate_uv_edges) + " degenerate uv edges, " +
                     std::to_string(extraction.repaired_regions) + " repaired regions)");
  if(quad_code != Error_code::SUCCESS)
  {
    PVF_FUZZ_CHECK(num_faces(quads) == 0 && num_vertices(quads) == 0, "a failed extraction wrote the mesh");
    PVF_FUZZ_CHECK(std::string(PVF::get_error_message(quad_code)) != "unknown error", "extraction: " + code_name(quad_code));
    return;
  }
  PVF_FUZZ_CHECK(num_faces(quads) > 0, "an empty quad mesh returned with SUCCESS");
  PVF_FUZZ_CHECK(extraction.faces == num_faces(quads), "result.faces is not the number of faces");
  PVF_FUZZ_CHECK(extraction.folded_quads == 0, "folded quads on SUCCESS");
  PVF_FUZZ_CHECK(CGAL::is_valid_polygon_mesh(quads), "the quad mesh is not a valid polygon mesh");
  for(auto f : faces(quads))
  {
    const std::size_t corners = CGAL::halfedges_around_face(halfedge(f, quads), quads).size();
    if(trimmed)
      PVF_FUZZ_CHECK(corners >= 3, "a face of fewer than 3 corners");
    else
      PVF_FUZZ_CHECK(corners == 4, "a face that is not a quad");
  }
  for(auto v : vertices(quads))
    PVF_FUZZ_CHECK(halfedge(v, quads) != boost::graph_traits<Mesh>::null_halfedge(), "an isolated quad vertex");
  // a closed surface gets a closed quad mesh of its topology (holes of fold-overs filled,
  // components split into quads included)
  if(!trimmed && CGAL::is_closed(tm))
    PVF_FUZZ_CHECK(CGAL::is_closed(quads) &&
                     long(num_vertices(quads)) - long(num_edges(quads)) + long(num_faces(quads)) ==
                       long(num_vertices(tm)) - long(num_edges(tm)) + long(num_faces(tm)),
                   "the quads of a closed surface are not closed, or not of its Euler characteristic");
  // the trimmed polygons cover the surface: same Euler characteristic (cells that
  // go around a cylinder are cut into disks, FOUND_BUGS.md)
  if(trimmed)
    PVF_FUZZ_CHECK(long(num_vertices(quads)) - long(num_edges(quads)) + long(num_faces(quads)) ==
                     long(num_vertices(tm)) - long(num_edges(tm)) + long(num_faces(tm)),
                   "the trimmed polygons do not have the Euler characteristic of the surface");
  CGAL::Bbox_3 box;
  for(auto v : vertices(tm))
    box += tm.point(v).bbox();
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  for(auto v : vertices(quads))
  {
    PVF_FUZZ_CHECK(finite(quads.point(v)), "a quad vertex is not finite");
    const double d = distance_to_surface(quads.point(v), tm);
    PVF_FUZZ_CHECK(d <= 1e-9 * diagonal, "a quad vertex " + std::to_string(d) + " off the surface");
  }
}

} // namespace pvf_fuzz_quad_map
