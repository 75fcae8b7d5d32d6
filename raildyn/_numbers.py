"""The one check of a single number, below both :mod:`raildyn.constants` and :mod:`raildyn._checks`.

:mod:`raildyn.constants` validates the bounds of a :class:`~raildyn.constants.PlausibleRange`
with it, and :mod:`raildyn._checks` (which reads the constants' table of ranges) re-exports
it, so that the ground floor imports in one direction: _numbers ← constants ← _checks.
"""

from __future__ import annotations

import math
import numbers

import numpy as np


def scalar(name: str, value, *, low=None, high=None, low_open=False, high_open=False) -> float:
    """Return ``value`` as a finite float within ``[low, high]``.

    ``low_open`` / ``high_open`` make the matching bound strict.
    """
    # The common case first and cheaply (this runs inside right-hand sides): a plain float or int.
    # A bool is no number (True is not 1.0 m), and a complex number is not cast to its real part.
    if type(value) is not float and (
        isinstance(value, bool) or not isinstance(value, (numbers.Real, np.floating, np.integer))
    ):
        if not (isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iuf"):
            raise TypeError(f"{name} must be a real number, got {value!r} of type {type(value).__name__}")
    x = float(value)
    if not math.isfinite(x):
        where = interval_words(low, high, low_open, high_open)
        raise ValueError(f"{name} must be a finite number in {where}, got {value!r}")
    if (low is not None and (x < low or (low_open and x == low))) or (
        high is not None and (x > high or (high_open and x == high))
    ):
        raise ValueError(f"{name} must be in {interval_words(low, high, low_open, high_open)}, got {value!r}")
    return x


def interval_words(low, high, low_open, high_open) -> str:
    """The allowed interval in words, for an error message."""
    lo = "(" if low_open else "["
    hi = ")" if high_open else "]"
    return f"{lo}{'-inf' if low is None else low}, {'inf' if high is None else high}{hi}"
