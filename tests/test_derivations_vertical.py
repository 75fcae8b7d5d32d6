"""Chapter 6's vertical models derived (raildyn.derivations.vertical), held to the numeric models.

Each derivation is compared with the model's ``matrices(V)`` over random parameter sets (hypothesis)
at several speeds, to round-off (tests/derivation_helpers.py says why 1e-12 of each matrix's largest
entry); one entry of each is also checked against a closed form written by hand, and the inputs'
delays against the model's ``input_positions``.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy
from derivation_helpers import assert_derived, factors, scaled, system_matrices
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from raildyn.constants import GRAVITY
from raildyn.derivations import time
from raildyn.derivations.vertical import freight_rock_and_roll, vertical_car, vertical_locomotive
from raildyn.vehicles import VerticalCar
from raildyn.vehicles.freight import GDU_ORE_CAR, VerticalFreightCar
from raildyn.vehicles.locomotive import VerticalLocomotive

SPEEDS = st.lists(st.floats(1.0, 120.0), min_size=1, max_size=3)


def _fields(model) -> list:
    return list(model.__dataclass_fields__)


def _symbols(derivation) -> dict:
    """The derivation's parameter symbols by name."""
    return {str(s): s for s, _ in derivation.parameters}


def _behind(derivation, model) -> np.ndarray:
    """s_j, m, read from the last step w_j(t) = z_v(t − s_j/V), for the model's parameters."""
    equation = derivation.steps[-1].equation
    (V,) = {s for s in equation.rhs.free_symbols if str(s) == "V"}
    values = derivation.values(model)
    return np.array([float(sympy.expand((time - u.args[0]) * V).subs(values)) for u in equation.rhs])


# -- the passenger car ---------------------------------------------------------------------------------


@settings(max_examples=25, deadline=None)
@given(changes=factors(_fields(VerticalCar())), speeds=SPEEDS)
def test_vertical_car_matches_the_model(changes, speeds):
    base = VerticalCar()
    assume(
        base.semi_wheelbase * changes["semi_wheelbase"]
        < base.semi_bogie_spacing * changes["semi_bogie_spacing"]
    )
    car = scaled(base, changes)
    for V in speeds:
        assert_derived(vertical_car(), system_matrices(car, V), car, V)


def test_vertical_car_closed_forms():
    d = vertical_car()
    p = _symbols(d)
    l, b, k_s, k_p, c_p = (p[n] for n in ("l", "b", "k_s", "k_p", "c_p"))
    # Body pitch on the two secondaries at ±l; a bogie's pitch on its two primaries at ±b; the leading
    # wheelset lifts the front bogie's centre by k_p and its pitch by k_p b, its rate pulls with c_p b.
    assert sympy.simplify(d.K[1, 1] - 2 * k_s * l**2) == 0
    assert sympy.simplify(d.K[3, 3] - 2 * k_p * b**2) == 0
    assert sympy.simplify(d.K[0, 2] + k_s) == 0
    assert (d.GK[2, 0], d.GK[3, 0], d.GC[3, 0], d.GC[3, 1]) == (k_p, k_p * b, c_p * b, -c_p * b)
    # and numerically, for the benchmark car
    car = VerticalCar()
    K = car.matrices(30.0).K
    assert K[1, 1] == pytest.approx(2 * car.secondary_stiffness * car.semi_bogie_spacing**2, rel=1e-15)


def test_vertical_car_delays_are_the_models():
    car = VerticalCar()
    np.testing.assert_allclose(_behind(vertical_car(), car), car.linear_system().input_positions, rtol=1e-15)


# -- the locomotive ------------------------------------------------------------------------------------


@settings(max_examples=25, deadline=None)
@given(changes=factors(_fields(VerticalLocomotive())), speeds=SPEEDS)
def test_vertical_locomotive_matches_the_model(changes, speeds):
    base = VerticalLocomotive()
    assume(
        base.axle_spacing * changes["axle_spacing"] < base.semi_truck_spacing * changes["semi_truck_spacing"]
    )
    loco = scaled(base, changes)
    for V in speeds:
        assert_derived(vertical_locomotive(), system_matrices(loco, V), loco, V)


