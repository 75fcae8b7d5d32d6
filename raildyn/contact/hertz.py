"""Hertz's normal contact between a wheel and a rail: ellipse, pressure, approach and stiffness.

The two bodies are described near the contact point by their principal radii
of curvature; the gap between them is ``A x² + B y²`` with x the rolling
direction. Hertz showed that the contact area is an ellipse whose shape depends
only on ``B/A`` and whose size grows as the cube root of the load. The shape
factors m and n are computed here from the complete elliptic integrals
(``scipy.special.ellipk``/``ellipe``), not read from a table.

Book: Garg & Dukkipati (1984), chapter 4 (Hertz theory, Table of m and n);
the elliptic-integral forms follow Johnson, *Contact Mechanics* (1985), §4.2.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np

from raildyn import _checks
from raildyn.constants import STEEL_POISSON_RATIO, STEEL_YOUNGS_MODULUS

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.special

__all__ = ["HertzCoefficients", "HertzContact", "hertz_coefficients", "hertz_contact"]

_BISECTION_STEPS = 60  # halves a bracket of width 15 in log(b/a) to ~1e-17: below double precision


def _ratio_from_cos_theta(cos_theta: np.ndarray) -> np.ndarray:
    """Axis ratio k = b/a ≤ 1 of the ellipse whose curvature angle has the given cos θ_H.

    Solves ``(B−A)/(B+A) = [(1+k²)E(e_c) − 2k²K(e_c)] / (e_c² E(e_c))`` with e_c² = 1 − k²
    (Johnson 1985, eqs. 4.39) by bisection on log k, vectorized over θ_H.
    """
    from scipy import special

    lo = np.full(cos_theta.shape, -15.0)  # log k = −15 (a/b ≈ 3e6): cos θ_H = 1 − 1e-12
    hi = np.zeros(cos_theta.shape)  # log k = 0: circle, cos θ_H = 0
    for _ in range(_BISECTION_STEPS):
        mid = 0.5 * (lo + hi)
        k2 = np.exp(2 * mid)
        m = 1.0 - k2
        big_k, big_e = special.ellipkm1(k2), special.ellipe(m)  # K via its complement: accurate as e → 1
        with np.errstate(invalid="ignore", divide="ignore"):
            direct = ((1 + k2) * big_e - 2 * k2 * big_k) / (m * big_e)
        # Near the circle the direct form cancels (its numerator is O(e⁴)); use its series there.
        series = m * (3 / 8 + m * (3 / 16 + m * (111 / 1024 + m * 141 / 2048)))
        value = np.where(m > 1e-3, direct, series)
        # value falls from 1 to 0 as log k rises from −∞ to 0
        too_flat = value > cos_theta
        lo = np.where(too_flat, mid, lo)
        hi = np.where(too_flat, hi, mid)
    return np.exp(0.5 * (lo + hi))


def _shape_factors(k: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Hertz's m and n for the axis ratio k = b/a (Johnson 1985, eq. 4.36 rearranged).

    m³ = 2E(e_c)/(π k²), n = k m, with e_c² = 1 − k².
    """
    from scipy import special

    m3 = 2.0 * special.ellipe(1.0 - k**2) / (np.pi * k**2)
    m = np.cbrt(m3)
    return m, k * m


@dataclass(frozen=True)
class HertzCoefficients:
    """Hertz's coefficients m and n (dimensionless) for an angle θ_H.

    Attributes
    ----------
    theta : float or ndarray
        θ_H, rad, cos θ_H = |B − A|/(A + B).
    m : float or ndarray
        Coefficient of the semi-axis along the direction of smaller relative curvature.
    n : float or ndarray
        Coefficient of the other semi-axis (n <= 1 <= m).
    """

    theta: float | np.ndarray
    m: float | np.ndarray
    n: float | np.ndarray

    def __post_init__(self):
        _checks.fields(self)


