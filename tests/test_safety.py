"""Running safety in a curve (raildyn.curving.safety): each criterion against a closed form or an
independent computation.

* Prud'homme's limit and the limit twist: their formulas, number by number;
* unloading on twisted track: the closed form against the hand computation for the Manchester car,
  and against an independent minimisation of the springs' energy (body and frames free to roll);
* overturning: the cant deficiency at which the inner wheels lift, by hand from the moment
  balance, with and without the body's roll and a side wind; and, with the roll suppressed, the
  load transfer of the quasi-static equilibrium itself;
* wheel climb and track shift: the assessment reads the equilibrium's Y and Q and the contact's own
  flange angle and friction.
"""

import matplotlib.pyplot as plt
import numpy as np
import pytest

from raildyn.constants import GRAVITY
from raildyn.curving import (
    SafetyAssessment,
    limit_twist,
    prudhomme_limit,
    quasi_static_curving,
    safety_assessment,
    twist_unloading,
)
from raildyn.curving.climb import nadal_limit, weinstock_limit
from raildyn.curving.safety import MANCHESTER_PRIMARY_ROLL_STIFFNESS
from raildyn.track import cant_deficiency
from raildyn.vehicles import Bogie, LateralCar, VerticalCar
from raildyn.wheelset import WheelRailContact

CAR = LateralCar()
V, R, D = 100 / 3.6, 600.0, 0.1  # m/s, m, m: 97 mm of cant deficiency


@pytest.fixture(scope="module")
def assessment() -> SafetyAssessment:
    return safety_assessment(CAR, V, R, D)


# ---------------------------------------------------------------------------------- Prud'homme


def test_prudhomme_limit_is_ten_kilonewtons_plus_a_third_of_the_axle_load():
    # closed form: (10 + P/3) kN, P in kN; α = 0.85 for a freight wagon (exact arithmetic, 1e-12)
    assert prudhomme_limit(120e3) == pytest.approx(50e3, rel=1e-12)
    assert prudhomme_limit(225e3, 0.85) == pytest.approx(0.85 * (10e3 + 75e3), rel=1e-12)
    # EN 14363's form 10 + 2Q₀/3 with Q₀ = P/2 is the same number
    P = np.array([80e3, 160e3, 250e3])
    np.testing.assert_allclose(prudhomme_limit(P), 10e3 + 2 * (P / 2) / 3, rtol=1e-12)


def test_the_assessment_holds_each_axles_track_shift_force_to_prudhomme(assessment):
    state = assessment.equilibrium
    np.testing.assert_allclose(assessment.track_shift_force, np.abs(state.wheel_lateral.sum(axis=1)))
    P = CAR.wheelset.axle_load
    assert assessment.prudhomme_limit == pytest.approx(10e3 + P / 3, rel=1e-12)
    freight = safety_assessment(CAR, V, R, D, factor=0.85, start=state)
    assert freight.prudhomme_limit == pytest.approx(0.85 * assessment.prudhomme_limit, rel=1e-12)


# ---------------------------------------------------------------------------------- twist


def test_limit_twist_has_its_three_pieces_and_meets_at_their_ends():
    np.testing.assert_allclose(limit_twist([2.5, 4.0, 10.0, 20.0, 30.0]), [7e-3, 7e-3, 4e-3, 3e-3, 3e-3])
    assert limit_twist(19.0) == pytest.approx(1e-3 * (20 / 19 + 2), rel=1e-12)


def test_twist_unloading_of_the_manchester_car_by_hand():
    # Iwnicki (1998): P = 44482 kg g / 4, a = 0.75 m, b = 1.28 m, s = 9.5 m; k_φ1 = 2 × 1220 kN/m × 1 m²,
    # k_φ2 = 2 × 430 kN/m × 1 m² + 940 kN·m/rad (the anti-roll bar). Twists: 7 ‰ over 2.56 m,
    # (20/19 + 2) ‰ over 19 m.
    P, a, b, s = 44482.0 * GRAVITY / 4, 0.75, 1.28, 9.5
    k1, k2 = 2 * 1220e3, 2 * 430e3 + 940e3
    g_bogie, g_car = 7e-3, (20 / 19 + 2) * 1e-3
    bogie = k1 * g_bogie * b / (4 * a * a)  # 9716.6 N
    series = 1.0 / (1.0 / (2 * k1) + 1.0 / k2)  # 1.3150e6 N·m/rad
    car = series * g_car * s / (8 * a * a)  # 8474 N
    hand = (bogie + car) / (P / 2)
    assert hand == pytest.approx(0.3336, abs=1e-4)
    assert twist_unloading(P, a, b, s, k1, k2) == pytest.approx(hand, rel=1e-12)
    assert MANCHESTER_PRIMARY_ROLL_STIFFNESS == k1 == VerticalCar().primary_stiffness
    assert CAR.roll_stiffness == k2


