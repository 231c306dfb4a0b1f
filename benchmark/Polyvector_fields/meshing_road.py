# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.
"""The meshing road (issue 22): the command-line program from a mesh to quads, whole process, as a user runs it.

run_benchmarks.py calls run_groups() to measure and road_report() to write the tables. Each run of
design_polyvector_field is a process of its own, started from a fresh `python3 -c` wrapper so that
getrusage(RUSAGE_CHILDREN) holds that run's peak resident set only; the wall time is the wrapper's
(process start to exit). The stage times come from the program's `time (s)` line and, for the map, from its
`(time: comb and cut ...)` line. The groups:

  bunny      bunny.off --curvature-constraints 1 --quad-mesh, the same with --conjugate --planarize, and
             --conjugate --quad-mesh --planarize alone (once: the stage table only)
  map160k    bumpy.off after 3 Loop steps (159,744 faces) --curvature-constraints 1 --parametrize: the map stage
  million    bunny.off after 2 Loop steps (1,206,528 faces) --curvature-constraints 1 --quad-mesh
  growth     the map stage on bumpy.off after L, LL, LLL, LLLL, LLSSS (10k to 1.08M faces; L Loop, S sqrt 3)
  libigl     the 576k-face torus against libigl's n_polyvector (needs a libigl checkout, see run_libigl())
  corpus     read from the output folder of scripts/run_corpus.py (nothing is run)

The subdivided meshes are written once by pvf_subdivide_mesh (CGAL's Loop and sqrt(3) steps) into the
results folder and reused.
"""

import glob
import importlib.util
import json
import math
import os
import re
import shlex
import subprocess
import sys
import time

GROUPS = ("bunny", "map160k", "million", "growth", "libigl", "corpus")
# The stages of the program's `time (s)` line, in its order.
STAGES = ("load mesh", "refinement", "frames and connection", "constraints", "curvature", "design", "frame field", "roots",
          "singularities", "diagnostics", "parametrization", "quad mesh", "planarization", "write")
# "The field" of the ratio target: everything from the mesh in memory to the field and its singularities
# (the curvature included: the curvature constraints and the conjugate field need it). Not the field: reading
# the mesh, the diagnostics, the map, the quads, the planarization and the files.
FIELD_STAGES = ("frames and connection", "constraints", "curvature", "design", "frame field", "roots",
                "singularities")
# The map's own sub-stages (the program's line `(time: comb and cut ...)`).
MAP_STAGES = ("comb and cut", "seam reduction", "assembly", "factorization", "conjugate gradient", "integer rounding",
              "stiffening")
# The extraction's own sub-stages (the program's line `(time: charts ...)` under its quad mesh).
QUAD_STAGES = ("charts", "fold-over repair", "integer points", "tracing", "cells", "quads and their checks")
# The growth series on bumpy.off: L is one Loop step (x4 faces), S one sqrt(3) step (x3).
GROWTH_SCHEMES = ("L", "LL", "LLL", "LLLL", "LLSSS")
MAP_OPTIONS = ["--curvature-constraints", "1", "--parametrize"]
# The bunny's runs: name, options, whether it is repeated (--repeats) or run once. The conjugate field of the
# target starts from the same 1% curvature constraints as the first run (the field the "2 s" refers
# to); the issue's command taken literally (no constraints but the sharp edges' partial ones, which couple
# the degrees into one larger system) is run once for the stage table.
BUNNY_RUNS = (("bunny_curvature", ["--curvature-constraints", "1", "--quad-mesh", "bunny.quads.obj"], True),
              ("bunny_conjugate", ["--curvature-constraints", "1", "--conjugate", "--quad-mesh", "bunny.quads.obj",
                                   "--planarize"], True),
              ("bunny_conjugate_no_curvature", ["--conjugate", "--quad-mesh", "bunny.quads.obj", "--planarize"],
               False))
# The libigl commit that pvf_libigl_n_polyvector was measured against: the last before n_polyvector moved
# to libdirectional.
LIBIGL_COMMIT = "4000571d9"
MILLION_OPTIONS = ["--curvature-constraints", "1", "--quad-mesh", "bunny_LL.quads.obj"]

# The whole process in a child of a fresh interpreter: one JSON line (wall time, peak RSS, exit), then the
# program's standard output, then a line of dashes and its standard error.
WRAPPER = r"""
import json, resource, subprocess, sys, time
timeout = float(sys.argv[1])
t = time.time()
try:
    p = subprocess.run(sys.argv[2:], stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout)
    code, out, err = p.returncode, p.stdout, p.stderr
except subprocess.TimeoutExpired as e:
    code, out, err = None, e.stdout or b"", e.stderr or b""
wall = time.time() - t
print(json.dumps({"wall_s": wall, "peak_kb": resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss,
                  "exit": code}))
sys.stdout.write(out.decode("utf-8", "replace"))
sys.stdout.write("\n----8<----\n" + err.decode("utf-8", "replace"))
"""


