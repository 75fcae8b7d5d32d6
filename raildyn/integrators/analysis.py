"""Stability and accuracy of each scheme on the test oscillator x'' + 2ξω x' + ω² x = 0, and on a model.

The amplification matrix A of each scheme and what its eigenvalues give (ρ(A), the period
elongation, the amplitude decay, the stability limits) live in
:mod:`raildyn.integrators.amplification` {Bathe 1996, §9.4.1}; this module re-exports them and
builds on them: :class:`~raildyn.integrators.SchemeAccuracy` (the chart of {Bathe 1996, Figs.
9.2–9.4} for one scheme), a model's largest stable step (:func:`~raildyn.integrators.stable_step`)
and stiffness (:func:`~raildyn.integrators.stiffness_ratio`), and the measured order of accuracy
(:func:`~raildyn.integrators.convergence_study`, which runs the schemes). The period of the test
oscillator is T = 1 s, so ω = 2π rad/s and Δt = Δt/T.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks, plots
from raildyn._checks import array, integer, scalar, square_matrix
from raildyn._tables import Tabular
from raildyn.integrators._common import FIRST_ORDER, METHODS, PARAMETERS, draw_line, highest_frequency
from raildyn.integrators.amplification import (
    MAX_DT_OVER_T,  # noqa: F401  (its old home: importable from here for one more issue)
    MIN_DT_OVER_T,  # noqa: F401
    _parameters,
    _principal_elongation,
    _ratios,
    amplification_matrix,
    amplitude_decay,
    first_order_step_limit,
    period_elongation,
    spectral_radius,
    stability_limit,
)
from raildyn.integrators.schemes import integrate
from raildyn.vibration import SDOF, first_order_matrix

# Imported where used, to keep this module's import cheap (tests/test_imports.py): matplotlib

__all__ = [
    "METHODS",
    "PARAMETERS",
    "ConvergenceStudy",
    "SchemeAccuracy",
    "amplification_matrix",
    "amplitude_decay",
    "convergence_study",
    "first_order_step_limit",
    "period_elongation",
    "scheme_accuracy",
    "spectral_radius",
    "stability_limit",
    "stable_step",
    "stiffness_ratio",
]


# ---------------------------------------------------------------------------
# A model's step limit and stiffness


def stable_step(method: str, M, C, K, **params) -> float:
    """The largest stable time step of ``method`` on the model ``M x'' + C x' + K x = 0``, s.

    For the schemes on (x, v, a) and the multistep displacement schemes the limit is
    :func:`stability_limit` times T_min = 2π/ω_max, the period of the highest undamped
    mode (viscous damping does not lower the central difference limit). For the
    first-order schemes (forward Euler, RK4, ABM) it is set by the eigenvalues of
    the first-order system (:func:`raildyn.vibration.first_order_matrix`), so that a
    heavily damped mode, such as a creep time constant, can bind first
    (:func:`first_order_step_limit`).

    Parameters
    ----------
    method : str
        One of ``METHODS``.
    M, C, K : array_like, shape (n, n), or float
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative.
    **params
        The scheme's parameters (see :func:`amplification_matrix`).

    Returns
    -------
    float
        Δt_max, s: inf if no step is too long, 0 if none is stable.

    Examples
    --------
    >>> round(stable_step("central_difference", 1.0, 0.0, 1.0e6), 9)  # 2/ω_max, ω_max = 1000 rad/s
    0.002
    >>> round(stable_step("rk4", 1.0, 2000.0, 1.0) * 1e3, 4)  # the creep-like mode s = −2000 1/s binds
    1.3926
    """
    chosen = _parameters(method, params)
    M = square_matrix("M", M, positive_definite=True)
    C = square_matrix("C", C, size=M.shape[0], symmetric=False)
    K = square_matrix("K", K, size=M.shape[0], symmetric=False)
    if method in FIRST_ORDER:
        lam = np.linalg.eigvals(first_order_matrix(M, C, K))
        return float(min((first_order_step_limit(method, z) for z in lam if z != 0), default=np.inf))
    ratio = stability_limit(method, **chosen)
    wmax = highest_frequency(M, K)
    if np.isinf(ratio) or wmax == 0.0:
        return np.inf
    return float(ratio * 2 * np.pi / wmax)


def stiffness_ratio(M, C, K) -> float:
    """|s|max / |s|min over the eigenvalues s of the first-order system: how stiff the equations are.

    A ratio of thousands means motions on very different time scales: an explicit
    scheme must follow the fastest, an implicit one may step over it {Hairer & Wanner 1996}.

    Parameters
    ----------
    M, C, K : array_like, shape (n, n), or float
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative.

    Returns
    -------
    float
        The ratio (dimensionless).

    Raises
    ------
    ValueError
        If K is singular (a rigid-body mode, s = 0: the ratio is unbounded), or M, C and K
        span time scales beyond double precision.

    Examples
    --------
    >>> round(stiffness_ratio(1.0, 1001.0, 1000.0), 6)  # s = −1 and −1000 1/s
    1000.0
    """
    M = square_matrix("M", M, positive_definite=True)
    C = square_matrix("C", C, size=M.shape[0], symmetric=False)
    K = square_matrix("K", K, size=M.shape[0], symmetric=False)
    size = np.abs(np.linalg.eigvals(first_order_matrix(M, C, K)))
    if size.min() == 0.0:
        raise ValueError(
            "the first-order system has an eigenvalue s = 0, so the stiffness ratio is unbounded: K is "
            "singular (a rigid-body mode), or M, C and K span time scales beyond double precision"
        )
    with np.errstate(over="ignore"):
        ratio = float(size.max() / size.min())
    if not np.isfinite(ratio):
        raise ValueError(
            f"M, C and K span time scales beyond double precision: |s| from {size.min():.3g} to "
            f"{size.max():.3g} 1/s"
        )
    return ratio


# ---------------------------------------------------------------------------
# The accuracy chart of a scheme, as one result with its drawings

# ρ above this is not drawn (the charts stop at ρ = 1.6); amplitude decays are drawn within ±1000 %.
_RHO_SHOWN = 2.0
_AD_SHOWN = 1.0e3


@dataclass(frozen=True)
class SchemeAccuracy(Tabular):
    """Spectral radius, period elongation and amplitude decay of one scheme against Δt/T.

    Attributes
    ----------
    method : str
        The scheme, one of ``METHODS``.
    parameters : dict
        Its parameters, defaults filled in.
    damping_ratio : float
        ξ of the test oscillator.
    dt_over_T : ndarray, shape (k,)
        Steps over the undamped period.
    spectral_radius : ndarray, shape (k,)
        ρ(A), dimensionless.
    period_elongation_fraction : ndarray, shape (k,)
        (T̄ − T_d)/T_d as a fraction (NaN where the computed motion does not oscillate).
    amplitude_decay_fraction : ndarray, shape (k,)
        Amplitude lost per period beyond the physical decay, as a fraction.
    stability_limit_dt_over_T : float
        Largest stable Δt/T (inf: unconditionally stable; 0: never stable).

    The values are checked: shaped (k,) alike and finite, ρ >= 0, with NaN only where the
    period elongation is documented to hold it and an infinite limit only for an
    unconditionally stable scheme.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (
        ("dt_over_T", "-"), ("spectral_radius", "-"), ("period_elongation_fraction", "-"),
        ("amplitude_decay_fraction", "-"),
    )  # fmt: skip
    _scalars = (("damping_ratio", "-"), ("stability_limit_dt_over_T", "-"))

    method: str
    parameters: dict
    damping_ratio: float
    dt_over_T: np.ndarray
    spectral_radius: np.ndarray
    period_elongation_fraction: np.ndarray
    amplitude_decay_fraction: np.ndarray
    stability_limit_dt_over_T: float

    def __post_init__(self):
        _checks.choice("method", self.method, METHODS)
        _checks.instance("parameters", self.parameters, dict, "dict")
        scalar("damping_ratio", self.damping_ratio, low=0.0, high=1.0, high_open=True)
        k = _ratios(self.dt_over_T).size
        for name, low in (("spectral_radius", 0.0), ("amplitude_decay_fraction", None)):
            values = array(name, getattr(self, name), ndim=1, low=low)
            if values.size != k:
                raise ValueError(f"{name} must have shape ({k},) like dt_over_T, got shape {values.shape}")
        chosen = _parameters(self.method, self.parameters)
        pe = _checks._numbers("period_elongation_fraction", self.period_elongation_fraction)
        if pe.shape != (k,) or np.isinf(pe).any():
            raise ValueError(
                f"period_elongation_fraction must have shape ({k},) like dt_over_T and hold finite values "
                f"(or NaN where the motion does not oscillate), got {pe!r:.80}"
            )
        # NaN is documented where the computed motion does not oscillate, and only there.
        expected = np.isnan(_principal_elongation(self.method, self.dt_over_T, self.damping_ratio, chosen))
        if np.any(np.isnan(pe) != expected):
            raise ValueError(
                f"period_elongation_fraction may be NaN only where the computed motion of {self.method} does "
                f"not oscillate; got NaN at {np.isnan(pe).sum()} steps, expected at {expected.sum()}"
            )
        limit = _checks._numbers("stability_limit_dt_over_T", self.stability_limit_dt_over_T)
        if limit.ndim or not limit >= 0:
            raise ValueError(
                f"stability_limit_dt_over_T must be a number >= 0 (inf: unconditionally stable), "
                f"got {self.stability_limit_dt_over_T!r}"
            )
        if np.isinf(limit) and np.isfinite(stability_limit(self.method, self.damping_ratio, **chosen)):
            raise ValueError(
                f"stability_limit_dt_over_T may be inf only for an unconditionally stable scheme, "
                f"and {self.method} is not"
            )

    def _draw(self, ax, artists, y, ylabel, style) -> dict:
        import matplotlib

        if artists is not None:
            _checks.instance("artists", artists, dict, "dict of an earlier call's artists")
            if "line" not in artists:
                raise ValueError(
                    f"artists must be the dict an earlier call returned, with 'line', got {artists!r}"
                )
            artists["line"].set_data(self.dt_over_T, y)
            return artists
        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            (line,) = draw_line(ax, self.dt_over_T, y, style)
            ax.set_xlabel(r"$\Delta t/T$")
            ax.set_ylabel(ylabel)
        return {"line": line}

    def plot_spectral_radius(self, ax=None, *, artists=None, **style) -> dict:
        """Draw ρ(A) against Δt/T (values above 2 left out); return the artists.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw (new axes on a new figure if None). Set a log scale on it for a
            wide range of steps.
        artists : dict, optional
            The artists of an earlier call: their data are replaced in place (a widget's
            update) and nothing new is drawn.
        **style
            Passed to ``Axes.plot`` (``label``, ``color``...).

        Returns
        -------
        dict
            ``{"line": Line2D}``.
        """
        y = np.where(self.spectral_radius < _RHO_SHOWN, self.spectral_radius, np.nan)
        return self._draw(ax, artists, y, r"spectral radius $\rho(A)$", style)

    def plot_period_elongation(self, ax=None, *, artists=None, **style) -> dict:
        """Draw the period elongation in % against Δt/T; return the artists.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw (new axes on a new figure if None).
        artists : dict, optional
            The artists of an earlier call, updated in place.
        **style
            Passed to ``Axes.plot``.

        Returns
        -------
        dict
            ``{"line": Line2D}``.
        """
        return self._draw(ax, artists, 100 * self.period_elongation_fraction, "period elongation (%)", style)

    def plot_amplitude_decay(self, ax=None, *, artists=None, **style) -> dict:
        """Draw the amplitude decay per period in % against Δt/T (within ±1000 %); return the artists.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw (new axes on a new figure if None).
        artists : dict, optional
            The artists of an earlier call, updated in place.
        **style
            Passed to ``Axes.plot``.

        Returns
        -------
        dict
            ``{"line": Line2D}``.
        """
        y = np.clip(100 * self.amplitude_decay_fraction, -_AD_SHOWN, _AD_SHOWN)
        return self._draw(ax, artists, y, "amplitude decay per period (%)", style)


