"""Shared test set-up: a display-free matplotlib that every test leaves as it found it, the book built once,
and the record of every model checked against its independent reference, from which the book's validation
page is generated (``book/_generated/validation.json``, read by ``book/_ext/raildyn_book.py``)."""

import matplotlib

matplotlib.use("Agg")

import json  # noqa: E402
import os  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
from dataclasses import dataclass  # noqa: E402
from pathlib import Path  # noqa: E402

import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "scripts"))
import book_cache  # noqa: E402  (scripts/book_cache.py: the book's execution cache, kept while raildyn is unchanged)

_DEFAULTS = dict(matplotlib.rcParams)


@pytest.fixture(autouse=True)
def _matplotlib_hygiene():
    """Close every figure after a test and fail it if it changed matplotlib's defaults."""
    yield
    plt.close("all")
    changed = sorted(k for k, v in matplotlib.rcParams.items() if k != "backend" and _DEFAULTS.get(k) != v)
    matplotlib.rcParams.update({k: _DEFAULTS[k] for k in changed})
    assert not changed, f"the test changed matplotlib rcParams: {changed}"


# Run first in every kernel the book build starts (an IPython start-up file): any warning raised by
# raildyn, numpy or matplotlib becomes an error, so the executed notebooks that tests/test_notebooks.py
# reads ran strict. (The one exception is ipykernel's own notice at kernel shutdown, not the notebook's.)
STRICT = """import warnings
warnings.simplefilter("error")
warnings.filterwarnings("ignore", category=PendingDeprecationWarning, module="ipykernel")
"""


# -- the session's background jobs ---------------------------------------------------------------------
# Four jobs of minutes run in processes of their own while the tests go on: the book's build (started
# once the checks its validation page lists have run); from the built book, its printing (`make pdf`) and
# its student edition (`make book-student`); and an environment built from the Binder configuration
# alone. The tests that read a job's result wait for it.


@dataclass
class _Job:
    proc: subprocess.Popen
    work: Path  # the job's folder; what it printed is in work/log.txt

    def result(self, timeout: float = 1800) -> subprocess.CompletedProcess:
        """Wait for the job; its outcome, with everything it printed (both streams) as ``stdout``."""
        late = ""
        try:
            self.proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
            late = f"\n(stopped: still running after {timeout:.0f} s)"
        text = (self.work / "log.txt").read_text(errors="replace") + late
        return subprocess.CompletedProcess(self.proc.args, self.proc.returncode, text, "")


_JOBS: dict[str, _Job] = {}


def _start(name: str, args: list[str], work: Path, **popen) -> None:
    work.mkdir(parents=True, exist_ok=True)
    with (work / "log.txt").open("w") as log:
        _JOBS[name] = _Job(subprocess.Popen(args, stdout=log, stderr=subprocess.STDOUT, **popen), work)


BOOK_BUILD = [
    str(Path(sys.executable).parent / "jupyter-book"),
    *("build", ".", "--config", "book/_config.yml", "--toc", "book/_toc.yml", "--path-output", "book"),
    *("--all", "-W", "-n", "--keep-going"),
]


@pytest.fixture(scope="session")
def book_started(tmp_path_factory):
    """Start building the book into book/_build, as ``make book`` does, with warnings reported and every
    notebook executed in a strict kernel (``STRICT``). Every test after the validation page's checks asks
    for this (``pytest_collection_modifyitems``), so that the build runs beside them."""
    if "book" in _JOBS:
        return
    write_references()  # the validation page reads the checks recorded so far in this session
    # As `make book`: no progress bars, which a page without a kernel would show frozen at 0 %.
    ipython = tmp_path_factory.mktemp("ipython")
    startup = ipython / "profile_default" / "startup"
    startup.mkdir(parents=True)
    (startup / "00-strict.py").write_text(STRICT)
    env = {**os.environ, "RAILDYN_PROGRESS": "0", "IPYTHONDIR": str(ipython)}
    # Every notebook runs here, strict: the execution cache `make book` keeps starts empty, and what this
    # build ran is stamped as run on raildyn as it is now, so that a `make book` after the tests reuses it.
    book_cache.empty(ROOT / "book" / "_build")
    _start("book", BOOK_BUILD, tmp_path_factory.mktemp("build"), cwd=ROOT, env=env)


