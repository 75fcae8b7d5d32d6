"""Sample functions from a PSD and the PSD back from a record.

:func:`~raildyn.random_vibration.synthesis_lines` and :func:`~raildyn.random_vibration.synthesize`
build stationary records for time-domain simulation as sums of harmonics with random phases;
:func:`~raildyn.random_vibration.welch_psd` estimates the PSD of a record
(:class:`~raildyn.random_vibration.Spectrum`), one-sided per rad/s as everywhere in
:mod:`raildyn.random_vibration`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.random_vibration._common import (
    _MAX_RECORD,
    _MAX_VALUES,
    _finite,
    _spectrum_grid,
)

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.signal

__all__ = [
    "SpectralLines",
    "Spectrum",
    "synthesis_lines",
    "synthesize",
    "welch_psd",
]


@dataclass(frozen=True)
class Spectrum:
    """A one-sided PSD on a grid of frequencies (raildyn's convention, module docstring).

    Attributes
    ----------
    omega : ndarray, shape (n,)
        Circular frequencies, rad/s (or wavenumbers, rad/m, for a spectrum in space), >= 0
        and strictly increasing.
    psd : ndarray, shape (..., n)
        One-sided PSD per rad/s (per rad/m), >= 0; several records give several rows.
    """

    omega: np.ndarray
    psd: np.ndarray

    def __post_init__(self):
        w = _checks.increasing("omega", self.omega, low=0.0)
        S = _checks.array("psd", self.psd, low=0.0)
        if S.ndim == 0 or S.shape[-1] != w.size:
            raise ValueError(f"psd must have shape (..., {w.size}) to match omega, got {S.shape}")
        object.__setattr__(self, "omega", w)
        object.__setattr__(self, "psd", S)

    @property
    def mean_square(self) -> float | np.ndarray:
        """∫ S dω over the grid by the trapezoid rule, (quantity)²: see :func:`mean_square`."""
        value = np.trapezoid(self.psd, self.omega, axis=-1)
        return float(value) if np.ndim(value) == 0 else value

    @property
    def rms(self) -> float | np.ndarray:
        """√(mean square), in the unit of the quantity."""
        return np.sqrt(self.mean_square)


@dataclass(frozen=True)
class SpectralLines(Tabular):
    """The spectral lines of a synthesized sample (:func:`synthesis_lines`).

    Attributes
    ----------
    omega : ndarray, shape (k,)
        Line frequencies kept, rad/s, > 0 and strictly increasing.
    psd : ndarray, shape (k,)
        One-sided PSD at those frequencies, (signal unit)²/(rad/s), >= 0.
    d_omega : float
        Line spacing Δω = 2π/(n·dt), rad/s, > 0.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("omega", "rad/s"), ("psd", "(signal unit)²/(rad/s)"))
    _scalars = (("d_omega", "rad/s"),)

    omega: np.ndarray
    psd: np.ndarray
    d_omega: float

    def __post_init__(self):
        w = _checks.increasing("omega", self.omega, low=0.0, low_open=True)
        object.__setattr__(self, "omega", w)
        object.__setattr__(self, "psd", _checks.array("psd", self.psd, shape=w.shape, low=0.0))
        object.__setattr__(self, "d_omega", _checks.positive("d_omega", self.d_omega))

    @property
    def mean_square(self) -> float:
        """Σ_k S(ω_k) Δω: the mean square of every sample over its record, (quantity)²."""
        return float(np.sum(self.psd) * self.d_omega)


