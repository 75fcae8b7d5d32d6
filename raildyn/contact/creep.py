"""Creepages and the creep-force laws of chapter 4: Kalker linear, Carter, Johnson–Vermeulen, SHE, Polach.

Sign convention (Kalker; Garg & Dukkipati ch. 4): the creepages γ_x (longitudinal),
γ_y (lateral) and φ (spin, 1/m) are the rigid slip of the wheel over the rail
divided by the rolling speed; the forces are those of the rail on the wheel, so
at small creepage

    Fx = −f₁₁ γ_x,   Fy = −f₂₂ γ_y − f₂₃ φ,   Mz = f₂₃ γ_y − f₃₃ φ.

Every law here takes numbers or numpy arrays (broadcast together) and returns a
:class:`CreepForces`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn.constants import STEEL_POISSON_RATIO, STEEL_SHEAR_MODULUS

__all__ = [
    "KALKER_NU",
    "POLACH_DRY",
    "POLACH_WET",
    "CreepCoefficients",
    "CreepForces",
    "JohnsonVermeulenCoefficients",
    "KalkerCoefficients",
    "PolachAdhesion",
    "WheelsetCreepages",
    "carter",
    "carter_coefficient",
    "creep_coefficients",
    "johnson_vermeulen",
    "johnson_vermeulen_coefficients",
    "kalker_coefficients",
    "kalker_linear",
    "polach",
    "polach_adhesion",
    "saturation_factor",
    "shen_hedrick_elkins",
    "wheelset_creepages",
]

# fmt: off
# Kalker's coefficients C_ij of the linear theory for an elliptical contact,
# Kalker (1967) as tabulated in Kalker (1990), Table E.3, reproduced in Garg &
# Dukkipati (1984) ch. 4 and Iwnicki (2006) ch. 7. Rows: g = a/b (first block,
# a ≤ b) or g = b/a (second block, a ≥ b) = 0.1, 0.2, …, 1.0; within each row
# C11, C22, C23, C33, each for ν = 0, 0.25, 0.5. The C11, C22 and C23 columns
# were checked digit by digit against the transcription in Vollebregt's CONTACT
# code (m_hertz.f90, routine linrol, "Table E.3 of Kalker 1990").
_G = np.arange(1, 11) / 10.0
_KALKER_A_LE_B = np.array([
    # C11 ν=0,.25,.5      C22                  C23                    C33
    [2.51, 3.31, 4.85,   2.51, 2.52, 2.53,   0.334, 0.473, 0.731,   6.42, 8.28, 11.7],   # a/b = 0.1
    [2.59, 3.37, 4.81,   2.59, 2.63, 2.66,   0.483, 0.603, 0.809,   3.46, 4.27, 5.66],   # 0.2
    [2.68, 3.44, 4.80,   2.68, 2.75, 2.81,   0.607, 0.715, 0.889,   2.49, 2.96, 3.72],   # 0.3
    [2.78, 3.53, 4.82,   2.78, 2.88, 2.98,   0.720, 0.823, 0.977,   2.02, 2.32, 2.77],   # 0.4
    [2.88, 3.62, 4.83,   2.88, 3.01, 3.14,   0.827, 0.929, 1.07,    1.74, 1.93, 2.22],   # 0.5
    [2.98, 3.72, 4.91,   2.98, 3.14, 3.31,   0.930, 1.03, 1.18,     1.56, 1.68, 1.86],   # 0.6
    [3.09, 3.81, 4.97,   3.09, 3.28, 3.48,   1.03, 1.14, 1.29,      1.43, 1.50, 1.60],   # 0.7
    [3.19, 3.91, 5.05,   3.19, 3.41, 3.65,   1.13, 1.25, 1.40,      1.34, 1.37, 1.42],   # 0.8
    [3.29, 4.01, 5.12,   3.29, 3.54, 3.82,   1.23, 1.36, 1.51,      1.27, 1.27, 1.27],   # 0.9
    [3.40, 4.12, 5.20,   3.40, 3.67, 3.98,   1.33, 1.47, 1.63,      1.21, 1.19, 1.16],   # 1.0
])
_KALKER_A_GE_B = np.array([
    [10.7, 11.7, 12.9,   10.7, 12.8, 16.0,   12.2, 14.6, 18.0,      0.795, 0.526, 0.228],  # b/a = 0.1
    [6.96, 7.78, 8.82,   6.96, 8.14, 9.79,   5.72, 6.63, 7.89,      0.828, 0.601, 0.341],  # 0.2
    [5.57, 6.34, 7.34,   5.57, 6.40, 7.51,   3.79, 4.32, 5.01,      0.868, 0.674, 0.446],  # 0.3
    [4.84, 5.57, 6.57,   4.84, 5.48, 6.31,   2.88, 3.24, 3.70,      0.912, 0.747, 0.549],  # 0.4
    [4.37, 5.10, 6.11,   4.37, 4.90, 5.56,   2.35, 2.62, 2.96,      0.958, 0.819, 0.650],  # 0.5
    [4.06, 4.78, 5.80,   4.06, 4.50, 5.04,   2.01, 2.23, 2.50,      1.01, 0.892, 0.751],   # 0.6
    [3.82, 4.54, 5.58,   3.82, 4.21, 4.67,   1.76, 1.95, 2.18,      1.05, 0.965, 0.852],   # 0.7
    [3.65, 4.36, 5.42,   3.65, 3.99, 4.39,   1.58, 1.75, 1.94,      1.10, 1.04, 0.954],    # 0.8
    [3.51, 4.22, 5.30,   3.51, 3.81, 4.16,   1.44, 1.59, 1.77,      1.16, 1.11, 1.06],     # 0.9
    [3.40, 4.12, 5.20,   3.40, 3.67, 3.98,   1.33, 1.47, 1.63,      1.21, 1.19, 1.16],     # 1.0
])
# fmt: on
KALKER_NU = (0.0, 0.25, 0.5)
"""The Poisson ratios of the columns of Kalker's table."""


