"""In a real browser: the live widgets under Voilà, and the built book read offline.

Debian's chromium is driven by Playwright for Python, with no browser download.
Every server listens on 127.0.0.1, no page may ask anything of another host, and every wait is
bounded.
"""

from __future__ import annotations

import contextlib
import functools
import http.cookiejar
import http.server
import json
import math
import os
import re
import shutil
import socket
import subprocess
import sys
import threading
import time
import urllib.request
from pathlib import Path
from urllib.parse import urlparse

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))
CHROMIUM = "/usr/bin/chromium"
FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
    "--disable-quic",
]

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(
        not Path(CHROMIUM).exists(), reason="Debian's chromium is not installed (make test installs it)"
    ),
]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for_http(url: str, timeout: float) -> None:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        with contextlib.suppress(OSError):
            with urllib.request.urlopen(url, timeout=2):
                return
        time.sleep(0.3)
    raise TimeoutError(f"{url} did not answer within {timeout} s")


@pytest.fixture(scope="module")
def browser():
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS, headless=True)
        yield b
        b.close()


# This machine: every request a page makes must go to one of these.
LOCAL_HOSTS = {"127.0.0.1", "localhost"}


class PageLog:
    """Console errors, uncaught exceptions and the address of every request a page made."""

    def __init__(self, page):
        self.errors: list[str] = []
        self.messages: list[str] = []  # every console message but the errors, for a failure's report
        self.hosts: set[str] = set()
        self.urls: list[str] = []
        page.on("console", lambda m: (self.errors if m.type == "error" else self.messages).append(m.text))
        page.on("pageerror", lambda e: self.errors.append(str(e)))
        page.on("request", self._request)
        page.on("websocket", lambda socket: self.urls.append(socket.url))
        page.on("requestfailed", self._failed)

    def off_machine(self) -> list[str]:
        """Every request to anything but this machine; a data: or blob: address is the page's own."""
        return [
            u
            for u in self.urls
            if urlparse(u).scheme not in ("data", "blob") and urlparse(u).hostname not in LOCAL_HOSTS
        ]

    def _failed(self, request):
        # A widget picture replaced while its previous frame is still loading cancels that load
        # (a blob: URL, net::ERR_ABORTED): not an error. Any other failed request is.
        if request.url.startswith("blob:") and "ERR_ABORTED" in str(request.failure):
            return
        self.errors.append(f"request failed: {request.url[:120]} ({request.failure})")

    def _request(self, request):
        self.urls.append(request.url)
        url = urlparse(request.url)
        if url.scheme in ("http", "https", "ws", "wss"):
            self.hosts.add(url.hostname)


# ---------------------------------------------------------------- live widgets


def app_setting(name: str) -> list[str]:
    """A setting of `make app`, read from the Makefile (its continued lines joined, as make joins them),
    so that the tests serve the app as it does."""
    makefile = (ROOT / "Makefile").read_text().replace("\\\n", " ")
    match = re.search(rf"^{name}\s*:=(.*)$", makefile, flags=re.M)
    assert match, f"the Makefile sets no {name}"
    return match.group(1).split()


@pytest.fixture(scope="module")
def voila_app(tmp_path_factory):
    """The app as `make app` serves it (the notebooks directory, the project's page template), on a free
    local port, for every test of the module; yield its address."""
    port = free_port()
    voila_bin = str(Path(sys.executable).parent / "voila")
    (templates,) = app_setting("APP_TEMPLATES")
    paths = [str(ROOT / templates), *filter(None, [os.environ.get("JUPYTER_PATH")])]
    env = {**os.environ, "JUPYTER_PATH": os.pathsep.join(paths)}
    cmd = [voila_bin, "notebooks", *app_setting("APP_OPTIONS"), f"--port={port}"]
    with open(tmp_path_factory.mktemp("voila") / "voila.log", "w") as log:
        proc = subprocess.Popen(cmd, cwd=ROOT, env=env, stdout=log, stderr=subprocess.STDOUT)
        try:
            wait_for_http(f"http://127.0.0.1:{port}/", timeout=60)
            yield f"http://127.0.0.1:{port}/"
        finally:
            proc.terminate()
            try:
                proc.wait(timeout=15)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait(timeout=15)


