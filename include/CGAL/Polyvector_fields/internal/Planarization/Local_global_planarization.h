// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_PLANARIZATION_LOCAL_GLOBAL_PLANARIZATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_PLANARIZATION_LOCAL_GLOBAL_PLANARIZATION_H

// The local-global planarization of a quad mesh behind planarize_quad_mesh()
// (after Liu, Pottmann, Wallner, Yang and Wang 2006). Its energy is
//   sum_f |C (X_f - P_f)|^2 + wc sum_i |x_i - a_i|^2 + wf sum_j |D_j X - b_j|^2:
// - the local step: P_f, the four vertices of quad f projected onto their
//   best-fit plane; C centres them;
// - closeness: a_i = x_i + beta (s_i - x_i), s_i the closest point of the
//   reference surface (an AABB tree), or on the border or a crease for the
//   vertices on them (Feature_closeness, Surface_closeness.h);
// - fairness: D_j, the second differences of the polylines through the
//   interior vertices of valence 4 and along the straight runs of the border,
//   with b_j = (1 - beta) D_j X.
// The matrix C^T C + wc I + wf D^T D does not change: it is factored once by
// the solver's Sparse_factorization (real symmetric positive definite), and
// every iteration solves for the three coordinates at once. Once beta is at
// its floor, a vertex farther than the distance bound ends the iterations
// (TOO_FAR_FROM_SURFACE): nothing pulls it back any more. A result is also
// checked on the other side of the distance (Surface_coverage).

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Sparse_factorization.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/internal/Planarization/Gauss_newton_planarization.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>

#include <CGAL/Polyvector_fields/internal/Planarization/Surface_closeness.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

struct Planarization_parameters
{
  double threshold = 0.01;         // planarity to reach on every face
  double closeness_weight = 1;     // wc
  double fairness_weight = 0.1;    // wf
  double closeness_decay = 0.9;    // the factor of beta at each iteration
  std::size_t max_iterations = 500;
  // the largest number of kept steps of the Gauss-Newton method that runs
  // when the local-global iterations fail (Gauss_newton_planarization.h);
  // 0: none
  std::size_t gauss_newton_steps = 50;
  // The local step and the closest points shared among the cores (TBB):
  // the same numbers as one core, bit for bit (each quad and each vertex is
  // computed alone, and the sums are made in order afterwards).
  bool parallel = true;
  // The largest distance of a vertex of the result to the reference, when
  // given; otherwise default_distance_fraction of the mean edge length of the
  // input quad mesh.
  bool distance_given = false;
  double max_distance_to_surface = 0;
  // The creases of the reference that the vertices on them follow
  // (Feature_closeness): edges whose faces' normals make an angle above this,
  // in degrees (the CLI's default crease angle); 180: none. Also the turn of
  // the border or of a crease above which a vertex is a corner.
  double crease_angle = 40;
};

// The default of max_distance_to_surface, as a fraction of the mean quad edge length.
constexpr double default_distance_fraction = 0.05;
// The floor of beta: the pull towards the surface never falls below this
// fraction of its first strength.
constexpr double closeness_floor = 1e-3;

inline Error_code check_planarization_parameters(const Planarization_parameters& p)
{
  if(!std::isfinite(p.threshold) || !std::isfinite(p.closeness_weight) || !std::isfinite(p.fairness_weight) ||
     !std::isfinite(p.closeness_decay) || !std::isfinite(p.max_distance_to_surface) || !std::isfinite(p.crease_angle))
    return Error_code::NON_FINITE_VALUE;
  if(!(p.threshold > 0) || !(p.closeness_weight > 0) || p.fairness_weight < 0 || !(p.closeness_decay > 0) ||
     p.closeness_decay > 1 || (p.distance_given && !(p.max_distance_to_surface > 0)) || p.crease_angle < 0 ||
     p.crease_angle > 180)
    return Error_code::INVALID_PARAMETER;
  return Error_code::SUCCESS;
}

