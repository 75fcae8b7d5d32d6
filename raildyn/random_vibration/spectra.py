"""Properties of one power spectral density: its conversion between conventions, mean square
and RMS, spectral moments, zero-upcrossing and peak rates, and the irregularity factor.

Every PSD is one-sided per rad/s (per rad/m in space), the convention the package docstring of
:mod:`raildyn.random_vibration` sets out; :func:`~raildyn.random_vibration.convert_psd` brings other
forms to it.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks
from raildyn.random_vibration._common import (
    _CYCLIC_UNITS,
    _SIDED,
    _SPACE_UNITS,
    _TIME_UNITS,
    _finite,
    _spectrum_grid,
)

__all__ = [
    "convert_psd",
    "irregularity_factor",
    "mean_square",
    "peak_rate",
    "rms",
    "spectral_moments",
    "zero_upcrossing_rate",
]


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
