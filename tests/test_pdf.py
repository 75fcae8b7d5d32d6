"""`make pdf`: the built book printed to one PDF by headless chromium (scripts/book_pdf.py), in the
background from the moment the book is built (tests/conftest.py), checked here."""

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


def test_the_book_prints_to_one_pdf_with_its_mathematics_typeset(printed_book):
    from pypdf import PdfReader

    proc, log, out = printed_book
    assert proc.returncode == 0, log[-4000:]
    reader = PdfReader(out)
    pages = book_pdf.toc_pages()
    # Every page of the table of contents prints to at least one sheet, each with its bookmark.
    assert f"({len(reader.pages)} pages)" in log and len(reader.pages) >= len(pages)
    assert len(reader.outline) == len(pages)
    text = "\n".join(page.extract_text() for page in reader.pages)
    # MathJax typeset the mathematics: no TeX source left, and chapter 1's equation of motion is there
    # in typeset glyphs (the dots over x are combining accents in the PDF's text).
    assert "$$" not in text and "\\frac" not in text and "\\ddot" not in text
    assert "¨x" in text.replace(" ", "")
