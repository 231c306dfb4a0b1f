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

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>
#include <CGAL/Polyvector_fields/quad_planarity.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <chrono>
#include <cmath>
#include <vector>


namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// reports on a run of `planarize_quad_mesh()`; filled also on failure, as far as it was computed.
struct Planarization_result
{
  std::size_t iterations = 0;                  ///< local-global iterations done
  bool converged = false;                      ///< every face reached `planarity_threshold`
  double threshold = 0;                        ///< `planarity_threshold` used
  double max_planarity_before = 0;             ///< largest face planarity of the input
  double mean_planarity_before = 0;            ///< mean face planarity of the input
  double max_planarity_after = 0;              ///< largest face planarity of the last iterate
  double mean_planarity_after = 0;             ///< mean face planarity of the last iterate
  double max_distance = 0;                     ///< largest distance of a vertex of the last iterate to the reference surface
  double mean_distance = 0;                    ///< mean distance of the vertices of the last iterate to the reference surface
  double max_distance_before = 0;              ///< largest distance of an input vertex to the reference surface
  double mean_edge_length = 0;                 ///< mean edge length of the input quad mesh
  double max_displacement = 0;                 ///< largest vertex motion
  std::size_t fairness_rows = 0;               ///< second differences in the fairness term
  // times in seconds
  double time_tree = 0;            ///< the AABB tree of the reference
  double time_factorization = 0;   ///< assembly and factorization of the fixed matrix
  double time_local = 0;           ///< best-fit planes (all iterations)
  double time_closest = 0;         ///< closest points on the reference (all iterations)
  double time_solve = 0;           ///< right-hand sides and solves (all iterations)
  double time_total = 0;  ///< the whole call
};

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// moves the vertices of the quad mesh `qm` until the planarity of every face is at
/// most `planarity_threshold`, keeping them close to the triangle mesh `reference`
/// and the mesh fair.
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
/// The matrix is factored with Eigen's `SimplicialLDLT` (real, symmetric, positive
/// definite). All computations are done in `double`, whatever the kernels.
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
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the largest number of iterations}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{500}
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
///          `INVALID_PARAMETER` (a parameter out of its range); `SOLVER_FAILURE`; `DID_NOT_CONVERGE` when
///          `number_of_iterations` iterations did not reach the threshold. On failure `qm` is left as it was;
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
  typedef std::chrono::steady_clock Clock;
  auto seconds = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const auto start = Clock::now();
  result = Planarization_result();

  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, qm));
  const auto rpm = choose_parameter(get_parameter(np_ref, CGAL::internal_np::vertex_point),
                                    CGAL::get_const_property_map(CGAL::vertex_point, reference));
  const double threshold = choose_parameter(get_parameter(np, internal_np::planarity_threshold), 0.01);
  const double wc = choose_parameter(get_parameter(np, internal_np::closeness_weight), 1.0);
  const double wf = choose_parameter(get_parameter(np, internal_np::fairness_weight), 0.1);
  const double decay = choose_parameter(get_parameter(np, internal_np::closeness_decay), 0.9);
  const std::size_t max_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), std::size_t(500));
  result.threshold = threshold;
  if(!std::isfinite(threshold) || !std::isfinite(wc) || !std::isfinite(wf) || !std::isfinite(decay))
    return Error_code::NON_FINITE_VALUE;
  if(!(threshold > 0) || !(wc > 0) || wf < 0 || !(decay > 0) || decay > 1)
    return Error_code::INVALID_PARAMETER;
  if(faces(qm).empty() || faces(reference).empty())
    return Error_code::EMPTY_MESH;
  for(auto f : faces(qm))
    if(degree(f, qm) != 4)
      return Error_code::NON_QUAD_FACE;
  for(auto f : faces(reference))
    if(degree(f, reference) != 3)
      return Error_code::NON_TRIANGLE_FACE;

  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  typedef typename boost::property_traits<std::remove_const_t<decltype(rpm)> >::value_type Ref_point;
  typedef typename CGAL::Kernel_traits<Ref_point>::Kernel K;
  typedef CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, std::remove_const_t<decltype(rpm)> > Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;

  internal::Numbering<vertex_descriptor> vindex;
  std::vector<vertex_descriptor> verts;
  for(vertex_descriptor v : vertices(qm))
  {
    vindex.add(v);
    verts.push_back(v);
  }
  const std::size_t n = verts.size();
  Eigen::MatrixXd X(Eigen::Index(n), 3);
  for(std::size_t i = 0; i < n; ++i)
  {
    const Point& p = get(vpm, verts[i]);
    X(Eigen::Index(i), 0) = CGAL::to_double(p.x());
    X(Eigen::Index(i), 1) = CGAL::to_double(p.y());
    X(Eigen::Index(i), 2) = CGAL::to_double(p.z());
  }
  if(!X.allFinite())
    return Error_code::NON_FINITE_VALUE;
  std::vector<std::array<std::size_t, 4> > quads;
  for(auto f : faces(qm))
  {
    std::array<std::size_t, 4> q;
    std::size_t i = 0;
    for(auto h : halfedges_around_face(halfedge(f, qm), qm))
      q[i++] = vindex(target(h, qm));
    quads.push_back(q);
  }
  double edge_sum = 0;
  std::size_t edge_count = 0;
  for(auto e : edges(qm))
  {
    const auto h = halfedge(e, qm);
    edge_sum += (X.row(Eigen::Index(vindex(source(h, qm)))) - X.row(Eigen::Index(vindex(target(h, qm))))).norm();
    ++edge_count;
  }
  result.mean_edge_length = edge_sum / double(edge_count);

  auto planarity = [&](const Eigen::MatrixXd& Y, double& mx, double& mean) {
    mx = 0;
    double sum = 0;
    for(const auto& q : quads)
    {
      std::array<std::array<double, 3>, 4> p;
      for(int k = 0; k < 4; ++k)
        p[k] = { Y(Eigen::Index(q[k]), 0), Y(Eigen::Index(q[k]), 1), Y(Eigen::Index(q[k]), 2) };
      const double v = quad_planarity(p[0], p[1], p[2], p[3]);
      mx = (std::max)(mx, v);
      sum += v;
    }
    mean = sum / double(quads.size());
  };

  // ---- AABB tree of the reference
  auto t = Clock::now();
  Tree tree(faces(reference).first, faces(reference).second, reference, rpm);
  tree.accelerate_distance_queries();
  result.time_tree = seconds(t);
  Eigen::MatrixXd S(Eigen::Index(n), 3);
  bool have_hint = false;
  auto closest = [&](const Eigen::MatrixXd& Y, double& mx, double& mean) {
    const auto t0 = Clock::now();
    mx = 0;
    double sum = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      const typename K::Point_3 q(Y(Eigen::Index(i), 0), Y(Eigen::Index(i), 1), Y(Eigen::Index(i), 2));
      // the previous closest point as the hint: the vertices move little per iteration
      const typename K::Point_3 s = have_hint ? tree.closest_point(q, typename K::Point_3(S(Eigen::Index(i), 0), S(Eigen::Index(i), 1), S(Eigen::Index(i), 2)))
                                              : tree.closest_point(q);
      S(Eigen::Index(i), 0) = CGAL::to_double(s.x());
      S(Eigen::Index(i), 1) = CGAL::to_double(s.y());
      S(Eigen::Index(i), 2) = CGAL::to_double(s.z());
      const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(q, s)));
      mx = (std::max)(mx, d);
      sum += d;
    }
    mean = sum / double(n);
    have_hint = true;
    result.time_closest += seconds(t0);
  };
  planarity(X, result.max_planarity_before, result.mean_planarity_before);
  double dmax, dmean;
  closest(X, dmax, dmean);
  result.max_distance_before = dmax;

  // ---- fixed matrix: planarity (centred quads) + closeness + fairness
  t = Clock::now();
  std::vector<Eigen::Triplet<double> > T;
  for(const auto& q : quads)
    for(int a = 0; a < 4; ++a)
      for(int b = 0; b < 4; ++b)
        T.emplace_back(Eigen::Index(q[a]), Eigen::Index(q[b]), (a == b ? 1.0 : 0.0) - 0.25);
  for(std::size_t i = 0; i < n; ++i)
    T.emplace_back(Eigen::Index(i), Eigen::Index(i), wc);
  // fairness rows: x_a - 2 x_i + x_b
  std::vector<std::array<std::size_t, 3> > rows;
  for(std::size_t i = 0; i < n; ++i)
  {
    const vertex_descriptor v = verts[i];
    std::vector<std::size_t> nb;
    std::vector<std::size_t> border_nb;
    for(auto h : halfedges_around_target(halfedge(v, qm), qm))
    {
      nb.push_back(vindex(source(h, qm)));
      if(CGAL::is_border_edge(h, qm))
        border_nb.push_back(vindex(source(h, qm)));
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
      rows.push_back({ border_nb[0], i, border_nb[1] });  // a straight run of the border (not a staircase corner)
  }
  result.fairness_rows = rows.size();
  Eigen::SparseMatrix<double> Dm(Eigen::Index(rows.size()), Eigen::Index(n));
  {
    std::vector<Eigen::Triplet<double> > DT;
    for(std::size_t r = 0; r < rows.size(); ++r)
    {
      DT.emplace_back(Eigen::Index(r), Eigen::Index(rows[r][0]), 1.0);
      DT.emplace_back(Eigen::Index(r), Eigen::Index(rows[r][1]), -2.0);
      DT.emplace_back(Eigen::Index(r), Eigen::Index(rows[r][2]), 1.0);
    }
    Dm.setFromTriplets(DT.begin(), DT.end());
  }
  const Eigen::SparseMatrix<double> DtD = (Dm.transpose() * Dm).pruned();
  Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  A.setFromTriplets(T.begin(), T.end());
  if(wf > 0)
    A += wf * DtD;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > solver(A);
  if(solver.info() != Eigen::Success)
    return Error_code::SOLVER_FAILURE;
  result.time_factorization = seconds(t);

  const Eigen::MatrixXd X0 = X;
  double beta = 1;
  double mx = result.max_planarity_before, mean = result.mean_planarity_before;
  std::size_t it = 0;
  while(mx > threshold && it < max_iterations)
  {
    ++it;
    // local step: best-fit planes
    t = Clock::now();
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(Eigen::Index(n), 3);
    for(const auto& q : quads)
    {
      Eigen::Matrix<double, 4, 3> P;
      for(int k = 0; k < 4; ++k)
        P.row(k) = X.row(Eigen::Index(q[k]));
      const Eigen::RowVector3d c = P.colwise().mean();
      const Eigen::Matrix<double, 4, 3> Q = P.rowwise() - c;
      const Eigen::Matrix3d cov = Q.transpose() * Q;
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
      const Eigen::Vector3d nrm = es.eigenvectors().col(0);
      for(int k = 0; k < 4; ++k)
      {
        const Eigen::RowVector3d r = Q.row(k) - (Q.row(k).dot(nrm.transpose())) * nrm.transpose();
        rhs.row(Eigen::Index(q[k])) += r;  // C P_f: the projected quad, centred
      }
    }
    result.time_local += seconds(t);
    closest(X, dmax, dmean);
    // closeness (proximal, pulled by beta) and fairness (relaxed by beta)
    t = Clock::now();
    rhs += wc * (X + beta * (S - X));
    if(wf > 0)
      rhs += wf * (1 - beta) * (DtD * X);
    const Eigen::MatrixXd Xn = solver.solve(rhs);
    if(solver.info() != Eigen::Success || !Xn.allFinite())
      return Error_code::SOLVER_FAILURE;
    X = Xn;
    result.time_solve += seconds(t);
    beta = (std::max)(1e-3, beta * decay);
    planarity(X, mx, mean);
  }
  result.iterations = it;
  result.max_planarity_after = mx;
  result.mean_planarity_after = mean;
  closest(X, dmax, dmean);
  result.max_distance = dmax;
  result.mean_distance = dmean;
  result.max_displacement = (X - X0).rowwise().norm().maxCoeff();
  result.converged = mx <= threshold;
  result.time_total = seconds(start);
  if(!result.converged)
    return Error_code::DID_NOT_CONVERGE;
  for(std::size_t i = 0; i < n; ++i)
    put(vpm, verts[i], Point(X(Eigen::Index(i), 0), X(Eigen::Index(i), 1), X(Eigen::Index(i), 2)));
  return Error_code::SUCCESS;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_PLANARIZE_QUAD_MESH_H
