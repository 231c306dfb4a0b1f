// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The seamless map of a combed frame field (see compute_integer_grid_map()):
// the guidance system (gradient operator and target Jacobians), the rounds of
// mixed-integer solves with stiffening, the snapping of the output to a dyadic
// grid, and the exact seam transitions of the result.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_SEAMLESS_MAP_SOLVE_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_SEAMLESS_MAP_SOLVE_H

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/comb_and_cut.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/feature_alignment.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/gaussian_integers.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/map_check.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/mixed_integer_solve.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/seamless_reduction.h>
#include <CGAL/Polyvector_fields/parameters.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// The named parameters of the map (besides minimum_frame_angle and the solver).
struct Seamless_map_parameters
{
  double stiffening = 1;
  std::size_t max_rounds = 20;
  bool refactor = false;
  bool keep_integers = true;
  bool edge_length_given = false;
  double edge_length = 0;
};

template <typename NamedParameters>
Error_code read_seamless_map_parameters(const NamedParameters& np, Seamless_map_parameters& p)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  p.stiffening = choose_parameter(get_parameter(np, internal_np::stiffening_factor), 1.0);
  p.max_rounds = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), std::size_t(20));
  p.refactor = choose_parameter(get_parameter(np, internal_np::rounding_by_refactorization), false);
  p.keep_integers = choose_parameter(get_parameter(np, internal_np::stiffening_keeps_integers), true);
  if(!std::isfinite(p.stiffening))
    return Error_code::NON_FINITE_VALUE;
  if(!(p.stiffening > 0))
    return Error_code::INVALID_PARAMETER;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::target_edge_length_t>::value)
  {
    p.edge_length_given = true;
    p.edge_length = get_parameter(np, internal_np::target_edge_length);
  }
  return Error_code::SUCCESS;
}

// The target edge length, checked: the given one, or the mean edge length.
inline Error_code check_edge_length(const Seamless_map_parameters& p)
{
  if(!p.edge_length_given)
    return Error_code::SUCCESS;
  if(!std::isfinite(p.edge_length))
    return Error_code::NON_FINITE_VALUE;
  if(!(p.edge_length > 0))
    return Error_code::INVALID_PARAMETER;
  return Error_code::SUCCESS;
}

// The least-squares guidance: rows sqrt(A_f) (grad uv - J*_f), 4 per face, over
// the reduced unknowns (B1 y - d1), with what the measures of a map need.
struct Guidance_system
{
  Eigen::SparseMatrix<double> B1;
  Eigen::VectorXd d1;
  std::vector<double> area;                                 // per face
  std::vector<std::array<double, 4> > target;               // per face: J*_f by rows
  std::vector<std::array<std::complex<double>, 3> > gradient;  // per face: grad of the hat function of each corner
  // the stars checked for winding by flipped_faces(): the corners whose target is
  // vertex v are star_corner[star_begin[v] .. star_begin[v + 1]) (none for a vertex
  // that is not checked). An interior vertex's star must turn star_quarter_turns[v]
  // quarter turns in the map (4 - k for a cone of index k/4, 4 for a regular
  // vertex); a border vertex off the integer grid has star_quarter_turns[v] < 0 and
  // must turn less than a full turn.
  std::vector<std::size_t> star_begin, star_corner;
  std::vector<int> star_quarter_turns;
};

// The stars of the vertices checked for winding (see Guidance_system): the interior
// vertices, and the border vertices that are not integer points (whose values have a
// continuous unknown).
template <typename CornerMesh>
void assemble_stars(const CornerMesh& M, const Comb_data& D, const Seamless_reduction& R, Guidance_system& S)
{
  std::vector<char> checked(M.V, 0);
  for(std::size_t c = 0; c < 3 * M.F; ++c)
  {
    const std::size_t v = M.target[c];
    if(!M.border_vertex[v])
      checked[v] = 1;
    else
      for(const Corner_term& t : R.corner_terms[c])
        checked[v] = checked[v] || t.column < R.continuous_columns;
  }
  S.star_begin.assign(M.V + 1, 0);
  for(std::size_t c = 0; c < 3 * M.F; ++c)
    if(checked[M.target[c]])
      ++S.star_begin[M.target[c] + 1];
  for(std::size_t v = 0; v < M.V; ++v)
    S.star_begin[v + 1] += S.star_begin[v];
  S.star_corner.assign(S.star_begin[M.V], 0);
  std::vector<std::size_t> fill(S.star_begin.begin(), S.star_begin.end() - 1);
  for(std::size_t c = 0; c < 3 * M.F; ++c)
    if(checked[M.target[c]])
      S.star_corner[fill[M.target[c]]++] = c;
  S.star_quarter_turns.assign(M.V, 4);
  for(std::size_t v = 0; v < M.V; ++v)
    S.star_quarter_turns[v] = M.border_vertex[v] ? -1 : 4 - D.index[v];
}

