# SPDX-License-Identifier: MIT
"""Figures of docs/results/batch.md: the batch's per-file overhead (many
small files, one worker, against the same CLI calls in a plain loop) and its
speed-up from 1 to 2 local workers on a corpus.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/measure_batch.py [CORPUS] [SMALL_MODEL]
"""

import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

from seamless.batch import default_cli, run_batch

ROOT = pathlib.Path(__file__).resolve().parents[2]


def overhead(model, n=100):
    """Seconds per file: the batch with one worker, and the CLI alone in a loop."""
    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(tmp, "small")
        folder.mkdir()
        for i in range(n):
            shutil.copy(model, folder / f"m{i:04d}.json")
        cli = default_cli()
        start = time.monotonic()
        for i in range(n):
            out = pathlib.Path(tmp, f"plain{i}.glb")
            subprocess.run([cli, "tessellate", folder / f"m{i:04d}.json", "-o", out, "--stats",
                            f"{out}.json", "--threads", "1"], check=True, capture_output=True)
        plain = (time.monotonic() - start) / n
        start = time.monotonic()
        run_batch([folder], pathlib.Path(tmp, "out"), workers=1)
        batch = (time.monotonic() - start) / n
    return batch, plain


def speedup(corpus):
    times = {}
    for workers in (1, 2):
        with tempfile.TemporaryDirectory() as tmp:
            start = time.monotonic()
            summary = run_batch([corpus], tmp, workers=workers, check=True)
            times[workers] = time.monotonic() - start
    return times, summary


def main():
    corpus = sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared/models/cad-corpus")
    small = sys.argv[2] if len(sys.argv) > 2 else str(ROOT / "data/models/bilinear.json")
    print(f"load average before: {os.getloadavg()}")
    batch, plain = overhead(small)
    print(f"per file: batch {batch * 1e3:.1f} ms, CLI loop {plain * 1e3:.1f} ms, "
          f"overhead {(batch - plain) * 1e3:.1f} ms")
    times, summary = speedup(corpus)
    print(f"corpus {corpus}: {summary['files']} files, outcomes {summary['outcomes']}")
    print(f"1 worker {times[1]:.2f} s, 2 workers {times[2]:.2f} s, "
          f"speed-up {times[1] / times[2]:.2f}")
    print(f"load average after: {os.getloadavg()}")


if __name__ == "__main__":
    main()
