"""What the one- and many-degree-of-freedom modules of :mod:`raildyn.vibration` share.

The domain limits every oscillator is held to (rates, counts, the phase of one time step), the
characteristic roots of eq. 1.9, the sign rule for mode shapes and the convolution of a response.
Kept apart so that ``sdof``, ``sdof_curves``, ``mdof`` and ``damped`` can all import it without
importing each other.
"""

from __future__ import annotations

import numpy as np

# The domain of an SDOF: k/m (= ω_n², (rad/s)²) within [1/_RATE, _RATE] and c/m (= 2ξω_n, 1/s) at
# most _RATE. Then ω_n, ξω_n and both roots stay below 1e300, inside floating point with room to
# spare, and the free response stays finite for every ξ (ξ = 1e200 included).
_RATE = 1e300


# At most this many maxima, peaks or frequencies in one call: a bound on the memory asked for.
_MAX_COUNT = 1_000_000


# The largest phase ω_n h (rad) of one time step in forced_response: beyond it the rounding of h
# alone (1e-16 of it) moves the phase by more than 1e-4 rad, and near 1e16 the one-step matrix
# exponential stops being finite.
_MAX_PHASE = 1e12


def _check_rates(stiffness_rate: float, damping_rate: float, stiffness_names: str, damping_names: str):
    """Refuse an SDOF outside its domain (see ``_RATE``), naming the parameters that set each rate."""
    if not (1.0 / _RATE <= stiffness_rate <= _RATE):
        raise ValueError(
            f"{stiffness_names} give omega_n^2 = k/m = {stiffness_rate:.4g} (rad/s)^2; raildyn takes "
            f"k/m in [1e-300, 1e300] (omega_n from 1e-150 to 1e150 rad/s) so that omega_n^2 and the "
            "roots stay inside floating point"
        )
    if not damping_rate <= _RATE:
        raise ValueError(
            f"{damping_names} give c/m = 2 xi omega_n = {damping_rate:.4g} 1/s; raildyn takes c/m "
            "<= 1e300 1/s so that the roots -xi omega_n ± ... stay inside floating point"
        )


def _one_minus_square(xi):
    """1 − ξ², written as (1 − ξ)(1 + ξ) so that it keeps its relative accuracy near ξ = 1."""
    return (1.0 - xi) * (1.0 + xi)


def _roots(natural_frequency: float, xi: np.ndarray) -> np.ndarray:
    """Roots s₁, s₂ = (−ξ ± √(ξ² − 1)) ω_n (eq. 1.9) for an array of ξ; shape (n, 2)."""
    wn = natural_frequency
    over = xi > 1.0
    wd = wn * np.sqrt(np.maximum(_one_minus_square(np.minimum(xi, 1.0)), 0.0))
    re = 0.0 - xi * wn  # +0.0, not −0.0, for an undamped system
    # Overdamped: s₂ = −ω_n g and s₁ = −ω_n/g with g = ξ + √(ξ − 1)√(ξ + 1) >= 1 (s₁ s₂ = ω_n²):
    # no cancellation in s₁ for large ξ, and no ξ² to overflow.
    g = np.where(over, xi + np.sqrt(np.maximum(xi - 1.0, 0.0)) * np.sqrt(xi + 1.0), 1.0)
    s1 = np.where(over, -wn / g, re + 1j * wd)
    s2 = np.where(over, -wn * g, re - 1j * wd)
    return np.stack([s1, s2], axis=-1)


def _reciprocal(numerator, denominator):
    """numerator/denominator, with a complex infinity where the denominator is exactly zero.

    Only an undamped system driven exactly at resonance meets a zero, and there
    the steady amplitude really is unbounded; returning inf avoids a NaN.
    """
    num = np.broadcast_to(np.asarray(numerator, dtype=complex), np.shape(denominator))
    out = np.full(np.shape(denominator), complex(np.inf, 0.0))
    np.divide(num, denominator, out=out, where=denominator != 0)
    return out


def _pivots(vectors: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Index arrays (rows, columns) of the entry of largest magnitude in each column.

    Ties within a relative 1e-8 (a symmetric chain has entries ±a) go to the
    first such row, so the sign or phase convention does not hang on rounding.
    """
    mag = np.abs(vectors)
    rows = np.argmax(mag >= (1.0 - 1e-8) * mag.max(axis=0), axis=0)
    return rows, np.arange(vectors.shape[1])


def _causal_convolution(samples: np.ndarray, kernel: np.ndarray) -> np.ndarray:
    """The first ``samples.size`` terms of the convolution Σ_j kernel[k − j] samples[j], by real FFT.

    numpy's FFT rather than ``scipy.signal.fftconvolve``, which computes the same sum the same way but
    costs its module's import, a second or more, on the first response of a session.
    """
    n = samples.size
    size = 1 << (2 * n - 2).bit_length()  # a power of two ≥ 2n − 1: no wrap-around
    product = np.fft.rfft(samples, size) * np.fft.rfft(kernel, size)
    return np.fft.irfft(product, size)[:n]
