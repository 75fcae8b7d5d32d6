"""The three-piece freight truck and the freight car in the lateral plane (chapters 6 and 7), and the
nonlinear suspension elements of :class:`raildyn.wheelset.NonlinearLateral` they use."""

from __future__ import annotations

import numpy as np
import pytest

from raildyn.suspension import clearance_force, coulomb_friction
from raildyn.vehicles import Bogie
from raildyn.wheelset import NonlinearLateral, SuspensionElement, WheelRailContact

# ---------------------------------------------------------------------------
# Nonlinear suspension elements


def _random_states(n, count, seed=7):
    rng = np.random.default_rng(seed)
    scale = np.concatenate([np.full(n, 4e-3), np.full(n, 0.05)])
    return rng.normal(size=(count, 2 * n)) * scale


def test_an_element_with_the_linear_law_changes_nothing():
    # The bogie's secondary lateral spring and damper (320 kN/m, 64 kN·s/m on the frame's y) as an
    # element whose law is that same spring and damper: removed from K and C₀, added back by the law.
    # The two right-hand sides are the same sums in another order: equal to rounding (1e-12 relative).
    system = Bogie().linear_system()
    k, c = 2 * 160.0e3, 2 * 32.0e3
    element = SuspensionElement({"frame y": 1.0}, lambda d, v: k * d + c * v, stiffness=k, damping=c)
    plain = NonlinearLateral(system, WheelRailContact(), 40.0)
    with_element = NonlinearLateral(system, WheelRailContact(), 40.0, (element,))
    for x in _random_states(system.size, 10):
        np.testing.assert_allclose(with_element.rhs(0.0, x), plain.rhs(0.0, x), rtol=1e-12, atol=1e-9)


def test_an_element_adds_its_force_along_its_deflection():
    # Friction of 5 kN between the frame and the leading wheelset laterally, d = y_f − y_w1: the
    # accelerations change by −M⁻¹ g F(ḋ) exactly (the law is evaluated at the state's ḋ), also for
    # a batch of states (columns), as solve_ivp's vectorised calls pass them.
    system = Bogie().linear_system()
    g = np.zeros(system.size)
    g[[0, 2]] = 1.0, -1.0
    law = lambda d, v: coulomb_friction(v, 5.0e3, velocity_scale=0.01)  # noqa: E731
    element = SuspensionElement({"frame y": 1.0, "wheelset1 y": -1.0}, law)
    plain = NonlinearLateral(system, WheelRailContact(), 40.0)
    model = NonlinearLateral(system, WheelRailContact(), 30.0, (element,))
    assert model.at_speed(40.0).elements == (element,)
    X = _random_states(system.size, 6).T
    n = system.size
    expected = plain.at_speed(30.0).rhs(0.0, X)
    ddot = g @ X[n:]
    expected[n:] -= np.linalg.solve(system.M, np.outer(g, 5.0e3 * np.tanh(ddot / 0.01)))
    np.testing.assert_allclose(model.rhs(0.0, X), expected, rtol=1e-12, atol=1e-9)


def test_a_clearance_element_acts_only_beyond_its_play():
    # A lateral play of 5 mm between wheelset 1 and the frame with a 10 MN/m stop (the law of
    # raildyn.suspension.clearance_force): inside the play the model is the plain one.
    system = Bogie().linear_system()
    element = SuspensionElement(
        {"wheelset1 y": 1.0, "frame y": -1.0}, lambda d, v: clearance_force(d, 5e-3, 1e7)
    )
    plain = NonlinearLateral(system, WheelRailContact(), 40.0)
    model = NonlinearLateral(system, WheelRailContact(), 40.0, [element])
    x = np.zeros(2 * system.size)
    x[2] = 4e-3
    np.testing.assert_array_equal(model.rhs(0.0, x), plain.rhs(0.0, x))
    x[2] = 6e-3  # 1 mm beyond: the stop pushes the wheelset back with 10 kN
    change = model.rhs(0.0, x) - plain.rhs(0.0, x)
    g = np.zeros(system.size)
    g[[2, 0]] = 1.0, -1.0
    np.testing.assert_allclose(change[system.size :], -np.linalg.solve(system.M, g * 1e4), rtol=1e-9)


def test_elements_are_refused_by_name():
    system = Bogie().linear_system()
    ok = SuspensionElement({"frame y": 1.0}, lambda d, v: 0.0 * d)
    with pytest.raises(ValueError, match="coordinates"):
        NonlinearLateral(system, elements=(SuspensionElement({"body y": 1.0}, lambda d, v: 0.0 * d),))
    with pytest.raises(TypeError, match="elements"):
        NonlinearLateral(system, elements=ok)
    with pytest.raises(TypeError, match=r"elements\[1\]"):
        NonlinearLateral(system, elements=(ok, "wedge"))
    with pytest.raises(ValueError, match="coordinates"):
        SuspensionElement({"frame y": 0.0}, lambda d, v: d)
    with pytest.raises(ValueError, match="force"):
        SuspensionElement({"frame y": 1.0}, lambda d, v: d[:2])
    with pytest.raises(ValueError, match="force"):
        SuspensionElement({"frame y": 1.0}, lambda d, v: np.full_like(d, np.nan))
    with pytest.raises(ValueError, match="stiffness"):
        SuspensionElement({"frame y": 1.0}, lambda d, v: d, stiffness=-1.0)
