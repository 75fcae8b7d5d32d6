"""Parameter identification from test records by least squares, with confidence intervals.

Four identifications a railway dynamics course meets, each a fit of a physical model to a
record with ``scipy.optimize.least_squares``:

* :func:`free_decay` — natural frequency and damping ratio from a free decay (a damped
  sinusoid), beside chapter 1's logarithmic decrement of the same record (book eq. 1.17);
* :func:`bridge_free_vibration` — a bridge's frequency and damping from the free vibration
  left when a train has crossed;
* :func:`~raildyn.validation.bridge_wim.weigh_in_motion` — bridge weigh-in-motion: the
  train's speed, axle spacings and axle loads from strain records, through the bending-moment
  influence line of the simply supported span of chapter 10 {moses1979}, in
  :mod:`raildyn.validation.bridge_wim`;
* :func:`coast_down` — the Davis coefficients A, B, C from a coast-down record.

Every fit reports its estimates with standard errors and intervals from the Jacobian at
the solution: the covariance s²(JᵀJ)⁻¹, with s² the residual variance over n − p degrees of
freedom, and Student's t quantile at the stated confidence (95 % by default). These are the
usual linearised (asymptotic) intervals of nonlinear regression {seber2003}: they hold when
the noise is independent, of constant variance and small enough for the model to be
close to linear over the interval. Coloured noise (as in a real strain record) makes them
too narrow. The fit result, :class:`~raildyn.validation.fits.ParameterFit`, and the checks of
a record are in :mod:`raildyn.validation.fits`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from raildyn import _checks

# Moved to raildyn.validation.fits and raildyn.validation.bridge_wim (issue 33): imported here so
# that the old paths (raildyn.validation.identification.X) keep working for one issue; then this goes.
from raildyn.validation.bridge_wim import WeighInMotionFit, weigh_in_motion  # noqa: F401
from raildyn.validation.fits import ParameterFit, _confidence, _intervals, _record
from raildyn.vibration import damping_ratio_from_decrement, decrement_from_peaks

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.optimize,
# scipy.signal

__all__ = [
    "CoastDownFit",
    "FreeDecayFit",
    "bridge_free_vibration",
    "coast_down",
    "free_decay",
]


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
    from scipy import signal

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
    from scipy import optimize

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
    from scipy import optimize

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
