# SPDX-License-Identifier: MIT
"""seamless.render against the PNG `seamless render` writes."""

import numpy as np
import pytest

import seamless
from helpers import TEAPOT_SCENE, read_json
from png_pixels import read_png_rgb

SIZE = (96, 72)


@pytest.mark.parametrize("method", ["intracy", "tray"])
def test_pixels_equal_the_cli_png(cli, tmp_path, method):
    png, stats = tmp_path / "cli.png", tmp_path / "stats.json"
    proc = cli("render", TEAPOT_SCENE, "--size", "x".join(map(str, SIZE)), "--method", method,
               "-o", png, "--stats", stats)
    assert proc.returncode == 0, proc.stderr
    image, st = seamless.render(TEAPOT_SCENE, size=SIZE, method=method)
    assert image.shape == (SIZE[1], SIZE[0], 3) and image.dtype == np.uint8
    assert np.array_equal(image, read_png_rgb(png))
    expected = read_json(stats)
    assert st.keys() == expected.keys()
    assert st["method"] == expected["method"] and st["primary_rays"] == expected["primary_rays"]


def test_threads_give_equal_images():
    one, _ = seamless.render(TEAPOT_SCENE, size=SIZE, threads=1)
    two, _ = seamless.render(TEAPOT_SCENE, size=SIZE, threads=2)
    assert np.array_equal(one, two)


def test_levels_quantise_the_image():
    image, st = seamless.render(TEAPOT_SCENE, size=SIZE, levels=2, dither=False)
    assert st["levels"] == 2 and set(np.unique(image)) <= {0, 255}
