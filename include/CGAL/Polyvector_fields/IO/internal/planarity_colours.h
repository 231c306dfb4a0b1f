// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_PLANARITY_COLOURS_H
#define CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_PLANARITY_COLOURS_H

// The colour map of face planarity shared by the HTML viewer and the PLY
// writer: blue for a planar quad, through light blue, pale yellow and orange,
// to red at the top of the range (the planarity drawn red, and beyond). Faces
// that are not quads (planarity -1) are grey. The viewer's colour bar is
// drawn from the same stops, so that a colour on screen reads back on the bar.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {
namespace internal {

struct Colour_stop
{
  double t;  // position in [0, 1]
  std::uint8_t r, g, b;
};

// The stops, from planar (t = 0) to the top of the range (t = 1).
inline const std::array<Colour_stop, 5>& planarity_colour_stops()
{
  static const std::array<Colour_stop, 5> stops = { { { 0.0, 35, 75, 200 },
                                                      { 0.3, 80, 170, 235 },
                                                      { 0.55, 245, 240, 190 },
                                                      { 0.8, 250, 150, 55 },
                                                      { 1.0, 210, 25, 25 } } };
  return stops;
}

// The grey of faces that are not quads.
constexpr std::array<std::uint8_t, 3> non_quad_colour = { 150, 150, 150 };

// The colour of planarity `q` on the range [0, range] (range > 0); q < 0
// (a face that is not a quad) is grey, q above the range is red.
inline std::array<std::uint8_t, 3> planarity_colour(double q, double range)
{
  if(!(q >= 0))
    return non_quad_colour;
  const auto& stops = planarity_colour_stops();
  double t = q / range;
  if(!(t <= 1))
    t = 1;
  std::size_t i = 1;
  while(i + 1 < stops.size() && t > stops[i].t)
    ++i;
  const Colour_stop& a = stops[i - 1];
  const Colour_stop& b = stops[i];
  const double s = (t - a.t) / (b.t - a.t);
  auto mix = [s](std::uint8_t x, std::uint8_t y) {
    return std::uint8_t(std::lround(double(x) + s * (double(y) - double(x))));
  };
  return { mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b) };
}

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_PLANARITY_COLOURS_H
