// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// What the fuzz targets of the two constraint readers (`constraints`: the
// text format, `dmat`: libigl's .dmat pair) check alike: a successful read is
// valid and writes back with write_constraints() so that it reads the same;
// and with expected_degree(N) the read has the same outcome, except a refusal
// when a face has more than N vectors.

#ifndef CGAL_POLYVECTOR_FIELDS_TEST_FUZZ_CONSTRAINTS_HARNESS_H
#define CGAL_POLYVECTOR_FIELDS_TEST_FUZZ_CONSTRAINTS_HARNESS_H

#include "fuzz_support.h"

#include <CGAL/Polyvector_fields/IO/constraints.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace pvf_fuzz {

typedef PVF::Face_constraint<Face, Vector> Constraint;

// The outcome of one read: code, message and constraints.
struct Constraints_read
{
  Error_code code;
  std::string message;
  std::vector<Constraint> out;
};

// What a successful read must hold (faces of the mesh, each once, with at
// least one vector, all finite, hard); returns the largest number of vectors of a face.
inline std::size_t check_valid_constraints(const std::vector<Constraint>& constraints, const Mesh& tm)
{
  std::set<Face> seen;
  std::size_t most = 0;
  for(const Constraint& c : constraints)
  {
    PVF_FUZZ_CHECK(tm.is_valid(c.face) && !tm.is_removed(c.face), "a constraint names a face not in the mesh");
    PVF_FUZZ_CHECK(seen.insert(c.face).second, "face " + std::to_string(std::size_t(c.face)) + " is constrained twice");
    PVF_FUZZ_CHECK(!c.vectors.empty(), "a constraint has no vector");
    PVF_FUZZ_CHECK(std::isinf(c.weight) && c.weight > 0, "a constraint read from a file is not hard");
    for(const Vector& v : c.vectors)
      PVF_FUZZ_CHECK(finite(v), "a non-finite vector " + vector_text(v) + " was read");
    most = (std::max)(most, c.vectors.size());
  }
  return most;
}

// Writes `constraints` in the text format with write_constraints() and reads
// them back: the same constraints, bit for bit.
inline void check_constraints_round_trip(const std::vector<Constraint>& constraints, const Mesh& tm,
                                         const std::string& what)
{
  std::ostringstream os;
  const Error_code written = PIO::write_constraints(os, tm, constraints);
  PVF_FUZZ_CHECK(written == Error_code::SUCCESS, what + ": write_constraints() failed with " + code_name(written));
  std::string message;
  std::vector<Constraint> back;
  std::istringstream is(os.str());
  const Error_code code = PIO::read_constraints(is, tm, back, PVF::parameters::error_message(message));
  PVF_FUZZ_CHECK(code == Error_code::SUCCESS, what + ": what write_constraints() wrote does not read back: " +
                                               code_name(code) + ": " + message + "\n" + os.str());
  PVF_FUZZ_CHECK(same_constraints(back, constraints), what + ": the constraints do not read back the same:\n" + os.str());
}

// With expected_degree(N) (`with_N`) against without (`plain`, whose faces
// have at most `most` vectors): the same outcome, except a refusal at a face
// with more than N vectors.
inline void check_constraints_with_degree(const Constraints_read& plain, const Constraints_read& with_N, std::size_t N,
                                          std::size_t most)
{
  const std::string what = "expected_degree(" + std::to_string(N) + ")";
  if(plain.code == Error_code::SUCCESS)
  {
    if(N >= most)
    {
      PVF_FUZZ_CHECK(with_N.code == Error_code::SUCCESS, what + " refuses what is read without it: " +
                                                           code_name(with_N.code) + ": " + with_N.message);
      PVF_FUZZ_CHECK(same_constraints(with_N.out, plain.out), what + " reads other constraints");
    }
    else
      PVF_FUZZ_CHECK(with_N.code == Error_code::TOO_MANY_CONSTRAINT_VECTORS,
                     what + " accepts a face with " + std::to_string(most) + " vectors: " + code_name(with_N.code));
  }
  else
  {
    PVF_FUZZ_CHECK(with_N.code != Error_code::SUCCESS, what + " accepts what is refused without it");
    if(with_N.code != Error_code::TOO_MANY_CONSTRAINT_VECTORS)
      PVF_FUZZ_CHECK(with_N.code == plain.code && with_N.message == plain.message,
                     what + " fails otherwise: " + code_name(with_N.code) + " '" + with_N.message + "' against " +
                       code_name(plain.code) + " '" + plain.message + "'");
  }
}

} // namespace pvf_fuzz

#endif // CGAL_POLYVECTOR_FIELDS_TEST_FUZZ_CONSTRAINTS_HARNESS_H
