#!/usr/bin/env bash
# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.
#
# Runs every case of cases.txt (see its header) against the command-line
# program and checks, for each: the exit code, exactly one line on standard
# error matching the case's regex, and a work folder left as the setup made it.
#   bash run_cases.sh EXE DATA_DIR WORK_ROOT [CASE_NAME]
# Prints one line per case and exits non-zero if any case fails.
set -u
exe=$1 data=$2 work_root=$3 only=${4:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
keep_content="this file must survive a failed run"
failures=0 count=0

trim() { local s=$1; s=${s#"${s%%[![:space:]]*}"}; s=${s%"${s##*[![:space:]]}"}; printf '%s' "$s"; }

# The listing of a folder: relative paths with their content checksums.
listing() { (cd "$1" && find . -mindepth 1 \( -type f -o -type d -o -type l \) -print0 | sort -z |
             while IFS= read -r -d '' f; do
               if [ -L "$f" ]; then echo "$f -> link"; elif [ -d "$f" ]; then echo "$f/";
               else echo "$f $(cksum < "$f")"; fi; done); }

while IFS= read -r raw || [ -n "$raw" ]; do
  case "$raw" in ''|'#'*) continue ;; esac
  IFS='|' read -r name expected regex arguments setup <<<"$raw"
  name=$(trim "$name"); expected=$(trim "$expected"); regex=$(trim "$regex")
  arguments=$(trim "$arguments"); setup=$(trim "${setup:-}")
  [ -n "$only" ] && [ "$only" != "$name" ] && continue
  count=$((count + 1))
  work="$work_root/$name"
  rm -rf "$work" && mkdir -p "$work"

  # Setup.
  IFS=';' read -r -a items <<<"$setup"
  for item in "${items[@]}"; do
    item=$(trim "$item")
    IFS=':' read -r kind what rest <<<"$item"
    rest=${rest//@DATA@/$data}; rest=${rest//@BUMPY@/$data/bumpy.off}; rest=${rest//@IN@/$here}
    case "$kind" in
      '') ;;
      mkdir) mkdir -p "$work/$what" ;;
      keep) printf '%s\n' "$keep_content" > "$work/$what" ;;
      link) ln -s "$rest" "$work/$what" ;;
      text) printf '%s\n' "$rest" > "$work/$what" ;;
      copy) cp "$rest" "$work/$what" ;;
      zeros) head -c "$rest" /dev/zero | tr '\0' '7' > "$work/$what" ;;
      *) echo "FAIL $name: unknown setup item '$item'"; failures=$((failures + 1)); continue 2 ;;
    esac
  done
  before=$(listing "$work")

  # Arguments (empty ones kept: they are cases of their own).
  args=()
  IFS=';' read -r -a parts <<<"$arguments;"
  for a in "${parts[@]}"; do
    a=${a//@WORK@/$work}; a=${a//@IN@/$here}; a=${a//@DATA@/$data}; a=${a//@BUMPY@/$data/bumpy.off}
    args+=("$a")
  done
  # read -a drops the trailing empty field only when it is the ';' we added.
  if [[ "$arguments" != *--out-* ]]; then
    args+=(--out-field "$work/out.rawfield" --out-singularities "$work/out.sings" --out-vtk "$work/out.vtk")
  fi

  (cd "$work" && timeout 120 "$exe" "${args[@]}" >"$work_root/$name.stdout" 2>"$work_root/$name.stderr")
  rc=$?
  err=$(cat "$work_root/$name.stderr")
  lines=$(printf '%s' "$err" | grep -c '')
  after=$(listing "$work")
  problem=""
  if [ "$rc" != "$expected" ]; then problem="exit code $rc, expected $expected"
  elif [ "$lines" != 1 ]; then problem="$lines lines on stderr, expected 1"
  elif ! printf '%s' "${err//$work/}" | tr 'A-Z' 'a-z' | grep -qE -- "$regex"; then problem="stderr does not match /$regex/"
  elif [ "$before" != "$after" ]; then problem="the work folder changed: $(diff <(echo "$before") <(echo "$after") | tr '\n' ' ')"
  fi
  if [ -n "$problem" ]; then
    echo "FAIL $name: $problem"
    echo "     stderr: $err"
    failures=$((failures + 1))
  else
    echo "ok   $name: $err"
  fi
done < "$here/cases.txt"

echo "$count cases, $failures failed"
[ "$count" -gt 0 ] && [ "$failures" = 0 ]
