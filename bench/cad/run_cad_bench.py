#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""seamless against OpenCASCADE's BRepMesh on real CAD parts (issue 28, section 4).

For every STEP/IGES file of ../shared/models/cad-corpus/ and data/models/cad/
(sub-folders included), at D = 1e-3 and 1e-4 of the file's bounding box
diagonal (OpenCASCADE's, BRepBndLib::AddOptimal) and angle 0.5 rad:
  - `seamless tessellate --tolerance D --angle 28.65 (degrees) --stats` on 1
    and 2 threads, and `occt_mesh --deflection D --angle 0.5` on 1 and 2
    threads (BRepMesh_IncrementalMesh; reading timed apart);
  - `seamless check --closed --json` on both meshes (PLY with solid ids: each
    solid judged apart, solids in contact reported, not counted as defects);
  - `brep_deviation MODEL MESH` on both meshes: the same two-way measure
    against the B-rep (lib/mesh/deviation/brep_deviation.h);
then writes docs/results/cad.md. Every run has a time limit; a file seamless
refuses, or a run that fails or times out, is a row that says so.

Run from the source tree after building with -DSEAMLESS_BUILD_BENCH=ON:
    python3 bench/cad/run_cad_bench.py [--build build] [--timeout 120]
Python 3 standard library only.
"""

import argparse
import datetime
import glob
import json
import math
import os
import platform
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
EXTENSIONS = (".step", ".stp", ".iges", ".igs")
LEVELS = (1e-3, 1e-4)
ANGLE_RAD = 0.5
# `seamless tessellate --angle` takes degrees.
ANGLE_DEG = math.degrees(ANGLE_RAD)
# The meshes judged and measured: PLY, whose solid ids let `check` judge each
# solid apart (docs/check.md), for both tools.
MESH_EXT = "ply"


def corpus_files():
    files = []
    for folder in (os.path.join(SOURCE, "..", "shared", "models", "cad-corpus"),
                   os.path.join(SOURCE, "data", "models", "cad")):
        for path in glob.glob(os.path.join(folder, "**", "*"), recursive=True):
            if os.path.isfile(path) and path.lower().endswith(EXTENSIONS):
                files.append(os.path.normpath(path))
    return sorted(files, key=lambda p: (os.path.dirname(p), os.path.basename(p).lower()))


def run(cmd, timeout):
    """(returncode or 'timeout', stdout, stderr, wall seconds)."""
    t0 = time.monotonic()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout, p.stderr, time.monotonic() - t0
    except subprocess.TimeoutExpired:
        return "timeout", "", "", time.monotonic() - t0


def first_line(text, limit=90):
    for line in text.splitlines():
        line = line.strip()
        if line:
            return line if len(line) <= limit else line[:limit - 3] + "..."
    return ""


def parse_json(text):
    """The JSON object a tool printed (from its first line opening with '{')."""
    start = text.find("\n{") + 1 if not text.startswith("{") else 0
    try:
        return json.loads(text[start:]) if (start or text.startswith("{")) else None
    except ValueError:
        return None


def failure(rc, err, timeout, path=None):
    """One line: the time limit, or the tool's message without its prefixes."""
    if rc == "timeout":
        return "timeout (> %g s)" % timeout
    line = first_line(err, 1000)
    if line.startswith("error: "):
        line = line[len("error: "):]
    if path and line.startswith(path + ": "):
        line = line[len(path) + 2:]
    line = line if len(line) <= 90 else line[:87] + "..."
    return line or "exit %s" % rc


class Bench:
    def __init__(self, args):
        self.args = args
        self.seamless = os.path.join(args.build, "bin", "seamless")
        self.occt = os.path.join(args.build, "bench", "cad", "occt_mesh")
        self.deviation = os.path.join(args.build, "bench", "cad", "brep_deviation")
        os.makedirs(args.work, exist_ok=True)

    def out(self, path, level, tool, ext):
        name = os.path.basename(path)  # with its extension: torus.igs and torus.step both exist
        return os.path.join(self.args.work, "%s.%g.%s.%s" % (name, level, tool, ext))

    def occt_run(self, path, D, threads, output):
        cmd = [self.occt, path, "--deflection", repr(D), "--angle", repr(ANGLE_RAD),
               "--threads", str(threads), "--repeat", str(self.args.repeat)]
        if output:
            cmd += ["-o", output]
        rc, out, err, wall = run(cmd, self.args.timeout)
        js = parse_json(out) if rc in (0, 1) else None
        if js is None:
            return {"ok": False, "error": failure(rc, err, self.args.timeout, path), "wall": wall}
        js["ok"] = rc == 0
        if rc != 0:
            js["error"] = "no triangles"
        return js

    def seamless_run(self, path, D, threads, output, stats):
        cmd = [self.seamless, "tessellate", path, "-o", output, "--tolerance", repr(D),
               "--angle", "%.6f" % ANGLE_DEG, "--threads", str(threads), "--stats", stats]
        times = []
        js = None
        for _ in range(self.args.repeat):
            rc, out, err, wall = run(cmd, self.args.timeout)
            if rc != 0:
                return {"ok": False, "error": failure(rc, err, self.args.timeout, path),
                        "wall": wall}
            try:
                with open(stats) as f:
                    js = json.load(f)
            except (OSError, ValueError):
                return {"ok": False, "error": "no --stats file written", "wall": wall}
            # Meshing only: the certified bound that --stats computes is
            # reported apart (OpenCASCADE computes none).
            bound = js.get("brep", {}).get("bound_seconds", 0.0)
            times.append((js.get("seconds", wall) - bound, wall, bound))
            if wall > 5:  # slow: once is enough
                break
        times.sort()
        js["ok"] = True
        js["mesh_seconds"], js["wall"], js["bound_seconds"] = times[len(times) // 2]
        # Reading, writing, start-up and the bound: what the run took beyond meshing.
        js["other_seconds"] = max(0.0, js["wall"] - js["mesh_seconds"])
        return js

    def check(self, mesh):
        rc, out, err, _ = run([self.seamless, "check", "--closed", "--json", mesh],
                              self.args.timeout)
        js = parse_json(out) if rc in (0, 1) else None
        return js if js is not None else {"error": failure(rc, err, self.args.timeout)}

    def measure(self, path, mesh):
        rc, out, err, _ = run([self.deviation, path, mesh, "--threads", "2"],
                              self.args.deviation_timeout)
        js = parse_json(out) if rc == 0 else None
        if js is None:
            return {"error": failure(rc, err, self.args.deviation_timeout, path)}
        return js

    def tool_side(self, path, level, D, tool):
        """Both thread counts, the check and the deviation of one tool's mesh."""
        mesh = self.out(path, level, tool, MESH_EXT)
        if os.path.exists(mesh):
            os.remove(mesh)
        if tool == "occt":
            r1 = self.occt_run(path, D, 1, mesh)
        else:
            r1 = self.seamless_run(path, D, 1, mesh, self.out(path, level, tool, "json"))
        side = {"run1": r1}
        if not r1.get("ok"):
            return side
        if tool == "occt":
            side["run2"] = self.occt_run(path, D, 2, None)
        else:
            side["run2"] = self.seamless_run(path, D, 2, self.out(path, level, "seamless2", "off"),
                                             self.out(path, level, "seamless2", "json"))
        side["check"] = self.check(mesh)
        side["deviation"] = self.measure(path, mesh)
        return side

    def file(self, path):
        name = os.path.basename(path)
        print("==", name, flush=True)
        rc, out, err, _ = run([self.occt, path, "--info"], self.args.timeout)
        info = parse_json(out) if rc == 0 else None
        row = {"file": os.path.relpath(path, SOURCE), "name": name, "levels": {}}
        if info is None:
            row["error"] = "OpenCASCADE: " + failure(rc, err, self.args.timeout, path)
            return row
        row.update(diagonal=info["diagonal"], faces=info["faces"],
                   occt_read_seconds=info["read_seconds"])
        occt_timed_out = False
        for level in self.args.levels:
            D = level * info["diagonal"]
            entry = {"D": D}
            entry["seamless"] = self.tool_side(path, level, D, "seamless")
            if occt_timed_out:
                entry["occt"] = {"run1": {"ok": False, "error": "skipped (timed out at a coarser D)"}}
            else:
                entry["occt"] = self.tool_side(path, level, D, "occt")
                occt_timed_out = "timeout" in entry["occt"]["run1"].get("error", "")
            row["levels"][repr(level)] = entry
            for tool in ("seamless", "occt"):
                r = entry[tool]["run1"]
                print("  %g %-8s %s" % (level, tool, "%d triangles, %.3f s" % (
                    r["triangles"], r["mesh_seconds"]) if r.get("ok") else r.get("error")),
                      flush=True)
        return row


def machine():
    cpu = "unknown"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    occt = "unknown"
    try:
        with open("/usr/include/opencascade/Standard_Version.hxx") as f:
            for line in f:
                if line.startswith("#define OCC_VERSION_COMPLETE"):
                    occt = line.split('"')[1]
    except OSError:
        pass
    commit = subprocess.run(["git", "-C", SOURCE, "describe", "--always", "--dirty"],
                            capture_output=True, text=True).stdout.strip()
    return {"cpu": cpu, "cores": os.cpu_count(), "system": platform.platform(), "occt": occt,
            "commit": commit, "date": datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC"),
            "load": open("/proc/loadavg").read().split()[:3]}


def remeasure(bench, args):
    """The deviations of the meshes a previous run left in WORK, measured again."""
    results_path = os.path.join(args.work, "results.json")
    with open(results_path) as f:
        results = json.load(f)
    for row in results["rows"]:
        path = os.path.join(SOURCE, row["file"])
        for key, entry in row.get("levels", {}).items():
            for tool in ("seamless", "occt"):
                side = entry[tool]
                if side["run1"].get("ok"):
                    print("==", row["name"], key, tool, flush=True)
                    side["deviation"] = bench.measure(
                        path, bench.out(path, float(key), tool, MESH_EXT))
    with open(results_path, "w") as f:
        json.dump(results, f, indent=1)
    import cad_report
    with open(args.out, "w") as f:
        f.write(cad_report.markdown(results))
    print("wrote", args.out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(SOURCE, "build"))
    ap.add_argument("--work", default=None, help="meshes and raw results (default BUILD/cad-bench)")
    ap.add_argument("--out", default=os.path.join(SOURCE, "docs", "results", "cad.md"))
    ap.add_argument("--timeout", type=float, default=120, help="seconds per meshing or check run")
    ap.add_argument("--deviation-timeout", type=float, default=600)
    ap.add_argument("--repeat", type=int, default=3, help="timed meshings per run (median)")
    ap.add_argument("--levels", default=",".join(repr(x) for x in LEVELS))
    ap.add_argument("--report-only", action="store_true",
                    help="rewrite the report from WORK/results.json without running anything")
    ap.add_argument("--deviation-only", action="store_true",
                    help="measure the meshes of WORK/results.json's run again (after a change "
                         "to brep_deviation) and rewrite the report")
    ap.add_argument("files", nargs="*", help="default: the whole corpus")
    args = ap.parse_args()
    args.levels = [float(x) for x in args.levels.split(",")]
    args.work = args.work or os.path.join(args.build, "cad-bench")
    sys.path.insert(0, HERE)
    sys.dont_write_bytecode = True  # no __pycache__ in the source tree
    import cad_report
    if args.report_only:
        with open(os.path.join(args.work, "results.json")) as f:
            results = json.load(f)
        with open(args.out, "w") as f:
            f.write(cad_report.markdown(results))
        print("wrote", args.out)
        return
    bench = Bench(args)
    if args.deviation_only:
        remeasure(bench, args)
        return
    for tool in (bench.seamless, bench.occt, bench.deviation):
        if not os.access(tool, os.X_OK):
            sys.exit("missing %s: build with -DSEAMLESS_BUILD_BENCH=ON" % tool)
    files = [os.path.abspath(f) for f in args.files] or corpus_files()
    results = {"machine": machine(), "timeout": args.timeout, "repeat": args.repeat,
               "levels": args.levels, "angle": ANGLE_RAD, "rows": []}
    t0 = time.monotonic()
    for path in files:
        results["rows"].append(bench.file(path))
    results["machine"]["load_end"] = open("/proc/loadavg").read().split()[:3]
    results["machine"]["wall_minutes"] = (time.monotonic() - t0) / 60
    with open(os.path.join(args.work, "results.json"), "w") as f:
        json.dump(results, f, indent=1)
    with open(args.out, "w") as f:
        f.write(cad_report.markdown(results))
    print("wrote", args.out)


if __name__ == "__main__":
    main()
