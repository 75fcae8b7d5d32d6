"""Tests of raildyn.contact.creep (book chapter 4): Kalker's table and the creep-force laws.

Tiers: Kalker's table at its own points (Kalker 1990 Table E.3, as in Garg &
Dukkipati 1984 ch. 4) and its known asymptotes; closed forms (Carter, the
small-creepage limits); properties (saturation at μN, monotonicity); bad input.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn.constants import STEEL_POISSON_RATIO, STEEL_SHEAR_MODULUS
from raildyn.contact import (
    KALKER_NU,
    POLACH_DRY,
    POLACH_WET,
    CreepCoefficients,
    PolachAdhesion,
    WheelsetCreepages,
    carter,
    carter_coefficient,
    creep_coefficients,
    johnson_vermeulen,
    johnson_vermeulen_coefficients,
    kalker_coefficients,
    kalker_linear,
    polach,
    polach_adhesion,
    saturation_factor,
    shen_hedrick_elkins,
    wheelset_creepages,
)

PROPERTY = settings(max_examples=50, deadline=None)

# A few rows of Kalker's table as printed (Kalker 1990 Table E.3; Garg & Dukkipati 1984 ch. 4),
# typed again here from the source, independently of the module: (a/b, ν) → (C11, C22, C23, C33).
TABLE_POINTS = {
    (0.1, 0.0): (2.51, 2.51, 0.334, 6.42),
    (0.1, 0.5): (4.85, 2.53, 0.731, 11.7),
    (0.5, 0.25): (3.62, 3.01, 0.929, 1.93),
    (0.8, 0.25): (3.91, 3.41, 1.25, 1.37),
    (1.0, 0.0): (3.40, 3.40, 1.33, 1.21),
    (1.0, 0.25): (4.12, 3.67, 1.47, 1.19),
    (1.0, 0.5): (5.20, 3.98, 1.63, 1.16),
    (1 / 0.6, 0.5): (5.80, 5.04, 2.50, 0.751),
    (2.0, 0.25): (5.10, 4.90, 2.62, 0.819),
    (1 / 0.3, 0.0): (5.57, 5.57, 3.79, 0.868),
    (10.0, 0.25): (11.7, 12.8, 14.6, 0.526),
    (10.0, 0.5): (12.9, 16.0, 18.0, 0.228),
}


@pytest.mark.parametrize("point", sorted(TABLE_POINTS), ids=str)
def test_kalker_coefficients_reproduce_the_table(point, reference):
    c = kalker_coefficients(*point)
    # The interpolation passes through the table: only rounding differs (1e-12).
    got = np.array([c.c11, c.c22, c.c23, c.c33])
    reference(4, f"Kalker's creep coefficients at a/b = {point[0]:g}, ν = {point[1]:g}", "Kalker 1967 table",
              "published", np.abs(got / np.array(TABLE_POINTS[point]) - 1).max(), 1e-12)  # fmt: skip


def test_every_table_row_is_reproduced_vectorized():
    g = np.arange(1, 11) / 10
    ratios = np.r_[g, 1 / g[::-1]]
    for nu in KALKER_NU:
        c = kalker_coefficients(ratios, nu)
        assert c.c11.shape == ratios.shape
        # Symmetry of the table at ν = 0: C11 = C22 for every a/b (Kalker 1967).
        if nu == 0.0:
            np.testing.assert_allclose(c.c11, c.c22, rtol=1e-12)


def test_kalker_table_near_its_thin_ellipse_asymptote():
    # Kalker's asymptote for a/b → 0: C11 → π²/(4(1−ν)), C22 → π²/4 (Kalker 1990 App. E;
    # the same limits are coded in CONTACT's linrol). At a/b = 0.1 the table is within 3 %.
    for nu in KALKER_NU:
        c = kalker_coefficients(0.1, nu)
        assert c.c11 == pytest.approx(math.pi**2 / (4 * (1 - nu)), rel=0.03)
        assert c.c22 == pytest.approx(math.pi**2 / 4, rel=0.03)


@given(st.floats(0.1, 10.0), st.floats(0.0, 0.5))
@PROPERTY
def test_coefficients_are_positive_and_continuous(ratio, nu):
    c = kalker_coefficients(ratio, nu)
    near = kalker_coefficients(min(ratio * (1 + 1e-6), 10.0), nu)
    for name in ("c11", "c22", "c23", "c33"):
        value = getattr(c, name)
        assert value > 0
        # Piecewise linear in a/b with slopes below 100 per unit: a 1e-6 step moves < 1e-3.
        assert abs(getattr(near, name) - value) < 1e-3


def test_creep_coefficients_scale_with_the_ellipse():
    a, b, g, nu = 6e-3, 4e-3, 8.1e10, 0.3
    f = creep_coefficients(a, b, g, nu)
    c = kalker_coefficients(a / b, nu)
    # Definitions f11 = Gab C11 ... (Kalker 1967): equal up to rounding.
    assert f.f11 == pytest.approx(g * a * b * c.c11, rel=1e-14)
    assert f.f22 == pytest.approx(g * a * b * c.c22, rel=1e-14)
    assert f.f23 == pytest.approx(g * (a * b) ** 1.5 * c.c23, rel=1e-14)
    assert f.f33 == pytest.approx(g * (a * b) ** 2 * c.c33, rel=1e-14)
    arr = creep_coefficients(np.array([a, 2 * a]), b, g, nu)
    assert arr.f11.shape == (2,) and arr.f11[0] == pytest.approx(f.f11)


def test_linear_theory_signs_follow_kalker():
    f = creep_coefficients(6e-3, 4e-3)
    r = kalker_linear(1e-3, 2e-3, 0.1, f)
    assert r.fx == pytest.approx(-f.f11 * 1e-3)
    assert r.fy == pytest.approx(-f.f22 * 2e-3 - f.f23 * 0.1)
    assert r.mz == pytest.approx(f.f23 * 2e-3 - f.f33 * 0.1)


def test_carter_closed_form_and_its_saturation():
    n, mu, r, a = 1e5, 0.3, 0.46, 6e-3
    f = carter_coefficient(n, r, a)
    assert f == pytest.approx(2 * n * r / a)
    xi = np.linspace(-0.01, 0.01, 2001)
    force = carter(xi, n, mu, f)
    u = r * xi / (mu * a)
    inside = np.abs(u) < 1
    # Carter (1926): F/μN = −sign(u)(1 − (1 − |u|)²) inside, full sliding beyond; exact algebra.
    np.testing.assert_allclose(
        force[inside], -mu * n * np.sign(u[inside]) * (1 - (1 - np.abs(u[inside])) ** 2)
    )
    np.testing.assert_allclose(force[~inside], -mu * n * np.sign(u[~inside]))
    assert np.all(np.diff(force) <= 1e-9)  # non-increasing in ξ


@given(st.floats(0.0, 0.05), st.floats(0.0, 0.05), st.floats(0.05, 0.6))
@PROPERTY
def test_johnson_vermeulen_and_she_are_bounded_and_start_on_the_linear_theory(xi, eta, mu):
    n = 1e5
    f = creep_coefficients(6e-3, 4e-3)
    jv = johnson_vermeulen(xi, eta, n, mu, 6e-3, 4e-3)
    she = shen_hedrick_elkins(xi, eta, 0.0, n, mu, f)
    # Bounded by μN up to rounding.
    assert math.hypot(jv.fx, jv.fy) <= mu * n * (1 + 1e-12)
    assert math.hypot(she.fx, she.fy) <= mu * n * (1 + 1e-12)
    # Monotone: more creepage in the same direction never lowers the resultant.
    jv2 = johnson_vermeulen(xi * 1.1 + 1e-7, eta * 1.1, n, mu, 6e-3, 4e-3)
    she2 = shen_hedrick_elkins(xi * 1.1 + 1e-7, eta * 1.1, 0.0, n, mu, f)
    assert jv2.resultant >= jv.resultant - 1e-9 * n
    assert she2.resultant >= she.resultant - 1e-9 * n


def test_saturated_laws_tend_to_the_linear_theory_and_to_mu_n():
    n, mu = 1e5, 0.3
    f = creep_coefficients(6e-3, 4e-3)
    small = 1e-7
    lin = kalker_linear(small, 0.0, 0.0, f)
    # At β = f11 ξ/(μN) ≈ 3e-5 the saturation factors differ from 1 by O(β): 1e-4. Johnson and
    # Vermeulen start on their own linear law, −G a b C11 ξ with their C11, not on Kalker's.
    c11 = johnson_vermeulen_coefficients(6e-3 / 4e-3, STEEL_POISSON_RATIO).c11
    jv_lin = -STEEL_SHEAR_MODULUS * 6e-3 * 4e-3 * c11 * small
    assert johnson_vermeulen(small, 0.0, n, mu, 6e-3, 4e-3).fx == pytest.approx(jv_lin, rel=1e-4)
    assert shen_hedrick_elkins(small, 0.0, 0.0, n, mu, f).fx == pytest.approx(lin.fx, rel=1e-4)
    assert polach(small, 0.0, 0.0, n, mu, 6e-3, 4e-3).fx == pytest.approx(lin.fx, rel=1e-4)
    big = 0.5
    assert johnson_vermeulen(big, 0.0, n, mu, 6e-3, 4e-3).fx == pytest.approx(-mu * n, rel=1e-12)
    assert shen_hedrick_elkins(big, 0.0, 0.0, n, mu, f).fx == pytest.approx(-mu * n, rel=1e-12)
    # Polach's arctan approaches μQ like 1 − 4/(πε): at ε ≈ 5e3 within 3e-4.
    assert polach(big, 0.0, 0.0, n, mu, 6e-3, 4e-3).fx == pytest.approx(-mu * n, rel=3e-4)


def test_polach_spin_term_matches_the_linear_theory_at_small_spin():
    # Polach (2000) built ε_M so that the spin force starts with Kalker's f23 φ.
    a, b, n, mu = 6e-3, 4e-3, 1e5, 0.3
    f = creep_coefficients(a, b)
    phi = 1e-4
    r = polach(0.0, 0.0, phi, n, mu, a, b)
    # K_M = −(2/3)ε_M + O(ε_M³) with ε_M ≈ 1e-4 here: 1e-6 relative is generous.
    assert r.fy == pytest.approx(-f.f23 * phi, rel=1e-6)
    assert r.mz is None


def test_polach_spin_force_is_kalkers_whatever_the_longitudinal_creepage():
    # For small creepage Kalker's linear theory gives Fy = −f₂₃φ (η = 0) independent of ξ.
    # Polach's spin force does so only with ε_M proportional to s_C = √(ξ² + η_C²): with
    # |η_C| = |φa| instead (as in some transcriptions) it would be (|φa|/s_C)·f₂₃φ, here 0.6 %
    # of it. ξ = 1e-5 keeps ε ≈ 0.01, so the saturation changes the result by about 1e-4.
    a, b, n, mu = 6e-3, 4e-3, 1e5, 0.3
    f = creep_coefficients(a, b)
    xi, phi = 1e-5, 1e-5
    r = polach(xi, 0.0, phi, n, mu, a, b)
    assert r.fy == pytest.approx(-f.f23 * phi, rel=2e-4)
    assert r.fx == pytest.approx(-f.f11 * xi, rel=2e-4)


def test_polach_2005_friction_falls_from_mu0_to_a_mu0():
    dry = POLACH_DRY
    w = np.array([0.0, 0.1, 1.0, 10.0, 1e2])  # m/s: at most MAXIMUM_SPEED
    mu = dry.friction(w)
    assert mu[0] == pytest.approx(0.55)
    assert np.all(np.diff(mu) < 0)
    assert mu[-1] == pytest.approx(0.4 * 0.55, rel=1e-12)
    # μ₀[(1 − A)e^{−Bw} + A] at w = 1 m/s, B = 0.6 s/m (Polach 2005, eq. for μ(w)).
    assert mu[2] == pytest.approx(0.55 * (0.6 * math.exp(-0.6) + 0.4), rel=1e-12)


def test_polach_adhesion_without_decay_is_the_1999_method():
    a, b, q = 6e-3, 4e-3, 1e5
    plain = PolachAdhesion(k_a=1.0, k_s=1.0, static_friction=0.3, limit_ratio=1.0, decay_rate=0.0)
    xi = np.geomspace(1e-5, 0.2, 25)
    got = polach_adhesion(xi, 0.3 * xi, 0.5, q, 30.0, a, b, plain)
    ref = polach(xi, 0.3 * xi, 0.5, q, 0.3, a, b)
    np.testing.assert_allclose(got.fx, ref.fx, rtol=1e-13)
    np.testing.assert_allclose(got.fy, ref.fy, rtol=1e-13)


@pytest.mark.parametrize("conditions", [POLACH_DRY, POLACH_WET], ids=["dry", "wet"])
def test_polach_adhesion_slope_peak_and_falling_branch(conditions):
    a, b, q, v = 6e-3, 4e-3, 1e5, 20.0
    # Initial slope: (2Qμ/π)(k_A + k_S)ε, i.e. (k_A + k_S)/2 of Kalker's f₁₁.
    tiny = 1e-8
    slope = -polach_adhesion(tiny, 0.0, 0.0, q, v, a, b, conditions).fx / tiny
    f11 = creep_coefficients(a, b).f11
    assert slope == pytest.approx(0.5 * (conditions.k_a + conditions.k_s) * f11, rel=1e-5)
    # The adhesion coefficient rises to a peak, then falls with the friction (to ξ = 0.2, a slip
    # of 4 m/s; far beyond, μ sits at A·μ₀ and the curve creeps up towards it); it never
    # exceeds μ at the slip speed.
    xi = np.geomspace(1e-5, 1.0, 400)
    fx = -polach_adhesion(xi, 0.0, 0.0, q, v, a, b, conditions).fx / q
    peak = int(np.argmax(fx))
    assert 0 < peak < xi.size - 1
    assert np.all(np.diff(fx[peak:][xi[peak:] < 0.2]) < 0)
    assert np.all(fx <= conditions.friction(v * xi) * (1 + 1e-12))
    assert fx[-1] > conditions.limit_ratio * conditions.static_friction * 0.9


def test_polach_closed_form_for_pure_longitudinal_creepage():
    # Pure ξ: F = (2Qμ/π)(ε/(1+ε²) + arctan ε), ε = GπabC11ξ/(4Qμ) (Polach 1999, eq. 7).
    a, b, q, mu, g = 6e-3, 4e-3, 1e5, 0.3, 8.1e10
    c11 = kalker_coefficients(a / b, 0.3).c11
    for xi in (1e-4, 1e-3, 1e-2):
        eps = g * math.pi * a * b * c11 * xi / (4 * q * mu)
        expected = -2 * q * mu / math.pi * (eps / (1 + eps**2) + math.atan(eps))
        assert polach(xi, 0.0, 0.0, q, mu, a, b, g).fx == pytest.approx(expected, rel=1e-12)


@given(st.floats(1e-5, 0.05), st.floats(0.05, 0.6))
@PROPERTY
def test_polach_is_bounded_by_mu_q(xi, mu):
    r = polach(xi, xi / 2, 0.0, 1e5, mu, 6e-3, 4e-3)
    # The bracket ε/(1+ε²) + arctan ε never exceeds π/2.
    assert r.resultant <= mu * 1e5 * (1 + 1e-12)


def test_wheelset_creepages_of_a_shifted_coned_wheelset():
    # A cone of slope λ shifted by y: r_L,R = r0 ± λy, so ξ_L,R = ∓λy/r0 (book ch. 5), η = −ψ.
    lam, y, r0, v = 0.05, 2e-3, 0.46, 30.0
    c = wheelset_creepages(v, 0.0, 1e-3, 0.0, r0 + lam * y, r0 - lam * y, r0, 0.75, lam, lam)
    assert c.longitudinal[0] == pytest.approx(-lam * y / r0)
    assert c.longitudinal[1] == pytest.approx(lam * y / r0)
    assert c.lateral[0] == pytest.approx(-1e-3)
    # the spin's roll term over the axle's nominal radius r₀ (it turns at V/r₀), not the wheel's own
    assert c.spin[0] == pytest.approx(-math.sin(lam) / r0, rel=1e-14)
    assert c.spin[1] == pytest.approx(math.sin(lam) / r0, rel=1e-14)


def test_the_yaw_rate_spins_a_steep_contact_by_its_cosine():
    # On a flange at 70° the yaw rate's share of the spin is ψ̇ cos 70°/V, a third of ψ̇/V (book ch. 4).
    v, psid, r0, flange = 30.0, 0.3, 0.46, math.radians(70.0)
    c = wheelset_creepages(v, 0.0, 0.0, psid, r0, r0, r0, 0.75, flange, 0.02)
    assert c.spin[0] == pytest.approx(psid * math.cos(flange) / v - math.sin(flange) / r0, rel=1e-14)
    assert c.spin[1] == pytest.approx(psid * math.cos(0.02) / v + math.sin(0.02) / r0, rel=1e-14)


def test_bad_input():
    with pytest.raises(ValueError, match="a_over_b"):
        kalker_coefficients(0.05, 0.3)
    with pytest.raises(ValueError, match="a_over_b"):
        kalker_coefficients(12.0, 0.3)
    with pytest.raises(ValueError, match="poisson_ratio"):
        kalker_coefficients(1.0, 0.6)
    with pytest.raises(ValueError, match="poisson_ratio"):
        kalker_coefficients(1.0, -0.1)
    f = creep_coefficients(6e-3, 4e-3)
    with pytest.raises(ValueError, match="friction"):
        johnson_vermeulen(0.01, 0.0, 1e5, 0.0, 6e-3, 4e-3)
    with pytest.raises(ValueError, match="friction"):
        shen_hedrick_elkins(0.01, 0.0, 0.0, 1e5, -0.1, f)
    with pytest.raises(ValueError, match="normal_load"):
        polach(0.01, 0.0, 0.0, -1e5, 0.3, 6e-3, 4e-3)
    with pytest.raises(ValueError, match="speed"):
        polach_adhesion(0.01, 0.0, 0.0, 1e5, 0.0, 6e-3, 4e-3)
    with pytest.raises(ValueError, match="limit_ratio"):
        PolachAdhesion(k_a=1.0, k_s=0.4, static_friction=0.5, limit_ratio=1.5, decay_rate=0.6)
    with pytest.raises(ValueError, match="slip_speed"):
        POLACH_DRY.friction(-1.0)
    with pytest.raises(ValueError, match="normal_load"):
        carter(0.01, -5.0, 0.3, 1e7)
    with pytest.raises(ValueError, match="a"):
        creep_coefficients(-1e-3, 4e-3)
    with pytest.raises(ValueError, match="speed"):
        wheelset_creepages(0.0, 0, 0, 0, 0.46, 0.46, 0.46, 0.75)


def test_user_built_inputs_are_checked():
    # Issue 15: CreepCoefficients holding NaN was accepted; PolachAdhesion blamed `friction`.
    with pytest.raises(ValueError, match="f22"):
        CreepCoefficients(9.8e6, math.nan, 9.2e3, 18.0)
    with pytest.raises(ValueError, match="f11"):
        CreepCoefficients(-1.0, 8.7e6, 9.2e3, 18.0)
    assert CreepCoefficients(9.8e6, 8.7e6, 0.0, 0.0).f23 == 0.0  # spin neglected
    with pytest.raises(ValueError, match="static_friction"):
        PolachAdhesion(k_a=1.0, k_s=0.4, static_friction=0.0, limit_ratio=0.4, decay_rate=0.6)
    with pytest.raises(TypeError, match="coefficients"):
        kalker_linear(1e-3, 0.0, 0.0, None)
    with pytest.raises(TypeError, match="conditions"):
        polach_adhesion(0.01, 0.0, 0.0, 1e5, 20.0, 6e-3, 4e-3, "dry")
    with pytest.raises(ValueError, match=r"a/b must be in \[0.1, 10\].*a = 0.05"):
        creep_coefficients(0.05, 4e-3)  # both semi-axes plausible, their ratio outside Kalker's table
    with pytest.raises(ValueError, match=r"a must be in \[1e-05, 0.05\] m"):
        creep_coefficients(1e300, 4e-3)  # a semi-axis far beyond any contact patch
    with pytest.raises(TypeError, match="check"):
        wheelset_creepages(40.0, 0, 0, 0, 0.46, 0.46, 0.46, 0.75, check="no")
    with pytest.raises(TypeError, match="check"):
        saturation_factor(1.0, 1.0, check=None)
    with pytest.raises(ValueError, match="spin"):
        WheelsetCreepages(np.zeros(2), np.zeros(2), np.zeros(3))


def test_huge_creepages_saturate_instead_of_overflowing():
    # Polach's K_M in its cancellation-free form and ε capped: full slip, no NaN.
    r = polach(1e300, 0.0, 1e300, 1e5, 0.3, 6e-3, 4e-3)
    assert np.isfinite([r.fx, r.fy]).all() and abs(r.fx) <= 0.3 * 1e5 * (1 + 2 / math.pi)
    assert float(saturation_factor(1e300, 1.0)) == 1e-300
    assert carter(1e300, 1e5, 0.3, 1e7) == -0.3 * 1e5


def test_unchecked_creepages_equal_the_checked_ones():
    args = (40.0, 0.01, 1e-3, 0.02, 0.46015, 0.45985, 0.46, 0.75, 0.05, -0.05)
    checked, unchecked = wheelset_creepages(*args), wheelset_creepages(*args, check=False)
    for name in ("longitudinal", "lateral", "spin"):
        np.testing.assert_array_equal(getattr(checked, name), getattr(unchecked, name))


def test_defaults_are_the_steel_constants_of_raildyn():
    from raildyn.constants import STEEL_POISSON_RATIO, STEEL_SHEAR_MODULUS

    # One source for G and ν: the default coefficients are those of G = E/(2(1 + ν)) = 80.8 GPa,
    # the shear modulus of the steel that Hertz's patch uses, not a separately rounded 81 GPa.
    a, b = 6e-3, 4e-3
    default = creep_coefficients(a, b)
    assert default == creep_coefficients(a, b, STEEL_SHEAR_MODULUS, STEEL_POISSON_RATIO)
    c = kalker_coefficients(a / b, STEEL_POISSON_RATIO)
    assert default.f11 == pytest.approx(STEEL_SHEAR_MODULUS * a * b * c.c11, rel=1e-14)
    assert polach(1e-3, 0.0, 0.0, 1e5, 0.3, a, b) == polach(
        1e-3, 0.0, 0.0, 1e5, 0.3, a, b, STEEL_SHEAR_MODULUS, STEEL_POISSON_RATIO
    )
    dry = polach_adhesion(1e-3, 0.0, 0.0, 1e5, 20.0, a, b)
    assert dry == polach_adhesion(1e-3, 0.0, 0.0, 1e5, 20.0, a, b, POLACH_DRY, STEEL_SHEAR_MODULUS, 0.3)
