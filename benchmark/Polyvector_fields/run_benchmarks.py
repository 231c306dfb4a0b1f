#!/usr/bin/env python3
# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.
"""Configures, builds and runs the benchmark suite, then writes a Markdown table.

    python3 benchmark/Polyvector_fields/run_benchmarks.py [--max-level L] [--build-dir DIR] [--out FILE] [--no-build]

From the repository root. It configures a Release build with
-DPVF_BUILD_BENCHMARKS=ON in build-bench/ (tests off), builds the benchmark
programs, runs them (Google Benchmark JSON in build-bench/results/), runs
pvf_peak_memory once per size and solver (one process each, so that VmHWM is
that run's peak), runs the command-line program on a 576,000-face torus as a
user would (whole process: reading the OFF file, the design, the roots, the
singularities and writing the results), and writes the tables to
benchmark/results.md and stdout. The first table has one row per performance
target, with the measured figure and whether it is met.

Sizes: bumpy.off (2,496 faces) after 1..L Loop subdivisions: 10k, 40k, 160k,
640k faces for the default L = 4 (about 15 minutes on 2 cores); L = 5 adds
2.56M faces for the default solver only (a few more minutes and about 3 GB).

The meshing road (issue 22, meshing_road.py): the command-line program from a
mesh to quads, whole process, one row per target of the issue, the bunny's
stages side by side, the growth of the map's time and the corpus. Groups:
bunny, map160k, million, growth, libigl, corpus (--road-groups, default all);
--road-only runs them without the design suite, --no-road the suite alone. The
tables are made from every JSON file of build-dir/results, so groups run
separately add up in one benchmark/results.md. For example, the cheap groups:

    python3 benchmark/Polyvector_fields/run_benchmarks.py --road-only --road-groups bunny,map160k

and the corpus row from a run of scripts/run_corpus.py --out DIR (its table
saved with > DIR/table.md gives wall times; without it, the logs' stage times):

    python3 benchmark/Polyvector_fields/run_benchmarks.py --road-only --road-groups corpus \
        --corpus-results DIR --corpus-table DIR/table.md
"""

import argparse
import json
import math
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import meshing_road  # noqa: E402
from meshing_road import loglog_exponent, table  # noqa: E402  (one Markdown table writer, one fit)

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PROGRAMS = ["pvf_design_benchmark", "pvf_frame_field_benchmark", "pvf_quad_benchmark", "pvf_peak_memory",
            "design_polyvector_field", "pvf_subdivide_mesh"]
# What the meshing road alone needs (--road-only).
ROAD_PROGRAMS = ["design_polyvector_field", "pvf_subdivide_mesh"]
# Benchmark solver name -> pvf_peak_memory arguments (solver, mode).
MEMORY_SOLVERS = {"SimplicialLDLT": ("ldlt", "sequential"), "SimplicialLDLT_parallel": ("ldlt", "parallel"),
                  "CHOLMOD": ("cholmod", "sequential"), "CHOLMOD_parallel": ("cholmod", "parallel"),
                  "CHOLMOD_METIS": ("cholmod-metis", "sequential"), "AMG_parallel": ("amg", "parallel"),
                  "default": ("default", "parallel")}
# The package's default: Default_sparse_solver (direct below 8,000 unknowns,
# multigrid above) with Parallel_if_available_tag.
DEFAULT_SOLVER = "default"
# The direct solver that was the default before multigrid (for the no-regression target).
DIRECT_SOLVER = "CHOLMOD_parallel"
# The whole-process run of the command-line program: a torus of 600 x 480 quads
# split into 576,000 triangles, 1% of its faces under random frame constraints.
TORUS = (600, 480, 3.0, 1.0)


def run(cmd, env=None, capture=False):
    print("+ " + " ".join(cmd), file=sys.stderr, flush=True)
    if capture:
        return subprocess.run(cmd, env=env, check=True, stdout=subprocess.PIPE, text=True).stdout
    subprocess.run(cmd, env=env, check=True)
    return None


def build(build_dir, jobs, programs=PROGRAMS, libigl_include=None):
    extra = []
    if libigl_include:
        extra = ["-DPVF_LIBIGL_INCLUDE_DIR=" + os.path.abspath(libigl_include)]
        programs = list(programs) + ["pvf_libigl_n_polyvector"]
    run(["cmake", "-S", ROOT, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
         "-DPVF_BUILD_BENCHMARKS=ON", "-DBUILD_TESTING=OFF"] + extra)
    for program in programs:
        run(["cmake", "--build", build_dir, "--target", program, "-j", str(jobs)])


