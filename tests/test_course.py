"""What a course needs from every chapter notebook: objectives, self-checks, exercises, a summary and
the schematics of its models, drawn by raildyn.diagrams."""

from __future__ import annotations

import re
from pathlib import Path

import nbformat
import pytest

from raildyn.course.page import ANSWER_LINE

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))

# The schematic each chapter's models need (issue 21): raildyn.diagrams functions its notebook calls.
SCHEMATICS = {
    "01": ("oscillator_model", "rigid_body_freedoms"),
    "05": ("wheelset_section", "wheelset_plan"),
    "06": ("car_side", "truck_schematic"),
    "07": ("bogie_plan", "car_plan"),
    "09": ("coupler_chain",),
    "10": ("beam_load",),
}


def _markdown(path) -> list[str]:
    return [c.source for c in nbformat.read(path, as_version=4).cells if c.cell_type == "markdown"]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_each_chapter_opens_with_objectives_and_ends_with_a_summary(path):
    text = _markdown(path)
    assert any("**Learning objectives.**" in t for t in text[:3]), (
        f"{path.name}: no learning objectives at the top"
    )
    assert any(re.match(r"## Summary", t) for t in text), f"{path.name}: no summary"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_each_chapter_has_self_checks_and_five_exercises(path):
    text = "\n".join(_markdown(path))
    checks = text.split("### Check yourself", 1)
    assert len(checks) == 2, f"{path.name}: no 'Check yourself' section"
    assert len(re.findall(r"^\*\*[a-z]\.\*\*", checks[1].split("## ", 1)[0], flags=re.M)) >= 2, (
        f"{path.name}: fewer than two self-check questions"
    )
    exercises = text.split("## Exercises", 1)
    assert len(exercises) == 2 and len(re.findall(r"^\*\*\d+\.\*\*", exercises[1], flags=re.M)) >= 5, (
        f"{path.name}: fewer than five exercises"
    )


@pytest.mark.parametrize("chapter", sorted(SCHEMATICS))
def test_each_model_is_drawn_in_its_notebook(chapter):
    path = next(p for p in NOTEBOOKS if p.stem.startswith(chapter))
    code = "\n".join(c.source for c in nbformat.read(path, as_version=4).cells if c.cell_type == "code")
    missing = [f for f in SCHEMATICS[chapter] if not re.search(rf"\b{f}\(", code)]
    assert not missing, f"{path.name}: the schematics {missing} of raildyn.diagrams are not drawn"


# --------------------------------------------------------------------------- the course page

COURSE = ROOT / "book" / "course.md"
WORDS_A_MINUTE = 25  # the page's reading speed for the chapters' text


def _weeks() -> list[list[str]]:
    rows = []
    for line in COURSE.read_text(encoding="utf-8").splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("|") and len(cells) == 6 and cells[0].isdigit():
            rows.append(cells)
    return rows


def test_the_course_page_plans_twelve_weeks_over_every_chapter():
    assert "book/course" in (ROOT / "book" / "_toc.yml").read_text()
    weeks = _weeks()
    assert [int(w[0]) for w in weeks] == list(range(1, 13))
    linked = {name for w in weeks for name in re.findall(r"</notebooks/([\w]+)>", w[1])}
    assert linked == {p.stem for p in NOTEBOOKS}
    assert all(w[2] and w[3] for w in weeks)  # core and optional sections every week


def test_the_course_page_times_each_week_from_its_chapters_text():
    # Each chapter's reading time (its Markdown at the page's words a minute) is shared equally among
    # the weeks that take it; the page states each week's sum to the nearest half hour (±0.5 h lets a
    # chapter grow a little before the page must be updated).
    share = {}
    weeks = _weeks()
    for path in NOTEBOOKS:
        words = sum(len(s.split()) for s in _markdown(path))
        taking = [w for w in weeks if f"/notebooks/{path.stem}>" in w[1]]
        for w in taking:
            share[w[0]] = share.get(w[0], 0.0) + words / WORDS_A_MINUTE / 60 / len(taking)
    for w in weeks:
        stated = float(w[5].removesuffix(" h"))
        assert abs(stated - share[w[0]]) <= 0.5, (w[0], stated, round(share[w[0]], 2))


def test_the_capstone_follows_one_car_with_a_rubric():
    text = COURSE.read_text(encoding="utf-8")
    capstone = text.split("## The capstone project")[1]
    for chapter in ("5 and 7", "chapter 7", "chapter 6", "chapter 8", "chapter 10", "chapter 11"):
        assert chapter in capstone
    weights = [int(m) for m in re.findall(r"\| (\d+) % \|", capstone)]
    assert len(weights) == 7 and sum(weights) == 100


