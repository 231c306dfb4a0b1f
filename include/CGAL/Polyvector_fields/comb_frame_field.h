// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_COMB_FRAME_FIELD_H
#define CGAL_POLYVECTOR_FIELDS_COMB_FRAME_FIELD_H

/// \file comb_frame_field.h
/// Combing of a frame field along a dual spanning tree, and the cut graph that
/// opens each component of the mesh into a disk (Bommes, Zimmer, Kobbelt 2009,
/// Section 3; Kaelberer, Nieser, Polthier 2007, Section 4), on the faces,
/// numbering and transport of one `Tangent_bundle`. The result,
/// `Frame_field_comb`, is what `compute_integer_grid_map()` takes.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/Corner_mesh.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/comb_and_cut.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <array>
#include <complex>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// reports what `comb_frame_field()` (and the first stage of
/// `compute_integer_grid_map()`) found.
struct Comb_result
{
  std::size_t clamped_faces = 0;       ///< faces whose frame was clamped (angle below the bound, or one zero vector)
  std::size_t singular_vertices = 0;   ///< interior vertices of non-zero index, after the cancellation
  std::size_t cancelled_singularity_pairs = 0;  ///< pairs of opposite singularities closer than `singularity_cancellation_distance`, cancelled
  std::size_t merged_singularity_pairs = 0;     ///< close pairs merged into one singular vertex of valence 3 to 6
  std::size_t moved_singularities = 0;          ///< singularities moved away from a close one of the same sign (two +1: one vertex of valence 2 otherwise)
  std::size_t split_singularities = 0;          ///< quarter turns split off a singular vertex whose valence would be below 3 or above 6 (each a new singular vertex)
  std::size_t singularities_moved_to_border = 0; ///< singularities closer than half `singularity_cancellation_distance` to the border, whose index moved onto a border vertex (where it is gone: the border turns freely)
  std::size_t turned_frames = 0;               ///< faces whose frames turned to follow the matching that the cancellation, merging or moving of singularities (onto the border too) changed (those within three times `singularity_cancellation_distance` of a changed edge)
  std::size_t cut_edges = 0;           ///< interior edges of the cut graph (the seams)
  std::size_t boundary_edges = 0;      ///< boundary edges (always in the cut)
  std::size_t seam_curves = 0;         ///< maximal seam paths between nodes of the cut graph
  std::size_t components = 0;          ///< connected components of the mesh
  std::size_t first_invalid_face = 0;  ///< on `NOT_A_FRAME_FIELD`, `ZERO_FRAME` or a non-finite coefficient (`NON_FINITE_VALUE`): the index of the first bad face, in the bundle's numbering (the order of `faces(tm)`)
};

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// is a frame field combed and cut by `comb_frame_field()`: the cut graph with
/// the rotation of the transition across each of its edges, and the combed
/// frames, in the numbering of one `Tangent_bundle`. `compute_integer_grid_map()`
/// takes it, so that the seams are found once.
///
/// <b>Numbering.</b> Faces and vertices are numbered as by the bundle. The
/// corners (halfedges) of face `f` are `3f`, `3f+1`, `3f+2`: `halfedge(face(f))`
/// and its two successors; corner `c` stands for the halfedge `h` and for the
/// value at `target(h)` inside `face(h)`.
///
/// <b>Transitions.</b> Across an interior edge, with `h` on side A, the combed
/// frame of `face(opposite(h))` is `R^r` times the one of `face(h)` (`R` the
/// quarter turn, `r = rotation(h)`): a map guided by the comb satisfies
/// `uv_B = R^r uv_A + t` with `t` integer. `r` is 0 off the cut graph.
///
/// The bundle (and its mesh) must outlive this object.
///
/// \tparam Bundle a `Tangent_bundle`
template <typename Bundle>
class Frame_field_comb
{
public:
  /// \name Types
  /// @{
  typedef typename Bundle::face_descriptor face_descriptor;          ///< the face type of the mesh
  typedef typename Bundle::vertex_descriptor vertex_descriptor;      ///< the vertex type of the mesh
  typedef typename Bundle::halfedge_descriptor halfedge_descriptor;  ///< the halfedge type of the mesh
  /// @}