template <typename CornerMesh>
void assemble_guidance(const CornerMesh& M, const Comb_data& D, const Seamless_reduction& R, double h, std::size_t columns,
                       Guidance_system& S)
{
  const std::size_t F = M.F;
  std::vector<Eigen::Triplet<double> > triplets;
  S.d1.resize(Eigen::Index(4 * F));
  S.area.assign(F, 0);
  S.target.resize(F);
  S.gradient.resize(F);
  auto add_corner = [&](std::size_t row_x, std::size_t row_y, std::size_t c, Complex grad, double s) {
    // U_c contributes grad.x to row_x+0 (dU/dx) and grad.y to row_x+1; V_c to row_y, row_y+1
    for(const auto& term : R.corner_terms[c])
    {
      // the column moves U_c by term.u and V_c by term.v
      const Eigen::Index col = Eigen::Index(term.column);
      if(term.u != 0)
      {
        triplets.emplace_back(Eigen::Index(row_x), col, s * term.u * grad.real());
        triplets.emplace_back(Eigen::Index(row_x + 1), col, s * term.u * grad.imag());
      }
      if(term.v != 0)
      {
        triplets.emplace_back(Eigen::Index(row_y), col, s * term.v * grad.real());
        triplets.emplace_back(Eigen::Index(row_y + 1), col, s * term.v * grad.imag());
      }
    }
  };
  for(std::size_t f = 0; f < F; ++f)
  {
    Complex q[3];
    for(int k = 0; k < 3; ++k)
      q[k] = M.local_point(3 * f + std::size_t(k));
    const double A2 = std::imag(std::conj(q[1] - q[0]) * (q[2] - q[0]));  // twice the area
    S.area[f] = A2 / 2;
    const double s = std::sqrt(S.area[f]);
    for(int k = 0; k < 3; ++k)
      S.gradient[f][k] = Complex(0, 1) * (q[(k + 2) % 3] - q[(k + 1) % 3]) / A2;
    const Complex u = D.roots[f][D.offset[f]], v = D.roots[f][(D.offset[f] + 1) % 4];
    const double det = u.real() * v.imag() - u.imag() * v.real();
    // J* = h^-1 [u v]^-1: rows grad U* = (v_y, -v_x)/det/h, grad V* = (-u_y, u_x)/det/h
    S.target[f] = { v.imag() / det / h, -v.real() / det / h, -u.imag() / det / h, u.real() / det / h };
    for(int k = 0; k < 4; ++k)
      S.d1[Eigen::Index(4 * f + std::size_t(k))] = s * S.target[f][std::size_t(k)];
    for(int k = 0; k < 3; ++k)
      add_corner(4 * f, 4 * f + 2, 3 * f + std::size_t(k), S.gradient[f][k], s);
  }
  S.B1.resize(Eigen::Index(4 * F), Eigen::Index(columns));
  S.B1.setFromTriplets(triplets.begin(), triplets.end());
  assemble_stars(M, D, R, S);
}

// uv of every corner for a vector of unknowns
inline void corner_uv(const Seamless_reduction& R, const Eigen::VectorXd& y, std::vector<Complex>& uv)
{
  const std::size_t C = R.corner_terms.size();
  uv.assign(C, Complex(0));
  for(std::size_t c = 0; c < C; ++c)
    for(const auto& term : R.corner_terms[c])
      uv[c] += Complex(term.u, term.v) * y[Eigen::Index(term.column)];
}

