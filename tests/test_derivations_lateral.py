"""Chapter 7's derivations (raildyn.derivations.lateral) held to the bogie and the car of raildyn.vehicles.

Each derived model is compared with the numeric model over random parameter sets (hypothesis) at
several speeds, to round-off (tests/derivation_helpers.py says why 1e-12 of each matrix's largest
entry); one entry of each is also checked against a closed form written out by hand.
"""

from __future__ import annotations

import pytest
import sympy
from derivation_helpers import FACTOR_RANGES, assert_derived, system_matrices
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn.constants import GRAVITY
from raildyn.derivations.lateral import bogie, lateral_car
from raildyn.vehicles.lateral import COOPERRIDER_CAR, Bogie, LateralCar

SPEEDS = (2.0, 30.0, 140.0)  # m/s: the creep damping C₁/V spans a factor of 70

# Factors on the defaults in [0.3, 3] (tests/derivation_helpers.factors): wheelset fields reached
# through Bogie.replace / LateralCar.replace, which pass them on to the wheelset.
WHEELSET = (
    "mass", "yaw_inertia", "rolling_radius", "half_gauge", "conicity", "axle_load", "f11", "f22", "f23",
    "f33", "lateral_stiffness", "yaw_stiffness", "lateral_damping", "yaw_damping",
)  # fmt: skip
FRAME = (
    "frame_mass", "frame_yaw_inertia", "semi_wheelbase", "secondary_lateral_stiffness",
    "secondary_lateral_damping", "secondary_yaw_stiffness", "secondary_yaw_damping",
)  # fmt: skip
# The body's fields in ranges that keep the car valid: the bogie centres beyond the wheelbase
# (9.5 m against at most 3 × 1.28 m) and the roll springs above the weight's moment m g h.
BODY = {
    "body_mass": (0.3, 2.0),
    "body_yaw_inertia": (0.3, 3.0),
    "body_roll_inertia": (0.3, 3.0),
    "semi_bogie_spacing": (1.0, 3.0),
    "body_height": (0.3, 2.0),
    "roll_stiffness": (1.0, 3.0),
    "roll_damping": (0.3, 3.0),
}


def _factors(names, low=0.3, high=3.0):
    # narrower where a parameter would leave its plausible range (derivation_helpers.FACTOR_RANGES)
    return st.fixed_dictionaries({n: st.floats(*FACTOR_RANGES.get(n, (low, high))) for n in names})


def _bogie_changes(base: Bogie, ws: dict, frame: dict, angles: dict) -> dict:
    wheelset = base.wheelset
    changes = {n: getattr(wheelset, n) * f for n, f in ws.items()}
    # The contact angle and ε drawn apart from the conicity (each ≤ 0.15 × 3 = 0.45, inside [0, 0.5]).
    changes |= {n: getattr(wheelset, n) * f for n, f in angles.items()}
    changes |= {n: getattr(base, n) * f for n, f in frame.items()}
    return changes


ANGLES = ("contact_angle", "contact_angle_parameter")


@settings(max_examples=15, deadline=None)
@given(ws=_factors(WHEELSET), frame=_factors(FRAME), angles=_factors(ANGLES))
def test_bogie_matches_the_bogie(ws, frame, angles):
    base = Bogie().replace(secondary_yaw_damping=5.0e4)  # the default has none: give it a value to check
    model = base.replace(**_bogie_changes(base, ws, frame, angles))
    for speed in SPEEDS:
        assert_derived(bogie(), system_matrices(model, speed), model, speed)


@settings(max_examples=10, deadline=None)
@given(
    ws=_factors(WHEELSET),
    frame=_factors(FRAME),
    angles=_factors(ANGLES),
    body=st.fixed_dictionaries({n: st.floats(lo, hi) for n, (lo, hi) in BODY.items()}),
)
def test_lateral_car_matches_the_car(ws, frame, angles, body):
    base = LateralCar().replace(secondary_yaw_damping=5.0e4)
    changes = _bogie_changes(base.bogie, ws, frame, angles) | {
        n: getattr(base, n) * f for n, f in body.items()
    }
    model = base.replace(**changes)
    for speed in SPEEDS:
        assert_derived(lateral_car(), system_matrices(model, speed), model, speed)


@pytest.mark.parametrize("model", [LateralCar(), COOPERRIDER_CAR], ids=["Manchester", "Cooperrider"])
def test_lateral_car_matches_the_published_cars(model):
    for speed in (10.0, 60.0):
        assert_derived(lateral_car(), system_matrices(model, speed), model, speed)


def test_bogie_frame_yaw_stiffness_closed_form():
    # Written out by hand: the frame yaws against two primary lateral springs at arm b (2 k_y b²),
    # two primary yaw springs (2 k_ψ) and the secondary yaw spring (k_sψ); the wheelset's lateral
    # row holds −2f₂₂ on its yaw (the creep force of the lateral creepage −ψ).
    d = bogie()
    named = {s.name: s for s, _ in d.parameters}
    ky, kpsi, kspsi, b, f22 = (named[n] for n in ("k_y", "k_psi", "k_{s\\psi}", "b", "f_22"))
    assert sympy.expand(d.K[1, 1] - (2 * ky * b**2 + 2 * kpsi + kspsi)) == 0
    assert sympy.expand(d.K[2, 3] + 2 * f22) == 0
    model = Bogie()
    K = model.matrices(30.0).K
    expected = 2 * model.wheelset.lateral_stiffness * model.semi_wheelbase**2
    expected += 2 * model.wheelset.yaw_stiffness + model.secondary_yaw_stiffness
    assert K[1, 1] == pytest.approx(expected, rel=1e-14)


def test_lateral_car_roll_closed_form():
    # By hand: the body's roll stiffness is 2 k_ϕ from the two bogies' roll springs, plus 2 h² k_sy
    # from the secondary lateral springs at the seat h below the centre, less m g h of the weight;
    # a cross-level c under one wheelset tilts its frame by c/(4a), so G_K[ϕ, c] = k_ϕ/(4a).
    model = LateralCar()
    mats = model.matrices(40.0)
    k_sy = model.bogie.secondary_lateral_stiffness
    h, kphi, a = model.body_height, model.roll_stiffness, model.wheelset.half_gauge
    expected = 2 * kphi + 2 * h**2 * k_sy - model.body_mass * GRAVITY * h
    derived = lateral_car().numeric(model, 40.0)
    for K in (mats.K, derived[2]):
        assert K[2, 2] == pytest.approx(expected, rel=1e-13)
    for GK in (mats.GK, derived[3]):
        assert GK[2, 4] == pytest.approx(kphi / (4 * a), rel=1e-13)


def test_derivations_are_cached_and_name_their_coordinates():
    assert bogie() is bogie() and lateral_car() is lateral_car()
    assert len(lateral_car().coordinates) == 15 and len(lateral_car().inputs) == 8
    assert bogie().labels[:2] == ("y_f", "psi_f")
