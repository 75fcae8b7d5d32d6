"""A prediction against a measurement in time: NRMSE, correlation, Theil's U, Sprague–Geers (chapter 11).

Two records of equal length on one uniform step, the measured one first: :func:`nrmse`,
:func:`correlation`, :func:`theil_u`, :func:`sprague_geers`, and :func:`compare`, which gives all of
them at once as an :class:`Agreement` with a ``.plot``. In frequency, see
:mod:`raildyn.validation.spectra`; the statistics of acceptance testing are in
:mod:`raildyn.validation.acceptance`.

Every metric is scale-free where its definition is (the records are scaled by their largest
magnitude before they are squared), so a record in N or in kN, or one with entries near the
floating-point limit, gives the same answer.

References
----------
* H. Theil, *Economic Forecasts and Policy*, 2nd ed., North-Holland, 1961 (the
  inequality coefficient U, bounded form); *Applied Economic Forecasting*,
  North-Holland, 1966 (an unbounded coefficient, for predicted changes; not used here).
* K. Pearson, "Mathematical contributions to the theory of evolution. III. Regression,
  heredity and panmixia", *Phil. Trans. R. Soc. A* 187, 253–318, 1896 (the correlation).
* M. A. Sprague and T. L. Geers, "A spectral-element method for modelling cavitation
  in transient fluid–structure interaction", *Int. J. Numer. Meth. Engng* 60(15),
  2467–2499, 2004 (the magnitude, phase and combined errors).
* L. E. Schwer, "Validation metrics for response histories: perspectives and case
  studies", *Engineering with Computers* 23, 295–309, 2007 (the Sprague–Geers errors
  restated and compared with other metrics)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.plots import COLORS, STYLE, axes_or_new
from raildyn.validation import _records

# Imported where used, to keep this module's import cheap (tests/test_imports.py): matplotlib

__all__ = [
    "NORMALISATIONS",
    "Agreement",
    "SpragueGeers",
    "compare",
    "correlation",
    "nrmse",
    "sprague_geers",
    "theil_u",
]

NORMALISATIONS = ("range", "rms", "std", "mean")
"""The names :func:`nrmse` accepts: the RMS error divided by the measured record's range
(max − min), RMS, standard deviation or |mean|."""


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
    m, p = _records.pair(measured, predicted)
    normalisation = _checks.choice("normalisation", normalisation, NORMALISATIONS)
    u, s = _records.scaled(m)
    if normalisation == "range":
        scale = s * float(u.max() - u.min())
    elif normalisation == "rms":
        scale = _records.rms(m)
    elif normalisation == "std":
        scale = s * float(np.std(u)) if np.ptp(u) > 0.0 else 0.0
    else:
        scale = s * abs(float(np.mean(u)))
    if not scale > 0.0:
        raise ValueError(
            f"measured must not have a zero {normalisation} (normalisation={normalisation!r}), "
            "so the error cannot be normalised by it; choose another normalisation"
        )
    return _records.rms(_records.diff(m, p)) / scale


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
    m, p = _records.pair(measured, predicted)
    for name, x in (("measured", m), ("predicted", p)):
        if np.ptp(x) == 0.0:
            raise ValueError(f"{name} must not be constant: the correlation divides by its spread")
    # r does not change when a record is scaled by a positive factor: scale before squaring
    a, b = _records.scaled(m)[0], _records.scaled(p)[0]
    a, b = _records.scaled(a - np.mean(a))[0], _records.scaled(b - np.mean(b))[0]
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
    m, p = _records.pair(measured, predicted)
    rm, rp = _records.rms(m), _records.rms(p)
    if rm == 0.0 and rp == 0.0:
        raise ValueError("measured and predicted must not both be zero: Theil's U is 0/0 then")
    # divide each term first: rm + rp may overflow where the ratio does not
    d = _records.rms(_records.diff(m, p))
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
    m, p = _records.pair(measured, predicted)
    _records.time_base(time, m.size)  # checked; on a uniform grid the step cancels from every ratio
    w = np.ones(m.size)
    w[[0, -1]] = 0.5
    w /= w.sum()
    u, su = _records.scaled(m)
    v, sv = _records.scaled(p)
    for name, s in (("measured", su), ("predicted", sv)):
        if s == 0.0:
            raise ValueError(f"{name} must not be zero everywhere: the Sprague–Geers phase error is 0/0 then")
    uu, vv, uv = np.dot(w, u * u), np.dot(w, v * v), np.dot(w, u * v)
    magnitude = (sv / su) * float(np.sqrt(vv / uu)) - 1.0
    cosine = min(1.0, max(-1.0, float(uv / np.sqrt(uu * vv))))
    phase = float(np.arccos(cosine) / np.pi)
    return SpragueGeers(magnitude, phase, float(np.hypot(magnitude, phase)))


@dataclass(frozen=True)
class Agreement(Tabular):
    """How well a prediction agrees with a measurement in time (:func:`compare`).

    Attributes
    ----------
    time : ndarray, shape (n,) or None
        The uniform time base, s; None for records given without one (samples 0, 1, ...).
    measured : ndarray, shape (n,)
        The measurement, finite, in the record's unit.
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

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("time", "s"), ("measured", "record's unit"), ("predicted", "record's unit"))
    _scalars = (
        ("nrmse", "-"), ("correlation", "-"), ("theil_u", "-"), ("magnitude", "-"), ("phase", "-"),
        ("combined", "-"),
    )  # fmt: skip

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
        m, p = _records.pair(self.measured, self.predicted)
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
        import matplotlib

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
    m, p = _records.pair(measured, predicted)
    t = _records.time_base(time, m.size)
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
