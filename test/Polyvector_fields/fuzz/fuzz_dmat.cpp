// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Fuzz target `dmat`: the libigl .dmat pair reader read_dmat_constraints()
// (IO/constraints.h).
//
// The input is cut in two at its first byte 0xFF (dropped), or else at half:
// the first part is `b`, the second `bc`; they are read on a tetrahedron
// (face ids 0..3) without and with expected_degree(N). Checked as for the
// text reader: known code and message on failure, `out` untouched, valid
// constraints, agreement between the degrees, and a write_constraints()
// round trip of what is read.

#include "fuzz_support.h"

#include <CGAL/Polyvector_fields/IO/constraints.h>

#include <algorithm>
#include <set>
#include <sstream>

namespace pvf_fuzz_dmat {

using namespace pvf_fuzz;

typedef PVF::Face_constraint<Face, Vector> Constraint;

inline std::vector<Constraint> sentinel(const Mesh& tm)
{
  return { Constraint{ *faces(tm).begin(), { Vector(-7, 0.5, 1e-3) }, 2.0 } };
}

struct Read
{
  Error_code code;
  std::string message;
  std::vector<Constraint> out;
};

inline Read read(const std::string& b, const std::string& bc, const Mesh& tm, std::size_t N)
{
  Read r;
  r.out = sentinel(tm);
  std::istringstream b_stream(b), bc_stream(bc);
  r.code = N == 0 ? PIO::read_dmat_constraints(b_stream, bc_stream, tm, r.out, PVF::parameters::error_message(r.message))
                  : PIO::read_dmat_constraints(b_stream, bc_stream, tm, r.out,
                                               PVF::parameters::expected_degree(N, PVF::parameters::error_message(r.message)));
  if(r.code != Error_code::SUCCESS)
  {
    check_failure_reported(r.code, r.message, "read_dmat_constraints");
    PVF_FUZZ_CHECK(same_constraints(r.out, sentinel(tm)), "a failed read changed `out`");
  }
  return r;
}

inline void run(const std::uint8_t* data, std::size_t size)
{
  const std::uint8_t* cut = 
    size == 0 ? nullptr : static_cast<const std::uint8_t*>(std::memchr(data, 0xFF, size));
  std::string b, bc;
  if(cut != nullptr)
  {
    b = as_text(data, std::size_t(cut - data));
    bc = as_text(cut + 1, size - std::size_t(cut - data) - 1);
  }
  else
  {
    b = as_text(data, size / 2);
    bc = as_text(data + size / 2, size - size / 2);
  }

  const Mesh& tm = tetrahedron();
  const Read plain = read(b, bc, tm, 0);
  std::size_t most = 0;
  if(plain.code == Error_code::SUCCESS)
  {
    std::set<Face> seen;
    std::size_t vectors = 0;
    for(const Constraint& c : plain.out)
    {
      PVF_FUZZ_CHECK(tm.is_valid(c.face) && !tm.is_removed(c.face), "a constraint names a face not in the mesh");
      PVF_FUZZ_CHECK(seen.insert(c.face).second, "a face is constrained twice");
      PVF_FUZZ_CHECK(!c.vectors.empty(), "a constraint has no vector");
      PVF_FUZZ_CHECK(std::isinf(c.weight) && c.weight > 0, "a constraint read from a file is not hard");
      PVF_FUZZ_CHECK(vectors == 0 || c.vectors.size() == vectors, "the rows of bc have different numbers of vectors");
      vectors = c.vectors.size();
      for(const Vector& v : c.vectors)
        PVF_FUZZ_CHECK(finite(v), "a non-finite vector " + vector_text(v) + " was read");
      most = (std::max)(most, c.vectors.size());
    }
    // What is read writes and reads back in the text format, bit for bit.
    std::ostringstream os;
    const Error_code written = PIO::write_constraints(os, tm, plain.out);
    PVF_FUZZ_CHECK(written == Error_code::SUCCESS, "write_constraints() failed with " + code_name(written));
    std::vector<Constraint> back;
    std::string message;
    std::istringstream is(os.str());
    const Error_code code = PIO::read_constraints(is, tm, back, PVF::parameters::error_message(message));
    PVF_FUZZ_CHECK(code == Error_code::SUCCESS && same_constraints(back, plain.out),
                   "the constraints do not read back the same: " + code_name(code) + " " + message + "\n" + os.str());
  }

  std::vector<std::size_t> degrees = { 1, 2, 4 };
  if(most > 1)
    degrees.push_back(most - 1);
  if(most > 0)
    degrees.push_back(most);
  for(std::size_t N : degrees)
  {
    const Read with_N = read(b, bc, tm, N);
    const std::string what = "expected_degree(" + std::to_string(N) + ")";
    if(plain.code == Error_code::SUCCESS && plain.out.empty())
      // No row: the column count of bc alone decides (a header may announce many columns of no row).
      PVF_FUZZ_CHECK((with_N.code == Error_code::SUCCESS && with_N.out.empty()) ||
                       with_N.code == Error_code::TOO_MANY_CONSTRAINT_VECTORS,
                     what + " on matrices without rows: " + code_name(with_N.code));
    else if(plain.code == Error_code::SUCCESS)
    {
      if(N >= most)
        PVF_FUZZ_CHECK(with_N.code == Error_code::SUCCESS && same_constraints(with_N.out, plain.out),
                       what + " does not read what is read without it: " + code_name(with_N.code) + " " + with_N.message);
      else
        PVF_FUZZ_CHECK(with_N.code == Error_code::TOO_MANY_CONSTRAINT_VECTORS,
                       what + " accepts rows of " + std::to_string(most) + " vectors: " + code_name(with_N.code));
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
}

} // namespace pvf_fuzz_dmat

PVF_FUZZ_TARGET(dmat)
{
  pvf_fuzz_dmat::run(data, size);
}
