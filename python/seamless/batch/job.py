# SPDX-License-Identifier: MIT
"""One input file, in processes of its own: `seamless tessellate` (and
`seamless check --json` with --check) under a time limit and a memory limit.
A crash, a hang or a memory blow-up becomes the file's outcome; the CLI
writes its outputs atomically (temporary file and rename), so a file is
never half-written. Runs on the batch's machine or on a Dask worker."""

import ctypes
import json
import os
import resource
import signal
import socket
import subprocess
import threading
import time

from .inputs import file_hash

OK, REFUSED, CRASHED, TIMED_OUT, OUT_OF_MEMORY = (
    "ok",
    "refused",
    "crashed",
    "timed out",
    "out of memory",
)
OUTCOMES = (OK, REFUSED, CRASHED, TIMED_OUT, OUT_OF_MEMORY)

_PR_SET_PDEATHSIG = 1
_prctl = ctypes.CDLL(None, use_errno=True).prctl  # resolved here, not in the forked child


def _limits(memory_bytes):
    """preexec_fn: the child's address space limit, and its death with its parent.
    Two system calls and nothing else between fork and exec (the batch forks
    from several threads); util-linux's prlimit and setpriv as wrappers did the
    same at two more process starts (+30 ms a file on a loaded machine)."""

    def apply():
        resource.setrlimit(resource.RLIMIT_AS, (memory_bytes, memory_bytes))
        # A killed worker takes its child along (Dask reruns the task elsewhere).
        _prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)

    return apply


class _Process(subprocess.Popen):
    """Popen that keeps the child's CPU seconds (user + system, os.wait4) when
    it reaps it: what a file costs, whatever the machine's load (None if
    another path reaped it). Popen reaps through _try_wait (CPython 3.8 to
    3.13); os.wait4 is its waitpid with the rusage."""

    cpu_seconds = None

    def _try_wait(self, wait_flags):
        try:
            pid, status, usage = os.wait4(self.pid, wait_flags)
        except ChildProcessError:  # reaped elsewhere (SIGCHLD ignored): status unknown
            return self.pid, 0
        if pid == self.pid:
            self.cpu_seconds = usage.ru_utime + usage.ru_stime
        return pid, status


# The CLI processes running in this process's jobs, for stop_all().
_running = set()
_running_lock = threading.Lock()
_stopped = threading.Event()


def stop_all():
    """Kills every job's running process (the batch was interrupted: what is in
    flight is not recorded, and is redone by the next run)."""
    with _running_lock:
        _stopped.set()
        for proc in _running:
            proc.kill()


def _run(command, time_limit, memory_bytes, cpu):
    """(outcome, reason, stdout) of one CLI process; its CPU seconds added to cpu[0]."""
    with _running_lock:
        if _stopped.is_set():
            return CRASHED, "interrupted", ""
        proc = _Process(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                text=True, errors="replace", preexec_fn=_limits(memory_bytes))
        _running.add(proc)
    try:
        stdout, stderr = proc.communicate(timeout=time_limit)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        return TIMED_OUT, f"killed after the time limit of {time_limit:g} s", ""
    finally:
        with _running_lock:
            _running.discard(proc)
        if proc.cpu_seconds is not None and cpu[0] is not None:
            cpu[0] += proc.cpu_seconds
        else:
            cpu[0] = None
    lines = stderr.strip().splitlines()
    last = lines[-1] if lines else ""
    if last.startswith("error: "):
        last = last[len("error: ") :]
    if proc.returncode in (0, 1):  # check: 1 = defects found, a result
        return OK, "", stdout
    if proc.returncode == 2:
        return (OUT_OF_MEMORY if last == "out of memory" else REFUSED), last, ""
    if proc.returncode == -signal.SIGKILL:  # the kernel's OOM killer, the usual sender
        return OUT_OF_MEMORY, "killed (SIGKILL)", ""
    if proc.returncode < 0:
        return CRASHED, f"killed by {signal.Signals(-proc.returncode).name}" + (
            f": {last}" if last else ""
        ), ""
    return CRASHED, f"exit status {proc.returncode}" + (f": {last}" if last else ""), ""


