"""Comparing a prediction with a measurement: agreement metrics, spectra and test statistics (chapter 11).

Three groups, each on records sampled at one uniform step:

* **in time**, two records of equal length, the measured one first:
  :func:`nrmse`, :func:`correlation`, :func:`theil_u`, :func:`sprague_geers`, and
  :func:`compare`, which gives all of them at once as an :class:`Agreement` with a
  ``.plot``;
* **in frequency**: PSDs come from :func:`raildyn.random_vibration.welch_psd`, the
  package's one Welch estimator (one-sided, per rad/s; ``welch_psd(np.stack([measured,
  predicted]), dt)`` gives both at once); here :func:`third_octave_rms`
  (RMS in the one-third-octave bands of IEC 61260-1) and :func:`frequency_response_h1`
  (the H1 estimate and the coherence from an excitation and a response record);
* **the statistics of acceptance testing** (UIC 518, EN 14363): :func:`percentiles`,
  :func:`sliding_rms`, :func:`section_maxima`.

Every metric is scale-free where its definition is (the records are scaled by their
largest magnitude before they are squared), so a record in N or in kN, or one with
entries near the floating-point limit, gives the same answer.

References
----------
* H. Theil, *Economic Forecasts and Policy*, 2nd ed., North-Holland, 1961 (the
  inequality coefficient U, bounded form); *Applied Economic Forecasting*,
  North-Holland, 1966 (an unbounded coefficient, for predicted changes; not used here).
* K. Pearson, "Mathematical contributions to the theory of evolution. III. Regression,
  heredity and panmixia", *Phil. Trans. R. Soc. A* 187, 253–318, 1896 (the correlation).
* R. J. Hyndman and Y. Fan, "Sample quantiles in statistical packages", *The American
  Statistician* 50(4), 361–365, 1996 (definition 7: numpy's default percentile).
* M. A. Sprague and T. L. Geers, "A spectral-element method for modelling cavitation
  in transient fluid–structure interaction", *Int. J. Numer. Meth. Engng* 60(15),
  2467–2499, 2004 (the magnitude, phase and combined errors).
* L. E. Schwer, "Validation metrics for response histories: perspectives and case
  studies", *Engineering with Computers* 23, 295–309, 2007 (the Sprague–Geers errors
  restated and compared with other metrics).
* IEC 61260-1:2014, *Electroacoustics — Octave-band and fractional-octave-band
  filters — Part 1: Specifications* (base-10 band centres and edges; the same in
  ANSI S1.11-2004).
* J. S. Bendat and A. G. Piersol, *Random Data: Analysis and Measurement Procedures*,
  4th ed., Wiley, 2010, ch. 6 (H1 = G_xy/G_xx and the ordinary coherence).
* P. D. Welch, "The use of fast Fourier transform for the estimation of power
  spectra", *IEEE Trans. Audio Electroacoust.* 15(2), 70–73, 1967.
* UIC 518 (4th ed., 2009) and EN 14363:2016, *Railway applications — Testing and
  simulation for the acceptance of running characteristics of railway vehicles*:
  the 0.15 % and 99.85 % percentiles of each test section, sliding means and sliding
  r.m.s. values (as tabulated for UIC 518 / EN 14363 in the GENSYS course notes,
  gensys.se/course/UIC518_tests.html; the clause numbers of EN 14363:2016 are not
  checked here).
"""

from __future__ import annotations

from dataclasses import dataclass

import matplotlib
import numpy as np
import scipy.signal

from raildyn import _checks
from raildyn.plots import COLORS, STYLE, axes_or_new
from raildyn.random_vibration import welch_psd

__all__ = [
    "NORMALISATIONS",
    "Agreement",
    "BandRMS",
    "FrequencyResponseEstimate",
    "SectionMaxima",
    "SlidingRMS",
    "SpragueGeers",
    "compare",
    "correlation",
    "frequency_response_h1",
    "nrmse",
    "percentiles",
    "section_maxima",
    "sliding_rms",
    "sprague_geers",
    "theil_u",
    "third_octave_rms",
]

NORMALISATIONS = ("range", "rms", "std", "mean")
"""The names :func:`nrmse` accepts: the RMS error divided by the measured record's range
(max − min), RMS, standard deviation or |mean|."""

# IEC 61260-1:2014, base-10 system: octave ratio G = 10^(3/10), reference frequency 1000 Hz; for
# one-third octaves (b = 3, odd) the exact mid-band frequencies are f_m = 1000·G^(x/3) Hz and the
# band edges f_m·G^(∓1/6).
_G = 10.0**0.3
_F_REFERENCE = 1000.0
# A band is reported only when it spans at least this many Welch bins: the Hann window's main lobe
# is 4 bins wide, so a tone inside a narrower band would spill into its neighbours.
_MIN_BINS_PER_BAND = 4


# --------------------------------------------------------------------------- input


def _record(name: str, value, *, min_size: int = 2) -> np.ndarray:
    """A 1-D finite record of at least ``min_size`` samples."""
    x = _checks.array(name, value, ndim=1, allow_empty=False)
    if x.size < min_size:
        raise ValueError(f"{name} must hold at least {min_size} samples, got {x.size}")
    return x


