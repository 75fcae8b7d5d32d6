"""Sphinx hooks for the raildyn book.

* Docstrings use ``|x|`` for a magnitude; reStructuredText would read it as a
  substitution, so the bars are escaped outside literals.
* sphinx-thebe's settings script can reach a page twice, which the browser
  reports as an error; repeated inline scripts are dropped.
* sphinx-book-theme leaves pydata-sphinx-theme's colour mode empty, which its
  script reports as an error; the mode starts as "auto" (follow the system).
* The executed notebooks carry the kernel's widget state. Without a kernel the
  state is dead weight (hundreds of kB of PNG per page), and every raildyn widget
  already brings its own kernel-free HTML, so the state is left out of the pages.
* Notebooks cite and cross-reference with plain Markdown links, ``[Kalker 1967](cite:kalker1967)``
  and ``[(eq-creepages)](eq:eq-creepages)``, which read as text in JupyterLab and under Voilà
  (where a ``{cite}`` role would show its raw markup); as the book reads a notebook they
  become the ``{cite}`` and ``{eq}`` roles, so the book keeps its numbered equations and its
  bibliography. :func:`cite_text` writes the link text from the bibliography.
* The chapters are numbered by the table of contents, and so are their equations, (7.12); a
  notebook's title keeps its own number for JupyterLab ("# 7 Lateral stability"), which the book
  drops. A code cell (an answer's comment) cites an equation by its label, "(eq-cd-limit)", which
  JupyterLab shows beside the equation; the book prints the equation's number there instead.
* The notation page writes its symbols in plain text ("ω_n", "f₁₁"); the book typesets that
  column as the chapters do (:func:`symbol_tex`).
* The ``validation-table`` directive writes the validation page's tables from the
  checks the test suite recorded (``book/_generated/validation.json``, see
  ``tests/conftest.py``); when there is no record yet it runs those checks first
  (``pytest -m reference``), so ``make book`` alone still gets a complete page. Its numbers
  are written as a reader writes them (2.5 × 10⁻¹⁵) and kept on one line.
* The book's own style sheet, ``static/raildyn-book.css``: numbers on one line, answers that
  wrap instead of scrolling sideways, tables that fit their column.
* Sphinx keeps every page's document tree to the end of the build: Python's cycle collector
  scanned them all again at each full collection (10.5 s of the student edition's 38 s). The
  modules loaded by then are frozen out of its scans, and a full collection waits for a hundred
  middle ones instead of ten (:func:`collect_less`): the edition builds in 33 s, its peak memory
  3 % higher.
"""

import gc
import json
import re
import subprocess
import sys
from collections import defaultdict
from pathlib import Path

from docutils import nodes
from docutils.nodes import make_id
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

logger = logging.getLogger(__name__)

_ROOT = Path(__file__).resolve().parents[2]
_RECORD = _ROOT / "book" / "_generated" / "validation.json"

_LITERAL = re.compile(r"(``.*?``)")

_BIB_ENTRY = re.compile(r"@\w+\{([^,\s]+),(.*?)\n\}", re.S)
_CITE_LINK = re.compile(r"\[[^\[\]]*\]\(cite:([^)\s]+)\)")
_EQ_LINK = re.compile(r"\[[^\[\]]*\]\(eq:([^)\s]+)\)")


def _field(body: str, name: str) -> str:
    match = re.search(rf"\b{name}\s*=\s*[{{\"](.*?)[}}\"]\s*,?\s*\n", body, re.S)
    return re.sub(r"[{}]", "", match.group(1)).strip() if match else ""


_ACCENTS = {"'": "\u0301", "`": "\u0300", '"': "\u0308", "^": "\u0302", "~": "\u0303", "v": "\u030c"}


def _latin(text: str) -> str:
    """LaTeX accents and quotes as the characters they stand for: Fr\\'yba → Frýba."""
    import unicodedata

    text = re.sub(r"\\([`'\"^~v])\{?(\w)\}?", lambda m: m.group(2) + _ACCENTS[m.group(1)], text)
    return unicodedata.normalize("NFC", text.replace("``", "“").replace("''", "”"))


def load_bib() -> dict:
    """Every entry of the book's bibliographies: key → (authors, year) as the .bib files write them."""
    entries = {}
    for path in sorted((_ROOT / "book").glob("*.bib")):
        for key, body in _BIB_ENTRY.findall(path.read_text(encoding="utf-8")):
            body += "\n"
            who = _field(body, "author") or _field(body, "editor")
            entries[key] = (_latin(who), _field(body, "year"), _latin(_field(body, "title")))
    return entries


