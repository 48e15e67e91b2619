# SPDX-License-Identifier: MIT
"""seamless from Python: crack-free tessellation, watertightness checks and
interval ray tracing of B-spline surfaces (docs/python.md).

    import seamless
    mesh = seamless.tessellate("data/models/teapot.json", tolerance=1e-3)
    mesh.vertices        # (n, 3) float64, no copy
    seamless.write_mesh(mesh, "teapot.glb")
    seamless.check(mesh)["passed"]

Every function releases the GIL while the library works; bad input raises
seamless.InputError (a ValueError) with the one line the CLI prints.
"""

from ._seamless import (  # noqa: F401  (the public API)
    InputError,
    Mesh,
    Model,
    check,
    load_model,
    read_mesh,
    render,
    tessellate,
    write_mesh,
)

__all__ = [
    "InputError",
    "Mesh",
    "Model",
    "check",
    "load_model",
    "read_mesh",
    "render",
    "tessellate",
    "write_mesh",
]
