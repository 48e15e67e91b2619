# SPDX-License-Identifier: MIT
"""seamless.check against `seamless check --json`."""

import json

import pytest

import seamless
from helpers import DATA, TEAPOT


@pytest.fixture(scope="module")
def meshes(tmp_path_factory):
    """The teapot (open: no bottom) and the torus (closed), tessellated into OFF files."""
    folder = tmp_path_factory.mktemp("check")
    teapot = folder / "teapot.off"
    seamless.write_mesh(seamless.tessellate(TEAPOT), teapot)
    torus = folder / "torus.off"
    seamless.write_mesh(seamless.tessellate(DATA / "models" / "torus.json"), torus)
    return {"teapot": teapot, "torus": torus}


@pytest.mark.parametrize("name", ["teapot", "torus"])
@pytest.mark.parametrize("flags", [[], ["--closed"], ["--gap", "1e-3"], ["--no-weld"]])
def test_report_equals_cli_json(cli, meshes, name, flags):
    path = meshes[name]
    proc = cli("check", "--json", path, *flags)
    assert proc.returncode in (0, 1), proc.stderr
    expected = json.loads(proc.stdout)
    report = seamless.check(
        str(path),
        closed="--closed" in flags,
        gap=1e-3 if "--gap" in flags else None,
        weld="--no-weld" not in flags,
    )
    assert report == expected
    assert report["passed"] == (proc.returncode == 0)


def test_mesh_object_checks_like_its_file(meshes):
    mesh = seamless.read_mesh(meshes["torus"])
    from_file = seamless.check(meshes["torus"], closed=True)
    assert seamless.check(mesh, closed=True) == from_file
    assert from_file["passed"] and from_file["closed"]
    built = seamless.Mesh(mesh.vertices, mesh.triangles)
    report = seamless.check(built)
    assert report["file"] is None and report["triangles"] == from_file["triangles"]


def test_union_judges_touching_solids_as_one_mesh(cli, tmp_path):
    """as1's 18 solids touch where the file places them: each passes on its own, the union
    does not (`seamless check --union`)."""
    mesh = tmp_path / "as1.ply"
    proc = cli("tessellate", DATA / "models" / "cad" / "occt_as1-oc-214-mat.stp", "-o", mesh)
    assert proc.returncode == 0, proc.stderr
    for union in (False, True):
        flags = ["--closed"] + (["--union"] if union else [])
        proc = cli("check", "--json", mesh, *flags)
        assert proc.returncode in (0, 1), proc.stderr
        report = seamless.check(str(mesh), closed=True, union=union)
        assert report == json.loads(proc.stdout)
        assert report["passed"] == (proc.returncode == 0)
        assert report["passed"] != union
