// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_PARAMETERS_H
#define CGAL_POLYVECTOR_FIELDS_PARAMETERS_H

// Named parameters of this package.
//
// CGAL 5.5 builds the dot-chaining members of `CGAL::Named_function_parameters`
// from a fixed list, so a package outside CGAL cannot add members. Instead each
// parameter of this package is a tag in `CGAL::Polyvector_fields::internal_np`
// and a free function in `CGAL::Polyvector_fields::parameters` that either
// starts a pack or stacks the value on top of an existing pack:
//
//   PVF::parameters::sign_symmetric(true)                       // new pack
//   PVF::parameters::sign_symmetric(true, CGAL::parameters::verbose(true))
//   PVF::parameters::sign_symmetric(true).vertex_point_map(vpm) // CGAL's members chain after ours
//   PVF::parameters::combine(np1, np2)                           // stacks two packs
//
// A value given twice is found at the top of the pack (the last one stacked).

#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#define CGAL_PVF_ADD_NAMED_PARAMETER(TAG_TYPE, TAG_VALUE, FUNCTION)                       \
  namespace CGAL { namespace Polyvector_fields {                                        \
  namespace internal_np { enum TAG_TYPE { TAG_VALUE }; }                                \
  namespace parameters {                                                                \
  template <typename K>                                                                 \
  CGAL::Named_function_parameters<K, internal_np::TAG_TYPE>                             \
  FUNCTION(const K& k)                                                                  \
  { return CGAL::Named_function_parameters<K, internal_np::TAG_TYPE>(k); }              \
  template <typename K, typename T, typename Tag, typename Base>                        \
  CGAL::Named_function_parameters<K, internal_np::TAG_TYPE,                             \
                                  CGAL::Named_function_parameters<T, Tag, Base> >       \
  FUNCTION(const K& k, const CGAL::Named_function_parameters<T, Tag, Base>& np)         \
  {                                                                                     \
    return CGAL::Named_function_parameters<K, internal_np::TAG_TYPE,                    \
                                           CGAL::Named_function_parameters<T, Tag, Base> >(k, np); \
  }                                                                                     \
  } } }

// Field design (paper Section 3).
// `bool`: the field is made of pairs {u, -u} (only even-degree coefficients); default `false`.
CGAL_PVF_ADD_NAMED_PARAMETER(sign_symmetric_t, sign_symmetric, sign_symmetric)
// `Smoothness_weights`: the weight of each interior edge in the smoothness
// energy; default `Smoothness_weights::UNIFORM` (the paper's Eq. 6).
CGAL_PVF_ADD_NAMED_PARAMETER(smoothness_weights_t, smoothness_weights, smoothness_weights)

// Frame fields (paper Section 4).
CGAL_PVF_ADD_NAMED_PARAMETER(angle_bound_t, angle_bound, angle_bound)
CGAL_PVF_ADD_NAMED_PARAMETER(orthogonality_weight_t, orthogonality_weight, orthogonality_weight)
CGAL_PVF_ADD_NAMED_PARAMETER(initial_lambda_t, initial_lambda, initial_lambda)
CGAL_PVF_ADD_NAMED_PARAMETER(lambda_factor_t, lambda_factor, lambda_factor)
CGAL_PVF_ADD_NAMED_PARAMETER(maximum_lambda_t, maximum_lambda, maximum_lambda)
CGAL_PVF_ADD_NAMED_PARAMETER(stopping_rule_t, stopping_rule, stopping_rule)
CGAL_PVF_ADD_NAMED_PARAMETER(tolerance_t, tolerance, tolerance)
CGAL_PVF_ADD_NAMED_PARAMETER(principal_curvature_map_t, principal_curvature_map, principal_curvature_map)

// Input and output.
// `std::size_t`: the degree `N` that a reader expects in the file; a file of
// another degree gives `Error_code::INCONSISTENT_DEGREE`. The default `0`
// accepts any degree.
CGAL_PVF_ADD_NAMED_PARAMETER(expected_degree_t, expected_degree, expected_degree)
// `std::size_t`: the largest input a reader accepts, in bytes.
CGAL_PVF_ADD_NAMED_PARAMETER(maximum_file_size_t, maximum_file_size, maximum_file_size)
// `bool`: whether a mesh reader repairs what it can (see `IO::read_triangle_mesh()`).
CGAL_PVF_ADD_NAMED_PARAMETER(repair_t, repair, repair)