def scheme_accuracy(method: str, dt_over_T, damping_ratio: float = 0.0, **params) -> SchemeAccuracy:
    """The accuracy chart of a scheme on the test oscillator: ρ, period elongation and amplitude decay.

    Bathe's Figs. 9.2–9.3 {Bathe 1996} for one scheme, from its amplification matrix
    (:func:`spectral_radius`, :func:`period_elongation`, :func:`amplitude_decay`,
    :func:`stability_limit`).

    Parameters
    ----------
    method : str
        One of ``METHODS``.
    dt_over_T : array_like, shape (k,)
        Steps over the undamped natural period, in [1e-4, 1e6], at least one.
    damping_ratio : float
        ξ of the oscillator, in [0, 1).
    **params
        The scheme's parameters (see :func:`amplification_matrix`).

    Returns
    -------
    SchemeAccuracy

    Examples
    --------
    >>> chart = scheme_accuracy("central_difference", [0.1, 0.3, 0.4])
    >>> chart.spectral_radius.round(6).tolist(), round(chart.stability_limit_dt_over_T * np.pi, 9)
    ([1.0, 1.0, 4.070901], 1.0)
    """
    chosen = _parameters(method, params)
    xi = scalar("damping_ratio", damping_ratio, low=0.0, high=1.0, high_open=True)
    ratios = _ratios(dt_over_T)
    return SchemeAccuracy(
        method,
        chosen,
        xi,
        ratios,
        np.atleast_1d(spectral_radius(method, ratios, xi, **chosen)),
        np.atleast_1d(period_elongation(method, ratios, xi, **chosen)),
        np.atleast_1d(amplitude_decay(method, ratios, xi, **chosen)),
        stability_limit(method, xi, **chosen),
    )


