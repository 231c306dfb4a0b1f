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
# A success case passes when the program exits with 0 and its outputs agree
# with its summary on standard output:
# - the .rawfield has the header "N F" and one line of 3N numbers per face,
#   N the degree and F the number of faces of the summary;
# - the .sings has the header "N S", S the number of singularities of the
#   summary, then S lines "vertex numerator" with a vertex of the mesh, as
#   many positive and negative indices as the summary counts, and the sum of
#   indices it gives;
# - the .vtk has the mesh's V points, one cell per face and per singularity,
#   and the N root vectors;
# - the map's OBJ has one face per face of the mesh and one texture
#   coordinate per corner;
# - the quad mesh (.off, .obj, and its .quads.vtk) has the summary's number of
#   vertices and of quads, every face a quad but the trimmed boundary polygons
#   the summary counts;
# - every file the summary says it wrote exists;
# - stdout says expect_stdout, matches the regex expect_stdout_regex, and does
#   not say reject_stdout, when the case sets them.
#
# Constraint files are written in the program's format: one constrained face
# per line, "face_id x1 y1 z1 [x2 y2 z2 ...]", vectors in world coordinates,
# face ids 0-based in file order; lines starting with '#' are comments.

cmake_minimum_required(VERSION 3.16)

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
  set(expect_degree 4)
  set(expect_faces 12)
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
  set(expect_degree 4)
  set(expect_faces ${bumpy_faces})
elseif(CASE STREQUAL "sharp_edges_fandisk")
  # Partial constraints along the feature lines of fandisk
  # (select_sharp_edge_constraints()): faces with one sharp edge get one
  # vector, faces with two or more get a full frame.
  set(args --mesh "${DATA_DIR}/fandisk.off" --degree 4 --sign-symmetric --sharp-edges 30)
  set(expect_success TRUE)
  set(expect_degree 4)
  set(expect_faces 14454)
  set(expect_stdout " from sharp edges), hard")
elseif(CASE STREQUAL "amg_bumpy")
  # The multigrid solver asked for on a mesh the default would give the
  # direct solver: it runs, converges, and says so.
  set(args --mesh "${bumpy}" --sign-symmetric --random-constraints 25 --solver amg)
  set(expect_success TRUE)
  set(expect_degree 4)
  set(expect_faces ${bumpy_faces})
  set(expect_stdout "solver          multigrid-preconditioned conjugate gradient: ")
elseif(CASE STREQUAL "parametrize_bumpy")
  # A frame field from 1% curvature constraints and the integer-grid map it
  # guides, written as OBJ with one texture coordinate per corner.
  set(args --mesh "${bumpy}" --curvature-constraints 1 --parametrize --out-param "${WORK_DIR}/map.obj")
  list(APPEND outputs "${WORK_DIR}/map.obj")
  set(expect_success TRUE)
  set(expect_degree 4)
  set(expect_faces ${bumpy_faces})
  set(expect_stdout " 0 flipped faces")
elseif(CASE STREQUAL "planar_quads_inspired")
  # The paper's pipeline on its architectural input: conjugate field, map at
  # the paper's quad size, quad mesh, planarized to 1%.
  set(args --conjugate --edge-length 0.82 --quad-mesh "${WORK_DIR}/quads.off" --planarize)
  list(APPEND outputs "${WORK_DIR}/quads.off" "${WORK_DIR}/out.quads.vtk")
  set(expect_success TRUE)
  set(expect_degree 4)
  set(expect_faces 4288)
  set(expect_stdout "-> after ")
elseif(CASE STREQUAL "planarize_bumpy")
  # Quads of a conjugate field on bumpy (1% curvature constraints): the
  # local-global iterations stop with a vertex too far from the surface, and
  # the second method (Gauss-Newton steps, on by default) reaches 1% within
  # the bound, folding no quad.
  set(args --mesh "${bumpy}" --curvature-constraints 1 --conjugate --quad-mesh "${WORK_DIR}/quads.off" --planarize)
  list(APPEND outputs "${WORK_DIR}/quads.off" "${WORK_DIR}/out.quads.vtk")
  set(expect_success TRUE)
  set(expect_degree 4)
  set(expect_faces ${bumpy_faces})
  set(expect_stdout "(they left the surface) and ")