@dataclass(frozen=True)
class KalkerCoefficients:
    """Kalker's dimensionless coefficients C₁₁, C₂₂, C₂₃, C₃₃ (floats or arrays)."""

    c11: np.ndarray | float
    c22: np.ndarray | float
    c23: np.ndarray | float
    c33: np.ndarray | float

    def __post_init__(self):
        _checks.fields(self)


@dataclass(frozen=True)
class CreepCoefficients:
    """Kalker's creep coefficients of one contact.

    Each is a float, or an array (one value per contact) broadcasting with the creepages
    it multiplies; a list is stored as an array.

    Attributes
    ----------
    f11 : longitudinal, G a b C₁₁ (N), > 0
    f22 : lateral, G a b C₂₂ (N), > 0
    f23 : lateral/spin, G (ab)^{3/2} C₂₃ (N m), >= 0 (0 neglects the spin coupling)
    f33 : spin, G (ab)² C₃₃ (N m²), >= 0 (0 neglects the spin moment)
    """

    f11: np.ndarray | float
    f22: np.ndarray | float
    f23: np.ndarray | float
    f33: np.ndarray | float

    def __post_init__(self):
        for name, open_ in (("f11", True), ("f22", True), ("f23", False), ("f33", False)):
            value = _checks.array(name, getattr(self, name), low=0.0, low_open=open_, allow_empty=False)
            object.__setattr__(self, name, _out(value))


@dataclass(frozen=True)
class CreepForces:
    """Creep forces of the rail on the wheel in the contact plane.

    Attributes
    ----------
    fx : longitudinal force (N)
    fy : lateral force (N)
    mz : spin moment about the contact normal (N m); ``None`` for laws that give none
    """

    fx: np.ndarray | float
    fy: np.ndarray | float
    mz: np.ndarray | float | None = None

    def __post_init__(self):
        _checks.fields(self)

    @property
    def resultant(self):
        """√(Fx² + Fy²) (N)."""
        return np.hypot(self.fx, self.fy)


# Both blocks of the table, and the slopes np.interp would compute between their rows, so that
# kalker_coefficients interpolates all 12 columns after one search (3× faster for a batch).
_BLOCKS = np.stack([_KALKER_A_LE_B, _KALKER_A_GE_B])
_SLOPES = np.diff(_BLOCKS, axis=1) / np.diff(_G)[None, :, None]


def _out(value):
    """A 0-d array back to a float, so scalar calls give scalars."""
    arr = np.asarray(value)
    return float(arr) if arr.ndim == 0 else arr


def _poisson(poisson_ratio) -> float:
    return _checks.scalar("poisson_ratio", poisson_ratio, low=0.0, high=0.5)


def _friction(friction, name: str = "friction") -> float:
    return _checks.friction(name, friction)


def _coefficients(coefficients) -> CreepCoefficients:
    return _checks.instance("coefficients", coefficients, CreepCoefficients)


def _ratio(a, b) -> np.ndarray:
    """a/b of checked semi-axes, within Kalker's table (0.1 to 10): the message names a and b."""
    ratio = np.asarray(a / b)
    bad = (ratio < 0.1 - 1e-12) | (ratio > 10.0 + 1e-9)
    if np.any(bad):
        a_bad, b_bad = (float(np.broadcast_to(v, ratio.shape)[bad].flat[0]) for v in (a, b))
        raise ValueError(
            f"a/b must be in [0.1, 10] (the range of Kalker's table), got a = {a_bad!r} m and b = {b_bad!r} m"
        )
    return ratio