def _pair(measured, predicted, names=("measured", "predicted"), min_size: int = 2):
    """Two records of equal length (a record each, named by ``names``)."""
    m = _record(names[0], measured, min_size=min_size)
    p = _record(names[1], predicted, min_size=min_size)
    if p.size != m.size:
        raise ValueError(
            f"{names[1]} must have as many samples as {names[0]} ({m.size}), got {p.size}: "
            "resample both onto one time base first"
        )
    return m, p


def _time(time, n: int) -> np.ndarray | None:
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


def _scaled(x: np.ndarray) -> tuple[np.ndarray, float]:
    """``x`` divided by its largest magnitude, and that magnitude (0 for a zero record)."""
    s = float(np.max(np.abs(x)))
    return (x / s if s > 0.0 else x), s


def _rms(x: np.ndarray, weights: np.ndarray | None = None) -> float:
    """√(mean x²) (weighted by ``weights``, which sum to 1), without overflow."""
    u, s = _scaled(x)
    mean_square = np.mean(u * u) if weights is None else np.dot(weights, u * u)
    return s * float(np.sqrt(mean_square))


def _diff(measured: np.ndarray, predicted: np.ndarray) -> np.ndarray:
    """predicted − measured, computed after halving so that opposite huge entries do not overflow."""
    return 2.0 * (0.5 * predicted - 0.5 * measured) if _huge(measured, predicted) else predicted - measured


def _huge(*arrays) -> bool:
    return any(np.max(np.abs(a)) > 1e307 for a in arrays)


def _percent(name: str, value, *, pair: bool = False) -> np.ndarray:
    """Percentages in [0, 100]; a pair (lower, upper) with lower <= upper when ``pair``."""
    q = _checks.array(name, value, ndim=1, allow_empty=False)
    if np.any((q < 0.0) | (q > 100.0)):
        raise ValueError(f"{name} must hold percentages in [0, 100], got {value!r}")
    if pair and (q.size != 2 or q[0] > q[1]):
        raise ValueError(
            f"{name} must be a pair (lower, upper) of percentages, lower <= upper, got {value!r}"
        )
    return q


def _samples(name: str, length: float, spacing: float, n: int, what: str) -> int:
    """A length (s or m) as a whole number of samples, 1 to n, or a ValueError naming ``name``."""
    k = int(round(length / spacing))
    if not 1 <= k <= n:
        raise ValueError(
            f"{name} must span 1 to {n} samples of spacing {spacing:g} (the {what}), "
            f"got {length!r} = {length / spacing:.4g} samples"
        )
    return k


# --------------------------------------------------------------------------- metrics in time


def nrmse(measured, predicted, *, normalisation: str = "range") -> float:
    """Normalised root-mean-square error of a prediction, dimensionless.

    NRMSE = √(mean (p − m)²) / N(m), where N is, by ``normalisation``:

    * ``"range"``: max m − min m (the most common choice; reads as a share of the swing);
    * ``"rms"``: √(mean m²) (then NRMSE² is the relative error energy);
    * ``"std"``: the standard deviation of m (NRMSE² = 1 − R² for a least-squares fit);
    * ``"mean"``: |mean m| (the coefficient of variation of the RMSE, for records far from 0).

    The normalisations are conventional, not from one source; say which one you quote.

    Parameters
    ----------
    measured : array_like, shape (n,)
        The measurement, any unit, finite, n >= 2; its N must not vanish.
    predicted : array_like, shape (n,)
        The prediction on the same time base, same unit, finite.
    normalisation : {"range", "rms", "std", "mean"}
        What the RMS error is divided by.

    Returns
    -------
    float
        NRMSE >= 0 (0: identical records).

    Examples
    --------
    >>> m = np.sin(np.linspace(0, 2 * np.pi, 101))
    >>> round(nrmse(m, 1.1 * m, normalisation="rms"), 6)
    0.1
    """
    m, p = _pair(measured, predicted)
    normalisation = _checks.choice("normalisation", normalisation, NORMALISATIONS)
    u, s = _scaled(m)
    if normalisation == "range":
        scale = s * float(u.max() - u.min())
    elif normalisation == "rms":
        scale = _rms(m)
    elif normalisation == "std":
        scale = s * float(np.std(u)) if np.ptp(u) > 0.0 else 0.0
    else:
        scale = s * abs(float(np.mean(u)))
    if not scale > 0.0:
        raise ValueError(
            f"measured must not have a zero {normalisation} (normalisation={normalisation!r}), "
            "so the error cannot be normalised by it; choose another normalisation"
        )
    return _rms(_diff(m, p)) / scale


def correlation(measured, predicted) -> float:
    """Pearson's correlation coefficient of the two records, dimensionless.

    r = Σ (m − m̄)(p − p̄) / √(Σ (m − m̄)² Σ (p − p̄)²) (Pearson 1896): 1 for a prediction
    that is a positive gain and offset of the measurement, blind to amplitude errors.

    Parameters
    ----------
    measured : array_like, shape (n,)
        The measurement, finite, n >= 2, not constant.
    predicted : array_like, shape (n,)
        The prediction on the same time base, finite, not constant.

    Returns
    -------
    float
        r in [−1, 1].

    Examples
    --------
    >>> m = np.sin(np.linspace(0, 2 * np.pi, 101))
    >>> round(correlation(m, 3.0 * m + 1.0), 12)
    1.0
    """
    m, p = _pair(measured, predicted)
    for name, x in (("measured", m), ("predicted", p)):
        if np.ptp(x) == 0.0:
            raise ValueError(f"{name} must not be constant: the correlation divides by its spread")
    # r does not change when a record is scaled by a positive factor: scale before squaring
    a, b = _scaled(m)[0], _scaled(p)[0]
    a, b = _scaled(a - np.mean(a))[0], _scaled(b - np.mean(b))[0]
    r = float(np.dot(a, b) / np.sqrt(np.dot(a, a) * np.dot(b, b)))
    return min(1.0, max(-1.0, r))


