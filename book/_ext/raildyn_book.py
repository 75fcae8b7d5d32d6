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
* The ``validation-table`` directive writes the validation page's tables from the
  checks the test suite recorded (``book/_generated/validation.json``, see
  ``tests/conftest.py``); when there is no record yet it runs those checks first
  (``pytest -m reference``), so ``make book`` alone still gets a complete page.
"""

import json
import re
import subprocess
import sys
from collections import defaultdict
from pathlib import Path

from docutils import nodes
from sphinx.util.docutils import SphinxDirective

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


def book_roles(app, docname, source):
    """A notebook's citation and equation links become the book's {cite} and {eq} roles."""
    if not docname.startswith("notebooks/"):
        return
    notebook = json.loads(source[0])
    for cell in notebook["cells"]:
        if cell["cell_type"] == "markdown":
            text = "".join(cell["source"])
            text = _CITE_LINK.sub(lambda m: "{cite}`" + m.group(1) + "`", text)
            cell["source"] = _EQ_LINK.sub(lambda m: "{eq}`" + m.group(1) + "`", text)
    source[0] = json.dumps(notebook, ensure_ascii=False)


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


def _table(rows) -> nodes.table:
    """A docutils table with a header row."""
    header = ("model", "reference", "kind", "error", "tolerance", "within")
    table = nodes.table(classes=["validation"])
    group = nodes.tgroup(cols=len(header))
    table += group
    group.extend(nodes.colspec(colwidth=w) for w in (30, 34, 12, 8, 8, 6))
    head, body = nodes.thead(), nodes.tbody()
    group += head
    group += body
    for target, cells in ((head, header), *((body, r) for r in rows)):
        row = nodes.row()
        for cell in cells:
            entry = nodes.entry()
            entry += nodes.paragraph(text=str(cell))
            row += entry
        target += row
    return table


def _unit(check) -> str:
    """A check's unit after its numbers; none for a relative error."""
    return f" {check['unit']}" if check.get("unit", "rel.") != "rel." else ""


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
                text=f"{len(record)} checks in {len(by_chapter)} chapters; {within} of them "
                f"({100 * within / len(record):.0f} %) within their tolerance."
            )
        ]
        for chapter, checks in sorted(by_chapter.items()):
            section = nodes.rubric(text=f"Chapter {chapter} ({len(checks)} checks)")
            rows = [
                (c["model"], c["reference"], c["kind"], f"{c['error']:.2g}{_unit(c)}",
                 f"{c['tolerance']:.2g}{_unit(c)}", "yes" if c["within"] else "NO")
                for c in checks
            ]  # fmt: skip
            out += [section, _table(rows)]
        return out


def setup(app):
    app.add_directive("validation-table", ValidationTable)
    app.connect("autodoc-process-docstring", escape_bars)
    app.connect("source-read", book_roles)
    # Before myst-nb (priority 500) adds the page's scripts.
    app.connect("html-page-context", drop_widget_state, priority=400)
    app.connect("html-page-context", drop_repeated_scripts, priority=900)
    app.connect("html-page-context", set_colour_mode, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
