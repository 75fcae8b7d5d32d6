"""The notation page (book/notation.md): one meaning per symbol, code names that exist, and the
collisions it resolved kept out of the notebooks."""

from __future__ import annotations

import ast
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


# --------------------------------------------------------------------------- one meaning for β, κ, λ, m̄

CHAPTERS = range(1, 12)


def _markdown(path: Path) -> str:
    return "\n".join(c.source for c in nbformat.read(path, as_version=4).cells if c.cell_type == "markdown")


def _chapter(path: Path) -> int:
    return int(path.stem[:2])


def _chapters(column: str) -> set[int]:
    """The chapters a row of the page names: "all", "5, 8", "3–8", "4–"."""
    if column.strip() == "all":
        return set(CHAPTERS)
    found = set()
    for part in column.split(","):
        low, dash, high = part.strip().partition("–")
        found |= set(range(int(low), int(high or max(CHAPTERS)) + 1)) if dash else {int(low)}
    return found


#: The symbols the page gives one meaning, with the TeX and Unicode forms a notebook may write them in.
ONE_MEANING = {
    "β": r"\\beta(?![a-zA-Z])|β",
    "κ": r"\\kappa(?![a-zA-Z])|κ",
    "λ": r"\\lambda(?![a-zA-Z])|λ",
    "m̄": r"\\bar\s*\{?m\b|\\overline\{m\}|m̄",
    "a_r": r"(?<![\\\w])a_(?:r|\{r\})(?![\w{])",
}


def _row_of(symbol: str) -> list[str]:
    rows = [row for row in _rows() if symbol in (s.strip() for s in row[0].split(","))]
    assert len(rows) == 1, f"{symbol} must have exactly one row on the notation page, has {len(rows)}"
    return rows[0]


def test_the_page_gives_each_of_these_symbols_one_meaning():
    local = PAGE.read_text(encoding="utf-8").split("## Symbols with a second, local meaning")[1]
    for symbol in ONE_MEANING:
        _row_of(symbol)
        assert not re.search(rf"^- {re.escape(symbol)}\b", local, re.M), f"{symbol} keeps a second meaning"


def _one_meaning_cases():
    for symbol in ONE_MEANING:
        for path in NOTEBOOKS:
            yield pytest.param(symbol, path, id=f"{symbol}-{path.stem[:2]}")


@pytest.mark.parametrize("symbol, path", list(_one_meaning_cases()))
def test_a_notebook_uses_these_symbols_only_where_the_page_gives_them(symbol, path):
    """β, κ, λ, m̄ and a_r appear only in the chapters of their one row: any other chapter that writes
    them means something else by them (β was Newmark's, Rayleigh's, a creep ratio, a yaw deflection
    and a beam's wavenumber; λ a conicity, an eigenvalue and a wavelength)."""
    chapters = _chapters(_row_of(symbol)[4])
    uses = re.findall(ONE_MEANING[symbol], _markdown(path))
    assert not uses or _chapter(path) in chapters, (
        f"{path.name} writes {symbol} {len(uses)} times; the page gives it to chapters {sorted(chapters)}"
    )


# Meanings the page took away from β, κ, λ and m̄, which the chapter check cannot see where the
# symbol keeps its own meaning: (pattern in a notebook's Markdown, what replaced it).
RETIRED += [
    (r"e\^\{\\lambda t\}|\\lambda_\{?[i12]|\|\\lambda\||\\mathrm\{Re\}\\,\\lambda|eigenvalues?\s+\$\\lambda",
     "s_r for an eigenvalue; λ is the conicity"),
    (r"wavelengths?\s+\$\\lambda|2\\pi\s*[xV]?\s*/\\lambda|\\lambda\s*=\s*(?:\d+[bl]\b|\d*b/|d/i)",
     "L_w for a wavelength; λ is the conicity"),
    (r"\\alpha\\mathbf M\s*\+\s*\\beta", "a_M, a_K for Rayleigh's coefficients"),
    (r"m_i\s*-\s*\\bar m|\\bar p\b", "⟨m⟩, ⟨p⟩ for the means of records; m̄ is a mass per length"),
    (r"\\frac\{EI\}\{m\}|2P/\(mL|mass \$m\$ per unit length|\\frac\{4kEI\}\{m\^2\}",
     "m̄ for a beam's mass per length"),
]  # fmt: skip


