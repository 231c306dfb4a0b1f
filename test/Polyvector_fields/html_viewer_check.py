#!/usr/bin/env python3
# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

"""The HTML viewer in a real browser (ctest test cli_html_viewer_browser).

Runs design_polyvector_field on the bundled architectural mesh (the paper's
pipeline: conjugate field, map, quad mesh, planarized), writing the page
(--out-html) and the coloured PLY (--out-ply). Then:
- the page is self-contained: no element loads anything (no src or href);
- the PLY has one face per quad, each with its planarity as quality and the
  colour of the map, the largest quality being the summary's largest
  planarity;
- headless Chromium (WebGL through ANGLE's SwiftShader) opens the page twice,
  the whole view and the view straight at the worst quad (#view=worst), and
  takes a screenshot and dumps the DOM in each run;
- the DOM: the viewer ran to its end (data-state "rendered"), no JavaScript
  error was recorded (window errors, rejected promises, console.error), the
  title holds the summary's figures, and the worst quad the page found has the
  summary's largest planarity;
- the screenshots: the canvas is not blank (a tenth of its pixels at least
  differ from the white background); the colour bar is drawn (its ends are the
  writer's blue and red); the whole view shows the colours of planar quads
  (the lower third of the bar) and of worse ones (the upper half); and in the
  view of the worst quad, the middle of the canvas has the colour of the top
  of the bar (position at least 0.85 on it), red.

Only the Python standard library is used (PNG decoded with zlib).
usage: html_viewer_check.py EXE CHROMIUM WORK_DIR [SCREENSHOT_COPY]
(SCREENSHOT_COPY: where to copy the screenshot of the whole view, as the
README's first picture doc/Polyvector_fields/fig/viewer_inspired.png was made.)
"""

import html
import os
import re
import shutil
import struct
import subprocess
import sys
import time
import zlib

WIDTH, HEIGHT = 1200, 800


def fail(message):
    print("html_viewer_check: FAILED: " + message)
    sys.exit(1)


