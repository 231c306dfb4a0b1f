#!/usr/bin/python3
# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

"""Compares the irregular vertices of our quad meshes with QuadriFlow's (and Instant Meshes').

Usage:
  scripts/compare_remeshers.py --ours DIR --quadriflow PATH [--instant-meshes PATH]
                               [--checker PATH] [--sharp-edges D] [--timeout S]
                               [--work DIR] [--reuse] FOLDER_OR_FILE...

DIR is an output folder of scripts/run_corpus.py, run on the same FOLDER_OR_FILE
list (in the same order, so that the output names agree). For every mesh M whose
quad mesh DIR/<name>.quads.obj exists (the pipeline succeeded), with N the number
of quads in it:
  - M is written as a triangle OBJ (polygons split in fans) into the work folder,
    since QuadriFlow reads only OBJ triangles and quads;
  - QuadriFlow runs twice: `quadriflow -i M.obj -o OUT -f N`, then with `-sharp`;
  - with --instant-meshes, Instant Meshes runs in batch mode twice:
    `"Instant Meshes" -o OUT -f N/4 -d M.obj`, then with `-c D` (creases). Its
    pure-quad output splits every face of a quad-dominant mesh of about N/4 faces
    into quads, hence about N quads;
  - when M has a boundary (the checker counts boundary edges in it), QuadriFlow
    also gets `-boundary` and Instant Meshes `-b`, their options that align the
    field to the boundary (without it QuadriFlow leaves tens of irregular
    vertices along a boundary); --no-boundary-options leaves them out;
  - check_quad_mesh (which does not use the package's code) checks our quad mesh
    and every other output against M with --sharp-edges D --min-area-ratio 0.
Every run gets --timeout seconds (default 300) and runs alone. The outputs and
logs go to the work folder (default output/compare); --reuse keeps the outputs
already there instead of running the tool again.

It prints one Markdown table on standard output: per method, the quads, the
irregular vertices (interior + boundary, as counted by the checker), the
coverage of the input's edges sharper than D degrees (D = 40 by default) and the
checker's verdict (with the names of the failed checks). QuadriFlow and Instant
Meshes move vertices off the input surface, so the checker's `on_surface` check
(1e-6 of the bounding-box diagonal) is expected to fail for them; the table
gives their largest distance too. After the table come the totals: irregular
vertices per 1000 quads (sum over meshes, and median over meshes), over the
meshes where a method has an output and over the meshes where all have one, and
the same for the interior irregular vertices alone, and the meshes where ours
has more irregular vertices per 1000 quads than another method (with the ratio). The progress goes to standard error.

Example (part 5 of issue 21):
  scripts/run_corpus.py --out /tmp/c1 --sharp-edges 40 \\
      --options "--curvature-constraints 1" ../shared/data/corpus ../shared/data
  scripts/compare_remeshers.py --ours /tmp/c1 --quadriflow /path/to/quadriflow \\
      ../shared/data/corpus ../shared/data > compare.md
"""

import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_corpus  # noqa: E402  (its mesh listing, output names, process runner and summary parser)

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def parse_arguments():
    parser = argparse.ArgumentParser(
        description="Compare the irregular vertices of our quad meshes with QuadriFlow's and Instant Meshes'.")
    parser.add_argument("paths", nargs="+", metavar="FOLDER_OR_FILE",
                        help="the meshes given to scripts/run_corpus.py, in the same order")
    parser.add_argument("--ours", required=True, metavar="DIR", help="the output folder of scripts/run_corpus.py")
    parser.add_argument("--quadriflow", required=True, metavar="PATH", help="the QuadriFlow executable")
    parser.add_argument("--instant-meshes", metavar="PATH",
                        help="the Instant Meshes executable (batch mode); no Instant Meshes columns without it")
    parser.add_argument("--checker", default=os.path.join(REPO, "build", "tools", "check_quad_mesh",
                                                          "check_quad_mesh"),
                        help="the checker (default: build/tools/check_quad_mesh/check_quad_mesh)")
    parser.add_argument("--sharp-edges", type=float, default=40, metavar="D",
                        help="dihedral angle of the sharp edges, for the checker and Instant Meshes' -c (default 40)")
    parser.add_argument("--timeout", type=float, default=300, help="seconds per run before it is killed (default 300)")
    parser.add_argument("--work", default=os.path.join("output", "compare"),
                        help="folder of the triangle OBJ inputs, the outputs and the logs (default output/compare)")
    parser.add_argument("--no-boundary-options", action="store_true",
                        help="never give QuadriFlow -boundary nor Instant Meshes -b")
    parser.add_argument("--reuse", action="store_true",
                        help="keep an output already in the work folder instead of running the tool again")
    return parser.parse_args()


