"""Real wheels on real rails: the linear models on a profile pair (``Wheelset.on_profiles``: the cone as its
limit, ε read from the pair's contact angles by an independent first harmonic, a car's critical speed on real
wheels) and the pair's own flange angle in the curving limits."""

import dataclasses

import numpy as np
import pytest

from raildyn import stability
from raildyn.contact.geometry import contact_geometry
from raildyn.contact.profiles import conical_wheel, s1002_wheel, uic60_rail
from raildyn.curving import quasi_static_curving
from raildyn.track import balance_speed
from raildyn.vehicles import LateralCar, cooperrider_car
from raildyn.wheelset import WheelRailContact, Wheelset, profile_contact


@pytest.mark.parametrize("slope", [0.025, 0.05, 0.1])
def test_a_conical_wheel_linearises_to_its_cone(slope):
    # The contact angle of a cone is its slope's angle everywhere (to the contact search's 1e-9); its λ_e
    # and ε are the cone's λ, the values a Wheelset takes for a cone, to within what the wheelset's roll on
    # the crowned rail heads adds (measured up to 2 % for λ_e and 0.5 % for ε at these slopes; roll=False
    # gives λ_e exactly, tests/test_contact_profiles.py).
    ws = Wheelset().on_profiles(conical_wheel(slope), uic60_rail(1 / 40), 3e-3)
    assert ws.contact_angle == pytest.approx(np.arctan(slope), abs=1e-9)
    assert ws.conicity == pytest.approx(slope, rel=0.03)
    assert ws.contact_angle_parameter == pytest.approx(slope, rel=0.02)


def test_epsilon_is_the_first_harmonic_of_the_contact_angle_difference():
    # An independent first harmonic: Δϑ evaluated by contact_geometry at y = ŷ sin θ itself (not read from a
    # table), k = (1/(2πŷ)) ∫ Δϑ sin θ dθ, ε = a k. The model reads a table of 801 shifts, linearly: its
    # quadrature differs by the interpolation across the contact's jumps (measured 3e-4 of ε), within 1e-3.
    wheel, rail, A = s1002_wheel(), uic60_rail(1 / 40), 3e-3
    ws = Wheelset().on_profiles(wheel, rail, A)
    theta = 2 * np.pi * np.arange(512) / 512
    dd = contact_geometry(wheel, rail, A * np.sin(theta)).contact_angle_difference
    expected = ws.half_gauge * (dd * np.sin(theta)).mean() / A
    assert ws.contact_angle_parameter == pytest.approx(expected, rel=1e-3)
    # A new S1002 wheel on a 1:40 rail: a contact angle difference far steeper than a cone's (ε ≫ λ_e).
    assert ws.contact_angle_parameter > 10 * ws.conicity


def test_real_wheels_hunt_at_a_speed_a_train_reaches():
    # Cooperrider's car on its 1:40 cone is stable beyond 200 m/s; on new S1002 wheels and UIC 60 rails at
    # 1:40, linearised at 3 mm (λ_e 0.17), it hunts at about 92 m/s (333 km/h).
    car = cooperrider_car()
    assert not stability.critical_speed(car, (1.0, 200.0)).found
    ws = car.bogie.wheelset.on_profiles(s1002_wheel(), uic60_rail(1 / 40), 3e-3)
    real = car.replace(
        conicity=ws.conicity,
        contact_angle=ws.contact_angle,
        contact_angle_parameter=ws.contact_angle_parameter,
        rolling_radius=ws.rolling_radius,
    )
    assert 80.0 < stability.critical_speed(real, (1.0, 200.0)).speed < 105.0


def test_on_profiles_refuses_an_amplitude_the_linear_model_cannot_take():
    with pytest.raises(ValueError, match="amplitude"):
        Wheelset().on_profiles(s1002_wheel(), uic60_rail(1 / 40), 5e-4)
    with pytest.raises(ValueError, match="amplitude"):
        Wheelset().on_profiles(s1002_wheel(), uic60_rail(1 / 40), 0.02)
    with pytest.raises(TypeError, match="wheel"):
        Wheelset().on_profiles("S1002", uic60_rail(1 / 40))


def test_a_profile_pair_carries_its_own_flange_angle():
    # S1002's flank is a straight line of slope 2.747477419 (EN 13715, section E): 70.0°. On the rail its
    # contact angle differs from that by the wheelset's roll at flange contact (measured 3.3e-4 rad).
    flank = np.arctan(2.747477419)
    contact = profile_contact(s1002_wheel(), uic60_rail(1 / 40))
    assert contact.flange_angle == pytest.approx(flank, abs=1e-3)
    assert WheelRailContact().flange_angle == pytest.approx(np.radians(70.0), abs=1e-9)  # the cone's default
    with pytest.raises(ValueError, match="flange_angle"):
        WheelRailContact(flange_angle=np.radians(95.0))


def test_quasi_static_curving_reads_the_flange_angle_of_the_contact():
    # The flange angle shares a flange's load between tread and flange; left out, it is the contact's.
    steep = dataclasses.replace(WheelRailContact(), flange_angle=np.radians(60.0))
    model = LateralCar().nonlinear(contact=steep)
    V = balance_speed(600.0, 0.1)
    by_contact = quasi_static_curving(model, V, 600.0, 0.1)
    given = quasi_static_curving(model, V, 600.0, 0.1, flange_angle=np.radians(60.0))
    default = quasi_static_curving(LateralCar().nonlinear(), V, 600.0, 0.1)
    np.testing.assert_array_equal(by_contact.derailment_quotient, given.derailment_quotient)
    assert not np.allclose(by_contact.derailment_quotient, default.derailment_quotient)
