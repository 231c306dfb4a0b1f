// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_TANGENT_BUNDLE_H
#define CGAL_POLYVECTOR_FIELDS_TANGENT_BUNDLE_H

/// \file Tangent_bundle.h
/// The discrete tangent bundle of a triangle mesh: face frames, numbering,
/// Levi-Civita transport and connected components, built once and shared.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/internal/Tangent_bundle/frames_and_transport.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <complex>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
/// \ingroup PkgPolyvectorFieldsFrames
///
/// is the discrete tangent bundle of a triangle mesh (paper, Section 3.1): the
/// plane of each face identified with the complex plane by its `Face_frame`,
/// the discrete Levi-Civita connection between the frames of adjacent faces,
/// a numbering of the faces and vertices, and the connected components.
///
/// Every algorithm of the package works on it: build it once and pass it to
/// the designer, the root and singularity computations, the energies and
/// measures, so that the frames and the numbering are computed once for a
/// whole pipeline. The forms of the functions that take a mesh build their
/// own.
///
/// <b>Numbering.</b> Faces are numbered `0 .. number_of_faces()-1` in the order
/// of `faces(tm)` and vertices `0 .. number_of_vertices()-1` in the order of
/// `vertices(tm)`: for a mesh read from a file, the order of the file. A
/// `Surface_mesh` holding removed elements is numbered correctly.
///
/// <b>Transport.</b> A vector `u_f` of face `f` is parallel to the vector
/// `u_g = u_f * conj(e_f) * e_g` of the adjacent face `g`, where `e_f` and `e_g`
/// are the unit direction of their common edge written in the frames of `f` and
/// `g`. Boundary edges carry no transport.
///
/// All quantities are computed in `double`, safely over the whole range of
/// `double` (points are scaled by powers of two where a square could overflow).
///
/// <b>Concurrency.</b> The constructors take an optional concurrency tag,
/// `CGAL::Parallel_if_available_tag` by default: with `CGAL::Parallel_tag`
/// (and TBB) the frames and the transport of the faces and edges are computed
/// on several threads, which then read the mesh and the vertex point map at
/// the same time. Each frame and each transport is computed by the same
/// operations whatever the tag and the number of threads, so the bundle is
/// bit-identical to the one built with `CGAL::Sequential_tag`.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
/// \tparam VertexPointMap a model of `ReadablePropertyMap` from vertices to points;
///         the default is the internal point map of `TriangleMesh`
///
/// The mesh must outlive this object and keep its combinatorics and points while it is in use.
template <typename TriangleMesh,
          typename VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>
class Tangent_bundle
{
public:
  /// \name Types
  /// @{
  typedef TriangleMesh Triangle_mesh;  ///< the mesh type
  typedef VertexPointMap Vertex_point_map;  ///< the vertex point map type
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;          ///< the face type of `TriangleMesh`
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;      ///< the vertex type of `TriangleMesh`
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;  ///< the halfedge type of `TriangleMesh`

  /// an interior edge seen from its two faces: `face(h)` has index `f` and
  /// `face(opposite(h))` has index `g`. `e_f` and `e_g` are the unit direction of
  /// the edge from `source(h)` to `target(h)` in the frames of `f` and `g`.
  struct Dual_edge
  {
    std::size_t f;              ///< the index of `face(h)`
    std::size_t g;              ///< the index of `face(opposite(h))`
    std::complex<double> e_f;   ///< the unit direction of the edge in the frame of `f`
    std::complex<double> e_g;   ///< the unit direction of the edge in the frame of `g`
    halfedge_descriptor h;      ///< the halfedge of the edge whose face is `f`
  };
  /// @}

  /// builds the tangent bundle of `tm` with the points of `vpm`. Check `status()` before use.
  Tangent_bundle(const TriangleMesh& tm, VertexPointMap vpm)
    : Tangent_bundle(tm, vpm, CGAL::Parallel_if_available_tag())
  {}

  /// builds the tangent bundle of `tm` with its internal point map.
  explicit Tangent_bundle(const TriangleMesh& tm)
    : Tangent_bundle(tm, CGAL::get_const_property_map(CGAL::vertex_point, tm), CGAL::Parallel_if_available_tag())
  {}

  /// builds the tangent bundle of `tm` with the points of `vpm`, in parallel or not as
  /// `ConcurrencyTag` says (`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
  /// `CGAL::Parallel_if_available_tag`); the result does not depend on it.
  template <typename ConcurrencyTag,
            typename = std::enable_if_t<internal::Is_concurrency_tag<ConcurrencyTag>::value> >
  Tangent_bundle(const TriangleMesh& tm, VertexPointMap vpm, ConcurrencyTag)
    : m_tm(tm), m_vpm(vpm)
  {
    build<ConcurrencyTag>();
  }

