#!/usr/bin/python3
# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

"""Runs the field-to-quads pipeline on a folder of meshes and checks every quad mesh.

Usage:
  scripts/run_corpus.py [--exe PATH] [--checker PATH] [--jobs J] [--timeout S]
                        [--out DIR] [--options "..."] [--sharp-edges D]
                        [--min-area-ratio R] [--max-hausdorff H]
                        FOLDER_OR_FILE...

For every .off/.obj/.ply/.stl mesh (folders are not searched recursively) it runs
  design_polyvector_field --mesh M <options> --quad-mesh OUT/<name>.quads.obj
      --out-mesh OUT/<name>.mesh.off --out-field ... --out-singularities ...
(the log of each run is OUT/<name>.log), then checks the quad mesh against M with
check_quad_mesh, which does not use the package's code. Each mesh gets one of:
  ok        exit 0 and the checker accepts the quad mesh
  refused   exit 1 with a message about the mesh file, and the checker cannot
            make a surface of the file either: the input is not a surface
  failed    exit 1 (or 2) otherwise, including a refused mesh that the checker
            reads as a surface
  crashed   killed by a signal
  timeout   still running after --timeout seconds (default 300), killed
  INVALID   exit 0, but the checker rejects the output (the worst case)
  unchecked exit 0, but the checker could not run
It prints one Markdown table on standard output, then a line of totals; the
progress goes to standard error. The exit status is 0 when every mesh is ok or
refused, 1 otherwise.

Defaults: the executables of build/ in this repository, --out output/corpus,
the checker's bars --min-area-ratio 0.98 and --max-hausdorff 0.01. With
--planarize among the options, when the program says it planarized the quads
to a threshold T, the checker holds every quad to T (--max-planarity) and lets
the vertices lie --max-surface-distance (default 0.05) mean quad edges off
the surface; when the program wrote the quads as extracted, they are checked
as without --planarize (vertices within 1e-6 of the bounding-box diagonal),
and the table gives their planarity. --sharp-edges D
is given to both the pipeline and the checker, which then measures the part of
the input's edges sharper than D degrees that lies on quad edges: within 1% of
the mean quad edge, and "traced" (within 1%, or between the ends of a quad edge
whose two ends are on the sharp edges and within a quarter of its length: the
chords of a curved crease; see check_quad_mesh).

Example (the command of issue 21):
  scripts/run_corpus.py --jobs 2 --options "--curvature-constraints 1" ../shared/data/corpus
"""

import argparse
import concurrent.futures
import os
import re
import shlex
import signal
import subprocess
import sys
import threading
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MESH_EXTENSIONS = (".off", ".obj", ".ply", ".stl")
STATUSES = ("ok", "refused", "failed", "crashed", "timeout", "INVALID", "unchecked")


def parse_arguments():
    parser = argparse.ArgumentParser(
        description="Run design_polyvector_field --quad-mesh on meshes and check each quad mesh independently.")
    parser.add_argument("paths", nargs="+", metavar="FOLDER_OR_FILE", help="meshes, or folders of meshes")
    parser.add_argument("--exe", default=os.path.join(REPO, "build", "tools", "design_polyvector_field",
                                                      "design_polyvector_field"),
                        help="the pipeline (default: build/tools/design_polyvector_field/design_polyvector_field)")
    parser.add_argument("--checker", default=os.path.join(REPO, "build", "tools", "check_quad_mesh",
                                                          "check_quad_mesh"),
                        help="the checker (default: build/tools/check_quad_mesh/check_quad_mesh)")
    parser.add_argument("--jobs", type=int, default=1, help="meshes run at the same time (default 1)")
    parser.add_argument("--timeout", type=float, default=300, help="seconds per run before it is killed (default 300)")
    parser.add_argument("--out", default=os.path.join("output", "corpus"),
                        help="folder of the outputs and logs (default output/corpus)")
    parser.add_argument("--options", default="", help="more options for design_polyvector_field, one string")
    parser.add_argument("--sharp-edges", type=float, default=None, metavar="D",
                        help="give --sharp-edges D to the pipeline, and measure the sharp-edge coverage")
    parser.add_argument("--min-area-ratio", type=float, default=0.98,
                        help="the checker's bar on quad area / input area (default 0.98; 0: reported only)")
    parser.add_argument("--max-hausdorff", type=float, default=0.01,
                        help="the checker's bar on the input-to-quads distance, in bbox diagonals (default 0.01)")
    arguments = parser.parse_args()
    if arguments.jobs < 1:
        parser.error("--jobs must be at least 1")
    if not arguments.timeout > 0:
        parser.error("--timeout must be positive")
    for tool in (arguments.exe, arguments.checker):
        if not os.access(tool, os.X_OK):
            parser.error("'%s' is not an executable: build it (cmake --build build --target "
                         "design_polyvector_field check_quad_mesh) or give its path" % tool)
    return arguments