  /// builds an empty comb; `comb_frame_field()` fills it.
  Frame_field_comb() {}

  /// returns whether `comb_frame_field()` has filled this object successfully.
  bool is_valid() const { return m_mesh != nullptr; }
  /// returns the tangent bundle. \pre `is_valid()`
  const Bundle& bundle() const { return m_mesh->bundle; }
  /// returns the counts of the combing and the cut.
  const Comb_result& report() const { return m_report; }
  /// returns the minimum frame angle the frames were clamped to.
  double minimum_frame_angle() const { return m_minimum_frame_angle; }

  /// returns the corner index `3f+k` of `h` (see <b>Numbering</b>). \pre `h` is not a border halfedge
  std::size_t corner(halfedge_descriptor h) const { return m_mesh->corner_index(h); }
  /// returns the halfedge of corner `c`.
  halfedge_descriptor halfedge(std::size_t c) const { return m_mesh->halfedge[c]; }
  /// returns whether the edge of `h` is on the cut graph (boundary edges included).
  bool is_cut(halfedge_descriptor h) const
  {
    const std::size_t c = corner_or_border(h);
    return c == internal::npos || m_data.seam[c] != 0;
  }
  /// returns the rotation `r` in `0..3` of the transition from `face(h)` to `face(opposite(h))`;
  /// 0 off the cut graph and on the boundary.
  int rotation(halfedge_descriptor h) const
  {
    const std::size_t c = corner_or_border(h);
    return c == internal::npos || !m_data.seam[c] ? 0 : m_data.rotation[c];
  }
  /// returns the combed unit vectors `u` and `v` of the face of index `f`, as complex numbers in its bundle frame.
  std::array<std::complex<double>, 2> combed_frame(std::size_t f) const
  {
    return { { m_data.roots[f][std::size_t(m_data.offset[f])], m_data.roots[f][std::size_t((m_data.offset[f] + 1) % 4)] } };
  }
  /// returns the index of vertex `v` times 4 (the numerator `k` of `k/4`); 0 on the boundary.
  int index_numerator(vertex_descriptor v) const { return m_data.index[m_mesh->bundle.index(v)]; }

  /// returns the number of seam curves: the maximal paths of interior cut edges between nodes of the
  /// cut graph (singular vertices, branch vertices, boundary vertices).
  std::size_t number_of_seam_curves() const { return m_data.curves.size(); }
  /// returns the two ends of seam curve `i`.
  std::pair<vertex_descriptor, vertex_descriptor> seam_curve_ends(std::size_t i) const
  {
    return { m_mesh->bundle.vertex(m_data.curves[i].start), m_mesh->bundle.vertex(m_data.curves[i].end) };
  }
  /// returns the interior cut edges of seam curve `i`, as halfedges oriented along the curve.
  std::vector<halfedge_descriptor> seam_curve_halfedges(std::size_t i) const
  {
    std::vector<halfedge_descriptor> out;
    for(std::size_t c : m_data.curves[i].corners)
      out.push_back(m_mesh->halfedge[c]);
    return out;
  }

  /// \cond SKIP_IN_MANUAL
  const internal::Corner_mesh<Bundle>& corner_mesh() const { return *m_mesh; }
  const internal::Comb_data& data() const { return m_data; }