def kalker_coefficients(a_over_b, poisson_ratio) -> KalkerCoefficients:
    """Kalker's C₁₁, C₂₂, C₂₃, C₃₃ for an ellipse ratio a/b and Poisson ratio ν.

    Linear interpolation in g = a/b (a ≤ b) or g = b/a (a ≥ b) between the rows of
    Kalker's table, then quadratic (Lagrange) interpolation through ν = 0, 0.25,
    0.5. At the table points the table values are returned exactly.

    Parameters
    ----------
    a_over_b : float or array_like
        a/b, with a the semi-axis in the rolling direction; 0.1 ≤ a/b ≤ 10.
    poisson_ratio : float
        ν in [0, 0.5].

    Returns
    -------
    KalkerCoefficients

    Examples
    --------
    >>> c = kalker_coefficients(1.0, 0.25)
    >>> c.c11, c.c22, c.c23, c.c33
    (4.12, 3.67, 1.47, 1.19)
    """
    ratio = _checks.array("a_over_b", a_over_b)
    if np.any(ratio < 0.1 - 1e-12) or np.any(ratio > 10.0 + 1e-9):
        bad = ratio[(ratio < 0.1 - 1e-12) | (ratio > 10.0 + 1e-9)].flat[0]
        raise ValueError(f"a_over_b must be in [0.1, 10] (the range of Kalker's table), got {bad!r}")
    nu = _poisson(poisson_ratio)
    ratio = np.clip(ratio, 0.1, 10.0)
    g = np.where(ratio <= 1.0, ratio, 1.0 / ratio)
    # Interpolate every column along g in the right block of the table: np.interp's arithmetic,
    # slope × (g − g_j) + C_j, for all 12 columns after one search (the table's last row exactly).
    j = np.clip(np.searchsorted(_G, g, side="right") - 1, 0, _G.size - 2)
    block = (ratio > 1.0).astype(np.intp)
    rows = _SLOPES[block, j] * (g - _G[j])[..., None] + _BLOCKS[block, j]
    rows = np.where((g == _G[-1])[..., None], _BLOCKS[block, -1], rows).reshape(*ratio.shape, 4, 3)
    weights = np.array(
        [
            (nu - 0.25) * (nu - 0.5) / ((0.0 - 0.25) * (0.0 - 0.5)),
            (nu - 0.0) * (nu - 0.5) / ((0.25 - 0.0) * (0.25 - 0.5)),
            (nu - 0.0) * (nu - 0.25) / ((0.5 - 0.0) * (0.5 - 0.25)),
        ]
    )
    c = np.round(rows @ weights, 12)
    return KalkerCoefficients(*(_out(c[..., i]) for i in range(4)))


def creep_coefficients(
    a, b, shear_modulus=STEEL_SHEAR_MODULUS, poisson_ratio=STEEL_POISSON_RATIO
) -> CreepCoefficients:
    """Kalker's creep coefficients f₁₁, f₂₂, f₂₃, f₃₃ of a contact ellipse.

    f₁₁ = G a b C₁₁, f₂₂ = G a b C₂₂, f₂₃ = G (ab)^{3/2} C₂₃, f₃₃ = G (ab)² C₃₃
    (Kalker 1967; Garg & Dukkipati 1984, ch. 4).

    Parameters
    ----------
    a, b : float or array_like
        Semi-axes (m) in the rolling and lateral directions, each in [1e-5, 0.05]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "contact_semi_axis"), with
        0.1 ≤ a/b ≤ 10. Arrays broadcast together.
    shear_modulus : float
        G (Pa); default :data:`raildyn.constants.STEEL_SHEAR_MODULUS`, E/(2(1 + ν)) = 80.8 GPa.
    poisson_ratio : float
        ν in [0, 0.5]; default :data:`raildyn.constants.STEEL_POISSON_RATIO` (0.3).

    Returns
    -------
    CreepCoefficients
        Floats for scalar input, arrays of the broadcast shape otherwise.

    Examples
    --------
    With G = 81 GPa and ν = 0.25 (a circle, C₁₁ = 4.12 from Kalker's table):

    >>> f = creep_coefficients(6e-3, 6e-3, 8.1e10, 0.25)
    >>> round(f.f11 / 1e6, 3)  # MN
    12.014
    """
    a_arr = _checks.plausible_array("a", a, "contact_semi_axis")
    b_arr = _checks.plausible_array("b", b, "contact_semi_axis")
    g_mod = _checks.positive("shear_modulus", shear_modulus)
    a_arr, b_arr = np.broadcast_arrays(a_arr, b_arr)
    c = kalker_coefficients(_ratio(a_arr, b_arr), poisson_ratio)
    ab = a_arr * b_arr
    return CreepCoefficients(
        f11=_out(g_mod * ab * c.c11),
        f22=_out(g_mod * ab * c.c22),
        f23=_out(g_mod * ab**1.5 * c.c23),
        f33=_out(g_mod * ab**2 * c.c33),
    )


def kalker_linear(longitudinal, lateral, spin, coefficients: CreepCoefficients) -> CreepForces:
    """Kalker's linear theory: Fx = −f₁₁γ_x, Fy = −f₂₂γ_y − f₂₃φ, Mz = f₂₃γ_y − f₃₃φ.

    Parameters
    ----------
    longitudinal, lateral : float or array_like
        Creepages γ_x and γ_y (dimensionless).
    spin : float or array_like
        Spin creepage φ (1/m).
    coefficients : CreepCoefficients
        f₁₁, f₂₂, f₂₃, f₃₃ of the contact (:func:`creep_coefficients`).

    Returns
    -------
    CreepForces
        Unbounded: valid only while the creepages are small (no sliding).

    Examples
    --------
    >>> f = creep_coefficients(6e-3, 4e-3)
    >>> bool(kalker_linear(1e-3, 0.0, 0.0, f).fx == -f.f11 * 1e-3)
    True
    """
    xi = _checks.array("longitudinal", longitudinal, allow_empty=False)
    eta = _checks.array("lateral", lateral, allow_empty=False)
    phi = _checks.array("spin", spin, allow_empty=False)
    f = _coefficients(coefficients)
    return CreepForces(
        fx=_out(-f.f11 * xi + 0.0 * (eta + phi)),
        fy=_out(-f.f22 * eta - f.f23 * phi + 0.0 * xi),
        mz=_out(f.f23 * eta - f.f33 * phi + 0.0 * xi),
    )


