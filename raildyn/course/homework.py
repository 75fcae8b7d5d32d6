"""Homework a lecturer can set: per-student variants of a numeric exercise
(:class:`~raildyn.course.Exercise`), and a class's answers marked (:func:`~raildyn.course.mark`,
:func:`~raildyn.course.mark_csv`)."""

from __future__ import annotations

import csv
import hashlib
import math
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from raildyn import _checks
from raildyn.course.answers import Verdict, check

__all__ = ["Exercise", "Mark", "mark", "mark_csv"]


def _seed(student: str, exercise: str) -> int:
    digest = hashlib.sha256(f"{exercise}\0{student}".encode()).digest()
    return int.from_bytes(digest[:8], "little")


@dataclass(frozen=True)
class Exercise:
    """A numeric exercise whose values every student draws afresh from their id.

    Attributes
    ----------
    name : str
        The exercise's name, as in the class's answer sheet (not empty).
    answer : callable
        ``answer(**values)`` → the expected answer, a finite float: the raildyn computation.
    parameters : mapping of str to (float, float)
        Each value the exercise varies, with the interval it is drawn from (finite, low ≤ high; the
        same low and high fix a value). Default none: one answer for all.
    rtol, atol : float
        The tolerance :func:`check` holds the answer to. Default 1 % and 0.
    digits : int
        Significant figures each drawn value is rounded to (what the student sees), in [1, 12].
        Default 3.
    """

    name: str
    answer: Callable
    parameters: Mapping = field(default_factory=dict)
    rtol: float = 0.01
    atol: float = 0.0
    digits: int = 3

    def __post_init__(self):
        if not isinstance(self.name, str) or not self.name.strip():
            raise ValueError(f"name must be a non-empty string, got {self.name!r}")
        if not isinstance(self.parameters, Mapping):
            raise TypeError(f"parameters must map names to (low, high), got {type(self.parameters).__name__}")
        for key, bounds in self.parameters.items():
            low, high = _checks.array(f"parameters[{key!r}]", bounds, shape=(2,))
            if low > high:
                raise ValueError(f"parameters[{key!r}] must be (low, high) with low <= high, got {bounds!r}")
        _checks.function("answer", self.answer)
        # Tried once now, at the middle of every interval, so that a wrong key fails when it is written.
        middle = {key: 0.5 * (low + high) for key, (low, high) in self.parameters.items()}
        _checks.returned("answer", np.asarray(self.answer(**middle), dtype=float), shape=(), at=f"{middle}")
        _checks.scalar("rtol", self.rtol, low=0.0, high=1.0)
        _checks.nonnegative("atol", self.atol)
        _checks.integer("digits", self.digits, low=1, high=12)

    def variant(self, student: str) -> dict:
        """The values this student's exercise states: the same id gives the same values.

        Parameters
        ----------
        student : str
            The student's id (not empty).

        Returns
        -------
        dict
            Name → value, each rounded to ``digits`` significant figures.
        """
        student = _student(student)
        rng = np.random.default_rng(_seed(student, self.name))
        values = {}
        for key, (low, high) in self.parameters.items():
            x = float(rng.uniform(low, high))
            values[key] = float(f"{x:.{self.digits}g}") if x else 0.0
        return values

    def expected(self, student: str) -> float:
        """The right answer for this student's values: ``answer(**variant(student))``.

        Parameters
        ----------
        student : str
            The student's id (not empty).

        Returns
        -------
        float
        """
        value = self.answer(**self.variant(student))
        return _checks.returned(
            "answer", np.asarray(value, dtype=float), shape=(), at=f"student {student!r}"
        )[()]

    def check(self, student: str, answer) -> Verdict:
        """:func:`check` this student's answer against their own expected value.

        Parameters
        ----------
        student : str
            The student's id (not empty).
        answer : float
            Their answer, finite.

        Returns
        -------
        Verdict
        """
        return check(answer, self.expected(student), rtol=self.rtol, atol=self.atol)


def _student(student) -> str:
    if not isinstance(student, str) or not student.strip():
        raise ValueError(f"student must be a non-empty string (an id), got {student!r}")
    return student.strip()


