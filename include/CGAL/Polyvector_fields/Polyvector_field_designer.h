// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_POLYVECTOR_FIELD_DESIGNER_H
#define CGAL_POLYVECTOR_FIELDS_POLYVECTOR_FIELD_DESIGNER_H

/// \file Polyvector_field_designer.h

#include <CGAL/Polyvector_fields/Default_sparse_solver.h>
#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Face_constraint.h>
#include <CGAL/Polyvector_fields/Polyvector_field.h>
#include <CGAL/Polyvector_fields/Smoothness_weights.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/internal/Field_design/Coefficient_system.h>
#include <CGAL/Polyvector_fields/internal/Field_design/constraint_specification.h>
#include <CGAL/Polyvector_fields/internal/field_access.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/Default.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <complex>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsDesign
///
/// times of the stages of the last `Polyvector_field_designer::solve()`, in seconds.
struct Design_statistics
{
  double connection = 0;      ///< face frames and Levi-Civita connection (at construction; 0 when a bundle was given)
  double assembly = 0;        ///< assembly of the sparse matrices
  double factorization = 0;   ///< symbolic analysis and numeric factorization
  double solve = 0;           ///< triangular solves
  bool factorization_reused = false;  ///< `true` when the previous factorization served again
  std::size_t number_of_degrees_solved = 0;  ///< coefficient degrees that were not identically zero
};