  /// builds the tangent bundle of `tm` with its internal point map, in parallel or not as
  /// `ConcurrencyTag` says; the result does not depend on it.
  template <typename ConcurrencyTag,
            typename = std::enable_if_t<internal::Is_concurrency_tag<ConcurrencyTag>::value> >
  Tangent_bundle(const TriangleMesh& tm, ConcurrencyTag tag)
    : Tangent_bundle(tm, CGAL::get_const_property_map(CGAL::vertex_point, tm), tag)
  {}

  /// returns `Error_code::SUCCESS`, or why the mesh cannot carry a field:
  /// `EMPTY_MESH`, `NON_TRIANGLE_FACE` or `DEGENERATE_FACE`.
  Error_code status() const { return m_status; }

  /// returns the first face for which `status()` is not `SUCCESS`, if any.
  std::size_t first_invalid_face() const { return m_first_invalid_face; }

  /// returns the mesh.
  const TriangleMesh& mesh() const { return m_tm; }
  /// returns the vertex point map.
  VertexPointMap vertex_point_map() const { return m_vpm; }

  /// \name Faces and their frames
  /// @{

  /// returns the number of faces of the mesh.
  std::size_t number_of_faces() const { return m_faces.size(); }
  /// returns the index of `f`, in `0 .. number_of_faces()-1`.
  std::size_t index(face_descriptor f) const { return m_face_index(f); }
  /// returns whether `f` is a face of the mesh.
  bool contains(face_descriptor f) const { return m_face_index.contains(f); }
  /// returns the face of index `i`.
  face_descriptor face(std::size_t i) const { return m_faces[i]; }
  /// returns the frame of the face of index `i`.
  const Face_frame& frame(std::size_t i) const { return m_frames[i]; }
  /// @}

  /// \name Vertices
  /// @{

  /// returns the number of vertices of the mesh (isolated ones included).
  std::size_t number_of_vertices() const { return m_vertices.size(); }
  /// returns the index of `v`, in `0 .. number_of_vertices()-1`.
  std::size_t index(vertex_descriptor v) const { return m_vertex_index(v); }
  /// returns the vertex of index `i`.
  vertex_descriptor vertex(std::size_t i) const { return m_vertices[i]; }
  /// returns the point of the vertex of index `i`, in `double`.
  std::array<double, 3> point(std::size_t i) const { return point_of(m_vertices[i]); }
  /// @}

  /// \name Connection
  /// @{

  /// returns the interior edges, one entry per edge.
  const std::vector<Dual_edge>& interior_edges() const { return m_edges; }
  /// returns the unit direction, in the frame of `face(h)`, of the edge from `source(h)` to `target(h)`.
  std::complex<double> edge_direction(halfedge_descriptor h) const
  {
    return edge_direction_in(h, frame(index(internal::face_of(h, m_tm))));
  }
  /// transports the tangent vector `u` of `face(h)` to `face(opposite(h))`.
  std::complex<double> transport(const std::complex<double>& u, halfedge_descriptor h) const
  {
    const halfedge_descriptor o = opposite(h, m_tm);
    // The edge read from o runs the other way: both signs cancel in the ratio.
    return u * std::conj(edge_direction(h)) * (-edge_direction(o));
  }
  /// @}

  /// \name Components
  /// @{

  /// returns the number of connected components (faces connected through interior edges).
  std::size_t number_of_components() const { return m_number_of_components; }
  /// returns the component, in `0 .. number_of_components()-1`, of the face of index `i`.
  std::size_t component(std::size_t i) const { return m_component[i]; }
  /// @}

private:
  std::array<double, 3> point_of(vertex_descriptor v) const
  {
    using boost::get;
    return internal::to_array(get(m_vpm, v));
  }

  // The unit direction of the edge of `h` in `frame`, the frame of `face(h)`:
  // the one computation of `edge_direction()` and of the transport.
  std::complex<double> edge_direction_in(halfedge_descriptor h, const Face_frame& frame) const
  {
    return internal::edge_direction_in_frame(h, frame, m_tm, m_vpm);
  }

  // Faces and edges per thread range: below this TBB's overhead is not worth it.
  static constexpr std::size_t grain = 4096;

