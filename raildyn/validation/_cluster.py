"""Running the studies of :mod:`raildyn.validation.uncertainty` on dask.distributed or an executor.

A call opens what it needs (a LocalCluster of processes when no client is given, a Client on a
scheduler address or a cluster object) and closes what it opened; a ``concurrent.futures``
executor (threads, processes) is used as it is and left open. The model runs on the workers in
batches whose rows were drawn beforehand, gathered in their order, so the answer does not
depend on the number of workers nor on where they run. The module is private:
:mod:`raildyn.validation.uncertainty` imports its names.
"""

from __future__ import annotations

import contextlib
import math
import os
import pickle
import re
from concurrent.futures import Executor, ThreadPoolExecutor

import numpy as np

from raildyn import _checks
from raildyn._progress import progress_bar

__all__ = [
    "BATCHES_PER_WORKER",
    "CONNECT_TIMEOUT",
    "MIN_BATCHES",
    "batches",
    "check_client",
    "evaluate_all",
    "machine_cores",
    "session",
]

#: Seconds to wait for a scheduler given by its address.
CONNECT_TIMEOUT = 10.0
# The batches, when ``batch`` is None. A task costs an overhead o besides its evaluations
# (scheduling, pickling the model and its rows, sending the answer back: 3 to 10 ms a task on
# a LocalCluster of the 2-core development machine, quiet to busy). n evaluations of t seconds
# split into k W near-equal batches run on W workers in k full rounds and take about
# n t / W + k o + s, s being how long the workers that finish first wait for the last, so the
# parallel efficiency is about 1 / (1 + (k o + s) W / (n t)). A whole multiple of W keeps every
# round full (a fixed 64 batches on 24 workers leave 8 of them idle for the third round), and a
# few rounds let the load balance (a worker that drew slow rows takes fewer batches) while
# k o stays small against n t / W. For 3,000 critical speeds of 6–7 ms on 16 workers: 1.2 s of
# work each, 64 batches of 47 evaluations, k o = 0.01–0.04 s. Replaying 1,000 measured
# evaluation times (taken three times over) on 16 workers gives an efficiency of 0.88–0.90 for
# k from 1 to 8, on 24 workers 0.83–0.85 at k = 4 where 64 batches give 0.80–0.82
# (benchmarks/bench_ch11_uncertainty.py replays it in every run). At least MIN_BATCHES in all,
# so that the progress bar moves on one or two workers.
#: Batches per worker when ``batch`` is None.
BATCHES_PER_WORKER = 4
#: Fewest batches when ``batch`` is None (a whole multiple of the workers at or above it).
MIN_BATCHES = 16