def read_polygons(path):
    """(vertices, polygons) of an OFF or OBJ file; polygons are lists of 0-based indices."""
    lower = path.lower()
    vertices, polygons = [], []
    with open(path, "r", errors="replace") as f:
        lines = [line.split("#")[0].strip() for line in f]
    if lower.endswith(".obj"):
        for line in lines:
            tokens = line.split()
            if not tokens:
                continue
            if tokens[0] == "v":
                vertices.append(tuple(float(x) for x in tokens[1:4]))
            elif tokens[0] == "f":
                polygon = []
                for token in tokens[1:]:
                    index = int(token.split("/")[0])
                    polygon.append(index - 1 if index > 0 else len(vertices) + index)
                polygons.append(polygon)
        return vertices, polygons
    if lower.endswith(".off"):
        lines = [line for line in lines if line]
        header = lines[0].split()
        if not header[0].endswith("OFF"):
            raise ValueError("not an OFF file")
        counts, rest = (header[1:4], lines[1:]) if len(header) >= 4 else (lines[1].split(), lines[2:])
        vertex_count, face_count = int(counts[0]), int(counts[1])
        for line in rest[:vertex_count]:
            vertices.append(tuple(float(x) for x in line.split()[:3]))
        for line in rest[vertex_count:vertex_count + face_count]:
            tokens = line.split()
            size = int(tokens[0])
            polygons.append([int(x) for x in tokens[1:1 + size]])
        return vertices, polygons
    raise ValueError("only .off and .obj are converted")


def write_triangle_obj(mesh, path):
    """Writes the mesh as an OBJ of triangles (fans), with full precision."""
    vertices, polygons = read_polygons(mesh)
    with open(path, "w") as f:
        for v in vertices:
            f.write("v %.17g %.17g %.17g\n" % v)
        for polygon in polygons:
            for i in range(1, len(polygon) - 1):
                f.write("f %d %d %d\n" % (polygon[0] + 1, polygon[i] + 1, polygon[i + 1] + 1))


def check(arguments, mesh, quads):
    """The checker's summary of the quad mesh against the mesh ({} when it could not run)."""
    command = [arguments.checker, mesh, quads, "--sharp-edges", "%g" % arguments.sharp_edges,
               "--min-area-ratio", "0"]
    code, out, err, _ = run_corpus.run_process(command, arguments.timeout)
    summary = run_corpus.parse_summary(out)
    if summary:
        summary["_report"] = out
    return summary