  // Combs: the body of comb_frame_field().
  // `cancellation_distance`: see `singularity_cancellation_distance` (0: none).
  template <typename CoefficientMap>
  Error_code compute(const Bundle& bundle, CoefficientMap coefficient_map, double min_angle,
                     double cancellation_distance = 0)
  {
    m_mesh.reset();
    m_data = internal::Comb_data();
    m_report = Comb_result();
    m_minimum_frame_angle = min_angle;
    if(bundle.status() != Error_code::SUCCESS)
      return bundle.status();
    auto mesh = std::make_shared<const internal::Corner_mesh<Bundle> >(bundle);
    const Error_code code =
      internal::comb_and_cut(*mesh, coefficient_map, min_angle, cancellation_distance, m_data, m_report);
    if(code == Error_code::SUCCESS)
      m_mesh = mesh;
    return code;
  }
  /// \endcond

private:
  std::size_t corner_or_border(halfedge_descriptor h) const
  {
    return CGAL::is_border_edge(h, m_mesh->tm) ? internal::npos : m_mesh->corner_index(h);
  }

  std::shared_ptr<const internal::Corner_mesh<Bundle> > m_mesh;
  internal::Comb_data m_data;
  Comb_result m_report;
  double m_minimum_frame_angle = 0;
};

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// combs the frame field `{+-u, +-v}` of the tangent bundle `bundle` along a dual
/// spanning tree and computes its cut graph (Bommes, Zimmer, Kobbelt 2009,
/// Section 3), into `comb`; see the other overload for the cleaning, the combing
/// and the cut, and `Frame_field_comb` for what `comb` holds.
///
/// \tparam TriangleMesh, VertexPointMap the parameters of the bundle
/// \tparam CoefficientMap a model of `ReadablePropertyMap` from faces to `std::vector<std::complex<double>>` of size 4
///
/// \param bundle the tangent bundle of a triangle mesh (it must outlive `comb`)
/// \param coefficient_map the frame field
/// \param comb receives the combed field and its cut graph (its `report()` also on failure, as far as it was computed)
/// \param np an optional sequence of named parameters: `minimum_frame_angle` (see the other overload)
///
/// \returns as the other overload; on failure `comb.is_valid()` is false.
template <typename TriangleMesh, typename VertexPointMap, typename CoefficientMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code comb_frame_field(const Tangent_bundle<TriangleMesh, VertexPointMap>& bundle, CoefficientMap coefficient_map,
                            Frame_field_comb<Tangent_bundle<TriangleMesh, VertexPointMap> >& comb,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  comb = Frame_field_comb<Tangent_bundle<TriangleMesh, VertexPointMap> >();
  double min_angle = 0;
  double cancellation_distance = 0;
  Error_code parameter_code = internal::read_minimum_frame_angle(np, min_angle);
  if(parameter_code == Error_code::SUCCESS)
    parameter_code = internal::read_cancellation_distance(np, cancellation_distance);
  if(parameter_code != Error_code::SUCCESS)
    return parameter_code;
  return comb.compute(bundle, coefficient_map, min_angle, cancellation_distance);
}

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// combs the frame field `{+-u, +-v}` of a mesh along a dual spanning tree and
/// computes its cut graph (Bommes, Zimmer, Kobbelt 2009, Section 3).
///
/// The field is read as 4 coefficients per face (a sign-symmetric 4-PolyVector,
/// as `design_polyvector_field()` with `sign_symmetric(true)`,
/// `Polyvector_field_designer` and the frame-field algorithms write it). Per
/// face, `u` and `v` are two consecutive roots in the counterclockwise order of
/// `polyvector_roots()`, normalised to unit length; if they make an angle below
/// `minimum_frame_angle` (or above pi minus it), they are turned symmetrically
/// about their bisector to that angle, and if one of them is zero it is replaced
/// by the other turned by 90 degrees: both faces are counted in
/// `Comb_result::clamped_faces`.
///
/// Combing chooses, per face, which root is `u` so that the principal matching
/// of the cleaned field (see `principal_matching()`) is the identity on every
/// edge that a breadth-first dual spanning tree crosses (one tree per connected
/// component, rooted at its first face). The cut graph is made of the other
/// edges, boundary edges included; its dangling branches are pruned unless they
/// end at a singular vertex (see `compute_singularities()`), so it passes
/// through every singular vertex and every handle and opens each component
/// into a disk.
///
/// All computations are done in `double`, in the frames of the tangent bundle.
///
/// \tparam Mesh_or_bundle a `Tangent_bundle`, or a model of `FaceListGraph` (whose bundle is then built
///         with the named parameter `vertex_point_map`); in both cases the mesh is a triangle mesh
/// \tparam CoefficientMap a model of `ReadablePropertyMap` from faces to `std::vector<std::complex<double>>` of size 4
/// \tparam CutEdgeMap a model of `WritablePropertyMap` from edges to `bool`: true on the cut graph, boundary edges included
/// \tparam CombedFrameMap a model of `WritablePropertyMap` from faces to `std::array<Vector_3, 2>`:
///         the combed unit `u` and `v`, in world coordinates
/// \tparam RotationMap a model of `WritablePropertyMap` from halfedges to `int` in `0..3`: the rotation `r`
///         of the transition from `face(h)` to `face(opposite(h))` (`uv' = R^r uv + t`, `R` the quarter
///         turn); written for both halfedges of every interior edge, 0 off the cut
///
/// \param mesh_or_bundle the mesh, or its tangent bundle
/// \param coefficient_map the frame field
/// \param cut_edge_map receives the cut graph
/// \param combed_frame_map receives the combed frames
/// \param rotation_map receives the rotations of the transitions
/// \param result receives the counts of the combing and the cut (also on failure, as far as they were computed)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{minimum_frame_angle}
///     \cgalParamDescription{the smallest angle, in radians, between `u` and `v`: frames below it are
///                           clamped to it; given with `Polyvector_fields::parameters::minimum_frame_angle()`}
///     \cgalParamType{`double` in `(0, pi/2]`}
///     \cgalParamDefault{10 degrees}
///   \cgalParamNEnd
///   \cgalParamNBegin{singularity_cancellation_distance}
///     \cgalParamDescription{singular vertices closer than this along mesh edges, or joined by one edge
///                           shorter than sqrt(2) times this (on a coarse mesh two such vertices may
///                           round to the same integer point), are handled
///                           pair by pair, the closest first: opposite indices cancel, a pair whose
///                           merged index makes a quad vertex of valence 3 to 6 merges, any other
///                           pair (two of index 1/4) is moved apart. Before that, a singular vertex
///                           of index above 1/4 or below -1/2 (a quad vertex of valence below 3 or
///                           above 6) is split into several, a quarter turn at a time; then a singular vertex
///                           closer than half this distance to the border (along interior edges) gives its
///                           index to the closest border vertex within that distance whose angle can
///                           take it (the border turns freely there, and the singularity is gone;
///                           again after the pairs, for those moved apart). The index moves by whole quarter
///                           turns of the matching along the shortest edge path, as with the period
///                           jumps of mixed-integer quadrangulation. The map places every singular
///                           vertex on an integer point: two closer than one quad would meet there,
///                           and the faces between them would fold over. The frames within three times
///                           this distance of a changed edge then turn to follow the new matching (the
///                           quarter turn of each edge spread over the faces around it, see the
///                           manual's section on close singularities): the combed frames are those
///                           turned frames, and near a changed edge their own principal matching and
///                           singularities may differ from the comb's. `Comb_result` counts the
///                           pairs, the singularities given to the border and the turned frames;
///                           its `singular_vertices` are those that remain. The sum of the interior
///                           indices is kept, but for the indices given to the border. Given with
///                           `Polyvector_fields::parameters::singularity_cancellation_distance()`}
///     \cgalParamType{`double >= 0`, in mesh units; the quad size is the natural choice}
///     \cgalParamDefault{0: every singularity of the field is kept}
///   \cgalParamNEnd
///   \pvfParamVertexPointMap
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::SUCCESS`; a mesh error of the bundle (`EMPTY_MESH`, `NON_TRIANGLE_FACE`,
///          `DEGENERATE_FACE`); `NON_FINITE_VALUE` for a coefficient or a parameter;
///          `NOT_A_FRAME_FIELD` if a face does not hold 4 coefficients or has non-zero odd
///          coefficients; `ZERO_FRAME` if a face's frame is zero (it cannot be clamped);
///          `INVALID_PARAMETER` for `minimum_frame_angle` out of range. For the errors of the
///          field, `result.first_invalid_face` is the face. Nothing is written to the maps on failure.
///
/// \sa `Frame_field_comb`, `compute_integer_grid_map()`, `principal_matching()`, `compute_singularities()`
template <typename Mesh_or_bundle, typename CoefficientMap, typename CutEdgeMap, typename CombedFrameMap,
          typename RotationMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code comb_frame_field(const Mesh_or_bundle& mesh_or_bundle, CoefficientMap coefficient_map,
                            CutEdgeMap cut_edge_map, CombedFrameMap combed_frame_map, RotationMap rotation_map,
                            Comb_result& result, const NamedParameters& np = CGAL::parameters::default_values())
{
  result = Comb_result();
  double min_angle = 0;
  double cancellation_distance = 0;
  Error_code parameter_code = internal::read_minimum_frame_angle(np, min_angle);
  if(parameter_code == Error_code::SUCCESS)
    parameter_code = internal::read_cancellation_distance(np, cancellation_distance);
  if(parameter_code != Error_code::SUCCESS)
    return parameter_code;
  const auto& bundle = internal::bundle_of(mesh_or_bundle, np);
  if(bundle.status() != Error_code::SUCCESS)
    return bundle.status();
  Frame_field_comb<std::decay_t<decltype(bundle)> > comb;
  const Error_code code = comb.compute(bundle, coefficient_map, min_angle, cancellation_distance);
  result = comb.report();
  if(code != Error_code::SUCCESS)
    return code;
  typedef typename boost::property_traits<CombedFrameMap>::value_type Frame_pair;
  typedef typename Frame_pair::value_type Vector_3;
  for(std::size_t f = 0; f < bundle.number_of_faces(); ++f)
  {
    const std::array<std::complex<double>, 2> uv = comb.combed_frame(f);
    const auto a = bundle.frame(f).to_world(uv[0]);
    const auto b = bundle.frame(f).to_world(uv[1]);
    put(combed_frame_map, bundle.face(f), Frame_pair{ { Vector_3(a[0], a[1], a[2]), Vector_3(b[0], b[1], b[2]) } });
  }
  const auto& tm = bundle.mesh();
  for(auto e : edges(tm))
  {
    const auto h = halfedge(e, tm);
    if(!CGAL::is_border_edge(h, tm))
    {
      put(rotation_map, h, comb.rotation(h));
      put(rotation_map, opposite(h, tm), comb.rotation(opposite(h, tm)));
    }
    put(cut_edge_map, e, comb.is_cut(h));
  }
  return Error_code::SUCCESS;
}

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// combs the frame field `field` (degree 4, sign-symmetric: the designer's
/// field, optimised or not by the frame-field algorithms) and computes its cut
/// graph into `comb`, as the overload on a tangent bundle and a coefficient map.
///
/// \returns as that overload, and `NOT_A_FRAME_FIELD` if `field` is not of degree 4 and sign-symmetric.
template <typename TangentBundle, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code comb_frame_field(const Polyvector_field<TangentBundle>& field, Frame_field_comb<TangentBundle>& comb,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  if(!field.is_frame_field())
  {
    comb = Frame_field_comb<TangentBundle>();
    return Error_code::NOT_A_FRAME_FIELD;
  }
  return comb_frame_field(field.tangent_bundle(), field.coefficient_map(), comb, np);
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_COMB_FRAME_FIELD_H
