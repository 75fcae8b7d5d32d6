"""Shared test set-up: a display-free matplotlib that every test leaves as it found it."""

import matplotlib

matplotlib.use("Agg")

import os  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
from pathlib import Path  # noqa: E402

import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]

_DEFAULTS = dict(matplotlib.rcParams)


@pytest.fixture(autouse=True)
def _matplotlib_hygiene():
    """Close every figure after a test and fail it if it changed matplotlib's defaults."""
    yield
    plt.close("all")
    changed = sorted(k for k, v in matplotlib.rcParams.items() if k != "backend" and _DEFAULTS.get(k) != v)
    matplotlib.rcParams.update({k: _DEFAULTS[k] for k in changed})
    assert not changed, f"the test changed matplotlib rcParams: {changed}"


@pytest.fixture(scope="session")
def built_book():
    """Build the book once per session into book/_build, as ``make book`` does, warnings reported.

    Returns the finished process and the folder of the HTML pages.
    """
    jb = Path(sys.executable).parent / "jupyter-book"
    cmd = [
        str(jb),
        "build",
        ".",
        "--config",
        "book/_config.yml",
        "--toc",
        "book/_toc.yml",
        "--path-output",
        "book",
        "--all",
        "-W",
        "-n",
        "--keep-going",
    ]
    # As `make book`: no progress bars, which a page without a kernel would show frozen at 0 %.
    env = {**os.environ, "RAILDYN_PROGRESS": "0"}
    proc = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=900, env=env)
    return proc, ROOT / "book" / "_build" / "html"