inline void map_jacobian(const Guidance_system& S, std::size_t f, const std::vector<Complex>& uv, double J[4])
{
  J[0] = J[1] = J[2] = J[3] = 0;
  for(int k = 0; k < 3; ++k)
  {
    const Complex z = uv[3 * f + std::size_t(k)], g = S.gradient[f][k];
    J[0] += z.real() * g.real();
    J[1] += z.real() * g.imag();
    J[2] += z.imag() * g.real();
    J[3] += z.imag() * g.imag();
  }
}

// sum A_f |grad uv - J*_f|^2, unit weights
inline double guidance_energy(const Guidance_system& S, const std::vector<Complex>& uv)
{
  double E = 0;
  for(std::size_t f = 0; f < S.area.size(); ++f)
  {
    double J[4];
    map_jacobian(S, f, uv, J);
    double e = 0;
    for(int k = 0; k < 4; ++k)
      e += (J[k] - S.target[f][std::size_t(k)]) * (J[k] - S.target[f][std::size_t(k)]);
    E += S.area[f] * e;
  }
  return E;
}

// The smallest uv corner angle, in radians, with which a star is checked for winding.
constexpr double min_star_angle = 1e-6;

// The faces that the map does not lay out injectively: the faces with
// det(grad uv) <= 0, the faces around an interior vertex whose star turns by
// another multiple of pi/2 than its cone angle (Guidance_system::star_quarter_turns),
// for instance twice around a regular vertex: each of its faces is positive,
// but the map covers the plane twice there (a branch point), and the quads of
// such a map have a vertex of 8 edges off the integer grid; and the faces
// around a border vertex off the integer grid whose star turns a full turn or
// more: the border overlaps itself there, and an iso-line along it would leave
// the vertex into two faces.
inline std::size_t flipped_faces(const Guidance_system& S, const std::vector<Complex>& uv, std::vector<char>& flag)
{
  const std::size_t F = S.area.size();
  flag.assign(F, 0);
  std::size_t count = 0;
  for(std::size_t f = 0; f < F; ++f)
  {
    double J[4];
    map_jacobian(S, f, uv, J);
    if(!(J[0] * J[3] - J[1] * J[2] > 0))
    {
      flag[f] = 1;
      ++count;
    }
  }
  // a star with a face of det <= 0 is flagged already, and its angles can be undefined
  const std::vector<char> negative = flag;
  const std::size_t V = S.star_quarter_turns.size();
  for(std::size_t v = 0; v < V; ++v)
  {
    const std::size_t begin = S.star_begin[v], end = S.star_begin[v + 1];
    bool positive = begin != end;
    for(std::size_t i = begin; i < end && positive; ++i)
      positive = !negative[S.star_corner[i] / 3];
    if(!positive)
      continue;
    // the sum of the uv corner angles at v; a star with a corner of (nearly) zero
    // or straight angle, a face collapsed to a segment that round-off left positive,
    // is left to the extraction, which tests such faces exactly
    double turn = 0;
    for(std::size_t i = begin; i < end && positive; ++i)
    {
      const std::size_t c = S.star_corner[i], first = c - c % 3;
      const Complex p = uv[c], a = uv[first + (c % 3 + 1) % 3] - p, b = uv[first + (c % 3 + 2) % 3] - p;
      const double angle = std::arg(b * std::conj(a));
      positive = angle > min_star_angle && angle < CGAL_PI - min_star_angle;
      turn += angle;
    }
    if(!positive)
      continue;
    if(S.star_quarter_turns[v] < 0 ? turn < 2 * CGAL_PI - min_star_angle
                                   : std::abs(turn / (CGAL_PI / 2) - double(S.star_quarter_turns[v])) < 0.5)
      continue;
    for(std::size_t i = begin; i < end; ++i)
    {
      const std::size_t f = S.star_corner[i] / 3;
      count += flag[f] == 0;
      flag[f] = 1;
    }
  }
  return count;
}

// Solves after the first one in which the features near flipped faces are left free.
constexpr std::size_t max_feature_releases = 3;

