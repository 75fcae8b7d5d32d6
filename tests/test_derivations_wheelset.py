"""Chapter 5's wheelset derivations (raildyn.derivations.wheelset) held to raildyn.wheelset.

The derived matrices are compared with the package's to round-off (tests/derivation_helpers.py says
why 1e-12 of each matrix's largest entry), over random parameter sets (every parameter scaled by a
factor in [0.3, 3]), speeds, curve radii and positions along a vehicle; a few entries are also
held to closed forms written by hand.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy
from derivation_helpers import assert_derived, factors, scaled, system_matrices
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn.constants import GRAVITY, STANDARD_RAIL_SPACING
from raildyn.curving import steady_curving
from raildyn.derivations.wheelset import critical_speed_limit, curved_wheelset, tangent_wheelset
from raildyn.track import speed_for_deficiency
from raildyn.wheelset import Wheelset, curve_loads, pure_rolling_offset, wickens_critical_speed

FIELDS = (
    "mass", "yaw_inertia", "rolling_radius", "half_gauge", "conicity", "axle_load", "f11", "f22", "f23",
    "f33", "contact_angle", "contact_angle_parameter", "lateral_stiffness", "yaw_stiffness",
    "lateral_damping", "yaw_damping",
)  # fmt: skip
SPEEDS = (1.0, 30.0, 150.0)  # m/s: C₁/V spans two decades


def _symbol(derivation, name):
    return next(s for s, _ in derivation.parameters if s.name == name)


@settings(max_examples=30, deadline=None)
@given(changes=factors(FIELDS))
def test_tangent_wheelset_matches_the_package(changes):
    ws = scaled(Wheelset(), changes)
    for V in SPEEDS:
        assert_derived(tangent_wheelset(), system_matrices(ws, V), ws, V)


def test_tangent_wheelset_closed_forms():
    # By hand (Garg & Dukkipati 1984, ch. 5; Wickens 2003, ch. 2): the lateral creep force on the yaw,
    # −2f₂₂ψ, puts −2f₂₂ in K[0, 1]; the yaw row holds the spin stiffness 2f₂₃, the suspension and the
    # destabilising gravitational −Waϑ₀; the cross-level's roll z_c/(2a_r) (2a_r the rail spacing) tilts
    # the normal forces by −W z_c/(2a_r); the longitudinal creep damping is 2a²f₁₁/V.
    d = tangent_wheelset()
    f11, f22, f23, f33, W, a, th0, k_psi, c_psi = (
        _symbol(d, n) for n in ("f_11", "f_22", "f_23", "f_33", "W", "a", "vartheta_0", "k_psi", "c_psi")
    )
    V = d.speed
    assert sympy.simplify(d.K[0, 1] + 2 * f22) == 0
    assert sympy.simplify(d.K[1, 1] - (k_psi + 2 * f23 - W * a * th0)) == 0
    assert sympy.simplify(d.GK[0, 1] + W / (2 * _symbol(d, "a_r"))) == 0
    assert sympy.simplify(d.C[1, 1] - (c_psi + (2 * a**2 * f11 + 2 * f33) / V)) == 0
    assert d.GC == sympy.zeros(2, 2)


def test_tangent_wheelset_shows_the_spin_of_the_contact_angle_difference():
    # The spin of the contact-angle difference, 2f₂₃εy/(a r₀) laterally and 2f₃₃εy/(a r₀) in yaw (at
    # y_t = 0), shown as a step and held in K: −2f₂₃ε/(a r₀) beside the gravitational Wε/a, and
    # −2f₃₃ε/(a r₀) beside 2af₁₁λ/r₀.
    d = tangent_wheelset()
    (step,) = [s for s in d.steps if "spin of the contact-angle difference" in s.caption]
    f11, f23, f33, eps, a, r0, lam, W = (
        _symbol(d, n) for n in ("f_11", "f_23", "f_33", "varepsilon", "a", "r_0", "lambda", "W")
    )
    y, _ = d.coordinates
    expected = sympy.Matrix([2 * f23, 2 * f33]) * eps * y / (a * r0)
    assert (step.equation.rhs - expected).applyfunc(sympy.simplify) == sympy.zeros(2, 1)
    k_y = _symbol(d, "k_y")
    assert sympy.simplify(d.K[0, 0] - (k_y + W * eps / a - 2 * f23 * eps / (a * r0))) == 0
    assert sympy.simplify(d.K[1, 0] - (2 * a * f11 * lam / r0 - 2 * f33 * eps / (a * r0))) == 0


def test_free_wheelset_is_the_tangent_one_without_suspension():
    free = Wheelset().free()
    for V in SPEEDS:
        assert tangent_wheelset().difference(system_matrices(free, V), free, V) < 1e-14


@settings(max_examples=30, deadline=None)
@given(
    changes=factors(FIELDS),
    radius=st.floats(50.0, 1e4),
    position=st.floats(-3.0, 3.0),
    speed=st.floats(1.0, 100.0),
    cant=st.floats(0.0, 0.2),
)
def test_curved_wheelset_matches_curve_loads(changes, radius, position, speed, cant):
    ws = scaled(Wheelset(), changes)
    d = curved_wheelset()
    M, C, K, GK, GC = d.numeric((ws, position), speed)
    # In the turning axes the left-hand side is the tangent track's (no Coriolis terms to first order).
    assert_derived(d, system_matrices(ws, speed)[:3], (ws, position), speed)
    # The curve's loads: curve_loads plus the unbalanced inertia force −m a_q, a_q = V²/R − g D/G.
    loads = GK @ [1.0 / radius, cant]
    a_q = speed**2 / radius - GRAVITY * cant / STANDARD_RAIL_SPACING
    expected = curve_loads(ws, radius, position) + [-ws.mass * a_q, 0.0]
    scale = max(np.abs(curve_loads(ws, radius, position)).max(), ws.mass * abs(a_q), 1e-300)
    np.testing.assert_allclose(loads, expected, rtol=0.0, atol=1e-12 * scale)
    # G_C: the Euler force and moment of a changing curvature, −m x V and −I_z V per unit κ̇; to round-off
    # of the matrix's largest entry, as assert_derived holds the others (a subnormal x keeps few digits).
    expected_GC = np.array([[-ws.mass * position * speed, 0.0], [-ws.yaw_inertia * speed, 0.0]])
    np.testing.assert_allclose(GC, expected_GC, rtol=1e-12, atol=1e-12 * np.abs(expected_GC).max())


@settings(max_examples=20, deadline=None)
@given(changes=factors(FIELDS), radius=st.floats(150.0, 5000.0), deficiency=st.floats(-0.1, 0.2))
def test_curved_wheelset_steady_state_is_steady_curving(changes, radius, deficiency):
    # K q = G_K w for the lone wheelset (x = 0) is the equilibrium that steady_curving solves.
    ws = scaled(Wheelset(), changes)
    cant = 0.1
    V = speed_for_deficiency(radius, cant, max(deficiency, -cant + 0.01))
    _, _, K, GK, _ = curved_wheelset().numeric(ws, V)
    q = np.linalg.solve(K, GK @ [1.0 / radius, cant])
    state = steady_curving(ws, V, radius, cant=cant)
    # Tolerance: the two solve the same 2 × 2 system; its condition number (up to ~1e6 for the
    # softest draws) times round-off bounds the difference.
    np.testing.assert_allclose(-q[0], state.offset[0], rtol=1e-8, atol=1e-13)
    np.testing.assert_allclose(-q[1], state.angle_of_attack[0], rtol=1e-8, atol=1e-13)


@pytest.mark.parametrize("radius", [150.0, 600.0, 3000.0])
def test_pure_rolling_offset_comes_out_of_the_curved_derivation(radius):
    # The last step: the free wheelset without spin or gravity terms, at the balance speed, stands at
    # y = −r₀aκ/λ, i.e. r₀a/(λR) towards the outer rail (Garg & Dukkipati 1984, ch. 5).
    d = curved_wheelset()
    step = d.steps[-1]
    a, r0, lam = (_symbol(d, n) for n in ("a", "r_0", "lambda"))
    kappa, _ = d.inputs
    y, psi = step.equation.rhs
    assert sympy.simplify(y + r0 * a * kappa / lam) == 0 and psi == 0
    ws = Wheelset()
    value = float(y.subs({r0: ws.rolling_radius, a: ws.half_gauge, lam: ws.conicity, kappa: 1.0 / radius}))
    expected = pure_rolling_offset(ws.rolling_radius, ws.half_gauge, ws.conicity, radius)
    assert value == pytest.approx(-expected, rel=1e-14)


@settings(max_examples=20, deadline=None)
@given(changes=factors(FIELDS))
def test_critical_speed_limit_is_wickens(changes):
    ws = scaled(Wheelset(), changes)
    steps, d = critical_speed_limit(), tangent_wheelset()
    symbols = [symbol for symbol, _ in d.parameters]
    values = list(d.values(ws).values())
    V_c = np.sqrt(sympy.lambdify(symbols, steps[-1].equation.rhs)(*values))
    assert V_c == pytest.approx(wickens_critical_speed(ws), rel=1e-12)
    # The first step is the full characteristic polynomial: its roots are the eigenvalues of the
    # state matrix (to the root-finder's accuracy, relative to the largest root).
    V = 40.0
    coefficients = sympy.Poly(steps[0].equation.lhs, sympy.Symbol("s")).all_coeffs()
    roots = np.roots(sympy.lambdify([*symbols, d.speed], coefficients)(*values, V))
    eig = np.linalg.eigvals(ws.matrices(V).state_matrix())
    np.testing.assert_allclose(
        np.sort_complex(roots), np.sort_complex(eig), rtol=0.0, atol=1e-6 * np.abs(eig).max()
    )


def test_the_symbol_table_names_every_field_of_the_wheelset_symbols():
    # raildyn.derivations._wheel_rail maps each WheelsetSymbols field to its symbol and Wheelset field; a
    # field added to one and not the other would leave a symbol without a value.
    from dataclasses import fields

    from raildyn.derivations._wheel_rail import _FIELDS, WheelsetSymbols

    assert set(_FIELDS) == {f.name for f in fields(WheelsetSymbols)}