# --------------------------------------------------------------------------- exercises worth setting

LEVELS = ("Warm-up", "Standard", "Challenge")
KINDS = ("derive", "compute", "explain", "design", "predict-then-check")
_LABEL = re.compile(r"^\*\*(\d+)\.\*\* \*([\w-]+) · ([\w-]+)\.\*")
ANSWER_TAG = "hide-cell"  # every worked answer's tag (tests/test_notebooks.py holds it)


def _exercises(path) -> list[tuple[str, str, str, int]]:
    """(number, level, kind, index of its answer cell) of each exercise of a notebook, in order."""
    cells = nbformat.read(path, as_version=4).cells
    start = next(
        i for i, c in enumerate(cells) if c.cell_type == "markdown" and c.source.startswith("## Exercises")
    )
    found = []
    for i in range(start, len(cells)):
        cell = cells[i]
        if cell.cell_type != "markdown":
            continue
        for line in cell.source.splitlines():
            if re.match(r"^\*\*\d+\.\*\*", line):
                label = _LABEL.match(line)
                assert label, f"{path.name}: exercise without its level and kind: {line[:80]}"
                answer = next(j for j in range(i + 1, len(cells)) if cells[j].cell_type == "code")
                found.append((*label.groups(), answer))
    return found


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_each_exercise_states_its_level_and_kind(path):
    exercises = _exercises(path)
    assert [int(e[0]) for e in exercises] == list(range(1, len(exercises) + 1)), f"{path.name}: numbering"
    for number, level, kind, _ in exercises:
        assert level in LEVELS and kind in KINDS, f"{path.name} exercise {number}: {level} · {kind}"
    levels = {e[1] for e in exercises}
    assert {"Warm-up", "Challenge"} <= levels, (
        f"{path.name}: levels {levels}, a warm-up and a challenge wanted"
    )
    assert "predict-then-check" in {e[2] for e in exercises}, f"{path.name}: no predict-then-check exercise"


def _derive_answers(path) -> list[int]:
    """The answer cells of the derive exercises that call lagrange and check the matrices they get
    (a chapter may also set a derivation by hand)."""
    cells = nbformat.read(path, as_version=4).cells
    derive = [answer for _, _, kind, answer in _exercises(path) if kind == "derive"]
    return [i for i in derive if "lagrange(" in cells[i].source and "check_matrices(" in cells[i].source]


@pytest.mark.parametrize("path", [p for p in NOTEBOOKS if p.stem[:2] <= "10"], ids=lambda p: p.stem)
def test_chapters_one_to_ten_set_two_derivations_checked_against_the_model(path):
    answers = _derive_answers(path)
    assert len(answers) >= 2, f"{path.name}: {len(answers)} derive exercises call lagrange and check_matrices"


@pytest.mark.slow
@pytest.mark.parametrize("path", [p for p in NOTEBOOKS if p.stem[:2] <= "10"], ids=lambda p: p.stem)
def test_each_worked_derivation_passes_its_check(path, built_book):
    # The book executed every notebook (book/_build/jupyter_execute keeps them with their outputs, cells
    # in the same order): each derive answer's verdict, folded in its output, must read right. An answer
    # may go on to change one term on purpose and show the slip named (a ✗ after the ✓ of the derivation).
    proc, _ = built_book
    assert proc.returncode == 0, (proc.stdout + proc.stderr)[-4000:]
    executed = nbformat.read(ROOT / "book" / "_build" / "jupyter_execute" / "notebooks" / path.name, 4)
    for i in _derive_answers(path):
        shown = " ".join(
            str(o.get("data", {}).get("text/html", o.get("text", ""))) for o in executed.cells[i].outputs
        )
        assert re.search(r"✓ \d+ \(expected \d+\): right", shown), f"{path.name} cell {i}: {shown[-300:]}"


