"""The book's build: from nothing, and again after one notebook's code changed.

Both builds run ``make book`` in a copy of the repository's files (so the checkout's own build is left
alone), with this environment (``VENV``; the install step is not remade). The clean build executes every
notebook; the rebuild, after a comment is added to one code cell of the slowest notebook (chapter 7),
executes that notebook alone (Jupyter Book's execution cache) and rewrites the pages that changed. The
baseline of the clean build is the notebooks alone executed one after another by nbclient (no Sphinx),
so its ratio says what the book adds to running them; the baseline of the rebuild is the clean build.
A third row gives the slowest notebook's execution in the clean build (as the book's cache recorded it,
numba's cache as the install leaves it: a fresh clone's first run), beside the same notebook alone.
One repeat each: a clean build takes minutes.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from benchmarks.common import Case

ROOT = Path(__file__).resolve().parents[1]
VENV = Path(sys.executable).parent.parent
EDITED = "notebooks/07_lateral_stability.ipynb"


def _copy_of_repository() -> Path:
    """The repository's tracked files, times kept, in a new folder (the Makefile compares times)."""
    tree = Path(tempfile.mkdtemp(prefix="raildyn-book-bench-"))
    files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True)
    for name in files.stdout.splitlines():
        (tree / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(ROOT / name, tree / name)
    return tree


def _make_book(tree: Path) -> float:
    stamp = VENV / ".installed-stamp"
    start = time.perf_counter()
    subprocess.run(
        ["make", "-C", str(tree), "book", f"VENV={VENV}", "-o", str(stamp)],
        check=True, capture_output=True, env={**os.environ, "MPLCONFIGDIR": str(tree / ".mpl")},
    )  # fmt: skip
    return time.perf_counter() - start


def _edit_one_notebook(tree: Path) -> None:
    import nbformat

    nb = nbformat.read(tree / EDITED, as_version=4)
    cell = next(c for c in nb.cells if c.cell_type == "code" and "import" in c.source)
    cell.source += "\n# edited"
    nbformat.write(nb, tree / EDITED)


def _execute_alone(tree: Path) -> dict[str, float]:
    """Each notebook executed by nbclient, one after another, no book: seconds by notebook name."""
    import nbformat
    from nbclient import NotebookClient

    seconds = {}
    for path in sorted((tree / "notebooks").glob("*.ipynb")):
        nb = nbformat.read(path, as_version=4)
        start = time.perf_counter()
        NotebookClient(nb, timeout=300, resources={"metadata": {"path": str(path.parent)}}).execute()
        seconds[path.name] = time.perf_counter() - start
    return seconds


def _executed_in_the_build(tree: Path) -> dict[str, float]:
    """The execution time the book's cache recorded for each notebook: seconds by notebook name."""
    from jupyter_cache import get_cache

    cache = get_cache(str(tree / "book" / "_build" / ".jupyter_cache"))
    return {Path(r.uri).name: r.data["execution_seconds"] for r in cache.list_cache_records()}


def cases(repeats: int):
    tree = _copy_of_repository()
    try:
        clean = _make_book(tree)
        executed = _executed_in_the_build(tree)
        _edit_one_notebook(tree)
        again = _make_book(tree)
        alone = _execute_alone(tree)
    finally:
        shutil.rmtree(tree, ignore_errors=True)
    slowest = max(executed, key=executed.get)
    return [
        Case("the book built from nothing (every notebook executed)", [clean], [sum(alone.values())],
             "≤ 4 min", "the 11 notebooks executed alone (nbclient, no book)"),
        Case("the book rebuilt after one code cell of chapter 7 changed", [again], [clean], "≤ 60 s",
             "the book built from nothing"),
        Case(f"the slowest notebook's execution in that build ({slowest}; numba's cache built)",
             [executed[slowest]], [alone[slowest]], "≤ 30 s", "the same notebook executed alone (nbclient)"),
    ]  # fmt: skip
