# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

# Fields: bit-identity with the command-line program, and round trips
# (roots -> singularities, map -> seamless uv).

import os
import subprocess

import numpy as np
import pytest

import polyvector_fields as pvf
from conftest import data_path


def run_cli(tmp_path, *args):
    cli = os.environ.get("PVF_CLI")
    if not cli:
        pytest.skip("PVF_CLI (the built design_polyvector_field) is not set: run the tests through ctest")
    result = subprocess.run([cli, *args], capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    return result.stdout


def read_rawfield(path):
    with open(path) as f:
        N, F = (int(w) for w in f.readline().split())
        rows = [[float(w) for w in line.split()] for line in f if line.strip()]
    X = np.array(rows)
    assert X.shape == (F, 3 * N)
    return N, X


def read_sings(path):
    with open(path) as f:
        N, S = (int(w) for w in f.readline().split())
        pairs = [tuple(int(w) for w in line.split()) for line in f if line.strip()]
    assert len(pairs) == S
    return N, sorted(pairs)


def check_against_cli(V, F, X, tmp_path, *cli_args):
    """Runs the program, and checks that its .rawfield is X bit for bit and
    that its .sings are the singularities of X; returns their number."""
    field, sings = tmp_path / "cli.rawfield", tmp_path / "cli.sings"
    run_cli(tmp_path, *cli_args, "--out-field", str(field), "--out-singularities", str(sings))
    N, X_cli = read_rawfield(field)
    # .rawfield holds the shortest decimal text that reads back as the same
    # double: equality is exact, bit for bit (the sign of zeros too).
    assert X.shape == X_cli.shape
    assert np.array_equal(X, X_cli)
    assert np.array_equal(np.signbit(X), np.signbit(X_cli))
    # Round trip: the singularities of the roots (the coefficients rebuilt
    # from the vectors) are the program's, computed from the coefficients.
    S, index, info = pvf.singularities(V, F, X)
    N_s, pairs = read_sings(sings)
    assert N_s == N == info["degree"]
    assert sorted(zip(S.tolist(), info["index_numerators"].tolist())) == pairs
    return len(pairs)


def test_bit_identical_to_the_command_line_program(inspired, tmp_path):
    # The program's default run: the bundled mesh, its 84 constraints, a frame field.
    V, F, b, bc = inspired
    X, info = pvf.design_field(V, F, b, bc, degree=4, sign_symmetric=True)
    assert info["full_constraints"] == 84
    # (this field has no singularity: the program's summary says 0 too)
    assert check_against_cli(V, F, X, tmp_path) == 0


def test_bit_identical_to_the_command_line_program_with_singularities(bumpy, tmp_path):
    # No constraint on a closed genus-0 mesh: the smoothest 4-RoSy field, whose
    # singularities' indices sum to the Euler characteristic 2 (Poincare-Hopf).
    V, F = bumpy
    X, _ = pvf.design_field(V, F, None, None, degree=4)
    count = check_against_cli(V, F, X, tmp_path, "--mesh", data_path("bumpy.off"), "--degree", "4")
    assert count >= 8
    _, _, info = pvf.singularities(V, F, X)
    assert info["index_numerators"].sum() == 2 * 4


def test_constraints_are_met_and_int32_fortran_faces_give_the_same_field(inspired):
    V, F, b, bc = inspired
    X, _ = pvf.design_field(V, F, b, bc, degree=4, sign_symmetric=True)
    F32 = np.asfortranarray(F.astype(np.int32))
    X32, _ = pvf.design_field(np.asfortranarray(V), F32, b.astype(np.int32), bc, degree=4, sign_symmetric=True)
    assert np.array_equal(X, X32)
    # Hard full constraints: u and v of a constrained face are the constraint
    # vectors projected onto the face plane (up to the order of the roots and
    # their signs), to rounding.
    for f, row in zip(b[:10], bc[:10]):
        p0, p1, p2 = V[F[f]]
        n = np.cross(p1 - p0, p2 - p0)
        n /= np.linalg.norm(n)
        wanted = [row[0:3] - n * (row[0:3] @ n), row[3:6] - n * (row[3:6] @ n)]
        wanted = [w / np.linalg.norm(w) * np.linalg.norm(r) for w, r in zip(wanted, [row[0:3], row[3:6]])]
        got = X[f].reshape(4, 3)
        for w in wanted:
            assert min(np.linalg.norm(g - w) for g in got) <= 1e-9 * np.linalg.norm(w)


def test_poincare_hopf_on_a_closed_mesh(bumpy):
    # The smoothest 4-RoSy field of a genus-0 surface (no constraint): the
    # indices of its singularities sum to the Euler characteristic, 2.
    V, F = bumpy
    X, info = pvf.design_field(V, F, None, None, degree=4)
    assert info["components"] == 1
    S, index, sinfo = pvf.singularities(V, F, X)
    assert not sinfo["sign_symmetric"]  # a 4-RoSy field is not told sign-symmetric unless asked
    assert sinfo["index_numerators"].sum() == 2 * 4
    assert np.allclose(index * 4, sinfo["index_numerators"])
    # Asked as sign-symmetric, the same vectors give the same singularities.
    S2, _, info2 = pvf.singularities(V, F, X, sign_symmetric=True)
    assert sorted(zip(S.tolist(), sinfo["index_numerators"].tolist())) == \
        sorted(zip(S2.tolist(), info2["index_numerators"].tolist()))


def test_partial_constraints_with_nan_padding(inspired):
    V, F, b, bc = inspired
    # The first 10 faces keep only u: their vectors hold u (a root) but v is free.
    bc2 = bc.copy()
    bc2[:10, 3:6] = np.nan
    X, info = pvf.design_field(V, F, b, bc2, degree=4, sign_symmetric=True)
    assert info["full_constraints"] == 74 and info["partial_constraints"] == 10
    for f, row in zip(b[:10], bc2[:10]):
        u = row[0:3]
        got = X[f].reshape(4, 3)
        # u projected onto the face plane is one of the vectors (partial constraint P(u) = 0)
        p0, p1, p2 = V[F[f]]
        n = np.cross(p1 - p0, p2 - p0)
        n /= np.linalg.norm(n)
        w = u - n * (u @ n)
        w *= np.linalg.norm(u) / np.linalg.norm(w)
        assert min(np.linalg.norm(g - w) for g in got) <= 1e-8 * np.linalg.norm(w)


def seamless_defects(F, UV, FUV):
    """Interior edges whose two charts are not related by a grid symmetry (quarter turn + integer translation), exactly."""
    corner = {}
    for f in range(len(F)):
        for k in range(3):
            corner[(f, int(F[f, k]))] = UV[FUV[f, k]]
    edge_faces = {}
    for f in range(len(F)):
        for k in range(3):
            a, c = int(F[f, k]), int(F[f, (k + 1) % 3])
            edge_faces.setdefault((min(a, c), max(a, c)), []).append(f)
    rotations = [np.array(m) for m in ([[1, 0], [0, 1]], [[0, -1], [1, 0]], [[-1, 0], [0, -1]], [[0, 1], [-1, 0]])]
    bad, seams = 0, 0
    for (a, c), fs in edge_faces.items():
        if len(fs) != 2:
            continue
        f, g = fs
        ok = False
        for R in rotations:
            ta = corner[(g, a)] - R @ corner[(f, a)]
            tc = corner[(g, c)] - R @ corner[(f, c)]
            if np.array_equal(ta, tc) and np.array_equal(ta, np.round(ta)):
                ok = True
                if not (R == rotations[0]).all() or ta.any():
                    seams += 1
                break
        bad += not ok
    return bad, seams


def test_integer_grid_map_is_seamless(bumpy):
    V, F = bumpy
    X, _ = pvf.frame_field(V, F)
    UV, FUV, info = pvf.integer_grid_map(V, F, X, quads=300)
    assert UV.shape == (3 * len(F), 2) and FUV.shape == (len(F), 3)
    bad, seams = seamless_defects(F, UV, FUV)
    assert bad == 0
    assert seams > 0 and info["singular_vertices"] > 0  # a sphere's field has seams and singularities
    assert info["flipped_faces"] == 0
    # The transitions the map reports are the ones the uv satisfy.
    T = info["seam_transitions"]
    assert T.shape == (len(F), 3, 3) and set(np.unique(T[:, :, 0])) <= {0, 1, 2, 3}
    # The quads of the map, with its transitions or from the uv alone: the same mesh.
    Vq, Fq, qinfo = pvf.quad_mesh(V, F, UV, FUV, T)
    Vq2, Fq2, _ = pvf.quad_mesh(V, F, UV, FUV)
    assert Fq.shape[1] == 4 and qinfo["quads"] == len(Fq) > 0
    assert np.array_equal(Vq, Vq2) and np.array_equal(Fq, Fq2)
    # A vertex that no face uses changes nothing (the map and the quads ignore it).
    V1 = np.r_[V, [[100.0, 100.0, 100.0]]]
    UV1, FUV1, _ = pvf.integer_grid_map(V1, F, X, quads=300)
    assert np.array_equal(UV1, UV) and np.array_equal(FUV1, FUV)
    Vq1, Fq1, _ = pvf.quad_mesh(V1, F, UV1, FUV1, T)
    assert np.array_equal(Vq1, Vq) and np.array_equal(Fq1, Fq)
    # A closed surface gives a closed quad mesh: every edge in two quads.
    edges = np.sort(np.concatenate([Fq[:, [k, (k + 1) % 4]] for k in range(4)]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    assert (counts == 2).all()
    # Euler characteristic of the quad mesh: V - E + F = 2.
    assert len(Vq) - len(counts) + len(Fq) == 2


def test_principal_curvatures_of_a_sphere():
    # An icosphere of radius 2 with outward normals: k1 = k2 = 1/2 (positive where
    # the surface bends away from the normal), to the accuracy of the jet fit.
    t = (1 + 5 ** 0.5) / 2
    V = np.array([[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t],
                  [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]], dtype=float)
    F = np.array([[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2],
                  [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5],
                  [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]])
    for _ in range(3):  # subdivide, projecting onto the sphere
        edges = {}
        faces = []
        V = list(V)
        def mid(a, c):
            key = (min(a, c), max(a, c))
            if key not in edges:
                V.append((np.asarray(V[a]) + np.asarray(V[c])) / 2)
                edges[key] = len(V) - 1
            return edges[key]
        for a, c, d in F:
            ab, cd, da = mid(a, c), mid(c, d), mid(d, a)
            faces += [[a, ab, da], [ab, c, cd], [da, cd, d], [ab, cd, da]]
        V = np.array(V)
        F = np.array(faces)
    V = 2 * V / np.linalg.norm(V, axis=1)[:, None]
    PD1, PD2, PV1, PV2, info = pvf.principal_curvatures(V, F)
    assert PD1.shape == PD2.shape == (len(F), 3) and PV1.shape == (len(F),)
    assert np.all(PV1 >= PV2)
    assert np.allclose(PV1, 0.5, atol=0.02) and np.allclose(PV2, 0.5, atol=0.02)
    assert np.allclose(np.linalg.norm(PD1, axis=1), 1) and np.allclose((PD1 * PD2).sum(axis=1), 0, atol=1e-12)
