# SPDX-License-Identifier: MIT
"""seamless batch: tessellate (and check) many model files, each in its own
process with a time and a memory limit, into OUT_DIR mirroring the input
tree, with a manifest that makes a rerun skip what is done; on this machine
or on a Dask cluster (docs/batch.md).

    python3 -m seamless.batch INPUTS... -o OUT_DIR [--check] [--workers N]
    seamless.batch.run_batch(["models/"], "out", check=True)
"""

import os
import pathlib
import shutil
import time

from . import engines, inputs, job, manifest, report

__all__ = ["run_batch", "default_cli", "OUTCOMES"]
OUTCOMES = job.OUTCOMES
FORMATS = ("glb", "gltf", "off", "obj", "ply", "stl")


def default_cli():
    """The seamless program: $SEAMLESS_CLI, the build's bin/ beside this package, or PATH's."""
    if os.environ.get("SEAMLESS_CLI"):
        return os.environ["SEAMLESS_CLI"]
    built = pathlib.Path(__file__).resolve().parents[2].parent / "bin" / "seamless"
    if built.is_file():
        return str(built)
    return shutil.which("seamless") or "seamless"


def run_batch(
    paths,
    out_dir,
    *,
    tolerance=None,
    format="glb",
    check=False,
    workers=None,
    scheduler=None,
    time_limit=600,
    memory_limit_mb=4096,
    threads=1,
    cli=None,
):
    """Runs the batch; returns its summary (report.summarise). `scheduler` is a
    Dask scheduler address or a distributed.Client; without it `workers`
    jobs run at once here (default: every core)."""
    if format not in FORMATS:
        raise inputs.BatchInputError(f"--format: expected one of {', '.join(FORMATS)}")
    start = time.monotonic()
    out_dir = os.path.abspath(out_dir)
    items = inputs.collect(paths)
    # Recorded with every file (manifest.OUTPUT_OPTIONS of them decide what a rerun skips).
    options = {"tolerance": tolerance, "format": format, "check": bool(check), "threads": threads,
               "time_limit": time_limit, "memory_limit_mb": memory_limit_mb}
    previous = manifest.read(out_dir)
    entries, tasks, pending = {}, [], []
    for item in items:
        size, sha = os.path.getsize(item.path), inputs.file_hash(item.path)
        if manifest.is_done(previous.get(item.path), sha, options):
            entries[item.path] = previous[item.path]
            continue
        outputs = job.outputs_of(out_dir, item.relative, format, check)
        tasks.append((item.path, outputs))
        pending.append({"input": item.path, "size": size, "sha256": sha, "options": options})
    # Largest first (size as the cost's proxy): no big file starts last while the other
    # workers idle (longest-processing-time-first scheduling).
    order = sorted(range(len(tasks)), key=lambda i: -pending[i]["size"])
    tasks, pending = [tasks[i] for i in order], [pending[i] for i in order]
    run_options = dict(options, cli=cli or default_cli())
    bar = report.Progress(len(tasks))
    writer = manifest.Writer(out_dir)
    try:
        for i, result in _engine(tasks, run_options, workers, scheduler):
            entry = dict(pending[i], **result)
            writer.append(entry)
            entries[entry["input"]] = entry
            bar.update(entry["outcome"])
    finally:
        writer.close()
        bar.finish()
    ordered = [entries[item.path] for item in items]
    return report.summarise(ordered, time.monotonic() - start, len(items) - len(tasks))


def _engine(tasks, options, workers, scheduler):
    if scheduler is None:
        return engines.local(tasks, options, workers or os.cpu_count() or 1)
    if isinstance(scheduler, str):
        return _with_client(tasks, options, scheduler)
    return engines.dask(tasks, options, scheduler)


def _with_client(tasks, options, address):
    from distributed import Client

    with Client(address) as client:
        yield from engines.dask(tasks, options, client)
