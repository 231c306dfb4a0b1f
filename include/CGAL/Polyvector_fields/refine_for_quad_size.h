// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_REFINE_FOR_QUAD_SIZE_H
#define CGAL_POLYVECTOR_FIELDS_REFINE_FOR_QUAD_SIZE_H

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/internal/Refinement/refinement.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <map>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// refines the triangle mesh `tm` for a quad mesh of quad size `quad_size`: every
/// edge longer than `2 * quad_size` is split at its midpoint, and the faces on either
/// side with it, until no edge is longer
/// (`CGAL::Polygon_mesh_processing::split_long_edges()`). Then, when there are
/// features (`edge_is_constrained_map`, and the border with `boundary_alignment`),
/// every interior edge that joins two vertices on features without being a feature
/// itself is split at its midpoint: a triangle whose three vertices lie on features
/// would have no area in a map that puts the features on integer iso-lines
/// (`compute_integer_grid_map()`), for instance an ear of the border.
///
/// A seamless map needs a few triangles per quad and room around each singularity;
/// on a coarse mesh (a box of 12 triangles, a cylinder whose caps are fans of long
/// thin triangles) the quads asked for are smaller than the triangles. Splitting
/// moves no vertex: every new vertex is the midpoint of an edge, so it lies on the
/// input surface, and an edge on a crease becomes edges on the same crease.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh, refined in place
/// \param quad_size the target quad size `h > 0`, in mesh units
/// \param face_origin on input, one value per face of `tm` in the order of `faces(tm)`
///        (for example the face's position in a file); on output, one value per face of the
///        refined mesh, in the order of `faces(tm)`: the value of the face it was cut from.
///        An empty vector on input gives the faces' positions.
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the points of the vertices; the midpoints of the split edges are written
///                           through it. CGAL 5.5's default point map of an OpenMesh (without
///                           `CGAL_USE_OM_POINTS`) writes floats: on an OpenMesh whose `Point` is
///                           `OpenMesh::Vec3d`, give a map that writes doubles to keep the midpoints exact}
///     \cgalParamType{a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{the feature edges (for example from `select_sharp_edge_constraints()`); updated:
///                           the halves of a split feature edge are features, the other new edges are not}
///     \cgalParamType{a model of `ReadWritePropertyMap` from `boost::graph_traits<TriangleMesh>::%edge_descriptor`
///                    to `bool`, default constructible}
///     \cgalParamDefault{no feature edge}
///   \cgalParamNEnd
///   \cgalParamNBegin{boundary_alignment}
///     \cgalParamDescription{whether the border edges are features too; given with
///                           `Polyvector_fields::parameters::boundary_alignment()`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `SUCCESS`; `INVALID_PARAMETER` if `quad_size` is not positive or `face_origin`
///          has neither 0 nor `num_faces(tm)` entries; `NON_FINITE_VALUE` for a non-finite
///          `quad_size`; `NON_TRIANGLE_FACE` if a face is not a triangle. On error, `tm`
///          is unchanged.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code refine_for_quad_size(TriangleMesh& tm, double quad_size, std::vector<std::size_t>& face_origin,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  if(!std::isfinite(quad_size))
    return Error_code::NON_FINITE_VALUE;
  if(!(quad_size > 0))
    return Error_code::INVALID_PARAMETER;
  if(!CGAL::is_triangle_mesh(tm))
    return Error_code::NON_TRIANGLE_FACE;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, tm));
  const bool with_border = choose_parameter(get_parameter(np, internal_np::boundary_alignment), false);
  std::size_t feature_splits = 0;
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value)
  {
    std::map<edge_descriptor, bool> none;
    return internal::refine_for_quad_size(tm, quad_size, face_origin, vpm, boost::make_assoc_property_map(none),
                                          with_border, feature_splits);
  }
  else
    return internal::refine_for_quad_size(tm, quad_size, face_origin, vpm,
                                          get_parameter(np, CGAL::internal_np::edge_is_constrained), with_border,
                                          feature_splits);
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_REFINE_FOR_QUAD_SIZE_H
