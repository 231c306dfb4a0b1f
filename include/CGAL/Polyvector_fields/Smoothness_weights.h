// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_SMOOTHNESS_WEIGHTS_H
#define CGAL_POLYVECTOR_FIELDS_SMOOTHNESS_WEIGHTS_H

/// \file Smoothness_weights.h

#include <CGAL/Polyvector_fields/face_frames.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsDesign
///
/// The weight `w_e` of each interior edge `e = (f, g)` in the smoothness
/// energy `sum_e w_e sum_m |c_{f,m} conj(e_f)^(N-m) - c_{g,m} conj(e_g)^(N-m)|^2`
/// (user manual, section "Smoothness weights").
enum class Smoothness_weights
{
  /// `w_e = 1`, the paper's Eq. 6. The energy then counts edges, so the field
  /// follows the density of the triangulation: a finely meshed region weighs
  /// more than a coarse one of the same area.
  UNIFORM,
  /// `w_e = 3 |e|^2 / (A_f + A_g)`, with `A_f`, `A_g` the areas of the two
  /// faces (the weights that Brandt et al. 2020 derive from the Dirichlet
  /// energy of a piecewise-constant field): the energy approximates the
  /// integral of the field's squared covariant derivative, whatever the
  /// triangulation. The weight has no unit, so a field is unchanged when the
  /// mesh is scaled; it is `2 sqrt(3)` for two equilateral triangles.
  HARMONIC
};

namespace internal {

// 3 |e|^2 / (A_f + A_g) for the edge p q between the triangles p q r and q p s.
// The four points are scaled by one power of two first, which leaves the
// ratio unchanged and keeps every square in range.
inline double harmonic_edge_weight(std::array<double, 3> p, std::array<double, 3> q,
                                   std::array<double, 3> r, std::array<double, 3> s)
{
  scale_to_unit({ &p, &q, &r, &s });
  const std::array<double, 3> e = difference(q, p);
  const auto length = [](const std::array<double, 3>& a) { return std::sqrt(dot(a, a)); };
  const double twice_area_f = length(cross(e, difference(r, p)));
  const double twice_area_g = length(cross(e, difference(s, p)));
  return 6. * dot(e, e) / (twice_area_f + twice_area_g);
}

// The weights of the interior edges of `bundle`, in the order of
// `bundle.interior_edges()`; empty for UNIFORM (the energy's "all ones").
template <typename Bundle>
std::vector<double> smoothness_edge_weights(const Bundle& bundle, Smoothness_weights kind)
{
  std::vector<double> weights;
  if(kind == Smoothness_weights::UNIFORM)
    return weights;
  const auto& tm = bundle.mesh();
  const auto point = [&](auto v) { return bundle.point(bundle.index(v)); };
  weights.reserve(bundle.interior_edges().size());
  for(const auto& edge : bundle.interior_edges())
  {
    const auto h = edge.h;
    const auto o = opposite(h, tm);
    weights.push_back(harmonic_edge_weight(point(source(h, tm)), point(target(h, tm)),
                                           point(target(next(h, tm), tm)), point(target(next(o, tm), tm))));
  }
  return weights;
}

// The named parameter `smoothness_weights` of `np`.
template <typename NamedParameters>
Smoothness_weights read_smoothness_weights(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::smoothness_weights),
                                            Smoothness_weights::UNIFORM);
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_SMOOTHNESS_WEIGHTS_H
