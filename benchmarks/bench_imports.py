"""Cold imports: each chapter's models, and ``raildyn.figures``, imported in a fresh interpreter (issue 37).

A reader's first cell imports a chapter's module; the goal is 0.3 s for a model module and 0.5 s for
the figures' registry. Each repeat starts a new interpreter and times the ``import`` statement alone
(the interpreter's own start-up left out), right after the baseline in its own new interpreter:
``import numpy, scipy.linalg``, what every model needs, so the ratio says what raildyn adds on a
machine whose load moves the absolute times. The bytecode is written by one untimed import first, as
a reader's second session finds it. What each import may load is tests/test_imports.py's.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from benchmarks.common import Case

ROOT = Path(__file__).resolve().parents[1]

# The model modules, each to import in ≤ 0.3 s: the list whose imports tests/test_imports.py holds.
from tests.test_imports import MODELS  # noqa: E402

BASELINE = "numpy, scipy.linalg"
_TIMED = "import time; start = time.perf_counter(); import {}; print(time.perf_counter() - start)"


def import_seconds(modules: str, root: Path = ROOT) -> float:
    """Seconds to run ``import <modules>`` in a new interpreter that finds raildyn in ``root``."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}  # as a reader's
    env["PYTHONPATH"] = str(root)
    proc = subprocess.run(
        [sys.executable, "-c", _TIMED.format(modules)],
        cwd=root,  # `python -c` looks in its working directory first
        env=env,
        capture_output=True,
        text=True,
        check=False,
    )
    if proc.returncode:
        raise RuntimeError(f"import {modules} failed: {proc.stderr[-2000:]}")
    return float(proc.stdout.splitlines()[-1])


def import_case(module: str, goal_s: float, repeats: int, root: Path = ROOT) -> Case:
    """``module``'s cold import beside the baseline's, alternating one of each, ``repeats`` times."""
    import_seconds(module, root)  # untimed: writes the bytecode
    ours, baseline = [], []
    for _ in range(repeats):
        baseline.append(import_seconds(BASELINE, root))
        ours.append(import_seconds(module, root))
    name = f"import {module}, fresh interpreter"
    return Case(name, ours, baseline, f"≤ {goal_s:g} s", f"import {BASELINE}")


def cases(repeats: int) -> list[Case]:
    count = max(3, repeats // 3)  # a new interpreter each time: fewer repeats than the in-process cases
    return [import_case(m, 0.3, count) for m in MODELS] + [import_case("raildyn.figures", 0.5, count)]