def carter_coefficient(normal_load, wheel_radius, semi_axis):
    """Carter's longitudinal creep coefficient 2NR/a of a cylinder rolling on a plane (N).

    Parameters
    ----------
    normal_load : float
        N (N), in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_load").
    wheel_radius : float
        R (m), in [0.1, 1.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_radius").
    semi_axis : float
        Half-length a of the contact strip in the rolling direction (m), in [1e-5, 0.05]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "contact_semi_axis").

    Returns
    -------
    float
        dF/dγ_x at γ_x = 0, N.

    Examples
    --------
    >>> round(carter_coefficient(1e5, 0.46, 6e-3) / 1e6, 4)  # 2NR/a, MN
    15.3333
    """
    n = _checks.plausible("normal_load", normal_load, "wheel_load")
    r = _checks.plausible("wheel_radius", wheel_radius, "wheel_radius")
    a = _checks.plausible("semi_axis", semi_axis, "contact_semi_axis")
    return 2.0 * n * r / a


def carter(longitudinal, normal_load, friction, creep_coefficient):
    """Carter's two-dimensional theory: longitudinal creep force of a rolling cylinder.

    With χ = f γ_x/(2μN) and f the initial slope (Carter's 2NR/a_c, or Kalker's
    f₁₁ to compare shapes), F = −μN(2χ − χ|χ|) while |χ| < 1 and −μN sign(χ)
    beyond: the adhesion zone at the leading edge shrinks to nothing at |χ| = 1
    (Carter 1926; Garg & Dukkipati 1984, ch. 4; Johnson 1985, §8.2).

    Parameters
    ----------
    longitudinal : float or array_like
        Creepage γ_x.
    normal_load : float
        N (N), in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_load").
    friction : float
        Coefficient of friction μ, in (0, 1] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "friction").
    creep_coefficient : float
        Initial slope dF/dγ_x (N), > 0.

    Returns
    -------
    float or ndarray
        Fx (N).

    Examples
    --------
    Beyond u = 1 the whole patch slides and the force is μN:

    >>> carter(0.05, 1e5, 0.3, carter_coefficient(1e5, 0.46, 6e-3))
    -30000.0
    """
    xi = _checks.array("longitudinal", longitudinal, allow_empty=False)
    n = _checks.plausible("normal_load", normal_load, "wheel_load")
    mu = _friction(friction)
    f = _checks.positive("creep_coefficient", creep_coefficient)
    u = f * xi / (2 * mu * n)
    v = np.minimum(np.abs(u), 1.0)  # |u| ≥ 1: the whole patch slides, 2v − v² = 1
    mag = 2 * v - v**2
    return _out(-mu * n * np.sign(u) * mag)


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
    (:func:`shen_hedrick_elkins`) applies this saturation to Kalker's linear forces, spin
    included, so the two differ at zero spin only through the creep coefficients.

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


def saturation_factor(force, limit, *, check: bool = True) -> np.ndarray:
    """Shen–Hedrick–Elkins reduction of a linear creep force F towards μN (Shen et al. 1983): F_sat/F.

    With F̂ = F/(μN), F_sat = μN(F̂ − F̂²/3 + F̂³/27) for F̂ < 3 and μN beyond. The one
    statement of the law in raildyn: :func:`shen_hedrick_elkins` and the nonlinear
    wheelset (:func:`raildyn.wheelset.contact_forces`) both scale by it.

    Parameters
    ----------
    force : float or array_like
        Magnitude |F| of the linear (Kalker) force, N, >= 0.
    limit : float
        μN, N (> 0).
    check : bool
        Check the input (default); False for a caller that has (as :func:`wheelset_creepages`):
        then nothing is checked and bad input gives bad numbers.

    Returns
    -------
    ndarray
        F_sat/F, in (0, 1]; 1 where F = 0.

    Examples
    --------
    >>> float(saturation_factor(3.0e4, 1.0e4))  # F̂ = 3: fully saturated, F_sat = μN
    0.3333333333333333
    """
    if check is not False:
        _checks.flag("check", check)
        force, limit = (
            _checks.array("force", force, low=0.0, allow_empty=False),
            _checks.positive("limit", limit),
        )
    u = np.abs(force) / limit
    v = np.minimum(u, 3.0)  # u ≥ 3: saturated, v − v²/3 + v³/27 = 1 (and no overflow for a huge u)
    sat = v - v**2 / 3.0 + v**3 / 27.0
    return np.divide(sat, u, out=np.ones_like(u), where=u > 0)