def theil_u(measured, predicted) -> float:
    """Theil's inequality coefficient U of a prediction, dimensionless, in [0, 1].

    U = √(mean (p − m)²) / (√(mean p²) + √(mean m²)) (Theil 1961): 0 for a perfect
    prediction, 1 for one of the wrong sign everywhere (p = −k m) or a zero one. For a pure
    gain p = g m with g >= 0, U = |g − 1| / (g + 1). Theil (1966) also gave an unbounded
    coefficient, for predicted and actual changes; it is not computed here.

    Parameters
    ----------
    measured : array_like, shape (n,)
        The measurement, finite, n >= 2.
    predicted : array_like, shape (n,)
        The prediction on the same time base, finite; not both records zero.

    Returns
    -------
    float
        U in [0, 1].

    Examples
    --------
    >>> m = np.sin(np.linspace(0, 2 * np.pi, 101))
    >>> round(theil_u(m, 2.0 * m), 12)  # (2 - 1)/(2 + 1)
    0.333333333333
    """
    m, p = _pair(measured, predicted)
    rm, rp = _rms(m), _rms(p)
    if rm == 0.0 and rp == 0.0:
        raise ValueError("measured and predicted must not both be zero: Theil's U is 0/0 then")
    # divide each term first: rm + rp may overflow where the ratio does not
    d = _rms(_diff(m, p))
    return min(1.0, d / rm / (1.0 + rp / rm) if rm >= rp else d / rp / (1.0 + rm / rp))


@dataclass(frozen=True)
class SpragueGeers:
    """The Sprague–Geers errors of a prediction (:func:`sprague_geers`), dimensionless.

    Attributes
    ----------
    magnitude : float
        M = √(ψ_pp/ψ_mm) − 1, >= −1: the relative error of the RMS, blind to phase.
    phase : float
        P = arccos(ψ_mp/√(ψ_mm ψ_pp))/π, in [0, 1]: blind to magnitude.
    combined : float
        C = √(M² + P²), >= 0.
    """

    magnitude: float
    phase: float
    combined: float

    def __post_init__(self):
        object.__setattr__(self, "magnitude", _checks.scalar("magnitude", self.magnitude, low=-1.0))
        object.__setattr__(self, "phase", _checks.scalar("phase", self.phase, low=0.0, high=1.0))
        object.__setattr__(self, "combined", _checks.nonnegative("combined", self.combined))


def sprague_geers(measured, predicted, time=None) -> SpragueGeers:
    """The Sprague–Geers magnitude, phase and combined errors of a prediction (integral form).

    With ψ_mm = ∫ m² dt, ψ_pp = ∫ p² dt and ψ_mp = ∫ m p dt over the record (each
    divided by its duration, which cancels), M = √(ψ_pp/ψ_mm) − 1,
    P = arccos(ψ_mp/√(ψ_mm ψ_pp))/π and C = √(M² + P²) (Sprague & Geers 2004, as
    restated by Schwer 2007). The integrals are taken by the trapezoid rule on the
    uniform time base. A pure gain g > 0 gives M = g − 1 and P = 0; a sine delayed by
    τ, over whole periods, gives M = 0 and P = ωτ/π (for ωτ <= π).

    Parameters
    ----------
    measured : array_like, shape (n,)
        The measurement, finite, n >= 2, not zero everywhere.
    predicted : array_like, shape (n,)
        The prediction on the same time base, finite, not zero everywhere (P is undefined then).
    time : None, float or array_like, shape (n,)
        The time base: None (samples one unit apart), the step dt in s (> 0), or the
        times in s (uniform, strictly increasing). Only the trapezoid weights depend on it.

    Returns
    -------
    SpragueGeers
        ``magnitude``, ``phase`` and ``combined``.

    Examples
    --------
    >>> t = np.linspace(0.0, 1.0, 1001)
    >>> sg = sprague_geers(np.sin(2 * np.pi * t), 1.2 * np.sin(2 * np.pi * t), t)
    >>> round(sg.magnitude, 9), round(sg.phase, 6)
    (0.2, 0.0)
    """
    m, p = _pair(measured, predicted)
    _time(time, m.size)  # checked; on a uniform grid the step cancels from every ratio
    w = np.ones(m.size)
    w[[0, -1]] = 0.5
    w /= w.sum()
    u, su = _scaled(m)
    v, sv = _scaled(p)
    for name, s in (("measured", su), ("predicted", sv)):
        if s == 0.0:
            raise ValueError(f"{name} must not be zero everywhere: the Sprague–Geers phase error is 0/0 then")
    uu, vv, uv = np.dot(w, u * u), np.dot(w, v * v), np.dot(w, u * v)
    magnitude = (sv / su) * float(np.sqrt(vv / uu)) - 1.0
    cosine = min(1.0, max(-1.0, float(uv / np.sqrt(uu * vv))))
    phase = float(np.arccos(cosine) / np.pi)
    return SpragueGeers(magnitude, phase, float(np.hypot(magnitude, phase)))


