"""The Binder configuration alone gives an environment in which the notebooks run.

A fresh virtual environment stands in for repo2docker's default one (Python with Jupyter's kernel and
nbclient), ``binder/postBuild`` installs raildyn into it, and notebook 01 runs there from
``notebooks/``, in a copy of the repository made from git, so that nothing of this checkout's own
environment leaks in.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

RUN = """
import nbformat
from nbclient import NotebookClient

nb = nbformat.read("01_analysis_of_dynamic_systems.ipynb", as_version=4)
NotebookClient(nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": "."}}).execute()
print("ran", sum(c.cell_type == "code" for c in nb.cells), "code cells")
"""


@pytest.mark.slow
def test_binder_configuration_alone_runs_notebook_01(tmp_path):
    repo = tmp_path / "repo"
    subprocess.run(["git", "clone", "-q", str(ROOT), str(repo)], check=True)
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    bin_ = venv / "bin"
    env = {k: v for k, v in os.environ.items() if k not in ("VIRTUAL_ENV", "PYTHONPATH", "MPLCONFIGDIR")}
    env["PATH"] = f"{bin_}{os.pathsep}{env['PATH']}"
    env["RAILDYN_PROGRESS"] = "0"
    # What repo2docker's base environment brings: a Jupyter kernel and a way to run notebooks.
    base = ["ipykernel>=6.29,<8", "nbclient>=0.10,<0.11", "nbformat>=5.10,<6"]
    subprocess.run([bin_ / "python", "-m", "pip", "install", "-q", *base], check=True, env=env)
    subprocess.run(["bash", "binder/postBuild"], cwd=repo, check=True, env=env, capture_output=True)
    proc = subprocess.run(
        [bin_ / "python", "-c", RUN], cwd=repo / "notebooks", env=env, capture_output=True, text=True
    )
    assert proc.returncode == 0, proc.stderr[-4000:]
    assert "ran" in proc.stdout
    # The environment is the Binder one, not this checkout's: raildyn comes from the copy's install.
    where = subprocess.run(
        [bin_ / "python", "-c", "import raildyn; print(raildyn.__file__)"],
        cwd=tmp_path, env=env, capture_output=True, text=True, check=True,
    )  # fmt: skip
    assert str(venv) in where.stdout
