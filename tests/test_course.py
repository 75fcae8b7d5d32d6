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
