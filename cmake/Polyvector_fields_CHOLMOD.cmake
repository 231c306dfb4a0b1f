# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

# Looks for SuiteSparse's CHOLMOD and, when it is there, defines the imported
# INTERFACE target CGAL::Polyvector_fields_CHOLMOD_support. That target adds
# the CHOLMOD include directory, links CHOLMOD and the SuiteSparse libraries it
# calls, and defines CGAL_PVF_HAS_CHOLMOD=1.
#
# Used by the package's own build and by the installed package config.
# Debian: libsuitesparse-dev puts cholmod.h in /usr/include/suitesparse.

if(NOT TARGET CGAL::Polyvector_fields_CHOLMOD_support)
  find_path(PVF_CHOLMOD_INCLUDE_DIR cholmod.h
            PATH_SUFFIXES suitesparse
            DOC "Directory holding SuiteSparse's cholmod.h")
  find_library(PVF_CHOLMOD_LIBRARY cholmod DOC "SuiteSparse CHOLMOD library")
  find_library(PVF_SUITESPARSECONFIG_LIBRARY suitesparseconfig DOC "SuiteSparse_config library")
  mark_as_advanced(PVF_CHOLMOD_INCLUDE_DIR PVF_CHOLMOD_LIBRARY PVF_SUITESPARSECONFIG_LIBRARY)

  if(PVF_CHOLMOD_INCLUDE_DIR AND PVF_CHOLMOD_LIBRARY AND PVF_SUITESPARSECONFIG_LIBRARY)
    set(_pvf_cholmod_libraries "${PVF_CHOLMOD_LIBRARY}")
    # The orderings CHOLMOD calls directly. A shared libcholmod already names
    # them; a static one needs them on the link line.
    foreach(_pvf_lib amd camd colamd ccolamd)
      string(TOUPPER "${_pvf_lib}" _pvf_LIB)
      find_library(PVF_${_pvf_LIB}_LIBRARY ${_pvf_lib} DOC "SuiteSparse ${_pvf_lib} library")
      mark_as_advanced(PVF_${_pvf_LIB}_LIBRARY)
      if(PVF_${_pvf_LIB}_LIBRARY)
        list(APPEND _pvf_cholmod_libraries "${PVF_${_pvf_LIB}_LIBRARY}")
      endif()
    endforeach()
    list(APPEND _pvf_cholmod_libraries "${PVF_SUITESPARSECONFIG_LIBRARY}")
    # dlsym(), with which the package finds OpenBLAS's thread control (in libc
    # since glibc 2.34; libdl before).
    if(CMAKE_DL_LIBS)
      list(APPEND _pvf_cholmod_libraries ${CMAKE_DL_LIBS})
    endif()

    add_library(CGAL::Polyvector_fields_CHOLMOD_support INTERFACE IMPORTED)
    set_target_properties(CGAL::Polyvector_fields_CHOLMOD_support PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${PVF_CHOLMOD_INCLUDE_DIR}"
      INTERFACE_LINK_LIBRARIES "${_pvf_cholmod_libraries}"
      INTERFACE_COMPILE_DEFINITIONS "CGAL_PVF_HAS_CHOLMOD=1")
    unset(_pvf_cholmod_libraries)
    unset(_pvf_lib)
    unset(_pvf_LIB)
  endif()
endif()
