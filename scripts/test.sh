#!/usr/bin/env bash
# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.
#
# Installs what is missing, builds everything in build/ and runs all tests;
# then builds the tests that take untrusted input (label "sanitize": the core
# and io groups and the fuzz corpus replay) again in build-sanitize/ with
# AddressSanitizer and UndefinedBehaviorSanitizer (GCC, -O1 -g1, assertions on) and
# runs them.
# Exits non-zero when anything fails. Works from any directory.
#   bash scripts/test.sh                  everything
#   bash scripts/test.sh --no-sanitizers  only the first part
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

sanitizers=1
for arg in "$@"; do
  case "$arg" in
    --no-sanitizers) sanitizers=0 ;;
    -h|--help) echo "usage: bash scripts/test.sh [--no-sanitizers]"; exit 0 ;;
    *) echo "test.sh: unknown argument '$arg'" >&2; exit 2 ;;
  esac
done

start=$(date +%s)
# Prints how long the step since the last call took, so that CI logs show where the time goes.
step_start=$start
step_done() {
  local now
  now=$(date +%s)
  echo "test.sh: $1 took $(( now - step_start )) s"
  step_start=$now
}
bash scripts/install_dependencies.sh
step_done "installing dependencies"
# The examples as one program (PVF_EXAMPLES_AS_ONE_PROGRAM, see
# examples/Polyvector_fields/CMakeLists.txt): each still runs as its test
# example_NAME, from one translation unit instead of twelve. Measured (g++ 12,
# user+sys CPU of each compile, on the shared 2-core machine): one example
# program alone 82 s (angle_bounded_frame_field) to 186 s (planar_quad_mesh)
# at -O3 with the precompiled header (31 s more, once), planar_quad_mesh 166 s
# at -O1; the twelve as one program at -O1, 192 s.
# The Python module is built for Debian's /usr/bin/python3, for which the
# install script installed numpy and pytest (another python3 may come first
# in PATH, e.g. from pyenv, without them). It adds one translation unit
# (about 170 s of CPU at -O1) and the tests python_tests (about 10 s) and
# python_install.
python_args=()
if [ -x /usr/bin/python3 ]; then
  python_args=(-DPython_EXECUTABLE=/usr/bin/python3)
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON -DPVF_EXAMPLES_AS_ONE_PROGRAM=ON "${python_args[@]}"
cmake --build build -j2
step_done "the release build"
# --no-tests=error: a build that registered no test must not pass silently.
ctest --test-dir build --output-on-failure -j2 --no-tests=error
step_done "the release tests"
echo "test.sh: release build and tests took $(( $(date +%s) - start )) s"

if [ "$sanitizers" = 1 ]; then
  # No build type: no NDEBUG, so CGAL's and Eigen's assertions are on; -O1 keeps
  # the tests fast, and -g1 (line tables only) gives the reports their lines at
  # a quarter less compile time than -g.
  flags="-O1 -g1 -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
  # No precompiled header here: it pays for itself over many translation units
  # (measured: 7% less per test TU), and this build has only three.
  cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE= -DBUILD_TESTING=ON -DPVF_PRECOMPILED_HEADERS=OFF \
        "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined"
  cmake --build build-sanitize -j2 --target pvf_sanitized_tests
  step_done "the sanitizer build"
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-sanitize --output-on-failure -j2 --no-tests=error -L sanitize
  step_done "the sanitizer tests"
  echo "test.sh: everything, sanitizers included, took $(( $(date +%s) - start )) s"
fi