# --------------------------------------------------------------------------- cross-level and rail spacing


def test_the_cross_level_is_delta_z_over_the_rail_spacing_as_the_code_has_it():
    """The notebooks write the cross-level Δz (c is a damping) and its roll of the rails as Δz/(2a_r),
    2a_r the rail spacing over which a cross-level is measured, as a cant is: what
    raildyn.wheelset.add_wheelset builds, held here with a half gauge other than the default (so that
    the contact spacing 2a and the 1.5 m rail spacing differ)."""
    from raildyn.constants import STANDARD_RAIL_SPACING
    from raildyn.linear_model import Assembler
    from raildyn.wheelset import Wheelset, add_wheelset

    for path in NOTEBOOKS:
        text = _markdown(path)
        found = re.findall(
            r"c/\(2a\)|\\frac\{W\s*c\}\{2a\}|Wc/\(2a\)|"
            r"\\Delta z\}?\s*/\s*\(?2a(?!_r)|\\frac\{W\s*\\Delta z\}\{2a\}",
            text,
        )
        assert not found, f"{path.name}: {found}"
    ws = Wheelset(half_gauge=0.7)
    asm = Assembler(["y", "ψ"], n_inputs=1)
    add_wheelset(asm, "y", "ψ", ws, cross_level=0)
    system = asm.system(input_positions=[0.0], input_kinds=["cross_level"])
    # -W Δz/(2a_r) on the lateral row, nothing on the yaw row: exact (one division)
    assert system.GK[0, 0] == -ws.axle_load / STANDARD_RAIL_SPACING
    assert system.GK[1, 0] == 0.0


def _math(text: str) -> list[str]:
    return re.findall(r"\$\$.*?\$\$|\$[^$]*\$", text, re.S)


def test_the_cant_is_stated_over_the_rail_spacing_2a_r_everywhere():
    """One symbol for the base of the cant: 2a_r, the rail spacing of raildyn.track.cant (chapter 8 wrote
    2a, chapter 5 2a_r); 2a stays the contact spacing."""
    for path in NOTEBOOKS:
        bad = [m for m in _math(_markdown(path)) if "h_t" in m and re.search(r"2a(?![_\w])", m)]
        assert not bad, f"{path.name}: a cant over 2a, not 2a_r: {bad[:3]}"
    for module in ("cant", "curve"):
        docs = (ROOT / "raildyn" / "track" / f"{module}.py").read_text(encoding="utf-8")
        assert not re.search(r"2a(?![_\w])", docs), f"raildyn.track.{module} states the rail spacing as 2a"


# --------------------------------------------------------------------------- FRA classes at speeds they allow

# 49 CFR 213.9(a) (classes 1–5) and 213.307(a) (class 6), mph, (freight, passenger): the published table.
CFR_213 = {1: (10, 15), 2: (25, 30), 3: (40, 60), 4: (60, 80), 5: (80, 90), 6: (110, 110)}

#: Vehicles that run in freight service: a run of one of them is held to the freight limit.
FREIGHT = {
    "EMPTY_FREIGHT_CAR", "LOADED_FREIGHT_CAR", "LATERAL_LOCOMOTIVE", "DEFAULT_LOCOMOTIVE",
    "VerticalFreightCar", "GDU_ORE_CAR", "LateralFreightCar", "VerticalLocomotive", "LateralLocomotive",
}  # fmt: skip


def test_the_speed_limits_are_the_regulation_s():
    from raildyn.constants import MPH
    from raildyn.track import FRA_CLASSES, FRA_SPEED_LIMITS_MPH, fra_speed_limit

    assert set(FRA_SPEED_LIMITS_MPH) == set(FRA_CLASSES)
    for c, (freight, passenger) in CFR_213.items():
        assert FRA_SPEED_LIMITS_MPH[c] == {"freight": freight, "passenger": passenger}
        # the exact mile (1609.344 m): to rounding
        assert fra_speed_limit(c, "freight") == pytest.approx(freight * 1609.344 / 3600, rel=1e-15)
        assert fra_speed_limit(c) == pytest.approx(passenger * MPH, rel=1e-15)
    with pytest.raises(ValueError, match="track_class must be an integer in"):
        fra_speed_limit(7)
    with pytest.raises(ValueError, match="service must be one of"):
        fra_speed_limit(4, "mixed")


