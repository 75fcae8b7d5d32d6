"""The Jupyter Book builds from the repository root with zero warnings (-W -n --keep-going)."""

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))


@pytest.mark.slow
def test_book_builds_without_warnings(built_book):
    proc, html = built_book
    log = proc.stdout + proc.stderr
    assert proc.returncode == 0, log[-6000:]
    # -W already turns Sphinx warnings into a failed build; this also catches ones printed without it.
    # The executing kernel's own start-up notice (transport encryption) is not the book's.
    warnings = [line for line in log.splitlines() if "WARNING" in line and "[IPKernelApp]" not in line]
    assert not warnings, "\n".join(warnings)
    assert (html / "index.html").exists()


@pytest.mark.slow
def test_book_has_chapter_one_with_offline_mathjax(built_book):
    _, html = built_book
    page = (html / "notebooks" / "01_analysis_of_dynamic_systems.html").read_text(encoding="utf-8")
    assert "_static/mathjax/tex-chtml.js" in page, "MathJax is not the bundled copy"
    assert (html / "_static" / "mathjax" / "tex-chtml.js").exists()
    remote = re.findall(r'<(?:script|link|img)[^>]*(?:src|href)="(https?://[^"]+)"', page)
    assert not remote, f"the page loads from the network: {remote}"
    assert "Logarithmic decrement" in page or "logarithmic decrement" in page
    assert page.count("<img") >= 4, "the executed notebook's figures are missing"


@pytest.mark.slow
def test_no_progress_bar_is_left_frozen_on_a_page(built_book):
    _, html = built_book
    for page in (html / "notebooks").glob("*.html"):
        assert "0%|" not in page.read_text(encoding="utf-8"), f"{page.name} shows a progress bar stuck at 0 %"


@pytest.mark.slow
def test_no_page_names_the_machine_it_was_built_on(built_book):
    # A path of the build (a data file's location, shown as a constant's value) means nothing to a reader,
    # and its length, which differs from machine to machine, once widened the printed API page.
    _, html = built_book
    for page in html.rglob("*.html"):
        assert str(ROOT) not in page.read_text(encoding="utf-8"), f"{page.relative_to(html)} names {ROOT}"


@pytest.mark.slow
def test_book_links_its_repository_and_its_issues(built_book):
    # A course reports errata where the book's buttons point: both come from repository.url.
    import yaml

    _, html = built_book
    config = yaml.safe_load((html.parents[1] / "_config.yml").read_text(encoding="utf-8"))
    url = config["repository"]["url"]
    page = (html / "book" / "intro.html").read_text(encoding="utf-8")
    assert f'href="{url}"' in page, "no repository button"
    assert f'href="{url}/issues' in page, "no issues button"


# --- pages that read well ---------------------------------------------------------------------------


class _ReadableText:
    """The text a reader sees on a page outside code and typeset mathematics: what is left once the
    <script>, <style>, <pre>, <code> and MathJax's own elements (class "math") are taken out."""

    _SKIP_TAGS = {"script", "style", "pre", "code", "textarea"}
    _VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source", "wbr"}

    def __init__(self, page: str):
        from html.parser import HTMLParser

        outer, parts, stack = self, [], []

        class Parser(HTMLParser):
            def handle_starttag(self, tag, attrs):
                if tag in outer._VOID:
                    return
                classes = (dict(attrs).get("class") or "").split()
                stack.append(tag in outer._SKIP_TAGS or "math" in classes or "highlight" in classes)

            def handle_endtag(self, tag):
                if tag not in outer._VOID and stack:
                    stack.pop()

            def handle_data(self, data):
                if not any(stack):
                    parts.append(data)

        Parser(convert_charrefs=True).feed(page)
        self.text = "".join(parts)


@pytest.mark.slow
def test_no_page_shows_raw_dollar_mathematics(built_book):
    # Chapter 7's list item showed "$$ y'' = … $$" as text: MyST leaves $…$ it could not parse as literal
    # dollars. Every formula is typeset, so no "$" is left in what a reader sees.
    _, html = built_book
    found = {}
    for page in sorted(html.rglob("*.html")):
        text = _ReadableText(page.read_text(encoding="utf-8")).text
        hits = [text[max(0, m.start() - 40) : m.start() + 40] for m in re.finditer(r"\$", text)]
        if hits:
            found[str(page.relative_to(html))] = hits[:3]
    assert not found, found


