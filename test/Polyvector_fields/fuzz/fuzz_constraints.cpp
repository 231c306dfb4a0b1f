// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Fuzz target `constraints`: the constraint text reader (IO/constraints.h).
//
// The input is a constraint file, read on a tetrahedron (face ids 0..3) by
//  - read_constraints(std::istream&) without expected_degree;
//  - the same with expected_degree(N) for several N;
//  - read_constraints_by_id(filename) on the same bytes written to a file.
// Checked: a failure has a known code and a message and leaves `out` as it
// was; the readers agree with one another (same code, same message, same
// constraints; with N, a refusal at "too many vectors" exactly when a face has
// more than N); what is read is valid (faces of the mesh, each once, finite
// vectors, hard); and write_constraints() writes it back so that it reads the
// same, bit for bit.

#include "constraints_harness.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <sstream>

namespace pvf_fuzz_constraints {

using namespace pvf_fuzz;

typedef PVF::Face_constraint<std::size_t, Vector> Id_constraint;

typedef Constraints_read Read;

// Reads `text` without expected_degree (N = 0) or with expected_degree(N).
inline Read read(const std::string& text, const Mesh& tm, std::size_t N)
{
  Read r;
  r.out = sentinel_constraints(tm);
  std::istringstream is(text);
  r.code = N == 0 ? PIO::read_constraints(is, tm, r.out, PVF::parameters::error_message(r.message))
                  : PIO::read_constraints(is, tm, r.out,
                                          PVF::parameters::expected_degree(N, PVF::parameters::error_message(r.message)));
  if(r.code != Error_code::SUCCESS)
  {
    check_failure_reported(r.code, r.message, "read_constraints");
    PVF_FUZZ_CHECK(is_sentinel(tm, r.out), "a failed read changed `out`");
  }
  return r;
}

inline void run(const std::string& text)
{
  const Mesh& tm = tetrahedron();
  const Read plain = read(text, tm, 0);
  std::size_t most = 0;
  if(plain.code == Error_code::SUCCESS)
  {
    most = check_valid_constraints(plain.out, tm);
    check_constraints_round_trip(plain.out, tm, "read_constraints");
  }

  std::vector<std::size_t> degrees = { 1, 2, 4, 32 };
  if(most > 1)
    degrees.push_back(most - 1);
  if(most > 0)
    degrees.push_back(most);
  for(std::size_t N : degrees)
    check_constraints_with_degree(plain, read(text, tm, N), N, most);

  // The file overload, on ids: the same outcome.
  write_scratch_file(text);
  std::vector<Id_constraint> by_id = { Id_constraint{ 2, { Vector(1, 2, 3) }, 5.0 } };
  const std::vector<Id_constraint> by_id_sentinel = by_id;
  std::string message;
  const Error_code code =
    PIO::read_constraints_by_id(scratch_file(), num_faces(tm), by_id, PVF::parameters::error_message(message));
  std::remove(scratch_file().c_str());
  PVF_FUZZ_CHECK(code == plain.code && message == plain.message,
                 "read_constraints_by_id gives " + code_name(code) + " '" + message + "', the stream reader " +
                   code_name(plain.code) + " '" + plain.message + "'");
  if(code != Error_code::SUCCESS)
  {
    check_failure_reported(code, message, "read_constraints_by_id");
    PVF_FUZZ_CHECK(same_constraints(by_id, by_id_sentinel), "a failed read_constraints_by_id changed `out`");
  }
  else
  {
    PVF_FUZZ_CHECK(by_id.size() == plain.out.size(), "read_constraints_by_id reads another number of constraints");
    const auto face_ids = PIO::internal::face_list(tm);
    for(std::size_t i = 0; i < by_id.size(); ++i)
    {
      PVF_FUZZ_CHECK(by_id[i].face < face_ids.size() && face_ids[by_id[i].face] == plain.out[i].face,
                     "read_constraints_by_id and read_constraints disagree on the face of constraint " + std::to_string(i));
      PVF_FUZZ_CHECK(same_vectors(by_id[i].vectors, plain.out[i].vectors),
                     "read_constraints_by_id and read_constraints disagree on the vectors of constraint " + std::to_string(i));
    }
  }
}

} // namespace pvf_fuzz_constraints

PVF_FUZZ_TARGET(constraints)
{
  pvf_fuzz_constraints::run(pvf_fuzz::as_text(data, size));
}
