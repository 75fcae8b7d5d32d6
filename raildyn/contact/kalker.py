"""Kalker's linear creep theory: the creep coefficients, the linear forces and the sign convention.

The ground floor of the creep laws of chapter 4: :class:`CreepCoefficients` (f₁₁, f₂₂, f₂₃, f₃₃
of a patch, from Kalker's table), :class:`CreepForces` (what every law returns) and
:func:`kalker_linear`. The saturating laws are in :mod:`~raildyn.contact.saturation` (Carter,
Shen–Hedrick–Elkins), :mod:`~raildyn.contact.johnson_vermeulen` and :mod:`~raildyn.contact.polach`;
a wheelset's creepages in :mod:`~raildyn.contact.creepages`.

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
    "CreepCoefficients",
    "CreepForces",
    "KalkerCoefficients",
    "creep_coefficients",
    "kalker_coefficients",
    "kalker_linear",
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