def _parse_json(text):
    try:
        return json.loads(text)
    except ValueError:
        return None


def _read_json(path):
    try:
        with open(path) as f:
            return _parse_json(f.read())
    except OSError:
        return None


def _write_atomically(path, text):
    tmp = f"{path}.{os.getpid()}.tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def outputs_of(out_dir, relative, fmt, check):
    """The output paths of one input: mesh, stats and (with check) the check report."""
    base = os.path.join(out_dir, relative)
    paths = {"mesh": f"{base}.{fmt}", "stats": f"{base}.stats.json"}
    if check:
        paths["check"] = f"{base}.check.json"
    return paths


def _check(cli, mesh, report_path, time_limit, memory, cpu):
    """(outcome, reason, figures) of `seamless check --json MESH`, its report written."""
    outcome, reason, text = _run([cli, "check", "--json", mesh], time_limit, memory, cpu)
    report = _parse_json(text) if outcome == OK else None
    if outcome != OK:
        return outcome, reason, {}
    if report is None:
        return CRASHED, "check --json printed no JSON report", {}
    _write_atomically(report_path, text)  # the CLI's own bytes
    closed = report.get("closed", False)
    return OK, "", {"passed": report["passed"], "closed": closed,
                    "watertight": report["passed"] and closed}


def _tessellate_and_check(input_path, outputs, options):
    start = time.monotonic()
    cli, limit = options["cli"], options["time_limit"]
    memory = int(options["memory_limit_mb"]) << 20
    os.makedirs(os.path.dirname(outputs["mesh"]), exist_ok=True)
    command = [cli, "tessellate", input_path, "-o", outputs["mesh"], "--stats", outputs["stats"]]
    command += ["--threads", str(options["threads"])]
    # The STEP/IGES reader's own limits (600 s, 4 GiB by default) follow the file's, so a
    # longer --time-limit or a larger --memory-limit reaches OpenCASCADE's read too.
    command += ["--reader-time-limit", repr(float(limit)),
                "--reader-memory-limit", f"{int(options['memory_limit_mb'])}M"]
    if options.get("tolerance"):
        command += ["--tolerance", repr(options["tolerance"])]
    cpu = [0.0]  # the file's processes' CPU seconds; None when one of them was not measured
    outcome, reason, _ = _run(command, limit, memory, cpu)
    stats = _read_json(outputs["stats"]) if outcome == OK else None
    if outcome == OK and stats is None:
        outcome, reason = CRASHED, "exit status 0 without its --stats file"
    figures = {}
    if outcome == OK:
        figures = {k: stats.get(k) for k in ("triangles", "vertices", "certified_bound")}
        figures["tessellate_seconds"] = stats.get("seconds")
        if "check" in outputs:
            left = max(limit - (time.monotonic() - start), 1)
            outcome, reason, checked = _check(cli, outputs["mesh"], outputs["check"], left, memory,
                                             cpu)
            figures.update(checked)
    done = {k: p for k, p in outputs.items() if outcome == OK and os.path.exists(p)}
    return {
        "outcome": outcome,
        "reason": reason,
        "figures": figures,
        "outputs": done,
        "output_sha256": {k: file_hash(p) for k, p in done.items()},
        "seconds": round(time.monotonic() - start, 6),
        "cpu_seconds": None if cpu[0] is None else round(cpu[0], 6),
        "host": socket.gethostname(),
    }


def failed(reason):
    """The manifest fields of a file whose job itself failed."""
    return {"outcome": CRASHED, "reason": reason, "figures": {}, "outputs": {},
            "output_sha256": {}, "seconds": 0, "cpu_seconds": None,
            "host": socket.gethostname()}


def run_file(input_path, outputs, options):
    """Tessellates (and checks) one file; returns its manifest fields but the
    input's own (path, size, hash), which the batch adds. Never raises: a
    failure of the job itself (an output folder it cannot make) is the file's
    outcome too."""
    try:
        return _tessellate_and_check(input_path, outputs, options)
    except Exception as e:  # recorded, and the batch goes on
        return failed(f"batch job: {type(e).__name__}: {e}")
