"""`make pdf`: the built book printed to one PDF by headless chromium (scripts/book_pdf.py), in the
background once the book is built (tests/background.py), checked here.

What a reader of the PDF needs, each checked against the built HTML or the notebooks rather than against
numbers typed here: every page numbered; every link inside the PDF (a citation to its entry in the
bibliography, an equation reference to its equation) or to the web, none to the print server; every
worked answer printed; every line of code whole; the mathematics text in reading order; the course first
and the API reference after it.
"""

from __future__ import annotations

import html
import json
import re
import sys
import unicodedata
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "scripts"))

import book_pdf  # noqa: E402
import pdf_text  # noqa: E402  (tests/pdf_text.py: the printed book's text, read by its job)

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(not Path(book_pdf.CHROMIUM).exists(), reason="Debian's chromium is not installed"),
]

# The page number sits in the bottom margin, 15 mm = 42.5 pt; the text of the page ends above it.
FOOT = 15 / 25.4 * 72


@dataclass
class Printed:
    reader: object
    log: str
    html: Path
    pages: list[str]  # the HTML paths, in the PDF's order
    ranges: dict  # HTML path -> range of its PDF pages (0-based)
    runs: list  # per PDF page: [(text, x, y, kind)] (pdf_text.read_runs)
    numbers: dict  # a page object's number -> its index

    def text(self, path: str) -> str:
        """The text of one HTML page's PDF pages without their page numbers, whitespace removed and
        NFKC-normalised (the PDF's ligatures "ﬁ" become "fi")."""
        return flat(
            "".join(
                t
                for i in self.ranges[path]
                for t, _, y, kind in self.runs[i]
                if kind == "math" or (kind == "text" and y > FOOT)
            )
        )

    def article(self, path: str) -> str:
        """The article of one built HTML page (its printed part: no navigation)."""
        source = (self.html / path).read_text(encoding="utf-8")
        return source[source.index("<article") : source.index("</article>")]


def _chapters(reader) -> list:
    """The PDF's top-level bookmarks (pypdf lists a bookmark's children, as a list, after it)."""
    return [item for item in reader.outline if not isinstance(item, list)]


def flat(text: str) -> str:
    return re.sub(r"\s+", "", unicodedata.normalize("NFKC", text))


def plain(fragment: str) -> str:
    """The text of an HTML fragment."""
    return html.unescape(re.sub(r"<[^>]+>", "", fragment))


@pytest.fixture(scope="module")
def book(printed_book, built_book) -> Printed:
    from pypdf import PdfReader

    proc, log, out = printed_book
    assert proc.returncode == 0, log[-4000:]
    reader = PdfReader(out)
    pages = book_pdf.toc_pages()
    # One bookmark per HTML page, in the PDF's order (its sections' bookmarks under it, as a list): the
    # bookmarks give each page's range of sheets.
    starts = [reader.get_destination_page_number(item) for item in _chapters(reader)]
    assert len(starts) == len(pages) and starts == sorted(starts), starts
    ends = starts[1:] + [len(reader.pages)]
    runs = pdf_text.load_runs(out)  # read by the background job as soon as the PDF was printed
    assert len(runs) == len(reader.pages)
    ranges = {p: range(a, b) for p, a, b in zip(pages, starts, ends, strict=True)}
    numbers = {page.indirect_reference.idnum: i for i, page in enumerate(reader.pages)}
    return Printed(reader, log, built_book[1], pages, ranges, runs, numbers)


def test_the_book_prints_to_one_pdf_with_its_mathematics_typeset(book):
    reader, pages = book.reader, book_pdf.toc_pages()
    # Every page of the table of contents prints to at least one sheet, each with its bookmark.
    assert f"({len(reader.pages)} pages)" in book.log and len(reader.pages) >= len(pages)
    assert len(_chapters(reader)) == len(pages)
    text = "\n".join("".join(run[0] for run in page) for page in book.runs)
    # MathJax typeset the mathematics: no TeX source left, and chapter 1's equation of motion is there
    # in typeset glyphs (the dots over x are combining accents in the PDF's text).
    assert "$$" not in text and "\\frac" not in text and "\\ddot" not in text
    assert "¨x" in text.replace(" ", "")


def test_every_page_of_the_book_is_printed(book):
    # The pages the built book's contents list (its sidebar, on the root page), whatever the form of the
    # table of contents that lists them (parts, chapters, sections).
    root = book.html / "book" / "intro.html"
    entry = r'<li class="toctree-l\d[^>]*><a class="reference internal" href="([^"#]+)"'
    listed = re.findall(entry, root.read_text())
    printed = {(root.parent / href).resolve().relative_to(book.html.resolve()).as_posix() for href in listed}
    assert len(printed) > 10 and printed | {"book/intro.html"} == set(book.pages)