def cite_text(keys: str, bib: dict) -> str:
    """The text a reader sees for a citation outside the book: "Kalker 1967", "Chu et al. 1979"."""
    out = []
    for key in keys.split(","):
        authors, year, title = bib[key.strip()]
        names = [a.strip() for a in authors.split(" and ") if a.strip()]
        last = [n.split(",")[0] if "," in n else n.split()[-1] for n in names]
        if not names or (len(names) == 1 and "," not in names[0] and len(names[0].split()) > 3):
            # No person named (a standard, a web page): the title's lead, "ISO 2631-1:1997".
            who = re.split(r"[:(]| -- ", title)[0].strip()
            who = " ".join(who.split()[:3]) if who else key.strip()
        elif len(last) == 1:
            who = last[0]
        elif len(last) == 2:
            who = f"{last[0]} and {last[1]}"
        else:
            who = f"{last[0]} et al."
        out.append(f"{who} {year}".strip())
    return "; ".join(out)


_CHAPTER_TITLE = re.compile(r"\A(#\s+)\d+\s+")


def book_roles(app, docname, source):
    """A notebook's citation and equation links become the book's {cite} and {eq} roles, and its title
    ("# 7 Lateral stability") loses the number the book's numbered table of contents puts before it."""
    if not docname.startswith("notebooks/"):
        return
    notebook = json.loads(source[0])
    titled = False
    for cell in notebook["cells"]:
        if cell["cell_type"] == "markdown":
            text = "".join(cell["source"])
            if not titled:
                text, titled = _CHAPTER_TITLE.sub(r"\1", text), True
            text = _CITE_LINK.sub(lambda m: "{cite}`" + m.group(1) + "`", text)
            cell["source"] = _EQ_LINK.sub(lambda m: "{eq}`" + m.group(1) + "`", text)
    source[0] = json.dumps(notebook, ensure_ascii=False)


_GREEK = {
    "α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "ε": "varepsilon", "ζ": "zeta", "η": "eta",
    "θ": "theta", "ϑ": "vartheta", "κ": "kappa", "λ": "lambda", "μ": "mu", "ν": "nu", "ξ": "xi", "π": "pi",
    "ρ": "rho", "σ": "sigma", "τ": "tau", "ϕ": "phi", "φ": "varphi", "χ": "chi", "ψ": "psi", "ω": "omega",
    "Γ": "Gamma", "Δ": "Delta", "Θ": "Theta", "Λ": "Lambda", "Ξ": "Xi", "Σ": "Sigma", "Φ": "Phi",
    "Ψ": "Psi", "Ω": "Omega", "ℓ": "ell", "·": "cdot", "⟨": "langle", "⟩": "rangle",
}  # fmt: skip
_SUBSCRIPTS = dict(zip("₀₁₂₃₄₅₆₇₈₉", "0123456789", strict=True))
_SUPERSCRIPTS = dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹", "0123456789", strict=True))
_ACCENT_TEX = {"\u0302": "hat", "\u0304": "bar"}
_SCRIPT_CHAR = re.compile(r"[A-Za-z0-9]|[α-ωΑ-Ωϑϕℓ]")


def _tex_run(text: str) -> str:
    """Letters, digits and Greek as TeX: "sψ" → "s\\psi"."""
    return "".join(rf"\{_GREEK[c]} " if c in _GREEK else c for c in text).strip()


def symbol_tex(symbol: str) -> str:
    """TeX for a symbol as the notation page writes it in plain text: "ω_n" → "\\omega_n", "f₁₁" →
    "f_{11}", "**G**_K" → "\\mathbf{G}_K", "F^tr" → "F^{\\text{tr}}", "m̄" → "\\bar{m}", "σ_Y²" →
    "\\sigma_Y^2"."""
    out, i = [], 0
    while i < len(symbol):
        c = symbol[i]
        if symbol.startswith("**", i):
            end = symbol.index("**", i + 2)
            out.append(rf"\mathbf{{{_tex_run(symbol[i + 2 : end])}}}")
            i = end + 2
        elif c in "_^":
            j = i + 1
            while j < len(symbol) and _SCRIPT_CHAR.fullmatch(symbol[j]):
                j += 1
            run = symbol[i + 1 : j]
            if not run:
                raise ValueError(f"{c} without a script in the symbol {symbol!r}")
            word = c == "^" and len(run) > 1 and run.isalpha()  # F^tr: a label, upright
            script = rf"\text{{{run}}}" if word else _tex_run(run)
            out.append(f"{c}{{{script}}}" if len(run) > 1 or word else f"{c}{script}")
            i = j
        elif c in _SUBSCRIPTS or c in _SUPERSCRIPTS:
            table, mark = (_SUBSCRIPTS, "_") if c in _SUBSCRIPTS else (_SUPERSCRIPTS, "^")
            j = i
            while j < len(symbol) and symbol[j] in table:
                j += 1
            digits = "".join(table[d] for d in symbol[i:j])
            out.append(f"{mark}{{{digits}}}" if len(digits) > 1 else f"{mark}{digits}")
            i = j
        elif i + 1 < len(symbol) and symbol[i + 1] in _ACCENT_TEX:
            out.append(rf"\{_ACCENT_TEX[symbol[i + 1]]}{{{_tex_run(c)}}}")
            i += 2
        else:
            out.append(rf"\{_GREEK[c]} " if c in _GREEK else c)
            i += 1
    return re.sub(r" (?=[_^(),\s]|$)", "", "".join(out)).strip()


