"""The single-degree-of-freedom oscillator m x'' + c x' + k x = F(t) (book eq. 1.3).

Free response in every damping regime, the characteristic roots and their locus
(Fig. 1.4), the logarithmic decrement (eq. 1.17), harmonic and base-excited
response, and the exact response to a sampled force. SI units: m, kg, s, N, rad/s.

Results come as frozen dataclasses: :class:`DecayPeaks`, :class:`FreeVibration`
(with ``.plot``) and :class:`RootLocus` (with ``.plot``, book Fig. 1.4).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import scipy.linalg
import scipy.signal

from raildyn import _checks
from raildyn._checks import array, integer, nonnegative, positive, scalar, time_grid

if TYPE_CHECKING:  # mdof imports this module, so its classes are named here for the annotations only
    from raildyn.vibration.mdof import StateSpaceMatrices

__all__ = [
    "SDOF",
    "DecayPeaks",
    "FreeVibration",
    "RootLocus",
    "damping_ratio_from_decrement",
    "decrement_from_peaks",
    "log_decrement",
    "magnification_factor",
    "phase_angle",
    "root_locus",
    "transmissibility_ratio",
]

# |ξ − 1| at or below this counts as critical damping in SDOF.regime.
CRITICAL_TOLERANCE = 1e-9

# The domain of an SDOF: k/m (= ω_n², (rad/s)²) within [1/_RATE, _RATE] and c/m (= 2ξω_n, 1/s) at
# most _RATE. Then ω_n, ξω_n and both roots stay below 1e300, inside floating point with room to
# spare, and the free response stays finite for every ξ (ξ = 1e200 included).
_RATE = 1e300

# At most this many maxima, peaks or frequencies in one call: a bound on the memory asked for.
_MAX_COUNT = 1_000_000

# The largest phase ω_n h (rad) of one time step in forced_response: beyond it the rounding of h
# alone (1e-16 of it) moves the phase by more than 1e-4 rad, and near 1e16 the one-step matrix
# exponential stops being finite.
_MAX_PHASE = 1e12


def _check_rates(stiffness_rate: float, damping_rate: float, stiffness_names: str, damping_names: str):
    """Refuse an SDOF outside its domain (see ``_RATE``), naming the parameters that set each rate."""
    if not (1.0 / _RATE <= stiffness_rate <= _RATE):
        raise ValueError(
            f"{stiffness_names} give omega_n^2 = k/m = {stiffness_rate:.4g} (rad/s)^2; raildyn takes "
            f"k/m in [1e-300, 1e300] (omega_n from 1e-150 to 1e150 rad/s) so that omega_n^2 and the "
            "roots stay inside floating point"
        )
    if not damping_rate <= _RATE:
        raise ValueError(
            f"{damping_names} give c/m = 2 xi omega_n = {damping_rate:.4g} 1/s; raildyn takes c/m "
            "<= 1e300 1/s so that the roots -xi omega_n ± ... stay inside floating point"
        )


# ---------------------------------------------------------------------------
# Closed forms shared by the SDOF class and the module-level functions


def _one_minus_square(xi):
    """1 − ξ², written as (1 − ξ)(1 + ξ) so that it keeps its relative accuracy near ξ = 1."""
    return (1.0 - xi) * (1.0 + xi)


def _roots(natural_frequency: float, xi: np.ndarray) -> np.ndarray:
    """Roots s₁, s₂ = (−ξ ± √(ξ² − 1)) ω_n (eq. 1.9) for an array of ξ; shape (n, 2)."""
    wn = natural_frequency
    over = xi > 1.0
    wd = wn * np.sqrt(np.maximum(_one_minus_square(np.minimum(xi, 1.0)), 0.0))
    re = 0.0 - xi * wn  # +0.0, not −0.0, for an undamped system
    # Overdamped: s₂ = −ω_n g and s₁ = −ω_n/g with g = ξ + √(ξ − 1)√(ξ + 1) >= 1 (s₁ s₂ = ω_n²):
    # no cancellation in s₁ for large ξ, and no ξ² to overflow.
    g = np.where(over, xi + np.sqrt(np.maximum(xi - 1.0, 0.0)) * np.sqrt(xi + 1.0), 1.0)
    s1 = np.where(over, -wn / g, re + 1j * wd)
    s2 = np.where(over, -wn * g, re - 1j * wd)
    return np.stack([s1, s2], axis=-1)


def _decay_pair(wn: float, xi: float, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return e^(−ξω_n t) C(t) and e^(−ξω_n t) S(t) for t >= 0.

    C and S solve y'' = −ω_n²(1 − ξ²) y with C(0) = 1, C'(0) = 0, S(0) = 0,
    S'(0) = 1: cos and sin(ω_d t)/ω_d when ξ <= 1, cosh and sinh when ξ > 1.
    Every solution of eq. (1.5) is a combination of the two, and both pass
    continuously through ξ = 1 (S → t), so no regime divides by ω_d → 0.
    """
    q = _one_minus_square(xi)
    if q >= 0.0:
        wd = wn * math.sqrt(q)
        decay = np.exp(-xi * wn * t)
        s = np.sin(wd * t) / wd if wd > 0.0 else t
        return decay * np.cos(wd * t), decay * s
    # Overdamped: write cosh and sinh through the slow root s₁ and the ratio e^((s₂−s₁)t) = e^(−2bt),
    # which neither overflows for large t nor loses accuracy as b → 0. The square roots are taken
    # apart, and s₁ = −ω_n/g (g = ξ + √(ξ² − 1)), so that nothing overflows for ξ up to 1e300.
    root = math.sqrt(xi - 1.0) * math.sqrt(xi + 1.0)
    b = wn * root
    slow = np.exp((-wn / (xi + root)) * t)
    z = 2.0 * b * t
    return slow * 0.5 * (1.0 + np.exp(-z)), slow * (-np.expm1(-z) / (2.0 * b))