def shen_hedrick_elkins(longitudinal, lateral, spin, normal_load, friction, coefficients: CreepCoefficients):
    """Kalker's linear forces bounded by the heuristic saturation of Shen, Hedrick and Elkins (1983).

    The linear forces include spin (Fy = −f₂₂γ_y − f₂₃φ). With F̂ = |F_lin|/(μN), the resultant
    √(Fx² + Fy²) becomes μN(F̂ − F̂²/3 + F̂³/27) for F̂ ≤ 3 and μN beyond; Fx, Fy and Mz are all
    scaled by the same factor. The cubic is Vermeulen and Johnson's 1 − (1 − F̂/3)³
    (:func:`johnson_vermeulen`), applied to Kalker's coefficients instead of theirs.

    Parameters
    ----------
    longitudinal, lateral : float or array_like
        Creepages γ_x, γ_y (dimensionless).
    spin : float or array_like
        φ (1/m).
    normal_load : float
        N (N), in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_load").
    friction : float
        μ, in (0, 1] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "friction").
    coefficients : CreepCoefficients
        Kalker's coefficients of the contact.

    Returns
    -------
    CreepForces
        Linear forces scaled to a resultant within μN.

    Examples
    --------
    At F̂ = 3 (the linear force three times μN) the curve meets μN:

    >>> f = creep_coefficients(6e-3, 4e-3)
    >>> round(shen_hedrick_elkins(3 * 30e3 / f.f11, 0.0, 0.0, 1e5, 0.3, f).fx, 6)
    -30000.0
    """
    n = _checks.plausible("normal_load", normal_load, "wheel_load")
    mu = _friction(friction)
    lin = kalker_linear(longitudinal, lateral, spin, coefficients)
    scale = saturation_factor(lin.resultant, mu * n)
    return CreepForces(
        fx=_out(scale * lin.fx),
        fy=_out(scale * lin.fy),
        mz=_out(scale * lin.mz),
    )


def polach(
    longitudinal,
    lateral,
    spin,
    normal_load,
    friction,
    a,
    b,
    shear_modulus=STEEL_SHEAR_MODULUS,
    poisson_ratio=STEEL_POISSON_RATIO,
    *,
    k_a: float = 1.0,
    k_s: float = 1.0,
) -> CreepForces:
    """Polach's fast creep-force method with spin (Polach 1999, 2000).

    The creep force from γ_x and γ_y is

        F = (2Qμ/π) [k_A ε/(1 + (k_A ε)²) + arctan(k_S ε)],
        ε = G π a b C_jj s_C /(4 Q μ),  C_jj = √((C₁₁ γ_x/s)² + (C₂₂ γ_y/s)²),

    shared as Fx = −F γ_x/s_C, Fy = −F γ_y/s_C, where s_C = √(γ_x² + γ_yC²) and
    γ_yC = γ_y + φa when that is larger in magnitude than γ_y (else γ_y); a, b are the semi-axes
    a_c, b_c of the contact ellipse (Polach's notation). Spin adds a
    lateral force F_yS = (9/16) a Q μ K_M [1 + 6.3(1 − e^{−a/b})] φ/s_C with
    K_M = |ε_M|(χ_M³/3 − χ_M²/2 + 1/6) − √((1 − χ_M²)³)/3, χ_M = (ε_M² − 1)/(ε_M² + 1),
    ε_M = (8/3) G b √(ab) C₂₃ s_C /(Q μ [1 + 6.3(1 − e^{−a/b})]).
    k_A = k_S = 1 is the original method; k_A, k_S < 1 reduce the initial slope
    as in Polach (2005).

    Parameters
    ----------
    longitudinal, lateral : float or array_like
        γ_x, γ_y.
    spin : float or array_like
        φ (1/m).
    normal_load : float
        Q (N), in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_load").
    friction : float
        μ, in (0, 1] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "friction").
    a, b : float
        Semi-axes of the contact ellipse (m), each in [1e-5, 0.05]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "contact_semi_axis": a few mm in service),
        with 0.1 ≤ a/b ≤ 10 (Kalker's table).
    shear_modulus, poisson_ratio : float
        G (Pa) and ν for Kalker's coefficients; the steel of :mod:`raildyn.constants` by default.
    k_a, k_s : float, keyword
        Reduction factors in (0, 1].

    Returns
    -------
    CreepForces
        ``mz`` is None (the method gives no spin moment).

    Examples
    --------
    >>> r = polach(1e-3, 0.0, 0.0, 1e5, 0.3, 6e-3, 4e-3)
    >>> bool(-0.3 * 1e5 < r.fx < 0.0), r.mz is None
    (True, True)
    """
    inputs = _polach_inputs(longitudinal, lateral, spin, normal_load, a, b, shear_modulus, poisson_ratio)
    mu = _friction(friction)
    k_a = _checks.scalar("k_a", k_a, low=0.0, high=1.0, low_open=True)
    k_s = _checks.scalar("k_s", k_s, low=0.0, high=1.0, low_open=True)
    return _polach(*inputs, mu, k_a, k_s)


def _polach_inputs(longitudinal, lateral, spin, normal_load, a, b, shear_modulus, poisson_ratio):
    """Checked (γ_x, γ_y, φ broadcast together, Q, a, b, G, Kalker's C) for Polach's method."""
    xi = _checks.array("longitudinal", longitudinal, allow_empty=False)
    eta = _checks.array("lateral", lateral, allow_empty=False)
    phi = _checks.array("spin", spin, allow_empty=False)
    q = _checks.plausible("normal_load", normal_load, "wheel_load")
    a = _checks.plausible("a", a, "contact_semi_axis")
    b = _checks.plausible("b", b, "contact_semi_axis")
    g_mod = _checks.positive("shear_modulus", shear_modulus)
    c = kalker_coefficients(_ratio(a, b), poisson_ratio)
    return (*np.broadcast_arrays(xi, eta, phi), q, a, b, g_mod, c)