// The vertices of a quad mesh numbered 0..n-1, their positions (one row
// each), and the four vertices of each quad.
template <typename PolygonMesh>
struct Quad_mesh_arrays
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  Numbering<vertex_descriptor> index;
  std::vector<vertex_descriptor> descriptors;
  Eigen::MatrixXd X;
  std::vector<std::array<std::size_t, 4> > quads;

  // false if a coordinate is not finite
  template <typename VertexPointMap>
  bool build(const PolygonMesh& qm, VertexPointMap vpm)
  {
    for(vertex_descriptor v : vertices(qm))
    {
      index.add(v);
      descriptors.push_back(v);
    }
    const std::size_t n = descriptors.size();
    X.resize(Eigen::Index(n), 3);
    for(std::size_t i = 0; i < n; ++i)
    {
      const auto& p = get(vpm, descriptors[i]);
      X(Eigen::Index(i), 0) = CGAL::to_double(p.x());
      X(Eigen::Index(i), 1) = CGAL::to_double(p.y());
      X(Eigen::Index(i), 2) = CGAL::to_double(p.z());
    }
    if(!X.allFinite())
      return false;
    for(auto f : faces(qm))
    {
      std::array<std::size_t, 4> q;
      std::size_t i = 0;
      for(auto h : halfedges_around_face(halfedge(f, qm), qm))
        q[i++] = index(target(h, qm));
      quads.push_back(q);
    }
    return true;
  }

  double mean_edge_length(const PolygonMesh& qm) const
  {
    double edge_sum = 0;
    std::size_t edge_count = 0;
    for(auto e : edges(qm))
    {
      const auto h = halfedge(e, qm);
      edge_sum += (X.row(Eigen::Index(index(source(h, qm)))) - X.row(Eigen::Index(index(target(h, qm))))).norm();
      ++edge_count;
    }
    return edge_sum / double(edge_count);
  }

  // The largest and the mean planarity of the quads at positions Y.
  void planarity(const Eigen::MatrixXd& Y, double& mx, double& mean) const
  {
    std::vector<double> each;
    planarity_of_quads(Y, quads, each, mx, mean);
  }

  // The border of the quad mesh: the kind of each vertex (Feature_closeness:
  // a border vertex of degree 3 between two border edges is BORDER, any other
  // a CORNER), the border edges, and all edges.
  std::vector<char> border(const PolygonMesh& qm, std::vector<std::array<std::size_t, 2> >& border_edges,
                           std::vector<std::array<std::size_t, 2> >& all_edges) const
  {
    std::vector<char> kind(descriptors.size(), Feature_closeness::INTERIOR);
    for(std::size_t i = 0; i < descriptors.size(); ++i)
    {
      const vertex_descriptor v = descriptors[i];
      if(!CGAL::is_border(v, qm))
        continue;
      std::size_t degree = 0, border_degree = 0;
      for(auto h : halfedges_around_target(halfedge(v, qm), qm))
      {
        ++degree;
        if(CGAL::is_border_edge(h, qm))
          ++border_degree;
      }
      kind[i] = degree == 3 && border_degree == 2 ? Feature_closeness::BORDER : Feature_closeness::CORNER;
    }
    border_edges.clear();
    all_edges.clear();
    for(auto e : edges(qm))
    {
      const std::array<std::size_t, 2> ends = { index(source(halfedge(e, qm), qm)), index(target(halfedge(e, qm), qm)) };
      all_edges.push_back(ends);
      if(CGAL::is_border(e, qm))
        border_edges.push_back(ends);
    }
    return kind;
  }

  // The second differences x_a - 2 x_i + x_b of the fairness term: the two
  // polylines through an interior vertex of valence 4, and the border through
  // a border vertex of degree 3 (a straight run, not a staircase corner).
  std::vector<std::array<std::size_t, 3> > fairness_rows(const PolygonMesh& qm) const
  {
    std::vector<std::array<std::size_t, 3> > rows;
    for(std::size_t i = 0; i < descriptors.size(); ++i)
    {
      const vertex_descriptor v = descriptors[i];
      std::vector<std::size_t> nb, border_nb;
      for(auto h : halfedges_around_target(halfedge(v, qm), qm))
      {
        nb.push_back(index(source(h, qm)));
        if(CGAL::is_border_edge(h, qm))
          border_nb.push_back(index(source(h, qm)));
      }
      if(!CGAL::is_border(v, qm))
      {
        if(nb.size() == 4)
        {
          rows.push_back({ nb[0], i, nb[2] });
          rows.push_back({ nb[1], i, nb[3] });
        }
      }
      else if(border_nb.size() == 2 && nb.size() == 3)
        rows.push_back({ border_nb[0], i, border_nb[1] });
    }
    return rows;
  }
};