def _reciprocal(numerator, denominator):
    """numerator/denominator, with a complex infinity where the denominator is exactly zero.

    Only an undamped system driven exactly at resonance meets a zero, and there
    the steady amplitude really is unbounded; returning inf avoids a NaN.
    """
    num = np.broadcast_to(np.asarray(numerator, dtype=complex), np.shape(denominator))
    out = np.full(np.shape(denominator), complex(np.inf, 0.0))
    np.divide(num, denominator, out=out, where=denominator != 0)
    return out


# ---------------------------------------------------------------------------
# Results


@dataclass(frozen=True)
class DecayPeaks:
    """Successive maxima of an underdamped free response (book Fig. 1.5).

    Attributes
    ----------
    times : ndarray, shape (count,)
        Times of the maxima, s, one damped period T_d apart.
    values : ndarray, shape (count,)
        Displacements there, m (or the unit of x0).
    """

    times: np.ndarray
    values: np.ndarray

    def __post_init__(self):
        times = array("times", self.times, ndim=1, low=0.0)
        values = array("values", self.values)
        if values.shape != times.shape:
            raise ValueError(
                f"times and values must have the same shape, got {times.shape} and {values.shape}"
            )
        object.__setattr__(self, "times", times)
        object.__setattr__(self, "values", values)

    @property
    def log_decrement(self) -> float:
        """δ = ln(x₁/x_{j+1})/j measured over the j periods between the first and the last peak (eq. 1.17).

        Needs at least two peaks; equal to :attr:`~raildyn.vibration.SDOF.log_decrement` to rounding.
        """
        return decrement_from_peaks(self.values[0], self.values[-1], cycles=self.values.size - 1)


@dataclass(frozen=True)
class FreeVibration:
    """The free response of an SDOF system on a time grid, with its envelope and its maxima.

    Built by :meth:`SDOF.free_vibration`; :meth:`plot` draws it as book Fig. 1.5.

    Attributes
    ----------
    time : ndarray, shape (n,)
        t, s.
    displacement : ndarray, shape (n,)
        x(t), in the unit of x0 (m).
    envelope : ndarray, shape (n,)
        A e^(−ξω_n t) when the system oscillates, else |x(t)|; same unit.
    peaks : DecayPeaks
        The first maxima (empty arrays when ξ >= 1: no oscillation, no peaks).
    """

    time: np.ndarray
    displacement: np.ndarray
    envelope: np.ndarray
    peaks: DecayPeaks

    def __post_init__(self):
        time = array("time", time_grid("time", self.time), low=0.0)
        object.__setattr__(self, "time", time)
        object.__setattr__(self, "displacement", array("displacement", self.displacement, shape=time.shape))
        object.__setattr__(self, "envelope", array("envelope", self.envelope, shape=time.shape, low=0.0))
        _checks.instance("peaks", self.peaks, DecayPeaks)

    def plot(self, ax=None, *, artists=None) -> dict:
        """Draw x(t), the envelope ±A e^(−ξω_n t) and the maxima; or move artists drawn before.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        artists : dict, optional
            The dict a previous call returned: its lines are moved to this
            response (``set_data``) instead of drawing new ones, as a widget does.

        Returns
        -------
        dict
            The artists: ``line``, ``upper``, ``lower`` (the envelope) and ``peaks``.
        """
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict returned by an earlier plot")
            missing = {"line", "upper", "lower", "peaks"} - set(artists)
            if missing:
                raise ValueError(
                    f"artists must be the dict an earlier plot returned; it lacks {sorted(missing)}"
                )
            artists["line"].set_data(self.time, self.displacement)
            artists["upper"].set_data(self.time, self.envelope)
            artists["lower"].set_data(self.time, -self.envelope)
            artists["peaks"].set_data(self.peaks.times, self.peaks.values)
            return artists
        import matplotlib

        from raildyn import plots

        drawn = plots.time_history(self.time, self.displacement, ax=ax, envelope=self.envelope)
        ax = drawn["line"].axes
        with matplotlib.rc_context(plots.STYLE):
            (drawn["peaks"],) = ax.plot(
                self.peaks.times, self.peaks.values, "s", color=plots.COLORS[1], ms=6, label="maxima"
            )
        return drawn