def _fra_classes(node: ast.AST) -> set[int]:
    """FRA classes given as numbers to the spectrum builders inside ``node``."""
    positions = {"track_psd": 2, "band_variance": 2, "TrackSpectrum": 2, "synthesize_track": 1, "fra_psd": 1}
    found = set()
    for call in (n for n in ast.walk(node) if isinstance(n, ast.Call)):
        name = getattr(call.func, "attr", getattr(call.func, "id", ""))
        if name not in positions or len(call.args) <= positions[name]:
            continue
        if name != "fra_psd" and not (isinstance(call.args[0], ast.Constant) and call.args[0].value == "fra"):
            continue
        grade = call.args[positions[name]]
        if isinstance(grade, ast.Constant) and isinstance(grade.value, int):
            found.add(grade.value)
    return found


def _speeds_kmh(tree: ast.AST) -> set[float]:
    """The speeds in km/h a cell writes as numbers: ``x / 3.6`` with x a number, or a loop variable over
    numbers (a tuple of numbers in the cell where the loop runs over a name)."""
    divided = [n for n in ast.walk(tree) if isinstance(n, ast.BinOp) and isinstance(n.op, ast.Div)
               and isinstance(n.right, ast.Constant) and n.right.value == 3.6]  # fmt: skip
    speeds = {float(n.left.value) for n in divided if isinstance(n.left, ast.Constant)}
    names = {n.left.id for n in divided if isinstance(n.left, ast.Name)}
    arguments = {id(a) for n in ast.walk(tree) if isinstance(n, ast.Call) for a in n.args}
    tuples = [
        n
        for n in ast.walk(tree)
        if isinstance(n, ast.Tuple)
        and n.elts
        and id(n) not in arguments  # a range passed to a function (a speed bracket) is not a run
        and all(isinstance(e, ast.Constant) and isinstance(e.value, (int, float)) for e in n.elts)
    ]
    for loop in (n for n in ast.walk(tree) if isinstance(n, ast.For)):
        if isinstance(loop.target, ast.Name) and loop.target.id in names:
            if isinstance(loop.iter, (ast.Tuple, ast.List)):
                speeds |= {float(e.value) for e in loop.iter.elts if isinstance(e, ast.Constant)}
            else:  # over a name bound elsewhere in the cell: every tuple of numbers counts
                speeds |= {float(e.value) for t in tuples for e in t.elts}
    return speeds


def _limit_kmh(classes, freight: bool) -> float:
    from raildyn.track import fra_speed_limit

    return 3.6 * min(fra_speed_limit(c, "freight" if freight else "passenger") for c in classes)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_fra_classes_run_at_speeds_they_allow(path):
    """Every FRA class a notebook runs, in code or in its text, at a speed written there, stays within
    the speed its class allows (passenger trains, or freight trains for a freight vehicle)."""
    cells = nbformat.read(path, as_version=4).cells
    spectra: dict[str, set[int]] = {}  # a name bound to FRA spectra in an earlier cell
    bad = []
    for cell in cells:
        if cell.cell_type != "code":
            continue
        tree = ast.parse(python(cell.source))
        names = {n.id for n in ast.walk(tree) if isinstance(n, ast.Name)}
        classes = _fra_classes(tree) | set().union(*(spectra.get(n, set()) for n in names))
        for node in (n for n in ast.walk(tree) if isinstance(n, ast.Assign)):
            if _fra_classes(node.value):
                for target in (t for t in node.targets if isinstance(t, ast.Name)):
                    spectra[target.id] = _fra_classes(node.value)
        if not classes:
            continue
        limit = _limit_kmh(classes, freight=bool(names & FREIGHT))
        bad += [(sorted(classes), v, round(limit, 1)) for v in _speeds_kmh(tree) if v > limit]
    for sentence in re.split(r"(?<=[.;?])\s", _markdown(path).replace("\n", " ")):
        classes = {int(c) for c in re.findall(r"\bclass(?:es)? ([1-6])\b", sentence)}
        classes |= {int(c) for c in re.findall(r"\bclasses [1-6] and ([1-6])\b", sentence)}
        speeds = [float(v) for v in re.findall(r"(\d+(?:\.\d+)?) km/h", sentence)]
        if classes and speeds:
            limit = _limit_kmh(classes, freight=bool(re.search(r"freight|locomotive", sentence, re.I)))
            bad += [(sorted(classes), v, round(limit, 1)) for v in speeds if v > limit]
    assert not bad, f"{path.name}: (classes, km/h run, km/h allowed): {bad}"