def log(message):
    print(message, file=sys.stderr, flush=True)


def number_list(text):
    """'name 1.0; other name 2.5;' -> {'name': 1.0, 'other name': 2.5}"""
    items = {}
    for item in re.split(r"[;,]", text):
        words = item.split()
        if len(words) >= 2:
            try:
                items[" ".join(words[:-1])] = float(words[-1])
            except ValueError:
                pass
    return items


def parse_output(out):
    """What the program's summary says: stages, map sub-stages, sizes and the quality figures."""
    entry = {"stages": {}, "map_stages": {}, "quad_stages": {}}
    for line in out.splitlines():
        if line.startswith("time (s)"):
            entry["stages"] = number_list(line[len("time (s)"):].split("(design:")[0])
        elif line.strip().startswith("(time: comb and cut"):
            entry["map_stages"] = number_list(line.strip()[len("(time:"):].rstrip(")"))
        elif line.strip().startswith("(time: charts"):
            entry["quad_stages"] = number_list(line.strip()[len("(time:"):].rstrip(")"))
        elif line.startswith("mesh "):
            m = re.search(r": (\d+) faces", line)
            if m:
                entry["faces"] = int(m.group(1))
        elif line.startswith("refinement "):
            m = re.search(r"(\d+) -> (\d+) faces", line)
            if m:
                entry["faces_before_refinement"] = int(m.group(1))
        elif line.startswith("parametrization "):
            m = re.search(r"(\d+) flipped faces", line)
            if m:
                entry["map_flipped_faces"] = int(m.group(1))
            m = re.search(r"(\d+) integer unknowns", line)
            if m:
                entry["integer_unknowns"] = int(m.group(1))
            m = re.search(r"after (\d+) stiffening rounds", line)
            entry["stiffening_rounds"] = int(m.group(1)) if m else 0
            m = re.search(r"energy rounded/continuous ([0-9.eE+-]+)", line)
            if m:
                entry["energy_ratio"] = float(m.group(1))
            entry["map_recomputed"] = "computed again" in line
        elif line.startswith("quad mesh "):
            m = re.search(r"(\d+) quads.*?, (\d+) vertices, (\d+) irregular vertices", line)
            if m:
                entry["quads"], entry["quad_vertices"], entry["irregular_vertices"] = map(int, m.groups())
        elif line.startswith("planarity "):
            entry["planarity"] = line[len("planarity"):].strip()
        elif line.startswith("singularities "):
            m = re.match(r"singularities\s+(\d+)", line)
            if m:
                entry["singularities"] = int(m.group(1))
    return entry


def run_measured(cmd, cwd, label, repeats=1, timeout=900.0):
    """`cmd` run `repeats` times in `cwd`; the best successful run (smallest wall time), or the failed one."""
    best, walls = None, []
    for _ in range(max(1, repeats)):
        log("+ (cd %s && %s)" % (cwd, " ".join(shlex.quote(c) for c in cmd)))
        raw = subprocess.run([sys.executable, "-c", WRAPPER, repr(float(timeout))] + cmd, cwd=cwd, check=True,
                             stdout=subprocess.PIPE, text=True).stdout
        head, rest = raw.split("\n", 1)
        out, _, err = rest.partition("\n----8<----\n")
        measured = json.loads(head)
        entry = parse_output(out)
        entry.update(label=label, wall_s=measured["wall_s"], peak_kb=measured["peak_kb"], exit=measured["exit"],
                     command=cmd, when=time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()))
        if measured["exit"] is None:
            entry["status"] = "timeout after %g s" % timeout
        elif measured["exit"] != 0:
            lines = [l for l in err.splitlines() if l.strip()]
            entry["status"] = "exit %s: %s" % (measured["exit"], lines[-1] if lines else "")
        else:
            entry["status"] = "ok"
        log("  %s: %s, %.2f s, %.0f MB" % (label, entry["status"], entry["wall_s"], entry["peak_kb"] / 1024.0))
        if entry["status"] != "ok":
            entry["runs_s"] = walls + [entry["wall_s"]]
            entry["load_avg"] = list(os.getloadavg())
            return entry  # a failure is not repeated
        walls.append(entry["wall_s"])
        if best is None or entry["wall_s"] < best["wall_s"]:
            best = entry
    best["runs_s"] = walls
    best["load_avg"] = list(os.getloadavg())
    return best


