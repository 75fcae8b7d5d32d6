"""Answers a student can check and homework a lecturer can set (the course's tools).

* :func:`check` holds an answer to the expected value within a tolerance and, when it is off, says
  why if the slip is a common one: the sign, a factor 2π (hertz for radians a second), a unit
  (millimetres for metres, km/h for m/s, a mass for a weight, degrees for radians), a factor two
  (a peak-to-peak value for an amplitude), a square or a square root (a variance for an RMS value).
* :class:`Exercise` draws each student's own values of a numeric exercise from their id, always the
  same for the same id, and computes the answer with raildyn: a lecturer sets one exercise and every
  student meets different numbers.
* :func:`mark` and :func:`mark_csv` mark a class's answers (a CSV of student, exercise, answer), and
  ``python -m raildyn mark ANSWERS.csv KEY.py`` does so from the command line, KEY.py listing the
  exercises as ``EXERCISES``.
* :func:`check_matrices` holds the matrices a student derived (with
  :func:`raildyn.derivations.lagrange`) to a model's, entry by entry, and names the first entry that
  is off and the likely slip.
* :class:`SelfCheck` is a question that answers in the page itself, without a kernel: the static book,
  the lecture-room app and JupyterLab alike check a number (with :func:`check`'s slips) or a choice
  in the page's JavaScript.
* ``%load_ext raildyn.course`` makes a cell that opens with the line ``#| answer`` a worked answer: its
  output stays folded under "Show the answer" when the notebook is run, in JupyterLab as in the
  lecture-room app.
"""

from __future__ import annotations

import csv
import hashlib
import html
import itertools
import json
import math
import sys
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from raildyn import _checks
from raildyn.constants import GRAVITY

__all__ = ["Exercise", "Mark", "SelfCheck", "Verdict", "check", "check_matrices", "mark", "mark_csv"]

#: The slips :func:`check` recognises: the factor between the answer given and the one expected, and
#: what it most often means.
SLIPS = (
    (2 * math.pi, "2π times too large: rad/s where Hz was asked?"),
    (1 / (2 * math.pi), "2π times too small: Hz where rad/s was asked?"),
    (1e3, "1000 times too large: mm for m, g for kg, or N for kN?"),
    (1e-3, "1000 times too small: m for mm, or kN for N?"),
    (1e6, "a million times too large: µm for m, or N for MN?"),
    (1e-6, "a million times too small: m for µm, or MN for N?"),
    (3.6, "3.6 times too large: km/h where m/s was asked?"),
    (1 / 3.6, "3.6 times too small: m/s where km/h was asked?"),
    (GRAVITY, "g times too large: a weight (N) where a mass (kg) was asked?"),
    (1 / GRAVITY, "g times too small: a mass (kg) where a weight (N) was asked?"),
    (180 / math.pi, "degrees where radians were asked?"),
    (math.pi / 180, "radians where degrees were asked?"),
    (2.0, "twice too large: a peak-to-peak value for an amplitude, or both wheels for one?"),
    (0.5, "half too small: an amplitude for a peak-to-peak value, or one wheel for both?"),
)


@dataclass(frozen=True)
class Verdict:
    """What :func:`check` found.

    Attributes
    ----------
    correct : bool
        The answer lies within the tolerance of the expected value.
    answer, expected : float
        As given and as computed (finite).
    reason : str
        "right", or why the answer is off (not empty).
    """

    correct: bool
    answer: float
    expected: float
    reason: str

    def __post_init__(self):
        _checks.flag("correct", self.correct)
        _checks.scalar("answer", self.answer)
        _checks.scalar("expected", self.expected)
        if not isinstance(self.reason, str) or not self.reason:
            raise ValueError(f"reason must be a non-empty string, got {self.reason!r}")

    def __str__(self) -> str:
        mark = "✓" if self.correct else "✗"
        return f"{mark} {self.answer:.6g} (expected {self.expected:.6g}): {self.reason}"


def _close(a: float, b: float, rtol: float, atol: float) -> bool:
    return abs(a - b) <= atol + rtol * abs(b)