def test_the_dollar_finder_sees_raw_dollars_and_not_code_or_typeset_mathematics():
    page = (
        '<p>With <span class="math notranslate">\\(\\psi\\)</span>: $$ y = 1 $$</p>'
        "<pre>x = '$'</pre><p>in <code>$HOME</code></p>"
    )
    assert _ReadableText(page).text.count("$") == 4


@pytest.mark.slow
def test_captions_name_what_a_figure_shows_not_its_id(built_book):
    _, html = built_book
    captions = 0
    for path in NOTEBOOKS:
        page = (html / "notebooks" / f"{path.stem}.html").read_text(encoding="utf-8")
        chapter = int(path.stem[:2])
        for n, caption in enumerate(re.findall(r"<figcaption>(.*?)</figcaption>", page, re.S), start=1):
            captions += 1
            assert caption.startswith(f"Figure {chapter}.{n}"), f"{path.stem}: {caption[:50]!r}"
            assert not re.search(r"\bfig\d+\.\w", caption), (
                f"{path.stem}: the caption shows an id: {caption[:50]!r}"
            )
    assert captions >= 26


@pytest.mark.slow
def test_equations_are_numbered_within_their_chapter_and_answers_cite_numbers(built_book):
    # (7.12), not the twelfth of a book-wide count; an answer's "(eq-cd-limit)" prints as "(2.12)".
    _, html = built_book
    for path in NOTEBOOKS:
        page = (html / "notebooks" / f"{path.stem}.html").read_text(encoding="utf-8")
        chapter = int(path.stem[:2])
        numbers = re.findall(r'<span class="eqno">\((\d+)\.(\d+)\)', page)
        if numbers:
            assert {int(c) for c, _ in numbers} == {chapter}, f"{path.stem}: {numbers[:5]}"
            assert [int(n) for _, n in numbers] == list(range(1, len(numbers) + 1)), path.stem
        cited = re.findall(
            r'class="reference internal"[^>]*><span class="std std-ref">\(([\d.]+)\)|>\(([\d.]+)\)</a>', page
        )
        assert all(re.fullmatch(r"\d+\.\d+", a or b) for a, b in cited), f"{path.stem}: {cited[:5]}"
        code = " ".join(re.findall(r"<pre>(.*?)</pre>", page, re.S))
        assert "(eq-" not in code, f"{path.stem}: a code cell cites an equation by its label"
        # The chapter's heading carries its number once: "7. Lateral stability", not "7. 7 Lateral …".
        title = re.search(r'<h1><span class="section-number">([^<]*)</span>([^<]*)<', page)
        assert title and title.group(1) == f"{chapter}. ", f"{path.stem}: {title and title.group(0)}"
        assert not re.match(r"\s*\d", title.group(2)), f"{path.stem}: the number twice: {title.group(0)}"
    answers = (html / "notebooks" / "02_numerical_methods.html").read_text(encoding="utf-8")
    assert "T_min/π (2." in answers


@pytest.mark.slow
def test_answers_fold_under_a_bar_that_says_answer(built_book):
    _, html = built_book
    for path in NOTEBOOKS:
        page = (html / "notebooks" / f"{path.stem}.html").read_text(encoding="utf-8")
        assert "Show code cell" not in page, path.stem
        folds = re.findall(
            r'<details class="[^"]*\bhide\b[^"]*">\s*<summary[^>]*>\s*<p[^>]*>([^<]*)</p>', page
        )
        assert folds and set(folds) == {"Answer"}, f"{path.stem}: {set(folds)}"


