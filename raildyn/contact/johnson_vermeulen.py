"""Johnson and Vermeulen's creep law for an elliptical contact, with its own creep coefficients.

:func:`johnson_vermeulen_coefficients` (from the complete elliptic integrals B, C and D of the
patch) and :func:`johnson_vermeulen`, the saturating law built on them. Sign convention and results
as in :mod:`raildyn.contact.kalker`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn.constants import STEEL_POISSON_RATIO, STEEL_SHEAR_MODULUS
from raildyn.contact.kalker import (
    CreepForces,
    _friction,
    _out,
    _poisson,
)

__all__ = [
    "JohnsonVermeulenCoefficients",
    "johnson_vermeulen",
    "johnson_vermeulen_coefficients",
]


@dataclass(frozen=True)
class JohnsonVermeulenCoefficients:
    """Vermeulen and Johnson's dimensionless creep coefficients C₁₁, C₂₂ of an elliptical contact.

    The creep coefficients of their theory are f₁₁ = G a b C₁₁ and f₂₂ = G a b C₂₂, as
    Kalker's; the numbers differ (:func:`johnson_vermeulen_coefficients`). Floats or arrays.
    """

    c11: np.ndarray | float
    c22: np.ndarray | float

    def __post_init__(self):
        _checks.fields(self)


# The power series of Johnson's B, C, D in m = e² (each × 2/π), used below m = 0.1 where the
# closed forms in K and E lose digits to cancellation (C by about 1/m²): 40 terms leave 1e-40.
_SERIES_TERMS = 40


_SERIES_BELOW = 0.1


_A = np.cumprod(
    np.concatenate([[1.0], ((np.arange(1, _SERIES_TERMS + 2) - 0.5) / np.arange(1, _SERIES_TERMS + 2)) ** 2])
)


_N = np.arange(1, _SERIES_TERMS + 2)


_SERIES_D = _A[1:] * 2 * _N / (2 * _N - 1)  # D = (π/2) Σ_{n≥1} a_n 2n/(2n − 1) m^{n−1}, a_n = ((1/2)_n/n!)²


_SERIES_K = _A[:-1]  # K = (π/2) Σ_{n≥0} a_n m^n


_SERIES_C = 2 * _SERIES_D[1:] - _SERIES_K[1:]  # C = (2D − K)/m


def _elliptic_bcd(m: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Johnson's complete elliptic integrals B, C, D of the parameter m = e² ∈ [0, 1).

    B = ∫₀^{π/2} cos²φ/Δ dφ, C = ∫₀^{π/2} sin²φ cos²φ/Δ³ dφ, D = ∫₀^{π/2} sin²φ/Δ dφ with
    Δ = √(1 − m sin²φ); in Legendre's K, E: D = (K − E)/m, B = K − D, C = (D − B)/m
    (Johnson 1985, §3.5 and §7.3 use them for elliptical contacts).
    """
    from scipy import special

    m = np.asarray(m, dtype=float)
    small = m < _SERIES_BELOW
    ms = np.where(small, m, 0.0)
    k = special.ellipk(m)
    d = np.where(small, 0.5 * np.pi * np.polyval(_SERIES_D[::-1][-_SERIES_TERMS:], ms), 0.0)
    c = np.where(small, 0.5 * np.pi * np.polyval(_SERIES_C[::-1][-_SERIES_TERMS:], ms), 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        d_big = (k - special.ellipe(m)) / m
        c_big = (2.0 * d_big - k) / m
    d = np.where(small, d, d_big)
    c = np.where(small, c, c_big)
    return k - d, c, d


_JV_RATIO = (1e-3, 1e3)  # a/b: 0.1 to 10 in practice; the theory's formulas hold for any ellipse


def johnson_vermeulen_coefficients(a_over_b, poisson_ratio) -> JohnsonVermeulenCoefficients:
    """Creep coefficients C₁₁, C₂₂ of Vermeulen and Johnson's theory for an elliptical contact.

    Vermeulen and Johnson (1964) take the adhesion area to be an ellipse similar to the contact
    ellipse, touching it at the leading edge, and the traction to be the difference of two
    Hertz-shaped (semi-ellipsoidal) distributions over the two ellipses. The surface
    displacement of such a traction (Cerruti's solution) is quadratic inside the ellipse, so
    the no-slip condition holds everywhere in the adhesion area, and the creepage at vanishing
    force gives f_ii = G a b C_ii with C_ii = π/c_i, where, with Johnson's elliptic integrals
    B = ∫cos²φ/Δ dφ, C = ∫sin²φ cos²φ/Δ³ dφ, D = ∫sin²φ/Δ dφ (over [0, π/2], Δ = √(1 − e² sin²φ);
    D = (K − E)/e², B = K − D, C = (D − B)/e² in Legendre's K, E) of e² = 1 − (minor/major)²:

    * a ≤ b (g = a/b): c₁ = B − ν(D − C), c₂ = (1 − ν)B + ν(D − C);
    * a ≥ b (g = b/a): c₁ = g[(1 − ν)D + νC], c₂ = g(D − νC).

    For a circle (B = D = π/4, C = π/16) these are C₁₁ = 16/(4 − 3ν), C₂₂ = 16/(4 − ν), the
    slopes of Johnson's (1958) rolling sphere; they exceed Kalker's exact C₁₁, C₂₂ by 15 to
    23 % for a circle (ν = 0.25: 4.92 against 4.12, 4.27 against 3.67) and by up to 27 % for
    the narrow ellipses of Kalker's table (a/b = 0.1).

    Parameters
    ----------
    a_over_b : float or array_like
        a/b, with a the semi-axis in the rolling direction; 1e-3 ≤ a/b ≤ 1e3.
    poisson_ratio : float
        ν in [0, 0.5].

    Returns
    -------
    JohnsonVermeulenCoefficients

    Examples
    --------
    >>> c = johnson_vermeulen_coefficients(1.0, 0.25)  # 16/3.25 and 16/3.75
    >>> round(float(c.c11), 6), round(float(c.c22), 6)
    (4.923077, 4.266667)
    """
    ratio = _checks.array("a_over_b", a_over_b, low=0.0, low_open=True)
    if np.any(ratio < _JV_RATIO[0]) or np.any(ratio > _JV_RATIO[1]):
        bad = ratio[(ratio < _JV_RATIO[0]) | (ratio > _JV_RATIO[1])].flat[0]
        raise ValueError(
            f"a_over_b must be in [{_JV_RATIO[0]}, {_JV_RATIO[1]}] (an elliptical contact), got {bad!r}"
        )
    nu = _poisson(poisson_ratio)
    g = np.where(ratio <= 1.0, ratio, 1.0 / ratio)
    b_, c_, d_ = _elliptic_bcd(1.0 - g * g)
    c1 = np.where(ratio <= 1.0, b_ - nu * (d_ - c_), g * ((1.0 - nu) * d_ + nu * c_))
    c2 = np.where(ratio <= 1.0, (1.0 - nu) * b_ + nu * (d_ - c_), g * (d_ - nu * c_))
    return JohnsonVermeulenCoefficients(c11=_out(np.pi / c1), c22=_out(np.pi / c2))


def johnson_vermeulen(
    longitudinal,
    lateral,
    normal_load,
    friction,
    a,
    b,
    shear_modulus=STEEL_SHEAR_MODULUS,
    poisson_ratio=STEEL_POISSON_RATIO,
) -> CreepForces:
    """Vermeulen and Johnson's creep law for an elliptical contact without spin (Vermeulen & Johnson 1964).

    With their own creep coefficients f₁₁ = G a b C₁₁, f₂₂ = G a b C₂₂
    (:func:`johnson_vermeulen_coefficients`, not Kalker's) and
    χ = √((f₁₁γ_x)² + (f₂₂γ_y)²)/(3μN), the adhesion ellipse shrinks to 1 − χ of the
    contact's size and the resultant is F = μN[1 − (1 − χ)³] for χ < 1, μN beyond (full
    sliding), directed along (f₁₁γ_x, f₂₂γ_y). At small creepage the forces are −f₁₁γ_x and
    −f₂₂γ_y with these coefficients, 15–23 % above Kalker's for a circle.

    The cubic in χ is, with F̂ = 3χ, Shen, Hedrick and Elkins's F̂ − F̂²/3 + F̂³/27: their law
    (:func:`~raildyn.contact.saturation.shen_hedrick_elkins`) applies this saturation to Kalker's
    linear forces, spin included, so the two differ at zero spin only through the creep coefficients.

    Parameters
    ----------
    longitudinal, lateral : float or array_like
        Creepages γ_x, γ_y (dimensionless).
    normal_load : float
        N (N), in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_load").
    friction : float
        μ, in (0, 1] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "friction").
    a, b : float
        Semi-axes of the contact ellipse (m), in the rolling and lateral directions, each in
        [1e-5, 0.05] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "contact_semi_axis"), with
        1e-3 ≤ a/b ≤ 1e3.
    shear_modulus, poisson_ratio : float
        G (Pa) and ν; the steel of :mod:`raildyn.constants` by default.

    Returns
    -------
    CreepForces
        ``mz`` is None (the theory has no spin).

    Examples
    --------
    >>> round(johnson_vermeulen(0.5, 0.0, 1e5, 0.3, 6e-3, 4e-3).fx, 6)  # saturated: μN
    -30000.0
    >>> f = johnson_vermeulen(1e-7, 0.0, 1e5, 0.3, 6e-3, 6e-3, 8.1e10, 0.25).fx  # slope G a² 16/(4 − 3ν)
    >>> round(-f / 1e-7 / (8.1e10 * 36e-6 * 16 / 3.25), 4)
    1.0
    """
    xi = _checks.array("longitudinal", longitudinal, allow_empty=False)
    eta = _checks.array("lateral", lateral, allow_empty=False)
    n = _checks.plausible("normal_load", normal_load, "wheel_load")
    mu = _friction(friction)
    a = _checks.plausible("a", a, "contact_semi_axis")
    b = _checks.plausible("b", b, "contact_semi_axis")
    g_mod = _checks.positive("shear_modulus", shear_modulus)
    if not _JV_RATIO[0] <= a / b <= _JV_RATIO[1]:
        raise ValueError(
            f"a/b must be in [{_JV_RATIO[0]}, {_JV_RATIO[1]}] (an elliptical contact), "
            f"got a = {a!r} m and b = {b!r} m"
        )
    c = johnson_vermeulen_coefficients(a / b, poisson_ratio)
    lin_x = g_mod * a * b * c.c11 * xi
    lin_y = g_mod * a * b * c.c22 * eta
    chi = np.hypot(lin_x, lin_y) / (3 * mu * n)
    sat = 1.0 - (1.0 - np.minimum(chi, 1.0)) ** 3
    safe = np.where(chi > 0, chi, 1.0)
    scale = np.where(chi > 0, sat / (3 * safe), 1.0)  # F/(3μNχ) → 1 as χ → 0
    return CreepForces(fx=_out(-scale * lin_x), fy=_out(-scale * lin_y))