def find_meshes(paths):
    """The meshes named or found in the folders, in order, without repetition."""
    meshes = []
    for path in paths:
        if os.path.isdir(path):
            for name in sorted(os.listdir(path)):
                full = os.path.join(path, name)
                if os.path.isfile(full) and name.lower().endswith(MESH_EXTENSIONS):
                    meshes.append(full)
        elif os.path.isfile(path):
            meshes.append(path)
        else:
            sys.exit("run_corpus.py: '%s' is neither a mesh nor a folder" % path)
    unique = []
    for mesh in meshes:
        if os.path.abspath(mesh) not in (os.path.abspath(m) for m in unique):
            unique.append(mesh)
    return unique


def output_names(meshes):
    """A distinct output stem for each mesh: its file name, prefixed by its folder when two share one."""
    names, seen = [], set()
    for mesh in meshes:
        name = os.path.basename(mesh)
        if name in seen:
            name = os.path.basename(os.path.dirname(os.path.abspath(mesh))) + "_" + name
        while name in seen:
            name = "_" + name
        seen.add(name)
        names.append(name)
    return names


def count_faces(path):
    """The number of faces in the file, read cheaply; None when the file is not understood."""
    try:
        lower = path.lower()
        if lower.endswith(".obj"):
            with open(path, "rb") as f:
                return sum(1 for line in f if line.startswith(b"f ") or line.startswith(b"f\t"))
        if lower.endswith(".off"):
            tokens = []
            with open(path, "rb") as f:
                for line in f:
                    tokens += line.split(b"#")[0].split()
                    if len(tokens) >= 4:
                        break
            return int(tokens[2]) if len(tokens) >= 4 and tokens[0].endswith(b"OFF") else None
        if lower.endswith(".ply"):
            with open(path, "rb") as f:
                for line in f:
                    match = re.match(rb"element\s+face\s+(\d+)", line)
                    if match:
                        return int(match.group(1))
                    if line.startswith(b"end_header"):
                        return None
        if lower.endswith(".stl"):
            with open(path, "rb") as f:
                data = f.read()
            if data[:5] == b"solid" and b"facet" in data[:1000]:
                return data.count(b"endfacet")
            if len(data) >= 84:
                return int.from_bytes(data[80:84], "little")
    except (OSError, ValueError):
        return None
    return None


def run_process(command, timeout, cwd=None):
    """(returncode or None on timeout, stdout, stderr, seconds); the process group is killed on timeout."""
    start = time.monotonic()
    try:
        process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=cwd,
                                   start_new_session=True)
    except OSError as error:
        return 127, "", "cannot run %s: %s" % (command[0], error), time.monotonic() - start
    try:
        out, err = process.communicate(timeout=timeout)
        code = process.returncode
    except subprocess.TimeoutExpired:
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        out, err = process.communicate()
        code = None
    return code, out.decode("utf-8", "replace"), err.decode("utf-8", "replace"), time.monotonic() - start


def last_line(text):
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    return lines[-1] if lines else ""


def parse_summary(text):
    for line in reversed(text.splitlines()):
        if line.startswith("summary "):
            return dict(item.split("=", 1) for item in line.split()[1:] if "=" in item)
    return {}


def option_value(options, flag):
    """The value after `flag` in the option list, or None."""
    for i, option in enumerate(options):
        if option == flag and i + 1 < len(options):
            return options[i + 1]
    return None


