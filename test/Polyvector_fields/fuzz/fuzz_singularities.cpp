// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Fuzz target `singularities`: read_singularities() (IO/singularities.h).
//
// The input is a singularity file (`N count`, then `vertex numerator` lines),
// read on a tetrahedron (vertex ids 0..3) without and with expected_degree.
// Checked: a failure has a known code and a message and leaves `out` and N
// as they were; a success gives N >= 1 and distinct vertices of the mesh with
// non-zero numerators; expected_degree(N) reads the same and
// expected_degree(N + 1) gives INCONSISTENT_DEGREE; write_singularities()
// writes them back so that they read the same.

#include "fuzz_support.h"

#include <CGAL/Polyvector_fields/IO/singularities.h>
#include <CGAL/Polyvector_fields/Singularity.h>

#include <set>
#include <sstream>

namespace pvf_fuzz_singularities {

using namespace pvf_fuzz;

typedef PVF::Singularity<Vertex> Singularity;

inline bool same(const std::vector<Singularity>& a, const std::vector<Singularity>& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i].vertex != b[i].vertex || a[i].index_numerator != b[i].index_numerator)
      return false;
  return true;
}

inline Error_code read(const std::string& text, const Mesh& tm, std::size_t expected, std::size_t& N,
                       std::vector<Singularity>& out)
{
  out = sentinel_singularities(tm);
  N = sentinel_degree;
  std::string message;
  std::istringstream is(text);
  const Error_code code =
    expected == 0 ? PIO::read_singularities(is, tm, N, out, PVF::parameters::error_message(message))
                  : PIO::read_singularities(is, tm, N, out,
                                            PVF::parameters::expected_degree(expected, PVF::parameters::error_message(message)));
  if(code != Error_code::SUCCESS)
  {
    check_failure_reported(code, message, "read_singularities");
    PVF_FUZZ_CHECK(is_sentinel(tm, out), "a failed read_singularities changed `out`");
    PVF_FUZZ_CHECK(N == sentinel_degree, "a failed read_singularities changed N");
  }
  return code;
}

inline void run(const std::string& text)
{
  const Mesh& tm = tetrahedron();
  std::size_t N = 0;
  std::vector<Singularity> out;
  const Error_code code = read(text, tm, 0, N, out);
  std::size_t N2 = 0;
  std::vector<Singularity> out2;
  if(code != Error_code::SUCCESS)
  {
    PVF_FUZZ_CHECK(read(text, tm, 4, N2, out2) != Error_code::SUCCESS,
                   "expected_degree(4) accepts what is refused without it");
    return;
  }

  PVF_FUZZ_CHECK(N >= 1, "read_singularities succeeded with N = 0");
  std::set<Vertex> seen;
  for(const Singularity& s : out)
  {
    PVF_FUZZ_CHECK(tm.is_valid(s.vertex) && !tm.is_removed(s.vertex), "a singularity is not a vertex of the mesh");
    PVF_FUZZ_CHECK(seen.insert(s.vertex).second, "a vertex is listed twice");
    PVF_FUZZ_CHECK(s.index_numerator != 0, "a singularity of index 0 was read");
  }

  Error_code code2 = read(text, tm, N, N2, out2);
  PVF_FUZZ_CHECK(code2 == Error_code::SUCCESS && N2 == N && same(out2, out),
                 "expected_degree(N) does not read the same: " + code_name(code2));
  if(N < (std::numeric_limits<std::size_t>::max)())
  {
    code2 = read(text, tm, N + 1, N2, out2);
    PVF_FUZZ_CHECK(code2 == Error_code::INCONSISTENT_DEGREE,
                   "expected_degree(N + 1) gives " + code_name(code2) + ", not INCONSISTENT_DEGREE");
  }

  std::ostringstream os;
  const Error_code written = PIO::write_singularities(os, tm, N, out);
  PVF_FUZZ_CHECK(written == Error_code::SUCCESS, "write_singularities() failed with " + code_name(written));
  code2 = read(os.str(), tm, 0, N2, out2);
  PVF_FUZZ_CHECK(code2 == Error_code::SUCCESS && N2 == N && same(out2, out),
                 "the singularities do not read back the same: " + code_name(code2) + "\n" + os.str());
}

} // namespace pvf_fuzz_singularities

PVF_FUZZ_TARGET(singularities)
{
  pvf_fuzz_singularities::run(pvf_fuzz::as_text(data, size));
}