def test_every_page_carries_its_number_at_its_foot(book):
    wrong = []
    for index, runs in enumerate(book.runs):
        foot = "".join(t for t, _, y, kind in runs if y <= FOOT and kind == "text").strip()
        if foot != str(index + 1):
            wrong.append((index + 1, foot))
    assert not wrong, f"{len(wrong)} pages without their number at the foot, e.g. {wrong[:5]}"


def _links(reader):
    """(page index, link annotation) for every link of the PDF."""
    for index, page in enumerate(reader.pages):
        for ref in page.get("/Annots") or []:
            annot = ref.get_object()
            if annot.get("/Subtype") == "/Link":
                yield index, annot


def _target(book, annot):
    """The (page index, left, top) a link inside the PDF leads to, or None for a link to an address."""
    from pypdf.generic import ArrayObject

    reader = book.reader
    dest = annot.get("/Dest")
    action = annot.get("/A")
    if dest is None and action is not None and action.get("/S") == "/GoTo":
        dest = action["/D"]
    if dest is None:
        return None
    if not isinstance(dest, ArrayObject):
        dest = reader.named_destinations[str(dest)]
        return reader.get_destination_page_number(dest), float(dest.left or 0), float(dest.top or 0)
    return book.numbers[dest[0].idnum], float(dest[2] or 0), float(dest[3] or 0)


def test_every_link_leads_inside_the_pdf_or_to_the_web_never_to_the_print_server(book):
    inside, addresses, unresolved = 0, [], []
    for index, annot in _links(book.reader):
        try:
            target = _target(book, annot)
        except (KeyError, IndexError) as error:  # a named destination that does not exist, a lost page
            unresolved.append((index + 1, repr(error)))
            continue
        if target is not None:
            assert 0 <= target[0] < len(book.reader.pages)
            inside += 1
        else:
            addresses.append((index + 1, str(annot["/A"].get("/URI", annot["/A"]))))
    assert not unresolved, unresolved[:10]
    local = [a for a in addresses if re.search(r"//(127\.0\.0\.1|localhost)\b", a[1]) or "file:" in a[1]]
    assert not local, f"{len(local)} links to the print server or a local file, e.g. {local[:5]}"
    assert all(re.match(r"(https?://|mailto:)", a[1]) for a in addresses), addresses
    # Every cross-reference of the printed pages (an equation, a section, another chapter, a citation, an
    # API entry) is a link inside the PDF: one or more (a link broken across lines is two) per reference.
    for path in book.pages:
        references = len(re.findall(r'<a class="reference internal"', book.article(path)))
        here = sum(
            1 for index, annot in _links(book.reader) if index in book.ranges[path] and "/Dest" in annot
        )
        assert here >= references, f"{path}: {here} links inside the PDF for {references} cross-references"
    assert inside > 1000, inside


def _words(book, page: int, left: float, right: float, low: float, high: float) -> str:
    """The text of the runs of one PDF page that start inside a box (pt, from the bottom left)."""
    runs = sorted(
        (
            (-y, x, t)
            for t, x, y, kind in book.runs[page]
            if left - 1 <= x <= right and low <= y <= high and kind == "text"
        ),
        key=lambda r: r[:2],
    )
    return " ".join(t for _, _, t in runs)


def _below(book, page: int, top: float, span: float) -> str:
    """The text that follows a destination: its page's from ``top`` down ``span`` pt, continued at the top
    of the next page when the page ends first (an element at the foot of a page can print on the next)."""
    words = _words(book, page, 0, 1e4, max(top - span, FOOT), top + 2)
    rest = span - (top - FOOT)
    if rest > 0 and page + 1 < len(book.runs):
        height = float(book.reader.pages[page + 1].mediabox.top)
        words += " " + _words(book, page + 1, 0, 1e4, height - FOOT - rest, height)
    return words


