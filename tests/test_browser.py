"""In a real browser: the live widgets under Voilà, and the built book read offline.

Debian's chromium is driven by Playwright for Python, with no browser download.
Every server listens on 127.0.0.1 and every wait is bounded.
"""

from __future__ import annotations

import contextlib
import functools
import http.server
import shutil
import socket
import subprocess
import sys
import threading
import time
import urllib.request
from pathlib import Path
from urllib.parse import urlparse

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
SCREENSHOTS = ROOT / "book" / "_build" / "screenshots"

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


class PageLog:
    """Console errors, uncaught exceptions and the hosts of every request a page made."""

    def __init__(self, page):
        self.errors: list[str] = []
        self.hosts: set[str] = set()
        page.on("console", lambda m: self.errors.append(m.text) if m.type == "error" else None)
        page.on("pageerror", lambda e: self.errors.append(str(e)))
        page.on("request", self._request)
        page.on("requestfailed", self._failed)

    def _failed(self, request):
        # A widget picture replaced while its previous frame is still loading cancels that load
        # (a blob: URL, net::ERR_ABORTED): not an error. Any other failed request is.
        if request.url.startswith("blob:") and "ERR_ABORTED" in str(request.failure):
            return
        self.errors.append(f"request failed: {request.url[:120]} ({request.failure})")

    def _request(self, request):
        url = urlparse(request.url)
        if url.scheme in ("http", "https", "ws", "wss"):
            self.hosts.add(url.hostname)


# ---------------------------------------------------------------- live widgets


@contextlib.contextmanager
def voila(notebook: Path, log_path: Path):
    """Serve one notebook with Voilà on a free local port; yield its address."""
    port = free_port()
    voila_bin = str(Path(sys.executable).parent / "voila")
    cmd = [voila_bin, str(notebook), "--no-browser", f"--port={port}", "--Voila.ip=127.0.0.1"]
    with open(log_path, "w") as log:
        proc = subprocess.Popen(cmd, cwd=notebook.parent, stdout=log, stderr=subprocess.STDOUT)
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


# Voilà's "lab" page template links Font Awesome from a CDN, whatever the notebook holds. raildyn's
# widgets use no icons, so the test answers those two style sheets with an empty one (as a machine
# with no network would, minus the console error) and still fails on any other outside request.
VOILA_CDN_STYLES = "https://cdn.jsdelivr.net/npm/@fortawesome/**"


IMAGE_DIGEST = """async (img) => {
  const bytes = new Uint8Array(await (await fetch(img.src)).arrayBuffer());
  let h = 2166136261 >>> 0;
  for (let i = 0; i < bytes.length; i++) { h = Math.imul(h ^ bytes[i], 16777619) >>> 0; }
  return bytes.length + ":" + h;
}"""


def image_of(control):
    return (
        control.locator("xpath=ancestor::div[contains(@class,'raildyn-widget')][1]")
        .locator(".widget-image")
        .first
    )


