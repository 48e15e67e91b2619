# SPDX-License-Identifier: MIT
"""The batch's manifest, OUT_DIR/manifest.jsonl: one JSON line per file
processed (input path, size and SHA-256, options, outcome with the reason,
figures, outputs and their SHA-256), appended and flushed to disk as each
file finishes, so an interrupted batch loses at most the files in flight. A
later run reads it to skip what is done; the last line of an input wins."""

import json
import os

NAME = "manifest.jsonl"


def read(out_dir):
    """input path -> its last entry (a torn last line, from a killed run, is ignored)."""
    last = {}
    try:
        with open(os.path.join(out_dir, NAME)) as f:
            for line in f:
                try:
                    entry = json.loads(line)
                except ValueError:
                    continue
                last[entry["input"]] = entry
    except FileNotFoundError:
        pass
    return last


# The options that change the outputs; the limits and thread counts do not
# (a rerun with a longer time limit keeps what is done and retries the rest).
OUTPUT_OPTIONS = ("tolerance", "format", "check")


def is_done(entry, sha256, options):
    """Whether `entry` is an ok result of the same content and output options, its outputs
    still there."""
    return (
        entry is not None
        and entry["outcome"] == "ok"
        and entry["sha256"] == sha256
        and all(entry["options"].get(k) == options[k] for k in OUTPUT_OPTIONS)
        and all(os.path.exists(p) for p in entry["outputs"].values())
    )


class Writer:
    """Appends entries, each flushed and synced before the next file counts as done."""

    def __init__(self, out_dir):
        os.makedirs(out_dir, exist_ok=True)
        self._file = open(os.path.join(out_dir, NAME), "a")

    def append(self, entry):
        self._file.write(json.dumps(entry, sort_keys=True) + "\n")
        self._file.flush()
        os.fsync(self._file.fileno())

    def close(self):
        self._file.close()