// The fixed matrix C^T C + wc I + wf D^T D; DtD receives D^T D.
inline Eigen::SparseMatrix<double> planarization_matrix(std::size_t n, const std::vector<std::array<std::size_t, 4> >& quads,
                                                        const std::vector<std::array<std::size_t, 3> >& rows, double wc,
                                                        double wf, Eigen::SparseMatrix<double>& DtD)
{
  std::vector<Eigen::Triplet<double> > T;
  for(const auto& q : quads)
    for(int a = 0; a < 4; ++a)
      for(int b = 0; b < 4; ++b)
        T.emplace_back(Eigen::Index(q[a]), Eigen::Index(q[b]), (a == b ? 1.0 : 0.0) - 0.25);
  for(std::size_t i = 0; i < n; ++i)
    T.emplace_back(Eigen::Index(i), Eigen::Index(i), wc);
  Eigen::SparseMatrix<double> Dm(Eigen::Index(rows.size()), Eigen::Index(n));
  std::vector<Eigen::Triplet<double> > DT;
  for(std::size_t r = 0; r < rows.size(); ++r)
  {
    DT.emplace_back(Eigen::Index(r), Eigen::Index(rows[r][0]), 1.0);
    DT.emplace_back(Eigen::Index(r), Eigen::Index(rows[r][1]), -2.0);
    DT.emplace_back(Eigen::Index(r), Eigen::Index(rows[r][2]), 1.0);
  }
  Dm.setFromTriplets(DT.begin(), DT.end());
  DtD = (Dm.transpose() * Dm).pruned();
  Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  A.setFromTriplets(T.begin(), T.end());
  if(wf > 0)
    A += wf * DtD;
  return A;
}

// The local step: for each quad, its vertices projected onto its best-fit
// plane and centred (C P_f), summed into the rows of its vertices. The quads
// are projected independently (shared among the cores with `parallel`) into
// `projected`, then summed in quad order: the same sums either way.
inline Eigen::MatrixXd projected_quads(const Eigen::MatrixXd& X, const std::vector<std::array<std::size_t, 4> >& quads,
                                       bool parallel, std::vector<Eigen::Matrix<double, 4, 3> >& projected)
{
  projected.resize(quads.size());
  for_each_range(parallel, quads.size(), 1024, [&](std::size_t begin, std::size_t end) {
    for(std::size_t f = begin; f < end; ++f)
    {
      Eigen::Matrix<double, 4, 3> P;
      for(int k = 0; k < 4; ++k)
        P.row(k) = X.row(Eigen::Index(quads[f][k]));
      const Eigen::RowVector3d c = P.colwise().mean();
      const Eigen::Matrix<double, 4, 3> Q = P.rowwise() - c;
      const Eigen::Matrix3d cov = Q.transpose() * Q;
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
      const Eigen::Vector3d nrm = es.eigenvectors().col(0);
      for(int k = 0; k < 4; ++k)
        projected[f].row(k) = Q.row(k) - (Q.row(k).dot(nrm.transpose())) * nrm.transpose();
    }
  });
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(X.rows(), 3);
  for(std::size_t f = 0; f < quads.size(); ++f)
    for(int k = 0; k < 4; ++k)
      rhs.row(Eigen::Index(quads[f][k])) += projected[f].row(k);
  return rhs;
}

// The whole algorithm on checked input (quads, triangles, valid parameters).
// `result` is filled as far as it was computed; the vertex points of `qm` are
// written only on SUCCESS.
template <typename SolverTraits, typename PolygonMesh, typename TriangleMesh, typename VertexPointMap,
          typename ReferencePointMap, typename Result>