@dataclass(frozen=True)
class Agreement:
    """How well a prediction agrees with a measurement in time (:func:`compare`).

    Attributes
    ----------
    time : ndarray, shape (n,) or None
        The uniform time base, s; None for records given without one (samples 0, 1, ...).
    measured : ndarray, shape (n,)
        The measurement, finite.
    predicted : ndarray, shape (n,)
        The prediction, finite, in the unit of ``measured``.
    normalisation : str
        Which normalisation ``nrmse`` used (one of :data:`NORMALISATIONS`).
    nrmse : float
        Normalised RMS error, >= 0 (:func:`nrmse`).
    correlation : float
        Pearson's r, in [−1, 1] (:func:`correlation`).
    theil_u : float
        Theil's U, in [0, 1] (:func:`theil_u`).
    magnitude : float
        Sprague–Geers M, >= −1 (:func:`sprague_geers`).
    phase : float
        Sprague–Geers P, in [0, 1].
    combined : float
        Sprague–Geers C = √(M² + P²), >= 0.
    """

    time: np.ndarray | None
    measured: np.ndarray
    predicted: np.ndarray
    normalisation: str
    nrmse: float
    correlation: float
    theil_u: float
    magnitude: float
    phase: float
    combined: float

    def __post_init__(self):
        m, p = _pair(self.measured, self.predicted)
        object.__setattr__(self, "measured", m)
        object.__setattr__(self, "predicted", p)
        if self.time is not None:
            t = _checks.time_grid("time", self.time, uniform=True)
            if t.size != m.size:
                raise ValueError(f"time must hold one time per sample ({m.size}), got {t.size}")
            object.__setattr__(self, "time", t)
        _checks.choice("normalisation", self.normalisation, NORMALISATIONS)
        bounds = {
            "nrmse": (0.0, None), "correlation": (-1.0, 1.0), "theil_u": (0.0, 1.0),
            "magnitude": (-1.0, None), "phase": (0.0, 1.0), "combined": (0.0, None),
        }  # fmt: skip
        for name, (low, high) in bounds.items():
            object.__setattr__(self, name, _checks.scalar(name, getattr(self, name), low=low, high=high))

    def plot(self, ax=None) -> dict:
        """The two records overlaid, the metrics in the title.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes if None.

        Returns
        -------
        dict
            The lines ``measured`` and ``predicted``.
        """
        ax = axes_or_new(ax)
        x = np.arange(self.measured.size) if self.time is None else self.time
        with matplotlib.rc_context(STYLE):
            (measured,) = ax.plot(x, self.measured, color="0.2", lw=1.2, label="measured")
            (predicted,) = ax.plot(x, self.predicted, color=COLORS[1], lw=1.2, ls="--", label="predicted")
            ax.set_xlabel("sample" if self.time is None else "time $t$ (s)")
            ax.set_title(
                f"NRMSE ({self.normalisation}) {self.nrmse:.3g}   r {self.correlation:.3f}   "
                f"U {self.theil_u:.3g}\nSprague–Geers M {self.magnitude:+.3g}   P {self.phase:.3g}   "
                f"C {self.combined:.3g}"
            )
            ax.legend()
        return {"measured": measured, "predicted": predicted}


def compare(measured, predicted, time=None, *, normalisation: str = "range") -> Agreement:
    """Every time-domain agreement metric of a prediction against a measurement, in one call.

    Calls :func:`nrmse`, :func:`correlation`, :func:`theil_u` and :func:`sprague_geers`
    (see each for its definition and source) on the same two records.

    Parameters
    ----------
    measured : array_like, shape (n,)
        The measurement, any unit, finite, n >= 2, neither constant nor zero.
    predicted : array_like, shape (n,)
        The prediction on the same time base and in the same unit, finite, not constant.
    time : None, float or array_like, shape (n,)
        None (samples one unit apart), the step dt in s (> 0), or the uniform times in s.
    normalisation : {"range", "rms", "std", "mean"}
        The normalisation of the RMS error (:data:`NORMALISATIONS`).

    Returns
    -------
    Agreement
        The records, the metrics and a ``.plot``.

    Examples
    --------
    >>> t = np.arange(0.0, 2.0, 0.001)
    >>> a = compare(np.sin(2 * np.pi * t), 1.1 * np.sin(2 * np.pi * t), 0.001)
    >>> round(a.correlation, 9), round(a.magnitude, 9)
    (1.0, 0.1)
    """
    m, p = _pair(measured, predicted)
    t = _time(time, m.size)
    normalisation = _checks.choice("normalisation", normalisation, NORMALISATIONS)
    sg = sprague_geers(m, p)
    return Agreement(
        time=t,
        measured=m,
        predicted=p,
        normalisation=normalisation,
        nrmse=nrmse(m, p, normalisation=normalisation),
        correlation=correlation(m, p),
        theil_u=theil_u(m, p),
        magnitude=sg.magnitude,
        phase=sg.phase,
        combined=sg.combined,
    )


