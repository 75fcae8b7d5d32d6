"""Shared test set-up: a display-free matplotlib that every test leaves as it found it, the book built once,
and the record of every model checked against its independent reference, from which the book's validation
page is generated (``book/_generated/validation.json``, read by ``book/_ext/raildyn_book.py``)."""

import gc

import matplotlib

matplotlib.use("Agg")

# Collecting imports every module of raildyn and its dependencies, over a million objects that all
# live to the end: the cycle collector would scan the growing heap again and again for garbage there
# is none of (a grammar built at import, jsonschema's, took 5 s instead of 1 s in a worker). It runs
# again once the tests are collected (pytest_collection_finish), and at once in the controller of
# `pytest -n`, which collects none (pytest_configure).
gc.disable()

import atexit  # noqa: E402
import contextlib  # noqa: E402
import json  # noqa: E402
import os  # noqa: E402
import signal  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from dataclasses import dataclass  # noqa: E402
from pathlib import Path  # noqa: E402

import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402
from background import YIELDING  # noqa: E402  (tests/background.py: the session's background jobs)

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


# -- the session's background jobs ---------------------------------------------------------------------
# Four jobs of minutes run beside the tests, in processes of their own (tests/background.py): the book's
# build, started as soon as the checks its validation page lists have run, and from the built book its
# printing (`make pdf`) and its student edition (`make book-student`); and, from the session's first test,
# an environment built from the Binder configuration alone. Their folders are in one place for every
# process of the session (``RAILDYN_TEST_JOBS``), so that a test reads a job's result in whichever process
# it runs.

JOBS = "RAILDYN_TEST_JOBS"
BACKGROUND = Path(__file__).with_name("background.py")
# What the collected tests ask for, and whether this process has lowered its priority yet.
_SESSION = {"readers": False, "references": False, "binder": False, "yielded": False}
_LAUNCHED: set[str] = set()  # the jobs this process has seen started


@dataclass
class _Job:
    name: str

    @property
    def work(self) -> Path:
        """The job's folder: what it printed is in work/log.txt, its exit status in work/rc once it ended."""
        return Path(os.environ[JOBS]) / self.name

    def result(self, timeout: float = 1800) -> subprocess.CompletedProcess:
        """Wait for the job; its outcome, with everything it printed (both streams) as ``stdout``.

        A job that did not run (``rc`` "skipped: why") skips the test that asked for it."""
        rc = self.work / "rc"
        deadline = time.monotonic() + timeout
        while not rc.exists():
            if time.monotonic() > deadline:
                pytest.fail(f"the background job {self.name!r} did not end within {timeout:.0f} s")
            driver = self.work.with_name("binder" if self.name == "binder" else "book")  # who runs it
            pid = driver.with_suffix(".pid")
            if pid.exists() and not _alive(int(pid.read_text())) and not rc.exists():
                log = driver.with_suffix(".log").read_text(errors="replace")[-3000:]
                pytest.fail(f"tests/background.py ended without ending the job {self.name!r}: {log}")
            time.sleep(0.5)
        status = rc.read_text()
        if status.startswith("skipped: "):
            pytest.skip(status.removeprefix("skipped: "))
        text = (self.work / "log.txt").read_text(errors="replace")
        return subprocess.CompletedProcess(self.name, int(status), text, "")


def _alive(pid: int) -> bool:
    """Whether a process runs (on Linux, a zombie, ended but not reaped, does not)."""
    try:
        os.kill(pid, 0)
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0] != "Z"
    except ProcessLookupError:
        return False
    except FileNotFoundError:  # no /proc: the process exists
        return True


def _launch(job: str) -> None:
    """Start tests/background.py on a job ("book" or "binder") unless a process of this session already did
    (the first to make the folder ``<job>.started`` starts it)."""
    if job in _LAUNCHED:
        return
    _LAUNCHED.add(job)
    base = Path(os.environ[JOBS])
    try:
        (base / f"{job}.started").mkdir()
    except FileExistsError:
        return
    if job == "book":
        write_references()  # the validation page reads the checks recorded so far in this session
    # Through a shell that leaves it running in the background and ends: the job is nobody's child here,
    # so it outlives the process that started it (a worker of `pytest -n` may end first), in a session of
    # its own (its process group, which the session's end stops if it still runs).
    started = subprocess.run(
        ["sh", "-c", 'exec "$@" > "$0" 2>&1 & echo $!', str(base / f"{job}.log"), sys.executable,
         str(BACKGROUND), str(base), f"--{job}"],
        capture_output=True, text=True, check=True, start_new_session=True,
    )  # fmt: skip
    (base / f"{job}.pid").write_text(started.stdout.strip())