def _symbols_as_math(cell: str) -> str:
    """The symbol column's "s₁, s₂, s_r" as "$s_1$, $s_2$, $s_r$" (a comma inside parentheses stays)."""
    parts, depth, start = [], 0, 0
    for k, c in enumerate(cell):
        depth += (c in "(⟨") - (c in ")⟩")
        if c == "," and depth == 0:
            parts.append(cell[start:k])
            start = k + 1
    parts.append(cell[start:])
    return ", ".join(f"${symbol_tex(p.strip())}$" for p in parts if p.strip())


def notation_math(app, docname, source):
    """The notation page writes its symbols in plain text (tests/test_notation.py reads them so); the
    book typesets the symbol column as the chapters do: "ω_n" becomes $\\omega_n$."""
    if docname != "book/notation":
        return
    lines = source[0].split("\n")
    for n, line in enumerate(lines):
        if line.startswith("| ") and not line.startswith("| symbol |"):
            first, bar, rest = line[2:].partition(" | ")
            lines[n] = f"| {_symbols_as_math(first)}{bar}{rest}"
    source[0] = "\n".join(lines)


_EQ_LABEL_IN_CODE = re.compile(r"\((eq-[\w-]+)\)")


def equation_numbers_in_code(app, doctree, docname):
    """A code cell (an answer's comment) cites an equation by its label, "(eq-cd-limit)", which is what
    JupyterLab shows beside the equation; the book shows the equation's number there, "(2.5)"."""
    if not docname.startswith("notebooks/"):
        return
    env = app.env
    equations = env.get_domain("math").equations

    def number(match):
        label = match.group(1)
        where = equations.get(label)
        numbers = ()
        if where:
            numbered = env.toc_fignumbers.get(where[0], {}).get("displaymath", {})
            numbers = numbered.get(make_id(f"equation-{label}"), ())
        if not numbers:
            logger.warning(f"a code cell cites {match.group(0)}, which no equation numbers", location=docname)
            return match.group(0)
        return "(" + ".".join(map(str, numbers)) + ")"

    for block in doctree.findall(nodes.literal_block):
        text = block.astext()
        cited = _EQ_LABEL_IN_CODE.sub(number, text)
        if cited != text:
            block.rawsource = cited
            block.children = []
            block += nodes.Text(cited)


def _escape(line: str) -> str:
    if line.lstrip().startswith((">>>", "...", "+-", "| ")):  # doctests, tables, line blocks stay
        return line
    parts = _LITERAL.split(line)
    return "".join(p if p.startswith("``") else p.replace("|", r"\|") for p in parts)


def escape_bars(app, what, name, obj, options, lines):
    lines[:] = [_escape(line) for line in lines]


def drop_widget_state(app, pagename, templatename, context, doctree):
    metadata = getattr(app.env, "nb_metadata", {}).get(pagename, {})
    metadata.get("js_files", {}).pop("ipywidgets_state", None)


def drop_repeated_scripts(app, pagename, templatename, context, doctree):
    seen, kept = set(), []
    for script in context.get("script_files", []):
        # An inline script may come with filename None or "" for the same body.
        attributes = tuple(sorted(getattr(script, "attributes", {}).items()))
        key = (getattr(script, "filename", script) or "", attributes)
        if key not in seen:
            seen.add(key)
            kept.append(script)
    context["script_files"] = kept


def set_colour_mode(app, pagename, templatename, context, doctree):
    if not context.get("default_mode"):
        context["default_mode"] = "auto"


def _record() -> dict:
    """The recorded checks; the reference tests are run first when nothing is recorded."""
    if not _RECORD.exists():
        subprocess.run(
            [sys.executable, "-m", "pytest", "-q", "-m", "reference", "-p", "no:cacheprovider", "tests"],
            cwd=_ROOT, capture_output=True, text=True, timeout=1800, check=False,
        )  # fmt: skip
    return json.loads(_RECORD.read_text()) if _RECORD.exists() else {}


