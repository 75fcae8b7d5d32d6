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

Parallel efficiency against the number of workers: the same 1,000 critical speeds on a
``LocalCluster`` of 1, 2, 4, ... workers up to the machine's cores (each cluster started and
warmed outside the timing, the default batches of ``monte_carlo``), efficiency
T₁ / (W T_W) with T₁ the one-worker cluster. The issue's goal is 3,000 critical speeds at an
efficiency ≥ 0.85 on 16 workers, which a 2-core machine cannot run: the row replays on 16
workers what this machine measures, each evaluation's own time (1,000 measured, taken three
times over) in the default batches for 16 workers, each task with the overhead per task
measured here (100 tasks of a model that carries the car as the real one does but returns at
once, on the one-worker cluster), the tasks taken in turn by the first free worker (as the
scheduler does), after the one evaluation the call makes in this process first. What
that replay leaves out (memory bandwidth shared by 16 processes, a busier scheduler) is why it
is a prediction, reported beside the measured rows.

Quasi-Monte Carlo against Monte Carlo: the mean of the Ishigami function (exactly a/2 = 3.5
for x uniform on [−π, π]³) by :func:`raildyn.validation.uncertainty.monte_carlo` at N = 256
and 1024 evaluations, with ``sampling="sobol"`` and ``"halton"`` against ``"random"``, over 32
seeds: the root-mean-square error over the seeds of each, at equal evaluations (the timed
columns: the Sobol' studies against the random ones).
"""

from __future__ import annotations

import heapq
import math
import multiprocessing
import os
import statistics
import sys
import time
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import cloudpickle
import numpy as np
from scipy import stats

from benchmarks.common import Case, timed, widget_case
from raildyn.stability import critical_speed
from raildyn.validation import _cluster
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


def _carried(**params) -> float:
    """No work, but the car travels with each task as it does with :func:`car_critical_speed`."""
    return CAR.wheelset.conicity


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
        *_efficiency_cases(repeats, mc.samples),
        *_qmc_cases(),
        *_widget_cases(repeats),
    ]


def _worker_counts() -> list[int]:
    """1, 2, 4, ... up to the machine's cores, and the cores themselves."""
    cores = _cluster.machine_cores()
    return sorted({1, cores, *(2**k for k in range(int(math.log2(cores)) + 1))})


def _replay(times: np.ndarray, overhead: float, workers: int) -> float:
    """The parallel efficiency of evaluations of these times, in the default batches, on ``workers``.

    Each task costs its evaluations plus ``overhead``; the tasks go in turn to the first free
    worker; the probe (the first evaluation, run in the calling process first) adds its time.
    """
    free = [0.0] * workers
    for start, stop in _cluster.batches(times.size, None, workers):
        heapq.heappush(free, heapq.heappop(free) + times[start:stop].sum() + overhead)
    return times.sum() / (workers * (max(free) + times[0]))


def _efficiency_cases(repeats: int, samples: np.ndarray) -> list[Case]:
    """The critical speeds on 1, 2, ... workers: efficiency T1 / (W T_W), and the replay on 16."""
    from distributed import Client, LocalCluster

    names = list(DISTRIBUTIONS)
    each = []
    for row in samples:  # each evaluation's own time, for the replay
        start = time.perf_counter()
        car_critical_speed(**dict(zip(names, map(float, row), strict=True)))
        each.append(time.perf_counter() - start)
    each = np.array(each)
    runs, load = {}, [os.getloadavg()[0]]
    for w in _worker_counts():
        cluster = LocalCluster(n_workers=w, threads_per_worker=1, processes=True, dashboard_address=":0")
        with cluster, Client(cluster) as client:

            def run(i, client=client):
                return monte_carlo(car_critical_speed, DISTRIBUTIONS, EVALUATIONS, rng=11, client=client)

            run(0)  # warms the workers (imports, first calls), as a kept cluster is
            runs[w] = timed(run, max(2, repeats // 5))
            if w == 1:
                start = time.perf_counter()
                monte_carlo(_carried, DISTRIBUTIONS, 1000, rng=11, client=client, batch=10)
                overhead = (time.perf_counter() - start) / 100
    load.append(os.getloadavg()[0])
    t1 = statistics.median(runs[1])
    replayed = _replay(np.tile(each, 3), overhead, 16)
    return [
        Case(
            f"{EVALUATIONS} critical speeds on a {w}-worker LocalCluster against 1 worker (default batches): "
            f"efficiency T1/({w} T{w}) = {t1 / (w * statistics.median(tw)):.2f}; load average "
            f"{load[0]:.1f} to {load[1]:.1f} on {_cluster.machine_cores()} cores. Replayed on 16 workers "
            f"(3,000 critical speeds, {1e3 * each.mean():.1f} ms each as measured, {1e3 * overhead:.1f} ms "
            f"overhead per task): efficiency {replayed:.2f}",
            tw,
            runs[1],
            "efficiency ≥ 0.85 on 16 workers (3,000 critical speeds; replayed), ≥ 0.8 measured",
            "1-worker LocalCluster",
        )
        for w, tw in runs.items()
        if w > 1
    ]


A_ISHIGAMI, B_ISHIGAMI = 7.0, 0.1


def _ishigami(x1, x2, x3):
    return np.sin(x1) + A_ISHIGAMI * np.sin(x2) ** 2 + B_ISHIGAMI * x3**4 * np.sin(x1)


def _qmc_cases(seeds: int = 32) -> list[Case]:
    """RMS error of the Ishigami mean over seeds: scrambled Sobol' and Halton against random, equal N."""
    uniform = stats.uniform(-np.pi, 2 * np.pi)
    dists = {"x1": uniform, "x2": uniform, "x3": uniform}
    out = []
    with ThreadPoolExecutor(1) as pool:
        for n in (256, 1024):
            rms, times = {}, {}
            for sampling in ("random", "sobol", "halton"):
                errors, times[sampling] = [], []
                for seed in range(seeds):
                    start = time.perf_counter()
                    mc = monte_carlo(
                        _ishigami, dists, n, rng=seed, client=pool, sampling=sampling, vectorized=True
                    )
                    times[sampling].append(time.perf_counter() - start)
                    errors.append(float(mc.mean) - A_ISHIGAMI / 2)
                rms[sampling] = math.sqrt(np.mean(np.square(errors)))
            out.append(
                Case(
                    f"mean of the Ishigami function (exactly 3.5), N = {n} evaluations, RMS error over "
                    f"{seeds} seeds: Monte Carlo {rms['random']:.4f}, scrambled Sobol' {rms['sobol']:.4f} "
                    f"({rms['random'] / rms['sobol']:.0f}× smaller), scrambled Halton {rms['halton']:.4f} "
                    f"({rms['random'] / rms['halton']:.0f}× smaller); timed: one study each at equal "
                    "evaluations (the Sobol' one adds the scrambling of its sequence, about 3 ms)",
                    times["sobol"],
                    times["random"],
                    "QMC RMS error ≥ 5× below Monte Carlo's at equal evaluations",
                    "Monte Carlo (random draws), same N",
                )
            )
    return out


def _widget_cases(repeats: int) -> list[Case]:
    """Chapter 11's widgets, each update against a new figure per change."""
    from raildyn.widgets import chapter11

    return [
        widget_case(label, recipe, control, values, repeats)
        for label, recipe, control, values in chapter11.BENCH_MOVES
    ]
