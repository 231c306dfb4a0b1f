#!/usr/bin/python3
# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.
"""Regenerates every figure of the user manual (doc/Polyvector_fields/fig/*.png).

    /usr/bin/python3 doc/Polyvector_fields/make_figures.py [BUILD_DIR] [--parametrization]

BUILD_DIR (default: build/ in the repository) is a CMake build folder of the
package. The program design_polyvector_field is built there if it is missing.
It is run on the bundled meshes; its legacy VTK outputs are written to a
temporary folder, read back here, and drawn headless with matplotlib (Debian:
python3-matplotlib, installed by `scripts/install_dependencies.sh --doc`).
With --parametrization only the figures of the integer-grid maps and of the
quad meshes are made: the program's OBJ outputs (one uv per corner) are drawn
as a checkerboard of period one uv unit, rasterised per pixel, and its quad
meshes (VTK with the planarity of each face) coloured by planarity.

Each picture is an orthographic view from a fixed camera. Faces are flat
shaded and drawn back to front; a glyph (one short segment per vector from the
face centre, all of the same length except in limitation_scale.png: only
directions are shown) is drawn on a subset of the faces that are seen, one per
screen cell; hidden glyphs and dots are removed with a depth buffer. Singular
vertices are dots: red for positive indices, blue for negative ones.
Constrained faces are orange: filled, ringed, or outlined where they cluster.
Look at every picture after a change: the cameras are fixed by hand.
"""

import os
import subprocess
import sys
import tempfile

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402
from matplotlib import cm, colors  # noqa: E402

CONSTRAINT_COLOR = "#ff8c1a"
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
DATA = os.path.join(ROOT, "data")
FIG = os.path.join(HERE, "fig")

# ---------------------------------------------------------------------------
# Running the package
# ---------------------------------------------------------------------------


def designer(build_dir):
    """Returns the path of design_polyvector_field, configured and (re)built if needed."""
    if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
        subprocess.run(["cmake", "-S", ROOT, "-B", build_dir], check=True)
    # A no-op when the program is up to date; otherwise the figures follow the current sources.
    subprocess.run(["cmake", "--build", build_dir, "--target", "design_polyvector_field"], check=True)
    return os.path.join(build_dir, "tools", "design_polyvector_field", "design_polyvector_field")


def run(exe, workdir, name, args):
    """Runs the designer with `args`; returns the parsed VTK file, with the report in field["report"]."""
    vtk = os.path.join(workdir, name + ".vtk")
    command = [exe] + args + ["--out-vtk", vtk,
                              "--out-field", os.path.join(workdir, name + ".rawfield"),
                              "--out-singularities", os.path.join(workdir, name + ".sings")]
    print("$ " + " ".join(os.path.relpath(a, ROOT) if a.startswith(ROOT) else a for a in command[1:]))
    done = subprocess.run(command, check=True, capture_output=True, text=True)
    sys.stdout.write("".join("    " + line + "\n" for line in done.stdout.splitlines()))
    field = read_vtk(vtk)
    field["report"] = done.stdout
    return field


def times(report):
    """The stage times of the program's report line `time (s)  stage t; stage t; ...`."""
    line = next(l for l in report.splitlines() if l.startswith("time (s)"))
    out = {}
    for item in line[len("time (s)"):].split(";"):
        item = item.strip()
        if item:
            name, value = item.rsplit(" ", 1)
            out[name] = float(value)
    return out


# ---------------------------------------------------------------------------
# Legacy VTK (ASCII UNSTRUCTURED_GRID) as written by IO::write_VTK()
# ---------------------------------------------------------------------------


def read_vtk(path):
    with open(path) as f:
        tokens = f.read().split()
    pos = 0

    def take(n):
        nonlocal pos
        out = tokens[pos:pos + n]
        pos += n
        return out

    data = {"vectors": {}, "scalars": {}}
    while pos < len(tokens):
        word = tokens[pos]
        pos += 1
        if word == "POINTS":
            n = int(take(2)[0])
            data["points"] = np.array(take(3 * n), dtype=float).reshape(n, 3)
        elif word == "CELLS":
            n, size = (int(t) for t in take(2))
            flat = np.array(take(size), dtype=np.int64)
            cells, i = [], 0
            for _ in range(n):
                k = flat[i]
                cells.append(flat[i + 1:i + 1 + k])
                i += k + 1
            data["cells"] = cells
        elif word == "CELL_TYPES":
            n = int(take(1)[0])
            data["types"] = np.array(take(n), dtype=int)
        elif word == "CELL_DATA":
            data["ncells"] = int(take(1)[0])
        elif word == "VECTORS":
            name, _ = take(2)
            data["vectors"][name] = np.array(take(3 * data["ncells"]), dtype=float).reshape(-1, 3)
        elif word == "SCALARS":
            name, _ = take(2)
            if tokens[pos] == "1":  # optional number of components
                pos += 1
            if tokens[pos] == "LOOKUP_TABLE":
                pos += 2
            data["scalars"][name] = np.array(take(data["ncells"]), dtype=float)
    types = data["types"]
    tri = types == 5
    field = {}
    field["points"] = data["points"]
    field["faces"] = np.array([c for c, t in zip(data["cells"], types) if t == 5], dtype=np.int64)
    k = 0
    roots = []
    while "root_%d" % k in data["vectors"]:
        roots.append(data["vectors"]["root_%d" % k][tri])
        k += 1
    field["roots"] = np.stack(roots, axis=1)  # F x N x 3
    field["scalars"] = {name: v[tri] for name, v in data["scalars"].items()}
    vertex_cells = np.nonzero(types == 1)[0]
    field["singular_vertices"] = np.array([data["cells"][i][0] for i in vertex_cells], dtype=np.int64)
    field["singular_index"] = data["scalars"]["singularity_index"][vertex_cells]
    return field


