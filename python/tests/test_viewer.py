# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

# The web page and the coloured PLY written from Python (write_html_viewer,
# write_quad_mesh_ply), the free border of the quad extraction
# (keep_trimmed_boundary), and the page opened in headless Chromium.

import html
import os
import re
import shutil
import sys
import time

import numpy as np
import pytest

import polyvector_fields as pvf

THREE_JS = "/usr/share/javascript/three"
needs_three_js = pytest.mark.skipif(not os.path.exists(os.path.join(THREE_JS, "three.min.js")),
                                    reason="three.js is not installed (Debian: libjs-three)")


@pytest.fixture(scope="module")
def road(inspired):
    """The paper's architectural mesh: its frame field, and the quads of a map of about 400 quads."""
    V, F, b, bc = inspired
    X, _ = pvf.frame_field(V, F, b, bc)
    UV, FUV, minfo = pvf.integer_grid_map(V, F, X, quads=400)
    Vq, Fq, qinfo = pvf.quad_mesh(V, F, UV, FUV, minfo["seam_transitions"])
    return V, F, b, X, UV, FUV, minfo, Vq, Fq, qinfo


@pytest.fixture(scope="module")
def bumpy_road(bumpy):
    """A closed mesh: a frame field with singularities, and about 300 quads."""
    V, F = bumpy
    X, _ = pvf.frame_field(V, F, curvature_constraints=0.02)
    UV, FUV, minfo = pvf.integer_grid_map(V, F, X, quads=300)
    Vq, Fq, _ = pvf.quad_mesh(V, F, UV, FUV, minfo["seam_transitions"])
    return V, F, X, Vq, Fq


def title_of(path):
    text = open(path, encoding="utf-8").read()
    return text, html.unescape(re.search(r"<title>(.*?)</title>", text, re.S).group(1))


def external_loads(text):
    """Elements that load something (src or href), and addresses fetched over the network."""
    elements = re.findall(r"<(?:script|link|img|iframe|source|video|audio)\b[^>]*\b(?:src|href)\s*=", text, re.I)
    fetched = re.findall(r"(?:src|href)\s*=\s*[\"']?\s*(?:https?:)?//", text, re.I)
    fetched += re.findall(r"(?:fetch|importScripts)\s*\(\s*[\"']https?:", text, re.I)
    return elements + fetched


@needs_three_js
def test_the_page_holds_the_figures_of_its_inputs(bumpy_road, tmp_path):
    V, F, X, Vq, Fq = bumpy_road
    page = tmp_path / "page.html"
    pvf.write_html_viewer(page, V, F, X, Vq=Vq, Fq=Fq, page_title="bumpy")
    assert os.listdir(tmp_path) == ["page.html"]  # no temporary file left
    text, title = title_of(page)
    assert external_loads(text) == []
    # The figures, each from its own function: faces, singularities of the field, quads and their planarity.
    S, _, _ = pvf.singularities(V, F, X)
    P, planarity = pvf.quad_planarity(Vq, Fq)
    assert len(S) > 0 and len(Fq) > 100 and planarity["max"] > 0
    expected = "bumpy: %d faces, %d singularities, %d quads, planarity max %s, mean %s" % (
        len(F), len(S), len(Fq), "%.3g%%" % (100 * planarity["max"]), "%.3g%%" % (100 * planarity["mean"]))
    assert title == expected
    assert '"constrained":' not in text
    # The singularities given as singularities() returns them, or as rows (vertex, numerator),
    # make the same page as those found from X.
    found = page.read_bytes()
    given = pvf.singularities(V, F, X)
    pvf.write_html_viewer(tmp_path / "given.html", V, F, X, singularities=given, Vq=Vq, Fq=Fq, page_title="bumpy")
    rows = np.column_stack((given[0], given[2]["index_numerators"])).astype(np.int32)
    pvf.write_html_viewer(tmp_path / "rows.html", V, F, X, singularities=rows, Vq=Vq, Fq=Fq, page_title="bumpy")
    assert (tmp_path / "given.html").read_bytes() == found
    assert (tmp_path / "rows.html").read_bytes() == found
    # One singularity fewer: one fewer in the title, another page.
    pvf.write_html_viewer(tmp_path / "fewer.html", V, F, X, singularities=rows[1:], Vq=Vq, Fq=Fq, page_title="bumpy")
    assert title_of(tmp_path / "fewer.html")[1] == expected.replace("%d singularities" % len(S),
                                                                    "%d singularities" % (len(S) - 1))


