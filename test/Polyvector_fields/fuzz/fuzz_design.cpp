// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Fuzz target `design`: read constraints, then design (Polyvector_field_designer.h),
// then compute_field_roots() and compute_singularities().
//
// Input (missing bytes count as 0):
//   byte 0: the degree N = 1 + byte % 32;
//   byte 1: bit 0 sign symmetry (taken only for an even N), bit 1 soft
//           constraints, bit 2 the mesh (0: a 3 x 3 grid, 18 faces, an open
//           disk; 1: a closed icosahedron, 20 faces; small, so that one
//           execution costs about a millisecond even at N = 32), bit 3 read with
//           expected_degree (N, or N / 2 with sign symmetry);
//   byte 2: the soft weight 10^(byte % 71 - 35) (1e-35 .. 1e35, so that the
//           refusal of weights outside [1e-30, 1e30] is exercised too);
//   the rest: a constraint file (IO/constraints.h format) on that mesh.
// Any error code is fine. Checked: the designer accepts the mesh and degree;
// a failed add_constraints() leaves no constraint; after solve() succeeds,
// every face has N finite coefficients, compute_field_roots() succeeds with N
// finite roots in the face plane, and compute_singularities() succeeds with
// distinct interior vertices of non-zero index; on the sphere, when no index
// is undefined, the indices add up to the Euler characteristic (sum k = 2N).

#include "fuzz_support.h"

#include <CGAL/Polyvector_fields/IO/constraints.h>
#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>
#include <CGAL/Polyvector_fields/compute_field_roots.h>
#include <CGAL/Polyvector_fields/compute_singularities.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/subdivision_method_3.h>

#include <complex>
#include <iterator>
#include <set>
#include <sstream>