@pytest.fixture(scope="session")
def built_book():
    """The book, built: (the build's outcome, the folder of its HTML pages). In a session with the
    validation page's checks, the process that ran the last of them started the build."""
    if not _SESSION["references"]:
        _launch("book")
    return _Job("book").result(timeout=1200), ROOT / "book" / "_build" / "html"


def _assert_built(built_book) -> None:
    proc, _ = built_book
    assert proc.returncode == 0, f"the book's build failed: {proc.stdout[-4000:]}"


@pytest.fixture(scope="session")
def printed_book(built_book):
    """The book printed by ``scripts/book_pdf.py`` in the background, its text then read by
    ``tests/pdf_text.py``: (its outcome, its log, the PDF)."""
    _assert_built(built_book)
    job = _Job("pdf")
    proc = job.result()
    return proc, proc.stdout, job.work / "raildyn.pdf"


@pytest.fixture(scope="session")
def student_book(built_book):
    """The student edition, built as ``make book-student`` builds it from the notebooks the book executed:
    (its outcome, the folder of its HTML pages)."""
    _assert_built(built_book)
    job = _Job("student")
    return job.result(timeout=900), job.work / "_build" / "html"


@pytest.fixture(scope="session")
def binder_run():
    """The environment built from the Binder configuration alone (tests/binder_env.py), waited for:
    (its outcome, what it printed, its folder). The session's first test started it."""
    _launch("binder")
    job = _Job("binder")
    proc = job.result(timeout=2400)
    return proc, proc.stdout, job.work


# The tests' own processes lower their priority to background.YIELDING once the book's build may run, so
# that the other tests take up what the build's chain leaves. (Where Linux shares the processor among
# sessions before processes, autogroup, niceness counts only within the tests' session: the build's
# kernels, each in a session of its own, then share the machine evenly with it; on this 2-core machine
# the build took 290-340 s beside the tests, 177 s alone.)


def pytest_runtest_setup(item):
    # The Binder environment takes minutes and needs nothing of the tests: it starts with the first test.
    if _SESSION["binder"]:
        _launch("binder")
    # A process that will not start the book's build gives way to it (a process can only lower its own
    # priority, and what it starts inherits it: the process that starts the build lowers it after).
    if _book_rank(item) != 0 and not _SESSION["yielded"]:
        _SESSION["yielded"] = True
        os.nice(YIELDING)


def pytest_runtest_teardown(item, nextitem):
    # The last of the validation page's checks starts the book's build (tests run in _order's order).
    if _SESSION["readers"] and _book_rank(item) == 0 and (nextitem is None or _book_rank(nextitem) != 0):
        _launch("book")


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
    """For a test of the book's or of a background job: the checks the validation page lists (0), the
    built book (1), the student edition and the Binder environment (2), the printed book (3), the last
    three made in the background meanwhile; None for any other test."""
    names = getattr(item, "fixturenames", ())
    if "printed_book" in names:
        return 3
    if "binder_run" in names or "student_book" in names:
        return 2
    if "built_book" in names:
        return 1
    return 0 if "reference" in names else None


def _group(item) -> str:
    """The tests that must run in one process, in order: the validation page's checks, the lecture-room
    app's (one Voilà server), those marked ``shares(key)`` with one key (their model runs are cached in
    the process, so they are made once), a file's whose tests share a module-wide fixture (computed once),
    or else the test alone."""
    if _book_rank(item) == 0:
        return "references"
    if "voila_app" in getattr(item, "fixturenames", ()):
        return "app"
    shares = item.get_closest_marker("shares")
    if shares:
        return f"shares {shares.args[0]}"
    info = getattr(item, "_fixtureinfo", None)
    defs = info.name2fixturedefs.values() if info else ()
    shared = any(d[-1].scope in ("package", "module", "class") for d in defs)
    return item.nodeid.split("::")[0] if shared else item.nodeid


