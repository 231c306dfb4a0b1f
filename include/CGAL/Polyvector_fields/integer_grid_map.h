// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTEGER_GRID_MAP_H
#define CGAL_POLYVECTOR_FIELDS_INTEGER_GRID_MAP_H

/// \file integer_grid_map.h
/// The mixed-integer quadrangulation of Bommes, Zimmer and Kobbelt (2009)
/// from a (possibly non-orthogonal) frame field: a seamless map whose integer
/// iso-lines follow the field, with every singular vertex on an integer point.
/// It works on one `Tangent_bundle`: frames, numbering, transport and components
/// are built once (or given) and shared by the combing, the cut and the solve.

#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/comb_frame_field.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/mixed_integer_solve.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/seamless_reduction.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#if defined(CGAL_PVF_HAS_CHOLMOD)
#  include <Eigen/CholmodSupport>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

#if defined(DOXYGEN_RUNNING)
/// \ingroup PkgPolyvectorFieldsParametrization
///
/// is the sparse solver of `compute_integer_grid_map()` when none is given, a model
/// of `SparseLinearAlgebraWithFactorTraits_d` on `double` (the system is real,
/// symmetric and positive definite): CHOLMOD through Eigen's
/// `CholmodDecomposition` when the macro `CGAL_PVF_HAS_CHOLMOD` is defined (as
/// for `Direct_sparse_solver`), Eigen's `SimplicialLDLT` otherwise.
typedef unspecified_type Default_real_sparse_solver;
#elif defined(CGAL_PVF_HAS_CHOLMOD)
typedef CGAL::Eigen_solver_traits<Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> >
  Default_real_sparse_solver;
#else
typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > > Default_real_sparse_solver;
#endif

/// \ingroup PkgPolyvectorFieldsParametrization
///
/// reports on a run of `compute_integer_grid_map()`.
struct Integer_grid_map_result
{
  Comb_result comb;                       ///< the combing and the cut (clamped faces, singularities, seams)
  std::size_t faces = 0;                  ///< faces of the mesh
  std::size_t singular_vertices = 0;      ///< singular vertices (all placed on integer points)
  std::size_t seam_curves = 0;            ///< seam curves, one integer translation each before reduction
  std::size_t cut_edges = 0;              ///< interior cut edges
  std::size_t clamped_faces = 0;          ///< faces whose frame was clamped
  std::size_t continuous_unknowns = 0;    ///< scalar continuous unknowns (2 per regular vertex, minus pins)
  std::size_t integer_unknowns = 0;       ///< scalar integer unknowns after the exact reduction (and pins)
  std::size_t integer_unknowns_before_reduction = 0;  ///< 2 (singular vertices + seam curves)
  std::size_t extra_integer_relations = 0;///< relations left at the root of a seam tree (expected 0)
  std::size_t flipped_faces = 0;          ///< faces with det(grad uv) <= 0 in the output
  std::vector<std::size_t> flipped_per_round;  ///< flipped faces after each stiffening round
  std::size_t stiffening_rounds = 0;      ///< solves after the first one
  std::size_t factorizations = 0;         ///< numeric factorizations of the sparse system
  double target_edge_length = 0;          ///< h used
  double mean_edge_length = 0;            ///< of the mesh
  double continuous_energy = 0;           ///< sum A_f |grad uv - J*_f|^2 of the continuous (unrounded) optimum, unit weights
  double rounded_energy = 0;              ///< the same energy for the output
  double energy_ratio = 0;                ///< rounded / continuous
  double max_seam_residual = 0;           ///< worst |uv_B - (R^r uv_A + t)| over cut-edge endpoints, t the nearest integer vector (output)
  double max_seam_residual_before_snapping = 0;  ///< the same before the values are snapped to a dyadic grid
  double max_singularity_residual = 0;    ///< worst distance of a singular corner to the integer grid (output)
  std::size_t inconsistencies = 0;        ///< internal checks that failed (expected 0)
  // times in seconds
  double time_comb = 0;           ///< the tangent bundle (when a mesh is given), matching, singularities, combing, cut, seam curves
  double time_reduction = 0;      ///< sectors, seam relations, exact elimination over Z[i]
  double time_assembly = 0;       ///< gradient operator and normal equations (all rounds)
  double time_factorization = 0;  ///< sparse factorizations (all rounds)
  double time_schur = 0;          ///< solves for the Schur complement of the integer unknowns (all rounds)
  double time_rounding = 0;       ///< greedy rounding with updates (all rounds)
  double time_stiffening = 0;     ///< everything spent in rounds after the first
  double time_output = 0;         ///< snapping, checks and writing the map
  double time_total = 0;  ///< the whole call
};


