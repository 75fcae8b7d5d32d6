"""Print the built book to one PDF, offline: ``make pdf`` runs this after ``make book``.

Each page of the table of contents is opened in Debian's headless chromium (driven by Playwright, as
the browser tests do), served from the built HTML on 127.0.0.1 so that nothing leaves the machine.
The script waits until MathJax has typeset the page's mathematics, prepares the page for paper
(``book_print.css`` beside this script; every folded answer unfolded; a formula or table wider than the
column shrunk to fit), then prints it; pypdf merges the pages, with one bookmark per page and, under it,
one per section. The course comes first; the API reference follows it as an appendix (``APPENDIX``).

On paper, then:

* every link leads to its place in the PDF: a citation to its entry in the bibliography, an equation
  reference to the equation, a link to another chapter to that chapter's section. Chromium writes a
  destination only for an element that a link of the same page points at, so each page gets one hidden
  link per element id before printing; the links between pages, which Chromium writes as addresses on
  the print server, are rewritten to those destinations. A link that finds no destination stops the
  script. External links (a DOI, a repository) stay as they are;
* the worked answers the book folds away (the notebooks' cells tagged hide-cell) are printed unfolded,
  each under the label "Answer";
* code wraps at the edge of its box, and a formula or table too wide for the column is shrunk to fit
  it: nothing is cut at the sheet's edge;
* mathematics is MathJax's CommonHTML output with its own fonts (a Type 3 font in the PDF, each glyph
  mapped to its character), kept in the flow of its line, so that its characters are text in reading
  order: a search finds "ω", and a sentence copied keeps its formulas;
* every sheet carries its page number (printed by chromium onto a blank page and laid over the sheet).

A kernel-free widget prints its default frame, which is the frame its page shows on opening.

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
from urllib.parse import unquote, urlsplit

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = "/usr/bin/chromium"
PRINT_CSS = Path(__file__).with_name("book_print.css")
# The pages printed after the course, as its appendix, in this order.
APPENDIX = ("book/api",)
ANSWER_LABEL = "Answer"
# A4, with the top and bottom margins in which the page number sits.
MARGIN_MM = 15
PAPER = dict(format="A4", print_background=True, margin={"top": f"{MARGIN_MM}mm", "bottom": f"{MARGIN_MM}mm"})

# Resolves once MathJax has typeset everything it found (MathJax 3), or at once on a page without it.
_TYPESET = """() => (window.MathJax && MathJax.startup && MathJax.startup.promise)
    ? MathJax.startup.promise.then(() => true) : true"""

# Unfolds every fold (a hidden cell under its label), gives every element id a hidden same-page link
# (so that chromium writes a PDF destination for it), and returns the number of hidden cells unfolded.
_PREPARE = """(label) => {
    let answers = 0;
    for (const fold of document.querySelectorAll('details')) {
        fold.open = true;
        if (fold.classList.contains('hide') && !fold.querySelector('.raildyn-print-answer')) {
            const tag = document.createElement('p');
            tag.className = 'raildyn-print-answer';
            tag.textContent = label;
            fold.insertBefore(tag, fold.querySelector('summary').nextSibling);
            answers += 1;
        }
    }
    const box = document.createElement('div');
    box.hidden = true;
    for (const element of document.querySelectorAll('[id]')) {
        const link = document.createElement('a');
        link.setAttribute('href', '#' + element.id);
        box.append(link);
    }
    document.body.append(box);
    return answers;
}"""

# Shrinks each display formula and each table wider than its column (a derivation's long expression; a
# table of code names) until it fits: paper cannot scroll, and the formula would otherwise be cut at the
# sheet's edges. Returns [elements shrunk, elements still wider than the column, what sticks out].
_FIT = """() => {
    const column = document.querySelector('.bd-article');
    const inner = (element) => element.querySelector(':scope > mjx-math') || element;
    let shrunk = 0;
    const fit = (element, room) => {
        for (let step = 0; step < 6; step++) {
            const wide = inner(element).getBoundingClientRect().width;
            if (wide <= room + 0.5) return;
            const size = parseFloat(getComputedStyle(element).fontSize);
            element.style.setProperty('font-size', (0.99 * size * room / wide) + 'px', 'important');
            shrunk += step === 0;
        }
    };
    for (const math of column.querySelectorAll('mjx-container[display="true"]')) {
        // Its room: its box's width less what shares the box (the equation's number).
        const others = [...math.parentElement.children].filter((e) => e !== math);
        const taken = others.reduce((sum, e) => sum + e.getBoundingClientRect().width, 0);
        fit(math, math.parentElement.clientWidth - taken - (taken ? 12 : 0));
    }
    for (const table of column.querySelectorAll('table')) fit(table, table.parentElement.clientWidth);
    const style = getComputedStyle(column), box = column.getBoundingClientRect();
    const left = box.left + parseFloat(style.paddingLeft), right = box.right - parseFloat(style.paddingRight);
    let past = 0;
    for (const element of column.querySelectorAll('mjx-container, table, pre, img')) {
        const edge = inner(element).getBoundingClientRect();
        past += edge.width > 0 && (edge.left < left - 2 || edge.right > right + 2);
    }
    // Anything else that widens the page (a signature's unbroken name) makes chromium shrink the whole
    // page to the sheet, and the PDF's destinations, measured unshrunk, then drift from their headings.
    const sheet = document.documentElement;
    past += sheet.scrollWidth > sheet.clientWidth + 1;
    // What sticks out, named for the log: the innermost elements past the column's right edge.
    const out = [...column.querySelectorAll('*')].filter((e) => !e.children.length
        && e.getBoundingClientRect().right > right + 2).slice(0, 3)
        .map((e) => `${e.tagName.toLowerCase()}.${e.className}: ${e.textContent.trim().slice(0, 60)}`);
    return [shrunk, past, out];
}"""

# The page's sections (its second-level headings) for the PDF's bookmarks: [[element id, title]].
_SECTIONS = """() => [...document.querySelectorAll('.bd-article section > h2')].map((h) => [
    h.parentElement.id,
    [...h.childNodes].filter((n) => !(n.classList && n.classList.contains('headerlink')))
        .map((n) => n.textContent).join('').trim(),
])"""

# One blank sheet per page of the book with its number at the foot, laid over the printed sheets.
_NUMBERS = """<!DOCTYPE html><meta charset="utf-8"><style>
@page {{ size: A4; margin: 0 }}
body {{ margin: 0 }}
div {{ height: 290mm; position: relative; break-after: page }}
span {{ position: absolute; bottom: 0; width: 100%; text-align: center;
        font: 9pt "DejaVu Sans", sans-serif; color: #333 }}
</style>{sheets}"""


def toc_pages() -> list[str]:
    """The pages of the PDF in order, as HTML paths: the root, each file of ``book/_toc.yml`` but the
    appendix, then the appendix (``APPENDIX``)."""
    import yaml

    def files_in(entries) -> list[str]:
        """The files of a list of entries, each followed by its sections, in reading order (a part
        holds chapters; a chapter may hold sections)."""
        found = []
        for entry in entries:
            found += [entry["file"]] if "file" in entry else []
            for key in ("parts", "chapters", "sections"):
                found += files_in(entry.get(key, []))
        return found

    toc = yaml.safe_load((ROOT / "book" / "_toc.yml").read_text(encoding="utf-8"))
    top = {"file": toc["root"], "parts": toc.get("parts", []), "chapters": toc.get("chapters", [])}
    files = files_in([top])
    course = [f for f in files if f not in APPENDIX]
    appendix = [f for f in APPENDIX if f in files]
    return [f"{f}.html" for f in course + appendix]


def appendix_pages() -> list[str]:
    """The HTML paths of the appendix, as :func:`toc_pages` writes them."""
    return [f"{f}.html" for f in APPENDIX]


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def _destinations(reader, path: str, start: int) -> dict:
    """``(html path, element id) -> (sheet, left, top)`` for the destinations chromium wrote into one printed
    page (``reader``), whose first sheet is sheet ``start`` of the book; ``(path, "")`` is its top."""
    found = {(path, ""): (start, 0.0, float(reader.pages[0].mediabox.top))}
    # Chromium measures a destination's height as if the sheet had no top margin: it sits one margin
    # (15 mm) above its element, which in a bibliography is the entry before.
    margin = MARGIN_MM / 25.4 * 72
    for name, dest in reader.named_destinations.items():
        sheet = reader.get_destination_page_number(dest)
        top = min(float(dest.top or 0) - margin, float(reader.pages[sheet].mediabox.top))
        found[(path, str(name).removeprefix("/"))] = (start + sheet, float(dest.left or 0), top)
    return found


def _relink(writer, owners: list[str], destinations: dict, base: str) -> tuple[int, list[str]]:
    """Point each link of the merged book at its destination inside it.

    ``owners[i]`` is the HTML path of sheet ``i``. A same-page link names a destination of its page; a
    link to another page is an address on the print server (``base``). Returns the number of links
    rewritten and the links that found no destination.
    """
    from pypdf.generic import ArrayObject, FloatObject, NameObject, NullObject

    rewritten, lost = 0, []
    for index, sheet in enumerate(writer.pages):
        for ref in sheet.get("/Annots") or []:
            annot = ref.get_object()
            if annot.get("/Subtype") != "/Link":
                continue
            action = annot.get("/A")
            if "/Dest" in annot and not isinstance(annot["/Dest"], ArrayObject):
                key = (owners[index], str(annot["/Dest"]).removeprefix("/"))
            elif action is not None and str(action.get("/URI", "")).startswith(base):
                url = urlsplit(str(action["/URI"]))
                key = (url.path.removeprefix("/"), unquote(url.fragment))
            else:
                continue
            if key not in destinations:
                lost.append(f"{owners[index]} (page {index + 1}) -> {key[0]}#{key[1]}")
                continue
            target, left, top = destinations[key]
            annot[NameObject("/Dest")] = ArrayObject(
                [writer.pages[target].indirect_reference, NameObject("/XYZ"), FloatObject(left),
                 FloatObject(top), NullObject()]
            )  # fmt: skip
            annot.pop("/A", None)
            rewritten += 1
    return rewritten, lost


def _number(writer, numbers) -> None:
    """Lay sheet ``i`` of ``numbers`` (its page number, as chromium printed it) over page ``i`` of the book.

    Each number becomes a form XObject drawn after the page's own content, which stays as chromium wrote
    it (wrapped in q/Q, since chromium leaves its coordinate flip in force): cheaper, smaller and faster to
    read back than pypdf's ``merge_page``, which rewrites every content stream.
    """
    from pypdf.generic import ArrayObject, DecodedStreamObject, DictionaryObject, NameObject

    def stream(data: bytes, **entries):
        obj = DecodedStreamObject()
        obj.set_data(data)
        obj.update({NameObject(k): v for k, v in entries.items()})
        return writer._add_object(obj.flate_encode())

    save, draw = stream(b"q\n"), stream(b"\nQ q /RaildynPageNumber Do Q\n")
    for sheet, number in zip(writer.pages, numbers.pages, strict=True):
        form = stream(
            number.get_contents().get_data(),
            **{"/Type": NameObject("/XObject"), "/Subtype": NameObject("/Form"), "/BBox": number.mediabox,
               "/Resources": number["/Resources"].clone(writer)},
        )  # fmt: skip
        resources = DictionaryObject(sheet["/Resources"].get_object())
        xobjects = DictionaryObject(resources.get("/XObject", DictionaryObject()).get_object())
        xobjects[NameObject("/RaildynPageNumber")] = form
        resources[NameObject("/XObject")] = xobjects
        sheet[NameObject("/Resources")] = resources
        contents = sheet["/Contents"]
        own = list(contents) if isinstance(contents, ArrayObject) else [contents]
        sheet[NameObject("/Contents")] = ArrayObject([save, *own, draw])


def print_book(html: Path, out: Path) -> int:
    """Print every page of the built book under ``html`` into ``out``; returns the number of PDF pages."""
    from playwright.sync_api import sync_playwright
    from pypdf import PdfReader, PdfWriter
    from pypdf.generic import Fit

    pages = toc_pages()
    missing = [p for p in pages if not (html / p).exists()]
    if missing:
        raise SystemExit(f"the built book lacks {missing}: run `make book` first")
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(_Quiet, directory=html))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    base = f"http://127.0.0.1:{server.server_address[1]}/"
    writer = PdfWriter()
    owners: list[str] = []
    destinations: dict = {}
    answers = fitted = overflowing = 0
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox"])
            # The width of an A4 sheet (210 mm at 96 px per inch), so that the page is laid out on screen
            # as on paper and _FIT measures what prints.
            page = browser.new_page(viewport={"width": 794, "height": 1123})
            page.emulate_media(media="print")
            for i, path in enumerate(pages, 1):
                page.goto(base + path, wait_until="load", timeout=120_000)
                page.evaluate(_TYPESET)
                page.add_style_tag(path=str(PRINT_CSS))
                unfolded = page.evaluate(_PREPARE, ANSWER_LABEL)
                answers += unfolded
                shrunk, past, sticking_out = page.evaluate(_FIT)
                fitted += shrunk
                overflowing += past
                title = page.title().split("—")[0].split("#")[0].strip() or path
                reader = PdfReader(io.BytesIO(page.pdf(**PAPER)))
                start = len(writer.pages)
                for sheet in reader.pages:
                    writer.add_page(sheet)
                owners += [path] * len(reader.pages)
                destinations.update(_destinations(reader, path, start))
                appendix = "Appendix: " if path in appendix_pages() else ""
                chapter = writer.add_outline_item(appendix + title, start, is_open=False)
                for anchor, heading in page.evaluate(_SECTIONS):
                    if (path, anchor) in destinations:
                        sheet, left, top = destinations[(path, anchor)]
                        writer.add_outline_item(heading, sheet, parent=chapter, fit=Fit.xyz(left, top))
                note = f", answers unfolded: {unfolded}" if unfolded else ""
                note += f", formulas or tables shrunk to fit: {shrunk}" if shrunk else ""
                note += (
                    f", elements wider than the page's column: {past} ({'; '.join(sticking_out)})"
                    if past
                    else ""
                )
                print(f"[{i}/{len(pages)}] {path}: pages: {len(reader.pages)}{note}", flush=True)
            # The page numbers, printed on blank sheets and laid over the book's.
            sheets = "".join(f"<div><span>{n}</span></div>" for n in range(1, len(writer.pages) + 1))
            page.set_content(_NUMBERS.format(sheets=sheets))
            numbers = PdfReader(io.BytesIO(page.pdf(**{**PAPER, "margin": {"bottom": "6mm"}})))
            browser.close()
    finally:
        server.shutdown()
        server.server_close()
    if len(numbers.pages) != len(writer.pages):
        raise SystemExit(f"{len(numbers.pages)} numbered sheets for {len(writer.pages)} pages")
    _number(writer, numbers)
    rewritten, lost = _relink(writer, owners, destinations, base)
    if lost:
        raise SystemExit(f"{len(lost)} links find no destination in the PDF, e.g. " + "; ".join(lost[:10]))
    writer.add_metadata({"/Title": "raildyn — Dynamics of Railway Vehicle Systems, interactively"})
    writer.page_mode = "/UseOutlines"
    out.parent.mkdir(parents=True, exist_ok=True)
    with out.open("wb") as f:
        writer.write(f)
    course = owners.index(appendix_pages()[0]) if appendix_pages()[0] in owners else len(owners)
    print(
        f"{answers} answers unfolded, {fitted} formulas or tables shrunk to their column, {overflowing} "
        f"elements wider than it, {rewritten} links inside the PDF; the course is pages 1–{course} "
        f"({100 * course / len(owners):.0f} %), the API reference appendix pages {course + 1}–{len(owners)}",
        flush=True,
    )
    return len(writer.pages)


def main(argv: list[str]) -> None:
    html = Path(argv[1]) if len(argv) > 1 else ROOT / "book" / "_build" / "html"
    out = Path(argv[2]) if len(argv) > 2 else ROOT / "book" / "_build" / "raildyn.pdf"
    count = print_book(html.resolve(), out.resolve())
    print(f"The book is at {out} ({count} pages)")


if __name__ == "__main__":
    main(sys.argv)
