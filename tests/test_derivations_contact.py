"""Chapter 4's creepages derived from the contact points' velocities (raildyn.derivations.contact).

The derived (first-order) creepages are held to raildyn.contact.wheelset_creepages: to round-off
where the two are the same formulas (no contact angle), and within the higher-order terms the
package's exact spin keeps (ψ̇ cos ϑ/V ∓ sin ϑ/r₀ for ψ̇/V ∓ ϑ/r₀) otherwise; the package's spin
is held to the derivation's exact (unlinearised) spin to round-off at any contact angle.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn import contact
from raildyn.derivations.contact import CreepageDerivation, creepages

RELATIVE = 1e-12  # the same formulas evaluated in another order: a few ulps (tests/derivation_helpers.py)

# Running states of a wheelset: speeds 1–100 m/s, rates and angles of the size a linear model meets.
speeds = st.floats(1.0, 100.0)
lateral_velocities = st.floats(-0.5, 0.5)
yaw_angles = st.floats(-0.01, 0.01)
yaw_rates = st.floats(-0.5, 0.5)
radii = st.floats(0.3, 0.6)
shifts = st.floats(-5e-3, 5e-3)  # rolling-radius change r − r₀, m
half_gauges = st.floats(0.7, 0.8)


@settings(max_examples=60, deadline=None)
@given(V=speeds, yd=lateral_velocities, psi=yaw_angles, psid=yaw_rates, r0=radii, dL=shifts, dR=shifts,
       a=half_gauges)  # fmt: skip
def test_derived_creepages_equal_the_package_without_contact_angles(V, yd, psi, psid, r0, dL, dR, a):
    args = (V, yd, psi, psid, r0 + dL, r0 + dR, r0, a)
    mine = creepages().numeric(*args)
    theirs = contact.wheelset_creepages(*args)
    # Round-off relative to the largest term each creepage is a difference of: r/r₀ ≈ 1 in γ_x (the
    # derivation writes 1 − r/r₀, the package (r₀ − r)/r₀: the same to a few ulps of 1), aψ̇/V beside
    # it, ẏ/V and ψ in γ_y, ψ̇/V in φ.
    terms = {
        "longitudinal": max(1.0, abs(a * psid / V)),
        "lateral": abs(yd / V) + abs(psi),
        "spin": abs(psid / V),
    }
    for name, scale in terms.items():
        m, t = getattr(mine, name), getattr(theirs, name)
        np.testing.assert_allclose(m, t, rtol=0.0, atol=RELATIVE * scale + 1e-300, err_msg=name)


@settings(max_examples=60, deadline=None)
@given(V=speeds, psid=yaw_rates, r0=radii, dL=shifts, dR=shifts, thL=st.floats(-0.1, 0.1),
       thR=st.floats(-0.1, 0.1))  # fmt: skip
def test_spin_differs_from_the_first_order_form_by_higher_order_terms_only(V, psid, r0, dL, dR, thL, thR):
    # Derived to first order: φ = ψ̇/V ∓ ϑ/r₀; package (exact): ψ̇ cos ϑ/V ∓ sin ϑ/r₀. Their difference,
    # ψ̇(1 − cos ϑ)/V ∓ (ϑ − sin ϑ)/r₀, is bounded by |ψ̇|ϑ²/(2V) + |ϑ|³/(6r₀): products of small
    # quantities, as a first-order derivation leaves out.
    r = np.array([r0 + dL, r0 + dR])
    th = np.array([thL, thR])
    mine = creepages().numeric(V, 0.0, 0.0, psid, *r, r0, 0.75, thL, thR).spin
    theirs = contact.wheelset_creepages(V, 0.0, 0.0, psid, *r, r0, 0.75, thL, thR).spin
    bound = abs(psid) * th**2 / (2 * V) + np.abs(th) ** 3 / (6 * r0)
    assert np.all(np.abs(mine - theirs) <= bound * (1 + 1e-9) + 1e-15 * (abs(psid) / V + 1))


@settings(max_examples=60, deadline=None)
@given(V=speeds, psid=yaw_rates, r0=radii, dL=shifts, dR=shifts, thL=st.floats(-1.5, 1.5),
       thR=st.floats(-1.5, 1.5))  # fmt: skip
def test_package_spin_is_the_angular_velocity_about_the_contact_normal(V, psid, r0, dL, dR, thL, thR):
    # The derivation's exact spin, ω·n/V = ψ̇ cos ϑ/V ∓ sin ϑ/r₀ before it is linearised, against the
    # package at any contact angle, a flange's included: the same formula, so to round-off of its
    # two terms. The yaw rate's term carries cos ϑ (a third of it at 70°) and the roll's term the
    # axle's angular speed V/r₀, the nominal radius, whatever the contact's own rolling radius.
    d = creepages()
    exact = [next(s.equation.rhs for s in d.steps if str(s.equation.lhs) == f"varphi_{k}") for k in "LR"]
    spin = sympy.lambdify(list(d.symbols), exact, modules="numpy")
    args = (V, 0.0, 0.0, psid, r0 + dL, r0 + dR, r0, 0.75, thL, thR)
    mine = np.array(spin(*args), dtype=float)
    theirs = contact.wheelset_creepages(*args).spin
    scale = abs(psid) / V + 1.0 / r0
    np.testing.assert_allclose(theirs, mine, rtol=0.0, atol=RELATIVE * scale)


def test_creepages_in_closed_form():
    # Hand-written: a cone of conicity λ shifted by y has r_L = r₀ + λy, so
    # γ_x,L = −λy/r₀ − aψ̇/V; and γ_y = ẏ/V − ψ at both wheels (book ch. 4).
    d = creepages()
    V, yd, psi, psid, rL, rR, r0, a, thL, thR = d.symbols
    lam, y = sympy.symbols("lambda y")
    gx_left = d.longitudinal[0].subs(rL, r0 + lam * y)
    assert sympy.simplify(gx_left - (-lam * y / r0 - a * psid / V)) == 0
    assert sympy.simplify(d.lateral[0] - (yd / V - psi)) == 0 and d.lateral[0] == d.lateral[1]
    assert sympy.simplify(d.spin[0] - (psid / V - thL / r0)) == 0
    # Before linearising, the spin is the angular velocity along the tilted normal: ψ̇ cos ϑ/V − sin ϑ/r₀.
    exact = next(s.equation.rhs for s in d.steps if str(s.equation.lhs) == "varphi_L")
    assert sympy.simplify(exact - (psid * sympy.cos(thL) / V - sympy.sin(thL) / r0)) == 0


def test_derivation_refuses_a_matrix_of_the_wrong_shape():
    d = creepages()
    with pytest.raises(ValueError, match="spin"):
        CreepageDerivation(d.longitudinal, d.lateral, sympy.Matrix([1, 2, 3]), d.symbols)


def test_numeric_refuses_a_speed_of_zero():
    with pytest.raises(ValueError, match="speed"):
        creepages().numeric(0.0, 0.0, 0.0, 0.0, 0.46, 0.46, 0.46, 0.75)


def test_the_trace_line_is_derived():
    # The derived line, evaluated on the S1002 profile and its slope, is raildyn.contact.trace_line's (the
    # same formulas: round-off), at both signs of the yaw.
    import sympy

    from raildyn.contact import s1002_wheel, trace_line
    from raildyn.derivations.contact import trace_line as derived_line

    d = derived_line()
    wheel = s1002_wheel()
    slope = np.gradient(wheel.radius, wheel.lateral)
    evaluate = sympy.lambdify(d.symbols, [d.lateral_seen, d.radius_seen, d.lead], modules="numpy")
    for yaw in (0.01, -0.02):
        ours = trace_line(wheel.lateral, wheel.radius, yaw, 1.5)
        theirs = evaluate(wheel.lateral, wheel.radius, slope, yaw, 1.5)
        for a, b in zip(ours, theirs, strict=True):
            np.testing.assert_allclose(a, b, rtol=0, atol=1e-15)
    assert d.sin_theta == d.symbols[2] * sympy.tan(d.symbols[3])