def check(answer, expected, *, rtol: float = 0.01, atol: float = 0.0) -> Verdict:
    """Hold ``answer`` to ``expected`` within |answer − expected| ≤ atol + rtol·|expected|, and say why not.

    Parameters
    ----------
    answer : float
        The student's answer, finite.
    expected : float
        The right value, finite.
    rtol : float
        Relative tolerance, in [0, 1]. Default 1 %.
    atol : float
        Absolute tolerance, ≥ 0, in the answer's unit. Default 0.

    Returns
    -------
    Verdict

    Examples
    --------
    >>> print(check(2 * 3.1416 * 1.5, 1.5))
    ✗ 9.4248 (expected 1.5): 2π times too large: rad/s where Hz was asked?
    """
    a = _checks.scalar("answer", answer)
    e = _checks.scalar("expected", expected)
    rtol = _checks.scalar("rtol", rtol, low=0.0, high=1.0)
    atol = _checks.nonnegative("atol", atol)
    if _close(a, e, rtol, atol):
        return Verdict(True, a, e, "right")
    if e != 0.0 and _close(-a, e, rtol, atol):
        return Verdict(False, a, e, "the sign is wrong: which way is the quantity positive?")
    for factor, why in SLIPS:
        for sign, note in ((1.0, ""), (-1.0, " (and the sign is wrong)")):
            if e != 0.0 and _close(sign * a, factor * e, rtol, atol * factor):
                return Verdict(False, a, e, why + note)
    if e > 0.0 and a > 0.0:
        if _close(a, e * e, rtol, atol):
            return Verdict(False, a, e, "the square of the answer: a variance where an RMS value was asked?")
        if _close(a * a, e, rtol, atol):
            return Verdict(
                False, a, e, "the square root of the answer: an RMS value where a variance was asked?"
            )
    tolerance = f"{100 * rtol:g} %" + (f" and {atol:g}" if atol else "")
    words = f"{100 * abs(a - e) / abs(e):.3g} %" if e != 0.0 else f"{abs(a):.3g} from zero"
    return Verdict(False, a, e, f"off by {words} (tolerance {tolerance}): check the method, not a unit")


_MATRICES = ("M", "C", "K", "GK", "GC")


def _numbers(name: str, matrix, values: Mapping) -> np.ndarray:
    """A derived matrix as floats: sympy's with ``values`` put in, anything else as an array."""
    if type(matrix).__module__.startswith("sympy"):
        matrix = matrix.xreplace(values)
        left = sorted(str(s) for s in matrix.free_symbols)
        if left:
            raise ValueError(f"derived {name} still holds the symbols {left}: give their numbers in values")
        matrix = np.array(matrix.evalf().tolist(), dtype=float)
    return _checks.array(f"derived {name}", matrix, ndim=2)


