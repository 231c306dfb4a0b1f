// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_CHOLMOD_AVAILABLE_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_CHOLMOD_AVAILABLE_H

// Defines CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE when the package's CHOLMOD code is
// compiled: when CGAL_PVF_HAS_CHOLMOD is defined (the CMake target
// CGAL::Polyvector_fields_CHOLMOD_support defines it and links CHOLMOD), or,
// without that macro, when <cholmod.h> can be included (the program must then
// link CHOLMOD itself). The condition is the same in every translation unit
// built with the same include paths, so that every one of them sees the same
// specializations.

#if defined(CGAL_PVF_HAS_CHOLMOD)
#  define CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE 1
#elif defined(__has_include)
#  if __has_include(<cholmod.h>)
#    define CGAL_PVF_CHOLMOD_SOLVER_AVAILABLE 1
#  endif
#endif

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_CHOLMOD_AVAILABLE_H