// Leaves free every feature edge with an endpoint on a face that the map y
// flips (both corners of the edge); returns the number of edges released.
template <typename CornerMesh>
std::size_t release_features_near_flips(const CornerMesh& M, const Seamless_reduction& R, const Guidance_system& S,
                                        const Eigen::VectorXd& y, std::vector<char>& feature)
{
  std::vector<std::complex<double> > uv;
  std::vector<char> flag;
  corner_uv(R, y, uv);
  flipped_faces(S, uv, flag);
  std::vector<char> near(M.V, 0);
  for(std::size_t f = 0; f < M.F; ++f)
    if(flag[f])
      for(std::size_t k = 0; k < 3; ++k)
        near[M.target[3 * f + k]] = 1;
  std::size_t released = 0;
  for(std::size_t c = 0; c < 3 * M.F; ++c)
    if(feature[c] && R.feature_coordinate[c] >= 0 && (near[M.target[c]] || near[M.source(c)]))
    {
      const std::size_t o = M.opposite[c];
      ++released;  // the other side, cleared here, is not counted again
      feature[c] = 0;
      if(o != npos)
        feature[o] = 0;
    }
  return released;
}

// The pairs of corners of one face whose vertices are both integer points
// (singular vertices, feature corners, the pinned vertex: no continuous
// column in their terms), and the faces whose third vertex would fall on the
// iso-line of their aligned feature edge, as forms over the integer unknowns
// (column - nx): the rounding keeps them apart (mixed_integer_solve.h).
template <typename CornerMesh>
std::vector<Distinct_points> integer_point_pairs(const CornerMesh& M, const Seamless_reduction& R)
{
  const std::size_t nx = R.continuous_columns;
  auto integer_only = [&](std::size_t c) {
    if(R.corner_terms[c].empty())
      return false;
    for(const Corner_term& t : R.corner_terms[c])
      if(t.column < nx)
        return false;
    return true;
  };
  std::vector<Distinct_points> pairs;
  std::set<std::pair<std::size_t, std::size_t> > seen;  // vertex pairs, one form each
  for(std::size_t f = 0; f < M.F; ++f)
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t a = 3 * f + k, b = 3 * f + (k + 1) % 3;
      if(!integer_only(a) || !integer_only(b))
        continue;
      if(!seen.insert(std::make_pair((std::min)(M.target[a], M.target[b]), (std::max)(M.target[a], M.target[b]))).second)
        continue;
      Distinct_points form;
      auto add = [&](const Corner_term& t, long long sign) {
        const long long u = sign * std::llround(t.u), v = sign * std::llround(t.v);
        for(auto& x : form.terms)
          if(x.unknown == t.column - nx)
          {
            x.u += u;
            x.v += v;
            return;
          }
        form.terms.push_back({ t.column - nx, u, v });
      };
      for(const Corner_term& t : R.corner_terms[a])
        add(t, 1);
      for(const Corner_term& t : R.corner_terms[b])
        add(t, -1);
      form.terms.erase(std::remove_if(form.terms.begin(), form.terms.end(),
                                      [](const Distinct_points::Term& t) { return t.u == 0 && t.v == 0; }),
                       form.terms.end());
      if(!form.terms.empty())
        pairs.push_back(std::move(form));
    }
  // A face with an aligned feature edge, whose third vertex is integer in the
  // coordinate j that the edge keeps (a singular vertex, a feature corner, a
  // vertex of a feature curve along the same direction): on the edge's
  // iso-line, it would flatten the face. The difference of that coordinate
  // is an integer form (in the u slot, v = 0).
  auto integer_in = [&](std::size_t c, int j) {
    for(const Corner_term& t : R.corner_terms[c])
      if(t.column < nx && (j == 0 ? t.u : t.v) != 0)
        return false;
    return true;
  };
  std::set<std::array<std::size_t, 3> > seen_lines;
  for(std::size_t c = 0; c < 3 * M.F; ++c)
  {
    const int j = R.feature_coordinate.empty() ? -1 : R.feature_coordinate[c];
    if(j < 0)
      continue;
    const std::size_t third = CornerMesh::next(c);
    if(!integer_in(third, j) || !integer_in(c, j))
      continue;
    if(!seen_lines.insert({ M.target[third], M.target[c], std::size_t(j) }).second)
      continue;
    Distinct_points form;
    auto add = [&](const Corner_term& t, long long sign) {
      const long long a = sign * std::llround(j == 0 ? t.u : t.v);
      if(a == 0)
        return;
      for(auto& x : form.terms)
        if(x.unknown == t.column - nx)
        {
          x.u += a;
          return;
        }
      form.terms.push_back({ t.column - nx, a, 0 });
    };
    for(const Corner_term& t : R.corner_terms[third])
      add(t, 1);
    for(const Corner_term& t : R.corner_terms[c])
      add(t, -1);
    form.terms.erase(std::remove_if(form.terms.begin(), form.terms.end(),
                                    [](const Distinct_points::Term& t) { return t.u == 0 && t.v == 0; }),
                     form.terms.end());
    if(!form.terms.empty())
      pairs.push_back(std::move(form));
  }
  return pairs;
}

