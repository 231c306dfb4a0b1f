// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_SINGULARITY_H
#define CGAL_POLYVECTOR_FIELDS_SINGULARITY_H

/// \file Singularity.h

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsTopology
///
/// is a singular interior vertex of an N-PolyVector field: its index is
/// `index_numerator / N` (paper, Section 3.4).
template <typename VertexDescriptor>
struct Singularity
{
  VertexDescriptor vertex;  ///< the singular vertex
  int index_numerator;      ///< the integer `k` of the index `k/N`; never 0
};

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_SINGULARITY_H
