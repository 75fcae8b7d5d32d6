"""Single-degree-of-freedom curves as functions of the damping factor ξ and frequency ratio r.

The root locus (book Fig. 1.4, :class:`RootLocus` with ``.plot``), the logarithmic decrement and
its inverse (eq. 1.17), the decrement measured from two peaks, and the harmonic-response curves:
magnification factor, phase angle and transmissibility. The oscillator itself is
:class:`raildyn.vibration.SDOF`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._checks import array, integer, positive, scalar
from raildyn._tables import Tabular
from raildyn.vibration._domain import _RATE, _check_rates, _one_minus_square, _roots

__all__ = [
    "RootLocus",
    "damping_ratio_from_decrement",
    "decrement_from_peaks",
    "log_decrement",
    "magnification_factor",
    "phase_angle",
    "root_locus",
    "transmissibility_ratio",
]


@dataclass(frozen=True)
class RootLocus(Tabular):
    """Characteristic roots s₁, s₂ of an SDOF system over a sweep of damping factors (book Fig. 1.4).

    Attributes
    ----------
    natural_frequency : float
        ω_n, rad/s.
    damping_ratios : ndarray, shape (n,)
        ξ values swept.
    roots : complex ndarray, shape (n, 2)
        s₁ (+ sign in eq. 1.9) and s₂ for each ξ, rad/s.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("damping_ratios", "-"), ("roots", "rad/s"))
    _scalars = (("natural_frequency", "rad/s"),)

    natural_frequency: float
    damping_ratios: np.ndarray
    roots: np.ndarray

    def __post_init__(self):
        object.__setattr__(self, "natural_frequency", positive("natural_frequency", self.natural_frequency))
        xi = array("damping_ratios", self.damping_ratios, ndim=1, low=0.0, allow_empty=False)
        object.__setattr__(self, "damping_ratios", xi)
        object.__setattr__(self, "roots", array("roots", self.roots, dtype=complex, shape=(xi.size, 2)))

    def plot(self, ax=None, *, mark=None, normalised: bool = False) -> dict:
        """Draw both branches of the locus, the circle |s| = ω_n and, optionally, marked roots.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        mark : complex array_like, shape (2,), optional
            Roots to mark, rad/s, finite (scaled like the locus when ``normalised``); the
            marker is drawn hidden when None, for a widget to move and show later.
        normalised : bool
            Draw s/ω_n instead of s in rad/s.

        Returns
        -------
        dict
            The artists: ``branch1``, ``branch2``, ``roots`` (the marker) and ``circle``.
        """
        import matplotlib

        from raildyn import plots

        if mark is not None:
            mark = array("mark", mark, dtype=complex, shape=(2,))
        normalised = _checks.flag("normalised", normalised)
        ax = plots.axes_or_new(ax)
        scale = 1.0 / self.natural_frequency if normalised else 1.0
        locus = self.roots * scale
        radius = self.natural_frequency * scale
        with matplotlib.rc_context(plots.STYLE):
            phi = np.linspace(np.pi / 2, 3 * np.pi / 2, 91)
            (circle,) = ax.plot(radius * np.cos(phi), radius * np.sin(phi), ls=":", color="0.6", lw=1)
            (b1,) = ax.plot(locus[:, 0].real, locus[:, 0].imag, color=plots.COLORS[0], label="$s_1$")
            (b2,) = ax.plot(locus[:, 1].real, locus[:, 1].imag, color=plots.COLORS[1], label="$s_2$")
            marks = np.zeros(2, complex) if mark is None else scale * mark
            (pts,) = ax.plot(marks.real, marks.imag, "o", color="k", ms=7, mfc="w", mew=2, zorder=5)
            pts.set_visible(mark is not None)
            ax.axhline(0, color="0.4", lw=0.8)
            ax.axvline(0, color="0.4", lw=0.8)
            ax.set_aspect("equal", adjustable="box")
            unit = r"$s/\omega_n$" if normalised else "$s$ (rad/s)"
            ax.set_xlabel(f"Re {unit}")
            ax.set_ylabel(f"Im {unit}")
            ax.legend(loc="upper left")
        return {"branch1": b1, "branch2": b2, "roots": pts, "circle": circle}