// The largest weight stiffening gives a face (the others start at 1). Without
// a bound, faces that stay flipped round after round see their weight
// multiplied by at least 2 per round: after 20 rounds on cow.off (5234
// continuous and 290 integer unknowns, h = 0.045) the Schur complement of the
// integer unknowns had eigenvalues from 0.008 to 4e16, and rounding errors made
// it indefinite (the solve failed). At 1e6 the condition number of the system
// grows by 1e6 at most, far within double precision, and a face that is 1e6
// times heavier than the others already leaves them all the distortion.
constexpr double max_stiffening_weight = 1e6;

// Stiffening: the faces around a flip get heavier, by their relative distortion,
// up to max_stiffening_weight.
template <typename CornerMesh>
void stiffen(const CornerMesh& M, const Guidance_system& S, const std::vector<std::vector<std::size_t> >& vertex_faces,
             const std::vector<Complex>& uv, const std::vector<char>& flag, double stiffening, std::vector<double>& weight)
{
  const std::size_t F = M.F;
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
      map_jacobian(S, f, uv, J);
      double e = 0, n2 = 0;
      for(int k = 0; k < 4; ++k)
      {
        e += (J[k] - S.target[f][std::size_t(k)]) * (J[k] - S.target[f][std::size_t(k)]);
        n2 += S.target[f][std::size_t(k)] * S.target[f][std::size_t(k)];
      }
      double distortion = std::sqrt(e / n2);
      if(flag[f])
        distortion = (std::max)(distortion, 1.0);
      weight[f] = (std::min)(weight[f] * (1 + stiffening * distortion), max_stiffening_weight);
    }
}

// Stiffening ends when this many rounds in a row have not lowered the fewest
// flips seen: on the corpus, a round that lowered it after 8 such rounds was
// rare, and each round costs a factorization.
constexpr std::size_t stiffening_patience = 8;

// The solution of the first round, with unit weights: the same in every call
// of run_stiffening_rounds() on one system, so it is computed once.
struct Unit_weight_round
{
  bool made = false;
  Eigen::VectorXd y_continuous, y_rounded;
};