def test_the_apps_widget_manager_is_the_one_voila_was_built_with():
    # Voilà 0.5 carries its own copy of the widget manager, built against its own JupyterLab. An installed
    # jupyterlab_widgets whose manager is newer replaces that copy in the app's pages (the page loads the
    # newest version of a shared module), and there some widgets drew as "model not found" in one page
    # load of four or five (pyproject.toml's app extra pins the pair).
    from packaging.version import Version

    share = Path(sys.prefix) / "share" / "jupyter"
    licences = (
        share / "voila/labextensions/@voila-dashboards/widgets-manager8/static/third-party-licenses.json"
    )
    name = "@jupyter-widgets/jupyterlab-manager"
    voilas = next(p["versionInfo"] for p in json.loads(licences.read_text())["packages"] if p["name"] == name)
    installed = json.loads((share / "labextensions" / name / "package.json").read_text())["version"]
    assert Version(installed) <= Version(voilas), (
        f"jupyterlab_widgets installs {name} {installed}, newer than Voilà's own {voilas}"
    )


def open_notebook(page, base: str, notebook: Path, log: PageLog) -> None:
    """Open a notebook in the app and wait until its widgets are drawn and the page is quiet; if they
    are not drawn, fail with what the page logged."""
    page.goto(f"{base}voila/render/{notebook.name}", timeout=120_000)
    try:
        page.wait_for_selector(".raildyn-widget .widget-image", timeout=120_000)
    except Exception as error:
        raise AssertionError(
            f"{notebook.name}: no widget drew in the app ({type(error).__name__}); the page logged"
            f" {log.errors or 'no error'}; messages {log.messages[-12:]}"
        ) from None
    page.wait_for_load_state("networkidle", timeout=60_000)


def close_notebook(page, base: str) -> None:
    """Close a notebook's page, then shut its kernel down, so that the one server does not gather kernels.

    The page's own request to do so, sent as it unloads, carries no XSRF token and Voilà refuses it
    (403, voila-dashboards/voila#1458): the test asks with the token the server's cookie holds."""
    config = page.evaluate("() => JSON.parse(document.getElementById('jupyter-config-data').textContent)")
    page.close()  # before the kernel stops, so that its socket closes cleanly
    jar = http.cookiejar.CookieJar()
    opener = urllib.request.build_opener(urllib.request.HTTPCookieProcessor(jar))
    opener.open(base, timeout=30).read()
    token = next(c.value for c in jar if c.name == "_xsrf")
    shutdown = urllib.request.Request(
        f"{base}voila/api/shutdown/{config['kernelId']}", method="POST", headers={"X-XSRFToken": token}
    )
    with opener.open(shutdown, timeout=30) as answer:
        assert answer.status in (200, 204), f"the kernel's shutdown answered {answer.status}"


IMAGE_DIGEST = """async (img) => {
  const bytes = new Uint8Array(await (await fetch(img.src)).arrayBuffer());
  let h = 2166136261 >>> 0;
  for (let i = 0; i < bytes.length; i++) { h = Math.imul(h ^ bytes[i], 16777619) >>> 0; }
  return bytes.length + ":" + h;
}"""


def picture(image) -> tuple[str | None, str]:
    """What a widget's image shows: (its address, a digest of its bytes)."""
    return image.get_attribute("src"), image.evaluate(IMAGE_DIGEST)


def wait_changed(image, before: tuple[str | None, str], what: str, timeout: float = 60.0) -> None:
    """Wait until the image shows other bytes than ``before`` (``picture``). Its address is polled and its
    bytes digested only when the address changed: a digest fetches and hashes the picture, 20 ms of
    chromium's time, and the wait polls five times a second."""
    # A minute: the app's kernel shares the machine with the book's build on the other worker of
    # `make test`, and a control whose model runs anew (a curve entry at a new speed) can take seconds.
    address, digest = before
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        now = image.get_attribute("src")
        if now != address:
            address = now
            if image.evaluate(IMAGE_DIGEST) != digest:
                return
        time.sleep(0.2)
    raise AssertionError(f"the figure did not change after moving {what}")


