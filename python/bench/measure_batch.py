# SPDX-License-Identifier: MIT
"""Figures of docs/results/batch.md: the batch's per-file overhead (many
small files, one worker, against the same CLI calls in a plain loop; wall
and CPU seconds) and its speed-up from 1 to 2 local workers on a corpus,
with the speed-up an idle machine allows (the fastest 1-worker run's
per-file wall and CPU seconds scheduled on 2 workers in the batch's order,
largest file first, and longest job first).

    PYTHONPATH=build/python /usr/bin/python3 python/bench/measure_batch.py \
        [--corpus DIR|LIST] [--small MODEL] [--time-limit S] [--repeat N] [--skip-overhead]
        [--raw FILE.json]

The speed-up runs alternate 1 and 2 workers --repeat times; each run's
load average (1 minute) is printed beside it, and --raw keeps every run's
per-file seconds.
"""

import argparse
import heapq
import json
import os
import pathlib
import resource
import shutil
import subprocess
import tempfile
import time

from seamless.batch import default_cli, run_batch

ROOT = pathlib.Path(__file__).resolve().parents[2]


def cpu(who):
    r = resource.getrusage(who)
    return r.ru_utime + r.ru_stime


def overhead(model, n=200):
    """Per file, (wall, own CPU, children's CPU): the batch on one worker, the CLI in a loop."""
    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(tmp, "small")
        folder.mkdir()
        for i in range(n):
            shutil.copy(model, folder / f"m{i:04d}.json")
        cli = default_cli()
        t, s, c = time.monotonic(), cpu(resource.RUSAGE_SELF), cpu(resource.RUSAGE_CHILDREN)
        for i in range(n):
            out = pathlib.Path(tmp, f"plain{i}.glb")
            subprocess.run([cli, "tessellate", folder / f"m{i:04d}.json", "-o", out, "--stats",
                            f"{out}.json", "--threads", "1"], check=True, capture_output=True)
        plain = ((time.monotonic() - t) / n, (cpu(resource.RUSAGE_SELF) - s) / n,
                 (cpu(resource.RUSAGE_CHILDREN) - c) / n)
        t, s, c = time.monotonic(), cpu(resource.RUSAGE_SELF), cpu(resource.RUSAGE_CHILDREN)
        run_batch([folder], pathlib.Path(tmp, "out"), workers=1)
        batch = ((time.monotonic() - t) / n, (cpu(resource.RUSAGE_SELF) - s) / n,
                 (cpu(resource.RUSAGE_CHILDREN) - c) / n)
    return batch, plain


def list_makespan(seconds, workers):
    """Finish time of the jobs, in this order, each given to whichever worker is free first."""
    loads = [0.0] * workers
    for s in seconds:
        heapq.heappush(loads, heapq.heappop(loads) + s)
    return max(loads)


def lpt_makespan(seconds, workers):
    """The same, the longest job first (longest-processing-time-first)."""
    return list_makespan(sorted(seconds, reverse=True), workers)


def one_run(corpus, workers, time_limit):
    """(wall seconds, {input: (outcome, seconds)}, summary) of one batch over the corpus."""
    with tempfile.TemporaryDirectory() as tmp:
        start = time.monotonic()
        summary = run_batch([corpus], tmp, workers=workers, check=True, time_limit=time_limit)
        wall = time.monotonic() - start
        with open(os.path.join(tmp, "manifest.jsonl")) as f:
            files = {}
            for line in f:
                e = json.loads(line)
                files[os.path.basename(e["input"])] = {
                    k: e.get(k) for k in ("outcome", "size", "seconds", "cpu_seconds")}
    return wall, files, summary


def speedups(corpus, time_limit, repeat):
    runs = []
    for r in range(repeat):
        for workers in (1, 2):
            load = os.getloadavg()[0]
            wall, files, summary = one_run(corpus, workers, time_limit)
            runs.append({"workers": workers, "wall": wall, "load_before": load,
                         "load_after": os.getloadavg()[0], "files": files,
                         "outcomes": summary["outcomes"]})
            print(f"run {r + 1}, {workers} worker(s): {wall:.2f} s, load {load:.2f} -> "
                  f"{runs[-1]['load_after']:.2f}, outcomes {summary['outcomes']}", flush=True)
    return runs


def report_speedups(runs):
    ones = [r for r in runs if r["workers"] == 1]
    twos = [r for r in runs if r["workers"] == 2]
    ratios = [a["wall"] / b["wall"] for a, b in zip(ones, twos)]
    print("speed-ups (1-worker wall / 2-worker wall, pairwise): "
          + ", ".join(f"{x:.2f}" for x in ratios))
    best1, best2 = min(r["wall"] for r in ones), min(r["wall"] for r in twos)
    print(f"best 1 worker {best1:.2f} s, best 2 workers {best2:.2f} s: {best1 / best2:.2f}")
    files = min(ones, key=lambda r: r["wall"])["files"]
    for key in ("seconds", "cpu_seconds"):
        cost = {name: f[key] for name, f in files.items() if f[key] is not None}
        if not cost:
            continue
        total = sum(cost.values())
        by_size = [cost[n] for n in sorted(cost, key=lambda n: -files[n]["size"])]
        print(f"per-file {key} of the best 1-worker run: sum {total:.2f}, longest "
              f"{max(cost.values()):.2f}; 2 workers on an idle machine: largest file first "
              f"(the batch's order) {total / list_makespan(by_size, 2):.2f}x, longest job "
              f"first {total / lpt_makespan(list(cost.values()), 2):.2f}x")
    slowest = sorted(files.items(), key=lambda kv: -kv[1]["seconds"])[:8]
    for name, f in slowest:
        print(f"  {f['seconds']:8.2f} s wall {f['cpu_seconds'] or 0:8.2f} s CPU "
              f"{f['outcome']:10} {name}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corpus", default=str(ROOT.parent / "shared/models/cad-corpus"))
    ap.add_argument("--small", default=str(ROOT / "data/models/bilinear.json"))
    ap.add_argument("--time-limit", type=float, default=600)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--skip-overhead", action="store_true")
    ap.add_argument("--raw", help="write every run's figures here (JSON)")
    a = ap.parse_args()
    print(f"load average before: {os.getloadavg()}")
    if not a.skip_overhead:
        batch, plain = overhead(a.small)
        print("per file (wall, batch's own CPU, children's CPU), ms: "
              f"batch {tuple(round(x * 1e3, 1) for x in batch)}, "
              f"CLI loop {tuple(round(x * 1e3, 1) for x in plain)}", flush=True)
    runs = speedups(a.corpus, a.time_limit, a.repeat)
    report_speedups(runs)
    if a.raw:
        with open(a.raw, "w") as f:
            json.dump(runs, f, indent=1)
    print(f"load average after: {os.getloadavg()}")


if __name__ == "__main__":
    main()