def run_method(arguments, method, tri_obj, output, quad_count, boundary):
    """Runs one remesher; (status, seconds). status is 'ok', 'timeout', 'exit N' or 'no output'."""
    if arguments.reuse and os.path.isfile(output) and os.path.getsize(output) > 0:
        return "ok", 0.0
    if os.path.exists(output):
        os.remove(output)
    if method.startswith("qf"):
        command = [arguments.quadriflow, "-i", tri_obj, "-o", output, "-f", str(quad_count)]
        if method == "qf-sharp":
            command.append("-sharp")
        if boundary:
            command.append("-boundary")
    else:
        command = [arguments.instant_meshes, "-o", output, "-f", str(max(1, round(quad_count / 4))), "-d"]
        if method == "im-crease":
            command += ["-c", "%g" % arguments.sharp_edges]
        if boundary:
            command.append("-b")
        command.append(tri_obj)
    code, out, err, seconds = run_corpus.run_process(command, arguments.timeout)
    with open(output + ".log", "w") as log:
        log.write("$ %s\n%s\n%s" % (" ".join(command), out, err))
    if code is None:
        return "timeout", seconds
    if code != 0:
        return "exit %d" % code, seconds
    if not os.path.isfile(output) or os.path.getsize(output) == 0:
        return "no output", seconds
    return "ok", seconds


METHOD_TITLES = {"ours": "ours", "qf": "QF", "qf-sharp": "QF -sharp", "im": "IM", "im-crease": "IM -c"}


def irregular(summary):
    return int(summary["irregular_interior"]) + int(summary["irregular_boundary"])


def interior(summary):
    return int(summary["irregular_interior"])


def per_thousand(summary, count=irregular):
    return 1000.0 * count(summary) / max(1, int(summary["quads"]))


def irregular_cell(summary):
    if int(summary["irregular_boundary"]):
        return "%d (%s+%s)" % (irregular(summary), summary["irregular_interior"], summary["irregular_boundary"])
    return str(irregular(summary))


def sharp_cell(summary):
    if int(summary.get("sharp_edges", 0)) == 0:
        return "-"
    return "%.1f%%" % (100.0 * float(summary["sharp_coverage"]))


def verdict_cell(summary):
    if summary.get("valid") == "1":
        return "yes"
    text = "no (%s)" % summary.get("failed", "?")
    if "on_surface" in summary.get("failed", "") and "max_distance" in summary:
        text += " %.2g diag" % float(summary["max_distance"])
    return text


def print_table(methods, rows):
    header = ["mesh"]
    for method in methods:
        title = METHOD_TITLES[method]
        header += ["%s quads" % title, "%s irregular" % title, "%s sharp" % title, "%s valid" % title]
    print("| " + " | ".join(header) + " |")
    print("|---|" + "---:|---:|---:|---|" * len(methods))
    for name, results in rows:
        cells = [name]
        for method in methods:
            status, summary = results.get(method, ("missing", {}))
            if status == "ok" and summary:
                cells += [summary["quads"], irregular_cell(summary), sharp_cell(summary), verdict_cell(summary)]
            else:
                cells += ["", "", "", "**%s**" % (status if status != "ok" else "unchecked")]
        print("| " + " | ".join(cells) + " |")


def print_totals(methods, rows):
    def measured(results, method):
        status, summary = results.get(method, ("missing", {}))
        return summary if status == "ok" and summary and "quads" in summary else None

    common = [results for _, results in rows if all(measured(results, m) for m in methods)]
    for title, count in (("Irregular vertices (interior + boundary)", irregular),
                         ("Interior irregular vertices", interior)):
        print()
        print("%s per 1000 quads: sum over the meshes (total irregular / total quads), and median of the "
              "meshes' ratios." % title)
        print()
        print("| method | meshes with an output | valid per checker | per 1000 quads (sum) | median | "
              "on the %d meshes where all have an output: sum | median |" % len(common))
        print("|---|---:|---:|---:|---:|---:|---:|")
        for method in methods:
            summaries = [measured(results, method) for _, results in rows]
            summaries = [s for s in summaries if s]
            on_common = [measured(results, method) for results in common]

            def sum_and_median(items):
                if not items:
                    return "", ""
                irregulars, quads = sum(count(s) for s in items), sum(int(s["quads"]) for s in items)
                return ("%.2f (%d / %d)" % (1000.0 * irregulars / max(1, quads), irregulars, quads),
                        "%.2f" % statistics.median(per_thousand(s, count) for s in items))
            all_sum, all_median = sum_and_median(summaries)
            common_sum, common_median = sum_and_median(on_common)
            valid = sum(1 for s in summaries if s.get("valid") == "1")
            print("| %s | %d | %d | %s | %s | %s | %s |" % (METHOD_TITLES[method], len(summaries), valid,
                                                           all_sum, all_median, common_sum, common_median))
    for other in [m for m in methods if m != "ours"]:
        worse = []
        for name, results in rows:
            ours, theirs = measured(results, "ours"), measured(results, other)
            if ours and theirs and per_thousand(ours) > per_thousand(theirs):
                ratio = per_thousand(ours) / per_thousand(theirs) if per_thousand(theirs) > 0 else float("inf")
                worse.append((ratio, "%s (%d in %s quads vs %d in %s, x%.2f)" % (
                    name, irregular(ours), ours["quads"], irregular(theirs), theirs["quads"], ratio)))
        worse.sort(key=lambda item: -item[0])
        print()
        print("Meshes where ours has more irregular vertices per 1000 quads than %s: %s" % (
            METHOD_TITLES[other], "; ".join(text for _, text in worse) if worse else "none"))


