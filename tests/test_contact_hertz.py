"""Tests of raildyn.contact.hertz (book chapter 4): Hertz's m, n and the contact ellipse.

Tiers: the classic table of m and n (Timoshenko & Goodier 1970 §140, reproduced in
Garg & Dukkipati 1984 ch. 4); closed forms (circular contact, the elliptic-integral
identities); properties (scaling with the load); bad input.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import special

from raildyn.contact import hertz_coefficients, hertz_contact

PROPERTY = settings(max_examples=50, deadline=None)

# θ (deg): (m, n), Hertz's table as printed by Timoshenko & Goodier (1970) §140 and by
# Garg & Dukkipati (1984) ch. 4, three decimals.
CLASSIC_TABLE = {
    30: (2.731, 0.493),
    35: (2.397, 0.530),
    40: (2.136, 0.567),
    45: (1.926, 0.604),
    50: (1.754, 0.641),
    55: (1.611, 0.678),
    60: (1.486, 0.717),
    65: (1.378, 0.759),
    70: (1.284, 0.802),
    75: (1.202, 0.846),
    80: (1.128, 0.893),
    85: (1.061, 0.944),
    90: (1.000, 1.000),
}


@pytest.mark.parametrize("theta_deg", sorted(CLASSIC_TABLE))
def test_m_n_against_the_classic_table(theta_deg):
    h = hertz_coefficients(math.radians(theta_deg))
    m, n = h.m, h.n
    m_tab, n_tab = CLASSIC_TABLE[theta_deg]
    # The table has three decimals (±0.0005) and carries errors of up to 2 units in the third
    # decimal in Hertz's own computation (Cooper 1969 lists them): 2.5e-3 absolute.
    assert m == pytest.approx(m_tab, abs=2.5e-3)
    assert n == pytest.approx(n_tab, abs=2.5e-3)


def test_m_n_vectorized_equal_scalar_calls():
    theta = np.radians([10.0, 33.0, 77.0])
    h = hertz_coefficients(theta)
    m, n = h.m, h.n
    for t, mi, ni in zip(theta, m, n, strict=True):
        one = hertz_coefficients(float(t))
        assert (mi, ni) == pytest.approx((one.m, one.n), rel=1e-14)


@given(st.floats(1.0, 90.0))
@PROPERTY
def test_m_n_satisfy_the_defining_elliptic_integral_equations(theta_deg):
    h = hertz_coefficients(math.radians(theta_deg))
    m, n = h.m, h.n
    k = n / m
    e2 = 1 - k**2
    big_k, big_e = special.ellipk(e2), special.ellipe(e2)
    # cos θ = [(1+k²)E − 2k²K]/(e²E) and m³ = 2E/(πk²) (Johnson 1985 eqs 4.39); the
    # bisection stops at ~1e-17 in log k, the rest is rounding in K and E: 1e-9.
    if theta_deg < 89.99:
        assert ((1 + k**2) * big_e - 2 * k**2 * big_k) / (e2 * big_e) == pytest.approx(
            math.cos(math.radians(theta_deg)), abs=1e-9
        )
    assert m**3 == pytest.approx(2 * big_e / (math.pi * k**2), rel=1e-12)
    assert 0 < n <= 1 <= m


def test_circular_contact_matches_the_closed_form(reference):
    # Equal curvatures in both directions: a sphere R on a plane, a = ∛(3NR/(4E*)),
    # p0 = 3N/(2πa²), δ = a²/R, with 1/E* = 2(1−ν²)/E for two equal steel bodies.
    load, radius, young, nu = 80e3, 0.5, 2.1e11, 0.3
    c = hertz_contact(load, radius, radius, math.inf, young, nu)
    e_star = young / (2 * (1 - nu**2))
    a = (3 * load * radius / (4 * e_star)) ** (1 / 3)
    # Closed forms evaluated in double precision; the bisection is converged to 1e-17: 1e-12.
    gap = max(abs(c.a / a - 1), abs(c.peak_pressure / (3 * load / (2 * math.pi * a**2)) - 1))
    reference(
        4,
        "Hertz contact of a sphere on a plane",
        "a = ∛(3NR/4E*), p₀ = 3N/2πa² (Hertz 1882)",
        "closed form",
        gap,
        1e-12,
    )
    assert c.b == pytest.approx(a, rel=1e-12)
    assert c.peak_pressure == pytest.approx(3 * load / (2 * math.pi * a**2), rel=1e-12)
    assert c.approach == pytest.approx(a**2 / radius, rel=1e-12)
    assert c.stiffness == pytest.approx(1.5 * load / (a**2 / radius), rel=1e-12)
    assert c.m == pytest.approx(1.0) and c.theta == pytest.approx(math.pi / 2)


def test_wheel_on_rail_ellipse_is_long_in_the_rolling_direction():
    # R_wheel = 0.46 m, conical tread, rail crown R = 0.3 m: A = 1.087 < B = 1.667 1/m,
    # so the long axis is along x, with the load integrating to N.
    c = hertz_contact(100e3, 0.46, math.inf, 0.3)
    assert c.a > c.b and c.a_over_b == pytest.approx(c.m / c.n)
    # Integral of the Hertz pressure over the ellipse, 2/3 π a b p0 = N exactly.
    assert 2 / 3 * math.pi * c.a * c.b * c.peak_pressure == pytest.approx(100e3, rel=1e-12)
    x, y = np.meshgrid(np.linspace(-c.a, c.a, 801), np.linspace(-c.b, c.b, 801))
    total = c.pressure(x, y).sum() * (x[0, 1] - x[0, 0]) * (y[1, 0] - y[0, 0])
    # A 801² rectangle rule on the square-root edge converges like h^1.5: 0.5 % is ample.
    assert total == pytest.approx(100e3, rel=5e-3)
    flipped = hertz_contact(100e3, 0.3, math.inf, 0.46)
    assert flipped.a < flipped.b


@given(st.floats(1e3, 1e5), st.floats(1.5, 10.0))  # both loads within the plausible 1 N to 1 MN
@PROPERTY
def test_semi_axes_grow_as_the_cube_root_of_the_load(load, factor):
    c1 = hertz_contact(load, 0.46, 0.5, 0.3)
    c2 = hertz_contact(load * factor, 0.46, 0.5, 0.3)
    # a ∝ N^{1/3}, p0 ∝ N^{1/3}, δ ∝ N^{2/3}; only rounding differs: 1e-12.
    assert c2.a / c1.a == pytest.approx(factor ** (1 / 3), rel=1e-12)
    assert c2.peak_pressure / c1.peak_pressure == pytest.approx(factor ** (1 / 3), rel=1e-12)
    assert c2.approach / c1.approach == pytest.approx(factor ** (2 / 3), rel=1e-12)


def test_concave_wheel_radius_is_allowed_while_the_contact_stays_elliptic():
    c = hertz_contact(100e3, 0.46, -0.5, 0.3)  # hollow tread, rail crown sharper
    assert c.a > 0 and c.b > c.a * 0.1


def test_bad_input():
    with pytest.raises(ValueError, match="normal_load"):
        hertz_contact(-1.0, 0.46, math.inf, 0.3)
    with pytest.raises(ValueError, match="poisson_ratio"):
        hertz_contact(1e5, 0.46, math.inf, 0.3, 2.1e11, 0.6)
    with pytest.raises(ValueError, match="relative curvature B"):
        hertz_contact(1e5, 0.46, -0.2, 0.3)
    with pytest.raises(ValueError, match="wheel_transverse_radius"):
        hertz_contact(1e5, 0.46, 0.0, 0.3)
    with pytest.raises(ValueError, match="theta"):
        hertz_coefficients(0.0)
    with pytest.raises(ValueError, match="theta"):
        hertz_coefficients(2.0)


def test_defaults_are_the_steel_constants_of_raildyn():
    from raildyn.constants import STEEL_POISSON_RATIO, STEEL_YOUNGS_MODULUS

    # One source for E and ν: the default contact equals the one given the constants, exactly.
    default = hertz_contact(100e3, 0.46, math.inf, 0.3)
    explicit = hertz_contact(100e3, 0.46, math.inf, 0.3, STEEL_YOUNGS_MODULUS, STEEL_POISSON_RATIO)
    assert default == explicit


def test_coefficients_are_a_frozen_dataclass_with_theta():
    import dataclasses

    h = hertz_coefficients(math.radians(45.0))
    assert dataclasses.is_dataclass(h) and not isinstance(h, tuple)
    assert h.theta == pytest.approx(math.pi / 4, rel=1e-15)
    with pytest.raises(dataclasses.FrozenInstanceError):
        h.m = 2.0
