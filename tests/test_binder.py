"""The Binder configuration alone gives an environment in which the notebooks run (tests/binder_env.py).

The environment is built in the background from the session's first test (tests/background.py, started
by tests/conftest.py; ``binder_run``); the test waits for it and reads what it printed.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest
from packaging.specifiers import SpecifierSet

ROOT = Path(__file__).resolve().parents[1]


def _runtime() -> str:
    """The Python version binder/runtime.txt asks repo2docker for ("3.11")."""
    text = (ROOT / "binder" / "runtime.txt").read_text(encoding="utf-8").strip()
    # repo2docker reads one line "python-X.Y" (its documentation, "Specify a version of Python").
    match = re.fullmatch(r"python-(\d+\.\d+)", text)
    assert match, f"binder/runtime.txt must be one line 'python-X.Y', got {text!r}"
    return match.group(1)


def test_binder_python_satisfies_requires_python():
    # Without runtime.txt repo2docker builds its default Python (3.10 in 2024), and `pip install .` in
    # postBuild then fails against requires-python; the pinned version must be one pyproject accepts.
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    allowed = SpecifierSet(project["requires-python"])
    assert allowed.contains(_runtime()), (
        f"binder/runtime.txt asks for Python {_runtime()}, pyproject requires {allowed}"
    )


@pytest.mark.slow
def test_binder_configuration_alone_runs_notebook_01(binder_run):
    proc, out, work = binder_run
    assert proc.returncode == 0, out[-4000:]
    assert "notebook ran:" in out
    # raildyn came from the Binder environment's own install, not from this checkout.
    assert f"raildyn from {work / 'venv'}" in out
    # ... on the Python binder/runtime.txt asks for.
    assert f"python {_runtime()}" in out, out[-2000:]
