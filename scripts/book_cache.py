"""Keep the book's execution cache only while raildyn itself is unchanged.

Jupyter Book keeps each executed notebook in ``book/_build/.jupyter_cache``, keyed by the notebook's
code cells, so ``make book`` re-runs only the notebooks whose code changed. The key cannot see
raildyn's own files: after a change to a model, a cached notebook would show the old model's numbers.
So the cache carries a digest of raildyn's files and of the pinned ranges, and is emptied when they
no longer match. ``make book`` runs this before building; the tests' build starts from an empty cache
and leaves it stamped for the next ``make book``.

Usage: ``python scripts/book_cache.py [BUILD_DIR]`` (default book/_build).
"""

from __future__ import annotations

import hashlib
import shutil
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CACHE = ".jupyter_cache"
STAMP = ".raildyn-sources"


def digest() -> str:
    """A digest of every file of the raildyn package (compiled caches aside), of the ranges it is installed
    with (pyproject.toml) and of the versions it runs on (constraints.txt)."""
    files = [p for p in (ROOT / "raildyn").rglob("*") if p.is_file() and "__pycache__" not in p.parts]
    sha = hashlib.sha256()
    for path in sorted(files) + [ROOT / "pyproject.toml", ROOT / "constraints.txt"]:
        sha.update(str(path.relative_to(ROOT)).encode() + b"\0" + path.read_bytes() + b"\0")
    return sha.hexdigest()


def empty(build: Path) -> None:
    """Drop the cached notebooks, their stamp and Sphinx's record of what it read (``.doctrees``):
    the next build reads every page again and executes every notebook."""
    for folder in (CACHE, ".doctrees"):
        shutil.rmtree(build / folder, ignore_errors=True)
    (build / STAMP).unlink(missing_ok=True)


def stamp(build: Path) -> None:
    """Record that the cached notebooks ran on raildyn as it is now."""
    build.mkdir(parents=True, exist_ok=True)
    (build / STAMP).write_text(digest() + "\n")


def refresh(build: Path) -> bool:
    """Empty the cache if raildyn changed since it was filled, then stamp it; True if it was emptied."""
    stale = not (build / STAMP).exists() or (build / STAMP).read_text().strip() != digest()
    if stale:
        empty(build)
    stamp(build)
    return stale


if __name__ == "__main__":
    build = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "book" / "_build"
    if refresh(build):
        print("raildyn changed since the notebooks were cached: every notebook runs again")
