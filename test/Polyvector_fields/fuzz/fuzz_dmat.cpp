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

#include "constraints_harness.h"

#include <algorithm>
#include <set>
#include <sstream>

namespace pvf_fuzz_dmat {

using namespace pvf_fuzz;


typedef Constraints_read Read;

inline Read read(const std::string& b, const std::string& bc, const Mesh& tm, std::size_t N)
{
  Read r;
  r.out = sentinel_constraints(tm);
  std::istringstream b_stream(b), bc_stream(bc);
  r.code = N == 0 ? PIO::read_dmat_constraints(b_stream, bc_stream, tm, r.out, PVF::parameters::error_message(r.message))
                  : PIO::read_dmat_constraints(b_stream, bc_stream, tm, r.out,
                                               PVF::parameters::expected_degree(N, PVF::parameters::error_message(r.message)));
  if(r.code != Error_code::SUCCESS)
  {
    check_failure_reported(r.code, r.message, "read_dmat_constraints");
    PVF_FUZZ_CHECK(is_sentinel(tm, r.out), "a failed read changed `out`");
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
    most = check_valid_constraints(plain.out, tm);
    for(const Constraint& c : plain.out)
      PVF_FUZZ_CHECK(c.vectors.size() == most, "the rows of bc have different numbers of vectors");
    // What is read writes and reads back in the text format, bit for bit.
    check_constraints_round_trip(plain.out, tm, "read_dmat_constraints");
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
    else
      check_constraints_with_degree(plain, with_N, N, most);
  }
}

} // namespace pvf_fuzz_dmat

PVF_FUZZ_TARGET(dmat)
{
  pvf_fuzz_dmat::run(data, size);
}
