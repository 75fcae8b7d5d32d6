"""The book printed, then its text read once: the background job whose result ``tests/test_pdf.py`` checks.

It runs ``scripts/book_pdf.py`` as ``make pdf`` does, then reads every sheet's text runs with pypdf and
writes them beside the PDF (``<pdf>.runs.json``). The reading is half a minute of one core: done here, it
runs beside the other tests as soon as the PDF exists, instead of after them in the test that reads it.

Usage: ``python tests/pdf_text.py HTML_DIR OUT_PDF``
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def runs_path(pdf: Path) -> Path:
    """Where the runs of ``pdf`` are written."""
    return pdf.with_name(pdf.name + ".runs.json")


def read_runs(pdf: Path) -> list[list[tuple[str, float, float, str]]]:
    """Per sheet: ``[(text, x, y, kind)]`` as pypdf's visitor reports them, in pt from the bottom left.

    The kind is "text"; "math" for MathJax's fonts (Type 3), whose reported position can be a few pt off
    its baseline; or "stretched" for the middle of a tall delimiter (a matrix's bracket): one glyph drawn
    through a scaled matrix, which chromium paints after the text of the page (as it paints any
    transformed box) and whose characters ("⎢") are no part of the reading."""
    from pypdf import PdfReader

    runs = []
    for page in PdfReader(pdf).pages:
        found = []

        def visit(text, cm, tm, font, size, found=found):
            x, y = tm[4] * cm[0] + tm[5] * cm[2] + cm[4], tm[4] * cm[1] + tm[5] * cm[3] + cm[5]
            kind = "text"
            if (font or {}).get("/Subtype") == "/Type3":
                kind = "math" if abs(abs(cm[3]) - abs(cm[0])) <= 1e-3 * abs(cm[0]) else "stretched"
            found.append((text, x, y, kind))

        page.extract_text(visitor_text=visit)
        runs.append(found)
    return runs


def load_runs(pdf: Path) -> list[list[tuple[str, float, float, str]]]:
    """The runs this script wrote for ``pdf`` (JSON keeps every float exactly)."""
    return [[tuple(run) for run in page] for page in json.loads(runs_path(pdf).read_text(encoding="utf-8"))]


def main(html: Path, pdf: Path) -> int:
    printed = subprocess.run([sys.executable, str(ROOT / "scripts" / "book_pdf.py"), str(html), str(pdf)])
    if printed.returncode != 0:
        return printed.returncode
    runs_path(pdf).write_text(json.dumps(read_runs(pdf)), encoding="utf-8")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__.rpartition("Usage: ")[2])
    sys.exit(main(Path(sys.argv[1]), Path(sys.argv[2])))
