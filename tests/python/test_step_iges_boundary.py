# SPDX-License-Identifier: MIT
"""STEP and IGES behind the process boundary: a file on which OpenCASCADE
crashes raises seamless.InputError with the CLI's line, the interpreter goes
on, and OpenCASCADE's libraries are never mapped into it."""

import pathlib

import pytest

import seamless
from helpers import DATA, ROOT, cli_error_line

REPRODUCERS = sorted(
    p
    for p in (ROOT.parent / "shared" / "reproducers").iterdir()
    if p.suffix in (".step", ".stp", ".igs", ".iges")
)


def maps_opencascade():
    return "libTK" in pathlib.Path("/proc/self/maps").read_text()


def test_there_are_reproducers():
    assert len(REPRODUCERS) >= 6


@pytest.mark.parametrize("path", REPRODUCERS, ids=lambda p: p.name)
def test_reproducer_raises_the_cli_line(cli, path):
    expected = cli_error_line(cli("info", path))
    assert "OpenCASCADE crashed reading it (signal" in expected
    with pytest.raises(seamless.InputError) as info:
        seamless.load_model(str(path))
    assert str(info.value) == expected and info.value.file == str(path)


def test_good_file_after_a_crash_without_mapping_opencascade():
    with pytest.raises(seamless.InputError):
        seamless.load_model(str(REPRODUCERS[0]))
    model = seamless.load_model(str(DATA / "models" / "cad" / "torus.igs"))
    assert model is not None
    assert not maps_opencascade()
