# SPDX-License-Identifier: MIT
"""What a batch tells: a progress line on a terminal while it runs, and at
the end a summary (counts per outcome, watertight count, total triangles,
time) on stdout and as OUT_DIR/summary.json and summary.md."""

import json
import os
import sys
import time

from .job import OK, OUTCOMES


class Progress:
    """"files done/total, failures, rate, ETA" on stderr, redrawn in place; only on a terminal."""

    def __init__(self, total, stream=sys.stderr):
        self.total, self.done, self.failed = total, 0, 0
        self._stream, self._start = stream, time.monotonic()
        self._on = stream.isatty()

    def update(self, outcome):
        self.done += 1
        self.failed += outcome != OK
        if not self._on:
            return
        elapsed = time.monotonic() - self._start
        rate = self.done / elapsed if elapsed > 0 else 0
        eta = (self.total - self.done) / rate if rate > 0 else 0
        width = 30
        filled = width * self.done // max(self.total, 1)
        self._stream.write(
            f"\rbatch [{'#' * filled}{'.' * (width - filled)}] {self.done}/{self.total} files, "
            f"{self.failed} failed, {rate:.1f} files/s, ETA {eta:.0f} s\033[K"
        )
        self._stream.flush()

    def finish(self):
        if self._on:
            self._stream.write("\r\033[K")
            self._stream.flush()


def summarise(entries, seconds, skipped):
    """The summary of the inputs' entries (this run's and those skipped as done)."""
    counts = {o: 0 for o in OUTCOMES}
    triangles, watertight, checked = 0, 0, 0
    for e in entries:
        counts[e["outcome"]] += 1
        triangles += e["figures"].get("triangles", 0)
        if "watertight" in e["figures"]:
            checked += 1
            watertight += e["figures"]["watertight"]
    return {
        "files": len(entries),
        "outcomes": counts,
        "skipped_as_done": skipped,
        "checked": checked,
        "watertight": watertight,
        "triangles": triangles,
        "seconds": round(seconds, 3),
    }


def _rows(summary):
    rows = [(outcome, summary["outcomes"][outcome]) for outcome in OUTCOMES]
    rows += [
        ("files", summary["files"]),
        ("skipped as done", summary["skipped_as_done"]),
        ("watertight (of checked)", f"{summary['watertight']} of {summary['checked']}"),
        ("triangles", summary["triangles"]),
        ("seconds", summary["seconds"]),
    ]
    return rows


def write(summary, out_dir, stream=sys.stdout):
    rows = _rows(summary)
    width = max(len(name) for name, _ in rows)
    for name, value in rows:
        stream.write(f"{name:<{width}}  {value}\n")
    md = "| | |\n|---|---:|\n" + "".join(f"| {name} | {value} |\n" for name, value in rows)
    for name, text in (("summary.json", json.dumps(summary, indent=2) + "\n"), ("summary.md", md)):
        tmp = os.path.join(out_dir, name + ".tmp")
        with open(tmp, "w") as f:
            f.write(text)
        os.replace(tmp, os.path.join(out_dir, name))
