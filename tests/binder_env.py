"""Build an environment from the Binder configuration alone and run notebook 01 in it.

A fresh virtual environment stands in for repo2docker's (the Python that ``binder/runtime.txt`` asks
for, with Jupyter's kernel and nbclient), ``binder/postBuild`` installs raildyn into it, and notebook
01 runs there from ``notebooks/`` through ``binder/start`` (as every launch does), in a clone of the
repository, so that nothing of this checkout's own environment leaks in. ``tests/background.py`` runs
this script from the test session's first test (the installation and the kernels' compilation
take minutes), and the tests of ``tests/test_binder.py`` and ``tests/test_warm.py`` read
what it printed.

Usage: ``python tests/binder_env.py WORKDIR`` → prints what postBuild printed, ``notebook ran``, numba's
counts of the first compiled calls (``first calls: {...}``), ``raildyn from <path>`` and ``python X.Y``.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

RUN = """
import nbformat
from nbclient import NotebookClient

nb = nbformat.read("01_analysis_of_dynamic_systems.ipynb", as_version=4)
NotebookClient(nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": "."}}).execute()
print("notebook ran:", sum(c.cell_type == "code" for c in nb.cells), "code cells")
"""

# What repo2docker's base environment brings: a Jupyter kernel and a way to run notebooks.
BASE = ["ipykernel>=6.29,<8", "nbclient>=0.10,<0.12", "nbformat>=5.10,<6"]


def _runtime_python() -> str:
    """The interpreter of the version binder/runtime.txt names ("python-3.11" → python3.11)."""
    runtime = (ROOT / "binder" / "runtime.txt").read_text(encoding="utf-8").strip()
    version = re.fullmatch(r"python-(\d+\.\d+)", runtime)
    if not version:
        sys.exit(f"binder/runtime.txt must be one line 'python-X.Y', got {runtime!r}")
    if f"{sys.version_info.major}.{sys.version_info.minor}" == version.group(1):
        return sys.executable
    found = shutil.which(f"python{version.group(1)}")
    if not found:
        sys.exit(f"binder/runtime.txt asks for Python {version.group(1)}, which this machine does not have")
    return found


def main(work: Path) -> None:
    repo, venv = work / "repo", work / "venv"
    subprocess.run(["git", "clone", "-q", str(ROOT), str(repo)], check=True)
    subprocess.run([_runtime_python(), "-m", "venv", str(venv)], check=True)
    bin_ = venv / "bin"
    env = {k: v for k, v in os.environ.items() if k not in ("VIRTUAL_ENV", "PYTHONPATH", "MPLCONFIGDIR")}
    env["PATH"] = f"{bin_}{os.pathsep}{env['PATH']}"
    env["RAILDYN_PROGRESS"] = "0"
    env["PIP_NO_COMPILE"] = "1"  # no byte-compiling at install: less CPU taken from the tests running beside
    subprocess.run([bin_ / "python", "-m", "pip", "install", "-q", *BASE], check=True, env=env)
    # postBuild installs raildyn and compiles its kernels into a cache that starts empty: what it prints
    # (how many kernels it compiled, how many it loaded) is read by tests/test_warm.py.
    subprocess.run(["bash", "binder/postBuild"], cwd=repo, check=True, env=env)
    start = ["bash", str(repo / "binder" / "start")]  # what every launch runs through
    subprocess.run([*start, bin_ / "python", "-c", RUN], cwd=repo / "notebooks", env=env, check=True)
    # A fresh process of the launched environment makes the notebooks' first compiled calls
    # (tests/test_warm.py holds numba's counts: every kernel loaded from postBuild's cache, none compiled).
    first_calls = (ROOT / "tests" / "first_calls.py").read_text(encoding="utf-8")
    subprocess.run([*start, bin_ / "python", "-c", first_calls], cwd=work, env=env, check=True)
    subprocess.run(
        [bin_ / "python", "-c", "import sys, raildyn; print('raildyn from', raildyn.__file__); "
         "print(f'python {sys.version_info.major}.{sys.version_info.minor}')"],
        cwd=work, env=env, check=True,
    )  # fmt: skip


if __name__ == "__main__":
    main(Path(sys.argv[1]))
