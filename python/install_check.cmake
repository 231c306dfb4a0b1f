# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

# The python_install test, run by ctest as
#   cmake -DBUILD_DIR=... -DWORK_DIR=... -DPYTHON=... -DSITE=... -DMESH=... -P install_check.cmake
# installs the build into WORK_DIR/prefix, then imports polyvector_fields from
# WORK_DIR/prefix/SITE only (not from the build tree) and designs a field on MESH.

foreach(var BUILD_DIR WORK_DIR PYTHON SITE MESH)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "install_check.cmake: -D${var}=... is required")
  endif()
endforeach()
set(prefix "${WORK_DIR}/prefix")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "python_install: cmake --install failed (${rc})\n${out}\n${err}")
endif()

set(script "
import os, sys
import polyvector_fields as pvf
where = os.path.realpath(pvf.__file__)
assert where.startswith(os.path.realpath(sys.argv[1])), where
V, F, _ = pvf.read_triangle_mesh(sys.argv[2])
X, info = pvf.frame_field(V, F)
assert X.shape == (len(F), 12), X.shape
print('imported', where, 'and designed a frame field on', len(F), 'faces')
")
execute_process(COMMAND "${CMAKE_COMMAND}" -E env "PYTHONPATH=${prefix}/${SITE}" "PYTHONNOUSERSITE=1"
                        "${PYTHON}" -c "${script}" "${prefix}" "${MESH}"
                WORKING_DIRECTORY "${WORK_DIR}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "python_install: importing from ${prefix}/${SITE} failed (${rc})\n${out}\n${err}")
endif()
message(STATUS "python_install: ${out}")
