"""The notation page (book/notation.md): one meaning per symbol, code names that exist, and the
collisions it resolved kept out of the notebooks."""

from __future__ import annotations

import importlib
import re
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[1]
PAGE = ROOT / "book" / "notation.md"
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))
SOURCE = "\n".join(p.read_text(encoding="utf-8") for p in (ROOT / "raildyn").rglob("*.py"))


def _rows() -> list[list[str]]:
    rows = []
    for line in PAGE.read_text(encoding="utf-8").splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("|") and len(cells) == 6 and cells[0] not in ("symbol", "---"):
            rows.append(cells)
    return rows


def test_the_page_is_in_the_book():
    assert "book/notation" in (ROOT / "book" / "_toc.yml").read_text()
    assert len(_rows()) > 60


def test_each_symbol_has_one_meaning():
    seen = {}
    for symbol, meaning, *_ in _rows():
        for s in (x.strip() for x in symbol.split(",")):
            assert s not in seen, f"{s!r} means both {seen[s]!r} and {meaning!r}"
            seen[s] = meaning


def test_every_code_name_exists_in_the_package():
    missing = []
    for symbol, _, _, code, *_ in _rows():
        for name in re.findall(r"`([^`]+)`", code):
            if name.startswith('"') or name.startswith("."):
                continue  # a coordinate label pattern, e.g. "… y"
            if name.startswith("raildyn."):
                importlib.import_module(name)
                continue
            head, _, attr = name.partition(".")
            if attr:  # Class.field: the class exists and names the field
                if not re.search(rf"class {head}\b", SOURCE) or not re.search(rf"\b{attr}\b", SOURCE):
                    missing.append((symbol, name))
            elif not re.search(rf"\b{re.escape(name.lstrip('.'))}\b", SOURCE):
                missing.append((symbol, name))
    assert not missing, f"code names the package does not have: {missing}"


# Uses the notation page retired: (pattern in a notebook's Markdown, what replaced it).
RETIRED = [
    (r"\\zeta\b", "ξ for a damping ratio"),
    (r"\\xi_[xy{]|\\xi_\{[LR]|w_\\xi|\\xi\s*=\s*x", "γ_x, γ_y for creepages; x̄ for x − vt"),
    (r"\\eta\b", "γ_y for the lateral creepage"),
    (r"\\delta\s*\(|\\delta_(?![D{]|jk)|\\delta_\{(?!D\}|jk\})", "δ_D for Dirac; ϑ for contact angles; Δx_i"),
    (r"[ξδζ][₀₁₂_]", "the page's symbols"),
]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebooks_keep_the_retired_symbols_out(path):
    text = "\n".join(c.source for c in nbformat.read(path, as_version=4).cells if c.cell_type == "markdown")
    found = [(m.group(0), why) for pattern, why in RETIRED for m in re.finditer(pattern, text)]
    assert not found, f"{path.name}: {found[:8]}"
    if path.stem[:2] not in ("01", "11"):  # δ is the logarithmic decrement, chapters 1 and 11
        # δ before a coordinate is the variation of virtual work (δx, δw, δψ): an operator, allowed
        bare = re.findall(
            r"\\delta(?![_a-zA-Z])(?!\s*(?:\\,)?\s*(?:[a-zA-Z]|\\(?:psi|theta|phi|mathbf)))", text
        )
        assert not bare, f"{path.name}: δ used for something other than the logarithmic decrement"
