"""Tests for the freight car on three-piece trucks (raildyn.vehicles.freight).

Tiers: closed forms (static deflection, bounce/pitch/roll frequencies, 4 F X per
cycle and its smoothing deficit), symmetry (joints in phase cannot roll the car),
the nonlinear rocking peak at the predicted speed, and bad input.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn.vehicles import response as resp
from raildyn.vehicles.freight import FreightCar, rock_and_roll, wedge_energy_per_cycle
from raildyn.vibration import modal_analysis

CAR = FreightCar()


def test_static_deflection_is_quarter_weight_over_nest():
    q = CAR.linear().static_deflection()
    # four equal nests share the weight: δ = m g / 4k (0.06 m by construction); rounding only
    assert q[0] == pytest.approx(-CAR.body_mass * 9.81 / (4 * CAR.nest_stiffness), rel=1e-12)
    np.testing.assert_allclose(q[1:], 0.0, atol=1e-15)


def test_natural_frequencies_match_closed_forms():
    v = CAR.linear()
    got = np.sort(modal_analysis(v.M, v.K).natural_frequencies) / (2 * np.pi)
    want = np.sort(list(CAR.natural_frequencies().values()))
    # bounce, pitch and roll are uncoupled for a symmetric car: eigenvalues of a diagonal pencil
    np.testing.assert_allclose(got, want, rtol=1e-12)


def test_roll_stiffness_loses_the_weight_term():
    k, b = CAR.nest_stiffness, CAR.semi_spring_spacing
    assert CAR.roll_stiffness == pytest.approx(4 * k * b**2 - CAR.body_mass * 9.81 * CAR.cg_height, rel=1e-14)
    # the resonance sits where one cross-level cycle per rail meets f_roll
    assert CAR.roll_resonance_speed(11.9) == pytest.approx(CAR.natural_frequencies()["roll"] * 11.9)


def test_wedge_energy_is_four_f_x():
    F, X, f = 8.0e3, 0.012, 1.3
    # ideal Coulomb: ∮ F sgn(v) v dt = F · (total travel 4X); midpoint rule, crossings between nodes
    assert wedge_energy_per_cycle(F, X, f) == pytest.approx(4 * F * X, rel=1e-7)


@settings(max_examples=50, deadline=None)
@given(F=st.floats(1e2, 5e4), X=st.floats(1e-2, 5e-2), f=st.floats(0.5, 5.0), eps=st.floats(1e-4, 2e-3))
def test_property_smooth_wedge_deficit(F, X, f, eps):
    """F tanh(v/ε) dissipates less than 4FX by F ε² π²/(6 X ω²) to leading order.

    Near each of the two velocity zeros per cycle v ≈ Xω² s, and ∫₀^∞ u(1 − tanh u) du = π²/24;
    the next term is smaller by (ε/(Xω))² <= 0.004 here, so 2 % of the deficit (plus quadrature).
    """
    w = 2 * np.pi * f
    E = wedge_energy_per_cycle(F, X, f, velocity_scale=eps, n=200_000)
    deficit = 4 * F * X - E
    predicted = F * eps**2 * np.pi**2 / (6 * X * w**2)
    assert deficit == pytest.approx(predicted, rel=0.02, abs=1e-9 * F * X)


def test_in_phase_joints_do_not_roll_the_car():
    v = CAR.linear(equivalent_damping=2e4)
    w = np.linspace(0.5, 30, 50)
    # vertical irregularity (both rails alike) gives no roll: the two nests of a truck cancel exactly
    assert np.abs(resp.track_frf(v, w, 10.0, "body φ")).max() == 0.0
    # cross-level does
    assert np.abs(resp.track_frf(v, w, 10.0, "body φ", component="cross_level")).max() > 0


def test_rocking_peaks_near_the_roll_resonance():
    Vr = CAR.roll_resonance_speed()
    speeds = Vr * np.array([0.6, 0.8, 1.0, 1.2, 1.4])
    r = rock_and_roll(CAR, speeds, cycles=16)
    # the friction shifts and blunts the peak but, on a 20 % speed grid, it stays at the linear resonance
    assert int(np.argmax(r.roll_amplitude)) == 2
    assert r.roll_amplitude[2] > 2 * max(r.roll_amplitude[0], r.roll_amplitude[-1])
    assert r.resonance_speed == pytest.approx(Vr)


def test_bad_input():
    with pytest.raises(ValueError, match="body_mass"):
        FreightCar(body_mass=0.0)
    with pytest.raises(ValueError, match="wedge_friction"):
        FreightCar(wedge_friction=-1.0)
    with pytest.raises(ValueError, match="roll stiffness"):
        FreightCar(cg_height=20.0)
    with pytest.raises(ValueError, match="speeds"):
        rock_and_roll(CAR, [-1.0])
    with pytest.raises(ValueError, match="amplitude"):
        wedge_energy_per_cycle(1.0, 0.0, 1.0)
    with pytest.raises(ValueError, match="equivalent_damping"):
        CAR.linear(-1.0)