def _line_grid(dt: float, n: int) -> tuple[np.ndarray, float]:
    """Circular frequencies ω_k = k Δω, k = 1..⌈n/2⌉−1, of an n-point record, and Δω."""
    d_omega = 2.0 * np.pi / (n * dt)
    k = np.arange(1, (n - 1) // 2 + 1)
    return k * d_omega, d_omega


def _evaluate_psd(psd, w: np.ndarray) -> np.ndarray:
    """One-sided PSD values at the line frequencies w, from a callable or an (omega, values) pair."""
    if callable(psd):
        raw = psd(w)
        at = f"the {w.size} synthesis frequencies"
        values = _checks.returned("psd", raw, shape=w.shape if np.ndim(raw) else (), low=0.0, at=at)
        return np.broadcast_to(values, w.shape)
    if isinstance(psd, (tuple, list)) and len(psd) == 2:
        S, grid = _spectrum_grid(psd[1], psd[0], min_points=2)
        return np.interp(w, grid, S, left=0.0, right=0.0)
    raise TypeError(
        "psd must be a callable S(omega) (rad/s -> one-sided PSD) or a pair (omega_grid, values), "
        f"got {type(psd).__name__}"
    )


def _band_mask(band, w: np.ndarray, dt: float) -> np.ndarray:
    if band is None:
        return np.ones(w.shape, dtype=bool)
    nyquist = np.pi / dt
    try:
        pair = _checks._numbers("band", band)
        lo, hi = (float(b) for b in pair)
    except (TypeError, ValueError):
        raise ValueError(f"band must be a pair (omega_lo, omega_hi) in rad/s, got {band!r}") from None
    if not (np.isfinite(lo) and np.isfinite(hi) and 0.0 <= lo < hi <= nyquist):
        raise ValueError(
            f"band must satisfy 0 <= omega_lo < omega_hi <= pi/dt = {nyquist:.6g} rad/s (the Nyquist "
            f"frequency), got {band!r}"
        )
    mask = (w >= lo) & (w <= hi)
    if not np.any(mask):
        spacing = w[1] - w[0] if w.size > 1 else w[0]
        raise ValueError(
            f"band {band!r} holds none of the synthesis frequencies (spacing 2*pi/(n*dt) = {spacing:.6g} "
            "rad/s); widen the band or lengthen the record"
        )
    return mask


def synthesis_lines(psd, dt, n, *, band=None) -> SpectralLines:
    """The spectral lines :func:`synthesize` uses: frequencies, PSD values and spacing.

    ω_k = 2πk/(n·dt) for k = 1 … ⌈n/2⌉ − 1 (the zero frequency and, for even n,
    the Nyquist frequency are left out), restricted to ``band`` if given. Every
    sample of :func:`synthesize` has mean square over its record exactly
    Σ_k S(ω_k) Δω (``SpectralLines.mean_square``).

    Parameters
    ----------
    psd : callable or (omega_grid, values)
        One-sided PSD per rad/s, as for :func:`synthesize`.
    dt : float
        Time step, s, > 0.
    n : int
        Number of time points, from 4 to 2**24, as for :func:`synthesize`.
    band : (omega_lo, omega_hi), optional
        Lines kept, rad/s, as for :func:`synthesize`.

    Returns
    -------
    SpectralLines
        Line frequencies (rad/s), PSD values there and the spacing Δω (rad/s).

    Examples
    --------
    >>> lines = synthesis_lines(lambda w: 0.01, dt=0.01, n=8)
    >>> lines.omega.round(3).tolist(), round(lines.d_omega, 3)
    ([78.54, 157.08, 235.619], 78.54)
    """
    dt = _checks.positive("dt", dt)
    n = _checks.integer("n", n, low=4, high=_MAX_RECORD)
    w, d_omega = _line_grid(dt, n)
    mask = _band_mask(band, w, dt)
    S = _evaluate_psd(psd, w)
    return SpectralLines(omega=w[mask], psd=S[mask], d_omega=d_omega)


def synthesize(
    psd: Callable | tuple,
    dt: float,
    n: int,
    rng=None,
    *,
    n_samples: int = 1,
    band: tuple[float, float] | None = None,
) -> np.ndarray:
    """Sample functions of a zero-mean stationary Gaussian process with a given one-sided PSD.

    Spectral representation with deterministic amplitudes and independent
    uniform random phases (Shinozuka & Jan 1972):

        x(t) = Σ_k √(2 S(ω_k) Δω) cos(ω_k t + φ_k),   φ_k ~ U[0, 2π),

    on t = arange(n)·dt, with ω_k = kΔω, Δω = 2π/(n·dt), k = 1 … ⌈n/2⌉ − 1 (the
    zero and Nyquist frequencies are left out). Because the ω_k are exactly the
    record's discrete Fourier frequencies, the sum is one inverse real FFT, and
    Parseval's theorem makes the mean square of every sample over the record
    exactly Σ_k S(ω_k) Δω (to round-off): only the phases are random. The
    sample is Gaussian in the limit of many lines (central limit theorem) and
    periodic with period n·dt.

    Parameters
    ----------
    psd : callable or (omega_grid, values)
        One-sided PSD per rad/s: a callable S(omega) taking an array of circular
        frequencies and returning finite values >= 0 of its shape (a scalar result
        means a flat spectrum), or a pair of arrays interpolated linearly and taken
        as zero outside the grid.
    dt : float
        Time step, s, > 0 (the Nyquist frequency is π/dt rad/s).
    n : int
        Number of time points, from 4 to 2**24 (a longer record is built in pieces:
        one FFT of 2**24 points already takes about a second).
    rng : numpy.random.Generator, int or None
        Source of the phases; the same seed gives the same samples.
    n_samples : int
        Number of independent sample functions, >= 1, with n_samples·n <= 2**26
        (the samples then take at most 0.5 GB).
    band : (omega_lo, omega_hi), optional
        Keep only lines with omega_lo <= ω_k <= omega_hi, rad/s; needs
        0 <= omega_lo < omega_hi <= π/dt. The phases drawn do not depend on
        ``band``, so the same seed gives the same phase on every line kept.

    Returns
    -------
    ndarray
        Shape ``(n,)`` when ``n_samples == 1``, else ``(n_samples, n)``; the
        values at t = arange(n)·dt, in the unit whose square the PSD carries.

    Examples
    --------
    >>> x = synthesize(lambda w: 0.01, dt=0.01, n=1024, rng=1)
    >>> lines = synthesis_lines(lambda w: 0.01, dt=0.01, n=1024)
    >>> bool(np.isclose(np.mean(x**2), lines.mean_square, rtol=1e-12))
    True
    """
    generator = _checks.generator(rng)
    n_samples = _checks.integer("n_samples", n_samples, low=1)
    dt = _checks.positive("dt", dt)
    n = _checks.integer("n", n, low=4, high=_MAX_RECORD)
    if n_samples * n > _MAX_VALUES:
        raise ValueError(
            f"n_samples * n must be at most 2**26 = {_MAX_VALUES} values (0.5 GB), got {n_samples} * {n}"
        )
    w, d_omega = _line_grid(dt, n)
    mask = _band_mask(band, w, dt)
    S = _evaluate_psd(psd, w) * mask
    phases = generator.uniform(0.0, 2.0 * np.pi, size=(n_samples, w.size))
    amplitude = np.sqrt(2.0 * S * d_omega)
    # numpy's irfft gives x[m] = (1/n)[X_0 + 2 Re Σ_k X_k e^{2πikm/n} (+ Nyquist term)], so a cosine of
    # amplitude A_k and phase φ_k needs the coefficient X_k = (n/2) A_k e^{iφ_k}.
    spectrum = np.zeros((n_samples, n // 2 + 1), dtype=complex)
    spectrum[:, 1 : w.size + 1] = 0.5 * n * amplitude * np.exp(1j * phases)
    x = np.fft.irfft(spectrum, n=n, axis=-1)
    return x[0] if n_samples == 1 else x


def welch_psd(x, dt, nperseg=None) -> Spectrum:
    """Welch estimate of the PSD of a sampled record, in the raildyn convention.

    Calls ``scipy.signal.welch`` (Hann window, 50 % overlap, mean removed;
    Welch 1967), whose one-sided per-Hz density is converted to one-sided per
    rad/s: ω = 2πf and S = S_Hz/(2π). The zero-frequency (and, for even
    ``nperseg``, the Nyquist) value is not doubled by scipy, so it reads half
    the one-sided density; compare away from those ends.

    Parameters
    ----------
    x : array_like
        Record(s) sampled every ``dt``, finite: shape ``(n,)``, or ``(m, n)`` for m
        records estimated separately.
    dt : float
        Sampling interval, s, > 0.
    nperseg : int, optional
        Segment length, 4 <= nperseg <= n; default min(256, n). Longer segments
        resolve finer (Δω = 2π/(nperseg·dt)) but average fewer segments.

    Returns
    -------
    Spectrum
        ``omega`` (nperseg//2 + 1,) in rad/s and ``psd`` (..., nperseg//2 + 1),
        one-sided per rad/s.

    Examples
    --------
    The mean square of a unit sine is 1/2, whatever the window:

    >>> t = np.arange(4096) * 0.01
    >>> est = welch_psd(np.sin(2 * np.pi * 5.0 * t), 0.01, nperseg=1024)
    >>> round(est.mean_square, 3)
    0.5
    """
    import scipy.signal

    arr = _checks.array("x", x)
    if arr.ndim not in (1, 2):
        raise ValueError(f"x must be a 1-D record or a 2-D array of records, got shape {arr.shape}")
    dt = _checks.positive("dt", dt)
    n = arr.shape[-1]
    if n < 4:
        raise ValueError(f"x must hold at least 4 samples per record, got {n}")
    nperseg = min(256, n) if nperseg is None else _checks.integer("nperseg", nperseg, low=4, high=n)
    with np.errstate(over="ignore", invalid="ignore"):
        f, p_hz = scipy.signal.welch(arr, fs=1.0 / dt, nperseg=nperseg, axis=-1)
    return Spectrum(omega=2.0 * np.pi * f, psd=_finite(p_hz, "x and dt", "a PSD") / (2.0 * np.pi))
