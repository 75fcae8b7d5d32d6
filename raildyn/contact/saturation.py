"""Creep laws that cap the linear forces at the friction limit: Carter and Shen–Hedrick–Elkins.

Carter's two-dimensional law for a cylinder rolling on a plane (:func:`carter`, with its
coefficient :func:`carter_coefficient`), and Shen, Hedrick and Elkins's scaling of Kalker's
linear forces (:func:`shen_hedrick_elkins`, through :func:`saturation_factor`). Sign convention and
results as in :mod:`raildyn.contact.kalker`.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks
from raildyn._compiled import compiled_as
from raildyn.contact.kalker import (
    CreepCoefficients,
    CreepForces,
    _friction,
    _out,
    kalker_linear,
)

__all__ = [
    "carter",
    "carter_coefficient",
    "saturation_factor",
    "saturation_scale",
    "shen_hedrick_elkins",
]


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
        Check the input (default); False for a caller that has (as
        :func:`~raildyn.contact.creepages.wheelset_creepages`): then nothing is checked and bad input
        gives bad numbers.

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
    return _scale(np.abs(force) / limit)


def _scale(u):
    # (3 − v + v²/9)/max(u, 3) with v = min(u, 3) is 1 − u/3 + u²/27 up to u = 3 and exactly 1/u beyond
    # (no overflow for a huge u), 1 at u = 0: F_sat/F everywhere, with no division by zero.
    v = np.minimum(u, 3.0)
    return (3.0 - v + v * v / 9.0) / np.maximum(u, 3.0)


@compiled_as(_scale)
def saturation_scale(u):
    """F_sat/F of :func:`saturation_factor` at the normalised force F̂ = u = |F|/(μN).

    The law in the form that numpy evaluates on arrays and numba compiles for floats: the
    compiled wheel–rail engine (:mod:`raildyn.wheelset`) calls this function, and compiles it
    without its check (see ``raildyn._compiled``).

    Parameters
    ----------
    u : float or array_like
        F̂ = |F|/(μN), ≥ 0 (dimensionless).

    Returns
    -------
    float or ndarray
        F_sat/F, in (0, 1]: 1 − u/3 + u²/27 up to u = 3, 1/u beyond.

    Examples
    --------
    >>> float(saturation_scale(6.0))  # twice the force that saturates: half of it is carried
    0.16666666666666666
    """
    return _scale(_checks.array("u", u, low=0.0, allow_empty=False))


def shen_hedrick_elkins(longitudinal, lateral, spin, normal_load, friction, coefficients: CreepCoefficients):
    """Kalker's linear forces bounded by the heuristic saturation of Shen, Hedrick and Elkins (1983).

    The linear forces include spin (Fy = −f₂₂γ_y − f₂₃φ). With F̂ = |F_lin|/(μN), the resultant
    √(Fx² + Fy²) becomes μN(F̂ − F̂²/3 + F̂³/27) for F̂ ≤ 3 and μN beyond; Fx, Fy and Mz are all
    scaled by the same factor. The cubic is Vermeulen and Johnson's 1 − (1 − F̂/3)³
    (:func:`~raildyn.contact.johnson_vermeulen.johnson_vermeulen`), applied to Kalker's coefficients
    instead of theirs.

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

    >>> from raildyn.contact.kalker import creep_coefficients
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