elseif(CASE STREQUAL "planarize_bumpy_without_gauss_newton")
  # The same run with --gauss-newton-steps 0: the local-global failure is
  # reported as it is, the quads are written as extracted, and no
  # Gauss-Newton step is taken.
  set(args --mesh "${bumpy}" --curvature-constraints 1 --conjugate --quad-mesh "${WORK_DIR}/quads.off" --planarize
           --gauss-newton-steps 0)
  list(APPEND outputs "${WORK_DIR}/quads.off" "${WORK_DIR}/out.quads.vtk")
  set(expect_success TRUE)
  set(expect_degree 4)
  set(expect_faces ${bumpy_faces})
  set(expect_stdout "with the pull towards the surface at its floor: the quad mesh is written as extracted")
  set(reject_stdout "Gauss-Newton")
elseif(CASE STREQUAL "default_size_made_finer_knight")
  # libigl's decimated knight (1000 faces) at the default quad size. How far
  # the quads are from the surface does not fall with every finer size: 1.76%,
  # 2.21%, 1.09%, then 0.60% of the bounding-box diagonal at the first four,
  # for the default bound of 0.9%. Stopping at the first size that brought the
  # quads no closer split the whole knight into quads on its triangles (5127
  # irregular vertices); on a mesh of one component the sizes now go on past
  # one such size, and the quads come within the bound.
  set(args --mesh "${DATA_DIR}/decimated-knight.off" --curvature-constraints 1 --quad-mesh "${WORK_DIR}/quads.off")
  list(APPEND outputs "${WORK_DIR}/quads.off" "${WORK_DIR}/out.quads.vtk")
  set(expect_success TRUE)
  set(expect_degree 4)
  set(expect_stdout "the default made finer")
  set(expect_stdout_regex "every input point within 0\\.[0-8][0-9]*% of the bounding-box diagonal")
  set(reject_stdout "split into quads")
elseif(CASE STREQUAL "default_run")
  # The README's main command: no arguments, the bundled run, writing into
  # output/ of the working directory.
  set(args "")
  set(output_args "")
  set(expect_success TRUE)
  set(expect_degree 4)
  set(expect_faces 4288)
else()
  message(FATAL_ERROR "cli_checks.cmake: unknown case '${CASE}'")
endif()

# ---------------------------------------------------------------------------
# The outputs of a success case, read back and compared with the summary.
# ---------------------------------------------------------------------------
function(pvf_fail message)
  message(FATAL_ERROR "${message}")
endfunction()

# The number `name` the summary line matched by `regex` gives (group `group`).
function(pvf_summary_number summary regex group result)
  if(NOT summary MATCHES "${regex}")
    pvf_fail("the summary has no line matching '${regex}':\n${summary}")
  endif()
  set(${result} "${CMAKE_MATCH_${group}}" PARENT_SCOPE)
endfunction()

# The lines of a file, empty lines dropped.
function(pvf_read_lines file result)
  file(STRINGS "${file}" lines)
  list(FILTER lines EXCLUDE REGEX "^[ \t\r]*$")
  set(${result} "${lines}" PARENT_SCOPE)
endfunction()

function(pvf_check_rawfield file N F)
  pvf_read_lines("${file}" lines)
  list(LENGTH lines count)
  math(EXPR expected "${F} + 1")
  if(NOT count EQUAL expected)
    pvf_fail("${file}: ${count} lines, expected the header and ${F} faces")
  endif()
  list(GET lines 0 header)
  if(NOT header MATCHES "^${N} ${F}$")
    pvf_fail("${file}: header '${header}', expected '${N} ${F}'")
  endif()
  list(REMOVE_AT lines 0)
  math(EXPR numbers "3 * ${N}")
  set(face 0)
  foreach(line IN LISTS lines)
    string(REGEX MATCHALL "[^ \t]+" tokens "${line}")
    list(LENGTH tokens n)
    if(NOT n EQUAL numbers)
      pvf_fail("${file}: face ${face} has ${n} numbers, expected ${numbers} (${N} vectors)")
    endif()
    foreach(token IN LISTS tokens)
      if(NOT token MATCHES "^-?[0-9]+(\\.[0-9]+)?([eE][-+]?[0-9]+)?$")
        pvf_fail("${file}: face ${face}: '${token}' is not a finite number")
      endif()
    endforeach()
    math(EXPR face "${face} + 1")
  endforeach()
  message(STATUS "checked ${file}: ${F} faces of ${N} vectors")
