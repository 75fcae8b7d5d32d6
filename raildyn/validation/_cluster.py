"""Running the studies of :mod:`raildyn.validation.uncertainty` on dask.distributed.

A call opens what it needs (a LocalCluster of processes when no client is given, a Client on a
scheduler address or a cluster object) and closes what it opened; the model runs on the workers
in batches whose rows were drawn beforehand, gathered in their order, so the answer does not
depend on the number of workers. The module is private: :mod:`raildyn.validation.uncertainty`
imports its names.
"""

from __future__ import annotations

import contextlib
import math
import re

import numpy as np

from raildyn import _checks
from raildyn._progress import progress_bar

__all__ = ["CONNECT_TIMEOUT", "DEFAULT_BATCHES", "check_client", "evaluate_all", "session"]

#: Seconds to wait for a scheduler given by its address.
CONNECT_TIMEOUT = 10.0
#: Batches the work is split into when ``batch`` is None (enough for a smooth bar and for
#: load balancing over a few tens of workers; few enough that scheduling costs little).
DEFAULT_BATCHES = 64


def check_client(client) -> None:
    """None, a distributed.Client, a scheduler address or a cluster object (with scheduler_address)."""
    if client is None:
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
        "client must be a distributed.Client, a scheduler address, a cluster object (LocalCluster, "
        f"a dask-jobqueue cluster) or None, got {client!r:.80} of type {type(client).__name__}"
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


def evaluate_all(model_fn, names, X, client, workers, batch, vectorized, desc, *, scalar=False):
    """The model at every row of X, on dask.distributed, in batches gathered in their order."""
    shape = probe(model_fn, names, X, vectorized, scalar)
    n = X.shape[0]
    size = batch if batch is not None else max(1, math.ceil(n / DEFAULT_BATCHES))
    starts = range(0, n, size)
    from distributed import as_completed

    with session(client, workers) as c:
        task = batch_task()
        futures = [
            c.submit(task, model_fn, names, X[s : s + size], s, shape, vectorized, pure=False) for s in starts
        ]
        try:
            with progress_bar(total=len(futures), desc=f"{desc} ({n} evaluations, batches)") as bar:
                for done in as_completed(futures):
                    if done.status == "error":
                        done.result()  # raises the model's error here, naming its sample
                    bar.update(1)
            parts = c.gather(futures)
        finally:
            c.cancel(futures)
    return np.concatenate(parts)
