"""Fuzz registry: chapter 11's Monte Carlo bands and Sobol' indices (raildyn.validation.uncertainty).

The valid calls run on one in-process cluster (threads: it starts in well under a second),
started at the first call and closed when the interpreter exits; they draw quasi-random
samples (Halton's for the bands, Sobol' points for the indices, 16 = 2^4 of them). The change ``client: none``
starts the default LocalCluster (hence the longer limit of those entries) of the valid call's ``workers``,
one process: a process takes seconds to start, and the default of one a core runs the same path.
"""

from __future__ import annotations

import atexit

import numpy as np
from fuzzing import call, fuzz, on
from scipy import stats

from raildyn.validation.uncertainty import MonteCarloResult, SobolResult

_CLIENTS: list = []


def _client():
    if not _CLIENTS:
        from distributed import Client

        c = Client(n_workers=1, threads_per_worker=2, processes=False, dashboard_address=":0")
        atexit.register(c.close)
        _CLIENTS.append(c)
    return _CLIENTS[0]


DISTRIBUTIONS = {"k": stats.norm(1.0e6, 1.0e5), "m": stats.uniform(900.0, 200.0)}


def _mc_result() -> MonteCarloResult:
    rng = np.random.default_rng(0)
    X = rng.normal(size=(20, 2))
    Y = np.outer(X[:, 0] + X[:, 1], [1.0, 2.0, 3.0])
    p = np.array([2.5, 50.0, 97.5])
    return MonteCarloResult(("a", "b"), X, Y, Y.mean(0), Y.std(0, ddof=1), p, np.percentile(Y, p, axis=0))


def _sobol_result() -> SobolResult:
    return SobolResult(
        ("k", "c"), np.array([0.6, 0.1]), np.array([0.8, 0.3]), np.array([[0.5, 0.7], [0.0, 0.2]]),
        np.array([[0.7, 0.9], [0.2, 0.4]]), 0.95, 100, 2.0,
    )  # fmt: skip


ENTRIES = [
    fuzz(
        "raildyn.validation.uncertainty.monte_carlo",
        lambda: call(
            lambda k, m: np.sqrt(k / m),
            DISTRIBUTIONS,
            20,
            rng=1,
            sampling="halton",
            client=_client(),
            workers=1,
        ),
        accepts={
            "model_fn": "returns-negative returns-shape",  # any finite output of one fixed shape
            "rng": "zero none",  # seed 0; None: fresh entropy
            "client": "none",  # the default: a LocalCluster of `workers` processes for the call
            "workers": "none",  # one a core
            "batch": "huge",  # one batch of everything
        },
        limit=30.0,
    ),
    fuzz(
        "raildyn.validation.uncertainty.sobol_indices",
        lambda: call(
            lambda k, m: k / m,
            DISTRIBUTIONS,
            16,
            rng=1,
            sampling="sobol",
            client=_client(),
            workers=1,
            bootstrap=20,
            confidence=0.9,
        ),
        accepts={
            "confidence": "tiny",
            "model_fn": "returns-negative",
            "rng": "zero none",
            "client": "none",
            "workers": "none",
            "batch": "huge",
        },
        limit=30.0,
    ),
    fuzz(
        "raildyn.validation.uncertainty.MonteCarloResult",
        lambda: call(*(getattr(_mc_result(), f) for f in MonteCarloResult.__dataclass_fields__)),
        # samples, outputs, their statistics: whatever a model computes (a mean may be 0 or < 0)
        accepts={
            "samples": "zero negative",
            "outputs": "zero negative",
            "mean": "zero negative",
            "std": "zero",
            "bands": "zero negative",
        },  # fmt: skip
    ),
    fuzz(
        "raildyn.validation.uncertainty.MonteCarloResult.plot",
        lambda: on(_mc_result(), None, x=[0.0, 1.0, 2.0]),
        accepts={"x": "zero negative none"},  # any abscissa; None: 0, 1, 2
    ),
    fuzz(
        "raildyn.validation.uncertainty.SobolResult",
        lambda: call(*(getattr(_sobol_result(), f) for f in SobolResult.__dataclass_fields__)),
        # estimates of S_i may dip below 0; S_Ti and the intervals of S_i may be 0
        accepts={
            "confidence": "tiny",
            "variance": "big tiny mm",
            "first_order": "zero negative",
            "total": "zero",
            "first_order_interval": "zero",
            "total_interval": "zero",
        },  # fmt: skip
    ),
    fuzz("raildyn.validation.uncertainty.SobolResult.plot", lambda: on(_sobol_result())),
]