# --------------------------------------------------------------------------- metrics in frequency


@dataclass(frozen=True)
class BandRMS:
    """RMS values in one-third-octave bands (:func:`third_octave_rms`).

    Attributes
    ----------
    centre_hz : ndarray, shape (k,)
        Exact mid-band frequencies f_m = 1000·10^(x/10) Hz (IEC 61260-1 base 10), > 0, increasing.
    lower_hz, upper_hz : ndarray, shape (k,)
        Band edges f_m·10^(∓1/20), Hz.
    rms : ndarray, shape (k,)
        RMS of the record in each band, >= 0, in the record's unit.
    """

    centre_hz: np.ndarray
    lower_hz: np.ndarray
    upper_hz: np.ndarray
    rms: np.ndarray

    def __post_init__(self):
        f = _checks.increasing("centre_hz", self.centre_hz, low=0.0, low_open=True)
        object.__setattr__(self, "centre_hz", f)
        for name in ("lower_hz", "upper_hz"):
            edge = _checks.array(name, getattr(self, name), shape=f.shape, low=0.0, low_open=True)
            object.__setattr__(self, name, edge)
        object.__setattr__(self, "rms", _checks.array("rms", self.rms, shape=f.shape, low=0.0))
        if np.any(self.lower_hz >= self.centre_hz) or np.any(self.upper_hz <= self.centre_hz):
            raise ValueError("lower_hz and upper_hz must bracket centre_hz in every band")

    @property
    def mean_square(self) -> float:
        """Σ rms²: the mean square in all the bands together, (unit)²."""
        s = float(self.rms.max())
        return 0.0 if s == 0.0 else s * s * float(np.sum((self.rms / s) ** 2))

    def plot(self, ax=None, *, label: str | None = None, color=COLORS[0]) -> dict:
        """The band RMS as steps over the band edges, on a logarithmic frequency axis.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes if None.
        label : str, optional
            Legend label.
        color : color
            Line colour.

        Returns
        -------
        dict
            ``{"line": line}``.
        """
        ax = axes_or_new(ax)
        edges = np.append(self.lower_hz, self.upper_hz[-1])
        with matplotlib.rc_context(STYLE):
            line = ax.stairs(self.rms, edges, color=color, label=label, lw=1.4)
            ax.set_xscale("log")
            ax.set_xlabel("frequency $f$ (Hz), one-third-octave bands")
            ax.set_ylabel("band RMS")
        return {"line": line}


def third_octave_rms(record, dt, *, nperseg=None, f_min=None, f_max=None) -> BandRMS:
    """RMS of a record in the one-third-octave bands of IEC 61260-1 (base 10).

    The bands have exact mid-band frequencies f_m = 1000·G^(x/3) Hz, G = 10^(3/10), for
    integer x, and edges f_m·G^(∓1/6) (IEC 61260-1:2014; ANSI S1.11-2004 the same). The
    mean square in a band is the Welch PSD (:func:`raildyn.random_vibration.welch_psd`,
    per rad/s) summed over the bins whose frequency lies in [f_lower, f_upper), times the
    bin width Δω; by Parseval the bands together hold the record's mean square in their
    range. The mean is removed (it lies in no band). A band is reported when it lies
    below the Nyquist frequency and spans at least 4 bins (the Hann main lobe), so that a
    tone at its centre stays inside it.

    Parameters
    ----------
    record : array_like, shape (n,)
        The record, any unit, finite, n >= 8.
    dt : float
        Sampling interval, s, > 0.
    nperseg : int, optional
        Welch segment length, 8 <= nperseg <= n; default n (one Hann-windowed segment: the
        finest resolution, Δf = 1/(n dt)). Shorter segments average more but lose the low bands.
    f_min, f_max : float, optional
        Keep only the bands whose centre lies in [f_min, f_max], Hz (> 0); default all.

    Returns
    -------
    BandRMS
        Band centres and edges (Hz) and the band RMS (unit of the record).

    Examples
    --------
    A unit sine at 10 Hz (a band centre) has all its RMS, 1/√2, in the 10 Hz band:

    >>> t = np.arange(20000) * 1e-3
    >>> bands = third_octave_rms(np.sin(2 * np.pi * 10.0 * t), 1e-3)
    >>> i = int(np.argmin(abs(bands.centre_hz - 10.0)))
    >>> float(round(bands.rms[i] * np.sqrt(2), 3))
    1.0
    """
    x = _record("record", record, min_size=8)
    dt = _checks.positive("dt", dt)
    n = x.size
    nperseg = n if nperseg is None else _checks.integer("nperseg", nperseg, low=8, high=n)
    lo = 0.0 if f_min is None else _checks.positive("f_min", f_min)
    hi = np.inf if f_max is None else _checks.positive("f_max", f_max)
    if hi < lo:
        raise ValueError(f"f_max must be >= f_min ({lo:g} Hz), got {f_max!r}")
    u, s = _scaled(x)
    u, spread = _scaled(u - np.mean(u))  # the mean lies in no band
    s *= spread
    spectrum = welch_psd(u, 1.0, nperseg=nperseg)  # in the unit sampling interval; f = ω/(2π dt)
    f = spectrum.omega / (2.0 * np.pi * dt)
    power = spectrum.psd * (spectrum.omega[1] - spectrum.omega[0])  # mean square per bin, scaled record
    df = 1.0 / (nperseg * dt)
    nyquist = 0.5 / dt
    width = _G ** (1 / 6) - _G ** (-1 / 6)  # band width / f_m
    # the band indices x that fit: f_m·width >= 4 Δf and f_m·G^(1/6) <= Nyquist
    f_low = max(lo, _MIN_BINS_PER_BAND * df / width)
    f_high = min(hi, nyquist / _G ** (1 / 6))
    with np.errstate(over="ignore", divide="ignore"):
        x_low = int(np.ceil(3.0 * np.log10(f_low / _F_REFERENCE) / 0.3 - 1e-9))
        x_high = int(np.floor(3.0 * np.log10(f_high / _F_REFERENCE) / 0.3 + 1e-9))
    if x_high < x_low:
        raise ValueError(
            f"record of {n} samples at dt = {dt:g} s (nperseg {nperseg}) resolves no one-third-octave band "
            f"with centre in [{lo:g}, {hi:g}] Hz: a band needs {_MIN_BINS_PER_BAND} bins of {df:.3g} Hz "
            f"and must lie below the Nyquist frequency {nyquist:.3g} Hz; use a longer record or a wider "
            "f_min/f_max"
        )
    index = np.arange(x_low, x_high + 1)
    centre = _F_REFERENCE * _G ** (index / 3.0)
    lower, upper = centre * _G ** (-1 / 6), centre * _G ** (1 / 6)
    which = np.searchsorted(lower, f, side="right") - 1  # the band whose lower edge is below each bin
    inside = (which >= 0) & (f < upper[np.clip(which, 0, None)])
    mean_square = np.bincount(which[inside], weights=power[inside], minlength=index.size)
    return BandRMS(centre, lower, upper, s * np.sqrt(mean_square))