// Rounds of solves: the first one, then stiffening while faces flip. The
// first round rounds the integers. With keep_integers, a stiffening round
// keeps the integers of the last rounding and solves for the continuous
// unknowns only (one factorization and one solve), as long as that removes
// flips; a round that does not have fewer flips than the one before it makes
// the next round round the integers again, with the stiffened weights.
// Without, every round rounds them. The rounds end without flips, after
// p.max_rounds stiffening rounds, or after `patience` rounds without fewer
// flips than the best; best_y is the solution of the round with the
// fewest flips (then the lowest energy) among the rounds of every call.
template <typename CornerMesh, typename Solver, typename Report>
Error_code run_stiffening_rounds(const CornerMesh& M, const Guidance_system& S, std::size_t m,
                             const Seamless_map_parameters& p, bool keep_integers, const Seamless_reduction& R,
                             const std::vector<std::vector<std::size_t> >& vertex_faces,
                             Mixed_integer_system<Solver>& system, Unit_weight_round& unit, Eigen::VectorXd& best_y,
                             std::size_t& best_flips, double& best_energy, std::size_t patience, Report& result)
{
  const std::size_t F = M.F;
  std::vector<double> weight(F, 1.0), row_weight(4 * F, 1.0);
  Eigen::VectorXd y_cont, y_round, integers;
  std::vector<Complex> uv;
  std::vector<char> flag;
  std::size_t fewest = std::numeric_limits<std::size_t>::max(), last_flips = fewest, best_round = 0;
  bool round_integers = true;
  for(std::size_t round = 0; round <= p.max_rounds; ++round)
  {
    const auto round_start = std::chrono::steady_clock::now();
    for(std::size_t f = 0; f < F; ++f)
      for(int k = 0; k < 4; ++k)
        row_weight[4 * f + std::size_t(k)] = std::sqrt(weight[f]);
    Error_code code = Error_code::SUCCESS;
    const bool reused = round == 0 && unit.made;
    if(reused)
    {
      // the first round of an earlier call: the same weights, the same solution
      y_cont = unit.y_continuous;
      y_round = unit.y_rounded;
      integers = y_round.tail(Eigen::Index(m));
    }
    else
      // a round that keeps the integers only raised weights since the last
      // factorization: the factor stays, as conjugate gradient's preconditioner
      code = system.set_weights(row_weight, result, round_integers);
    if(code == Error_code::SUCCESS && !reused)
    {
      if(round_integers)
      {
        code = system.round(p.refactor && round == 0, y_cont, y_round, result);
        integers = y_round.tail(Eigen::Index(m));
        ++result.integer_roundings;
      }
      else
        code = system.solve_for_integers(integers, y_round, result);
    }
    if(code != Error_code::SUCCESS)
      return code;
    if(round == 0 && !reused)
    {
      unit.y_continuous = y_cont;
      unit.y_rounded = y_round;
      unit.made = true;
    }
    if(round == 0 && result.flipped_per_round.empty())
    {
      corner_uv(R, y_cont, uv);
      result.continuous_energy = guidance_energy(S, uv);
    }
    corner_uv(R, y_round, uv);
    const std::size_t flips = flipped_faces(S, uv, flag);
    const double E = guidance_energy(S, uv);
    result.flipped_per_round.push_back(flips);
    if(flips < fewest)
    {
      fewest = flips;
      best_round = round;
    }
    if(flips < best_flips || (flips == best_flips && E < best_energy))
    {
      best_flips = flips;
      best_energy = E;
      best_y = y_round;
    }
    if(!reused && (round > 0 || result.flipped_per_round.size() > 1))
    {
      ++result.stiffening_rounds;
      result.time_stiffening += seconds_since(round_start);
    }
    if(flips == 0 || round == p.max_rounds || round - best_round >= patience)
      break;
    // keeping the integers stalled: round them again (a rounding is always
    // followed by at least one round that keeps them)
    round_integers = !keep_integers || (!round_integers && round > 0 && flips >= last_flips);
    last_flips = flips;
    stiffen(M, S, vertex_faces, uv, flag, p.stiffening, weight);
  }
  return Error_code::SUCCESS;
}

// Before the last solve of a map with features, the wider search runs only
// when the fast rounds left at most this many flipped faces: its purpose
// there is to spare the features beside a few flips. Many flips (truck.obj of
// libigl's tutorial data: about 200 after the fast rounds, 40 rounds, 1300
// integer unknowns) release their features whatever the search, and the
// wider search, a Schur complement per round, was most of the map's time
// (the whole run: 282 s -> 159 s).
constexpr std::size_t wide_search_max_flips_before_release = 16;

// The patience of the wider search when features are released after it (the
// other searches have stiffening_patience). There, its purpose is to end
// below the fast rounds' fewest flips, sparing the features beside them, and
// each of its rounds makes a Schur complement. On the corpus (libigl's
// tutorial data, with and without sharp edges at 40 degrees), no wider search
// before a release that went more than 4 rounds without lowering its fewest
// flips ended below the fast rounds (armadillo.obj's ran 20 rounds to end at
// the fast rounds' 8 flips). The fast rounds did: face.obj's went from 2
// flips to 0 after 7 rounds without fewer, fertility.off's from 1 to 0
// after 5.
constexpr std::size_t wide_search_patience_before_release = 4;

