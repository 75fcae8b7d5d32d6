"""Build the student edition of the book: the same pages with every worked answer removed.

``make book-student`` runs this after ``make book``. The instructor's book folds each worked answer
(a notebook cell tagged ``hide-cell``) under its question; a lecturer who hands the book out as
homework wants them gone, code, reasoning and output alike. The notebooks are not executed again:
the edition starts from the notebooks as ``make book`` executed them (``jupyter_execute/`` of the
build), drops their answer cells, and builds the book from those with execution off. Everything else
(the text, the figures, the kernel-free widgets, the self-checks that answer in the page) is as in the
instructor's book.

Usage: ``python scripts/student_edition.py [BUILD_DIR] [OUT_DIR] [jupyter-book options]`` (defaults:
book/_build, book/_build/student; the pages land in OUT_DIR/_build/html).
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
# The tag of a worked answer (tests/test_notebooks.py holds every answer to it).
ANSWER_TAG = "hide-cell"
TITLE_SUFFIX = " (student edition)"


def student_notebook(executed: Path, out: Path) -> int:
    """Write ``executed`` without its worked answers to ``out``; returns the number of answers removed."""
    import nbformat

    nb = nbformat.read(executed, as_version=4)
    kept = [c for c in nb.cells if ANSWER_TAG not in c.metadata.get("tags", [])]
    removed = len(nb.cells) - len(kept)
    nb.cells = kept
    nbformat.write(nb, out)
    return removed


def source_tree(build: Path, tree: Path) -> int:
    """Lay out the edition's sources in ``tree`` (the book's folder, the answerless notebooks, a config
    with execution off); returns the number of answers removed."""
    import yaml

    executed = build / "jupyter_execute" / "notebooks"
    notebooks = sorted((ROOT / "notebooks").glob("*.ipynb"))
    missing = [p.name for p in notebooks if not (executed / p.name).exists()]
    if missing:
        raise SystemExit(f"{executed} lacks the executed notebooks {missing}: run `make book` first")
    if tree.exists():
        shutil.rmtree(tree)
    shutil.copytree(ROOT / "book", tree / "book", ignore=shutil.ignore_patterns("_build"))
    (tree / "notebooks").mkdir(parents=True)
    removed = sum(student_notebook(executed / p.name, tree / "notebooks" / p.name) for p in notebooks)
    config = yaml.safe_load((ROOT / "book" / "_config.yml").read_text(encoding="utf-8"))
    config["title"] += TITLE_SUFFIX
    config["execute"]["execute_notebooks"] = "off"
    (tree / "book" / "_config.yml").write_text(yaml.safe_dump(config, sort_keys=False), encoding="utf-8")
    return removed


def build_edition(build: Path, out: Path, options: list[str]) -> subprocess.CompletedProcess:
    """Build the student edition's pages into ``out``/_build/html from the instructor's ``build``."""
    tree = out / "source"
    removed = source_tree(build, tree)
    print(f"student edition: {removed} worked answers removed", flush=True)
    jupyter_book = Path(sys.executable).parent / "jupyter-book"
    cmd = [str(jupyter_book), "build", str(tree), "--config", str(tree / "book" / "_config.yml")]
    cmd += ["--toc", str(tree / "book" / "_toc.yml"), "--path-output", str(out), *options]
    return subprocess.run(cmd, cwd=tree, capture_output=True, text=True, timeout=900)


def main(argv: list[str]) -> None:
    build = Path(argv[0]) if argv else ROOT / "book" / "_build"
    out = Path(argv[1]) if len(argv) > 1 else build / "student"
    proc = build_edition(build.resolve(), out.resolve(), argv[2:])
    sys.stdout.write(proc.stdout[-3000:] + proc.stderr[-3000:])
    if proc.returncode:
        raise SystemExit(proc.returncode)
    print(f"The student edition is at {out.resolve() / '_build' / 'html' / 'index.html'}")


if __name__ == "__main__":
    main(sys.argv[1:])