def write_torus(path, n, m, R, r):
    """The OFF file of a torus of n x m quads, each split into two triangles (2nm faces)."""
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (n * m, 2 * n * m))
        for i in range(n):
            a = 2 * math.pi * i / n
            for j in range(m):
                b = 2 * math.pi * j / m
                f.write("%.17g %.17g %.17g\n" % ((R + r * math.cos(b)) * math.cos(a),
                                                  (R + r * math.cos(b)) * math.sin(a), r * math.sin(b)))
        for i in range(n):
            for j in range(m):
                p, q = i * m + j, ((i + 1) % n) * m + j
                p2, q2 = i * m + (j + 1) % m, ((i + 1) % n) * m + (j + 1) % m
                f.write("3 %d %d %d\n3 %d %d %d\n" % (p, q, q2, p, q2, p2))


def run_cli_torus(cli, resdir, solver="auto", repeats=2):
    """The command-line program on the torus, whole process, as a user runs it; best of `repeats` runs.

    Wall time from the parent; peak memory is the child's maximum resident set (getrusage), each run
    in a process of its own (a fresh `python3 -c` wrapper, so that RUSAGE_CHILDREN holds that run only).
    """
    n, m, R, r = TORUS
    mesh = os.path.join(resdir, "torus_%dx%d.off" % (n, m))
    if not os.path.exists(mesh):
        write_torus(mesh + ".tmp", n, m, R, r)
        os.replace(mesh + ".tmp", mesh)
    faces = 2 * n * m
    cmd = [cli, "--mesh", mesh, "--sign-symmetric", "--random-constraints", str(faces // 100), "--solver", solver,
           "--out-field", os.path.join(resdir, "torus.rawfield"),
           "--out-singularities", os.path.join(resdir, "torus.sings")]
    wrapper = ("import resource, subprocess, sys, time\n"
               "t = time.time(); out = subprocess.run(sys.argv[1:], check=True, stdout=subprocess.PIPE, text=True).stdout\n"
               "wall = time.time() - t\n"
               "print('WALL %r PEAK_KB %d' % (wall, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss))\n"
               "print(out)\n")
    best = None
    for _ in range(repeats):
        print("+ " + " ".join(cmd), file=sys.stderr, flush=True)
        out = subprocess.run([sys.executable, "-c", wrapper] + cmd, check=True, stdout=subprocess.PIPE,
                             text=True).stdout
        first = out.split("\n", 1)[0].split()
        entry = {"solver": solver, "faces": faces, "wall_s": float(first[1]), "peak_kb": int(first[3]), "stages": {}}
        for line in out.splitlines():
            if line.startswith("time (s)"):
                body = line[len("time (s)"):].split("(design:")
                for item in body[0].split(";"):
                    words = item.split()
                    if len(words) >= 2:
                        entry["stages"][" ".join(words[:-1])] = float(words[-1])
            elif line.startswith("solver "):
                entry["solver_line"] = line[len("solver"):].strip()
        if best is None or entry["wall_s"] < best["wall_s"]:
            best = entry
    best["load_avg"] = list(os.getloadavg())
    return best


def run_benchmark(binary, out_json, env, extra=()):
    run([binary, "--benchmark_out=" + out_json, "--benchmark_out_format=json"] + list(extra), env=env)
    with open(out_json) as f:
        return json.load(f)


def seconds(b):
    unit = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b.get("time_unit", "ns")]
    return b["real_time"] * unit


def fmt(x, digits=3):
    if x is None:
        return "-"
    if isinstance(x, float) and math.isnan(x):
        return "-"
    if abs(x) >= 100:
        return "%.0f" % x
    return ("%." + str(digits) + "g") % x


def split_name(name):
    # "BM_design/CHOLMOD/3/real_time" -> ("BM_design", "CHOLMOD", "3")
    parts = [p for p in name.split("/") if p not in ("real_time",) and not p.startswith("iterations:")]
    return parts


def blas_name():
    """The library behind libblas.so.3 (Debian alternatives), for the record."""
    try:
        path = os.path.realpath("/usr/lib/x86_64-linux-gnu/libblas.so.3")
        return "OpenBLAS (%s)" % path if "openblas" in path else path
    except OSError:
        return "unknown"