def run_one(mesh, name, arguments, cli_options):
    out = os.path.abspath(arguments.out)
    stem = os.path.join(out, name)
    quads = stem + ".quads.obj"
    for old in (quads, stem + ".mesh.off", stem + ".log", stem + ".check.txt"):
        if os.path.exists(old):
            os.remove(old)
    command = [os.path.abspath(arguments.exe), "--mesh", os.path.abspath(mesh)] + cli_options + [
        "--quad-mesh", quads, "--out-mesh", stem + ".mesh.off", "--out-field", stem + ".rawfield",
        "--out-singularities", stem + ".sings"]
    code, stdout, stderr, seconds = run_process(command, arguments.timeout, cwd=out)
    with open(stem + ".log", "w") as log:
        log.write("$ " + " ".join(shlex.quote(c) for c in command) + "\n" + stdout + stderr)
    result = {"mesh": mesh, "faces": count_faces(mesh), "seconds": seconds, "reason": "", "check": {}}
    message = last_line(stderr).replace("design_polyvector_field: ", "", 1)
    if code is None:
        result.update(status="timeout", reason="killed after %g s" % arguments.timeout)
    elif code < 0:
        try:
            signal_name = signal.Signals(-code).name
        except ValueError:
            signal_name = "signal %d" % -code
        said = message or last_line(stdout)  # e.g. a solver library's last words
        result.update(status="crashed", reason=signal_name + (" after: " + said if said else ""))
    elif code != 0:
        if code == 1 and message.startswith("mesh '"):
            # The pipeline says the file is not a surface: does an independent reader agree?
            check_code, _, check_err, _ = run_process(
                [os.path.abspath(arguments.checker), os.path.abspath(mesh), "--input-only"], arguments.timeout)
            message = message.replace("mesh '%s': " % os.path.abspath(mesh), "", 1)
            if check_code == 2:
                why = last_line(check_err).split(" is not a surface: ")
                result.update(status="refused", reason=message + (" (check_quad_mesh: " + why[1] + ")"
                                                                  if len(why) == 2 else ""))
            else:
                result.update(status="failed", reason="refused a mesh that check_quad_mesh reads as a surface: "
                              + message)
        else:
            result.update(status="failed", reason=("exit %d: " % code if code != 1 else "") + message)
    elif not os.path.isfile(quads):
        result.update(status="INVALID", reason="exit 0, but no quad mesh was written")
    else:
        checker = [os.path.abspath(arguments.checker), os.path.abspath(mesh), quads,
                   "--min-area-ratio", repr(arguments.min_area_ratio),
                   "--max-hausdorff", repr(arguments.max_hausdorff)]
        sharp = option_value(cli_options, "--sharp-edges")
        if sharp is not None:
            checker += ["--sharp-edges", sharp]
        if "--planarize" in cli_options:
            planarized = planarization_outcome(stdout)
            result["planarization"] = planarized
            if planarized is not None:
                # the program says the quads are planar to T within its distance bound: both are checked
                surface_distance = option_value(cli_options, "--max-surface-distance")
                checker += ["--max-planarity", repr(planarized),
                            "--distance-tolerance-edge", surface_distance if surface_distance else "0.05"]
        check_code, check_out, check_err, _ = run_process(checker, arguments.timeout)
        with open(stem + ".check.txt", "w") as report:
            report.write("$ " + " ".join(shlex.quote(c) for c in checker) + "\n" + check_out + check_err)
        result["check"] = parse_summary(check_out)
        if check_code == 0:
            result.update(status="ok")
        elif check_code == 1:
            result.update(status="INVALID", reason=invalid_reason(check_out, result["check"], arguments))
        else:
            result.update(status="unchecked",
                          reason="check_quad_mesh exit %s: %s" % (check_code, last_line(check_err or check_out)))
    return result


def planarization_outcome(stdout):
    """The threshold the program says every quad is planar to, or None when it wrote the quads as extracted."""
    for line in stdout.splitlines():
        if line.startswith("planarity ") and " -> after " in line:
            match = re.search(r"\(threshold ([0-9.eE+-]+)%\)", line)
            if match:
                return float(match.group(1)) / 100
    return None


def invalid_reason(check_out, summary, arguments):
    """The failed checks of check_quad_mesh, in a few words each."""
    lines = {line.split(":", 1)[0]: line for line in check_out.splitlines() if "(FAIL" in line}
    parts = []
    for name in summary.get("failed", ",".join(lines)).split(","):
        s = summary
        if name == "all_quads":
            parts.append("%s of %s faces not quads" % (s.get("non_quads", "?"), s.get("quads", "?")))
        elif name == "manifold":
            value = lines.get(name, "").split(":", 1)[-1].split(" (FAIL")[0]
            parts.append("not manifold: " + ", ".join(item.strip() for item in value.split(",")
                                                       if not item.strip().startswith("0 ")))
        elif name == "components":
            parts.append("components: input %s, quads %s" % (s.get("input_components", "?"),
                                                              s.get("quad_components", "?")))
        elif name == "euler":
            parts.append("%s closed component(s) open or with another Euler characteristic"
                         % s.get("euler_mismatches", "?"))
        elif name == "on_surface":
            parts.append("a vertex %s bbox diagonal off the surface" % s.get("max_distance", "?"))
        elif name == "folded":
            both = s.get("folded_both_diagonals")
            parts.append("%s folded quad(s)%s" % (s.get("folded", "?"),
                                                   " (%s along both diagonals)" % both if both is not None else ""))
        elif name == "area_ratio":
            parts.append("area ratio %s < %g" % (s.get("area_ratio", "?"), arguments.min_area_ratio))
        elif name == "hausdorff":
            parts.append("Hausdorff %s > %g" % (s.get("hausdorff", "?"), arguments.max_hausdorff))
        elif name == "planar":
            parts.append("a quad of planarity %s beyond the program's threshold" % s.get("max_planarity", "?"))
        else:
            parts.append(lines.get(name, name))
    return "; ".join(parts)