def hertz_coefficients(theta) -> HertzCoefficients:
    """Hertz's coefficients m and n for the angle θ_H with cos θ_H = |B − A|/(A + B).

    Parameters
    ----------
    theta : float or array_like
        Angle θ_H in radians, in (0, π/2]. θ_H = π/2 is a circular contact (m = n = 1).

    Returns
    -------
    HertzCoefficients
        ``m`` and ``n`` (floats for a scalar θ_H): the semi-axes are ``m c_H`` (along
        the direction of smaller relative curvature) and ``n c_H``, with
        ``c_H = ∛(3 N (1−ν²) / (2 E (A+B)))`` for two bodies of the same material
        (book ch. 4; Timoshenko & Goodier 1970 §140).

    Examples
    --------
    >>> h = hertz_coefficients(math.radians(60))
    >>> round(h.m, 3), round(h.n, 3)
    (1.486, 0.717)
    """
    th = _checks.array("theta", theta)
    if np.any(th <= 0) or np.any(th > np.pi / 2 + 1e-12):
        raise ValueError(f"theta must be in (0, π/2] radians, got {theta!r}")
    k = _ratio_from_cos_theta(np.abs(np.cos(th)))
    m, n = _shape_factors(k)
    if np.ndim(theta) == 0:
        return HertzCoefficients(theta=float(th), m=float(m), n=float(n))
    return HertzCoefficients(theta=th, m=m, n=n)


@dataclass(frozen=True)
class HertzContact:
    """Hertz's solution for one wheel–rail contact (SI units).

    Attributes
    ----------
    a : float
        a_c, semi-axis in the rolling direction (m).
    b : float
        b_c, semi-axis across the rail (m).
    peak_pressure : float
        p₀ = 3N/(2πa_c b_c) at the centre of the ellipse (Pa).
    approach : float
        Mutual approach u_N of distant points of the two bodies (m).
    stiffness : float
        Linearized normal stiffness dN/du_N = 3N/(2u_N) at this load (N/m).
    theta : float
        Hertz's auxiliary angle θ_H (rad), cos θ_H_H = |B − A|/(A + B).
    m, n : float
        Hertz's coefficients for θ_H.
    curvature_sum : float
        A + B (1/m).
    normal_load : float
        N (N).
    """

    a: float
    b: float
    peak_pressure: float
    approach: float
    stiffness: float
    theta: float
    m: float
    n: float
    curvature_sum: float
    normal_load: float

    def __post_init__(self):
        for f in fields(self):
            _checks.scalar(f.name, getattr(self, f.name))

    @property
    def a_over_b(self) -> float:
        """Ellipse ratio a/b, the argument of Kalker's coefficient table."""
        return self.a / self.b

    def pressure(self, x, y):
        """Hertz pressure p₀√(1 − x²/a² − y²/b²) at (x, y); zero outside the ellipse.

        Parameters
        ----------
        x : float or array_like
            Distance from the centre along the rolling direction, m, finite, any sign.
        y : float or array_like
            Distance from the centre across the rail, m, finite, any sign; broadcast with ``x``.

        Returns
        -------
        ndarray
            p, Pa.

        Examples
        --------
        >>> c = hertz_contact(100e3, 0.46, math.inf, 0.3)
        >>> bool(c.pressure(0.0, 0.0) == c.peak_pressure), float(c.pressure(c.a, 0.0))
        (True, 0.0)
        """
        r = np.minimum(np.hypot(_checks.array("x", x) / self.a, _checks.array("y", y) / self.b), 1.0)
        return self.peak_pressure * np.sqrt(1.0 - r**2)


def _curvature(name: str, radius) -> float:
    """1/R for a signed radius (m), |R| >= 1 mm; ``math.inf`` gives a flat direction (0).

    The sharpest radii of real profiles are the 13-15 mm of a rail's gauge corner and a wheel's
    flange root; a radius below a millimetre is a slip (metres typed as kilometres, or a
    curvature for a radius), and its curvature would overflow the formulas.
    """
    if radius == math.inf:
        return 0.0
    r = _checks.scalar(name, radius)
    if abs(r) < _MIN_PROFILE_RADIUS:
        raise ValueError(
            f"{name} must be a radius in m of at least {_MIN_PROFILE_RADIUS} m in size (math.inf if "
            f"straight), got {radius!r}"
        )
    return 1.0 / r


_MIN_PROFILE_RADIUS = 1.0e-3  # m: below any radius of a real wheel or rail profile (see _curvature)


