# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

# The test of check_quad_mesh:
#   cmake -DCHECKER=... -DWORK_DIR=... -P check_quad_mesh_test.cmake
# It writes small meshes (a unit cube, a square) and quad meshes made from
# them, valid ones and broken ones, runs the checker on each pair and asserts
# its exit status and the lines that must say ok or FAIL.

cmake_minimum_required(VERSION 3.16)

foreach(var CHECKER WORK_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "check_quad_mesh_test.cmake: -D${var}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# The unit cube, outward faces: as 12 triangles (the input) and as 6 quads.
set(cube_points "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n")
set(cube_quads "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n")
set(cube_triangles "3 0 3 2\n3 0 2 1\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n\
3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n")
file(WRITE "${WORK_DIR}/cube.off" "OFF\n8 12 0\n${cube_points}${cube_triangles}")
file(WRITE "${WORK_DIR}/cube_quads.off" "OFF\n8 6 0\n${cube_points}${cube_quads}")
# The triangles given as the quad mesh.
file(WRITE "${WORK_DIR}/cube_triangles_as_quads.off" "OFF\n8 12 0\n${cube_points}${cube_triangles}")
# Every quad reversed: a consistent mesh that faces inwards.
file(WRITE "${WORK_DIR}/cube_quads_reversed.off"
     "OFF\n8 6 0\n${cube_points}4 1 2 3 0\n4 7 6 5 4\n4 4 5 1 0\n4 5 6 2 1\n4 6 7 3 2\n4 7 4 0 3\n")
# One quad reversed (the bottom one).
file(WRITE "${WORK_DIR}/cube_one_quad_flipped.off"
     "OFF\n8 6 0\n${cube_points}4 1 2 3 0\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n")
# The quads moved away from the cube by 0.3 along x.
file(WRITE "${WORK_DIR}/cube_quads_moved.off"
     "OFF\n8 6 0\n0.3 0 0\n1.3 0 0\n1.3 1 0\n0.3 1 0\n0.3 0 1\n1.3 0 1\n1.3 1 1\n0.3 1 1\n${cube_quads}")
# The top quad missing: an open box on a closed cube.
file(WRITE "${WORK_DIR}/cube_quads_open.off"
     "OFF\n8 5 0\n${cube_points}4 0 3 2 1\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n")
# Two cubes (the second at x + 3) as input, the quads of the first one only.
set(second_cube_points "3 0 0\n4 0 0\n4 1 0\n3 1 0\n3 0 1\n4 0 1\n4 1 1\n3 1 1\n")
set(second_cube_triangles "3 8 11 10\n3 8 10 9\n3 12 13 14\n3 12 14 15\n3 8 9 13\n3 8 13 12\n\
3 9 10 14\n3 9 14 13\n3 10 11 15\n3 10 15 14\n3 11 8 12\n3 11 12 15\n")
file(WRITE "${WORK_DIR}/two_cubes.off"
     "OFF\n16 24 0\n${cube_points}${second_cube_points}${cube_triangles}${second_cube_triangles}")

# The square [0,2]^2 as two triangles, and a 2x2 grid of quads on it.
file(WRITE "${WORK_DIR}/square.off" "OFF\n4 2 0\n0 0 0\n2 0 0\n2 2 0\n0 2 0\n3 0 1 2\n3 0 2 3\n")
set(grid_points "0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n")
set(grid_quads "4 0 1 4 3\n4 1 2 5 4\n4 3 4 7 6\n4 4 5 8 7\n")
file(WRITE "${WORK_DIR}/grid.off" "OFF\n9 4 0\n${grid_points}${grid_quads}")
# The same grid with its centre vertex pushed to (1.9, 1.9): the top-right
# quad becomes a dart, whose split along one diagonal is folded.
file(WRITE "${WORK_DIR}/grid_dart.off"
     "OFF\n9 4 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1.9 1.9 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n${grid_quads}")
# Only the bottom-left quad: on the surface, but covering a quarter of it.
file(WRITE "${WORK_DIR}/grid_quarter.off" "OFF\n9 1 0\n${grid_points}4 0 1 4 3\n")

# Runs the checker on INPUT and QUADS with extra arguments; asserts the exit
# status and that each regex of ARGN matches its output.
function(check name input quads extra expected_status)
  set(command "${CHECKER}" "${WORK_DIR}/${input}" "${WORK_DIR}/${quads}")
  if(NOT extra STREQUAL "")
    separate_arguments(extra_list UNIX_COMMAND "${extra}")
    list(APPEND command ${extra_list})
  endif()
  execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status STREQUAL "${expected_status}")
    message(FATAL_ERROR "${name}: exit status '${status}', expected ${expected_status}\n${out}${err}")
  endif()
  foreach(regex IN LISTS ARGN)
    if(NOT "${out}${err}" MATCHES "${regex}")
      message(FATAL_ERROR "${name}: the output does not match '${regex}':\n${out}${err}")
    endif()
  endforeach()
  message(STATUS "${name}: ok")