def _comment_words(code: str) -> int:
    return sum(
        len(line.strip().lstrip("#").split()) for line in code.splitlines() if line.strip().startswith("#")
    )


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_every_worked_answer_folds_and_explains_its_reasoning(path):
    # "#| answer" keeps the output folded when the notebook runs (JupyterLab unfolds a cell's outputs when
    # it runs it; the lecture-room app shows no answer), and, as the first line, is all a collapsed cell
    # shows of it; the comments beneath say why, in words beside the numbers.
    cells = nbformat.read(path, as_version=4).cells
    code = [c.source for c in cells if c.cell_type == "code"]
    loads = next((k for k, s in enumerate(code) if "%load_ext raildyn.course" in s), None)
    answers = [
        k
        for k, c in enumerate(c for c in cells if c.cell_type == "code")
        if ANSWER_TAG in c.metadata.get("tags", [])
    ]
    assert answers and loads is not None and loads < answers[0], (
        f"{path.name}: %load_ext raildyn.course first"
    )
    for k in answers:
        first, _, rest = code[k].partition("\n")
        assert first == ANSWER_LINE, f"{path.name}: an answer does not start with #| answer: {first[:60]}"
        assert _comment_words(rest) >= 15, f"{path.name}: an answer explains too little: {rest[:120]}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_no_cell_but_an_answer_uses_what_an_answer_defines(path):
    # The student edition removes the answers and the lecture-room app does not run them: the chapter
    # must run without them, so no other cell may read a name that an answer was the last to define.
    import ast

    from test_notation import python  # a cell's code without its line magics (the one definition)

    last, wrong = {}, []
    for i, cell in enumerate(nbformat.read(path, as_version=4).cells):
        if cell.cell_type != "code":
            continue
        tree = ast.parse(python(cell.source))
        answer = ANSWER_TAG in cell.metadata.get("tags", [])
        if not answer:
            reads = {n.id for n in ast.walk(tree) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)}
            wrong += [(i, name) for name in sorted(reads) if last.get(name)]
        names = {n.id for n in ast.walk(tree) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)}
        names |= {n.name for n in ast.walk(tree) if isinstance(n, ast.FunctionDef | ast.ClassDef)}
        imports = (n for n in ast.walk(tree) if isinstance(n, ast.Import | ast.ImportFrom))
        names |= {a.asname or a.name.split(".")[0] for n in imports for a in n.names}
        last |= dict.fromkeys(names, answer)
    assert not wrong, f"{path.name}: cells that read what only an answer defined: {wrong[:5]}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_each_chapter_asks_questions_that_check_themselves_in_the_page(path):
    cells = nbformat.read(path, as_version=4).cells
    start = next(
        i for i, c in enumerate(cells) if c.cell_type == "markdown" and "### Check yourself" in c.source
    )
    end = next(
        i
        for i in range(start + 1, len(cells))
        if cells[i].cell_type == "markdown" and cells[i].source.startswith("## ")
    )
    checks = [c for c in cells[start:end] if c.cell_type == "code" and "course.SelfCheck(" in c.source]
    assert len(checks) >= 2, f"{path.name}: {len(checks)} self-checks, two wanted"
    for c in checks:
        assert "remove-input" in c.metadata.get("tags", []), f"{path.name}: a self-check shows its code"


# --------------------------------------------------------------------------- the student edition


def _answer_sentences(source: str) -> list[str]:
    """The comment lines of an answer long enough to be its own words (six words or more)."""
    lines = (line.strip().lstrip("#").strip() for line in source.splitlines() if line.strip().startswith("#"))
    return [line for line in lines if len(line.split()) >= 6]


@pytest.mark.slow
@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_the_student_edition_keeps_the_questions_and_no_answer(student_book, path):
    import html as markup

    proc, pages = student_book
    log = proc.stdout + proc.stderr
    assert proc.returncode == 0 and "WARNING" not in log.replace("[IPKernelApp] WARNING", ""), log[-4000:]
    page = (pages / "notebooks" / f"{path.stem}.html").read_text(encoding="utf-8")
    text = markup.unescape(re.sub(r"<[^>]+>", " ", page))
    flat = " ".join(text.split())
    assert "tag_hide-cell" not in page and "raildyn-answer" not in page, f"{path.name}: an answer is left"
    cells = nbformat.read(path, as_version=4).cells
    answers = [c.source for c in cells if ANSWER_TAG in c.metadata.get("tags", [])]
    left = [s for a in answers for s in _answer_sentences(a) if " ".join(s.split()) in flat]
    assert not left, f"{path.name}: answer text in the student edition: {left[:3]}"
    for number, _, _, _ in _exercises(path):
        assert f"{number}." in flat, f"{path.name}: exercise {number} is missing"
    assert len(re.findall(r"raildyn-selfcheck", page)) >= 2, f"{path.name}: its self-checks are missing"


def test_chapter_seven_marks_its_freight_and_locomotive_part_optional():
    # Chapter 7 is the longest; its freight cars and locomotives are optional reading, in the notebook's
    # heading as in the course page, so that a week's reading stays a week's.
    path = next(p for p in NOTEBOOKS if p.stem.startswith("07"))
    assert any(t.startswith("## Freight cars and locomotives (optional)") for t in _markdown(path))
    week = next(w for w in _weeks() if w[0] == "8")
    assert "freight cars and locomotives" in week[3] and "freight" not in week[2]
