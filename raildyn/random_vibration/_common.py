"""What the modules of :mod:`raildyn.random_vibration` share: the PSD conventions they accept,
the memory bounds of one call, and the checks on a frequency grid and on overflow.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks

_SIDED = ("one", "two")


_TIME_UNITS = ("rad/s", "Hz")


_SPACE_UNITS = ("rad/m", "cycles/m")


_CYCLIC_UNITS = ("Hz", "cycles/m")


# At most this many frequencies from cancellation_frequencies: a bound on the memory asked for.
_MAX_COUNT = 1_000_000


# At most this many points in one synthesized record, and in all the records of one call: the FFT
# of 2**24 points takes about a second and the 2**26 values about 0.5 GB; longer records are built
# in pieces.
_MAX_RECORD = 2**24


_MAX_VALUES = 2**26


def _finite(value, names: str, what: str):
    """``value`` itself, unless it overflowed (computed under ``np.errstate(over="ignore")``)."""
    if not np.all(np.isfinite(value)):
        raise ValueError(f"{names} give {what} beyond floating point range; rescale them")
    return value


def _spectrum_grid(psd, omega, *, increasing=True, min_points=1) -> tuple[np.ndarray, np.ndarray]:
    """Check a one-sided PSD on its frequency grid: same 1-D length, finite, >= 0."""
    w = _checks.array("omega", omega, ndim=1, low=0.0)
    S = _checks.array("psd", psd, ndim=1)
    if S.shape != w.shape:
        raise ValueError(f"psd and omega must have the same length, got psd {S.shape} and omega {w.shape}")
    if w.size < min_points:
        raise ValueError(f"omega must hold at least {min_points} frequencies, got {w.size}")
    S = _checks.array("psd", S, low=0.0)
    if increasing and w.size > 1:
        _checks.increasing("omega", w)
    return S, w