endfunction()

# Valid: the cube's own quads. 8 corners of valence 3, area and Hausdorff
# exact, and the 12 box edges (the only ones above 40 degrees: the diagonals
# of the triangulation are flat) lie on quad edges.
check(valid_cube cube.off cube_quads.off "--sharp-edges 40" 0
      "all_quads: 6 faces, 0 not quads \\(ok\\)"
      "manifold: 0 non-manifold edges, 0 edges with inconsistent orientation, 0 non-manifold vertices, 0 faces with a repeated vertex \\(ok\\)"
      "components: input 1, quads 1 \\(ok\\)"
      "euler: 1 closed component\\(s\\) compared, 0 mismatch\\(es\\) \\(ok\\)"
      "on_surface: max distance 0 bbox diagonal .*, 0 vertices beyond"
      "folded: 0 of 6 quads"
      "area_ratio: 1 \\("
      "hausdorff: [^\n]*: 0 bbox diagonal \\(ok"
      "boundary_edges: 0 input boundary edges"
      "sharp_edges: 12 interior input edges above 40 degrees; 100% of their 60 samples [^\n]*; 12 edges covered entirely"
      "statistics: 6 faces, 8 vertices \\(0 on the boundary\\), 8 irregular interior vertices"
      "summary valid=1 failed=none quads=6 non_quads=0 vertices=8 input_components=1 quad_components=1 irregular_interior=8 irregular_boundary=0 area_ratio=1 hausdorff=0 sharp_edges=12 sharp_coverage=1 sharp_edges_covered=12")
# Valid: a 2x2 grid on a square. Boundary vertices at the corners (one quad,
# 90 degrees) and along the sides (two quads, 180 degrees) are regular.
check(valid_grid square.off grid.off "--min-area-ratio 0.98" 0
      "euler: 0 closed component\\(s\\) compared, 0 mismatch\\(es\\); 1 open component\\(s\\), 0 with another chi"
      "boundary_edges: 4 input boundary edges; 100% of their 20 samples [^\n]*; 4 edges covered entirely"
      "statistics: 4 faces, 9 vertices \\(8 on the boundary\\), 0 irregular interior vertices \\(valence != 4\\), 0 irregular boundary vertices"
      "summary valid=1 ")

# Invalid ones.
check(triangles_as_quads cube.off cube_triangles_as_quads.off "" 1
      "all_quads: 12 faces, 12 not quads \\(FAIL"
      "summary valid=0 failed=all_quads ")
check(reversed_quads cube.off cube_quads_reversed.off "" 1
      "manifold: [^\n]*\\(ok\\)"
      "folded: 6 of 6 quads [^\n]*: 6 reversed, 6 along both diagonals, 0 along one diagonal only [^\n]*\\(FAIL"
      "summary valid=0 failed=folded ")
check(one_quad_flipped cube.off cube_one_quad_flipped.off "" 1
      "manifold: 0 non-manifold edges, 4 edges with inconsistent orientation[^\n]*\\(FAIL"
      "folded: 1 of 6 quads [^\n]*: 1 reversed, 1 along both diagonals, 0 along one [^\n]*\\(FAIL")