def read_png(path):
    """Returns (width, height, rows) with rows[y][x] = (r, g, b)."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail(path + " is not a PNG file")
    pos, chunks, header = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            chunks.append(body)
        pos += 12 + length
    width, height, depth, colour_type, _, _, interlace = header
    if depth != 8 or colour_type not in (2, 6) or interlace != 0:
        fail("unexpected PNG format in %s (depth %d, colour type %d, interlace %d)" % (path, depth, colour_type, interlace))
    channels = 3 if colour_type == 2 else 4
    raw = zlib.decompress(b"".join(chunks))
    stride = width * channels
    rows, previous, pos = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[pos], bytearray(raw[pos + 1:pos + 1 + stride])
        pos += 1 + stride
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def chromium(browser, url, work, action):
    """Runs headless Chromium on url with --screenshot=FILE or --dump-dom; returns stdout."""
    command = [browser, "--headless", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
               "--hide-scrollbars", "--window-size=%d,%d" % (WIDTH, HEIGHT), "--force-device-scale-factor=1",
               "--user-data-dir=" + os.path.join(work, "chromium-profile"), "--no-first-run",
               "--disable-extensions", "--virtual-time-budget=10000"]
    if os.geteuid() == 0:
        command.append("--no-sandbox")
    command += action + [url]
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=180)
    if result.returncode != 0:
        fail("chromium exited with %d: %s" % (result.returncode, result.stderr.decode(errors="replace")[-2000:]))
    return result.stdout.decode(errors="replace")


def status_of(dom):
    match = re.search(r'<div id="pvf-status"([^>]*)>', dom)
    if not match:
        fail("the dumped DOM has no pvf-status element")
    return dict(re.findall(r'([a-z-]+)="([^"]*)"', match.group(1)))


def check_dom(dom, what):
    status = status_of(dom)
    errors = re.search(r'<pre id="pvf-errors"[^>]*>(.*?)</pre>', dom, re.S)
    if errors and errors.group(1).strip():
        fail("%s: the page logged JavaScript errors:\n%s" % (what, html.unescape(errors.group(1))))
    if status.get("data-errors") != "0":
        fail("%s: data-errors is %s" % (what, status.get("data-errors")))
    if status.get("data-state") != "rendered":
        fail("%s: the viewer did not finish (data-state %s)" % (what, status.get("data-state")))
    return status


def normalised(colour):
    m = max(colour)
    return tuple(255.0 * c / m for c in colour) if m > 0 else (0.0, 0.0, 0.0)


def main():
    if len(sys.argv) < 4:
        fail("usage: html_viewer_check.py EXE CHROMIUM WORK_DIR [SCREENSHOT_COPY]")
    exe, browser, work = os.path.abspath(sys.argv[1]), sys.argv[2], os.path.abspath(sys.argv[3])
    copy = sys.argv[4] if len(sys.argv) > 4 else None
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    page, ply = os.path.join(work, "inspired.html"), os.path.join(work, "inspired_quads.ply")
    quads = os.path.join(work, "inspired_quads.obj")

    start = time.time()
    run = subprocess.run([exe, "--conjugate", "--edge-length", "0.82", "--quad-mesh", quads, "--planarize",
                          "--out-html", page, "--out-ply", ply],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=work, timeout=600)
    summary = run.stdout.decode()
    if run.returncode != 0:
        fail("design_polyvector_field exited with %d: %s" % (run.returncode, run.stderr.decode()))
    print("design_polyvector_field: %.1f s" % (time.time() - start))
    faces = int(re.search(r"^mesh .*?: (\d+) faces", summary, re.M).group(1))
    singularities = int(re.search(r"^singularities\s+(\d+)", summary, re.M).group(1))
    quad_count = int(re.search(r"^quad mesh\s+(\d+) quads", summary, re.M).group(1))
    after = re.search(r"-> after \d+ iterations max ([0-9.e+-]+)%, mean ([0-9.e+-]+)%", summary)
    if not after:
        fail("the summary has no planarization result:\n" + summary)
    max_planarity, mean_planarity = float(after.group(1)) / 100, float(after.group(2)) / 100
    for path in (page, ply):
        if ("wrote           " + path) not in summary:
            fail("the summary does not list " + path)

    # The page: self-contained, and its title holds the figures.
    text = open(page, encoding="utf-8").read()
    print("page: %d bytes" % len(text.encode("utf-8")))
    loads = re.findall(r"<(?:script|link|img|iframe|source|video|audio)\b[^>]*\b(?:src|href)\s*=", text, re.I)
    if loads:
        fail("the page loads external resources: %s" % loads[:3])
    title = html.unescape(re.search(r"<title>(.*?)</title>", text, re.S).group(1))
    expected = "%d faces, %d singularities, %d quads, planarity max " % (faces, singularities, quad_count)
    if expected not in title:
        fail("the title '%s' does not hold '%s'" % (title, expected))
    title_max = float(re.search(r"planarity max ([0-9.e+-]+)%", title).group(1)) / 100
    if abs(title_max - max_planarity) > 0.006 * max_planarity:   # the title has 3 digits, the summary 6
        fail("the title's largest planarity %g differs from the summary's %g" % (title_max, max_planarity))

    # The PLY: a face per quad, with quality (planarity) and colour.
    lines = open(ply, encoding="ascii").read().split("\n")
    end = lines.index("end_header")
    header = lines[:end]
    face_count = int([l for l in header if l.startswith("element face")][0].split()[2])
    vertex_count = int([l for l in header if l.startswith("element vertex")][0].split()[2])
    face_properties = [l.split()[-1] for l in header[header.index([l for l in header if l.startswith("element face")][0]) + 1:]
                       if l.startswith("property")]
    if face_count != quad_count or face_properties[:1] != ["vertex_indices"] or \
            not {"red", "green", "blue", "quality"} <= set(face_properties):
        fail("PLY header: %d faces for %d quads, face properties %s" % (face_count, quad_count, face_properties))
    qualities = []
    for line in lines[end + 1 + vertex_count:end + 1 + vertex_count + face_count]:
        values = line.split()
        n = int(values[0])
        if n != 4:
            fail("PLY face with %d vertices" % n)
        props = dict(zip(face_properties[1:], values[1 + n:]))
        qualities.append(float(props["quality"]))
        if not all(0 <= int(props[c]) <= 255 for c in ("red", "green", "blue")):
            fail("PLY colour out of range: " + line)
    if abs(max(qualities) - max_planarity) > 1e-5 * max_planarity:
        fail("largest PLY quality %.9g, summary's largest planarity %.9g" % (max(qualities), max_planarity))
    if abs(sum(qualities) / len(qualities) - mean_planarity) > 1e-5 * mean_planarity:
        fail("mean PLY quality %.9g, summary's mean planarity %.9g" % (sum(qualities) / len(qualities), mean_planarity))

    # The browser: DOM and screenshot of both views.
    url = "file://" + os.path.abspath(page)
    start = time.time()
    whole_png, worst_png = os.path.join(work, "whole.png"), os.path.join(work, "worst.png")
    whole = check_dom(chromium(browser, url, work, ["--screenshot=" + whole_png, "--dump-dom"]), "whole view")
    worst = check_dom(chromium(browser, url + "#view=worst&layers=quads", work,
                               ["--screenshot=" + worst_png, "--dump-dom"]), "worst-quad view")
    print("chromium, two runs: %.1f s" % (time.time() - start))
    if worst.get("data-layers") != "quads" or whole.get("data-layers") != "singularities,quads":
        fail("layers shown: %s and %s" % (whole.get("data-layers"), worst.get("data-layers")))
    page_worst = float(worst.get("data-worst-planarity", "nan"))
    if not abs(page_worst - max_planarity) <= 1e-5 * max_planarity:   # float32 in the page
        fail("the page's worst quad has planarity %g, the summary's largest is %g" % (page_worst, max_planarity))

    bar = [float(x) for x in whole.get("data-colour-bar", "").split(",") if x]
    if len(bar) != 4:
        fail("the page did not report where its colour bar is")
    bx, by, bw, bh = bar
    width, height, rows = read_png(whole_png)
    if (width, height) != (WIDTH, HEIGHT):
        fail("screenshot of %dx%d pixels" % (width, height))
    x = int(bx + bw / 2)
    ramp = [(t, normalised(rows[int(by + 2 + (bh - 4) * (1 - t))][x])) for t in [i / 100 for i in range(101)]]
    bottom, top = ramp[0][1], ramp[-1][1]
    if not (bottom[2] > 1.5 * bottom[0] and top[0] > 2.5 * top[1] and top[0] > 2.5 * top[2]):
        fail("the colour bar is not blue to red: bottom %s, top %s" % (bottom, top))

    def position_on_bar(colour):
        c = normalised(colour)
        return min(ramp, key=lambda r: sum((a - b) ** 2 for a, b in zip(r[1], c)))[0]

    background = rows[5][WIDTH // 2]
    in_canvas = [(x, y) for y in range(0, HEIGHT, 2) for x in range(0, WIDTH, 2) if not (bx - 10 <= x <= bx + bw + 120)]
    differing = [p for p in in_canvas if max(abs(a - b) for a, b in zip(rows[p[1]][p[0]], background)) > 30]
    if len(differing) < 0.10 * len(in_canvas):
        fail("the canvas is nearly blank: %d of %d pixels differ from the background" % (len(differing), len(in_canvas)))
    saturated = [p for p in differing if max(rows[p[1]][p[0]]) - min(rows[p[1]][p[0]]) > 60]
    positions = [position_on_bar(rows[y][x]) for x, y in saturated]
    low = sum(1 for t in positions if t < 0.34)
    high = sum(1 for t in positions if t > 0.5)
    if low < 0.02 * len(differing) or high < 20:
        fail("planarity colours: %d pixels of the lower third of the bar, %d of its upper half (of %d drawn)"
             % (low, high, len(differing)))

    width, height, rows = read_png(worst_png)
    centre = [rows[HEIGHT // 2 + dy][WIDTH // 2 + dx] for dy in range(-3, 4) for dx in range(-3, 4)]
    mean = tuple(sum(c[i] for c in centre) / len(centre) for i in range(3))
    t = position_on_bar(mean)
    if t < 0.85 or not (mean[0] > 2 * mean[1] and mean[0] > 2 * mean[2]):
        fail("the worst quad is drawn %s, at %.2f on the colour bar (red is 1)" % (mean, t))
    print("html_viewer_check: ok: %d faces, %d singularities, %d quads, planarity max %.4g%%; canvas %d%% drawn, "
          "%d pixels of planar colours, %d of worse ones; worst quad drawn %s (%.2f on the bar)"
          % (faces, singularities, quad_count, 100 * max_planarity, 100 * len(differing) // len(in_canvas), low, high,
             tuple(round(c) for c in mean), t))
    if copy:
        shutil.copyfile(whole_png, copy)


if __name__ == "__main__":
    main()