def off_faces(path):
    with open(path) as f:
        tokens = []
        for line in f:
            tokens += line.split("#")[0].split()
            if len(tokens) >= 4:
                return int(tokens[2])
    return None


def subdivided(ctx, source, scheme):
    """The OFF file of `source` after `scheme` (written once by pvf_subdivide_mesh) and its face count."""
    stem = os.path.splitext(os.path.basename(source))[0]
    path = os.path.join(ctx["meshes"], "%s_%s.off" % (stem, scheme or "0"))
    if not os.path.exists(path):
        log("+ pvf_subdivide_mesh %s %s %s" % (source, scheme or "-", path))
        subprocess.run([ctx["subdivide"], source, scheme or "-", path], check=True, stdout=subprocess.DEVNULL)
    return path, off_faces(path)


def workdir(ctx, name):
    d = os.path.join(ctx["resdir"], "road", name)
    os.makedirs(d, exist_ok=True)
    return d


def run_bunny(ctx):
    out = {}
    faces = off_faces(ctx["bunny"]) if ctx["bunny"].lower().endswith(".off") else None
    for name, options, repeated in BUNNY_RUNS:
        cmd = [ctx["cli"], "--mesh", ctx["bunny"]] + options
        out[name] = run_measured(cmd, workdir(ctx, name), name, ctx["repeats"] if repeated else 1, ctx["timeout"])
        out[name]["input_faces"] = faces
    return out


def run_map160k(ctx):
    path, faces = subdivided(ctx, ctx["bumpy"], "LLL")
    entry = run_measured([ctx["cli"], "--mesh", path] + MAP_OPTIONS, workdir(ctx, "bumpy_LLL"), "bumpy_LLL",
                         ctx["repeats"], ctx["timeout"])
    entry["scheme"], entry["input_faces"] = "LLL", faces
    return {"map160k": entry}


def run_million(ctx):
    path, faces = subdivided(ctx, ctx["bunny"], "LL")
    entry = run_measured([ctx["cli"], "--mesh", path] + MILLION_OPTIONS, workdir(ctx, "bunny_LL"), "bunny_LL", 1,
                         ctx["timeout"])
    entry["scheme"], entry["input_faces"] = "LL", faces
    return {"million": entry}


def run_growth(ctx, done):
    series = []
    for scheme in ctx["growth"]:
        if scheme == "LLL" and "map160k" in done and done["map160k"].get("status") == "ok":
            series.append(dict(done["map160k"], reused="the 160k row's run"))
            continue
        path, faces = subdivided(ctx, ctx["bumpy"], scheme)
        entry = run_measured([ctx["cli"], "--mesh", path] + MAP_OPTIONS, workdir(ctx, "bumpy_" + scheme),
                             "bumpy_" + scheme, 1, ctx["timeout"])
        entry["scheme"], entry["input_faces"] = scheme, faces
        series.append(entry)
    return {"growth": series}


