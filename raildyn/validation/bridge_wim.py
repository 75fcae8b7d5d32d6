"""Bridge weigh-in-motion: a train's speed, axle spacings and axle loads from strain records.

:func:`weigh_in_motion` fits the bending-moment influence line of the simply supported span of
chapter 10 to strain records at two or more sections {moses1979}; it returns a
:class:`WeighInMotionFit`, a :class:`~raildyn.validation.fits.ParameterFit` with intervals.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn.bridge import SimplySupportedBeam
from raildyn.validation.fits import ParameterFit, _confidence, _intervals, _record

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.optimize,
# scipy.signal

__all__ = ["WeighInMotionFit", "weigh_in_motion"]


def _moment_influence(span, x, a):
    """Bending moment at x of a simply supported span under a unit force at a, m (0 off the span).

    Statics of the simple beam: a(L − x)/L for a <= x, x(L − a)/L for a >= x.
    """
    m = np.where(a <= x, a * (span - x), x * (span - a)) / span
    return np.where((a >= 0.0) & (a <= span), m, 0.0)


@dataclass(frozen=True, eq=False)
class WeighInMotionFit(ParameterFit):
    """A bridge weigh-in-motion fit: speed, arrival time, axle spacings, axle loads and offsets.

    The parameters (``names``) are ``speed`` (m/s), ``arrival`` (s: the leading axle at
    the entry support), ``spacing_1`` … (m, between consecutive axles, when they were fitted),
    ``load_1`` … (N, leading axle first) and ``offset_1`` … (strain, one per sensor).

    Attributes
    ----------
    given_spacings : ndarray or None
        The spacings held fixed, m, when they were not fitted; else None.
    """

    given_spacings: np.ndarray | None = None

    def __post_init__(self):
        super().__post_init__()
        if self.given_spacings is not None:
            _checks.array("given_spacings", self.given_spacings, ndim=1, low=0.0, low_open=True)

    @property
    def speed(self) -> float:
        """v, m/s."""
        return self.value("speed")

    def _group(self, word) -> np.ndarray:
        return np.array([e for n, e in zip(self.names, self.estimate, strict=True) if n.startswith(word)])

    @property
    def loads(self) -> np.ndarray:
        """Axle loads, N, leading axle first."""
        return self._group("load_")

    @property
    def spacings(self) -> np.ndarray:
        """Spacing of consecutive axles, m (the fitted ones, or those given)."""
        fitted = self._group("spacing_")
        return fitted if self.given_spacings is None else np.asarray(self.given_spacings, dtype=float)


def _wim_design(t, v, t0, offsets_d, beam_span, positions):
    """Influence matrix G (s, n, a): strain per unit (load × scale) of each axle at each sensor."""
    a = v * (t[None, :, None] - t0) - offsets_d[None, None, :]  # axle positions (1, n, a)
    return _moment_influence(beam_span, positions[:, None, None], a)


def _linear_fit(a, y):
    """Least-squares coefficients of a @ coef ≈ y by the normal equations on scaled columns.

    The matrix is tall and narrow (samples × axles and offsets): the normal equations are
    much faster than an SVD here, and scaling the columns keeps them well conditioned;
    a singular system (an axle never on the span during the record) falls back to lstsq.
    """
    norms = np.linalg.norm(a, axis=0)
    norms[norms == 0.0] = 1.0
    an = a / norms
    try:
        coef = np.linalg.solve(an.T @ an, an.T @ y)
    except np.linalg.LinAlgError:
        coef = np.linalg.lstsq(an, y, rcond=None)[0]
    return coef / norms


def _wim_scales(theta, t):
    """Typical changes of speed, arrival and spacings, for least_squares's ``x_scale``."""
    return np.concatenate([[abs(theta[0]) * 1e-3, t[1] - t[0]], np.full(theta.size - 2, 1e-2)])


def _wim_starts(t, eps, pos, span, d, speed, keep=3):
    """(speed, arrival) pairs to start the weigh-in-motion fit from, best first.

    For each trial speed (the one given, or 160 from 1 to 150 m/s, 3.2 % apart: the nearest
    is within 1.6 % of the truth, which lines every axle up within half an influence line
    for a train up to about 30 spans long; give ``speed`` for a longer one) the template of
    equal axle loads is cross-correlated with the records, which scores every arrival at once.
    """
    from scipy import signal

    dt = t[1] - t[0]
    y = eps - np.median(eps, axis=1, keepdims=True)
    speeds = np.array([speed]) if speed is not None else np.geomspace(1.0, 150.0, 160)
    scored = []
    for v in speeds:
        tau = np.arange(0.0, (span + d[-1]) / v + dt, dt)
        if tau.size > 4 * t.size:  # a passage much longer than the record: too slow to be this train
            continue
        g = _moment_influence(span, pos[:, None, None], v * tau[None, :, None] - d[None, None, :]).sum(axis=2)
        norm = np.linalg.norm(g)
        if norm == 0.0:
            continue
        corr = sum(signal.correlate(y[i], g[i], mode="full") for i in range(pos.size)) / norm
        lags = signal.correlation_lags(t.size, tau.size, mode="full")
        k = int(np.argmax(corr))
        scored.append((corr[k], float(v), float(t[0] + lags[k] * dt)))
    if not scored:
        raise ValueError("strain: no trial speed gives a passage that fits the record; give speed")
    scored.sort(reverse=True)
    return [(v, t0) for _, v, t0 in scored[:keep]]


