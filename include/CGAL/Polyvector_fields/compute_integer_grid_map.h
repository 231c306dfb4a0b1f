// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_COMPUTE_INTEGER_GRID_MAP_H
#define CGAL_POLYVECTOR_FIELDS_COMPUTE_INTEGER_GRID_MAP_H

/// \file compute_integer_grid_map.h
/// The mixed-integer quadrangulation of Bommes, Zimmer and Kobbelt (2009)
/// from a (possibly non-orthogonal) frame field: a seamless map whose integer
/// iso-lines follow the field, with every singular vertex on an integer point.
/// It works on one `Tangent_bundle` and on the cut graph of `comb_frame_field()`:
/// the seams are found once, and the map returns their exact transitions for
/// `extract_quad_mesh()`.

#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/comb_frame_field.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/seamless_map_solve.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/seamless_reduction.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// is the transition of a seamless map across an interior edge, from the chart
/// of `face(h)` to the chart of `face(opposite(h))`: `uv_B = R^rotation uv_A +
/// translation`, `R` the quarter turn counterclockwise. It is exact: `rotation`
/// is the combed rotation of the edge and `translation` is computed over the
/// integers from the map's unknowns.
struct Seam_transition
{
  int rotation = 0;                                   ///< in `0..3`; 0 off the cut graph
  std::array<std::int64_t, 2> translation{ { 0, 0 } };  ///< integer; 0 off the cut graph
};

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// reports on a run of `compute_integer_grid_map()`, and holds the exact seam
/// transitions of the map it computed (what `extract_quad_mesh()` consumes).
struct Integer_grid_map_result
{
  Comb_result comb;                       ///< the combing and the cut (clamped faces, singular vertices, all placed on integer points, seam curves, cut edges)
  std::size_t faces = 0;                  ///< faces of the mesh
  std::size_t continuous_unknowns = 0;    ///< scalar continuous unknowns (2 per regular vertex, minus pins)
  std::size_t integer_unknowns = 0;       ///< scalar integer unknowns after the exact reduction (and pins)
  std::size_t integer_unknowns_before_reduction = 0;  ///< 2 (singular vertices + seam curves)
  std::size_t extra_integer_relations = 0;///< relations left at the root of a seam tree (expected 0)
  std::size_t feature_edges = 0;          ///< edges asked to lie on integer iso-lines: the edges of `edge_is_constrained_map`, and the border edges with `boundary_alignment`
  std::size_t aligned_feature_edges = 0;  ///< of them, on an integer iso-line of the map (exactly)
  std::size_t unaligned_feature_edges = 0;///< of them, left free because the field does not run along them (within `max_feature_angle`)
  std::size_t dropped_feature_edges = 0;  ///< of them, left free because their relation could not be eliminated over the integers (expected 0)
  std::size_t flattening_feature_edges = 0;  ///< of them, left free because another feature edge of one of their faces keeps the same coordinate: on one iso-line, the two would flatten the face (see <b>Features</b>)
  std::size_t released_feature_edges = 0; ///< of them, left free because faces around them stayed flipped with them aligned (see <b>Features</b>)
  std::size_t feature_vertices = 0;       ///< vertices on an aligned feature edge
  std::size_t feature_corners = 0;        ///< of them, regular vertices put on an integer point: the field follows two feature curves there, or one that turns (see Features)
  std::size_t flipped_faces = 0;          ///< faces that the output does not lay out injectively: det(grad uv) <= 0, or around a vertex whose star winds the wrong number of turns (see <b>Flips</b>)
  std::vector<std::size_t> flipped_per_round;  ///< flipped faces after each stiffening round
  std::size_t stiffening_rounds = 0;      ///< solves after the first one
  std::size_t integer_roundings = 0;      ///< solves that rounded the integer unknowns (the first, and the stiffening rounds after one that did not remove flips); the other rounds keep the integers and solve for the continuous unknowns only
  std::size_t factorizations = 0;         ///< numeric factorizations of the sparse system
  std::size_t cg_solves = 0;              ///< stiffening rounds that kept the integers and were solved by conjugate gradient, preconditioned by an earlier factorization, instead of a new one (see <b>Solve</b>)
  std::size_t cg_iterations = 0;          ///< their iterations, in all
  std::size_t integer_point_collisions_avoided = 0;  ///< roundings that took the other integer next to the minimiser, so that two integer points of one face (singular vertices, feature corners) did not meet (all rounds)
  double target_edge_length = 0;          ///< h used
  double mean_edge_length = 0;            ///< of the mesh
  double continuous_energy = 0;           ///< sum A_f |grad uv - J*_f|^2 of the continuous (unrounded) optimum, unit weights
  double rounded_energy = 0;              ///< the same energy for the output
  double energy_ratio = 0;                ///< rounded / continuous
  double max_seam_residual = 0;           ///< worst |uv_B - (R^r uv_A + t)| over interior edge endpoints, (r, t) the edge's transition in `seam_transitions` (output): 0 on success
  double max_seam_residual_before_snapping = 0;  ///< before the values are snapped to a dyadic grid: the same with the edge's combed rotation and `t` the nearest integer vector (0 off the cut)
  double max_singularity_residual = 0;    ///< worst distance of a singular corner to the integer grid (output)
  std::size_t inconsistencies = 0;        ///< internal checks that failed (expected 0)
  std::string diagnostic;                 ///< empty on success; for `MAP_CHECK_FAILED`, the check that failed and where
  // times in seconds
  double time_comb = 0;           ///< the tangent bundle (when a mesh is given), matching, singularities, combing, cut, seam curves (0 when a comb is given)
  double time_reduction = 0;      ///< sectors, seam relations, exact elimination over Z[i]
  double time_assembly = 0;       ///< gradient operator and normal equations (all rounds)
  double time_factorization = 0;  ///< sparse factorizations (all rounds)
  double time_schur = 0;          ///< solves for the Schur complement of the integer unknowns (all rounds)
  double time_rounding = 0;       ///< greedy rounding with updates (all rounds)
  double time_cg = 0;             ///< conjugate gradient (all rounds)
  double time_stiffening = 0;     ///< everything spent in rounds after the first
  double time_output = 0;         ///< snapping, checks and writing the map
  double time_total = 0;  ///< the whole call
  /// the exact transition across the edge of every corner, in the numbering of `Frame_field_comb`
  /// (corner `3f+k`: the `k`-th halfedge of face `f` from `halfedge(face)`, `f` the bundle's index);
  /// the identity off the cut graph and on the boundary. Filled on success.
  std::vector<Seam_transition> seam_transitions;
};