def check_matrices(derived, model, values: Mapping | None = None, *, rtol: float = 1e-6) -> Verdict:
    """Hold the matrices a student derived to a model's, entry by entry, and name the first entry that is off.

    Parameters
    ----------
    derived : sequence of sympy.Matrix or array_like
        (M, C, K) or (M, C, K, GK, GC), as :func:`raildyn.derivations.lagrange` returns them.
    model : SystemMatrices or sequence of array_like
        The model's matrices at the same speed: a linear model's ``matrices(speed)`` (whose labels
        name the entries) or (M, C, K) or (M, C, K, GK, GC). Only the matrices both hold are compared.
    values : mapping of sympy.Symbol to float, optional
        The number of each symbol left in ``derived`` (the model's parameters, the speed).
    rtol : float
        An entry is right when it lies within rtol × (the largest entry of that matrix of the model's)
        of the model's entry, in [0, 1]. Default 1e-6: the algebra must be exact, the numbers are.

    Returns
    -------
    Verdict
        Right when every entry is; otherwise ``answer`` and ``expected`` are the first wrong entry's
        two values (matrices in the order M, C, K, G_K, G_C, rows first) and ``reason`` names the entry
        and the slip, e.g. "K[y, psi]: the sign is wrong: …".

    Examples
    --------
    >>> import sympy
    >>> from raildyn.derivations import coordinates, lagrange
    >>> m, k = sympy.symbols("m k", positive=True)
    >>> (x,) = coordinates("x")
    >>> mine = lagrange(m * x.diff() ** 2 / 2, k * x**2 / 2, 0, [x])
    >>> print(check_matrices(mine, ([[2.0]], [[0.0]], [[-8.0]]), {m: 2.0, k: 8.0}))
    ✗ 8 (expected -8): K[0, 0]: the sign is wrong: which way is the quantity positive?
    """
    if values is None:
        values = {}
    if not isinstance(values, Mapping):
        raise TypeError(f"values must map sympy symbols to numbers, got {type(values).__name__}")
    rtol = _checks.scalar("rtol", rtol, low=0.0, high=1.0)
    if all(hasattr(model, key) for key in ("M", "C", "K")):
        theirs = [getattr(model, key) for key in _MATRICES if hasattr(model, key)]
        labels = tuple(getattr(model, "labels", ()))
    elif isinstance(model, Iterable) and not isinstance(model, str | bytes):
        theirs, labels = list(model), ()
    else:
        raise TypeError(f"model must be a model's matrices(speed) or (M, C, K[, GK, GC]), got {model!r:.80}")
    if isinstance(derived, str | bytes) or not isinstance(derived, Iterable):
        raise TypeError(f"derived must be (M, C, K) or (M, C, K, GK, GC), got {derived!r:.80}")
    mine = list(derived)
    for name, given in (("derived", mine), ("model", theirs)):
        if len(given) not in (3, 5):
            raise ValueError(f"{name} must hold 3 matrices (M, C, K) or 5 (with GK, GC), got {len(given)}")
    pairs = []
    for name, a, b in zip(_MATRICES, mine, theirs, strict=False):
        pairs.append((name, _numbers(name, a, values), _checks.array(f"model {name}", b, ndim=2)))
    checked = 0
    for name, a, b in pairs:
        if a.shape != b.shape:
            return Verdict(
                False, float(a.size), float(b.size),
                f"{name} is {a.shape[0]}×{a.shape[1]}, the model's {b.shape[0]}×{b.shape[1]}: "
                "a coordinate (or an input) missing or extra?",
            )  # fmt: skip
        atol = rtol * max(float(np.abs(b).max(initial=0.0)), np.finfo(float).tiny)
        for i, j in itertools.product(*map(range, a.shape)):
            checked += 1
            if _close(a[i, j], b[i, j], 0.0, atol):
                continue
            if name == "M" and np.allclose(np.sort(np.diag(a)), np.sort(np.diag(b)), rtol=rtol, atol=atol):
                return Verdict(
                    False, a[i, j], b[i, j],
                    f"the coordinates are in another order than the model's {labels or ''}".rstrip(),
                )  # fmt: skip
            rows = labels if len(labels) == a.shape[0] else range(a.shape[0])
            columns = labels if name in ("M", "C", "K") and len(labels) == a.shape[1] else range(a.shape[1])
            slip = check(a[i, j], b[i, j], rtol=rtol, atol=atol).reason
            return Verdict(False, a[i, j], b[i, j], f"{name}[{list(rows)[i]}, {list(columns)[j]}]: {slip}")
    return Verdict(True, float(checked), float(checked), "right")


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


# --------------------------------------------------------------------------- on the page, without a kernel

# The page's check of a number: the same rules as check() (the tolerance, then the sign, then SLIPS,
# then a square or a square root), in JavaScript so that the static book answers with no kernel.
_SELF_CHECK_JS = """(function () {
  const box = document.getElementById(%(id)s), spec = %(spec)s;
  const say = box.querySelector('.raildyn-selfcheck-verdict');
  const close = (a, b, rtol, atol) => Math.abs(a - b) <= atol + rtol * Math.abs(b);
  function verdict(a) {
    const e = spec.expected, r = spec.rtol, t = spec.atol;
    if (close(a, e, r, t)) return [true, 'right'];
    const sign = 'the sign is wrong: which way is the quantity positive?';
    if (e !== 0 && close(-a, e, r, t)) return [false, sign];
    for (const [factor, why] of spec.slips) {
      if (e !== 0 && close(a, factor * e, r, t * factor)) return [false, why];
      if (e !== 0 && close(-a, factor * e, r, t * factor)) return [false, why + ' (and the sign is wrong)'];
    }
    const square = 'the square of the answer: a variance where an RMS value was asked?';
    const root = 'the square root of the answer: an RMS value where a variance was asked?';
    if (e > 0 && a > 0 && close(a, e * e, r, t)) return [false, square];
    if (e > 0 && a > 0 && close(a * a, e, r, t)) return [false, root];
    return [false, 'not yet: check the method, not a unit'];
  }
  box.querySelector('button').addEventListener('click', () => {
    let right, why;
    if (spec.choices) {
      const picked = box.querySelector('input[type=radio]:checked');
      if (!picked) { say.textContent = 'Pick one first.'; return; }
      right = Number(picked.value) === spec.right;
      why = right ? 'right' : 'not that one: think again';
    } else {
      const typed = box.querySelector('input').value.trim();
      const a = Number(typed.replace(',', '.').replace('\\u2212', '-'));
      if (!Number.isFinite(a) || typed === '') { say.textContent = 'Type a number first.'; return; }
      [right, why] = verdict(a);
    }
    say.textContent = (right ? '\\u2713 ' : '\\u2717 ') + why + (right && spec.why ? ' ' + spec.why : '');
    say.dataset.right = right;
  });
})();"""

