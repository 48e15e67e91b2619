# SPDX-License-Identifier: MIT
"""STEP and IGES behind the process boundary: a file on which OpenCASCADE
crashes raises seamless.InputError with the CLI's line, the interpreter goes
on, and OpenCASCADE's libraries are never mapped into it."""

import pathlib

import pytest

import seamless
from helpers import DATA, ROOT, cli_error_line

# ../shared/reproducers, and the crashers the fuzzer has found since, kept as
# fuzz_step_iges's seeds (tests/model/step_iges_reproducers.h): each name once.
_SEEDS = ROOT / "tests" / "fuzz" / "corpus" / "step_iges"
_BY_NAME = {
    p.name: p
    for p in list(_SEEDS.glob("occ-*-segv.*")) + list((ROOT.parent / "shared" / "reproducers").iterdir())
    if p.suffix in (".step", ".stp", ".igs", ".iges")
}
REPRODUCERS = [_BY_NAME[name] for name in sorted(_BY_NAME)]


def maps_opencascade():
    return "libTK" in pathlib.Path("/proc/self/maps").read_text()


def test_there_are_reproducers():
    assert len(REPRODUCERS) >= 7


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
