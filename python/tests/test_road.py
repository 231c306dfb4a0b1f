# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

# The whole road on a bundled mesh: quads, counts, planarity after the
# planarization, and the quad mesh saved and read back.

import numpy as np

import polyvector_fields as pvf
from conftest import data_path
from test_field import run_cli


def test_quad_remesh_makes_planar_quads(tmp_path):
    # The paper's architectural mesh, a conjugate field, about 1000 quads, planar to 2%.
    V, F, _ = pvf.read_triangle_mesh(data_path("inspired_mesh.obj"))
    Vq, Fq, info = pvf.quad_remesh(V, F, quads=1000, conjugate=True, planarize=0.02)
    # All quads, every vertex used, the counts the stages report.
    assert Fq.ndim == 2 and Fq.shape[1] == 4 and len(Fq) > 0
    assert info["quads"]["quads"] == len(Fq) and info["quads"]["vertices"] == len(Vq)
    assert np.array_equal(np.unique(Fq), np.arange(len(Vq)))
    # About the quads asked for.
    assert 800 <= len(Fq) <= 1200, len(Fq)
    # Every quad edge in one or two quads (a manifold quad mesh with a border).
    edges = np.sort(np.concatenate([Fq[:, [k, (k + 1) % 4]] for k in range(4)]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    assert counts.max() == 2 and (counts == 1).any()
    # Conjugate field, then planarization to the threshold.
    assert info["field"]["conjugate_iterations"] > 0
    assert info["planarization"]["status"] == "SUCCESS"
    assert info["planarization"]["max_planarity_before"] > 0.02  # there was something to do
    P, planarity = pvf.quad_planarity(Vq, Fq)
    assert planarity["max"] <= 0.02 and P.max() == planarity["max"]
    assert info["planarity"]["max"] == planarity["max"]
    # The same stages as the command-line program: the same numbers of quads and vertices.
    cli_quads = tmp_path / "cli.obj"
    run_cli(tmp_path, "--mesh", data_path("inspired_mesh.obj"), "--quads", "1000", "--conjugate",
            "--planarize", "0.02", "--quad-mesh", str(cli_quads), "--out-field", str(tmp_path / "cli.rawfield"))
    lines = cli_quads.read_text().split("\n")
    assert sum(line.startswith("f ") for line in lines) == len(Fq)
    assert sum(line.startswith("v ") for line in lines) == len(Vq)
    # Saved and read back exactly (17 digits), as quads.
    path = tmp_path / "quads.obj"
    pvf.save_mesh(path, Vq, Fq)
    text = path.read_text().split("\n")
    assert sum(line.startswith("f ") for line in text) == len(Fq)
    read = np.array([[float(w) for w in line.split()[1:]] for line in text if line.startswith("v ")])
    assert np.array_equal(read, Vq)


def test_the_stages_of_the_road_one_by_one():
    # The road of quad_remesh, called stage by stage on a closed mesh without features.
    V, F, _ = pvf.read_triangle_mesh(data_path("bumpy.off"))
    X, finfo = pvf.frame_field(V, F, curvature_constraints=0.02)
    assert finfo["curvature_constraints"] > 0 and X.shape == (len(F), 12)
    UV, FUV, minfo = pvf.integer_grid_map(V, F, X, quads=300)
    Vq, Fq, qinfo = pvf.quad_mesh(V, F, UV, FUV, minfo["seam_transitions"])
    P, planarity = pvf.quad_planarity(Vq, Fq)
    Vp, pinfo = pvf.planarize(Vq, Fq, V, F, threshold=0.05)
    _, after = pvf.quad_planarity(Vp, Fq)
    assert pinfo["status"] in ("SUCCESS", "DID_NOT_CONVERGE", "TOO_FAR_FROM_SURFACE", "FOLDED_QUAD")
    if pinfo["status"] == "SUCCESS":
        assert after["max"] <= 0.05
    else:
        assert np.array_equal(Vp, Vq)  # not reached: the quads come back as given
    assert abs(after["max"] - pinfo["max_planarity_after"]) <= 1e-12 or pinfo["status"] != "SUCCESS"
    assert abs(planarity["max"] - pinfo["max_planarity_before"]) <= 1e-12


def test_planarize_gauss_newton_steps_bound_the_second_method():
    # One local-global iteration cannot take these quads to 1%, so the second
    # method decides: with gauss_newton_steps=0 it does not run and the quads
    # come back as given; with 3 it runs, and keeps at most 3 steps.
    V, F, _ = pvf.read_triangle_mesh(data_path("bumpy.off"))
    X, _ = pvf.frame_field(V, F, curvature_constraints=0.02)
    UV, FUV, minfo = pvf.integer_grid_map(V, F, X, quads=300)
    Vq, Fq, _ = pvf.quad_mesh(V, F, UV, FUV, minfo["seam_transitions"])
    _, before = pvf.quad_planarity(Vq, Fq)
    assert before["max"] > 0.01  # else the local-global iteration would succeed at once

    Vp, info = pvf.planarize(Vq, Fq, V, F, threshold=0.01, number_of_iterations=1, gauss_newton_steps=0)
    assert info["status"] != "SUCCESS"
    assert not info["gauss_newton_ran"] and info["gauss_newton_steps"] == 0
    assert np.array_equal(Vp, Vq)

    Vp, info = pvf.planarize(Vq, Fq, V, F, threshold=0.01, number_of_iterations=1, gauss_newton_steps=3)
    assert info["gauss_newton_ran"]
    assert 1 <= info["gauss_newton_steps"] <= 3
    # stopping for want of progress takes four kept steps: one sets the best
    assert info["gauss_newton_stalled"] is False
    if info["status"] == "SUCCESS":
        _, after = pvf.quad_planarity(Vp, Fq)
        assert after["max"] <= 0.01
    else:
        # where the 3 steps got to is reported, and the quads come back as given
        assert (info["gauss_newton_max_planarity"] > 0.01 or info["gauss_newton_max_distance"] > info["distance_bound"]
                or info["gauss_newton_max_distance_to_quads"]
                > info["max_distance_to_quads_before"] + info["distance_bound"])
        assert np.array_equal(Vp, Vq)


def test_planarize_crease_angle_holds_the_vertices_of_the_creases():
    # A 4 x 4 grid on the ridge z = |x| + 0.15 x y: the crease x = 0 (a
    # dihedral angle of 90 degrees) runs along quad edges, and the twist makes
    # every quad non-planar. With crease_angle=40 the crease is found and its
    # vertices slide along it only: the quads become planar and still cover
    # the surface. With 180 (no crease) they are free and slide off it, the
    # quads cut the crease, and the result is refused: the quads come back as
    # given.
    n = 4
    grid = [(2.0 * i / n - 1, 2.0 * j / n - 1) for i in range(n + 1) for j in range(n + 1)]
    V = np.array([(x, y, abs(x) + 0.15 * x * y) for x, y in grid])
    idx = lambda i, j: i * (n + 1) + j
    Fq = np.array([(idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)) for i in range(n) for j in range(n)])
    F = np.array([t for i in range(n) for j in range(n)
                  for t in ((idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)), (idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)))])
    _, before = pvf.quad_planarity(V, Fq)
    assert before["max"] > 0.01

    Vp, info = pvf.planarize(V, Fq, V, F, crease_angle=40.0)
    assert info["status"] == "SUCCESS"
    _, after = pvf.quad_planarity(Vp, Fq)
    assert after["max"] <= 0.01
    bound = info["distance_bound"]
    crease = V[:, 0] == 0
    assert crease.sum() == 5
    # the distance of each crease vertex to the line x = z = 0
    assert np.hypot(Vp[crease, 0], Vp[crease, 2]).max() <= bound
    assert info["max_distance_to_quads"] <= info["max_distance_to_quads_before"] + bound

    Vp, info = pvf.planarize(V, Fq, V, F, crease_angle=180.0)
    assert info["status"] == "TOO_FAR_FROM_SURFACE"
    assert info["gauss_newton_max_distance_to_quads"] > info["max_distance_to_quads_before"] + bound
    assert np.array_equal(Vp, V)
