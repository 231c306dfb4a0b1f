// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_SHARP_EDGE_CONSTRAINTS_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_SHARP_EDGE_CONSTRAINTS_H

// The work of select_sharp_edge_constraints(): CGAL's detect_sharp_edges()
// finds the candidate edges; each face beside a sharp edge collects the
// edge's dihedral angle and unit direction, and keeps the directions of its
// sharpest edges.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Face_constraint.h>
#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>

#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The angle between the normals of the two faces of an interior edge, in
// radians, in [0, pi]; from the faces' frames (see face_frame()).
inline double dihedral_normal_angle(const Face_frame& a, const Face_frame& b)
{
  const double cosine = a.normal[0] * b.normal[0] + a.normal[1] * b.normal[1] + a.normal[2] * b.normal[2];
  return std::acos((std::max)(-1.0, (std::min)(1.0, cosine)));
}

// Two sharp edges that meet at a vertex where no other sharp edge (nor the
// border) meets continue one crease curve when they turn by at most this
// angle there; beyond, the vertex is a corner of the crease network.
constexpr double crease_curve_max_turn_degrees = 45;

// Drops the noise among the kept sharp edges (`Kept`: e, border), the creases
// too short for the quads that will follow them:
// - every edge of a network (sharp edges connected through their vertices,
//   the border aside) shorter than `minimum_length` in all;
// - every edge of a crease curve shorter than `minimum_length`, unless both
//   of its ends are junctions, where three or more sharp or border edges
//   meet (the edge of a box between two corners; the border counts whether
//   it is kept or not). A crease curve is a chain
//   of sharp edges through vertices where exactly two of them meet, at a turn
//   of at most crease_curve_max_turn_degrees: on a scan, the sharp edges at
//   a given dihedral angle make short zigzags, which turn at almost every
//   vertex; on a CAD model they are long curves that meet at corners.
// The border edges are kept.
template <typename TriangleMesh, typename VertexPointMap, typename Kept>
void drop_short_creases(const TriangleMesh& tm, VertexPointMap vpm, double minimum_length, std::vector<Kept>& kept)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  std::map<vertex_descriptor, std::size_t> node_of;
  std::vector<vertex_descriptor> nodes;
  auto node = [&](vertex_descriptor v) {
    const auto inserted = node_of.emplace(v, nodes.size());
    if(inserted.second)
      nodes.push_back(v);
    return inserted.first->second;
  };
  auto point = [&](std::size_t n) { return to_array(get(vpm, nodes[n])); };
  // the sharp edges (indices into kept) with their two nodes and length
  std::vector<std::size_t> sharp;
  std::vector<std::array<std::size_t, 2> > ends;
  std::vector<double> length;
  for(std::size_t i = 0; i < kept.size(); ++i)
  {
    if(kept[i].border)
      continue;
    const auto h = halfedge(kept[i].e, tm);
    const std::size_t a = node(source(h, tm)), b = node(target(h, tm));
    // the length in mesh units: scaled first, so that its square cannot overflow
    std::array<double, 3> pa = point(a), pb = point(b);
    const int e = scale_to_unit({ &pa, &pb });
    const auto d = difference(pb, pa);
    sharp.push_back(i);
    ends.push_back({ a, b });
    length.push_back(std::ldexp(std::sqrt(dot(d, d)), e));
  }
  std::vector<std::vector<std::size_t> > incident(nodes.size());  // sharp edges (positions in `sharp`)
  std::vector<std::size_t> border_degree(nodes.size(), 0);
  for(std::size_t s = 0; s < sharp.size(); ++s)
    for(std::size_t n : ends[s])
      incident[n].push_back(s);
  // the border edges at each node, kept or not (a crease that ends on the
  // border of an open box ends at a corner)
  for(std::size_t n = 0; n < nodes.size(); ++n)
    for(const auto h : CGAL::halfedges_around_target(nodes[n], tm))
      border_degree[n] += CGAL::is_border_edge(h, tm) ? 1 : 0;
  auto is_junction = [&](std::size_t n) { return incident[n].size() + border_degree[n] >= 3; };

  // union-find over the sharp edges: one for networks, one for curves
  auto make_sets = [&]() {
    std::vector<std::size_t> up(sharp.size());
    for(std::size_t s = 0; s < up.size(); ++s)
      up[s] = s;
    return up;
  };
  auto root = [](std::vector<std::size_t>& up, std::size_t x) {
    while(up[x] != x)
      x = up[x] = up[up[x]];
    return x;
  };
  std::vector<std::size_t> network = make_sets(), curve = make_sets();
  std::vector<std::size_t> curve_ends(sharp.size(), 0), junction_ends(sharp.size(), 0);
  std::vector<char> joined(nodes.size(), 0);  // the two sharp edges of the node continue one curve there
  const double max_turn = crease_curve_max_turn_degrees * CGAL_PI / 180.0;
  for(std::size_t n = 0; n < nodes.size(); ++n)
  {
    const std::vector<std::size_t>& here = incident[n];
    for(std::size_t k = 1; k < here.size(); ++k)
      network[root(network, here[k])] = root(network, here[0]);
    bool continues = false;
    if(here.size() == 2 && border_degree[n] == 0)
    {
      // the turn between the incoming direction (p to n) and the outgoing one (n to q)
      const std::size_t p = ends[here[0]][0] == n ? ends[here[0]][1] : ends[here[0]][0];
      const std::size_t q = ends[here[1]][0] == n ? ends[here[1]][1] : ends[here[1]][0];
      const auto in = scaled_difference(point(n), point(p)), out = scaled_difference(point(q), point(n));
      const double norms = std::sqrt(dot(in, in) * dot(out, out));
      continues = norms > 0 && std::acos((std::max)(-1.0, (std::min)(1.0, dot(in, out) / norms))) <= max_turn;
    }
    if(continues)
      curve[root(curve, here[1])] = root(curve, here[0]);
    joined[n] = continues ? 1 : 0;
  }
  for(std::size_t n = 0; n < nodes.size(); ++n)
  {
    if(joined[n])
      continue;
    for(std::size_t s : incident[n])
    {
      const std::size_t c = root(curve, s);
      ++curve_ends[c];
      junction_ends[c] += is_junction(n) ? 1 : 0;
    }
  }
  std::vector<double> network_length(sharp.size(), 0), curve_length(sharp.size(), 0);
  for(std::size_t s = 0; s < sharp.size(); ++s)
  {
    network_length[root(network, s)] += length[s];
    curve_length[root(curve, s)] += length[s];
  }
  std::vector<char> drop(kept.size(), 0);
  for(std::size_t s = 0; s < sharp.size(); ++s)
  {
    const std::size_t c = root(curve, s);
    const bool between_junctions = curve_ends[c] == 2 && junction_ends[c] == 2;
    drop[sharp[s]] = network_length[root(network, s)] < minimum_length ||
                     (curve_length[c] < minimum_length && !between_junctions);
  }
  std::size_t w = 0;
  for(std::size_t i = 0; i < kept.size(); ++i)
    if(!drop[i])
      kept[w++] = kept[i];
  kept.resize(w);
}