namespace pvf_fuzz_design {

using namespace pvf_fuzz;

typedef std::complex<double> Complex;
typedef PVF::Face_constraint<Face, Vector> Constraint;

// The icosahedron on the unit sphere: 20 faces, closed, genus 0.
inline const Mesh& icosahedron()
{
  static const Mesh tm = [] {
    Mesh m;
    CGAL::make_icosahedron(m, Point(0, 0, 0), 1.0);
    return m;
  }();
  return tm;
}

inline const Mesh& grid_3x3()
{
  static const Mesh tm = grid(3, 3);
  return tm;
}

inline void run(const std::uint8_t* data, std::size_t size)
{
  const std::uint8_t b0 = size > 0 ? data[0] : 0, b1 = size > 1 ? data[1] : 0, b2 = size > 2 ? data[2] : 0;
  const std::string text = size > 3 ? as_text(data + 3, size - 3) : std::string();
  const std::size_t N = 1 + b0 % 32;
  const bool sign_symmetric = (b1 & 1) != 0 && N % 2 == 0;
  const bool soft = (b1 & 2) != 0;
  const bool sphere = (b1 & 4) != 0;
  const bool with_degree = (b1 & 8) != 0;
  const double weight = std::pow(10.0, double(b2 % 71) - 35);
  const std::string what = "N = " + std::to_string(N) + (sign_symmetric ? ", sign-symmetric" : "") +
                           (soft ? ", soft weight " + std::to_string(weight) : ", hard") +
                           (sphere ? ", sphere" : ", grid");

  Mesh tm = sphere ? icosahedron() : grid_3x3();  // a copy: the maps below are added to it

  std::vector<Constraint> constraints;
  std::string message;
  std::istringstream is(text);
  const std::size_t vectors_per_face = sign_symmetric ? N / 2 : N;
  Error_code code =
    with_degree ? PIO::read_constraints(is, tm, constraints,
                                        PVF::parameters::expected_degree(vectors_per_face,
                                                                         PVF::parameters::error_message(message)))
                : PIO::read_constraints(is, tm, constraints, PVF::parameters::error_message(message));
  if(code != Error_code::SUCCESS)
  {
    check_failure_reported(code, message, "read_constraints");
    return;
  }
  if(soft)
    for(Constraint& c : constraints)
      c.weight = weight;

  PVF::Polyvector_field_designer<Mesh> designer(tm, N, PVF::parameters::sign_symmetric(sign_symmetric));
  PVF_FUZZ_CHECK(designer.status() == Error_code::SUCCESS,
                 what + ": the designer refuses the mesh: " + code_name(designer.status()));
  code = designer.add_constraints(constraints);
  if(code != Error_code::SUCCESS)
  {
    PVF_FUZZ_CHECK(std::string(PVF::get_error_message(code)) != "unknown error", what + ": unknown code");
    PVF_FUZZ_CHECK(designer.number_of_constraints() == 0,
                   what + ": a failed add_constraints() kept " + std::to_string(designer.number_of_constraints()) +
                     " constraints");
    return;
  }
  PVF_FUZZ_CHECK(designer.number_of_constraints() == constraints.size(), what + ": constraints lost");

  auto coefficients = tm.add_property_map<Face, std::vector<Complex> >("f:fuzz_coefficients").first;
  code = designer.solve(coefficients);
  if(code != Error_code::SUCCESS)
  {
    PVF_FUZZ_CHECK(std::string(PVF::get_error_message(code)) != "unknown error", what + ": unknown code");
    return;
  }
  for(Face f : faces(tm))
  {
    const std::vector<Complex>& c = coefficients[f];
    PVF_FUZZ_CHECK(c.size() == N, what + ": face " + std::to_string(std::size_t(f)) + " has " +
                                    std::to_string(c.size()) + " coefficients");
    for(std::size_t m = 0; m < N; ++m)
      PVF_FUZZ_CHECK(std::isfinite(c[m].real()) && std::isfinite(c[m].imag()),
                     what + ": coefficient " + std::to_string(m) + " of face " + std::to_string(std::size_t(f)) +
                       " is not finite after SUCCESS");
  }

  auto roots = tm.add_property_map<Face, std::vector<Vector> >("f:fuzz_roots").first;
  code = PVF::compute_field_roots(tm, N, coefficients, roots, PVF::parameters::sign_symmetric(sign_symmetric));
  PVF_FUZZ_CHECK(code == Error_code::SUCCESS, what + ": compute_field_roots() fails on a designed field: " + code_name(code));
  const auto& bundle = designer.tangent_bundle();
  for(Face f : faces(tm))
  {
    PVF_FUZZ_CHECK(roots[f].size() == N, what + ": face " + std::to_string(std::size_t(f)) + " has " +
                                           std::to_string(roots[f].size()) + " roots");
    const std::array<double, 3>& n = bundle.frame(bundle.index(f)).normal;
    for(const Vector& r : roots[f])
    {
      PVF_FUZZ_CHECK(finite(r), what + ": a non-finite root " + vector_text(r) + " on face " +
                                  std::to_string(std::size_t(f)));
      const double along_normal = r.x() * n[0] + r.y() * n[1] + r.z() * n[2];
      // |r| by hypot: squared_length() underflows to 0 for roots below 1e-154.
      const double length = std::hypot(r.x(), std::hypot(r.y(), r.z()));
      PVF_FUZZ_CHECK(std::abs(along_normal) <= 1e-9 * length,
                     what + ": root " + vector_text(r) + " of face " + std::to_string(std::size_t(f)) +
                       " is not in the face plane");
    }
  }

  std::vector<PVF::Singularity<Vertex> > singularities;
  std::vector<Vertex> undefined;
  code = PVF::compute_singularities(tm, N, coefficients, std::back_inserter(singularities), std::back_inserter(undefined));
  PVF_FUZZ_CHECK(code == Error_code::SUCCESS, what + ": compute_singularities() fails on a designed field: " + code_name(code));
  std::set<Vertex> seen;
  long long index_sum = 0;
  for(const auto& s : singularities)
  {
    PVF_FUZZ_CHECK(tm.is_valid(s.vertex) && !CGAL::is_border(s.vertex, tm), what + ": a singularity on no interior vertex");
    PVF_FUZZ_CHECK(seen.insert(s.vertex).second, what + ": a vertex is singular twice");
    PVF_FUZZ_CHECK(s.index_numerator != 0, what + ": a singularity of index 0");
    index_sum += s.index_numerator;
  }
  for(Vertex v : undefined)
    PVF_FUZZ_CHECK(seen.insert(v).second, what + ": a vertex is both singular and undefined, or undefined twice");
  if(sphere && undefined.empty())
    PVF_FUZZ_CHECK(index_sum == 2 * (long long)(N), what + ": the indices add up to " + std::to_string(index_sum) +
                                                      "/N on a sphere, not 2N = " + std::to_string(2 * N));
}

} // namespace pvf_fuzz_design

PVF_FUZZ_TARGET(design)
{
  pvf_fuzz_design::run(data, size);
}