_EPS_MAX = 1e100  # Polach's ε and ε_M beyond which the creep force is that of full slip to rounding


def _polach(xi, eta, phi, q, a, b, g_mod, c, mu, k_a, k_s) -> CreepForces:
    """Polach's method on checked input; ``mu`` may be an array broadcasting with the creepages."""
    eta_c = np.where(np.abs(eta + phi * a) > np.abs(eta), eta + phi * a, eta)
    s_c = np.hypot(xi, eta_c)
    s = np.hypot(xi, eta)
    safe_s = np.where(s > 0, s, 1.0)
    c_jj = np.where(s > 0, np.hypot(c.c11 * xi / safe_s, c.c22 * eta / safe_s), c.c22)
    # Past ε = 1e100 the force is the full-slip 2Qμ/π·π/2 to double precision: the cap keeps huge
    # creepages (or moduli) from overflowing to inf/inf.
    eps = np.minimum(g_mod * np.pi * a * b * c_jj * s_c / (4 * q * mu), _EPS_MAX)
    force = 2 * q * mu / np.pi * (k_a * eps / (1 + (k_a * eps) ** 2) + np.arctan(k_s * eps))
    safe_sc = np.where(s_c > 0, s_c, 1.0)
    k_m_factor = 1 + 6.3 * (1 - np.exp(-a / b))
    # ε_M grows with the whole creepage s_C (not with |γ_yC| alone): then for small creepage
    # the spin force is Kalker's −f₂₃φ whatever γ_x is (tests/test_contact_creep.py).
    eps_m = np.minimum(8.0 / 3.0 * g_mod * b * np.sqrt(a * b) * c.c23 * s_c / (q * mu * k_m_factor), _EPS_MAX)
    # Polach's K_M = |ε_M|(χ³/3 − χ²/2 + 1/6) − √((1 − χ²)³)/3 with χ = (ε_M² − 1)/(ε_M² + 1) is, exactly,
    # −(2/3)|ε_M|/(1 + ε_M²)²: the same numbers without the cancellation that the first form suffers
    # at large ε_M (and its inf/inf once ε_M² overflows).
    k_m = -2.0 / 3.0 * eps_m / (1 + eps_m**2) / (1 + eps_m**2)
    fy_spin = 9 / 16 * a * q * mu * k_m * k_m_factor * phi / safe_sc
    fx = np.where(s_c > 0, -force * xi / safe_sc, 0.0)
    fy = np.where(s_c > 0, -force * eta / safe_sc + fy_spin, 0.0)
    return CreepForces(fx=_out(fx), fy=_out(fy))


@dataclass(frozen=True)
class PolachAdhesion:
    """Wheel–rail conditions for Polach's (2005) method near the adhesion limit.

    Friction falls with the slip speed w (m/s) as ``μ = μ₀[(1 − A) e^{−Bw} + A]``, and
    the reduction factors ``k_A`` (adhesion zone) and ``k_S`` (slip zone) lower the
    initial slope of the creep-force curve, which Kalker's theory overestimates on
    real, contaminated rails (Polach 2005).

    Attributes
    ----------
    k_a, k_s : float
        Reduction factors in (0, 1].
    static_friction : float
        μ₀ at zero slip speed (> 0).
    limit_ratio : float
        A = μ∞/μ₀ in (0, 1].
    decay_rate : float
        B, s/m (>= 0).
    """

    k_a: float
    k_s: float
    static_friction: float
    limit_ratio: float
    decay_rate: float

    def __post_init__(self):
        _checks.scalar("k_a", self.k_a, low=0.0, high=1.0, low_open=True)
        _checks.scalar("k_s", self.k_s, low=0.0, high=1.0, low_open=True)
        _friction(self.static_friction, "static_friction")
        _checks.scalar("limit_ratio", self.limit_ratio, low=0.0, high=1.0, low_open=True)
        _checks.nonnegative("decay_rate", self.decay_rate)

    def friction(self, slip_speed):
        """Coefficient of friction μ = μ₀[(1 − A) e^{−Bw} + A] at a slip speed w.

        Parameters
        ----------
        slip_speed : float or array_like
            w, m/s, each in [0, :data:`~raildyn.constants.MAXIMUM_SPEED`] (any shape).

        Returns
        -------
        float or ndarray
            μ, dimensionless.

        Examples
        --------
        >>> POLACH_DRY.friction(0.0), round(POLACH_DRY.friction(100.0), 6)
        (0.55, 0.22)
        """
        return _out(self._mu(_checks.plausible_array("slip_speed", slip_speed, "speed", low=0.0)))

    def _mu(self, w):
        """μ at slip speeds w ≥ 0 already checked (polach_adhesion's, which grow with the creepages)."""
        a = self.limit_ratio
        return self.static_friction * ((1 - a) * np.exp(-self.decay_rate * w) + a)