endfunction()

function(pvf_check_sings file N V S positive negative sum)
  pvf_read_lines("${file}" lines)
  list(LENGTH lines count)
  math(EXPR expected "${S} + 1")
  if(NOT count EQUAL expected)
    pvf_fail("${file}: ${count} lines, expected the header and the summary's ${S} singularities")
  endif()
  list(GET lines 0 header)
  if(NOT header MATCHES "^${N} ${S}$")
    pvf_fail("${file}: header '${header}', expected '${N} ${S}'")
  endif()
  list(REMOVE_AT lines 0)
  set(p 0)
  set(n 0)
  set(total 0)
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "^([0-9]+) (-?[0-9]+)$")
      pvf_fail("${file}: '${line}' is not 'vertex numerator'")
    endif()
    set(vertex "${CMAKE_MATCH_1}")
    set(numerator "${CMAKE_MATCH_2}")
    if(NOT vertex LESS V OR numerator EQUAL 0)
      pvf_fail("${file}: '${line}': vertex not in the mesh's ${V}, or a zero index")
    endif()
    if(numerator GREATER 0)
      math(EXPR p "${p} + 1")
    else()
      math(EXPR n "${n} + 1")
    endif()
    math(EXPR total "${total} + ${numerator}")
  endforeach()
  if(NOT p EQUAL positive OR NOT n EQUAL negative OR NOT total EQUAL sum)
    pvf_fail("${file}: ${p} positive, ${n} negative, sum ${total}; the summary says ${positive}, ${negative}, ${sum}")
  endif()
  message(STATUS "checked ${file}: ${S} singularities, sum of indices ${sum}/${N}")
endfunction()

function(pvf_check_field_vtk file N V F S)
  file(READ "${file}" text)
  math(EXPR cells "${F} + ${S}")
  math(EXPR last "${N} - 1")
  foreach(expected "\nPOINTS ${V} double\n" "\nCELLS ${cells} " "\nCELL_DATA ${cells}\n" "\nVECTORS root_0 double\n"
                   "\nVECTORS root_${last} double\n")
    string(FIND "${text}" "${expected}" at)
    if(at EQUAL -1)
      string(STRIP "${expected}" shown)
      pvf_fail("${file}: no '${shown}' (${V} vertices, ${F} faces, ${S} singularities, ${N} vectors)")
    endif()
  endforeach()
  string(FIND "${text}" "\nVECTORS root_${N} " at)
  if(NOT at EQUAL -1)
    pvf_fail("${file}: more than ${N} root vectors per face")
  endif()
  # As many constrained faces as the summary says.
  set(flags_header "\nSCALARS is_constrained int 1\nLOOKUP_TABLE default\n")
  string(FIND "${text}" "${flags_header}" at)
  if(at EQUAL -1)
    pvf_fail("${file}: no is_constrained array")
  endif()
  string(LENGTH "${flags_header}" length)
  math(EXPR at "${at} + ${length}")
  string(SUBSTRING "${text}" ${at} -1 flags)
  string(REGEX MATCHALL "[^\n]+" flags "${flags}")
  list(SUBLIST flags 0 ${cells} flags)
  list(FILTER flags INCLUDE REGEX "^1$")
  list(LENGTH flags flagged)
  if(NOT flagged EQUAL constrained)
    pvf_fail("${file}: ${flagged} constrained faces, the summary says ${constrained}")
  endif()
  message(STATUS "checked ${file}: ${V} points, ${cells} cells, ${N} root vectors, ${constrained} constrained faces")
endfunction()

