"""The test session's jobs of minutes, run apart from pytest's processes (``tests/conftest.py`` starts this).

With ``--book``: the book's build, as ``make book`` builds it but with warnings reported and every notebook
executed in a strict kernel (``STRICT``); then, from the built book, its printing (``scripts/book_pdf.py``,
where chromium is installed) and its student edition (``scripts/student_edition.py``) side by side. With
``--binder``: an environment built from the Binder configuration alone (``tests/binder_env.py``).

Each job has a folder under JOBS: what it printed in ``log.txt`` and, once it has ended, its exit status in
``rc`` ("skipped: why" where it did not run). The tests that read a job wait for its ``rc``
(``conftest._Job``), in whichever of pytest's processes they run; this process outlives the one that
started it, so that the worker which ran the validation page's checks may finish before the book is built.

Usage: ``python tests/background.py JOBS --book`` or ``... JOBS --binder``
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "scripts"))
import book_cache  # noqa: E402  (scripts/book_cache.py: the book's execution cache, kept while raildyn is unchanged)

BOOK_BUILD = [
    str(Path(sys.executable).parent / "jupyter-book"),
    *("build", ".", "--config", "book/_config.yml", "--toc", "book/_toc.yml", "--path-output", "book"),
    *("--all", "-W", "-n", "--keep-going"),
]

# Run first in every kernel the book's build starts (an IPython start-up file): any warning raised by
# raildyn, numpy or matplotlib becomes an error, so the executed notebooks that tests/test_notebooks.py
# reads ran strict. (The one exception is ipykernel's own notice at kernel shutdown, not the notebook's.)
STRICT = """import warnings
warnings.simplefilter("error")
warnings.filterwarnings("ignore", category=PendingDeprecationWarning, module="ipykernel")
"""


# The niceness of every process of the session but the book's chain (the build, its printing, its student
# edition: the session's longest run of steps one after another): tests/conftest.py lowers the tests' own
# to it, and the Binder environment runs at it.
YIELDING = 10


def start(jobs: Path, name: str, args: list[str], **popen) -> tuple[subprocess.Popen, Path]:
    """Start one job, its output in its folder's log.txt: (the process, the folder)."""
    folder = jobs / name
    folder.mkdir(parents=True, exist_ok=True)
    with (folder / "log.txt").open("w") as log:
        return subprocess.Popen(args, stdout=log, stderr=subprocess.STDOUT, **popen), folder


def finish(folder: Path, status: str) -> None:
    """Write a job's status in one step: a waiting test never reads half of it."""
    draft = folder / "rc.draft"
    draft.write_text(status)
    draft.replace(folder / "rc")


def skip(jobs: Path, name: str, why: str) -> None:
    """Mark a job as not run, and why (the test that reads it is skipped)."""
    folder = jobs / name
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "log.txt").write_text(why + "\n")
    finish(folder, f"skipped: {why}")


def build_book(jobs: Path) -> int:
    """The book's build into book/_build; what it ran is stamped as run on raildyn as it is now, so that a
    `make book` after the tests reuses it (the execution cache starts empty: every notebook runs here)."""
    ipython = Path(tempfile.mkdtemp(prefix="ipython-", dir=jobs))
    startup = ipython / "profile_default" / "startup"
    startup.mkdir(parents=True)
    (startup / "00-strict.py").write_text(STRICT)
    # As `make book`: no progress bars, which a page without a kernel would show frozen at 0 %.
    env = {**os.environ, "RAILDYN_PROGRESS": "0", "IPYTHONDIR": str(ipython)}
    book_cache.empty(ROOT / "book" / "_build")
    proc, folder = start(jobs, "book", BOOK_BUILD, cwd=ROOT, env=env)
    code = proc.wait()
    if code == 0:
        book_cache.stamp(ROOT / "book" / "_build")
    finish(folder, str(code))
    return code


def main(jobs: Path, job: str) -> None:
    running = []
    if job == "book":
        if build_book(jobs) != 0:
            for name in ("pdf", "student"):
                skip(jobs, name, "the book's build failed")
        else:
            html = ROOT / "book" / "_build" / "html"
            scripts = ROOT / "scripts"
            if Path("/usr/bin/chromium").exists():
                pdf = jobs / "pdf" / "raildyn.pdf"
                # printed, then its text read for tests/test_pdf.py (tests/pdf_text.py)
                running.append(
                    start(
                        jobs,
                        "pdf",
                        [sys.executable, str(ROOT / "tests" / "pdf_text.py"), str(html), str(pdf)],
                    )
                )
            else:
                skip(jobs, "pdf", "chromium is not installed: the book was not printed")
            student = [sys.executable, str(scripts / "student_edition.py"), str(ROOT / "book" / "_build"),
                       str(jobs / "student"), "-W", "-n", "--keep-going"]  # fmt: skip
            running.append(start(jobs, "student", student))
    else:
        os.nice(YIELDING)
        environment = [sys.executable, str(ROOT / "tests" / "binder_env.py"), str(jobs / "binder")]
        running.append(start(jobs, "binder", environment))
    for proc, folder in running:
        finish(folder, str(proc.wait()))


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[2] not in ("--book", "--binder"):
        sys.exit(__doc__.rpartition("Usage: ")[2])
    main(Path(sys.argv[1]), sys.argv[2].removeprefix("--"))
