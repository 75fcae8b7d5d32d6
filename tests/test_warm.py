"""The warm-up (``python -m raildyn compile``) leaves numba's cache built for every kernel.

One fresh process with an empty cache (``NUMBA_CACHE_DIR`` in a temporary folder) runs the command, which
must write an index (.nbi) for every cached numba function of raildyn, found in the sources, and machine
code (.nbc) for every module that has one. A second fresh process then makes the first calls the
notebooks make (a bifurcation diagram, a FASTSIM batch, a train run, a bridge crossing) and the whole
warm-up again: numba's own counts must show every kernel loaded from the cache, none compiled. Times are
not asserted here: the cold and warm first calls are timed by ``benchmarks/bench_cold.py``.
"""

from __future__ import annotations

import ast
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

# The first call of each compiled path the notebooks meet, then the warm-up; numba's counts as JSON.
FIRST_CALLS = """
import json
import numpy as np
from raildyn import bridge, stability, train
from raildyn.__main__ import cache_counts, kernels, warm
from raildyn.contact import fastsim
from raildyn.vehicles import LateralCar

stability.bifurcation_diagram(LateralCar().nonlinear(), np.linspace(50.0, 100.0, 3), duration=0.5, refine=1,
                              progress=False)
fastsim(np.linspace(-2e-3, 2e-3, 1000), 0.0, 0.0, 100e3, 0.3, 6e-3, 4e-3, fields=False)
train.simulate(train.braking_model(10, 1), 5.0, 20.0)
beam = bridge.SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=5)
bridge.crossing(beam, bridge.AxleSequence([0.0], [1.0e5]), 40.0)
first = {name: [sum(k.stats.cache_hits.values()), sum(k.stats.cache_misses.values())]
         for name, k in kernels().items()}
warm(progress=False)
print(json.dumps({"first": first, "all": cache_counts()}))
"""


def _cached_functions() -> dict[Path, list[str]]:
    """Module file (relative to raildyn/) -> its functions decorated with ``numba.njit(..., cache=True)``."""
    found: dict[Path, list[str]] = {}
    for path in sorted((ROOT / "raildyn").rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if not isinstance(node, ast.FunctionDef):
                continue
            for dec in node.decorator_list:
                if (
                    isinstance(dec, ast.Call)
                    and ast.unparse(dec.func) in ("numba.njit", "njit", "numba.jit")
                    and any(k.arg == "cache" and ast.unparse(k.value) == "True" for k in dec.keywords)
                ):
                    found.setdefault(path.relative_to(ROOT / "raildyn"), []).append(node.name)
    return found


def _cache_files(cache: Path, module: Path) -> list[str]:
    """The names of numba's cache files of one module under ``NUMBA_CACHE_DIR``: numba keeps them in a
    folder named after the module's folder and a hash of its path (``bridge_<sha1>``), each file named
    ``<module>.<function>-<line>.py<version>.nbi`` (the index) or ``... .<n>.nbc`` (the code)."""
    return [
        p.name
        for folder in cache.glob(f"{module.parent.name}_*")
        for p in folder.iterdir()
        if p.name.startswith(f"{module.stem}.")
    ]


def _env(cache: Path) -> dict[str, str]:
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache), RAILDYN_PROGRESS="0")
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])])
    return env


def test_the_sources_declare_cached_kernels_where_the_warm_up_looks():
    modules = {str(m) for m in _cached_functions()}
    # The modules whose kernels the chapters run: the test below would pass vacuously without them.
    for module in ("integrators/_dopri.py", "wheelset/_engine.py", "contact/_fastsim_kernel.py",
                   "train/_kernel.py", "bridge/_kernel.py", "bridge/_impact_kernel.py",
                   "vehicles/_rocking_kernel.py"):  # fmt: skip
        assert module in modules, f"no cached numba function found in raildyn/{module}"


@pytest.mark.slow
def test_warm_up_builds_the_cache_and_a_fresh_process_loads_every_kernel(tmp_path):
    cache = tmp_path / "numba"
    cache.mkdir()
    env = _env(cache)
    warm = subprocess.run(
        [sys.executable, "-m", "raildyn", "compile"], cwd=ROOT, env=env, capture_output=True, text=True
    )
    assert warm.returncode == 0, warm.stderr[-3000:]
    assert " 0 loaded from the cache" in warm.stdout, warm.stdout
    assert f"numba's cache: under {cache}" in warm.stdout, warm.stdout

    # An index for every cached function of every module, and compiled code beside each module's indexes.
    missing = []
    for module, functions in _cached_functions().items():
        names = _cache_files(cache, module)
        indexed = {n.partition("-")[0] for n in names if n.endswith(".nbi")}
        missing += [f"{module}: {fn}" for fn in functions if f"{module.stem}.{fn}" not in indexed]
        assert any(n.endswith(".nbc") for n in names), f"no code cached for raildyn/{module}"
    assert not missing, f"the warm-up left these numba functions uncompiled: {missing}"

    check = subprocess.run(
        [sys.executable, "-c", FIRST_CALLS], cwd=ROOT, env=env, capture_output=True, text=True
    )
    assert check.returncode == 0, check.stderr[-3000:]
    counts = json.loads(check.stdout.strip().splitlines()[-1])
    used = {name: c for name, c in counts["first"].items() if sum(c)}
    compiled = {name: c for name, c in used.items() if c[1]}
    assert not compiled, f"compiled again instead of loaded from the warm-up's cache: {compiled}"
    # The notebooks' first calls reached the kernels of each path: the engine, FASTSIM, the train, the bridge.
    for module in ("wheelset._engine", "contact._fastsim_kernel", "train._kernel", "bridge._kernel"):
        assert any(f"raildyn.{module}." in name for name in used), f"no kernel of {module} was loaded: {used}"
    loaded, recompiled = counts["all"]
    assert recompiled == 0 and loaded > 0, counts["all"]
