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


@pytest.fixture(scope="session")
def built_book(tmp_path_factory):
    """Build the book once per session into book/_build, as ``make book`` does, warnings reported,
    every notebook executed in a strict kernel (``STRICT``).

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
    write_references()  # the validation page reads the checks recorded so far in this session
    # As `make book`: no progress bars, which a page without a kernel would show frozen at 0 %.
    ipython = tmp_path_factory.mktemp("ipython")
    startup = ipython / "profile_default" / "startup"
    startup.mkdir(parents=True)
    (startup / "00-strict.py").write_text(STRICT)
    env = {**os.environ, "RAILDYN_PROGRESS": "0", "IPYTHONDIR": str(ipython)}
    # Every notebook runs here, strict: the execution cache `make book` keeps starts empty, and what this
    # build ran is stamped as run on raildyn as it is now, so that a `make book` after the tests reuses it.
    build = ROOT / "book" / "_build"
    book_cache.empty(build)
    proc = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=900, env=env)
    if proc.returncode == 0:
        book_cache.stamp(build)
    html = build / "html"
    if proc.returncode == 0 and Path("/usr/bin/chromium").exists():
        # `make pdf`'s printing (a minute or two of chromium) starts now, in the background, so that it
        # overlaps the other tests of the built book; tests/test_pdf.py waits for it (``printed_book``).
        out = tmp_path_factory.mktemp("pdf") / "raildyn.pdf"
        log = (out.parent / "log.txt").open("w")
        script = ROOT / "scripts" / "book_pdf.py"
        _PDF.update(out=out, log=log, proc=subprocess.Popen(
            [sys.executable, str(script), str(html), str(out)], stdout=log, stderr=subprocess.STDOUT
        ))  # fmt: skip
    return proc, html


_PDF: dict = {}


@pytest.fixture(scope="session")
def printed_book(built_book):
    """The book printed by ``scripts/book_pdf.py`` in the background: (finished process, its log, the PDF)."""
    if not _PDF:
        pytest.skip("the book was not printed (its build failed, or chromium is missing)")
    _PDF["proc"].wait(timeout=1800)
    _PDF["log"].close()
    return _PDF["proc"], (_PDF["out"].parent / "log.txt").read_text(), _PDF["out"]


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


_BINDER: dict = {}


@pytest.fixture(scope="session")
def background_jobs(request):
    """Start the session's long background job, the Binder environment (minutes of installing), if its
    test is to run. Every test of the book's group asks for it, so the job starts with the first of them,
    on the one process that runs that group (``pytest -n``: one worker; alone: the session)."""
    wanted = any("binder_run" in getattr(item, "fixturenames", ()) for item in request.session.items)
    if wanted and not _BINDER:
        work = Path(tempfile.mkdtemp(prefix="raildyn-binder-"))
        log = (work / "log.txt").open("w")
        script = Path(__file__).with_name("binder_env.py")
        _BINDER.update(work=work, log=log, proc=subprocess.Popen(
            [sys.executable, str(script), str(work)], stdout=log, stderr=subprocess.STDOUT
        ))  # fmt: skip


@pytest.fixture(scope="session")
def binder_run(background_jobs):
    """The background Binder run, waited for: (finished process, what it printed, its folder)."""
    if not _BINDER:
        pytest.skip("the Binder environment was not started (its test was not collected)")
    _BINDER["proc"].wait(timeout=1800)
    _BINDER["log"].close()
    return _BINDER["proc"], (_BINDER["work"] / "log.txt").read_text(), _BINDER["work"]


# Under `pytest -n`, the file in which the workers write each test's group for the controller's scheduler.
GROUPS = "RAILDYN_TEST_GROUPS"


def _book_rank(item) -> int | None:
    """Where a test of the book's group runs within it: the checks its validation page lists (0), the
    book (1), the Binder environment (2, built in the background meanwhile), the printed book last (3,
    printed meanwhile); None for a test outside the group."""
    names = getattr(item, "fixturenames", ())
    if "printed_book" in names:
        return 3
    if "binder_run" in names:
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


def pytest_collection_modifyitems(config, items):
    """Mark the reference checks (``pytest -m reference`` runs them alone) and order the long groups.

    Two groups hold a process for minutes: the book's (its checks, the build, the tests that read it) and
    the lecture-room app's. They go first, so that under ``pytest -n`` they start at once, each on one
    worker, while the other workers share the rest as they come free (``pytest_xdist_make_scheduler``).
    Within the book's group the order is ``_book_rank``'s.
    """
    for item in items:
        names = getattr(item, "fixturenames", ())
        if "reference" in names:
            item.add_marker(pytest.mark.reference)
        if _book_rank(item) is not None and "background_jobs" not in names:
            item.fixturenames.append("background_jobs")
    # stable: within each group the tests keep the order they were collected in
    items.sort(key=lambda item: (0, _book_rank(item)) if _book_rank(item) is not None else
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
    for job in (_BINDER, _PDF):  # a session stopped early leaves nothing running behind
        if job and job["proc"].poll() is None:
            job["proc"].kill()