_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def number(value: float) -> str:
    """A measured number as a reader writes it, to two significant digits: 0.0037, 2.5 × 10⁻¹⁵, 1.2 × 10⁴."""
    if value == 0:
        return "0"
    mantissa, exponent = f"{value:.1e}".split("e")
    exponent = int(exponent)
    if -3 <= exponent <= 3:
        text = f"{float(mantissa) * 10.0**exponent:.6g}"
    else:
        mantissa = mantissa.rstrip("0").rstrip(".")
        power = "10" + str(exponent).translate(_SUPERSCRIPT)
        text = power if mantissa in ("1", "-1") else f"{mantissa}\u00a0\u00d7\u00a0{power}"
        text = "-" + power if mantissa == "-1" else text
    return text.replace("-", "\u2212")


class _OneLine(str):
    """A cell's text kept on one line (a kind of reference: "python-control")."""


def _cell(cell) -> nodes.entry:
    """A table cell: text, text kept on one line, or (number, unit) whose number is kept on one line."""
    entry, paragraph = nodes.entry(), nodes.paragraph()
    if isinstance(cell, tuple):
        value, unit = cell
        paragraph += nodes.inline(text=number(value), classes=["raildyn-number"])
        if unit:
            paragraph += nodes.Text(f" {unit}")
    elif isinstance(cell, _OneLine):
        paragraph += nodes.inline(text=str(cell), classes=["raildyn-number"])
    else:
        paragraph += nodes.Text(str(cell))
    entry += paragraph
    return entry


def _table(rows) -> nodes.table:
    """A docutils table with a header row; a (number, unit) cell keeps its number on one line."""
    header = ("model", "reference", "kind", "error", "tolerance", "within")
    table = nodes.table(classes=["validation"])
    group = nodes.tgroup(cols=len(header))
    table += group
    group.extend(nodes.colspec(colwidth=w) for w in (30, 30, 12, 10, 10, 6))
    head, body = nodes.thead(), nodes.tbody()
    group += head
    group += body
    for target, cells in ((head, header), *((body, r) for r in rows)):
        row = nodes.row()
        for cell in cells:
            row += _cell(cell)
        target += row
    return table


def _unit(check) -> str:
    """A check's unit after its numbers; none for a relative error."""
    return check["unit"] if check.get("unit", "rel.") != "rel." else ""


def _count(n: int, noun: str) -> str:
    """The count and its noun: 1 check, 3 checks."""
    return f"{n} {noun}" + ("" if n == 1 else "s")


class ValidationTable(SphinxDirective):
    """Every recorded check of a model against its reference, by chapter, with its error and tolerance."""

    def run(self):
        record = _record()
        if not record:
            return [nodes.paragraph(text="No reference check has been recorded: run `make test`.")]
        by_chapter = defaultdict(list)
        for check in sorted(record.values(), key=lambda c: (c["chapter"], c["model"], c["reference"])):
            by_chapter[check["chapter"]].append(check)
        within = sum(c["within"] for c in record.values())
        out = [
            nodes.paragraph(
                text=f"{_count(len(record), 'check')} in {_count(len(by_chapter), 'chapter')}; {within} of "
                f"them ({100 * within / len(record):.0f} %) within their tolerance."
            )
        ]
        for chapter, checks in sorted(by_chapter.items()):
            section = nodes.rubric(text=f"Chapter {chapter} ({_count(len(checks), 'check')})")
            rows = [
                (c["model"], c["reference"], _OneLine(c["kind"]), (c["error"], _unit(c)),
                 (c["tolerance"], _unit(c)), "yes" if c["within"] else "NO")
                for c in checks
            ]  # fmt: skip
            out += [section, _table(rows)]
        return out


def add_static(app, config):
    """The book's own style sheet and script (book/_ext/static/raildyn-book.css, .js) are copied with the
    theme's."""
    config.html_static_path.append(str(Path(__file__).with_name("static")))


def collect_less() -> None:
    """Leave the loaded modules out of the cycle collector's scans, and scan the rest a tenth as often."""
    gc.collect()
    gc.freeze()
    gc.set_threshold(700, 10, 100)  # Python's default: (700, 10, 10)


def setup(app):
    collect_less()
    app.connect("config-inited", add_static)
    app.add_css_file("raildyn-book.css")
    app.add_js_file("raildyn-book.js")
    app.add_directive("validation-table", ValidationTable)
    app.connect("autodoc-process-docstring", escape_bars)
    app.connect("source-read", book_roles)
    app.connect("source-read", notation_math)
    app.connect("doctree-resolved", equation_numbers_in_code)
    # Before myst-nb (priority 500) adds the page's scripts.
    app.connect("html-page-context", drop_widget_state, priority=400)
    app.connect("html-page-context", drop_repeated_scripts, priority=900)
    app.connect("html-page-context", set_colour_mode, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