def root_locus(natural_frequency: float, damping_ratios) -> RootLocus:
    """Characteristic roots s₁, s₂ (rad/s) for each damping factor in a sweep (Fig. 1.4).

    Parameters
    ----------
    natural_frequency : float
        ω_n in rad/s, in (0, 1e150] (the domain of :class:`~raildyn.vibration.SDOF`).
    damping_ratios : array_like, shape (n,)
        ξ values, >= 0, with 2ξω_n <= 1e300 1/s (the domain of :class:`~raildyn.vibration.SDOF`); not empty.

    Returns
    -------
    RootLocus
        ``roots`` has shape (n, 2): columns s₁ (+ sign in eq. 1.9) and s₂;
        ``.plot(ax)`` draws Fig. 1.4.

    Examples
    --------
    >>> root_locus(1.0, [0.0, 1.0]).roots
    array([[ 0.+1.j,  0.-1.j],
           [-1.+0.j, -1.+0.j]])
    """
    wn = scalar("natural_frequency", natural_frequency, low=0.0, low_open=True, high=math.sqrt(_RATE))
    xi = array("damping_ratios", damping_ratios, ndim=1, low=0.0, allow_empty=False)
    _check_rates(wn * wn, 2.0 * xi.max() * wn, "natural_frequency", "damping_ratios and natural_frequency")
    return RootLocus(wn, xi, _roots(wn, xi))


def log_decrement(damping_ratio):
    """Logarithmic decrement δ = ln(x₁/x₂) = 2πξ/√(1 − ξ²) (eq. 1.17).

    Parameters
    ----------
    damping_ratio : array_like
        ξ, 0 <= ξ < 1 (a system with ξ >= 1 does not oscillate, so it has no decrement;
        :attr:`~raildyn.vibration.SDOF.log_decrement` reports ``math.inf`` for it); any shape, not empty.

    Returns
    -------
    ndarray or float
        δ, dimensionless, shape of ``damping_ratio``.

    Examples
    --------
    >>> round(float(log_decrement(0.1)), 4)
    0.6315
    """
    xi = array("damping_ratio", damping_ratio, low=0.0, allow_empty=False)
    if np.any(xi >= 1.0):
        raise ValueError(
            f"damping_ratio must be < 1 (a system with xi >= 1 does not oscillate, so it has no "
            f"decrement), got {xi[xi >= 1.0].flat[0]!r}"
        )
    return (2.0 * np.pi * xi / np.sqrt(_one_minus_square(xi)))[()]


def damping_ratio_from_decrement(delta):
    """Damping factor from a measured decrement, ξ = δ/√(4π² + δ²) (eq. 1.17 inverted).

    Parameters
    ----------
    delta : array_like
        δ >= 0 (finite: a system with ξ >= 1 has no decrement to measure); any shape, not empty.

    Returns
    -------
    ndarray or float
        ξ, shape of ``delta``.

    Examples
    --------
    >>> round(float(damping_ratio_from_decrement(log_decrement(0.3))), 12)
    0.3
    """
    d = array("delta", delta, low=0.0, allow_empty=False)
    return (d / np.hypot(2.0 * np.pi, d))[()]


def decrement_from_peaks(first, later, cycles: int = 1) -> float:
    """Logarithmic decrement measured from two maxima ``cycles`` periods apart: δ = ln(x₀/x_j)/j.

    Successive maxima of a free decay shrink by e^δ each period (eqs. 1.15-1.17),
    so j periods apart they shrink by e^(jδ); averaging over several periods is
    how a decrement is read off a record.

    Parameters
    ----------
    first : float
        The earlier maximum x₀, > 0 (any unit).
    later : float
        The maximum x_j, j periods later, > 0 (same unit).
    cycles : int
        j >= 1.

    Returns
    -------
    float
        δ, dimensionless.

    Examples
    --------
    >>> delta = decrement_from_peaks(12.0, 3.0, cycles=5)
    >>> round(delta, 4), round(float(damping_ratio_from_decrement(delta)), 4)
    (0.2773, 0.0441)
    """
    x0 = positive("first", first)
    xj = positive("later", later)
    j = integer("cycles", cycles, low=1)
    return math.log(x0 / xj) / j


