"""Parameter identification from test records by least squares, with confidence intervals.

Four identifications a railway dynamics course meets, each a fit of a physical model to a
record with ``scipy.optimize.least_squares``:

* :func:`free_decay` — natural frequency and damping ratio from a free decay (a damped
  sinusoid), beside chapter 1's logarithmic decrement of the same record (book eq. 1.17);
* :func:`bridge_free_vibration` — a bridge's frequency and damping from the free vibration
  left when a train has crossed;
* :func:`weigh_in_motion` — bridge weigh-in-motion: the train's speed, axle spacings and
  axle loads from strain records, through the bending-moment influence line of the
  simply supported span of chapter 10 {moses1979};
* :func:`coast_down` — the Davis coefficients A, B, C from a coast-down record.

Every fit reports its estimates with standard errors and intervals from the Jacobian at
the solution: the covariance s²(JᵀJ)⁻¹, with s² the residual variance over n − p degrees of
freedom, and Student's t quantile at the stated confidence (95 % by default). These are the
usual linearised (asymptotic) intervals of nonlinear regression {seber2003}: they hold when
the noise is independent, of constant variance and small enough for the model to be
close to linear over the interval. Coloured noise (as in a real strain record) makes them
too narrow.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import optimize, signal, stats

from raildyn import _checks
from raildyn.bridge import SimplySupportedBeam
from raildyn.vibration import damping_ratio_from_decrement, decrement_from_peaks

__all__ = [
    "CoastDownFit",
    "FreeDecayFit",
    "ParameterFit",
    "WeighInMotionFit",
    "bridge_free_vibration",
    "coast_down",
    "free_decay",
    "weigh_in_motion",
]


# -- shared pieces ----------------------------------------------------------------------------------------

# The largest magnitude a record may hold: its squares (sums of squares in the fits) stay finite.
_LARGEST = 1e100


def _record(time, values, *, name="response", rows=None) -> tuple[np.ndarray, np.ndarray]:
    """A uniform time grid and a finite record of the same length (1-D, or ``rows`` × n when given)."""
    t = _checks.time_grid("time", time, uniform=True)
    if t.size < 3:
        raise ValueError(f"time must hold at least 3 samples, got {t.size}")
    x = _checks.array(name, values, allow_empty=False)
    if np.abs(x).max() > _LARGEST:
        raise ValueError(
            f"{name} must stay within ±{_LARGEST:g} (its squares must be finite), got {x.max()!r}"
        )
    if rows is None:
        if x.ndim != 1:
            raise ValueError(f"{name} must be a 1-D record, got shape {x.shape}")
        n = x.size
    else:
        x = np.atleast_2d(x)
        if x.ndim != 2 or x.shape[0] != rows:
            raise ValueError(
                f"{name} must have shape ({rows}, n), one row per sensor, got {np.shape(values)}"
            )
        n = x.shape[1]
    if n != t.size:
        raise ValueError(f"{name} must have as many samples as time ({t.size}), got {n}")
    return t, x


def _confidence(confidence) -> float:
    return _checks.scalar("confidence", confidence, low=0.0, high=1.0, low_open=True, high_open=True)


def _intervals(solution, n: int, confidence: float):
    """Standard errors and t-intervals from the Jacobian at a least-squares solution.

    cov = s² (JᵀJ)⁻¹, s² = Σr²/(n − p) {seber2003}; a rank-deficient JᵀJ (a parameter the record
    does not determine) gives an infinite standard error, which the caller refuses.
    """
    jac = np.asarray(solution.jac, dtype=float)
    p = jac.shape[1]
    dof = n - p
    if dof < 1:
        raise ValueError(f"the record must have more samples than the {p} parameters fitted, got {n}")
    s2 = 2.0 * solution.cost / dof
    # scale the columns before inverting: the parameters differ by many orders of magnitude
    norms = np.linalg.norm(jac, axis=0)
    norms[norms == 0.0] = 1.0
    js = jac / norms
    u, sv, vt = np.linalg.svd(js, full_matrices=False)
    if sv.min() <= sv.max() * 1e-12:
        raise ValueError(
            "the record does not determine every parameter (the Jacobian is rank-deficient); "
            "give a longer record, more sensors or fix a parameter"
        )
    cov = (vt.T / sv**2) @ vt / np.outer(norms, norms) * s2
    se = np.sqrt(np.diag(cov))
    half = stats.t.ppf(0.5 + confidence / 2.0, dof) * se
    est = np.asarray(solution.x, dtype=float)
    return se, np.column_stack([est - half, est + half]), math.sqrt(2.0 * solution.cost / n)


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class ParameterFit:
    """A least-squares fit of a model to a record: estimates, standard errors and intervals.

    Attributes
    ----------
    names : tuple of str
        The parameters, in the order of the arrays below.
    estimate : ndarray, (p,)
        The least-squares estimates (units: see the function that made the fit).
    standard_error : ndarray, (p,)
        Their standard errors, from s²(JᵀJ)⁻¹ at the solution.
    interval : ndarray, (p, 2)
        Lower and upper limits of each parameter's interval at ``confidence`` (Student's t
        with n − p degrees of freedom).
    confidence : float
        The confidence level of ``interval``, in (0, 1).
    residual_rms : float
        Root mean square of measured − fitted, in the record's unit.
    time : ndarray, (n,)
        t of the record, s.
    measured : ndarray, (n,) or (s, n)
        The record (one row per sensor where there are several).
    fitted : ndarray, same shape as ``measured``
        The model at the estimates.
    """

    names: tuple
    estimate: np.ndarray
    standard_error: np.ndarray
    interval: np.ndarray
    confidence: float
    residual_rms: float
    time: np.ndarray
    measured: np.ndarray
    fitted: np.ndarray

    def __post_init__(self):
        _checks.fields(self)
        names = _checks.strings("names", self.names, unique=True)
        p = len(names)
        for field, shape in (("estimate", (p,)), ("standard_error", (p,)), ("interval", (p, 2))):
            _checks.array(field, getattr(self, field), shape=shape)
        _checks.array("standard_error", self.standard_error, low=0.0)
        _confidence(self.confidence)
        _checks.nonnegative("residual_rms", self.residual_rms)
        t = _checks.array("time", self.time, ndim=1, allow_empty=False)
        m = _checks.array("measured", self.measured)
        if m.shape[-1] != t.size or m.ndim not in (1, 2):
            raise ValueError(f"measured must have shape (n,) or (s, n) with n = {t.size}, got {m.shape}")
        if np.shape(self.fitted) != m.shape:
            raise ValueError(
                f"fitted must have the shape of measured {m.shape}, got shape {np.shape(self.fitted)}"
            )
        _checks.array("fitted", self.fitted)

    def value(self, name: str) -> float:
        """The estimate of one parameter, by name.

        Parameters
        ----------
        name : str
            One of ``names``.

        Returns
        -------
        float
        """
        return float(self.estimate[self._index(name)])

    def bounds(self, name: str) -> tuple[float, float]:
        """The interval of one parameter at ``confidence``, by name.

        Parameters
        ----------
        name : str
            One of ``names``.

        Returns
        -------
        tuple of float
            (lower, upper).
        """
        lo, hi = self.interval[self._index(name)]
        return float(lo), float(hi)

    def _index(self, name) -> int:
        _checks.choice("name", name, self.names)
        return self.names.index(name)

    def plot(self, ax=None) -> dict:
        """Draw the record and the fitted model against time.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.

        Returns
        -------
        dict
            The artists: ``measured`` and ``fitted``, each a list of lines (one per sensor).
        """
        import matplotlib

        from raildyn import plots

        ax = plots.axes_or_new(ax)
        measured, fitted = np.atleast_2d(self.measured), np.atleast_2d(self.fitted)
        drawn = {"measured": [], "fitted": []}
        with matplotlib.rc_context(plots.STYLE):
            for i, (m, f) in enumerate(zip(measured, fitted, strict=True)):
                color = plots.COLORS[i % len(plots.COLORS)]
                (line,) = ax.plot(self.time, m, color=color, lw=0.6, alpha=0.5, label="measured" * (i == 0))
                drawn["measured"].append(line)
                (line,) = ax.plot(self.time, f, color=color, lw=1.4, label="fitted" * (i == 0))
                drawn["fitted"].append(line)
            ax.set_xlabel("time (s)")
            ax.legend()
        return drawn


# -- free decay ---------------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class FreeDecayFit(ParameterFit):
    """A damped sinusoid fitted to a free decay, beside the logarithmic decrement of its maxima.

    The parameters (``names``) are ``frequency_hz`` (f_n = ω_n/2π, Hz), ``damping_ratio``
    (ξ), ``amplitude`` (A, the record's unit), ``phase`` (φ, rad) and ``offset`` (the record's
    unit) of x(t) = A e^(−ξω_n t) cos(ω_d t + φ) + offset (book eqs. 1.12-1.14).

    Attributes
    ----------
    log_decrement : float or None
        δ from the first and the last clear maxima of the record (book eq. 1.17, by
        :func:`raildyn.vibration.decrement_from_peaks`); None when fewer than two maxima stand
        above the noise.
    decrement_damping_ratio : float or None
        ξ = δ/√(4π² + δ²) from that decrement (:func:`raildyn.vibration.damping_ratio_from_decrement`).
    """

    log_decrement: float | None = None
    decrement_damping_ratio: float | None = None

    @property
    def frequency_hz(self) -> float:
        """f_n, Hz."""
        return self.value("frequency_hz")

    @property
    def damping_ratio(self) -> float:
        """ξ, dimensionless."""
        return self.value("damping_ratio")


def _decay_model(p, t):
    f, xi, a, phase, offset = p
    wn = 2 * np.pi * f
    wd = wn * np.sqrt(max(1.0 - xi * xi, 1e-12))
    return a * np.exp(-xi * wn * t) * np.cos(wd * t + phase) + offset


def _decay_linear(f, xi, t, x):
    """Amplitude, phase and offset that fit best for a given f and ξ (a linear least-squares fit)."""
    wn = 2 * np.pi * f
    wd = wn * math.sqrt(max(1.0 - xi * xi, 1e-12))
    env = np.exp(-xi * wn * t)
    basis = np.column_stack([env * np.cos(wd * t), env * np.sin(wd * t), np.ones_like(t)])
    (c, s, offset), *_ = np.linalg.lstsq(basis, x, rcond=None)
    return math.hypot(c, s), math.atan2(-s, c), offset


def _decrement(t, x, offset, noise, frequency):
    """δ and ξ from the first and the last maxima standing clear of the noise (eq. 1.17), or Nones.

    Maxima are taken at least 0.7 of a period apart (``frequency``, Hz, from the fit), so that
    noise on one crest does not count as a second crest; the periods between the first and
    the last are counted from their time apart.
    """
    y = x - offset
    dt = t[1] - t[0]
    apart = max(int(0.7 / (frequency * dt)), 1)
    peaks, _ = signal.find_peaks(y, height=max(4.0 * noise, 0.0), distance=apart)
    peaks = peaks[y[peaks] > 0.0]
    if peaks.size < 2:
        return None, None
    cycles = int(round((t[peaks[-1]] - t[peaks[0]]) * frequency))
    if cycles < 1 or y[peaks[-1]] >= y[peaks[0]]:
        return None, None
    delta = decrement_from_peaks(float(y[peaks[0]]), float(y[peaks[-1]]), cycles=cycles)
    return float(delta), float(damping_ratio_from_decrement(delta))


def free_decay(time, response, *, confidence: float = 0.95) -> FreeDecayFit:
    """Natural frequency and damping ratio from a free decay, by fitting a damped sinusoid.

    Fits x(t) = A e^(−ξω_n t') cos(ω_d t' + φ) + offset, t' = t − t₀, ω_d = ω_n√(1 − ξ²)
    (book eqs. 1.12-1.14) by nonlinear least squares. The start comes from the record: f from
    the largest peak of its zero-padded spectrum, ξ from the decay of its maxima, A, φ and
    the offset by linear least squares. The result also carries chapter 1's logarithmic
    decrement of the same maxima (eq. 1.17), the classical hand method, for comparison:
    the fit uses every sample, the decrement two maxima, so the fit's ξ is the more precise
    under noise.

    Parameters
    ----------
    time : array_like, (n,)
        t, s: uniformly spaced, increasing, at least 3 samples and more than 5.
    response : array_like, (n,)
        x(t), any unit (displacement, strain, acceleration of one mode): finite.
    confidence : float
        Level of the intervals, in (0, 1); default 0.95.

    Returns
    -------
    FreeDecayFit

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(0.0, 4.0, 0.005)
    >>> x = np.exp(-0.02 * 2 * np.pi * 3.0 * t) * np.cos(2 * np.pi * 3.0 * np.sqrt(1 - 0.02**2) * t)
    >>> fit = free_decay(t, x)
    >>> round(fit.frequency_hz, 6), round(fit.damping_ratio, 6)
    (3.0, 0.02)
    """
    t, x = _record(time, response)
    level = _confidence(confidence)
    if t.size <= 5:
        raise ValueError(f"time must hold more than the 5 parameters fitted, got {t.size} samples")
    tau = t - t[0]
    dt = tau[1]
    if np.ptp(x) == 0.0:
        raise ValueError("response must vary: a constant record has no frequency or damping to identify")
    # start: the spectral peak (zero-padded 8x, the record's mean removed)
    nfft = 8 * (1 << int(np.ceil(np.log2(t.size))))
    spectrum = np.abs(np.fft.rfft(x - x.mean(), nfft))
    freqs = np.fft.rfftfreq(nfft, dt)
    f0 = float(freqs[1 + np.argmax(spectrum[1:])])
    # ξ start: the envelope's decay over the record (log of the largest |x| in each half)
    half = x.size // 2
    a1, a2 = np.abs(x[:half] - x.mean()).max(), np.abs(x[half:] - x.mean()).max()
    xi0 = min(max(math.log(max(a1, 1e-300) / max(a2, 1e-300)) / (2 * np.pi * f0 * tau[half]), 1e-4), 0.5)

    def residual(p):
        return _decay_model(p, tau) - x

    amp, phase, offset = _decay_linear(f0, xi0, tau, x)
    nyquist = 0.5 / dt
    start = np.array([f0, xi0, amp, phase, offset])
    lower = [1e-9 * nyquist, 0.0, 0.0, -np.inf, -np.inf]
    upper = [nyquist, 0.999, np.inf, np.inf, np.inf]
    start = np.clip(start, np.array(lower) + 1e-12, np.array(upper) - 1e-12)
    scale = np.array([f0 * 1e-3, 1e-3, max(amp, 1e-300) * 1e-2, 1e-2, max(amp, 1e-300) * 1e-2])
    sol = optimize.least_squares(residual, start, bounds=(lower, upper), x_scale=scale, method="trf")
    se, interval, rms = _intervals(sol, t.size, level)
    fitted = _decay_model(sol.x, tau)
    delta, xi_d = _decrement(t, x, sol.x[4], rms, sol.x[0] * np.sqrt(1.0 - sol.x[1] ** 2))
    return FreeDecayFit(
        ("frequency_hz", "damping_ratio", "amplitude", "phase", "offset"),
        sol.x,
        se,
        interval,
        level,
        rms,
        t,
        x,
        fitted,
        delta,
        xi_d,
    )


def bridge_free_vibration(time, response, leaves: float, *, confidence: float = 0.95) -> FreeDecayFit:
    """A bridge's fundamental frequency and damping from the free vibration after a train leaves.

    Of the two ways to read them off a record, a damped sinusoid fitted to the free
    vibration, or the peak and half-power bandwidth of the record's spectrum, this
    uses the first: the free vibration after the last axle leaves the span is exactly
    the model (no forcing), and it is not limited by the spectrum's frequency
    resolution 1/T, which for a lightly damped bridge over a few seconds of record is wider
    than the half-power band 2ξf itself, so the half-power estimate of ξ would be biased
    upwards {bendat2010}. It needs a record in which the fundamental dominates after the
    train has left (filter around it first if other modes ring too).

    Parameters
    ----------
    time : array_like, (n,)
        t, s: uniformly spaced and increasing.
    response : array_like, (n,)
        The bridge's deflection, strain or acceleration at one point, any unit; finite.
    leaves : float
        The time the last axle leaves the span, s, inside the record with more than five
        samples after it.
    confidence : float
        Level of the intervals, in (0, 1); default 0.95.

    Returns
    -------
    FreeDecayFit
        Fitted to the samples from ``leaves`` on.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(0.0, 6.0, 0.002)
    >>> free = np.exp(-0.01 * 2 * np.pi * 5.0 * (t - 2.0)) * np.sin(2 * np.pi * 5.0 * (t - 2.0))
    >>> x = np.where(t < 2.0, np.sin(np.pi * t / 2.0), free)
    >>> round(bridge_free_vibration(t, x, 2.0).frequency_hz, 3)
    5.0
    """
    t, x = _record(time, response)
    at = _checks.scalar("leaves", leaves, low=float(t[0]), high=float(t[-1]))
    keep = t >= at
    if keep.sum() <= 5:
        raise ValueError(
            f"leaves must leave more than 5 samples after it, got {leaves!r} ({keep.sum()} after)"
        )
    return free_decay(t[keep], x[keep], confidence=confidence)


# -- bridge weigh-in-motion ---------------------------------------------------------------------------------


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
    :func:`raildyn.bridge.beam.moving_force`; notebook 11 derives it) and ε₀ a zero offset per
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


# -- coast-down: the Davis coefficients ----------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class CoastDownFit(ParameterFit):
    """The Davis coefficients fitted to a coast-down record.

    The parameters (``names``) are ``A`` (N), ``B`` (N·s/m), ``C`` (N·s²/m²) of the
    resistance R(v) = A + Bv + Cv² and ``initial_speed`` (m/s, at the record's first sample).
    """

    def resistance(self, speed) -> np.ndarray:
        """R(v) = A + Bv + Cv² at the fitted coefficients, N.

        Parameters
        ----------
        speed : array_like
            v, m/s (finite, within ±1000 m/s; not empty).

        Returns
        -------
        ndarray
            Shape of ``speed``.
        """
        v = _checks.plausible_array("speed", speed, "speed", signed=True, allow_empty=False)
        a, b, c = self.estimate[:3]
        return a + b * v + c * v**2


def _coast(p, tau, mass):
    """v(t) of m dv/dt = −(A + Bv + Cv²), v(0) = v₀: the Riccati equation's closed form.

    With q = √(4AC − B²) (complex when B² > 4AC): v = (q tan(arctan((2Cv₀ + B)/q) − qt/(2m)) − B)/(2C);
    C = 0 gives the linear equation's exponential (or, with B = 0 too, a straight line).
    """
    a, b, c, v0 = p
    if abs(c) * max(v0, 1.0) ** 2 < 1e-12 * (abs(a) + abs(b) * max(v0, 1.0) + 1e-300):
        if abs(b) * tau[-1] / mass < 1e-12:
            return v0 - a * tau / mass
        return (v0 + a / b) * np.exp(-b * tau / mass) - a / b
    q = np.sqrt(complex(4 * a * c - b * b))
    with np.errstate(all="ignore"):
        v = (q * np.tan(np.arctan((2 * c * v0 + b) / q) - q * tau / (2 * mass)) - b) / (2 * c)
    return v.real


def coast_down(time, speed, mass: float, *, confidence: float = 0.95) -> CoastDownFit:
    """The Davis coefficients A, B, C from a coast-down record, by least squares on the ODE's solution.

    A train coasting on level tangent track slows by its resistance alone,
    m dv/dt = −(A + Bv + Cv²), the Davis form {davis1926} that
    :func:`raildyn.train.resistance.davis_resistance` evaluates from a vehicle's mass, axles
    and frontal area. The fit is to the speed record itself through the equation's closed-form
    solution (a Riccati equation with constant coefficients), with A, B, C and v₀ unknown,
    not to a numerically differentiated record: differencing a noisy speed amplifies the
    noise by about 1/(Δt) and biases a least-squares fit of the derivative (errors in the
    regressor v then correlate with the derivative's). The differentiated record gives only
    the start. The mass should include the rotating masses' equivalent.

    Parameters
    ----------
    time : array_like, (n,)
        t, s: uniformly spaced and increasing, more than 4 samples.
    speed : array_like, (n,)
        v(t), m/s, > 0 (the record must end before the train stops), lower at the end than at the
        start (a coasting train slows down).
    mass : float
        m, kg, in [10, 1e9] (from the lightest vehicle body, PLAUSIBLE_RANGES["mass"], to a million
        tonnes: beyond any train).
    confidence : float
        Level of the intervals, in (0, 1); default 0.95.

    Returns
    -------
    CoastDownFit

    Examples
    --------
    >>> import numpy as np
    >>> t = np.arange(0.0, 600.0, 1.0)
    >>> v = _coast((4000.0, 60.0, 6.0, 40.0), t, 4.0e5)
    >>> np.round(coast_down(t, v, 4.0e5).estimate, 3)
    array([4000.,   60.,    6.,   40.])
    """
    t, v = _record(time, speed, name="speed")
    _checks.plausible_array("speed", v, "speed", low=-np.inf)  # at most MAXIMUM_SPEED (>0 just below)
    if np.any(v <= 0.0):
        raise ValueError(
            f"speed must be > 0 throughout (a coast-down before standstill), got min {v.min()!r}"
        )
    if v[-1] >= v[0]:
        raise ValueError(
            f"speed must fall over the record (a train coasting slows by its resistance), got "
            f"{v[0]!r} m/s at the start and {v[-1]!r} m/s at the end"
        )
    m = _checks.scalar("mass", mass, low=10.0, high=1.0e9)
    level = _confidence(confidence)
    if t.size <= 4:
        raise ValueError(f"time must hold more than the 4 parameters fitted, got {t.size} samples")
    tau = t - t[0]
    # start: a straight regression of −m dv/dt on 1, v, v² (np.gradient of the record)
    dvdt = np.gradient(v, tau)
    basis = np.column_stack([np.ones_like(v), v, v**2])
    abc, *_ = np.linalg.lstsq(basis, -m * dvdt, rcond=None)
    start = np.concatenate([abc, [v[0]]])

    def residual(p):
        return _coast(p, tau, m) - v

    force = max(m * np.abs(v[-1] - v[0]) / max(tau[-1], 1e-300), 1e-300)
    vmax = float(v.max())
    xs = np.array([force, force / vmax, force / vmax**2, vmax * 1e-3])
    sol = optimize.least_squares(residual, start, x_scale=xs, method="lm")
    fitted = _coast(sol.x, tau, m)
    if not np.all(np.isfinite(fitted)):
        raise ValueError("the coast-down fit did not converge: the record may not be a coast-down")
    se, interval, rms = _intervals(sol, t.size, level)
    return CoastDownFit(("A", "B", "C", "initial_speed"), sol.x, se, interval, level, rms, t, v, fitted)