def test_a_citation_leads_to_its_entry_in_the_bibliography(book):
    bibliography = book.ranges["book/bibliography.html"]
    course = [p for p in book.pages if p.startswith("notebooks/")]
    checked = 0
    for index, annot in _links(book.reader):
        target = _target(book, annot)
        if (
            target is None
            or target[0] not in bibliography
            or not any(index in book.ranges[p] for p in course)
        ):
            continue
        x1, y1, x2, y2 = (float(v) for v in annot["/Rect"])
        cited = _words(book, index, x1, x2, y1 - 1, y2 + 1)  # "Garg and Dukkipati, 1984"
        # The entry under the anchor: its authors on its first lines, its year anywhere in it (a long
        # title can fill six lines), up to the next entry's label.
        entry, whole = _below(book, target[0], target[2], 40), _below(book, target[0], target[2], 240)
        whole = whole[: whole.find("[", whole.find("]")) % (len(whole) + 1)]
        # Its first name and its year (a citation broken across lines has one part without the other).
        name = re.match(r"\W*(?!et\b|al\b|and\b)([^\W\d_]{2,})", cited)
        year = re.search(r"\b(1[89]|20)\d\d[a-z]?\b", cited)
        assert name or year or re.fullmatch(r"\W*(et al\.|n\.d\.)?\W*", cited), (
            f"page {index + 1}: a link reads {cited!r}"
        )
        assert name is None or name.group(1) in entry, f"page {index + 1}: {cited!r} leads to {entry!r}"
        assert year is None or year.group(0) in whole, f"page {index + 1}: {cited!r} leads to {whole!r}"
        checked += 1
    # As many citation links as the chapters' HTML has citations (a citation broken across lines is two).
    citation = re.compile(r'<a class="reference internal" href="[^"]*bibliography\.html#')
    cited = sum(len(citation.findall(book.article(p))) for p in course)
    assert cited > 50 and checked >= cited, (checked, cited)


def test_an_equation_reference_leads_to_its_equation(book):
    checked = 0
    for index, annot in _links(book.reader):
        target = _target(book, annot)
        if target is None:
            continue
        x1, y1, x2, y2 = (float(v) for v in annot["/Rect"])
        label = _words(book, index, x1, x2, y1 - 1, y2 + 1).replace(" ", "")
        if not re.fullmatch(r"\(\d+(\.\d+)?\)", label):
            continue
        # The number sits at the right of its equation, which may be tall (a matrix): within 200 pt.
        assert label in _below(book, target[0], target[2], 200).replace(" ", ""), (index + 1, label)
        checked += 1
    assert checked > 50, checked


def _hidden_cells(notebook: Path) -> int:
    cells = json.loads(notebook.read_text(encoding="utf-8"))["cells"]
    return sum(any(t.startswith("hide-") for t in c.get("metadata", {}).get("tags", [])) for c in cells)


def test_every_worked_answer_is_printed_whole(book):
    total = 0
    for path in [p for p in book.pages if p.startswith("notebooks/")]:
        # Each cell the notebook hides (its worked answers) is printed under the label "Answer" ...
        hidden = _hidden_cells(ROOT / path.replace(".html", ".ipynb"))
        labels = sum(
            run[0].strip() == book_pdf.ANSWER_LABEL for i in book.ranges[path] for run in book.runs[i]
        )
        assert labels == hidden, f"{path}: {labels} answers printed for {hidden} hidden cells"
        # ... with its code and its output, every line of it.
        text = book.text(path)
        folds = re.findall(r'<details class="[^"]*\bhide\b[^"]*">(.*?)</details>', book.article(path), re.S)
        assert len(folds) == hidden, path
        for fold in folds:
            lines = [
                flat(line)
                for pre in re.findall(r"<pre[^>]*>(.*?)</pre>", fold, re.S)
                for line in plain(pre).splitlines()
            ]
            missing = [line for line in lines if line and line not in text]
            assert lines and not missing, f"{path}: an answer printed without {missing[:3]}"
        total += hidden
    # The notebooks hide 102 worked answers at the time of writing; the count comes from them.
    assert total > 50, total


def test_no_line_of_code_is_cut(book):
    # Every line of every code box and text output of the book is in the PDF's text, whole: a line too
    # long for its box wraps instead of being cut at the box's edge (chromium leaves a cut line's hidden
    # part out of the PDF altogether).
    checked, cut = 0, []
    for path in book.pages:
        text = book.text(path)
        for pre in re.findall(r"<pre[^>]*>(.*?)</pre>", book.article(path), re.S):
            for line in plain(pre).splitlines():
                if line.strip():
                    checked += 1
                    if flat(line) not in text:
                        cut.append(f"{path}: {line.strip()[:90]}")
    assert checked > 2000 and not cut, f"{len(cut)} of {checked} lines cut, e.g. {cut[:5]}"