// Parametrization (integer-grid maps).
// `double` in (0, pi/2], in radians: frames whose two directions make a smaller angle
// (or one larger than pi minus it) are clamped to it (see `comb_frame_field()`).
CGAL_PVF_ADD_NAMED_PARAMETER(minimum_frame_angle_t, minimum_frame_angle, minimum_frame_angle)
// `double >= 0`, in mesh units: singular vertices closer than this along mesh edges are
// cancelled, merged or moved apart by the combing (see `comb_frame_field()`); default 0: none.
CGAL_PVF_ADD_NAMED_PARAMETER(singularity_cancellation_distance_t, singularity_cancellation_distance,
                             singularity_cancellation_distance)

// `bool`: the border edges are features too: the field follows them (select_sharp_edge_constraints())
// and the map puts them on integer iso-lines (compute_integer_grid_map()); default `false`.
CGAL_PVF_ADD_NAMED_PARAMETER(boundary_alignment_t, boundary_alignment, boundary_alignment)
// `double >= 0`, in mesh units: networks of sharp edges shorter than this are not features
// (select_sharp_edge_constraints()); default 0: every sharp edge is one.
CGAL_PVF_ADD_NAMED_PARAMETER(minimum_feature_length_t, minimum_feature_length, minimum_feature_length)

// `double > 0`: the length, in mesh units, of one unit of uv along the unit field directions (the quad size).
CGAL_PVF_ADD_NAMED_PARAMETER(target_edge_length_t, target_edge_length, target_edge_length)
// `double > 0`: growth of the face weights at each stiffening round.
CGAL_PVF_ADD_NAMED_PARAMETER(stiffening_factor_t, stiffening_factor, stiffening_factor)
// `bool`: refactor the whole system after each rounding instead of the Schur-complement update (a reference, for tests and benchmarks).
CGAL_PVF_ADD_NAMED_PARAMETER(rounding_by_refactorization_t, rounding_by_refactorization, rounding_by_refactorization)
// `bool`: a stiffening round keeps the integers of the last rounding while that removes flips (default `true`), or rounds them again in every round.
CGAL_PVF_ADD_NAMED_PARAMETER(stiffening_keeps_integers_t, stiffening_keeps_integers, stiffening_keeps_integers)

// Quad meshes.
// `bool`: `extract_quad_mesh()` keeps the cells cut by the mesh boundary as trimmed polygons; default `false` (whole quads only).
CGAL_PVF_ADD_NAMED_PARAMETER(keep_trimmed_boundary_t, keep_trimmed_boundary, keep_trimmed_boundary)
// `std::size_t`: the largest ring count of a fold-over repair region of `extract_quad_mesh()` (0: no repair); default 6.
CGAL_PVF_ADD_NAMED_PARAMETER(fold_over_repair_rings_t, fold_over_repair_rings, fold_over_repair_rings)
// `bool`: `extract_quad_mesh()` cuts the fold-overs that the repair leaves out of the map and fills the holes
// they leave in the quads with quads (whole cells only); default `true` (`false`: they make the call fail).
CGAL_PVF_ADD_NAMED_PARAMETER(fill_fold_overs_t, fill_fold_overs, fill_fold_overs)
// `double >= 0`: an input vertex farther than this many mean quad sides from the quads of `extract_quad_mesh()`
// moves the nearest quad corner onto itself; default 0.3 (0: none).
CGAL_PVF_ADD_NAMED_PARAMETER(tip_snapping_distance_t, tip_snapping_distance, tip_snapping_distance)
// `bool`: a connected component where the map of `extract_quad_mesh()` has no whole cell (smaller than a quad)
// gets its triangles split into quads instead of failing the call; default `false`.
CGAL_PVF_ADD_NAMED_PARAMETER(split_components_without_cells_t, split_components_without_cells,
                             split_components_without_cells)
