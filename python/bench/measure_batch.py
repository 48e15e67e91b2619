# SPDX-License-Identifier: MIT
"""Figures of docs/results/batch.md: the batch's per-file overhead (many
small files, one worker, against the same CLI calls in a plain loop; wall
and CPU seconds) and its speed-up from 1 to 2 local workers on a corpus,
with the speed-up an idle machine allows (the 1-worker run's per-file times
scheduled largest first on 2 workers).

    PYTHONPATH=build/python /usr/bin/python3 python/bench/measure_batch.py [CORPUS] [SMALL_MODEL]
"""

import heapq
import json
import os
import pathlib
import resource
import shutil
import subprocess
import sys
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


def lpt_makespan(seconds, workers):
    """Finish time of the jobs given largest first to whichever worker is free."""
    loads = [0.0] * workers
    for s in sorted(seconds, reverse=True):
        heapq.heappush(loads, heapq.heappop(loads) + s)
    return max(loads)


def speedup(corpus):
    times, per_file = {}, []
    for workers in (1, 2):
        with tempfile.TemporaryDirectory() as tmp:
            start = time.monotonic()
            summary = run_batch([corpus], tmp, workers=workers, check=True)
            times[workers] = time.monotonic() - start
            if workers == 1:
                with open(os.path.join(tmp, "manifest.jsonl")) as f:
                    per_file = [json.loads(line)["seconds"] for line in f]
    return times, per_file, summary


def main():
    corpus = sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared/models/cad-corpus")
    small = sys.argv[2] if len(sys.argv) > 2 else str(ROOT / "data/models/bilinear.json")
    print(f"load average before: {os.getloadavg()}")
    batch, plain = overhead(small)
    print("per file (wall, batch's own CPU, children's CPU), ms: "
          f"batch {tuple(round(x * 1e3, 1) for x in batch)}, "
          f"CLI loop {tuple(round(x * 1e3, 1) for x in plain)}")
    times, per_file, summary = speedup(corpus)
    print(f"corpus {corpus}: {summary['files']} files, outcomes {summary['outcomes']}")
    total, longest = sum(per_file), max(per_file)
    print(f"1 worker {times[1]:.2f} s (files {total:.2f} s, longest {longest:.2f} s), "
          f"2 workers {times[2]:.2f} s: speed-up {times[1] / times[2]:.2f}; "
          f"idle-machine bound {total / lpt_makespan(per_file, 2):.2f}")
    print(f"load average after: {os.getloadavg()}")


if __name__ == "__main__":
    main()
