# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

# Checks that the code fragments the user manual quotes still exist: Doxygen
# silently shows nothing when a \skip or \until pattern is not found in an
# example. For each `\dontinclude FILE`, the following `\skip P` and `\until P`
# patterns must occur in FILE in that order; each `\cgalExample{FILE}` must exist.
# FILE is looked for in EXAMPLES, then in TOOLS if given (Doxygen's EXAMPLE_PATH).
#   cmake -DMANUAL=doc/Polyvector_fields/Polyvector_fields.txt -DEXAMPLES=examples [-DTOOLS=tools] -P check_snippets.cmake

if(NOT MANUAL OR NOT EXAMPLES)
  message(FATAL_ERROR "usage: cmake -DMANUAL=<manual.txt> -DEXAMPLES=<examples folder> -P check_snippets.cmake")
endif()

# The path of a quoted file: in EXAMPLES, else in TOOLS, else in EXAMPLES (missing).
function(pvf_quoted_file name result)
  set(path "${EXAMPLES}/${name}")
  if(NOT EXISTS "${path}" AND TOOLS AND EXISTS "${TOOLS}/${name}")
    set(path "${TOOLS}/${name}")
  endif()
  set(${result} "${path}" PARENT_SCOPE)
endfunction()

# The manual is walked line by line with string(FIND): lines hold ';' and '[',
# which CMake lists would split or group.
cmake_policy(SET CMP0007 NEW)
file(READ "${MANUAL}" manual)
set(failures 0)
set(checked 0)
set(rest "")
set(current "")
while(NOT manual STREQUAL "")
  string(FIND "${manual}" "\n" eol)
  if(eol EQUAL -1)
    set(line "${manual}")
    set(manual "")
  else()
    string(SUBSTRING "${manual}" 0 ${eol} line)
    math(EXPR next "${eol} + 1")
    string(SUBSTRING "${manual}" ${next} -1 manual)
  endif()
  string(FIND "${line}" "\\cgalExample{" example_at)
  if(NOT example_at EQUAL -1)
    string(REGEX REPLACE ".*\\\\cgalExample\\{([^}]+)\\}.*" "\\1" example "${line}")
    pvf_quoted_file("${example}" example_path)
    if(NOT EXISTS "${example_path}")
      message(SEND_ERROR "${MANUAL}: \\cgalExample{${example}}: no such file in ${EXAMPLES}")
      math(EXPR failures "${failures} + 1")
    endif()
  elseif(line MATCHES "^\\\\dontinclude[ \t]")
    string(REGEX REPLACE "^\\\\dontinclude[ \t]+" "" current "${line}")
    string(STRIP "${current}" current)
    pvf_quoted_file("${current}" current_path)
    if(EXISTS "${current_path}")
      file(READ "${current_path}" rest)
    else()
      message(SEND_ERROR "${MANUAL}: \\dontinclude ${current}: no such file in ${EXAMPLES}")
      math(EXPR failures "${failures} + 1")
      set(rest "")
    endif()
  elseif(line MATCHES "^\\\\(skip|until)[ \t]")
    set(command "${CMAKE_MATCH_1}")
    string(REGEX REPLACE "^\\\\(skip|until)[ \t]+" "" pattern "${line}")
    string(STRIP "${pattern}" pattern)
    string(FIND "${rest}" "${pattern}" at)
    if(at EQUAL -1)
      message(SEND_ERROR "${MANUAL}: \\${command} '${pattern}' is not found in ${current} after the previous pattern")
      math(EXPR failures "${failures} + 1")
    else()
      string(LENGTH "${pattern}" length)
      math(EXPR after "${at} + ${length}")
      string(SUBSTRING "${rest}" ${after} -1 rest)
      math(EXPR checked "${checked} + 1")
    endif()
  endif()
endwhile()

if(failures GREATER 0)
  message(FATAL_ERROR "${failures} quoted fragment(s) of the examples are missing")
endif()
message(STATUS "all ${checked} \\skip/\\until patterns quoted by ${MANUAL} are found")
