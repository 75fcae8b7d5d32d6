"""An answer checked and its slip named: a number (:func:`~raildyn.course.check`) and a derivation's
matrices (:func:`~raildyn.course.check_matrices`)."""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn.constants import GRAVITY

__all__ = ["SLIPS", "Verdict", "check", "check_matrices"]

#: The slips :func:`~raildyn.course.check` recognises: the factor between the answer given and the one
#: expected, and what it most often means.
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