def link_texts(notebook: Path, scheme: str) -> list[str]:
    """The text of every Markdown link of the notebook to `scheme:` ("cite" or "eq"), in order."""
    cells = nbformat.read(notebook, as_version=4).cells
    text = "\n".join(c.source for c in cells if c.cell_type == "markdown")
    return re.findall(rf"\[([^\[\]]+)\]\({scheme}:[^)\s]+\)", text)


def click_citation_and_equation(page, notebook: Path) -> None:
    """Click the notebook's first citation and first equation link, and check the page stays. The
    notebooks cite ([Garg and Dukkipati 1984](cite:garg1984)) and refer to equations ([(eq-sdof)](eq:eq-sdof))
    with links that only the book resolves; a click that left the page would fire its unload handler,
    which drops the kernel's connection, and no widget would redraw after it."""
    address = page.url
    for scheme in ("cite", "eq"):
        texts = link_texts(notebook, scheme)
        assert texts, f"{notebook.name} has no {scheme}: link to click"
        page.locator(".jp-RenderedMarkdown").get_by_text(texts[0], exact=True).first.click()
        assert page.url == address, f"a click on {texts[0]!r} left the page for {page.url}"


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=lambda p: p.stem)
def test_every_control_changes_its_figure_under_voila(browser, voila_app, notebook):
    # Each control is moved one step (one model run in the kernel), after a click on a citation and on
    # an equation link, so that the figures changing also shows that the clicks left the widgets alive.
    page = browser.new_page(viewport={"width": 1300, "height": 900})
    log = PageLog(page)
    open_notebook(page, voila_app, notebook, log)
    click_citation_and_equation(page, notebook)
    widgets = page.locator(".raildyn-widget")
    assert widgets.count() >= 1
    moved = 0
    for w in range(widgets.count()):
        box = widgets.nth(w)
        image = box.locator(".widget-image").first
        for s in range(box.locator(".noUi-handle").count()):
            handle = box.locator(".noUi-handle").nth(s)
            before = picture(image)
            handle.focus()
            handle.press("ArrowRight")
            wait_changed(image, before, f"slider {s} of widget {w}")
            moved += 1
        for d in range(box.locator("select").count()):
            select = box.locator("select").nth(d)
            before = picture(image)
            # ipywidgets shows option labels with no-break spaces; the value has plain ones.
            options = [o.replace("\xa0", " ") for o in select.locator("option").all_inner_texts()]
            current = select.input_value().replace("\xa0", " ")
            select.select_option(index=next(i for i, o in enumerate(options) if o != current))
            wait_changed(image, before, f"dropdown {d} of widget {w}")
            moved += 1
        for c in range(box.locator("input[type=checkbox]").count()):
            before = picture(image)
            box.locator("input[type=checkbox]").nth(c).click()
            wait_changed(image, before, f"checkbox {c} of widget {w}")
            moved += 1
    assert moved > 0
    # The lecture room sees no worked answer: the app does not even work them out (raildyn.course).
    assert page.locator(".raildyn-answer").count() == 0, f"{notebook.name}: an answer shows in the app"
    close_notebook(page, voila_app)
    assert not log.errors, f"{notebook.name}: console errors {log.errors}"
    assert not log.off_machine(), f"{notebook.name}: requests off this machine {log.off_machine()}"


def test_the_app_lists_every_notebook_from_this_machine(browser, voila_app):
    # The first page `make app` shows: the server's list, each name a link to its notebook's page.
    page = browser.new_page(viewport={"width": 1300, "height": 900})
    log = PageLog(page)
    page.goto(voila_app, timeout=60_000)
    page.wait_for_load_state("networkidle", timeout=60_000)
    for notebook in NOTEBOOKS:
        name = page.get_by_text(notebook.name, exact=True)
        name.wait_for(timeout=30_000)
        link = name.evaluate("e => e.closest('a') && e.closest('a').getAttribute('href')")
        assert link and link.split("?")[0].endswith(f"voila/render/{notebook.name}"), (
            f"{notebook.name} links to {link!r}, not to its page"
        )
    page.close()
    assert not log.errors, f"the list of notebooks: console errors {log.errors}"
    assert not log.off_machine(), f"the list of notebooks: requests off this machine {log.off_machine()}"