def test_the_fra_speed_check_sees_a_run_above_the_limit():
    # the check above must see what it is for: class 4 at 160 km/h, in code and in text
    tree = ast.parse(
        'psd = track.track_psd("fra", "vertical", 4)\nfor kmh in (80, 160):\n    f(psd, kmh / 3.6)'
    )
    assert _fra_classes(tree) == {4} and _speeds_kmh(tree) == {80.0, 160.0}
    assert 160.0 > _limit_kmh({4}, freight=False) > 120.0
    assert _limit_kmh({4}, freight=True) < 100.0


# --------------------------------------------------------------------------- order of the chapters

#: Models first derived in a later chapter, by the names a notebook's code reaches them.
DERIVED_IN = {"MANCHESTER_CAR": 7, "LATERAL_LOCOMOTIVE": 7, "EMPTY_FREIGHT_CAR": 7, "LOADED_FREIGHT_CAR": 7}


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_a_model_from_a_later_chapter_is_pointed_forward_to(path):
    """A notebook that uses a model before the chapter that derives it says so in the section that
    first uses it: "derived in chapter N"."""
    cells = nbformat.read(path, as_version=4).cells
    for name, chapter in DERIVED_IN.items():
        if chapter <= _chapter(path):
            continue
        uses = [i for i, c in enumerate(cells) if c.cell_type == "code" and name in _loaded(c.source)]
        first = uses[0] if uses else None
        if first is None:
            continue
        heading = max(
            i for i, c in enumerate(cells[:first]) if c.cell_type == "markdown" and "\n## " in "\n" + c.source
        )
        section = "\n".join(c.source for c in cells[heading:first] if c.cell_type == "markdown")
        assert re.search(rf"derived in chapter {chapter}", section), (
            f"{path.name} uses {name} (derived in chapter {chapter}) without saying so in its section"
        )


def python(source: str) -> str:
    """A cell's code as Python: its IPython line magics (``%load_ext …``) left out."""
    return "\n".join(line for line in source.splitlines() if not line.lstrip().startswith("%"))


def _loaded(source: str) -> set[str]:
    """The names a cell's code uses (an import alone does not count)."""
    return {n.id for n in ast.walk(ast.parse(python(source))) if isinstance(n, ast.Name)}


# --------------------------------------------------------------------------- no development talk

DEVELOPMENT = re.compile(
    r"\b(issues?|todo|fixme|sessions?|development|will be added|to be added|work in progress|coming soon|"
    r"placeholder|still wanted|not yet implemented)\b",
    re.I,
)


def _public_docstrings():
    for path in sorted((ROOT / "raildyn").rglob("*.py")):
        if any(part.startswith("_") and part != "__init__.py" for part in path.relative_to(ROOT).parts):
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef)) and ast.get_docstring(node):
                yield f"{path.relative_to(ROOT)}:{getattr(node, 'name', 'module')}", ast.get_docstring(node)


def test_no_student_facing_text_talks_of_development():
    texts = [(p.name, _markdown(p)) for p in NOTEBOOKS]
    texts += [(p.name, p.read_text(encoding="utf-8")) for p in sorted((ROOT / "book").glob("*.md"))]
    texts += list(_public_docstrings())
    found = [(where, m.group(0)) for where, text in texts for m in DEVELOPMENT.finditer(text)]
    assert not found, f"text about the project's own making: {found[:10]}"
    assert DEVELOPMENT.search("This will be added in a later version.")  # the check can fail