check(moved_quads cube.off cube_quads_moved.off "" 1
      "on_surface: [^\n]* 4 vertices beyond [^\n]*\\(FAIL"
      "hausdorff: [^\n]*\\(FAIL")
check(open_box_on_closed_cube cube.off cube_quads_open.off "" 1
      "euler: 1 closed component\\(s\\) compared, 1 mismatch\\(es\\) \\(FAIL: input component 0 closed, chi 2, its quads open, chi 1"
      "hausdorff: [^\n]*\\(FAIL")
check(missing_component two_cubes.off cube_quads.off "" 1
      "components: input 2, quads 1 \\(FAIL: input component 1 \\(12 triangles\\) has 0 quad components"
      "hausdorff: [^\n]*\\(FAIL")
# A dart is reported, not failed: its other diagonal splits it into two triangles
# that face the right way.
check(dart grid_dart.off grid_dart.off "" 0
      "folded: 1 of 4 quads [^\n]*: 0 reversed, 0 along both diagonals, 1 along one diagonal only [^\n]*\\(ok")
check(quarter_covered square.off grid_quarter.off "--min-area-ratio 0.98 --max-hausdorff 0.01" 1
      "area_ratio: 0.25 [^\n]*\\(FAIL: bar >= 0.98"
      "manifold: [^\n]*\\(ok\\)"
      "boundary_edges: 4 input boundary edges; 30% of their 20 samples"
      "statistics: [^\n]*, 5 unreferenced points"
      "hausdorff: [^\n]*\\(FAIL")
# A planarized-style tolerance: the moved cube passes "on_surface" within
# one mean quad edge, and still fails the Hausdorff bar.
check(edge_relative_tolerance cube.off cube_quads_moved.off "--distance-tolerance-edge 1" 1
      "on_surface: [^\n]* 0 vertices beyond [^\n]*\\(ok"
      "summary valid=0 failed=hausdorff ")

# Planarity: the 2x2 grid with its centre vertex lifted by 0.1. Each quad's
# diagonals, (1,1,0.1) and (-1,1,0) from a corner one edge apart, are
# 0.1 / |(-0.1,-0.1,2)| = 0.049875 apart, over a mean diagonal length of
# (sqrt(2.01) + sqrt(2)) / 2 = 1.415979: planarity 0.035223 for all four.
file(WRITE "${WORK_DIR}/grid_lifted.off"
     "OFF\n9 4 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0.1\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n${grid_quads}")
check(planarity_reported square.off grid.off "" 0
      "planarity: max 0, mean 0 \\(diagonal distance over mean diagonal, 4 quads\\)")
check(planar_within_bound square.off grid_lifted.off
      "--distance-tolerance-edge 1 --max-hausdorff 0.1 --max-planarity 0.0353" 0
      "planar: max 0.03522[0-9]*, mean 0.03522[0-9]* \\(diagonal distance over mean diagonal, 4 quads\\), 0 beyond 0.0353 \\(ok")
check(not_planar_enough square.off grid_lifted.off
      "--distance-tolerance-edge 1 --max-hausdorff 0.1 --max-planarity 0.0352" 1
      "planar: [^\n]*, 4 beyond 0.0352 \\(FAIL: bound 0.0352"
      "summary valid=0 failed=planar ")

# A tent whose crease bends: (0,0,1) (1,0.05,1) (2,0,1), with planar sides
# going down to z = 0 one unit away. Two quads whose middle edge is the chord
# (0,0,1)-(2,0,1) of the crease: the samples of the crease are 0.05 x (x <= 1)
# off the chord, so only 4 of 10 are within 1% of the mean quad edge (1.665),
# but all 10 are traced (the chord's ends are on the crease, and they are
# within a quarter of its length); largest sagitta 0.045 / 1.665 = 0.027.
# Moved to y = 0.3, the same chord has no end on the crease: nothing is traced.
set(tent_points "0 0 1\n1 0.05 1\n2 0 1\n0 -1 0\n1 -0.95 0\n2 -1 0\n0 1 0\n1 1.05 0\n2 1 0\n")
file(WRITE "${WORK_DIR}/bent_crease.off" "OFF\n9 8 0\n${tent_points}\
3 0 3 4\n3 0 4 1\n3 1 4 5\n3 1 5 2\n3 0 1 7\n3 0 7 6\n3 1 2 8\n3 1 8 7\n")
file(WRITE "${WORK_DIR}/bent_crease_chords.off"
     "OFF\n6 2 0\n0 -1 0\n2 -1 0\n2 0 1\n0 0 1\n2 1 0\n0 1 0\n4 0 1 2 3\n4 3 2 4 5\n")
