"""Fuzz registry: the course's tools (answers checked, per-student variants, a class marked)."""

from __future__ import annotations

import math

from fuzzing import call, fuzz, on

from raildyn.course import Exercise, Verdict

EXERCISE = Exercise(
    "f", lambda m, k: math.sqrt(k / m) / (2 * math.pi), {"m": (800.0, 1200.0), "k": (1e6, 2e6)}
)
MATRICES = ([[2.0, 0.0], [0.0, 1.0]], [[0.0, 0.0], [0.0, 0.0]], [[8.0, -1.0], [-1.0, 3.0]])
ROWS = [
    {"student": "s1", "exercise": "f", "answer": "5.5"},
    {"student": "s2", "exercise": "f", "answer": "x"},
]

ENTRIES = [
    fuzz(
        "raildyn.course.check",
        lambda: call(1.51, 1.5, rtol=0.01, atol=0.0),
        # any finite answer is marked, even far off; a zero or huge expected value is a value like another
        accepts={
            "answer": "zero negative huge big tiny mm",
            "expected": "zero negative huge big tiny mm",
            "rtol": "zero tiny",
            "atol": "zero big tiny mm huge",
        },
    ),
    fuzz(
        "raildyn.course.Verdict",
        lambda: call(True, 1.51, 1.5, "right"),
        accepts={
            "answer": "zero negative huge big tiny mm",
            "expected": "zero negative huge big tiny mm",
            "reason": "unknown",
        },  # any words  # fmt: skip
    ),
    fuzz(
        "raildyn.course.Exercise",
        lambda: call("f", EXERCISE.answer, {"m": (800.0, 1200.0), "k": (1e6, 2e6)}, 0.01, 0.0, 3),
        accepts={
            "parameters": "empty",
            "rtol": "zero tiny",
            "atol": "zero big tiny mm huge",
            "answer": "returns-negative",
        },  # fmt: skip
    ),
    fuzz("raildyn.course.Exercise.variant", lambda: on(EXERCISE, "s1"), accepts={"student": "unknown"}),
    fuzz("raildyn.course.Exercise.expected", lambda: on(EXERCISE, "s1"), accepts={"student": "unknown"}),
    fuzz(
        "raildyn.course.Exercise.check",
        lambda: on(EXERCISE, "s1", 5.5),
        accepts={"student": "unknown", "answer": "zero negative huge big tiny mm"},
    ),
    fuzz(
        "raildyn.course.Mark",
        lambda: call("s1", "f", "5.5", Verdict(True, 5.5, 5.5, "right")),
        # any text: an id, an exercise's name, what the student wrote
        accepts={"verdict": "none", "answer": "empty unknown", "student": "unknown", "exercise": "unknown"},
    ),
    fuzz("raildyn.course.mark", lambda: call(ROWS, [EXERCISE]), accepts={"rows": "empty"}),
    fuzz(
        "raildyn.course.check_matrices",
        lambda: call(MATRICES, MATRICES, {}, rtol=1e-6),
        # any finite matrices are compared (a wrong one is a verdict, not an error); no symbols is no values
        accepts={
            "derived": "zero negative",
            "model": "zero negative",
            "values": "empty none",
            "rtol": "zero tiny mm",
        },
    ),
    fuzz(
        "raildyn.course.SelfCheck",
        lambda: call("What is the frequency?", 1.5, "Hz", 0.02, 0.0, (), None, ""),
        accepts={
            "question": "unknown",
            "expected": "zero negative huge big tiny mm",
            "unit": "empty unknown",
            "why": "empty unknown",
            "rtol": "zero tiny",
            "atol": "zero big tiny mm huge",
            "choices": "empty",
            "right": "none",
        },
    ),
    fuzz("raildyn.course.mark_csv", lambda: call(*_csv()), skip=("answers", "out")),
]


def _csv():
    import csv
    import tempfile
    from pathlib import Path

    folder = Path(tempfile.mkdtemp())
    answers = folder / "answers.csv"
    with answers.open("w", newline="") as f:
        w = csv.DictWriter(f, ["student", "exercise", "answer"])
        w.writeheader()
        w.writerows(ROWS)
    return answers, [EXERCISE], folder / "marks.csv"
