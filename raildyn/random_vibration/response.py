"""The response of a linear system to random input: the response PSD through a frequency response,
several inputs a time delay apart (two axles on one track) through their cross-spectral matrix, the
frequencies such a delay cancels, and the closed-form mean square of an oscillator under white noise.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks
from raildyn.random_vibration._common import (
    _MAX_COUNT,
    _SIDED,
    _finite,
    _spectrum_grid,
)

__all__ = [
    "cancellation_frequencies",
    "delayed_input_csd",
    "delayed_mean_psd",
    "response_psd",
    "sdof_white_noise_mean_square",
]


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
            Sy = _without_cancellation_noise(Sy, np.einsum("ij,ijk,ik->i", abs(H), abs(S), abs(H)), q)
        else:
            Sy = H @ S @ np.conj(np.swapaxes(H, -1, -2))
            Sy = 0.5 * (Sy + np.conj(np.swapaxes(Sy, -1, -2)))
            scale = np.einsum("ipj,ijk,ipk->ip", abs(H), abs(S), abs(H))
            p = np.arange(H.shape[1])
            Sy[:, p, p] = _without_cancellation_noise(Sy[:, p, p].real, scale, q)  # the auto-spectra
    return _finite(Sy, "frf and input_psd", "a response PSD")


def _without_cancellation_noise(auto, scale, q: int):
    """An auto-spectrum with its rounding below zero set to zero.

    Inputs that are one process met with delays (:func:`delayed_input_csd`) make a rank-one
    cross-spectral matrix, and where the delays cancel (a wheelbase filter's node) the sum
    Σ_jk H_j S_jk conj(H_k) of terms of size ``scale`` is zero but for rounding, which can fall on either
    side of it. The sum of q² products errs by at most about 2q² ε·scale (each product and addition one
    rounding), so a negative value within 4q² ε·scale is that rounding and is set to zero; a larger
    negative value (a cross-spectral matrix that is not positive semi-definite) stays as it is.
    """
    noise = (auto < 0) & (auto >= -4 * q * q * np.finfo(float).eps * scale)
    return np.where(noise, 0.0, auto)


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
