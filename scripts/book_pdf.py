"""Print the built book to one PDF, offline: ``make pdf`` runs this after ``make book``.

Each page of the table of contents is opened in Debian's headless chromium (driven by Playwright, as
the browser tests do), served from the built HTML on 127.0.0.1 so that nothing leaves the machine.
The script waits until MathJax has typeset the page's mathematics, then prints it; pypdf merges the
pages in the book's order, with one bookmark per page. A kernel-free widget prints its default frame,
which is the frame its page shows on opening.

Usage: ``python scripts/book_pdf.py [HTML_DIR] [OUT_PDF]`` (defaults: book/_build/html,
book/_build/raildyn.pdf).
"""

from __future__ import annotations

import functools
import http.server
import io
import sys
import threading
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = "/usr/bin/chromium"

# Resolves once MathJax has typeset everything it found (MathJax 3), or at once on a page without it.
_TYPESET = """() => (window.MathJax && MathJax.startup && MathJax.startup.promise)
    ? MathJax.startup.promise.then(() => true) : true"""


def toc_pages() -> list[str]:
    """The book's pages in reading order: the root, then each file of ``book/_toc.yml``, as HTML paths."""
    import yaml

    toc = yaml.safe_load((ROOT / "book" / "_toc.yml").read_text(encoding="utf-8"))
    files = [toc["root"]] + [entry["file"] for entry in toc.get("chapters", [])]
    return [f"{f}.html" for f in files]


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def print_book(html: Path, out: Path) -> int:
    """Print every page of the built book under ``html`` into ``out``; returns the number of PDF pages."""
    from playwright.sync_api import sync_playwright
    from pypdf import PdfReader, PdfWriter

    pages = toc_pages()
    missing = [p for p in pages if not (html / p).exists()]
    if missing:
        raise SystemExit(f"the built book lacks {missing}: run `make book` first")
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(_Quiet, directory=html))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    base = f"http://127.0.0.1:{server.server_address[1]}/"
    writer = PdfWriter()
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox"])
            page = browser.new_page()
            page.emulate_media(media="print")
            for i, path in enumerate(pages, 1):
                page.goto(base + path, wait_until="load", timeout=120_000)
                page.evaluate(_TYPESET)
                title = page.title().split("—")[0].split("#")[0].strip() or path
                pdf = page.pdf(format="A4", print_background=True, margin={"top": "15mm", "bottom": "15mm"})
                start = len(writer.pages)
                for sheet in PdfReader(io.BytesIO(pdf)).pages:
                    writer.add_page(sheet)
                writer.add_outline_item(title, start)
                print(f"[{i}/{len(pages)}] {path}: {len(writer.pages) - start} pages", flush=True)
            browser.close()
    finally:
        server.shutdown()
        server.server_close()
    writer.add_metadata({"/Title": "raildyn — Dynamics of Railway Vehicle Systems, interactively"})
    out.parent.mkdir(parents=True, exist_ok=True)
    with out.open("wb") as f:
        writer.write(f)
    return len(writer.pages)


def main(argv: list[str]) -> None:
    html = Path(argv[1]) if len(argv) > 1 else ROOT / "book" / "_build" / "html"
    out = Path(argv[2]) if len(argv) > 2 else ROOT / "book" / "_build" / "raildyn.pdf"
    count = print_book(html.resolve(), out.resolve())
    print(f"The book is at {out} ({count} pages)")


if __name__ == "__main__":
    main(sys.argv)
