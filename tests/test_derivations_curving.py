"""Chapter 8's steady-curving derivations (raildyn.derivations.curving) held to the package.

The package's steady state in a curve (raildyn.curving.steady.steady_curving) solves K q = f with the
model's stiffness matrix K and the loads f = Σ curve_loads(wheelset, R, x) − M r a_q, linear in
κ = 1/R and a_q: so the derived K must equal the model's K, and the derived G_K's columns the loads per
unit κ and per unit a_q, over random parameter sets (tolerance: tests/derivation_helpers.py).
"""

from __future__ import annotations

import numpy as np
import sympy
from derivation_helpers import assert_derived, factors, scaled
from hypothesis import given, settings

from raildyn.curving import bending_shear_stiffness, self_steering_curving, steady_curving
from raildyn.derivations.curving import bending_shear, bogie_curving, wheelset_curving
from raildyn.linear_model import as_linear_system
from raildyn.track import balance_speed
from raildyn.vehicles import Bogie
from raildyn.wheelset import Wheelset, curve_loads

CONTACT = ("f11", "f22", "f23", "f33", "rolling_radius", "conicity", "axle_load")
PRIMARY = ("lateral_stiffness", "yaw_stiffness", "mass")
R = 800.0  # m: any radius; the loads are linear in 1/R


def _steady(model):
    """The package's (M, C, K, G_K) of the steady state: M, C zero, G_K = loads per κ and per a_q."""
    system = as_linear_system(model)
    n = len(system.labels)
    lateral = np.array([label.endswith(" y") for label in system.labels], dtype=float)
    per_kappa = np.zeros(n)
    for (iy, ipsi, ws), x in zip(system.wheelsets, system.wheelset_positions, strict=True):
        per_kappa[[iy, ipsi]] += R * curve_loads(ws, R, x)
    GK = np.column_stack([per_kappa, -(system.M @ lateral)])
    return np.zeros((n, n)), np.zeros((n, n)), system.K, GK, np.zeros((n, 2))


def _wheelset(changes) -> Wheelset:
    ws = Wheelset(contact_angle=0.1, contact_angle_parameter=0.2)  # independent of the conicity
    return scaled(ws, changes)


def _bogie(wheelset_changes, bogie_changes) -> Bogie:
    return scaled(Bogie(wheelset=_wheelset(wheelset_changes)), bogie_changes)


@settings(max_examples=15, deadline=None)
@given(changes=factors(CONTACT + PRIMARY + ("half_gauge", "contact_angle", "contact_angle_parameter")))
def test_wheelset_curving_matches_steady_curving(changes):
    ws = _wheelset(changes)
    assert_derived(wheelset_curving(), _steady(ws), ws)


BOGIE = ("semi_wheelbase", "frame_mass", "secondary_lateral_stiffness", "secondary_yaw_stiffness")


@settings(max_examples=15, deadline=None)
@given(
    ws_changes=factors(CONTACT + PRIMARY + ("half_gauge", "contact_angle", "contact_angle_parameter")),
    changes=factors(BOGIE),
)
def test_bogie_curving_matches_steady_curving(ws_changes, changes):
    bogie = _bogie(ws_changes, changes)
    assert_derived(bogie_curving(), _steady(bogie), bogie)


def test_bogie_curving_solves_to_the_steady_state():
    # The derived K q = G_K (κ, a_q) gives steady_curving's displacement in a canted curve above the
    # balance speed (a_q > 0). The two solves use the same matrices (shown above) in another order: 1e-9.
    bogie = Bogie()
    _, _, K, GK, _ = bogie_curving().numeric(bogie)
    state = steady_curving(bogie, 35.0, 600.0, 0.1)
    q = np.linalg.solve(K, GK @ [1 / 600.0, state.unbalanced_acceleration])
    np.testing.assert_allclose(q, state.displacement, rtol=1e-9, atol=1e-12)


def _condensed(bogie):
    """The bogie's stiffness matrix with the frame condensed out (Schur complement) and its loads per κ."""
    M, C, K, GK, GC = _steady(bogie)
    w, f = [2, 3, 4, 5], [0, 1]
    K_red = K[np.ix_(w, w)] - K[np.ix_(w, f)] @ np.linalg.solve(K[np.ix_(f, f)], K[np.ix_(f, w)])
    # the frame carries no load per unit κ (curve_loads act on the wheelsets only)
    assert np.all(GK[f, 0] == 0.0)
    return np.zeros((4, 4)), np.zeros((4, 4)), K_red, GK[w, :1], np.zeros((4, 1))