def _scaled_terms(frequency_ratio, damping_ratio):
    """Checked r and ξ, and the terms (1 − r², 2ξr) and 1 of the SDOF curves, each divided by s².

    s = max(r, 1): dividing through by s² keeps every term finite for any finite r and ξ (1e300
    included) and changes nothing for r <= 1. Returns (1 − r²)/s², 2ξr/s² and 1/s².
    """
    r = array("frequency_ratio", frequency_ratio, low=0.0, allow_empty=False)
    xi = array("damping_ratio", damping_ratio, low=0.0, allow_empty=False)
    _checks.broadcast(frequency_ratio=r, damping_ratio=xi)
    inv = 1.0 / np.maximum(r, 1.0)
    u = r * inv
    return (inv - u) * (inv + u), 2.0 * xi * u * inv, inv * inv


def magnification_factor(frequency_ratio, damping_ratio):
    """Dynamic magnification |X| k/F₀ = 1/√((1 − r²)² + (2ξr)²) of a harmonically forced SDOF system.

    Parameters
    ----------
    frequency_ratio : array_like
        r = ω/ω_n >= 0, any shape (not empty).
    damping_ratio : array_like
        ξ >= 0; broadcast against ``frequency_ratio``.

    Returns
    -------
    ndarray
        Dimensionless; inf for ξ = 0 at r = 1.

    Examples
    --------
    >>> magnification_factor([0.0, 1.0], 0.25)
    array([1., 2.])
    """
    q, y, inv2 = _scaled_terms(frequency_ratio, damping_ratio)
    den = np.hypot(q, y)
    num = np.broadcast_to(inv2, den.shape)
    return np.divide(num, den, out=np.full(den.shape, np.inf), where=den > 0)[()]


def phase_angle(frequency_ratio, damping_ratio):
    """Phase lag φ = atan2(2ξr, 1 − r²) of the displacement behind the force, rad, in [0, π].

    For ξ = 0 the lag jumps from 0 to π at r = 1, where π/2 (the limit as
    ξ → 0) is returned.

    Parameters
    ----------
    frequency_ratio : array_like
        r = ω/ω_n >= 0, any shape (not empty).
    damping_ratio : array_like
        ξ >= 0; broadcast against ``frequency_ratio``.

    Returns
    -------
    ndarray
        φ, rad.

    Examples
    --------
    >>> np.round(phase_angle([0.0, 1.0], 0.1) / np.pi, 12)
    array([0. , 0.5])
    """
    q, y, _ = _scaled_terms(frequency_ratio, damping_ratio)  # the angle does not change with the scale
    # atan2(0, 0) would give 0 for the undamped system at resonance; the limit ξ → 0 there is π/2.
    return np.where((q == 0.0) & (y == 0.0), np.pi / 2, np.arctan2(y, q))[()]


def transmissibility_ratio(frequency_ratio, damping_ratio):
    """Transmissibility √(1 + (2ξr)²)/√((1 − r²)² + (2ξr)²), for force to ground or base motion to mass.

    Equal to 1 at r = √2 whatever ξ; isolation (< 1) needs r > √2.

    Parameters
    ----------
    frequency_ratio : array_like
        r = ω/ω_n >= 0, any shape (not empty).
    damping_ratio : array_like
        ξ >= 0; broadcast against ``frequency_ratio``.

    Returns
    -------
    ndarray
        Dimensionless; inf for ξ = 0 at r = 1.

    Examples
    --------
    >>> round(float(transmissibility_ratio(3.0, 0.0)), 12)
    0.125
    """
    q, y, inv2 = _scaled_terms(frequency_ratio, damping_ratio)
    num = np.hypot(inv2, y)
    den = np.hypot(q, y)
    return np.divide(num, den, out=np.full(den.shape, np.inf), where=den > 0)[()]
