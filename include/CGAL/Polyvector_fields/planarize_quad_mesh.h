// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// Quad-mesh planarization (the planarity goal, fairness and
// closeness to a reference surface of Liu, Pottmann, Wallner, Yang, Wang 2006),
// solved by local-global iterations with one prefactored matrix.

#ifndef CGAL_POLYVECTOR_FIELDS_PLANARIZE_QUAD_MESH_H
#define CGAL_POLYVECTOR_FIELDS_PLANARIZE_QUAD_MESH_H

/// \file planarize_quad_mesh.h

#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Sparse_factorization.h>
#include <CGAL/Polyvector_fields/internal/Planarization/Local_global_planarization.h>
#include <CGAL/Polyvector_fields/parameters.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Sparse>

#include <cstddef>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// reports on a run of `planarize_quad_mesh()`; filled also on failure, as far as it was computed.
struct Planarization_result
{
  std::size_t iterations = 0;                  ///< local-global iterations done
  bool converged = false;                      ///< every face reached `planarity_threshold`
  bool left_surface = false;                   ///< the local-global iterations stopped before the threshold: with the pull towards the surface at its floor, a vertex was farther than `distance_bound` from it (their outcome `Error_code::TOO_FAR_FROM_SURFACE`, unless the second method succeeds)
  double threshold = 0;                        ///< `planarity_threshold` used
  double max_planarity_before = 0;             ///< largest face planarity of the input
  double mean_planarity_before = 0;            ///< mean face planarity of the input
  double max_planarity_after = 0;              ///< largest face planarity of the last iterate
  double mean_planarity_after = 0;             ///< mean face planarity of the last iterate
  double max_distance = 0;                     ///< largest distance of a vertex of the last iterate to the reference surface (for a vertex on the border or a crease, the larger of that and its distance to them; for a corner, the larger of that and its distance to its input position): the worst distance, at most `distance_bound` on success
  double mean_distance = 0;                    ///< mean distance of the vertices of the last iterate to the reference surface
  double max_distance_to_quads_before = 0;     ///< the other side of `max_distance_before`: the largest distance from the surface (sampled at the vertices of `reference` and of the input) to the input quads, each taken as the four triangles of its two diagonals (measured when a result needs it, 0 otherwise)
  double max_distance_to_quads = 0;            ///< the same distance to the quads of the last iterate, measured once it reached the threshold within `distance_bound` (0 otherwise): at most `max_distance_to_quads_before + distance_bound` on success (otherwise `Error_code::TOO_FAR_FROM_SURFACE`)
  double max_distance_before = 0;              ///< `max_distance` of the input (on a crease, a vertex may be up to 1% of the mean quad edge off it)
  double distance_bound = 0;                   ///< `max_distance_to_surface` used: the largest `max_distance` a success allows
  double mean_edge_length = 0;                 ///< mean edge length of the input quad mesh
  double max_displacement = 0;                 ///< largest vertex motion
  std::size_t folded_quads = 0;                ///< quads of the last iterate folded (neither diagonal gives two triangles facing the side of the input quad's normal) that the input did not fold: 0 on success (otherwise `Error_code::FOLDED_QUAD`)
  std::size_t fairness_rows = 0;               ///< second differences in the fairness term
  bool gauss_newton_ran = false;               ///< the local-global iterations failed and the Gauss-Newton method ran
  std::size_t gauss_newton_steps = 0;          ///< its kept steps
  std::size_t gauss_newton_rejected_steps = 0; ///< its rejected steps (the energy did not fall, or a quad folded)
  bool gauss_newton_stalled = false;            ///< it stopped after three kept steps without progress
  double gauss_newton_max_planarity = 0;       ///< largest face planarity of its last kept iterate
  double gauss_newton_max_distance = 0;        ///< largest distance of a vertex of its last kept iterate to the reference
  double gauss_newton_max_distance_to_quads = 0;  ///< `max_distance_to_quads` for its last kept iterate, measured when that iterate met the other checks (0 otherwise)
  // times in seconds
  double time_tree = 0;            ///< the AABB tree of the reference, its creases and the input's border
  double time_factorization = 0;   ///< assembly and factorization of the fixed matrix
  double time_local = 0;           ///< best-fit planes (all iterations)
  double time_closest = 0;         ///< closest points on the reference (all iterations)
  double time_solve = 0;           ///< right-hand sides and solves (all iterations)
  double time_gauss_newton = 0;    ///< the Gauss-Newton method, when it ran
  double time_total = 0;  ///< the whole call
};

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// moves the vertices of the quad mesh `qm` until the planarity of every face is at
/// most `planarity_threshold`, keeping them close to the triangle mesh `reference`
/// and the mesh fair. The result is checked before it is returned: it is a success only
/// if no vertex ended farther than `max_distance_to_surface` from `reference`; if the
/// surface is not farther from the quads than from the input quads by more than that
/// bound (the other side of the distance, the largest over the surface: sampled at the vertices of `reference` and
/// of the input, each quad taken as the four triangles of its two diagonals,
/// `Planarization_result::max_distance_to_quads`), so that quads that shrink away from a
/// border or cut a crease are not a success; and if no quad is folded that the input did
/// not fold (folded: neither diagonal splits it into two triangles that face the side of
/// the input quad's normal, the cross product of its diagonals).
///
/// <b>Borders and creases.</b> The vertices on the border of `qm` and on the creases of
/// `reference` that `qm` follows slide along them only, in both methods below: their pull
/// towards the surface is replaced by one towards the border polyline of the input (across the
/// border, in the surface) or towards the creases (across them), and the corners of the
/// border and of the creases stay where they were. Each may end at most `max_distance_to_surface`
/// from them, as from the surface (`Planarization_result::max_distance`). A crease is an edge of `reference`
/// whose faces' normals make an angle above `crease_angle` (40 degrees by default); `qm` follows it
/// where a vertex lies on it (within 1% of the mean quad edge) with two of its quad edges along it
/// (both ends on creases, the midpoint within a quarter of the edge's length); a vertex with one or
/// more than two such edges, or on the border with one, is a corner, and so is a border vertex of
/// degree other than 3, and a vertex where the border or the crease turns by more than `crease_angle`.
///
/// <b>Energy</b> (after Liu et al. 2006): planarity, closeness to the reference and
/// fairness, `sum_f |C (X_f - P_f)|^2 + wc sum_i |x_i - a_i|^2 + wf sum_j |D_j X - b_j|^2`:
/// - local step: `P_f`, the four vertices of quad f projected onto its best-fit plane;
///   `C` centres them (the energy is invariant to a motion of the plane);
/// - closeness: `a_i = x_i + beta (s_i - x_i)`, `s_i` the closest point of the
///   reference (AABB tree): a proximal term around the current iterate pulled by
///   `beta` towards the surface;
/// - fairness: `D_j` are the second differences of the two polylines through each
///   interior vertex of valence 4 (and of the boundary where it runs straight: border vertices of
///   degree 3), `b_j = (1 - beta) D_j X`.
///
/// The matrix `C^T C + wc I + wf D^T D` does not change and is factored once.
/// `beta` starts at 1 and is multiplied by `closeness_decay` at each iteration
/// (floor 1e-3): at a fixed point the effective closeness and fairness weights
/// are `wc beta` and `wf beta`, so planarity wins more and more.
///
/// Once `beta` is at its floor, the surface no longer pulls a vertex back: if
/// one is then farther than `max_distance_to_surface`, the iterations stop
/// there (`Planarization_result::left_surface`), instead of running on to
/// `number_of_iterations` towards the same failure.
///
/// <b>Second method</b> (after Tang et al. 2014). When the local-global iterations end
/// short of the threshold or too far from the surface, a Gauss-Newton
/// (Levenberg-Marquardt) minimization starts again from the input, over the vertices and a
/// unit normal `n_f` per quad, of
/// `sum_f w_f sum_{edges ab of f} (n_f . (x_b - x_a))^2 + sum_f (|n_f|^2 - 1)^2`
/// `+ sum_i c_i ((m_i . (x_i - s_i))^2 + t |x_i - s_i|^2) + g |D (X - X_0)|^2`
/// `+ k sum_f sum_{corner triangles abc of f} max(0, s A0_abc - A_abc)^2`, in units of the
/// mean quad edge, `s_i` the closest point of the reference and `m_i` the unit normal of the
/// input quad mesh at vertex `i` (the sum of the cross products of the diagonals of its
/// quads), so that vertices may slide along the surface (`t` = `g` = 1e-3); on the border
/// and the creases the closeness term holds the vertex across them (see above). The last term
/// keeps the shape of the quads: `A_abc` is the signed area, against the normal of the input
/// quad, of each of the four triangles (0,1,2), (0,2,3), (1,2,3), (1,3,0) of its corners, and
/// `A0_abc` its input value (`k` = 1, `s` = 1/4); a dart or a bowtie is as planar as a square,
/// and without it the steps turn quads into darts that every later step would fold. A step is
/// kept only if this energy falls and it folds no quad that the input did not fold. After each kept step, `w_f` doubles on every quad
/// above 0.8 times the threshold and `c_i` on every vertex farther than 0.8 times
/// `max_distance_to_surface` (both start at 1 and stay below 1e4), until every quad is
/// within the threshold and every vertex within the bound, or `gauss_newton_steps` steps,
/// or three kept steps in a row without progress: neither the largest planarity nor the
/// largest distance to the reference has fallen below 0.99 of its mark, the value it had
/// at the first kept step or when it last fell so (`Planarization_result::gauss_newton_stalled`).
/// Each step factors a system of the three coordinates of every vertex (the
/// normals are eliminated quad by quad), so a step costs about nine times a
/// local-global factorization; on success its result replaces the local-global one,
/// otherwise the local-global failure is returned and
/// `Planarization_result::gauss_newton_max_planarity` and
/// `Planarization_result::gauss_newton_max_distance` tell how far it got.
///
/// That matrix is real, symmetric and positive definite; it is factored through
/// `Sparse_factorization<SolverTraits, double>` for the solver of the named parameter
/// `sparse_linear_solver` (default: `Default_real_sparse_solver`, CHOLMOD when it
/// is available), and each iteration solves for the three coordinates at once. All computations are done in
/// `double`, whatever the kernels.
/// It is a local-global method like the frame-field algorithms, but not on their
/// driver: its unknowns are real vertex positions (three right-hand sides, one
/// matrix that never changes), not complex field coefficients per face with a
/// weight `lambda` that changes the matrix.
///
/// \tparam PolygonMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph` whose faces are quads
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
///
/// \param qm the quad mesh, whose vertex points are moved on success only
/// \param reference the surface that the vertices are kept close to (typically the mesh `qm` was extracted from)
/// \param result receives the measures, the iteration count and the times (also on failure)
/// \param np an optional sequence of named parameters for `qm`, among the ones listed below
/// \param np_ref an optional sequence of named parameters for `reference` (`vertex_point_map`)
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{planarity_threshold}
///     \cgalParamDescription{the largest planarity (see `quad_planarity()`) to reach on every face; given with
///                           `Polyvector_fields::parameters::planarity_threshold()`}
///     \cgalParamType{`double > 0`}
///     \cgalParamDefault{0.01 (1%)}
///   \cgalParamNEnd
///   \cgalParamNBegin{closeness_weight}
///     \cgalParamDescription{the weight `wc` of the closeness term; given with
///                           `Polyvector_fields::parameters::closeness_weight()`}
///     \cgalParamType{`double > 0`}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{fairness_weight}
///     \cgalParamDescription{the weight `wf` of the fairness term; given with
///                           `Polyvector_fields::parameters::fairness_weight()`}
///     \cgalParamType{`double >= 0`}
///     \cgalParamDefault{0.1}
///   \cgalParamNEnd
///   \cgalParamNBegin{closeness_decay}
///     \cgalParamDescription{the factor applied to `beta` at each iteration; given with
///                           `Polyvector_fields::parameters::closeness_decay()`}
///     \cgalParamType{`double` in `(0, 1]`}
///     \cgalParamDefault{0.9}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_distance_to_surface}
///     \cgalParamDescription{the largest distance, in mesh units, from a vertex of the result to `reference`
///                           (measured to the closest point of its triangles): a planarization that reaches
///                           `planarity_threshold` by moving a vertex farther is not a success, but
///                           `Error_code::TOO_FAR_FROM_SURFACE`; given with
///                           `Polyvector_fields::parameters::max_distance_to_surface()`}
///     \cgalParamType{`double > 0`}
///     \cgalParamDefault{5% of the mean edge length of the input quad mesh (`Planarization_result::mean_edge_length`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{crease_angle}
///     \cgalParamDescription{the creases of `reference` that the vertices on them slide along: its edges whose
///                           faces' normals make an angle above this, in degrees, 180 for none; also the turn of the
///                           border or of a crease above which a vertex stays where it was (see <b>Borders and
///                           creases</b>); given with `Polyvector_fields::parameters::crease_angle()`}
///     \cgalParamType{`double` in `[0, 180]`}
///     \cgalParamDefault{40}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the largest number of local-global iterations}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{500}
///   \cgalParamNEnd
///   \cgalParamNBegin{gauss_newton_steps}
///     \cgalParamDescription{the largest number of kept steps of the second method, which runs when the
///                           local-global iterations fail; 0 runs none; given with
///                           `Polyvector_fields::parameters::gauss_newton_steps()`}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{50}
///   \cgalParamNEnd
///   \cgalParamNBegin{sparse_linear_solver}
///     \cgalParamDescription{the sparse solver of the fixed matrix, through its model of
///                           `SparseFactorization` on `double` (Section \ref pvf_solver_concept)}
///     \cgalParamType{a class `SolverTraits` for which `Sparse_factorization<SolverTraits, double>` is a model of
///                    `SparseFactorization`, such as a model of `SparseLinearAlgebraWithFactorTraits_d` on `double`}
///     \cgalParamDefault{`Default_real_sparse_solver`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `qm`}
///     \cgalParamType{a model of `ReadWritePropertyMap` with `boost::graph_traits<PolygonMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, qm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::SUCCESS` (then `qm` holds the planarized mesh); `EMPTY_MESH` (either mesh);
///          `NON_QUAD_FACE`; `NON_TRIANGLE_FACE` (reference); `NON_FINITE_VALUE` (a parameter or a coordinate);
///          `INVALID_PARAMETER` (a parameter out of its range); `SOLVER_FAILURE`; and when the second method
///          did not succeed either (or did not run), the outcome of the local-global iterations:
///          `DID_NOT_CONVERGE` when `number_of_iterations` iterations did not reach the threshold;
///          `TOO_FAR_FROM_SURFACE` when they reached it with a vertex farther than `max_distance_to_surface`
///          from `reference`, or with the surface farther from the quads than from the input quads by more
///          than that (`Planarization_result::max_distance_to_quads`), or stopped before it with such a vertex and the pull towards the surface at its
///          floor (`Planarization_result::left_surface`; `Planarization_result::max_distance` tells how far);
///          `FOLDED_QUAD` when they reached it within the bound but folded a quad that the input did not fold
///          (`Planarization_result::folded_quads`). On failure `qm` is left as it was;
///          `result` holds the measurements either way.
///
/// \sa `quad_planarity()`, `extract_quad_mesh()`
template <typename PolygonMesh, typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename NamedParametersRef = CGAL::parameters::Default_named_parameters>
Error_code planarize_quad_mesh(PolygonMesh& qm, const TriangleMesh& reference, Planarization_result& result,
                               const NamedParameters& np = CGAL::parameters::default_values(),
                               const NamedParametersRef& np_ref = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::sparse_linear_solver_t, NamedParameters,
                                                             Default_real_sparse_solver>::type Solver;
  result = Planarization_result();

  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, qm));
  const auto rpm = choose_parameter(get_parameter(np_ref, CGAL::internal_np::vertex_point),
                                    CGAL::get_const_property_map(CGAL::vertex_point, reference));
  internal::Planarization_parameters p;
  p.threshold = choose_parameter(get_parameter(np, internal_np::planarity_threshold), p.threshold);
  p.closeness_weight = choose_parameter(get_parameter(np, internal_np::closeness_weight), p.closeness_weight);
  p.fairness_weight = choose_parameter(get_parameter(np, internal_np::fairness_weight), p.fairness_weight);
  p.closeness_decay = choose_parameter(get_parameter(np, internal_np::closeness_decay), p.closeness_decay);
  p.max_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), p.max_iterations);
  p.gauss_newton_steps = choose_parameter(get_parameter(np, internal_np::gauss_newton_steps), p.gauss_newton_steps);
  p.crease_angle = choose_parameter(get_parameter(np, internal_np::crease_angle), p.crease_angle);
  p.distance_given = !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::max_distance_to_surface_t>::value;
  p.max_distance_to_surface = choose_parameter(get_parameter(np, internal_np::max_distance_to_surface), 0.0);
  const Solver solver = choose_parameter(get_parameter(np, CGAL::internal_np::sparse_linear_solver), Solver());
  result.threshold = p.threshold;
  const Error_code code = internal::check_planarization_parameters(p);
  if(code != Error_code::SUCCESS)
    return code;
  if(faces(qm).empty() || faces(reference).empty())
    return Error_code::EMPTY_MESH;
  for(auto f : faces(qm))
    if(degree(f, qm) != 4)
      return Error_code::NON_QUAD_FACE;
  for(auto f : faces(reference))
    if(degree(f, reference) != 3)
      return Error_code::NON_TRIANGLE_FACE;
  return internal::planarize_quad_mesh(qm, reference, vpm, rpm, p, solver, result);
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_PLANARIZE_QUAD_MESH_H