@dataclass(frozen=True)
class Mark:
    """One answer of a class, marked.

    Attributes
    ----------
    student, exercise : str
        Who answered which exercise (not empty).
    answer : str
        What they wrote, as in the sheet.
    verdict : Verdict or None
        The check; None where the answer is not a number.
    """

    student: str
    exercise: str
    answer: str
    verdict: Verdict | None

    def __post_init__(self):
        _student(self.student)
        if not isinstance(self.exercise, str) or not self.exercise.strip():
            raise ValueError(f"exercise must be a non-empty string, got {self.exercise!r}")
        if not isinstance(self.answer, str):
            raise TypeError(f"answer must be the text the student wrote, got {type(self.answer).__name__}")
        if self.verdict is not None and not isinstance(self.verdict, Verdict):
            raise TypeError(f"verdict must be a Verdict or None, got {type(self.verdict).__name__}")

    @property
    def correct(self) -> bool:
        """True for a right answer."""
        return self.verdict is not None and self.verdict.correct

    @property
    def reason(self) -> str:
        """The verdict's reason, or why there is none."""
        return self.verdict.reason if self.verdict is not None else "not a number"


def mark(rows: Iterable[Mapping], exercises) -> list[Mark]:
    """Mark a class's answers: each row's answer checked against that student's own variant.

    Parameters
    ----------
    rows : iterable of mappings
        Each with the keys "student", "exercise" and "answer" (the text of a CSV row).
    exercises : sequence of Exercise
        The exercises the rows name (names unique).

    Returns
    -------
    list of Mark
        One per row, in order.

    Raises
    ------
    ValueError
        If a row names an exercise not among ``exercises``, or lacks a key.
    """
    if isinstance(rows, str | bytes) or not isinstance(rows, Iterable):
        raise TypeError(f"rows must be an iterable of mappings (a csv.DictReader), got {type(rows).__name__}")
    if isinstance(exercises, str | bytes) or not isinstance(exercises, Iterable):
        raise TypeError(f"exercises must be a sequence of Exercise, got {type(exercises).__name__}")
    by_name = {}
    for ex in exercises:
        if not isinstance(ex, Exercise):
            raise TypeError(f"exercises must hold Exercise objects, got {type(ex).__name__}")
        if ex.name in by_name:
            raise ValueError(f"exercises must have unique names, got {ex.name!r} twice")
        by_name[ex.name] = ex
    marks = []
    for i, row in enumerate(rows):
        missing = {"student", "exercise", "answer"} - set(row)
        if missing:
            raise ValueError(
                f"rows[{i}] must have the keys student, exercise and answer, lacks {sorted(missing)}"
            )
        name = str(row["exercise"]).strip()
        if name not in by_name:
            raise ValueError(f"rows[{i}] names exercise {name!r}, not among {sorted(by_name)}")
        text = str(row["answer"]).strip()
        try:
            value = float(text)
        except ValueError:
            value = math.nan
        student = _student(str(row["student"]))
        verdict = by_name[name].check(student, value) if math.isfinite(value) else None
        marks.append(Mark(student, name, text, verdict))
    return marks


def mark_csv(answers, exercises, out) -> dict:
    """Mark a CSV of answers (columns student, exercise, answer) and write each mark to ``out``.

    ``out`` gets the columns student, exercise, answer, expected, correct (1 or 0) and reason.

    Parameters
    ----------
    answers : str or Path
        The class's answers, a CSV file with a header row.
    exercises : sequence of Exercise
        As for :func:`mark`.
    out : str or Path
        Where to write the marks (a CSV file; its folder must exist).

    Returns
    -------
    dict
        Student → number of right answers.
    """
    if isinstance(exercises, str | bytes) or not isinstance(exercises, Iterable):
        raise TypeError(f"exercises must be a sequence of Exercise, got {type(exercises).__name__}")
    answers, out = Path(answers), Path(out)
    if not answers.is_file():
        raise ValueError(f"answers must be an existing CSV file, got {str(answers)!r}")
    with answers.open(newline="", encoding="utf-8") as f:
        marks = mark(csv.DictReader(f), exercises)
    totals = {}
    with out.open("w", newline="", encoding="utf-8") as f:
        writer = csv.writer(f)
        writer.writerow(["student", "exercise", "answer", "expected", "correct", "reason"])
        for m in marks:
            expected = "" if m.verdict is None else f"{m.verdict.expected:.6g}"
            writer.writerow([m.student, m.exercise, m.answer, expected, int(m.correct), m.reason])
            totals[m.student] = totals.get(m.student, 0) + int(m.correct)
    return totals