function(pvf_check_param_obj file F)
  pvf_read_lines("${file}" lines)
  set(faces 0)
  set(texture 0)
  foreach(line IN LISTS lines)
    if(line MATCHES "^vt ")
      math(EXPR texture "${texture} + 1")
    elseif(line MATCHES "^f ")
      if(NOT line MATCHES "^f [0-9]+/[0-9]+ [0-9]+/[0-9]+ [0-9]+/[0-9]+$")
        pvf_fail("${file}: '${line}' is not a triangle with a texture coordinate per corner")
      endif()
      math(EXPR faces "${faces} + 1")
    endif()
  endforeach()
  math(EXPR corners "3 * ${F}")
  if(NOT faces EQUAL F OR NOT texture EQUAL corners)
    pvf_fail("${file}: ${faces} faces and ${texture} texture coordinates, expected ${F} and ${corners}")
  endif()
  message(STATUS "checked ${file}: ${F} faces, ${corners} corners")
endfunction()

# The quad mesh, .off or .obj: `vertices` vertices, `quads` quads and `trimmed` other polygons.
function(pvf_check_quad_mesh file vertices quads trimmed)
  pvf_read_lines("${file}" lines)
  set(v 0)
  set(q 0)
  set(other 0)
  if(file MATCHES "\\.off$")
    list(GET lines 0 magic)
    list(GET lines 1 header)
    if(NOT magic STREQUAL "OFF" OR NOT header MATCHES "^([0-9]+) ([0-9]+) ")
      pvf_fail("${file}: not an OFF file")
    endif()
    set(v "${CMAKE_MATCH_1}")
    set(declared "${CMAKE_MATCH_2}")
    list(SUBLIST lines 2 -1 body)
    set(i 0)
    foreach(line IN LISTS body)
      if(i GREATER_EQUAL v)
        string(REGEX MATCHALL "[^ \t]+" tokens "${line}")
        list(GET tokens 0 k)
        list(LENGTH tokens n)
        math(EXPR n "${n} - 1")
        if(NOT n EQUAL k)
          pvf_fail("${file}: face line '${line}' announces ${k} vertices")
        endif()
        if(k EQUAL 4)
          math(EXPR q "${q} + 1")
        else()
          math(EXPR other "${other} + 1")
        endif()
      endif()
      math(EXPR i "${i} + 1")
    endforeach()
    math(EXPR read "${q} + ${other}")
    if(NOT read EQUAL declared)
      pvf_fail("${file}: the header announces ${declared} faces, the file has ${read}")
    endif()
  else()
    foreach(line IN LISTS lines)
      if(line MATCHES "^v ")
        math(EXPR v "${v} + 1")
      elseif(line MATCHES "^f ")
        string(REGEX MATCHALL "[^ \t]+" tokens "${line}")
        list(LENGTH tokens n)
        if(n EQUAL 5)
          math(EXPR q "${q} + 1")
        else()
          math(EXPR other "${other} + 1")
        endif()
      endif()
    endforeach()
  endif()
  if(NOT v EQUAL vertices OR NOT q EQUAL quads OR NOT other EQUAL trimmed)
    pvf_fail("${file}: ${v} vertices, ${q} quads and ${other} other faces; the summary says ${vertices}, ${quads}, ${trimmed}")
  endif()
  message(STATUS "checked ${file}: ${v} vertices, ${q} quads, ${other} trimmed polygons")
endfunction()

function(pvf_check_quad_vtk file vertices polygons)
  file(READ "${file}" text)
  foreach(expected "\nPOINTS ${vertices} double\n" "\nPOLYGONS ${polygons} " "\nCELL_DATA ${polygons}\n"
                   "\nSCALARS planarity double 1\n")
    string(FIND "${text}" "${expected}" at)
    if(at EQUAL -1)
      string(STRIP "${expected}" shown)
      pvf_fail("${file}: no '${shown}' (${vertices} vertices, ${polygons} polygons)")
    endif()
  endforeach()
  message(STATUS "checked ${file}: ${vertices} points, ${polygons} polygons")
endfunction()

