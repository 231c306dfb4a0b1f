// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The check of an integer-grid map before compute_integer_grid_map() returns
// it: from the snapped corner values and the exact seam transitions only,
// independently of how they were computed. Every test is exact (the values
// are dyadic, the transitions integer): a map that passes has the seams, the
// singular points and the vertex fans that extract_quad_mesh() requires of the
// transitions it is given.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_MAP_CHECK_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_MAP_CHECK_H

#include <CGAL/Polyvector_fields/internal/Integer_grid_map/comb_and_cut.h>
#include <CGAL/Polyvector_fields/internal/Integer_grid_map/gaussian_integers.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// A grid symmetry z -> i^r z + t, t in Z[i].
struct Grid_symmetry
{
  int r = 0;
  Gint t;
};

// b after a: z -> b(a(z)).
inline Grid_symmetry compose(const Grid_symmetry& b, const Grid_symmetry& a)
{
  return Grid_symmetry{ (a.r + b.r) & 3, i_power(b.r) * a.t + b.t };
}

// i^r z + t in floating point: exact when z is dyadic and |z| + |t| < 2^52 (as
// the snapped values are).
inline std::complex<double> apply(const Grid_symmetry& g, const std::complex<double>& z)
{
  const Gint rot = i_power(g.r);
  const double re = double(rot.re) * z.real() - double(rot.im) * z.imag();
  const double im = double(rot.re) * z.imag() + double(rot.im) * z.real();
  return std::complex<double>(re + double(g.t.re), im + double(g.t.im));
}

// The worst |uv_B - (i^r uv_A + t)| over the endpoints of interior edges, with
// (r, t) the transition of the edge: 0 for an exact map.
template <typename CornerMesh, typename Transition>
double transition_residual(const CornerMesh& M, const std::vector<std::complex<double> >& uv,
                           const std::vector<Transition>& transitions)
{
  double worst = 0;
  for(std::size_t c = 0; c < 3 * M.F && c < transitions.size() && c < uv.size(); ++c)
  {
    const std::size_t o = M.opposite[c];
    if(o == npos)
      continue;
    const Grid_symmetry g{ transitions[c].rotation, Gint(transitions[c].translation[0], transitions[c].translation[1]) };
    worst = (std::max)({ worst, std::abs(apply(g, uv[c]) - uv[CornerMesh::prev(o)]),
                         std::abs(apply(g, uv[CornerMesh::prev(c)]) - uv[o]) });
  }
  return worst;
}

// Checks the map `uv` (per corner) with the transitions `transitions` (per
// corner, from face(c) to face(opposite(c)), with members `rotation` and
// `translation`). Returns an empty string if the map is an integer-grid map,
// else what is wrong, first found:
// - a value that is not finite;
// - a transition whose rotation is not in 0..3, or that is not the identity
//   across a border edge;
// - a seam: across an interior edge, the two endpoints in the other face are
//   not exactly the transition of the ones in this face, or the transition of
//   the other side is not its inverse;
// - a singular vertex (non-zero index in `D`) whose value is not an integer point;
// - a regular interior vertex around which the transitions do not compose to
//   the identity (the map is not single-valued there).
template <typename CornerMesh, typename Transition>
std::string check_integer_grid_map(const CornerMesh& M, const Comb_data& D, const std::vector<std::complex<double> >& uv,
                                   const std::vector<Transition>& transitions)
{
  const std::size_t C = 3 * M.F;
  if(uv.size() != C || transitions.size() != C)
    return "the map does not have one value and one transition per corner";
  auto symmetry = [&](std::size_t c) {
    const Transition& T = transitions[c];
    return Grid_symmetry{ T.rotation, Gint(T.translation[0], T.translation[1]) };
  };
  for(std::size_t c = 0; c < C; ++c)
  {
    if(!std::isfinite(uv[c].real()) || !std::isfinite(uv[c].imag()))
      return "a value of the map is not finite (corner " + std::to_string(c) + ")";
    const Transition& T = transitions[c];
    if(T.rotation < 0 || T.rotation > 3)
      return "a transition has a rotation outside 0..3 (corner " + std::to_string(c) + ")";
    const std::size_t o = M.opposite[c];
    if(o == npos)
    {
      if(T.rotation != 0 || T.translation[0] != 0 || T.translation[1] != 0)
        return "a border edge has a transition other than the identity (corner " + std::to_string(c) + ")";
      continue;
    }
    // target(c) is target(prev(o)) in face(o); source(c) = target(prev(c)) is target(o)
    const Grid_symmetry g = symmetry(c);
    if(apply(g, uv[c]) != uv[CornerMesh::prev(o)] || apply(g, uv[CornerMesh::prev(c)]) != uv[o])
      return "a seam is not exact under its transition (corner " + std::to_string(c) + ", vertex " +
             std::to_string(M.target[c]) + ")";
    const Grid_symmetry back = compose(symmetry(o), g);
    if(back.r != 0 || !back.t.is_zero())
      return "the transitions of the two sides of an edge are not inverse (corner " + std::to_string(c) + ")";
  }
  for(std::size_t c = 0; c < C; ++c)
    if(D.index[M.target[c]] != 0 &&
       (uv[c].real() != std::floor(uv[c].real()) || uv[c].imag() != std::floor(uv[c].imag())))
      return "a singular vertex is not on an integer point (vertex " + std::to_string(M.target[c]) + ")";
  // around every interior regular vertex, ccw from one of its corners
  std::vector<char> seen(M.V, 0);
  for(std::size_t c0 = 0; c0 < C; ++c0)
  {
    const std::size_t v = M.target[c0];
    if(seen[v] || M.border_vertex[v] || D.index[v] != 0)
      continue;
    seen[v] = 1;
    Grid_symmetry around;
    std::size_t c = c0, steps = 0;
    do
    {
      around = compose(symmetry(c), around);
      c = M.ccw(c);
      if(++steps > C)
        return "the faces around a vertex do not form a closed fan (vertex " + std::to_string(v) + ")";
    } while(c != npos && c != c0);
    if(c == npos)
      return "the faces around an interior vertex do not form a closed fan (vertex " + std::to_string(v) + ")";
    if(around.r != 0 || !around.t.is_zero())
      return "the transitions around a regular vertex do not compose to the identity (vertex " + std::to_string(v) +
             ", rotation " + std::to_string(around.r) + ")";
  }
  return std::string();
}

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_INTEGER_GRID_MAP_MAP_CHECK_H