@dataclass(frozen=True)
class RootLocus:
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


# ---------------------------------------------------------------------------
# Single degree of freedom


@dataclass(frozen=True)
class SDOF:
    """A linear single-degree-of-freedom oscillator, ``m x'' + c x' + k x = F(t)`` (eq. 1.3).

    Parameters
    ----------
    mass : float
        m in kg, > 0.
    damping : float
        Viscous damping coefficient c in N·s/m, >= 0, with c/m = 2ξω_n <= 1e300 1/s.
    stiffness : float
        k in N/m, > 0, with k/m = ω_n² in [1e-300, 1e300] (rad/s)².

    Notes
    -----
    The two bounds on the rates k/m and c/m keep ω_n, ξω_n and both roots below 1e300, inside
    floating point, so that every response stays finite, however heavy the damping (ξ = 1e200
    included); no physical oscillator comes near them.

    Examples
    --------
    >>> s = SDOF(mass=1000.0, damping=2000.0, stiffness=4.0e5)
    >>> round(s.natural_frequency, 6), round(s.damping_ratio, 6), s.regime
    (20.0, 0.05, 'underdamped')
    """

    mass: float
    damping: float
    stiffness: float

    def __post_init__(self):
        # The dataclass is frozen, so the checked floats are stored through object.__setattr__.
        object.__setattr__(self, "mass", positive("mass", self.mass))
        object.__setattr__(self, "damping", nonnegative("damping", self.damping))
        object.__setattr__(self, "stiffness", positive("stiffness", self.stiffness))
        _check_rates(
            self.stiffness / self.mass, self.damping / self.mass, "stiffness and mass", "damping and mass"
        )

    @classmethod
    def from_modal(cls, natural_frequency: float, damping_ratio: float, mass: float = 1.0) -> SDOF:
        """Build the oscillator from its natural frequency, damping factor and mass.

        Uses k = m ω_n² and c = ξ c_c = 2 ξ m ω_n (eqs. 1.5 and 1.14).

        Parameters
        ----------
        natural_frequency : float
            ω_n, rad/s, in (0, 1e150] (the domain of :class:`~raildyn.vibration.SDOF`: k/m = ω_n² <= 1e300).
        damping_ratio : float
            ξ, >= 0, with 2ξω_n <= 1e300 1/s (the domain of :class:`~raildyn.vibration.SDOF`).
        mass : float
            m, kg, > 0, with m ω_n² and 2ξmω_n finite.

        Returns
        -------
        SDOF

        Examples
        --------
        >>> s = SDOF.from_modal(10.0, 0.2, mass=2.0)
        >>> s.stiffness, s.damping
        (200.0, 8.0)
        """
        wn = scalar("natural_frequency", natural_frequency, low=0.0, low_open=True, high=math.sqrt(_RATE))
        xi = nonnegative("damping_ratio", damping_ratio)
        m = positive("mass", mass)
        _check_rates(wn * wn, 2.0 * xi * wn, "natural_frequency", "damping_ratio and natural_frequency")
        k, c = m * wn**2, 2.0 * xi * m * wn
        if not (math.isfinite(k) and math.isfinite(c)):
            raise ValueError(
                f"mass {m!r} with natural_frequency {wn!r} and damping_ratio {xi!r} gives k = m omega_n^2 "
                f"= {k:.4g} N/m and c = 2 xi m omega_n = {c:.4g} N s/m: beyond floating point"
            )
        return cls(mass=m, damping=c, stiffness=k)

    # -- characteristics -------------------------------------------------

    @property
    def natural_frequency(self) -> float:
        """Undamped natural circular frequency ω_n = √(k/m), rad/s (eq. 1.5)."""
        return math.sqrt(self.stiffness / self.mass)

    @property
    def critical_damping(self) -> float:
        """Critical damping coefficient c_c = 2√(km), N·s/m (eq. 1.14)."""
        km = self.stiffness * self.mass
        # √(km) rounds once (so ξ = 1 comes out exactly where it should); √k √m only where km
        # would overflow or underflow.
        return 2.0 * (
            math.sqrt(km) if 1e-300 < km < 1e300 else math.sqrt(self.stiffness) * math.sqrt(self.mass)
        )

    @property
    def damping_ratio(self) -> float:
        """Damping factor ξ = c/c_c, dimensionless (eq. 1.14)."""
        return self.damping / self.critical_damping

    @property
    def damped_frequency(self) -> float:
        """Damped circular frequency ω_d = ω_n √(1 − ξ²), rad/s (eq. 1.11); 0.0 when ξ >= 1."""
        q = _one_minus_square(self.damping_ratio)
        return self.natural_frequency * math.sqrt(q) if q > 0.0 else 0.0

    @property
    def damped_period(self) -> float:
        """Damped period T_d = 2π/ω_d, s; ``math.inf`` when ξ >= 1."""
        wd = self.damped_frequency
        return 2.0 * math.pi / wd if wd > 0.0 else math.inf

    @property
    def log_decrement(self) -> float:
        """Logarithmic decrement δ = 2πξ/√(1 − ξ²) (eq. 1.17); ``math.inf`` when ξ >= 1."""
        xi = self.damping_ratio
        return float(log_decrement(xi)) if xi < 1.0 else math.inf

    @property
    def regime(self) -> str:
        """Damping regime: ``"undamped"``, ``"underdamped"``, ``"critically damped"`` or ``"overdamped"``.

        Critical means |ξ − 1| <= 1e-9, a band far below any measured damping
        but wide enough to absorb rounding in ξ = c/(2√(km)).
        """
        xi = self.damping_ratio
        if xi == 0.0:
            return "undamped"
        if abs(xi - 1.0) <= CRITICAL_TOLERANCE:
            return "critically damped"
        return "underdamped" if xi < 1.0 else "overdamped"

    def roots(self) -> np.ndarray:
        """Characteristic roots [s₁, s₂] = (−ξ ± √(ξ² − 1)) ω_n, rad/s (eqs. 1.8, 1.9).

        Returns
        -------
        complex ndarray, shape (2,)
            s₁ takes the + sign: the upper root when underdamped, the one
            nearer zero when overdamped.

        Examples
        --------
        >>> SDOF.from_modal(2.0, 1.0).roots()
        array([-2.+0.j, -2.+0.j])
        """
        return _roots(self.natural_frequency, np.array([self.damping_ratio]))[0]

    # -- free and impulse response --------------------------------------

    def _pair(self, t):
        t = array("t", t, low=0.0, allow_empty=False)
        with np.errstate(over="ignore", invalid="ignore"):
            ec, es = _decay_pair(self.natural_frequency, self.damping_ratio, t)
        if not (np.all(np.isfinite(ec)) and np.all(np.isfinite(es))):
            raise ValueError(
                f"t must keep omega_d t finite for this system (omega_d = "
                f"{self.damped_frequency:.4g} rad/s), got t up to {t.max():.4g} s"
            )
        return ec, es

    @staticmethod
    def _finite(x, x0: float, v0: float):
        """``x`` itself, unless the initial state is so large that the response overflows."""
        if not np.all(np.isfinite(x)):
            raise ValueError(
                f"x0 = {x0!r} and v0 = {v0!r} give a response beyond floating point range at some t; "
                "scale the initial state down (the response is linear in it)"
            )
        return x

    def free_response(self, t, x0: float, v0: float):
        """Displacement x(t), m, of the free system started from x(0) = x0, x'(0) = v0.

        Solves eq. (1.5) in closed form: eqs. (1.11), (1.12) and (1.13) are
        the three faces of ``x = e^(−ξω_n t) [x0 C(t) + (v0 + ξω_n x0) S(t)]``
        with ``S = sin(ω_d t)/ω_d`` (ξ < 1), ``t`` (ξ = 1) or ``sinh(b t)/b``,
        b = ω_n√(ξ² − 1) (ξ > 1), evaluated so that it is smooth through ξ = 1.

        Parameters
        ----------
        t : array_like
            Times since the start, s, >= 0, any shape (not empty).
        x0 : float
            Initial displacement, m (any sign).
        v0 : float
            Initial velocity, m/s (any sign).

        Returns
        -------
        ndarray
            x(t), same shape as ``t`` (a numpy scalar for a scalar ``t``).

        Examples
        --------
        >>> s = SDOF.from_modal(1.0, 0.0)
        >>> round(float(s.free_response(np.pi, 1.0, 0.0)), 12)
        -1.0
        """
        x0, v0 = scalar("x0", x0), scalar("v0", v0)
        ec, es = self._pair(t)
        with np.errstate(over="ignore", invalid="ignore"):
            x = x0 * ec + (v0 + self.damping_ratio * self.natural_frequency * x0) * es
        return self._finite(x, x0, v0)[()]

    def free_velocity(self, t, x0: float, v0: float):
        """Velocity x'(t), m/s, of the free system.

        Differentiating the closed form and using ξ²ω_n² + ω_n²(1 − ξ²) = ω_n² gives
        ``x' = e^(−ξω_n t) [v0 C(t) − (ξω_n v0 + ω_n² x0) S(t)]``.

        Parameters
        ----------
        t : array_like
            Times since the start, s, >= 0, any shape (not empty).
        x0 : float
            Initial displacement, m (any sign).
        v0 : float
            Initial velocity, m/s (any sign).

        Returns
        -------
        ndarray
            x'(t), m/s, same shape as ``t``.

        Examples
        --------
        >>> s = SDOF.from_modal(1.0, 0.0)
        >>> round(float(s.free_velocity(np.pi / 2, 1.0, 0.0)), 12)
        -1.0
        """
        x0, v0 = scalar("x0", x0), scalar("v0", v0)
        ec, es = self._pair(t)
        wn = self.natural_frequency
        with np.errstate(over="ignore", invalid="ignore"):
            v = v0 * ec - (self.damping_ratio * wn * v0 + wn**2 * x0) * es
        return self._finite(v, x0, v0)[()]

    def impulse_response(self, t):
        """Unit-impulse response h(t), m/(N·s): the free response from x0 = 0, v0 = 1/m.

        The response to any force is the convolution x = ∫ h(t − τ) F(τ) dτ.

        Parameters
        ----------
        t : array_like
            Times after the impulse, s, >= 0, any shape (not empty).

        Returns
        -------
        ndarray
            h(t), m/(N·s), same shape as ``t``.

        Examples
        --------
        >>> s = SDOF.from_modal(1.0, 0.0, mass=2.0)
        >>> round(float(s.impulse_response(np.pi / 2)), 12)  # sin(ω_n t)/(m ω_n)
        0.5
        """
        return (self._pair(t)[1] / self.mass)[()]

    def envelope(self, t, x0: float, v0: float):
        """Decay envelope A e^(−ξω_n t), m, of the free response (ξ < 1; Fig. 1.5).

        A = √(x0² + ((v0 + ξω_n x0)/ω_d)²) is the amplitude of eq. (1.11). For
        ξ >= 1 the motion does not oscillate and |x(t)| itself is returned.

        Parameters
        ----------
        t : array_like
            Times since the start, s, >= 0, any shape (not empty).
        x0 : float
            Initial displacement, m (any sign).
        v0 : float
            Initial velocity, m/s (any sign).

        Returns
        -------
        ndarray
            The envelope, m, same shape as ``t``.

        Examples
        --------
        >>> s = SDOF.from_modal(1.0, 0.0)
        >>> float(s.envelope(3.0, 3.0, 4.0))
        5.0
        """
        x0, v0 = scalar("x0", x0), scalar("v0", v0)
        t = array("t", t, low=0.0, allow_empty=False)
        wd = self.damped_frequency
        if wd == 0.0:
            return np.abs(self.free_response(t, x0, v0))
        sigma = self.damping_ratio * self.natural_frequency
        amplitude = math.hypot(x0, (v0 + sigma * x0) / wd)
        return (amplitude * np.exp(-sigma * t))[()]

    def decay_peaks(self, x0: float, v0: float, count: int = 2) -> DecayPeaks:
        """The first ``count`` maxima of the free response (ξ < 1).

        Successive maxima are one damped period apart and their ratio is
        x₁/x₂ = e^(ξω_n T_d), so ln(x₁/x₂) = δ (eqs. 1.15-1.17, Fig. 1.5). A
        maximum at t = 0 (when v0 = 0 and x0 > 0) is the first one.

        Parameters
        ----------
        x0 : float
            Initial displacement, m (any sign).
        v0 : float
            Initial velocity, m/s (any sign).
        count : int
            Number of maxima, from 1 to 1_000_000 (a bound on the memory asked for).

        Returns
        -------
        DecayPeaks
            Their times (s) and values (m).

        Examples
        --------
        >>> s = SDOF.from_modal(2 * np.pi, 0.1)
        >>> peaks = s.decay_peaks(1.0, 0.0, count=2)
        >>> round(peaks.log_decrement, 6) == round(s.log_decrement, 6)
        True
        """
        count = integer("count", count, low=1, high=_MAX_COUNT)
        x0, v0 = scalar("x0", x0), scalar("v0", v0)
        wd = self.damped_frequency
        if wd == 0.0:
            raise ValueError(
                f"decay_peaks needs an oscillating system (damping ratio < 1), got {self.damping_ratio!r}"
            )
        sigma = self.damping_ratio * self.natural_frequency
        # x = A e^(−σt) cos(ω_d t − φ) has x' = −A ω_n e^(−σt) sin(ω_d t − φ + arcsin ξ);
        # maxima sit where ω_d t − φ + arcsin ξ is a whole number of turns.
        phi = math.atan2((v0 + sigma * x0) / wd, x0)
        offset = (phi - math.asin(self.damping_ratio)) % (2.0 * math.pi)
        if 2.0 * math.pi - offset < 1e-9:  # a peak rounded to just before t = 0 is the one at t = 0
            offset = 0.0
        times = (offset + 2.0 * math.pi * np.arange(count)) / wd
        return DecayPeaks(times, np.asarray(self.free_response(times, x0, v0)))

    def free_vibration(self, t, x0: float, v0: float, *, peaks: int = 2) -> FreeVibration:
        """The free response on a time grid with its decay envelope and first maxima (book Fig. 1.5).

        Parameters
        ----------
        t : array_like, shape (n,)
            Times since the start, s, >= 0, strictly increasing (the abscissa of
            :meth:`~raildyn.vibration.FreeVibration.plot`).
        x0 : float
            Initial displacement, m (any sign).
        v0 : float
            Initial velocity, m/s (any sign).
        peaks : int
            Number of maxima to locate, from 1 to 1_000_000 (none are located when ξ >= 1).

        Returns
        -------
        FreeVibration
            With ``.plot(ax)``.

        Examples
        --------
        >>> s = SDOF.from_modal(2 * np.pi, 0.1)
        >>> r = s.free_vibration(np.linspace(0.0, 3.0, 301), 1.0, 0.0, peaks=3)
        >>> r.peaks.times.round(4).tolist(), round(r.peaks.log_decrement, 4)
        ([0.0, 1.005, 2.0101], 0.6315)
        """
        peaks = integer("peaks", peaks, low=1, high=_MAX_COUNT)
        t = array("t", time_grid("t", t), low=0.0)
        x = np.asarray(self.free_response(t, x0, v0))
        envelope = np.asarray(self.envelope(t, x0, v0))
        if self.damped_frequency > 0.0:
            found = self.decay_peaks(x0, v0, count=peaks)
        else:
            found = DecayPeaks(np.empty(0), np.empty(0))
        return FreeVibration(t, x, envelope, found)

    # -- harmonic response -----------------------------------------------

    def receptance(self, omega):
        """Receptance X/F = 1/(k − mω² + icω), m/N, at circular frequencies ω.

        Complex; its modulus times k is the magnification factor and minus its
        angle the phase lag. Infinite for an undamped system exactly at ω_n.

        Parameters
        ----------
        omega : array_like
            ω, rad/s, >= 0, any shape (not empty).

        Returns
        -------
        complex ndarray
            X/F, m/N, same shape as ``omega``.

        Examples
        --------
        >>> SDOF(1.0, 0.0, 4.0).receptance([0.0, 1.0])
        array([0.25      +0.j, 0.33333333+0.j])
        """
        inv2, den = self._dynamic_stiffness(omega)
        return _reciprocal(inv2, den)[()]

    def base_frf(self, omega):
        """Complex ratio X/Y of mass to base motion, (k + icω)/(k − mω² + icω).

        For ``m x'' + c (x' − y') + k (x − y) = 0``; dimensionless.

        Parameters
        ----------
        omega : array_like
            ω, rad/s, >= 0, any shape (not empty).

        Returns
        -------
        complex ndarray
            X/Y, same shape as ``omega``.
        """
        inv2, den, u, inv = self._dynamic_stiffness(omega, parts=True)
        return _reciprocal(self.stiffness * inv2 + 1j * self.damping * u * inv, den)[()]

    def _dynamic_stiffness(self, omega, *, parts=False):
        """1/s² and (k − mω² + icω)/s² for the checked ``omega``, with s = max(ω, 1 rad/s).

        Dividing through by s² keeps every term finite for any finite ω (1e300 included); for
        ω <= 1 rad/s nothing changes. With ``parts`` also u = ω/s and 1/s.
        """
        w = array("omega", omega, low=0.0, allow_empty=False)
        inv = 1.0 / np.maximum(w, 1.0)
        u = w * inv
        inv2 = inv * inv
        den = self.stiffness * inv2 - self.mass * u * u + 1j * self.damping * u * inv
        return (inv2, den, u, inv) if parts else (inv2, den)

    def transmissibility(self, omega):
        """Displacement transmissibility |X/Y| = |1 + 2iξr| / |1 − r² + 2iξr|, r = ω/ω_n.

        Parameters
        ----------
        omega : array_like
            ω, rad/s, >= 0, any shape (not empty).

        Returns
        -------
        ndarray
            |X/Y|, dimensionless, same shape as ``omega``.

        Examples
        --------
        >>> s = SDOF.from_modal(1.0, 0.3)
        >>> round(float(s.transmissibility(np.sqrt(2.0))), 12)
        1.0
        """
        return np.abs(self.base_frf(omega))[()]

    # -- response to a sampled force -------------------------------------

    def _foh_matrices(self, h: float) -> tuple[np.ndarray, np.ndarray]:
        """Exact one-step matrices for a force linear over the step h (first-order hold).

        The exponential of the augmented matrix [[A, B, 0], [0, 0, 1], [0, 0, 0]] h
        carries the state and a ramp input together (the triangle-hold
        equivalent of Franklin, Powell & Workman, *Digital Control of Dynamic
        Systems*, 3rd ed., 1998, ch. 6).
        With z = [x, x'], the step is z₊ = Φ z + P F + Q F₊; returns (P, Q).
        """
        matrices = self.state_space()
        a, b = matrices.A, matrices.B
        aug = np.zeros((4, 4))
        aug[:2, :2], aug[:2, 2:3], aug[2, 3] = a, b, 1.0
        e = scipy.linalg.expm(aug * h)
        q = e[:2, 3] / h
        return e[:2, 2] - q, q

    def forced_response(self, t, force, x0: float = 0.0, v0: float = 0.0) -> np.ndarray:
        """Displacement x(t), m, under a force sampled at t, from x(t[0]) = x0, x'(t[0]) = v0.

        The force is taken as piecewise linear between samples (first-order
        hold), and the response to that input is exact: the free part is the
        closed form of :meth:`free_response`, and the forced part is the
        discrete convolution of the samples with the exact one-step kernel,
        evaluated by FFT (so 10⁵ samples take milliseconds).

        Parameters
        ----------
        t : array_like, shape (n,)
            Uniformly spaced, strictly increasing times, s, with a step h such that
            ω_n h <= 1e12 rad (beyond, the rounding of h alone moves the phase of a step).
        force : array_like, shape (n,)
            F(t) in N at the times ``t``.
        x0, v0 : float
            Initial displacement (m) and velocity (m/s) at t[0], any sign.

        Returns
        -------
        ndarray, shape (n,)
            x(t), m.

        See Also
        --------
        duhamel_response : the same response by the rectangle rule, to compare with.

        Examples
        --------
        >>> s = SDOF.from_modal(2.0, 0.5, mass=1.0)
        >>> t = np.linspace(0.0, 20.0, 2001)
        >>> round(float(s.forced_response(t, np.full(t.size, 4.0))[-1]), 6)  # settles at F/k = 1
        1.0
        """
        t = time_grid("t", t, uniform=True)
        f = array("force", force, shape=t.shape)
        x0, v0 = scalar("x0", x0), scalar("v0", v0)
        n = t.size
        if n == 1:
            return np.array([x0])
        h = (t[-1] - t[0]) / (n - 1)
        if self.natural_frequency * h > _MAX_PHASE:
            raise ValueError(
                f"t must have a step h with omega_n h <= {_MAX_PHASE:g} rad; h = {h:.4g} s with omega_n = "
                f"{self.natural_frequency:.4g} rad/s gives {self.natural_frequency * h:.4g}"
            )
        tau = np.arange(n) * h
        p, q = self._foh_matrices(h)
        # With w = z − Q F the step becomes w₊ = Φ w + (Φ Q + P) F and x = [1 0] w + Q₀ F: a plain
        # discrete system whose free part is the closed-form free response from w(0) = z(0) − Q F(0),
        # and whose impulse response (the convolution kernel) is Q₀ at k = 0, then the free response
        # from the state ΦQ + P = e^(Ah)Q + P at τ = (k − 1)h.
        gamma = p + np.array([self.free_response(h, q[0], q[1]), self.free_velocity(h, q[0], q[1])])
        kernel = np.empty(n)
        kernel[0] = q[0]
        kernel[1:] = self.free_response(tau[:-1], gamma[0], gamma[1])
        free = self.free_response(tau, x0 - q[0] * f[0], v0 - q[1] * f[0])
        return free + scipy.signal.fftconvolve(f, kernel)[:n]

    def duhamel_response(self, t, force) -> np.ndarray:
        """Response from rest to a sampled force by Duhamel's integral, summed by the rectangle rule.

        x(t_k) ≈ Δt Σ_{j<=k} h(t_k − t_j) F(t_j), with h the unit-impulse response
        (:meth:`impulse_response`): the convolution x = ∫₀ᵗ h(t − τ) F(τ) dτ of the
        book's chapter 1 evaluated the plain way. It converges to the exact
        :meth:`forced_response` as Δt → 0: at first order in Δt, at second when
        F(t₀) = 0 (the term the rectangle rule counts whole at τ = t₀ then vanishes).

        Parameters
        ----------
        t : array_like, shape (n,)
            Uniformly spaced, strictly increasing times, s; the system is at rest at t[0].
        force : array_like, shape (n,)
            F(t), N.

        Returns
        -------
        ndarray, shape (n,)
            x(t), m.

        Examples
        --------
        >>> s = SDOF.from_modal(2 * np.pi, 0.2, mass=10.0)
        >>> t = np.linspace(0.0, 2.0, 2001)
        >>> f = np.where(t < 0.2, np.sin(np.pi * t / 0.2), 0.0)
        >>> bool(np.abs(s.duhamel_response(t, f) - s.forced_response(t, f)).max() < 1e-7)
        True
        """
        t = time_grid("t", t, uniform=True)
        f = array("force", force, shape=t.shape)
        if t.size == 1:
            return np.zeros(1)
        h = (t[-1] - t[0]) / (t.size - 1)
        kernel = self.impulse_response(t - t[0])
        return h * scipy.signal.fftconvolve(f, kernel)[: t.size]

    # -- linear-system views ---------------------------------------------

    def state_space(self) -> StateSpaceMatrices:
        """State-space matrices for state [x, x'] (m, m/s), input F (N), output x (m).

        A = [[0, 1], [−k/m, −c/m]], B = [[0], [1/m]], C = [[1, 0]], D = [[0]].

        Returns
        -------
        StateSpaceMatrices
            A (2, 2), B (2, 1), C (1, 2), D (1, 1).

        Examples
        --------
        >>> SDOF(2.0, 0.4, 8.0).state_space().A
        array([[ 0. ,  1. ],
               [-4. , -0.2]])
        """
        from raildyn.vibration.mdof import state_space  # mdof builds on SDOF, so import late

        return state_space([[self.mass]], [[self.damping]], [[self.stiffness]], [[1.0]])

    def to_control(self):
        """The oscillator as a ``control.StateSpace`` (input F in N, output x in m).

        Returns
        -------
        control.StateSpace

        Examples
        --------
        >>> import control
        >>> np.round(control.poles(SDOF.from_modal(2.0, 1.0).to_control()), 6)
        array([-2.+0.j, -2.+0.j])
        """
        from raildyn.vibration.mdof import to_control  # mdof builds on SDOF, so import late

        return to_control([[self.mass]], [[self.damping]], [[self.stiffness]], [[1.0]])


# ---------------------------------------------------------------------------
# SDOF curves as functions of ξ and r


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
