"""Equivalent conicity of a tabulated rolling-radius difference Δr(y): EN 15302 and the first harmonic.

A coned wheelset of slope λ, rolling without slip, moves along the track in Klingel's
sine wave of wavelength L = 2π√(r₀ e₀/λ) (r₀ the nominal rolling radius, e₀ half the
distance between the contact points). A real wheel–rail pair has a nonlinear
rolling-radius difference Δr(y) = r_L − r_R, and its kinematic motion has a wavelength that
depends on the amplitude; the *equivalent conicity* λ_e(ŷ) is the slope of the cone with the
same wavelength at that amplitude.

* :func:`kinematic_conicity` is that quantity as EN 15302 defines it (CEN 2008, §4 and
  Annex B, the "integration of the nonlinear differential equation"): the kinematic
  wheelset equation y'' = −Δr(y)/(2 r₀ e₀) (x the distance run) is integrated once,
  ψ² = (C − S(y))/(r₀ e₀) with S(y) = ∫Δr dy, and x = ∫dy/ψ between the turning points
  gives half the wavelength. r₀ and e₀ enter the wavelength and Klingel's formula alike and
  cancel: λ_e depends on Δr(y) alone. The amplitude ŷ is half the peak-to-peak lateral
  excursion; the motion is centred on the lowest point of S, where Δr changes sign (for an
  asymmetric pair, not at y = 0).
* :func:`harmonic_conicity` is the describing-function (first-harmonic) linearisation,
  λ_h(A) = (1/(2πA)) ∫₀^{2π} Δr(A sin θ) sin θ dθ, which assumes a sinusoidal motion.

The two agree for a cone and part near a jump of Δr: the harmonic value weighs the jump by
its first Fourier coefficient over a sine of amplitude A, whereas the kinematic motion is
not a sine at all: it lingers on the flat part of Δr, where the restoring slope is small, and
turns quickly on the steep part, so its period is set by the time it spends on each part of
the curve. EN 15302 also describes (Annex C) a linear regression of Δr over ±ŷ; it is not
implemented here.

Δr is interpolated linearly between the tabulated shifts. On each interval S is then a
quadratic, and the time ∫dy/√(C − S) over it has a closed form (an arctangent, an
inverse hyperbolic tangent, or 2h/(√Q₀ + √Q₁)), so the integration is exact for the
interpolated table: no step size, and the square-root singularities at the turning points
cost nothing.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks

__all__ = ["harmonic_conicity", "kinematic_conicity"]

_SAMPLES_MAX = (
    65536  # quadrature points: the rectangle rule is long converged (spectrally, or 1/n² at a kink)
)
_REACH_SLACK = 1e-9  # relative: an amplitude this close to the table's reach is taken as the reach (rounding)
_BISECTIONS = 200  # halvings of the level C: the bracket reaches adjacent floats long before


def _table(shifts, delta_r) -> tuple[np.ndarray, np.ndarray]:
    """Checked (y, Δr): y strictly increasing, at least two; Δr finite, one per y."""
    y = _checks.increasing("shifts", shifts)
    if y.ndim != 1 or y.size < 2:
        raise ValueError(f"shifts must hold at least two positions in a 1-D array, got shape {y.shape}")
    dr = _checks.array("delta_r", delta_r, shape=(y.size,))
    return y, dr


def _amplitudes(amplitudes) -> np.ndarray:
    """Amplitudes (m) as a non-empty 1-D array, each > 0."""
    amp = np.atleast_1d(_checks.array("amplitudes", amplitudes, low=0.0, low_open=True, allow_empty=False))
    if amp.ndim != 1:
        raise ValueError(f"amplitudes must be a number or a 1-D array, got shape {amp.shape}")
    return amp


def harmonic_conicity(shifts, delta_r, amplitudes, *, samples: int = 256) -> np.ndarray:
    """First-harmonic (describing-function) conicity of a tabulated Δr(y).

    λ_h(A) = (1/(2πA)) ∫₀^{2π} Δr(A sin θ) sin θ dθ: the first Fourier coefficient of
    Δr(y)/2 over a sinusoidal motion y = A sin θ (Δr interpolated linearly; the table must
    cover ±max(A)). A cone of slope λ gives λ at every A. This is *not* EN 15302's equivalent
    conicity (:func:`kinematic_conicity`): near a jump of Δr it runs well above it.

    Parameters
    ----------
    shifts : array_like
        y (m), strictly increasing, at least two.
    delta_r : array_like
        Δr(y) (m), same length, any sign.
    amplitudes : float or array_like
        A (m), > 0, 1-D, within the table: the shifts must span ±max(A).
    samples : int, keyword
        Points in θ of the quadrature (the rectangle rule, spectrally accurate for a
        periodic integrand apart from the kinks of Δr), 8 to 65536.

    Returns
    -------
    ndarray
        λ_h for each amplitude (dimensionless).

    Examples
    --------
    >>> y = np.linspace(-0.01, 0.01, 201)
    >>> np.round(harmonic_conicity(y, 2 * 0.05 * y, [2e-3, 5e-3]), 12).tolist()  # a cone: λ
    [0.05, 0.05]
    """
    y, dr = _table(shifts, delta_r)
    amp = _amplitudes(amplitudes)
    reach = min(-y[0], y[-1])
    if amp.max() > reach * (1 + 1e-12):
        raise ValueError(
            f"amplitudes must lie within the table of shifts, which spans ±{max(reach, 0.0):.4g} m "
            f"(from {y[0]:.4g} to {y[-1]:.4g} m), got {amp.max()!r}"
        )
    n = _checks.integer("samples", samples, low=8, high=_SAMPLES_MAX)
    theta = 2 * np.pi * np.arange(n) / n
    values = np.interp(amp[:, None] * np.sin(theta)[None, :], y, dr)
    return (values * np.sin(theta)).mean(axis=1) / amp


class _Potential:
    """S(y) = ∫Δr dy of a piecewise-linear Δr, on a grid refined so that Δr keeps one sign per interval.

    ``y``, ``dr``, ``s`` at the nodes; ``slope`` of Δr on each interval. The nodes include every
    zero crossing of Δr, so S is monotone between nodes and its extrema are nodes.
    """

    def __init__(self, y: np.ndarray, dr: np.ndarray):
        cross = np.flatnonzero(np.sign(dr[:-1]) * np.sign(dr[1:]) < 0)
        at = y[cross] + (y[cross + 1] - y[cross]) * (dr[cross] / (dr[cross] - dr[cross + 1]))
        inside = (at > y[cross]) & (at < y[cross + 1])  # a crossing that rounds on to a node is that node
        y = np.insert(y, cross[inside] + 1, at[inside])
        dr = np.insert(dr, cross[inside] + 1, 0.0)
        self.y, self.dr = y, dr
        h = np.diff(y)
        self.slope = np.diff(dr) / h
        self.s = np.concatenate([[0.0], np.cumsum(0.5 * (dr[1:] + dr[:-1]) * h)])

    def at(self, k: np.ndarray, t: np.ndarray) -> np.ndarray:
        """S at y[k] + t (0 ≤ t ≤ the interval k)."""
        return self.s[k] + t * (self.dr[k] + 0.5 * self.slope[k] * t)


def _rising_root(s0, d0, q, level) -> np.ndarray:
    """t ≥ 0 where s0 + d0 t + q t²/2 first reaches ``level`` ≥ s0 while rising (d0 + q t ≥ 0)."""
    rise = np.maximum(level - s0, 0.0)
    root = np.sqrt(np.maximum(d0 * d0 + 2.0 * q * rise, 0.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(d0 + root > 0, 2.0 * rise / (d0 + root), 0.0)
    return t


class _Side:
    """One side of the well of S: the nodes from the centre outwards, S non-decreasing where it matters.

    ``sign`` is +1 for the side of larger y, −1 for the other; the other side is handled as the
    mirror image (y → −y, Δr → −Δr leave S unchanged), so both use the same rising-root algebra.
    """

    def __init__(self, pot: _Potential, centre: int, sign: int):
        if sign > 0:
            idx = np.arange(centre, pot.y.size)
        else:
            idx = np.arange(centre, -1, -1)
        self.y = sign * pot.y[idx]
        self.dr = sign * pot.dr[idx]
        self.s = pot.s[idx]
        self.sign = sign
        self.slope = np.diff(self.dr) / np.diff(self.y)  # unchanged by the mirror: (−Δr)/(−y)
        self.peak = np.maximum.accumulate(self.s)  # the highest level reached up to each node

    @property
    def top(self) -> float:
        """The highest level S reaches on this side within the table."""
        return float(self.peak[-1]) if self.peak.size > 1 else -np.inf

    def turning(self, level: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(interval index j, offset t) of the first point where S reaches each level (< top)."""
        j = np.searchsorted(self.peak, level, side="left") - 1  # node j below the level, node j+1 not
        j = np.clip(j, 0, self.y.size - 2)
        t = _rising_root(self.s[j], self.dr[j], self.slope[j], level)
        return j, np.minimum(t, self.y[j + 1] - self.y[j])

    def position(self, level: np.ndarray) -> np.ndarray:
        """Distance from the centre to the turning point at each level (m, ≥ 0)."""
        j, t = self.turning(level)
        return self.y[j] + t - self.y[0]

    def time(self, level: np.ndarray) -> np.ndarray:
        """∫ dy/√(C − S) from the centre to the turning point, for each level C (exact per interval)."""
        j_end, t_end = self.turning(level)
        n = self.y.size - 1
        k = np.arange(n)[None, :]
        inside = k < j_end[:, None]  # whole intervals before the one holding the turning point
        last = k == j_end[:, None]
        h_full = np.diff(self.y)[None, :]
        h = np.where(inside, h_full, np.where(last, t_end[:, None], 0.0))
        c = level[:, None]
        q0 = np.maximum(c - self.s[None, :-1], 0.0)
        q1 = np.where(last, 0.0, np.maximum(c - self.s[None, 1:], 0.0))
        pieces = np.where(h > 0, _interval_time(h, q0, q1, self.slope[None, :]), 0.0)
        return pieces.sum(axis=1)


