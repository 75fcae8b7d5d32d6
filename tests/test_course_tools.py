"""raildyn.course: an answer checked and its slip named, per-student variants, a class marked."""

from __future__ import annotations

import csv
import math

import pytest

from raildyn import course
from raildyn.__main__ import main
from raildyn.constants import GRAVITY
from raildyn.course.page import ANSWER_FOLD


@pytest.mark.parametrize(
    ("answer", "words"),
    [
        (-1.5, "sign"),
        (1.5 * 2 * math.pi, "rad/s where Hz"),
        (1.5 / (2 * math.pi), "Hz where rad/s"),
        (1500.0, "1000 times too large"),
        (1.5 * 3.6, "km/h where m/s"),
        (1.5 * GRAVITY, "weight (N) where a mass"),
        (math.degrees(1.5), "degrees where radians"),
        (3.0, "twice too large"),
        (2.25, "a variance where an RMS"),
        (1.5**0.5, "an RMS value where a variance"),
        (1.9, "off by 26.7 %"),
    ],
)
def test_a_wrong_answer_is_told_its_slip(answer, words):
    verdict = course.check(answer, 1.5)
    assert not verdict.correct and words in verdict.reason, verdict.reason


def test_a_right_answer_within_its_tolerance():
    assert course.check(1.514, 1.5).correct  # 0.9 % off, tolerance 1 %
    assert not course.check(1.516, 1.5).correct  # 1.07 % off
    assert course.check(1.59, 1.5, rtol=0.0, atol=0.1).correct
    # A slip outside the tolerance is not named: 2π·1.5 off by 5 % is just off.
    assert "off by" in course.check(1.05 * 2 * math.pi * 1.5, 1.5).reason
    assert "0.2 from zero" in course.check(0.2, 0.0, atol=0.1).reason


def test_each_student_has_their_own_values_and_answer():
    ex = course.Exercise(
        "bounce", lambda m, k: (k / m) ** 0.5 / (2 * math.pi), {"m": (800, 1200), "k": (1e6, 2e6)}
    )
    a, b = ex.variant("s001"), ex.variant("s002")
    assert a == ex.variant("s001") and a != b  # the same id, the same values; another id, others
    assert all(800 <= v["m"] <= 1200 and 1e6 <= v["k"] <= 2e6 for v in (a, b))
    assert a["m"] == float(f"{a['m']:.3g}")  # rounded to what the student reads
    assert ex.expected("s001") == pytest.approx((a["k"] / a["m"]) ** 0.5 / (2 * math.pi), rel=1e-15)
    assert ex.check("s001", ex.expected("s001") * 2 * math.pi).reason.startswith("2π times too large")
    # Over many students the values spread over their interval.
    ms = [ex.variant(f"s{i:03d}")["m"] for i in range(200)]
    assert min(ms) < 850 and max(ms) > 1150


def test_a_class_is_marked_from_a_csv(tmp_path, capsys):
    from raildyn.vehicles import VerticalCar

    key = tmp_path / "key.py"
    key.write_text(
        "from raildyn.course import Exercise\n"
        "from raildyn.vehicles import VerticalCar\n"
        "def bounce(k):\n"
        "    return VerticalCar(secondary_stiffness=k).body_frequencies().bounce_hz\n"
        "EXERCISES = [Exercise('bounce', bounce, {'k': (4e5, 1.2e6)})]\n"
    )

    def bounce(k):
        return VerticalCar(secondary_stiffness=k).body_frequencies().bounce_hz

    ex = course.Exercise("bounce", bounce, {"k": (4e5, 1.2e6)})
    right = ex.expected("ann")
    answers = tmp_path / "answers.csv"
    with answers.open("w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["student", "exercise", "answer"])
        wrong = 2 * math.pi * ex.expected("bob")  # rad/s for Hz
        w.writerows([["ann", "bounce", f"{right:.4f}"], ["bob", "bounce", f"{wrong:.4f}"],
                     ["cat", "bounce", "about one hertz"]])  # fmt: skip
    out = tmp_path / "marks.csv"
    assert main(["mark", str(answers), str(key), "--out", str(out)]) == 0
    with out.open(newline="") as f:
        rows = list(csv.DictReader(f))
    assert [r["correct"] for r in rows] == ["1", "0", "0"]
    assert "rad/s where Hz" in rows[1]["reason"] and rows[2]["reason"] == "not a number"
    assert "ann: 1 of 1" in capsys.readouterr().out


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="answer"):
        course.check(math.nan, 1.0)
    with pytest.raises(ValueError, match="rtol"):
        course.check(1.0, 1.0, rtol=2.0)
    with pytest.raises(ValueError, match="student"):
        course.Exercise("x", lambda: 1.0).variant("")
    with pytest.raises(ValueError, match="parameters"):
        course.Exercise("x", lambda a: a, {"a": (2.0, 1.0)})
    with pytest.raises(ValueError, match="names exercise"):
        course.mark(
            [{"student": "a", "exercise": "nope", "answer": "1"}], [course.Exercise("x", lambda: 1.0)]
        )


# --------------------------------------------------------------------------- derived matrices checked