def wait_changed(image, before: str, what: str, timeout: float = 20.0) -> str:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        now = image.evaluate(IMAGE_DIGEST)
        if now != before:
            return now
        time.sleep(0.2)
    raise AssertionError(f"the figure did not change after moving {what}")


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=lambda p: p.stem)
def test_every_control_changes_its_figure_under_voila(browser, notebook, tmp_path):
    page = browser.new_page(viewport={"width": 1300, "height": 900})
    page.route(VOILA_CDN_STYLES, lambda route: route.fulfill(status=200, content_type="text/css", body=""))
    log = PageLog(page)
    with voila(notebook, tmp_path / "voila.log") as url:
        page.goto(url, timeout=120_000)
        page.wait_for_selector(".raildyn-widget .widget-image", timeout=120_000)
        page.wait_for_load_state("networkidle", timeout=60_000)
        widgets = page.locator(".raildyn-widget")
        assert widgets.count() >= 1
        moved = 0
        for w in range(widgets.count()):
            box = widgets.nth(w)
            image = box.locator(".widget-image").first
            for s in range(box.locator(".noUi-handle").count()):
                handle = box.locator(".noUi-handle").nth(s)
                before = image.evaluate(IMAGE_DIGEST)
                handle.focus()
                for _ in range(3):
                    handle.press("ArrowRight")
                wait_changed(image, before, f"slider {s} of widget {w}")
                moved += 1
            for d in range(box.locator("select").count()):
                select = box.locator("select").nth(d)
                before = image.evaluate(IMAGE_DIGEST)
                # ipywidgets shows option labels with no-break spaces; the value has plain ones.
                options = [o.replace("\xa0", " ") for o in select.locator("option").all_inner_texts()]
                current = select.input_value().replace("\xa0", " ")
                select.select_option(index=next(i for i, o in enumerate(options) if o != current))
                wait_changed(image, before, f"dropdown {d} of widget {w}")
                moved += 1
            for c in range(box.locator("input[type=checkbox]").count()):
                before = image.evaluate(IMAGE_DIGEST)
                box.locator("input[type=checkbox]").nth(c).click()
                wait_changed(image, before, f"checkbox {c} of widget {w}")
                moved += 1
        assert moved > 0
        page.close()  # before the server stops, so that the kernel's socket closes cleanly
    assert not log.errors, f"{notebook.name}: console errors {log.errors}"
    outside = log.hosts - {"127.0.0.1", "cdn.jsdelivr.net"}
    assert not outside, f"{notebook.name}: requests to {outside}"


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


def book_pages():
    return [
        "index.html",
        "book/intro.html",
        "book/api.html",
        "book/bibliography.html",
        "book/validation.html",
    ] + [f"notebooks/{p.stem}.html" for p in NOTEBOOKS]


@pytest.mark.parametrize("page_path", book_pages())
def test_book_page_reads_offline(browser, book_server, page_path):
    base, html = book_server
    page = browser.new_page(viewport={"width": 1280, "height": 1000})
    log = PageLog(page)
    page.goto(base + page_path, timeout=60_000, wait_until="load")
    page.wait_for_load_state("networkidle", timeout=60_000)
    has_math = page.evaluate("() => document.body.innerHTML.includes('class=\"math')")
    if has_math:
        # a visible one: a heading's mathematics also stands in the page's table of contents, which a
        # narrow window hides
        page.wait_for_selector("mjx-container >> visible=true", timeout=30_000)
    text = page.inner_text("main") if page.locator("main").count() else page.inner_text("body")
    assert "$$" not in text, f"{page_path}: raw $$ left, MathJax did not typeset"
    broken = page.evaluate(
        "() => Array.from(document.images).filter(i => !(i.complete && i.naturalWidth > 0))"
        ".map(i => i.src.slice(0, 80))"
    )
    assert not broken, f"{page_path}: images not loaded {broken}"
    if page_path.startswith("notebooks/"):
        SCREENSHOTS.mkdir(parents=True, exist_ok=True)
        page.screenshot(path=str(SCREENSHOTS / f"{Path(page_path).stem}.png"), full_page=True)
    page.close()
    assert not log.errors, f"{page_path}: console errors {log.errors}"
    assert log.hosts <= {"127.0.0.1"}, (
        f"{page_path}: requests left the machine for {log.hosts - {'127.0.0.1'}}"
    )


@pytest.mark.parametrize("notebook", NOTEBOOKS, ids=lambda p: p.stem)
def test_static_sliders_swap_frames_without_a_kernel(browser, book_server, notebook):
    base, _ = book_server
    page = browser.new_page(viewport={"width": 1280, "height": 1000})
    log = PageLog(page)
    page.goto(f"{base}notebooks/{notebook.stem}.html", timeout=60_000)
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
    page.close()
    assert not log.errors, f"{notebook.name}: console errors {log.errors}"


def test_page_weight_per_chapter(book_server):
    """Each chapter page, with everything it embeds, under 3 MB (issue goal; the frames are inline)."""
    _, html = book_server
    for nb in NOTEBOOKS:
        size = (html / "notebooks" / f"{nb.stem}.html").stat().st_size
        print(f"{nb.stem}: {size / 1e6:.2f} MB")
        assert size < 3e6, f"{nb.stem}.html weighs {size / 1e6:.2f} MB"


def test_chromium_is_debians():
    assert shutil.which("chromium") == CHROMIUM
