// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_TANGENT_BUNDLE_FRAMES_AND_TRANSPORT_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_TANGENT_BUNDLE_FRAMES_AND_TRANSPORT_H

// The steps that build a Tangent_bundle: the numbering of faces and vertices,
// the interior edges, the face frames, the Levi-Civita transport across the
// interior edges, and the connected components. Each frame and each transport
// is computed by the same operations whatever the concurrency tag.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <atomic>
#include <complex>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The BGL primitives are found by argument-dependent lookup, so that a mesh
// whose graph traits are included after this header still works; these
// helpers let classes with members of the same names reach the free functions.
template <typename TriangleMesh>
typename boost::graph_traits<TriangleMesh>::face_descriptor
face_of(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, const TriangleMesh& tm)
{
  return face(h, tm);
}

// Numbers the elements of `range` 0, 1, ... in its order: `list[i]` is the
// element of index i, and `numbering` gives the index of an element.
template <typename Range, typename Descriptor>
void number_elements(const Range& range, std::size_t size, std::vector<Descriptor>& list,
                     Numbering<Descriptor>& numbering)
{
  list.reserve(size);
  numbering.reserve(size);
  for(Descriptor d : range)
  {
    numbering.add(d);
    list.push_back(d);
  }
}

// The interior edges of `tm`, in the order of edges(tm), each by its halfedge
// `halfedge(e)`. Boundary edges carry no transport (natural boundary condition:
// they carry no term).
template <typename TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> interior_halfedges(const TriangleMesh& tm)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  std::vector<halfedge_descriptor> interior;
  interior.reserve(num_edges(tm));
  for(auto e : edges(tm))
  {
    const halfedge_descriptor h = halfedge(e, tm);
    if(!CGAL::is_border(h, tm) && !CGAL::is_border(opposite(h, tm), tm))
      interior.push_back(h);
  }
  return interior;
}

// The unit direction of the edge of `h` (from source(h) to target(h)) in
// `frame`, the frame of `face(h)`: the one computation of the edge directions
// and of the transport.
template <typename TriangleMesh, typename VertexPointMap>
std::complex<double> edge_direction_in_frame(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                                             const Face_frame& frame, const TriangleMesh& tm, const VertexPointMap& vpm)
{
  using boost::get;
  const std::array<double, 3> d = scaled_difference(to_array(get(vpm, target(h, tm))), to_array(get(vpm, source(h, tm))));
  const std::complex<double> e = frame.to_complex(d[0], d[1], d[2]);
  return e / std::abs(e);
}

// The frame of every face of `faces`, each face on its own, written to
// `frames` (already sized). Returns the index of the first face that has no
// frame (the one of smallest index, whichever thread meets it first), or
// faces.size(); frames from that face on are not all written.
template <typename ConcurrencyTag, typename TriangleMesh, typename VertexPointMap, typename FrameVector>
std::size_t compute_face_frames(const TriangleMesh& tm, const VertexPointMap& vpm,
                                const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& faces,
                                FrameVector& frames, std::size_t grain)
{
  std::atomic<std::size_t> first_invalid(faces.size());
  for_each_range<ConcurrencyTag>(faces.size(), grain, [&](std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i)
    {
      if(i >= first_invalid.load(std::memory_order_relaxed))
        return;  // a face before this one failed
      if(Polyvector_fields::face_frame(faces[i], tm, frames[i], CGAL::parameters::vertex_point_map(vpm)) !=
         Error_code::SUCCESS)
      {
        std::size_t current = first_invalid.load(std::memory_order_relaxed);
        while(i < current && !first_invalid.compare_exchange_weak(current, i, std::memory_order_relaxed))
        {}
        return;
      }
    }
  });
  return first_invalid.load();
}

// The halfedge and the two face indices of each dual edge, from the interior
// halfedges (the edges are already sized).
template <typename ConcurrencyTag, typename TriangleMesh, typename DualEdge>
void set_dual_edge_faces(const TriangleMesh& tm,
                         const std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& interior,
                         const Numbering<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_index,
                         std::vector<DualEdge>& dual_edges, std::size_t grain)
{
  for_each_range<ConcurrencyTag>(dual_edges.size(), grain, [&](std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i)
    {
      DualEdge& d = dual_edges[i];
      d.h = interior[i];
      d.f = face_index(face_of(d.h, tm));
      d.g = face_index(face_of(opposite(d.h, tm), tm));
    }
  });
}

// The transport of each dual edge on its own: the unit direction of the edge
// in the frames of its two faces.
template <typename ConcurrencyTag, typename TriangleMesh, typename VertexPointMap, typename FrameVector,
          typename DualEdge>
void compute_edge_transport(const TriangleMesh& tm, const VertexPointMap& vpm, const FrameVector& frames,
                            std::vector<DualEdge>& dual_edges, std::size_t grain)
{
  for_each_range<ConcurrencyTag>(dual_edges.size(), grain, [&](std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i)
    {
      DualEdge& d = dual_edges[i];
      d.e_f = edge_direction_in_frame(d.h, frames[d.f], tm, vpm);
      d.e_g = -edge_direction_in_frame(opposite(d.h, tm), frames[d.g], tm, vpm);
    }
  });
}

// The connected components of `number_of_faces` faces connected through the
// dual edges, numbered in the order of their first face; returns their number.
template <typename DualEdge>
std::size_t connected_face_components(std::size_t number_of_faces, const std::vector<DualEdge>& dual_edges,
                                      std::vector<std::size_t>& component)
{
  std::vector<std::size_t> parent(number_of_faces);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&parent](std::size_t i) {
    while(parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  for(const DualEdge& d : dual_edges)
    parent[find(d.f)] = find(d.g);

  component.resize(number_of_faces);
  std::vector<std::size_t> label(number_of_faces, std::size_t(-1));
  std::size_t number_of_components = 0;
  for(std::size_t i = 0; i < number_of_faces; ++i)
  {
    const std::size_t root = find(i);
    if(label[root] == std::size_t(-1))
      label[root] = number_of_components++;
    component[i] = label[root];
  }
  return number_of_components;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_TANGENT_BUNDLE_FRAMES_AND_TRANSPORT_H
