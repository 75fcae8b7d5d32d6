"""The single-degree-of-freedom oscillator m x'' + c x' + k x = F(t) (book eq. 1.3).

Free response in every damping regime, the characteristic roots, the logarithmic decrement
(eq. 1.17), harmonic and base-excited response, and the exact response to a sampled force, as the
methods of one class, :class:`SDOF`. SI units: m, kg, s, N, rad/s.

Its results (:class:`DecayPeaks`, :class:`FreeVibration`, :class:`RootLocus`) are in
:mod:`raildyn.vibration.sdof_results`; the curves as functions of ξ and r (root locus, decrement,
magnification, phase, transmissibility) in :mod:`raildyn.vibration.sdof_curves`.

Why this module is longer than 600 lines: it is the one class :class:`SDOF` and the closed form
its free response is built on; a reader looking up what an oscillator can answer finds every
method here, and splitting the class across files would hide half of them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.linalg

from raildyn import _deprecated
from raildyn._checks import array, integer, nonnegative, positive, scalar, time_grid
from raildyn.vibration._domain import (
    _MAX_COUNT,
    _MAX_PHASE,
    _RATE,
    _causal_convolution,
    _check_rates,
    _one_minus_square,
    _reciprocal,
    _roots,
)
from raildyn.vibration.damped import StateSpaceMatrices, state_space_matrices, to_control
from raildyn.vibration.sdof_curves import (  # noqa: F401  (all but log_decrement: re-exports, see below)
    RootLocus,
    damping_ratio_from_decrement,
    decrement_from_peaks,
    log_decrement,
    magnification_factor,
    phase_angle,
    root_locus,
    transmissibility_ratio,
)
from raildyn.vibration.sdof_results import DecayPeaks, FreeVibration

# The results and curves above moved to raildyn.vibration.sdof_results and
# raildyn.vibration.sdof_curves (issue 33); the ones this module does not use are imported only so
# that the old paths (raildyn.vibration.sdof.X) keep working for one issue, then they go.

__all__ = ["SDOF"]

# |ξ − 1| at or below this counts as critical damping in SDOF.regime.
CRITICAL_TOLERANCE = 1e-9


# ---------------------------------------------------------------------------
# Closed forms shared by the SDOF class and the module-level functions


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
        matrices = self.state_space_matrices()
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
        evaluated by FFT (so 10⁵ samples take milliseconds: ``benchmarks/bench_ch01_widgets.py``).

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
        return free + _causal_convolution(f, kernel)

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
        return h * _causal_convolution(f, kernel)

    # -- linear-system views ---------------------------------------------

    def state_space_matrices(self) -> StateSpaceMatrices:
        """State-space matrices for state [x, x'] (m, m/s), input F (N), output x (m).

        A = [[0, 1], [−k/m, −c/m]], B = [[0], [1/m]], C = [[1, 0]], D = [[0]].

        Returns
        -------
        StateSpaceMatrices
            A (2, 2), B (2, 1), C (1, 2), D (1, 1).

        Examples
        --------
        >>> SDOF(2.0, 0.4, 8.0).state_space_matrices().A
        array([[ 0. ,  1. ],
               [-4. , -0.2]])
        """
        return state_space_matrices([[self.mass]], [[self.damping]], [[self.stiffness]], [[1.0]])

    # The method's name before issue 33, kept for one issue (raildyn._deprecated): calling it warns and
    # calls state_space_matrices.
    state_space = _deprecated.renamed_method("state_space_matrices")

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
        return to_control([[self.mass]], [[self.damping]], [[self.stiffness]], [[1.0]])
