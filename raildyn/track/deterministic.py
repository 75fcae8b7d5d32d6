"""Deterministic track irregularities along distance: dipped rail joints, an isolated bump, sinusoids.

Each function takes distances ``x`` (m) and returns the irregularity (m) or, with
``derivative=1`` or ``2``, its slope (m/m) or curvature (1/m) along the track; a
vehicle at speed V sees the rates V·dz/dx and V²·d²z/dx².

Jointed rail (Garg & Dukkipati 1984, ch. 3): rails of length L (11.9 m, the
39-ft North American rail) whose ends are pushed down at each joint. Each joint
is a cusp of depth δ and half-width a,

    z(ξ) = −δ (1 − |ξ|/a)²  for |ξ| < a,   0 elsewhere,

ξ being the distance to the nearest joint. z and its slope are continuous away
from the joint, where the slope jumps by 4δ/a (the cusp) — the kick that a
wheel receives on each joint; the curvature jumps at |ξ| = a. With a = L/2 the
whole rail sags between joints. On the two rails the joints are either *in
phase* (opposite each other: a bounce and pitch input) or *staggered* by L/2
(a roll input, the source of rock-and-roll of freight cars).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks

__all__ = [
    "RAIL_LENGTH",
    "JointedTrack",
    "dipped_joints",
    "jointed_track",
    "bump",
    "sinusoid",
    "passing_frequency",
    "harmonic_amplitudes",
]

RAIL_LENGTH = 11.9  # m; the 39-ft rail of North American jointed track (Garg & Dukkipati 1984, ch. 3)


def _derivative(value) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value not in (0, 1, 2):
        raise ValueError(f"derivative must be 0, 1 or 2; got {value!r}")
    return int(value)


def dipped_joints(
    x, depth: float, half_width: float, *, rail_length: float = RAIL_LENGTH, offset: float = 0.0, derivative=0
) -> np.ndarray:
    """Vertical profile of one jointed rail with cusp-shaped dipped joints at x = offset + jL.

    Parameters
    ----------
    x : array_like
        Distance along the track, m.
    depth : float
        δ >= 0, depth of the dip at each joint, m.
    half_width : float
        a, half the length of track each dip spans, m, 0 < a <= L/2.
    rail_length : float
        L > 0, distance between joints, m (default 11.9).
    offset : float
        Position of one joint, m.
    derivative : {0, 1, 2}
        Return z (m), dz/dx or d²z/dx² (1/m). At a joint itself the slope is
        taken as the mean of its two one-sided values (0); the curvature returned
        is the regular part, without the Dirac term of the slope jump 4δ/a.

    Returns
    -------
    ndarray, same shape as ``x``

    Examples
    --------
    >>> dipped_joints([0.0, 1.0, 5.95], depth=0.01, half_width=2.0).round(6).tolist()
    [-0.01, -0.0025, 0.0]
    """
    x = _checks.array("x", x)
    delta = _checks.nonnegative("depth", depth)
    L = _checks.positive("rail_length", rail_length)
    a = _checks.scalar("half_width", half_width, low=0.0, low_open=True, high=L / 2)
    offset = _checks.scalar("offset", offset)
    order = _derivative(derivative)
    xi = np.mod(x - offset + 0.5 * L, L) - 0.5 * L  # signed distance to the nearest joint
    u = np.abs(xi) / a
    inside = u < 1.0
    if order == 0:
        return np.where(inside, -delta * (1.0 - u) ** 2, 0.0)
    if order == 1:
        return np.where(inside, 2.0 * delta * (1.0 - u) * np.sign(xi) / a, 0.0)
    return np.where(inside, -2.0 * delta / a**2, 0.0)


@dataclass(frozen=True)
class JointedTrack:
    """Vertical profiles of the two rails of jointed track (or their derivatives).

    Attributes
    ----------
    x : ndarray
        Distance, m.
    left, right : ndarray
        Rail profiles, m (or their derivatives).
    arrangement : str
        "staggered" or "in_phase".
    """

    x: np.ndarray
    left: np.ndarray
    right: np.ndarray
    arrangement: str

    @property
    def vertical(self) -> np.ndarray:
        """Centreline profile (left + right)/2: the bounce input."""
        return 0.5 * (self.left + self.right)

    @property
    def cross_level(self) -> np.ndarray:
        """Cross-level left − right: the roll input (zero for joints in phase)."""
        return self.left - self.right


def jointed_track(
    x,
    depth: float,
    half_width: float,
    *,
    rail_length: float = RAIL_LENGTH,
    arrangement: str = "staggered",
    derivative=0,
) -> JointedTrack:
    """Both rails of jointed track: joints in phase, or staggered by half a rail length.

    The left rail has a joint at x = 0; the right one at x = 0 (``"in_phase"``)
    or x = L/2 (``"staggered"``). Other arguments as for :func:`dipped_joints`.

    Examples
    --------
    >>> t = jointed_track([0.0, 5.95], 0.01, 2.0, arrangement="staggered")
    >>> t.cross_level.round(6).tolist()
    [-0.01, 0.01]
    """
    if arrangement not in ("staggered", "in_phase"):
        raise ValueError(f"arrangement must be 'staggered' or 'in_phase'; got {arrangement!r}")
    L = _checks.positive("rail_length", rail_length)
    left = dipped_joints(x, depth, half_width, rail_length=L, derivative=derivative)
    shift = 0.5 * L if arrangement == "staggered" else 0.0
    right = dipped_joints(x, depth, half_width, rail_length=L, offset=shift, derivative=derivative)
    return JointedTrack(np.asarray(x, dtype=float), left, right, arrangement)


def bump(x, height: float, length: float, *, position: float = 0.0, derivative=0) -> np.ndarray:
    """An isolated bump (height > 0) or dip (height < 0) of 1 − cos shape.

    z = (h/2)(1 − cos(2π(x − x₀)/ℓ)) for x₀ <= x <= x₀ + ℓ, and 0 elsewhere: z and its
    slope are continuous everywhere, the curvature jumps by ±2π²h/ℓ² at both ends.

    Parameters
    ----------
    x : array_like
        Distance, m.
    height : float
        h, m (any sign).
    length : float
        ℓ > 0, m.
    position : float
        x₀, start of the bump, m.
    derivative : {0, 1, 2}
        z (m), dz/dx or d²z/dx² (1/m).

    Examples
    --------
    >>> bump([0.0, 0.5, 1.0], height=0.02, length=1.0).round(6).tolist()
    [0.0, 0.02, 0.0]
    """
    x = _checks.array("x", x)
    h = _checks.scalar("height", height)
    ell = _checks.positive("length", length)
    x0 = _checks.scalar("position", position)
    order = _derivative(derivative)
    k = 2.0 * np.pi / ell
    s = x - x0
    inside = (s >= 0.0) & (s <= ell)
    if order == 0:
        return np.where(inside, 0.5 * h * (1.0 - np.cos(k * s)), 0.0)
    if order == 1:
        return np.where(inside, 0.5 * h * k * np.sin(k * s), 0.0)
    return np.where(inside, 0.5 * h * k**2 * np.cos(k * s), 0.0)


def sinusoid(x, amplitude: float, wavelength: float, *, phase: float = 0.0, derivative=0) -> np.ndarray:
    """A sinusoidal profile or alignment z = A sin(2πx/λ + φ), or its derivatives.

    Parameters
    ----------
    x : array_like
        Distance, m.
    amplitude : float
        A, m.
    wavelength : float
        λ > 0, m.
    phase : float
        φ, rad.
    derivative : {0, 1, 2}

    Examples
    --------
    >>> float(sinusoid(0.0, 0.005, 20.0, derivative=1))  # A·2π/λ
    0.0015707963267948967
    """
    x = _checks.array("x", x)
    A = _checks.scalar("amplitude", amplitude)
    lam = _checks.positive("wavelength", wavelength)
    phi = _checks.scalar("phase", phase)
    order = _derivative(derivative)
    k = 2.0 * np.pi / lam
    arg = k * x + phi
    return (A * np.sin(arg), A * k * np.cos(arg), -A * k**2 * np.sin(arg))[order]


def passing_frequency(speed: float, rail_length: float = RAIL_LENGTH) -> float:
    """Frequency f = V/L (Hz) at which the joints of one rail pass an axle at speed V (m/s)."""
    return _checks.positive("speed", speed) / _checks.positive("rail_length", rail_length)


def harmonic_amplitudes(one_period, count: int) -> np.ndarray:
    """Amplitudes of the first ``count`` harmonics of a periodic profile (same unit as the profile).

    ``one_period`` samples exactly one period uniformly, without repeating its
    first point. Harmonic n has the wavelength L/n, so an axle at speed V meets it
    at the frequency nV/L (see :func:`passing_frequency`). The amplitude of
    harmonic n is 2|Xₙ|/N from the discrete Fourier transform of the N samples.

    >>> x = np.arange(64) / 64
    >>> np.round(harmonic_amplitudes(3 * np.cos(2 * np.pi * x) + np.sin(6 * np.pi * x), 3), 12).tolist()
    [3.0, 0.0, 1.0]
    """
    samples = _checks.array("one_period", one_period, ndim=1)
    count = _checks.integer("count", count, low=1, high=(samples.size - 1) // 2)
    return 2.0 * np.abs(np.fft.rfft(samples))[1 : count + 1] / samples.size
