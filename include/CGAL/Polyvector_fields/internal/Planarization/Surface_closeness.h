// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_PLANARIZATION_SURFACE_CLOSENESS_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_PLANARIZATION_SURFACE_CLOSENESS_H

// How the planarization of a quad mesh stays on its reference surface, and
// how its result is checked to still cover it:
// - Closest_points: the closest points of the vertices on the reference
//   (an AABB tree of its triangles), for the closeness terms of both methods
//   and the distance bound;
// - Feature_closeness: the border of the input quad mesh and the creases of
//   the reference, which the vertices on them may not leave: they slide along
//   them, and their corners stay where they were;
// - Surface_coverage: the other side of that distance, the largest distance
//   from the surface to the quads, which a planarization may not raise by
//   more than the distance bound.

#include <CGAL/Polyvector_fields/internal/parallel.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/property_map/property_map.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// Closest points on a triangle mesh, each query hinted by the previous answer
// for the same vertex (the vertices move little per iteration).
template <typename TriangleMesh, typename ReferencePointMap>
class Closest_points
{
  typedef typename boost::property_traits<ReferencePointMap>::value_type Ref_point;
  typedef typename CGAL::Kernel_traits<Ref_point>::Kernel K;
  typedef CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, ReferencePointMap> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;

public:
  Closest_points(const TriangleMesh& reference, ReferencePointMap rpm)
    : m_tree(faces(reference).first, faces(reference).second, reference, rpm)
  {
    m_tree.build();  // before the queries share it
    m_tree.accelerate_distance_queries();
  }

  // For the Gauss-Newton method: the closest points S of the rows of Y and
  // their distances, each query hinted by the previous answer of this method
  // for the same row (the first ones by the tree's own search).
  void hinted_by_own(const Eigen::MatrixXd& Y, Eigen::MatrixXd& S, std::vector<double>& distance, bool parallel)
  {
    const bool hinted = m_own_hints.rows() == Y.rows();
    if(!hinted)
      m_own_hints.resize(Y.rows(), 3);
    query(Y, hinted, m_own_hints, distance, parallel);
    S = m_own_hints;
  }

  // S receives the closest points of the rows of Y, and `distance` their
  // distances, each query hinted by the previous answer in S.
  // The queries are independent (the tree is only read): with `parallel`,
  // the cores share them.
  void operator()(const Eigen::MatrixXd& Y, Eigen::MatrixXd& S, std::vector<double>& distance, bool parallel)
  {
    if(!m_have_hint)
      S.resize(Y.rows(), 3);
    query(Y, m_have_hint, S, distance, parallel);
    m_have_hint = true;
  }

private:
  // The closest points of the rows of Y into S, hinted by the rows of S
  // when `hinted`, and their distances.
  void query(const Eigen::MatrixXd& Y, bool hinted, Eigen::MatrixXd& S, std::vector<double>& distance, bool parallel) const
  {
    const std::size_t n = std::size_t(Y.rows());
    distance.resize(n);
    for_each_range(parallel, n, 1024, [&](std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i)
      {
        const Eigen::Index r = Eigen::Index(i);
        const typename K::Point_3 q(Y(r, 0), Y(r, 1), Y(r, 2));
        const typename K::Point_3 s = hinted ? m_tree.closest_point(q, typename K::Point_3(S(r, 0), S(r, 1), S(r, 2)))
                                             : m_tree.closest_point(q);
        S(r, 0) = CGAL::to_double(s.x());
        S(r, 1) = CGAL::to_double(s.y());
        S(r, 2) = CGAL::to_double(s.z());
        distance[i] = std::sqrt(CGAL::to_double(CGAL::squared_distance(q, s)));
      }
    });
  }

  Tree m_tree;
  bool m_have_hint = false;
  Eigen::MatrixXd m_own_hints;
};

// The unit normals of a quad mesh at its vertices, rows of positions Y: the
// normalized sum of the cross products of the diagonals of its quads (zero
// where that sum is).
inline Eigen::MatrixXd quad_vertex_normals(const Eigen::MatrixXd& Y, const std::vector<std::array<std::size_t, 4> >& quads)
{
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(Y.rows(), 3);
  for(const auto& q : quads)
  {
    const Eigen::Vector3d d1 = (Y.row(Eigen::Index(q[2])) - Y.row(Eigen::Index(q[0]))).transpose();
    const Eigen::Vector3d d2 = (Y.row(Eigen::Index(q[3])) - Y.row(Eigen::Index(q[1]))).transpose();
    const Eigen::RowVector3d c = d1.cross(d2).transpose();
    for(std::size_t k = 0; k < 4; ++k)
      M.row(Eigen::Index(q[k])) += c;
  }
  for(Eigen::Index i = 0; i < M.rows(); ++i)
  {
    const double length = M.row(i).norm();
    if(length > 0)
      M.row(i) /= length;
  }
  return M;
}

