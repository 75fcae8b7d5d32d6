"""raildyn.course: an answer checked and its slip named, per-student variants, a class marked."""

from __future__ import annotations

import csv
import math

import pytest

from raildyn import course
from raildyn.__main__ import main
from raildyn.constants import GRAVITY


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