def design_rows(design, solver):
    """faces -> (benchmark entry) of BM_design for one solver."""
    rows = {}
    for b in design["benchmarks"]:
        if b.get("run_type", "iteration") != "iteration" or "error_occurred" in b:
            continue
        p = split_name(b["name"])
        if p[0] == "BM_design" and p[1] == solver:
            rows[int(b["faces"])] = b
    return rows


def targets(design, frames, memory, torus=None):
    """One row per performance target of the linear-time issue: the measured figure, met or missed."""
    rows = []

    def row(target, measured, met, how):
        rows.append([target, measured, "met" if met else "**missed**", how])

    default = design_rows(design, DEFAULT_SOLVER)
    direct = design_rows(design, DIRECT_SOLVER)
    mem = {int(m["faces"]): m for m in memory if (m["solver"], m.get("mode")) == MEMORY_SOLVERS[DEFAULT_SOLVER]}
    if torus:
        st = torus["stages"]
        row("576k-face torus, whole process <= 3.0 s", "%s s" % fmt(torus["wall_s"]), torus["wall_s"] <= 3.0,
            "command-line program, best of 2 (%s)" % "; ".join("%s %s" % (k, fmt(v)) for k, v in st.items()))
        row("576k-face torus, peak memory <= 800 MB", "%s MB" % fmt(torus["peak_kb"] / 1024.0),
            torus["peak_kb"] / 1024.0 <= 800, "maximum resident set of the process")
        if "design" in st:
            row("576k-face torus, the design alone <= 1.5 s", "%s s" % fmt(st["design"]), st["design"] <= 1.5,
                "the program's design stage: assembly, solver setup, solves")
    big = [f for f in default if f > 2000000]
    for f in big:
        b = default[f]
        row("%d faces: design <= 12 s" % f, "%s s" % fmt(seconds(b)), seconds(b) <= 12,
            "BM_design/default (frames, assembly, setup, solves, roots)")
        m = mem.get(f)
        if m:
            row("%d faces: design <= 3 GB" % f, "%s MB" % fmt(m["peak_kb"] / 1024.0), m["peak_kb"] <= 3 * 1024 * 1024,
                "pvf_peak_memory %d default: peak of the process (mesh included)" % 5)
    pts = sorted((f, seconds(b)) for f, b in default.items())
    if len(pts) >= 2:
        e = loglog_exponent(pts)
        row("log-log exponent, %d..%d faces <= 1.1" % (pts[0][0], pts[-1][0]), "%.2f" % e, e <= 1.1,
            "least-squares slope of BM_design/default over %d sizes" % len(pts))
    for f in sorted(default):
        if f <= 50000 and f in direct:
            t, t0 = seconds(default[f]), seconds(direct[f])
            # Within 5%: two runs of the same code differ by that much on a shared machine.
            row("%d faces: no slower than the direct solver (before)" % f, "%s s vs %s s" % (fmt(t), fmt(t0)),
                t <= 1.05 * t0, "BM_design/default against BM_design/%s (the default before)" % DIRECT_SOLVER)
    for b in frames["benchmarks"]:
        p = split_name(b["name"])
        if b.get("run_type", "iteration") != "iteration" or "error_occurred" in b:
            continue
        if p[0] == "BM_conjugate_per_iteration" and p[1] == DEFAULT_SOLVER and 200000 <= int(b["faces"]) <= 400000:
            row("frame-field iteration at %d faces <= 0.25 s" % int(b["faces"]), "%s s" % fmt(b["per_iteration_s"]),
                b["per_iteration_s"] <= 0.25, "BM_conjugate_per_iteration/default: (6 steps - 1 step) / 5")
    for m in sorted(memory, key=lambda m: int(m["faces"])):
        if m["solver"] == "amg" and "relative_difference_to_direct" in m:
            d = float(m["relative_difference_to_direct"])
            row("%d faces: multigrid field within 1e-8 of the direct solver's" % int(m["faces"]), "%.1e" % d, d <= 1e-8,
                "pvf_peak_memory %s amg: max |c - c_direct| / max |c_direct| over all coefficients" % m["level"])
    out = ["## Targets (linear time) against the package default (`Default_sparse_solver`, parallel degrees)\n"]
    if not rows:
        return out + ["(nothing measured)\n"]
    return out + [table(["target", "measured", "", "how"], rows), ""]