@dataclass(frozen=True)
class FrequencyResponseEstimate:
    """The H1 estimate of a frequency response and the coherence (:func:`frequency_response_h1`).

    Attributes
    ----------
    omega : ndarray, shape (k,)
        Circular frequencies, rad/s, >= 0, increasing.
    h1 : ndarray of complex, shape (k,)
        H1(ω) = G_xy/G_xx, in (response unit)/(excitation unit); 0 where the excitation has no power.
    coherence : ndarray, shape (k,)
        Ordinary coherence γ² = |G_xy|²/(G_xx G_yy), in [0, 1]; 0 where either record has no power.
    """

    omega: np.ndarray
    h1: np.ndarray
    coherence: np.ndarray

    def __post_init__(self):
        w = _checks.increasing("omega", self.omega, low=0.0)
        object.__setattr__(self, "omega", w)
        h = _checks.array("h1", self.h1, shape=w.shape, dtype=complex)
        object.__setattr__(self, "h1", h)
        g = _checks.array("coherence", self.coherence, shape=w.shape, low=0.0)
        if np.any(g > 1.0 + 1e-9):
            raise ValueError(f"coherence must lie in [0, 1], got a maximum of {g.max()!r}")
        object.__setattr__(self, "coherence", np.minimum(g, 1.0))

    def plot(self, ax=None) -> dict:
        """|H1| against ω on log–log axes, and the coherence on a second axis at the right.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw |H1|; new axes if None.

        Returns
        -------
        dict
            The lines ``h1`` and ``coherence``.
        """
        ax = axes_or_new(ax)
        keep = self.omega > 0
        with matplotlib.rc_context(STYLE):
            (h1,) = ax.loglog(self.omega[keep], np.abs(self.h1[keep]), color=COLORS[0], label="|H1|")
            ax.set_xlabel(r"circular frequency $\omega$ (rad/s)")
            ax.set_ylabel("|H1| (response / excitation)")
            right = ax.twinx()
            (coherence,) = right.semilogx(
                self.omega[keep], self.coherence[keep], color=COLORS[2], lw=1, label="coherence"
            )
            right.set_ylim(0.0, 1.05)
            right.set_ylabel(r"coherence $\gamma^2$")
        return {"h1": h1, "coherence": coherence}


