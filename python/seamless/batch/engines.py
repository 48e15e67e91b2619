# SPDX-License-Identifier: MIT
"""Where the per-file jobs run: a pool on this machine (--workers N), or the
workers of a Dask distributed cluster (--scheduler ADDRESS). Either way the
results stream back in the order they finish, to the one process that
writes the manifest; a Dask worker that dies mid-task has its task rerun
elsewhere by the scheduler, and the file is recorded once, when its future
finishes."""

import concurrent.futures
import uuid

from . import job


def local(tasks, options, workers):
    """Yields (index, result) as the jobs finish; each job waits on its own processes."""
    with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
        futures = {
            pool.submit(job.run_file, path, outputs, options): i
            for i, (path, outputs) in enumerate(tasks)
        }
        try:
            for f in concurrent.futures.as_completed(futures):
                yield futures[f], f.result()
        except BaseException:  # Ctrl-C: what runs is stopped unrecorded, the rest never starts
            for f in futures:
                f.cancel()
            job.stop_all()
            raise


def dask(tasks, options, client):
    """The same on a Dask cluster (`client`: a distributed.Client)."""
    from distributed import as_completed
    from distributed.scheduler import KilledWorker

    run = uuid.uuid4().hex[:12]  # keys unique to this batch: no result of another run is reused
    futures = {
        client.submit(job.run_file, path, outputs, options, key=f"seamless-{run}-{i}", pure=False): i
        for i, (path, outputs) in enumerate(tasks)
    }
    try:
        for f in as_completed(futures):
            i = futures[f]
            try:
                yield i, f.result()
            except KilledWorker as e:  # the file killed every worker that tried it
                yield i, job.failed(f"the Dask workers that ran it died ({e})")
            except Exception as e:  # the cluster's failure, recorded as the file's
                yield i, job.failed(f"Dask: {type(e).__name__}: {e}")
    except BaseException:
        client.cancel(list(futures))
        raise

