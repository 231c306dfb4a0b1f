// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_POLYVECTOR_FIELD_H
#define CGAL_POLYVECTOR_FIELDS_POLYVECTOR_FIELD_H

/// \file Polyvector_field.h

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Smoothness_weights.h>
#include <CGAL/Polyvector_fields/internal/Field_design/constraint_specification.h>
#include <CGAL/Polyvector_fields/internal/field_access.h>

#include <boost/property_map/property_map.hpp>

#include <complex>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsDesign
///
/// an N-PolyVector field on a tangent bundle: the degree `N`, whether the
/// field is sign-symmetric, and the `N` coefficients `c_0 .. c_{N-1}` of the
/// monic polynomial of every face, in the face frame (paper, Section 3.1),
/// together with what the stages after the design need to know of it: the
/// constraints it was designed with (the frame-field algorithms hold the hard
/// ones) and the smoothness weights of its energy.
///
/// `Polyvector_field_designer::solve()` makes one; the roots, the
/// singularities, the measures, the frame-field algorithms, the combing and
/// the integer-grid map take one. A field from elsewhere (a file, another
/// program) is made with the constructor and `read_coefficients()`; it has no
/// constraints.
///
/// The field refers to its tangent bundle, which must outlive it.
///
/// \tparam TangentBundle a `Tangent_bundle`
template <typename TangentBundle>
class Polyvector_field
{
public:
  /// \name Types
  /// @{
  typedef TangentBundle Bundle;  ///< the tangent bundle type
  typedef typename Bundle::face_descriptor face_descriptor;  ///< the face type of the mesh
  typedef std::complex<double> Complex;  ///< the complex number type of the coefficients

  /// a model of `ReadablePropertyMap` from faces to `std::vector<Complex>` (the
  /// `N` coefficients of the face), a view on the field: it is valid as long
  /// as the field is, and reads its current coefficients.
  class Coefficient_map
  {
  public:
    typedef face_descriptor key_type;  ///< the face
    typedef std::vector<Complex> value_type;  ///< its coefficients
    typedef value_type reference;  ///< a copy: the field stores its coefficients contiguously
    typedef boost::readable_property_map_tag category;  ///< readable only

    Coefficient_map() = default;
    /// the view of `field`
    explicit Coefficient_map(const Polyvector_field& field) : m_field(&field) {}
    /// the coefficients of face `f`
    friend value_type get(const Coefficient_map& map, key_type f) { return map.m_field->coefficients_of(f); }

  private:
    const Polyvector_field* m_field = nullptr;
  };
  /// @}

  /// the zero field of degree `N` on `bundle`.
  Polyvector_field(const Bundle& bundle, std::size_t N, bool sign_symmetric = false,
                   Smoothness_weights weights = Smoothness_weights::UNIFORM)
    : m_bundle(&bundle), m_N(N), m_sign_symmetric(sign_symmetric), m_weights(weights),
      m_coefficients(bundle.number_of_faces() * N, Complex(0))
  {}

  /// returns the tangent bundle the field lives on.
  const Bundle& tangent_bundle() const { return *m_bundle; }

  /// returns the degree `N`.
  std::size_t degree() const { return m_N; }

  /// returns whether the field is sign-symmetric (its vectors come in pairs `{u, -u}`).
  bool is_sign_symmetric() const { return m_sign_symmetric; }

  /// returns whether the field is a frame field `{±u, ±v}`: degree 4 and sign-symmetric.
  bool is_frame_field() const { return m_N == 4 && m_sign_symmetric; }

  /// returns the edge weights of the smoothness energy the field was designed with.
  Smoothness_weights smoothness_weights() const { return m_weights; }

  /// returns the coefficients: `N` per face, face after face, in the order of
  /// the tangent bundle's face numbering (`coefficients()[i * N + m]` is `c_m` of
  /// the face `tangent_bundle().face(i)`).
  const std::vector<Complex>& coefficients() const { return m_coefficients; }

  /// returns the coefficients for writing; their number must stay `N` times the number of faces.
  std::vector<Complex>& coefficients() { return m_coefficients; }

  /// returns the `N` coefficients of face `f`.
  std::vector<Complex> coefficients_of(face_descriptor f) const
  {
    const std::size_t i = m_bundle->index(f);
    return std::vector<Complex>(m_coefficients.begin() + std::ptrdiff_t(i * m_N),
                                m_coefficients.begin() + std::ptrdiff_t((i + 1) * m_N));
  }

  /// returns a readable property map from faces to their coefficients, a view on this field.
  Coefficient_map coefficient_map() const { return Coefficient_map(*this); }

  /// writes the coefficients of every face into `map`, a model of
  /// `WritablePropertyMap` from faces to `std::vector<std::complex<double>>`.
  template <typename CoefficientMap>
  void write_coefficients(CoefficientMap map) const
  {
    internal::write_coefficients(*m_bundle, m_N, m_coefficients, map);
  }

  /// reads the coefficients of every face from `map`, a model of
  /// `ReadablePropertyMap` from faces to `std::vector<std::complex<double>>`.
  /// \returns `SUCCESS`, the bundle's error, `INVALID_DEGREE`, `INCONSISTENT_DEGREE`
  ///          (a vector not of size `N`) or `NON_FINITE_VALUE`; on failure the field is unchanged.
  template <typename CoefficientMap>
  Error_code read_coefficients(CoefficientMap map)
  {
    return internal::read_coefficients(*m_bundle, m_N, map, m_coefficients);
  }

  /// returns the number of faces with a constraint of the design.
  std::size_t number_of_constraints() const { return m_constraints.size(); }

  /// returns whether face `f` is fixed by a hard full constraint of the design.
  bool is_fixed(face_descriptor f) const
  {
    const auto it = m_constraints.find(m_bundle->index(f));
    return it != m_constraints.end() && it->second.full && it->second.is_hard();
  }

  /// \cond SKIP_IN_MANUAL
  // The constraints of the design, in the face frames, keyed by face index
  // (the frame-field algorithms hold them).
  const internal::Specifications& constraint_specifications() const { return m_constraints; }
  void set_constraint_specifications(internal::Specifications s) { m_constraints = std::move(s); }
  /// \endcond

private:
  const Bundle* m_bundle;
  std::size_t m_N;
  bool m_sign_symmetric;
  Smoothness_weights m_weights;
  std::vector<Complex> m_coefficients;
  internal::Specifications m_constraints;
};

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_POLYVECTOR_FIELD_H