@pytest.mark.slow
def test_validation_page_counts_and_names_read_as_prose(built_book):
    _, html = built_book
    page = (html / "book" / "validation.html").read_text(encoding="utf-8")
    counts = re.findall(r"\((\d+) (checks?)\)", page)
    assert counts, "no chapter headings with their count of checks"
    assert all((n == "1") == (word == "check") for n, word in counts), counts
    rows = re.findall(r"<tr[^>]*><td><p>(.*?)</p></td>\s*<td><p>(.*?)</p></td>", page, re.S)
    assert len(rows) >= 100
    for model, against in rows:
        for text in (model, against):
            assert not re.search(r"\b[a-z]{2,}_[a-z]{2,}", text), (
                f"a code name on the validation page: {text!r}"
            )
            assert not re.search(r"\b(fra|german)\b", text), f"a lower-case code value: {text!r}"
    numbers = re.findall(r'<span class="raildyn-number">([^<]*)</span>', page)
    assert len(numbers) >= 2 * len(rows)
    assert not [n for n in numbers if re.search(r"\de[+-]?\d", n)], "a number in programmers' notation"


@pytest.mark.slow
def test_notation_page_typesets_every_symbol(built_book):
    _, html = built_book
    page = (html / "book" / "notation.html").read_text(encoding="utf-8")
    cells = re.findall(r"<tr[^>]*>\s*<td><p>(.*?)</p></td>", page, re.S)
    assert len(cells) >= 120
    plain = [
        c
        for c in cells
        if not re.fullmatch(r'(<span class="math notranslate nohighlight">[^<]*</span>(, )?)+', c)
    ]
    assert not plain, f"symbols the notation page leaves as plain text: {plain[:5]}"


def test_symbol_tex_writes_the_chapters_tex():
    import sys

    sys.path.insert(0, str(ROOT / "book" / "_ext"))
    from raildyn_book import _symbols_as_math, symbol_tex

    assert symbol_tex("ω_n") == r"\omega_n"
    assert symbol_tex("f₁₁") == "f_{11}"
    assert symbol_tex("**G**_K") == r"\mathbf{G}_K"
    assert symbol_tex("k_sψ") == r"k_{s\psi}"
    assert symbol_tex("F^tr") == r"F^{\text{tr}}"
    assert symbol_tex("m̄") == r"\bar{m}"
    assert symbol_tex("σ_Y²") == r"\sigma_Y^2"
    assert symbol_tex("Δψ_j") == r"\Delta \psi_j"
    assert _symbols_as_math("s₁, s₂, s_r") == "$s_1$, $s_2$, $s_r$"
    assert _symbols_as_math("Λ(x, x_P)") == r"$\Lambda(x, x_P)$"


def test_validation_numbers_read_as_a_reader_writes_them():
    import sys

    sys.path.insert(0, str(ROOT / "book" / "_ext"))
    from raildyn_book import number

    times = "\u00a0×\u00a0"  # no break either side of the ×
    assert [number(v) for v in (0.0, 2.5e-15, 1e-10, 0.0037, 0.42, 1.0, 1.2e4, -3e-5)] == [
        "0", f"2.5{times}10⁻¹⁵", "10⁻¹⁰", "0.0037", "0.42", "1", f"1.2{times}10⁴", f"−3{times}10⁻⁵",
    ]  # fmt: skip


@pytest.mark.slow
def test_every_internal_link_reaches_its_target(built_book):
    # A link inside the book goes to a page that exists and, with a fragment, to an element it has.
    from urllib.parse import unquote, urlparse

    _, html = built_book
    ids: dict = {}
    broken, checked = [], 0
    for page in sorted(html.rglob("*.html")):
        for href in re.findall(r'<a\b[^>]*\bhref="([^"]*)"', page.read_text(encoding="utf-8")):
            link = urlparse(href)
            if link.scheme or href.startswith("//"):
                continue
            checked += 1
            target = (page.parent / unquote(link.path)).resolve() if link.path else page
            if target.is_dir():
                target = target / "index.html"
            if not target.exists():
                broken.append((page.name, href))
            elif link.fragment and target.suffix == ".html":
                if target not in ids:
                    ids[target] = set(re.findall(r'\bid="([^"]+)"', target.read_text(encoding="utf-8")))
                if unquote(link.fragment) not in ids[target]:
                    broken.append((page.name, href))
    assert checked > 1000 and not broken, broken[:10]