def weigh_in_motion(
    beam: SimplySupportedBeam,
    time,
    strain,
    positions,
    spacings,
    *,
    fibre_distance: float = 1.0,
    speed: float | None = None,
    fit_spacings: bool = True,
    confidence: float = 0.95,
) -> WeighInMotionFit:
    """Train speed, axle spacings and axle loads from bridge strain records (bridge weigh-in-motion).

    Moses's algorithm {moses1979}: the strain at a sensor at x on a simply supported span is
    the sum over the axles of load × the bending-moment influence line at x, times z_g/EI
    (z_g the sensor's distance from the neutral axis),

    .. math:: \\varepsilon_g(t) = \\frac{z_g}{EI} \\sum_k P_k\\, \\Lambda\\big(x, V (t - t_0) - d_k\\big)
              + \\varepsilon_{0,g},

    with d_k the distance of axle k behind the leading one, Λ(x, x_P) the moment at x under a unit
    force at x_P (statics of the simple beam, the static limit of chapter 10's
    :func:`raildyn.bridge.beam.moving_force_response`; notebook 11 derives it) and ε₀ a zero offset per
    sensor. Given V, t₀ and the spacings, the loads and offsets are linear: they come by linear
    least squares, as in Moses's algorithm. The speed, arrival and (with ``fit_spacings``) the
    spacings are found by nonlinear least squares over that projected problem (variable projection
    {golub1973}), started from the best of a grid of speeds (or ``speed``), each scored at every
    arrival at once by cross-correlating the records with the template of equal loads; a last
    joint fit of every parameter gives the Jacobian for the intervals. Dynamics (the bridge's and
    the vehicle's) are outside the model and end up in the residual; so does any departure of the
    real influence line from the simple span's (continuity, load spreading), which a measured
    influence line removes {obrien2006}.

    Parameters
    ----------
    beam : SimplySupportedBeam
        The span (L, m) and its flexural rigidity (EI, N·m²).
    time : array_like, (n,)
        t, s: uniformly spaced and increasing.
    strain : array_like, (s, n) or (n,)
        Strain at each sensor (dimensionless), one row per sensor; the zero offset may remain.
    positions : array_like, (s,)
        x of each sensor from the support the train enters by, m, each inside (0, L).
    spacings : array_like, (a − 1,)
        Distances between consecutive axles, m, each in (0, 1000]: the values when ``fit_spacings`` is
        False, the start otherwise (its length sets the number of axles, a − 1 >= 0).
    fibre_distance : float
        c, m, in [0.01, 100]: the distance from the neutral axis to the gauge; loads scale as EI/c, so
        with an unknown section c = 1 gives loads in units of EI/c (calibrate them by a known
        train).
    speed : float, optional
        Start for v, m/s, in (0, 200]; None: the best of 160 trial speeds from 1 to 150 m/s.
    fit_spacings : bool
        Whether to identify the spacings (True) or hold them at ``spacings``.
    confidence : float
        Level of the intervals, in (0, 1); default 0.95.

    Returns
    -------
    WeighInMotionFit

    Examples
    --------
    Two axles of 100 kN, 3 m apart, at 20 m/s over a 10 m span, seen by gauges at 4 m and 6 m
    with c = 0.1 m:

    >>> import numpy as np
    >>> beam = SimplySupportedBeam(10.0, 1.0e9, 1.0e4)
    >>> t = np.arange(0.0, 2.0, 1.0 / 512)
    >>> x = np.array([[4.0], [6.0]])
    >>> def strain(a):  # c/EI × P × the moment at x under a unit force at a
    ...     m = np.where(a <= x, a * (10.0 - x), x * (10.0 - a)) / 10.0
    ...     return 0.1 / 1.0e9 * 1.0e5 * np.where((a >= 0.0) & (a <= 10.0), m, 0.0)
    >>> eps = strain(20.0 * (t - 0.2)) + strain(20.0 * (t - 0.2) - 3.0)
    >>> fit = weigh_in_motion(beam, t, eps, x[:, 0], [2.8], fibre_distance=0.1)
    >>> round(fit.speed, 6), np.round(fit.spacings, 6), np.round(fit.loads / 1.0e5, 6)
    (20.0, array([3.]), array([1., 1.]))
    """
    from scipy import optimize

    _checks.instance("beam", beam, SimplySupportedBeam)
    pos = _checks.array("positions", positions, ndim=1, allow_empty=False)
    if np.any(pos <= 0.0) or np.any(pos >= beam.span):
        raise ValueError(
            f"positions must lie within (0, {beam.span}) m, inside the span (a gauge at a support "
            f"feels no moment), got {pos}"
        )
    t, eps = _record(time, strain, name="strain", rows=pos.size)
    if np.any(np.ptp(eps, axis=1) == 0.0):
        raise ValueError("strain must vary at every sensor: a constant record holds no passage")
    gaps = _checks.array("spacings", spacings, ndim=1, low=0.0, low_open=True)
    if gaps.size and gaps.max() > 1000.0:
        raise ValueError(f"spacings must be at most 1000 m each, got {gaps.max()!r}")
    c = _checks.scalar("fibre_distance", fibre_distance, low=0.01, high=100.0)
    fit_gaps = _checks.flag("fit_spacings", fit_spacings)
    level = _confidence(confidence)
    if speed is not None:
        speed = _checks.speed("speed", speed)
    n_axles, n_sens = gaps.size + 1, pos.size
    scale = c / beam.flexural_rigidity
    L = beam.span
    # unknowns: the offsets as one column each
    offset_cols = np.zeros((n_sens, t.size, n_sens))
    offset_cols[np.arange(n_sens), :, np.arange(n_sens)] = 1.0

    def design(v, t0, gap):
        d = np.concatenate([[0.0], np.cumsum(gap)])
        g = scale * _wim_design(t, v, t0, d, L, pos)  # (s, n, a)
        return np.concatenate([g, offset_cols], axis=2).reshape(n_sens * t.size, n_axles + n_sens)

    y = eps.reshape(-1)

    def projected(theta):
        v, t0 = theta[0], theta[1]
        gap = theta[2:] if fit_gaps else gaps
        a = design(v, t0, gap)
        return a @ _linear_fit(a, y) - y

    # start: the speed and arrival whose template (equal loads at the given spacings) best matches
    # the records, by cross-correlation over every arrival at once; the best few are refined
    d_given = np.concatenate([[0.0], np.cumsum(gaps)])
    candidates = _wim_starts(t, eps, pos, L, d_given, speed)
    best = None
    for v_try, t_try in candidates:  # first with the spacings held: speed and arrival alone
        held = optimize.least_squares(
            lambda th: projected(np.concatenate([th, gaps]) if fit_gaps else th),
            np.array([v_try, t_try]),
            x_scale=_wim_scales(np.array([v_try, t_try]), t),
            method="lm",
        )
        if best is None or held.cost < best.cost:
            best = held
    theta0 = np.concatenate([best.x, gaps]) if fit_gaps else best.x
    xs = _wim_scales(theta0, t)
    outer = optimize.least_squares(projected, theta0, x_scale=xs, method="lm") if fit_gaps else best
    v, t0 = outer.x[0], outer.x[1]
    gap = outer.x[2:] if fit_gaps else gaps
    coef = _linear_fit(design(v, t0, gap), y)
    if v <= 0.0 or (fit_gaps and np.any(gap <= 0.0)):
        raise ValueError(
            "strain: the fit did not converge to a positive speed and spacings (is the record a passage, "
            "with the loads pressing down?); give a start speed"
        )

    # the joint fit of every parameter, from the projected solution: its Jacobian gives the intervals
    n_theta = outer.x.size

    def full(p):
        a = design(p[0], p[1], p[2:n_theta] if fit_gaps else gaps)
        return a @ p[n_theta:] - y

    p0 = np.concatenate([outer.x, coef])
    load_scale = max(np.abs(coef[:n_axles]).max(), 1e-300)
    xs_full = np.concatenate([xs, np.full(n_axles, load_scale * 1e-2), np.full(n_sens, 1e-6)])
    sol = optimize.least_squares(full, p0, x_scale=xs_full, method="lm")
    try:
        se, interval, rms = _intervals(sol, y.size, level)
    except ValueError as err:
        raise ValueError(f"strain: {err}") from None
    names = ["speed", "arrival"]
    if fit_gaps:
        names += [f"spacing_{i + 1}" for i in range(gaps.size)]
    names += [f"load_{i + 1}" for i in range(n_axles)] + [f"offset_{i + 1}" for i in range(n_sens)]
    fitted = (full(sol.x) + y).reshape(eps.shape)
    measured = eps if np.ndim(strain) == 2 else eps[0]
    fitted = fitted if np.ndim(strain) == 2 else fitted[0]
    given = None if fit_gaps else gaps
    return WeighInMotionFit(tuple(names), sol.x, se, interval, level, rms, t, measured, fitted, given)
