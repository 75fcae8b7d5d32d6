"""The import graph (issue 37): importing a model module loads none of the heavy libraries it uses in places.

A reader's first cell imports a chapter's module; what that costs is what it loads. Each model module
imports scipy.signal, the optimizers, the integrators, the statistics, matplotlib, numba's compiled
kernels and the rest where a function needs them, so its import loads numpy, scipy.linalg and raildyn's
own code. Read from ``sys.modules`` in a fresh interpreter, not timed: the import times, against
their goals (0.3 s, and 0.5 s for ``raildyn.figures``), are ``benchmarks/bench_imports.py``'s.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from functools import cache
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

#: The models of the book's chapters, each imported as a reader's first cell would.
MODELS = (
    "raildyn.constants",
    "raildyn.errors",
    "raildyn.plots",
    "raildyn.vibration",
    "raildyn.random_vibration",
    "raildyn.integrators",
    "raildyn.track",
    "raildyn.suspension",
    "raildyn.contact",
    "raildyn.linear_model",
    "raildyn.wheelset",
    "raildyn.vehicles",
    "raildyn.ride",
    "raildyn.stability",
    "raildyn.curving",
    "raildyn.train",
    "raildyn.bridge",
    "raildyn.validation",
)

#: Loaded by no model's import: each costs a tenth of a second or more, and only some functions use it
#: (sympy is the derivations', ipywidgets the widgets', dask the parameter studies' on a cluster).
HEAVY = (
    "scipy.signal",
    "scipy.stats",
    "scipy.optimize",
    "scipy.interpolate",
    "scipy.integrate",
    "matplotlib",
    "control",
    "sympy",
    "dask",
    "distributed",
    "ipywidgets",
    "IPython",
    "numba",  # loaded by the kernels where they run; the formulas wait for it (raildyn._compiled)
)


@cache
def _kernels() -> frozenset[str]:
    """Every raildyn module that imports numba at its top: a compiled kernel."""
    found = set()
    for path in (ROOT / "raildyn").rglob("*.py"):
        if re.search(r"^(import numba|from numba)", path.read_text(encoding="utf-8"), re.M):
            parts = path.relative_to(ROOT).with_suffix("").parts
            found.add(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return frozenset(found)


def _fresh(script: str) -> dict:
    """Run ``script`` in a fresh interpreter on this checkout's raildyn; it prints one JSON value."""
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}
    proc = subprocess.run(
        [sys.executable, "-c", script], cwd=ROOT, env=env, capture_output=True, text=True, timeout=300
    )
    assert proc.returncode == 0, proc.stderr[-3000:]
    return json.loads(proc.stdout.splitlines()[-1])


def _heavy(modules) -> list[str]:
    return sorted(m for m in modules if any(m == h or m.startswith(h + ".") for h in HEAVY))


@pytest.fixture(scope="module")
def loaded() -> dict[str, list[str]]:
    """Model → the modules its import added, importing the models one after another in one interpreter.

    One interpreter is enough: a heavy module loaded by one model's import is in that model's list
    (and the later models', which find it loaded, could not hide it).
    """
    return _fresh(
        "import importlib, json, sys\n"
        "seen = {}\n"
        f"for name in {list(MODELS)!r}:\n"
        "    before = set(sys.modules)\n"
        "    importlib.import_module(name)\n"
        "    seen[name] = sorted(set(sys.modules) - before)\n"
        "print(json.dumps(seen))\n"
    )


def test_every_model_is_imported(loaded):
    assert list(loaded) == list(MODELS)
    assert "raildyn.vibration.sdof" in loaded["raildyn.vibration"]  # the lists are of what was loaded


@pytest.mark.parametrize("model", MODELS)
def test_a_model_loads_no_heavy_library(loaded, model):
    assert _heavy(loaded[model]) == [], f"importing {model} loads {_heavy(loaded[model])}"


@pytest.mark.parametrize("model", MODELS)
def test_a_model_loads_no_compiled_kernel(loaded, model):
    kernels = sorted(_kernels() & set(loaded[model]))
    assert kernels == [], f"importing {model} loads the compiled {kernels}: import them where they run"


def test_the_kernels_are_found():
    # The list the test above holds the models to: a kernel of every compiled chapter.
    compiled = ("integrators._dopri", "wheelset._engine", "train._kernel", "bridge._kernel")
    compiled += ("contact._fastsim_kernel", "vehicles._rocking_kernel", "vehicles._march_kernel")
    assert {f"raildyn.{name}" for name in compiled} <= _kernels()


def test_the_figures_load_their_chapters_when_first_asked():
    seen = _fresh(
        "import json, sys\n"
        "import raildyn.figures as figures\n"
        "at_import = sorted(sys.modules)\n"
        "listed = 'REGISTRY' in dir(figures)\n"
        "registry = figures.REGISTRY\n"
        "print(json.dumps([at_import, listed, sorted(registry), registry is figures.REGISTRY]))\n"
    )
    at_import, listed, ids, same = seen
    chapters = set(MODELS) - {"raildyn.constants", "raildyn.errors", "raildyn.plots"}
    models = sorted(m for m in at_import if ".".join(m.split(".")[:2]) in chapters)
    assert models == [], f"importing raildyn.figures loads the models {models}"
    assert [m for m in _heavy(at_import) if not m.startswith("matplotlib")] == []
    assert not any(m.startswith("matplotlib.pyplot") for m in at_import)
    assert listed and same
    assert {"fig1.4", "fig1.5", "fig7.bifurcation"} <= set(ids)
