#!/usr/bin/env bash
# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Compares two folders written by run_outputs.sh: cmp of every output file and
# of the exit status of each run of NEWDIR (stdout and stderr hold times and
# are left out). Prints one DIFF line per differing file; exits 1 if any.
#   bash scripts/check/compare_outputs.sh BASEDIR NEWDIR
B=$1; N=$2; diffs=0
for d in "$N"/*/; do n=$(basename "$d")
  for f in $( (cd "$B/$n" 2>/dev/null && find . -type f ! -name stdout.txt ! -name stderr.txt; cd "$d" && find . -type f ! -name stdout.txt ! -name stderr.txt) | sort -u); do
    cmp -s "$B/$n/$f" "$d/$f" || { echo "DIFF $n/${f#./}"; diffs=$((diffs + 1)); }
  done
done
echo "compare_outputs: $(ls -d "$N"/*/ | wc -l) runs, $diffs differing files"
[ "$diffs" -eq 0 ]