@settings(max_examples=15, deadline=None)
@given(
    ws_changes=factors(CONTACT + ("lateral_stiffness", "yaw_stiffness", "half_gauge")),
    changes=factors(("semi_wheelbase",)),
)
def test_bending_shear_is_the_bogie_with_its_frame_condensed(ws_changes, changes):
    bogie = _bogie(ws_changes, changes).replace(secondary_lateral_stiffness=0.0, secondary_yaw_stiffness=0.0)
    # The Schur complement subtracts nearly equal numbers (k_y − k_y²/(2k_y)...): a few ulps of the
    # largest entry more than a plain sum, still far inside 1e-12 of it.
    assert_derived(bending_shear(), _condensed(bogie), bogie)


def test_bending_shear_holds_the_package_stiffnesses():
    # Closed form: the shear spring couples the lateral displacements by −k_sh, and the yaws by
    # −k_b + b²k_sh (the bending spring, and the shear spring's lever b at each wheelset);
    # k_b, k_sh are bending_shear_stiffness's.
    bogie = Bogie()
    _, _, K, _, _ = bending_shear().numeric(bogie)
    k = bending_shear_stiffness(bogie)
    b = bogie.semi_wheelbase
    assert np.isclose(K[1, 3], -k.bending + b**2 * k.shear, rtol=1e-13) and np.isclose(
        K[0, 2], -k.shear, rtol=1e-13
    )


def test_bending_shear_gives_the_self_steering_closed_form():
    # Without spin or gravitational stiffness the derived equations solve to self_steering_curving's
    # α₁ = (b/R) k_b k_sh/(k_b k_sh + aλf₁₁f₂₂/r₀) (hand-derived in notebook 08): 1e-9 for two solves.
    plain = Wheelset(f23=0.0, f33=0.0, contact_angle=0.0, contact_angle_parameter=0.0)
    bogie = Bogie(wheelset=plain, secondary_lateral_stiffness=0.0, secondary_yaw_stiffness=0.0)
    _, _, K, GK, _ = bending_shear().numeric(bogie)
    y1, psi1, y2, psi2 = np.linalg.solve(K, GK[:, 0] / R)
    b = bogie.semi_wheelbase
    closed = self_steering_curving(bogie, R)
    # α = −(ψ − x/R) from the local tangent; offset −(y − x²/2R) towards the outer rail
    np.testing.assert_allclose([-(psi1 - b / R), -(psi2 + b / R)], closed.angle_of_attack, rtol=1e-9)
    np.testing.assert_allclose([-(y1 - b**2 / (2 * R)), -(y2 - b**2 / (2 * R))], closed.offset, rtol=1e-9)
    assert balance_speed(R, 0.1) > 0  # the closed form is at the balance speed: a_q = 0, no input


def test_wheelset_curving_closed_forms():
    # Hand-written entries: K[0, 1] = −2f₂₂ (lateral creep of the yaw), K[1, 0] = 2aλf₁₁/r₀ − 2f₃₃ε/(a r₀)
    # (longitudinal creep, and the spin of the contact-angle difference); the centred wheelset's yaw
    # load per unit κ is −2a²f₁₁ − 2f₃₃ (longitudinal creep and spin).
    d = wheelset_curving()
    symbol = {str(s): s for s, _ in d.parameters}
    f11, f22, f33, a, r0, lam = (symbol[n] for n in ("f_11", "f_22", "f_33", "a", "r_0", "lambda"))
    eps = symbol["varepsilon"]
    assert d.K[0, 1] == -2 * f22
    assert sympy.simplify(d.K[1, 0] - (2 * a * lam * f11 / r0 - 2 * f33 * eps / (a * r0))) == 0
    assert sympy.simplify(d.GK[1, 0] - (-2 * a**2 * f11 - 2 * f33)) == 0
    assert d.M == sympy.zeros(2, 2) and d.C == sympy.zeros(2, 2)
