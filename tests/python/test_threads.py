# SPDX-License-Identifier: MIT
"""The GIL is released while the library works: other Python threads run,
and calls from two threads at once both succeed with the sequential results."""

import threading
import time

import numpy as np

import seamless
from helpers import TEAPOT, TEAPOT_SCENE

TOLERANCE = 3e-3  # about 0.1 s of work on one thread


def in_thread(call, *args, **kwargs):
    """Starts call(*args, **kwargs) in a thread; returns (thread, result box)."""
    box = {}

    def run():
        try:
            box["value"] = call(*args, **kwargs)
        except BaseException as e:  # handed to the test
            box["error"] = e

    thread = threading.Thread(target=run)
    thread.start()
    return thread, box


def result(thread, box):
    thread.join()
    if "error" in box:
        raise box["error"]
    return box["value"]


def test_python_runs_while_tessellating():
    thread, box = in_thread(seamless.tessellate, TEAPOT, tolerance=TOLERANCE, threads=1)
    ticks = 0
    while thread.is_alive():  # held GIL: no tick until the call returns
        ticks += 1
        time.sleep(0.001)
    assert len(result(thread, box).triangles) > 0
    assert ticks >= 5


def test_concurrent_calls_equal_sequential_ones(tmp_path):
    expected = seamless.tessellate(TEAPOT, tolerance=TOLERANCE)
    expected_image, _ = seamless.render(TEAPOT_SCENE, size=(64, 48))
    off = tmp_path / "t.off"
    seamless.write_mesh(expected, off)
    expected_report = seamless.check(off)

    first = in_thread(seamless.tessellate, TEAPOT, tolerance=TOLERANCE, threads=2)
    second = in_thread(seamless.tessellate, TEAPOT, tolerance=TOLERANCE, threads=2)
    image = in_thread(seamless.render, TEAPOT_SCENE, size=(64, 48))
    report = seamless.check(off)  # on this thread meanwhile
    for mesh in (result(*first), result(*second)):
        assert np.array_equal(mesh.vertices, expected.vertices)
        assert np.array_equal(mesh.triangles, expected.triangles)
    assert np.array_equal(result(*image)[0], expected_image)
    assert report == expected_report


def test_progress_from_worker_threads_while_another_call_runs():
    calls = []
    first = in_thread(seamless.tessellate, TEAPOT, tolerance=TOLERANCE, progress=calls.append)
    mesh = seamless.tessellate(TEAPOT, tolerance=TOLERANCE, progress=calls.append)
    assert np.array_equal(result(*first).triangles, mesh.triangles)
    assert calls and max(calls) <= 1