def machine_cores() -> int:
    """The cores this process may run on (its CPU affinity where the system tells it)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # macOS and Windows have no sched_getaffinity
        return os.cpu_count() or 1


def batches(n: int, batch: int | None, workers: int) -> list[tuple[int, int]]:
    """The (start, stop) rows of each task: ``batch`` rows each, or near-equal batches for ``workers``."""
    if batch is not None:
        return [(s, min(s + batch, n)) for s in range(0, n, batch)]
    per_worker = max(BATCHES_PER_WORKER, math.ceil(MIN_BATCHES / workers))
    tasks = min(n, per_worker * workers)
    edges = [n * i // tasks for i in range(tasks + 1)]  # sizes differ by one row at most
    return list(zip(edges[:-1], edges[1:], strict=True))


def check_client(client) -> None:
    """None, an executor, a distributed.Client, a scheduler address or a cluster object."""
    if client is None or isinstance(client, Executor):
        return
    from distributed import Client

    if isinstance(client, Client):
        return
    if isinstance(client, str):
        if "://" not in client and not re.fullmatch(r"[^\s/:]+:\d+", client):
            raise ValueError(
                f"client must be a scheduler address such as 'tcp://10.0.0.5:8786' or 'host:8786', "
                f"got {client!r}"
            )
        return
    if isinstance(getattr(client, "scheduler_address", None), str):
        return
    raise TypeError(
        "client must be a concurrent.futures executor (ThreadPoolExecutor, ProcessPoolExecutor), a "
        "distributed.Client, a scheduler address, a cluster object (LocalCluster, a dask-jobqueue "
        f"cluster) or None, got {client!r:.80} of type {type(client).__name__}"
    )


def batch_task():
    """The function each task runs: the model at the rows of one batch, checked.

    It is built inside this function so that cloudpickle sends it by value, with no reference
    to this module: a worker then needs numpy and the model only, not raildyn.validation,
    whose import (every sibling module, scipy.signal, the bridge's compiled kernels) takes
    seconds on each new worker.
    """

    def evaluate(model_fn, names, X, start, shape, vectorized):
        import numpy as np

        def where(k):
            values = ", ".join(f"{name} = {float(X[k, j]):.6g}" for j, name in enumerate(names))
            return f"sample {start + k} ({values})"

        def as_numbers(out, at):
            try:
                return np.asarray(out, dtype=float)
            except (TypeError, ValueError):
                raise TypeError(f"model_fn must return numbers, returned {out!r:.80} at {at}") from None

        def run(params, at):
            try:
                return model_fn(**params)
            except Exception as err:
                err.add_note(f"raised by model_fn at {at}")  # the sample travels back with the error
                raise

        m = X.shape[0]
        if vectorized:
            at = f"samples {start} to {start + m - 1} (called with arrays)"
            Y = as_numbers(run({name: X[:, j].copy() for j, name in enumerate(names)}, at), at)
            if Y.shape != (m, *shape):
                raise ValueError(
                    f"model_fn must return an array of shape {(m, *shape)} at {at}, got {Y.shape}"
                )
            bad = ~np.isfinite(Y.reshape(m, -1)).all(axis=1)
            if bad.any():
                raise ValueError(
                    f"model_fn returned a non-finite value at {where(int(np.flatnonzero(bad)[0]))}"
                )
            return Y
        Y = np.empty((m, *shape))
        for k in range(m):
            y = as_numbers(run({name: float(X[k, j]) for j, name in enumerate(names)}, where(k)), where(k))
            if y.shape != shape:
                raise ValueError(
                    f"model_fn must return an array of shape {shape}, returned shape {y.shape} at {where(k)}"
                )
            if not np.isfinite(y).all():
                raise ValueError(f"model_fn returned a non-finite value at {where(k)}: {y!r}")
            Y[k] = y
        return Y

    return evaluate


def where(index, params) -> str:
    """'sample 17 (k = 1.2e6, m = 950)', for a message."""
    values = ", ".join(f"{k} = {v:.6g}" for k, v in params.items())
    return f"sample {index} ({values})"


def probe(model_fn, names, X, vectorized, scalar) -> tuple:
    """The output's shape, from the model at the first sample, evaluated here before any is sent."""
    if vectorized:
        out = model_fn(**{name: X[:1, j].copy() for j, name in enumerate(names)})
        arr = _checks.returned("model_fn", out, at="sample 0 (called with arrays of one value)")
        if arr.ndim == 0 or arr.shape[0] != 1:
            raise ValueError(
                f"model_fn (vectorized) must return one row per sample; given 1 sample it returned "
                f"shape {arr.shape}"
            )
        shape = arr.shape[1:]
    else:
        params = {name: float(X[0, j]) for j, name in enumerate(names)}
        shape = _checks.returned("model_fn", model_fn(**params), at=where(0, params)).shape
    if scalar and shape != ():
        raise ValueError(f"model_fn must return a single number for Sobol' indices, returned shape {shape}")
    return shape


@contextlib.contextmanager
def session(client, workers):
    """A distributed.Client for the call; what the call opened it closes."""
    from distributed import Client, LocalCluster

    if isinstance(client, Client):
        yield client
        return
    if client is None:
        import logging

        with (
            LocalCluster(
                n_workers=workers,
                threads_per_worker=1,
                processes=True,
                dashboard_address=":0",
                silence_logs=logging.ERROR,
            ) as cluster,
            Client(cluster) as opened,
        ):
            yield opened
        return
    if isinstance(client, str):
        try:
            opened = Client(client, timeout=CONNECT_TIMEOUT)
        except (OSError, TimeoutError, ValueError) as err:
            raise ValueError(
                f"client: no dask scheduler answered at {client!r} within {CONNECT_TIMEOUT:g} s ({err})"
            ) from err
    else:
        opened = Client(client)
    with opened:
        yield opened


class _Call:
    """A task as one pickle that runs it when loaded, for an executor of processes.

    ``pickle.loads`` of ``cloudpickle.dumps(_Call(fn, *args))`` is ``fn(*args)`` (the pickle's
    REDUCE step). A process pool pickles what it sends with the standard pickle, which sends
    functions by name: the task built by :func:`batch_task` has none, nor has a lambda or a
    notebook's model. Sent as bytes to ``pickle.loads``, they travel by value, as dask sends
    them, and the worker imports neither this module nor raildyn.
    """

    def __init__(self, fn, *args):
        self.fn, self.args = fn, args

    def __reduce__(self):
        return self.fn, self.args


def _executor_workers(executor) -> int:
    """The workers of a concurrent.futures executor (the machine's cores if it does not say)."""
    return int(getattr(executor, "_max_workers", 0) or machine_cores())


def _dask_workers(client) -> int:
    """The threads of the cluster's workers (0 while an adaptive cluster has none yet)."""
    return sum(w.get("nthreads", 1) for w in client.scheduler_info().get("workers", {}).values())


def _wait(futures, as_completed, failed, desc) -> None:
    """Advance the bar as the batches finish; raise the first error, naming its sample."""
    with progress_bar(total=len(futures), desc=desc) as bar:
        for done in as_completed(futures):
            if failed(done):
                done.result()  # raises the model's error here, naming its sample
            bar.update(1)


def evaluate_all(model_fn, names, X, client, workers, batch, vectorized, desc, *, scalar=False):
    """The model at every row of X, on dask.distributed or an executor, in batches gathered in order."""
    shape = probe(model_fn, names, X, vectorized, scalar)
    n = X.shape[0]
    task = batch_task()
    desc = f"{desc} ({n} evaluations, batches)"
    if isinstance(client, Executor):
        import concurrent.futures

        rows = batches(n, batch, _executor_workers(client))
        args = [(model_fn, names, X[s:e], s, shape, vectorized) for s, e in rows]
        if isinstance(client, ThreadPoolExecutor):  # shares this process: nothing to pickle
            futures = [client.submit(task, *a) for a in args]
        else:
            import cloudpickle

            futures = [client.submit(pickle.loads, cloudpickle.dumps(_Call(task, *a))) for a in args]
        try:
            _wait(futures, concurrent.futures.as_completed, lambda f: f.exception() is not None, desc)
            parts = [f.result() for f in futures]
        finally:
            for f in futures:
                f.cancel()
        return np.concatenate(parts)
    from distributed import as_completed

    with session(client, workers) as c:
        rows = batches(n, batch, _dask_workers(c) or workers)
        futures = [c.submit(task, model_fn, names, X[s:e], s, shape, vectorized, pure=False) for s, e in rows]
        try:
            _wait(futures, as_completed, lambda f: f.status == "error", desc)
            parts = c.gather(futures)
        finally:
            c.cancel(futures)
    return np.concatenate(parts)