/// \ingroup PkgPolyvectorFieldsDesign
///
/// designs smooth N-PolyVector fields on a triangle mesh from constraints
/// (paper, Section 3.6), and keeps the factorization of its linear systems so
/// that new constraint values on the same faces are solved for without
/// factoring again.
///
/// The field minimises the smoothness energy of Eq. 6, with the transport
/// power `N - m` of the user manual's section "Smoothness", under the constraints:
/// - a *hard full* constraint fixes all the coefficients of its face;
/// - a *hard partial* constraint (fewer than `N` vectors) makes each given vector a root;
/// - a *soft* constraint adds its weighted squared residual to the energy (see `Face_constraint`).
///
/// Each coefficient degree is solved on its own unless partial constraints couple
/// them; degrees whose constraint values are all zero are skipped (they are zero).
/// Boundary edges carry no term (natural boundary condition). Each connected
/// component is solved on its own; a component without constraint receives the
/// smoothest field of unit vectors: an N-RoSy field given by the smallest
/// eigenvector of its connection Laplacian.
///
/// Computations are done in `double` and `std::complex<double>` whatever the kernel.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam Traits a model of `Kernel`; `CGAL::Default` means the kernel of the point type
///         (only its type `Vector_3` is used: the type of the constraint vectors)
/// \tparam VertexPointMap a model of `ReadablePropertyMap` from vertices to points;
///         `CGAL::Default` means the internal point map of the mesh
/// \tparam SolverTraits a model of `SparseLinearAlgebraWithFactorTraits_d` on `std::complex<double>`;
///         by default `Default_sparse_solver` (the direct solver, CHOLMOD when it was found at
///         configure time and Eigen's `SimplicialLDLT` otherwise, below 8,000 unknowns per
///         system, multigrid-preconditioned conjugate gradient above), which `CGAL::Default` also means
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`:
///         with parallelism (TBB), the independent coefficient degrees are assembled, factored and solved
///         at the same time (with the package's own solvers `Cholmod_sparse_solver` and
///         `Simplicial_ldlt_solver`, and any other `CGAL::Eigen_solver_traits` model); the field is
///         bit-identical to the sequential one.
template <typename TriangleMesh,
          typename Traits = CGAL::Default,
          typename VertexPointMap = CGAL::Default,
          typename SolverTraits = Default_sparse_solver,  // the actual type, so that it is part of the class's name
          typename ConcurrencyTag = CGAL::Parallel_if_available_tag>
class Polyvector_field_designer
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#endif
  static constexpr bool parallel = std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;

public:
  /// \name Types
  /// @{
  typedef typename CGAL::Default::Get<
    VertexPointMap,
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type Vertex_point_map;  ///< the vertex point map type (`VertexPointMap` or the internal one)
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point_3;  ///< the point type
  typedef typename CGAL::Default::Get<Traits, typename CGAL::Kernel_traits<Point_3>::Kernel>::type Geom_traits;  ///< the kernel (`Traits` or the kernel of `Point_3`)
  typedef typename CGAL::Default::Get<SolverTraits, Default_sparse_solver>::type Solver_traits;  ///< the sparse solver (`SolverTraits` or `Default_sparse_solver`)
  typedef typename Geom_traits::Vector_3 Vector_3;  ///< the vector type of the constraints
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;  ///< the face type of `TriangleMesh`
  typedef Face_constraint<face_descriptor, Vector_3> Constraint;  ///< the constraint type accepted by `add_constraint()`
  typedef Tangent_bundle<TriangleMesh, Vertex_point_map> Bundle;  ///< the tangent bundle type returned by `tangent_bundle()`
  typedef std::complex<double> Complex;  ///< the complex number type of the coefficients
  typedef Polyvector_field<Bundle> Field;  ///< the field type returned by `solve()`
  /// @}

  /// builds the face frames and the connection of `tm` for fields of degree `N`.
  ///
  /// \cgalNamedParamsBegin
  ///   \pvfParamVertexPointMap
  ///   \pvfParamSignSymmetric
  ///   \pvfParamSmoothnessWeights
  ///   \cgalParamNBegin{sparse_linear_solver}
  ///     \cgalParamDescription{a prototype of the solver; each factorization uses its own copy}
  ///     \cgalParamType{`Solver_traits`}
  ///     \cgalParamDefault{`Solver_traits()`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// Check `status()` before use.
  template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
  Polyvector_field_designer(const TriangleMesh& tm, std::size_t N,
                            const NamedParameters& np = CGAL::parameters::default_values())
    : Polyvector_field_designer(N, np)
  {
    const internal::Timer timer;
    m_own_bundle.reset(new Bundle(
      tm, CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                             CGAL::get_const_property_map(CGAL::vertex_point, tm))));
    m_bundle = m_own_bundle.get();
    m_statistics.connection = timer.elapsed();
    check_status();
  }

  /// designs fields of degree `N` on the tangent bundle `bundle`, which must
  /// outlive the designer; the named parameters are those of the other
  /// constructor but `vertex_point_map` (the bundle's is used).
  template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
  Polyvector_field_designer(const Bundle& bundle, std::size_t N,
                            const NamedParameters& np = CGAL::parameters::default_values())
    : Polyvector_field_designer(N, np)
  {
    m_bundle = &bundle;
    check_status();
  }

  /// returns `Error_code::SUCCESS` when the mesh and the degree are valid, the reason otherwise
  /// (`EMPTY_MESH`, `NON_TRIANGLE_FACE`, `DEGENERATE_FACE`, `INVALID_DEGREE`).
  Error_code status() const { return m_status; }

  /// returns the degree `N`.
  std::size_t degree() const { return m_N; }

  /// returns whether the field is sign-symmetric.
  bool is_sign_symmetric() const { return m_sign_symmetric; }

  /// returns the tangent bundle: face frames, numbering and connection.
  const Bundle& tangent_bundle() const { return *m_bundle; }

  /// \name Constraints
  /// @{

  /// adds a constraint. On failure nothing is added and the error is returned:
  /// `INVALID_FACE`, `DUPLICATE_CONSTRAINT`, `EMPTY_CONSTRAINT`, `TOO_MANY_CONSTRAINT_VECTORS`,
  /// `ZERO_CONSTRAINT_VECTOR`, `NON_FINITE_VALUE`, `VALUE_OUT_OF_RANGE`, `INVALID_WEIGHT`, or the
  /// `status()` of an invalid designer.
  Error_code add_constraint(const Constraint& constraint)
  {
    if(m_status != Error_code::SUCCESS)
      return m_status;
    if(!m_bundle->contains(constraint.face))
      return Error_code::INVALID_FACE;
    const std::size_t f = m_bundle->index(constraint.face);
    if(m_specifications.count(f))
      return Error_code::DUPLICATE_CONSTRAINT;
    internal::Face_specification specification;
    const Error_code code = internal::make_face_specification(m_bundle->frame(f), constraint.vectors, constraint.weight,
                                                              m_N, m_sign_symmetric, specification);
    if(code == Error_code::SUCCESS)
      m_specifications.emplace(f, std::move(specification));
    return code;
  }

  /// adds the constraint `{f, vectors, weight}`.
  Error_code add_constraint(face_descriptor f, const std::vector<Vector_3>& vectors,
                            double weight = std::numeric_limits<double>::infinity())
  {
    return add_constraint(Constraint{ f, vectors, weight });
  }

  /// adds all the constraints of `constraints` (a range of `Constraint`), or none of them
  /// if one is refused; returns the first error.
  template <typename ConstraintRange>
  Error_code add_constraints(const ConstraintRange& constraints)
  {
    const internal::Specifications saved = m_specifications;
    for(const Constraint& c : constraints)
    {
      const Error_code code = add_constraint(c);
      if(code != Error_code::SUCCESS)
      {
        m_specifications = saved;
        return code;
      }
    }
    return Error_code::SUCCESS;
  }

  /// removes all constraints. The factorization is kept: if the next constraints
  /// hold on the same faces, with the same kinds, weights (and, for partial
  /// constraints, the same vectors), `solve()` does not factor again.
  void clear_constraints() { m_specifications.clear(); }

  /// returns the number of constrained faces.
  std::size_t number_of_constraints() const { return m_specifications.size(); }
  /// @}

  /// computes the field and writes it into `coefficients`.
  ///
  /// \tparam CoefficientMap a model of `WritablePropertyMap` with `face_descriptor` as key type
  ///         and `std::vector<std::complex<double>>` as value type: the `N` coefficients
  ///         `c_0 .. c_{N-1}` of the monic polynomial of each face, in the face frame.
  ///
  /// \returns `Error_code::SUCCESS`, `status()` if the designer is invalid, `VALUE_OUT_OF_RANGE` if the
  ///          lengths of the constraint vectors are too far apart (see the user manual, "Supported range"),
  ///          or `SOLVER_FAILURE`. On failure `coefficients` is not written.
  template <typename CoefficientMap>
  Error_code solve(CoefficientMap coefficients)
  {
    const Error_code code = compute();
    if(code != Error_code::SUCCESS)
      return code;
    internal::write_coefficients(*m_bundle, m_N, m_solution, coefficients);
    return Error_code::SUCCESS;
  }

  /// computes the field and writes it into `field`: its bundle, degree and
  /// symmetry are the designer's, and it keeps the constraints and the
  /// smoothness weights of the design, which the stages after the design use
  /// (the frame-field algorithms hold the hard constraints).
  ///
  /// \returns as the other overload. On failure `field` is not written.
  Error_code solve(Field& field)
  {
    const Error_code code = compute();
    if(code != Error_code::SUCCESS)
      return code;
    field = Field(*m_bundle, m_N, m_sign_symmetric, m_weight_kind);
    field.coefficients() = m_solution;
    field.set_constraint_specifications(m_specifications);
    return Error_code::SUCCESS;
  }

  /// returns the coefficients of the last successful `solve()`: `N` per face,
  /// face after face in the order of the tangent bundle's face numbering.
  const std::vector<Complex>& coefficient_array() const { return m_solution; }

  /// returns the times and facts of the last `solve()`.
  const Design_statistics& statistics() const { return m_statistics; }

private:
  typedef internal::Coefficient_system<Bundle, Solver_traits> System;

  template <typename NamedParameters>
  Polyvector_field_designer(std::size_t N, const NamedParameters& np)
    : m_N(N),
      m_sign_symmetric(CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, internal_np::sign_symmetric), false)),
      m_weight_kind(internal::read_smoothness_weights(np)),
      m_solver_prototype(CGAL::parameters::choose_parameter(
        CGAL::parameters::get_parameter(np, CGAL::internal_np::sparse_linear_solver), Solver_traits()))
  {}

  void check_status()
  {
    if(m_N == 0 || (m_sign_symmetric && m_N % 2 != 0))
      m_status = Error_code::INVALID_DEGREE;
    else
      m_status = m_bundle->status();
    if(m_status == Error_code::SUCCESS)
      m_edge_weights = internal::smoothness_edge_weights(*m_bundle, m_weight_kind);
  }

  Error_code compute()
  {
    if(m_status != Error_code::SUCCESS)
      return m_status;
    const std::vector<int> degrees = internal::active_degrees(m_specifications, m_N, m_sign_symmetric);
    const int k = internal::length_exponent(m_specifications);
    if(!internal::lengths_in_range(m_specifications, k, m_N))
      return Error_code::VALUE_OUT_OF_RANGE;
    bool partial = false;
    for(const auto& entry : m_specifications)
      partial = partial || !entry.second.full;
    m_statistics.factorization_reused = false;
    m_statistics.assembly = m_statistics.factorization = m_statistics.solve = 0;
    m_statistics.number_of_degrees_solved = degrees.size();
    if(m_system && m_system->degrees() == degrees && internal::same_matrices(m_system->specifications(), m_specifications) &&
       (!partial || m_system->length_exponent() == k))
    {
      m_system->specifications() = m_specifications;
      m_system->set_length_exponent(k);
      m_statistics.factorization_reused = true;
    }
    else
    {
      m_system.reset(new System(*m_bundle, m_N, degrees, m_solver_prototype, parallel, m_edge_weights));
      m_system->specifications() = m_specifications;
      m_system->set_length_exponent(k);
      if(!m_system->factor())
      {
        m_system.reset();
        return Error_code::SOLVER_FAILURE;
      }
      m_system->release_matrices();  // the designer never refactors: new weights make a new system
      m_statistics.assembly = m_system->times().assembly;
      m_statistics.factorization = m_system->times().factorization;
    }
    std::vector<Complex> solution;
    if(!m_system->solve(solution))
    {
      m_system.reset();
      return Error_code::SOLVER_FAILURE;
    }
    m_statistics.solve = m_system->times().solve;
    m_solution.swap(solution);
    return Error_code::SUCCESS;
  }

  std::size_t m_N;
  bool m_sign_symmetric;
  Smoothness_weights m_weight_kind;
  std::vector<double> m_edge_weights;  // per interior edge; empty: uniform
  Solver_traits m_solver_prototype;
  std::unique_ptr<const Bundle> m_own_bundle;
  const Bundle* m_bundle = nullptr;
  Error_code m_status = Error_code::SUCCESS;
  internal::Specifications m_specifications;
  std::unique_ptr<System> m_system;
  std::vector<Complex> m_solution;
  Design_statistics m_statistics;
};

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_POLYVECTOR_FIELD_DESIGNER_H
