// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_SELECT_SHARP_EDGE_CONSTRAINTS_H
#define CGAL_POLYVECTOR_FIELDS_SELECT_SHARP_EDGE_CONSTRAINTS_H

/// \file select_sharp_edge_constraints.h
/// Partial constraints along the sharp edges of a mesh.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Face_constraint.h>
#include <CGAL/Polyvector_fields/internal/Field_design/sharp_edge_constraints.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsDesign
///
/// constrains the faces along the sharp edges of `tm` to follow those edges,
/// with partial constraints (see `Face_constraint`): on a CAD-like model the
/// field then runs along the feature lines and is free elsewhere.
///
/// <b>Rule.</b> The sharp edges are found with \cgal's
/// `CGAL::Polygon_mesh_processing::detect_sharp_edges()`, with
/// `angle_in_degrees` as its angle; an edge is kept when it has two faces (a
/// border edge, which `detect_sharp_edges()` also marks, is not sharp here)
/// and the angle between the normals of its faces strictly exceeds
/// `angle_in_degrees` (an edge at exactly the threshold, such as an edge of a
/// box with a threshold of 90 degrees, is not sharp). Each face beside at
/// least one sharp edge gets the hard constraint whose vectors are the unit
/// directions of its sharp edges, the sharpest first (largest angle between
/// the normals; equal angles in no specified order), at most
/// `maximum_vectors_per_face` of them. The direction of an edge is that of
/// its halfedge `halfedge(e, tm)`, from source to target; with a
/// sign-symmetric field the sign does not matter. The constraints are stored
/// in `out` in the order of `faces(tm)`.
///
/// With `boundary_alignment`, the border edges are kept too, as the sharpest
/// edges (their angle counts as 180 degrees): the field then follows the
/// boundary, as `compute_integer_grid_map()` needs to put it on iso-lines.
/// With `edge_is_constrained_map`, every edge is marked in it, `true` for a
/// kept edge: the features to give to `compute_integer_grid_map()`, by the
/// same rule.
///
/// For an `N`-PolyVector field, `maximum_vectors_per_face` is `N` (or `N/2`
/// with sign symmetry, which makes a face with that many sharp edges fully
/// constrained); a face with fewer sharp edges gets a partial constraint.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam FaceDescriptor `boost::graph_traits<TriangleMesh>::%face_descriptor` (deduced)
/// \tparam Vector_3 the vector type of the constraints, constructible from three `double` values
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param angle_in_degrees the threshold on the angle between the normals of the two faces of an edge, in degrees
/// \param maximum_vectors_per_face the largest number of vectors of a constraint
/// \param out receives the constraints (its former content is replaced); unchanged on failure
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \pvfParamVertexPointMap
///   \cgalParamNBegin{boundary_alignment}
///     \cgalParamDescription{whether the border edges are kept as sharp edges; given with
///                           `Polyvector_fields::parameters::boundary_alignment()`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_feature_length}
///     \cgalParamDescription{the creases shorter than this are dropped: on a scan, the sharp edges
///                           make short zigzags that a quad mesh cannot follow. Dropped are the networks
///                           of sharp edges (connected through their vertices) shorter than this in all,
///                           and the crease curves shorter than this that do not join two corners. A
///                           crease curve is a chain of sharp edges through vertices where exactly two
///                           of them meet (the border aside) and turn by at most 45 degrees; a corner is
///                           a vertex where three or more sharp or border edges meet (the edges of a box
///                           are kept whatever their length). The border is always kept; given with
///                           `Polyvector_fields::parameters::minimum_feature_length()`}
///     \cgalParamType{`double >= 0`, in mesh units}
///     \cgalParamDefault{0: every sharp edge is kept}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{receives, for every edge, whether it was kept (written on success only)}
///     \cgalParamType{a model of `WritablePropertyMap` from `boost::graph_traits<TriangleMesh>::%edge_descriptor` to `bool`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{a geometric traits class, given to `detect_sharp_edges()`}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the \cgal kernel deduced from the point type of the mesh}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns
/// - `Error_code::INVALID_PARAMETER` if `angle_in_degrees` is not in `[0, 180)` (NaN included),
///   `maximum_vectors_per_face` is 0 or `minimum_feature_length` is negative or NaN;
/// - `Error_code::EMPTY_MESH` if `tm` has no face;
/// - `Error_code::NON_TRIANGLE_FACE` if a face is not a triangle;
/// - `Error_code::DEGENERATE_FACE` if a face has zero area or a non-finite coordinate;
/// - `Error_code::SUCCESS` otherwise, even when no edge is sharp (`out` is then empty).
///
/// \sa `select_curvature_constraints()`, `Polyvector_field_designer`
template <typename TriangleMesh,
          typename FaceDescriptor,
          typename Vector_3,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code select_sharp_edge_constraints(const TriangleMesh& tm,
                                         double angle_in_degrees,
                                         std::size_t maximum_vectors_per_face,
                                         std::vector<Face_constraint<FaceDescriptor, Vector_3> >& out,
                                         const NamedParameters& np = CGAL::parameters::default_values())
{
  static_assert(std::is_same<FaceDescriptor, typename boost::graph_traits<TriangleMesh>::face_descriptor>::value,
                "the constraints must be on the faces of the mesh");
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if(!(angle_in_degrees >= 0. && angle_in_degrees < 180.) || maximum_vectors_per_face == 0)
    return Error_code::INVALID_PARAMETER;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    CGAL::get_const_property_map(CGAL::vertex_point, tm));
  const bool with_border = choose_parameter(get_parameter(np, internal_np::boundary_alignment), false);
  const double minimum_length = choose_parameter(get_parameter(np, internal_np::minimum_feature_length), 0.0);
  if(!(minimum_length >= 0))
    return Error_code::INVALID_PARAMETER;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value)
    return internal::select_sharp_edge_constraints(tm, angle_in_degrees, maximum_vectors_per_face, vpm, with_border,
                                                   minimum_length, out, np, [](edge_descriptor, bool) {});
  else
  {
    // the map is written only on success
    std::vector<std::pair<edge_descriptor, bool> > flags;
    const Error_code code = internal::select_sharp_edge_constraints(
      tm, angle_in_degrees, maximum_vectors_per_face, vpm, with_border, minimum_length, out, np,
      [&flags](edge_descriptor e, bool kept) { flags.emplace_back(e, kept); });
    if(code == Error_code::SUCCESS)
    {
      auto ecm = get_parameter(np, CGAL::internal_np::edge_is_constrained);
      for(const auto& flag : flags)
        put(ecm, flag.first, flag.second);
    }
    return code;
  }
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_SELECT_SHARP_EDGE_CONSTRAINTS_H