_SELF_CHECKS = itertools.count()


def _inline_math(text: str) -> str:
    """``text`` as HTML, each $…$ in it marked up as the book marks inline mathematics (a span of class
    "math" around \\(…\\)), which the book's MathJax and JupyterLab's both typeset."""
    parts = html.escape(text).split("$")
    if len(parts) % 2 == 0:
        raise ValueError(f"question must pair its $ signs (each formula between two), got {text!r:.80}")
    return "".join(
        f'<span class="math notranslate nohighlight">\\({p}\\)</span>' if i % 2 else p
        for i, p in enumerate(parts)
    )


@dataclass(frozen=True, repr=False)
class SelfCheck:
    """A question that checks its answer in the page: a number within a tolerance, or one choice of several.

    Displayed in a notebook (its ``_repr_html_``), it is a question, an answer box and a "Check"
    button; the check runs in the page's JavaScript, so it answers in the static book, in the
    lecture-room app and in JupyterLab alike, with no kernel. A number is held as :func:`check` holds
    it and a wrong one meets the same slips (the sign, 2π, a unit, a factor two).

    Attributes
    ----------
    question : str
        What is asked (not empty; HTML is escaped; a formula stands between two dollar signs, which
        the page's MathJax typesets).
    expected : float or None
        The right number, finite, in ``unit``; None for a choice.
    unit : str
        The unit the answer is asked in, shown beside the box (may be empty).
    rtol, atol : float
        The tolerance of a number, as for :func:`check`. Default 2 % and 0.
    choices : tuple of str
        For a choice: the options (at least two, different); empty for a number.
    right : int or None
        For a choice: the index of the right option.
    why : str
        Shown after a right answer: the reason in a sentence (may be empty).
    """

    question: str
    expected: float | None = None
    unit: str = ""
    rtol: float = 0.02
    atol: float = 0.0
    choices: tuple = ()
    right: int | None = None
    why: str = ""

    def __post_init__(self):
        if not isinstance(self.question, str) or not self.question.strip():
            raise ValueError(f"question must be a non-empty string, got {self.question!r}")
        _inline_math(self.question)
        for key in ("unit", "why"):
            if not isinstance(getattr(self, key), str):
                raise TypeError(f"{key} must be a string, got {type(getattr(self, key)).__name__}")
        _checks.scalar("rtol", self.rtol, low=0.0, high=1.0)
        _checks.nonnegative("atol", self.atol)
        if not isinstance(self.choices, tuple | list):
            raise TypeError(
                f"choices must be a tuple of strings (none for a number), got {self.choices!r:.60}"
            )
        if self.choices:
            choices = _checks.strings("choices", self.choices, unique=True)
            if len(choices) < 2:
                raise ValueError(f"choices must offer at least two options, got {len(choices)}")
            if self.expected is not None:
                raise ValueError(f"expected must be None for a choice, got {self.expected!r}")
            _checks.integer("right", self.right, low=0, high=len(choices) - 1)
        else:
            if self.expected is None:
                raise ValueError("expected must be a number for a question without choices, got None")
            _checks.scalar("expected", self.expected)
            if self.right is not None:
                raise ValueError(f"right must be None for a number (no choices), got {self.right!r}")

    def __repr__(self) -> str:  # the question only: a plain-text display must not give the answer away
        return f"SelfCheck({self.question!r})"

    def _repr_html_(self) -> str:
        box = f"raildyn-selfcheck-{next(_SELF_CHECKS)}-{_seed('', self.question) % 10**8}"
        spec = {"rtol": self.rtol, "atol": self.atol, "why": self.why, "slips": SLIPS}
        if self.choices:
            spec |= {"choices": len(self.choices), "right": self.right}
            field_ = "".join(
                f'<label><input type="radio" name="{box}" value="{i}"> {html.escape(c)}</label><br>'
                for i, c in enumerate(self.choices)
            )
        else:
            spec["expected"] = float(self.expected)
            unit = f" {html.escape(self.unit)}" if self.unit else ""
            field_ = f'<input type="text" inputmode="decimal" size="12" aria-label="your answer">{unit} '
        script = _SELF_CHECK_JS % {"id": json.dumps(box), "spec": json.dumps(spec)}
        return (
            f'<div class="raildyn-selfcheck" id="{box}">'
            f"<p><b>Check yourself:</b> {_inline_math(self.question)}</p>"
            f"<p>{field_}<button>Check</button></p>"
            f'<p class="raildyn-selfcheck-verdict" aria-live="polite"></p><script>{script}</script></div>'
        )