# ---------------------------------------------------------------- the built book


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@pytest.fixture(scope="module")
def book_server(built_book):
    proc, html = built_book
    assert proc.returncode == 0, (proc.stdout + proc.stderr)[-4000:]
    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), functools.partial(_QuietHandler, directory=html)
    )
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{server.server_address[1]}/", html
    server.shutdown()
    server.server_close()


@pytest.fixture(scope="module")
def chapter_pages(browser, book_server):
    """Each chapter's page of the built book, loaded once (a few seconds: its figures' frames are inline)
    and kept open for every test that reads it: ``chapter_pages(notebook)`` → (page, its log)."""
    base, _ = book_server
    opened: dict[str, tuple] = {}

    def page_of(notebook: Path) -> tuple:
        if notebook.stem not in opened:
            page = browser.new_page(viewport={"width": 1280, "height": 1000})
            log = PageLog(page)
            page.goto(f"{base}notebooks/{notebook.stem}.html", timeout=60_000, wait_until="load")
            page.wait_for_load_state("networkidle", timeout=60_000)
            opened[notebook.stem] = page, log
        return opened[notebook.stem]

    yield page_of
    for page, _ in opened.values():
        page.close()


def reads_offline(page, log: PageLog, name: str) -> None:
    """The page's mathematics is typeset, its images are loaded, and it logged no error and asked nothing
    of another host."""
    has_math = page.evaluate("() => document.body.innerHTML.includes('class=\"math')")
    if has_math:
        # a visible one: a heading's mathematics also stands in the page's table of contents, which a
        # narrow window hides
        page.wait_for_selector("mjx-container >> visible=true", timeout=30_000)
    text = page.inner_text("main") if page.locator("main").count() else page.inner_text("body")
    assert "$$" not in text, f"{name}: raw $$ left, MathJax did not typeset"
    broken = page.evaluate(
        "() => Array.from(document.images).filter(i => !(i.complete && i.naturalWidth > 0))"
        ".map(i => i.src.slice(0, 80))"
    )
    assert not broken, f"{name}: images not loaded {broken}"
    assert not log.errors, f"{name}: console errors {log.errors}"
    assert log.hosts <= {"127.0.0.1"}, f"{name}: requests left the machine for {log.hosts - {'127.0.0.1'}}"
    assert not log.off_machine(), f"{name}: requests off this machine {log.off_machine()}"


@pytest.mark.parametrize(
    "page_path",
    ["index.html", "book/intro.html", "book/api.html", "book/bibliography.html", "book/validation.html"],
)
def test_book_page_reads_offline(browser, book_server, page_path):
    base, _ = book_server
    page = browser.new_page(viewport={"width": 1280, "height": 1000})
    log = PageLog(page)
    page.goto(base + page_path, timeout=60_000, wait_until="load")
    page.wait_for_load_state("networkidle", timeout=60_000)
    reads_offline(page, log, page_path)
    page.close()


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=lambda p: p.stem)
def test_chapter_page_reads_offline(chapter_pages, notebook):
    page, log = chapter_pages(notebook)
    reads_offline(page, log, f"{notebook.stem}.html")


@contextlib.contextmanager
def chapter_page(chapter_pages, notebook: Path):
    """A chapter's page of the built book; on leaving, no console error and no request off this machine."""
    page, log = chapter_pages(notebook)
    yield page
    assert not log.errors, f"{notebook.name}: console errors {log.errors}"
    assert not log.off_machine(), f"{notebook.name}: requests off this machine {log.off_machine()}"


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=lambda p: p.stem)
def test_static_sliders_swap_frames_without_a_kernel(chapter_pages, notebook):
    with chapter_page(chapter_pages, notebook) as page:
        _swap_every_frame(page)


