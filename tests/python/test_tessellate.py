# SPDX-License-Identifier: MIT
"""seamless.tessellate and write_mesh against `seamless tessellate`."""

import numpy as np
import pytest

import seamless
from helpers import DATA, TEAPOT, read_json

FORMATS = [".off", ".obj", ".ply", ".stl", ".gltf", ".glb"]


# The teapot, and an IGES file (read through the OpenCASCADE module libseamless loads).
@pytest.mark.parametrize("model", [TEAPOT, DATA / "models" / "cad" / "rounded_cube.iges"])
def test_off_byte_identical_to_cli(cli, tmp_path, model):
    by_cli, by_module = tmp_path / "cli.off", tmp_path / "module.off"
    assert cli("tessellate", model, "-o", by_cli).returncode == 0
    seamless.write_mesh(seamless.tessellate(model), by_module)
    assert by_module.read_bytes() == by_cli.read_bytes()


@pytest.mark.parametrize("ext", FORMATS)
def test_every_format_byte_identical_to_cli(cli, tmp_path, ext):
    model = DATA / "models" / "sphere.json"
    by_cli, by_module = tmp_path / f"cli{ext}", tmp_path / f"module{ext}"
    assert cli("tessellate", model, "--tolerance", "1e-2", "-o", by_cli).returncode == 0
    seamless.write_mesh(seamless.tessellate(str(model), tolerance=1e-2), by_module)
    assert by_module.read_bytes() == by_cli.read_bytes()


def test_arrays_are_views_of_the_mesh():
    mesh = seamless.tessellate(TEAPOT)
    v, t, n, s = mesh.vertices, mesh.triangles, mesh.normals, mesh.surface_id
    assert v.dtype == np.float64 and v.ndim == 2 and v.shape[1] == 3
    assert t.dtype == np.uint32 and t.shape == (len(s), 3) and n.shape == (len(s), 3, 3)
    assert t.max() < len(v) and s.max() < len(mesh.surface_names)
    # No copy: each access views the same storage, which the mesh owns.
    assert np.shares_memory(v, mesh.vertices) and v.base is not None
    assert not v.flags.writeable and not t.flags.writeable
    del mesh  # the views keep it alive
    assert np.isfinite(v).all() and np.allclose(np.linalg.norm(n, axis=2), 1)


def test_stats_have_the_cli_fields(cli, tmp_path):
    assert cli("tessellate", TEAPOT, "--tolerance", "1e-2", "--angle", "20", "-o",
               tmp_path / "x.off", "--stats", tmp_path / "s.json").returncode == 0
    expected = read_json(tmp_path / "s.json")
    stats = seamless.tessellate(TEAPOT, tolerance=1e-2, angle=20).stats
    assert stats.keys() == expected.keys()
    timing = {"seconds", "phase_seconds", "output", "model"}
    for key in expected.keys() - timing:
        assert stats[key] == expected[key], key
    assert stats["certified_bound"] <= 1e-2 and stats["model"] == str(TEAPOT)


def test_model_object_and_path_give_the_same_mesh():
    model = seamless.load_model(TEAPOT)
    assert model.surfaces == 32 and model.patches == 32 and model.brep is None
    lo, hi = model.bbox
    assert model.d_max == max(h - l for l, h in zip(lo, hi))
    a, b = seamless.tessellate(model), seamless.tessellate(TEAPOT)
    assert np.array_equal(a.vertices, b.vertices) and np.array_equal(a.triangles, b.triangles)


def test_threads_give_equal_arrays():
    one = seamless.tessellate(TEAPOT, tolerance=3e-3, threads=1)
    two = seamless.tessellate(TEAPOT, tolerance=3e-3, threads=2)
    for name in ("vertices", "triangles", "normals", "surface_id"):
        assert np.array_equal(getattr(one, name), getattr(two, name)), name


def test_progress_reports_fractions():
    seen = []
    seamless.tessellate(TEAPOT, tolerance=3e-3, threads=2, progress=seen.append)
    assert seen and all(0 <= f <= 1 for f in seen)


def test_progress_exception_is_raised_after_the_work():
    def fail(fraction):
        raise KeyError("stop")

    with pytest.raises(KeyError, match="stop"):
        seamless.tessellate(TEAPOT, threads=2, progress=fail)


def test_read_mesh_round_trip(tmp_path):
    mesh = seamless.tessellate(TEAPOT)
    for ext in FORMATS:
        seamless.write_mesh(mesh, tmp_path / f"m{ext}")
        back = seamless.read_mesh(tmp_path / f"m{ext}")
        assert len(back.triangles) == len(mesh.triangles), ext
    back = seamless.read_mesh(tmp_path / "m.off")
    assert np.array_equal(back.vertices, mesh.vertices)  # OFF keeps every bit
    assert np.array_equal(back.triangles, mesh.triangles)


def test_mesh_from_arrays_writes_like_the_library(tmp_path):
    mesh = seamless.tessellate(TEAPOT)
    copy = seamless.Mesh(mesh.vertices, mesh.triangles, surface_id=mesh.surface_id)
    seamless.write_mesh(mesh, tmp_path / "a.off")
    seamless.write_mesh(copy, tmp_path / "b.off")
    assert (tmp_path / "a.off").read_bytes() == (tmp_path / "b.off").read_bytes()


def test_face_id_of_a_brep_model():
    model = seamless.load_model(DATA / "models" / "cad" / "b123d_M6-1x12-countersunk-screw.step")
    mesh = seamless.tessellate(model, tolerance=model.d_max * 1e-3)
    ids = mesh.face_id
    assert ids.dtype == np.int32 and ids.shape == (len(mesh.triangles),)
    assert not ids.flags.writeable and np.shares_memory(ids, mesh.face_id)
    # A STEP file's faces each have a surface of their own: every face id
    # known, and as many faces as surfaces meshed, one for one.
    assert ids.min() >= 0 and ids.max() < model.brep["faces"]
    pairs = set(zip(ids.tolist(), mesh.surface_id.tolist()))
    assert len(pairs) == len(set(ids.tolist())) == len(set(mesh.surface_id.tolist()))
    # Without a B-rep the faces are not known.
    assert seamless.tessellate(TEAPOT).face_id is None


def test_keywords_take_numpy_scalars():
    a = seamless.tessellate(TEAPOT, tolerance=np.float64(1e-2), threads=np.int64(1))
    b = seamless.tessellate(TEAPOT, tolerance=1e-2, threads=1)
    assert np.array_equal(a.vertices, b.vertices)