def _after_the_build() -> None:
    """Once the book is built: stamp its execution cache and start the jobs that follow it (once)."""
    global _FOLLOWED
    build = _JOBS.get("book")
    if _FOLLOWED or build is None or build.proc.poll() is None:
        return
    _FOLLOWED = True
    html = ROOT / "book" / "_build" / "html"
    scripts = ROOT / "scripts"

    def folder(name: str) -> Path:  # beside the build's, in the session's temporary folder
        return Path(tempfile.mkdtemp(prefix=f"{name}-", dir=build.work.parent))

    if build.proc.returncode == 0:
        book_cache.stamp(ROOT / "book" / "_build")
        if Path("/usr/bin/chromium").exists():
            pdf = folder("pdf")
            _start(
                "pdf",
                [sys.executable, str(scripts / "book_pdf.py"), str(html), str(pdf / "raildyn.pdf")],
                pdf,
            )
        student = folder("student")
        _start("student", [sys.executable, str(scripts / "student_edition.py"), str(ROOT / "book" / "_build"),
                           str(student), "-W", "-n", "--keep-going"], student)  # fmt: skip
    if _BINDER_WANTED:
        _start_binder(folder("binder"))


def _start_binder(work: Path) -> None:
    if "binder" not in _JOBS:
        _start("binder", [sys.executable, str(Path(__file__).with_name("binder_env.py")), str(work)], work)


_FOLLOWED = False  # whether the jobs that follow the build have been started
_BINDER_WANTED = False  # whether this session runs a test of the Binder environment


@pytest.fixture(scope="session")
def built_book(book_started):
    """The book, built: (the build's outcome, the folder of its HTML pages)."""
    proc = _JOBS["book"].result(timeout=900)
    _after_the_build()
    return proc, ROOT / "book" / "_build" / "html"


def _assert_built(built_book) -> None:
    proc, _ = built_book
    assert proc.returncode == 0, f"the book's build failed: {proc.stdout[-4000:]}"


@pytest.fixture(scope="session")
def printed_book(built_book):
    """The book printed by ``scripts/book_pdf.py`` in the background: (its outcome, its log, the PDF)."""
    _assert_built(built_book)
    if "pdf" not in _JOBS:
        pytest.skip("chromium is not installed: the book was not printed")
    job = _JOBS["pdf"]
    proc = job.result()
    return proc, proc.stdout, job.work / "raildyn.pdf"


@pytest.fixture(scope="session")
def student_book(built_book):
    """The student edition, built as ``make book-student`` builds it from the notebooks the book executed:
    (its outcome, the folder of its HTML pages)."""
    _assert_built(built_book)
    job = _JOBS["student"]
    return job.result(timeout=900), job.work / "_build" / "html"


@pytest.fixture(scope="session")
def binder_run(tmp_path_factory):
    """The environment built from the Binder configuration alone (tests/binder_env.py), waited for:
    (its outcome, what it printed, its folder). In a session that builds the book it was started, in the
    background, with the jobs that follow the build."""
    _start_binder(tmp_path_factory.mktemp("binder"))
    job = _JOBS["binder"]
    proc = job.result()
    return proc, proc.stdout, job.work


@pytest.hookimpl(tryfirst=True)
def pytest_runtest_setup(item):
    # Each test's start looks in on the book's build, so that the jobs that follow it start soon after it.
    _after_the_build()


# -- the validation page's record ------------------------------------------------------------------------

REFERENCES = ROOT / "book" / "_generated" / "validation.json"
_KINDS = ("closed form", "published", "python-control", "scipy", "finite elements", "independent model")
_RECORDED: dict[str, dict] = {}


@pytest.fixture
def reference(request):
    """Check a model against its independent reference, and record the check for the validation page.

    Call it as ``reference(chapter, model, against, kind, error, tolerance)``: the relative (or stated)
    error measured and the tolerance the test holds it to; it asserts ``error <= tolerance``. ``kind`` is
    one of ``_KINDS``. The page lists every such check with its numbers, so nothing on it is typed by hand.
    """
    calls = []

    def record(
        chapter: int, model: str, against: str, kind: str, error: float, tolerance: float, unit="rel."
    ):
        assert kind in _KINDS, f"kind must be one of {_KINDS}, got {kind!r}"
        error, tolerance = float(error), float(tolerance)
        key = f"{request.node.nodeid}#{len(calls)}"
        calls.append(key)
        _RECORDED[key] = dict(
            chapter=int(chapter), model=model, reference=against, kind=kind, error=error,
            tolerance=tolerance, unit=unit, within=bool(error <= tolerance), test=request.node.nodeid,
        )  # fmt: skip
        assert error <= tolerance, (
            f"{model} against {against}: error {error:.3g} above tolerance {tolerance:.3g}"
        )

    return record


def write_references() -> None:
    """Merge this session's checks into the record; drop those of test files that no longer exist."""
    if not _RECORDED:
        return
    old = json.loads(REFERENCES.read_text()) if REFERENCES.exists() else {}
    kept = {k: v for k, v in old.items() if (ROOT / k.split("::")[0]).exists()}
    REFERENCES.parent.mkdir(parents=True, exist_ok=True)
    REFERENCES.write_text(json.dumps({**kept, **_RECORDED}, indent=1, sort_keys=True))


# Under `pytest -n`, the file in which the workers write each test's group for the controller's scheduler.
GROUPS = "RAILDYN_TEST_GROUPS"