def _swap_every_frame(page) -> None:
    statics = page.locator(".raildyn-static")
    assert statics.count() >= 1, "no kernel-free widget on the page"
    for k in range(statics.count()):
        block = statics.nth(k)
        img = block.locator("img")
        for r in range(block.locator("input[type=range]").count()):
            slider = block.locator("input[type=range]").nth(r)
            before = img.get_attribute("src")
            value, top = int(slider.input_value()), int(slider.get_attribute("max"))
            slider.focus()
            slider.press("ArrowLeft" if value == top else "ArrowRight")
            assert img.get_attribute("src") != before, (
                f"static slider {r} of block {k} did not change the picture"
            )
            assert block.evaluate("b => b.querySelector('img').naturalWidth") > 0


# The chapters whose pages show an animation of raildyn.animations (its player: .raildyn-animation).
ANIMATED = [nb for nb in NOTEBOOKS if nb.stem[:2] in {"05", "06", "07", "08", "09", "10"}]


@pytest.mark.parametrize("notebook", ANIMATED, ids=lambda p: p.stem)
def test_animations_play_without_a_kernel(chapter_pages, notebook):
    with chapter_page(chapter_pages, notebook) as page:
        players = page.locator(".raildyn-animation")
        assert players.count() >= 1, f"{notebook.name}: no animation on the page"
        for k in range(players.count()):
            _play(players.nth(k), f"{notebook.name}, animation {k}")


def test_an_animation_plays_offline_in_its_own_page(browser, tmp_path):
    # The player on its own (Animation.save), served from this machine: what the book's pages embed,
    # checked without building the book.
    from raildyn import animations

    animations.bridge_crossing(frames=8).save(tmp_path / "crossing.html")
    server = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), functools.partial(_QuietHandler, directory=tmp_path)
    )
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        page = browser.new_page(viewport={"width": 1000, "height": 800})
        log = PageLog(page)
        page.goto(f"http://127.0.0.1:{server.server_address[1]}/crossing.html", timeout=60_000)
        page.wait_for_load_state("networkidle", timeout=60_000)
        _play(page.locator(".raildyn-animation").first, "crossing.html")
        page.close()
    finally:
        server.shutdown()
        server.server_close()
    assert not log.errors, f"console errors {log.errors}"
    assert log.hosts <= {"127.0.0.1"} and not log.off_machine(), (
        f"requests off this machine {log.off_machine()}"
    )


def _play(player, name: str) -> None:
    """Press play and watch the picture change at least twice on its own; pause; step with the slider."""
    img = player.locator("img[data-frame]")
    seen = [img.get_attribute("src")]
    player.locator("button[data-action=play]").click()
    deadline = time.monotonic() + 10.0
    while len(set(seen)) < 3 and time.monotonic() < deadline:
        time.sleep(0.05)
        seen.append(img.get_attribute("src"))
    assert len(set(seen)) >= 3, f"{name}: playing, the picture changed {len(set(seen)) - 1} times in 10 s"
    assert player.locator("button[data-action=play]").get_attribute("aria-pressed") == "true"
    player.locator("button[data-action=play]").click()  # pause
    paused, label = img.get_attribute("src"), player.locator("output[data-label]").text_content()
    time.sleep(0.5)
    assert img.get_attribute("src") == paused, f"{name}: the picture moved on after pause"
    slider = player.locator("input[data-control=frame]")
    frame = int(slider.input_value())
    slider.focus()
    slider.press("ArrowLeft" if frame == int(slider.get_attribute("max")) else "ArrowRight")
    assert img.get_attribute("src") != paused, f"{name}: the slider did not change the picture"
    assert player.evaluate("p => p.querySelector('img').naturalWidth") > 0
    assert player.locator("output[data-label]").text_content() not in ("", label), (
        f"{name}: the label stood still"
    )


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=lambda p: p.stem)
def test_self_checks_answer_in_the_static_book(chapter_pages, notebook):
    # Each question that checks itself answers in the page's JavaScript, with no kernel: a right number
    # or choice is told so, and a wrong number meets the same slip that raildyn.course.check names.
    with chapter_page(chapter_pages, notebook) as page:
        boxes = page.locator(".raildyn-selfcheck")
        assert boxes.count() >= 2, f"{notebook.name}: {boxes.count()} self-checks"
        for k in range(boxes.count()):
            _answer(boxes.nth(k), f"{notebook.name}, self-check {k}")


