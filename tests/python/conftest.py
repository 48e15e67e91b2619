# SPDX-License-Identifier: MIT
"""Fixtures: the CLI the module's results are compared with.

ctest sets PYTHONPATH (build/python) and SEAMLESS_CLI; by hand:
    PYTHONPATH=build/python /usr/bin/python3 -m pytest tests/python
"""

import subprocess
import sys

import pytest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree

from helpers import cli_path


@pytest.fixture(scope="session")
def cli():
    """Runs `seamless ARGS...` and returns the CompletedProcess (text; exit status unchecked)."""
    exe = cli_path()

    def run(*args):
        return subprocess.run([exe, *map(str, args)], capture_output=True, text=True)

    return run