// The creases of the reference, for Feature_closeness: its edges between two
// faces whose normals make an angle above `angle_in_degrees`
// (CGAL::Polygon_mesh_processing::detect_sharp_edges(), which also marks the
// border edges: they are left out).
template <typename TriangleMesh, typename ReferencePointMap>
std::vector<CGAL::Simple_cartesian<double>::Segment_3> reference_creases(const TriangleMesh& reference,
                                                                         ReferencePointMap rpm, double angle_in_degrees)
{
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  typedef typename CGAL::Kernel_traits<typename boost::property_traits<ReferencePointMap>::value_type>::Kernel Kernel;
  typedef CGAL::Simple_cartesian<double> K;
  std::map<edge_descriptor, bool> sharp_flags;
  boost::associative_property_map<std::map<edge_descriptor, bool> > is_sharp(sharp_flags);
  CGAL::Polygon_mesh_processing::detect_sharp_edges(reference, typename Kernel::FT(angle_in_degrees), is_sharp,
                                                    CGAL::parameters::vertex_point_map(rpm));
  std::vector<K::Segment_3> creases;
  for(edge_descriptor e : edges(reference))
    if(get(is_sharp, e) && !CGAL::is_border(e, reference))
    {
      const auto& a = get(rpm, source(e, reference));
      const auto& b = get(rpm, target(e, reference));
      creases.emplace_back(K::Point_3(CGAL::to_double(a.x()), CGAL::to_double(a.y()), CGAL::to_double(a.z())),
                           K::Point_3(CGAL::to_double(b.x()), CGAL::to_double(b.y()), CGAL::to_double(b.z())));
    }
  return creases;
}

// The feature curves of the input quad mesh: its border, and the creases of
// the reference it follows. Along a free boundary the surface goes on beyond
// the quads, so a pull towards the closest point of the surface lets a border
// vertex slide inwards, and the quads shrink away from the border; on a crease
// the closest point lets a vertex slide off it, and the quads cut the crease.
// So the closeness target of a vertex on a feature curve is changed:
// - BORDER, a vertex of a run of the border (degree 3, between two border
//   edges that turn by at most the crease angle): it keeps the surface's closest point s along the normal m
//   and along the tangent t of the closest edge of the input's border
//   polyline, but takes the polyline's closest point p along the third
//   direction b = m x t (in the surface, across the border): its target is
//   s + b (b . (p - s)), and the Gauss-Newton method weighs (b . (x - target))^2
//   as much as the pull along the normal: it slides along the border only;
// - CREASE, a vertex on the reference's sharp edges (within 1% of the mean
//   quad edge) with exactly two quad edges along them (both ends on them,
//   the midpoint within a quarter of the edge's length), which turn by at
//   most the crease angle: its target is the closest point of the sharp
//   edges (of any crease: near where creases meet, the corners hold the
//   quads), and the Gauss-Newton method weighs
//   |(I - t t^T)(x - target)|^2, t the direction of the closest sharp edge:
//   it slides along the crease only;
// - CORNER, any other border vertex, a border vertex with a quad edge along
//   the sharp edges, or a vertex with one or more than two of them, or two
//   that turn by more than the crease angle (a corner of the border, where a
//   crease meets the border, an end or a corner of a crease): its target is
//   its input position, in every direction.
// A vertex on the sharp edges with no quad edge along them is not on a crease
// that the quads follow (a quad's diagonal on a crease, say): it stays
// INTERIOR.
class Feature_closeness
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef std::vector<K::Segment_3>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, Iterator> > > Tree;

