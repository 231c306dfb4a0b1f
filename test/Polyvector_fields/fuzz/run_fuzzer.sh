#!/usr/bin/env bash
# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.
#
# Runs one libFuzzer program of a PVF_BUILD_FUZZERS=ON build, or minimises its corpus.
#
#   run_fuzzer.sh BUILD_DIR TARGET [RUNS] [libFuzzer options...]
#       fuzzes TARGET for RUNS executions (default 1000000), starting from
#       corpus/TARGET (but its bug_* files); new inputs go to BUILD_DIR/fuzz-work/TARGET/corpus,
#       crashes to BUILD_DIR/fuzz-work/TARGET/artifacts, the log to
#       BUILD_DIR/fuzz-work/TARGET/log.txt. With FORK=1 in the environment,
#       libFuzzer runs in fork mode and goes on after crashes, timeouts and
#       out-of-memory inputs (each is saved in artifacts/).
#   run_fuzzer.sh merge BUILD_DIR TARGET [libFuzzer options...]
#       minimises corpus/TARGET with -merge=1: its named files (seeds, bug_*)
#       stay, and of the inputs found by fuzzing (its 40-hex-digit files and
#       the work corpus) only those that add coverage to them are kept.
#       -use_counters=0 keeps those that add edges only (a smaller corpus).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

if [[ "${1:-}" == merge ]]; then
  build="$(cd "$2" && pwd)"; target="$3"; shift 3
  exe="$build/test/Polyvector_fields/fuzz/fuzz_$target"
  work="$build/fuzz-work/$target"
  corpus="$here/corpus/$target"
  fresh="$work/merged" found="$work/found"
  rm -rf "$fresh" "$found"; mkdir -p "$fresh" "$found" "$work/corpus"
  # Named files (the seeds, and bug_* regression inputs) are kept as they are;
  # inputs named by libFuzzer (40 hex digits) are merged again with the work
  # corpus, and only those that add coverage to the seeds are kept.
  for file in "$corpus"/*; do
    name="$(basename "$file")"
    if [[ "$name" =~ ^[0-9a-f]{40}$ ]]; then cp "$file" "$found/"
    elif [[ "$name" != bug_* ]]; then cp "$file" "$fresh/"
    fi
  done
  "$exe" -merge=1 -max_len=4096 -timeout=10 -rss_limit_mb=4096 "$@" "$fresh" "$found" "$work/corpus"
  for file in "$corpus"/bug_*; do [[ -e "$file" ]] && cp "$file" "$fresh/"; done
  rm -rf "$corpus"
  cp -r "$fresh" "$corpus"
  echo "corpus/$target: $(ls "$corpus" | wc -l) files"
  exit 0
fi

build="$(cd "$1" && pwd)"; target="$2"; runs="${3:-1000000}"; shift $(( $# >= 3 ? 3 : $# ))
# One core: no thread pools in the BLAS under CHOLMOD. A small quarantine of
# AddressSanitizer (freed memory kept poisoned, 256 MB by default) keeps the
# meshing harnesses, which allocate much per execution, out of page faults.
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}" OPENBLAS_NUM_THREADS="${OPENBLAS_NUM_THREADS:-1}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-quarantine_size_mb=16}"
exe="$build/test/Polyvector_fields/fuzz/fuzz_$target"
[[ -x "$exe" ]] || { echo "no $exe: build it with -DPVF_BUILD_FUZZERS=ON (target pvf_fuzzers)" >&2; exit 2; }
work="$build/fuzz-work/$target"
mkdir -p "$work/corpus" "$work/artifacts"
options=(-runs="$runs" -max_len=4096 -timeout=2 -report_slow_units=1 -print_final_stats=1
         -dict="$here/pvf.dict" -artifact_prefix="$work/artifacts/")
if [[ "${FORK:-0}" == 1 ]]; then
  options+=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
fi
# The seeds: all of corpus/TARGET, the bug_* regression inputs included (the
# bugs they found are fixed; see FOUND_BUGS.md).
rm -rf "$work/seeds"; mkdir -p "$work/seeds"
cp "$here/corpus/$target"/* "$work/seeds/"
cd "$work"
"$exe" "${options[@]}" "$@" "$work/corpus" "$work/seeds" 2>&1 | tee "$work/log.txt"
