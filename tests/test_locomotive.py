"""Tests for the six-axle locomotive (raildyn.vehicles.locomotive): closed forms, filter zeros, bad input."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn.constants import GRAVITY
from raildyn.vehicles import response as resp
from raildyn.vehicles.locomotive import DEFAULT_LOCOMOTIVE, VerticalLocomotive
from raildyn.vibration import modal_analysis

LOCO = DEFAULT_LOCOMOTIVE


def _two_dof(m1, k1, m2, k2):
    """ω² of m1 on k1 on m2 on k2 (ground), from the characteristic quadratic."""
    a, b, c = m1 * m2, -(m1 * (k1 + k2) + m2 * k1), k1 * k2
    d = np.sqrt(b * b - 4 * a * c)
    return np.array([(-b - d) / (2 * a), (-b + d) / (2 * a)])


def test_static_deflection_matches_hand_calculation():
    q = LOCO.linear_system().static_deflection()
    # each truck: half the body on one secondary; half body + frame on three primaries
    truck = (LOCO.body_mass / 2 + LOCO.truck_mass) * GRAVITY / (3 * LOCO.primary_stiffness)
    body = truck + LOCO.body_mass / 2 * GRAVITY / LOCO.secondary_stiffness
    np.testing.assert_allclose(q[[0, 2, 4]], [-body, -truck, -truck], rtol=1e-12)
    np.testing.assert_allclose(q[[1, 3, 5]], 0.0, atol=1e-14)


def test_undamped_frequencies_match_closed_forms(reference):
    v = LOCO.linear_system()
    got = np.sort(modal_analysis(v.M, v.K).natural_frequencies ** 2)
    ks, kp, s, a, mt = (
        LOCO.secondary_stiffness,
        LOCO.primary_stiffness,
        LOCO.semi_truck_spacing,
        LOCO.axle_spacing,
        LOCO.truck_mass,
    )
    bounce = _two_dof(LOCO.body_mass, 2 * ks, 2 * mt, 6 * kp)
    pitch = _two_dof(LOCO.body_pitch_inertia, 2 * ks * s**2, 2 * mt * s**2, 6 * kp * s**2)
    truck_pitch = 2 * kp * a**2 / LOCO.truck_pitch_inertia  # axles at ±a (the middle one has no arm)
    want = np.sort(np.concatenate([bounce, pitch, [truck_pitch] * 2]))
    # symmetric eigenproblem against the quadratic formula: rounding only
    reference(
        6,
        "vertical locomotive's undamped frequencies",
        "two-mass closed forms",
        "closed form",
        np.abs(got / want - 1).max(),
        1e-9,
    )


@settings(max_examples=50, deadline=None)
@given(speed=st.floats(5.0, 50.0))
def test_property_three_axle_filter_zeros(speed):
    """Body bounce sees 1 + e^{-iωa/V} + e^{-2iωa/V}: zero at λ = 3a and 3a/2 (cube roots of unity)."""
    v = LOCO.linear_system()
    lam = np.array([3 * LOCO.axle_spacing, 1.5 * LOCO.axle_spacing])
    H = resp.track_frf(v, 2 * np.pi * speed / lam, speed, "body z")
    scale = np.abs(resp.track_frf(v, np.linspace(0.5, 60, 300), speed, "body z")).max()
    # exact cancellation of three unit phasors: rounding of the exponentials
    assert np.abs(H).max() < 1e-12 * scale


def test_bad_input():
    with pytest.raises(ValueError, match="truck_mass"):
        VerticalLocomotive(truck_mass=-3.0)
    with pytest.raises(ValueError, match="axle_spacing"):
        VerticalLocomotive(axle_spacing=7.0)
    with pytest.raises(ValueError, match="secondary_damping"):
        VerticalLocomotive(secondary_damping=-1.0)


def test_issue_15_body_on_two_trucks_refuses_an_inconsistent_layout():
    from raildyn.vehicles.vertical import body_on_two_trucks

    a, s = LOCO.axle_spacing, LOCO.semi_truck_spacing
    args = dict(
        labels=("body z", "body θ", "truck1 z", "truck1 θ", "truck2 z", "truck2 θ"),
        body_mass=LOCO.body_mass, body_pitch_inertia=LOCO.body_pitch_inertia, truck_mass=LOCO.truck_mass,
        truck_pitch_inertia=LOCO.truck_pitch_inertia, semi_truck_spacing=s, axle_offsets=(a, 0.0, -a),
        primary_stiffness=LOCO.primary_stiffness, primary_damping=LOCO.primary_damping,
        secondary_stiffness=LOCO.secondary_stiffness, secondary_damping=LOCO.secondary_damping,
        axle_positions=LOCO.axle_positions,
    )  # fmt: skip
    system = body_on_two_trucks(**args)
    np.testing.assert_array_equal(system.M, LOCO.linear_system().M)
    for change, word in (
        (dict(axle_positions=np.zeros(6)), "axle_positions"),
        (dict(axle_offsets=(a, a, -a)), "axle_offsets"),
        (dict(axle_offsets=(2 * s, 0.0, -a)), "axle_offsets"),
        (dict(semi_truck_spacing=1e300), "semi_truck_spacing"),
        (dict(truck_mass=-1.0), "truck_mass"),
        (dict(labels="body z"), "labels"),
    ):
        with pytest.raises((TypeError, ValueError), match=rf"\b{word}\b"):
            body_on_two_trucks(**(args | change))
