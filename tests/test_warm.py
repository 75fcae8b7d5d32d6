"""The warm-up (``python -m raildyn compile``) leaves numba's cache built for every kernel.

The Binder environment (``tests/binder_env.py``, built from nothing in the background) is where it is
checked: its ``postBuild`` installs raildyn and runs the warm-up with an empty cache, which must compile
every kernel and leave an index (.nbi) beside the installed sources for every cached numba function of
raildyn, found in the sources, and machine code (.nbc) for every module that has one. A fresh process of
that environment then makes the first calls the notebooks make (``tests/first_calls.py``: a bifurcation
diagram, a FASTSIM batch, a train run, a bridge crossing) and the whole warm-up again: numba's own counts
must show every kernel loaded from the cache, none compiled. Times are not asserted here: the cold and
warm first calls are timed by ``benchmarks/bench_cold.py``.
"""

from __future__ import annotations

import ast
import functools
import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


@functools.cache
def _functions() -> tuple[tuple[Path, ast.FunctionDef], ...]:
    """Every function of raildyn's sources: (module file relative to raildyn/, its node), parsed once."""
    return tuple(
        (path.relative_to(ROOT / "raildyn"), node)
        for path in sorted((ROOT / "raildyn").rglob("*.py"))
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8")))
        if isinstance(node, ast.FunctionDef)
    )


def _cached_functions() -> dict[Path, list[str]]:
    """Module file (relative to raildyn/) -> its functions decorated with ``numba.njit(..., cache=True)``."""
    found: dict[Path, list[str]] = {}
    for module, node in _functions():
        for dec in node.decorator_list:
            if (
                isinstance(dec, ast.Call)
                and ast.unparse(dec.func) in ("numba.njit", "njit", "numba.jit")
                and any(k.arg == "cache" and ast.unparse(k.value) == "True" for k in dec.keywords)
            ):
                found.setdefault(module, []).append(node.name)
    return found


def test_the_sources_declare_cached_kernels_where_the_warm_up_looks():
    modules = {str(m) for m in _cached_functions()}
    # The modules whose kernels the chapters run: the test below would pass vacuously without them.
    for module in ("integrators/_dopri.py", "wheelset/_engine.py", "contact/_fastsim_kernel.py",
                   "train/_kernel.py", "bridge/_kernel.py", "bridge/_impact_kernel.py",
                   "vehicles/_rocking_kernel.py"):  # fmt: skip
        assert module in modules, f"no cached numba function found in raildyn/{module}"


def _kernel_bodies():
    """Every numba function of raildyn, cached or not: (module file relative to raildyn/, its node)."""
    for module, node in _functions():
        if any(
            ast.unparse(dec.func if isinstance(dec, ast.Call) else dec) in ("numba.njit", "njit", "numba.jit")
            for dec in node.decorator_list
        ):
            yield module, node


def _scalar(value: ast.expr) -> bool:
    return (
        isinstance(value, ast.Constant)
        or (isinstance(value, ast.UnaryOp) and isinstance(value.operand, ast.Constant))
        or ast.unparse(value) in ("np.nan", "np.inf", "-np.inf")
    )


def test_kernels_copy_arrays_element_by_element_and_solve_through_inv():
    # ARCHITECTURE.md, compiled kernels: an array assigned to a slice (x[:] = y) or np.linalg.solve makes
    # numba compile a message that formats shapes, 2 s of the warm-up for the first and 1 s for each
    # further shape. (An array assigned to a row by an integer index, X[s] = y, does too; the sources
    # cannot tell it from a number assigned to an element, so it is left to review.)
    found = []
    for module, kernel in _kernel_bodies():
        for node in ast.walk(kernel):
            sliced = isinstance(node, ast.Assign) and any(
                isinstance(t, ast.Subscript) and any(isinstance(s, ast.Slice) for s in ast.walk(t.slice))
                for t in node.targets
            )
            if sliced and not _scalar(node.value):
                found.append(f"raildyn/{module}:{node.lineno} {ast.unparse(node)}")
            if isinstance(node, ast.Call) and ast.unparse(node.func) == "np.linalg.solve":
                found.append(f"raildyn/{module}:{node.lineno} {ast.unparse(node)}")
    assert len({m for m, _ in _kernel_bodies()}) >= 7, "the numba functions were not found"
    assert not found, f"kernels that assign an array to a slice or call np.linalg.solve: {found}"


@pytest.mark.slow
def test_the_install_compiles_every_kernel_and_a_fresh_process_loads_them(binder_run):
    proc, out, work = binder_run
    assert proc.returncode == 0, out[-4000:]
    # postBuild's warm-up met an empty cache: it compiled everything and loaded nothing.
    assert " 0 loaded from the cache" in out, out[-3000:]

    # An index beside the installed sources for every cached function, and code beside each module's.
    (package,) = (work / "venv" / "lib").glob("python3*/site-packages/raildyn")
    missing = []
    for module, functions in _cached_functions().items():
        cached = package / module.parent / "__pycache__"
        names = [p.name for p in cached.glob(f"{module.stem}.*")] if cached.is_dir() else []
        indexed = {n.partition("-")[0] for n in names if n.endswith(".nbi")}
        missing += [f"{module}: {fn}" for fn in functions if f"{module.stem}.{fn}" not in indexed]
        assert any(n.endswith(".nbc") for n in names), f"no code cached for raildyn/{module}"
    assert not missing, f"the warm-up left these numba functions uncompiled: {missing}"

    (line,) = [line for line in out.splitlines() if line.startswith("first calls: ")]
    counts = json.loads(line.removeprefix("first calls: "))
    used = {name: c for name, c in counts["first"].items() if sum(c)}
    compiled = {name: c for name, c in used.items() if c[1]}
    assert not compiled, f"compiled again instead of loaded from the warm-up's cache: {compiled}"
    # The notebooks' first calls reached the kernels of each path: the engine, FASTSIM, the train, the bridge.
    for module in ("wheelset._engine", "contact._fastsim_kernel", "train._kernel", "bridge._kernel"):
        assert any(f"raildyn.{module}." in name for name in used), f"no kernel of {module} was loaded: {used}"
    loaded, recompiled = counts["all"]
    assert recompiled == 0 and loaded > 0, counts["all"]


def test_the_warm_up_shares_its_paths_among_processes(capsys):
    # `compile --jobs 2` (the Makefile's install): every path runs once, in one process or the other, and
    # the counts add up over both (here the install's cache is built, so they load what they can).
    from raildyn.__main__ import STEPS, main

    assert main(["compile", "--jobs", "2"]) == 0
    out = capsys.readouterr().out
    for label, _ in STEPS:
        assert out.count(f"s  {label}\n") == 1, out
    assert " kernels compiled, " in out and " loaded from the cache, for raildyn at " in out
    with pytest.raises(SystemExit):
        main(["compile", "--jobs", "0"])
    assert "--jobs must be an integer in [1, 64], got 0" in capsys.readouterr().err