/// \ingroup PkgPolyvectorFieldsParametrization
///
/// computes a seamless integer-grid map of a triangle mesh guided by the frame
/// field of `coefficient_map` (Bommes, Zimmer, Kobbelt 2009: mixed-integer
/// quadrangulation).
///
/// <b>Combing and cut.</b> The field is cleaned, combed and cut as by
/// `comb_frame_field()` (same named parameter `minimum_frame_angle`), on the
/// same tangent bundle.
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
/// The boundary is free.
///
/// <b>Solve.</b> The continuous block is factored once per round (sparse SPD,
/// `sparse_linear_solver`); the integer unknowns are eliminated through their
/// Schur complement (dense, small), rounded greedily (closest to an integer
/// first) with an exact O(m^2) update of the minimiser and of the inverse per
/// rounding. Then faces with `det(grad uv) <= 0` and the faces around them get
/// a larger weight and the problem is solved again, at most
/// `number_of_iterations` times (stiffening); the round with the fewest flips is kept.
///
/// <b>Output.</b> `uv_map[h]` is the value at `target(h)` inside `face(h)`. The
/// values are snapped to a dyadic grid (2^-k, about 1e-12 of a quad), so that
/// across every seam `uv_B = R^r uv_A + t` holds exactly in floating point and
/// singular vertices are exactly integer.
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
///          which no test mesh has shown). `uv_map` is written only on success; the mesh is never changed.
///
/// \sa `comb_frame_field()`, `IO::write_integer_grid_map_OBJ()`
template <typename Mesh_or_bundle, typename CoefficientMap, typename UVMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code compute_integer_grid_map(const Mesh_or_bundle& mesh_or_bundle, CoefficientMap coefficient_map,
                                    UVMap uv_map, Integer_grid_map_result& result,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef std::complex<double> Complex;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::sparse_linear_solver_t, NamedParameters,
                                                             Default_real_sparse_solver>::type Solver;
  const auto start = std::chrono::steady_clock::now();
  result = Integer_grid_map_result();

  double min_angle = 0;
  Error_code code = internal::read_minimum_frame_angle(np, min_angle);
  if(code != Error_code::SUCCESS)
    return code;
  const double stiffening = choose_parameter(get_parameter(np, internal_np::stiffening_factor), 1.0);
  const std::size_t max_rounds = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), std::size_t(20));
  const bool refactor = choose_parameter(get_parameter(np, internal_np::rounding_by_refactorization), false);
  const Solver solver_prototype = choose_parameter(get_parameter(np, CGAL::internal_np::sparse_linear_solver), Solver());
  if(!std::isfinite(stiffening))
    return Error_code::NON_FINITE_VALUE;
  if(!(stiffening > 0))
    return Error_code::INVALID_PARAMETER;

  // ---- Stage 1: the bundle (built here from a mesh), matching, combing, cut graph.
  auto t = std::chrono::steady_clock::now();
  const auto& bundle = internal::bundle_of(mesh_or_bundle, np);
  if(bundle.status() != Error_code::SUCCESS)
    return bundle.status();
  typedef std::decay_t<decltype(bundle)> Bundle;
  typedef internal::Corner_mesh<Bundle> Mesh;
  const Mesh M(bundle);
  const std::size_t F = M.F, C = 3 * F;
  double edge_sum = 0;
  std::size_t edge_count = 0;
  for(std::size_t c = 0; c < C; ++c)
    if(M.opposite[c] == internal::igm_npos || c < M.opposite[c])
    {
      const auto dvec = internal::difference(M.point[M.target[c]], M.point[M.source(c)]);
      edge_sum += std::sqrt(internal::dot(dvec, dvec));
      ++edge_count;
    }
  result.mean_edge_length = edge_sum / double(edge_count);
  double h = result.mean_edge_length;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::target_edge_length_t>::value)
    h = get_parameter(np, internal_np::target_edge_length);
  if(!std::isfinite(h))
    return Error_code::NON_FINITE_VALUE;
  if(!(h > 0))
    return Error_code::INVALID_PARAMETER;
  result.target_edge_length = h;

  internal::Comb_data D;
  code = internal::comb_and_cut(M, coefficient_map, min_angle, D);
  result.comb = D.report;
  if(code != Error_code::SUCCESS)
    return code;
  result.faces = F;
  result.singular_vertices = D.report.singular_vertices;
  result.seam_curves = D.report.seam_curves;
  result.cut_edges = D.report.cut_edges;
  result.clamped_faces = D.report.clamped_faces;
  result.inconsistencies += D.pruned_nonzero_rotation;
  result.time_comb = internal::seconds_since(t);

  // ---- Stage 2: reduced variables.
  t = std::chrono::steady_clock::now();
  internal::Seamless_reduction R;
  code = internal::reduce_seamless_variables(M, D, R);
  result.inconsistencies += R.inconsistencies;
  result.extra_integer_relations = R.extra_relations;
  if(code != Error_code::SUCCESS)
    return code;
  const std::size_t nx = 2 * R.continuous_vertices, m = 2 * R.integer_variables;
  result.continuous_unknowns = nx;
  result.integer_unknowns = m;
  result.integer_unknowns_before_reduction = 2 * (result.singular_vertices + result.seam_curves);
  result.time_reduction = internal::seconds_since(t);

  // ---- Stage 3: gradient operator B1 (4 rows per face, scaled by sqrt(A_f)) and target d1.
  t = std::chrono::steady_clock::now();
  std::vector<Eigen::Triplet<double> > triplets;
  Eigen::VectorXd d1(Eigen::Index(4 * F));
  std::vector<double> area(F);
  std::vector<std::array<double, 4> > target(F);
  std::vector<std::array<Complex, 3> > gradient(F);
  auto add_corner = [&](std::size_t row_x, std::size_t row_y, std::size_t c, Complex grad, double s) {
    // U_c contributes grad.x to row_x+0 (dU/dx) and grad.y to row_x+1; V_c to row_y, row_y+1
    for(const auto& term : R.corner_terms[c])
    {
      // U = Re(coef * z), V = Im(coef * z), z = (column, column + 1)
      const double p = term.re, q = term.im;
      const Eigen::Index col = Eigen::Index(term.column);
      triplets.emplace_back(Eigen::Index(row_x), col, s * p * grad.real());
      triplets.emplace_back(Eigen::Index(row_x + 1), col, s * p * grad.imag());
      triplets.emplace_back(Eigen::Index(row_x), col + 1, -s * q * grad.real());
      triplets.emplace_back(Eigen::Index(row_x + 1), col + 1, -s * q * grad.imag());
      triplets.emplace_back(Eigen::Index(row_y), col, s * q * grad.real());
      triplets.emplace_back(Eigen::Index(row_y + 1), col, s * q * grad.imag());
      triplets.emplace_back(Eigen::Index(row_y), col + 1, s * p * grad.real());
      triplets.emplace_back(Eigen::Index(row_y + 1), col + 1, s * p * grad.imag());
    }
  };
  for(std::size_t f = 0; f < F; ++f)
  {
    Complex q[3];
    for(int k = 0; k < 3; ++k)
      q[k] = M.local_point(3 * f + std::size_t(k));
    const double A2 = std::imag(std::conj(q[1] - q[0]) * (q[2] - q[0]));  // twice the area
    area[f] = A2 / 2;
    const double s = std::sqrt(area[f]);
    for(int k = 0; k < 3; ++k)
      gradient[f][k] = Complex(0, 1) * (q[(k + 2) % 3] - q[(k + 1) % 3]) / A2;
    const Complex u = D.roots[f][D.offset[f]], v = D.roots[f][(D.offset[f] + 1) % 4];
    const double det = u.real() * v.imag() - u.imag() * v.real();
    // J* = h^-1 [u v]^-1: rows grad U* = (v_y, -v_x)/det/h, grad V* = (-u_y, u_x)/det/h
    target[f] = { v.imag() / det / h, -v.real() / det / h, -u.imag() / det / h, u.real() / det / h };
    for(int k = 0; k < 4; ++k)
      d1[Eigen::Index(4 * f + std::size_t(k))] = s * target[f][std::size_t(k)];
    for(int k = 0; k < 3; ++k)
      add_corner(4 * f, 4 * f + 2, 3 * f + std::size_t(k), gradient[f][k], s);
  }
  Eigen::SparseMatrix<double> B1(Eigen::Index(4 * F), Eigen::Index(nx + m));
  B1.setFromTriplets(triplets.begin(), triplets.end());
  triplets.clear();
  triplets.shrink_to_fit();
  result.time_assembly += internal::seconds_since(t);

  // uv of every corner for a vector of unknowns
  auto corner_uv = [&](const Eigen::VectorXd& y, std::vector<Complex>& uv) {
    uv.assign(C, Complex(0));
    for(std::size_t c = 0; c < C; ++c)
      for(const auto& term : R.corner_terms[c])
      {
        const Complex z(y[Eigen::Index(term.column)], y[Eigen::Index(term.column + 1)]);
        uv[c] += Complex(term.re, term.im) * z;
      }
  };
  auto jacobian = [&](std::size_t f, const std::vector<Complex>& uv, double J[4]) {
    J[0] = J[1] = J[2] = J[3] = 0;
    for(int k = 0; k < 3; ++k)
    {
      const Complex z = uv[3 * f + std::size_t(k)], g = gradient[f][k];
      J[0] += z.real() * g.real();
      J[1] += z.real() * g.imag();
      J[2] += z.imag() * g.real();
      J[3] += z.imag() * g.imag();
    }
  };
  auto energy = [&](const std::vector<Complex>& uv) {
    double E = 0;
    for(std::size_t f = 0; f < F; ++f)
    {
      double J[4];
      jacobian(f, uv, J);
      double e = 0;
      for(int k = 0; k < 4; ++k)
        e += (J[k] - target[f][std::size_t(k)]) * (J[k] - target[f][std::size_t(k)]);
      E += area[f] * e;
    }
    return E;
  };
  auto flipped = [&](const std::vector<Complex>& uv, std::vector<char>& flag) {
    flag.assign(F, 0);
    std::size_t count = 0;
    for(std::size_t f = 0; f < F; ++f)
    {
      double J[4];
      jacobian(f, uv, J);
      if(!(J[0] * J[3] - J[1] * J[2] > 0))
      {
        flag[f] = 1;
        ++count;
      }
    }
    return count;
  };

  // ---- Stage 4: solve, round, stiffen.
  std::vector<double> weight(F, 1.0), row_weight(4 * F, 1.0);
  Eigen::VectorXd y_cont, y_round, best_y;
  std::vector<Complex> uv;
  std::vector<char> flag;
  std::size_t best_flips = std::numeric_limits<std::size_t>::max();
  double best_energy = 0;
  std::vector<std::vector<std::size_t> > vertex_faces(M.V);
  for(std::size_t c = 0; c < C; ++c)
    vertex_faces[M.target[c]].push_back(Mesh::face(c));
  for(std::size_t round = 0; round <= max_rounds; ++round)
  {
    const auto round_start = std::chrono::steady_clock::now();
    for(std::size_t f = 0; f < F; ++f)
      for(int k = 0; k < 4; ++k)
        row_weight[4 * f + std::size_t(k)] = std::sqrt(weight[f]);
    code = internal::solve_mixed_integer(B1, d1, row_weight, nx, m, solver_prototype, refactor && round == 0, y_cont,
                                         y_round, result);
    if(code != Error_code::SUCCESS)
      return code;
    if(round == 0)
    {
      corner_uv(y_cont, uv);
      result.continuous_energy = energy(uv);
    }
    corner_uv(y_round, uv);
    const std::size_t flips = flipped(uv, flag);
    const double E = energy(uv);
    result.flipped_per_round.push_back(flips);
    if(flips < best_flips || (flips == best_flips && E < best_energy))
    {
      best_flips = flips;
      best_energy = E;
      best_y = y_round;
    }
    if(round > 0)
    {
      ++result.stiffening_rounds;
      result.time_stiffening += internal::seconds_since(round_start);
    }
    if(flips == 0 || round == max_rounds)
      break;
    // Stiffening: faces around a flip get heavier, by their relative distortion.
    std::vector<char> near(F, 0);
    for(std::size_t f = 0; f < F; ++f)
      if(flag[f])
        for(int k = 0; k < 3; ++k)
          for(std::size_t g : vertex_faces[M.target[3 * f + std::size_t(k)]])
            near[g] = 1;
    for(std::size_t f = 0; f < F; ++f)
      if(near[f])
      {
        double J[4];
        jacobian(f, uv, J);
        double e = 0, n2 = 0;
        for(int k = 0; k < 4; ++k)
        {
          e += (J[k] - target[f][std::size_t(k)]) * (J[k] - target[f][std::size_t(k)]);
          n2 += target[f][std::size_t(k)] * target[f][std::size_t(k)];
        }
        double distortion = std::sqrt(e / n2);
        if(flag[f])
          distortion = (std::max)(distortion, 1.0);
        weight[f] *= 1 + stiffening * distortion;
      }
  }

  // ---- Output: snap to a dyadic grid, so that seams and singularities are exact.
  t = std::chrono::steady_clock::now();
  corner_uv(best_y, uv);
  result.max_seam_residual_before_snapping = internal::seam_residual(M, D, uv);
  double largest = 1;
  for(const Complex& z : uv)
    largest = (std::max)({ largest, std::abs(z.real()), std::abs(z.imag()) });
  // values are multiples of 2^-k with |value| < 2^(50-k): exact sums with integers
  const int e = int(std::ceil(std::log2(4 * largest + 4)));
  const double quantum = std::ldexp(1.0, (std::min)(-1, e - 50));
  Eigen::VectorXd y = best_y;
  for(std::size_t i = 0; i < nx; ++i)
    y[Eigen::Index(i)] = std::round(y[Eigen::Index(i)] / quantum) * quantum;
  for(std::size_t i = nx; i < nx + m; ++i)
    y[Eigen::Index(i)] = std::round(y[Eigen::Index(i)]);
  corner_uv(y, uv);
  result.flipped_faces = flipped(uv, flag);
  result.rounded_energy = energy(uv);
  result.energy_ratio = result.continuous_energy > 0 ? result.rounded_energy / result.continuous_energy : 1.0;
  result.max_seam_residual = internal::seam_residual(M, D, uv);
  for(std::size_t c = 0; c < C; ++c)
    if(D.index[M.target[c]] != 0)
    {
      const Complex z = uv[c];
      result.max_singularity_residual = (std::max)({ result.max_singularity_residual, std::abs(z.real() - std::round(z.real())),
                                                     std::abs(z.imag() - std::round(z.imag())) });
    }
  typedef typename boost::property_traits<UVMap>::value_type UV;
  for(std::size_t c = 0; c < C; ++c)
    put(uv_map, M.halfedge[c], UV{ uv[c].real(), uv[c].imag() });
  result.time_output = internal::seconds_since(t);
  result.time_total = internal::seconds_since(start);
  return Error_code::SUCCESS;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTEGER_GRID_MAP_H
