# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

# Bad input: every case raises polyvector_fields.Error with the reason and the
# code, never crashes the interpreter, and writes no file.

import os

import numpy as np
import pytest

import polyvector_fields as pvf

# Two triangles sharing the edge 1-2, a square in the plane z = 0.
V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], dtype=float)
F = np.array([[0, 1, 2], [1, 3, 2]])
b = np.array([0])
bc = np.array([[1.0, 0, 0, 0, 1, 0]])


def refused(code, text, function, *args, **kwargs):
    with pytest.raises(pvf.Error) as e:
        function(*args, **kwargs)
    assert e.value.code == code, str(e.value)
    assert text in str(e.value), str(e.value)
    assert isinstance(e.value, ValueError)
    return e.value


CASES = [
    # arrays
    ("BAD_ARRAY", "V: expected shape (n, 3), got (4, 2)", pvf.design_field, (V[:, :2], F, b, bc), {}),
    ("BAD_ARRAY", "V: expected a real array", pvf.design_field, (V.astype(str), F, b, bc), {}),
    ("NON_FINITE_VALUE", "V[2, 1] is nan", pvf.design_field,
     (np.where(np.arange(12).reshape(4, 3) == 7, np.nan, V), F, b, bc), {}),
    ("NON_FINITE_VALUE", "V[0, 0] is inf", pvf.principal_curvatures,
     (np.where(np.arange(12).reshape(4, 3) == 0, np.inf, V), F), {}),
    ("BAD_ARRAY", "F: expected an integer array", pvf.design_field, (V, F.astype(float), b, bc), {}),
    ("BAD_ARRAY", "F: expected shape (n, 3), got (2, 4)", pvf.design_field, (V, np.c_[F, F[:, :1]], b, bc), {}),
    ("BAD_ARRAY", "F[1, 1] = 4 is not a vertex of V (0..4-1)", pvf.design_field, (V, np.array([[0, 1, 2], [1, 4, 2]]), b, bc), {}),
    ("BAD_ARRAY", "F[0, 0] = -1 is not a vertex", pvf.singularities, (V, np.array([[-1, 1, 2], [1, 3, 2]]), np.zeros((2, 12))), {}),
    ("EMPTY_MESH", "no face", pvf.design_field, (V, np.zeros((0, 3), dtype=int), None, None), {}),
    ("BAD_ARRAY", "an array is required, not None", pvf.design_field, (None, F, b, bc), {}),
    # meshes
    ("DEGENERATE_FACE", "F row 1: face repeats vertex 3", pvf.design_field, (V, np.array([[0, 1, 2], [1, 3, 3]]), b, bc), {}),
    ("NON_MANIFOLD_MESH", "F row 2", pvf.design_field,
     (np.r_[V, [[0.5, 0.5, 1]]], np.array([[0, 1, 2], [1, 3, 2], [1, 2, 4]]), b, bc), {}),
    ("NON_MANIFOLD_MESH", "F row 1", pvf.design_field, (V, np.array([[0, 1, 2], [1, 2, 3]]), b, bc), {}),
    ("DEGENERATE_FACE", "degenerate face (zero area or non-finite coordinates): face 0 of F", pvf.design_field,
     (np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0]], dtype=float), np.array([[0, 1, 2], [0, 3, 1]]), None, None), {}),
    # constraints
    ("BAD_ARRAY", "b[0, 0] = 2 is not a face of F (0..2-1)", pvf.design_field, (V, F, np.array([2]), bc), {}),
    ("BAD_ARRAY", "bc: has 1 rows, b has 2", pvf.design_field, (V, F, np.array([0, 1]), bc), {}),
    ("BAD_ARRAY", "bc: expected 3k columns", pvf.design_field, (V, F, b, bc[:, :4]), {}),
    ("BAD_ARRAY", "b and bc go together", pvf.design_field, (V, F, b, None), {}),
    ("DUPLICATE_CONSTRAINT", "constraint 1 (face 0)", pvf.design_field, (V, F, np.array([0, 0]), np.r_[bc, bc]), {}),
    ("TOO_MANY_CONSTRAINT_VECTORS", "constraint 0 (face 0)", pvf.design_field, (V, F, b, np.c_[bc, bc]),
     {"degree": 4, "sign_symmetric": True}),
    ("ZERO_CONSTRAINT_VECTOR", "constraint 0 (face 0)", pvf.design_field, (V, F, b, np.array([[0.0, 0, 1]])), {}),
    ("NON_FINITE_VALUE", "bc row 0, vector 0: NaN is allowed only as whole trailing triples", pvf.design_field,
     (V, F, b, np.array([[np.nan, 0, 1, 1, 0, 0]])), {}),
    ("EMPTY_CONSTRAINT", "bc row 0: no vector", pvf.design_field, (V, F, b, np.full((1, 3), np.nan)), {}),
    ("INVALID_WEIGHT", "soft[0] = 0.000000: a soft weight must be in [1e-8, 1e8]", pvf.design_field, (V, F, b, bc), {"soft": 0.0}),
    ("INVALID_DEGREE", "degree", pvf.design_field, (V, F, b, bc), {"degree": 3, "sign_symmetric": True}),
    ("INVALID_DEGREE", "degree", pvf.design_field, (V, F, None, None), {"degree": 0}),
    ("INVALID_PARAMETER", "smoothness_weights: 'cotan'", pvf.design_field, (V, F, b, bc), {"smoothness_weights": "cotan"}),
    # numbers, flags and strings out of their range or of the wrong type: named, not pybind11's TypeError
    ("INVALID_DEGREE", "degree: -1 is not in 1..32", pvf.design_field, (V, F, b, bc), {"degree": -1}),
    ("INVALID_DEGREE", "degree: 33 is not in 1..32", pvf.design_field, (V, F, b, bc), {"degree": 33}),
    ("INVALID_DEGREE", "degree: expected an integer, got 4.0", pvf.design_field, (V, F, b, bc), {"degree": 4.0}),
    ("INVALID_DEGREE", "degree: expected an integer, got True", pvf.design_field, (V, F, b, bc), {"degree": True}),
    ("INVALID_DEGREE", "degree: expected an integer", pvf.design_field, (V, F, b, bc), {"degree": 2 ** 70}),
    ("INVALID_PARAMETER", "sign_symmetric: expected True or False, got 'yes'", pvf.design_field, (V, F, b, bc),
     {"sign_symmetric": "yes"}),
    ("INVALID_PARAMETER", "smoothness_weights: expected a string, got 3", pvf.design_field, (V, F, b, bc),
     {"smoothness_weights": 3}),
    ("INVALID_PARAMETER", "orthogonality_weight: expected a number, got None", pvf.frame_field, (V, F),
     {"orthogonality_weight": None}),
    ("INVALID_PARAMETER", "conjugate: expected True or False, got 1", pvf.frame_field, (V, F), {"conjugate": 1}),
    ("INVALID_PARAMETER", "vectors_per_face: -1 is not in 1..2", pvf.sharp_edges, (V, F), {"vectors_per_face": -1}),
    ("INVALID_PARAMETER", "angle: expected a number, got 'steep'", pvf.sharp_edges, (V, F), {"angle": "steep"}),
    ("INVALID_PARAMETER", "quad_size: expected a number", pvf.refine_for_quad_size, (V, F, [1.0]), {}),
    ("INVALID_PARAMETER", "stiffening_keeps_integers: expected True or False", pvf.integer_grid_map,
     (V, F, np.tile([1.0, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0], (2, 1))), {"stiffening_keeps_integers": None}),
    ("INVALID_PARAMETER", "keep_trimmed_boundary: expected True or False", pvf.quad_mesh,
     (V, F, np.zeros((6, 2)), np.arange(6).reshape(2, 3)), {"keep_trimmed_boundary": "no"}),
    ("INVALID_PARAMETER", "split_components: expected True or False", pvf.quad_mesh,
     (V, F, np.zeros((6, 2)), np.arange(6).reshape(2, 3)), {"split_components": 1}),
    ("INVALID_PARAMETER", "max_input_distance must be a positive distance, got -1", pvf.quad_mesh,
     (V, F, np.zeros((6, 2)), np.arange(6).reshape(2, 3)), {"max_input_distance": -1.0}),
    ("INVALID_PARAMETER", "max_input_distance must be a positive distance", pvf.quad_mesh,
     (V, F, np.zeros((6, 2)), np.arange(6).reshape(2, 3)), {"max_input_distance": float("nan")}),
    ("INVALID_PARAMETER", "max_deviation must be a fraction of the bounding-box diagonal in (0, 1], got 0.0",
     pvf.quad_remesh, (V, F), {"max_deviation": 0}),
    ("INVALID_PARAMETER", "max_deviation must be a fraction of the bounding-box diagonal in (0, 1], got 1.5",
     pvf.quad_remesh, (V, F), {"max_deviation": 1.5}),
    ("INVALID_PARAMETER", "max_deviation is measured on whole quads", pvf.quad_remesh, (V, F),
     {"max_deviation": 0.01, "keep_trimmed_boundary": True}),
    ("INVALID_PARAMETER", "keep_trimmed_boundary keeps the border's polygons, which are not split", pvf.quad_mesh,
     (V, F, np.zeros((6, 2)), np.arange(6).reshape(2, 3)), {"keep_trimmed_boundary": True, "split_components": True}),
    ("INVALID_PARAMETER", "max_deviation: expected a number, got '1%'", pvf.quad_remesh, (V, F),
     {"max_deviation": "1%"}),
    ("INVALID_PARAMETER", "threshold: expected a number", pvf.planarize, (V, np.array([[0, 1, 3, 2]]), V, F),
     {"threshold": None}),
    ("INVALID_PARAMETER", "repair: expected True or False", pvf.read_triangle_mesh, ("m.off",), {"repair": "no"}),
    ("INVALID_PARAMETER", "angle_bound: 120", pvf.frame_field, (V, F, b, bc), {"angle_bound": 120}),
    ("INVALID_PARAMETER", "curvature constraints", pvf.frame_field, (V, F), {"curvature_constraints": 2.0}),
    # fields and maps
    ("BAD_ARRAY", "X: expected one row per face of F (2), got 3", pvf.singularities, (V, F, np.ones((3, 12))), {}),
    ("BAD_ARRAY", "X: expected 3N columns", pvf.singularities, (V, F, np.ones((2, 7))), {}),
    ("INVALID_DEGREE", "X: sign symmetry needs an even number", pvf.singularities, (V, F, np.ones((2, 9))), {"sign_symmetric": True}),
    ("INVALID_PARAMETER", "number_of_iterations: -1 is not at least 1", pvf.frame_field, (V, F),
     {"angle_bound": 60, "number_of_iterations": -1}),
    ("INVALID_PARAMETER", "tolerance: expected a number or None", pvf.frame_field, (V, F),
     {"conjugate": True, "tolerance": "small"}),
    ("INVALID_PARAMETER", "edge_length: must be positive and finite", pvf.integer_grid_map,
     (V, F, np.tile([1.0, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0], (2, 1))), {"edge_length": -1.0}),
    ("NOT_A_FRAME_FIELD", "X: not a frame field", pvf.integer_grid_map, (V, F, np.ones((2, 12))), {}),
    ("ZERO_FRAME", "X row 0: vector 0 is zero in the face plane", pvf.integer_grid_map,
     (V, F, np.tile([0, 0, 1.0, 0, 1, 0, 0, 0, -1, 0, -1, 0], (2, 1))), {}),
    ("INVALID_PARAMETER", "give edge_length or quads, not both", pvf.integer_grid_map,
     (V, F, np.tile([1.0, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0], (2, 1))), {"edge_length": 1, "quads": 4}),
    ("BAD_ARRAY", "features row 0: vertices 0 and 3 are not joined by an edge", pvf.integer_grid_map,
     (V, F, np.tile([1.0, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0], (2, 1))), {"features": np.array([[0, 3]])}),
    ("BAD_ARRAY", "FUV[0, 2] = 6 is not a row of UV", pvf.quad_mesh, (V, F, np.zeros((6, 2)), np.array([[0, 1, 6], [3, 4, 5]])), {}),
    ("BAD_ARRAY", "UV: expected shape (n, 2)", pvf.quad_mesh, (V, F, np.zeros((6, 3)), np.arange(6).reshape(2, 3)), {}),
    ("NOT_AN_INTEGER_GRID_MAP", "quad_mesh", pvf.quad_mesh, (V, F, np.zeros((6, 2)), np.arange(6).reshape(2, 3)), {}),
    ("BAD_ARRAY", "seam_transitions: expected an integer array of shape (2, 3, 3)", pvf.quad_mesh,
     (V, F, np.zeros((6, 2)), np.arange(6).reshape(2, 3)), {"seam_transitions": np.zeros((2, 3))}),
    # quads
    ("BAD_ARRAY", "Fq: expected shape (n, 4), got (2, 3)", pvf.quad_planarity, (V, F), {}),
    ("BAD_ARRAY", "Fq[0, 3] = 9 is not a vertex of Vq", pvf.planarize, (V, np.array([[0, 1, 3, 9]]), V, F), {}),
    ("INVALID_PARAMETER", "threshold -1", pvf.planarize, (V, np.array([[0, 1, 3, 2]]), V, F), {"threshold": -1.0}),
    ("INVALID_PARAMETER", "gauss_newton_steps: -1 is not in 0..1000000", pvf.planarize,
     (V, np.array([[0, 1, 3, 2]]), V, F), {"gauss_newton_steps": -1}),
    ("INVALID_PARAMETER", "gauss_newton_steps: expected an integer, got 2.5", pvf.planarize,
     (V, np.array([[0, 1, 3, 2]]), V, F), {"gauss_newton_steps": 2.5}),
    ("INVALID_PARAMETER", "crease_angle 181", pvf.planarize, (V, np.array([[0, 1, 3, 2]]), V, F),
     {"crease_angle": 181.0}),
    ("INVALID_PARAMETER", "crease_angle: expected a number", pvf.planarize, (V, np.array([[0, 1, 3, 2]]), V, F),
     {"crease_angle": "sharp"}),
    # files
    ("CANNOT_OPEN_FILE", "mesh '/nonexistent/m.off'", pvf.read_triangle_mesh, ("/nonexistent/m.off",), {}),
    ("BAD_ARRAY", "save_mesh: '", pvf.save_mesh, ("x.ply", V, F), {}),
    ("BAD_ARRAY", "save_mesh: F: an index is not a vertex", pvf.save_mesh, ("x.obj", V, F + 2), {}),
]