def cell(text, limit=160):
    text = str(text).replace("|", "\\|").replace("\n", " ")
    return text if len(text) <= limit else text[:limit - 1] + "…"


def print_table(results, planarize):
    print("| mesh | faces | status | reason | seconds | quads | irregular vertices | area ratio | "
          "Hausdorff/diag | sharp-edge coverage, traced (and boundary) |" + (" planarity max |" if planarize else ""))
    print("|---|---:|---|---|---:|---:|---:|---:|---:|---:|" + ("---|" if planarize else ""))
    for r in results:
        c = r["check"]
        irregular = ""
        if "irregular_interior" in c:
            irregular = c["irregular_interior"] + (
                "+" + c["irregular_boundary"] if c.get("irregular_boundary", "0") != "0" else "")
        coverage = c.get("sharp_coverage", "")
        if c.get("sharp_edges") == "0":
            coverage = "no sharp edge"
        elif coverage not in ("", "-"):
            coverage = "%.1f%% of %s edges" % (100 * float(coverage), c.get("sharp_edges", "?"))
            if c.get("sharp_traced", "-") != "-":
                coverage += ", traced %.1f%%" % (100 * float(c["sharp_traced"]))
        elif coverage == "-":
            coverage = ""
        if c.get("boundary_edges", "0") != "0":
            coverage += ("; " if coverage else "") + "boundary %.1f%% of %s edges" % (
                100 * float(c.get("boundary_coverage", "nan")), c["boundary_edges"])
            if "boundary_traced" in c:
                coverage += ", traced %.1f%%" % (100 * float(c["boundary_traced"]))
        planarity = ""
        if planarize and "max_planarity" in c:
            planarity = "%.3g%% " % (100 * float(c["max_planarity"]))
            planarity += ("(planarized to %g%%)" % (100 * r["planarization"]) if r.get("planarization") is not None
                          else "(as extracted)")
        print("| %s | %s | %s | %s | %.1f | %s | %s | %s | %s | %s |%s" % (
            cell(os.path.basename(r["mesh"])), "" if r["faces"] is None else r["faces"],
            "**%s**" % r["status"] if r["status"] not in ("ok", "refused") else r["status"],
            cell(r["reason"]), r["seconds"], c.get("quads", ""), irregular,
            c.get("area_ratio", ""), c.get("hausdorff", ""), coverage,
            " %s |" % planarity if planarize else ""))


def main():
    arguments = parse_arguments()
    meshes = find_meshes(arguments.paths)
    if not meshes:
        sys.exit("run_corpus.py: no .off/.obj/.ply/.stl mesh in " + " ".join(arguments.paths))
    os.makedirs(arguments.out, exist_ok=True)
    cli_options = shlex.split(arguments.options)
    if arguments.sharp_edges is not None:
        cli_options += ["--sharp-edges", "%g" % arguments.sharp_edges]
    names = output_names(meshes)
    lock = threading.Lock()
    done = [0]

    def job(index):
        result = run_one(meshes[index], names[index], arguments, cli_options)
        with lock:
            done[0] += 1
            sys.stderr.write("[%d/%d] %s: %s (%.1f s) %s\n" % (done[0], len(meshes), names[index], result["status"],
                                                               result["seconds"], result["reason"][:120]))
            sys.stderr.flush()
        return result

    with concurrent.futures.ThreadPoolExecutor(max_workers=arguments.jobs) as pool:
        results = list(pool.map(job, range(len(meshes))))

    print("options: `%s`" % " ".join(shlex.quote(o) for o in cli_options))
    print()
    print_table(results, "--planarize" in cli_options)
    counts = {status: sum(1 for r in results if r["status"] == status) for status in STATUSES}
    print()
    print("total: %d meshes: " % len(results) +
          ", ".join("%s %d" % (status, counts[status]) for status in STATUSES
                    if counts[status] > 0 or status in ("ok", "refused", "failed", "crashed", "timeout", "INVALID")))
    bad = len(results) - counts["ok"] - counts["refused"]
    return 0 if bad == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