public:
  enum Kind : char { INTERIOR = 0, BORDER = 1, CREASE = 2, CORNER = 3 };

  Feature_closeness(const Feature_closeness&) = delete;  // the trees point into the segments
  Feature_closeness& operator=(const Feature_closeness&) = delete;

  // X0: the input positions; border_kind: of each vertex, INTERIOR, BORDER or
  // CORNER; border_edges: the border edges of the input, and quad_edges all
  // its edges, as pairs of vertices; creases: the reference's sharp edges;
  // edge: the mean quad edge; turn_in_degrees: the turn of the border or of a
  // crease at a vertex above which the vertex is a CORNER
  Feature_closeness(const Eigen::MatrixXd& X0, const std::vector<std::array<std::size_t, 4> >& quads,
                    std::vector<char> border_kind, const std::vector<std::array<std::size_t, 2> >& border_edges,
                    const std::vector<std::array<std::size_t, 2> >& quad_edges, std::vector<K::Segment_3> creases,
                    double edge, double turn_in_degrees)
    : m_X0(X0), m_normals(quad_vertex_normals(X0, quads)), m_kind(std::move(border_kind)),
      m_creases(std::move(creases))
  {
    const std::size_t n = m_kind.size();
    const double cos_turn = std::cos(turn_in_degrees * CGAL_PI / 180);
    // a vertex whose two feature edges (to a and b) turn by more than the
    // angle is a CORNER
    auto turns = [&](std::size_t i, std::size_t a, std::size_t b) {
      const Eigen::Vector3d in = (X0.row(Eigen::Index(i)) - X0.row(Eigen::Index(a))).transpose();
      const Eigen::Vector3d out = (X0.row(Eigen::Index(b)) - X0.row(Eigen::Index(i))).transpose();
      const double lengths = in.norm() * out.norm();
      return !(lengths > 0) || in.dot(out) < cos_turn * lengths;
    };
    std::vector<std::vector<std::size_t> > along(n);  // the feature edges at each vertex
    for(const auto& e : border_edges)
    {
      m_border_segments.emplace_back(point(X0, e[0]), point(X0, e[1]));
      along[e[0]].push_back(e[1]);
      along[e[1]].push_back(e[0]);
    }
    for(std::size_t i = 0; i < n; ++i)
      if(m_kind[i] == BORDER && (along[i].size() != 2 || turns(i, along[i][0], along[i][1])))
        m_kind[i] = CORNER;
    build(m_border_tree, m_border_segments);
    build(m_crease_tree, m_creases);
    if(!m_creases.empty())
    {
      // the vertices on the creases, and the quad edges along them (of
      // non-zero length, both ends on the creases and the midpoint near them)
      const double tolerance = 0.01 * edge;
      std::vector<char> on_crease(n, 0);
      for(std::size_t i = 0; i < n; ++i)
        on_crease[i] = distance_to_creases(point(X0, i)) <= tolerance;
      std::vector<std::vector<std::size_t> > crease_along(n);
      for(const auto& e : quad_edges)
        if(on_crease[e[0]] && on_crease[e[1]])
        {
          const K::Point_3 a = point(X0, e[0]), b = point(X0, e[1]);
          const double length = std::sqrt(CGAL::squared_distance(a, b));
          if(length > 0 && distance_to_creases(CGAL::midpoint(a, b)) <= 0.25 * length)
          {
            crease_along[e[0]].push_back(e[1]);
            crease_along[e[1]].push_back(e[0]);
          }
        }
      for(std::size_t i = 0; i < n; ++i)
        if(!crease_along[i].empty())
          m_kind[i] = m_kind[i] == INTERIOR && crease_along[i].size() == 2 &&
                          !turns(i, crease_along[i][0], crease_along[i][1])
                        ? CREASE
                        : CORNER;
    }
    for(std::size_t i = 0; i < n; ++i)
      if(m_kind[i] != INTERIOR)
        m_features.push_back(i);
  }

  const std::vector<char>& kind() const { return m_kind; }
  // the unit normals of the input quad mesh at its vertices (quad_vertex_normals())
  const Eigen::MatrixXd& normals() const { return m_normals; }

  // For the vertices on feature curves at positions X, whose closest points
  // on the surface are the rows of S at `distance`: their targets into those
  // rows of S; into the rows of D the unit direction b of a BORDER vertex or
  // t of a CREASE vertex (zero for the others); and into `distance` the
  // larger of the distance to the surface and the distance to the feature
  // (across the border for a BORDER vertex, to the creases for a CREASE
  // vertex, to its input position for a CORNER), so that a vertex may leave
  // neither by more than the distance bound.
  void targets(const Eigen::MatrixXd& X, Eigen::MatrixXd& S, Eigen::MatrixXd& D, std::vector<double>& distance) const
  {
    D.setZero(X.rows(), 3);
    for(std::size_t i : m_features)
    {
      const Eigen::Index r = Eigen::Index(i);
      if(m_kind[i] == CORNER)
      {
        S.row(r) = m_X0.row(r);
        distance[i] = (std::max)(distance[i], (X.row(r) - S.row(r)).norm());
        continue;
      }
      const Tree& tree = m_kind[i] == BORDER ? m_border_tree : m_crease_tree;
      const auto found = tree.closest_point_and_primitive(point(X, i));
      const Eigen::RowVector3d p(found.first.x(), found.first.y(), found.first.z());
      const K::Vector_3 v = found.second->to_vector();
      const Eigen::Vector3d t(v.x(), v.y(), v.z());
      if(m_kind[i] == CREASE)
      {
        S.row(r) = p;
        if(t.norm() > 0)
          D.row(r) = t.normalized().transpose();
        distance[i] = (std::max)(distance[i], (X.row(r) - p).norm());
        continue;
      }
      const Eigen::Vector3d m = m_normals.row(r).transpose();
      const Eigen::Vector3d b = m.cross(t);
      if(!(b.norm() > 0))
        continue;  // a border edge of zero length, or along the normal: the surface's point
      D.row(r) = b.normalized().transpose();
      S.row(r) += D.row(r).dot(p - S.row(r)) * D.row(r);
      distance[i] = (std::max)(distance[i], std::abs(D.row(r).dot(X.row(r) - p)));
    }
  }

