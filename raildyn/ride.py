"""Ride comfort: Sperling's ride index Wz and the ISO 2631-1 frequency-weighted RMS (chapter 6).

Sperling's index of a harmonic acceleration of peak a (cm/s²) at f Hz is
Wz = 0.896 (a³ F(f)/f)^{1/10}, F the frequency correction factor (Sperling 1941;
Garg & Dukkipati 1984, ch. 6). Writing B(f)³ = 0.896¹⁰ F(f)/f gives Wz = (aB)^{0.3};
B is approximated by the rational filter of :func:`sperling_weighting`, and a
random acceleration with weighted RMS σ_w (m/s²) is given the index of the
harmonic of the same RMS: a = √2 · 100 σ_w cm/s², so Wz = (100√2 σ_w)^{0.3}
= 4.42 σ_w^{0.3}.

ISO 2631-1 (1997, annex A) weights whole-body vertical acceleration by W_k and
horizontal by W_d, each the product of a band limit (high pass at f₁, low pass
at f₂), an acceleration–velocity transition (f₃, f₄, Q₄) and, for W_k, an upward
step (f₅, Q₅, f₆, Q₆); the weighted RMS is √∫|W|² S dω.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn import random_vibration as rv

__all__ = [
    "RideQuality",
    "iso2631_weighting",
    "ride_quality",
    "ride_quality_history",
    "sperling_correction",
    "sperling_harmonic",
    "sperling_index",
    "sperling_weighting",
]

# Sperling's correction factor F(f) (Sperling 1941, as tabulated by Garg & Dukkipati 1984, ch. 6).
_SPERLING_F = {
    "vertical": ((0.5, 5.9, lambda f: 0.325 * f**2), (5.9, 20.0, lambda f: 400.0 / f**2), 20.0),
    "lateral": ((0.5, 5.4, lambda f: 0.8 * f**2), (5.4, 26.0, lambda f: 650.0 / f**2), 26.0),
}

# Rational fits of B(f), f in Hz, as commonly quoted for Sperling's weighting (source to be confirmed;
# tests/test_ride.py checks the vertical fit against F(f) above: within 4 %, 7 % at the 5.9 Hz corner).
_SPERLING_B = {
    "vertical": (0.588, 1.911, 0.25, 0.277, 1.563, 0.0368),
    "lateral": (0.737, 1.911, 0.25, 0.277, 1.563, 0.0368),
}

# ISO 2631-1:1997, table A.2: f1, f2, f3, f4, Q4, f5, Q5, f6, Q6 (Hz); W_d has no upward step.
_ISO = {
    "Wk": (0.4, 100.0, 12.5, 12.5, 0.63, 2.37, 0.91, 3.35, 0.91),
    "Wd": (0.4, 100.0, 2.0, 2.0, 0.63, None, None, None, None),
}


def _direction(direction: str) -> str:
    return _checks.choice("direction", direction, _SPERLING_F)


def _frequency(frequency, low: float) -> np.ndarray:
    """Frequencies in Hz, >= ``low``, any shape, not empty (an empty grid has no answer)."""
    return _checks.array("frequency", frequency, low=low, allow_empty=False)


def _ratio(num, den, s):
    """Σ num_k s^k / Σ den_k s^k (coefficients in ascending powers), finite for any finite s.

    Both polynomials are divided by m^n, m = max(|s|, 1) and n the higher degree, so that
    no power of a large s overflows; for |s| <= 1 this is the plain quotient.
    """
    m = np.maximum(np.abs(s), 1.0)
    u = s / m
    n = max(len(num), len(den)) - 1

    def scaled(coefficients):
        return sum(c * u**k * m ** (k - n) for k, c in enumerate(coefficients))

    return scaled(num) / scaled(den)


def sperling_correction(frequency, direction: str = "vertical") -> np.ndarray:
    """Sperling's correction factor F(f), tabulated by frequency (Sperling 1941; book ch. 6).

    Parameters
    ----------
    frequency : array_like
        f, Hz, >= 0.5 (where the table starts); any shape, not empty.
    direction : {"vertical", "lateral"}
        Which table.

    Returns
    -------
    ndarray
        F(f), dimensionless.

    Examples
    --------
    >>> sperling_correction([1.0, 10.0, 30.0]).round(3).tolist()
    [0.325, 4.0, 1.0]
    """
    f = _frequency(frequency, 0.5)
    (a0, a1, low), (_, b1, high), top = _SPERLING_F[_direction(direction)]
    # each branch evaluated inside its own range (f² of a large f would overflow)
    return np.where(f < a1, low(np.minimum(f, a1)), np.where(f < b1, high(np.minimum(f, b1)), 1.0))


def sperling_weighting(frequency, direction: str = "vertical") -> np.ndarray:
    """|B(f)|: the rational fit of Sperling's weighting filter.

    Parameters
    ----------
    frequency : array_like
        f, Hz, >= 0; any shape, not empty.
    direction : {"vertical", "lateral"}
        Which fit.

    Returns
    -------
    ndarray
        |B(f)|, dimensionless.

    Examples
    --------
    >>> float(sperling_weighting(0.0))
    0.0
    """
    f = _frequency(frequency, 0.0)
    c, n1, n2, d1, d2, d3 = _SPERLING_B[_direction(direction)]
    # |B|² = (n1 f² + n2² f⁴)/((1 − d1 f²)² + (d2 f − d3 f³)²), numerator and denominator divided by
    # g⁶, g = max(f, 1), so that no power of a large f overflows (|B| falls as 1/f up there).
    g = np.maximum(f, 1.0)
    r = f / g
    num = n1 * r**2 * g**-4.0 + (n2 * r**2 / g) ** 2
    den = (g**-3.0 - d1 * r**2 / g) ** 2 + (d2 * r * g**-2.0 - d3 * r**3) ** 2
    return c * np.sqrt(num / den)


def sperling_harmonic(amplitude, frequency, direction: str = "vertical") -> np.ndarray:
    """Sperling's index Wz = 0.896 (a³ F(f)/f)^{1/10} of a harmonic acceleration, from the table F(f).

    Parameters
    ----------
    amplitude : array_like
        Peak acceleration a, m/s², >= 0 (converted to cm/s² inside, as Sperling's formula
        wants); not empty, broadcast against ``frequency``.
    frequency : array_like
        f, Hz, >= 0.5; not empty.
    direction : {"vertical", "lateral"}
        Which table of F(f).

    Returns
    -------
    ndarray
        Wz (1 very good … 4.5 dangerous).

    Examples
    --------
    >>> round(float(sperling_harmonic(0.3, 4.0)), 3)
    2.552
    """
    a = _checks.array("amplitude", amplitude, low=0.0, allow_empty=False) * 100.0  # cm/s²
    f = _frequency(frequency, 0.5)
    _checks.broadcast(amplitude=a, frequency=f)
    # (a³F/f)^{1/10} as a^{3/10} (F/f)^{1/10}: a³ would overflow for a large a.
    return 0.896 * a**0.3 * (sperling_correction(f, direction) / f) ** 0.1


def iso2631_weighting(frequency, weighting: str = "Wk") -> np.ndarray:
    """Complex ISO 2631-1 frequency weighting W(i2πf) (ISO 2631-1:1997, annex A).

    Parameters
    ----------
    frequency : array_like
        f, Hz, >= 0; any shape, not empty.
    weighting : {"Wk", "Wd"}
        W_k (vertical) or W_d (horizontal).

    Returns
    -------
    complex ndarray
        W, dimensionless.

    Examples
    --------
    >>> round(float(abs(iso2631_weighting(6.3))), 2)  # W_k is near 1 around 4-8 Hz
    1.05
    """
    f = _frequency(frequency, 0.0)
    f1, f2, f3, f4, q4, f5, q5, f6, q6 = _ISO[_checks.choice("weighting", weighting, _ISO)]
    s = 2j * np.pi * f
    w1, w2, w3, w4 = (2 * np.pi * x for x in (f1, f2, f3, f4))
    q1 = 1 / np.sqrt(2)
    # Each factor a ratio of polynomials in s (ascending powers), evaluated so that no power overflows.
    high = _ratio((0, 0, 1), (w1**2, w1 / q1, 1), s)
    low = _ratio((w2**2,), (w2**2, w2 / q1, 1), s)
    transition = _ratio((1, 1 / w3), (1, 1 / (q4 * w4), 1 / w4**2), s)
    H = high * low * transition
    if f5 is not None:
        w5, w6 = 2 * np.pi * f5, 2 * np.pi * f6
        step = _ratio((1, 1 / (q5 * w5), 1 / w5**2), (1, 1 / (q6 * w6), 1 / w6**2), s)
        H = H * step * (w5 / w6) ** 2
    return H


@dataclass(frozen=True)
class RideQuality:
    """Ride measures of one acceleration spectrum.

    Attributes
    ----------
    rms : float
        Unweighted RMS, m/s², >= 0.
    sperling_rms : float
        RMS weighted by Sperling's B(f), m/s², >= 0.
    wz : float
        Sperling's ride index (1 very good … 4.5 dangerous), >= 0.
    iso_rms : float
        ISO 2631-1 weighted RMS (W_k vertical, W_d lateral), m/s², >= 0.
    """

    rms: float
    sperling_rms: float
    wz: float
    iso_rms: float

    def __post_init__(self):
        for name in ("rms", "sperling_rms", "wz", "iso_rms"):
            object.__setattr__(self, name, _checks.nonnegative(name, getattr(self, name)))


def sperling_index(weighted_rms) -> float:
    """Sperling's ride index of a random acceleration, Wz = (100√2 σ_w)^{0.3} (module docstring).

    Parameters
    ----------
    weighted_rms : float
        σ_w, the RMS weighted by Sperling's B(f), m/s², >= 0.

    Returns
    -------
    float
        Wz.

    Examples
    --------
    >>> round(sperling_index(1 / (100 * 2**0.5)), 12)
    1.0
    """
    s = _checks.nonnegative("weighted_rms", weighted_rms)
    return float((100.0 * np.sqrt(2.0) * s) ** 0.3)


def ride_quality(psd, omega, direction: str = "vertical") -> RideQuality:
    """Ride measures of a one-sided acceleration spectrum.

    Parameters
    ----------
    psd : array_like, shape (n,)
        One-sided PSD of the acceleration, (m/s²)² per rad/s, >= 0.
    omega : array_like, shape (n,)
        Circular frequencies, rad/s, >= 0, strictly increasing, n >= 2.
    direction : {"vertical", "lateral"}
        Sperling's vertical or lateral weighting; ISO W_k or W_d.

    Returns
    -------
    RideQuality
        Unweighted and weighted RMS (m/s²) and Sperling's Wz.

    Examples
    --------
    >>> w = np.linspace(0.0, 200.0, 2001)
    >>> q = ride_quality(np.full(w.size, 1e-4), w)
    >>> round(q.rms, 4)  # √(1e-4 × 200)
    0.1414
    """
    w = _checks.time_grid("omega", omega)
    if w.size < 2 or w[0] < 0:
        raise ValueError(f"omega must hold at least 2 frequencies, all >= 0 rad/s, got {w!r:.80}")
    S = _checks.array("psd", psd, shape=w.shape, low=0.0)
    direction = _direction(direction)
    f = w / (2 * np.pi)
    B = sperling_weighting(f, direction)
    W = iso2631_weighting(f, "Wk" if direction == "vertical" else "Wd")
    ms = rv.mean_square(S, w)
    sw = float(np.sqrt(rv.mean_square(B**2 * S, w)))
    return RideQuality(
        float(np.sqrt(ms)), sw, sperling_index(sw), float(np.sqrt(rv.mean_square(np.abs(W) ** 2 * S, w)))
    )


def ride_quality_history(acceleration, dt, direction: str = "vertical") -> RideQuality:
    """Ride measures of an acceleration history, weighted by FFT.

    Parameters
    ----------
    acceleration : array_like, shape (n,)
        Acceleration, m/s², any values, sampled uniformly; n >= 4 (the mean is removed).
    dt : float
        Sampling interval, s, > 0.
    direction : {"vertical", "lateral"}
        Sperling's vertical or lateral weighting; ISO W_k or W_d.

    Returns
    -------
    RideQuality
        Unweighted and weighted RMS (m/s²) and Sperling's Wz.

    Examples
    --------
    >>> t = np.arange(4000) * 0.005
    >>> q = ride_quality_history(np.sin(2 * np.pi * 2.0 * t), 0.005)
    >>> round(q.rms, 4)  # a unit sine: 1/√2
    0.7071
    """
    a = _checks.array("acceleration", acceleration, ndim=1)
    dt = _checks.positive("dt", dt)
    direction = _direction(direction)
    if a.size < 4:
        raise ValueError(f"acceleration must hold at least 4 samples, got {a.size}")
    # Scaled to a peak of 1 (and the RMS values scaled back), so that no square overflows.
    scale = float(np.max(np.abs(a))) or 1.0
    a = a / scale
    a = a - a.mean()
    A = np.fft.rfft(a)
    f = np.fft.rfftfreq(a.size, dt)
    B = sperling_weighting(f, direction)
    W = np.abs(iso2631_weighting(f, "Wk" if direction == "vertical" else "Wd"))

    def _rms(weight):
        return scale * float(np.sqrt(np.mean(np.fft.irfft(A * weight, n=a.size) ** 2)))

    sw = _rms(B)
    return RideQuality(scale * float(np.sqrt(np.mean(a**2))), sw, sperling_index(sw), _rms(W))