# ---------------------------------------------------------------------------
# libigl's n_polyvector on the torus of the previous issue.
# ---------------------------------------------------------------------------
def write_frame_constraints(mesh, path, fraction=0.01, seed=1):
    """Random full frame constraints on `fraction` of the faces of the OFF `mesh`, in the program's format.

    Each line 'face ux uy uz vx vy vz': u a random unit vector in the face's plane, v at an angle drawn in
    [45, 135] degrees from u (a general frame, as the benchmark programs' random constraints).
    """
    import random
    with open(mesh) as f:
        tokens = f.readline().split()
        if not tokens or tokens[0] != "OFF":
            raise RuntimeError("'%s' is not an OFF file" % mesh)
        nv, nf = (int(x) for x in f.readline().split()[:2])
        points = [tuple(float(x) for x in f.readline().split()[:3]) for _ in range(nv)]
        faces = [tuple(int(x) for x in f.readline().split()[1:4]) for _ in range(nf)]
    rng = random.Random(seed)
    chosen = sorted(rng.sample(range(nf), max(1, int(nf * fraction))))

    def sub(a, b):
        return (a[0] - b[0], a[1] - b[1], a[2] - b[2])

    def cross(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    def unit(a):
        n = math.sqrt(a[0] ** 2 + a[1] ** 2 + a[2] ** 2)
        return (a[0] / n, a[1] / n, a[2] / n)

    with open(path + ".tmp", "w") as out:
        out.write("# %d random frames (u, v at 45..135 degrees) on %s, seed %d\n" % (len(chosen), os.path.basename(mesh),
                                                                                   seed))
        for face in chosen:
            p0, p1, p2 = (points[i] for i in faces[face])
            e1 = unit(sub(p1, p0))
            e2 = unit(cross(unit(cross(e1, sub(p2, p0))), e1))
            a = rng.uniform(0, 2 * math.pi)
            b = a + math.radians(rng.uniform(45, 135))
            u = tuple(math.cos(a) * x + math.sin(a) * y for x, y in zip(e1, e2))
            v = tuple(math.cos(b) * x + math.sin(b) * y for x, y in zip(e1, e2))
            out.write("%d %s\n" % (face, " ".join("%.17g" % c for c in u + v)))
    os.replace(path + ".tmp", path)
    return len(chosen)


def rawfield_difference(first, second):
    """Largest distance from a vector of one .rawfield to the nearest vector of the same face in the other,
    over the length of the longest vector of both files (the fields as sets of vectors per face)."""
    with open(first) as a, open(second) as b:
        ha, hb = a.readline().split(), b.readline().split()
        if ha != hb:
            return float("inf")
        n = int(ha[0])
        worst, longest = 0.0, 0.0
        for la, lb in zip(a, b):
            va, vb = [float(x) for x in la.split()], [float(x) for x in lb.split()]
            us = [va[3 * i:3 * i + 3] for i in range(n)]
            ws = [vb[3 * i:3 * i + 3] for i in range(n)]
            for u in us:
                longest = max(longest, math.sqrt(sum(c * c for c in u)))
                worst = max(worst, min(math.sqrt(sum((p - q) ** 2 for p, q in zip(u, w))) for w in ws))
    return worst / longest if longest > 0 else float("nan")


def run_libigl(ctx):
    """The torus field by both programs on the same constraint file, each the best of its runs."""
    program = ctx.get("libigl_program")
    if not program:
        return {"libigl": {"status": "not measured: libigl not available (build pvf_libigl_n_polyvector with "
                                     "-DPVF_LIBIGL_INCLUDE_DIR and give --libigl-program)"}}
    if not os.access(program, os.X_OK):
        return {"libigl": {"status": "not measured: '%s' is not an executable" % program}}
    entries = {}
    mesh = ctx["torus_mesh"]
    if not os.path.exists(mesh):
        ctx["write_torus"](mesh)
    constraints = os.path.splitext(mesh)[0] + ".constraints"
    if not os.path.exists(constraints):
        write_frame_constraints(mesh, constraints)
    ours = run_measured([ctx["cli"], "--mesh", mesh, "--sign-symmetric", "--constraints", constraints,
                         "--out-field", "torus.rawfield", "--out-singularities", "torus.sings"],
                        workdir(ctx, "torus_ours"), "torus_ours", ctx["repeats"], ctx["timeout"])
    theirs = run_measured([program, mesh, constraints, "torus.rawfield"], workdir(ctx, "torus_libigl"),
                          "torus_libigl", ctx.get("libigl_repeats", 1), ctx["timeout"])
    entries["ours"], entries["libigl"] = ours, theirs
    if ok(ours) and ok(theirs):
        entries["difference"] = rawfield_difference(os.path.join(workdir(ctx, "torus_ours"), "torus.rawfield"),
                                                    os.path.join(workdir(ctx, "torus_libigl"), "torus.rawfield"))
    return {"libigl": entries}


# ---------------------------------------------------------------------------
# The corpus, from the output folder of scripts/run_corpus.py.
# ---------------------------------------------------------------------------
def _run_corpus_module(root):
    spec = importlib.util.spec_from_file_location("run_corpus", os.path.join(root, "scripts", "run_corpus.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def read_corpus_table(path):
    """mesh file name -> (status, seconds) from the Markdown table that run_corpus.py prints."""
    rows = {}
    with open(path) as f:
        for line in f:
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) < 5 or cells[0] in ("mesh", "") or cells[0].startswith("---"):
                continue
            try:
                rows[cells[0]] = (cells[2].strip("*"), float(cells[4]))
            except ValueError:
                continue
    return rows


def read_corpus(root, folder, table=None):
    """One entry per <name>.log of run_corpus.py's output folder: mesh, faces, time and how it ended.

    The time is the wall time of run_corpus.py's table when given (`table`), else the sum of the program's
    stage times on its `time (s)` line (the log holds no wall time; process start and exit are not in it).
    A run without that line did not finish: refused input (the program's message names the mesh file),
    failed (another message), or killed (no message: run_corpus.py's timeout).
    """
    if not os.path.isdir(folder):
        return {"status": "not measured: '%s' is not a folder" % folder}
    count_faces = _run_corpus_module(root).count_faces
    walls = read_corpus_table(table) if table else {}
    meshes = []
    for path in sorted(glob.glob(os.path.join(folder, "*.log"))):
        with open(path, errors="replace") as f:
            text = f.read()
        first, _, body = text.partition("\n")
        if not first.startswith("$ "):
            continue
        cmd = shlex.split(first[2:])
        mesh = cmd[cmd.index("--mesh") + 1] if "--mesh" in cmd else path
        info = parse_output(body)
        faces = count_faces(mesh) if os.path.isfile(mesh) else None
        if faces is None:
            faces = info.get("faces_before_refinement", info.get("faces"))
        entry = {"mesh": os.path.basename(mesh), "faces": faces, "seconds": None, "source": "stages"}
        if info["stages"]:
            entry["status"] = "finished"
            entry["seconds"] = sum(info["stages"].values())
        else:
            lines = [l for l in body.splitlines() if l.strip()]
            last = lines[-1] if lines else ""
            if last.startswith("design_polyvector_field: mesh '"):
                entry["status"], entry["reason"] = "refused", last.split(": ", 1)[1]
            elif last.startswith("design_polyvector_field: "):
                entry["status"], entry["reason"] = "failed", last.split(": ", 1)[1]
            else:
                entry["status"], entry["reason"] = "killed", "no summary: killed by run_corpus.py's timeout"
        if entry["mesh"] in walls:
            status, seconds = walls[entry["mesh"]]
            entry["seconds"], entry["source"], entry["table_status"] = seconds, "table", status
            if status == "timeout":
                entry["status"], entry["reason"] = "killed", "timeout after %.0f s" % seconds
        meshes.append(entry)
    return {"folder": os.path.abspath(folder), "table": table, "meshes": meshes}


def corpus_bound(faces):
    return max(5.0, (faces or 0) / 10000.0)


# ---------------------------------------------------------------------------
# Measuring, then the tables.
# ---------------------------------------------------------------------------
def run_groups(ctx, groups, previous=None, save=None):
    """Runs the groups asked for; the entries of the others are kept from `previous` (road.json).

    `save(road)` is called after each group, so that a run stopped later keeps what was measured. The corpus
    and libigl groups keep an earlier measurement when this run has no input for them.
    """
    road = dict(previous or {})
    for group in groups:
        if save and road:
            save(road)
        if group == "corpus" and not ctx.get("corpus_results") and "meshes" in road.get("corpus", {}):
            log("== meshing road: corpus kept from %s (no --corpus-results)" % road["corpus"]["folder"])
            continue
        if group == "libigl" and not ctx.get("libigl_program") and "ours" in road.get("libigl", {}):
            log("== meshing road: libigl kept from the earlier run (no pvf_libigl_n_polyvector)")
            continue
        log("== meshing road: %s" % group)
        if group == "bunny":
            road.update(run_bunny(ctx))
        elif group == "map160k":
            road.update(run_map160k(ctx))
        elif group == "million":
            road.update(run_million(ctx))
        elif group == "growth":
            road.update(run_growth(ctx, road))
        elif group == "libigl":
            road.update(run_libigl(ctx))
        elif group == "corpus":
            if ctx.get("corpus_results"):
                road["corpus"] = read_corpus(ctx["root"], ctx["corpus_results"], ctx.get("corpus_table"))
            else:
                road["corpus"] = {"status": "not measured: give --corpus-results DIR (the --out folder of "
                                            "scripts/run_corpus.py)"}
    if save:
        save(road)
    return road


def fmt(x, digits=3):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    if abs(x) >= 100:
        return "%.0f" % x
    return ("%." + str(digits) + "g") % x


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    for r in rows:
        lines.append("| " + " | ".join(str(c) for c in r) + " |")
    return "\n".join(lines)


def loglog_exponent(points):
    """Least-squares slope of log(time) over log(faces)."""
    pts = [(math.log(f), math.log(t)) for f, t in points if f > 0 and t > 0]
    if len(pts) < 2:
        return float("nan")
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx


def shown(cmd):
    """The command as a user types it: the program's and the meshes' paths shortened."""
    out = []
    for c in cmd:
        if os.path.isabs(c):
            c = os.path.basename(c)
        out.append(c)
    return "`" + " ".join(shlex.quote(c) for c in out) + "`"


def field_time(entry):
    return sum(entry["stages"].get(s, 0.0) for s in FIELD_STAGES)


def ok(entry):
    return bool(entry) and entry.get("status") == "ok"


def road_targets(road):
    """One row per target of issue 22: [target, measured, met / missed / not measured, how]."""
    rows = []

    def row(target, measured, met, how):
        rows.append([target, measured, "not measured" if met is None else ("met" if met else "**missed**"), how])

    def failed(target, entry, group):
        if not entry:
            row(target, "-", None, "run with `--road-groups %s`" % group)
        else:
            row(target, entry.get("status", "?"), False if "status" in entry and entry["status"].startswith(
                ("timeout", "exit")) else None, shown(entry["command"]) if "command" in entry else "")

    b = road.get("bunny_curvature")
    if ok(b):
        runs = len(b.get("runs_s", [1]))
        row("bunny (%s faces), `--curvature-constraints 1 --quad-mesh`, whole process <= 5 s"
            % b.get("input_faces", b.get("faces", "?")), "%s s" % fmt(b["wall_s"]), b["wall_s"] <= 5.0,
            "%s, best of %d, wall time of the process%s; %s quads, %s irregular vertices, %s flipped faces of the map"
            % (shown(b["command"]), runs,
               " (the program refines the mesh to %d faces)" % b["faces"] if b.get("faces_before_refinement") else "",
               b.get("quads", "?"), b.get("irregular_vertices", "?"), b.get("map_flipped_faces", "?")))
        f = field_time(b)
        ratio = b["wall_s"] / f if f > 0 else float("inf")
        row("bunny, whole process <= 2.5 x the field in the same run", "%s (%s s / %s s)" % (fmt(ratio), fmt(b["wall_s"]),
                                                                                          fmt(f)),
            ratio <= 2.5, "the same run; the field = the stages %s of the `time (s)` line" % ", ".join(FIELD_STAGES))
    else:
        failed("bunny, `--curvature-constraints 1 --quad-mesh`, whole process <= 5 s and <= 2.5 x the field", b,
               "bunny")
    c = road.get("bunny_conjugate")
    if ok(c):
        row("bunny, `--curvature-constraints 1 --conjugate --quad-mesh --planarize`, whole process <= 8 s",
            "%s s" % fmt(c["wall_s"]),
            c["wall_s"] <= 8.0, "%s, best of %d; planarity %s" % (shown(c["command"]), len(c.get("runs_s", [1])),
                                                                   c.get("planarity", "?")))
    else:
        failed("bunny, `--curvature-constraints 1 --conjugate --quad-mesh --planarize`, whole process <= 8 s", c,
               "bunny")
    m = road.get("map160k")
    if ok(m):
        t = m["stages"].get("parametrization", float("nan"))
        row("%d faces (bumpy, 3 Loop steps), the map alone <= 3 s" % m.get("faces", 0), "%s s" % fmt(t), t <= 3.0,
            "%s, best of %d: its `parametrization` stage (%s); %s flipped faces, energy rounded / continuous %s"
            % (shown(m["command"]), len(m.get("runs_s", [1])),
               ", ".join("%s %s" % (k, fmt(v)) for k, v in m["map_stages"].items()), m.get("map_flipped_faces", "?"),
               fmt(m.get("energy_ratio"), 4)))
    else:
        failed("160k faces (bumpy, 3 Loop steps), the map alone <= 3 s", m, "map160k")
    g = road.get("million")
    if ok(g):
        gb = g["peak_kb"] / 1024.0 / 1024.0
        row("%d faces (bunny, 2 Loop steps), `--quad-mesh` <= 60 s" % g.get("faces", 0), "%s s" % fmt(g["wall_s"]),
            g["wall_s"] <= 60.0, "%s, one run, wall time; the mesh written by pvf_subdivide_mesh; stages: %s"
            % (shown(g["command"]), "; ".join("%s %s" % (k, fmt(v)) for k, v in g["stages"].items())))
        row("%d faces, `--quad-mesh` <= 4 GB" % g.get("faces", 0), "%s GB" % fmt(gb), gb <= 4.0,
            "the same run: maximum resident set of the process (getrusage)")
    else:
        failed("1M faces (bunny, 2 Loop steps), `--quad-mesh` <= 60 s and <= 4 GB", g, "million")
    series = road.get("growth") or []
    pts = [(e["faces"], e["stages"]["parametrization"]) for e in series if ok(e) and "parametrization" in e["stages"]]
    bad = [e for e in series if not ok(e)]
    if len(pts) >= 4:
        e = loglog_exponent(pts)
        row("growth of the map's time, %d..%d faces: log-log exponent <= 1.15" % (pts[0][0], pts[-1][0]),
            "%.2f" % e, e <= 1.15 and not bad,
            "least-squares slope of the `parametrization` stage over %d sizes of bumpy (table below)%s"
            % (len(pts), "; not finished: " + ", ".join("%s (%s)" % (x.get("label"), x.get("status")) for x in bad)
               if bad else ""))
    elif series:
        row("growth of the map's time, 10k..1M faces: log-log exponent <= 1.15", "%d sizes finished" % len(pts),
            False if bad else None, "the exponent needs 4 sizes: " +
            ("not finished: " + ", ".join("%s (%s)" % (x.get("label"), x.get("status")) for x in bad) if bad else
             "only %d were run (--growth)" % len(series)))
    else:
        row("growth of the map's time, 10k..1M faces: log-log exponent <= 1.15", "-", None,
            "run with `--road-groups growth`")
    lib = road.get("libigl") or {}
    if "ours" in lib and ok(lib["ours"]) and ok(lib.get("libigl")):
        ours, theirs = lib["ours"], lib["libigl"]
        speedup = theirs["wall_s"] / ours["wall_s"]
        row("576k-face field against libigl's `n_polyvector`, whole process: >= 30 x", "%s x (%s s against %s s)"
            % (fmt(speedup), fmt(ours["wall_s"]), fmt(theirs["wall_s"])), speedup >= 30,
            "%s best of %d, against %s (one run; libigl at commit %s, header-only)%s"
            % (shown(ours["command"]), len(ours.get("runs_s", [1])), shown(theirs["command"]), LIBIGL_COMMIT,
               "; the two fields differ by at most %.1e of the longest vector" % lib["difference"]
               if "difference" in lib else ""))
        d = ours["stages"].get("design", float("nan"))
        row("576k-face field: the design alone <= 1.5 s", "%s s" % fmt(d), d <= 1.5,
            "the same run: its `design` stage (assembly, solver setup, solves)")
    else:
        status = lib.get("status") or (lib.get("libigl") or {}).get("status") or (lib.get("ours") or {}).get(
            "status") or "run with `--road-groups libigl`"
        row("576k-face field against libigl's `n_polyvector`: >= 30 x, the design alone <= 1.5 s", "-", None, status)
    corpus = road.get("corpus") or {}
    if "meshes" in corpus:
        met, missed, refused = [], [], []
        for e in corpus["meshes"]:
            if e["status"] == "refused":
                refused.append(e)
            elif e["status"] == "finished" and e["seconds"] is not None and e["seconds"] <= corpus_bound(e["faces"]):
                met.append(e)
            else:
                missed.append(e)
        listed = "; ".join("%s (%s faces): %s" % (e["mesh"], e["faces"] if e["faces"] is not None else "?",
                                                  ("%s s > %s s" % (fmt(e["seconds"]), fmt(corpus_bound(e["faces"])))
                                                   if e["status"] == "finished" else
                                                   "%s%s" % (e["status"], ", " + e["reason"] if e.get("reason") else "")))
                           for e in missed)
        row("every corpus mesh, `--quad-mesh` <= max(5 s, 1 s per 10k faces)",
            "%d met, %d missed of %d meshes%s" % (len(met), len(missed), len(met) + len(missed),
                                                  "; not counted, refused as not a surface: %d" % len(refused)
                                                  if refused else ""),
            not missed and bool(met),
            "read from %s (%s)%s" % (os.path.basename(corpus["folder"]),
                                     "wall times of run_corpus.py's table" if corpus.get("table")
                                     else "the program's stage times summed, from each log",
                                     "; missed: " + listed if missed else ""))
    else:
        row("every corpus mesh, `--quad-mesh` <= max(5 s, 1 s per 10k faces)", "-", None,
            corpus.get("status", "run with `--road-groups corpus --corpus-results DIR`"))
    return rows


def stage_table(road):
    """The stages of the bunny runs side by side (the table of the manual's performance section)."""
    runs = [(name, road[name]) for name, _, _ in BUNNY_RUNS if ok(road.get(name))]
    if not runs:
        return []
    rows = []
    for stage in STAGES:
        if not any(stage in e["stages"] for _, e in runs):
            continue
        rows.append([stage] + [fmt(e["stages"][stage]) if stage in e["stages"] else "-" for _, e in runs])
        if stage == "parametrization":
            for sub in MAP_STAGES:
                if any(sub in e["map_stages"] for _, e in runs):
                    rows.append(["&nbsp;&nbsp;map: " + sub] + [fmt(e["map_stages"].get(sub)) for _, e in runs])
        if stage == "quad mesh":
            for sub in QUAD_STAGES:
                if any(sub in e.get("quad_stages", {}) for _, e in runs):
                    rows.append(["&nbsp;&nbsp;extraction: " + sub]
                                + [fmt(e.get("quad_stages", {}).get(sub)) for _, e in runs])
    rows.append(["field (%s)" % ", ".join(FIELD_STAGES)] + [fmt(field_time(e)) for _, e in runs])
    rows.append(["sum of the stages"] + [fmt(sum(e["stages"].values())) for _, e in runs])
    rows.append(["**whole process** (wall, best of %s)" % "/".join(str(len(e.get("runs_s", [1]))) for _, e in runs)]
                + ["**%s**" % fmt(e["wall_s"]) for _, e in runs])
    rows.append(["faces (file -> after the program's refinement)"] + ["%s -> %s" % (e.get("input_faces", "?"),
                                                                                  e.get("faces", "?"))
                                                                      for _, e in runs])
    rows.append(["peak memory (MB)"] + [fmt(e["peak_kb"] / 1024.0) for _, e in runs])
    rows.append(["quads / irregular vertices"] + ["%s / %s" % (e.get("quads", "-"), e.get("irregular_vertices", "-"))
                                                  for _, e in runs])
    out = ["## The meshing road on the bunny, stage by stage (seconds)\n",
           "Commands (in a folder of their own, so that the default outputs output/bunny.* are written too):\n"]
    for name, e in runs:
        out.append("- %s: %s (measured %s, load average after it %s)" % (
            name, shown(e["command"]), e.get("when", "?"), ", ".join("%.2f" % x for x in e.get("load_avg", []))))
    out.append("")
    out.append(table(["stage"] + [name for name, _ in runs], rows))
    out.append("")
    return out


def growth_table(road):
    series = road.get("growth") or []
    if not series:
        return []
    rows = []
    for e in series:
        if not ok(e):
            rows.append([e.get("scheme", "?"), e.get("input_faces", "?"), e.get("status", "?")] + ["-"] * 6)
            continue
        rows.append([e.get("scheme", "?"), e.get("faces", "?"), fmt(e["stages"].get("parametrization")),
                     ", ".join("%s %s" % (k, fmt(v)) for k, v in e["map_stages"].items()),
                     e.get("map_flipped_faces", "-"), e.get("integer_unknowns", "-"), fmt(e.get("energy_ratio"), 4),
                     fmt(e["wall_s"]),
                     fmt(e["peak_kb"] / 1024.0)])
    pts = [(e["faces"], e["stages"]["parametrization"]) for e in series if ok(e) and "parametrization" in e["stages"]]
    out = ["## Growth of the map's time (bumpy.off subdivided: L a Loop step, S a sqrt(3) step)\n",
           "Each size: `design_polyvector_field --mesh bumpy_<steps>.off %s`, one run; the map is its "
           "`parametrization` stage.\n" % " ".join(MAP_OPTIONS),
           table(["steps", "faces", "map s", "map sub-stages s", "flipped faces", "integer unknowns",
                  "energy rounded / continuous", "whole process s", "peak MB"], rows), ""]
    if len(pts) >= 2:
        out.append("Log-log exponent over the %d sizes: **%.2f**%s\n" % (
            len(pts), loglog_exponent(pts),
            "; over >= 100k faces only: %.2f" % loglog_exponent([p for p in pts if p[0] >= 100000])
            if len([p for p in pts if p[0] >= 100000]) >= 2 else ""))
    return out


def corpus_table(road):
    corpus = road.get("corpus") or {}
    if "meshes" not in corpus:
        return []
    rows = []
    for e in sorted(corpus["meshes"], key=lambda e: (e["faces"] or 0)):
        bound = corpus_bound(e["faces"])
        verdict = "-" if e["status"] == "refused" else (
            "met" if e["status"] == "finished" and e["seconds"] is not None and e["seconds"] <= bound else "**missed**")
        rows.append([e["mesh"], e["faces"] if e["faces"] is not None else "?", e["status"], fmt(e["seconds"]),
                     fmt(bound), verdict, e.get("reason", "")])
    return ["## Corpus: time per mesh against max(5 s, 1 s per 10k faces)\n",
            "From `%s`%s.\n" % (corpus["folder"], " and the table `%s`" % corpus["table"] if corpus.get("table") else
                                " (time: the program's stage times summed)"),
            table(["mesh", "faces", "run", "time s", "bound s", "", "reason"], rows), ""]


def road_report(road):
    """The Markdown sections of the meshing road."""
    out = ["## Targets (the meshing road) of issue 22: whole process of `design_polyvector_field`, Release\n"]
    out.append(table(["target", "measured", "", "how"], road_targets(road)))
    out.append("")
    out.extend(stage_table(road))
    out.extend(growth_table(road))
    out.extend(corpus_table(road))
    return out