file(WRITE "${WORK_DIR}/bent_crease_beside.off"
     "OFF\n6 2 0\n0 -1 0\n2 -1 0\n2 0.3 0.7\n0 0.3 0.7\n2 1 0\n0 1 0\n4 0 1 2 3\n4 3 2 4 5\n")
check(crease_traced_by_chords bent_crease.off bent_crease_chords.off "--sharp-edges 40 --max-hausdorff 0.05" 0
      "sharp_edges: 2 interior input edges above 40 degrees; 40% of their 10 samples [^\n]*; 0 edges covered entirely; 100% traced [^\n]*largest sagitta 0.027"
      "sharp_coverage=0.4 sharp_edges_covered=0 sharp_traced=1 ")
check(crease_beside_the_quads bent_crease.off bent_crease_beside.off "--sharp-edges 40" 1
      "sharp_edges: 2 interior input edges above 40 degrees; 0% of their 10 samples [^\n]*; 0% traced"
      "sharp_coverage=0 sharp_edges_covered=0 sharp_traced=0 ")
# Bent more, (0,0,1) (1,0.6,1) (2,0,1) (crease 81 degrees, side pieces 46):
# the samples are 0.6 x off the same chord, and the last one of each edge
# (0.54) is beyond a quarter of it (0.5): 8 of 10 traced, none covered (the
# flat quads are folded against the steep input there, a failure of its own).
set(steep_tent_points "0 0 1\n1 0.6 1\n2 0 1\n0 -1 0\n1 -0.4 0\n2 -1 0\n0 1 0\n1 1.6 0\n2 1 0\n")
file(WRITE "${WORK_DIR}/steep_crease.off" "OFF\n9 8 0\n${steep_tent_points}\
3 0 3 4\n3 0 4 1\n3 1 4 5\n3 1 5 2\n3 0 1 7\n3 0 7 6\n3 1 2 8\n3 1 8 7\n")
check(crease_beyond_a_quarter_of_the_chord steep_crease.off bent_crease_chords.off
      "--sharp-edges 60 --max-hausdorff 0.5" 1
      "sharp_edges: 2 interior input edges above 60 degrees; 0% of their 10 samples [^\n]*; 80% traced"
      "summary valid=0 failed=folded "
      "sharp_coverage=0 sharp_edges_covered=0 sharp_traced=0.8 ")

# Unreadable input and bad command lines: status 2.
check(missing_file cube.off no_such_file.off "" 2 "QUADS '[^']*no_such_file.off' cannot be opened")
file(WRITE "${WORK_DIR}/garbage.off" "this is not a mesh\n")
check(garbage_input garbage.off cube_quads.off "" 2 "INPUT '[^']*garbage.off' is not a readable mesh")
check(unknown_option cube.off cube_quads.off "--frobnicate 3" 2 "unknown option --frobnicate")

# --input-only: status 0 for a surface, 2 for three triangles on one edge.
function(check_input_only name input expected_status regex)
  execute_process(COMMAND "${CHECKER}" "${WORK_DIR}/${input}" --input-only
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status STREQUAL "${expected_status}" OR NOT "${out}${err}" MATCHES "${regex}")
    message(FATAL_ERROR "${name}: exit status '${status}' (expected ${expected_status}), "
                        "output expected to match '${regex}':\n${out}${err}")
  endif()
  message(STATUS "${name}: ok")
endfunction()
check_input_only(input_only_cube cube.off 0 "12 triangles, 1 component\\(s\\), 1 closed")
file(WRITE "${WORK_DIR}/book.off"
     "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n")
check_input_only(input_only_book book.off 2 "is not a surface: 1 edges are shared by more than two faces")