def main():
    arguments = parse_arguments()
    for executable in [arguments.quadriflow, arguments.checker] + (
            [arguments.instant_meshes] if arguments.instant_meshes else []):
        if not os.access(executable, os.X_OK):
            sys.exit("compare_remeshers.py: '%s' is not an executable" % executable)
    os.makedirs(arguments.work, exist_ok=True)
    methods = ["ours", "qf", "qf-sharp"] + (["im", "im-crease"] if arguments.instant_meshes else [])

    meshes = run_corpus.find_meshes(arguments.paths)
    names = run_corpus.output_names(meshes)
    rows, skipped = [], []
    for mesh, name in zip(meshes, names):
        ours = os.path.join(arguments.ours, name + ".quads.obj")
        if not os.path.isfile(ours):
            skipped.append(name)
            continue
        print("%s ..." % name, file=sys.stderr, flush=True)
        results = {}
        summary = check(arguments, mesh, ours)
        results["ours"] = ("ok", summary)
        quad_count = int(summary.get("quads", 0)) if summary else 0
        if quad_count == 0:
            rows.append((name, results))
            continue
        tri_obj = os.path.join(arguments.work, name + ".tri.obj")
        try:
            write_triangle_obj(mesh, tri_obj)
        except (OSError, ValueError, IndexError) as error:
            for method in methods[1:]:
                results[method] = ("input not converted: %s" % error, {})
            rows.append((name, results))
            continue
        for method in methods[1:]:
            boundary = not arguments.no_boundary_options and int(summary.get("boundary_edges", 0)) > 0
            output = os.path.join(arguments.work, "%s.%s%s.obj" % (name, method, ".b" if boundary else ""))
            status, seconds = run_method(arguments, method, tri_obj, output, quad_count, boundary)
            results[method] = (status, check(arguments, mesh, output) if status == "ok" else {})
            print("  %s: %s (%.1f s)" % (method, status, seconds), file=sys.stderr, flush=True)
        rows.append((name, results))

    print("Checker: `check_quad_mesh INPUT QUADS --sharp-edges %g --min-area-ratio 0`; QF: QuadriFlow `-f` at our "
          "quad count%s%s." % (arguments.sharp_edges,
                               "; IM: Instant Meshes `-f` a quarter of it, `-d`" if arguments.instant_meshes else "",
                               "" if arguments.no_boundary_options else
                               "; on meshes with a boundary, QF `-boundary` and IM `-b`"))
    print()
    print_table(methods, rows)
    print_totals(methods, rows)
    if skipped:
        print()
        print("Without our quad mesh (not compared): %s" % ", ".join(skipped))
    return 0


if __name__ == "__main__":
    sys.exit(main())