@pytest.mark.parametrize("k1, k2", [(2.44e6, 1.8e6), (5e6, 0.4e6), (0.8e6, 9e6)])
def test_twist_unloading_against_the_minimum_of_the_springs_energy(k1, k2):
    """An independent computation: the body and both frames free to roll, the four wheelsets rolled
    by the twist g x/(2a) at their x; the rolls minimise the springs' energy (a 3 × 3 linear solve),
    and the leading wheelset's primary moment over 2a is its ΔQ. The same twist over both bases.
    Both are exact, so they agree to rounding (rel 1e-12)."""
    P, a, b, s, g = 110e3, 0.75, 1.3, 9.0, 4e-3
    x = np.array([s + b, s - b, -s + b, -s - b])
    wheelset_roll = g * x / (2 * a)
    frame_of = [0, 0, 1, 1]
    # unknowns [frame 1, frame 2, body]: K q = f from ∂/∂q of Σ ½k1(φ_w − φ_f)² + Σ ½k2(φ_f − φ_b)²
    K = np.array([[2 * k1 + k2, 0.0, -k2], [0.0, 2 * k1 + k2, -k2], [-k2, -k2, 2 * k2]])
    f = np.zeros(3)
    for roll, frame in zip(wheelset_roll, frame_of, strict=True):
        f[frame] += k1 * roll
    frame_1, frame_2, body = np.linalg.solve(K, f)
    frames = np.array([frame_1, frame_2])
    moment = k1 * (wheelset_roll - frames[frame_of])
    independent = np.abs(moment).max() / (2 * a) / (P / 2)
    assert abs(body) < 1e-12 * abs(frame_1)  # the twist is antisymmetric: the body stays level
    closed = twist_unloading(P, a, b, s, k1, k2, bogie_twist=g, car_twist=g)
    assert closed == pytest.approx(independent, rel=1e-12)


def test_the_assessment_puts_the_car_on_its_limit_twists(assessment):
    assert assessment.bogie_twist == pytest.approx(7e-3)
    assert assessment.car_twist == pytest.approx(limit_twist(19.0))
    P, b, s = CAR.wheelset.axle_load, CAR.bogie.semi_wheelbase, CAR.semi_bogie_spacing
    expected = twist_unloading(P, 0.75, b, s, MANCHESTER_PRIMARY_ROLL_STIFFNESS, CAR.roll_stiffness)
    assert assessment.twist_unloading == pytest.approx(expected, rel=1e-12)
    assert assessment.twist_limit == 0.6


# ---------------------------------------------------------------------------------- overturning


def _by_hand(car, h, limit=1.0, F=0.0, h_w=2.0):
    """The cant deficiency of overturning from the moment balance about the unloaded rail, m."""
    W, a, G = 4 * car.wheelset.axle_load, car.wheelset.half_gauge, 1.5
    m_b, h_b, k = car.body_mass, car.body_height, car.roll_stiffness
    stiff = 2 * k - m_b * GRAVITY * h_b
    s = m_b * GRAVITY * h_b / stiff
    # ΔQ/Q₀ = [W h a_q/g + m_b g h_b (s a_q/g + φ_w) + F h_w]/(a W), φ_w = F (h_w − (h − h_b))/stiff
    wind = F * h_w + m_b * GRAVITY * h_b * F * (h_w - (h - h_b)) / stiff
    a_q = (limit * a * W - wind) / (W * h / GRAVITY + m_b * h_b * s)
    return max(a_q, 0.0) * G / GRAVITY, s


def test_overturning_deficiency_by_hand(assessment):
    hand, s = _by_hand(CAR, 1.8)
    assert assessment.flexibility == pytest.approx(s, rel=1e-12)
    assert assessment.overturning_deficiency == pytest.approx(hand, rel=1e-12)
    # a rigid car tips at G a/h = 1.5 × 0.75/1.8 = 625 mm; the body's roll on its springs lowers that
    assert 0.5 < hand < 1.5 * 0.75 / 1.8
    # the unloading is linear in a_q through zero: at this curve's deficiency, its share of the limit
    assert assessment.overturning_unloading == pytest.approx(
        assessment.cant_deficiency / assessment.overturning_deficiency, rel=1e-12
    )