private:
  static K::Point_3 point(const Eigen::MatrixXd& X, std::size_t i)
  {
    return K::Point_3(X(Eigen::Index(i), 0), X(Eigen::Index(i), 1), X(Eigen::Index(i), 2));
  }
  static void build(Tree& tree, const std::vector<K::Segment_3>& segments)
  {
    if(segments.empty())
      return;
    tree.insert(segments.begin(), segments.end());
    tree.build();
    tree.accelerate_distance_queries();
  }
  double distance_to_creases(const K::Point_3& q) const { return std::sqrt(m_crease_tree.squared_distance(q)); }

  Eigen::MatrixXd m_X0;
  Eigen::MatrixXd m_normals;
  std::vector<char> m_kind;
  std::vector<std::size_t> m_features;
  std::vector<K::Segment_3> m_border_segments, m_creases;
  Tree m_border_tree, m_crease_tree;
};

// The other side of the distance to the surface. Every vertex of the result
// may be on the surface while the quads no longer cover it: border vertices
// that slide inwards along the surface leave a strip uncovered, vertices that
// slide off a crease cut it. The surface is sampled at the vertices of the
// reference and of the input quad mesh, each quad is taken as the four
// triangles of its two diagonals, and the largest distance from a sample to
// the quads is measured, for the input quads once and for a result. A result
// may exceed the input's by at most the distance bound: the input's figure
// already holds what the quads cannot cover (the sagitta of a quad on a
// curved surface, the strip left along a free boundary).
class Surface_coverage
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef std::vector<K::Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Iterator> > > Tree;

public:
  // X0: the input positions of the quads' vertices
  template <typename TriangleMesh, typename ReferencePointMap>
  Surface_coverage(const TriangleMesh& reference, ReferencePointMap rpm, const Eigen::MatrixXd& X0,
                   const std::vector<std::array<std::size_t, 4> >& quads, bool parallel)
    : m_quads(quads), m_parallel(parallel)
  {
    for(auto v : vertices(reference))
    {
      const auto& p = get(rpm, v);
      m_samples.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    }
    for(Eigen::Index i = 0; i < X0.rows(); ++i)
      m_samples.emplace_back(X0(i, 0), X0(i, 1), X0(i, 2));
    m_input = largest_distance(X0);
  }

  // the largest distance from a sample to the input quads
  double input() const { return m_input; }

  // the largest distance from a sample to the quads at positions X
  double largest_distance(const Eigen::MatrixXd& X) const
  {
    if(m_quads.empty() || m_samples.empty())
      return 0;
    auto point = [&X](std::size_t i) { return K::Point_3(X(Eigen::Index(i), 0), X(Eigen::Index(i), 1), X(Eigen::Index(i), 2)); };
    std::vector<K::Triangle_3> triangles;
    triangles.reserve(4 * m_quads.size());
    for(const auto& q : m_quads)
      for(std::size_t k = 0; k < 4; ++k)
        triangles.emplace_back(point(q[k]), point(q[(k + 1) % 4]), point(q[(k + 2) % 4]));
    Tree tree(triangles.begin(), triangles.end());
    tree.build();  // before the queries share it
    tree.accelerate_distance_queries();
    std::vector<double> distance(m_samples.size());
    for_each_range(m_parallel, m_samples.size(), 1024, [&](std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i)
        distance[i] = std::sqrt(tree.squared_distance(m_samples[i]));
    });
    return *std::max_element(distance.begin(), distance.end());
  }

private:
  const std::vector<std::array<std::size_t, 4> >& m_quads;
  bool m_parallel;
  std::vector<K::Point_3> m_samples;
  double m_input = 0;
};

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_PLANARIZATION_SURFACE_CLOSENESS_H
