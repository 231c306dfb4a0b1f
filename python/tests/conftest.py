# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

# Shared fixtures of the Python tests. ctest gives PYTHONPATH (the build's
# python/ folder), PVF_DATA_DIR (the bundled meshes) and PVF_CLI (the built
# design_polyvector_field).

import os

import numpy as np
import pytest

import polyvector_fields as pvf

DATA = os.environ.get("PVF_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "data"))


def data_path(name):
    return os.path.join(DATA, name)


def read_dmat(path):
    """libigl's ASCII .dmat: 'cols rows', then the values column-major."""
    with open(path) as f:
        words = f.read().split()
    cols, rows = int(words[0]), int(words[1])
    values = np.array([float(w) for w in words[2:2 + cols * rows]])
    return values.reshape(cols, rows).T


@pytest.fixture(scope="session")
def inspired():
    """The paper's architectural mesh, read as the command-line program reads it, and its 84 constraints."""
    V, F, info = pvf.read_triangle_mesh(data_path("inspired_mesh.obj"))
    b = read_dmat(data_path("inspired_mesh_b.dmat")).astype(np.int64).reshape(-1)
    bc = read_dmat(data_path("inspired_mesh_bc.dmat"))
    # The constraints name faces of the file: the mesh is read without change.
    assert info["file_faces"] == len(F) and np.array_equal(info["source_face"], np.arange(len(F)))
    return V, F, b, bc


@pytest.fixture(scope="session")
def bumpy():
    V, F, _ = pvf.read_triangle_mesh(data_path("bumpy.off"))
    return V, F