def _book_rank(item) -> int | None:
    """Where a test of the book's group runs within it: the checks its validation page lists (0), the
    built book (1), the student edition and the Binder environment (2), the printed book (3), the last
    three made in the background meanwhile; None for a test outside the group."""
    names = getattr(item, "fixturenames", ())
    if "printed_book" in names:
        return 3
    if "binder_run" in names or "student_book" in names:
        return 2
    if "built_book" in names:
        return 1
    return 0 if "reference" in names else None


def _group(item) -> str:
    """The tests that must run in one process, in order: the book's, the lecture-room app's (one Voilà
    server), a file's whose tests share a module-wide fixture (computed once), or else the test alone."""
    if _book_rank(item) is not None:
        return "book"
    if "voila_app" in getattr(item, "fixturenames", ()):
        return "app"
    info = getattr(item, "_fixtureinfo", None)
    defs = info.name2fixturedefs.values() if info else ()
    shared = any(d[-1].scope in ("package", "module", "class") for d in defs)
    return item.nodeid.split("::")[0] if shared else item.nodeid


def pytest_itemcollected(item):
    # before `-m` selects: `pytest -m reference` runs the reference checks alone
    if "reference" in getattr(item, "fixturenames", ()):
        item.add_marker(pytest.mark.reference)


@pytest.hookimpl(trylast=True)  # after `-m` and `-k` have deselected: only the tests that will run
def pytest_collection_modifyitems(config, items):
    """Order the tests.

    Two groups hold a process for minutes: the book's (its checks, then the tests that read the built
    book, in ``_book_rank``'s order) and the lecture-room app's. Under ``pytest -n`` they go first, so
    that they start at once, each on one worker, while the other workers share the rest as they come free
    (``pytest_xdist_make_scheduler``). In one process the book's checks go first, then the app's tests,
    then every other test, each asking for the book's build to start, and the tests that read the book
    go last, so that the build and the jobs that follow it run beside the rest.
    """
    global _BINDER_WANTED
    _BINDER_WANTED = any("binder_run" in getattr(item, "fixturenames", ()) for item in items)
    one_process = not getattr(config.option, "numprocesses", None) and not os.environ.get(
        "PYTEST_XDIST_WORKER"
    )
    book = lambda item: _book_rank(item) is not None  # noqa: E731
    if one_process:
        if any((_book_rank(item) or 0) > 0 for item in items):
            for item in items:  # (the doctests of raildyn/ see no fixture of this file)
                if _book_rank(item) != 0 and Path(item.path).is_relative_to(ROOT / "tests"):
                    item.fixturenames.append("book_started")
        # stable: within each group the tests keep the order they were collected in
        items.sort(key=lambda item: (0, 0) if _book_rank(item) == 0 else (3, _book_rank(item)) if book(item)
                   else (1 if _group(item) == "app" else 2, 0))  # fmt: skip
        return
    items.sort(key=lambda item: (0, _book_rank(item)) if book(item) else
               (1 if _group(item) == "app" else 2, 0))  # fmt: skip
    if os.environ.get(GROUPS) and os.environ.get("PYTEST_XDIST_WORKER"):
        # a worker of `pytest -n` tells the controller each test's group (every worker, the same map)
        path = Path(os.environ[GROUPS])
        draft = path.with_name(f"{os.environ['PYTEST_XDIST_WORKER']}.json")
        draft.write_text(json.dumps({item.nodeid: _group(item) for item in items}))
        draft.replace(path)


def pytest_configure(config):
    if getattr(config.option, "numprocesses", None) and not hasattr(config, "workerinput"):
        os.environ[GROUPS] = str(Path(tempfile.mkdtemp(prefix="raildyn-groups-")) / "groups.json")


@pytest.hookimpl(tryfirst=True)
def pytest_xdist_make_scheduler(config, log):
    """pytest-xdist's scheduling by scope, the scope being a test's group (``_group``): each group goes
    whole to one worker, in the order of the collection (``--no-loadscope-reorder``). (pytest-xdist's own
    ``--dist loadgroup`` renames the tests in a way pytest 9.2 no longer reads, so it groups nothing.)"""
    from xdist.scheduler import LoadScopeScheduling

    class ByGroup(LoadScopeScheduling):
        groups: dict[str, str] | None = None

        def _split_scope(self, nodeid: str) -> str:
            if self.groups is None:  # written by the workers as they collected, before they reported
                self.groups = json.loads(Path(os.environ[GROUPS]).read_text())
            return self.groups.get(nodeid, nodeid.split("::")[0])

    return ByGroup(config, log)


def pytest_sessionfinish(session, exitstatus):
    write_references()
    for job in _JOBS.values():  # a session stopped early leaves nothing running behind
        if job.proc.poll() is None:
            job.proc.kill()
