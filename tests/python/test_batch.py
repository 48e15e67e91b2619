# SPDX-License-Identifier: MIT
"""seamless batch: outcomes contained and recorded, reruns skip what is done,
and the same batch on a 2-worker Dask LocalCluster with a worker killed
mid-task gives every file one outcome and the same outputs."""

import json
import os
import shutil
import signal
import subprocess
import threading
import time

import distributed
import pytest

from helpers import DATA, cli_path
from seamless.batch import run_batch

# Input name -> the bundled model it copies; hang, crash and slow are for the test double.
GOOD = {"sphere.json": "sphere.json", "bilinear.json": "bilinear.json",
        "sub/torus.json": "torus.json"}
DOUBLED = {"hang.json": "sphere.json", "crash.json": "sphere.json", "slow.json": "teapot.json"}


def fake_cli(folder):
    """A test double of the seamless program: a model named hang.* sleeps past
    any time limit, crash.* dies by SIGSEGV, slow.* sleeps 1 s first; every
    other call runs the real program."""
    script = folder / "sleeping_crashing_seamless"
    script.write_text(
        "#!/bin/sh\n"
        'for a in "$@"; do case "$(basename "$a")" in\n'
        "  hang.*) exec sleep 60 ;;\n"
        "  crash.*) kill -SEGV $$ ;;\n"
        "  slow.*) sleep 1 ;;\n"
        "esac; done\n"
        f'exec "{cli_path()}" "$@"\n'
    )
    script.chmod(0o755)
    return str(script)


