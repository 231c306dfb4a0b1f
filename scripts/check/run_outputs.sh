#!/usr/bin/env bash
# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Runs design_polyvector_field on the README's documented runs (readme) or on
# every mesh of ../shared/data/corpus (corpus), each run's files, exit status
# and output in OUTDIR/<run>/, so that two builds can be compared with
# compare_outputs.sh (for example the code before and after a refactoring).
#   bash scripts/check/run_outputs.sh EXE OUTDIR [readme|corpus] [TIMEOUT_SECONDS]
set -uo pipefail
EXE=$(realpath "$1"); OUT=$(realpath -m "$2"); MODE=${3:-readme}; T=${4:-300}
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd); D=$ROOT/data; CORPUS=$ROOT/../shared/data/corpus
mkdir -p "$OUT"
run() { local name=$1; shift; local d="$OUT/$name"; rm -rf "$d"; mkdir -p "$d"
  ( cd "$d"; timeout "$T" "$EXE" "$@" > stdout.txt 2> stderr.txt; echo $? > rc.txt ); }
if [ "$MODE" = readme ]; then
  run main --mesh $D/inspired_mesh.obj --dmat-b $D/inspired_mesh_b.dmat --dmat-bc $D/inspired_mesh_bc.dmat --conjugate --edge-length 0.82 --quad-mesh inspired_quads.obj --planarize --out-param p.obj --out-field f.rawfield --out-singularities f.sings --out-vtk f.vtk
  run default --mesh $D/inspired_mesh.obj --dmat-b $D/inspired_mesh_b.dmat --dmat-bc $D/inspired_mesh_bc.dmat --out-field f.rawfield --out-singularities f.sings --out-vtk f.vtk
  run conj --mesh $D/inspired_mesh.obj --dmat-b $D/inspired_mesh_b.dmat --dmat-bc $D/inspired_mesh_bc.dmat --conjugate --out-field f.rawfield --out-singularities f.sings --out-vtk f.vtk
  run bumpy_param --mesh $D/bumpy.off --curvature-constraints 1 --parametrize --out-param p.obj --out-field f.rawfield --out-singularities f.sings --out-vtk f.vtk
  run eight_quads --mesh $D/eight.off --curvature-constraints 1 --quad-mesh q.off --out-param p.obj --out-field f.rawfield --out-singularities f.sings
  run bumpy_angle --mesh $D/bumpy.off --random-constraints 30 --angle-bound 70 --out-field f.rawfield --out-singularities f.sings --out-vtk f.vtk
  run fandisk_sharp --mesh $D/fandisk.off --degree 4 --sign-symmetric --sharp-edges 30 --out-field f.rawfield --out-singularities f.sings --out-vtk f.vtk
  run lilium6 --mesh $D/lilium.obj --degree 6 --random-constraints 20 --out-field f.rawfield --out-singularities f.sings --out-vtk f.vtk
  run bubble_conj --mesh $D/botanic-garden-bubble.off --curvature-constraints 2 --conjugate --out-field f.rawfield --out-singularities f.sings --out-vtk f.vtk
  run bumpy_angle_q --mesh $D/bumpy.off --random-constraints 30 --angle-bound 70 --quad-mesh q.obj --planarize --out-param p.obj
else
  for m in "$CORPUS"/*.off "$CORPUS"/*.obj; do
    run "corpus_$(basename "$m")" --mesh "$m" --curvature-constraints 1 --quad-mesh q.obj --out-param p.obj --out-field f.rawfield
  done
fi
