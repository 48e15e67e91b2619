# SPDX-License-Identifier: MIT
"""Bad input raises seamless.InputError (a ValueError) with the CLI's line."""

import numpy as np
import pytest

import seamless
from helpers import TEAPOT, TEAPOT_SCENE, cli_error_line


def raised(call, *args, **kwargs):
    with pytest.raises(seamless.InputError) as info:
        call(*args, **kwargs)
    assert isinstance(info.value, ValueError)
    return info.value


def test_missing_model_message_equals_cli(cli, tmp_path):
    missing = tmp_path / "missing.json"
    expected = cli_error_line(cli("tessellate", missing, "-o", tmp_path / "x.off"))
    error = raised(seamless.tessellate, missing)
    assert str(error) == expected and error.file == str(missing)
    assert str(raised(seamless.load_model, str(missing))) == expected


@pytest.mark.parametrize(
    "text",
    ['{"version": 1, "surfaces": [{"degree": [3, 3]}]}', "{", '{"version": 7}', "\x00\xff"],
)
def test_malformed_model_message_equals_cli(cli, tmp_path, text):
    model = tmp_path / "bad.json"
    model.write_text(text, errors="surrogateescape")
    expected = cli_error_line(cli("tessellate", model, "-o", tmp_path / "x.off"))
    assert str(raised(seamless.tessellate, model)) == expected


@pytest.mark.parametrize("text", ["OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "OFF\n", "nonsense"])
def test_malformed_mesh_message_equals_cli(cli, tmp_path, text):
    mesh = tmp_path / "bad.off"
    mesh.write_text(text)
    expected = cli_error_line(cli("check", mesh))
    assert str(raised(seamless.read_mesh, mesh)) == expected
    assert str(raised(seamless.check, mesh)) == expected


def test_missing_scene_message_equals_cli(cli, tmp_path):
    scene = tmp_path / "none.json"
    expected = cli_error_line(cli("render", scene, "-o", tmp_path / "x.png"))
    assert str(raised(seamless.render, scene)) == expected


def test_unknown_mesh_extension_message_equals_cli(cli, tmp_path):
    out = tmp_path / "x.xyz"
    expected = cli_error_line(cli("tessellate", TEAPOT, "-o", out))
    assert str(raised(seamless.write_mesh, seamless.tessellate(TEAPOT), out)) == expected
    assert not out.exists()


@pytest.mark.parametrize(
    "call, kwargs, field",
    [
        (seamless.tessellate, {"tolerance": -1}, "tolerance"),
        (seamless.tessellate, {"tolerance": float("nan")}, "tolerance"),
        (seamless.tessellate, {"angle": 200}, "angle"),
        (seamless.tessellate, {"threads": -1}, "threads"),
        (seamless.tessellate, {"max_triangles": 0}, "max_triangles"),
        (seamless.tessellate, {"trimmed": "sometimes"}, "trimmed"),
        (seamless.check, {"gap": 0}, "gap"),
        (seamless.render, {"size": (0, 10)}, "size"),
        (seamless.render, {"levels": 1}, "levels"),
        (seamless.render, {"method": "raster"}, "method"),
    ],
)
def test_bad_keywords_name_their_field(call, kwargs, field, tmp_path):
    target = {seamless.tessellate: TEAPOT, seamless.render: TEAPOT_SCENE}.get(call)
    if target is None:  # check
        target = tmp_path / "t.off"
        seamless.write_mesh(seamless.tessellate(TEAPOT), target)
    error = raised(call, target, **kwargs)
    assert error.field == field and field in str(error)


def test_triangle_budget_is_refused():
    error = raised(seamless.tessellate, TEAPOT, tolerance=1e-4, max_triangles=1000)
    assert "max_triangles" in str(error)


def test_mesh_arrays_are_checked():
    v = np.zeros((3, 3))
    raised(seamless.Mesh, v, np.array([[0, 1, 3]]))
    raised(seamless.Mesh, v, np.array([[0, 1, -1]]))
    raised(seamless.Mesh, np.zeros((3, 2)), np.array([[0, 1, 2]]))
    raised(seamless.Mesh, np.full((3, 3), np.inf), np.array([[0, 1, 2]]))
    raised(seamless.Mesh, v, np.array([[0, 1, 2]]), surface_id=[0, 1])


def test_wrong_types_are_type_errors():
    with pytest.raises(TypeError):
        seamless.tessellate(42)
    with pytest.raises(TypeError):
        seamless.check(3.5)
    with pytest.raises(TypeError):
        seamless.tessellate(TEAPOT, tolerance="fine")
    with pytest.raises(TypeError, match="threads"):
        seamless.tessellate(TEAPOT, threads=1.5)
    with pytest.raises(TypeError, match="unexpected keyword argument 'tolerence'"):
        seamless.tessellate(TEAPOT, tolerence=1e-3)
    with pytest.raises(TypeError):  # keywords only after the model
        seamless.tessellate(TEAPOT, 1e-3)