// See select_sharp_edge_constraints(). `vpm` gives the points, `np` goes to
// detect_sharp_edges() (vertex_point_map, geom_traits).
// `with_border`: border edges are kept too; the creases shorter than
// `minimum_length` are dropped (drop_short_creases()); `feature_edge(e, kept)` is called
// once per edge, after the faces' checks, with whether it was kept.
template <typename TriangleMesh, typename VertexPointMap, typename FaceDescriptor, typename Vector_3,
          typename NamedParameters, typename FeatureEdgeOutput>
Error_code select_sharp_edge_constraints(const TriangleMesh& tm,
                                         double angle_in_degrees,
                                         std::size_t maximum_vectors_per_face,
                                         VertexPointMap vpm,
                                         bool with_border,
                                         double minimum_length,
                                         std::vector<Face_constraint<FaceDescriptor, Vector_3> >& out,
                                         const NamedParameters& np,
                                         FeatureEdgeOutput feature_edge)
{
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::face_descriptor face_descriptor;
  typedef typename Graph_traits::edge_descriptor edge_descriptor;
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;

  // The faces, numbered in the order of faces(tm), with their frames.
  std::vector<face_descriptor> face_list;
  Numbering<face_descriptor> face_index;
  std::vector<Face_frame> frames;
  for(face_descriptor f : faces(tm))
  {
    Face_frame frame;
    const Error_code code = face_frame(f, tm, frame, CGAL::parameters::vertex_point_map(vpm));
    if(code != Error_code::SUCCESS)
      return code;
    face_index.add(f);
    face_list.push_back(f);
    frames.push_back(frame);
  }
  if(face_list.empty())
    return Error_code::EMPTY_MESH;

  // CGAL's test is "at least the angle", and it marks border edges too; an
  // edge here is sharp when the angle between the normals strictly exceeds
  // the threshold, and an edge of two faces.
  std::map<edge_descriptor, bool> sharp_flags;
  boost::associative_property_map<std::map<edge_descriptor, bool> > is_sharp(sharp_flags);
  CGAL::Polygon_mesh_processing::detect_sharp_edges(tm, typename Geom_traits::FT(angle_in_degrees), is_sharp, np);
  const double threshold = angle_in_degrees * CGAL_PI / 180.0;

  // The kept edges with their angle: a border edge, with boundary_alignment,
  // counts as the sharpest (angle pi).
  struct Kept
  {
    edge_descriptor e;
    double angle;
    bool border;
  };
  std::vector<Kept> kept;
  std::vector<edge_descriptor> all_edges;
  for(edge_descriptor e : edges(tm))
  {
    all_edges.push_back(e);
    const auto h = halfedge(e, tm);
    if(CGAL::is_border_edge(h, tm))
    {
      if(with_border)
        kept.push_back(Kept{ e, CGAL_PI, true });
    }
    else if(get(is_sharp, e))
    {
      const double angle =
        dihedral_normal_angle(frames[face_index(face(h, tm))], frames[face_index(face(opposite(h, tm), tm))]);
      if(angle > threshold)
        kept.push_back(Kept{ e, angle, false });
    }
  }
  if(minimum_length > 0)
    drop_short_creases(tm, vpm, minimum_length, kept);
  std::set<edge_descriptor> kept_set;
  for(const Kept& k : kept)
    kept_set.insert(k.e);
  for(edge_descriptor e : all_edges)
    feature_edge(e, kept_set.count(e) > 0);

  // (dihedral angle, unit direction) of the kept edges of each face, in the order of edges(tm).
  std::vector<std::vector<std::pair<double, std::array<double, 3> > > > edges_of_face(face_list.size());
  for(const Kept& k : kept)
  {
    const auto h = halfedge(k.e, tm);
    // The direction, scaled first so that its squared length cannot overflow.
    std::array<double, 3> d = scaled_difference(to_array(get(vpm, target(h, tm))), to_array(get(vpm, source(h, tm))));
    const double length = std::sqrt(dot(d, d));
    d = { d[0] / length, d[1] / length, d[2] / length };
    for(const auto g : { h, opposite(h, tm) })
      if(!CGAL::is_border(g, tm))
        edges_of_face[face_index(face(g, tm))].emplace_back(k.angle, d);
  }

  std::vector<Face_constraint<FaceDescriptor, Vector_3> > result;
  for(std::size_t f = 0; f < face_list.size(); ++f)
  {
    auto& list = edges_of_face[f];
    if(list.empty())
      continue;
    std::sort(list.begin(), list.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    Face_constraint<FaceDescriptor, Vector_3> c;
    c.face = face_list[f];
    for(std::size_t i = 0; i < list.size() && i < maximum_vectors_per_face; ++i)
      c.vectors.push_back(Vector_3(list[i].second[0], list[i].second[1], list[i].second[2]));
    result.push_back(c);
  }
  out.swap(result);
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FIELD_DESIGN_SHARP_EDGE_CONSTRAINTS_H
