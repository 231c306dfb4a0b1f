# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

# Command-line checks of design_polyvector_field, one case per ctest test:
#   cmake -DEXE=... -DCASE=... -DWORK_DIR=... -DDATA_DIR=... -P cli_checks.cmake
#
# A failure case gives bad input and asks for all three outputs. It passes when
# the program exits with a non-zero code (not a crash), writes exactly one line
# on stderr that names the problem (a lower-case regex per case, "reason"),
# and creates none of the output files.
# A success case passes when the program exits with 0 and writes the three
# outputs, each non-empty.
#
# Constraint files are written in the program's format: one constrained face
# per line, "face_id x1 y1 z1 [x2 y2 z2 ...]", vectors in world coordinates,
# face ids 0-based in file order; lines starting with '#' are comments.

foreach(var EXE CASE WORK_DIR DATA_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "cli_checks.cmake: -D${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

set(bumpy "${DATA_DIR}/bumpy.off")        # 1250 vertices, 2496 triangles, closed
set(bumpy_faces 2496)
set(out_field "${WORK_DIR}/out.rawfield")
set(out_sings "${WORK_DIR}/out.sings")
set(out_vtk "${WORK_DIR}/out.vtk")
set(outputs "${out_field}" "${out_sings}" "${out_vtk}")
set(output_args --out-field "${out_field}" --out-singularities "${out_sings}" --out-vtk "${out_vtk}")
set(constraints "${WORK_DIR}/constraints.txt")

# Tangent vectors for bumpy.off: face 0 has unit normal ~(0, -0.515, 0.857),
# so (1,0,0) lies in its plane and (0,1,0) projects to length ~0.86; face 1261
# has normal ~(0.948, 0, -0.317), so (0,1,0) lies in its plane.
set(expect_success FALSE)
if(CASE STREQUAL "missing_mesh")
  set(args --mesh "${WORK_DIR}/no_such_mesh.off")
  set(reason "does not exist")
elseif(CASE STREQUAL "malformed_mesh")
  # The header announces 4 vertices and 4 faces; the file stops in the vertices.
  file(WRITE "${WORK_DIR}/broken.off" "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1\n")
  set(args --mesh "${WORK_DIR}/broken.off")
  set(reason "line 5: vertex 2 has fewer than 3 coordinates")
elseif(CASE STREQUAL "non_triangle_mesh")
  # A closed, valid cube made of quads.
  file(WRITE "${WORK_DIR}/cube.off"
       "OFF\n8 6 0\n"
       "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
       "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n")
  set(args --mesh "${WORK_DIR}/cube.off" --no-repair)
  set(reason "face 0 \\(line 11\\) has 4 vertices: the mesh is not a triangle mesh")
elseif(CASE STREQUAL "quad_mesh_repaired")
  # The same cube without --no-repair: triangulated, designed on, and reported.
  file(WRITE "${WORK_DIR}/cube.off"
       "OFF\n8 6 0\n"
       "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
       "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n")
  file(WRITE "${constraints}" "0 1 0 0 0 1 0\n")
  set(args --mesh "${WORK_DIR}/cube.off" --degree 4 --sign-symmetric --constraints "${constraints}")
  set(expect_success TRUE)
  set(expect_stdout "repair          6 faces in the file -> 6 polygons triangulated")
elseif(CASE STREQUAL "degree_zero")
  set(args --mesh "${bumpy}" --degree 0)
  set(reason "degree")
elseif(CASE STREQUAL "degree_not_a_number")
  set(args --mesh "${bumpy}" --degree abc)
  set(reason "degree")
elseif(CASE STREQUAL "unknown_flag")
  set(args --mesh "${bumpy}" --degree 4 --no-such-flag)
  set(reason "no-such-flag")
elseif(CASE STREQUAL "constraint_face_out_of_range")
  # Valid ids are 0 .. 2495: the first id past the end.
  file(WRITE "${constraints}" "0 1 0 0\n${bumpy_faces} 1 0 0\n")
  set(args --mesh "${bumpy}" --degree 4 --constraints "${constraints}")
  set(reason "face|range")
elseif(CASE STREQUAL "constraint_nan")
  file(WRITE "${constraints}" "0 1 0 0\n1261 0 nan 0\n")
  set(args --mesh "${bumpy}" --degree 4 --constraints "${constraints}")
  set(reason "nan|finite")
elseif(CASE STREQUAL "constraint_too_many_vectors")
  # N = 2 takes at most 2 vectors per face; this face has 3.
  file(WRITE "${constraints}" "0 1 0 0  0 1 0  1 1 0\n")
  set(args --mesh "${bumpy}" --degree 2 --constraints "${constraints}")
  set(reason "vectors|degree")
elseif(CASE STREQUAL "sign_symmetric_odd_degree")
  set(args --mesh "${bumpy}" --degree 3 --sign-symmetric)
  set(reason "sign|even|odd")
elseif(CASE STREQUAL "success_bumpy")
  # Sign-symmetric N = 4: face 0 fully constrained by {±u, ±v}, face 1261
  # partially by {±w}.
  file(WRITE "${constraints}" "# face x y z ...\n0 1 0 0 0 1 0\n1261 0 1 0\n")
  set(args --mesh "${bumpy}" --degree 4 --sign-symmetric --constraints "${constraints}")
  set(expect_success TRUE)
elseif(CASE STREQUAL "amg_bumpy")
  # The multigrid solver asked for on a mesh the default would give the
  # direct solver: it runs, converges, and says so.
  set(args --mesh "${bumpy}" --sign-symmetric --random-constraints 25 --solver amg)
  set(expect_success TRUE)
  set(expect_stdout "solver          multigrid-preconditioned conjugate gradient: ")
elseif(CASE STREQUAL "parametrize_bumpy")
  # A frame field from 1% curvature constraints and the integer-grid map it
  # guides, written as OBJ with one texture coordinate per corner.
  set(args --mesh "${bumpy}" --curvature-constraints 1 --parametrize --out-param "${WORK_DIR}/map.obj")
  list(APPEND outputs "${WORK_DIR}/map.obj")
  set(expect_success TRUE)
  set(expect_stdout " 0 flipped faces")
elseif(CASE STREQUAL "planar_quads_inspired")
  # The paper's pipeline on its architectural input: conjugate field, map at
  # the paper's quad size, quad mesh, planarized to 1%.
  set(args --conjugate --edge-length 0.82 --quad-mesh "${WORK_DIR}/quads.off" --planarize)
  list(APPEND outputs "${WORK_DIR}/quads.off" "${WORK_DIR}/out.quads.vtk")
  set(expect_success TRUE)
  set(expect_stdout "-> after ")
elseif(CASE STREQUAL "default_run")
  # The README's main command: no arguments, the bundled run, writing into
  # output/ of the working directory.
  set(args "")
  set(output_args "")
  set(expect_success TRUE)
else()
  message(FATAL_ERROR "cli_checks.cmake: unknown case '${CASE}'")
endif()

list(JOIN args " " shown_args)
list(JOIN output_args " " shown_output_args)
message(STATUS "running: ${EXE} ${shown_args} ${shown_output_args}")
execute_process(COMMAND "${EXE}" ${args} ${output_args}
                WORKING_DIRECTORY "${WORK_DIR}"
                RESULT_VARIABLE rc
                OUTPUT_VARIABLE out
                ERROR_VARIABLE err
                TIMEOUT 240)
message(STATUS "exit: ${rc}")

if(expect_success)
  if(NOT rc STREQUAL "0")
    message(FATAL_ERROR "expected exit code 0, got '${rc}'\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  if(DEFINED expect_stdout)
    string(FIND "${out}" "${expect_stdout}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "stdout does not say '${expect_stdout}'\nstdout:\n${out}")
    endif()
  endif()
  if(CASE STREQUAL "default_run")
    set(outputs "")
    foreach(ext rawfield sings vtk)
      file(GLOB found "${WORK_DIR}/output/*.${ext}")
      if(NOT found)
        message(FATAL_ERROR "the default run wrote no output/*.${ext}\nstdout:\n${out}\nstderr:\n${err}")
      endif()
      list(APPEND outputs ${found})
    endforeach()
  endif()
  foreach(file IN LISTS outputs)
    if(NOT EXISTS "${file}")
      message(FATAL_ERROR "expected output ${file} was not written\nstdout:\n${out}\nstderr:\n${err}")
    endif()
    file(SIZE "${file}" size)
    if(size EQUAL 0)
      message(FATAL_ERROR "output ${file} is empty")
    endif()
    message(STATUS "wrote ${file} (${size} bytes)")
  endforeach()
  return()
endif()

# A failure case. A crash gives a text such as "Segmentation fault" instead of
# a number, and a timeout gives "Process terminated due to timeout".
if(NOT rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "expected a non-zero exit code, the program ended with '${rc}'\nstderr:\n${err}")
endif()
if(rc EQUAL 0)
  message(FATAL_ERROR "expected a non-zero exit code, got 0\nstdout:\n${out}\nstderr:\n${err}")
endif()
string(REGEX REPLACE "\r?\n$" "" line "${err}")
if(line STREQUAL "")
  message(FATAL_ERROR "expected exactly one line on stderr, got none")
endif()
if(line MATCHES "\n")
  message(FATAL_ERROR "expected exactly one line on stderr, got:\n${err}")
endif()
message(STATUS "stderr: ${line}")
# The message must name the actual problem, not some earlier one. The work
# directory is taken out first: its path holds the case's name.
string(REPLACE "${WORK_DIR}" "" lower_line "${line}")
string(TOLOWER "${lower_line}" lower_line)
if(NOT lower_line MATCHES "${reason}")
  message(FATAL_ERROR "the stderr line does not match '${reason}', so the run may have failed for another reason")
endif()
foreach(file IN LISTS outputs)
  if(EXISTS "${file}")
    message(FATAL_ERROR "bad input, yet ${file} was created")
  endif()
endforeach()
