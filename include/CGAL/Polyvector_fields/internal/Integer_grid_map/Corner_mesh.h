// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The mesh by corners, on a tangent bundle: the numbering that the combing,
// the cut and the integer-grid map share.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_CORNER_MESH_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_CORNER_MESH_H

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The BGL calls of Corner_mesh, outside of it: its members named halfedge,
// target, next and opposite would hide the BGL functions. Unqualified, these
// are found by argument-dependent lookup where the mesh type declares them
// (in namespace OpenMesh for OpenMesh, for instance), whatever the order of
// the includes.

// The three halfedges of face f from halfedge(f, tm), and their targets.
template <typename TriangleMesh>
void face_corners(typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& tm,
                  std::array<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor, 3>& h,
                  std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 3>& v)
{
  h[0] = halfedge(f, tm);
  h[1] = next(h[0], tm);
  h[2] = next(h[1], tm);
  for(std::size_t k = 0; k < 3; ++k)
    v[k] = target(h[k], tm);
}

// The opposite of h, or the null halfedge if it is a border halfedge.
template <typename TriangleMesh>
typename boost::graph_traits<TriangleMesh>::halfedge_descriptor
interior_opposite(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, const TriangleMesh& tm)
{
  const auto o = opposite(h, tm);
  return CGAL::is_border(o, tm) ? boost::graph_traits<TriangleMesh>::null_halfedge() : o;
}

// ---------------------------------------------------------------------------
// The mesh by corners, on a tangent bundle: corner 3f+k is the k-th halfedge of
// face f (the bundle's face index), starting at halfedge(f). Vertices, frames
// and components are the bundle's; only the corners are numbered here.
// ---------------------------------------------------------------------------
template <typename Bundle>
struct Corner_mesh
{
  typedef typename Bundle::Triangle_mesh TriangleMesh;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  const Bundle& bundle;
  const TriangleMesh& tm;
  std::size_t F = 0, V = 0;
  Numbering<halfedge_descriptor> corner_index;
  std::vector<std::array<double, 3> > point;      // per vertex index
  std::vector<char> border_vertex;                // per vertex index
  std::vector<halfedge_descriptor> halfedge;      // per corner
  std::vector<std::size_t> target, opposite;      // per corner; opposite = npos on the border
  std::vector<std::size_t> vertex_corner;         // per vertex: one corner whose target it is (npos: isolated)

  explicit Corner_mesh(const Bundle& b) : bundle(b), tm(b.mesh())
  {
    if(bundle.status() != Error_code::SUCCESS)
      return;
    V = bundle.number_of_vertices();
    F = bundle.number_of_faces();
    point.reserve(V);
    for(std::size_t v = 0; v < V; ++v)
      point.push_back(bundle.point(v));
    border_vertex.assign(V, 0);
    halfedge.resize(3 * F);
    target.resize(3 * F);
    opposite.assign(3 * F, npos);
    vertex_corner.assign(V, npos);
    for(std::size_t f = 0; f < F; ++f)
    {
      std::array<halfedge_descriptor, 3> h;
      std::array<vertex_descriptor, 3> v;
      internal::face_corners(bundle.face(f), tm, h, v);
      for(std::size_t k = 0; k < 3; ++k)
      {
        halfedge[3 * f + k] = h[k];
        corner_index.add(h[k]);
        target[3 * f + k] = bundle.index(v[k]);
        vertex_corner[target[3 * f + k]] = 3 * f + k;
      }
    }
    for(std::size_t c = 0; c < 3 * F; ++c)
    {
      const halfedge_descriptor o = internal::interior_opposite(halfedge[c], tm);
      if(o == GT::null_halfedge())
      {
        border_vertex[target[c]] = 1;
        border_vertex[source(c)] = 1;
      }
      else
        opposite[c] = corner_index(o);
    }
  }

  Error_code status() const { return bundle.status(); }
  static std::size_t next(std::size_t c) { return c - c % 3 + (c % 3 + 1) % 3; }
  static std::size_t prev(std::size_t c) { return c - c % 3 + (c % 3 + 2) % 3; }
  static std::size_t face(std::size_t c) { return c / 3; }
  std::size_t source(std::size_t c) const { return target[prev(c)]; }
  // next corner counterclockwise around target(c), crossing edge(c); npos at the border
  std::size_t ccw(std::size_t c) const { return opposite[c] == npos ? npos : prev(opposite[c]); }
  // previous corner counterclockwise around target(c)
  std::size_t cw(std::size_t c) const { return opposite[next(c)]; }
  // 2D coordinates in the frame of face(c) of target(c), relative to source(halfedge(face))
  std::complex<double> local_point(std::size_t c) const
  {
    const std::size_t f = face(c);
    const std::array<double, 3>& p0 = point[target[3 * f + 2]];
    const std::array<double, 3> d = difference(point[target[c]], p0);
    return bundle.frame(f).to_complex(d[0], d[1], d[2]);
  }
  // length of the edge of corner c
  double edge_length(std::size_t c) const
  {
    const std::array<double, 3> d = difference(point[target[c]], point[source(c)]);
    return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  }
};

// The mean length of the edges of the mesh (the default quad size of the map).
template <typename CornerMesh>
double mean_edge_length(const CornerMesh& M)
{
  double edge_sum = 0;
  std::size_t edge_count = 0;
  for(std::size_t c = 0; c < 3 * M.F; ++c)
    if(M.opposite[c] == npos || c < M.opposite[c])
    {
      edge_sum += M.edge_length(c);
      ++edge_count;
    }
  return edge_count == 0 ? 0.0 : edge_sum / double(edge_count);
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_CORNER_MESH_H