def crossover(design):
    """Design time per size and solver, to show where multigrid overtakes the direct solvers."""
    solvers = ["SimplicialLDLT_parallel", "CHOLMOD_parallel", "AMG_parallel", "default"]
    per = {s: design_rows(design, s) for s in solvers}
    sizes = sorted({f for s in solvers for f in per[s]})
    rows = [[f] + [fmt(seconds(per[s][f])) if f in per[s] else "-" for s in solvers] for f in sizes]
    return ["## Crossover: design time (s) by solver\n",
            "The default uses the direct solver below 8,000 unknowns per system and multigrid above.\n",
            table(["faces"] + solvers, rows), ""]


def report(design, frames, memory, max_level, elapsed, quads=None, torus=None, road=None):
    out = []
    out.append("# Polyvector fields benchmark results\n")
    if road:
        out.append("Release build, %d cores, written %s.\n" % (os.cpu_count() or 0,
                                                               time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())))
        out.extend(meshing_road.road_report(road))
    if design is None:
        out.append("(The design suite was not run: run without --road-only.)\n")
        return "\n".join(out)
    out.append("Design suite: Release build, %d cores; bumpy.off after 1..%d Loop subdivisions; "
               "sign-symmetric 4-PolyVector (frame field) with 1%% of the faces under hard general-frame "
               "constraints (two active degrees). Times are wall-clock (Google Benchmark real time); "
               "suite ran in %s s.\n" % (os.cpu_count() or 0, max_level,
                                            "%.0f" % elapsed if elapsed == elapsed else "?"))
    load = design.get("context", {}).get("load_avg")
    if load:
        out.append("Load average when the design benchmarks started: %s (a figure above 0 means other "
                   "processes shared the cores, and wall-clock times are inflated).\n"
                   % ", ".join("%.2f" % x for x in load))
    benches = [b for b in design["benchmarks"] if b.get("run_type", "iteration") == "iteration"]
    out.extend(targets(design, frames, memory, torus))
    if torus:
        out.append("Torus run: `design_polyvector_field --mesh torus_600x480.off --sign-symmetric --random-constraints "
                   "5760 --solver %s` (the mesh written by this script); solver: %s; load average after it: %s.\n"
                   % (torus["solver"], torus.get("solver_line", "?"), ", ".join("%.2f" % x for x in torus["load_avg"])))
    out.extend(crossover(design))

    # End to end and stages.
    rows, fits = [], {}
    mem = {(m["solver"], m.get("mode", "parallel"), int(m["faces"])): m for m in memory}
    for b in benches:
        p = split_name(b["name"])
        if p[0] != "BM_design" or "error_occurred" in b:
            continue
        solver, faces = p[1], int(b["faces"])
        total = seconds(b)
        fits.setdefault(solver, []).append((faces, total))
        m = mem.get(MEMORY_SOLVERS.get(solver, ("", "")) + (faces,))
        rows.append([faces, solver, fmt(total), fmt(b["connection_s"]), fmt(b["assembly_s"]),
                     fmt(b["factorization_s"]), fmt(b["solve_s"]), fmt(b["roots_s"]), int(b.get("degrees", 0)),
                     fmt(faces / total / 1e3) if total > 0 else "-",
                     fmt(m["peak_kb"] / 1024.0) if m else "-", fmt(m["design_peak_kb"] / 1024.0) if m else "-"])
    rows.sort(key=lambda r: (r[1], r[0]))
    out.append("## Design, end to end (frames, assembly, factorization, solves, roots)\n")
    out.append(table(["faces", "solver", "total s", "connection s", "assembly s", "factorization s", "solve s",
                      "roots s", "degrees", "kfaces/s", "peak MB", "design peak MB"], rows))
    out.append("\nSolvers: CHOLMOD is `Cholmod_sparse_solver` (the package's own CHOLMOD driver: one symbolic "
               "analysis for all degrees, CHOLMOD's choice of ordering and of supernodal LL^*); SimplicialLDLT is "
               "`Simplicial_ldlt_solver` (Eigen, AMD ordering shared by the degrees); `_parallel` means "
               "`CGAL::Parallel_tag` (the two degrees assembled, factored and solved in parallel with TBB), the "
               "others `CGAL::Sequential_tag`. AMG is `Amg_sparse_solver` (conjugate gradient preconditioned by "
               "smoothed-aggregation multigrid); default is `Default_sparse_solver` (the direct solver below "
               "8,000 unknowns, AMG above) with `Parallel_if_available_tag`, the package's default. CHOLMOD_METIS is a benchmark-only "
               "variant forcing METIS nested dissection through Eigen's CholmodSupernodalLLT (no shared analysis). "
               "BLAS: %s.\n" % blas_name())
    out.append("Peak memory: `pvf_peak_memory` runs one design per process; it resets the kernel's "
               "peak-RSS mark after generating the mesh (`/proc/self/clear_refs`), so *peak MB* is VmHWM of "
               "the process during the design (mesh and libraries included) and *design peak MB* is that "
               "minus VmRSS just before the design.\n")
    out.append("Log-log fit exponent of end-to-end time over faces (all sizes in the table):\n")
    for solver, pts in sorted(fits.items()):
        out.append("- %s: **%.2f** (%s faces)" % (solver, loglog_exponent(pts),
                                                  ", ".join(str(f) for f, _ in sorted(pts))))
        big = [p for p in pts if p[0] >= 100000]
        if len(big) >= 2:
            out.append("  - over >= 100k faces only: %.2f" % loglog_exponent(big))
    out.append("")

    # Other size-dependent benchmarks.
    rows = []
    for b in benches:
        p = split_name(b["name"])
        if p[0] in ("BM_connection", "BM_resolve", "BM_singularities"):
            if "error_occurred" in b:
                rows.append([p[0], p[1] if len(p) > 2 else "", "-", "error: " + b.get("error_message", "")])
                continue
            label = p[1] if p[0] == "BM_resolve" else ""
            extra = ""
            if p[0] == "BM_resolve":
                extra = "triangular solves %s s" % fmt(b["solve_s"])
            elif p[0] == "BM_singularities":
                extra = "%d singularities" % int(b["singularities"])
            rows.append([p[0], label, int(b["faces"]), fmt(seconds(b)), extra])
    out.append("## Stages measured alone\n")
    out.append("`BM_connection`: face frames + Levi-Civita connection. `BM_resolve`: new constraint values on the "
               "same faces (factorization reused; right-hand sides, solves, copy-out). `BM_singularities`: the "
               "public `compute_singularities()` (it rebuilds its own connection).\n")
    out.append(table(["benchmark", "solver", "faces", "time s", "notes"], rows))
    out.append("")

    rows = []
    for b in benches:
        p = split_name(b["name"])
        if p[0].startswith("BM_roots"):
            rows.append([p[0], int(p[1]), fmt(seconds(b) * 1e3), fmt(b["items_per_second"] / 1e6)])
        elif p[0].startswith("BM_field_roots"):
            rows.append([p[0] + "/" + p[1], int(p[2]), fmt(seconds(b) * 1e3), fmt(b["items_per_second"] / 1e6)])
    out.append("## Root extraction kernel (`polyvector_roots`, pointer form, N = 4)\n")
    out.append("`sign_symmetric`: closed form; `general`: companion-matrix path on the same kind of input "
               "(odd coefficients slightly nonzero); both on one thread. `BM_field_roots`: the loop over the faces "
               "of `compute_field_roots()` (internal::field_roots), sequential or with the faces shared among "
               "the cores (TBB).\n")
    out.append(table(["benchmark", "faces", "time ms", "Mfaces/s"], rows))
    out.append("")

    rows = []
    for b in frames["benchmarks"]:
        if b.get("run_type", "iteration") != "iteration":
            continue
        p = split_name(b["name"])
        if p[0] in ("BM_conjugate_curvature", "BM_conjugate_step_bunny", "BM_angle_bound_bunny"):
            continue  # tables of their own below
        if "error_occurred" in b:
            rows.append([p[0], p[1] if len(p) > 1 else "", "-", "-", "-", "-", "error: " + b.get("error_message", "")])
            continue
        if p[0] == "BM_conjugate_per_iteration":
            rows.append([p[0], p[1], int(b["faces"]), "-", "-", "-",
                         "per iteration %s s (first step incl. setup and curvature: %s s)"
                         % (fmt(b["per_iteration_s"]), fmt(b["first_step_total_s"]))])
        else:
            note = ("residual %s" % fmt(b["residual"])) if "residual" in b else \
                   ("min free angle %s deg" % fmt(b.get("min_free_angle_deg", float("nan"))))
            rows.append([p[0], p[1], int(b["faces"]), fmt(seconds(b)), int(b["iterations"]),
                         "yes" if b["converged"] else "no", note])
    out.append("## Frame-field algorithms to convergence\n")
    out.append(table(["benchmark", "solver", "faces", "time s", "iterations", "converged", "notes"], rows))
    out.append("")

    rows = []
    for b in frames["benchmarks"]:
        if b.get("run_type", "iteration") != "iteration" or split_name(b["name"])[0] != "BM_conjugate_curvature":
            continue
        if "error_occurred" in b:
            rows.append([b.get("label", b["name"]), "-", "-", "-", "-", "-", "-", "error: " + b.get("error_message", "")])
            continue
        rows.append([b.get("label", b["name"]), int(b["faces"]), int(b["constraints"]), fmt(seconds(b)),
                     "%d%s" % (int(b["iterations"]), "" if b["converged"] else " (not converged)"),
                     "%d -> %d" % (int(b["smooth_singularities"]), int(b["singularities"])),
                     "%s -> %s" % (fmt(b["weighted_deviation_start"]), fmt(b["weighted_deviation"])),
                     fmt(b["mean_deviation_all_faces"])])
    out.append("## Conjugate fields from 1% curvature constraints (default stopping rule)\n")
    out.append("Time of the conjugate field alone (curvature and constraints excluded). Singularities: of the smooth "
               "field it starts from, then of the result. Deviation: |u^T S v| / (|u| |v| max|k|), weighted by "
               "Khat over the free faces as the stopping rule weighs it (start -> end), and the plain mean over "
               "all faces.\n")
    out.append(table(["mesh", "faces", "constraints", "time s", "iterations", "singularities",
                      "weighted deviation", "mean deviation, all faces"], rows))
    out.append("")
    for b in frames["benchmarks"]:
        p = split_name(b["name"])
        if b.get("run_type", "iteration") != "iteration" or "error_occurred" in b:
            continue
        if p[0] == "BM_conjugate_step_bunny":
            out.append("- bunny (%d faces), one conjugate step: %s s; a fresh factorization of the same system: "
                       "%s s; ratio %s (target <= 0.2)" % (int(b["faces"]), fmt(b["per_iteration_s"]),
                                                           fmt(b["fresh_factorization_s"]),
                                                           fmt(b["iteration_over_factorization"])))
        elif p[0] == "BM_angle_bound_bunny":
            out.append("- bunny (%d faces), angle bound 70 degrees from %d random constraints: %s s, %d iterations%s, "
                       "smallest free angle %s degrees" % (int(b["faces"]), int(b["constraints"]), fmt(seconds(b)),
                                                           int(b["iterations"]),
                                                           "" if b["converged"] else " (not converged)",
                                                           fmt(b["min_free_angle_deg"])))
    out.append("")
    if quads:
        rows = []
        for b in quads["benchmarks"]:
            if b.get("run_type", "iteration") != "iteration":
                continue
            if "error_occurred" in b:
                rows.append([b.get("label", b["name"])] + ["-"] * 9 + ["error: " + b.get("error_message", "")])
                continue
            rows.append([b.get("label", b["name"]), int(b["faces"]), int(b["quads"]), fmt(b["field_s"]),
                         "%s (factorization %s, stiffening %s)" % (fmt(b["map_s"]), fmt(b["map_factorization_s"]),
                                                                   fmt(b["map_stiffening_s"])),
                         fmt(b["extraction_s"]), fmt(b["planarity_s"]),
                         "%s (%d iterations, closest points %s)" % (fmt(b["planarization_s"]),
                                                                    int(b["planarization_iterations"]),
                                                                    fmt(b["planarization_closest_points_s"])),
                         "%s%% / %s%%" % (fmt(100 * b["planarity_max_before"]), fmt(100 * b["planarity_mean_before"])),
                         "%s%%" % fmt(100 * b["planarity_max_after"]), int(b["flipped_faces"])])
        out.append("## Planar-quad pipeline, stage by stage\n")
        out.append(table(["run", "faces", "quads", "field s", "map s", "extraction s", "planarity s", "planarization s",
                          "planarity before max / mean", "max after", "flipped"], rows))
        out.append("")
    return "\n".join(out)