# ---------------------------------------------------------------------------
# Rendering
# ---------------------------------------------------------------------------


def camera(azimuth, elevation):
    """Rotation whose rows are the screen x, screen y and towards-viewer axes."""
    a, e = np.radians(azimuth), np.radians(elevation)
    view = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])  # towards the viewer
    up = np.array([0.0, 0.0, 1.0])
    x = np.cross(up, view)
    if np.linalg.norm(x) < 1e-9:
        x = np.array([0.0, 1.0, 0.0])
    x /= np.linalg.norm(x)
    y = np.cross(view, x)
    return np.stack([x, y, view])


def depth_buffer(p2, depth, faces, visible, resolution):
    """Rasterises the visible triangles; returns (buffer, to_pixel)."""
    lo, hi = p2.min(axis=0), p2.max(axis=0)
    scale = (resolution - 1) / (hi - lo).max()
    pix = (p2 - lo) * scale
    zbuf = np.full((resolution, resolution), -np.inf)
    for f in np.nonzero(visible)[0]:
        a, b, c = pix[faces[f]]
        x0, y0 = np.floor(np.minimum(np.minimum(a, b), c)).astype(int)
        x1, y1 = np.ceil(np.maximum(np.maximum(a, b), c)).astype(int)
        xs, ys = np.meshgrid(np.arange(max(x0, 0), min(x1, resolution - 1) + 1),
                             np.arange(max(y0, 0), min(y1, resolution - 1) + 1))
        px, py = xs.ravel().astype(float), ys.ravel().astype(float)
        det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
        if abs(det) < 1e-12:
            continue
        l1 = ((px - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (py - a[1])) / det
        l2 = ((b[0] - a[0]) * (py - a[1]) - (px - a[0]) * (b[1] - a[1])) / det
        l0 = 1 - l1 - l2
        inside = (l0 >= -0.02) & (l1 >= -0.02) & (l2 >= -0.02)
        if not inside.any():
            continue
        za, zb, zc = depth[faces[f]]
        z = l0 * za + l1 * zb + l2 * zc
        ix, iy = xs.ravel()[inside], ys.ravel()[inside]
        np.maximum.at(zbuf, (iy, ix), z[inside])
    return zbuf, lambda q: np.clip(np.round((q - lo) * scale).astype(int), 0, resolution - 1)


def render(field, ax, azimuth, elevation, title=None, glyph_cells=38, glyph_scale=0.42,
           color_by=None, cmap="viridis", vmin=None, vmax=None, constrained=True, glyph_color="#1a1a2e",
           dot_size=38, glyph_width=0.9, ring_size=90, outline=False, glyph_reference=None):
    """Draws `field` into the axes `ax`, seen from the camera (azimuth, elevation) in degrees.

    color_by: one value per face, drawn with `cmap` between vmin and vmax (else grey faces).
    glyph_cells: number of screen cells across the picture; one glyph per cell.
    ring_size: size of the rings around constrained faces (0: none); outline: outline them instead.
    glyph_reference: if given, a vector of this length gets a full-length glyph and shorter vectors
    shorter glyphs (else every glyph has the same length).
    """
    P, F, R = field["points"], field["faces"], field["roots"]
    rot = camera(azimuth, elevation)
    q = P @ rot.T
    p2, depth = q[:, :2], q[:, 2]
    tri = q[F]
    normal = np.cross(P[F[:, 1]] - P[F[:, 0]], P[F[:, 2]] - P[F[:, 0]])
    area2 = np.linalg.norm(normal, axis=1)
    normal = normal / np.maximum(area2, 1e-300)[:, None]
    facing = normal @ rot[2]
    # Open meshes are seen from both sides: orient every face towards the viewer.
    shade_normal = normal * np.where(facing < 0, -1.0, 1.0)[:, None]
    light = np.array([0.35, 0.45, 0.82])
    light /= np.linalg.norm(light)
    lambert = np.clip((shade_normal @ rot.T) @ light, 0, 1)
    shade = 0.45 + 0.55 * lambert

    if color_by is not None:
        norm = colors.Normalize(vmin=np.min(color_by) if vmin is None else vmin,
                                vmax=np.max(color_by) if vmax is None else vmax)
        base = cm.get_cmap(cmap)(norm(color_by))[:, :3]
    else:
        base = np.tile(np.array([0.80, 0.82, 0.86]), (len(F), 1))
    is_constrained = field["scalars"].get("is_constrained")
    if constrained and is_constrained is not None and color_by is None:
        base[is_constrained > 0.5] = np.array(colors.to_rgb(CONSTRAINT_COLOR))
    face_rgb = np.clip(base * shade[:, None], 0, 1)

    order = np.argsort(tri[:, :, 2].mean(axis=1))  # back to front
    ax.add_collection(PolyCollection(tri[order, :, :2], facecolors=face_rgb[order],
                                     edgecolors=face_rgb[order] * 0.93, linewidths=0.15))

    # Depth buffer for glyph and dot visibility.
    resolution = 700
    zbuf, to_pixel = depth_buffer(p2, depth, F, np.ones(len(F), bool), resolution)
    extent = (p2.max(axis=0) - p2.min(axis=0)).max()
    tolerance = 4e-3 * extent

    centroid = P[F].mean(axis=1)
    c2 = centroid @ rot.T
    pix = to_pixel(c2[:, :2])
    seen = c2[:, 2] >= zbuf[pix[:, 1], pix[:, 0]] - tolerance
    # One glyph per screen cell, on the face nearest to the cell centre.
    cell = extent / glyph_cells
    lo = p2.min(axis=0)
    key = np.floor((c2[:, :2] - lo) / cell).astype(int)
    offset = np.linalg.norm((c2[:, :2] - lo) / cell - key - 0.5, axis=1)
    chosen = {}
    for f in np.nonzero(seen)[0]:
        k = (key[f, 0], key[f, 1])
        if k not in chosen or offset[f] < offset[chosen[k]]:
            chosen[k] = f
    glyph_faces = set(chosen.values())
    marked = np.zeros(0, dtype=np.int64)
    if constrained and is_constrained is not None:
        marked = np.nonzero(seen & (is_constrained > 0.5))[0]
        if not outline:
            glyph_faces.update(marked.tolist())
    glyph_faces = np.array(sorted(glyph_faces), dtype=np.int64)
    length = glyph_scale * cell
    segments = []
    for f in glyph_faces:
        for v in R[f]:
            n = np.linalg.norm(v)
            if n < 1e-12:
                continue
            d = (v / n) @ rot.T
            if glyph_reference:
                d = d * min(n / glyph_reference, 1.5)
            start = c2[f, :2]
            segments.append([start, start + length * d[:2]])
    ax.add_collection(LineCollection(segments, colors=glyph_color, linewidths=glyph_width, capstyle="round"))
    if len(marked) and outline:
        # Constrained faces drawn with an outline (for clusters of constraints, where rings would merge).
        ax.add_collection(PolyCollection(tri[marked, :, :2], facecolors="none", edgecolors=CONSTRAINT_COLOR,
                                         linewidths=1.0, zorder=3))
    elif len(marked) and ring_size:
        ax.scatter(c2[marked, 0], c2[marked, 1], s=ring_size, facecolors="none",
                   edgecolors=CONSTRAINT_COLOR, linewidths=1.6, zorder=4)

    # Singularities.
    sv, si = field["singular_vertices"], field["singular_index"]
    if len(sv):
        sq = P[sv] @ rot.T
        spx = to_pixel(sq[:, :2])
        vis = sq[:, 2] >= zbuf[spx[:, 1], spx[:, 0]] - 3 * tolerance
        for sign, color in ((1, "#d7191c"), (-1, "#2b83ba")):
            m = vis & (np.sign(si) == sign)
            ax.scatter(sq[m, 0], sq[m, 1], s=dot_size, c=color, edgecolors="white", linewidths=0.7, zorder=5)

    pad = 0.03 * extent
    ax.set_xlim(p2[:, 0].min() - pad, p2[:, 0].max() + pad)
    ax.set_ylim(p2[:, 1].min() - pad, p2[:, 1].max() + pad)
    ax.set_aspect("equal")
    ax.axis("off")
    if title:
        ax.set_title(title, fontsize=10)
    return len(glyph_faces)


def save(fig, name):
    """Writes the figure as an 8-bit palette PNG (a quarter of the size of RGBA)."""
    from PIL import Image
    path = os.path.join(FIG, name)
    fig.canvas.draw()
    rgba = np.asarray(fig.canvas.buffer_rgba())
    plt.close(fig)
    image = Image.fromarray(rgba[:, :, :3].copy())
    try:  # libimagequant keeps small saturated marks (singularities) in the palette
        image = image.quantize(colors=256, method=Image.Quantize.LIBIMAGEQUANT, dither=Image.Dither.NONE)
    except (ValueError, OSError):
        image = image.quantize(colors=256, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE)
    image.save(path, optimize=True)
    print("wrote %s (%d KB)" % (os.path.relpath(path, ROOT), os.path.getsize(path) // 1024))


def truncated(name, low, high):
    """The part [low, high] of a matplotlib colour map, so that black glyphs stay readable on it."""
    return colors.LinearSegmentedColormap.from_list(name + "_part", cm.get_cmap(name)(np.linspace(low, high, 256)))


# ---------------------------------------------------------------------------
# The figures
# ---------------------------------------------------------------------------


def main():
    arguments = [a for a in sys.argv[1:] if not a.startswith("--")]
    only_parametrization = "--parametrization" in sys.argv[1:]  # the integer-grid maps and the quad meshes
    build_dir = os.path.abspath(arguments[0] if arguments else os.path.join(ROOT, "build"))
    exe = designer(build_dir)
    os.makedirs(FIG, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="pvf_figures_") as work:
        if not only_parametrization:
            figures(exe, work)
        parametrization_figures(exe, work)
        planar_quads_figure(exe, work)


# ---------------------------------------------------------------------------
# Integer-grid maps: a checkerboard of period one uv unit (one quad) on the surface
# ---------------------------------------------------------------------------


def read_uv_obj(path):
    """The OBJ of IO::write_integer_grid_map_OBJ(): points, triangles, and the uv of each corner (F x 3 x 2)."""
    points, uvs, faces, corners = [], [], [], []
    with open(path) as f:
        for line in f:
            t = line.split()
            if not t:
                continue
            if t[0] == "v":
                points.append([float(x) for x in t[1:4]])
            elif t[0] == "vt":
                uvs.append([float(x) for x in t[1:3]])
            elif t[0] == "f":
                pairs = [c.split("/") for c in t[1:]]
                faces.append([int(a) - 1 for a, _ in pairs])
                corners.append([int(b) - 1 for _, b in pairs])
    uvs = np.array(uvs)
    return np.array(points), np.array(faces, dtype=np.int64), uvs[np.array(corners, dtype=np.int64)]


def checkerboard(points, faces, corner_uv, ax, azimuth, elevation, title, resolution=900):
    """Rasterises the surface with a per-pixel depth test; each pixel takes the parity of floor(u) + floor(v)."""
    rot = camera(azimuth, elevation)
    q = points @ rot.T
    p2, depth = q[:, :2], q[:, 2]
    normal = np.cross(points[faces[:, 1]] - points[faces[:, 0]], points[faces[:, 2]] - points[faces[:, 0]])
    normal /= np.maximum(np.linalg.norm(normal, axis=1), 1e-300)[:, None]
    facing = normal @ rot[2]
    light = np.array([0.35, 0.45, 0.82])
    light /= np.linalg.norm(light)
    lambert = np.abs((normal @ rot.T) @ light)  # open meshes are seen from both sides
    shade = 0.35 + 0.65 * lambert
    lo, hi = p2.min(axis=0), p2.max(axis=0)
    scale = (resolution - 1) / (hi - lo).max()
    size = np.ceil((hi - lo) * scale).astype(int) + 1
    pix = (p2 - lo) * scale
    zbuf = np.full((size[1], size[0]), -np.inf)
    image = np.ones((size[1], size[0], 3))
    light_square, dark_square = np.array([0.93, 0.93, 0.90]), np.array([0.20, 0.36, 0.62])
    for f in range(len(faces)):
        a, b, c = pix[faces[f]]
        det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
        if abs(det) < 1e-12:
            continue
        x0, y0 = np.floor(np.minimum(np.minimum(a, b), c)).astype(int)
        x1, y1 = np.ceil(np.maximum(np.maximum(a, b), c)).astype(int)
        xs, ys = np.meshgrid(np.arange(max(x0, 0), min(x1, size[0] - 1) + 1),
                             np.arange(max(y0, 0), min(y1, size[1] - 1) + 1))
        px, py = xs.ravel() + 0.0, ys.ravel() + 0.0
        l1 = ((px - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (py - a[1])) / det
        l2 = ((b[0] - a[0]) * (py - a[1]) - (px - a[0]) * (b[1] - a[1])) / det
        l0 = 1 - l1 - l2
        inside = (l0 >= -1e-9) & (l1 >= -1e-9) & (l2 >= -1e-9)
        if not inside.any():
            continue
        l0, l1, l2 = l0[inside], l1[inside], l2[inside]
        ix, iy = xs.ravel()[inside], ys.ravel()[inside]
        z = l0 * depth[faces[f, 0]] + l1 * depth[faces[f, 1]] + l2 * depth[faces[f, 2]]
        front = z > zbuf[iy, ix]
        if not front.any():
            continue
        ix, iy, z = ix[front], iy[front], z[front]
        w = np.stack([l0[front], l1[front], l2[front]], axis=1)
        uv = w @ corner_uv[f]
        parity = (np.floor(uv[:, 0]) + np.floor(uv[:, 1])).astype(np.int64) % 2
        colour = np.where(parity[:, None] == 0, light_square, dark_square) * shade[f]
        zbuf[iy, ix] = z
        image[iy, ix] = colour
    ax.imshow(image, origin="lower", interpolation="bilinear")
    ax.axis("off")
    ax.set_title(title, fontsize=9)


def parametrization_figures(exe, work):
    inspired = ["--mesh", os.path.join(DATA, "inspired_mesh.obj"),
                "--dmat-b", os.path.join(DATA, "inspired_mesh_b.dmat"),
                "--dmat-bc", os.path.join(DATA, "inspired_mesh_bc.dmat"), "--edge-length", "0.82"]
    runs = [("inspired_smooth", "inspired_mesh, smooth field", inspired, (-70, 50)),
            ("inspired_conjugate", "inspired_mesh, conjugate field", inspired + ["--conjugate"], (-70, 50)),
            ("bumpy", "bumpy, 1% curvature constraints",
             ["--mesh", os.path.join(DATA, "bumpy.off"), "--curvature-constraints", "1"], (35, 28)),
            ("eight", "eight (genus 2), 1% curvature constraints",
             ["--mesh", os.path.join(DATA, "eight.off"), "--curvature-constraints", "1"], (-90, 55)),
            ("fandisk", "fandisk, sharp edges (30\u00b0)",
             ["--mesh", os.path.join(DATA, "fandisk.off"), "--sign-symmetric", "--sharp-edges", "30"], (40, 30))]
    fig = plt.figure(figsize=(12.0, 8.2), dpi=100)
    for i, (name, what, args, view) in enumerate(runs):
        obj = os.path.join(work, name + ".param.obj")
        f = run(exe, work, name, args + ["--parametrize", "--out-param", obj])
        line = next(l for l in f["report"].splitlines() if l.startswith("parametrization"))
        flipped = int(line.split(" flipped faces")[0].split()[-1])
        assert flipped == 0, line
        points, faces, corner_uv = read_uv_obj(obj)
        ax = fig.add_axes([(i % 3) / 3.0 + 0.003, 0.51 - 0.5 * (i // 3), 0.327, 0.41])
        checkerboard(points, faces, corner_uv, ax, view[0], view[1],
                     "%s\n%d faces, %d singularities, 0 flipped" % (what, len(faces), len(f["singular_vertices"])))
    save(fig, "integer_grid_maps.png")


def read_quads_vtk(path):
    """The POLYDATA of IO::write_quad_mesh_VTK(): points, polygons and the planarity of each."""
    with open(path) as f:
        tokens = f.read().split()
    pos = tokens.index("POINTS")
    n = int(tokens[pos + 1])
    points = np.array(tokens[pos + 3:pos + 3 + 3 * n], dtype=float).reshape(n, 3)
    pos = tokens.index("POLYGONS")
    count = int(tokens[pos + 1])
    i = pos + 3
    polygons = []
    for _ in range(count):
        k = int(tokens[i])
        polygons.append(np.array(tokens[i + 1:i + 1 + k], dtype=np.int64))
        i += k + 1
    pos = tokens.index("planarity", i)
    planarity = np.array(tokens[pos + 5:pos + 5 + count], dtype=float)  # after "double 1 LOOKUP_TABLE default"
    return points, polygons, planarity


def quads(points, polygons, planarity, ax, azimuth, elevation, title, vmax, cmap):
    """Flat-shaded polygons, back to front, coloured by planarity (clamped at vmax)."""
    rot = camera(azimuth, elevation)
    q = points @ rot.T
    light = np.array([0.35, 0.45, 0.82])
    light /= np.linalg.norm(light)
    shapes, rgb, depth = [], [], []
    norm = colors.Normalize(0, vmax)
    for poly, value in zip(polygons, planarity):
        p = points[poly]
        normal = np.cross(p[2] - p[0], p[3 % len(p)] - p[1])
        normal /= max(np.linalg.norm(normal), 1e-300)
        shade = 0.55 + 0.45 * abs((normal @ rot.T) @ light)
        rgb.append(np.clip(np.array(cm.get_cmap(cmap)(norm(min(value, vmax)))[:3]) * shade, 0, 1))
        shapes.append(q[poly, :2])
        depth.append(q[poly, 2].mean())
    order = np.argsort(depth)
    ax.add_collection(PolyCollection([shapes[i] for i in order], facecolors=[rgb[i] for i in order],
                                     edgecolors="#202020", linewidths=0.12))
    pad = 0.03 * (q[:, :2].max(axis=0) - q[:, :2].min(axis=0)).max()
    ax.set_xlim(q[:, 0].min() - pad, q[:, 0].max() + pad)
    ax.set_ylim(q[:, 1].min() - pad, q[:, 1].max() + pad)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title(title, fontsize=9)


def planar_quads_figure(exe, work):
    """The paper's Fig. 13: quads of the smooth and the conjugate field, before and after planarization."""
    inspired = ["--mesh", os.path.join(DATA, "inspired_mesh.obj"),
                "--dmat-b", os.path.join(DATA, "inspired_mesh_b.dmat"),
                "--dmat-bc", os.path.join(DATA, "inspired_mesh_bc.dmat"), "--edge-length", "0.82"]
    cmap, vmax = truncated("RdYlBu_r", 0.0, 1.0), 0.01
    fig = plt.figure(figsize=(11.0, 8.6), dpi=100)
    for column, (name, what, extra) in enumerate((("smooth", "smooth field", []),
                                                  ("conjugate", "conjugate field", ["--conjugate"]))):
        for row, planarize in enumerate((False, True)):
            tag = "quads_%s%s" % (name, "_planar" if planarize else "")
            args = inspired + extra + ["--quad-mesh", os.path.join(work, tag + ".off")]
            if planarize:
                args.append("--planarize")
            f = run(exe, work, tag, args)
            points, polygons, planarity = read_quads_vtk(os.path.join(work, tag + ".quads.vtk"))
            title = "%s, %s: %d quads\nplanarity max %.2f%%, mean %.2f%%" % (
                what, "planarized to 1%" if planarize else "extracted", len(polygons),
                100 * planarity.max(), 100 * planarity.mean())
            if planarize:
                line = next(l for l in f["report"].splitlines() if l.startswith("planarity"))
                iterations = line.split("after ")[1].split(" iterations")[0] if "after " in line else "?"
                title += " (%s iterations)" % iterations
            ax = fig.add_axes([0.005 + 0.47 * column, 0.53 - 0.47 * row, 0.46, 0.42])
            quads(points, polygons, planarity, ax, -70, 50, title, vmax, cmap)
    cax = fig.add_axes([0.92, 0.2, 0.015, 0.6])
    bar = fig.colorbar(cm.ScalarMappable(norm=colors.Normalize(0, 100 * vmax), cmap=cmap), cax=cax)
    bar.set_label("planarity (%); 1% and above in red", fontsize=8)
    save(fig, "planar_quads_inspired.png")


def legend(fig, entries, y=0.01):
    from matplotlib.lines import Line2D
    handles = []
    for label, color, marker in entries:
        if marker == "outline":
            handles.append(Line2D([], [], marker="^", linestyle="none", markersize=9, markerfacecolor="none",
                                  markeredgecolor=color, markeredgewidth=1.3, label=label))
        elif marker == "square":
            handles.append(Line2D([], [], marker="s", linestyle="none", markersize=8, color=color, label=label))
        elif marker == "ring":
            handles.append(Line2D([], [], marker="o", linestyle="none", markersize=9, markerfacecolor="none",
                                  markeredgecolor=color, markeredgewidth=1.6, label=label))
        else:
            handles.append(Line2D([], [], marker="o", linestyle="none", markersize=7, color=color,
                                  markeredgecolor="white", label=label))
    fig.legend(handles=handles, loc="lower center", ncol=len(entries), fontsize=8, frameon=False,
               bbox_to_anchor=(0.5, y))


SINGULARITIES = [("singularity, index > 0", "#d7191c", "o"), ("singularity, index < 0", "#2b83ba", "o")]
CONSTRAINED = ("constrained face", CONSTRAINT_COLOR, "ring")


def single(field, name, azimuth, elevation, size=(6.4, 5.6), **options):
    fig = plt.figure(figsize=size, dpi=110)
    ax = fig.add_axes([0.0, 0.06, 1.0, 0.94])
    render(field, ax, azimuth, elevation, **options)
    constrained = CONSTRAINED if options.get("ring_size", 1) else ("constrained face", CONSTRAINT_COLOR, "square")
    legend(fig, [constrained] + SINGULARITIES)
    save(fig, name)


def pair(fields, titles, name, azimuth, elevation, array, cmap, vmin, vmax, label, size=(11.0, 5.0), **options):
    fig = plt.figure(figsize=size, dpi=100)
    for i, (field, title) in enumerate(zip(fields, titles)):
        ax = fig.add_axes([0.0 + 0.455 * i, 0.08, 0.45, 0.84])
        render(field, ax, azimuth, elevation, color_by=field["scalars"][array], cmap=cmap,
               vmin=vmin, vmax=vmax, title=title, **options)
    cax = fig.add_axes([0.925, 0.2, 0.013, 0.6])
    fig.colorbar(cm.ScalarMappable(norm=colors.Normalize(vmin, vmax), cmap=cmap), cax=cax).set_label(label, fontsize=8)
    constrained = ("constrained face", CONSTRAINT_COLOR, "outline") if options.get("outline") else CONSTRAINED
    legend(fig, [constrained] + SINGULARITIES)
    save(fig, name)


def frames_figure(field, name):
    """A close view of a patch of faces: each face's frame (e1, e2) and the field's vectors.

    The frames come from the file: write_VTK() lists the corners of face f as
    source(h), target(h), target(next(h)) with h = halfedge(f), so e1 is the
    direction of the first corner to the second, as in Face_frame.
    """
    P, F, R = field["points"], field["faces"], field["roots"]
    centroid = P[F].mean(axis=1)
    normal = np.cross(P[F[:, 1]] - P[F[:, 0]], P[F[:, 2]] - P[F[:, 0]])
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    edge = np.linalg.norm(P[F[:, 1]] - P[F[:, 0]], axis=1).mean()
    # The patch: the flattest neighbourhood among the faces that look towards a fixed direction.
    direction = np.array([0.3, -1.0, 0.4])
    direction /= np.linalg.norm(direction)
    best, patch = -2.0, None
    for f in np.nonzero(normal @ direction > 0.6)[0]:
        near = np.nonzero(np.linalg.norm(centroid - centroid[f], axis=1) < 2.4 * edge)[0]
        flatness = (normal[near] @ normal[f]).min()
        if flatness > best:
            best, patch, centre = flatness, near, centroid[f]
    n = normal[patch].sum(axis=0)
    n /= np.linalg.norm(n)
    azimuth, elevation = np.degrees(np.arctan2(n[1], n[0])), np.degrees(np.arcsin(n[2]))
    rot = camera(azimuth, elevation)
    q = P @ rot.T
    fig = plt.figure(figsize=(5.6, 5.4), dpi=110)
    ax = fig.add_axes([0.0, 0.08, 1.0, 0.92])
    light = 0.55 + 0.45 * np.clip(normal[patch] @ rot[2], 0, 1)
    ax.add_collection(PolyCollection(q[F[patch]][:, :, :2], facecolors=np.outer(light, [0.86, 0.87, 0.90]),
                                     edgecolors="#6b6b7b", linewidths=0.8))
    length = 0.3 * edge
    half = 1.9 * edge
    centre2 = (centre @ rot.T)[:2]
    for f in patch:
        c = centroid[f] @ rot.T
        if np.abs(c[:2] - centre2).max() > half - 0.45 * edge:
            continue  # its glyphs would be cut by the border of the picture
        e1 = P[F[f, 1]] - P[F[f, 0]]
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(normal[f], e1)
        for axis, color in ((e1, "#d7191c"), (e2, "#1a9641")):
            d = axis @ rot.T
            ax.annotate("", xy=(c[0] + length * d[0], c[1] + length * d[1]), xytext=(c[0], c[1]),
                        arrowprops=dict(arrowstyle="-|>", color=color, lw=1.4, mutation_scale=9), zorder=4)
        for v in R[f]:
            d = (v / np.linalg.norm(v)) @ rot.T
            ax.plot([c[0], c[0] + 0.75 * length * d[0]], [c[1], c[1] + 0.75 * length * d[1]],
                    color="#1a1a2e", lw=1.1, solid_capstyle="round", zorder=3)
    ax.set_xlim(centre2[0] - half, centre2[0] + half)
    ax.set_ylim(centre2[1] - half, centre2[1] + half)
    ax.set_aspect("equal")
    ax.axis("off")
    from matplotlib.lines import Line2D
    handles = [Line2D([], [], color="#d7191c", lw=1.6, label="e1, along halfedge(f)"),
               Line2D([], [], color="#1a9641", lw=1.6, label="e2 = n x e1"),
               Line2D([], [], color="#1a1a2e", lw=1.2, label="field vectors")]
    fig.legend(handles=handles, loc="lower center", ncol=3, fontsize=8, frameon=False, bbox_to_anchor=(0.5, 0.01))
    save(fig, name)


def figures(exe, work):
    bumpy = os.path.join(DATA, "bumpy.off")

    # 1. A 4-PolyVector field (four independent vectors) from random hard constraints.
    f = run(exe, work, "bumpy4", ["--mesh", bumpy, "--degree", "4", "--random-constraints", "12", "--seed", "3"])
    single(f, "polyvector4_bumpy.png", 35, 28, glyph_cells=32, glyph_scale=0.45)
    frames_figure(f, "face_frames.png")

    # N-RoSy fields: without constraints, the smoothest field of unit N-RoSy vectors.
    rosy3 = run(exe, work, "bumpy_rosy3", ["--mesh", bumpy, "--degree", "3"])
    rosy4 = run(exe, work, "eight_rosy4", ["--mesh", os.path.join(DATA, "eight.off"), "--degree", "4"])
    fig = plt.figure(figsize=(11.0, 5.0), dpi=100)
    for i, (fld, what, n, chi, view) in enumerate(((rosy3, "3-RoSy field, sphere", 3, 2, (35, 28)),
                                                   (rosy4, "4-RoSy field, genus 2", 4, -2, (-90, 55)))):
        ax = fig.add_axes([0.005 + 0.5 * i, 0.08, 0.49, 0.84])
        k = np.rint(fld["singular_index"] * n).astype(int)
        title = "%s: %d singularities, index sum %d/%d = %d = \u03c7" % (what, len(k), k.sum(), n, chi)
        render(fld, ax, view[0], view[1], title=title, glyph_cells=32, glyph_scale=0.5)
        assert k.sum() == n * chi
    legend(fig, SINGULARITIES)
    save(fig, "rosy_singularities.png")

    # 2. A sign-symmetric 6-PolyVector field with partial constraints along the sharp edges of fandisk.
    f = run(exe, work, "fandisk6", ["--mesh", os.path.join(DATA, "fandisk.off"), "--degree", "6",
                                    "--sign-symmetric", "--sharp-edges", "30"])
    single(f, "polyvector6_fandisk.png", 40, 30, glyph_cells=34, glyph_scale=0.45, ring_size=0)

    # 3. A smooth frame field from curvature constraints (2 % of the faces).
    f = run(exe, work, "bumpy_curvature", ["--mesh", bumpy, "--curvature-constraints", "2"])
    single(f, "curvature_constraints.png", 35, 28, glyph_cells=32, glyph_scale=0.45)

    # 4. Angle bound: the smooth frame field from random (skewed) constraints, and the same with a 70 degree bound.
    common = ["--mesh", bumpy, "--sign-symmetric", "--random-constraints", "12", "--seed", "2"]
    smooth = run(exe, work, "bumpy_free", common)
    bounded = run(exe, work, "bumpy_bound", common + ["--angle-bound", "70"])
    titles = []
    for fld, what in ((smooth, "smooth frame field"), (bounded, "angle bound 70\u00b0")):
        free = fld["scalars"]["is_constrained"] < 0.5
        titles.append("%s: smallest angle %.0f\u00b0 (free faces)" % (what, fld["scalars"]["min_angle_degrees"][free].min()))
    pair((smooth, bounded), titles, "angle_bound.png", 130, 12, "min_angle_degrees", truncated("RdYlBu", 0.12, 0.88),
         0, 90, "angle between u and v (degrees)", glyph_cells=30, glyph_scale=0.45)

    # Limitation: with very sparse constraints the field shrinks between them (scale is coupled with rotation).
    f = run(exe, work, "bumpy_sparse", ["--mesh", bumpy, "--sign-symmetric", "--random-constraints", "2", "--seed", "1"])
    length = np.linalg.norm(f["roots"], axis=2).mean(axis=1)
    reference = length[f["scalars"]["is_constrained"] > 0.5].mean()
    f["scalars"]["relative_length"] = length / reference
    fig = plt.figure(figsize=(6.4, 5.9), dpi=110)
    ax = fig.add_axes([0.0, 0.06, 0.88, 0.88])
    render(f, ax, 35, 28, color_by=f["scalars"]["relative_length"], cmap=truncated("YlGnBu", 0.05, 0.6),
           vmin=0, vmax=1, glyph_cells=30, glyph_scale=0.5, glyph_reference=reference,
           title="two constraints: the median vector is %.2f times as long" % np.median(length / reference))
    cax = fig.add_axes([0.88, 0.2, 0.02, 0.6])
    fig.colorbar(cm.ScalarMappable(norm=colors.Normalize(0, 1), cmap=truncated("YlGnBu", 0.05, 0.6)),
                 cax=cax).set_label("vector length / constraint length", fontsize=8)
    legend(fig, [CONSTRAINED] + SINGULARITIES)
    save(fig, "limitation_scale.png")

    # Performance: the stages of the design on the bundled meshes, frame fields from 12 random constraints.
    rows = []
    for mesh in ("botanic-garden-bubble.off", "bumpy.off", "inspired_mesh.obj", "lilium.obj", "eight.off", "fandisk.off"):
        f = run(exe, work, "timing", ["--mesh", os.path.join(DATA, mesh), "--sign-symmetric",
                                      "--random-constraints", "12"])
        rows.append((mesh.split(".")[0], len(f["faces"]), times(f["report"])))
    f = run(exe, work, "timing", ["--mesh", os.path.join(DATA, "fandisk.off"), "--sign-symmetric",
                                  "--sharp-edges", "30"])
    rows.append(("fandisk, partial", len(f["faces"]), times(f["report"])))
    partial = next(l for l in f["report"].splitlines() if l.startswith("constraints")).split()[1]
    fig = plt.figure(figsize=(7.5, 3.6), dpi=100)
    ax = fig.add_axes([0.1, 0.25, 0.86, 0.66])
    stages = [("frames and connection", "#9ecae1"), ("assembly", "#4292c6"), ("factorization", "#08519c"),
              ("solve", "#fd8d3c"), ("roots", "#a1d99b"), ("singularities", "#31a354")]
    bottom = np.zeros(len(rows))
    for stage, color in stages:
        values = np.array([r[2].get(stage, 0.0) for r in rows]) * 1000
        ax.bar(np.arange(len(rows)), values, bottom=bottom, color=color, label=stage, width=0.65)
        bottom += values
    ax.set_xticks(np.arange(len(rows)))
    ax.set_xticklabels(["%s\n%d faces" % (r[0], r[1]) for r in rows], fontsize=7.5, rotation=25, ha="right")
    ax.set_ylabel("time (ms)", fontsize=9)
    ax.set_title("frame field from 12 constraints (last bar: %s partial constraints)" % partial, fontsize=9)
    ax.legend(fontsize=7, ncol=2, frameon=False)
    ax.spines["top"].set_visible(False)
    ax.spines["right"].set_visible(False)
    save(fig, "performance.png")

    # 5. Smooth and conjugate frame fields on the architectural mesh from its 84 bundled constraints.
    # The program writes conjugacy_deviation for frame-field runs only: the smooth field is asked with
    # --angle-bound 1, which every face of this cross field already satisfies (0 iterations, field unchanged).
    inspired = ["--mesh", os.path.join(DATA, "inspired_mesh.obj"),
                "--dmat-b", os.path.join(DATA, "inspired_mesh_b.dmat"),
                "--dmat-bc", os.path.join(DATA, "inspired_mesh_bc.dmat")]
    smooth = run(exe, work, "inspired_smooth", inspired + ["--angle-bound", "1"])
    conjugate = run(exe, work, "inspired_conjugate", inspired + ["--conjugate"])
    titles = ["%s: mean deviation %.3f" % (what, fld["scalars"]["conjugacy_deviation"].mean())
              for fld, what in ((smooth, "smooth frame field"), (conjugate, "conjugate frame field"))]
    pair((smooth, conjugate), titles, "conjugate_inspired.png", -70, 50, "conjugacy_deviation",
         truncated("YlOrRd", 0.0, 0.8), 0, 0.5, "conjugacy deviation", size=(11.0, 4.6),
         glyph_cells=34, glyph_scale=0.45, outline=True)


if __name__ == "__main__":
    main()
