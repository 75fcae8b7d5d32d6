"""Chapter 7's freight truck and locomotive derived (raildyn.derivations.trucks), held to the numeric models.

Each derivation is held to its model's ``matrices(V)`` over random parameter sets (hypothesis: every
parameter scaled by a factor in [0.3, 3]) at three speeds, to round-off (tests/derivation_helpers.py says
why 1e-12 of each matrix's largest entry). These tests found one bug: the friction dampers
c = 4F/(π ω X) came from :func:`raildyn.vehicles.wedges.wedge_energy_per_cycle`, which integrated the
ideal law by the midpoint rule, and the kinks of F |cos φ| left an error of 4.1e-9 of the energy; it now
returns the closed form 4 F X, and the trucks with friction agree to round-off like the others.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy
from derivation_helpers import FACTOR_RANGES, assert_derived, system_matrices
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from raildyn.constants import GRAVITY
from raildyn.derivations.trucks import (
    lateral_freight_car,
    lateral_locomotive,
    three_axle_truck,
    three_piece_truck,
)
from raildyn.vehicles.locomotive_lateral import LATERAL_LOCOMOTIVE, ThreeAxleTruck
from raildyn.vehicles.three_piece import EMPTY_FREIGHT_CAR, LOADED_FREIGHT_CAR, ThreePieceTruck
from raildyn.wheelset import creep_terms

SPEEDS = (3.0, 25.0, 120.0)  # m/s: the creep damping C₁/V from large to small

WHEELSET = (
    "mass", "yaw_inertia", "rolling_radius", "half_gauge", "conicity", "axle_load", "f11", "f22", "f23",
    "f33", "contact_angle", "contact_angle_parameter", "lateral_stiffness", "yaw_stiffness",
    "lateral_damping", "yaw_damping",
)  # fmt: skip
THREE_PIECE = (
    "side_frame_mass", "side_frame_yaw_inertia", "bolster_yaw_inertia", "semi_wheelbase",
    "side_frame_spacing", "warp_stiffness", "nest_shear_stiffness", "lateral_friction", "warp_friction",
    "centre_plate_friction", "reference_frequency", "reference_amplitude", "reference_angle",
)  # fmt: skip
THREE_AXLE = (
    "frame_mass", "frame_yaw_inertia", "motor_mass", "axle_spacing", "middle_lateral_stiffness",
    "middle_lateral_damping", "secondary_lateral_stiffness", "secondary_lateral_damping",
    "secondary_yaw_stiffness", "secondary_yaw_damping",
)  # fmt: skip
BODY = (
    "body_mass", "body_yaw_inertia", "body_roll_inertia", "semi_truck_spacing", "body_height",
    "roll_stiffness", "roll_damping",
)  # fmt: skip
FRICTION = ("lateral_friction", "warp_friction", "centre_plate_friction")

# The defaults leave some dampers at 0, which no factor would move: start them from a value.
FREIGHT_TRUCK = ThreePieceTruck().replace(lateral_damping=5.0e3, yaw_damping=2.0e3)
LOCO_TRUCK = ThreeAxleTruck().replace(secondary_yaw_damping=50.0e3)


def _value(model, name):
    """A field of the model, of its truck or of its wheelset."""
    for holder in (model, getattr(model, "truck", None), getattr(model, "wheelset", None)):
        if holder is not None and name in type(holder).__dataclass_fields__:
            return getattr(holder, name)
    raise AttributeError(name)


def _scaled(model, changes: dict):
    """The model with each named field (its own, its truck's or its wheelset's) times its factor; None if
    the changes make it invalid (a body that topples, trucks whose wheelsets cross)."""
    try:
        return model.replace(**{n: _value(model, n) * f for n, f in changes.items()})
    except ValueError:
        return None


def _factors(names):
    # narrower where a parameter would leave its plausible range (derivation_helpers.FACTOR_RANGES)
    return st.fixed_dictionaries({n: st.floats(*FACTOR_RANGES.get(n, (0.3, 3.0))) for n in names})


def _assert_matches(derivation, model):
    """The derived matrices equal the model's at every speed."""
    for V in SPEEDS:
        assert_derived(derivation, system_matrices(model, V), model, V)


def _entry(derivation, matrix, row, column):
    """An entry of a derived matrix, by the names of the coordinates (and inputs) it couples."""
    names = derivation.labels
    inputs = tuple(str(u.func) for u in derivation.inputs)
    j = names.index(column) if column in names else inputs.index(column)
    return getattr(derivation, matrix)[names.index(row), j]


