"""The records of chapter 11 and their checks: one shape for a measured or predicted history.

Every metric, spectrum and acceptance statistic of :mod:`raildyn.validation` takes 1-D finite records
on one uniform step; these are the checks and the overflow-safe sums they share. The module is private:
the public modules import its names.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks

__all__ = ["diff", "huge", "pair", "percent", "record", "rms", "samples", "scaled", "time_base"]


def record(name: str, value, *, min_size: int = 2) -> np.ndarray:
    """A 1-D finite record of at least ``min_size`` samples."""
    x = _checks.array(name, value, ndim=1, allow_empty=False)
    if x.size < min_size:
        raise ValueError(f"{name} must hold at least {min_size} samples, got {x.size}")
    return x


def pair(measured, predicted, names=("measured", "predicted"), min_size: int = 2):
    """Two records of equal length (a record each, named by ``names``)."""
    m = record(names[0], measured, min_size=min_size)
    p = record(names[1], predicted, min_size=min_size)
    if p.size != m.size:
        raise ValueError(
            f"{names[1]} must have as many samples as {names[0]} ({m.size}), got {p.size}: "
            "resample both onto one time base first"
        )
    return m, p


def time_base(time, n: int) -> np.ndarray | None:
    """None, a step dt > 0 (s), or a uniform grid of ``n`` times (s) → the grid (None stays None)."""
    if time is None:
        return None
    if np.ndim(time) == 0 and not isinstance(time, (str, bytes)):
        dt = _checks.positive("time", time)
        return np.arange(n) * dt
    t = _checks.time_grid("time", time, uniform=True)
    if t.size != n:
        raise ValueError(f"time must hold one time per sample ({n}), got {t.size}")
    return t


def scaled(x: np.ndarray) -> tuple[np.ndarray, float]:
    """``x`` divided by its largest magnitude, and that magnitude (0 for a zero record)."""
    s = float(np.max(np.abs(x)))
    return (x / s if s > 0.0 else x), s


def rms(x: np.ndarray, weights: np.ndarray | None = None) -> float:
    """√(mean x²) (weighted by ``weights``, which sum to 1), without overflow."""
    u, s = scaled(x)
    mean_square = np.mean(u * u) if weights is None else np.dot(weights, u * u)
    return s * float(np.sqrt(mean_square))


def diff(measured: np.ndarray, predicted: np.ndarray) -> np.ndarray:
    """predicted − measured, computed after halving so that opposite huge entries do not overflow."""
    return 2.0 * (0.5 * predicted - 0.5 * measured) if huge(measured, predicted) else predicted - measured


def huge(*arrays) -> bool:
    return any(np.max(np.abs(a)) > 1e307 for a in arrays)


def percent(name: str, value, *, pair: bool = False) -> np.ndarray:
    """Percentages in [0, 100]; a pair (lower, upper) with lower <= upper when ``pair``."""
    q = _checks.array(name, value, ndim=1, allow_empty=False)
    if np.any((q < 0.0) | (q > 100.0)):
        raise ValueError(f"{name} must hold percentages in [0, 100], got {value!r}")
    if pair and (q.size != 2 or q[0] > q[1]):
        raise ValueError(
            f"{name} must be a pair (lower, upper) of percentages, lower <= upper, got {value!r}"
        )
    return q


def samples(name: str, length: float, spacing: float, n: int, what: str) -> int:
    """A length (s or m) as a whole number of samples, 1 to n, or a ValueError naming ``name``."""
    k = int(round(length / spacing))
    if not 1 <= k <= n:
        raise ValueError(
            f"{name} must span 1 to {n} samples of spacing {spacing:g} (the {what}), "
            f"got {length!r} = {length / spacing:.4g} samples"
        )
    return k
