// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Fuzz target `off_mesh`: IO::internal::read_off_soup(), then
// IO::internal::soup_to_triangle_mesh() (see mesh_harness.h). Byte 0: bit 0
// sets the repair; the rest is the OFF file.

#include "mesh_harness.h"

PVF_FUZZ_TARGET(off_mesh)
{
  pvf_fuzz_mesh::run(pvf_fuzz_mesh::Format::OFF, data, size);
}
