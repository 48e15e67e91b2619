# SPDX-License-Identifier: MIT
"""python3 -m seamless.batch (and `seamless batch`): docs/batch.md."""

import argparse
import sys

from . import FORMATS, report, run_batch
from .inputs import BatchInputError


def parse(argv):
    p = argparse.ArgumentParser(
        prog="seamless batch",
        description="Tessellate (and check) many model files, each in its own process with a "
        "time and a memory limit, into OUT_DIR mirroring the input tree; a rerun skips what "
        "is done (OUT_DIR/manifest.jsonl).",
    )
    p.add_argument("inputs", nargs="+", metavar="INPUT",
                   help="model file, folder (recursively) or list file (.txt: one input a line)")
    p.add_argument("-o", "--output", required=True, metavar="OUT_DIR")
    p.add_argument("--tolerance", type=float, help="requested deviation, model units")
    p.add_argument("--format", default="glb", choices=FORMATS, help="mesh format (default glb)")
    p.add_argument("--check", action="store_true", help="also write each mesh's check --json report")
    p.add_argument("--workers", type=int, help="files at once on this machine (default: cores)")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="a Dask scheduler, e.g. tcp://host:8786: the files run on its workers")
    p.add_argument("--time-limit", type=float, default=600, metavar="S",
                   help="seconds per file (default 600)")
    p.add_argument("--memory-limit", type=int, default=4096, metavar="MB",
                   help="address space per file process, MiB (default 4096)")
    p.add_argument("--threads", type=int, default=1,
                   help="threads of each file's tessellation (default 1: files run in parallel)")
    p.add_argument("--cli", help="the seamless program the jobs run (default: this build's)")
    return p.parse_args(argv)


def main(argv=None):
    a = parse(sys.argv[1:] if argv is None else argv)
    try:
        summary = run_batch(
            a.inputs, a.output, tolerance=a.tolerance, format=a.format, check=a.check,
            workers=a.workers, scheduler=a.scheduler, time_limit=a.time_limit,
            memory_limit_mb=a.memory_limit, threads=a.threads, cli=a.cli,
        )
    except BatchInputError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("interrupted: the files finished are in the manifest; run again to go on",
              file=sys.stderr)
        return 130
    report.write(summary, a.output)
    return 0 if summary["outcomes"]["ok"] == summary["files"] else 1


if __name__ == "__main__":
    sys.exit(main())
