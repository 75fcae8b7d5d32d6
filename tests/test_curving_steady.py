"""Linear steady-state curving (raildyn.curving.steady and the curve loads of raildyn.wheelset): closed
forms of the free, suspended and rigidly held wheelsets, limits, and the equilibrium of every vehicle."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn.constants import GRAVITY
from raildyn.curving.steady import SteadyCurving, steady_curving
from raildyn.vehicles import (
    EMPTY_FREIGHT_CAR,
    LATERAL_LOCOMOTIVE,
    LOADED_FREIGHT_CAR,
    Bogie,
    LateralCar,
    VerticalCar,
)
from raildyn.wheelset import (
    WheelRailContact,
    Wheelset,
    contact_forces,
    creep_terms,
    curve_loads,
    pure_rolling_offset,
)

# No spin, no gravitational stiffness: the assumptions of the classical closed forms (Wickens 2003, ch. 7).
_PLAIN = dict(f23=0.0, f33=0.0, contact_angle=0.0, contact_angle_parameter=0.0)


def _balance_speed(radius: float, cant: float) -> float:
    """V with no unbalanced acceleration, V²/R = g D/G (G = 1.5 m), written here to stay independent."""
    return float(np.sqrt(GRAVITY * radius * cant / 1.5))


def test_the_free_wheelset_rolls_at_the_pure_rolling_offset(reference):
    # r₀a/(λR) towards the outer rail, square to the rails, no creep force: exact but for rounding.
    ws = Wheelset(**_PLAIN).free()
    for radius in (300.0, 600.0, 2500.0):
        state = steady_curving(ws, _balance_speed(radius, 0.1), radius, cant=0.1)
        expected = pure_rolling_offset(ws.rolling_radius, ws.half_gauge, ws.conicity, radius)
        reference(
            8,
            f"free wheelset's steady offset on a {radius:g} m curve",
            "r₀a/(λR), pure rolling",
            "closed form",
            abs(state.offset[0] / expected - 1),
            1e-12,
        )
        assert abs(state.angle_of_attack[0]) < 1e-12
        assert abs(state.longitudinal_creep_force[0]) < 1e-6 * ws.f11 * ws.half_gauge / radius


def test_the_suspended_wheelset_steers_as_its_two_equations_say():
    # A wheelset on yaw and lateral springs k_ψ, k_y to a frame held on the curve's tangent. Its two
    # equilibrium equations, solved by hand (lateral: 2f₂₂ψ = k_y y; yaw: k_ψ ψ = −2af₁₁(λy/r₀ + a/R)):
    #   y = −4a²f₁₁f₂₂ / (k_y k_ψ R) / (1 + 4af₁₁f₂₂λ / (k_y k_ψ r₀)),   ψ = k_y y / (2 f₂₂).
    ws = Wheelset(**_PLAIN, lateral_stiffness=2.0e6, yaw_stiffness=4.0e6)
    R, a, r0, lam = 800.0, ws.half_gauge, ws.rolling_radius, ws.conicity
    f11, f22, ky, kpsi = ws.f11, ws.f22, ws.lateral_stiffness, ws.yaw_stiffness
    y = -4 * a * a * f11 * f22 / (ky * kpsi * R) / (1 + 4 * a * f11 * f22 * lam / (ky * kpsi * r0))
    psi = ky * y / (2 * f22)
    state = steady_curving(ws, _balance_speed(R, 0.05), R, cant=0.05)
    assert -state.offset[0] == pytest.approx(y, rel=1e-10)
    assert -state.angle_of_attack[0] == pytest.approx(psi, rel=1e-10)
    # Held at the tangent point, where radial is ψ = 0, the outer rail's extra length turns the wheelset
    # to point outwards (ψ < 0); the lateral creep of that yaw shifts it out towards pure rolling.
    assert psi < 0 and state.angle_of_attack[0] > 0


def test_a_stiff_primary_gives_the_rigid_bogie():
    # Rigid two-axle bogie with linear creep and no spin or gravity (Newland 1969; Boocock 1969; Wickens
    # 2003, ch. 7): each wheelset is b/R off the radial, pointing out at the front, and the bogie runs
    # r₀(a² + (f₂₂/f₁₁)b²)/(λaR) towards the outer rail. A primary of 1e13 N/m (N·m/rad) leaves elastic
    # deflections of force/stiffness ≈ 1e4/1e13 m, a part in 1e7 of the answer: rel 1e-6.
    bogie = Bogie(secondary_lateral_stiffness=0.0, secondary_yaw_stiffness=0.0).replace(
        **_PLAIN, yaw_stiffness=1e13, lateral_stiffness=1e13
    )
    ws, b, R = bogie.wheelset, bogie.semi_wheelbase, 600.0
    a, r0, lam = ws.half_gauge, ws.rolling_radius, ws.conicity
    state = steady_curving(bogie, _balance_speed(R, 0.1), R, cant=0.1)
    np.testing.assert_allclose(state.angle_of_attack, [b / R, -b / R], rtol=1e-6)
    offset = r0 * (a * a + ws.f22 / ws.f11 * b * b) / (lam * a * R)
    np.testing.assert_allclose(state.offset, [offset, offset], rtol=1e-6)
    np.testing.assert_allclose(state.positions, [b, -b])


@pytest.mark.parametrize("model", [Wheelset(), Bogie(), LateralCar(), LOADED_FREIGHT_CAR, LATERAL_LOCOMOTIVE])
def test_a_large_radius_tends_to_tangent_track(model):
    # With no cant every load is proportional to 1/R (a_q = V²/R), so R·q is the same at any radius, to
    # rounding, and q → 0 as R → ∞.
    near, far = steady_curving(model, 25.0, 1000.0), steady_curving(model, 25.0, 1.0e6)
    np.testing.assert_allclose(1e6 * far.displacement, 1000.0 * near.displacement, rtol=1e-9, atol=1e-12)
    assert np.abs(far.displacement).max() < 1e-4


@pytest.mark.parametrize(
    "model", [Wheelset(), Bogie(), LateralCar(), EMPTY_FREIGHT_CAR, LOADED_FREIGHT_CAR, LATERAL_LOCOMOTIVE]
)
def test_the_rails_carry_the_unbalanced_force_of_every_vehicle(model):
    # Equilibrium of the whole vehicle, independent of how it is assembled: the rails' lateral forces on
    # all the wheelsets (creep plus gravitational stiffness) and the springs to a fixed support balance
    # m_total·a_q, while the suspension's internal forces cancel. The lone wheelset and the lone bogie lean
    # on a support held on the tangent (the primary, the secondary lateral spring), whose force outwards is
    # k·y. Rounding: rel 1e-9.
    system = model.linear_system()
    state = steady_curving(model, 35.0, 1500.0, cant=0.05)
    assert state.unbalanced_acceleration > 0.4  # a real cant deficiency (0.49 m/s²)
    gravity = np.array([w.axle_load * w.contact_angle_parameter / w.half_gauge for *_, w in system.wheelsets])
    outwards = (state.lateral_creep_force - gravity * state.offset).sum()
    if isinstance(model, Wheelset):
        outwards += model.lateral_stiffness * state.coordinate("wheelset y")
    if isinstance(model, Bogie):
        outwards += model.secondary_lateral_stiffness * state.coordinate("frame y")
    lateral = np.array([s.endswith(" y") for s in system.labels], dtype=float)
    total_mass = lateral @ system.M @ lateral
    assert outwards == pytest.approx(-total_mass * state.unbalanced_acceleration, rel=1e-9)


def test_the_car_s_bogies_follow_the_track_under_the_body():
    # The secondary yaw springs turn by about ±l/R between body and bogie (each bogie close to the tangent
    # where it runs): within 5 % on the Manchester car in a 3000 m curve (measured 1.6 % and 2.1 %).
    car = LateralCar()
    state = steady_curving(car, 30.0, 3000.0)
    l, b = car.semi_bogie_spacing, car.bogie.semi_wheelbase
    np.testing.assert_allclose(state.positions, [l + b, l - b, -l + b, -l - b], rtol=1e-12)
    l_over_r = l / 3000.0
    turn = [state.coordinate(f"frame{k} ψ") - state.coordinate("body ψ") for k in (1, 2)]
    np.testing.assert_allclose(turn, [l_over_r, -l_over_r], rtol=0.05)


@settings(max_examples=30, deadline=None)
@given(
    radius=st.floats(150.0, 1e5),
    position=st.floats(-20.0, 20.0),
    conicity=st.floats(0.01, 0.4),
)
def test_the_curve_loads_are_the_tangent_terms_with_the_track_moved(radius, position, conicity):
    # f = (K_creep + K_gravity) q_t − C₁[:, 1]/R: a wheelset displaced with the track (q = q_t) and yawing at
    # V/R feels exactly the tangent-track force −(K (q − q_t) + C₁ q̇/V) it would feel there, i.e. zero
    # but for the constant terms; checked here as linearity in q_t.
    ws = Wheelset(conicity=conicity)
    terms = creep_terms(ws)
    K = terms.K_creep + terms.K_gravity
    q_t = np.array([0.5 * position**2 / radius, position / radius])
    expected = K @ q_t - terms.C1[:, 1] / radius
    np.testing.assert_allclose(curve_loads(ws, radius, position), expected, rtol=1e-12, atol=1e-9)


@pytest.mark.parametrize("position", [0.0, 1.28, -1.28])
def test_the_curve_loads_are_the_nonlinear_contacts_in_the_small(position):
    # An independent path: raildyn.wheelset.contact_forces (creepages by wheelset_creepages, Kalker's forces,
    # their saturation) on a wheelset held where the track would put it (y = −y_t, ψ = −ψ_t, yaw rate V/R).
    # Only the saturation differs from the linear loads, by a part of order the creep force over μW/2, ∝ 1/R:
    # measured 2.5 % of the largest load at R = 10 km and 0.25 % at 100 km, so the gap falls tenfold.
    ws, contact, V = Wheelset(), WheelRailContact(), 30.0
    gaps = []
    for radius in (1.0e4, 1.0e5):
        linear = curve_loads(ws, radius, position)
        y_t, psi_t = 0.5 * position**2 / radius, position / radius
        nonlinear = np.ravel(contact_forces(ws, contact, -y_t, -psi_t, 0.0, V / radius, V))
        gaps.append(np.abs(nonlinear - linear).max() / np.abs(linear).max())
    assert gaps[1] < 3e-3
    assert gaps[0] / gaps[1] == pytest.approx(10.0, rel=0.05)


def test_the_plot_draws_and_updates_the_wheelsets():
    state = steady_curving(LateralCar(), 30.0, 1200.0)
    artists = state.plot()
    assert len(artists["axles"]) == 4
    before = artists["axles"][0].get_xydata().copy()
    steady_curving(LateralCar(), 30.0, 600.0).plot(artists=artists)
    assert not np.allclose(artists["axles"][0].get_xydata(), before)
    assert artists["title"].get_text().startswith("R = 600 m")


def test_bad_input_is_refused_by_name():
    with pytest.raises(ValueError, match="radius"):
        steady_curving(Bogie(), 20.0, 0.0)
    with pytest.raises(ValueError, match="radius"):
        steady_curving(Bogie(), 20.0, -600.0)
    with pytest.raises(ValueError, match="speed"):
        steady_curving(Bogie(), 0.0, 600.0)
    with pytest.raises(ValueError, match="cant"):
        steady_curving(Bogie(), 20.0, 600.0, cant=-0.05)
    with pytest.raises(TypeError, match="model"):
        steady_curving("bogie", 20.0, 600.0)
    with pytest.raises(ValueError, match="model"):
        steady_curving(VerticalCar(), 20.0, 600.0)
    with pytest.raises(ValueError, match="position"):
        curve_loads(Wheelset(), 600.0, np.nan)
    with pytest.raises(ValueError, match="radius"):
        pure_rolling_offset(0.46, 0.75, 0.15, 0.0)
    with pytest.raises(ValueError, match="displacement"):
        SteadyCurving(600.0, 20.0, 0.0, 0.0, ("a",), np.zeros(2), np.zeros(1), *np.zeros((4, 1)))