# Polach (2005), Table 2: the parameters fitted to measured adhesion of locomotives on dry and
# on wet rail (values as transcribed in the RailBreak repository, tools/eval/plant_ref.py, and
# reproduced by the parameter formulas of Open Rails' Axle.cs at μ₀ = 0.55 and 0.30).
POLACH_DRY = PolachAdhesion(k_a=1.0, k_s=0.4, static_friction=0.55, limit_ratio=0.4, decay_rate=0.6)
"""Dry rail (Polach 2005, Table 2)."""
POLACH_WET = PolachAdhesion(k_a=0.3, k_s=0.1, static_friction=0.30, limit_ratio=0.4, decay_rate=0.2)
"""Wet rail (Polach 2005, Table 2)."""


def polach_adhesion(
    longitudinal,
    lateral,
    spin,
    normal_load,
    speed,
    a,
    b,
    conditions: PolachAdhesion = POLACH_DRY,
    shear_modulus=STEEL_SHEAR_MODULUS,
    poisson_ratio=STEEL_POISSON_RATIO,
) -> CreepForces:
    """Polach's (2005) creep forces near the adhesion limit: friction falling with slip speed.

    As :func:`polach`, with ``μ = conditions.friction(w)`` at the slip speed
    ``w = V √(γ_x² + γ_y²)`` and the reduction factors of ``conditions``. Beyond the
    adhesion peak the force falls as the creepage grows, the behaviour that wheel-slip
    control of a locomotive has to live with.

    Parameters
    ----------
    longitudinal, lateral, spin : float or array_like
        γ_x, γ_y, φ (1/m).
    normal_load : float
        Q (N), in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_load").
    speed : float
        Rolling speed V (m/s), in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    a, b : float
        Semi-axes of the contact ellipse (m), each in [1e-5, 0.05]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "contact_semi_axis": a few mm in service),
        with 0.1 ≤ a/b ≤ 10 (Kalker's table).
    conditions : PolachAdhesion
        :data:`POLACH_DRY` (default) or :data:`POLACH_WET`, or your own.
    shear_modulus, poisson_ratio : float
        G (Pa) and ν; the steel of :mod:`raildyn.constants` by default.

    Returns
    -------
    CreepForces
        ``mz`` is None.

    Examples
    --------
    Past the adhesion peak the force falls as the creepage grows:

    >>> fx = polach_adhesion(np.array([0.01, 0.2]), 0.0, 0.0, 1e5, 20.0, 6e-3, 4e-3).fx
    >>> bool(-fx[1] < -fx[0])
    True
    """
    _checks.instance("conditions", conditions, PolachAdhesion)
    inputs = _polach_inputs(longitudinal, lateral, spin, normal_load, a, b, shear_modulus, poisson_ratio)
    v = _checks.speed("speed", speed)
    xi, eta = inputs[:2]
    mu = np.asarray(conditions._mu(v * np.hypot(xi, eta)))
    return _polach(*inputs, mu, conditions.k_a, conditions.k_s)


@dataclass(frozen=True)
class WheelsetCreepages:
    """Creepages at the two contacts of a wheelset; index 0 is the left wheel, 1 the right.

    Attributes
    ----------
    longitudinal : ndarray, shape (2, ...)
        γ_x at the left and right contacts.
    lateral : ndarray, shape (2, ...)
        γ_y (the same at both wheels in this kinematic form).
    spin : ndarray, shape (2, ...)
        φ (1/m).

    The three arrays are finite and of one shape (2, ...).
    """

    longitudinal: np.ndarray
    lateral: np.ndarray
    spin: np.ndarray

    def __post_init__(self):
        _checks.fields(self)
        shape = np.shape(self.longitudinal)
        for name in ("longitudinal", "lateral", "spin"):
            value = np.asarray(getattr(self, name), dtype=float)
            if value.ndim == 0 or value.shape[0] != 2 or value.shape != shape:
                raise ValueError(
                    f"{name} must have the shape (2, ...) of longitudinal (left, right), "
                    f"{shape}, got shape {value.shape}"
                )
            object.__setattr__(self, name, value)


def _unchecked_creepages(longitudinal, lateral, spin) -> WheelsetCreepages:
    """A :class:`WheelsetCreepages` built without its check, for the unchecked path (a right-hand side)."""
    out = object.__new__(WheelsetCreepages)
    object.__setattr__(out, "longitudinal", longitudinal)
    object.__setattr__(out, "lateral", lateral)
    object.__setattr__(out, "spin", spin)
    return out