// `double >= 0`: a connected component of the input of `extract_quad_mesh()` with a vertex or face centroid
// farther than this from the quads gets its triangles split into quads; default 0 (none).
CGAL_PVF_ADD_NAMED_PARAMETER(max_input_distance_t, max_input_distance, max_input_distance)
// `double > 0`: the largest face planarity that `planarize_quad_mesh()` must reach; default 0.01 (1%).
CGAL_PVF_ADD_NAMED_PARAMETER(planarity_threshold_t, planarity_threshold, planarity_threshold)
// `double > 0`: the weight of the closeness (proximal) term of `planarize_quad_mesh()`; default 1.
CGAL_PVF_ADD_NAMED_PARAMETER(closeness_weight_t, closeness_weight, closeness_weight)
// `double >= 0`: the weight of the fairness term (second differences along the polylines) of `planarize_quad_mesh()`; default 0.1.
CGAL_PVF_ADD_NAMED_PARAMETER(fairness_weight_t, fairness_weight, fairness_weight)
// `double` in (0, 1]: the factor applied at each iteration of `planarize_quad_mesh()` to the pull towards the surface and to the fairness target; default 0.9.
CGAL_PVF_ADD_NAMED_PARAMETER(closeness_decay_t, closeness_decay, closeness_decay)
// `double > 0`, in mesh units: the largest distance from a vertex of the result of `planarize_quad_mesh()`
// to the reference surface; default 5% of the mean edge length of the input quad mesh.
CGAL_PVF_ADD_NAMED_PARAMETER(max_distance_to_surface_t, max_distance_to_surface, max_distance_to_surface)
// `std::size_t`: the largest number of kept steps of the Gauss-Newton method that `planarize_quad_mesh()` runs
// when its local-global iterations fail; default 50, 0 for none.
CGAL_PVF_ADD_NAMED_PARAMETER(gauss_newton_steps_t, gauss_newton_steps, gauss_newton_steps)
// `double` in [0, 180], in degrees: the creases of the reference that `planarize_quad_mesh()` holds the
// vertices on them to (edges whose faces' normals make a larger angle), and the turn of the border or of a
// crease above which a vertex stays where it was; default 40, 180 for no crease.
CGAL_PVF_ADD_NAMED_PARAMETER(crease_angle_t, crease_angle, crease_angle)

// Curvature estimation and curvature constraints.
CGAL_PVF_ADD_NAMED_PARAMETER(ring_size_t, ring_size, ring_size)
CGAL_PVF_ADD_NAMED_PARAMETER(anisotropy_threshold_t, anisotropy_threshold, anisotropy_threshold)
CGAL_PVF_ADD_NAMED_PARAMETER(constrained_fraction_t, constrained_fraction, constrained_fraction)

// The HTML viewer (`IO::write_HTML_viewer()`) and the PLY writer of quad meshes.
// `std::string`: the folder of Debian's libjs-three (three.js r111), whose `three.min.js` and
// `examples/js/controls/OrbitControls.js` are copied into the page; default `/usr/share/javascript/three`.
CGAL_PVF_ADD_NAMED_PARAMETER(three_js_directory_t, three_js_directory, three_js_directory)
// `std::string`: the title of the page, before its summary figures; default "CGAL Polyvector Fields".
CGAL_PVF_ADD_NAMED_PARAMETER(page_title_t, page_title, page_title)
// `std::size_t >= 1`: above this many faces, the page draws the field on a regular subsample of
// about this many faces; default 20000.
CGAL_PVF_ADD_NAMED_PARAMETER(max_glyph_faces_t, max_glyph_faces, max_glyph_faces)
// `double > 0`: the planarity drawn in the red of the colour map (larger values too); default the
// largest planarity of the quad mesh (1% if every quad is planar).
CGAL_PVF_ADD_NAMED_PARAMETER(planarity_colour_range_t, planarity_colour_range, planarity_colour_range)

// Parameters that refer to an object of the caller instead of copying it:
// the named parameter holds its address, and the object must outlive the call.
#define CGAL_PVF_ADD_REFERENCE_PARAMETER(TAG_TYPE, TAG_VALUE, FUNCTION, ...)                  \
  namespace CGAL { namespace Polyvector_fields {                                            \
  namespace internal_np { enum TAG_TYPE { TAG_VALUE }; }                                    \
  namespace parameters {                                                                    \
  inline CGAL::Named_function_parameters<__VA_ARGS__*, internal_np::TAG_TYPE>              \
  FUNCTION(__VA_ARGS__& value)                                                              \
  { return CGAL::Named_function_parameters<__VA_ARGS__*, internal_np::TAG_TYPE>(&value); }  \
  template <typename T, typename Tag, typename Base>                                        \
  CGAL::Named_function_parameters<__VA_ARGS__*, internal_np::TAG_TYPE,                     \
                                  CGAL::Named_function_parameters<T, Tag, Base> >           \
  FUNCTION(__VA_ARGS__& value, const CGAL::Named_function_parameters<T, Tag, Base>& np)     \
  {                                                                                         \
    return CGAL::Named_function_parameters<__VA_ARGS__*, internal_np::TAG_TYPE,            \
                                           CGAL::Named_function_parameters<T, Tag, Base> >(&value, np); \
  }                                                                                         \
  } } }

// `std::string&`: receives, when a reader fails, the reason and where it is in the input.
CGAL_PVF_ADD_REFERENCE_PARAMETER(error_message_t, error_message, error_message, std::string)
// `std::size_t&`: receives the number of vertices whose curvature comes from
// the fallback estimator of `estimate_principal_curvatures()`.
CGAL_PVF_ADD_REFERENCE_PARAMETER(fallback_vertices_t, fallback_vertices, fallback_vertices, std::size_t)