def frequency_response_h1(excitation, response, dt, *, nperseg=None) -> FrequencyResponseEstimate:
    """The H1 estimate of the frequency response from excitation and response records, and the coherence.

    H1(ω) = G_xy(ω)/G_xx(ω) and γ²(ω) = |G_xy|²/(G_xx G_yy) (Bendat & Piersol 2010, ch. 6),
    with the auto- and cross-spectra by Welch's method (``scipy.signal.csd`` and
    ``scipy.signal.welch``: Hann window, 50 % overlap, mean removed; G_xy ∝ E[conj(X) Y]).
    H1 is unbiased by noise on the response and biased low by noise on the excitation;
    γ² near 1 says the response is a linear function of the excitation, near 0 that it is
    not. With a single segment γ² is 1 everywhere: use several (``nperseg`` < n).

    Parameters
    ----------
    excitation : array_like, shape (n,)
        The input x(t), any unit, finite, n >= 8, not constant.
    response : array_like, shape (n,)
        The output y(t) on the same time base, any unit, finite.
    dt : float
        Sampling interval, s, > 0.
    nperseg : int, optional
        Segment length, 8 <= nperseg <= n; default min(256, n).

    Returns
    -------
    FrequencyResponseEstimate
        ``omega`` (rad/s), ``h1`` (response unit per excitation unit) and ``coherence``.

    Examples
    --------
    A response twice the excitation:

    >>> x = np.random.default_rng(0).standard_normal(4096)
    >>> est = frequency_response_h1(x, 2.0 * x, 0.01)
    >>> round(float(np.abs(est.h1[1:-1]).mean()), 9), round(float(est.coherence[1:-1].min()), 9)
    (2.0, 1.0)
    """
    x, y = _pair(excitation, response, names=("excitation", "response"), min_size=8)
    dt = _checks.positive("dt", dt)
    nperseg = min(256, x.size) if nperseg is None else _checks.integer("nperseg", nperseg, low=8, high=x.size)
    u, su = _scaled(x)
    v, sv = _scaled(y)
    if np.ptp(u) == 0.0:
        raise ValueError("excitation must not be constant (or zero): H1 divides by its spectrum")
    u, v = u - np.mean(u), v - np.mean(v)
    f, g_uu = scipy.signal.welch(u, fs=1.0, nperseg=nperseg)
    _, g_vv = scipy.signal.welch(v, fs=1.0, nperseg=nperseg)
    _, g_uv = scipy.signal.csd(u, v, fs=1.0, nperseg=nperseg)
    tiny = np.finfo(float).tiny / np.finfo(float).eps
    has_x = g_uu > tiny * max(float(g_uu.max()), tiny)
    has_both = has_x & (g_vv > tiny * max(float(g_vv.max()), tiny))
    h1 = np.zeros(f.size, dtype=complex)
    h1[has_x] = (sv / su) * g_uv[has_x] / g_uu[has_x]
    coherence = np.zeros(f.size)
    coherence[has_both] = np.abs(g_uv[has_both]) ** 2 / (g_uu[has_both] * g_vv[has_both])
    if not np.all(np.isfinite(h1)):
        raise ValueError("response is too large against excitation: H1 overflows; rescale the records")
    return FrequencyResponseEstimate(2.0 * np.pi * f / dt, h1, np.minimum(coherence, 1.0))


# --------------------------------------------------------------------------- acceptance statistics


def percentiles(record, percent=(0.15, 99.85)) -> np.ndarray:
    """Percentiles of a record, in its unit: by default the 0.15 % and 99.85 % of acceptance tests.

    UIC 518 and EN 14363 characterise the dynamic quantities of each test section (wheel
    forces, Y/Q, accelerations) by their 0.15 % and 99.85 % percentiles, and the
    quasi-static ones by the 50 % percentile (see the module's references). The
    percentile here is numpy's linear interpolation between order statistics
    (Hyndman & Fan 1996, definition 7); whether it matches the standards' own rule to the
    sample is not checked here.

    Parameters
    ----------
    record : array_like, shape (n,)
        The (filtered) record of one section, any unit, finite, n >= 1.
    percent : array_like, shape (k,)
        Percentages in [0, 100].

    Returns
    -------
    ndarray, shape (k,)
        The percentiles, in the unit of ``record``.

    Examples
    --------
    >>> percentiles(np.arange(10001.0), (0.15, 50.0, 99.85)).tolist()
    [15.0, 5000.0, 9985.0]
    """
    x = _record("record", record, min_size=1)
    q = _percent("percent", percent)
    return np.percentile(x, q)


@dataclass(frozen=True)
class SlidingRMS:
    """A sliding RMS of a record (:func:`sliding_rms`).

    Attributes
    ----------
    position : ndarray, shape (k,)
        Centre of each window from the first sample, in the unit of the spacing (s or m).
    rms : ndarray, shape (k,)
        RMS over each window, >= 0, in the record's unit.
    window : float
        The window length, s or m, > 0.
    """

    position: np.ndarray
    rms: np.ndarray
    window: float

    def __post_init__(self):
        pos = _checks.increasing("position", self.position, low=0.0)
        object.__setattr__(self, "position", pos)
        object.__setattr__(self, "rms", _checks.array("rms", self.rms, shape=pos.shape, low=0.0))
        object.__setattr__(self, "window", _checks.positive("window", self.window))

    def plot(self, ax=None, *, label: str | None = None, color=COLORS[0]) -> dict:
        """The sliding RMS against the window centre.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes if None.
        label : str, optional
            Legend label.
        color : color
            Line colour.

        Returns
        -------
        dict
            ``{"line": line}``.
        """
        ax = axes_or_new(ax)
        with matplotlib.rc_context(STYLE):
            (line,) = ax.plot(self.position, self.rms, color=color, label=label)
            ax.set_xlabel("window centre (s or m)")
            ax.set_ylabel(f"sliding RMS over {self.window:g}")
        return {"line": line}