@needs_three_js
def test_the_page_of_a_field_with_constraints(road, tmp_path):
    V, F, b, X, _, _, _, Vq, Fq, _ = road
    page = tmp_path / "page.html"
    pvf.write_html_viewer(page, V, F, X, Vq=Vq, Fq=Fq, constrained_faces=b, page_title="inspired")
    text, title = title_of(page)
    S, _, _ = pvf.singularities(V, F, X)
    assert title.startswith("inspired: %d faces, %d singularities, %d quads, planarity max " % (len(F), len(S), len(Fq)))
    assert '"constrained":' in text and external_loads(text) == []


@needs_three_js
def test_the_page_without_quads_and_its_options(road, tmp_path):
    V, F, _, X, _, _, _, _, _, _ = road
    page = tmp_path / "field.html"
    # No singularity given as an empty array; the field on 1 face in 4.
    pvf.write_html_viewer(page, V, F, X, singularities=np.zeros((0, 2), dtype=np.int64),
                          max_glyph_faces=(len(F) + 3) // 4, three_js_directory=THREE_JS)
    text, title = title_of(page)
    assert title == "CGAL Polyvector Fields: %d faces, 0 singularities" % len(F)
    assert '"stride":4' in text and '"constrained":' not in text and external_loads(text) == []


@needs_three_js
def test_a_missing_three_js_leaves_no_file(road, tmp_path):
    V, F, _, X, _, _, _, Vq, Fq, _ = road
    missing = tmp_path / "no-three"
    out = tmp_path / "out"
    out.mkdir()
    with pytest.raises(pvf.Error) as e:
        pvf.write_html_viewer(out / "page.html", V, F, X, Vq=Vq, Fq=Fq, three_js_directory=missing)
    assert e.value.code == "CANNOT_OPEN_FILE"
    assert str(missing / "three.min.js") in str(e.value) and "write_html_viewer" in str(e.value)
    assert os.listdir(out) == []
    # A page already there is left as it was.
    (out / "page.html").write_text("before")
    with pytest.raises(pvf.Error):
        pvf.write_html_viewer(out / "page.html", V, F, X, three_js_directory=str(missing))
    assert (out / "page.html").read_text() == "before" and os.listdir(out) == ["page.html"]


# A square of two triangles, a field of 4 vectors per face, one quad.
SV = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], dtype=float)
SF = np.array([[0, 1, 2], [1, 3, 2]])
SX = np.tile([1.0, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0], (2, 1))
SQ = np.array([[0, 1, 3, 2]])

BAD_PAGES = [
    ("BAD_ARRAY", "X: expected one row per face of F (2), got 1", dict(X=SX[:1])),
    ("NON_FINITE_VALUE", "X[0, 1] is nan", dict(X=np.where(np.arange(24).reshape(2, 12) == 1, np.nan, SX))),
    ("BAD_ARRAY", "Fq: Vq and Fq go together", dict(Vq=SV)),
    ("BAD_ARRAY", "Fq[0, 2] = 4 is not a vertex of Vq", dict(Vq=SV, Fq=np.array([[0, 1, 4, 2]]))),
    ("BAD_ARRAY", "Fq row 0: -1 pads the end of a row only", dict(Vq=SV, Fq=np.array([[0, 1, 3, -1, 2]]))),
    ("BAD_ARRAY", "Fq row 0: a polygon has at least 3 corners", dict(Vq=SV, Fq=np.array([[0, 1, -1, -1]]))),
    ("BAD_ARRAY", "singularities[0, 0] = 7 is not a vertex of V", dict(singularities=np.array([[7, 1]]))),
    ("BAD_ARRAY", "singularities: expected shape (n, 2)", dict(singularities=np.array([1, 2, 3]))),
    ("INVALID_PARAMETER", "write_html_viewer", dict(singularities=np.array([[0, 0]]))),  # a zero index
    ("BAD_ARRAY", "constrained_faces[0, 0] = 2 is not a face of F", dict(constrained_faces=[2])),
    ("INVALID_PARAMETER", "max_glyph_faces must be at least 1", dict(max_glyph_faces=0)),
    ("INVALID_PARAMETER", "max_glyph_faces: -3 is not in 0..", dict(max_glyph_faces=-3)),
    ("INVALID_PARAMETER", "max_glyph_faces: expected an integer", dict(max_glyph_faces=2.5)),
    ("INVALID_PARAMETER", "write_html_viewer", dict(Vq=SV, Fq=SQ, planarity_colour_range=-1.0)),
    ("INVALID_PARAMETER", "planarity_colour_range: expected a number", dict(planarity_colour_range="red")),
    ("INVALID_PARAMETER", "page_title: expected a string", dict(page_title=3)),
]


