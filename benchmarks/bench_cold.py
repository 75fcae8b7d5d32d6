"""Cold starts: the first call of each compiled path in a fresh process, with numba's cache empty and built.

raildyn's kernels are compiled by numba on first use and cached on disk (``cache=True``); the install
builds the cache ahead of time (``python -m raildyn compile``). Each case runs a fresh
Python process that imports the chapter's module and makes the first call a notebook makes (the first
bifurcation diagram, FASTSIM batch, train run and bridge crossing): raildyn's time with the cache the
warm-up built, the baseline's with an empty cache (``NUMBA_CACHE_DIR`` pointed at a new folder, one per
process, so that no path borrows another's compiled kernels). The time is the import of the module and
the call, what a reader waits for in the cell; the row's name gives the import's share of the warm time.
Goal: with the warm cache, each ≤ 2 s. A last row times the warm-up itself, on a built cache against an
empty one (the time an install spends).
"""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from benchmarks.common import Case

ROOT = Path(__file__).resolve().parents[1]

# The first call of each path, as the notebooks make it (chapters 7, 4, 9 and 10).
FIRST_CALLS = {
    "bifurcation diagram of the car (11 speeds × 8 s + 4 bisections)": (
        "from raildyn import stability\nfrom raildyn.vehicles import LateralCar",
        "car = LateralCar().nonlinear()\n"
        "stability.bifurcation_diagram(car, np.linspace(50.0, 100.0, 11), progress=False)",
    ),
    "FASTSIM batch, 10⁴ states × 20×20 cells": (
        "from raildyn.contact import fastsim",
        "fastsim(np.linspace(-3e-3, 3e-3, 10_000), 0.0, 0.0, 100e3, 0.3, 6e-3, 4e-3, fields=False)",
    ),
    "train run, 150 wagons braking, 60 s": (
        "from raildyn import train",
        "m = train.braking_model(150, 2)\ntrain.simulate(m, 60.0, 20.0, initial_extension=m.gear.slack / 2)",
    ),
    "bridge crossing, the Manchester car over 20 m at 144 km/h": (
        "from raildyn import bridge\nfrom raildyn.vehicles import VerticalCar",
        "bridge.crossing(bridge.SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=5), "
        "bridge.vehicle(VerticalCar(), 1813.0), 40.0)",
    ),
}

PROGRAM = """
import json, time
import numpy as np
start = time.perf_counter()
{imports}
imported = time.perf_counter()
{call}
done = time.perf_counter()
print(json.dumps({{"import": imported - start, "total": done - start}}))
"""


def _env(cache: str) -> dict[str, str]:
    env = dict(os.environ, NUMBA_CACHE_DIR=cache, RAILDYN_PROGRESS="0")
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])])
    return env


def _run(args: list[str], cache: str) -> str:
    proc = subprocess.run([sys.executable, *args], cwd=ROOT, env=_env(cache), capture_output=True, text=True)
    if proc.returncode:
        raise RuntimeError(f"{' '.join(args)[:80]} failed:\n{proc.stderr[-3000:]}")
    return proc.stdout


def _first_call(imports: str, call: str, cache: str) -> dict:
    return json.loads(_run(["-c", PROGRAM.format(imports=imports, call=call)], cache).splitlines()[-1])


def _warm_up(cache: str) -> float:
    start = time.perf_counter()
    _run(["-m", "raildyn", "compile"], cache)
    return time.perf_counter() - start


def cases(repeats: int) -> list[Case]:
    # Cold runs compile for tens of seconds each: one per path; the warm ones are repeated.
    warm_repeats = max(1, repeats // 5)
    out = []
    with tempfile.TemporaryDirectory(prefix="raildyn-bench-cold-") as tmp:
        built = os.path.join(tmp, "built")
        from_empty = _warm_up(built)
        again = [_warm_up(built) for _ in range(warm_repeats)]
        for name, (imports, call) in FIRST_CALLS.items():
            cold = _first_call(imports, call, tempfile.mkdtemp(dir=tmp))
            warm = [_first_call(imports, call, built) for _ in range(warm_repeats)]
            share = statistics.median(w["import"] for w in warm)
            out.append(
                Case(
                    f"first {name}, fresh process, import + call (import {share:.2f} s warm)",
                    [w["total"] for w in warm],
                    [cold["total"]],
                    "≤ 2 s with the warm cache",
                    "empty numba cache",
                )
            )
    out.append(
        Case(
            "python -m raildyn compile (the warm-up of the install), process included",
            again,
            [from_empty],
            "report: once at install",
            "from an empty cache",
        )
    )
    return out
