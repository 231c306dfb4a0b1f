#!/usr/bin/env bash
# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.
#
# Installs the Debian packages needed to build and test the package, and only
# those that are missing; running it again does nothing.
#   bash scripts/install_dependencies.sh          build, tests, benchmarks, manual
#   bash scripts/install_dependencies.sh --doc    also matplotlib, to redraw the manual's figures
#                                                 (doc/Polyvector_fields/make_figures.py)
# doxygen is always installed: the test doc_polyvector_fields_doxygen needs it.
# libjs-three (three.js, copied into the pages of --out-html) and chromium
# (the browser of the test cli_html_viewer_browser) too.
set -euo pipefail

# pybind11-dev python3-dev python3-numpy: the Python module (python/);
# python3-pytest: its tests.
packages=(g++ cmake make libcgal-dev libeigen3-dev libboost-dev libgtest-dev
          libbenchmark-dev libsuitesparse-dev libopenblas0-pthread libtbb-dev libopenmesh-dev doxygen
          pybind11-dev python3-dev python3-numpy python3-pytest
          libjs-three chromium)
for arg in "$@"; do
  case "$arg" in
    --doc) packages+=(python3-matplotlib) ;;
    -h|--help) echo "usage: bash scripts/install_dependencies.sh [--doc]"; exit 0 ;;
    *) echo "install_dependencies: unknown argument '$arg' (known: --doc)" >&2; exit 2 ;;
  esac
done

if ! command -v dpkg-query >/dev/null 2>&1; then
  echo "install_dependencies: not a Debian-like system (no dpkg-query); make sure these are installed: ${packages[*]}"
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = installed ] || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_dependencies: all ${#packages[@]} packages already installed"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "install_dependencies: missing ${missing[*]}; run as root or install sudo" >&2
  exit 1
fi

echo "install_dependencies: installing ${missing[*]}"
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install_dependencies: installed ${#missing[@]} package(s)"
