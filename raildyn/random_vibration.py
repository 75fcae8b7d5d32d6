"""Random vibration: spectra, response spectra, mean squares and sample functions (chapter 1).

The random part of Garg & Dukkipati's chapter 1: a stationary process described
by its power spectral density (PSD), the response PSD of a linear system, mean
squares by integration over frequency, several correlated inputs through a
cross-spectral matrix (two axles meeting the same track a time d/V apart), and
sample functions synthesized from a PSD for time-domain simulation.

The PSD convention of raildyn
-----------------------------
Every PSD in raildyn is **one-sided, per rad/s** in time (**per rad/m** in
space), so that the variance of a zero-mean process is

    σ² = ∫₀^∞ S(ω) dω.

Sources use other forms; with ω = 2πf (and Ω = 2πn in space, n in cycles/m):

* two-sided, on (−∞, ∞), per rad/s:  S₂(ω) = S(ω)/2, because the even S₂ covers
  each frequency twice (Newland 1993, ch. 5);
* one-sided per Hz:  S_Hz(f) df = S(ω) dω, so S_Hz(f) = 2π S(ω);
* two-sided per Hz:  S_Hz,2(f) = π S(ω).

:func:`convert_psd` converts the density *values* between these forms; the
frequency axis is converted separately by ω = 2πf (Ω = 2πn in space). A spatial
track spectrum S(Ω) per rad/m seen at speed V becomes the temporal spectrum
S(Ω)/V at ω = VΩ (the same change of variables, with dΩ = dω/V).

Cross-spectra
-------------
For inputs x_j(t) the cross-spectral matrix used here is

    S_jk(ω) = 2 · (1/2π) ∫ E[x_j(t+τ) x_k(t)] e^{−iωτ} dτ      (ω ≥ 0),

i.e. S_jk ∝ E[X_j X_k*] in terms of Fourier amplitudes. With it the response
y = H x of a linear system has S_y = H S_x Hᴴ, the usual matrix form. Texts that
define the cross-correlation as E[x_j(t) x_k(t+τ)] (e.g. Newland 1993, ch. 3 and
ch. 7) obtain the complex conjugate (= transpose) of this matrix and write the
response as H* S Hᵀ; the diagonal, and every response PSD, is the same.

References
----------
* D. E. Newland, *An Introduction to Random Vibrations, Spectral and Wavelet
  Analysis*, 3rd ed., Longman, 1993.
* S. H. Crandall and W. D. Mark, *Random Vibration in Mechanical Systems*,
  Academic Press, 1963.
* M. Shinozuka and C.-M. Jan, "Digital simulation of random processes and its
  applications", *J. Sound Vib.* 25(1), 111–128, 1972.
* S. O. Rice, "Mathematical analysis of random noise", *Bell Syst. Tech. J.* 23,
  282–332 (1944) and 24, 46–156 (1945).
* P. D. Welch, "The use of fast Fourier transform for the estimation of power
  spectra", *IEEE Trans. Audio Electroacoust.* 15(2), 70–73, 1967.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import scipy.signal

from raildyn import _checks

__all__ = [
    "SpectralLines",
    "Spectrum",
    "cancellation_frequencies",
    "convert_psd",
    "response_psd",
    "delayed_input_csd",
    "delayed_mean_psd",
    "mean_square",
    "rms",
    "spectral_moments",
    "zero_upcrossing_rate",
    "peak_rate",
    "irregularity_factor",
    "sdof_white_noise_mean_square",
    "synthesis_lines",
    "synthesize",
    "welch_psd",
]

_SIDED = ("one", "two")
_TIME_UNITS = ("rad/s", "Hz")
_SPACE_UNITS = ("rad/m", "cycles/m")
_CYCLIC_UNITS = ("Hz", "cycles/m")

# At most this many frequencies from cancellation_frequencies: a bound on the memory asked for.
_MAX_COUNT = 1_000_000
# At most this many points in one synthesized record, and in all the records of one call: the FFT
# of 2**24 points takes about a second and the 2**26 values about 0.5 GB; longer records are built
# in pieces.
_MAX_RECORD = 2**24
_MAX_VALUES = 2**26


def _finite(value, names: str, what: str):
    """``value`` itself, unless it overflowed (computed under ``np.errstate(over="ignore")``)."""
    if not np.all(np.isfinite(value)):
        raise ValueError(f"{names} give {what} beyond floating point range; rescale them")
    return value


# --------------------------------------------------------------------------- results


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
class SpectralLines:
    """The spectral lines of a synthesized sample (:func:`synthesis_lines`).

    Attributes
    ----------
    omega : ndarray, shape (k,)
        Line frequencies kept, rad/s, > 0 and strictly increasing.
    psd : ndarray, shape (k,)
        One-sided PSD at those frequencies, per rad/s, >= 0.
    d_omega : float
        Line spacing Δω = 2π/(n·dt), rad/s, > 0.
    """

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


# --------------------------------------------------------------------------- conventions


def convert_psd(values, *, from_sided, from_unit, to_sided="one", to_unit="rad/s") -> np.ndarray:
    """Convert PSD values between one-/two-sided and per-radian/per-cycle forms.

    Only the density values change; the frequency axis converts on its own by
    ω = 2πf (time) or Ω = 2πn (space). The factors follow from keeping the
    variance fixed: a two-sided density is half the one-sided one, and
    S_Hz(f) df = S(ω) dω gives S_Hz = 2π S (Newland 1993, ch. 5).

    Parameters
    ----------
    values : array_like
        PSD values, >= 0, in (quantity)² per unit of ``from_unit``; any shape, not empty.
    from_sided, to_sided : {"one", "two"}
        One-sided (on ω >= 0) or two-sided (on −∞ < ω < ∞, even in ω).
    from_unit, to_unit : {"rad/s", "Hz", "rad/m", "cycles/m"}
        The frequency unit the density is per. Time units convert only to time
        units, space units only to space units.

    Returns
    -------
    ndarray
        The values in the target form (same shape as ``values``).

    Examples
    --------
    A two-sided level of 1 per rad/s is 2 one-sided per rad/s and 4π per Hz:

    >>> float(convert_psd(1.0, from_sided="two", from_unit="rad/s"))
    2.0
    >>> float(convert_psd(1.0, from_sided="two", from_unit="rad/s", to_unit="Hz")) / np.pi
    4.0
    """
    from_sided = _checks.choice("from_sided", from_sided, _SIDED)
    to_sided = _checks.choice("to_sided", to_sided, _SIDED)
    from_unit = _checks.choice("from_unit", from_unit, _TIME_UNITS + _SPACE_UNITS)
    to_unit = _checks.choice("to_unit", to_unit, _TIME_UNITS + _SPACE_UNITS)
    if (from_unit in _TIME_UNITS) != (to_unit in _TIME_UNITS):
        raise ValueError(
            f"from_unit {from_unit!r} and to_unit {to_unit!r} must both be time units "
            f"{_TIME_UNITS} or both space units {_SPACE_UNITS}; converting between time and "
            "space needs a speed (S_t(ω) = S(Ω)/V at ω = VΩ)"
        )
    arr = _checks.array("values", values, low=0.0, allow_empty=False)
    factor = 1.0
    # to the raildyn form: one-sided, per radian
    if from_sided == "two":
        factor *= 2.0
    if from_unit in _CYCLIC_UNITS:
        factor /= 2.0 * np.pi
    # from the raildyn form to the target
    if to_sided == "two":
        factor /= 2.0
    if to_unit in _CYCLIC_UNITS:
        factor *= 2.0 * np.pi
    return np.asarray(arr * factor)


# --------------------------------------------------------------------------- response spectra


def response_psd(frf, input_psd) -> np.ndarray:
    """PSD (or cross-spectral matrix) of the response of a linear system.

    S_y(ω) = H(ω) S_x(ω) H(ω)ᴴ (Newland 1993, ch. 7; the SISO case
    S_y = |H|² S_x is ch. 6), evaluated frequency by frequency.

    Parameters
    ----------
    frf : array_like, complex
        Frequency response on the frequency grid of ``input_psd``, in
        (output unit)/(input unit). Shape ``(n,)`` (one input, one output),
        ``(n, q)`` (q inputs, one output) or ``(n, p, q)`` (q inputs, p outputs).
    input_psd : array_like
        ``(n,)`` real PSD >= 0 when ``frf`` is ``(n,)``; otherwise the ``(n, q, q)``
        Hermitian cross-spectral matrix of the inputs (convention in the module
        docstring; :func:`delayed_input_csd` builds one).

    Returns
    -------
    ndarray
        ``(n,)`` real response PSD for a single output, or the ``(n, p, p)``
        complex response cross-spectral matrix (made exactly Hermitian, so its
        diagonal is real) for ``frf`` of shape ``(n, p, q)``.

    Examples
    --------
    >>> h = np.array([1.0, 2.0j]); s = np.array([3.0, 1.0])
    >>> response_psd(h, s).tolist()
    [3.0, 4.0]
    """
    H = _checks.array("frf", frf, dtype=complex, allow_empty=False)
    raw = _checks.array("input_psd", input_psd, dtype=complex)
    allowed = "allowed: frf (n,) with input_psd (n,); frf (n, q) or (n, p, q) with input_psd (n, q, q)"
    mismatch = ValueError(f"frf shape {H.shape} does not match input_psd shape {raw.shape}; {allowed}")
    if H.ndim == 1:
        if raw.ndim != 1 or raw.shape != H.shape:
            raise mismatch
        S = _checks.array("input_psd", raw.real, low=0.0)
        with np.errstate(over="ignore", invalid="ignore"):
            return _finite(np.abs(H) ** 2 * S, "frf and input_psd", "a response PSD")
    if H.ndim not in (2, 3) or raw.ndim != 3:
        raise mismatch
    n, q = H.shape[0], H.shape[-1]
    if raw.shape != (n, q, q):
        raise mismatch
    S = _checks.hermitian("input_psd", input_psd)
    diag = np.diagonal(S, axis1=-2, axis2=-1).real
    if np.any(diag < 0):
        i, j = np.argwhere(diag < 0)[0]
        raise ValueError(
            f"input_psd must have auto-spectra (diagonal) >= 0, got input_psd[{i}, {j}, {j}] = {diag[i, j]!r}"
        )
    with np.errstate(over="ignore", invalid="ignore"):
        if H.ndim == 2:
            # single output: y = Σ_j H_j x_j, so S_y = Σ_jk H_j S_jk conj(H_k), real by Hermitian symmetry
            Sy = np.einsum("ij,ijk,ik->i", H, S, np.conj(H)).real
        else:
            Sy = H @ S @ np.conj(np.swapaxes(H, -1, -2))
            Sy = 0.5 * (Sy + np.conj(np.swapaxes(Sy, -1, -2)))
    return _finite(Sy, "frf and input_psd", "a response PSD")


def delayed_input_csd(psd, omega, delays) -> np.ndarray:
    """Cross-spectral matrix of q inputs that are one process met with time delays.

    Input j is x_j(t) = u(t − τ_j): the same process u reaching it τ_j later
    (a wheelset a distance d behind the leading one at speed V meets the same
    track a time τ = d/V later). Shifting a signal by τ multiplies its Fourier
    amplitude by e^{−iωτ}, so with the convention of the module docstring
    (S_jk ∝ E[X_j X_k*])

        S_jk(ω) = S(ω) exp(−iω(τ_j − τ_k)).

    Only differences of delays matter. In terms of ``scipy.signal.csd(a, b)``,
    which estimates E[A* B], S_jk corresponds to ``csd(x_k, x_j)``.

    Parameters
    ----------
    psd : array_like, shape (n,)
        One-sided PSD S(ω) of u, >= 0, per rad/s.
    omega : array_like, shape (n,)
        Circular frequencies, rad/s, >= 0.
    delays : array_like, shape (q,)
        Time delays τ_j in s (any sign; for axles at distances d_j behind the
        first, τ_j = d_j/V).

    Returns
    -------
    ndarray, complex, shape (n, q, q)
        The Hermitian cross-spectral matrix, ready for :func:`response_psd`.

    Examples
    --------
    Two axles 2.5 m apart at 25 m/s; the sum of the two inputs cancels at
    ω = π/τ:

    >>> tau = 2.5 / 25.0
    >>> csd = delayed_input_csd([1.0, 1.0], [0.0, np.pi / tau], [0.0, tau])
    >>> np.round(response_psd(np.ones((2, 2)), csd), 12).tolist()
    [4.0, 0.0]
    """
    S, w = _spectrum_grid(psd, omega, increasing=False)
    tau = _checks.array("delays", delays, ndim=1)
    if tau.size == 0:
        raise ValueError("delays must hold at least one delay, got an empty array")
    dtau = tau[:, None] - tau[None, :]
    with np.errstate(over="ignore", invalid="ignore"):
        csd = S[:, None, None] * np.exp(-1j * w[:, None, None] * dtau[None, :, :])
    return _finite(csd, "omega and delays", "phases omega (tau_j - tau_k)")


def delayed_mean_psd(psd, omega, delays) -> np.ndarray:
    """PSD of the mean of q inputs that are one process met with time delays.

    The mean y(t) = (1/q) Σ_j u(t − τ_j) (the average of what q axles meet,
    a bounce input) has the frequency response (1/q) Σ_j e^{−iωτ_j}, so

        S_y(ω) = S(ω) |(1/q) Σ_j e^{−iωτ_j}|²

    (:func:`response_psd` of the cross-spectral matrix of
    :func:`delayed_input_csd` gives the same). For two inputs τ apart,
    S_y = S cos²(ωτ/2): the mean misses every frequency of
    :func:`cancellation_frequencies`.

    Parameters
    ----------
    psd : array_like, shape (n,)
        One-sided PSD S(ω) of u, >= 0, per rad/s.
    omega : array_like, shape (n,)
        Circular frequencies, rad/s, >= 0.
    delays : array_like, shape (q,)
        Time delays τ_j, s.

    Returns
    -------
    ndarray, shape (n,)
        One-sided PSD of the mean, per rad/s.

    Examples
    --------
    >>> tau = 0.1
    >>> np.round(delayed_mean_psd([1.0, 1.0], [0.0, np.pi / tau], [0.0, tau]), 12).tolist()
    [1.0, 0.0]
    """
    S, w = _spectrum_grid(psd, omega, increasing=False)
    tau = _checks.array("delays", delays, ndim=1)
    if tau.size == 0:
        raise ValueError("delays must hold at least one delay, got an empty array")
    with np.errstate(over="ignore", invalid="ignore"):
        gain = np.exp(-1j * w[:, None] * tau[None, :]).mean(axis=1)
    return S * np.abs(_finite(gain, "omega and delays", "phases omega tau_j")) ** 2


def cancellation_frequencies(delay, count: int) -> np.ndarray:
    """Circular frequencies ω_j = (2j + 1)π/τ at which the mean of two inputs τ apart vanishes.

    Two inputs that are one process met τ apart average to zero wherever one is
    half a period behind the other: ωτ = π, 3π, 5π … (the zeros of
    cos(ωτ/2) in :func:`delayed_mean_psd`). For axles a distance d apart at
    speed V, τ = d/V.

    Parameters
    ----------
    delay : float
        τ, s, > 0.
    count : int
        Number of frequencies, from 1 to 1_000_000 (a bound on the memory asked for).

    Returns
    -------
    ndarray, shape (count,)
        ω_j, rad/s, j = 0 … count − 1.

    Examples
    --------
    >>> np.round(cancellation_frequencies(np.pi, 3), 12).tolist()
    [1.0, 3.0, 5.0]
    """
    tau = _checks.positive("delay", delay)
    n = _checks.integer("count", count, low=1, high=_MAX_COUNT)
    return (2 * np.arange(n) + 1) * np.pi / tau


# --------------------------------------------------------------------------- mean squares and moments


def _spectrum_grid(psd, omega, *, increasing=True, min_points=1) -> tuple[np.ndarray, np.ndarray]:
    """Check a one-sided PSD on its frequency grid: same 1-D length, finite, >= 0."""
    w = _checks.array("omega", omega, ndim=1, low=0.0)
    S = _checks.array("psd", psd, ndim=1)
    if S.shape != w.shape:
        raise ValueError(f"psd and omega must have the same length, got psd {S.shape} and omega {w.shape}")
    if w.size < min_points:
        raise ValueError(f"omega must hold at least {min_points} frequencies, got {w.size}")
    S = _checks.array("psd", S, low=0.0)
    if increasing and w.size > 1:
        _checks.increasing("omega", w)
    return S, w


def mean_square(psd, omega) -> float:
    """Mean square σ² = ∫ S(ω) dω of a zero-mean process, by the trapezoid rule.

    The integral runs over the given grid only: what lies outside it (the tail
    beyond its last frequency) is left out, so extend the grid until the tail is
    negligible.

    Parameters
    ----------
    psd : array_like, shape (n,)
        One-sided PSD >= 0 per rad/s (per rad/m in space).
    omega : array_like, shape (n,)
        Frequencies >= 0, strictly increasing, rad/s (rad/m), n >= 2.

    Returns
    -------
    float
        Mean square, in (quantity)².

    Examples
    --------
    >>> mean_square([2.0, 2.0], [1.0, 4.0])
    6.0
    """
    S, w = _spectrum_grid(psd, omega, min_points=2)
    with np.errstate(over="ignore", invalid="ignore"):
        return float(_finite(np.trapezoid(S, w), "psd and omega", "a mean square"))


def rms(psd, omega) -> float:
    """Root mean square √(∫ S dω) of a zero-mean process (see :func:`mean_square`).

    Parameters
    ----------
    psd : array_like, shape (n,)
        One-sided PSD >= 0 per rad/s (per rad/m in space).
    omega : array_like, shape (n,)
        Frequencies >= 0, strictly increasing, rad/s (rad/m), n >= 2.

    Returns
    -------
    float
        RMS, in the unit of the quantity.

    Examples
    --------
    >>> rms([2.0, 2.0], [1.0, 3.0])
    2.0
    """
    return float(np.sqrt(mean_square(psd, omega)))


def spectral_moments(psd, omega, orders=(0, 2, 4)) -> np.ndarray:
    """Spectral moments m_k = ∫ ω^k S(ω) dω (trapezoid rule over the grid).

    m₀ is the mean square of the process, m₂ that of its derivative and m₄ that
    of its second derivative (Newland 1993, ch. 8).

    Parameters
    ----------
    psd, omega : array_like, shape (n,)
        As for :func:`mean_square`.
    orders : sequence of float
        Orders k >= 0, at least one.

    Returns
    -------
    ndarray, shape (len(orders),)
        m_k for each order, in the order given; m_k in (quantity)²·(rad/s)^k.

    Examples
    --------
    >>> spectral_moments([1.0, 1.0], [0.0, 1.0], orders=(0, 1))
    array([1. , 0.5])
    """
    S, w = _spectrum_grid(psd, omega, min_points=2)
    k = _checks.array("orders", orders, ndim=1, low=0.0, allow_empty=False)
    with np.errstate(over="ignore", invalid="ignore"):
        out = np.trapezoid(w ** k[:, None] * S, w, axis=-1)
    return _finite(out, "orders, omega and psd", "spectral moments")


def zero_upcrossing_rate(psd, omega) -> float:
    """Expected rate of zero up-crossings ν₀⁺ = (1/2π) √(m₂/m₀) of a Gaussian process.

    Rice's formula (Rice 1944; Newland 1993, ch. 8). For a PSD per rad/s the
    result is in crossings per second; per rad/m, crossings per metre.

    Parameters
    ----------
    psd : array_like, shape (n,)
        One-sided PSD >= 0 per rad/s (per rad/m).
    omega : array_like, shape (n,)
        Frequencies >= 0, strictly increasing, rad/s (rad/m), n >= 2.

    Returns
    -------
    float
        ν₀⁺, 1/s (1/m in space).

    Examples
    --------
    A narrow band at ω = 2π rad/s crosses zero upwards about once a second:

    >>> w = np.linspace(6.2, 6.36, 201)
    >>> round(zero_upcrossing_rate(np.ones(w.size), w), 3)
    1.0
    """
    m0, m2 = spectral_moments(psd, omega, orders=(0, 2))
    if m0 <= 0:
        raise ValueError(
            "psd must not be zero everywhere: the mean square m0 is 0, so no crossing rate exists"
        )
    return float(np.sqrt(m2 / m0) / (2.0 * np.pi))


def peak_rate(psd, omega) -> float:
    """Expected rate of maxima ν_p = (1/2π) √(m₄/m₂) of a Gaussian process (Rice 1945; Newland 1993, ch. 8).

    Parameters
    ----------
    psd : array_like, shape (n,)
        One-sided PSD >= 0 per rad/s (per rad/m).
    omega : array_like, shape (n,)
        Frequencies >= 0, strictly increasing, rad/s (rad/m), n >= 2.

    Returns
    -------
    float
        ν_p, 1/s for a PSD per rad/s, 1/m for one per rad/m.

    Examples
    --------
    >>> w = np.linspace(6.2, 6.36, 201)
    >>> round(peak_rate(np.ones(w.size), w), 3)
    1.0
    """
    m2, m4 = spectral_moments(psd, omega, orders=(2, 4))
    if m2 <= 0:
        raise ValueError("psd must not vanish at every omega > 0: m2 is 0, so no peak rate exists")
    return float(np.sqrt(m4 / m2) / (2.0 * np.pi))


def irregularity_factor(psd, omega) -> float:
    """Irregularity factor α = ν₀⁺/ν_p = m₂/√(m₀ m₄), between 0 and 1.

    The ratio of zero up-crossings to maxima: α → 1 for a narrow-band process
    (one peak per crossing), α → 0 for a broad-band one (Rice 1945; Newland 1993,
    ch. 8).

    Parameters
    ----------
    psd : array_like, shape (n,)
        One-sided PSD >= 0 per rad/s (per rad/m).
    omega : array_like, shape (n,)
        Frequencies >= 0, strictly increasing, rad/s (rad/m), n >= 2.

    Returns
    -------
    float
        α, dimensionless.

    Examples
    --------
    >>> w = np.linspace(6.2, 6.36, 201)
    >>> round(irregularity_factor(np.ones(w.size), w), 3)  # narrow band: α close to 1
    1.0
    """
    m0, m2, m4 = spectral_moments(psd, omega, orders=(0, 2, 4))
    if m0 <= 0 or m4 <= 0:
        raise ValueError("psd must not vanish at every omega > 0: m0 or m4 is 0, so the factor is undefined")
    return float(m2 / np.sqrt(m0 * m4))


def sdof_white_noise_mean_square(mass, damping, stiffness, psd_level, sided="one") -> float:
    """Mean square displacement of m x'' + c x' + k x = F(t) under white-noise force F.

    For a two-sided force PSD S₀ per rad/s, σ_x² = π S₀/(k c) (Crandall & Mark
    1963; Newland 1993, ch. 7); with the one-sided level G₀ = 2 S₀ of the raildyn
    convention, σ_x² = π G₀/(2 k c). The mass drops out, but is still checked.

    Parameters
    ----------
    mass : float
        m > 0, kg.
    damping : float
        c > 0, N·s/m (undamped, the mean square is unbounded).
    stiffness : float
        k > 0, N/m.
    psd_level : float
        White force PSD level >= 0, N²/(rad/s), in the form ``sided``.
    sided : {"one", "two"}
        Whether ``psd_level`` is one-sided (G₀) or two-sided (S₀).

    Returns
    -------
    float
        σ_x², m².

    Examples
    --------
    >>> sdof_white_noise_mean_square(1.0, 2.0, 4.0, 16.0 / np.pi)
    1.0
    """
    _checks.positive("mass", mass)
    c = _checks.positive("damping", damping)
    k = _checks.positive("stiffness", stiffness)
    level = _checks.nonnegative("psd_level", psd_level)
    sided = _checks.choice("sided", sided, _SIDED)
    two = 1.0 if sided == "two" else 2.0
    with np.errstate(over="ignore"):
        return float(_finite(np.pi * np.float64(level) / (two * k) / c, "psd_level, stiffness and damping",
                             "a mean square"))  # fmt: skip


# --------------------------------------------------------------------------- sample functions


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
