"""Polach's creep law and its friction that falls with slip speed.

:func:`polach` (the creep force of a patch with an adhesion and a slip area) and
:class:`PolachAdhesion` (its five parameters, with the dry and wet sets :data:`POLACH_DRY` and
:data:`POLACH_WET`; :func:`polach_adhesion` the adhesion curve). Sign convention and results as in
:mod:`raildyn.contact.kalker`.
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
    _ratio,
    kalker_coefficients,
)

__all__ = [
    "POLACH_DRY",
    "POLACH_WET",
    "PolachAdhesion",
    "polach",
    "polach_adhesion",
]


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