// The rounds of run_stiffening_rounds(): with p.keep_integers, first the fast
// rounds that keep the integers; when faces still flip after them, at most
// wide_search_max_flips of them, the rounds again from unit weights,
// rounding the integers in every round (a wider search: on fandisk the fast
// rounds left a flip that released two sharp edges, the second search none).
// best_y is the best of all rounds. The first round of both, with unit
// weights, is solved once. The fast rounds end after stiffening_patience
// rounds without fewer flips, the wider search after wide_search_patience.
// wide_search_skipped: whether the wider search was left out because of
// wide_search_max_flips.
template <typename CornerMesh, typename Solver, typename Report>
Error_code solve_with_stiffening(const CornerMesh& M, const Guidance_system& S, std::size_t nx, std::size_t m,
                                 const Seamless_map_parameters& p, const Solver& solver_prototype,
                                 const Seamless_reduction& R, std::size_t wide_search_max_flips,
                                 std::size_t wide_search_patience, Eigen::VectorXd& best_y, bool& wide_search_skipped,
                                 Report& result)
{
  const std::vector<Distinct_points> distinct = integer_point_pairs(M, R);
  std::vector<std::vector<std::size_t> > vertex_faces(M.V);
  for(std::size_t c = 0; c < 3 * M.F; ++c)
    vertex_faces[M.target[c]].push_back(CornerMesh::face(c));
  Mixed_integer_system<Solver> system(S.B1, S.d1, nx, m, distinct, solver_prototype);
  Unit_weight_round unit;
  std::size_t best_flips = std::numeric_limits<std::size_t>::max();
  double best_energy = 0;
  Error_code code = run_stiffening_rounds(M, S, m, p, p.keep_integers, R, vertex_faces, system, unit, best_y,
                                          best_flips, best_energy, stiffening_patience, result);
  wide_search_skipped = false;
  if(code == Error_code::SUCCESS && p.keep_integers && best_flips > 0)
  {
    wide_search_skipped = best_flips > wide_search_max_flips;
    if(!wide_search_skipped)
      code = run_stiffening_rounds(M, S, m, p, false, R, vertex_faces, system, unit, best_y, best_flips, best_energy,
                                   wide_search_patience, result);
  }
  return code;
}

// Snaps the unknowns to a dyadic grid (continuous) and to integers (integer
// unknowns), so that seams and singularities are exact in floating point.
inline void snap_unknowns(Eigen::VectorXd& y, std::size_t nx, std::size_t m, const std::vector<Complex>& uv)
{
  double largest = 1;
  for(const Complex& z : uv)
    largest = (std::max)({ largest, std::abs(z.real()), std::abs(z.imag()) });
  // values are multiples of 2^-k with |value| < 2^(50-k): exact sums with integers
  const int e = int(std::ceil(std::log2(4 * largest + 4)));
  const double quantum = std::ldexp(1.0, (std::min)(-1, e - 50));
  for(std::size_t i = 0; i < nx; ++i)
    y[Eigen::Index(i)] = std::round(y[Eigen::Index(i)] / quantum) * quantum;
  for(std::size_t i = nx; i < nx + m; ++i)
    y[Eigen::Index(i)] = std::round(y[Eigen::Index(i)]);
}

