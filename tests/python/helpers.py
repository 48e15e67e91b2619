# SPDX-License-Identifier: MIT
"""Paths and helpers the tests share (conftest.py holds the fixtures)."""

import json
import os
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = ROOT / "data"
TEAPOT = DATA / "models" / "teapot.json"
TEAPOT_SCENE = DATA / "scenes" / "teapot.json"


def cli_path():
    """The seamless program: $SEAMLESS_CLI (ctest sets it) or build/bin/seamless."""
    exe = os.environ.get("SEAMLESS_CLI", str(ROOT / "build" / "bin" / "seamless"))
    assert os.access(exe, os.X_OK), f"the seamless CLI is not built: {exe}"
    return exe


def cli_error_line(proc):
    """The one line the CLI prints for bad input (exit 2), without "error: "."""
    assert proc.returncode == 2, proc.stderr
    line = proc.stderr.strip().splitlines()[-1]
    assert line.startswith("error: ")
    return line[len("error: ") :]


def read_json(path):
    with open(path) as f:
        return json.load(f)