def test_the_unloading_is_the_equilibriums_transfer_plus_the_bodys_roll(assessment):
    # the equilibrium's own load transfer (Q_o − Q_i)/(Q_o + Q_i) = h a_q/(a g) on every axle, and the
    # body's roll s a_q/g moving its weight h_b s a_q/g sideways: m_b h_b s a_q/(a W) more
    Q = assessment.equilibrium.wheel_vertical
    transfer = (Q[:, 1] - Q[:, 0]) / (Q[:, 1] + Q[:, 0])
    a_q = assessment.equilibrium.unbalanced_acceleration
    W, a = 4 * CAR.wheelset.axle_load, CAR.wheelset.half_gauge
    roll = CAR.body_mass * CAR.body_height * assessment.flexibility * a_q / (a * W)
    np.testing.assert_allclose(assessment.overturning_unloading, transfer + roll, rtol=1e-12)
    # a car whose body does not roll tips at G a/h = 1.5 × 0.75/1.8 = 625 mm (rel 1e-4: the roll left
    # by the stiffest spring accepted, s ≈ 1.5e-4, moves it by 6e-5)
    stiff = safety_assessment(CAR.replace(roll_stiffness=9.9e8), V, R, D)
    assert stiff.overturning_deficiency == pytest.approx(1.5 * 0.75 / 1.8, rel=1e-4)


def test_wind_and_a_lower_limit_bring_overturning_closer():
    calm = safety_assessment(CAR, V, R, D)
    windy = safety_assessment(CAR, V, R, D, wind_force=40e3, wind_height=2.2, overturning_limit=0.9)
    hand, _ = _by_hand(CAR, 1.8, limit=0.9, F=40e3, h_w=2.2)
    assert windy.overturning_deficiency == pytest.approx(hand, rel=1e-12)
    assert windy.overturning_deficiency < calm.overturning_deficiency
    assert windy.overturning_unloading > calm.overturning_unloading
    # a gale that alone lifts the wheels: no cant deficiency left
    gale = safety_assessment(CAR, V, R, D, wind_force=400e3, wind_height=3.0)
    assert gale.overturning_deficiency == 0.0
    assert gale.overturning_unloading > 1.0 and not gale.safe


def test_a_cant_excess_unloads_the_outer_rail_as_a_deficiency_does_the_inner():
    slow = safety_assessment(CAR, 5.0, R, 0.15)
    assert slow.cant_deficiency < 0
    assert slow.overturning_unloading == pytest.approx(
        -slow.cant_deficiency / slow.overturning_deficiency, rel=1e-12
    )


# ---------------------------------------------------------------------------------- wheel climb


def test_wheel_climb_uses_the_equilibriums_quotients_and_the_contacts_flange_angle(assessment):
    state = assessment.equilibrium
    np.testing.assert_allclose(assessment.wheel_quotient, state.derailment_quotient, rtol=1e-12)
    np.testing.assert_allclose(assessment.axle_sum, state.derailment_quotient.sum(axis=1), rtol=1e-12)
    contact = WheelRailContact()
    assert assessment.flange_angle == contact.flange_angle
    assert assessment.nadal_limit == pytest.approx(nadal_limit(contact.flange_angle, contact.friction))
    steep = WheelRailContact(flange_angle=np.radians(65.0), friction=0.4)
    other = safety_assessment(CAR, V, R, D, contact=steep)
    assert other.nadal_limit == pytest.approx(nadal_limit(np.radians(65.0), 0.4), rel=1e-12)
    assert other.weinstock_limit == pytest.approx(weinstock_limit(np.radians(65.0), 0.4), rel=1e-12)
    assert other.nadal_limit < assessment.nadal_limit  # a shallower flange, more friction: lower


def test_the_criteria_and_the_verdict(assessment):
    criteria = assessment.criteria
    assert set(criteria) == set(assessment.utilisation)
    assert criteria["Nadal Y/Q"] == (assessment.wheel_quotient.max(), assessment.nadal_limit)
    assert assessment.safe  # 97 mm of deficiency in 600 m at 100 km/h: every criterion within its limit
    assert assessment.cant_deficiency == pytest.approx(cant_deficiency(V, R, D))


# ---------------------------------------------------------------------------------- plot and input