// The exact transition of every interior corner c (from face(c) to
// face(opposite(c))): uv_B = i^r uv_A + t, r the combed rotation on the cut
// (0 elsewhere), and t obtained from the reduced unknowns over Z[i]: the value
// at target(c) on side B minus i^r times the one on side A, whose continuous
// unknowns cancel, leaves integer unknowns with Gaussian-integer coefficients.
// Writes Transition{r, {tx, ty}} per corner (the identity on the border);
// returns the number of inconsistencies (a continuous unknown that does not
// cancel, or two endpoints of one edge with different translations).
template <typename CornerMesh, typename Transition>
std::size_t exact_seam_transitions(const CornerMesh& M, const Comb_data& D, const Seamless_reduction& R,
                                   std::size_t nx, const Eigen::VectorXd& y, std::vector<Transition>& out)
{
  const std::size_t C = 3 * M.F;
  std::size_t inconsistencies = 0;
  out.assign(C, Transition());
  std::vector<std::pair<std::size_t, Gint> > form;
  auto translation = [&](std::size_t a, std::size_t b, Gint rot) {
    // uv[b] - rot * uv[a], as a Z[i]-form over the columns, then evaluated
    form.clear();
    auto add = [&](std::size_t column, Gint coefficient) {
      for(auto& x : form)
        if(x.first == column)
        {
          x.second = x.second + coefficient;
          return;
        }
      form.emplace_back(column, coefficient);
    };
    for(const auto& term : R.corner_terms[b])
      add(term.column, Gint(std::llround(term.u), std::llround(term.v)));
    for(const auto& term : R.corner_terms[a])
      add(term.column, -(rot * Gint(std::llround(term.u), std::llround(term.v))));
    Gint t;
    for(const auto& x : form)
    {
      if(x.second.is_zero())
        continue;
      if(x.first < nx)
      {
        ++inconsistencies;
        continue;
      }
      t = t + x.second * Gint(std::llround(y[Eigen::Index(x.first)]), 0);
    }
    return t;
  };
  for(std::size_t c = 0; c < C; ++c)
  {
    const std::size_t o = M.opposite[c];
    if(o == npos)
      continue;
    const int r = D.seam[c] ? D.rotation[c] : 0;
    const Gint rot = i_power(r);
    // target(c) is target(prev(o)); source(c) = target(prev(c)) is target(o)
    const Gint t1 = translation(c, CornerMesh::prev(o), rot), t2 = translation(CornerMesh::prev(c), o, rot);
    if(!(t1 == t2))
      ++inconsistencies;
    out[c] = Transition{ r, { t1.re, t1.im } };
  }
  return inconsistencies;
}

// Snaps the solution y, measures it (flips, energy, residuals), computes the
// exact seam transitions, checks the map (map_check.h) and, if it passes,
// writes the uv of every corner. `result` is an Integer_grid_map_result; on a
// failed check, result.diagnostic says what failed and nothing is written.
template <typename CornerMesh, typename UVMap, typename Report>
Error_code write_snapped_map(const CornerMesh& M, const Comb_data& D, const Seamless_reduction& R,
                             const Guidance_system& S, std::size_t nx, std::size_t m, Eigen::VectorXd& y, UVMap uv_map,
                             Report& result)
{
  std::vector<std::complex<double> > uv;
  std::vector<char> flag;
  corner_uv(R, y, uv);
  result.max_seam_residual_before_snapping = seam_residual(M, D, uv);
  snap_unknowns(y, nx, m, uv);
  corner_uv(R, y, uv);
  result.flipped_faces = flipped_faces(S, uv, flag);
  result.rounded_energy = guidance_energy(S, uv);
  result.energy_ratio = result.continuous_energy > 0 ? result.rounded_energy / result.continuous_energy : 1.0;
  result.max_singularity_residual = singularity_residual(M, D, uv);
  const std::size_t inconsistencies = exact_seam_transitions(M, D, R, nx, y, result.seam_transitions);
  result.inconsistencies += inconsistencies;
  result.max_seam_residual = transition_residual(M, uv, result.seam_transitions);
  if(inconsistencies != 0)
    result.diagnostic = "the seam transitions could not be computed exactly from the integer unknowns";
  else
    result.diagnostic = check_integer_grid_map(M, D, uv, result.seam_transitions);
  if(result.diagnostic.empty())
    result.diagnostic = check_feature_alignment(M, R.feature_coordinate, uv);
  if(!result.diagnostic.empty())
  {
    result.seam_transitions.clear();
    return Error_code::MAP_CHECK_FAILED;
  }
  typedef typename boost::property_traits<UVMap>::value_type UV;
  for(std::size_t c = 0; c < 3 * M.F; ++c)
    put(uv_map, M.halfedge[c], UV{ uv[c].real(), uv[c].imag() });
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_SEAMLESS_MAP_SOLVE_H