def make_inputs(folder, doubled=()):
    """folder/models: the good models, the named test-double inputs and one refused file."""
    models = folder / "models"
    for name, source in list(GOOD.items()) + [(n, DOUBLED[n]) for n in doubled]:
        (models / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(DATA / "models" / source, models / name)
    (models / "refused.json").write_text('{"version": 1, "surfaces": []}')
    return models


def manifest_lines(out):
    with open(out / "manifest.jsonl") as f:
        return [json.loads(line) for line in f]


def test_outcomes_are_contained_and_a_rerun_skips_the_good(tmp_path):
    models, double = make_inputs(tmp_path, ["hang.json", "crash.json"]), fake_cli(tmp_path)
    out = tmp_path / "out"
    summary = run_batch([models], out, check=True, workers=2, time_limit=1.5, cli=double)
    by_name = {os.path.relpath(e["input"], models): e for e in manifest_lines(out)}
    assert summary["outcomes"] == {"ok": 3, "refused": 1, "crashed": 1, "timed out": 1,
                                   "out of memory": 0}
    assert by_name["hang.json"]["outcome"] == "timed out"
    assert by_name["crash.json"]["outcome"] == "crashed"
    assert "SIGSEGV" in by_name["crash.json"]["reason"]
    assert by_name["refused.json"]["outcome"] == "refused"
    assert by_name["refused.json"]["reason"] == f"{models}/refused.json: surfaces: expected at least one surface"
    for name in GOOD:
        entry = by_name[name]
        assert entry["outcome"] == "ok" and entry["figures"]["triangles"] > 0
        assert entry["cpu_seconds"] > 0  # the file's processes' own, from os.wait4
        assert (out / "models" / f"{name}.glb").is_file()  # the input tree, mirrored
        assert json.loads((out / "models" / f"{name}.check.json").read_text())["passed"]
    assert not list(out.rglob("hang*")) and not list(out.rglob("crash*"))
    assert summary["watertight"] == 2  # sphere and torus; the bilinear patch is open

    again = run_batch([models], out, check=True, workers=2, time_limit=1.5, cli=double)
    assert again["skipped_as_done"] == 3 and again["outcomes"] == summary["outcomes"]
    assert len(manifest_lines(out)) == 6 + 3  # only the failures were retried


def test_command_line_writes_the_summary(tmp_path):
    models = make_inputs(tmp_path)
    out = tmp_path / "out"
    # `seamless batch` runs `python3 -m seamless.batch` (tools/batch.cpp).
    proc = subprocess.run([cli_path(), "batch", str(models), "-o", str(out), "--format", "off",
                           "--workers", "2"], capture_output=True, text=True)
    assert proc.returncode == 1, proc.stderr  # one file refused
    summary = json.loads((out / "summary.json").read_text())
    assert summary["files"] == 4 and summary["outcomes"]["ok"] == 3
    assert "refused" in proc.stdout and (out / "summary.md").is_file()
    assert (out / "models" / "sub" / "torus.json.off").is_file()


@pytest.mark.filterwarnings("ignore::DeprecationWarning")  # tornado, inside distributed
def test_dask_cluster_with_a_worker_killed_mid_task(tmp_path):
    models, double = make_inputs(tmp_path, ["slow.json"]), fake_cli(tmp_path)
    here = run_batch([models], tmp_path / "here", workers=2, cli=double)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        result = {}
        batch = threading.Thread(target=lambda: result.update(
            run_batch([models], tmp_path / "dask", scheduler=client, cli=double)))
        batch.start()
        killed = kill_worker_holding_a_task(client)
        batch.join()
    assert killed
    assert result["files"] == 5 and result["outcomes"]["ok"] == 4
    lines = manifest_lines(tmp_path / "dask")
    assert sorted(e["input"] for e in lines) == sorted(e["input"] for e in
                                                       manifest_lines(tmp_path / "here"))
    same = {e["input"]: e["output_sha256"].get("mesh") for e in manifest_lines(tmp_path / "here")}
    assert {e["input"]: e["output_sha256"].get("mesh") for e in lines} == same


def kill_worker_holding_a_task(client, timeout=20):
    """SIGKILLs the process of a worker while it runs a task; whether it did."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        busy = [w for w, keys in client.processing().items() if keys]
        if busy:
            pid = client.run(os.getpid, workers=[busy[0]])[busy[0]]
            os.kill(pid, signal.SIGKILL)
            return True
        time.sleep(0.05)
    return False


def test_interrupted_batch_loses_only_the_files_in_flight(tmp_path):
    models, double = make_inputs(tmp_path, ["hang.json"]), fake_cli(tmp_path)
    out = tmp_path / "out"
    command = [cli_path(), "batch", str(models), "-o", str(out), "--workers", "2", "--cli", double]
    proc = subprocess.Popen(command, stderr=subprocess.PIPE, text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline and not (
            (out / "manifest.jsonl").exists() and len(manifest_lines(out)) == 4):
        time.sleep(0.05)  # all but hang.json, which sleeps
    proc.send_signal(signal.SIGINT)  # Ctrl-C
    _, err = proc.communicate(timeout=10)
    assert proc.returncode == 130 and "interrupted" in err
    assert len(manifest_lines(out)) == 4  # hang.json, in flight, is not recorded
    again = run_batch([models], out, workers=2, time_limit=1, cli=double)
    assert again["skipped_as_done"] == 3 and again["outcomes"]["timed out"] == 1


def test_the_step_iges_reader_gets_the_files_limits(tmp_path):
    # A test double that records its arguments, then runs the real program.
    log = tmp_path / "calls.txt"
    script = tmp_path / "recording_seamless"
    script.write_text(f'#!/bin/sh\necho "$@" >>"{log}"\nexec "{cli_path()}" "$@"\n')
    script.chmod(0o755)
    models = tmp_path / "models"
    models.mkdir()
    shutil.copy(DATA / "models" / "cad" / "torus.igs", models / "torus.igs")
    summary = run_batch([models], tmp_path / "out", workers=1, time_limit=42, memory_limit_mb=3000,
                        cli=str(script))
    assert summary["outcomes"]["ok"] == 1  # the real program took the reader's limits
    (call,) = [line.split() for line in log.read_text().splitlines() if "tessellate" in line]
    assert call[call.index("--reader-time-limit") + 1] == "42.0"
    assert call[call.index("--reader-memory-limit") + 1] == "3000M"
