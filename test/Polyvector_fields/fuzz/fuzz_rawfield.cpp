// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Fuzz target `rawfield`: read_rawfield() (IO/rawfield.h).
//
// The input is a .rawfield file (`N F`, then F lines of 3N numbers), read on a
// tetrahedron (F = 4) without and with expected_degree. Checked: a failure
// has a known code and a message and leaves the root map and N as they were;
// a success gives N >= 1 finite roots on every face; expected_degree(N)
// reads the same and expected_degree(N + 1) gives INCONSISTENT_DEGREE; and
// write_rawfield() writes the roots back so that they read the same, bit for bit.

#include "fuzz_support.h"

#include <CGAL/Polyvector_fields/IO/rawfield.h>

#include <sstream>

namespace pvf_fuzz_rawfield {

using namespace pvf_fuzz;

typedef Mesh::Property_map<Face, std::vector<Vector> > Root_map;

struct Field
{
  Mesh tm = tetrahedron();
  Root_map roots = tm.add_property_map<Face, std::vector<Vector> >("f:fuzz_roots").first;

  void reset() { fill_sentinel_roots(tm, roots); }
  bool untouched() const { return has_sentinel_roots(tm, roots); }
};

// Reads `text` into `field` without (expected = 0) or with expected_degree(expected).
inline Error_code read(const std::string& text, Field& field, std::size_t expected, std::size_t& N, std::string& message)
{
  field.reset();
  N = sentinel_degree;
  message.clear();
  std::istringstream is(text);
  const Error_code code =
    expected == 0 ? PIO::read_rawfield(is, field.tm, field.roots, N, PVF::parameters::error_message(message))
                  : PIO::read_rawfield(is, field.tm, field.roots, N,
                                       PVF::parameters::expected_degree(expected, PVF::parameters::error_message(message)));
  if(code != Error_code::SUCCESS)
  {
    check_failure_reported(code, message, "read_rawfield");
    PVF_FUZZ_CHECK(field.untouched(), "a failed read_rawfield changed the root map");
    PVF_FUZZ_CHECK(N == sentinel_degree, "a failed read_rawfield changed N");
  }
  return code;
}

inline void run(const std::string& text)
{
  static Field field, again;
  std::size_t N = 0;
  std::string message;
  const Error_code code = read(text, field, 0, N, message);
  if(code != Error_code::SUCCESS)
  {
    // expected_degree cannot make a refused file acceptable.
    std::size_t N4 = 0;
    std::string message4;
    PVF_FUZZ_CHECK(read(text, again, 4, N4, message4) != Error_code::SUCCESS,
                   "expected_degree(4) accepts what is refused without it");
    return;
  }

  PVF_FUZZ_CHECK(N >= 1, "read_rawfield succeeded with N = 0");
  for(Face f : faces(field.tm))
  {
    PVF_FUZZ_CHECK(field.roots[f].size() == N, "face " + std::to_string(std::size_t(f)) + " has " +
                                                 std::to_string(field.roots[f].size()) + " roots, not N = " +
                                                 std::to_string(N));
    for(const Vector& v : field.roots[f])
      PVF_FUZZ_CHECK(finite(v), "a non-finite root " + vector_text(v) + " was read");
  }

  std::size_t N2 = 0;
  std::string message2;
  Error_code code2 = read(text, again, N, N2, message2);
  PVF_FUZZ_CHECK(code2 == Error_code::SUCCESS && N2 == N, "expected_degree(N) refuses the file: " + code_name(code2));
  for(Face f : faces(field.tm))
    PVF_FUZZ_CHECK(same_vectors(again.roots[f], field.roots[f]), "expected_degree(N) reads other roots");
  if(N < (std::numeric_limits<std::size_t>::max)())
  {
    code2 = read(text, again, N + 1, N2, message2);
    PVF_FUZZ_CHECK(code2 == Error_code::INCONSISTENT_DEGREE,
                   "expected_degree(N + 1) gives " + code_name(code2) + ", not INCONSISTENT_DEGREE");
  }

  std::ostringstream os;
  const Error_code written = PIO::write_rawfield(os, field.tm, field.roots, N);
  PVF_FUZZ_CHECK(written == Error_code::SUCCESS, "write_rawfield() failed with " + code_name(written));
  code2 = read(os.str(), again, 0, N2, message2);
  PVF_FUZZ_CHECK(code2 == Error_code::SUCCESS && N2 == N,
                 "what write_rawfield() wrote does not read back: " + code_name(code2) + " " + message2);
  for(Face f : faces(field.tm))
    PVF_FUZZ_CHECK(same_vectors(again.roots[f], field.roots[f]), "the roots do not read back the same:\n" + os.str());
}

} // namespace pvf_fuzz_rawfield

PVF_FUZZ_TARGET(rawfield)
{
  pvf_fuzz_rawfield::run(pvf_fuzz::as_text(data, size));
}