def _order(item) -> tuple[int, int]:
    """The validation page's checks, the app's tests, the others, and last those that read the book.
    Among the others, the groups that go whole to one worker (a file's, a ``shares`` key's) come before
    the tests that go one at a time: the longer pieces first, so that the short ones fill the workers'
    ends evenly."""
    rank = _book_rank(item)
    if rank:
        return 3, rank
    group = _group(item)
    return {"references": 0, "app": 1}.get(group, 2), int("::" in group or group.startswith("shares "))


def pytest_itemcollected(item):
    # before `-m` selects: `pytest -m reference` runs the reference checks alone
    if "reference" in getattr(item, "fixturenames", ()):
        item.add_marker(pytest.mark.reference)


@pytest.hookimpl(trylast=True)  # after `-m` and `-k` have deselected: only the tests that will run
def pytest_collection_modifyitems(config, items):
    """Order the tests (``_order``): the validation page's checks, whose last one starts the book's build
    in the background; the lecture-room app's tests; every other test; and last the tests that read the
    book and the jobs that follow its build, in ``_book_rank``'s order. Under ``pytest -n`` each of the
    first two groups goes whole to one worker, the other tests a file or a test at a time
    (``_group``), to whichever worker comes free (``pytest_xdist_make_scheduler``).
    """
    _SESSION["readers"] = any((_book_rank(item) or 0) > 0 for item in items)
    _SESSION["references"] = any(_book_rank(item) == 0 for item in items)
    _SESSION["binder"] = any("binder_run" in getattr(item, "fixturenames", ()) for item in items)
    items.sort(key=_order)  # stable: within each group the tests keep the order they were collected in
    if os.environ.get(GROUPS) and os.environ.get("PYTEST_XDIST_WORKER"):
        # a worker of `pytest -n` tells the controller each test's group (every worker, the same map)
        path = Path(os.environ[GROUPS])
        draft = path.with_name(f"{os.environ['PYTEST_XDIST_WORKER']}.json")
        draft.write_text(json.dumps({item.nodeid: _group(item) for item in items}))
        draft.replace(path)


def pytest_collection_finish(session):
    # The objects of the collected modules, frozen, are left out of the cycle collector's scans. The
    # tests' own long-lived objects (caches, hypothesis's examples) still grow by hundreds of
    # thousands: a full collection every hundred middle ones (Python's default is ten) scans them a
    # tenth as often. Measured in a worker of `make test-fast`: 5.4-5.9 s of full collections before,
    # 2.3-3.3 s after.
    gc.collect()
    gc.freeze()
    gc.set_threshold(700, 10, 100)
    gc.enable()


@pytest.hookimpl(trylast=True)  # after pytest's own set-up of its temporary folders
def pytest_configure(config):
    if hasattr(config, "workerinput"):
        # A worker of `pytest -n`: the controller set the session's folders in the environment. Its
        # interpreter's teardown, freeing what some two thousand tests built, takes 4-6 s of the machine
        # after its last report, and the controller waits for it; once the exit handlers registered
        # during the session have run, the worker ends at once.
        atexit.register(_end_at_once)
        return
    if getattr(config.option, "numprocesses", None):
        gc.enable()  # the controller of `pytest -n` collects no tests: no pytest_collection_finish here
        os.environ[GROUPS] = str(Path(tempfile.mkdtemp(prefix="raildyn-groups-")) / "groups.json")
    # The jobs' folders in the session's temporary folder, which pytest clears a few sessions later.
    factory = getattr(config, "_tmp_path_factory", None)
    base = (
        factory.mktemp("jobs", numbered=False) if factory else Path(tempfile.mkdtemp(prefix="raildyn-jobs-"))
    )
    os.environ[JOBS] = str(base)


def _end_at_once() -> None:
    """End this process now, its streams flushed, without the interpreter's teardown."""
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0)


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
    if hasattr(session.config, "workerinput"):
        return  # the jobs outlive a worker: another may be waiting for them
    for pid in Path(os.environ[JOBS]).glob("*.pid"):  # a session stopped early leaves nothing running behind
        with contextlib.suppress(ProcessLookupError):
            os.killpg(os.getpgid(int(pid.read_text())), signal.SIGKILL)