def test_vertical_locomotive_closed_forms():
    d = vertical_locomotive()
    p = _symbols(d)
    l, b, k_s, k_p = (p[n] for n in ("l", "b", "k_s", "k_p"))
    # A truck bounces on its three primaries and the secondary; it pitches on the two outer axles
    # only (the middle axle stands under its centre).
    assert sympy.simplify(d.K[2, 2] - (3 * k_p + k_s)) == 0
    assert sympy.simplify(d.K[3, 3] - 2 * k_p * b**2) == 0
    assert sympy.simplify(d.K[1, 1] - 2 * k_s * l**2) == 0
    assert d.GK[3, 1] == 0 and d.GK[4, 4] == k_p


def test_vertical_locomotive_delays_are_the_models():
    loco = VerticalLocomotive()
    np.testing.assert_allclose(
        _behind(vertical_locomotive(), loco), loco.linear_system().input_positions, rtol=1e-15
    )


# -- the freight car's rock and roll -------------------------------------------------------------------


@settings(max_examples=25, deadline=None)
@given(
    changes=factors([f for f in _fields(VerticalFreightCar()) if f != "equivalent_damping"]),
    damping=st.floats(0.0, 2e5),
    speeds=SPEEDS,
)
def test_freight_rock_and_roll_matches_the_model(changes, damping, speeds):
    base = VerticalFreightCar()
    new = {n: getattr(base, n) * f for n, f in changes.items()}
    assume(new["semi_truck_wheelbase"] < new["semi_truck_spacing"])
    # the body must not topple: 4 k d² − m g h > 0
    assume(
        4 * new["nest_stiffness"] * new["semi_spring_spacing"] ** 2
        > new["body_mass"] * GRAVITY * new["cg_height"]
    )
    car = base.replace(equivalent_damping=damping, **new)
    for V in speeds:
        assert_derived(freight_rock_and_roll(), system_matrices(car, V), car, V)


@pytest.mark.parametrize(
    "car", [VerticalFreightCar(equivalent_damping=3e4), GDU_ORE_CAR], ids=["hopper", "GDU"]
)
def test_freight_rock_and_roll_matches_both_cars(car):
    assert_derived(freight_rock_and_roll(), system_matrices(car, 15.0), car, 15.0)


def test_freight_rock_and_roll_closed_forms():
    d = freight_rock_and_roll()
    p = _symbols(d)
    m, h, d_, k, g, I_phi = (p[n] for n in ("m", "h", "d", "k", "g", "I_phi"))
    # Roll about the spring plane: the nests at ±d give 4 k d², the weight h above takes m g h away;
    # the inertia about the roll axis is I_φ + m h² (parallel axes). Each rail height enters one nest
    # with weight ½.
    assert sympy.simplify(d.K[2, 2] - (4 * k * d_**2 - m * g * h)) == 0
    assert sympy.simplify(d.M[2, 2] - (I_phi + m * h**2)) == 0
    assert list(d.GK[0, :]) == [k / 2] * 8
    car = VerticalFreightCar()
    assert car.matrices(10.0).K[2, 2] == pytest.approx(car.roll_stiffness, rel=1e-14)


def test_freight_rock_and_roll_delays_are_the_models():
    car = VerticalFreightCar()
    np.testing.assert_allclose(
        _behind(freight_rock_and_roll(), car), car.linear_system().input_positions, rtol=1e-15
    )
    # left rail first at each axle, as the model's input_rails (+1 left, −1 right)
    names = [e.func.__name__ for e in freight_rock_and_roll().steps[-1].equation.rhs]
    rails = car.linear_system().input_rails
    assert names == ["z_L" if r > 0 else "z_R" for r in rails]