# Reads the summary, then checks each output against it (by its kind).
function(pvf_check_outputs summary outputs)
  pvf_summary_number("${summary}" "\nmesh [^\n]*: ([0-9]+) faces, ([0-9]+) vertices" 1 F)
  pvf_summary_number("${summary}" "\nmesh [^\n]*: ([0-9]+) faces, ([0-9]+) vertices" 2 V)
  pvf_summary_number("${summary}" "\nfield +degree ([0-9]+)" 1 N)
  pvf_summary_number("${summary}" "\nconstraints +([0-9]+) faces" 1 constrained)
  set(sings_regex "\nsingularities +([0-9]+) \\(([0-9]+) positive, ([0-9]+) negative\\), sum of indices (-?[0-9]+)/([0-9]+)")
  pvf_summary_number("${summary}" "${sings_regex}" 1 S)
  pvf_summary_number("${summary}" "${sings_regex}" 2 positive)
  pvf_summary_number("${summary}" "${sings_regex}" 3 negative)
  pvf_summary_number("${summary}" "${sings_regex}" 4 sum)
  if(DEFINED expect_degree AND NOT N EQUAL expect_degree)
    pvf_fail("the summary says degree ${N}, expected ${expect_degree}")
  endif()
  if(DEFINED expect_faces AND NOT F EQUAL expect_faces)
    pvf_fail("the summary says ${F} faces, expected ${expect_faces}")
  endif()
  set(quad_regex "\nquad mesh +([0-9]+) quads( and ([0-9]+) trimmed boundary polygons)?, ([0-9]+) vertices")
  set(checked 0)
  foreach(file IN LISTS outputs)
    if(file MATCHES "\\.rawfield$")
      pvf_check_rawfield("${file}" ${N} ${F})
    elseif(file MATCHES "\\.sings$")
      pvf_check_sings("${file}" ${N} ${V} ${S} ${positive} ${negative} ${sum})
    elseif(file MATCHES "\\.quads\\.vtk$" OR file MATCHES "(\\.off|quads\\.obj)$")
      pvf_summary_number("${summary}" "${quad_regex}" 1 quads)
      pvf_summary_number("${summary}" "${quad_regex}" 4 quad_vertices)
      set(trimmed 0)
      if(summary MATCHES "${quad_regex}" AND NOT "${CMAKE_MATCH_3}" STREQUAL "")
        set(trimmed "${CMAKE_MATCH_3}")
      endif()
      if(file MATCHES "\\.vtk$")
        math(EXPR polygons "${quads} + ${trimmed}")
        pvf_check_quad_vtk("${file}" ${quad_vertices} ${polygons})
      else()
        pvf_check_quad_mesh("${file}" ${quad_vertices} ${quads} ${trimmed})
      endif()
    elseif(file MATCHES "\\.vtk$")
      pvf_check_field_vtk("${file}" ${N} ${V} ${F} ${S})
    elseif(file MATCHES "\\.obj$")
      pvf_check_param_obj("${file}" ${F})
    else()
      pvf_fail("no check for the output ${file}")
    endif()
    math(EXPR checked "${checked} + 1")
  endforeach()
  # Every file the summary says it wrote exists (relative to the working directory).
  string(REGEX MATCHALL "\nwrote +[^\n]+" wrote "${summary}")
  list(LENGTH wrote written)
  if(NOT written EQUAL checked)
    pvf_fail("the summary lists ${written} files, the case expects ${checked}:\n${summary}")
  endif()
  foreach(line IN LISTS wrote)
    string(REGEX REPLACE "^\nwrote +" "" path "${line}")
    if(NOT IS_ABSOLUTE "${path}")
      set(path "${WORK_DIR}/${path}")
    endif()
    if(NOT EXISTS "${path}")
      pvf_fail("the summary says it wrote ${path}, which does not exist")
    endif()
  endforeach()
endfunction()

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
  if(DEFINED expect_stdout_regex)
    if(NOT out MATCHES "${expect_stdout_regex}")
      message(FATAL_ERROR "stdout does not match '${expect_stdout_regex}'\nstdout:\n${out}")
    endif()
  endif()
  if(DEFINED reject_stdout)
    string(FIND "${out}" "${reject_stdout}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "stdout says '${reject_stdout}', which it should not\nstdout:\n${out}")
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
  pvf_check_outputs("\n${out}" "${outputs}")
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
# Nothing is written on a failure, and the summary (printed when a late stage
# fails) does not say otherwise.
string(REGEX MATCHALL "wrote +[^\n]*" claims "${out}")
foreach(claim IN LISTS claims)
  if(NOT claim MATCHES "^wrote +nothing: ")
    message(FATAL_ERROR "the run failed, yet its summary says '${claim}'\nstdout:\n${out}")
  endif()
endforeach()
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