def test_the_plot_draws_one_bar_per_criterion_and_updates_in_place(assessment):
    artists = assessment.plot()
    figure = artists["limit"].figure
    widths = [bar.get_width() for bar in artists["bars"]]
    np.testing.assert_allclose(widths, list(assessment.utilisation.values()))
    faster = safety_assessment(CAR, 130 / 3.6, R, D, start=assessment.equilibrium)
    again = faster.plot(artists=artists)
    assert again is artists and artists["limit"].figure is figure
    np.testing.assert_allclose([b.get_width() for b in artists["bars"]], list(faster.utilisation.values()))
    assert len(plt.get_fignums()) == 1


@pytest.mark.parametrize(
    "change, name",
    [
        ({"speed": -1.0}, "speed"),
        ({"radius": 10.0}, "radius"),
        ({"cant": 0.5}, "cant"),
        ({"cg_height": 0.5}, "cg_height"),  # below the body's springs
        ({"factor": 1.5}, "factor"),
        ({"wind_force": -1.0}, "wind_force"),
        ({"overturning_limit": 1.2}, "overturning_limit"),
        ({"primary_roll_stiffness": 0.0}, "primary_roll_stiffness"),
    ],
)
def test_bad_input_names_the_parameter(change, name):
    args = {"speed": V, "radius": R, "cant": D} | change
    with pytest.raises(ValueError, match=name):
        safety_assessment(CAR, **args)


def test_bad_models_and_spacings_are_refused():
    with pytest.raises(TypeError, match="model"):
        safety_assessment(Bogie(), V, R, D)
    with pytest.raises(ValueError, match="semi_bogie_spacing"):
        twist_unloading(110e3, 0.75, 1.3, 1.0, 2e6, 2e6)
    with pytest.raises(ValueError, match="bogie_twist"):
        twist_unloading(110e3, 0.75, 1.3, 9.0, 2e6, 2e6, bogie_twist=7.0)  # ‰ typed for m/m
    with pytest.raises(ValueError, match="factor"):
        prudhomme_limit(100e3, 0.0)
    with pytest.raises(ValueError, match="base"):
        limit_twist(-2.0)


def test_the_equilibrium_is_the_quasi_static_one(assessment):
    state = quasi_static_curving(CAR.nonlinear(), V, R, D)
    np.testing.assert_allclose(
        assessment.equilibrium.wheel_lateral, state.wheel_lateral, rtol=1e-9, atol=1e-6
    )


def test_on_real_profiles_nadal_takes_the_pairs_own_flange_angle():
    from raildyn.contact.profiles import s1002_wheel, uic60_rail
    from raildyn.wheelset import profile_contact

    contact = profile_contact(s1002_wheel(), uic60_rail(1 / 40))
    r = safety_assessment(CAR, V, R, D, contact=contact)
    assert r.flange_angle == contact.flange_angle
    assert np.degrees(r.flange_angle) == pytest.approx(70.0, abs=0.5)  # the S1002 flank, about 70°
    assert r.nadal_limit == pytest.approx(nadal_limit(contact.flange_angle, contact.friction), rel=1e-12)
    np.testing.assert_allclose(r.wheel_quotient, r.equilibrium.derailment_quotient, rtol=1e-12)


# ---------------------------------------------------------------------------------- the widget


def test_the_widget_shows_the_assessment_of_its_controls():
    from widget_helpers import status_line

    from raildyn.widgets import chapter08_safety

    container, update = chapter08_safety.safety_chart()
    bars = list(container.live.figure.axes[0].patches)
    update(speed_kmh=120.0, radius=800.0, cant_mm=80.0, wind_kn=60.0)
    status = status_line(container)
    expected = safety_assessment(
        CAR, 120 / 3.6, 800.0, 0.08, contact=chapter08_safety._contact(), wind_force=60e3, wind_height=2.0
    )
    assert f"twist ΔQ/Q₀ {expected.twist_unloading:.2f}" in status
    assert f"overturning ΔQ/Q₀ {expected.overturning_unloading:.2f}" in status
    assert f"lift at {1e3 * expected.overturning_deficiency:.0f} mm" in status
    # the same bars, moved in place to the new utilisations (the widget starts Newton from its last
    # equilibrium, this test from the linear state: they meet to the search's tolerance, rel 1e-6)
    assert container.live.figure.axes[0].patches[:] == bars
    np.testing.assert_allclose([b.get_width() for b in bars], list(expected.utilisation.values()), rtol=1e-6)
    # beyond every equilibrium (the inner wheels lifted) the bars go and the status says why
    update(speed_kmh=200.0, radius=300.0)
    assert "no equilibrium" in status_line(container)
    assert not any(b.get_visible() for b in bars)