def wheelset_creepages(
    speed,
    lateral_velocity,
    yaw_angle,
    yaw_rate,
    rolling_radius_left,
    rolling_radius_right,
    nominal_radius,
    half_gauge,
    contact_angle_left=0.0,
    contact_angle_right=0.0,
    *,
    check: bool = True,
) -> WheelsetCreepages:
    """Creepages of a wheelset on straight track (Garg & Dukkipati 1984, ch. 4–5).

    The wheelset runs at ``speed`` V and turns about its axle at Ω = V/r₀, the angular
    speed of its nominal rolling radius; y is positive to the left, the yaw ψ positive
    anticlockwise seen from above, the contact angles ϑ positive when the contact moves
    towards the flange. Each creepage is a slip velocity of the contact point divided by
    V, so all three share the one radius that sets Ω, the nominal r₀: the rolling radius
    r_L or r_R enters only through the rim's speed Ω r in γ_x, and the spin is the angular
    velocity about the contact normal, ψ̇ cos ϑ ∓ Ω sin ϑ, over V. With a the half
    distance between the contacts,

        γ_x,L = (r₀ − r_L)/r₀ − a ψ̇/V,            γ_x,R = (r₀ − r_R)/r₀ + a ψ̇/V,
        γ_y   = ẏ/V − ψ,
        φ_L = ψ̇ cos ϑ_L / V − sin ϑ_L / r₀,     φ_R = ψ̇ cos ϑ_R / V + sin ϑ_R / r₀

    (Kalker 1967; :func:`raildyn.derivations.contact.creepages` derives them from the
    velocities of the contact points). The cos ϑ matters at a steep contact: on a flange
    at 70° the yaw rate gives only a third of the spin it gives on the tread.

    Parameters
    ----------
    speed : float
        V (m/s), in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    lateral_velocity, yaw_angle, yaw_rate : float or array_like
        ẏ (m/s), ψ (rad), ψ̇ (rad/s).
    rolling_radius_left, rolling_radius_right : float or array_like
        r_L, r_R at the current contacts (m), each in [0.1, 1.5]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_radius"),
        e.g. r₀ ± Δr(y)/2.
    nominal_radius : float
        r₀ (m), in [0.1, 1.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_radius").
    half_gauge : float
        a (m), half the lateral distance between the contact points, in [0.15, 1.1]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "half_gauge").
    contact_angle_left, contact_angle_right : float or array_like
        ϑ_L, ϑ_R (rad), within ±π/2.
    check : bool
        Check the input and the result (default). A caller that has checked it already, such as
        the right-hand side of :class:`raildyn.wheelset.NonlinearLateral` evaluated
        thousands of times a run, passes False: bad input then gives bad numbers.

    Returns
    -------
    WheelsetCreepages
        γ_x, γ_y, φ at the left (index 0) and right (index 1) contacts.

    Examples
    --------
    A coned wheelset shifted 3 mm to the left, λ = 1/20:

    >>> c = wheelset_creepages(40.0, 0.0, 0.0, 0.0, 0.46 + 1.5e-4, 0.46 - 1.5e-4, 0.46, 0.75)
    >>> np.round(c.longitudinal * 1e4, 4).tolist()
    [-3.2609, 3.2609]
    """
    if check is False:
        return _unchecked_creepages(*_wheelset_creepages(
            speed, lateral_velocity, yaw_angle, yaw_rate, rolling_radius_left, rolling_radius_right,
            nominal_radius, half_gauge, contact_angle_left, contact_angle_right,
        ))  # fmt: skip
    _checks.flag("check", check)
    v = _checks.speed("speed", speed)
    r0 = _checks.plausible("nominal_radius", nominal_radius, "wheel_radius")
    l_half = _checks.plausible("half_gauge", half_gauge, "half_gauge")
    y_dot = _checks.array("lateral_velocity", lateral_velocity, allow_empty=False)
    psi = _checks.array("yaw_angle", yaw_angle, allow_empty=False)
    psi_dot = _checks.array("yaw_rate", yaw_rate, allow_empty=False)
    r_l = _checks.plausible_array(
        "rolling_radius_left", rolling_radius_left, "wheel_radius", allow_empty=False
    )
    r_r = _checks.plausible_array(
        "rolling_radius_right", rolling_radius_right, "wheel_radius", allow_empty=False
    )
    d_l = _checks.array("contact_angle_left", contact_angle_left, allow_empty=False)
    d_r = _checks.array("contact_angle_right", contact_angle_right, allow_empty=False)
    for name, angle in (("contact_angle_left", d_l), ("contact_angle_right", d_r)):
        if np.abs(angle).max(initial=0.0) > np.pi / 2:
            raise ValueError(f"{name} must be within ±π/2 rad (an angle in degrees?), got {angle!r:.80}")
    return WheelsetCreepages(*_wheelset_creepages(v, y_dot, psi, psi_dot, r_l, r_r, r0, l_half, d_l, d_r))


def _wheelset_creepages(v, y_dot, psi, psi_dot, r_l, r_r, r0, l_half, d_l, d_r):
    """γ_x, γ_y, φ of :func:`wheelset_creepages`, each of shape (2, ...), from checked arrays."""
    yaw, spin = l_half * psi_dot / v, psi_dot / v
    parts = (
        (r0 - r_l) / r0 - yaw,
        (r0 - r_r) / r0 + yaw,
        y_dot / v - psi,
        spin * np.cos(d_l) - np.sin(d_l) / r0,
        spin * np.cos(d_r) + np.sin(d_r) / r0,
    )
    # Broadcast only when the shapes differ: the nonlinear wheelset calls this at every evaluation
    # of its right-hand side, with arrays of one shape.
    if len({np.shape(p) for p in parts}) > 1:
        parts = np.broadcast_arrays(*parts)
    xi_l, xi_r, eta, phi_l, phi_r = parts
    return np.array((xi_l, xi_r)), np.array((eta, eta)), np.array((phi_l, phi_r))