Error_code planarize_quad_mesh(PolygonMesh& qm, const TriangleMesh& reference, VertexPointMap vpm,
                               ReferencePointMap rpm, const Planarization_parameters& p, const SolverTraits& solver,
                               Result& result)
{
  const Timer start;
  Quad_mesh_arrays<PolygonMesh> mesh;
  if(!mesh.build(qm, vpm))
    return Error_code::NON_FINITE_VALUE;
  const std::size_t n = mesh.descriptors.size();
  Eigen::MatrixXd& X = mesh.X;
  result.mean_edge_length = mesh.mean_edge_length(qm);
  result.distance_bound = p.distance_given ? p.max_distance_to_surface
                                                        : default_distance_fraction * result.mean_edge_length;

  Timer t;
  Closest_points<TriangleMesh, ReferencePointMap> closest(reference, rpm);
  std::vector<std::array<std::size_t, 2> > border_edges, all_edges;
  std::vector<char> border_kind = mesh.border(qm, border_edges, all_edges);
  const Feature_closeness features(X, mesh.quads, std::move(border_kind), border_edges, all_edges,
                                   p.crease_angle < 180 ? reference_creases(reference, rpm, p.crease_angle)
                                                        : std::vector<CGAL::Simple_cartesian<double>::Segment_3>(),
                                   result.mean_edge_length, p.crease_angle);
  result.time_tree = t.elapsed();
  // S: the closest points on the reference (also the hints of the next
  // queries); target: the closeness targets (Feature_closeness::targets()
  // on the feature curves)
  Eigen::MatrixXd S, target, direction;
  std::vector<double> distance;  // of each vertex, to the surface and its feature (Feature_closeness::targets())
  double dmax, dmean;
  auto closest_points = [&]() {
    const Timer t0;
    closest(X, S, distance, p.parallel);
    target = S;
    features.targets(X, target, direction, distance);
    dmax = 0;
    double sum = 0;
    for(double d : distance)
    {
      dmax = (std::max)(dmax, d);
      sum += d;
    }
    dmean = sum / double(n);
    result.time_closest += t0.elapsed();
  };
  mesh.planarity(X, result.max_planarity_before, result.mean_planarity_before);
  closest_points();
  result.max_distance_before = dmax;

  t = Timer();
  const double wc = p.closeness_weight, wf = p.fairness_weight;
  const std::vector<std::array<std::size_t, 3> > rows = mesh.fairness_rows(qm);
  result.fairness_rows = rows.size();
  Eigen::SparseMatrix<double> DtD;
  const Eigen::SparseMatrix<double> A = planarization_matrix(n, mesh.quads, rows, wc, wf, DtD);
  typedef Sparse_factorization<SolverTraits, double> Factorization;
  typename Factorization::Solver_scope scope;
  Factorization factorization(solver);
  if(!factorization.analyze(A) || !factorization.factorize(A))
    return Error_code::SOLVER_FAILURE;
  result.time_factorization = t.elapsed();

  const Eigen::MatrixXd X0 = X;
  double beta = 1;
  double mx = result.max_planarity_before, mean = result.mean_planarity_before;
  std::size_t it = 0;
  std::vector<Eigen::Matrix<double, 4, 3> > projected;
  while(mx > p.threshold && it < p.max_iterations)
  {
    t = Timer();
    Eigen::MatrixXd rhs = projected_quads(X, mesh.quads, p.parallel, projected);
    result.time_local += t.elapsed();
    closest_points();
    // With the pull at its floor, nothing brings a vertex that is too far
    // back to the surface: the iterations would only end in
    // TOO_FAR_FROM_SURFACE, later.
    if(beta <= closeness_floor && !(dmax <= result.distance_bound))
    {
      result.left_surface = true;
      break;
    }
    ++it;
    // closeness (proximal, pulled by beta) and fairness (relaxed by beta)
    t = Timer();
    rhs += wc * (X + beta * (target - X));
    if(wf > 0)
      rhs += wf * (1 - beta) * (DtD * X);
    Eigen::MatrixXd Xn;
    if(!factorization.solve(rhs, Xn) || !Xn.allFinite())
      return Error_code::SOLVER_FAILURE;
    X = Xn;
    result.time_solve += t.elapsed();
    beta = (std::max)(closeness_floor, beta * p.closeness_decay);
    mesh.planarity(X, mx, mean);
  }
  result.iterations = it;
  result.max_planarity_after = mx;
  result.mean_planarity_after = mean;
  if(!result.left_surface)  // otherwise dmax is already that of X
    closest_points();
  result.max_distance = dmax;
  result.mean_distance = dmean;
  result.max_displacement = (X - X0).rowwise().norm().maxCoeff();
  result.converged = mx <= p.threshold;
  const Quad_folds folds(X0, mesh.quads);  // the quads the input folds, for both methods
  // the surface's distance to the quads, measured once a result needs it
  std::optional<Surface_coverage> coverage;
  auto coverage_bound = [&]() {
    if(!coverage)
    {
      coverage.emplace(reference, rpm, X0, mesh.quads, p.parallel);
      result.max_distance_to_quads_before = coverage->input();
    }
    return coverage->input() + result.distance_bound;
  };
  // whether the quads at Y cover the surface; `measure` receives the surface's distance to them
  auto covers = [&](const Eigen::MatrixXd& Y, double& measure) {
    const double bound = coverage_bound();
    measure = coverage->largest_distance(Y);
    return measure <= bound;
  };
  Error_code code = Error_code::SUCCESS;
  if(result.left_surface)
    code = Error_code::TOO_FAR_FROM_SURFACE;
  else if(!result.converged)
    code = Error_code::DID_NOT_CONVERGE;
  // The result is checked before it is returned: planar faces bought by
  // leaving the surface are not a success.
  else if(!(dmax <= result.distance_bound))
    code = Error_code::TOO_FAR_FROM_SURFACE;
  // nor planar faces that no longer cover the surface
  else if(!covers(X, result.max_distance_to_quads))
    code = Error_code::TOO_FAR_FROM_SURFACE;
  // nor are planar faces bought by folding a quad
  else if((result.folded_quads = folds.new_folds(X, mesh.quads)) > 0)
    code = Error_code::FOLDED_QUAD;
  if(code != Error_code::SUCCESS && p.gauss_newton_steps > 0 && result.mean_edge_length > 0)
  {
    // The second method, from the input: on success its result replaces the
    // local-global one; otherwise the local-global failure is reported.
    Eigen::MatrixXd Xg;
    auto closest_points_of = [&](const Eigen::MatrixXd& Y, Eigen::MatrixXd& S_, std::vector<double>& d_,
                                 Eigen::MatrixXd& D_) {
      closest.hinted_by_own(Y, S_, d_, p.parallel);
      features.targets(Y, S_, D_, d_);
    };
    Gauss_newton_report g;
    gauss_newton_planarization(X0, mesh.quads, folds, DtD, result.mean_edge_length, p.threshold, result.distance_bound,
                               p.gauss_newton_steps, p.parallel, solver, features, closest_points_of, Xg, g);
    result.gauss_newton_ran = true;
    result.gauss_newton_steps = g.steps;
    result.gauss_newton_rejected_steps = g.rejected;
    result.gauss_newton_stalled = g.stalled;
    result.gauss_newton_max_planarity = g.max_planarity;
    result.gauss_newton_max_distance = g.max_distance;
    result.time_gauss_newton = g.time;
    if(g.succeeded)
      g.succeeded = covers(Xg, result.gauss_newton_max_distance_to_quads);
    if(g.succeeded)
    {
      X = Xg;
      result.converged = true;
      result.max_planarity_after = g.max_planarity;
      result.mean_planarity_after = g.mean_planarity;
      result.max_distance = g.max_distance;
      result.mean_distance = g.mean_distance;
      result.max_displacement = (X - X0).rowwise().norm().maxCoeff();
      result.folded_quads = g.folded_quads;
      result.max_distance_to_quads = result.gauss_newton_max_distance_to_quads;
      code = Error_code::SUCCESS;
    }
  }
  result.time_total = start.elapsed();
  if(code != Error_code::SUCCESS)
    return code;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  for(std::size_t i = 0; i < n; ++i)
    put(vpm, mesh.descriptors[i], Point(X(Eigen::Index(i), 0), X(Eigen::Index(i), 1), X(Eigen::Index(i), 2)));
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_PLANARIZATION_LOCAL_GLOBAL_PLANARIZATION_H
