"""Records in frequency: RMS in one-third-octave bands, the H1 estimate and the coherence (chapter 11).

PSDs come from :func:`raildyn.random_vibration.welch_psd`, the package's one Welch estimator
(one-sided, per rad/s; ``welch_psd(np.stack([measured, predicted]), dt)`` gives both at once); here
:func:`third_octave_rms` (RMS in the one-third-octave bands of IEC 61260-1) and
:func:`frequency_response_h1` (the H1 estimate and the coherence from an excitation and a response
record).

References
----------
* IEC 61260-1:2014, *Electroacoustics — Octave-band and fractional-octave-band
  filters — Part 1: Specifications* (base-10 band centres and edges; the same in
  ANSI S1.11-2004).
* J. S. Bendat and A. G. Piersol, *Random Data: Analysis and Measurement Procedures*,
  4th ed., Wiley, 2010, ch. 6 (H1 = G_xy/G_xx and the ordinary coherence).
* P. D. Welch, "The use of fast Fourier transform for the estimation of power
  spectra", *IEEE Trans. Audio Electroacoust.* 15(2), 70–73, 1967."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.plots import COLORS, STYLE, axes_or_new
from raildyn.random_vibration import welch_psd
from raildyn.validation import _records

# Imported where used, to keep this module's import cheap (tests/test_imports.py): matplotlib, scipy.signal

__all__ = ["BandRMS", "FrequencyResponseEstimate", "frequency_response_h1", "third_octave_rms"]

# IEC 61260-1:2014, base-10 system: octave ratio G = 10^(3/10), reference frequency 1000 Hz; for
# one-third octaves (b = 3, odd) the exact mid-band frequencies are f_m = 1000·G^(x/3) Hz and the
# band edges f_m·G^(∓1/6).
_G = 10.0**0.3
_F_REFERENCE = 1000.0
# A band is reported only when it spans at least this many Welch bins: the Hann window's main lobe
# is 4 bins wide, so a tone inside a narrower band would spill into its neighbours.
_MIN_BINS_PER_BAND = 4


@dataclass(frozen=True)
class BandRMS(Tabular):
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

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("centre_hz", "Hz"), ("lower_hz", "Hz"), ("upper_hz", "Hz"), ("rms", "record's unit"))

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
        import matplotlib

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
    x = _records.record("record", record, min_size=8)
    dt = _checks.positive("dt", dt)
    n = x.size
    nperseg = n if nperseg is None else _checks.integer("nperseg", nperseg, low=8, high=n)
    lo = 0.0 if f_min is None else _checks.positive("f_min", f_min)
    hi = np.inf if f_max is None else _checks.positive("f_max", f_max)
    if hi < lo:
        raise ValueError(f"f_max must be >= f_min ({lo:g} Hz), got {f_max!r}")
    u, s = _records.scaled(x)
    u, spread = _records.scaled(u - np.mean(u))  # the mean lies in no band
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
class FrequencyResponseEstimate(Tabular):
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

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("omega", "rad/s"), ("h1", "(response unit)/(excitation unit)"), ("coherence", "-"))

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
        import matplotlib

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
    import scipy.signal

    x, y = _records.pair(excitation, response, names=("excitation", "response"), min_size=8)
    dt = _checks.positive("dt", dt)
    nperseg = min(256, x.size) if nperseg is None else _checks.integer("nperseg", nperseg, low=8, high=x.size)
    u, su = _records.scaled(x)
    v, sv = _records.scaled(y)
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