def load_json(resdir, name):
    path = os.path.join(resdir, name)
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--max-level", type=int, default=4, help="highest subdivision level (4: 640k faces, 5: 2.56M)")
    ap.add_argument("--build-dir", default=os.path.join(ROOT, "build-bench"))
    ap.add_argument("--out", default=os.path.join(ROOT, "benchmark", "results.md"))
    ap.add_argument("--jobs", type=int, default=2, help="parallel compile jobs (one CGAL TU takes ~1.3 GB)")
    ap.add_argument("--no-build", action="store_true", help="use the programs already built")
    ap.add_argument("--filter", default="", help="--benchmark_filter for pvf_design_benchmark")
    ap.add_argument("--report-only", action="store_true",
                    help="rewrite the tables from the JSON files of the last runs (build-dir/results)")
    road = ap.add_argument_group("the meshing road (issue 22)")
    road.add_argument("--road-only", action="store_true", help="run the meshing road only, not the design suite")
    road.add_argument("--no-road", action="store_true", help="run the design suite only, not the meshing road")
    road.add_argument("--road-groups", default=",".join(meshing_road.GROUPS),
                      help="comma-separated groups of the road to run (default: all): " + ", ".join(meshing_road.GROUPS))
    road.add_argument("--repeats", type=int, default=3,
                      help="runs of each road command but the 1M-face one and the growth series; the best counts "
                           "(default 3)")
    road.add_argument("--timeout", type=float, default=900,
                      help="seconds before a road run is killed and reported as missed (default 900)")
    road.add_argument("--bunny", default=None,
                      help="the bunny (default: ../shared/data/bunny.off beside the repository, else data/bunny.off)")
    road.add_argument("--growth", default=",".join(meshing_road.GROWTH_SCHEMES),
                      help="the sizes of the growth series: bumpy.off after these steps (L Loop, S sqrt 3), "
                           "comma-separated (default %s)" % ",".join(meshing_road.GROWTH_SCHEMES))
    road.add_argument("--corpus-results", default=None, metavar="DIR",
                      help="the --out folder of a run of scripts/run_corpus.py (nothing is run)")
    road.add_argument("--corpus-table", default=None, metavar="FILE",
                      help="run_corpus.py's standard output (its table) for that run: wall times and statuses")
    road.add_argument("--libigl-include", default=None, metavar="DIR",
                      help="include/ of a libigl checkout that has igl/n_polyvector.h: builds "
                           "pvf_libigl_n_polyvector against it for the libigl group (see that file's header)")
    road.add_argument("--libigl-program", default=None, metavar="EXE",
                      help="pvf_libigl_n_polyvector already built (default: the build's, if it is there)")
    args = ap.parse_args()
    groups = [g for g in args.road_groups.split(",") if g]
    unknown = [g for g in groups if g not in meshing_road.GROUPS]
    if unknown:
        ap.error("unknown --road-groups %s (groups: %s)" % (", ".join(unknown), ", ".join(meshing_road.GROUPS)))
    if args.road_only and args.no_road:
        ap.error("--road-only and --no-road exclude each other")
    if args.repeats < 1:
        ap.error("--repeats must be at least 1")
    if args.corpus_table and not args.corpus_results:
        ap.error("--corpus-table goes with --corpus-results")
    schemes = [g for g in args.growth.split(",") if g]
    if any(not c or c.strip("LS") for c in schemes):
        ap.error("--growth expects steps made of L and S, comma-separated, e.g. L,LL,LLL,LLLL")
    if len(schemes) < 4 and "growth" in groups and not args.no_road:
        print("note: fewer than 4 sizes in --growth: the growth target needs 4", file=sys.stderr)

    start = time.time()
    resdir = os.path.join(args.build_dir, "results")
    if args.report_only:
        names = ("design.json", "frames.json", "memory.json", "quads.json", "torus.json", "road.json")
        loaded = [load_json(resdir, name) for name in names]
        text = report(loaded[0], loaded[1], loaded[2], args.max_level, float("nan"), loaded[3], loaded[4], loaded[5])
        with open(args.out, "w") as f:
            f.write(text + "\n")
        print(text)
        return
    if not args.no_build:
        build(args.build_dir, args.jobs, ROAD_PROGRAMS if args.road_only else PROGRAMS, args.libigl_include)
    bindir = os.path.join(args.build_dir, "benchmark", "Polyvector_fields")
    cli = os.path.join(args.build_dir, "tools", "design_polyvector_field", "design_polyvector_field")
    os.makedirs(resdir, exist_ok=True)
    env = dict(os.environ, PVF_BENCH_MAX_LEVEL=str(args.max_level))

    design = frames = memory = quads = torus = None
    if not args.road_only:
        extra = ["--benchmark_filter=" + args.filter] if args.filter else []
        design = run_benchmark(os.path.join(bindir, "pvf_design_benchmark"), os.path.join(resdir, "design.json"),
                               env, extra)
        frames = run_benchmark(os.path.join(bindir, "pvf_frame_field_benchmark"), os.path.join(resdir, "frames.json"),
                               env)
        quads = run_benchmark(os.path.join(bindir, "pvf_quad_benchmark"), os.path.join(resdir, "quads.json"), env)

        # One process per (level, solver, mode) that the design benchmark ran.
        variants = sorted({(split_name(b["name"])[1], int(split_name(b["name"])[2])) for b in design["benchmarks"]
                           if split_name(b["name"])[0] == "BM_design" and "error_occurred" not in b})
        memory = []
        for solver_name, level in sorted(variants, key=lambda v: (v[1], v[0])):
            if solver_name not in MEMORY_SOLVERS:
                continue
            solver, mode = MEMORY_SOLVERS[solver_name]
            line = run([os.path.join(bindir, "pvf_peak_memory"), str(level), solver, mode], env=env, capture=True)
            entry = dict(kv.split("=", 1) for kv in line.split())
            for key in ("faces", "mesh_rss_kb", "peak_kb", "design_peak_kb", "hwm_reset"):
                entry[key] = int(entry[key])
            memory.append(entry)
        with open(os.path.join(resdir, "memory.json"), "w") as f:
            json.dump(memory, f, indent=1)

        torus = run_cli_torus(cli, resdir)
        with open(os.path.join(resdir, "torus.json"), "w") as f:
            json.dump(torus, f, indent=1)
    else:
        # The suite's tables of an earlier run, if any, stay in the report.
        design, frames, memory, quads, torus = (load_json(resdir, n) for n in
                                                ("design.json", "frames.json", "memory.json", "quads.json",
                                                 "torus.json"))
        if None in (design, frames, memory):
            design = frames = memory = quads = torus = None

    road = load_json(resdir, "road.json")
    if not args.no_road:
        bunny = args.bunny
        if bunny is None:
            shared = os.path.join(ROOT, "..", "shared", "data", "bunny.off")
            bunny = shared if os.path.isfile(shared) else os.path.join(ROOT, "data", "bunny.off")
        if not os.path.isfile(bunny):
            sys.exit("run_benchmarks.py: the bunny '%s' is not a file (--bunny PATH)" % bunny)
        n, m, R, r = TORUS
        ctx = {"root": ROOT, "resdir": resdir, "cli": cli, "subdivide": os.path.join(bindir, "pvf_subdivide_mesh"),
               "bunny": os.path.abspath(bunny), "bumpy": os.path.join(ROOT, "data", "bumpy.off"),
               "meshes": os.path.join(resdir, "road", "meshes"), "repeats": args.repeats, "timeout": args.timeout,
               "growth": schemes, "corpus_results": args.corpus_results, "corpus_table": args.corpus_table,
               "libigl_program": args.libigl_program or (os.path.join(bindir, "pvf_libigl_n_polyvector")
                                                         if os.access(os.path.join(bindir, "pvf_libigl_n_polyvector"),
                                                                      os.X_OK) else None),
               "torus_mesh": os.path.join(resdir, "torus_%dx%d.off" % (n, m)),
               "write_torus": lambda path: (write_torus(path + ".tmp", n, m, R, r), os.replace(path + ".tmp", path))}
        for program in (cli, ctx["subdivide"]):
            if not os.access(program, os.X_OK):
                sys.exit("run_benchmarks.py: '%s' is not built (run without --no-build, or build the targets %s)"
                         % (program, " ".join(ROAD_PROGRAMS)))
        os.makedirs(ctx["meshes"], exist_ok=True)

        def save(measured):
            with open(os.path.join(resdir, "road.json.tmp"), "w") as f:
                json.dump(measured, f, indent=1)
            os.replace(os.path.join(resdir, "road.json.tmp"), os.path.join(resdir, "road.json"))

        road = meshing_road.run_groups(ctx, groups, road, save)

    text = report(design, frames, memory, args.max_level, time.time() - start, quads, torus, road)
    with open(args.out, "w") as f:
        f.write(text + "\n")
    print(text)


if __name__ == "__main__":
    main()