  template <typename ConcurrencyTag>
  void build()
  {
    internal::number_elements(faces(m_tm), num_faces(m_tm), m_faces, m_face_index);
    internal::number_elements(vertices(m_tm), num_vertices(m_tm), m_vertices, m_vertex_index);
    if(m_faces.empty())
    {
      m_status = Error_code::EMPTY_MESH;
      return;
    }
    const std::vector<halfedge_descriptor> interior = internal::interior_halfedges(m_tm);

    // The frames, each face on its own, while the calling thread also
    // allocates the edges (the first touch of their memory costs as much as
    // computing a frame).
    m_frames.resize(m_faces.size());  // not initialised: each frame is written once below
    std::size_t first_invalid = m_faces.size();
    internal::invoke_both<ConcurrencyTag>(
      [&] { first_invalid = internal::compute_face_frames<ConcurrencyTag>(m_tm, m_vpm, m_faces, m_frames, grain); },
      [&] { m_edges.resize(interior.size()); });
    if(first_invalid < m_faces.size())
    {
      set_invalid_face(first_invalid);
      return;
    }

    internal::set_dual_edge_faces<ConcurrencyTag>(m_tm, interior, m_face_index, m_edges, grain);
    // The transport of each edge on its own, while the calling thread also
    // finds the connected components (which read only the faces of the edges).
    internal::invoke_both<ConcurrencyTag>(
      [&] { internal::compute_edge_transport<ConcurrencyTag>(m_tm, m_vpm, m_frames, m_edges, grain); },
      [&] { build_components(); });
  }

  // The state a face-by-face loop leaves when the face of index `i` has no
  // frame: no frame from it on, no edge, and its error as the status.
  void set_invalid_face(std::size_t i)
  {
    std::fill(m_frames.begin() + std::ptrdiff_t(i), m_frames.end(), Face_frame());
    Face_frame unused;
    m_status = face_frame(m_faces[i], m_tm, unused, CGAL::parameters::vertex_point_map(m_vpm));
    m_first_invalid_face = i;
    std::vector<Dual_edge>().swap(m_edges);
  }

  // The connected components, numbered in the order of their first face.
  void build_components()
  {
    m_number_of_components = internal::connected_face_components(m_faces.size(), m_edges, m_component);
  }

  const TriangleMesh& m_tm;
  VertexPointMap m_vpm;
  internal::Numbering<face_descriptor> m_face_index;
  internal::Numbering<vertex_descriptor> m_vertex_index;
  std::vector<face_descriptor> m_faces;
  std::vector<vertex_descriptor> m_vertices;
  std::vector<Face_frame, internal::Uninitialized_allocator<Face_frame> > m_frames;
  std::vector<Dual_edge> m_edges;
  std::vector<std::size_t> m_component;
  std::size_t m_number_of_components = 0;
  Error_code m_status = Error_code::SUCCESS;
  std::size_t m_first_invalid_face = 0;
};

namespace internal {

// The tangent bundle type of the `tm + np` forms, with the vertex point map of `np`.
template <typename TriangleMesh, typename NamedParameters>
using Tangent_bundle_of =
  Tangent_bundle<TriangleMesh, typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type>;

template <typename TriangleMesh, typename NamedParameters>
Tangent_bundle_of<TriangleMesh, NamedParameters> make_tangent_bundle(const TriangleMesh& tm, const NamedParameters& np)
{
  return Tangent_bundle_of<TriangleMesh, NamedParameters>(
    tm, CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                           CGAL::get_const_property_map(CGAL::vertex_point, tm)));
}

// Whether a type is a `Tangent_bundle` (for the functions that have one
// overload for meshes and one for bundles).
template <typename T>
struct Is_tangent_bundle : std::false_type {};
template <typename TriangleMesh, typename VertexPointMap>
struct Is_tangent_bundle<Tangent_bundle<TriangleMesh, VertexPointMap> > : std::true_type {};

// The tangent bundle of a mesh (built) or of a bundle (itself): for the
// functions that accept both.
template <typename TriangleMesh, typename VertexPointMap, typename NamedParameters>
const Tangent_bundle<TriangleMesh, VertexPointMap>& bundle_of(const Tangent_bundle<TriangleMesh, VertexPointMap>& bundle,
                                                              const NamedParameters&)
{
  return bundle;
}

// (The return type is deduced, so that it is not formed for a bundle during
// overload resolution.)
template <typename TriangleMesh, typename NamedParameters>
auto bundle_of(const TriangleMesh& tm, const NamedParameters& np)
{
  return make_tangent_bundle(tm, np);
}

} // namespace internal

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_TANGENT_BUNDLE_H
