"""Chapter 11: 1,000 critical speeds of the chapter-7 car under parameter scatter, on a 2-worker
``LocalCluster`` (:func:`raildyn.validation.uncertainty.monte_carlo`) against a serial loop, in the same run.

The car is :class:`raildyn.vehicles.LateralCar` (the Manchester benchmark vehicle); the primary lateral and
yaw stiffnesses, the secondary lateral and yaw stiffnesses and the conicity each scatter uniformly
by ±10 % about their defaults. Each evaluation is one :func:`raildyn.stability.linear.critical_speed`
(a batched eigenvalue scan and a bracketed regula falsi, about 20 ms). The baseline is the plain loop over the
same 1,000 draws in this process. The two answers must agree to 1e-9 m/s (the same arithmetic on the
same numbers; only the process differs) before the timing counts.

The cluster (two worker processes, one thread each) is started once, outside the timing, as a
user who runs several studies keeps it; its start-up time is reported in the case's name. The
ratio is the speed-up; the parallel efficiency is the speed-up over the number of workers
(ideal 1). The machine's load average is reported beside them: on a shared 2-core machine,
other work takes cores from the workers and not from the loop, which needs only one. So is what
the machine itself allows two processes at that moment: the same draws split in halves over two
plain processes (``concurrent.futures``, no dask), started and warmed outside the timing; the
cluster's speed-up is to be read against that ceiling. The three are timed in interleaved rounds
(cluster, loop, bare processes; at least two rounds), so that a change in the machine's load
between rounds falls on all three alike.
"""

from __future__ import annotations

import multiprocessing
import os
import statistics
import sys
import time
from concurrent.futures import ProcessPoolExecutor

import cloudpickle
import numpy as np
from scipy import stats

from benchmarks.common import Case, timed, widget_case
from raildyn.stability import critical_speed
from raildyn.validation.uncertainty import monte_carlo
from raildyn.vehicles import LateralCar

# The model below lives in this file, which the worker processes may not import by name.
cloudpickle.register_pickle_by_value(sys.modules[__name__])

CAR = LateralCar()
WORKERS = 2
EVALUATIONS = 1000
SPEED_RANGE = (1.0, 150.0)  # m/s: the default car's critical speed is 77.9 m/s


def _scatter(value: float, spread: float = 0.10):
    """Uniform on value × [1 − spread, 1 + spread]."""
    return stats.uniform(value * (1 - spread), 2 * spread * value)


DISTRIBUTIONS = {
    "lateral_stiffness": _scatter(CAR.wheelset.lateral_stiffness),
    "yaw_stiffness": _scatter(CAR.wheelset.yaw_stiffness),
    "secondary_lateral_stiffness": _scatter(CAR.bogie.secondary_lateral_stiffness),
    "secondary_yaw_stiffness": _scatter(CAR.bogie.secondary_yaw_stiffness),
    "conicity": _scatter(CAR.wheelset.conicity),
}


def car_critical_speed(**params) -> float:
    """The linear critical speed (m/s) of the car with the given stiffnesses and conicity."""
    return critical_speed(CAR.replace(**params), SPEED_RANGE).speed


def _serial(samples: np.ndarray) -> np.ndarray:
    names = list(DISTRIBUTIONS)
    return np.array([car_critical_speed(**dict(zip(names, map(float, row), strict=True))) for row in samples])


def _bare_processes(pool, samples: np.ndarray) -> np.ndarray:
    """The draws split in WORKERS equal parts on as many plain processes: the machine's own ceiling."""
    return np.concatenate(list(pool.map(_serial, np.array_split(samples, WORKERS))))


def cases(repeats: int):
    from distributed import Client, LocalCluster

    start = time.perf_counter()
    spawn = multiprocessing.get_context("spawn")
    with (
        LocalCluster(
            n_workers=WORKERS, threads_per_worker=1, processes=True, dashboard_address=":0"
        ) as cluster,
        Client(cluster) as client,
        ProcessPoolExecutor(WORKERS, mp_context=spawn) as pool,
    ):
        startup = time.perf_counter() - start

        def on_cluster(i):
            return monte_carlo(car_critical_speed, DISTRIBUTIONS, EVALUATIONS, rng=11, client=client)

        mc = on_cluster(0)  # also warms the workers
        serial = _serial(mc.samples)
        gap = np.abs(mc.outputs - serial).max()
        if gap > 1e-9:
            raise AssertionError(f"critical speeds on the cluster and in the loop differ by {gap:.3g} m/s")
        _bare_processes(pool, mc.samples[: 2 * WORKERS])  # start and warm the plain processes
        load = [os.getloadavg()[0]]  # other work on the machine takes cores from the workers
        # Interleaved, one of each per round, so that a change in the machine's load between
        # rounds falls on all three alike.
        fast, slow, bare = [], [], []
        for _ in range(max(2, repeats // 5)):
            fast += timed(on_cluster, 1)
            slow += timed(lambda i: _serial(mc.samples), 1)
            bare += timed(lambda i: _bare_processes(pool, mc.samples), 1)
        load.append(os.getloadavg()[0])
    speedup = statistics.median(slow) / statistics.median(fast)
    ceiling = statistics.median(slow) / statistics.median(bare)
    return [
        Case(
            f"{EVALUATIONS} critical speeds of the car, ±10 % scatter on 4 stiffnesses and the conicity "
            f"(V_c {mc.bands[0]:.1f}–{mc.bands[-1]:.1f} m/s, 95 %), {WORKERS}-worker LocalCluster: "
            f"speed-up {speedup:.2f}, efficiency {speedup / WORKERS:.2f}; cluster start-up "
            f"{startup:.1f} s, not timed; {'bit-identical' if gap == 0 else f'agree to {gap:.1g} m/s'}; "
            f"load average {load[0]:.1f} to {load[1]:.1f} on {os.cpu_count()} cores; {WORKERS} bare "
            f"processes without dask (concurrent.futures, halves of the same draws) reach {ceiling:.2f}",
            fast,
            slow,
            f"speed-up ≥ 1.6 on {WORKERS} workers (efficiency ≥ 0.8; ideal {WORKERS})",
            "serial loop, same draws",
        ),
        *_widget_cases(repeats),
    ]


def _widget_cases(repeats: int) -> list[Case]:
    """Chapter 11's widgets, each update against a new figure per change."""
    from raildyn.widgets import chapter11

    return [
        widget_case(label, recipe, control, values, repeats)
        for label, recipe, control, values in chapter11.BENCH_MOVES
    ]
