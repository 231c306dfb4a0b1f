# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

# The install_consumer test, run by ctest as
#   cmake -DBUILD_DIR=... -DCONSUMER_SOURCE_DIR=... -DWORK_DIR=... \
#         -DGENERATOR=... -DCXX_COMPILER=... -DCONFIG=... -P install_check.cmake
# 1. installs the build BUILD_DIR into WORK_DIR/prefix;
# 2. configures and builds CONSUMER_SOURCE_DIR against that prefix only;
# 3. checks that the package was found in the prefix, and runs the consumer.

foreach(var BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "install_check.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT CONFIG)
  set(CONFIG Release)
endif()

set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# Runs a command; on failure prints what it printed and stops.
function(run_step what)
  execute_process(COMMAND ${ARGN}
                  RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install_consumer: ${what} failed (${rc})\n"
                        "command: ${ARGN}\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

run_step("cmake --install"
         "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}" --config "${CONFIG}")

run_step("configuring the consumer"
         "${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE_DIR}" -B "${consumer_build}"
         -G "${GENERATOR}"
         "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
         "-DCMAKE_BUILD_TYPE=${CONFIG}"
         "-DCMAKE_PREFIX_PATH=${prefix}"
         # Find the package through the prefix only, never through a registry.
         -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
         -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)

# The consumer must have used the installed config, not a copy found elsewhere.
file(STRINGS "${consumer_build}/CMakeCache.txt" config_dir_line
     REGEX "^CGAL_Polyvector_fields_DIR:")
string(REGEX REPLACE "^[^=]*=" "" config_dir "${config_dir_line}")
get_filename_component(real_prefix "${prefix}" REALPATH)
if(EXISTS "${config_dir}")
  get_filename_component(config_dir "${config_dir}" REALPATH)
endif()
string(FIND "${config_dir}" "${real_prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "install_consumer: CGAL_Polyvector_fields was found in '${config_dir}', "
                      "not in the install prefix '${real_prefix}'")
endif()

run_step("building the consumer"
         "${CMAKE_COMMAND}" --build "${consumer_build}" --config "${CONFIG}")

set(consumer "${consumer_build}/pvf_install_consumer")
if(NOT EXISTS "${consumer}")
  set(consumer "${consumer_build}/${CONFIG}/pvf_install_consumer")  # multi-config generators
endif()
run_step("running the consumer" "${consumer}")
message(STATUS "package config: ${config_dir}")
message(STATUS "${step_output}")