# ---------------------------------------------------------------------------
# Order of convergence, measured on the damped oscillator under a constant force

_STUDY_PERIOD = 1.0  # s: T of the oscillator
_STUDY_DAMPING = 0.05  # ξ
_STUDY_FORCE = 10.0  # N on the 1 kg mass
_STUDY_START = (1.0, 2.0)  # x0 (m), v0 (m/s)
# The longest study: after 100 s (100 periods at ξ = 0.05) the free motion has decayed by e^-31,
# leaving the static deflection every scheme reproduces, so a longer run measures nothing more.
_STUDY_MAX_DURATION = 100.0
# The most steps a run may take: far beyond where rounding, not the scheme, sets the error.
_STUDY_MAX_STEPS = 100_000


@dataclass(frozen=True)
class ConvergenceStudy(Tabular):
    """The error of a scheme at several steps on a problem with an exact answer, and the order it shows.

    Attributes
    ----------
    method : str
        The scheme.
    parameters : dict
        Its parameters, defaults filled in.
    step_counts : ndarray of int, shape (k,)
        Steps over the run.
    dt_over_T : ndarray, shape (k,)
        The steps over the oscillator's period.
    max_error_m : ndarray, shape (k,)
        Largest |x − x_exact| over the run, m.
    orders : ndarray, shape (k − 1,)
        log₂ of successive error ratios over log₂ of the step ratios: the measured order.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units;
    # ``orders`` (one fewer, between successive steps) is no column.
    _columns = (("step_counts", "-"), ("dt_over_T", "-"), ("max_error_m", "m"))

    method: str
    parameters: dict
    step_counts: np.ndarray
    dt_over_T: np.ndarray
    max_error_m: np.ndarray
    orders: np.ndarray

    def __post_init__(self):
        _checks.choice("method", self.method, METHODS)
        _checks.instance("parameters", self.parameters, dict, "dict")
        counts = self.step_counts
        if not (isinstance(counts, np.ndarray) and counts.dtype.kind in "iu"):
            raise TypeError(f"step_counts must be an array of integers, got {counts!r:.80}")
        counts = array("step_counts", counts, ndim=1, low=4)
        if counts.size < 2 or np.any(np.diff(counts) <= 0):
            raise ValueError(f"step_counts must hold at least two increasing counts, got {counts!r}")
        k = counts.size
        for name, size, low in (("dt_over_T", k, 0.0), ("max_error_m", k, 0.0), ("orders", k - 1, None)):
            values = array(name, getattr(self, name), ndim=1, low=low, low_open=name == "dt_over_T")
            if values.size != size:
                raise ValueError(
                    f"{name} must have {size} entries (from step_counts), got shape {values.shape}"
                )


def convergence_study(
    method: str, step_counts=(200, 400, 800), duration: float = 2.0, **params
) -> ConvergenceStudy:
    """Measure a scheme's order of accuracy against the exact response of a damped oscillator.

    The oscillator has m = 1 kg, T = 1 s and ξ = 0.05, starts from x₀ = 1 m,
    v₀ = 2 m/s and carries a constant 10 N force, which every scheme samples exactly,
    so the error against :meth:`raildyn.vibration.SDOF.forced_response` (exact for
    it) is the scheme's alone. A scheme of order p has a global error ∝ Δt^p, so
    the measured order is log(e₁/e₂)/log(Δt₁/Δt₂).

    Parameters
    ----------
    method : str
        One of ``METHODS``.
    step_counts : sequence of int
        Steps over the run, at least two, each in [4, 100000] (beyond, rounding rather than
        the scheme sets the error), in increasing order.
    duration : float
        Length of the run, s, in [0.01, 100] (after 100 periods the free motion has decayed by
        e^-31, leaving the static deflection every scheme reproduces).
    **params
        The scheme's parameters (see :func:`amplification_matrix`).

    Returns
    -------
    ConvergenceStudy

    Raises
    ------
    raildyn.errors.SolverError
        If a run blows up (a step beyond the scheme's stability limit).

    Examples
    --------
    >>> study = convergence_study("rk4", (400, 800))
    >>> round(float(study.orders[0]), 1)
    4.0
    """
    chosen = _parameters(method, params)
    if isinstance(step_counts, str) or not np.iterable(step_counts):
        raise TypeError(f"step_counts must be a sequence of integers, got {step_counts!r:.80}")
    counts = [integer("step_counts", k, low=4, high=_STUDY_MAX_STEPS) for k in step_counts]
    if len(counts) < 2 or any(b <= a for a, b in zip(counts, counts[1:], strict=False)):
        raise ValueError(f"step_counts must hold at least two increasing counts, got {step_counts!r}")
    duration = scalar("duration", duration, low=0.01, high=_STUDY_MAX_DURATION)
    system = SDOF.from_modal(2 * np.pi / _STUDY_PERIOD, _STUDY_DAMPING)
    x0, v0 = _STUDY_START
    errors = []
    for steps in counts:
        t = np.linspace(0.0, duration, steps + 1)
        load = np.full(t.size, _STUDY_FORCE)
        exact = system.forced_response(t, load, x0=x0, v0=v0)
        force = (lambda tk, x, v: np.array([_STUDY_FORCE])) if method in FIRST_ORDER else load
        run = integrate(method, system.mass, system.damping, system.stiffness, t, x0, v0, force, **chosen)
        errors.append(np.abs(run.x[0] - exact).max())
    errors = np.array(errors)
    steps = np.array(counts)
    orders = np.log(errors[:-1] / errors[1:]) / np.log(steps[1:] / steps[:-1])
    return ConvergenceStudy(method, chosen, steps, duration / steps / _STUDY_PERIOD, errors, orders)