@needs_three_js
@pytest.mark.parametrize("code, text, changes", BAD_PAGES, ids=[c[1][:40] for c in BAD_PAGES])
def test_a_bad_page_input_is_refused_and_writes_nothing(code, text, changes, tmp_path):
    args = dict(V=SV, F=SF, X=SX)
    args.update(changes)
    with pytest.raises(pvf.Error) as e:
        pvf.write_html_viewer(tmp_path / "page.html", **args)
    assert e.value.code == code and text in str(e.value), str(e.value)
    assert os.listdir(tmp_path) == []


@needs_three_js
def test_the_square_page_works(tmp_path):
    # The cases above fail for their stated reason only.
    pvf.write_html_viewer(tmp_path / "page.html", SV, SF, SX, Vq=SV, Fq=SQ, constrained_faces=[0, 1])
    _, title = title_of(tmp_path / "page.html")
    assert title == "CGAL Polyvector Fields: 2 faces, 0 singularities, 1 quads, planarity max 0%, mean 0%"


def read_ply(path):
    lines = open(path, encoding="ascii").read().split("\n")
    end = lines.index("end_header")
    header = lines[:end]
    vertices = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    faces = int(next(l for l in header if l.startswith("element face")).split()[2])
    at = header.index(next(l for l in header if l.startswith("element face")))
    properties = [l.split()[-1] for l in header[at + 1:] if l.startswith("property")]
    rows = []
    for line in lines[end + 1 + vertices:end + 1 + vertices + faces]:
        values = line.split()
        n = int(values[0])
        rows.append((n, dict(zip(properties[1:], values[1 + n:]))))
    return vertices, rows


def test_the_ply_holds_the_planarity_of_each_quad(road, tmp_path):
    _, _, _, _, _, _, _, Vq, Fq, _ = road
    P, _ = pvf.quad_planarity(Vq, Fq)
    pvf.write_quad_mesh_ply(tmp_path / "quads.ply", Vq, Fq)
    assert os.listdir(tmp_path) == ["quads.ply"]
    vertices, rows = read_ply(tmp_path / "quads.ply")
    assert vertices == len(Vq) and len(rows) == len(Fq) and all(n == 4 for n, _ in rows)
    quality = np.array([float(p["quality"]) for _, p in rows])
    assert np.allclose(quality, P, rtol=1e-5, atol=1e-12)
    # The worst quad red, the most planar one blue (the colour range is the largest planarity).
    worst, best = rows[int(np.argmax(P))][1], rows[int(np.argmin(P))][1]
    assert int(worst["red"]) > 2 * int(worst["blue"]) and int(best["blue"]) > 2 * int(best["red"])
    # A range below every non-zero planarity gives all those quads the colour of its top.
    pvf.write_quad_mesh_ply(tmp_path / "red.ply", Vq, Fq, planarity_colour_range=P[P > 0].min() / 2)
    _, red = read_ply(tmp_path / "red.ply")
    assert len({(p["red"], p["green"], p["blue"]) for (_, p), x in zip(red, P) if x > 0}) == 1


@pytest.mark.parametrize("code, text, args", [
    ("BAD_ARRAY", "Fq[0, 3] = 9 is not a vertex of Vq", (SV, np.array([[0, 1, 3, 9]]))),
    ("EMPTY_MESH", "Fq: the mesh has no face", (SV, np.zeros((0, 4), dtype=int))),
    ("INVALID_PARAMETER", "write_quad_mesh_ply", (SV, SQ, -1.0)),
    ("NON_FINITE_VALUE", "Vq[3, 2] is inf", (np.where(np.arange(12).reshape(4, 3) == 11, np.inf, SV), SQ)),
], ids=["index", "empty", "range", "inf"])
def test_a_bad_ply_input_is_refused_and_writes_nothing(code, text, args, tmp_path):
    with pytest.raises(pvf.Error) as e:
        pvf.write_quad_mesh_ply(tmp_path / "q.ply", *args)
    assert e.value.code == code and text in str(e.value), str(e.value)
    assert os.listdir(tmp_path) == []


def polygon_area(Vq, Fq):
    """The area of each polygon (rows padded with -1), by the fan from its first corner."""
    areas = []
    for row in Fq:
        p = Vq[row[row >= 0]]
        areas.append(sum(0.5 * np.linalg.norm(np.cross(p[k] - p[0], p[k + 1] - p[0])) for k in range(1, len(p) - 1)))
    return np.array(areas)


