"""What a course needs from every chapter notebook: objectives, self-checks, exercises, a summary and
the schematics of its models, drawn by raildyn.diagrams."""

from __future__ import annotations

import re
from pathlib import Path

import nbformat
import pytest

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