def _answer(box, name: str) -> None:
    """Answer one self-check wrongly and rightly, and hold what the page says to raildyn.course.check."""
    from raildyn import course

    spec = json.loads(re.search(r"spec = (\{.*?\});", box.locator("script").text_content()).group(1))
    verdict = box.locator(".raildyn-selfcheck-verdict")
    if "choices" in spec:
        wrong = (spec["right"] + 1) % spec["choices"]
        for pick, mark in ((wrong, "✗"), (spec["right"], "✓")):
            box.locator("input[type=radio]").nth(pick).check()
            box.locator("button").click()
            assert verdict.text_content().startswith(mark), (name, verdict.text_content())
        return
    e = spec["expected"]
    for a in (e, -e, 2 * math.pi * e, 1000 * e, 1.37 * e + 0.37):
        box.locator("input").fill(repr(a))
        box.locator("button").click()
        told, python = verdict.text_content(), course.check(a, e, rtol=spec["rtol"], atol=spec["atol"])
        assert told.startswith("✓" if python.correct else "✗"), (name, a, told, python)
        if not python.correct and not python.reason.startswith("off by"):
            assert python.reason in told, (name, a, told, python.reason)


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=lambda p: p.stem)
def test_answers_wrap_in_a_1280_pixel_window(chapter_pages, notebook):
    # Opened, an answer wraps its long lines instead of scrolling sideways (comments run to 110
    # characters). It runs after the other tests of the shared page, since it opens every answer.
    with chapter_page(chapter_pages, notebook) as page:
        wide = page.evaluate(
            """() => { document.querySelectorAll('details.hide').forEach(d => d.open = true);
            return Array.from(document.querySelectorAll('.cell.tag_hide-cell pre'))
                .filter(p => p.scrollWidth > p.clientWidth + 1).map(p => p.textContent.slice(0, 60));
            }"""
        )
        assert not wide, f"{notebook.stem}: answers that scroll sideways: {wide[:3]}"


def test_notation_and_validation_pages_fit_a_1280_pixel_window(browser, book_server):
    # The notation tables fit their column, and no number of the validation page is split across lines.
    base, _ = book_server
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    log = PageLog(page)
    page.goto(f"{base}book/notation.html", timeout=60_000)
    page.wait_for_function("() => document.querySelectorAll('mjx-container').length > 100", timeout=60_000)
    over = page.evaluate(
        """() => Array.from(document.querySelectorAll('table'))
            .map(t => t.scrollWidth - t.parentElement.clientWidth).filter(d => d > 1)"""
    )
    assert not over, f"notation tables wider than their column by {over} px"
    # Every request of the page done before the next one opens: chromium asks for the favicon after
    # the page's load, and leaving the page cancels what is still under way (net::ERR_ABORTED).
    page.wait_for_load_state("networkidle", timeout=60_000)
    page.goto(f"{base}book/validation.html", timeout=60_000)
    page.wait_for_load_state("networkidle", timeout=60_000)
    split = page.evaluate(
        """() => Array.from(document.querySelectorAll('.raildyn-number'))
            .filter(e => e.getClientRects().length > 1).map(e => e.textContent)"""
    )
    assert not split, f"numbers split across lines: {split[:5]}"
    page.close()
    assert not log.errors, f"notation and validation pages: console errors {log.errors}"
    assert not log.off_machine(), f"notation and validation pages: requests off {log.off_machine()}"


def test_page_weight_per_chapter(book_server):
    """Each chapter page, with everything it embeds, under 3 MB (issue goal; the frames are inline)."""
    _, html = book_server
    for nb in NOTEBOOKS:
        size = (html / "notebooks" / f"{nb.stem}.html").stat().st_size
        print(f"{nb.stem}: {size / 1e6:.2f} MB")
        assert size < 3e6, f"{nb.stem}.html weighs {size / 1e6:.2f} MB"


def test_chromium_is_debians():
    assert shutil.which("chromium") == CHROMIUM