// The per-face arrays of `IO::write_VTK()`, named, and its constrained faces
// as one flag per face (in the order of faces(tm)) or as a list of faces.
CGAL_PVF_ADD_REFERENCE_PARAMETER(face_scalars_t, face_scalars, face_scalars,
                                 const std::vector<std::pair<std::string, std::vector<double> > >)
CGAL_PVF_ADD_REFERENCE_PARAMETER(is_constrained_t, is_constrained, is_constrained, const std::vector<bool>)

namespace CGAL {
namespace Polyvector_fields {
namespace internal_np {
enum constrained_faces_t { constrained_faces };
enum quad_mesh_t { quad_mesh };
} // namespace internal_np
namespace parameters {

template <typename FaceDescriptor>
CGAL::Named_function_parameters<const std::vector<FaceDescriptor>*, internal_np::constrained_faces_t>
constrained_faces(const std::vector<FaceDescriptor>& faces)
{
  return CGAL::Named_function_parameters<const std::vector<FaceDescriptor>*, internal_np::constrained_faces_t>(&faces);
}

template <typename FaceDescriptor, typename T, typename Tag, typename Base>
CGAL::Named_function_parameters<const std::vector<FaceDescriptor>*, internal_np::constrained_faces_t,
                                CGAL::Named_function_parameters<T, Tag, Base> >
constrained_faces(const std::vector<FaceDescriptor>& faces, const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return CGAL::Named_function_parameters<const std::vector<FaceDescriptor>*, internal_np::constrained_faces_t,
                                         CGAL::Named_function_parameters<T, Tag, Base> >(&faces, np);
}

// The quad mesh shown by `IO::write_HTML_viewer()`: a reference to the caller's polygon mesh,
// which must outlive the call.
template <typename PolygonMesh>
CGAL::Named_function_parameters<const PolygonMesh*, internal_np::quad_mesh_t>
quad_mesh(const PolygonMesh& pm)
{
  return CGAL::Named_function_parameters<const PolygonMesh*, internal_np::quad_mesh_t>(&pm);
}

template <typename PolygonMesh, typename T, typename Tag, typename Base>
CGAL::Named_function_parameters<const PolygonMesh*, internal_np::quad_mesh_t,
                                CGAL::Named_function_parameters<T, Tag, Base> >
quad_mesh(const PolygonMesh& pm, const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return CGAL::Named_function_parameters<const PolygonMesh*, internal_np::quad_mesh_t,
                                         CGAL::Named_function_parameters<T, Tag, Base> >(&pm, np);
}

} // namespace parameters
} // namespace Polyvector_fields
} // namespace CGAL

namespace CGAL {
namespace Polyvector_fields {
namespace IO {
namespace internal {
// The default of the named parameter `maximum_file_size`: 1 GiB.
constexpr std::size_t default_maximum_file_size = std::size_t(1) << 30;
} // namespace internal
} // namespace IO

namespace parameters {

// CGAL's own parameters that this package reads, so that a user can name every
// parameter through CGAL::Polyvector_fields::parameters.
using CGAL::parameters::default_values;
using CGAL::parameters::vertex_point_map;
using CGAL::parameters::geom_traits;
using CGAL::parameters::sparse_linear_solver;
using CGAL::parameters::number_of_iterations;
using CGAL::parameters::verbose;
using CGAL::parameters::degree_fitting;
using CGAL::parameters::degree_monge;
using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::is_default_parameter;

namespace internal {

// Re-stacks every entry of `top` onto `base`, keeping their order.
template <typename Base>
const Base& restack(const CGAL::Named_function_parameters<bool, CGAL::internal_np::all_default_t>&,
                    const Base& base)
{
  return base;
}

template <typename T, typename Tag, typename Base>
CGAL::Named_function_parameters<T, Tag, Base>
restack(const CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>& top,
        const Base& base)
{
  return CGAL::Named_function_parameters<T, Tag, Base>(top.v, base);
}

template <typename T, typename Tag, typename TopBase, typename Base>
auto restack(const CGAL::Named_function_parameters<T, Tag, TopBase>& top, const Base& base)
{
  auto below = restack(static_cast<const TopBase&>(top), base);
  return CGAL::Named_function_parameters<T, Tag, decltype(below)>(top.v, below);
}

} // namespace internal

// stacks the named-parameter packs `np1`, `np2`, ...; a value given in a later
// pack hides the same parameter in an earlier one.
template <typename NP1>
const NP1& combine(const NP1& np1)
{
  return np1;
}

template <typename NP1, typename NP2, typename... NPs>
auto combine(const NP1& np1, const NP2& np2, const NPs&... nps)
{
  return combine(internal::restack(np2, np1), nps...);
}

} // namespace parameters
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_PARAMETERS_H
