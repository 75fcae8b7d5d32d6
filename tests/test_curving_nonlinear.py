"""Nonlinear curving: the nonlinear lateral model on a curve, its quasi-static equilibrium
(raildyn.curving.quasi_static) and the dynamic curve entry (raildyn.curving.entry)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from raildyn.constants import GRAVITY
from raildyn.contact.geometry import contact_geometry
from raildyn.contact.profiles import conical_wheel, s1002_wheel, uic60_rail
from raildyn.curving import curve_entry, curving_map, quasi_static_curving, steady_curving
from raildyn.curving.climb import nadal_limit
from raildyn.errors import SolverError
from raildyn.track import Curve, balance_speed
from raildyn.vehicles import EMPTY_FREIGHT_CAR, LATERAL_LOCOMOTIVE, LOADED_FREIGHT_CAR, Bogie, LateralCar
from raildyn.wheelset import WheelRailContact, Wheelset, contact_forces, profile_contact, wheel_forces

VEHICLES = [LateralCar(), LOADED_FREIGHT_CAR, EMPTY_FREIGHT_CAR, LATERAL_LOCOMOTIVE]


@pytest.mark.parametrize("model", VEHICLES, ids=["car", "loaded", "empty", "locomotive"])
def test_in_gentle_curves_the_equilibrium_tends_to_the_linear_steady_state(model):
    # Off the flanges only the creep saturation differs from the linear model, by a relative amount that
    # grows with the creep force, ∝ 1/R: the nonlinear equilibrium tends to the linear one at first order.
    # Measured (max |Δq| / max |q|): 0.2 to 1.0 % at 20 km, 4.1 to 4.3 times that at 5 km.
    nonlinear = model.nonlinear()
    gap = []
    for radius in (5000.0, 20000.0):
        state = quasi_static_curving(nonlinear, 30.0, radius, 0.0)
        linear = steady_curving(model, 30.0, radius, 0.0)
        assert not state.flange_contact.any()
        gap.append(np.abs(state.displacement - linear.displacement).max() / np.abs(linear.displacement).max())
    assert gap[1] < 0.015
    assert 3.5 < gap[0] / gap[1] < 4.5


@pytest.mark.parametrize("model", VEHICLES, ids=["car", "loaded", "empty", "locomotive"])
def test_the_rails_carry_the_unbalanced_force(model):
    # Equilibrium of the whole vehicle in a sharp curve with the flanges on: the rails' lateral forces on
    # the wheelsets (creep, gravity and flange: the guiding forces) add up to m_total·a_q inwards. The
    # searches stop at 1e-9 of the weight, so rel 1e-6 of a force of tens of kN is far inside it.
    system = model.linear_system()
    state = quasi_static_curving(model.nonlinear(), 20.0, 300.0, 0.05)
    assert state.flange_contact.any()
    lateral = np.array([s.endswith(" y") for s in system.labels], dtype=float)
    total_mass = lateral @ system.M @ lateral
    assert state.guiding_force.sum() == pytest.approx(total_mass * state.unbalanced_acceleration, rel=1e-6)
    # The flange force is the share of the guiding force the flange spring carries, where it touches.
    np.testing.assert_array_equal(state.flange_force != 0.0, state.flange_contact)
    assert np.all(state.wear_number >= 0.0)


def test_the_manchester_car_flanges_with_its_leading_wheelsets_in_600_m():
    # At the balance speed for 100 mm of cant the leading wheelset of each bogie runs past the 9.1 mm
    # flangeway clearance, with an angle of attack above the geometric b/R = 2.1 mrad of a rigid bogie
    # (the flange forces it further round), and the trailing ones run off the flange near radial.
    state = quasi_static_curving(LateralCar().nonlinear(), balance_speed(600.0, 0.1), 600.0, 0.1)
    assert state.flange_contact.tolist() == [True, False, True, False]
    assert np.all(state.angle_of_attack[[0, 2]] > 1.28 / 600.0)
    assert np.all(np.abs(state.angle_of_attack[[1, 3]]) < 1e-3)
    assert np.all(state.offset[[0, 2]] > 9.1e-3)
    # The guiding forces of each wheelset are its contact forces there, by definition.
    ws = LateralCar().bogie.wheelset
    fy, _ = contact_forces(ws, WheelRailContact(), -state.offset[0], -state.angle_of_attack[0], 0.0,
                           state.speed / 600.0, state.speed)  # fmt: skip
    assert state.guiding_force[0] == pytest.approx(float(fy), rel=1e-12)


def test_the_wheel_loads_and_quotients():
    # Q: half the axle load each at the balance speed; above it the roll moment m a_q h moves
    # ΔQ = (W/2)(h/a)(a_q/g) to the outer wheel (rounding: rel 1e-12). Y/Q of the leading outer wheel stays
    # below Nadal's limit for a 70° flange and μ = 0.3 (1.38): the car does not climb in 600 m.
    ws = LateralCar().bogie.wheelset
    W, a = ws.axle_load, ws.half_gauge
    at_balance = quasi_static_curving(LateralCar().nonlinear(), balance_speed(600.0, 0.1), 600.0, 0.1)
    np.testing.assert_allclose(at_balance.wheel_vertical, W / 2, rtol=1e-12)
    fast = quasi_static_curving(LateralCar().nonlinear(), 28.0, 600.0, 0.1, cg_height=1.5)
    transfer = 0.5 * W * 1.5 / a * fast.unbalanced_acceleration / GRAVITY
    np.testing.assert_allclose(
        fast.wheel_vertical[:, 1] - fast.wheel_vertical[:, 0], 2 * transfer, rtol=1e-12
    )
    np.testing.assert_allclose(fast.wheel_vertical.sum(axis=1), W, rtol=1e-12)
    assert 0.0 < fast.derailment_quotient[0, 1] < nadal_limit(np.radians(70.0), 0.3)
    # The outer flange pushes the leading wheel inwards: its Y points to the curve's centre.
    assert fast.wheel_lateral[0, 1] > 0.0


def test_the_map_holds_the_single_points_and_the_forces_vanish():
    # Every point of a map is the equilibrium quasi_static_curving finds alone (the same Newton and the same
    # tolerance, from other starts: agreement to 1e-9 m is far inside the 1e-9-of-the-weight residual's
    # displacement, about 1e-4 N over 1e6 N/m), and arc_forces vanish there.
    model = Bogie().nonlinear()
    speeds, radii = np.array([12.0, 20.0, 25.0]), np.array([200.0, 450.0, 1500.0])
    grid = curving_map(model, speeds, radii, 0.1)
    for i, R in enumerate(radii):
        for j, V in enumerate(speeds):
            one = quasi_static_curving(model, V, R, 0.1)
            np.testing.assert_allclose(grid.offset[i, j], one.offset, atol=1e-9)
            np.testing.assert_allclose(grid.angle_of_attack[i, j], one.angle_of_attack, atol=1e-9)
            np.testing.assert_allclose(grid.derailment_quotient[i, j], one.derailment_quotient, atol=1e-6)
            residual = model.arc_forces(one.displacement, V, 1.0 / R, one.unbalanced_acceleration)
            assert np.abs(residual).max() < 1e-9 * GRAVITY * np.trace(model.system.M)
    # Sharper curves and higher speeds push the leading wheelset harder against its flange.
    assert np.all(np.diff(grid.flange_force[:, -1, 0]) <= 0.0)
    artists = grid.plot(quantity="derailment_quotient", wheelset=0)
    assert artists["contours"] is not None


def test_a_start_near_the_answer_gives_the_same_answer():
    # A widget re-solves from the last equilibrium: the same point to the search's tolerance.
    model = LateralCar().nonlinear()
    cold = quasi_static_curving(model, 25.0, 600.0, 0.1, flange_angle=np.radians(65.0))
    near = quasi_static_curving(model, 26.0, 620.0, 0.1)
    warm = quasi_static_curving(model, 25.0, 600.0, 0.1, flange_angle=np.radians(65.0), start=near)
    np.testing.assert_allclose(warm.displacement, cold.displacement, atol=1e-9)
    np.testing.assert_allclose(warm.derailment_quotient, cold.derailment_quotient, atol=1e-6)


def test_a_fast_car_in_a_gentle_curve_is_found_by_the_homotopy():
    # At 140 km/h in 1000 m with no cant (a_q = 1.5 m/s²) Newton from the linear state stalls at the
    # flange's edge and the neighbours' continuation has no neighbour; raising the curve's load from
    # nothing finds the equilibrium, off the flanges, with the forces balanced.
    model = LateralCar().nonlinear()
    state = quasi_static_curving(model, 140 / 3.6, 1000.0)
    residual = model.arc_forces(state.displacement, 140 / 3.6, 1e-3, state.unbalanced_acceleration)
    assert np.abs(residual).max() < 1e-9 * GRAVITY * np.trace(model.system.M)
    assert not state.flange_contact.any() and np.all(np.abs(state.offset) < 9.1e-3)


def test_arc_jacobian_is_the_forces_derivative():
    # Against forward differences of arc_forces in every coordinate (the step 1e-7 of both: they agree to
    # about 1e-11 of the largest entry, measured; 1e-7 leaves room for a state near a bend of the laws).
    for model in (LateralCar().nonlinear(), LOADED_FREIGHT_CAR.nonlinear()):
        n = model.system.size
        q = np.random.default_rng(2).normal(scale=4e-3, size=(n, 2))
        args = (np.array([20.0, 30.0]), np.array([1 / 600, 1 / 400]), np.array([0.3, -0.1]))
        J = model.arc_jacobian(q, *args)
        F = model.arc_forces(q, *args)
        for j in range(n):
            shifted = q.copy()
            shifted[j] += 1e-7
            np.testing.assert_allclose(J[:, :, j], ((model.arc_forces(shifted, *args) - F) / 1e-7).T,
                                       atol=1e-7 * np.abs(J).max())  # fmt: skip


def test_arc_forces_are_the_right_hand_side_on_an_arc():
    # On a long arc the model's right-hand side at rest is M⁻¹ times arc_forces, to rounding.
    model = LateralCar().nonlinear()
    R, D = 600.0, 0.1
    on_arc = model.replace(
        curve=Curve(radius=R, cant=D, transition_length=0.0, arc_length=400.0, straight=0.0), start=200.0
    )
    n = model.system.size
    q = np.random.default_rng(0).normal(scale=5e-3, size=n)
    forces = model.arc_forces(q, 25.0, 1.0 / R, 25.0**2 / R - GRAVITY * D / 1.5)
    np.testing.assert_allclose(model.system.M @ on_arc.rhs(0.0, np.concatenate([q, 0 * q]), 25.0)[n:], forces,
                               rtol=1e-12, atol=1e-6)  # fmt: skip
    # A batch is its columns.
    batch = model.arc_forces(np.stack([q, 2 * q], axis=1), [25.0, 30.0], 1.0 / R, [0.1, 0.2])
    np.testing.assert_allclose(batch[:, 1], model.arc_forces(2 * q, 30.0, 1.0 / R, 0.2), rtol=1e-12)


def test_the_curve_entry_settles_to_the_quasi_static_equilibrium():
    # The Manchester car enters a 600 m curve through a 60 m clothoid at 5 m/s above the balance speed;
    # after 150 m of arc the transient has died away (it decays by e in a few metres of creep damping):
    # measured 1.1e-7 m, 6.5e-8 rad and 0.3 N from the quasi-static answer (7e-10 m after 250 m). Tolerances
    # 1e-6 m, 1e-6 rad and 20 N (1e-6 m on the 14.6 MN/m flange spring is 15 N).
    speed = balance_speed(600.0, 0.1) + 5.0
    curve = Curve(radius=600.0, cant=0.1, transition_length=60.0, arc_length=150.0, straight=20.0)
    run = curve_entry(LateralCar().nonlinear(), speed, curve)
    state = quasi_static_curving(LateralCar().nonlinear(), speed, 600.0, 0.1)
    np.testing.assert_allclose(run.offset[:, -1], state.offset, atol=1e-6)
    np.testing.assert_allclose(run.angle_of_attack[:, -1], state.angle_of_attack, atol=1e-6)
    np.testing.assert_allclose(run.flange_force[:, -1], state.flange_force, atol=20.0)
    # On entry the leading flange force overshoots its steady value (the transient the issue asks for).
    assert run.flange_force[0].max() > state.flange_force[0]
    # Before the curve every wheelset is centred; the run starts on the straight.
    assert np.all(np.abs(run.offset[:, 0]) < 1e-12)
    artists = run.plot()
    assert len(artists["lines"]) == 4
    run.plot(artists=artists, quantity="flange_force")


def test_the_curve_model_on_tangent_track_is_the_tangent_model():
    # A curve whose straight reaches past the whole run leaves the right-hand side that of tangent track.
    model = Bogie().nonlinear()
    on_curve = model.replace(curve=Curve(straight=1000.0), start=0.0)
    state = np.random.default_rng(1).normal(scale=1e-3, size=model.state_size)
    np.testing.assert_allclose(
        on_curve.rhs(0.5, state, 30.0), model.rhs(0.5, state, 30.0), rtol=1e-12, atol=1e-9
    )


def test_a_runs_samples_relative_to_the_track_at_once_are_each_samples_own():
    # The bogie's two wheelsets (x = ±b) at 30 m/s over the clothoid, the arc and the track beyond,
    # read at once (one time per column) and one sample at a time: the same numbers, to rounding.
    curve = Curve(radius=800.0, transition_length=40.0, arc_length=30.0, straight=0.0)
    model = Bogie().nonlinear().replace(curve=curve, start=-5.0)
    t = np.linspace(0.0, 4.0, 9)
    states = np.random.default_rng(2).normal(scale=1e-3, size=(model.state_size, t.size))
    offset, yaw = model.relative_to_track(t, states, 30.0)
    for j, tj in enumerate(t):
        one = model.relative_to_track(tj, states[:, j], 30.0)
        np.testing.assert_allclose(offset[:, j], one[0], rtol=1e-14, atol=1e-18)
        np.testing.assert_allclose(yaw[:, j], one[1], rtol=1e-14, atol=1e-18)
    # On the arc (from s = 40 m to 70 m) y_t = x²/(2R) and ψ_t = x/R, whatever the time.
    b = model.system.wheelset_positions
    on_arc = model.relative_to_track(t[4], np.zeros(model.state_size), 30.0)  # s_c = 55 m
    assert 40.0 < 55.0 - abs(b).max() and 55.0 + abs(b).max() < 70.0
    np.testing.assert_allclose(on_arc[0], -b * b / 1600.0, rtol=1e-12)
    np.testing.assert_allclose(on_arc[1], -b / 800.0, rtol=1e-12)
    with pytest.raises(ValueError, match="t must be a number"):
        model.relative_to_track(t[:1], states[:, 0], 30.0)
    with pytest.raises(ValueError, match="t must have shape"):
        model.relative_to_track(t[:3], states, 30.0)


def test_the_profile_contact_holds_chapter_4s_geometry_and_finds_the_flange():
    # The tables are contact_geometry's at their samples (rounding) and between them within the linear
    # interpolation's error over 0.25 mm; the clearance is the last shift before a contact steeper than
    # 40° (S1002 on UIC 60 at 1:40: the tread contact's angle is 0.12 rad at 6.5 mm, the flange's 1.22 rad
    # at 7 mm). A cone has no flange and is refused.
    wheel, rail = s1002_wheel(), uic60_rail(1 / 40)
    contact = profile_contact(wheel, rail)
    assert contact.flange_clearance == pytest.approx(6.5e-3)
    on_grid = np.array([-6.5e-3, -2.0e-3, 0.0, 1.25e-3, 6.0e-3])
    geometry = contact_geometry(wheel, rail, on_grid)
    np.testing.assert_allclose(contact.rolling_radius_difference(on_grid), geometry.rolling_radius_difference,
                               atol=1e-12)  # fmt: skip
    np.testing.assert_allclose(contact.contact_angle_difference(on_grid), geometry.contact_angle_difference,
                               atol=1e-12)  # fmt: skip
    np.testing.assert_allclose(contact.tread_angles(on_grid), geometry.contact_angle, atol=1e-12)
    steeper = contact_geometry(wheel, rail, [7.0e-3]).contact_angle[0, 0]
    assert steeper > np.radians(40.0)
    # Beyond the clearance the tread's difference goes on along its last slope (it keeps growing).
    assert contact.rolling_radius_difference(0.009) > contact.rolling_radius_difference(0.0065) > 0
    with pytest.raises(ValueError, match="flange"):
        profile_contact(conical_wheel(1 / 20), rail)
    # The Manchester car on these profiles in 600 m: the leading wheelsets steer on the steep treads
    # near their flanges, at an angle of attack above the geometric b/R.
    state = quasi_static_curving(
        LateralCar().nonlinear(contact=contact), balance_speed(600.0, 0.1), 600.0, 0.1
    )
    assert np.all(state.angle_of_attack[[0, 2]] > 1.28 / 600.0)
    assert np.all(np.abs(state.offset) < 7e-3)


def test_wheel_forces_add_up_to_the_contact_forces():
    # Per wheel and summed, the same forces as contact_forces (lateral: creep + flange; the gravity term is
    # the contact-angle difference's, not a wheel's): here on a cone with ε = 0 it vanishes.
    ws, contact = Wheelset(contact_angle_parameter=0.0), WheelRailContact()
    y = np.array([-0.012, -0.002, 0.0, 0.005, 0.011])
    psi, ydot, psidot = 2e-3, 0.01, -0.02
    forces = wheel_forces(ws, contact, y, psi, ydot, psidot, 30.0)
    lateral, _ = contact_forces(ws, contact, y, psi, ydot, psidot, 30.0)
    np.testing.assert_allclose(forces.lateral.sum(axis=0) + forces.flange.sum(axis=0), lateral, rtol=1e-12)
    np.testing.assert_allclose(forces.longitudinal[0], -forces.longitudinal[1])
    assert np.all(forces.flange[0][y < 0] == 0.0) and np.all(forces.flange[1][y > 0] == 0.0)


def test_bad_input_is_refused_by_name():
    model = Bogie().nonlinear()
    with pytest.raises(ValueError, match="radius"):
        quasi_static_curving(model, 20.0, 30.0)
    with pytest.raises(ValueError, match="speed"):
        quasi_static_curving(model, 0.0, 600.0)
    with pytest.raises(ValueError, match="cant"):
        quasi_static_curving(model, 20.0, 600.0, 0.3)
    with pytest.raises(ValueError, match="cg_height"):
        quasi_static_curving(model, 20.0, 600.0, cg_height=0.0)
    with pytest.raises(ValueError, match="flange_angle"):
        quasi_static_curving(model, 20.0, 600.0, flange_angle=70.0)
    with pytest.raises(TypeError, match="model"):
        quasi_static_curving(Bogie(), 20.0, 600.0)
    with pytest.raises(TypeError, match="curve"):
        curve_entry(model, 20.0, 600.0)
    with pytest.raises(ValueError, match="curve"):
        curve_entry(model, 1.0, Curve(arc_length=500.0))  # 630 m at 1 m/s: over two minutes
    with pytest.raises(ValueError, match="curve"):
        curve_entry(LateralCar().nonlinear(), 20.0, Curve(arc_length=10.0))  # the car is 21.6 m long
    with pytest.raises(TypeError, match="curve"):
        dataclasses.replace(model, curve="600 m")
    with pytest.raises(ValueError, match="start"):
        dataclasses.replace(model, start=np.inf)


def test_a_vehicle_that_cannot_be_held_on_the_rails_is_refused():
    # With no flange the car cannot be held in a 50 m curve at 40 m/s (a_q = 32 m/s², over three times g):
    # the creep saturates at 0.3 of the weight and only the gravitational stiffness grows, metres off the
    # centre line, so the equilibrium found is refused by the package's failure policy, not returned.
    soft = dataclasses.replace(LateralCar().nonlinear(), contact=WheelRailContact(flange_stiffness=0.0))
    with pytest.raises(SolverError, match="off the track"):
        quasi_static_curving(soft, 40.0, 50.0)