def _two_masses():
    """Two masses on springs, derived by Lagrange's equations, and the same system by hand."""
    import sympy

    from raildyn.derivations import coordinates, lagrange

    m1, m2, k1, k2, c1 = sympy.symbols("m1 m2 k1 k2 c1", positive=True)
    x1, x2 = coordinates("x1 x2")
    T = (m1 * x1.diff() ** 2 + m2 * x2.diff() ** 2) / 2
    U = (k1 * x1**2 + k2 * (x2 - x1) ** 2) / 2
    D = c1 * x1.diff() ** 2 / 2
    values = {m1: 40.0, m2: 400.0, k1: 2.0e6, k2: 1.0e5, c1: 3.0e3}
    # By hand: M = diag(m1, m2), C = [[c1, 0], [0, 0]], K = [[k1 + k2, −k2], [−k2, k2]].
    model = ([[40.0, 0.0], [0.0, 400.0]], [[3.0e3, 0.0], [0.0, 0.0]], [[2.1e6, -1.0e5], [-1.0e5, 1.0e5]])
    return lagrange(T, U, D, [x1, x2]), model, values


def test_derived_matrices_that_agree_are_right():
    mine, model, values = _two_masses()
    verdict = course.check_matrices(mine, model, values)
    assert verdict.correct and verdict.reason == "right" and verdict.answer == 12  # 3 matrices × 4 entries


@pytest.mark.parametrize(
    ("change", "words"),
    [
        (lambda K: K * -1.0, "K[0, 0]: the sign is wrong"),
        (lambda K: K * 0.5, "K[0, 0]: twice too large"),
        (lambda K: K - [[0.0, 0.0], [0.0, 1.0e4]], "K[1, 1]: off by 11.1 %"),
    ],
)
def test_a_wrong_entry_is_named_with_its_slip(change, words):
    import numpy as np

    mine, model, values = _two_masses()
    wrong = (*model[:2], change(np.array(model[2])))  # the model changed: the derivation is now the slip
    verdict = course.check_matrices(mine, wrong, values)
    assert not verdict.correct and verdict.reason.startswith(words), verdict.reason


def test_the_model_labels_name_the_entry_and_an_order_or_a_size_is_told():
    import numpy as np

    from raildyn.linear_model import SystemMatrices

    mine, model, values = _two_masses()
    M, C, K = (np.array(a) for a in model)
    labelled = SystemMatrices(M, C, -K, np.zeros((2, 1)), np.zeros((2, 1)), ("wheel", "body"), 10.0)
    assert course.check_matrices(mine, labelled, values).reason.startswith("K[wheel, wheel]: the sign")
    swapped = [a[::-1, ::-1] for a in (M, C, K)]
    assert "another order" in course.check_matrices(mine, swapped, values).reason
    assert "1×1, the model's 2×2" in course.check_matrices([a[:1, :1] for a in (M, C, K)], model).reason


def test_a_symbol_without_its_number_is_named():
    mine, model, values = _two_masses()
    with pytest.raises(ValueError, match=r"derived M still holds the symbols \['m2'\]"):
        course.check_matrices(mine, model, {k: v for k, v in values.items() if str(k) != "m2"})


# --------------------------------------------------------------------------- the page's own checks


def test_a_self_check_keeps_its_answer_out_of_plain_text_and_states_its_rules():
    import json
    import re

    number = course.SelfCheck("The wavelength, in metres?", 19.7, "m", rtol=0.05)
    assert "19.7" not in repr(number) and "wavelength" in repr(number)
    spec = json.loads(re.search(r"spec = (\{.*?\});", number._repr_html_()).group(1))
    assert spec["expected"] == 19.7 and spec["rtol"] == 0.05 and [2.0, spec["slips"][-2][1]] in spec["slips"]
    choice = course.SelfCheck("Which hunts?", choices=("the free wheelset", "neither"), right=0)
    assert 'type="radio"' in choice._repr_html_() and '"right": 0' in choice._repr_html_()
    with pytest.raises(ValueError, match="right"):
        course.SelfCheck("Which?", choices=("a", "b"), right=2)
    with pytest.raises(ValueError, match="expected must be a number"):
        course.SelfCheck("How far?")
    formula = course.SelfCheck("What is $L_b$ in metres?", 20.0)._repr_html_()
    assert '<span class="math notranslate nohighlight">\\(L_b\\)</span> in metres' in formula
    with pytest.raises(ValueError, match=r"question must pair its \$ signs"):
        course.SelfCheck("Costs $5?", 5.0)


def test_an_answer_folds_its_output_and_a_failing_answer_fails(tmp_path):
    import nbformat
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError

    cells = [
        "%load_ext raildyn.course\nimport matplotlib\nmatplotlib.use('agg')\nimport matplotlib.pyplot as plt",
        "#| answer\n# the reasoning\nprint('f = 1.5 Hz')\nfrom IPython.display import display, HTML\n"
        "display(HTML('<b>bold</b>'))\nimport sympy\nprint('then')\ndisplay(sympy.Matrix([[1, 2]]))\n3 * 7",
        "import os\nos.environ['VOILA_KERNEL_ID'] = 'k'",  # as the lecture-room app's kernel
        "#| answer\nprint('worked out in the app')",
        "del os.environ['VOILA_KERNEL_ID']",
        "#| answer\nraise ValueError('a slip')",
    ]
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in cells])
    client = NotebookClient(
        nb, timeout=120, kernel_name="python3", resources={"metadata": {"path": tmp_path}}
    )
    with pytest.raises(CellExecutionError, match="a slip"):
        client.execute()
    assert not nb.cells[3].outputs  # the app does not work an answer out
    (shown,) = nb.cells[1].outputs
    page = shown["data"]["text/html"]
    assert page.startswith(f'<details class="raildyn-answer"><summary>{ANSWER_FOLD}</summary>')
    # what was printed, then what was displayed in the order it was, a formula as the book marks one
    order = [
        "f = 1.5 Hz",
        "then",
        "<b>bold</b>",
        '<div class="math notranslate nohighlight">\\[',
        "<pre>21</pre>",
    ]
    at = [page.find(part) for part in order]
    assert -1 not in at and at == sorted(at), at
