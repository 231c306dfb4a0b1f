#!/usr/bin/env bash
# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.
#
# Installs what is missing, builds design_polyvector_field in build/ and runs
# it with the arguments given. With no argument it designs a field on a
# bundled mesh and writes output/*.rawfield, *.sings and *.vtk.
#   bash scripts/design.sh
#   bash scripts/design.sh --mesh my.off --degree 4 --out-vtk my.vtk
# The program runs in the directory you called this script from, so relative
# paths in the arguments, and output/, are relative to it.
set -euo pipefail
caller_dir=$(pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

bash scripts/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target design_polyvector_field -j2

cd "$caller_dir"
exec "$root/build/tools/design_polyvector_field/design_polyvector_field" "$@"