def sliding_rms(record, spacing, window, *, step=None) -> SlidingRMS:
    """The RMS of a record over a window sliding along it.

    r_j = √((1/w) Σ_{i = jk}^{jk + w − 1} x_i²), w = window/spacing samples, k = step/spacing
    (both rounded to whole samples). UIC 518 and EN 14363 use sliding r.m.s. values
    of filtered bogie-frame accelerations and track forces to detect running instability
    (module references); the window and step the standard prescribes are inputs here.
    The record is in time (spacing and window in s) or along the track (in m): one unit
    for both.

    Parameters
    ----------
    record : array_like, shape (n,)
        The record, any unit, finite, n >= 1 (filter it to the band of interest first).
    spacing : float
        Sample spacing, s or m, > 0.
    window : float
        Window length in the unit of ``spacing``, spanning 1 to n samples.
    step : float, optional
        Advance from one window to the next, in the unit of ``spacing``, at least one
        sample; default one sample.

    Returns
    -------
    SlidingRMS
        Window centres and RMS values.

    Examples
    --------
    The RMS of a unit sine over whole periods is 1/√2 wherever the window sits:

    >>> s = np.arange(2000) * 0.5  # every 0.5 m
    >>> r = sliding_rms(np.sin(2 * np.pi * s / 20.0), 0.5, 100.0, step=10.0)
    >>> bool(np.allclose(r.rms, np.sqrt(0.5)))
    True
    """
    x = _record("record", record, min_size=1)
    spacing = _checks.positive("spacing", spacing)
    window = _checks.positive("window", window)
    w = _samples("window", window, spacing, x.size, "window length")
    k = 1 if step is None else _samples("step", _checks.positive("step", step), spacing, x.size, "step")
    u, s = _scaled(x)
    energy = np.concatenate(([0.0], np.cumsum(u * u)))
    starts = np.arange(0, x.size - w + 1, k)
    mean_square = np.maximum(energy[starts + w] - energy[starts], 0.0) / w
    return SlidingRMS((starts + 0.5 * (w - 1)) * spacing, s * np.sqrt(mean_square), w * spacing)


@dataclass(frozen=True)
class SectionMaxima:
    """Extremes (or percentiles) of a record section by section (:func:`section_maxima`).

    Attributes
    ----------
    start : ndarray, shape (k,)
        Where each section begins, from the first sample, in the unit of the spacing (s or m).
    lower, upper : ndarray, shape (k,)
        The lower and upper statistic of each section (minimum and maximum, or the
        percentiles asked for), in the record's unit; lower <= upper.
    length : float
        Section length, s or m, > 0.
    percent : ndarray, shape (2,)
        The percentiles taken, in [0, 100] ((0, 100): the extremes).
    """

    start: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    length: float
    percent: np.ndarray

    def __post_init__(self):
        start = _checks.increasing("start", self.start, low=0.0)
        object.__setattr__(self, "start", start)
        for name in ("lower", "upper"):
            object.__setattr__(self, name, _checks.array(name, getattr(self, name), shape=start.shape))
        if np.any(self.lower > self.upper):
            raise ValueError("lower must not exceed upper in any section")
        object.__setattr__(self, "length", _checks.positive("length", self.length))
        object.__setattr__(self, "percent", _percent("percent", self.percent, pair=True))

    def plot(self, ax=None, *, color=COLORS[0]) -> dict:
        """The lower and upper statistic of each section as steps along the record.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes if None.
        color : color
            Colour of both steps.

        Returns
        -------
        dict
            The step artists ``lower`` and ``upper``.
        """
        ax = axes_or_new(ax)
        edges = np.append(self.start, self.start[-1] + self.length)
        lo, hi = (f"{q:g} %" for q in self.percent)
        with matplotlib.rc_context(STYLE):
            upper = ax.stairs(self.upper, edges, color=color, label=f"section {hi}")
            lower = ax.stairs(self.lower, edges, color=color, ls="--", label=f"section {lo}")
            ax.set_xlabel("position along the record (s or m)")
            ax.legend()
        return {"lower": lower, "upper": upper}


def section_maxima(record, spacing, length, *, percent=(0.0, 100.0)) -> SectionMaxima:
    """The extremes, or two percentiles, of a record in consecutive sections of a given length.

    The record is cut into ⌊n/m⌋ sections of m = length/spacing samples (rounded); a
    shorter tail is left out. Each section gives its ``percent`` percentiles (numpy's
    linear rule, as in :func:`percentiles`): (0, 100), the default, is the minimum and
    maximum; (0.15, 99.85) are the per-section values of UIC 518 and EN 14363, whose
    test zones are evaluated section by section (module references).

    Parameters
    ----------
    record : array_like, shape (n,)
        The record, any unit, finite, n >= 1.
    spacing : float
        Sample spacing, s or m, > 0.
    length : float
        Section length in the unit of ``spacing``, spanning 1 to n samples.
    percent : array_like, shape (2,)
        The lower and upper percentiles, in [0, 100], lower <= upper.

    Returns
    -------
    SectionMaxima
        Section starts and the lower and upper statistic of each.

    Examples
    --------
    >>> sm = section_maxima([0.0, 3.0, -1.0, 2.0, 5.0, -4.0, 9.0], 1.0, 3.0)
    >>> sm.upper.tolist(), sm.lower.tolist()
    ([3.0, 5.0], [-1.0, -4.0])
    """
    x = _record("record", record, min_size=1)
    spacing = _checks.positive("spacing", spacing)
    length = _checks.positive("length", length)
    q = _percent("percent", percent, pair=True)
    m = _samples("length", length, spacing, x.size, "section length")
    k = x.size // m
    sections = x[: k * m].reshape(k, m)
    lower, upper = np.percentile(sections, q, axis=1)
    return SectionMaxima(np.arange(k) * m * spacing, lower, upper, m * spacing, q)