@pytest.mark.parametrize("code, text, function, args, kwargs", CASES, ids=[c[1][:40] for c in CASES])
def test_bad_input_is_refused_with_the_reason(code, text, function, args, kwargs, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    refused(code, text, function, *args, **kwargs)
    assert os.listdir(tmp_path) == []  # nothing written, not even a temporary file


def test_a_file_that_cannot_be_read_as_a_mesh(tmp_path):
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    e = refused("MALFORMED_FILE", "mesh '", pvf.read_triangle_mesh, str(bad))
    assert str(bad) in str(e)


def test_the_refusal_leaves_the_arrays_unchanged():
    V2, F2, bc2 = V.copy(), F.copy(), bc.copy()
    with pytest.raises(pvf.Error):
        pvf.design_field(V2, F2, np.array([0, 0]), np.r_[bc2, bc2])
    assert np.array_equal(V2, V) and np.array_equal(F2, F) and np.array_equal(bc2, bc)


def test_the_valid_square_works():
    # The cases above fail for their stated reason only: the same square with good arguments succeeds.
    X, info = pvf.design_field(V, F, b, bc)
    assert X.shape == (2, 12) and info["full_constraints"] == 0 and info["partial_constraints"] == 1
    P, pinfo = pvf.quad_planarity(V, np.array([[0, 1, 3, 2]]))
    assert P.tolist() == [0.0] and pinfo["max"] == 0.0