# What a folded answer's summary says (the page shows it; the answer's output is under it).
ANSWER_FOLD = "Show the answer"


def _fold(captured) -> str:
    """The captured output of an answer as HTML folded under :data:`ANSWER_FOLD`."""
    parts = [f"<pre>{html.escape(captured.stdout)}</pre>"] if captured.stdout.strip() else []
    for output in captured.outputs:
        data = output.data
        if "text/html" in data:
            parts.append(data["text/html"])
        elif "image/png" in data:
            parts.append(f'<img src="data:image/png;base64,{data["image/png"]}" alt="the answer\'s figure">')
        elif "image/svg+xml" in data:
            parts.append(data["image/svg+xml"])
        else:
            parts.append(f"<pre>{html.escape(data.get('text/plain', ''))}</pre>")
    return f'<details class="raildyn-answer"><summary>{ANSWER_FOLD}</summary>{"".join(parts)}</details>'


def _answer(line: str, cell: str) -> None:
    """``%%answer`` (what ``#| answer`` runs): run the cell, then show what it printed and drew folded.

    JupyterLab unfolds a cell's outputs whenever the cell runs, so a worked answer hidden by the
    notebook's metadata would show after "Run All"; folded in its own output it stays hidden until
    opened, there and in the lecture-room app. An error is shown unfolded and fails the cell.
    """
    from IPython import get_ipython
    from IPython.display import HTML, display
    from IPython.utils.capture import capture_output

    if line.strip():
        raise ValueError(f"%%answer takes no arguments, got {line.strip()!r}")
    shell = get_ipython()
    with capture_output() as captured:
        result = shell.run_cell(cell, store_history=False, silent=False)
    sys.stderr.write(captured.stderr)  # a warning stays a warning (the tests make warnings errors)
    if not result.success:
        captured.show()
        result.raise_error()
    widgets = [o for o in captured.outputs if "application/vnd.jupyter.widget-view+json" in o.data]
    captured.outputs[:] = [o for o in captured.outputs if o not in widgets]
    display(HTML(_fold(captured)))
    for widget in widgets:  # a live widget cannot fold into HTML: it shows as it is
        display(widget.data, raw=True)


#: The first line of a worked answer's cell: a comment, so that the cell stays Python (linted, parsed,
#: and run as plain code where the extension is not loaded), and all a collapsed cell shows of it.
ANSWER_LINE = "#| answer"


def _answer_cells(lines: list[str]) -> list[str]:
    """IPython input transformer: a cell that opens with :data:`ANSWER_LINE` runs as ``%%answer``."""
    if lines and lines[0].strip() == ANSWER_LINE:
        return ["%%answer\n", *lines[1:]]
    return lines


def load_ipython_extension(ipython) -> None:
    """``%load_ext raildyn.course``: a cell that opens with ``#| answer`` is a worked answer.

    Registers the cell magic ``%%answer`` (:func:`_answer`) and an input transformer that runs every
    cell whose first line is ``#| answer`` through it.
    """
    ipython.register_magic_function(_answer, magic_kind="cell", magic_name="answer")
    if _answer_cells not in ipython.input_transformers_cleanup:
        ipython.input_transformers_cleanup.append(_answer_cells)