def _symbols(derivation):
    return {str(s): s for s, _ in derivation.parameters} | {"V": derivation.speed}


# ---------------------------------------------------------------------------------------------- three-piece


@settings(max_examples=25, deadline=None)
@given(changes=_factors(WHEELSET + THREE_PIECE))
def test_three_piece_truck_matches_the_model(changes):
    truck = _scaled(FREIGHT_TRUCK, changes)
    assume(truck is not None)
    _assert_matches(three_piece_truck(), truck)


@settings(max_examples=15, deadline=None)
@given(changes=_factors(WHEELSET + tuple(n for n in THREE_PIECE if n not in FRICTION)))
def test_three_piece_truck_without_friction_matches_to_round_off(changes):
    truck = _scaled(FREIGHT_TRUCK.replace(**dict.fromkeys(FRICTION, 0.0)), changes)
    assume(truck is not None)
    _assert_matches(three_piece_truck(), truck)


def test_three_piece_truck_by_hand():
    d = three_piece_truck()
    s = _symbols(d)
    # The side frames slide ±d ψ_b as the bolster yaws: their mass at d adds to its inertia.
    assert _entry(d, "M", "psi_b", "psi_b") == s["I_b"] + s["m_f"] * s["d"] ** 2
    # Wheelset creep: lateral force −2f₂₂(ẏ/V − ψ), yaw moment −2af₁₁λy/r₀ with the spin of the
    # contact-angle difference 2f₃₃εy/(a r₀), and the gravitational W a ϑ₀ ψ.
    assert _entry(d, "K", "y_1", "psi_1") == -2 * s["f_22"]
    spin = 2 * s["f_33"] * s["epsilon"] / (s["a"] * s["r_0"])
    assert (
        sympy.simplify(
            _entry(d, "K", "psi_1", "y_1") - (2 * s["a"] * s["f_11"] * s["lambda"] / s["r_0"] - spin)
        )
        == 0
    )
    assert (
        sympy.simplify(
            _entry(d, "K", "psi_1", "psi_1")
            - (s["k_psi"] + 2 * s["f_23"] - s["W"] * s["a"] * s["vartheta_0"])
        )
        == 0
    )
    # The nests' lateral wedges as the damper 4F/(π ω X), beside the two wheelsets' pendulum dampers.
    expected = 2 * s["c_y"] + 4 * s["F_l"] / (sympy.pi * s["omega"] * s["X"])
    assert sympy.simplify(_entry(d, "C", "y_f", "y_f") - expected) == 0
    # The equivalent damper, derived as a step from the energy per cycle.
    step = next(st for st in d.steps if "equivalent damper" in st.caption)
    F, omega, X = sympy.symbols(r"F \omega X", positive=True)
    assert sympy.simplify(step.equation.rhs - 4 * F / (sympy.pi * omega * X)) == 0


# ---------------------------------------------------------------------------------------------- freight car


@pytest.mark.parametrize("base", [LOADED_FREIGHT_CAR, EMPTY_FREIGHT_CAR], ids=["loaded", "empty"])
@settings(max_examples=12, deadline=None)
@given(changes=_factors(BODY + WHEELSET + THREE_PIECE))
def test_freight_car_matches_the_model(base, changes):
    car = _scaled(base.replace(lateral_damping=5.0e3, yaw_damping=2.0e3), changes)
    assume(car is not None)
    _assert_matches(lateral_freight_car(), car)


@settings(max_examples=8, deadline=None)
@given(changes=_factors(BODY + WHEELSET))
def test_freight_car_without_friction_matches_to_round_off(changes):
    car = _scaled(LOADED_FREIGHT_CAR.replace(**dict.fromkeys(FRICTION, 0.0)), changes)
    assume(car is not None)
    _assert_matches(lateral_freight_car(), car)