/// \ingroup PkgPolyvectorFieldsParametrization
///
/// computes a seamless integer-grid map guided by the combed frame field `comb`
/// (computed by `comb_frame_field()`), on its tangent bundle and cut graph: see
/// the other overload for the energy, the solve and the output. The seams are
/// those of `comb` (nothing is combed again); `result.comb` is `comb.report()`
/// and `result.seam_transitions` the exact transitions of the map.
///
/// \tparam Bundle a `Tangent_bundle`
/// \tparam UVMap as in the other overload
///
/// \param comb a valid comb (`comb.is_valid()`)
/// \param uv_map receives the map, for every halfedge of a face
/// \param result receives the counts, measures, times and the seam transitions
/// \param np the named parameters of the other overload but `minimum_frame_angle` (the comb's)
///            and `vertex_point_map` (the bundle's)
///
/// \returns as the other overload; `INVALID_PARAMETER` also if `comb` is not valid.
template <typename Bundle, typename UVMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code compute_integer_grid_map(const Frame_field_comb<Bundle>& comb, UVMap uv_map, Integer_grid_map_result& result,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::sparse_linear_solver_t, NamedParameters,
                                                             Default_real_sparse_solver>::type Solver;
  const auto start = std::chrono::steady_clock::now();
  result = Integer_grid_map_result();
  internal::Seamless_map_parameters p;
  Error_code code = internal::read_seamless_map_parameters(np, p);
  const Solver solver_prototype = choose_parameter(get_parameter(np, CGAL::internal_np::sparse_linear_solver), Solver());
  if(code != Error_code::SUCCESS)
    return code;
  if(!comb.is_valid())
    return Error_code::INVALID_PARAMETER;
  const auto& M = comb.corner_mesh();
  const internal::Comb_data& D = comb.data();
  result.comb = comb.report();
  result.mean_edge_length = internal::mean_edge_length(M);
  code = internal::check_edge_length(p);
  if(code != Error_code::SUCCESS)
    return code;
  const double h = p.edge_length_given ? p.edge_length : result.mean_edge_length;
  result.target_edge_length = h;
  result.faces = M.F;
  result.inconsistencies += D.pruned_nonzero_rotation + (D.matching_inconsistent ? 1 : 0);

  // reduced unknowns, guidance system, rounds of solves; with features, again
  // without the features around faces that stay flipped (see Features)
  std::vector<char> feature;
  const bool has_features = internal::feature_corners(M, np, feature);
  auto t = std::chrono::steady_clock::now();
  internal::Seamless_reduction seams;  // the seams' reduction, the same in every attempt
  code = internal::reduce_seamless_variables(M, D, seams);
  result.inconsistencies += seams.inconsistencies;
  result.extra_integer_relations = seams.extra_relations;
  if(code != Error_code::SUCCESS)
    return code;
  result.integer_unknowns_before_reduction = 2 * (result.comb.singular_vertices + result.comb.seam_curves);
  result.time_reduction = internal::seconds_since(t);
  internal::Seamless_reduction R;
  internal::Guidance_system S;
  Eigen::VectorXd y;
  std::size_t nx = 0, m = 0;
  for(std::size_t attempt = 0;; ++attempt)
  {
    t = std::chrono::steady_clock::now();
    R = seams;
    if(has_features)
    {
      internal::Feature_alignment_report features;
      internal::align_features(M, D, feature, internal::max_feature_angle, h, R, features);
      result.aligned_feature_edges = features.aligned_edges;
      result.unaligned_feature_edges = features.unaligned_edges;
      result.dropped_feature_edges = features.dropped_edges;
      result.flattening_feature_edges = features.flattening_edges;
      result.feature_vertices = features.feature_vertices;
      result.feature_corners = features.feature_corners;
      if(attempt == 0)
        result.feature_edges = features.feature_edges;
    }
    nx = R.continuous_columns;
    m = R.integer_columns;
    result.continuous_unknowns = nx;
    result.integer_unknowns = m;
    result.time_reduction += internal::seconds_since(t);
    t = std::chrono::steady_clock::now();
    S = internal::Guidance_system();
    internal::assemble_guidance(M, D, R, h, nx + m, S);
    result.time_assembly += internal::seconds_since(t);
    result.flipped_per_round.clear();
    result.stiffening_rounds = 0;
    result.integer_roundings = 0;
    result.cg_solves = result.cg_iterations = 0;
    // before the last solve, the wider search only for a few flips (see Solve)
    const bool last = !has_features || attempt == internal::max_feature_releases;
    bool narrowed = false;
    code = internal::solve_with_stiffening(
      M, S, nx, m, p, solver_prototype, R,
      last ? std::numeric_limits<std::size_t>::max() : internal::wide_search_max_flips_before_release,
      last ? internal::stiffening_patience : internal::wide_search_patience_before_release, y, narrowed, result);
    if(code != Error_code::SUCCESS)
      return code;
    auto flat = [&result]() {
      return result.flipped_per_round.empty() ||
             *std::min_element(result.flipped_per_round.begin(), result.flipped_per_round.end()) == 0;
    };
    if(last || flat())
      break;
    std::size_t released = internal::release_features_near_flips(M, R, S, y, feature);
    if(released == 0 && narrowed)
    {
      // this map would be the one returned: the wider search first, then the
      // release again, on its flips
      result.flipped_per_round.clear();
      result.stiffening_rounds = 0;
      result.integer_roundings = 0;
      result.cg_solves = result.cg_iterations = 0;
      code = internal::solve_with_stiffening(M, S, nx, m, p, solver_prototype, R,
                                             std::numeric_limits<std::size_t>::max(), internal::stiffening_patience, y,
                                             narrowed, result);
      if(code != Error_code::SUCCESS)
        return code;
      if(flat())
        break;
      released = internal::release_features_near_flips(M, R, S, y, feature);
    }
    result.released_feature_edges += released;
    if(released == 0)
      break;
  }

  // output: snapped to a dyadic grid, so that seams and singularities are exact
  t = std::chrono::steady_clock::now();
  code = internal::write_snapped_map(M, D, R, S, nx, m, y, uv_map, result);
  result.time_output = internal::seconds_since(t);
  result.time_total = internal::seconds_since(start);
  return code;
}

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// computes a seamless integer-grid map of a triangle mesh guided by the frame
/// field of `coefficient_map` (Bommes, Zimmer, Kobbelt 2009: mixed-integer
/// quadrangulation).
///
/// <b>Combing and cut.</b> The field is cleaned, combed and cut once by
/// `comb_frame_field()` (same named parameter `minimum_frame_angle`), on the
/// same tangent bundle, and the map is computed from that comb by the other
/// overload: a caller who already has the comb calls that one.
///
/// <b>Target.</b> In face `f`, with `u`, `v` the combed unit field directions
/// (see `comb_frame_field()`; clamped faces included) as complex numbers in the
/// face frame, the target Jacobian is `J*_f = h^-1 [u v]^-1`: moving by `h`
/// along `u` moves the map by one unit in its first coordinate and not at all
/// in the second, and the same for `v`. For a non-orthogonal frame this is
/// the dual basis; the integer iso-lines follow `u` and `v`.
///
/// <b>Energy.</b> `sum_f w_f A_f |grad uv - J*_f|^2` over the uv of every
/// corner, with the seams `uv_B = R^r uv_A + t` (R the quarter turn, r the
/// rotation of the cut edge, `t` in Z^2 per seam curve) and every singular
/// vertex on an integer point, by construction: the unknowns are one uv per
/// vertex (its first sector) and, as integers, the uv of the singular vertices
/// and the translations of the seam curves that the exact elimination of the
/// seam relations over the Gaussian integers leaves free. One translation per
/// component is pinned (a singular vertex at the origin, or the first vertex).
/// The boundary is free, unless it is a feature.
///
/// <b>Features.</b> The edges of `edge_is_constrained_map` (sharp edges, say
/// from `select_sharp_edge_constraints()`), and the border edges with
/// `boundary_alignment`, are features. Along a feature edge whose field
/// direction (`u` or `v` in one of its faces) makes an angle of at most
/// 30 degrees with the edge, the map keeps the other coordinate constant and
/// integer: the edge lies on an integer iso-line, so a chain of such edges
/// becomes a chain of quad edges. The coordinate of each vertex on such an
/// edge becomes an integer unknown, and the relation "same value at both ends"
/// of each edge is eliminated exactly over the integers (as the seams), so the
/// alignment is exact in the output. A vertex where the field follows two
/// feature curves (a corner of a box) gets both coordinates integer: a quad
/// corner. So does a vertex where one feature curve turns by more than
/// 5 degrees between two edges at least one quad long (the rim of a coarse
/// cylinder): a quad edge is straight in space, and without a corner there it
/// would cut the bend. A finely sampled curve (shorter edges) keeps its
/// vertices free along the iso-line: consecutive integer points would make
/// it rigid, and fold the map where the field turns against the curve. A feature edge along which neither field direction runs is left
/// free and counted (`unaligned_feature_edges`): where feature curves meet
/// at an angle that the frame does not have (two creases at 30 degrees, say,
/// with an orthogonal frame), only the curve that the field follows is on an
/// iso-line. Two feature edges of one triangle along the same field direction
/// (an ear of the border, or a triangle across a crease that the field follows
/// on both sides) would put its three corners on one iso-line, and the
/// triangle would have no area in the map: the shorter of the two is left
/// free (`flattening_feature_edges`). Design the field with the features as constraints first, so
/// that it follows them. Features closer to each other than about half a quad
/// are put on the same or neighbouring iso-lines, which fold the faces
/// between them: when faces stay flipped after the stiffening, the feature
/// edges with an endpoint on a flipped face are left free and the map is
/// solved again, at most 3 times (`released_feature_edges`). The quad size
/// must resolve the features for them all to be kept.
///
/// <b>Flips.</b> A face is flipped when its map has `det(grad uv) <= 0`, and
/// also when every face around one of its vertices is positive but the star of
/// that vertex turns by the wrong angle in the map. Around an interior vertex,
/// the star must turn `(4 - k) pi / 2` for a cone of index `k/4`, and `2 pi`
/// for a regular vertex. A regular vertex whose star turns `4 pi` is a branch
/// point: the map covers the plane twice there. A border vertex off the integer
/// grid must turn less than `2 pi`. A star with a corner angle within `1e-6` of
/// 0 or `pi` is left to the exact tests of `extract_quad_mesh()`. The
/// stiffening, the release of features and `result.flipped_faces` count both
/// kinds.
///
/// <b>Solve.</b> The continuous block is factored once per round (sparse SPD,
/// `sparse_linear_solver`); the integer unknowns are eliminated through their
/// Schur complement (dense, small), rounded greedily (closest to an integer
/// first) with an exact O(m^2) update of the minimiser and of the inverse per
/// rounding. Two integer points of one face (singular vertices, feature
/// corners) are kept apart: when the nearest integer of the last free unknown
/// of their difference would make them meet, the integer on the other side of
/// the minimiser is taken (`integer_point_collisions_avoided`). Then the flipped faces (see <b>Flips</b>) and the faces around them get
/// a larger weight and the problem is solved again, at most
/// `number_of_iterations` times (stiffening); the round with the fewest flips is kept.
/// A stiffening round keeps the integers of the last rounding and solves for
/// the continuous unknowns only: the normal equations are updated on the
/// reweighted faces and, since stiffening only raises weights, solved by
/// conjugate gradient preconditioned by the last factorization
/// (`cg_solves`, `cg_iterations`, for the rounds of the map returned). Its stopping rule,
/// `r^T M^-1 r <= 10^-24 b^T M^-1 b` with `M` the factored matrix, bounds the
/// error in the energy norm by `10^-12 kappa^(1/2)` of the solution, `kappa`
/// the largest ratio of a weight to its factored value (at most `10^6`); after
/// 30 iterations without convergence the system is factored again, on the
/// ordering of the first round, and solved directly. After a round that did not lower the number of flips, the next one rounds
/// the integers again (`integer_roundings`). The rounds end after 8 rounds in
/// a row without fewer flips than the best one. When faces still flip, the
/// rounds start again from unit weights and round the integers in every round
/// (a wider search, slower: a Schur complement per round), and the best round
/// of both is kept; the first round of both, with unit weights, is solved
/// once. With features, a solve that will release features (see
/// <b>Features</b>) runs the wider search only when the fast rounds left at
/// most 16 flipped faces: beyond, the features beside them are released
/// whatever the search; and that search ends after 4 rounds in a row without
/// fewer flips than its best. The map that is returned always had the wider
/// search (with that patience of 4 when no feature was beside its flips). The greedy rounding updates only the block of the integers
/// still free, about `m^3 / 3` operations for `m` integer unknowns.
///
/// <b>Output.</b> `uv_map[h]` is the value at `target(h)` inside `face(h)`. The
/// values are snapped to a dyadic grid (2^-k, about 1e-12 of a quad), so that
/// across every seam `uv_B = R^r uv_A + t` holds exactly in floating point and
/// singular vertices are exactly integer. `result.seam_transitions` holds the
/// transition of every edge, exact (see `Seam_transition`).
///
/// All computations are done in `double`, whatever the kernel of the mesh.
///
/// \tparam Mesh_or_bundle a `Tangent_bundle`, or a model of `FaceListGraph` (whose bundle is then built
///         with the named parameter `vertex_point_map`); in both cases the mesh is a triangle mesh
/// \tparam CoefficientMap a model of `ReadablePropertyMap` from faces to `std::vector<std::complex<double>>`
///         of size 4: a sign-symmetric 4-PolyVector field (a frame field)
/// \tparam UVMap a model of `WritablePropertyMap` from halfedges to a type constructible as `{u, v}` from
///         two `double` values (`Point_2`, `std::array<double, 2>`): the value at `target(h)` inside `face(h)`
///
/// \param mesh_or_bundle the mesh, or its tangent bundle
/// \param coefficient_map the frame field
/// \param uv_map receives the map, for every halfedge of a face
/// \param result receives the counts, measures and times (also on failure, as far as they were computed)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{target_edge_length}
///     \cgalParamDescription{the length `h`, in mesh units, of one unit of uv along the unit field
///                           directions: the quad size; given with `Polyvector_fields::parameters::target_edge_length()`}
///     \cgalParamType{`double > 0`}
///     \cgalParamDefault{the mean edge length of the mesh}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_frame_angle}
///     \cgalParamDescription{the smallest angle, in radians, between `u` and `v`; see `comb_frame_field()`}
///     \cgalParamType{`double` in `(0, pi/2]`}
///     \cgalParamDefault{10 degrees}
///   \cgalParamNEnd
///   \cgalParamNBegin{singularity_cancellation_distance}
///     \cgalParamDescription{singular vertices closer than this are cancelled, merged or moved apart
///                           before the map is solved, and the frames near the matching this changes
///                           turn to follow it; see `comb_frame_field()`}
///     \cgalParamType{`double >= 0`, in mesh units}
///     \cgalParamDefault{0: every singularity of the field is kept}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{a property map telling which edges are features, to be put on integer
///                           iso-lines (see <b>Features</b>); given with `CGAL::parameters::edge_is_constrained_map()`}
///     \cgalParamType{a model of `ReadablePropertyMap` from `boost::graph_traits<TriangleMesh>::%edge_descriptor` to `bool`}
///     \cgalParamDefault{no feature edge}
///   \cgalParamNEnd
///   \cgalParamNBegin{boundary_alignment}
///     \cgalParamDescription{whether the border edges are features too; given with
///                           `Polyvector_fields::parameters::boundary_alignment()`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`: a free boundary}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the maximum number of stiffening rounds after the first solve}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{20}
///   \cgalParamNEnd
///   \cgalParamNBegin{stiffening_factor}
///     \cgalParamDescription{the weight of a face near a flip is multiplied by `1 + stiffening_factor * d`
///                           at each round, `d` its relative distortion (at least 1 on a flipped face);
///                           given with `Polyvector_fields::parameters::stiffening_factor()`}
///     \cgalParamType{`double > 0`}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{rounding_by_refactorization}
///     \cgalParamDescription{in the first round, refactor the system after each rounding instead of
///                           updating the Schur complement (a slow reference, for tests and benchmarks);
///                           given with `Polyvector_fields::parameters::rounding_by_refactorization()`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{stiffening_keeps_integers}
///     \cgalParamDescription{whether the stiffening rounds first keep the integers of the last rounding as
///                           long as that lowers the number of flipped faces (one factorization and one solve
///                           per round), and round them in every round only when faces still flip after
///                           that; or round them in every round from the start (a Schur complement per
///                           round: slower, another search); given with
///                           `Polyvector_fields::parameters::stiffening_keeps_integers()`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{sparse_linear_solver}
///     \cgalParamDescription{a model of `SparseLinearAlgebraWithFactorTraits_d` on `double`, copied for each factorization}
///     \cgalParamDefault{`Default_real_sparse_solver`}
///   \cgalParamNEnd
///   \pvfParamVertexPointMap
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::SUCCESS`; a mesh error of the bundle (`EMPTY_MESH`, `NON_TRIANGLE_FACE`,
///          `DEGENERATE_FACE`) or `NON_MANIFOLD_MESH` (a vertex whose faces do not form a fan);
///          `NON_FINITE_VALUE` for a coefficient or a parameter; `INVALID_PARAMETER` for a parameter out
///          of its range (`target_edge_length <= 0`, `minimum_frame_angle`, `stiffening_factor`);
///          `NOT_A_FRAME_FIELD` or `ZERO_FRAME` as `comb_frame_field()`; `SOLVER_FAILURE` if a factorization
///          or a solve fails (also if the seam relations could not be eliminated over the Gaussian integers,
///          which no test mesh has shown); `MAP_CHECK_FAILED` if the computed map fails its final check
///          (`result.diagnostic` says which part): before it is returned, the map is checked exactly from its
///          values and `result.seam_transitions` alone: every seam exact under its transition, the two
///          sides of every edge inverse, every singular vertex on an integer point, the transitions
///          around every interior regular vertex composing to the identity, and every aligned feature
///          edge on an integer iso-line. `uv_map` is written only on
///          success; the mesh is never changed.
///
/// \sa `comb_frame_field()`, `extract_quad_mesh()`, `IO::write_integer_grid_map_OBJ()`
template <typename Mesh_or_bundle, typename CoefficientMap, typename UVMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code compute_integer_grid_map(const Mesh_or_bundle& mesh_or_bundle, CoefficientMap coefficient_map,
                                    UVMap uv_map, Integer_grid_map_result& result,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto start = std::chrono::steady_clock::now();
  result = Integer_grid_map_result();
  double min_angle = 0;
  Error_code code = internal::read_minimum_frame_angle(np, min_angle);
  if(code != Error_code::SUCCESS)
    return code;
  internal::Seamless_map_parameters p;
  code = internal::read_seamless_map_parameters(np, p);
  if(code != Error_code::SUCCESS)
    return code;
  const auto& bundle = internal::bundle_of(mesh_or_bundle, np);
  if(bundle.status() != Error_code::SUCCESS)
    return bundle.status();
  code = internal::check_edge_length(p);
  if(code != Error_code::SUCCESS)
    return code;
  double cancellation_distance = 0;
  code = internal::read_cancellation_distance(np, cancellation_distance);
  if(code != Error_code::SUCCESS)
    return code;
  Frame_field_comb<std::decay_t<decltype(bundle)> > comb;
  code = comb.compute(bundle, coefficient_map, min_angle, cancellation_distance);
  result.comb = comb.report();
  if(code != Error_code::SUCCESS)
    return code;
  const double time_comb = internal::seconds_since(start);
  code = compute_integer_grid_map(comb, uv_map, result, np);
  result.time_comb = time_comb;
  result.time_total = internal::seconds_since(start);
  return code;
}

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// computes the seamless integer-grid map guided by the frame field `field`
/// (degree 4, sign-symmetric), as the overload on a tangent bundle and a
/// coefficient map: it combs the field once (`comb_frame_field()`), then maps
/// the comb (the overload on a `Frame_field_comb`).
///
/// \returns as the overload on a coefficient map, and `NOT_A_FRAME_FIELD` if `field` is not of degree 4
///          and sign-symmetric.
template <typename TangentBundle, typename UVMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code compute_integer_grid_map(const Polyvector_field<TangentBundle>& field, UVMap uv_map,
                                    Integer_grid_map_result& result,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  if(!field.is_frame_field())
  {
    result = Integer_grid_map_result();
    return Error_code::NOT_A_FRAME_FIELD;
  }
  return compute_integer_grid_map(field.tangent_bundle(), field.coefficient_map(), uv_map, result, np);
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_COMPUTE_INTEGER_GRID_MAP_H
