"""Chapter 4's creepages derived from the contact points' velocities (raildyn.derivations.contact).

The derived (first-order) creepages are held to raildyn.contact.wheelset_creepages: to round-off
where the two are the same formulas (no contact angle), and within the second-order terms the
package's book form keeps (sin ϑ/r_L for ϑ/r₀) otherwise.
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
def test_spin_differs_from_the_book_form_by_second_order_terms_only(V, psid, r0, dL, dR, thL, thR):
    # Derived: φ = ψ̇/V ∓ ϑ/r₀; package (book): ψ̇/V ∓ sin ϑ/r. Their difference is
    # ϑ/r₀ − sin ϑ/r = (ϑ − sin ϑ)/r + ϑ(r − r₀)/(r r₀), bounded by |ϑ|³/(6r) + |ϑ||r − r₀|/(r r₀):
    # a product of two small quantities, as a first-order derivation leaves out.
    r = np.array([r0 + dL, r0 + dR])
    th = np.array([thL, thR])
    mine = creepages().numeric(V, 0.0, 0.0, psid, *r, r0, 0.75, thL, thR).spin
    theirs = contact.wheelset_creepages(V, 0.0, 0.0, psid, *r, r0, 0.75, thL, thR).spin
    bound = np.abs(th) ** 3 / (6 * r) + np.abs(th) * np.abs(r - r0) / (r * r0)
    assert np.all(np.abs(mine - theirs) <= bound * (1 + 1e-9) + 1e-15 * (abs(psid) / V + 1))


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