def hertz_contact(
    normal_load,
    wheel_rolling_radius,
    wheel_transverse_radius,
    rail_transverse_radius,
    youngs_modulus=STEEL_YOUNGS_MODULUS,
    poisson_ratio=STEEL_POISSON_RATIO,
    *,
    rail_rolling_radius=math.inf,
) -> HertzContact:
    """Contact ellipse, peak pressure and approach for a wheel on a rail of the same steel.

    Parameters
    ----------
    normal_load : float
        Normal force N (N), in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_load").
    wheel_rolling_radius : float
        Rolling radius of the wheel R₁ (m), in [0.1, 1.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "wheel_radius").
    wheel_transverse_radius : float
        Radius of the wheel profile across the rail R₁′ (m), at least 1 mm in size (the
        sharpest real profile radii, at a flange root or gauge corner, are 13-15 mm): positive when convex,
        negative when concave (a hollow tread or the flange root), ``math.inf``
        for a conical tread.
    rail_transverse_radius : float
        Radius of the rail head across the rail R₂′ (m), at least 1 mm in size, positive convex,
        ``math.inf`` for a flat rail. The transverse curvatures must add up to
        B = ½(1/R₁′ + 1/R₂′) > 0, and the rolling ones to A = ½(1/R₁ + 1/R₂) > 0: else
        the bodies do not touch in an ellipse.
    youngs_modulus : float
        E (Pa), for both bodies; default :data:`raildyn.constants.STEEL_YOUNGS_MODULUS` (210 GPa).
    poisson_ratio : float
        ν in [0, 0.5); default :data:`raildyn.constants.STEEL_POISSON_RATIO` (0.3).
    rail_rolling_radius : float, keyword
        Radius of the rail along the track (m), at least 1 mm in size (negative in a sag); ``math.inf``
        for straight track.

    Returns
    -------
    HertzContact
        Semi-axes, peak pressure, approach and normal stiffness.

    Notes
    -----
    With A = ½(1/R₁ + 1/R₂), B = ½(1/R₁′ + 1/R₂′) (book ch. 4) and two bodies of
    the same material, c_H = ∛(3N(1−ν²)/(2E(A+B))); the semi-axis along the
    direction of smaller curvature is m c_H and the other n c_H. The peak pressure
    is p₀ = 3N/(2πa_c b_c) and the approach u_N = 2 K(e_c) p₀ b_min (1−ν²)/E with b_min
    the smaller semi-axis and e_c the eccentricity (Johnson 1985, eq. 4.38; Hertz 1882).

    Examples
    --------
    >>> c = hertz_contact(100e3, 0.46, math.inf, 0.3)
    >>> round(c.a * 1e3, 2), round(c.b * 1e3, 2)  # mm
    (7.16, 5.39)
    """
    from scipy import special

    load = _checks.plausible("normal_load", normal_load, "wheel_load")
    _checks.plausible("wheel_rolling_radius", wheel_rolling_radius, "wheel_radius")
    young = _checks.positive("youngs_modulus", youngs_modulus)
    nu = _checks.scalar("poisson_ratio", poisson_ratio, low=0.0, high=0.5, high_open=True)
    big_a = 0.5 * (
        _curvature("wheel_rolling_radius", wheel_rolling_radius)
        + _curvature("rail_rolling_radius", rail_rolling_radius)
    )
    big_b = 0.5 * (
        _curvature("wheel_transverse_radius", wheel_transverse_radius)
        + _curvature("rail_transverse_radius", rail_transverse_radius)
    )
    for big, what, one, other in (
        (big_a, "A (rolling)", "wheel_rolling_radius", "rail_rolling_radius"),
        (big_b, "B (transverse)", "wheel_transverse_radius", "rail_transverse_radius"),
    ):
        if big <= 0:
            raise ValueError(
                f"the relative curvature {what} = ½(1/{one} + 1/{other}) must be positive for an elliptical "
                f"contact, got {big:.4g} 1/m; check the signs of {one} and {other} (a concave surface "
                "must be the less curved)"
            )
    total = big_a + big_b
    cos_theta = abs(big_b - big_a) / total
    k = _ratio_from_cos_theta(np.array(cos_theta))
    m, n = (float(v) for v in _shape_factors(k))
    k = float(k)
    e_star = young / (1.0 - nu**2)  # plane-strain modulus of one body; the pair has E*/2
    c = (3.0 * load / (2.0 * e_star * total)) ** (1.0 / 3.0)
    major, minor = m * c, n * c
    # The longer axis lies along the direction of smaller relative curvature.
    a, b = (major, minor) if big_a <= big_b else (minor, major)
    p0 = 3.0 * load / (2.0 * np.pi * a * b)
    approach = 2.0 * float(special.ellipkm1(k**2)) * p0 * minor / e_star
    return HertzContact(
        a=a,
        b=b,
        peak_pressure=p0,
        approach=approach,
        stiffness=1.5 * load / approach,
        theta=math.acos(min(cos_theta, 1.0)),
        m=m,
        n=n,
        curvature_sum=total,
        normal_load=load,
    )
