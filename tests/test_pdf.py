"""`make pdf`: the built book printed to one PDF by headless chromium (scripts/book_pdf.py)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "scripts"))

import book_pdf  # noqa: E402

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(not Path(book_pdf.CHROMIUM).exists(), reason="Debian's chromium is not installed"),
]


def test_the_book_prints_to_one_pdf_with_its_mathematics_typeset(built_book, tmp_path):
    from pypdf import PdfReader

    proc, html = built_book
    assert proc.returncode == 0, (proc.stdout + proc.stderr)[-4000:]
    out = tmp_path / "raildyn.pdf"
    count = book_pdf.print_book(html, out)
    reader = PdfReader(out)
    pages = book_pdf.toc_pages()
    # Every page of the table of contents prints to at least one sheet, each with its bookmark.
    assert len(reader.pages) == count >= len(pages)
    assert len(reader.outline) == len(pages)
    text = "\n".join(page.extract_text() for page in reader.pages)
    # MathJax typeset the mathematics: no TeX source left, and chapter 1's equation of motion is there
    # in typeset glyphs (the dots over x are combining accents in the PDF's text).
    assert "$$" not in text and "\\frac" not in text and "\\ddot" not in text
    assert "¨x" in text.replace(" ", "")