def test_nothing_is_wider_than_its_column(book):
    # A formula or a table wider than the page's column would be cut at the sheet's edge (a derivation's
    # long expression; the notation page's tables): the printer shrinks each to its column, then measures
    # every formula, table, code box and picture of the page as laid out for the sheet, and reports those
    # still wider than their column.
    found = re.search(
        r"(\d+) formulas or tables shrunk to their column, (\d+) elements wider than it", book.log
    )
    pages = [line for line in book.log.splitlines() if "wider than the page's column" in line]
    assert found and int(found.group(2)) == 0, (found and found.group(0), pages)


# TeX that MathJax prints as its own characters, one for one: letters, digits, operators, Greek letters,
# a subscript or a superscript (not both on one symbol: MathJax prints the superscript first).
_GREEK = dict(
    zip(
        "alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi pi rho sigma tau upsilon "
        "phi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Phi Psi Omega varepsilon varphi".split(),
        "αβγδϵζηθικλμνξπρστυϕχψωΓΔΘΛΞΠΣΦΨΩεφ",
        strict=True,
    )
)
_MATH = re.compile(r'<span class="math notranslate nohighlight">\\\((.*?)\\\)</span>', re.S)


def _as_printed(tex: str) -> str | None:
    """The characters MathJax prints for a simple formula, in order; None for any other formula."""
    if re.search(r"_(\{[^{}]*\}|\\?\w)\^|\^(\{[^{}]*\}|\\?\w)_", tex):
        return None
    out = []
    for token in re.findall(r"\\[A-Za-z]+|\\.|.", tex):
        if token.startswith("\\"):
            if token[1:] in _GREEK:
                out.append(_GREEK[token[1:]])
            elif token not in ("\\,", "\\;", "\\ ", "\\!"):
                return None
        elif token == "-":
            out.append("−")
        elif re.fullmatch(r"[A-Za-z0-9=+(),./<>|]", token):
            out.append(token)
        elif token not in "_^{} ":
            return None
    return "".join(out)


def test_the_mathematics_is_text_in_reading_order(book):
    # A paragraph of the course whose formulas are simple reads in the PDF's text as it does in the book,
    # each formula's characters in place: search finds a symbol, and a sentence copied keeps its formulas.
    checked, missing = 0, []
    for path in [p for p in book.pages if p.startswith(("notebooks/", "book/intro"))]:
        text = book.text(path)
        for paragraph in re.findall(r"<p>(.*?)</p>", book.article(path), re.S):
            formulas = [_as_printed(html.unescape(tex)) for tex in _MATH.findall(paragraph)]
            if not formulas or None in formulas:
                continue
            parts = _MATH.split(paragraph)  # text, tex, text, tex, ..., text
            expected = "".join(formulas[i // 2] if i % 2 else plain(part) for i, part in enumerate(parts))
            checked += 1
            if flat(expected) not in text:
                missing.append(f"{path}: {expected[:100]}")
    assert checked > 100 and not missing, f"{len(missing)} of {checked} paragraphs, e.g. {missing[:3]}"


def test_each_section_has_its_bookmark_at_its_heading(book):
    outline, checked = book.reader.outline, 0
    tops = [i for i, item in enumerate(outline) if not isinstance(item, list)]
    for path, at in zip(book.pages, tops, strict=True):
        children = outline[at + 1] if at + 1 < len(outline) and isinstance(outline[at + 1], list) else []
        headings = re.findall(r"<h2>(.*?)</h2>", book.article(path), re.S)
        assert len(children) == len(headings), (path, len(children), len(headings))
        for child, heading in zip(children, headings, strict=True):
            title = plain(heading).removesuffix("#").strip()
            page = book.reader.get_destination_page_number(child)
            assert child.title == title and page in book.ranges[path], (path, child.title, title)
            assert flat(title) in flat(_below(book, page, float(child.top), 100)), (path, title)
            checked += 1
    assert checked > 50, checked


def test_the_course_comes_first_and_the_api_reference_is_its_appendix(book):
    titles = [item.title for item in _chapters(book.reader)]
    appendix = book_pdf.appendix_pages()
    assert book.pages[-len(appendix) :] == appendix and all(
        t.startswith("Appendix") for t in titles[-len(appendix) :]
    )
    first = min(book.ranges[p].start for p in appendix)
    assert all(book.ranges[p].stop <= first for p in book.pages if p not in appendix)
    # The appendix is the API reference: its first page is the reference's, its pages end the PDF.
    assert "APIreference" in flat("".join(run[0] for run in book.runs[first]))
    assert book.ranges[appendix[-1]].stop == len(book.runs)
    assert f"the course is pages 1–{first} " in book.log