def test_the_trimmed_boundary_covers_the_whole_surface(road, tmp_path):
    V, F, _, _, UV, FUV, minfo, Vq, Fq, qinfo = road
    Vt, Ft, tinfo = pvf.quad_mesh(V, F, UV, FUV, minfo["seam_transitions"], keep_trimmed_boundary=True)
    corners = (Ft >= 0).sum(axis=1)
    assert tinfo["trimmed_polygons"] > 0 and Ft.shape[1] == corners.max() and corners.min() >= 3
    assert ((corners < Ft.shape[1]) == (Ft[:, -1] == -1)).all()  # -1 only at the end of the shorter rows
    # The whole cells are the default extraction's quads; the polygons of the border are added.
    assert tinfo["quads"] == qinfo["quads"] and len(Ft) == qinfo["quads"] + tinfo["trimmed_polygons"]
    # The trimmed mesh covers the surface (its border is the mesh's), the whole cells only part of it.
    area = 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1).sum()
    whole, trimmed = polygon_area(Vq, Fq).sum(), polygon_area(Vt, Ft).sum()
    assert abs(trimmed - area) <= 0.005 * area, (trimmed, area)  # measured: 99.99% of the area
    assert whole <= 0.95 * area, (whole, area)  # measured: 86%
    # Such rows are saved as polygons, and drawn and written by the writers.
    pvf.save_mesh(tmp_path / "trimmed.off", Vt, Ft)
    umask = os.umask(0)
    os.umask(umask)
    assert os.stat(tmp_path / "trimmed.off").st_mode & 0o777 == 0o666 & ~umask  # not mkstemp's 0600
    lines = (tmp_path / "trimmed.off").read_text().split("\n")
    assert [int(l.split()[0]) for l in lines[2 + len(Vt):2 + len(Vt) + len(Ft)]] == corners.tolist()
    pvf.write_quad_mesh_ply(tmp_path / "trimmed.ply", Vt, Ft)
    _, rows = read_ply(tmp_path / "trimmed.ply")
    assert [n for n, _ in rows] == corners.tolist()
    assert all(float(p["quality"]) == -1.0 for n, p in rows if n != 4)  # not a quad: no planarity
    with pytest.raises(pvf.Error) as e:
        pvf.quad_mesh(V, F, UV, FUV, keep_trimmed_boundary=1)
    assert e.value.code == "INVALID_PARAMETER" and "keep_trimmed_boundary" in str(e.value)


def test_quad_remesh_passes_keep_trimmed_boundary_on(inspired):
    V, F, _, _ = inspired
    Vq, Fq, info = pvf.quad_remesh(V, F, quads=400, sharp_edges=None, boundary_alignment=False,
                                   keep_trimmed_boundary=True)
    corners = (Fq >= 0).sum(axis=1)
    assert info["quads"]["trimmed_polygons"] > 0 and (corners != 4).any()
    # The planarity is that of the faces with 4 corners.
    P, planarity = pvf.quad_planarity(Vq, Fq[corners == 4][:, :4])
    assert info["planarity"]["max"] == planarity["max"] and info["planarity"]["faces"] == (corners == 4).sum()
    X = info["X"]
    assert X.shape == (len(info["F"]), 12)
    # with the default size too, the border's polygons are kept; they are not
    # measured against the input, so no deviation bound makes the size finer
    _, Fd, default = pvf.quad_remesh(V, F, sharp_edges=None, boundary_alignment=False, keep_trimmed_boundary=True)
    assert default["max_deviation"] is None and default["finer_sizes"] == [] and default["split_at"] is None
    assert default["quads"]["trimmed_polygons"] > 0 and ((Fd >= 0).sum(axis=1) != 4).any()
    with pytest.raises(pvf.Error) as e:
        pvf.quad_remesh(V, F, quads=400, keep_trimmed_boundary=True, planarize=True)
    assert e.value.code == "INVALID_PARAMETER" and "keep_trimmed_boundary" in str(e.value)


@needs_three_js
@pytest.mark.skipif(shutil.which("chromium") is None, reason="chromium is not installed (Debian: chromium)")
def test_the_python_page_in_a_browser(bumpy_road, tmp_path):
    # One headless Chromium run of the checks of test/Polyvector_fields/html_viewer_check.py: the viewer
    # ran to its end without a JavaScript error, with the layers of a page with quads, and found
    # the worst quad at the largest planarity.
    sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "test", "Polyvector_fields"))
    import html_viewer_check as check
    V, F, X, Vq, Fq = bumpy_road
    _, planarity = pvf.quad_planarity(Vq, Fq)
    page = tmp_path / "page.html"
    pvf.write_html_viewer(page, V, F, X, Vq=Vq, Fq=Fq)
    start = time.time()
    status = check.check_dom(check.chromium(shutil.which("chromium"), "file://" + str(page), str(tmp_path),
                                            ["--dump-dom"]), "page written from Python")
    print("chromium: %.1f s" % (time.time() - start))
    assert status.get("data-layers") == "singularities,quads"
    assert abs(float(status["data-worst-planarity"]) - planarity["max"]) <= 1e-5 * planarity["max"]