def _interval_time(h, q0, q1, slope) -> np.ndarray:
    """∫₀^h dt/√Q(t) for a quadratic Q ≥ 0 with Q(0) = q0, Q(h) = q1 and Q'' = −slope.

    With σ = √q0 + √q1 and g = |slope|/2 the integral is 2 arctan(√g h/σ)/√g for slope > 0,
    2 artanh(√g h/σ)/√g for slope < 0 and 2h/σ for slope = 0 (Euler's substitution
    √Q = √q0 + w t reduces every case to this one form; σ ≥ √g h always, with equality only
    when Q has a double root in [0, h], where the time is infinite).
    """
    sigma = np.sqrt(q0) + np.sqrt(q1)
    g = 0.5 * np.abs(slope)
    root = np.sqrt(g)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        ratio = root * h / sigma
        arc = np.where(slope > 0, np.arctan2(root * h, sigma), np.arctanh(np.minimum(ratio, 1.0)))
        out = np.where(g > 0, 2.0 * arc / np.where(g > 0, root, 1.0), 2.0 * h / sigma)
    return out


def kinematic_conicity(shifts, delta_r, amplitudes) -> np.ndarray:
    """Equivalent conicity λ_e(ŷ) of a tabulated Δr(y) by EN 15302's kinematic method.

    The wheelset's kinematic motion y'' = −Δr(y)/(2 r₀ e₀) has the first integral
    ψ² = (C − S(y))/(r₀ e₀), S(y) = ∫Δr dy (EN 15302, Annex B). For the level C whose turning
    points y₁ < y₂ (S(y₁) = S(y₂) = C) lie 2ŷ apart, half the wavelength is
    √(r₀ e₀) ∫_{y₁}^{y₂} dy/√(C − S), and Klingel's L = 2π√(r₀ e₀/λ_e) gives

        λ_e = π² / (∫_{y₁}^{y₂} dy/√(C − S(y)))²,

    free of r₀ and e₀. The motion is centred on the lowest point of S (where Δr rises
    through zero); ŷ is half its peak-to-peak excursion. Where Δr is exactly zero over a
    central band wider than 2ŷ the wheelset is not steered at all there: λ_e = 0.

    Parameters
    ----------
    shifts : array_like
        y (m), strictly increasing, at least two; the table must reach both turning points.
    delta_r : array_like
        Δr(y) = r_L − r_R (m), one per shift, interpolated linearly; it must rise through
        zero (a restoring rolling-radius difference) somewhere inside the table.
    amplitudes : float or array_like
        ŷ (m), > 0, 1-D, each within the table's reach (the largest motion whose turning
        points both lie in the table; the message names it).

    Returns
    -------
    ndarray
        λ_e for each amplitude (dimensionless), ≥ 0.

    Examples
    --------
    A cone gives its slope; a rolling-radius difference that jumps by 2δ at y = 0
    (Δr = δ sign y, here as a steep ramp) gives π²δ/(16ŷ), below the first harmonic's 2δ/(πŷ):

    >>> y = np.linspace(-0.01, 0.01, 201)
    >>> np.round(kinematic_conicity(y, 2 * 0.05 * y, [2e-3, 5e-3]), 12).tolist()
    [0.05, 0.05]
    >>> y = np.array([-0.01, -1e-12, 1e-12, 0.01])
    >>> step = kinematic_conicity(y, 1e-3 * np.sign(y), 4e-3)[0]
    >>> round(float(step / (np.pi**2 * 1e-3 / (16 * 4e-3))), 9)
    1.0
    """
    y, dr = _table(shifts, delta_r)
    amp = _amplitudes(amplitudes)
    if not np.any(dr):  # a cylinder: no steering at all, an infinite wavelength
        reach = 0.5 * (y[-1] - y[0])
        if amp.max() > reach * (1 + _REACH_SLACK):
            raise ValueError(
                f"amplitudes must lie within the reach of the table, {reach:.4g} m (half the span of the "
                f"shifts, from {y[0]:.4g} to {y[-1]:.4g} m), got {amp.max()!r}"
            )
        return np.zeros_like(amp)
    pot = _Potential(y, dr)
    centre = int(np.argmin(pot.s))
    right, left = _Side(pot, centre, +1), _Side(pot, centre, -1)
    floor = pot.s[centre]
    top = min(right.top, left.top)
    if not top > floor:
        raise ValueError(
            "delta_r must rise through zero inside the table of shifts (a restoring rolling-radius "
            f"difference, negative on one side of the centre and positive on the other), got values from "
            f"{dr.min():.4g} to {dr.max():.4g} m over y from {y[0]:.4g} to {y[-1]:.4g} m"
        )
    # Δr exactly zero on a band around the centre: no steering there, λ_e = 0 for motions inside it.
    band = sum(side.y[np.argmax(side.s > floor) - 1] - side.y[0] for side in (right, left))
    width_top = right.position(np.array([top]))[0] + left.position(np.array([top]))[0]
    reach = 0.5 * width_top
    if amp.max() > reach * (1 + _REACH_SLACK):
        raise ValueError(
            f"amplitudes must lie within the reach of the table, {reach:.4g} m (the largest motion whose "
            f"turning points both lie between y = {y[0]:.4g} and {y[-1]:.4g} m), got {amp.max()!r}"
        )
    target = np.minimum(2.0 * amp, width_top)
    lo = np.full(amp.shape, floor)
    hi = np.full(amp.shape, top)
    for _ in range(_BISECTIONS):  # the level C whose turning points lie 2ŷ apart (the width grows with C)
        mid = 0.5 * (lo + hi)
        if not np.any((mid > lo) & (mid < hi)):
            break
        wide = right.position(mid) + left.position(mid) >= target
        hi = np.where(wide, mid, hi)
        lo = np.where(wide, lo, mid)
    period = right.time(hi) + left.time(hi)  # ∫ dy/√(C − S) from one turning point to the other
    with np.errstate(divide="ignore", over="ignore"):
        lam = np.where(np.isfinite(period), (np.pi / period) ** 2, 0.0)
    return np.where(2.0 * amp <= band * (1 + _REACH_SLACK), 0.0, lam)