def test_freight_car_roll_by_hand():
    d = lateral_freight_car()
    s = _symbols(d)
    # Roll: two trucks' nests in roll, less the weight h above them, plus the nests' shear at h (each truck).
    expected = 2 * s["k_phi"] - s["m"] * s["g"] * s["h"] + 2 * s["k_n"] * s["h"] ** 2
    assert sympy.simplify(_entry(d, "K", "phi", "phi") - expected) == 0
    # The nests tilt with the mean cross-level of their truck, over the rail spacing 2a_r: k_φ/(4a_r) per
    # metre at each of its wheelsets.
    assert sympy.simplify(_entry(d, "GK", "phi", r"\Delta{}z_11") - s["k_phi"] / (4 * s["a_r"])) == 0
    assert float(d.numeric(LOADED_FREIGHT_CAR, 20.0)[2][2, 2]) == pytest.approx(
        2 * LOADED_FREIGHT_CAR.roll_stiffness
        - LOADED_FREIGHT_CAR.body_mass * GRAVITY * LOADED_FREIGHT_CAR.body_height
        + 2 * LOADED_FREIGHT_CAR.truck.nest_shear_stiffness * LOADED_FREIGHT_CAR.body_height**2,
        rel=1e-12,
    )


# ---------------------------------------------------------------------------------------------- locomotive


@settings(max_examples=25, deadline=None)
@given(changes=_factors(WHEELSET + THREE_AXLE), share=st.floats(0.0, 1.0))
def test_three_axle_truck_matches_the_model(changes, share):
    truck = _scaled(LOCO_TRUCK.replace(motor_axle_share=share), changes)
    assume(truck is not None)
    _assert_matches(three_axle_truck(), truck)


def test_three_axle_truck_by_hand():
    d = three_axle_truck()
    s = _symbols(d)
    frame_share = (1 - s["rho_m"]) * s["m_m"]
    # Three motors' frame shares move with the frame, at x = ±b and 0.
    assert sympy.simplify(_entry(d, "M", "y_T", "y_T") - (s["m_t"] + 3 * frame_share)) == 0
    assert sympy.simplify(_entry(d, "M", "psi_T", "psi_T") - (s["I_t"] + 2 * frame_share * s["b"] ** 2)) == 0
    assert _entry(d, "M", "y_T", "psi_T") == 0
    # The middle axle on its centring springs only; the leading one on the primary at x = b.
    assert _entry(d, "K", "y_2", "y_T") == -s["k_m"]
    assert _entry(d, "K", "y_1", "psi_T") == -s["k_y"] * s["b"]


@settings(max_examples=15, deadline=None)
@given(changes=_factors(BODY + WHEELSET + THREE_AXLE), share=st.floats(0.0, 1.0))
def test_locomotive_matches_the_model(changes, share):
    loco = _scaled(LATERAL_LOCOMOTIVE.replace(motor_axle_share=share, secondary_yaw_damping=50.0e3), changes)
    assume(loco is not None)
    _assert_matches(lateral_locomotive(), loco)


def test_locomotive_by_hand():
    d = lateral_locomotive()
    s = _symbols(d)
    # The frames tilt with the mean cross-level of their three wheelsets: k_φ/(6a_r) per metre at each.
    assert sympy.simplify(_entry(d, "GK", "phi", r"\Delta{}z_11") - s["k_phi"] / (6 * s["a_r"])) == 0
    assert sympy.simplify(_entry(d, "GC", "phi", r"\Delta{}z_23") - s["c_phi"] / (6 * s["a_r"])) == 0
    # Body yaw: the two trucks' secondary lateral springs at ±l and yaw springs.
    expected = 2 * s["k_sy"] * s["l"] ** 2 + 2 * s[r"k_s\psi"]
    assert sympy.simplify(_entry(d, "K", "psi", "psi") - expected) == 0


@pytest.mark.parametrize("V", SPEEDS)
def test_wheel_rail_terms_equal_creep_terms(V):
    # The wheel-rail forces built here from the creepages, against raildyn.wheelset.creep_terms: the
    # leading wheelset's block of the locomotive truck, less its primary springs and dampers.
    truck = LOCO_TRUCK
    ws = truck.wheelset
    terms = creep_terms(ws)
    M, C, K, GK, GC = three_axle_truck().numeric(truck, V)
    block = slice(2, 4)  # y_1, ψ_1
    primary_K = np.diag([ws.lateral_stiffness, ws.yaw_stiffness])
    primary_C = np.diag([ws.lateral_damping, ws.yaw_damping])
    scale = np.abs(terms.K_creep).max()
    np.testing.assert_allclose(
        K[block, block] - primary_K, terms.K_creep + terms.K_gravity, rtol=0, atol=1e-12 * scale
    )
    np.testing.assert_allclose(C[block, block] - primary_C, terms.C1 / V, rtol=0, atol=1e-12 * scale / V)
